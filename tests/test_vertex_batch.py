"""The batched vertex stage (csrc/vertex_batch.c, light_batch) against the per-vertex reference.

Vertices are transformed, clip-coded, lit and fogged in batches; the per-vertex
functions of csrc/vertex.c stay as the reference path, chosen with
``ctx.debug(8)``. Random scenes (lights of every kind, two-sided lighting,
COLOR_MATERIAL, NORMALIZE/RESCALE_NORMAL, fog, user clip planes, culling, the
matrix palette, texture matrices, point sizes, every array type, w != 1) are
drawn with DrawArrays and with DrawElements in random index orders, both
sparse and dense index ranges, as triangles, strips, fans, lines and points;
colour and depth buffers must be identical in every build.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import BUILDS, make_ctx

from gles import constants as C

W = H = 48
REFERENCE = 8  # GLES_DEBUG_VERTEX_REFERENCE


def _array(rng: np.random.Generator, values: np.ndarray, kinds: list[str]) -> tuple[int, np.ndarray]:
    """values (floats) as one of the array types in `kinds`: (GL type, data)."""
    kind = kinds[rng.integers(len(kinds))]
    if kind == "float":
        return C.GL_FLOAT, values.astype(np.float32)
    if kind == "fixed":
        return C.GL_FIXED, np.round(values * 65536).astype(np.int32)
    if kind == "short":
        return C.GL_SHORT, np.round(values).astype(np.int16)
    return C.GL_BYTE, np.round(values).astype(np.int8)


def _lights(gl, rng: np.random.Generator) -> None:
    gl.glEnable(C.GL_LIGHTING)
    for _ in range(int(rng.integers(1, 5))):
        light = C.GL_LIGHT0 + int(rng.integers(0, 8))
        gl.glEnable(light)
        w = float(rng.choice([0.0, 1.0, 2.0]))
        where = rng.uniform(-3, 3, 3)
        gl.glLightfv(light, C.GL_POSITION, [*where, w])
        gl.glLightfv(light, C.GL_AMBIENT, [*rng.uniform(0, 0.3, 3), 1.0])
        gl.glLightfv(light, C.GL_DIFFUSE, [*rng.uniform(0, 1.2, 3), 1.0])
        spec = rng.uniform(0, 1, 3) if rng.random() < 0.7 else np.zeros(3)
        gl.glLightfv(light, C.GL_SPECULAR, [*spec, 1.0])
        if rng.random() < 0.4:
            # often towards the scene, so the cone meets it
            aim = -where + rng.uniform(-1, 1, 3) if rng.random() < 0.6 else rng.uniform(-1, 1, 3)
            gl.glLightfv(light, C.GL_SPOT_DIRECTION, list(aim))
            gl.glLightf(light, C.GL_SPOT_CUTOFF, float(rng.uniform(10, 90)))
            gl.glLightf(light, C.GL_SPOT_EXPONENT, float(rng.uniform(0, 40)))
        if rng.random() < 0.5:
            gl.glLightf(light, C.GL_CONSTANT_ATTENUATION, float(rng.uniform(0.2, 1.5)))
            gl.glLightf(light, C.GL_LINEAR_ATTENUATION, float(rng.uniform(0, 0.5)))
            gl.glLightf(light, C.GL_QUADRATIC_ATTENUATION, float(rng.uniform(0, 0.2)))
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [*rng.uniform(0, 1, 3), 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_DIFFUSE, [*rng.uniform(0, 1, 3), float(rng.uniform(0.3, 1))])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [*rng.uniform(0, 1, 3), 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_EMISSION, [*rng.uniform(0, 0.2, 3), 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, float(rng.uniform(0, 128)))
    gl.glLightModelf(C.GL_LIGHT_MODEL_TWO_SIDE, float(rng.random() < 0.5))
    gl.glLightModelfv(C.GL_LIGHT_MODEL_AMBIENT, [*rng.uniform(0, 0.4, 3), 1.0])
    if rng.random() < 0.4:
        gl.glEnable(C.GL_COLOR_MATERIAL)
    if rng.random() < 0.6:
        gl.glEnable(C.GL_NORMALIZE)
    elif rng.random() < 0.5:
        gl.glEnable(C.GL_RESCALE_NORMAL)


def _state(gl, rng: np.random.Generator, palette: bool) -> None:
    gl.glViewport(int(rng.integers(-8, 8)), int(rng.integers(-8, 8)), W, H)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    if rng.random() < 0.7:
        gl.glFrustumf(-0.6, 0.6, -0.6, 0.6, 1.0, 9.0)
    else:
        gl.glOrthof(-4, 4, -4, 4, -9, 9)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glTranslatef(0.0, 0.0, -4.0)
    if rng.random() < 0.8:
        gl.glRotatef(float(rng.uniform(0, 360)), *rng.uniform(-1, 1, 3))
    if rng.random() < 0.5:
        gl.glScalef(*rng.uniform(0.5, 1.5, 3))
    if rng.random() < 0.7:
        _lights(gl, rng)
    if rng.random() < 0.5:
        gl.glEnable(C.GL_FOG)
        mode = [C.GL_LINEAR, C.GL_EXP, C.GL_EXP2][int(rng.integers(3))]
        gl.glFogf(C.GL_FOG_MODE, mode)
        gl.glFogf(C.GL_FOG_START, 2.0)
        gl.glFogf(C.GL_FOG_END, 7.0)
        gl.glFogf(C.GL_FOG_DENSITY, 0.3)
        gl.glHint(C.GL_FOG_HINT, C.GL_NICEST if rng.random() < 0.3 else C.GL_FASTEST)
    if rng.random() < 0.4:
        gl.glClipPlanef(C.GL_CLIP_PLANE0, list(rng.uniform(-1, 1, 3)) + [0.3])
        gl.glEnable(C.GL_CLIP_PLANE0)
    if rng.random() < 0.5:
        gl.glEnable(C.GL_CULL_FACE)
        gl.glCullFace([C.GL_BACK, C.GL_FRONT][int(rng.integers(2))])
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glShadeModel(C.GL_SMOOTH if rng.random() < 0.8 else C.GL_FLAT)
    if palette:
        gl.glEnable(C.GL_MATRIX_PALETTE_OES)
        gl.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
        for i in range(4):
            gl.glCurrentPaletteMatrixOES(i)
            gl.glLoadIdentity()
            gl.glTranslatef(*rng.uniform(-0.5, 0.5, 2), -4.0)
            gl.glRotatef(float(rng.uniform(0, 360)), *rng.uniform(-1, 1, 3))
        gl.glMatrixMode(C.GL_MODELVIEW)


def _arrays(gl, rng: np.random.Generator, n: int, palette: bool) -> list:
    """Random vertex arrays (kept alive by the returned list)."""
    keep = []
    size = int(rng.choice([2, 3, 3, 4]))
    pos = rng.uniform(-2.2, 2.2, (n, size))
    if size == 4:
        pos[:, 3] = rng.uniform(0.5, 1.5, n)
    t, a = _array(rng, pos * 16 if rng.random() < 0.2 else pos, ["float", "float", "fixed"])
    if t == C.GL_FLOAT and a.dtype == np.float32 and np.abs(a).max() > 10:
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glScalef(1 / 16, 1 / 16, 1 / 16)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(size, t, 0, a)
    keep.append(a)
    if rng.random() < 0.8:
        nrm = rng.uniform(-1, 1, (n, 3))
        t, a = _array(rng, nrm * 100, ["float", "short", "byte"])
        if t == C.GL_FLOAT:
            a = nrm.astype(np.float32)
        gl.glEnableClientState(C.GL_NORMAL_ARRAY)
        gl.glNormalPointer(t, 0, a)
        keep.append(a)
    else:
        gl.glNormal3f(*rng.uniform(-1, 1, 3))
    if rng.random() < 0.7:
        if rng.random() < 0.5:
            a = rng.integers(0, 256, (n, 4)).astype(np.uint8)
            gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, a)
        else:
            a = rng.uniform(0, 1, (n, 4)).astype(np.float32)
            gl.glColorPointer(4, C.GL_FLOAT, 0, a)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        keep.append(a)
    else:
        gl.glColor4f(*rng.uniform(0, 1, 4))
    if rng.random() < 0.3:
        a = rng.uniform(1, 4, n).astype(np.float32)
        gl.glEnableClientState(C.GL_POINT_SIZE_ARRAY_OES)
        gl.glPointSizePointerOES(C.GL_FLOAT, 0, a)
        keep.append(a)
    if palette:
        idx = rng.integers(0, 4, (n, 2)).astype(np.uint8)
        wts = rng.uniform(0, 1, (n, 2)).astype(np.float32)
        wts /= wts.sum(axis=1, keepdims=True)
        gl.glEnableClientState(C.GL_MATRIX_INDEX_ARRAY_OES)
        gl.glEnableClientState(C.GL_WEIGHT_ARRAY_OES)
        gl.glMatrixIndexPointerOES(2, C.GL_UNSIGNED_BYTE, 0, idx)
        gl.glWeightPointerOES(2, C.GL_FLOAT, 0, wts)
        keep += [idx, wts]
    return keep


MODES = (C.GL_TRIANGLES, C.GL_TRIANGLES, C.GL_TRIANGLE_STRIP, C.GL_TRIANGLE_FAN,
         C.GL_LINES, C.GL_LINE_STRIP, C.GL_LINE_LOOP, C.GL_POINTS)


def _render(numeric: str, seed: int, flags: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """A random scene (every light kind, array and index type, clip plane, palette)
    drawn with the debug `flags`: its colour and depth buffers."""
    rng = np.random.default_rng(seed)
    ctx = make_ctx(numeric, W, H, depth=16, range_check="off")
    gl = ctx.gl
    ctx.debug(flags)
    gl.glClearColor(0.1, 0.1, 0.1, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    palette = rng.random() < 0.2
    _state(gl, rng, palette)
    n = int(rng.integers(3, 300))
    keep = _arrays(gl, rng, n, palette)
    for _ in range(3):
        mode = MODES[int(rng.integers(len(MODES)))]
        how = rng.random()
        if how < 0.35:
            first = int(rng.integers(0, n - 2))
            gl.glDrawArrays(mode, first, int(rng.integers(1, n - first + 1)))
        else:
            count = int(rng.integers(1, 400))
            if how < 0.7:      # random order over the whole array: a dense or sparse range
                idx = rng.integers(0, n, count)
            else:              # a few vertices far apart: the gathered path
                idx = rng.choice([0, n // 2, n - 1], count)
            itype = C.GL_UNSIGNED_SHORT if rng.random() < 0.5 else C.GL_UNSIGNED_BYTE
            idx = idx.astype(np.uint16 if itype == C.GL_UNSIGNED_SHORT else np.uint8)
            if itype == C.GL_UNSIGNED_BYTE:
                idx = np.minimum(idx, 255).astype(np.uint8)
            gl.glDrawElements(mode, len(idx), itype, idx)
    del keep
    assert gl.glGetError() == 0
    return ctx.color_buffer().copy(), ctx.depth_buffer().copy()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("seed", range(60))
def test_batched_matches_per_vertex(numeric: str, seed: int) -> None:
    """Random scenes: the batched path draws exactly what the per-vertex reference draws."""
    col_b, dep_b = _render(numeric, seed)
    col_r, dep_r = _render(numeric, seed, REFERENCE)
    assert np.array_equal(col_b, col_r), f"colour differs at {np.argwhere(col_b != col_r)[:4].tolist()}"
    assert np.array_equal(dep_b, dep_r), "depth differs"


@pytest.mark.parametrize("numeric", BUILDS)
def test_scenes_draw_something(numeric: str) -> None:
    """The random scenes are not empty (the comparison above would pass on blank images)."""
    drawn = 0
    for seed in range(60):
        col, _ = _render(numeric, seed)
        drawn += int((col.reshape(-1, 4)[:, :3] != np.uint8(26)).any(axis=1).sum() > 20)
    assert drawn >= 40
