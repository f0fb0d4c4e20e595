"""Hard cases for 16.16 fixed point: twelve scenes where fixed-point arithmetic is stressed.

Each scene follows the protocol of :mod:`gles.compare`: ``scene(gl, w, h)``
issues OpenGL ES 1.1 Common-profile calls on ``gl`` (the command set of a
:class:`gles.Context` or of a :class:`gles.mesa.MesaContext`, which take the
same PyOpenGL-style calls), does its setup (textures, matrices, lights,
fog, the numpy arrays it draws, kept alive in the closure) and returns a
zero-argument ``frame()`` that draws one complete frame, starting with
``glClear``. A scene creates no context and never calls ``glFinish`` or
``glReadPixels``; it is deterministic (fixed seeds, procedural textures), so
a difference between two renderers is a difference of arithmetic. Every
scene is colourful, so that an error shows in the picture::

    from gles.compare import compare
    from gles.hardcases import HARD_CASES
    case = HARD_CASES["near_far_extreme"]
    print(compare(case.scene, 256, 256).table())

:data:`HARD_CASES` maps each name to a :class:`HardCase`: a title, the scene,
one sentence on what it stresses, and what the range checks of
:mod:`gles.profile` must report for the scene on the fixed build. Those three
flags are decided from the rules, not from what the code happens to do:

* per value, for the real arguments of the float commands: ``|x| >= 32768``
  overflows, a nonzero ``|x| <= 2^-17`` underflows (vertex, colour and
  texture-coordinate arrays are not checked per value);
* per draw: ``c*s + t >= 16384`` breaks the rule, with ``s`` and ``t`` taken
  from P*MV as the application built it (in double) and ``c`` the largest
  ``|component|`` of the vertices the draw reads.

The cases:

``vertices_near_limit``
    a height field with components up to +-32767 under a composite scale of
    1/32000 (an ortho of +-16000 after a modelview scale of 1/2); the rule
    holds (c*s + t = 2.02).
``rule_breaking_matrices``
    a rosette 0.0018 across at (30, 20), magnified by a modelview scale of
    1000 and a translation of (-30000, -20000), with wedges reaching out to
    components of 49.86: P*MV breaks the rule (c*s + t = 79864) yet the
    rosette lands on screen, every eye coordinate fits 16.16, and the wedges
    (20000 NDC long) are clipped to the window.
``near_far_extreme``
    glFrustumf with near 0.001 and far 1e5 (far overflows 16.16): pairs of
    crossing quads at eight depths from 0.002 to 300, a disc at 2000 in
    front of a wall at 8000, all depth tested.
``sliver_triangles``
    a sunburst of 720 slivers, a fan of nearly parallel slivers from an apex
    far off screen, and rows of sub-pixel-thin triangles across the window.
``crossing_w0``
    the inside of a tube around the camera, whose rings before and behind
    the eye give triangles crossing w = 0, clipped at the near plane.
``huge_triangles``
    half-planes drawn as triangles with vertices at +-15980 NDC (the rule
    holds: c*s + t = 15982), beside a perspective ground triangle 10000
    across and 8100 deep seen from 0.3 above it through a near plane at
    0.01 (c*s + t = 16000.02).
``texcoords_1000_repeat``
    the same patch of a 256x256 texture reached at s, t near 0, +1000 and
    -1000 with REPEAT, NEAREST and LINEAR.
``projective_q_to_0``
    a dual-paraboloid lookup: texcoords (rx, ry, rz, 1) and a texture
    matrix making q = 1 + rz, which reaches 0 at the back pole.
``shininess_spot_128``
    per-vertex lighting of a finely tessellated plane and sphere with
    shininess 128 and a spot exponent of 128.
``exp2_fog_dense``
    EXP2 fog with densities 5 to 50, each band fading from d z = 0 to 4
    across the window, and density 50 out to depth 900 (where (d z)^2 = 2e9
    exceeds 16.16 by far).
``additive_passes``
    64 additive passes (ONE, ONE) of a dim textured quad, each rounded to 8
    bits before the next adds to it.
``texture_scroll_1e5``
    a texture matrix built by 100000 glTranslatef(0.0013, 0.0007, 0), as an
    application that never reloads it would: 0.0013 is 85.197 units of
    2^-16 and 16.16 keeps 85, so the fixed build's scroll lags the exact one
    by 0.30 of a repeat in s (and leads by 0.19 in t, 45.875 kept as 46).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import constants as C

__all__ = ["HARD_CASES", "HardCase", "Frame", "Scene", "texture_scroll"]

Frame = Callable[[], None]
Scene = Callable[[Any, int, int], Frame]


@dataclass(frozen=True)
class HardCase:
    """One hard case: the scene and what the fixed build's range checks must report."""

    title: str
    scene: Scene
    stresses: str            # one sentence
    expect_overflow: bool    # some real argument has |x| >= 32768
    expect_underflow: bool   # some nonzero real argument has |x| <= 2^-17
    expect_rule: bool        # some draw has c*s + t >= 16384


# {====================================================================
# helpers shared by the scenes (the same calls on gles and on Mesa)

def _hsv(h: Any, s: Any = 1.0, v: Any = 1.0) -> np.ndarray:
    """HSV (each in [0, 1], broadcast) to RGB floats in [0, 1], shape (..., 3)."""
    h, s, v = np.broadcast_arrays(np.asarray(h, np.float64) % 1.0, np.asarray(s, np.float64),
                                  np.asarray(v, np.float64))
    k = (np.array([5.0, 3.0, 1.0]) + h[..., None] * 6.0) % 6.0
    return v[..., None] - v[..., None] * s[..., None] * np.clip(np.minimum(k, 4.0 - k), 0.0, 1.0)


def _rgba(rgb: Any, alpha: float = 1.0) -> np.ndarray:
    """Float RGB (..., 3) in [0, 1] to contiguous uint8 RGBA (..., 4)."""
    rgb = np.asarray(rgb, np.float64)
    a = np.full(rgb.shape[:-1] + (1,), alpha)
    return np.ascontiguousarray(np.rint(np.clip(np.concatenate([rgb, a], -1), 0, 1) * 255), np.uint8)


