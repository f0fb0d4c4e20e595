"""The C ABI: C programs built against libGLESv1_CM and libEGL of every build.

Each program under tests/c/ is compiled with the system compiler against the
libraries and headers `gles.cabi` points at, renders into a pbuffer and
writes the pixels it reads back (egl_errors.c and threads.c check EGL's
errors and its per-thread current context themselves). Its image must be byte-identical to the
same calls made through the Python binding on the same numeric build and
profile (the two share one compiled core, so any difference is a
conversion the C entry points make differently from gl.py), and, on the
double build, within the tolerances below of the same program built
against the system's Mesa libraries.
"""

from __future__ import annotations

import ctypes
import os
import shutil
import subprocess
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import gles
from gles import cabi
from gles import constants as C

CDIR = Path(__file__).resolve().parent / "c"
W = H = 64
CC = shutil.which(os.environ.get("CC", "cc"))
CFLAGS = ["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-pthread"]

pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler")


def FX(v: float) -> int:
    """A 16.16 constant, as the programs' FX() macro (truncation toward zero)."""
    return int(v * 65536.0)


# {====================================================================
# the programs' calls through the Python binding (each mirrors tests/c/<name>.c)

def triangle(gl: Any) -> None:
    vertices = np.array([FX(-0.75), FX(-0.625), 0, FX(0.8125), FX(-0.25), 0, FX(-0.125), FX(0.875), 0],
                        dtype=np.int32)
    colors = np.array([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255], dtype=np.uint8)
    gl.glClearColorx(0, 0, FX(0.25), FX(1))
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glRotatex(FX(30), 0, 0, FX(1))
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, C.GL_FIXED, 0, vertices)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)


def texquad(gl: Any) -> None:
    y, x = np.mgrid[0:16, 0:16]
    src = np.zeros((16, 16, 4), dtype=np.int64)
    src[..., 0] = x * 17
    src[..., 1] = y * 17
    src[..., 2] = 255 - (x + y) * 8
    src[..., 3] = 255
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    level, size = 0, 16
    while size >= 1:
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, C.GL_RGBA, size, size, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                        src.astype(np.uint8))
        if size > 1:
            sums = src[0::2, 0::2] + src[0::2, 1::2] + src[1::2, 0::2] + src[1::2, 1::2]
            src = (sums + 2) // 4
        level, size = level + 1, size // 2
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
    gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, float(C.GL_REPEAT))
    gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, float(C.GL_REPEAT))
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glClearColor(0.25, 0.25, 0.25, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glFrustumf(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glTranslatef(0.0, 0.0, -2.5)
    gl.glRotatef(-60.0, 1.0, 0.0, 0.0)
    gl.glColor4f(1.0, 0.875, 0.75, 1.0)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, np.array([-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0], np.float32))
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.array([0, 0, 2, 0, 0, 2, 2, 2], np.float32))
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


def litmesh(gl: Any) -> None:
    n = 9
    j, i = np.mgrid[0:n, 0:n]
    x = (i - 4).astype(np.float32) * np.float32(0.25)
    y = (j - 4).astype(np.float32) * np.float32(0.25)
    vertex = np.zeros((n, n, 6), dtype=np.float32)
    vertex[..., 0], vertex[..., 1] = x, y
    vertex[..., 2] = (x * x + y * y) * np.float32(0.25)
    vertex[..., 3], vertex[..., 4], vertex[..., 5] = -x * np.float32(0.5), -y * np.float32(0.5), 1.0
    index = []
    for jj in range(n - 1):
        for ii in range(n - 1):
            a = jj * n + ii
            b, c = a + 1, a + n
            d = c + 1
            index += [a, b, d, a, d, c]
    indices = np.array(index, dtype=np.uint16)
    buffers = gl.glGenBuffers(2)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, int(buffers[0]))
    gl.glBufferData(C.GL_ARRAY_BUFFER, vertex.nbytes, vertex, C.GL_STATIC_DRAW)
    gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, int(buffers[1]))
    gl.glBufferData(C.GL_ELEMENT_ARRAY_BUFFER, indices.nbytes, indices, C.GL_STATIC_DRAW)
    gl.glClearColor(0.0, 0.0, 0.0, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    for cap in (C.GL_DEPTH_TEST, C.GL_LIGHTING, C.GL_LIGHT0, C.GL_LIGHT1, C.GL_NORMALIZE):
        gl.glEnable(cap)
    white = [1.0, 1.0, 1.0, 1.0]
    gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, [1.0, 1.0, 2.0, 0.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, white)
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, white)
    gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, [-1.0, 0.5, 1.0, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [0.25, 0.5, 1.0, 1.0])
    gl.glLightf(C.GL_LIGHT1, C.GL_LINEAR_ATTENUATION, 0.5)
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [0.125, 0.125, 0.125, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_DIFFUSE, [0.75, 0.5, 0.25, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, white)
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 24.0)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glFrustumf(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glTranslatef(0.0, 0.0, -3.0)
    gl.glRotatef(-50.0, 1.0, 0.0, 0.0)
    gl.glRotatef(20.0, 0.0, 0.0, 1.0)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 24, 0)
    gl.glNormalPointer(C.GL_FLOAT, 24, 12)
    gl.glDrawElements(C.GL_TRIANGLES, indices.size, C.GL_UNSIGNED_SHORT, 0)
    gl.glDeleteBuffers(2, buffers)


