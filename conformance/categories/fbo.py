"""Framebuffer objects: OES_framebuffer_object (EXT_framebuffer_object §4.4
as the OES extension restricts it).

Categories FBO.texture, FBO.renderbuffer, FBO.renderbuffer16, FBO.status
and FBO.errors. Every
test uses Common-Lite commands, draws flat axis-aligned quads whose edges lie
on pixel boundaries in colours every visual and buffer format holds exactly
(channels 0 or 1), and compares the framebuffer object's pixels with the
quads; only the formats OES_framebuffer_object requires are used
(RGBA4_OES, RGB5_A1_OES, RGB565_OES, DEPTH_COMPONENT16_OES, and RGB/RGBA
textures). The extension lets an implementation call any combination
FRAMEBUFFER_UNSUPPORTED_OES: a test of such a combination is skipped, never
failed.
"""

from __future__ import annotations

import numpy as np

from ..harness import TestContext, Unsupported, conformance_test

ONE = 1 << 16
RED, GREEN, BLUE, WHITE = (255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 255, 255)


def _object(t: TestContext) -> int:
    gl = t.gl
    fb = int(np.atleast_1d(gl.glGenFramebuffersOES(1))[0])
    gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, fb)
    return fb


def _renderbuffer(t: TestContext, fmt: int, w: int, h: int) -> int:
    gl = t.gl
    rb = int(np.atleast_1d(gl.glGenRenderbuffersOES(1))[0])
    gl.glBindRenderbufferOES(gl.GL_RENDERBUFFER_OES, rb)
    gl.glRenderbufferStorageOES(gl.GL_RENDERBUFFER_OES, fmt, w, h)
    return rb


def _attach(t: TestContext, attachment: int, rb: int) -> None:
    gl = t.gl
    gl.glFramebufferRenderbufferOES(gl.GL_FRAMEBUFFER_OES, attachment, gl.GL_RENDERBUFFER_OES, rb)


def _quad(t: TestContext, x0: int, y0: int, x1: int, y1: int, rgba, z: float = 0.0) -> None:
    t.gl.glColor4x(*[ONE if c else 0 for c in rgba])
    t.draw(t.gl.GL_TRIANGLE_STRIP, [[x0, y0, z], [x1, y0, z], [x0, y1, z], [x1, y1, z]], size=3)


