"""OES_texture_cube_map: cube map objects, their errors and state (worked
by hand from the extension text), face selection and sampling against the
extension's table and formulas evaluated in numpy, NORMAL_MAP_OES and
REFLECTION_MAP_OES texture coordinate generation against the spec's
formulas on a known mesh, and a reflective mipmapped cube-mapped sphere
against the double build and Mesa's llvmpipe."""

from __future__ import annotations

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import mesa

_MESA = mesa.available()
needs_mesa = pytest.mark.skipif(_MESA is not None, reason=f"Mesa peer unavailable: {_MESA}")

CUBE = C.GL_TEXTURE_CUBE_MAP_OES
FACES = [C.GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + i for i in range(6)]
NUMERICS = ["fixed", "float", "double"]
# one colour per face (+x, -x, +y, -y, +z, -z)
FACE_RGB = np.array([[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 0], [255, 0, 255], [0, 255, 255]],
                    np.uint8)


def _face_image(face: int, size: int, checker: bool) -> np.ndarray:
    img = np.empty((size, size, 4), np.uint8)
    img[..., :3] = FACE_RGB[face]
    img[..., 3] = 255
    if checker:
        # texel (i, j) darkened where i + j is odd, its brightness by face and position too
        jj, ii = np.mgrid[0:size, 0:size]
        img[..., :3] = (img[..., :3].astype(int) * ((ii + jj) % 2 == 0)[..., None]
                        + (ii * 7 + jj * 3 + face * 11)[..., None] % 64).clip(0, 255).astype(np.uint8)
    return img


def _images(size: int, checker: bool) -> list[np.ndarray]:
    return [_face_image(f, size, checker) for f in range(6)]


def _load_cube(gl, images: list[np.ndarray], mipmaps: bool = False) -> int:
    gl.glBindTexture(CUBE, 1)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    if mipmaps:
        gl.glTexParameteri(CUBE, C.GL_GENERATE_MIPMAP, 1)
    for f, img in enumerate(images):
        gl.glTexImage2D(FACES[f], 0, C.GL_RGBA, img.shape[1], img.shape[0], 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                        np.ascontiguousarray(img))
    return 1


# {====================================================================
# the extension's face table, sampled in numpy

# (sc, tc, ma) as functions of (rx, ry, rz) per face
TABLE = [
    lambda r: (-r[2], -r[1], r[0]), lambda r: (r[2], -r[1], r[0]),
    lambda r: (r[0], r[2], r[1]), lambda r: (r[0], -r[2], r[1]),
    lambda r: (r[0], -r[1], r[2]), lambda r: (-r[0], -r[1], r[2]),
]


def _face_of(r: np.ndarray) -> int:
    a = np.abs(r)
    axis = int(np.argmax(a))
    return 2 * axis + (0 if r[axis] >= 0 else 1)


def _face_st(r: np.ndarray) -> tuple[int, float, float]:
    f = _face_of(r)
    sc, tc, ma = TABLE[f](r)
    return f, (sc / abs(ma) + 1) / 2, (tc / abs(ma) + 1) / 2


def _sample(images: list[np.ndarray], r: np.ndarray, linear: bool) -> np.ndarray:
    """§3.7.7 on the chosen face (CLAMP_TO_EDGE)."""
    f, s, t = _face_st(r)
    img = images[f].astype(float)
    n = img.shape[0]
    if not linear:
        i, j = min(int(np.floor(s * n)), n - 1), min(int(np.floor(t * n)), n - 1)
        return img[j, i]
    u, v = s * n - 0.5, t * n - 0.5
    i0, j0 = int(np.floor(u)), int(np.floor(v))
    a, b = u - i0, v - j0

    def tx(i: int, j: int) -> np.ndarray:
        return img[min(max(j, 0), n - 1), min(max(i, 0), n - 1)]
    return ((1 - a) * (1 - b) * tx(i0, j0) + a * (1 - b) * tx(i0 + 1, j0) + (1 - a) * b * tx(i0, j0 + 1)
            + a * b * tx(i0 + 1, j0 + 1))


def _directions() -> np.ndarray:
    """Directions whose face is never a tie and whose face coordinates sit
    away from texel edges (NEAREST) on every face: (sc/|ma|, tc/|ma|) on a
    grid of texel centres offset by a quarter texel."""
    out = []
    n = 8
    rng = np.random.default_rng(5)
    for f in range(6):
        for _ in range(12):
            i, j = rng.integers(0, n, 2)
            s = (i + 0.25 + 0.5 * rng.random()) / n
            t = (j + 0.25 + 0.5 * rng.random()) / n
            a, b = 2 * s - 1, 2 * t - 1          # sc/|ma|, tc/|ma|
            ma = 1.0 + rng.random()
            sc, tc = a * ma, b * ma
            axis, sign = f // 2, 1.0 if f % 2 == 0 else -1.0
            r = np.zeros(3)
            r[axis] = sign * ma
            # invert the table: (sc, tc) back to the two minor components
            if f == 0:
                r[2], r[1] = -sc, -tc
            elif f == 1:
                r[2], r[1] = sc, -tc
            elif f == 2:
                r[0], r[2] = sc, tc
            elif f == 3:
                r[0], r[2] = sc, -tc
            elif f == 4:
                r[0], r[1] = sc, -tc
            else:
                r[0], r[1] = -sc, -tc
            out.append(r)
    return np.array(out)


