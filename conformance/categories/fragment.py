"""Per-fragment operations and fog: APFunc, Blend, Dither, LogicOp, Mask.stencil,
Scissor, SPClear, SPCorner, SPFunc, SPOp and Fog (spec sections 3.8, 4.1, 4.2).

Every test uses Common-Lite commands only (x forms; GL_FIXED and
GL_UNSIGNED_BYTE arrays) and draws with ``t.ortho_pixels()`` rectangles whose
edges lie on pixel boundaries, so coverage is exact and only the operation
under test decides a pixel. Colours are checked with the visual's tolerance
(one step per channel); stencil values, logic-op bits and pass/fail patterns
exactly, because the rules leave no freedom there. ES has no stencil
read-back: stencil values are read by drawing with StencilFunc(EQUAL, v)
for each candidate v.

Expected values come from the spec's formulas: Table 4.1 for blending
(computed from the destination as read back, with Ad = 1 when the buffer has
no alpha, §4.1.7), Table 4.2 for logic ops, §4.1.5 for stencil, equations
3.22-3.24 for fog. Optional extensions (OES_blend_subtract,
OES_blend_func_separate, OES_blend_equation_separate, OES_stencil_wrap) are
tested where GL_EXTENSIONS names them.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ..harness import TestContext, conformance_test

ONE = 1 << 16
RGBA_VISUALS = ("rgba8888", "rgb565", "rgba4444", "rgba5551")
ALL_VISUALS = ("rgba8888", "rgba8888-d16", "rgb565", "rgba4444", "rgba5551")

FUNCS: dict[str, Callable[[Any, Any], Any]] = {
    "GL_NEVER": lambda a, b: np.zeros(np.broadcast(a, b).shape, dtype=bool),
    "GL_LESS": np.less,
    "GL_EQUAL": np.equal,
    "GL_LEQUAL": np.less_equal,
    "GL_GREATER": np.greater,
    "GL_NOTEQUAL": np.not_equal,
    "GL_GEQUAL": np.greater_equal,
    "GL_ALWAYS": lambda a, b: np.ones(np.broadcast(a, b).shape, dtype=bool),
}


# {============================================================
# helpers

def _fx(v: float) -> int:
    return int(round(v * ONE))


def _rect(t: TestContext, x0: float, y0: float, x1: float, y1: float, *, z: float = 0.0,
          colors: Any = None) -> None:
    """Fill [x0, x1] x [y0, y1] (window pixels) at object z (window depth (1 - z)/2)."""
    gl = t.gl
    a, b, c, d = (x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)
    t.draw(gl.GL_TRIANGLES, [a, b, c, a, c, d], colors, size=3)


def _full(t: TestContext, rgba: Sequence[int] = (255, 255, 255, 255), z: float = 0.0) -> None:
    t.gl.glColor4ub(*rgba)
    _rect(t, 0, 0, t.width, t.height, z=z)


def _region(t: TestContext, x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
    m = np.zeros((t.height, t.width), dtype=bool)
    m[max(y0, 0):max(y1, 0), max(x0, 0):max(x1, 0)] = True
    return m


def _cells(t: TestContext, colors: np.ndarray, *, z: float = 0.0) -> None:
    """Draw an n x n grid of cells covering the window, cell (i, j) (row i from the bottom) in
    ubyte colour colors[i, j]."""
    n = colors.shape[0]
    cw, ch = t.width // n, t.height // n
    verts, cols = [], []
    for i in range(n):
        for j in range(n):
            x0, y0, x1, y1 = j * cw, i * ch, (j + 1) * cw, (i + 1) * ch
            verts += [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y0, z), (x1, y1, z), (x0, y1, z)]
            cols += [colors[i, j]] * 6
    t.draw(t.gl.GL_TRIANGLES, verts, np.asarray(cols, dtype=np.uint8), size=3)


def _per_pixel(t: TestContext, cells: np.ndarray) -> np.ndarray:
    """Expand per-cell values (n, n, ...) to pixels (h, w, ...)."""
    n = cells.shape[0]
    return np.repeat(np.repeat(cells, t.height // n, axis=0), t.width // n, axis=1)


def _expect_image(t: TestContext, img: np.ndarray, want: np.ndarray, where: str, *,
                  extra: Any = 0.0) -> None:
    """Every pixel of `img` (as read) within one step (+ 2^-13, + `extra` steps) per channel of
    the exact `want` (h, w, 4), compared in the visual's shades: the stored shade k is recovered
    exactly from the 8-bit read-back, whose own rounding is not the GL's error."""
    tops = np.array([(1 << b) - 1 for b in t.visual.bits], dtype=np.float64)
    err = np.abs(_shades(t, img) - want * tops)
    bad = (err > 1.0 + tops * 2.0**-13 + extra).any(axis=-1)
    if bad.any():
        y, x = (int(v) for v in np.argwhere(bad)[0])
        t.fail(f"{where}: {int(bad.sum())} pixels off by more than one step; first at (x={x}, y={y}): "
               f"shades {_shades(t, img)[y, x].tolist()}, exact {np.round(want[y, x] * tops, 3).tolist()} "
               f"of {tops.astype(int).tolist()}")


def _blend_slack(t: TestContext) -> np.ndarray:
    """Extra steps allowed for a blended channel of fewer than 8 bits. §4.1.7 requires the
    implied conversion of a stored value to keep only 0 and 1 exact, and implementations blend
    such buffers through 8-bit values: the destination's conversion and the rounded 8-bit result
    (a factor up to 2 on the destination) move the value by up to 1.5/255, (2^b - 1) 1.5/255
    steps of the channel, before dithering picks one of the two neighbours."""
    return np.array([((1 << b) - 1) * 1.5 / 255 if 0 < b < 8 else 0.0 for b in t.visual.bits])


def _read_stored(t: TestContext) -> np.ndarray:
    """The colour buffer as the values k / (2^b - 1) it stores (alpha 1 without alpha bits, §4.1.7)."""
    tops = np.array([(1 << b) - 1 for b in t.visual.bits], dtype=np.float64)
    out = _shades(t, t.read()) / np.maximum(tops, 1)
    out[..., tops == 0] = 1.0
    return out


