"""The numeric layer (csrc/num.h) through gles_num_eval.

The fixed build's NUM is s15.16. An input that is a multiple of 2^-16 in
range converts exactly, so every property is checked against exact integer
arithmetic on the raw 32-bit values (never against the code under test):
errors are measured in LSB = 2^-16. The float and double builds are checked
against IEEE arithmetic (numpy float32 / Python float), which rounds each
operation correctly.

The largest errors seen are collected in MAX_ERRORS and printed at the end
of the module (visible with ``pytest -s``).
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest
from conftest import BUILDS
from hypothesis import given, settings
from hypothesis import strategies as st

from gles import _binding

LSB = 2.0**-16
RAW_MIN, RAW_MAX = -(2**31), 2**31 - 1

FIX = _binding.core("fixed").lib
OP = {name: getattr(FIX, f"GLES_NUMOP_{name}") for name in (
    "FROM", "ADD", "SUB", "MUL", "DIV", "RECIP", "SQRT", "RSQRT", "SIN_DEG", "COS_DEG",
    "TO_UNORM8", "FROM_UNORM8")}

# name -> largest error seen (LSB unless the key says otherwise)
MAX_ERRORS: dict[str, float] = {}

raw32 = st.integers(RAW_MIN, RAW_MAX)
# values that keep products and quotients in range more often
raw_mid = st.integers(-(2**24), 2**24)


def record(key: str, value: float) -> None:
    """Remember the largest value seen under `key`."""
    if value > MAX_ERRORS.get(key, -1.0):
        MAX_ERRORS[key] = float(value)


@pytest.fixture(scope="module", autouse=True)
def _report_errors():
    """Print the measured error maxima once the module's tests have run."""
    yield
    print("\nnumeric max errors:", json.dumps(dict(sorted(MAX_ERRORS.items())), indent=1))


def fx(op: str, a_raw: int, b_raw: int = 0) -> int:
    """Apply a fixed-build op to raw 16.16 inputs; return the raw 16.16 result."""
    r = FIX.gles_num_eval(OP[op], a_raw * LSB, b_raw * LSB)
    raw = r * 65536.0
    assert raw == math.floor(raw), f"result {r!r} is not a multiple of 2^-16"
    return int(raw)


def check_rounded(key: str, got_raw: int, exact_raw: Fraction) -> None:
    """got is exact rounded to nearest, or saturated when exact is out of range."""
    if exact_raw > RAW_MAX:
        assert got_raw == RAW_MAX, f"{key}: exact {float(exact_raw) * LSB} must saturate to the maximum"
        return
    if exact_raw < RAW_MIN:
        assert got_raw == RAW_MIN, f"{key}: exact {float(exact_raw) * LSB} must saturate to the minimum"
        return
    err = abs(got_raw - exact_raw)
    record(key, float(err))
    assert err <= Fraction(1, 2), f"{key}: error {float(err)} LSB > 1/2"


# {================================================================
# fixed build: the four operations


def test_from_double_is_exact_on_the_grid():
    """Multiples of 2^-16 in range convert exactly (the premise of every test below)."""
    for raw in (0, 1, -1, 12345, -98765, RAW_MAX, RAW_MIN, 65536, -65536):
        assert fx("FROM", raw) == raw


def test_from_double_rounds_to_nearest():
    """Off-grid doubles round to the nearest multiple of 2^-16 (1/3 -> 21845)."""
    got = FIX.gles_num_eval(OP["FROM"], 1.0 / 3.0, 0.0) * 65536
    assert got == 21845
    got = FIX.gles_num_eval(OP["FROM"], -1.0 / 3.0, 0.0) * 65536
    assert got == -21845


@settings(max_examples=200, deadline=None)
@given(raw32, raw32)
def test_add_sub_exact_or_saturated(a, b):
    """Sums and differences are exact in range and saturate outside it."""
    check_rounded("add", fx("ADD", a, b), Fraction(a + b))
    check_rounded("sub", fx("SUB", a, b), Fraction(a - b))
    assert MAX_ERRORS.get("add", 0) == 0 and MAX_ERRORS.get("sub", 0) == 0


@settings(max_examples=200, deadline=None)
@given(st.one_of(raw32, raw_mid), st.one_of(raw32, raw_mid))
def test_mul_rounds_to_nearest(a, b):
    """a*b is within half an LSB of the exact product (one rounding), or saturated."""
    check_rounded("mul", fx("MUL", a, b), Fraction(a * b, 65536))


@settings(max_examples=200, deadline=None)
@given(st.one_of(raw32, raw_mid), st.one_of(raw32, raw_mid).filter(lambda v: v != 0))
def test_div_rounds_to_nearest(a, b):
    """a/b is within half an LSB of the exact quotient, or saturated."""
    check_rounded("div", fx("DIV", a, b), Fraction(a * 65536, b))


