"""Every fragment state: the span functions the core picks against span_generic.

``span_generic`` (csrc/span.c) runs each fragment through texturing on every
enabled unit, the texture environments, fog, the alpha, stencil and depth
tests, blending, dither, the logic op and the colour mask, on RGBA8888 or
RGB565; ``ctx.debug(1)`` forces every triangle through it. Without the flag
the core picks faster span functions for the current state, and whatever it
picks must leave the colour, depth and stencil buffers bit-identical to the
generic path's, for any state. test_spans.py, test_span_blend.py and
test_span_texture.py check that for the state families of the fused spans;
this file draws random states from the whole fragment state space:

* the context: numeric build, colour format, depth bits 0/16/24, stencil
  bits 0/8, a window of 24..40 x 24..32 or (one in three) 4..12 rows wider
  than a chunk of the span chain (up to WIDE: over two chunks); random clear
  colour, depth, stencil;
* shade model, perspective or ortho projection, dither, scissor (random box),
  colour mask, depth test (func, mask, DepthRange), stencil test (func, ref,
  value mask, write mask, the three ops incl. INCR_WRAP/DECR_WRAP_OES), alpha
  test, blending (BlendFunc, BlendFuncSeparateOES, BlendEquationOES and
  BlendEquationSeparateOES; every legal factor incl. SRC_ALPHA_SATURATE),
  logic op (all 16), fog (mode, start, end, density, colour, FOG_HINT:
  NICEST evaluates the factor per fragment), polygon offset fill;
* texturing on each of the GL_MAX_TEXTURE_UNITS = 4 units: a texture per
  unit (ALPHA, LUMINANCE, LUMINANCE_ALPHA, RGB, RGBA, also as 5_6_5, 4_4_4_4
  and 5_5_5_1 texels; 1..64 texels a side, non-square; level 0 only, a full
  uploaded chain, GENERATE_MIPMAP, or a chain missing levels (incomplete with
  a mipmap filter, so the unit is off)), every min and mag filter, every
  wrap mode; environments REPLACE, MODULATE, DECAL, BLEND, ADD and COMBINE
  (every function incl. DOT3_RGB/DOT3_RGBA, sources incl. the TEXTUREn
  crossbar, operands, RGB_SCALE/ALPHA_SCALE 1, 2, 4), environment colour;
  texture coordinates from size 2, 3 or 4 arrays (q != 1: projective) or the
  current coordinates, and an occasional non-identity texture matrix;
* overlapping random triangles, partly clipped, with per-vertex colours,
  drawn partly in one glDrawArrays and partly one by one, over phases with
  state changes between them; one scene in three draws the same vertices as
  GL_LINES, LINE_STRIP or LINE_LOOP of width 1, 0.6 or 2 (aliased lines of
  width 1 run through the span functions a row or a column at a time).

Three random tests: the whole state space, with an optional second phase
that changes one to three fields of up to three parts of the state (only the
commands for what changed are issued), or a unit's filters alone, its enable
alone, or part of its level 0; texturing, with one to four complete units and
most tests and operations off, so formats, filters and environments meet
more often; and single commands between draws (STEPS: every state command
the span choice depends on, and texture rebinding, sharing, deletion and
re-specification), so a command that fails to re-pick the span function
shows. Hand-picked states add named combinations.

OES_texture_env_crossbar leaves a source naming a unit that is off (disabled
or incomplete) undefined; the core reads zero for it in every path. The
scenes with single commands and one in four of the others keep such sources;
the rest move them to units that are on.

Each scene is rendered in two fresh contexts, with and without
``ctx.debug(1)``; the buffers and glGetError must agree. The names of the
faster paths are not checked (they change); the forced run must report
"generic" after every draw.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np
import pytest
from conftest import (
    BUILDS,
    HAS_SIMD,
    SPAN_CHUNK,
    has_avx512,
    make_ctx,
    random_triangles,
    set_frustum,
    set_ortho,
)
from hypothesis import event, given, settings
from hypothesis import strategies as st

from gles import constants as C

pytestmark = pytest.mark.filterwarnings("ignore::gles.RangeWarning")

UNITS = 4  # GL_MAX_TEXTURE_UNITS (test_max_texture_units checks it)
ALL_ON = (True, True, True, True)

FUNCS = (C.GL_NEVER, C.GL_LESS, C.GL_EQUAL, C.GL_LEQUAL, C.GL_GREATER, C.GL_NOTEQUAL, C.GL_GEQUAL,
         C.GL_ALWAYS)
STENCIL_OPS = (C.GL_KEEP, C.GL_ZERO, C.GL_REPLACE, C.GL_INCR, C.GL_DECR, C.GL_INVERT, C.GL_INCR_WRAP_OES,
               C.GL_DECR_WRAP_OES)
SRC_FACTORS = (C.GL_ZERO, C.GL_ONE, C.GL_DST_COLOR, C.GL_ONE_MINUS_DST_COLOR, C.GL_SRC_ALPHA,
               C.GL_ONE_MINUS_SRC_ALPHA, C.GL_DST_ALPHA, C.GL_ONE_MINUS_DST_ALPHA, C.GL_SRC_ALPHA_SATURATE)
DST_FACTORS = (C.GL_ZERO, C.GL_ONE, C.GL_SRC_COLOR, C.GL_ONE_MINUS_SRC_COLOR, C.GL_SRC_ALPHA,
               C.GL_ONE_MINUS_SRC_ALPHA, C.GL_DST_ALPHA, C.GL_ONE_MINUS_DST_ALPHA)
EQUATIONS = (C.GL_FUNC_ADD_OES, C.GL_FUNC_SUBTRACT_OES, C.GL_FUNC_REVERSE_SUBTRACT_OES)
LOGIC_OPS = tuple(getattr(C, "GL_" + n) for n in (
    "CLEAR", "AND", "AND_REVERSE", "COPY", "AND_INVERTED", "NOOP", "XOR", "OR", "NOR", "EQUIV", "INVERT",
    "OR_REVERSE", "COPY_INVERTED", "OR_INVERTED", "NAND", "SET"))
FOG_MODES = (C.GL_LINEAR, C.GL_EXP, C.GL_EXP2)
HINTS = (C.GL_DONT_CARE, C.GL_FASTEST, C.GL_NICEST)

# (format, type) of the client texels
TEX_FORMATS = ((C.GL_RGBA, C.GL_UNSIGNED_BYTE), (C.GL_RGB, C.GL_UNSIGNED_BYTE),
               (C.GL_ALPHA, C.GL_UNSIGNED_BYTE), (C.GL_LUMINANCE, C.GL_UNSIGNED_BYTE),
               (C.GL_LUMINANCE_ALPHA, C.GL_UNSIGNED_BYTE),
               (C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5), (C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4),
               (C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1))
CHANNELS = {C.GL_RGBA: 4, C.GL_RGB: 3, C.GL_ALPHA: 1, C.GL_LUMINANCE: 1, C.GL_LUMINANCE_ALPHA: 2}
MIN_FILTERS = (C.GL_NEAREST, C.GL_LINEAR, C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_NEAREST,
               C.GL_NEAREST_MIPMAP_LINEAR, C.GL_LINEAR_MIPMAP_LINEAR)
MAG_FILTERS = (C.GL_NEAREST, C.GL_LINEAR)
WRAPS = (C.GL_REPEAT, C.GL_CLAMP_TO_EDGE, C.GL_MIRRORED_REPEAT_OES)
MIPS = ("none", "full", "generate", "partial")

ENV_MODES = (C.GL_REPLACE, C.GL_MODULATE, C.GL_DECAL, C.GL_BLEND, C.GL_ADD, C.GL_COMBINE)
COMBINE_RGB = (C.GL_REPLACE, C.GL_MODULATE, C.GL_ADD, C.GL_ADD_SIGNED, C.GL_INTERPOLATE, C.GL_SUBTRACT,
               C.GL_DOT3_RGB, C.GL_DOT3_RGBA)
COMBINE_ALPHA = COMBINE_RGB[:6]
SOURCES = (C.GL_TEXTURE, C.GL_CONSTANT, C.GL_PRIMARY_COLOR, C.GL_PREVIOUS) + tuple(
    C.GL_TEXTURE0 + u for u in range(UNITS))
RGB_OPERANDS = (C.GL_SRC_COLOR, C.GL_ONE_MINUS_SRC_COLOR, C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
ALPHA_OPERANDS = (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
SCALES = (1.0, 2.0, 4.0)
TEXCOORDS = ("array2", "array4", "array3", "current")

SEED = st.integers(0, 2**32 - 1)


# {================================================================
# the strategy


MODES = (C.GL_TRIANGLES,) * 6 + (C.GL_LINES, C.GL_LINE_STRIP, C.GL_LINE_LOOP)


def rarely(n: int = 3) -> st.SearchStrategy[bool]:
    """On one time in n (shrinks to off)."""
    return st.sampled_from((False,) * (n - 1) + (True,))


def color4(lo: float = -0.25, hi: float = 1.25) -> st.SearchStrategy[tuple]:
    """An RGBA colour, some of it outside [0, 1] (the commands clamp it)."""
    return st.tuples(*[st.floats(lo, hi)] * 4)


def mask_value() -> st.SearchStrategy[int]:
    return st.one_of(st.sampled_from((0xFF, 0xFFFFFFFF, 0x0F, 0xF0, 0x01, 0x00)), st.integers(0, 255))


# a unit that is off: the GL default environment, a small texture, plain coordinates
OFF_ENV = {"mode": C.GL_MODULATE, "color": (0.0, 0.0, 0.0, 0.0), "rgb": C.GL_MODULATE, "alpha": C.GL_MODULATE,
           "src_rgb": (C.GL_TEXTURE, C.GL_PREVIOUS, C.GL_CONSTANT),
           "op_rgb": (C.GL_SRC_COLOR, C.GL_SRC_COLOR, C.GL_SRC_ALPHA),
           "src_alpha": (C.GL_TEXTURE, C.GL_PREVIOUS, C.GL_CONSTANT),
           "op_alpha": (C.GL_SRC_ALPHA, C.GL_SRC_ALPHA, C.GL_SRC_ALPHA), "rgb_scale": 1.0, "alpha_scale": 1.0}
OFF_TEX = {"enabled": False, "format": (C.GL_RGBA, C.GL_UNSIGNED_BYTE), "log_w": 3, "log_h": 3, "mip": "none",
           "min": C.GL_NEAREST, "mag": C.GL_NEAREST, "wrap_s": C.GL_REPEAT, "wrap_t": C.GL_REPEAT, "seed": 0}
OFF_TC = {"kind": "array2", "seed": 0, "matrix": None}


@st.composite
def texture_strategy(draw: Any, unit: int, on: bool | None = None) -> dict:
    """A unit's texture, enabled when `on` (None: at random, complete or not); a
    disabled unit's is a fixed small one (phase 2 may enable it)."""
    if on is None:
        on = draw(st.sampled_from((True, True, False)) if unit == 0 else rarely())
        complete = False
    else:
        complete = on
    if not on:
        return {**OFF_TEX, "seed": draw(SEED)}
    tex = {
        "enabled": True,
        "format": draw(st.sampled_from(TEX_FORMATS)),
        "log_w": draw(st.integers(0, 6)),
        "log_h": draw(st.integers(0, 6)),
        "mip": draw(st.sampled_from(MIPS)),
        "min": draw(st.sampled_from(MIN_FILTERS)),
        "mag": draw(st.sampled_from(MAG_FILTERS)),
        "wrap_s": draw(st.sampled_from(WRAPS)),
        "wrap_t": draw(st.sampled_from(WRAPS)),
        "seed": draw(SEED),
    }
    if complete and not texture_complete(tex):
        tex["mip"] = draw(st.sampled_from(("full", "generate")))
    return tex


