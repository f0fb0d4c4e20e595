"""A gallery of fixed-function techniques: realistic OpenGL ES 1.1 scenes.

Each scene shows one classic way of using the ES 1.1 fixed-function
pipeline (lighting, mipmapped ground planes with fog, DOT3 bump mapping,
light maps, detail textures, environment mapping through the texture
matrix, projective textures, stencil reflections, blended sprites). The
scenes are written in the conventions :mod:`gles` and its Mesa peer
(:mod:`gles.mesa`) share, so one function renders on both and the images
can be compared.

The protocol
------------
A scene is a plain function ``scene(gl, w, h) -> frame``:

* ``gl`` is the command namespace of a context (``gles.Context(...).gl`` or
  ``gles.mesa.MesaContext(...).gl``) of ``w`` x ``h`` pixels with RGBA8888
  colour, 24-bit depth and 8-bit stencil;
* the call does the setup (state, textures, client arrays) and returns a
  zero-argument callable ``frame()`` that draws one complete frame, starting
  with ``glClear``; the caller times ``frame()`` repeatedly and reads the
  image after the last one;
* ``frame`` holds every numpy array the GL reads at draw time (client arrays
  are read when drawing, not when the pointer is set);
* a scene never calls ``glFinish`` or ``glReadPixels`` and never creates a
  context; every texture is procedural (numpy, fixed seeds), so a scene
  draws the same image every time, and does no file I/O;
* the projection follows ``w / h``, so a scene looks right at any size.

:data:`GALLERY` maps each scene's name to a one-line title (for a report
table) and its function::

    import gles
    from gles.gallery import GALLERY
    ctx = gles.Context(256, 256, numeric="fixed")
    title, scene = GALLERY["lit_mesh"]
    frame = scene(ctx.gl, 256, 256)
    frame()
    ctx.save("lit_mesh.png")
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from gles import constants as C

__all__ = ["GALLERY", "Frame", "Scene",
           "lit_mesh", "ground_plane", "dot3_bump", "light_map", "detail_texture",
           "env_map_dual_paraboloid", "projective_spotlight", "stencil_reflection", "alpha_sprites"]

Frame = Callable[[], None]
Scene = Callable[[Any, int, int], Frame]


# {================================================================
# numpy helpers: arrays in the types the GL reads, matrices, meshes

def _f32(a: Any) -> np.ndarray:
    return np.ascontiguousarray(a, dtype=np.float32)


def _u8(a: Any) -> np.ndarray:
    """Round and clamp to ubyte (texels and colours)."""
    return np.ascontiguousarray(np.clip(np.round(a), 0, 255), dtype=np.uint8)


def _normalize(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _smoothstep(e0: float, e1: float, x: np.ndarray) -> np.ndarray:
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def _gl_matrix(m: np.ndarray) -> np.ndarray:
    """A 4x4 matrix (column-vector convention) as the column-major float[16] GL loads."""
    return _f32(np.asarray(m, dtype=np.float64).T.reshape(16))


def _translate(x: float, y: float, z: float) -> np.ndarray:
    m = np.eye(4)
    m[:3, 3] = (x, y, z)
    return m


def _rotate(angle: float, x: float, y: float, z: float) -> np.ndarray:
    """glRotate's matrix: `angle` degrees about the axis (x, y, z)."""
    a = np.array([x, y, z], dtype=np.float64)
    a /= np.linalg.norm(a)
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    m = np.eye(4)
    m[:3, :3] = c * np.eye(3) + s * k + (1 - c) * np.outer(a, a)
    return m


def _frustum(left: float, right: float, bottom: float, top: float, near: float, far: float) -> np.ndarray:
    """glFrustum's matrix."""
    return np.array([
        [2 * near / (right - left), 0, (right + left) / (right - left), 0],
        [0, 2 * near / (top - bottom), (top + bottom) / (top - bottom), 0],
        [0, 0, -(far + near) / (far - near), -2 * far * near / (far - near)],
        [0, 0, -1, 0]])


