"""A stateful fuzzer of the GL ES 1.1 commands.

    python tools/fuzz.py --minutes N --seed S      # seeds S, S+1, ... for N minutes
    python tools/fuzz.py --seeds 0:200             # a fixed seed range (CI)
    python tools/fuzz.py --replay 123              # one sequence, in this process
    python tools/fuzz.py --backend cabi ...        # the same through the C ABI

Each seed makes one context (random build, profile, colour format, depth and
stencil bits, size, range-check policy and memory limit) and a sequence of
random calls of every command of its profile. Values come from classes:
valid and invalid enums; ints at the edges of their C types and beyond; NaN,
infinities, 1e30, -0.0 and denormals; fixed values near +-2^31; textures of
every format and size (zero sizes, GENERATE_MIPMAP); buffers (deleting a
bound one); arrays of every type and stride; draws with out-of-range counts,
offsets and indices; matrix stacks past their depth.

After every call the invariant must hold: the call returned or raised
GLError, TypeError or ValueError; glGetError returns NO_ERROR or one of the
six error codes; and a call that raised or recorded an error left the state
as it was (a snapshot of queried state, the framebuffer and the memory in
use, compared before and after).

--backend says what runs the calls: "python" (gles.Context, the default),
"checked" (gles.Context with check_errors=True: every GL error must raise
GLError at its call), "cabi" (gles's own libGLESv1_CM and libEGL through
CabiContext below, a ctypes harness that passes only pointers a correct C
program could, and now and then NULL) or "mixed" (one of the three per seed).

Sequences run in worker processes, so a crash or a hang (a call taking more
than --call-timeout seconds) is caught too. A failing sequence is shrunk to
a minimal one that fails the same way and printed as a few lines of Python.
"""

from __future__ import annotations

import argparse
import logging
import math
import os
import pickle
import queue
import random
import re
import subprocess
import sys
import tempfile
import threading
import time
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np

ROOT = Path(__file__).resolve().parent.parent

import gles  # noqa: E402
from gles import constants as C  # noqa: E402
from gles.errors import GLError  # noqa: E402

# a sequence may turn debug output on with the default callback, which logs:
# the handler keeps those records off stderr
logging.getLogger("gles.debug").addHandler(logging.NullHandler())

ERRORS = {
    C.GL_NO_ERROR,
    C.GL_INVALID_ENUM,
    C.GL_INVALID_VALUE,
    C.GL_INVALID_OPERATION,
    C.GL_STACK_OVERFLOW,
    C.GL_STACK_UNDERFLOW,
    C.GL_OUT_OF_MEMORY,
    C.GL_INVALID_FRAMEBUFFER_OPERATION_OES,     # OES_framebuffer_object
}
ALL_ENUMS = sorted({int(getattr(C, n)) for n in C.__all__ if n.startswith("GL_")})
_NAME_OF: dict[int, str] = {}
for _n in C.__all__:
    if _n.startswith("GL_"):
        _NAME_OF.setdefault(int(getattr(C, _n)), _n)

# {====================================================================
# values: (python value, source text)


@dataclass
class Val:
    value: Any
    text: str


def _float_text(x: float) -> str:
    if math.isnan(x):
        return "float('nan')"
    if math.isinf(x):
        return "float('inf')" if x > 0 else "float('-inf')"
    return repr(float(x))


def _list_text(vals: list[Any]) -> str:
    return "[" + ", ".join(_float_text(v) if isinstance(v, float) else repr(v) for v in vals) + "]"


def _array_text(a: np.ndarray) -> str:
    return f"np.array({_list_text(a.tolist())}, dtype=np.{a.dtype})"


INT_EDGES = [0, 1, -1, 2, 7, 2**31 - 1, -(2**31), 2**31, 2**32 - 1, 2**32, -(2**31) - 1, 2**63, 2**15, 65535]
FLOATS = [
    float("nan"),
    float("inf"),
    float("-inf"),
    1e30,
    -1e30,
    -0.0,
    0.0,
    5e-324,
    1e-310,
    1e-40,
    0.5,
    1.0,
    -1.0,
    2.0,
    255.0,
    32768.0,
    1e6,
    3.4e38,
]
FIXED_EDGES = [0, 65536, -65536, 32768, 2**31 - 1, -(2**31), 2**31, -(2**31) - 1, 1, -1, 2**24, 2**16 * 200]


class Gen:
    """Random values by class, from one seeded generator."""

    def __init__(self, rng: random.Random) -> None:
        self.r = rng

    def enum(self, valid: list[int]) -> Val:
        r = self.r.random()
        if valid and r < 0.8:
            v = int(self.r.choice(valid))  # a plain int: sequences are pickled
        elif r < 0.9:
            v = self.r.choice(ALL_ENUMS)
        else:
            v = self.r.choice([0, 1, 0xFFFF, 2**32 - 1, 0x1234, -1, 2**32])
        return Val(v, f"G.{_NAME_OF[v]}" if v in _NAME_OF and v > 1 else repr(v))

    def int(self, lo: int = 0, hi: int = 8) -> Val:
        v = self.r.randint(lo, hi) if self.r.random() < 0.8 else self.r.choice(INT_EDGES)
        return Val(v, repr(v))

    def size(self) -> Val:
        r = self.r.random()
        if r < 0.6:
            v = self.r.choice([0, 1, 2, 4, 8, 16, 32, 64])
        elif r < 0.75:
            v = self.r.choice([3, 5, 128, 256, 2048, 4096])
        else:
            v = self.r.choice(INT_EDGES)
        return Val(v, repr(v))

    def real(self) -> float:
        r = self.r.random()
        if r < 0.6:
            return self.r.choice(
                [self.r.uniform(-2, 2), self.r.uniform(-100, 100), float(self.r.randint(-3, 3))]
            )
        return self.r.choice(FLOATS) * self.r.choice([1, 1, -1])

    def float(self) -> Val:
        v = self.real()
        return Val(v, _float_text(v))

    def fixed_int(self) -> int:
        r = self.r.random()
        if r < 0.6:
            return self.r.randint(-4 * 65536, 4 * 65536)
        return self.r.choice(FIXED_EDGES)

    def fixed(self) -> Val:
        v = self.fixed_int()
        return Val(v, repr(v))

    def bool(self) -> Val:
        v = self.r.choice([True, False, 0, 1, 2])
        return Val(v, repr(v))

    def vec(self, n: int, kind: str) -> Val:
        k = n if self.r.random() < 0.9 else self.r.randint(0, n + 2)
        if kind == "f":
            vals: list[Any] = [self.real() for _ in range(k)]
        elif kind == "x":
            vals = [self.fixed_int() for _ in range(k)]
        else:
            vals = [self.int(-4, 16).value for _ in range(k)]
        if k == 1 and self.r.random() < 0.3:
            v = vals[0]
            return Val(v, _float_text(v) if isinstance(v, float) else repr(v))
        return Val(vals, _list_text(vals))

    def data(self, nbytes: int) -> Val:
        r = self.r.random()
        if r < 0.15:
            return Val(None, "None")
        if r < 0.2:
            v = self.r.choice([0, 4096, 2**40])
            return Val(v, repr(v))
        if r < 0.35:
            nbytes = self.r.randint(0, max(nbytes, 1) * 2)
        nbytes = min(max(nbytes, 0), 1 << 22)
        return Val(bytes(nbytes), f"bytes({nbytes})")

    def array(self, gltype: int, n: int) -> Val:
        dt = {
            C.GL_BYTE: np.int8,
            C.GL_UNSIGNED_BYTE: np.uint8,
            C.GL_SHORT: np.int16,
            C.GL_UNSIGNED_SHORT: np.uint16,
            C.GL_FIXED: np.int32,
            C.GL_FLOAT: np.float32,
        }.get(gltype, np.float32)
        if self.r.random() < 0.1:
            dt = self.r.choice([np.float64, np.int64, np.uint8])
        if np.dtype(dt).kind == "f":
            a = np.array([self.real() for _ in range(n)], dtype=np.float64).astype(dt)
        else:
            info = np.iinfo(dt)
            a = np.array(
                [
                    self.r.choice(
                        [
                            0,
                            1,
                            -1 if info.min else 2,
                            info.min,
                            info.max,
                            self.r.randint(max(info.min, -40), min(info.max, 40)),
                        ]
                    )
                    for _ in range(n)
                ],
                dtype=dt,
            )
        return Val(a, _array_text(a))

    def pointer(self, gltype: int) -> Val:
        r = self.r.random()
        if r < 0.15:
            v = self.r.choice([0, 4, 16, 64, 2**31, 2**63, -4])
            return Val(v, repr(v))
        if r < 0.2:
            return Val(None, "None")
        return self.array(gltype, self.r.choice([0, 1, 3, 8, 16, 32, 64]))


# {====================================================================
# the commands and their argument classes

CAPS = [
    C.GL_ALPHA_TEST,
    C.GL_BLEND,
    C.GL_COLOR_LOGIC_OP,
    C.GL_COLOR_MATERIAL,
    C.GL_CULL_FACE,
    C.GL_DEPTH_TEST,
    C.GL_DITHER,
    C.GL_FOG,
    C.GL_LIGHTING,
    C.GL_LIGHT0,
    C.GL_LIGHT1,
    C.GL_LINE_SMOOTH,
    C.GL_MULTISAMPLE,
    C.GL_NORMALIZE,
    C.GL_POINT_SMOOTH,
    C.GL_POINT_SPRITE_OES,
    C.GL_POLYGON_OFFSET_FILL,
    C.GL_RESCALE_NORMAL,
    C.GL_SAMPLE_ALPHA_TO_COVERAGE,
    C.GL_SAMPLE_ALPHA_TO_ONE,
    C.GL_SAMPLE_COVERAGE,
    C.GL_SCISSOR_TEST,
    C.GL_STENCIL_TEST,
    C.GL_TEXTURE_2D,
    C.GL_CLIP_PLANE0,
    C.GL_MATRIX_PALETTE_OES,
    C.GL_TEXTURE_CUBE_MAP_OES,
    C.GL_TEXTURE_GEN_STR_OES,
    C.GL_DEBUG_OUTPUT_KHR,
    C.GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR,
]
# TexImage2D's targets: TEXTURE_2D and OES_texture_cube_map's faces
IMAGE_T = [C.GL_TEXTURE_2D, C.GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES, C.GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_OES,
           C.GL_TEXTURE_CUBE_MAP_OES]
