"""Points, lines, point sprites, polygon offset and draw-texture
(ES 1.1 §3.3, §3.4, §3.5.2, OES_point_sprite, OES_point_size_array,
OES_draw_texture).

Every expectation is computed here from the spec's rules (SPEC-NOTES.md):

* aliased points: the width is the size rounded to an integer; an odd width w
  covers the w x w pixels centred on pixel floor(x) (centre floor(x) + 1/2),
  an even width those centred on the corner floor(x + 1/2);
* smooth points: a disc of diameter size, coverage multiplies alpha;
* distance attenuation: size * sqrt(1 / (a + b d + c d^2)), d the eye
  distance, clamped to [POINT_SIZE_MIN, POINT_SIZE_MAX];
* sprites: the pixels whose centres lie in the size x size square, with
  s = 1/2 + (x_f + 1/2 - x_w) / size and t = 1/2 - (y_f + 1/2 - y_w) / size;
* lines: one fragment per column (x-major) or row (y-major) whose centre lies
  in the half-open span from the first endpoint to the second; w per column
  for width w;
* polygon offset o = m * factor + units (one depth unit), fill only;
* draw texture: the crop rectangle mapped linearly onto the window rectangle.

The scene is 1:1 (object units = pixels, power-of-two sizes, coordinates on
the 1/256 grid), so every build computes window positions exactly. The Mesa
comparisons run the same checks on llvmpipe.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import BUILDS, make_ctx, set_ortho

from gles import constants as C
from gles import mesa

W = H = 128

MESA_REASON = mesa.available()
needs_mesa = pytest.mark.skipif(MESA_REASON is not None, reason=str(MESA_REASON))


# {============================================================
# helpers


class Target:
    """A gles context of one build, or a Mesa llvmpipe context, with a uniform face."""

    def __init__(self, kind: str, w: int = W, h: int = H, depth: int = 24) -> None:
        self.kind = kind
        self.w, self.h = w, h
        if kind == "mesa":
            self._mesa = mesa.MesaContext(w, h)
            self._mesa.__enter__()
            self.gl = self._mesa.gl
        else:
            self._mesa = None
            self.ctx = make_ctx(kind, w, h, depth=depth)
            self.gl = self.ctx.gl
        gl = self.gl
        gl.glDisable(C.GL_DITHER)
        set_ortho(gl, w, h)
        self.clear()

    def close(self) -> None:
        if self._mesa is not None:
            self._mesa.__exit__(None, None, None)

    def clear(self) -> None:
        gl = self.gl
        gl.glClearColor(0.0, 0.0, 0.0, 0.0)
        gl.glClearDepthf(1.0)
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)

    def read(self) -> np.ndarray:
        """uint8 RGBA (h, w, 4), bottom row first."""
        return np.asarray(self.gl.glReadPixels(0, 0, self.w, self.h, C.GL_RGBA, C.GL_UNSIGNED_BYTE))

    def mask(self) -> np.ndarray:
        """(h, w) bool: pixels touched (any channel non-zero)."""
        return self.read().any(axis=-1)

    def draw(self, mode: int, verts: Any, colors: Any = None) -> None:
        gl = self.gl
        v = np.ascontiguousarray(verts, dtype=np.float32)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(v.shape[1], C.GL_FLOAT, 0, v)
        if colors is not None:
            c = np.ascontiguousarray(colors, dtype=np.uint8)
            gl.glEnableClientState(C.GL_COLOR_ARRAY)
            gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, c)
        else:
            gl.glDisableClientState(C.GL_COLOR_ARRAY)
        gl.glDrawArrays(mode, 0, len(v))
        gl.glDisableClientState(C.GL_COLOR_ARRAY)
        self._keep = v


@pytest.fixture(params=BUILDS)
def tgt(request: pytest.FixtureRequest) -> Any:
    t = Target(request.param)
    yield t
    t.close()


@pytest.fixture
def mesa_tgt() -> Any:
    if MESA_REASON is not None:
        pytest.skip(str(MESA_REASON))
    t = Target("mesa")
    yield t
    t.close()


def q256(v: Any) -> Any:
    return np.round(np.asarray(v, dtype=np.float64) * 256) / 256


def aliased_point_mask(x: float, y: float, size: float, w: int = W, h: int = H) -> np.ndarray:
    """§3.3: the footprint of an aliased point."""
    n = max(1, int(np.floor(size + 0.5)))
    m = np.zeros((h, w), dtype=bool)
    if n % 2:
        cx, cy = int(np.floor(x)), int(np.floor(y))
        x0, y0 = cx - (n - 1) // 2, cy - (n - 1) // 2
    else:
        cx, cy = int(np.floor(x + 0.5)), int(np.floor(y + 0.5))
        x0, y0 = cx - n // 2, cy - n // 2
    m[max(y0, 0):max(y0 + n, 0), max(x0, 0):max(x0 + n, 0)] = True
    return m


def centres(w: int = W, h: int = H) -> tuple[np.ndarray, np.ndarray]:
    """Pixel centres (X, Y) as (h, w) arrays."""
    return np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)


def describe(got: np.ndarray, want: np.ndarray) -> str:
    extra = np.argwhere(got & ~want)
    missing = np.argwhere(want & ~got)
    return (f"{len(extra)} extra (first y,x {extra[:3].tolist()}), "
            f"{len(missing)} missing (first y,x {missing[:3].tolist()})")


def point_cases(seed: int, sizes: Any, per_size: int = 2) -> list[tuple[float, float, float]]:
    """Random subpixel centres (1/256 grid, well inside the window) for each size."""
    rng = np.random.default_rng(seed)
    out = []
    for s in sizes:
        for _ in range(per_size):
            x, y = q256(rng.uniform(W / 2 - 8, W / 2 + 8, size=2))
            out.append((float(x), float(y), float(s)))
    return out


# {============================================================
# aliased points


def check_aliased_points(t: Target, cases: list[tuple[float, float, float]]) -> list[str]:
    gl = t.gl
    bad = []
    for x, y, s in cases:
        t.clear()
        gl.glPointSize(s)
        t.draw(C.GL_POINTS, [(x, y)], [(255, 255, 255, 255)])
        got, want = t.mask(), aliased_point_mask(x, y, s)
        if not np.array_equal(got, want):
            bad.append(f"size {s} at ({x}, {y}): {describe(got, want)}")
    return bad


def test_aliased_point_footprints_1_to_50(tgt: Target) -> None:
    bad = check_aliased_points(tgt, point_cases(7, range(1, 51)))
    assert not bad, "\n".join(bad[:10])


def test_aliased_point_fractional_sizes_round(tgt: Target) -> None:
    # sizes away from .5: the width is the nearest integer
    bad = check_aliased_points(tgt, point_cases(8, [1.3, 2.2, 2.7, 3.4, 4.6, 7.25, 9.9, 12.1]))
    assert not bad, "\n".join(bad)


def test_point_pixel_centre_and_corner(tgt: Target) -> None:
    # exact cases: size 1 at any point of a pixel covers that pixel; size 2 at
    # a pixel's centre covers the 2x2 block whose corner is nearest
    bad = check_aliased_points(tgt, [(10.0, 20.0, 1), (10.99609375, 20.5, 1), (10.5, 20.5, 2),
                                     (10.25, 20.75, 2), (10.5, 20.5, 3), (10.75, 20.25, 4)])
    assert not bad, "\n".join(bad)


def test_point_colour_is_vertex_colour(tgt: Target) -> None:
    tgt.gl.glPointSize(3.0)
    tgt.draw(C.GL_POINTS, [(20.5, 20.5), (40.5, 40.5)], [(10, 200, 30, 255), (250, 5, 100, 77)])
    img = tgt.read()
    assert (img[19:22, 19:22] == (10, 200, 30, 255)).all()
    assert (img[39:42, 39:42] == (250, 5, 100, 77)).all()


@needs_mesa
def test_mesa_aliased_point_footprints(mesa_tgt: Target) -> None:
    """llvmpipe against the same rule (see the report for what differs)."""
    bad = check_aliased_points(mesa_tgt, point_cases(7, range(1, 51)))
    assert not bad, f"{len(bad)} of 100 differ:\n" + "\n".join(bad[:10])


# {============================================================
# smooth points


@pytest.mark.parametrize("size", [1.0, 2.5, 4.0, 7.3, 12.0, 25.5])
def test_smooth_point_coverage(tgt: Target, size: float) -> None:
    gl = tgt.gl
    gl.glEnable(C.GL_POINT_SMOOTH)
    gl.glPointSize(size)
    x, y = 40.3125, 50.6875
    tgt.draw(C.GL_POINTS, [(x, y)], [(255, 255, 255, 255)])
    a = tgt.read()[..., 3].astype(np.float64) / 255
    X, Y = centres()
    # distance from the point to the nearest and farthest points of each pixel
    nx = np.clip(x, X - 0.5, X + 0.5) - x
    ny = np.clip(y, Y - 0.5, Y + 0.5) - y
    near = np.hypot(nx, ny)
    far = np.hypot(np.abs(X - x) + 0.5, np.abs(Y - y) + 0.5)
    r = size / 2
    outside = near >= r
    inside = far <= r
    assert (a[outside] == 0).all(), f"{int((a[outside] > 0).sum())} pixels outside the disc have alpha"
    assert (a[inside] == 1).all(), f"pixels inside the disc: min alpha {a[inside].min()}"
    # total coverage approximates the disc's area (4x4 samples: generous bound)
    total = a.sum()
    area = np.pi * r * r
    assert abs(total - area) <= 0.25 * area + 1.0, (total, area)
    # the pixel holding the centre is covered
    assert a[int(y), int(x)] > 0


def test_smooth_point_partial_alpha(tgt: Target) -> None:
    gl = tgt.gl
    gl.glEnable(C.GL_POINT_SMOOTH)
    gl.glPointSize(6.0)
    tgt.draw(C.GL_POINTS, [(30.5, 30.5)], [(255, 255, 255, 255)])
    a = tgt.read()[..., 3]
    assert ((a > 0) & (a < 255)).any(), "a smooth point has no partially covered pixel"


# {============================================================
# distance attenuation and clamping


def attenuation_scene(t: Target) -> None:
    """Eye space = window pixels shifted: eye (0, 0, z) lands at window (W/2, H/2)."""
    gl = t.gl
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(-W / 2, W / 2, -H / 2, H / 2, -100.0, 100.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


@pytest.mark.parametrize("size,abc,eye", [
    (20.0, (1.0, 0.0, 0.0), (0.25, 0.25, -10.0)),
    (20.0, (0.0, 0.1, 0.0), (0.25, 0.25, -10.0)),     # sqrt(1/(0.1*10)) = 1
    (30.0, (0.0, 0.0, 0.01), (3.25, 4.25, -12.0)),    # d = 13: 30/1.3 = 23.08
    (40.0, (1.0, 0.5, 0.0), (0.25, 0.25, -6.0)),      # 40 / 2 = 20
    (10.0, (0.25, 0.0, 0.0), (0.25, 0.25, -50.0)),    # 10 * 2 = 20
    (16.0, (0.5, 0.0, 0.0025), (6.25, 8.25, -24.0)),  # d = 26, 16/sqrt(2.19) = 10.81
])
def test_distance_attenuation(tgt: Target, size: float, abc: tuple, eye: tuple) -> None:
    gl = tgt.gl
    attenuation_scene(tgt)
    gl.glPointSize(size)
    gl.glPointParameterfv(C.GL_POINT_DISTANCE_ATTENUATION, list(abc))
    assert gl.glGetError() == 0
    tgt.draw(C.GL_POINTS, [eye], [(255, 255, 255, 255)])
    d = float(np.linalg.norm(eye))
    a, b, c = abc
    derived = size * np.sqrt(1.0 / (a + b * d + c * d * d))
    assert abs((derived % 1) - 0.5) > 0.05, "test case too close to a rounding boundary"
    want = aliased_point_mask(W / 2 + eye[0], H / 2 + eye[1], derived)
    got = tgt.mask()
    assert np.array_equal(got, want), f"derived size {derived:.3f}: {describe(got, want)}"


@pytest.mark.parametrize("size,a,mn,mx,want_size", [
    (2.0, 1.0, 5.0, 64.0, 5),      # below the minimum
    (20.0, 1.0, 1.0, 7.0, 7),      # above the maximum
    (40.0, 4.0, 1.0, 64.0, 20),    # attenuated, within
    (40.0, 100.0, 6.0, 64.0, 6),   # attenuated to 4, clamped up
    (8.0, 0.01, 1.0, 33.0, 33),    # attenuated to 80, clamped down
])
def test_point_size_min_max(tgt: Target, size: float, a: float, mn: float, mx: float, want_size: int) -> None:
    gl = tgt.gl
    gl.glPointSize(size)
    gl.glPointParameterfv(C.GL_POINT_DISTANCE_ATTENUATION, [a, 0.0, 0.0])
    gl.glPointParameterf(C.GL_POINT_SIZE_MIN, mn)
    gl.glPointParameterf(C.GL_POINT_SIZE_MAX, mx)
    assert gl.glGetError() == 0
    assert gl.glGetFloatv(C.GL_POINT_SIZE_MIN) == pytest.approx(mn)
    assert gl.glGetFloatv(C.GL_POINT_SIZE_MAX) == pytest.approx(mx)
    tgt.draw(C.GL_POINTS, [(60.5, 60.5)], [(255, 255, 255, 255)])
    got, want = tgt.mask(), aliased_point_mask(60.5, 60.5, want_size)
    assert np.array_equal(got, want), describe(got, want)


def test_point_parameter_x_forms(tgt: Target) -> None:
    gl = tgt.gl
    gl.glPointSizex(9 << 16)
    gl.glPointParameterxv(C.GL_POINT_DISTANCE_ATTENUATION, [1 << 14, 0, 0])   # a = 1/4: size 18
    gl.glPointParameterx(C.GL_POINT_SIZE_MAX, 17 << 16)
    assert gl.glGetError() == 0
    tgt.draw(C.GL_POINTS, [(60.5, 60.5)], [(255, 255, 255, 255)])
    got, want = tgt.mask(), aliased_point_mask(60.5, 60.5, 17)
    assert np.array_equal(got, want), describe(got, want)


# {============================================================
# point size array


@pytest.mark.parametrize("gltype", [C.GL_FIXED, C.GL_FLOAT])
def test_point_size_array(tgt: Target, gltype: int) -> None:
    gl = tgt.gl
    gl.glPointSize(1.0)
    pts = [(16.5, 16.5), (48.25, 16.75), (96.5, 20.5), (20.5, 70.5), (70.5, 80.5)]
    sizes = [1.0, 4.0, 7.0, 12.0, 21.0]
    arr = (np.array([int(s * 65536) for s in sizes], dtype=np.int32) if gltype == C.GL_FIXED
           else np.array(sizes, dtype=np.float32))
    gl.glEnableClientState(C.GL_POINT_SIZE_ARRAY_OES)
    gl.glPointSizePointerOES(gltype, 0, arr)
    assert gl.glGetError() == 0
    tgt.draw(C.GL_POINTS, pts, [(255, 255, 255, 255)] * len(pts))
    gl.glDisableClientState(C.GL_POINT_SIZE_ARRAY_OES)
    want = np.zeros((H, W), dtype=bool)
    for (x, y), s in zip(pts, sizes):
        want |= aliased_point_mask(x, y, s)
    got = tgt.mask()
    assert np.array_equal(got, want), describe(got, want)
    # disabled again: POINT_SIZE applies
    tgt.clear()
    tgt.draw(C.GL_POINTS, pts, [(255, 255, 255, 255)] * len(pts))
    assert tgt.mask().sum() == len(pts)


def test_point_size_array_stride_and_errors(tgt: Target) -> None:
    gl = tgt.gl
    # interleaved: each size followed by a junk value
    arr = np.array([5.0, 99.0, 2.0, 99.0], dtype=np.float32)
    gl.glEnableClientState(C.GL_POINT_SIZE_ARRAY_OES)
    gl.glPointSizePointerOES(C.GL_FLOAT, 8, arr)
    assert gl.glGetError() == 0
    tgt.draw(C.GL_POINTS, [(30.5, 30.5), (80.5, 80.5)], [(255, 255, 255, 255)] * 2)
    want = aliased_point_mask(30.5, 30.5, 5) | aliased_point_mask(80.5, 80.5, 2)
    got = tgt.mask()
    assert np.array_equal(got, want), describe(got, want)
    gl.glPointSizePointerOES(C.GL_SHORT, 0, np.zeros(4, dtype=np.int16))
    assert gl.glGetError() == C.GL_INVALID_ENUM
    gl.glPointSizePointerOES(C.GL_FLOAT, -4, arr)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glDisableClientState(C.GL_POINT_SIZE_ARRAY_OES)


# {============================================================
# point sprites

TEX = 64


def coord_texture(gl: Any, n: int = TEX) -> np.ndarray:
    """An n x n RGBA texture whose texel (i, j) is (4i, 4j, 0, 255), NEAREST."""
    i, j = np.meshgrid(np.arange(n), np.arange(n))          # i: column (s), j: row (t)
    img = np.stack([i * (256 // n), j * (256 // n), np.zeros_like(i), np.full_like(i, 255)],
                   axis=-1).astype(np.uint8)
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, C.GL_CLAMP_TO_EDGE)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, C.GL_CLAMP_TO_EDGE)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, n, n, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                    np.ascontiguousarray(img))
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    return img


def check_sprite(t: Target, x: float, y: float, size: float) -> list[str]:
    gl = t.gl
    t.clear()
    gl.glPointSize(size)
    t.draw(C.GL_POINTS, [(x, y)], [(255, 255, 255, 255)])
    img = t.read()
    X, Y = centres()
    want = (X >= x - size / 2) & (X < x + size / 2) & (Y >= y - size / 2) & (Y < y + size / 2)
    got = img[..., 3] > 0
    errs = []
    if not np.array_equal(got, want):
        errs.append(f"sprite size {size} at ({x}, {y}): footprint {describe(got, want)}")
        return errs
    s = 0.5 + (X - x) / size
    tt = 0.5 - (Y - y) / size
    for coord, chan, name in ((s, 0, "s"), (tt, 1, "t")):
        u = coord * TEX
        lo = np.clip(np.floor(u - 1e-3), 0, TEX - 1) * 4
        hi = np.clip(np.floor(u + 1e-3), 0, TEX - 1) * 4
        v = img[..., chan].astype(np.int64)
        bad = want & ~((v == lo) | (v == hi))
        if bad.any():
            yy, xx = np.argwhere(bad)[0]
            errs.append(f"sprite size {size} at ({x}, {y}): {name} wrong at {int(bad.sum())} pixels, "
                        f"first (x={xx}, y={yy}): texel {v[yy, xx] // 4}, want {lo[yy, xx] // 4}"
                        f" ({name} = {coord[yy, xx]:.4f})")
    return errs


def enable_sprites(gl: Any) -> None:
    coord_texture(gl)
    gl.glEnable(C.GL_POINT_SPRITE_OES)
    gl.glTexEnvi(C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES, 1)


def test_point_sprite_coords(tgt: Target) -> None:
    enable_sprites(tgt.gl)
    rng = np.random.default_rng(3)
    errs = []
    for size in (1.0, 2.0, 3.0, 5.5, 8.0, 13.0, 16.0, 31.7, 48.0, 63.0):
        x, y = q256(rng.uniform(50, 70, size=2))
        errs += check_sprite(tgt, float(x), float(y), size)
    assert not errs, "\n".join(errs)


def test_point_sprite_without_coord_replace(tgt: Target) -> None:
    gl = tgt.gl
    coord_texture(gl)
    gl.glEnable(C.GL_POINT_SPRITE_OES)
    gl.glPointSize(8.0)
    gl.glMultiTexCoord4f(C.GL_TEXTURE0, 10.5 / TEX, 20.5 / TEX, 0.0, 1.0)
    tgt.draw(C.GL_POINTS, [(60.0, 60.0)], [(255, 255, 255, 255)])
    img = tgt.read()
    blk = img[56:64, 56:64]
    assert (blk[..., 0] == 40).all() and (blk[..., 1] == 80).all(), "the vertex's coordinate applies"
    assert img[..., 3].astype(bool).sum() == 64


@needs_mesa
def test_mesa_point_sprite_coords(mesa_tgt: Target) -> None:
    enable_sprites(mesa_tgt.gl)
    rng = np.random.default_rng(3)
    errs = []
    for size in (1.0, 2.0, 3.0, 5.5, 8.0, 13.0, 16.0, 31.7, 48.0, 63.0):
        x, y = q256(rng.uniform(50, 70, size=2))
        errs += check_sprite(mesa_tgt, float(x), float(y), size)
    assert not errs, "\n".join(errs)


# {============================================================
# aliased lines


def line_cases(seed: int, n: int, xmajor: bool) -> list[tuple[float, float, float, float]]:
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        p = q256(rng.uniform(4, W - 4, size=4))
        x0, y0, x1, y1 = (float(v) for v in p)
        dx, dy = abs(x1 - x0), abs(y1 - y0)
        if (dx > dy + 1) if xmajor else (dy > dx + 1):
            out.append((x0, y0, x1, y1))
    return out


def check_line(got: np.ndarray, x0: float, y0: float, x1: float, y1: float, width: int = 1,
               slack: int = 0) -> str | None:
    """Columns (x-major) or rows whose centres are in [first, second): `width`
    fragments each, centred on the line; no fragment elsewhere. `slack`
    columns at each end may have anything (the conformance rule uses 1)."""
    xmajor = abs(x1 - x0) >= abs(y1 - y0)
    g = got if xmajor else got.T
    a0, b0, a1, b1 = (x0, y0, x1, y1) if xmajor else (y0, x0, y1, x1)
    n_major = g.shape[1]
    c = np.arange(n_major) + 0.5
    inside = (c >= a0) & (c < a1) if a1 > a0 else (c > a1) & (c <= a0)
    cols = np.nonzero(inside)[0]
    if slack:
        lo, hi = cols.min() - slack, cols.max() + slack
        core = cols[slack:len(cols) - slack]
    else:
        lo, hi, core = cols.min(), cols.max(), cols
    outside = np.ones(n_major, dtype=bool)
    outside[max(lo, 0):hi + 1] = False
    if g[:, outside].any():
        return f"fragments outside the span, at columns {np.nonzero(g[:, outside].any(axis=0))[0][:5]}"
    for col in core:
        rows = np.nonzero(g[:, col])[0]
        m = b0 + (b1 - b0) * (col + 0.5 - a0) / (a1 - a0)
        if len(rows) != width:
            return f"column {col}: {len(rows)} fragments, want {width}"
        if rows.max() - rows.min() != width - 1:
            return f"column {col}: fragments not contiguous {rows}"
        mid = (rows.min() + rows.max() + 1) / 2
        if abs(mid - m) > 0.5 + 1 / 128:   # the crossing is computed on the subpixel grid
            return f"column {col}: fragments {rows} centred at {mid}, line at {m:.4f}"
    return None


@pytest.mark.parametrize("xmajor", [True, False])
def test_line_one_fragment_per_column(tgt: Target, xmajor: bool) -> None:
    errs = []
    for x0, y0, x1, y1 in line_cases(11 if xmajor else 12, 25, xmajor):
        tgt.clear()
        tgt.draw(C.GL_LINES, [(x0, y0), (x1, y1)], [(255, 255, 255, 255)] * 2)
        e = check_line(tgt.mask(), x0, y0, x1, y1)
        if e:
            errs.append(f"({x0}, {y0})-({x1}, {y1}): {e}")
    assert not errs, "\n".join(errs[:8])


def test_line_half_open_at_pixel_centres(tgt: Target) -> None:
    for (a, b), pix in (
        (((2.5, 5.5), (10.5, 5.5)), [(x, 5) for x in range(2, 10)]),
        (((10.5, 5.5), (2.5, 5.5)), [(x, 5) for x in range(3, 11)]),
        (((7.5, 3.5), (7.5, 12.5)), [(7, y) for y in range(3, 12)]),
        (((7.5, 12.5), (7.5, 3.5)), [(7, y) for y in range(4, 13)]),
    ):
        tgt.clear()
        tgt.draw(C.GL_LINES, [a, b], [(255, 255, 255, 255)] * 2)
        want = np.zeros((H, W), dtype=bool)
        for x, y in pix:
            want[y, x] = True
        got = tgt.mask()
        assert np.array_equal(got, want), f"{a}-{b}: {describe(got, want)}"


def test_line_hv_off_centre(tgt: Target) -> None:
    # horizontal at y = 20.25 covers row 20; vertical at x = 33.75 covers column 33
    tgt.draw(C.GL_LINES, [(4.0, 20.25), (60.0, 20.25), (33.75, 70.0), (33.75, 100.0)],
             [(255, 255, 255, 255)] * 4)
    want = np.zeros((H, W), dtype=bool)
    want[20, 4:60] = True
    want[70:100, 33] = True
    got = tgt.mask()
    assert np.array_equal(got, want), describe(got, want)


def count_hits(t: Target, mode: int, verts: list) -> np.ndarray:
    """Draw with ONE, ONE blending of 1/8 grey: the number of fragments per pixel."""
    gl = t.gl
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    t.draw(mode, verts, [(32, 32, 32, 32)] * len(verts))
    gl.glDisable(C.GL_BLEND)
    return (t.read()[..., 0].astype(int) + 16) // 32


def test_line_strip_shared_vertices_once(tgt: Target) -> None:
    verts = [(10.5, 10.5), (40.5, 18.5), (50.5, 60.5), (20.5, 70.5), (12.25, 30.75)]
    hits = count_hits(tgt, C.GL_LINE_STRIP, verts)
    assert hits.max() == 1, f"pixels hit twice: {np.argwhere(hits > 1)[:5].tolist()}"
    # each segment's own columns are all present
    assert hits.sum() == 30 + 42 + 30 + 40, hits.sum()


def test_line_loop_rectangle_once(tgt: Target) -> None:
    verts = [(2.5, 2.5), (12.5, 2.5), (12.5, 8.5), (2.5, 8.5)]
    hits = count_hits(tgt, C.GL_LINE_LOOP, verts)
    want = np.zeros((H, W), dtype=int)
    want[2, 2:13] = 1
    want[8, 2:13] = 1
    want[2:9, 2] = 1
    want[2:9, 12] = 1
    assert np.array_equal(hits, want), describe(hits > 0, want > 0) + f", max {hits.max()}"


@pytest.mark.parametrize("width", [2, 3, 4, 5, 8])
def test_wide_line_columns(tgt: Target, width: int) -> None:
    gl = tgt.gl
    gl.glLineWidth(float(width))
    errs = []
    for x0, y0, x1, y1 in line_cases(20 + width, 10, True):
        y0, y1 = y0 / 2 + 32, y1 / 2 + 32    # keep the wide columns inside the window
        tgt.clear()
        tgt.draw(C.GL_LINES, [(x0, y0), (x1, y1)], [(255, 255, 255, 255)] * 2)
        e = check_line(tgt.mask(), x0, y0, x1, y1, width)
        if e:
            errs.append(f"({x0}, {y0})-({x1}, {y1}) width {width}: {e}")
    assert not errs, "\n".join(errs[:8])


def test_wide_line_y_major_rows(tgt: Target) -> None:
    gl = tgt.gl
    gl.glLineWidthx(3 << 16)
    tgt.draw(C.GL_LINES, [(40.3, 5.2), (52.7, 90.6)], [(255, 255, 255, 255)] * 2)
    got = tgt.mask()
    x0, y0, x1, y1 = (float(v) for v in np.float32([40.3, 5.2, 52.7, 90.6]))
    e = check_line(got, x0, y0, x1, y1, 3)
    assert e is None, e


@pytest.mark.parametrize("width", [1.0, 2.0, 3.5])
def test_smooth_line_coverage(tgt: Target, width: float) -> None:
    gl = tgt.gl
    gl.glEnable(C.GL_LINE_SMOOTH)
    gl.glLineWidth(width)
    x0, y0, x1, y1 = 10.25, 20.5, 100.75, 70.125
    tgt.draw(C.GL_LINES, [(x0, y0), (x1, y1)], [(255, 255, 255, 255)] * 2)
    a = tgt.read()[..., 3].astype(np.float64) / 255
    X, Y = centres()
    dx, dy = x1 - x0, y1 - y0
    L = np.hypot(dx, dy)
    along = ((X - x0) * dx + (Y - y0) * dy) / L
    across = np.abs((X - x0) * dy - (Y - y0) * dx) / L
    far = (across > width / 2 + 0.75) | (along < -0.75) | (along > L + 0.75)
    assert (a[far] == 0).all(), f"{int((a[far] > 0).sum())} pixels far from the line have alpha"
    near = (across <= max(width / 2 - 0.75, 0.0) + 0.01) & (along > 2) & (along < L - 2)
    if width >= 2:
        # fully inside: full coverage
        full = (across <= width / 2 - 0.75) & (along > 2) & (along < L - 2)
        assert (a[full] == 1).all(), f"min alpha inside {a[full].min()}"
    # every column along the body has some coverage, none above 1
    cols = np.arange(int(x0) + 2, int(x1) - 2)
    assert (a[:, cols].max(axis=0) > 0).all()
    assert a.max() <= 1.0 and near.any()


def test_flat_shaded_line_second_vertex(tgt: Target) -> None:
    gl = tgt.gl
    gl.glShadeModel(C.GL_FLAT)
    red, green, blue = (255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255)
    tgt.draw(C.GL_LINES, [(4.5, 10.5), (60.5, 10.5)], [red, green])
    img = tgt.read()
    assert (img[10, 4:60] == green).all()
    tgt.clear()
    tgt.draw(C.GL_LINE_STRIP, [(4.5, 20.5), (30.5, 20.5), (60.5, 20.5)], [red, green, blue])
    img = tgt.read()
    assert (img[20, 4:30] == green).all() and (img[20, 30:60] == blue).all()
    tgt.clear()
    white = (255, 255, 255, 255)
    tgt.draw(C.GL_LINE_LOOP, [(4.5, 30.5), (60.5, 30.5), (60.5, 40.5), (4.5, 40.5)],
             [red, green, blue, white])
    img = tgt.read()
    assert (img[30, 4:60] == green).all()          # 0 -> 1: vertex 1
    assert (img[30:40, 60] == blue).all()          # 1 -> 2: vertex 2
    assert (img[40, 5:61] == white).all()          # 2 -> 3: vertex 3
    assert (img[31:41, 4] == red).all()            # 3 -> 0, the closing segment: vertex 0


def test_smooth_shaded_line_interpolates(tgt: Target) -> None:
    tgt.draw(C.GL_LINES, [(0.5, 10.5), (64.5, 10.5)], [(0, 0, 0, 255), (255, 0, 0, 255)])
    r = tgt.read()[10, 0:64, 0].astype(float)
    want = 255 * np.arange(64) / 64
    assert np.abs(r - want).max() <= 1.01


@needs_mesa
@pytest.mark.parametrize("xmajor", [True, False])
def test_mesa_line_matches_gles_away_from_endpoints(mesa_tgt: Target, xmajor: bool) -> None:
    """llvmpipe and gles agree on every column but the first and last.

    At the endpoints llvmpipe applies the diamond-exit rule itself (a column
    whose centre lies just outside the span may be drawn, or one just inside
    left out); gles uses the half-open centre span. Both are within the
    spec's 1 px endpoint slack; this test pins the interior agreement."""
    ref = Target("fixed")
    errs, ends = [], 0
    for x0, y0, x1, y1 in line_cases(11 if xmajor else 12, 25, xmajor):
        for t in (mesa_tgt, ref):
            t.clear()
            t.draw(C.GL_LINES, [(x0, y0), (x1, y1)], [(255, 255, 255, 255)] * 2)
        gm, gg = mesa_tgt.mask(), ref.mask()
        if not xmajor:
            gm, gg = gm.T, gg.T
        a, b = sorted((x0, x1) if xmajor else (y0, y1))
        diff = np.nonzero((gm != gg).any(axis=0))[0]
        interior = [c for c in diff if abs(c + 0.5 - a) > 1.5 and abs(c + 0.5 - b) > 1.5]
        ends += len(diff) - len(interior)
        # a crossing within a subpixel of a row boundary is a tie gles decides on its 1/256 grid
        ma, na, mb, nb = (x0, y0, x1, y1) if xmajor else (y0, x0, y1, x1)
        line = [na + (nb - na) * (c + 0.5 - ma) / (mb - ma) for c in interior]
        ties = [c for c, m in zip(interior, line) if abs(m - round(m)) < 1 / 128]
        interior = [c for c in interior if c not in ties]
        if interior:
            errs.append(f"({x0}, {y0})-({x1}, {y1}): columns {interior[:5]} differ")
    assert not errs, "\n".join(errs[:8])
    print(f"llvmpipe vs gles: {ends} endpoint columns differ over 25 lines")


