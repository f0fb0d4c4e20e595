"""gles.compare: its metrics against numpy computed independently, and the
compare/render/CLI plumbing on a small scene."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from conftest import decode_png
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from gles import compare as cmp
from gles import constants as C
from gles.__main__ import main


def reference_metrics(img: np.ndarray, ref: np.ndarray) -> dict[str, float]:
    """The definitions, one pixel and one channel at a time."""
    h, w = img.shape[:2]
    diffs = []
    over = 0
    for y in range(h):
        for x in range(w):
            ds = [abs(int(img[y, x, ch]) - int(ref[y, x, ch])) for ch in range(3)]
            diffs.extend(ds)
            over += max(ds) > 1
    n = len(diffs)
    mse = sum(d * d for d in diffs) / n
    return {
        "max_abs": max(diffs),
        "mean_abs": sum(diffs) / n,
        "rmse": math.sqrt(mse),
        "psnr": math.inf if mse == 0 else 10 * math.log10(255 * 255 / mse),
        "share_over_1lsb": over / (h * w),
    }


images = hnp.arrays(np.uint8, st.tuples(st.integers(1, 6), st.integers(1, 6), st.just(4)))


@given(images, st.data())
@settings(max_examples=200, deadline=None)
def test_metrics_match_the_definitions(ref: np.ndarray, data: st.DataObject) -> None:
    noise = data.draw(hnp.arrays(np.int16, ref.shape, elements=st.integers(-3, 3)))
    scale = data.draw(st.sampled_from([0, 1, 40]))
    img = np.clip(ref.astype(np.int16) + noise * scale, 0, 255).astype(np.uint8)
    got = cmp.metrics(img, ref)
    want = reference_metrics(img, ref)
    assert got.max_abs == want["max_abs"]
    assert got.mean_abs == pytest.approx(want["mean_abs"], rel=1e-12)
    assert got.rmse == pytest.approx(want["rmse"], rel=1e-12)
    assert got.share_over_1lsb == pytest.approx(want["share_over_1lsb"], rel=1e-12)
    if math.isinf(want["psnr"]):
        assert math.isinf(got.psnr)
    else:
        assert got.psnr == pytest.approx(want["psnr"], rel=1e-12)


def test_metrics_ignore_alpha_and_known_values() -> None:
    ref = np.zeros((2, 2, 4), np.uint8)
    img = ref.copy()
    img[..., 3] = 200                      # alpha is not part of the visible image
    assert math.isinf(cmp.metrics(img, ref).psnr)
    img[0, 0, 0] = 2                       # one channel of one pixel off by 2
    m = cmp.metrics(img, ref)
    assert (m.max_abs, m.share_over_1lsb) == (2, 0.25)
    assert m.rmse == pytest.approx(math.sqrt(4 / 12))
    assert m.psnr == pytest.approx(20 * math.log10(255 / math.sqrt(4 / 12)))
    with pytest.raises(ValueError):
        cmp.metrics(np.zeros((2, 3, 4), np.uint8), ref)


def test_heatmap_is_black_exactly_where_equal() -> None:
    rng = np.random.default_rng(3)
    ref = rng.integers(0, 256, (8, 9, 4), dtype=np.uint8)
    img = ref.copy()
    img[2, 3, 1] ^= 1
    img[5, 5, 2] = 255 - img[5, 5, 2] if img[5, 5, 2] < 128 else 0
    hm = cmp.heatmap(img, ref)
    assert hm.shape == (8, 9, 3) and hm.dtype == np.uint8
    differs = np.any(img[..., :3] != ref[..., :3], axis=2)
    assert np.array_equal(hm.any(axis=2), differs)
    # larger differences are brighter
    assert int(hm[5, 5].sum()) > int(hm[2, 3].sum())


def triangle_scene(gl, w, h):
    """A smooth triangle under a perspective projection."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumf(-1, 1, -1, 1, 1, 10)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glTranslatef(0.1, 0, -2.7)
    gl.glRotatef(17, 0.3, 0.2, 1)
    v = np.array([-1, -1, 0, 1, -1, 0.5, 0, 1, -0.5], np.float32)
    c = np.array([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255], np.uint8)

    def frame():
        gl.glClearColor(0, 0, 0, 1)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, c)
        gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    return frame


