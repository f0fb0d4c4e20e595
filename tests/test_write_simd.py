"""The RGBA8888 writers, four fragments at a time, against a model and the other paths.

The chain's RGBA8888 writers (blend kind 0 none, 1 SRC_ALPHA /
ONE_MINUS_SRC_ALPHA, 2 ONE / ONE; with a logic op or colour mask) convert
four fragments at a time in the AVX2 instance, with one 128-bit load and
store where the four slots are consecutive and single words otherwise, a
group with a channel outside the kernel's range by the per-fragment code,
and the last n % 4 fragments of a chunk one by one.

* A model test: a REPLACE texture over a known framebuffer, every build,
  each kind; the expected words follow span_rgba8's arithmetic (num.h's
  frag_from_unorm, frag_mul, frag_to_unorm) in exact integers (fixed) or
  float32 / float64 operations in the same order. Alpha tests keep random
  fragments, so groups of four are consecutive or not; a row is a chunk
  and a last 3 columns.
* A random test: triangles (smooth, perspective: interpolated colours can
  overshoot [0, 1] by a rounding step), DrawTex rectangles and point sprites
  under random kinds, logic ops, masks, texture environments (COMBINE with
  scale 4, ADD, SUBTRACT), alpha or stencil tests dropping fragments, widths
  not a multiple of 4; the chain's two instances and the per-fragment
  reference must agree bit for bit.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, make_ctx, random_triangles, set_frustum, set_ortho
from test_frag_stages import TEX_W, H, W
from test_frag_stages import replace_quad as quad

from gles import constants as C

pytestmark = pytest.mark.filterwarnings("ignore::gles.RangeWarning")

KINDS = (None, (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), (C.GL_ONE, C.GL_ONE))
LOGIC_OPS = tuple(getattr(C, "GL_" + n) for n in (
    "CLEAR", "AND", "AND_REVERSE", "COPY", "AND_INVERTED", "NOOP", "XOR", "OR", "NOR", "EQUIV", "INVERT",
    "OR_REVERSE", "COPY_INVERTED", "OR_INVERTED", "NAND", "SET"))
# the per-fragment reference, the chain, and its baseline instance where a vector one exists
PATHS = (1, 0) + ((16,) if HAS_SIMD else ())

FRAG_ONE = 1 << 30


# {================================================================
# span_rgba8 in exact arithmetic


def unorm(numeric: str, t: np.ndarray) -> np.ndarray:
    """frag_from_unorm(t, 255)."""
    if numeric == "fixed":
        return ((t.astype(np.int64) << 31) // 255 + 1) >> 1
    ft = np.float32 if numeric == "float" else np.float64
    return t.astype(ft) / ft(255)


def model(numeric: str, src: np.ndarray, dst: np.ndarray, kind: int) -> np.ndarray:
    """span_rgba8 of fragments whose colour is the texel bytes src (h, w, 4) over the bytes dst."""
    c, u = unorm(numeric, src), unorm(numeric, dst)
    if numeric == "fixed":
        def clamp(v):
            return np.clip(v, 0, FRAG_ONE)

        def mul(a, b):
            return (a * b + (1 << 29)) >> 30

        one = np.int64(FRAG_ONE)
    else:
        ft = c.dtype.type

        def clamp(v):
            return np.where(v < 0, ft(0), np.where(v > 1, ft(1), v))

        def mul(a, b):
            return a * b

        one = ft(1)
    if kind == 0:
        v = c
    else:
        sa = clamp(c[..., 3:4]) if kind == 1 else one
        da = one - sa if kind == 1 else one
        v = mul(clamp(c), sa) + mul(u, da)
    if numeric == "fixed":
        b = np.where(v <= 0, 0, np.where(v >= FRAG_ONE, 255, (np.maximum(v, 0) * 255 + (1 << 29)) >> 30))
    else:
        b = np.where(~(v > 0), 0, np.where(v >= 1, 255, np.trunc(v * v.dtype.type(255) + v.dtype.type(0.5))))
    return b.astype(np.uint8)





@pytest.mark.parametrize("numeric", BUILDS)
def test_write_model(numeric: str) -> None:
    rng = np.random.default_rng(5)
    for kind in range(3):
        for keep_frac in (1.0, 0.8, 0.5, 0.2):
            dst = rng.integers(0, 256, size=(8, TEX_W, 4)).astype(np.uint8)
            src = rng.integers(0, 256, size=(8, TEX_W, 4)).astype(np.uint8)
            # edges: every byte value against extreme stored bytes and alphas
            src[0, :, :] = (np.arange(TEX_W)[:, None] * 2 + np.array([0, 1, 0, 1])) % 256
            src[1, :, 3] = rng.choice((0, 1, 254, 255), size=TEX_W)
            dst[2, :, :] = rng.choice((0, 255), size=(TEX_W, 4))
            # alpha test GREATER on an alpha of its own: the second draw keeps random fragments
            passes = rng.random((8, TEX_W)) < keep_frac
            shown = src.copy()
            shown[..., 3] = np.where(passes, np.maximum(src[..., 3], 1), 0)
            expect = np.where(passes[:, :W, None], model(numeric, shown[:, :W], dst[:, :W], kind), dst[:, :W])
            for flags in PATHS:
                ctx = make_ctx(numeric, W, H, depth=0, stencil=0)
                ctx.debug(flags)
                gl = ctx.gl
                set_ortho(gl, W, H)
                quad(gl, dst)
                assert (ctx.color_buffer() == dst[:, :W]).all()
                if keep_frac < 1:
                    gl.glEnable(C.GL_ALPHA_TEST)
                    gl.glAlphaFunc(C.GL_GREATER, 0.0)
                if kind:
                    gl.glEnable(C.GL_BLEND)
                    gl.glBlendFunc(*KINDS[kind])
                quad(gl, shown)
                got = ctx.color_buffer()
                assert (got == expect).all(), (numeric, flags, kind, keep_frac)


# {================================================================
# random states: the paths agree


def random_state(rng: np.random.Generator) -> dict:
    return {
        "prim": str(rng.choice(("tri", "tri", "drawtex", "sprite"))),
        "kind": int(rng.integers(3)),
        "op": int(rng.choice(LOGIC_OPS)) if rng.random() < 0.3 else None,
        "mask": tuple(int(x) for x in rng.integers(0, 2, 4)) if rng.random() < 0.25 else (1, 1, 1, 1),
        "drop": str(rng.choice(("none", "alpha", "stencil"))),
        "env": str(rng.choice(("none", "REPLACE", "MODULATE", "COMBINE"))),
        "combine": str(rng.choice(("MODULATE", "ADD", "SUBTRACT", "ADD_SIGNED", "INTERPOLATE"))),
        "scale": float(rng.choice((1.0, 2.0, 4.0))),
        "persp": bool(rng.random() < 0.7),
        "w": int(rng.choice((67, 13, 6, 130))), "h": int(rng.integers(3, 12)),
        "seed": int(rng.integers(2**31)),
    }


def texture(gl: Any, rng: np.random.Generator, s: dict) -> None:
    img = rng.integers(0, 256, size=(16, 16, 4)).astype(np.uint8)
    img[..., 3] = rng.choice((0, 1, 100, 127, 128, 200, 254, 255), size=(16, 16))
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 16, 16, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, [0, 0, 16, 16])
    gl.glEnable(C.GL_TEXTURE_2D)
    if s["env"] == "COMBINE":
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)
        for what in ("COMBINE_RGB", "COMBINE_ALPHA"):
            fn = s["combine"] if what == "COMBINE_RGB" or s["combine"] != "DOT3_RGB" else "ADD"
            gl.glTexEnvi(C.GL_TEXTURE_ENV, getattr(C, "GL_" + what), getattr(C, "GL_" + fn))
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_RGB, C.GL_TEXTURE)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC1_RGB, C.GL_PRIMARY_COLOR)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC2_RGB, C.GL_TEXTURE)
        gl.glTexEnvf(C.GL_TEXTURE_ENV, C.GL_RGB_SCALE, s["scale"])
        gl.glTexEnvf(C.GL_TEXTURE_ENV, C.GL_ALPHA_SCALE, s["scale"])
    else:
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, getattr(C, "GL_" + s["env"]))


def draw(gl: Any, rng: np.random.Generator, s: dict) -> None:
    w, h = s["w"], s["h"]
    if s["prim"] == "tri":
        (set_frustum if s["persp"] else set_ortho)(gl, w, h)
        verts, cols = random_triangles(rng, s["persp"], 5, w)
        # extreme vertex colours: perspective weights can carry them past [0, 1]
        cols[rng.random(cols.shape) < 0.5] = 255
        cols[rng.random(cols.shape) < 0.3] = 0
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, np.ascontiguousarray(verts, dtype=np.float32))
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(cols))
        tc = np.ascontiguousarray(rng.uniform(-1, 2, size=(len(verts), 2)), dtype=np.float32)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        gl.glDrawArrays(C.GL_TRIANGLES, 0, len(verts))
    elif s["prim"] == "drawtex":
        gl.glColor4f(*rng.uniform(0, 1, 4))
        x, y = rng.uniform(-3, w / 2), rng.uniform(-2, h / 2)
        gl.glDrawTexfOES(x, y, 0.0, rng.uniform(1, w + 4), rng.uniform(1, h + 2))
    else:
        set_ortho(gl, w, h)
        gl.glEnable(C.GL_POINT_SPRITE_OES)
        gl.glTexEnvi(C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES, 1)
        n = 6
        verts = np.column_stack([rng.uniform(0, w, n), rng.uniform(0, h, n), np.zeros(n)]).astype(np.float32)
        cols = rng.integers(0, 256, (n, 4), dtype=np.uint8)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
        gl.glPointSize(float(rng.uniform(3, 14)))
        gl.glDrawArrays(C.GL_POINTS, 0, n)


def render(numeric: str, flags: int, s: dict) -> tuple:
    w, h = s["w"], s["h"]
    ctx = make_ctx(numeric, w, h, depth=0, stencil=8)
    ctx.debug(flags)
    gl = ctx.gl
    rng = np.random.default_rng(s["seed"])
    set_ortho(gl, w, h)
    gl.glClearColor(*rng.uniform(0, 1, 4))
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    # a random framebuffer (the blends and logic ops read it), and for a
    # stencil test a random stencil pattern from it
    img = rng.integers(0, 256, size=(8, TEX_W, 4)).astype(np.uint8)
    img[..., 3] = rng.choice((0, 255), size=(8, TEX_W))
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(C.GL_ALWAYS, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_REPLACE)
    gl.glEnable(C.GL_ALPHA_TEST)
    gl.glAlphaFunc(C.GL_GREATER, 0.5)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glScalef(w / W, h / H, 1)
    quad(gl, img)
    gl.glLoadIdentity()
    gl.glDisable(C.GL_ALPHA_TEST)
    gl.glDisable(C.GL_STENCIL_TEST)
    gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glDisable(C.GL_TEXTURE_2D)
    if s["env"] != "none":
        texture(gl, rng, s)
    if s["drop"] == "alpha":
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glAlphaFunc(C.GL_GREATER, float(rng.uniform(0, 0.7)))
    elif s["drop"] == "stencil":
        gl.glEnable(C.GL_STENCIL_TEST)
        gl.glStencilFunc(C.GL_EQUAL, 1, 0xFF)
        gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
    if s["kind"]:
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(*KINDS[s["kind"]])
    if s["op"] is not None:
        gl.glEnable(C.GL_COLOR_LOGIC_OP)
        gl.glLogicOp(s["op"])
    gl.glColorMask(*s["mask"])
    draw(gl, rng, s)
    return gl.glGetError(), ctx.color_buffer(), ctx.stencil_buffer()


@pytest.mark.parametrize("numeric", BUILDS)
def test_write_random_states(numeric: str) -> None:
    rng = np.random.default_rng({"fixed": 11, "float": 12, "double": 13}[numeric])
    for _ in range(200):
        s = random_state(rng)
        err, ref, st = render(numeric, 1, s)
        assert err == C.GL_NO_ERROR, s
        for flags in PATHS[1:]:
            e, got, gst = render(numeric, flags, s)
            assert e == err
            assert (gst == st).all(), (numeric, flags, s)
            assert (got == ref).all(), (numeric, flags, s)
