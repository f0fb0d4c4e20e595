"""A gallery of fixed-function techniques: realistic OpenGL ES 1.1 scenes.

Each scene shows one classic way of using the ES 1.1 fixed-function
pipeline (lighting, mipmapped ground planes with fog, DOT3 bump mapping,
light maps, detail textures, environment mapping through the texture
matrix and through a cube map, projective textures, stencil reflections,
blended sprites). The scenes are written in the conventions :mod:`gles`
and its Mesa peer (:mod:`gles.mesa`) share, so one function renders on both
and the images can be compared.

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
* ``frame`` sets the client arrays it draws from each time, so it holds every
  numpy array the GL reads at draw time (client arrays are read when drawing,
  not when the pointer is set);
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
           "env_map_dual_paraboloid", "env_map_cube", "projective_spotlight", "stencil_reflection",
           "alpha_sprites"]

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


def _view_tangents(w: int, h: int, fovy: float) -> tuple[float, float]:
    """tan of the half angles (x, y) of a view of nominal angle `fovy` on a w x h window:
    `fovy` spans the window's shorter side, so the framed subject fits at any aspect."""
    t = math.tan(math.radians(fovy) / 2)
    return (t * w / h, t) if w >= h else (t, t * h / w)


def _perspective(gl: Any, w: int, h: int, fovy: float, near: float, far: float) -> None:
    """Viewport over the window and a symmetric frustum (see _view_tangents); modelview
    identity (left current)."""
    tx, ty = _view_tangents(w, h, fovy)
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumf(-near * tx, near * tx, -near * ty, near * ty, near, far)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def _mesh_frame(gl: Any, verts: np.ndarray, normals: np.ndarray, idx: np.ndarray) -> Frame:
    """A frame that clears colour and depth and draws the indexed triangles with their normals."""

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glNormalPointer(C.GL_FLOAT, 0, normals)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)

    return frame


def _combine_rgb(gl: Any, func: int, src0: int, src1: int) -> None:
    """The active unit's environment: COMBINE with COMBINE_RGB = func of the
    colours (SRC_COLOR) of src0 and src1; alpha is left as it is."""
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, func)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_RGB, src0)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND0_RGB, C.GL_SRC_COLOR)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC1_RGB, src1)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND1_RGB, C.GL_SRC_COLOR)


