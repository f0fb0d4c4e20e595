"""The level of detail of the AVX2 span samplers against the baseline's.

In the fixed build the AVX2 instance's level-of-detail sampler
(``lod_block``, csrc/texsample.c) chooses the levels of four fragments at a
time (``avx2_lod_choose4``, csrc/span_avx2.h): rho from the clamped
coordinate differences, lambda = lod_log2(rho) as a vector form of the
table and series, and §3.7.8's decisions. The baseline instance calls the
scalar ``lod_choose`` per fragment. ``gles_debug_sample`` runs either
instance's span sampler at given coordinates; these tests require the same
texels from both over coordinates built to put lambda at and around every
boundary the decisions have.

The levels are random except for red, which alternates between 0 and 255
from level to level: where two levels are mixed, red is the mix fraction
(or its complement) itself, so every bit of frac shows.

Exact Python arithmetic (lod_log2 from csrc/tables.h) picks the rho
values and checks that the inputs reach each boundary; the expected
texels are the scalar code's.
"""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, make_ctx

from gles import constants as C

TABLES = Path(__file__).resolve().parents[1] / "csrc" / "tables.h"
ONE = 1 << 32            # TEXC_ONE of the fixed build
LIM = 1 << 50            # lod_choose's clamp, 2^18 in TEXC
LAMBDA_ONE = 1 << 30     # LODV_ONE
MINS = [C.GL_NEAREST, C.GL_LINEAR, C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_NEAREST,
        C.GL_NEAREST_MIPMAP_LINEAR, C.GL_LINEAR_MIPMAP_LINEAR]
MIN_IDS = ["n", "l", "nmn", "lmn", "nml", "lml"]
WRAPS = [(C.GL_REPEAT, C.GL_REPEAT), (C.GL_CLAMP_TO_EDGE, C.GL_CLAMP_TO_EDGE),
         (C.GL_REPEAT, C.GL_CLAMP_TO_EDGE), (C.GL_CLAMP_TO_EDGE, C.GL_REPEAT),
         (C.GL_MIRRORED_REPEAT_OES, C.GL_CLAMP_TO_EDGE)]
WRAP_IDS = ["repeat", "clamp", "repeat-clamp", "clamp-repeat", "mirror-clamp"]
SIZES = [(256, 256), (2048, 1), (1, 2048), (64, 4), (8, 32), (1, 1)]


@cache
def fx_table(name: str) -> tuple[int, ...]:
    """One of csrc/tables.h's tables (fx_log2_tab, fx_recip_tab, fx_exp2_tab)."""
    text = TABLES.read_text()
    body = text[text.index(name):]
    return tuple(int(v) for v in re.findall(r"-?\d+", body[body.index("{") + 1: body.index("}")]))


def fx_log2(x: int) -> int:
    """num.h's fx_log2 (fixed build) of 1 <= x < 2^31 in exact integers, 0.30."""
    log2_tab, recip_tab = fx_table("fx_log2_tab"), fx_table("fx_recip_tab")
    b = x.bit_length()
    frac = (x << (31 - b)) - (1 << 30)
    i = frac >> 22
    y = ((frac & ((1 << 22) - 1)) * recip_tab[i]) >> 30
    y2 = (y * y) >> 30
    y3 = (y2 * y) >> 30
    ln1p = y - y2 // 2 + y3 // 3
    return (b - 17) * (1 << 30) + log2_tab[i] + ((ln1p * 1549082005) >> 30)


def lod_log2(rho: int) -> int:
    """num.h's lod_log2 (fixed build) in exact integers."""
    if rho <= 0:
        return -(1 << 40)
    r = rho >> 16
    if r == 0:
        return -(17 << 30)
    return fx_log2(min(r, (1 << 31) - 1))


def _first_r_at(target: int) -> int:
    """The least 16.16 rho whose lod_log2 is at least target (lod_log2 is
    non-decreasing in r)."""
    lo, hi = 1, (1 << 31) - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if lod_log2(mid << 16) >= target:
            hi = mid
        else:
            lo = mid + 1
    return lo


@cache
def _edge_rs() -> list[int]:
    """16.16 footprints around every boundary of the decisions: lambda at
    and beside each integer (exact at powers of two) and each half (c and
    the MIPMAP_NEAREST steps), the smallest and largest values."""
    rs = {0, 1, 2, 3, (1 << 31) - 2, (1 << 31) - 1, 1 << 31, 1 << 33}
    for k in range(-16, 16):
        for target in (k << 30, (k << 30) + (1 << 29)):
            r = _first_r_at(target)
            rs.update(v for v in range(r - 2, r + 3) if 0 < v < 1 << 34)
    return sorted(rs)


