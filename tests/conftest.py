"""Shared helpers for the rendering tests.

The usual scene is 1:1: ``glViewport(0, 0, w, h)`` with the projection
``glOrthof(0, w, 0, h, -1, 1)`` and an identity modelview, so object x, y are
window pixels and pixel (i, j) has its centre at (i + 1/2, j + 1/2). With
power-of-two framebuffer sizes and vertex coordinates on the 1/256 grid
(the rasterizer's subpixel grid), every build computes the window positions
exactly, so expected coverage can be worked out from the input alone.
"""

from __future__ import annotations

import functools
import struct
import sys
import zlib
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import gles
from gles import constants as C

# the conformance package (its state tables are shared with the tests) lives
# beside tests/; make it importable however pytest was started
_ROOT = str(Path(__file__).resolve().parent.parent)
if _ROOT not in sys.path:
    sys.path.insert(0, _ROOT)

BUILDS = ("fixed", "float", "double")

# whether the span stages have a vector instance on this CPU (ctx.simd), so
# that the path tests also compare the baseline instance (ctx.debug(16))
HAS_SIMD = gles.Context(1, 1).simd != "baseline"

# the most pixels of a row the span chain takes through its stages at once
# (a chunk): tests draw rows wider than this so that they cross a chunk's end
SPAN_CHUNK = int(gles.Context(1, 1)._lib.gles_span_chunk())


def make_ctx(numeric: str, w: int = 64, h: int = 64, **kw: Any) -> gles.Context:
    """A context of the given build and size; keyword options go to gles.Context."""
    return gles.Context(w, h, numeric=numeric, **kw)


@functools.cache
def has_avx512(numeric: str) -> bool:
    """Whether the build's span stages run an AVX-512 instance on this CPU
    (then tests compare its AVX2 instance, ctx.debug(32), as well)."""
    return make_ctx(numeric, 1, 1).simd == "avx512"


@pytest.fixture(params=BUILDS)
def numeric(request: pytest.FixtureRequest) -> str:
    """Each numeric build in turn."""
    return request.param


