"""OES_compressed_ETC1_RGB8_texture, EXT_texture_format_BGRA8888,
OES_element_index_uint, EXT_blend_minmax, APPLE_texture_max_level and
EXT_read_format_bgra.

Expected texels come from the extension specs evaluated in numpy (the
conformance suite's ETC1 decoder, written from the spec's tables; byte
swaps), from the same
image uploaded the core's way (RGBA bytes, ushort indices), and from Mesa
(llvmpipe) where it runs. Textures are drawn 1:1 with NEAREST and REPLACE,
so a window pixel is a texel exactly.
"""

from __future__ import annotations

import numpy as np
import pytest

import gles
from conformance.categories.texture import etc1_decode as etc1_reference
from conformance.categories.texture import etc1_random as random_etc1
from gles import constants as C
from gles import mesa

_MESA = mesa.available()
needs_mesa = pytest.mark.skipif(_MESA is not None, reason=f"Mesa peer unavailable: {_MESA}")

# {================================================================
# drawing a texture 1:1

def _context(w: int, h: int, peer: bool = False):
    return mesa.MesaContext(w, h) if peer else gles.Context(w, h)


def draw_texture_1to1(gl, w: int, h: int) -> None:
    """The bound texture over the w x h window, texel (i, j) on pixel (i, j)."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0, w, 0, h, -1, 1)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    v = np.array([0, 0, w, 0, 0, h, w, h], np.float32)
    t = np.array([0, 0, 1, 0, 0, 1, 1, 1], np.float32)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, t)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


def read(gl, w: int, h: int) -> np.ndarray:
    """(h, w, 4) uint8, row 0 the bottom row (the texture's first row)."""
    return np.asarray(gl.glReadPixels(0, 0, w, h, C.GL_RGBA, C.GL_UNSIGNED_BYTE))


def render_etc1(data: bytes, w: int, h: int, peer: bool = False) -> np.ndarray:
    with _context(w, h, peer) as ctx:
        gl = ctx.gl
        gl.glBindTexture(C.GL_TEXTURE_2D, 1)
        gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, w, h, 0, len(data), data)
        assert gl.glGetError() == C.GL_NO_ERROR
        draw_texture_1to1(gl, w, h)
        return read(gl, w, h)


# {================================================================
# ETC1

def test_extensions_listed() -> None:
    for profile in ("common", "common-lite"):
        ext = gles.Context(2, 2, profile=profile).gl.glGetString(C.GL_EXTENSIONS).decode().split()
        for name in ("GL_OES_compressed_ETC1_RGB8_texture", "GL_EXT_texture_format_BGRA8888",
                     "GL_OES_element_index_uint", "GL_EXT_blend_minmax", "GL_APPLE_texture_max_level",
                     "GL_EXT_read_format_bgra"):
            assert name in ext


def test_etc1_reference_decodes_a_hand_block() -> None:
    # individual mode, no flip: left half colour 0x1 (17) per channel with
    # table 0, right half 0xF (255) with table 7; every index 0 ("00": +2 / +47)
    block = bytes([0x1F, 0x1F, 0x1F, (0 << 5) | (7 << 2), 0, 0, 0, 0])
    got = etc1_reference(block, 4, 4)
    assert (got[:, :2] == 19).all() and (got[:, 2:] == 255).all()
    # every index 3 ("11": the large negative): 17 - 8 = 9, 255 - 183 = 72
    block = bytes([0x1F, 0x1F, 0x1F, (0 << 5) | (7 << 2), 0xFF, 0xFF, 0xFF, 0xFF])
    got = etc1_reference(block, 4, 4)
    assert (got[:, :2] == 9).all() and (got[:, 2:] == 72).all()


@pytest.mark.parametrize("w,h", [(16, 16), (8, 4), (4, 8), (2, 2), (1, 1), (32, 2), (12, 8), (6, 10), (5, 3)])
def test_etc1_texels_are_the_specs(w: int, h: int) -> None:
    rng = np.random.default_rng(w * 100 + h)
    data = random_etc1(rng, w, h)
    got = render_etc1(data, w, h)
    want = etc1_reference(data, w, h)
    np.testing.assert_array_equal(got[..., :3], want)
    assert (got[..., 3] == 255).all()


