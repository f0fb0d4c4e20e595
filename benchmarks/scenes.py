"""Benchmark scenes: GL calls in the conventions gles and its Mesa peer share.

Each scene has ``setup(gl, w, h) -> state`` (arrays and fixed state, not
timed) and ``frame(gl, state)`` (one timed frame, without glFinish, which the
runner adds). ``min_coverage(w, h)`` is the fraction of pixels a correct
frame leaves different from the clear colour, at least.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from gles import constants as C

CLEAR = (0.0, 0.0, 0.0, 1.0)


@dataclass(frozen=True)
class Scene:
    name: str
    description: str
    setup: Callable[[Any, int, int], Any]
    frame: Callable[[Any, Any], None]
    min_coverage: Callable[[int, int], float]


def _ortho(gl: Any, w: int, h: int) -> None:
    """Object units = pixels, origin bottom-left."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0.0, float(w), 0.0, float(h), -1.0, 1.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def _common(gl: Any) -> None:
    gl.glClearColor(*CLEAR)
    gl.glDisable(C.GL_DITHER)
    gl.glDisable(C.GL_CULL_FACE)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)


# {================================================================
# flat_overdraw: fill rate of constant-colour pixels

def flat_overdraw_setup(gl: Any, w: int, h: int) -> Any:
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
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for r, g, b in state["colors"]:
        gl.glColor4ub(r, g, b, 255)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


# {================================================================
# smooth_mesh: vertex throughput, smooth colour, depth test

GRID = 141                        # vertices per side: 2 * 140 * 140 = 39200 triangles


def smooth_mesh_setup(gl: Any, w: int, h: int) -> Any:
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
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)


# {================================================================
# small_draws: per-draw and per-matrix-change overhead

N_DRAWS = 2000


def small_draws_setup(gl: Any, w: int, h: int) -> Any:
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
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for x, y, angle, (r, g, b) in state["draws"]:
        gl.glPushMatrix()
        gl.glTranslatef(x, y, 0.0)
        gl.glRotatef(angle, 0.0, 0.0, 1.0)
        gl.glColor4ub(r, g, b, 255)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        gl.glPopMatrix()


# {================================================================
# lit_mesh: the lighting stage, two lights (one a spot), specular

