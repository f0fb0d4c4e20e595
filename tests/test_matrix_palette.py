"""OES_matrix_palette: palette matrices, index and weight arrays, skinned positions and normals.

Expected positions are the extension's eye = sum_i w_i M_i v evaluated in
float64 from the 16.16 inputs; lit colours use the lighting reference of
test_lighting with either normal transformation the extension allows,
n Inv(sum w_i Mu_i) or sum w_i n Inv(Mu_i).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from test_lighting import Spec, fx, q16

import gles
from gles import constants as C

ONE = 65536
W = H = 64
MARGIN = 1.0 / 8.0     # pixels: centres this close to a skinned edge may go either way


def _mat(lin: np.ndarray | None = None, t: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> np.ndarray:
    m = np.eye(4)
    if lin is not None:
        m[:3, :3] = lin
    m[:3, 3] = t
    return q16(m)


def _rot_z(deg: float) -> np.ndarray:
    a = math.radians(deg)
    return np.array([[math.cos(a), -math.sin(a), 0.0], [math.sin(a), math.cos(a), 0.0], [0.0, 0.0, 1.0]])


def _load(gl: Any, m: np.ndarray) -> None:
    gl.glLoadMatrixx([fx(a) for a in np.asarray(m).T.reshape(-1)])


def _context(numeric: str, profile: str = "common") -> gles.Context:
    ctx = gles.Context(W, H, numeric=numeric, profile=profile)
    gl = ctx.gl
    gl.glViewport(0, 0, W, H)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthox(0, W * ONE, 0, H * ONE, -8 * ONE, 8 * ONE)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glDisable(C.GL_DITHER)
    return ctx


def _set_palette(gl: Any, mats: list[np.ndarray]) -> None:
    gl.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
    for i, m in enumerate(mats):
        gl.glCurrentPaletteMatrixOES(i)
        _load(gl, m)
    gl.glMatrixMode(C.GL_MODELVIEW)


def strip(n: int = 8) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A strip of n quads along x as separate triangles: positions (in 16.16), bone
    indices (0, 1), weights (1 - t, t) with t rising across the middle, and normals."""
    xs = np.linspace(-24.0, 24.0, n + 1)
    pos, idx, wts, nrm = [], [], [], []
    for i in range(n):
        quad = [(xs[i], -5.0), (xs[i + 1], -5.0), (xs[i + 1], 5.0), (xs[i], 5.0)]
        for j in (0, 1, 2, 0, 2, 3):
            x, y = quad[j]
            t = min(max((x + 16.0) / 32.0, 0.0), 1.0)
            pos.append((x, y, 0.0))
            idx.append((0, 1))
            wts.append((1.0 - t, t))
            v = np.array([0.3 * x / 24.0, 0.4 * y / 5.0, 1.0])
            nrm.append(v / np.linalg.norm(v))
    return q16(pos), np.array(idx, dtype=np.uint8), q16(wts), q16(nrm)


def skinned(mats: list[np.ndarray], pos: np.ndarray, idx: np.ndarray, wts: np.ndarray) -> np.ndarray:
    """Eye coordinates sum_i w_i M_i v (n, 4)."""
    v = np.concatenate([pos, np.ones((len(pos), 1))], axis=1)
    out = np.zeros((len(pos), 4))
    for u in range(idx.shape[1]):
        m = np.stack([mats[i] for i in idx[:, u]])
        out += wts[:, u:u + 1] * np.einsum("nij,nj->ni", m, v)
    return out


def inside_mask(tris: np.ndarray, margin: float) -> np.ndarray:
    """Pixel centres inside some triangle (window xy, (k, 3, 2)) by more than `margin`."""
    x, y = np.meshgrid(np.arange(W) + 0.5, np.arange(H) + 0.5)
    out = np.zeros((H, W), dtype=bool)
    for tri in tris:
        (x0, y0), (x1, y1), (x2, y2) = tri
        a = 0.5 * ((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0))
        if a == 0:
            continue
        p = tri if a > 0 else tri[::-1]
        ok = np.ones((H, W), dtype=bool)
        for i in range(3):
            e0, e1 = p[i], p[(i + 1) % 3]
            ex, ey = e1 - e0
            ok &= ex * (y - e0[1]) - ey * (x - e0[0]) > margin * math.hypot(ex, ey)
        out |= ok
    return out


