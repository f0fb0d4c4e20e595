"""The ES 1.1 state tables (Tables 6.3-6.24), row by row, in every build and profile.

The rows, their kinds and initial values live in conformance/categories/queries.py
(:data:`STATE`), shared with the Gets conformance category. Here each row is
checked strictly against gles: GetBooleanv, GetIntegerv, GetFixedv and (Common
only) GetFloatv with the section 6.1.2 conversions, exact to the unit
(GetFixedv rounds to nearest; GetIntegerv's colour mapping within one unit of
Table 4.4's formula). Then set/get round trips with x forms (both profiles) and
f forms (Common), IsEnabled of every enable, and the per-command state
(GetLight, GetMaterial, GetTexParameter, GetTexEnv, GetClipPlane, GetPointerv,
GetString, GetBufferParameteriv). The rows of OES_texture_cube_map's and
KHR_debug's New State (all in gles's GL_EXTENSIONS) are among them, with the
cube map's per-unit state and GetTexGen*OES.
"""

from __future__ import annotations

import numpy as np
import pytest

import gles
from conformance.categories import queries as Q
from gles import constants as C

BUILDS = ("fixed", "float", "double")
PROFILES = ("common", "common-lite")
W, H = 16, 8


def _ctx(numeric: str, profile: str, color: str = "rgba8888") -> gles.Context:
    return gles.Context(W, H, numeric=numeric, profile=profile, color=color)


BITS = {"rgba8888": (8, 8, 8, 8), "rgb565": (5, 6, 5, 0), "rgba4444": (4, 4, 4, 4), "rgba5551": (5, 5, 5, 1)}
READ_PAIRS = {
    "rgba8888": (C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE),
    "rgb565": (C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5),
    "rgba4444": (C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4),
    "rgba5551": (C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1),
}


def _env(profile: str, color: str = "rgba8888") -> Q.Env:
    return Q.Env(W, H, BITS[color], 24, 8, profile == "common-lite")


@pytest.fixture(params=BUILDS)
def numeric(request: pytest.FixtureRequest) -> str:
    return request.param


@pytest.fixture(params=PROFILES)
def profile(request: pytest.FixtureRequest) -> str:
    return request.param


@pytest.mark.parametrize("row", Q.STATE, ids=lambda r: f"{r.table}-{r.name[3:]}")
def test_initial_value(row: Q.StateValue, numeric: str, profile: str) -> None:
    """Each state value's initial value through every Get of the profile."""
    gl = _ctx(numeric, profile).gl
    common = profile == "common"
    problems = Q.check_row(gl, common, row, row.want(_env(profile)), strict=True, minimum=row.minimum)
    if row.enable:
        if gl.glIsEnabled(row.pname) != bool(row.want(_env(profile))[0]):
            problems.append(f"IsEnabled({row.name})")
    assert gl.glGetError() == C.GL_NO_ERROR
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("color", tuple(BITS))
def test_pixel_depths(color: str, numeric: str) -> None:
    """Table 6.23 follows the visual; OES_read_format names its native pair."""
    gl = _ctx(numeric, "common", color).gl
    env = _env("common", color)
    for name in ("GL_RED_BITS", "GL_GREEN_BITS", "GL_BLUE_BITS", "GL_ALPHA_BITS"):
        row = Q.BY_NAME[name]
        assert not Q.check_row(gl, True, row, row.want(env), strict=True)
    fmt = gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES)
    typ = gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_TYPE_OES)
    want = READ_PAIRS[color]
    assert (fmt, typ) == want
    # enums: GetFixedv unscaled
    assert gl.glGetFixedv(C.GL_IMPLEMENTATION_COLOR_READ_TYPE_OES) == want[1]


def test_point_size_max_and_ranges(numeric: str, profile: str) -> None:
    """POINT_SIZE_MAX starts at the largest point size (Table 6.11); ranges hold 1 (Table 6.21)."""
    gl = _ctx(numeric, profile).gl
    assert not Q.initial_problems(gl, profile == "common", _env(profile), strict=True)


@pytest.mark.parametrize("setter", sorted(Q.SETTERS) + sorted(Q.EXT_SETTERS))
@pytest.mark.parametrize("form", ("x", "f"))
def test_round_trip(setter: str, form: str, numeric: str, profile: str) -> None:
    """Every settable value returns what was set, in every Get of the profile."""
    if form == "f" and profile != "common":
        pytest.skip("f forms are Common-only")
    gl = _ctx(numeric, profile).gl
    problems = Q.round_trip_problems(gl, profile == "common", setter, form, strict=True)
    assert not problems, "\n".join(problems)


def test_float_state_is_exact_float32(numeric: str) -> None:
    """A Common context given 0.1 returns float32(0.1), not the 16.16 0.0999908."""
    gl = _ctx(numeric, "common").gl
    gl.glFogf(C.GL_FOG_DENSITY, 0.1)
    gl.glPointSize(0.1)
    gl.glPolygonOffset(0.1, 0.1)
    gl.glClearColor(0.1, 0.1, 0.1, 0.1)
    gl.glColor4f(0.1, 0.1, 0.1, 0.1)
    gl.glLightf(C.GL_LIGHT0, C.GL_SPOT_EXPONENT, 0.1)
    for pname in (C.GL_FOG_DENSITY, C.GL_POINT_SIZE, C.GL_POLYGON_OFFSET_FACTOR, C.GL_POLYGON_OFFSET_UNITS,
                  C.GL_COLOR_CLEAR_VALUE, C.GL_CURRENT_COLOR):
        got = np.atleast_1d(np.asarray(gl.glGetFloatv(pname), np.float32))
        assert np.all(got == np.float32(0.1)), (C.NAMES.get(pname), got.tolist())
    assert np.float32(gl.glGetLightfv(C.GL_LIGHT0, C.GL_SPOT_EXPONENT)) == np.float32(0.1)
    # and GetFixedv rounds it to nearest: 0.1 * 65536 = 6553.6 -> 6554
    assert gl.glGetFixedv(C.GL_FOG_DENSITY) == 6554
    assert gl.glGetIntegerv(C.GL_FOG_DENSITY) == 0


