"""The Python API: gles.Context, current contexts and the module-level
commands, threads, image()/save(), RGB565 framebuffers and ReadPixels packing,
GetString, the Common-Lite profile and the commands not built yet."""

from __future__ import annotations

import threading

import numpy as np
import pytest
from conftest import decode_png

import gles
from gles import constants as C
from gles import gl
from gles import gl as G

BUILDS = ("fixed", "float", "double")


def in_fresh_thread(fn):
    """Run fn() in a new thread (which has no current context); return its result or raise its error."""
    out: dict = {}

    def run():
        try:
            out["value"] = fn()
        except BaseException as e:
            out["error"] = e

    t = threading.Thread(target=run)
    t.start()
    t.join()
    if "error" in out:
        raise out["error"]
    return out.get("value")


def draw_rect(g, x0, y0, x1, y1, rgba) -> None:
    """Fill window rectangle [x0, x1) x [y0, y1) with a colour, via Ortho over the whole window."""
    vp = g.glGetIntegerv(G.GL_VIEWPORT)
    g.glMatrixMode(G.GL_PROJECTION)
    g.glLoadIdentity()
    g.glOrthox(0, int(vp[2]) << 16, 0, int(vp[3]) << 16, -1 << 16, 1 << 16)
    g.glMatrixMode(G.GL_MODELVIEW)
    g.glLoadIdentity()
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_SHORT, 0, np.array([x0, y0, x1, y0, x0, y1, x1, y1], np.int16))
    g.glColor4ub(*rgba)
    g.glDrawArrays(G.GL_TRIANGLE_STRIP, 0, 4)


# {====================================================================
# construction


def test_context_basics():
    """A new context has the requested size and buffers, and shows its settings."""
    ctx = gles.Context(7, 3, numeric="float", depth=16, stencil=0)
    assert (ctx.width, ctx.height) == (7, 3)
    assert (ctx.profile, ctx.numeric, ctx.color) == ("common", "float", "rgba8888")
    assert ctx.image().shape == (3, 7, 4) and ctx.image().dtype == np.uint8
    assert ctx.depth_buffer().shape == (3, 7)
    assert ctx.stencil_buffer() is None
    g = ctx.gl
    assert g.glGetIntegerv(G.GL_DEPTH_BITS) == 16
    assert g.glGetIntegerv(G.GL_STENCIL_BITS) == 0
    assert [g.glGetIntegerv(p) for p in (G.GL_RED_BITS, G.GL_GREEN_BITS, G.GL_BLUE_BITS, G.GL_ALPHA_BITS)] \
        == [8, 8, 8, 8]
    # §2.10.1: the initial viewport is the window
    assert list(g.glGetIntegerv(G.GL_VIEWPORT)) == [0, 0, 7, 3]
    assert "7x3" in repr(ctx) and "float" in repr(ctx)


@pytest.mark.parametrize("kwargs", [
    dict(width=0, height=4), dict(width=4, height=0), dict(width=-3, height=4),
    dict(width=4097, height=4), dict(width=4, height=5000),
    dict(width=4, height=4, profile="es2"), dict(width=4, height=4, profile="Common"),
    dict(width=4, height=4, numeric="half"), dict(width=4, height=4, color="rgb888"),
    dict(width=4, height=4, depth=8), dict(width=4, height=4, depth=32),
    dict(width=4, height=4, stencil=1), dict(width=4, height=4, stencil=16),
])
def test_context_rejects_bad_arguments(kwargs):
    """Unknown profiles, builds, colour formats, depth/stencil sizes, and sizes
    outside 1..4096 are ValueErrors."""
    with pytest.raises(ValueError):
        gles.Context(**kwargs)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("profile", ["common", "common-lite"])
@pytest.mark.parametrize("color", ["rgba8888", "rgb565", "rgba4444", "rgba5551"])
def test_every_combination_constructs(numeric, profile, color):
    """Every profile x build x colour format makes a working context; the largest size too."""
    ctx = gles.Context(3, 2, numeric=numeric, profile=profile, color=color, depth=0, stencil=0)
    assert ctx.gl.glGetError() == G.GL_NO_ERROR
    assert numeric.encode() in ctx.gl.glGetString(G.GL_RENDERER)


def test_largest_context():
    """4096 is an accepted width and height."""
    ctx = gles.Context(4096, 1, depth=0, stencil=0)
    assert ctx.image().shape == (1, 4096, 4)


# {====================================================================
# current contexts and the module-level commands


