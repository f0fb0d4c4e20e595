"""Benchmark scenes: GL calls in the conventions gles and its Mesa peer share.

Each scene has ``setup(gl, w, h) -> state`` (arrays and fixed state, not
timed) and ``frame(gl, state)`` (one timed frame, without glFinish, which the
runner adds). ``min_coverage(w, h)`` is the fraction of pixels a correct
frame leaves different from the clear colour, at least; ``color`` is the
colour buffer format the runner asks both peers for ("rgba8888" or
"rgb565"). Every array and texture is made with numpy from fixed seeds, so a
scene draws the same frame every time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from gles import constants as C

CLEAR = (0.0, 0.0, 0.0, 1.0)


@dataclass(frozen=True)
class Scene:
    """One benchmark scene: untimed setup, one timed frame, the image check's threshold."""

    name: str
    description: str
    setup: Callable[[Any, int, int], Any]
    frame: Callable[[Any, Any], None]
    min_coverage: Callable[[int, int], float]
    color: str = "rgba8888"


def _ortho(gl: Any, w: int, h: int) -> None:
    """Object units = pixels, origin bottom-left."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0.0, float(w), 0.0, float(h), -1.0, 1.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def _perspective(gl: Any, w: int, h: int, near: float, far: float, half_height: float = 0.5) -> None:
    """A symmetric frustum of the window's aspect; the modelview left as identity."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    a = half_height * w / h
    gl.glFrustumf(-a, a, -half_height, half_height, near, far)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def _common(gl: Any) -> None:
    """The clear colour, no dithering or culling, a vertex array."""
    gl.glClearColor(*CLEAR)
    gl.glDisable(C.GL_DITHER)
    gl.glDisable(C.GL_CULL_FACE)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)


def _grid_indices(nx: int, ny: int) -> np.ndarray:
    """GL_TRIANGLES indices (uint16) of a grid of nx by ny vertices, row-major."""
    i, j = np.meshgrid(np.arange(ny - 1), np.arange(nx - 1), indexing="ij")
    a = (i * nx + j).reshape(-1)
    idx = np.stack([a, a + 1, a + nx, a + 1, a + nx + 1, a + nx], axis=-1)
    return np.ascontiguousarray(idx.reshape(-1), dtype=np.uint16)


def _quad(x0: float, y0: float, x1: float, y1: float, z: float | None = None) -> np.ndarray:
    """A GL_TRIANGLE_STRIP rectangle, 2 or 3 floats per vertex."""
    v = [[x0, y0], [x1, y0], [x0, y1], [x1, y1]]
    if z is not None:
        v = [p + [z] for p in v]
    return np.array(v, dtype=np.float32)


# {================================================================
# flat_overdraw: fill rate of constant-colour pixels

def flat_overdraw_setup(gl: Any, w: int, h: int) -> Any:
    """A full-screen quad and 20 seeded colours; no depth, flat shading."""
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_FLAT)
    quad = np.array([0, 0, w, 0, 0, h, w, h], dtype=np.float32)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, quad)
    rng = np.random.default_rng(1)
    colors = [tuple(int(c) for c in rng.integers(40, 256, size=3)) for _ in range(20)]
    return {"quad": quad, "colors": colors}


def flat_overdraw_frame(gl: Any, state: Any) -> None:
    """Clear, then the quad 20 times, one colour each."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for r, g, b in state["colors"]:
        gl.glColor4ub(r, g, b, 255)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


# {================================================================
# smooth_mesh: vertex throughput, smooth colour, depth test

GRID = 141                        # vertices per side: 2 * 140 * 140 = 39200 triangles


def smooth_mesh_setup(gl: Any, w: int, h: int) -> Any:
    """The wavy grid with ubyte colours under a perspective view, depth test LESS."""
    _common(gl)
    gl.glShadeModel(C.GL_SMOOTH)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glClearDepthf(1.0)
    u = np.linspace(-1.0, 1.0, GRID)
    x, y = np.meshgrid(u, u)
    z = 0.12 * np.sin(3.0 * x) * np.cos(4.0 * y)
    verts = np.stack([1.6 * x, 1.6 * y, z], axis=-1).astype(np.float32).reshape(-1, 3)
    colors = np.stack([(x + 1) * 127.5, (y + 1) * 127.5, (z / 0.12 + 1) * 127.5,
                       np.full_like(x, 255)], axis=-1).astype(np.uint8).reshape(-1, 4)
    i = np.arange(GRID - 1)
    a = (i[:, None] * GRID + i[None, :]).reshape(-1)          # lower-left corner of each cell
    idx = np.stack([a, a + 1, a + GRID, a + 1, a + GRID + 1, a + GRID], axis=-1)
    indices = np.ascontiguousarray(idx.reshape(-1), dtype=np.uint16)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    aspect = w / h
    gl.glFrustumf(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 10.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glTranslatef(0.0, 0.0, -2.0)
    gl.glRotatef(-25.0, 1.0, 0.0, 0.0)
    gl.glRotatef(10.0, 0.0, 0.0, 1.0)
    return {"verts": verts, "colors": colors, "indices": indices}


def smooth_mesh_frame(gl: Any, state: Any) -> None:
    """Clear colour and depth, one glDrawElements of the whole mesh."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)


# {================================================================
# small_draws: per-draw and per-matrix-change overhead

N_DRAWS = 2000