def _shades(t: TestContext, img: np.ndarray) -> np.ndarray:
    """Channel values as integer shades of the visual's bits (alpha of RGB565: 0)."""
    tops = np.array([(1 << b) - 1 for b in t.visual.bits])
    return np.rint(img * np.maximum(tops, 1)).astype(np.int64) * (tops > 0)


def _expect_state(t: TestContext, what: str, got: Any, want: Any, section: str) -> None:
    got_l, want_l = np.atleast_1d(np.asarray(got)).tolist(), np.atleast_1d(np.asarray(want)).tolist()
    if got_l != want_l:
        t.fail(f"{what} is {got_l}, expected {want_l} (§{section})")


def _stencil_values(t: TestContext, candidates: Sequence[int]) -> np.ndarray:
    """The stencil value of every pixel among `candidates` (-1 where none matches), read with
    StencilFunc(EQUAL, v, 0xFF): ES 1.1 cannot read the stencil buffer back. Leaves the stencil
    test enabled with KEEP operations and the depth test disabled."""
    gl = t.gl
    gl.glDisable(gl.GL_DEPTH_TEST)
    gl.glEnable(gl.GL_STENCIL_TEST)
    gl.glStencilOp(gl.GL_KEEP, gl.GL_KEEP, gl.GL_KEEP)
    gl.glColorMask(True, True, True, True)
    out = np.full((t.height, t.width), -1, dtype=np.int64)
    for v in candidates:
        gl.glClearColorx(0, 0, 0, 0)
        gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        gl.glStencilFunc(gl.GL_EQUAL, v, 0xFF)
        _full(t)
        hit = t.read()[..., 0] > 0.5
        if (hit & (out >= 0)).any():
            t.fail(f"stencil read-back: pixels match both {v} and another value")
        out[hit] = v
    return out


def _expect_stencil(t: TestContext, want: np.ndarray, where: str) -> None:
    got = _stencil_values(t, sorted(set(np.unique(want).tolist())))
    bad = got != want
    if bad.any():
        y, x = (int(v) for v in np.argwhere(bad)[0])
        found = "none of the expected values" if got[y, x] < 0 else f"0x{got[y, x]:02X}"
        t.fail(f"{where}: {int(bad.sum())} pixels with the wrong stencil value; first at (x={x}, y={y}): "
               f"{found}, expected 0x{want[y, x]:02X} (§4.1.5)")


def _set_stencil_bands(t: TestContext, values: Sequence[int]) -> np.ndarray:
    """Vertical bands of the window with the given stencil values (colour untouched); returns
    the (h, w) expected stencil image."""
    gl = t.gl
    n = len(values)
    bw = t.width // n
    gl.glStencilMask(0xFF)
    gl.glClearStencil(0)
    gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
    gl.glEnable(gl.GL_STENCIL_TEST)
    gl.glStencilOp(gl.GL_REPLACE, gl.GL_REPLACE, gl.GL_REPLACE)
    gl.glColorMask(False, False, False, False)
    gl.glDisable(gl.GL_DEPTH_TEST)
    want = np.zeros((t.height, t.width), dtype=np.int64)
    for i, v in enumerate(values):
        gl.glStencilFunc(gl.GL_ALWAYS, v, 0xFF)
        _rect(t, i * bw, 0, (i + 1) * bw, t.height)
        want[:, i * bw:(i + 1) * bw] = v
    gl.glColorMask(True, True, True, True)
    gl.glStencilOp(gl.GL_KEEP, gl.GL_KEEP, gl.GL_KEEP)
    return want


# {============================================================
# APFunc (§4.1.4)

@conformance_test("APFunc", section="4.1.4", uses=("alpha",), visuals=ALL_VISUALS)
def ap_func(t: TestContext) -> None:
    """Each alpha function against fragment alphas 0, 1/3, 2/3, 1 and references at those values
    (and clamped from outside [0, 1]): a quad passes exactly where the comparison holds."""
    gl = t.gl
    t.ortho_pixels()
    # alpha and reference are the same 16.16 values, so they stay equal, and k/3 stay ordered,
    # at whatever precision (at least 2 bits, §2.12.8) the GL compares them
    thirds = [_fx(k / 3) for k in range(4)]
    cw = t.width // 4
    gl.glEnable(gl.GL_ALPHA_TEST)
    for fname, fn in FUNCS.items():
        for ref in (0, 1, 2, 3, -3, 6):                # in thirds; -3 and 6 clamp to 0 and 3
            gl.glClearColorx(0, 0, 0, 0)
            gl.glClear(gl.GL_COLOR_BUFFER_BIT)
            gl.glAlphaFuncx(getattr(gl, fname), _fx(ref / 3) if ref in (-3, 6) else thirds[ref])
            _expect_state(t, "GL_ALPHA_TEST_FUNC", gl.glGetIntegerv(gl.GL_ALPHA_TEST_FUNC),
                          getattr(gl, fname), "4.1.4")
            for k in range(4):
                gl.glColor4x(ONE, ONE, ONE, thirds[k])
                _rect(t, k * cw, 0, (k + 1) * cw, t.height)
            clamped = min(max(ref, 0), 3)
            passes = np.repeat(fn(np.arange(4), clamped), cw)[None, :] & np.ones((t.height, 1), dtype=bool)
            drawn = t.read()[..., 0] > 0.5
            bad = drawn != passes
            if bad.any():
                y, x = (int(v) for v in np.argwhere(bad)[0])
                t.fail(f"AlphaFuncx({fname}, {ref}/3): fragment alpha {x // cw}/3 "
                       f"{'passed' if drawn[y, x] else 'failed'}, should have "
                       f"{'passed' if passes[y, x] else 'failed'} (reference clamped to {clamped}/3)")
    _expect_state(t, "GL_ALPHA_TEST_REF (set to 2, clamped when specified)",
                  gl.glGetFixedv(gl.GL_ALPHA_TEST_REF), ONE, "4.1.4")


