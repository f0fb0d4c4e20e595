"""Bad input never crashes the core, hangs a draw or leaks an exception that
is not the documented one.

Each test is a reproduction of a failure found by random call sequences
against a sanitizer build (or a rule of the spec about such input). A GL
rule gives the spec's GL error and leaves state unchanged; Python misuse
raises TypeError or ValueError naming the argument before C runs.
"""

from __future__ import annotations

import time
from typing import Any, Callable

import numpy as np
import pytest
from conftest import BUILDS
from test_errors import snapshot

import gles
from gles import gl as G

INT_MAX, INT_MIN = 2**31 - 1, -(2**31)


def ctx_of(numeric: str = "fixed", w: int = 16, h: int = 16, **kw: Any) -> gles.Context:
    return gles.Context(w, h, numeric=numeric, range_check="off", **kw)


def same(a: dict[str, Any], b: dict[str, Any]) -> bool:
    return a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)


# {====================================================================
# the three crashes


def test_read_pixels_huge_into_small_buffer() -> None:
    """(2^31-1)^2 RGBA pixels need more than 2^63 bytes: the size check must
    not overflow. A valid read into a short buffer is Python misuse
    (ValueError) and writes nothing."""
    ctx = ctx_of()
    buf = bytearray(b"\xab" * 16)
    with pytest.raises(ValueError, match="ReadPixels"):
        ctx.gl.glReadPixels(0, 0, INT_MAX, INT_MAX, G.GL_RGBA, G.GL_UNSIGNED_BYTE, buf)
    assert buf == bytearray(b"\xab" * 16)
    assert ctx.gl.glGetError() == G.GL_NO_ERROR


def test_read_pixels_huge_without_buffer() -> None:
    """Without a buffer only the part inside the framebuffer is read and
    allocated (the rest is undefined, §4.3.1), not 2^64 bytes; a GL error
    (bad format) still wins."""
    ctx = ctx_of()
    g = ctx.gl
    px = g.glReadPixels(0, 0, INT_MAX, INT_MAX, G.GL_RGBA, G.GL_UNSIGNED_BYTE)
    assert px.shape == (ctx.height, ctx.width, 4)
    assert np.array_equal(px, ctx.color_buffer())
    assert g.glGetError() == G.GL_NO_ERROR
    assert g.glReadPixels(0, 0, INT_MAX, INT_MAX, G.GL_RGBA, G.GL_FLOAT) is None
    assert g.glGetError() == G.GL_INVALID_ENUM


@pytest.mark.parametrize("size", [(2048, 0), (0, 2048), (0, 0), (1, 0)])
def test_generate_mipmap_of_an_empty_level(size: tuple[int, int]) -> None:
    """GENERATE_MIPMAP on a level 0 with a zero dimension derives empty
    levels (it used to box-filter a NULL image)."""
    ctx = ctx_of()
    g = ctx.gl
    g.glTexParameteri(G.GL_TEXTURE_2D, G.GL_GENERATE_MIPMAP, 1)
    g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, size[0], size[1], 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None)
    assert g.glGetError() == G.GL_NO_ERROR
    assert ctx.memory_used == 0


def test_generate_mipmap_after_a_full_image_then_an_empty_one() -> None:
    """An empty level 0 after a 4x4 one leaves no derived level behind (the
    budget's count drops to zero)."""
    ctx = ctx_of()
    g = ctx.gl
    g.glTexParameteri(G.GL_TEXTURE_2D, G.GL_GENERATE_MIPMAP, 1)
    g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 4, 4, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, bytes(64))
    assert ctx.memory_used == 4 * (16 + 4 + 1)
    g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 4, 0, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None)
    assert g.glGetError() == G.GL_NO_ERROR
    assert ctx.memory_used == 0


@pytest.mark.parametrize("call", ["data", "sub"])
def test_an_int_is_never_buffer_data(call: str) -> None:
    """BufferData/BufferSubData read bytes from data; an int there is not an
    address (the int-as-offset rule belongs to the pointer commands)."""
    ctx = ctx_of()
    g = ctx.gl
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 1)
    g.glBufferData(G.GL_ARRAY_BUFFER, 64, None, G.GL_STATIC_DRAW)
    before = snapshot(ctx)
    with pytest.raises(TypeError, match="not an int"):
        if call == "data":
            g.glBufferData(G.GL_ARRAY_BUFFER, 64, 4096, G.GL_STATIC_DRAW)
        else:
            g.glBufferSubData(G.GL_ARRAY_BUFFER, 0, 64, 4096)
    assert g.glGetError() == G.GL_NO_ERROR
    assert same(before, snapshot(ctx))


