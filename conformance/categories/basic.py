"""Basic categories: initial state, clears, colours, corners, ramps, masks,
depth buffer, and the entry-point sweep (covgl).

Every test uses only Common-Lite commands (x forms) and GL_FIXED /
GL_UNSIGNED_BYTE / GL_SHORT / GL_BYTE arrays, and draws with
``t.ortho_pixels()``: object x, y are window pixels and object z maps to
window depth d = (1 - z) / 2. Geometry edges lie on pixel boundaries, so no
pixel centre is ever on an outer edge and coverage is known exactly.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from gles import gl as _gles_gl

from ..harness import TestContext, conformance_test

ONE = 1 << 16
RGBA_VISUALS = ("rgba8888", "rgb565", "rgba4444", "rgba5551")
DEPTH_VISUALS = ("rgba8888", "rgba8888-d16")


# {============================================================
# helpers

def _fx(v: float) -> int:
    """A real as a 16.16 int."""
    return int(round(v * 65536))


def _z(depth: float) -> float:
    """Object z that t.ortho_pixels() maps to window depth `depth`."""
    return 1.0 - 2.0 * depth


def _rect(t: TestContext, x0: float, y0: float, x1: float, y1: float, *, depth: float = 0.5,
          colors: Any = None, mode: str = "triangles") -> None:
    """Fill the axis-aligned rectangle [x0, x1] x [y0, y1] at window depth `depth`."""
    gl = t.gl
    z = _z(depth)
    a, b, c, d = (x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)
    if mode == "triangles":
        t.draw(gl.GL_TRIANGLES, [a, b, c, a, c, d], colors, size=3)
    elif mode == "strip":
        t.draw(gl.GL_TRIANGLE_STRIP, [a, b, d, c], colors, size=3)
    elif mode == "fan":
        t.draw(gl.GL_TRIANGLE_FAN, [a, b, c, d], colors, size=3)
    elif mode == "elements":
        t.draw(gl.GL_TRIANGLES, [a, b, c, d], colors, size=3, indices=[0, 1, 2, 0, 2, 3])
    else:
        raise ValueError(mode)


def _region(t: TestContext, x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
    """Boolean (h, w) mask of the pixels [x0, x1) x [y0, y1)."""
    m = np.zeros((t.height, t.width), dtype=bool)
    m[y0:y1, x0:x1] = True
    return m


def _levels(bits: int) -> list[float]:
    """Ten representable values k / (2^bits - 1) spread over [0, 1], ends included."""
    top = (1 << bits) - 1 if bits else 1
    return [round(k * top / 9) / top for k in range(10)]


def _color_x(gl: Any, rgba: Sequence[float]) -> None:
    """The current colour from reals, through glColor4x."""
    gl.glColor4x(*[_fx(c) for c in rgba])


def _expect_state(t: TestContext, what: str, got: Any, want: Any, section: str) -> None:
    """A queried value equals the one the spec section gives."""
    got_l = np.atleast_1d(np.asarray(got)).tolist()
    want_l = np.atleast_1d(np.asarray(want)).tolist()
    if got_l != want_l:
        t.fail(f"{what} is {got_l}, expected {want_l} (§{section})")


# {============================================================
# MustPass

@conformance_test("MustPass", section="6.2", uses=("depth",), visuals=RGBA_VISUALS)
def must_pass(t: TestContext) -> None:
    """The initial state is as the state tables give it, and a cleared window reads back."""
    gl = t.gl
    t.check_gl_error("right after context creation")
    _expect_state(t, "GL_VIEWPORT", gl.glGetIntegerv(gl.GL_VIEWPORT), [0, 0, t.width, t.height], "2.10.1")
    _expect_state(t, "GL_DEPTH_RANGE", gl.glGetFixedv(gl.GL_DEPTH_RANGE), [0, ONE], "2.10.1")
    _expect_state(t, "GL_MATRIX_MODE", gl.glGetIntegerv(gl.GL_MATRIX_MODE), gl.GL_MODELVIEW, "2.10.2")
    for cap, name, want, sec in ((gl.GL_DITHER, "GL_DITHER", True, "4.1.8"),
                                 (gl.GL_DEPTH_TEST, "GL_DEPTH_TEST", False, "4.1.6"),
                                 (gl.GL_CULL_FACE, "GL_CULL_FACE", False, "3.5.1")):
        _expect_state(t, f"glIsEnabled({name})", bool(gl.glIsEnabled(cap)), want, sec)
    _expect_state(t, "GL_DEPTH_FUNC", gl.glGetIntegerv(gl.GL_DEPTH_FUNC), gl.GL_LESS, "4.1.6")
    _expect_state(t, "GL_COLOR_CLEAR_VALUE", gl.glGetFixedv(gl.GL_COLOR_CLEAR_VALUE), [0, 0, 0, 0], "4.2.3")
    _expect_state(t, "GL_DEPTH_CLEAR_VALUE", gl.glGetFixedv(gl.GL_DEPTH_CLEAR_VALUE), ONE, "4.2.3")
    _expect_state(t, "GL_COLOR_WRITEMASK", [bool(v) for v in gl.glGetBooleanv(gl.GL_COLOR_WRITEMASK)],
                  [True] * 4, "4.2.2")
    _expect_state(t, "GL_DEPTH_WRITEMASK", bool(gl.glGetBooleanv(gl.GL_DEPTH_WRITEMASK)), True, "4.2.2")
    t.check_gl_error("after the state queries")
    everything = np.ones((t.height, t.width), dtype=bool)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT)
    t.expect_pixels(everything, (0, 0, 0, 0), "glClear with the initial clear colour")
    t.clear((1.0, 0.0, 1.0, 1.0))
    t.expect_pixels(everything, (1.0, 0.0, 1.0, 1.0), "glClear to (1, 0, 1, 1)")


# {============================================================
# BClear

@conformance_test("BClear", section="4.2.3", visuals=RGBA_VISUALS)
def b_clear(t: TestContext) -> None:
    """Clearing to representable colours reads back each colour everywhere."""
    gl = t.gl
    everything = np.ones((t.height, t.width), dtype=bool)
    per_channel = [_levels(b) for b in t.visual.bits]
    for k in range(10):
        # each channel walks its levels with its own stride, so channels differ
        rgba = tuple(per_channel[c][(k * step) % 10] for c, step in enumerate((1, 3, 7, 9)))
        gl.glClearColorx(*[_fx(v) for v in rgba])
        gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        t.expect_pixels(everything, rgba, f"clear to {tuple(round(v, 4) for v in rgba)}")


# {============================================================
# BColor

_UB_COLORS = ((255, 0, 0, 255), (0, 255, 0, 128), (0, 0, 255, 0), (10, 100, 200, 50),
              (128, 64, 32, 16), (255, 255, 255, 255), (1, 254, 127, 129))
_X_COLORS = ((0.5, 0.25, 0.75, 1.0), (1.0, 1.0, 0.0, 0.5), (0.0, 0.125, 0.875, 0.0),
             (0x1234 / 65536, 0xFEDC / 65536, 0x8000 / 65536, 0x4321 / 65536))


@conformance_test("BColor", section="2.7", visuals=RGBA_VISUALS)
def b_color(t: TestContext) -> None:
    """The current colour (glColor4x, glColor4ub) reaches every pixel of a covering quad."""
    gl = t.gl
    t.ortho_pixels()
    everything = np.ones((t.height, t.width), dtype=bool)
    for shade in (gl.GL_SMOOTH, gl.GL_FLAT):
        gl.glShadeModel(shade)
        mode = "smooth" if shade == gl.GL_SMOOTH else "flat"
        for ub in _UB_COLORS:
            t.clear((0.5, 0.5, 0.5, 0.5))
            gl.glColor4ub(*ub)
            _rect(t, 0, 0, t.width, t.height)
            t.expect_pixels(everything, [c / 255 for c in ub], f"glColor4ub{ub}, {mode}")
        for rgba in _X_COLORS:
            t.clear((0.5, 0.5, 0.5, 0.5))
            _color_x(gl, rgba)
            _rect(t, 0, 0, t.width, t.height)
            t.expect_pixels(everything, rgba, f"glColor4x{tuple(_fx(c) for c in rgba)}, {mode}")
    # §2.12.5: after lighting (on or off) colours are clamped to [0, 1]
    t.clear((0.5, 0.5, 0.5, 0.5))
    gl.glColor4x(2 * ONE, -ONE, ONE // 2, 3 * ONE // 2)
    _rect(t, 0, 0, t.width, t.height)
    t.expect_pixels(everything, (1.0, 0.0, 0.5, 1.0), "glColor4x(2, -1, 0.5, 1.5) clamped (§2.12.5)")


@conformance_test("BColor.msb", section="2.12.8", uses=("nodither",), visuals=RGBA_VISUALS)
def b_color_msb(t: TestContext) -> None:
    """Unsigned-byte colours, unlit and unclipped, arrive as their most significant bits."""
    gl = t.gl
    t.ortho_pixels()
    gl.glDisable(gl.GL_DITHER)  # §4.1.8: undithered components are truncated, never dithered
    everything = np.ones((t.height, t.width), dtype=bool)
    bits = t.visual.bits
    values = [0, 1, 7, 8, 100, 127, 128, 129, 200, 247, 248, 254, 255]
    for i, v in enumerate(values):
        ub = (v, values[(i + 4) % len(values)], values[(i + 9) % len(values)], values[(i + 2) % len(values)])
        want = []
        for c, b in zip(ub, bits):
            want.append(((c >> (8 - b)) / ((1 << b) - 1)) if b else c / 255)
        t.clear((0.5, 0.5, 0.5, 0.5))
        gl.glColor4ub(*ub)
        _rect(t, 0, 0, t.width, t.height)
        img = t.read()
        # compare shade indices exactly: the rule leaves no freedom
        for ch, b in enumerate(bits):
            if not b:
                continue
            top = (1 << b) - 1
            got = np.rint(img[..., ch] * top).astype(int)
            exp = int(round(want[ch] * top))
            if (got != exp).any():
                ys, xs = np.nonzero(got != exp)
                t.fail(f"glColor4ub{ub}: channel {'RGBA'[ch]} is {got[ys[0], xs[0]]}/{top} at "
                       f"(x={xs[0]}, y={ys[0]}), the {b} most significant bits of {ub[ch]} are {exp}")
        t.expect_pixels(everything, want, f"glColor4ub{ub}", img=img)


# {============================================================
# BCorner

@conformance_test("BCorner", section="2.10.1")
def b_corner(t: TestContext) -> None:
    """A one-pixel square in each corner lights exactly that corner pixel."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    for mode in ("triangles", "strip", "fan", "elements"):
        for x, y in ((0, 0), (w - 1, 0), (0, h - 1), (w - 1, h - 1)):
            t.clear((0, 0, 0, 0))
            gl.glColor4x(ONE, ONE, ONE, ONE)
            _rect(t, x, y, x + 1, y + 1, mode=mode)
            img = t.read()
            where = f"pixel square at ({x}, {y}) drawn as {mode}"
            t.expect_color(x, y, (1, 1, 1, 1), where, img=img)
            others = np.ones((h, w), dtype=bool)
            others[y, x] = False
            t.expect_pixels(others, (0, 0, 0, 0), where + ": other pixels", img=img)


