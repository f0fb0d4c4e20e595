"""GL_COMBINE in the span chain's AVX2 instance against the baseline and the reference.

The AVX2 instance of the chain computes COMBINE with a fragment's four
channels in one register (csrc/texenv.c, ``combine_run_avx2``); the baseline
instance (``ctx.debug(16)``) runs the scalar ``combine_block`` over the run,
and ``ctx.debug(1)`` the per-fragment reference. Random COMBINE states on one
or two units (every function incl. DOT3_RGB/DOT3_RGBA, every source incl.
the TEXTUREn crossbar, every operand, RGB_SCALE/ALPHA_SCALE 1, 2, 4, a random
environment colour) over random textures and vertex colours whose bytes are
often 0, 1, 127, 128, 254 or 255 (so DOT3's a - 1/2 and the complements meet
zero and both signs) must give the same pixels on all three paths, in every
build. The benchmark's state (DOT3_RGB of a normal map with the primary
colour, MODULATE alpha, then MODULATE by a second texture) is one named case.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import (
    BUILDS,
    HAS_SIMD,
    SPAN_CHUNK,
    colour_window,
    draw_arrays,
    has_avx512,
    make_ctx,
    random_triangles,
    set_frustum,
    set_ortho,
)

from gles import constants as C

pytestmark = pytest.mark.filterwarnings("ignore::gles.RangeWarning")

COMBINE_RGB = (C.GL_REPLACE, C.GL_MODULATE, C.GL_ADD, C.GL_ADD_SIGNED, C.GL_INTERPOLATE, C.GL_SUBTRACT,
               C.GL_DOT3_RGB, C.GL_DOT3_RGBA)
COMBINE_ALPHA = COMBINE_RGB[:6]
RGB_OPERANDS = (C.GL_SRC_COLOR, C.GL_ONE_MINUS_SRC_COLOR, C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
ALPHA_OPERANDS = (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
SCALES = (1.0, 2.0, 4.0)
EDGE_BYTES = np.array([0, 1, 2, 63, 64, 127, 128, 129, 191, 192, 253, 254, 255], dtype=np.uint8)
# (internal format, channels) of the textures
FORMATS = ((C.GL_RGBA, 4), (C.GL_RGBA, 4), (C.GL_RGB, 3), (C.GL_LUMINANCE_ALPHA, 2), (C.GL_ALPHA, 1))

# the paths: the chain's default instance first, then the baseline (where a
# vector one exists) and the per-fragment reference
PATHS = (0, 1) + ((16,) if HAS_SIMD else ())

HAS_AVX512 = has_avx512("double")

# a row is a chunk and a last 3 columns
W, H = SPAN_CHUNK + 3, 8


def edge_bytes(rng: np.random.Generator, shape: tuple) -> np.ndarray:
    """Random bytes, about half of them from EDGE_BYTES."""
    out = rng.integers(0, 256, size=shape).astype(np.uint8)
    pick = rng.random(shape) < 0.5
    out[pick] = rng.choice(EDGE_BYTES, size=int(pick.sum()))
    return out


def random_combine(rng: np.random.Generator, units: int) -> dict:
    """One unit's COMBINE state; sources name units 0..units-1, or (rarely) one that is off."""
    top = units + (1 if rng.random() < 0.1 else 0)
    sources = (C.GL_TEXTURE, C.GL_CONSTANT, C.GL_PRIMARY_COLOR, C.GL_PREVIOUS) + tuple(
        C.GL_TEXTURE0 + u for u in range(top))
    env = [float(x) for x in rng.choice((0.0, 0.5, 1.0, 127 / 255, 128 / 255, rng.uniform(0, 1)), 4)]
    return {
        "rgb": int(rng.choice(COMBINE_RGB)), "alpha": int(rng.choice(COMBINE_ALPHA)),
        "src_rgb": [int(rng.choice(sources)) for _ in range(3)],
        "src_alpha": [int(rng.choice(sources)) for _ in range(3)],
        "op_rgb": [int(rng.choice(RGB_OPERANDS)) for _ in range(3)],
        "op_alpha": [int(rng.choice(ALPHA_OPERANDS)) for _ in range(3)],
        "rgb_scale": float(rng.choice(SCALES)), "alpha_scale": float(rng.choice(SCALES)),
        "color": env,
    }


