"""Scenes that take their constants from ``gl`` (gl.GL_TEXTURE_2D) run on every
build and peer through compare, render, report and the command line."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import gles
from gles import compare as cmp
from gles import report
from gles.__main__ import main

# a 2x2 texture: red, green / blue, white (bottom row first)
TEXELS = np.array([[[255, 0, 0, 255], [0, 255, 0, 255]],
                   [[0, 0, 255, 255], [255, 255, 255, 255]]], np.uint8)


def textured_scene(gl, w, h):
    """A 2x2 NEAREST texture stretched over the viewport, every name through `gl`."""
    tex = gl.glGenTextures(1)
    gl.glBindTexture(gl.GL_TEXTURE_2D, tex)
    gl.glTexParameterx(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST)
    gl.glTexParameterx(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST)
    gl.glTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_RGBA, 2, 2, 0, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE, TEXELS)
    gl.glEnable(gl.GL_TEXTURE_2D)
    verts = np.array([-1, -1, 1, -1, -1, 1, 1, 1], np.float32)
    uv = np.array([0, 0, 1, 0, 0, 1, 1, 1], np.float32)

    def frame():
        gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
        gl.glEnableClientState(gl.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(2, gl.GL_FLOAT, 0, verts)
        gl.glTexCoordPointer(2, gl.GL_FLOAT, 0, uv)
        gl.glDrawArrays(gl.GL_TRIANGLE_STRIP, 0, 4)
    return frame


def expected(w: int, h: int) -> np.ndarray:
    """Each quarter of the window shows one texel (top row first)."""
    img = np.empty((h, w, 4), np.uint8)
    img[h // 2:, : w // 2] = TEXELS[0, 0]
    img[h // 2:, w // 2:] = TEXELS[0, 1]
    img[: h // 2, : w // 2] = TEXELS[1, 0]
    img[: h // 2, w // 2:] = TEXELS[1, 1]
    return img


def failing_scene(gl, w, h):
    gl.glClear(gl.GL_NO_SUCH_CONSTANT)


@pytest.mark.parametrize("numeric", ["fixed", "float", "double"])
def test_gl_carries_every_constant(numeric: str) -> None:
    ctx = gles.Context(4, 4, numeric=numeric)
    for profile_ctx in (ctx, gles.Context(4, 4, numeric=numeric, profile="common-lite")):
        for name in gles.constants.__all__:
            assert getattr(profile_ctx.gl, name) == getattr(gles.constants, name)
    ctx.check_errors = True                 # the checked class too
    ctx.range_check = "raise"               # and the ranged one
    assert ctx.gl.GL_TEXTURE_2D == 0x0DE1 and repr(ctx.gl.GL_TEXTURE_2D) == "GL_TEXTURE_2D"


def test_compare_runs_a_scene_using_gl_constants() -> None:
    from gles import mesa

    peers = ("mesa-llvmpipe",) if mesa.available("llvmpipe") is None else ()
    res = cmp.compare(textured_scene, 16, 16, peers=peers, runs=1)
    assert res.failed == {}
    for r in res.renders.values():
        assert r.skipped is None and r.error is None and r.gl_error == 0
        assert np.array_equal(r.image, expected(16, 16)), r.renderer
        assert r.heatmap is not None


def test_render_runs_a_scene_using_gl_constants() -> None:
    for numeric in cmp.BUILDS:
        r = cmp.render(textured_scene, numeric, 8, 8, runs=1)
        assert np.array_equal(r.image, expected(8, 8))


def test_report_runs_a_scene_using_gl_constants(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    entry = report.Entry("textured", "a texture through gl.GL_*", "Techniques", textured_scene)
    monkeypatch.setattr(report, "entries", lambda only=None: [entry])
    page = report.build_report(tmp_path, 8, 8, runs=1, peers=(), progress=False)
    text = page.read_text()
    assert "FAILED" not in text and "skipped" not in text
    for numeric in cmp.BUILDS:
        assert (tmp_path / "img" / f"textured_{numeric}.png").exists()


def test_a_failing_build_is_a_failure_not_a_skip(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    res = cmp.compare(failing_scene, 8, 8, peers=(), runs=1)
    assert sorted(res.failed) == ["double", "fixed", "float"]
    for r in res.renders.values():
        assert r.skipped is None and r.error.startswith("AttributeError") and "GL_NO_SUCH_CONSTANT" in r.error
    assert "FAILED" in res.table()
    path = tmp_path / "bad.py"
    path.write_text("def scene(gl, w, h):\n    gl.glClear(gl.GL_NO_SUCH_CONSTANT)\n")
    assert main(["compare", str(path), "--size", "8x8", "--runs", "1", "--peers", ""]) == 1
    assert "fixed failed: AttributeError" in capsys.readouterr().err
    assert main(["render", str(path), "-o", str(tmp_path / "bad.png"), "--size", "4x4"]) == 1
    assert not (tmp_path / "bad.png").exists()
    good = tmp_path / "good.py"
    good.write_text("import numpy as np\n"
                    "def scene(gl, w, h):\n"
                    "    gl.glClearColor(0, 1, 0, 1)\n"
                    "    gl.glClear(gl.GL_COLOR_BUFFER_BIT)\n")
    assert main(["compare", str(good), "--size", "8x8", "--runs", "1", "--peers", ""]) == 0
    assert main(["render", str(good), "-o", str(tmp_path / "good.png"), "--size", "4x4"]) == 0