def _draw_points(make, images: list[np.ndarray], dirs: np.ndarray, linear: bool) -> np.ndarray:
    """One pixel per direction: a point of size 1 at pixel (k, 0) with texture coordinate (s, t, r) = d."""
    n = len(dirs)
    with make(n, 1) as ctx:
        gl = ctx.gl
        _load_cube(gl, images)
        flt = C.GL_LINEAR if linear else C.GL_NEAREST
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, flt)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MAG_FILTER, flt)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_WRAP_T, C.GL_CLAMP_TO_EDGE)
        gl.glEnable(CUBE)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glOrthof(0, n, 0, 1, -1, 1)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([[k + 0.5, 0.5] for k in range(n)], np.float32))
        gl.glTexCoordPointer(3, C.GL_FLOAT, 0, dirs.astype(np.float32))
        gl.glDrawArrays(C.GL_POINTS, 0, n)
        assert gl.glGetError() == C.GL_NO_ERROR
        px = gl.glReadPixels(0, 0, n, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
        return np.asarray(px).reshape(n, 4).astype(float)


def _gles(numeric: str):
    return lambda w, h: gles.Context(w, h, numeric=numeric)


@pytest.mark.parametrize("numeric", NUMERICS)
def test_face_selection_nearest(numeric: str) -> None:
    images = _images(8, checker=True)
    dirs = _directions().astype(np.float32).astype(float)
    got = _draw_points(_gles(numeric), images, dirs, linear=False)
    want = np.array([_sample(images, d, False) for d in dirs])
    np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize("numeric", NUMERICS)
def test_face_selection_linear(numeric: str) -> None:
    images = _images(8, checker=True)
    dirs = _directions().astype(np.float32).astype(float)
    got = _draw_points(_gles(numeric), images, dirs, linear=True)
    want = np.array([_sample(images, d, True) for d in dirs])
    # the bilinear weights' 16 bits and one rounding to 8 bits
    assert np.abs(got - want).max() <= 1.0


@pytest.mark.parametrize("numeric", NUMERICS)
def test_each_face_by_its_axis(numeric: str) -> None:
    """The six axis directions (and scaled, q ignored) reach the six faces' colours."""
    images = _images(4, checker=False)
    dirs = np.array([[3, 0.5, -0.25], [-2, 0.25, 0.5], [0.5, 7, 0.25], [-0.25, -1, 0.5], [0.25, 0.5, 2],
                     [0.5, -0.25, -5]], float)
    got = _draw_points(_gles(numeric), images, dirs, linear=False)
    np.testing.assert_array_equal(got[:, :3], FACE_RGB.astype(float))


@needs_mesa
def test_face_selection_against_llvmpipe() -> None:
    images = _images(8, checker=True)
    dirs = _directions().astype(np.float32).astype(float)
    ours = _draw_points(_gles("fixed"), images, dirs, linear=False)
    peer = _draw_points(lambda w, h: mesa.MesaContext(w, h), images, dirs, linear=False)
    np.testing.assert_array_equal(ours, peer)


# {====================================================================
# texture coordinate generation on a known mesh

def _rot(deg: float, axis) -> np.ndarray:
    a = np.radians(deg)
    x, y, z = np.asarray(axis, float) / np.linalg.norm(axis)
    c, s = np.cos(a), np.sin(a)
    return np.array([[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                     [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                     [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]])


TEX_N = 32      # face size of the coordinate-coding cube map


def _coding_images() -> list[np.ndarray]:
    """Texel (i, j) of face f is (8 i, 8 j, 40 f + 20): a pixel names its texel."""
    out = []
    for f in range(6):
        jj, ii = np.mgrid[0:TEX_N, 0:TEX_N]
        img = np.stack([8 * ii, 8 * jj, np.full_like(ii, 40 * f + 20), np.full_like(ii, 255)], -1)
        out.append(img.astype(np.uint8))
    return out


MESH_RNG = np.random.default_rng(11)
MESH_N = 96
MV_R = _rot(35.0, [1, 2, 0.5])             # the modelview's rotation
TEX_R = _rot(20.0, [0, 1, 0])              # the texture matrix
EYE = np.stack([np.arange(MESH_N) + 0.5, np.full(MESH_N, 0.5), -3 - 2 * MESH_RNG.random(MESH_N)], -1)
OBJ = np.ascontiguousarray((MV_R.T @ EYE.T).T, np.float32)
NRM = MESH_RNG.normal(size=(MESH_N, 3))
NRM = (NRM / np.linalg.norm(NRM, axis=1, keepdims=True)).astype(np.float32)


def _texgen_draw(make, mode: int) -> np.ndarray:
    with make(MESH_N, 1) as ctx:
        gl = ctx.gl
        _load_cube(gl, _coding_images())
        for p in (C.GL_TEXTURE_MIN_FILTER, C.GL_TEXTURE_MAG_FILTER):
            gl.glTexParameteri(CUBE, p, C.GL_NEAREST)
        gl.glEnable(CUBE)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glTexGeniOES(C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_GEN_MODE_OES, mode)
        gl.glEnable(C.GL_TEXTURE_GEN_STR_OES)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glOrthof(0, MESH_N, 0, 1, -100, 100)
        gl.glMatrixMode(C.GL_TEXTURE)
        m4 = np.eye(4)
        m4[:3, :3] = TEX_R
        gl.glLoadMatrixf(m4.T.astype(np.float32).ravel())
        gl.glMatrixMode(C.GL_MODELVIEW)
        m4 = np.eye(4)
        m4[:3, :3] = MV_R
        gl.glLoadMatrixf(m4.T.astype(np.float32).ravel())
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_NORMAL_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, OBJ)
        gl.glNormalPointer(C.GL_FLOAT, 0, NRM)
        gl.glDrawArrays(C.GL_POINTS, 0, MESH_N)
        assert gl.glGetError() == C.GL_NO_ERROR
        return np.asarray(gl.glReadPixels(0, 0, MESH_N, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE)).reshape(MESH_N, 4)


def _texgen_expected(mode: int) -> tuple[np.ndarray, np.ndarray]:
    """The texel each point samples by the spec's formulas, and whether it
    is clear of texel edges and face ties by `margin` texels."""
    mv = MV_R.astype(np.float32).astype(float)
    eye = (mv @ OBJ.astype(float).T).T
    nf = (mv @ NRM.astype(float).T).T              # the inverse transpose of a rotation is itself
    if mode == C.GL_NORMAL_MAP_OES:
        str_ = nf
    else:
        u = eye / np.linalg.norm(eye, axis=1, keepdims=True)
        str_ = u - 2 * nf * np.sum(nf * u, axis=1, keepdims=True)
    str_ = (TEX_R.astype(np.float32).astype(float) @ str_.T).T
    want = np.zeros((MESH_N, 3), int)
    clear = np.zeros(MESH_N, bool)
    for k, r in enumerate(str_):
        f, s, t = _face_st(r)
        a = np.sort(np.abs(r))
        i, j = min(int(s * TEX_N), TEX_N - 1), min(int(t * TEX_N), TEX_N - 1)
        want[k] = [8 * i, 8 * j, 40 * f + 20]
        fs, ft = s * TEX_N % 1, t * TEX_N % 1
        clear[k] = a[2] - a[1] > 1e-2 and min(fs, 1 - fs, ft, 1 - ft) > 0.02
    return want, clear


@pytest.mark.parametrize("numeric", NUMERICS)
@pytest.mark.parametrize("mode", [C.GL_NORMAL_MAP_OES, C.GL_REFLECTION_MAP_OES])
def test_texgen_against_the_formulas(numeric: str, mode: int) -> None:
    got = _texgen_draw(_gles(numeric), mode)
    want, clear = _texgen_expected(mode)
    assert clear.sum() > 0.8 * MESH_N
    np.testing.assert_array_equal(got[clear, :3], want[clear])


@needs_mesa
def test_texgen_against_llvmpipe() -> None:
    """REFLECTION_MAP_OES only: llvmpipe's NORMAL_MAP_OES does not give the
    eye-space normal (a known deviation, docs/conformance.md)."""
    mode = C.GL_REFLECTION_MAP_OES
    _, clear = _texgen_expected(mode)
    ours = _texgen_draw(_gles("fixed"), mode)
    peer = _texgen_draw(lambda w, h: mesa.MesaContext(w, h), mode)
    np.testing.assert_array_equal(ours[clear], peer[clear])


# {====================================================================
# a reflective cube-mapped sphere

def _sphere(n_lat: int = 24, n_lon: int = 32) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    lat = np.linspace(0, np.pi, n_lat + 1)
    lon = np.linspace(0, 2 * np.pi, n_lon + 1)
    la, lo = np.meshgrid(lat, lon, indexing="ij")
    nrm = np.stack([np.sin(la) * np.cos(lo), np.cos(la), np.sin(la) * np.sin(lo)], -1).reshape(-1, 3)
    idx = []
    for i in range(n_lat):
        for j in range(n_lon):
            a, b = i * (n_lon + 1) + j, (i + 1) * (n_lon + 1) + j
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return (np.ascontiguousarray(nrm, np.float32), np.ascontiguousarray(nrm, np.float32),
            np.array(idx, np.uint16))


def _env_images(size: int = 32) -> list[np.ndarray]:
    """Six colours with a coarse checker of 4-texel squares, so that the
    mipmaps differ from level 0."""
    out = []
    jj, ii = np.mgrid[0:size, 0:size]
    dark = ((ii // 4 + jj // 4) % 2 == 1)[..., None]
    for f in range(6):
        img = np.empty((size, size, 4), np.uint8)
        img[..., :3] = np.where(dark, FACE_RGB[f] // 3, FACE_RGB[f])
        img[..., 3] = 255
        out.append(img)
    return out


def _sphere_scene(make, size: int = 128, lit: bool = False) -> np.ndarray:
    with make(size, size) as ctx:
        gl = ctx.gl
        _sphere_draw(gl, lit)
        return np.asarray(gl.glReadPixels(0, 0, size, size, C.GL_RGBA, C.GL_UNSIGNED_BYTE))


def _sphere_draw(gl, lit: bool) -> None:
    """The sphere with REFLECTION_MAP_OES into the six-colour mipmapped cube map."""
    pos, nrm, idx = _sphere()
    _load_cube(gl, _env_images(), mipmaps=True)
    gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
    gl.glTexParameteri(CUBE, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
    gl.glTexParameteri(CUBE, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
    gl.glTexParameteri(CUBE, C.GL_TEXTURE_WRAP_T, C.GL_CLAMP_TO_EDGE)
    gl.glEnable(CUBE)
    gl.glTexGeniOES(C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_GEN_MODE_OES, C.GL_REFLECTION_MAP_OES)
    gl.glEnable(C.GL_TEXTURE_GEN_STR_OES)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE if lit else C.GL_REPLACE)
    if lit:
        gl.glEnable(C.GL_LIGHTING)
        gl.glEnable(C.GL_LIGHT0)
        gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, np.array([1, 1, 1, 0], np.float32))
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glClearColor(0.1, 0.1, 0.1, 1)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glFrustumf(-0.6, 0.6, -0.6, 0.6, 1.5, 10)
    gl.glMatrixMode(C.GL_TEXTURE)
    gl.glRotatef(25, 0, 1, 0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glTranslatef(0, 0, -3.2)
    gl.glRotatef(30, 1, 0.3, 0)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, pos)
    gl.glNormalPointer(C.GL_FLOAT, 0, nrm)
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
    assert gl.glGetError() == C.GL_NO_ERROR


def _psnr(a: np.ndarray, b: np.ndarray) -> float:
    mse = np.mean((a[..., :3].astype(np.float64) - b[..., :3].astype(np.float64)) ** 2)
    return float("inf") if mse == 0 else 10 * np.log10(255.0**2 / mse)


@pytest.mark.parametrize("lit", [False, True])
def test_reflective_sphere_against_double(lit: bool) -> None:
    fixed = _sphere_scene(_gles("fixed"), lit=lit)
    double = _sphere_scene(_gles("double"), lit=lit)
    flt = _sphere_scene(_gles("float"), lit=lit)
    # the sphere covers a good share of the window, and every face shows
    assert (np.abs(fixed[..., :3].astype(int) - 26).sum(-1) > 30).mean() > 0.3
    assert _psnr(fixed, double) >= 30.0            # test_gallery's MIN_PSNR_FIXED
    assert _psnr(flt, double) >= 30.0


@needs_mesa
@pytest.mark.parametrize("lit", [False, True])
def test_reflective_sphere_against_llvmpipe(lit: bool) -> None:
    fixed = _sphere_scene(_gles("fixed"), lit=lit)
    peer = _sphere_scene(lambda w, h: mesa.MesaContext(w, h), lit=lit)
    assert _psnr(fixed, peer) >= 35.0


def test_threads_give_the_same_bytes() -> None:
    def run(threads: int) -> np.ndarray:
        def make(w: int, h: int) -> gles.Context:
            ctx = gles.Context(w, h, threads=threads)
            ctx.debug(64)          # every draw threaded, however small
            return ctx
        return _sphere_scene(make, lit=True)
    one = run(1)
    for n in (2, 3):
        np.testing.assert_array_equal(run(n), one)


# {====================================================================
# errors and state, worked from the extension text

def _err(gl) -> int:
    return int(gl.glGetError())


@pytest.mark.parametrize("profile", ["common", "common-lite"])
def test_initial_state_and_queries(profile: str) -> None:
    with gles.Context(4, 4, profile=profile) as ctx:
        gl = ctx.gl
        assert b"GL_OES_texture_cube_map" in gl.glGetString(C.GL_EXTENSIONS).split()
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_CUBE_MAP_OES) == 0
        assert gl.glGetIntegerv(C.GL_MAX_CUBE_MAP_TEXTURE_SIZE_OES) >= 16
        for cap in (CUBE, C.GL_TEXTURE_GEN_STR_OES):
            assert not gl.glIsEnabled(cap)
            assert not gl.glGetBooleanv(cap)
            gl.glEnable(cap)
            assert gl.glIsEnabled(cap) and gl.glGetBooleanv(cap) and gl.glGetIntegerv(cap) == 1
            assert gl.glGetFixedv(cap) == gl.glGetFixedv(C.GL_DITHER)     # as any enable
        # per unit
        gl.glActiveTexture(C.GL_TEXTURE1)
        assert not gl.glIsEnabled(CUBE) and not gl.glIsEnabled(C.GL_TEXTURE_GEN_STR_OES)
        # initially REFLECTION_MAP_OES, an enum in every form
        mode = (C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_GEN_MODE_OES)
        assert gl.glGetTexGenivOES(*mode) == C.GL_REFLECTION_MAP_OES
        assert gl.glGetTexGenxvOES(*mode) == C.GL_REFLECTION_MAP_OES
        gl.glTexGenxOES(*mode, C.GL_NORMAL_MAP_OES)
        assert gl.glGetTexGenivOES(*mode) == C.GL_NORMAL_MAP_OES
        gl.glActiveTexture(C.GL_TEXTURE0)
        assert gl.glGetTexGenivOES(*mode) == C.GL_REFLECTION_MAP_OES
        if profile == "common":
            gl.glTexGenfOES(*mode, float(C.GL_NORMAL_MAP_OES))
            assert gl.glGetTexGenfvOES(*mode) == float(C.GL_NORMAL_MAP_OES)
        else:
            assert not hasattr(gl, "glTexGenfOES") and not hasattr(gl, "glGetTexGenfvOES")
        assert _err(gl) == 0


def test_texgen_errors() -> None:
    with gles.Context(4, 4) as ctx:
        gl = ctx.gl
        mode = (C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_GEN_MODE_OES)
        # OBJECT_LINEAR, EYE_LINEAR and SPHERE_MAP are not supported; S/T/R/Q coords neither
        for v in (0x2401, 0x2400, 0x2402, C.GL_TEXTURE_2D):
            gl.glTexGeniOES(*mode, v)
            assert _err(gl) == C.GL_INVALID_ENUM
        gl.glTexGeniOES(0x2000, C.GL_TEXTURE_GEN_MODE_OES, C.GL_NORMAL_MAP_OES)    # GL_S
        assert _err(gl) == C.GL_INVALID_ENUM
        gl.glTexGeniOES(C.GL_TEXTURE_GEN_STR_OES, C.GL_TEXTURE_MIN_FILTER, C.GL_NORMAL_MAP_OES)
        assert _err(gl) == C.GL_INVALID_ENUM
        gl.glGetTexGenivOES(C.GL_TEXTURE_GEN_STR_OES, 0x2501)                     # OBJECT_PLANE
        assert _err(gl) == C.GL_INVALID_ENUM
        gl.glTexGenfOES(*mode, C.GL_NORMAL_MAP_OES + 0.5)
        assert _err(gl) == C.GL_INVALID_ENUM
        for cap in (0x0C60, 0x0C61, 0x0C62, 0x0C63):                               # TEXTURE_GEN_S..Q
            gl.glEnable(cap)
            assert _err(gl) == C.GL_INVALID_ENUM
        assert gl.glGetTexGenivOES(*mode) == C.GL_REFLECTION_MAP_OES


def test_binding_and_target_for_life() -> None:
    with gles.Context(4, 4) as ctx:
        gl = ctx.gl
        gl.glBindTexture(CUBE, 3)
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_CUBE_MAP_OES) == 3
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D) == 0
        assert gl.glIsTexture(3)
        gl.glBindTexture(C.GL_TEXTURE_2D, 3)
        assert _err(gl) == C.GL_INVALID_OPERATION
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D) == 0
        gl.glBindTexture(C.GL_TEXTURE_2D, 4)
        gl.glBindTexture(CUBE, 4)
        assert _err(gl) == C.GL_INVALID_OPERATION
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_CUBE_MAP_OES) == 3
        # the default objects: 0 on either target
        gl.glBindTexture(CUBE, 0)
        assert _err(gl) == 0 and gl.glGetIntegerv(C.GL_TEXTURE_BINDING_CUBE_MAP_OES) == 0
        gl.glBindTexture(0x806F, 1)                                               # TEXTURE_3D
        assert _err(gl) == C.GL_INVALID_ENUM
        # deleting a bound cube map binds 0
        gl.glBindTexture(CUBE, 3)
        gl.glDeleteTextures([3])
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_CUBE_MAP_OES) == 0
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D) == 4
        # a name deleted may come back as the other target
        gl.glBindTexture(C.GL_TEXTURE_2D, 3)
        assert _err(gl) == 0