def test_buffer_data_short_data_after_the_gl_rules() -> None:
    """Data shorter than size raises only when the call is GL-valid; an
    invalid target, usage or unbound target gives its GL error instead."""
    g = ctx_of().gl
    g.glBufferData(G.GL_ARRAY_BUFFER, 8, b"1234", G.GL_STATIC_DRAW)      # nothing bound
    assert g.glGetError() == G.GL_INVALID_OPERATION
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 1)
    g.glBufferData(G.GL_ARRAY_BUFFER, 8, b"1234", 0x1234)
    assert g.glGetError() == G.GL_INVALID_ENUM
    with pytest.raises(ValueError, match="size is 8"):
        g.glBufferData(G.GL_ARRAY_BUFFER, 8, b"1234", G.GL_STATIC_DRAW)
    g.glBufferData(G.GL_ARRAY_BUFFER, 4, b"1234", G.GL_STATIC_DRAW)
    g.glBufferSubData(G.GL_ARRAY_BUFFER, 2, 8, b"12")                     # past the end
    assert g.glGetError() == G.GL_INVALID_VALUE
    with pytest.raises(ValueError, match="size is 4"):
        g.glBufferSubData(G.GL_ARRAY_BUFFER, 0, 4, b"12")


# {====================================================================
# draws whose time depends on bad coordinates

# a modelview of huge and infinite entries that left a 4-vertex LINE_LOOP's
# window coordinates near 2^40 subpixels (72 s per draw before lines were
# stepped only inside the clip rectangle)
HANG_MATRIX = [1.5928532041937506, 1.9421616677106952, -1e30, -1e30, 0.8986578380082597, -0.9512656227569223,
               -0.7295148358087187, -1.199937499926774, -0.15518161942642905, 1.0, 0.0, -1.0,
               1.8263239554671875, -1.0, 1.3201869020927721, -0.6508628411671227]
HANG_ROTATE = (-0.45822850510041047, 1.410389519232897, 1.5741520273644207, 1.3816180512746987)
HANG_VERTS = [0.749577262628776, -1.0, 0.572162655766665, 0.5906667757947535, -0.9305272649901268,
              0.900241535670157, -1.972832882754243, -0.07991063554058098]


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("mode", [G.GL_LINE_LOOP, G.GL_LINE_STRIP, G.GL_LINES, G.GL_POINTS,
                                  G.GL_TRIANGLE_FAN])
@pytest.mark.parametrize("smooth", [False, True])
def test_draw_time_does_not_depend_on_unclipped_coordinates(numeric: str, mode: int, smooth: bool) -> None:
    g = ctx_of(numeric, 31, 33).gl
    g.glPointParameterxv(G.GL_POINT_DISTANCE_ATTENUATION, [-204793, 156181, -65536])
    if smooth:
        g.glEnable(G.GL_LINE_SMOOTH)
        g.glEnable(G.GL_POINT_SMOOTH)
        g.glLineWidth(5.0)
    g.glLoadMatrixf(HANG_MATRIX)
    g.glRotatef(*HANG_ROTATE)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, np.array(HANG_VERTS, dtype=np.float32))
    t0 = time.perf_counter()
    for _ in range(10):
        g.glDrawArrays(mode, 0, 4)
    assert time.perf_counter() - t0 < 2.0
    assert g.glGetError() == G.GL_NO_ERROR


