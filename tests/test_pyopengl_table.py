"""README's "PyOpenGL → gles" table: one test per row (test_row_<id>_...)."""

from __future__ import annotations

import re
import threading
import warnings
from pathlib import Path

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import gl as module_gl

README = Path(__file__).resolve().parents[1] / "README.md"


def make(**kw) -> gles.Context:
    return gles.Context(8, 8, **kw)


def test_every_row_has_a_test() -> None:
    text = README.read_text(encoding="utf-8")
    section = text.split("### PyOpenGL → gles", 1)[1].split("\n#", 1)[0]
    ids = re.findall(r"^\| (P\d+) \|", section, flags=re.M)
    assert ids == [f"P{i}" for i in range(1, len(ids) + 1)] and len(ids) >= 15
    tests = {n.split("_")[2] for n in globals() if n.startswith("test_row_")}
    assert tests == set(ids)


def test_row_P1_constants() -> None:
    assert module_gl.GL_TEXTURE_2D == 0x0DE1 and repr(module_gl.GL_TEXTURE_2D) == "GL_TEXTURE_2D"
    g = make().gl
    assert g.GL_TEXTURE_2D is C.GL_TEXTURE_2D and g.GL_RGBA == 0x1908


def test_row_P2_contexts() -> None:
    a, b = make(), make()
    a.gl.glClearColor(1, 0, 0, 1)            # bound: no current context needed
    a.gl.glClear(C.GL_COLOR_BUFFER_BIT)
    seen = {}

    def other_thread() -> None:
        b.make_current()
        module_gl.glClearColor(0, 1, 0, 1)
        module_gl.glClear(C.GL_COLOR_BUFFER_BIT)
        seen["b"] = module_gl.current_gl() is b.gl

    t = threading.Thread(target=other_thread)
    t.start()
    t.join()
    assert seen["b"]
    assert tuple(a.image()[0, 0]) == (255, 0, 0, 255) and tuple(b.image()[0, 0]) == (0, 255, 0, 255)


def test_row_P3_errors() -> None:
    ctx = make()
    ctx.gl.glEnable(0x1234)                  # recorded, not raised
    assert ctx.gl.glGetError() == C.GL_INVALID_ENUM
    ctx.check_errors = True
    with pytest.raises(gles.GLError) as info:
        ctx.gl.glEnable(0x1234)
    assert info.value.err == C.GL_INVALID_ENUM and info.value.function == "glEnable"
    assert info.value.py_args == (0x1234,)
    assert ctx.gl.glGetError() == 0          # consumed


def test_row_P4_gen() -> None:
    g = make().gl
    one = g.glGenTextures(1)
    assert isinstance(one, int) and one > 0
    three = g.glGenBuffers(3)
    assert isinstance(three, np.ndarray) and three.dtype == np.uint32 and three.shape == (3,)


def test_row_P5_delete() -> None:
    g = make().gl
    names = g.glGenTextures(3)
    for n in names:
        g.glBindTexture(C.GL_TEXTURE_2D, int(n))
    g.glDeleteTextures(names)                # PyOpenGL's form
    assert not any(g.glIsTexture(int(n)) for n in names)
    bufs = [int(v) for v in g.glGenBuffers(2)]
    for n in bufs:
        g.glBindBuffer(C.GL_ARRAY_BUFFER, n)
    g.glDeleteBuffers(bufs[:1])
    assert not g.glIsBuffer(bufs[0]) and g.glIsBuffer(bufs[1])
    g.glDeleteBuffers(1, bufs[1:])           # the C form
    assert not g.glIsBuffer(bufs[1])
    t = g.glGenTextures(1)
    g.glBindTexture(C.GL_TEXTURE_2D, t)
    g.glDeleteTextures(t)                    # one int: one name
    assert not g.glIsTexture(t) and g.glGetError() == 0
    with pytest.raises(TypeError, match="glDeleteTextures"):
        g.glDeleteTextures(1.5)


def test_row_P6_buffer_data_sizes() -> None:
    g = make().gl
    b = g.glGenBuffers(1)
    g.glBindBuffer(C.GL_ARRAY_BUFFER, b)
    data = np.arange(6, dtype=np.float32)
    g.glBufferData(C.GL_ARRAY_BUFFER, data, C.GL_STATIC_DRAW)
    assert g.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_SIZE) == 24
    assert g.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_USAGE) == C.GL_STATIC_DRAW
    g.glBufferSubData(C.GL_ARRAY_BUFFER, 8, np.array([7, 8], np.float32))
    # what the buffer holds, read back through a draw's vertex fetch would need more setup:
    # the size and the GL error state are the contract here
    assert g.glGetError() == 0
    g.glBufferData(C.GL_ARRAY_BUFFER, 10, None, C.GL_DYNAMIC_DRAW)    # the C form
    assert g.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_SIZE) == 10
    g.glBufferSubData(C.GL_ARRAY_BUFFER, 2, 4, b"abcd")               # the C form
    assert g.glGetError() == 0
    with pytest.raises(TypeError, match="glBufferData"):
        g.glBufferData(C.GL_ARRAY_BUFFER, 16, C.GL_STATIC_DRAW)      # an int is not data
    with pytest.raises(TypeError, match="glBufferSubData"):
        g.glBufferSubData(C.GL_ARRAY_BUFFER, 0, 4)
    assert g.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_SIZE) == 10