def test_etc1_both_modes_and_flips_covered() -> None:
    # 64 blocks: every combination of diff and flip bits appears
    rng = np.random.default_rng(7)
    data = random_etc1(rng, 32, 32)
    modes = {(b[3] & 3) for b in (data[i:i + 8] for i in range(0, len(data), 8))}
    assert modes == {0, 1, 2, 3}
    np.testing.assert_array_equal(render_etc1(data, 32, 32)[..., :3], etc1_reference(data, 32, 32))


@needs_mesa
def test_etc1_matches_mesa() -> None:
    rng = np.random.default_rng(11)
    data = random_etc1(rng, 32, 16)
    np.testing.assert_array_equal(render_etc1(data, 32, 16), render_etc1(data, 32, 16, peer=True))


def test_etc1_errors_leave_the_texture() -> None:
    rng = np.random.default_rng(3)
    data = random_etc1(rng, 8, 8)
    ctx = gles.Context(8, 8)
    gl = ctx.gl
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, 8, 8, 0, len(data), data)
    assert gl.glGetError() == C.GL_NO_ERROR
    bad = [
        # imageSize not ceil(w/4) * ceil(h/4) * 8
        (lambda: gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, 8, 8, 0, 24, data),
         C.GL_INVALID_VALUE),
        # beyond MAX_TEXTURE_SIZE (any smaller size is legal: OES_texture_npot)
        (lambda: gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, 4096, 4, 0, 8192,
                                           data * 256),
         C.GL_INVALID_VALUE),
        # a negative level is the paletted formats' convention, not ETC1's
        (lambda: gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, -1, C.GL_ETC1_RGB8_OES, 8, 8, 0, 32, data),
         C.GL_INVALID_VALUE),
        # a border: the extension says INVALID_OPERATION (ES 1.1's general rule INVALID_VALUE)
        (lambda: gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, 8, 8, 1, 32, data),
         C.GL_INVALID_OPERATION),
        # ETC1 textures take no sub-images, compressed or not, nor copies
        (lambda: gl.glCompressedTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 4, 4, C.GL_ETC1_RGB8_OES, 8,
                                              data[:8]),
         C.GL_INVALID_OPERATION),
        (lambda: gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 1, 1, C.GL_RGB, C.GL_UNSIGNED_BYTE,
                                    np.zeros(3, np.uint8)), C.GL_INVALID_OPERATION),
        (lambda: gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2), C.GL_INVALID_OPERATION),
        # ETC1 is no uncompressed format
        (lambda: gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, 1, 1, 0, C.GL_RGB,
                                 C.GL_UNSIGNED_BYTE, np.zeros(3, np.uint8)), C.GL_INVALID_VALUE),
    ]
    for call, err in bad:
        call()
        assert gl.glGetError() == err
    draw_texture_1to1(gl, 8, 8)
    np.testing.assert_array_equal(read(gl, 8, 8)[..., :3], etc1_reference(data, 8, 8))
    with pytest.raises(ValueError):
        gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, 8, 8, 0, 32, data[:16])


def test_etc1_in_compressed_formats() -> None:
    gl = gles.Context(2, 2).gl
    formats = list(gl.glGetIntegerv(C.GL_COMPRESSED_TEXTURE_FORMATS))
    assert gl.glGetIntegerv(C.GL_NUM_COMPRESSED_TEXTURE_FORMATS) == len(formats) == 11
    assert C.GL_ETC1_RGB8_OES in formats