ENV = st.fixed_dictionaries({
    "mode": st.sampled_from(ENV_MODES),
    "color": color4(),
    "rgb": st.sampled_from(COMBINE_RGB),
    "alpha": st.sampled_from(COMBINE_ALPHA),
    "src_rgb": st.tuples(*[st.sampled_from(SOURCES)] * 3),
    "op_rgb": st.tuples(*[st.sampled_from(RGB_OPERANDS)] * 3),
    "src_alpha": st.tuples(*[st.sampled_from(SOURCES)] * 3),
    "op_alpha": st.tuples(*[st.sampled_from(ALPHA_OPERANDS)] * 3),
    "rgb_scale": st.sampled_from(SCALES),
    "alpha_scale": st.sampled_from(SCALES),
})

TEXCOORD = st.fixed_dictionaries({
    "kind": st.sampled_from(TEXCOORDS),
    "seed": SEED,
    # None: identity texture matrix; else the seed of a random one
    "matrix": st.one_of(st.none(), st.none(), SEED),
})

# one strategy per part of the state: the phases set these one by one
ASPECTS: dict[str, st.SearchStrategy] = {
    "smooth": st.booleans(),
    "dither": st.booleans(),
    "scissor": st.fixed_dictionaries({
        "on": rarely(4),
        # x, y, width, height in percent of the window's
        "box": st.tuples(st.integers(-10, 80), st.integers(-10, 80), st.integers(0, 110),
                         st.integers(0, 110)),
    }),
    "color_mask": st.one_of(st.just(ALL_ON), st.tuples(*[st.booleans()] * 4)),
    "depth": st.fixed_dictionaries({
        "on": st.booleans(),
        "func": st.sampled_from((C.GL_LESS, C.GL_LESS) + FUNCS),
        "mask": st.sampled_from((True, True, False)),
        "range": st.one_of(st.none(), st.none(), st.tuples(st.floats(0, 1), st.floats(0, 1))),
    }),
    "stencil": st.fixed_dictionaries({
        "on": rarely(4),
        "func": st.sampled_from(FUNCS),
        "ref": st.one_of(st.integers(0, 255), st.integers(-3, 300)),
        "value_mask": mask_value(),
        "write_mask": mask_value(),
        "ops": st.tuples(*[st.sampled_from(STENCIL_OPS)] * 3),
    }),
    "alpha": st.fixed_dictionaries({
        "on": rarely(),
        "func": st.sampled_from(FUNCS),
        "ref": st.one_of(st.integers(0, 255).map(lambda v: v / 255), st.floats(-0.1, 1.1)),
    }),
    "blend": st.fixed_dictionaries({
        "on": st.booleans(),
        "func": st.one_of(st.sampled_from(((C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), (C.GL_ONE, C.GL_ONE))),
                          st.tuples(st.sampled_from(SRC_FACTORS), st.sampled_from(DST_FACTORS))),
        # None, or the (src, dst) alpha factors of a glBlendFuncSeparateOES
        "separate": st.one_of(st.none(), st.none(),
                              st.tuples(st.sampled_from(SRC_FACTORS), st.sampled_from(DST_FACTORS))),
        # None (no call), (mode,) for glBlendEquationOES, (rgb, alpha) for the separate form
        "equation": st.one_of(st.none(), st.tuples(st.sampled_from(EQUATIONS)),
                              st.tuples(st.sampled_from(EQUATIONS), st.sampled_from(EQUATIONS))),
    }),
    "logic": st.fixed_dictionaries({"on": rarely(), "op": st.sampled_from(LOGIC_OPS)}),
    "fog": st.fixed_dictionaries({
        "on": rarely(),
        "mode": st.sampled_from(FOG_MODES),
        "start": st.floats(-1.0, 3.0),
        "end": st.floats(-1.0, 4.0),
        "density": st.floats(0.0, 2.5),
        "color": color4(),
        "hint": st.sampled_from(HINTS),
    }),
    "offset": st.fixed_dictionaries({"on": rarely(), "factor": st.floats(-4, 4), "units": st.floats(-8, 8)}),
}
for _u in range(UNITS):
    ASPECTS[f"tex{_u}"] = texture_strategy(_u)
    ASPECTS[f"env{_u}"] = ENV
    ASPECTS[f"tc{_u}"] = TEXCOORD

# changes only phase 2 makes, to the texture phase 1 bound: its filters alone,
# its unit's enable alone, part of its level 0 (glTexSubImage2D)
CHANGES: dict[str, st.SearchStrategy] = dict(ASPECTS)
for _u in range(UNITS):
    CHANGES[f"filter{_u}"] = st.tuples(st.sampled_from(MIN_FILTERS), st.sampled_from(MAG_FILTERS))
    CHANGES[f"enable{_u}"] = st.booleans()
    CHANGES[f"subimage{_u}"] = SEED

# a row over two chunks of the chain and into a third
WIDE = 2 * SPAN_CHUNK + 22

# most windows are small; one in three is wider than a chunk of the chain, or two
SIZES = st.sampled_from((False, False, True)).flatmap(
    lambda wide: st.tuples(st.integers(SPAN_CHUNK + 6, WIDE), st.integers(4, 12)) if wide
    else st.tuples(st.integers(24, 40), st.integers(24, 32)))


# the per-fragment operations a texturing scene mostly leaves off
TESTS_AND_OPS = ("scissor", "stencil", "alpha", "logic", "offset", "fog")


@st.composite
def scenes(draw: Any, textured: bool = False, steps: bool = False) -> dict:
    """A context, geometry, the state of phase 1 and the changes of an optional phase 2.

    ``textured``: one to four units on, with complete textures, and each of
    TESTS_AND_OPS off three times in four (texture formats, filters and
    environments meet more often).

    A change to a part phase 1 set replaces one to three of its fields, so that
    phase 2 often issues a single command. ``steps``: instead of phase 2, three to
    ten phases of one command each (STEPS), any crossbar sources kept.
    """
    units_on = draw(st.sets(st.integers(0, UNITS - 1), min_size=1)) if textured else None
    state: dict[str, Any] = {}
    for key, strategy in ASPECTS.items():
        if units_on is not None and key.startswith("tex"):
            state[key] = draw(texture_strategy(int(key[3:]), int(key[3:]) in units_on))
        elif key.startswith(("env", "tc")) and not state[f"tex{key[-1]}"]["enabled"]:
            state[key] = dict(OFF_ENV if key.startswith("env") else OFF_TC)
        else:
            state[key] = draw(strategy)
        if textured and key in TESTS_AND_OPS and not draw(rarely(4)):
            state[key] = {**state[key], "on": False}
    changes = None
    if not steps and draw(st.booleans()):
        changes = {}
        for key in draw(st.lists(st.sampled_from(sorted(CHANGES)), min_size=1, max_size=3, unique=True)):
            new = draw(CHANGES[key])
            if isinstance(state.get(key), dict):
                fields = draw(st.lists(st.sampled_from(sorted(new)), min_size=1, max_size=3, unique=True))
                new = {**state[key], **{f: new[f] for f in fields}}
            changes[key] = new
    scene = {
        "numeric": draw(st.sampled_from(BUILDS)),
        "color": draw(st.sampled_from(("rgba8888", "rgb565", "rgba4444", "rgba5551"))),
        "depth_bits": draw(st.sampled_from((0, 16, 24))),
        "stencil_bits": draw(st.sampled_from((0, 8))),
        "size": draw(SIZES),
        "persp": draw(st.booleans()),
        "triangles": draw(st.integers(4, 12)) if not steps else 0,
        # one scene in three draws the vertices as lines (width-1 x-major lines run as spans)
        "mode": draw(st.sampled_from(MODES)),
        "line_width": draw(st.sampled_from((1.0, 1.0, 0.6, 2.0))),
        "geometry": draw(SEED),
        "clear": (draw(color4(0.0, 1.0)), draw(st.one_of(st.just(1.0), st.floats(0.0, 1.0))),
                  draw(st.integers(0, 255))),
        # crossbar sources may name units that are off (else they are moved to units that are on)
        "crossbar_to_off": steps or draw(rarely(4)),
        "state": state,
        "changes": changes,
    }
    if steps:
        scene["steps"] = draw(st.lists(STEPS, min_size=3, max_size=10))
        scene["triangles"] = draw(st.integers(len(scene["steps"]) + 1, 20))
    return scene


# {================================================================
# applying a state


def texture_levels(tex: dict) -> int:
    """The number of mip levels below level 0 of a full chain."""
    return max(tex["log_w"], tex["log_h"])


def texture_complete(tex: dict) -> bool:
    """§3.7.10 for the textures upload_texture makes."""
    mipmapped = tex["min"] not in (C.GL_NEAREST, C.GL_LINEAR)
    return not mipmapped or tex["mip"] in ("full", "generate") or texture_levels(tex) == 0


@dataclass
class Textures:
    """What the commands issued so far did to the textures."""

    units: dict[int, dict] = field(default_factory=dict)    # per unit: its texture's fields and enable
    images: dict[int, dict] = field(default_factory=dict)   # per texture name: its level 0's fields

    def track(self, key: str, v: Any) -> None:
        """Follow a part of the state (or a phase-2 change) of `key`."""
        for kind in ("tex", "filter", "enable"):
            if key.startswith(kind):
                u = int(key[len(kind):])
                if kind == "tex":
                    self.units[u] = dict(v)
                elif kind == "filter":
                    self.units[u] = {**self.units[u], "min": v[0], "mag": v[1]}
                else:
                    self.units[u] = {**self.units[u], "enabled": v}


def active_units(*parts: dict) -> set[int]:
    """The units enabled with a complete texture after the parts are applied in turn."""
    t = Textures()
    for part in parts:
        for key, v in part.items():
            t.track(key, v)
    return {u for u, tex in t.units.items() if tex["enabled"] and texture_complete(tex)}


