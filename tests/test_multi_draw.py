"""EXT_multi_draw_arrays: the extension's loop of DrawArrays/DrawElements,
checked against the draws made one by one, and against Mesa."""

from __future__ import annotations

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import mesa

_MESA = mesa.available()
needs_mesa = pytest.mark.skipif(_MESA is not None, reason=f"Mesa peer unavailable: {_MESA}")

W = H = 32
# four strips of 10 vertices, one per row of 8-pixel cells, one after the other
_GRID = np.array([[x, y + d] for y in range(0, 32, 8) for x in range(0, 33, 8) for d in (0, 8)], np.float32)
_COLORS = np.random.default_rng(3).integers(0, 256, (len(_GRID), 4), dtype=np.uint8)
_COLORS[:, 3] = 255


def _setup(ctx):
    gl = ctx.gl
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthof(0, W, 0, H, -1, 1)
    gl.glShadeModel(C.GL_FLAT)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)          # (a new surface's contents are undefined)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, _GRID)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, _COLORS)
    return gl


def _read(gl) -> np.ndarray:
    return np.asarray(gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE))


FIRST, COUNT = [0, 10, 22, 30], [6, 0, 8, 10]
# parts of the first and third strips, by index
STRIPS = [np.arange(0, 6, dtype=np.uint16), np.array([], np.uint16), np.arange(20, 28, dtype=np.uint16)]


def _multi(ctx) -> tuple[np.ndarray, np.ndarray]:
    gl = _setup(ctx)
    gl.glMultiDrawArraysEXT(C.GL_TRIANGLE_STRIP, FIRST, COUNT, 4)
    arrays = _read(gl)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glMultiDrawElementsEXT(C.GL_TRIANGLE_STRIP, [len(s) for s in STRIPS], C.GL_UNSIGNED_SHORT, STRIPS, 3)
    elements = _read(gl)
    assert gl.glGetError() == C.GL_NO_ERROR
    return arrays, elements


def test_multi_draws_are_the_single_draws() -> None:
    with gles.Context(W, H) as a, gles.Context(W, H) as b:
        arrays, elements = _multi(a)
        gl = _setup(b)
        for f, c in zip(FIRST, COUNT):
            if c:
                gl.glDrawArrays(C.GL_TRIANGLE_STRIP, f, c)
        np.testing.assert_array_equal(arrays, _read(gl))
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        for s in STRIPS:
            if len(s):
                gl.glDrawElements(C.GL_TRIANGLE_STRIP, len(s), C.GL_UNSIGNED_SHORT, s)
        np.testing.assert_array_equal(elements, _read(gl))
    assert (arrays[..., 3] > 0).any() and (elements[..., 3] > 0).any()


@needs_mesa
def test_multi_draws_match_mesa() -> None:
    with gles.Context(W, H) as ours, mesa.MesaContext(W, H) as peer:
        for got, want in zip(_multi(ours), _multi(peer)):
            np.testing.assert_array_equal(got, want)


def test_multi_draw_elements_from_a_buffer() -> None:
    with gles.Context(W, H) as a, gles.Context(W, H) as b:
        _, want = _multi(b)
        gl = _setup(a)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, int(gl.glGenBuffers(1)))
        data = np.concatenate([STRIPS[0], STRIPS[2]])
        gl.glBufferData(C.GL_ELEMENT_ARRAY_BUFFER, data.nbytes, data, C.GL_STATIC_DRAW)
        gl.glMultiDrawElementsEXT(C.GL_TRIANGLE_STRIP, [6, 8], C.GL_UNSIGNED_SHORT, [0, 12], 2)
        np.testing.assert_array_equal(_read(gl), want)


def test_multi_draw_errors() -> None:
    gl = _setup(gles.Context(W, H))
    gl.glMultiDrawArraysEXT(C.GL_TRIANGLES, [0], [3], -1)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glMultiDrawArraysEXT(0x0007, [0], [4], 1)           # GL_QUADS: no ES mode
    assert gl.glGetError() == C.GL_INVALID_ENUM
    gl.glMultiDrawArraysEXT(0x0007, [0], [0], 1)           # no list drawn: no error (the loop)
    assert gl.glGetError() == C.GL_NO_ERROR
    with pytest.raises(ValueError, match="count holds 1 items"):
        gl.glMultiDrawArraysEXT(C.GL_TRIANGLES, [0, 3], [3], 2)
    with pytest.raises(ValueError):
        gl.glMultiDrawArraysEXT(C.GL_TRIANGLES, [0], [2**40], 1)
    with pytest.raises(ValueError):                          # past the vertex array, as DrawArrays
        gl.glMultiDrawArraysEXT(C.GL_TRIANGLES, [0], [300], 1)
    assert (_read(gl) == 0).all()


def test_extension_listed() -> None:
    assert b"GL_EXT_multi_draw_arrays" in gles.Context(2, 2).gl.glGetString(C.GL_EXTENSIONS).split()