# BindTexture's and TexParameter's
TEX_T = [C.GL_TEXTURE_2D, C.GL_TEXTURE_CUBE_MAP_OES]
GEN_C = [C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_2D]
GEN_P = [C.GL_TEXTURE_GEN_MODE_OES, C.GL_TEXTURE_MIN_FILTER]
GEN_V = [C.GL_NORMAL_MAP_OES, C.GL_REFLECTION_MAP_OES, 0x2402]
CLIENT = [
    C.GL_VERTEX_ARRAY,
    C.GL_NORMAL_ARRAY,
    C.GL_COLOR_ARRAY,
    C.GL_TEXTURE_COORD_ARRAY,
    C.GL_POINT_SIZE_ARRAY_OES,
    C.GL_MATRIX_INDEX_ARRAY_OES,
    C.GL_WEIGHT_ARRAY_OES,
]
MODES = [
    C.GL_POINTS,
    C.GL_LINES,
    C.GL_LINE_LOOP,
    C.GL_LINE_STRIP,
    C.GL_TRIANGLES,
    C.GL_TRIANGLE_STRIP,
    C.GL_TRIANGLE_FAN,
]
TYPES = [C.GL_BYTE, C.GL_UNSIGNED_BYTE, C.GL_SHORT, C.GL_UNSIGNED_SHORT, C.GL_FIXED, C.GL_FLOAT]
BASE = [C.GL_ALPHA, C.GL_LUMINANCE, C.GL_LUMINANCE_ALPHA, C.GL_RGB, C.GL_RGBA]
PALETTE = list(range(C.GL_PALETTE4_RGB8_OES, C.GL_PALETTE8_RGB5_A1_OES + 1))
PIXTYPES = [
    C.GL_UNSIGNED_BYTE,
    C.GL_UNSIGNED_SHORT_5_6_5,
    C.GL_UNSIGNED_SHORT_4_4_4_4,
    C.GL_UNSIGNED_SHORT_5_5_5_1,
]
FUNCS = list(range(C.GL_NEVER, C.GL_ALWAYS + 1))
FACTORS = [
    C.GL_ZERO,
    C.GL_ONE,
    C.GL_SRC_COLOR,
    C.GL_ONE_MINUS_SRC_COLOR,
    C.GL_SRC_ALPHA,
    C.GL_ONE_MINUS_SRC_ALPHA,
    C.GL_DST_ALPHA,
    C.GL_ONE_MINUS_DST_ALPHA,
    C.GL_DST_COLOR,
    C.GL_ONE_MINUS_DST_COLOR,
    C.GL_SRC_ALPHA_SATURATE,
]
STENCIL_OPS = [
    C.GL_KEEP,
    C.GL_ZERO,
    C.GL_REPLACE,
    C.GL_INCR,
    C.GL_DECR,
    C.GL_INVERT,
    C.GL_INCR_WRAP_OES,
    C.GL_DECR_WRAP_OES,
]
LIGHTS = [C.GL_LIGHT0, C.GL_LIGHT1, C.GL_LIGHT7, C.GL_LIGHT0 + 8]
LIGHT_P = [
    C.GL_AMBIENT,
    C.GL_DIFFUSE,
    C.GL_SPECULAR,
    C.GL_POSITION,
    C.GL_SPOT_DIRECTION,
    C.GL_SPOT_EXPONENT,
    C.GL_SPOT_CUTOFF,
    C.GL_CONSTANT_ATTENUATION,
    C.GL_LINEAR_ATTENUATION,
    C.GL_QUADRATIC_ATTENUATION,
]
MAT_P = [C.GL_AMBIENT, C.GL_DIFFUSE, C.GL_SPECULAR, C.GL_EMISSION, C.GL_SHININESS, C.GL_AMBIENT_AND_DIFFUSE]
FACES = [C.GL_FRONT, C.GL_BACK, C.GL_FRONT_AND_BACK]
LM_P = [C.GL_LIGHT_MODEL_AMBIENT, C.GL_LIGHT_MODEL_TWO_SIDE]
FOG_P = [C.GL_FOG_MODE, C.GL_FOG_DENSITY, C.GL_FOG_START, C.GL_FOG_END, C.GL_FOG_COLOR]
FOG_MODES = [C.GL_LINEAR, C.GL_EXP, C.GL_EXP2]
TEXP = [
    C.GL_TEXTURE_MIN_FILTER,
    C.GL_TEXTURE_MAG_FILTER,
    C.GL_TEXTURE_WRAP_S,
    C.GL_TEXTURE_WRAP_T,
    C.GL_GENERATE_MIPMAP,
    C.GL_TEXTURE_CROP_RECT_OES,
    C.GL_TEXTURE_MAX_ANISOTROPY_EXT,
    C.GL_TEXTURE_MAX_LEVEL_APPLE,
]
TEXP_V = [
    C.GL_NEAREST,
    C.GL_LINEAR,
    C.GL_NEAREST_MIPMAP_NEAREST,
    C.GL_LINEAR_MIPMAP_LINEAR,
    C.GL_NEAREST_MIPMAP_LINEAR,
    C.GL_LINEAR_MIPMAP_NEAREST,
    C.GL_REPEAT,
    C.GL_CLAMP_TO_EDGE,
    C.GL_MIRRORED_REPEAT_OES,
    1,
    0,
]
FB_T = [C.GL_FRAMEBUFFER_OES, C.GL_RENDERBUFFER_OES]
RB_T = [C.GL_RENDERBUFFER_OES, C.GL_FRAMEBUFFER_OES]
FB_ATTACH = [C.GL_COLOR_ATTACHMENT0_OES, C.GL_DEPTH_ATTACHMENT_OES, C.GL_STENCIL_ATTACHMENT_OES,
             C.GL_TEXTURE_2D]
RB_FORMATS = [C.GL_RGBA8_OES, C.GL_RGB8_OES, C.GL_RGB565_OES, C.GL_RGBA4_OES, C.GL_RGB5_A1_OES,
              C.GL_DEPTH_COMPONENT16_OES, C.GL_DEPTH_COMPONENT24_OES, C.GL_STENCIL_INDEX8_OES,
              C.GL_DEPTH24_STENCIL8_OES, C.GL_RGBA]
FB_P = [C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES,
        C.GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_OES, C.GL_RENDERBUFFER_WIDTH_OES]
RB_P = [C.GL_RENDERBUFFER_WIDTH_OES, C.GL_RENDERBUFFER_HEIGHT_OES, C.GL_RENDERBUFFER_INTERNAL_FORMAT_OES,
        C.GL_RENDERBUFFER_RED_SIZE_OES, C.GL_RENDERBUFFER_ALPHA_SIZE_OES, C.GL_RENDERBUFFER_DEPTH_SIZE_OES,
        C.GL_RENDERBUFFER_STENCIL_SIZE_OES, C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES]
ENV_T = [C.GL_TEXTURE_ENV, C.GL_POINT_SPRITE_OES, C.GL_TEXTURE_FILTER_CONTROL_EXT]
ENV_P = [
    C.GL_TEXTURE_ENV_MODE,
    C.GL_TEXTURE_ENV_COLOR,
    C.GL_COMBINE_RGB,
    C.GL_COMBINE_ALPHA,
    C.GL_SRC0_RGB,
    C.GL_SRC1_RGB,
    C.GL_SRC2_ALPHA,
    C.GL_OPERAND0_RGB,
    C.GL_OPERAND2_ALPHA,
    C.GL_RGB_SCALE,
    C.GL_ALPHA_SCALE,
    C.GL_COORD_REPLACE_OES,
    C.GL_TEXTURE_LOD_BIAS_EXT,
]
ENV_V = [
    C.GL_MODULATE,
    C.GL_REPLACE,
    C.GL_DECAL,
    C.GL_BLEND,
    C.GL_ADD,
    C.GL_COMBINE,
    C.GL_ADD_SIGNED,
    C.GL_INTERPOLATE,
    C.GL_SUBTRACT,
    C.GL_DOT3_RGB,
    C.GL_DOT3_RGBA,
    C.GL_TEXTURE,
    C.GL_CONSTANT,
    C.GL_PRIMARY_COLOR,
    C.GL_PREVIOUS,
    C.GL_SRC_COLOR,
    C.GL_ONE_MINUS_SRC_ALPHA,
    C.GL_TEXTURE1,
    1,
    2,
    4,
]
POINT_P = [
    C.GL_POINT_SIZE_MIN,
    C.GL_POINT_SIZE_MAX,
    C.GL_POINT_FADE_THRESHOLD_SIZE,
    C.GL_POINT_DISTANCE_ATTENUATION,
]
HINT_T = [
    C.GL_PERSPECTIVE_CORRECTION_HINT,
    C.GL_POINT_SMOOTH_HINT,
    C.GL_LINE_SMOOTH_HINT,
    C.GL_FOG_HINT,
    C.GL_GENERATE_MIPMAP_HINT,
]
HINT_V = [C.GL_FASTEST, C.GL_NICEST, C.GL_DONT_CARE]
MATRIX_MODES = [C.GL_MODELVIEW, C.GL_PROJECTION, C.GL_TEXTURE, C.GL_MATRIX_PALETTE_OES]
UNITS = [C.GL_TEXTURE0, C.GL_TEXTURE1, C.GL_TEXTURE0 + 2, C.GL_TEXTURE0 + 4]
BUF_T = [C.GL_ARRAY_BUFFER, C.GL_ELEMENT_ARRAY_BUFFER]
USAGE = [C.GL_STATIC_DRAW, C.GL_DYNAMIC_DRAW]
PLANES = [C.GL_CLIP_PLANE0, C.GL_CLIP_PLANE0 + 1, C.GL_CLIP_PLANE0 + 5]
GET_P = [
    C.GL_VIEWPORT,
    C.GL_MODELVIEW_MATRIX,
    C.GL_FOG_END,
    C.GL_CURRENT_COLOR,
    C.GL_DEPTH_RANGE,
    C.GL_COLOR_CLEAR_VALUE,
    C.GL_POINT_SIZE,
    C.GL_STENCIL_WRITEMASK,
    C.GL_MAX_TEXTURE_SIZE,
    C.GL_CURRENT_NORMAL,
    C.GL_ALPHA_TEST_REF,
    C.GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES,
    C.GL_COMPRESSED_TEXTURE_FORMATS,
    C.GL_LIGHT_MODEL_AMBIENT,
    C.GL_POINT_DISTANCE_ATTENUATION,
]
POINTER_P = [C.GL_VERTEX_ARRAY_POINTER, C.GL_COLOR_ARRAY_POINTER, C.GL_TEXTURE_COORD_ARRAY_POINTER]
PIXEL_P = [C.GL_PACK_ALIGNMENT, C.GL_UNPACK_ALIGNMENT]

Spec = Callable[[Gen], list[Val]]


def _tex_image(g: Gen) -> list[Val]:
    fmt = g.enum(BASE + PALETTE[:1])
    w, h = g.size(), g.size()
    typ = g.enum(PIXTYPES)
    nb = (
        (w.value * 4 + 8) * h.value
        if isinstance(w.value, int) and 0 <= w.value <= 2048 and 0 <= h.value <= 2048
        else 64
    )
    return [
        g.enum(IMAGE_T),
        g.int(0, 11),
        fmt,
        w,
        h,
        g.int(0, 0),
        fmt if g.r.random() < 0.8 else g.enum(BASE),
        typ,
        g.data(nb),
    ]


def _tex_sub(g: Gen) -> list[Val]:
    w, h = g.size(), g.size()
    nb = (
        (w.value * 4 + 8) * h.value
        if isinstance(w.value, int) and 0 <= w.value <= 2048 and 0 <= h.value <= 2048
        else 64
    )
    return [
        g.enum(IMAGE_T),
        g.int(0, 4),
        g.int(0, 8),
        g.int(0, 8),
        w,
        h,
        g.enum(BASE),
        g.enum(PIXTYPES),
        g.data(nb),
    ]


def _compressed(g: Gen) -> list[Val]:
    level = g.int(-5, 0)
    n = g.r.choice([0, 16, 48, 176, 300, 1024, 2048])
    return [
        g.enum(IMAGE_T),
        level,
        g.enum(PALETTE),
        g.size(),
        g.size(),
        g.int(0, 0),
        g.int(0, 2048),
        g.data(n),
    ]


def _draw_elements(g: Gen) -> list[Val]:
    typ = g.enum([C.GL_UNSIGNED_BYTE, C.GL_UNSIGNED_SHORT])
    return [g.enum(MODES), g.int(0, 24), typ, g.pointer(typ.value)]


def _discard(g: Gen) -> list[Val]:
    k = g.r.randint(0, 3)
    pool = [C.GL_COLOR_EXT, C.GL_DEPTH_EXT, C.GL_STENCIL_EXT, C.GL_COLOR_ATTACHMENT0_OES,
            C.GL_DEPTH_ATTACHMENT_OES, C.GL_TEXTURE_2D]
    att = [g.r.choice(pool) for _ in range(k)]
    n = g.int(0, k) if g.r.random() < 0.9 else g.int(-2, k)
    return [g.enum(FB_T), n, Val(att, repr(att))]