# {============================================================
# ColRamp

@conformance_test("ColRamp", section="3.5.1", uses=("nodither",), visuals=RGBA_VISUALS, size=(512, 8))
def col_ramp(t: TestContext) -> None:
    """A smooth ramp per channel shows all 2^bits shades, in order."""
    gl = t.gl
    t.ortho_pixels()
    gl.glDisable(gl.GL_DITHER)
    gl.glShadeModel(gl.GL_SMOOTH)
    t.clear((0, 0, 0, 0))
    bands = []
    for ch, bits in enumerate(t.visual.bits):
        if not bits:
            continue
        top = (1 << bits) - 1
        # 2 pixels per shade: pixel i's centre gets (i + 1/2) / 2 shades, so
        # every shade is a round-to-nearest distance of 1/4 shade from a centre
        length = 2 * top
        y0 = 2 * ch
        lo = [0, 0, 0, 0 if ch == 3 else 255]
        hi = list(lo)
        lo[ch], hi[ch] = 0, 255
        verts = [(0, y0), (length, y0), (length, y0 + 2), (0, y0), (length, y0 + 2), (0, y0 + 2)]
        t.draw(gl.GL_TRIANGLES, verts, [lo, hi, hi, lo, hi, lo])
        bands.append((ch, bits, top, length, y0))
    img = t.read()
    for ch, bits, top, length, y0 in bands:
        for y in (y0, y0 + 1):
            shades = np.rint(img[y, :length, ch] * top).astype(int)
            steps = np.diff(shades)
            if (steps < 0).any():
                i = int(np.nonzero(steps < 0)[0][0])
                t.fail(f"channel {'RGBA'[ch]} ramp row {y}: shade falls from {shades[i]} to "
                       f"{shades[i + 1]} at x={i + 1} (not monotonic)")
            distinct = len(np.unique(shades))
            if distinct != top + 1:
                missing = sorted(set(range(top + 1)) - set(shades.tolist()))
                t.fail(f"channel {'RGBA'[ch]} ramp row {y}: {distinct} distinct shades, want "
                       f"2^{bits} = {top + 1}; missing {missing[:8]}{'...' if len(missing) > 8 else ''}")


# {============================================================
# Mask

@conformance_test("Mask.color", section="4.2.2", visuals=RGBA_VISUALS)
def mask_color(t: TestContext) -> None:
    """glColorMask keeps masked channels unchanged, for drawing and for glClear."""
    gl = t.gl
    t.ortho_pixels()
    everything = np.ones((t.height, t.width), dtype=bool)
    for bits in range(16):
        m = [bool(bits & (1 << c)) for c in range(4)]
        name = "".join(ch if on else "-" for ch, on in zip("RGBA", m))
        gl.glColorMask(True, True, True, True)
        t.clear((0, 0, 0, 0))
        gl.glColorMask(*m)
        _expect_state(t, "GL_COLOR_WRITEMASK", [bool(v) for v in gl.glGetBooleanv(gl.GL_COLOR_WRITEMASK)],
                      m, "4.2.2")
        gl.glColor4x(ONE, ONE, ONE, ONE)
        _rect(t, 0, 0, t.width, t.height)
        t.expect_pixels(everything, [1.0 if on else 0.0 for on in m], f"draw white over black, mask {name}")
        gl.glColorMask(True, True, True, True)
        gl.glClearColorx(ONE, ONE, ONE, ONE)
        gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        gl.glColorMask(*m)
        gl.glClearColorx(0, 0, 0, 0)
        gl.glClear(gl.GL_COLOR_BUFFER_BIT)
        t.expect_pixels(everything, [0.0 if on else 1.0 for on in m], f"clear white to black, mask {name}")
    gl.glColorMask(True, True, True, True)


