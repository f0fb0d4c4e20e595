"""Per-fragment operations (ES 1.1 §4.1, §4.2) against the spec's formulas in numpy.

Scissor, alpha test, stencil test and operations (with OES_stencil_wrap),
blending (every factor, OES_blend_subtract, OES_blend_func_separate,
OES_blend_equation_separate), dither, logic op, the write masks, Clear,
ReadPixels of the implementation format, and the multisample state with
SAMPLE_BUFFERS 0.

Every pixel is drawn as its own one-pixel quad with its own flat colour, so
one draw tests a thousand (source, destination) pairs. Colours are ubytes
c/255; the expected result is the spec's formula in float64, clamped and
rounded to nearest. With such inputs an exact result is never a rounding tie
(a sum of products of two ubytes over 255 is at least 1/255 of a step from
one), and every build keeps ubyte colours to within 2^-24 of exact (the fixed
build in 0.30), so every build must match exactly.
"""

from __future__ import annotations

import itertools
from typing import Any, Callable

import numpy as np
import pytest
from conftest import BUILDS, set_ortho

import gles
from gles import constants as C

W = H = 32

FUNCS: dict[str, Callable[[Any, Any], Any]] = {
    "NEVER": lambda a, b: np.zeros(np.broadcast(a, b).shape, dtype=bool),
    "LESS": np.less,
    "EQUAL": np.equal,
    "LEQUAL": np.less_equal,
    "GREATER": np.greater,
    "NOTEQUAL": np.not_equal,
    "GEQUAL": np.greater_equal,
    "ALWAYS": lambda a, b: np.ones(np.broadcast(a, b).shape, dtype=bool),
}

# how close to an integer floor(v 2^b) may find an exact 5/6-bit value and
# still go either way: far above every build's rounding of ubyte colours
# (float32 3e-6 of a 6-bit step, 0.30 3e-8), far below the 1/255 of a step
# between distinct exact values
FLOOR_SLACK = 1e-4

# the 16-bit colour buffers' channels as GL's packed types: (bits, lowest bit)
# of R, G, B (and A) in the word, red in the high bits
LAYOUTS = {"rgb565": ((5, 11), (6, 5), (5, 0)),
           "rgba4444": ((4, 12), (4, 8), (4, 4), (4, 0)),
           "rgba5551": ((5, 11), (5, 6), (5, 1), (1, 0))}
FORMATS16 = tuple(LAYOUTS)


def bits_of(color: str) -> np.ndarray:
    """The channel widths of a 16-bit format (3 for RGB565, else 4)."""
    return np.array([b for b, _ in LAYOUTS[color]])


def split16(raw: np.ndarray, color: str) -> np.ndarray:
    """A 16-bit buffer's words as their channels (..., 3 or 4) of integers."""
    raw = np.asarray(raw).astype(np.int64)
    return np.stack([(raw >> shift) & ((1 << bits) - 1) for bits, shift in LAYOUTS[color]], axis=-1)


def channel_masks(color: str) -> list[int]:
    """The word's bits of each channel of a 16-bit format."""
    return [((1 << bits) - 1) << shift for bits, shift in LAYOUTS[color]]


# {============================================================
# drawing helpers

def pixel_quads(w: int, h: int) -> np.ndarray:
    """Two triangles per pixel of a w x h window, row-major from the bottom row: (6wh, 2) float32."""
    ys, xs = np.mgrid[0:h, 0:w]
    x = xs.reshape(-1).astype(np.float32)
    y = ys.reshape(-1).astype(np.float32)
    corners = [(0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (0, 1)]
    return np.stack([np.stack([x + dx, y + dy], axis=1) for dx, dy in corners], axis=1).reshape(-1, 2)


class Frame:
    """A context with window-pixel coordinates, flat shading and dither off.

    ``paint(rgba)`` draws every pixel (or those of ``where``) as one quad of
    colour ``rgba[y, x]`` (ubyte) at window depth ``depth[y, x]``.
    """

    def __init__(self, numeric: str, w: int = W, h: int = H, **kw: Any) -> None:
        self.ctx = gles.Context(w, h, numeric=numeric, **kw)
        self.gl = self.ctx.gl
        self.w, self.h = w, h
        set_ortho(self.gl, w, h)
        self.gl.glShadeModel(C.GL_FLAT)
        self.gl.glDisable(C.GL_DITHER)
        self.quads = pixel_quads(w, h)

    def paint(self, rgba: Any = None, *, depth: Any = 0.5, where: Any = None) -> None:
        gl = self.gl
        n = self.w * self.h
        z = np.broadcast_to(1.0 - 2.0 * np.asarray(depth, dtype=np.float64), (self.h, self.w)).reshape(-1)
        v = np.column_stack([self.quads, np.repeat(z, 6)]).astype(np.float32)
        col = None
        if rgba is not None:
            col = np.broadcast_to(np.asarray(rgba, dtype=np.uint8), (self.h, self.w, 4)).reshape(n, 4)
            col = np.repeat(col, 6, axis=0)
        if where is not None:
            keep = np.repeat(np.asarray(where, dtype=bool).reshape(-1), 6)
            v = v[keep]
            col = None if col is None else col[keep]
            if not len(v):
                return
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, np.ascontiguousarray(v))
        if col is None:
            gl.glDisableClientState(C.GL_COLOR_ARRAY)
        else:
            gl.glEnableClientState(C.GL_COLOR_ARRAY)
            gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(col))
        gl.glDrawArrays(C.GL_TRIANGLES, 0, len(v))

    def fill_stencil(self, values: np.ndarray) -> None:
        """Write `values` into the stencil buffer one bit plane at a time (StencilMask per plane)."""
        gl = self.gl
        gl.glColorMask(False, False, False, False)
        gl.glDisable(C.GL_DEPTH_TEST)
        gl.glEnable(C.GL_STENCIL_TEST)
        gl.glStencilMask(0xFF)
        gl.glClearStencil(0)
        gl.glClear(C.GL_STENCIL_BUFFER_BIT)
        gl.glStencilFunc(C.GL_ALWAYS, 0xFF, 0xFF)
        gl.glStencilOp(C.GL_REPLACE, C.GL_REPLACE, C.GL_REPLACE)
        for b in range(8):
            gl.glStencilMask(1 << b)
            self.paint(where=(values >> b) & 1 == 1)
        gl.glStencilMask(0xFF)
        gl.glColorMask(True, True, True, True)

    def fill_depth(self, depth: np.ndarray) -> None:
        """Write per-pixel window depths (colour and stencil untouched)."""
        gl = self.gl
        gl.glColorMask(False, False, False, False)
        gl.glDisable(C.GL_STENCIL_TEST)
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDepthFunc(C.GL_ALWAYS)
        gl.glDepthMask(True)
        self.paint(depth=depth)
        gl.glColorMask(True, True, True, True)

    def rgba(self) -> np.ndarray:
        return self.ctx.color_buffer().astype(np.int64)