@needs_mesa
@pytest.mark.parametrize("xmajor", [True, False])
def test_mesa_line_conformance_rule(mesa_tgt: Target, xmajor: bool) -> None:
    """The published LineRaster rule: one per column, 1 px endpoint slack."""
    errs = []
    for x0, y0, x1, y1 in line_cases(11 if xmajor else 12, 25, xmajor):
        mesa_tgt.clear()
        mesa_tgt.draw(C.GL_LINES, [(x0, y0), (x1, y1)], [(255, 255, 255, 255)] * 2)
        e = check_line(mesa_tgt.mask(), x0, y0, x1, y1, slack=1)
        if e:
            errs.append(f"({x0}, {y0})-({x1}, {y1}): {e}")
    assert not errs, "\n".join(errs[:8])


# {============================================================
# polygon offset


def quad(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> list:
    """A quad whose object z goes linearly from z0 at x0 to z1 at x1 (two triangles)."""
    return [(x0, y0, z0), (x1, y0, z1), (x1, y1, z1), (x0, y0, z0), (x1, y1, z1), (x0, y1, z0)]


def offset_case(t: Target, q: list, factor: float, units: float, func: int) -> np.ndarray:
    """Draw q red, then q green with the offset and depth func; the green mask."""
    gl = t.gl
    t.clear()
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_ALWAYS)
    t.draw(C.GL_TRIANGLES, q, [(255, 0, 0, 255)] * len(q))
    gl.glDepthFunc(func)
    gl.glEnable(C.GL_POLYGON_OFFSET_FILL)
    gl.glPolygonOffset(factor, units)
    t.draw(C.GL_TRIANGLES, q, [(0, 255, 0, 255)] * len(q))
    gl.glDisable(C.GL_POLYGON_OFFSET_FILL)
    return t.read()[..., 1] == 255