@pytest.mark.parametrize("numeric", BUILDS)
def test_non_finite_matrices_draw_in_bounded_time(numeric: str) -> None:
    """Every primitive under matrices holding inf, -inf, NaN and 1e30."""
    g = ctx_of(numeric, 31, 33).gl
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, np.array(HANG_VERTS, dtype=np.float32))
    rng = np.random.default_rng(19)
    specials = np.array([np.inf, -np.inf, np.nan, 1e30, -1e30, 0.0, 1e-30])
    t0 = time.perf_counter()
    for _ in range(60):
        m = rng.uniform(-2, 2, 16)
        pick = rng.random(16) < 0.3
        m[pick] = rng.choice(specials, int(pick.sum()))
        g.glLoadMatrixf(m)
        for mode in (G.GL_POINTS, G.GL_LINES, G.GL_LINE_LOOP, G.GL_TRIANGLES, G.GL_TRIANGLE_STRIP):
            g.glDrawArrays(mode, 0, 4)
    assert time.perf_counter() - t0 < 10.0
    assert g.glGetError() == G.GL_NO_ERROR


# {====================================================================
# out-of-range ints: ValueError naming the argument


RANGE_CASES: list[tuple[str, Callable[[Any], Any], str]] = [
    ("texture", lambda g: g.glBindTexture(G.GL_TEXTURE_2D, -1), "texture=-1"),
    ("buffer", lambda g: g.glIsBuffer(-1), "buffer=-1"),
    ("viewport", lambda g: g.glViewport(0, 0, 2**31, 8), "width=2147483648"),
    ("stencil", lambda g: g.glClearStencil(2**32), "s=4294967296"),
    ("copytex", lambda g: g.glCopyTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 0, 0, 4097, -2**40, 0),
     "height=-1099511627776"),
    ("enum", lambda g: g.glEnable(2**32), "cap=4294967296"),
    ("fixed", lambda g: g.glTranslatex(0, 2**31, 0), "y=2147483648"),
    ("fixed vector", lambda g: g.glLoadMatrixx([2**40] * 16), "glLoadMatrixx"),
    ("ubyte", lambda g: g.glColor4ub(0, 256, 0, 0), "256"),
    ("names", lambda g: g.glDeleteTextures(1, [-1]), "glDeleteTextures"),
    ("float", lambda g: g.glClearColor(2**1100, 0, 0, 0), "red="),
    ("buffer size", lambda g: g.glBufferData(G.GL_ARRAY_BUFFER, 2**63, None, G.GL_STATIC_DRAW), "size="),
    ("offset", lambda g: g.glVertexPointer(2, G.GL_FLOAT, 0, 2**64), "offset"),
    ("mask", lambda g: g.glStencilMask(2**32), "mask=4294967296"),
]


@pytest.mark.parametrize("case", RANGE_CASES, ids=[c[0] for c in RANGE_CASES])
def test_out_of_range_ints_raise_value_error(case: tuple[str, Callable[[Any], Any], str]) -> None:
    _, call, text = case
    ctx = ctx_of()
    before = snapshot(ctx)
    with pytest.raises(ValueError) as info:
        call(ctx.gl)
    assert text in str(info.value)
    assert ctx.gl.glGetError() == G.GL_NO_ERROR
    assert same(before, snapshot(ctx))


def test_a_float_for_an_int_is_a_type_error_naming_it() -> None:
    g = ctx_of().gl
    with pytest.raises(TypeError, match="width=2.5"):
        g.glViewport(0, 0, 2.5, 8)


def test_minus_one_is_the_all_ones_mask() -> None:
    """A GLuint mask given as a negative GLint is its two's complement, as in C."""
    g = ctx_of().gl
    g.glStencilMask(-1)
    assert g.glGetIntegerv(G.GL_STENCIL_WRITEMASK) == INT_MAX     # 0xFFFFFFFF clamps to GLint


# {====================================================================
# queries of float state saturate (fixed) or round and clamp (integer)


def test_get_clip_plane_x_saturates() -> None:
    g = ctx_of("float").gl
    g.glClipPlanef(G.GL_CLIP_PLANE0, [1e30, -1e30, 0.5, -2.5])
    # 0.5 * 2^16 = 32768; -2.5 * 2^16 = -163840
    assert g.glGetClipPlanex(G.GL_CLIP_PLANE0).tolist() == [INT_MAX, INT_MIN, 32768, -163840]