def test_module_functions_use_the_current_context():
    """After make_current, `from gles import gl` functions act on that context."""

    def body():
        ctx = gles.Context(4, 4)
        assert ctx.make_current() is ctx
        gl.glClearColorx(0, 0x10000, 0, 0x10000)
        gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        px = gl.glReadPixels(0, 0, 4, 4, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE)
        assert px.shape == (4, 4, 4)
        assert (px == [0, 255, 0, 255]).all()
        assert (ctx.image() == [0, 255, 0, 255]).all()
        gl.glViewport(1, 1, 2, 2)
        assert list(ctx.gl.glGetIntegerv(G.GL_VIEWPORT)) == [1, 1, 2, 2]
        assert gl.current_gl() is ctx.gl
        # switching makes the other context current
        other = gles.Context(2, 2).make_current()
        assert list(gl.glGetIntegerv(gl.GL_VIEWPORT)) == [0, 0, 2, 2]
        assert gl.current_gl() is other.gl

    in_fresh_thread(body)


def test_with_block_makes_current_and_releases():
    """`with ctx:` makes the context current and releases it at the end."""

    def body():
        ctx = gles.Context(2, 2)
        with ctx as c:
            assert c is ctx
            gl.glEnable(gl.GL_DEPTH_TEST)
        assert ctx.gl.glIsEnabled(G.GL_DEPTH_TEST)
        with pytest.raises(RuntimeError):
            gl.glGetError()

    in_fresh_thread(body)


def test_no_current_context():
    """Module-level commands without a current context raise RuntimeError; ctx.gl needs none."""

    def body():
        with pytest.raises(RuntimeError, match="make_current"):
            gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        with pytest.raises(RuntimeError):
            gl.current_gl()
        ctx = gles.Context(3, 3)
        ctx.gl.glClearColorx(0x10000, 0, 0, 0x10000)
        ctx.gl.glClear(G.GL_COLOR_BUFFER_BIT)
        assert (ctx.image() == [255, 0, 0, 255]).all()
        assert ctx.gl.glGetError() == G.GL_NO_ERROR
        return True

    assert in_fresh_thread(body)


def test_current_context_is_per_thread():
    """A context made current in one thread is not current in another."""

    def body():
        ctx = gles.Context(2, 2).make_current()
        with pytest.raises(RuntimeError):
            in_fresh_thread(gl.current_gl)
        with pytest.raises(RuntimeError):
            in_fresh_thread(gl.glGetError)
        assert gl.current_gl() is ctx.gl

    in_fresh_thread(body)


def test_two_contexts_are_independent():
    """State, errors and framebuffers of one context are not seen by another."""
    a, b = gles.Context(8, 8), gles.Context(8, 8)
    ga, gb = a.gl, b.gl
    gb.glClear(G.GL_COLOR_BUFFER_BIT)  # to the initial clear colour, (0, 0, 0, 0)
    ga.glViewport(1, 2, 3, 4)
    ga.glEnable(G.GL_CULL_FACE)
    ga.glMatrixMode(G.GL_PROJECTION)
    ga.glTranslatex(5 << 16, 0, 0)
    ga.glPushMatrix()
    ga.glColor4x(0, 0x8000, 0, 0x10000)
    ga.glEnableClientState(G.GL_COLOR_ARRAY)
    ga.glPixelStorei(G.GL_PACK_ALIGNMENT, 8)
    buf = ga.glGenBuffers(1)
    ga.glBindBuffer(G.GL_ARRAY_BUFFER, buf)
    ga.glClearColorx(0x10000, 0x10000, 0, 0x10000)
    ga.glClear(G.GL_COLOR_BUFFER_BIT)
    ga.glEnable(0x0DE0)  # an error in a only
    assert list(gb.glGetIntegerv(G.GL_VIEWPORT)) == [0, 0, 8, 8]
    assert not gb.glIsEnabled(G.GL_CULL_FACE)
    assert gb.glGetIntegerv(G.GL_MATRIX_MODE) == G.GL_MODELVIEW
    assert gb.glGetIntegerv(G.GL_PROJECTION_STACK_DEPTH) == 1
    np.testing.assert_array_equal(gb.glGetFloatv(G.GL_PROJECTION_MATRIX), np.eye(4))
    np.testing.assert_array_equal(gb.glGetFloatv(G.GL_CURRENT_COLOR), [1, 1, 1, 1])
    assert not gb.glIsEnabled(G.GL_COLOR_ARRAY)
    assert gb.glGetIntegerv(G.GL_PACK_ALIGNMENT) == 4
    assert gb.glGetIntegerv(G.GL_ARRAY_BUFFER_BINDING) == 0
    assert not gb.glIsBuffer(buf)
    assert not b.image().any()
    assert gb.glGetError() == G.GL_NO_ERROR
    assert ga.glGetError() == G.GL_INVALID_ENUM
    assert (a.image() == [255, 255, 0, 255]).all()