def _bind_two_units(gl: Any, textures: Sequence[int], tc: np.ndarray) -> None:
    """Bind textures[0] and textures[1] to units 0 and 1, both reading the
    texture coordinates `tc`; unit 0 is left active."""
    for unit in (1, 0):
        gl.glActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glBindTexture(C.GL_TEXTURE_2D, textures[unit])
        gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)


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
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [0.6, 1.1, 1.7, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPECULAR, [1.0, 1.0, 1.0, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [0.3, 0.2, 0.15, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_DIFFUSE, [0.8, 0.6, 0.45, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [0.9, 0.9, 0.9, 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 40.0)
    gl.glTranslatef(0.0, 0.0, -4.5)
    gl.glRotatef(-58.0, 1.0, 0.0, 0.0)
    gl.glRotatef(20.0, 0.0, 1.0, 0.0)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    return _mesh_frame(gl, verts, normals, idx)


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
    gl.glFogf(C.GL_FOG_DENSITY, 0.018)
    gl.glFogfv(C.GL_FOG_COLOR, [*fog_rgb, 1.0])
    gl.glHint(C.GL_FOG_HINT, C.GL_NICEST)       # per-fragment fog: the plane is two triangles
    # the sky: a gradient from the horizon (where fog and sky meet) up to the zenith, in NDC
    horizon = math.tan(math.radians(pitch)) / _view_tangents(w, h, fovy)[1]
    sky = _f32([[-1, horizon, 0], [1, horizon, 0], [-1, 1, 0], [1, 1, 0]])
    sky_rgba = _u8(np.array([[*fog_rgb, 1]] * 2 + [[*zenith, 1]] * 2) * 255)
    # the plane y = 0 from just in front of the eye (below the view) to 256 ahead, 256 wide.
    # It must not reach behind the eye: fog distance is |z_eye|, interpolated linearly, and a
    # vertex behind the eye would give the near-plane clip vertex a large |z| (thick fog).
    plane = _f32([[-128, 0, -1], [128, 0, -1], [-128, 0, -256], [128, 0, -256]])
    # 4 units a repeat, the pattern turned by 20 degrees so the joints run diagonally
    turn = np.radians(20.0)
    spin = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
    plane_tc = _f32(plane[:, [0, 2]] @ spin.T / 4.0)
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


# {================================================================
# 3. dot3_bump

def dot3_bump(gl: Any, w: int, h: int) -> Frame:
    """A brick wall bump-mapped by DOT3: N (normal map) . L (per-vertex colour), times the bricks."""
    _begin(gl, (0.02, 0.02, 0.03, 1.0))
    gl.glDisable(C.GL_DEPTH_TEST)
    gl.glDisable(C.GL_CULL_FACE)
    height, ids = _bricks(128, 4, 2, 1.0, 21)
    grain = _noise(128, 8, 22, octaves=5)
    bumps = height * (0.85 + 0.3 * grain)                        # rough brick faces, sunken mortar
    brick = np.array([150.0, 70.0, 48.0]) * (0.8 + 0.4 * ids[..., None]) * (0.8 + 0.35 * grain[..., None])
    mortar = np.array([170.0, 165.0, 150.0]) * (0.85 + 0.2 * grain[..., None])
    mix = _smoothstep(0.0, 0.5, height)[..., None]
    base = brick * mix + mortar * (1 - mix)
    # unit 0: N . L, where L comes from the primary colour and N from the normal map
    gl.glActiveTexture(C.GL_TEXTURE0)
    normal_tex = _mipmapped(gl, _normal_map(bumps, 6.0))
    gl.glEnable(C.GL_TEXTURE_2D)
    _combine_rgb(gl, C.GL_DOT3_RGB, C.GL_TEXTURE, C.GL_PRIMARY_COLOR)
    # unit 1: the diffuse bricks, MODULATE by the light term
    gl.glActiveTexture(C.GL_TEXTURE1)
    base_tex = _mipmapped(gl, base)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glActiveTexture(C.GL_TEXTURE0)
    # the wall: z = 0 in object space, so tangent space is object space (x = s, y = t, z = normal)
    cols, rows = 33, 21
    gx, gy = np.meshgrid(np.linspace(-2.0, 2.0, cols), np.linspace(-1.25, 1.25, rows))
    verts = _f32(np.stack([gx, gy, np.zeros_like(gx)], axis=-1).reshape(-1, 3))
    tc = _f32(np.stack([(gx + 2.0) * 0.75, (gy + 1.25) * 0.8], axis=-1).reshape(-1, 2))   # 3 x 2 tiles
    idx = _grid_indices(cols, rows)
    # a point light grazing the wall from the upper left: the unit vector to it, biased into colour
    light = np.array([-0.9, 0.55, 0.45])
    to_light = _normalize(light - verts.astype(np.float64))
    colors = _u8(np.concatenate([(to_light * 0.5 + 0.5) * 255, np.full((len(verts), 1), 255)], axis=1))
    _perspective(gl, w, h, 45.0, 1.0, 10.0)
    gl.glTranslatef(0.0, 0.0, -3.3)
    gl.glRotatef(-25.0, 0.0, 1.0, 0.0)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    for unit in (1, 0):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    textures = (normal_tex, base_tex)

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        _bind_two_units(gl, textures, tc)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)

    return frame


# {================================================================
# 4. light_map

def _planks(size: int, seed: int) -> np.ndarray:
    """Wooden floor boards along t: 4 boards per tile with grain and a dark joint, RGB."""
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    board = (x * 4).astype(int)
    rng = np.random.default_rng(seed)
    tone = rng.uniform(0.8, 1.15, 4)[board]
    streaks = _noise(size, 4, seed + 1, octaves=5)
    grain = 0.5 + 0.5 * np.sin(2 * np.pi * (x * 4 * 6 + 3 * streaks))    # rings along the boards
    wood = np.array([190.0, 130.0, 80.0]) * (tone * (0.8 + 0.2 * grain))[..., None]
    joint = _smoothstep(0.0, 1.5, np.minimum(x * 4 % 1, 1 - x * 4 % 1) * size / 4)[..., None]
    return wood * joint + np.array([40.0, 25.0, 15.0]) * (1 - joint)


def _plaster(size: int, seed: int) -> np.ndarray:
    """Off-white plaster with a faint mottle, RGB."""
    n = _noise(size, 4, seed, octaves=5)
    return np.array([222.0, 214.0, 198.0]) * (0.86 + 0.14 * n)[..., None]


def light_map(gl: Any, w: int, h: int) -> Frame:
    """A room corner lit only by light maps: base textures on unit 0, 16x16 light maps on unit 1."""
    _begin(gl, (0.0, 0.0, 0.0, 1.0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glDisable(C.GL_CULL_FACE)
    # the room: floor y = 0, walls at z = -6 (back), x = -3 and x = 3, ceiling y = 3, open at
    # z = 3, behind the camera.
    # Each face: corner, edge u, edge v (world units), and its base texture's units per repeat.
    faces = [
        (np.array([-3.0, 0.0, 3.0]), np.array([6.0, 0.0, 0.0]), np.array([0.0, 0.0, -9.0]), 2.0, "floor"),
        (np.array([-3.0, 0.0, -6.0]), np.array([6.0, 0.0, 0.0]), np.array([0.0, 3.0, 0.0]), 3.0, "wall"),
        (np.array([-3.0, 0.0, 3.0]), np.array([0.0, 0.0, -9.0]), np.array([0.0, 3.0, 0.0]), 3.0, "wall"),
        (np.array([3.0, 0.0, -6.0]), np.array([0.0, 0.0, 9.0]), np.array([0.0, 3.0, 0.0]), 3.0, "wall"),
        (np.array([-3.0, 3.0, -6.0]), np.array([6.0, 0.0, 0.0]), np.array([0.0, 0.0, 9.0]), 3.0, "ceiling"),
    ]
    lights = [(np.array([-1.6, 2.2, -4.6]), np.array([1.0, 0.78, 0.5]) * 4.5),   # warm lamp, back left
              (np.array([2.3, 1.0, -2.6]), np.array([0.45, 0.6, 1.0]) * 3.0)]    # cool lamp, right
    planes = []
    for corner, eu, ev, _, _ in faces:
        n = _normalize(np.cross(eu, ev))
        if n @ (np.array([0.0, 1.5, -3.0]) - corner) < 0:           # normals into the room
            n = -n
        planes.append((n, float(n @ corner)))
    # the light maps: diffuse from both lamps with 1/d^2 falloff, plus ambient darkened
    # near the other faces (a cheap ambient occlusion), sampled at the texel centres
    lm = 16
    centres = (np.arange(lm) + 0.5) / lm
    verts, tc0, tc1, maps = [], [], [], []
    for k, (corner, eu, ev, repeat, _) in enumerate(faces):
        n, _ = planes[k]
        p = corner + centres[None, :, None] * eu + centres[:, None, None] * ev    # (v, u, 3)
        rgb = np.full(p.shape, 0.16)
        for pos, colour in lights:
            d = pos - p
            dist2 = (d * d).sum(axis=-1, keepdims=True)
            lambert = np.clip((d @ n)[..., None] / np.sqrt(dist2), 0.0, 1.0)
            rgb = rgb + colour * lambert / (1.0 + dist2)
        for j, (nj, dj) in enumerate(planes):
            if j != k:
                rgb = rgb * (1.0 - 0.45 * np.exp(-np.abs(p @ nj - dj) / 0.5))[..., None]
        maps.append(_u8(np.clip(rgb, 0.0, 1.0) * 255))
        quad = np.array([corner, corner + eu, corner + ev, corner + eu + ev])
        uv = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
        verts.append(quad)
        tc0.append(uv * [np.linalg.norm(eu) / repeat, np.linalg.norm(ev) / repeat])
        tc1.append((0.5 + uv * (lm - 1)) / lm)         # texel centres at the face's edges
    verts, tc0, tc1 = _f32(np.concatenate(verts)), _f32(np.concatenate(tc0)), _f32(np.concatenate(tc1))
    gl.glActiveTexture(C.GL_TEXTURE0)
    floor_tex = _mipmapped(gl, _planks(128, 31))
    wall_tex = _mipmapped(gl, _plaster(64, 32))
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glActiveTexture(C.GL_TEXTURE1)
    map_tex = [_texture(gl, [m], C.GL_LINEAR, C.GL_LINEAR, C.GL_CLAMP_TO_EDGE) for m in maps]
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glActiveTexture(C.GL_TEXTURE0)
    for unit in (0, 1):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glColor4f(1.0, 1.0, 1.0, 1.0)
    _perspective(gl, w, h, 55.0, 0.5, 20.0)
    view = _look_at((0.4, 1.5, 2.2), (-0.4, 1.0, -4.0), (0.0, 1.0, 0.0))
    base = [floor_tex if face[4] == "floor" else wall_tex for face in faces]

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glLoadMatrixf(_gl_matrix(view))
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        for unit, tc in ((0, tc0), (1, tc1)):
            gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
            gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        for k in range(len(faces)):
            gl.glActiveTexture(C.GL_TEXTURE0)
            gl.glBindTexture(C.GL_TEXTURE_2D, base[k])
            gl.glActiveTexture(C.GL_TEXTURE1)
            gl.glBindTexture(C.GL_TEXTURE_2D, map_tex[k])
            gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 4 * k, 4)

    return frame


# {================================================================
# 5. detail_texture

def detail_texture(gl: Any, w: int, h: int) -> Frame:
    """Rolling terrain: one colour map stretched over it, sharpened by a detail texture
    repeated 16 times (texture matrix) and added signed on unit 1."""
    sky = (0.66, 0.76, 0.86)
    _begin(gl, (*sky, 1.0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glEnable(C.GL_CULL_FACE)
    # the terrain: heights from smooth noise on a 33 x 33 grid over [-16, 16]^2
    n = 33
    field = _noise(32, 4, 41, octaves=3)
    field = np.pad(field, ((0, 1), (0, 1)), mode="wrap")
    gx, gz = np.meshgrid(np.linspace(-16.0, 16.0, n), np.linspace(16.0, -16.0, n))
    gy = 4.0 * field - 1.0
    verts = np.stack([gx, gy, gz], axis=-1)
    # vertex colours: the sun's diffuse term on the height field's normals, plus sky light
    dx = np.gradient(gy, axis=1) / (32.0 / (n - 1))
    dz = np.gradient(gy, axis=0) / (-32.0 / (n - 1))
    normals = _normalize(np.stack([-dx, np.ones_like(dx), -dz], axis=-1))
    sun = _normalize(np.array([-0.5, 0.6, -0.35]))
    shade = 0.35 + 0.75 * np.clip(normals @ sun, 0.0, 1.0)
    colors = _u8(np.concatenate([np.repeat(shade[..., None], 3, -1), np.ones_like(shade)[..., None]], -1)
                 .reshape(-1, 4) * 255)
    tc = _f32(np.stack([(gx + 16.0) / 32.0, (gz + 16.0) / 32.0], axis=-1).reshape(-1, 2))
    verts = _f32(verts.reshape(-1, 3))
    # rows run towards -z, columns towards +x: u x v points up, so the faces look up
    idx = _grid_indices(n, n)
    # unit 0: the colour map, grass and earth mixed by a noise mask
    mask = _smoothstep(0.45, 0.6, _noise(128, 4, 42, octaves=5))[..., None]
    grass = np.array([88.0, 132.0, 52.0]) * (0.85 + 0.3 * _noise(128, 16, 43))[..., None]
    earth = np.array([142.0, 112.0, 78.0]) * (0.85 + 0.3 * _noise(128, 16, 44))[..., None]
    gl.glActiveTexture(C.GL_TEXTURE0)
    base_tex = _mipmapped(gl, grass * (1 - mask) + earth * mask)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    # unit 1: grey detail around 0.5, ADD_SIGNED adds (detail - 0.5). The smaller mipmap levels
    # fade to 0.5 (the classic detail-texture trick), so distant ground does not shimmer.
    detail = _noise(64, 16, 45, octaves=3) - 0.5
    levels = _mipmaps(np.repeat((128.0 + 150.0 * detail)[..., None], 3, axis=-1))
    levels = [_u8(128.0 + (lv.astype(np.float64) - 128.0) * 0.55 ** k) for k, lv in enumerate(levels)]
    gl.glActiveTexture(C.GL_TEXTURE1)
    detail_tex = _texture(gl, levels, C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR, C.GL_REPEAT)
    gl.glEnable(C.GL_TEXTURE_2D)
    _combine_rgb(gl, C.GL_ADD_SIGNED, C.GL_PREVIOUS, C.GL_TEXTURE)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_ALPHA, C.GL_REPLACE)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_ALPHA, C.GL_PREVIOUS)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND0_ALPHA, C.GL_SRC_ALPHA)
    # the same coordinates feed both units; unit 1's texture matrix repeats the detail 16 times
    gl.glMatrixMode(C.GL_TEXTURE)
    gl.glLoadIdentity()
    gl.glScalef(16.0, 16.0, 1.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glActiveTexture(C.GL_TEXTURE0)
    for unit in (0, 1):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glFogf(C.GL_FOG_MODE, C.GL_LINEAR)       # a little haze so the far edge melts into the sky
    gl.glFogf(C.GL_FOG_START, 14.0)
    gl.glFogf(C.GL_FOG_END, 40.0)
    gl.glFogfv(C.GL_FOG_COLOR, [*sky, 1.0])
    gl.glHint(C.GL_FOG_HINT, C.GL_NICEST)
    gl.glEnable(C.GL_FOG)
    _perspective(gl, w, h, 50.0, 0.5, 60.0)
    view = _look_at((-2.0, 5.0, 15.0), (1.0, 0.5, 0.0), (0.0, 1.0, 0.0))
    textures = (base_tex, detail_tex)

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glLoadMatrixf(_gl_matrix(view))
        _bind_two_units(gl, textures, tc)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)

    return frame


# {================================================================
# 6. env_map_dual_paraboloid

def _sample_wrapped(grid: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Bilinear samples of a tileable (n, n) grid at real coordinates x (column), y (row)."""
    n = grid.shape[0]
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = x - x0, y - y0
    i0, j0 = x0.astype(int) % n, y0.astype(int) % n
    i1, j1 = (i0 + 1) % n, (j0 + 1) % n
    top = grid[j0, i0] * (1 - fx) + grid[j0, i1] * fx
    bottom = grid[j1, i0] * (1 - fx) + grid[j1, i1] * fx
    return top * (1 - fy) + bottom * fy


def _environment(d: np.ndarray) -> np.ndarray:
    """The colour (0..255 RGB) seen along unit directions d (..., 3), y up: a sky with a
    sun and clouds above a checkered ground that fades into haze at the horizon."""
    x, y, z = d[..., 0], d[..., 1], d[..., 2]
    haze = np.array([225.0, 228.0, 232.0])
    up = np.clip(y, 0.0, 1.0)[..., None]
    sky = haze + (np.array([40.0, 90.0, 190.0]) - haze) * np.sqrt(up)
    # clouds: tileable noise on the plane y = 1 above the viewer, sampled bilinearly
    cu = np.where(y > 0.02, x / np.maximum(y, 0.02), 0.0) * 12
    cv = np.where(y > 0.02, z / np.maximum(y, 0.02), 0.0) * 12
    cover = _smoothstep(0.55, 0.8, _sample_wrapped(_noise(64, 4, 61, octaves=4), cu, cv))
    cover = cover * _smoothstep(0.02, 0.25, y)
    sky = sky + (np.array([250.0, 250.0, 250.0]) - sky) * cover[..., None]
    sun_dir = _normalize(np.array([-0.45, 0.5, 0.74]))
    cos_sun = d @ sun_dir
    sky = sky + np.array([255.0, 220.0, 150.0]) * (_smoothstep(0.996, 0.998, cos_sun)
                                                  + 0.35 * np.clip(cos_sun, 0, 1) ** 60)[..., None]
    # the ground: a checker on the plane y = -1, hazier towards the horizon
    down = np.clip(-y, 1e-3, 1.0)
    gu, gv = x / down, z / down
    checker = (np.floor(gu) + np.floor(gv)) % 2
    ground = np.where(checker[..., None] == 1, [70.0, 110.0, 60.0], [150.0, 140.0, 110.0])
    ground = ground + (haze - ground) * (1 - _smoothstep(0.0, 0.35, down))[..., None]
    return np.clip(np.where((y >= 0)[..., None], sky, ground), 0, 255)


def _paraboloid_map(size: int, front: bool) -> np.ndarray:
    """One paraboloid map, RGBA: texel (u, v) in [-1, 1]^2 holds the direction whose
    reflection vector r maps to u = rx / (1 + rz), v = ry / (1 + rz) (front) or
    rx / (1 - rz), ry / (1 - rz) (back). The formula continues past the unit disc into the
    other hemisphere, so bilinear filtering at the rim blends matching colours; alpha is 1
    inside the disc only, so that the alpha test picks each hemisphere's map, and 0 on the
    outermost texels too, where the disc touches the square: coordinates far outside the
    map (q -> 0) clamp to those and must fail the alpha test."""
    v, u = ((np.mgrid[0:size, 0:size] + 0.5) / size) * 2 - 1
    r2 = u * u + v * v
    dz = (1 - r2) if front else (r2 - 1)
    d = np.stack([2 * u, 2 * v, dz], axis=-1) / (1 + r2)[..., None]
    alpha = np.where(r2 <= 1.0, 255.0, 0.0)[..., None]
    alpha[[0, -1], :] = alpha[:, [0, -1]] = 0.0
    return _u8(np.concatenate([_environment(d), alpha], axis=-1))


def _paraboloid_matrix(front: bool) -> np.ndarray:
    """The texture matrix taking (rx, ry, rz, 1) to (s, t, 0, q) with q = 1 +- rz and
    s / q = (rx / q + 1) / 2, t / q = (ry / q + 1) / 2: the projective divide does the
    paraboloid's division, per fragment."""
    sz = 1.0 if front else -1.0
    return np.array([[0.5, 0.0, 0.5 * sz, 0.5],
                     [0.0, 0.5, 0.5 * sz, 0.5],
                     [0.0, 0.0, 0.0, 0.0],
                     [0.0, 0.0, sz, 1.0]])


def env_map_dual_paraboloid(gl: Any, w: int, h: int) -> Frame:
    """A chrome torus reflecting a sky and ground through two paraboloid maps, the
    reflection vectors projected by the texture matrix."""
    _begin(gl, (0.1, 0.1, 0.12, 1.0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glEnable(C.GL_CULL_FACE)
    # the torus in eye space (the modelview stays identity): eye = world, camera at the origin
    verts, normals, idx = _torus(1.0, 0.45, 96, 48)
    model = _translate(0.0, 0.0, -4.6) @ _rotate(-62.0, 1, 0, 0) @ _rotate(15.0, 0, 1, 0)
    p = _transform(model, verts.astype(np.float64))
    n = normals.astype(np.float64) @ model[:3, :3].T
    view = _normalize(p)                                         # from the eye to the vertex
    refl = view - 2.0 * (view * n).sum(axis=-1, keepdims=True) * n
    verts = _f32(p)
    tc = _f32(np.concatenate([refl, np.ones((len(refl), 1))], axis=-1))
    back_tex = _texture(gl, [_paraboloid_map(128, False)], C.GL_LINEAR, C.GL_LINEAR, C.GL_CLAMP_TO_EDGE)
    front_tex = _texture(gl, [_paraboloid_map(128, True)], C.GL_LINEAR, C.GL_LINEAR, C.GL_CLAMP_TO_EDGE)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glColor4f(1.0, 0.92, 0.78, 1.0)                          # a slightly golden chrome
    gl.glAlphaFunc(C.GL_GREATER, 0.5)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    back_m, front_m = _gl_matrix(_paraboloid_matrix(False)), _gl_matrix(_paraboloid_matrix(True))
    _perspective(gl, w, h, 40.0, 1.0, 10.0)

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glTexCoordPointer(4, C.GL_FLOAT, 0, tc)
        # pass 1: every fragment from the back map (it is still right a little past its rim)
        gl.glMatrixMode(C.GL_TEXTURE)
        gl.glLoadMatrixf(back_m)
        gl.glBindTexture(C.GL_TEXTURE_2D, back_tex)
        gl.glDisable(C.GL_ALPHA_TEST)
        gl.glDepthFunc(C.GL_LESS)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
        # pass 2: the front map over it where the reflection points towards +z (alpha 1 inside
        # its disc); q = 1 + rz goes to 0 where rz -> -1, and s/q, t/q run far outside the
        # map there, to clamped border texels with alpha 0
        gl.glLoadMatrixf(front_m)
        gl.glBindTexture(C.GL_TEXTURE_2D, front_tex)
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glDepthFunc(C.GL_LEQUAL)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
        gl.glMatrixMode(C.GL_MODELVIEW)

    return frame


# {================================================================
# 7. env_map_cube

# the direction (x, y, z) of texel (sc, tc) in [-1, 1]^2 of each face (+x, -x, +y, -y, +z, -z),
# the inverse of OES_texture_cube_map's table (sc = -rz, tc = -ry on +x, and so on)
_CUBE_FACES = (
    lambda sc, tc: (np.ones_like(sc), -tc, -sc), lambda sc, tc: (-np.ones_like(sc), -tc, sc),
    lambda sc, tc: (sc, np.ones_like(sc), tc), lambda sc, tc: (sc, -np.ones_like(sc), -tc),
    lambda sc, tc: (sc, -tc, np.ones_like(sc)), lambda sc, tc: (-sc, -tc, -np.ones_like(sc)),
)


def _courtyard(d: np.ndarray) -> np.ndarray:
    """The colour (0..255 RGB) seen along directions d (..., 3) from the middle of a cube
    courtyard of half-size 1, y up: a sky gradient above the walls, a checkered floor, and
    four walls of their own colours with pilasters and a dark plinth, up to height 0.3."""
    x, y, z = d[..., 0], d[..., 1], d[..., 2]
    side = np.maximum(np.abs(x), np.abs(z))
    height = y / np.maximum(side, 1e-6)                          # where d meets a wall
    along = np.where(np.abs(x) >= np.abs(z), z, x) / np.maximum(side, 1e-6)
    up = np.clip(y / np.linalg.norm(d, axis=-1), 0.0, 1.0)[..., None]
    horizon, zenith = np.array([235.0, 225.0, 205.0]), np.array([35.0, 80.0, 185.0])
    sky = horizon + (zenith - horizon) * np.sqrt(up)
    # the floor: a checker of 6 x 6 squares on y = -1
    down = np.maximum(-y, 1e-6)
    checker = (np.floor(3 * x / down) + np.floor(3 * z / down)) % 2
    floor = np.where(checker[..., None] == 1, [60.0, 62.0, 70.0], [200.0, 195.0, 180.0])
    # the walls: +x terracotta, -x sage, +z ochre, -z slate blue
    colours = np.array([[190.0, 85.0, 55.0], [110.0, 160.0, 105.0],
                        [215.0, 170.0, 70.0], [80.0, 100.0, 160.0]])
    which = np.where(np.abs(x) >= np.abs(z), np.where(x >= 0, 0, 1), np.where(z >= 0, 2, 3))
    wall = colours[which]
    pilaster = np.abs(((along + 1) * 2) % 1.0 - 0.5) < 0.06     # four bays per wall
    wall = np.where(pilaster[..., None], 0.5 * wall + 110.0, wall)
    wall = np.where((height < -0.75)[..., None], 0.35 * wall, wall)
    out = np.where((height > 0.3)[..., None], sky, wall)
    return np.clip(np.where((-y >= side)[..., None], floor, out), 0, 255)


def _cube_texture(gl: Any, size: int) -> int:
    """The courtyard as a cube map on the active unit, each face's mipmap chain built in
    numpy (trilinear, CLAMP_TO_EDGE)."""
    cube = C.GL_TEXTURE_CUBE_MAP_OES
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(cube, name)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    t, s = ((np.mgrid[0:size, 0:size] + 0.5) / size) * 2 - 1      # row 0 = t near 0
    for face, direction in enumerate(_CUBE_FACES):
        img = _courtyard(np.stack(direction(s, t), axis=-1))
        for level, texels in enumerate(_mipmaps(img)):
            n = texels.shape[0]
            gl.glTexImage2D(C.GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + face, level, C.GL_RGB, n, n, 0,
                            C.GL_RGB, C.GL_UNSIGNED_BYTE, texels)
    gl.glTexParameteri(cube, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
    gl.glTexParameteri(cube, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
    gl.glTexParameteri(cube, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
    gl.glTexParameteri(cube, C.GL_TEXTURE_WRAP_T, C.GL_CLAMP_TO_EDGE)
    return name


def env_map_cube(gl: Any, w: int, h: int) -> Frame:
    """A chrome torus reflecting a courtyard through a mipmapped cube map, the reflection
    vectors generated in eye space (REFLECTION_MAP_OES)."""
    _begin(gl, (0.1, 0.1, 0.12, 1.0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glEnable(C.GL_CULL_FACE)
    verts, normals, idx = _torus(1.0, 0.45, 96, 48)
    _cube_texture(gl, 64)
    gl.glEnable(C.GL_TEXTURE_CUBE_MAP_OES)
    # r = u - 2 (n . u) n from the eye-space position and normal: the environment is fixed
    # in eye space, the camera at its middle looking down -z
    gl.glTexGeniOES(C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_GEN_MODE_OES, C.GL_REFLECTION_MAP_OES)
    gl.glEnable(C.GL_TEXTURE_GEN_STR_OES)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glColor4f(0.92, 0.95, 1.0, 1.0)                          # a slightly cool chrome
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    _perspective(gl, w, h, 40.0, 1.0, 10.0)
    gl.glTranslatef(0.0, 0.0, -4.6)
    gl.glRotatef(-58.0, 1.0, 0.0, 0.0)
    gl.glRotatef(-25.0, 0.0, 1.0, 0.0)
    return _mesh_frame(gl, verts, normals, idx)


# {================================================================
# 8. projective_spotlight

def _gobo(size: int) -> np.ndarray:
    """A spotlight's slide, RGB: a warm disc with a soft edge, crossed by window bars,
    and a 2-texel black border so that CLAMP_TO_EDGE leaves everything outside dark."""
    v, u = ((np.mgrid[0:size, 0:size] + 0.5) / size) * 2 - 1
    r = np.hypot(u, v)
    disc = 1.0 - _smoothstep(0.72, 0.92, r)
    bars = _smoothstep(0.025, 0.05, np.minimum(np.abs(u), np.abs(v)))       # a cross of window bars
    rim = _smoothstep(0.45, 0.47, r) * (1 - _smoothstep(0.49, 0.51, r))     # and a thin ring
    light = disc * bars * (1 - 0.8 * rim)
    rgb = np.array([255.0, 236.0, 200.0]) * light[..., None]
    rgb[:2], rgb[-2:], rgb[:, :2], rgb[:, -2:] = 0, 0, 0, 0
    return rgb


def projective_spotlight(gl: Any, w: int, h: int) -> Frame:
    """A slide projector over a floor and boxes: object positions as texture coordinates,
    the light's frustum in the texture matrix, added over a dim fill-lit pass."""
    _begin(gl, (0.0, 0.0, 0.0, 1.0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glEnable(C.GL_CULL_FACE)
    # the scene in world space: a 12 x 12 floor (a grid, so per-vertex lighting is smooth)
    # and four boxes; colours per vertex feed the material through COLOR_MATERIAL
    n = 25
    fx, fz = np.meshgrid(np.linspace(-6.0, 6.0, n), np.linspace(6.0, -6.0, n))
    parts_v = [np.stack([fx, np.zeros_like(fx), fz], axis=-1).reshape(-1, 3)]
    parts_n = [np.tile([0.0, 1.0, 0.0], (n * n, 1))]
    parts_c = [np.tile([0.75, 0.75, 0.72], (n * n, 1))]
    parts_i = [_grid_indices(n, n).astype(np.int64)]
    boxes = [((-1.2, 0.75, -0.8), (1.5, 1.5, 1.5), (0.85, 0.3, 0.25)),
             ((1.3, 0.5, 0.6), (1.0, 1.0, 1.0), (0.25, 0.55, 0.85)),
             ((0.4, 1.1, -2.6), (1.0, 2.2, 1.0), (0.9, 0.8, 0.3)),
             ((-2.6, 0.35, 1.4), (0.7, 0.7, 0.7), (0.35, 0.75, 0.4))]
    base = n * n
    for centre, size, colour in boxes:
        bv, bn, bi = _box(centre, size)
        parts_v.append(bv)
        parts_n.append(bn)
        parts_c.append(np.tile(colour, (len(bv), 1)))
        parts_i.append(bi + base)
        base += len(bv)
    pos = np.concatenate(parts_v)
    verts = _f32(pos)
    normals = _f32(np.concatenate(parts_n))
    colors = _u8(np.concatenate([np.concatenate(parts_c), np.ones((len(pos), 1))], axis=1) * 255)
    idx = np.ascontiguousarray(np.concatenate(parts_i), dtype=np.uint16)
    tc = _f32(np.concatenate([pos, np.ones((len(pos), 1))], axis=1))   # (x, y, z, 1), object space
    # the projector: its view and a 50-degree frustum; bias maps clip [-1, 1] to texture [0, 1]
    light_pos = np.array([-3.0, 6.5, 3.0])
    light_view = _look_at(light_pos, (0.0, 0.3, -0.8), (0.0, 1.0, 0.0))
    near = 1.0
    half = near * math.tan(math.radians(25.0))
    bias = _translate(0.5, 0.5, 0.5) @ np.diag([0.5, 0.5, 0.5, 1.0])
    tex_matrix = _gl_matrix(bias @ _frustum(-half, half, -half, half, near, 30.0) @ light_view)
    gobo = _texture(gl, _mipmaps(_gobo(128)), C.GL_LINEAR_MIPMAP_LINEAR, C.GL_LINEAR, C.GL_CLAMP_TO_EDGE)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_COLOR_MATERIAL)            # AMBIENT_AND_DIFFUSE from the colour array
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.22, 0.24, 0.3, 1.0])      # a dim, cool fill
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, [0.0, 0.0, 0.0, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [1.0, 1.0, 1.0, 1.0])        # the projector's lamp
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPECULAR, [0.0, 0.0, 0.0, 1.0])
    gl.glLightf(C.GL_LIGHT1, C.GL_QUADRATIC_ATTENUATION, 0.008)
    gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    for array in (C.GL_NORMAL_ARRAY, C.GL_COLOR_ARRAY, C.GL_TEXTURE_COORD_ARRAY):
        gl.glEnableClientState(array)
    _perspective(gl, w, h, 42.0, 1.0, 40.0)
    view = _gl_matrix(_look_at((6.5, 6.0, 8.5), (0.0, 0.4, -0.5), (0.0, 1.0, 0.0)))

    def frame() -> None:
        gl.glDepthMask(True)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glMatrixMode(C.GL_TEXTURE)
        gl.glLoadMatrixf(tex_matrix)
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glLoadMatrixf(view)
        # the lights are placed in world space (under the view matrix)
        gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, [0.4, 1.0, 0.7, 0.0])
        gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, [*light_pos, 1.0])
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glNormalPointer(C.GL_FLOAT, 0, normals)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
        gl.glTexCoordPointer(4, C.GL_FLOAT, 0, tc)
        # pass 1: fill light and a little ambient, untextured; lays down depth
        gl.glLightModelfv(C.GL_LIGHT_MODEL_AMBIENT, [0.12, 0.12, 0.14, 1.0])
        gl.glEnable(C.GL_LIGHT0)
        gl.glDisable(C.GL_LIGHT1)
        gl.glDisable(C.GL_TEXTURE_2D)
        gl.glDisable(C.GL_BLEND)
        gl.glDepthFunc(C.GL_LESS)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
        # pass 2: the projector's diffuse light times the slide, added on the same surfaces
        gl.glLightModelfv(C.GL_LIGHT_MODEL_AMBIENT, [0.0, 0.0, 0.0, 1.0])
        gl.glDisable(C.GL_LIGHT0)
        gl.glEnable(C.GL_LIGHT1)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, gobo)
        gl.glEnable(C.GL_BLEND)
        gl.glDepthFunc(C.GL_EQUAL)
        gl.glDepthMask(False)
        gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)

    return frame


# {================================================================
# 9. stencil_reflection

def _marble_tiles(size: int, seed: int) -> np.ndarray:
    """Polished floor tiles, RGB: a 4x4 checker of dark and light marble with veins."""
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    checker = ((x * 4).astype(int) + (y * 4).astype(int)) % 2
    veins = np.abs(np.sin(2 * np.pi * (2 * x + y + 1.5 * _noise(size, 4, seed, octaves=5))))
    vein = 1.0 - 0.35 * (1 - _smoothstep(0.0, 0.15, veins))
    light = np.array([225.0, 222.0, 215.0]) * vein[..., None]
    dark = np.array([60.0, 64.0, 78.0]) * (2 - vein)[..., None]
    return np.where(checker[..., None] == 1, light, dark)


def stencil_reflection(gl: Any, w: int, h: int) -> Frame:
    """A lit torus and box over a polished floor, mirrored in it with the stencil buffer."""
    _begin(gl, (0.05, 0.05, 0.07, 1.0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glEnable(C.GL_CULL_FACE)
    gl.glClearStencil(0)
    torus_v, torus_n, torus_i = _torus(0.7, 0.28, 48, 24)
    bv, bn, bi = _box((0.0, 0.0, 0.0), (0.8, 0.8, 0.8))
    box_v, box_n, box_i = _f32(bv), _f32(bn), np.ascontiguousarray(bi, dtype=np.uint16)
    # the mirror: its front edge cuts the lower part of the torus's reflection off (stencil)
    floor_v = _f32([[-2.4, 0.0, 2.6], [2.4, 0.0, 2.6], [-2.4, 0.0, -2.4], [2.4, 0.0, -2.4]])
    floor_tc = _f32([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [2.0, 2.0]])
    floor_tex = _mipmapped(gl, _marble_tiles(128, 71))
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glEnable(C.GL_LIGHT0)
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.9, 0.88, 0.82, 1.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, [0.8, 0.8, 0.8, 1.0])
    gl.glEnable(C.GL_COLOR_MATERIAL)
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [0.7, 0.7, 0.7, 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 40.0)
    _perspective(gl, w, h, 45.0, 1.0, 30.0)
    view = _gl_matrix(_look_at((0.0, 1.7, 5.4), (0.0, 0.45, 0.0), (0.0, 1.0, 0.0)))
    light_pos = [-2.0, 4.0, 3.0, 1.0]

    def objects() -> None:
        """The torus standing on its rim above the floor and a box on the floor, lit,
        under the current modelview (the view, or the view times the mirror)."""
        gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, light_pos)   # mirrored along with the objects
        gl.glEnable(C.GL_LIGHTING)
        gl.glEnableClientState(C.GL_NORMAL_ARRAY)
        gl.glPushMatrix()
        gl.glTranslatef(-0.35, 1.15, 0.0)
        gl.glRotatef(-20.0, 0.0, 1.0, 0.0)
        gl.glRotatef(10.0, 1.0, 0.0, 0.0)
        gl.glColor4f(0.85, 0.55, 0.15, 1.0)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, torus_v)
        gl.glNormalPointer(C.GL_FLOAT, 0, torus_n)
        gl.glDrawElements(C.GL_TRIANGLES, len(torus_i), C.GL_UNSIGNED_SHORT, torus_i)
        gl.glPopMatrix()
        gl.glPushMatrix()
        gl.glTranslatef(1.3, 0.4, 0.3)
        gl.glRotatef(35.0, 0.0, 1.0, 0.0)
        gl.glColor4f(0.2, 0.45, 0.8, 1.0)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, box_v)
        gl.glNormalPointer(C.GL_FLOAT, 0, box_n)
        gl.glDrawElements(C.GL_TRIANGLES, len(box_i), C.GL_UNSIGNED_SHORT, box_i)
        gl.glPopMatrix()
        gl.glDisableClientState(C.GL_NORMAL_ARRAY)
        gl.glDisable(C.GL_LIGHTING)

    def floor() -> None:
        gl.glVertexPointer(3, C.GL_FLOAT, 0, floor_v)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)

    def frame() -> None:
        gl.glColorMask(True, True, True, True)  # Clear obeys the masks: open them first
        gl.glDepthMask(True)
        gl.glStencilMask(0xFF)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
        gl.glLoadMatrixf(view)
        # 1. the floor's pixels into the stencil only (1 where the mirror is)
        gl.glEnable(C.GL_STENCIL_TEST)
        gl.glStencilFunc(C.GL_ALWAYS, 1, 0xFF)
        gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_REPLACE)
        gl.glColorMask(False, False, False, False)
        gl.glDepthMask(False)
        floor()
        # 2. the objects mirrored in y = 0, only where stencil = 1; the mirror flips the winding
        gl.glColorMask(True, True, True, True)
        gl.glDepthMask(True)
        gl.glStencilFunc(C.GL_EQUAL, 1, 0xFF)
        gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
        gl.glPushMatrix()
        gl.glScalef(1.0, -1.0, 1.0)
        gl.glFrontFace(C.GL_CW)
        objects()
        gl.glFrontFace(C.GL_CCW)
        gl.glPopMatrix()
        gl.glDisable(C.GL_STENCIL_TEST)
        # 3. the floor, translucent, over the reflection
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, floor_tex)
        gl.glEnable(C.GL_BLEND)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, floor_tc)
        gl.glColor4f(1.0, 1.0, 1.0, 0.65)
        floor()
        gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glDisable(C.GL_BLEND)
        gl.glDisable(C.GL_TEXTURE_2D)
        # 4. the objects themselves
        objects()

    return frame


