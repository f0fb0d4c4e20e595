"""OES_framebuffer_object (with OES_rgb8_rgba8, OES_depth24, OES_stencil8,
OES_packed_depth_stencil, OES_fbo_render_mipmap): render to textures and
renderbuffers. Expected images come from the same scene drawn into a window
of the same format (an object's buffers are drawn exactly as a window's),
from Mesa, and from hand-worked completeness rules (EXT_framebuffer_object
§4.4.4 as OES_framebuffer_object restricts it)."""

from __future__ import annotations

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import mesa

_MESA = mesa.available()
needs_mesa = pytest.mark.skipif(_MESA is not None, reason=f"Mesa peer unavailable: {_MESA}")

FB, RB = C.GL_FRAMEBUFFER_OES, C.GL_RENDERBUFFER_OES
COLOR, DEPTH, STENCIL = C.GL_COLOR_ATTACHMENT0_OES, C.GL_DEPTH_ATTACHMENT_OES, C.GL_STENCIL_ATTACHMENT_OES


def _texture(gl, w: int, h: int, fmt: int = C.GL_RGBA, data=None) -> int:
    t = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, t)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, w, h, 0, fmt, C.GL_UNSIGNED_BYTE, data)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    return t


def _renderbuffer(gl, fmt: int, w: int, h: int) -> int:
    r = int(gl.glGenRenderbuffersOES(1))
    gl.glBindRenderbufferOES(RB, r)
    gl.glRenderbufferStorageOES(RB, fmt, w, h)
    return r


def _framebuffer(gl) -> int:
    f = int(gl.glGenFramebuffersOES(1))
    gl.glBindFramebufferOES(FB, f)
    return f


def _read(gl, w: int, h: int) -> np.ndarray:
    return np.asarray(gl.glReadPixels(0, 0, w, h, C.GL_RGBA, C.GL_UNSIGNED_BYTE))