def set_ortho(gl: Any, w: int, h: int, near: float = -1.0, far: float = 1.0) -> None:
    """Object units = window pixels, origin bottom-left; modelview identity."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0.0, float(w), 0.0, float(h), near, far)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def set_frustum(gl: Any, w: int, h: int, near: float = 1.0, far: float = 3.0) -> None:
    """glFrustumf(-1, 1, -1, 1, near, far) over the whole framebuffer; modelview identity.

    Eye x/(-z) in [-1, 1] maps to window x in [0, w] (and likewise for y).
    """
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumf(-1.0, 1.0, -1.0, 1.0, near, far)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def colour_window(numeric: str, flags: int, w: int, h: int, persp: bool,
                  seed: int) -> tuple[gles.Context, Any, np.random.Generator]:
    """A w x h colour-only context with debug `flags`, set_frustum's or set_ortho's
    projection, cleared to a colour drawn from rng(seed); returns ctx, gl and that rng."""
    ctx = make_ctx(numeric, w, h, depth=0, stencil=0)
    ctx.debug(flags)
    gl = ctx.gl
    (set_frustum if persp else set_ortho)(gl, w, h)
    rng = np.random.default_rng(seed)
    gl.glClearColor(*rng.uniform(0, 1, 4))
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    return ctx, gl, rng


def draw_arrays(gl: Any, verts: np.ndarray, colors: np.ndarray | None = None,
                mode: int = C.GL_TRIANGLES, indices: np.ndarray | None = None) -> None:
    """Draw float32 vertices (n, 2|3|4) with optional ubyte RGBA colours (n, 4)
    under whatever matrices are current."""
    v = np.ascontiguousarray(verts, dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(v.shape[1], C.GL_FLOAT, 0, v)
    if colors is not None:
        col = np.ascontiguousarray(colors, dtype=np.uint8)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, col)
    else:
        gl.glDisableClientState(C.GL_COLOR_ARRAY)
    if indices is None:
        gl.glDrawArrays(mode, 0, len(v))
    else:
        idx = np.ascontiguousarray(indices, dtype=np.uint16)
        gl.glDrawElements(mode, len(idx), C.GL_UNSIGNED_SHORT, idx)


def draw_tris(gl: Any, verts_xy_window: Any, colors: Any = None, mode: int = C.GL_TRIANGLES,
              indices: Any = None, w: int | None = None, h: int | None = None) -> None:
    """Draw triangles given in window pixels (x, y) or (x, y, z) under the 1:1 ortho setup.

    ``w``, ``h`` default to the framebuffer's size (taken from the GL
    object's context).
    """
    if w is None or h is None:
        w, h = gl.handle.width, gl.handle.height
    set_ortho(gl, w, h)
    draw_arrays(gl, np.asarray(verts_xy_window, dtype=np.float32),
                None if colors is None else np.asarray(colors, dtype=np.uint8), mode,
                None if indices is None else np.asarray(indices))


def read_rgba(ctx: gles.Context) -> np.ndarray:
    """The framebuffer as uint8 RGBA (h, w, 4), bottom row first (row index = window y)."""
    out = ctx.gl.glReadPixels(0, 0, ctx.width, ctx.height, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    assert out is not None
    return out


def clear(ctx: gles.Context, rgba: tuple = (0.0, 0.0, 0.0, 0.0), depth: float | None = None) -> None:
    """Clear colour (and depth when given) with every mask on."""
    gl = ctx.gl
    gl.glColorMask(True, True, True, True)
    gl.glClearColor(*rgba)
    mask = C.GL_COLOR_BUFFER_BIT
    if depth is not None:
        gl.glDepthMask(True)
        gl.glClearDepthf(depth)
        mask |= C.GL_DEPTH_BUFFER_BIT
    gl.glClear(mask)


def coverage(ctx: gles.Context) -> np.ndarray:
    """Boolean (h, w): pixels whose colour is not the cleared zero, bottom row first."""
    return read_rgba(ctx).any(axis=2)


def random_triangles(rng: np.random.Generator, persp: bool, n: int,
                     width: int) -> tuple[np.ndarray, np.ndarray]:
    """n overlapping random triangles: vertices (some outside the view volume,
    so clipping runs too, for a frustum in perspective or the 1:1 ortho of a
    window `width` wide) and ubyte colours, about a quarter of them one colour
    (the constant-colour span)."""
    tris, cols = [], []
    for _ in range(n):
        if persp:
            z = -rng.uniform(0.8, 3.3, size=3)
            xy = rng.uniform(-1.2, 1.2, size=(3, 2)) * -z[:, None]
            v = np.column_stack([xy, z])
        else:
            v = np.column_stack([rng.uniform(-6, width + 6, size=(3, 2)), rng.uniform(-1.2, 1.2, size=3)])
        c = rng.integers(0, 256, size=(3, 4))
        if rng.random() < 0.25:
            c[:] = c[0]
        tris.append(v)
        cols.append(c)
    return np.vstack(tris), np.vstack(cols).astype(np.uint8)


def decode_png(data: bytes) -> np.ndarray:
    """A minimal PNG reader (8-bit RGB/RGBA/grey, no interlace) written from the
    format's definition (chunks with CRCs, zlib, the five row filters): the
    independent check of what gles writes."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        assert crc == zlib.crc32(kind + body) & 0xFFFFFFFF, kind
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
        pos += 12 + length
    w, h, depth, color_type, _, _, interlace = header
    assert depth == 8 and interlace == 0
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[color_type]
    raw = zlib.decompress(idat)
    stride = w * channels
    out = np.zeros((h, stride), np.uint8)
    prev = np.zeros(stride, np.int32)
    for y in range(h):
        ftype = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, np.int32)
        for i in range(stride):
            a = cur[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if ftype == 0:
                pred = 0
            elif ftype == 1:
                pred = a
            elif ftype == 2:
                pred = b
            elif ftype == 3:
                pred = (a + b) // 2
            else:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[i] = (line[i] + pred) & 0xFF
        out[y] = cur
        prev = cur
    return out.reshape(h, w, channels)
