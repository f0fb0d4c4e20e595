"""gles.compare: its metrics against numpy computed independently, and the
compare/render/CLI plumbing on a small scene."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
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