def _depth_stencil_scene(gl, w: int, h: int) -> None:
    """Overlapping smooth triangles with depth test, a stencil mask drawn
    first (a quarter of the target), blending where the stencil passes."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0, w, 0, h, -1, 1)
    gl.glClearColor(0.1, 0.2, 0.3, 1.0)
    gl.glClearStencil(0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    # the stencil mask
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(C.GL_ALWAYS, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_REPLACE)
    gl.glColorMask(0, 0, 0, 0)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([0, 0, w / 2, 0, 0, h / 2, w / 2, h / 2], np.float32))
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    gl.glColorMask(1, 1, 1, 1)
    gl.glStencilFunc(C.GL_NOTEQUAL, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
    # two triangles at different depths
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    tris = np.array([[2, 2, 0.5], [w - 3, 5, 0.5], [w / 2, h - 2, -0.5],
                     [3, h - 4, -0.8], [w - 2, h / 2, 0.9], [5, 3, 0.9]], np.float32)
    cols = np.array([[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255],
                     [255, 255, 0, 200], [0, 255, 255, 120], [255, 0, 255, 60]], np.uint8)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, tris)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 6)
    for cap in (C.GL_BLEND, C.GL_DEPTH_TEST, C.GL_STENCIL_TEST):
        gl.glDisable(cap)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)


@pytest.mark.parametrize("numeric", ["fixed", "float"])
@pytest.mark.parametrize("color, depth, stencil", [
    (C.GL_RGBA8_OES, C.GL_DEPTH_COMPONENT24_OES, C.GL_STENCIL_INDEX8_OES),
    (C.GL_RGB565_OES, C.GL_DEPTH_COMPONENT16_OES, C.GL_STENCIL_INDEX8_OES),
    (C.GL_RGBA4_OES, C.GL_DEPTH_COMPONENT16_OES, C.GL_STENCIL_INDEX8_OES),
    (C.GL_RGB5_A1_OES, C.GL_DEPTH24_STENCIL8_OES, C.GL_DEPTH24_STENCIL8_OES),
    (C.GL_RGBA8_OES, C.GL_DEPTH24_STENCIL8_OES, C.GL_DEPTH24_STENCIL8_OES),
])
def test_renderbuffers_draw_as_a_window_does(numeric: str, color: int, depth: int, stencil: int) -> None:
    w, h = 40, 24
    window_format = {C.GL_RGB565_OES: "rgb565", C.GL_RGBA4_OES: "rgba4444",
                     C.GL_RGB5_A1_OES: "rgba5551"}.get(color, "rgba8888")
    depth_bits = 16 if depth == C.GL_DEPTH_COMPONENT16_OES else 24
    with gles.Context(w, h, numeric=numeric, color=window_format, depth=depth_bits, stencil=8) as win:
        _depth_stencil_scene(win.gl, w, h)
        want = _read(win.gl, w, h)
    with gles.Context(8, 8, numeric=numeric, depth=0, stencil=0) as ctx:
        gl = ctx.gl
        _framebuffer(gl)
        c = _renderbuffer(gl, color, w, h)
        gl.glFramebufferRenderbufferOES(FB, COLOR, RB, c)
        z = _renderbuffer(gl, depth, w, h)
        gl.glFramebufferRenderbufferOES(FB, DEPTH, RB, z)
        s = z if stencil == depth else _renderbuffer(gl, stencil, w, h)
        gl.glFramebufferRenderbufferOES(FB, STENCIL, RB, s)
        assert gl.glCheckFramebufferStatusOES(FB) == C.GL_FRAMEBUFFER_COMPLETE_OES
        assert gl.glGetIntegerv(C.GL_DEPTH_BITS) == depth_bits
        assert gl.glGetIntegerv(C.GL_STENCIL_BITS) == 8
        _depth_stencil_scene(gl, w, h)
        got = _read(gl, w, h)
        assert gl.glGetError() == C.GL_NO_ERROR
        # the window was not drawn into
        assert (np.asarray(ctx.image()) == 0).all()
    np.testing.assert_array_equal(got, want)


def _rtt_scene(make, w: int = 64, h: int = 64) -> np.ndarray:
    """A smooth perspective triangle pair rendered into a 32x32 texture with a
    depth renderbuffer, then that texture on a tilted quad in the window
    (LINEAR, after GenerateMipmapOES, LINEAR_MIPMAP_LINEAR)."""
    with make() as ctx:
        gl = ctx.gl
        tex = _texture(gl, 32, 32)
        _framebuffer(gl)
        gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, tex, 0)
        gl.glFramebufferRenderbufferOES(FB, DEPTH, RB, _renderbuffer(gl, C.GL_DEPTH_COMPONENT16_OES, 32, 32))
        assert gl.glCheckFramebufferStatusOES(FB) == C.GL_FRAMEBUFFER_COMPLETE_OES
        _depth_stencil_scene(gl, 32, 32)
        gl.glBindFramebufferOES(FB, 0)
        gl.glBindTexture(C.GL_TEXTURE_2D, tex)
        gl.glGenerateMipmapOES(C.GL_TEXTURE_2D)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
        gl.glViewport(0, 0, w, h)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glFrustumf(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0)
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glLoadIdentity()
        gl.glTranslatef(0, 0, -2.0)
        gl.glRotatef(-60, 1, 0, 0)
        gl.glClearColor(0, 0, 0, 1)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([-1, -1, 1, -1, -1, 1, 1, 1], np.float32))
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.array([0, 0, 2, 0, 0, 2, 2, 2], np.float32))
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        assert gl.glGetError() == C.GL_NO_ERROR
        return _read(gl, w, h)


def _psnr(a: np.ndarray, b: np.ndarray) -> float:
    mse = np.mean((a[..., :3].astype(np.float64) - b[..., :3].astype(np.float64)) ** 2)
    return float("inf") if mse == 0 else 10 * np.log10(255.0**2 / mse)


def test_render_to_texture_against_double() -> None:
    fixed = _rtt_scene(lambda: gles.Context(64, 64, numeric="fixed"))
    double = _rtt_scene(lambda: gles.Context(64, 64, numeric="double"))
    assert (fixed[..., :3] != 0).any(axis=-1).mean() > 0.3
    assert _psnr(fixed, double) >= 30.0            # test_gallery's MIN_PSNR_FIXED


@needs_mesa
def test_render_to_texture_against_llvmpipe() -> None:
    fixed = _rtt_scene(lambda: gles.Context(64, 64, numeric="fixed"))
    peer = _rtt_scene(lambda: mesa.MesaContext(64, 64))
    assert _psnr(fixed, peer) >= 35.0              # the bar


def test_threads_give_the_same_bytes_into_an_object() -> None:
    def run(threads: int) -> np.ndarray:
        with gles.Context(8, 8, threads=threads) as ctx:
            ctx.debug(64)          # every draw threaded, however small
            gl = ctx.gl
            _framebuffer(gl)
            gl.glFramebufferRenderbufferOES(FB, COLOR, RB, _renderbuffer(gl, C.GL_RGBA8_OES, 96, 80))
            ds = _renderbuffer(gl, C.GL_DEPTH24_STENCIL8_OES, 96, 80)
            gl.glFramebufferRenderbufferOES(FB, DEPTH, RB, ds)
            gl.glFramebufferRenderbufferOES(FB, STENCIL, RB, ds)
            _depth_stencil_scene(gl, 96, 80)
            return _read(gl, 96, 80)
    one = run(1)
    for n in (2, 3):
        np.testing.assert_array_equal(run(n), one)


def test_completeness() -> None:
    gl = gles.Context(8, 8).gl
    _framebuffer(gl)
    status = lambda: gl.glCheckFramebufferStatusOES(FB)  # noqa: E731
    assert status() == C.GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_OES
    # a renderbuffer without storage, a texture without an image, a luminance texture
    empty = int(gl.glGenRenderbuffersOES(1))
    gl.glBindRenderbufferOES(RB, empty)
    gl.glFramebufferRenderbufferOES(FB, COLOR, RB, empty)
    assert status() == C.GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES
    t = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, t)
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, t, 0)
    assert status() == C.GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, _texture(gl, 8, 8, C.GL_LUMINANCE), 0)
    assert status() == C.GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES
    # a depth format on the color point
    gl.glFramebufferRenderbufferOES(FB, COLOR, RB, _renderbuffer(gl, C.GL_DEPTH_COMPONENT16_OES, 8, 8))
    assert status() == C.GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES
    # sizes that differ
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, _texture(gl, 8, 8), 0)
    gl.glFramebufferRenderbufferOES(FB, DEPTH, RB, _renderbuffer(gl, C.GL_DEPTH_COMPONENT16_OES, 8, 4))
    assert status() == C.GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_OES
    gl.glFramebufferRenderbufferOES(FB, DEPTH, RB, 0)
    assert status() == C.GL_FRAMEBUFFER_COMPLETE_OES
    # 4- and 5-bit channels are colour buffers gles draws into
    for fmt in (C.GL_RGBA4_OES, C.GL_RGB5_A1_OES):
        gl.glFramebufferRenderbufferOES(FB, COLOR, RB, _renderbuffer(gl, fmt, 8, 8))
        assert status() == C.GL_FRAMEBUFFER_COMPLETE_OES
    # an object without a color buffer is one gles cannot draw into
    gl.glFramebufferRenderbufferOES(FB, COLOR, RB, 0)
    gl.glFramebufferRenderbufferOES(FB, DEPTH, RB, _renderbuffer(gl, C.GL_DEPTH_COMPONENT16_OES, 8, 8))
    assert status() == C.GL_FRAMEBUFFER_UNSUPPORTED_OES
    gl.glBindFramebufferOES(FB, 0)
    assert status() == C.GL_FRAMEBUFFER_COMPLETE_OES
    assert gl.glGetError() == C.GL_NO_ERROR


def test_incomplete_objects_refuse_drawing_and_reading() -> None:
    ctx = gles.Context(8, 8)
    gl = ctx.gl
    gl.glClearColor(1, 0, 0, 1)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    window = np.asarray(ctx.image()).copy()
    _framebuffer(gl)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([-1, -1, 1, -1, -1, 1], np.float32))
    t = _texture(gl, 4, 4)
    calls = [
        lambda: gl.glClear(C.GL_COLOR_BUFFER_BIT),
        lambda: gl.glDrawArrays(C.GL_TRIANGLES, 0, 3),
        lambda: gl.glDrawElements(C.GL_TRIANGLES, 3, C.GL_UNSIGNED_BYTE, np.array([0, 1, 2], np.uint8)),
        lambda: gl.glReadPixels(0, 0, 1, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE),
        lambda: gl.glCopyTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 0, 0, 4, 4, 0),
        lambda: gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2),
        lambda: gl.glDrawTexiOES(0, 0, 0, 4, 4),
    ]
    for call in calls:
        call()
        assert gl.glGetError() == C.GL_INVALID_FRAMEBUFFER_OPERATION_OES
    np.testing.assert_array_equal(np.asarray(ctx.image()), window)
    del t


def test_queries_and_errors() -> None:
    gl = gles.Context(8, 8).gl
    assert gl.glGetIntegerv(C.GL_MAX_RENDERBUFFER_SIZE_OES) == 2048
    r = _renderbuffer(gl, C.GL_RGB565_OES, 5, 3)
    q = lambda p: gl.glGetRenderbufferParameterivOES(RB, p)  # noqa: E731
    assert (q(C.GL_RENDERBUFFER_WIDTH_OES), q(C.GL_RENDERBUFFER_HEIGHT_OES)) == (5, 3)
    assert q(C.GL_RENDERBUFFER_INTERNAL_FORMAT_OES) == C.GL_RGB565_OES
    assert [q(p) for p in (C.GL_RENDERBUFFER_RED_SIZE_OES, C.GL_RENDERBUFFER_GREEN_SIZE_OES,
                           C.GL_RENDERBUFFER_BLUE_SIZE_OES, C.GL_RENDERBUFFER_ALPHA_SIZE_OES)] == [5, 6, 5, 0]
    assert gl.glGetIntegerv(C.GL_RENDERBUFFER_BINDING_OES) == r and gl.glIsRenderbufferOES(r)
    bad = [
        (lambda: gl.glRenderbufferStorageOES(RB, C.GL_RGBA, 4, 4), C.GL_INVALID_ENUM),
        (lambda: gl.glRenderbufferStorageOES(RB, C.GL_RGBA8_OES, 2049, 4), C.GL_INVALID_VALUE),
        (lambda: gl.glRenderbufferStorageOES(FB, C.GL_RGBA8_OES, 4, 4), C.GL_INVALID_ENUM),
        (lambda: gl.glFramebufferRenderbufferOES(FB, COLOR, RB, r), C.GL_INVALID_OPERATION),  # window bound
        (lambda: gl.glGetFramebufferAttachmentParameterivOES(
            FB, COLOR, C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES), C.GL_INVALID_OPERATION),
        (lambda: gl.glBindFramebufferOES(RB, 1), C.GL_INVALID_ENUM),
    ]
    for call, err in bad:
        call()
        assert gl.glGetError() == err
    assert q(C.GL_RENDERBUFFER_WIDTH_OES) == 5                 # the storage kept
    f = _framebuffer(gl)
    assert gl.glGetIntegerv(C.GL_FRAMEBUFFER_BINDING_OES) == f and gl.glIsFramebufferOES(f)
    t = _texture(gl, 8, 8)
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, t, 1)          # OES_fbo_render_mipmap
    a = lambda p, at=COLOR: gl.glGetFramebufferAttachmentParameterivOES(FB, at, p)  # noqa: E731
    assert a(C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES) == C.GL_TEXTURE
    assert a(C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES) == t
    assert a(C.GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_OES) == 1
    assert a(C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, DEPTH) == C.GL_NONE_OES
    assert a(C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES, DEPTH) is None     # no object: INVALID_ENUM
    assert gl.glGetError() == C.GL_INVALID_ENUM
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, 999, 0)         # no such texture
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, t, -1)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glDeleteFramebuffersOES([f])
    assert gl.glGetIntegerv(C.GL_FRAMEBUFFER_BINDING_OES) == 0 and not gl.glIsFramebufferOES(f)


def test_rgb_targets_keep_no_alpha() -> None:
    """An RGB texture (or RGB8 renderbuffer) as the color buffer: ALPHA_BITS 0,
    alpha never written, DST_ALPHA reads 1, ReadPixels' A is 1 (§4.3.1), also for
    a texture specified without data."""
    for attach in ("texture", "texture without data", "rgb8"):
        ctx = gles.Context(4, 4)
        gl = ctx.gl
        _framebuffer(gl)
        if attach.startswith("texture"):
            t = _texture(gl, 4, 4, C.GL_RGB, None if attach.endswith("data") else np.zeros(48, np.uint8))
            gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, t, 0)
            assert (_read(gl, 4, 4)[..., 3] == 255).all()
        else:
            gl.glFramebufferRenderbufferOES(FB, COLOR, RB, _renderbuffer(gl, C.GL_RGB8_OES, 4, 4))
        assert gl.glGetIntegerv(C.GL_ALPHA_BITS) == 0 and gl.glGetIntegerv(C.GL_RED_BITS) == 8
        assert list(gl.glGetBooleanv(C.GL_COLOR_WRITEMASK)) == [1, 1, 1, 1]
        gl.glClearColor(0, 0, 0, 0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(C.GL_DST_ALPHA, C.GL_ZERO)          # source times destination alpha (1)
        gl.glColor4ub(200, 100, 50, 7)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([-1, -1, 1, -1, -1, 1, 1, 1], np.float32))
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        px = _read(gl, 4, 4)
        assert (px[..., :3] == [200, 100, 50]).all() and (px[..., 3] == 255).all()
        gl.glBindFramebufferOES(FB, 0)
        assert gl.glGetIntegerv(C.GL_ALPHA_BITS) == 8


def test_deleted_attachments_detach() -> None:
    ctx = gles.Context(8, 8)
    gl = ctx.gl
    f = _framebuffer(gl)
    t = _texture(gl, 8, 8)
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, t, 0)
    r = _renderbuffer(gl, C.GL_DEPTH_COMPONENT16_OES, 8, 8)
    gl.glFramebufferRenderbufferOES(FB, DEPTH, RB, r)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    # delete both while bound, then in another object
    gl.glDeleteRenderbuffersOES([r])
    assert gl.glCheckFramebufferStatusOES(FB) == C.GL_FRAMEBUFFER_COMPLETE_OES
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glBindFramebufferOES(FB, 0)
    gl.glDeleteTextures([t])
    gl.glBindFramebufferOES(FB, f)
    assert gl.glCheckFramebufferStatusOES(FB) == C.GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_OES
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    assert gl.glGetError() == C.GL_INVALID_FRAMEBUFFER_OPERATION_OES


def test_respecified_and_self_copied_textures() -> None:
    """A new image for an attached level: the object draws into the new one;
    CopyTexSubImage2D from an object into its own texture (undefined, but
    no overlapping copy in memory)."""
    ctx = gles.Context(8, 8)
    gl = ctx.gl
    _framebuffer(gl)
    t = _texture(gl, 8, 8)
    gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, t, 0)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 16, 4, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, None)
    gl.glClearColor(0, 1, 0, 1)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    px = _read(gl, 16, 4)
    assert px.shape == (4, 16, 4) and (px == [0, 255, 0, 255]).all()
    gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 1, 1, 0, 0, 12, 3)
    assert gl.glGetError() == C.GL_NO_ERROR


def test_generate_mipmap_is_generate_mipmap() -> None:
    """GenerateMipmapOES derives the levels GENERATE_MIPMAP derives."""
    data = np.random.default_rng(2).integers(0, 256, (8, 8, 4), dtype=np.uint8)
    ctx = gles.Context(1, 1)
    gl = ctx.gl
    a = _texture(gl, 8, 8, data=data)
    gl.glGenerateMipmapOES(C.GL_TEXTURE_2D)
    b = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, b)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, C.GL_TRUE)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 8, 8, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, data)
    for name in (a, b):
        gl.glBindTexture(C.GL_TEXTURE_2D, name)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    _framebuffer(gl)
    outs = []
    for name in (a, b):      # level 3 (1x1) read back through an object
        gl.glFramebufferTexture2DOES(FB, COLOR, C.GL_TEXTURE_2D, name, 3)
        outs.append(_read(gl, 1, 1))
    np.testing.assert_array_equal(outs[0], outs[1])
    gl.glBindTexture(C.GL_TEXTURE_2D, 0)
    gl.glGenerateMipmapOES(C.GL_TEXTURE_2D)          # no level 0
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    gl.glGenerateMipmapOES(C.GL_TEXTURE)
    assert gl.glGetError() == C.GL_INVALID_ENUM


def test_extensions_listed() -> None:
    ext = gles.Context(2, 2).gl.glGetString(C.GL_EXTENSIONS).split()
    for name in (b"GL_OES_framebuffer_object", b"GL_OES_rgb8_rgba8", b"GL_OES_depth24", b"GL_OES_stencil8",
                 b"GL_OES_packed_depth_stencil", b"GL_OES_fbo_render_mipmap", b"GL_EXT_discard_framebuffer"):
        assert name in ext


def test_discard_framebuffer() -> None:
    """EXT_discard_framebuffer: a hint (gles keeps the contents) with the extension's errors."""
    ctx = gles.Context(4, 4)
    gl = ctx.gl
    gl.glClearColor(0, 1, 0, 1)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glDiscardFramebufferEXT(FB, [C.GL_COLOR_EXT, C.GL_DEPTH_EXT, C.GL_STENCIL_EXT])
    assert gl.glGetError() == C.GL_NO_ERROR
    assert (np.asarray(ctx.image()) == [0, 255, 0, 255]).all()
    gl.glDiscardFramebufferEXT(FB, 1, [COLOR])                   # an object's token, the window bound
    assert gl.glGetError() == C.GL_INVALID_ENUM
    _framebuffer(gl)
    gl.glDiscardFramebufferEXT(FB, 2, [COLOR, DEPTH])
    assert gl.glGetError() == C.GL_NO_ERROR
    gl.glDiscardFramebufferEXT(FB, 1, [C.GL_COLOR_EXT])
    assert gl.glGetError() == C.GL_INVALID_ENUM
    gl.glDiscardFramebufferEXT(RB, 0, [])
    assert gl.glGetError() == C.GL_INVALID_ENUM
    gl.glDiscardFramebufferEXT(FB, -1, [])
    assert gl.glGetError() == C.GL_INVALID_VALUE
    with pytest.raises(ValueError):
        gl.glDiscardFramebufferEXT(FB, 3, [COLOR])