def small_draws_setup(gl: Any, w: int, h: int) -> Any:
    """An 8x8 quad and N_DRAWS seeded positions, angles and colours on a grid."""
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_FLAT)
    quad = np.array([-4, -4, 4, -4, -4, 4, 4, 4], dtype=np.float32)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, quad)
    rng = np.random.default_rng(2)
    cols = int(np.ceil(np.sqrt(N_DRAWS * w / h)))
    rows = int(np.ceil(N_DRAWS / cols))
    k = np.arange(N_DRAWS)
    xs = (k % cols + 0.5) * (w / cols)
    ys = (k // cols + 0.5) * (h / rows)
    draws = [(float(x), float(y), float(a), tuple(int(c) for c in col))
             for x, y, a, col in zip(xs, ys, rng.uniform(0, 90, N_DRAWS),
                                     rng.integers(40, 256, size=(N_DRAWS, 3)))]
    return {"quad": quad, "draws": draws}


def small_draws_frame(gl: Any, state: Any) -> None:
    """One Push/Translate/Rotate/Color/DrawArrays/Pop per quad."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for x, y, angle, (r, g, b) in state["draws"]:
        gl.glPushMatrix()
        gl.glTranslatef(x, y, 0.0)
        gl.glRotatef(angle, 0.0, 0.0, 1.0)
        gl.glColor4ub(r, g, b, 255)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        gl.glPopMatrix()


# {================================================================
# blended_quads: fill rate with SRC_ALPHA / ONE_MINUS_SRC_ALPHA

def blended_quads_setup(gl: Any, w: int, h: int) -> Any:
    """flat_overdraw with SRC_ALPHA, ONE_MINUS_SRC_ALPHA blending."""
    state = flat_overdraw_setup(gl, w, h)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    return state


def blended_quads_frame(gl: Any, state: Any) -> None:
    """Clear, then the 20 quads at alpha 96/255."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for r, g, b in state["colors"]:
        gl.glColor4ub(r, g, b, 96)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


def wireframe_setup(gl: Any, w: int, h: int) -> Any:
    """The smooth_mesh grid with line indices (two edges per cell plus the diagonal)."""
    state = smooth_mesh_setup(gl, w, h)
    i = np.arange(GRID - 1)
    a = (i[:, None] * GRID + i[None, :]).reshape(-1)          # lower-left corner of each cell
    edges = np.stack([a, a + 1, a, a + GRID, a + 1, a + GRID], axis=-1)
    state["indices"] = np.ascontiguousarray(edges.reshape(-1), dtype=np.uint16)
    return state


def wireframe_frame(gl: Any, state: Any) -> None:
    """Clear colour and depth, one glDrawElements(GL_LINES)."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_LINES, len(idx), C.GL_UNSIGNED_SHORT, idx)


# {================================================================
# texture helpers

def _texture_rgba(gl: Any, img: np.ndarray, min_filter: int, mag_filter: int,
                  *, levels: list[np.ndarray] | None = None, wrap: int = C.GL_REPEAT) -> int:
    """A texture object from uint8 RGBA (h, w, 4) on the active unit.

    ``levels`` are mipmap levels 1, 2, ... uploaded one by one after level 0.
    """
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    for level, im in enumerate([img, *(levels or [])]):
        h, w = im.shape[:2]
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, C.GL_RGBA, w, h, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                        np.ascontiguousarray(im, dtype=np.uint8))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, min_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, mag_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, wrap)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, wrap)
    return name


def _noise_texture(size: int, seed: int) -> np.ndarray:
    """A smooth-ish random RGBA image (sums of sines), alpha 255."""
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:size, 0:size] * (2 * np.pi / size)
    img = np.zeros((size, size, 4))
    for c in range(3):
        for _ in range(4):
            fx, fy = rng.integers(1, 9, size=2)
            img[..., c] += np.sin(fx * x + fy * y + rng.uniform(0, 6.3))
    img[..., :3] = (img[..., :3] - img[..., :3].min()) / np.ptp(img[..., :3]) * 255
    img[..., 3] = 255
    return img.astype(np.uint8)


def _blobs(size: int, seed: int, lo: float, hi: float) -> np.ndarray:
    """A periodic smooth field (sums of sines) scaled to [lo, hi], as float (size, size)."""
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:size, 0:size] * (2 * np.pi / size)
    f = np.zeros((size, size))
    for _ in range(5):
        fx, fy = rng.integers(1, 6, size=2)
        f += np.sin(fx * x + rng.uniform(0, 6.3)) * np.cos(fy * y + rng.uniform(0, 6.3))
    return lo + (f - f.min()) / np.ptp(f) * (hi - lo)


def _mip_chain(img: np.ndarray) -> list[np.ndarray]:
    """Levels 1.. down to 1x1 of a square power-of-two RGBA image, each a 2x2 box filter."""
    out = []
    cur = img.astype(np.float64)
    while cur.shape[0] > 1:
        cur = 0.25 * (cur[0::2, 0::2] + cur[1::2, 0::2] + cur[0::2, 1::2] + cur[1::2, 1::2])
        out.append(np.round(cur).astype(np.uint8))
    return out


def _ortho_modulated(gl: Any, w: int, h: int, shade: int, size: int, noise_seed: int, blob_seed: int,
                     alpha_lo: float) -> None:
    """Pixel units, no depth test, and a bilinear RGBA noise texture whose alpha is blobs
    from alpha_lo to 255, MODULATE by the vertex colour."""
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(shade)
    img = _noise_texture(size, noise_seed)
    img[..., 3] = np.round(_blobs(size, blob_seed, alpha_lo, 255)).astype(np.uint8)
    _texture_rgba(gl, img, C.GL_LINEAR, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)


# {================================================================
# textured_blend: bilinear texture fetch, MODULATE by vertex colours, SRC_ALPHA blending

N_BLEND_LAYERS = 8


def textured_blend_setup(gl: Any, w: int, h: int) -> Any:
    """A full-screen layer and 7 large rotated ones, 256x256 RGBA (alpha 96..255), smooth vertex colours."""
    _ortho_modulated(gl, w, h, C.GL_SMOOTH, 256, 3, 13, 96)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    rng = np.random.default_rng(4)
    verts, coords = [], []
    for k in range(N_BLEND_LAYERS):
        if k == 0:
            cx, cy, a, sx, sy = w / 2, h / 2, 0.0, w / 2, h / 2
        else:
            cx, cy = rng.uniform(0.3, 0.7) * w, rng.uniform(0.3, 0.7) * h
            a = rng.uniform(-0.4, 0.4)
            sx, sy = rng.uniform(0.3, 0.45) * w, rng.uniform(0.3, 0.45) * h
        ca, sa = math.cos(a), math.sin(a)
        corners = np.array([[-1, -1], [1, -1], [-1, 1], [1, 1]], dtype=np.float64) * [sx, sy]
        verts.append(np.stack([cx + ca * corners[:, 0] - sa * corners[:, 1],
                               cy + sa * corners[:, 0] + ca * corners[:, 1]], axis=-1))
        s0, t0 = rng.uniform(0, 1, size=2)
        k_mag = rng.uniform(0.35, 0.55)               # about 2x to 3x magnification
        coords.append([s0, t0] + (corners + [sx, sy]) * k_mag / 256)
    verts_a = np.ascontiguousarray(np.concatenate(verts), dtype=np.float32)
    coords_a = np.ascontiguousarray(np.concatenate(coords), dtype=np.float32)
    colors = np.concatenate([rng.integers(110, 256, (4 * N_BLEND_LAYERS, 3)),
                             rng.integers(150, 231, (4 * N_BLEND_LAYERS, 1))], axis=-1)
    colors[:4, 3] = 255                                   # the background layer is opaque
    colors_a = np.ascontiguousarray(colors, dtype=np.uint8)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, verts_a)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, coords_a)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors_a)
    return {"verts": verts_a, "coords": coords_a, "colors": colors_a}


def textured_blend_frame(gl: Any, state: Any) -> None:
    """Clear, then one glDrawArrays per layer, back to front."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for k in range(N_BLEND_LAYERS):
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 4 * k, 4)