def test_image_errors() -> None:
    img = np.zeros((8, 8, 4), np.uint8)
    with gles.Context(16, 16) as ctx:
        gl = ctx.gl
        gl.glBindTexture(CUBE, 1)
        # the cube target itself names no image
        gl.glTexImage2D(CUBE, 0, C.GL_RGBA, 8, 8, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        assert _err(gl) == C.GL_INVALID_ENUM
        # faces are square
        gl.glTexImage2D(FACES[2], 0, C.GL_RGBA, 8, 4, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        assert _err(gl) == C.GL_INVALID_VALUE
        gl.glCopyTexImage2D(FACES[0], 0, C.GL_RGBA, 0, 0, 4, 8, 0)
        assert _err(gl) == C.GL_INVALID_VALUE
        gl.glCompressedTexImage2D(FACES[0], 0, C.GL_ETC1_RGB8_OES, 8, 4, 0, 16, bytes(16))
        assert _err(gl) == C.GL_INVALID_VALUE
        pal = bytes(16 * 3 + 8 * 4 // 2)
        gl.glCompressedTexImage2D(FACES[0], 0, C.GL_PALETTE4_RGB8_OES, 8, 4, 0, len(pal), pal)
        assert _err(gl) == C.GL_INVALID_VALUE
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
        # the six faces take images, sub-images and copies; the 2D binding is untouched
        for f in FACES:
            gl.glTexImage2D(f, 0, C.GL_RGBA, 8, 8, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        gl.glTexSubImage2D(FACES[3], 0, 1, 1, 2, 2, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        gl.glCopyTexSubImage2D(FACES[4], 0, 0, 0, 0, 0, 4, 4)
        gl.glCopyTexImage2D(FACES[5], 0, C.GL_RGBA, 0, 0, 8, 8, 0)
        assert _err(gl) == 0
        gl.glTexSubImage2D(FACES[3], 0, 6, 6, 4, 4, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        assert _err(gl) == C.GL_INVALID_VALUE
        gl.glTexSubImage2D(CUBE, 0, 0, 0, 1, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        assert _err(gl) == C.GL_INVALID_ENUM
        gl.glCopyTexSubImage2D(CUBE, 0, 0, 0, 0, 0, 1, 1)
        assert _err(gl) == C.GL_INVALID_ENUM
        gl.glCompressedTexSubImage2D(FACES[0], 0, 0, 0, 4, 4, C.GL_ETC1_RGB8_OES, 8, bytes(8))
        assert _err(gl) == C.GL_INVALID_OPERATION
        # parameters: the cube target, not a face
        gl.glTexParameteri(FACES[0], C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR)
        assert _err(gl) == C.GL_INVALID_ENUM
        gl.glGetTexParameteriv(FACES[0], C.GL_TEXTURE_MIN_FILTER)
        assert _err(gl) == C.GL_INVALID_ENUM
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
        assert gl.glGetTexParameteriv(CUBE, C.GL_TEXTURE_WRAP_S) == C.GL_CLAMP_TO_EDGE
        assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S) == C.GL_REPEAT
        assert gl.glGetTexParameteriv(CUBE, C.GL_TEXTURE_MIN_FILTER) == C.GL_NEAREST
        gl.glGenerateMipmapOES(FACES[0])
        assert _err(gl) == C.GL_INVALID_ENUM


def _cube_colour(make, setup) -> np.ndarray:
    """The colour a pixel samples along +x (REPLACE), after setup(gl)."""
    with make(1, 1) as ctx:
        gl = ctx.gl
        gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glClearColor(0, 0, 0, 0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        setup(gl)
        gl.glColor4f(0.5, 0.5, 0.5, 0.5)
        gl.glMultiTexCoord4f(C.GL_TEXTURE0, 1, 0.1, 0.1, 1)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([-1, -1, 3, -1, -1, 3], np.float32))
        gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
        assert gl.glGetError() == C.GL_NO_ERROR
        return np.asarray(gl.glReadPixels(0, 0, 1, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE)).reshape(4)


def _faces(gl, sizes=(4,) * 6, fmts=(C.GL_RGBA,) * 6, levels: bool = False) -> None:
    for f, (n, fmt) in enumerate(zip(sizes, fmts)):
        lv = 0
        while True:
            img = np.zeros((n, n, 4 if fmt == C.GL_RGBA else 3), np.uint8)
            img[..., :3] = FACE_RGB[f]
            if fmt == C.GL_RGBA:
                img[..., 3] = 255
            gl.glTexImage2D(FACES[f], lv, fmt, n, n, 0, fmt, C.GL_UNSIGNED_BYTE, img)
            if not levels or n == 1:
                break
            n, lv = n // 2, lv + 1


@pytest.mark.parametrize("numeric", NUMERICS)
def test_completeness_and_precedence(numeric: str) -> None:
    make = _gles(numeric)
    red, untextured = [255, 0, 0, 255], [128, 128, 128, 128]
    tex2d = np.full((1, 1, 4), [0, 0, 255, 255], np.uint8)

    def base(gl) -> None:
        gl.glBindTexture(C.GL_TEXTURE_2D, 5)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, tex2d)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
        gl.glBindTexture(CUBE, 1)

    def with_(*steps):
        def setup(gl) -> None:
            base(gl)
            for s in steps:
                s(gl)
        return setup

    nearest = lambda gl: gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)  # noqa: E731
    on = lambda gl: gl.glEnable(CUBE)                                                      # noqa: E731
    on2d = lambda gl: gl.glEnable(C.GL_TEXTURE_2D)                                         # noqa: E731
    # complete (NEAREST), enabled: +x's colour; with TEXTURE_2D also enabled, the cube map wins
    assert list(_cube_colour(make, with_(_faces, nearest, on))) == red
    assert list(_cube_colour(make, with_(_faces, nearest, on, on2d))) == red
    # only TEXTURE_2D enabled: the 2D texture
    assert list(_cube_colour(make, with_(_faces, nearest, on2d))) == [0, 0, 255, 255]
    # the default filter needs mipmaps: incomplete, as if texturing were off (not the 2D texture)
    assert list(_cube_colour(make, with_(_faces, on, on2d))) == untextured
    assert list(_cube_colour(make, with_(lambda gl: _faces(gl, levels=True), on))) == red
    # faces of different sizes or formats, or a face missing: incomplete
    assert list(_cube_colour(make, with_(lambda gl: _faces(gl, sizes=(4, 4, 4, 2, 4, 4)), nearest, on))) \
        == untextured
    assert list(_cube_colour(make, with_(lambda gl: _faces(gl, fmts=(C.GL_RGBA,) * 5 + (C.GL_RGB,)), nearest,
                                         on))) == untextured
    assert list(_cube_colour(make, with_(lambda gl: _faces(gl, sizes=(4,) * 5 + (0,)), nearest, on))) \
        == untextured
    # GENERATE_MIPMAP and GenerateMipmapOES make every face mipmap complete
    gen = lambda gl: gl.glTexParameteri(CUBE, C.GL_GENERATE_MIPMAP, 1)                    # noqa: E731
    assert list(_cube_colour(make, with_(gen, _faces, on))) == red
    assert list(_cube_colour(make, with_(_faces, lambda gl: gl.glGenerateMipmapOES(CUBE), on))) == red


def test_generate_mipmap_needs_cube_complete() -> None:
    with gles.Context(4, 4) as ctx:
        gl = ctx.gl
        gl.glBindTexture(CUBE, 1)
        _faces(gl, sizes=(4, 4, 4, 4, 4, 2))
        gl.glGenerateMipmapOES(CUBE)
        assert _err(gl) == C.GL_INVALID_OPERATION


def test_render_to_a_face() -> None:
    """A face attached to a framebuffer object takes a clear; that face then samples as drawn."""
    with gles.Context(1, 1) as ctx:
        gl = ctx.gl
        gl.glBindTexture(CUBE, 1)
        _faces(gl)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
        fb = gl.glGenFramebuffersOES(1)
        gl.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, fb)
        att = (C.GL_FRAMEBUFFER_OES, C.GL_COLOR_ATTACHMENT0_OES)
        gl.glFramebufferTexture2DOES(*att, C.GL_TEXTURE_2D, 1, 0)
        assert _err(gl) == C.GL_INVALID_OPERATION                 # a cube map is no 2D texture
        gl.glBindTexture(C.GL_TEXTURE_2D, 2)
        gl.glFramebufferTexture2DOES(*att, FACES[0], 2, 0)
        assert _err(gl) == C.GL_INVALID_OPERATION                 # a 2D texture has no faces
        gl.glFramebufferTexture2DOES(*att, FACES[0], 1, 0)
        assert _err(gl) == 0
        assert gl.glGetFramebufferAttachmentParameterivOES(
            *att, C.GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_OES) == FACES[0]
        assert gl.glCheckFramebufferStatusOES(C.GL_FRAMEBUFFER_OES) == C.GL_FRAMEBUFFER_COMPLETE_OES
        gl.glClearColor(0, 1, 0, 1)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, 0)
        gl.glEnable(CUBE)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glMultiTexCoord4f(C.GL_TEXTURE0, 1, 0.1, 0.1, 1)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array([-1, -1, 3, -1, -1, 3], np.float32))
        gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
        assert list(np.asarray(gl.glReadPixels(0, 0, 1, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE)).ravel()) \
            == [0, 255, 0, 255]
        # deleting the cube map detaches its face
        gl.glDeleteTextures([1])
        gl.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, fb)
        assert gl.glGetFramebufferAttachmentParameterivOES(
            *att, C.GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES) == C.GL_NONE_OES


