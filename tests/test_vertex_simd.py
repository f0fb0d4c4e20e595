"""The vertex batch's AVX2 kernels (csrc/vertex_avx2.h) against the scalar code and exact arithmetic.

Where the CPU has AVX2, the fixed build's vertex batch runs AVX2 kernels for
the matrix rows and normal products (num_dot4_lanes, num_dot3_lanes), the
FLOAT array conversion (num_from_float), GL_NORMALIZE (num_normalize3), a
directional light's term, and the range check's scan of FLOAT arrays (every
build); ``ctx.debug(16)``
runs the scalar code. ``gles_debug_vertex_lanes`` calls either on given
lanes, so the kernels are compared directly, on random inputs and on the
edges where an exact scheme could slip: INT32_MIN and INT32_MAX everywhere,
sums at the saturation limits and beyond 64 bits, rounding ties and their
neighbours, NaN, infinities, huge and denormal floats. The expected values
come from Python's exact integers and IEEE doubles (the rules of
docs/numerics.md), not from the core. The image tests render lit scenes
with both instances (and the per-vertex reference) and require identical
pixels. Without AVX2 both calls run the scalar code and the comparisons
still check it against the exact arithmetic.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, make_ctx
from test_lod_simd import fx_log2, fx_table
from test_vertex_batch import _render

from gles import constants as C

I32_MIN, I32_MAX = -(2**31), 2**31 - 1
EDGES = np.array([I32_MIN, I32_MIN + 1, I32_MAX, I32_MAX - 1, 0, 1, -1, 2**15, -(2**15), 2**15 - 1,
                  -(2**15) + 1, 2**16, -(2**16), 2**16 + 1, 2**30, -(2**30), 0x12345678, -0x12345678],
                 np.int64)
BASELINE = 16  # GLES_DEBUG_BASELINE_SIMD
REFERENCE = 8  # GLES_DEBUG_VERTEX_REFERENCE
EXP2_TAB = np.array(fx_table("fx_exp2_tab"), np.int64)


@pytest.fixture(scope="module")
def core():
    """The fixed build's ffi and library (the hook works in that build)."""
    ctx = make_ctx("fixed", 1, 1)
    return ctx._ffi, ctx._lib


def _lanes(core, simd: int, kernel: int, n: int, m, data: np.ndarray) -> np.ndarray:
    """gles_debug_vertex_lanes: 256 outputs of `kernel` over n lanes."""
    ffi, lib = core
    mm = np.zeros(10, np.int32)
    mm[:len(m)] = np.asarray(m, np.int64).astype(np.int32)
    data = np.ascontiguousarray(data).view(np.int32)
    out = np.zeros(256, np.int32)
    ok = lib.gles_debug_vertex_lanes(simd, kernel, n, ffi.cast("int32_t *", mm.ctypes.data),
                                     ffi.cast("int32_t *", data.ctypes.data),
                                     ffi.cast("int32_t *", out.ctypes.data))
    assert ok == 1
    return out


def _both(core, kernel: int, n: int, m, data: np.ndarray) -> np.ndarray:
    """The kernel's result; the AVX2 and the scalar code must agree bit for bit."""
    vec = _lanes(core, 1, kernel, n, m, data)
    base = _lanes(core, 0, kernel, n, m, data)
    np.testing.assert_array_equal(vec, base, err_msg=f"kernel {kernel}, m {list(m)}")
    return vec


# {================================================================
# exact reference arithmetic (docs/numerics.md: one rounding, ties away from zero, saturation)

def _sat(v: int) -> int:
    return max(I32_MIN, min(I32_MAX, v))


def _round16(v: int) -> int:
    """v / 2^16 rounded to nearest, ties away from zero."""
    q = (abs(v) + 2**15) >> 16
    return q if v >= 0 else -q


def _mul(a: int, b: int) -> int:
    return _sat(_round16(a * b))


def _add(a: int, b: int) -> int:
    return _sat(a + b)


