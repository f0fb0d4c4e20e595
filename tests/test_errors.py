"""GL errors (ES 1.1 §2.5) of every command that exists, one table row per rule.

For each row the test checks that the command records the right error; that
only the first error is kept until glGetError reads it (the same call again
and a call with a different error do not replace it, and the next GetError
returns NO_ERROR); and that the failing command changed nothing: a broad
snapshot of queried state, the framebuffer, buffer objects and anything the
command could write through a pointer is compared before and after.

Errors do not depend on the numeric build; the table runs on the fixed build.
"""

from __future__ import annotations

from typing import Any, Callable, NamedTuple

import numpy as np
import pytest

import gles
from gles import gl as G

# desktop OpenGL tokens that ES 1.1 does not accept
GL_TEXTURE_1D = 0x0DE0
GL_QUADS = 0x0007
GL_EDGE_FLAG_ARRAY = 0x8079
GL_STREAM_DRAW = 0x88E0
GL_PACK_ROW_LENGTH = 0x0D02
GL_COLOR = 0x1800
GL_ACCUM_BUFFER_BIT = 0x0200
GL_INT = 0x1404

W = H = 16
TRI = np.array([1, 1, 14, 2, 4, 13], dtype=np.int16)

INT_STATE = [
    G.GL_VIEWPORT, G.GL_SCISSOR_BOX, G.GL_DEPTH_FUNC, G.GL_CULL_FACE_MODE, G.GL_FRONT_FACE,
    G.GL_SHADE_MODEL, G.GL_MATRIX_MODE, G.GL_PACK_ALIGNMENT, G.GL_UNPACK_ALIGNMENT,
    G.GL_ACTIVE_TEXTURE, G.GL_CLIENT_ACTIVE_TEXTURE, G.GL_ARRAY_BUFFER_BINDING,
    G.GL_ELEMENT_ARRAY_BUFFER_BINDING, G.GL_PERSPECTIVE_CORRECTION_HINT, G.GL_POINT_SMOOTH_HINT,
    G.GL_LINE_SMOOTH_HINT, G.GL_FOG_HINT, G.GL_GENERATE_MIPMAP_HINT, G.GL_MODELVIEW_STACK_DEPTH,
    G.GL_PROJECTION_STACK_DEPTH, G.GL_TEXTURE_STACK_DEPTH, G.GL_VERTEX_ARRAY_SIZE,
    G.GL_VERTEX_ARRAY_TYPE, G.GL_VERTEX_ARRAY_STRIDE, G.GL_VERTEX_ARRAY_BUFFER_BINDING,
    G.GL_NORMAL_ARRAY_TYPE, G.GL_NORMAL_ARRAY_STRIDE, G.GL_NORMAL_ARRAY_BUFFER_BINDING,
    G.GL_COLOR_ARRAY_SIZE, G.GL_COLOR_ARRAY_TYPE, G.GL_COLOR_ARRAY_STRIDE,
    G.GL_COLOR_ARRAY_BUFFER_BINDING, G.GL_TEXTURE_COORD_ARRAY_SIZE, G.GL_TEXTURE_COORD_ARRAY_TYPE,
    G.GL_TEXTURE_COORD_ARRAY_STRIDE, G.GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
    G.GL_POINT_SIZE_ARRAY_TYPE_OES, G.GL_POINT_SIZE_ARRAY_STRIDE_OES,
    G.GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES, G.GL_STENCIL_CLEAR_VALUE, G.GL_COLOR_WRITEMASK,
    G.GL_DEPTH_WRITEMASK,
]
FLOAT_STATE = [
    G.GL_MODELVIEW_MATRIX, G.GL_PROJECTION_MATRIX, G.GL_TEXTURE_MATRIX, G.GL_CURRENT_COLOR,
    G.GL_CURRENT_NORMAL, G.GL_CURRENT_TEXTURE_COORDS, G.GL_DEPTH_RANGE, G.GL_COLOR_CLEAR_VALUE,
    G.GL_DEPTH_CLEAR_VALUE,
]
CAPS = [
    G.GL_ALPHA_TEST, G.GL_BLEND, G.GL_COLOR_LOGIC_OP, G.GL_COLOR_MATERIAL, G.GL_CULL_FACE,
    G.GL_DEPTH_TEST, G.GL_DITHER, G.GL_FOG, G.GL_LIGHTING, G.GL_LINE_SMOOTH, G.GL_MULTISAMPLE,
    G.GL_NORMALIZE, G.GL_POINT_SMOOTH, G.GL_POLYGON_OFFSET_FILL, G.GL_RESCALE_NORMAL,
    G.GL_SAMPLE_ALPHA_TO_COVERAGE, G.GL_SAMPLE_ALPHA_TO_ONE, G.GL_SAMPLE_COVERAGE, G.GL_SCISSOR_TEST,
    G.GL_STENCIL_TEST, G.GL_TEXTURE_2D, G.GL_CLIP_PLANE0, G.GL_LIGHT0, G.GL_VERTEX_ARRAY,
    G.GL_NORMAL_ARRAY, G.GL_COLOR_ARRAY, G.GL_TEXTURE_COORD_ARRAY, G.GL_POINT_SIZE_ARRAY_OES,
]
# state of the later stages, compared by the same snapshot
INT_STATE += [
    G.GL_ALPHA_TEST_FUNC, G.GL_STENCIL_FUNC, G.GL_STENCIL_REF, G.GL_STENCIL_VALUE_MASK,
    G.GL_STENCIL_WRITEMASK, G.GL_STENCIL_FAIL, G.GL_STENCIL_PASS_DEPTH_FAIL, G.GL_STENCIL_PASS_DEPTH_PASS,
    G.GL_BLEND_SRC, G.GL_BLEND_DST, G.GL_LOGIC_OP_MODE, G.GL_FOG_MODE, G.GL_TEXTURE_BINDING_2D,
    G.GL_MATRIX_INDEX_ARRAY_SIZE_OES, G.GL_WEIGHT_ARRAY_SIZE_OES, G.GL_CURRENT_PALETTE_MATRIX_OES,
]
FLOAT_STATE += [
    G.GL_ALPHA_TEST_REF, G.GL_FOG_DENSITY, G.GL_FOG_START, G.GL_FOG_END, G.GL_FOG_COLOR,
    G.GL_LIGHT_MODEL_AMBIENT, G.GL_POINT_SIZE, G.GL_LINE_WIDTH, G.GL_POINT_SIZE_MIN, G.GL_POINT_SIZE_MAX,
    G.GL_POINT_FADE_THRESHOLD_SIZE, G.GL_POINT_DISTANCE_ATTENUATION, G.GL_POLYGON_OFFSET_FACTOR,
    G.GL_POLYGON_OFFSET_UNITS, G.GL_SAMPLE_COVERAGE_VALUE,
]
LIGHT_STATE = [G.GL_AMBIENT, G.GL_DIFFUSE, G.GL_SPECULAR, G.GL_POSITION, G.GL_SPOT_DIRECTION,
               G.GL_SPOT_EXPONENT, G.GL_SPOT_CUTOFF, G.GL_CONSTANT_ATTENUATION, G.GL_LINEAR_ATTENUATION,
               G.GL_QUADRATIC_ATTENUATION]