def ub_round(v: np.ndarray) -> np.ndarray:
    """The spec's conversion of [0, 1] values to 8 bits: clamp, round to nearest."""
    return np.floor(np.clip(v, 0.0, 1.0) * 255.0 + 0.5).astype(np.int64)


def check_rounded(got: np.ndarray, exact: np.ndarray, what: str) -> None:
    """`got` (8-bit) is `exact` (real, [0,1] after clamping) rounded to nearest, exactly."""
    e = np.clip(exact, 0.0, 1.0) * 255.0
    want = np.floor(e + 0.5).astype(np.int64)
    bad = got != want
    if bad.any():
        i = tuple(np.argwhere(bad)[0])
        pytest.fail(f"{what}: {int(bad.sum())} channel values differ from round-to-nearest; first at {i}: "
                    f"got {got[i]}, exact {e[i]:.6f} (want {want[i]})")


# {============================================================
# alpha test (§4.1.4)

ALPHA_REFS = (0.0, 1 / 255, 77 / 255, 128 / 255, 254 / 255, 1.0, 0.35, 128.3 / 255, 127.7 / 255, -0.5, 1.5)


@pytest.mark.parametrize("numeric", BUILDS)
def test_alpha_functions_and_reference_clamp(numeric):
    """Every function against every alpha 0..255: ref clamped to [0, 1] and both sides
    compared as 8-bit values (ref rounded to nearest, §4.1.4); the state reads back."""
    f = Frame(numeric, 16, 16)
    gl = f.gl
    alpha = np.arange(256).reshape(16, 16)
    src = np.stack([np.full_like(alpha, 255), alpha, np.full_like(alpha, 9), alpha], axis=-1)
    gl.glEnable(C.GL_ALPHA_TEST)
    for name, fn in FUNCS.items():
        for ref in ALPHA_REFS:
            gl.glClearColor(0, 0, 0, 0)
            gl.glClear(C.GL_COLOR_BUFFER_BIT)
            gl.glAlphaFunc(getattr(C, "GL_" + name), ref)
            f.paint(src)
            clamped = min(max(ref, 0.0), 1.0)
            assert gl.glGetIntegerv(C.GL_ALPHA_TEST_FUNC) == getattr(C, "GL_" + name)
            assert gl.glGetFloatv(C.GL_ALPHA_TEST_REF) == pytest.approx(clamped, abs=1e-7)
            passed = f.rgba()[..., 0] == 255
            want = fn(alpha, int(np.floor(clamped * 255 + 0.5)))
            np.testing.assert_array_equal(passed, want, err_msg=f"{numeric} ALPHA {name} ref={ref}")
    assert gl.glGetError() == 0


@pytest.mark.parametrize("numeric", BUILDS)
def test_alpha_func_fixed_form(numeric):
    """glAlphaFuncx with k/255 as 16.16 passes EQUAL for alpha k, for every k."""
    f = Frame(numeric, 16, 16)
    gl = f.gl
    alpha = np.arange(256).reshape(16, 16)
    src = np.stack([np.full_like(alpha, 255)] * 3 + [alpha], axis=-1)
    gl.glEnable(C.GL_ALPHA_TEST)
    for k in (0, 1, 100, 128, 200, 255):
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glAlphaFuncx(C.GL_EQUAL, int(round(k / 255 * 65536)))
        f.paint(src)
        np.testing.assert_array_equal(f.rgba()[..., 0] == 255, alpha == k)
    gl.glAlphaFuncx(C.GL_GEQUAL, 3 << 16)
    assert gl.glGetFixedv(C.GL_ALPHA_TEST_REF) == 1 << 16


@pytest.mark.parametrize("numeric", BUILDS)
def test_scissor_and_alpha_come_before_stencil_and_depth(numeric):
    """A fragment the scissor or the alpha test discards changes neither stencil nor depth (§4.1 order)."""
    f = Frame(numeric, 16, 16)
    gl = f.gl
    alpha = np.arange(256).reshape(16, 16)
    gl.glClearDepthf(1.0)
    gl.glClearStencil(0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    gl.glEnable(C.GL_ALPHA_TEST)
    gl.glAlphaFunc(C.GL_GREATER, 100 / 255)
    gl.glEnable(C.GL_SCISSOR_TEST)
    gl.glScissor(2, 3, 11, 9)
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(C.GL_ALWAYS, 7, 0xFF)
    gl.glStencilOp(C.GL_INCR, C.GL_INCR, C.GL_REPLACE)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_ALWAYS)
    f.paint(np.stack([alpha] * 4, axis=-1), depth=0.25)
    inbox = np.zeros((16, 16), dtype=bool)
    inbox[3:12, 2:13] = True
    reached = inbox & (alpha > 100)
    np.testing.assert_array_equal(f.ctx.stencil_buffer(), np.where(reached, 7, 0))
    np.testing.assert_array_equal(f.ctx.depth_buffer() < (1 << 24) - 1, reached)


# {============================================================
# stencil test and operations (§4.1.5, OES_stencil_wrap)

STENCIL_REFS = (0, 1, 77, 128, 254, 255, -5, 300, 1000)
STENCIL_MASKS = (0xFF, 0x0F, 0xF0, 0x3C, 0x181, 0)


@pytest.mark.parametrize("numeric", BUILDS)
def test_stencil_functions_refs_and_masks(numeric):
    """Every function, reference (clamped to [0, 255]) and value mask against every stored value."""
    f = Frame(numeric, 16, 16)
    gl = f.gl
    stored = np.arange(256, dtype=np.int64).reshape(16, 16)
    f.fill_stencil(stored)
    np.testing.assert_array_equal(f.ctx.stencil_buffer(), stored)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
    for name, fn in FUNCS.items():
        for ref, mask in itertools.product(STENCIL_REFS, STENCIL_MASKS):
            gl.glClear(C.GL_COLOR_BUFFER_BIT)
            gl.glStencilFunc(getattr(C, "GL_" + name), ref, mask)
            f.paint((255, 255, 255, 255))
            m = mask & 0xFF
            want = fn(min(max(ref, 0), 255) & m, stored & m)
            np.testing.assert_array_equal(f.rgba()[..., 0] == 255, want,
                                          err_msg=f"{numeric} STENCIL {name} ref={ref} mask={mask:#x}")
    np.testing.assert_array_equal(f.ctx.stencil_buffer(), stored)
    assert gl.glGetIntegerv(C.GL_STENCIL_FUNC) == C.GL_ALWAYS
    assert gl.glGetIntegerv(C.GL_STENCIL_VALUE_MASK) & 0xFF == 0


STENCIL_OPS = ("KEEP", "ZERO", "REPLACE", "INCR", "DECR", "INVERT", "INCR_WRAP_OES", "DECR_WRAP_OES")


def stencil_op(name: str, s: np.ndarray, ref: int) -> np.ndarray:
    """Table of §4.1.5 and OES_stencil_wrap on 8-bit values."""
    return {
        "KEEP": s,
        "ZERO": np.zeros_like(s),
        "REPLACE": np.full_like(s, min(max(ref, 0), 255)),
        "INCR": np.minimum(s + 1, 255),
        "DECR": np.maximum(s - 1, 0),
        "INVERT": ~s & 0xFF,
        "INCR_WRAP_OES": (s + 1) & 0xFF,
        "DECR_WRAP_OES": (s - 1) & 0xFF,
    }[name]