@conformance_test("APFunc.precision", section="4.1.4", uses=("alpha",), visuals=("rgba8888",))
def ap_func_precision(t: TestContext) -> None:
    """With 8 alpha bits the reference is converted to 8 bits and the fragment alpha rounded
    (§4.1.4): an x-form reference k/255 equals alpha k, is above k - 1 and below k + 1."""
    gl = t.gl
    t.ortho_pixels()
    gl.glEnable(gl.GL_ALPHA_TEST)
    for k in (1, 64, 128, 200, 254):
        alphas = np.array([k - 1, k, k + 1, k])
        col = np.zeros((4, 4, 4), dtype=np.int64) + 255
        col[..., 3] = alphas[None, :]
        for fname, fn in FUNCS.items():
            gl.glClearColorx(0, 0, 0, 0)
            gl.glClear(gl.GL_COLOR_BUFFER_BIT)
            gl.glAlphaFuncx(getattr(gl, fname), _fx(k / 255))
            _cells(t, col)
            passes = _per_pixel(t, np.broadcast_to(fn(alphas, k), (4, 4)))
            drawn = t.read()[..., 0] > 0.5
            bad = drawn != passes
            if bad.any():
                y, x = (int(v) for v in np.argwhere(bad)[0])
                t.fail(f"AlphaFuncx({fname}, {_fx(k / 255)}/65536 = {k}/255 rounded to 16.16): alpha "
                       f"{alphas[x * 4 // t.width]}/255 {'passed' if drawn[y, x] else 'failed'}; at 8 bits "
                       f"the reference is {k}")


# {============================================================
# Blend (§4.1.7)

SRC_FACTORS = ("GL_ZERO", "GL_ONE", "GL_DST_COLOR", "GL_ONE_MINUS_DST_COLOR", "GL_SRC_ALPHA",
               "GL_ONE_MINUS_SRC_ALPHA", "GL_DST_ALPHA", "GL_ONE_MINUS_DST_ALPHA", "GL_SRC_ALPHA_SATURATE")
DST_FACTORS = ("GL_ZERO", "GL_ONE", "GL_SRC_COLOR", "GL_ONE_MINUS_SRC_COLOR", "GL_SRC_ALPHA",
               "GL_ONE_MINUS_SRC_ALPHA", "GL_DST_ALPHA", "GL_ONE_MINUS_DST_ALPHA")