def _dot_expected(m, rows: np.ndarray, n: int, terms: int, w_one: bool) -> list[int]:
    """The exact sum of m[t] rows[t][i] (w = 1 when w_one) rounded once, per lane."""
    out = []
    for i in range(n):
        vals = [int(rows[t][i]) for t in range(terms)]
        if w_one:
            vals[3] = 65536
        acc = sum(int(m[t]) * vals[t] for t in range(terms))
        out.append(_sat(_round16(acc)))
    return out


def _from_float_expected(f: float) -> int:
    v = float(f) * 65536.0
    if math.isnan(v):
        return 0
    if v <= I32_MIN:
        return I32_MIN
    if v >= I32_MAX:
        return I32_MAX
    return math.floor(v + 0.5)


# {================================================================
# dot products of lanes

def _dot_cases(rng: np.random.Generator, terms: int):
    """(coefficients, rows (4, 64)) for sums of `terms` products, covering random,
    edge, tie and saturation inputs."""
    for _ in range(60):                                   # the whole int32 range
        yield rng.integers(I32_MIN, I32_MAX + 1, 4), rng.integers(I32_MIN, I32_MAX + 1, (4, 64))
    for _ in range(60):                                   # edge values only
        yield rng.choice(EDGES, 4), rng.choice(EDGES, (4, 64))
    for _ in range(30):                                   # zero coefficients (skipped terms)
        m = rng.integers(-(2**20), 2**20, 4)
        m[rng.random(4) < 0.5] = 0
        yield m, rng.integers(-(2**24), 2**24, (4, 64))
    last = terms - 1
    for _ in range(60):                                   # ties and their neighbours, both signs
        m = rng.integers(-(2**18), 2**18, 4)
        m[last] = 1
        rows = rng.integers(-(2**22), 2**22, (4, 64))
        for i in range(64):
            s = sum(int(m[t]) * int(rows[t][i]) for t in range(last))
            target = 2**15 + int(rng.integers(-1, 2))
            rows[last][i] = target - s % 2**16 + 2**16 * int(rng.integers(-(2**10), 2**10))
        yield m, rows
    # the saturation edge: x + y / 2^16 around INT32_MAX + 1/2 and INT32_MIN - 1/2
    ys = [2**15 - 1, 2**15, 2**15 + 1, -(2**15) - 1, -(2**15), -(2**15) + 1, 0, 2**16, -(2**16)]
    for x in (I32_MAX, I32_MAX - 1, I32_MIN, I32_MIN + 1):
        rows = np.zeros((4, 64), np.int64)
        rows[0, :] = x
        rows[1, :len(ys)] = ys
        yield np.array([65536, 1, 0, 0]), rows
    # sums beyond 64 bits and around +-2^63
    big = np.array([I32_MIN, I32_MIN, I32_MIN, I32_MIN])
    yield big, np.full((4, 64), I32_MIN)
    yield big, np.full((4, 64), I32_MAX)
    rows = rng.choice([I32_MIN, I32_MAX, I32_MIN + 1, -(2**30), 2**30], (4, 64))
    yield big, rows
    yield np.array([I32_MAX, I32_MAX, I32_MIN, I32_MAX]), rows


def test_dot4_lanes_exact(core):
    """num_dot4_lanes: AVX2 = scalar = the exact sum rounded once, with and without w = 1."""
    pick = np.random.default_rng(7)
    for m, rows in _dot_cases(np.random.default_rng(1304), 4):
        for w_one in (0, 1):
            n = 64 if pick.random() < 0.5 else 8 * int(pick.integers(1, 8))
            data = np.ascontiguousarray(rows.reshape(-1), np.int64).astype(np.int32)
            got = _both(core, 0, n, [*m, w_one], data)
            want = _dot_expected(m, rows, n, 4, bool(w_one))
            assert got[:n].tolist() == want, f"m {m.tolist()} w_one {w_one}"


def test_dot3_lanes_exact(core):
    """num_dot3_lanes: AVX2 = scalar = the exact sum rounded once."""
    for m, rows in _dot_cases(np.random.default_rng(1303), 3):
        data = np.ascontiguousarray(rows.reshape(-1), np.int64).astype(np.int32)
        got = _both(core, 1, 64, m[:3], data)
        assert got[:64].tolist() == _dot_expected(m, rows, 64, 3, False), f"m {m.tolist()}"