def _arrays(gl: Any, pos: np.ndarray, idx: np.ndarray, wts: np.ndarray, *,
            float_weights: bool = False) -> None:
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FIXED, 0, np.round(pos * ONE).astype(np.int32))
    gl.glEnableClientState(C.GL_MATRIX_INDEX_ARRAY_OES)
    gl.glEnableClientState(C.GL_WEIGHT_ARRAY_OES)
    gl.glMatrixIndexPointerOES(idx.shape[1], C.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(idx))
    if float_weights:
        gl.glWeightPointerOES(wts.shape[1], C.GL_FLOAT, 0, wts.astype(np.float32))
    else:
        gl.glWeightPointerOES(wts.shape[1], C.GL_FIXED, 0, np.round(wts * ONE).astype(np.int32))


def _read(gl: Any) -> np.ndarray:
    return gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)


BONES = [_mat(t=(32.0, 30.0, 0.0)), _mat(_rot_z(50.0), (32.0, 30.0, 0.0))]


# {================================================================
# limits and state


@pytest.mark.parametrize("profile", ["common", "common-lite"])
def test_limits_and_initial_state(numeric: str, profile: str) -> None:
    """MAX_PALETTE_MATRICES_OES 32, MAX_VERTEX_UNITS_OES 4, and the extension's initial state."""
    gl = gles.Context(4, 4, numeric=numeric, profile=profile).gl
    assert b"GL_OES_matrix_palette" in gl.glGetString(C.GL_EXTENSIONS).split()
    assert gl.glGetIntegerv(C.GL_MAX_PALETTE_MATRICES_OES) == 32
    assert gl.glGetIntegerv(C.GL_MAX_VERTEX_UNITS_OES) == 4
    assert gl.glGetIntegerv(C.GL_CURRENT_PALETTE_MATRIX_OES) == 0
    assert not gl.glIsEnabled(C.GL_MATRIX_PALETTE_OES)
    assert not gl.glIsEnabled(C.GL_MATRIX_INDEX_ARRAY_OES)
    assert not gl.glIsEnabled(C.GL_WEIGHT_ARRAY_OES)
    assert gl.glGetIntegerv(C.GL_MATRIX_INDEX_ARRAY_SIZE_OES) == 0
    assert gl.glGetIntegerv(C.GL_MATRIX_INDEX_ARRAY_TYPE_OES) == C.GL_UNSIGNED_BYTE
    assert gl.glGetIntegerv(C.GL_MATRIX_INDEX_ARRAY_STRIDE_OES) == 0
    assert gl.glGetIntegerv(C.GL_WEIGHT_ARRAY_SIZE_OES) == 0
    assert gl.glGetIntegerv(C.GL_WEIGHT_ARRAY_STRIDE_OES) == 0
    if profile == "common":
        assert gl.glGetIntegerv(C.GL_WEIGHT_ARRAY_TYPE_OES) == C.GL_FLOAT
    assert gl.glGetIntegerv(C.GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES) == 0
    assert gl.glGetIntegerv(C.GL_WEIGHT_ARRAY_BUFFER_BINDING_OES) == 0
    for cap in (C.GL_MATRIX_PALETTE_OES,):
        gl.glEnable(cap)
        assert gl.glIsEnabled(cap)
        gl.glDisable(cap)
    for arr in (C.GL_MATRIX_INDEX_ARRAY_OES, C.GL_WEIGHT_ARRAY_OES):
        gl.glEnableClientState(arr)
        assert gl.glIsEnabled(arr)
        gl.glDisableClientState(arr)
        assert not gl.glIsEnabled(arr)
    assert gl.glGetError() == 0