def _multi_draw_arrays(g: Gen) -> list[Val]:
    k = g.r.randint(0, 3)
    first = [g.int(0, 8).value for _ in range(k)]
    count = [g.int(-1, 24).value for _ in range(k)]
    n = g.int(0, k) if g.r.random() < 0.9 else g.int(-2, 6)
    return [g.enum(MODES), Val(first, repr(first)), Val(count, repr(count)), n]


def _multi_draw_elements(g: Gen) -> list[Val]:
    typ = g.enum([C.GL_UNSIGNED_BYTE, C.GL_UNSIGNED_SHORT])
    k = g.r.randint(0, 3)
    ptrs = [g.pointer(typ.value) for _ in range(k)]
    count = [g.int(-1, 24).value for _ in range(k)]
    n = g.int(0, k) if g.r.random() < 0.9 else g.int(-2, 6)
    return [g.enum(MODES), Val(count, repr(count)), typ,
            Val([p.value for p in ptrs], "[" + ", ".join(p.text for p in ptrs) + "]"), n]


def _array_ptr(sizes: list[int], types: list[int], with_size: bool = True) -> Spec:
    def spec(g: Gen) -> list[Val]:
        typ = g.enum(types)
        out = [Val(g.r.choice(sizes), "")] if with_size else []
        if out:
            out[0] = g.int(min(sizes), max(sizes)) if g.r.random() < 0.9 else g.int(0, 8)
        return out + [typ, g.int(0, 16) if g.r.random() < 0.8 else g.int(-4, 64), g.pointer(typ.value)]

    return spec


def _read_pixels(g: Gen) -> list[Val]:
    fmt = g.enum([C.GL_RGBA, C.GL_RGB])
    typ = g.enum([C.GL_UNSIGNED_BYTE, C.GL_UNSIGNED_SHORT_5_6_5])
    args = [g.int(-4, 8), g.int(-4, 8), g.size(), g.size(), fmt, typ]
    if g.r.random() < 0.3:
        n = g.r.choice([0, 16, 1024, 65536])
        args.append(Val(bytearray(n), f"bytearray({n})"))
    return args


# KHR_debug
DEBUG_SOURCES = [C.GL_DEBUG_SOURCE_APPLICATION_KHR, C.GL_DEBUG_SOURCE_THIRD_PARTY_KHR,
                 C.GL_DEBUG_SOURCE_API_KHR, C.GL_DONT_CARE]
DEBUG_TYPES = [C.GL_DEBUG_TYPE_ERROR_KHR, C.GL_DEBUG_TYPE_MARKER_KHR, C.GL_DEBUG_TYPE_OTHER_KHR,
               C.GL_DEBUG_TYPE_PUSH_GROUP_KHR, C.GL_DONT_CARE]
DEBUG_SEVERITIES = [C.GL_DEBUG_SEVERITY_HIGH_KHR, C.GL_DEBUG_SEVERITY_LOW_KHR,
                    C.GL_DEBUG_SEVERITY_NOTIFICATION_KHR, C.GL_DONT_CARE]
LABEL_IDS = [C.GL_TEXTURE, C.GL_BUFFER_KHR, C.GL_FRAMEBUFFER_OES, C.GL_RENDERBUFFER_OES,
             C.GL_VERTEX_ARRAY_KHR, C.GL_SHADER_KHR, C.GL_PROGRAM_PIPELINE_KHR]
DEBUG_POINTER_P = [C.GL_DEBUG_CALLBACK_FUNCTION_KHR, C.GL_DEBUG_CALLBACK_USER_PARAM_KHR]
DEBUG_MESSAGES: list[Any] = []


def debug_record(source: int, type: int, id: int, severity: int, length: int, message: bytes,
                 user_param: Any) -> None:
    """A debug callback the sequences set: keeps the last messages."""
    DEBUG_MESSAGES.append((source, type, id, severity, message))
    del DEBUG_MESSAGES[:-16]


def _pick(g: Gen, options: list[Any]) -> Val:
    v = g.r.choice(options)
    return Val(v, repr(v))


def _debug_text(g: Gen) -> Val:
    r = g.r.random()
    if r < 0.6:
        v: Any = g.r.choice(["", "label", "group \u00e9", "a\x00b"])
        return Val(v, repr(v))
    if r < 0.7:
        v = g.r.choice([b"bytes", b"", b"\xff\xfe"])
        return Val(v, repr(v))
    if r < 0.9:
        n = g.r.choice([255, 256, 1023, 1024, 2000])
        return Val("x" * n, f"'x' * {n}")
    v = g.r.choice([None, 7, 1.5, ["a"]])
    return Val(v, repr(v))


def _debug_length(g: Gen) -> Val:
    return g.int(-2, 12) if g.r.random() < 0.85 else g.int(250, 1030)


def _debug_control(g: Gen) -> list[Val]:
    k = g.r.randint(0, 3)
    ids = [g.int(0, 8).value for _ in range(k)]
    n = g.int(0, k) if g.r.random() < 0.9 else g.int(-2, 6)
    return [g.enum(DEBUG_SOURCES), g.enum(DEBUG_TYPES), g.enum(DEBUG_SEVERITIES), n,
            Val(ids, repr(ids)) if k or g.r.random() < 0.5 else Val(None, "None"), g.bool()]


def _debug_callback(g: Gen) -> list[Val]:
    cb = g.r.choice([Val(None, "None"), Val(debug_record, "fuzz.debug_record"), Val("no", "'no'")])
    return [cb, _pick(g, [None, 0, "user"])]


def _debug_log(g: Gen) -> list[Val]:
    count = g.int(0, 4)
    out = []
    for dt in (np.uint32, np.uint32, np.uint32, np.uint32, np.int32):
        n = g.r.choice([None, 0, 2, 4, 8])
        text = f"np.zeros({n}, np.{np.dtype(dt)})"
        out.append(Val(None, "None") if n is None else Val(np.zeros(n, dt), text))
    size = g.int(-1, 200)
    n = g.r.choice([None, 0, 64, 256])
    log = Val(None, "None") if n is None else Val(bytearray(n), f"bytearray({n})")
    return [count, size, *out, log]


def _names(g: Gen) -> list[Val]:
    k = g.r.randint(0, 4)
    names = [g.int(0, 8).value for _ in range(k)]
    n = g.int(0, k) if g.r.random() < 0.9 else g.int(0, 8)
    return [n, Val(names, repr(names))]


def _f(n: int) -> Spec:
    return lambda g: [g.float() for _ in range(n)]


def _x(n: int) -> Spec:
    return lambda g: [g.fixed() for _ in range(n)]


def _e(*lists: list[int]) -> Spec:
    return lambda g: [g.enum(lst) for lst in lists]


def _scalar_param(
    targets: list[int], pnames: list[int], kind: str, vector_n: int = 0, values: list[int] | None = None
) -> Spec:
    def spec(g: Gen) -> list[Val]:
        args = [g.enum(targets)] if targets else []
        args.append(g.enum(pnames))
        if values and g.r.random() < 0.5:
            v = g.enum(values)
            args.append(
                Val([v.value] * vector_n, "[" + ", ".join([v.text] * vector_n) + "]") if vector_n else v
            )
        elif vector_n:
            args.append(g.vec(vector_n, kind))
        else:
            args.append({"f": g.float, "x": g.fixed, "i": lambda: g.int(-2, 8)}[kind]())
        return args

    return spec


