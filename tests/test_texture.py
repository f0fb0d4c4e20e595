"""Texturing (ES 1.1 §3.7): objects, images, parameters, texel selection.

Expected pixels come from a numpy model of the spec's formulas (§3.7.6
wrapping, equations 3.16-3.18 for NEAREST and LINEAR), evaluated in float64
at the pixel centres of screen-aligned quads. The other texturing test files
import the model and the drawing helpers from here.

Tolerance per channel: the visual's 1/255 + 2^-13 (the published rule), plus
for the fixed build 2^-15 (its bilinear weights keep 16 fraction bits, so each
of the two weights is off by less than 2^-16). Where a build computes the
texture coordinate itself inexactly (float32 at s = 1024 keeps 2^-13 of s,
a quarter texel of a 2048-texel image), the model is evaluated over the
coordinate interval the build's precision allows and the pixel must match
one of those values; `coord_slack` gives the interval per build.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any, Callable, NamedTuple

import numpy as np
import pytest
from conftest import BUILDS, make_ctx, set_ortho

from gles import constants as C
from gles.mesa import MesaContext, available

MESA_REASON = available("llvmpipe")
TARGETS = (*BUILDS, "llvmpipe")

VISUAL_TOL = 1.0 / 255 + 2.0**-13
FRAG = (51, 102, 153, 204)          # the primary colour of most draws
RGB565_TOL = np.array([1.0 / 31, 1.0 / 63, 1.0 / 31, 1.0]) + 2.0**-13
FIXED_EXTRA = 2.0**-15

NEAREST, LINEAR = C.GL_NEAREST, C.GL_LINEAR
REPEAT, CLAMP, MIRROR = C.GL_REPEAT, C.GL_CLAMP_TO_EDGE, C.GL_MIRRORED_REPEAT_OES
MIN_FILTERS = (C.GL_NEAREST, C.GL_LINEAR, C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_NEAREST,
               C.GL_NEAREST_MIPMAP_LINEAR, C.GL_LINEAR_MIPMAP_LINEAR)

# the 8 format/type pairs of §3.6.2 that TexImage2D accepts
PAIRS = (
    (C.GL_RGBA, C.GL_UNSIGNED_BYTE), (C.GL_RGB, C.GL_UNSIGNED_BYTE),
    (C.GL_LUMINANCE_ALPHA, C.GL_UNSIGNED_BYTE), (C.GL_LUMINANCE, C.GL_UNSIGNED_BYTE),
    (C.GL_ALPHA, C.GL_UNSIGNED_BYTE), (C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5),
    (C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4), (C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1),
)
BPP = {C.GL_RGBA: 4, C.GL_RGB: 3, C.GL_LUMINANCE_ALPHA: 2, C.GL_LUMINANCE: 1, C.GL_ALPHA: 1}


# {================================================================
# contexts


class Target:
    """A gles build or Mesa llvmpipe, with the same GL calling conventions."""

    def __init__(self, kind: str, w: int = 64, h: int = 64, **kw: Any) -> None:
        self.kind, self.w, self.h = kind, w, h
        if kind == "llvmpipe":
            self.ctx: Any = MesaContext(w, h, driver="llvmpipe", **kw)
        else:
            self.ctx = make_ctx(kind, w, h, **kw)
        self.gl = self.ctx.gl
        self.gl.glDisable(C.GL_DITHER)

    def read(self) -> np.ndarray:
        """RGBA as float in [0, 1], (h, w, 4), row index = window y."""
        px = self.gl.glReadPixels(0, 0, self.w, self.h, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
        return np.asarray(px, dtype=np.float64) / 255.0

    def close(self) -> None:
        if self.kind == "llvmpipe":
            self.ctx.close()


def open_target(request: pytest.FixtureRequest) -> Iterator[Target]:
    """The body of the `target` fixtures: a Target of request.param, closed afterwards."""
    if request.param == "llvmpipe" and MESA_REASON is not None:
        pytest.skip(f"Mesa llvmpipe unavailable: {MESA_REASON}")
    t = Target(request.param)
    yield t
    t.close()


@pytest.fixture(params=TARGETS)
def target(request: pytest.FixtureRequest) -> Iterator[Target]:
    """Each gles build, then Mesa llvmpipe (skipped where it cannot run)."""
    yield from open_target(request)


def tolerance(kind: str) -> float:
    """Per-channel colour tolerance of a build (module docstring); llvmpipe filters
    with 8-bit weights and 8-bit intermediate colours, one more 8-bit step."""
    return VISUAL_TOL + {"fixed": FIXED_EXTRA, "llvmpipe": 2.0**-8}.get(kind, 0.0)


def coord_slack(kind: str, smax: float) -> float:
    """How far (in s units) a build may put an interpolated coordinate whose
    vertex values reach |smax|: fixed keeps 0.30 weights and 32 fraction
    bits, float a 24-bit significand, llvmpipe float32 plus its own steps."""
    rel = {"fixed": 2.0**-27, "float": 2.0**-20, "double": 2.0**-45, "llvmpipe": 2.0**-18}[kind]
    return (abs(smax) + 1.0) * rel


# {================================================================
# the model (§3.7.6, §3.7.7 equations 3.16-3.18)


def wrap_coord(s: np.ndarray, n: int, mode: int) -> np.ndarray:
    """The coordinate after §3.7.6 wrapping (OES_texture_mirrored_repeat too)."""
    s = np.asarray(s, dtype=np.float64)
    lo, hi = 1.0 / (2 * n), 1.0 - 1.0 / (2 * n)
    if mode == REPEAT:
        return s - np.floor(s)
    if mode == MIRROR:
        f = s - np.floor(s)
        s = np.where(np.floor(s) % 2 == 0, f, 1.0 - f)
    return np.clip(s, lo, hi)


def nearest_index(s: np.ndarray, n: int, mode: int) -> np.ndarray:
    """Equation 3.16: i = floor(u), n - 1 at s = 1."""
    u = wrap_coord(s, n, mode) * n
    return np.clip(np.floor(u), 0, n - 1).astype(np.int64)


def linear_index(s: np.ndarray, n: int, mode: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """i0, i1 and alpha of equation 3.18."""
    u = wrap_coord(s, n, mode) * n - 0.5
    i0 = np.floor(u)
    a = u - i0
    i0 = i0.astype(np.int64)
    i1 = i0 + 1
    if mode == REPEAT:
        return i0 % n, i1 % n, a
    return np.clip(i0, 0, n - 1), np.clip(i1, 0, n - 1), a


def sample(tex: np.ndarray, s: Any, t: Any, filt: int, ws: int = REPEAT, wt: int = REPEAT) -> np.ndarray:
    """The filtered texel (§3.7.7) of float RGBA `tex` (rows j from the bottom) at s, t."""
    h, w = tex.shape[:2]
    s, t = np.broadcast_arrays(np.asarray(s, np.float64), np.asarray(t, np.float64))
    if filt == NEAREST:
        return tex[nearest_index(t, h, wt), nearest_index(s, w, ws)]
    i0, i1, a = linear_index(s, w, ws)
    j0, j1, b = linear_index(t, h, wt)
    a, b = a[..., None], b[..., None]
    return ((1 - a) * (1 - b) * tex[j0, i0] + a * (1 - b) * tex[j0, i1]
            + (1 - a) * b * tex[j1, i0] + a * b * tex[j1, i1])


def sample_range(tex: np.ndarray, s: np.ndarray, t: np.ndarray, ds: float, dt: float, filt: int,
                 ws: int = REPEAT, wt: int = REPEAT) -> tuple[np.ndarray, np.ndarray]:
    """Per-channel min and max of `sample` over [s - ds, s + ds] x [t - dt, t + dt],
    probed at steps of at most a third of a texel."""
    h, w = tex.shape[:2]
    ks = int(np.ceil(2 * ds * w * 3)) + 1
    kt = int(np.ceil(2 * dt * h * 3)) + 1
    lo = hi = sample(tex, s, t, filt, ws, wt)
    for fs in np.linspace(-1.0, 1.0, ks + 1 if ks > 1 else 2):
        for ft in np.linspace(-1.0, 1.0, kt + 1 if kt > 1 else 2):
            v = sample(tex, s + fs * ds, t + ft * dt, filt, ws, wt)
            lo, hi = np.minimum(lo, v), np.maximum(hi, v)
    return lo, hi


def centres(x0: int, y0: int, x1: int, y1: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixel-centre window coordinates of the rectangle [x0, x1) x [y0, y1), shape (rows, cols)."""
    return np.meshgrid(np.arange(x0, x1) + 0.5, np.arange(y0, y1) + 0.5)


def affine_st(x0: float, y0: float, x1: float, y1: float, st0: Any, st1: Any,
              px: np.ndarray, py: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """s, t at window points of a screen-aligned quad with (s, t) = st0 at (x0, y0), st1 at (x1, y1)."""
    s = st0[0] + (px - x0) / (x1 - x0) * (st1[0] - st0[0])
    t = st0[1] + (py - y0) / (y1 - y0) * (st1[1] - st0[1])
    return s, t


def unorm(u8: Any) -> np.ndarray:
    return np.asarray(u8, dtype=np.float64) / 255.0


def expect_close(img: np.ndarray, want: np.ndarray, tol: Any, what: str,
                 lo: np.ndarray | None = None, hi: np.ndarray | None = None) -> float:
    """Every channel within tol of `want` (or of [lo, hi] when given); returns the max error."""
    if lo is None or hi is None:
        lo = hi = want
    err = np.maximum(lo - img, img - hi).clip(0)
    worst = float(err.max()) if err.size else 0.0
    bad = (err > tol).any(axis=-1)
    if bad.any():
        idx = np.unravel_index(int(np.argmax(np.where(bad, err.max(axis=-1), -1))), err.shape[:-1])
        raise AssertionError(
            f"{what}: {int(bad.sum())} pixels off by up to {worst * 255:.2f}/255; "
            f"first worst at (row, col) {tuple(int(i) for i in idx)}: got {np.round(img[idx] * 255, 1)}, "
            f"want {np.round(lo[idx] * 255, 1)}..{np.round(hi[idx] * 255, 1)}")
    return worst


# {================================================================
# GL helpers


def ortho(gl: Any, w: int, h: int) -> None:
    set_ortho(gl, w, h)


def make_texture(gl: Any, rgba_u8: np.ndarray, fmt: int = C.GL_RGBA, *, min_filter: int = NEAREST,
                 mag_filter: int = NEAREST, wrap: tuple[int, int] = (REPEAT, REPEAT),
                 levels: list[np.ndarray] | None = None, generate_mipmap: bool = False) -> int:
    """A new texture object on the active unit from uint8 (h, w, 4) RGBA data,
    stored in base format `fmt` (its components taken as Table 3.8 says); more
    levels from `levels`, or all of them by GENERATE_MIPMAP."""
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    if generate_mipmap:
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    for lvl, img in enumerate([rgba_u8] + list(levels or [])):
        h, w = img.shape[:2]
        gl.glTexImage2D(C.GL_TEXTURE_2D, lvl, fmt, w, h, 0, fmt, C.GL_UNSIGNED_BYTE, client_bytes(img, fmt))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, min_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, mag_filter)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, wrap[0])
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, wrap[1])
    return name


