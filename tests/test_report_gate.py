"""python -m gles report as a CI gate: scene files, verdicts against
--min-psnr and --max-over-1lsb and the exit code, report.json, RGB565, the
plot and the colour bar.

Expected PSNRs and shares come from renders on gles.Context directly and the
definitions in numpy, not from the report's code."""

from __future__ import annotations

import json
import math
import re
import struct
import zlib
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from gles import Context, report
from gles.__main__ import main
from gles.compare import Comparison, Metrics, Render
from gles.target import APT_COMMAND, SceneCost

SCENES = '''
"""Scenes for the report's gate tests."""
import numpy as np


def flat(gl, w, h):
    """A clear colour: the same on every build."""
    gl.glClearColor(0.25, 0.5, 0.75, 1.0)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT)


def far(gl, w, h):
    """A smooth triangle 30000 units out, scaled back by 1/30000."""
    gl.glClearColor(0, 0, 0, 1)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glScalef(1 / 30000, 1 / 30000, 1)
    v = np.array([-29000.3, -28000.7, 0, 29000.1, -27000.9, 0, 1000.4, 29500.2, 0], np.float32)
    c = np.array([255, 30, 0, 255, 0, 255, 40, 255, 20, 60, 255, 255], np.uint8)
    gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
    gl.glEnableClientState(gl.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, gl.GL_FLOAT, 0, v)
    gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, c)
    gl.glDrawArrays(gl.GL_TRIANGLES, 0, 3)


def _helper(x):
    return x


def not_a_scene(x):
    return x
'''

W, H = 32, 24


@pytest.fixture()
def scene_file(tmp_path: Path) -> Path:
    path = tmp_path / "my_scenes.py"
    path.write_text(SCENES)
    return path


def _module(path: Path) -> Any:
    ns: dict[str, Any] = {}
    exec(compile(path.read_text(), str(path), "exec"), ns)
    return ns


def _image(fn: Any, numeric: str, color: str = "rgba8888") -> np.ndarray:
    ctx = Context(W, H, numeric=numeric, color=color, range_check="off")
    fn(ctx.gl, W, H)
    return ctx.image()


def _psnr_share(img: np.ndarray, ref: np.ndarray) -> tuple[float, float]:
    d = np.abs(img[..., :3].astype(float) - ref[..., :3].astype(float))
    mse = float(np.mean(d ** 2))
    psnr = math.inf if mse == 0 else 10 * math.log10(255 ** 2 / mse)
    return psnr, float(np.mean(d.max(axis=2) > 1))


def _read_png(path: Path) -> np.ndarray:
    """The PNGs of gles._png: 8-bit, filter 0 on every row."""
    data = path.read_bytes()
    pos, idat = 8, b""
    w = h = channels = 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, _depth, ctype = struct.unpack(">IIBB", body[:10])
            channels = {2: 3, 6: 4, 0: 1}[ctype]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + w * channels)
    assert not raw[:, 0].any()
    return raw[:, 1:].reshape(h, w, channels)


def _run(out: Path, scenes: str, *extra: str) -> int:
    return main(["report", "--out", str(out), "--scenes", scenes, "--size", f"{W}x{H}", "--runs", "1",
                 "--peers", "", "--quiet", *extra])


def test_min_psnr_gates_the_exit_code(scene_file: Path, tmp_path: Path, capsys: Any,
                                      monkeypatch: Any) -> None:
    monkeypatch.setenv("GLES_TARGET", "off")       # the gate does not need the target's counts
    ns = _module(scene_file)
    psnr, _ = _psnr_share(_image(ns["far"], "fixed"), _image(ns["far"], "double"))
    assert 5 < psnr < 60                            # the far scene's fixed build is visibly off
    # just below the fixed build's PSNR: every scene passes
    assert _run(tmp_path / "a", str(scene_file), "--min-psnr", f"{psnr - 0.5:.2f}") == 0
    data = json.loads((tmp_path / "a" / "report.json").read_text())
    assert [s["verdict"]["status"] for s in data["scenes"]] == ["pass", "pass"]
    capsys.readouterr()
    # just above it: far falls short on fixed (float equals double), flat never does
    assert _run(tmp_path / "b", str(scene_file), "--min-psnr", f"{psnr + 0.5:.2f}") == 1
    err = capsys.readouterr().err
    line = [x for x in err.splitlines() if "fall short" in x]
    assert len(line) == 1 and "1 of 2 scenes" in line[0] and "far (fixed" in line[0] and "flat" not in line[0]
    data = json.loads((tmp_path / "b" / "report.json").read_text())
    far = next(s for s in data["scenes"] if s["name"] == "far")
    assert far["verdict"]["status"] == "fail" and far["verdict"]["checked"] == ["fixed", "float"]
    assert data["failing"] == ["far"]
    assert "FAIL: fixed" in (tmp_path / "b" / "report.md").read_text()
    assert "FAIL: fixed" in (tmp_path / "b" / "report.html").read_text()
    # without thresholds nothing is gated
    assert _run(tmp_path / "c", str(scene_file)) == 0
    data = json.loads((tmp_path / "c" / "report.json").read_text())
    assert {s["verdict"]["status"] for s in data["scenes"]} == {"not gated"}