MATERIAL_STATE = [G.GL_AMBIENT, G.GL_DIFFUSE, G.GL_SPECULAR, G.GL_EMISSION, G.GL_SHININESS]
TEXENV_STATE = [G.GL_TEXTURE_ENV_MODE, G.GL_TEXTURE_ENV_COLOR, G.GL_COMBINE_RGB, G.GL_COMBINE_ALPHA,
                G.GL_SRC0_RGB, G.GL_OPERAND0_RGB, G.GL_RGB_SCALE, G.GL_ALPHA_SCALE]
TEXPARAM_STATE = [G.GL_TEXTURE_MIN_FILTER, G.GL_TEXTURE_MAG_FILTER, G.GL_TEXTURE_WRAP_S, G.GL_TEXTURE_WRAP_T,
                  G.GL_GENERATE_MIPMAP, G.GL_TEXTURE_CROP_RECT_OES]
POINTERS = [G.GL_VERTEX_ARRAY_POINTER, G.GL_NORMAL_ARRAY_POINTER, G.GL_COLOR_ARRAY_POINTER,
            G.GL_TEXTURE_COORD_ARRAY_POINTER, G.GL_POINT_SIZE_ARRAY_POINTER_OES]


def snapshot(ctx: gles.Context) -> dict[str, Any]:
    """Everything queryable that an erring command could have changed."""
    g = ctx.gl
    s: dict[str, Any] = {}
    for p in INT_STATE:
        s[repr(p)] = g.glGetIntegerv(p)
    for p in FLOAT_STATE:
        s[repr(p)] = g.glGetFloatv(p)
    for p in CAPS:
        s[f"enabled {p!r}"] = g.glIsEnabled(p)
    for p in POINTERS:
        s[repr(p)] = g.glGetPointerv(p)
    for p in LIGHT_STATE:
        s[f"light0 {p!r}"] = np.asarray(g.glGetLightfv(G.GL_LIGHT0, p)).tolist()
    for p in MATERIAL_STATE:
        s[f"material {p!r}"] = np.asarray(g.glGetMaterialfv(G.GL_FRONT, p)).tolist()
    for p in TEXENV_STATE:
        s[f"texenv {p!r}"] = np.asarray(g.glGetTexEnvfv(G.GL_TEXTURE_ENV, p)).tolist()
    s["coord replace"] = g.glGetTexEnviv(G.GL_POINT_SPRITE_OES, G.GL_COORD_REPLACE_OES)
    for p in TEXPARAM_STATE:
        s[f"texparam {p!r}"] = np.asarray(g.glGetTexParameterfv(G.GL_TEXTURE_2D, p)).tolist()
    for name in range(1, 9):
        s[f"IsBuffer({name})"] = g.glIsBuffer(name)
    for target, binding in ((G.GL_ARRAY_BUFFER, G.GL_ARRAY_BUFFER_BINDING),
                            (G.GL_ELEMENT_ARRAY_BUFFER, G.GL_ELEMENT_ARRAY_BUFFER_BINDING)):
        if g.glGetIntegerv(binding):
            s[f"{target!r} size"] = g.glGetBufferParameteriv(target, G.GL_BUFFER_SIZE)
            s[f"{target!r} usage"] = g.glGetBufferParameteriv(target, G.GL_BUFFER_USAGE)
    s["color buffer"] = ctx.color_buffer()
    s["depth buffer"] = ctx.depth_buffer()
    s["stencil buffer"] = ctx.stencil_buffer()
    return s


def assert_same(before: dict[str, Any], after: dict[str, Any]) -> None:
    assert before.keys() == after.keys()
    for k in before:
        np.testing.assert_array_equal(np.asarray(after[k]), np.asarray(before[k]), err_msg=k)