# {====================================================================
# level of detail on a face: linear face coordinates, exact derivatives

LOD_N = 64                                   # face size
LOD_COLOURS = np.array([[40 * k, 255 - 40 * k, (97 * k) % 256, 255] for k in range(7)], np.uint8)


def _lod_draw(numeric: str, minf: int, face: int, s0: float, s1: float) -> np.ndarray:
    """A 16x4 window whose columns run the face coordinate s' from s0 to s1
    (t' from 0.4 to 0.45 up the rows) on `face` (+x or -y), each level of
    each face one solid colour."""
    w, h = 16, 4
    with gles.Context(w, h, numeric=numeric) as ctx:
        gl = ctx.gl
        gl.glBindTexture(CUBE, 1)
        for f in range(6):
            n, lv = LOD_N, 0
            while n >= 1:
                img = np.broadcast_to(LOD_COLOURS[lv], (n, n, 4)).copy()
                gl.glTexImage2D(FACES[f], lv, C.GL_RGBA, n, n, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
                n, lv = n // 2, lv + 1
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, minf)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
        gl.glEnable(CUBE)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glOrthof(0, w, 0, h, -1, 1)
        corners = [(0, 0, s0, 0.4), (w, 0, s1, 0.4), (0, h, s0, 0.45), (w, h, s1, 0.45)]
        pos, tex = [], []
        for x, y, s, t in corners:
            sc, tc = 2 * s - 1, 2 * t - 1
            # invert the table for +x (sc = -rz, tc = -ry) or -y (sc = rx, tc = -rz), |ma| = 1
            tex.append([1, -tc, -sc] if face == 0 else [sc, -1, -tc])
            pos.append([x, y])
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glVertexPointer(2, C.GL_FLOAT, 0, np.array(pos, np.float32))
        gl.glTexCoordPointer(3, C.GL_FLOAT, 0, np.array(tex, np.float32))
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
        assert gl.glGetError() == C.GL_NO_ERROR
        return np.asarray(gl.glReadPixels(0, 0, w, h, C.GL_RGBA, C.GL_UNSIGNED_BYTE)).astype(float)