def test_max_over_1lsb_gates_the_exit_code(scene_file: Path, tmp_path: Path, monkeypatch: Any) -> None:
    monkeypatch.setenv("GLES_TARGET", "off")
    ns = _module(scene_file)
    _, share = _psnr_share(_image(ns["far"], "fixed"), _image(ns["far"], "double"))
    assert 0.01 < share < 0.99
    assert _run(tmp_path / "a", str(scene_file), "--max-over-1lsb", f"{share + 0.005:.4f}") == 0
    assert _run(tmp_path / "b", str(scene_file), "--max-over-1lsb", f"{share - 0.005:.4f}") == 1
    # both thresholds: either one falling short fails the scene
    assert _run(tmp_path / "c", str(scene_file), "--min-psnr", "0", "--max-over-1lsb",
                f"{share - 0.005:.4f}") == 1


@pytest.mark.parametrize("args", [["--max-over-1lsb", "5"], ["--max-over-1lsb", "x"],
                                  ["--min-psnr", "nan"], ["--color", "rgb332"]])
def test_bad_thresholds_are_usage_errors(args: list[str], tmp_path: Path) -> None:
    with pytest.raises(SystemExit) as exc:
        main(["report", "--out", str(tmp_path), "--quiet", *args])
    assert exc.value.code == 2


def test_bad_scene_files_are_usage_errors(tmp_path: Path, capsys: Any) -> None:
    empty = tmp_path / "empty.py"
    empty.write_text("X = 1\n")
    broken = tmp_path / "broken.py"
    broken.write_text("import no_such_module_here\n")
    for path, words in ((tmp_path / "missing.py", "no such scene file"), (empty, "defines no scene"),
                        (broken, "ModuleNotFoundError")):
        assert _run(tmp_path / "out", str(path)) == 2
        err = capsys.readouterr().err
        assert path.name in err and words in err


def test_scene_file_forms(scene_file: Path, tmp_path: Path) -> None:
    got = report.scene_file(scene_file)
    assert [e.name for e in got] == ["flat", "far"]       # helpers and other signatures left out
    assert got[0].title == "A clear colour: the same on every build."
    assert got[0].group == "Scenes of my_scenes.py"
    table = tmp_path / "table.py"
    table.write_text("def a(gl, w, h):\n    pass\n\ndef b(gl, w, h):\n    pass\n\n"
                     "SCENES = {'second': ('Second title', b), 'first': a}\n")
    got = report.scene_file(table)
    assert [(e.name, e.title) for e in got] == [("second", "Second title"), ("first", "first")]
    bad = tmp_path / "bad.py"
    bad.write_text("SCENES = {'a b': lambda gl, w, h: None}\n")
    with pytest.raises(ValueError, match="scene name"):
        report.scene_file(bad)
    bad.write_text("SCENES = {'a': lambda x: None}\n")
    with pytest.raises(ValueError, match="not a function scene"):
        report.scene_file(bad)
    # names and files together; the same name twice is an error
    mixed = report.select(["lit_mesh", str(scene_file)])
    assert [e.name for e in mixed] == ["lit_mesh", "flat", "far"]
    with pytest.raises(ValueError, match="two scenes"):
        report.select([str(scene_file), str(scene_file)])


def _comp(fixed: Render, peer_psnr: float = 1.0) -> Comparison:
    double = Render("double", None, times_ms=[1.0], metrics=Metrics(0, 0, 0, math.inf, 0))
    peer = Render("mesa-llvmpipe", None, times_ms=[1.0], metrics=Metrics(200, 50, 90, peer_psnr, 0.9))
    return Comparison("s", 4, 4, "double", {"fixed": fixed, "double": double, "mesa-llvmpipe": peer})


def test_verdict_thresholds() -> None:
    fixed = Render("fixed", None, times_ms=[1.0], metrics=Metrics(3, 0.5, 1.0, 40.0, 0.02))
    assert report.verdict(_comp(fixed)).status == "not gated"
    # at the threshold passes; the peer is far off and does not gate; double is the reference
    v = report.verdict(_comp(fixed), min_psnr=40.0, max_over_1lsb=0.02)
    assert (v.status, v.checked) == ("pass", ["fixed"])
    assert report.verdict(_comp(fixed), min_psnr=40.01).failures == ["fixed 40.0 dB < 40.01 dB"]
    v = report.verdict(_comp(fixed), max_over_1lsb=0.019)
    assert v.status == "fail" and "2.00%" in v.failures[0]
    failed = Render("fixed", None, error="RuntimeError: boom")
    assert report.verdict(_comp(failed), min_psnr=0).failures == ["fixed failed"]
    unmeasured = Render("fixed", np.zeros((4, 4, 4), np.uint8), times_ms=[1.0])
    assert report.verdict(_comp(unmeasured), min_psnr=0).status == "fail"


