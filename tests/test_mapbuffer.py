"""OES_mapbuffer and EXT_map_buffer_range: a mapping reaches Python as a
numpy copy written back at unmap (or flush). Expected bytes are the ones
written; drawing from a buffer filled through a mapping is compared with the
same buffer filled by glBufferData, and with Mesa, whose mapping is the
store's address (written here with ctypes)."""

from __future__ import annotations

import ctypes

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import mesa

_MESA = mesa.available()
needs_mesa = pytest.mark.skipif(_MESA is not None, reason=f"Mesa peer unavailable: {_MESA}")

AB = C.GL_ARRAY_BUFFER
R, W_, FLUSH = C.GL_MAP_READ_BIT_EXT, C.GL_MAP_WRITE_BIT_EXT, C.GL_MAP_FLUSH_EXPLICIT_BIT_EXT


def _ctx_with_buffer(data: np.ndarray):
    ctx = gles.Context(16, 16)
    gl = ctx.gl
    gl.glBindBuffer(AB, int(gl.glGenBuffers(1)))
    gl.glBufferData(AB, data.nbytes, data, C.GL_DYNAMIC_DRAW)
    return ctx, gl


def _contents(gl, n: int) -> np.ndarray:
    """The buffer's bytes, through a read mapping."""
    got = gl.glMapBufferRangeEXT(AB, 0, n, R)
    assert gl.glUnmapBufferOES(AB)
    return got


def test_write_then_unmap_keeps_unwritten_bytes() -> None:
    ctx, gl = _ctx_with_buffer(np.arange(32, dtype=np.uint8))
    m = gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)
    assert m.shape == (32,) and m.dtype == np.uint8
    assert gl.glGetBufferParameteriv(AB, C.GL_BUFFER_MAPPED_OES) == 1
    assert gl.glGetBufferParameteriv(AB, C.GL_BUFFER_ACCESS_OES) == C.GL_WRITE_ONLY_OES
    assert gl.glGetBufferPointervOES(AB, C.GL_BUFFER_MAP_POINTER_OES) is m
    m[4:8] = 200
    assert gl.glUnmapBufferOES(AB) is True
    assert gl.glGetBufferParameteriv(AB, C.GL_BUFFER_MAPPED_OES) == 0
    assert gl.glGetBufferPointervOES(AB, C.GL_BUFFER_MAP_POINTER_OES) is None
    want = np.arange(32, dtype=np.uint8)
    want[4:8] = 200
    np.testing.assert_array_equal(_contents(gl, 32), want)
    # the array outlives the mapping as plain memory: writes after the unmap change nothing
    m[:] = 1
    np.testing.assert_array_equal(_contents(gl, 32), want)
    assert gl.glGetError() == C.GL_NO_ERROR


def test_range_mappings_and_explicit_flushes() -> None:
    ctx, gl = _ctx_with_buffer(np.zeros(64, np.uint8))
    m = gl.glMapBufferRangeEXT(AB, 16, 32, W_)
    assert m.shape == (32,)
    m[:] = 7
    gl.glUnmapBufferOES(AB)
    want = np.zeros(64, np.uint8)
    want[16:48] = 7
    np.testing.assert_array_equal(_contents(gl, 64), want)
    # with FLUSH_EXPLICIT only the flushed subranges reach the buffer
    m = gl.glMapBufferRangeEXT(AB, 8, 16, W_ | FLUSH)
    m[:] = 9
    gl.glFlushMappedBufferRangeEXT(AB, 2, 3)            # from the mapping's start
    gl.glFlushMappedBufferRangeEXT(AB, 10, 1)
    assert gl.glGetError() == C.GL_NO_ERROR
    gl.glUnmapBufferOES(AB)
    want[10:13] = 9
    want[18] = 9
    np.testing.assert_array_equal(_contents(gl, 64), want)