def test_compare_end_to_end() -> None:
    res = cmp.compare(triangle_scene, 40, 30, peers=(), runs=3)
    assert list(res.renders) == ["fixed", "float", "double"]
    assert res.scene == "triangle_scene"
    ref = res.renders["double"].image
    assert ref.shape == (30, 40, 4)
    for r in res.renders.values():
        assert r.skipped is None and r.gl_error == 0
        assert len(r.times_ms) == 3 and r.time_ms > 0
        want = reference_metrics(r.image, ref)
        assert r.metrics.max_abs == want["max_abs"]
        assert r.metrics.rmse == pytest.approx(want["rmse"])
        assert np.array_equal(r.heatmap.any(axis=2), np.any(r.image[..., :3] != ref[..., :3], axis=2))
    assert math.isinf(res.renders["double"].metrics.psnr)
    assert res.renders["fixed"].range is not None and res.renders["fixed"].range.total == 0
    # the smooth colours of fixed are within a step or two of double
    assert res.renders["fixed"].metrics.max_abs <= 255
    assert "| fixed |" in res.table()


def test_reference_outside_builds_and_unknown_renderer() -> None:
    res = cmp.compare(triangle_scene, 16, 16, builds=("fixed",), peers=("nonsense",), runs=1)
    assert res.renders["fixed"].metrics is not None
    assert res.renders["nonsense"].error.startswith("ValueError")
    assert res.renders["nonsense"].skipped is None and list(res.failed) == ["nonsense"]


def test_unknown_build_or_mesa_driver_is_an_error_not_a_skip(tmp_path) -> None:
    """A misspelt build or Mesa driver fails the comparison (status 1); only
    a known peer that this machine lacks is skipped."""
    res = cmp.compare(triangle_scene, 8, 8, builds=("fixd",), peers=("mesa-foo",), runs=1)
    assert set(res.failed) == {"fixd", "mesa-foo"}
    assert all(res.renders[r].skipped is None for r in ("fixd", "mesa-foo"))
    path = tmp_path / "scene.py"
    path.write_text("def scene(gl, w, h):\n    gl.glClear(gl.GL_COLOR_BUFFER_BIT)\n")
    from gles.__main__ import main

    common = ["compare", str(path), "--size", "8x8", "--runs", "1"]
    assert main([*common, "--builds", "fixd", "--peers", ""]) == 1
    assert main([*common, "--builds", "fixed", "--peers", "mesa-foo"]) == 1


def test_scene_without_frame_is_timed_whole() -> None:
    calls = []

    def whole(gl, w, h):
        calls.append(1)
        gl.glClearColor(1, 0, 0, 1)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)

    r = cmp.render(whole, "float", 8, 8, runs=4)
    assert len(calls) == 1 + 4 and len(r.times_ms) == 4     # one untimed warm-up
    assert (r.image[..., 0] == 255).all()


def test_peer_missing_is_skipped(monkeypatch: pytest.MonkeyPatch) -> None:
    from gles import mesa

    monkeypatch.setattr(mesa, "available", lambda driver="llvmpipe": "no libEGL here")
    r = cmp.render(triangle_scene, "mesa-llvmpipe", 8, 8)
    assert r.skipped == "no libEGL here" and r.image is None


def test_mesa_peer_agrees_on_the_triangle() -> None:
    from gles import mesa

    if mesa.available("llvmpipe") is not None:
        pytest.skip("Mesa llvmpipe is not available")
    res = cmp.compare(triangle_scene, 32, 32, builds=("double",), peers=("mesa-llvmpipe",), runs=1)
    # same coverage rule and rounding to nearest: a few LSB of interpolation difference at most
    assert res.renders["mesa-llvmpipe"].metrics.share_over_1lsb < 0.05