def _pointer_state(gl: Any) -> list[int]:
    return [int(gl.glGetIntegerv(p)) for p in (
        C.GL_MATRIX_INDEX_ARRAY_SIZE_OES, C.GL_MATRIX_INDEX_ARRAY_TYPE_OES,
        C.GL_MATRIX_INDEX_ARRAY_STRIDE_OES, C.GL_WEIGHT_ARRAY_SIZE_OES, C.GL_WEIGHT_ARRAY_TYPE_OES,
        C.GL_WEIGHT_ARRAY_STRIDE_OES)]


POINTER_ERRORS = [
    ("index size 0", lambda g, a: g.glMatrixIndexPointerOES(0, C.GL_UNSIGNED_BYTE, 0, a), C.GL_INVALID_VALUE),
    ("index size 5", lambda g, a: g.glMatrixIndexPointerOES(5, C.GL_UNSIGNED_BYTE, 0, a), C.GL_INVALID_VALUE),
    ("index stride -1", lambda g, a: g.glMatrixIndexPointerOES(2, C.GL_UNSIGNED_BYTE, -1, a),
     C.GL_INVALID_VALUE),
    ("index type BYTE", lambda g, a: g.glMatrixIndexPointerOES(2, C.GL_BYTE, 0, a), C.GL_INVALID_ENUM),
    ("index type SHORT", lambda g, a: g.glMatrixIndexPointerOES(2, C.GL_SHORT, 0, a), C.GL_INVALID_ENUM),
    ("index type UNSIGNED_SHORT", lambda g, a: g.glMatrixIndexPointerOES(2, C.GL_UNSIGNED_SHORT, 0, a),
     C.GL_INVALID_ENUM),
    ("index type FIXED", lambda g, a: g.glMatrixIndexPointerOES(2, C.GL_FIXED, 0, a), C.GL_INVALID_ENUM),
    ("weight size 0", lambda g, a: g.glWeightPointerOES(0, C.GL_FIXED, 0, a), C.GL_INVALID_VALUE),
    ("weight size 5", lambda g, a: g.glWeightPointerOES(5, C.GL_FIXED, 0, a), C.GL_INVALID_VALUE),
    ("weight stride -4", lambda g, a: g.glWeightPointerOES(2, C.GL_FIXED, -4, a), C.GL_INVALID_VALUE),
    ("weight type BYTE", lambda g, a: g.glWeightPointerOES(2, C.GL_BYTE, 0, a), C.GL_INVALID_ENUM),
    ("weight type UNSIGNED_BYTE", lambda g, a: g.glWeightPointerOES(2, C.GL_UNSIGNED_BYTE, 0, a),
     C.GL_INVALID_ENUM),
    ("weight type SHORT", lambda g, a: g.glWeightPointerOES(2, C.GL_SHORT, 0, a), C.GL_INVALID_ENUM),
]


@pytest.mark.parametrize("case", [c[0] for c in POINTER_ERRORS])
def test_pointer_errors(case: str) -> None:
    """Sizes outside 1..MAX_VERTEX_UNITS_OES and negative strides are INVALID_VALUE, other types
    INVALID_ENUM; the pointer state is unchanged."""
    _, call, err = next(c for c in POINTER_ERRORS if c[0] == case)
    gl = gles.Context(4, 4).gl
    gl.glMatrixIndexPointerOES(3, C.GL_UNSIGNED_BYTE, 6, np.zeros(64, dtype=np.uint8))
    gl.glWeightPointerOES(3, C.GL_FIXED, 16, np.zeros(64, dtype=np.int32))
    before = _pointer_state(gl)
    arr = np.zeros(64, dtype=np.uint8)
    try:
        call(gl, arr)
    except TypeError:
        # the binding checks the array's dtype against the type first; pass raw bytes instead
        call(gl, arr.tobytes())
    assert gl.glGetError() == err
    assert _pointer_state(gl) == before


