"""Queries: state tables, OES_matrix_get, OES_query_matrix, OES_read_format.

Categories Gets, Gets.extensions, MatrixGetTest, MatrixQuery and ReadFormat
(spec sections 6.1, 6.2 with Tables 6.3-6.24, 2.10.2 and 4.3.1).

:data:`STATE` is the ES 1.1.12 state tables as data: one row per value with
its table, its kind (how Get converts it, section 6.1.2) and its initial
value (or minimum, for the implementation-dependent ones). ``tests/
test_state_tables.py`` drives the same rows through every gles build.

Rows with ``ext`` set come from an extension's New State tables
(OES_texture_cube_map, KHR_debug); they are checked only when GL_EXTENSIONS
names the extension, by Gets.extensions rather than Gets, so that an
implementation's difference in them shows apart from the core tables'.
The table of such a row is the extension's own (its numbering).

Conversion rules checked (section 6.1.2): GetBooleanv is FALSE iff zero;
GetIntegerv rounds to nearest, except colours, normals, DepthRange and the
depth clear value, which map [-1, 1] onto the integer range (Table 4.4);
GetFixedv scales by 2^16 (booleans become 1.0 or 0.0) and leaves enums
unscaled; GetFloatv coerces. The spec does not say how GetFixedv rounds a
float times 2^16 ("converted to an integer representation"), so one unit of
slack is allowed there, and the colour mapping of GetIntegerv is checked to
2^-16 of the range (Common precision is about 1 part in 10^5, section 2.1.1).
ALPHA_TEST_REF is not in the section 6.1.2 list of mapped values, but it is
the reference for a colour component; either reading is accepted.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from gles import constants as C

from ..harness import TestContext, Unsupported, conformance_test

ONE = 1 << 16
KINDS = ("int", "enum", "bool", "float", "norm", "ref", "mask")


def fx(v: float) -> int:
    """A real as the 16.16 integer nearest to it."""
    return int(np.floor(v * ONE + 0.5))


def unfx(i: int) -> float:
    return i / ONE


@dataclass(frozen=True)
class Env:
    """What initial values depend on: window size, framebuffer bits."""

    width: int
    height: int
    bits: tuple[int, int, int, int]
    depth: int
    stencil: int
    lite: bool = False  # a Common-Lite context (section 2.8: array types start FIXED)


@dataclass(frozen=True)
class StateValue:
    """One row of Tables 6.3-6.24 queried with Get{Boolean,Integer,Fixed,Float}v."""

    name: str  # GL_* constant name
    kind: str  # one of KINDS
    table: str  # "6.16"
    initial: Any  # tuple of reals/enums, or callable(Env) -> tuple
    minimum: bool = False  # implementation dependent: initial is a lower bound
    enable: bool = False  # also an IsEnabled / EnableClientState capability
    ext: str | None = None  # checked only when GL_EXTENSIONS names this extension

    @property
    def pname(self) -> int:
        return int(getattr(C, self.name))

    def want(self, env: Env) -> tuple:
        return tuple(self.initial(env)) if callable(self.initial) else tuple(self.initial)


def ARRAY_TYPE0(e: Env) -> tuple:  # noqa: N802  (a table value)
    """Section 2.8: FLOAT for the Common profile, FIXED for Common-Lite."""
    return (C.GL_FIXED if e.lite else C.GL_FLOAT,)


I4 = (1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0)

CUBE_EXT = "GL_OES_texture_cube_map"
DEBUG_EXT = "GL_KHR_debug"


def _rows() -> list[StateValue]:
    S = StateValue
    rows = [
        # Table 6.3 Current values
        S("GL_CURRENT_COLOR", "norm", "6.3", (1, 1, 1, 1)),
        S("GL_CURRENT_TEXTURE_COORDS", "float", "6.3", (0, 0, 0, 1)),
        S("GL_CURRENT_NORMAL", "norm", "6.3", (0, 0, 1)),
        # Tables 6.4, 6.5 Vertex array data
        S("GL_CLIENT_ACTIVE_TEXTURE", "enum", "6.4", (C.GL_TEXTURE0,)),
        S("GL_VERTEX_ARRAY", "bool", "6.4", (0,), enable=True),
        S("GL_VERTEX_ARRAY_SIZE", "int", "6.4", (4,)),
        S("GL_VERTEX_ARRAY_TYPE", "enum", "6.4", ARRAY_TYPE0),
        S("GL_VERTEX_ARRAY_STRIDE", "int", "6.4", (0,)),
        S("GL_NORMAL_ARRAY", "bool", "6.4", (0,), enable=True),
        S("GL_NORMAL_ARRAY_TYPE", "enum", "6.4", ARRAY_TYPE0),
        S("GL_NORMAL_ARRAY_STRIDE", "int", "6.4", (0,)),
        S("GL_COLOR_ARRAY", "bool", "6.4", (0,), enable=True),
        S("GL_COLOR_ARRAY_SIZE", "int", "6.4", (4,)),
        S("GL_COLOR_ARRAY_TYPE", "enum", "6.5", ARRAY_TYPE0),
        S("GL_COLOR_ARRAY_STRIDE", "int", "6.5", (0,)),
        S("GL_TEXTURE_COORD_ARRAY", "bool", "6.5", (0,), enable=True),
        S("GL_TEXTURE_COORD_ARRAY_SIZE", "int", "6.5", (4,)),
        S("GL_TEXTURE_COORD_ARRAY_TYPE", "enum", "6.5", ARRAY_TYPE0),
        S("GL_TEXTURE_COORD_ARRAY_STRIDE", "int", "6.5", (0,)),
        S("GL_POINT_SIZE_ARRAY_OES", "bool", "6.5", (0,), enable=True),
        S("GL_POINT_SIZE_ARRAY_TYPE_OES", "enum", "6.5", ARRAY_TYPE0),
        S("GL_POINT_SIZE_ARRAY_STRIDE_OES", "int", "6.5", (0,)),
        S("GL_ARRAY_BUFFER_BINDING", "int", "6.5", (0,)),
        S("GL_VERTEX_ARRAY_BUFFER_BINDING", "int", "6.5", (0,)),
        S("GL_NORMAL_ARRAY_BUFFER_BINDING", "int", "6.5", (0,)),
        S("GL_COLOR_ARRAY_BUFFER_BINDING", "int", "6.5", (0,)),
        S("GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING", "int", "6.5", (0,)),
        S("GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES", "int", "6.5", (0,)),
        S("GL_ELEMENT_ARRAY_BUFFER_BINDING", "int", "6.5", (0,)),
        # Table 6.7 Transformation state
        S("GL_MODELVIEW_MATRIX", "float", "6.7", I4),
        S("GL_PROJECTION_MATRIX", "float", "6.7", I4),
        S("GL_TEXTURE_MATRIX", "float", "6.7", I4),
        S("GL_VIEWPORT", "int", "6.7", lambda e: (0, 0, e.width, e.height)),
        S("GL_DEPTH_RANGE", "norm", "6.7", (0, 1)),
        S("GL_MODELVIEW_STACK_DEPTH", "int", "6.7", (1,)),
        S("GL_PROJECTION_STACK_DEPTH", "int", "6.7", (1,)),
        S("GL_TEXTURE_STACK_DEPTH", "int", "6.7", (1,)),
        S("GL_MATRIX_MODE", "enum", "6.7", (C.GL_MODELVIEW,)),
        S("GL_NORMALIZE", "bool", "6.7", (0,), enable=True),
        S("GL_RESCALE_NORMAL", "bool", "6.7", (0,), enable=True),
        S("GL_CLIP_PLANE0", "bool", "6.7", (0,), enable=True),
        # Table 6.8 Coloring
        S("GL_FOG_COLOR", "norm", "6.8", (0, 0, 0, 0)),
        S("GL_FOG_DENSITY", "float", "6.8", (1,)),
        S("GL_FOG_START", "float", "6.8", (0,)),
        S("GL_FOG_END", "float", "6.8", (1,)),
        S("GL_FOG_MODE", "enum", "6.8", (C.GL_EXP,)),
        S("GL_FOG", "bool", "6.8", (0,), enable=True),
        S("GL_SHADE_MODEL", "enum", "6.8", (C.GL_SMOOTH,)),
        # Table 6.9 Lighting (materials: MATERIAL_STATE)
        S("GL_LIGHTING", "bool", "6.9", (0,), enable=True),
        S("GL_COLOR_MATERIAL", "bool", "6.9", (0,), enable=True),
        S("GL_LIGHT_MODEL_AMBIENT", "norm", "6.9", (0.2, 0.2, 0.2, 1.0)),
        S("GL_LIGHT_MODEL_TWO_SIDE", "bool", "6.9", (0,)),
        # Table 6.10 Lighting (cont.) (light parameters: LIGHT_STATE)
        *[S(f"GL_LIGHT{i}", "bool", "6.10", (0,), enable=True) for i in range(8)],
        # Table 6.11 Rasterization
        S("GL_POINT_SIZE", "float", "6.11", (1,)),
        S("GL_POINT_SMOOTH", "bool", "6.11", (0,), enable=True),
        S("GL_POINT_SIZE_MIN", "float", "6.11", (0,)),
        S("GL_POINT_SIZE_MAX", "float", "6.11", (1,), minimum=True),
        S("GL_POINT_FADE_THRESHOLD_SIZE", "float", "6.11", (1,)),
        S("GL_POINT_DISTANCE_ATTENUATION", "float", "6.11", (1, 0, 0)),
        S("GL_POINT_SPRITE_OES", "bool", "6.11", (0,), enable=True),
        S("GL_LINE_WIDTH", "float", "6.11", (1,)),
        S("GL_LINE_SMOOTH", "bool", "6.11", (0,), enable=True),
        S("GL_CULL_FACE", "bool", "6.11", (0,), enable=True),
        S("GL_CULL_FACE_MODE", "enum", "6.11", (C.GL_BACK,)),
        S("GL_FRONT_FACE", "enum", "6.11", (C.GL_CCW,)),
        S("GL_POLYGON_OFFSET_FACTOR", "float", "6.11", (0,)),
        S("GL_POLYGON_OFFSET_UNITS", "float", "6.11", (0,)),
        S("GL_POLYGON_OFFSET_FILL", "bool", "6.11", (0,), enable=True),
        # Table 6.12 Multisampling
        S("GL_MULTISAMPLE", "bool", "6.12", (1,), enable=True),
        S("GL_SAMPLE_ALPHA_TO_COVERAGE", "bool", "6.12", (0,), enable=True),
        S("GL_SAMPLE_ALPHA_TO_ONE", "bool", "6.12", (0,), enable=True),
        S("GL_SAMPLE_COVERAGE", "bool", "6.12", (0,), enable=True),
        S("GL_SAMPLE_COVERAGE_VALUE", "float", "6.12", (1,)),
        S("GL_SAMPLE_COVERAGE_INVERT", "bool", "6.12", (0,)),
        # Table 6.13 Textures (per unit)
        S("GL_TEXTURE_2D", "bool", "6.13", (0,), enable=True),
        S("GL_TEXTURE_BINDING_2D", "int", "6.13", (0,)),
        # Table 6.15 Texture environment (TEXENV_STATE for the GetTexEnv rows)
        S("GL_ACTIVE_TEXTURE", "enum", "6.15", (C.GL_TEXTURE0,)),
        # Table 6.16 Pixel operations
        S("GL_SCISSOR_TEST", "bool", "6.16", (0,), enable=True),
        S("GL_SCISSOR_BOX", "int", "6.16", lambda e: (0, 0, e.width, e.height)),
        S("GL_ALPHA_TEST", "bool", "6.16", (0,), enable=True),
        S("GL_ALPHA_TEST_FUNC", "enum", "6.16", (C.GL_ALWAYS,)),
        S("GL_ALPHA_TEST_REF", "ref", "6.16", (0,)),
        S("GL_STENCIL_TEST", "bool", "6.16", (0,), enable=True),
        S("GL_STENCIL_FUNC", "enum", "6.16", (C.GL_ALWAYS,)),
        S("GL_STENCIL_VALUE_MASK", "mask", "6.16", (-1,)),
        S("GL_STENCIL_REF", "int", "6.16", (0,)),
        S("GL_STENCIL_FAIL", "enum", "6.16", (C.GL_KEEP,)),
        S("GL_STENCIL_PASS_DEPTH_FAIL", "enum", "6.16", (C.GL_KEEP,)),
        S("GL_STENCIL_PASS_DEPTH_PASS", "enum", "6.16", (C.GL_KEEP,)),
        S("GL_DEPTH_TEST", "bool", "6.16", (0,), enable=True),
        S("GL_DEPTH_FUNC", "enum", "6.16", (C.GL_LESS,)),
        S("GL_BLEND", "bool", "6.16", (0,), enable=True),
        S("GL_BLEND_SRC", "enum", "6.16", (C.GL_ONE,)),
        S("GL_BLEND_DST", "enum", "6.16", (C.GL_ZERO,)),
        S("GL_DITHER", "bool", "6.16", (1,), enable=True),
        S("GL_COLOR_LOGIC_OP", "bool", "6.16", (0,), enable=True),
        S("GL_LOGIC_OP_MODE", "enum", "6.16", (C.GL_COPY,)),
        # Table 6.17 Framebuffer control
        S("GL_COLOR_WRITEMASK", "bool", "6.17", (1, 1, 1, 1)),
        S("GL_DEPTH_WRITEMASK", "bool", "6.17", (1,)),
        S("GL_STENCIL_WRITEMASK", "mask", "6.17", (-1,)),
        S("GL_COLOR_CLEAR_VALUE", "norm", "6.17", (0, 0, 0, 0)),
        S("GL_DEPTH_CLEAR_VALUE", "norm", "6.17", (1,)),
        S("GL_STENCIL_CLEAR_VALUE", "int", "6.17", (0,)),
        # Table 6.18 Pixels
        S("GL_UNPACK_ALIGNMENT", "int", "6.18", (4,)),
        S("GL_PACK_ALIGNMENT", "int", "6.18", (4,)),
        # Table 6.19 Hints
        *[
            S(f"GL_{h}_HINT", "enum", "6.19", (C.GL_DONT_CARE,))
            for h in ("PERSPECTIVE_CORRECTION", "POINT_SMOOTH", "LINE_SMOOTH", "FOG", "GENERATE_MIPMAP")
        ],
        # Tables 6.20-6.22 Implementation dependent values (minimums)
        S("GL_MAX_LIGHTS", "int", "6.20", (8,), minimum=True),
        S("GL_MAX_CLIP_PLANES", "int", "6.20", (1,), minimum=True),
        S("GL_MAX_MODELVIEW_STACK_DEPTH", "int", "6.20", (16,), minimum=True),
        S("GL_MAX_PROJECTION_STACK_DEPTH", "int", "6.20", (2,), minimum=True),
        S("GL_MAX_TEXTURE_STACK_DEPTH", "int", "6.20", (2,), minimum=True),
        S("GL_SUBPIXEL_BITS", "int", "6.20", (4,), minimum=True),
        S("GL_MAX_TEXTURE_SIZE", "int", "6.20", (64,), minimum=True),
        S("GL_MAX_VIEWPORT_DIMS", "int", "6.20", lambda e: (e.width, e.height), minimum=True),
        S("GL_ALIASED_POINT_SIZE_RANGE", "float", "6.21", (1, 1), minimum=True),
        S("GL_SMOOTH_POINT_SIZE_RANGE", "float", "6.21", (1, 1), minimum=True),
        S("GL_ALIASED_LINE_WIDTH_RANGE", "float", "6.21", (1, 1), minimum=True),
        S("GL_SMOOTH_LINE_WIDTH_RANGE", "float", "6.21", (1, 1), minimum=True),
        S("GL_MAX_TEXTURE_UNITS", "int", "6.22", (2,), minimum=True),
        S("GL_SAMPLE_BUFFERS", "int", "6.22", (0,), minimum=True),
        S("GL_SAMPLES", "int", "6.22", (0,), minimum=True),
        S("GL_NUM_COMPRESSED_TEXTURE_FORMATS", "int", "6.22", (10,), minimum=True),
        # Table 6.23 Implementation dependent pixel depths
        S("GL_RED_BITS", "int", "6.23", lambda e: (e.bits[0],)),
        S("GL_GREEN_BITS", "int", "6.23", lambda e: (e.bits[1],)),
        S("GL_BLUE_BITS", "int", "6.23", lambda e: (e.bits[2],)),
        S("GL_ALPHA_BITS", "int", "6.23", lambda e: (e.bits[3],)),
        S("GL_DEPTH_BITS", "int", "6.23", lambda e: (e.depth,)),
        S("GL_STENCIL_BITS", "int", "6.23", lambda e: (e.stencil,)),
        # OES_texture_cube_map New State: its table 6.12 (per texture unit), table 6.14
        # (TEXTURE_GEN_STR_OES, per unit; TEXTURE_GEN_MODE_OES: TEXGEN_STATE) and New
        # Implementation Dependent State, table 6.24 (a minimum)
        S("GL_TEXTURE_CUBE_MAP_OES", "bool", "6.12 OES_texture_cube_map", (0,), enable=True, ext=CUBE_EXT),
        S("GL_TEXTURE_BINDING_CUBE_MAP_OES", "int", "6.12 OES_texture_cube_map", (0,), ext=CUBE_EXT),
        S("GL_TEXTURE_GEN_STR_OES", "bool", "6.14 OES_texture_cube_map", (0,), enable=True, ext=CUBE_EXT),
        S("GL_MAX_CUBE_MAP_TEXTURE_SIZE_OES", "int", "6.24 OES_texture_cube_map", (16,), minimum=True,
          ext=CUBE_EXT),
        # KHR_debug New State: Debug Output State (DEBUG_OUTPUT is FALSE but in a debug context)
        # and New Implementation Dependent State, table 6.56 (minimums)
        S("GL_DEBUG_OUTPUT_KHR", "bool", "6.55 KHR_debug", (0,), enable=True, ext=DEBUG_EXT),
        S("GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR", "bool", "6.55 KHR_debug", (0,), enable=True, ext=DEBUG_EXT),
        S("GL_DEBUG_LOGGED_MESSAGES_KHR", "int", "6.55 KHR_debug", (0,), ext=DEBUG_EXT),
        S("GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR", "int", "6.55 KHR_debug", (0,), ext=DEBUG_EXT),
        S("GL_DEBUG_GROUP_STACK_DEPTH_KHR", "int", "6.55 KHR_debug", (1,), ext=DEBUG_EXT),
        S("GL_MAX_DEBUG_MESSAGE_LENGTH_KHR", "int", "6.56 KHR_debug", (1,), minimum=True, ext=DEBUG_EXT),
        S("GL_MAX_DEBUG_LOGGED_MESSAGES_KHR", "int", "6.56 KHR_debug", (1,), minimum=True, ext=DEBUG_EXT),
        S("GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR", "int", "6.56 KHR_debug", (64,), minimum=True, ext=DEBUG_EXT),
        S("GL_MAX_LABEL_LENGTH_KHR", "int", "6.56 KHR_debug", (256,), minimum=True, ext=DEBUG_EXT),
    ]
    return rows


STATE: list[StateValue] = _rows()
BY_NAME: dict[str, StateValue] = {s.name: s for s in STATE}
CORE_STATE: list[StateValue] = [s for s in STATE if s.ext is None]
EXT_STATE: list[StateValue] = [s for s in STATE if s.ext is not None]

# The ten OES_compressed_paletted_texture formats (Table 6.22 COMPRESSED_TEXTURE_FORMATS)
PALETTE_FORMATS = tuple(
    int(getattr(C, f"GL_PALETTE{n}_{f}_OES"))
    for n in (4, 8)
    for f in ("RGB8", "RGBA8", "R5_G6_B5", "RGBA4", "RGB5_A1")
)

# GetPointerv rows (Tables 6.4, 6.5): initial 0
POINTERS = (
    "GL_VERTEX_ARRAY_POINTER",
    "GL_NORMAL_ARRAY_POINTER",
    "GL_COLOR_ARRAY_POINTER",
    "GL_TEXTURE_COORD_ARRAY_POINTER",
    "GL_POINT_SIZE_ARRAY_POINTER_OES",
)

# Tables 6.9 (material, both faces) and 6.10 (per light); GetMaterial/GetLight
MATERIAL_STATE = (
    ("GL_AMBIENT", (0.2, 0.2, 0.2, 1.0)),
    ("GL_DIFFUSE", (0.8, 0.8, 0.8, 1.0)),
    ("GL_SPECULAR", (0, 0, 0, 1.0)),
    ("GL_EMISSION", (0, 0, 0, 1.0)),
    ("GL_SHININESS", (0,)),
)


def light_state(i: int) -> tuple[tuple[str, tuple], ...]:
    """Table 6.10 initial values of light i (Table 2.8: LIGHT0 differs)."""
    full = (1.0, 1.0, 1.0, 1.0) if i == 0 else (0, 0, 0, 1.0)
    return (
        ("GL_AMBIENT", (0, 0, 0, 1.0)),
        ("GL_DIFFUSE", full),
        ("GL_SPECULAR", full),
        ("GL_POSITION", (0, 0, 1.0, 0)),
        ("GL_CONSTANT_ATTENUATION", (1.0,)),
        ("GL_LINEAR_ATTENUATION", (0,)),
        ("GL_QUADRATIC_ATTENUATION", (0,)),
        ("GL_SPOT_DIRECTION", (0, 0, -1.0)),
        ("GL_SPOT_EXPONENT", (0,)),
        ("GL_SPOT_CUTOFF", (180.0,)),
    )


# Table 6.14 (per texture object; GetTexParameter): (name, kind, initial)
TEXPARAM_STATE = (
    ("GL_TEXTURE_MIN_FILTER", "enum", C.GL_NEAREST_MIPMAP_LINEAR),
    ("GL_TEXTURE_MAG_FILTER", "enum", C.GL_LINEAR),
    ("GL_TEXTURE_WRAP_S", "enum", C.GL_REPEAT),
    ("GL_TEXTURE_WRAP_T", "enum", C.GL_REPEAT),
    ("GL_GENERATE_MIPMAP", "bool", 0),
)

# Table 6.15 (per unit; GetTexEnv): (name, kind, initial)
TEXENV_STATE = (
    ("GL_TEXTURE_ENV_MODE", "enum", (C.GL_MODULATE,)),
    ("GL_TEXTURE_ENV_COLOR", "norm", (0, 0, 0, 0)),
    ("GL_COMBINE_RGB", "enum", (C.GL_MODULATE,)),
    ("GL_COMBINE_ALPHA", "enum", (C.GL_MODULATE,)),
    ("GL_SRC0_RGB", "enum", (C.GL_TEXTURE,)),
    ("GL_SRC1_RGB", "enum", (C.GL_PREVIOUS,)),
    ("GL_SRC2_RGB", "enum", (C.GL_CONSTANT,)),
    ("GL_SRC0_ALPHA", "enum", (C.GL_TEXTURE,)),
    ("GL_SRC1_ALPHA", "enum", (C.GL_PREVIOUS,)),
    ("GL_SRC2_ALPHA", "enum", (C.GL_CONSTANT,)),
    ("GL_OPERAND0_RGB", "enum", (C.GL_SRC_COLOR,)),
    ("GL_OPERAND1_RGB", "enum", (C.GL_SRC_COLOR,)),
    ("GL_OPERAND2_RGB", "enum", (C.GL_SRC_ALPHA,)),
    ("GL_OPERAND0_ALPHA", "enum", (C.GL_SRC_ALPHA,)),
    ("GL_OPERAND1_ALPHA", "enum", (C.GL_SRC_ALPHA,)),
    ("GL_OPERAND2_ALPHA", "enum", (C.GL_SRC_ALPHA,)),
    ("GL_RGB_SCALE", "float", (1.0,)),
    ("GL_ALPHA_SCALE", "float", (1.0,)),
)

# OES_texture_cube_map table 6.14 (per unit; GetTexGen*OES of TEXTURE_GEN_STR_OES): (name, kind, initial)
TEXGEN_STATE = (("GL_TEXTURE_GEN_MODE_OES", "enum", (C.GL_REFLECTION_MAP_OES,)),)


# {============================================================
# conversions (section 6.1.2)


def norm_to_int(v: float) -> int:
    """Table 4.4 INT: [-1, 1] onto [-2^31, 2^31 - 1], ((2^32 - 1) v - 1) / 2."""
    return int(np.clip(np.floor(((2.0**32 - 1) * v - 1) / 2 + 0.5), -(2**31), 2**31 - 1))


def _fixed_of(v: float) -> int:
    return int(np.clip(np.floor(v * ONE + 0.5), -(2**31), 2**31 - 1))


def as_list(v: Any) -> list:
    if v is None:
        return []
    a = np.asarray(v)
    return [x.item() for x in a.reshape(-1)]


def check_values(
    kind: str, getter: str, got: Any, want: tuple, *, strict: bool, minimum: bool = False
) -> str | None:
    """None if `got` (from Get<getter>v: "b", "i", "x", "f") is `want` converted
    per section 6.1.2, else a description of the difference."""
    g = as_list(got)
    if len(g) != len(want):
        return f"{len(g)} values {g}, expected {len(want)}"
    for k, (a, w) in enumerate(zip(g, want)):
        ok = True
        if kind == "mask" and w == -1:
            # "1's" (Table 6.16/6.17): the stencil bits at least are all ones
            ok = (
                (getter == "b" and bool(a))
                or (getter == "i" and (int(a) & 0xFF) == 0xFF)
                or getter in ("x", "f")
            )
        elif getter == "b":
            ok = bool(a) == (w != 0)
        elif getter == "f":
            ok = np.float32(a) >= np.float32(w) if minimum else np.float32(a) == np.float32(w)
        elif getter == "x":
            if kind == "enum":
                e = int(w)
            elif kind == "bool":
                e = ONE if w else 0
            else:
                e = _fixed_of(w)
            slack = 0 if (strict or kind in ("enum", "int", "bool", "mask")) else 1
            ok = int(a) >= e - slack if minimum else abs(int(a) - e) <= slack
        else:  # "i"
            if kind == "norm":
                tol = 1 if strict else 2**15
                ok = abs(int(a) - norm_to_int(w)) <= tol
            elif kind == "ref":
                ok = int(a) == int(np.floor(w + 0.5)) or abs(int(a) - norm_to_int(w)) <= (
                    1 if strict else 2**15
                )
            elif kind == "bool":
                ok = int(a) == (1 if w else 0)
            else:
                e = int(np.floor(w + 0.5))
                ok = int(a) >= e if minimum else int(a) == e
        if not ok:
            return f"value {k} is {a!r}, expected {'at least ' if minimum else ''}{w!r} ({kind})"
    return None


def getters(common: bool) -> tuple[str, ...]:
    return ("b", "i", "x", "f") if common else ("b", "i", "x")


def get(gl: Any, getter: str, pname: int) -> Any:
    fn = {"b": gl.glGetBooleanv, "i": gl.glGetIntegerv, "x": gl.glGetFixedv}.get(getter)
    return fn(pname) if fn is not None else gl.glGetFloatv(pname)


def check_row(
    gl: Any, common: bool, row: StateValue, want: tuple, *, strict: bool, minimum: bool = False
) -> list[str]:
    """Query `row` with every Get of the profile; problems found (and GL errors)."""
    problems = []
    for g in getters(common):
        got = get(gl, g, row.pname)
        err = gl.glGetError()
        if err:
            problems.append(f"{row.name} (Table {row.table}) Get{g}: GL error 0x{err:04X}")
            continue
        why = check_values(row.kind, g, got, want, strict=strict, minimum=minimum)
        if why:
            problems.append(f"{row.name} (Table {row.table}) Get{g}v: {why}")
    return problems


def extensions(gl: Any) -> set[str]:
    """The names GL_EXTENSIONS lists."""
    ext = gl.glGetString(C.GL_EXTENSIONS) or b""
    return set((ext.decode() if isinstance(ext, bytes) else ext).split())


def env_of(t: TestContext) -> Env:
    """The context as its VERSION string describes it (Mesa is always Common)."""
    v = t.visual
    lite = "ES-CL" in (t.gl.glGetString(C.GL_VERSION) or b"").decode()
    return Env(t.width, t.height, v.bits, v.depth, v.stencil, lite)


# {============================================================
# set/get round trips: each setter sets state with x forms (form "x") or
# f forms (form "f", Common only) and returns {state name: expected values}


def _q(*v: float) -> tuple:
    """Reals as an x command receives them."""
    return tuple(unfx(fx(a)) for a in v)


def _f32(*v: float) -> tuple:
    """Reals as a float32 array argument holds them."""
    return tuple(float(np.float32(a)) for a in v)


def set_current(gl: Any, form: str) -> dict:
    gl.glActiveTexture(C.GL_TEXTURE0)  # CURRENT_TEXTURE_COORDS reads the active unit
    if form == "x":
        gl.glColor4x(*[fx(a) for a in (0.25, 0.5, 0.75, 0.1)])
        gl.glNormal3x(fx(0.5), fx(-0.25), fx(0.1))
        gl.glMultiTexCoord4x(C.GL_TEXTURE0, fx(1.5), fx(-2.25), fx(0.1), fx(3))
        return {
            "GL_CURRENT_COLOR": _q(0.25, 0.5, 0.75, 0.1),
            "GL_CURRENT_NORMAL": _q(0.5, -0.25, 0.1),
            "GL_CURRENT_TEXTURE_COORDS": _q(1.5, -2.25, 0.1, 3),
        }
    gl.glColor4f(0.1, 0.2, 0.3, 0.4)
    gl.glNormal3f(0.1, -0.2, 0.3)
    gl.glMultiTexCoord4f(C.GL_TEXTURE0, 0.1, 2.7, -3.3, 1.0)
    return {
        "GL_CURRENT_COLOR": (0.1, 0.2, 0.3, 0.4),
        "GL_CURRENT_NORMAL": (0.1, -0.2, 0.3),
        "GL_CURRENT_TEXTURE_COORDS": (0.1, 2.7, -3.3, 1.0),
    }


_KEEP: list = []


def set_arrays(gl: Any, form: str) -> dict:
    data = np.zeros(64, np.int16)
    fixed = np.zeros(16, np.int32)
    ub = np.zeros(64, np.uint8)
    sb = np.zeros(64, np.int8)
    _KEEP[:] = [data, fixed, ub, sb]
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, 0)
    gl.glVertexPointer(3, C.GL_SHORT, 12, data)
    gl.glNormalPointer(C.GL_BYTE, 6, sb)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 8, ub)
    gl.glClientActiveTexture(C.GL_TEXTURE1)
    gl.glTexCoordPointer(2, C.GL_SHORT, 8, data)
    gl.glPointSizePointerOES(C.GL_FIXED, 8, fixed)
    for a in (
        "GL_VERTEX_ARRAY",
        "GL_NORMAL_ARRAY",
        "GL_COLOR_ARRAY",
        "GL_TEXTURE_COORD_ARRAY",
        "GL_POINT_SIZE_ARRAY_OES",
    ):
        gl.glEnableClientState(getattr(C, a))
    return {
        "GL_VERTEX_ARRAY": (1,),
        "GL_VERTEX_ARRAY_SIZE": (3,),
        "GL_VERTEX_ARRAY_TYPE": (C.GL_SHORT,),
        "GL_VERTEX_ARRAY_STRIDE": (12,),
        "GL_NORMAL_ARRAY": (1,),
        "GL_NORMAL_ARRAY_TYPE": (C.GL_BYTE,),
        "GL_NORMAL_ARRAY_STRIDE": (6,),
        "GL_COLOR_ARRAY": (1,),
        "GL_COLOR_ARRAY_SIZE": (4,),
        "GL_COLOR_ARRAY_TYPE": (C.GL_UNSIGNED_BYTE,),
        "GL_COLOR_ARRAY_STRIDE": (8,),
        "GL_CLIENT_ACTIVE_TEXTURE": (C.GL_TEXTURE1,),
        "GL_TEXTURE_COORD_ARRAY": (1,),
        "GL_TEXTURE_COORD_ARRAY_SIZE": (2,),
        "GL_TEXTURE_COORD_ARRAY_TYPE": (C.GL_SHORT,),
        "GL_TEXTURE_COORD_ARRAY_STRIDE": (8,),
        "GL_POINT_SIZE_ARRAY_OES": (1,),
        "GL_POINT_SIZE_ARRAY_TYPE_OES": (C.GL_FIXED,),
        "GL_POINT_SIZE_ARRAY_STRIDE_OES": (8,),
    }


def set_buffers(gl: Any, form: str) -> dict:
    b = gl.glGenBuffers(2)
    a, e = int(b[0]), int(b[1])
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, a)
    gl.glBufferData(C.GL_ARRAY_BUFFER, 64, None, C.GL_STATIC_DRAW)
    gl.glVertexPointer(2, C.GL_FIXED, 0, 0)
    gl.glNormalPointer(C.GL_FIXED, 0, 0)
    gl.glColorPointer(4, C.GL_FIXED, 0, 0)
    gl.glTexCoordPointer(2, C.GL_FIXED, 0, 0)
    gl.glPointSizePointerOES(C.GL_FIXED, 0, 0)
    gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, e)
    return {
        n: (a,)
        for n in (
            "GL_ARRAY_BUFFER_BINDING",
            "GL_VERTEX_ARRAY_BUFFER_BINDING",
            "GL_NORMAL_ARRAY_BUFFER_BINDING",
            "GL_COLOR_ARRAY_BUFFER_BINDING",
            "GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING",
            "GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES",
        )
    } | {"GL_ELEMENT_ARRAY_BUFFER_BINDING": (e,)}


def set_transform(gl: Any, form: str) -> dict:
    m = np.array([2.0, 0.5, -1.25, 0, 0.1, 3, 0, 0, 0, 0, 1, 0, 7.5, -8.25, 0.75, 1.0])
    # stack depths grow from wherever an earlier round left them
    dp = int(gl.glGetIntegerv(C.GL_PROJECTION_STACK_DEPTH))
    dm = int(gl.glGetIntegerv(C.GL_MODELVIEW_STACK_DEPTH))
    gl.glMatrixMode(C.GL_PROJECTION)
    if form == "x":
        gl.glLoadMatrixx(np.array([fx(v) for v in m], np.int32))
        m = np.array(_q(*m))
        gl.glDepthRangex(fx(0.25), fx(0.75))
        dr = (0.25, 0.75)
    else:
        gl.glLoadMatrixf(m.astype(np.float32))
        m = m.astype(np.float32).astype(np.float64)
        gl.glDepthRangef(0.1, 0.9)
        dr = (0.1, 0.9)
    gl.glPushMatrix()
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glPushMatrix()
    gl.glPushMatrix()
    gl.glViewport(1, 2, 30, 40)
    return {
        "GL_PROJECTION_MATRIX": tuple(m),
        "GL_MATRIX_MODE": (C.GL_MODELVIEW,),
        "GL_PROJECTION_STACK_DEPTH": (dp + 1,),
        "GL_MODELVIEW_STACK_DEPTH": (dm + 2,),
        "GL_VIEWPORT": (1, 2, 30, 40),
        "GL_DEPTH_RANGE": dr,
    }


def set_fog(gl: Any, form: str) -> dict:
    if form == "x":
        gl.glFogx(C.GL_FOG_MODE, C.GL_LINEAR)
        gl.glFogx(C.GL_FOG_DENSITY, fx(0.1))
        gl.glFogx(C.GL_FOG_START, fx(2.75))
        gl.glFogx(C.GL_FOG_END, fx(-10.25))
        gl.glFogxv(C.GL_FOG_COLOR, np.array([fx(v) for v in (0.25, 0.5, 0.1, 1.0)], np.int32))
        d = {
            "GL_FOG_DENSITY": _q(0.1),
            "GL_FOG_START": (2.75,),
            "GL_FOG_END": (-10.25,),
            "GL_FOG_COLOR": _q(0.25, 0.5, 0.1, 1.0),
        }
    else:
        gl.glFogf(C.GL_FOG_MODE, float(C.GL_LINEAR))
        gl.glFogf(C.GL_FOG_DENSITY, 0.1)
        gl.glFogf(C.GL_FOG_START, 2.7)
        gl.glFogf(C.GL_FOG_END, -10.3)
        gl.glFogfv(C.GL_FOG_COLOR, np.array([0.1, 0.2, 0.3, 0.4], np.float32))
        d = {
            "GL_FOG_DENSITY": (0.1,),
            "GL_FOG_START": (2.7,),
            "GL_FOG_END": (-10.3,),
            "GL_FOG_COLOR": _f32(0.1, 0.2, 0.3, 0.4),
        }
    gl.glShadeModel(C.GL_FLAT)
    return d | {"GL_FOG_MODE": (C.GL_LINEAR,), "GL_SHADE_MODEL": (C.GL_FLAT,)}


def set_light_model(gl: Any, form: str) -> dict:
    if form == "x":
        gl.glLightModelxv(
            C.GL_LIGHT_MODEL_AMBIENT, np.array([fx(v) for v in (0.1, 0.5, 0.75, 0.25)], np.int32)
        )
        gl.glLightModelx(C.GL_LIGHT_MODEL_TWO_SIDE, ONE)
        return {"GL_LIGHT_MODEL_AMBIENT": _q(0.1, 0.5, 0.75, 0.25), "GL_LIGHT_MODEL_TWO_SIDE": (1,)}
    gl.glLightModelfv(C.GL_LIGHT_MODEL_AMBIENT, np.array([0.1, 0.2, 0.3, 0.4], np.float32))
    gl.glLightModelf(C.GL_LIGHT_MODEL_TWO_SIDE, 1.0)
    return {"GL_LIGHT_MODEL_AMBIENT": _f32(0.1, 0.2, 0.3, 0.4), "GL_LIGHT_MODEL_TWO_SIDE": (1,)}


def set_raster(gl: Any, form: str) -> dict:
    gl.glCullFace(C.GL_FRONT)
    gl.glFrontFace(C.GL_CW)
    d = {"GL_CULL_FACE_MODE": (C.GL_FRONT,), "GL_FRONT_FACE": (C.GL_CW,)}
    if form == "x":
        gl.glPointSizex(fx(2.75))
        gl.glLineWidthx(fx(1.25))
        gl.glPointParameterx(C.GL_POINT_SIZE_MIN, fx(0.1))
        gl.glPointParameterx(C.GL_POINT_SIZE_MAX, fx(1.0))
        gl.glPointParameterx(C.GL_POINT_FADE_THRESHOLD_SIZE, fx(0.75))
        gl.glPointParameterxv(C.GL_POINT_DISTANCE_ATTENUATION, np.array([fx(0.5), fx(0.1), fx(2)], np.int32))
        gl.glPolygonOffsetx(fx(1.25), fx(-3.75))
        gl.glSampleCoveragex(fx(0.25), True)
        return d | {
            "GL_POINT_SIZE": (2.75,),
            "GL_LINE_WIDTH": (1.25,),
            "GL_POINT_SIZE_MIN": _q(0.1),
            "GL_POINT_SIZE_MAX": (1.0,),
            "GL_POINT_FADE_THRESHOLD_SIZE": (0.75,),
            "GL_POINT_DISTANCE_ATTENUATION": _q(0.5, 0.1, 2),
            "GL_POLYGON_OFFSET_FACTOR": (1.25,),
            "GL_POLYGON_OFFSET_UNITS": (-3.75,),
            "GL_SAMPLE_COVERAGE_VALUE": (0.25,),
            "GL_SAMPLE_COVERAGE_INVERT": (1,),
        }
    gl.glPointSize(0.1)
    gl.glLineWidth(1.1)
    gl.glPointParameterf(C.GL_POINT_SIZE_MIN, 0.1)
    gl.glPointParameterf(C.GL_POINT_SIZE_MAX, 0.9)
    gl.glPointParameterf(C.GL_POINT_FADE_THRESHOLD_SIZE, 0.3)
    gl.glPointParameterfv(C.GL_POINT_DISTANCE_ATTENUATION, np.array([0.1, 0.2, 0.3], np.float32))
    gl.glPolygonOffset(0.1, -2.7)
    gl.glSampleCoverage(0.1, False)
    return d | {
        "GL_POINT_SIZE": (0.1,),
        "GL_LINE_WIDTH": (1.1,),
        "GL_POINT_SIZE_MIN": (0.1,),
        "GL_POINT_SIZE_MAX": (0.9,),
        "GL_POINT_FADE_THRESHOLD_SIZE": (0.3,),
        "GL_POINT_DISTANCE_ATTENUATION": _f32(0.1, 0.2, 0.3),
        "GL_POLYGON_OFFSET_FACTOR": (0.1,),
        "GL_POLYGON_OFFSET_UNITS": (-2.7,),
        "GL_SAMPLE_COVERAGE_VALUE": (0.1,),
        "GL_SAMPLE_COVERAGE_INVERT": (0,),
    }


def set_texture_units(gl: Any, form: str) -> dict:
    tex = gl.glGenTextures(1)
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    gl.glMatrixMode(C.GL_TEXTURE)
    depth = int(gl.glGetIntegerv(C.GL_TEXTURE_STACK_DEPTH))
    gl.glPushMatrix()
    gl.glLoadIdentity()
    gl.glTranslatex(fx(0.5), 0, 0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    m = list(I4)
    m[12] = 0.5
    return {
        "GL_ACTIVE_TEXTURE": (C.GL_TEXTURE1,),
        "GL_TEXTURE_BINDING_2D": (int(tex),),
        "GL_TEXTURE_STACK_DEPTH": (depth + 1,),
        "GL_TEXTURE_MATRIX": tuple(m),
    }


def set_pixel_ops(gl: Any, form: str) -> dict:
    gl.glScissor(3, 4, 20, 10)
    if form == "x":
        gl.glAlphaFuncx(C.GL_GREATER, fx(0.25))
        ref = (0.25,)
    else:
        gl.glAlphaFunc(C.GL_LEQUAL, 0.1)
        ref = (0.1,)
    gl.glStencilFunc(C.GL_EQUAL, 5, 0x0F)
    gl.glStencilOp(C.GL_INCR, C.GL_DECR, C.GL_REPLACE)
    gl.glDepthFunc(C.GL_GEQUAL)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glLogicOp(C.GL_XOR)
    return {
        "GL_SCISSOR_BOX": (3, 4, 20, 10),
        "GL_ALPHA_TEST_FUNC": (C.GL_GREATER if form == "x" else C.GL_LEQUAL,),
        "GL_ALPHA_TEST_REF": ref,
        "GL_STENCIL_FUNC": (C.GL_EQUAL,),
        "GL_STENCIL_REF": (5,),
        "GL_STENCIL_VALUE_MASK": (0x0F,),
        "GL_STENCIL_FAIL": (C.GL_INCR,),
        "GL_STENCIL_PASS_DEPTH_FAIL": (C.GL_DECR,),
        "GL_STENCIL_PASS_DEPTH_PASS": (C.GL_REPLACE,),
        "GL_DEPTH_FUNC": (C.GL_GEQUAL,),
        "GL_BLEND_SRC": (C.GL_SRC_ALPHA,),
        "GL_BLEND_DST": (C.GL_ONE_MINUS_SRC_ALPHA,),
        "GL_LOGIC_OP_MODE": (C.GL_XOR,),
    }


def set_framebuffer(gl: Any, form: str) -> dict:
    gl.glColorMask(True, False, True, False)
    gl.glDepthMask(False)
    gl.glStencilMask(0x3C)
    gl.glClearStencil(7)
    gl.glPixelStorei(C.GL_PACK_ALIGNMENT, 1)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 8)
    if form == "x":
        gl.glClearColorx(fx(0.25), fx(0.5), fx(0.1), fx(1.0))
        gl.glClearDepthx(fx(0.25))
        cc, cd = _q(0.25, 0.5, 0.1, 1.0), (0.25,)
    else:
        gl.glClearColor(0.1, 0.2, 0.3, 0.4)
        gl.glClearDepthf(0.1)
        cc, cd = (0.1, 0.2, 0.3, 0.4), (0.1,)
    return {
        "GL_COLOR_WRITEMASK": (1, 0, 1, 0),
        "GL_DEPTH_WRITEMASK": (0,),
        "GL_STENCIL_WRITEMASK": (0x3C,),
        "GL_STENCIL_CLEAR_VALUE": (7,),
        "GL_PACK_ALIGNMENT": (1,),
        "GL_UNPACK_ALIGNMENT": (8,),
        "GL_COLOR_CLEAR_VALUE": cc,
        "GL_DEPTH_CLEAR_VALUE": cd,
    }


def set_hints(gl: Any, form: str) -> dict:
    out = {}
    for i, h in enumerate(
        ("PERSPECTIVE_CORRECTION", "POINT_SMOOTH", "LINE_SMOOTH", "FOG", "GENERATE_MIPMAP")
    ):
        mode = C.GL_NICEST if i % 2 else C.GL_FASTEST
        gl.glHint(getattr(C, f"GL_{h}_HINT"), mode)
        out[f"GL_{h}_HINT"] = (mode,)
    return out


def set_cube_map(gl: Any, form: str) -> dict:
    """OES_texture_cube_map: a cube map bound, cube mapping and texgen on, on unit 1."""
    tex = gl.glGenTextures(1)
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glBindTexture(C.GL_TEXTURE_CUBE_MAP_OES, tex)
    gl.glEnable(C.GL_TEXTURE_CUBE_MAP_OES)
    gl.glEnable(C.GL_TEXTURE_GEN_STR_OES)
    return {
        "GL_TEXTURE_BINDING_CUBE_MAP_OES": (int(tex),),
        "GL_TEXTURE_CUBE_MAP_OES": (1,),
        "GL_TEXTURE_GEN_STR_OES": (1,),
    }


DEBUG_TEXT = "state"  # a marker message: NEXT_LOGGED_MESSAGE_LENGTH counts its null terminator


def set_debug(gl: Any, form: str) -> dict:
    """KHR_debug: output on, a marker inserted into the emptied log, a group pushed
    (its push message is logged too when the log holds two messages)."""
    gl.glDebugMessageCallbackKHR(None, None)  # messages go to the log (5.5.3)
    gl.glGetDebugMessageLogKHR(1 << 16, 0, None, None, None, None, None, None)  # empty it
    depth = int(gl.glGetIntegerv(C.GL_DEBUG_GROUP_STACK_DEPTH_KHR))
    room = int(gl.glGetIntegerv(C.GL_MAX_DEBUG_LOGGED_MESSAGES_KHR))
    gl.glEnable(C.GL_DEBUG_OUTPUT_KHR)
    gl.glEnable(C.GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR)
    gl.glDebugMessageInsertKHR(
        C.GL_DEBUG_SOURCE_APPLICATION_KHR,
        C.GL_DEBUG_TYPE_MARKER_KHR,
        1,
        C.GL_DEBUG_SEVERITY_NOTIFICATION_KHR,
        -1,
        DEBUG_TEXT,
    )
    gl.glPushDebugGroupKHR(C.GL_DEBUG_SOURCE_APPLICATION_KHR, 2, -1, "group")
    return {
        "GL_DEBUG_OUTPUT_KHR": (1,),
        "GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR": (1,),
        "GL_DEBUG_LOGGED_MESSAGES_KHR": (min(2, room),),
        "GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR": (len(DEBUG_TEXT) + 1,),
        "GL_DEBUG_GROUP_STACK_DEPTH_KHR": (depth + 1,),
    }


SETTERS: dict[str, Callable[[Any, str], dict]] = {
    "current": set_current,
    "arrays": set_arrays,
    "buffers": set_buffers,
    "transform": set_transform,
    "fog": set_fog,
    "light_model": set_light_model,
    "raster": set_raster,
    "texture_units": set_texture_units,
    "pixel_ops": set_pixel_ops,
    "framebuffer": set_framebuffer,
    "hints": set_hints,
}

# setters of extension state: (extension, setter)
EXT_SETTERS: dict[str, tuple[str, Callable[[Any, str], dict]]] = {
    "cube_map": (CUBE_EXT, set_cube_map),
    "debug": (DEBUG_EXT, set_debug),
}

ENABLES = [s for s in CORE_STATE if s.enable]
EXT_ENABLES = [s for s in EXT_STATE if s.enable]
CLIENT_STATES = {
    "GL_VERTEX_ARRAY",
    "GL_NORMAL_ARRAY",
    "GL_COLOR_ARRAY",
    "GL_TEXTURE_COORD_ARRAY",
    "GL_POINT_SIZE_ARRAY_OES",
}


def toggle(gl: Any, name: str, on: bool) -> None:
    cap = int(getattr(C, name))
    if name in CLIENT_STATES:
        (gl.glEnableClientState if on else gl.glDisableClientState)(cap)
    else:
        (gl.glEnable if on else gl.glDisable)(cap)


# {============================================================
# per-command state (lights, materials, texture parameters, texenv, clip plane)


def light_material_problems(gl: Any, common: bool, strict: bool, n_lights: int) -> list[str]:
    """Initial GetLight/GetMaterial values (Tables 6.9, 6.10) in x and f forms."""
    problems = []
    forms = [("x", gl.glGetLightxv, gl.glGetMaterialxv)]
    if common:
        forms.append(("f", gl.glGetLightfv, gl.glGetMaterialfv))
    for g, getl, getm in forms:
        for i in range(n_lights):
            for name, want in light_state(i):
                why = check_values("float", g, getl(C.GL_LIGHT0 + i, getattr(C, name)), want, strict=strict)
                if why:
                    problems.append(f"GetLight{g}v(LIGHT{i}, {name}) (Table 6.10): {why}")
        for face in (C.GL_FRONT, C.GL_BACK):
            for name, want in MATERIAL_STATE:
                why = check_values("float", g, getm(face, getattr(C, name)), want, strict=strict)
                if why:
                    problems.append(f"GetMaterial{g}v({C.NAMES.get(face, face)}, {name}) (Table 6.9): {why}")
    err = gl.glGetError()
    if err:
        problems.append(f"GetLight/GetMaterial: GL error 0x{err:04X}")
    return problems


def light_material_round_trip(gl: Any, form: str, strict: bool) -> list[str]:
    """Set light 1 and the material, read them back (modelview identity)."""
    if form == "x":
        vals = {
            "GL_AMBIENT": _q(0.1, 0.25, 0.5, 1),
            "GL_DIFFUSE": _q(0.75, 0.5, 0.25, 0.1),
            "GL_SPECULAR": _q(1, 0.1, 0, 0.5),
            "GL_POSITION": _q(1.5, -2, 3.25, 1),
            "GL_SPOT_DIRECTION": _q(0, -1, 0),
            "GL_SPOT_EXPONENT": (12.5,),
            "GL_SPOT_CUTOFF": (45.0,),
            "GL_CONSTANT_ATTENUATION": (2.0,),
            "GL_LINEAR_ATTENUATION": _q(0.1),
            "GL_QUADRATIC_ATTENUATION": (0.25,),
        }
        for name, v in vals.items():
            gl.glLightxv(C.GL_LIGHT1, getattr(C, name), np.array([fx(a) for a in v], np.int32))
        mat = {
            "GL_AMBIENT": _q(0.1, 0.2, 0.3, 0.4),
            "GL_DIFFUSE": _q(0.5, 0.25, 0.75, 1),
            "GL_SPECULAR": _q(1, 1, 0.1, 1),
            "GL_EMISSION": _q(0, 0.5, 0, 1),
            "GL_SHININESS": (64.5,),
        }
        for name, v in mat.items():
            gl.glMaterialxv(C.GL_FRONT_AND_BACK, getattr(C, name), np.array([fx(a) for a in v], np.int32))
        getl, getm = gl.glGetLightxv, gl.glGetMaterialxv
    else:
        vals = {
            "GL_AMBIENT": (0.1, 0.2, 0.3, 0.4),
            "GL_DIFFUSE": (0.7, 0.6, 0.5, 0.1),
            "GL_SPECULAR": (0.9, 0.1, 0.3, 0.5),
            "GL_POSITION": (1.5, -2, 3.25, 1),
            "GL_SPOT_DIRECTION": (0, -1, 0),
            "GL_SPOT_EXPONENT": (12.1,),
            "GL_SPOT_CUTOFF": (45.3,),
            "GL_CONSTANT_ATTENUATION": (2.1,),
            "GL_LINEAR_ATTENUATION": (0.1,),
            "GL_QUADRATIC_ATTENUATION": (0.3,),
        }
        for name, v in vals.items():
            gl.glLightfv(C.GL_LIGHT1, getattr(C, name), np.array(v, np.float32))
        mat = {
            "GL_AMBIENT": (0.1, 0.2, 0.3, 0.4),
            "GL_DIFFUSE": (0.5, 0.6, 0.7, 0.8),
            "GL_SPECULAR": (0.9, 0.1, 0.2, 0.3),
            "GL_EMISSION": (0.3, 0.1, 0.7, 0.9),
            "GL_SHININESS": (64.1,),
        }
        for name, v in mat.items():
            gl.glMaterialfv(C.GL_FRONT_AND_BACK, getattr(C, name), np.array(v, np.float32))
        getl, getm = gl.glGetLightfv, gl.glGetMaterialfv
    problems = []
    for name, want in vals.items():
        why = check_values("float", form, getl(C.GL_LIGHT1, getattr(C, name)), want, strict=strict)
        if why:
            problems.append(f"Light{form}v(LIGHT1, {name}) round trip (Table 6.10): {why}")
    for face in (C.GL_FRONT, C.GL_BACK):
        for name, want in mat.items():
            why = check_values("float", form, getm(face, getattr(C, name)), want, strict=strict)
            if why:
                problems.append(f"Material{form}v({name}) round trip, face 0x{face:04X} (Table 6.9): {why}")
    err = gl.glGetError()
    if err:
        problems.append(f"light/material round trip ({form}): GL error 0x{err:04X}")
    return problems


def tex_problems(gl: Any, common: bool, strict: bool) -> list[str]:
    """Initial GetTexParameter (Table 6.14), GetTexEnv (Table 6.15) values and
    round trips through TexParameter/TexEnv x and i forms."""
    problems = []
    forms = ["i", "x"] + (["f"] if common else [])

    def get_tp(g: str, pname: int) -> Any:
        return getattr(gl, f"glGetTexParameter{g}v")(C.GL_TEXTURE_2D, pname)

    def get_te(g: str, target: int, pname: int) -> Any:
        return getattr(gl, f"glGetTexEnv{g}v")(target, pname)

    def tex_check(kind: str, g: str, got: Any, want: tuple, what: str) -> None:
        if kind == "bool" and g == "x":
            return  # GetTexParameterxv of a boolean: not settled by the spec (enum-like or 1.0)
        if g == "i" and kind == "float":
            kind = "float"
        why = check_values(kind, "i" if g == "i" else g, got, want, strict=strict)
        if why:
            problems.append(f"{what}: {why}")

    for g in forms:
        for name, kind, init in TEXPARAM_STATE:
            tex_check(
                kind, g, get_tp(g, getattr(C, name)), (init,), f"GetTexParameter{g}v({name}) (Table 6.14)"
            )
        for name, kind, init in TEXENV_STATE:
            tex_check(
                kind,
                g,
                get_te(g, C.GL_TEXTURE_ENV, getattr(C, name)),
                init,
                f"GetTexEnv{g}v({name}) (Table 6.15)",
            )
        tex_check(
            "bool",
            g,
            get_te(g, C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES),
            (0,),
            f"GetTexEnv{g}v(COORD_REPLACE_OES) (Table 6.15)",
        )
    err = gl.glGetError()
    if err:
        problems.append(f"initial GetTexParameter/GetTexEnv: GL error 0x{err:04X}")
    # round trips
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_NEAREST)
    gl.glTexParameterx(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
    gl.glTexParameterx(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, C.GL_CLAMP_TO_EDGE)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)
    gl.glTexEnvx(C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, C.GL_DOT3_RGB)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC1_ALPHA, C.GL_PRIMARY_COLOR)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND2_RGB, C.GL_ONE_MINUS_SRC_COLOR)
    gl.glTexEnvx(C.GL_TEXTURE_ENV, C.GL_RGB_SCALE, fx(2.0))
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_ALPHA_SCALE, 4)
    gl.glTexEnvxv(
        C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, np.array([fx(v) for v in (0.25, 0.1, 1, 0.5)], np.int32)
    )
    gl.glTexEnvi(C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES, 1)
    want_tp = (
        ("GL_TEXTURE_MIN_FILTER", "enum", C.GL_LINEAR_MIPMAP_NEAREST),
        ("GL_TEXTURE_MAG_FILTER", "enum", C.GL_NEAREST),
        ("GL_TEXTURE_WRAP_S", "enum", C.GL_CLAMP_TO_EDGE),
        ("GL_TEXTURE_WRAP_T", "enum", C.GL_CLAMP_TO_EDGE),
        ("GL_GENERATE_MIPMAP", "bool", 1),
    )
    want_te = (
        ("GL_TEXTURE_ENV_MODE", "enum", (C.GL_COMBINE,)),
        ("GL_COMBINE_RGB", "enum", (C.GL_DOT3_RGB,)),
        ("GL_SRC1_ALPHA", "enum", (C.GL_PRIMARY_COLOR,)),
        ("GL_OPERAND2_RGB", "enum", (C.GL_ONE_MINUS_SRC_COLOR,)),
        ("GL_RGB_SCALE", "float", (2.0,)),
        ("GL_ALPHA_SCALE", "float", (4.0,)),
        ("GL_TEXTURE_ENV_COLOR", "norm", _q(0.25, 0.1, 1, 0.5)),
    )
    for g in forms:
        for name, kind, v in want_tp:
            tex_check(kind, g, get_tp(g, getattr(C, name)), (v,), f"TexParameter({name}) round trip, Get{g}v")
        for name, kind, v in want_te:
            tex_check(
                kind,
                g,
                get_te(g, C.GL_TEXTURE_ENV, getattr(C, name)),
                v,
                f"TexEnv({name}) round trip, Get{g}v",
            )
        tex_check(
            "bool",
            g,
            get_te(g, C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES),
            (1,),
            f"TexEnv(COORD_REPLACE_OES) round trip, Get{g}v",
        )
    err = gl.glGetError()
    if err:
        problems.append(f"TexParameter/TexEnv round trip: GL error 0x{err:04X}")
    return problems


def clip_plane_problems(gl: Any, common: bool, strict: bool) -> list[str]:
    problems = []
    for g, fn in [("x", gl.glGetClipPlanex)] + ([("f", gl.glGetClipPlanef)] if common else []):
        why = check_values("float", g, fn(C.GL_CLIP_PLANE0), (0, 0, 0, 0), strict=strict)
        if why:
            problems.append(f"GetClipPlane{g}(CLIP_PLANE0) initial (Table 6.7): {why}")
    eq = _q(0.5, -1, 0.1, 2.25)
    gl.glClipPlanex(C.GL_CLIP_PLANE0, np.array([fx(v) for v in eq], np.int32))
    for g, fn in [("x", gl.glGetClipPlanex)] + ([("f", gl.glGetClipPlanef)] if common else []):
        why = check_values("float", g, fn(C.GL_CLIP_PLANE0), eq, strict=strict)
        if why:
            problems.append(f"GetClipPlane{g}(CLIP_PLANE0) after ClipPlanex (Table 6.7): {why}")
    err = gl.glGetError()
    if err:
        problems.append(f"clip plane: GL error 0x{err:04X}")
    return problems


def pointer_problems(gl: Any) -> list[str]:
    problems = []
    for name in POINTERS:
        v = gl.glGetPointerv(getattr(C, name))
        if v:
            problems.append(f"GetPointerv({name}) initial is {v}, expected 0 (Tables 6.4/6.5)")
    err = gl.glGetError()
    if err:
        problems.append(f"GetPointerv: GL error 0x{err:04X}")
    return problems


def misc_problems(gl: Any, common: bool, *, exact_version: str | None) -> list[str]:
    """Strings, GetError, compressed formats, buffer object state (Tables 6.6, 6.22, 6.24)."""
    problems = []
    if gl.glGetError() != 0:
        problems.append("GetError is not NO_ERROR initially (Table 6.24)")
    version = (gl.glGetString(C.GL_VERSION) or b"").decode()
    if exact_version is not None and not version.startswith(exact_version):
        problems.append(f"VERSION is {version!r}, expected {exact_version!r}")
    if not re.match(r"OpenGL ES-C[ML] 1\.1", version):
        problems.append(f"VERSION {version!r} does not start with 'OpenGL ES-CM 1.1' or 'OpenGL ES-CL 1.1'")
    for s in (C.GL_VENDOR, C.GL_RENDERER):
        if not gl.glGetString(s):
            problems.append(f"GetString(0x{s:04X}) is empty")
    ext = (gl.glGetString(C.GL_EXTENSIONS) or b"").decode().split()
    for e in (
        "GL_OES_read_format",
        "GL_OES_compressed_paletted_texture",
        "GL_OES_point_size_array",
        "GL_OES_point_sprite",
    ):
        if e not in ext:
            problems.append(f"EXTENSIONS lacks the required {e}")
    fmts = set(as_list(gl.glGetIntegerv(C.GL_COMPRESSED_TEXTURE_FORMATS)))
    missing = [hex(f) for f in PALETTE_FORMATS if f not in fmts]
    if missing:
        problems.append(f"COMPRESSED_TEXTURE_FORMATS lacks {missing} (Table 6.22)")
    n = gl.glGetIntegerv(C.GL_NUM_COMPRESSED_TEXTURE_FORMATS)
    if n != len(fmts):
        problems.append(f"NUM_COMPRESSED_TEXTURE_FORMATS {n} but {len(fmts)} formats listed")
    b = gl.glGenBuffers(1)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, b)
    size = gl.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_SIZE)
    usage = gl.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_USAGE)
    if (size, usage) != (0, C.GL_STATIC_DRAW):
        problems.append(
            f"new buffer: BUFFER_SIZE {size}, BUFFER_USAGE 0x{usage:04X}; expected 0, STATIC_DRAW (Table 6.6)"
        )
    gl.glBufferData(C.GL_ARRAY_BUFFER, 24, None, C.GL_DYNAMIC_DRAW)
    size = gl.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_SIZE)
    usage = gl.glGetBufferParameteriv(C.GL_ARRAY_BUFFER, C.GL_BUFFER_USAGE)
    if (size, usage) != (24, C.GL_DYNAMIC_DRAW):
        problems.append(f"after BufferData(24, DYNAMIC_DRAW): BUFFER_SIZE {size}, BUFFER_USAGE 0x{usage:04X}")
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, 0)
    gl.glDeleteBuffers(1, [b])
    err = gl.glGetError()
    if err:
        problems.append(f"strings/buffers: GL error 0x{err:04X}")
    return problems


def initial_rows_problems(gl: Any, common: bool, rows: Any, env: Env, *, strict: bool) -> list[str]:
    """Each row at its initial value in every Get, and IsEnabled of the enables among them."""
    problems = []
    for row in rows:
        problems += check_row(gl, common, row, row.want(env), strict=strict, minimum=row.minimum)
        if row.enable:
            on = gl.glIsEnabled(row.pname)
            if bool(on) != bool(row.want(env)[0]):
                problems.append(f"IsEnabled({row.name}) (Table {row.table}) is {on}")
    return problems


def initial_problems(gl: Any, common: bool, env: Env, *, strict: bool) -> list[str]:
    """Every row of CORE_STATE at its initial value, plus IsEnabled of the enables."""
    problems = initial_rows_problems(gl, common, CORE_STATE, env, strict=strict)
    # POINT_SIZE_MAX starts at the largest supported size (Table 6.11)
    top = max(
        as_list(gl.glGetFixedv(C.GL_ALIASED_POINT_SIZE_RANGE))[1],
        as_list(gl.glGetFixedv(C.GL_SMOOTH_POINT_SIZE_RANGE))[1],
    )
    psm = gl.glGetFixedv(C.GL_POINT_SIZE_MAX)
    if abs(int(psm) - int(top)) > 1:
        problems.append(f"POINT_SIZE_MAX (Table 6.11) is {psm / ONE}, the largest point size is {top / ONE}")
    for name in (
        "GL_ALIASED_POINT_SIZE_RANGE",
        "GL_SMOOTH_POINT_SIZE_RANGE",
        "GL_ALIASED_LINE_WIDTH_RANGE",
        "GL_SMOOTH_LINE_WIDTH_RANGE",
    ):
        lo, hi = as_list(gl.glGetFixedv(getattr(C, name)))
        if not lo <= ONE <= hi:
            problems.append(f"{name} (Table 6.21) is ({lo / ONE}, {hi / ONE}); it must contain 1")
    return problems


def enable_problems(gl: Any, rows: list[StateValue] | None = None) -> list[str]:
    """Each enable (of `rows`, else of the core tables): on -> IsEnabled/GetBooleanv/
    GetIntegerv say so; off again."""
    problems = []
    for row in ENABLES if rows is None else rows:
        for on in (True, False):
            toggle(gl, row.name, on)
            got = (gl.glIsEnabled(row.pname), gl.glGetBooleanv(row.pname), gl.glGetIntegerv(row.pname))
            err = gl.glGetError()
            if err or bool(got[0]) != on or bool(got[1]) != on or int(got[2]) != int(on):
                problems.append(
                    f"{row.name} (Table {row.table}) {'enabled' if on else 'disabled'}: IsEnabled, "
                    f"GetBooleanv, GetIntegerv = {got}, error 0x{err:04X}"
                )
    if rows is not None:
        return problems
    # TEXTURE_2D is per unit (Table 6.13)
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glActiveTexture(C.GL_TEXTURE0)
    if gl.glIsEnabled(C.GL_TEXTURE_2D):
        problems.append("TEXTURE_2D enabled on unit 1 shows as enabled on unit 0 (Table 6.13: per unit)")
    gl.glActiveTexture(C.GL_TEXTURE1)
    if not gl.glIsEnabled(C.GL_TEXTURE_2D):
        problems.append("TEXTURE_2D enabled on unit 1 does not show on unit 1")
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glActiveTexture(C.GL_TEXTURE0)
    return problems


def round_trip_problems(gl: Any, common: bool, setter: str, form: str, *, strict: bool) -> list[str]:
    """Set the state of `setter` (of SETTERS or EXT_SETTERS) and read it back."""
    want = SETTERS[setter](gl, form) if setter in SETTERS else EXT_SETTERS[setter][1](gl, form)
    err = gl.glGetError()
    problems = [f"setting {setter} ({form} forms): GL error 0x{err:04X}"] if err else []
    for name, vals in want.items():
        problems += [
            f"after {setter} ({form}): {p}" for p in check_row(gl, common, BY_NAME[name], vals, strict=strict)
        ]
    return problems


def _texgen_problems(gl: Any, common: bool, want: int, what: str, *, strict: bool) -> list[str]:
    """TEXTURE_GEN_MODE_OES of the active unit through GetTexGen{i,x(,f)}vOES."""
    problems = []
    for g in ["i", "x"] + (["f"] if common else []):
        for name, kind, _ in TEXGEN_STATE:
            got = getattr(gl, f"glGetTexGen{g}vOES")(C.GL_TEXTURE_GEN_STR_OES, getattr(C, name))
            why = check_values(kind, g, got, (want,), strict=strict)
            if why:
                problems.append(f"GetTexGen{g}vOES({name}) {what} (OES_texture_cube_map table 6.14): {why}")
    return problems


def cube_map_unit_problems(gl: Any, common: bool, *, strict: bool) -> list[str]:
    """OES_texture_cube_map's per-unit state: TEXTURE_GEN_MODE_OES initially
    REFLECTION_MAP_OES on each unit; TEXTURE_CUBE_MAP_OES, TEXTURE_GEN_STR_OES,
    TEXTURE_BINDING_CUBE_MAP_OES and the mode set on unit 1 (the mode by each TexGen
    form in turn) show on unit 1 in every Get and leave unit 0 at its initial values."""
    problems = []
    refl, normal = C.GL_REFLECTION_MAP_OES, C.GL_NORMAL_MAP_OES
    for unit in (0, 1):
        gl.glActiveTexture(C.GL_TEXTURE0 + unit)
        problems += _texgen_problems(gl, common, refl, f"initially, unit {unit}", strict=strict)
    tex = int(gl.glGenTextures(1))
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glBindTexture(C.GL_TEXTURE_CUBE_MAP_OES, tex)
    gl.glEnable(C.GL_TEXTURE_CUBE_MAP_OES)
    gl.glEnable(C.GL_TEXTURE_GEN_STR_OES)
    mode = (C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_GEN_MODE_OES)
    setters = [("i", gl.glTexGeniOES, int), ("x", gl.glTexGenxOES, int)]
    if common:
        setters.append(("f", gl.glTexGenfOES, float))
    for form, fn, conv in setters:
        for m in (normal, refl, normal):
            gl.glActiveTexture(C.GL_TEXTURE1)
            fn(*mode, conv(m))
            err = gl.glGetError()
            if err:
                problems.append(
                    f"TexGen{form}OES(TEXTURE_GEN_STR_OES, TEXTURE_GEN_MODE_OES, 0x{m:04X}) on unit 1: "
                    f"GL error 0x{err:04X}"
                )
            problems += _texgen_problems(gl, common, m, f"after TexGen{form}OES on unit 1", strict=strict)
            gl.glActiveTexture(C.GL_TEXTURE0)
            problems += _texgen_problems(gl, common, refl, f"of unit 0 after TexGen{form}OES on unit 1",
                                         strict=strict)
    for unit, want in ((0, (0, 0, 0)), (1, (1, 1, tex))):
        gl.glActiveTexture(C.GL_TEXTURE0 + unit)
        for name, v in zip(
            ("GL_TEXTURE_CUBE_MAP_OES", "GL_TEXTURE_GEN_STR_OES", "GL_TEXTURE_BINDING_CUBE_MAP_OES"), want
        ):
            row = BY_NAME[name]
            found = check_row(gl, common, row, (v,), strict=strict)
            problems += [f"unit {unit}, unit 1 set: {p}" for p in found]
            if row.enable and bool(gl.glIsEnabled(row.pname)) != bool(v):
                problems.append(f"unit {unit}, unit 1 set: IsEnabled({name}) is not {bool(v)} (per unit)")
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glTexGeniOES(*mode, refl)
    gl.glDisable(C.GL_TEXTURE_GEN_STR_OES)
    gl.glDisable(C.GL_TEXTURE_CUBE_MAP_OES)
    gl.glBindTexture(C.GL_TEXTURE_CUBE_MAP_OES, 0)
    gl.glDeleteTextures(1, [tex])
    gl.glActiveTexture(C.GL_TEXTURE0)
    err = gl.glGetError()
    if err:
        problems.append(f"cube map per-unit state: GL error 0x{err:04X}")
    return problems


def ext_problems(gl: Any, common: bool, env: Env, *, strict: bool) -> list[str]:
    """The rows of EXT_STATE whose extension GL_EXTENSIONS names: initial values in
    every Get and IsEnabled, the enables, the cube map's per-unit state, and the
    round trips of EXT_SETTERS in x and (Common) f forms."""
    have = extensions(gl)
    rows = [r for r in EXT_STATE if r.ext in have]
    problems = initial_rows_problems(gl, common, rows, env, strict=strict)
    problems += enable_problems(gl, [r for r in rows if r.enable])
    if CUBE_EXT in have:
        problems += cube_map_unit_problems(gl, common, strict=strict)
    for form in ("x", "f") if common else ("x",):
        for setter, (ext, _) in EXT_SETTERS.items():
            if ext in have:
                problems += round_trip_problems(gl, common, setter, form, strict=strict)
    return problems


# {============================================================
# the conformance tests

_ALL_PATH_STATES = ("dither", "scissor", "alpha", "blend", "depth", "stencil", "fog")


@conformance_test(
    "Gets", section="6.1", uses=_ALL_PATH_STATES, visuals=("rgba8888", "rgb565", "rgba4444", "rgba5551")
)
def gets(t: TestContext) -> None:
    """Initial values of Tables 6.3-6.24 through every Get, then set/get round trips."""
    gl = t.gl
    problems = misc_problems(gl, t.common, exact_version=None)
    t.clear()  # a known picture for the path comparison; clear values stay the initial ones
    problems += initial_problems(gl, t.common, env_of(t), strict=False)
    n_lights = int(gl.glGetIntegerv(C.GL_MAX_LIGHTS))
    problems += light_material_problems(gl, t.common, False, n_lights)
    problems += pointer_problems(gl)
    problems += clip_plane_problems(gl, t.common, False)
    problems += enable_problems(gl)
    problems += tex_problems(gl, t.common, False)
    for form in ("x", "f") if t.common else ("x",):
        problems += light_material_round_trip(gl, form, False)
        for setter in SETTERS:
            problems += round_trip_problems(gl, t.common, setter, form, strict=False)
    if problems:
        t.fail(f"{len(problems)} state query problems; " + "; ".join(problems[:12]))


@conformance_test("Gets.extensions", section="6.1", uses=_ALL_PATH_STATES, visuals=("rgba8888",))
def gets_extensions(t: TestContext) -> None:
    """New State of OES_texture_cube_map and KHR_debug (where listed) through every Get."""
    gl = t.gl
    if not extensions(gl) & {CUBE_EXT, DEBUG_EXT}:
        raise Unsupported(f"neither {CUBE_EXT} nor {DEBUG_EXT} is in GL_EXTENSIONS")
    t.clear()  # a known picture for the path comparison
    problems = ext_problems(gl, t.common, env_of(t), strict=False)
    if problems:
        t.fail(f"{len(problems)} extension state problems; " + "; ".join(problems[:12]))


def _matrix(gl: Any) -> np.ndarray:
    return np.asarray(gl.glGetFixedv(C.GL_MODELVIEW_MATRIX), np.float64).reshape(-1) / ONE


@conformance_test("MatrixGetTest", section="6.1.2", uses=_ALL_PATH_STATES)
def matrix_get(t: TestContext) -> None:
    """OES_matrix_get: *_MATRIX_FLOAT_AS_INT_BITS_OES after known transforms."""
    gl = t.gl
    t.clear()  # nothing is drawn: a known picture for the path comparison
    cases = (
        ("GL_MODELVIEW", "GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES"),
        ("GL_PROJECTION", "GL_PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES"),
        ("GL_TEXTURE", "GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES"),
    )
    for mode, pname in cases:
        gl.glMatrixMode(getattr(C, mode))
        ident = np.asarray(gl.glGetIntegerv(getattr(C, pname)), np.int64).reshape(-1)
        want = np.array(I4, np.float32).view(np.int32)
        if not np.array_equal(ident, want):
            t.fail(f"{pname} initially {ident.tolist()}, expected identity bits {want.tolist()}")
        # translate(1.5, -2.25, 0.5) * scale(3, 0.25, -2): every element exact in 16.16 and float32
        gl.glTranslatex(fx(1.5), fx(-2.25), fx(0.5))
        gl.glScalex(fx(3), fx(0.25), fx(-2))
        m = np.diag([3.0, 0.25, -2.0, 1.0])
        m[:3, 3] = (1.5, -2.25, 0.5)
        want = m.T.reshape(-1).astype(np.float32).view(np.int32)
        got = np.asarray(gl.glGetIntegerv(getattr(C, pname)), np.int64).reshape(-1)
        if not np.array_equal(got, want):
            t.fail(
                f"{pname} after Translate/Scale: {got.tolist()}, expected {want.tolist()} "
                f"(float {want.view(np.float32).tolist()})"
            )
        # a rotation by 90 degrees about z: elements 0, +-1 exactly representable; allow 1 ulp-ish
        gl.glLoadIdentity()
        gl.glRotatex(fx(90), 0, 0, ONE)
        bits = np.asarray(gl.glGetIntegerv(getattr(C, pname)), np.int64).reshape(-1)
        got = bits.astype(np.int32).view(np.float32)
        want_f = np.array([0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], np.float32)
        if np.max(np.abs(got - want_f)) > 2.0**-14:
            t.fail(f"{pname} after Rotate(90, z) reads {got.tolist()} as floats")
        gl.glLoadIdentity()
    gl.glMatrixMode(C.GL_MODELVIEW)
    t.check_gl_error("MatrixGetTest")


@conformance_test("MatrixQuery", section="6.1.2", uses=_ALL_PATH_STATES)
def matrix_query(t: TestContext) -> None:
    """OES_query_matrix: mantissa and exponent reconstruct the matrix, status 0."""
    gl = t.gl
    ext = (gl.glGetString(C.GL_EXTENSIONS) or b"").decode().split()
    if "GL_OES_query_matrix" not in ext or not hasattr(gl, "glQueryMatrixxOES"):
        raise Unsupported("GL_OES_query_matrix is not exported")
    t.clear()  # nothing is drawn: a known picture for the path comparison
    m = np.diag([3.0, 0.25, -2.0, 1.0])
    m[:3, 3] = (1.5, -2.25, 0.1)
    m = m.T.reshape(-1)
    for mode in (C.GL_MODELVIEW, C.GL_PROJECTION, C.GL_TEXTURE):
        gl.glMatrixMode(mode)
        mant, expo, status = gl.glQueryMatrixxOES()
        got = np.asarray(mant, np.float64) / ONE * np.exp2(np.asarray(expo, np.float64))
        if status != 0 or not np.array_equal(got, np.array(I4)):
            t.fail(f"mode 0x{mode:04X} identity: status {status}, matrix {got.tolist()}")
        gl.glLoadMatrixx(np.array([fx(v) for v in m], np.int32))
        want = np.array(_q(*m))
        mant, expo, status = gl.glQueryMatrixxOES()
        got = np.asarray(mant, np.float64) / ONE * np.exp2(np.asarray(expo, np.float64))
        if status != 0:
            t.fail(f"mode 0x{mode:04X}: status {status:#x} for a finite matrix")
        bad = np.abs(got - want) > np.abs(want) * 2.0**-15
        if bad.any():
            t.fail(f"mode 0x{mode:04X}: reconstructed {got.tolist()}, loaded {want.tolist()}")
        gl.glLoadIdentity()
    gl.glMatrixMode(C.GL_MODELVIEW)
    t.check_gl_error("MatrixQuery")


def _unpack(fmt: int, typ: int, px: np.ndarray, h: int, w: int) -> np.ndarray:
    """A ReadPixels result of (format, type) as float RGBA (alpha 1 where absent)."""
    a = np.asarray(px)
    if (fmt, typ) == (C.GL_RGBA, C.GL_UNSIGNED_BYTE):
        return a.reshape(h, w, 4) / 255.0
    if (fmt, typ) == (C.GL_RGB, C.GL_UNSIGNED_BYTE):
        return np.concatenate([a.reshape(h, w, 3) / 255.0, np.ones((h, w, 1))], axis=-1)
    if (fmt, typ) == (C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE):
        return a.reshape(h, w, 4)[..., [2, 1, 0, 3]] / 255.0
    v = a.reshape(h, w).astype(np.uint32)
    if (fmt, typ) == (C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5):
        return np.stack([(v >> 11) / 31.0, ((v >> 5) & 63) / 63.0, (v & 31) / 31.0, np.ones((h, w))], axis=-1)
    if (fmt, typ) == (C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4):
        return np.stack(
            [(v >> 12) / 15.0, ((v >> 8) & 15) / 15.0, ((v >> 4) & 15) / 15.0, (v & 15) / 15.0], axis=-1
        )
    if (fmt, typ) == (C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1):
        return np.stack(
            [(v >> 11) / 31.0, ((v >> 6) & 31) / 31.0, ((v >> 1) & 31) / 31.0, (v & 1) * 1.0], axis=-1
        )
    raise Unsupported(f"no unpacking rule for format 0x{fmt:04X} type 0x{typ:04X}")


@conformance_test("ReadFormat", section="4.3.1", visuals=("rgba8888", "rgb565", "rgba4444", "rgba5551"))
def read_format(t: TestContext) -> None:
    """OES_read_format: the implementation's pair reads the same pixels as RGBA/UNSIGNED_BYTE."""
    gl = t.gl
    fmt = int(gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES))
    typ = int(gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_TYPE_OES))
    t.check_gl_error("GetIntegerv(IMPLEMENTATION_COLOR_READ_FORMAT/TYPE_OES)")
    table_3_4 = {
        (C.GL_RGBA, C.GL_UNSIGNED_BYTE),
        (C.GL_RGB, C.GL_UNSIGNED_BYTE),
        (C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4),
        (C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1),
        (C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5),
        (C.GL_LUMINANCE_ALPHA, C.GL_UNSIGNED_BYTE),
        (C.GL_LUMINANCE, C.GL_UNSIGNED_BYTE),
        (C.GL_ALPHA, C.GL_UNSIGNED_BYTE),
        (C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE),
    }
    if (fmt, typ) not in table_3_4:
        t.fail(f"IMPLEMENTATION_COLOR_READ format 0x{fmt:04X} type 0x{typ:04X} is not a Table 3.4 pair")
    if fmt in (C.GL_LUMINANCE, C.GL_LUMINANCE_ALPHA, C.GL_ALPHA):
        raise Unsupported(f"read format 0x{fmt:04X} drops colour channels; nothing to compare")
    w, h = t.width, t.height
    t.ortho_pixels()
    t.clear((0.25, 0.5, 0.75, 1.0))
    # a ramp of colours: quads of distinct colours across the window
    cols = [
        (255, 0, 0, 255),
        (0, 255, 0, 255),
        (0, 0, 255, 255),
        (255, 255, 255, 255),
        (128, 64, 32, 255),
        (17, 200, 99, 255),
        (250, 130, 5, 255),
        (0, 0, 0, 255),
    ]
    for i, c in enumerate(cols):
        x0 = i * w // len(cols)
        x1 = (i + 1) * w // len(cols)
        t.draw(gl.GL_TRIANGLE_STRIP, [x0, 0, x1, 0, x0, h // 2, x1, h // 2], [c] * 4)
    ref = t.read()
    px = gl.glReadPixels(0, 0, w, h, fmt, typ)
    t.check_gl_error(f"ReadPixels(0x{fmt:04X}, 0x{typ:04X})")
    if px is None:
        t.fail(f"ReadPixels with the implementation's pair 0x{fmt:04X}/0x{typ:04X} returned nothing")
    got = _unpack(fmt, typ, px, h, w)
    # the pair may hold fewer bits than the visual: tolerance of the coarser of the two
    pair_bits = {
        C.GL_UNSIGNED_SHORT_5_6_5: (5, 6, 5, 0),
        C.GL_UNSIGNED_SHORT_4_4_4_4: (4, 4, 4, 4),
        C.GL_UNSIGNED_SHORT_5_5_5_1: (5, 5, 5, 1),
    }.get(typ, (8, 8, 8, 8))
    tol = np.array(
        [
            1.0 / ((1 << min(a, b)) - 1) + 2.0**-13 if min(a, b) else 1.0
            for a, b in zip(pair_bits, t.visual.bits)
        ]
    )
    if fmt == C.GL_RGB or t.visual.bits[3] == 0:
        tol[3] = 1.0
    diff = np.abs(got - ref) > tol
    if diff.any():
        ys, xs = np.nonzero(diff.any(axis=-1))
        y, x = int(ys[0]), int(xs[0])
        t.fail(
            f"{int(diff.any(axis=-1).sum())} pixels differ between RGBA/UNSIGNED_BYTE and "
            f"0x{fmt:04X}/0x{typ:04X}; first at ({x}, {y}): {ref[y, x].tolist()} vs {got[y, x].tolist()}"
        )