def test_map_errors() -> None:
    ctx, gl = _ctx_with_buffer(np.zeros(16, np.uint8))
    cases = [
        (lambda: gl.glMapBufferOES(AB, 0x88B8), C.GL_INVALID_ENUM),             # READ_ONLY: not in ES 1
        (lambda: gl.glMapBufferOES(C.GL_TEXTURE_2D, C.GL_WRITE_ONLY_OES), C.GL_INVALID_ENUM),
        (lambda: gl.glMapBufferRangeEXT(AB, -1, 4, W_), C.GL_INVALID_VALUE),
        (lambda: gl.glMapBufferRangeEXT(AB, 8, 9, W_), C.GL_INVALID_VALUE),       # past BUFFER_SIZE
        (lambda: gl.glMapBufferRangeEXT(AB, 0, 4, W_ | 0x40), C.GL_INVALID_VALUE),  # unknown bit
        (lambda: gl.glMapBufferRangeEXT(AB, 0, 0, W_), C.GL_INVALID_OPERATION),    # length 0
        (lambda: gl.glMapBufferRangeEXT(AB, 0, 4, FLUSH), C.GL_INVALID_OPERATION),  # neither R nor W
        (lambda: gl.glMapBufferRangeEXT(AB, 0, 4, R | C.GL_MAP_INVALIDATE_RANGE_BIT_EXT),
         C.GL_INVALID_OPERATION),
        (lambda: gl.glMapBufferRangeEXT(AB, 0, 4, R | FLUSH), C.GL_INVALID_OPERATION),
        (lambda: gl.glUnmapBufferOES(AB), C.GL_INVALID_OPERATION),                # not mapped
        (lambda: gl.glFlushMappedBufferRangeEXT(AB, 0, 1), C.GL_INVALID_OPERATION),
    ]
    for call, err in cases:
        assert call() in (None, False)
        assert gl.glGetError() == err
    assert gl.glGetBufferParameteriv(AB, C.GL_BUFFER_MAPPED_OES) == 0
    gl.glMapBufferRangeEXT(AB, 4, 8, W_)
    gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)                                   # already mapped
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    gl.glFlushMappedBufferRangeEXT(AB, 0, 1)                                      # no FLUSH_EXPLICIT
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    gl.glBufferSubData(AB, 0, np.ones(4, np.uint8))                              # the store is the client's
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    gl.glUnmapBufferOES(AB)
    m = gl.glMapBufferRangeEXT(AB, 4, 8, W_ | FLUSH)
    gl.glFlushMappedBufferRangeEXT(AB, 4, 5)                                      # past the mapping
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glBindBuffer(AB, 0)
    gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)                                    # no buffer bound
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    del m


def test_draws_refuse_mapped_buffers() -> None:
    ctx, gl = _ctx_with_buffer(np.array([0, 0, 16, 0, 0, 16, 16, 16], np.float32))
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthof(0, 16, 0, 16, -1, 1)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, 0)
    gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    idx = int(gl.glGenBuffers(1))
    gl.glUnmapBufferOES(AB)
    gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, idx)
    gl.glBufferData(C.GL_ELEMENT_ARRAY_BUFFER, np.array([0, 1, 2, 3], np.uint16), C.GL_STATIC_DRAW)
    gl.glMapBufferOES(C.GL_ELEMENT_ARRAY_BUFFER, C.GL_WRITE_ONLY_OES)
    gl.glDrawElements(C.GL_TRIANGLE_STRIP, 4, C.GL_UNSIGNED_SHORT, 0)
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    assert (np.asarray(ctx.image())[..., 3] == 0).all()        # nothing drawn
    gl.glUnmapBufferOES(C.GL_ELEMENT_ARRAY_BUFFER)
    gl.glDrawElements(C.GL_TRIANGLE_STRIP, 4, C.GL_UNSIGNED_SHORT, 0)
    assert gl.glGetError() == C.GL_NO_ERROR