SPECS: dict[str, Spec] = {
    "glActiveTexture": _e(UNITS),
    "glClientActiveTexture": _e(UNITS),
    "glAlphaFunc": lambda g: [g.enum(FUNCS), g.float()],
    "glAlphaFuncx": lambda g: [g.enum(FUNCS), g.fixed()],
    "glBindBuffer": lambda g: [g.enum(BUF_T), g.int(0, 6)],
    "glBindTexture": lambda g: [g.enum(TEX_T), g.int(0, 6)],
    "glBlendEquationOES": _e([C.GL_FUNC_ADD_OES, C.GL_FUNC_SUBTRACT_OES, C.GL_FUNC_REVERSE_SUBTRACT_OES]),
    "glBlendEquationSeparateOES": _e(
        [C.GL_FUNC_ADD_OES, C.GL_FUNC_SUBTRACT_OES], [C.GL_FUNC_ADD_OES, C.GL_FUNC_REVERSE_SUBTRACT_OES]
    ),
    "glBlendFunc": _e(FACTORS, FACTORS),
    "glBlendFuncSeparateOES": _e(FACTORS, FACTORS, FACTORS, FACTORS),
    "glBufferData": lambda g: (
        lambda s: [g.enum(BUF_T), s, g.data(s.value if isinstance(s.value, int) else 0), g.enum(USAGE)]
    )(g.size()),
    "glBufferSubData": lambda g: (
        lambda s: [g.enum(BUF_T), g.int(0, 32), s, g.data(s.value if isinstance(s.value, int) else 0)]
    )(g.size()),
    "glClear": lambda g: [
        Val(v, hex(v)) for v in [g.r.choice([0x4100, 0x4500, 0x400, 0x100, 0x4000, 0, 0x1, 0xFFFFFFFF])]
    ],
    "glClearColor": _f(4),
    "glClearColorx": _x(4),
    "glClearDepthf": _f(1),
    "glClearDepthx": _x(1),
    "glClearStencil": lambda g: [g.int(0, 300)],
    "glClipPlanef": lambda g: [g.enum(PLANES), g.vec(4, "f")],
    "glClipPlanex": lambda g: [g.enum(PLANES), g.vec(4, "x")],
    "glColor4f": _f(4),
    "glColor4x": _x(4),
    "glColor4ub": lambda g: [g.int(0, 255) for _ in range(4)],
    "glColorMask": lambda g: [g.bool() for _ in range(4)],
    "glColorPointer": _array_ptr([4], [C.GL_UNSIGNED_BYTE, C.GL_FIXED, C.GL_FLOAT]),
    "glCompressedTexImage2D": _compressed,
    "glCompressedTexSubImage2D": lambda g: [
        g.enum([C.GL_TEXTURE_2D]),
        g.int(0, 2),
        g.int(0, 4),
        g.int(0, 4),
        g.size(),
        g.size(),
        g.enum(PALETTE),
        g.int(0, 64),
        g.data(64),
    ],
    "glCopyTexImage2D": lambda g: [
        g.enum([C.GL_TEXTURE_2D]),
        g.int(0, 6),
        g.enum(BASE),
        g.int(-8, 8),
        g.int(-8, 8),
        g.size(),
        g.size(),
        g.int(0, 0),
    ],
    "glCopyTexSubImage2D": lambda g: [
        g.enum([C.GL_TEXTURE_2D]),
        g.int(0, 4),
        g.int(0, 8),
        g.int(0, 8),
        g.int(-8, 8),
        g.int(-8, 8),
        g.size(),
        g.size(),
    ],
    "glCullFace": _e(FACES),
    "glFrontFace": _e([C.GL_CW, C.GL_CCW]),
    "glCurrentPaletteMatrixOES": lambda g: [g.int(0, 12)],
    "glDeleteBuffers": _names,
    "glDeleteVertexArraysOES": _names,
    "glDeleteTextures": _names,
    "glDepthFunc": _e(FUNCS),
    "glDepthMask": lambda g: [g.bool()],
    "glDepthRangef": _f(2),
    "glDepthRangex": _x(2),
    "glDisable": _e(CAPS),
    "glEnable": _e(CAPS),
    "glIsEnabled": _e(CAPS),
    "glDisableClientState": _e(CLIENT),
    "glEnableClientState": _e(CLIENT),
    "glDrawArrays": lambda g: [g.enum(MODES), g.int(0, 8), g.int(0, 24)],
    "glDrawElements": _draw_elements,
    "glMultiDrawArraysEXT": _multi_draw_arrays,
    "glMultiDrawElementsEXT": _multi_draw_elements,
    "glDrawTexfOES": _f(5),
    "glDrawTexxOES": _x(5),
    "glDrawTexiOES": lambda g: [g.int(-8, 40) for _ in range(5)],
    "glDrawTexsOES": lambda g: [g.int(-8, 40) for _ in range(5)],
    "glDrawTexfvOES": lambda g: [g.vec(5, "f")],
    "glDrawTexxvOES": lambda g: [g.vec(5, "x")],
    "glDrawTexivOES": lambda g: [g.vec(5, "i")],
    "glDrawTexsvOES": lambda g: [g.vec(5, "i")],
    "glFinish": lambda g: [],
    "glFlush": lambda g: [],
    "glFogf": _scalar_param([], FOG_P, "f", values=FOG_MODES),
    "glFogx": _scalar_param([], FOG_P, "x", values=FOG_MODES),
    "glFogfv": _scalar_param([], FOG_P, "f", 4, FOG_MODES),
    "glFogxv": _scalar_param([], FOG_P, "x", 4, FOG_MODES),
    "glFrustumf": _f(6),
    "glFrustumx": _x(6),
    "glOrthof": _f(6),
    "glOrthox": _x(6),
    "glGenBuffers": lambda g: [g.int(0, 3)],
    "glGenVertexArraysOES": lambda g: [g.int(0, 3)],
    "glGenTextures": lambda g: [g.int(0, 3)],
    "glGetBooleanv": _e(GET_P),
    "glGetFixedv": _e(GET_P),
    "glGetFloatv": _e(GET_P),
    "glGetIntegerv": _e(GET_P),
    "glGetBufferParameteriv": _e(BUF_T, [C.GL_BUFFER_SIZE, C.GL_BUFFER_USAGE]),
    "glGetClipPlanef": _e(PLANES),
    "glGetClipPlanex": _e(PLANES),
    "glGetLightfv": _e(LIGHTS, LIGHT_P),
    "glGetLightxv": _e(LIGHTS, LIGHT_P),
    "glGetMaterialfv": _e(FACES, MAT_P),
    "glGetMaterialxv": _e(FACES, MAT_P),
    "glGetPointerv": _e(POINTER_P + DEBUG_POINTER_P),
    "glGetPointervKHR": _e(POINTER_P + DEBUG_POINTER_P),
    "glDebugMessageControlKHR": _debug_control,
    "glDebugMessageInsertKHR": lambda g: [g.enum(DEBUG_SOURCES), g.enum(DEBUG_TYPES), g.int(0, 8),
                                          g.enum(DEBUG_SEVERITIES), _debug_length(g), _debug_text(g)],
    "glDebugMessageCallbackKHR": _debug_callback,
    "glGetDebugMessageLogKHR": _debug_log,
    "glPushDebugGroupKHR": lambda g: [g.enum(DEBUG_SOURCES), g.int(0, 8), _debug_length(g), _debug_text(g)],
    "glPopDebugGroupKHR": lambda g: [],
    "glObjectLabelKHR": lambda g: [g.enum(LABEL_IDS), g.int(0, 6), _debug_length(g), _debug_text(g)],
    "glGetObjectLabelKHR": lambda g: [g.enum(LABEL_IDS), g.int(0, 6), g.int(-1, 300)],
    "glObjectPtrLabelKHR": lambda g: [_pick(g, [None, 0, 4096]), _debug_length(g), _debug_text(g)],
    "glGetObjectPtrLabelKHR": lambda g: [_pick(g, [None, 0, 4096]), g.int(-1, 64)],
    "glGetString": _e([C.GL_VENDOR, C.GL_RENDERER, C.GL_VERSION, C.GL_EXTENSIONS]),
    "glGetTexEnvfv": _e(ENV_T, ENV_P),
    "glGetTexEnviv": _e(ENV_T, ENV_P),
    "glGetTexEnvxv": _e(ENV_T, ENV_P),
    "glGetTexParameterfv": _e(TEX_T, TEXP),
    "glGetTexParameteriv": _e(TEX_T, TEXP),
    "glGetTexParameterxv": _e(TEX_T, TEXP),
    "glHint": _e(HINT_T, HINT_V),
    "glIsBuffer": lambda g: [g.int(0, 6)],
    "glIsVertexArrayOES": lambda g: [g.int(0, 6)],
    "glGenFramebuffersOES": lambda g: [g.int(0, 3)],
    "glGenRenderbuffersOES": lambda g: [g.int(0, 3)],
    "glDeleteFramebuffersOES": _names,
    "glDeleteRenderbuffersOES": _names,
    "glBindFramebufferOES": lambda g: [g.enum(FB_T), g.int(0, 4)],
    "glBindRenderbufferOES": lambda g: [g.enum(RB_T), g.int(0, 4)],
    "glIsFramebufferOES": lambda g: [g.int(0, 6)],
    "glIsRenderbufferOES": lambda g: [g.int(0, 6)],
    "glRenderbufferStorageOES": lambda g: [g.enum(RB_T), g.enum(RB_FORMATS), g.int(-1, 40),
                                           g.int(-1, 40)],
    "glFramebufferTexture2DOES": lambda g: [g.enum(FB_T), g.enum(FB_ATTACH),
                                            g.enum([C.GL_TEXTURE_2D, 0x8515]), g.int(0, 4), g.int(-1, 3)],
    "glFramebufferRenderbufferOES": lambda g: [g.enum(FB_T), g.enum(FB_ATTACH), g.enum(RB_T), g.int(0, 4)],
    "glCheckFramebufferStatusOES": lambda g: [g.enum(FB_T)],
    "glGetFramebufferAttachmentParameterivOES": lambda g: [g.enum(FB_T), g.enum(FB_ATTACH), g.enum(FB_P)],
    "glGetRenderbufferParameterivOES": lambda g: [g.enum(RB_T), g.enum(RB_P)],
    "glGenerateMipmapOES": lambda g: [g.enum([C.GL_TEXTURE_2D, C.GL_TEXTURE_CUBE_MAP_OES, C.GL_TEXTURE])],
    "glDiscardFramebufferEXT": _discard,
    "glMapBufferOES": lambda g: [g.enum(BUF_T), g.enum([C.GL_WRITE_ONLY_OES, 0x88B8])],
    "glUnmapBufferOES": lambda g: [g.enum(BUF_T)],
    "glGetBufferPointervOES": lambda g: [g.enum(BUF_T),
                                         g.enum([C.GL_BUFFER_MAP_POINTER_OES, C.GL_BUFFER_SIZE])],
    "glMapBufferRangeEXT": lambda g: [g.enum(BUF_T), g.int(-1, 24), g.int(-1, 24), g.int(0, 0x3F)],
    "glFlushMappedBufferRangeEXT": lambda g: [g.enum(BUF_T), g.int(-1, 12), g.int(-1, 12)],
    "glBindVertexArrayOES": lambda g: [g.int(0, 6)],
    "glIsTexture": lambda g: [g.int(0, 6)],
    "glLightModelf": _scalar_param([], LM_P, "f"),
    "glLightModelx": _scalar_param([], LM_P, "x"),
    "glLightModelfv": _scalar_param([], LM_P, "f", 4),
    "glLightModelxv": _scalar_param([], LM_P, "x", 4),
    "glLightf": _scalar_param(LIGHTS, LIGHT_P, "f"),
    "glLightx": _scalar_param(LIGHTS, LIGHT_P, "x"),
    "glLightfv": _scalar_param(LIGHTS, LIGHT_P, "f", 4),
    "glLightxv": _scalar_param(LIGHTS, LIGHT_P, "x", 4),
    "glLineWidth": _f(1),
    "glLineWidthx": _x(1),
    "glPointSize": _f(1),
    "glPointSizex": _x(1),
    "glLoadIdentity": lambda g: [],
    "glPushMatrix": lambda g: [],
    "glPopMatrix": lambda g: [],
    "glLoadMatrixf": lambda g: [g.vec(16, "f")],
    "glLoadMatrixx": lambda g: [g.vec(16, "x")],
    "glMultMatrixf": lambda g: [g.vec(16, "f")],
    "glMultMatrixx": lambda g: [g.vec(16, "x")],
    "glLoadPaletteFromModelViewMatrixOES": lambda g: [],
    "glLogicOp": _e(list(range(C.GL_CLEAR, C.GL_SET + 1))),
    "glMaterialf": _scalar_param(FACES, MAT_P, "f"),
    "glMaterialx": _scalar_param(FACES, MAT_P, "x"),
    "glMaterialfv": _scalar_param(FACES, MAT_P, "f", 4),
    "glMaterialxv": _scalar_param(FACES, MAT_P, "x", 4),
    "glMatrixIndexPointerOES": _array_ptr([0, 1, 2, 3], [C.GL_UNSIGNED_BYTE]),
    "glWeightPointerOES": _array_ptr([0, 1, 2, 3], [C.GL_FIXED, C.GL_FLOAT]),
    "glMatrixMode": _e(MATRIX_MODES),
    "glMultiTexCoord4f": lambda g: [g.enum(UNITS)] + _f(4)(g),
    "glMultiTexCoord4x": lambda g: [g.enum(UNITS)] + _x(4)(g),
    "glNormal3f": _f(3),
    "glNormal3x": _x(3),
    "glNormalPointer": _array_ptr([3], [C.GL_BYTE, C.GL_SHORT, C.GL_FIXED, C.GL_FLOAT], with_size=False),
    "glPixelStorei": lambda g: [g.enum(PIXEL_P), g.int(0, 8)],
    "glPointParameterf": _scalar_param([], POINT_P, "f"),
    "glPointParameterx": _scalar_param([], POINT_P, "x"),
    "glPointParameterfv": _scalar_param([], POINT_P, "f", 3),
    "glPointParameterxv": _scalar_param([], POINT_P, "x", 3),
    "glPointSizePointerOES": _array_ptr([1], [C.GL_FIXED, C.GL_FLOAT], with_size=False),
    "glPolygonOffset": _f(2),
    "glPolygonOffsetx": _x(2),
    "glQueryMatrixxOES": lambda g: [],
    "glReadPixels": _read_pixels,
    "glRotatef": _f(4),
    "glRotatex": _x(4),
    "glScalef": _f(3),
    "glScalex": _x(3),
    "glTranslatef": _f(3),
    "glTranslatex": _x(3),
    "glSampleCoverage": lambda g: [g.float(), g.bool()],
    "glSampleCoveragex": lambda g: [g.fixed(), g.bool()],
    "glScissor": lambda g: [g.int(-4, 8), g.int(-4, 8), g.size(), g.size()],
    "glViewport": lambda g: [g.int(-4, 8), g.int(-4, 8), g.size(), g.size()],
    "glShadeModel": _e([C.GL_FLAT, C.GL_SMOOTH]),
    "glStencilFunc": lambda g: [g.enum(FUNCS), g.int(0, 300), g.int(0, 255)],
    "glStencilMask": lambda g: [g.int(0, 255)],
    "glStencilOp": _e(STENCIL_OPS, STENCIL_OPS, STENCIL_OPS),
    "glTexCoordPointer": _array_ptr([2, 3, 4], [C.GL_BYTE, C.GL_SHORT, C.GL_FIXED, C.GL_FLOAT]),
    "glVertexPointer": _array_ptr([2, 3, 4], [C.GL_BYTE, C.GL_SHORT, C.GL_FIXED, C.GL_FLOAT]),
    "glTexEnvf": _scalar_param(ENV_T, ENV_P, "f", values=ENV_V),
    "glTexEnvi": _scalar_param(ENV_T, ENV_P, "i", values=ENV_V),
    "glTexEnvx": _scalar_param(ENV_T, ENV_P, "x", values=ENV_V),
    "glTexEnvfv": _scalar_param(ENV_T, ENV_P, "f", 4, ENV_V),
    "glTexEnviv": _scalar_param(ENV_T, ENV_P, "i", 4, ENV_V),
    "glTexEnvxv": _scalar_param(ENV_T, ENV_P, "x", 4, ENV_V),
    "glTexImage2D": _tex_image,
    "glTexSubImage2D": _tex_sub,
    "glTexParameterf": _scalar_param(TEX_T, TEXP, "f", values=TEXP_V),
    "glTexParameteri": _scalar_param(TEX_T, TEXP, "i", values=TEXP_V),
    "glTexParameterx": _scalar_param(TEX_T, TEXP, "x", values=TEXP_V),
    "glTexParameterfv": _scalar_param(TEX_T, TEXP, "f", 4, TEXP_V),
    "glTexGenfOES": _scalar_param(GEN_C, GEN_P, "f", values=GEN_V),
    "glTexGenfvOES": _scalar_param(GEN_C, GEN_P, "f", 1, GEN_V),
    "glGetTexGenfvOES": _e(GEN_C, GEN_P),
    "glTexParameteriv": _scalar_param(TEX_T, TEXP, "i", 4, TEXP_V),
    "glTexGeniOES": _scalar_param(GEN_C, GEN_P, "i", values=GEN_V),
    "glTexGenivOES": _scalar_param(GEN_C, GEN_P, "i", 1, GEN_V),
    "glGetTexGenivOES": _e(GEN_C, GEN_P),
    "glTexParameterxv": _scalar_param(TEX_T, TEXP, "x", 4, TEXP_V),
    "glTexGenxOES": _scalar_param(GEN_C, GEN_P, "x", values=GEN_V),
    "glTexGenxvOES": _scalar_param(GEN_C, GEN_P, "x", 1, GEN_V),
    "glGetTexGenxvOES": _e(GEN_C, GEN_P),
}
# commands drawn more often: they make the state the others act on
WEIGHTS = {
    "glDrawArrays": 8,
    "glDrawElements": 4,
    "glVertexPointer": 4,
    "glEnableClientState": 4,
    "glTexImage2D": 3,
    "glEnable": 3,
    "glBindBuffer": 2,
    "glBufferData": 2,
    "glBindTexture": 2,
    "glLoadMatrixf": 2,
    "glPushMatrix": 2,
    "glColorPointer": 2,
    "glTexCoordPointer": 2,
}