def test_get_material_and_light_x_saturate() -> None:
    g = ctx_of("float").gl
    g.glMaterialfv(G.GL_FRONT_AND_BACK, G.GL_DIFFUSE, [1e6, -1e6, 0.25, 1.0])
    assert g.glGetMaterialxv(G.GL_FRONT, G.GL_DIFFUSE).tolist() == [INT_MAX, INT_MIN, 16384, 65536]
    g.glLightfv(G.GL_LIGHT0, G.GL_POSITION, [1e30, 0.0, 0.0, 0.0])
    # the position is transformed by the identity modelview: still 1e30
    assert g.glGetLightxv(G.GL_LIGHT0, G.GL_POSITION).tolist()[0] == INT_MAX


def test_get_integer_and_fixed_of_large_float_state() -> None:
    g = ctx_of("float").gl
    g.glFogf(G.GL_FOG_END, 1e30)
    g.glFogf(G.GL_FOG_START, -1e30)
    assert g.glGetIntegerv(G.GL_FOG_END) == INT_MAX
    assert g.glGetFixedv(G.GL_FOG_END) == INT_MAX
    assert g.glGetIntegerv(G.GL_FOG_START) == INT_MIN
    assert g.glGetFixedv(G.GL_FOG_START) == INT_MIN
    g.glFogf(G.GL_FOG_END, 2.5)         # rounds to nearest: floor(2.5 + 0.5)
    assert g.glGetIntegerv(G.GL_FOG_END) == 3
    g.glFogf(G.GL_FOG_END, 2.4)
    assert g.glGetIntegerv(G.GL_FOG_END) == 2
    g.glLoadMatrixf([3e9, 0, 0, 0, 0, -3e9, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])
    mv_i = g.glGetIntegerv(G.GL_MODELVIEW_MATRIX).reshape(16)
    mv_x = g.glGetFixedv(G.GL_MODELVIEW_MATRIX).reshape(16)
    assert (mv_i[0], mv_i[5], mv_i[10]) == (INT_MAX, INT_MIN, 1)
    assert (mv_x[0], mv_x[5], mv_x[10]) == (INT_MAX, INT_MIN, 65536)


def test_queries_of_nan_state_give_zero() -> None:
    """NaN has no nearest integer; the fixed and integer queries answer 0."""
    g = ctx_of("float").gl
    g.glLoadMatrixf([float("nan")] + [0.0] * 15)
    assert np.isnan(g.glGetFloatv(G.GL_MODELVIEW_MATRIX)[0, 0])
    assert g.glGetIntegerv(G.GL_MODELVIEW_MATRIX)[0, 0] == 0
    assert g.glGetFixedv(G.GL_MODELVIEW_MATRIX)[0, 0] == 0


def test_buffer_data_huge_is_out_of_memory() -> None:
    ctx = ctx_of()
    g = ctx.gl
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 1)
    g.glBufferData(G.GL_ARRAY_BUFFER, 12, bytes(12), G.GL_DYNAMIC_DRAW)
    before = snapshot(ctx)
    g.glBufferData(G.GL_ARRAY_BUFFER, 2**40, None, G.GL_STATIC_DRAW)
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    assert same(before, snapshot(ctx))
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_SIZE) == 12
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_USAGE) == G.GL_DYNAMIC_DRAW


def test_gen_of_too_many_names_is_out_of_memory() -> None:
    """2^31 - 1 names would take 8 GiB to list: OUT_OF_MEMORY, none made."""
    g = ctx_of().gl
    assert g.glGenTextures(INT_MAX) is None
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    assert g.glGenBuffers(INT_MAX) is None
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    assert g.glGenTextures(1) == 1


# {====================================================================
# piglit's oes_compressed_paletted_texture-api rules, as piglit states them

# (internal format, bits per index (4 or 8), palette bytes)
PALETTED = [
    (G.GL_PALETTE4_RGB8_OES, 4, 3 * 16), (G.GL_PALETTE4_RGBA8_OES, 4, 4 * 16),
    (G.GL_PALETTE4_R5_G6_B5_OES, 4, 2 * 16), (G.GL_PALETTE4_RGBA4_OES, 4, 2 * 16),
    (G.GL_PALETTE4_RGB5_A1_OES, 4, 2 * 16), (G.GL_PALETTE8_RGB8_OES, 8, 3 * 256),
    (G.GL_PALETTE8_RGBA8_OES, 8, 4 * 256), (G.GL_PALETTE8_R5_G6_B5_OES, 8, 2 * 256),
    (G.GL_PALETTE8_RGBA4_OES, 8, 2 * 256), (G.GL_PALETTE8_RGB5_A1_OES, 8, 2 * 256),
]
DATA = bytes(4096)      # longer than any image below, so only the GL rules decide