def client_bytes(rgba_u8: np.ndarray, fmt: int) -> np.ndarray:
    """uint8 RGBA (h, w, 4) as tightly packed UNSIGNED_BYTE data of `fmt`."""
    sel = {C.GL_RGBA: [0, 1, 2, 3], C.GL_RGB: [0, 1, 2], C.GL_LUMINANCE_ALPHA: [0, 3],
           C.GL_LUMINANCE: [0], C.GL_ALPHA: [3]}[fmt]
    return np.ascontiguousarray(rgba_u8[..., sel], dtype=np.uint8)


def base_color(rgba: np.ndarray, fmt: int) -> np.ndarray:
    """Table 3.14: the texture source colour (Cs, As) of float RGBA texels stored as `fmt`."""
    out = np.array(rgba, dtype=np.float64, copy=True)
    if fmt == C.GL_ALPHA:
        out[..., :3] = 0.0
    if fmt in (C.GL_LUMINANCE, C.GL_LUMINANCE_ALPHA):
        out[..., 1] = out[..., 2] = out[..., 0]
    if fmt in (C.GL_LUMINANCE, C.GL_RGB):
        out[..., 3] = 1.0
    return out


def env(gl: Any, mode: int, **kw: Any) -> None:
    """glTexEnvi(TEXTURE_ENV_MODE, mode) and any GL_<name>=value pairs on the active unit."""
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, mode)
    for k, v in kw.items():
        pname = getattr(C, "GL_" + k)
        if pname == C.GL_TEXTURE_ENV_COLOR:
            gl.glTexEnvxv(C.GL_TEXTURE_ENV, pname, [int(round(c * 65536)) for c in v])
        elif pname in (C.GL_RGB_SCALE, C.GL_ALPHA_SCALE):
            gl.glTexEnvx(C.GL_TEXTURE_ENV, pname, int(v * 65536))
        else:
            gl.glTexEnvi(C.GL_TEXTURE_ENV, pname, v)


class Quad(NamedTuple):
    """A screen-aligned quad in window pixels with texture coordinates per unit:
    coords[u] = (st at (x0, y0), st at (x1, y1)), or four (s, t, r, q) rows in
    strip order for projective coordinates."""

    x0: float
    y0: float
    x1: float
    y1: float
    coords: tuple


def draw_quad(gl: Any, q: Quad, color: Any = None) -> None:
    """Draw `q` as a GL_TRIANGLE_STRIP (vertices (x0,y0), (x1,y0), (x0,y1), (x1,y1));
    texture coordinates from FLOAT arrays on units 0.. len(coords) - 1."""
    v = np.array([q.x0, q.y0, q.x1, q.y0, q.x0, q.y1, q.x1, q.y1], dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)
    if color is not None:
        gl.glColor4ub(*[int(c) for c in color])
    keep = []
    for u, c in enumerate(q.coords):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + u)
        arr = np.asarray(c, dtype=np.float64)
        if arr.shape == (2, 2):
            (s0, t0), (s1, t1) = arr
            tc = np.array([s0, t0, s1, t0, s0, t1, s1, t1], dtype=np.float32)
            size = 2
        else:
            tc = np.ascontiguousarray(arr.reshape(-1), dtype=np.float32)
            size = arr.shape[1]
        keep.append(tc)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(size, C.GL_FLOAT, 0, tc)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    for u in range(len(q.coords)):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + u)
        gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glClientActiveTexture(C.GL_TEXTURE0)