# {================================================================
# trilinear_fog: perspective ground plane, LINEAR_MIPMAP_LINEAR, LINEAR fog, depth test

FOG_GRID = 17                 # vertices per side of the ground plane


def trilinear_fog_setup(gl: Any, w: int, h: int) -> Any:
    """A 16x16-cell ground plane to z = -300, a 256x256 mip chain uploaded level by level, fog 5..200."""
    _common(gl)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glClearDepthf(1.0)
    img = _noise_texture(256, 5)
    chk = ((np.indices((256, 256)) // 32).sum(axis=0) % 2).astype(bool)
    img[chk, :3] //= 2                      # a checker under the noise, so minification shows
    _texture_rgba(gl, img, C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR, levels=_mip_chain(img))
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glEnable(C.GL_FOG)
    gl.glFogf(C.GL_FOG_MODE, C.GL_LINEAR)
    gl.glFogf(C.GL_FOG_START, 5.0)
    gl.glFogf(C.GL_FOG_END, 200.0)
    gl.glFogfv(C.GL_FOG_COLOR, [0.55, 0.65, 0.8, 1.0])
    _perspective(gl, w, h, 1.0, 400.0)
    gl.glRotatef(8.0, 1.0, 0.0, 0.0)                  # looking slightly down
    gl.glTranslatef(0.0, -1.5, 0.0)
    gl.glRotatef(12.0, 0.0, 1.0, 0.0)
    # y = 0 from z = -1 to z = -300, 300 units wide: 150 repeats to the horizon
    xs = np.linspace(-150.0, 150.0, FOG_GRID)
    zs = np.linspace(-1.0, -300.0, FOG_GRID)
    x, z = np.meshgrid(xs, zs)
    verts = np.ascontiguousarray(np.stack([x, np.zeros_like(x), z], axis=-1).reshape(-1, 3), dtype=np.float32)
    tc = np.ascontiguousarray(np.stack([x / 2.0, -z / 2.0], axis=-1).reshape(-1, 2), dtype=np.float32)
    idx = _grid_indices(FOG_GRID, FOG_GRID)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    return {"verts": verts, "tc": tc, "indices": idx}


def trilinear_fog_frame(gl: Any, state: Any) -> None:
    """Clear colour and depth, one glDrawElements of the plane."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)


# {================================================================
# alpha_blend_logic: alpha test + additive blend in one pass, then an XOR logic-op pass

N_ADD_LAYERS = 6
N_XOR_QUADS = 3


def alpha_blend_logic_setup(gl: Any, w: int, h: int) -> Any:
    """A 128x128 texture, alpha blobs (about half above 0.5); full-screen additive layers; XOR quads."""
    _ortho_modulated(gl, w, h, C.GL_FLAT, 128, 8, 9, 0)
    gl.glAlphaFunc(C.GL_GREATER, 0.5)
    gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    gl.glLogicOp(C.GL_XOR)
    rng = np.random.default_rng(10)
    full = _quad(0, 0, w, h)
    layers = []
    for _ in range(N_ADD_LAYERS):
        s0, t0 = rng.uniform(0, 1, size=2)
        k = rng.uniform(0.6, 1.2)                     # 128 texels over 0.6..1.2 x 256 pixels
        tc = np.array([[s0, t0], [s0 + k * w / 256, t0], [s0, t0 + k * h / 256],
                       [s0 + k * w / 256, t0 + k * h / 256]], dtype=np.float32)
        layers.append((tc, tuple(int(c) for c in rng.integers(60, 140, size=3))))
    xor = []
    for _ in range(N_XOR_QUADS):
        x0, y0 = rng.uniform(0, 0.5) * w, rng.uniform(0, 0.5) * h
        q = _quad(x0, y0, x0 + 0.5 * w, y0 + 0.5 * h)
        tc = np.ascontiguousarray(q / 200.0, dtype=np.float32)
        xor.append((q, tc))
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    return {"full": full, "layers": layers, "xor": xor}


def alpha_blend_logic_frame(gl: Any, state: Any) -> None:
    """Pass 1: alpha test GREATER 0.5 + blend ONE, ONE; pass 2: COLOR_LOGIC_OP XOR."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glEnable(C.GL_ALPHA_TEST)
    gl.glEnable(C.GL_BLEND)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, state["full"])
    for tc, (r, g, b) in state["layers"]:
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        gl.glColor4ub(r, g, b, 255)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    gl.glDisable(C.GL_ALPHA_TEST)
    gl.glDisable(C.GL_BLEND)
    gl.glEnable(C.GL_COLOR_LOGIC_OP)
    gl.glColor4ub(255, 255, 255, 255)
    for q, tc in state["xor"]:
        gl.glVertexPointer(2, C.GL_FLOAT, 0, q)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    gl.glDisable(C.GL_COLOR_LOGIC_OP)


# {================================================================
# stencil_multipass: a stencil mask, then passes with StencilFunc EQUAL / NOTEQUAL and depth test

N_MASK_SHAPES = 12
MASK_SEGMENTS = 48


def stencil_multipass_setup(gl: Any, w: int, h: int) -> Any:
    """12 seeded ellipses (triangle fans) for the mask; two textures; quads at several depths."""
    _common(gl)
    _ortho(gl, w, h)
    gl.glShadeModel(C.GL_SMOOTH)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glClearDepthf(1.0)
    gl.glClearStencil(0)
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    tex_a = _texture_rgba(gl, _noise_texture(256, 11), C.GL_LINEAR, C.GL_LINEAR)
    tex_b = _texture_rgba(gl, _noise_texture(128, 12), C.GL_LINEAR, C.GL_LINEAR)
    rng = np.random.default_rng(14)
    ang = np.linspace(0.0, 2 * np.pi, MASK_SEGMENTS + 1)
    fans = []
    for _ in range(N_MASK_SHAPES):
        cx, cy = rng.uniform(0.1, 0.9) * w, rng.uniform(0.1, 0.9) * h
        rx, ry = rng.uniform(0.06, 0.2) * w, rng.uniform(0.06, 0.2) * h
        fan = np.concatenate([[[cx, cy]], np.stack([cx + rx * np.cos(ang), cy + ry * np.sin(ang)], -1)])
        fans.append(np.ascontiguousarray(fan, dtype=np.float32))
    # pass 1 (inside the mask): 4 textured full-screen layers at seeded depths, in seeded order
    layers = []
    for z in rng.uniform(-0.8, 0.8, size=4):
        q = _quad(0, 0, w, h, float(z))
        s0, t0 = rng.uniform(0, 1, size=2)
        tc = np.ascontiguousarray(q[:, :2] / 300.0 + [s0, t0], dtype=np.float32)
        layers.append((q, tc, tuple(int(c) for c in rng.integers(120, 256, size=3))))
    # pass 2 (outside the mask): a smooth-coloured quad behind everything
    back = _quad(0, 0, w, h, 0.9)
    back_colors = np.array([[40, 60, 200, 255], [200, 60, 40, 255], [40, 200, 60, 255],
                            [220, 220, 60, 255]], dtype=np.uint8)
    # pass 3 (inside the mask): a blended overlay in front, depth LEQUAL, no depth writes
    front = _quad(0, 0, w, h, -0.9)
    front_tc = np.ascontiguousarray(front[:, :2] / 128.0, dtype=np.float32)
    return {"fans": fans, "layers": layers, "back": back, "back_colors": back_colors,
            "front": front, "front_tc": front_tc, "tex": (tex_a, tex_b)}


def stencil_multipass_frame(gl: Any, state: Any) -> None:
    """Mask (stencil only), textured layers (EQUAL 1), colour (NOTEQUAL 1), blended overlay (EQUAL 1)."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    tex_a, tex_b = state["tex"]
    # the mask: stencil = 1 inside the ellipses, no colour or depth writes
    gl.glColorMask(0, 0, 0, 0)
    gl.glDepthMask(0)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glStencilFunc(C.GL_ALWAYS, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_REPLACE)
    for fan in state["fans"]:
        gl.glVertexPointer(2, C.GL_FLOAT, 0, fan)
        gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, len(fan))
    gl.glColorMask(1, 1, 1, 1)
    gl.glDepthMask(1)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
    # pass 1: inside, textured layers with depth test
    gl.glStencilFunc(C.GL_EQUAL, 1, 0xFF)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex_a)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    for q, tc, (r, g, b) in state["layers"]:
        gl.glVertexPointer(3, C.GL_FLOAT, 0, q)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        gl.glColor4ub(r, g, b, 255)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    # pass 2: outside, smooth colour
    gl.glStencilFunc(C.GL_NOTEQUAL, 1, 0xFF)
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, state["back"])
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, state["back_colors"])
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)
    # pass 3: inside, a blended textured overlay in front
    gl.glStencilFunc(C.GL_EQUAL, 1, 0xFF)
    gl.glDepthFunc(C.GL_LEQUAL)
    gl.glDepthMask(0)
    gl.glEnable(C.GL_BLEND)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex_b)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, state["front"])
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, state["front_tc"])
    gl.glColor4ub(255, 255, 255, 100)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    gl.glDisable(C.GL_BLEND)
    gl.glDepthMask(1)
    gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)


# {================================================================
# drawtex_blit: glDrawTexfOES / glDrawTexiOES with GL_TEXTURE_CROP_RECT_OES

N_BLITS = 300


def drawtex_blit_setup(gl: Any, w: int, h: int) -> Any:
    """A 256x256 atlas; N_BLITS seeded crop rectangles (32..128) drawn at 64..200 pixels, REPLACE."""
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    img = _noise_texture(256, 15)
    chk = ((np.indices((256, 256)) // 16).sum(axis=0) % 2).astype(bool)
    img[chk, :3] = img[chk, :3] // 2 + 100
    _texture_rgba(gl, img, C.GL_LINEAR, C.GL_LINEAR, wrap=C.GL_CLAMP_TO_EDGE)
    gl.glEnable(C.GL_TEXTURE_2D)
    # REPLACE: Mesa 22.3's DrawTex takes a stale current colour (see README), so no tint
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    rng = np.random.default_rng(16)
    blits = []
    for k in range(N_BLITS):
        cw, ch = (int(v) for v in rng.integers(32, 129, size=2))
        u, v = int(rng.integers(0, 257 - cw)), int(rng.integers(0, 257 - ch))
        dw, dh = (float(d) for d in rng.uniform(64, 200, size=2))
        x, y = float(rng.uniform(-dw / 2, w - dw / 2)), float(rng.uniform(-dh / 2, h - dh / 2))
        blits.append((k % 2 == 0, [u, v, cw, ch], x, y, dw, dh))
    return {"blits": blits}


def drawtex_blit_frame(gl: Any, state: Any) -> None:
    """Clear, then per blit: crop rect, glDrawTexfOES (even) or glDrawTexiOES (odd)."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for as_float, crop, x, y, dw, dh in state["blits"]:
        gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, crop)
        if as_float:
            gl.glDrawTexfOES(x, y, 0.0, dw, dh)
        else:
            gl.glDrawTexiOES(int(x), int(y), 0, int(dw), int(dh))


