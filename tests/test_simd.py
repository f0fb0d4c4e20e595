"""The vector instance of the span stages against the baseline and the reference.

Where the CPU has AVX2 (``ctx.simd == "avx2"``) the fragment chain and the
texture samplers run an AVX2 instance (csrc/span_stages.h, span_avx2.h);
``ctx.debug(16)`` runs the baseline instance, ``ctx.debug(1)`` the
per-fragment reference. The random-state tests (test_span_chain.py,
test_rect_chain.py) compare all three; these tests cover the kernels'
operand ranges exhaustively: every framebuffer byte under every source
alpha for the blending writers, and every texel byte under the bilinear
weights' extremes.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, SPAN_CHUNK, make_ctx

from gles import constants as C

PATHS = {"reference": 1, "chain": 0, "baseline": 16, "avx2": 32}


def test_simd_name_and_switch():
    ctx = make_ctx("float", 4, 4)
    assert ctx.simd in ("avx2", "baseline")
    ctx.debug(16)
    assert ctx.simd == "baseline"
    ctx.debug(0)
    assert ctx.simd == ("avx2" if HAS_SIMD else "baseline")


@pytest.mark.parametrize("numeric", ["fixed", "double"])
def test_avx512_instance_name_and_switch(numeric):
    """The fixed and double builds have an AVX-512 instance (the fixed
    build's perspective stage, the double build's float kernels); debug(32)
    caps it at AVX2, debug(16) at the baseline."""
    assert make_ctx("float", 4, 4).simd in ("avx2", "baseline")
    ctx = make_ctx(numeric, 4, 4)
    assert ctx.simd in (("avx512", "avx2") if HAS_SIMD else ("baseline",))
    best = ctx.simd
    ctx.debug(32)
    assert ctx.simd == ("avx2" if HAS_SIMD else "baseline")
    ctx.debug(16)
    assert ctx.simd == "baseline"
    ctx.debug(48)
    assert ctx.simd == "baseline"
    ctx.debug(0)
    assert ctx.simd == best


def _texture(gl, img: np.ndarray, filt: int) -> None:
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    for p, v in ((C.GL_TEXTURE_MIN_FILTER, filt), (C.GL_TEXTURE_MAG_FILTER, filt),
                 (C.GL_TEXTURE_WRAP_S, C.GL_REPEAT), (C.GL_TEXTURE_WRAP_T, C.GL_REPEAT)):
        gl.glTexParameteri(C.GL_TEXTURE_2D, p, v)
    h, w = img.shape[:2]
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, w, h, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)


def _blend_scene(numeric: str, flags: int, blend: tuple[int, int] | None, color: str = "rgba8888",
                 dither: bool = True) -> np.ndarray:
    """A 256x256 framebuffer holding every byte value in every channel (a
    REPLACE blit of a texture), then a smooth quad whose alpha runs over
    [0, 1] across x and colour over [0, 1] across y, blended by `blend`."""
    ctx = make_ctx(numeric, 256, 256, color=color)
    ctx.debug(flags)
    gl = ctx.gl
    if not dither:
        gl.glDisable(C.GL_DITHER)
    x, y = np.meshgrid(np.arange(256), np.arange(256))
    dst = np.stack([x, y, 255 - x, (x + 3 * y) % 256], axis=-1).astype(np.uint8)
    gl.glEnable(C.GL_TEXTURE_2D)
    _texture(gl, dst, C.GL_NEAREST)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glDrawTexiOES(0, 0, 0, 256, 256)
    gl.glDisable(C.GL_TEXTURE_2D)
    if blend:
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(*blend)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthof(0, 256, 0, 256, -1, 1)
    gl.glMatrixMode(C.GL_MODELVIEW)
    verts = np.array([[0, 0], [256, 0], [256, 256], [0, 256]], np.float32)
    cols = np.array([[0, 0, 1, 0], [1, 0.5, 0, 1], [0, 1, 1, 1], [1, 1, 0, 0]], np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_FLOAT, 0, cols)
    gl.glShadeModel(C.GL_SMOOTH)
    gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, 4)
    assert gl.glGetError() == C.GL_NO_ERROR
    return ctx.color_buffer()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("blend", [None, (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), (C.GL_ONE, C.GL_ONE)],
                         ids=["replace", "alpha", "add"])
def test_writers_over_every_byte(numeric, blend):
    """Every destination byte under every source alpha: the same bits on every path."""
    ref = _blend_scene(numeric, PATHS["reference"], blend)
    for name in ("chain", "avx2", "baseline"):
        np.testing.assert_array_equal(_blend_scene(numeric, PATHS[name], blend), ref, err_msg=name)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("blend", [None, (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)],
                         ids=["replace", "alpha"])
@pytest.mark.parametrize("dither", [True, False], ids=["dither", "no-dither"])
def test_565_writers_over_every_value(numeric, blend, dither):
    """The same on RGB565: every 5- and 6-bit destination value, dithered or not."""
    ref = _blend_scene(numeric, PATHS["reference"], blend, "rgb565", dither)
    for name in ("chain", "avx2", "baseline"):
        np.testing.assert_array_equal(_blend_scene(numeric, PATHS[name], blend, "rgb565", dither), ref,
                                      err_msg=name)


def _bilinear_scene(numeric: str, flags: int, env: int) -> np.ndarray:
    """A 16x16 texture of extreme and random bytes, magnified 16x with
    GL_LINEAR (so the weights take every 1/16 step, 0 included) and
    shifted by a fraction of a texel, under MODULATE or REPLACE."""
    ctx = make_ctx(numeric, 128, 128)
    ctx.debug(flags)
    gl = ctx.gl
    rng = np.random.default_rng(7)
    img = rng.integers(0, 256, (16, 16, 4), dtype=np.uint8)
    img[::3] = 255
    img[1::5] = 0
    gl.glEnable(C.GL_TEXTURE_2D)
    _texture(gl, img, C.GL_LINEAR)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, env)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthof(0, 128, 0, 128, -1, 1)
    gl.glMatrixMode(C.GL_MODELVIEW)
    verts = np.array([[0, 0], [128, 0], [128, 128], [0, 128]], np.float32)
    tc = (np.array([[0, 0], [1, 0], [1, 1], [0, 1]], np.float32) * 0.5 + 0.013).astype(np.float32)
    cols = np.array([[255, 0, 128, 255], [0, 255, 255, 128], [255, 255, 0, 0], [10, 200, 90, 255]], np.uint8)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, 4)
    assert gl.glGetError() == C.GL_NO_ERROR
    return ctx.color_buffer()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("env", [C.GL_MODULATE, C.GL_REPLACE], ids=["modulate", "replace"])
def test_bilinear_over_extreme_texels(numeric, env):
    ref = _bilinear_scene(numeric, PATHS["reference"], env)
    for name in ("chain", "avx2", "baseline"):
        np.testing.assert_array_equal(_bilinear_scene(numeric, PATHS[name], env), ref, err_msg=name)


def _sampled(ctx, coords: np.ndarray, simd: int) -> np.ndarray:
    """What texture unit 0's span sampler gives at coords (n x 6: s, t and
    the right and upper neighbours' s, t) through the best instance up to
    level simd (0 baseline, 1 AVX2, 2 AVX-512)."""
    n = len(coords)
    src = np.ascontiguousarray(coords, dtype=np.float64)
    out = np.zeros((n, 4), np.float64)
    ffi = ctx._ffi
    ok = ctx._lib.gles_debug_sample(ctx._ptr, 0, simd, n, ffi.cast("double *", src.ctypes.data),
                                    ffi.cast("double *", out.ctypes.data))
    assert ok == 1
    return out


def _sampler_case(numeric: str, seed: int, filt: int, wrap: tuple[int, int]) -> list[np.ndarray]:
    """One random power-of-two texture and 4095 random coordinates
    (tails that are not a multiple of the kernels' widths included),
    sampled by the baseline, the AVX2 and the AVX-512 instance (each the
    best the CPU has up to that level)."""
    rng = np.random.default_rng(seed)
    w, h = (1 << int(rng.integers(0, 9)) for _ in range(2))
    ctx = make_ctx(numeric, 4, 4)
    gl = ctx.gl
    img = rng.integers(0, 256, (h, w, 4), dtype=np.uint8)
    img[rng.random((h, w)) < 0.2] = 255
    img[rng.random((h, w)) < 0.2] = 0
    gl.glEnable(C.GL_TEXTURE_2D)
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    if filt != C.GL_LINEAR:
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
    for p, v in ((C.GL_TEXTURE_MIN_FILTER, filt), (C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR),
                 (C.GL_TEXTURE_WRAP_S, wrap[0]), (C.GL_TEXTURE_WRAP_T, wrap[1])):
        gl.glTexParameteri(C.GL_TEXTURE_2D, p, v)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, w, h, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
    n = 4095                 # eight at a time, then four, then one by one
    st = rng.uniform(-3, 3, (n, 2)) * rng.choice([1, 1, 1, 40], (n, 1))
    st[: n // 8] = np.round(st[: n // 8] * 64) / 64          # texel centres and edges
    # coordinates that are not finite, alone in a group of four and together,
    # and (1500: the sampler takes 64 at a time) in the second four of eight
    st[[1001, 1500, 2050, 2051, 3000]] = [[np.nan, 0.5], [0.5, np.nan], [0.25, np.inf], [-np.inf, np.nan],
                                          [1e30, -1e30]]
    # groups of eight along one texel row, magnified (the kernels load a
    # row's texels where every lane reads the same rows), some of them on
    # the last rows, at the right edge or stepping leftwards
    for g, first in enumerate(range(3104, 3104 + 8 * 96, 8)):
        t = (h - rng.uniform(0, 1.5)) / h if g % 3 == 0 else rng.uniform(-1, 2)
        s0 = (w - rng.uniform(0, 8)) / w if g % 4 == 0 else rng.uniform(-1, 2)
        ds = rng.uniform(0, 1) / w * (-1 if g % 5 == 0 else 1)
        st[first:first + 8] = np.column_stack([s0 + ds * np.arange(8), np.full(8, t)])
    # neighbours a random footprint away: magnified to minified by 2^8
    step = np.exp2(rng.uniform(-8, 8, (n, 1))) / max(w, h) * rng.choice([-1, 1], (n, 2))
    coords = np.concatenate([st, st + step * [1, 0], st + step * [0, 1]], axis=1)
    return [_sampled(ctx, coords, level) for level in (0, 1, 2)]


@pytest.mark.parametrize("numeric", ["float", "double"])
def test_samplers_give_every_byte_over_255(numeric):
    """At texel centres (both weights 0) a bilinear sample is its texel:
    every byte value d in every channel comes out as d / 255 divided in the
    build's type (numpy's division), from the baseline, the AVX2 and the
    AVX-512 instance (whose kernels form it without a division)."""
    ctx = make_ctx(numeric, 4, 4)
    gl = ctx.gl
    y, x = np.mgrid[0:16, 0:16]
    img = np.stack([(16 * y + x + 85 * c) % 256 for c in range(4)], axis=-1).astype(np.uint8)
    gl.glEnable(C.GL_TEXTURE_2D)
    _texture(gl, img, C.GL_LINEAR)
    st = np.column_stack([(x.ravel() + 0.5) / 16, (y.ravel() + 0.5) / 16])
    coords = np.concatenate([st, st, st], axis=1)
    kind = np.float32 if numeric == "float" else np.float64
    want = (img.reshape(-1, 4).astype(kind) / kind(255)).astype(np.float64)
    for level in (0, 1, 2):
        np.testing.assert_array_equal(_sampled(ctx, coords, level), want, err_msg=f"level {level}")


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("filt", [C.GL_LINEAR, C.GL_LINEAR_MIPMAP_LINEAR, C.GL_NEAREST_MIPMAP_LINEAR,
                                  C.GL_LINEAR_MIPMAP_NEAREST], ids=["linear", "lml", "nml", "lmn"])
@pytest.mark.parametrize("wrap", [(C.GL_REPEAT, C.GL_REPEAT), (C.GL_CLAMP_TO_EDGE, C.GL_CLAMP_TO_EDGE),
                                  (C.GL_REPEAT, C.GL_CLAMP_TO_EDGE), (C.GL_CLAMP_TO_EDGE, C.GL_REPEAT),
                                  (C.GL_MIRRORED_REPEAT_OES, C.GL_REPEAT)],
                         ids=["repeat", "clamp", "repeat-clamp", "clamp-repeat", "mirror-repeat"])
def test_span_samplers_match_baseline(numeric, filt, wrap):
    """The vector instance's samplers (eight fragments at a time where they
    can) give the baseline's texels bit for bit, over random sizes, texels,
    sub-texel positions (every 16-bit weight, so the kernels' rounding
    ties occur) and footprints."""
    for seed in range(3):
        base, avx2, avx512 = _sampler_case(numeric, seed, filt, wrap)
        np.testing.assert_array_equal(avx2, base, err_msg=f"seed {seed}, AVX2")
        np.testing.assert_array_equal(avx512, base, err_msg=f"seed {seed}, AVX-512")


def _persp_tangent(simd: int, eshift: int, lin_recip: int, mant, qshift, affine: int, area2: int, ea, eb,
                   e: np.ndarray) -> np.ndarray:
    """gles_debug_persp_tangent: each point's weights, then their tangents along ea and eb (n x 3 x 3)."""
    ctx = make_ctx("fixed", 1, 1)
    ffi, lib = ctx._ffi, ctx._lib
    e = np.ascontiguousarray(e, dtype=np.int64)
    out = np.zeros((len(e), 3, 3), np.int32)
    ok = lib.gles_debug_persp_tangent(simd, eshift, lin_recip, [int(m) for m in mant],
                                      [int(q) for q in qshift], affine, area2, [int(v) for v in ea],
                                      [int(v) for v in eb], len(e), ffi.cast("int64_t *", e.ctypes.data),
                                      ffi.cast("int32_t *", out.ctypes.data))
    assert ok == 1
    return out