def quad_st(q: Quad, unit: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Model s, t at the pixel centres the quad covers (integer corners)."""
    px, py = centres(int(q.x0), int(q.y0), int(q.x1), int(q.y1))
    (s0, t0), (s1, t1) = q.coords[unit]
    return affine_st(q.x0, q.y0, q.x1, q.y1, (s0, t0), (s1, t1), px, py)


def region(img: np.ndarray, q: Quad) -> np.ndarray:
    return img[int(q.y0):int(q.y1), int(q.x0):int(q.x1)]


def render_quads(t: Target, quads: list[Quad], setup: Callable[[Any], None] | None = None,
                 color: Any = FRAG) -> np.ndarray:
    """Clear to black, draw each quad (after `setup`) and read back."""
    gl = t.gl
    ortho(gl, t.w, t.h)
    gl.glClearColorx(0, 0, 0, 0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    if setup is not None:
        setup(gl)
    for q in quads:
        draw_quad(gl, q, color)
    assert gl.glGetError() == 0
    return t.read()


def rand_tex(rng: np.random.Generator, w: int, h: int) -> np.ndarray:
    return rng.integers(0, 256, size=(h, w, 4), dtype=np.uint8)


# {================================================================
# texture objects and unit state (§3.7.11, §3.7.13, §2.10.2, §6.2)


def test_limits_and_initial_state():
    """MAX_TEXTURE_UNITS 4, MAX_TEXTURE_SIZE 2048, and the initial per-unit state of §6.2."""
    gl = make_ctx("fixed", 8, 8).gl
    assert gl.glGetIntegerv(C.GL_MAX_TEXTURE_UNITS) == 4
    assert gl.glGetIntegerv(C.GL_MAX_TEXTURE_SIZE) == 2048
    assert gl.glGetIntegerv(C.GL_ACTIVE_TEXTURE) == C.GL_TEXTURE0
    assert gl.glGetIntegerv(C.GL_CLIENT_ACTIVE_TEXTURE) == C.GL_TEXTURE0
    # the ten paletted formats and ETC1_RGB8_OES
    assert gl.glGetIntegerv(C.GL_NUM_COMPRESSED_TEXTURE_FORMATS) == 11
    assert sorted(gl.glGetIntegerv(C.GL_COMPRESSED_TEXTURE_FORMATS)) == list(range(0x8B90, 0x8B9A)) + [0x8D64]
    for u in range(4):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        assert gl.glGetIntegerv(C.GL_ACTIVE_TEXTURE) == C.GL_TEXTURE0 + u
        assert not gl.glIsEnabled(C.GL_TEXTURE_2D)
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D) == 0
        assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER) == C.GL_NEAREST_MIPMAP_LINEAR
        assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER) == C.GL_LINEAR
        assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S) == C.GL_REPEAT
        assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T) == C.GL_REPEAT
        assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP) == 0
        e = lambda p: gl.glGetTexEnviv(C.GL_TEXTURE_ENV, p)  # noqa: E731
        assert e(C.GL_TEXTURE_ENV_MODE) == C.GL_MODULATE
        assert e(C.GL_COMBINE_RGB) == C.GL_MODULATE and e(C.GL_COMBINE_ALPHA) == C.GL_MODULATE
        assert [e(C.GL_SRC0_RGB), e(C.GL_SRC1_RGB), e(C.GL_SRC2_RGB)] == [
            C.GL_TEXTURE, C.GL_PREVIOUS, C.GL_CONSTANT]
        assert [e(C.GL_SRC0_ALPHA), e(C.GL_SRC1_ALPHA), e(C.GL_SRC2_ALPHA)] == [
            C.GL_TEXTURE, C.GL_PREVIOUS, C.GL_CONSTANT]
        assert [e(C.GL_OPERAND0_RGB), e(C.GL_OPERAND1_RGB), e(C.GL_OPERAND2_RGB)] == [
            C.GL_SRC_COLOR, C.GL_SRC_COLOR, C.GL_SRC_ALPHA]
        alpha_ops = [e(C.GL_OPERAND0_ALPHA), e(C.GL_OPERAND1_ALPHA), e(C.GL_OPERAND2_ALPHA)]
        assert alpha_ops == [C.GL_SRC_ALPHA] * 3
        assert list(gl.glGetTexEnvxv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR)) == [0, 0, 0, 0]
        assert gl.glGetTexEnvxv(C.GL_TEXTURE_ENV, C.GL_RGB_SCALE) == 65536
        assert gl.glGetTexEnvxv(C.GL_TEXTURE_ENV, C.GL_ALPHA_SCALE) == 65536
    assert gl.glGetError() == 0


def test_objects_gen_bind_delete_is():
    """GenTextures gives unused names; a name becomes a texture when bound;
    DeleteTextures rebinds 0 on every unit that had it and ignores 0 and unused names (§3.7.11)."""
    gl = make_ctx("fixed", 8, 8).gl
    names = [int(n) for n in gl.glGenTextures(3)]
    assert len(set(names)) == 3 and 0 not in names
    assert not any(gl.glIsTexture(n) for n in names)       # no state until bound
    assert int(gl.glGenTextures(1)) not in names           # marked used by GenTextures
    gl.glBindTexture(C.GL_TEXTURE_2D, names[0])
    assert gl.glIsTexture(names[0]) and not gl.glIsTexture(names[1])
    assert not gl.glIsTexture(0)
    # an object keeps its own parameters; name 0 is the default texture
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
    gl.glBindTexture(C.GL_TEXTURE_2D, 0)
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S) == C.GL_REPEAT
    gl.glBindTexture(C.GL_TEXTURE_2D, 777)                   # binding an unused name creates it
    assert gl.glIsTexture(777)
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER) == C.GL_NEAREST_MIPMAP_LINEAR
    # shared among units
    for u in (0, 2, 3):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        gl.glBindTexture(C.GL_TEXTURE_2D, names[0])
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glBindTexture(C.GL_TEXTURE_2D, names[1])
    gl.glActiveTexture(C.GL_TEXTURE2)
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S) == C.GL_CLAMP_TO_EDGE
    gl.glDeleteTextures(4, [0, names[0], 123456, names[0]])
    assert gl.glGetError() == 0
    bound = []
    for u in range(4):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        bound.append(gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D))
    assert bound == [0, names[1], 0, 0]
    assert not gl.glIsTexture(names[0]) and gl.glIsTexture(names[1])
    # the deleted name is unused again: binding it makes a fresh object
    gl.glBindTexture(C.GL_TEXTURE_2D, names[0])
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S) == C.GL_REPEAT
    assert gl.glGetError() == 0


def test_unit_state_is_per_unit():
    """ActiveTexture selects TEXTURE_2D enable, binding, environment and texture
    matrix (stack) per unit; ClientActiveTexture selects the texcoord array (§2.7, §2.8, §2.10.2)."""
    gl = make_ctx("fixed", 8, 8).gl
    modes = (C.GL_ADD, C.GL_DECAL, C.GL_BLEND, C.GL_REPLACE)
    gl.glMatrixMode(C.GL_TEXTURE)
    for u in range(4):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        gl.glBindTexture(C.GL_TEXTURE_2D, 10 + u)
        if u % 2:
            gl.glEnable(C.GL_TEXTURE_2D)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, modes[u])
        gl.glLoadIdentity()
        gl.glTranslatex((u + 1) << 16, 0, 0)
        for _ in range(u % 2):
            gl.glPushMatrix()
    for u in range(4):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        assert gl.glIsEnabled(C.GL_TEXTURE_2D) == bool(u % 2)
        assert gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D) == 10 + u
        assert gl.glGetTexEnviv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE) == modes[u]
        m = np.asarray(gl.glGetFloatv(C.GL_TEXTURE_MATRIX)).reshape(4, 4)
        assert m[3, 0] == u + 1
        assert gl.glGetIntegerv(C.GL_TEXTURE_STACK_DEPTH) == 1 + u % 2
    for u in range(4):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + u)
        if u == 2:
            gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    for u in range(4):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + u)
        assert gl.glIsEnabled(C.GL_TEXTURE_COORD_ARRAY) == (u == 2)
    assert gl.glGetIntegerv(C.GL_ACTIVE_TEXTURE) == C.GL_TEXTURE3
    assert gl.glGetError() == 0


# {================================================================
# images: TexImage2D for all 8 format/type pairs with UNPACK_ALIGNMENT (§3.6.2, §3.7.1)


def decode(raw: np.ndarray, fmt: int, gltype: int, w: int, h: int, align: int) -> np.ndarray:
    """Client image bytes to float RGBA (h, w, 4) as §3.6.2 unpacks them (before Table 3.8)."""
    if gltype == C.GL_UNSIGNED_BYTE:
        n = BPP[fmt]
        stride = -(-w * n // align) * align
        rows = np.stack([raw[j * stride: j * stride + w * n] for j in range(h)]).reshape(h, w, n)
        c = rows.astype(np.float64) / 255.0
        out = np.zeros((h, w, 4))
        out[..., 3] = 1.0
        if fmt == C.GL_ALPHA:
            out[..., 3] = c[..., 0]
        elif fmt in (C.GL_LUMINANCE, C.GL_LUMINANCE_ALPHA):
            out[..., :3] = c[..., :1]
            if fmt == C.GL_LUMINANCE_ALPHA:
                out[..., 3] = c[..., 1]
        else:
            out[..., :n] = c
        return out
    stride = -(-w * 2 // align) * align
    v = np.stack([raw[j * stride: j * stride + 2 * w].view("<u2") for j in range(h)]).astype(np.int64)
    out = np.ones((h, w, 4))
    if gltype == C.GL_UNSIGNED_SHORT_5_6_5:
        out[..., 0], out[..., 1], out[..., 2] = (v >> 11) / 31, ((v >> 5) & 63) / 63, (v & 31) / 31
    elif gltype == C.GL_UNSIGNED_SHORT_4_4_4_4:
        for k in range(4):
            out[..., k] = ((v >> (12 - 4 * k)) & 15) / 15
    else:
        out[..., 0], out[..., 1], out[..., 2] = (v >> 11) / 31, ((v >> 6) & 31) / 31, ((v >> 1) & 31) / 31
        out[..., 3] = v & 1
    return out


def image_bytes(fmt: int, gltype: int, w: int, h: int, align: int) -> int:
    """What TexImage2D reads: full rows padded to the alignment, the last row unpadded."""
    n = BPP[fmt] if gltype == C.GL_UNSIGNED_BYTE else 2
    return -(-w * n // align) * align * (h - 1) + w * n


def replace_view(t: Target, fmt: int, w: int, h: int, zoom: int = 4, color: tuple = FRAG) -> np.ndarray:
    """Draw the bound texture 1:1 (zoomed), NEAREST, REPLACE, over a flat colour; read it back."""
    gl = t.gl
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, NEAREST)
    env(gl, C.GL_REPLACE)
    q = Quad(0, 0, w * zoom, h * zoom, (((0, 0), (1, 1)),))
    img = render_quads(t, [q], color=color)
    return region(img, q)[::zoom, ::zoom]


def replace_expect(texels: np.ndarray, fmt: int, color: tuple = FRAG) -> np.ndarray:
    """Table 3.15 REPLACE: Cv = Cs (Cp for ALPHA), Av = As (Ap for LUMINANCE and RGB)."""
    cs = base_color(texels, fmt)
    cp = np.broadcast_to(unorm(color), cs.shape)
    out = cs.copy()
    if fmt == C.GL_ALPHA:
        out[..., :3] = cp[..., :3]
    if fmt in (C.GL_LUMINANCE, C.GL_RGB):
        out[..., 3] = cp[..., 3]
    return out


@pytest.mark.parametrize("pair", PAIRS, ids=lambda p: f"{C.NAMES[p[0]]}-{C.NAMES[p[1]]}")
def test_teximage_all_pairs_and_alignment(target: Target, pair: tuple[int, int]):
    """Each format/type pair at UNPACK_ALIGNMENT 1, 2, 4 and 8 (padding bytes are
    garbage and must not be read; the last row needs no padding) gives the texels
    of §3.6.2 and Table 3.8, seen through REPLACE."""
    fmt, gltype = pair
    gl = target.gl
    rng = np.random.default_rng(fmt * 7 + gltype)
    w, h = 2, 8                      # rows of 2 texels: padded at alignment 4 and 8
    for align in (1, 2, 4, 8):
        need = image_bytes(fmt, gltype, w, h, align)
        raw = rng.integers(0, 256, size=need, dtype=np.uint8)
        name = int(gl.glGenTextures(1))
        gl.glBindTexture(C.GL_TEXTURE_2D, name)
        gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, align)
        assert gl.glGetIntegerv(C.GL_UNPACK_ALIGNMENT) == align
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, w, h, 0, fmt, gltype, raw)
        assert gl.glGetError() == 0
        texels = decode(raw, fmt, gltype, w, h, align)
        got = replace_view(target, fmt, w, h)
        expect_close(got, replace_expect(texels, fmt), tolerance(target.kind),
                     f"{C.NAMES[fmt]}/{C.NAMES[gltype]} alignment {align}")
        gl.glDeleteTextures(1, [name])


def test_teximage_short_data_is_refused():
    """Pixel data shorter than the rows TexImage2D reads raises ValueError and defines nothing."""
    gl = make_ctx("fixed", 8, 8).gl
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 4)
    need = image_bytes(C.GL_RGB, C.GL_UNSIGNED_BYTE, 2, 4, 4)      # 8 * 3 + 6
    gl.glBindTexture(C.GL_TEXTURE_2D, 5)
    with pytest.raises(ValueError):
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGB, 2, 4, 0, C.GL_RGB, C.GL_UNSIGNED_BYTE, bytes(need - 1))
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGB, 2, 4, 0, C.GL_RGB, C.GL_UNSIGNED_BYTE, bytes(need))
    assert gl.glGetError() == 0


@pytest.mark.parametrize("pair", PAIRS, ids=lambda p: f"{C.NAMES[p[0]]}-{C.NAMES[p[1]]}")
def test_texsubimage_all_pairs(numeric: str, pair: tuple[int, int]):
    """TexSubImage2D replaces exactly its rectangle (alignment 8, odd offsets), leaves
    the other texels, and a null image keeps the contents (§3.7.2)."""
    fmt, gltype = pair
    t = Target(numeric)
    gl = t.gl
    rng = np.random.default_rng(fmt + 3 * gltype)
    w, h = 8, 4
    raw = rng.integers(0, 256, size=image_bytes(fmt, gltype, w, h, 1), dtype=np.uint8)
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, w, h, 0, fmt, gltype, raw)
    texels = decode(raw, fmt, gltype, w, h, 1)
    rects = (((1, 1, 3, 2), 8), ((5, 0, 3, 4), 2), ((0, 3, 8, 1), 4), ((2, 2, 0, 1), 1))
    for (x, y, sw, sh), align in rects:
        sub = rng.integers(0, 256, size=image_bytes(fmt, gltype, max(sw, 1), sh, align), dtype=np.uint8)
        gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, align)
        gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, x, y, sw, sh, fmt, gltype, sub)
        assert gl.glGetError() == 0
        if sw:
            texels[y:y + sh, x:x + sw] = decode(sub, fmt, gltype, sw, sh, align)
        got = replace_view(t, fmt, w, h)
        expect_close(got, replace_expect(texels, fmt), tolerance(numeric), f"sub-image at {(x, y, sw, sh)}")
    gl.glTexImage2D(C.GL_TEXTURE_2D, 1, fmt, 4, 2, 0, fmt, gltype, None)   # defined, contents unspecified
    gl.glTexSubImage2D(C.GL_TEXTURE_2D, 1, 0, 0, 4, 2, fmt, gltype, raw)
    assert gl.glGetError() == 0


# {================================================================
# CopyTexImage2D and CopyTexSubImage2D (§3.7.2, Table 3.9)

COPY_FORMATS = (C.GL_ALPHA, C.GL_LUMINANCE, C.GL_LUMINANCE_ALPHA, C.GL_RGB, C.GL_RGBA)


def paint(gl: Any, w: int, h: int, seed: int) -> None:
    """Fill the window with smooth random colours (alpha too)."""
    rng = np.random.default_rng(seed)
    ortho(gl, w, h)
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glShadeModel(C.GL_SMOOTH)
    v = np.array([0, 0, w, 0, 0, h, w, h, w / 2, h / 2, 0, 0], dtype=np.float32)
    idx = np.array([0, 1, 4, 1, 3, 4, 3, 2, 4, 2, 0, 4], dtype=np.uint16)
    col = rng.integers(0, 256, size=(6, 4), dtype=np.uint8)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, v)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, col)
    gl.glDrawElements(C.GL_TRIANGLES, 12, C.GL_UNSIGNED_SHORT, idx)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)


@pytest.mark.parametrize("color", ["rgba8888", "rgb565"])
def test_copyteximage(numeric: str, color: str):
    """CopyTexImage2D takes the texels ReadPixels(RGBA) would return and keeps the
    components of Table 3.8; on RGB565 only LUMINANCE and RGB are legal (Table 3.9)."""
    t = Target(numeric, 32, 32, color=color)
    gl = t.gl
    paint(gl, 32, 32, seed=1)
    fb = gl.glReadPixels(0, 0, 32, 32, C.GL_RGBA, C.GL_UNSIGNED_BYTE).astype(np.float64) / 255.0
    x, y, w, h = 3, 5, 16, 8
    for fmt in COPY_FORMATS:
        legal = color == "rgba8888" or fmt in (C.GL_LUMINANCE, C.GL_RGB)
        gl.glBindTexture(C.GL_TEXTURE_2D, 0)
        gl.glCopyTexImage2D(C.GL_TEXTURE_2D, 0, fmt, x, y, w, h, 0)
        err = gl.glGetError()
        if not legal:
            assert err == C.GL_INVALID_OPERATION, C.NAMES[fmt]
            continue
        assert err == 0
        texels = fb[y:y + h, x:x + w]
        got = replace_view(t, fmt, w, h, zoom=2)
        want = replace_expect(texels, fmt)
        tol = tolerance(numeric)
        if color == "rgb565":
            # drawn back into the 565 buffer, which rounds each channel to its bits again
            want[..., 3] = 1.0
            tol = RGB565_TOL
        expect_close(got, want, tol, f"CopyTexImage2D {C.NAMES[fmt]} on {color}")
        paint(gl, 32, 32, seed=1)


@pytest.mark.parametrize("color", ["rgba8888", "rgb565"])
@pytest.mark.parametrize("origin", [(-3, -2), (22, 27), (-5, 20), (30, -7)])
def test_copyteximage_across_the_window_edge(numeric: str, color: str, origin: tuple[int, int]):
    """A copy rectangle that crosses the window's edges: the texels of the
    part inside are the framebuffer's (as ReadPixels returns them), whatever
    the format; the call succeeds (§3.7.2 leaves the part outside undefined)."""
    t = Target(numeric, 32, 32, color=color)
    gl = t.gl
    paint(gl, 32, 32, seed=5)
    fb = gl.glReadPixels(0, 0, 32, 32, C.GL_RGBA, C.GL_UNSIGNED_BYTE).astype(np.float64) / 255.0
    x, y = origin
    w, h = 16, 8
    sx, sy = slice(max(x, 0), min(x + w, 32)), slice(max(y, 0), min(y + h, 32))
    inside = (slice(sy.start - y, sy.stop - y), slice(sx.start - x, sx.stop - x))
    for fmt in (C.GL_RGB, C.GL_LUMINANCE) + ((C.GL_RGBA, C.GL_ALPHA) if color == "rgba8888" else ()):
        gl.glBindTexture(C.GL_TEXTURE_2D, 0)
        gl.glCopyTexImage2D(C.GL_TEXTURE_2D, 0, fmt, x, y, w, h, 0)
        assert gl.glGetError() == 0
        want = replace_expect(fb[sy, sx], fmt)
        got = replace_view(t, fmt, w, h, zoom=2)[inside]
        tol = tolerance(numeric)
        if color == "rgb565":
            want[..., 3] = 1.0
            tol = RGB565_TOL
        expect_close(got, want, tol, f"CopyTexImage2D {C.NAMES[fmt]} from {origin} on {color}")
        # and CopyTexSubImage2D of the same rectangle into the copied level
        paint(gl, 32, 32, seed=5)
        gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, x, y, w, h)
        assert gl.glGetError() == 0
        expect_close(replace_view(t, fmt, w, h, zoom=2)[inside], want, tol,
                     f"CopyTexSubImage2D {C.NAMES[fmt]} from {origin} on {color}")
        paint(gl, 32, 32, seed=5)


def test_copytexsubimage(numeric: str):
    """CopyTexSubImage2D replaces a rectangle of an existing level with framebuffer
    pixels and leaves the rest; errors leave the texture alone (§3.7.2)."""
    t = Target(numeric, 32, 32)
    gl = t.gl
    rng = np.random.default_rng(3)
    base = rand_tex(rng, 8, 8)
    make_texture(gl, base)
    paint(gl, 32, 32, seed=2)
    fb = gl.glReadPixels(0, 0, 32, 32, C.GL_RGBA, C.GL_UNSIGNED_BYTE).astype(np.float64) / 255.0
    gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 2, 3, 20, 9, 5, 4)
    assert gl.glGetError() == 0
    want = unorm(base)
    want[3:7, 2:7] = fb[9:13, 20:25]
    got = replace_view(t, C.GL_RGBA, 8, 8, zoom=4)
    expect_close(got, want, tolerance(numeric), "CopyTexSubImage2D")
    gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 6, 3, 0, 0, 3, 1)       # 6 + 3 > 8
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 1, 0, 0, 0, 0, 1, 1)       # level 1 undefined
    assert gl.glGetError() == C.GL_INVALID_VALUE
    got2 = replace_view(t, C.GL_RGBA, 8, 8, zoom=4)
    assert np.array_equal(got, got2)


def test_copytexsubimage_rgb565(numeric: str):
    """On an RGB565 framebuffer CopyTexSubImage2D into an RGBA texture is INVALID_OPERATION
    (Table 3.9); into an RGB texture it copies what ReadPixels returns, and drawn back
    into the 565 buffer those texels give the same 565 pixels."""
    t = Target(numeric, 32, 32, color="rgb565")
    gl = t.gl
    make_texture(gl, np.full((8, 8, 4), 200, np.uint8))
    gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2)
    assert gl.glGetError() == C.GL_INVALID_OPERATION
    base = np.full((8, 8, 4), (200, 100, 50, 255), np.uint8)
    make_texture(gl, base, C.GL_RGB)
    paint(gl, 32, 32, seed=4)
    fb = gl.glReadPixels(0, 0, 32, 32, C.GL_RGBA, C.GL_UNSIGNED_BYTE).astype(np.float64) / 255.0
    gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 1, 2, 10, 20, 6, 5)
    assert gl.glGetError() == 0
    want = replace_expect(unorm(base), C.GL_RGB)
    want[2:7, 1:7, :3] = fb[20:25, 10:16, :3]
    want[..., 3] = 1.0                          # no alpha bits
    expect_close(replace_view(t, C.GL_RGB, 8, 8), want, RGB565_TOL, "CopyTexSubImage2D on RGB565")


# {================================================================
# OES_compressed_paletted_texture (§3.7.4)

PALETTE_FORMATS = {
    # format: (index bits, entry format, entry type)
    C.GL_PALETTE4_RGB8_OES: (4, C.GL_RGB, C.GL_UNSIGNED_BYTE),
    C.GL_PALETTE4_RGBA8_OES: (4, C.GL_RGBA, C.GL_UNSIGNED_BYTE),
    C.GL_PALETTE4_R5_G6_B5_OES: (4, C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5),
    C.GL_PALETTE4_RGBA4_OES: (4, C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4),
    C.GL_PALETTE4_RGB5_A1_OES: (4, C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1),
    C.GL_PALETTE8_RGB8_OES: (8, C.GL_RGB, C.GL_UNSIGNED_BYTE),
    C.GL_PALETTE8_RGBA8_OES: (8, C.GL_RGBA, C.GL_UNSIGNED_BYTE),
    C.GL_PALETTE8_R5_G6_B5_OES: (8, C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5),
    C.GL_PALETTE8_RGBA4_OES: (8, C.GL_RGBA, C.GL_UNSIGNED_SHORT_4_4_4_4),
    C.GL_PALETTE8_RGB5_A1_OES: (8, C.GL_RGBA, C.GL_UNSIGNED_SHORT_5_5_5_1),
}


def paletted_image(rng: np.random.Generator, fmt: int, w: int, h: int,
                   levels: int) -> tuple[bytes, list[np.ndarray], int]:
    """(data, float RGBA texels of each level, base format) of a paletted image:
    the palette, then each level's indices (4-bit: first texel in the high nibble)."""
    bits, efmt, etype = PALETTE_FORMATS[fmt]
    entries = 1 << bits
    ebytes = BPP[efmt] if etype == C.GL_UNSIGNED_BYTE else 2
    pal_raw = rng.integers(0, 256, size=entries * ebytes, dtype=np.uint8)
    palette = decode(pal_raw, efmt, etype, entries, 1, 1)[0]
    data = [pal_raw.tobytes()]
    out = []
    lw, lh = w, h
    for _ in range(levels):
        idx = rng.integers(0, entries, size=lw * lh)
        out.append(palette[idx].reshape(lh, lw, 4))
        if bits == 8:
            data.append(idx.astype(np.uint8).tobytes())
        else:
            pad = np.append(idx, 0) if idx.size % 2 else idx
            data.append(((pad[0::2] << 4) | pad[1::2]).astype(np.uint8).tobytes())
        lw, lh = max(lw // 2, 1), max(lh // 2, 1)
    return b"".join(data), out, efmt


@pytest.mark.parametrize("fmt", list(PALETTE_FORMATS), ids=lambda f: C.NAMES[f])
def test_paletted_all_formats_several_levels(target: Target, fmt: int):
    """Each of the 10 PALETTE*_OES formats with level -3 (four levels 8x4 .. 1x1 in one
    image): every level decodes to its palette entries (level d viewed at lambda = d
    with NEAREST_MIPMAP_NEAREST, one texel per pixel)."""
    gl = target.gl
    rng = np.random.default_rng(fmt)
    w, h = 8, 4
    data, levels, base = paletted_image(rng, fmt, w, h, 4)
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, -3, fmt, w, h, 0, len(data), data)
    assert gl.glGetError() == 0
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, NEAREST)
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    quads = [Quad(16 * d, 0, 16 * d + max(w >> d, 1), max(h >> d, 1), (((0, 0), (1, 1)),)) for d in range(4)]
    img = render_quads(target, quads)
    for d, q in enumerate(quads):
        expect_close(region(img, q), replace_expect(levels[d], base), tolerance(target.kind),
                     f"{C.NAMES[fmt]} level {d}")