def base(ctx: gles.Context) -> None:
    """Non-default state in every area, and something drawn, so that a reset shows."""
    g = ctx.gl
    g.glViewport(1, 0, 14, 15)
    g.glScissor(2, 3, 11, 12)
    g.glClearColorx(0x1000, 0x8000, 0x4000, 0xFFFF)
    g.glClearDepthx(0xC000)
    g.glClearStencil(5)
    g.glClear(G.GL_COLOR_BUFFER_BIT | G.GL_DEPTH_BUFFER_BIT | G.GL_STENCIL_BUFFER_BIT)
    g.glEnable(G.GL_DEPTH_TEST)
    g.glDepthFunc(G.GL_LEQUAL)
    g.glCullFace(G.GL_FRONT)
    g.glFrontFace(G.GL_CW)
    g.glShadeModel(G.GL_FLAT)
    g.glHint(G.GL_FOG_HINT, G.GL_NICEST)
    g.glPixelStorei(G.GL_PACK_ALIGNMENT, 2)
    g.glMatrixMode(G.GL_MODELVIEW)
    g.glPushMatrix()
    g.glTranslatex(0x800, 0, 0)
    g.glColor4ub(200, 100, 50, 25)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glMatrixMode(G.GL_PROJECTION)
    g.glOrthox(0, W << 16, 0, H << 16, -1 << 16, 1 << 16)
    g.glVertexPointer(2, G.GL_SHORT, 0, TRI)
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    g.glColor4x(0x1000, 0x2000, 0x3000, 0x4000)


def with_buffers(g) -> None:
    """Array and element buffers bound, with data, and arrays sourced from them."""
    a, e = (int(n) for n in g.glGenBuffers(2))
    g.glBindBuffer(G.GL_ARRAY_BUFFER, a)
    g.glBufferData(G.GL_ARRAY_BUFFER, 12, TRI, G.GL_DYNAMIC_DRAW)
    g.glVertexPointer(2, G.GL_SHORT, 0, 0)
    g.glBindBuffer(G.GL_ELEMENT_ARRAY_BUFFER, e)
    g.glBufferData(G.GL_ELEMENT_ARRAY_BUFFER, 3, bytes([0, 1, 2]), G.GL_STATIC_DRAW)


def unbound(g) -> None:
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 0)
    g.glBindBuffer(G.GL_ELEMENT_ARRAY_BUFFER, 0)


def full_stack(g) -> None:
    g.glMatrixMode(G.GL_PROJECTION)
    for _ in range(g.glGetIntegerv(G.GL_MAX_PROJECTION_STACK_DEPTH) - 1):
        g.glPushMatrix()


def sentinel(g) -> bytearray:
    """A pixel buffer for ReadPixels, filled with a pattern an erring read must not touch."""
    return bytearray(b"\xa5" * 4096)


class Row(NamedTuple):
    id: str
    section: str
    call: Callable[..., Any]
    error: int
    setup: Callable[..., Any] | None = None
    returns: Any = "any"  # what the erring call must return ("any": not checked)


def _rp(fmt, typ, w=2, h=2):
    return lambda g, env: g.glReadPixels(0, 0, w, h, fmt, typ, array=env)


E, V, OP = G.GL_INVALID_ENUM, G.GL_INVALID_VALUE, G.GL_INVALID_OPERATION
UNITS = 4  # MAX_TEXTURE_UNITS, checked by test_limits_used_by_the_table
PLANES = 6  # MAX_CLIP_PLANES, likewise