def _scene(t: TestContext) -> np.ndarray:
    """The expected image of _draw_scene without its blue square: black,
    a red left half, a green top-right quarter (uint8)."""
    w, h = t.width, t.height
    img = np.zeros((h, w, 4), np.uint8)
    img[..., 3] = 255
    img[:, : w // 2] = RED
    img[h // 2:, w // 2:] = GREEN
    return img


def _draw_scene(t: TestContext, depth: bool) -> np.ndarray:
    """Clear to black, a red left half and a green top-right quarter, then a
    blue middle square behind them (depth 0.75 against 0.5): hidden under
    them with `depth`, over them without. Returns the expected image."""
    gl = t.gl
    w, h = t.width, t.height
    t.ortho_pixels()
    t.clear((0, 0, 0, 1))
    if depth:
        gl.glEnable(gl.GL_DEPTH_TEST)
    _quad(t, 0, 0, w // 2, h, RED)
    _quad(t, w // 2, h // 2, w, h, GREEN)
    # behind both (ortho z -0.5 is depth 0.75): hidden where they are, with depth
    _quad(t, w // 4, h // 4, 3 * w // 4, 3 * h // 4, BLUE, z=-0.5)
    gl.glDisable(gl.GL_DEPTH_TEST)
    want = _scene(t)
    if depth:
        region = want[h // 4: 3 * h // 4, w // 4: 3 * w // 4]
        black = (region[..., :3] == 0).all(axis=-1)
        region[black] = BLUE
    else:
        want[h // 4: 3 * h // 4, w // 4: 3 * w // 4] = BLUE
    return want


def _expect(t: TestContext, want: np.ndarray, where: str) -> None:
    got = np.round(t.read() * 255).astype(int)
    bad = (np.abs(got - want.astype(int)) > 0).any(axis=-1)
    if bad.any():
        y, x = (int(v) for v in np.argwhere(bad)[0])
        t.fail(f"{where}: {int(bad.sum())} pixels differ; first at (x={x}, y={y}): {got[y, x].tolist()}, "
               f"expected {want[y, x].tolist()}")


@conformance_test("FBO.texture", section="OES_framebuffer_object", size=(32, 32))
def fbo_texture(t: TestContext) -> None:
    """Drawing into an RGBA texture attached as COLOR_ATTACHMENT0 fills the texture: read
    back through the object, and drawn one texel a pixel into the window afterwards."""
    t.need_extension("GL_OES_framebuffer_object")
    gl = t.gl
    w, h = t.width, t.height
    tex = int(np.atleast_1d(gl.glGenTextures(1))[0])
    gl.glBindTexture(gl.GL_TEXTURE_2D, tex)
    gl.glTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_RGBA, w, h, 0, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE, None)
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST)
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST)
    fb = _object(t)
    gl.glFramebufferTexture2DOES(gl.GL_FRAMEBUFFER_OES, gl.GL_COLOR_ATTACHMENT0_OES, gl.GL_TEXTURE_2D, tex, 0)
    if gl.glCheckFramebufferStatusOES(gl.GL_FRAMEBUFFER_OES) != gl.GL_FRAMEBUFFER_COMPLETE_OES:
        t.fail("an RGBA texture alone is not a complete framebuffer object")
    want = _draw_scene(t, depth=False)
    _expect(t, want, "read from the object")
    gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, 0)
    t.ortho_pixels()
    t.clear((0, 0, 0, 0))
    gl.glEnable(gl.GL_TEXTURE_2D)
    gl.glTexEnvi(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE, gl.GL_REPLACE)
    gl.glEnableClientState(gl.GL_TEXTURE_COORD_ARRAY)
    coords = np.array([0, 0, ONE, 0, 0, ONE, ONE, ONE], np.int32)
    gl.glTexCoordPointer(2, gl.GL_FIXED, 0, coords)
    _quad(t, 0, 0, w, h, WHITE)
    gl.glDisableClientState(gl.GL_TEXTURE_COORD_ARRAY)
    gl.glDisable(gl.GL_TEXTURE_2D)
    _expect(t, want, "the texture drawn in the window")
    gl.glDeleteFramebuffersOES(1, [fb])
    gl.glDeleteTextures(1, [tex])
    t.check_gl_error("FBO.texture")


@conformance_test("FBO.renderbuffer", section="OES_framebuffer_object", uses=("depth",), size=(32, 32))
def fbo_renderbuffer(t: TestContext) -> None:
    """RGB565_OES and DEPTH_COMPONENT16_OES renderbuffers (the required formats) form a
    complete object whose depth test hides what is behind."""
    t.need_extension("GL_OES_framebuffer_object")
    gl = t.gl
    w, h = t.width, t.height
    t.clear((0, 0, 0, 0))          # (the window's final image is compared across path levels)
    fb = _object(t)
    c = _renderbuffer(t, gl.GL_RGB565_OES, w, h)
    z = _renderbuffer(t, gl.GL_DEPTH_COMPONENT16_OES, w, h)
    _attach(t, gl.GL_COLOR_ATTACHMENT0_OES, c)
    _attach(t, gl.GL_DEPTH_ATTACHMENT_OES, z)
    status = gl.glCheckFramebufferStatusOES(gl.GL_FRAMEBUFFER_OES)
    if status != gl.GL_FRAMEBUFFER_COMPLETE_OES:
        t.fail(f"RGB565 + DEPTH_COMPONENT16 renderbuffers: status 0x{status:04X}")
    if int(np.atleast_1d(gl.glGetIntegerv(gl.GL_DEPTH_BITS))[0]) < 16:
        t.fail("DEPTH_BITS of a DEPTH_COMPONENT16 object is below 16")
    want = _draw_scene(t, depth=True)
    _expect(t, want, "RGB565 + DEPTH16 object")
    gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, 0)
    gl.glDeleteFramebuffersOES(1, [fb])
    gl.glDeleteRenderbuffersOES(2, [c, z])
    t.check_gl_error("FBO.renderbuffer")


@conformance_test("FBO.renderbuffer16", section="OES_framebuffer_object", uses=("depth",), size=(32, 32))
def fbo_renderbuffer16(t: TestContext) -> None:
    """RGBA4_OES and RGB5_A1_OES colour renderbuffers with DEPTH_COMPONENT16_OES: complete (or
    UNSUPPORTED, which the extension allows), the depth-tested scene exactly, alpha bits
    present, and blending that reads the stored alpha (DST_ALPHA of a cleared 0 or 1)."""
    t.need_extension("GL_OES_framebuffer_object")
    gl = t.gl
    w, h = t.width, t.height
    t.clear((0, 0, 0, 0))          # (the window's final image is compared across path levels)
    unsupported = []
    for name, fmt in (("RGBA4", gl.GL_RGBA4_OES), ("RGB5_A1", gl.GL_RGB5_A1_OES)):
        fb = _object(t)
        c = _renderbuffer(t, fmt, w, h)
        z = _renderbuffer(t, gl.GL_DEPTH_COMPONENT16_OES, w, h)
        _attach(t, gl.GL_COLOR_ATTACHMENT0_OES, c)
        _attach(t, gl.GL_DEPTH_ATTACHMENT_OES, z)
        status = gl.glCheckFramebufferStatusOES(gl.GL_FRAMEBUFFER_OES)
        if status == gl.GL_FRAMEBUFFER_UNSUPPORTED_OES:
            unsupported.append(name)
        elif status != gl.GL_FRAMEBUFFER_COMPLETE_OES:
            t.fail(f"{name} + DEPTH_COMPONENT16 renderbuffers: status 0x{status:04X}")
        else:
            if int(np.atleast_1d(gl.glGetIntegerv(gl.GL_ALPHA_BITS))[0]) < 1:
                t.fail(f"ALPHA_BITS of an {name} object is 0")
            _expect(t, _draw_scene(t, depth=True), f"{name} + DEPTH16 object")
            # the right half's alpha 0 where nothing was drawn, then ONE_MINUS_DST_ALPHA, DST_ALPHA
            # of white: white over the cleared right-bottom quarter, the drawn colours elsewhere
            t.clear((0, 0, 0, 0))
            _quad(t, 0, 0, w // 2, h, RED)
            gl.glEnable(gl.GL_BLEND)
            gl.glBlendFunc(gl.GL_ONE_MINUS_DST_ALPHA, gl.GL_DST_ALPHA)
            _quad(t, 0, 0, w, h // 2, WHITE)
            gl.glDisable(gl.GL_BLEND)
            want = np.zeros((h, w, 4), np.uint8)
            want[:, : w // 2] = RED
            want[: h // 2, w // 2:] = WHITE
            _expect(t, want, f"{name} object, DST_ALPHA blending")
        gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, 0)
        gl.glDeleteFramebuffersOES(1, [fb])
        gl.glDeleteRenderbuffersOES(2, [c, z])
    t.check_gl_error("FBO.renderbuffer16")
    if len(unsupported) == 2:
        raise Unsupported("RGBA4_OES and RGB5_A1_OES objects are FRAMEBUFFER_UNSUPPORTED_OES here")


@conformance_test("FBO.status", section="OES_framebuffer_object", size=(16, 16))
def fbo_status(t: TestContext) -> None:
    """CheckFramebufferStatusOES: no attachment is MISSING_ATTACHMENT, a renderbuffer without
    storage INCOMPLETE_ATTACHMENT, attachments of two sizes INCOMPLETE_DIMENSIONS, and the
    window (object 0) COMPLETE."""
    t.need_extension("GL_OES_framebuffer_object")
    gl = t.gl
    t.clear((0, 0, 0, 0))          # (the window's final image is compared across path levels)
    fb = _object(t)
    cases = []
    cases.append(("no attachment", gl.GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_OES))
    got = [gl.glCheckFramebufferStatusOES(gl.GL_FRAMEBUFFER_OES)]
    empty = int(np.atleast_1d(gl.glGenRenderbuffersOES(1))[0])
    gl.glBindRenderbufferOES(gl.GL_RENDERBUFFER_OES, empty)
    _attach(t, gl.GL_COLOR_ATTACHMENT0_OES, empty)
    cases.append(("a renderbuffer without storage", gl.GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES))
    got.append(gl.glCheckFramebufferStatusOES(gl.GL_FRAMEBUFFER_OES))
    c = _renderbuffer(t, gl.GL_RGB565_OES, 16, 16)
    z = _renderbuffer(t, gl.GL_DEPTH_COMPONENT16_OES, 8, 16)
    _attach(t, gl.GL_COLOR_ATTACHMENT0_OES, c)
    _attach(t, gl.GL_DEPTH_ATTACHMENT_OES, z)
    cases.append(("16x16 color, 8x16 depth", gl.GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_OES))
    got.append(gl.glCheckFramebufferStatusOES(gl.GL_FRAMEBUFFER_OES))
    gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, 0)
    cases.append(("the window", gl.GL_FRAMEBUFFER_COMPLETE_OES))
    got.append(gl.glCheckFramebufferStatusOES(gl.GL_FRAMEBUFFER_OES))
    for (what, want), status in zip(cases, got):
        if status != want:
            t.fail(f"{what}: status 0x{status:04X}, expected 0x{want:04X}")
    gl.glDeleteFramebuffersOES(1, [fb])
    gl.glDeleteRenderbuffersOES(3, [empty, c, z])
    t.check_gl_error("FBO.status")


@conformance_test("FBO.errors", section="OES_framebuffer_object", size=(16, 16))
def fbo_errors(t: TestContext) -> None:
    """Drawing or clearing an incomplete object is INVALID_FRAMEBUFFER_OPERATION_OES;
    attaching with object 0 bound INVALID_OPERATION; an unknown renderbuffer format
    INVALID_ENUM."""
    t.need_extension("GL_OES_framebuffer_object")
    gl = t.gl
    t.clear((0, 0, 0, 0))          # (the window's final image is compared across path levels)
    rb = _renderbuffer(t, gl.GL_RGB565_OES, 4, 4)
    _attach(t, gl.GL_COLOR_ATTACHMENT0_OES, rb)
    t.check_gl_error("FramebufferRenderbufferOES with object 0 bound", gl.GL_INVALID_OPERATION)
    gl.glRenderbufferStorageOES(gl.GL_RENDERBUFFER_OES, gl.GL_TEXTURE_2D, 4, 4)
    t.check_gl_error("RenderbufferStorageOES of TEXTURE_2D", gl.GL_INVALID_ENUM)
    fb = _object(t)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT)
    t.check_gl_error("Clear of an object without attachments", gl.GL_INVALID_FRAMEBUFFER_OPERATION_OES)
    t.draw(gl.GL_TRIANGLES, [[0, 0], [4, 0], [0, 4]])
    t.check_gl_error("DrawArrays into an object without attachments", gl.GL_INVALID_FRAMEBUFFER_OPERATION_OES)
    gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, 0)
    gl.glDeleteFramebuffersOES(1, [fb])
    gl.glDeleteRenderbuffersOES(1, [rb])
    t.check_gl_error("FBO.errors")