def test_weight_types_per_profile() -> None:
    """Weights are FIXED or FLOAT; Common-Lite has no FLOAT arrays (INVALID_ENUM)."""
    common = gles.Context(4, 4).gl
    common.glWeightPointerOES(2, C.GL_FLOAT, 0, np.zeros(8, dtype=np.float32))
    assert common.glGetError() == 0
    assert common.glGetIntegerv(C.GL_WEIGHT_ARRAY_TYPE_OES) == C.GL_FLOAT
    lite = gles.Context(4, 4, profile="common-lite").gl
    lite.glWeightPointerOES(2, C.GL_FLOAT, 0, np.zeros(8, dtype=np.float32))
    assert lite.glGetError() == C.GL_INVALID_ENUM
    lite.glWeightPointerOES(4, C.GL_FIXED, 0, np.zeros(8, dtype=np.int32))
    assert lite.glGetError() == 0
    assert lite.glGetIntegerv(C.GL_WEIGHT_ARRAY_SIZE_OES) == 4


def test_current_palette_matrix_range() -> None:
    """CurrentPaletteMatrixOES takes 0..31; 32 is INVALID_VALUE and changes nothing."""
    gl = gles.Context(4, 4).gl
    gl.glCurrentPaletteMatrixOES(31)
    assert gl.glGetError() == 0
    assert gl.glGetIntegerv(C.GL_CURRENT_PALETTE_MATRIX_OES) == 31
    for bad in (32, 1000, 2**32 - 1):
        gl.glCurrentPaletteMatrixOES(bad)
        assert gl.glGetError() == C.GL_INVALID_VALUE
        assert gl.glGetIntegerv(C.GL_CURRENT_PALETTE_MATRIX_OES) == 31


def test_palette_mode_has_no_stack() -> None:
    """MatrixMode(MATRIX_PALETTE_OES): Push is STACK_OVERFLOW, Pop STACK_UNDERFLOW; the matrix is kept."""
    gl = _context("double").gl
    gl.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
    assert gl.glGetError() == 0
    assert gl.glGetIntegerv(C.GL_MATRIX_MODE) == C.GL_MATRIX_PALETTE_OES
    gl.glCurrentPaletteMatrixOES(2)
    gl.glTranslatex(10 * ONE, 0, 0)
    gl.glPushMatrix()
    assert gl.glGetError() == C.GL_STACK_OVERFLOW
    gl.glPopMatrix()
    assert gl.glGetError() == C.GL_STACK_UNDERFLOW
    gl.glMatrixMode(C.GL_MODELVIEW)
    # palette matrix 2 is still the translation: a vertex bound to it lands 10 px right
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    tri = q16([(2.0, 2.0, 0.0), (20.0, 2.0, 0.0), (2.0, 20.0, 0.0)])
    _arrays(gl, tri, np.full((3, 1), 2, dtype=np.uint8), np.ones((3, 1)))
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    got = _read(gl)[..., 0] > 0
    want = inside_mask(np.array([tri[:, :2] + [10.0, 0.0]]), 0.0)
    assert (got == want).all()


# {================================================================
# skinning


def _check_positions(img: np.ndarray, eye: np.ndarray, what: str) -> None:
    win = eye[:, :2] / eye[:, 3:4]
    tris = win.reshape(-1, 3, 2)
    inside = inside_mask(tris, MARGIN)
    outside = ~inside_mask(tris, -MARGIN)
    drawn = img[..., :3].any(axis=-1)
    assert inside.sum() > 200, "test bug: the strip covers too little"
    assert drawn[inside].all(), f"{what}: {int((~drawn & inside).sum())} pixels inside the strip not drawn"
    assert not drawn[outside].any(), f"{what}: {int((drawn & outside).sum())} pixels outside the strip drawn"


