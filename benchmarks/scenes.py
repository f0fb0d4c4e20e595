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