def _f32(a: Any) -> np.ndarray:
    return np.ascontiguousarray(a, dtype=np.float32)


def _aspect(w: int, h: int) -> float:
    return w / h


def _start(gl: Any, w: int, h: int) -> None:
    """The state every scene starts from: full viewport, identity matrices, no dither."""
    gl.glViewport(0, 0, w, h)
    gl.glDisable(C.GL_DITHER)
    for mode in (C.GL_TEXTURE, C.GL_PROJECTION, C.GL_MODELVIEW):
        gl.glMatrixMode(mode)
        gl.glLoadIdentity()


def _projection(gl: Any, kind: str, *args: float) -> None:
    """Load glOrthof/glFrustumf(*args) into the projection; back to the modelview."""
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    (gl.glOrthof if kind == "ortho" else gl.glFrustumf)(*args)
    gl.glMatrixMode(C.GL_MODELVIEW)


def _disc_fan(cx: float, cy: float, rx: float, ry: float, z: float, m: int,
              centre: list[float], rim: list[float]) -> tuple[np.ndarray, np.ndarray]:
    """A TRIANGLE_FAN ellipse at depth z: the centre then m + 1 rim points
    (the first repeated), coloured `centre` and `rim`."""
    t = np.arange(m + 1) * (2 * math.pi / m)
    verts = _f32(np.vstack([[cx, cy, z], np.stack([cx + rx * np.cos(t), cy + ry * np.sin(t),
                                                   np.full(m + 1, z)], -1)]))
    colors = _rgba(np.vstack([centre, np.tile(rim, (m + 1, 1))]))
    return verts, colors


def _draw(gl: Any, mode: int, verts: np.ndarray, colors: np.ndarray | None = None,
          texcoords: np.ndarray | None = None, normals: np.ndarray | None = None,
          count: int | None = None) -> None:
    """Point the client arrays at the data (as :func:`_arrays`) and draw the
    first `count` vertices (all of them by default) as `mode`."""
    _arrays(gl, verts, colors, texcoords, normals)
    gl.glDrawArrays(mode, 0, len(verts) if count is None else count)


def _arrays(gl: Any, verts: np.ndarray, colors: np.ndarray | None = None, texcoords: np.ndarray | None = None,
            normals: np.ndarray | None = None) -> None:
    """Point the client arrays at the given data (float32 positions, uint8 RGBA
    colours, float32 texcoords and normals) and disable the ones not given."""
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(verts.shape[1], C.GL_FLOAT, 0, verts)
    for arr, state in ((colors, C.GL_COLOR_ARRAY), (texcoords, C.GL_TEXTURE_COORD_ARRAY),
                       (normals, C.GL_NORMAL_ARRAY)):
        if arr is None:
            gl.glDisableClientState(state)
        else:
            gl.glEnableClientState(state)
    if colors is not None:
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    if texcoords is not None:
        gl.glTexCoordPointer(texcoords.shape[1], C.GL_FLOAT, 0, texcoords)
    if normals is not None:
        gl.glNormalPointer(C.GL_FLOAT, 0, normals)


def _texture(gl: Any, rgba: np.ndarray, min_filter: int = C.GL_NEAREST, mag_filter: int = C.GL_NEAREST,
             wrap: int = C.GL_REPEAT, mipmap: bool = False) -> int:
    """A new RGBA texture object from uint8 (h, w, 4) data (row 0 is t = 0)."""
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    if mipmap:
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, C.GL_TRUE)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    h, w = rgba.shape[:2]
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, w, h, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                    np.ascontiguousarray(rgba, np.uint8))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, min_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, mag_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, wrap)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, wrap)
    return name


def _grid_indices(nx: int, ny: int) -> np.ndarray:
    """Two triangles per cell of a grid of (ny + 1) rows of (nx + 1) vertices, row-major."""
    i, j = np.meshgrid(np.arange(nx), np.arange(ny))
    a = (j * (nx + 1) + i).reshape(-1)
    tri = np.stack([a, a + 1, a + nx + 2, a, a + nx + 2, a + nx + 1], -1)
    return np.ascontiguousarray(tri.reshape(-1), np.uint16)


def _quads_flat(corners: np.ndarray) -> np.ndarray:
    """Quads (n, 4, k) as unindexed triangles (6 n, k): 0 1 2, 0 2 3."""
    return np.ascontiguousarray(corners[:, [0, 1, 2, 0, 2, 3]].reshape(-1, corners.shape[-1]))


# {====================================================================
# 1. vertices near the limit