@pytest.mark.parametrize("profile", ["common", "common-lite"])
def test_two_bone_positions(numeric: str, profile: str) -> None:
    """eye = sum_i w_i M_i v: a strip bent by two bones lands where the extension says."""
    gl = _context(numeric, profile).gl
    _set_palette(gl, BONES)
    pos, idx, wts, _ = strip()
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    _arrays(gl, pos, idx, wts)
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    assert gl.glGetError() == 0
    _check_positions(_read(gl), skinned(BONES, pos, idx, wts), "two bones")


def test_weights_not_summing_to_one(numeric: str) -> None:
    """Weights are used as given: eye w is their sum, so after the division the strip lands where
    the normalised weights put it."""
    pos, idx, wts, _ = strip()
    images = []
    for factor in (1.0, 1.5, 0.75):
        gl = _context(numeric).gl
        _set_palette(gl, BONES)
        gl.glEnable(C.GL_MATRIX_PALETTE_OES)
        w = q16(wts * factor)
        _arrays(gl, pos, idx, w)
        gl.glColor4x(ONE, ONE, ONE, ONE)
        gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
        img = _read(gl)
        _check_positions(img, skinned(BONES, pos, idx, w), f"weights times {factor}")
        images.append(img)
    assert (np.abs(images[0].astype(int) - images[1].astype(int)) == 0).mean() > 0.99


def test_four_units(numeric: str) -> None:
    """MAX_VERTEX_UNITS_OES (4) matrices per vertex, FLOAT weights, indices up to 31."""
    gl = _context(numeric).gl
    mats = {3: _mat(t=(30.0, 28.0, 0.0)), 17: _mat(_rot_z(20.0), (34.0, 30.0, 0.0)),
            30: _mat(np.diag([1.2, 0.8, 1.0]), (31.0, 33.0, 0.0)), 31: _mat(_rot_z(-15.0), (33.0, 29.0, 0.5))}
    gl.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
    for i, m in mats.items():
        gl.glCurrentPaletteMatrixOES(i)
        _load(gl, m)
    gl.glMatrixMode(C.GL_MODELVIEW)
    pos, _, _, _ = strip()
    rng = np.random.default_rng(4)
    idx = np.tile(np.array([3, 17, 30, 31], dtype=np.uint8), (len(pos), 1))
    wts = rng.dirichlet(np.ones(4), size=len(pos))
    wts = wts.astype(np.float32).astype(np.float64)
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    _arrays(gl, pos, idx, wts, float_weights=True)
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    assert gl.glGetError() == 0
    full = [np.eye(4)] * 32
    for i, m in mats.items():
        full[i] = m
    used = q16(wts) if numeric == "fixed" else wts
    _check_positions(_read(gl), skinned(full, pos, idx, used), "four units")