def test_dot_cases_reach_the_edges():
    """The cases of both tests include rounding ties of both signs, both saturations
    and sums beyond 64 bits."""
    for terms in (3, 4):
        _check_reach(terms)


def _check_reach(terms: int) -> None:
    rng = np.random.default_rng(1300 + terms)
    ties = {1: 0, -1: 0}
    sat = set()
    for m, rows in _dot_cases(rng, terms):
        for i in range(64):
            acc = sum(int(m[t]) * int(rows[t][i]) for t in range(terms))
            if acc % 2**16 == 2**15:
                ties[1 if acc > 0 else -1] += 1
            r = _round16(acc)
            if r > I32_MAX:
                sat.add("max")
            if r < I32_MIN:
                sat.add("min")
            if abs(acc) >= 2**63:
                sat.add("beyond int64")
    assert ties[1] > 100 and ties[-1] > 100
    assert sat == {"max", "min", "beyond int64"}


# {================================================================
# FLOAT arrays to 16.16

SPECIAL_FLOATS = np.array([np.nan, -np.nan, np.inf, -np.inf, 0.0, -0.0, 3.4e38, -3.4e38, 1e-40, -1e-40,
                           1.4e-45, 32768.0, -32768.0, 32767.998, -32767.998, 32767.99998, -32768.00001,
                           65536.0, -65536.0, 0.5 / 65536, -0.5 / 65536, 1.5 / 65536, -1.5 / 65536,
                           2.5 / 65536, -2.5 / 65536, 1.0, -1.0], np.float32)


def _float_values(rng: np.random.Generator, count: int) -> np.ndarray:
    kind = rng.integers(4)
    if kind == 0:   # every magnitude, both signs
        v = rng.standard_normal(count) * 10.0 ** rng.uniform(-45, 39, count)
    elif kind == 1:
        v = rng.choice(SPECIAL_FLOATS, count)
    elif kind == 2:  # ties: k + 1/2 units of 2^-16, and their float neighbours
        v = (rng.integers(-(2**23), 2**23, count) + 0.5) / 65536
        f = v.astype(np.float32)
        nudge = rng.integers(-1, 2, count)
        toward = np.where(nudge > 0, np.float32(np.inf), np.float32(-np.inf))
        return np.where(nudge == 0, f, np.nextafter(f, toward)).astype(np.float32)
    else:            # around the limits of 16.16
        v = rng.choice([32768.0, -32768.0], count) + rng.uniform(-0.01, 0.01, count)
    with np.errstate(over="ignore"):
        return v.astype(np.float32)


@pytest.mark.parametrize("size", [1, 2, 3, 4])
def test_float_fetch_exact(core, size):
    """The FLOAT fetch: AVX2 = scalar = floor(65536 f + 1/2) in double, NaN 0, clamped;
    packed and strided elements, in and out of order, reading nothing past the last."""
    rng = np.random.default_rng(1303 + size)
    for _ in range(150):
        n = 8 * int(rng.integers(1, 9))
        stride = size + int(rng.integers(0, 3))
        # the array ends with the last element's last component
        vals = _float_values(rng, n * stride)[:(n - 1) * stride + size]
        reverse = int(rng.integers(2))
        got = _both(core, 2, n, [size, stride, reverse], np.ascontiguousarray(vals))
        for i in range(n):
            v = n - 1 - i if reverse else i
            for c in range(size):
                f = vals[v * stride + c]
                assert got[64 * c + i] == _from_float_expected(f), f"f = {f!r}"


# {================================================================
# a directional light's term

def _term_expected(m, d: int, col: int, acc: int) -> int:
    if m[9]:
        amb, dif = _mul(col, m[2]), _mul(col, m[3])
    else:
        amb, dif = int(m[0]), int(m[1])
    term = amb
    if d > 0:
        term = _add(term, _mul(d, dif))
    return _add(acc, _mul(int(m[4]), term))