def paletted(gl: Any) -> None:
    data = np.zeros(16 * 4 + 32 + 8 + 2 + 1, dtype=np.uint8)
    for e in range(16):
        data[e * 4: e * 4 + 4] = [e * 17, 255 - e * 17, (e & 3) * 85, 255]
    nibbles = []
    for level, size in enumerate((8, 4, 2, 1)):
        level_nibbles = [(t % size + 2 * (t // size) + 5 * level) & 15 for t in range(size * size)]
        if len(level_nibbles) % 2:
            level_nibbles.append(0)
        nibbles += level_nibbles
    packed = [(nibbles[k] << 4) | nibbles[k + 1] for k in range(0, len(nibbles), 2)]
    data[64:] = packed
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, -3, C.GL_PALETTE4_RGBA8_OES, 8, 8, 0, data.size, data)
    gl.glTexParameterx(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    gl.glTexParameterx(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvx(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glClearColorx(FX(0.5), 0, FX(0.5), FX(1))
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glOrthox(0, FX(W), 0, FX(H), FX(-1), FX(1))
    gl.glMatrixMode(C.GL_MODELVIEW)
    vertices = np.array([0, 0, 64, 0, 0, 64, 64, 64, 0, 0, 32, 0, 0, 32, 32, 32,
                         32, 0, 48, 0, 32, 16, 48, 16, 48, 0, 56, 0, 48, 8, 56, 8], dtype=np.int16)
    texcoords = np.array([0, 0, 1, 0, 0, 1, 1, 1] + [0, 0, 8, 0, 0, 8, 8, 8] * 3, dtype=np.int8)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glVertexPointer(2, C.GL_SHORT, 0, vertices)
    gl.glTexCoordPointer(2, C.GL_BYTE, 0, texcoords)
    for q in range(4):
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, q * 4, 4)


def matrix_palette(gl: Any) -> None:
    assert b"GL_OES_matrix_palette" in gl.glGetString(C.GL_EXTENSIONS).split()
    gl.glClearColorx(0, 0, 0, FX(1))
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glTranslatex(FX(-0.25), 0, 0)
    gl.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
    gl.glCurrentPaletteMatrixOES(0)
    gl.glLoadPaletteFromModelViewMatrixOES()
    gl.glCurrentPaletteMatrixOES(1)
    gl.glLoadIdentity()
    gl.glTranslatex(0, FX(0.25), 0)
    gl.glRotatex(FX(40), 0, 0, FX(1))
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    vertices = np.zeros(20, np.int32)
    weights = np.zeros(20, np.int32)
    indices = np.zeros(20, np.uint8)
    colors = np.zeros(40, np.uint8)
    for i in range(5):
        for j in range(2):
            v = i * 2 + j
            vertices[v * 2] = FX(-0.625) + i * FX(0.3125)
            vertices[v * 2 + 1] = FX(0.125) if j else FX(-0.375)
            weights[v * 2] = FX(1) - i * FX(0.25)
            weights[v * 2 + 1] = i * FX(0.25)
            indices[v * 2], indices[v * 2 + 1] = 0, 1
            colors[v * 4: v * 4 + 4] = [255 - i * 60, 255 if j else 64, i * 60, 255]
    for array in (C.GL_VERTEX_ARRAY, C.GL_COLOR_ARRAY, C.GL_MATRIX_INDEX_ARRAY_OES, C.GL_WEIGHT_ARRAY_OES):
        gl.glEnableClientState(array)
    gl.glVertexPointer(2, C.GL_FIXED, 0, vertices)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glMatrixIndexPointerOES(2, C.GL_UNSIGNED_BYTE, 0, indices)
    gl.glWeightPointerOES(2, C.GL_FIXED, 0, weights)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 10)


# name: (Python mirror, depth bits, stencil bits, profiles it runs on,
#        largest share of pixels more than 8 off Mesa's, largest difference on the rest)
PROGRAMS: dict[str, tuple[Callable[[Any], None], int, int, tuple[str, ...], float]] = {
    "triangle": (triangle, 0, 0, ("common", "common-lite"), 0.0),
    # trilinear LOD: llvmpipe's per-quad approximation (measured: 0 pixels > 8, max 7)
    "texquad": (texquad, 16, 0, ("common",), 0.0),
    # specular highlights: pow and per-vertex rounding (measured 0.73% > 8, max 20)
    "litmesh": (litmesh, 24, 0, ("common",), 0.01),
    "paletted": (paletted, 0, 0, ("common", "common-lite"), 0.0),
    # Mesa has no OES_matrix_palette: no peer comparison
    "matrix_palette": (matrix_palette, 0, 0, ("common", "common-lite"), 0.0),
}
CASES = [(name, numeric, profile) for name, spec in PROGRAMS.items()
         for numeric in cabi.NUMERICS for profile in spec[3]]


# {====================================================================
# building and running

def _compile(source: Path, out: Path, include: list[str], libdir: str | None) -> None:
    cmd = [CC, *CFLAGS, *include, str(source), "-o", str(out)]
    cmd += ([f"-L{libdir}"] if libdir else []) + ["-lGLESv1_CM", "-lEGL"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    assert proc.returncode == 0, f"{' '.join(cmd)}\n{proc.stderr}"


@pytest.fixture(scope="module")
def binaries(tmp_path_factory: pytest.TempPathFactory) -> Callable[[str, str], Path]:
    """A program compiled against the headers and libraries of one profile
    (the link-time library only names the sonames; the numeric build is the
    run-time LD_LIBRARY_PATH's)."""
    root = tmp_path_factory.mktemp("cabi")
    cache: dict[tuple[str, str], Path] = {}

    def get(name: str, profile: str) -> Path:
        key = (name, profile)
        if key not in cache:
            out = root / f"{name}-{profile}"
            _compile(CDIR / f"{name}.c", out, [f"-I{cabi.include_dir()}"], str(cabi.libdir("fixed", profile)))
            cache[key] = out
        return cache[key]

    return get


def _run(binary: Path, out: Path, env: dict[str, str]) -> subprocess.CompletedProcess:
    return subprocess.run([str(binary), str(out)], capture_output=True, text=True, env={**os.environ, **env},
                          timeout=120)


def run_ours(binary: Path, out: Path, numeric: str, profile: str) -> np.ndarray:
    proc = _run(binary, out, {"LD_LIBRARY_PATH": str(cabi.libdir(numeric, profile))})
    assert proc.returncode == 0, proc.stderr
    return np.fromfile(out, dtype=np.uint8).reshape(H, W, 4)


def run_python(name: str, numeric: str, profile: str) -> np.ndarray:
    fn, depth, stencil, _, _ = PROGRAMS[name]
    ctx = gles.Context(W, H, numeric=numeric, profile=profile, depth=depth, stencil=stencil,
                       range_check="off")
    fn(ctx.gl)
    px = ctx.gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    assert ctx.gl.glGetError() == C.GL_NO_ERROR
    return px


@pytest.mark.parametrize("name,numeric,profile", CASES)
def test_c_program_matches_python_binding(binaries: Callable[[str, str], Path], tmp_path: Path, name: str,
                                          numeric: str, profile: str) -> None:
    c_image = run_ours(binaries(name, profile), tmp_path / "c.raw", numeric, profile)
    py_image = run_python(name, numeric, profile)
    assert np.array_equal(c_image, py_image), \
        f"{int((c_image != py_image).any(axis=2).sum())} pixels differ between C and Python"
    # the scene draws something: more than the clear colour
    assert len(np.unique(c_image.reshape(-1, 4), axis=0)) >= 8


@pytest.mark.parametrize("name", list(PROGRAMS))
def test_c_program_threads(binaries: Callable[[str, str], Path], tmp_path: Path, name: str) -> None:
    """GLES_THREADS=N gives a C program's contexts N threads, and the same bytes."""
    binary = binaries(name, "common")
    images = []
    for threads in ("", "2", "3"):
        proc = _run(binary, tmp_path / f"t{threads}.raw",
                    {"LD_LIBRARY_PATH": str(cabi.libdir("fixed", "common")), "GLES_THREADS": threads})
        assert proc.returncode == 0, proc.stderr
        images.append(np.fromfile(tmp_path / f"t{threads}.raw", dtype=np.uint8))
    assert np.array_equal(images[0], images[1]) and np.array_equal(images[0], images[2])


def _mesa_env() -> dict[str, str]:
    return {"GALLIUM_DRIVER": "llvmpipe", "LIBGL_ALWAYS_SOFTWARE": "1", "LP_NUM_THREADS": "1"}


def _system_gles() -> str | None:
    """Why the programs cannot be built against the system's EGL and GLES 1, or None."""
    from gles import mesa

    reason = mesa.available("llvmpipe")
    if reason is not None:
        return f"Mesa llvmpipe unavailable: {reason}"
    if not Path("/usr/include/GLES/gl.h").is_file():
        return "no system GLES/gl.h"
    return None


@pytest.mark.parametrize("name", [n for n in PROGRAMS if n != "matrix_palette"])
def test_c_program_agrees_with_mesa(binaries: Callable[[str, str], Path], tmp_path: Path, name: str) -> None:
    reason = _system_gles()
    if reason:
        pytest.skip(reason)
    ours = run_ours(binaries(name, "common"), tmp_path / "ours.raw", "double", "common").astype(int)
    mesa_bin = tmp_path / "mesa"
    _compile(CDIR / f"{name}.c", mesa_bin, [], None)
    proc = _run(mesa_bin, tmp_path / "mesa.raw", _mesa_env())
    assert proc.returncode == 0, proc.stderr
    peer = np.fromfile(tmp_path / "mesa.raw", dtype=np.uint8).reshape(H, W, 4).astype(int)
    diff = np.abs(ours - peer).max(axis=2)
    share = float((diff > 8).mean())
    assert share <= PROGRAMS[name][4], f"{share:.2%} of the pixels differ from Mesa by more than 8"


@pytest.mark.parametrize("numeric", cabi.NUMERICS)
@pytest.mark.parametrize("profile", cabi.PROFILES)
def test_egl_error_walk(binaries: Callable[[str, str], Path], tmp_path: Path, numeric: str,
                        profile: str) -> None:
    env = {"LD_LIBRARY_PATH": str(cabi.libdir(numeric, profile))}
    proc = _run(binaries("egl_errors", profile), tmp_path / "unused", env)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.strip() == "all checks passed"


@pytest.mark.parametrize("numeric", cabi.NUMERICS)
def test_current_context_is_per_thread(binaries: Callable[[str, str], Path], tmp_path: Path,
                                       numeric: str) -> None:
    """Two threads render at once, each on its own context (tests/c/threads.c);
    a context current in one thread is EGL_BAD_ACCESS in another."""
    for profile in cabi.PROFILES:
        env = {"LD_LIBRARY_PATH": str(cabi.libdir(numeric, profile))}
        proc = _run(binaries("threads", profile), tmp_path / "unused", env)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        assert proc.stdout.strip() == "all checks passed"


# {====================================================================
# the libraries themselves

def test_common_lite_has_no_float_commands() -> None:
    lite = ctypes.CDLL(str(cabi.library("GLESv1_CM", "fixed", "common-lite")))
    common = ctypes.CDLL(str(cabi.library("GLESv1_CM", "fixed", "common")))
    from gles.gl import FLOAT_COMMANDS

    for name in ("glClearColor", "glFrustumf", "glGetFloatv", "glDrawTexfOES"):
        assert not hasattr(lite, name) and hasattr(common, name), name
    assert hasattr(lite, "glClearColorx") and hasattr(lite, "glDrawTexxOES")
    # the Python binding's float commands are exactly the ones the C library leaves out
    for name in FLOAT_COMMANDS:
        assert hasattr(common, name) and not hasattr(lite, name), name


def test_every_es11_command_is_exported() -> None:
    names = []
    for line in (cabi.include_dir() / "GLES" / "gl.h").read_text().splitlines():
        if line.startswith("GL_API "):
            names.append(line.split("GL_APIENTRY")[1].split("(")[0].strip())
    assert len(names) == 145          # ES 1.1: 106 in both profiles, 39 in Common only
    common = ctypes.CDLL(str(cabi.library("GLESv1_CM", "float", "common")))
    for name in names:
        assert hasattr(common, name), name


def test_get_proc_address_finds_gl_and_egl_entry_points() -> None:
    for profile in cabi.PROFILES:
        egl = ctypes.CDLL(str(cabi.library("EGL", "fixed", profile)))
        gl = ctypes.CDLL(str(cabi.library("GLESv1_CM", "fixed", profile)))
        egl.eglGetProcAddress.restype = ctypes.c_void_p
        egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
        for name in ("glWeightPointerOES", "glDrawTexxOES", "glQueryMatrixxOES", "glEnable"):
            addr = egl.eglGetProcAddress(name.encode())
            assert addr == ctypes.cast(getattr(gl, name), ctypes.c_void_p).value, name
        assert egl.eglGetProcAddress(b"eglGetPlatformDisplayEXT")
        assert egl.eglGetProcAddress(b"glNoSuchCommand") is None
        float_cmd = egl.eglGetProcAddress(b"glClearColor")
        assert (float_cmd is not None) == (profile == "common")


def test_one_compiled_core_per_build() -> None:
    """The cffi module and the C libraries need the same core library, and
    the core library holds the only copy of the core's code."""
    lib = cabi.libdir("fixed", "common").parent.parent
    for numeric in cabi.NUMERICS:
        core = lib / f"libgles_{numeric}.so"
        assert core.is_file()
        for path in (Path(gles.__file__).parent.glob(f"_core_{numeric}*.so")):
            assert f"libgles_{numeric}.so" in _needed(path)
            assert "gles_DrawArrays" not in _defined(path)
        for profile in cabi.PROFILES:
            for name in ("GLESv1_CM", "EGL"):
                path = cabi.library(name, numeric, profile)
                assert f"libgles_{numeric}.so" in _needed(path)
                assert "gles_DrawArrays" not in _defined(path)
        assert "gles_DrawArrays" in _defined(core)


def _readelf(path: Path, *args: str) -> str:
    tool = shutil.which("readelf")
    if tool is None:
        pytest.skip("no readelf")
    return subprocess.run([tool, *args, str(path)], capture_output=True, text=True, check=True).stdout


def _needed(path: Path) -> str:
    return _readelf(path, "-d")


def _defined(path: Path) -> set[str]:
    out = _readelf(path, "--dyn-syms", "-W")
    names = set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 8 and parts[6] != "UND":
            names.add(parts[7].split("@")[0])
    return names


def test_libdir_command_and_pkg_config(tmp_path: Path) -> None:
    import sys

    out = subprocess.run([sys.executable, "-m", "gles", "libdir", "--numeric", "double", "--profile",
                          "common-lite"], capture_output=True, text=True, check=True).stdout.strip()
    assert Path(out) == cabi.libdir("double", "common-lite")
    pkg = shutil.which("pkg-config") or shutil.which("pkgconf")
    if pkg is None:
        pytest.skip("no pkg-config")
    env = {**os.environ, "PKG_CONFIG_PATH": out}
    flags = subprocess.run([pkg, "--cflags", "--libs", "glesv1_cm", "egl"], capture_output=True, text=True,
                           env=env, check=True).stdout.split()
    assert f"-L{out}" in flags and "-lGLESv1_CM" in flags and "-lEGL" in flags
    include = [f for f in flags if f.startswith("-I")]
    assert include and Path(include[0][2:]).resolve() == cabi.include_dir().resolve()


def test_readme_lines_build_and_run_a_program(tmp_path: Path) -> None:
    """The README's two shell lines, as a user types them, on examples/triangle.c
    (the headers from the system where it has them, else from
    `python -m gles libdir --include`); its picture is the Python binding's."""
    import sys

    libdir = subprocess.run([sys.executable, "-m", "gles", "libdir"], capture_output=True, text=True,
                            check=True).stdout.strip()
    include = [] if Path("/usr/include/GLES/gl.h").is_file() else [f"-I{cabi.include_dir()}"]
    source = CDIR.parent.parent / "examples" / "triangle.c"
    subprocess.run([CC, str(source), *include, f"-L{libdir}", "-lGLESv1_CM", "-lEGL", "-o", "triangle"],
                   check=True, cwd=tmp_path)
    subprocess.run(["./triangle"], check=True, cwd=tmp_path, env={**os.environ, "LD_LIBRARY_PATH": libdir},
                   timeout=60)
    ppm = (tmp_path / "triangle.ppm").read_bytes()
    header = b"P6 128 128 255\n"
    assert ppm.startswith(header)
    image = np.frombuffer(ppm[len(header):], dtype=np.uint8).reshape(128, 128, 3)

    ctx = gles.Context(128, 128, depth=0, stencil=0, range_check="off")
    gl = ctx.gl
    gl.glClearColorx(0, 0, 16384, 65536)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(2, C.GL_FIXED, 0, np.array([-52428, -45875, 52428, -26214, 0, 55705], np.int32))
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0,
                      np.array([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255], np.uint8))
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    assert np.array_equal(image, ctx.image()[..., :3])
    # a triangle over the clear colour: its three corners' colours are there
    assert (image == [0, 0, 64]).all(axis=2).mean() > 0.4


def test_failed_queries_write_nothing() -> None:
    """A query that records a GL error leaves its output untouched (§2.5),
    and GetString of an unknown name is NULL with INVALID_ENUM."""
    from gles import mesa

    egl, lib = cabi.library("EGL", "fixed", "common"), cabi.library("GLESv1_CM", "fixed", "common")
    ctx = mesa.LibraryContext(8, 8, str(egl), str(lib))
    try:
        ctx.make_current()
        gl = ctypes.CDLL(str(lib))
        gl.glGetError.restype = ctypes.c_uint
        gl.glGetString.restype = ctypes.c_char_p
        assert gl.glGetError() == C.GL_NO_ERROR
        out = ctypes.c_void_p(0x1234)
        gl.glGetPointerv(C.GL_TEXTURE_2D, ctypes.byref(out))
        assert out.value == 0x1234 and gl.glGetError() == C.GL_INVALID_ENUM
        eq = (ctypes.c_int * 4)(7, 7, 7, 7)
        gl.glGetClipPlanex(C.GL_CLIP_PLANE0 + 99, eq)
        assert list(eq) == [7, 7, 7, 7] and gl.glGetError() == C.GL_INVALID_ENUM
        ints = (ctypes.c_int * 16)(*([5] * 16))
        gl.glGetIntegerv(0x7777, ints)
        assert list(ints) == [5] * 16 and gl.glGetError() == C.GL_INVALID_ENUM
        assert gl.glGetString(0x7777) is None and gl.glGetError() == C.GL_INVALID_ENUM
        # the first error sticks through the probes: a later successful query keeps it
        gl.glEnable(0x7777)
        gl.glGetPointerv(C.GL_VERTEX_ARRAY_POINTER, ctypes.byref(out))
        assert out.value is None and gl.glGetError() == C.GL_INVALID_ENUM and gl.glGetError() == 0
        # §6.1.2 through the C entry points: colours map to the whole int range
        # in GetIntegerv, GetFixedv leaves enums unscaled
        gl.glClearColorx(65536, 0, 32768, 65536)
        gl.glGetIntegerv(C.GL_COLOR_CLEAR_VALUE, ints)
        assert list(ints[:4]) == [2**31 - 1, 0, 2**30 - 1, 2**31 - 1]   # ((2^32 - 1) c - 1) / 2, rounded
        fixed = (ctypes.c_int * 16)()
        gl.glGetFixedv(C.GL_DEPTH_FUNC, fixed)
        assert fixed[0] == C.GL_LESS
        gl.glGetFixedv(C.GL_LINE_WIDTH, fixed)
        assert fixed[0] == 65536
    finally:
        ctx.close()