def random_state(rng: np.random.Generator) -> dict:
    units = int(rng.integers(1, 3))
    envs = []
    for u in range(units):
        if u > 0 and rng.random() < 0.3:
            envs.append({"mode": C.GL_MODULATE})
        else:
            envs.append({"mode": C.GL_COMBINE, **random_combine(rng, units)})
    fmts = [FORMATS[int(rng.integers(len(FORMATS)))] for _ in range(units)]
    return {"units": units, "envs": envs, "formats": fmts, "persp": bool(rng.random() < 0.5),
            "linear": [bool(rng.random() < 0.5) for _ in range(units)], "seed": int(rng.integers(2**31))}


def set_env(gl: Any, env: dict) -> None:
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, env["mode"])
    if env["mode"] != C.GL_COMBINE:
        return
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, env["rgb"])
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_ALPHA, env["alpha"])
    for n in range(3):
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_RGB + n, env["src_rgb"][n])
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_ALPHA + n, env["src_alpha"][n])
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND0_RGB + n, env["op_rgb"][n])
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND0_ALPHA + n, env["op_alpha"][n])
    gl.glTexEnvf(C.GL_TEXTURE_ENV, C.GL_RGB_SCALE, env["rgb_scale"])
    gl.glTexEnvf(C.GL_TEXTURE_ENV, C.GL_ALPHA_SCALE, env["alpha_scale"])
    gl.glTexEnvfv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, env["color"])


def render(numeric: str, flags: int, s: dict) -> tuple:
    w, h = s.get("size", (W, H))
    if s.get("rgb565"):
        ctx = make_ctx(numeric, w, h, color="rgb565", depth=0, stencil=0)
        ctx.debug(flags)
        gl, rng = ctx.gl, np.random.default_rng(s["seed"])
        (set_frustum if s["persp"] else set_ortho)(gl, w, h)
        gl.glClearColor(*rng.uniform(0, 1, 4))
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        if not s.get("dither", True):
            gl.glDisable(C.GL_DITHER)
    elif s.get("holes"):
        ctx = make_ctx(numeric, w, h, depth=0, stencil=8)
        ctx.debug(flags)
        gl, rng = ctx.gl, np.random.default_rng(s["seed"])
        gl.glClearColor(*rng.uniform(0, 1, 4))
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
        # stencil 1 under thin slivers, then draw where it is 0: the
        # chunks' live slots are not all neighbours
        set_ortho(gl, w, h)
        gl.glEnable(C.GL_STENCIL_TEST)
        gl.glStencilFunc(C.GL_ALWAYS, 1, 0xFF)
        gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_REPLACE)
        gl.glColorMask(False, False, False, False)
        x = rng.uniform(0, w, 40)
        zero, top = np.zeros(40), np.full(40, h)
        slivers = np.stack([np.stack([x, zero, zero], -1), np.stack([x + 0.7, zero, zero], -1),
                            np.stack([x, top, zero], -1)], 1).reshape(-1, 3)
        draw_arrays(gl, np.ascontiguousarray(slivers, dtype=np.float32))
        gl.glColorMask(True, True, True, True)
        gl.glStencilFunc(C.GL_EQUAL, 0, 0xFF)
        gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
        (set_frustum if s["persp"] else set_ortho)(gl, w, h)
    else:
        ctx, gl, rng = colour_window(numeric, flags, w, h, s["persp"], s["seed"])
    if s.get("blend"):
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(*s["blend"])
    if s.get("alpha_test"):
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glAlphaFunc(*s["alpha_test"])
    gl.glShadeModel(s.get("shade", C.GL_SMOOTH))
    verts, _ = random_triangles(rng, s["persp"], 5, w)
    # a covering quad first (two triangles): whole chunks of live fragments
    if s["persp"]:
        quad = np.array([[-2, -2, -1], [2, -2, -1], [-2, 2, -1], [2, -2, -1], [2, 2, -1], [-2, 2, -1]], float)
    else:
        quad = np.array([[0, 0, 0], [w, 0, 0], [0, h, 0], [w, 0, 0], [w, h, 0], [0, h, 0]], float)
    verts = np.ascontiguousarray(np.concatenate([quad, verts]), dtype=np.float32)
    cols = np.ascontiguousarray(edge_bytes(rng, (len(verts), 4)))
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
    for u in range(s["units"]):
        fmt, nch = s["formats"][u]
        size = (8, 16)
        img = np.ascontiguousarray(edge_bytes(rng, size + (nch,)))
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        gl.glClientActiveTexture(C.GL_TEXTURE0 + u)
        gl.glBindTexture(C.GL_TEXTURE_2D, u + 1)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, size[1], size[0], 0, fmt, C.GL_UNSIGNED_BYTE, img)
        filt = C.GL_LINEAR if s["linear"][u] else C.GL_NEAREST
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, filt)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, filt)
        if s.get("clamp"):
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, C.GL_CLAMP_TO_EDGE)
        gl.glEnable(C.GL_TEXTURE_2D)
        set_env(gl, s["envs"][u])
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        tc = np.ascontiguousarray(rng.uniform(-1, 2, size=(len(verts), 2)), dtype=np.float32)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    if s.get("non_finite"):
        # one vertex's coordinates scaled to infinity by the texture matrix
        gl.glMatrixMode(C.GL_TEXTURE)
        for _ in range(10):
            gl.glScalef(1e38, 1e38, 1.0)
        gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(verts))
    return gl.glGetError(), ctx.color_buffer()


