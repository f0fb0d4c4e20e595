"""The span chain's fog, alpha test and RGBA8888 writers against the spec and the reference.

The chain (csrc/span_stages.h) computes the per-vertex fog factor of four
fragments at a time, tests four alphas at a time against the reference with
the function fixed per chunk and compacts the survivors, and writes RGBA8888
under logic ops and colour masks with writers fixed per state.
``ctx.debug(1)`` forces the per-fragment reference (``fragment_process``),
``ctx.debug(16)`` the baseline instance of the chain.

* Model tests, where the expected pixels follow from the spec in numpy: the
  alpha test (every function, references 0, 1 and between, and every stored
  alpha 0..255, so each reference meets alphas at, below and above it) on
  texels that REPLACE the colour; and every logic op with and without colour
  masks (and the masks without a logic op) over a known framebuffer.
* A random test: random triangles under random fog (every mode, per vertex
  and per fragment, start = end), alpha tests, blends, logic ops and masks,
  drawn twice; both chain instances and the reference must agree bit for bit.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, SPAN_CHUNK, colour_window, make_ctx, random_triangles, set_ortho

from gles import constants as C

pytestmark = pytest.mark.filterwarnings("ignore::gles.RangeWarning")

FUNCS = (C.GL_NEVER, C.GL_LESS, C.GL_EQUAL, C.GL_LEQUAL, C.GL_GREATER, C.GL_NOTEQUAL, C.GL_GEQUAL,
         C.GL_ALWAYS)
LOGIC_OPS = tuple(getattr(C, "GL_" + n) for n in (
    "CLEAR", "AND", "AND_REVERSE", "COPY", "AND_INVERTED", "NOOP", "XOR", "OR", "NOR", "EQUIV", "INVERT",
    "OR_REVERSE", "COPY_INVERTED", "OR_INVERTED", "NAND", "SET"))
FOG_MODES = (C.GL_LINEAR, C.GL_EXP, C.GL_EXP2)
BLENDS = ((C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), (C.GL_ONE, C.GL_ONE), (C.GL_DST_COLOR, C.GL_ZERO),
          (C.GL_ONE, C.GL_ONE_MINUS_SRC_ALPHA))

# the paths: debug flags; the baseline instance only where a vector one exists
PATHS = (1, 0) + ((16,) if HAS_SIMD else ())

# a row is a chunk and a last 3 columns, so groups of four end early
W, H = SPAN_CHUNK + 3, 8
# the textures' width: the power of two past the window's
TEX_W = 1 << (W - 1).bit_length()
CLEAR = (10, 200, 90, 140)


def logic(op: int, s: np.ndarray, d: np.ndarray) -> np.ndarray:
    """§4.1.10 on uint32 words."""
    s, d = s.astype(np.uint32), d.astype(np.uint32)
    return {
        C.GL_CLEAR: s & 0, C.GL_AND: s & d, C.GL_AND_REVERSE: s & ~d, C.GL_COPY: s,
        C.GL_AND_INVERTED: ~s & d, C.GL_NOOP: d, C.GL_XOR: s ^ d, C.GL_OR: s | d, C.GL_NOR: ~(s | d),
        C.GL_EQUIV: ~(s ^ d), C.GL_INVERT: ~d, C.GL_OR_REVERSE: s | ~d, C.GL_COPY_INVERTED: ~s,
        C.GL_OR_INVERTED: ~s | d, C.GL_NAND: ~(s & d), C.GL_SET: (s & 0) | 0xFFFFFFFF,
    }[op]


def compare(func: int, a: np.ndarray, b: int) -> np.ndarray:
    return {
        C.GL_NEVER: a < 0, C.GL_LESS: a < b, C.GL_EQUAL: a == b, C.GL_LEQUAL: a <= b,
        C.GL_GREATER: a > b, C.GL_NOTEQUAL: a != b, C.GL_GEQUAL: a >= b, C.GL_ALWAYS: a >= 0,
    }[func]


def words(img: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(img).view("<u4")[..., 0]


def texels(seed: int, alpha: np.ndarray | None = None) -> np.ndarray:
    """A TEX_W x 8 RGBA texture of random bytes (alpha[y, x] when given)."""
    img = np.random.default_rng(seed).integers(0, 256, size=(8, TEX_W, 4)).astype(np.uint8)
    if alpha is not None:
        img[..., 3] = alpha
    return img


def replace_quad(gl: Any, img: np.ndarray) -> None:
    """The window covered by texels img[y, x] at pixel (x, y), NEAREST, REPLACE."""
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, TEX_W, 8, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                    np.ascontiguousarray(img))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glEnable(C.GL_TEXTURE_2D)
    v = np.array([[0, 0], [W, 0], [0, H], [W, H]], dtype=np.float32)
    t = np.array([[0, 0], [W / TEX_W, 0], [0, 1], [W / TEX_W, 1]], dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, t)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


def new_ctx(numeric: str, flags: int) -> Any:
    ctx = make_ctx(numeric, W, H, depth=0, stencil=0)
    ctx.debug(flags)
    gl = ctx.gl
    set_ortho(gl, W, H)
    gl.glClearColor(*[c / 255 for c in CLEAR])
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    return ctx


# {================================================================
# the alpha test on known alphas

# every alpha 0..255 in the window, and more
ALPHAS = ((np.arange(TEX_W)[None, :] * 5 + np.arange(8)[:, None] * 67) % 256).astype(np.uint8)
REFS = (0.0, 1.0, 0.5, 1 / 255, 254 / 255, 128 / 255, 0.3, 0.9981)


@pytest.mark.parametrize("numeric", BUILDS)
def test_alpha_model(numeric: str) -> None:
    img = texels(7, ALPHAS)
    expect_src = img[:, :W]
    for func in FUNCS:
        for ref in REFS:
            ref8 = int(np.floor(float(np.float32(ref)) * 255.0 + 0.5))
            passes = compare(func, ALPHAS[:, :W].astype(np.int64), ref8)
            expect = np.where(passes[..., None], expect_src, np.array(CLEAR, np.uint8))
            for flags in PATHS:
                ctx = new_ctx(numeric, flags)
                gl = ctx.gl
                gl.glEnable(C.GL_ALPHA_TEST)
                gl.glAlphaFunc(func, ref)
                replace_quad(gl, img)
                got = ctx.color_buffer()
                assert (got == expect).all(), (numeric, flags, func, ref)


# {================================================================
# logic ops and colour masks on a known framebuffer

MASKS = ((1, 1, 1, 1), (1, 0, 1, 0), (0, 1, 1, 1), (1, 1, 1, 0), (0, 0, 0, 1))


@pytest.mark.parametrize("numeric", BUILDS)
def test_logic_model(numeric: str) -> None:
    dst, src = texels(11), texels(12)
    d, s = words(dst[:, :W]), words(src[:, :W])
    for op in (None, *LOGIC_OPS):
        for mask in MASKS:
            keep = sum(0xFF << (8 * i) for i in range(4) if not mask[i])
            out = logic(op if op is not None else C.GL_COPY, s, d)
            expect = (d & keep) | (out & ~np.uint32(keep))
            for flags in PATHS:
                ctx = new_ctx(numeric, flags)
                gl = ctx.gl
                replace_quad(gl, dst)
                assert (words(ctx.color_buffer()) == d).all()
                if op is not None:
                    gl.glEnable(C.GL_COLOR_LOGIC_OP)
                    gl.glLogicOp(op)
                    # blending is ignored under a logic op
                    gl.glEnable(C.GL_BLEND)
                    gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
                gl.glColorMask(*mask)
                replace_quad(gl, src)
                got = words(ctx.color_buffer())
                assert (got == expect).all(), (numeric, flags, op, mask)


# {================================================================
# random states against the reference


def random_state(rng: np.random.Generator) -> dict:
    fog = None
    if rng.random() < 0.75:
        start = float(rng.uniform(-1.0, 3.0))
        end = start if rng.random() < 0.1 else float(rng.uniform(-1.0, 4.0))
        fog = {"mode": int(rng.choice(FOG_MODES)), "start": start, "end": end,
               "density": float(rng.choice((0.0, rng.uniform(0, 2.5)))),
               "color": [float(x) for x in rng.uniform(-0.2, 1.2, 4)],
               "nicest": bool(rng.random() < 0.35)}
    alpha = None
    if rng.random() < 0.6:
        ref = float(rng.choice((0.0, 1.0, rng.integers(0, 256) / 255, rng.uniform(0, 1))))
        alpha = (int(rng.choice(FUNCS)), ref)
    blend = BLENDS[rng.integers(len(BLENDS))] if rng.random() < 0.5 else None
    op = int(rng.choice(LOGIC_OPS)) if rng.random() < 0.4 else None
    mask = tuple(int(x) for x in rng.integers(0, 2, 4)) if rng.random() < 0.4 else (1, 1, 1, 1)
    return {"persp": bool(rng.random() < 0.7), "smooth": bool(rng.random() < 0.8), "fog": fog, "alpha": alpha,
            "blend": blend, "op": op, "mask": mask, "tex": bool(rng.random() < 0.5),
            "w": int(rng.choice((W, 29))), "h": int(rng.integers(6, 14)), "seed": int(rng.integers(2**31))}


def render(numeric: str, flags: int, s: dict) -> tuple:
    w, h = s["w"], s["h"]
    ctx, gl, rng = colour_window(numeric, flags, w, h, s["persp"], s["seed"])
    gl.glShadeModel(C.GL_SMOOTH if s["smooth"] else C.GL_FLAT)
    verts, cols = random_triangles(rng, s["persp"], 6, w)
    verts = np.ascontiguousarray(verts, dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(cols))
    if s["tex"]:
        img = rng.integers(0, 256, size=(8, 8, 4)).astype(np.uint8)
        img[..., 3] = rng.choice((0, 1, 127, 128, 254, 255), size=(8, 8))
        gl.glBindTexture(C.GL_TEXTURE_2D, 1)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 8, 8, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR)
        mag = int(rng.choice((C.GL_NEAREST, C.GL_LINEAR)))
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, mag)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, int(rng.choice((C.GL_MODULATE, C.GL_REPLACE))))
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        tc = np.ascontiguousarray(rng.uniform(-1, 2, size=(len(verts), 2)), dtype=np.float32)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    if s["fog"]:
        f = s["fog"]
        gl.glEnable(C.GL_FOG)
        gl.glFogf(C.GL_FOG_MODE, f["mode"])
        gl.glFogf(C.GL_FOG_START, f["start"])
        gl.glFogf(C.GL_FOG_END, f["end"])
        gl.glFogf(C.GL_FOG_DENSITY, f["density"])
        gl.glFogfv(C.GL_FOG_COLOR, f["color"])
        gl.glHint(C.GL_FOG_HINT, C.GL_NICEST if f["nicest"] else C.GL_DONT_CARE)
    if s["alpha"]:
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glAlphaFunc(*s["alpha"])
    if s["blend"]:
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(*s["blend"])
    if s["op"] is not None:
        gl.glEnable(C.GL_COLOR_LOGIC_OP)
        gl.glLogicOp(s["op"])
    gl.glColorMask(*s["mask"])
    # twice: the second pass meets what the first wrote
    for _ in range(2):
        gl.glDrawArrays(C.GL_TRIANGLES, 0, len(verts))
    return gl.glGetError(), ctx.color_buffer()


@pytest.mark.parametrize("numeric", BUILDS)
def test_random_states(numeric: str) -> None:
    rng = np.random.default_rng({"fixed": 1, "float": 2, "double": 3}[numeric])
    for _ in range(150):
        s = random_state(rng)
        err, ref = render(numeric, 1, s)
        assert err == C.GL_NO_ERROR
        for flags in PATHS[1:]:
            e, got = render(numeric, flags, s)
            assert e == err
            assert (got == ref).all(), (numeric, flags, s)