ROWS = [
    # enables (§2.5 implicit rule on the caps listed in each section)
    Row("Enable bad cap", "§2.5", lambda g, e: g.glEnable(GL_TEXTURE_1D), E),
    Row("Disable bad cap", "§2.5", lambda g, e: g.glDisable(GL_TEXTURE_1D), E),
    Row("Enable client array cap", "§2.5, §2.8", lambda g, e: g.glEnable(G.GL_VERTEX_ARRAY), E),
    Row("Enable LIGHT8", "§2.12.1", lambda g, e: g.glEnable(G.GL_LIGHT0 + 8), E),
    Row("Enable CLIP_PLANE beyond max", "§2.11",
        lambda g, e: g.glEnable(G.GL_CLIP_PLANE0 + PLANES), E),
    Row("IsEnabled bad cap", "§6.1.1", lambda g, e: g.glIsEnabled(GL_TEXTURE_1D), E, returns=False),
    Row("EnableClientState bad array", "§2.8", lambda g, e: g.glEnableClientState(GL_EDGE_FLAG_ARRAY), E),
    Row("EnableClientState server cap", "§2.8", lambda g, e: g.glEnableClientState(G.GL_TEXTURE_2D), E),
    Row("DisableClientState bad array", "§2.8", lambda g, e: g.glDisableClientState(GL_EDGE_FLAG_ARRAY), E),
    # simple state
    Row("DepthFunc bad", "§4.1.6", lambda g, e: g.glDepthFunc(G.GL_NEVER - 1), E),
    Row("DepthFunc other enum", "§4.1.6", lambda g, e: g.glDepthFunc(G.GL_FRONT), E),
    Row("CullFace bad", "§3.5.1", lambda g, e: g.glCullFace(G.GL_CW), E),
    Row("FrontFace bad", "§3.5.1", lambda g, e: g.glFrontFace(G.GL_FRONT), E),
    Row("ShadeModel bad", "§2.12.6", lambda g, e: g.glShadeModel(G.GL_FLAT + 2), E),
    Row("Hint bad target", "§5.2", lambda g, e: g.glHint(G.GL_FOG, G.GL_NICEST), E),
    Row("Hint bad mode", "§5.2", lambda g, e: g.glHint(G.GL_FOG_HINT, G.GL_LINEAR), E),
    Row("MatrixMode bad", "§2.10.2", lambda g, e: g.glMatrixMode(GL_COLOR), E),
    Row("PixelStorei bad pname", "§3.6.1", lambda g, e: g.glPixelStorei(GL_PACK_ROW_LENGTH, 4), E),
    Row("PixelStorei alignment 3", "§3.6.1", lambda g, e: g.glPixelStorei(G.GL_PACK_ALIGNMENT, 3), V),
    Row("PixelStorei alignment 0", "§3.6.1", lambda g, e: g.glPixelStorei(G.GL_UNPACK_ALIGNMENT, 0), V),
    Row("PixelStorei alignment 16", "§3.6.1", lambda g, e: g.glPixelStorei(G.GL_PACK_ALIGNMENT, 16), V),
    Row("ActiveTexture beyond units", "§2.10.2",
        lambda g, e: g.glActiveTexture(G.GL_TEXTURE0 + UNITS), E),
    Row("ActiveTexture not a unit", "§2.10.2", lambda g, e: g.glActiveTexture(G.GL_TEXTURE_2D), E),
    Row("ClientActiveTexture beyond units", "§2.8",
        lambda g, e: g.glClientActiveTexture(G.GL_TEXTURE0 + UNITS), E),
    Row("MultiTexCoord bad unit", "§2.7",
        lambda g, e: g.glMultiTexCoord4x(G.GL_TEXTURE0 + UNITS, 1, 2, 3, 4), E),
    Row("Viewport negative width", "§2.10.1", lambda g, e: g.glViewport(0, 0, -1, 4), V),
    Row("Viewport negative height", "§2.10.1", lambda g, e: g.glViewport(0, 0, 4, -8), V),
    Row("Scissor negative width", "§4.1.2", lambda g, e: g.glScissor(0, 0, -3, 4), V),
    Row("Scissor negative height", "§4.1.2", lambda g, e: g.glScissor(1, 1, 4, -1), V),
    Row("Clear other bit", "§4.2.3",
        lambda g, e: g.glClear(G.GL_COLOR_BUFFER_BIT | GL_ACCUM_BUFFER_BIT), V),
    Row("Clear bit 0", "§4.2.3", lambda g, e: g.glClear(G.GL_DEPTH_BUFFER_BIT | 1), V),
    # matrices
    Row("PushMatrix overflow", "§2.10.2", lambda g, e: g.glPushMatrix(), G.GL_STACK_OVERFLOW, full_stack),
    Row("PopMatrix underflow", "§2.10.2",
        lambda g, e: (g.glMatrixMode(G.GL_TEXTURE), g.glPopMatrix()), G.GL_STACK_UNDERFLOW,
        lambda g: g.glMatrixMode(G.GL_TEXTURE)),
    Row("Frustum n <= 0", "§2.10.2", lambda g, e: g.glFrustumx(-1, 1, -1, 1, 0, 1 << 16), V),
    Row("Ortho l == r", "§2.10.2", lambda g, e: g.glOrthox(1, 1, -1, 1, -1, 1), V),
    Row("ClipPlane bad plane", "§2.11",
        lambda g, e: g.glClipPlanex(G.GL_CLIP_PLANE0 + PLANES, [1, 0, 0, 0]), E),
    # drawing
    Row("DrawArrays negative first", "§2.8", lambda g, e: g.glDrawArrays(G.GL_TRIANGLES, -1, 3), V),
    Row("DrawArrays negative count", "§2.8, §2.5", lambda g, e: g.glDrawArrays(G.GL_TRIANGLES, 0, -3), V),
    Row("DrawArrays bad mode", "§2.6.1", lambda g, e: g.glDrawArrays(GL_QUADS, 0, 3), E),
    Row("DrawArrays mode beyond FAN", "§2.6.1", lambda g, e: g.glDrawArrays(G.GL_TRIANGLE_FAN + 1, 0, 3), E),
    Row("DrawElements negative count", "§2.8, §2.5",
        lambda g, e: g.glDrawElements(G.GL_TRIANGLES, -3, G.GL_UNSIGNED_BYTE, bytes([0, 1, 2])), V),
    Row("DrawElements bad mode", "§2.6.1",
        lambda g, e: g.glDrawElements(GL_QUADS, 3, G.GL_UNSIGNED_BYTE, bytes([0, 1, 2])), E),
    # (UNSIGNED_INT is an index type: OES_element_index_uint)
    Row("DrawElements type INT", "§2.8",
        lambda g, e: g.glDrawElements(G.GL_TRIANGLES, 3, GL_INT, np.arange(3, dtype=np.int32)), E),
    Row("DrawElements type BYTE", "§2.8",
        lambda g, e: g.glDrawElements(G.GL_TRIANGLES, 3, G.GL_BYTE, bytes([0, 1, 2])), E),
    Row("DrawElements type SHORT, element buffer", "§2.8, §2.9.2",
        lambda g, e: g.glDrawElements(G.GL_TRIANGLES, 3, G.GL_SHORT, 0), E, with_buffers),
    # array pointers (Table 2.4)
    Row("VertexPointer size 1", "§2.8", lambda g, e: g.glVertexPointer(1, G.GL_FLOAT, 0, None), V),
    Row("VertexPointer size 5", "§2.8", lambda g, e: g.glVertexPointer(5, G.GL_FLOAT, 0, None), V),
    Row("VertexPointer negative stride", "§2.8", lambda g, e: g.glVertexPointer(3, G.GL_FLOAT, -4, None), V),
    Row("VertexPointer type UNSIGNED_BYTE", "§2.8",
        lambda g, e: g.glVertexPointer(3, G.GL_UNSIGNED_BYTE, 0, None), E),
    Row("VertexPointer type INT", "§2.8", lambda g, e: g.glVertexPointer(3, GL_INT, 0, None), E),
    Row("ColorPointer size 3", "§2.8", lambda g, e: g.glColorPointer(3, G.GL_UNSIGNED_BYTE, 0, None), V),
    Row("ColorPointer negative stride", "§2.8",
        lambda g, e: g.glColorPointer(4, G.GL_UNSIGNED_BYTE, -1, None), V),
    Row("ColorPointer type BYTE", "§2.8", lambda g, e: g.glColorPointer(4, G.GL_BYTE, 0, None), E),
    Row("ColorPointer type SHORT", "§2.8", lambda g, e: g.glColorPointer(4, G.GL_SHORT, 0, None), E),
    Row("NormalPointer type UNSIGNED_BYTE", "§2.8",
        lambda g, e: g.glNormalPointer(G.GL_UNSIGNED_BYTE, 0, None), E),
    Row("NormalPointer negative stride", "§2.8", lambda g, e: g.glNormalPointer(G.GL_FLOAT, -12, None), V),
    Row("TexCoordPointer size 1", "§2.8", lambda g, e: g.glTexCoordPointer(1, G.GL_FLOAT, 0, None), V),
    Row("TexCoordPointer type UNSIGNED_SHORT", "§2.8",
        lambda g, e: g.glTexCoordPointer(2, G.GL_UNSIGNED_SHORT, 0, None), E),
    Row("TexCoordPointer negative stride", "§2.8",
        lambda g, e: g.glTexCoordPointer(2, G.GL_FLOAT, -8, None), V),
    Row("PointSizePointerOES type SHORT", "§2.8",
        lambda g, e: g.glPointSizePointerOES(G.GL_SHORT, 0, None), E),
    Row("PointSizePointerOES type BYTE", "§2.8",
        lambda g, e: g.glPointSizePointerOES(G.GL_BYTE, 0, None), E),
    Row("PointSizePointerOES negative stride", "§2.8",
        lambda g, e: g.glPointSizePointerOES(G.GL_FIXED, -4, None), V),
    # buffer objects
    Row("GenBuffers negative n", "§2.9, §2.5", lambda g, e: g.glGenBuffers(-1), V),
    Row("DeleteBuffers negative n", "§2.9, §2.5", lambda g, e: g.glDeleteBuffers(-1, [1]), V, with_buffers),
    Row("BindBuffer bad target", "§2.9", lambda g, e: g.glBindBuffer(G.GL_TEXTURE_2D, 3), E),
    Row("BufferData bad target", "§2.9",
        lambda g, e: g.glBufferData(G.GL_TEXTURE_2D, 4, bytes(4), G.GL_STATIC_DRAW), E, with_buffers),
    Row("BufferData bad usage", "§2.9",
        lambda g, e: g.glBufferData(G.GL_ARRAY_BUFFER, 4, bytes(4), GL_STREAM_DRAW), E, with_buffers),
    Row("BufferData negative size", "§2.9",
        lambda g, e: g.glBufferData(G.GL_ARRAY_BUFFER, -4, None, G.GL_STATIC_DRAW), V, with_buffers),
    Row("BufferData no buffer bound", "§2.9",
        lambda g, e: g.glBufferData(G.GL_ARRAY_BUFFER, 4, bytes(4), G.GL_STATIC_DRAW), OP, unbound),
    Row("BufferData no element buffer bound", "§2.9.2",
        lambda g, e: g.glBufferData(G.GL_ELEMENT_ARRAY_BUFFER, 4, bytes(4), G.GL_STATIC_DRAW), OP, unbound),
    Row("BufferSubData no buffer bound", "§2.9",
        lambda g, e: g.glBufferSubData(G.GL_ARRAY_BUFFER, 0, 4, bytes(4)), OP, unbound),
    Row("BufferSubData bad target", "§2.9",
        lambda g, e: g.glBufferSubData(G.GL_TEXTURE_2D, 0, 4, bytes(4)), E, with_buffers),
    Row("BufferSubData past the end", "§2.9",
        lambda g, e: g.glBufferSubData(G.GL_ARRAY_BUFFER, 10, 4, bytes(4)), V, with_buffers),
    Row("BufferSubData offset past the end", "§2.9",
        lambda g, e: g.glBufferSubData(G.GL_ARRAY_BUFFER, 13, 0, b""), V, with_buffers),
    Row("BufferSubData negative offset", "§2.9",
        lambda g, e: g.glBufferSubData(G.GL_ARRAY_BUFFER, -1, 2, bytes(2)), V, with_buffers),
    Row("BufferSubData element buffer past the end", "§2.9.2",
        lambda g, e: g.glBufferSubData(G.GL_ELEMENT_ARRAY_BUFFER, 0, 4, bytes(4)), V, with_buffers),
    Row("GetBufferParameteriv bad pname", "§6.1.3",
        lambda g, e: g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_USAGE + 100), E,
        with_buffers, 0),
    Row("GetBufferParameteriv bad target", "§6.1.3",
        lambda g, e: g.glGetBufferParameteriv(G.GL_TEXTURE_2D, G.GL_BUFFER_SIZE), E, with_buffers, 0),
    Row("GetBufferParameteriv no buffer bound", "§2.9, §6.1.3",
        lambda g, e: g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_SIZE), OP, unbound, 0),
    # pixels
    Row("ReadPixels bad format", "§4.3.1, §2.5", _rp(G.GL_TEXTURE_2D, G.GL_UNSIGNED_BYTE), E, sentinel),
    Row("ReadPixels bad type", "§4.3.1, §2.5", _rp(G.GL_RGBA, G.GL_FLOAT), E, sentinel),
    Row("ReadPixels type/format mismatch", "§3.6.2",
        _rp(G.GL_RGBA, G.GL_UNSIGNED_SHORT_5_6_5), OP, sentinel),
    Row("ReadPixels pair not offered", "§4.3.1",
        _rp(G.GL_RGB, G.GL_UNSIGNED_SHORT_5_6_5), OP, sentinel),
    Row("ReadPixels negative width", "§4.3.1, §2.5",
        _rp(G.GL_RGBA, G.GL_UNSIGNED_BYTE, w=-1), V, sentinel),
    Row("ReadPixels negative height", "§4.3.1, §2.5",
        _rp(G.GL_RGBA, G.GL_UNSIGNED_BYTE, h=-2), V, sentinel),
    Row("ReadPixels negative width, returned array", "§4.3.1, §2.5",
        lambda g, e: g.glReadPixels(0, 0, -1, 2, G.GL_RGBA, G.GL_UNSIGNED_BYTE), V, None, None),
    Row("ReadPixels bad format, returned array", "§4.3.1",
        lambda g, e: g.glReadPixels(0, 0, 2, 2, G.GL_TEXTURE_2D, G.GL_UNSIGNED_BYTE), E, None, None),
    # queries
    Row("GetIntegerv unknown pname", "§6.1.1", lambda g, e: g.glGetIntegerv(0x0DE0), E, None, None),
    Row("GetFloatv unknown pname", "§6.1.1", lambda g, e: g.glGetFloatv(0x0DE0), E, None, None),
    Row("GetFixedv unknown pname", "§6.1.1", lambda g, e: g.glGetFixedv(0x0DE0), E, None, None),
    Row("GetBooleanv unknown pname", "§6.1.1", lambda g, e: g.glGetBooleanv(0x0DE0), E, None, None),
    Row("GetClipPlane bad plane", "§6.1.3",
        lambda g, e: g.glGetClipPlanef(G.GL_CLIP_PLANE0 + PLANES), E, None, "any"),
    Row("GetString bad name", "§6.1.5", lambda g, e: g.glGetString(G.GL_VIEWPORT), E, None, None),
    Row("GetPointerv bad pname", "§6.1.5", lambda g, e: g.glGetPointerv(G.GL_VERTEX_ARRAY_SIZE), E, None, 0),
    # lighting (§2.12.2)
    Row("Light bad light", "§2.12.2", lambda g, e: g.glLightf(G.GL_LIGHT0 + 8, G.GL_SPOT_EXPONENT, 1.0), E),
    Row("Light bad pname", "§2.12.2", lambda g, e: g.glLightf(G.GL_LIGHT0, G.GL_SHININESS, 1.0), E),
    Row("Light scalar with vector pname", "§2.12.2",
        lambda g, e: g.glLightf(G.GL_LIGHT0, G.GL_AMBIENT, 0.5), E),
    Row("Light spot exponent above 128", "§2.12.2",
        lambda g, e: g.glLightf(G.GL_LIGHT0, G.GL_SPOT_EXPONENT, 129.0), V),
    Row("Light spot exponent negative", "§2.12.2",
        lambda g, e: g.glLightx(G.GL_LIGHT0, G.GL_SPOT_EXPONENT, -1), V),
    Row("Light cutoff 91", "§2.12.2", lambda g, e: g.glLightf(G.GL_LIGHT0, G.GL_SPOT_CUTOFF, 91.0), V),
    Row("Light cutoff negative", "§2.12.2", lambda g, e: g.glLightf(G.GL_LIGHT0, G.GL_SPOT_CUTOFF, -1.0), V),
    Row("Light negative attenuation", "§2.12.2",
        lambda g, e: g.glLightf(G.GL_LIGHT0, G.GL_QUADRATIC_ATTENUATION, -0.5), V),
    Row("LightModel bad pname", "§2.12.2", lambda g, e: g.glLightModelf(G.GL_AMBIENT, 1.0), E),
    Row("Material face FRONT", "§2.12.2", lambda g, e: g.glMaterialf(G.GL_FRONT, G.GL_SHININESS, 1.0), E),
    Row("Material shininess above 128", "§2.12.2",
        lambda g, e: g.glMaterialf(G.GL_FRONT_AND_BACK, G.GL_SHININESS, 130.0), V),
    Row("Material bad pname", "§2.12.2",
        lambda g, e: g.glMaterialf(G.GL_FRONT_AND_BACK, G.GL_SPOT_CUTOFF, 1.0), E),
    Row("GetLight bad light", "§6.1.3", lambda g, e: g.glGetLightfv(G.GL_LIGHT0 + 8, G.GL_AMBIENT), E, None,
        None),
    Row("GetMaterial face FRONT_AND_BACK", "§6.1.3",
        lambda g, e: g.glGetMaterialfv(G.GL_FRONT_AND_BACK, G.GL_AMBIENT), E, None, None),
    # per-fragment operations and fog (§4.1, §3.8)
    Row("AlphaFunc bad", "§4.1.4", lambda g, e: g.glAlphaFunc(G.GL_FRONT, 0.5), E),
    Row("StencilFunc bad", "§4.1.5", lambda g, e: g.glStencilFunc(G.GL_FRONT, 0, 0xFF), E),
    Row("StencilOp bad", "§4.1.5", lambda g, e: g.glStencilOp(G.GL_KEEP, G.GL_FRONT, G.GL_KEEP), E),
    Row("BlendFunc SRC_COLOR as source", "§4.1.7", lambda g, e: g.glBlendFunc(G.GL_SRC_COLOR, G.GL_ZERO), E),
    Row("BlendFunc SRC_ALPHA_SATURATE as destination", "§4.1.7",
        lambda g, e: g.glBlendFunc(G.GL_ONE, G.GL_SRC_ALPHA_SATURATE), E),
    Row("BlendEquationOES bad", "OES_blend_subtract", lambda g, e: g.glBlendEquationOES(G.GL_ONE), E),
    Row("LogicOp bad", "§4.1.9", lambda g, e: g.glLogicOp(G.GL_FRONT), E),
    Row("Fog bad mode", "§3.8", lambda g, e: g.glFogf(G.GL_FOG_MODE, float(G.GL_NEAREST)), E),
    Row("Fog negative density", "§3.8", lambda g, e: g.glFogf(G.GL_FOG_DENSITY, -1.0), V),
    Row("Fog bad pname", "§3.8", lambda g, e: g.glFogf(G.GL_SHININESS, 1.0), E),
    Row("Fog scalar colour", "§3.8", lambda g, e: g.glFogf(G.GL_FOG_COLOR, 1.0), E),
    # points, lines, polygon offset (§3.3-3.5)
    Row("PointSize zero", "§3.3", lambda g, e: g.glPointSize(0.0), V),
    Row("PointSizex negative", "§3.3", lambda g, e: g.glPointSizex(-65536), V),
    Row("LineWidth zero", "§3.4", lambda g, e: g.glLineWidth(0.0), V),
    Row("PointParameter bad pname", "§3.3", lambda g, e: g.glPointParameterf(G.GL_POINT_SIZE, 1.0), E),
    Row("PointParameter negative min", "§3.3",
        lambda g, e: g.glPointParameterf(G.GL_POINT_SIZE_MIN, -1.0), V),
    Row("DrawTex zero width", "OES_draw_texture", lambda g, e: g.glDrawTexiOES(0, 0, 0, 0, 4), V),
    # textures (§3.7)
    Row("BindTexture bad target", "§3.7.13", lambda g, e: g.glBindTexture(GL_TEXTURE_1D, 1), E),
    Row("GenTextures negative", "§3.7.13", lambda g, e: g.glGenTextures(-1), V, None, None),
    Row("TexImage2D bad target", "§3.7.1", lambda g, e: g.glTexImage2D(GL_TEXTURE_1D, 0, G.GL_RGBA, 2, 2, 0,
        G.GL_RGBA, G.GL_UNSIGNED_BYTE, bytes(16)), E),
    Row("TexImage2D negative level", "§3.7.1", lambda g, e: g.glTexImage2D(G.GL_TEXTURE_2D, -1, G.GL_RGBA,
        2, 2, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, bytes(16)), V),
    Row("TexImage2D border 1", "§3.7.1", lambda g, e: g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 2, 2, 1,
        G.GL_RGBA, G.GL_UNSIGNED_BYTE, bytes(16)), V),
    # (any size up to the limit is legal: OES_texture_npot)
    Row("TexImage2D height beyond MAX_TEXTURE_SIZE", "§3.7.1", lambda g, e: g.glTexImage2D(G.GL_TEXTURE_2D, 0,
        G.GL_RGBA, 1, 2049, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None), V),
    Row("TexImage2D beyond MAX_TEXTURE_SIZE", "§3.7.1", lambda g, e: g.glTexImage2D(G.GL_TEXTURE_2D, 0,
        G.GL_RGBA, 4096, 1, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None), V),
    Row("TexImage2D internalformat differs", "§3.7.1", lambda g, e: g.glTexImage2D(G.GL_TEXTURE_2D, 0,
        G.GL_RGB, 2, 2, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, bytes(16)), OP),
    Row("TexImage2D 565 with RGBA", "§3.7.1", lambda g, e: g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA,
        2, 2, 0, G.GL_RGBA, G.GL_UNSIGNED_SHORT_5_6_5, bytes(8)), OP),
    Row("TexParameter bad filter", "§3.7.4", lambda g, e: g.glTexParameteri(G.GL_TEXTURE_2D,
        G.GL_TEXTURE_MAG_FILTER, G.GL_LINEAR_MIPMAP_LINEAR), E),
    Row("TexParameter bad wrap", "§3.7.4", lambda g, e: g.glTexParameteri(G.GL_TEXTURE_2D,
        G.GL_TEXTURE_WRAP_S, G.GL_LINEAR), E),
    Row("TexEnv bad mode", "§3.7.12", lambda g, e: g.glTexEnvi(G.GL_TEXTURE_ENV, G.GL_TEXTURE_ENV_MODE,
        G.GL_LINEAR), E),
    Row("TexEnv RGB_SCALE 3", "§3.7.12", lambda g, e: g.glTexEnvf(G.GL_TEXTURE_ENV, G.GL_RGB_SCALE, 3.0), V),
    Row("TexEnv bad target", "§3.7.12", lambda g, e: g.glTexEnvi(G.GL_TEXTURE_2D, G.GL_TEXTURE_ENV_MODE,
        G.GL_REPLACE), E),
    Row("CompressedTexImage2D bad format", "§3.7.3", lambda g, e: g.glCompressedTexImage2D(G.GL_TEXTURE_2D,
        0, G.GL_RGBA, 2, 2, 0, 16, bytes(16)), E),
    Row("CompressedTexSubImage2D on paletted", "OES_compressed_paletted_texture",
        lambda g, e: g.glCompressedTexSubImage2D(G.GL_TEXTURE_2D, 0, 0, 0, 2, 2, G.GL_PALETTE8_RGBA8_OES,
                                                 16, bytes(16)), OP),
    Row("CopyTexImage2D border 1", "§3.7.2", lambda g, e: g.glCopyTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA,
        0, 0, 2, 2, 1), V),
    # OES_matrix_palette
    Row("CurrentPaletteMatrixOES beyond the palette", "OES_matrix_palette",
        lambda g, e: g.glCurrentPaletteMatrixOES(32), V),
    Row("MatrixIndexPointerOES size 5", "OES_matrix_palette",
        lambda g, e: g.glMatrixIndexPointerOES(5, G.GL_UNSIGNED_BYTE, 0, bytes(10)), V),
    Row("WeightPointerOES bad type", "OES_matrix_palette",
        lambda g, e: g.glWeightPointerOES(2, G.GL_BYTE, 0, np.zeros(4, np.int8)), E),
]