def test_paletted_single_level_and_sizes(numeric: str):
    """Level 0 gives one level; the imageSize must match palette + indices exactly
    (INVALID_VALUE otherwise); a positive level is INVALID_VALUE (§3.7.4)."""
    t = Target(numeric, 16, 16)
    gl = t.gl
    rng = np.random.default_rng(9)
    fmt = C.GL_PALETTE4_RGBA8_OES
    data, levels, base = paletted_image(rng, fmt, 4, 4, 1)
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, fmt, 4, 4, 0, len(data) + 1, data + b"\0")
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 1, fmt, 4, 4, 0, len(data), data)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, fmt, 4, 4, 0, len(data), data)
    assert gl.glGetError() == 0
    got = replace_view(t, C.GL_RGBA, 4, 4)
    expect_close(got, replace_expect(levels[0], base), tolerance(numeric), "PALETTE4_RGBA8 level 0")
    # one level with a mipmapping filter: incomplete, the unit is off
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    img = render_quads(t, [Quad(0, 0, 4, 4, (((0, 0), (1, 1)),))], color=(10, 20, 30, 40))
    expect_close(img[:4, :4], np.broadcast_to(unorm((10, 20, 30, 40)), (4, 4, 4)), VISUAL_TOL, "incomplete")


# {================================================================
# GENERATE_MIPMAP and completeness (§3.7.7, §3.7.9)