@pytest.mark.parametrize("numerics", [("fixed", "double"), ("fixed", "fixed", "float")])
def test_threads_render_at_the_same_time(numerics):
    """Two or three threads, each with its own current context (of different or the same
    numeric build), draw hundreds of times at once through the module-level commands;
    each gets exactly its own image."""
    n_draws = 300
    n = len(numerics)
    width = 16 * n
    barrier = threading.Barrier(n)
    results: dict = {}

    def colour(k: int, i: int) -> list[int]:
        c = (i * 7 + k * 100) % 256
        return [c, k * 120, 255 - c, 255]

    def worker(k: int, numeric: str) -> None:
        try:
            ctx = gles.Context(width, 32, numeric=numeric, depth=0, stencil=0)
            ctx.make_current()
            # each thread draws into its own column through its own viewport:
            # state leaking between contexts would show in the other columns
            gl.glViewport(k * 16, 0, 16, 32)
            gl.glMatrixMode(gl.GL_PROJECTION)
            gl.glOrthox(0, 16 << 16, 0, 32 << 16, -1 << 16, 1 << 16)
            gl.glMatrixMode(gl.GL_MODELVIEW)
            gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
            quad = np.array([0, 0, 16, 0, 0, 32, 16, 32], np.int16)
            gl.glVertexPointer(2, gl.GL_SHORT, 0, quad)
            gl.glClear(gl.GL_COLOR_BUFFER_BIT)  # the initial clear colour is (0, 0, 0, 0)
            barrier.wait()
            for i in range(n_draws):
                gl.glColor4ub(*colour(k, i))
                gl.glDrawArrays(gl.GL_TRIANGLE_STRIP, 0, 4)
                if i % 50 == 49:
                    img = gl.glReadPixels(0, 0, width, 32, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE)
                    mine = img[:, k * 16:(k + 1) * 16]
                    assert (mine == colour(k, i)).all(), (k, i)
                    img[:, k * 16:(k + 1) * 16] = 0
                    assert not img.any(), (k, i)
            results[k] = ctx.image()
        except BaseException as e:
            results[k] = e

    threads = [threading.Thread(target=worker, args=(k, numeric)) for k, numeric in enumerate(numerics)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(60)
    for k in range(n):
        if isinstance(results.get(k), BaseException):
            raise results[k]
        img = results[k]
        assert (img[:, k * 16:(k + 1) * 16] == colour(k, n_draws - 1)).all()
        img[:, k * 16:(k + 1) * 16] = 0
        assert not img.any()


# {====================================================================
# image() and save()


def test_image_is_top_row_first():
    """image() is top row first; glReadPixels and color_buffer() are bottom row first."""
    ctx = gles.Context(8, 6, depth=0, stencil=0)
    g = ctx.gl
    g.glClear(G.GL_COLOR_BUFFER_BIT)
    draw_rect(g, 0, 0, 4, 3, (10, 20, 30, 40))  # the bottom-left quadrant
    img = ctx.image()
    assert tuple(img[-1, 0]) == (10, 20, 30, 40)
    assert tuple(img[0, 0]) == (0, 0, 0, 0)
    assert (img[3:, :4] == [10, 20, 30, 40]).all()
    assert not img[:3].any() and not img[:, 4:].any()
    px = g.glReadPixels(0, 0, 8, 6, G.GL_RGBA, G.GL_UNSIGNED_BYTE)
    assert tuple(px[0, 0]) == (10, 20, 30, 40)
    np.testing.assert_array_equal(px[::-1], img)
    np.testing.assert_array_equal(ctx.color_buffer(), px)


def _picture() -> gles.Context:
    ctx = gles.Context(5, 4, depth=0, stencil=0)
    g = ctx.gl
    draw_rect(g, 0, 0, 2, 2, (255, 0, 0, 255))
    draw_rect(g, 2, 1, 5, 4, (0, 128, 255, 77))
    draw_rect(g, 0, 3, 1, 4, (1, 2, 3, 4))
    return ctx


def test_save_writes_a_png_of_the_image(tmp_path):
    """save() writes a PNG that decodes (zlib, by hand) to exactly image()."""
    ctx = _picture()
    path = tmp_path / "out.png"
    ctx.save(path)
    img = decode_png(path.read_bytes())
    assert img.shape == (4, 5, 4)
    np.testing.assert_array_equal(img, ctx.image())
    assert tuple(img[0, 0]) == (1, 2, 3, 4)  # top-left in the file is the top-left of the window
    ctx.save(str(tmp_path / "again.png"))  # a str path works too
    np.testing.assert_array_equal(decode_png((tmp_path / "again.png").read_bytes()), ctx.image())


def test_save_decodes_with_pillow(tmp_path):
    """Pillow reads the saved PNG as the same RGBA pixels."""
    image_mod = pytest.importorskip("PIL.Image")
    ctx = _picture()
    ctx.save(tmp_path / "out.png")
    with image_mod.open(tmp_path / "out.png") as im:
        assert im.mode == "RGBA"
        np.testing.assert_array_equal(np.asarray(im), ctx.image())


# {====================================================================
# RGB565

# raw 565 values chosen by hand: each channel at its extremes and in between
RAW565 = [(31, 63, 31), (0, 0, 0), (16, 32, 1), (1, 62, 30), (30, 1, 15), (7, 40, 23)]


def _fill565(ctx: gles.Context) -> np.ndarray:
    """Clear one column per RAW565 entry (scissored ClearColor k / (2^bits - 1));
    return the raw values expected."""
    g = ctx.gl
    g.glEnable(G.GL_SCISSOR_TEST)
    want = np.zeros((ctx.height, ctx.width), np.uint16)
    for x in range(ctx.width):
        r, gg, b = RAW565[x % len(RAW565)]
        g.glScissor(x, 0, 1, ctx.height)
        g.glClearColor(r / 31, gg / 63, b / 31, 0.5)
        g.glClear(G.GL_COLOR_BUFFER_BIT)
        want[:, x] = (r << 11) | (gg << 5) | b
    g.glDisable(G.GL_SCISSOR_TEST)
    return want


@pytest.mark.parametrize("numeric", BUILDS)
def test_rgb565_read_and_image(numeric):
    """An RGB565 context stores 5/6/5 bits; ReadPixels(RGB, UNSIGNED_SHORT_5_6_5) returns
    the raw values; RGBA/UNSIGNED_BYTE and image() expand each channel to round(c * 255 / max)
    with alpha 255 (§4.3.1)."""
    ctx = gles.Context(6, 3, numeric=numeric, color="rgb565", depth=0, stencil=0)
    g = ctx.gl
    assert [g.glGetIntegerv(p) for p in (G.GL_RED_BITS, G.GL_GREEN_BITS, G.GL_BLUE_BITS, G.GL_ALPHA_BITS)] \
        == [5, 6, 5, 0]
    want = _fill565(ctx)
    raw = g.glReadPixels(0, 0, 6, 3, G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5)
    assert raw.dtype == np.uint16 and raw.shape == (3, 6)
    np.testing.assert_array_equal(raw, want)
    np.testing.assert_array_equal(ctx.color_buffer(), want)
    expanded = np.zeros((3, 6, 4), np.uint8)
    for x in range(6):
        r, gg, b = RAW565[x]
        expanded[:, x] = (round(r * 255 / 31), round(gg * 255 / 63), round(b * 255 / 31), 255)
    assert tuple(expanded[0, 0]) == (255, 255, 255, 255) and tuple(expanded[0, 2]) == (132, 130, 8, 255)
    np.testing.assert_array_equal(g.glReadPixels(0, 0, 6, 3, G.GL_RGBA, G.GL_UNSIGNED_BYTE), expanded)
    np.testing.assert_array_equal(ctx.image(), expanded[::-1])
    assert g.glGetError() == G.GL_NO_ERROR


@pytest.mark.parametrize("color, fmt, typ", [("rgb565", G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5),
                                             ("rgba8888", G.GL_BGRA_EXT, G.GL_UNSIGNED_BYTE)])
def test_implementation_read_format(color, fmt, typ):
    """IMPLEMENTATION_COLOR_READ_FORMAT/TYPE_OES name a pair ReadPixels accepts (OES_read_format)."""
    ctx = gles.Context(2, 2, color=color)
    g = ctx.gl
    assert g.glGetIntegerv(G.GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES) == fmt
    assert g.glGetIntegerv(G.GL_IMPLEMENTATION_COLOR_READ_TYPE_OES) == typ
    assert g.glReadPixels(0, 0, 2, 2, fmt, typ) is not None
    # RGBA/UNSIGNED_BYTE is always accepted
    assert g.glReadPixels(0, 0, 2, 2, G.GL_RGBA, G.GL_UNSIGNED_BYTE).shape == (2, 2, 4)
    assert g.glGetError() == G.GL_NO_ERROR
    assert b"GL_OES_read_format" in g.glGetString(G.GL_EXTENSIONS).split()
    assert b"GL_EXT_read_format_bgra" in g.glGetString(G.GL_EXTENSIONS).split()


@pytest.mark.parametrize("align, stride", [(1, 6), (2, 6), (4, 8), (8, 8)])
def test_read_pixels_pack_alignment_565(align, stride):
    """ReadPixels into an array= buffer starts row j at j * stride, the 6-byte rows of a
    3-pixel 565 read rounded up to PACK_ALIGNMENT (§3.6.2 / §4.3.1); bytes past the last
    row are not written."""
    ctx = gles.Context(3, 2, color="rgb565", depth=0, stencil=0)
    g = ctx.gl
    want = _fill565(ctx)
    g.glPixelStorei(G.GL_PACK_ALIGNMENT, align)
    assert g.glGetIntegerv(G.GL_PACK_ALIGNMENT) == align
    need = stride * 1 + 6
    buf = bytearray(b"\xee" * (need + 5))
    assert g.glReadPixels(0, 0, 3, 2, G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5, array=buf) is None
    for j in range(2):
        row = np.frombuffer(bytes(buf[j * stride:j * stride + 6]), np.uint16)
        np.testing.assert_array_equal(row, want[j])
    assert buf[need:] == b"\xee" * 5
    # the returned-array form hides the padding
    np.testing.assert_array_equal(g.glReadPixels(0, 0, 3, 2, G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5), want)
    # exactly `need` bytes are enough; one fewer is a ValueError and nothing is written
    g.glReadPixels(0, 0, 3, 2, G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5, array=bytearray(need))
    short = bytearray(b"\x11" * (need - 1))
    with pytest.raises(ValueError):
        g.glReadPixels(0, 0, 3, 2, G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5, array=short)
    assert short == b"\x11" * (need - 1)
    assert g.glGetError() == G.GL_NO_ERROR


@pytest.mark.parametrize("align, stride", [(1, 12), (4, 12), (8, 16)])
def test_read_pixels_pack_alignment_rgba(align, stride):
    """The same for RGBA/UNSIGNED_BYTE: 3 pixels are 12 bytes, 16 with alignment 8."""
    ctx = gles.Context(3, 3, depth=0, stencil=0)
    g = ctx.gl
    draw_rect(g, 0, 0, 3, 1, (1, 2, 3, 4))
    draw_rect(g, 0, 1, 3, 2, (5, 6, 7, 8))
    draw_rect(g, 0, 2, 3, 3, (9, 10, 11, 12))
    g.glPixelStorei(G.GL_PACK_ALIGNMENT, align)
    buf = np.full(stride * 2 + 12, 0xEE, np.uint8)
    g.glReadPixels(0, 0, 3, 3, G.GL_RGBA, G.GL_UNSIGNED_BYTE, array=buf)
    for j in range(3):
        np.testing.assert_array_equal(buf[j * stride:j * stride + 12].reshape(3, 4),
                                      [[4 * j + 1, 4 * j + 2, 4 * j + 3, 4 * j + 4]] * 3)


def test_read_pixels_partly_outside_the_window():
    """A rectangle reaching outside the window reads the inside pixels correctly, without
    error, for both read formats; the outside ones are undefined (§4.3.1), so the array
    returned holds only the inside part."""
    ctx = gles.Context(4, 3, depth=0, stencil=0)
    g = ctx.gl
    draw_rect(g, 0, 0, 4, 3, (9, 8, 7, 6))
    draw_rect(g, 1, 1, 2, 2, (200, 100, 50, 25))
    full = g.glReadPixels(0, 0, 4, 3, G.GL_RGBA, G.GL_UNSIGNED_BYTE)
    px = g.glReadPixels(-2, -1, 5, 6, G.GL_RGBA, G.GL_UNSIGNED_BYTE)
    assert px.shape == (3, 3, 4)        # columns 0..2 (x + width = 3), rows 0..2 (the window's)
    np.testing.assert_array_equal(px, full[0:3, 0:3])
    corner = g.glReadPixels(3, 2, 4, 4, G.GL_RGBA, G.GL_UNSIGNED_BYTE)
    assert corner.shape == (1, 1, 4)
    np.testing.assert_array_equal(corner[0, 0], full[2, 3])
    far = g.glReadPixels(100, 100, 2, 2, G.GL_RGBA, G.GL_UNSIGNED_BYTE)
    assert far.shape == (0, 0, 4)
    c565 = gles.Context(3, 3, color="rgb565", depth=0, stencil=0)
    want = _fill565(c565)
    px565 = c565.gl.glReadPixels(-1, 1, 5, 3, G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5)
    assert px565.shape == (2, 3)
    np.testing.assert_array_equal(px565, want[1:3, :])
    assert g.glGetError() == c565.gl.glGetError() == G.GL_NO_ERROR


# {====================================================================
# GetString and profiles


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("profile, version", [("common", "OpenGL ES-CM 1.1"),
                                              ("common-lite", "OpenGL ES-CL 1.1")])
def test_get_string(numeric, profile, version):
    """VERSION names the profile (§6.1.5), RENDERER the numeric build; VENDOR is set."""
    g = gles.Context(2, 2, numeric=numeric, profile=profile).gl
    assert g.glGetString(G.GL_VERSION) == version.encode()
    assert numeric.encode() in g.glGetString(G.GL_RENDERER)
    assert g.glGetString(G.GL_VENDOR)
    ext = g.glGetString(G.GL_EXTENSIONS).decode().split()
    assert all(" " not in e and e.startswith("GL_") for e in ext)
    # OES_single_precision is the Common profile's float commands
    assert ("GL_OES_single_precision" in ext) == (profile == "common")
    assert g.glGetError() == G.GL_NO_ERROR
    assert g.glGetString(0x1234) is None
    assert g.glGetError() == G.GL_INVALID_ENUM


# the 39 Common-only commands (Appendix C)
FLOAT_ONLY = """AlphaFunc ClearColor ClearDepthf ClipPlanef Color4f DepthRangef Fogf Fogfv Frustumf
GetClipPlanef GetFloatv GetLightfv GetMaterialfv GetTexEnvfv GetTexParameterfv LightModelf LightModelfv
Lightf Lightfv LineWidth LoadMatrixf Materialf Materialfv MultMatrixf MultiTexCoord4f Normal3f Orthof
PointParameterf PointParameterfv PointSize PolygonOffset Rotatef SampleCoverage Scalef TexEnvf TexEnvfv
TexParameterf TexParameterfv Translatef""".split()


def fixed_form(name: str) -> str:
    """The Common-Lite counterpart of a float command (OES_fixed_point naming)."""
    if name == "GetFloatv":
        return "GetFixedv"
    if name.endswith("fv"):
        return name[:-2] + "xv"
    if name.endswith("f"):
        return name[:-1] + "x"
    return name + "x"


def test_common_lite_has_no_float_commands():
    """A Common-Lite context's commands lack every float command of Appendix C but have
    each one's fixed form; a Common context has both."""
    assert len(FLOAT_ONLY) == 39
    lite = gles.Context(2, 2, profile="common-lite").gl
    common = gles.Context(2, 2).gl
    for name in FLOAT_ONLY:
        assert hasattr(common, "gl" + name), name
        assert not hasattr(lite, "gl" + name), name
        assert hasattr(lite, "gl" + fixed_form(name)), name
        assert hasattr(common, "gl" + fixed_form(name)), name
    with pytest.raises(AttributeError):
        lite.glClearColor(0, 0, 0, 1)
    lite.glClearColorx(0, 0, 0, 0x10000)
    assert lite.glGetError() == G.GL_NO_ERROR
    # the core's float commands are exactly Appendix C's; extension float
    # commands (glDrawTexfOES) are Common-only too
    core = {n for n in gl.FLOAT_COMMANDS if not n.endswith("OES")}
    assert core == {"gl" + n for n in FLOAT_ONLY}
    assert {n for n in gl.FLOAT_COMMANDS if n.endswith("OES")} == {
        "glDrawTexfOES", "glDrawTexfvOES", "glTexGenfOES", "glTexGenfvOES", "glGetTexGenfvOES"}


def test_module_forwarder_on_common_lite():
    """A module-level float command with a Common-Lite context current raises an
    AttributeError that says why."""

    def body():
        gles.Context(2, 2, profile="common-lite").make_current()
        with pytest.raises(AttributeError, match="Common-Lite"):
            gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        with pytest.raises(AttributeError, match="Common-Lite"):
            gl.glTranslatef(1.0, 0.0, 0.0)
        gl.glTranslatex(1 << 16, 0, 0)
        assert gl.glGetError() == gl.GL_NO_ERROR

    in_fresh_thread(body)


@pytest.mark.parametrize("cmd, args", [
    ("glVertexPointer", (2, G.GL_FLOAT, 0, np.zeros(6, np.float32))),
    ("glColorPointer", (4, G.GL_FLOAT, 0, np.zeros(12, np.float32))),
    ("glNormalPointer", (G.GL_FLOAT, 0, np.zeros(9, np.float32))),
    ("glTexCoordPointer", (2, G.GL_FLOAT, 0, np.zeros(6, np.float32))),
    ("glPointSizePointerOES", (G.GL_FLOAT, 0, np.zeros(3, np.float32))),
])
def test_common_lite_rejects_float_arrays(cmd, args):
    """Common-Lite has no FLOAT arrays: INVALID_ENUM, the array state unchanged (Appendix C, §2.5)."""
    g = gles.Context(2, 2, profile="common-lite").gl
    type_pname = {"glVertexPointer": G.GL_VERTEX_ARRAY_TYPE,
                  "glColorPointer": G.GL_COLOR_ARRAY_TYPE,
                  "glNormalPointer": G.GL_NORMAL_ARRAY_TYPE,
                  "glTexCoordPointer": G.GL_TEXTURE_COORD_ARRAY_TYPE,
                  "glPointSizePointerOES": G.GL_POINT_SIZE_ARRAY_TYPE_OES}[cmd]
    fixed_args = tuple(G.GL_FIXED if a is G.GL_FLOAT else a for a in args[:-1]) + (None,)
    getattr(g, cmd)(*fixed_args)
    assert g.glGetError() == G.GL_NO_ERROR
    getattr(g, cmd)(*args)
    assert g.glGetError() == G.GL_INVALID_ENUM
    assert g.glGetIntegerv(type_pname) == G.GL_FIXED
    # the Common profile takes the same call
    c = gles.Context(2, 2).gl
    getattr(c, cmd)(*args)
    assert c.glGetError() == G.GL_NO_ERROR
    assert c.glGetIntegerv(type_pname) == G.GL_FLOAT


@pytest.mark.parametrize("pname", [G.GL_VERTEX_ARRAY_TYPE, G.GL_NORMAL_ARRAY_TYPE, G.GL_COLOR_ARRAY_TYPE,
                                   G.GL_TEXTURE_COORD_ARRAY_TYPE, G.GL_POINT_SIZE_ARRAY_TYPE_OES])
@pytest.mark.parametrize("profile, want", [("common", G.GL_FLOAT), ("common-lite", G.GL_FIXED)])
def test_initial_array_types_per_profile(pname, profile, want):
    """§2.8: "The array types are each FLOAT for the Common profile and FIXED for the
    Common-Lite profile" (a Common-Lite context must never report a type it rejects)."""
    g = gles.Context(2, 2, profile=profile).gl
    assert g.glGetIntegerv(pname) == want


def test_common_lite_renders_with_fixed_commands():
    """A Common-Lite context draws with FIXED arrays and x commands."""
    ctx = gles.Context(8, 8, profile="common-lite", depth=0, stencil=0)
    g = ctx.gl
    g.glMatrixMode(G.GL_PROJECTION)
    g.glOrthox(0, 8 << 16, 0, 8 << 16, -1 << 16, 1 << 16)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FIXED, 0, np.array([0, 0, 8, 0, 0, 8, 8, 8], np.int32) << 16)
    g.glColor4x(0x10000, 0, 0x10000, 0x10000)
    g.glDrawArrays(G.GL_TRIANGLE_STRIP, 0, 4)
    assert (ctx.image() == [255, 0, 255, 255]).all()
    np.testing.assert_array_equal(g.glGetFixedv(G.GL_CURRENT_COLOR), [0x10000, 0, 0x10000, 0x10000])


