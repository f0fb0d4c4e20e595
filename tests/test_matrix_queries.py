"""OES_matrix_get and OES_query_matrix, against numpy-built matrices."""

from __future__ import annotations

import numpy as np
import pytest

import gles
from gles import constants as C

BUILDS = ("fixed", "float", "double")


def _expected() -> np.ndarray:
    """translate(1.5, -2.25, 0.1) * scale(3, 1, 1), column-major as GL stores it."""
    t = np.eye(4)
    t[:3, 3] = (1.5, -2.25, 0.1)
    s = np.diag([3.0, 1.0, 1.0, 1.0])
    return (t @ s).T.reshape(-1)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("mode,pname", [
    (C.GL_MODELVIEW, C.GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES),
    (C.GL_PROJECTION, C.GL_PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES),
    (C.GL_TEXTURE, C.GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES),
])
def test_float_as_int_bits(numeric: str, mode: int, pname: int) -> None:
    """The query returns each element's IEEE single bit pattern, unscaled in every Get."""
    gl = gles.Context(4, 4, numeric=numeric).gl
    gl.glMatrixMode(mode)
    gl.glTranslatef(1.5, -2.25, 0.1)
    gl.glScalef(3.0, 1.0, 1.0)
    want = _expected().astype(np.float32).view(np.int32)
    np.testing.assert_array_equal(np.asarray(gl.glGetIntegerv(pname), np.int32).reshape(16), want)
    np.testing.assert_array_equal(np.asarray(gl.glGetFixedv(pname), np.int32).reshape(16), want)
    assert gl.glGetError() == C.GL_NO_ERROR


@pytest.mark.parametrize("numeric", BUILDS)
def test_query_matrix(numeric: str) -> None:
    """mantissa / 2^16 * 2^exponent gives every element to 2^-16 relative, status 0."""
    gl = gles.Context(4, 4, numeric=numeric, profile="common").gl
    gl.glTranslatef(1.5, -2.25, 0.1)
    gl.glScalef(3.0, 1.0, 1.0)
    mant, expo, status = gl.glQueryMatrixxOES()
    assert status == 0
    got = mant / 65536.0 * np.exp2(expo)
    want = _expected()
    assert np.all(np.abs(got - want) <= np.abs(want) * 2.0**-16)
    # exactly representable elements come back exactly
    exact = np.isin(want, (0.0, 1.0, 3.0, 1.5, -2.25))
    np.testing.assert_array_equal(got[exact], want[exact])


def test_extensions_listed() -> None:
    for profile in ("common", "common-lite"):
        ext = gles.Context(2, 2, profile=profile).gl.glGetString(C.GL_EXTENSIONS).decode().split()
        assert "GL_OES_matrix_get" in ext and "GL_OES_query_matrix" in ext