@pytest.mark.parametrize("numeric", NUMERICS)
@pytest.mark.parametrize("minf", [C.GL_NEAREST, C.GL_LINEAR, C.GL_NEAREST_MIPMAP_NEAREST,
                                  C.GL_LINEAR_MIPMAP_NEAREST, C.GL_NEAREST_MIPMAP_LINEAR,
                                  C.GL_LINEAR_MIPMAP_LINEAR])
@pytest.mark.parametrize("face, s0, s1", [(0, 0.05, 0.75), (3, 0.1, 0.95)])
def test_level_of_detail_on_a_face(numeric: str, minf: int, face: int, s0: float, s1: float) -> None:
    """§3.7.7 with rho = |ds'/dx| * size (the largest derivative here)."""
    got = _lod_draw(numeric, minf, face, s0, s1)
    lam = np.log2(LOD_N * (s1 - s0) / 16)
    cols = LOD_COLOURS.astype(float)
    if minf in (C.GL_NEAREST, C.GL_LINEAR):
        want = cols[0]
    elif minf in (C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_NEAREST):
        want = cols[int(np.ceil(lam + 0.5)) - 1]
    else:
        d, f = int(np.floor(lam)), lam - np.floor(lam)
        want = (1 - f) * cols[d] + f * cols[d + 1]
    assert np.abs(got - want).max() <= 2.0


