"""Every texel byte and every stored RGB565 channel value through the fused stages.

The float and double builds' fused sample/modulate/write stage (span_float8.h;
the double build's in AVX-512 lanes where the CPU has them) forms a texel byte's
d / 255 and a stored 5- or 6-bit channel's d / 31 or d / 63 without the
division that the per-fragment path does. Here a 16x16 texture holds all 256
bytes in each channel, and the destination every 5- and 6-bit value, drawn
magnified (bilinear between neighbours, so each byte meets fractional weights)
and blended; the images must equal ``ctx.debug(1)``'s (the per-fragment
reference) in every build.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import BUILDS, make_ctx

from gles import constants as C

W, H = 96, 80


def _all_bytes_texture() -> np.ndarray:
    """16x16 RGBA: each channel holds every byte once, in a different order per channel."""
    v = np.arange(256)
    chans = [v, v[::-1], (v * 7) % 256, (v * 13 + 5) % 256]
    return np.ascontiguousarray(np.stack([c.astype(np.uint8).reshape(16, 16) for c in chans], axis=-1))


def _render(numeric: str, color: str, env: str, blend: bool, dither: bool, reference: bool) -> np.ndarray:
    ctx = make_ctx(numeric, W, H, color=color)
    if reference:
        ctx.debug(1)
    gl = ctx.gl
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0, W, 0, H, -1, 1)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glDisable(C.GL_DEPTH_TEST)
    (gl.glEnable if dither else gl.glDisable)(C.GL_DITHER)
    # a first layer of every stored value: a gradient of vertex colours
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    quad = np.array([[0, 0], [W, 0], [0, H], [W, H]], dtype=np.float32)
    cols = np.array([[0, 0, 0, 255], [255, 0, 128, 255], [0, 255, 64, 255], [255, 255, 255, 255]],
                    dtype=np.uint8)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, quad)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)
    # then the texture over it
    tex = _all_bytes_texture()
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 16, 16, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, tex)
    for p in (C.GL_TEXTURE_MIN_FILTER, C.GL_TEXTURE_MAG_FILTER):
        gl.glTexParameteri(C.GL_TEXTURE_2D, p, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, getattr(C, "GL_" + env))
    if blend:
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glColor4f(0.9, 0.7, 1.0, 0.8)
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, np.array([0, 0, 16, 16], dtype=np.int32))
    gl.glDrawTexfOES(1.25, 0.5, 0.0, 16 * 5.5, 16 * 4.75)      # a blit: every texel, fractional weights
    assert gl.glGetError() == 0
    return ctx.color_buffer()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize(("color", "env", "blend", "dither"), [
    ("rgba8888", "REPLACE", False, False),
    ("rgba8888", "MODULATE", True, False),
    ("rgb565", "MODULATE", True, False),
    ("rgb565", "MODULATE", True, True),
    ("rgb565", "REPLACE", False, True),
])
def test_every_byte_matches_reference(numeric: str, color: str, env: str, blend: bool, dither: bool) -> None:
    fast = _render(numeric, color, env, blend, dither, reference=False)
    ref = _render(numeric, color, env, blend, dither, reference=True)
    np.testing.assert_array_equal(fast, ref)
