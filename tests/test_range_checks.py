"""Range checks for 16.16 (gles.profile): they fire exactly when the rules say.

Per value: a real with |x| >= 32768 (or NaN) overflows; a nonzero real whose
16.16 value, round(x * 65536), is 0 underflows. Per draw (McReynolds and
Blythe 8.3.2): with s the largest |element| of the upper 3x3 of P*MV, t the
largest |element| of its 4th column and c the largest |component| of the
vertices drawn, c*s + t >= 16384 breaks the rule. The expected outcome is
computed here in numpy from those definitions.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import gles
from gles import constants as C
from gles.profile import CHECKED_COMMANDS, RangeError, RangeWarning, classify

FIXED_MAX = 0x7FFFFFFF / 65536


def fixed_ctx(policy: str = "warn", **kw) -> gles.Context:
    return gles.Context(16, 16, numeric="fixed", range_check=policy, **kw)


def quiet(fn, *args):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RangeWarning)
        return fn(*args)


def expected_kind(x: float) -> str | None:
    """The rule, from its definition: overflow, or nonzero -> 0 under round-half-up."""
    if math.isnan(x) or abs(x) >= 32768:
        return "overflow"
    if x != 0 and math.floor(x * 65536 + 0.5) == 0:
        return "underflow"
    return None


# {====================================================================
# per value

reals = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True, width=64),
    st.floats(min_value=32767.0, max_value=32769.0),
    st.floats(min_value=-32769.0, max_value=-32767.0),
    st.floats(min_value=-2.0**-16, max_value=2.0**-16),
    st.sampled_from([2.0**-17, -2.0**-17, 2.0**-17 * (1 + 2**-52), -2.0**-17 * (1 + 2**-52), 32768.0,
                     -32768.0, FIXED_MAX, -FIXED_MAX, 5e-324, -5e-324, 0.0, -0.0]),
)


@given(reals)
@settings(max_examples=400, deadline=None)
def test_classify_matches_definition(x: float) -> None:
    assert classify(x) == expected_kind(x)


@given(reals)
@settings(max_examples=200, deadline=None)
def test_classify_matches_the_fixed_conversion(x: float) -> None:
    # the core's own double -> 16.16 conversion: an underflow is exactly a
    # nonzero real that the fixed build turns into 0
    assume(not math.isnan(x) and abs(x) < 32768)
    core = gles.Context(1, 1, numeric="fixed", range_check="off")._lib
    becomes_zero = core.gles_num_eval(0, x, 0.0) == 0.0
    assert (classify(x) == "underflow") == (x != 0 and becomes_zero)


@given(st.lists(reals, min_size=3, max_size=3))
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_translate_counts_each_argument(xyz: list[float]) -> None:
    ctx = fixed_ctx()
    quiet(ctx.gl.glTranslatef, *xyz)
    rep = ctx.range_report()
    kinds = [expected_kind(v) for v in xyz]
    assert rep.counts["overflow"] == kinds.count("overflow")
    assert rep.counts["underflow"] == kinds.count("underflow")
    assert rep.counts["rule"] == 0
    for name, v in zip("xyz", xyz):
        if expected_kind(v):
            assert rep.by_source[f"glTranslatef({name})"] == 1


@given(st.lists(reals, min_size=16, max_size=16))
@settings(max_examples=100, deadline=None)
def test_load_matrix_counts_each_element(m: list[float]) -> None:
    ctx = fixed_ctx()
    quiet(ctx.gl.glLoadMatrixf, np.array(m))
    kinds = [expected_kind(v) for v in m]
    rep = ctx.range_report()
    assert rep.counts["overflow"] == kinds.count("overflow")
    assert rep.counts["underflow"] == kinds.count("underflow")


def test_enum_valued_params_are_not_values() -> None:
    # CLAMP_TO_EDGE is 0x812F (> 32768) and COMBINE 0x8570: enums, not 16.16 reals
    ctx = fixed_ctx("raise")
    g = ctx.gl
    g.glTexEnvf(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)
    g.glTexEnvf(C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, C.GL_DOT3_RGB)
    g.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
    g.glFogf(C.GL_FOG_MODE, C.GL_EXP2)
    g.glFogfv(C.GL_FOG_MODE, [C.GL_LINEAR])
    assert ctx.range_report().total == 0
    assert g.glGetError() == 0
    with pytest.raises(RangeError):
        g.glTexEnvfv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, [0.5, 0.5, 1e-9, 1.0])


@pytest.mark.parametrize("name", CHECKED_COMMANDS)
def test_every_checked_command_reports(name: str) -> None:
    """Each float command with reals reports an out-of-range value in the
    right argument, and under "raise" changes nothing."""
    calls = {
        "glAlphaFunc": (C.GL_LESS, 4e4),
        "glClearColor": (4e4, 0, 0, 1),
        "glClearDepthf": (4e4,),
        "glDepthRangef": (4e4, 1),
        "glTranslatef": (4e4, 0, 0),
        "glScalef": (4e4, 1, 1),
        "glRotatef": (4e4, 0, 0, 1),
        "glFrustumf": (-1, 1, -1, 1, 1, 4e4),
        "glOrthof": (-4e4, 1, -1, 1, -1, 1),
        "glColor4f": (4e4, 0, 0, 1),
        "glNormal3f": (4e4, 0, 1),
        "glMultiTexCoord4f": (C.GL_TEXTURE0, 4e4, 0, 0, 1),
        "glPointSize": (4e4,),
        "glLineWidth": (4e4,),
        "glPolygonOffset": (4e4, 0),
        "glSampleCoverage": (4e4, False),
        "glDrawTexfOES": (0, 0, 0, 4e4, 1),
        "glLoadMatrixf": ([4e4] + [0.0] * 15,),
        "glMultMatrixf": ([4e4] + [0.0] * 15,),
        "glClipPlanef": (C.GL_CLIP_PLANE0, [4e4, 0, 0, 0]),
        "glDrawTexfvOES": ([0, 0, 0, 4e4, 1],),
        "glLightf": (C.GL_LIGHT0, C.GL_CONSTANT_ATTENUATION, 4e4),
        "glLightfv": (C.GL_LIGHT0, C.GL_POSITION, [4e4, 0, 0, 1]),
        "glLightModelf": (C.GL_LIGHT_MODEL_TWO_SIDE, 0),
        "glLightModelfv": (C.GL_LIGHT_MODEL_AMBIENT, [4e4, 0, 0, 1]),
        "glMaterialf": (C.GL_FRONT_AND_BACK, C.GL_SHININESS, 4e4),
        "glMaterialfv": (C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [4e4, 0, 0, 1]),
        "glFogf": (C.GL_FOG_END, 4e4),
        "glFogfv": (C.GL_FOG_COLOR, [4e4, 0, 0, 1]),
        "glTexEnvf": (C.GL_TEXTURE_ENV, C.GL_RGB_SCALE, 4e4),
        "glTexEnvfv": (C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, [4e4, 0, 0, 1]),
        "glTexParameterf": (C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, 4e4),
        "glTexParameterfv": (C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_ANISOTROPY_EXT, [4e4]),
        "glPointParameterf": (C.GL_POINT_SIZE_MAX, 4e4),
        "glPointParameterfv": (C.GL_POINT_DISTANCE_ATTENUATION, [4e4, 0, 0]),
    }
    args = calls[name]
    ctx = fixed_ctx()
    if name == "glLightModelf":
        # ES 1.1's only scalar light-model value, TWO_SIDE, is a boolean: never checked
        ctx.gl.glLightModelf(C.GL_LIGHT_MODEL_TWO_SIDE, 4e4)
        assert ctx.range_report().total == 0
        return
    with pytest.warns(RangeWarning, match=name):
        getattr(ctx.gl, name)(*args)
    rep = ctx.range_report()
    assert rep.counts["overflow"] == 1
    assert rep.events[0].margin == pytest.approx(4e4 / 32768)
    # "raise": the call does nothing, state and the error flag unchanged
    strict = fixed_ctx("raise")
    before = strict.gl.glGetFloatv(C.GL_MODELVIEW_MATRIX)
    with pytest.raises(RangeError, match=name):
        getattr(strict.gl, name)(*args)
    assert strict.gl.glGetError() == 0
    assert np.array_equal(strict.gl.glGetFloatv(C.GL_MODELVIEW_MATRIX), before)


def test_clamp_keeps_values_in_range() -> None:
    ctx = fixed_ctx("clamp")
    g = ctx.gl
    with warnings.catch_warnings():
        warnings.simplefilter("error", RangeWarning)   # clamp does not warn
        g.glMatrixMode(C.GL_PROJECTION)
        g.glFrustumf(-1, 1, -1, 1, 1e-9, 1e6)
    # the near plane became 2^-16 (not 0, which would be INVALID_VALUE), far the largest 16.16 value
    assert g.glGetError() == 0
    n, f = 2.0**-16, FIXED_MAX
    p = g.glGetFloatv(C.GL_PROJECTION_MATRIX).astype(np.float64).reshape(16)
    assert p[10] == pytest.approx(np.float32(-(f + n) / (f - n)))
    assert p[14] == pytest.approx(np.float32(-2 * f * n / (f - n)), rel=1e-6)
    assert ctx.range_report().counts == {"overflow": 1, "underflow": 1, "rule": 0}


def test_off_costs_nothing_and_counts_nothing() -> None:
    ctx = fixed_ctx("off")
    assert type(ctx.gl).__name__ == "GLCommon"
    ctx.gl.glTranslatef(1e9, 1e-9, 0)
    assert ctx.range_report().total == 0 and ctx.range_report().draws_checked == 0


def test_defaults_per_build() -> None:
    assert gles.Context(4, 4, numeric="fixed").range_check == "warn"
    assert gles.Context(4, 4, numeric="float").range_check == "off"
    assert gles.Context(4, 4, numeric="double", range_check="warn").range_check == "warn"
    with pytest.raises(ValueError):
        gles.Context(4, 4, range_check="loud")


def test_policy_switch_keeps_arrays_and_current() -> None:
    ctx = fixed_ctx("off")
    ctx.make_current()
    v = np.array([0, 0, 8, 0, 0, 8], np.float32)
    ctx.gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    ctx.gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
    ctx.range_check = "raise"
    from gles import gl as G
    assert G.current_gl() is ctx.gl
    with pytest.raises(RangeError):
        G.glTranslatef(1e5, 0, 0)
    ctx.check_errors = True
    assert ctx.range_check == "raise"
    G.glDrawArrays(C.GL_TRIANGLES, 0, 3)   # the kept array is still valid


def test_warning_points_at_the_caller() -> None:
    ctx = fixed_ctx()
    with pytest.warns(RangeWarning) as rec:
        ctx.gl.glScalef(1e6, 1, 1)
    assert rec[0].filename == __file__


def test_report_reset() -> None:
    ctx = fixed_ctx()
    quiet(ctx.gl.glScalef, 1e6, 1, 1)
    assert ctx.range_report(reset=True).total == 1
    assert ctx.range_report().total == 0


# {====================================================================
# per draw

def dyadic(lo: int, hi: int, denom: int) -> st.SearchStrategy[float]:
    """Reals k / denom: products and sums of a few stay exact in double, so
    the expected side of c*s + t < 16384 is never a rounding accident."""
    return st.integers(lo, hi).map(lambda k: k / denom)


matrices = st.lists(dyadic(-(2**14), 2**14, 64), min_size=16, max_size=16).map(np.array)


def rule_breaks(p: np.ndarray, mv: np.ndarray, verts: np.ndarray) -> bool:
    m = p.reshape(4, 4).T @ mv.reshape(4, 4).T          # column-major arrays -> row-major P*MV
    s = np.abs(m[:3, :3]).max()
    t = np.abs(m[:, 3]).max()
    c = np.abs(verts).max()
    return bool(c * s + t >= 16384)


def draw_setup(policy: str, p: np.ndarray, mv: np.ndarray, verts: np.ndarray, profile: str = "common"):
    ctx = gles.Context(8, 8, numeric="fixed", profile=profile, range_check=policy)
    g = ctx.gl
    g.glMatrixMode(C.GL_PROJECTION)
    g.glLoadMatrixx((np.rint(p * 65536)).astype(np.int64))
    g.glMatrixMode(C.GL_MODELVIEW)
    g.glLoadMatrixx((np.rint(mv * 65536)).astype(np.int64))
    g.glEnableClientState(C.GL_VERTEX_ARRAY)
    return ctx, g


@given(matrices, matrices, st.integers(2, 4), st.integers(1, 12), st.data())
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_draw_arrays_rule(p: np.ndarray, mv: np.ndarray, size: int, n: int, data: st.DataObject) -> None:
    verts = np.array(data.draw(st.lists(dyadic(-(2**20), 2**20, 16), min_size=n * size, max_size=n * size)),
                     dtype=np.float32).reshape(n, size)
    first = data.draw(st.integers(0, n - 1))
    count = data.draw(st.integers(1, n - first))
    ctx, g = draw_setup("warn", p, mv, verts)
    g.glVertexPointer(size, C.GL_FLOAT, 0, verts)
    quiet(g.glDrawArrays, C.GL_POINTS, first, count)
    rep = ctx.range_report()
    assert rep.draws_checked == 1
    assert rep.counts["rule"] == int(rule_breaks(p, mv, verts[first:first + count]))


@given(matrices, matrices, st.integers(2, 4), st.integers(1, 10), st.data())
@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_draw_elements_rule_on_a_buffer(p: np.ndarray, mv: np.ndarray, size: int, n: int,
                                        data: st.DataObject) -> None:
    """Buffer objects: the cached bound of the whole buffer, refined to the
    drawn index range lo..hi when it breaks the rule; FIXED and SHORT arrays."""
    gltype = data.draw(st.sampled_from([C.GL_FIXED, C.GL_SHORT, C.GL_FLOAT]))
    if gltype == C.GL_SHORT:
        raw = np.array(data.draw(st.lists(st.integers(-32768, 32767), min_size=n * size, max_size=n * size)),
                       dtype=np.int16)
        verts = raw.astype(np.float64)
    elif gltype == C.GL_FIXED:
        raw = np.array(data.draw(st.lists(st.integers(-(2**31), 2**31 - 1), min_size=n * size,
                                          max_size=n * size)), dtype=np.int32)
        verts = raw / 65536.0
    else:
        raw = np.array(data.draw(st.lists(dyadic(-(2**20), 2**20, 16), min_size=n * size, max_size=n * size)),
                       dtype=np.float32)
        verts = raw.astype(np.float64)
    verts = verts.reshape(n, size)
    idx = np.array(data.draw(st.lists(st.integers(0, n - 1), min_size=1, max_size=8)), dtype=np.uint16)
    ctx, g = draw_setup("warn", p, mv, verts, profile="common-lite" if gltype != C.GL_FLOAT else "common")
    buf = g.glGenBuffers(1)
    g.glBindBuffer(C.GL_ARRAY_BUFFER, buf)
    g.glBufferData(C.GL_ARRAY_BUFFER, raw.nbytes, raw, C.GL_STATIC_DRAW)
    g.glVertexPointer(size, gltype, 0, 0)
    quiet(g.glDrawElements, C.GL_POINTS, idx.size, C.GL_UNSIGNED_SHORT, idx)
    lo, hi = int(idx.min()), int(idx.max())
    assert ctx.range_report().counts["rule"] == int(rule_breaks(p, mv, verts[lo:hi + 1]))


def test_buffer_sub_data_refreshes_the_cached_bound() -> None:
    ident = np.eye(4).reshape(-1)
    small = np.zeros((3, 3), np.float32)
    ctx, g = draw_setup("warn", ident, ident, small)
    buf = g.glGenBuffers(1)
    g.glBindBuffer(C.GL_ARRAY_BUFFER, buf)
    g.glBufferData(C.GL_ARRAY_BUFFER, small.nbytes, small, C.GL_DYNAMIC_DRAW)
    g.glVertexPointer(3, C.GL_FLOAT, 0, 0)
    g.glDrawArrays(C.GL_POINTS, 0, 3)
    assert ctx.range_report().counts["rule"] == 0
    g.glBufferSubData(C.GL_ARRAY_BUFFER, 12, 4, np.array([20000.0], np.float32))
    with pytest.warns(RangeWarning, match="c = 20000"):
        g.glDrawArrays(C.GL_POINTS, 0, 3)
    # the rule is over the drawn vertices: vertex 0 alone is fine
    g.glDrawArrays(C.GL_POINTS, 0, 1)
    assert ctx.range_report().counts["rule"] == 1


def test_client_arrays_are_read_at_each_draw() -> None:
    """A client array changed in place after glVertexPointer is seen (the
    bound of client memory is never cached)."""
    ident = np.eye(4).reshape(-1)
    verts = np.zeros((3, 3), np.float32)
    ctx, g = draw_setup("warn", ident, ident, verts)
    g.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    g.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    verts[2, 1] = -17000.0
    with pytest.warns(RangeWarning):
        g.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    assert ctx.range_report().draws_breaking_rule == 1


def test_raise_draws_nothing() -> None:
    ctx = gles.Context(16, 16, numeric="fixed", range_check="raise")
    g = ctx.gl
    g.glMatrixMode(C.GL_MODELVIEW)
    g.glScalef(2.0**-12, 2.0**-12, 2.0**-12)    # brings 20000 on screen: 20000 / 4096 ~ 4.9
    g.glScalef(1 / 8.0, 1 / 8.0, 1 / 8.0)
    v = np.array([-20000, -20000, 20000, -20000, 0, 20000], np.float32)
    g.glEnableClientState(C.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, C.GL_FLOAT, 0, v)
    g.glClearColor(0, 0, 0, 1)
    g.glClear(C.GL_COLOR_BUFFER_BIT)
    before = ctx.image()
    g.glScalef(4096.0, 4096.0, 4096.0)   # now s = 1/8: c*s + t = 2501 (t = 1, the w row), fine
    g.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    assert not np.array_equal(ctx.image(), before)
    g.glClear(C.GL_COLOR_BUFFER_BIT)
    g.glScalef(8.0, 8.0, 8.0)            # s = 1: c*s + t = 20001 breaks the rule
    with pytest.raises(RangeError, match="nothing was drawn"):
        g.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    assert np.array_equal(ctx.image(), before)
    assert g.glGetError() == 0


def test_palette_matrices_count() -> None:
    ctx = gles.Context(8, 8, numeric="fixed", range_check="warn")
    g = ctx.gl
    g.glEnable(C.GL_MATRIX_PALETTE_OES)
    g.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
    g.glCurrentPaletteMatrixOES(3)
    g.glLoadMatrixf(np.diag([100.0, 100, 100, 1]).reshape(-1))
    v = np.array([[200, 0, 0]] * 3, np.float32)
    g.glEnableClientState(C.GL_VERTEX_ARRAY)
    g.glEnableClientState(C.GL_MATRIX_INDEX_ARRAY_OES)
    g.glEnableClientState(C.GL_WEIGHT_ARRAY_OES)
    g.glVertexPointer(3, C.GL_FLOAT, 0, v)
    g.glMatrixIndexPointerOES(1, C.GL_UNSIGNED_BYTE, 0, np.zeros(3, np.uint8))
    g.glWeightPointerOES(1, C.GL_FLOAT, 0, np.ones(3, np.float32))
    with pytest.warns(RangeWarning, match="s = 100"):
        g.glDrawArrays(C.GL_TRIANGLES, 0, 3)


def test_non_finite_vertex_breaks_the_rule() -> None:
    ident = np.eye(4).reshape(-1)
    v = np.array([0, 0, np.nan, 0, 1, 1], np.float32)
    ctx, g = draw_setup("warn", ident, ident, v)
    g.glVertexPointer(2, C.GL_FLOAT, 0, v)
    quiet(g.glDrawArrays, C.GL_TRIANGLES, 0, 3)
    assert ctx.range_report().counts["rule"] == 1


# {====================================================================
# per value, in FLOAT arrays: drawn values 16.16 cannot hold

ARRAYS = {   # name -> (enable, set the pointer, components)
    "normal": (C.GL_NORMAL_ARRAY, lambda g, a: g.glNormalPointer(C.GL_FLOAT, 0, a), 3),
    "color": (C.GL_COLOR_ARRAY, lambda g, a: g.glColorPointer(4, C.GL_FLOAT, 0, a), 4),
    "texcoord": (C.GL_TEXTURE_COORD_ARRAY, lambda g, a: g.glTexCoordPointer(2, C.GL_FLOAT, 0, a), 2),
    "pointsize": (C.GL_POINT_SIZE_ARRAY_OES, lambda g, a: g.glPointSizePointerOES(C.GL_FLOAT, 0, a), 1),
}

array_values = st.one_of(dyadic(-(2**17), 2**17, 2),
                         st.sampled_from([32768.0, -32768.0, 32767.5, np.nan, np.inf]))


@given(st.integers(1, 8), st.sets(st.sampled_from(sorted(ARRAYS)), min_size=1), st.data())
@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_float_array_overflow(n: int, names: set[str], data: st.DataObject) -> None:
    first = data.draw(st.integers(0, n - 1))
    count = data.draw(st.integers(1, n - first))
    ident = np.eye(4).reshape(-1)
    verts = np.zeros((n, 2), np.float32)
    ctx, g = draw_setup("warn", ident, ident, verts)
    g.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    expect = 0
    keep = []
    for name in sorted(names):
        enable, set_pointer, size = ARRAYS[name]
        arr = np.array(data.draw(st.lists(array_values, min_size=n * size, max_size=n * size)),
                       dtype=np.float32).reshape(n, size)
        keep.append(arr)
        g.glEnableClientState(enable)
        set_pointer(g, arr)
        drawn = np.abs(arr[first:first + count].astype(np.float64))
        expect += bool(np.isnan(drawn).any() or (drawn >= 32768).any())
    quiet(g.glDrawArrays, C.GL_POINTS, first, count)
    rep = ctx.range_report()
    assert rep.counts["overflow"] == expect
    assert rep.counts["rule"] == 0


def test_float_array_in_a_buffer_is_refined_to_the_drawn_range() -> None:
    ident = np.eye(4).reshape(-1)
    verts = np.zeros((3, 2), np.float32)
    ctx, g = draw_setup("raise", ident, ident, verts)
    g.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    tex = np.array([[0, 0], [0, 0], [50000, 0]], np.float32)
    buf = g.glGenBuffers(1)
    g.glBindBuffer(C.GL_ARRAY_BUFFER, buf)
    g.glBufferData(C.GL_ARRAY_BUFFER, tex.nbytes, tex, C.GL_STATIC_DRAW)
    g.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    g.glTexCoordPointer(2, C.GL_FLOAT, 0, 0)
    g.glDrawArrays(C.GL_POINTS, 0, 2)           # the whole buffer's bound is 50000; the drawn range is fine
    with pytest.raises(RangeError, match=r"\(glTexCoordPointer, unit 0\) holds \|x\| = 50000"):
        g.glDrawArrays(C.GL_POINTS, 1, 2)
    assert ctx.range_report().counts == {"overflow": 1, "underflow": 0, "rule": 0}