def box_mipmaps(level0: np.ndarray) -> list[np.ndarray]:
    """uint8 levels 1..q from 2x2 box filtering, each rounded to 8 bits (a 1-wide
    dimension averages the pair along the other)."""
    out = []
    cur = level0.astype(np.float64)
    while cur.shape[0] > 1 or cur.shape[1] > 1:
        h, w = cur.shape[:2]
        if h > 1:
            cur = (cur[0::2] + cur[1::2]) / 2
        if w > 1:
            cur = (cur[:, 0::2] + cur[:, 1::2]) / 2
        cur = np.floor(cur + 0.5)
        out.append(cur.astype(np.uint8))
    return out


def view_levels(t: Target, w: int, h: int, nlevels: int) -> list[np.ndarray]:
    """Each level d of the bound texture drawn at lambda = d (NEAREST_MIPMAP_NEAREST,
    REPLACE, one texel per pixel), as float RGBA."""
    gl = t.gl
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, NEAREST)
    env(gl, C.GL_REPLACE)
    quads, x = [], 0
    for d in range(nlevels):
        lw, lh = max(w >> d, 1), max(h >> d, 1)
        # lambda = d needs the full texture across w >> d pixels in the longer direction
        quads.append(Quad(x, 0, x + lw, lh, (((0, 0), (1, 1)),)))
        x += lw + 1
    img = render_quads(t, quads)
    return [region(img, q) for q in quads]


def test_generate_mipmap_box_filter(numeric: str):
    """GENERATE_MIPMAP: TexImage2D, TexSubImage2D and CopyTexImage2D of level 0 recompute
    levels 1..q; a 2x2 box filter, 8x2 (non-square) down to 1x1."""
    t = Target(numeric, 64, 16)
    gl = t.gl
    rng = np.random.default_rng(5)
    level0 = rand_tex(rng, 16, 4)
    gl.glBindTexture(C.GL_TEXTURE_2D, 1)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
    assert gl.glGetTexParameteriv(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP) == 1
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 16, 4, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, level0)
    want = [level0] + box_mipmaps(level0)
    for d, got in enumerate(view_levels(t, 16, 4, len(want))):
        expect_close(got, unorm(want[d]), tolerance(numeric), f"generated level {d}")
    # a sub-image of level 0 regenerates
    patch = rand_tex(rng, 4, 2)
    gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 8, 2, 4, 2, C.GL_RGBA, C.GL_UNSIGNED_BYTE, patch)
    level0[2:4, 8:12] = patch
    want = [level0] + box_mipmaps(level0)
    for d, got in enumerate(view_levels(t, 16, 4, len(want))):
        expect_close(got, unorm(want[d]), tolerance(numeric), f"level {d} after TexSubImage2D")
    # so does CopyTexImage2D
    paint(gl, 64, 16, seed=7)
    fb = gl.glReadPixels(0, 0, 8, 8, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    gl.glCopyTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 0, 0, 8, 8, 0)
    want = [fb] + box_mipmaps(fb)
    for d, got in enumerate(view_levels(t, 8, 8, len(want))):
        expect_close(got, unorm(want[d]), tolerance(numeric), f"level {d} after CopyTexImage2D")
    assert gl.glGetError() == 0


def test_incomplete_texture_disables_its_unit(numeric: str):
    """A mipmapping filter on an incomplete mipmap disables that unit only: missing
    level, wrong size, different format, zero-size level 0 (§3.7.9); NEAREST/LINEAR
    need level 0 alone."""
    t = Target(numeric, 16, 16)
    gl = t.gl
    red = np.zeros((4, 4, 4), np.uint8)
    red[..., 0] = red[..., 3] = 255
    col = (0, 0, 255, 255)
    q = Quad(0, 0, 16, 16, (((0, 0), (1, 1)), ((0, 0), (1, 1))))

    def shows_red() -> bool:
        img = render_quads(t, [q], color=col)
        if np.allclose(img, unorm((255, 0, 0, 255))):
            return True
        assert np.allclose(img, unorm(col)), "neither the texture nor the fragment colour"
        return False

    gl.glActiveTexture(C.GL_TEXTURE0)
    make_texture(gl, red, min_filter=C.GL_LINEAR_MIPMAP_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    assert not shows_red()                                  # levels 1, 2 missing
    gl.glTexImage2D(C.GL_TEXTURE_2D, 1, C.GL_RGBA, 2, 2, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, red[:2, :2])
    assert not shows_red()                                  # level 2 missing
    gl.glTexImage2D(C.GL_TEXTURE_2D, 2, C.GL_RGBA, 2, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, red[:1, :2])
    assert not shows_red()                                  # level 2 has the wrong size
    gl.glTexImage2D(C.GL_TEXTURE_2D, 2, C.GL_RGB, 1, 1, 0, C.GL_RGB, C.GL_UNSIGNED_BYTE, red[:1, :1, :3])
    assert not shows_red()                                  # level 2 has another format
    gl.glTexImage2D(C.GL_TEXTURE_2D, 2, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, red[:1, :1])
    assert shows_red()                                      # complete
    gl.glTexImage2D(C.GL_TEXTURE_2D, 1, C.GL_RGBA, 0, 0, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, None)
    assert not shows_red()                                  # level 1 emptied
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, LINEAR)
    assert shows_red()                                      # no mipmap needed
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 0, 4, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, None)
    assert not shows_red()                                  # null level 0: as if disabled
    # an incomplete unit 0 leaves the later units working on the primary colour
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST_MIPMAP_NEAREST)
    gl.glActiveTexture(C.GL_TEXTURE1)
    half = np.full((4, 4, 4), 128, np.uint8)
    make_texture(gl, half)
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_MODULATE)
    img = render_quads(t, [q], color=col)
    expect_close(img, np.broadcast_to(unorm(col) * 128 / 255, img.shape), tolerance(numeric),
                 "unit 1 after an incomplete unit 0")


# {================================================================
# errors: the command is ignored (§2.5, §3.7)


class ErrRow(NamedTuple):
    name: str
    call: Callable[[Any], Any]
    errors: tuple[int, ...]        # acceptable errors (more than one where specs differ)
    color: str = "rgba8888"


E, V, OP = C.GL_INVALID_ENUM, C.GL_INVALID_VALUE, C.GL_INVALID_OPERATION
T2D, RGBA, UB = C.GL_TEXTURE_2D, C.GL_RGBA, C.GL_UNSIGNED_BYTE
PIX = bytes(4 * 16 * 16)
PAL = bytes(16 * 3 + 8)       # PALETTE4_RGB8, 4x4, one level
GL_CLAMP = 0x2900             # desktop GL, not in ES


def _tex(fn: str, *a: Any) -> Callable[[Any], Any]:
    return lambda g: getattr(g, fn)(*a)