def test_enables(numeric: str, profile: str) -> None:
    """IsEnabled, GetBooleanv and GetIntegerv follow Enable/Disable for every enable."""
    gl = _ctx(numeric, profile).gl
    problems = Q.enable_problems(gl) + Q.enable_problems(gl, Q.EXT_ENABLES)
    assert not problems, "\n".join(problems)


def test_extension_state(numeric: str, profile: str) -> None:
    """OES_texture_cube_map and KHR_debug New State: initial values, enables, the cube
    map's per-unit state and TEXTURE_GEN_MODE_OES in every GetTexGen form, round trips."""
    gl = _ctx(numeric, profile).gl
    assert {Q.CUBE_EXT, Q.DEBUG_EXT} <= Q.extensions(gl)
    problems = Q.ext_problems(gl, profile == "common", _env(profile), strict=True)
    assert not problems, "\n".join(problems)


def test_cube_map_state_is_per_unit(numeric: str, profile: str) -> None:
    gl = _ctx(numeric, profile).gl
    problems = Q.cube_map_unit_problems(gl, profile == "common", strict=True)
    assert not problems, "\n".join(problems)


def test_enable_of_unknown_cap_is_invalid_enum(numeric: str) -> None:
    gl = _ctx(numeric, "common").gl
    assert gl.glIsEnabled(C.GL_FOG_DENSITY) is False
    assert gl.glGetError() == C.GL_INVALID_ENUM
    assert gl.glGetIntegerv(0x1234) is None
    assert gl.glGetError() == C.GL_INVALID_ENUM


def test_lights_and_materials(numeric: str, profile: str) -> None:
    """Tables 6.9 and 6.10: initial values of all 8 lights and both faces; round trips."""
    gl = _ctx(numeric, profile).gl
    common = profile == "common"
    problems = Q.light_material_problems(gl, common, True, 8)
    for form in ("x", "f") if common else ("x",):
        problems += Q.light_material_round_trip(gl, form, True)
    assert not problems, "\n".join(problems)


def test_texture_parameters_and_env(numeric: str, profile: str) -> None:
    """Tables 6.14 and 6.15 through GetTexParameter/GetTexEnv i, x (and f)."""
    gl = _ctx(numeric, profile).gl
    problems = Q.tex_problems(gl, profile == "common", True)
    assert not problems, "\n".join(problems)


def test_texture_env_is_per_unit(numeric: str) -> None:
    gl = _ctx(numeric, "common-lite").gl
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_DECAL)
    assert gl.glGetTexEnviv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE) == C.GL_DECAL
    gl.glActiveTexture(C.GL_TEXTURE0)
    assert gl.glGetTexEnviv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE) == C.GL_MODULATE


def test_clip_plane_pointers_strings_buffers(numeric: str, profile: str) -> None:
    """GetClipPlane (Table 6.7), GetPointerv (6.4, 6.5), strings, buffer state (6.6), GetError (6.24)."""
    gl = _ctx(numeric, profile).gl
    common = profile == "common"
    version = "OpenGL ES-CM 1.1" if common else "OpenGL ES-CL 1.1"
    problems = Q.misc_problems(gl, common, exact_version=version)
    problems += Q.pointer_problems(gl)
    problems += Q.clip_plane_problems(gl, common, True)
    assert not problems, "\n".join(problems)
    arr = np.zeros(8, np.int16)
    gl.glVertexPointer(2, C.GL_SHORT, 0, arr)
    assert gl.glGetPointerv(C.GL_VERTEX_ARRAY_POINTER) == arr.ctypes.data


def test_matrix_get_bits_and_query(numeric: str, profile: str) -> None:
    """OES_matrix_get bits after a known transform; OES_query_matrix reconstructs it."""
    gl = _ctx(numeric, profile).gl
    gl.glMatrixMode(C.GL_TEXTURE)
    gl.glTranslatex(Q.fx(1.75), Q.fx(-2.25), Q.fx(0.75))
    gl.glScalex(Q.fx(3), Q.fx(0.25), Q.fx(-2))
    m = np.diag([3.0, 0.25, -2.0, 1.0])
    m[:3, 3] = (1.75, -2.25, 0.75)
    want = m.T.reshape(-1)
    bits = np.asarray(gl.glGetIntegerv(C.GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES), np.int32).reshape(16)
    np.testing.assert_array_equal(bits, want.astype(np.float32).view(np.int32))
    mant, expo, status = gl.glQueryMatrixxOES()
    assert status == 0
    np.testing.assert_array_equal(mant / 65536.0 * np.exp2(expo), want)
    np.testing.assert_array_equal(gl.glGetFixedv(C.GL_TEXTURE_MATRIX).reshape(16), np.round(want * 65536))
    # GetIntegerv rounds matrix elements to nearest (not the colour mapping)
    np.testing.assert_array_equal(gl.glGetIntegerv(C.GL_TEXTURE_MATRIX).reshape(16),
                                  [3, 0, 0, 0, 0, 0, 0, 0, 0, 0, -2, 0, 2, -2, 1, 1])