def offset_tgt(numeric: str) -> Target:
    return Target(numeric, 64, 64, depth=16)


@pytest.mark.parametrize("numeric", BUILDS)
def test_polygon_offset_units(numeric: str) -> None:
    t = offset_tgt(numeric)
    q = quad(4, 60, 4, 60, 0.3, 0.3)
    area = np.zeros((64, 64), dtype=bool)
    area[4:60, 4:60] = True
    assert not offset_case(t, q, 0, 0, C.GL_LESS).any(), "coplanar without offset passes LESS"
    assert np.array_equal(offset_case(t, q, 0, -1, C.GL_LESS), area), "units -1 must pass LESS"
    assert not offset_case(t, q, 0, 1, C.GL_LESS).any()
    assert np.array_equal(offset_case(t, q, 0, 1, C.GL_GREATER), area), "units +1 must pass GREATER"
    assert not offset_case(t, q, 5.0, 0, C.GL_GREATER).any(), "factor on a flat polygon: m = 0"
    t.gl.glPolygonOffsetx(0, -(1 << 16))
    assert t.gl.glGetFloatv(C.GL_POLYGON_OFFSET_UNITS) == -1.0


@pytest.mark.parametrize("numeric", BUILDS)
def test_polygon_offset_factor_slope(numeric: str) -> None:
    """Slope m in depth units per pixel; B lies m/2 behind A: a factor of -1
    brings it in front (o = -m), -1/4 does not (o = -m/4)."""
    t = offset_tgt(numeric)
    gl = t.gl
    Z = 65535
    # z from -0.5 at x=0 to 0.5 at x=64: window depth 0.75 -> 0.25, slope 0.5/64 per pixel
    m = 0.5 / 64 * Z
    shift = m / 2 / Z * 2                      # object-z shift moving window depth by m/2 (behind)
    a = quad(0, 64, 4, 60, -0.5, 0.5)
    b = quad(0, 64, 4, 60, -0.5 - shift, 0.5 - shift)
    area = np.zeros((64, 64), dtype=bool)
    area[4:60, :] = True
    for factor, passes in ((-1.0, True), (-0.25, False), (0.0, False)):
        t.clear()
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDepthFunc(C.GL_ALWAYS)
        t.draw(C.GL_TRIANGLES, a, [(255, 0, 0, 255)] * 6)
        gl.glDepthFunc(C.GL_LESS)
        gl.glEnable(C.GL_POLYGON_OFFSET_FILL)
        gl.glPolygonOffset(factor, 0.0)
        t.draw(C.GL_TRIANGLES, b, [(0, 255, 0, 255)] * 6)
        gl.glDisable(C.GL_POLYGON_OFFSET_FILL)
        green = t.read()[..., 1] == 255
        if passes:
            assert np.array_equal(green, area), f"factor {factor}: {describe(green, area)}"
        else:
            assert not green.any(), f"factor {factor}: {int(green.sum())} pixels passed"
    assert gl.glGetFloatv(C.GL_POLYGON_OFFSET_FACTOR) == 0.0