@pytest.mark.parametrize("numeric", ["fixed", "float", "double"])
def test_row_P7_matrix_queries(numeric: str) -> None:
    g = make(numeric=numeric).gl
    g.glTranslatef(1.0, 2.0, 3.0)
    m = g.glGetFloatv(C.GL_MODELVIEW_MATRIX)
    want = np.eye(4, dtype=np.float32)
    want[3, :3] = (1, 2, 3)                  # column-major: row 3 of the array is column 3
    assert m.shape == (4, 4) and np.array_equal(m, want)
    assert np.array_equal(g.glGetFixedv(C.GL_MODELVIEW_MATRIX), np.round(want * 65536))
    assert np.array_equal(g.glGetIntegerv(C.GL_MODELVIEW_MATRIX), want.astype(np.int32))
    assert g.glGetBooleanv(C.GL_PROJECTION_MATRIX).shape == (4, 4)
    assert g.glGetIntegerv(C.GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES).shape == (4, 4)
    assert isinstance(g.glGetIntegerv(C.GL_MATRIX_MODE), int)
    assert g.glGetIntegerv(C.GL_VIEWPORT).shape == (4,)


def test_row_P8_get_string() -> None:
    g = make().gl
    for name in (C.GL_VENDOR, C.GL_RENDERER, C.GL_VERSION, C.GL_EXTENSIONS):
        assert isinstance(g.glGetString(name), bytes)
    assert g.glGetString(C.GL_VERSION) == b"OpenGL ES-CM 1.1"
    assert b"GL_OES_fixed_point" in g.glGetString(C.GL_EXTENSIONS).split()
    assert g.glGetString(0x1234) is None and g.glGetError() == C.GL_INVALID_ENUM


def test_row_P9_read_pixels() -> None:
    ctx = make()
    g = ctx.gl
    g.glClearColor(1, 0, 0, 1)
    g.glClear(C.GL_COLOR_BUFFER_BIT)
    px = g.glReadPixels(0, 0, 8, 4, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    assert isinstance(px, np.ndarray) and px.dtype == np.uint8 and px.shape == (4, 8, 4)
    assert (px == [255, 0, 0, 255]).all()
    out = bytearray(8 * 4 * 4)
    assert g.glReadPixels(0, 0, 8, 4, C.GL_RGBA, C.GL_UNSIGNED_BYTE, out) is None
    assert bytes(out) == px.tobytes()
    with pytest.raises(TypeError):
        g.glReadPixels(0, 0, 8, 4, C.GL_RGBA, C.GL_UNSIGNED_BYTE, outputType=bytes)
    c565 = gles.Context(4, 2, color="rgb565")
    c565.gl.glClearColor(1, 0, 0, 1)
    c565.gl.glClear(C.GL_COLOR_BUFFER_BIT)
    raw = c565.gl.glReadPixels(0, 0, 4, 2, C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5)
    assert raw.dtype == np.uint16 and raw.shape == (2, 4) and (raw == 0xF800).all()


def test_row_P10_dtype_must_match_type() -> None:
    g = make().gl
    with pytest.raises(TypeError, match="glVertexPointer"):
        g.glVertexPointer(2, C.GL_FLOAT, 0, np.zeros(8, np.float64))
    with pytest.raises(TypeError, match="glTexImage2D"):
        g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 2, 2, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                       np.ones((2, 2, 4), np.float32))
    assert g.glGetPointerv(C.GL_VERTEX_ARRAY_POINTER) == 0 and g.glGetError() == 0


def test_row_P11_buffer_offsets() -> None:
    g = make().gl
    with pytest.raises(ValueError, match="bound buffer"):
        g.glVertexPointer(2, C.GL_FLOAT, 0, 16)
    b = g.glGenBuffers(1)
    g.glBindBuffer(C.GL_ARRAY_BUFFER, b)
    g.glBufferData(C.GL_ARRAY_BUFFER, np.zeros(16, np.float32), C.GL_STATIC_DRAW)
    g.glVertexPointer(2, C.GL_FLOAT, 0, 16)
    assert g.glGetPointerv(C.GL_VERTEX_ARRAY_POINTER) == 16
    g.glVertexPointer(2, C.GL_FLOAT, 0, None)
    assert g.glGetPointerv(C.GL_VERTEX_ARRAY_POINTER) == 0