ERROR_ROWS = (
    ErrRow("GenTextures n < 0", _tex("glGenTextures", -1), (V,)),
    ErrRow("DeleteTextures n < 0", _tex("glDeleteTextures", -1, [1]), (V,)),
    ErrRow("BindTexture bad target", _tex("glBindTexture", C.GL_TEXTURE, 1), (E,)),
    ErrRow("TexImage2D bad target",
           _tex("glTexImage2D", C.GL_TEXTURE, 0, RGBA, 4, 4, 0, RGBA, UB, PIX), (E,)),
    ErrRow("TexImage2D bad format",
           _tex("glTexImage2D", T2D, 0, RGBA, 4, 4, 0, C.GL_BGRA_EXT, UB, PIX), (E, OP)),
    ErrRow("TexImage2D bad type", _tex("glTexImage2D", T2D, 0, RGBA, 4, 4, 0, RGBA, C.GL_FLOAT, PIX), (E,)),
    ErrRow("TexImage2D level < 0", _tex("glTexImage2D", T2D, -1, RGBA, 4, 4, 0, RGBA, UB, PIX), (V,)),
    ErrRow("TexImage2D level > log2 max", _tex("glTexImage2D", T2D, 12, RGBA, 1, 1, 0, RGBA, UB, PIX), (V,)),
    ErrRow("TexImage2D width < 0", _tex("glTexImage2D", T2D, 0, RGBA, -4, 4, 0, RGBA, UB, PIX), (V,)),
    # (sizes need not be powers of two: OES_texture_npot)
    ErrRow("TexImage2D height < 0", _tex("glTexImage2D", T2D, 0, RGBA, 4, -3, 0, RGBA, UB, PIX), (V,)),
    ErrRow("TexImage2D height > MAX", _tex("glTexImage2D", T2D, 0, RGBA, 1, 2049, 0, RGBA, UB, None), (V,)),
    ErrRow("TexImage2D width > MAX", _tex("glTexImage2D", T2D, 0, RGBA, 4096, 1, 0, RGBA, UB, None), (V,)),
    ErrRow("TexImage2D border 1", _tex("glTexImage2D", T2D, 0, RGBA, 4, 4, 1, RGBA, UB, PIX), (V,)),
    ErrRow("TexImage2D internalformat 4", _tex("glTexImage2D", T2D, 0, 4, 4, 4, 0, RGBA, UB, PIX), (V,)),
    ErrRow("TexImage2D internalformat PALETTE", _tex("glTexImage2D", T2D, 0, C.GL_PALETTE4_RGB8_OES,
                                                      4, 4, 0, RGBA, UB, PIX), (V, OP)),
    ErrRow("TexImage2D internalformat != format",
           _tex("glTexImage2D", T2D, 0, C.GL_RGB, 4, 4, 0, RGBA, UB, PIX), (OP,)),
    ErrRow("TexImage2D RGBA with 5_6_5",
           _tex("glTexImage2D", T2D, 0, RGBA, 4, 4, 0, RGBA, C.GL_UNSIGNED_SHORT_5_6_5, PIX), (OP,)),
    ErrRow("TexImage2D RGB with 4_4_4_4", _tex("glTexImage2D", T2D, 0, C.GL_RGB, 4, 4, 0, C.GL_RGB,
                                                C.GL_UNSIGNED_SHORT_4_4_4_4, PIX), (OP,)),
    ErrRow("TexSubImage2D bad target",
           _tex("glTexSubImage2D", C.GL_TEXTURE, 0, 0, 0, 2, 2, RGBA, UB, PIX), (E,)),
    ErrRow("TexSubImage2D level < 0", _tex("glTexSubImage2D", T2D, -1, 0, 0, 2, 2, RGBA, UB, PIX), (V,)),
    ErrRow("TexSubImage2D xoffset < 0", _tex("glTexSubImage2D", T2D, 0, -1, 0, 2, 2, RGBA, UB, PIX), (V,)),
    ErrRow("TexSubImage2D x + w > width", _tex("glTexSubImage2D", T2D, 0, 3, 0, 2, 2, RGBA, UB, PIX), (V,)),
    ErrRow("TexSubImage2D y + h > height", _tex("glTexSubImage2D", T2D, 0, 0, 3, 2, 2, RGBA, UB, PIX), (V,)),
    ErrRow("TexSubImage2D width < 0", _tex("glTexSubImage2D", T2D, 0, 0, 0, -2, 2, RGBA, UB, PIX), (V,)),
    ErrRow("TexSubImage2D undefined level",
           _tex("glTexSubImage2D", T2D, 1, 0, 0, 1, 1, RGBA, UB, PIX), (V, OP)),
    ErrRow("TexSubImage2D format != internalformat",
           _tex("glTexSubImage2D", T2D, 0, 0, 0, 2, 2, C.GL_RGB, UB, PIX), (OP,)),
    ErrRow("TexSubImage2D RGBA with 5_6_5",
           _tex("glTexSubImage2D", T2D, 0, 0, 0, 2, 2, RGBA, C.GL_UNSIGNED_SHORT_5_6_5, PIX), (OP,)),
    ErrRow("TexSubImage2D bad type",
           _tex("glTexSubImage2D", T2D, 0, 0, 0, 2, 2, RGBA, C.GL_SHORT, PIX), (E,)),
    ErrRow("CopyTexImage2D bad target", _tex("glCopyTexImage2D", C.GL_TEXTURE, 0, RGBA, 0, 0, 4, 4, 0), (E,)),
    ErrRow("CopyTexImage2D level < 0", _tex("glCopyTexImage2D", T2D, -1, RGBA, 0, 0, 4, 4, 0), (V,)),
    ErrRow("CopyTexImage2D height < 0", _tex("glCopyTexImage2D", T2D, 0, RGBA, 0, 0, 4, -2, 0), (V,)),
    ErrRow("CopyTexImage2D width > MAX", _tex("glCopyTexImage2D", T2D, 0, RGBA, 0, 0, 4096, 1, 0), (V,)),
    ErrRow("CopyTexImage2D border 1", _tex("glCopyTexImage2D", T2D, 0, RGBA, 0, 0, 4, 4, 1), (V,)),
    ErrRow("CopyTexImage2D internalformat 3", _tex("glCopyTexImage2D", T2D, 0, 3, 0, 0, 4, 4, 0), (V, E)),
    ErrRow("CopyTexImage2D RGBA from RGB565", _tex("glCopyTexImage2D", T2D, 0, RGBA, 0, 0, 4, 4, 0), (OP,),
           "rgb565"),
    ErrRow("CopyTexImage2D ALPHA from RGB565", _tex("glCopyTexImage2D", T2D, 0, C.GL_ALPHA, 0, 0, 4, 4, 0),
           (OP,), "rgb565"),
    ErrRow("CopyTexSubImage2D bad target",
           _tex("glCopyTexSubImage2D", C.GL_TEXTURE, 0, 0, 0, 0, 0, 2, 2), (E,)),
    ErrRow("CopyTexSubImage2D level < 0", _tex("glCopyTexSubImage2D", T2D, -1, 0, 0, 0, 0, 2, 2), (V,)),
    ErrRow("CopyTexSubImage2D y + h > height", _tex("glCopyTexSubImage2D", T2D, 0, 0, 3, 0, 0, 2, 2), (V,)),
    ErrRow("CopyTexSubImage2D RGBA texture on RGB565",
           _tex("glCopyTexSubImage2D", T2D, 0, 0, 0, 0, 0, 2, 2), (OP,), "rgb565"),
    ErrRow("CopyTexSubImage2D of a paletted texture", lambda g: (
        g.glActiveTexture(C.GL_TEXTURE1), g.glCopyTexSubImage2D(T2D, 0, 0, 0, 0, 0, 2, 2),
        g.glActiveTexture(C.GL_TEXTURE0)), (OP,)),
    ErrRow("TexSubImage2D of a paletted texture (§3.7.4: no subimages)", lambda g: (
        g.glActiveTexture(C.GL_TEXTURE1), g.glTexSubImage2D(T2D, 0, 0, 0, 2, 2, C.GL_RGB, UB, PIX),
        g.glActiveTexture(C.GL_TEXTURE0)), (OP,)),
    ErrRow("CompressedTexImage2D RGBA", _tex("glCompressedTexImage2D", T2D, 0, RGBA, 4, 4, 0, 56, PAL), (E,)),
    ErrRow("CompressedTexImage2D bad target",
           _tex("glCompressedTexImage2D", C.GL_TEXTURE, 0, C.GL_PALETTE4_RGB8_OES, 4, 4, 0, 56, PAL), (E,)),
    ErrRow("CompressedTexImage2D level 1",
           _tex("glCompressedTexImage2D", T2D, 1, C.GL_PALETTE4_RGB8_OES, 4, 4, 0, 56, PAL), (V,)),
    ErrRow("CompressedTexImage2D imageSize short",
           _tex("glCompressedTexImage2D", T2D, 0, C.GL_PALETTE4_RGB8_OES, 4, 4, 0, 55, PAL), (V,)),
    ErrRow("CompressedTexImage2D width > MAX",
           _tex("glCompressedTexImage2D", T2D, 0, C.GL_PALETTE4_RGB8_OES, 4096, 4, 0, 54, PAL), (V,)),
    ErrRow("CompressedTexImage2D width < 0",
           _tex("glCompressedTexImage2D", T2D, 0, C.GL_PALETTE4_RGB8_OES, -4, 4, 0, 56, PAL), (V,)),
    ErrRow("CompressedTexImage2D border 1",
           _tex("glCompressedTexImage2D", T2D, 0, C.GL_PALETTE4_RGB8_OES, 4, 4, 1, 56, PAL), (V, OP)),
    ErrRow("CompressedTexSubImage2D paletted",
           _tex("glCompressedTexSubImage2D", T2D, 0, 0, 0, 4, 4, C.GL_PALETTE4_RGB8_OES, 56, PAL), (OP,)),
    ErrRow("CompressedTexSubImage2D RGBA",
           _tex("glCompressedTexSubImage2D", T2D, 0, 0, 0, 4, 4, RGBA, 56, PAL),
           (E,)),
    ErrRow("TexParameter bad target", _tex("glTexParameteri", C.GL_TEXTURE, C.GL_TEXTURE_MIN_FILTER, LINEAR),
           (E,)),
    ErrRow("TexParameter bad pname", _tex("glTexParameteri", T2D, C.GL_TEXTURE_ENV_MODE, LINEAR), (E,)),
    ErrRow("TexParameter MIN_FILTER REPEAT",
           _tex("glTexParameteri", T2D, C.GL_TEXTURE_MIN_FILTER, REPEAT), (E,)),
    ErrRow("TexParameter MAG_FILTER mipmap",
           _tex("glTexParameteri", T2D, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR_MIPMAP_LINEAR), (E,)),
    ErrRow("TexParameter WRAP_S CLAMP", _tex("glTexParameteri", T2D, C.GL_TEXTURE_WRAP_S, GL_CLAMP), (E,)),
    ErrRow("TexParameter WRAP_T LINEAR", _tex("glTexParameterx", T2D, C.GL_TEXTURE_WRAP_T, LINEAR), (E,)),
    ErrRow("TexEnvi TEXTURE_ENV_COLOR (a vector)",
           _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, 0), (E,)),
    ErrRow("TexEnv bad target", _tex("glTexEnvi", T2D, C.GL_TEXTURE_ENV_MODE, C.GL_ADD), (E,)),
    ErrRow("TexEnv bad pname", _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_TEXTURE_MIN_FILTER, C.GL_ADD), (E,)),
    ErrRow("TexEnv bad mode",
           _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_SUBTRACT), (E,)),
    ErrRow("TexEnv COMBINE_ALPHA DOT3_RGB",
           _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_COMBINE_ALPHA, C.GL_DOT3_RGB), (E,)),
    ErrRow("TexEnv COMBINE_RGB DECAL",
           _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, C.GL_DECAL), (E,)),
    ErrRow("TexEnv SRC0_RGB TEXTURE4", _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_SRC0_RGB, C.GL_TEXTURE0 + 4),
           (E,)),
    ErrRow("TexEnv SRC1_ALPHA ZERO", _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_SRC1_ALPHA, C.GL_ZERO), (E,)),
    ErrRow("TexEnv OPERAND0_ALPHA SRC_COLOR",
           _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_OPERAND0_ALPHA, C.GL_SRC_COLOR), (E,)),
    ErrRow("TexEnv OPERAND2_RGB ZERO",
           _tex("glTexEnvi", C.GL_TEXTURE_ENV, C.GL_OPERAND2_RGB, C.GL_ZERO), (E,)),
    ErrRow("TexEnv RGB_SCALE 3", _tex("glTexEnvx", C.GL_TEXTURE_ENV, C.GL_RGB_SCALE, 3 << 16), (V,)),
    ErrRow("TexEnv ALPHA_SCALE 0.5", _tex("glTexEnvx", C.GL_TEXTURE_ENV, C.GL_ALPHA_SCALE, 1 << 15), (V,)),
    ErrRow("GetTexParameteriv bad target",
           _tex("glGetTexParameteriv", C.GL_TEXTURE, C.GL_TEXTURE_WRAP_S), (E,)),
    ErrRow("GetTexParameteriv bad pname",
           _tex("glGetTexParameteriv", T2D, C.GL_TEXTURE_ENV_COLOR), (E,)),
    ErrRow("GetTexEnviv bad pname", _tex("glGetTexEnviv", C.GL_TEXTURE_ENV, C.GL_TEXTURE_WRAP_S), (E,)),
    ErrRow("ActiveTexture TEXTURE4", _tex("glActiveTexture", C.GL_TEXTURE0 + 4), (E,)),
    ErrRow("ClientActiveTexture TEXTURE4", _tex("glClientActiveTexture", C.GL_TEXTURE0 + 4), (E,)),
)