# {================================================================
# lit_mesh_lights: a 40000-triangle torus, three lights (directional, spot, point), COLOR_MATERIAL

TORUS_MAJOR, TORUS_MINOR = 200, 100       # segments around the ring and around the tube


def _torus(n_major: int, n_minor: int, big: float, small: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vertices, unit normals (float32) and GL_TRIANGLES indices (uint16, CCW outside) of a torus."""
    u = np.linspace(0.0, 2 * np.pi, n_major + 1)
    v = np.linspace(0.0, 2 * np.pi, n_minor + 1)
    uu, vv = np.meshgrid(u, v, indexing="ij")             # (n_major + 1, n_minor + 1)
    n = np.stack([np.cos(vv) * np.cos(uu), np.cos(vv) * np.sin(uu), np.sin(vv)], axis=-1)
    centre = np.stack([big * np.cos(uu), big * np.sin(uu), np.zeros_like(uu)], axis=-1)
    verts = centre + small * n
    idx = _grid_indices(n_minor + 1, n_major + 1).reshape(-1, 3)[:, ::-1]   # CCW seen from outside
    return (np.ascontiguousarray(verts.reshape(-1, 3), dtype=np.float32),
            np.ascontiguousarray(n.reshape(-1, 3), dtype=np.float32), np.ascontiguousarray(idx.reshape(-1)))


def lit_mesh_lights_setup(gl: Any, w: int, h: int) -> Any:
    """The torus in perspective, ubyte colours via COLOR_MATERIAL, specular, back faces culled."""
    _common(gl)
    gl.glShadeModel(C.GL_SMOOTH)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glClearDepthf(1.0)
    gl.glEnable(C.GL_CULL_FACE)
    gl.glCullFace(C.GL_BACK)
    verts, normals, idx = _torus(TORUS_MAJOR, TORUS_MINOR, 1.0, 0.42)
    uu, vv = np.meshgrid(np.linspace(0, 1, TORUS_MAJOR + 1), np.linspace(0, 1, TORUS_MINOR + 1),
                         indexing="ij")
    colors = np.stack([160 + 95 * np.cos(2 * np.pi * 6 * uu), 160 + 95 * np.sin(2 * np.pi * 3 * vv),
                       np.full_like(uu, 140), np.full_like(uu, 255)], axis=-1)
    colors = np.ascontiguousarray(np.clip(colors, 0, 255).reshape(-1, 4), dtype=np.uint8)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glNormalPointer(C.GL_FLOAT, 0, normals)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_COLOR_MATERIAL)
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [0.7, 0.7, 0.7, 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 24.0)
    gl.glLightModelfv(C.GL_LIGHT_MODEL_AMBIENT, [0.1, 0.1, 0.1, 1.0])
    _perspective(gl, w, h, 1.0, 10.0)
    # lights in eye coordinates (modelview identity)
    for light in (C.GL_LIGHT0, C.GL_LIGHT1, C.GL_LIGHT2):
        gl.glEnable(light)
    gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, [0.4, 0.8, 1.0, 0.0])               # directional
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.5, 0.5, 0.45, 1.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, [0.4, 0.4, 0.4, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, [-1.5, 1.0, -1.0, 1.0])             # spot, attenuated
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [0.4, 0.6, 1.0, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPECULAR, [1.0, 1.0, 1.0, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPOT_DIRECTION, [1.2, -0.8, -2.0])
    gl.glLightf(C.GL_LIGHT1, C.GL_SPOT_CUTOFF, 30.0)
    gl.glLightf(C.GL_LIGHT1, C.GL_SPOT_EXPONENT, 8.0)
    gl.glLightf(C.GL_LIGHT1, C.GL_CONSTANT_ATTENUATION, 0.8)
    gl.glLightf(C.GL_LIGHT1, C.GL_LINEAR_ATTENUATION, 0.15)
    gl.glLightf(C.GL_LIGHT1, C.GL_QUADRATIC_ATTENUATION, 0.05)
    gl.glLightfv(C.GL_LIGHT2, C.GL_POSITION, [1.5, -1.0, -2.0, 1.0])             # point, attenuated
    gl.glLightfv(C.GL_LIGHT2, C.GL_DIFFUSE, [0.8, 0.4, 0.2, 1.0])
    gl.glLightf(C.GL_LIGHT2, C.GL_QUADRATIC_ATTENUATION, 0.3)
    gl.glTranslatef(0.0, 0.0, -3.6)
    gl.glRotatef(-55.0, 1.0, 0.0, 0.0)
    gl.glRotatef(20.0, 0.0, 0.0, 1.0)
    return {"verts": verts, "normals": normals, "colors": colors, "indices": idx}


# {================================================================
# vertex_city: many medium draws, each its own modelview, lit, GL_NORMALIZE

CITY_COLS, CITY_ROWS = 25, 20
BUILDING_COLS, BUILDING_FLOORS = 4, 8      # side faces subdivided into columns x floors


def _building() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A unit box (x, z in [-0.5, 0.5], y in [0, 1]), subdivided walls and roof: verts, normals, indices."""
    verts, normals, idx = [], [], []

    def face(origin: np.ndarray, du: np.ndarray, dv: np.ndarray, nu: int, nv: int) -> None:
        base = sum(len(v) for v in verts)
        a, b = np.meshgrid(np.linspace(0, 1, nu + 1), np.linspace(0, 1, nv + 1))   # u varies fastest
        p = origin + a[..., None] * du + b[..., None] * dv
        verts.append(p.reshape(-1, 3))
        n = np.cross(du, dv)                                # outward; the grid's triangles are CCW about it
        normals.append(np.tile(n / np.linalg.norm(n), ((nu + 1) * (nv + 1), 1)))
        idx.append(_grid_indices(nu + 1, nv + 1).astype(np.int64) + base)

    x, y, z = np.eye(3)
    fc, fl = BUILDING_COLS, BUILDING_FLOORS
    face(np.array([-0.5, 0, 0.5]), x, y, fc, fl)           # +z wall
    face(np.array([0.5, 0, -0.5]), -x, y, fc, fl)          # -z wall
    face(np.array([0.5, 0, 0.5]), -z, y, fc, fl)           # +x wall
    face(np.array([-0.5, 0, -0.5]), z, y, fc, fl)          # -x wall
    face(np.array([-0.5, 1, 0.5]), x, -z, fc, fc)          # roof
    return (np.ascontiguousarray(np.concatenate(verts), dtype=np.float32),
            np.ascontiguousarray(np.concatenate(normals), dtype=np.float32),
            np.ascontiguousarray(np.concatenate(idx), dtype=np.uint16))


def vertex_city_setup(gl: Any, w: int, h: int) -> Any:
    """A 25x20 grid of buildings far from the camera, two directional lights, per-building scale, colour."""
    _common(gl)
    gl.glShadeModel(C.GL_SMOOTH)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glClearDepthf(1.0)
    gl.glEnable(C.GL_CULL_FACE)
    gl.glCullFace(C.GL_BACK)
    verts, normals, idx = _building()
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glNormalPointer(C.GL_FLOAT, 0, normals)
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_NORMALIZE)
    gl.glEnable(C.GL_LIGHT0)
    gl.glEnable(C.GL_LIGHT1)
    gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, [0.3, 1.0, 0.6, 0.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.8, 0.75, 0.7, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, [-0.7, 0.3, -0.4, 0.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [0.2, 0.3, 0.5, 1.0])
    _perspective(gl, w, h, 1.0, 300.0)
    gl.glTranslatef(0.0, -2.0, -80.0)
    gl.glRotatef(35.0, 1.0, 0.0, 0.0)
    gl.glRotatef(30.0, 0.0, 1.0, 0.0)
    rng = np.random.default_rng(17)
    buildings = []
    for i in range(CITY_ROWS):
        for j in range(CITY_COLS):
            x, z = (j - CITY_COLS / 2) * 1.6, (i - CITY_ROWS / 2) * 1.6
            sx, sz = (float(s) for s in rng.uniform(0.7, 1.3, size=2))
            sy = float(rng.uniform(0.8, 6.0))
            col = [float(c) for c in rng.uniform(0.3, 0.9, size=3)] + [1.0]
            buildings.append((float(x), float(z), sx, sy, sz, col))
    return {"verts": verts, "normals": normals, "indices": idx, "buildings": buildings}


def vertex_city_frame(gl: Any, state: Any) -> None:
    """Clear; per building Push/Translate/Scale/Material/DrawElements/Pop."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    idx = state["indices"]
    n = len(idx)
    for x, z, sx, sy, sz, col in state["buildings"]:
        gl.glPushMatrix()
        gl.glTranslatef(x, 0.0, z)
        gl.glScalef(sx, sy, sz)
        gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT_AND_DIFFUSE, col)
        gl.glDrawElements(C.GL_TRIANGLES, n, C.GL_UNSIGNED_SHORT, idx)
        gl.glPopMatrix()


# {================================================================
# combine_dot3: unit 0 COMBINE DOT3_RGB of a normal map with per-vertex light vectors (biased, in the
# primary colour), unit 1 MODULATE by a base texture

DOT3_GRID = 17


def combine_dot3_setup(gl: Any, w: int, h: int) -> Any:
    """Normal map on unit 0 (COMBINE DOT3_RGB with the primary colour), base texture on unit 1."""
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_SMOOTH)
    size = 128
    y, x = np.mgrid[0:size, 0:size] * (2 * np.pi / size)
    hx = 0.6 * np.cos(4 * x) * np.sin(3 * y)          # a bumpy height field's slopes
    hy = 0.6 * np.sin(4 * x) * np.cos(3 * y)
    n = np.stack([-hx, -hy, np.ones_like(hx)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    normal_map = np.concatenate([np.round((n * 0.5 + 0.5) * 255), np.full((size, size, 1), 255)], axis=-1)
    gl.glActiveTexture(C.GL_TEXTURE0)
    _texture_rgba(gl, normal_map.astype(np.uint8), C.GL_LINEAR, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, C.GL_DOT3_RGB)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_RGB, C.GL_TEXTURE)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND0_RGB, C.GL_SRC_COLOR)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC1_RGB, C.GL_PRIMARY_COLOR)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND1_RGB, C.GL_SRC_COLOR)
    gl.glActiveTexture(C.GL_TEXTURE1)
    _texture_rgba(gl, _noise_texture(128, 7), C.GL_LINEAR, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glActiveTexture(C.GL_TEXTURE0)
    # a grid over the window; the light vector from each vertex to a point light, biased into colour
    g = DOT3_GRID
    gx, gy = np.meshgrid(np.linspace(0, w, g), np.linspace(0, h, g))
    verts = np.stack([gx, gy], axis=-1).astype(np.float32).reshape(-1, 2)
    light = np.array([0.3 * w, 0.7 * h, 0.35 * max(w, h)])
    lv = np.stack([light[0] - gx, light[1] - gy, np.full_like(gx, light[2])], axis=-1)
    lv /= np.linalg.norm(lv, axis=-1, keepdims=True)
    colors = np.concatenate([np.round((lv * 0.5 + 0.5) * 255), np.full((g, g, 1), 255)], axis=-1)
    colors = np.ascontiguousarray(colors.reshape(-1, 4), dtype=np.uint8)
    tc0 = np.ascontiguousarray(verts / 128.0 * 1.5, dtype=np.float32)      # the bumps, tiled
    tc1 = np.ascontiguousarray(verts / 256.0, dtype=np.float32)
    i = np.arange(g - 1)
    a = (i[:, None] * g + i[None, :]).reshape(-1)
    idx = np.ascontiguousarray(np.stack([a, a + 1, a + g, a + 1, a + g + 1, a + g], -1).reshape(-1),
                               dtype=np.uint16)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    for unit, tc in ((0, tc0), (1, tc1)):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    gl.glClientActiveTexture(C.GL_TEXTURE0)
    return {"verts": verts, "colors": colors, "tc": (tc0, tc1), "indices": idx}


def combine_dot3_frame(gl: Any, state: Any) -> None:
    """Clear, one glDrawElements of the grid."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)


# {================================================================
# point_sprites: blended point sprites

N_SPRITES = 5000


def point_sprites_setup(gl: Any, w: int, h: int) -> Any:
    """Seeded positions, sizes (FLOAT size array) and colours; a radial 32x32 texture."""
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    rng = np.random.default_rng(5)
    verts = np.stack([rng.uniform(0, w, N_SPRITES),
                      rng.uniform(0, h, N_SPRITES)], axis=-1).astype(np.float32)
    sizes = rng.uniform(4.0, 24.0, N_SPRITES).astype(np.float32)
    colors = np.concatenate([rng.integers(64, 256, (N_SPRITES, 3)),
                             np.full((N_SPRITES, 1), 128)], axis=-1).astype(np.uint8)
    r = np.hypot(*np.meshgrid(np.linspace(-1, 1, 32), np.linspace(-1, 1, 32)))
    lum = (np.clip(1.0 - r, 0.0, 1.0) * 255).astype(np.uint8)
    img = np.ascontiguousarray(np.stack([lum, lum, lum, lum], axis=-1))
    tex = _texture_rgba(gl, img, C.GL_LINEAR, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glEnable(C.GL_POINT_SPRITE_OES)
    gl.glTexEnvi(C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES, 1)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glEnableClientState(C.GL_POINT_SIZE_ARRAY_OES)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glPointSizePointerOES(C.GL_FLOAT, 0, sizes)
    return {"verts": verts, "sizes": sizes, "colors": colors, "tex": tex}


def point_sprites_frame(gl: Any, state: Any) -> None:
    """Clear, one glDrawArrays(GL_POINTS) of every sprite."""
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glDrawArrays(C.GL_POINTS, 0, N_SPRITES)


# {================================================================
# the registry

def _full(w: int, h: int) -> float:
    return 0.99


SCENES: dict[str, Scene] = {s.name: s for s in (
    Scene("flat_overdraw", "20 full-screen flat-colour quads, no depth",
          flat_overdraw_setup, flat_overdraw_frame, _full),
    Scene("smooth_mesh", f"{2 * (GRID - 1) ** 2} smooth triangles (ubyte colours, "
          "DrawElements UNSIGNED_SHORT), depth test, perspective",
          smooth_mesh_setup, smooth_mesh_frame, lambda w, h: 0.8),
    Scene("small_draws", f"{N_DRAWS} 8x8 quads, one draw and one Push/Translate/Rotate/Pop each",
          small_draws_setup, small_draws_frame,
          lambda w, h: min(0.9, 0.5 * N_DRAWS * 64 / (w * h))),
    Scene("blended_quads", "20 full-screen quads blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA",
          blended_quads_setup, blended_quads_frame, _full),
    Scene("wireframe", f"the smooth_mesh grid as {3 * (GRID - 1) ** 2} GL_LINES (ubyte colours, "
          "DrawElements UNSIGNED_SHORT), depth test, perspective",
          wireframe_setup, wireframe_frame, lambda w, h: 0.2),
    Scene("textured_blend", f"{N_BLEND_LAYERS} large layers (one full-screen), 256x256 RGBA texture, "
          "bilinear, MODULATE by smooth vertex colours, blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA",
          textured_blend_setup, textured_blend_frame, _full),
    Scene("trilinear_fog", "a perspective ground plane to the horizon, 256x256 mip chain uploaded "
          "level by level, LINEAR_MIPMAP_LINEAR, 150 repeats, LINEAR fog, depth test",
          trilinear_fog_setup, trilinear_fog_frame, lambda w, h: 0.55),
    Scene("combine_dot3", f"a {DOT3_GRID}x{DOT3_GRID} full-screen grid, unit 0 COMBINE DOT3_RGB of a "
          "normal map and per-vertex light vectors, unit 1 MODULATE by a base texture, both bilinear",
          combine_dot3_setup, combine_dot3_frame, _full),
    Scene("alpha_blend_logic", f"{N_ADD_LAYERS} full-screen textured layers with alpha test GREATER 0.5 "
          f"and blend ONE, ONE, then {N_XOR_QUADS} quarter-screen textured quads with LOGIC_OP XOR",
          alpha_blend_logic_setup, alpha_blend_logic_frame, lambda w, h: 0.97),
    Scene("stencil_multipass", f"a stencil mask of {N_MASK_SHAPES} ellipses, then 4 textured depth-tested "
          "layers (EQUAL), a smooth quad (NOTEQUAL), a blended textured overlay (EQUAL)",
          stencil_multipass_setup, stencil_multipass_frame, _full),
    Scene("point_sprites", f"{N_SPRITES} point sprites (COORD_REPLACE, FLOAT size array 4..24, 32x32 "
          "bilinear texture, MODULATE), blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA",
          point_sprites_setup, point_sprites_frame, lambda w, h: 0.85),
    Scene("drawtex_blit", f"{N_BLITS} glDrawTexfOES/glDrawTexiOES blits of 64..200 px from 32..128 "
          "texel crop rectangles, bilinear, REPLACE",
          drawtex_blit_setup, drawtex_blit_frame, lambda w, h: 0.98),
    Scene("lit_mesh_lights", f"a {2 * TORUS_MAJOR * TORUS_MINOR}-triangle torus, directional + attenuated "
          "spot + attenuated point light, COLOR_MATERIAL, specular, one glDrawElements, back faces culled",
          lit_mesh_lights_setup, smooth_mesh_frame, lambda w, h: 0.25),
    Scene("vertex_city", f"{CITY_COLS * CITY_ROWS} buildings of 288 triangles, one glDrawElements and "
          "one Push/Translate/Scale/Material/Pop each, two lights, NORMALIZE, small on screen",
          vertex_city_setup, vertex_city_frame, lambda w, h: 0.08),
)}

# RGB565 targets: the same calls into a 16-bit colour buffer
for _base in ("textured_blend", "trilinear_fog"):
    _s = SCENES[_base]
    SCENES[f"{_base}_565"] = Scene(f"{_base}_565", f"{_base} into an RGB565 colour buffer",
                                   _s.setup, _s.frame, _s.min_coverage, color="rgb565")

# former names of scenes, still accepted by run.py's --scenes
ALIASES = {"textured_quads": "textured_blend", "ground_plane": "trilinear_fog", "dot3": "combine_dot3",
           "particles": "point_sprites", "lit_mesh": "lit_mesh_lights"}