@pytest.mark.parametrize("numeric", NUMERICS)
def test_batches_match_the_per_vertex_reference(numeric: str) -> None:
    """Texture coordinate generation in the vertex batches gives the per-vertex path's bits."""
    def make(debug: int):
        def m(w: int, h: int) -> gles.Context:
            ctx = gles.Context(w, h, numeric=numeric)
            ctx.debug(debug)
            return ctx
        return m
    for lit in (False, True):
        np.testing.assert_array_equal(_sphere_scene(make(8), 64, lit), _sphere_scene(make(0), 64, lit))


@pytest.mark.parametrize("numeric", NUMERICS)
def test_trace_replays_byte_identical(numeric: str) -> None:
    from gles import trace as T

    t = gles.trace(lambda gl, w, h: _sphere_draw(gl, True), 64, 64, numeric=numeric)
    np.testing.assert_array_equal(t.image[::-1], _sphere_scene(_gles(numeric), 64, True))
    assert T.replay(t, raw=True) == t.color_buffer


@pytest.mark.parametrize("numeric", NUMERICS)
def test_extreme_directions_draw_without_harm(numeric: str) -> None:
    """Zero, huge, infinite and NaN directions, and a triangle whose corners point into
    opposite faces, through every min filter: defined pixels, no error."""
    bad = [[0, 0, 0], [1e30, -1e30, 3], [np.inf, 1, 1], [np.nan, 1, 2], [1, -1, 1], [-1, 1, -1],
           [3e4, 3e4, -3e4], [1e-9, 0, -1e-9], [0, 1e-30, 0]]
    with gles.Context(16, 16, numeric=numeric, range_check="off") as ctx:
        gl = ctx.gl
        _load_cube(gl, _env_images(8), mipmaps=True)
        gl.glEnable(CUBE)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        rng = np.random.default_rng(3)
        for minf in (C.GL_NEAREST, C.GL_LINEAR, C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_NEAREST,
                     C.GL_NEAREST_MIPMAP_LINEAR, C.GL_LINEAR_MIPMAP_LINEAR):
            gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, minf)
            for wrap in (C.GL_REPEAT, C.GL_MIRRORED_REPEAT_OES):
                gl.glTexParameteri(CUBE, C.GL_TEXTURE_WRAP_S, wrap)
                tc = np.array([bad[i] + [1.0] for i in rng.integers(0, len(bad), 6)], np.float32)
                tc[:, 3] = rng.choice([1.0, -1.0, 0.0], 6)
                gl.glTexCoordPointer(4, C.GL_FLOAT, 0, tc)
                gl.glVertexPointer(2, C.GL_FLOAT, 0, rng.uniform(-1.5, 1.5, (6, 2)).astype(np.float32))
                gl.glDrawArrays(C.GL_TRIANGLES, 0, 6)
                gl.glDrawArrays(C.GL_LINES, 0, 6)
                gl.glDrawArrays(C.GL_POINTS, 0, 6)
        gl.glTexParameteriv(CUBE, C.GL_TEXTURE_CROP_RECT_OES, [0, 0, 8, 8])
        gl.glDrawTexiOES(0, 0, 0, 16, 16)
        assert gl.glGetError() == C.GL_NO_ERROR