@settings(max_examples=200, deadline=None)
@given(raw32.filter(lambda v: v != 0))
def test_recip_rounds_to_nearest(a):
    """1/a is within half an LSB of the exact reciprocal, or saturated (|a| < 2^-15)."""
    check_rounded("recip", fx("RECIP", a), Fraction(2**32, a))


# {================================================================
# fixed build: square roots


@settings(max_examples=200, deadline=None)
@given(st.integers(0, RAW_MAX))
def test_sqrt_within_half_lsb(a):
    """sqrt(a) is the nearest 16.16 value: |r - sqrt(a * 2^16)| <= 1/2 in raw units."""
    r = fx("SQRT", a)
    v = a * 65536  # the raw result is sqrt(v)
    # (r - 1/2)^2 <= v <= (r + 1/2)^2, in integers (no lower bound for r = 0)
    assert r >= 0 and 4 * v <= (2 * r + 1) ** 2, (a, r)
    assert r == 0 or (2 * r - 1) ** 2 <= 4 * v, (a, r)
    if a:
        record("sqrt", abs(r - math.sqrt(v)))


def test_sqrt_of_non_positive_is_zero():
    """sqrt is defined as 0 for 0 and negative inputs (no trap, §2.1.1)."""
    assert fx("SQRT", 0) == 0
    assert fx("SQRT", -65536) == 0


@settings(max_examples=300, deadline=None)
@given(st.one_of(st.integers(1, 255), st.integers(256, RAW_MAX)))
def test_rsqrt(a):
    """1/sqrt(a) is within 1 LSB of exact for inputs >= 2^-8; smaller inputs give
    large results, recorded as relative error (they must stay within 1 LSB too,
    since the result 2^24/sqrt(a) <= 2^24 fits in range)."""
    r = fx("RSQRT", a)
    exact = 2**24 / math.sqrt(a)  # raw units; double is accurate to ~2^-28 raw here
    err = abs(r - exact)
    if a >= 256:
        record("rsqrt (input >= 2^-8)", err)
        assert err <= 1.0, (a, r, exact)
    else:
        record("rsqrt (input < 2^-8)", err)
        record("rsqrt relative (input < 2^-8)", err / exact)
        assert err <= 1.0, (a, r, exact)


def test_rsqrt_of_non_positive_saturates():
    """1/sqrt(0) is +infinity: the fixed build saturates to the maximum."""
    assert fx("RSQRT", 0) == RAW_MAX
    assert fx("RSQRT", -5) == RAW_MAX


# {================================================================
# fixed build: sine and cosine of degrees


def exact_sincos(a_raw: int) -> tuple[float, float]:
    """sin and cos of a_raw / 65536 degrees, reduced exactly in integers first."""
    full = 360 * 65536
    red = a_raw % full  # exact, in [0, 360) degrees * 65536
    rad = red / 65536.0 * (math.pi / 180.0)
    return math.sin(rad), math.cos(rad)


@settings(max_examples=300, deadline=None)
@given(st.integers(-3600 * 65536, 3600 * 65536))
def test_sin_cos_deg_within_2_lsb(a):
    """sin and cos of degrees in [-3600, 3600] are within 2 LSB of exact."""
    s_exact, c_exact = exact_sincos(a)
    s = fx("SIN_DEG", a) * LSB
    c = fx("COS_DEG", a) * LSB
    es, ec = abs(s - s_exact) / LSB, abs(c - c_exact) / LSB
    record("sin_deg", es)
    record("cos_deg", ec)
    assert es <= 2.0 and ec <= 2.0, (a * LSB, s, s_exact, c, c_exact)


def test_sin_cos_exact_at_quadrants():
    """Multiples of 90 degrees give exact 0 and +-1 (the reduction is exact)."""
    for k in range(-40, 41):
        deg = 90 * k
        s = fx("SIN_DEG", deg * 65536)
        c = fx("COS_DEG", deg * 65536)
        assert (s, c) == [(0, 65536), (65536, 0), (0, -65536), (-65536, 0)][k % 4], deg


# {================================================================
# fixed build: saturation at the ends of the range


def ev(op: str, a: float, b: float = 0.0) -> float:
    return FIX.gles_num_eval(OP[op], a, b)