def _other_error(g, error: int) -> None:
    """Record a different error than `error` (it must not replace the first)."""
    if error == G.GL_INVALID_ENUM:
        g.glPixelStorei(G.GL_PACK_ALIGNMENT, 5)  # INVALID_VALUE
    else:
        g.glMatrixMode(GL_COLOR)  # INVALID_ENUM


@pytest.mark.parametrize("row", ROWS, ids=lambda r: f"{r.section} {r.id}")
def test_error_rule(row: Row):
    """The command records the row's error, only the first error sticks, nothing changes."""
    ctx = gles.Context(W, H, numeric="fixed", depth=16, stencil=8)
    g = ctx.gl
    base(ctx)
    env = row.setup(g) if row.setup else None
    assert g.glGetError() == G.GL_NO_ERROR, "setup erred"
    before = snapshot(ctx)
    pristine = bytes(env) if isinstance(env, bytearray) else None
    assert g.glGetError() == G.GL_NO_ERROR

    result = row.call(g, env)
    if row.returns != "any":
        assert result == row.returns
    row.call(g, env)        # the same error again
    _other_error(g, row.error)
    assert g.glGetError() == row.error
    assert g.glGetError() == G.GL_NO_ERROR

    assert_same(before, snapshot(ctx))
    if pristine is not None:
        assert bytes(env) == pristine, "the erring ReadPixels wrote through its pointer"
    assert g.glGetError() == G.GL_NO_ERROR