def test_etc1_mipmaps_complete_only_as_etc1() -> None:
    """A chain of ETC1 levels samples its smallest level; one RGB level in
    it makes the texture incomplete (texturing off: the fragment colour)."""
    rng = np.random.default_rng(5)
    ctx = gles.Context(1, 1)
    gl = ctx.gl
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    levels = [random_etc1(rng, s, s) for s in (4, 2, 1)]
    for level, (s, data) in enumerate(zip((4, 2, 1), levels)):
        gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, level, C.GL_ETC1_RGB8_OES, s, s, 0, len(data), data)
    draw_texture_1to1(gl, 1, 1)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    # a 1x1 window over the 4x4 texture: minified by 4, level 2 (1x1)
    gl.glColor4ub(1, 2, 3, 4)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    np.testing.assert_array_equal(read(gl, 1, 1)[0, 0, :3], etc1_reference(levels[2], 1, 1)[0, 0])
    gl.glTexImage2D(C.GL_TEXTURE_2D, 1, C.GL_RGB, 2, 2, 0, C.GL_RGB, C.GL_UNSIGNED_BYTE,
                    np.zeros(16, np.uint8))
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    assert list(read(gl, 1, 1)[0, 0]) == [1, 2, 3, 4]
    assert gl.glGetError() == C.GL_NO_ERROR


# {================================================================
# BGRA8888

def _bgra_image(w: int, h: int, seed: int) -> np.ndarray:
    return np.random.default_rng(seed).integers(0, 256, (h, w, 4), dtype=np.uint8)


def render_upload(w: int, h: int, fmt: int, pixels: np.ndarray, peer: bool = False) -> np.ndarray:
    with _context(w, h, peer) as ctx:
        gl = ctx.gl
        gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
        gl.glBindTexture(C.GL_TEXTURE_2D, 1)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, w, h, 0, fmt, C.GL_UNSIGNED_BYTE, pixels)
        assert gl.glGetError() == C.GL_NO_ERROR
        draw_texture_1to1(gl, w, h)
        return read(gl, w, h)


def test_bgra_is_rgba_with_the_bytes_swapped() -> None:
    bgra = _bgra_image(16, 8, 1)
    rgba = bgra[..., [2, 1, 0, 3]]
    got = render_upload(16, 8, C.GL_BGRA_EXT, bgra)
    np.testing.assert_array_equal(got, rgba)
    np.testing.assert_array_equal(got, render_upload(16, 8, C.GL_RGBA, np.ascontiguousarray(rgba)))


@needs_mesa
def test_bgra_matches_mesa() -> None:
    bgra = _bgra_image(16, 16, 2)
    np.testing.assert_array_equal(render_upload(16, 16, C.GL_BGRA_EXT, bgra),
                                  render_upload(16, 16, C.GL_BGRA_EXT, bgra, peer=True))


def test_bgra_sub_image_and_errors() -> None:
    bgra = _bgra_image(4, 4, 3)
    ctx = gles.Context(4, 4)
    gl = ctx.gl
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_BGRA_EXT, 4, 4, 0, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE, bgra)
    patch = np.array([[[9, 8, 7, 6]]], np.uint8)
    gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 1, 2, 1, 1, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE, patch)
    assert gl.glGetError() == C.GL_NO_ERROR
    bad = [
        # the level is BGRA: an RGBA sub-image does not match it
        (lambda: gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 1, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                                    np.zeros(4, np.uint8)), C.GL_INVALID_OPERATION),
        # internalformat and format must agree (ES 1.1)
        (lambda: gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 4, 4, 0, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE,
                                 bgra),
         C.GL_INVALID_OPERATION),
        # BGRA is unsigned bytes only
        (lambda: gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_BGRA_EXT, 4, 4, 0, C.GL_BGRA_EXT,
                                 C.GL_UNSIGNED_SHORT_4_4_4_4, bgra), C.GL_INVALID_OPERATION),
        # the extension adds no BGRA copy
        (lambda: gl.glCopyTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_BGRA_EXT, 0, 0, 2, 2, 0), C.GL_INVALID_VALUE),
    ]
    for call, err in bad:
        call()
        assert gl.glGetError() == err
    draw_texture_1to1(gl, 4, 4)
    want = bgra[..., [2, 1, 0, 3]].copy()
    want[2, 1] = [7, 8, 9, 6]
    np.testing.assert_array_equal(read(gl, 4, 4), want)


