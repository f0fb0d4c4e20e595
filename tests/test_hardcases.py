"""The hard cases of gles.hardcases: every scene on every build, the fixed
build against double, and the range checks against the rules.

* Every scene runs on the fixed, float and double builds (and on Mesa
  llvmpipe where it is available) with no exception and no GL error, and
  draws the same frame each time ``frame()`` is called.
* The fixed picture holds no wraparound garbage. The double build is an
  independent reference (the same C code in IEEE double). Honest 16.16 errors
  move edges by a fraction of a pixel and change colours by a step or two;
  wraparound puts colours where the reference has none (geometry on the wrong
  side of the window, a region of the wrong colour). The check (see
  ``garbage``) allows the first and catches the second. Where a case differs
  more for a reason we can state, it is compared with that reason made exact
  instead: the composite scale 16.16 keeps (vertices_near_limit), the scroll
  it accumulates (texture_scroll_1e5), the vertex rounding a scale of 1000
  magnifies (rule_breaking_matrices, bit for bit), and a bound on the
  texture-coordinate error as q -> 0 (projective_q_to_0).
* The fixed build's range checks report overflow, underflow and rule-breaking
  draws exactly when the case says; the case's flags are themselves derived
  here from the rules by an independent recorder of the calls (``RuleOracle``).
* ``range_check="raise"`` refuses the call and leaves state unchanged;
  ``"clamp"`` renders without warnings.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from functools import cache
from typing import Any, Callable

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import hardcases as H
from gles import mesa
from gles.profile import RangeError, RangeWarning

SIZE = 64
BUILDS = ("fixed", "float", "double")
NAMES = list(H.HARD_CASES)

# a known defect of the fixed build, reproduced by test_fixed_frustum_depth_term below:
# glFrustumf computes -2fn/(f-n) as -(2f) * (n/(f-n)), and n/(f-n) = 0.001/32768 rounds
# to 0 in 16.16, so every window depth is the far plane and LESS rejects every fragment

# {====================================================================
# an independent recorder of what the range checks must report

UNDERFLOW_AT = 2.0 ** -17


def _value_kind(x: float) -> str | None:
    """The per-value rule as stated: |x| >= 32768 (or NaN) overflows, nonzero |x| <= 2^-17 underflows."""
    if math.isnan(x) or abs(x) >= 32768.0:
        return "overflow"
    if x != 0.0 and abs(x) <= UNDERFLOW_AT:
        return "underflow"
    return None


def _rotation(angle: float, x: float, y: float, z: float) -> np.ndarray:
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    s, c = math.sin(math.radians(angle)), math.cos(math.radians(angle))
    return np.array([[x * x * (1 - c) + c, x * y * (1 - c) - z * s, x * z * (1 - c) + y * s, 0],
                     [y * x * (1 - c) + z * s, y * y * (1 - c) + c, y * z * (1 - c) - x * s, 0],
                     [x * z * (1 - c) - y * s, y * z * (1 - c) + x * s, z * z * (1 - c) + c, 0],
                     [0, 0, 0, 1]])


class RuleOracle:
    """Wraps a command set and forwards every call, recording in double the
    matrices the application builds and the vertex arrays it draws, so as to
    count, from the calls alone, the events the range checks must report:
    per value, the reals of the float commands (Python floats and float
    arrays; integer arguments are enums); per draw, c*s + t >= 16384."""

    def __init__(self, gl: Any) -> None:
        self._gl = gl
        self._mode = C.GL_MODELVIEW
        self._stacks: dict[int, list[np.ndarray]] = {
            mode: [np.eye(4)] for mode in (C.GL_MODELVIEW, C.GL_PROJECTION, C.GL_TEXTURE)}
        self._vertex: tuple[int, np.ndarray] | None = None
        self.counts = {"overflow": 0, "underflow": 0, "rule": 0}
        self.worst_rule = 0.0

    # matrices, as §2.10.2 defines them
    def _mult(self, m: np.ndarray) -> None:
        st = self._stacks[self._mode]
        st[-1] = st[-1] @ m

    def _on_glMatrixMode(self, mode: int) -> None:
        self._mode = int(mode)

    def _on_glLoadIdentity(self) -> None:
        self._stacks[self._mode][-1] = np.eye(4)

    def _on_glPushMatrix(self) -> None:
        st = self._stacks[self._mode]
        st.append(st[-1].copy())

    def _on_glPopMatrix(self) -> None:
        self._stacks[self._mode].pop()

    def _on_glLoadMatrixf(self, m: Any) -> None:
        self._stacks[self._mode][-1] = np.asarray(m, np.float64).reshape(4, 4).T

    def _on_glMultMatrixf(self, m: Any) -> None:
        self._mult(np.asarray(m, np.float64).reshape(4, 4).T)

    def _on_glTranslatef(self, x: float, y: float, z: float) -> None:
        m = np.eye(4)
        m[:3, 3] = (x, y, z)
        self._mult(m)

    def _on_glScalef(self, x: float, y: float, z: float) -> None:
        self._mult(np.diag([x, y, z, 1.0]))

    def _on_glRotatef(self, angle: float, x: float, y: float, z: float) -> None:
        self._mult(_rotation(angle, x, y, z))

    def _on_glOrthof(self, l: float, r: float, b: float, t: float, n: float, f: float) -> None:  # noqa: E741
        self._mult(np.array([[2 / (r - l), 0, 0, -(r + l) / (r - l)], [0, 2 / (t - b), 0, -(t + b) / (t - b)],
                             [0, 0, -2 / (f - n), -(f + n) / (f - n)], [0, 0, 0, 1]]))

    def _on_glFrustumf(self, l: float, r: float, b: float, t: float, n: float, f: float) -> None:  # noqa: E741
        self._mult(np.array([[2 * n / (r - l), 0, (r + l) / (r - l), 0],
                             [0, 2 * n / (t - b), (t + b) / (t - b), 0],
                             [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)],
                             [0, 0, -1, 0]]))

    # the vertex array and the draws
    def _on_glVertexPointer(self, size: int, type_: int, stride: int, pointer: Any) -> None:
        assert type_ == C.GL_FLOAT and stride == 0, "the oracle reads tightly packed float vertices only"
        self._vertex = (int(size), np.asarray(pointer, np.float64).reshape(-1, int(size)))

    def _rule(self, verts: np.ndarray) -> None:
        pmv = self._stacks[C.GL_PROJECTION][-1] @ self._stacks[C.GL_MODELVIEW][-1]
        s = float(np.abs(pmv[:3, :3]).max())
        t = float(np.abs(pmv[:, 3]).max())
        c = float(np.abs(verts).max()) if verts.size else 0.0
        lhs = c * s + t
        self.worst_rule = max(self.worst_rule, lhs)
        if lhs >= 16384.0:
            self.counts["rule"] += 1

    def _on_glDrawArrays(self, mode: int, first: int, count: int) -> None:
        assert self._vertex is not None
        self._rule(self._vertex[1][first:first + count])

    def _on_glDrawElements(self, mode: int, count: int, type_: int, indices: Any) -> None:
        assert self._vertex is not None
        self._rule(self._vertex[1][np.asarray(indices, np.int64)[:count]])

    def _values(self, name: str, args: tuple) -> None:
        if not (name.endswith("f") or name.endswith("fv") or name == "glClearColor"):
            return
        for a in args:
            if isinstance(a, float):
                vals: list[float] = [a]
            elif isinstance(a, np.ndarray) and a.dtype.kind == "f":
                vals = [float(v) for v in a.reshape(-1)]
            else:
                continue      # an enum, an integer
            for v in vals:
                kind = _value_kind(v)
                if kind:
                    self.counts[kind] += 1

    def __getattr__(self, name: str) -> Any:
        fn = getattr(self._gl, name)
        if not name.startswith("gl") or not callable(fn):
            return fn
        hook: Callable[..., None] | None = getattr(self, "_on_" + name, None)

        def call(*args: Any) -> Any:
            self._values(name, args)
            out = fn(*args)
            if hook is not None:
                hook(*args)
            return out
        return call


# {====================================================================
# rendering, once per case and build

@dataclass
class Rendered:
    image: np.ndarray                  # uint8 (h, w, 4), top row first
    second: np.ndarray                 # the image after a second frame()
    gl_error: int
    report: Any = None                 # RangeReport (fixed only)
    warned: int = 0                    # RangeWarnings issued (fixed only)
    oracle: RuleOracle | None = None   # fixed only


def render(scene: Callable[..., Any], numeric: str, size: int = SIZE, range_check: str | None = None,
           **kw: Any) -> Rendered:
    """Set the scene up and draw two frames on a new context of `numeric`; the
    fixed build runs with range checks on ("warn"), recorded by a RuleOracle."""
    if range_check is None:
        range_check = "warn" if numeric == "fixed" else "off"
    ctx = gles.Context(size, size, numeric=numeric, range_check=range_check)
    oracle = RuleOracle(ctx.gl) if numeric == "fixed" else None
    gl = oracle if oracle is not None else ctx.gl
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        frame = scene(gl, size, size, **kw)
        frame()
        first = ctx.image()
        frame()
        second = ctx.image()
    return Rendered(first, second, int(ctx.gl.glGetError()),
                    ctx.range_report() if numeric == "fixed" else None,
                    sum(issubclass(w.category, RangeWarning) for w in caught), oracle)


@cache
def rendered(name: str, numeric: str) -> Rendered:
    return render(H.HARD_CASES[name].scene, numeric)


# {====================================================================
# the wraparound check

def nearest_colour_error(a: np.ndarray, b: np.ndarray, r: int) -> np.ndarray:
    """Per pixel of `a`: the smallest max-channel difference (RGB) to any pixel of
    `b` within Chebyshev distance `r` (the window's border pixels repeated)."""
    a3 = a[..., :3].astype(np.int16)
    b3 = np.pad(b[..., :3].astype(np.int16), ((r, r), (r, r), (0, 0)), mode="edge")
    h, w = a3.shape[:2]
    best = np.full((h, w), 255, np.int16)
    for dy in range(2 * r + 1):
        for dx in range(2 * r + 1):
            best = np.minimum(best, np.abs(a3 - b3[dy:dy + h, dx:dx + w]).max(-1))
    return best


def erode(mask: np.ndarray, r: int = 1) -> np.ndarray:
    """Pixels whose whole (2r+1)^2 neighbourhood is in `mask` (outside counts as not)."""
    h, w = mask.shape
    p = np.pad(mask, r, constant_values=False)
    out = np.ones_like(mask)
    for dy in range(2 * r + 1):
        for dx in range(2 * r + 1):
            out &= p[dy:dy + h, dx:dx + w]
    return out


# Edges: every case draws at 64x64 with vertices computed from 16.16 clip
# coordinates, which put window positions within a small fraction of a pixel of
# double's (1/256 px in the clipping tests of docs/numerics.md, 0.25 px for the
# x1000 magnification of rule_breaking_matrices at this size). So every colour of
# one picture appears within SHIFT_PX = 1 pixel in the other, up to COLOUR_TOL.
SHIFT_PX = 1
# Colours: docs/numerics.md bounds every stage at one 8-bit step per rounding
# (lighting 0.8, fog 0.5 + 2^-8, texturing 2^-15 per filter, blending exact); a
# pixel goes through at most three roundings the builds can differ in (vertex
# colour, texture filter, framebuffer write): 3 steps. One more step covers a
# gradient sampled a fraction of a pixel away from where double samples it
# (the neighbourhood search only absorbs whole-pixel moves): 4 steps.
COLOUR_TOL = 4
# A feature thinner than a pixel (a sliver's tip, a ring 0.3 px wide) may cover a
# pixel centre in one build and not in the other; such pixels are isolated. Garbage
# is a region: we allow no 3x3 block of unmatched pixels, and isolated ones on at
# most 1% of the window.
ISOLATED_SHARE = 0.01
# Away from edges, where double's 3x3 neighbourhood spans at most FLAT_RANGE steps
# per channel, the pixels themselves must agree within FLAT_TOL: moving an edge or
# a gradient by up to a pixel changes such a pixel by at most FLAT_RANGE, and the
# builds' roundings add one step.
FLAT_RANGE = 2
FLAT_TOL = FLAT_RANGE + 1


def garbage(image: np.ndarray, reference: np.ndarray, rows: np.ndarray | None = None) -> list[str]:
    """What in `image` cannot be an honest 16.16 error against `reference`
    (both (h, w, 4) uint8, top row first); [] when nothing. `rows` limits the
    check to some rows (bool (h,), top row first)."""
    h, w = image.shape[:2]
    sel = np.ones((h, w), bool) if rows is None else np.repeat(rows[:, None], w, 1)
    unmatched = (np.maximum(nearest_colour_error(image, reference, SHIFT_PX),
                            nearest_colour_error(reference, image, SHIFT_PX)) > COLOUR_TOL) & sel
    problems = []
    blocks = erode(unmatched)
    if blocks.any():
        y, x = np.argwhere(blocks)[0]
        problems.append(f"{int(blocks.sum())} pixels inside 3x3 blocks of colours not found within "
                        f"{SHIFT_PX} px in the other picture, e.g. at (x={x}, y={y}): {image[y, x, :3]} "
                        f"against {reference[y, x, :3]}")
    if unmatched.sum() > ISOLATED_SHARE * sel.sum():
        problems.append(f"{int(unmatched.sum())} unmatched pixels, more than {ISOLATED_SHARE:.0%}")
    ref3 = reference[..., :3].astype(np.int16)
    pad = np.pad(ref3, ((1, 1), (1, 1), (0, 0)), mode="edge")
    lo = np.full_like(ref3, 255)
    hi = np.zeros_like(ref3)
    for dy in range(3):
        for dx in range(3):
            lo = np.minimum(lo, pad[dy:dy + h, dx:dx + w])
            hi = np.maximum(hi, pad[dy:dy + h, dx:dx + w])
    flat = ((hi - lo).max(-1) <= FLAT_RANGE) & sel
    err = np.abs(image[..., :3].astype(np.int16) - ref3).max(-1)
    if flat.any() and err[flat].max() > FLAT_TOL:
        y, x = np.argwhere(flat & (err == err[flat].max()))[0]
        problems.append(f"colour error {int(err[flat].max())} > {FLAT_TOL} away from edges, "
                        f"e.g. at (x={x}, y={y}): {image[y, x, :3]} against {reference[y, x, :3]}")
    return problems


@pytest.mark.parametrize("name", ["crossing_w0", "rule_breaking_matrices", "exp2_fog_dense"])
def test_garbage_check_itself(name: str) -> None:
    """The check passes what honest errors look like (the whole picture moved by a
    pixel, colours off by a step) and fails what wraparound looks like (geometry
    on the other side of the window, a block of wrong colour, a region missing)."""
    ref = rendered(name, "double").image
    h, w = ref.shape[:2]
    assert not garbage(ref, ref)
    assert not garbage(np.concatenate([ref[:, :1], ref[:, :-1]], axis=1), ref)      # moved 1 px right
    assert not garbage(np.concatenate([ref[1:], ref[-1:]], axis=0), ref)            # moved 1 px up
    step = ref.copy()
    step[..., :3] = np.clip(ref[..., :3].astype(int) + 1, 0, 255).astype(np.uint8)
    assert not garbage(step, ref)
    assert garbage(np.roll(ref, w // 2, axis=1), ref)
    assert garbage(ref[:, ::-1], ref)
    block = ref.copy()
    block[h // 3:h // 3 + 6, w // 3:w // 3 + 6, :3] = 255 - block[h // 3:h // 3 + 6, w // 3:w // 3 + 6, :3]
    assert garbage(block, ref)
    hole = ref.copy()
    hole[h // 2:h // 2 + 8, w // 4:w // 4 + 8] = ref[0, 0]
    assert garbage(hole, ref) or (ref[h // 2:h // 2 + 8, w // 4:w // 4 + 8] == ref[0, 0]).all()


# {====================================================================
# the table itself

def test_table() -> None:
    assert len(H.HARD_CASES) == 12
    for name, case in H.HARD_CASES.items():
        assert isinstance(case, H.HardCase)
        assert callable(case.scene) and case.scene.__name__ == name
        assert case.title and case.stresses.endswith(".")
        with pytest.raises(AttributeError):
            case.title = "x"  # type: ignore[misc]


# {====================================================================
# no crash, no GL error, the same frame every time

@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("name", NAMES)
def test_runs_without_gl_error(name: str, numeric: str) -> None:
    r = rendered(name, numeric)
    assert r.gl_error == 0, f"{name} on {numeric}: glGetError() = {r.gl_error:#x}"
    assert np.array_equal(r.image, r.second), f"{name} on {numeric}: frame() is not repeatable"


@pytest.mark.skipif(mesa.available("llvmpipe") is not None, reason=str(mesa.available("llvmpipe")))
@pytest.mark.parametrize("name", NAMES)
def test_runs_on_mesa(name: str) -> None:
    with mesa.MesaContext(SIZE, SIZE, driver="llvmpipe") as ctx:
        frame = H.HARD_CASES[name].scene(ctx.gl, SIZE, SIZE)
        frame()
        assert ctx.gl.glGetError() == 0
        px = ctx.gl.glReadPixels(0, 0, SIZE, SIZE, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
        tm = np.asarray(ctx.gl.glGetFloatv(C.GL_TEXTURE_MATRIX), np.float64).reshape(-1)
    ref = rendered(name, "double").image[::-1]
    if name == "texture_scroll_1e5":
        # Mesa accumulates the scroll in float32 and ends elsewhere (s near 129.88, not 130):
        # compare with the exact picture of the translation it reached
        ref = render(H.texture_scroll, "double", steps=1, step=(float(tm[12]), float(tm[13]))).image[::-1]
    # Mesa is another implementation (float32, 8-bit filter weights): only ask that it
    # drew a picture of the same kind, most pixels within a few steps of double
    close = np.abs(px[..., :3].astype(int) - ref[..., :3]).max(-1) <= 8
    assert close.mean() > 0.5, f"{name}: llvmpipe agrees with double on {close.mean():.0%} of pixels"


# {====================================================================
# no wraparound garbage in the fixed picture

def _generic(name: str) -> None:
    problems = garbage(rendered(name, "fixed").image, rendered(name, "double").image)
    assert not problems, f"{name}: " + "; ".join(problems)


GENERIC = [n for n in NAMES if n not in ("vertices_near_limit", "projective_q_to_0", "texture_scroll_1e5")]


@pytest.mark.parametrize("name", GENERIC)
def test_fixed_has_no_garbage(name: str) -> None:
    _generic(name)


def test_fixed_near_limit_is_the_16_16_composite_scale() -> None:
    """The composite scale of vertices_near_limit is 1/32000 = 2.048 units of 2^-16;
    16.16 keeps 2 (the ortho's 2/32000 = 4.096 units kept as 4, times the exact 1/2),
    so the fixed picture is the scene drawn exactly with an ortho of +-16384: 2.3%
    smaller than double's, edges up to 0.75 px in at this size and colours along
    the height field's steep gradients off by more than COLOUR_TOL. Against that
    exact picture, the generic check holds."""
    fixed = rendered("vertices_near_limit", "fixed").image
    exact = render(H.vertices_near_limit, "double", half_width=16384.0).image
    problems = garbage(fixed, exact)
    assert not problems, "; ".join(problems)
    # and the 2.3% is visible against double's own picture
    double = rendered("vertices_near_limit", "double").image
    assert not np.array_equal(fixed, double)


def test_fixed_scroll_is_the_16_16_sum_of_rounded_steps() -> None:
    """100000 glTranslatef(0.0013, 0.0007, 0): 16.16 holds each step as 85 and 46
    units of 2^-16 (85.197 and 45.875 rounded), and sums them exactly, so the
    fixed texture matrix translates by (8500000, 4600000) / 65536 = (129.6997,
    70.1904), 0.30 of a repeat behind in s and 0.19 ahead in t: its picture is
    double's with that single translation, bit for bit, and the fixed build's own
    with that single translation."""
    steps = H.SCROLL_STEPS
    acc = tuple(steps * round(v * 65536) / 65536 for v in H.SCROLL_STEP)
    assert acc == (8500000 / 65536, 4600000 / 65536)
    fixed = rendered("texture_scroll_1e5", "fixed").image
    one_fixed = render(H.texture_scroll, "fixed", steps=1, step=acc).image
    one_double = render(H.texture_scroll, "double", steps=1, step=acc).image
    assert np.array_equal(fixed, one_fixed)
    assert not garbage(fixed, one_double)
    assert np.abs(fixed[..., :3].astype(int) - one_double[..., :3]).max() <= 1
    # against the exact scroll (130, 70) the texture is visibly shifted
    double = rendered("texture_scroll_1e5", "double").image
    assert np.mean(np.abs(fixed[..., :3].astype(int) - double[..., :3]).max(-1) > 8) > 0.5


class _RoundedVertices:
    """A command set whose float vertex arrays are first rounded to 16.16 as the
    fixed build reads them (nearest, ties up: floor(x 2^16 + 1/2) / 2^16)."""

    def __init__(self, gl: Any) -> None:
        self._gl = gl
        self._kept: list[np.ndarray] = []

    def __getattr__(self, name: str) -> Any:
        fn = getattr(self._gl, name)
        if name != "glVertexPointer":
            return fn

        def pointer(size: int, type_: int, stride: int, data: Any) -> None:
            r = np.floor(np.asarray(data, np.float64) * 65536.0 + 0.5) / 65536.0
            self._kept.append(np.ascontiguousarray(r, np.float32))     # exact: 21 significant bits
            fn(size, type_, stride, self._kept[-1])
        return pointer


def test_fixed_rule_breaking_is_vertex_rounding_magnified() -> None:
    """rule_breaking_matrices breaks the rule by 4.9 times, yet no fixed-point
    intermediate leaves 16.16 (eye and clip coordinates stay within +-30000, and
    P*MV itself is exact), so the only difference from double is the 16.16
    rounding of the vertices, 2^-17 at most, which the scale of 1000 turns into
    0.0076 NDC (a quarter pixel here, a pixel at 256x256). Double, given the
    vertices the fixed build reads, draws the fixed picture bit for bit."""
    fixed = rendered("rule_breaking_matrices", "fixed").image
    ctx = gles.Context(SIZE, SIZE, numeric="double")
    gl = _RoundedVertices(ctx.gl)
    H.rule_breaking_matrices(gl, SIZE, SIZE)()
    assert np.array_equal(fixed, ctx.image())


def _paraboloid_q_rows(size: int) -> np.ndarray:
    """q at the centre of each pixel row, top row first: the grid's rows carry
    q = 1 + rz, interpolated linearly in y (orthographic, so w = 1)."""
    n = H.PARABOLOID_GRID
    q_vertex_rows = 1.0 + H.paraboloid_directions(n)[:, 0, 2]
    y = (np.arange(size) + 0.5) / size * n          # grid units from the bottom
    return np.interp(y, np.arange(n + 1), q_vertex_rows)[::-1]


def test_fixed_projective_q_to_0() -> None:
    """s/q as q -> 0. The fixed build's s and q at the vertices come out of the
    texture matrix within 2^-17 each, and are interpolated with 32 fraction bits,
    so s/q is off by at most 2^-17 (1 + s/q) / q; near the back pole
    s/q ~ 1/2 + 1/sqrt(2q), and the 64-texel texture turns that into
    E(q) = 64 * 2^-17 (1.5 + 1/sqrt(2q)) / q texels in each of s and t. A pixel may
    then be off by 1 (rounding) + 255 min(1, 2 E(q)) steps: 1.5 at q = 1/2, 11 at
    q = 0.05, 82 at q = 0.02. Rows with q >= 0.02 are held to that bound (and to
    the generic check where it allows no more than COLOUR_TOL); below, s/q
    passes 100 and the sample lands anywhere in the texture, so we ask only what
    every LINEAR sample of this texture keeps: R + G = 255 within one rounding."""
    fixed = rendered("projective_q_to_0", "fixed").image
    double = rendered("projective_q_to_0", "double").image
    q = _paraboloid_q_rows(SIZE)
    err = np.abs(fixed[..., :3].astype(int) - double[..., :3]).max(-1).max(-1)
    e = 64 * 2.0 ** -17 * (1.5 + 1.0 / np.sqrt(2 * np.maximum(q, 1e-9))) / np.maximum(q, 1e-9)
    bound = 1 + 255 * np.minimum(1.0, 2 * e)
    held = q >= 0.02
    bad = held & (err > bound)
    assert not bad.any(), f"rows {np.flatnonzero(bad)}: error {err[bad]} > bound {bound[bad]} (q = {q[bad]})"
    tight = bound <= COLOUR_TOL
    assert not garbage(fixed, double, rows=tight)
    for img in (fixed, double):
        rg = img[..., 0].astype(int) + img[..., 1]
        assert np.abs(rg - 255).max() <= 1
        assert (img[..., 3] == 255).all()


# {====================================================================
# range checks

@pytest.mark.parametrize("name", NAMES)
def test_range_checks_report_what_the_case_says(name: str) -> None:
    case = H.HARD_CASES[name]
    r = rendered(name, "fixed")
    counts = r.report.counts
    assert (counts["overflow"] > 0) == case.expect_overflow, counts
    assert (counts["underflow"] > 0) == case.expect_underflow, counts
    assert (counts["rule"] > 0) == case.expect_rule, counts
    assert r.warned == r.report.total, "under 'warn' every event warns"


@pytest.mark.parametrize("name", NAMES)
def test_case_flags_follow_from_the_rules(name: str) -> None:
    """The flags, rederived from the calls by RuleOracle, and the checks' counts
    event for event (two frames' draws, plus the setup)."""
    case = H.HARD_CASES[name]
    r = rendered(name, "fixed")
    assert r.oracle is not None
    o = r.oracle.counts
    assert (o["overflow"] > 0, o["underflow"] > 0, o["rule"] > 0) == (
        case.expect_overflow, case.expect_underflow, case.expect_rule), o
    assert r.report.counts == o


def test_rule_margins() -> None:
    """The margins the cases' docstrings state, from the oracle."""
    worst = {n: rendered(n, "fixed").oracle.worst_rule for n in NAMES}   # type: ignore[union-attr]
    assert worst["rule_breaking_matrices"] == pytest.approx(79864, abs=1)
    assert worst["vertices_near_limit"] == pytest.approx(32767 / 32000 + 1, rel=1e-6)
    assert 16000 < worst["huge_triangles"] < 16384
    assert all(v < 16384 for n, v in worst.items() if n != "rule_breaking_matrices")


def test_raise_refuses_and_leaves_state_unchanged() -> None:
    ctx = gles.Context(SIZE, SIZE, numeric="fixed", range_check="raise")
    gl = ctx.gl
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glFrustumf(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0)
    before = np.array(gl.glGetFloatv(C.GL_PROJECTION_MATRIX))
    with pytest.raises(RangeError, match="far"):
        gl.glFrustumf(-0.001, 0.001, -0.001, 0.001, 0.001, 1e5)
    assert np.array_equal(np.array(gl.glGetFloatv(C.GL_PROJECTION_MATRIX)), before)
    assert gl.glGetError() == 0
    with pytest.raises(RangeError, match="underflow|rounds to 0"):
        gl.glTranslatef(1e-6, 0.0, 0.0)
    assert np.array_equal(np.array(gl.glGetFloatv(C.GL_PROJECTION_MATRIX)), before)
    assert ctx.range_report().counts == {"overflow": 1, "underflow": 1, "rule": 0}


def test_raise_refuses_a_draw_that_breaks_the_rule() -> None:
    """rule_breaking_matrices under "raise": its first draw raises and draws nothing."""
    ctx = gles.Context(SIZE, SIZE, numeric="fixed", range_check="raise")
    frame = H.rule_breaking_matrices(ctx.gl, SIZE, SIZE)
    with pytest.raises(RangeError, match="c\\*s \\+ t"):
        frame()
    img = ctx.image()
    assert (img == img[0, 0]).all(), "a refused draw drew something"
    assert ctx.gl.glGetError() == 0


@pytest.mark.parametrize("name", ["near_far_extreme", "rule_breaking_matrices"])
def test_clamp_renders_without_warnings(name: str) -> None:
    """Under "clamp" the scene renders, warns of nothing, and counts the same events;
    the far plane 1e5 becomes 32767.99998, which is what the core's own saturation
    gives under "warn", so the pictures are the same."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = render(H.HARD_CASES[name].scene, "fixed", range_check="clamp")
    assert r.gl_error == 0 and r.warned == 0
    warn = rendered(name, "fixed")
    assert r.report.counts == warn.report.counts
    assert np.array_equal(r.image, warn.image)


# {====================================================================
# the defects the cases found, reproduced small

def test_fixed_frustum_depth_term() -> None:
    """Regression: the fixed build once computed -2fn/(f-n) as -(2f)(n/(f-n)), and
    n/(f-n) rounded to 0 for n = 0.001, f >= 131. glFrustumf(-1, 1, -1, 1, 0.001,
    1000) in every build: a quad at z = -2 under depth test LESS must be drawn
    (its depth is 1 - 0.001/2, not the far plane)."""
    covered = {}
    for numeric in BUILDS:
        ctx = gles.Context(16, 16, numeric=numeric)
        gl = ctx.gl
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glFrustumf(-0.001, 0.001, -0.001, 0.001, 0.001, 1000.0)
        gl.glMatrixMode(C.GL_MODELVIEW)
        v = np.array([-1, -1, -2, 1, -1, -2, 1, 1, -2, -1, 1, -2], np.float32)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
        gl.glColor4f(1.0, 1.0, 1.0, 1.0)
        gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, 4)
        covered[numeric] = int((ctx.image()[..., 0] > 0).sum())
    assert covered["double"] == 64
    assert covered["fixed"] == covered["double"], covered


def test_fixed_ortho_wide_extent() -> None:
    """Regression: r - l = 40000 does not fit 16.16, but 2/(r - l) does; the fixed
    build once saturated r - l and drew the picture 22% too large. Now each
    element is one rounded ratio: 2/40000 = 3.28 units of 2^-16, kept as 3, so
    a quad at +-10000 covers 2 * 10000 * 3/65536 * 16 = 14.6 -> 14 px of 32."""
    sizes = {}
    for numeric in BUILDS:
        ctx = gles.Context(32, 32, numeric=numeric, range_check="off")
        gl = ctx.gl
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glOrthof(-20000, 20000, -20000, 20000, -1, 1)
        gl.glMatrixMode(C.GL_MODELVIEW)
        v = np.array([-10000, -10000, 10000, -10000, 10000, 10000, -10000, 10000], np.float32)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
        gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, 4)
        sizes[numeric] = int((ctx.image()[..., 0] > 0).sum(axis=1).max())
    assert sizes["double"] == sizes["float"] == 16
    assert sizes["fixed"] == 14