@pytest.mark.parametrize("numeric", BUILDS)
def test_polygon_offset_not_for_lines_points(numeric: str) -> None:
    t = offset_tgt(numeric)
    gl = t.gl
    for mode, verts in ((C.GL_LINES, [(4.5, 10.5, 0.2), (60.5, 10.5, 0.2)]),
                        (C.GL_POINTS, [(30.5, 30.5, 0.2)])):
        t.clear()
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDepthFunc(C.GL_LESS)
        gl.glPointSize(5.0)
        t.draw(mode, verts, [(255, 0, 0, 255)] * len(verts))
        gl.glEnable(C.GL_POLYGON_OFFSET_FILL)
        gl.glPolygonOffset(-4.0, -1000.0)
        t.draw(mode, verts, [(0, 255, 0, 255)] * len(verts))
        gl.glDisable(C.GL_POLYGON_OFFSET_FILL)
        img = t.read()
        assert not (img[..., 1] == 255).any(), f"polygon offset applied to mode {mode}"
        assert (img[..., 0] == 255).any()


# {============================================================
# draw texture


def drawtex_setup(gl: Any, n: int = 8) -> np.ndarray:
    """An n x n texture, texel (i, j) = (32i, 32j, 255 - 16(i+j), 255), NEAREST, REPLACE."""
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    img = np.stack([i * 32, j * 32, 255 - 16 * (i + j), np.full_like(i, 255)], axis=-1).astype(np.uint8)
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(C.GL_TEXTURE_2D, name)
    for p in (C.GL_TEXTURE_MIN_FILTER, C.GL_TEXTURE_MAG_FILTER):
        gl.glTexParameteri(C.GL_TEXTURE_2D, p, C.GL_NEAREST)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, n, n, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                    np.ascontiguousarray(img))
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, np.array([0, 0, n, n], dtype=np.int32))
    return img