def test_no_error_initially():
    """A new context has no error recorded (§2.5)."""
    g = gles.Context(4, 4).gl
    assert g.glGetError() == G.GL_NO_ERROR


def test_error_clears_after_read():
    """After GetError returns the code, a further error records its own code (§2.5)."""
    g = gles.Context(4, 4).gl
    g.glEnable(GL_TEXTURE_1D)
    assert g.glGetError() == G.GL_INVALID_ENUM
    g.glViewport(0, 0, -1, -1)
    assert g.glGetError() == G.GL_INVALID_VALUE
    g.glPopMatrix()
    assert g.glGetError() == G.GL_STACK_UNDERFLOW
    assert g.glGetError() == G.GL_NO_ERROR


def test_viewport_is_clamped_to_max_viewport_dims():
    """Viewport sizes beyond MAX_VIEWPORT_DIMS are clamped, without error (§2.10.1);
    the maximum is at least the window size."""
    g = gles.Context(W, H).gl
    mw, mh = (int(v) for v in g.glGetIntegerv(G.GL_MAX_VIEWPORT_DIMS))
    assert mw >= W and mh >= H
    g.glViewport(-5, 7, mw + 1, mh * 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert list(g.glGetIntegerv(G.GL_VIEWPORT)) == [-5, 7, mw, mh]
    g.glViewport(3, -2, mw, 2**31 - 1)
    assert list(g.glGetIntegerv(G.GL_VIEWPORT)) == [3, -2, mw, mh]
    g.glViewport(0, 0, 0, 0)  # zero is a legal size
    assert list(g.glGetIntegerv(G.GL_VIEWPORT)) == [0, 0, 0, 0]
    assert g.glGetError() == G.GL_NO_ERROR


def test_limits_used_by_the_table():
    """The table's out-of-range units and planes are just past the queried limits."""
    g = gles.Context(2, 2).gl
    assert g.glGetIntegerv(G.GL_MAX_TEXTURE_UNITS) == UNITS
    assert g.glGetIntegerv(G.GL_MAX_CLIP_PLANES) == PLANES


def test_buffer_data_out_of_memory():
    """§2.9: BufferData that cannot allocate records OUT_OF_MEMORY and raises
    nothing (it is a GL error); the buffer keeps its old contents and size."""
    g = gles.Context(W, H).gl
    g.glBindBuffer(G.GL_ARRAY_BUFFER, g.glGenBuffers(1))
    g.glBufferData(G.GL_ARRAY_BUFFER, 8, bytes(range(8)), G.GL_STATIC_DRAW)
    g.glBufferData(G.GL_ARRAY_BUFFER, 1 << 46, None, G.GL_STATIC_DRAW)
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_SIZE) == 8