def _grid_normals(x: np.ndarray, y: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Unit normals of the height field z(x, y) from central differences."""
    dzdx = np.gradient(z, axis=1) / np.gradient(x, axis=1)
    dzdy = np.gradient(z, axis=0) / np.gradient(y, axis=0)
    n = np.stack([-dzdx, -dzdy, np.ones_like(z)], axis=-1)
    return (n / np.linalg.norm(n, axis=-1, keepdims=True)).astype(np.float32).reshape(-1, 3)


def lit_mesh_setup(gl: Any, w: int, h: int) -> Any:
    state = smooth_mesh_setup(gl, w, h)
    u = np.linspace(-1.0, 1.0, GRID)
    x, y = np.meshgrid(u, u)
    z = 0.12 * np.sin(3.0 * x) * np.cos(4.0 * y)
    normals = _grid_normals(1.6 * x, 1.6 * y, z)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glNormalPointer(C.GL_FLOAT, 0, normals)
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_LIGHT0)
    gl.glEnable(C.GL_LIGHT1)
    gl.glPushMatrix()
    gl.glLoadIdentity()
    gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, [0.5, 1.0, 1.0, 0.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.7, 0.7, 0.6, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, [-0.8, 0.6, 0.5, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [0.3, 0.5, 1.0, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPECULAR, [1.0, 1.0, 1.0, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPOT_DIRECTION, [0.6, -0.5, -2.0])
    gl.glLightf(C.GL_LIGHT1, C.GL_SPOT_CUTOFF, 35.0)
    gl.glLightf(C.GL_LIGHT1, C.GL_SPOT_EXPONENT, 10.0)
    gl.glLightf(C.GL_LIGHT1, C.GL_LINEAR_ATTENUATION, 0.3)
    gl.glPopMatrix()
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_DIFFUSE, [0.8, 0.6, 0.4, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [0.6, 0.6, 0.6, 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 32.0)
    state["normals"] = normals
    return state


# {================================================================
# blended_quads: fill rate with SRC_ALPHA / ONE_MINUS_SRC_ALPHA

def blended_quads_setup(gl: Any, w: int, h: int) -> Any:
    state = flat_overdraw_setup(gl, w, h)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    return state


def blended_quads_frame(gl: Any, state: Any) -> None:
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for r, g, b in state["colors"]:
        gl.glColor4ub(r, g, b, 96)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


SCENES = {s.name: s for s in (
    Scene("flat_overdraw", "20 full-screen flat-colour quads, no depth",
          flat_overdraw_setup, flat_overdraw_frame, lambda w, h: 0.99),
    Scene("smooth_mesh", f"{2 * (GRID - 1) ** 2} smooth triangles (ubyte colours, "
          "DrawElements UNSIGNED_SHORT), depth test, perspective",
          smooth_mesh_setup, smooth_mesh_frame, lambda w, h: 0.8),
    Scene("lit_mesh", "the smooth_mesh grid lit by a directional light and an attenuated "
          "spotlight with specular (shininess 32)",
          lit_mesh_setup, smooth_mesh_frame, lambda w, h: 0.8),
    Scene("blended_quads", "20 full-screen quads blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA",
          blended_quads_setup, blended_quads_frame, lambda w, h: 0.99),
    Scene("small_draws", f"{N_DRAWS} 8x8 quads, one draw and one Push/Translate/Rotate/Pop each",
          small_draws_setup, small_draws_frame,
          lambda w, h: min(0.9, 0.5 * N_DRAWS * 64 / (w * h))),
)}


# {================================================================
# texturing scenes

def _texture_rgba(gl: Any, img: np.ndarray, min_filter: int, mag_filter: int, *, mipmap: bool = False) -> int:
    """A texture object from uint8 RGBA (h, w, 4) on the active unit; GENERATE_MIPMAP when asked."""
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    if mipmap:
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    h, w = img.shape[:2]
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, w, h, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                    np.ascontiguousarray(img, dtype=np.uint8))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, min_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, mag_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, C.GL_REPEAT)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, C.GL_REPEAT)
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


# textured_quads: bilinear texture fetch + MODULATE + SRC_ALPHA blending, full screen

N_TEXTURED_QUADS = 10


def textured_quads_setup(gl: Any, w: int, h: int) -> Any:
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_FLAT)
    _texture_rgba(gl, _noise_texture(256, 3), C.GL_LINEAR, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    quad = np.array([0, 0, w, 0, 0, h, w, h], dtype=np.float32)
    # each quad shows the texture at its own offset and scale (magnified about 2x to 3x)
    rng = np.random.default_rng(4)
    coords = []
    for _ in range(N_TEXTURED_QUADS):
        s0, t0 = rng.uniform(0, 1, size=2)
        k = rng.uniform(0.35, 0.55)
        coords.append(np.array([s0, t0, s0 + k * w / 256, t0, s0, t0 + k * h / 256, s0 + k * w / 256,
                                t0 + k * h / 256], dtype=np.float32))
    gl.glVertexPointer(2, C.GL_FLOAT, 0, quad)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    colors = [tuple(int(c) for c in rng.integers(120, 256, size=3)) for _ in range(N_TEXTURED_QUADS)]
    return {"quad": quad, "coords": coords, "colors": colors}


def textured_quads_frame(gl: Any, state: Any) -> None:
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    for tc, (r, g, b) in zip(state["coords"], state["colors"]):
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        gl.glColor4ub(r, g, b, 110)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


# ground_plane: perspective, trilinear mipmaps (LINEAR_MIPMAP_LINEAR), many repeats, depth test

def ground_plane_setup(gl: Any, w: int, h: int) -> Any:
    _common(gl)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glClearDepthf(1.0)
    img = _noise_texture(256, 5)
    chk = ((np.indices((256, 256)) // 32).sum(axis=0) % 2).astype(bool)
    img[chk, :3] //= 2                      # a checker under the noise, so minification shows
    _texture_rgba(gl, img, C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR, mipmap=True)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    aspect = w / h
    gl.glFrustumf(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 400.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glTranslatef(0.0, -1.5, 0.0)
    gl.glRotatef(12.0, 0.0, 1.0, 0.0)
    # a 4x4-quad grid on y = 0 from z = -1 to z = -300, 300 units wide: 150 repeats to the horizon
    n = 5
    xs = np.linspace(-150.0, 150.0, n)
    zs = np.linspace(-1.0, -300.0, n)
    x, z = np.meshgrid(xs, zs)
    verts = np.stack([x, np.zeros_like(x), z], axis=-1).astype(np.float32).reshape(-1, 3)
    tc = np.stack([x / 2.0, -z / 2.0], axis=-1).astype(np.float32).reshape(-1, 2)
    i = np.arange(n - 1)
    a = (i[:, None] * n + i[None, :]).reshape(-1)
    idx = np.ascontiguousarray(np.stack([a, a + 1, a + n, a + 1, a + n + 1, a + n], -1).reshape(-1),
                               dtype=np.uint16)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    return {"verts": verts, "tc": tc, "indices": idx}


def ground_plane_frame(gl: Any, state: Any) -> None:
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)


# dot3: unit 0 COMBINE DOT3_RGB of a normal map with per-vertex light vectors (biased, in the
# primary colour), unit 1 MODULATE by a base texture

DOT3_GRID = 17


def dot3_setup(gl: Any, w: int, h: int) -> Any:
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


def dot3_frame(gl: Any, state: Any) -> None:
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)


SCENES.update({s.name: s for s in (
    Scene("textured_quads", f"{N_TEXTURED_QUADS} full-screen quads, 256x256 RGBA texture, bilinear (LINEAR), "
          "MODULATE, blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA",
          textured_quads_setup, textured_quads_frame, lambda w, h: 0.99),
    Scene("ground_plane", "a perspective ground plane to the horizon, 256x256 texture with generated "
          "mipmaps, LINEAR_MIPMAP_LINEAR, 150 repeats, depth test",
          ground_plane_setup, ground_plane_frame, lambda w, h: 0.45),
    Scene("dot3", f"a {DOT3_GRID}x{DOT3_GRID} full-screen grid, unit 0 COMBINE DOT3_RGB of a normal map and "
          "per-vertex light vectors, unit 1 MODULATE by a base texture, both bilinear",
          dot3_setup, dot3_frame, lambda w, h: 0.99),
)})


# {================================================================
# points and lines

N_PARTICLES = 5000


def particles_setup(gl: Any, w: int, h: int) -> Any:
    _common(gl)
    _ortho(gl, w, h)
    gl.glDisable(C.GL_DEPTH_TEST)
    rng = np.random.default_rng(5)
    verts = np.stack([rng.uniform(0, w, N_PARTICLES),
                      rng.uniform(0, h, N_PARTICLES)], axis=-1).astype(np.float32)
    sizes = rng.uniform(4.0, 24.0, N_PARTICLES).astype(np.float32)
    colors = np.concatenate([rng.integers(64, 256, (N_PARTICLES, 3)),
                             np.full((N_PARTICLES, 1), 128)], axis=-1).astype(np.uint8)
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


def particles_frame(gl: Any, state: Any) -> None:
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glDrawArrays(C.GL_POINTS, 0, N_PARTICLES)


def wireframe_setup(gl: Any, w: int, h: int) -> Any:
    state = smooth_mesh_setup(gl, w, h)
    i = np.arange(GRID - 1)
    a = (i[:, None] * GRID + i[None, :]).reshape(-1)          # lower-left corner of each cell
    edges = np.stack([a, a + 1, a, a + GRID, a + 1, a + GRID], axis=-1)
    state["indices"] = np.ascontiguousarray(edges.reshape(-1), dtype=np.uint16)
    return state


def wireframe_frame(gl: Any, state: Any) -> None:
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    idx = state["indices"]
    gl.glDrawElements(C.GL_LINES, len(idx), C.GL_UNSIGNED_SHORT, idx)


SCENES.update({s.name: s for s in (
    Scene("particles", f"{N_PARTICLES} point sprites (FLOAT size array 4..24, 32x32 bilinear texture, "
          "MODULATE), blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA",
          particles_setup, particles_frame, lambda w, h: 0.5),
    Scene("wireframe", f"the smooth_mesh grid as {3 * (GRID - 1) ** 2} GL_LINES (ubyte colours, "
          "DrawElements UNSIGNED_SHORT), depth test, perspective",
          wireframe_setup, wireframe_frame, lambda w, h: 0.2),
)})
