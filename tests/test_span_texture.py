"""Textured triangles through the span chain (one unit, REPLACE or MODULATE,
with and without depth LESS and SRC_ALPHA blending: the states that once had
fused textured spans) give pixels and depth identical to the generic path
(ctx.debug(1)) over random triangles, textures and filters."""

from __future__ import annotations

import numpy as np
import pytest

import gles
from gles import constants as C

BUILDS = ("fixed", "float", "double")
FILTERS = (C.GL_LINEAR, C.GL_NEAREST, C.GL_LINEAR_MIPMAP_LINEAR, C.GL_NEAREST_MIPMAP_NEAREST)


def _render(numeric: str, debug: int, env: int, depth: bool, blend: bool, min_filter: int, fmt: int,
            seed: int) -> tuple[np.ndarray, np.ndarray, str]:
    rng = np.random.default_rng(seed)
    xyz = rng.uniform(-1.2, 1.2, (12, 3))
    w = rng.uniform(0.3, 2.0, (12, 1))
    verts = np.concatenate([xyz * w, w], axis=1).astype(np.float32)
    coords = rng.uniform(-3, 3, (12, 2)).astype(np.float32)
    colors = rng.integers(0, 256, (12, 4)).astype(np.uint8)
    channels = 4 if fmt == C.GL_RGBA else 3
    texels = rng.integers(0, 256, (32, 32, channels)).astype(np.uint8)
    ctx = gles.Context(48, 48, numeric=numeric)
    ctx.debug(debug)
    gl = ctx.gl
    gl.glClearColor(0.3, 0.2, 0.1, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glBindTexture(C.GL_TEXTURE_2D, gl.glGenTextures(1))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, 32, 32, 0, fmt, C.GL_UNSIGNED_BYTE, texels)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, min_filter)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, env)
    if depth:
        gl.glEnable(C.GL_DEPTH_TEST)
    if blend:
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(4, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, coords)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 12)
    assert gl.glGetError() == C.GL_NO_ERROR
    return ctx.color_buffer(), ctx.depth_buffer(), ctx.last_span_path()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("seed", range(16))
def test_textured_spans_match_generic(numeric: str, seed: int) -> None:
    """Random state per seed; the chain must be the path chosen."""
    env = (C.GL_MODULATE, C.GL_REPLACE)[seed % 2]
    depth, blend = bool(seed // 2 % 2), bool(seed // 4 % 2)
    min_filter = FILTERS[seed // 8 % 2 + (2 if seed % 3 == 0 else 0)]
    fmt = C.GL_RGBA if seed % 5 else C.GL_RGB
    fast = _render(numeric, 0, env, depth, blend, min_filter, fmt, seed)
    slow = _render(numeric, 1, env, depth, blend, min_filter, fmt, seed)
    assert fast[2] == "chain" and slow[2] == "generic"
    assert np.array_equal(fast[0], slow[0])
    assert np.array_equal(fast[1], slow[1])