def test_report_json_matches_the_comparisons(scene_file: Path, tmp_path: Path, monkeypatch: Any) -> None:
    seen: list[Comparison] = []
    real = report.compare_scenes

    def recording(*args: Any, **kwargs: Any) -> list[Comparison]:
        seen.extend(real(*args, **kwargs))
        return seen

    monkeypatch.setattr(report, "compare_scenes", recording)
    page = report.build_report(tmp_path, W, H, runs=2, only=[str(scene_file)], peers=(), progress=False,
                               min_psnr=30.0)
    text = (page.parent / "report.json").read_text()
    data = json.loads(text, parse_constant=lambda c: pytest.fail(f"{c} in report.json"))
    assert data["schema"] == report.SCHEMA_VERSION
    assert data["size"] == [W, H] and data["color"] == "rgba8888" and data["runs"] == 2
    assert data["thresholds"] == {"min_psnr": 30.0, "max_over_1lsb": None}
    assert data["versions"]["gles"] and data["machine"]["cpus"]
    assert [s["name"] for s in data["scenes"]] == ["flat", "far"] == [c.scene for c in seen]
    for s, comp in zip(data["scenes"], seen):
        assert list(s["renders"]) == list(comp.renders)
        for name, r in comp.renders.items():
            d = s["renders"][name]
            assert d["host_times_ms"] == r.times_ms and len(r.times_ms) == 2
            assert d["host_ms_per_frame"] == r.time_ms
            m = d["metrics"]
            assert (m["max_abs"], m["mean_abs"], m["rmse"], m["share_over_1lsb"]) == (
                r.metrics.max_abs, r.metrics.mean_abs, r.metrics.rmse, r.metrics.share_over_1lsb)
            assert m["identical"] == math.isinf(r.metrics.psnr)
            assert m["psnr_db"] == (None if math.isinf(r.metrics.psnr) else r.metrics.psnr)
            if r.range is not None:
                assert d["range_events"]["total"] == r.range.total
                assert d["range_events"]["by_source"] == dict(r.range.by_source)
            assert (tmp_path / d["image"]).is_file() and (tmp_path / d["heatmap"]).is_file()
        tgt = s["target"]
        if data["target"]["available"]:
            fx, fl = tgt["instructions_per_frame"]["fixed"], tgt["instructions_per_frame"]["float"]
            assert fx > 0 and fl > 0 and tgt["fixed_over_float"] == pytest.approx(fx / fl)
            assert s["renders"]["fixed"]["target_instructions_per_frame"] == fx
            assert f"{fx:,}" in page.read_text()
        else:
            assert tgt is None and data["target"]["missing"]
    # the numbers against independent renders: far's fixed PSNR, and its verdict at 30 dB
    ns = _module(scene_file)
    psnr, share = _psnr_share(_image(ns["far"], "fixed"), _image(ns["far"], "double"))
    far = data["scenes"][1]["renders"]["fixed"]["metrics"]
    assert far["psnr_db"] == pytest.approx(psnr, rel=1e-9) and far["share_over_1lsb"] == pytest.approx(share)
    assert data["scenes"][1]["verdict"]["status"] == ("fail" if psnr < 30 else "pass")
    assert data["scenes"][0]["verdict"]["status"] == "pass"


@pytest.mark.parametrize("color", ["rgb565", "rgba4444", "rgba5551"])
def test_16bit_reports_render_every_build_in_their_format(scene_file: Path, tmp_path: Path, monkeypatch: Any,
                                                          color: str) -> None:
    monkeypatch.setenv("GLES_TARGET", "off")
    assert _run(tmp_path, str(scene_file), "--color", color) == 0
    data = json.loads((tmp_path / "report.json").read_text())
    assert data["color"] == color
    ns = _module(scene_file)
    for name in ("flat", "far"):
        ref = _image(ns[name], "double", color)
        assert not np.array_equal(ref, _image(ns[name], "double"))     # the format shows
        for build in ("fixed", "float", "double"):
            want = _image(ns[name], build, color)
            got = _read_png(tmp_path / "img" / f"{name}_{build}.png")
            assert np.array_equal(got, want), (name, build)
            psnr, share = _psnr_share(want, ref)          # against double in that format too
            m = next(s for s in data["scenes"] if s["name"] == name)["renders"][build]["metrics"]
            assert m["identical"] == math.isinf(psnr)
            if not math.isinf(psnr):
                assert m["psnr_db"] == pytest.approx(psnr, rel=1e-9)
            assert m["share_over_1lsb"] == pytest.approx(share)
    assert f"{color.upper()} framebuffer" in (tmp_path / "report.md").read_text()