# {================================================================
# 10. alpha_sprites

def alpha_sprites(gl: Any, w: int, h: int) -> Frame:
    """Smoke and embers over a camp fire: 300 camera-facing textured quads, sorted back to
    front, blended SRC_ALPHA / ONE_MINUS_SRC_ALPHA with depth writes off."""
    _begin(gl, (0.09, 0.1, 0.16, 1.0))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    gl.glDisable(C.GL_CULL_FACE)
    # opaque scenery: dark ground and two logs (boxes), vertex-coloured
    ground_v = np.array([[-40.0, 0.0, 8.0], [40.0, 0.0, 8.0], [-40.0, 0.0, -20.0], [40.0, 0.0, -20.0]])
    ground_c = np.array([[0.16, 0.14, 0.12]] * 2 + [[0.06, 0.06, 0.08]] * 2)
    parts_v, parts_c, parts_i = [ground_v], [ground_c], [np.array([0, 1, 2, 1, 3, 2])]
    base = 4
    for centre, size, angle in (((0.0, 0.18, 0.0), (1.8, 0.3, 0.3), 30.0),
                                ((0.0, 0.45, 0.0), (1.6, 0.28, 0.28), -40.0)):
        bv, bn, bi = _box((0.0, 0.0, 0.0), size)
        rot = _translate(*centre) @ _rotate(angle, 0, 1, 0)
        parts_v.append(_transform(rot, bv))
        # a little shading by face orientation, since lighting is off
        facing = np.abs(bn @ _normalize(np.array([0.3, 1.0, 0.5])))
        parts_c.append(np.array([0.3, 0.2, 0.12]) * (0.55 + 0.45 * facing)[:, None])
        parts_i.append(bi + base)
        base += len(bv)
    scene_v = _f32(np.concatenate(parts_v))
    scene_c = _u8(np.concatenate([np.concatenate(parts_c), np.ones((base, 1))], axis=1) * 255)
    scene_i = np.ascontiguousarray(np.concatenate(parts_i), dtype=np.uint16)
    # particles: age a in [0, 1) rising from the fire, drifting with the wind and spreading;
    # young ones are small bright embers, old ones big, faint grey smoke
    count = 300
    rng = np.random.default_rng(81)
    age = rng.random(count)
    swirl = rng.uniform(0, 2 * np.pi, count)
    spread = 0.25 + 1.1 * age * rng.random(count)
    centres = np.stack([spread * np.cos(swirl) + 1.6 * age ** 2,
                        0.4 + 5.0 * age + 0.2 * rng.standard_normal(count),
                        spread * np.sin(swirl) - 0.4 * age], axis=-1)
    sizes = 0.1 + 0.75 * age
    fire = np.array([1.0, 0.75, 0.25])
    smoke = np.array([0.55, 0.55, 0.6])
    mix = _smoothstep(0.1, 0.35, age)[:, None]
    rgb = fire * (1 - mix) + smoke * mix
    alpha = np.where(age < 0.2, 0.9, 0.6 * (1 - age) + 0.1)
    # build the quads in eye space, sorted far to near (eye z ascending)
    camera = _look_at((0.0, 2.6, 7.5), (0.4, 2.4, 0.0), (0.0, 1.0, 0.0))
    eye = _transform(camera, centres)
    order = np.argsort(eye[:, 2], kind="stable")
    corners = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
    quad_v = eye[order, None, :] + np.concatenate(
        [corners[None] * sizes[order, None, None] * 0.5, np.zeros((count, 4, 1))], axis=-1)
    sprite_v = _f32(quad_v.reshape(-1, 3))
    sprite_tc = _f32(np.tile((corners + 1) * 0.5, (count, 1)))
    sprite_c = _u8(np.repeat(np.concatenate([rgb, alpha[:, None]], axis=1)[order], 4, axis=0) * 255)
    sprite_i = np.ascontiguousarray(
        (np.arange(count)[:, None] * 4 + np.array([0, 1, 2, 0, 2, 3])[None]).reshape(-1), dtype=np.uint16)
    # the sprite: white with a soft round alpha and a little mottling, so the smoke has texture
    v, u = ((np.mgrid[0:64, 0:64] + 0.5) / 32) - 1
    r2 = u * u + v * v
    puff = np.clip(1 - r2, 0, 1) ** 2 * (0.75 + 0.25 * _noise(64, 4, 82))
    sprite = _u8(np.concatenate([np.full((64, 64, 3), 255.0), 255 * puff[..., None]], axis=-1))
    tex = _mipmapped(gl, sprite)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    _perspective(gl, w, h, 50.0, 0.5, 30.0)
    camera_m = _gl_matrix(camera)

    def frame() -> None:
        gl.glDepthMask(True)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        # the opaque scene first, writing depth
        gl.glLoadMatrixf(camera_m)
        gl.glDisable(C.GL_BLEND)
        gl.glDisable(C.GL_TEXTURE_2D)
        gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, scene_v)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, scene_c)
        gl.glDrawElements(C.GL_TRIANGLES, len(scene_i), C.GL_UNSIGNED_SHORT, scene_i)
        # then the sprites, already in eye space: depth-tested against the scene, not written
        gl.glLoadIdentity()
        gl.glEnable(C.GL_BLEND)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glBindTexture(C.GL_TEXTURE_2D, tex)
        gl.glDepthMask(False)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, sprite_v)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, sprite_c)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, sprite_tc)
        gl.glDrawElements(C.GL_TRIANGLES, len(sprite_i), C.GL_UNSIGNED_SHORT, sprite_i)

    return frame