TEX_PARAMS = (C.GL_TEXTURE_MIN_FILTER, C.GL_TEXTURE_MAG_FILTER, C.GL_TEXTURE_WRAP_S, C.GL_TEXTURE_WRAP_T,
              C.GL_GENERATE_MIPMAP)
ENV_PARAMS = (C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE_RGB, C.GL_COMBINE_ALPHA, C.GL_SRC0_RGB, C.GL_SRC1_RGB,
              C.GL_SRC2_RGB, C.GL_SRC0_ALPHA, C.GL_SRC1_ALPHA, C.GL_SRC2_ALPHA, C.GL_OPERAND0_RGB,
              C.GL_OPERAND1_RGB, C.GL_OPERAND2_RGB, C.GL_OPERAND0_ALPHA, C.GL_OPERAND1_ALPHA,
              C.GL_OPERAND2_ALPHA, C.GL_RGB_SCALE, C.GL_ALPHA_SCALE, C.GL_TEXTURE_ENV_COLOR)


def texture_state(t: Target) -> dict[str, Any]:
    """Bindings, parameters and environment of every unit, and the picture of unit 0's texture."""
    gl = t.gl
    active = gl.glGetIntegerv(C.GL_ACTIVE_TEXTURE)
    snap: dict[str, Any] = {"active": active, "client": gl.glGetIntegerv(C.GL_CLIENT_ACTIVE_TEXTURE)}
    for u in range(4):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        snap[f"binding{u}"] = gl.glGetIntegerv(C.GL_TEXTURE_BINDING_2D)
        for p in TEX_PARAMS:
            snap[f"param{u}.{C.NAMES[p]}"] = gl.glGetTexParameteriv(C.GL_TEXTURE_2D, p)
        for p in ENV_PARAMS:
            snap[f"env{u}.{C.NAMES[p]}"] = np.asarray(gl.glGetTexEnviv(C.GL_TEXTURE_ENV, p)).tolist()
    gl.glActiveTexture(C.GL_TEXTURE0)
    gl.glEnable(C.GL_TEXTURE_2D)
    ortho(gl, t.w, t.h)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    draw_quad(gl, Quad(0, 0, 16, 16, (((0, 0), (1, 1)),)), (255, 255, 255, 255))
    snap["picture"] = gl.glReadPixels(0, 0, 16, 16, C.GL_RGBA, C.GL_UNSIGNED_BYTE).tobytes()
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glActiveTexture(active)
    gl.glClientActiveTexture(snap["client"])
    assert gl.glGetError() == 0
    return snap


def error_fixture(color: str) -> Target:
    """Unit 0: a 4x4 RGBA texture with a level-1 gap and non-default parameters; unit 1
    bound to a paletted texture; unit 2 active with a non-default environment."""
    t = Target("fixed", 32, 32, color=color)
    gl = t.gl
    rng = np.random.default_rng(0)
    gl.glActiveTexture(C.GL_TEXTURE0)
    make_texture(gl, rand_tex(rng, 4, 4), min_filter=LINEAR, mag_filter=NEAREST, wrap=(CLAMP, MIRROR))
    env(gl, C.GL_COMBINE, COMBINE_RGB=C.GL_INTERPOLATE, SRC2_RGB=C.GL_PRIMARY_COLOR, RGB_SCALE=2.0,
        TEXTURE_ENV_COLOR=(0.25, 0.5, 0.75, 1.0))
    gl.glActiveTexture(C.GL_TEXTURE1)
    gl.glBindTexture(C.GL_TEXTURE_2D, 7)
    gl.glCompressedTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_PALETTE4_RGB8_OES, 4, 4, 0, len(PAL), PAL)
    gl.glActiveTexture(C.GL_TEXTURE0)
    gl.glClientActiveTexture(C.GL_TEXTURE2)
    assert gl.glGetError() == 0
    return t


@pytest.mark.parametrize("row", ERROR_ROWS, ids=lambda r: r.name)
def test_error_leaves_state_unchanged(row: ErrRow):
    """The command records one of the spec's errors (the first error sticks) and
    changes no texture binding, parameter, environment value or texel."""
    t = error_fixture(row.color)
    gl = t.gl
    before = texture_state(t)
    result = row.call(gl)
    err = gl.glGetError()
    assert err in row.errors, f"{row.name}: error 0x{err:04X}, expected one of {[hex(e) for e in row.errors]}"
    row.call(gl)
    gl.glTexEnvx(C.GL_TEXTURE_ENV, C.GL_RGB_SCALE, 5 << 16)       # another error: must not replace it
    assert gl.glGetError() in row.errors
    assert gl.glGetError() == 0
    after = texture_state(t)
    changed = [k for k in before if before[k] != after[k]]
    assert not changed, f"{row.name} changed {changed}"
    if row.name.startswith("GenTextures"):
        assert result is None


# {================================================================
# texel selection and bilinear weights against the model (§3.7.6-3.7.8)


WRAPS = {"repeat": REPEAT, "clamp": CLAMP, "mirror": MIRROR}


@pytest.mark.parametrize("filt", [NEAREST, LINEAR], ids=["NEAREST", "LINEAR"])
@pytest.mark.parametrize("wrap", list(WRAPS), ids=str)
def test_texel_selection_vs_model(target: Target, filt: int, wrap: str):
    """Magnified and minified screen-aligned quads with coordinates running outside
    [0, 1], non-square textures, both wrap directions: every pixel equals the
    spec's texel (NEAREST) or bilinear blend (LINEAR) at its centre."""
    gl = target.gl
    rng = np.random.default_rng(11)
    tex_u8 = rand_tex(rng, 8, 4)
    tex = unorm(tex_u8)
    mode = WRAPS[wrap]
    make_texture(gl, tex_u8, min_filter=filt, mag_filter=filt, wrap=(mode, mode))
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    # (x0, y0, x1, y1) and texcoords at the corners: magnified, minified, reversed, offset
    quads = [
        Quad(0, 0, 32, 32, (((-0.8125, -0.40625), (1.6875, 1.34375)),)),
        Quad(32, 0, 64, 16, (((2.3, 1.1), (-1.7, -0.45)),)),
        Quad(32, 16, 64, 32, (((-3.05, 0.2), (4.15, 2.9)),)),
        Quad(0, 32, 64, 64, (((0.53125, -2.21875), (0.96875, 3.78125)),)),
    ]
    img = render_quads(target, quads)
    tol = tolerance(target.kind)
    for q in quads:
        s, t = quad_st(q)
        d = coord_slack(target.kind, 5.0)
        lo, hi = sample_range(tex, s, t, d, d, filt, mode, mode)
        expect_close(region(img, q), lo, tol, f"{wrap} {C.NAMES[filt]} quad {q[:4]}", lo, hi)


def test_bilinear_weights_exact_positions(numeric: str):
    """Pixel centres at known fractions of a texel (alpha = beta = k/16) on a two-texel
    ramp: the colour is exactly (1 - alpha) c0 + alpha c1 (equation 3.18)."""
    t = Target(numeric, 64, 16)
    gl = t.gl
    tex_u8 = np.zeros((2, 2, 4), np.uint8)
    tex_u8[:, 0] = (0, 255, 16, 255)
    tex_u8[:, 1] = (255, 0, 240, 0)
    make_texture(gl, tex_u8, min_filter=LINEAR, mag_filter=LINEAR, wrap=(CLAMP, CLAMP))
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    # 32 pixels span u from 0.5 to 1.5 (texel centre to texel centre): alpha = (x + 1/2) / 32
    q = Quad(0, 0, 32, 16, (((0.25, 0.25), (0.75, 0.75)),))
    img = region(render_quads(t, [q]), q)
    alpha = (np.arange(32) + 0.5) / 32
    want = (1 - alpha)[:, None] * unorm(tex_u8[0, 0]) + alpha[:, None] * unorm(tex_u8[0, 1])
    expect_close(img, np.broadcast_to(want, img.shape), tolerance(numeric), "bilinear ramp")


