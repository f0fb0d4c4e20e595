"""EXT_texture_filter_anisotropic: the extension's own scheme. Fx, Fy are
the larger of |du|, |dv| per window step (its allowed approximation of Px,
Py), N = min(ceil(Fmax / Fmin), maxAniso) samples at lambda' = log2(Fmax / N)
spaced i / (N + 1) - 1/2 of the major axis' step apart (i = 1..N), averaged.
The expected pixels are that formula evaluated in numpy on an orthographic
quad, whose derivatives are exact."""

from __future__ import annotations

import math

import numpy as np
import pytest

import gles
from gles import constants as C

W = H = 16
RNG = np.random.default_rng(17)
LEVELS = [RNG.integers(0, 256, (32 >> d, 32 >> d, 4), dtype=np.uint8) for d in range(6)]


def _draw(numeric: str, aniso: float | None, s1: float, t1: float) -> np.ndarray:
    """The 32x32 mipmap over the window, s from 0 to s1 across, t from 0 to t1 up,
    NEAREST_MIPMAP_NEAREST / NEAREST, REPEAT."""
    with gles.Context(W, H, numeric=numeric) as ctx:
        gl = ctx.gl
        gl.glBindTexture(C.GL_TEXTURE_2D, 1)
        gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
        for d, img in enumerate(LEVELS):
            gl.glTexImage2D(C.GL_TEXTURE_2D, d, C.GL_RGBA, img.shape[1], img.shape[0], 0, C.GL_RGBA,
                            C.GL_UNSIGNED_BYTE, img)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
        if aniso is not None:
            gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glOrthof(0, W, 0, H, -1, 1)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([0, 0, W, 0, 0, H, W, H], np.float32))
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.array([0, 0, s1, 0, 0, t1, s1, t1], np.float32))
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        assert gl.glGetError() == C.GL_NO_ERROR
        return np.asarray(gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)).astype(float)


def _expected(aniso: float, s1: float, t1: float) -> np.ndarray:
    ds, dt = s1 / W, t1 / H                         # per window step, along x and along y
    fx, fy = 32 * ds, 32 * dt                       # |du/dx|, |dv/dy| (the others are 0)
    fmax, fmin = max(fx, fy), min(fx, fy)
    n = min(math.ceil(fmax / fmin), int(min(aniso, 16.0)))
    lam = math.log2(fmax / n)
    level = 0 if lam <= 0.5 else min(math.ceil(lam + 0.5) - 1, 5)   # (lambda <= 0: magnification, level 0)
    img = LEVELS[level].astype(float)
    size = img.shape[0]
    out = np.zeros((H, W, 4))
    for y in range(H):
        for x in range(W):
            acc = np.zeros(4)
            for i in range(1, n + 1):
                f = i / (n + 1) - 0.5
                s = (x + 0.5) * ds + (ds * f if fx > fy else 0.0)
                t = (y + 0.5) * dt + (dt * f if fx <= fy else 0.0)
                u, v = (s - math.floor(s)) * size, (t - math.floor(t)) * size
                acc += img[int(math.floor(v)) % size, int(math.floor(u)) % size]
            out[y, x] = acc / n
    return out


@pytest.mark.parametrize("numeric", ["fixed", "float", "double"])
@pytest.mark.parametrize("aniso, s1, t1",
                         [(16.0, 4.0, 0.5), (4.0, 4.0, 0.5), (16.0, 0.5, 2.0), (2.5, 2.0, 0.5)])
def test_footprint_samples_along_the_major_axis(numeric: str, aniso: float, s1: float, t1: float) -> None:
    got = _draw(numeric, aniso, s1, t1)
    want = _expected(aniso, s1, t1)
    assert np.abs(got - want).max() <= 1.0           # one rounding of the average to 8 bits


@pytest.mark.parametrize("numeric", ["fixed", "double"])
def test_isotropic_footprints_and_aniso_one_are_unchanged(numeric: str) -> None:
    # aniso 1 (the default) is the isotropic filter; an isotropic footprint takes one sample
    np.testing.assert_array_equal(_draw(numeric, 16.0, 2.0, 2.0), _draw(numeric, None, 2.0, 2.0))
    np.testing.assert_array_equal(_draw(numeric, 1.0, 4.0, 0.5), _draw(numeric, None, 4.0, 0.5))
    # and the anisotropic one is not the isotropic one
    assert (_draw(numeric, 16.0, 4.0, 0.5) != _draw(numeric, None, 4.0, 0.5)).any()


def test_state_and_errors() -> None:
    gl = gles.Context(2, 2).gl
    assert gl.glGetFloatv(C.GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT) == 16.0
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    assert gl.glGetTexParameterfv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT) == 1.0
    gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, 8.5)
    gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    assert gl.glGetTexParameterfv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT) == 8.5
    gl.glTexParameterx(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, 0x30000)     # 16.16: 3.0
    assert gl.glGetTexParameterxv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT) == 0x30000
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, 4)
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT) == 4
    gl.glBindTexture(C.GL_TEXTURE_2D, 2)                        # per texture object
    assert gl.glGetTexParameterfv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT) == 1.0
    assert b"GL_EXT_texture_filter_anisotropic" in gl.glGetString(C.GL_EXTENSIONS).split()


def test_fixed_range_check() -> None:
    """A value 16.16 cannot hold, through the f form on the fixed build, is reported."""
    ctx = gles.Context(2, 2, numeric="fixed", range_check="raise")
    with pytest.raises(gles.RangeError):
        ctx.gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, 1e6)
