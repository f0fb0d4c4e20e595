"""EXT_texture_lod_bias: lambda' = log2(rho) + bias (clamped to
MAX_TEXTURE_LOD_BIAS_EXT), per texture unit. A mipmap of one colour per level
drawn at a known lambda shows the level the spec's selection rule gives
(§3.7.7, equations 3.19-3.21), in every build and on Mesa."""

from __future__ import annotations

import math

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import mesa

_MESA = mesa.available()
needs_mesa = pytest.mark.skipif(_MESA is not None, reason=f"Mesa peer unavailable: {_MESA}")

LEVELS = np.array([(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 0, 255),
                   (0, 255, 255, 255), (255, 0, 255, 255)], np.uint8)


def _draw(ctx, bias: float, minf: int, unit: int = 0) -> np.ndarray:
    """32x32 levels over 8x8 pixels: lambda = 2 exactly; the centre pixel."""
    gl = ctx.gl
    gl.glActiveTexture(C.GL_TEXTURE0 + unit)
    gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    for d in range(6):
        s = 32 >> d
        gl.glTexImage2D(C.GL_TEXTURE_2D, d, C.GL_RGBA, s, s, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                        np.tile(LEVELS[d], (s, s, 1)))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, minf)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glTexEnvf(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT, bias)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthof(0, 8, 0, 8, -1, 1)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([0, 0, 8, 0, 0, 8, 8, 8], np.float32))
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.array([0, 0, 1, 0, 0, 1, 1, 1], np.float32))
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    assert gl.glGetError() == C.GL_NO_ERROR
    return np.asarray(gl.glReadPixels(0, 0, 8, 8, C.GL_RGBA, C.GL_UNSIGNED_BYTE))


def _expected(lam: float, minf: int) -> np.ndarray:
    """§3.7.7 for one lambda over LEVELS (q = 5); MAG is LINEAR: c = 0.5 for
    the NEAREST_MIPMAP_* filters, 0 otherwise (§3.7.8)."""
    c = 0.5 if minf in (C.GL_NEAREST_MIPMAP_NEAREST, C.GL_NEAREST_MIPMAP_LINEAR) else 0.0
    if lam <= c:
        return LEVELS[0].astype(float)
    if minf in (C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_NEAREST):
        d = 0 if lam <= 0.5 else min(math.ceil(lam + 0.5) - 1, 5)
        return LEVELS[d].astype(float)
    if lam >= 5:
        return LEVELS[5].astype(float)
    d = math.floor(lam)
    f = lam - d
    return (1 - f) * LEVELS[d] + f * LEVELS[d + 1]


BIASES = (0.0, 1.0, -1.0, -2.0, 0.75, 2.6, -1.25, 30.0, -30.0)


@pytest.mark.parametrize("numeric", ["fixed", "float", "double"])
@pytest.mark.parametrize("minf", [C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_LINEAR])
def test_bias_moves_lambda(numeric: str, minf: int) -> None:
    for bias in BIASES:
        with gles.Context(8, 8, numeric=numeric) as ctx:
            got = _draw(ctx, bias, minf)
        want = _expected(2.0 + max(-16.0, min(16.0, bias)), minf)
        # every pixel is at lambda 2 (an orthographic quad); LINEAR mixes round once
        assert (np.abs(got.astype(float) - want) <= 1.0).all(), (bias, got[4, 4], want)


@needs_mesa
@pytest.mark.parametrize("minf", [C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_LINEAR])
def test_bias_matches_mesa(minf: int) -> None:
    for bias in BIASES:
        with gles.Context(8, 8) as ours, mesa.MesaContext(8, 8) as peer:
            a, b = _draw(ours, bias, minf), _draw(peer, bias, minf)
        assert (np.abs(a.astype(int) - b.astype(int)) <= 1).all(), bias


def test_bias_is_per_unit_and_queried() -> None:
    with gles.Context(8, 8) as ctx:
        gl = ctx.gl
        assert gl.glGetFloatv(C.GL_MAX_TEXTURE_LOD_BIAS_EXT) == 16.0
        # unit 1 biased, unit 0 not: unit 0's draw is unbiased
        gl.glActiveTexture(C.GL_TEXTURE1)
        gl.glTexEnvf(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT, 1.5)
        assert gl.glGetTexEnvfv(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT) == 1.5
        gl.glActiveTexture(C.GL_TEXTURE0)
        assert gl.glGetTexEnvfv(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT) == 0.0
        got = _draw(ctx, 0.0, C.GL_NEAREST_MIPMAP_NEAREST)
        assert (got == LEVELS[2]).all()
        # the fixed forms: a 16.16 bias; the integer form the integer
        gl.glTexEnvx(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT, 0x18000)
        assert gl.glGetTexEnvxv(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT) == 0x18000
        gl.glTexEnvi(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT, -3)
        assert gl.glGetTexEnviv(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT) == -3
        # other pnames on the target, and the bias on TEXTURE_ENV: INVALID_ENUM, nothing changed
        gl.glTexEnvi(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        assert gl.glGetError() == C.GL_INVALID_ENUM
        gl.glTexEnvf(C.GL_TEXTURE_ENV, C.GL_TEXTURE_LOD_BIAS_EXT, 1.0)
        assert gl.glGetError() == C.GL_INVALID_ENUM
        assert gl.glGetTexEnviv(C.GL_TEXTURE_FILTER_CONTROL_EXT, C.GL_TEXTURE_LOD_BIAS_EXT) == -3


def test_extension_listed() -> None:
    assert b"GL_EXT_texture_lod_bias" in gles.Context(2, 2).gl.glGetString(C.GL_EXTENSIONS).split()