def texels(rng: np.random.Generator, fmt: int, gltype: int, w: int, h: int) -> np.ndarray:
    if gltype == C.GL_UNSIGNED_BYTE:
        return rng.integers(0, 256, size=(h, w, CHANNELS[fmt]), dtype=np.uint8)
    return rng.integers(0, 2**16, size=(h, w), dtype=np.uint16)


def upload_texture(gl: Any, unit: int, tex: dict, textures: Textures) -> None:
    """A new texture object on `unit` with the levels, filters and wraps of `tex`."""
    rng = np.random.default_rng(tex["seed"])
    fmt, gltype = tex["format"]
    gl.glActiveTexture(C.GL_TEXTURE0 + unit)
    name = gl.glGenTextures(1)
    textures.images[name] = tex
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, tex["min"])
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, tex["mag"])
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, tex["wrap_s"])
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, tex["wrap_t"])
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, int(tex["mip"] == "generate"))
    top = {"none": 0, "generate": 0, "full": texture_levels(tex),
           "partial": int(rng.integers(0, max(texture_levels(tex), 1)))}[tex["mip"]]
    for level in range(top + 1):
        w, h = max(1 << tex["log_w"] >> level, 1), max(1 << tex["log_h"] >> level, 1)
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, fmt, w, h, 0, fmt, gltype, texels(rng, fmt, gltype, w, h))
    (gl.glEnable if tex["enabled"] else gl.glDisable)(C.GL_TEXTURE_2D)


def texture_matrix(seed: int) -> np.ndarray:
    """A column-major 4x4: rotation, scale and shift of (s, t), and sometimes a q row
    that keeps q > 0.3 for the coordinates of texcoords()."""
    rng = np.random.default_rng(seed)
    m = np.eye(4)
    a = rng.uniform(-np.pi, np.pi)
    rot = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    m[:2, :2] = rot * rng.uniform(0.25, 2.5, size=2)[:, None]
    m[:2, 3] = rng.uniform(-1, 1, size=2)
    if rng.random() < 0.5:
        m[3, :2] = rng.uniform(-0.1, 0.1, size=2)
        m[3, 3] = rng.uniform(0.9, 2.0)
    return np.ascontiguousarray(m.T.reshape(-1))


def texcoords(seed: int, kind: str, n: int) -> np.ndarray:
    """(n, size) float32 coordinates, or one (s, t, r, q) row for "current"."""
    rng = np.random.default_rng(seed)
    size = {"array2": 2, "array3": 3, "array4": 4, "current": 4}[kind]
    rows = 1 if kind == "current" else n
    st_ = rng.uniform(-1.5, 2.5, size=(rows, 2))
    r = rng.uniform(-1, 1, size=(rows, 1))
    q = rng.uniform(0.3, 2.0, size=(rows, 1)) if size == 4 else np.ones((rows, 1))
    out = np.hstack([st_ * q, r, q])
    return np.ascontiguousarray(out[:, :size], dtype=np.float32)


def set_texcoords(gl: Any, unit: int, tc: dict, n: int) -> None:
    coords = texcoords(tc["seed"], tc["kind"], n)
    gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
    if tc["kind"] == "current":
        gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glMultiTexCoord4f(C.GL_TEXTURE0 + unit, *(float(v) for v in coords[0]))
    else:
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(coords.shape[1], C.GL_FLOAT, 0, coords)


def set_texture_matrix(gl: Any, unit: int, seed: int | None) -> None:
    gl.glActiveTexture(C.GL_TEXTURE0 + unit)
    gl.glMatrixMode(C.GL_TEXTURE)
    if seed is None:
        gl.glLoadIdentity()
    else:
        gl.glLoadMatrixf(texture_matrix(seed))
    gl.glMatrixMode(C.GL_MODELVIEW)


def bound_texture(gl: Any, unit: int) -> int:
    gl.glActiveTexture(C.GL_TEXTURE0 + unit)
    return int(gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D))


def replace_subimage(gl: Any, unit: int, seed: int, textures: Textures) -> None:
    """New texels in a random rectangle of level 0 of the texture `unit` has bound
    (nothing if it has none)."""
    tex = textures.images.get(bound_texture(gl, unit))
    if tex is None:
        return
    rng = np.random.default_rng(seed)
    fmt, gltype = tex["format"]
    tw, th = 1 << tex["log_w"], 1 << tex["log_h"]
    x, y = int(rng.integers(0, tw)), int(rng.integers(0, th))
    w, h = int(rng.integers(1, tw - x + 1)), int(rng.integers(1, th - y + 1))
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, x, y, w, h, fmt, gltype, texels(rng, fmt, gltype, w, h))


def enable(gl: Any, cap: int, on: bool) -> None:
    (gl.glEnable if on else gl.glDisable)(cap)


def env_commands(gl: Any, unit: int, env: dict) -> list[tuple[Any, Callable[[], None]]]:
    def param(pname: int, value: Any, fn: Any) -> tuple[Any, Callable[[], None]]:
        def cmd() -> None:
            gl.glActiveTexture(C.GL_TEXTURE0 + unit)
            fn(C.GL_TEXTURE_ENV, pname, value)
        return (pname, value), cmd

    out = [param(C.GL_TEXTURE_ENV_MODE, env["mode"], gl.glTexEnvi),
           param(C.GL_TEXTURE_ENV_COLOR, list(env["color"]), gl.glTexEnvfv),
           param(C.GL_COMBINE_RGB, env["rgb"], gl.glTexEnvi),
           param(C.GL_COMBINE_ALPHA, env["alpha"], gl.glTexEnvi),
           param(C.GL_RGB_SCALE, env["rgb_scale"], gl.glTexEnvf),
           param(C.GL_ALPHA_SCALE, env["alpha_scale"], gl.glTexEnvf)]
    for n in range(3):
        out += [param(C.GL_SRC0_RGB + n, env["src_rgb"][n], gl.glTexEnvi),
                param(C.GL_OPERAND0_RGB + n, env["op_rgb"][n], gl.glTexEnvi),
                param(C.GL_SRC0_ALPHA + n, env["src_alpha"][n], gl.glTexEnvi),
                param(C.GL_OPERAND0_ALPHA + n, env["op_alpha"][n], gl.glTexEnvi)]
    return out


def commands(gl: Any, key: str, v: Any, size: tuple[int, int], nverts: int,
             textures: Textures) -> list[tuple[Any, Callable[[], None]]]:
    """The commands that set one part of the state, for a window of `size` and `nverts`
    vertices, each with the values it depends on (a change of a part that leaves them
    equal skips the command)."""
    w, h = size
    if key == "smooth":
        return [(v, lambda: gl.glShadeModel(C.GL_SMOOTH if v else C.GL_FLAT))]
    if key == "dither":
        return [(v, lambda: enable(gl, C.GL_DITHER, v))]
    if key == "scissor":
        x, y, sw, sh = v["box"]
        return [(v["box"], lambda: gl.glScissor(w * x // 100, h * y // 100, w * sw // 100, h * sh // 100)),
                (v["on"], lambda: enable(gl, C.GL_SCISSOR_TEST, v["on"]))]
    if key == "color_mask":
        return [(v, lambda: gl.glColorMask(*v))]
    if key == "depth":
        return [(v["func"], lambda: gl.glDepthFunc(v["func"])),
                (v["mask"], lambda: gl.glDepthMask(v["mask"])),
                (v["range"], lambda: v["range"] is None or gl.glDepthRangef(*v["range"])),
                (v["on"], lambda: enable(gl, C.GL_DEPTH_TEST, v["on"]))]
    if key == "stencil":
        func = (v["func"], v["ref"], v["value_mask"])
        return [(func, lambda: gl.glStencilFunc(*func)),
                (v["write_mask"], lambda: gl.glStencilMask(v["write_mask"])),
                (v["ops"], lambda: gl.glStencilOp(*v["ops"])),
                (v["on"], lambda: enable(gl, C.GL_STENCIL_TEST, v["on"]))]
    if key == "alpha":
        return [((v["func"], v["ref"]), lambda: gl.glAlphaFunc(v["func"], v["ref"])),
                (v["on"], lambda: enable(gl, C.GL_ALPHA_TEST, v["on"]))]
    if key == "blend":
        def func() -> None:
            if v["separate"] is None:
                gl.glBlendFunc(*v["func"])
            else:
                gl.glBlendFuncSeparateOES(*v["func"], *v["separate"])

        def equation() -> None:
            if v["equation"] is not None and len(v["equation"]) == 1:
                gl.glBlendEquationOES(*v["equation"])
            elif v["equation"] is not None:
                gl.glBlendEquationSeparateOES(*v["equation"])

        return [((v["func"], v["separate"]), func), (v["equation"], equation),
                (v["on"], lambda: enable(gl, C.GL_BLEND, v["on"]))]
    if key == "logic":
        return [(v["op"], lambda: gl.glLogicOp(v["op"])),
                (v["on"], lambda: enable(gl, C.GL_COLOR_LOGIC_OP, v["on"]))]
    if key == "fog":
        return [(v["mode"], lambda: gl.glFogf(C.GL_FOG_MODE, v["mode"])),
                (v["start"], lambda: gl.glFogf(C.GL_FOG_START, v["start"])),
                (v["end"], lambda: gl.glFogf(C.GL_FOG_END, v["end"])),
                (v["density"], lambda: gl.glFogf(C.GL_FOG_DENSITY, v["density"])),
                (v["color"], lambda: gl.glFogfv(C.GL_FOG_COLOR, list(v["color"]))),
                (v["hint"], lambda: gl.glHint(C.GL_FOG_HINT, v["hint"])),
                (v["on"], lambda: enable(gl, C.GL_FOG, v["on"]))]
    if key == "offset":
        return [((v["factor"], v["units"]), lambda: gl.glPolygonOffset(v["factor"], v["units"])),
                (v["on"], lambda: enable(gl, C.GL_POLYGON_OFFSET_FILL, v["on"]))]
    for prefix in ("tex", "filter", "enable", "subimage", "env", "tc"):
        if key.startswith(prefix):
            u = int(key[len(prefix):])
            break
    else:
        raise KeyError(key)

    def on_unit(fn: Callable[[], None]) -> Callable[[], None]:
        def cmd() -> None:
            gl.glActiveTexture(C.GL_TEXTURE0 + u)
            fn()
        return cmd

    if prefix == "tex":
        return [(v, lambda: upload_texture(gl, u, v, textures))]
    if prefix == "filter":
        return [(v[0], on_unit(lambda: gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, v[0]))),
                (v[1], on_unit(lambda: gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, v[1])))]
    if prefix == "enable":
        return [(v, on_unit(lambda: enable(gl, C.GL_TEXTURE_2D, v)))]
    if prefix == "subimage":
        return [(v, lambda: replace_subimage(gl, u, v, textures))]
    if prefix == "env":
        return env_commands(gl, u, v)
    return [((v["kind"], v["seed"]), lambda: set_texcoords(gl, u, v, nverts)),
            (v["matrix"], lambda: set_texture_matrix(gl, u, v["matrix"]))]