# {====================================================================
# commands whose stage is not built yet


FLOAT_ONLY_NAMES = {"gl" + n for n in FLOAT_ONLY}


@pytest.mark.parametrize("name", sorted(gl.MISSING))
def test_missing_commands_raise_not_implemented(name):
    """Every command listed in gles.gl.MISSING raises NotImplementedError naming its stage,
    on both profiles (float commands exist on Common only) and records no GL error."""
    ctx = gles.Context(2, 2)
    with pytest.raises(NotImplementedError, match=gl.MISSING[name]):
        getattr(ctx.gl, name)(0, 0, 0)
    assert ctx.gl.glGetError() == G.GL_NO_ERROR
    lite = gles.Context(2, 2, profile="common-lite").gl
    if name in FLOAT_ONLY_NAMES:
        assert not hasattr(lite, name)
    else:
        with pytest.raises(NotImplementedError):
            getattr(lite, name)()


def test_missing_commands_are_es_commands():
    """MISSING lists only ES 1.1 command names the module also exposes at module level."""
    for name in gl.MISSING:
        assert name in gl.COMMON_COMMANDS
        assert callable(getattr(gl, name))
        assert (name in gl.COMMON_LITE_COMMANDS) == (name not in FLOAT_ONLY_NAMES)


@pytest.mark.parametrize("numeric", ["fixed", "double"])
def test_parameter_vectors_read_alike(numeric):
    """A list or tuple of Python floats (read without an array), a float32
    array, a list of ints and a list mixing in a numpy scalar set the same
    material, light and fog values; a short list or a non-number still
    raises, naming the command."""
    ctx = gles.Context(8, 8, numeric=numeric, range_check="off")
    gl = ctx.gl
    want = [0.25, 0.5, 0.75, 1.0]
    forms = [want, tuple(want), np.array(want, np.float32), [0.25, 0.5, 0.75, 1],
             [0.25, np.float64(0.5), 0.75, 1.0], want + [9.0]]
    for form in forms:
        gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [0.0, 0.0, 0.0, 0.0])
        gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, form)
        assert np.allclose(gl.glGetMaterialfv(C.GL_FRONT, C.GL_AMBIENT), want, atol=2**-16), form
        gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, form)
        assert np.allclose(gl.glGetLightfv(C.GL_LIGHT1, C.GL_DIFFUSE), want, atol=2**-16), form
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SHININESS, [7.5])
    assert np.allclose(gl.glGetMaterialfv(C.GL_FRONT, C.GL_SHININESS), [7.5])
    with pytest.raises(ValueError, match="glMaterialfv"):
        gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [0.5, 0.5, 0.5])
    with pytest.raises((TypeError, ValueError), match="glMaterialfv"):
        gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [0.5, 0.5, "x", 0.5])
    assert np.allclose(gl.glGetMaterialfv(C.GL_FRONT, C.GL_AMBIENT), want, atol=2**-16)
    assert gl.glGetError() == C.GL_NO_ERROR