@pytest.mark.parametrize("fmt,bits,palette", PALETTED)
def test_paletted_tex_image_2d_is_invalid_value(fmt: int, bits: int, palette: int) -> None:
    """ES 1.1 §3.7.1: a PALETTE* internalformat is not in Table 3.8, so
    TexImage2D gives INVALID_VALUE (the core rule before the extension's
    INVALID_OPERATION); piglit passes the palette token as format too."""
    ctx = ctx_of()
    before = snapshot(ctx)
    ctx.gl.glTexImage2D(G.GL_TEXTURE_2D, 0, fmt, 16, 16, 0, fmt, G.GL_UNSIGNED_BYTE, DATA)
    assert ctx.gl.glGetError() == G.GL_INVALID_VALUE
    assert same(before, snapshot(ctx))


@pytest.mark.parametrize("fmt,bits,palette", PALETTED)
def test_paletted_compressed_tex_image_2d_rules(fmt: int, bits: int, palette: int) -> None:
    g = ctx_of().gl
    indices = 16 * 16 * bits // 8
    # imageSize one short of the format's size: INVALID_VALUE
    g.glCompressedTexImage2D(G.GL_TEXTURE_2D, 0, fmt, 16, 16, 0, indices + palette - 1, DATA)
    assert g.glGetError() == G.GL_INVALID_VALUE
    # the exact size: no error
    g.glCompressedTexImage2D(G.GL_TEXTURE_2D, 0, fmt, 16, 16, 0, indices + palette, DATA)
    assert g.glGetError() == G.GL_NO_ERROR
    # a positive level: INVALID_VALUE
    g.glCompressedTexImage2D(G.GL_TEXTURE_2D, 1, fmt, 8, 8, 0, 8 * 8 * bits // 8 + palette, DATA)
    assert g.glGetError() == G.GL_INVALID_VALUE
    # a border: INVALID_VALUE (TexImage2D's rule, which piglit expects of ES)
    g.glCompressedTexImage2D(G.GL_TEXTURE_2D, 0, fmt, 16, 16, 1, 17 * 17 * bits // 8 + palette, DATA)
    assert g.glGetError() == G.GL_INVALID_VALUE


@pytest.mark.parametrize("level", [INT_MIN, -12, 1, INT_MAX])
def test_compressed_level_out_of_range(level: int) -> None:
    """A level below -(log2(MAX_TEXTURE_SIZE)) or above 0 is INVALID_VALUE
    (INT_MIN used to be negated in C, which overflows)."""
    ctx = ctx_of()
    before = snapshot(ctx)
    ctx.gl.glCompressedTexImage2D(G.GL_TEXTURE_2D, level, G.GL_PALETTE4_RGB8_OES, 4, 1, 0, 50, bytes(300))
    assert ctx.gl.glGetError() == G.GL_INVALID_VALUE
    assert same(before, snapshot(ctx))


def test_compressed_gl_rule_before_the_data_length() -> None:
    """imageSize against the format decides first (INVALID_VALUE); short data
    raises ValueError only for a GL-valid call, which would read past it."""
    g = ctx_of().gl
    need = 48 + 16 * 16 // 2          # PALETTE4_RGB8: 16 RGB entries, 4-bit indices
    g.glCompressedTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_PALETTE4_RGB8_OES, 16, 16, 0, need + 100, bytes(10))
    assert g.glGetError() == G.GL_INVALID_VALUE
    with pytest.raises(ValueError, match="CompressedTexImage2D"):
        g.glCompressedTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_PALETTE4_RGB8_OES, 16, 16, 0, need, bytes(10))
    assert g.glGetError() == G.GL_NO_ERROR


# {====================================================================
# the memory budget of textures and buffers


def test_default_memory_limit() -> None:
    assert ctx_of().memory_limit == 256 * 2**20