def test_load_palette_from_modelview(numeric: str) -> None:
    """LoadPaletteFromModelViewMatrixOES copies the modelview into the current palette matrix; later
    modelview changes do not reach it, and the modelview is unused while the palette is on."""
    gl = _context(numeric).gl
    gl.glLoadIdentity()
    gl.glTranslatex(32 * ONE, 30 * ONE, 0)
    gl.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
    gl.glCurrentPaletteMatrixOES(0)
    gl.glLoadPaletteFromModelViewMatrixOES()
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glRotatex(50 * ONE, 0, 0, ONE)
    gl.glMatrixMode(C.GL_MATRIX_PALETTE_OES)
    gl.glCurrentPaletteMatrixOES(1)
    gl.glLoadPaletteFromModelViewMatrixOES()
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glScalex(ONE // 4, ONE // 4, ONE)        # would shrink the strip if it were used
    assert gl.glGetError() == 0
    pos, idx, wts, _ = strip()
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    _arrays(gl, pos, idx, wts)
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    _check_positions(_read(gl), skinned(BONES, pos, idx, wts), "palette loaded from the modelview")


def test_palette_off_uses_modelview(numeric: str) -> None:
    """With MATRIX_PALETTE_OES disabled the index and weight arrays are ignored."""
    gl = _context(numeric).gl
    _set_palette(gl, BONES)
    _load(gl, _mat(t=(32.0, 30.0, 0.0)))
    pos, idx, wts, _ = strip()
    _arrays(gl, pos, idx, wts)
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    _check_positions(_read(gl), skinned([BONES[0]] * 2, pos, idx, np.column_stack([np.ones(len(pos)),
                                                                                     np.zeros(len(pos))])),
                     "palette disabled")


@pytest.mark.parametrize("off", [C.GL_MATRIX_INDEX_ARRAY_OES, C.GL_WEIGHT_ARRAY_OES])
def test_missing_array_draws_nothing(numeric: str, off: int) -> None:
    """With the palette on, a disabled index or weight array means nothing is drawn (and no error)."""
    gl = _context(numeric).gl
    _set_palette(gl, BONES)
    pos, idx, wts, _ = strip()
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    _arrays(gl, pos, idx, wts)
    gl.glDisableClientState(off)
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    gl.glDrawElements(C.GL_TRIANGLES, 6, C.GL_UNSIGNED_BYTE, np.arange(6, dtype=np.uint8))
    assert gl.glGetError() == 0
    assert not _read(gl).any()


def test_index_out_of_range_raises(numeric: str) -> None:
    """A matrix index >= MAX_PALETTE_MATRICES_OES is refused with ValueError before anything is drawn."""
    gl = _context(numeric).gl
    _set_palette(gl, BONES)
    pos, idx, wts, _ = strip()
    bad = idx.copy()
    bad[7, 1] = 32
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    _arrays(gl, pos, bad, wts)
    gl.glColor4x(ONE, ONE, ONE, ONE)
    with pytest.raises(ValueError, match="MAX_PALETTE_MATRICES"):
        gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    with pytest.raises(ValueError):
        gl.glDrawElements(C.GL_TRIANGLES, 3, C.GL_UNSIGNED_BYTE, np.array([6, 7, 8], dtype=np.uint8))
    assert not _read(gl).any()
    # vertices that do not read the bad index still draw
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 6)
    gl.glDrawElements(C.GL_TRIANGLES, 3, C.GL_UNSIGNED_BYTE, np.array([12, 13, 14], dtype=np.uint8))
    assert _read(gl).any()
    bad[7, 1] = 255
    gl.glMatrixIndexPointerOES(2, C.GL_UNSIGNED_BYTE, 0, bad)
    with pytest.raises(ValueError):
        gl.glDrawArrays(C.GL_TRIANGLES, 6, 3)
    assert gl.glGetError() == 0


def test_arrays_in_buffer_objects(numeric: str) -> None:
    """Index and weight arrays may live in a buffer object (their *_BUFFER_BINDING_OES follow it)."""
    gl = _context(numeric).gl
    _set_palette(gl, BONES)
    pos, idx, wts, _ = strip()
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FIXED, 0, np.round(pos * ONE).astype(np.int32))
    wbytes = np.round(wts * ONE).astype(np.int32).tobytes()
    ibytes = np.ascontiguousarray(idx).tobytes()
    buf = gl.glGenBuffers(1)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, buf)
    gl.glBufferData(C.GL_ARRAY_BUFFER, len(wbytes) + len(ibytes), wbytes + ibytes, C.GL_STATIC_DRAW)
    gl.glEnableClientState(C.GL_MATRIX_INDEX_ARRAY_OES)
    gl.glEnableClientState(C.GL_WEIGHT_ARRAY_OES)
    gl.glWeightPointerOES(2, C.GL_FIXED, 0, 0)
    gl.glMatrixIndexPointerOES(2, C.GL_UNSIGNED_BYTE, 0, len(wbytes))
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, 0)
    assert gl.glGetIntegerv(C.GL_WEIGHT_ARRAY_BUFFER_BINDING_OES) == buf
    assert gl.glGetIntegerv(C.GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES) == buf
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    assert gl.glGetError() == 0
    _check_positions(_read(gl), skinned(BONES, pos, idx, wts), "arrays in a buffer object")