def test_bgra_copy_sub_image_into_a_bgra_level() -> None:
    """CopyTexSubImage2D into a BGRA level copies the framebuffer's RGBA as RGBA texels."""
    ctx = gles.Context(4, 4)
    gl = ctx.gl
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_BGRA_EXT, 4, 4, 0, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE,
                    np.zeros((4, 4, 4), np.uint8))
    gl.glClearColorx(65536, 0, 0, 65536)          # red, exactly 255
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 0, 0, 4, 4)
    assert gl.glGetError() == C.GL_NO_ERROR
    gl.glClearColorx(0, 0, 0, 0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    draw_texture_1to1(gl, 4, 4)
    assert (read(gl, 4, 4) == [255, 0, 0, 255]).all()


def test_bgra_and_rgba_levels_do_not_mix() -> None:
    ctx = gles.Context(1, 1)
    gl = ctx.gl
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_BGRA_EXT, 2, 2, 0, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE,
                    np.full((2, 2, 4), 200, np.uint8))
    gl.glTexImage2D(C.GL_TEXTURE_2D, 1, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                    np.full(4, 100, np.uint8))
    draw_texture_1to1(gl, 1, 1)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    gl.glColor4ub(1, 2, 3, 4)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    assert list(read(gl, 1, 1)[0, 0]) == [1, 2, 3, 4]      # incomplete: texturing off
    gl.glTexImage2D(C.GL_TEXTURE_2D, 1, C.GL_BGRA_EXT, 1, 1, 0, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE,
                    np.array([10, 20, 30, 40], np.uint8))
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    assert list(read(gl, 1, 1)[0, 0]) == [30, 20, 10, 40]


def test_bgra_generate_mipmap_keeps_the_format() -> None:
    ctx = gles.Context(1, 1)
    gl = ctx.gl
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, C.GL_TRUE)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_BGRA_EXT, 2, 2, 0, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE,
                    np.tile(np.array([10, 20, 30, 40], np.uint8), (2, 2, 1)))
    draw_texture_1to1(gl, 1, 1)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    assert list(read(gl, 1, 1)[0, 0]) == [30, 20, 10, 40]


# {================================================================
# 32-bit indices