def apply(gl: Any, key: str, v: Any, size: tuple[int, int], nverts: int, textures: Textures,
          prev: Any = None) -> None:
    """Set one part of the state; with `prev` (the part's value so far) only the
    commands whose values differ."""
    old = None if prev is None else [sig for sig, _ in commands(gl, key, prev, size, nverts, textures)]
    for i, (sig, cmd) in enumerate(commands(gl, key, v, size, nverts, textures)):
        if old is None or old[i] != sig:
            cmd()
    textures.track(key, v)


def crossbar_on_units_on(scene: dict) -> dict:
    """Unless the scene says otherwise, move every TEXTUREn source that names a unit
    off in either phase to a unit on in both (or to TEXTURE if there is none).
    OES_texture_env_crossbar leaves a reference to a unit that is off undefined; the
    core reads zero for it, in every path, and the scenes that keep such sources
    check that."""
    if scene.get("crossbar_to_off"):
        return scene
    state, changes = scene["state"], scene["changes"] or {}
    ok = sorted(active_units(state) & active_units(state, changes))

    def src(s: int) -> int:
        if s < C.GL_TEXTURE0 or s - C.GL_TEXTURE0 in ok:
            return s
        return C.GL_TEXTURE0 + ok[(s - C.GL_TEXTURE0) % len(ok)] if ok else C.GL_TEXTURE

    def fixed(part: dict) -> dict:
        return {k: {**v, "src_rgb": tuple(map(src, v["src_rgb"])),
                    "src_alpha": tuple(map(src, v["src_alpha"]))} if k.startswith("env") else v
                for k, v in part.items()}

    return {**scene, "state": fixed(state), "changes": None if scene["changes"] is None else fixed(changes)}


# {================================================================
# single commands between draws


CAPS = (C.GL_DEPTH_TEST, C.GL_STENCIL_TEST, C.GL_ALPHA_TEST, C.GL_BLEND, C.GL_COLOR_LOGIC_OP, C.GL_FOG,
        C.GL_DITHER, C.GL_SCISSOR_TEST, C.GL_POLYGON_OFFSET_FILL)
UNIT = st.integers(0, UNITS - 1)
SRC = st.sampled_from(SRC_FACTORS)
DST = st.sampled_from(DST_FACTORS)
EQ = st.sampled_from(EQUATIONS)
ENV_PARAMS = st.one_of(
    st.tuples(st.just(C.GL_TEXTURE_ENV_MODE), st.sampled_from(ENV_MODES)),
    st.tuples(st.just(C.GL_COMBINE_RGB), st.sampled_from(COMBINE_RGB)),
    st.tuples(st.just(C.GL_COMBINE_ALPHA), st.sampled_from(COMBINE_ALPHA)),
    st.tuples(st.sampled_from((C.GL_SRC0_RGB, C.GL_SRC1_RGB, C.GL_SRC2_RGB, C.GL_SRC0_ALPHA, C.GL_SRC1_ALPHA,
                               C.GL_SRC2_ALPHA)), st.sampled_from(SOURCES)),
    st.tuples(st.sampled_from((C.GL_OPERAND0_RGB, C.GL_OPERAND1_RGB, C.GL_OPERAND2_RGB)),
              st.sampled_from(RGB_OPERANDS)),
    st.tuples(st.sampled_from((C.GL_OPERAND0_ALPHA, C.GL_OPERAND1_ALPHA, C.GL_OPERAND2_ALPHA)),
              st.sampled_from(ALPHA_OPERANDS)),
)
TEX_PARAMS = st.one_of(
    st.tuples(st.just(C.GL_TEXTURE_MIN_FILTER), st.sampled_from(MIN_FILTERS)),
    st.tuples(st.just(C.GL_TEXTURE_MAG_FILTER), st.sampled_from(MAG_FILTERS)),
    st.tuples(st.sampled_from((C.GL_TEXTURE_WRAP_S, C.GL_TEXTURE_WRAP_T)), st.sampled_from(WRAPS)),
)
# one GL command each: the name of the command (or of what it does) and its arguments
STEPS = st.one_of(
    st.tuples(st.just("DepthFunc"), st.sampled_from(FUNCS)),
    st.tuples(st.just("DepthMask"), st.booleans()),
    st.tuples(st.just("ColorMask"), st.tuples(*[st.booleans()] * 4)),
    st.tuples(st.just("ShadeModel"), st.sampled_from((C.GL_FLAT, C.GL_SMOOTH))),
    st.tuples(st.just("Enable"), st.sampled_from(CAPS), st.booleans()),
    st.tuples(st.just("BlendFunc"), SRC, DST),
    st.tuples(st.just("BlendFuncSeparateOES"), SRC, DST, SRC, DST),
    st.tuples(st.just("BlendEquationOES"), EQ),
    st.tuples(st.just("BlendEquationSeparateOES"), EQ, EQ),
    st.tuples(st.just("LogicOp"), st.sampled_from(LOGIC_OPS)),
    st.tuples(st.just("AlphaFunc"), st.sampled_from(FUNCS), st.integers(0, 255).map(lambda v: v / 255)),
    st.tuples(st.just("StencilFunc"), st.sampled_from(FUNCS), st.integers(0, 255), mask_value()),
    st.tuples(st.just("StencilOp"), *[st.sampled_from(STENCIL_OPS)] * 3),
    st.tuples(st.just("StencilMask"), mask_value()),
    st.tuples(st.just("Fogf"), st.sampled_from((C.GL_FOG_START, C.GL_FOG_END, C.GL_FOG_DENSITY)),
              st.floats(0.0, 3.0)),
    st.tuples(st.just("Fogf"), st.just(C.GL_FOG_MODE), st.sampled_from(FOG_MODES)),
    st.tuples(st.just("FogHint"), st.sampled_from(HINTS)),
    st.tuples(st.just("PolygonOffset"), st.floats(-4, 4), st.floats(-8, 8)),
    st.tuples(st.just("TexEnable"), UNIT, st.booleans()),
    st.tuples(st.just("TexParameteri"), UNIT, TEX_PARAMS),
    st.tuples(st.just("TexEnvi"), UNIT, ENV_PARAMS),
    st.tuples(st.just("TexEnvColor"), UNIT, color4()),
    # level 0 only, on the bound object: other levels may no longer match
    st.tuples(st.just("TexImage2D"), UNIT, st.sampled_from(TEX_FORMATS), st.integers(0, 6), st.integers(0, 6),
              SEED),
    st.tuples(st.just("TexSubImage2D"), UNIT, SEED),
    # bind the texture another unit has bound (one object on two units)
    st.tuples(st.just("BindTexture"), UNIT, UNIT),
    # delete a unit's texture: the units it was bound to fall back to texture 0
    st.tuples(st.just("DeleteTextures"), UNIT),
)


def run_step(gl: Any, step: tuple, textures: Textures) -> None:
    """Issue the one command of `step`."""
    name, *a = step
    if name == "Enable":
        enable(gl, a[0], a[1])
    elif name == "ShadeModel":
        gl.glShadeModel(a[0])
    elif name == "ColorMask":
        gl.glColorMask(*a[0])
    elif name == "Fogf":
        gl.glFogf(a[0], a[1])
    elif name == "FogHint":
        gl.glHint(C.GL_FOG_HINT, a[0])
    elif name in ("TexEnable", "TexParameteri", "TexEnvi", "TexEnvColor", "TexImage2D", "TexSubImage2D",
                  "BindTexture", "DeleteTextures"):
        u, *a = a
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        if name == "TexEnable":
            enable(gl, C.GL_TEXTURE_2D, a[0])
        elif name == "TexParameteri":
            gl.glTexParameteri(C.GL_TEXTURE_2D, *a[0])
        elif name == "TexEnvi":
            gl.glTexEnvi(C.GL_TEXTURE_ENV, *a[0])
        elif name == "TexEnvColor":
            gl.glTexEnvfv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, list(a[0]))
        elif name == "TexImage2D":
            (fmt, gltype), log_w, log_h, seed = a
            textures.images[bound_texture(gl, u)] = {"format": (fmt, gltype), "log_w": log_w, "log_h": log_h}
            gl.glActiveTexture(C.GL_TEXTURE0 + u)
            gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
            gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, 1 << log_w, 1 << log_h, 0, fmt, gltype,
                            texels(np.random.default_rng(seed), fmt, gltype, 1 << log_w, 1 << log_h))
        elif name == "TexSubImage2D":
            replace_subimage(gl, u, a[0], textures)
        elif name == "BindTexture":
            other = bound_texture(gl, a[0])
            gl.glActiveTexture(C.GL_TEXTURE0 + u)
            gl.glBindTexture(C.GL_TEXTURE_2D, other)
        else:
            doomed = bound_texture(gl, u)
            if doomed:
                gl.glDeleteTextures(1, [doomed])
                textures.images.pop(doomed, None)
    else:
        getattr(gl, "gl" + name)(*a)


# {================================================================
# rendering


def draw_phase(gl: Any, first: int, count: int, mode: int = C.GL_TRIANGLES) -> None:
    """Triangles first .. first+count-1 (or their vertices as lines of `mode`): about half in
    one call, then one call each."""
    if count <= 0:
        return
    batch = (count + 1) // 2
    gl.glDrawArrays(mode, 3 * first, 3 * batch)
    for i in range(first + batch, first + count):
        gl.glDrawArrays(mode, 3 * i, 3)