def test_memory_limit_textures_and_buffers_together() -> None:
    ctx = ctx_of(memory_limit=2**20)
    g = ctx.gl
    g.glBindTexture(G.GL_TEXTURE_2D, 1)
    # 512 x 512 texels of 4 bytes: exactly the budget
    g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 512, 512, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None)
    assert g.glGetError() == G.GL_NO_ERROR
    assert ctx.memory_used == 2**20
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 1)
    before = snapshot(ctx)
    g.glBufferData(G.GL_ARRAY_BUFFER, 1, b"x", G.GL_STATIC_DRAW)
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    assert same(before, snapshot(ctx))
    # replacing the image with a smaller one frees room
    g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 256, 512, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None)
    assert ctx.memory_used == 2**19
    g.glBufferData(G.GL_ARRAY_BUFFER, 2**19, None, G.GL_STATIC_DRAW)
    assert g.glGetError() == G.GL_NO_ERROR
    assert ctx.memory_used == 2**20
    # a larger image does not fit; the old one stays
    g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 512, 512, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None)
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    assert ctx.memory_used == 2**20
    g.glCopyTexImage2D(G.GL_TEXTURE_2D, 1, G.GL_RGBA, 0, 0, 16, 16, 0)
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    # deleting frees
    g.glDeleteTextures(1, [1])
    g.glDeleteBuffers(1, [1])
    assert ctx.memory_used == 0


def test_memory_limit_counts_generated_mipmaps() -> None:
    """512 x 512 with GENERATE_MIPMAP holds 4 * (512^2 + 256^2 + ... + 1) =
    1048576 + 349524 bytes; a budget one byte short refuses the image."""
    for limit, err in ((1048576 + 349524, G.GL_NO_ERROR), (1048576 + 349523, G.GL_OUT_OF_MEMORY)):
        ctx = ctx_of(memory_limit=limit)
        g = ctx.gl
        g.glTexParameteri(G.GL_TEXTURE_2D, G.GL_GENERATE_MIPMAP, 1)
        g.glTexImage2D(G.GL_TEXTURE_2D, 0, G.GL_RGBA, 512, 512, 0, G.GL_RGBA, G.GL_UNSIGNED_BYTE, None)
        assert g.glGetError() == err
        assert ctx.memory_used == (limit if err == G.GL_NO_ERROR else 0)


def test_memory_limit_paletted() -> None:
    """A paletted 16 x 16 image of 5 levels expands to 4 * (256 + 64 + 16 + 4 + 1) bytes."""
    need = 4 * (256 + 64 + 16 + 4 + 1)
    data = bytes(48 + (256 + 64 + 16 + 4 + 1 + 1) // 2 + 2)
    size = 48 + 128 + 32 + 8 + 2 + 1
    for limit, err in ((need, G.GL_NO_ERROR), (need - 1, G.GL_OUT_OF_MEMORY)):
        ctx = ctx_of(memory_limit=limit)
        ctx.gl.glCompressedTexImage2D(G.GL_TEXTURE_2D, -4, G.GL_PALETTE4_RGB8_OES, 16, 16, 0, size, data)
        assert ctx.gl.glGetError() == err
        assert ctx.memory_used == (need if err == G.GL_NO_ERROR else 0)


def test_memory_limit_setter_and_validation() -> None:
    ctx = ctx_of()
    g = ctx.gl
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 1)
    g.glBufferData(G.GL_ARRAY_BUFFER, 100, None, G.GL_STATIC_DRAW)
    ctx.memory_limit = 50           # below the use: only growth stops
    assert ctx.memory_limit == 50 and ctx.memory_used == 100
    g.glBufferData(G.GL_ARRAY_BUFFER, 101, None, G.GL_STATIC_DRAW)
    assert g.glGetError() == G.GL_OUT_OF_MEMORY
    g.glBufferData(G.GL_ARRAY_BUFFER, 40, None, G.GL_STATIC_DRAW)
    assert g.glGetError() == G.GL_NO_ERROR
    assert ctx.memory_used == 40
    with pytest.raises(ValueError, match="memory_limit"):
        ctx.memory_limit = -1
    with pytest.raises(TypeError, match="memory_limit"):
        gles.Context(4, 4, memory_limit=1.5)  # type: ignore[arg-type]


# {====================================================================
# 16.16 sums that need more than 64 bits (found under UBSan)