def test_mapping_ends_with_new_data_or_deletion() -> None:
    ctx, gl = _ctx_with_buffer(np.zeros(16, np.uint8))
    m = gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)
    gl.glBufferData(AB, 8, np.full(8, 5, np.uint8), C.GL_STATIC_DRAW)           # unmaps
    assert gl.glGetBufferParameteriv(AB, C.GL_BUFFER_MAPPED_OES) == 0
    m[:] = 1                                                                     # Python memory only
    assert gl.glUnmapBufferOES(AB) is False
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    np.testing.assert_array_equal(_contents(gl, 8), np.full(8, 5, np.uint8))
    m = gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)
    gl.glDeleteBuffers([gl.glGetIntegerv(C.GL_ARRAY_BUFFER_BINDING)])
    m[:] = 3                                                                     # the store is gone; no crash
    assert gl.glGetError() == C.GL_NO_ERROR


def _quad_scene(ctx, fill) -> np.ndarray:
    """A quad's vertices and colours in one buffer, written by `fill(gl)`;
    flat shaded, so every pixel is one vertex's colour exactly."""
    gl = ctx.gl
    gl.glShadeModel(C.GL_FLAT)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)          # (a new surface's contents are undefined)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthof(0, 16, 0, 16, -1, 1)
    gl.glBindBuffer(AB, int(gl.glGenBuffers(1)))
    gl.glBufferData(AB, 128, None, C.GL_DYNAMIC_DRAW)
    fill(gl)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, 0)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, 64)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    assert gl.glGetError() == C.GL_NO_ERROR
    return np.asarray(gl.glReadPixels(0, 0, 16, 16, C.GL_RGBA, C.GL_UNSIGNED_BYTE))


_VERTS = np.array([2, 2, 14, 2, 2, 14, 14, 14], np.float32).tobytes()
_COLORS = np.array([[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 0, 255]],
                   np.uint8).tobytes()


def _fill_by_map(gl) -> None:
    m = gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)
    m[:32] = np.frombuffer(_VERTS, np.uint8)
    assert gl.glUnmapBufferOES(AB)
    r = gl.glMapBufferRangeEXT(AB, 64, 16, W_ | C.GL_MAP_INVALIDATE_RANGE_BIT_EXT)
    r[:] = np.frombuffer(_COLORS, np.uint8)
    assert gl.glUnmapBufferOES(AB)


def _fill_by_data(gl) -> None:
    gl.glBufferSubData(AB, 0, _VERTS)
    gl.glBufferSubData(AB, 64, _COLORS)


def _fill_mesa(gl) -> None:
    p = gl.glMapBufferOES(AB, C.GL_WRITE_ONLY_OES)
    ctypes.memmove(p, _VERTS, len(_VERTS))
    assert gl.glUnmapBufferOES(AB)
    p = gl.glMapBufferRangeEXT(AB, 64, 16, W_ | C.GL_MAP_INVALIDATE_RANGE_BIT_EXT)
    ctypes.memmove(p, _COLORS, len(_COLORS))
    assert gl.glUnmapBufferOES(AB)


def test_drawing_from_a_mapped_fill_matches_buffer_data() -> None:
    with gles.Context(16, 16) as a, gles.Context(16, 16) as b:
        np.testing.assert_array_equal(_quad_scene(a, _fill_by_map), _quad_scene(b, _fill_by_data))


@needs_mesa
def test_drawing_from_a_mapped_fill_matches_mesa() -> None:
    with gles.Context(16, 16) as a, mesa.MesaContext(16, 16) as peer:
        np.testing.assert_array_equal(_quad_scene(a, _fill_by_map), _quad_scene(peer, _fill_mesa))


def test_extensions_listed() -> None:
    ext = gles.Context(2, 2).gl.glGetString(C.GL_EXTENSIONS).split()
    assert b"GL_OES_mapbuffer" in ext and b"GL_EXT_map_buffer_range" in ext