# {====================================================================
# sequences


@dataclass
class Setup:
    width: int
    height: int
    profile: str
    numeric: str
    color: str
    depth: int
    stencil: int
    range_check: str
    memory_limit: int
    backend: str = "python"  # "python", "checked" (check_errors=True) or "cabi"

    def text(self) -> str:
        if self.backend == "cabi":
            return (
                f"ctx = fuzz.CabiContext({self.width}, {self.height}, profile={self.profile!r}, "
                f"numeric={self.numeric!r}, color={self.color!r}, depth={self.depth}, "
                f"stencil={self.stencil}, memory_limit={self.memory_limit})"
            )
        checked = "\nctx.check_errors = True" if self.backend == "checked" else ""
        return (
            f"ctx = gles.Context({self.width}, {self.height}, profile={self.profile!r}, "
            f"numeric={self.numeric!r}, color={self.color!r}, depth={self.depth}, "
            f"stencil={self.stencil}, range_check={self.range_check!r}, memory_limit={self.memory_limit})"
            + checked
        )


@dataclass
class Call:
    name: str
    args: list[Val]

    def text(self) -> str:
        return f"g.{self.name}({', '.join(a.text for a in self.args)})"


def make_sequence(seed: int, max_calls: int = 120, backend: str = "python") -> tuple[Setup, list[Call]]:
    """The context and the calls of one seed on one backend (deterministic).

    backend "mixed" picks one per seed: python, checked, cabi for seed % 3 =
    0, 1, 2. A seed makes the same context and calls on every backend,
    except that on the C ABI (which has no range-check policy: its setups
    say "off") about one call in twenty that takes a pointer becomes the
    same call with NULL pointers.
    """
    if backend == "mixed":
        backend = BACKENDS[seed % 3]
    if backend not in BACKENDS:
        raise ValueError(f"backend must be one of {BACKENDS} or 'mixed', not {backend!r}")
    r = random.Random(seed)
    setup = Setup(
        r.randint(1, 40),
        r.randint(1, 40),
        r.choice(["common", "common-lite"]),
        r.choice(["fixed", "float", "double"]),
        r.choice(["rgba8888", "rgb565"]),
        r.choice([0, 16, 24]),
        r.choice([0, 8]),
        r.choice(["off", "warn", "clamp", "raise"]),
        r.choice([1 << 12, 1 << 16, 1 << 20, 1 << 24, 256 << 20]),
    )
    from gles import gl

    names = gl.COMMON_COMMANDS if setup.profile == "common" else gl.COMMON_LITE_COMMANDS
    pool = [n for n in names if n in SPECS]
    weights = [WEIGHTS.get(n, 1) for n in pool]
    g = Gen(r)
    calls = [Call(name, SPECS[name](g)) for name in r.choices(pool, weights, k=r.randint(10, max_calls))]
    setup.backend = backend
    if backend == "cabi":
        setup.range_check = "off"
        # a few calls with NULL for their pointers (what only C can pass)
        nr = random.Random(f"null {seed}")
        for i, call in enumerate(calls):
            if "*" in _c_params(call.name) and nr.random() < NULL_CALLS:
                args = [
                    Val(None, "None") if isinstance(a.value, (list, bytes, bytearray, np.ndarray)) else a
                    for a in call.args
                ]
                calls[i] = Call("null_pointers", [Val(call.name, repr(call.name))] + args)
    return setup, calls


def commands_covered() -> tuple[set[str], set[str]]:
    """(commands with a generator, commands of the Common profile without one)."""
    from gles import gl

    every = set(gl.COMMON_COMMANDS) - {"glGetError"}
    return every & set(SPECS), every - set(SPECS)


# {====================================================================
# running and the invariant

ALLOWED = (GLError, TypeError, ValueError)
BACKENDS = ("python", "checked", "cabi")


class CoreView:
    """The core context behind a backend, read through the core library's own
    functions: exact doubles, the same for gles.Context and the C ABI (whose
    entry points are a thin layer over the same core)."""

    def __init__(
        self, lib: Any, ffi: Any, p: Any, width: int, height: int, color: str, depth: int, stencil: int
    ) -> None:
        self.lib, self.ffi, self.p = lib, ffi, p
        self.width, self.height, self.color, self.depth, self.stencil = width, height, color, depth, stencil
        self._d16 = ffi.new("double[16]")
        self._kind = ffi.new("int *")
        self._d4 = ffi.new("double[4]")

    def get(self, pname: int) -> tuple[float, ...]:
        n = self.lib.gles_get(self.p, pname, self._d16, self._kind)
        return tuple(self._d16[i] for i in range(n))

    def get_int(self, pname: int) -> int:
        v = self.get(pname)
        return int(v[0]) if v else 0

    def is_enabled(self, cap: int) -> bool:
        return bool(self.lib.gles_IsEnabled(self.p, cap))

    def pointer(self, pname: int) -> int:
        return int(self.lib.gles_GetPointer(self.p, pname))

    def lm(self, fn: str, target: int, pname: int) -> tuple[float, ...]:
        n = getattr(self.lib, fn)(self.p, target, pname, self._d4)
        return tuple(self._d4[i] for i in range(n))

    def buffer_size(self, target: int) -> int:
        out = self.ffi.new("int[1]")
        self.lib.gles_GetBufferParameteriv(self.p, target, C.GL_BUFFER_SIZE, out)
        return int(out[0])

    def peek_error(self) -> int:
        """The pending GL error, left pending."""
        err = self.lib.gles_GetError(self.p)
        if err:
            self.lib.gles_set_error(self.p, err)
        return int(err)

    def framebuffer(self) -> tuple[bytes, bytes | None, bytes | None]:
        n = self.width * self.height
        lib, ffi, p = self.lib, self.ffi, self.p
        color = bytes(ffi.buffer(lib.gles_color_buffer(p), n * (2 if self.color == "rgb565" else 4)))
        depth = bytes(ffi.buffer(lib.gles_depth_buffer(p), n * 4)) if self.depth else None
        stencil = bytes(ffi.buffer(lib.gles_stencil_buffer(p), n)) if self.stencil else None
        return color, depth, stencil


def context_view(ctx: gles.Context) -> CoreView:
    return CoreView(
        ctx._lib, ctx._ffi, ctx._ptr, ctx.width, ctx.height, ctx.color, ctx.depth_bits, ctx.stencil_bits
    )


def snapshot(view: CoreView) -> tuple:
    """The state an erring call must leave alone, as exact doubles."""
    s: list[Any] = []
    for p in SNAP_GET:
        s.append(view.get(p))
    for p in CAPS + CLIENT:
        s.append(view.is_enabled(p))
    for p in POINTER_P:
        s.append(view.pointer(p))
    for light in (C.GL_LIGHT0, C.GL_LIGHT1):
        for p in LIGHT_P:
            s.append(view.lm("gles_GetLight", light, p))
    for face in (C.GL_FRONT, C.GL_BACK):
        for p in MAT_P[:5]:
            s.append(view.lm("gles_GetMaterial", face, p))
    for p in ENV_P[:-1]:
        s.append(view.lm("gles_GetTexEnv", C.GL_TEXTURE_ENV, p))
    for t in TEX_T:
        for p in TEXP:
            s.append(view.lm("gles_GetTexParameter", t, p))
    s.append(view.lm("gles_GetTexGen", C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_GEN_MODE_OES))
    eq = view.ffi.new("double[4]")
    view.lib.gles_GetClipPlane(view.p, C.GL_CLIP_PLANE0, eq)
    s.append(tuple(eq))
    for name in range(1, 7):
        s.append((bool(view.lib.gles_IsBuffer(view.p, name)), bool(view.lib.gles_IsTexture(view.p, name))))
    for t in BUF_T:
        s.append(view.buffer_size(t))
    s.append(int(view.lib.gles_memory_used(view.p)))
    s.extend(view.framebuffer())
    view.lib.gles_GetError(view.p)  # the snapshot's own queries must not leave an error
    return tuple(repr(v) if isinstance(v, tuple) else v for v in s)