def render(scene: dict, generic: bool, baseline: bool = False, avx2: bool = False) -> dict:
    """Draw `scene` in a fresh context; the buffers, glGetError and the span path of each phase.

    `generic` forces the per-fragment reference; `baseline` the baseline
    instance of the span stages where the CPU has a vector one; `avx2` the
    AVX2 instance where the CPU runs an AVX-512 one."""
    w, h = scene["size"]
    rng = np.random.default_rng(scene["geometry"])
    verts, cols = random_triangles(rng, scene["persp"], scene["triangles"], w)
    if not scene["persp"]:
        # random_triangles spans -6 .. w + 6 in x and y: fit y to the window's height
        verts[:, 1] = (verts[:, 1] + 6) * ((h + 12) / (w + 12)) - 6
    ctx = make_ctx(scene["numeric"], w, h, color=scene["color"], depth=scene["depth_bits"],
                   stencil=scene["stencil_bits"])
    gl = ctx.gl
    if generic or baseline or avx2:
        ctx.debug((1 if generic else 0) | (16 if baseline else 0) | (32 if avx2 else 0))
    rgba, depth, stencil = scene["clear"]
    gl.glClearColor(*rgba)
    gl.glClearDepthf(depth)
    gl.glClearStencil(stencil)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    (set_frustum(gl, w, h, 1.0, 3.0) if scene["persp"] else set_ortho(gl, w, h))
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, np.ascontiguousarray(verts, dtype=np.float32))
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(cols, dtype=np.uint8))
    textures = Textures()
    current = dict(scene["state"])
    for key, value in current.items():
        apply(gl, key, value, (w, h), len(verts), textures)

    def change() -> None:
        for key, value in scene["changes"].items():
            apply(gl, key, value, (w, h), len(verts), textures, current.get(key))
            current[key] = value

    phases = [] if scene["changes"] is None else [change]
    phases += [lambda step=step: run_step(gl, step, textures) for step in scene.get("steps", ())]
    n = scene["triangles"]
    mode = scene.get("mode", C.GL_TRIANGLES)
    gl.glLineWidth(scene.get("line_width", 1.0))
    ends = [n * (i + 1) // (len(phases) + 1) for i in range(len(phases) + 1)]
    draw_phase(gl, 0, ends[0], mode)
    paths = [ctx.last_span_path()]
    for i, phase in enumerate(phases):
        phase()
        draw_phase(gl, ends[i], ends[i + 1] - ends[i], mode)
        paths.append(ctx.last_span_path())
    return {"color": ctx.color_buffer(), "depth": ctx.depth_buffer(), "stencil": ctx.stencil_buffer(),
            "error": gl.glGetError(), "paths": paths}


def check_scene(scene: dict) -> list[str]:
    """Render `scene` both ways (three where the span stages have a vector
    instance: it and the baseline one) and require identical results; return
    the unforced paths."""
    scene = crossbar_on_units_on(scene)
    ref = render(scene, generic=True)
    out = render(scene, generic=False)
    if HAS_SIMD:
        others = {"baseline": render(scene, generic=False, baseline=True)}
        if has_avx512(scene["numeric"]):
            others["avx2"] = render(scene, generic=False, avx2=True)
        for which, base in others.items():
            assert base["error"] == ref["error"]
            for name in ("color", "depth", "stencil"):
                if ref[name] is not None:
                    np.testing.assert_array_equal(base[name], ref[name], err_msg=f"{which}, {name}")
    assert ref["paths"] and all(p == "generic" for p in ref["paths"]), ref["paths"]
    assert all(isinstance(p, str) and p for p in out["paths"]), out["paths"]
    assert ref["error"] == C.GL_NO_ERROR, f"the scene itself is invalid: error {ref['error']:#x}"
    assert out["error"] == ref["error"]
    msg = f"unforced span paths {out['paths']}"
    np.testing.assert_array_equal(out["color"], ref["color"], err_msg="colour buffer; " + msg)
    for name in ("depth", "stencil"):
        if ref[name] is None:
            assert out[name] is None
        else:
            np.testing.assert_array_equal(out[name], ref[name], err_msg=f"{name} buffer; " + msg)
    return out["paths"]


@settings(max_examples=400, deadline=None)
@given(scenes())
def test_random_fragment_states_match_generic(scene):
    """Random states over the whole fragment stage: bit-identical buffers and the
    same glGetError with and without the forced generic path."""
    for path in check_scene(scene):
        event(f"span path {path}")


@settings(max_examples=200, deadline=None)
@given(scenes(textured=True))
def test_random_texturing_states_match_generic(scene):
    """The same with one to four units on and most tests and operations off."""
    for path in check_scene(scene):
        event(f"span path {path}")


@settings(max_examples=200, deadline=None)
@given(scenes(steps=True))
def test_single_commands_between_draws_match_generic(scene):
    """A random state, then draws with one command between each two: whichever
    command it is, the next draw must run the span function for the state it left."""
    for path in check_scene(scene):
        event(f"span path {path}")
    for step in scene["steps"]:
        event(f"step {step[0]}")


# {================================================================
# hand-picked states


def base_state() -> dict:
    """Every fragment operation off (the GL defaults), smooth shading."""
    state = {
        "smooth": True, "dither": False, "scissor": {"on": False, "box": (0, 0, 0, 0)}, "color_mask": ALL_ON,
        "depth": {"on": False, "func": C.GL_LESS, "mask": True, "range": None},
        "stencil": {"on": False, "func": C.GL_ALWAYS, "ref": 0, "value_mask": 0xFF, "write_mask": 0xFF,
                    "ops": (C.GL_KEEP,) * 3},
        "alpha": {"on": False, "func": C.GL_ALWAYS, "ref": 0.0},
        "blend": {"on": False, "func": (C.GL_ONE, C.GL_ZERO), "separate": None, "equation": None},
        "logic": {"on": False, "op": C.GL_COPY},
        "fog": {"on": False, "mode": C.GL_EXP, "start": 0.0, "end": 1.0, "density": 1.0,
                "color": (0.0, 0.0, 0.0, 0.0), "hint": C.GL_DONT_CARE},
        "offset": {"on": False, "factor": 0.0, "units": 0.0},
    }
    for u in range(UNITS):
        state[f"tex{u}"] = dict(OFF_TEX)
        state[f"env{u}"] = dict(OFF_ENV)
        state[f"tc{u}"] = {"kind": "array2", "seed": u, "matrix": None}
    return state


def make_scene(numeric: str, seed: int, state: dict, changes: dict | None = None, **kw: Any) -> dict:
    rng = np.random.default_rng(seed)
    scene = {"numeric": numeric, "color": "rgba8888", "depth_bits": 24, "stencil_bits": 8, "size": (32, 32),
             "persp": bool(seed % 2), "triangles": 8, "geometry": seed,
             "clear": (tuple(float(v) for v in rng.uniform(0, 1, 4)), float(rng.uniform(0.3, 1.0)),
                       int(rng.integers(0, 256))),
             "state": state, "changes": changes}
    scene.update(kw)
    return scene


def tex(seed: int, **kw: Any) -> dict:
    return {**OFF_TEX, "enabled": True, "seed": seed, **kw}


def case_dot3_modulate_fog(numeric: str, seed: int) -> dict:
    """Two units, DOT3_RGBA of a normal map and the primary colour, then MODULATE; EXP2 fog."""
    s = base_state()
    s["tex0"] = tex(seed, log_w=4, log_h=4, min=C.GL_LINEAR, mag=C.GL_LINEAR)
    s["env0"] = {**OFF_ENV, "mode": C.GL_COMBINE, "rgb": C.GL_DOT3_RGBA, "rgb_scale": 2.0,
                 "src_rgb": (C.GL_TEXTURE, C.GL_PRIMARY_COLOR, C.GL_CONSTANT)}
    s["tex1"] = tex(seed + 1, format=(C.GL_RGB, C.GL_UNSIGNED_BYTE), log_w=3, log_h=5,
                    wrap_s=C.GL_MIRRORED_REPEAT_OES)
    s["env1"] = {**OFF_ENV, "mode": C.GL_MODULATE}
    s["tc1"] = {"kind": "array4", "seed": seed + 7, "matrix": seed}
    s["fog"] = {"on": True, "mode": C.GL_EXP2, "start": 0.0, "end": 1.0, "density": 0.6,
                "color": (0.2, 0.4, 0.9, 1.0), "hint": (C.GL_FASTEST, C.GL_NICEST)[seed % 2]}
    s["depth"] = {"on": True, "func": C.GL_LESS, "mask": True, "range": None}
    return make_scene(numeric, seed, s)


def case_alpha_additive_xor(numeric: str, seed: int) -> dict:
    """Alpha test, additive blending and the XOR logic op (which replaces blending)."""
    s = base_state()
    s["alpha"] = {"on": True, "func": C.GL_GREATER, "ref": 0.3}
    s["blend"] = {"on": True, "func": (C.GL_ONE, C.GL_ONE), "separate": None, "equation": None}
    s["logic"] = {"on": True, "op": C.GL_XOR}
    # then the logic op off: plain additive blending after the alpha test
    return make_scene(numeric, seed, s, changes={"logic": {"on": False, "op": C.GL_XOR}}, triangles=10)


def case_stencil_equal_multipass(numeric: str, seed: int) -> dict:
    """Pass 1 writes the stencil only (colour masked off); pass 2 draws where it is EQUAL."""
    s = base_state()
    s["color_mask"] = (False, False, False, False)
    s["stencil"] = {"on": True, "func": C.GL_ALWAYS, "ref": 1 + seed % 3, "value_mask": 0xFF,
                    "write_mask": 0xFF, "ops": (C.GL_KEEP, C.GL_INCR_WRAP_OES, C.GL_REPLACE)}
    s["depth"] = {"on": True, "func": C.GL_LEQUAL, "mask": False, "range": None}
    changes = {
        "color_mask": ALL_ON,
        "stencil": {"on": True, "func": C.GL_EQUAL, "ref": 1 + seed % 3, "value_mask": 0xFF,
                    "write_mask": 0xFF, "ops": (C.GL_KEEP, C.GL_DECR_WRAP_OES, C.GL_KEEP)},
        "tex0": tex(seed, format=(C.GL_LUMINANCE_ALPHA, C.GL_UNSIGNED_BYTE), min=C.GL_LINEAR),
    }
    return make_scene(numeric, seed, s, changes=changes, triangles=10)


def case_trilinear_fog_depth(numeric: str, seed: int) -> dict:
    """LINEAR_MIPMAP_LINEAR over a full uploaded chain, projective coordinates, LINEAR fog, depth LEQUAL."""
    s = base_state()
    s["tex0"] = tex(seed, log_w=6, log_h=5, mip="full", min=C.GL_LINEAR_MIPMAP_LINEAR, mag=C.GL_LINEAR,
                    wrap_t=C.GL_CLAMP_TO_EDGE)
    s["tc0"] = {"kind": "array4", "seed": seed, "matrix": None}
    s["fog"] = {"on": True, "mode": C.GL_LINEAR, "start": 0.5, "end": 3.5, "density": 1.0,
                "color": (0.9, 0.8, 0.1, 0.5), "hint": (C.GL_NICEST, C.GL_FASTEST)[seed % 2]}
    s["depth"] = {"on": True, "func": C.GL_LEQUAL, "mask": True, "range": None}
    return make_scene(numeric, seed, s)


def case_rgb565_dither_blend(numeric: str, seed: int) -> dict:
    """RGB565 with dither and SRC_ALPHA blending over a REPLACE texture."""
    s = base_state()
    s["dither"] = True
    s["blend"] = {"on": True, "func": (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), "separate": None,
                  "equation": None}
    s["tex0"] = tex(seed, mip="generate", min=C.GL_NEAREST_MIPMAP_LINEAR)
    s["env0"] = {**OFF_ENV, "mode": C.GL_REPLACE}
    s["depth"] = {"on": True, "func": C.GL_LESS, "mask": True, "range": None}
    return make_scene(numeric, seed, s, color="rgb565", depth_bits=16)


def case_rgba4444_dither_blend(numeric: str, seed: int) -> dict:
    """RGBA4444 with dither (alpha too) and ONE_MINUS_DST_ALPHA blending over a MODULATE
    texture, so the stored 4-bit alpha is read back."""
    s = base_state()
    s["dither"] = True
    s["blend"] = {"on": True, "func": (C.GL_ONE_MINUS_DST_ALPHA, C.GL_DST_ALPHA), "separate": None,
                  "equation": None}
    s["tex0"] = tex(seed, mip="generate", min=C.GL_LINEAR_MIPMAP_NEAREST)
    s["env0"] = {**OFF_ENV, "mode": C.GL_MODULATE}
    s["depth"] = {"on": True, "func": C.GL_LESS, "mask": True, "range": None}
    return make_scene(numeric, seed, s, color="rgba4444", depth_bits=16)


def case_rgba5551_logic_op(numeric: str, seed: int) -> dict:
    """RGBA5551 with dither and an XOR logic op on the stored bits, then blending."""
    s = base_state()
    s["dither"] = True
    s["logic"] = {"on": True, "op": C.GL_XOR}
    s["blend"] = {"on": True, "func": (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), "separate": None,
                  "equation": None}
    return make_scene(numeric, seed, s, changes={"logic": {"on": False, "op": C.GL_XOR}}, color="rgba5551",
                      triangles=10)


def case_four_unit_crossbar(numeric: str, seed: int) -> dict:
    """Four COMBINE units reading each other's textures, two of them mipmapped, non-identity
    texture matrices."""
    s = base_state()
    funcs = (C.GL_INTERPOLATE, C.GL_ADD_SIGNED, C.GL_SUBTRACT, C.GL_DOT3_RGB)
    for u in range(UNITS):
        fmt = TEX_FORMATS[(seed + u) % len(TEX_FORMATS)]
        # units 1 and 3 mipmapped (a level of detail on units after the first)
        s[f"tex{u}"] = tex(seed * 4 + u, format=fmt, log_w=u + 1, log_h=3, mag=C.GL_LINEAR,
                           min=C.GL_LINEAR_MIPMAP_NEAREST if u % 2 else C.GL_LINEAR, mip="generate")
        s[f"env{u}"] = {**OFF_ENV, "mode": C.GL_COMBINE, "rgb": funcs[u], "alpha": C.GL_ADD,
                        "src_rgb": (C.GL_TEXTURE0 + (u + 1) % UNITS, C.GL_PREVIOUS,
                                    C.GL_TEXTURE0 + (u + 3) % UNITS),
                        "src_alpha": (C.GL_TEXTURE, C.GL_TEXTURE0 + (u + 2) % UNITS, C.GL_CONSTANT),
                        "color": (0.3, 0.6, 0.9, 0.4), "rgb_scale": SCALES[u % 3], "alpha_scale": 2.0}
        s[f"tc{u}"] = {"kind": TEXCOORDS[u], "seed": seed + u, "matrix": seed + u if u % 2 else None}
    return make_scene(numeric, seed, s)


def case_offset_stencil_wrap(numeric: str, seed: int) -> dict:
    """Polygon offset under depth LEQUAL, then another offset under EQUAL; stencil wrapping ops."""
    s = base_state()
    s["offset"] = {"on": True, "factor": 1.5, "units": -2.0}
    s["depth"] = {"on": True, "func": C.GL_LEQUAL, "mask": True, "range": (0.1, 0.9)}
    s["stencil"] = {"on": True, "func": C.GL_NOTEQUAL, "ref": 3, "value_mask": 0x0F, "write_mask": 0xF3,
                    "ops": (C.GL_INCR_WRAP_OES, C.GL_DECR_WRAP_OES, C.GL_INVERT)}
    changes = {"offset": {"on": True, "factor": -1.0, "units": 4.0},
               "depth": {"on": True, "func": C.GL_EQUAL, "mask": False, "range": (0.1, 0.9)}}
    return make_scene(numeric, seed, s, changes=changes, triangles=10)


def case_wide_alpha_test(numeric: str, seed: int) -> dict:
    """Rows of WIDE pixels (three chunks of the chain) through a LUMINANCE_ALPHA
    texture, the alpha test (so depth and stencil come after it), depth LESS and stencil."""
    s = base_state()
    s["tex0"] = tex(seed, format=(C.GL_LUMINANCE_ALPHA, C.GL_UNSIGNED_BYTE), log_w=5, log_h=2,
                    min=C.GL_LINEAR, mag=C.GL_NEAREST)
    s["alpha"] = {"on": True, "func": C.GL_GEQUAL, "ref": 0.4}
    s["depth"] = {"on": True, "func": C.GL_LESS, "mask": True, "range": None}
    s["stencil"] = {"on": True, "func": C.GL_ALWAYS, "ref": 0, "value_mask": 0xFF, "write_mask": 0xFF,
                    "ops": (C.GL_KEEP, C.GL_KEEP, C.GL_INCR)}
    return make_scene(numeric, seed, s, changes={"stencil": {**s["stencil"], "on": False}},
                      size=(WIDE, 6), persp=False, triangles=10)


def case_mipmap_after_stencil(numeric: str, seed: int) -> dict:
    """LINEAR_MIPMAP_LINEAR over rows of WIDE pixels where an early stencil test
    (EQUAL to what a first pass counted) leaves scattered fragments: the level of
    detail's neighbour weights, found again or taken from the row below, for slots
    that are not neighbours, across chunks and overlapping triangles."""
    s = base_state()
    s["color_mask"] = (False, False, False, False)
    # the first pass flips bit 0 under each triangle; the second draws where it is set
    s["stencil"] = {"on": True, "func": C.GL_ALWAYS, "ref": 0, "value_mask": 0xFF, "write_mask": 0x01,
                    "ops": (C.GL_KEEP, C.GL_INVERT, C.GL_INVERT)}
    changes = {
        "color_mask": ALL_ON,
        "stencil": {"on": True, "func": C.GL_EQUAL, "ref": 1, "value_mask": 0x01, "write_mask": 0xFF,
                    "ops": (C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)},
        "tex0": tex(seed, log_w=6, log_h=5, mip="full", min=C.GL_LINEAR_MIPMAP_LINEAR, mag=C.GL_LINEAR),
        "tc0": {"kind": "array4", "seed": seed, "matrix": None},
    }
    return make_scene(numeric, seed, s, changes=changes, size=(WIDE, 40), triangles=24)


def case_modulate_alpha_test_blend(numeric: str, seed: int) -> dict:
    """A lone MODULATE unit (an RGBA texture, RGB on odd seeds), the alpha test and each
    RGBA8888 blend the fused MODULATE + write stage takes (none, SRC_ALPHA /
    ONE_MINUS_SRC_ALPHA, ONE / ONE), smooth or flat (seeds 2, 3), over rows of WIDE
    pixels; then another blend without the alpha test, under an early depth test."""
    s = base_state()
    s["smooth"] = seed < 2
    s["tex0"] = tex(seed, format=(C.GL_RGB if seed % 2 else C.GL_RGBA, C.GL_UNSIGNED_BYTE), log_w=5, log_h=3,
                    min=C.GL_LINEAR, mag=C.GL_LINEAR)
    blends = ({"on": False, "func": (C.GL_ONE, C.GL_ZERO), "separate": None, "equation": None},
              {"on": True, "func": (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), "separate": None,
               "equation": None},
              {"on": True, "func": (C.GL_ONE, C.GL_ONE), "separate": None, "equation": None})
    s["alpha"] = {"on": True, "func": FUNCS[(3 * seed + 1) % 7], "ref": 0.45}
    s["blend"] = blends[seed % 3]
    changes = {"alpha": {"on": False, "func": C.GL_ALWAYS, "ref": 0.0}, "blend": blends[(seed + 1) % 3],
               "depth": {"on": True, "func": C.GL_LESS, "mask": True, "range": None}}
    return make_scene(numeric, seed, s, changes=changes, size=(WIDE, 12), triangles=12)


def case_modulate_rgb565(numeric: str, seed: int) -> dict:
    """The fused MODULATE + write stage on RGB565: dithered (odd seeds) or the top bits,
    no blend or SRC_ALPHA / ONE_MINUS_SRC_ALPHA, the alpha test on seed 2; then dither
    and blend switched."""
    s = base_state()
    s["dither"] = bool(seed % 2)
    fmt = (C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4) if seed == 3 else (C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    s["tex0"] = tex(seed, format=fmt, log_w=4, log_h=4, min=C.GL_LINEAR, mag=C.GL_NEAREST)
    off = {"on": False, "func": (C.GL_ONE, C.GL_ZERO), "separate": None, "equation": None}
    alpha = {"on": True, "func": (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA), "separate": None,
             "equation": None}
    s["blend"] = alpha if seed < 2 else off
    if seed == 2:
        s["alpha"] = {"on": True, "func": C.GL_GEQUAL, "ref": 0.5}
    changes = {"dither": not s["dither"], "blend": off if seed < 2 else alpha}
    return make_scene(numeric, seed, s, changes=changes, color="rgb565", depth_bits=16, size=(WIDE, 12),
                      triangles=12)


CASES = {f.__name__[5:]: f for f in (case_dot3_modulate_fog, case_alpha_additive_xor,
                                     case_stencil_equal_multipass, case_trilinear_fog_depth,
                                     case_rgb565_dither_blend, case_four_unit_crossbar,
                                     case_offset_stencil_wrap, case_wide_alpha_test,
                                     case_mipmap_after_stencil, case_modulate_alpha_test_blend,
                                     case_modulate_rgb565, case_rgba4444_dither_blend,
                                     case_rgba5551_logic_op)}


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("case", sorted(CASES))
def test_hand_picked_states_match_generic(case, numeric):
    """Named combinations of stages, each over four seeds (geometry, textures, projection)."""
    for seed in range(4):
        check_scene(CASES[case](numeric, seed))


# {================================================================
# each command between two draws


def start_states() -> dict[str, tuple[dict, dict]]:
    """States whose span functions are special (fused spans, or chain stages picked for
    them), as (state, scene options); a command that changes what they depend on must
    make the next draw pick again."""
    plain = base_state()
    plain["depth"] = {"on": True, "func": C.GL_LESS, "mask": True, "range": None}
    alpha = {**plain, "blend": {"on": True, "func": (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA),
                                "separate": None, "equation": None}}
    add = {**plain, "blend": {**alpha["blend"], "func": (C.GL_ONE, C.GL_ONE)}}
    textured = {**plain, "tex0": tex(5, log_w=4, log_h=3, mip="full", min=C.GL_LINEAR, mag=C.GL_LINEAR),
                "tex1": {**tex(6, format=(C.GL_RGB, C.GL_UNSIGNED_BYTE)), "enabled": False},
                "tc1": {"kind": "array4", "seed": 9, "matrix": None}}
    two = {**textured, "tex1": {**textured["tex1"], "enabled": True},
           "env1": {**OFF_ENV, "mode": C.GL_ADD}, "blend": alpha["blend"]}
    return {"plain": (plain, {}), "alpha_blend": (alpha, {}), "add_blend": (add, {}),
            "textured": (textured, {}), "two_units": (two, {}),
            "rgb565": ({**plain, "dither": True}, {"color": "rgb565"}),
            "rgba4444": ({**alpha, "dither": True}, {"color": "rgba4444"}),
            "rgba5551": ({**alpha, "dither": True}, {"color": "rgba5551"})}


# each: one or more commands, a draw after each
COMMANDS = {
    "DepthFunc": [("DepthFunc", C.GL_ALWAYS), ("DepthFunc", C.GL_LESS), ("DepthFunc", C.GL_GEQUAL)],
    "DepthMask": [("DepthMask", False), ("DepthMask", True)],
    "ColorMask": [("ColorMask", (True, False, True, True)), ("ColorMask", ALL_ON)],
    "ShadeModel": [("ShadeModel", C.GL_FLAT), ("ShadeModel", C.GL_SMOOTH)],
    "depth_test": [("Enable", C.GL_DEPTH_TEST, False), ("Enable", C.GL_DEPTH_TEST, True)],
    "blend": [("Enable", C.GL_BLEND, True), ("Enable", C.GL_BLEND, False)],
    "BlendFunc": [("Enable", C.GL_BLEND, True), ("BlendFunc", C.GL_ONE, C.GL_ONE),
                  ("BlendFunc", C.GL_DST_COLOR, C.GL_ZERO),
                  ("BlendFunc", C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)],
    "BlendFuncSeparateOES": [("Enable", C.GL_BLEND, True),
                             ("BlendFuncSeparateOES", C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA, C.GL_ONE,
                              C.GL_ZERO),
                             ("BlendFuncSeparateOES", C.GL_ONE, C.GL_ONE, C.GL_ONE, C.GL_ONE)],
    "BlendEquationOES": [("Enable", C.GL_BLEND, True), ("BlendEquationOES", C.GL_FUNC_REVERSE_SUBTRACT_OES),
                         ("BlendEquationOES", C.GL_FUNC_ADD_OES)],
    "BlendEquationSeparateOES": [("Enable", C.GL_BLEND, True),
                                 ("BlendEquationSeparateOES", C.GL_FUNC_ADD_OES, C.GL_FUNC_SUBTRACT_OES)],
    "LogicOp": [("Enable", C.GL_COLOR_LOGIC_OP, True), ("LogicOp", C.GL_XOR), ("LogicOp", C.GL_COPY),
                ("Enable", C.GL_COLOR_LOGIC_OP, False)],
    "AlphaFunc": [("Enable", C.GL_ALPHA_TEST, True), ("AlphaFunc", C.GL_GREATER, 0.5),
                  ("AlphaFunc", C.GL_ALWAYS, 0.0), ("Enable", C.GL_ALPHA_TEST, False)],
    "stencil": [("Enable", C.GL_STENCIL_TEST, True), ("StencilOp", C.GL_KEEP, C.GL_INCR, C.GL_INVERT),
                ("StencilFunc", C.GL_LEQUAL, 1, 0xFF), ("StencilMask", 0x0F),
                ("Enable", C.GL_STENCIL_TEST, False)],
    "fog": [("Enable", C.GL_FOG, True), ("FogHint", C.GL_NICEST), ("Fogf", C.GL_FOG_MODE, C.GL_LINEAR),
            ("Fogf", C.GL_FOG_END, 2.0), ("FogHint", C.GL_FASTEST), ("Enable", C.GL_FOG, False)],
    "dither": [("Enable", C.GL_DITHER, False), ("Enable", C.GL_DITHER, True)],
    "scissor": [("Enable", C.GL_SCISSOR_TEST, True), ("Enable", C.GL_SCISSOR_TEST, False)],
    "PolygonOffset": [("Enable", C.GL_POLYGON_OFFSET_FILL, True), ("PolygonOffset", 2.0, 4.0),
                      ("Enable", C.GL_POLYGON_OFFSET_FILL, False)],
    "TexEnable": [("TexEnable", 0, False), ("TexEnable", 0, True), ("TexEnable", 1, True),
                  ("TexEnable", 1, False)],
    "min_filter": [("TexParameteri", 0, (C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)),
                   ("TexParameteri", 0, (C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)),
                   ("TexParameteri", 0, (C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR))],
    "mag_filter": [("TexParameteri", 0, (C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)),
                   ("TexParameteri", 0, (C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR))],
    "wrap": [("TexParameteri", 0, (C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)),
             ("TexParameteri", 0, (C.GL_TEXTURE_WRAP_T, C.GL_MIRRORED_REPEAT_OES))],
    "TexImage2D": [("TexImage2D", 0, (C.GL_RGB, C.GL_UNSIGNED_BYTE), 2, 5, 1),
                   ("TexImage2D", 0, (C.GL_ALPHA, C.GL_UNSIGNED_BYTE), 4, 3, 2)],
    "TexSubImage2D": [("TexSubImage2D", 0, 3), ("TexSubImage2D", 1, 4)],
    "BindTexture": [("BindTexture", 0, 1), ("BindTexture", 1, 0)],
    "DeleteTextures": [("DeleteTextures", 1), ("DeleteTextures", 0)],
    "TexEnvi": [("TexEnvi", 0, (C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)),
                ("TexEnvi", 0, (C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)),
                ("TexEnvi", 0, (C.GL_COMBINE_RGB, C.GL_DOT3_RGBA)),
                ("TexEnvi", 0, (C.GL_SRC1_RGB, C.GL_TEXTURE1)),
                ("TexEnvi", 0, (C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE))],
    "TexEnvColor": [("TexEnvi", 0, (C.GL_TEXTURE_ENV_MODE, C.GL_BLEND)), ("TexEnvColor", 0, (1, 0.5, 0, 1))],
}


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_each_command_between_draws(command):
    """From each start state, the commands of `command` with a draw after each: the
    buffers match the forced generic path's after every change."""
    steps = COMMANDS[command]
    for i, (name, (state, opts)) in enumerate(sorted(start_states().items())):
        scene = make_scene(BUILDS[i % len(BUILDS)], i, state, crossbar_to_off=True, steps=steps,
                           triangles=3 * len(steps) + 3, **opts)
        try:
            check_scene(scene)
        except AssertionError as e:
            raise AssertionError(f"from the state {name!r}: {e}") from None


# {================================================================
# the path names


def test_max_texture_units():
    """The strategy covers every unit there is."""
    assert make_ctx("fixed", 8, 8).gl.glGetIntegerv(C.GL_MAX_TEXTURE_UNITS) == UNITS


def test_forced_path_is_generic_and_the_other_is_named():
    """With debug(1) every draw reports "generic"; without it any name goes, but the
    plainest states (nothing on but colour writes, with or without one texture) do not
    all run the generic path, so the comparisons above compare two different paths."""
    unforced = []
    for smooth in (False, True):
        for textured in (False, True):
            s = base_state()
            s["smooth"] = smooth
            if textured:
                s["tex0"] = tex(3)
            scene = make_scene("fixed", 2, s, changes={"smooth": not smooth}, depth_bits=0)
            ref = render(scene, generic=True)
            out = render(scene, generic=False)
            assert ref["paths"] == ["generic", "generic"]
            assert all(isinstance(p, str) and p for p in out["paths"])
            unforced += out["paths"]
    assert set(unforced) != {"generic"}, unforced


# {================================================================
# the level of detail's tangents under extreme perspective


def _extreme_perspective_slivers(numeric: str, flags: int, seed: int, tc_range: float = 4.0) -> np.ndarray:
    """Thin mipmapped triangles whose vertices' w differ by up to 2^20 (clip
    coordinates sent as they are): the weights' tangents there are large
    and their terms cancel near the far vertices. Texture coordinates in
    +-tc_range. `flags` for ctx.debug (1: the per-fragment reference, 32:
    the AVX2 instance)."""
    rng = np.random.default_rng(seed)
    w, h = 48, 16
    ctx = make_ctx(numeric, w, h)
    gl = ctx.gl
    ctx.debug(flags)
    size = 32
    gl.glBindTexture(C.GL_TEXTURE_2D, int(gl.glGenTextures(1)))
    level = 0
    while size >= 1:
        img = rng.integers(0, 256, (size, size, 4), dtype=np.uint8)
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, C.GL_RGBA, size, size, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        size //= 2
        level += 1
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    verts, tcs = [], []
    for _ in range(40):
        # a row or two high, up to the window wide, w from 1 to 2^20 per vertex
        y = rng.uniform(1, h - 3)
        xs = rng.uniform(0, w, 3)
        ys = np.array([y, y + rng.uniform(0.5, 2.5), y + rng.uniform(0, 2.5)])
        ws = 2.0 ** rng.uniform(0, 20, 3)
        ws[rng.integers(0, 3)] = 1.0
        for x_w, y_w, wv in zip(xs, ys, ws):
            verts.append([(2 * x_w / w - 1) * wv, (2 * y_w / h - 1) * wv, 0.0, wv])
        tcs += rng.uniform(-tc_range, tc_range, (3, 2)).tolist()
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(4, C.GL_FLOAT, 0, np.ascontiguousarray(verts, dtype=np.float32))
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.ascontiguousarray(tcs, dtype=np.float32))
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(verts))
    assert gl.glGetError() == C.GL_NO_ERROR
    return ctx.color_buffer()