def _rho(c: np.ndarray, w: int, h: int) -> list[int]:
    """lod_choose's rho (fixed build) of TEXC rows s, t, dx.s, dx.t, dy.s, dy.t."""
    out = []
    for row in c.tolist():
        s, t, xs, xt, ys, yt = (min(max(v, -LIM), LIM) for v in row)
        out.append(max(abs(xs - s) * w, abs(ys - s) * w, abs(xt - t) * h, abs(yt - t) * h))
    return out


def _coords(rng: np.random.Generator, w: int, h: int) -> np.ndarray:
    """TEXC rows (s, t, then the right and upper neighbours' s, t) whose
    largest scaled difference is each edge footprint in turn, on a random
    axis and neighbour with a random sign, the other three smaller; then
    zero and tiny footprints, coordinates at and past the clamp, and random
    footprints from 2^-24 to 2^24 texels."""
    rows = []
    ws, hs = w.bit_length() - 1, h.bit_length() - 1
    for r in _edge_rs():
        for _ in range(2):
            s0, t0 = (int(v) for v in rng.integers(-3 * ONE, 3 * ONE, 2))
            axis, which, sign = (int(v) for v in rng.integers(0, 2, 3))
            sh = hs if axis else ws
            d = ((r << 16) + int(rng.integers(0, 1 << 16))) >> sh
            d = -d if sign else d
            limit = abs(d) << sh               # the others' scaled differences stay below
            diffs = [int(rng.integers(-(limit >> ws), (limit >> ws) + 1)),
                     int(rng.integers(-(limit >> hs), (limit >> hs) + 1))] * 2
            diffs[2 * which + axis] = d
            rows.append([s0, t0, s0 + diffs[0], t0 + diffs[1], s0 + diffs[2], t0 + diffs[3]])
    for _ in range(40):                        # rho 0, below 2^16 (r = 0), and just above
        s0, t0 = (int(v) for v in rng.integers(-3 * ONE, 3 * ONE, 2))
        e = [int(v) for v in rng.integers(-3, 4, 4)] if rng.random() < 0.5 else [0, 0, 0, 0]
        rows.append([s0, t0, s0 + e[0], t0 + e[1], s0 + e[2], t0 + e[3]])
    edge = [LIM - 1, LIM, LIM + 1, 3 * LIM, 1 << 62]
    for _ in range(200):                        # the clamp: at, beside and far past +-2^18
        row = [int(v) for v in rng.integers(-3 * ONE, 3 * ONE, 6)]
        for k in rng.choice(6, int(rng.integers(1, 7)), replace=False):
            row[k] = int(rng.choice(edge)) * int(rng.choice([-1, 1])) - int(rng.integers(0, 3))
        rows.append(row)
    n = 2000
    st = rng.integers(-4 * ONE, 4 * ONE, (n, 2))
    step = np.exp2(rng.uniform(-24, 24, (n, 1))) / max(w, h) * ONE
    d = (rng.uniform(-1, 1, (n, 4)) * step).astype(np.int64)
    rows += np.concatenate([st, st + d[:, :2], st + d[:, 2:]], axis=1).tolist()
    out = np.array(rows, dtype=np.int64)
    return out[rng.permutation(len(out))]