SNAP_GET = [
    C.GL_VIEWPORT,
    C.GL_SCISSOR_BOX,
    C.GL_DEPTH_FUNC,
    C.GL_CULL_FACE_MODE,
    C.GL_FRONT_FACE,
    C.GL_SHADE_MODEL,
    C.GL_MATRIX_MODE,
    C.GL_PACK_ALIGNMENT,
    C.GL_UNPACK_ALIGNMENT,
    C.GL_ACTIVE_TEXTURE,
    C.GL_CLIENT_ACTIVE_TEXTURE,
    C.GL_ARRAY_BUFFER_BINDING,
    C.GL_ELEMENT_ARRAY_BUFFER_BINDING,
    C.GL_MODELVIEW_STACK_DEPTH,
    C.GL_PROJECTION_STACK_DEPTH,
    C.GL_TEXTURE_STACK_DEPTH,
    C.GL_VERTEX_ARRAY_SIZE,
    C.GL_VERTEX_ARRAY_TYPE,
    C.GL_VERTEX_ARRAY_STRIDE,
    C.GL_COLOR_ARRAY_SIZE,
    C.GL_COLOR_ARRAY_TYPE,
    C.GL_TEXTURE_COORD_ARRAY_SIZE,
    C.GL_NORMAL_ARRAY_TYPE,
    C.GL_POINT_SIZE_ARRAY_TYPE_OES,
    C.GL_STENCIL_CLEAR_VALUE,
    C.GL_COLOR_WRITEMASK,
    C.GL_DEPTH_WRITEMASK,
    C.GL_ALPHA_TEST_FUNC,
    C.GL_STENCIL_FUNC,
    C.GL_STENCIL_REF,
    C.GL_STENCIL_VALUE_MASK,
    C.GL_STENCIL_WRITEMASK,
    C.GL_STENCIL_FAIL,
    C.GL_BLEND_SRC,
    C.GL_BLEND_DST,
    C.GL_LOGIC_OP_MODE,
    C.GL_FOG_MODE,
    C.GL_TEXTURE_BINDING_2D,
    C.GL_TEXTURE_BINDING_CUBE_MAP_OES,
    C.GL_MODELVIEW_MATRIX,
    C.GL_PROJECTION_MATRIX,
    C.GL_TEXTURE_MATRIX,
    C.GL_CURRENT_COLOR,
    C.GL_CURRENT_NORMAL,
    C.GL_CURRENT_TEXTURE_COORDS,
    C.GL_DEPTH_RANGE,
    C.GL_COLOR_CLEAR_VALUE,
    C.GL_DEPTH_CLEAR_VALUE,
    C.GL_ALPHA_TEST_REF,
    C.GL_FOG_DENSITY,
    C.GL_FOG_START,
    C.GL_FOG_END,
    C.GL_FOG_COLOR,
    C.GL_LIGHT_MODEL_AMBIENT,
    C.GL_LIGHT_MODEL_TWO_SIDE,
    C.GL_POINT_SIZE,
    C.GL_LINE_WIDTH,
    C.GL_POINT_SIZE_MIN,
    C.GL_POINT_SIZE_MAX,
    C.GL_POINT_FADE_THRESHOLD_SIZE,
    C.GL_POINT_DISTANCE_ATTENUATION,
    C.GL_POLYGON_OFFSET_FACTOR,
    C.GL_POLYGON_OFFSET_UNITS,
    C.GL_SAMPLE_COVERAGE_VALUE,
    C.GL_SAMPLE_COVERAGE_INVERT,
    C.GL_MATRIX_INDEX_ARRAY_SIZE_OES,
    C.GL_WEIGHT_ARRAY_SIZE_OES,
    C.GL_CURRENT_PALETTE_MATRIX_OES,
    C.GL_GENERATE_MIPMAP_HINT,
    C.GL_BLEND_EQUATION_RGB_OES,
    C.GL_BLEND_EQUATION_ALPHA_OES,
    C.GL_BLEND_SRC_RGB_OES,
    C.GL_BLEND_DST_ALPHA_OES,
]


class Failure(Exception):
    """The invariant broke at call `index`."""

    def __init__(self, index: int, kind: str, detail: str) -> None:
        super().__init__(f"call {index}: {kind}: {detail}")
        self.index, self.kind, self.detail = index, kind, detail


# {====================================================================
# the C ABI harness: what a careful C program may pass

# per client array: (cap, size pname or a fixed size, type, stride, binding, pointer)
_ARRAYS = [
    (
        C.GL_VERTEX_ARRAY,
        C.GL_VERTEX_ARRAY_SIZE,
        C.GL_VERTEX_ARRAY_TYPE,
        C.GL_VERTEX_ARRAY_STRIDE,
        C.GL_VERTEX_ARRAY_BUFFER_BINDING,
        C.GL_VERTEX_ARRAY_POINTER,
    ),
    (
        C.GL_NORMAL_ARRAY,
        3,
        C.GL_NORMAL_ARRAY_TYPE,
        C.GL_NORMAL_ARRAY_STRIDE,
        C.GL_NORMAL_ARRAY_BUFFER_BINDING,
        C.GL_NORMAL_ARRAY_POINTER,
    ),
    (
        C.GL_COLOR_ARRAY,
        C.GL_COLOR_ARRAY_SIZE,
        C.GL_COLOR_ARRAY_TYPE,
        C.GL_COLOR_ARRAY_STRIDE,
        C.GL_COLOR_ARRAY_BUFFER_BINDING,
        C.GL_COLOR_ARRAY_POINTER,
    ),
    (
        C.GL_POINT_SIZE_ARRAY_OES,
        1,
        C.GL_POINT_SIZE_ARRAY_TYPE_OES,
        C.GL_POINT_SIZE_ARRAY_STRIDE_OES,
        C.GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES,
        C.GL_POINT_SIZE_ARRAY_POINTER_OES,
    ),
    (
        C.GL_MATRIX_INDEX_ARRAY_OES,
        C.GL_MATRIX_INDEX_ARRAY_SIZE_OES,
        C.GL_MATRIX_INDEX_ARRAY_TYPE_OES,
        C.GL_MATRIX_INDEX_ARRAY_STRIDE_OES,
        C.GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES,
        C.GL_MATRIX_INDEX_ARRAY_POINTER_OES,
    ),
    (
        C.GL_WEIGHT_ARRAY_OES,
        C.GL_WEIGHT_ARRAY_SIZE_OES,
        C.GL_WEIGHT_ARRAY_TYPE_OES,
        C.GL_WEIGHT_ARRAY_STRIDE_OES,
        C.GL_WEIGHT_ARRAY_BUFFER_BINDING_OES,
        C.GL_WEIGHT_ARRAY_POINTER_OES,
    ),
]
_TEXCOORD_ARRAY = (
    C.GL_TEXTURE_COORD_ARRAY,
    C.GL_TEXTURE_COORD_ARRAY_SIZE,
    C.GL_TEXTURE_COORD_ARRAY_TYPE,
    C.GL_TEXTURE_COORD_ARRAY_STRIDE,
    C.GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
    C.GL_TEXTURE_COORD_ARRAY_POINTER,
)
_TYPE_BYTES = {
    C.GL_BYTE: 1,
    C.GL_UNSIGNED_BYTE: 1,
    C.GL_SHORT: 2,
    C.GL_UNSIGNED_SHORT: 2,
    C.GL_FIXED: 4,
    C.GL_FLOAT: 4,
}
_POINTER_COMMANDS = {
    "glVertexPointer",
    "glColorPointer",
    "glNormalPointer",
    "glTexCoordPointer",
    "glPointSizePointerOES",
    "glMatrixIndexPointerOES",
    "glWeightPointerOES",
}
NULL_CALLS = 0.05  # the share of C ABI calls with pointers that pass NULL
_MAX_NAMES = 1 << 16  # glGen*(n): the names array the harness allocates
_MAX_IMAGE_SIDE = 1 << 16  # past GL_MAX_TEXTURE_SIZE
_MAX_READ_PIXELS = 1 << 22  # glReadPixels: the pixels the harness allocates room for


# the values a C caller can pass for each integer type of the Khronos headers
_C_INT_RANGES = {
    "GLenum": (0, 2**32 - 1),
    "GLuint": (0, 2**32 - 1),
    "GLbitfield": (0, 2**32 - 1),
    "GLint": (-(2**31), 2**31 - 1),
    "GLsizei": (-(2**31), 2**31 - 1),
    "GLfixed": (-(2**31), 2**31 - 1),
    "GLclampx": (-(2**31), 2**31 - 1),
    "GLshort": (-(2**15), 2**15 - 1),
    "GLbyte": (-128, 127),
    "GLubyte": (0, 255),
    "GLboolean": (0, 255),
    "GLintptr": (-(2**63), 2**63 - 1),
    "GLsizeiptr": (-(2**63), 2**63 - 1),
}
_C_PARAMS: dict[str, list[str]] = {}


def _c_params(name: str) -> list[str]:
    """The parameter types of a GL command in GLES/gl.h and glext.h ("*" for a pointer)."""
    if not _C_PARAMS:
        from gles import cabi

        texts = [(cabi.include_dir() / "GLES" / header).read_text() for header in ("gl.h", "glext.h")]
        gl2ext = (cabi.include_dir() / "GLES2" / "gl2ext.h").read_text()
        start = gl2ext.index("#ifndef GL_KHR_debug\n")
        texts.append(gl2ext[start:gl2ext.index("#endif /* GL_KHR_debug */", start)])
        for text in texts:
            for m in re.finditer(r"GL_API(?:CALL)? \w[\w\s*]*?GL_APIENTRY (\w+) \(([^)]*)\);", text):
                params = [q.strip() for q in m.group(2).split(",") if q.strip() not in ("", "void")]
                # a callback is a pointer C may pass as NULL
                _C_PARAMS[m.group(1)] = ["*" if "*" in q or "GLDEBUGPROCKHR" in q else q.split()[-2]
                                         for q in params]
    return _C_PARAMS.get(name, [])


def _to_c_ints(name: str, args: list[Any]) -> list[Any]:
    """The arguments with each int converted to its parameter's C type as C
    converts it (modulo 2^bits), as the entry point will see it: ctypes
    would wrap it silently, after the harness sized memory by the value."""
    out = list(args)
    for i, (ctype, v) in enumerate(zip(_c_params(name), args)):
        bounds = _C_INT_RANGES.get(ctype)
        if bounds and _is_address(v) and not bounds[0] <= v <= bounds[1]:
            lo, hi = bounds
            out[i] = (int(v) - lo) % (hi - lo + 1) + lo
    return out


def _is_address(v: Any) -> bool:
    return isinstance(v, (int, np.integer)) and not isinstance(v, bool)


def _client_bytes(obj: Any, dtype: Any) -> bytes | None:
    """The bytes the C ABI wrapper would pass for client data `obj`."""
    if isinstance(obj, np.ndarray):
        return obj.tobytes() if obj.flags.c_contiguous else None
    if isinstance(obj, (bytes, bytearray, memoryview)):
        return bytes(obj)
    try:
        a = np.asarray(obj)
        if a.dtype.kind not in "biu":
            return None
        return np.ascontiguousarray(a, dtype).tobytes()
    except (TypeError, ValueError, OverflowError):
        return None