def _look_at(eye: Sequence[float], target: Sequence[float], up: Sequence[float]) -> np.ndarray:
    """The view matrix of a camera at `eye` looking at `target` (gluLookAt)."""
    e = np.asarray(eye, dtype=np.float64)
    f = _normalize(np.asarray(target, dtype=np.float64) - e)
    s = _normalize(np.cross(f, np.asarray(up, dtype=np.float64)))
    u = np.cross(s, f)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ e
    return m


def _transform(m: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Points (..., 3) through the affine 4x4 `m`."""
    return p @ m[:3, :3].T + m[:3, 3]


def _perspective(gl: Any, w: int, h: int, fovy: float, near: float, far: float) -> None:
    """Viewport over the window, a symmetric frustum of vertical angle `fovy` for
    the window's aspect; modelview identity (left current)."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    top = near * math.tan(math.radians(fovy) / 2)
    right = top * w / h
    gl.glFrustumf(-right, right, -top, top, near, far)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def _begin(gl: Any, clear: Sequence[float]) -> None:
    """State every scene starts from."""
    gl.glClearColor(*clear)
    gl.glClearDepthf(1.0)
    gl.glDisable(C.GL_DITHER)              # RGBA8888 rounds anyway; keep the two peers alike
    gl.glShadeModel(C.GL_SMOOTH)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)


def _grid_indices(cols: int, rows: int) -> np.ndarray:
    """Two triangles per cell of a rows x cols vertex grid (row-major), counter-clockwise
    when column index grows along +u and row index along +v with u x v facing the viewer."""
    a = (np.arange(rows - 1)[:, None] * cols + np.arange(cols - 1)[None, :]).reshape(-1)
    tris = np.stack([a, a + 1, a + cols, a + 1, a + cols + 1, a + cols], axis=-1)
    return np.ascontiguousarray(tris.reshape(-1), dtype=np.uint16)


