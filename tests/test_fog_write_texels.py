"""The fixed build's fused sampling, fog and write against an integer model.

Where AVX2 runs without AVX-512, a lone REPLACE unit of an RGBA texture with
a level of detail, LINEAR fog and a plain RGBA8888 or RGB565 write run as one
stage: the GL_LINEAR texels of one level, or of two mixed by the level of
detail's fraction, are fogged and written in float lanes, and a pixel whose
float value lies too near a rounding boundary to be proved goes to the exact
stages. ``gles_debug_fog_write_texels`` runs that kernel on one group of
eight chosen fragments. The expected pixels here come from the 0.30 integer
formulas of the reference path (frag_bilerp_rgba8, lod_mix, frag_lerp3, the
fog's frag_mul and the writers' conversions) evaluated with Python integers:
random inputs, and inputs drawn until a channel lies within 2^-10 of a byte's
or an RGB565 step's rounding point, where a wrong proof would show.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import HAS_SIMD, make_ctx
from test_modulate_write import BAYER_ROW0, ONE, _clamp01, _frag_mul, _pack565, _to_unorm8

pytestmark = pytest.mark.skipif(not HAS_SIMD, reason="no AVX2 instance on this CPU")


def _bilerp(c: list[int], a: int, b: int) -> list[int]:
    """frag_bilerp_rgba8 of the words c00, c10, c01, c11 at weights a, b (16 bits)."""
    ia, ib = 65536 - a, 65536 - b
    w = (ia * ib, a * ib, ia * b, a * b)
    out = []
    for k in range(4):
        acc = sum(((c[q] >> (8 * k)) & 0xFF) * w[q] for q in range(4))
        out.append(((((acc + 128) >> 8) * 16843009) + (1 << 25)) >> 26)
    return out


def _lerp3(a: list[int], w: list[int]) -> int:
    """frag_lerp3: 16.16 values at 0.30 weights, rounded half away from zero to 0.30."""
    acc = sum(x * y for x, y in zip(a, w))
    return (acc + 32768) >> 16 if acc >= 0 else -((-acc + 32768) >> 16)


def _fogged(lane: dict, fog: list[int], fc: list[int]) -> list[int]:
    """The texel (mixed where two), then fragment_fog with the factor from the weights."""
    m = _bilerp(lane["t1"], lane["a"], lane["b"])
    if lane["two"]:
        t2 = _bilerp(lane["t2"], lane["a"], lane["b"])
        m = [x + _frag_mul(lane["f"], y - x) for x, y in zip(m, t2)]
    f = _clamp01(_lerp3(fog, lane["w"]))
    return [_frag_mul(f, _clamp01(m[i])) + _frag_mul(ONE - f, fc[i]) for i in range(3)] + [m[3]]


def _threshold(x: int) -> int:
    return (2 * BAYER_ROW0[x & 3] + 1) * ONE // 32


def _pixel(v: list[int], x: int, rgb565: int, dither: int) -> int:
    """write_rgba8's word, or stage_write_565's pixel of column x (row 0)."""
    if rgb565:
        return _pack565(v[:3], x, dither)
    return sum(_to_unorm8(v[i]) << (8 * i) for i in range(4))


def _tie_distance(v: list[int], x: int, rgb565: int, dither: int) -> float:
    """How near the nearest rounding point the channels lie, in units of a byte or step."""
    d = 1.0
    for i, val in enumerate(v[: 3 if rgb565 else 4]):
        val = _clamp01(val)
        if not rgb565:
            z = val * 255 / ONE + 0.5
        elif dither:
            top = 31 if i != 1 else 63
            z = (val * top + _threshold(x)) / ONE
        else:
            z = val * (32 if i != 1 else 64) / ONE
        d = min(d, abs(z - round(z)))
    return d


def _lane(rng: np.random.Generator, two: int, far_weights: bool = False) -> dict:
    w1, w2 = sorted(rng.integers(0, ONE + 1, size=2))
    w = [ONE - w2, w2 - w1, w1]
    if far_weights:
        w = [int(x) for x in rng.integers(-2 * ONE, 2 * ONE, size=3)]
    words = lambda: [int(x) for x in rng.integers(0, 1 << 32, size=4, dtype=np.uint64)]  # noqa: E731
    return {"t1": words(), "t2": words(), "a": int(rng.integers(0, 65536)), "b": int(rng.integers(0, 65536)),
            "two": two, "f": int(rng.integers(0, ONE)), "w": [int(x) for x in w]}


def _run(lanes: list[dict], fog: list[int], fc: list[int], rgb565: int, dither: int) -> tuple[int, list[int]]:
    ctx = make_ctx("fixed", 1, 1)
    ffi, lib = ctx._ffi, ctx._lib
    two = lanes[0]["two"]
    tex1 = ffi.new("uint32_t[32]", [c for ln in lanes for c in ln["t1"]])
    tex2 = ffi.new("uint32_t[32]", [c for ln in lanes for c in ln["t2"]])
    ab = ffi.new("int32_t[16]", [v for ln in lanes for v in (ln["a"], ln["b"])])
    frac = ffi.new("int64_t[8]", [ln["f"] for ln in lanes])
    w = ffi.new("int32_t[24]", [x for ln in lanes for x in ln["w"]])
    t_row = ffi.new("int64_t[4]", [_threshold(x) for x in range(4)])
    out = ffi.new("uint32_t[8]")
    ok = lib.gles_debug_fog_write_texels(tex1, tex2, ab, two, frac, w, ffi.new("int32_t[3]", fog),
                                         ffi.new("int64_t[3]", fc), rgb565, dither, t_row, out)
    assert ok >= 0, "the kernel did not run"
    return ok, list(out)


def _group_params(rng: np.random.Generator) -> tuple[list[int], list[int]]:
    fog = [int(x) for x in rng.integers(-2 * 65536, 2 * 65536 + 1, size=3)]
    fc = [int(x) for x in rng.integers(0, ONE + 1, size=3)]
    return fog, fc


def _check(lanes, fog, fc, rgb565, dither) -> tuple[int, int]:
    ok, out = _run(lanes, fog, fc, rgb565, dither)
    for i, lane in enumerate(lanes):
        if (ok >> i) & 1:
            want = _pixel(_fogged(lane, fog, fc), i, rgb565, dither)
            assert out[i] == want, f"lane {i}: {out[i]:#x} != {want:#x} ({lane}, fog {fog}, fc {fc})"
    return bin(ok).count("1"), len(lanes)


TARGETS = [(0, 0), (1, 1), (1, 0)]      # RGBA8888, RGB565 dithered, RGB565 not


@pytest.mark.parametrize("two", [0, 1])
@pytest.mark.parametrize("rgb565, dither", TARGETS)
def test_random_groups_match_the_integer_model(two, rgb565, dither):
    """Random texels, weights, fractions, fog factors and colours: every
    proved pixel is the model's, and nearly all are proved."""
    rng = np.random.default_rng(40 + 2 * two + rgb565 + dither)
    proved = total = 0
    for _ in range(300):
        fog, fc = _group_params(rng)
        p, t = _check([_lane(rng, two) for _ in range(8)], fog, fc, rgb565, dither)
        proved += p
        total += t
    assert proved >= 0.97 * total, f"only {proved} of {total} proved"