def test_drawtex_one_to_one(tgt: Target) -> None:
    gl = tgt.gl
    tex = drawtex_setup(gl)
    gl.glDrawTexiOES(10, 12, 0, 8, 8)
    assert gl.glGetError() == 0
    img = tgt.read()
    assert np.array_equal(img[12:20, 10:18], tex)
    assert img.any(axis=-1).sum() == 64
    tgt.clear()
    gl.glDrawTexxOES(30 << 16, 40 << 16, 0, 8 << 16, 8 << 16)
    gl.glDrawTexsvOES([50, 60, 0, 8, 8])
    img = tgt.read()
    assert np.array_equal(img[40:48, 30:38], tex) and np.array_equal(img[60:68, 50:58], tex)


def test_drawtex_stretch_and_subcrop(tgt: Target) -> None:
    gl = tgt.gl
    tex = drawtex_setup(gl)
    gl.glDrawTexfOES(0.0, 0.0, 0.0, 16.0, 24.0)            # x2 horizontally, x3 vertically
    img = tgt.read()
    want = np.repeat(np.repeat(tex, 3, axis=0), 2, axis=1)
    assert np.array_equal(img[:24, :16], want)
    tgt.clear()
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, np.array([2, 3, 4, 2], dtype=np.int32))
    gl.glDrawTexiOES(40, 40, 0, 4, 2)
    img = tgt.read()
    assert np.array_equal(img[40:42, 40:44], tex[3:5, 2:6])