@pytest.mark.parametrize("numeric", BUILDS)
def test_lod_tangents_of_extreme_perspective_match_generic(numeric):
    """The weights' tangents and the coordinates at them, where vertices' w differ
    by up to 2^20 on thin triangles, equal the per-fragment reference's bit
    for bit."""
    for seed in range(3):
        chain = _extreme_perspective_slivers(numeric, 0, seed)
        assert (chain != chain[0, 0]).any(), "nothing drawn"
        ref = _extreme_perspective_slivers(numeric, 1, seed)
        np.testing.assert_array_equal(chain, ref, err_msg=f"seed {seed}")
        if has_avx512(numeric):
            np.testing.assert_array_equal(_extreme_perspective_slivers(numeric, 32, seed), ref,
                                          err_msg=f"AVX2, seed {seed}")


@pytest.mark.parametrize("numeric", BUILDS)
def test_lod_coordinates_far_apart_match_generic(numeric):
    """Texture coordinates up to +-30000 apart on one triangle (in the fixed
    build, differences past the int32 range of 16.16, which the stage's
    shorter form of the coordinates at the tangents does not take) equal the
    per-fragment reference's bit for bit."""
    for seed in range(2):
        chain = _extreme_perspective_slivers(numeric, 0, seed, 30000.0)
        assert (chain != chain[0, 0]).any(), "nothing drawn"
        np.testing.assert_array_equal(chain, _extreme_perspective_slivers(numeric, 1, seed, 30000.0),
                                      err_msg=f"seed {seed}")


