"""The Mesa peer (gles.mesa): EGL setup, the Python GL conventions, both drivers.

Expected pixel values are worked out by hand from the scene: an orthographic
projection glOrthof(0, W, 0, H) maps object units to window pixels, so pixel
(x, y) is inside a triangle when its centre (x + 0.5, y + 0.5) is.
"""

from __future__ import annotations

import gc
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import mesa

_REASON = mesa.available()
pytestmark = pytest.mark.skipif(_REASON is not None,
                                reason=f"Mesa peer unavailable: {_REASON}")

_SOFTPIPE_REASON = mesa.available("softpipe") if _REASON is None else _REASON
needs_softpipe = pytest.mark.skipif(_SOFTPIPE_REASON is not None,
                                    reason=f"softpipe unavailable: {_SOFTPIPE_REASON}")

# the directory the gles under test was imported from (the installed
# package in CI, src/ in a development tree)
SRC = Path(gles.__file__).resolve().parents[1]


def run_python(code: str) -> subprocess.CompletedProcess:
    """Run ``code`` in a fresh interpreter that imports the gles under test."""
    path = os.pathsep.join(filter(None, [str(SRC), os.environ.get("PYTHONPATH")]))
    return subprocess.run([sys.executable, "-c", code],
                          env={**os.environ, "PYTHONPATH": path},
                          capture_output=True, text=True, timeout=120)


@pytest.fixture
def ctx():
    with mesa.MesaContext(32, 32) as c:
        yield c