# {================================================================
# lit skinning


def _lit_strip(numeric: str, factor: float, normalize: bool, light_w: float) -> None:
    gl = _context(numeric).gl
    _set_palette(gl, BONES)
    pos, idx, wts, nrm = strip()
    wts = q16(wts * factor)
    ref = Spec()
    ref.lights[0].enabled = True
    ref.normalize = normalize
    gl.glShadeModel(C.GL_FLAT)
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_LIGHT0)
    if normalize:
        gl.glEnable(C.GL_NORMALIZE)
    light = q16([28.0, 40.0, 20.0, 1.0]) if light_w else q16([0.3, 0.5, 0.8, 0.0])
    gl.glLightxv(C.GL_LIGHT0, C.GL_POSITION, [fx(a) for a in light])
    ref.light(0, C.GL_POSITION, light)
    for pname, v in ((C.GL_DIFFUSE, [0.9, 0.7, 0.45, 1.0]), (C.GL_SPECULAR, [0.3, 0.3, 0.3, 1.0]),
                     (C.GL_AMBIENT, [0.2, 0.1, 0.3, 1.0])):
        gl.glMaterialxv(C.GL_FRONT_AND_BACK, pname, [fx(a) for a in q16(v)])
        ref.material(pname, q16(v))
    gl.glMaterialx(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 10 * ONE)
    ref.material(C.GL_SHININESS, [10.0])
    gl.glEnable(C.GL_MATRIX_PALETTE_OES)
    _arrays(gl, pos, idx, wts)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    gl.glNormalPointer(C.GL_FIXED, 0, np.round(nrm * ONE).astype(np.int32))
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(pos))
    assert gl.glGetError() == 0
    img = _read(gl).astype(np.float64)
    eye = skinned(BONES, pos, idx, wts)
    prov = np.arange(2, len(pos), 3)
    blend = [sum(wts[v, u] * BONES[idx[v, u]][:3, :3] for u in range(2)) for v in prov]
    form1 = np.stack([nrm[v] @ np.linalg.inv(b) for v, b in zip(prov, blend)])
    form2 = np.stack([sum(wts[v, u] * (nrm[v] @ np.linalg.inv(BONES[idx[v, u]][:3, :3])) for u in range(2))
                      for v in prov])
    wants = []
    for form in (form1, form2):
        if normalize:
            form = form / np.linalg.norm(form, axis=1, keepdims=True)
        wants.append(ref.shade(eye[prov], form)[0] * 255)
    tris = (eye[:, :2] / eye[:, 3:4]).reshape(-1, 3, 2)
    for k, tri in enumerate(tris):
        ins = inside_mask(tri[None], 0.75)
        if not ins.any():
            continue
        got = img[ins]
        errs = [np.abs(got - w[k]).max() for w in wants]
        assert min(errs) <= 1.0, (f"triangle {k} (weights {wts[3 * k + 2].tolist()}): got {got[0].tolist()}, "
                                  f"expected {np.round(wants[0][k], 1).tolist()} "
                                  f"or {np.round(wants[1][k], 1).tolist()}")


@pytest.mark.parametrize("light_w", [0.0, 1.0])
@pytest.mark.parametrize("normalize", [True, False])
def test_lit_skinned_strip(numeric: str, normalize: bool, light_w: float) -> None:
    """Skinned normals light as the extension says (either form), with directional and positional lights."""
    _lit_strip(numeric, 1.0, normalize, light_w)


@pytest.mark.parametrize("factor", [0.75, 1.25])
def test_lit_weights_not_summing_to_one(numeric: str, factor: float) -> None:
    """Unnormalised weights scale the skinned normal (either way, by the form); NORMALIZE undoes it."""
    _lit_strip(numeric, factor, False, 0.0)
    _lit_strip(numeric, factor, True, 1.0)