def _factor(name: str, s: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Table 4.1 for source s and destination d (..., 4) in [0, 1]."""
    one = np.ones_like(s)
    if name == "GL_SRC_ALPHA_SATURATE":
        f = np.minimum(s[..., 3:4], 1.0 - d[..., 3:4]) * one
        f[..., 3] = 1.0
        return f
    return {"GL_ZERO": 0 * one, "GL_ONE": one, "GL_SRC_COLOR": s, "GL_ONE_MINUS_SRC_COLOR": 1 - s,
            "GL_DST_COLOR": d, "GL_ONE_MINUS_DST_COLOR": 1 - d, "GL_SRC_ALPHA": s[..., 3:4] * one,
            "GL_ONE_MINUS_SRC_ALPHA": 1 - s[..., 3:4] * one, "GL_DST_ALPHA": d[..., 3:4] * one,
            "GL_ONE_MINUS_DST_ALPHA": 1 - d[..., 3:4] * one}[name]


def _equation(name: str, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return {"GL_FUNC_ADD_OES": a + b, "GL_FUNC_SUBTRACT_OES": a - b,
            "GL_FUNC_REVERSE_SUBTRACT_OES": b - a}[name]


def _blended(eq: str, s: np.ndarray, d: np.ndarray, fs: np.ndarray, fd: np.ndarray) -> np.ndarray:
    """One equation of §4.1.7 on source s and destination d with factors fs, fd; EXT_blend_minmax's
    MIN and MAX take the colours themselves, no factors."""
    if eq == "GL_MIN_EXT":
        return np.minimum(s, d)
    if eq == "GL_MAX_EXT":
        return np.maximum(s, d)
    return _equation(eq, s * fs, d * fd)


def _blend_case(t: TestContext, rng: np.random.Generator, funcs: Sequence[str], eqs: Sequence[str] | None,
                where: str) -> None:
    """Random destination and source cells; blended with funcs = (src_rgb, dst_rgb, src_a, dst_a)
    and eqs = (rgb, alpha) or None (BlendFunc with FUNC_ADD); compared with Table 4.1 computed
    from the destination as read back (Ad = 1 without alpha bits)."""
    gl = t.gl
    src_c = rng.integers(0, 256, (4, 4, 4))
    dst_c = rng.integers(0, 256, (4, 4, 4))
    gl.glDisable(gl.GL_BLEND)
    _cells(t, dst_c)
    d = _read_stored(t)
    gl.glEnable(gl.GL_BLEND)
    if eqs is None:
        gl.glBlendFunc(getattr(gl, funcs[0]), getattr(gl, funcs[1]))
        eqs = ("GL_FUNC_ADD_OES", "GL_FUNC_ADD_OES")
    else:
        gl.glBlendFuncSeparateOES(*(getattr(gl, n) for n in funcs))
        gl.glBlendEquationSeparateOES(*(getattr(gl, n) for n in eqs))
    _cells(t, src_c)
    gl.glDisable(gl.GL_BLEND)
    s = _per_pixel(t, src_c) / 255.0
    rgb = _blended(eqs[0], s, d, _factor(funcs[0], s, d), _factor(funcs[1], s, d))
    alpha = _blended(eqs[1], s, d, _factor(funcs[2], s, d), _factor(funcs[3], s, d))
    want = np.clip(np.concatenate([rgb[..., :3], alpha[..., 3:]], axis=-1), 0.0, 1.0)
    _expect_image(t, t.read(), want, where, extra=_blend_slack(t))


@conformance_test("Blend", section="4.1.7", uses=("blend",), visuals=RGBA_VISUALS)
def blend(t: TestContext) -> None:
    """Every source x destination factor of Table 4.1 (SRC_ALPHA_SATURATE included) on 16 random
    colour pairs each; the factors read back."""
    gl = t.gl
    t.ortho_pixels()
    rng = np.random.default_rng(41)
    for sf, df in itertools.product(SRC_FACTORS, DST_FACTORS):
        _blend_case(t, rng, (sf, df, sf, df), None, f"BlendFunc({sf}, {df})")
        _expect_state(t, "GL_BLEND_SRC", gl.glGetIntegerv(gl.GL_BLEND_SRC), getattr(gl, sf), "4.1.7")
        _expect_state(t, "GL_BLEND_DST", gl.glGetIntegerv(gl.GL_BLEND_DST), getattr(gl, df), "4.1.7")


@conformance_test("Blend.subtract", section="4.1.7", uses=("blend",), visuals=RGBA_VISUALS)
def blend_subtract(t: TestContext) -> None:
    """OES_blend_subtract: FUNC_SUBTRACT and FUNC_REVERSE_SUBTRACT (clamped at 0) with several factors."""
    t.need_extension("GL_OES_blend_subtract")
    gl = t.gl
    t.ortho_pixels()
    rng = np.random.default_rng(42)
    for eq in ("GL_FUNC_SUBTRACT_OES", "GL_FUNC_REVERSE_SUBTRACT_OES", "GL_FUNC_ADD_OES"):
        for sf, df in (("GL_ONE", "GL_ONE"), ("GL_SRC_ALPHA", "GL_ONE_MINUS_SRC_ALPHA"),
                       ("GL_DST_COLOR", "GL_SRC_COLOR"), ("GL_ONE_MINUS_DST_ALPHA", "GL_DST_ALPHA")):
            src_c, dst_c = rng.integers(0, 256, (4, 4, 4)), rng.integers(0, 256, (4, 4, 4))
            gl.glDisable(gl.GL_BLEND)
            _cells(t, dst_c)
            d = _read_stored(t)
            gl.glEnable(gl.GL_BLEND)
            gl.glBlendFunc(getattr(gl, sf), getattr(gl, df))
            gl.glBlendEquationOES(getattr(gl, eq))
            _expect_state(t, "GL_BLEND_EQUATION_OES", gl.glGetIntegerv(gl.GL_BLEND_EQUATION_OES),
                          getattr(gl, eq), "OES_blend_subtract")
            _cells(t, src_c)
            gl.glDisable(gl.GL_BLEND)
            s = _per_pixel(t, src_c) / 255.0
            want = np.clip(_equation(eq, s * _factor(sf, s, d), d * _factor(df, s, d)), 0.0, 1.0)
            _expect_image(t, t.read(), want, f"BlendEquationOES({eq}), BlendFunc({sf}, {df})",
                          extra=_blend_slack(t))
    gl.glBlendEquationOES(gl.GL_FUNC_ADD_OES)


@conformance_test("Blend.separate", section="4.1.7", uses=("blend",), visuals=RGBA_VISUALS)
def blend_separate(t: TestContext) -> None:
    """OES_blend_func_separate and OES_blend_equation_separate: RGB and alpha blend with their
    own factors and equations."""
    t.need_extension("GL_OES_blend_func_separate")
    t.need_extension("GL_OES_blend_equation_separate")
    gl = t.gl
    t.ortho_pixels()
    rng = np.random.default_rng(43)
    eqs = ("GL_FUNC_ADD_OES", "GL_FUNC_SUBTRACT_OES", "GL_FUNC_REVERSE_SUBTRACT_OES")
    if not t.has_extension("GL_OES_blend_subtract"):
        eqs = eqs[:1]
    for _ in range(24):
        funcs = (str(rng.choice(SRC_FACTORS)), str(rng.choice(DST_FACTORS)), str(rng.choice(SRC_FACTORS)),
                 str(rng.choice(DST_FACTORS)))
        eq = (str(rng.choice(eqs)), str(rng.choice(eqs)))
        _blend_case(t, rng, funcs, eq, f"BlendFuncSeparateOES{funcs}, BlendEquationSeparateOES{eq}")
        names = ("GL_BLEND_SRC_RGB_OES", "GL_BLEND_DST_RGB_OES", "GL_BLEND_SRC_ALPHA_OES",
                 "GL_BLEND_DST_ALPHA_OES")
        got = [gl.glGetIntegerv(getattr(gl, p)) for p in names]
        _expect_state(t, "the four blend factors", got, [getattr(gl, n) for n in funcs],
                      "OES_blend_func_separate")
    gl.glBlendEquationSeparateOES(gl.GL_FUNC_ADD_OES, gl.GL_FUNC_ADD_OES)


@conformance_test("Blend.minmax", section="EXT_blend_minmax", uses=("blend",), visuals=RGBA_VISUALS)
def blend_minmax(t: TestContext) -> None:
    """EXT_blend_minmax: MIN_EXT and MAX_EXT take the smaller and larger of source and destination
    whatever the factors, alone and beside the other equations for RGB or alpha."""
    t.need_extension("GL_EXT_blend_minmax")
    gl = t.gl
    t.ortho_pixels()
    rng = np.random.default_rng(44)
    others = ["GL_FUNC_ADD_OES"]
    if t.has_extension("GL_OES_blend_subtract"):
        others += ["GL_FUNC_SUBTRACT_OES", "GL_FUNC_REVERSE_SUBTRACT_OES"]
    cases = [("GL_MIN_EXT", "GL_MIN_EXT"), ("GL_MAX_EXT", "GL_MAX_EXT"), ("GL_MIN_EXT", "GL_MAX_EXT"),
             ("GL_MAX_EXT", "GL_MIN_EXT")]
    cases += [(str(rng.choice(["GL_MIN_EXT", "GL_MAX_EXT"])), str(rng.choice(others))) for _ in range(4)]
    cases += [(str(rng.choice(others)), str(rng.choice(["GL_MIN_EXT", "GL_MAX_EXT"]))) for _ in range(4)]
    for eq in cases:
        funcs = (str(rng.choice(SRC_FACTORS)), str(rng.choice(DST_FACTORS)), str(rng.choice(SRC_FACTORS)),
                 str(rng.choice(DST_FACTORS)))
        _blend_case(t, rng, funcs, eq, f"BlendFuncSeparateOES{funcs}, BlendEquationSeparateOES{eq}")
        _expect_state(t, "GL_BLEND_EQUATION_RGB_OES", gl.glGetIntegerv(gl.GL_BLEND_EQUATION_RGB_OES),
                      getattr(gl, eq[0]), "EXT_blend_minmax")
    gl.glBlendEquationSeparateOES(gl.GL_FUNC_ADD_OES, gl.GL_FUNC_ADD_OES)


# {============================================================
# Dither (§4.1.8)

@conformance_test("Dither", section="4.1.8", uses=("nodither",), visuals=RGBA_VISUALS, size=(128, 16))
def dither(t: TestContext) -> None:
    """Smooth ramps and a clear between two shades: with dither each value is one of the two
    shades around the exact one, and dither on and off differ by at most one shade."""
    gl = t.gl
    t.ortho_pixels()
    gl.glShadeModel(gl.GL_SMOOTH)
    w, h = t.width, t.height
    tops = np.array([(1 << b) - 1 for b in t.visual.bits])
    # the ramp runs from colour `left` at x = 0 to `right` at x = w (pixel centres at x + 1/2)
    left, right = np.array([0, 255, 0, 0]), np.array([255, 0, 128, 255])
    x = (np.arange(w) + 0.5) / w
    exact = np.broadcast_to((left + (right - left) * x[:, None]) / 255.0, (h, w, 4)) * tops
    verts = [(0, 0), (w, 0), (w, h), (0, 0), (w, h), (0, h)]
    cols = [left, right, right, left, right, left]
    images = {}
    for on in (False, True):
        (gl.glEnable if on else gl.glDisable)(gl.GL_DITHER)
        t.clear((0, 0, 0, 0))
        t.draw(gl.GL_TRIANGLES, verts, cols)
        images[on] = _shades(t, t.read())
    _check_dither(t, images, exact, tops, "ramp")
    gl.glShadeModel(gl.GL_FLAT)
    rgba = (0.3, 0.52, 0.9, 0.61)
    for on in (False, True):
        (gl.glEnable if on else gl.glDisable)(gl.GL_DITHER)
        t.clear(rgba)
        images[on] = _shades(t, t.read())
    _check_dither(t, images, np.broadcast_to(np.array(rgba) * tops, (h, w, 4)), tops, "glClear")
    gl.glEnable(gl.GL_DITHER)


def _check_dither(t: TestContext, images: dict, exact: np.ndarray, tops: np.ndarray, what: str) -> None:
    # interpolation and the 16.16 colour may be off by the published 2^-13
    slack = tops * 2.0**-13
    on, off = images[True], images[False]
    for ch in range(4):
        if not tops[ch]:
            continue
        e = exact[..., ch]
        bad = (on[..., ch] < np.ceil(e - slack[ch]) - 1) | (on[..., ch] > np.ceil(e + slack[ch]))
        if bad.any():
            y, x = (int(v) for v in np.argwhere(bad)[0])
            hi = int(np.ceil(e[y, x]))
            t.fail(f"{what}, dither on: channel {'RGBA'[ch]} is {on[y, x, ch]} at (x={x}, y={y}), the exact "
                   f"value {e[y, x]:.3f} allows only {hi - 1} or {hi} (§4.1.8)")
        diff = np.abs(on[..., ch] - off[..., ch])
        if diff.max() > 1:
            y, x = (int(v) for v in np.argwhere(diff > 1)[0])
            t.fail(f"{what}: channel {'RGBA'[ch]} differs by {diff[y, x]} shades with dither on and off at "
                   f"(x={x}, y={y}); at most one is allowed")


# {============================================================
# LogicOp (§4.1.9)

LOGIC_OPS: dict[str, Callable[[np.ndarray, np.ndarray], np.ndarray]] = {
    "GL_CLEAR": lambda s, d: 0 * s, "GL_AND": lambda s, d: s & d, "GL_AND_REVERSE": lambda s, d: s & ~d,
    "GL_COPY": lambda s, d: s, "GL_AND_INVERTED": lambda s, d: ~s & d, "GL_NOOP": lambda s, d: d,
    "GL_XOR": lambda s, d: s ^ d, "GL_OR": lambda s, d: s | d, "GL_NOR": lambda s, d: ~(s | d),
    "GL_EQUIV": lambda s, d: ~(s ^ d), "GL_INVERT": lambda s, d: ~d, "GL_OR_REVERSE": lambda s, d: s | ~d,
    "GL_COPY_INVERTED": lambda s, d: ~s, "GL_OR_INVERTED": lambda s, d: ~s | d,
    "GL_NAND": lambda s, d: ~(s & d), "GL_SET": lambda s, d: ~(0 * s),
}


def _exact_ubytes(bits: Sequence[int], shades: np.ndarray) -> np.ndarray:
    """Ubyte colours that every rule of §2.12.8 stores as the given shades: 2^(8-b) k + 2^(7-b)
    (its high bits are k, and it rounds to k too); 8-bit channels unchanged."""
    out = shades.copy()
    for ch, b in enumerate(bits):
        if 0 < b < 8:
            out[..., ch] = (shades[..., ch] << (8 - b)) + (1 << (7 - b))
    return out


@conformance_test("LogicOp", section="4.1.9", uses=("nodither", "blend"), visuals=RGBA_VISUALS)
def logic_op(t: TestContext) -> None:
    """All 16 operations of Table 4.2 on the stored bits, exactly; with blending also enabled the
    logic op replaces it."""
    gl = t.gl
    t.ortho_pixels()
    gl.glDisable(gl.GL_DITHER)
    bits = t.visual.bits
    tops = np.array([(1 << b) - 1 for b in bits])
    rng = np.random.default_rng(44)
    for k, (name, fn) in enumerate(LOGIC_OPS.items()):
        s_sh = rng.integers(0, 256, (4, 4, 4)) & np.maximum(tops, 255 * (tops == 0))
        d_sh = rng.integers(0, 256, (4, 4, 4)) & np.maximum(tops, 255 * (tops == 0))
        gl.glDisable(gl.GL_COLOR_LOGIC_OP)
        gl.glDisable(gl.GL_BLEND)
        _cells(t, _exact_ubytes(bits, d_sh))
        gl.glEnable(gl.GL_COLOR_LOGIC_OP)
        if k % 2:
            gl.glEnable(gl.GL_BLEND)
            gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE)
        gl.glLogicOp(getattr(gl, name))
        _expect_state(t, "GL_LOGIC_OP_MODE", gl.glGetIntegerv(gl.GL_LOGIC_OP_MODE), getattr(gl, name),
                      "4.1.9")
        _cells(t, _exact_ubytes(bits, s_sh))
        gl.glDisable(gl.GL_COLOR_LOGIC_OP)
        gl.glDisable(gl.GL_BLEND)
        got = _shades(t, t.read())
        want = _per_pixel(t, fn(s_sh, d_sh) & tops)
        bad = (got != want).any(axis=-1)
        if bad.any():
            y, x = (int(v) for v in np.argwhere(bad)[0])
            t.fail(f"LogicOp({name}){' with blending on' if k % 2 else ''}: {int(bad.sum())} pixels wrong; "
                   f"first at (x={x}, y={y}): shades {got[y, x].tolist()}, expected {want[y, x].tolist()}")


# {============================================================
# Mask.stencil (§4.2.2)

@conformance_test("Mask.stencil", section="4.2.2", uses=("stencil",), visuals=RGBA_VISUALS)
def mask_stencil(t: TestContext) -> None:
    """glStencilMask protects the masked bit planes when fragments write stencil and when
    glClear does; the mask reads back."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    left = _region(t, 0, 0, w // 2, h)
    gl.glStencilMask(0xFF)
    gl.glClearStencil(0)
    gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
    gl.glEnable(gl.GL_STENCIL_TEST)
    gl.glStencilFunc(gl.GL_ALWAYS, 0xFF, 0xFF)
    gl.glStencilOp(gl.GL_REPLACE, gl.GL_REPLACE, gl.GL_REPLACE)
    gl.glStencilMask(0x0F)
    _expect_state(t, "GL_STENCIL_WRITEMASK", gl.glGetIntegerv(gl.GL_STENCIL_WRITEMASK) & 0xFF, 0x0F, "4.2.2")
    gl.glColorMask(False, False, False, False)
    _rect(t, 0, 0, w // 2, h)                      # left: 0x0F
    gl.glStencilMask(0xC3)
    gl.glStencilOp(gl.GL_INVERT, gl.GL_INVERT, gl.GL_INVERT)
    _rect(t, 0, 0, w, h)                           # left: 0x0F ^ 0xC3 = 0xCC, right: 0xC3
    gl.glColorMask(True, True, True, True)
    want = np.where(left, 0xCC, 0xC3)
    _expect_stencil(t, want, "REPLACE under mask 0x0F, then INVERT under mask 0xC3")
    gl.glStencilMask(0xF0)
    gl.glClearStencil(0x5A)
    gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
    want = (want & 0x0F) | 0x50
    _expect_stencil(t, want, "glClear(STENCIL) to 0x5A under mask 0xF0")
    gl.glStencilMask(0x00)
    gl.glClearStencil(0)
    gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
    _expect_stencil(t, want, "glClear(STENCIL) under mask 0")
    gl.glStencilMask(0xFF)


# {============================================================
# Scissor (§4.1.2)

@conformance_test("Scissor", section="4.1.2", uses=("scissor",), visuals=RGBA_VISUALS)
def scissor(t: TestContext) -> None:
    """Drawing and glClear change exactly the pixels of the scissor box, for boxes inside, partly
    outside and beyond the window, one pixel and empty; a negative size is INVALID_VALUE."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    everything = np.ones((h, w), dtype=bool)
    boxes = [(8, 12, 20, 30), (-5, -7, 20, 25), (50, 40, 100, 100), (10, 10, 1, 1), (0, 0, 0, 10),
             (3, 5, 40, 0), (0, 0, w, h), (-10, -10, w + 20, h + 20)]
    for x, y, bw, bh in boxes:
        gl.glDisable(gl.GL_SCISSOR_TEST)
        t.clear((0, 0, 0, 0))
        gl.glEnable(gl.GL_SCISSOR_TEST)
        gl.glScissor(x, y, bw, bh)
        _expect_state(t, "GL_SCISSOR_BOX", gl.glGetIntegerv(gl.GL_SCISSOR_BOX), [x, y, bw, bh], "4.1.2")
        inside = _region(t, x, y, x + bw, y + bh)
        _full(t)
        img = t.read()
        t.expect_pixels(inside, (1, 1, 1, 1), f"draw, box {x, y, bw, bh}: inside", img=img)
        t.expect_pixels(everything & ~inside, (0, 0, 0, 0), f"draw, box {x, y, bw, bh}: outside", img=img)
        gl.glClearColorx(0, ONE, 0, ONE)
        gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        img = t.read()
        t.expect_pixels(inside, (0, 1, 0, 1), f"glClear, box {x, y, bw, bh}: inside", img=img)
        t.expect_pixels(everything & ~inside, (0, 0, 0, 0), f"glClear, box {x, y, bw, bh}: outside", img=img)
    gl.glScissor(1, 2, 3, 4)
    gl.glScissor(0, 0, -1, 5)
    t.check_gl_error("glScissor(0, 0, -1, 5)", gl.GL_INVALID_VALUE)
    gl.glScissor(0, 0, 5, -1)
    t.check_gl_error("glScissor(0, 0, 5, -1)", gl.GL_INVALID_VALUE)
    _expect_state(t, "GL_SCISSOR_BOX after the errors", gl.glGetIntegerv(gl.GL_SCISSOR_BOX), [1, 2, 3, 4],
                  "4.1.2")
    gl.glDisable(gl.GL_SCISSOR_TEST)


# {============================================================
# SPClear, SPCorner, SPFunc, SPOp (§4.1.5, §4.2.3)

@conformance_test("SPClear", section="4.2.3", uses=("stencil",), visuals=RGBA_VISUALS)
def sp_clear(t: TestContext) -> None:
    """glClear(STENCIL_BUFFER_BIT) sets every pixel to the clear value masked to 8 bits, and
    only inside the scissor box."""
    gl = t.gl
    t.ortho_pixels()
    everything = np.ones((t.height, t.width), dtype=bool)
    cases = ((0, 0), (1, 1), (0x55, 0x55), (0xAA, 0xAA), (0xFF, 0xFF), (0x1A5, 0xA5), (-1, 0xFF))
    for value, stored in cases:
        gl.glClearStencil(value)
        gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
        _expect_stencil(t, np.where(everything, stored, 0), f"glClearStencil({value:#x})")
    gl.glEnable(gl.GL_SCISSOR_TEST)
    gl.glScissor(5, 9, 30, 17)
    gl.glClearStencil(0x3C)
    gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
    gl.glDisable(gl.GL_SCISSOR_TEST)
    _expect_stencil(t, np.where(_region(t, 5, 9, 35, 26), 0x3C, 0xFF),
                    "glClearStencil(0x3C) in a scissor box")


@conformance_test("SPCorner", section="4.1.5", uses=("stencil",), visuals=RGBA_VISUALS)
def sp_corner(t: TestContext) -> None:
    """A one-pixel square drawn into stencil in each corner marks exactly that pixel."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    for x, y in ((0, 0), (w - 1, 0), (0, h - 1), (w - 1, h - 1)):
        gl.glClearStencil(0)
        gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
        gl.glEnable(gl.GL_STENCIL_TEST)
        gl.glStencilFunc(gl.GL_ALWAYS, 0x81, 0xFF)
        gl.glStencilOp(gl.GL_REPLACE, gl.GL_REPLACE, gl.GL_REPLACE)
        gl.glColorMask(False, False, False, False)
        _rect(t, x, y, x + 1, y + 1)
        gl.glColorMask(True, True, True, True)
        _expect_stencil(t, np.where(_region(t, x, y, x + 1, y + 1), 0x81, 0), f"pixel square at ({x}, {y})")


@conformance_test("SPFunc", section="4.1.5", uses=("stencil",), visuals=RGBA_VISUALS)
def sp_func(t: TestContext) -> None:
    """Each stencil function with references (clamped to [0, 255]) and value masks against four
    stored values: a quad passes exactly where (ref & mask) func (stored & mask) holds."""
    gl = t.gl
    t.ortho_pixels()
    bands = (0x00, 0x3C, 0x80, 0xFF)
    stored = _set_stencil_bands(t, bands)
    for fname, fn in FUNCS.items():
        for ref, mask in itertools.product((0x3C, 0x80, -1, 300), (0xFF, 0xF0, 0x0F)):
            gl.glClearColorx(0, 0, 0, 0)
            gl.glClear(gl.GL_COLOR_BUFFER_BIT)
            gl.glStencilFunc(getattr(gl, fname), ref, mask)
            _full(t)
            passes = fn(min(max(ref, 0), 255) & mask, stored & mask)
            drawn = t.read()[..., 0] > 0.5
            bad = drawn != passes
            if bad.any():
                y, x = (int(v) for v in np.argwhere(bad)[0])
                t.fail(f"StencilFunc({fname}, {ref}, {mask:#x}) against stored 0x{stored[y, x]:02X}: "
                       f"{'passed' if drawn[y, x] else 'failed'} at (x={x}, y={y}) (ref clamped to "
                       f"{min(max(ref, 0), 255)})")
    _expect_state(t, "GL_STENCIL_FUNC", gl.glGetIntegerv(gl.GL_STENCIL_FUNC), gl.GL_ALWAYS, "4.1.5")
    _expect_stencil(t, stored, "stored values after the KEEP draws")


def _stencil_op(name: str, s: np.ndarray, ref: int) -> np.ndarray:
    return {
        "GL_KEEP": s, "GL_ZERO": 0 * s, "GL_REPLACE": 0 * s + ref, "GL_INCR": np.minimum(s + 1, 255),
        "GL_DECR": np.maximum(s - 1, 0), "GL_INVERT": ~s & 0xFF, "GL_INCR_WRAP_OES": (s + 1) & 0xFF,
        "GL_DECR_WRAP_OES": (s - 1) & 0xFF,
    }[name]


@conformance_test("SPOp", section="4.1.5", uses=("stencil", "depth"), visuals=ALL_VISUALS)
def sp_op(t: TestContext) -> None:
    """Every stencil operation (OES_stencil_wrap's where present) as sfail, as dpfail and as
    dppass, on stored 0x00, 0x01, 0x80, 0xFF, where the depth test fails (top half) and passes."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    ops = ["GL_KEEP", "GL_ZERO", "GL_REPLACE", "GL_INCR", "GL_DECR", "GL_INVERT"]
    if t.has_extension("GL_OES_stencil_wrap"):
        ops += ["GL_INCR_WRAP_OES", "GL_DECR_WRAP_OES"]
    ref = 0x42
    near = _region(t, 0, h // 2, w, h)
    for slot in range(3):
        for op in ops:
            stored = _set_stencil_bands(t, (0x00, 0x01, 0x80, 0xFF))
            gl.glDepthMask(True)
            gl.glClearDepthx(ONE)
            gl.glClear(gl.GL_DEPTH_BUFFER_BIT)
            gl.glEnable(gl.GL_DEPTH_TEST)
            gl.glDepthFunc(gl.GL_ALWAYS)
            gl.glColorMask(False, False, False, False)
            gl.glDisable(gl.GL_STENCIL_TEST)
            _rect(t, 0, h // 2, w, h, z=0.5)              # depth 0.25 in the top half
            gl.glColorMask(True, True, True, True)
            gl.glDepthFunc(gl.GL_LESS)
            gl.glEnable(gl.GL_STENCIL_TEST)
            gl.glStencilFunc(gl.GL_NEVER if slot == 0 else gl.GL_ALWAYS, ref, 0xFF)
            three = ["GL_KEEP"] * 3
            three[slot] = op
            gl.glStencilOp(*(getattr(gl, n) for n in three))
            _full(t, z=0.0)                                 # depth 0.5: fails above, passes below
            if slot == 0:
                want = _stencil_op(op, stored, ref)
            else:
                depth_fails = near
                applies = depth_fails if slot == 1 else ~depth_fails
                want = np.where(applies, _stencil_op(op, stored, ref), stored)
            _expect_stencil(t, want, f"StencilOp with {op} as {('sfail', 'dpfail', 'dppass')[slot]}")
    gl.glDisable(gl.GL_DEPTH_TEST)


# {============================================================
# Fog (§3.8)

# eye x and y stay within 1/64 of the axis, so |z_eye| and the true eye distance agree to 2^-12
_FOG_SPAN = 1.0 / 64


def _fog_view(t: TestContext) -> None:
    gl = t.gl
    gl.glViewport(0, 0, t.width, t.height)
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    s = _fx(_FOG_SPAN)
    gl.glOrthox(-s, s, -s, s, 0, 32 * ONE)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()


def _fog_columns(t: TestContext, depths: Sequence[float], rgba: Sequence[int]) -> None:
    """One quad per eye distance, side by side across the window."""
    n = len(depths)
    s = _FOG_SPAN
    verts = []
    for k, c in enumerate(depths):
        x0, x1 = -s + 2 * s * k / n, -s + 2 * s * (k + 1) / n
        verts += [(x0, -s, -c), (x1, -s, -c), (x1, s, -c), (x0, -s, -c), (x1, s, -c), (x0, s, -c)]
    t.gl.glColor4ub(*rgba)
    t.draw(t.gl.GL_TRIANGLES, verts, size=3)


@conformance_test("Fog", section="3.8", uses=("fog",), visuals=RGBA_VISUALS, size=(64, 8))
def fog(t: TestContext) -> None:
    """LINEAR, EXP and EXP2 at eight eye distances each: C = f C_r + (1 - f) C_f with f from
    equations 3.22-3.24 clamped to [0, 1]; alpha unchanged; FOG_COLOR clamped when set."""
    gl = t.gl
    _fog_view(t)
    gl.glEnable(gl.GL_FOG)
    rgba = (230, 120, 20, 200)
    fog_colour = (0.1, 0.35, 0.9, 0.5)
    gl.glFogxv(gl.GL_FOG_COLOR, [_fx(c) for c in fog_colour])
    depths = (0.5, 1.0, 2.0, 3.0, 4.5, 6.0, 9.0, 14.0)
    cases = [("GL_LINEAR", 1.0, 2.0, 10.0), ("GL_LINEAR", 1.0, -4.0, 20.0), ("GL_EXP", 0.25, 0, 1),
             ("GL_EXP", 1.5, 0, 1), ("GL_EXP", 0.0, 0, 1), ("GL_EXP2", 0.125, 0, 1), ("GL_EXP2", 0.5, 0, 1)]
    c = np.array(depths)
    for mode, d, s, e in cases:
        gl.glFogx(gl.GL_FOG_MODE, getattr(gl, mode))
        gl.glFogx(gl.GL_FOG_DENSITY, _fx(d))
        gl.glFogx(gl.GL_FOG_START, _fx(s))
        gl.glFogx(gl.GL_FOG_END, _fx(e))
        t.clear((0, 0, 0, 0))
        _fog_columns(t, depths, rgba)
        f = {"GL_LINEAR": (e - c) / (e - s), "GL_EXP": np.exp(-d * c),
             "GL_EXP2": np.exp(-((d * c) ** 2))}[mode]
        f = np.clip(f, 0.0, 1.0)[:, None]
        cr, cf = np.array(rgba) / 255.0, np.array(fog_colour)
        cols = np.concatenate([f * cr[:3] + (1 - f) * cf[:3], np.full((len(depths), 1), cr[3])], axis=1)
        want = np.repeat(cols, t.width // len(depths), axis=0)[None, :, :] * np.ones((t.height, 1, 1))
        _expect_image(t, t.read(), want, f"fog {mode} density {d} start {s} end {e}")
    # a quad tilted in depth, LINEAR inside [start, end]: f is linear in z, z linear in x
    gl.glFogx(gl.GL_FOG_MODE, gl.GL_LINEAR)
    gl.glFogx(gl.GL_FOG_START, 0)
    gl.glFogx(gl.GL_FOG_END, 16 * ONE)
    t.clear((0, 0, 0, 0))
    sp = _FOG_SPAN
    gl.glColor4ub(*rgba)
    t.draw(gl.GL_TRIANGLES, [(-sp, -sp, -1), (sp, -sp, -15), (sp, sp, -15), (-sp, -sp, -1), (sp, sp, -15),
                             (-sp, sp, -1)], size=3)
    z = 1 + 14 * (np.arange(t.width) + 0.5) / t.width
    f = ((16 - z) / 16)[:, None]
    cr, cf = np.array(rgba) / 255.0, np.array(fog_colour)
    cols = np.concatenate([f * cr[:3] + (1 - f) * cf[:3], np.full((t.width, 1), cr[3])], axis=1)
    _expect_image(t, t.read(), np.broadcast_to(cols, (t.height, t.width, 4)), "fog LINEAR on a tilted quad")
    # FOG_COLOR outside [0, 1] is clamped when specified: at f = 1/2 the clamped colour shows
    gl.glFogxv(gl.GL_FOG_COLOR, [-ONE, ONE // 4, 2 * ONE, ONE])
    t.clear((0, 0, 0, 0))
    _fog_columns(t, (8.0,), rgba)
    cols = np.concatenate([0.5 * cr[:3] + 0.5 * np.array([0.0, 0.25, 1.0]), [cr[3]]])
    _expect_image(t, t.read(), np.broadcast_to(cols, (t.height, t.width, 4)),
                  "fog colour (-1, 0.25, 2) must be clamped to (0, 0.25, 1) when specified (§3.8); f = 1/2")
    _expect_state(t, "GL_FOG_COLOR", gl.glGetFixedv(gl.GL_FOG_COLOR), [0, ONE // 4, ONE, ONE], "3.8")
    gl.glFogx(gl.GL_FOG_DENSITY, -ONE)
    t.check_gl_error("glFogx(GL_FOG_DENSITY, -1)", gl.GL_INVALID_VALUE)
    gl.glFogx(gl.GL_FOG_MODE, gl.GL_FOG)
    t.check_gl_error("glFogx(GL_FOG_MODE, GL_FOG)", gl.GL_INVALID_ENUM)
    _expect_state(t, "GL_FOG_MODE", gl.glGetIntegerv(gl.GL_FOG_MODE), gl.GL_LINEAR, "3.8")
    gl.glDisable(gl.GL_FOG)