def _texture(ctx, w: int, h: int, minf: int, magf: int, wrap: tuple[int, int],
             rng: np.random.Generator) -> None:
    gl = ctx.gl
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glBindTexture(C.GL_TEXTURE_2D, gl.glGenTextures(1))
    for p, v in ((C.GL_TEXTURE_MIN_FILTER, minf), (C.GL_TEXTURE_MAG_FILTER, magf),
                 (C.GL_TEXTURE_WRAP_S, wrap[0]), (C.GL_TEXTURE_WRAP_T, wrap[1])):
        gl.glTexParameteri(C.GL_TEXTURE_2D, p, v)
    level, lw, lh = 0, w, h
    while True:
        img = rng.integers(0, 256, (lh, lw, 4), dtype=np.uint8)
        img[..., 0] = 255 * (level % 2)
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, C.GL_RGBA, lw, lh, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        if lw == 1 and lh == 1:
            break
        level, lw, lh = level + 1, max(lw // 2, 1), max(lh // 2, 1)
    assert gl.glGetError() == C.GL_NO_ERROR


def _sampled(ctx, coords: np.ndarray, simd: int) -> np.ndarray:
    out = np.zeros((len(coords), 4), np.float64)
    ffi = ctx._ffi
    ok = ctx._lib.gles_debug_sample(ctx._ptr, 0, simd, len(coords), ffi.cast("double *", coords.ctypes.data),
                                    ffi.cast("double *", out.ctypes.data))
    assert ok == 1
    return out


def _case(numeric: str, seed: int, size: tuple[int, int], minf: int, magf: int, wrap: tuple[int, int]):
    rng = np.random.default_rng(seed)
    w, h = size
    ctx = make_ctx(numeric, 4, 4)
    _texture(ctx, w, h, minf, magf, wrap, rng)
    coords = np.ascontiguousarray(_coords(rng, w, h).astype(np.float64) / ONE)
    # the fixed build's TEXC: texc_from_double of a multiple of 2^-32, saturated at 2^62
    texc = np.clip(coords * ONE, -float(1 << 62), float(1 << 62)).astype(np.int64)
    vec = _sampled(ctx, coords, 1)
    if ctx.simd == "avx512":
        # the AVX-512 instance (the fixed build's eight-lane choice) gives the AVX2 one's texels
        np.testing.assert_array_equal(_sampled(ctx, coords, 2), vec, err_msg="avx512")
    return texc, vec, _sampled(ctx, coords, 0)


def _trilinear_ctx(numeric: str, size: tuple[int, int], wrap: tuple[int, int], seed: int):
    """A 4x4 context with a LINEAR_MIPMAP_LINEAR texture of random levels
    (red alternating per level) of the size, and the generator after it."""
    rng = np.random.default_rng(seed)
    ctx = make_ctx(numeric, 4, 4)
    _texture(ctx, size[0], size[1], C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR, wrap, rng)
    return ctx, rng


def _runs(rng: np.random.Generator, size: tuple[int, int], count: int):
    """count runs of 16 to 64 fragments: (index, length, lambda between 0.05
    and q - 0.05, the footprint 2^lambda / w along s)."""
    for run in range(count):
        n = int(rng.integers(16, 65))
        lam = rng.uniform(0.05, max(size).bit_length() - 1.05)
        yield run, n, lam, (2.0 ** lam) / size[0]


def _runs_match_scalar(ctx, numeric: str, rows: list) -> None:
    """Rows of (s, t, right neighbour, upper neighbour) sampled by every
    instance give the baseline's texels, most of them mixes of two levels
    (red, 0 on even levels and full on odd ones, strictly between)."""
    coords = np.ascontiguousarray(np.array(rows, dtype=np.float64))
    base = _sampled(ctx, coords, 0)
    np.testing.assert_array_equal(_sampled(ctx, coords, 1), base, err_msg="avx2")
    if ctx.simd == "avx512":
        np.testing.assert_array_equal(_sampled(ctx, coords, 2), base, err_msg="avx512")
    red = base[:, 0]
    one = 1 << 30 if numeric == "fixed" else 1.0
    assert ((red > 0) & (red < one)).mean() > 0.5


pytestmark = pytest.mark.skipif(not HAS_SIMD, reason="no vector instance on this CPU")


@pytest.mark.parametrize("wrap", WRAPS, ids=WRAP_IDS)
@pytest.mark.parametrize("magf", [C.GL_NEAREST, C.GL_LINEAR], ids=["mag-n", "mag-l"])
@pytest.mark.parametrize("minf", MINS, ids=MIN_IDS)
def test_lod_kernel_matches_scalar(minf, magf, wrap):
    """Every size (square, 2048 x 1 and 1 x 2048, 1 x 1 where q = 0),
    filter pair and wrap: the AVX2 instance's texels (and the AVX-512
    one's, where it runs) are the baseline's, bit for bit."""
    for k, size in enumerate(SIZES):
        _, vec, base = _case("fixed", 100 * k + MINS.index(minf), size, minf, magf, wrap)
        np.testing.assert_array_equal(vec, base, err_msg=f"size {size}")


@pytest.mark.parametrize("numeric", [b for b in BUILDS if b != "fixed"])
@pytest.mark.parametrize("minf", MINS[2:], ids=MIN_IDS[2:])
def test_lod_runs_match_scalar_real(numeric, minf):
    """The float and double builds keep the scalar lod_choose inside the
    AVX2 instance's runs; their texels are the baseline's too."""
    for wrap in WRAPS[:2]:
        _, vec, base = _case(numeric, 7, (256, 64), minf, C.GL_LINEAR, wrap)
        np.testing.assert_array_equal(vec, base)


def test_inputs_reach_every_boundary():
    """The coordinates (by exact arithmetic) put lambda exactly on 0 and on
    integers up to and past q, just below and above 1/2 (where c is 0.5)
    and every half, and reach rho = 0, r = 0, the r clamp and the
    coordinate clamp; the red channel shows mixes of two levels."""
    texc, vec, base = _case("fixed", 3, (256, 256), C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR,
                            (C.GL_REPEAT, C.GL_REPEAT))
    rho = _rho(texc, 256, 256)
    lam = {lod_log2(r) for r in rho}
    assert 0 in rho and -(17 << 30) in lam
    assert any(r >> 16 > (1 << 31) - 1 for r in rho)
    assert all(k << 30 in lam for k in range(-8, 10))
    for k in range(0, 10):
        half = (k << 30) + (1 << 29)
        assert any(half - 40000 < v < half for v in lam) and any(half < v < half + 40000 for v in lam)
    assert (np.abs(texc) > LIM).any() and (np.abs(texc) == LIM).any()
    np.testing.assert_array_equal(vec, base)
    red = base[:, 0]
    assert ((red > 0) & (red < 1 << 30)).sum() > 300        # frac shows in red


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("wrap", WRAPS[:4], ids=WRAP_IDS[:4])
@pytest.mark.parametrize("size", [(256, 256), (64, 4), (8, 32)], ids=["256x256", "64x4", "8x32"])
def test_long_runs_of_one_level_pair_match_scalar(size, wrap, numeric):
    """Runs of up to 64 fragments with one footprint (so one level pair and
    one mix fraction) and scattered coordinates, near the edges too: the
    trilinear mix's groups (the fixed build's eight in AVX2 and sixteen in
    AVX-512, the double build's eight in AVX2 and AVX-512) give the baseline's
    texels at full precision (0.30 in the fixed build), where a rounding
    off by one unit shows."""
    ctx, rng = _trilinear_ctx(numeric, size, wrap, size[0] * 7 + size[1] + 100 * WRAPS.index(wrap))
    w, h = size
    rows = []
    for run, n, _lam, ds in _runs(rng, size, 24):
        st = rng.uniform(-1.5, 2.5, (n, 2))
        if run % 3 == 0:                        # on and beside the right and top edges
            st[:, 0] = rng.choice([1 - 0.5 / w, 1.0, 1 + 0.25 / w, -0.25 / w], n)
        rows += np.concatenate([st, st + [ds, 0.0], st + [0.0, ds * w / h / 4]], axis=1).tolist()
    _runs_match_scalar(ctx, numeric, rows)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("wrap", WRAPS[:2], ids=WRAP_IDS[:2])
@pytest.mark.parametrize("size", [(256, 256), (64, 4), (8, 32)], ids=["256x256", "64x4", "8x32"])
def test_clustered_runs_match_scalar(size, wrap, numeric):
    """Runs of one level pair whose footprints lie within a few texels of
    each other, as a perspective plane's do (the AVX-512 mix then reads a
    group's texels from a window of four rows of sixteen, or gathers them
    where a footprint lies outside it or the window outside the level):
    near the level's first and last rows and columns too, and on levels
    narrower than the window, the texels are the baseline's."""
    ctx, rng = _trilinear_ctx(numeric, size, wrap, size[0] + 3 * size[1] + 11 * WRAPS.index(wrap))
    w, h = size
    rows = []
    for run, n, lam, ds in _runs(rng, size, 40):
        level_w, level_h = max(w >> int(lam), 1), max(h >> int(lam), 1)
        cs, ct = rng.uniform(-1.5, 2.5, 2)
        if run % 4 == 1:                        # by the first or last row and column
            cs, ct = rng.choice([0.0, 1.0]), rng.choice([0.0, 1.0])
        # within about 6.5 texels along s and one along t of the level
        st = np.stack([cs + rng.uniform(-6.5, 6.5, n) / level_w,
                       ct + rng.uniform(-1.0, 1.0, n) / level_h], axis=1)
        if run % 5 == 2:                        # wider: some groups leave the window
            st[:, 0] += rng.uniform(-12, 12, n) / level_w
        rows += np.concatenate([st, st + [ds, 0.0], st + [0.0, ds * w / h / 4]], axis=1).tolist()
    _runs_match_scalar(ctx, numeric, rows)