def paths(numeric: str) -> tuple:
    """PATHS, and for the double build where the CPU runs its AVX-512
    instance also that instance capped at AVX2 (debug 32)."""
    return PATHS + ((32,) if numeric == "double" and HAS_AVX512 else ())


def check(numeric: str, s: dict) -> None:
    err, ref = render(numeric, PATHS[0], s)
    assert err == C.GL_NO_ERROR
    for flags in paths(numeric)[1:]:
        e, got = render(numeric, flags, s)
        assert e == err
        assert (got == ref).all(), (numeric, flags, s)


@pytest.mark.parametrize("numeric", BUILDS)
def test_random_combine(numeric: str) -> None:
    rng = np.random.default_rng({"fixed": 11, "float": 12, "double": 13}[numeric])
    for _ in range(200):
        check(numeric, random_state(rng))


def dot3_env(fn: int, alpha: int, scale: float) -> dict:
    return {"mode": C.GL_COMBINE, "rgb": fn, "alpha": alpha,
            "src_rgb": [C.GL_TEXTURE, C.GL_PRIMARY_COLOR, C.GL_CONSTANT],
            "src_alpha": [C.GL_TEXTURE, C.GL_PREVIOUS, C.GL_CONSTANT],
            "op_rgb": [C.GL_SRC_COLOR, C.GL_SRC_COLOR, C.GL_SRC_ALPHA],
            "op_alpha": [C.GL_SRC_ALPHA, C.GL_SRC_ALPHA, C.GL_SRC_ALPHA],
            "rgb_scale": scale, "alpha_scale": scale, "color": [0.5, 0.5, 0.5, 0.5]}


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("fn", [C.GL_DOT3_RGB, C.GL_DOT3_RGBA])
@pytest.mark.parametrize("scale", SCALES)
def test_dot3_then_modulate(numeric: str, fn: int, scale: float) -> None:
    """The benchmark's state: DOT3 of texture and primary colour (MODULATE alpha), then MODULATE."""
    for seed in range(4):
        s = {"units": 2, "envs": [dot3_env(fn, C.GL_MODULATE, scale), {"mode": C.GL_MODULATE}],
             "formats": [(C.GL_RGBA, 4), (C.GL_RGBA, 4)], "persp": bool(seed & 1),
             "linear": [True, bool(seed & 2)], "seed": 100 + seed}
        check(numeric, s)