def test_fixed_matrix_products_of_extreme_entries() -> None:
    """Four products of 32-bit entries need 65 bits: the fixed build's matrix
    product and vertex transform sum them exactly and saturate (the sum used
    to overflow int64). Batched (0) and per-vertex (8) transforms agree."""
    images = []
    for flags in (0, 8):
        ctx = ctx_of("fixed", 16, 16)
        ctx.debug(flags)
        g = ctx.gl
        g.glLoadMatrixx([256664, -123369, 32768, 0, 1, 32768, -78494, -250749, 13107200, INT_MIN, INT_MAX,
                         13107200, 0, 222269, 119203, 117248])
        g.glTranslatex(INT_MIN, 65536, 6109)
        g.glMultMatrixx([13107200, -171321, INT_MAX, INT_MIN, INT_MIN, 167681, 143237, 118763, -1, 13107200,
                         -199916, 0, 130608, -138471, -1, 32768])
        g.glEnableClientState(G.GL_VERTEX_ARRAY)
        verts = np.array([INT_MAX, INT_MAX, INT_MAX, INT_MIN, 0, INT_MAX, 0, INT_MIN, INT_MIN, 65536, 0, 0],
                         dtype=np.int32)
        g.glVertexPointer(3, G.GL_FIXED, 0, verts)
        g.glDrawArrays(G.GL_TRIANGLE_STRIP, 0, 4)
        g.glDrawArrays(G.GL_POINTS, 0, 4)
        assert g.glGetError() == G.GL_NO_ERROR
        images.append(ctx.color_buffer())
    assert np.array_equal(images[0], images[1])



# {====================================================================
# the C ABI: NULL where a command reads or writes values

_NULL_SCRIPT = r"""
import sys
sys.path.insert(0, sys.argv[3])
import gen_cabi
from gles import cabi, constants as C
from gles.mesa import LibraryContext

numeric, profile = sys.argv[1], sys.argv[2]
ctx = LibraryContext(4, 4, str(cabi.library("EGL", numeric, profile)),
                     str(cabi.library("GLESv1_CM", numeric, profile)))
gl = ctx.gl
gl.glBindTexture(C.GL_TEXTURE_2D, 1)
gl.glBindBuffer(C.GL_ARRAY_BUFFER, 2)
gl.glBufferData(C.GL_ARRAY_BUFFER, 16, None, C.GL_STATIC_DRAW)
# a valid value for each scalar argument, so that only the pointer is wrong
PNAME = {"glGetBufferParameteriv": C.GL_BUFFER_SIZE, "glGetPointerv": C.GL_VERTEX_ARRAY_POINTER,
         "Fog": C.GL_FOG_COLOR, "LightModel": C.GL_LIGHT_MODEL_AMBIENT, "Light": C.GL_AMBIENT,
         "Material": C.GL_AMBIENT, "TexEnv": C.GL_TEXTURE_ENV_COLOR,
         "TexParameter": C.GL_TEXTURE_CROP_RECT_OES, "PointParameter": C.GL_POINT_DISTANCE_ATTENUATION}
SCALAR = {"n": 4, "light": C.GL_LIGHT0, "face": C.GL_FRONT, "plane": C.GL_CLIP_PLANE0, "p": C.GL_CLIP_PLANE0,
          "width": 2, "height": 2, "format": C.GL_RGBA, "type": C.GL_UNSIGNED_BYTE}


def value(name, param):
    if param == "pname":
        return next((v for k, v in PNAME.items() if k in name), C.GL_VIEWPORT)
    if param == "target":
        return C.GL_TEXTURE_ENV if "TexEnv" in name else (
            C.GL_ARRAY_BUFFER if "Buffer" in name else C.GL_TEXTURE_2D)
    return SCALAR.get(param, 0)


def state():
    return [bytes(gl.glReadPixels(0, 0, 4, 4, C.GL_RGBA, C.GL_UNSIGNED_BYTE))] + [
        gl.glGetFixedv(p).tobytes()
        for p in (C.GL_MODELVIEW_MATRIX, C.GL_FOG_COLOR, C.GL_LIGHT_MODEL_AMBIENT)]


before, calls = state(), 0
for name, (ret, args, params) in sorted(gen_cabi.prototypes().items()):
    fn = ctx._raw.get(name)
    types = args.split(",")
    checked = [p for p, t in zip(params, types) if "*" in t and p not in gen_cabi.null_ok(name)]
    if fn is None or not checked:
        continue
    fn(*[None if "*" in t else value(name, p) for p, t in zip(params, types)])
    err = gl.glGetError()
    assert err == 0, (name, hex(err))
    calls += 1
assert state() == before
print("ok", calls)
"""