GALLERY: dict[str, tuple[str, Scene]] = {
    "lit_mesh": (
        "Lit torus: directional + attenuated spot light, specular (shininess 40), DrawElements",
        lit_mesh),
    "ground_plane": (
        "Ground plane to the horizon: numpy mipmap chain, LINEAR_MIPMAP_LINEAR, 64 repeats, EXP fog",
        ground_plane),
    "dot3_bump": (
        "DOT3 bump mapping: normal map . per-vertex light vector (COMBINE DOT3_RGB), x bricks",
        dot3_bump),
    "light_map": (
        "Light-mapped room: base textures x 16x16 bilinear light maps on unit 1 (MODULATE)",
        light_map),
    "detail_texture": (
        "Terrain: colour map + detail texture x16 by the texture matrix (COMBINE ADD_SIGNED)",
        detail_texture),
    "env_map_dual_paraboloid": (
        "Dual-paraboloid environment map: reflection vectors projected by the texture matrix",
        env_map_dual_paraboloid),
    "env_map_cube": (
        "Cube environment map: REFLECTION_MAP_OES texture coordinates, six mipmapped faces",
        env_map_cube),
    "projective_spotlight": (
        "Projective spotlight: bias x light frustum x light view in the texture matrix",
        projective_spotlight),
    "stencil_reflection": (
        "Planar reflection: mirror in the stencil, mirrored objects, blended floor",
        stencil_reflection),
    "alpha_sprites": (
        "300 alpha-blended sprites sorted back to front, depth writes off",
        alpha_sprites),
}