def _entry(name: str) -> report.Entry:
    return report.Entry(name, name, "Techniques", lambda gl, w, h: None)


def _scene(psnrs: dict[str, float], ms: dict[str, float]) -> Comparison:
    renders = {n: Render(n, None, times_ms=[ms[n]], metrics=Metrics(1, 0.1, 0.2, p, 0.0))
               for n, p in psnrs.items()}
    return Comparison("s", 4, 4, "double", renders)


def test_overview_joins_each_scenes_builds_and_names_every_point() -> None:
    results = [(_entry("alpha"), _scene({"fixed": 30.0, "float": 50.0, "double": math.inf,
                                         "mesa-llvmpipe": 45.0},
                                        {"fixed": 1.0, "float": 2.0, "double": 3.0, "mesa-llvmpipe": 9.0})),
               (_entry("beta"), _scene({"fixed": 20.0, "float": 60.0, "double": math.inf},
                                       {"fixed": 0.5, "float": 0.7, "double": 0.9}))]
    costs = {"alpha": SceneCost("alpha", {}, {"fixed": 1000, "float": 100000}),
             "beta": SceneCost("beta", {}, {"fixed": 2000, "float": 3000})}
    svg = report.overview_svg(results, costs)
    groups = re.findall(r'<g class="scene"><title>(\d+) (\w+)</title>(.*?)</g>', svg, re.S)
    # one group per scene in each panel: host (all renderers), target (fixed and float)
    assert [(n, s) for n, s, _ in groups] == [("1", "alpha"), ("2", "beta")] * 2
    host_alpha, target_alpha = groups[0][2], groups[2][2]
    line = re.findall(r'<polyline points="([^"]+)"', host_alpha)
    assert len(line) == 1 and len(line[0].split()) == 3          # fixed, float, double; not the peer
    tips = re.findall(r"<circle [^>]*><title>([^<]+)</title>", host_alpha)
    assert len(tips) == 4 and "1 alpha on fixed: 1.00 ms on this host, 30.0 dB" in tips
    assert any("mesa-llvmpipe" in t for t in tips)
    # the target panel: instructions to the right, PSNR up
    pts = {t.split(" on ")[1].split(":")[0]: (float(x), float(y)) for x, y, t in re.findall(
        r'<circle cx="([\d.]+)" cy="([\d.]+)" [^>]*><title>([^<]+)</title>', target_alpha)}
    assert set(pts) == {"fixed", "float"}
    assert pts["float"][0] > pts["fixed"][0] and pts["float"][1] < pts["fixed"][1]
    assert "1,000 target instructions per frame" in target_alpha
    # the legend names every scene by its number, and the axes say whose time it is
    assert " 1  alpha</text>" in svg and " 2  beta</text>" in svg
    assert "host ms per frame (this machine" in svg and "target instructions per frame" in svg
    # without the target the panel says what to install
    missing = report.overview_svg(results, None, f"n/a: needs the cross compiler ({APT_COMMAND})")
    assert "gcc-arm-linux-gnueabi" in missing and len(re.findall('<g class="scene">', missing)) == 2


def test_colour_bar_scale() -> None:
    svg = report.colorbar_svg()
    equal = re.search(r'<rect class="equal"[^>]*fill="#([0-9a-f]{6})"', svg)
    assert equal is not None and equal.group(1) == "000000"          # equal pixels are black
    fills = re.findall(r'<rect x="[\d.]+" y="18" [^>]*fill="#([0-9a-f]{6})"', svg)
    rgb = [tuple(int(f[i:i + 2], 16) for i in (0, 2, 4)) for f in fills]
    r, g, b = rgb[0]
    assert b > r and b > g and max(rgb[0]) < 200                    # 1 LSB: dark blue
    assert min(rgb[-1]) >= 245                                       # 255: white
    assert sum(rgb[-1]) > sum(rgb[len(rgb) // 2]) > sum(rgb[0])     # brighter as the error grows
    tick = r'<text x="([\d.]+)" y="48" text-anchor="middle">(\d+)<'
    ticks = [(float(x), int(t)) for x, t in re.findall(tick, svg)]
    assert [t for _, t in ticks] == [1, 2, 4, 8, 16, 32, 64, 128, 255]
    xs = [x for x, _ in ticks]
    assert xs == sorted(xs) and xs[1] - xs[0] == pytest.approx(xs[2] - xs[1], abs=0.2)   # log scale