@pytest.mark.parametrize("numeric", BUILDS)
def test_dot3_then_modulate_on_every_target(numeric: str) -> None:
    """The pair the fixed build fuses (stage_dot3_write): DOT3_RGB (MODULATE
    alpha) or DOT3_RGBA at scale 1 with the sources in either order, then
    MODULATE of an RGBA or RGB texture, on RGBA8888 (no blend, SRC_ALPHA,
    ONE/ONE; an alpha test) and RGB565 (dithered or not, no blend or
    SRC_ALPHA), smooth and flat, bilinear or nearest on each unit."""
    rng = np.random.default_rng(21)
    blends = (None, (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), (C.GL_ONE, C.GL_ONE))
    for case in range(24):
        env = dot3_env(C.GL_DOT3_RGBA if case % 3 == 2 else C.GL_DOT3_RGB, C.GL_MODULATE, 1.0)
        if case % 2:
            env["src_rgb"][:2] = env["src_rgb"][1::-1]
            env["src_alpha"][:2] = [C.GL_PRIMARY_COLOR, C.GL_TEXTURE]
        rgb565 = case % 4 == 3
        second = (C.GL_RGB, 3) if case % 5 == 1 else (C.GL_RGBA, 4)
        s = {"units": 2, "envs": [env, {"mode": C.GL_MODULATE}],
             "formats": [FORMATS[int(rng.integers(len(FORMATS)))], second],
             "persp": case % 4 == 1, "linear": [bool(rng.random() < 0.7), bool(rng.random() < 0.7)],
             "seed": 300 + case, "rgb565": rgb565, "dither": case % 8 != 3,
             "blend": blends[case % (2 if rgb565 else 3)],
             "alpha_test": (C.GL_GREATER, 0.4) if case % 6 == 5 else None,
             "shade": C.GL_FLAT if case % 7 == 6 else C.GL_SMOOTH}
        check(numeric, s)


@pytest.mark.parametrize("numeric", BUILDS)
def test_large_affine_triangles(numeric: str) -> None:
    """A window-covering quad of two triangles of about 24000 pixels each
    (the fixed build's edge values then take a shift, which its stepped
    affine weights divide out), under DOT3 then MODULATE (the two units'
    coordinates formed with the weights) and under one MODULATE unit."""
    for seed in range(2):
        pair = {"units": 2, "envs": [dot3_env(C.GL_DOT3_RGB, C.GL_MODULATE, 1.0), {"mode": C.GL_MODULATE}],
                "formats": [(C.GL_RGBA, 4), (C.GL_RGBA, 4)], "persp": False, "linear": [True, True],
                "seed": 500 + seed, "size": (256, 192)}
        check(numeric, pair)
        one = {"units": 1, "envs": [{"mode": C.GL_MODULATE}], "formats": [(C.GL_RGBA, 4)], "persp": False,
               "linear": [bool(seed)], "seed": 510 + seed, "size": (256, 192)}
        check(numeric, one)


@pytest.mark.parametrize("numeric", BUILDS)
def test_dot3_pair_cases(numeric: str) -> None:
    """The DOT3 pair (both units bilinear) under each blend kind, DOT3_RGB
    or DOT3_RGBA, an RGB or RGBA second texture, smooth or flat; chunks
    with tails (width a chunk and 3), live slots that are not neighbours (a
    stencil test drops slivers), an alpha test, REPEAT or CLAMP_TO_EDGE, and
    coordinates that are not finite (the texture matrix scaled to
    infinity, which the samplers leave to the scalar code). Every path,
    the double build's AVX2-capped one included, gives the same pixels."""
    blends = (None, (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), (C.GL_ONE, C.GL_ONE))
    for case in range(18):
        env = dot3_env(C.GL_DOT3_RGBA if case % 2 else C.GL_DOT3_RGB, C.GL_MODULATE, 1.0)
        s = {"units": 2, "envs": [env, {"mode": C.GL_MODULATE}],
             "formats": [(C.GL_RGBA, 4), (C.GL_RGB, 3) if case % 3 == 1 else (C.GL_RGBA, 4)],
             "persp": case % 4 == 2, "linear": [True, True], "seed": 700 + case,
             "blend": blends[case % 3], "shade": C.GL_FLAT if case % 5 == 4 else C.GL_SMOOTH,
             "holes": case % 2 == 0, "alpha_test": (C.GL_GREATER, 0.3) if case % 9 == 8 else None,
             "non_finite": case % 6 == 5, "clamp": case % 4 == 1}
        check(numeric, s)