@pytest.mark.parametrize("profile", ["common", "common-lite"])
def test_c_abi_null_pointers_do_nothing(profile: str) -> None:
    """A C caller's NULL for a pointer the command reads or writes (a query's
    output, a matrix, a parameter vector, glReadPixels' pixels, a names
    array) used to be dereferenced: glReadPixels(..., NULL) crashed. Every
    such entry point now does nothing (no error, no state change); NULL
    where GL gives it a meaning (data, pixels, array pointers, indices)
    still reaches the core. Run in a subprocess so a crash fails the test."""
    import subprocess
    import sys
    from pathlib import Path

    tools = str(Path(__file__).resolve().parent.parent / "tools")
    p = subprocess.run([sys.executable, "-c", _NULL_SCRIPT, "fixed", profile, tools],
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr[-2000:]
    calls = int(p.stdout.split()[-1])
    assert calls >= (50 if profile == "common" else 33)


_OVERREAD_SCRIPT = r"""
import ctypes, mmap, sys
from gles import cabi, constants as C
from gles.mesa import LibraryContext

profile = sys.argv[1]
ctx = LibraryContext(4, 4, str(cabi.library("EGL", "fixed", profile)),
                     str(cabi.library("GLESv1_CM", "fixed", profile)))
gl = ctx.gl
# one value just before an inaccessible page: reading a second one faults
page = mmap.PAGESIZE
libc = ctypes.CDLL(None)
libc.mmap.restype = ctypes.c_void_p
libc.mmap.argtypes = [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int, ctypes.c_int, ctypes.c_int,
                      ctypes.c_long]
libc.mprotect.argtypes = [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int]
base = libc.mmap(None, 2 * page, mmap.PROT_READ | mmap.PROT_WRITE,
                 mmap.MAP_PRIVATE | mmap.MAP_ANONYMOUS, -1, 0)
assert libc.mprotect(base + page, page, 0) == 0   # PROT_NONE
last = base + page - 4
gl.glBindTexture(C.GL_TEXTURE_2D, 1)
# (command, a pname with more values for another command, its target or light if any)
cases = [("Fog", C.GL_AMBIENT, ()), ("LightModel", C.GL_FOG_COLOR, ()),
         ("Light", C.GL_EMISSION, (C.GL_LIGHT0,)), ("Material", C.GL_POSITION, (C.GL_FRONT,)),
         ("Material", C.GL_SPOT_DIRECTION, (C.GL_FRONT,)), ("PointParameter", C.GL_SPOT_DIRECTION, ()),
         ("TexEnv", C.GL_TEXTURE_CROP_RECT_OES, (C.GL_TEXTURE_ENV,)),
         ("TexParameter", C.GL_TEXTURE_ENV_COLOR, (C.GL_TEXTURE_2D,))]
calls = 0
for stem, pname, first in cases:
    for suffix in ("xv", "fv", "iv"):
        fn = ctx._raw.get("gl" + stem + suffix)
        if fn is None:
            continue
        fn(*first, pname, last)
        assert gl.glGetError() == C.GL_INVALID_ENUM, (stem + suffix, hex(pname))
        calls += 1
print("ok", calls)
"""


@pytest.mark.parametrize("profile", ["common", "common-lite"])
def test_c_abi_vector_commands_read_what_the_command_takes(profile: str) -> None:
    """glFogxv(GL_AMBIENT, params) read four values (AMBIENT takes four, for
    lights) before the core refused the enum: a C caller's one value was
    over-read. Each vector command now reads the count of a pname it
    accepts, else one; here the value sits before an inaccessible page, so
    a second read faults. Run in a subprocess so a crash fails the test."""
    import subprocess
    import sys

    p = subprocess.run([sys.executable, "-c", _OVERREAD_SCRIPT, profile],
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr[-2000:]
    assert int(p.stdout.split()[-1]) == (18 if profile == "common" else 10)