@pytest.mark.parametrize("numeric", ["fixed", "float"])
def test_texture_parameters_read_alike(numeric):
    """Texture parameters given as Python ints, GL_* constants, floats,
    tuples and numpy arrays (a list of plain numbers is read without an
    array) set the same state; an int past 32 bits still raises."""
    def crop_rect(gl):
        return np.ravel(gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES)).tolist()

    ctx = gles.Context(8, 8, numeric=numeric, range_check="off")
    gl = ctx.gl
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    for crop in ([1, 2, 3, 4], (1, 2, 3, 4), np.array([1, 2, 3, 4], np.int32), [1, 2, 3, 4, 99]):
        gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, [0, 0, 0, 0])
        gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, crop)
        assert crop_rect(gl) == [1, 2, 3, 4]
    for mode in (C.GL_REPLACE, int(C.GL_REPLACE), np.int32(C.GL_REPLACE)):
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, mode)
        assert np.ravel(gl.glGetTexEnviv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE)).tolist() == [C.GL_REPLACE]
    if numeric == "float":
        for colour in ([0.25, 0.5, 0.75, 1.0], [0.25, 0.5, 0.75, 1], (0.25, 0.5, 0.75, True)):
            gl.glTexEnvfv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, colour)
            got = gl.glGetTexEnvfv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR)
            assert np.allclose(got, [0.25, 0.5, 0.75, 1.0])
        gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
        filt = gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER)
        assert np.ravel(filt).tolist() == [C.GL_NEAREST]
    with pytest.raises(ValueError, match="glTexParameteriv"):
        gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, [1, 2, 3, 2**40])
    assert crop_rect(gl) == [1, 2, 3, 4]
    assert gl.glGetError() == C.GL_NO_ERROR