def _torus(major: float, minor: float, nu: int, nv: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A torus about the z axis: float32 positions and unit normals (n, 3), uint16 triangles.

    The seam vertices are duplicated so that the grid is a plain rows x cols grid.
    """
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, nu + 1), np.linspace(0, 2 * np.pi, nv + 1))
    normals = np.stack([np.cos(v) * np.cos(u), np.cos(v) * np.sin(u), np.sin(v)], axis=-1)
    ring = np.stack([np.cos(u), np.sin(u), np.zeros_like(u)], axis=-1)
    verts = major * ring + minor * normals
    return _f32(verts.reshape(-1, 3)), _f32(normals.reshape(-1, 3)), _grid_indices(nu + 1, nv + 1)


def _box(center: Sequence[float], size: Sequence[float]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """An axis-aligned box: 24 float64 positions and normals (4 per face) and 36 indices
    (counter-clockwise seen from outside)."""
    c, half = np.asarray(center, dtype=np.float64), 0.5 * np.asarray(size, dtype=np.float64)
    verts, normals = [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = np.zeros(3)
            n[axis] = sign
            a, b = np.roll(np.eye(3), -axis - 1, axis=0)[:2]    # two axes spanning the face
            if sign < 0:
                a, b = b, a                                      # keep the winding outward
            for da, db in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                verts.append(c + half * (n + da * a + db * b))
                normals.append(n)
    quad = np.array([0, 1, 2, 0, 2, 3])
    idx = (np.arange(6)[:, None] * 4 + quad[None, :]).reshape(-1)
    return np.array(verts), np.array(normals), idx


# {================================================================
# procedural textures (uint8, row 0 = t near 0)

def _noise(size: int, cells: int, seed: int, octaves: int = 4, gain: float = 0.5) -> np.ndarray:
    """Tileable fractal value noise in [0, 1], (size, size) float64."""
    rng = np.random.default_rng(seed)
    out = np.zeros((size, size))
    amp = 1.0
    for octave in range(octaves):
        c = cells << octave
        if c > size:
            break
        grid = rng.random((c, c))
        x = np.arange(size) * (c / size)
        i0 = x.astype(int)
        f = x - i0
        f = f * f * (3 - 2 * f)                                  # smooth cell interpolation
        i1 = (i0 + 1) % c
        rows0 = grid[i0] * (1 - f)[:, None] + grid[i1] * f[:, None]
        out += amp * (rows0[:, i0] * (1 - f)[None, :] + rows0[:, i1] * f[None, :])
        amp *= gain
    return (out - out.min()) / np.ptp(out)


def _mipmaps(img: np.ndarray) -> list[np.ndarray]:
    """The full mipmap chain of a square power-of-two image by 2x2 box filtering, kept in
    float between levels so that rounding does not accumulate."""
    level = img.astype(np.float64)
    levels = [level]
    while level.shape[0] > 1:
        n = level.shape[0] // 2
        level = level.reshape(n, 2, n, 2, level.shape[2]).mean(axis=(1, 3))
        levels.append(level)
    return [_u8(x) for x in levels]


def _texture(gl: Any, levels: Sequence[np.ndarray], min_filter: int, mag_filter: int, wrap: int) -> int:
    """A texture object on the active unit from uint8 (n, n, 3|4) images, level by level."""
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    for level, img in enumerate(levels):
        h, w, channels = img.shape
        fmt = C.GL_RGBA if channels == 4 else C.GL_RGB
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, fmt, w, h, 0, fmt, C.GL_UNSIGNED_BYTE, _u8(img))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, min_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, mag_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, wrap)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, wrap)
    return name


def _mipmapped(gl: Any, img: np.ndarray) -> int:
    """Trilinear, repeating texture with the full chain built in numpy."""
    return _texture(gl, _mipmaps(img), C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR, C.GL_REPEAT)


def _bricks(size: int, rows: int, per_row: int, mortar: float, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """A tileable running-bond brick layout: (height in [0, 1] with bevelled brick edges,
    an id per brick for colour variation), both (size, size)."""
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    ry = y * rows
    row = ry.astype(int)
    rx = x * per_row + 0.5 * (row % 2)                           # every other row shifted half a brick
    col = rx.astype(int) % per_row
    # distance to the brick's edge in texels, then a bevel of ~3 texels
    dx = np.minimum(rx % 1.0, 1.0 - rx % 1.0) * size / per_row
    dy = np.minimum(ry % 1.0, 1.0 - ry % 1.0) * size / rows
    edge = np.minimum(dx, dy) - mortar
    height = _smoothstep(0.0, 3.0, edge)
    rng = np.random.default_rng(seed)
    ids = rng.random(rows * per_row)[row * per_row + col]
    return height, ids


def _normal_map(height: np.ndarray, strength: float) -> np.ndarray:
    """Encode the normals of a tileable height field as RGB = (n + 1) / 2 (tangent space, z out)."""
    dx = (np.roll(height, -1, axis=1) - np.roll(height, 1, axis=1)) * 0.5
    dy = (np.roll(height, -1, axis=0) - np.roll(height, 1, axis=0)) * 0.5
    n = _normalize(np.stack([-strength * dx, -strength * dy, np.ones_like(dx)], axis=-1))
    return _u8((n * 0.5 + 0.5) * 255)


# {================================================================
# 1. lit_mesh

def lit_mesh(gl: Any, w: int, h: int) -> Frame:
    """A smooth-shaded torus lit by a directional key light and an attenuated spot light."""
    _begin(gl, (0.07, 0.08, 0.11, 1.0))
    verts, normals, idx = _torus(1.0, 0.42, 64, 32)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glEnable(C.GL_CULL_FACE)                  # a closed mesh: back faces are never seen
    _perspective(gl, w, h, 40.0, 1.0, 20.0)
    # lights are given under the identity modelview, so their positions are in eye space
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_LIGHT0)
    gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, [-0.6, 0.7, 0.5, 0.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.6, 0.55, 0.48, 1.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, [0.5, 0.5, 0.5, 1.0])
    # a cold spot light close to the torus: a pool of light on its lower right with a soft
    # edge (exponent 24 brings the cone's border down to ~0.1, so per-vertex steps stay faint)
    gl.glEnable(C.GL_LIGHT1)
    spot = np.array([2.4, 0.6, -2.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, [*spot, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPOT_DIRECTION, list(np.array([0.7, -0.6, -4.2]) - spot))
    gl.glLightf(C.GL_LIGHT1, C.GL_SPOT_CUTOFF, 28.0)
    gl.glLightf(C.GL_LIGHT1, C.GL_SPOT_EXPONENT, 24.0)
    gl.glLightf(C.GL_LIGHT1, C.GL_CONSTANT_ATTENUATION, 0.4)
    gl.glLightf(C.GL_LIGHT1, C.GL_LINEAR_ATTENUATION, 0.15)
    gl.glLightf(C.GL_LIGHT1, C.GL_QUADRATIC_ATTENUATION, 0.05)
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [0.5, 0.9, 1.4, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPECULAR, [1.0, 1.0, 1.0, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [0.3, 0.2, 0.15, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_DIFFUSE, [0.8, 0.6, 0.45, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [0.9, 0.9, 0.9, 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 40.0)
    gl.glTranslatef(0.0, 0.0, -4.5)
    gl.glRotatef(-58.0, 1.0, 0.0, 0.0)
    gl.glRotatef(20.0, 0.0, 1.0, 0.0)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glNormalPointer(C.GL_FLOAT, 0, normals)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)

    return frame


# {================================================================
# 2. ground_plane

def _paving(size: int, seed: int) -> np.ndarray:
    """Stone paving: a 2x2 checker of two stone tones with grout lines and grain, RGB."""
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    checker = ((x * 2).astype(int) + (y * 2).astype(int)) % 2
    grain = _noise(size, 8, seed, octaves=5)
    light = np.array([196.0, 184.0, 160.0])
    dark = np.array([92.0, 84.0, 78.0])
    col = np.where(checker[..., None] == 1, light, dark) * (0.75 + 0.5 * grain[..., None])
    edge = np.minimum(np.minimum(x * 2 % 1, 1 - x * 2 % 1), np.minimum(y * 2 % 1, 1 - y * 2 % 1)) * size / 2
    grout = _smoothstep(1.0, 3.0, edge)[..., None]              # ~2-texel dark joints
    return col * grout + np.array([40.0, 38.0, 36.0]) * (1 - grout)


def ground_plane(gl: Any, w: int, h: int) -> Frame:
    """A paved plane to the horizon: trilinear mipmaps (64 repeats), EXP fog into the sky."""
    fog_rgb = (0.78, 0.84, 0.9)
    zenith = (0.27, 0.45, 0.78)
    _begin(gl, (*fog_rgb, 1.0))
    gl.glDisable(C.GL_DEPTH_TEST)                # one plane and a backdrop: drawing order suffices
    gl.glDisable(C.GL_CULL_FACE)
    fovy, pitch, eye_height = 45.0, 8.0, 1.6
    tex = _mipmapped(gl, _paving(256, 11))
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glFogf(C.GL_FOG_MODE, C.GL_EXP)
    gl.glFogf(C.GL_FOG_DENSITY, 0.022)
    gl.glFogfv(C.GL_FOG_COLOR, [*fog_rgb, 1.0])
    gl.glHint(C.GL_FOG_HINT, C.GL_NICEST)       # per-fragment fog: the plane is two triangles
    # the sky: a gradient from the horizon (where fog and sky meet) up to the zenith, in NDC
    horizon = math.tan(math.radians(pitch)) / math.tan(math.radians(fovy) / 2)
    sky = _f32([[-1, horizon, 0], [1, horizon, 0], [-1, 1, 0], [1, 1, 0]])
    sky_rgba = _u8(np.array([[*fog_rgb, 1]] * 2 + [[*zenith, 1]] * 2) * 255)
    # the plane y = 0 from 8 units behind the eye to 256 ahead, 256 wide; 4 units a repeat
    plane = _f32([[-128, 0, 8], [128, 0, 8], [-128, 0, -256], [128, 0, -256]])
    plane_tc = _f32(plane[:, [0, 2]] / 4.0)
    view = _rotate(pitch, 1, 0, 0) @ _translate(0, -eye_height, 0)

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glLoadIdentity()
        gl.glViewport(0, 0, w, h)
        gl.glDisable(C.GL_TEXTURE_2D)
        gl.glDisable(C.GL_FOG)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, sky)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, sky_rgba)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        _perspective(gl, w, h, fovy, 0.5, 300.0)
        gl.glLoadMatrixf(_gl_matrix(view))
        gl.glDisableClientState(C.GL_COLOR_ARRAY)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, tex)
        gl.glEnable(C.GL_FOG)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, plane)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, plane_tc)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    return frame