def vertices_near_limit(gl: Any, w: int, h: int, half_width: float = 16000.0) -> Frame:
    """A height field whose x, y reach +-32767 (z +-31000), and a checkered plane
    through it, brought on screen by a modelview scale of 1/2 and an ortho of
    +-`half_width` in x, y and z.

    With the default 16000 the composite scale is 1/32000 = 2.048 units of
    2^-16, which the fixed build holds as 2: its picture is the one this scene
    draws with ``half_width=16384`` in exact arithmetic (2.3% smaller)."""
    _start(gl, w, h)
    # 16.16 holds r - l only below 32768, so the world is halved in the modelview
    hw = float(half_width)
    _projection(gl, "ortho", -hw, hw, -hw, hw, -hw, hw)
    gl.glScalef(0.5, 0.5, 0.5)
    n = 40
    xs = np.linspace(-32767.0, 32767.0, n + 1)
    x, y = np.meshgrid(xs, xs)
    # |z| <= 31000: eye depths stay inside the ortho's +-16000 in every build (the fixed
    # build's near and far planes sit 2.3% further out), so nothing is clipped there
    z = 31000.0 * np.sin(x * (3.0 * math.pi / 65534.0) + 0.4) * np.cos(y * (2.0 * math.pi / 65534.0))
    field_v = _f32(np.stack([x, y, z], -1).reshape(-1, 3))
    field_c = _rgba(_hsv(0.72 * (1.0 - (z.reshape(-1) / 31000.0 + 1.0) / 2.0), 0.85, 1.0))
    field_i = _grid_indices(n, n)
    # a tilted plane of 10 x 10 checkered quads, z = 0.45 x - 0.3 y
    m = 10
    ps = np.linspace(-32000.0, 32000.0, m + 1)
    corners = []
    cols = []
    for j in range(m):
        for i in range(m):
            q = np.array([[ps[i], ps[j]], [ps[i + 1], ps[j]], [ps[i + 1], ps[j + 1]], [ps[i], ps[j + 1]]])
            corners.append(np.column_stack([q, 0.45 * q[:, 0] - 0.3 * q[:, 1]]))
            cols.append([250, 250, 250] if (i + j) % 2 else [20, 20, 30])
    plane_v = _f32(_quads_flat(np.array(corners)))
    plane_c = _rgba(np.repeat(np.array(cols, np.float64) / 255.0, 6, axis=0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glShadeModel(C.GL_SMOOTH)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClearDepthf(1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        _arrays(gl, field_v, field_c)
        gl.glDrawElements(C.GL_TRIANGLES, len(field_i), C.GL_UNSIGNED_SHORT, field_i)
        _draw(gl, C.GL_TRIANGLES, plane_v, plane_c)

    return frame


# {====================================================================
# 2. matrices that break the rule

def rule_breaking_matrices(gl: Any, w: int, h: int) -> Frame:
    """A rosette 0.0018 across at (30, 20) under glTranslatef(-30000, -20000, 0) and
    glScalef(1000, 1000, 1), with long wedges out to components of 49.86: P*MV
    has s = 1000 and t = 30000, so c*s + t = 79864; the rosette is on screen
    (NDC within +-0.9) and no eye coordinate leaves 16.16 (at most 30000)."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "ortho", -a, a, -1.0, 1.0, -1.0, 1.0)
    gl.glTranslatef(-30000.0, -20000.0, 0.0)
    gl.glScalef(1000.0, 1000.0, 1.0)
    cx, cy = 30.0, 20.0
    # wedges from near the centre out to radius 19.9 (components up to 49.9): eye
    # coordinates reach +-30000, in range, and NDC far beyond the window (clipped)
    k = 12
    th = np.arange(k) * (2 * math.pi / k) + 0.13
    apex = np.stack([cx + 1.5e-4 * np.cos(th), cy + 1.5e-4 * np.sin(th)], -1)
    half = math.radians(4.0)
    f1 = np.stack([cx + 19.9 * np.cos(th - half), cy + 19.9 * np.sin(th - half)], -1)
    f2 = np.stack([cx + 19.9 * np.cos(th + half), cy + 19.9 * np.sin(th + half)], -1)
    wedge_v = _f32(np.stack([apex, f1, f2], 1).reshape(-1, 2))
    wedge_c = _rgba(np.repeat(_hsv(np.arange(k) / k, 0.6, 0.55), 3, axis=0))
    # a fan of 48 slivers of radius 0.0009, alternating in brightness
    s = 48
    ang = np.arange(s + 1) * (2 * math.pi / s)
    rim = np.stack([cx + 9e-4 * np.cos(ang), cy + 9e-4 * np.sin(ang)], -1)
    fan_v = _f32(np.stack([np.tile([cx, cy], (s, 1)), rim[:-1], rim[1:]], 1).reshape(-1, 2))
    fan_c = _rgba(np.repeat(_hsv(np.arange(s) / s, 1.0, np.where(np.arange(s) % 2, 1.0, 0.7)), 3, axis=0))
    # two rings (triangle strips) at radii 0.00030-0.00042 and 0.00055-0.00068
    rings = []
    for r0, r1, shift in ((3.0e-4, 4.2e-4, 0.5), (5.5e-4, 6.8e-4, 0.0)):
        m = 96
        t = np.arange(m + 1) * (2 * math.pi / m)
        pts = np.empty((2 * (m + 1), 2))
        pts[0::2] = np.stack([cx + r0 * np.cos(t), cy + r0 * np.sin(t)], -1)
        pts[1::2] = np.stack([cx + r1 * np.cos(t), cy + r1 * np.sin(t)], -1)
        col = _rgba(np.repeat(_hsv(np.arange(m + 1) / m + shift, 0.9, 1.0), 2, axis=0))
        rings.append((_f32(pts), col))
    gl.glShadeModel(C.GL_FLAT)
    gl.glDisable(C.GL_DEPTH_TEST)

    def frame() -> None:
        gl.glClearColor(0.05, 0.05, 0.12, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        _draw(gl, C.GL_TRIANGLES, wedge_v, wedge_c)
        _draw(gl, C.GL_TRIANGLES, fan_v, fan_c)
        for v, c in rings:
            _draw(gl, C.GL_TRIANGLE_STRIP, v, c)

    return frame


# {====================================================================
# 3. near 0.001, far 1e5

NEAR_FAR_DEPTHS = tuple(0.002 * (1.5e5) ** (k / 7.0) for k in range(8))   # 0.002 .. 300


def near_far_extreme(gl: Any, w: int, h: int) -> Frame:
    """glFrustumf(..., 0.001, 1e5): eight tiles of two quads crossing in depth at
    0.002 .. 300, a disc at 2000 before a wall at 8000; depth test LESS, 24 bits."""
    _start(gl, w, h)
    a = _aspect(w, h)
    n = 0.001
    _projection(gl, "frustum", -n * a, n * a, -n, n, n, 1e5)
    # a vertex at eye depth d projects to NDC (x / (a d), y / d)
    tiles_v = []
    tiles_c = []
    delta = 0.3
    for k, d in enumerate(NEAR_FAR_DEPTHS):
        col, row = k % 4, k // 4
        x0, x1 = -1.0 + col * 0.5 + 0.06, -1.0 + (col + 1) * 0.5 - 0.06
        y0, y1 = 1.0 - (row + 1) * 1.0 + 0.22, 1.0 - row * 1.0 - 0.22
        for sign, hue in ((1.0, k / 8.0), (-1.0, k / 8.0 + 0.5)):
            dl, dr = d * (1 + sign * delta), d * (1 - sign * delta)
            quad = [(x0, y0, dl), (x1, y0, dr), (x1, y1, dr), (x0, y1, dl)]
            tiles_v.append([(xn * a * dd, yn * dd, -dd) for xn, yn, dd in quad])
            shade = [0.55, 1.0, 1.0, 0.55]
            tiles_c.append(_hsv(np.full(4, hue), 0.85, shade))
    tiles_v = _f32(_quads_flat(np.array(tiles_v)))
    tiles_c = _rgba(_quads_flat(np.array(tiles_c)))
    # a wall at 8000 over the whole view, a disc at 2000 in front of it
    dw = 8000.0
    wall_v = _f32([[-1.05 * a * dw, -1.05 * dw, -dw], [1.05 * a * dw, -1.05 * dw, -dw],
                   [1.05 * a * dw, 1.05 * dw, -dw], [-1.05 * a * dw, 1.05 * dw, -dw]])
    wall_c = _rgba([[0.1, 0.1, 0.35], [0.3, 0.05, 0.4], [0.05, 0.3, 0.45], [0.15, 0.15, 0.6]])
    dd = 2000.0
    m = 48
    disc_v, disc_c = _disc_fan(0.0, 0.0, 0.3 * a * dd, 0.3 * dd, -dd, m, [1.0, 0.95, 0.6], [1.0, 0.45, 0.1])
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glShadeModel(C.GL_SMOOTH)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClearDepthf(1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        _draw(gl, C.GL_TRIANGLES, tiles_v, tiles_c)
        _draw(gl, C.GL_TRIANGLE_FAN, disc_v, disc_c)
        _draw(gl, C.GL_TRIANGLE_FAN, wall_v, wall_c, count=4)

    return frame


# {====================================================================
# 4. slivers

def sliver_triangles(gl: Any, w: int, h: int) -> Frame:
    """A sunburst of 720 half-degree slivers, 200 nearly parallel slivers fanned
    from an apex far off screen, and rows of triangles 1/8 to 1/2 pixel thick."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "ortho", -a, a, -1.0, 1.0, -1.0, 1.0)
    # sunburst around (-0.35 a, 0.3), radius 3 (reaching far beyond the window)
    n = 720
    ang = np.arange(n + 1) * (2 * math.pi / n)
    cx, cy = -0.35 * a, 0.3
    sun_v = _f32(np.vstack([[cx, cy], np.stack([cx + 3 * np.cos(ang), cy + 3 * np.sin(ang)], -1)]))
    sun_c = _rgba(np.vstack([[1.0, 1.0, 1.0], _hsv(np.arange(n + 1) / 90.0, 1.0,
                                                    np.where(np.arange(n + 1) % 2, 1.0, 0.45))]))
    # a fan from an apex at (-20, -0.5) over the right half: slivers 0.012 wide at x = 0.5
    m = 200
    ys = np.linspace(-1.05, 0.1, m + 1)
    apex = np.array([-20.0, -0.5])
    far_x = 1.05 * a
    par_v = _f32(np.vstack([apex, np.stack([np.full(m + 1, far_x), ys], -1)]))
    par_c = _rgba(np.vstack([[1.0, 1.0, 1.0], _hsv(0.55 + 0.3 * np.arange(m + 1) / m, 0.9,
                                                    np.where(np.arange(m + 1) % 2, 1.0, 0.3))]))
    # rows of thin horizontal triangles at the top: thickness 1/8 .. 1/2 pixel, slightly tilted
    px = 2.0 / h
    rows = []
    for r in range(12):
        y = 0.5 + r * 0.04
        th = px * (0.125 + 0.375 * r / 11)
        rows.append([[-1.02 * a, y], [1.02 * a, y + 0.02], [1.02 * a, y + 0.02 + th]])
    thin_v = _f32(np.array(rows).reshape(-1, 2))
    thin_c = _rgba(np.repeat(_hsv(np.arange(12) / 12.0, 0.7, 1.0), 3, axis=0))
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_FLAT)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        _draw(gl, C.GL_TRIANGLE_FAN, sun_v, sun_c)
        _draw(gl, C.GL_TRIANGLE_FAN, par_v, par_c)
        _draw(gl, C.GL_TRIANGLES, thin_v, thin_c)

    return frame


# {====================================================================
# 5. triangles crossing w = 0

def crossing_w0(gl: Any, w: int, h: int) -> Frame:
    """The inside of a tube of radius 3 around the camera, from 30 behind the eye to
    150 in front, checkered in 16 x 6 quads; the rings at z = 10 and -10 put
    triangles across w = 0, which only clipping at the near plane can draw."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "frustum", -0.1 * a, 0.1 * a, -0.1, 0.1, 0.1, 200.0)
    gl.glRotatef(-14.0, 0.0, 1.0, 0.0)
    gl.glRotatef(9.0, 1.0, 0.0, 0.0)
    seg = 16
    zs = [30.0, 10.0, -10.0, -30.0, -60.0, -100.0, -150.0]
    ox, oy, rad = 0.7, -0.4, 3.0
    quads, cols = [], []
    for j in range(len(zs) - 1):
        for i in range(seg):
            t0, t1 = 2 * math.pi * i / seg, 2 * math.pi * (i + 1) / seg
            p = [(ox + rad * math.cos(t0), oy + rad * math.sin(t0)),
                 (ox + rad * math.cos(t1), oy + rad * math.sin(t1))]
            quads.append([(*p[0], zs[j]), (*p[1], zs[j]), (*p[1], zs[j + 1]), (*p[0], zs[j + 1])])
            cols.append(_hsv(i / seg, 0.85, 1.0 if (i + j) % 2 else 0.5))
    tube_v = _f32(_quads_flat(np.array(quads)))
    tube_c = _rgba(np.repeat(np.array(cols), 6, axis=0))
    m = 32
    cap_v, cap_c = _disc_fan(ox, oy, rad, rad, -150.0, m, [1.0, 1.0, 1.0], [0.9, 0.8, 0.2])
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glShadeModel(C.GL_FLAT)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClearDepthf(1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glShadeModel(C.GL_FLAT)
        _draw(gl, C.GL_TRIANGLES, tube_v, tube_c)
        gl.glShadeModel(C.GL_SMOOTH)
        _draw(gl, C.GL_TRIANGLE_FAN, cap_v, cap_c)

    return frame


# {====================================================================
# 6. huge triangles

def huge_triangles(gl: Any, w: int, h: int) -> Frame:
    """Left half: six triangles with vertices at +-15980 NDC, each a half-plane on
    screen, added together (ONE, ONE) so that every region shows which of them
    cover it. Right half: a textured ground triangle 10000 across and 8100 deep,
    0.3 below the eye, from behind it, through a near plane of 0.01."""
    _start(gl, w, h)
    wl = w // 2
    al = wl / h
    ar = (w - wl) / h
    rng = np.random.default_rng(6)
    tris, cols = [], []
    # the half viewport's ortho has P00 = 1 / al = 2: vertices at +-7990 are +-15980 NDC,
    # and c*s + t = 7990 * 2 + 1 < 16384
    big = 7990.0
    for k in range(6):
        p = np.array([rng.uniform(-0.7, 0.7) * al, rng.uniform(-0.7, 0.7)])
        th = rng.uniform(0, 2 * math.pi)
        u = np.array([math.cos(th), math.sin(th)])
        nrm = np.array([-u[1], u[0]])
        tris.append([p - big * u, p + big * u, p + big * nrm])
        c = _hsv(k / 6.0 + 0.05, 0.9, 0.42)
        cols.append([c, c, _hsv(k / 6.0 + 0.4, 0.9, 0.42)])
    half_v = _f32(np.array(tris).reshape(-1, 2))
    half_c = _rgba(np.array(cols).reshape(-1, 3))
    # the ground: y = -0.3, from 100 behind the eye to 8000 in front, texcoords x/4, z/4;
    # P00 = 2 again, so c*s + t = 8000 * 2 + 0.02 < 16384
    g = np.array([[-5000.0, -0.3, 100.0], [5000.0, -0.3, 100.0], [0.0, -0.3, -8000.0]])
    ground_v = _f32(g)
    ground_t = _f32(g[:, [0, 2]] / 4.0)
    tex = np.zeros((64, 64, 4), np.uint8)
    ii, jj = np.meshgrid(np.arange(64), np.arange(64))
    checker = ((ii // 8) + (jj // 8)) % 2
    tex[...] = _rgba(np.where(checker[..., None] == 1, _hsv(0.08 + ii / 512.0, 0.8, 1.0),
                              _hsv(0.55 + jj / 256.0, 0.7, 0.6)))
    ground_tex = _texture(gl, tex, C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR, C.GL_REPEAT, mipmap=True)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_SMOOTH)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glViewport(0, 0, wl, h)
        _projection(gl, "ortho", -al, al, -1.0, 1.0, -1.0, 1.0)
        gl.glDisable(C.GL_TEXTURE_2D)
        gl.glEnable(C.GL_BLEND)
        _draw(gl, C.GL_TRIANGLES, half_v, half_c)
        gl.glDisable(C.GL_BLEND)
        gl.glViewport(wl, 0, w - wl, h)
        _projection(gl, "frustum", -0.01 * ar, 0.01 * ar, -0.01, 0.01, 0.01, 20000.0)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, ground_tex)
        _draw(gl, C.GL_TRIANGLES, ground_v, texcoords=ground_t, count=3)
        gl.glDisable(C.GL_TEXTURE_2D)
        gl.glViewport(0, 0, w, h)

    return frame


# {====================================================================
# 7. texture coordinates at +-1000

TEXCOORD_OFFSETS = ((0.0, 0.0), (1000.0, 1000.0), (-1000.0, -1000.0))


def texcoords_1000_repeat(gl: Any, w: int, h: int) -> Frame:
    """Six cells: columns NEAREST and LINEAR, rows the same patch of a 256x256
    texture (12 texels across, turned by 17 degrees) at s, t near 0, +1000 and
    -1000. With REPEAT the three rows are the same picture in exact arithmetic."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "ortho", -a, a, -1.0, 1.0, -1.0, 1.0)
    size = 256
    ii, jj = np.meshgrid(np.arange(size), np.arange(size))
    hue = (ii * 0.045 + jj * 0.11) % 1.0
    val = np.where((ii + jj) % 2 == 0, 1.0, 0.6)
    tex = _rgba(_hsv(hue, 0.8, val))
    names = [_texture(gl, tex, C.GL_NEAREST, C.GL_NEAREST), _texture(gl, tex, C.GL_LINEAR, C.GL_LINEAR)]
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    span = 12.0 / size
    rot = math.radians(17.0)
    ex = np.array([math.cos(rot), math.sin(rot)]) * span
    ey = np.array([-math.sin(rot), math.cos(rot)]) * span
    cells = []
    for row, (os_, ot) in enumerate(TEXCOORD_OFFSETS):
        for col in range(2):
            x0, x1 = -a + col * a + 0.02, -a + (col + 1) * a - 0.02
            y1 = 1.0 - row * (2.0 / 3.0) - 0.02
            y0 = 1.0 - (row + 1) * (2.0 / 3.0) + 0.02
            v = _f32([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
            base = np.array([os_ + 0.3, ot + 0.6])
            tc = _f32([base, base + ex * (x1 - x0) / (2.0 / 3.0), base + ex * (x1 - x0) / (2.0 / 3.0) + ey,
                       base + ey])
            cells.append((names[col], v, tc))
    gl.glDisable(C.GL_DEPTH_TEST)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_TEXTURE_2D)
        for name, v, tc in cells:
            gl.glBindTexture(C.GL_TEXTURE_2D, name)
            _draw(gl, C.GL_TRIANGLE_FAN, v, texcoords=tc, count=4)
        gl.glDisable(C.GL_TEXTURE_2D)

    return frame


# {====================================================================
# 8. projective texture coordinates, q -> 0

# rows s, t, r, q of the texture matrix: s = (rx + 1 + rz) / 2, t = (ry + 1 + rz) / 2, q = 1 + rz,
# so s / q = rx / (2 (1 + rz)) + 1/2: the front paraboloid of a dual-paraboloid map
PARABOLOID_ROWS = np.array([[0.5, 0.0, 0.5, 0.5],
                            [0.0, 0.5, 0.5, 0.5],
                            [0.0, 0.0, 0.0, 0.0],
                            [0.0, 0.0, 1.0, 1.0]])
PARABOLOID_GRID = 24     # cells per side of the screen grid


def paraboloid_directions(n: int = PARABOLOID_GRID) -> np.ndarray:
    """The reflection directions (rx, ry, rz) at the (n + 1)^2 grid vertices, row 0
    (the bottom of the window) at the back pole rz = -1, the top row at rz = +1."""
    theta = np.linspace(math.pi, 0.0, n + 1)[:, None] * np.ones((1, n + 1))
    phi = np.linspace(0.0, 2 * math.pi, n + 1)[None, :] * np.ones((n + 1, 1))
    d = np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], -1)
    d[0, :, :2] = 0.0
    d[0, :, 2] = -1.0
    return d


def projective_q_to_0(gl: Any, w: int, h: int) -> Frame:
    """A grid over the window carrying texcoords (rx, ry, rz, 1) from the front pole
    (top) to the back pole (bottom, q = 0), through the paraboloid texture matrix;
    LINEAR, REPEAT, a texture whose texels all have R + G = 255."""
    _start(gl, w, h)
    _projection(gl, "ortho", -1.0, 1.0, -1.0, 1.0, -1.0, 1.0)
    n = PARABOLOID_GRID
    xs = np.linspace(-1.0, 1.0, n + 1)
    x, y = np.meshgrid(xs, xs)
    verts = _f32(np.stack([x, y], -1).reshape(-1, 2))
    d = paraboloid_directions(n)
    tc = _f32(np.concatenate([d, np.ones(d.shape[:2] + (1,))], -1).reshape(-1, 4))
    idx = _grid_indices(n, n)
    size = 64
    ii, jj = np.meshgrid(np.arange(size), np.arange(size))
    r = 0.5 + 0.5 * np.sin(ii * (2 * math.pi / size) * 3) * np.where(((ii // 8) + (jj // 8)) % 2, 1.0, -1.0)
    r = np.round(r * 255.0)
    b = np.round(127.5 + 127.5 * np.cos(jj * (2 * math.pi / size) * 2))
    tex = np.stack([r, 255.0 - r, b, np.full_like(r, 255.0)], -1).astype(np.uint8)
    name = _texture(gl, tex, C.GL_LINEAR, C.GL_LINEAR, C.GL_REPEAT)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glMatrixMode(C.GL_TEXTURE)
    gl.glLoadMatrixf(_f32(PARABOLOID_ROWS.T.reshape(-1)))     # column-major
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glDisable(C.GL_DEPTH_TEST)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, name)
        _arrays(gl, verts, texcoords=tc)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
        gl.glDisable(C.GL_TEXTURE_2D)

    return frame


# {====================================================================
# 9. shininess 128, spot exponent 128

def _sphere(nu: int, nv: int, radius: float, centre: tuple[float, float, float]
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    u = np.linspace(0.0, 2 * math.pi, nu + 1)
    v = np.linspace(-math.pi / 2, math.pi / 2, nv + 1)
    uu, vv = np.meshgrid(u, v)
    nrm = np.stack([np.cos(vv) * np.cos(uu), np.sin(vv), np.cos(vv) * np.sin(uu)], -1).reshape(-1, 3)
    pos = nrm * radius + np.array(centre)
    return _f32(pos), _f32(nrm), _grid_indices(nu, nv)


def shininess_spot_128(gl: Any, w: int, h: int) -> Frame:
    """A plane of 64 x 64 cells and a sphere of 64 x 32 under a spotlight of
    exponent 128 and a directional light, material shininess 128, per-vertex
    lighting with COLOR_MATERIAL (colourful vertex colours)."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "frustum", -0.06 * a, 0.06 * a, -0.06, 0.06, 0.1, 50.0)
    gl.glTranslatef(0.0, 0.1, -3.6)
    gl.glRotatef(32.0, 1.0, 0.0, 0.0)
    n = 64
    ps = np.linspace(-2.6, 2.6, n + 1)
    x, z = np.meshgrid(ps, ps)
    plane_v = _f32(np.stack([x, np.full_like(x, -0.9), z], -1).reshape(-1, 3))
    plane_n = _f32(np.tile([0.0, 1.0, 0.0], (len(plane_v), 1)))
    plane_c = _rgba(_hsv(0.16 * x.reshape(-1) + 0.09 * z.reshape(-1) + 0.55, 0.75, 1.0))
    plane_i = _grid_indices(n, n)
    sph_v, sph_n, sph_i = _sphere(64, 32, 0.75, (-0.2, -0.05, 0.1))
    sph_c = _rgba(_hsv(np.arctan2(sph_n[:, 2], sph_n[:, 0]) / (2 * math.pi) + 0.1, 0.7, 1.0))
    # lights are given in eye coordinates of the modelview set above
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_LIGHT0)
    gl.glEnable(C.GL_LIGHT1)
    gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, _f32([0.9, 2.2, 0.8, 1.0]))
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPOT_DIRECTION, _f32([-0.1, -3.1, 0.45]))
    gl.glLightf(C.GL_LIGHT0, C.GL_SPOT_CUTOFF, 40.0)
    gl.glLightf(C.GL_LIGHT0, C.GL_SPOT_EXPONENT, 128.0)
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, _f32([1.0, 1.0, 1.0, 1.0]))
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, _f32([1.0, 1.0, 1.0, 1.0]))
    gl.glLightfv(C.GL_LIGHT0, C.GL_AMBIENT, _f32([0.0, 0.0, 0.0, 1.0]))
    gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, _f32([-0.6, 0.7, 0.5, 0.0]))
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, _f32([0.45, 0.45, 0.5, 1.0]))
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPECULAR, _f32([1.0, 0.9, 0.7, 1.0]))
    gl.glLightModelfv(C.GL_LIGHT_MODEL_AMBIENT, _f32([0.2, 0.2, 0.2, 1.0]))
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, _f32([1.0, 1.0, 1.0, 1.0]))
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 128.0)
    gl.glEnable(C.GL_COLOR_MATERIAL)
    gl.glEnable(C.GL_NORMALIZE)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glShadeModel(C.GL_SMOOTH)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClearDepthf(1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        _arrays(gl, plane_v, plane_c, normals=plane_n)
        gl.glDrawElements(C.GL_TRIANGLES, len(plane_i), C.GL_UNSIGNED_SHORT, plane_i)
        _arrays(gl, sph_v, sph_c, normals=sph_n)
        gl.glDrawElements(C.GL_TRIANGLES, len(sph_i), C.GL_UNSIGNED_SHORT, sph_i)

    return frame


# {====================================================================
# 10. dense EXP2 fog

# (density, eye depth at the right edge) per band, top to bottom: d z runs from 0 to 4
# (f = e^-16) in the first five, and to 45000 in the last, (d z)^2 = 2e9
FOG_BANDS = ((5.0, 0.8), (8.0, 0.5), (14.0, 4.0 / 14.0), (25.0, 0.16), (50.0, 0.08), (50.0, 900.0))


def exp2_fog_dense(gl: Any, w: int, h: int) -> Frame:
    """Six bands whose eye depth runs from 0 (left) to 4 / density (900 for the last)
    under EXP2 fog of density 5, 8, 14, 25, 50 and 50, evaluated per fragment
    (NICEST); 24 flat-coloured stripes per band show the object colour through the fog."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "ortho", -a, a, -1.0, 1.0, -1.0, 1000.0)
    bands = []
    nb = len(FOG_BANDS)
    seg = 24
    for k, (density, zmax) in enumerate(FOG_BANDS):
        y1 = 1.0 - k * (2.0 / nb) - 0.01
        y0 = 1.0 - (k + 1) * (2.0 / nb) + 0.01
        xs = np.linspace(-a, a, seg + 1)
        zs = -np.linspace(0.0, zmax, seg + 1)
        quads = [[(xs[i], y0, zs[i]), (xs[i + 1], y0, zs[i + 1]), (xs[i + 1], y1, zs[i + 1]),
                  (xs[i], y1, zs[i])] for i in range(seg)]
        hues = np.where(np.arange(seg) % 2, k / nb, k / nb + 0.33)
        cols = np.repeat(_hsv(hues, 0.9, 1.0), 6, axis=0)
        bands.append((density, _f32(_quads_flat(np.array(quads))), _rgba(cols)))
    gl.glEnable(C.GL_FOG)
    gl.glFogx(C.GL_FOG_MODE, C.GL_EXP2)
    gl.glFogfv(C.GL_FOG_COLOR, _f32([0.55, 0.2, 0.65, 1.0]))
    gl.glHint(C.GL_FOG_HINT, C.GL_NICEST)
    gl.glShadeModel(C.GL_FLAT)
    gl.glDisable(C.GL_DEPTH_TEST)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        for density, v, c in bands:
            gl.glFogf(C.GL_FOG_DENSITY, density)
            _draw(gl, C.GL_TRIANGLES, v, c)

    return frame


# {====================================================================
# 11. additive passes

ADDITIVE_PASSES = 64


def additive_passes(gl: Any, w: int, h: int) -> Frame:
    """64 passes of a quad textured with a coloured blob, modulated by vertex
    colours of at most 24/255, each turned and shifted a little, added with
    glBlendFunc(ONE, ONE): every pass rounds to 8 bits before the next adds."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "ortho", -a, a, -1.0, 1.0, -1.0, 1.0)
    size = 64
    ii, jj = np.meshgrid(np.arange(size), np.arange(size))
    u = (ii + 0.5) / size * 2 - 1
    v = (jj + 0.5) / size * 2 - 1
    r2 = u * u + v * v
    fall = np.clip(1.0 - r2, 0.0, 1.0) ** 1.5
    tex = _rgba(_hsv(np.arctan2(v, u) / (2 * math.pi), 1.0, fall))
    name = _texture(gl, tex, C.GL_LINEAR, C.GL_LINEAR, C.GL_CLAMP_TO_EDGE)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    quad_v = _f32([[-0.6, -0.6], [0.6, -0.6], [0.6, 0.6], [-0.6, 0.6]])
    quad_t = _f32([[0, 0], [1, 0], [1, 1], [0, 1]])
    quad_c = np.ascontiguousarray([[24, 5, 9, 255], [5, 24, 9, 255], [9, 5, 24, 255], [16, 16, 16, 255]],
                                  np.uint8)
    gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_SMOOTH)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_BLEND)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, name)
        _arrays(gl, quad_v, quad_c, quad_t)
        for k in range(ADDITIVE_PASSES):
            gl.glLoadIdentity()
            ang = k * 2 * math.pi * 0.381966
            gl.glTranslatef(0.3 * math.cos(ang), 0.3 * math.sin(ang), 0.0)
            gl.glRotatef(k * 5.625, 0.0, 0.0, 1.0)
            gl.glScalef(1.0 - k / 160.0, 1.0 - k / 160.0, 1.0)
            gl.glDrawArrays(C.GL_TRIANGLE_FAN, 0, 4)
        gl.glLoadIdentity()
        gl.glDisable(C.GL_TEXTURE_2D)
        gl.glDisable(C.GL_BLEND)

    return frame


# {====================================================================
# 12. a texture matrix scrolled 1e5 times

SCROLL_STEPS = 100000
SCROLL_STEP = (0.0013, 0.0007)


def texture_scroll(gl: Any, w: int, h: int, steps: int = SCROLL_STEPS,
                   step: tuple[float, float] = SCROLL_STEP) -> Frame:
    """A window-filling quad (texcoords 0 .. 2.5) with a 32x32 colour-cell
    texture, NEAREST and REPEAT, under a texture matrix built in setup by
    `steps` calls of glTranslatef(step[0], step[1], 0) in GL_TEXTURE mode."""
    _start(gl, w, h)
    a = _aspect(w, h)
    _projection(gl, "ortho", -a, a, -1.0, 1.0, -1.0, 1.0)
    size = 32
    ii, jj = np.meshgrid(np.arange(size), np.arange(size))
    hue = ((ii // 4) * 0.125 + (jj // 4) * 0.375) % 1.0
    val = 0.55 + 0.45 * ((ii % 4) + (jj % 4)) / 6.0
    tex = _rgba(_hsv(hue, 0.85, val))
    name = _texture(gl, tex, C.GL_NEAREST, C.GL_NEAREST, C.GL_REPEAT)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glMatrixMode(C.GL_TEXTURE)
    gl.glLoadIdentity()
    sx, sy = float(step[0]), float(step[1])
    for _ in range(steps):
        gl.glTranslatef(sx, sy, 0.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    quad_v = _f32([[-a, -1], [a, -1], [a, 1], [-a, 1]])
    quad_t = _f32([[0, 0], [2.5 * a, 0], [2.5 * a, 2.5], [0, 2.5]])
    gl.glDisable(C.GL_DEPTH_TEST)

    def frame() -> None:
        gl.glClearColor(0.0, 0.0, 0.0, 1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, name)
        _draw(gl, C.GL_TRIANGLE_FAN, quad_v, texcoords=quad_t, count=4)
        gl.glDisable(C.GL_TEXTURE_2D)

    return frame


def texture_scroll_1e5(gl: Any, w: int, h: int) -> Frame:
    """texture_scroll with 100000 steps of (0.0013, 0.0007)."""
    return texture_scroll(gl, w, h)


# {====================================================================
# the table

HARD_CASES: dict[str, HardCase] = {
    "vertices_near_limit": HardCase(
        "Vertices near +-32767", vertices_near_limit,
        "Vertex components up to 32767 under a composite scale of 1/32000, which 16.16 holds "
        "as 2 units of 2^-16 instead of 2.048, in a depth-tested height field.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "rule_breaking_matrices": HardCase(
        "P*MV breaking c*s + t < 16384", rule_breaking_matrices,
        "A modelview scale of 1000 and translation of -30000 magnify a detail 0.001 across "
        "(c*s + t = 79864), so 16.16 vertex rounding is magnified 1000 times, with clipping of "
        "wedges whose clip coordinates reach 30000.",
        expect_overflow=False, expect_underflow=False, expect_rule=True),
    "near_far_extreme": HardCase(
        "Near 0.001, far 1e5", near_far_extreme,
        "A perspective projection with near 0.001 and far 1e5 (beyond 16.16), depth-testing "
        "crossing quads from 0.002 to 300 and a disc before a wall at 2000 and 8000.",
        expect_overflow=True, expect_underflow=False, expect_rule=False),
    "sliver_triangles": HardCase(
        "Sliver triangles", sliver_triangles,
        "Fans of long, thin triangles (half-degree sunburst, nearly parallel slivers from a far "
        "apex, sub-pixel-thin rows) whose coverage hangs on the last subpixel bit.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "crossing_w0": HardCase(
        "Triangles crossing w = 0", crossing_w0,
        "Triangles with vertices behind the eye, which must be clipped in homogeneous space "
        "before any division by w.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "huge_triangles": HardCase(
        "Huge triangles", huge_triangles,
        "Triangles 30000 NDC across and a ground triangle through a near plane of 0.01, whose "
        "clipped vertices and interpolated colours and texture coordinates come from huge spans.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "texcoords_1000_repeat": HardCase(
        "Texture coordinates at +-1000", texcoords_1000_repeat,
        "Texel selection and bilinear weights at s, t = +-1000 with REPEAT, where float32 keeps "
        "only 6e-5 of a coordinate.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "projective_q_to_0": HardCase(
        "Projective texture, q -> 0", projective_q_to_0,
        "A dual-paraboloid lookup whose q = 1 + rz falls to 0 at the back pole, where s/q and "
        "t/q grow without bound.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "shininess_spot_128": HardCase(
        "Shininess 128, spot exponent 128", shininess_spot_128,
        "Powers x^128 in the specular and spot terms of per-vertex lighting, which turn small "
        "errors in the dot products into visible ones near the highlight and the spot.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "exp2_fog_dense": HardCase(
        "Dense EXP2 fog", exp2_fog_dense,
        "EXP2 fog with densities 5 to 50, whose argument (d z)^2 runs from 0 past 16.16's range.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "additive_passes": HardCase(
        "64 additive passes", additive_passes,
        "Sixty-four additive passes of a dim textured quad, each rounded to 8 bits, so that "
        "differences in rounding accumulate.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
    "texture_scroll_1e5": HardCase(
        "Texture matrix scrolled 1e5 times", texture_scroll_1e5,
        "A texture matrix accumulated from 100000 glTranslatef(0.0013, 0.0007, 0), which 16.16 "
        "rounds to 85 and 46 units of 2^-16 at every call.",
        expect_overflow=False, expect_underflow=False, expect_rule=False),
}