@pytest.mark.parametrize("two", [0, 1])
@pytest.mark.parametrize("rgb565, dither", TARGETS)
def test_fragments_near_the_rounding_points(two, rgb565, dither):
    """Fragments drawn until a channel lies within 2^-10 of its rounding
    point (the proof's margin is 2^-11, its bound about 2^-11.7): where the
    kernel proves one, the pixel is the model's; most of the nearest go to
    the exact code."""
    rng = np.random.default_rng(70 + 2 * two + rgb565 + dither)
    proved = total = groups = 0
    while groups < 16:
        fog, fc = _group_params(rng)
        if max(fog) <= 0:           # (a fog factor of 0 everywhere: RGB565's channels are the fog colour's)
            continue
        lanes = []
        for _ in range(8000):
            lane = _lane(rng, two)
            if _tie_distance(_fogged(lane, fog, fc), len(lanes), rgb565, dither) < 2 ** -10:
                lanes.append(lane)
                if len(lanes) == 8:
                    break
        if len(lanes) < 8:
            continue
        groups += 1
        p, t = _check(lanes, fog, fc, rgb565, dither)
        proved += p
        total += t
    assert total - proved >= total // 4, "the lanes near a rounding point were proved too often"


def test_weights_far_outside_the_triangle_take_the_exact_code():
    """Weights whose magnitudes sum past 1 + 2^-7 are left to the exact code."""
    rng = np.random.default_rng(5)
    fog, fc = _group_params(rng)
    lanes = [_lane(rng, 1, far_weights=True) for _ in range(8)]
    for lane in lanes:
        lane["w"][0] = 2 * ONE - 1
    ok, _ = _run(lanes, fog, fc, 0, 0)
    assert ok == 0


def test_arguments_out_of_range_are_refused():
    """A weight of 65536, a fraction of 1 or a fog factor past 2 is refused (-1)."""
    rng = np.random.default_rng(6)
    fog, fc = _group_params(rng)
    lanes = [_lane(rng, 1) for _ in range(8)]
    lanes[3]["a"] = 65536
    with pytest.raises(AssertionError):
        _run(lanes, fog, fc, 0, 0)
    lanes[3]["a"] = 0
    lanes[2]["f"] = ONE
    with pytest.raises(AssertionError):
        _run(lanes, fog, fc, 0, 0)
    lanes[2]["f"] = 0
    with pytest.raises(AssertionError):
        _run(lanes, [3 * 65536, 0, 0], fc, 0, 0)
