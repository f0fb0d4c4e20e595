"""The depth buffer: clear values, the eight depth functions, the depth mask,
depth interpolation and glDepthRangef (ES 1.1 §2.11.1, §3.5.1, §4.1.5, §4.2.3).

Under the 1:1 ortho setup (glOrthof(0, w, 0, h, -1, 1)) an object z maps to
window depth d = (1 - z) / 2, stored as an integer near d * (2^bits - 1).
Expected values come from that formula evaluated in numpy; tolerances come
from ``depth_tolerance`` below, which derives each build's bound.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from conftest import BUILDS, clear, draw_arrays, make_ctx, read_rgba, set_frustum, set_ortho
from hypothesis import given, settings
from hypothesis import strategies as st

from gles import constants as C

W = H = 32

# (build, bits, projection) -> largest |stored - exact| seen, in depth units
MEASURED: dict[str, float] = {}


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    print("\ndepth max errors (units):", {k: round(v, 4) for k, v in sorted(MEASURED.items())})


def depth_tolerance(numeric: str, bits: int, persp: bool = False) -> float:
    """Largest |stored - exact| for an interpolated depth, in depth units.

    Z = 2^bits - 1. Every build ends with a rounding to an integer: 1/2.

    fixed: per-vertex depth keeps 16 fraction bits (error 2^-16) and loses 12
    of them before interpolating (< 2^-4); the linear weights are 0.30 values
    rounded from exact edge values through a truncated 2^61 / area reciprocal
    (w1, w2 within 1.5 * 2^-30, w0 = 1 - w1 - w2), so the interpolation
    z0 + (z1 - z0) w1 + (z2 - z0) w2 is off by at most 3 * 2^-30 * Z; the
    0.30 window depth truncates once (2^-30 * Z) and, with a perspective w,
    z/w rounds once more (2^-31 * Z).

    float (24-bit significand, u = 2^-24): a value below 2^bits is rounded
    to within h = 2^(bits - 25) (half an ulp). Per vertex d * Z rounds once
    (h); with a perspective w, z/w and z/w + 1 round too (u * Z together,
    halved by the / 2 and doubled back by the bound on z/w + 1). The weights
    e_i * (1 / area) carry 4u relative error (area and e_i converted to
    float, the reciprocal, the product) and w0 = 1 - w1 - w2 adds u, so the
    weights move the result by at most 5u * Z; the three products and two
    sums each round (5h). For 24 bits this is 0.5 + 6 * 0.5 + 5 (+ 1)
    = 8.5 units (9.5 in perspective); for 16 bits it stays below 0.54.

    double: as float with u = 2^-53: 0.5 plus far less than 10^-6.
    """
    Z = 2**bits - 1
    if numeric == "fixed":
        tol = 0.5 + 2.0**-16 + 2.0**-4 + 3 * Z * 2.0**-30 + Z * 2.0**-30
        return tol + (Z * 2.0**-31 if persp else 0.0)
    sig = 24 if numeric == "float" else 53
    u = 2.0**-sig
    h = 2.0 ** (bits - sig - 1)
    return 0.5 + 6 * h + 5 * u * Z + (u * Z if persp else 0.0)


def record(key: str, value: float) -> None:
    MEASURED[key] = max(value, MEASURED.get(key, 0.0))


def rect(x0: float, x1: float, y0: float, y1: float, z: float) -> np.ndarray:
    """Two triangles covering [x0, x1] x [y0, y1] at object depth z."""
    return np.array([(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y0, z), (x1, y1, z), (x0, y1, z)],
                    dtype=np.float32)


def nearest_ints(v: Fraction) -> set[int]:
    """The integers nearest to v (two of them when v is halfway: the spec
    does not fix the direction of a tie)."""
    return {math.floor(v + Fraction(1, 2)), math.ceil(v - Fraction(1, 2))}


# {================================================================
# clear


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("bits", [16, 24])
@pytest.mark.parametrize("value", [0.0, 0.5, 1.0, 0.2, 1 / 3, -0.5, 2.0])
def test_clear_depth_values(numeric, bits, value):
    """glClearDepthf(d) fills the buffer with d clamped to [0, 1], times 2^bits - 1,
    rounded to nearest (§2.11.1, §4.2.3)."""
    ctx = make_ctx(numeric, 8, 8, depth=bits)
    ctx.gl.glClearDepthf(value)
    ctx.gl.glClear(C.GL_DEPTH_BUFFER_BIT)
    d = min(max(Fraction(value), Fraction(0)), Fraction(1))
    buf = ctx.depth_buffer()
    assert buf is not None and buf.shape == (8, 8)
    got = {int(v) for v in np.unique(buf)}
    assert len(got) == 1 and got <= nearest_ints(d * (2**bits - 1)), (got, float(d))


@pytest.mark.parametrize("numeric", BUILDS)
def test_clear_depth_respects_mask_and_scissor(numeric):
    """The depth clear writes nothing with the depth mask off, and only inside
    the scissor box with the scissor test on (§4.2.3)."""
    ctx = make_ctx(numeric, 8, 8, depth=16)
    gl = ctx.gl
    gl.glClearDepthf(0.0)
    gl.glClear(C.GL_DEPTH_BUFFER_BIT)
    gl.glDepthMask(False)
    gl.glClearDepthf(1.0)
    gl.glClear(C.GL_DEPTH_BUFFER_BIT)
    assert (ctx.depth_buffer() == 0).all()
    gl.glDepthMask(True)
    gl.glEnable(C.GL_SCISSOR_TEST)
    gl.glScissor(2, 3, 4, 2)
    gl.glClear(C.GL_DEPTH_BUFFER_BIT)
    want = np.zeros((8, 8), dtype=np.uint32)
    want[3:5, 2:6] = 65535
    np.testing.assert_array_equal(ctx.depth_buffer(), want)


# {================================================================
# the depth functions

FUNCS = {
    "NEVER": lambda a, b: np.zeros_like(a, dtype=bool),
    "LESS": np.less,
    "EQUAL": np.equal,
    "LEQUAL": np.less_equal,
    "GREATER": np.greater,
    "NOTEQUAL": np.not_equal,
    "GEQUAL": np.greater_equal,
    "ALWAYS": lambda a, b: np.ones_like(a, dtype=bool),
}
RED, GREEN, BLUE = (255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255)
# object z -> window depth (1 - z) / 2: A at 0.25; B nearer (0.125), level
# with A (0.25, drawn with A's own vertices so every fragment computes the
# same value) or farther (0.75); the clear value 0.5 lies between, so B is
# compared against both sides of it
Z_A = 0.5
Z_B = {"nearer": 0.75, "level": 0.5, "farther": -0.5}
CLEAR_D = 0.5


def two_quads(numeric, bits, func, relation, depth_mask=True, depth_test=True):
    """Quad A (red, columns 4..19) drawn with ALWAYS, then quad B (green,
    columns 12..27, or A's own rectangle when level) with `func`; rows 4..27.
    Returns the image, the depth buffer and the exact window depths (real)."""
    ctx = make_ctx(numeric, W, H, depth=bits)
    gl = ctx.gl
    clear(ctx, (0.0, 0.0, 1.0, 1.0), depth=CLEAR_D)
    set_ortho(gl, W, H)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_ALWAYS)
    gl.glColor4ub(*RED)
    draw_arrays(gl, rect(4, 20, 4, 28, Z_A))
    (gl.glEnable if depth_test else gl.glDisable)(C.GL_DEPTH_TEST)
    gl.glDepthFunc(getattr(C, "GL_" + func))
    gl.glDepthMask(depth_mask)
    gl.glColor4ub(*GREEN)
    zb = Z_B[relation]
    draw_arrays(gl, rect(4, 20, 4, 28, zb) if relation == "level" else rect(12, 28, 4, 28, zb))
    Z = 2**bits - 1
    return read_rgba(ctx), ctx.depth_buffer(), ((1 - Z_A) / 2 * Z, (1 - zb) / 2 * Z, CLEAR_D * Z)


def regions(relation):
    """Boolean masks (h, w) of the pixels of quad A and quad B."""
    a = np.zeros((H, W), dtype=bool)
    a[4:28, 4:20] = True
    b = a.copy() if relation == "level" else np.zeros((H, W), dtype=bool)
    if relation != "level":
        b[4:28, 12:28] = True
    return a, b


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("bits", [16, 24])
@pytest.mark.parametrize("func", sorted(FUNCS))
@pytest.mark.parametrize("relation", sorted(Z_B))
def test_depth_functions(numeric, bits, func, relation):
    """Each of the eight functions decides per pixel, against what A or the clear
    left there, whether B's colour and depth are written (§4.1.5)."""
    img, dep, (da, db, dc) = two_quads(numeric, bits, func, relation)
    in_a, in_b = regions(relation)
    stored = np.where(in_a, da, dc)  # exact depth before B is drawn
    passed = in_b & FUNCS[func](np.full((H, W), db), stored)
    want_img = np.zeros((H, W, 4), dtype=np.uint8)
    want_img[:] = BLUE
    want_img[in_a] = RED
    want_img[passed] = GREEN
    np.testing.assert_array_equal(img, want_img)
    want_dep = np.where(passed, db, stored)
    tol = depth_tolerance(numeric, bits)
    err = np.abs(dep.astype(np.float64) - want_dep)
    # the clear value is rounded only once (the clear test covers its ties)
    assert err[in_a | in_b].max() <= tol
    assert err[~(in_a | in_b)].max() <= 0.5
    record(f"{numeric} {bits}-bit constant", float(err[in_a | in_b].max()))


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("bits", [16, 24])
def test_depth_mask_off_keeps_the_buffer(numeric, bits):
    """With the depth mask off, fragments that pass still colour the pixel but the
    depth buffer keeps its values; with the test disabled nothing is written
    to the depth buffer either (§4.1.5, §4.2.2)."""
    img, dep, (da, db, dc) = two_quads(numeric, bits, "LESS", "nearer", depth_mask=False)
    in_a, in_b = regions("nearer")
    assert (img[in_b] == GREEN).all()  # B is nearer than A and than the clear value
    ref = two_quads(numeric, bits, "NEVER", "nearer")[1]  # the buffer with A alone
    np.testing.assert_array_equal(dep, ref)
    img, dep, _ = two_quads(numeric, bits, "LESS", "farther", depth_test=False)
    assert (img[in_b] == GREEN).all()  # no test: B is drawn over everything
    np.testing.assert_array_equal(dep, ref)


# {================================================================
# interpolation: the plane through the vertices, in window space


def window_plane(win: np.ndarray, depth: np.ndarray) -> np.ndarray:
    """Depth at every pixel centre of the plane through (x_i, y_i, depth_i)."""
    px = (np.arange(W) + 0.5)[None, :]
    py = (np.arange(H) + 0.5)[:, None]
    (x0, y0), (x1, y1), (x2, y2) = win
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    l1 = ((px - x0) * (y2 - y0) - (x2 - x0) * (py - y0)) / area
    l2 = ((x1 - x0) * (py - y0) - (px - x0) * (y1 - y0)) / area
    return depth[0] + (depth[1] - depth[0]) * l1 + (depth[2] - depth[0]) * l2


def check_plane(numeric, bits, persp, obj, win, dwin):
    """Draw `obj`, then compare the stored depth of every covered pixel with the
    plane through the window vertices (`win`, depths `dwin` in [0, 1])."""
    Z = 2**bits - 1
    ctx = make_ctx(numeric, W, H, depth=bits)
    gl = ctx.gl
    clear(ctx, depth=1.0)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glColor4ub(255, 255, 255, 255)
    (set_frustum if persp else set_ortho)(gl, W, H)
    draw_arrays(gl, obj)
    covered = read_rgba(ctx).any(axis=2)
    if not covered.any():
        return
    want = window_plane(win, np.asarray(dwin) * Z)
    err = np.abs(ctx.depth_buffer().astype(np.float64) - want)[covered]
    record(f"{numeric} {bits}-bit {'perspective' if persp else 'ortho'}", float(err.max()))
    assert err.max() <= depth_tolerance(numeric, bits, persp), err.max()


grid256 = st.integers(1 * 256, (W - 1) * 256).map(lambda v: v / 256)
zs = st.integers(-3900, 3900).map(lambda v: v / 4096)  # within (-0.96, 0.96)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("bits", [16, 24])
@settings(max_examples=40, deadline=None)
@given(xy=st.lists(st.tuples(grid256, grid256), min_size=3, max_size=3),
       z=st.lists(zs, min_size=3, max_size=3))
def test_depth_is_the_window_plane_ortho(numeric, bits, xy, z):
    """A tilted triangle's depth at each covered pixel is the plane through its
    vertices evaluated at the pixel centre, within the derived tolerance."""
    win = np.array(xy, dtype=np.float64)
    obj = np.column_stack([win, z]).astype(np.float32)
    check_plane(numeric, bits, False, obj, win, [(1 - v) / 2 for v in z])


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("bits", [16, 24])
@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_depth_is_the_window_plane_perspective(numeric, bits, seed):
    """Under glFrustumf(-1, 1, -1, 1, 1, 3) depth is still linear in window
    space: per-vertex z_c / w_c = (-2 z_e - 3) / -z_e, mapped to [0, 1] and
    interpolated with the window-space plane (§3.5.1)."""
    rng = np.random.default_rng(seed)
    ze = -np.round(rng.uniform(1.1, 2.9, size=3) * 256) / 256
    xy = np.round(rng.uniform(-0.95, 0.95, size=(3, 2)) * -ze[:, None] * 256) / 256
    obj = np.column_stack([xy, ze])
    # window x, y: exact on the 1/256 grid in every build (see test_raster.persp_window)
    win = np.round((W / 2) * (1 + xy / -ze[:, None]) * 256) / 256
    d = ((-2 * ze - 3) / -ze + 1) / 2
    check_plane(numeric, bits, True, obj, win, d)


# {================================================================
# glDepthRangef


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("bits", [16, 24])
@pytest.mark.parametrize("near, far", [(0.0, 1.0), (0.25, 0.75), (1.0, 0.0), (0.125, 0.625), (0.5, 0.5)])
def test_depth_range(numeric, bits, near, far):
    """Window depth is n + (f - n) * (z_ndc + 1) / 2 (§2.11.1), also for a
    reversed or empty range; here z_ndc = -z_object."""
    Z = 2**bits - 1
    tol = depth_tolerance(numeric, bits)
    for z in (-0.5, 0.0, 0.75):
        ctx = make_ctx(numeric, 8, 8, depth=bits)
        gl = ctx.gl
        clear(ctx, depth=1.0)
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDepthFunc(C.GL_ALWAYS)
        gl.glDepthRangef(near, far)
        set_ortho(gl, 8, 8)
        draw_arrays(gl, rect(0, 8, 0, 8, z))
        want = (near + (far - near) * (1 - z) / 2) * Z
        err = np.abs(ctx.depth_buffer().astype(np.float64) - want).max()
        record(f"{numeric} {bits}-bit depth range", float(err))
        assert err <= tol, (near, far, z, err)


@pytest.mark.parametrize("numeric", BUILDS)
def test_depth_range_is_clamped(numeric):
    """glDepthRangef clamps both values to [0, 1] (§2.11.1)."""
    ctx = make_ctx(numeric, 8, 8, depth=16)
    ctx.gl.glDepthRangef(-1.0, 2.0)
    np.testing.assert_array_equal(ctx.gl.glGetFloatv(C.GL_DEPTH_RANGE), [0.0, 1.0])
    clear(ctx, depth=0.5)
    ctx.gl.glEnable(C.GL_DEPTH_TEST)
    ctx.gl.glDepthFunc(C.GL_ALWAYS)
    set_ortho(ctx.gl, 8, 8)
    draw_arrays(ctx.gl, rect(0, 8, 0, 8, -1.0))  # the far plane: depth f = 1
    assert (ctx.depth_buffer() == 65535).all()