def ortho(gl, w: int, h: int) -> None:
    """Object units = window pixels, origin bottom-left."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0.0, float(w), 0.0, float(h), -1.0, 1.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def read_rgba(gl, w: int, h: int) -> np.ndarray:
    return gl.glReadPixels(0, 0, w, h, C.GL_RGBA, C.GL_UNSIGNED_BYTE)


def test_context_basics(ctx):
    gl = ctx.gl
    assert gl.glGetString(C.GL_VERSION).startswith(b"OpenGL ES-CM 1.1")
    assert b"llvmpipe" in gl.glGetString(C.GL_RENDERER)
    assert ctx.driver == "llvmpipe"
    assert ctx.config["red"] == ctx.config["green"] == ctx.config["blue"] == 8
    assert (ctx.config["alpha"], ctx.config["depth"], ctx.config["stencil"]) == (8, 24, 8)
    assert gl.GL_TRIANGLES == C.GL_TRIANGLES  # constants ride along on ctx.gl
    assert gl.glGetError() == C.GL_NO_ERROR


def test_every_core_command_is_exposed(ctx):
    assert len(mesa.CORE_COMMANDS) == 145
    missing = [name for name in mesa.CORE_COMMANDS if not hasattr(ctx.gl, name)]
    assert missing == []
    # Extensions Mesa advertises for ES 1 come along too.
    if "GL_OES_draw_texture" in ctx.extensions:
        assert hasattr(ctx.gl, "glDrawTexiOES")
    if "GL_OES_matrix_palette" not in ctx.extensions:
        assert not hasattr(ctx.gl, "glMatrixIndexPointerOES")


def test_clear_and_read_back(ctx):
    gl = ctx.gl
    gl.glClearColorx(65536, 0, 65536, 65536)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    px = read_rgba(gl, 32, 32)
    assert px.shape == (32, 32, 4) and px.dtype == np.uint8
    assert (px == [255, 0, 255, 255]).all()
    # 0.2 * 255 = 51 exactly: no rounding question.
    gl.glClearColor(0.0, 0.2, 1.0, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    assert (read_rgba(gl, 32, 32) == [0, 51, 255, 255]).all()


def test_flat_triangle_covers_known_pixels(ctx):
    gl = ctx.gl
    ortho(gl, 32, 32)
    gl.glClearColorx(0, 0, 0, 65536)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, [4, 4, 28, 4, 4, 28])
    gl.glColor4ub(200, 100, 50, 255)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    px = read_rgba(gl, 32, 32)          # px[y, x], bottom row first
    # Inside: centre x+.5 > 4, y+.5 > 4 and x+y+1 < 32.
    for x, y in [(4, 4), (10, 10), (15, 15), (26, 4), (4, 26)]:
        assert list(px[y, x]) == [200, 100, 50, 255], (x, y)
    for x, y in [(3, 10), (10, 3), (16, 16), (31, 31), (27, 4), (4, 27)]:
        assert list(px[y, x]) == [0, 0, 0, 255], (x, y)
    # image() is the same picture, top row first.
    img = ctx.image()
    assert img.shape == (32, 32, 4)
    assert np.array_equal(img, px[::-1])
    assert list(img[31 - 4, 4]) == [200, 100, 50, 255]


def test_viewport_query(ctx):
    gl = ctx.gl
    vp = gl.glGetIntegerv(C.GL_VIEWPORT)
    assert isinstance(vp, np.ndarray) and list(vp) == [0, 0, 32, 32]
    gl.glViewport(2, 3, 20, 10)
    assert list(gl.glGetIntegerv(C.GL_VIEWPORT)) == [2, 3, 20, 10]


def test_getter_shapes(ctx):
    gl = ctx.gl
    assert gl.glGetIntegerv(C.GL_MATRIX_MODE) == C.GL_MODELVIEW
    assert isinstance(gl.glGetIntegerv(C.GL_MATRIX_MODE), int)
    gl.glTranslatef(1.0, 2.0, 3.0)
    m = gl.glGetFloatv(C.GL_MODELVIEW_MATRIX)
    assert m.shape == (4, 4) and list(m[3]) == [1.0, 2.0, 3.0, 1.0]    # column-major, as PyOpenGL
    assert list(gl.glGetFixedv(C.GL_MODELVIEW_MATRIX)[3]) == [65536, 131072,
                                                                  196608, 65536]
    assert list(gl.glGetBooleanv(C.GL_COLOR_WRITEMASK)) == [1, 1, 1, 1]
    assert list(gl.glGetFloatv(C.GL_DEPTH_RANGE)) == [0.0, 1.0]
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.5, 0.25, 1.0, 1.0])
    assert list(gl.glGetLightfv(C.GL_LIGHT0, C.GL_DIFFUSE)) == [0.5, 0.25, 1.0, 1.0]
    assert gl.glGetLightxv(C.GL_LIGHT0, C.GL_SPOT_CUTOFF) == 180 * 65536
    # Plane x = 2 in object space; the modelview moves it by +1 in x, and GL
    # stores it in eye space: x = 3.
    gl.glClipPlanef(C.GL_CLIP_PLANE0, np.array([1, 0, 0, -2], np.float32))
    assert list(gl.glGetClipPlanef(C.GL_CLIP_PLANE0)) == [1.0, 0.0, 0.0, -3.0]
    assert gl.glGetTexEnviv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE) == C.GL_MODULATE
    n = gl.glGetIntegerv(C.GL_NUM_COMPRESSED_TEXTURE_FORMATS)
    formats = gl.glGetIntegerv(C.GL_COMPRESSED_TEXTURE_FORMATS)
    assert np.size(formats) == n


def test_gen_and_delete(ctx):
    gl = ctx.gl
    b = gl.glGenBuffers(1)
    assert type(b) is int and b > 0
    many = gl.glGenBuffers(3)
    assert isinstance(many, np.ndarray) and many.dtype == np.uint32 and many.shape == (3,)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, b)
    assert gl.glIsBuffer(b)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, 0)
    gl.glDeleteBuffers(1, b)
    gl.glDeleteBuffers(3, many)
    assert not gl.glIsBuffer(b)
    t = gl.glGenTextures(2)
    gl.glDeleteTextures(2, [int(t[0]), int(t[1])])
    assert gl.glGetError() == C.GL_NO_ERROR


def test_vbo_sourced_draw(ctx):
    gl = ctx.gl
    ortho(gl, 32, 32)
    gl.glClearColorx(0, 0, 0, 65536)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    vbo, ibo = gl.glGenBuffers(2)
    verts = np.array([8, 8, 24, 8, 24, 24, 8, 24], np.float32)   # square [8,24]^2
    index = np.array([0, 1, 2, 0, 2, 3], np.uint16)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, vbo)
    gl.glBufferData(C.GL_ARRAY_BUFFER, verts.nbytes, verts, C.GL_STATIC_DRAW)
    gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, ibo)
    gl.glBufferData(C.GL_ELEMENT_ARRAY_BUFFER, index.nbytes, index.tobytes(),
                    C.GL_STATIC_DRAW)
    assert gl.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_SIZE) == 32
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, 0)          # offset into the VBO
    gl.glColor4x(0, 65536, 0, 65536)
    gl.glDrawElements(C.GL_TRIANGLES, 6, C.GL_UNSIGNED_SHORT, 0)
    assert gl.glGetError() == C.GL_NO_ERROR
    px = read_rgba(gl, 32, 32)
    for x, y in [(8, 8), (23, 23), (8, 23), (23, 8), (16, 16)]:
        assert list(px[y, x]) == [0, 255, 0, 255], (x, y)
    for x, y in [(7, 8), (8, 7), (24, 16), (16, 24)]:
        assert list(px[y, x]) == [0, 0, 0, 255], (x, y)


def test_client_array_is_kept_alive(ctx):
    gl = ctx.gl
    ortho(gl, 32, 32)
    gl.glClearColorx(0, 0, 0, 65536)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    # Temporaries: only the wrapper holds them after these calls.
    gl.glVertexPointer(2, C.GL_SHORT, 0, [0, 0, 32, 0, 0, 32, 32, 32])
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, bytes([0, 0, 255, 255] * 4))
    # A call GL rejects (size 7) must not release the array still in use.
    gl.glVertexPointer(7, C.GL_SHORT, 0, [1, 2, 3])
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gc.collect()
    junk = [np.full(8, 99, np.int16) for _ in range(1000)]  # reuse freed memory
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    del junk
    assert (read_rgba(gl, 32, 32) == [0, 0, 255, 255]).all()


def test_texcoord_arrays_kept_per_unit(ctx):
    gl = ctx.gl
    a0 = np.zeros(8, np.float32)
    a1 = np.ones(8, np.float32)
    gl.glClientActiveTexture(C.GL_TEXTURE0)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, a0)
    gl.glClientActiveTexture(C.GL_TEXTURE1)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, a1)
    assert gl.glGetPointerv(C.GL_TEXTURE_COORD_ARRAY_POINTER) == a1.ctypes.data
    gl.glClientActiveTexture(C.GL_TEXTURE0)
    assert gl.glGetPointerv(C.GL_TEXTURE_COORD_ARRAY_POINTER) == a0.ctypes.data
    kept = [v for v in ctx._keep.values() if v is a0 or v is a1]
    assert len(kept) == 2


def test_textured_quad(ctx):
    gl = ctx.gl
    ortho(gl, 32, 32)
    texels = np.array([[[255, 0, 0, 255], [0, 255, 0, 255]],
                       [[0, 0, 255, 255], [255, 255, 255, 255]]], np.uint8)
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 2, 2, 0, C.GL_RGBA,
                    C.GL_UNSIGNED_BYTE, texels)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, [0, 0, 32, 0, 0, 32, 32, 32])
    gl.glTexCoordPointer(2, C.GL_FIXED, 0, [0, 0, 65536, 0, 0, 65536, 65536, 65536])
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    px = read_rgba(gl, 32, 32)
    # Texel row 0 (t = 0) lands at the bottom of the window.
    assert list(px[4, 4]) == [255, 0, 0, 255]
    assert list(px[4, 28]) == [0, 255, 0, 255]
    assert list(px[28, 4]) == [0, 0, 255, 255]
    assert list(px[28, 28]) == [255, 255, 255, 255]


def test_read_pixels_has_no_padding(ctx):
    gl = ctx.gl
    gl.glClearColor(1.0, 0.2, 0.0, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    rgb = gl.glReadPixels(1, 1, 3, 2, C.GL_RGB, C.GL_UNSIGNED_BYTE)
    assert rgb.shape == (2, 3, 3) and rgb.dtype == np.uint8
    assert (rgb == [255, 51, 0]).all()
    # The application's pack alignment is left as it was.
    assert gl.glGetIntegerv(C.GL_PACK_ALIGNMENT) == 4


def test_misuse_raises_before_gl(ctx):
    gl = ctx.gl
    with pytest.raises(TypeError):
        gl.glClearColorx(0.5, 0, 0, 65536)          # GLfixed takes ints
    with pytest.raises(TypeError):
        gl.glLightxv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.5, 0.5, 0.5, 1.0])
    with pytest.raises(TypeError):
        gl.glLoadMatrixf(np.eye(4))                 # float64, not GLfloat
    with pytest.raises(ValueError):
        gl.glLoadMatrixf([1.0] * 12)                # 16 values needed
    with pytest.raises(ValueError):
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.zeros((4, 4), np.float32)[:, :2])
    with pytest.raises(ValueError):
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGB, 3, 3, 0, C.GL_RGB,
                        C.GL_UNSIGNED_BYTE, bytes(30))   # 4-aligned rows: 33 bytes
    with pytest.raises(ValueError):
        gl.glBufferData(C.GL_ARRAY_BUFFER, 64, bytes(16), C.GL_STATIC_DRAW)
    assert gl.glGetError() == C.GL_NO_ERROR


def test_gl_errors_are_reported(ctx):
    gl = ctx.gl
    gl.glEnable(0xFFFF)
    assert gl.glGetError() == C.GL_INVALID_ENUM
    assert gl.glGetError() == C.GL_NO_ERROR


def test_query_matrix(ctx):
    gl = ctx.gl
    if not hasattr(gl, "glQueryMatrixxOES"):
        pytest.skip("OES_query_matrix not exported")
    gl.glScalef(2.0, 0.5, 1.0)
    mantissa, exponent, status = gl.glQueryMatrixxOES()
    assert status == 0
    values = mantissa.astype(np.float64) / 65536 * np.exp2(exponent)
    assert list(values[[0, 5, 10, 15]]) == [2.0, 0.5, 1.0, 1.0]


def test_closed_context_refuses_calls():
    c = mesa.MesaContext(4, 4)
    gl = c.gl
    c.close()
    c.close()
    with pytest.raises(RuntimeError):
        gl.glClear(C.GL_COLOR_BUFFER_BIT)


def test_rgb565_config():
    with mesa.MesaContext(8, 8, color="rgb565", depth=16, stencil=0) as c:
        assert (c.config["red"], c.config["green"], c.config["blue"],
                c.config["alpha"]) == (5, 6, 5, 0)
        assert c.config["depth"] == 16 and c.config["stencil"] == 0
        gl = c.gl
        gl.glClearColorx(65536, 65536, 0, 65536)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        assert (c.image() == [255, 255, 0, 255]).all()


def test_unknown_driver_is_a_reason_not_an_error():
    reason = mesa.available("nosuchpipe")
    assert isinstance(reason, str) and "\n" not in reason
    with pytest.raises(ValueError):
        mesa.MesaContext(4, 4, driver="nosuchpipe")


def test_missing_library_is_a_reason():
    code = ("from gles import mesa; mesa._EGL_LIB = 'libEGL-not-here.so.1'; "
            "r = mesa.available(); assert r and 'libEGL-not-here' in r, r; print(r)")
    out = run_python(code)
    assert out.returncode == 0, out.stderr


@pytest.mark.parametrize("driver", [
    "llvmpipe", pytest.param("softpipe", marks=needs_softpipe)])
def test_shared_edges_cover_each_pixel_once(driver):
    """Edges through pixel centres: every pixel drawn exactly once (additive)."""
    with mesa.MesaContext(16, 16, driver=driver) as c:
        gl = c.gl
        ortho(gl, 16, 16)
        gl.glClearColorx(0, 0, 0, 0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
        gl.glColor4ub(64, 64, 64, 64)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        m = 8.5  # x = 8.5 and y = 8.5 run through pixel centres, and so do diagonals
        fan = [m, m, 0, 0, 16, 0, m, m, 16, 0, 16, 16,
               m, m, 16, 16, 0, 16, m, m, 0, 16, 0, 0]
        grid = []
        for x0, x1 in ((0, m), (m, 16)):
            for y0, y1 in ((0, m), (m, 16)):
                grid += [x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1]
        for tris in (fan, grid):
            gl.glClear(C.GL_COLOR_BUFFER_BIT)
            gl.glVertexPointer(2, C.GL_FLOAT, 0, tris)
            gl.glDrawArrays(C.GL_TRIANGLES, 0, len(tris) // 2)
            assert (read_rgba(gl, 16, 16) == 64).all()


@needs_softpipe
def test_softpipe_and_llvmpipe_in_one_process():
    with mesa.MesaContext(8, 8, driver="llvmpipe") as lp, \
            mesa.MesaContext(8, 8, driver="softpipe") as sp:
        assert sp.driver == "softpipe" and b"softpipe" in sp.gl.glGetString(C.GL_RENDERER)
        assert sp.gl.glGetString(C.GL_VERSION).startswith(b"OpenGL ES-CM 1.1")
        sp.gl.glClearColorx(0, 65536, 0, 65536)
        sp.gl.glClear(C.GL_COLOR_BUFFER_BIT)
        # lp.gl makes lp current again by itself.
        lp.gl.glClearColorx(65536, 0, 0, 65536)
        lp.gl.glClear(C.GL_COLOR_BUFFER_BIT)
        assert b"llvmpipe" in lp.gl.glGetString(C.GL_RENDERER)
        assert (sp.image() == [0, 255, 0, 255]).all()
        assert (lp.image() == [255, 0, 0, 255]).all()
        gb = sp.gl.glGenBuffers(1)
        assert type(gb) is int
    with mesa.MesaContext(4, 4, driver="softpipe") as a, \
            mesa.MesaContext(4, 4, driver="softpipe") as b:
        assert "softpipe" in a.renderer and "softpipe" in b.renderer


@needs_softpipe
def test_one_display_switches_driver_when_idle():
    # With a single display, a driver change needs every context closed first.
    code = ("from gles import mesa\n"
            "mesa._DISPLAYS[1:] = []\n"
            "with mesa.MesaContext(4, 4, driver='llvmpipe') as c:\n"
            "    assert 'llvmpipe' in c.renderer\n"
            "    try:\n"
            "        mesa.MesaContext(4, 4, driver='softpipe')\n"
            "    except RuntimeError as exc:\n"
            "        assert 'subprocess' in str(exc)\n"
            "    else:\n"
            "        raise AssertionError('second driver on a busy display')\n"
            "with mesa.MesaContext(4, 4, driver='softpipe') as c:\n"
            "    assert c.renderer == 'softpipe', c.renderer\n"
            "    c.gl.glClearColorx(0, 65536, 0, 65536)\n"
            "    c.gl.glClear(c.gl.GL_COLOR_BUFFER_BIT)\n"
            "    assert (c.image() == [0, 255, 0, 255]).all()\n")
    out = run_python(code)
    assert out.returncode == 0, out.stderr


@needs_softpipe
def test_softpipe_in_a_fresh_process():
    code = ("from gles import mesa; from gles import constants as C\n"
            "c = mesa.MesaContext(8, 8, driver='softpipe')\n"
            "gl = c.gl\n"
            "gl.glClearColorx(0, 0, 65536, 65536); gl.glClear(C.GL_COLOR_BUFFER_BIT)\n"
            "assert (c.image() == [0, 0, 255, 255]).all()\n"
            "print(gl.glGetString(C.GL_RENDERER).decode())\n")
    out = run_python(code)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "softpipe"