class CabiContext:
    """gles's own libEGL + libGLESv1_CM of one build and profile, driven
    through gles.mesa.LibraryContext, with the care a correct C program takes.

    C cannot check a pointer, so ``gl`` refuses (ValueError, before C runs)
    what would make the library read or write memory the caller does not
    own: an int address outside a buffer object, a draw reading past the
    client arrays given, image data shorter than the image, and output
    arrays too large to allocate. Every other argument reaches the C entry
    point as given, ints converted to their C types as C converts them;
    ``gl.null_pointers(name, ...)`` passes NULL for every pointer. ``view``
    reads the core context behind the EGL context; the memory budget (256
    MiB by default for C contexts) is set through it.
    """

    def __init__(
        self,
        width: int,
        height: int,
        *,
        profile: str,
        numeric: str,
        color: str,
        depth: int,
        stencil: int,
        memory_limit: int,
    ) -> None:
        import ctypes

        from gles import _binding, cabi, mesa

        self.library = mesa.LibraryContext(
            width,
            height,
            str(cabi.library("EGL", numeric, profile)),
            str(cabi.library("GLESv1_CM", numeric, profile)),
            color=color,
            depth=depth,
            stencil=stencil,
        )
        core = ctypes.CDLL(str(cabi.libdir(numeric, profile).parent.parent / f"libgles_{numeric}.so"))
        core.gles_cabi_current.restype = ctypes.c_void_p
        address = core.gles_cabi_current()
        if not address:
            raise RuntimeError("the C ABI context has no core context")
        mod = _binding.core(numeric)
        self.view = CoreView(
            mod.lib, mod.ffi, mod.ffi.cast("GlesContext *", address), width, height, color, depth, stencil
        )
        self.view.lib.gles_memory_limit(self.view.p, memory_limit)
        self.buffers: dict[int, bytes | None] = {}  # what each buffer object holds (None: unknown)
        self.gl = _GuardedGL(self)

    def close(self) -> None:
        self.library.close()

    def __enter__(self) -> CabiContext:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- what the guards need
    def _owned(self) -> dict[int, int]:
        """Address -> bytes of every client array the library may read."""
        from gles import mesa

        return {mesa._addr(k): k.nbytes for k in self.library._keep.values() if isinstance(k, np.ndarray)}

    def check_arrays(self, max_index: int) -> None:
        """Refuse a draw that would read a client array past its end."""
        v = self.view
        owned = self._owned()
        units = v.get_int(C.GL_MAX_TEXTURE_UNITS)
        active = v.get_int(C.GL_CLIENT_ACTIVE_TEXTURE)
        arrays = [(a, None) for a in _ARRAYS] + [(_TEXCOORD_ARRAY, u) for u in range(units)]
        try:
            for (cap, size, typ, stride, binding, pointer), unit in arrays:
                if unit is not None:
                    v.lib.gles_ClientActiveTexture(v.p, C.GL_TEXTURE0 + unit)
                if not v.is_enabled(cap) or v.get_int(binding):
                    continue  # the core checks buffer objects itself
                address = v.pointer(pointer)
                if address == 0:
                    continue  # the core refuses a NULL array
                if address not in owned:
                    raise ValueError(
                        f"harness: an enabled array points at {address:#x}, memory it does not own"
                    )
                elem = (size if isinstance(size, int) and size < 16 else v.get_int(size)) * _TYPE_BYTES.get(
                    v.get_int(typ), 4
                )
                need = max_index * (v.get_int(stride) or elem) + elem
                if need > owned[address]:
                    raise ValueError(f"harness: the draw reads {need} bytes of a {owned[address]}-byte array")
        finally:
            v.lib.gles_ClientActiveTexture(v.p, active)

    def max_index(self, count: int, typ: int, indices: Any) -> int | None:
        """The largest index glDrawElements would read (None: it reads none)."""
        v = self.view
        isize = {C.GL_UNSIGNED_BYTE: 1, C.GL_UNSIGNED_SHORT: 2}.get(typ)
        if isize is None or count <= 0:
            return None
        dtype = np.uint8 if isize == 1 else np.uint16
        element = v.get_int(C.GL_ELEMENT_ARRAY_BUFFER_BINDING)
        if element:
            if _is_address(indices):
                offset = int(indices)
            elif isinstance(indices, np.ndarray):
                from gles import mesa

                offset = mesa._addr(indices)
            else:
                offset = 0 if indices is None else -1
            data = self.buffers.get(element)
            if data is None:
                return 255 if isize == 1 else 65535  # unknown contents: the worst case
            if not 0 <= offset <= len(data) - count * isize:
                return None  # the core refuses the range
            raw = data[offset : offset + count * isize]
        else:
            if _is_address(indices):
                if indices:
                    raise ValueError("harness: an int index pointer needs a bound element buffer")
                return None
            if indices is None:
                return None
            raw = _client_bytes(indices, dtype)
            if raw is None:
                raise ValueError("harness: index data it cannot read")
            if len(raw) < count * isize:
                return None  # the wrapper refuses it (ValueError)
            raw = raw[: count * isize]
        return int(np.frombuffer(raw, dtype).max())


# the values a vector command reads (csrc/cabi/gl.c's param_count): these
# pnames' counts, else 1
_VECTOR_COUNTS = {
    "Light": {C.GL_AMBIENT: 4, C.GL_DIFFUSE: 4, C.GL_SPECULAR: 4, C.GL_POSITION: 4, C.GL_SPOT_DIRECTION: 3},
    "Material": {
        C.GL_AMBIENT: 4,
        C.GL_DIFFUSE: 4,
        C.GL_SPECULAR: 4,
        C.GL_EMISSION: 4,
        C.GL_AMBIENT_AND_DIFFUSE: 4,
    },
    "LightModel": {C.GL_LIGHT_MODEL_AMBIENT: 4},
    "Fog": {C.GL_FOG_COLOR: 4},
    "PointParameter": {C.GL_POINT_DISTANCE_ATTENUATION: 3},
    "TexParameter": {C.GL_TEXTURE_CROP_RECT_OES: 4},
    "TexEnv": {C.GL_TEXTURE_ENV_COLOR: 4},
    "TexGen": {},
}
_VECTOR_COMMAND = re.compile(
    r"gl(LightModel|Light|Material|Fog|PointParameter|TexParameter|TexEnv|TexGen)[fix]v(OES)?$"
)


def _values(obj: Any) -> int | None:
    """How many values a vector argument holds (None: the wrapper decides)."""
    if isinstance(obj, np.ndarray):
        return obj.size
    if isinstance(obj, (bytes, bytearray)):
        return len(obj) // 4
    if isinstance(obj, (list, tuple)):
        return len(obj)
    return 1 if isinstance(obj, float) else None


# the KHR_debug commands whose last two arguments are (length, string), with
# the GL limit of the string's length
_DEBUG_STRINGS = {"glDebugMessageInsertKHR": 1024, "glPushDebugGroupKHR": 1024, "glObjectLabelKHR": 256,
                  "glObjectPtrLabelKHR": 256}


def _guard(cc: CabiContext, name: str, args: list[Any]) -> None:
    """Refuse (ValueError) a call whose pointers a correct C program would not pass."""
    v = cc.view
    vector = _VECTOR_COMMAND.match(name)
    if vector and len(args) >= 2 and args[-1] is not None:
        need = _VECTOR_COUNTS[vector.group(1)].get(args[-2], 1)
        held = _values(args[-1])
        if held is not None and held < need:
            raise ValueError(f"harness: {name} reads {need} values, the array holds {held}")
    if name in _POINTER_COMMANDS:
        if _is_address(args[-1]) and args[-1] and not v.get_int(C.GL_ARRAY_BUFFER_BINDING):
            raise ValueError("harness: an int array pointer needs a bound array buffer")
    elif name == "glDrawArrays" and len(args) == 3:
        first, count = args[1], args[2]
        if _is_address(first) and _is_address(count) and count > 0 and first >= 0:
            cc.check_arrays(int(first) + int(count) - 1)
    elif name == "glDrawElements" and len(args) == 4:
        if _is_address(args[1]) and _is_address(args[2]) and 0 < args[1] < 2**31:
            hi = cc.max_index(int(args[1]), int(args[2]), args[3])
            if hi is not None:
                cc.check_arrays(hi)
    elif name in ("glMultiDrawArraysEXT", "glMultiDrawElementsEXT") and len(args) in (4, 5):
        # each list as the draw it makes; C reads primcount items of each list
        n = args[-1]
        lists = (args[1], args[2]) if name == "glMultiDrawArraysEXT" else (args[1], args[3])
        if _is_address(n) and n > 0:
            if any(not isinstance(x, (list, tuple)) or len(x) < n for x in lists):
                raise ValueError("harness: a list shorter than primcount")
            for i in range(int(n)):
                if name == "glMultiDrawArraysEXT":
                    _guard(cc, "glDrawArrays", [args[0], lists[0][i], lists[1][i]])
                    continue
                count, indices = lists[0][i], lists[1][i]
                # the one wrapper check glDrawElements has and a list of pointers has not
                isize = {C.GL_UNSIGNED_BYTE: 1, C.GL_UNSIGNED_SHORT: 2}.get(args[2], 0)
                if isinstance(indices, np.ndarray) and _is_address(count) and count > 0 \
                        and indices.nbytes < int(count) * isize:
                    raise ValueError("harness: an index array shorter than its count")
                _guard(cc, "glDrawElements", [args[0], count, args[2], indices])
    elif name in ("glTexImage2D", "glTexSubImage2D") and len(args) == 9:
        data, w, h, fmt, typ = (
            args[8],
            args[3 if name == "glTexImage2D" else 4],
            args[4 if name == "glTexImage2D" else 5],
            args[6],
            args[7],
        )
        if _is_address(data):
            if data:
                raise ValueError("harness: an int image pointer (ES 1.1 has no pixel buffers)")
        elif data is not None and all(_is_address(x) and 0 < x <= _MAX_IMAGE_SIDE for x in (w, h)):
            # texture_image_bytes is defined for sizes the core accepts; it
            # refuses larger ones before it reads (if not, a sanitizer sees it)
            need = int(v.lib.texture_image_bytes(v.p, w, h, fmt & 0xFFFFFFFF, typ & 0xFFFFFFFF))
            raw = _client_bytes(data, np.uint8)
            if raw is None or need > len(raw):
                raise ValueError(f"harness: the image reads {need} bytes of shorter data")
    elif name in _DEBUG_STRINGS and len(args) >= 2:
        # a length >= 0 below the GL limit makes C read that many characters
        length, text, limit = args[-2], args[-1], _DEBUG_STRINGS[name]
        if isinstance(text, (str, bytes)) and _is_address(length) and 0 <= length < limit:
            if length > len(text.encode("utf-8") if isinstance(text, str) else text):
                raise ValueError(f"harness: {name} reads {length} characters of a shorter string")
    elif name == "glGetDebugMessageLogKHR" and len(args) == 8:
        count, size = args[0], args[1]
        for a in args[2:7]:
            if a is not None and _is_address(count) and (not isinstance(a, np.ndarray) or a.size < count):
                raise ValueError("harness: an output array shorter than count")
        log = args[7]
        if log is not None and _is_address(size) and size > 0 and (
                not isinstance(log, (bytearray, np.ndarray)) or len(log) < size):
            raise ValueError("harness: messageLog shorter than bufSize")
    elif name in ("glCompressedTexImage2D", "glCompressedTexSubImage2D", "glBufferData", "glBufferSubData"):
        data = args[2] if name == "glBufferData" else args[-1]
        if _is_address(data) and data:
            raise ValueError(f"harness: an int data pointer in {name}")
    elif name in ("glGenBuffers", "glGenTextures", "glGenVertexArraysOES", "glGenFramebuffersOES",
                  "glGenRenderbuffersOES") and args and _is_address(args[0]):
        if args[0] > _MAX_NAMES:
            raise ValueError(f"harness: room for {args[0]} names")
    elif name == "glReadPixels" and len(args) >= 4:
        w, h = args[2], args[3]
        if _is_address(w) and _is_address(h) and w > 0 and h > 0 and w * h > _MAX_READ_PIXELS:
            raise ValueError(f"harness: room for {w}x{h} pixels")


def _after_buffer_data(cc: CabiContext, name: str, args: list[Any], bound: int) -> None:
    """Track what buffer objects hold, for the index range of glDrawElements."""
    if not bound or cc.view.peek_error():
        return
    if name == "glBufferData":
        size, data = int(args[1]), args[2]
        if data is None:
            cc.buffers[bound] = bytes(size) if size <= 1 << 24 else None
        else:
            raw = _client_bytes(data, np.uint8)
            cc.buffers[bound] = None if raw is None else raw[:size]
    else:
        offset, size, old = int(args[1]), int(args[2]), cc.buffers.get(bound)
        raw = _client_bytes(args[3], np.uint8)
        if old is None or raw is None:
            cc.buffers[bound] = None
        else:
            cc.buffers[bound] = old[:offset] + raw[:size] + old[offset + size :]