@conformance_test("Mask.depth", section="4.2.2", uses=("depth",), visuals=DEPTH_VISUALS)
def mask_depth(t: TestContext) -> None:
    """glDepthMask(FALSE) keeps the depth buffer unchanged, for drawing and for glClear."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    everything = np.ones((h, w), dtype=bool)
    red, green, blue = (1, 0, 0, 1), (0, 1, 0, 1), (0, 0, 1, 1)
    t.clear((0, 0, 0, 0))                       # depth 1
    gl.glEnable(gl.GL_DEPTH_TEST)
    gl.glDepthFunc(gl.GL_LESS)
    gl.glDepthMask(False)
    _expect_state(t, "GL_DEPTH_WRITEMASK", bool(gl.glGetBooleanv(gl.GL_DEPTH_WRITEMASK)), False, "4.2.2")
    _color_x(gl, red)
    _rect(t, 0, 0, w // 2, h, depth=0.25)
    t.expect_pixels(_region(t, 0, 0, w // 2, h), red, "depth 0.25 LESS than the cleared 1, mask off")
    gl.glDepthMask(True)
    _color_x(gl, green)
    _rect(t, 0, 0, w, h, depth=0.5)             # passes only where depth is still 1
    t.expect_pixels(everything, green, "depth 0.5 over a quad drawn with the depth mask off")
    # the depth buffer now holds 0.5; a masked clear must leave it so
    gl.glDepthMask(False)
    gl.glClearDepthx(ONE)
    gl.glClear(gl.GL_DEPTH_BUFFER_BIT)
    gl.glDepthMask(True)
    _color_x(gl, blue)
    _rect(t, 0, 0, w, h, depth=0.75)            # 0.75 < 0.5 fails everywhere
    t.expect_pixels(everything, green, "depth 0.75 after a depth clear with the mask off")


# {============================================================
# ZBClear and ZBFunc

_FUNCS: dict[str, Callable[[float, float], bool]] = {
    "GL_NEVER": lambda a, b: False,
    "GL_LESS": lambda a, b: a < b,
    "GL_EQUAL": lambda a, b: a == b,
    "GL_LEQUAL": lambda a, b: a <= b,
    "GL_GREATER": lambda a, b: a > b,
    "GL_NOTEQUAL": lambda a, b: a != b,
    "GL_GEQUAL": lambda a, b: a >= b,
    "GL_ALWAYS": lambda a, b: True,
}


@conformance_test("ZBClear", section="4.2.3", uses=("depth",), visuals=DEPTH_VISUALS)
def zb_clear(t: TestContext) -> None:
    """The depth clear value decides whether primitives at known depths pass LESS and GREATER."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    left, right = _region(t, 0, 0, w // 2, h), _region(t, w // 2, 0, w, h)
    bg, col_a, col_b = (0, 0, 0, 0), (1, 1, 0, 1), (0, 1, 1, 1)
    for clear in (0.0, 0.5, 1.0):
        for fname in ("GL_LESS", "GL_GREATER"):
            gl.glDisable(gl.GL_DEPTH_TEST)
            gl.glClearColorx(0, 0, 0, 0)
            gl.glClearDepthx(_fx(clear))
            gl.glClear(gl.GL_COLOR_BUFFER_BIT | gl.GL_DEPTH_BUFFER_BIT)
            gl.glEnable(gl.GL_DEPTH_TEST)
            gl.glDepthFunc(getattr(gl, fname))
            _color_x(gl, col_a)
            _rect(t, 0, 0, w // 2, h, depth=0.25)
            _color_x(gl, col_b)
            _rect(t, w // 2, 0, w, h, depth=0.75)
            img = t.read()
            fn = _FUNCS[fname]
            for region, d, col in ((left, 0.25, col_a), (right, 0.75, col_b)):
                passes = fn(d, clear)
                t.expect_pixels(region, col if passes else bg,
                                f"clear depth {clear}, {fname}, quad at depth {d} "
                                f"({'passes' if passes else 'fails'})", img=img)


# ZBFunc compares a quad with the depth another quad wrote, so EQUAL needs
# both to store the same value. A 16.16 z giving window depth j/16 lands at
# j * 2^(n-4) - j/16 in an n-bit buffer (n = 16 or 24): (8 - j)/16 of a unit
# inside a rounding interval for j < 8. Depth 0.5 (j = 8) would sit exactly
# on a boundary (0.5 * (2^24 - 1) = 8388607.5), where any round-off picks
# either neighbour, so the depths used here are 1/16, 2/16 and 3/16.
_ZB_REF = 2 / 16
_ZB_DEPTHS = (1 / 16, 2 / 16, 3 / 16)


@conformance_test("ZBFunc", section="4.1.6", uses=("depth",), visuals=DEPTH_VISUALS)
def zb_func(t: TestContext) -> None:
    """Each of the 8 depth functions passes exactly the quads whose depth compares true."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    x = [0, w // 3, 2 * w // 3, w]
    g = _levels(min(t.visual.bits[:3]))[5]     # a grey every colour channel represents
    grey, white = (g, g, g, 1.0), (1.0, 1.0, 1.0, 1.0)
    for fname, fn in _FUNCS.items():
        t.clear((0, 0, 0, 0))
        gl.glEnable(gl.GL_DEPTH_TEST)
        gl.glDepthFunc(gl.GL_ALWAYS)
        _color_x(gl, grey)
        _rect(t, 0, 0, w, h, depth=_ZB_REF)    # the reference depth everywhere
        gl.glDepthFunc(getattr(gl, fname))
        _expect_state(t, "GL_DEPTH_FUNC", gl.glGetIntegerv(gl.GL_DEPTH_FUNC), getattr(gl, fname), "4.1.6")
        _color_x(gl, white)
        for i, d in enumerate(_ZB_DEPTHS):
            _rect(t, x[i], 0, x[i + 1], h, depth=d)
        img = t.read()
        for i, d in enumerate(_ZB_DEPTHS):
            passes = fn(d, _ZB_REF)
            t.expect_pixels(_region(t, x[i], 0, x[i + 1], h), white if passes else grey,
                            f"{fname}: quad at depth {d * 16:g}/16 against {_ZB_REF * 16:g}/16 "
                            f"({'passes' if passes else 'fails'})", img=img)


# {============================================================
# covgl

_IDENTITY_X = [ONE if i % 5 == 0 else 0 for i in range(16)]
_IDENTITY_F = [1.0 if i % 5 == 0 else 0.0 for i in range(16)]

# (command, call, expected error). Calls run in this order, each command
# once, so a call may rely on the ones before it (a buffer is generated
# before it is bound).
Call = Callable[[Any, dict, TestContext], Any]


def _covgl_calls() -> list[tuple[str, Call, str]]:
    def arr(dtype: Any, n: int) -> np.ndarray:
        return np.zeros(n, dtype=dtype)

    calls: list[tuple[str, Call, str]] = [
        ("glGetError", lambda gl, s, t: gl.glGetError(), ""),
        ("glGetString", lambda gl, s, t: gl.glGetString(gl.GL_VERSION), ""),
        ("glGetIntegerv", lambda gl, s, t: gl.glGetIntegerv(gl.GL_VIEWPORT), ""),
        ("glGetBooleanv", lambda gl, s, t: gl.glGetBooleanv(gl.GL_DEPTH_WRITEMASK), ""),
        ("glGetFixedv", lambda gl, s, t: gl.glGetFixedv(gl.GL_DEPTH_RANGE), ""),
        ("glGetFloatv", lambda gl, s, t: gl.glGetFloatv(gl.GL_DEPTH_RANGE), ""),
        ("glIsEnabled", lambda gl, s, t: gl.glIsEnabled(gl.GL_DITHER), ""),
        ("glEnable", lambda gl, s, t: gl.glEnable(gl.GL_DITHER), ""),
        ("glDisable", lambda gl, s, t: gl.glDisable(gl.GL_CULL_FACE), ""),
        ("glHint", lambda gl, s, t: gl.glHint(gl.GL_PERSPECTIVE_CORRECTION_HINT, gl.GL_DONT_CARE), ""),
        ("glViewport", lambda gl, s, t: gl.glViewport(0, 0, t.width, t.height), ""),
        ("glScissor", lambda gl, s, t: gl.glScissor(0, 0, t.width, t.height), ""),
        ("glDepthRangef", lambda gl, s, t: gl.glDepthRangef(0.0, 1.0), ""),
        ("glDepthRangex", lambda gl, s, t: gl.glDepthRangex(0, ONE), ""),
        ("glClearColor", lambda gl, s, t: gl.glClearColor(0.0, 0.0, 0.0, 0.0), ""),
        ("glClearColorx", lambda gl, s, t: gl.glClearColorx(0, 0, 0, 0), ""),
        ("glClearDepthf", lambda gl, s, t: gl.glClearDepthf(1.0), ""),
        ("glClearDepthx", lambda gl, s, t: gl.glClearDepthx(ONE), ""),
        ("glClearStencil", lambda gl, s, t: gl.glClearStencil(0), ""),
        ("glClear", lambda gl, s, t: gl.glClear(
            gl.GL_COLOR_BUFFER_BIT | gl.GL_DEPTH_BUFFER_BIT | gl.GL_STENCIL_BUFFER_BIT), ""),
        ("glColorMask", lambda gl, s, t: gl.glColorMask(True, True, True, True), ""),
        ("glDepthMask", lambda gl, s, t: gl.glDepthMask(True), ""),
        ("glDepthFunc", lambda gl, s, t: gl.glDepthFunc(gl.GL_LESS), ""),
        ("glStencilMask", lambda gl, s, t: gl.glStencilMask(0xFF), ""),
        ("glStencilFunc", lambda gl, s, t: gl.glStencilFunc(gl.GL_ALWAYS, 0, 0xFF), ""),
        ("glStencilOp", lambda gl, s, t: gl.glStencilOp(gl.GL_KEEP, gl.GL_KEEP, gl.GL_KEEP), ""),
        ("glAlphaFunc", lambda gl, s, t: gl.glAlphaFunc(gl.GL_ALWAYS, 0.0), ""),
        ("glAlphaFuncx", lambda gl, s, t: gl.glAlphaFuncx(gl.GL_ALWAYS, 0), ""),
        ("glBlendFunc", lambda gl, s, t: gl.glBlendFunc(gl.GL_ONE, gl.GL_ZERO), ""),
        ("glBlendFuncSeparateOES", lambda gl, s, t: gl.glBlendFuncSeparateOES(
            gl.GL_ONE, gl.GL_ZERO, gl.GL_ONE, gl.GL_ZERO), ""),
        ("glBlendEquationOES", lambda gl, s, t: gl.glBlendEquationOES(gl.GL_FUNC_ADD_OES), ""),
        ("glBlendEquationSeparateOES", lambda gl, s, t: gl.glBlendEquationSeparateOES(
            gl.GL_FUNC_ADD_OES, gl.GL_FUNC_ADD_OES), ""),
        ("glLogicOp", lambda gl, s, t: gl.glLogicOp(gl.GL_COPY), ""),
        ("glSampleCoverage", lambda gl, s, t: gl.glSampleCoverage(1.0, False), ""),
        ("glSampleCoveragex", lambda gl, s, t: gl.glSampleCoveragex(ONE, False), ""),
        ("glCullFace", lambda gl, s, t: gl.glCullFace(gl.GL_BACK), ""),
        ("glFrontFace", lambda gl, s, t: gl.glFrontFace(gl.GL_CCW), ""),
        ("glShadeModel", lambda gl, s, t: gl.glShadeModel(gl.GL_SMOOTH), ""),
        ("glPolygonOffset", lambda gl, s, t: gl.glPolygonOffset(0.0, 0.0), ""),
        ("glPolygonOffsetx", lambda gl, s, t: gl.glPolygonOffsetx(0, 0), ""),
        ("glPointSize", lambda gl, s, t: gl.glPointSize(1.0), ""),
        ("glPointSizex", lambda gl, s, t: gl.glPointSizex(ONE), ""),
        ("glLineWidth", lambda gl, s, t: gl.glLineWidth(1.0), ""),
        ("glLineWidthx", lambda gl, s, t: gl.glLineWidthx(ONE), ""),
        ("glPointParameterf", lambda gl, s, t: gl.glPointParameterf(gl.GL_POINT_SIZE_MIN, 0.0), ""),
        ("glPointParameterfv", lambda gl, s, t: gl.glPointParameterfv(
            gl.GL_POINT_DISTANCE_ATTENUATION, [1.0, 0.0, 0.0]), ""),
        ("glPointParameterx", lambda gl, s, t: gl.glPointParameterx(gl.GL_POINT_SIZE_MIN, 0), ""),
        ("glPointParameterxv", lambda gl, s, t: gl.glPointParameterxv(
            gl.GL_POINT_DISTANCE_ATTENUATION, [ONE, 0, 0]), ""),
        ("glFogf", lambda gl, s, t: gl.glFogf(gl.GL_FOG_DENSITY, 1.0), ""),
        ("glFogfv", lambda gl, s, t: gl.glFogfv(gl.GL_FOG_COLOR, [0.0, 0.0, 0.0, 0.0]), ""),
        ("glFogx", lambda gl, s, t: gl.glFogx(gl.GL_FOG_MODE, gl.GL_EXP), ""),
        ("glFogxv", lambda gl, s, t: gl.glFogxv(gl.GL_FOG_COLOR, [0, 0, 0, 0]), ""),
        ("glPixelStorei", lambda gl, s, t: gl.glPixelStorei(gl.GL_PACK_ALIGNMENT, 4), ""),
        # matrices
        ("glMatrixMode", lambda gl, s, t: gl.glMatrixMode(gl.GL_PROJECTION), ""),
        ("glLoadIdentity", lambda gl, s, t: gl.glLoadIdentity(), ""),
        ("glPushMatrix", lambda gl, s, t: gl.glPushMatrix(), ""),
        ("glFrustumf", lambda gl, s, t: gl.glFrustumf(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0), ""),
        ("glFrustumx", lambda gl, s, t: gl.glFrustumx(-ONE, ONE, -ONE, ONE, ONE, 10 * ONE), ""),
        ("glOrthof", lambda gl, s, t: gl.glOrthof(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0), ""),
        ("glOrthox", lambda gl, s, t: gl.glOrthox(-ONE, ONE, -ONE, ONE, -ONE, ONE), ""),
        ("glPopMatrix", lambda gl, s, t: gl.glPopMatrix(), ""),
        ("glLoadMatrixf", lambda gl, s, t: gl.glLoadMatrixf(_IDENTITY_F), ""),
        ("glLoadMatrixx", lambda gl, s, t: gl.glLoadMatrixx(_IDENTITY_X), ""),
        ("glMultMatrixf", lambda gl, s, t: gl.glMultMatrixf(_IDENTITY_F), ""),
        ("glMultMatrixx", lambda gl, s, t: gl.glMultMatrixx(_IDENTITY_X), ""),
        ("glRotatef", lambda gl, s, t: gl.glRotatef(0.0, 0.0, 0.0, 1.0), ""),
        ("glRotatex", lambda gl, s, t: gl.glRotatex(0, 0, 0, ONE), ""),
        ("glScalef", lambda gl, s, t: gl.glScalef(1.0, 1.0, 1.0), ""),
        ("glScalex", lambda gl, s, t: gl.glScalex(ONE, ONE, ONE), ""),
        ("glTranslatef", lambda gl, s, t: gl.glTranslatef(0.0, 0.0, 0.0), ""),
        ("glTranslatex", lambda gl, s, t: gl.glTranslatex(0, 0, 0), ""),
        ("glClipPlanef", lambda gl, s, t: gl.glClipPlanef(gl.GL_CLIP_PLANE0, [0.0, 0.0, 0.0, 1.0]), ""),
        ("glClipPlanex", lambda gl, s, t: gl.glClipPlanex(gl.GL_CLIP_PLANE0, [0, 0, 0, ONE]), ""),
        ("glGetClipPlanef", lambda gl, s, t: gl.glGetClipPlanef(gl.GL_CLIP_PLANE0), ""),
        ("glGetClipPlanex", lambda gl, s, t: gl.glGetClipPlanex(gl.GL_CLIP_PLANE0), ""),
        ("glQueryMatrixxOES", lambda gl, s, t: gl.glQueryMatrixxOES(), ""),
        # current values
        ("glColor4f", lambda gl, s, t: gl.glColor4f(1.0, 1.0, 1.0, 1.0), ""),
        ("glColor4ub", lambda gl, s, t: gl.glColor4ub(255, 255, 255, 255), ""),
        ("glColor4x", lambda gl, s, t: gl.glColor4x(ONE, ONE, ONE, ONE), ""),
        ("glNormal3f", lambda gl, s, t: gl.glNormal3f(0.0, 0.0, 1.0), ""),
        ("glNormal3x", lambda gl, s, t: gl.glNormal3x(0, 0, ONE), ""),
        ("glMultiTexCoord4f", lambda gl, s, t: gl.glMultiTexCoord4f(gl.GL_TEXTURE0, 0.0, 0.0, 0.0, 1.0), ""),
        ("glMultiTexCoord4x", lambda gl, s, t: gl.glMultiTexCoord4x(gl.GL_TEXTURE0, 0, 0, 0, ONE), ""),
        # lighting
        ("glLightf", lambda gl, s, t: gl.glLightf(gl.GL_LIGHT0, gl.GL_SPOT_EXPONENT, 0.0), ""),
        ("glLightfv", lambda gl, s, t: gl.glLightfv(gl.GL_LIGHT0, gl.GL_AMBIENT, [0.0, 0.0, 0.0, 1.0]), ""),
        ("glLightx", lambda gl, s, t: gl.glLightx(gl.GL_LIGHT0, gl.GL_SPOT_CUTOFF, 180 * ONE), ""),
        ("glLightxv", lambda gl, s, t: gl.glLightxv(gl.GL_LIGHT0, gl.GL_DIFFUSE, [ONE, ONE, ONE, ONE]), ""),
        ("glLightModelf", lambda gl, s, t: gl.glLightModelf(gl.GL_LIGHT_MODEL_TWO_SIDE, 0.0), ""),
        ("glLightModelfv", lambda gl, s, t: gl.glLightModelfv(
            gl.GL_LIGHT_MODEL_AMBIENT, [0.2, 0.2, 0.2, 1.0]), ""),
        ("glLightModelx", lambda gl, s, t: gl.glLightModelx(gl.GL_LIGHT_MODEL_TWO_SIDE, 0), ""),
        ("glLightModelxv", lambda gl, s, t: gl.glLightModelxv(
            gl.GL_LIGHT_MODEL_AMBIENT, [_fx(0.2), _fx(0.2), _fx(0.2), ONE]), ""),
        ("glMaterialf", lambda gl, s, t: gl.glMaterialf(gl.GL_FRONT_AND_BACK, gl.GL_SHININESS, 0.0), ""),
        ("glMaterialfv", lambda gl, s, t: gl.glMaterialfv(
            gl.GL_FRONT_AND_BACK, gl.GL_AMBIENT, [0.2, 0.2, 0.2, 1.0]), ""),
        ("glMaterialx", lambda gl, s, t: gl.glMaterialx(gl.GL_FRONT_AND_BACK, gl.GL_SHININESS, 0), ""),
        ("glMaterialxv", lambda gl, s, t: gl.glMaterialxv(
            gl.GL_FRONT_AND_BACK, gl.GL_DIFFUSE, [_fx(0.8), _fx(0.8), _fx(0.8), ONE]), ""),
        ("glGetLightfv", lambda gl, s, t: gl.glGetLightfv(gl.GL_LIGHT0, gl.GL_AMBIENT), ""),
        ("glGetLightxv", lambda gl, s, t: gl.glGetLightxv(gl.GL_LIGHT0, gl.GL_DIFFUSE), ""),
        ("glGetMaterialfv", lambda gl, s, t: gl.glGetMaterialfv(gl.GL_FRONT, gl.GL_AMBIENT), ""),
        ("glGetMaterialxv", lambda gl, s, t: gl.glGetMaterialxv(gl.GL_FRONT, gl.GL_DIFFUSE), ""),
        # buffer objects (deleting the bound buffer unbinds it, so the
        # client-memory pointers below are addresses again)
        ("glGenBuffers", lambda gl, s, t: s.__setitem__("buf", int(gl.glGenBuffers(1))), ""),
        ("glBindBuffer", lambda gl, s, t: gl.glBindBuffer(gl.GL_ARRAY_BUFFER, s["buf"]), ""),
        ("glBufferData", lambda gl, s, t: gl.glBufferData(
            gl.GL_ARRAY_BUFFER, 64, arr(np.uint8, 64), gl.GL_STATIC_DRAW), ""),
        ("glBufferSubData", lambda gl, s, t: gl.glBufferSubData(
            gl.GL_ARRAY_BUFFER, 16, 16, arr(np.uint8, 16)), ""),
        ("glGetBufferParameteriv", lambda gl, s, t: gl.glGetBufferParameteriv(
            gl.GL_ARRAY_BUFFER, gl.GL_BUFFER_SIZE), ""),
        ("glIsBuffer", lambda gl, s, t: gl.glIsBuffer(s["buf"]), ""),
        ("glMapBufferOES", lambda gl, s, t: gl.glMapBufferOES(gl.GL_ARRAY_BUFFER, gl.GL_WRITE_ONLY_OES), ""),
        ("glGetBufferPointervOES", lambda gl, s, t: gl.glGetBufferPointervOES(
            gl.GL_ARRAY_BUFFER, gl.GL_BUFFER_MAP_POINTER_OES), ""),
        ("glUnmapBufferOES", lambda gl, s, t: gl.glUnmapBufferOES(gl.GL_ARRAY_BUFFER), ""),
        ("glMapBufferRangeEXT", lambda gl, s, t: gl.glMapBufferRangeEXT(
            gl.GL_ARRAY_BUFFER, 0, 4, gl.GL_MAP_WRITE_BIT_EXT | gl.GL_MAP_FLUSH_EXPLICIT_BIT_EXT), ""),
        ("glFlushMappedBufferRangeEXT", lambda gl, s, t: (
            gl.glFlushMappedBufferRangeEXT(gl.GL_ARRAY_BUFFER, 0, 4),
            gl.glUnmapBufferOES(gl.GL_ARRAY_BUFFER)), ""),
        ("glDeleteBuffers", lambda gl, s, t: gl.glDeleteBuffers(1, [s["buf"]]), ""),
        # textures
        ("glActiveTexture", lambda gl, s, t: gl.glActiveTexture(gl.GL_TEXTURE0), ""),
        ("glClientActiveTexture", lambda gl, s, t: gl.glClientActiveTexture(gl.GL_TEXTURE0), ""),
        ("glGenTextures", lambda gl, s, t: s.__setitem__("tex", int(gl.glGenTextures(1))), ""),
        ("glBindTexture", lambda gl, s, t: gl.glBindTexture(gl.GL_TEXTURE_2D, s["tex"]), ""),
        ("glTexImage2D", lambda gl, s, t: gl.glTexImage2D(
            gl.GL_TEXTURE_2D, 0, gl.GL_RGBA, 4, 4, 0, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE,
            arr(np.uint8, 64)), ""),
        ("glTexSubImage2D", lambda gl, s, t: gl.glTexSubImage2D(
            gl.GL_TEXTURE_2D, 0, 1, 1, 2, 2, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE, arr(np.uint8, 16)), ""),
        ("glCopyTexImage2D", lambda gl, s, t: gl.glCopyTexImage2D(
            gl.GL_TEXTURE_2D, 0, gl.GL_RGB, 0, 0, 4, 4, 0), ""),
        ("glCopyTexSubImage2D", lambda gl, s, t: gl.glCopyTexSubImage2D(
            gl.GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2), ""),
        ("glTexParameterf", lambda gl, s, t: gl.glTexParameterf(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MIN_FILTER, float(gl.GL_LINEAR)), ""),
        ("glTexParameterfv", lambda gl, s, t: gl.glTexParameterfv(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAG_FILTER, [float(gl.GL_LINEAR)]), ""),
        ("glTexParameteri", lambda gl, s, t: gl.glTexParameteri(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_WRAP_S, gl.GL_CLAMP_TO_EDGE), ""),
        ("glTexParameteriv", lambda gl, s, t: gl.glTexParameteriv(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_WRAP_T, [gl.GL_CLAMP_TO_EDGE]), ""),
        ("glTexParameterx", lambda gl, s, t: gl.glTexParameterx(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST), ""),
        ("glTexParameterxv", lambda gl, s, t: gl.glTexParameterxv(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAG_FILTER, [gl.GL_NEAREST]), ""),
        ("glGetTexParameterfv", lambda gl, s, t: gl.glGetTexParameterfv(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MIN_FILTER), ""),
        ("glGetTexParameteriv", lambda gl, s, t: gl.glGetTexParameteriv(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_WRAP_S), ""),
        ("glGetTexParameterxv", lambda gl, s, t: gl.glGetTexParameterxv(
            gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAG_FILTER), ""),
        ("glTexEnvf", lambda gl, s, t: gl.glTexEnvf(
            gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE, float(gl.GL_MODULATE)), ""),
        ("glTexEnvfv", lambda gl, s, t: gl.glTexEnvfv(
            gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_COLOR, [0.0, 0.0, 0.0, 0.0]), ""),
        ("glTexEnvi", lambda gl, s, t: gl.glTexEnvi(
            gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE, gl.GL_MODULATE), ""),
        ("glTexEnviv", lambda gl, s, t: gl.glTexEnviv(
            gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_COLOR, [0, 0, 0, 0]), ""),
        ("glTexEnvx", lambda gl, s, t: gl.glTexEnvx(
            gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE, gl.GL_MODULATE), ""),
        ("glTexEnvxv", lambda gl, s, t: gl.glTexEnvxv(
            gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_COLOR, [0, 0, 0, 0]), ""),
        ("glGetTexEnvfv", lambda gl, s, t: gl.glGetTexEnvfv(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_COLOR), ""),
        ("glGetTexEnviv", lambda gl, s, t: gl.glGetTexEnviv(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE), ""),
        ("glGetTexEnvxv", lambda gl, s, t: gl.glGetTexEnvxv(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE), ""),
        ("glIsTexture", lambda gl, s, t: gl.glIsTexture(s["tex"]), ""),
        # OES_texture_cube_map's texture coordinate generation
        ("glTexGeniOES", lambda gl, s, t: gl.glTexGeniOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES, gl.GL_REFLECTION_MAP_OES), ""),
        ("glTexGenivOES", lambda gl, s, t: gl.glTexGenivOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES, [gl.GL_NORMAL_MAP_OES]), ""),
        ("glTexGenfOES", lambda gl, s, t: gl.glTexGenfOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES, float(gl.GL_REFLECTION_MAP_OES)), ""),
        ("glTexGenfvOES", lambda gl, s, t: gl.glTexGenfvOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES, [float(gl.GL_NORMAL_MAP_OES)]), ""),
        ("glTexGenxOES", lambda gl, s, t: gl.glTexGenxOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES, gl.GL_REFLECTION_MAP_OES), ""),
        ("glTexGenxvOES", lambda gl, s, t: gl.glTexGenxvOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES, [gl.GL_NORMAL_MAP_OES]), ""),
        ("glGetTexGenivOES", lambda gl, s, t: gl.glGetTexGenivOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES), ""),
        ("glGetTexGenfvOES", lambda gl, s, t: gl.glGetTexGenfvOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES), ""),
        ("glGetTexGenxvOES", lambda gl, s, t: gl.glGetTexGenxvOES(
            gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES), ""),
        # OES_framebuffer_object (deleting the bound framebuffer rebinds the window)
        ("glGenerateMipmapOES", lambda gl, s, t: gl.glGenerateMipmapOES(gl.GL_TEXTURE_2D), ""),
        ("glGenFramebuffersOES", lambda gl, s, t: s.__setitem__(
            "fb", int(gl.glGenFramebuffersOES(1))), ""),
        ("glBindFramebufferOES", lambda gl, s, t: gl.glBindFramebufferOES(
            gl.GL_FRAMEBUFFER_OES, s["fb"]), ""),
        ("glIsFramebufferOES", lambda gl, s, t: gl.glIsFramebufferOES(s["fb"]), ""),
        ("glGenRenderbuffersOES", lambda gl, s, t: s.__setitem__(
            "rb", int(gl.glGenRenderbuffersOES(1))), ""),
        ("glBindRenderbufferOES", lambda gl, s, t: gl.glBindRenderbufferOES(
            gl.GL_RENDERBUFFER_OES, s["rb"]), ""),
        ("glIsRenderbufferOES", lambda gl, s, t: gl.glIsRenderbufferOES(s["rb"]), ""),
        ("glRenderbufferStorageOES", lambda gl, s, t: gl.glRenderbufferStorageOES(
            gl.GL_RENDERBUFFER_OES, gl.GL_RGB565_OES, 4, 4), ""),
        ("glGetRenderbufferParameterivOES", lambda gl, s, t: gl.glGetRenderbufferParameterivOES(
            gl.GL_RENDERBUFFER_OES, gl.GL_RENDERBUFFER_WIDTH_OES), ""),
        ("glFramebufferTexture2DOES", lambda gl, s, t: gl.glFramebufferTexture2DOES(
            gl.GL_FRAMEBUFFER_OES, gl.GL_COLOR_ATTACHMENT0_OES, gl.GL_TEXTURE_2D, s["tex"], 0), ""),
        ("glFramebufferRenderbufferOES", lambda gl, s, t: gl.glFramebufferRenderbufferOES(
            gl.GL_FRAMEBUFFER_OES, gl.GL_COLOR_ATTACHMENT0_OES, gl.GL_RENDERBUFFER_OES, s["rb"]), ""),
        ("glCheckFramebufferStatusOES", lambda gl, s, t: gl.glCheckFramebufferStatusOES(
            gl.GL_FRAMEBUFFER_OES), ""),
        ("glDiscardFramebufferEXT", lambda gl, s, t: gl.glDiscardFramebufferEXT(
            gl.GL_FRAMEBUFFER_OES, 1, np.array([gl.GL_COLOR_ATTACHMENT0_OES], np.uint32)), ""),
        ("glGetFramebufferAttachmentParameterivOES",
         lambda gl, s, t: gl.glGetFramebufferAttachmentParameterivOES(
             gl.GL_FRAMEBUFFER_OES, gl.GL_COLOR_ATTACHMENT0_OES,
             gl.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES), ""),
        ("glDeleteFramebuffersOES", lambda gl, s, t: gl.glDeleteFramebuffersOES(1, [s["fb"]]), ""),
        ("glDeleteRenderbuffersOES", lambda gl, s, t: gl.glDeleteRenderbuffersOES(1, [s["rb"]]), ""),
        # a paletted image: 16-entry RGBA8 palette + 2x2 4-bit indices (§3.7.4)
        ("glCompressedTexImage2D", lambda gl, s, t: gl.glCompressedTexImage2D(
            gl.GL_TEXTURE_2D, 0, gl.GL_PALETTE4_RGBA8_OES, 2, 2, 0, 66, arr(np.uint8, 66)), ""),
        # §3.7.4: paletted textures cannot be sub-updated, and ES 1.1 core has
        # no other compressed format, so the legal call is this one and it errs
        ("glCompressedTexSubImage2D", lambda gl, s, t: gl.glCompressedTexSubImage2D(
            gl.GL_TEXTURE_2D, 0, 0, 0, 2, 2, gl.GL_PALETTE4_RGBA8_OES, 66, arr(np.uint8, 66)),
         "GL_INVALID_OPERATION"),
        ("glDeleteTextures", lambda gl, s, t: gl.glDeleteTextures(1, [s["tex"]]), ""),
        # arrays and drawing
        # OES_vertex_array_object (deleting the bound array object rebinds object 0)
        ("glGenVertexArraysOES", lambda gl, s, t: s.__setitem__(
            "vao", int(gl.glGenVertexArraysOES(1))), ""),
        ("glBindVertexArrayOES", lambda gl, s, t: gl.glBindVertexArrayOES(s["vao"]), ""),
        ("glIsVertexArrayOES", lambda gl, s, t: gl.glIsVertexArrayOES(s["vao"]), ""),
        ("glDeleteVertexArraysOES", lambda gl, s, t: gl.glDeleteVertexArraysOES(1, [s["vao"]]), ""),
        ("glVertexPointer", lambda gl, s, t: gl.glVertexPointer(
            2, gl.GL_FIXED, 0, s.setdefault("v", np.array([0, 0, 4 * ONE, 0, 0, 4 * ONE], np.int32))), ""),
        ("glColorPointer", lambda gl, s, t: gl.glColorPointer(
            4, gl.GL_UNSIGNED_BYTE, 0, s.setdefault("c", np.full(12, 255, np.uint8))), ""),
        ("glNormalPointer", lambda gl, s, t: gl.glNormalPointer(
            gl.GL_BYTE, 0, s.setdefault("n", np.array([0, 0, 127] * 3, np.int8))), ""),
        ("glTexCoordPointer", lambda gl, s, t: gl.glTexCoordPointer(
            2, gl.GL_SHORT, 0, s.setdefault("tc", arr(np.int16, 6))), ""),
        ("glPointSizePointerOES", lambda gl, s, t: gl.glPointSizePointerOES(
            gl.GL_FIXED, 0, s.setdefault("ps", np.full(3, ONE, np.int32))), ""),
        ("glMatrixIndexPointerOES", lambda gl, s, t: gl.glMatrixIndexPointerOES(
            1, gl.GL_UNSIGNED_BYTE, 0, s.setdefault("mi", arr(np.uint8, 3))), ""),
        ("glWeightPointerOES", lambda gl, s, t: gl.glWeightPointerOES(
            1, gl.GL_FIXED, 0, s.setdefault("wt", np.full(3, ONE, np.int32))), ""),
        ("glCurrentPaletteMatrixOES", lambda gl, s, t: gl.glCurrentPaletteMatrixOES(0), ""),
        ("glLoadPaletteFromModelViewMatrixOES",
         lambda gl, s, t: gl.glLoadPaletteFromModelViewMatrixOES(), ""),
        ("glGetPointerv", lambda gl, s, t: gl.glGetPointerv(gl.GL_VERTEX_ARRAY_POINTER), ""),
        ("glEnableClientState", lambda gl, s, t: gl.glEnableClientState(gl.GL_VERTEX_ARRAY), ""),
        ("glDisableClientState", lambda gl, s, t: gl.glDisableClientState(gl.GL_NORMAL_ARRAY), ""),
        ("glDrawArrays", lambda gl, s, t: gl.glDrawArrays(gl.GL_TRIANGLES, 0, 3), ""),
        ("glDrawElements", lambda gl, s, t: gl.glDrawElements(
            gl.GL_TRIANGLES, 3, gl.GL_UNSIGNED_SHORT, s.setdefault("i", np.array([0, 1, 2], np.uint16))), ""),
        ("glMultiDrawArraysEXT", lambda gl, s, t: gl.glMultiDrawArraysEXT(
            gl.GL_TRIANGLES, s.setdefault("mf", np.array([0, 0], np.int32)),
            s.setdefault("mc", np.array([3, 3], np.int32)), 2), ""),
        ("glMultiDrawElementsEXT", lambda gl, s, t: gl.glMultiDrawElementsEXT(
            gl.GL_TRIANGLES, s.setdefault("mc", np.array([3, 3], np.int32)), gl.GL_UNSIGNED_SHORT,
            [s["i"], s["i"]], 2), ""),
        # OES_draw_texture: a 1x1 rectangle (no texture enabled, so the current colour)
        ("glDrawTexsOES", lambda gl, s, t: gl.glDrawTexsOES(0, 0, 0, 1, 1), ""),
        ("glDrawTexiOES", lambda gl, s, t: gl.glDrawTexiOES(0, 0, 0, 1, 1), ""),
        ("glDrawTexxOES", lambda gl, s, t: gl.glDrawTexxOES(0, 0, 0, ONE, ONE), ""),
        ("glDrawTexfOES", lambda gl, s, t: gl.glDrawTexfOES(0.0, 0.0, 0.0, 1.0, 1.0), ""),
        ("glDrawTexsvOES", lambda gl, s, t: gl.glDrawTexsvOES(np.array([0, 0, 0, 1, 1], np.int16)), ""),
        ("glDrawTexivOES", lambda gl, s, t: gl.glDrawTexivOES(np.array([0, 0, 0, 1, 1], np.int32)), ""),
        ("glDrawTexxvOES", lambda gl, s, t: gl.glDrawTexxvOES(np.array([0, 0, 0, ONE, ONE], np.int32)), ""),
        ("glDrawTexfvOES", lambda gl, s, t: gl.glDrawTexfvOES(np.array([0, 0, 0, 1, 1], np.float32)), ""),
        # KHR_debug (its ES form); no sync objects exist, so the Ptr labels are INVALID_VALUE
        ("glDebugMessageCallbackKHR", lambda gl, s, t: gl.glDebugMessageCallbackKHR(None, None), ""),
        ("glDebugMessageControlKHR", lambda gl, s, t: gl.glDebugMessageControlKHR(
            gl.GL_DONT_CARE, gl.GL_DONT_CARE, gl.GL_DONT_CARE, 0, None, True), ""),
        ("glDebugMessageInsertKHR", lambda gl, s, t: gl.glDebugMessageInsertKHR(
            gl.GL_DEBUG_SOURCE_APPLICATION_KHR, gl.GL_DEBUG_TYPE_MARKER_KHR, 1,
            gl.GL_DEBUG_SEVERITY_NOTIFICATION_KHR, -1, "covgl"), ""),
        ("glPushDebugGroupKHR", lambda gl, s, t: gl.glPushDebugGroupKHR(
            gl.GL_DEBUG_SOURCE_APPLICATION_KHR, 1, -1, "covgl"), ""),
        ("glPopDebugGroupKHR", lambda gl, s, t: gl.glPopDebugGroupKHR(), ""),
        ("glGetDebugMessageLogKHR", lambda gl, s, t: gl.glGetDebugMessageLogKHR(
            4, 0, None, None, None, None, None, None), ""),
        ("glObjectLabelKHR", lambda gl, s, t: (gl.glBindTexture(gl.GL_TEXTURE_2D, 9),
                                               gl.glObjectLabelKHR(gl.GL_TEXTURE, 9, -1, "covgl")), ""),
        ("glGetObjectLabelKHR", lambda gl, s, t: gl.glGetObjectLabelKHR(gl.GL_TEXTURE, 9, 16), ""),
        ("glObjectPtrLabelKHR", lambda gl, s, t: gl.glObjectPtrLabelKHR(None, -1, "covgl"),
         "GL_INVALID_VALUE"),
        ("glGetObjectPtrLabelKHR", lambda gl, s, t: gl.glGetObjectPtrLabelKHR(None, 16),
         "GL_INVALID_VALUE"),
        ("glGetPointervKHR", lambda gl, s, t: gl.glGetPointervKHR(gl.GL_DEBUG_CALLBACK_FUNCTION_KHR), ""),
        ("glFlush", lambda gl, s, t: gl.glFlush(), ""),
        ("glFinish", lambda gl, s, t: gl.glFinish(), ""),
        ("glReadPixels", lambda gl, s, t: gl.glReadPixels(0, 0, 4, 4, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE), ""),
    ]
    return calls


COVGL_CALLS = _covgl_calls()

# Entry points of optional extensions (not among the 145 commands of ES 1.1):
# called only where the context's GL_EXTENSIONS names the extension.
_EXTENSIONS = {
    "GL_OES_blend_equation_separate": "glBlendEquationSeparateOES",
    "GL_OES_blend_func_separate": "glBlendFuncSeparateOES",
    "GL_OES_blend_subtract": "glBlendEquationOES",
    "GL_OES_draw_texture": "glDrawTexsOES glDrawTexiOES glDrawTexxOES glDrawTexfOES glDrawTexsvOES "
                           "glDrawTexivOES glDrawTexxvOES glDrawTexfvOES",
    "GL_OES_framebuffer_object": "glGenerateMipmapOES glGenFramebuffersOES glBindFramebufferOES "
                                 "glIsFramebufferOES glGenRenderbuffersOES glBindRenderbufferOES "
                                 "glIsRenderbufferOES glRenderbufferStorageOES "
                                 "glGetRenderbufferParameterivOES glFramebufferTexture2DOES "
                                 "glFramebufferRenderbufferOES "
                                 "glCheckFramebufferStatusOES glGetFramebufferAttachmentParameterivOES "
                                 "glDeleteFramebuffersOES glDeleteRenderbuffersOES",
    "GL_OES_mapbuffer": "glMapBufferOES glGetBufferPointervOES glUnmapBufferOES",
    "GL_EXT_map_buffer_range": "glMapBufferRangeEXT glFlushMappedBufferRangeEXT",
    "GL_EXT_multi_draw_arrays": "glMultiDrawArraysEXT glMultiDrawElementsEXT",
    "GL_EXT_discard_framebuffer": "glDiscardFramebufferEXT",
    "GL_KHR_debug": "glDebugMessageControlKHR glDebugMessageInsertKHR glDebugMessageCallbackKHR "
                    "glGetDebugMessageLogKHR glPushDebugGroupKHR glPopDebugGroupKHR glObjectLabelKHR "
                    "glGetObjectLabelKHR glObjectPtrLabelKHR glGetObjectPtrLabelKHR glGetPointervKHR",
    "GL_OES_matrix_palette": "glCurrentPaletteMatrixOES glLoadPaletteFromModelViewMatrixOES "
                             "glMatrixIndexPointerOES glWeightPointerOES",
    "GL_OES_query_matrix": "glQueryMatrixxOES",
    "GL_OES_texture_cube_map": "glTexGeniOES glTexGenivOES glTexGenfOES glTexGenfvOES glTexGenxOES "
                               "glTexGenxvOES glGetTexGenivOES glGetTexGenfvOES glGetTexGenxvOES",
    "GL_OES_vertex_array_object": "glGenVertexArraysOES glBindVertexArrayOES glIsVertexArrayOES "
                                  "glDeleteVertexArraysOES",
}
EXTENSION_COMMANDS = {name: ext for ext, names in _EXTENSIONS.items() for name in names.split()}


def covgl_commands(profile: str, extensions: frozenset[str] = frozenset()) -> list[str]:
    """The commands covgl calls: the profile's commands that gles implements,
    less those of optional extensions missing from `extensions`."""
    names = _gles_gl.COMMON_COMMANDS if profile == "common" else _gles_gl.COMMON_LITE_COMMANDS
    return [n for n in names if n not in _gles_gl.MISSING
            and (n not in EXTENSION_COMMANDS or EXTENSION_COMMANDS[n] in extensions)]


@conformance_test("covgl", section="C")
def covgl(t: TestContext) -> None:
    """Every entry point accepts legal arguments without a GL error."""
    gl = t.gl
    extensions = frozenset((gl.glGetString(gl.GL_EXTENSIONS) or b"").decode().split())
    t.check_gl_error("glGetString(GL_EXTENSIONS)")
    wanted = set(covgl_commands(t.profile, extensions))
    table = {name for name, _, _ in COVGL_CALLS}
    missing = sorted(wanted - table)
    if missing:
        t.fail(f"covgl has no legal call for {', '.join(missing)}")
    state: dict[str, Any] = {}
    called = set()
    t.check_gl_error("before covgl")
    for name, call, expected in COVGL_CALLS:
        if name not in wanted:
            continue
        try:
            getattr(gl, name)
        except AttributeError:
            t.fail(f"{name} is not an entry point of this {t.profile} context")
        call(gl, state, t)
        called.add(name)
        want = getattr(gl, expected) if expected else 0
        err = gl.glGetError()
        if err != want:
            t.fail(f"{name} with legal arguments: glGetError() is 0x{err:04X}, expected 0x{want:04X}")
    if called != wanted:
        t.fail(f"covgl did not call {sorted(wanted - called)}")