def test_cli_compare_and_render(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scene = tmp_path / "tri.py"
    scene.write_text(
        "import numpy as np\n"
        "from gles import constants as C\n"
        "def scene(gl, w, h):\n"
        "    gl.glClearColor(0.2, 0.4, 0.6, 1)\n"
        "    def frame():\n"
        "        gl.glClear(C.GL_COLOR_BUFFER_BIT)\n"
        "    return frame\n")
    assert main(["compare", str(scene), "--size", "8x8", "--runs", "1", "--peers", "",
                 "--out", str(tmp_path / "o")]) == 0
    out = capsys.readouterr().out
    assert "| fixed |" in out and "| double |" in out
    assert (tmp_path / "o" / "scene_fixed.png").exists()
    assert (tmp_path / "o" / "scene_fixed_diff.png").exists()
    assert main(["render", str(scene), "-o", str(tmp_path / "r.png"), "--size", "4x4"]) == 0
    assert (tmp_path / "r.png").read_bytes().startswith(b"\x89PNG")
    with pytest.raises(SystemExit):
        main(["compare", str(scene), "--size", "0x8"])
    # a missing file, a file without a scene, an unknown scene: an error message, status 2
    assert main(["compare", str(tmp_path / "missing.py")]) == 2
    (tmp_path / "empty.py").write_text("x = 1\n")
    assert main(["render", str(tmp_path / "empty.py"), "-o", str(tmp_path / "e.png")]) == 2
    assert main(["report", "--out", str(tmp_path / "rep"), "--only", "no_such_scene"]) == 2
    assert "error:" in capsys.readouterr().err


def test_gles_compare_is_callable_and_a_module() -> None:
    import gles

    res = gles.compare(triangle_scene, 8, 8, builds=("double",), peers=(), runs=1)
    assert isinstance(res, cmp.Comparison)
    assert gles.compare.metrics is cmp.metrics


# {====================================================================
# failures, range counts per frame, the notebook view

def fails_on_float(gl, w, h):
    """Clears on every build but float, where it raises."""
    if b"(float)" in gl.glGetString(C.GL_RENDERER):
        raise RuntimeError("this scene does not run on float")
    gl.glClearColor(0.25, 0.5, 0.75, 1)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)


def test_a_build_that_raises_is_failed_with_its_traceback() -> None:
    res = cmp.compare(fails_on_float, 8, 8, peers=(), runs=2)
    assert list(res.renders) == ["fixed", "float", "double"]
    bad = res.renders["float"]
    assert bad.error == "RuntimeError: this scene does not run on float"
    assert bad.skipped is None and bad.image is None and bad.metrics is None
    assert bad.traceback.startswith("Traceback (most recent call last):")
    assert "in fails_on_float" in bad.traceback and "raise RuntimeError" in bad.traceback
    assert list(res.failed) == ["float"]
    assert "| float | FAILED: RuntimeError" in res.table()
    # the others still ran and were measured: 0.25, 0.5, 0.75 of 255 round to 64, 128, 191
    for name in ("fixed", "double"):
        r = res.renders[name]
        assert r.error is None and r.traceback is None
        assert (r.image[..., :3] == (64, 128, 191)).all() and math.isinf(r.metrics.psnr)


def test_a_failing_reference_outside_the_builds_is_listed() -> None:
    res = cmp.compare(fails_on_float, 8, 8, builds=("fixed",), peers=(), runs=1, reference="float")
    assert list(res.renders) == ["fixed", "float"] and list(res.failed) == ["float"]
    assert res.renders["fixed"].image is not None and res.renders["fixed"].metrics is None