# each op once in each of the three positions
OP_TRIPLES = [(STENCIL_OPS[i], STENCIL_OPS[(i + 3) % 8], STENCIL_OPS[(i + 6) % 8]) for i in range(8)]


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("depth_bits", [16, 24])
def test_stencil_operations(numeric, depth_bits):
    """sfail / dpfail / dppass with every op (wrap included) in every position, the write mask
    and the reference clamp; colour only where both tests pass."""
    rng = np.random.default_rng(depth_bits)
    f = Frame(numeric, 16, 16, depth=depth_bits)
    gl = f.gl
    stored = np.arange(256, dtype=np.int64).reshape(16, 16)
    for (sfail, dpfail, dppass), ref, wmask in itertools.product(OP_TRIPLES, (77, 300, -3), (0xFF, 0x5A)):
        far = rng.random((16, 16)) < 0.5                 # stored depth 0.75 (the fragment at 0.5 passes LESS)
        gl.glClearColor(0, 0, 0, 0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        f.fill_depth(np.where(far, 0.75, 0.25))
        f.fill_stencil(stored)
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDepthFunc(C.GL_LESS)
        gl.glStencilFunc(C.GL_LESS, ref, 0xFF)
        gl.glStencilOp(*(getattr(C, "GL_" + op) for op in (sfail, dpfail, dppass)))
        gl.glStencilMask(wmask)
        f.paint((255, 255, 255, 255), depth=0.5)
        sp = min(max(ref, 0), 255) < stored
        new = np.where(~sp, stencil_op(sfail, stored, ref),
                       np.where(~far, stencil_op(dpfail, stored, ref), stencil_op(dppass, stored, ref)))
        new = (stored & ~wmask & 0xFF) | (new & wmask)
        what = f"{numeric} d{depth_bits} ops=({sfail}, {dpfail}, {dppass}) ref={ref} writemask={wmask:#x}"
        np.testing.assert_array_equal(f.ctx.stencil_buffer(), new, err_msg=what)
        np.testing.assert_array_equal(f.rgba()[..., 0] == 255, sp & far, err_msg=what)
        gl.glStencilMask(0xFF)
    assert gl.glGetIntegerv(C.GL_STENCIL_WRITEMASK) & 0xFF == 0xFF
    assert gl.glGetError() == 0


@pytest.mark.parametrize("numeric", BUILDS)
def test_stencil_without_depth_test_or_buffers(numeric):
    """Depth test off or no depth buffer: dppass applies (§4.1.6); no stencil buffer: the test passes."""
    stored = np.arange(256, dtype=np.int64).reshape(16, 16)
    for depth_bits, depth_on in ((24, False), (0, True)):
        f = Frame(numeric, 16, 16, depth=depth_bits)
        gl = f.gl
        f.fill_stencil(stored)
        if depth_on:
            gl.glEnable(C.GL_DEPTH_TEST)
            gl.glDepthFunc(C.GL_NEVER)
        gl.glStencilFunc(C.GL_GEQUAL, 100, 0xFF)
        gl.glStencilOp(C.GL_ZERO, C.GL_INVERT, C.GL_INCR_WRAP_OES)
        f.paint((255, 255, 255, 255))
        sp = 100 >= stored
        np.testing.assert_array_equal(f.ctx.stencil_buffer(), np.where(sp, (stored + 1) & 0xFF, 0))
        np.testing.assert_array_equal(f.rgba()[..., 0] == 255, sp)
    f = Frame(numeric, 16, 16, stencil=0)
    gl = f.gl
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(C.GL_NEVER, 0, 0xFF)
    f.paint((255, 255, 255, 255))
    assert (f.rgba()[..., 0] == 255).all()
    assert f.ctx.stencil_buffer() is None


def test_stencil_clear_value_and_mask():
    """ClearStencil keeps the low 8 bits; StencilMask and the scissor box apply to Clear (§4.2.3)."""
    f = Frame("fixed", 16, 16)
    gl = f.gl
    gl.glClearStencil(0x1A5)
    gl.glClear(C.GL_STENCIL_BUFFER_BIT)
    assert (f.ctx.stencil_buffer() == 0xA5).all()
    gl.glStencilMask(0x0F)
    gl.glClearStencil(0x3C)
    gl.glEnable(C.GL_SCISSOR_TEST)
    gl.glScissor(4, 4, 8, 8)
    gl.glClear(C.GL_STENCIL_BUFFER_BIT)
    want = np.full((16, 16), 0xA5)
    want[4:12, 4:12] = 0xAC
    np.testing.assert_array_equal(f.ctx.stencil_buffer(), want)


# {============================================================
# blending (§4.1.7, OES_blend_subtract, _func_separate, _equation_separate)

SRC_FACTORS = ("ZERO", "ONE", "DST_COLOR", "ONE_MINUS_DST_COLOR", "SRC_ALPHA", "ONE_MINUS_SRC_ALPHA",
               "DST_ALPHA", "ONE_MINUS_DST_ALPHA", "SRC_ALPHA_SATURATE")
DST_FACTORS = ("ZERO", "ONE", "SRC_COLOR", "ONE_MINUS_SRC_COLOR", "SRC_ALPHA", "ONE_MINUS_SRC_ALPHA",
               "DST_ALPHA", "ONE_MINUS_DST_ALPHA")
EQUATIONS = ("FUNC_ADD_OES", "FUNC_SUBTRACT_OES", "FUNC_REVERSE_SUBTRACT_OES")


def blend_factor(name: str, s: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Table 4.1: the (..., 4) factor for source s and destination d in [0, 1]."""
    one = np.ones_like(s)
    sa, da = s[..., 3:4] * one, d[..., 3:4] * one
    if name == "SRC_ALPHA_SATURATE":
        f = np.minimum(s[..., 3:4], 1.0 - d[..., 3:4]) * one
        f[..., 3] = 1.0
        return f
    return {"ZERO": 0 * one, "ONE": one, "SRC_COLOR": s, "ONE_MINUS_SRC_COLOR": 1 - s, "DST_COLOR": d,
            "ONE_MINUS_DST_COLOR": 1 - d, "SRC_ALPHA": sa, "ONE_MINUS_SRC_ALPHA": 1 - sa, "DST_ALPHA": da,
            "ONE_MINUS_DST_ALPHA": 1 - da}[name]


def blend_equation(name: str, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return {"FUNC_ADD_OES": a + b, "FUNC_SUBTRACT_OES": a - b, "FUNC_REVERSE_SUBTRACT_OES": b - a}[name]


def blend_expected(s8: np.ndarray, d8: np.ndarray, funcs: tuple, eqs: tuple) -> np.ndarray:
    """The blended colour before clamping, from ubyte source and destination:
    funcs = (src_rgb, dst_rgb, src_alpha, dst_alpha), eqs = (rgb, alpha)."""
    s, d = s8 / 255.0, d8 / 255.0
    rgb = blend_equation(eqs[0], s * blend_factor(funcs[0], s, d), d * blend_factor(funcs[1], s, d))
    alpha = blend_equation(eqs[1], s * blend_factor(funcs[2], s, d), d * blend_factor(funcs[3], s, d))
    return np.concatenate([rgb[..., :3], alpha[..., 3:]], axis=-1)


def blend_sweep(numeric: str) -> list:
    """Every (src, dst, equation) of BlendFunc + BlendEquationOES on random ubyte pairs:
    [(name, src, dst, got)]."""
    rng = np.random.default_rng(11)
    f = Frame(numeric)
    gl = f.gl
    out = []
    for sf, df, eq in itertools.product(SRC_FACTORS, DST_FACTORS, EQUATIONS):
        src = rng.integers(0, 256, (H, W, 4))
        dst = rng.integers(0, 256, (H, W, 4))
        gl.glDisable(C.GL_BLEND)
        f.paint(dst)
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(getattr(C, "GL_" + sf), getattr(C, "GL_" + df))
        gl.glBlendEquationOES(getattr(C, "GL_" + eq))
        f.paint(src)
        out.append(((sf, df, eq), src, dst, f.rgba()))
    return out


@pytest.mark.parametrize("numeric", BUILDS)
def test_blend_every_factor_pair_and_equation(numeric):
    """Table 4.1 for each source x destination factor (SRC_ALPHA_SATURATE included) and each
    equation, 1024 random ubyte pairs each: exactly the float64 formula rounded to nearest, in
    every build; all failing combinations are listed."""
    bad = []
    for (sf, df, eq), src, dst, got in blend_sweep(numeric):
        e = np.clip(blend_expected(src, dst, (sf, df, sf, df), (eq, eq)), 0, 1) * 255
        wrong = got != np.floor(e + 0.5)
        if wrong.any():
            i = tuple(np.argwhere(wrong)[0])
            bad.append(f"BlendFunc({sf}, {df}) {eq}: {int(wrong.sum())} values, e.g. src "
                       f"{src[i[:2]].tolist()} dst {dst[i[:2]].tolist()} channel {i[2]}: got {got[i]}, "
                       f"exact {e[i]:.5f}")
    total = len(SRC_FACTORS) * len(DST_FACTORS) * len(EQUATIONS)
    assert not bad, f"{len(bad)} of {total} blends miss round-to-nearest:\n" + "\n".join(bad[:8])


@pytest.mark.parametrize("numeric", BUILDS)
def test_blend_func_and_equation_separate(numeric):
    """OES_blend_func_separate and OES_blend_equation_separate: RGB and alpha use their own
    factors and equations; the four factors and two equations read back."""
    rng = np.random.default_rng(5)
    f = Frame(numeric)
    gl = f.gl
    for _ in range(48):
        funcs = (rng.choice(SRC_FACTORS), rng.choice(DST_FACTORS), rng.choice(SRC_FACTORS),
                 rng.choice(DST_FACTORS))
        eqs = (rng.choice(EQUATIONS), rng.choice(EQUATIONS))
        src = rng.integers(0, 256, (H, W, 4))
        dst = rng.integers(0, 256, (H, W, 4))
        gl.glDisable(C.GL_BLEND)
        f.paint(dst)
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFuncSeparateOES(*(getattr(C, "GL_" + n) for n in funcs))
        gl.glBlendEquationSeparateOES(*(getattr(C, "GL_" + n) for n in eqs))
        f.paint(src)
        check_rounded(f.rgba(), blend_expected(src, dst, funcs, eqs), f"{numeric} {funcs} {eqs}")
        pnames = (C.GL_BLEND_SRC_RGB_OES, C.GL_BLEND_DST_RGB_OES, C.GL_BLEND_SRC_ALPHA_OES,
                  C.GL_BLEND_DST_ALPHA_OES)
        assert [gl.glGetIntegerv(p) for p in pnames] == [getattr(C, "GL_" + n) for n in funcs]
        assert gl.glGetIntegerv(C.GL_BLEND_SRC) == getattr(C, "GL_" + funcs[0])
        assert gl.glGetIntegerv(C.GL_BLEND_DST) == getattr(C, "GL_" + funcs[1])
        got_eqs = [gl.glGetIntegerv(p) for p in (C.GL_BLEND_EQUATION_RGB_OES, C.GL_BLEND_EQUATION_ALPHA_OES)]
        assert got_eqs == [getattr(C, "GL_" + n) for n in eqs]


@pytest.mark.parametrize("numeric", BUILDS)
def test_src_alpha_saturate(numeric):
    """SRC_ALPHA_SATURATE: colour factor min(As, 1 - Ad), alpha factor 1 (Table 4.1)."""
    f = Frame(numeric, 16, 16)
    gl = f.gl
    a = np.arange(256).reshape(16, 16)
    src = np.stack([np.full_like(a, 200), np.full_like(a, 255), a, a], axis=-1)
    dst = np.stack([np.full_like(a, 10), a, np.full_like(a, 40), 255 - a], axis=-1)
    f.paint(dst)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA_SATURATE, C.GL_ONE)
    f.paint(src)
    sat = np.minimum(a, a) / 255.0      # min(As, 1 - Ad) with Ad = 1 - a/255
    want = np.stack([200 / 255 * sat + 10 / 255, sat + a / 255, a / 255 * sat + 40 / 255,
                     a / 255 + (255 - a) / 255], axis=-1)
    check_rounded(f.rgba(), want, f"{numeric} SRC_ALPHA_SATURATE, ONE")


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("color", FORMATS16)
def test_blend_on_16bit_formats(numeric, color):
    """RGB565, RGBA4444, RGBA5551 (dither off): destination k/(2^b - 1), Ad = 1 where there are
    no alpha bits (§4.1.7), and the result truncated to the channel's bits (§4.1.8) as
    floor(v 2^b)."""
    rng = np.random.default_rng(7)
    f = Frame(numeric, color=color)
    gl = f.gl
    bits = bits_of(color)
    nch = len(bits)
    for sf, df in [("SRC_ALPHA", "ONE_MINUS_SRC_ALPHA"), ("ONE", "ONE"), ("DST_COLOR", "ZERO"),
                   ("ONE_MINUS_DST_ALPHA", "DST_ALPHA"), ("SRC_ALPHA_SATURATE", "ONE"),
                   ("ZERO", "SRC_COLOR"), ("DST_ALPHA", "ONE_MINUS_SRC_COLOR")]:
        gl.glDisable(C.GL_BLEND)
        f.paint(rng.integers(0, 256, (H, W, 4)))
        dk = split16(f.ctx.color_buffer(), color)
        d = np.concatenate([dk / ((1 << bits) - 1), np.ones((H, W, 4 - nch))], axis=-1)
        src = rng.integers(0, 256, (H, W, 4))
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(getattr(C, "GL_" + sf), getattr(C, "GL_" + df))
        f.paint(src)
        s = src / 255.0
        v = np.clip(s * blend_factor(sf, s, d) + d * blend_factor(df, s, d), 0, 1)[..., :nch]
        got = split16(f.ctx.color_buffer(), color)
        e = v * (1 << bits)
        want = np.minimum(np.floor(e), (1 << bits) - 1)
        near = np.abs(e - np.round(e)) < FLOOR_SLACK
        either = np.minimum(np.round(e), (1 << bits) - 1)
        ok = (got == want) | (near & ((got == either) | (got == either - 1)))
        assert ok.all(), f"{numeric} {color} BlendFunc({sf}, {df}): {int((~ok).sum())} channels differ"


@pytest.mark.parametrize("numeric", BUILDS)
def test_modulation_all_65536_pairs(numeric):
    """DST_COLOR, ZERO (and ZERO, SRC_COLOR): destination column x times source row y gives
    round(x y / 255) for all 65536 pairs, so x * 255 = x and 255 * 255 = 255."""
    n = 256
    f = Frame(numeric, n, n)
    gl = f.gl
    x = np.broadcast_to(np.arange(n), (n, n))
    y = x.T
    dst = np.stack([x, 255 - x, x, 255 - x], axis=-1)
    src = np.stack([y, y, 255 - y, 255 - y], axis=-1)
    want = (2 * dst * src + 255) // 510
    assert want[255, 255, 0] == 255 and (want[255, :, 0] == np.arange(n)).all()
    for funcs in ((C.GL_DST_COLOR, C.GL_ZERO), (C.GL_ZERO, C.GL_SRC_COLOR)):
        gl.glDisable(C.GL_BLEND)
        f.paint(dst)
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(*funcs)
        f.paint(src)
        got = f.rgba()
        wrong = got != want
        assert not wrong.any(), (f"{numeric} {funcs}: {int(wrong.sum())} of {want.size} products differ, "
                                 f"first (y, x, channel) {tuple(np.argwhere(wrong)[0])}")


# {============================================================
# dither (§4.1.8) and framebuffer conversion (§2.12.8)

@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("color", FORMATS16)
def test_undithered_16bit_keeps_the_high_bits(numeric, color):
    """Dither off: an unlit ubyte colour c is stored as its high bits (c >> (8 - b)), and
    any other value v as floor(v 2^b) clamped (§2.12.8, §4.1.8), for drawing and Clear."""
    f = Frame(numeric, 16, 16, color=color)
    gl = f.gl
    bits = bits_of(color)
    c = np.arange(256).reshape(16, 16)
    cols = np.stack([c, c, 255 - c, (c * 7) & 255], axis=-1)
    f.paint(cols)
    got = split16(f.ctx.color_buffer(), color)
    np.testing.assert_array_equal(got, cols[..., :len(bits)] >> (8 - bits))
    for v in (0.0, 0.3, 0.5, 0.77, 31 / 32, 1.0):
        gl.glClearColor(v, v, v, 1 - v)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        want = np.minimum(np.floor(np.array([v, v, v, 1 - v])[:len(bits)] * (1 << bits)), (1 << bits) - 1)
        assert (split16(f.ctx.color_buffer(), color) == want).all(), f"Clear({v}) with dither off"


def dither_checks(on: np.ndarray, off: np.ndarray, exact: np.ndarray, slack: float, what: str,
                  blocks: bool = True) -> None:
    """§4.1.8 on shade indices: each dithered value is floor or ceil of the exact c = v (2^b - 1)
    (within `slack`) and within one step of the undithered value; with `blocks` (uniform 4x4
    blocks) each aligned block averages to c within 1/32 (+ slack), as an ordered 4x4
    threshold matrix gives."""
    lo, hi = np.floor(exact - slack), np.ceil(exact + slack)
    bad = (on < lo) | (on > hi)
    assert not bad.any(), f"{what}: dithered value not floor/ceil of the exact value at {np.argwhere(bad)[0]}"
    assert (np.abs(on - off) <= 1).all(), f"{what}: dither changes a value by more than one step"
    if not blocks:
        return
    h, w = on.shape[:2]
    blocks = on.reshape(h // 4, 4, w // 4, 4, -1).mean(axis=(1, 3))
    exact_b = exact.reshape(h // 4, 4, w // 4, 4, -1).mean(axis=(1, 3))
    err = np.abs(blocks - exact_b)
    assert err.max() <= 1 / 32 + slack, f"{what}: a 4x4 block mean is {err.max():.4f} steps off the exact one"


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("color", FORMATS16)
def test_dither_on_16bit(numeric, color):
    """Dither on (the initial state): uniform 4x4 blocks of random colours, and smooth ramps;
    every channel the format has, alpha too (§4.1.7 allows it on each)."""
    rng = np.random.default_rng(3)
    f = Frame(numeric, color=color)
    gl = f.gl
    bits = bits_of(color)
    nch = len(bits)
    slack = FLOOR_SLACK
    block = rng.integers(0, 256, (H // 4, W // 4, 4))
    cols = np.repeat(np.repeat(block, 4, axis=0), 4, axis=1)
    exact = cols[..., :nch] / 255.0 * ((1 << bits) - 1)
    f.paint(cols)
    off = split16(f.ctx.color_buffer(), color)
    gl.glEnable(C.GL_DITHER)
    f.paint(cols)
    on = split16(f.ctx.color_buffer(), color)
    dither_checks(on, off, exact, slack, f"{numeric} {color} flat blocks")
    assert (on != off).any(), "dither on changed nothing"
    # a smooth ramp: red 0 -> 1 along x, green along y (exact interpolation at pixel centres)
    gl.glShadeModel(C.GL_SMOOTH)
    v = np.array([[0, 0], [W, 0], [W, H], [0, H]], dtype=np.float32)
    col = np.array([[0, 0, 255, 0], [255, 0, 255, 255], [255, 255, 0, 255], [0, 255, 0, 0]], np.uint8)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, col)
    ys, xs = np.mgrid[0:H, 0:W] + 0.5
    u, t = xs / W, ys / H
    exact = np.stack([u, t, 1 - t, u], axis=-1)[..., :nch] * ((1 << bits) - 1)   # linear on both triangles
    gl.glDisable(C.GL_DITHER)
    gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, 4)
    off = split16(f.ctx.color_buffer(), color)
    gl.glEnable(C.GL_DITHER)
    gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, 4)
    on = split16(f.ctx.color_buffer(), color)
    dither_checks(on, off, exact, slack, f"{numeric} {color} ramp", blocks=False)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("color", FORMATS16)
def test_clear_dithers_on_16bit(numeric, color):
    """Clear is dithered (§4.2.3) like fragments; with dither off it is uniform."""
    f = Frame(numeric, color=color)
    gl = f.gl
    bits = bits_of(color)
    for rgba in ((0.3, 0.52, 0.9, 0.41), (0.05, 0.95, 0.5, 0.6), (1 / 3, 2 / 3, 0.1, 0.45)):
        exact = np.broadcast_to(np.array(rgba[:len(bits)]) * ((1 << bits) - 1), (H, W, len(bits)))
        gl.glDisable(C.GL_DITHER)
        gl.glClearColor(*rgba)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        off = split16(f.ctx.color_buffer(), color)
        assert (off == off[0, 0]).all()
        gl.glEnable(C.GL_DITHER)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        on = split16(f.ctx.color_buffer(), color)
        dither_checks(on, off, exact, FLOOR_SLACK, f"{numeric} {color} Clear{rgba}")
        if abs(exact[0, 0, 0] - round(exact[0, 0, 0])) > FLOOR_SLACK:
            assert len(np.unique(on[..., 0])) == 2, "a clear value between two shades is dithered"


@pytest.mark.parametrize("numeric", BUILDS)
def test_rgba8888_is_not_dithered(numeric):
    """On RGBA8888 dither on gives the rounded value, like dither off (drawing and Clear)."""
    f = Frame(numeric)
    gl = f.gl
    rng = np.random.default_rng(4)
    cols = rng.integers(0, 256, (H, W, 4))
    images = []
    for on in (False, True):
        (gl.glEnable if on else gl.glDisable)(C.GL_DITHER)
        f.paint(cols)
        images.append(f.rgba())
        gl.glClearColor(0.31, 0.62, 0.93, 0.13)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        images.append(f.rgba())
    np.testing.assert_array_equal(images[0], cols)
    np.testing.assert_array_equal(images[2], cols)
    np.testing.assert_array_equal(images[1], images[3])
    assert images[1][0, 0].tolist() == [79, 158, 237, 33]     # 0.31, 0.62, 0.93, 0.13 x 255 rounded


READ_PAIRS = {"rgb565": (C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5),
              "rgba4444": (C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4),
              "rgba5551": (C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1)}


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("color", FORMATS16)
def test_read_pixels_implementation_format(numeric, color):
    """OES_read_format: the buffer's own packed pair (RGB/5_6_5, RGBA/4_4_4_4, RGBA/5_5_5_1)
    returns the stored (dithered) values; RGBA/UNSIGNED_BYTE expands them; RGBA8888 names
    BGRA_EXT/UNSIGNED_BYTE."""
    f = Frame(numeric, color=color)
    gl = f.gl
    gl.glEnable(C.GL_DITHER)
    gl.glClearColor(0.3, 0.6, 0.2, 0.7)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    fmt, typ = READ_PAIRS[color]
    assert gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES) == fmt
    assert gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_TYPE_OES) == typ
    raw = gl.glReadPixels(0, 0, W, H, fmt, typ)
    np.testing.assert_array_equal(raw, f.ctx.color_buffer())
    rgba = gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE).astype(np.int64)
    k = split16(raw, color)
    top = (1 << bits_of(color)) - 1
    np.testing.assert_array_equal(rgba[..., :len(top)], (k * 255 + top // 2) // top)
    if len(top) == 3:
        assert (rgba[..., 3] == 255).all()
    # another format's pair is INVALID_OPERATION and writes nothing
    for other, (ofmt, otyp) in READ_PAIRS.items():
        if other != color:
            gl.glReadPixels(0, 0, 1, 1, ofmt, otyp)
            assert gl.glGetError() == C.GL_INVALID_OPERATION
    g = Frame(numeric)
    # EXT_read_format_bgra
    assert g.gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES) == C.GL_BGRA_EXT
    assert g.gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_TYPE_OES) == C.GL_UNSIGNED_BYTE


# {============================================================
# logic op (§4.1.9)

LOGIC_OPS: dict[str, Callable[[np.ndarray, np.ndarray], np.ndarray]] = {
    "CLEAR": lambda s, d: 0 * s, "AND": lambda s, d: s & d, "AND_REVERSE": lambda s, d: s & ~d,
    "COPY": lambda s, d: s, "AND_INVERTED": lambda s, d: ~s & d, "NOOP": lambda s, d: d,
    "XOR": lambda s, d: s ^ d, "OR": lambda s, d: s | d, "NOR": lambda s, d: ~(s | d),
    "EQUIV": lambda s, d: ~(s ^ d), "INVERT": lambda s, d: ~d, "OR_REVERSE": lambda s, d: s | ~d,
    "COPY_INVERTED": lambda s, d: ~s, "OR_INVERTED": lambda s, d: ~s | d, "NAND": lambda s, d: ~(s & d),
    "SET": lambda s, d: ~(0 * s),
}


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("color", ["rgba8888", *FORMATS16])
def test_logic_op_all_16(numeric, color):
    """Table 4.2 on the stored bits of both formats; enabled, it replaces blending."""
    rng = np.random.default_rng(8)
    f = Frame(numeric, color=color)
    probe = Frame(numeric, color=color)
    gl = f.gl
    full = 0xFF if color == "rgba8888" else 0xFFFF
    for k, (name, fn) in enumerate(LOGIC_OPS.items()):
        src = rng.integers(0, 256, (H, W, 4))
        dst = rng.integers(0, 256, (H, W, 4))
        probe.paint(src)                       # the source as stored without the logic op
        s_bits = probe.ctx.color_buffer().astype(np.int64)
        gl.glDisable(C.GL_COLOR_LOGIC_OP)
        gl.glDisable(C.GL_BLEND)
        f.paint(dst)
        d_bits = f.ctx.color_buffer().astype(np.int64)
        gl.glEnable(C.GL_COLOR_LOGIC_OP)
        if k % 2:
            gl.glEnable(C.GL_BLEND)            # ignored while the logic op is on
            gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
        gl.glLogicOp(getattr(C, "GL_" + name))
        assert gl.glGetIntegerv(C.GL_LOGIC_OP_MODE) == getattr(C, "GL_" + name)
        f.paint(src)
        want = fn(s_bits, d_bits) & full
        np.testing.assert_array_equal(f.ctx.color_buffer(), want, err_msg=f"{numeric} {color} LogicOp {name}")


# {============================================================
# masks (§4.2.2)

@pytest.mark.parametrize("numeric", BUILDS)
def test_color_mask_with_blending_and_logic_op(numeric):
    """All 16 colour masks over a blended and a logic-op'd draw keep masked channels."""
    rng = np.random.default_rng(9)
    f = Frame(numeric)
    gl = f.gl
    for bits in range(16):
        mask = [bool(bits >> i & 1) for i in range(4)]
        for logic in (False, True):
            src = rng.integers(0, 256, (H, W, 4))
            dst = rng.integers(0, 256, (H, W, 4))
            gl.glColorMask(True, True, True, True)
            gl.glDisable(C.GL_BLEND)
            gl.glDisable(C.GL_COLOR_LOGIC_OP)
            f.paint(dst)
            gl.glColorMask(*mask)
            if logic:
                gl.glEnable(C.GL_COLOR_LOGIC_OP)
                gl.glLogicOp(C.GL_XOR)
                out = src ^ dst
            else:
                gl.glEnable(C.GL_BLEND)
                gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
                out = np.minimum(src + dst, 255)
            f.paint(src)
            np.testing.assert_array_equal(f.rgba(), np.where(mask, out, dst),
                                          err_msg=f"mask {mask} logic={logic}")
            assert [bool(v) for v in gl.glGetBooleanv(C.GL_COLOR_WRITEMASK)] == mask


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("color", FORMATS16)
def test_color_mask_16bit(numeric, color):
    """On a 16-bit format each channel's mask protects its bits, in drawing and Clear,
    and blending and the logic op leave masked channels as stored."""
    rng = np.random.default_rng(10)
    f = Frame(numeric, color=color)
    gl = f.gl
    masks = channel_masks(color)
    nch = len(masks)
    for bits in range(1 << nch):
        mask = [bool(bits >> i & 1) for i in range(nch)] + [True] * (4 - nch)
        kept = sum(m for m, on in zip(masks, mask) if not on)
        gl.glColorMask(True, True, True, True)
        gl.glClearColor(0, 0, 0, 0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glColorMask(*mask)
        f.paint((255, 255, 255, 255))
        assert (f.ctx.color_buffer() == 0xFFFF & ~kept & sum(masks)).all()
        gl.glClearColor(0, 0, 0, 0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        assert (f.ctx.color_buffer() == 0).all()
        for logic in (False, True):
            gl.glColorMask(True, True, True, True)
            gl.glDisable(C.GL_BLEND)
            gl.glDisable(C.GL_COLOR_LOGIC_OP)
            f.paint(rng.integers(0, 256, (H, W, 4)))
            before = f.ctx.color_buffer().astype(np.int64)
            gl.glColorMask(*mask)
            if logic:
                gl.glEnable(C.GL_COLOR_LOGIC_OP)
                gl.glLogicOp(C.GL_INVERT)
            else:
                gl.glEnable(C.GL_BLEND)
                gl.glBlendFunc(C.GL_ONE_MINUS_DST_COLOR, C.GL_ZERO)
            f.paint((0, 0, 0, 0))
            after = f.ctx.color_buffer().astype(np.int64)
            np.testing.assert_array_equal(after & kept, before & kept)
            if logic:
                np.testing.assert_array_equal(after & ~kept & 0xFFFF, ~before & ~kept & sum(masks) & 0xFFFF)
        gl.glDisable(C.GL_BLEND)
        gl.glDisable(C.GL_COLOR_LOGIC_OP)


@pytest.mark.parametrize("depth_bits", [16, 24])
def test_depth_mask(depth_bits):
    """DepthMask(FALSE): a passing fragment and a depth Clear leave the depth buffer as it was."""
    f = Frame("fixed", 16, 16, depth=depth_bits)
    gl = f.gl
    dmax = (1 << depth_bits) - 1
    gl.glClearDepthf(1.0)
    gl.glClear(C.GL_DEPTH_BUFFER_BIT)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthMask(False)
    f.paint((255, 0, 0, 255), depth=0.25)
    assert (f.ctx.depth_buffer() == dmax).all() and (f.rgba()[..., 0] == 255).all()
    gl.glDepthMask(True)
    f.paint((0, 255, 0, 255), depth=0.5)
    before = f.ctx.depth_buffer()
    gl.glDepthMask(False)
    gl.glClearDepthf(0.0)
    gl.glClear(C.GL_DEPTH_BUFFER_BIT)
    np.testing.assert_array_equal(f.ctx.depth_buffer(), before)
    assert not gl.glGetBooleanv(C.GL_DEPTH_WRITEMASK)


# {============================================================
# scissor (§4.1.2) with drawing and Clear

@pytest.mark.parametrize("numeric", BUILDS)
def test_scissor_draw_and_clear(numeric):
    """Random boxes (negative origins, beyond the window, empty): drawing, colour, depth and
    stencil Clear touch exactly the pixels inside; the box reads back."""
    rng = np.random.default_rng(12)
    f = Frame(numeric)
    gl = f.gl
    ys, xs = np.mgrid[0:H, 0:W]
    for _ in range(24):
        x, y = (int(v) for v in rng.integers(-8, W + 4, 2))
        w, h = (int(v) for v in rng.integers(0, W + 8, 2))
        inside = (xs >= x) & (xs < x + w) & (ys >= y) & (ys < y + h)
        gl.glDisable(C.GL_SCISSOR_TEST)
        gl.glClearColor(0, 0, 0, 0)
        gl.glClearDepthf(1.0)
        gl.glClearStencil(0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
        gl.glEnable(C.GL_SCISSOR_TEST)
        gl.glScissor(x, y, w, h)
        assert gl.glGetIntegerv(C.GL_SCISSOR_BOX).tolist() == [x, y, w, h]
        f.paint((255, 255, 255, 255))
        np.testing.assert_array_equal(f.rgba()[..., 0] == 255, inside, err_msg=f"draw, box {x, y, w, h}")
        gl.glClearColor(0, 1, 0, 1)
        gl.glClearDepthf(0.5)
        gl.glClearStencil(9)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
        img = f.rgba()
        np.testing.assert_array_equal(img[..., 1] == 255, inside, err_msg=f"clear, box {x, y, w, h}")
        np.testing.assert_array_equal(img[..., 0] == 255, np.zeros_like(inside))
        np.testing.assert_array_equal(f.ctx.stencil_buffer() == 9, inside)
        np.testing.assert_array_equal(f.ctx.depth_buffer() != (1 << 24) - 1, inside)


# {============================================================
# multisample state with SAMPLE_BUFFERS 0 (§4.1.3, §4.1.10)

MS_CAPS = (C.GL_MULTISAMPLE, C.GL_SAMPLE_ALPHA_TO_COVERAGE, C.GL_SAMPLE_ALPHA_TO_ONE, C.GL_SAMPLE_COVERAGE)


def test_sample_buffers_zero_and_coverage_state():
    """SAMPLE_BUFFERS and SAMPLES are 0; SampleCoverage clamps its value and keeps invert."""
    f = Frame("fixed")
    gl = f.gl
    assert gl.glGetIntegerv(C.GL_SAMPLE_BUFFERS) == 0
    assert gl.glGetIntegerv(C.GL_SAMPLES) == 0
    assert gl.glGetFloatv(C.GL_SAMPLE_COVERAGE_VALUE) == 1.0
    assert not gl.glGetBooleanv(C.GL_SAMPLE_COVERAGE_INVERT)
    for value, invert, want in ((0.25, True, 0.25), (1.5, False, 1.0), (-2.0, True, 0.0)):
        gl.glSampleCoverage(value, invert)
        assert gl.glGetFloatv(C.GL_SAMPLE_COVERAGE_VALUE) == want
        assert bool(gl.glGetBooleanv(C.GL_SAMPLE_COVERAGE_INVERT)) is invert
    gl.glSampleCoveragex(3 << 14, False)
    assert gl.glGetFixedv(C.GL_SAMPLE_COVERAGE_VALUE) == 3 << 14
    assert gl.glGetError() == 0


def test_multisample_initially_enabled():
    """MULTISAMPLE starts enabled (Table 6.17); the three sample enables start disabled."""
    gl = Frame("fixed").gl
    assert gl.glIsEnabled(C.GL_MULTISAMPLE)
    for cap in MS_CAPS[1:]:
        assert not gl.glIsEnabled(cap)


@pytest.mark.parametrize("numeric", BUILDS)
def test_multisample_enables_change_nothing(numeric):
    """With SAMPLE_BUFFERS 0 the multisample enables are accepted and change no pixel (§4.1.3)."""
    rng = np.random.default_rng(2)
    cols = rng.integers(0, 256, (H, W, 4))
    images = []
    for on in (False, True):
        f = Frame(numeric)
        gl = f.gl
        for cap in MS_CAPS:
            (gl.glEnable if on else gl.glDisable)(cap)
            assert bool(gl.glIsEnabled(cap)) is on
        gl.glSampleCoverage(0.0, False)
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
        f.paint(cols)
        images.append(f.rgba())
        assert gl.glGetError() == 0
    np.testing.assert_array_equal(images[0], images[1])


# {============================================================
# errors leave the state unchanged (§2.5)

STATE_INT = (C.GL_ALPHA_TEST_FUNC, C.GL_STENCIL_FUNC, C.GL_STENCIL_REF, C.GL_STENCIL_VALUE_MASK,
             C.GL_STENCIL_FAIL, C.GL_STENCIL_PASS_DEPTH_FAIL, C.GL_STENCIL_PASS_DEPTH_PASS,
             C.GL_STENCIL_WRITEMASK, C.GL_BLEND_SRC, C.GL_BLEND_DST, C.GL_BLEND_SRC_RGB_OES,
             C.GL_BLEND_DST_RGB_OES, C.GL_BLEND_SRC_ALPHA_OES, C.GL_BLEND_DST_ALPHA_OES,
             C.GL_BLEND_EQUATION_RGB_OES, C.GL_BLEND_EQUATION_ALPHA_OES, C.GL_LOGIC_OP_MODE, C.GL_SCISSOR_BOX)
STATE_FLOAT = (C.GL_ALPHA_TEST_REF, C.GL_SAMPLE_COVERAGE_VALUE, C.GL_COLOR_CLEAR_VALUE)

GL_BLEND_EQUATION = 0x8009   # the state's name, no equation

ERROR_CASES = {
    "AlphaFunc(bad func)": (lambda gl: gl.glAlphaFunc(C.GL_ALWAYS + 1, 0.7), C.GL_INVALID_ENUM),
    "AlphaFuncx(bad func)": (lambda gl: gl.glAlphaFuncx(C.GL_NEVER - 1, 0), C.GL_INVALID_ENUM),
    "StencilFunc(bad func)": (lambda gl: gl.glStencilFunc(C.GL_ZERO, 3, 0xFF), C.GL_INVALID_ENUM),
    "StencilOp(bad zfail)": (lambda gl: gl.glStencilOp(C.GL_KEEP, C.GL_ALWAYS, C.GL_KEEP), C.GL_INVALID_ENUM),
    "StencilOp(bad zpass)": (lambda gl: gl.glStencilOp(C.GL_ZERO, C.GL_ZERO, C.GL_ONE), C.GL_INVALID_ENUM),
    "BlendFunc(SRC_COLOR as source)": (lambda gl: gl.glBlendFunc(C.GL_SRC_COLOR, C.GL_ZERO),
                                       C.GL_INVALID_ENUM),
    "BlendFunc(DST_COLOR as destination)": (lambda gl: gl.glBlendFunc(C.GL_ONE, C.GL_DST_COLOR),
                                            C.GL_INVALID_ENUM),
    "BlendFunc(SRC_ALPHA_SATURATE as destination)": (
        lambda gl: gl.glBlendFunc(C.GL_ONE, C.GL_SRC_ALPHA_SATURATE), C.GL_INVALID_ENUM),
    "BlendFuncSeparateOES(bad alpha)": (
        lambda gl: gl.glBlendFuncSeparateOES(C.GL_ONE, C.GL_ONE, C.GL_ONE, C.GL_DST_COLOR),
        C.GL_INVALID_ENUM),
    # (MIN_EXT and MAX_EXT are equations: EXT_blend_minmax; BLEND_EQUATION itself is not)
    "BlendEquationOES(BLEND_EQUATION)": (
        lambda gl: gl.glBlendEquationOES(GL_BLEND_EQUATION), C.GL_INVALID_ENUM),
    "BlendEquationSeparateOES(bad alpha)": (
        lambda gl: gl.glBlendEquationSeparateOES(C.GL_FUNC_ADD_OES, GL_BLEND_EQUATION), C.GL_INVALID_ENUM),
    "LogicOp(bad op)": (lambda gl: gl.glLogicOp(C.GL_SET + 1), C.GL_INVALID_ENUM),
    "Scissor(negative width)": (lambda gl: gl.glScissor(1, 2, -1, 4), C.GL_INVALID_VALUE),
    "Scissor(negative height)": (lambda gl: gl.glScissor(1, 2, 4, -4), C.GL_INVALID_VALUE),
}


def snapshot(gl: Any) -> list:
    return ([np.atleast_1d(gl.glGetIntegerv(p)).tolist() for p in STATE_INT]
            + [np.atleast_1d(gl.glGetFloatv(p)).tolist() for p in STATE_FLOAT])


@pytest.mark.parametrize("case", list(ERROR_CASES))
def test_errors_leave_state_unchanged(case):
    """Each bad call records its error and changes no fragment state (and Clear with a bad bit no pixel)."""
    call, err = ERROR_CASES[case]
    f = Frame("fixed", 8, 8)
    gl = f.gl
    gl.glAlphaFunc(C.GL_GEQUAL, 0.25)
    gl.glStencilFunc(C.GL_NOTEQUAL, 5, 0x3C)
    gl.glStencilOp(C.GL_INCR_WRAP_OES, C.GL_INVERT, C.GL_REPLACE)
    gl.glStencilMask(0x7E)
    gl.glBlendFuncSeparateOES(C.GL_SRC_ALPHA, C.GL_ONE, C.GL_DST_ALPHA, C.GL_ZERO)
    gl.glBlendEquationSeparateOES(C.GL_FUNC_SUBTRACT_OES, C.GL_FUNC_REVERSE_SUBTRACT_OES)
    gl.glLogicOp(C.GL_NAND)
    gl.glScissor(1, 2, 3, 4)
    gl.glSampleCoverage(0.5, True)
    gl.glClearColor(0.25, 0.5, 0.75, 1.0)
    assert gl.glGetError() == 0
    before = snapshot(gl)
    call(gl)
    assert gl.glGetError() == err
    assert snapshot(gl) == before


def test_clear_with_a_bad_bit():
    """Clear with a bit outside COLOR|DEPTH|STENCIL is INVALID_VALUE and clears nothing (§4.2.3)."""
    f = Frame("fixed", 8, 8)
    gl = f.gl
    gl.glClearColor(1, 1, 1, 1)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | 0x0200)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    assert (f.rgba() == 0).all()
