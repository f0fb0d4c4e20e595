"""The positional light's AVX2 kernel (vx_positional_avx2) against the scalar code.

``gles_debug_vertex_lanes`` kernel 6 runs one positional light's term over
given lanes (eye positions, normals, colours, accumulators) either through
the AVX2 kernel or through the scalar ``positional_batch``; the two must
agree bit for bit on random inputs and on the edges (positions that
saturate VP, VP zero, attenuation factors of 0 and beyond 16.16's range,
cone limits at the exact cosine, exponents 0 and 128, zero and huge
normals, padding lanes). The scalar code is the expected value. Whole
images of random lit scenes with positional lights are then compared
between the AVX2 instance, the baseline one (``ctx.debug(16)``) and the
per-vertex reference (``ctx.debug(8)``) in every build.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, make_ctx

from gles import constants as C

I32_MIN, I32_MAX = -(2**31), 2**31 - 1
ONE = 65536
BASELINE = 16  # GLES_DEBUG_BASELINE_SIMD
REFERENCE = 8  # GLES_DEBUG_VERTEX_REFERENCE
EDGE = [I32_MIN, I32_MIN + 1, I32_MAX, I32_MAX - 1, 0, 1, -1, ONE, -ONE, ONE // 2, -ONE // 2, 2**24, -(2**24),
        2**30, -(2**30), 181 * ONE, -181 * ONE]


@pytest.fixture(scope="module")
def core():
    ctx = make_ctx("fixed", 1, 1)
    return ctx._ffi, ctx._lib


def _run(core, simd: int, n: int, m: np.ndarray, data: np.ndarray, dtype=np.int32) -> np.ndarray:
    """Kernel 6; the accumulators' bits (as unsigned integers, so NaNs compare by their bits)."""
    ffi, lib = core
    mm = np.ascontiguousarray(m, np.int32)
    dd = np.ascontiguousarray(data, np.int32)
    out = np.zeros(3 * 64 * np.dtype(dtype).itemsize, np.uint8)
    ptr = [ffi.cast("int32_t *", a.ctypes.data) for a in (mm, dd, out)]
    ok = lib.gles_debug_vertex_lanes(simd, 6, n, *ptr)
    assert ok == 1
    udt = {1: np.uint8, 4: np.uint32, 8: np.uint64}[np.dtype(dtype).itemsize]
    return out.view(udt).reshape(3, 64)[:, :n]


def _unit(rng, count):
    v = rng.normal(size=(count, 3))
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    return np.round(v * ONE).astype(np.int64)