def test_row_P12_fixed_arguments() -> None:
    g = make().gl
    g.glClearColorx(65536, 0, 32768, 65536)
    assert np.allclose(g.glGetFloatv(C.GL_COLOR_CLEAR_VALUE), [1, 0, 0.5, 1])
    with pytest.raises(TypeError, match="glClearColorx: green=0.5"):
        g.glClearColorx(65536, 0.5, 0, 65536)
    assert np.allclose(g.glGetFloatv(C.GL_COLOR_CLEAR_VALUE), [1, 0, 0.5, 1])


def test_row_P13_query_matrix() -> None:
    g = make().gl
    g.glTranslatex(3 << 16, 0, 0)
    mantissa, exponent, status = g.glQueryMatrixxOES()
    assert status == 0 and mantissa.shape == exponent.shape == (16,)
    assert mantissa[12] / 65536 * 2.0 ** exponent[12] == 3.0


def test_row_P14_common_lite() -> None:
    lite = make(profile="common-lite")
    assert hasattr(lite.gl, "glClearColorx") and not hasattr(lite.gl, "glClearColor")
    with pytest.raises(AttributeError):
        lite.gl.glClearColor(0, 0, 0, 1)
    lite.make_current()
    try:
        with pytest.raises(AttributeError, match="Common-profile command"):
            module_gl.glClearColor(0, 0, 0, 1)
    finally:
        module_gl._set_current(None)


def test_row_P15_range_warning() -> None:
    g = make(numeric="fixed").gl
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        g.glTranslatef(40000.0, 0, 0)
    assert [w.category for w in caught] == [gles.RangeWarning]
    assert "glTranslatef" in str(caught[0].message)


def test_row_P16_mapped_buffer() -> None:
    g = make().gl
    g.glBindBuffer(C.GL_ARRAY_BUFFER, g.glGenBuffers(1))
    g.glBufferData(C.GL_ARRAY_BUFFER, np.zeros(8, np.uint8), C.GL_STATIC_DRAW)
    m = g.glMapBufferOES(C.GL_ARRAY_BUFFER, C.GL_WRITE_ONLY_OES)
    assert isinstance(m, np.ndarray) and m.dtype == np.uint8 and m.shape == (8,)
    assert g.glGetBufferPointervOES(C.GL_ARRAY_BUFFER, C.GL_BUFFER_MAP_POINTER_OES) is m
    m[:] = 5
    assert g.glUnmapBufferOES(C.GL_ARRAY_BUFFER) is True
    back = g.glMapBufferRangeEXT(C.GL_ARRAY_BUFFER, 0, 8, C.GL_MAP_READ_BIT_EXT)
    assert (back == 5).all()
    g.glUnmapBufferOES(C.GL_ARRAY_BUFFER)


def test_row_P17_debug_callback() -> None:
    import gles.debug

    ctx = make()
    g = ctx.gl
    assert g.glGetPointerv(C.GL_DEBUG_CALLBACK_FUNCTION_KHR) is gles.debug.log_message
    seen: list = []
    param = {"any": "object"}
    g.glDebugMessageCallbackKHR(lambda *a: seen.append(a), param)
    g.glEnable(C.GL_DEBUG_OUTPUT_KHR)
    g.glDebugMessageInsertKHR(C.GL_DEBUG_SOURCE_APPLICATION_KHR, C.GL_DEBUG_TYPE_MARKER_KHR, 5,
                              C.GL_DEBUG_SEVERITY_NOTIFICATION_KHR, -1, "hello")
    assert seen == [(C.GL_DEBUG_SOURCE_APPLICATION_KHR, C.GL_DEBUG_TYPE_MARKER_KHR, 5,
                     C.GL_DEBUG_SEVERITY_NOTIFICATION_KHR, 5, b"hello", param)]
    assert g.glGetPointerv(C.GL_DEBUG_CALLBACK_USER_PARAM_KHR) is param

    def fails(*a):
        raise RuntimeError("in the callback")

    g.glDebugMessageCallbackKHR(fails, None)
    with pytest.raises(RuntimeError):
        g.glEnable(0x1234)
    g.glDebugMessageCallbackKHR(None, None)
    g.glEnable(0x1234)
    assert g.glGetIntegerv(C.GL_DEBUG_LOGGED_MESSAGES_KHR) == 1
    tex = g.glGenTextures(1)
    g.glBindTexture(C.GL_TEXTURE_2D, tex)
    g.glObjectLabelKHR(C.GL_TEXTURE, tex, -1, "albedo")
    assert g.glGetObjectLabelKHR(C.GL_TEXTURE, tex, 64) == b"albedo"