def test_directional_term_exact(core):
    """A directional light's term: AVX2 = scalar; without specular also = the exact
    num_mul / num_add sequence; operands over the whole int32 range and at the edges."""
    rng = np.random.default_rng(1304)
    for trial in range(400):
        wide = trial % 3 == 0
        if trial % 5 == 1:
            m = rng.choice(EDGES, 10)
            data = rng.choice(EDGES, 256)
        elif wide:
            m = rng.integers(I32_MIN, I32_MAX + 1, 10)
            data = rng.integers(I32_MIN, I32_MAX + 1, 256)
        else:
            m = rng.integers(0, 2**17, 10)
            data = rng.integers(-(2**17), 2**17, 256)
        m[5] = rng.integers(0, 128 * 65536 + 1)          # shininess
        if not wide:
            data[192:] = rng.integers(-(2**16), 2**16 + 1, 64)   # n . h, mostly in pow's domain
        m[7] = rng.integers(2)
        m[9] = rng.integers(2)
        n = 8 * int(rng.integers(1, 9))
        got = _both(core, 3, n, m, data.astype(np.int32))
        if not m[7]:
            want = [_term_expected(m, int(data[i]), int(data[64 + i]), int(data[128 + i])) for i in range(n)]
            assert got[:n].tolist() == want, f"m {m.tolist()}"


# {================================================================
# GL_NORMALIZE

