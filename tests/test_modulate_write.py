"""The fixed build's fused MODULATE + alpha test + RGBA8888 write against an integer model.

On AVX2 the chain runs a lone MODULATE unit, the alpha test and the RGBA8888
write (no blend, SRC_ALPHA/ONE_MINUS_SRC_ALPHA, or ONE/ONE) as one stage
(stage_modulate_write): eight fragments in float lanes, and where the float
value of a byte lies too near a rounding boundary to prove the byte, the
exact 0.30 chain for that fragment. ``gles_debug_modulate_write`` runs that
kernel on chosen inputs. The expected words here come from the 0.30 integer
formulas of the reference path (frag_lerp3f, frag_mul, frag_from_unorm,
frag_to_unorm and the blend), evaluated with Python integers: random
inputs, and inputs placed on the rounding ties of every channel and a few
units of 2^-30 beside them, where only the exact fallback can be right.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import HAS_SIMD, make_ctx, set_ortho

from gles import constants as C

ONE = 1 << 30
FUNCS = [C.GL_NEVER, C.GL_LESS, C.GL_EQUAL, C.GL_LEQUAL, C.GL_GREATER, C.GL_NOTEQUAL, C.GL_GEQUAL,
         C.GL_ALWAYS]

pytestmark = pytest.mark.skipif(not HAS_SIMD, reason="no AVX2 instance on this CPU")


def _clamp01(v: int) -> int:
    return min(max(v, 0), ONE)


def _to_unorm8(v: int) -> int:
    """frag_to_unorm(v, 255, 1/2): clamped, then (255 v + 2^29) >> 30."""
    return (_clamp01(v) * 255 + (1 << 29)) >> 30


def _compare(func: int, a: int, b: int) -> bool:
    return {C.GL_NEVER: False, C.GL_LESS: a < b, C.GL_EQUAL: a == b, C.GL_LEQUAL: a <= b,
            C.GL_GREATER: a > b, C.GL_NOTEQUAL: a != b, C.GL_GEQUAL: a >= b}.get(func, True)


BAYER_ROW0 = [0, 8, 2, 10]       # fragment_dither_threshold's matrix, row y = 0


def _pack565(v, x, dither) -> int:
    """fragment_channel of red, green, blue: frag_to_unorm with the dither
    threshold of column x, or the top bits (frag_to_msb)."""
    word = 0
    for val, bits, shift in zip(v, (5, 6, 5), (11, 5, 0)):
        top = (1 << bits) - 1
        if val <= 0:
            q = 0
        elif dither:
            t = (2 * BAYER_ROW0[x & 3] + 1) * ONE // 32
            q = top if val >= ONE else (val * top + t) >> 30
        else:
            q = min(val >> (30 - bits), top)
        word |= q << shift
    return word


def _frag_mul(a: int, b: int) -> int:
    """frag_mul: the 0.30 product rounded, (a b + 2^29) >> 30 (an arithmetic shift)."""
    return (a * b + (1 << 29)) >> 30


def _dot3(dot3: int, t0, c) -> list:
    """combine_block's DOT3 (scales 1) of the texel t0 and the colour c:
    4 sum(frag_mul(t0_i - 1/2, c_i - 1/2)) clamped in the rgb channels, and
    in alpha the same (DOT3_RGBA, dot3 = 2) or MODULATE's t0_a c_a."""
    d = _clamp01(4 * sum(_frag_mul(int(t0[i]) - ONE // 2, c[i] - ONE // 2) for i in range(3)))
    return [d, d, d, d if dot3 == 2 else _clamp01(_frag_mul(int(t0[3]), c[3]))]


def _model(smooth, rgb, kind, func, ref, col, p, ct, d, rgb565=0, dither=0, x=0, dot3=0, t0=None) -> int:
    """One fragment's word as the reference chain forms it (with dot3, a
    first unit's DOT3 of its texel t0 and the colour comes first)."""
    if smooth:
        c = []
        for i in range(4):
            acc = sum(col[k][i] * p[k] for k in range(3))
            v = (abs(acc) + (1 << 29)) >> 30                 # frag_lerp3f: half away from zero
            c.append(_clamp01(v if acc >= 0 else -v))
    else:
        c = [_clamp01(col[0][i]) for i in range(4)]
    if dot3:
        c = _dot3(dot3, t0, c)
    m = [(c[i] * ct[i] + (1 << 29)) >> 30 for i in range(4)]  # MODULATE, frag_mul
    if rgb:
        m[3] = c[3]
    if not _compare(func, _to_unorm8(m[3]), ref):
        return d
    if rgb565:
        cv = [_clamp01(v) for v in m]
        if kind == 0:
            return _pack565(m[:3], x, dither)
        sa = cv[3]
        dv = [(((((d >> sh) & top) << 31) // top) + 1) >> 1 for sh, top in ((11, 31), (5, 63), (0, 31))]
        out = [((cv[i] * sa + (1 << 29)) >> 30) + ((dv[i] * (ONE - sa) + (1 << 29)) >> 30) for i in range(3)]
        return _pack565(out, x, dither)
    x = [_clamp01(v) for v in m]
    dst = [(d >> (8 * i)) & 0xFF for i in range(4)]
    dv = [(16843009 * b + 2) >> 2 for b in dst]              # frag_from_unorm(b, 255)
    if kind == 0:
        out = x
    elif kind == 2:
        out = [x[i] + dv[i] for i in range(4)]
    else:
        sa = x[3]
        out = [((x[i] * sa + (1 << 29)) >> 30) + ((dv[i] * (ONE - sa) + (1 << 29)) >> 30) for i in range(4)]
    return sum(_to_unorm8(v) << (8 * i) for i, v in enumerate(out))


def _run(smooth, rgb, kind, func, ref, col, p, ct, dst, k, rgb565=0, dither=0, x0=0, pad=0, dot3=0, t0=None):
    """The kernel's words at offsets k of dst, and its count of exact lanes."""
    ctx = make_ctx("fixed", 1, 1)
    ffi, lib = ctx._ffi, ctx._lib
    n = len(k)
    p = np.ascontiguousarray(p, dtype=np.int32).reshape(-1)
    ct = np.ascontiguousarray(ct, dtype=np.int64).reshape(-1)
    t0 = np.ascontiguousarray(ct if t0 is None else t0, dtype=np.int64).reshape(-1)
    assert t0.size >= 4 * n
    k = np.ascontiguousarray(k, dtype=np.uint8)
    out = np.array(dst, dtype=np.uint16 if rgb565 else np.uint32)
    exact = lib.gles_debug_modulate_write(
        smooth, rgb, kind, func, ref, [int(v) for v in np.ravel(col)], n,
        ffi.cast("uint8_t *", k.ctypes.data), ffi.cast("int32_t *", p.ctypes.data), dot3,
        ffi.cast("int64_t *", t0.ctypes.data), ffi.cast("int64_t *", ct.ctypes.data), pad, rgb565, dither, x0,
        ffi.cast("void *", out.ctypes.data))
    assert exact >= 0
    return out, exact


def _expect(smooth, rgb, kind, func, ref, col, p, ct, dst, k, rgb565=0, dither=0, x0=0, dot3=0, t0=None):
    out = np.array(dst, dtype=np.uint16 if rgb565 else np.uint32)
    for j, off in enumerate(k):
        pj = p[j] if smooth else None
        x = x0 + int(off)
        t0j = None if t0 is None else t0[j]
        out[off] = _model(smooth, rgb, kind, func, ref, col, pj, ct[j], int(dst[off]), rgb565, dither, x,
                          dot3, t0j)
    return out


def _texels(rng, n):
    """0.30 texels as the samplers give them: frag_from_unorm of bytes,
    bilinear blends of them, and the extremes."""
    t = rng.integers(0, 256, (n, 4)) * 16843009 // 4
    t[: n // 2] = rng.integers(0, ONE + 1, (n // 2, 4))
    t[: min(n, 4)] = [0, ONE, ONE // 2, ONE - 1]
    return t


def _weights(rng, n):
    """Barycentric weights (0.30) of points in the triangle, summing to 1,
    and a few just outside (slightly negative)."""
    w = rng.integers(0, ONE + 1, (n, 2))
    w = np.sort(w, axis=1)
    p = np.stack([w[:, 0], w[:, 1] - w[:, 0], ONE - w[:, 1]], axis=1)
    p[: n // 8, 0] -= rng.integers(0, 1 << 12, n // 8)
    p[: n // 8, 1] += rng.integers(0, 1 << 12, n // 8)
    return p


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
@pytest.mark.parametrize("rgb", [0, 1], ids=["rgba", "rgb"])
@pytest.mark.parametrize("smooth", [0, 1], ids=["flat", "smooth"])
def test_random_inputs_match_the_integer_model(smooth, rgb, kind):
    rng = np.random.default_rng(100 + 6 * smooth + 3 * rgb + kind)
    lanes = exact_total = 0
    for trial in range(24):
        n = int(rng.integers(1, 65))
        col = rng.integers(0, ONE + 1, (3, 4))
        if not smooth and trial % 4 == 0:
            col = rng.integers(-ONE, 2 * ONE, (3, 4))       # a flat colour is clamped first
        p = _weights(rng, n)
        ct = _texels(rng, n)
        dst = rng.integers(0, 1 << 32, 80, dtype=np.uint64).astype(np.uint32)
        # adjacent offsets (one vector load), or gaps (gathers)
        k = np.arange(n) if trial % 2 else np.sort(rng.choice(80, n, replace=False))
        func = FUNCS[trial % len(FUNCS)] if trial % 3 else C.GL_ALWAYS
        ref = int(rng.integers(0, 256))
        out, exact = _run(smooth, rgb, kind, func, ref, col, p, ct, dst, k)
        np.testing.assert_array_equal(out, _expect(smooth, rgb, kind, func, ref, col, p, ct, dst, k))
        lanes += n - n % 8
        exact_total += exact - n % 8
    # the filter proves nearly every byte: each channel's margin is 2^-9 of
    # a step either side of a boundary, about 0.4% of values
    assert exact_total <= 0.05 * lanes


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
def test_rounding_ties_and_their_neighbours(kind):
    """Products at the ties of the final rounding: with a texel of 1, the
    flat colour c passes MODULATE unchanged, so a channel's byte is
    floor(255 c / 2^30 + 1/2), tied where 255 c = (b + 1/2) 2^30; c is put
    there and up to 40 units of 2^-30 either side, in every channel, with
    and without blending (kind 1 blends with a stored alpha that makes the
    destination term vanish or not)."""
    rng = np.random.default_rng(7 + kind)
    total = 0
    for b in list(range(0, 255, 7)) + [254]:
        tie = ((2 * b + 1) * ONE + 509) // 510                # the least c with 255 c >= (b + 1/2) 2^30
        for delta in range(-40, 41, 8):
            c = min(max(tie + delta + int(rng.integers(0, 8)), 0), ONE)
            col = np.array([[c, min(c + 1, ONE), max(c - 1, 0), ONE if kind != 1 else c]] * 3)
            n = 16
            ct = np.full((n, 4), ONE)
            ct[8:] = rng.integers(ONE - 64, ONE + 1, (8, 4))
            p = np.tile([ONE, 0, 0], (n, 1))
            dst = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
            dst[:4] = 0
            k = np.arange(n)
            for smooth in (0, 1):
                out, exact = _run(smooth, 0, kind, C.GL_ALWAYS, 0, col, p, ct, dst, k)
                expect = _expect(smooth, 0, kind, C.GL_ALWAYS, 0, col, p, ct, dst, k)
                np.testing.assert_array_equal(out, expect)
                total += exact
    assert total > 0          # the ties did reach the exact code


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
@pytest.mark.parametrize("dot3", [1, 2], ids=["dot3_rgb", "dot3_rgba"])
def test_dot3_before_the_modulate_matches_the_integer_model(dot3, kind):
    """stage_dot3_write's kernel: a first unit's COMBINE DOT3 of its texels
    t0 and the colour, then the MODULATE, on random inputs whose channels
    often sit at 1/2 (DOT3's zero), 0 and 1, smooth and flat, RGBA and RGB,
    RGBA8888 and (kinds 0 and 1) RGB565, counts that are not whole groups."""
    rng = np.random.default_rng(400 + 3 * dot3 + kind)
    lanes = exact_total = 0
    for trial in range(48):
        smooth, rgb = trial % 2, (trial // 2) % 2
        rgb565 = int(kind < 2 and trial % 3 == 0)
        n = int(rng.integers(1, 65)) if trial % 4 == 3 else 64
        col = rng.integers(0, ONE + 1, (3, 4))
        col[:, :3][rng.random((3, 3)) < 0.2] = ONE // 2
        p = _weights(rng, n)
        ct, t0 = _texels(rng, n), _texels(rng, n)
        t0[rng.random((n, 4)) < 0.1] = ONE // 2
        dst = rng.integers(0, 1 << 32, 80, dtype=np.uint64).astype(np.uint32)
        if rgb565:
            dst &= 0xFFFF
        k = np.arange(n) if trial % 2 else np.sort(rng.choice(80, n, replace=False))
        func = FUNCS[trial % len(FUNCS)] if trial % 3 == 1 else C.GL_ALWAYS
        ref = int(rng.integers(0, 256))
        args = (smooth, rgb, kind, func, ref, col, p, ct, dst, k, rgb565, trial % 2, 0)
        out, exact = _run(*args, pad=trial % 2, dot3=dot3, t0=t0)
        np.testing.assert_array_equal(out, _expect(*args, dot3=dot3, t0=t0))
        lanes += n - n % 8
        exact_total += max(exact - n % 8, 0)
    assert exact_total <= 0.05 * lanes


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
def test_dot3_at_the_rounding_ties(kind):
    """DOT3 results at the ties of the final rounding: with the colour
    (1, 1/2, 1/2) only the red product counts, frag_mul(x, 1/2) with x =
    t0_r - 1/2, so DOT3 gives D = 4 floor((x + 1) / 2); with a second
    texel of 1 the byte is floor(255 D / 2^30 + 1/2). x is put where D
    meets each tie and up to 40 units of 2^-30 either side; the alpha,
    t0_a c_a, is placed at the ties too (DOT3_RGB)."""
    rng = np.random.default_rng(17 + kind)
    total = 0
    for b in list(range(0, 255, 9)) + [254]:
        tie = ((2 * b + 1) * ONE + 509) // 510
        n = 24
        x = np.clip(tie // 2 + np.arange(-n // 2, n // 2) * 3 + rng.integers(0, 3, n), 0, ONE // 2)
        t0 = np.full((n, 4), ONE)
        t0[:, 0] = ONE // 2 + x
        t0[:, 1] = rng.integers(0, ONE + 1, n)              # times c_g - 1/2 = 0
        t0[:, 3] = np.clip(tie + np.arange(-n // 2, n // 2) * 3, 0, ONE)
        col = np.array([[ONE, ONE // 2, ONE // 2, ONE]] * 3)
        ct = np.full((n, 4), ONE)
        p = np.tile([ONE, 0, 0], (n, 1))
        dst = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
        k = np.arange(n)
        for smooth in (0, 1):
            for dot3 in (1, 2):
                args = (smooth, 0, kind, C.GL_ALWAYS, 0, col, p, ct, dst, k)
                out, exact = _run(*args, dot3=dot3, t0=t0)
                np.testing.assert_array_equal(out, _expect(*args, dot3=dot3, t0=t0))
                total += exact
    assert total > 0          # the ties did reach the exact code


def test_alpha_test_at_its_reference():
    """The alpha test's 8-bit alpha at the reference and beside it, for
    every function: its rounding is proved or left to the exact code as
    the bytes' is."""
    rng = np.random.default_rng(11)
    for ref in (0, 1, 127, 128, 254, 255):
        tie = ((2 * ref + 1) * ONE + 509) // 510
        alphas = [min(max(tie + d, 0), ONE) for d in range(-24, 25, 3)]
        alphas += [min(max((ref * ONE + 127) // 255 + d, 0), ONE) for d in (-2, 0, 2)]
        n = len(alphas) - len(alphas) % 8
        for func in FUNCS:
            for kind in (0, 1, 2):
                col = np.array([[ONE // 3, ONE // 2, ONE, ONE]] * 3)
                ct = np.full((n, 4), ONE)
                ct[:, 3] = alphas[:n]
                p = np.tile([0, ONE, 0], (n, 1))
                dst = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
                k = np.arange(n)
                out, _ = _run(1, 0, kind, func, ref, col, p, ct, dst, k)
                np.testing.assert_array_equal(out, _expect(1, 0, kind, func, ref, col, p, ct, dst, k))


def test_texels_outside_the_unit_range_take_the_exact_code():
    """A texel of 2^31 or more (no sampler makes one) sends its group of
    eight to the exact code whole."""
    rng = np.random.default_rng(13)
    n = 16
    col = rng.integers(0, ONE + 1, (3, 4))
    p = _weights(rng, n)
    ct = _texels(rng, n)
    ct[3, 1] = 1 << 31
    dst = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
    k = np.arange(n)
    out, exact = _run(1, 0, 1, C.GL_ALWAYS, 0, col, p, ct, dst, k)
    assert exact >= 8
    np.testing.assert_array_equal(out, _expect(1, 0, 1, C.GL_ALWAYS, 0, col, p, ct, dst, k))


def test_weights_far_outside_the_triangle_take_the_exact_code():
    """A fragment whose weights' magnitudes sum past 1 + 2^-7 (a point well
    outside its triangle; the bound counts that sum) goes to the exact
    code, its group's others not; in both builds that have the kernel."""
    rng = np.random.default_rng(15)
    n = 16
    far = [1.5, -0.25, -0.25]
    near = [0.25, 0.25, 0.5]
    k = np.arange(n)
    dst = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
    col = rng.integers(ONE // 4, 3 * ONE // 4, (3, 4))
    p = np.array([far if j % 5 == 0 else near for j in range(n)]) * ONE
    ct = np.full((n, 4), ONE // 2)
    out, exact = _run(1, 0, 0, C.GL_ALWAYS, 0, col, p.astype(np.int64), ct, dst, k)
    assert exact == 4           # fragments 0, 5, 10 and 15
    np.testing.assert_array_equal(out, _expect(1, 0, 0, C.GL_ALWAYS, 0, col, p.astype(np.int64), ct, dst, k))
    cold, pd = col / ONE, p / ONE
    ctd = np.full((n, 4), 0.5)
    out, exact = _run_d(1, 0, 0, C.GL_ALWAYS, 0, cold, pd, ctd, dst, k)
    assert exact == 4
    np.testing.assert_array_equal(out, _expect_d(1, 0, 0, C.GL_ALWAYS, 0, cold, pd, ctd, dst, k))


@pytest.mark.parametrize("dither", [0, 1], ids=["msb", "dither"])
@pytest.mark.parametrize("kind", [0, 1], ids=["none", "alpha"])
@pytest.mark.parametrize("smooth", [0, 1], ids=["flat", "smooth"])
def test_rgb565_matches_the_integer_model(smooth, kind, dither):
    """The RGB565 writer's kernel: random inputs, and channels at the
    boundaries of the 5- and 6-bit steps (with the dither thresholds of
    each column, or the top bits) and beside them."""
    rng = np.random.default_rng(200 + 4 * smooth + 2 * kind + dither)
    lanes = exact_total = 0
    for trial in range(24):
        n = int(rng.integers(1, 65))
        col = rng.integers(0, ONE + 1, (3, 4))
        p = _weights(rng, n)
        ct = _texels(rng, n)
        if trial % 3 == 0:
            # a flat colour on a step boundary: with a texel of 1 it is the
            # channel's value; boundaries of y 31 + t and y 32 (and 63, 64)
            top = int(rng.choice([31, 32, 63, 64]))
            q, t = int(rng.integers(1, top)), int(rng.integers(0, 32))
            edge = (q * 32 - (2 * t + 1 if top in (31, 63) else 0)) * ONE // (32 * top)
            col[:] = [edge + int(rng.integers(-6, 7)) for _ in range(4)]
            col = np.clip(col, 0, ONE)
            ct[:] = ONE
        dst = rng.integers(0, 1 << 16, 80).astype(np.uint16)
        k = np.arange(n) if trial % 2 else np.sort(rng.choice(80, n, replace=False))
        x0 = int(rng.integers(0, 8))
        func = FUNCS[trial % len(FUNCS)] if trial % 3 == 1 else C.GL_ALWAYS
        ref = int(rng.integers(0, 256))
        out, exact = _run(smooth, 0, kind, func, ref, col, p, ct, dst, k, 1, dither, x0)
        expect = _expect(smooth, 0, kind, func, ref, col, p, ct, dst, k, 1, dither, x0)
        np.testing.assert_array_equal(out, expect)
        if trial % 3:
            lanes += n - n % 8
            exact_total += exact - n % 8
    assert exact_total <= 0.05 * lanes


@pytest.mark.parametrize("rgb565", [0, 1], ids=["rgba8888", "rgb565"])
def test_padded_tails_over_scattered_fragments(rgb565):
    """A chunk's tail padded to a group of eight with copies of its last
    fragment (as the stage that samples in the kernel pads it) over
    fragments the tests left scattered: the copies write the last word
    again, and a padded group whose first and last offsets lie seven apart
    is still not eight neighbouring pixels."""
    rng = np.random.default_rng(17 + rgb565)
    tails = [[10, 12, 13, 17], [3, 4, 5, 6, 7, 8, 10], [0, 7], [5]]
    for trial in range(40):
        if trial < len(tails):
            k = np.array(list(range(0, 16, 2)) + [t + 20 for t in tails[trial]])
        else:
            n = int(rng.integers(1, 65))
            k = np.sort(rng.choice(80, n, replace=False))
        n = len(k)
        col = rng.integers(0, ONE + 1, (3, 4))
        p = _weights(rng, n)
        ct = _texels(rng, n)
        dst = rng.integers(0, 1 << (16 if rgb565 else 32), 80, dtype=np.uint64)
        dst = dst.astype(np.uint16 if rgb565 else np.uint32)
        kind = trial % 2
        out, _ = _run(1, 0, kind, C.GL_ALWAYS, 0, col, p, ct, dst, k, rgb565, 1, 3, pad=1)
        expect = _expect(1, 0, kind, C.GL_ALWAYS, 0, col, p, ct, dst, k, rgb565, 1, 3)
        np.testing.assert_array_equal(out, expect)


# {================================================================
# the float build's kernel: the scalar code's float operations in its order


def _model_f32(smooth, rgb, kind, func, ref, col, p, ct, d, f=np.float32, dot3=0, t0=None):
    """Words of the float build's chain (f = np.float64: the double build's)
    for all fragments at once, in numpy arithmetic of that type, operation
    by operation as frag_lerp3f, frag_clamp01, frag_mul, fragment_alpha8 and
    v4_rgba8 do them; with dot3, stage_color_dot3_modulate's DOT3 of the
    first unit's texels t0 and the colour first."""
    one, zero = f(1), f(0)

    def clamp01(v):
        return np.minimum(one, np.maximum(zero, v))

    def unorm8(v):
        x = (v * f(255) + f(0.5)).astype(f)
        x = np.where(v >= one, f(255), x)
        x = np.where(v > zero, x, zero)
        return x.astype(np.int64)

    col = col.astype(f)
    if smooth:
        w = p.astype(f)
        c = clamp01((col[0][None, :] * w[:, 0:1] + col[1][None, :] * w[:, 1:2]) + col[2][None, :] * w[:, 2:3])
    else:
        c = np.broadcast_to(clamp01(col[0]), (len(ct), 4))
    if dot3:
        half = f(0.5)
        q = (t0.astype(f)[:, :3] - half) * (c[:, :3] - half)
        dsum = np.maximum(f(0), np.minimum(f(1), (((f(0) + q[:, 0]) + q[:, 1]) + q[:, 2]) * f(4)))
        alpha = dsum if dot3 == 2 else clamp01(t0.astype(f)[:, 3] * c[:, 3])
        c = np.stack([dsum, dsum, dsum, alpha], axis=1)
    y = (c * ct.astype(f)).astype(f)
    if rgb:
        y[:, 3] = c[:, 3]
    passed = np.array([_compare(func, int(a), ref) for a in unorm8(y[:, 3])])
    dv = np.stack([(d >> (8 * i)) & 0xFF for i in range(4)], axis=1).astype(f) / f(255)
    if kind:
        y = clamp01(y)
        va = y[:, 3:4]
        y = y * va + dv * (one - va) if kind == 1 else y + dv
    b = unorm8(y)
    words = b[:, 0] | (b[:, 1] << 8) | (b[:, 2] << 16) | (b[:, 3] << 24)
    return np.where(passed, words, d).astype(np.uint32)


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
def test_float_build_kernel_matches_float32_model(kind):
    """The float build's eight-lane kernel gives the float32 words of the
    scalar code's operations in their order. Over 2^17 fragments per blend
    a one-ulp change moves a few bytes across a rounding boundary: another
    association of the colour's sum, or 1 - alpha off by an ulp, fails the
    SRC_ALPHA case. Every fourth trial has a count that is not a whole
    number of groups (the tail padded with copies of the last fragment,
    which must not be taken for eight neighbouring pixels)."""
    ctx = make_ctx("float", 1, 1)
    if not ctx.simd == "avx2":
        pytest.skip("no AVX2 instance")
    ffi, lib = ctx._ffi, ctx._lib
    f, ctype, entry = np.float32, "float *", lib.gles_debug_modulate_write_f
    rng = np.random.default_rng(300 + kind)
    for trial in range(2048):
        smooth, rgb = trial % 2, (trial // 2) % 2
        func = FUNCS[trial % len(FUNCS)] if trial % 5 == 0 else C.GL_ALWAYS
        ref = int(rng.integers(0, 256))
        n = int(rng.integers(1, 64)) if trial % 4 == 3 else 64
        col = rng.uniform(-0.1, 1.1, (3, 4)).astype(f)
        w = rng.uniform(0, 1, (n, 3)).astype(f)
        w /= w.sum(axis=1, keepdims=True)
        w = w.astype(f)
        ct = rng.uniform(0, 1, (n, 4)).astype(f)
        d = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
        k = np.arange(n) if trial % 3 else np.sort(rng.choice(80, n, replace=False))
        k = k.astype(np.uint8)
        dst = rng.integers(0, 1 << 32, 80, dtype=np.uint64).astype(np.uint32)
        dst[k] = d
        out = dst.copy()
        cf = np.ascontiguousarray(col.ravel())
        assert entry(
            smooth, rgb, kind, func, ref, ffi.cast(ctype, cf.ctypes.data), n,
            ffi.cast("uint8_t *", k.ctypes.data), ffi.cast(ctype, w.ctypes.data),
            ffi.cast(ctype, ct.ctypes.data), ffi.cast("uint32_t *", out.ctypes.data)) == 0
        expect = dst.copy()
        expect[k] = _model_f32(smooth, rgb, kind, func, ref, col, w, ct, d)
        np.testing.assert_array_equal(out, expect)


# {================================================================
# the double build's AVX2 kernel: float lanes, each byte proved equal to the
# double chain's or taken from it


def _run_d(smooth, rgb, kind, func, ref, col, p, ct, dst, k, rgb565=0, dither=0, x0=0, dot3=0, t0=None):
    """gles_debug_modulate_write_d's words at offsets k of dst, and its
    count of fragments left to the exact code."""
    ctx = make_ctx("double", 1, 1)
    if ctx.simd == "baseline":
        pytest.skip("no AVX2 instance")
    ffi, lib = ctx._ffi, ctx._lib
    n = len(k)
    cf = np.ascontiguousarray(col, dtype=np.float64).reshape(-1)
    w = np.ascontiguousarray(p, dtype=np.float64).reshape(-1)
    t = np.ascontiguousarray(ct, dtype=np.float64).reshape(-1)
    t0 = np.ascontiguousarray(ct if t0 is None else t0, dtype=np.float64).reshape(-1)
    k = np.ascontiguousarray(k, dtype=np.uint8)
    out = np.array(dst, dtype=np.uint16 if rgb565 else np.uint32)
    exact = lib.gles_debug_modulate_write_d(
        smooth, rgb, kind, func, ref, ffi.cast("double *", cf.ctypes.data), n,
        ffi.cast("uint8_t *", k.ctypes.data), ffi.cast("double *", w.ctypes.data), dot3,
        ffi.cast("double *", t0.ctypes.data), ffi.cast("double *", t.ctypes.data), rgb565, dither, x0,
        ffi.cast("void *", out.ctypes.data))
    assert exact >= 0
    return out, exact


def _expect_d(smooth, rgb, kind, func, ref, col, p, ct, dst, k, dot3=0, t0=None):
    expect = np.array(dst, dtype=np.uint32)
    expect[k] = _model_f32(smooth, rgb, kind, func, ref, col, p, ct, expect[k], f=np.float64,
                           dot3=dot3, t0=t0)
    return expect


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
def test_double_build_kernel_matches_float64_model(kind):
    """The double build's AVX2 kernel gives the double chain's words (the
    scalar code's IEEE double operations in their order, in numpy float64)
    on random colours, weights (a few slightly outside the triangle),
    texels (bytes / 255, bilinear blends of them, 0 and 1), stored words,
    alpha tests, and counts that are not whole groups; few lanes go to the
    exact code."""
    rng = np.random.default_rng(500 + kind)
    lanes = exact_total = 0
    for trial in range(512):
        smooth, rgb = trial % 2, (trial // 2) % 2
        func = FUNCS[trial % len(FUNCS)] if trial % 5 == 0 else C.GL_ALWAYS
        ref = int(rng.integers(0, 256))
        n = int(rng.integers(1, 64)) if trial % 4 == 3 else 64
        col = rng.uniform(0, 1, (3, 4))
        w = rng.uniform(0, 1, (n, 3))
        w /= w.sum(axis=1, keepdims=True)
        w[: n // 8, 0] -= rng.uniform(0, 2e-3, n // 8)
        ct = rng.uniform(0, 1, (n, 4))
        ct[: n // 2] = rng.integers(0, 256, (n // 2, 4)) / 255.0
        ct[: min(n, 2)] = [[0.0, 1.0, 0.5, 1.0], [1.0, 0.0, 1.0, 0.0]][: min(n, 2)]
        k = np.arange(n) if trial % 3 else np.sort(rng.choice(80, n, replace=False))
        dst = rng.integers(0, 1 << 32, 80, dtype=np.uint64).astype(np.uint32)
        out, exact = _run_d(smooth, rgb, kind, func, ref, col, w, ct, dst, k)
        np.testing.assert_array_equal(out, _expect_d(smooth, rgb, kind, func, ref, col, w, ct, dst, k))
        lanes += n
        exact_total += exact
    assert exact_total <= 0.05 * lanes


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
def test_double_build_kernel_at_the_rounding_ties(kind):
    """Values put on the ties of the final rounding, so that only the exact
    code can be right: the colour c of each rgb channel is solved (in
    float64) from a texel T, a stored byte D and the alpha A so that the
    blended value is (b + 1/2) / 255 for a random byte b (ONE / ONE: cT + D
    / 255; SRC_ALPHA: cT A + D / 255 (1 - A); none: cT), which lands within
    a few units of the last place either side of the tie; the vertex
    colours are all c (smooth) or c is the flat colour."""
    rng = np.random.default_rng(600 + kind)
    total = 0
    for _ in range(64):
        n = 64
        T = rng.uniform(0.3, 1.0, (n, 4))
        d = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
        alpha = 0.8 if kind == 1 else 1.0
        c = np.empty(4)
        c[3] = alpha
        ct = T.copy()
        ct[:, 3] = 1.0                      # A = c_a, the same in every fragment
        D = np.stack([(d >> (8 * i)) & 0xFF for i in range(3)], axis=1) / 255.0
        b = rng.integers(1, 255, 3)
        target = (b + 0.5) / 255.0
        # one colour per trial (flat and smooth alike): fragment 0's solution
        if kind == 0:
            m = target
        elif kind == 2:
            m = target - D[0]
        else:
            m = (target - D[0] * (1 - alpha)) / alpha
        c[:3] = np.clip(m / T[0, :3], 0.0, 1.0)
        # every fragment on the tie: its texel solved from the colour
        want = np.broadcast_to(target, (n, 3))
        if kind == 2:
            want = want - D
        elif kind == 1:
            want = (want - D * (1 - alpha)) / alpha
        with np.errstate(divide="ignore", invalid="ignore"):
            ct[:, :3] = np.clip(np.where(c[:3] > 0, want / c[:3], 0.0), 0.0, 1.0)
        col = np.array([c] * 3)
        w = rng.uniform(0, 1, (n, 3))
        w /= w.sum(axis=1, keepdims=True)
        k = np.arange(n)
        for smooth in (0, 1):
            out, exact = _run_d(smooth, 0, kind, C.GL_ALWAYS, 0, col, w, ct, d, k)
            np.testing.assert_array_equal(out, _expect_d(smooth, 0, kind, C.GL_ALWAYS, 0, col, w, ct, d, k))
            total += exact
    assert total > 0          # the ties did reach the exact code


@pytest.mark.parametrize("kind", [0, 1, 2], ids=["none", "alpha", "add"])
@pytest.mark.parametrize("dot3", [1, 2], ids=["dot3_rgb", "dot3_rgba"])
def test_double_build_dot3_matches_float64_model(dot3, kind):
    """The double build's kernel with a first unit's DOT3 before the
    MODULATE (stage_color_dot3_modulate's operations): random inputs whose
    channels often sit at 1/2, 0 and 1, and, in every other trial, the
    first unit's red texel solved so that the word lands on a tie (the
    colour (1, 1/2, 1/2) leaves the red product alone: DOT3 = 4 (t0_r -
    1/2) / 2, which with a second texel of 1 and no blend is the channel's
    value)."""
    rng = np.random.default_rng(800 + 3 * dot3 + kind)
    lanes = exact_total = ties_exact = 0
    for trial in range(256):
        smooth, rgb = trial % 2, (trial // 2) % 2
        n = int(rng.integers(1, 65)) if trial % 4 == 3 else 64
        col = rng.uniform(0, 1, (3, 4))
        col[:, :3][rng.random((3, 3)) < 0.2] = 0.5
        w = rng.uniform(0, 1, (n, 3))
        w /= w.sum(axis=1, keepdims=True)
        ct, t0 = rng.uniform(0, 1, (n, 4)), rng.uniform(0, 1, (n, 4))
        t0[rng.random((n, 4)) < 0.1] = 0.5
        ct[rng.random((n, 4)) < 0.1] = 1.0
        tie = trial % 2 == 0
        if tie:
            col = np.array([[1.0, 0.5, 0.5, 1.0]] * 3)
            ct[:] = 1.0
            b = rng.integers(1, 255, n)
            t0[:, 0] = 0.5 + (b + 0.5) / 255.0 / 2.0
        k = np.arange(n) if trial % 3 else np.sort(rng.choice(80, n, replace=False))
        dst = rng.integers(0, 1 << 32, 80, dtype=np.uint64).astype(np.uint32)
        func = FUNCS[trial % len(FUNCS)] if trial % 5 == 1 else C.GL_ALWAYS
        ref = int(rng.integers(0, 256))
        args = (smooth, rgb, kind, func, ref, col, w, ct, dst, k)
        out, exact = _run_d(*args, dot3=dot3, t0=t0)
        np.testing.assert_array_equal(out, _expect_d(*args, dot3=dot3, t0=t0))
        if tie:
            ties_exact += exact
        else:
            lanes += n
            exact_total += exact
    assert exact_total <= 0.1 * lanes
    if kind == 0:
        assert ties_exact > 0     # the ties did reach the exact code


def _model_565_f64(smooth, rgb, kind, col, p, ct, d, x, dither):
    """RGB565 words of the double build's chain (stage_color_modulate, then
    stage_write_565 or stage_write_565_alpha) in numpy float64, operation
    by operation; x: each fragment's column (row 0's dither thresholds)."""
    f = np.float64

    def clamp01(v):
        return np.minimum(f(1), np.maximum(f(0), v))

    if smooth:
        c = clamp01((col[0][None, :] * p[:, 0:1] + col[1][None, :] * p[:, 1:2]) + col[2][None, :] * p[:, 2:3])
    else:
        c = np.broadcast_to(clamp01(col[0]), (len(ct), 4))
    y = c * ct
    if rgb:
        y[:, 3] = c[:, 3]
    if kind:
        cv = clamp01(y)
        va = cv[:, 3:4]
        dv = np.stack([((d >> 11) & 31) / f(31), ((d >> 5) & 63) / f(63), (d & 31) / f(31)], axis=1)
        y = cv[:, :3] * va + dv * (f(1) - va)
    t = (2 * np.array(BAYER_ROW0)[x & 3] + 1) / f(32)
    word = np.zeros(len(d), dtype=np.int64)
    for i, (bits, shift) in enumerate(((5, 11), (6, 5), (5, 0))):
        v, top = y[:, i], (1 << bits) - 1
        if dither:
            q = np.where(v >= 1, top, (v * f(top) + t).astype(np.int64))
        else:
            q = np.minimum(np.floor(v * f(1 << bits)), top).astype(np.int64)
        word |= np.where(v > 0, q, 0) << shift
    return word.astype(np.uint16)


@pytest.mark.parametrize("dither", [0, 1], ids=["msb", "dither"])
@pytest.mark.parametrize("kind", [0, 1], ids=["none", "alpha"])
def test_double_build_rgb565_matches_float64_model(kind, dither):
    """The double build's RGB565 writer in the kernel: random inputs, and
    channels put on the steps' boundaries (c T = (s + t) / 31 with the
    fragment's dither threshold t, or s / 32 for the top bits), flat and
    smooth, from columns x0 of every phase."""
    rng = np.random.default_rng(700 + 2 * kind + dither)
    total = 0
    for trial in range(128):
        smooth, rgb = trial % 2, (trial // 2) % 2
        n = int(rng.integers(1, 64)) if trial % 4 == 3 else 64
        x0 = int(rng.integers(0, 4))
        col = rng.uniform(0, 1, (3, 4))
        w = rng.uniform(0, 1, (n, 3))
        w /= w.sum(axis=1, keepdims=True)
        ct = rng.uniform(0, 1, (n, 4))
        k = np.arange(n) if trial % 3 else np.sort(rng.choice(80, n, replace=False))
        x = x0 + k
        if trial % 2 == 0 and kind == 0:
            # on the boundaries: the texel solved from the flat colour
            col[:] = col[0]
            col[:, :3] = rng.uniform(0.5, 1.0, 3)
            t = (2 * np.array(BAYER_ROW0)[x & 3] + 1) / 32.0 if dither else np.zeros(n)
            for i, top in enumerate((31, 63, 31)):
                s = rng.integers(1, top, n)
                target = (s - t) / top if dither else s / (top + 1.0)
                ct[:, i] = np.clip(target / col[0, i], 0, 1)
        dst = rng.integers(0, 1 << 16, 80).astype(np.uint16)
        out, exact = _run_d(smooth, rgb, kind, C.GL_ALWAYS, 0, col, w, ct, dst, k,
                            rgb565=1, dither=dither, x0=x0)
        expect = dst.copy()
        expect[k] = _model_565_f64(smooth, rgb, kind, col, w, ct, dst[k].astype(np.int64), x, dither)
        np.testing.assert_array_equal(out, expect)
        total += exact
    if kind == 0:
        assert total > 0      # the boundaries did reach the exact code


def test_double_build_texels_outside_the_unit_range_take_the_exact_code():
    """A texel outside [0, 1] or NaN (no sampler makes one) sends its group
    of eight to the exact code whole."""
    rng = np.random.default_rng(14)
    n = 16
    col = rng.uniform(0, 1, (3, 4))
    w = np.tile([0.25, 0.25, 0.5], (n, 1))
    for bad in (1.5, -0.25, np.nan):
        ct = rng.uniform(0, 1, (n, 4))
        ct[3, 1] = bad
        dst = rng.integers(0, 1 << 32, n, dtype=np.uint64).astype(np.uint32)
        k = np.arange(n)
        out, exact = _run_d(1, 0, 1, C.GL_ALWAYS, 0, col, w, ct, dst, k)
        assert exact >= 8
        np.testing.assert_array_equal(out, _expect_d(1, 0, 1, C.GL_ALWAYS, 0, col, w, ct, dst, k))


@pytest.mark.parametrize("blend", [True, False], ids=["blend", "no_blend"])
@pytest.mark.parametrize("color", ["rgba8888", "rgb565"])
@pytest.mark.parametrize("wrap", [C.GL_REPEAT, C.GL_CLAMP_TO_EDGE])
def test_sampling_in_the_fused_stage_matches_reference(numeric, color, wrap, blend):
    """A lone MODULATE unit of a bilinear texture (sampled inside the fused
    stage on the fixed and float builds with AVX2) with dithering, under
    SRC_ALPHA blending or none, with texture coordinates that reach 1e30,
    infinity and NaN at some vertices: a group with a coordinate that is
    not finite takes the exact sampler, and every word equals the
    per-fragment reference's. Without blending into RGBA8888 the fixed
    build takes a row's last partial group as its last eight again (each
    word of the overlap written twice), and the rows here have every
    length."""
    w, h = 67, 23
    rng = np.random.default_rng(41)
    texels = rng.integers(0, 256, (16, 8, 4), dtype=np.uint8)
    images = []
    for flags in (1, 0):
        ctx = make_ctx(numeric, w, h, color=color, range_check="off")
        gl = ctx.gl
        ctx.debug(flags)
        set_ortho(gl, w, h)
        tex = gl.glGenTextures(1)
        gl.glBindTexture(C.GL_TEXTURE_2D, tex)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 8, 16, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, texels)
        for pname, value in ((C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR), (C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR),
                             (C.GL_TEXTURE_WRAP_S, wrap), (C.GL_TEXTURE_WRAP_T, wrap)):
            gl.glTexParameteri(C.GL_TEXTURE_2D, pname, value)
        gl.glEnable(C.GL_TEXTURE_2D)
        if blend:
            gl.glEnable(C.GL_BLEND)
            gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
        gl.glEnable(C.GL_DITHER)
        gl.glClearColor(0.2, 0.4, 0.6, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        specials = (1e30, -1e30, np.inf, -np.inf, np.nan, 3.7, -2.2)
        g = np.random.default_rng(7)
        for tri in range(24):
            verts = g.uniform(-4, [w + 4, h + 4, 0], (3, 3)).astype(np.float32)
            tc = g.uniform(-3, 3, (3, 2)).astype(np.float32)
            if tri % 3 == 0:
                tc[tri % 3, tri % 2] = specials[tri % len(specials)]
            cols = g.integers(0, 256, (3, 4), dtype=np.uint8)
            gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
            gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
            gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
            gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
        assert gl.glGetError() == C.GL_NO_ERROR
        images.append(ctx.color_buffer())
    np.testing.assert_array_equal(images[1], images[0])