def test_drawtex_negative_crop_flips(tgt: Target) -> None:
    gl = tgt.gl
    tex = drawtex_setup(gl)
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, np.array([8, 0, -8, 8], dtype=np.int32))
    gl.glDrawTexiOES(10, 10, 0, 8, 8)
    img = tgt.read()
    assert np.array_equal(img[10:18, 10:18], tex[:, ::-1])
    tgt.clear()
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, np.array([0, 8, 8, -8], dtype=np.int32))
    gl.glDrawTexiOES(10, 10, 0, 8, 8)
    img = tgt.read()
    assert np.array_equal(img[10:18, 10:18], tex[::-1, :])


@pytest.mark.parametrize("z,stored", [(0.5, 0.5), (-3.0, 0.25), (2.0, 0.75), (0.2, 0.35)])
def test_drawtex_depth(tgt: Target, z: float, stored: float) -> None:
    gl = tgt.gl
    drawtex_setup(gl)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_ALWAYS)
    gl.glDepthRangef(0.25, 0.75)
    gl.glDrawTexfOES(0.0, 0.0, z, 64.0, 64.0)
    gl.glDepthRangef(0.0, 1.0)
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glDepthFunc(C.GL_LESS)
    # under glOrthof(.., -1, 1) window depth d comes from object z = 1 - 2d
    for x0, d, hit in ((0, stored - 0.01, True), (32, stored + 0.01, False)):
        zo = 1 - 2 * d
        tgt.draw(C.GL_TRIANGLES, quad(x0, x0 + 32, 0, 64, zo, zo), [(1, 2, 3, 255)] * 6)
        block = tgt.read()[0:64, x0:x0 + 32]
        assert ((block == (1, 2, 3, 255)).all(axis=-1).all() if hit
                else not (block == (1, 2, 3, 255)).all(axis=-1).any()), (z, d, hit)