def test_cli_failing_build_exits_1_with_the_traceback(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    scene = tmp_path / "bad.py"
    scene.write_text(
        "from gles import constants as C\n"
        "def scene(gl, w, h):\n"
        "    if b'(double)' in gl.glGetString(C.GL_RENDERER):\n"
        "        raise ZeroDivisionError('no double here')\n"
        "    gl.glClear(C.GL_COLOR_BUFFER_BIT)\n")
    assert main(["compare", str(scene), "--size", "8x8", "--runs", "1", "--peers", ""]) == 1
    captured = capsys.readouterr()
    assert "| double | FAILED: ZeroDivisionError: no double here |" in captured.out
    assert "Traceback (most recent call last):" in captured.err
    assert f'File "{scene}", line 4, in scene' in captured.err
    assert "compare: double failed: ZeroDivisionError: no double here" in captured.err
    # a peer missing from the machine is not a failure
    ok = tmp_path / "ok.py"
    ok.write_text("def scene(gl, w, h):\n    gl.glClear(0x4000)\n")
    from gles import mesa

    if mesa.available("softpipe") is not None:
        assert main(["compare", str(ok), "--size", "8x8", "--runs", "1", "--peers", "mesa-softpipe"]) == 0


def test_cli_report_exits_1_with_the_traceback(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    from gles import report

    def only_the_failing(only=None):
        return [report.Entry("fails_on_float", "Fails on float", "Techniques", fails_on_float)]

    monkeypatch.setattr(report, "entries", only_the_failing)
    monkeypatch.setattr("gles.target.target_missing", lambda: "not measured here")
    out = tmp_path / "rep"
    assert main(["report", "--out", str(out), "--size", "8x8", "--runs", "1", "--peers", "",
                 "--quiet"]) == 1
    err = capsys.readouterr().err
    assert "report: fails_on_float: float failed: RuntimeError: this scene does not run on float" in err
    assert "Traceback (most recent call last):" in err and "in fails_on_float" in err
    # the report is still written, with the failure in it
    assert "FAILED: RuntimeError" in (out / "report.md").read_text()
    assert (out / "img" / "fails_on_float_fixed.png").exists()


def range_scene(gl, w, h):
    """Setup: one overflowing fog end. Each frame: two overflowing fog starts
    and one fog density that rounds to 0 in 16.16 (1e-6 < 2^-17)."""
    gl.glFogf(C.GL_FOG_END, 1e5)

    def frame():
        gl.glFogf(C.GL_FOG_START, 40000.0)
        gl.glFogf(C.GL_FOG_START, -50000.0)
        gl.glFogf(C.GL_FOG_DENSITY, 1e-6)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
    return frame


def range_scene_whole(gl, w, h):
    """The same calls, timed whole (no frame function)."""
    range_scene(gl, w, h)()


@pytest.mark.parametrize("scene", [range_scene, range_scene_whole])
def test_range_counts_are_per_frame_whatever_the_runs(scene) -> None:
    for runs in (1, 3, 5):
        rng = cmp.render(scene, "fixed", 8, 8, runs=runs).range
        # the setup's one and one frame's three, whatever the number of frames drawn
        assert rng.counts == {"overflow": 3, "underflow": 1, "rule": 0}, runs
        assert rng.by_source == {"glFogf(param)": 4}


def test_range_counts_of_a_hard_case_do_not_grow_with_runs() -> None:
    from gles.hardcases import HARD_CASES

    scene = HARD_CASES["rule_breaking_matrices"].scene
    counts = [cmp.render(scene, "fixed", 32, 32, runs=runs).range.counts for runs in (1, 2, 5)]
    assert counts[0] == counts[1] == counts[2] and counts[0]["rule"] > 0


def test_comparison_html_for_notebooks() -> None:
    import base64
    import re

    res = cmp.compare(fails_on_float, 6, 5, builds=("fixed", "float", "double"),
                      peers=("mesa-softpipe",), runs=1)
    res.renders["fixed"].image[0, 0, :3] = (0, 0, 0)      # a difference for the heatmap to show
    res.renders["fixed"].heatmap = cmp.heatmap(res.renders["fixed"].image, res.renders["double"].image)
    page = res._repr_html_()
    rows = re.findall(r"<tr><td>([^<]+)</td>", page)
    assert rows == list(res.renders)
    assert "FAILED: RuntimeError: this scene does not run on float" in page
    assert "in fails_on_float" in page                     # the traceback, folded
    soft = res.renders["mesa-softpipe"]
    if soft.skipped is not None:
        assert f"skipped: {soft.skipped}" in page
    urls = re.findall(r"src='data:image/png;base64,([A-Za-z0-9+/=]+)'", page)
    drawn = [r for r in res.renders.values() if r.image is not None]
    assert len(urls) == 2 * len(drawn)
    for r, (img, hm) in zip(drawn, zip(urls[::2], urls[1::2])):
        assert np.array_equal(decode_png(base64.b64decode(img, validate=True)), r.image)
        assert np.array_equal(decode_png(base64.b64decode(hm, validate=True)), r.heatmap)
    assert decode_png(base64.b64decode(urls[1]))[0, 0].any()   # fixed's one differing pixel