def _strip_scene(gl, n: int, w: int, h: int) -> tuple[np.ndarray, np.ndarray]:
    """n vertices, all far outside the window but four: a quad at n - 4.. n - 1
    (indices past 65535 when n is large), per-vertex colours."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0, w, 0, h, -1, 1)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    verts = np.full((n, 2), -1000.0, np.float32)
    verts[n - 4:] = [[1, 1], [w - 2, 1], [1, h - 2], [w - 2, h - 2]]
    colors = np.zeros((n, 4), np.uint8)
    colors[n - 4:] = [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 255, 255]]
    gl.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    return verts, colors


@pytest.mark.parametrize("peer", [False, pytest.param(True, marks=needs_mesa)])
def test_uint_indices_past_65535(peer: bool) -> None:
    n = 70000
    with _context(16, 16, peer) as ctx:
        gl = ctx.gl
        keep = _strip_scene(gl, n, 16, 16)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, n - 4, 4)
        want = read(gl, 16, 16)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glDrawElements(C.GL_TRIANGLE_STRIP, 4, C.GL_UNSIGNED_INT, np.arange(n - 4, n, dtype=np.uint32))
        assert gl.glGetError() == C.GL_NO_ERROR
        got = read(gl, 16, 16)
        del keep
    assert (want[..., 3] == 255).sum() == 13 * 13      # centres 1.5 .. 13.5
    np.testing.assert_array_equal(got, want)


def test_uint_indices_as_ushort_and_from_a_buffer() -> None:
    ctx = gles.Context(16, 16)
    gl = ctx.gl
    keep = _strip_scene(gl, 8, 16, 16)
    idx = np.array([7, 5, 6, 4, 6, 5], np.uint32)[[1, 0, 2, 1, 3, 2]]    # two triangles
    gl.glDrawElements(C.GL_TRIANGLES, 6, C.GL_UNSIGNED_SHORT, idx.astype(np.uint16))
    want = read(gl, 16, 16)
    assert (want[..., 3] == 255).any()
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glDrawElements(C.GL_TRIANGLES, 6, C.GL_UNSIGNED_INT, idx)
    np.testing.assert_array_equal(read(gl, 16, 16), want)
    # the same indices from an element array buffer, at a byte offset
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    buf = gl.glGenBuffers(1)
    gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, buf)
    data = np.concatenate([np.array([123456], np.uint32), idx])
    gl.glBufferData(C.GL_ELEMENT_ARRAY_BUFFER, data.nbytes, data, C.GL_STATIC_DRAW)
    gl.glDrawElements(C.GL_TRIANGLES, 6, C.GL_UNSIGNED_INT, 4)
    assert gl.glGetError() == C.GL_NO_ERROR
    np.testing.assert_array_equal(read(gl, 16, 16), want)
    # past the buffer's end: refused before anything is read
    with pytest.raises(ValueError):
        gl.glDrawElements(C.GL_TRIANGLES, 7, C.GL_UNSIGNED_INT, 4)
    del keep


def test_uint_index_misuse() -> None:
    ctx = gles.Context(4, 4)
    gl = ctx.gl
    keep = _strip_scene(gl, 8, 4, 4)
    with pytest.raises(TypeError, match="uint32"):
        gl.glDrawElements(C.GL_TRIANGLES, 3, C.GL_UNSIGNED_INT, np.array([4, 5, 6], np.uint16))
    with pytest.raises(ValueError):
        gl.glDrawElements(C.GL_TRIANGLES, 6, C.GL_UNSIGNED_INT, np.array([4, 5, 6], np.uint32))
    # an index past the vertex arrays
    with pytest.raises(ValueError):
        gl.glDrawElements(C.GL_TRIANGLES, 3, C.GL_UNSIGNED_INT, np.array([4, 5, 2**32 - 1], np.uint32))
    # GL_INT is still no index type
    gl.glDrawElements(C.GL_TRIANGLES, 3, 0x1404, np.array([4, 5, 6], np.int32))     # GL_INT
    assert gl.glGetError() == C.GL_INVALID_ENUM
    del keep


# {================================================================
# EXT_blend_minmax

def _blend_minmax(eq_rgb: int, eq_alpha: int, textured: bool, color: str = "rgba8888",
                  peer: bool = False) -> np.ndarray:
    """Clear to DST, then an 8x8 quad of SRC (by colour or by a REPLACE
    texture) with the equations and factors that MIN and MAX must ignore."""
    make = (lambda: mesa.MesaContext(8, 8)) if peer else (lambda: gles.Context(8, 8, color=color))
    with make() as ctx:
        gl = ctx.gl
        gl.glClearColor(*(c / 255 for c in DST))
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(C.GL_ZERO, C.GL_ONE_MINUS_SRC_ALPHA)
        gl.glBlendEquationSeparateOES(eq_rgb, eq_alpha)
        assert gl.glGetError() == C.GL_NO_ERROR
        assert gl.glGetIntegerv(C.GL_BLEND_EQUATION_RGB_OES) == eq_rgb
        assert gl.glGetIntegerv(C.GL_BLEND_EQUATION_ALPHA_OES) == eq_alpha
        if textured:
            gl.glBindTexture(C.GL_TEXTURE_2D, 1)
            gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                            np.array(SRC, np.uint8))
            draw_texture_1to1(gl, 8, 8)
        else:
            gl.glColor4ub(*SRC)
            gl.glEnableClientState(C.GL_VERTEX_ARRAY)
            gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([-1, -1, 1, -1, -1, 1, 1, 1], np.float32))
            gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        return read(gl, 8, 8)


SRC = (120, 100, 250, 10)
DST = (100, 150, 200, 50)


@pytest.mark.parametrize("textured", [False, True])
def test_blend_min_max_take_the_colours(textured: bool) -> None:
    lo, hi = np.minimum(SRC, DST), np.maximum(SRC, DST)
    assert (_blend_minmax(C.GL_MIN_EXT, C.GL_MIN_EXT, textured) == lo).all()
    assert (_blend_minmax(C.GL_MAX_EXT, C.GL_MAX_EXT, textured) == hi).all()
    got = _blend_minmax(C.GL_MIN_EXT, C.GL_MAX_EXT, textured)
    assert (got[..., :3] == lo[:3]).all() and (got[..., 3] == hi[3]).all()
    # mixed with a factor equation: alpha by ZERO * src + (1 - As) * dst
    got = _blend_minmax(C.GL_MAX_EXT, C.GL_FUNC_ADD_OES, textured)
    assert (got[..., :3] == hi[:3]).all()
    assert (np.abs(got[..., 3].astype(int) - round(DST[3] * (1 - SRC[3] / 255))) <= 1).all()


@needs_mesa
@pytest.mark.parametrize("textured", [False, True])
def test_blend_min_max_match_mesa(textured: bool) -> None:
    for eqs in ((C.GL_MIN_EXT, C.GL_MIN_EXT), (C.GL_MAX_EXT, C.GL_MIN_EXT)):
        np.testing.assert_array_equal(_blend_minmax(*eqs, textured), _blend_minmax(*eqs, textured, peer=True))


def test_blend_min_max_rgb565() -> None:
    """On RGB565 the stored destination (5/6 bits, expanded) against the source."""
    got = _blend_minmax(C.GL_MAX_EXT, C.GL_MAX_EXT, False, color="rgb565")
    dst = [round(round(c * 31 / 255) * 255 / 31) for c in DST[::2]]
    assert abs(int(got[0, 0, 0]) - max(SRC[0], dst[0])) <= 8
    assert abs(int(got[0, 0, 2]) - max(SRC[2], dst[1])) <= 8


def test_blend_equation_errors_keep_the_state() -> None:
    gl = gles.Context(1, 1).gl
    gl.glBlendEquationOES(C.GL_MIN_EXT)
    gl.glBlendEquationOES(0x8009)          # BLEND_EQUATION_EXT itself is no equation
    assert gl.glGetError() == C.GL_INVALID_ENUM
    gl.glBlendEquationSeparateOES(C.GL_MAX_EXT, 0x8009)
    assert gl.glGetError() == C.GL_INVALID_ENUM
    assert gl.glGetIntegerv(C.GL_BLEND_EQUATION_RGB_OES) == C.GL_MIN_EXT
    assert gl.glGetIntegerv(C.GL_BLEND_EQUATION_ALPHA_OES) == C.GL_MIN_EXT


# {================================================================
# APPLE_texture_max_level

def _max_level_scene(limit: int | None, peer: bool = False) -> np.ndarray:
    """An 8x8 texture with levels 0 and 1 only (red, green), drawn on a 1x1
    window (lambda 3) with NEAREST_MIPMAP_NEAREST, vertex colour (1, 2, 3, 4)."""
    with _context(1, 1, peer) as ctx:
        gl = ctx.gl
        gl.glBindTexture(C.GL_TEXTURE_2D, 1)
        for level, (size, rgba) in enumerate(((8, (255, 0, 0, 255)), (4, (0, 255, 0, 255)))):
            gl.glTexImage2D(C.GL_TEXTURE_2D, level, C.GL_RGBA, size, size, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                            np.tile(np.array(rgba, np.uint8), (size, size, 1)))
        if limit is not None:
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_LEVEL_APPLE, limit)
        draw_texture_1to1(gl, 1, 1)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
        gl.glColor4ub(1, 2, 3, 4)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        assert gl.glGetError() == C.GL_NO_ERROR
        return read(gl, 1, 1)[0, 0]


@pytest.mark.parametrize("peer", [False, pytest.param(True, marks=needs_mesa)])
def test_max_level_completes_and_clamps(peer: bool) -> None:
    # levels 2 and 3 missing: incomplete, texturing off
    assert list(_max_level_scene(None, peer)) == [1, 2, 3, 4]
    # TEXTURE_MAX_LEVEL_APPLE 1: complete, and lambda 3 clamps to level 1
    assert list(_max_level_scene(1, peer)) == [0, 255, 0, 255]
    # 0: level 0 alone
    assert list(_max_level_scene(0, peer)) == [255, 0, 0, 255]


def test_max_level_state_and_errors() -> None:
    gl = gles.Context(1, 1).gl
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_LEVEL_APPLE) == 1000
    gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_LEVEL_APPLE, 2.0)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_LEVEL_APPLE, -1)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_LEVEL_APPLE) == 2
    # per texture object
    gl.glBindTexture(C.GL_TEXTURE_2D, 2)
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAX_LEVEL_APPLE) == 1000


# {================================================================
# EXT_read_format_bgra

def _painted(peer: bool = False, color: str = "rgba8888"):
    """A 6x4 window of seeded colours, one a pixel (points of size 1)."""
    ctx = mesa.MesaContext(6, 4) if peer else gles.Context(6, 4, color=color)
    gl = ctx.gl
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthof(0, 6, 0, 4, -1, 1)
    xy = np.array([(x + 0.5, y + 0.5) for y in range(4) for x in range(6)], np.float32)
    rgba = np.random.default_rng(9).integers(0, 256, (24, 4), dtype=np.uint8)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, xy)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, rgba)
    gl.glDrawArrays(C.GL_POINTS, 0, 24)
    return ctx, rgba.reshape(4, 6, 4)


@pytest.mark.parametrize("peer", [False, pytest.param(True, marks=needs_mesa)])
def test_read_bgra_is_the_rgba_read_swapped(peer: bool) -> None:
    ctx, rgba = _painted(peer)
    with ctx:
        gl = ctx.gl
        assert gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES) == C.GL_BGRA_EXT
        assert gl.glGetIntegerv(C.GL_IMPLEMENTATION_COLOR_READ_TYPE_OES) == C.GL_UNSIGNED_BYTE
        got = np.asarray(gl.glReadPixels(0, 0, 6, 4, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE))
        assert gl.glGetError() == C.GL_NO_ERROR
    np.testing.assert_array_equal(got, rgba[..., [2, 1, 0, 3]])


def test_read_bgra_into_a_buffer_and_errors() -> None:
    ctx, rgba = _painted()
    gl = ctx.gl
    gl.glPixelStorei(C.GL_PACK_ALIGNMENT, 8)
    out = np.full(8 * 2 * 2, 7, np.uint8)                   # 3-pixel rows padded to 16 bytes
    gl.glReadPixels(1, 1, 3, 2, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE, out)
    rows = out.reshape(2, 16)
    np.testing.assert_array_equal(rows[:, :12].reshape(2, 3, 4), rgba[1:3, 1:4][..., [2, 1, 0, 3]])
    # the REV types are the extension's tokens, not this window's pair
    for typ in (C.GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT, C.GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT):
        assert gl.glReadPixels(0, 0, 1, 1, C.GL_BGRA_EXT, typ) is None
        assert gl.glGetError() == C.GL_INVALID_OPERATION
    # an RGB565 window's pair stays RGB/5_6_5
    ctx565, _ = _painted(color="rgb565")
    assert ctx565.gl.glReadPixels(0, 0, 1, 1, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE) is None
    assert ctx565.gl.glGetError() == C.GL_INVALID_OPERATION


# {================================================================
# the content these extensions are for: ETC1 and NPOT BGRA textures drawn
# through 32-bit indices

def _psnr(a: np.ndarray, b: np.ndarray) -> float:
    """dB over RGB (inf when equal)."""
    mse = np.mean((a[..., :3].astype(np.float64) - b[..., :3].astype(np.float64)) ** 2)
    return float("inf") if mse == 0 else 10 * np.log10(255.0**2 / mse)


def _mobile_scene(make) -> np.ndarray:
    """A perspective grid of 12x12 cells from a 70000-vertex array (its
    vertices past 65535, by UNSIGNED_INT indices): unit 0 a 20x12 ETC1
    texture, LINEAR, REPEAT over 3 x 2 repeats; unit 1 a 13x7 BGRA texture,
    LINEAR_MIPMAP_LINEAR with GENERATE_MIPMAP, MODULATE; depth test; 96x96."""
    rng = np.random.default_rng(21)
    etc1 = random_etc1(rng, 20, 12)
    bgra = rng.integers(0, 256, (7, 13, 4), dtype=np.uint8)
    n, base = 13, 70000 - 169
    gx, gy = np.meshgrid(np.linspace(-1, 1, n), np.linspace(-1, 1, n))
    verts = np.zeros((70000, 3), np.float32)
    verts[base:] = np.stack([gx, gy, 0.15 * np.sin(3 * gx) * np.cos(2 * gy)], -1).reshape(-1, 3)
    uv0 = np.zeros((70000, 2), np.float32)
    uv0[base:] = np.stack([(gx + 1) * 1.5, (gy + 1)], -1).reshape(-1, 2)
    uv1 = np.zeros((70000, 2), np.float32)
    uv1[base:] = np.stack([(gx + 1) * 0.5, (gy + 1) * 0.5], -1).reshape(-1, 2)
    cell = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).reshape(-1)
    idx = (np.stack([cell, cell + 1, cell + n, cell + 1, cell + n + 1, cell + n], -1).reshape(-1) + base)
    with make() as ctx:
        gl = ctx.gl
        gl.glViewport(0, 0, 96, 96)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glFrustumf(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0)
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glTranslatef(0, 0, -2.2)
        gl.glRotatef(-55, 1, 0, 0)
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glClearColor(0.1, 0.2, 0.3, 1)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
        for unit in (0, 1):
            gl.glActiveTexture(C.GL_TEXTURE0 + unit)
            gl.glBindTexture(C.GL_TEXTURE_2D, unit + 1)
            gl.glEnable(C.GL_TEXTURE_2D)
        gl.glActiveTexture(C.GL_TEXTURE0)
        gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_ETC1_RGB8_OES, 20, 12, 0, len(etc1), etc1)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glActiveTexture(C.GL_TEXTURE1)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, C.GL_TRUE)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_BGRA_EXT, 13, 7, 0, C.GL_BGRA_EXT, C.GL_UNSIGNED_BYTE, bgra)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        for unit, uv in ((0, uv0), (1, uv1)):
            gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
            gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
            gl.glTexCoordPointer(2, C.GL_FLOAT, 0, uv)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_INT, idx.astype(np.uint32))
        assert gl.glGetError() == C.GL_NO_ERROR
        return np.asarray(gl.glReadPixels(0, 0, 96, 96, C.GL_RGBA, C.GL_UNSIGNED_BYTE))


@needs_mesa
def test_mobile_scene_near_llvmpipe_and_double() -> None:
    fixed = _mobile_scene(lambda: gles.Context(96, 96, numeric="fixed"))
    double = _mobile_scene(lambda: gles.Context(96, 96, numeric="double"))
    peer = _mobile_scene(lambda: mesa.MesaContext(96, 96))
    covered = (fixed[..., :3] != fixed[-1, 0, :3]).any(axis=-1).mean()   # the top-left pixel: clear colour
    assert 0.3 < covered < 0.9
    assert _psnr(fixed, peer) >= 35.0              # the bar against llvmpipe
    assert _psnr(fixed, double) >= 30.0            # test_gallery's MIN_PSNR_FIXED