def test_clamp_to_edge_never_wraps(target: Target):
    """CLAMP_TO_EDGE with LINEAR far outside [0, 1]: only edge texels contribute;
    REPEAT on the same quad does blend across the edge (§3.7.6)."""
    gl = target.gl
    tex_u8 = np.zeros((4, 4, 4), np.uint8)
    tex_u8[..., 3] = 255
    tex_u8[:, 0, 0] = 255          # left column red
    tex_u8[:, 3, 2] = 255          # right column blue
    make_texture(gl, tex_u8, min_filter=LINEAR, mag_filter=LINEAR, wrap=(CLAMP, CLAMP))
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    q = Quad(0, 0, 64, 8, (((-2.0, 0.3), (3.0, 0.7)),))
    img = region(render_quads(target, [q]), q)
    s, _ = quad_st(q)
    left, right = s[0] < 0.125, s[0] > 0.875
    assert np.all(img[:, left, 0] == 1.0) and np.all(img[:, left, 2] == 0.0)
    assert np.all(img[:, right, 2] == 1.0) and np.all(img[:, right, 0] == 0.0)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, REPEAT)
    img = region(render_quads(target, [q]), q)
    edge = np.abs(s[0] - np.round(s[0])) < 0.1
    assert np.all((img[:, edge, 0] > 0.05) & (img[:, edge, 2] > 0.05))


# {================================================================
# texture matrices and projective coordinates (§2.10.2, §3.7.7)


def test_texture_matrix_per_unit(target: Target):
    """Each unit transforms its coordinates by its own texture matrix: unit 0 REPLACE
    through a rotation and translation, unit 1 MODULATE through a scale."""
    gl = target.gl
    rng = np.random.default_rng(21)
    a_u8, b_u8 = rand_tex(rng, 8, 8), rand_tex(rng, 4, 4)
    for u, (img_u8, mode, m) in enumerate(((a_u8, C.GL_REPLACE, "rot"), (b_u8, C.GL_MODULATE, "scale"))):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        make_texture(gl, img_u8, min_filter=LINEAR, mag_filter=LINEAR)
        gl.glEnable(C.GL_TEXTURE_2D)
        env(gl, mode)
        gl.glMatrixMode(C.GL_TEXTURE)
        gl.glLoadIdentity()
        if m == "rot":
            gl.glTranslatex(int(0.25 * 65536), int(-0.125 * 65536), 0)
            gl.glRotatex(90 << 16, 0, 0, 1 << 16)
        else:
            gl.glScalex(3 << 16, int(-1.5 * 65536), 1 << 16)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glActiveTexture(C.GL_TEXTURE0)
    q = Quad(0, 0, 64, 64, (((0.0, 0.0), (1.0, 1.0)), ((0.0, 0.0), (1.0, 1.0))))
    img = render_quads(target, [q])
    s, t = quad_st(q)
    # unit 0: (s, t) -> T R (s, t) = (0.25 - t, s - 0.125); unit 1: (3 s, -1.5 t)
    c0 = sample(unorm(a_u8), 0.25 - t, s - 0.125, LINEAR)
    c1 = sample(unorm(b_u8), 3 * s, -1.5 * t, LINEAR)
    want = c0 * c1
    d = coord_slack(target.kind, 4.0) + (2.0**-14 if target.kind == "fixed" else 0.0)   # 16.16 matrices
    lo0, hi0 = sample_range(unorm(a_u8), 0.25 - t, s - 0.125, d, d, LINEAR)
    lo1, hi1 = sample_range(unorm(b_u8), 3 * s, -1.5 * t, 3 * d, 3 * d, LINEAR)
    expect_close(img, want, tolerance(target.kind) + 2.0**-12, "two units, two texture matrices",
                 lo0 * lo1, hi0 * hi1)


def projective_model(verts: np.ndarray, strq: np.ndarray, px: np.ndarray,
                     py: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s/q, t/q at window points of a strip of two triangles in ortho (w = 1): s, t, q
    interpolate linearly in window space, then divide (§3.7, division by q)."""
    s_out = np.full(px.shape, np.nan)
    t_out = np.full(px.shape, np.nan)
    inside = np.zeros(px.shape, bool)
    for tri in ((0, 1, 2), (2, 1, 3)):
        p = verts[list(tri)]
        a = strq[list(tri)]
        den = (p[1, 1] - p[2, 1]) * (p[0, 0] - p[2, 0]) + (p[2, 0] - p[1, 0]) * (p[0, 1] - p[2, 1])
        l0 = ((p[1, 1] - p[2, 1]) * (px - p[2, 0]) + (p[2, 0] - p[1, 0]) * (py - p[2, 1])) / den
        l1 = ((p[2, 1] - p[0, 1]) * (px - p[2, 0]) + (p[0, 0] - p[2, 0]) * (py - p[2, 1])) / den
        l2 = 1 - l0 - l1
        m = (l0 >= 0) & (l1 >= 0) & (l2 >= 0) & ~inside
        val = l0[..., None] * a[0] + l1[..., None] * a[1] + l2[..., None] * a[2]
        s_out[m] = val[m][:, 0] / val[m][:, 3]
        t_out[m] = val[m][:, 1] / val[m][:, 3]
        inside |= m
    return s_out, t_out, inside


def test_projective_q(target: Target):
    """Vertex coordinates (s q, t q, 0, q) with a different q at each corner: the
    texture follows s/q, t/q of the linearly interpolated values (a projected image)."""
    gl = target.gl
    rng = np.random.default_rng(31)
    tex_u8 = rand_tex(rng, 16, 16)
    make_texture(gl, tex_u8, min_filter=LINEAR, mag_filter=LINEAR, wrap=(CLAMP, CLAMP))
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    verts = np.array([[0, 0], [64, 0], [0, 64], [64, 64]], np.float64)
    q = np.array([1.0, 0.25, 2.0, 0.5])
    st = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], np.float64)
    strq = np.column_stack([st[:, 0] * q, st[:, 1] * q, np.zeros(4), q])
    img = render_quads(target, [Quad(0, 0, 64, 64, (strq,))])
    px, py = centres(0, 0, 64, 64)
    s, t, inside = projective_model(verts, strq, px, py)
    assert inside.all()
    d = coord_slack(target.kind, 8.0) * 8      # a division by q >= 0.25 and the weights
    lo, hi = sample_range(unorm(tex_u8), s, t, d, d, LINEAR, CLAMP, CLAMP)
    expect_close(img, lo, tolerance(target.kind), "projective quad", lo, hi)


# {================================================================
# large coordinates: REPEAT before scaling (§3.7.6)


def test_s_1024_on_a_2048_texture(target: Target):
    """s and t near +-1024 on 2048-texel textures with REPEAT: magnified views near
    s = -1024, 0 and 1024 select the texel the wrapped coordinate names, and a quad
    spanning s in [-1024, 1024] does too (no overflow in 16.16 / 32.32)."""
    gl = target.gl
    rng = np.random.default_rng(41)
    tex_u8 = rand_tex(rng, 2048, 2)
    tex = unorm(tex_u8)
    make_texture(gl, tex_u8)
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    k = 16 / 2048
    quads = [
        Quad(0, 0, 64, 8, (((1024 - k, 0.25), (1024.0, 0.25)),)),
        Quad(0, 8, 64, 16, (((-1024.0, 0.75), (-1024 + k, 0.75)),)),
        Quad(0, 16, 64, 24, (((1023 + 3 * k, 0.25), (1023 + 4 * k, 0.75)),)),
        Quad(0, 24, 64, 32, (((-k / 2, 0.75), (k / 2, 0.25)),)),
        Quad(0, 32, 64, 40, (((-1024.0, 0.25), (1024 - 2.0**-6, 0.75)),)),
    ]
    img = render_quads(target, quads)
    errs = []
    for q in quads:
        s, t = quad_st(q)
        d = coord_slack(target.kind, 1024.0)
        lo, hi = sample_range(tex, s, t, d, 0.0, NEAREST)
        errs.append(expect_close(region(img, q), lo, tolerance(target.kind), f"s near {q.coords[0][0][0]}",
                                 lo, hi))
    # in 2x2048 the t direction: the same with t near 1024
    tex_t = np.ascontiguousarray(np.transpose(tex_u8, (1, 0, 2)))
    make_texture(gl, tex_t)
    q = Quad(0, 0, 8, 64, (((0.75, 1024 - k), (0.75, 1024.0)),))
    img = region(render_quads(target, [q]), q)
    s, t = quad_st(q)
    lo, hi = sample_range(unorm(tex_t), s, t, 0.0, coord_slack(target.kind, 1024.0), NEAREST)
    expect_close(img, lo, tolerance(target.kind), "t near 1024", lo, hi)


def test_high_repeat_counts(numeric: str):
    """Hundreds of repeats across a quad (NEAREST, minified): every pixel is the
    texel at frac(s) of its centre, within each build's coordinate precision."""
    t = Target(numeric)
    gl = t.gl
    rng = np.random.default_rng(43)
    tex_u8 = rand_tex(rng, 16, 16)
    tex = unorm(tex_u8)
    make_texture(gl, tex_u8)
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    quads = [Quad(0, 0, 64, 32, (((-300.03125, 7.53125), (300.15625, 7.53125 + 1.0 / 64)),)),
             Quad(0, 32, 64, 64, (((-0.3046875, -500.0078125), (999.6953125, 700.2421875)),))]
    img = render_quads(t, quads)
    for q in quads:
        s, tt = quad_st(q)
        d = coord_slack(numeric, 1000.0)
        lo, hi = sample_range(tex, s, tt, d, d, NEAREST)
        expect_close(region(img, q), lo, tolerance(numeric), f"repeats {q.coords}", lo, hi)


def test_textures_up_to_max_size(numeric: str):
    """A 2048x1 and a 1x2048 texture can be specified and sampled (MAX_TEXTURE_SIZE)."""
    t = Target(numeric, 32, 32)
    gl = t.gl
    rng = np.random.default_rng(47)
    for w, h in ((2048, 1), (1, 2048)):
        tex_u8 = rand_tex(rng, w, h)
        make_texture(gl, tex_u8)
        gl.glEnable(C.GL_TEXTURE_2D)
        env(gl, C.GL_REPLACE)
        q = Quad(0, 0, 32, 32, (((0.125, 0.125), (0.1328125, 0.1328125)),))
        img = region(render_quads(t, [q]), q)
        s, tt = quad_st(q)
        expect_close(img, sample(unorm(tex_u8), s, tt, NEAREST), tolerance(numeric), f"{w}x{h}")
    assert gl.glGetError() == 0