def _normalize_expected(v: list[int]) -> list[int]:
    """num_normalize3 (docs/numerics.md: divide by the largest component's power of two,
    one exact sum of squares, rsqrt by an integer square root) in Python integers."""
    m = max(min(abs(c), I32_MAX) for c in v)
    if m == 0:
        return v
    sh = m.bit_length() - 16
    w = [(abs(c) >> sh) * (1 if c >= 0 else -1) if sh >= 0 else c << -sh for c in v]
    a = (sum(c * c for c in w) + 2**15) >> 16
    inv = (math.isqrt(2**62 // a) + 64) >> 7
    return [_sat(_round16(c * inv)) for c in w]


def _normal_cases(rng: np.random.Generator):
    for _ in range(40):                     # every magnitude
        scale = 2.0 ** rng.uniform(-16, 31, (3, 64))
        yield np.clip(rng.standard_normal((3, 64)) * scale, I32_MIN, I32_MAX).astype(np.int64)
    for _ in range(20):
        yield rng.choice(EDGES, (3, 64))
    for _ in range(20):                     # axis-aligned and unit vectors (exact square roots)
        rows = np.zeros((3, 64), np.int64)
        axis = rng.integers(0, 3, 64)
        rows[axis, np.arange(64)] = rng.choice([65536, -65536, 32768, 2**20, -(2**31), I32_MAX, 1, -1], 64)
        yield rows
    # zero vectors among others
    rows = rng.integers(-(2**17), 2**17, (3, 64))
    rows[:, ::3] = 0
    yield rows


def test_rsqrt_by_double_is_exact_on_the_normalize_domain():
    """The premise of the AVX2 normalisation: for every a the kernel can meet
    (2^14 <= a <= 3 2^16), floor(2^31 / sqrt(a)) with IEEE double sqrt and division
    (correctly rounded, as vsqrtpd and vdivpd) is the integer root isqrt(2^62 // a)."""
    a = np.arange(2**14, 3 * 2**16 + 1)
    approx = np.floor(2.0**31 / np.sqrt(a.astype(np.float64))).astype(np.int64)
    exact = np.array([math.isqrt(2**62 // int(x)) for x in a.tolist()], np.int64)
    assert np.array_equal(approx, exact)


def test_normalize_exact(core):
    """num_normalize3 over lanes: AVX2 = scalar = the integer algorithm, for zero, tiny,
    huge, axis-aligned and INT32_MIN components."""
    for rows in _normal_cases(np.random.default_rng(1307)):
        got = _both(core, 5, 64, [], np.ascontiguousarray(rows.reshape(-1)).astype(np.int32))
        for i in range(64):
            want = _normalize_expected([int(rows[k][i]) for k in range(3)])
            assert [int(got[64 * k + i]) for k in range(3)] == want, rows[:, i].tolist()


# {================================================================
# the specular and spot power

def _pow_expected(x: np.ndarray, s: int) -> np.ndarray:
    """num_pow (fixed) of int64 lanes x in integers: fx_log2, (l s) / 65536 truncated
    toward zero, fx_exp2."""
    x = np.asarray(x, np.int64)
    if s == 0:
        return np.full_like(x, 65536)
    pos = x > 0
    lg = [fx_log2(int(v)) if v > 0 else 0 for v in x.tolist()]
    p = np.array([abs(v * s) // 65536 * (1 if v * s >= 0 else -1) for v in lg], np.int64)
    v = np.where(pos, _exp2_expected(p), 0)
    return np.where(x == 65536, 65536, v)


def test_pow_exact(core):
    """num_pow over lanes (the specular and spot powers): AVX2 = scalar = the integer
    algorithm, for bases over the whole int32 range, near 1.0 and tiny, and exponents
    at 0, one ulp, 1.0, 128 and just past the kernel's range (the scalar fallback);
    then 2^17 random cosines and exponents (the AVX2 kernel against the integers)."""
    rng = np.random.default_rng(1311)
    exps = [0, 1, 2, 65535, 65536, 65537, 128 * 65536 - 1, 128 * 65536, 129 * 65536, -1]
    exps += rng.integers(0, 128 * 65536 + 1, 40).tolist() + rng.integers(0, 4 * 65536, 20).tolist()
    for trial, s in enumerate(exps):
        kind = trial % 4
        if kind == 0:
            x = rng.choice(EDGES, 64)
        elif kind == 1:
            x = rng.integers(I32_MIN, I32_MAX + 1, 64)
        elif kind == 2:
            x = rng.integers(-4, 65536 + 5, 64)      # cosines, and just past 1.0
        else:
            x = rng.integers(1, 2**12, 64)            # tiny bases: deep negative logarithms
        x[:4] = [65536, 65535, 1, I32_MAX]
        got = _both(core, 8, 64, [s], x.astype(np.int32))
        assert got[:64].tolist() == _pow_expected(x, int(s)).tolist(), f"s {s}"
    for _ in range(2048):
        s = int(rng.integers(1, 128 * 65536 + 1))
        x = rng.integers(1, 65536, 64)
        got = _lanes(core, 1, 8, 64, [s], x.astype(np.int32))
        assert got[:64].tolist() == _pow_expected(x, s).tolist(), f"s {s}"


def _exp2_expected(p: np.ndarray) -> np.ndarray:
    """fx_exp2 of int64 lanes p (0.30) in integers, as 16.16 saturated."""
    p = np.asarray(p, np.int64)
    pc = np.clip(p, -20 * 2**30, 15 * 2**30)
    ip = pc >> 30
    f = pc - ip * 2**30
    j = f >> 22
    xx = ((f & (2**22 - 1)) * 744261118) >> 30
    x2 = (xx * xx) >> 30
    x3 = (x2 * xx) >> 30
    e = 2**30 + xx + x2 // 2 + x3 // 6
    r = (EXP2_TAB[j] * e + 2**29) >> 30
    sh = 14 - ip
    rounded = (r + (np.int64(1) << np.maximum(sh - 1, 0))) >> np.maximum(sh, 0)
    v = np.minimum(np.where(sh <= 0, r, rounded), I32_MAX)
    return np.where(p >= 15 * 2**30, I32_MAX, np.where(p <= -20 * 2**30, 0, v))


def test_exp2_exact(core):
    """fx_exp2 over lanes: AVX2 = scalar = the integer algorithm at the saturations,
    at every integer exponent and its neighbours, and at exponents where one step of
    2^-30 changes the rounded result (found by search: a few in a million are)."""
    rng = np.random.default_rng(1312)
    edges = [15 * 2**30, 15 * 2**30 - 1, -20 * 2**30, -20 * 2**30 + 1, 2**61, -(2**61), 0, 1, -1]
    edges += [k * 2**30 + d for k in range(-20, 15) for d in (-1, 0, 1)]
    found = []
    while len(found) < 256:
        p = rng.integers(-20 * 2**30, 15 * 2**30, 1 << 20)
        found += p[_exp2_expected(p) != _exp2_expected(p - 1)].tolist()
    cases = np.array(edges + found + [v - 1 for v in found], np.int64)
    for i in range(0, len(cases), 64):
        y = np.zeros(64, np.int64)
        chunk = cases[i:i + 64]
        y[:len(chunk)] = chunk
        got = _both(core, 9, 64, [], y.view(np.int32))
        assert got[:64].tolist() == _exp2_expected(y).tolist()


# {================================================================
# the range check's scan

def test_range_scan_exact(core):
    """The largest |component| of a FLOAT array (packed or strided, any sub-range):
    AVX2 = scalar = numpy's maximum, infinity when a NaN or infinity is read."""
    rng = np.random.default_rng(1305)
    for _ in range(600):
        size = int(rng.integers(1, 5))
        stride = size + (0 if rng.random() < 0.5 else int(rng.integers(1, 3)))
        n = 8 * int(rng.integers(1, 9))
        vals = _float_values(rng, n * stride)
        if rng.random() < 0.5:
            vals = np.where(np.isfinite(vals), vals, np.float32(1.0)).astype(np.float32)
        lo = int(rng.integers(0, n))
        hi = int(rng.integers(lo - 1, n))
        got = _both(core, 4, n, [size, stride, lo, hi], np.ascontiguousarray(vals))[0:1].view(np.float32)[0]
        read = np.array([vals[v * stride + c] for v in range(lo, hi + 1) for c in range(size)], np.float32)
        if len(read) == 0:
            want = 0.0
        elif not np.isfinite(read).all():
            want = math.inf
        else:
            want = float(np.abs(read).max())
        assert float(got) == want, (size, stride, lo, hi)


# {================================================================
# whole images: the AVX2 instance, the scalar one and the per-vertex reference

def _box():
    """A subdivided unit cube: float vertices, unit normals, ushort triangle indices."""
    verts, normals, idx = [], [], []
    k = 4
    for axis in range(3):
        for sign in (-1.0, 1.0):
            base = len(verts)
            for a in range(k + 1):
                for b in range(k + 1):
                    p = [0.0, 0.0, 0.0]
                    p[axis] = 0.5 * sign
                    p[(axis + 1) % 3] = a / k - 0.5
                    p[(axis + 2) % 3] = b / k - 0.5
                    nrm = [0.0, 0.0, 0.0]
                    nrm[axis] = sign
                    verts.append(p)
                    normals.append(nrm)
            for a in range(k):
                for b in range(k):
                    i0 = base + a * (k + 1) + b
                    quad = [i0, i0 + k + 1, i0 + k + 2, i0, i0 + k + 2, i0 + 1]
                    idx += quad if sign > 0 else quad[::-1]
    return (np.array(verts, np.float32), np.array(normals, np.float32), np.array(idx, np.uint16))


def _city(numeric: str, flags: int, seed: int, two_sided: bool, spec: bool, cm: bool):
    """Boxes of random scale and colour under two directional lights, NORMALIZE (vertex_city's work)."""
    rng = np.random.default_rng(seed)
    ctx = make_ctx(numeric, 64, 64, depth=16)
    ctx.debug(flags)
    gl = ctx.gl
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glEnable(C.GL_CULL_FACE)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glFrustumf(-0.5, 0.5, -0.5, 0.5, 1.0, 40.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    verts, normals, idx = _box()
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glNormalPointer(C.GL_FLOAT, 0, normals)
    colors = rng.integers(0, 256, (len(verts), 4)).astype(np.uint8)
    if cm:
        gl.glEnable(C.GL_COLOR_MATERIAL)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_NORMALIZE)
    gl.glLightModelf(C.GL_LIGHT_MODEL_TWO_SIDE, float(two_sided))
    for light in (C.GL_LIGHT0, C.GL_LIGHT3):
        gl.glEnable(light)
        gl.glLightfv(light, C.GL_POSITION, [*rng.uniform(-1, 1, 3), 0.0])
        gl.glLightfv(light, C.GL_DIFFUSE, [*rng.uniform(0, 1.5, 3), 1.0])
        gl.glLightfv(light, C.GL_AMBIENT, [*rng.uniform(0, 0.3, 3), 1.0])
        gl.glLightfv(light, C.GL_SPECULAR, [*rng.uniform(0, 1, 3), 1.0])
    if spec:
        gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [*rng.uniform(0, 1, 3), 1.0])
        gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, float(rng.uniform(0, 128)))
    gl.glTranslatef(0.0, -1.0, -12.0)
    gl.glRotatef(float(rng.uniform(0, 360)), *rng.uniform(-1, 1, 3))
    for _ in range(12):
        gl.glPushMatrix()
        gl.glTranslatef(*rng.uniform(-4, 4, 3))
        gl.glScalef(*rng.uniform(0.3, 3.0, 3))
        gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT_AND_DIFFUSE, [*rng.uniform(0.2, 1, 3), 1.0])
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
        gl.glPopMatrix()
    assert gl.glGetError() == 0
    return ctx.color_buffer().copy(), ctx.depth_buffer().copy()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("seed", range(8))
def test_city_scene_identical(numeric, seed):
    """vertex_city's kind of scene: AVX2, scalar and per-vertex reference draw the same pixels."""
    two_sided, spec, cm = seed & 1, seed & 2, seed & 4
    col, dep = _city(numeric, 0, seed, bool(two_sided), bool(spec), bool(cm))
    assert (col[..., :3] != 0).any(axis=-1).sum() > 300, "the scene is not empty"
    for flags in (BASELINE, REFERENCE):
        col2, dep2 = _city(numeric, flags, seed, bool(two_sided), bool(spec), bool(cm))
        where = np.argwhere(col != col2)[:4].tolist()
        assert np.array_equal(col, col2), f"flags {flags}: colour differs at {where}"
        assert np.array_equal(dep, dep2), f"flags {flags}: depth differs"


@pytest.mark.parametrize("seed", range(40))
def test_random_scenes_identical(seed):
    """Random scenes in the fixed build: the AVX2 and the scalar instance draw the same pixels."""
    col, dep = _render("fixed", 5000 + seed)
    col2, dep2 = _render("fixed", 5000 + seed, BASELINE)
    assert np.array_equal(col, col2), f"colour differs at {np.argwhere(col != col2)[:4].tolist()}"
    assert np.array_equal(dep, dep2)


@pytest.mark.parametrize("numeric", BUILDS)
def test_range_events_identical(numeric):
    """The range checks report the same events from either scan: values past 16.16,
    NaN and infinity in FLOAT vertex and normal arrays, packed and interleaved."""
    reports = []
    for flags in (0, BASELINE):
        ctx = make_ctx(numeric, 16, 16, range_check="clamp")
        ctx.debug(flags)
        gl = ctx.gl
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_NORMAL_ARRAY)
        rng = np.random.default_rng(1306)
        for trial in range(24):
            n = int(rng.integers(3, 40))
            inter = np.zeros((n, 7), np.float32)
            inter[:, :3] = rng.uniform(-2, 2, (n, 3))
            inter[:, 4:] = rng.uniform(-1, 1, (n, 3))
            if trial % 3:
                inter[int(rng.integers(n)), int(rng.choice([0, 1, 2, 4, 5, 6]))] = rng.choice(
                    [np.nan, np.inf, -np.inf, 40000.0, -32768.0, 32767.0, 1e30])
            if trial % 2:
                gl.glVertexPointer(3, C.GL_FLOAT, 28, inter)
                gl.glNormalPointer(C.GL_FLOAT, 28, inter.reshape(-1)[4:])
            else:
                v, nrm = np.ascontiguousarray(inter[:, :3]), np.ascontiguousarray(inter[:, 4:])
                gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
                gl.glNormalPointer(C.GL_FLOAT, 0, nrm)
            gl.glDrawArrays(C.GL_TRIANGLES, int(rng.integers(0, 2)), n - 2)
        report = ctx.range_report()
        assert report.total > 0 and report.draws_breaking_rule > 0
        reports.append(repr(report))
    assert reports[0] == reports[1]


def test_simd_instance_is_used():
    """Where the CPU has AVX2 the fixed context runs a vector instance (so that the
    comparisons above compare two instances): the vertex kernels are AVX2's under
    either name."""
    ctx = make_ctx("fixed", 4, 4)
    assert ctx.simd in (("avx2", "avx512") if HAS_SIMD else ("baseline",))