def test_drawtex_errors(tgt: Target) -> None:
    gl = tgt.gl
    drawtex_setup(gl)
    for args in ((0, 0, 0, 0, 8), (0, 0, 0, 8, 0), (0, 0, 0, -1, 8), (0, 0, 0, 8, -3)):
        gl.glDrawTexiOES(*args)
        assert gl.glGetError() == C.GL_INVALID_VALUE, args
    gl.glDrawTexfOES(0.0, 0.0, 0.0, -0.5, 4.0)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glDrawTexxOES(0, 0, 0, 8 << 16, 0)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    assert not tgt.mask().any()


@needs_mesa
def test_mesa_drawtex_one_to_one_and_flip(mesa_tgt: Target) -> None:
    gl = mesa_tgt.gl
    tex = drawtex_setup(gl)
    gl.glDrawTexiOES(10, 12, 0, 8, 8)
    img = mesa_tgt.read()
    assert np.array_equal(img[12:20, 10:18], tex)
    mesa_tgt.clear()
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, np.array([8, 0, -8, 8], dtype=np.int32))
    gl.glDrawTexiOES(10, 10, 0, 8, 8)
    assert np.array_equal(mesa_tgt.read()[10:18, 10:18], tex[:, ::-1])


# {============================================================
# errors leave the state unchanged