class _GuardedGL:
    """``ctx.gl`` of a CabiContext: the LibraryContext's commands behind the guards."""

    def __init__(self, cc: CabiContext) -> None:
        self._cc = cc

    def __getattr__(self, name: str) -> Any:
        fn = getattr(self._cc.library.gl, name)
        if not name.startswith("gl"):
            return fn
        cc = self._cc

        def command(*given: Any) -> Any:
            args = _to_c_ints(name, list(given))
            _guard(cc, name, args)
            if name in ("glBufferData", "glBufferSubData") and len(args) == 4:
                target = args[0]
                binding = {
                    C.GL_ARRAY_BUFFER: C.GL_ARRAY_BUFFER_BINDING,
                    C.GL_ELEMENT_ARRAY_BUFFER: C.GL_ELEMENT_ARRAY_BUFFER_BINDING,
                }.get(target)
                bound = cc.view.get_int(binding) if binding else 0
                out = fn(*args)
                _after_buffer_data(cc, name, list(args), bound)
                return out
            return fn(*args)

        command.__name__ = name
        return command

    def null_pointers(self, name: str, *args: Any) -> Any:
        """Call the C entry point `name` with NULL for each pointer argument
        (the other arguments in their places; output pointers the Python
        convention leaves out are NULL too)."""
        import ctypes

        cc = self._cc
        cargs = [
            None if t == "*" else (args[i] if i < len(args) else 0) for i, t in enumerate(_c_params(name))
        ]
        cargs = _to_c_ints(name, cargs)
        _guard(cc, name, cargs)
        cc.library.make_current()
        try:
            return cc.library._raw[name](*cargs)
        except ctypes.ArgumentError as e:
            raise TypeError(f"{name}: {e}") from None


# {====================================================================
# running and the invariant


def open_context(setup: Setup) -> tuple[Any, CoreView, Callable[[], None]]:
    """(ctx.gl, the core view, close) of the setup's backend."""
    config = dict(profile=setup.profile, numeric=setup.numeric, color=setup.color, depth=setup.depth,
                  stencil=setup.stencil, memory_limit=setup.memory_limit)
    if setup.backend == "cabi":
        cc = CabiContext(setup.width, setup.height, **config)
        return cc.gl, cc.view, cc.close
    ctx = gles.Context(setup.width, setup.height, range_check=setup.range_check, **config)
    ctx.check_errors = setup.backend == "checked"
    return ctx.gl, context_view(ctx), lambda: None


def run_sequence(setup: Setup, calls: list[Call], check_state: bool = True) -> int:
    """Run the calls on a new context; raise Failure where the invariant
    breaks. Returns the number of calls made."""
    g, view, close = open_context(setup)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for i, call in enumerate(calls):
                _check_call(setup, g, view, i, call, check_state)
    finally:
        close()
    return len(calls)


def _check_call(setup: Setup, g: Any, view: CoreView, i: int, call: Call, check_state: bool) -> None:
    before = snapshot(view) if check_state else None
    raised = None
    try:
        getattr(g, call.name)(*[a.value for a in call.args])
    except ALLOWED as e:
        raised = e
    except Exception as e:  # noqa: BLE001 -- anything else breaks the invariant
        raise Failure(i, f"{type(e).__name__} in {call.name}", f"{call.name}: {e}") from e
    err = g.glGetError()
    if err not in ERRORS:
        raise Failure(i, f"bad error code after {call.name}", f"glGetError returned {err:#x}")
    if raised is not None and err != C.GL_NO_ERROR:
        raise Failure(
            i,
            f"error and exception in {call.name}",
            f"{call.name}: raised {type(raised).__name__} and recorded {err:#x}",
        )
    if setup.backend == "checked" and err != C.GL_NO_ERROR:
        raise Failure(i, f"error not raised by {call.name}", f"{call.name} recorded {err:#x} without GLError")
    if check_state and (raised is not None or err != C.GL_NO_ERROR):
        after = snapshot(view)
        if after != before:
            diff = [k for k, (a, b) in enumerate(zip(before, after)) if a != b]
            why = f"raised {type(raised).__name__}" if raised is not None else f"error {err:#x}"
            raise Failure(
                i,
                f"state changed by {call.name}",
                f"{call.name} ({why}) changed snapshot entries {diff[:6]}",
            )


def reproduction(setup: Setup, calls: list[Call]) -> str:
    lines = ["import numpy as np", "import gles", "from gles import gl as G"]
    if setup.backend == "cabi":
        lines[1:2] = ["import sys", f"sys.path.insert(0, {str(ROOT / 'tools')!r})", "import fuzz"]
    lines += [setup.text(), "g = ctx.gl"]
    lines += [c.text() for c in calls]
    return "\n".join(lines)


# {====================================================================
# workers, shrinking and the command line


def _worker(first: int, last: int, max_calls: int, backend: str) -> None:
    """Run seeds first..last-1, one line per sequence on stdout."""
    for seed in range(first, last):
        setup, calls = make_sequence(seed, max_calls, backend)
        print(f"start {seed}", flush=True)
        try:
            n = run_sequence(setup, calls)
        except Failure as f:
            print(f"fail {seed} {f.index} {f.kind}|{f.detail}", flush=True)
            sys.exit(3)
        print(f"ok {seed} {n}", flush=True)


def _run_file(path: str) -> None:
    """Run a pickled (setup, calls) in this process; exit 3 on a Failure."""
    with open(path, "rb") as fh:
        setup, calls = pickle.load(fh)
    try:
        run_sequence(setup, calls)
    except Failure as f:
        print(f"fail {f.index} {f.kind}|{f.detail}", flush=True)
        sys.exit(3)


def _outcome(setup: Setup, calls: list[Call], timeout: float) -> str | None:
    """How a candidate sequence fails in a fresh process ("crash", "hang",
    or the invariant's kind), or None when it passes."""
    with tempfile.NamedTemporaryFile("wb", suffix=".pkl", delete=False) as fh:
        pickle.dump((setup, calls), fh)
        path = fh.name
    try:
        p = subprocess.run(
            [sys.executable, __file__, "--run-file", path], capture_output=True, text=True, timeout=timeout
        )
    except subprocess.TimeoutExpired:
        return "hang"
    finally:
        os.unlink(path)
    if p.returncode == 0:
        return None
    if p.returncode == 1 and "Traceback" in p.stderr and "runtime error" not in p.stderr:
        return "harness error"  # a Python traceback outside the invariant
    if p.returncode == 3:
        line = [ln for ln in p.stdout.splitlines() if ln.startswith("fail ")][-1]
        return line.split(" ", 2)[2].split("|")[0]
    return "crash"


def shrink(setup: Setup, calls: list[Call], kind: str, timeout: float, budget: float = 300.0) -> list[Call]:
    """The smallest subsequence found (removing chunks, then single calls)
    that still fails the same way."""
    t_end = time.monotonic() + budget
    chunk = max(len(calls) // 2, 1)
    while chunk >= 1 and time.monotonic() < t_end:
        i, changed = 0, False
        while i < len(calls) and time.monotonic() < t_end:
            cand = calls[:i] + calls[i + chunk :]
            if cand and _outcome(setup, cand, timeout) == kind:
                calls, changed = cand, True
            else:
                i += chunk
        if not changed:
            chunk //= 2
    return calls


def fuzz(
    seeds: range | None,
    minutes: float,
    start: int,
    max_calls: int,
    seq_timeout: float,
    batch: int = 25,
    backend: str = "python",
) -> int:
    """Run seeds (a fixed range, or from `start` for `minutes`); returns the
    number of failing sequences found."""
    t_end = time.monotonic() + minutes * 60 if seeds is None else float("inf")
    seq = calls_total = failures = 0
    nxt = start if seeds is None else seeds.start
    stop = None if seeds is None else seeds.stop
    t0 = time.monotonic()
    while (stop is None or nxt < stop) and time.monotonic() < t_end:
        last = nxt + batch if stop is None else min(nxt + batch, stop)
        proc = subprocess.Popen(
            [
                sys.executable,
                __file__,
                "--worker",
                f"{nxt}:{last}",
                "--max-calls",
                str(max_calls),
                "--backend",
                backend,
            ],
            stdout=subprocess.PIPE,
            text=True,
        )
        current, failed = None, None
        lines = _lines(proc)
        while True:
            try:
                line = lines.get(timeout=seq_timeout)
            except queue.Empty:  # a hang
                proc.kill()
                failed = (current, "hang", f"no sequence end in {seq_timeout} s")
                break
            if not line:
                break
            word, rest = line.split(" ", 1)
            if word == "start":
                current = int(rest)
            elif word == "ok":
                seq += 1
                calls_total += int(rest.split()[1])
                current = None
            elif word == "fail":
                s, _, what = rest.split(" ", 2)
                failed = (int(s), what.split("|")[0], what)
        rc = proc.wait()
        if failed is None and rc != 0 and current is not None:
            failed = (current, "crash", f"worker exit status {rc}")
        if failed is not None and failed[0] is not None:
            failures += 1
            s, kind, what = failed
            setup, calls = make_sequence(s, max_calls, backend)
            print(f"seed {s}: {what}", flush=True)
            small = shrink(setup, calls, kind, seq_timeout)
            print(f"--- seed {s}, {kind}, shrunk from {len(calls)} to {len(small)} calls:")
            print(reproduction(setup, small))
            print("---", flush=True)
            nxt = s + 1
        else:
            nxt = last
    dt = time.monotonic() - t0
    first = start if seeds is None else seeds.start
    print(
        f"fuzz ({backend}): {seq} sequences, {calls_total} calls, seeds {first}..{nxt - 1}, "
        f"{dt / 60:.1f} min, {failures} failing",
        flush=True,
    )
    return failures


def _lines(proc: subprocess.Popen) -> queue.Queue:
    """The worker's stdout lines, read by a thread ('' at its end)."""
    q: queue.Queue = queue.Queue()

    def read() -> None:
        assert proc.stdout is not None
        for line in proc.stdout:
            q.put(line.strip())
        q.put("")

    threading.Thread(target=read, daemon=True).start()
    return q


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--minutes", type=float, default=1.0, help="how long to run (default 1)")
    ap.add_argument("--seed", type=int, default=0, help="the first seed (default 0)")
    ap.add_argument("--seeds", help="a fixed seed range A:B instead of --minutes")
    ap.add_argument("--max-calls", type=int, default=120, help="longest sequence (default 120)")
    ap.add_argument(
        "--seq-timeout",
        type=float,
        default=60.0,
        help="seconds one sequence may take before it counts as a hang (default 60)",
    )
    ap.add_argument(
        "--backend",
        choices=BACKENDS + ("mixed",),
        default="python",
        help="python: gles.Context; checked: with check_errors=True; cabi: the C ABI libraries "
        "through a ctypes harness; mixed: one of the three per seed (default python)",
    )
    ap.add_argument("--cabi", action="store_true", help="the same as --backend cabi")
    ap.add_argument("--replay", type=int, help="run one seed here and print its reproduction on failure")
    ap.add_argument("--worker", help=argparse.SUPPRESS)
    ap.add_argument("--run-file", help=argparse.SUPPRESS)
    a = ap.parse_args(argv)
    if a.cabi:
        a.backend = "cabi"
    if a.worker:
        lo, hi = (int(v) for v in a.worker.split(":"))
        _worker(lo, hi, a.max_calls, a.backend)
        return 0
    if a.run_file:
        _run_file(a.run_file)
        return 0
    if a.replay is not None:
        setup, calls = make_sequence(a.replay, a.max_calls, a.backend)
        print(reproduction(setup, calls))
        run_sequence(setup, calls)
        print("ok")
        return 0
    seeds = None
    if a.seeds:
        lo, hi = (int(v) for v in a.seeds.split(":"))
        seeds = range(lo, hi)
    return 1 if fuzz(seeds, a.minutes, a.seed, a.max_calls, a.seq_timeout, backend=a.backend) else 0


if __name__ == "__main__":
    sys.exit(main())