# {================================================================
# perspective planes with a level of detail: every instance of the stage


def _mip_chain(gl: Any, rng: np.random.Generator, ramps: bool = False) -> None:
    """A full chain of random 64x64..1x1 RGBA levels into the bound texture;
    with ramps, a green ramp over the top half and an alpha ramp over the
    left half of each level (channels slowly varying over many fragments)."""
    size, level = 64, 0
    while size >= 1:
        img = rng.integers(0, 256, (size, size, 4), dtype=np.uint8)
        if ramps:
            texels = size * size
            ramp = (np.arange(texels).reshape(size, size) * 255 // max(texels - 1, 1)).astype(np.uint8)
            img[: size // 2, :, 1] = ramp[: size // 2]
            img[:, : size // 2, 3] = 255 - ramp[:, : size // 2]
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, C.GL_RGBA, size, size, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        size //= 2
        level += 1


def _look_at_ground(gl: Any, pitch: float, yaw: float) -> None:
    """The modelview of a view 1.5 above the ground plane, pitched down and yawed."""
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glRotatef(pitch, 1.0, 0.0, 0.0)
    gl.glTranslatef(0.0, -1.5, 0.0)
    gl.glRotatef(yaw, 0.0, 1.0, 0.0)


def _ground_view(gl: Any, w: int, h: int, half_h: float, pitch: float, yaw: float) -> None:
    """The viewport, a frustum 1.2 wide and 2 half_h high at the near plane 1 (far 400), and the view."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumf(-0.6, 0.6, -half_h, half_h, 1.0, 400.0)
    _look_at_ground(gl, pitch, yaw)


def _ground_grid(n: int = 9) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """An n x n grid on y = 0 from x = -80 to 80 and z = -1 to -200: x, z, the
    vertices and the triangles' indices."""
    xs, zs = np.meshgrid(np.linspace(-80.0, 80.0, n), np.linspace(-1.0, -200.0, n))
    verts = np.stack([xs, np.zeros_like(xs), zs], axis=-1).reshape(-1, 3)
    i = np.arange(n - 1)
    a = (i[:, None] * n + i[None, :]).reshape(-1)
    idx = np.stack([a, a + 1, a + n, a + 1, a + n + 1, a + n], -1).reshape(-1).astype(np.uint16)
    return xs, zs, verts, idx


def _mipmapped_plane(numeric: str, flags: int, case: str) -> np.ndarray:
    """A 160x96 view of a mipmapped ground plane to the horizon, yawed and
    pitched so that w changes along each row: rows of up to 160 fragments,
    whose groups of eight or four go through the vector kernels of the
    weights' division and tangents. `case`: "st" (the unit's coordinates
    formed with the weights), "q" (a projective unit: the tangents'
    weights stored instead), "two" (a second unit beside the one with the
    level of detail), "depth" (a depth test dropping fragments, so that
    slots are not the offsets), "fog" (linear fog from the vertices'
    distances, mixed in the fog stage's groups), "fog565" and
    "fog565_nodither" (that fog on an RGB565 target, dithered or not: the
    fog and the write in one pass where AVX-512 runs), "replace_fog" and
    "replace_fog_depth" (a REPLACE environment under that fog, with and
    without the depth test: the texels fogged and written in one stage
    where AVX2 runs without AVX-512)."""
    w, h = 160, 96
    color = "rgb565" if case.startswith("fog565") else "rgba8888"
    depth = case.endswith("depth")
    ctx = make_ctx(numeric, w, h, depth=24 if depth else 0, color=color)
    gl = ctx.gl
    ctx.debug(flags)
    if case == "fog565_nodither":
        gl.glDisable(C.GL_DITHER)
    rng = np.random.default_rng(7)
    gl.glClearColor(0.1, 0.2, 0.3, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | (C.GL_DEPTH_BUFFER_BIT if depth else 0))
    units = (0, 1) if case == "two" else (0,)
    for unit in units:
        gl.glActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glBindTexture(C.GL_TEXTURE_2D, int(gl.glGenTextures(1)))
        _mip_chain(gl, rng)
        minf = C.GL_LINEAR_MIPMAP_LINEAR if unit == 0 else C.GL_LINEAR
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, minf)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
        gl.glEnable(C.GL_TEXTURE_2D)
        env = C.GL_REPLACE if case.startswith("replace") else C.GL_MODULATE
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, env)
    gl.glActiveTexture(C.GL_TEXTURE0)
    if "fog" in case:
        gl.glEnable(C.GL_FOG)
        gl.glFogf(C.GL_FOG_MODE, C.GL_LINEAR)
        gl.glFogf(C.GL_FOG_START, 3.0)
        gl.glFogf(C.GL_FOG_END, 170.0)
        gl.glFogfv(C.GL_FOG_COLOR, [0.55, 0.65, 0.8, 1.0])
    _ground_view(gl, w, h, 0.36, 9.0, 17.0)
    xs, zs, verts, idx = _ground_grid()
    n = xs.shape[0]
    q = 1.0 + 0.5 * rng.random(n * n) if case == "q" else np.ones(n * n)
    st = np.stack([xs.ravel() / 3.0, -zs.ravel() / 3.0], axis=-1)
    tc = np.concatenate([st * q[:, None], np.zeros((n * n, 1)), q[:, None]], axis=-1)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, np.ascontiguousarray(verts, dtype=np.float32))
    for unit in units:
        gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(4, C.GL_FLOAT, 0, np.ascontiguousarray(tc * (1 + unit), dtype=np.float32))
    if depth:
        # a nearer tilted quad first, so that the plane's rows lose fragments to the depth test
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDisable(C.GL_TEXTURE_2D)
        gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
        quad = np.array([[-3, -1.4, -6], [1, -1.4, -3], [-3, 2, -6], [1, 2, -3]], np.float32)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, quad)
        for _ in range(6):
            gl.glTranslatef(1.3, 0.0, -1.0)
            gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        _look_at_ground(gl, 9.0, 17.0)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, np.ascontiguousarray(verts, dtype=np.float32))
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
    assert gl.glGetError() == C.GL_NO_ERROR
    return ctx.color_buffer()