def test_error_rules(tgt: Target) -> None:
    gl = tgt.gl
    gl.glPointSize(3.0)
    gl.glLineWidth(2.0)
    for bad in (0.0, -1.0):
        gl.glPointSize(bad)
        assert gl.glGetError() == C.GL_INVALID_VALUE
        gl.glLineWidth(bad)
        assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glPointSizex(0)
    assert gl.glGetError() == C.GL_INVALID_VALUE
    gl.glLineWidthx(-(1 << 16))
    assert gl.glGetError() == C.GL_INVALID_VALUE
    assert gl.glGetFloatv(C.GL_POINT_SIZE) == 3.0
    assert gl.glGetFloatv(C.GL_LINE_WIDTH) == 2.0

    gl.glPointParameterf(C.GL_POINT_SIZE_MIN, 2.0)
    gl.glPointParameterf(C.GL_POINT_SIZE_MAX, 9.0)
    gl.glPointParameterf(C.GL_POINT_FADE_THRESHOLD_SIZE, 1.5)
    gl.glPointParameterfv(C.GL_POINT_DISTANCE_ATTENUATION, [1.0, 0.5, 0.25])
    assert gl.glGetError() == 0
    for pname in (C.GL_POINT_SIZE, C.GL_LINE_WIDTH, C.GL_POINT_SMOOTH):
        gl.glPointParameterf(pname, 1.0)
        assert gl.glGetError() == C.GL_INVALID_ENUM, hex(pname)
        gl.glPointParameterx(pname, 1 << 16)
        assert gl.glGetError() == C.GL_INVALID_ENUM, hex(pname)
    # the scalar form does not take the vector pname
    gl.glPointParameterf(C.GL_POINT_DISTANCE_ATTENUATION, 1.0)
    assert gl.glGetError() == C.GL_INVALID_ENUM
    for pname in (C.GL_POINT_SIZE_MIN, C.GL_POINT_SIZE_MAX, C.GL_POINT_FADE_THRESHOLD_SIZE):
        gl.glPointParameterf(pname, -1.0)
        assert gl.glGetError() == C.GL_INVALID_VALUE, hex(pname)
        gl.glPointParameterxv(pname, [-(1 << 16)])
        assert gl.glGetError() == C.GL_INVALID_VALUE, hex(pname)
    assert gl.glGetFloatv(C.GL_POINT_SIZE_MIN) == 2.0
    assert gl.glGetFloatv(C.GL_POINT_SIZE_MAX) == 9.0
    assert gl.glGetFloatv(C.GL_POINT_FADE_THRESHOLD_SIZE) == 1.5
    assert list(gl.glGetFloatv(C.GL_POINT_DISTANCE_ATTENUATION)) == [1.0, 0.5, 0.25]
    gl.glPolygonOffset(2.0, 3.0)
    assert gl.glGetFloatv(C.GL_POLYGON_OFFSET_FACTOR) == 2.0
    assert gl.glGetFloatv(C.GL_POLYGON_OFFSET_UNITS) == 3.0
    assert gl.glGetError() == 0


def test_defaults(tgt: Target) -> None:
    gl = tgt.gl
    assert gl.glGetFloatv(C.GL_POINT_SIZE) == 1.0
    assert gl.glGetFloatv(C.GL_LINE_WIDTH) == 1.0
    assert gl.glGetFloatv(C.GL_POINT_SIZE_MIN) == 0.0
    assert gl.glGetFloatv(C.GL_POINT_SIZE_MAX) >= 1.0
    assert gl.glGetFloatv(C.GL_POINT_FADE_THRESHOLD_SIZE) == 1.0
    assert list(gl.glGetFloatv(C.GL_POINT_DISTANCE_ATTENUATION)) == [1.0, 0.0, 0.0]
    assert gl.glGetTexEnviv(C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES) == 0
    assert not gl.glIsEnabled(C.GL_POINT_SPRITE_OES)