def _light(rng, edge: bool) -> np.ndarray:
    """m: position, attenuation, spot direction, cutoff, exponents, colours, flags."""
    m = np.zeros(32, np.int64)
    m[0:3] = rng.integers(-8 * ONE, 8 * ONE, 3)
    m[3:6] = rng.choice([0, ONE, ONE // 3, 2 * ONE, rng.integers(0, 4 * ONE)], 3)
    m[6:9] = _unit(rng, 1)[0]
    m[9] = rng.integers(-ONE, ONE + 1)
    m[10] = rng.choice([0, ONE, 8 * ONE, 128 * ONE, rng.integers(0, 128 * ONE)])
    m[11] = rng.choice([0, ONE, 24 * ONE, 128 * ONE, rng.integers(0, 128 * ONE)])
    m[12:27] = rng.integers(0, 2 * ONE, 15)
    m[27:31] = rng.integers(0, 2, 4)
    if edge:
        pick = rng.integers(0, 6)
        if pick == 0:
            m[0:3] = rng.choice(EDGE, 3)
        elif pick == 1:
            m[3:6] = rng.choice([0, 1, I32_MAX, ONE, 2**20], 3)
        elif pick == 2:
            m[6:9] = rng.choice(EDGE, 3)
            m[9] = rng.choice(EDGE)
        else:
            m[12:27] = rng.choice(EDGE, 15)
    return m


def _data(rng, m: np.ndarray, edge: bool) -> np.ndarray:
    d = np.zeros((4, 3, 64), np.int64)
    d[0] = rng.integers(-6 * ONE, 6 * ONE, (3, 64))
    d[1] = _unit(rng, 64).T
    d[2] = rng.integers(0, ONE + 1, (3, 64))
    d[3] = rng.integers(-ONE, 3 * ONE, (3, 64))
    if edge:
        for _ in range(16):
            a, k, i = int(rng.integers(0, 4)), int(rng.integers(0, 3)), int(rng.integers(0, 64))
            d[a, k, i] = rng.choice(EDGE)
        for i in rng.integers(0, 64, 6):
            d[0, :, i] = m[0:3]                         # the light at the vertex: VP = 0
        for i in rng.integers(0, 64, 4):
            d[0, :, i] = m[0:3] - rng.integers(-2, 3, 3)  # VP of a few units in the last place
        for i in rng.integers(0, 64, 4):
            d[1, :, i] = rng.choice([0, I32_MAX, I32_MIN, 3 * ONE], 3)
    return d.reshape(-1)


FLOAT_EDGE = np.array([np.nan, np.inf, -np.inf, 0.0, -0.0, 1.0, -1.0, 1e-30, -1e-30, 1e30, -1e30, 1e-45, 3e38,
                       0.5, 2.0], np.float32)


def _fp_light(rng, edge: bool) -> np.ndarray:
    m = np.zeros(32, np.float32)
    m[0:3] = rng.uniform(-8, 8, 3)
    m[3:6] = rng.choice([0.0, 1.0, 0.3, 2.0, rng.uniform(0, 4)], 3)
    d = rng.normal(size=3)
    m[6:9] = d / np.linalg.norm(d)
    m[9] = rng.uniform(-1, 1)
    m[10] = rng.choice([0.0, 1.0, 8.0, 128.0, rng.uniform(0, 128)])
    m[11] = rng.choice([0.0, 1.0, 24.0, 128.0, rng.uniform(0, 128)])
    m[12:27] = rng.uniform(0, 2, 15)
    if edge:
        for _ in range(3):
            m[int(rng.integers(0, 27))] = rng.choice(FLOAT_EDGE)
    bits = m.view(np.int32).astype(np.int64)
    bits[27:31] = rng.integers(0, 2, 4)
    return bits


def _fp_data(rng, m: np.ndarray, edge: bool) -> np.ndarray:
    d = np.zeros((4, 3, 64), np.float32)
    d[0] = rng.uniform(-6, 6, (3, 64))
    nrm = rng.normal(size=(3, 64))
    d[1] = nrm / np.linalg.norm(nrm, axis=0)
    d[2] = rng.uniform(0, 1, (3, 64))
    d[3] = rng.uniform(-1, 3, (3, 64))
    pos = m[0:3].astype(np.int32).view(np.float32)
    for i in rng.integers(0, 64, 4):
        d[0, :, i] = pos                                 # the light at the vertex
    if edge:
        for _ in range(20):
            a, k, i = int(rng.integers(0, 4)), int(rng.integers(0, 3)), int(rng.integers(0, 64))
            d[a, k, i] = rng.choice(FLOAT_EDGE)
        for i in rng.integers(0, 64, 3):
            d[1, :, i] = 0.0
    return d.reshape(-1).view(np.int32)


@pytest.mark.parametrize("numeric", ["float", "double"])
@pytest.mark.parametrize("edge", [False, True])
def test_positional_kernel_matches_scalar_fp(numeric, edge):
    """The float builds' kernel against their scalar code, bit for bit (NaN, infinities, -0 included)."""
    ctx = make_ctx(numeric, 1, 1)
    core = (ctx._ffi, ctx._lib)
    dtype = np.float32 if numeric == "float" else np.float64
    rng = np.random.default_rng(515 + edge)
    for trial in range(300):
        m = _fp_light(rng, edge)
        n = int(rng.choice([8, 16, 64]))
        m[31] = int(rng.integers(1, n + 1)) if trial % 3 else n
        d = _fp_data(rng, m, edge)
        vec = _run(core, 1, n, m, d, dtype).view(dtype)
        ref = _run(core, 0, n, m, d, dtype).view(dtype)
        # bits, except that any NaN equals any NaN: which of two NaN operands an addition
        # passes on (and so the NaN's sign) follows the compiler's operand order, not the C source
        same = (vec == ref) & (np.signbit(vec) == np.signbit(ref)) | (np.isnan(vec) & np.isnan(ref))
        bad = np.argwhere(~same)[:4].tolist()
        assert same.all(), f"trial {trial}: lanes {bad}"


@pytest.mark.parametrize("edge", [False, True])
def test_positional_kernel_matches_scalar(core, edge):
    rng = np.random.default_rng(4242 + edge)
    for trial in range(400):
        m = _light(rng, edge)
        n = int(rng.choice([8, 16, 64]))
        m[31] = int(rng.integers(1, n + 1)) if trial % 3 else n
        d = _data(rng, m, edge)
        vec = _run(core, 1, n, m, d)
        ref = _run(core, 0, n, m, d)
        bad = np.argwhere(vec != ref)[:4].tolist()
        assert np.array_equal(vec, ref), f"trial {trial}, m {m.tolist()}: lanes {bad}"


def test_positional_kernel_cone_edges(core):
    """Vertices exactly on the cone's cosine and one unit either side of it."""
    rng = np.random.default_rng(77)
    for trial in range(60):
        m = _light(rng, False)
        m[27:31] = [1, 1, 1, trial & 1]
        m[31] = 64
        d = _data(rng, m, False).reshape(4, 3, 64)
        # VP along the spot direction's reverse at various angles: read cosang from the scalar run
        dirs = _unit(rng, 64)
        d[0] = (m[0:3][:, None] - dirs.T * 3)
        cos = (-(dirs * m[6:9]).sum(axis=1) + ONE // 2) // ONE
        m[9] = int(cos[int(rng.integers(0, 64))]) + int(rng.integers(-1, 2))
        vec = _run(core, 1, 64, m, d.reshape(-1))
        ref = _run(core, 0, 64, m, d.reshape(-1))
        assert np.array_equal(vec, ref), f"trial {trial}"


def _window(core, simd: int, m, rows: np.ndarray) -> np.ndarray:
    """gles_debug_vertex_lanes kernel 7: wx, wy, 1/w's mantissa and exponent, depth of 64 lanes."""
    ffi, lib = core
    mm = np.zeros(8, np.int32)
    mm[:len(m)] = (np.asarray(m, np.int64) & 0xFFFFFFFF).astype(np.uint32).view(np.int32)
    dd = np.ascontiguousarray(rows, np.int32)
    out = np.zeros(5 * 64 * 2, np.int32)
    ptr = [ffi.cast("int32_t *", a.ctypes.data) for a in (mm, dd, out)]
    ok = lib.gles_debug_vertex_lanes(simd, 7, 64, *ptr)
    assert ok == 1
    return out.view(np.int64).reshape(5, 64)


def _window_rows(rng, edge: bool) -> np.ndarray:
    """x, y, z, w of 64 lanes, most inside every plane (|x|, |y|, |z| <= w, w >= 1)."""
    w = rng.choice([rng.integers(1, 2**31, 64), rng.integers(1, 3 * ONE, 64), 2 ** rng.integers(0, 31, 64)])
    w = np.asarray(w, np.int64)
    if edge:
        special = [1, 2, 3, I32_MAX, 2**30, 2**30 + 1, 2**16, 2**16 - 1, 3 * 65535]
        w[rng.integers(0, 64, 12)] = rng.choice(special, 12)
    rows = np.zeros((4, 64), np.int64)
    rows[3] = w
    for k in range(3):
        f = rng.uniform(-1, 1, 64)
        rows[k] = np.clip(np.round(f * w), -w, w)
        if edge:
            sel = rng.integers(0, 64, 16)
            rows[k, sel] = rng.choice([-1, 1, 0], 16) * w[sel] + rng.choice([0, 0, 1, -1, 2, -2], 16)
            half = rng.integers(0, 64, 6)
            rows[k, half] = w[half] // 2 * rng.choice([-1, 1], 6)    # quotients at the rounding ties
    rows[:3] = np.clip(rows[:3], I32_MIN, I32_MAX)
    return rows.reshape(-1)


@pytest.mark.parametrize("edge", [False, True])
def test_window_kernel_matches_scalar(core, edge):
    rng = np.random.default_rng(99 + edge)
    for trial in range(400):
        vp = [int(rng.integers(-100, 100)), int(rng.integers(-100, 100)),
              int(rng.choice([0, 1, 4096, 640, 3])), int(rng.choice([0, 1, 4096, 480, 7]))]
        dn, df = (int(rng.choice([0, ONE, ONE // 3, int(rng.integers(0, ONE + 1))])) for _ in range(2))
        dmax = int(rng.choice([65535, 2**24 - 1, 255, 2**31 - 1, 2**32 - 1]))
        m = vp + [dn, df, dmax]
        rows = _window_rows(rng, edge)
        vec = _window(core, 1, m, rows)
        ref = _window(core, 0, m, rows)
        bad = np.argwhere(vec != ref)[:4].tolist()
        assert np.array_equal(vec, ref), f"trial {trial}, m {m}: {bad}"


def _scene(numeric: str, flags: int, seed: int):
    rng = np.random.default_rng(seed)
    ctx = make_ctx(numeric, 64, 64, depth=16)
    ctx.debug(flags)
    gl = ctx.gl
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glFrustumf(-0.5, 0.5, -0.5, 0.5, 1.0, 40.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    k = 24
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, k), np.linspace(0, np.pi, k))
    nrm = np.stack([np.sin(v) * np.cos(u), np.sin(v) * np.sin(u), np.cos(v)], -1).reshape(-1, 3)
    verts = (nrm * rng.uniform(0.5, 2.0)).astype(np.float32)
    nrm = (nrm * (rng.uniform(0.3, 2.0) if seed & 1 else 1.0)).astype(np.float32)
    i = np.arange(k - 1)
    a = (i[:, None] * k + i[None, :]).reshape(-1)
    idx = np.stack([a, a + 1, a + k, a + 1, a + k + 1, a + k], -1).reshape(-1).astype(np.uint16)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glNormalPointer(C.GL_FLOAT, 0, nrm)
    if seed & 2:
        gl.glEnable(C.GL_COLOR_MATERIAL)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, rng.integers(0, 256, (len(verts), 4)).astype(np.uint8))
    gl.glEnable(C.GL_LIGHTING)
    if seed & 4:
        gl.glEnable(C.GL_NORMALIZE)
    gl.glLightModelf(C.GL_LIGHT_MODEL_TWO_SIDE, float(seed & 8 != 0))
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [*rng.uniform(0, 1, 3), 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, float(rng.choice([0.0, 1.0, 24.0, 128.0])))
    gl.glTranslatef(0.0, 0.0, -5.0)
    for light in (C.GL_LIGHT0, C.GL_LIGHT2, C.GL_LIGHT5):
        gl.glEnable(light)
        pos = [*rng.uniform(-3, 3, 3), 1.0]
        if rng.random() < 0.2:
            pos = [0.0, 0.0, 0.0, 1.0]                   # inside the sphere, at its centre
        gl.glLightfv(light, C.GL_POSITION, pos)
        gl.glLightfv(light, C.GL_DIFFUSE, [*rng.uniform(0, 1.5, 3), 1.0])
        gl.glLightfv(light, C.GL_AMBIENT, [*rng.uniform(0, 0.3, 3), 1.0])
        spec = [*rng.uniform(0, 1, 3), 1.0] if rng.random() < 0.6 else [0.0, 0.0, 0.0, 1.0]
        gl.glLightfv(light, C.GL_SPECULAR, spec)
        if rng.random() < 0.6:
            gl.glLightf(light, C.GL_CONSTANT_ATTENUATION, float(rng.uniform(0, 2)))
            gl.glLightf(light, C.GL_LINEAR_ATTENUATION, float(rng.choice([0.0, rng.uniform(0, 1)])))
            gl.glLightf(light, C.GL_QUADRATIC_ATTENUATION, float(rng.choice([0.0, rng.uniform(0, 1)])))
        if rng.random() < 0.5:
            gl.glLightfv(light, C.GL_SPOT_DIRECTION, [*rng.uniform(-1, 1, 3)])
            gl.glLightf(light, C.GL_SPOT_CUTOFF, float(rng.uniform(5, 90)))
            gl.glLightf(light, C.GL_SPOT_EXPONENT, float(rng.choice([0.0, rng.uniform(0, 128)])))
    gl.glRotatef(float(rng.uniform(0, 360)), *rng.uniform(-1, 1, 3))
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
    assert gl.glGetError() == 0
    return ctx.color_buffer().copy(), ctx.depth_buffer().copy()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("seed", range(16))
def test_positional_scenes_identical(numeric, seed):
    col, dep = _scene(numeric, 0, seed)
    assert (col[..., :3] != 0).any(axis=-1).sum() > 200, "the scene is not empty"
    for flags in (BASELINE, REFERENCE):
        col2, dep2 = _scene(numeric, flags, seed)
        where = np.argwhere(col != col2)[:4].tolist()
        assert np.array_equal(col, col2), f"flags {flags}: colour differs at {where}"
        assert np.array_equal(dep, dep2), f"flags {flags}: depth differs"


def _window_scene(numeric: str, flags: int, seed: int):
    """Triangles in perspective with coordinates near the eye, on the planes, huge, infinite and NaN,
    under a random viewport and depth range: the window coordinates of every build."""
    rng = np.random.default_rng(seed)
    ctx = make_ctx(numeric, 64, 48, depth=16, range_check="off")
    ctx.debug(flags)
    gl = ctx.gl
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LEQUAL)
    gl.glShadeModel(C.GL_SMOOTH)
    gl.glViewport(int(rng.integers(-20, 20)), int(rng.integers(-20, 20)), int(rng.integers(1, 100)),
                  int(rng.integers(1, 100)))
    near, far = (float(v) for v in rng.choice([0.0, 1.0, 0.25, 0.75, rng.uniform(0, 1)], 2))
    gl.glDepthRangef(near, far)
    gl.glMatrixMode(C.GL_PROJECTION)
    zn, zf = float(rng.choice([0.01, 0.5, 1.0])), float(rng.choice([2.0, 50.0, 1e4]))
    gl.glFrustumf(-0.5, 0.5, -0.4, 0.4, zn, zf)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glTranslatef(0.0, 0.0, -float(rng.uniform(0.5, 8.0)))
    n = 240
    verts = rng.uniform(-3, 3, (n, 4)).astype(np.float32)
    verts[:, 3] = rng.choice([1.0, 1.0, 1.0, 0.5, 2.0, 1e-4, -1.0], n)
    special = [np.nan, np.inf, -np.inf, 1e30, -1e30, 3e4, -3e4, 1e-30, 0.0]
    for _ in range(int(rng.integers(0, 12))):
        verts[int(rng.integers(0, n)), int(rng.integers(0, 4))] = rng.choice(special)
    colors = rng.integers(0, 256, (n, 4)).astype(np.uint8)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(4, C.GL_FLOAT, 0, verts)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, n)
    gl.glDrawArrays(C.GL_POINTS, 0, n)
    gl.glDrawArrays(C.GL_LINES, 0, n)
    assert gl.glGetError() == 0
    return ctx.color_buffer().copy(), ctx.depth_buffer().copy()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("seed", range(24))
def test_window_scenes_identical(numeric, seed):
    col, dep = _window_scene(numeric, 0, 900 + seed)
    for flags in (BASELINE, REFERENCE):
        col2, dep2 = _window_scene(numeric, flags, 900 + seed)
        where = np.argwhere(col != col2)[:4].tolist()
        assert np.array_equal(col, col2), f"flags {flags}: colour differs at {where}"
        assert np.array_equal(dep, dep2), f"flags {flags}: depth differs"


def test_simd_instance_is_used():
    """The fixed build runs a vector instance where the CPU has AVX2 (its
    vertex kernels are AVX2's under the name "avx512" too)."""
    ctx = make_ctx("fixed", 4, 4)
    assert ctx.simd in (("avx2", "avx512") if HAS_SIMD else ("baseline",))