def _covered_points(rng: np.random.Generator, area: int, count: int) -> np.ndarray:
    """Edge values of covered points (e_i >= 0 summing to the area), some scaled
    down by powers of two (sums far below 2^31 after every shift)."""
    w = rng.dirichlet([0.3, 0.3, 0.3], count)
    e = np.floor(w * area).astype(np.int64)
    e[:, 0] = area - e[:, 1] - e[:, 2]
    e >>= rng.integers(0, 3, (count, 1)) * rng.integers(0, 20, (count, 1))
    e[e.sum(axis=1) <= 0] = [area, 0, 0]
    return e


def _tangent_setup(rng: np.random.Generator, trial: int) -> tuple:
    """A triangle that is not affine (1/w mantissas below 2^30, one shift 0), its
    area and edge steps, multiples of 2^8 summing to 0 in odd trials (a
    triangle's): up to 1/64 of the area (trial % 3 == 0), a sliver's four
    times the area (the tangents saturate), or up to 2^-12 of it."""
    eshift = int(rng.integers(0, 11))
    mant = rng.integers(1 << 29, 1 << 30, 3)
    qshift = rng.integers(0, 70 if trial % 5 == 0 else 24, 3)
    qshift[rng.integers(0, 3)] = 0
    area = int(rng.integers(1 << 8, 1 << 31)) << eshift
    lin_recip = (1 << 61) // (area >> eshift)
    reach = [area // 64, 4 * area, area >> 12][trial % 3]
    steps = []
    for _ in range(2):
        d = rng.integers(-reach - 1, reach + 1, 3) >> 8 << 8
        if trial % 2:
            d[0] = -d[1] - d[2]
        steps.append([int(v) for v in d])
    return eshift, lin_recip, mant, qshift, area, steps[0], steps[1]


@pytest.mark.skipif(not HAS_SIMD, reason="no vector instance on this CPU")
def test_tangent_kernel_matches_scalar():
    """The vector kernel of the level of detail's tangent weights (avx2_tangent4
    after avx2_persp4_den) gives wgt_tangent's bit for bit, with the same
    fragment weights: on covered points of random triangles that are not
    affine, with a triangle's edge steps, a sliver's (saturating the
    tangents) and steps of any size, and on sums below 2^31 (left to the
    scalar code, which scales them up)."""
    rng = np.random.default_rng(15)
    for trial in range(60):
        eshift, lin_recip, mant, qshift, area, ea, eb = _tangent_setup(rng, trial)
        e = _covered_points(rng, area, 512)
        vec, base = (_persp_tangent(simd, eshift, lin_recip, mant, qshift, 0, area, ea, eb, e)
                     for simd in (1, 0))
        np.testing.assert_array_equal(vec, base, err_msg=f"trial {trial}")
        np.testing.assert_array_equal(vec[:, 0], _persp(0, eshift, lin_recip, mant, qshift, 0, e),
                                      err_msg=f"trial {trial}: the weights")


def _tangent_exact(eshift: int, mant, qshift, area: int, d, other, e: np.ndarray,
                   p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The tangent weights in exact rationals, in units of 2^-30: p_i + (a_i - p_i
    sum_j a_j) / den with n_i = ((e_i >> eshift) mant_i) >> qshift_i, den = sum n_i,
    a_i = ((d_i >> eshift, truncated) mant_i) >> qshift_i (truncated), and the
    fragment's own weights p as the renderer gives them; with the largest
    |a_i| / den (in 2^-30) of this step and the other one (their a_i share a
    scale), the size of the terms that cancel."""
    def trunc_shift(x: int, k: int) -> int:
        return -((-x) >> k) if x < 0 else x >> k
    def a_of(step) -> list[int]:
        return [trunc_shift(trunc_shift(int(v), eshift) * int(m), min(int(q), 62))
                for v, m, q in zip(step, mant, qshift)]
    a = a_of(d)
    top = max(abs(v) for v in a + a_of(other))
    out, scale = [], []
    for row, pw in zip(e.tolist(), p.astype(np.int64).tolist()):
        den = sum(((x >> eshift) * int(m)) >> int(q) if q < 63 else 0 for x, m, q in zip(row, mant, qshift))
        if den <= 0:        # the linear weights: not this formula
            out.append([np.nan] * 3)
            scale.append(np.nan)
            continue
        scale.append(top * 2.0**30 / den)
        r = Fraction(sum(a) * (1 << 30), den)
        t = [pw[i] + Fraction(a[i] * (1 << 30), den) - Fraction(pw[i], 1 << 30) * r for i in (1, 2)]
        out.append([(1 << 30) - t[0] - t[1], t[0], t[1]])
    return np.array([[float(v) for v in row] for row in out]), np.array(scale)


def test_tangent_weights_are_the_derivative():
    """wgt_tangent's weights are the fragment's weights plus their derivative
    along the edge step, (a_i - p_i sum_j a_j) / den in exact rationals, within
    the roundings of the a_i to 29 bits, of a reciprocal of 31 bits and of the
    products to 2^-30 (8 units of 2^-30, and 2^-26 of the largest a_i / den,
    the terms whose difference the derivative is): on covered points of
    random triangles whose steps keep the derivative below a weight of one
    per pixel, including sums below 2^31 (the scaled-up reciprocal)."""
    rng = np.random.default_rng(16)
    for trial in range(24):
        eshift, lin_recip, mant, qshift, area, ea, eb = _tangent_setup(rng, 3 * trial)   # a triangle's steps
        e = _covered_points(rng, area, 96)
        out = _persp_tangent(0, eshift, lin_recip, mant, qshift, 0, area, ea, eb, e).astype(np.float64)
        for k, d, other in ((1, ea, eb), (2, eb, ea)):
            want, scale = _tangent_exact(eshift, mant, qshift, area, d, other, e, out[:, 0])
            deriv = np.abs(want - out[:, 0])
            with np.errstate(invalid="ignore"):
                fits = (deriv < 2**29).all(axis=1) & (np.abs(want) < 2**31 - 1).all(axis=1)
            assert fits.sum() > 24, f"trial {trial}: too few points in range"
            err = np.abs(out[fits, k] - want[fits])
            tol = 8 + scale[fits, None] * 2.0**-26
            past = float((err - tol).max())
            assert (err <= tol).all(), f"trial {trial}, step {k}: {past:.1f} past the bound"


def test_affine_tangent_is_the_linear_step():
    """On an affine triangle the tangents are the weights plus the linear
    step d_i / area (rounded to 2^-30), the same at every fragment; on a sliver
    (steps of at least twice the area) the step saturates at +-(2^31 - 1)."""
    area = (1 << 20) + 12345
    lin_recip = (1 << 61) // area
    e = np.array([[area - 1000 - 2000, 1000, 2000], [area // 3, area // 3, area - 2 * (area // 3)]], np.int64)
    ea, eb = [-256, 512, -256], [0, -(3 << 8), 3 << 8]
    for simd in (0, 1):
        out = _persp_tangent(simd, 0, lin_recip, [1 << 29] * 3, [0, 0, 0], 1, area, ea, eb, e)
        out = out.astype(np.int64)
        for k, d in ((1, ea), (2, eb)):
            for i in (1, 2):
                step = round(Fraction(d[i] << 30, area))
                np.testing.assert_array_equal(out[:, k, i] - out[:, 0, i], step)
            np.testing.assert_array_equal(out[:, k].sum(axis=1), 1 << 30)
    sliver = _persp_tangent(0, 0, lin_recip, [1 << 29] * 3, [0, 0, 0], 1, area, [-4 * area, 4 * area, 0],
                            [0, 0, 0], e).astype(np.int64)
    np.testing.assert_array_equal(sliver[:, 1, 1], (1 << 31) - 1)


def _persp(simd: int, eshift: int, lin_recip: int, mant, qshift, affine: int, e: np.ndarray) -> np.ndarray:
    ctx = make_ctx("fixed", 1, 1)
    ffi, lib = ctx._ffi, ctx._lib
    e = np.ascontiguousarray(e, dtype=np.int64)
    out = np.zeros(e.shape, np.int32)
    ok = lib.gles_debug_persp(simd, eshift, lin_recip, [int(m) for m in mant], [int(q) for q in qshift],
                              affine, len(e), ffi.cast("int64_t *", e.ctypes.data),
                              ffi.cast("int32_t *", out.ctypes.data))
    assert ok == 1
    return out


def _persp_exact(eshift: int, mant, qshift, e: np.ndarray) -> np.ndarray:
    """wgt_persp of a triangle that is not affine, in Python's integers: the
    products aligned by qshift, the sum normalised to 32 bits, one rounded
    reciprocal 2^62 / den, the weights rounded from it."""
    out = []
    for row in e.tolist():
        n = [((x >> eshift) * int(m)) >> int(q) if q < 63 else 0 for x, m, q in zip(row, mant, qshift)]
        den = sum(n)
        assert den > 0
        sh = den.bit_length() - 32
        if sh > 0:
            den, n = den >> sh, [x >> sh for x in n]
        recip = ((1 << 62) + den // 2) // den
        p1, p2 = ((n[1] * recip + (1 << 31)) >> 32), ((n[2] * recip + (1 << 31)) >> 32)
        out.append([(1 << 30) - p1 - p2, p1, p2])
    return np.array(out, np.int64)


@pytest.mark.skipif(not HAS_SIMD, reason="no vector instance on this CPU")
def test_fragment_weights_kernel_matches_scalar():
    """The vector kernels of the fragments' own weights (avx2_persp4 for a
    triangle that is not affine, avx2_linear4v for one that is) give
    wgt_persp's weights bit for bit: on covered points of random triangles,
    on points past the kernels' ranges (negative or too wide edge values,
    which go to the scalar code), on sums below 2^31 after every shift, and
    on reciprocals whose double quotient lies within 2^-20 of an integer;
    and the non-affine weights equal the formula in exact integers."""
    rng = np.random.default_rng(12)
    for trial in range(60):
        eshift = int(rng.integers(0, 12))
        mant = rng.integers(1 << 29, 1 << 30, 3)
        qshift = rng.integers(0, 70 if trial % 5 == 0 else 20, 3)
        qshift[rng.integers(0, 3)] = 0
        affine = int(trial % 6 == 0)
        area = int(rng.integers(1, 1 << 31)) << eshift
        lin_recip = (1 << 61) // (area >> eshift)
        # covered points: e_i >= 0 summing to the area; a few lanes outside
        w = rng.dirichlet([0.3, 0.3, 0.3], 1024)
        e = np.floor(w * area).astype(np.int64)
        e[:, 0] = area - e[:, 1] - e[:, 2]
        scale = rng.integers(0, 3, (1024, 1))
        e >>= scale * rng.integers(0, 20, (1024, 1))
        # outside the kernels' ranges but inside the scalar code's domain:
        # for an affine triangle, negative values of at most the area; for
        # one that is not, e_i >> eshift just past 31 bits (wgt_persp's
        # products assume e_i >= 0 there, as every covered fragment has)
        bad = (rng.random(1024) < 0.02) & (affine == 1)
        e[bad, rng.integers(0, 3)] = -int(rng.integers(1, area + 1))
        wide = (rng.random(1024) < 0.02) & (affine == 0)
        e[wide, 1] = (1 << (31 + eshift)) + int(rng.integers(0, 1 << 20))
        e[(e.sum(axis=1) <= 0)] = [area, 0, 0]
        vec, base = (_persp(simd, eshift, lin_recip, mant, qshift, affine, e) for simd in (1, 0))
        np.testing.assert_array_equal(vec, base, err_msg=f"trial {trial}")
        if not affine:
            ok = (e >= 0).all(axis=1) & ~wide
            rows = e[ok][:64]
            # (a zero sum takes the linear weights: not this formula)
            live = np.array([sum(((int(x) >> eshift) * int(m)) >> int(q) if q < 63 else 0
                                 for x, m, q in zip(r, mant, qshift)) > 0 for r in rows.tolist()])
            exact = _persp_exact(eshift, mant, qshift, rows[live])
            np.testing.assert_array_equal(vec[ok][:64][live], exact.astype(np.int32))
    # reciprocals at an integer: denominators in [2^31, 2^32) whose numerator
    # 2^62 + den / 2 leaves a remainder within 69 of 0 or of den (found by
    # factoring 2^63 - 1 - 2r and 2^63 + 1 + 2s; checked below): the double
    # quotient (its numerator rounded by up to 256) can land on either side
    dens = [2281422937, 2323823089, 3969050863, 4042815511, 2560349145, 2573134565, 2843990835, 3243108917,
            3584488803, 3602388391, 2965648683, 3110069001, 2927893643, 3150173183, 2977518503, 3097670771,
            2154230017, 3011351133, 3062868337, 4281516813, 2572639177, 3585179033, 2618402453, 3522518865,
            2364807063, 3900264077, 2889359841, 3192185309]
    for d in dens:
        r = ((1 << 62) + d // 2) % d
        assert (1 << 31) <= d < (1 << 32) and min(r, d - 1 - r) <= 69
    rows = []
    for d in dens:
        for n1 in (0, 1, d // 3, d // 2, (1 << 31) - 1, int(rng.integers(0, 1 << 31))):
            rest = d - n1                            # split so that every edge value is below 2^31
            rows.append([rest // 2, n1, rest - rest // 2])
    e = np.array(rows, np.int64)
    # (mantissas 2^29: the sum d 2^29 normalises back to d)
    vec = _persp(1, 0, 0, [1 << 29] * 3, [0, 0, 0], 0, e)
    np.testing.assert_array_equal(vec, _persp(0, 0, 0, [1 << 29] * 3, [0, 0, 0], 0, e))
    np.testing.assert_array_equal(vec, _persp_exact(0, [1 << 29] * 3, [0, 0, 0], e).astype(np.int32))


def _color_stage(simd: int, clamp: int, col: np.ndarray, p: np.ndarray) -> np.ndarray:
    ctx = make_ctx("fixed", 1, 1)
    ffi, lib = ctx._ffi, ctx._lib
    col = np.ascontiguousarray(col, dtype=np.int64)
    p = np.ascontiguousarray(p, dtype=np.int32)
    out = np.zeros((len(p), 4), np.int64)
    ok = lib.gles_debug_color(simd, clamp, [int(v) for v in col.ravel()], len(p),
                              ffi.cast("int32_t *", p.ctypes.data), ffi.cast("int64_t *", out.ctypes.data))
    assert ok == 1
    return out


def _lerp3f_reference(col: np.ndarray, p: np.ndarray, clamp: bool) -> np.ndarray:
    """frag_lerp3f (and frag_clamp01) in Python integers: the 60-bit sum
    rounded half away from zero to 0.30."""
    out = np.zeros((len(p), 4), np.int64)
    for j, w in enumerate(p.tolist()):
        for i in range(4):
            acc = sum(int(col[k][i]) * w[k] for k in range(3))
            v = (abs(acc) + (1 << 29)) >> 30
            v = v if acc >= 0 else -v
            out[j, i] = min(max(v, 0), 1 << 30) if clamp else v
    return out


@pytest.mark.skipif(not HAS_SIMD, reason="no vector instance on this CPU")
@pytest.mark.parametrize("clamp", [0, 1], ids=["plain", "clamped"])
def test_color_kernel_matches_scalar(clamp):
    """The colour stage's vector kernels (v4_lerp3f, and v4_lerp3f_clamp01,
    whose rounding leaves out the sign) give frag_lerp3f's value bit for
    bit: colours across [-1, 1.5] in 0.30 (the sums stay within int64),
    weights of points inside and outside the triangle, and sums at the
    rounding ties (k 2^30 + 2^29, positive and negative) and beside them."""
    rng = np.random.default_rng(5)
    one = 1 << 30
    for trial in range(12):
        col = rng.integers(-one, one + one // 2, (3, 4))
        if trial % 3 == 0:
            col = rng.integers(0, one + 1, (3, 4))          # colours in [0, 1], as lit or array colours are
        p = rng.integers(-one // 2, one + one // 2, (64, 3))
        p[:16, 0] = one - p[:16, 1] - p[:16, 2]             # weights that sum to 1
        # ties: with a[0] = 2^-30 (the integer 1) and the other weights 0
        # the sum is w0, here k 2^30 + 2^29
        col[0, 0] = 1
        tie = rng.integers(-2, 2, 16) * one + (1 << 29)
        p[16:32] = np.stack([tie, np.zeros(16), np.zeros(16)], axis=1)
        p[32:40] = p[16:24] + rng.integers(-1, 2, (8, 3))
        p[40:48] = -p[16:24]
        want = _lerp3f_reference(col, p, bool(clamp))
        np.testing.assert_array_equal(_color_stage(0, clamp, col, p), want, err_msg=f"scalar, trial {trial}")
        np.testing.assert_array_equal(_color_stage(1, clamp, col, p), want, err_msg=f"vector, trial {trial}")


def _persp_chunk(simd: int, eshift: int, lin_recip: int, e0, ea, n: int) -> np.ndarray:
    ctx = make_ctx("fixed", 1, 1)
    ffi, lib = ctx._ffi, ctx._lib
    out = np.zeros((n, 3), np.int32)
    ok = lib.gles_debug_persp_chunk(simd, eshift, lin_recip, [1 << 29] * 3, [0, 0, 0], 1, n,
                                    [int(v) for v in e0], [int(v) for v in ea],
                                    ffi.cast("int32_t *", out.ctypes.data))
    assert ok == 1
    return out


@pytest.mark.skipif(not HAS_SIMD, reason="no vector instance on this CPU")
def test_affine_chunk_weights_step_as_the_scalar_code():
    """stage_persp over a chunk of neighbouring pixels of an affine triangle
    steps each weight's sum (e_i >> eshift) R + 2^30 by (4 ea_i >> eshift) R
    per group of four where 4 ea_i is a multiple of 2^eshift (a triangle's
    ea_i is a multiple of 2^8; persp_affine_run), else takes the general
    loop: its weights equal wgt_linear's, ((e_i >> eshift) R + 2^30) >> 31
    in Python's integers, at every slot: inside the triangle, where a
    chunk's edge values leave the kernel's range at one end (the whole chunk
    goes the other way), on sums placed one below a multiple of 2^31, with
    eshift 0 to 12, steps that are multiples of 2^8 or any, and any count."""
    rng = np.random.default_rng(14)
    for trial in range(400):
        eshift = int(rng.integers(0, 13)) if trial % 3 else 0
        area = int(rng.integers(1 << 8, 1 << 31)) << eshift | int(rng.integers(0, 1 << eshift))
        lin_recip = (1 << 61) // (area >> eshift)
        n = int(rng.integers(1, SPAN_CHUNK + 1))
        # the row's edge values: e1, e2 start inside and step by ea (e0 takes the rest)
        lim = area // SPAN_CHUNK
        ea = [0, int(rng.integers(-lim, lim + 1)), int(rng.integers(-lim, lim + 1))]
        if trial % 2:
            ea = [v >> 8 << 8 for v in ea]      # a triangle's (A times one subpixel unit)
        ea[0] = -ea[1] - ea[2]
        e0 = [0, int(rng.integers(0, area // 2)), int(rng.integers(0, area // 2))]
        if trial % 5 == 0:
            # a sum (e1 >> eshift) R + 2^30 one below a multiple of 2^31 at slot 0
            m = (int(rng.integers(1, 1 << 30)) << 31) - 1 - (1 << 30)
            e0[1] = min(max(m // lin_recip, 0), (area >> eshift) // 2) << eshift
        if trial % 7 == 0:
            e0[2] = -int(rng.integers(1, 1 << 10))          # out of range at the start
        e0[0] = area - e0[1] - e0[2]
        got = _persp_chunk(1, eshift, lin_recip, e0, ea, n)
        base = _persp_chunk(0, eshift, lin_recip, e0, ea, n)
        np.testing.assert_array_equal(got, base, err_msg=f"trial {trial}")
        for j in range(n):
            e1, e2 = e0[1] + j * ea[1], e0[2] + j * ea[2]
            if e1 < 0 or e2 < 0:
                continue            # (the scalar code's domain; checked against it above)
            l1 = ((e1 >> eshift) * lin_recip + (1 << 30)) >> 31
            l2 = ((e2 >> eshift) * lin_recip + (1 << 30)) >> 31
            assert list(got[j]) == [(1 << 30) - l1 - l2, l1, l2], (trial, j)
