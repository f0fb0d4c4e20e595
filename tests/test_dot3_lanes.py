"""The DOT3 pair through the fused stages against the per-fragment path.

Unit 0 COMBINE DOT3_RGB (MODULATE alpha) or DOT3_RGBA of its texture and
the primary colour, unit 1 MODULATE of an RGBA or RGB texture: the double
build takes this pair in one pass of eight AVX-512 lanes where the CPU has
them (both units sampled there, or either one fetched by its own stage),
the fixed build in its float lanes, the float build and the AVX2-capped
double build in stage_color_dot3_modulate. The textures hold the edge bytes
0, 127, 128 and 255 next to each other (magnified, so the bilinear weights
are fractional between them), the vertex colours the bytes 0, 127, 128 and
255 (0 and 1 among them); the sweep covers the blends, an alpha test,
RGBA8888 and RGB565 (dithered or not), flat shading and chunk tails. Every
image must equal ``ctx.debug(1)``'s, and in the double build the AVX2-capped
instance's (debug 32) and the baseline's (debug 16).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, SPAN_CHUNK, has_avx512, make_ctx, set_ortho

from gles import constants as C

EDGES = np.array([0, 127, 128, 255], dtype=np.uint8)

# a row is a chunk and 5 more columns (a padded group)
W, H = SPAN_CHUNK + 5, 12


def edge_texture(rng: np.random.Generator, channels: int, size: int = 8) -> np.ndarray:
    """size x size texels of edge bytes, mostly, and a few random ones."""
    img = rng.choice(EDGES, size=(size, size, channels))
    odd = rng.random(img.shape) < 0.15
    img[odd] = rng.integers(0, 256, size=int(odd.sum()))
    return np.ascontiguousarray(img.astype(np.uint8))


def render(numeric: str, flags: int, s: dict) -> np.ndarray:
    ctx = make_ctx(numeric, W, H, color="rgb565" if s["rgb565"] else "rgba8888", depth=0, stencil=0)
    ctx.debug(flags)
    gl: Any = ctx.gl
    rng = np.random.default_rng(s["seed"])
    set_ortho(gl, W, H)
    gl.glClearColor(*rng.uniform(0, 1, 4))
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    (gl.glEnable if s["dither"] else gl.glDisable)(C.GL_DITHER)
    if s["blend"]:
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(*s["blend"])
    if s["alpha_test"]:
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glAlphaFunc(*s["alpha_test"])
    gl.glShadeModel(C.GL_FLAT if s["flat"] else C.GL_SMOOTH)
    # a covering quad, then triangles ending within rows (tails, short chunks)
    verts = [[0, 0], [W, 0], [0, H], [W, 0], [W, H], [0, H]]
    for _ in range(4):
        x, y = rng.uniform(0, W - 20), rng.uniform(0, H - 4)
        verts += [[x, y], [x + rng.uniform(3, 20), y + rng.uniform(0, 2)], [x + rng.uniform(0, 4), y + 4]]
    v = np.ascontiguousarray(verts, dtype=np.float32)
    cols = np.ascontiguousarray(rng.choice(EDGES, size=(len(v), 4)), dtype=np.uint8)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
    for u in range(2):
        fmt, nch = (C.GL_RGB, 3) if u == 1 and s["rgb_second"] else (C.GL_RGBA, 4)
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        gl.glClientActiveTexture(C.GL_TEXTURE0 + u)
        gl.glBindTexture(C.GL_TEXTURE_2D, u + 1)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, 8, 8, 0, fmt, C.GL_UNSIGNED_BYTE, edge_texture(rng, nch))
        # NEAREST: the unit's texels come from its fetch stage
        filt = C.GL_NEAREST if s["nearest"] == u else C.GL_LINEAR
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, filt)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, filt)
        if s["clamp"]:
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, C.GL_CLAMP_TO_EDGE)
        gl.glEnable(C.GL_TEXTURE_2D)
        if u == 0:
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, s["fn"])
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_ALPHA, C.GL_MODULATE)
            # the texture as argument 0 or 1: the pair takes either order
            first, second = (C.GL_TEXTURE, C.GL_PRIMARY_COLOR)[::-1 if s["swap"] else 1]
            for src, op in ((C.GL_SRC0_RGB, C.GL_OPERAND0_RGB), (C.GL_SRC1_RGB, C.GL_OPERAND1_RGB)):
                gl.glTexEnvi(C.GL_TEXTURE_ENV, src, first if src == C.GL_SRC0_RGB else second)
                gl.glTexEnvi(C.GL_TEXTURE_ENV, op, C.GL_SRC_COLOR)
            for src, op in ((C.GL_SRC0_ALPHA, C.GL_OPERAND0_ALPHA), (C.GL_SRC1_ALPHA, C.GL_OPERAND1_ALPHA)):
                gl.glTexEnvi(C.GL_TEXTURE_ENV, src, first if src == C.GL_SRC0_ALPHA else second)
                gl.glTexEnvi(C.GL_TEXTURE_ENV, op, C.GL_SRC_ALPHA)
        else:
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
        # magnified: about a texel per 5 pixels, so weights between edge bytes
        tc = np.ascontiguousarray(v / 40.0 + rng.uniform(-0.5, 0.5, 2), dtype=np.float32)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(v))
    assert gl.glGetError() == C.GL_NO_ERROR
    return ctx.color_buffer()


BLENDS = (None, (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), (C.GL_ONE, C.GL_ONE))


def cases() -> list[dict]:
    out = []
    for case in range(48):
        rgb565 = case % 4 == 3
        blend = BLENDS[case % 3]
        if rgb565 and blend == BLENDS[2]:
            blend = None
        out.append({
            "seed": 900 + case, "fn": C.GL_DOT3_RGBA if case % 2 else C.GL_DOT3_RGB, "rgb565": rgb565,
            "dither": case % 8 == 3, "blend": blend, "rgb_second": case % 5 == 1,
            "alpha_test": (C.GL_GEQUAL, 128 / 255) if case % 7 in (2, 5) else None,
            "flat": case % 6 == 4, "nearest": (-1, -1, 0, 1)[case % 4] if case >= 24 else -1,
            "clamp": case % 5 == 3, "swap": case % 3 == 1,
        })
    return out


@pytest.mark.parametrize("numeric", BUILDS)
def test_dot3_pair_matches_reference(numeric: str) -> None:
    flags = [16] if HAS_SIMD else []
    if numeric == "double" and has_avx512("double"):
        flags.append(32)
    for s in cases():
        ref = render(numeric, 1, s)
        got = render(numeric, 0, s)
        np.testing.assert_array_equal(got, ref, err_msg=str(s))
        for f in flags:
            np.testing.assert_array_equal(render(numeric, f, s), ref, err_msg=f"{s} debug {f}")