@pytest.mark.parametrize("numeric", NUMERICS)
def test_compressed_faces(numeric: str) -> None:
    """ETC1 faces (each one block of base colour (15, 0, 0) x 17, table 0, every texel's
    modifier +2: (255, 2, 2)) and PALETTE4_RGB8 faces (index 0 into each face's palette
    colour) make complete cube maps; ETC1 faces beside an RGB one do not (one internal
    format for all six)."""
    etc1 = bytes([0xF0, 0x00, 0x00, 0x00, 0, 0, 0, 0])

    def etc1_faces(mixed: bool):
        def setup(gl) -> None:
            gl.glBindTexture(CUBE, 1)
            gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
            gl.glTexParameteri(CUBE, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
            for f in FACES:
                gl.glCompressedTexImage2D(f, 0, C.GL_ETC1_RGB8_OES, 4, 4, 0, 8, etc1)
            if mixed:
                gl.glTexImage2D(FACES[5], 0, C.GL_RGB, 4, 4, 0, C.GL_RGB, C.GL_UNSIGNED_BYTE, bytes(48))
            gl.glEnable(CUBE)
        return setup

    def paletted(gl) -> None:
        gl.glBindTexture(CUBE, 1)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
        gl.glTexParameteri(CUBE, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
        for f in range(6):
            palette = np.zeros((16, 3), np.uint8)
            palette[0] = FACE_RGB[f]
            data = palette.tobytes() + bytes(8)
            gl.glCompressedTexImage2D(FACES[f], 0, C.GL_PALETTE4_RGB8_OES, 4, 4, 0, len(data), data)
        gl.glEnable(CUBE)

    make = _gles(numeric)
    # RGB textures: REPLACE keeps the fragment's alpha (0.5)
    assert list(_cube_colour(make, etc1_faces(False))) == [255, 2, 2, 128]
    assert list(_cube_colour(make, etc1_faces(True))) == [128, 128, 128, 128]
    assert list(_cube_colour(make, paletted)) == list(FACE_RGB[0]) + [128]