def test_saturation_not_wraparound():
    """Results beyond s15.16 saturate with the right sign instead of wrapping (§2.1.1)."""
    top, bottom = RAW_MAX * LSB, RAW_MIN * LSB
    assert top == pytest.approx(32767.99998, abs=1e-5)
    assert ev("MUL", 30000, 30000) == top
    assert ev("MUL", -30000, 30000) == bottom
    assert ev("MUL", -30000, -30000) == top
    assert ev("ADD", 30000, 30000) == top
    assert ev("ADD", -30000, -30000) == bottom
    assert ev("SUB", -30000, 30000) == bottom
    assert ev("SUB", 30000, -30000) == top
    assert ev("DIV", 30000, 0.5) == top
    assert ev("DIV", -30000, 0.5) == bottom
    assert ev("RECIP", LSB) == top
    assert ev("RECIP", -LSB) == bottom
    assert ev("FROM", 1e9) == top
    assert ev("FROM", -1e9) == bottom


def test_division_by_zero():
    """x/0 saturates with the sign of x; 0/0 is 0 (defined, never a trap)."""
    assert ev("DIV", 5.0, 0.0) == RAW_MAX * LSB
    assert ev("DIV", -5.0, 0.0) == RAW_MIN * LSB
    assert ev("DIV", LSB, 0.0) == RAW_MAX * LSB
    assert ev("DIV", 0.0, 0.0) == 0.0
    assert ev("RECIP", 0.0) == RAW_MAX * LSB


# {================================================================
# every build


@pytest.mark.parametrize("numeric", BUILDS)
def test_unorm8_round_trip(numeric):
    """c -> c/255 -> c is exact for all 256 ubyte values (the framebuffer must hold
    exactly the input's bits with lighting off, §2.1.1 / Table 2.7)."""
    lib = _binding.core(numeric).lib
    worst = 0.0
    for c in range(256):
        v = lib.gles_num_eval(OP["FROM_UNORM8"], float(c), 0.0)
        worst = max(worst, abs(v - c / 255.0))
        back = lib.gles_num_eval(OP["TO_UNORM8"], v, 0.0)
        assert back == c, (numeric, c, v, back)
    # c/255 itself is rounded once to the build's precision
    bound = {"fixed": LSB / 2, "float": 2.0**-25, "double": 2.0**-54}[numeric]
    record(f"from_unorm8 {numeric} (absolute)", worst)
    assert worst <= bound


@pytest.mark.parametrize("numeric", BUILDS)
def test_to_unorm8_rounds_to_nearest(numeric):
    """x in [0, 1] -> round(255 x), clamped outside [0, 1]."""
    lib = _binding.core(numeric).lib
    rng = np.random.default_rng(7)
    for raw in rng.integers(0, 65537, size=2000):
        x = int(raw) * LSB
        got = lib.gles_num_eval(OP["TO_UNORM8"], x, 0.0)
        exact = Fraction(int(raw) * 255, 65536)
        assert abs(got - exact) <= Fraction(1, 2), (numeric, x, got)
    assert lib.gles_num_eval(OP["TO_UNORM8"], -0.5, 0.0) == 0
    assert lib.gles_num_eval(OP["TO_UNORM8"], 1.5, 0.0) == 255


f32 = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, width=32)


@settings(max_examples=100, deadline=None)
@given(f32, f32)
def test_float_build_is_ieee_single(a, b):
    """The float build's operations are IEEE single precision, correctly rounded."""
    lib = _binding.core("float").lib
    a32, b32 = np.float32(a), np.float32(b)
    with np.errstate(over="ignore"):
        quotient = float(a32 / b32) if b32 != 0 else None
    assert lib.gles_num_eval(OP["ADD"], a, b) == float(a32 + b32)
    assert lib.gles_num_eval(OP["SUB"], a, b) == float(a32 - b32)
    assert lib.gles_num_eval(OP["MUL"], a, b) == float(a32 * b32)
    if quotient is not None:
        assert lib.gles_num_eval(OP["DIV"], a, b) == quotient
    if a32 > 0:
        assert lib.gles_num_eval(OP["SQRT"], a, 0.0) == float(np.sqrt(a32))


@settings(max_examples=100, deadline=None)
@given(st.floats(-1e12, 1e12, allow_nan=False), st.floats(-1e12, 1e12, allow_nan=False))
def test_double_build_is_ieee_double(a, b):
    """The double build's operations are IEEE double precision, correctly rounded."""
    lib = _binding.core("double").lib
    assert lib.gles_num_eval(OP["ADD"], a, b) == a + b
    assert lib.gles_num_eval(OP["SUB"], a, b) == a - b
    assert lib.gles_num_eval(OP["MUL"], a, b) == a * b
    if b != 0:
        assert lib.gles_num_eval(OP["DIV"], a, b) == a / b
    if a > 0:
        assert lib.gles_num_eval(OP["SQRT"], a, 0.0) == math.sqrt(a)