def _fogged_texels(seed: int, flags: int, numeric: str = "fixed") -> np.ndarray:
    """A perspective plane of a lone REPLACE unit under fog, the state where
    the fixed and double builds' AVX2 instances fog and write the texels in
    float lanes and prove each byte (the rest by the exact stages): random
    texels, smooth ramps among them (channels near a byte's rounding point
    over many fragments), every filter pair with GL_LINEAR in it, REPEAT or
    CLAMP_TO_EDGE, a random fog colour, and fog ranges whose vertex factors
    lie within [-2, 2] or (seed % 3 == 2) past it; a depth test drops some
    of each row's fragments. Seeds from 8 on draw to RGB565, dithered
    below 12."""
    rng = np.random.default_rng(1000 + seed)
    w, h = 256, 144
    ctx = make_ctx(numeric, w, h, depth=24, color="rgb565" if seed >= 8 else "rgba8888")
    gl = ctx.gl
    ctx.debug(flags)
    if seed >= 12:
        gl.glDisable(C.GL_DITHER)
    gl.glClearColor(0.0, 0.0, 0.0, 0.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glBindTexture(C.GL_TEXTURE_2D, int(gl.glGenTextures(1)))
    _mip_chain(gl, rng, ramps=True)
    filters = [(C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR), (C.GL_LINEAR_MIPMAP_NEAREST, C.GL_LINEAR),
               (C.GL_LINEAR_MIPMAP_LINEAR, C.GL_NEAREST), (C.GL_NEAREST_MIPMAP_LINEAR, C.GL_LINEAR)]
    minf, magf = filters[seed % 4]
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, minf)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, magf)
    wrap = C.GL_REPEAT if seed % 2 == 0 else C.GL_CLAMP_TO_EDGE
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, wrap)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, wrap)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glEnable(C.GL_FOG)
    gl.glFogf(C.GL_FOG_MODE, C.GL_LINEAR)
    start, end = (1.0, 150.0) if seed % 3 != 2 else (60.0, 90.0)    # (the latter: factors past [-2, 2])
    gl.glFogf(C.GL_FOG_START, start)
    gl.glFogf(C.GL_FOG_END, end)
    gl.glFogfv(C.GL_FOG_COLOR, [*rng.random(3).tolist(), 1.0])
    gl.glEnable(C.GL_DEPTH_TEST)
    pitch = float(rng.uniform(5, 12))
    _ground_view(gl, w, h, 0.35, pitch, float(rng.uniform(-30, 30)))
    xs, zs, verts, idx = _ground_grid()
    scale = float(rng.uniform(1.5, 6.0))
    st = np.stack([xs.ravel() / scale, -zs.ravel() / scale], axis=-1)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    # posts in front of the plane, drawn first: the depth test drops parts of its rows
    gl.glDisable(C.GL_TEXTURE_2D)
    for _ in range(5):
        x0, z0 = rng.uniform(-8, 8), rng.uniform(-30, -4)
        post = np.array([[x0, 0, z0], [x0 + 0.7, 0, z0], [x0, 4, z0], [x0 + 0.7, 4, z0]], np.float32)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, post)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.zeros((4, 2), np.float32))
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, np.ascontiguousarray(verts, dtype=np.float32))
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.ascontiguousarray(st, dtype=np.float32))
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
    assert gl.glGetError() == C.GL_NO_ERROR
    return ctx.color_buffer()


@pytest.mark.parametrize("numeric", ["fixed", "double"])
@pytest.mark.parametrize("seed", range(16))
def test_fogged_texels_in_float_lanes_match_generic(seed, numeric):
    """The fog and write of a REPLACE unit's texels in float lanes (each
    byte proved, else the exact stages) draws the per-fragment reference's
    bits, and so do the AVX2 and baseline instances, in the fixed build and
    in the double build (whose texels' indices and weights are its exact
    sampler's double values)."""
    ref = _fogged_texels(seed, 1, numeric)
    covered = ref != ref[0, 0] if ref.ndim == 2 else (ref != ref[0, 0]).any(axis=-1)
    assert covered.mean() > 0.5, "the plane covers little"
    for name, flags in (("chain", 0), ("avx2", 32), ("baseline", 16)):
        np.testing.assert_array_equal(_fogged_texels(seed, flags, numeric), ref, err_msg=f"{name}, {seed}")


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("case", ["st", "q", "two", "depth", "fog", "fog565", "fog565_nodither",
                                  "replace_fog", "replace_fog_depth"])
def test_mipmapped_plane_matches_generic_on_every_instance(numeric, case):
    """Each instance of the chain (the best this CPU runs, AVX2, the baseline)
    draws the plane with the per-fragment reference's bits."""
    ref = _mipmapped_plane(numeric, 1, case)
    covered = ref != ref[0, 0] if ref.ndim == 2 else (ref != ref[0, 0]).any(axis=-1)
    assert covered.mean() > 0.4, "the plane covers little"
    for name, flags in (("chain", 0), ("avx2", 32), ("baseline", 16)):
        np.testing.assert_array_equal(_mipmapped_plane(numeric, flags, case), ref, err_msg=name)
