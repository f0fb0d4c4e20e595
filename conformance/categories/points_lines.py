"""Points, lines and draw-texture.

Categories PointRaster, PointAntiAlias, PointSizeArray, PointSprite,
LineRaster, LineHV, LineAntiAlias and DrawTex (spec sections 3.3, 3.4,
OES_point_size_array, OES_point_sprite, OES_draw_texture).

Expected pictures come from the spec's rules (SPEC-NOTES.md): an aliased
point of width w (the size rounded) covers the w x w pixels centred on pixel
floor(x) (odd w) or on the corner floor(x + 1/2) (even w), exactly up to size
50 (the published PointRaster rule); a point sprite covers the pixels whose
centres lie in the size x size square with s = 1/2 + (x_f + 1/2 - x_w)/size,
t = 1/2 - (y_f + 1/2 - y_w)/size; an aliased line of width 1 gives one
fragment per column (x-major) or row (y-major), with 1 px slack at the
endpoints (the published LineRaster rule). Only x commands and non-FLOAT
arrays are used, so every test runs in both profiles. Window positions are
on the 1/16 grid (4 subpixel bits, Table 6.21) and the window is a power of
two, so they are exact in every implementation.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..harness import TestContext, Unsupported, conformance_test

ONE = 1 << 16
WHITE = (255, 255, 255, 255)


def _size_range(t: TestContext, pname: str) -> float:
    gl = t.gl
    r = gl.glGetFixedv(getattr(gl, pname))
    return float(np.asarray(r).reshape(-1)[1]) / ONE


def _covered(t: TestContext) -> np.ndarray:
    """Pixels that differ from the black clear colour (any channel above half a step)."""
    return (t.read()[..., :3] > 0.5 / 255).any(axis=-1)


def _describe(got: np.ndarray, want: np.ndarray) -> str:
    extra, missing = np.argwhere(got & ~want), np.argwhere(want & ~got)
    return (f"{len(extra)} extra pixels (first y,x {extra[:3].tolist()}), "
            f"{len(missing)} missing (first y,x {missing[:3].tolist()})")


def _q16(v: Any) -> Any:
    return np.round(np.asarray(v, dtype=np.float64) * 16) / 16


def point_footprint(x: float, y: float, size: float, w: int, h: int) -> np.ndarray:
    n = max(1, int(np.floor(size + 0.5)))
    if n % 2:
        x0, y0 = int(np.floor(x)) - (n - 1) // 2, int(np.floor(y)) - (n - 1) // 2
    else:
        x0, y0 = int(np.floor(x + 0.5)) - n // 2, int(np.floor(y + 0.5)) - n // 2
    m = np.zeros((h, w), dtype=bool)
    m[max(y0, 0):max(y0 + n, 0), max(x0, 0):max(x0 + n, 0)] = True
    return m


def _centres(t: TestContext) -> tuple[np.ndarray, np.ndarray]:
    return np.meshgrid(np.arange(t.width) + 0.5, np.arange(t.height) + 0.5)


# {============================================================
# PointRaster


@conformance_test("PointRaster", section="3.3", size=(128, 128))
def point_raster(t: TestContext) -> None:
    """Aliased points of sizes 1..50 at random subpixel centres cover exactly their footprint (3.3)."""
    gl = t.gl
    t.ortho_pixels()
    top = min(50, int(_size_range(t, "GL_ALIASED_POINT_SIZE_RANGE")))
    rng = np.random.default_rng(5)
    for size in range(1, top + 1):
        for _ in range(2):
            x, y = (float(v) for v in _q16(rng.uniform(56, 72, size=2)))
            t.clear()
            gl.glPointSizex(size * ONE)
            t.draw(gl.GL_POINTS, [(x, y)], [WHITE])
            got, want = _covered(t), point_footprint(x, y, size, t.width, t.height)
            if not np.array_equal(got, want):
                t.fail(f"size {size} at ({x}, {y}): {_describe(got, want)}")
    t.check_gl_error("PointRaster")


# {============================================================
# PointAntiAlias


@conformance_test("PointAntiAlias", section="3.3.2", uses=("blend", "alpha"), size=(64, 64))
def point_antialias(t: TestContext) -> None:
    """Smooth points: alpha 0 outside the disc, 1 for pixels inside it, coverage at the centre (3.3.2)."""
    gl = t.gl
    if t.visual.bits[3] == 0:
        raise Unsupported("the visual has no alpha bits")
    t.ortho_pixels()
    gl.glEnable(gl.GL_POINT_SMOOTH)
    top = _size_range(t, "GL_SMOOTH_POINT_SIZE_RANGE")
    X, Y = _centres(t)
    tol = t.visual.color_tolerance()[3]
    for size in (1.0, 3.0, 4.5, 8.0, 15.25):
        if size > top:
            continue
        x, y = 31.3125, 30.6875
        t.clear()
        gl.glPointSizex(int(size * ONE))
        t.draw(gl.GL_POINTS, [(x, y)], [WHITE])
        a = t.read()[..., 3]
        near = np.hypot(np.clip(x, X - 0.5, X + 0.5) - x, np.clip(y, Y - 0.5, Y + 0.5) - y)
        far = np.hypot(np.abs(X - x) + 0.5, np.abs(Y - y) + 0.5)
        r = size / 2
        if (a[near >= r + 1e-9] > tol).any():
            t.fail(f"smooth point size {size}: alpha outside the disc")
        if (a[far <= r] < 1 - tol).any():
            t.fail(f"smooth point size {size}: pixel inside the disc not fully covered")
        if a[int(y), int(x)] <= tol:
            t.fail(f"smooth point size {size}: no coverage at the centre")
    gl.glDisable(gl.GL_POINT_SMOOTH)
    t.check_gl_error("PointAntiAlias")


# {============================================================
# PointSizeArray


@conformance_test("PointSizeArray", section="OES_point_size_array", size=(128, 128))
def point_size_array(t: TestContext) -> None:
    """Per-vertex sizes from a FIXED size array give each point its footprint (OES_point_size_array)."""
    gl = t.gl
    t.need_extension("GL_OES_point_size_array")
    t.ortho_pixels()
    top = _size_range(t, "GL_ALIASED_POINT_SIZE_RANGE")
    pts = [(16.5, 16.5), (48.25, 16.75), (96.5, 20.5), (20.5, 70.5), (70.5, 80.5), (100.0, 100.0)]
    sizes = [min(s, top) for s in (1.0, 4.0, 7.0, 12.0, 21.0, 2.0)]
    arr = np.array([int(s * ONE) for s in sizes], dtype=np.int32)
    t.clear()
    gl.glPointSizex(ONE)
    gl.glEnableClientState(gl.GL_POINT_SIZE_ARRAY_OES)
    gl.glPointSizePointerOES(gl.GL_FIXED, 0, arr)
    t.draw(gl.GL_POINTS, pts, [WHITE] * len(pts))
    gl.glDisableClientState(gl.GL_POINT_SIZE_ARRAY_OES)
    want = np.zeros((t.height, t.width), dtype=bool)
    for (x, y), s in zip(pts, sizes):
        want |= point_footprint(x, y, s, t.width, t.height)
    got = _covered(t)
    if not np.array_equal(got, want):
        t.fail(f"size array: {_describe(got, want)}")
    t.check_gl_error("PointSizeArray")


# {============================================================
# PointSprite

TEX = 64


@conformance_test("PointSprite", section="OES_point_sprite", uses=("texture",), size=(128, 128))
def point_sprite(t: TestContext) -> None:
    """Sprites cover the size x size square; COORD_REPLACE gives s, t by position (OES_point_sprite)."""
    gl = t.gl
    t.need_extension("GL_OES_point_sprite")
    t.ortho_pixels()
    i, j = np.meshgrid(np.arange(TEX), np.arange(TEX))
    img = np.stack([i * 4, j * 4, np.zeros_like(i), np.full_like(i, 255)], axis=-1).astype(np.uint8)
    name = int(np.asarray(gl.glGenTextures(1)).reshape(-1)[0])
    gl.glBindTexture(gl.GL_TEXTURE_2D, name)
    for p, v in ((gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST), (gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST),
                 (gl.GL_TEXTURE_WRAP_S, gl.GL_CLAMP_TO_EDGE), (gl.GL_TEXTURE_WRAP_T, gl.GL_CLAMP_TO_EDGE)):
        gl.glTexParameteri(gl.GL_TEXTURE_2D, p, v)
    gl.glTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_RGBA, TEX, TEX, 0, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE,
                    np.ascontiguousarray(img))
    gl.glEnable(gl.GL_TEXTURE_2D)
    gl.glTexEnvi(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE, gl.GL_REPLACE)
    gl.glEnable(gl.GL_POINT_SPRITE_OES)
    gl.glTexEnvi(gl.GL_POINT_SPRITE_OES, gl.GL_COORD_REPLACE_OES, 1)
    top = _size_range(t, "GL_ALIASED_POINT_SIZE_RANGE")
    X, Y = _centres(t)
    rng = np.random.default_rng(9)
    step = 255 * t.visual.color_tolerance()[:2]          # one shade, in 0..255 units
    try:
        for size in (1.0, 2.0, 3.0, 5.5, 8.0, 13.0, 16.0, 31.75, 48.0):
            if size > top:
                continue
            x, y = (float(v) for v in _q16(rng.uniform(56, 72, size=2)))
            t.clear()
            gl.glPointSizex(int(size * ONE))
            t.draw(gl.GL_POINTS, [(x, y)], [WHITE])
            got = t.read()
            want = (X >= x - size / 2) & (X < x + size / 2) & (Y >= y - size / 2) & (Y < y + size / 2)
            # a pixel centre exactly on the square's edge may go either way
            edge = ((np.abs(np.abs(X - x) - size / 2) < 1e-9) | (np.abs(np.abs(Y - y) - size / 2) < 1e-9))
            cov = got[..., 3] > 0.5
            if ((cov != want) & ~edge).any():
                t.fail(f"sprite size {size} at ({x}, {y}): footprint {_describe(cov & ~edge, want & ~edge)}")
            for coord, ch, nm in ((0.5 + (X - x) / size, 0, "s"), (0.5 - (Y - y) / size, 1, "t")):
                u = coord * TEX
                lo = np.clip(np.floor(u - 1e-3), 0, TEX - 1) * 4
                hi = np.clip(np.floor(u + 1e-3), 0, TEX - 1) * 4
                v = got[..., ch] * 255
                ok = (np.abs(v - lo) <= step[ch]) | (np.abs(v - hi) <= step[ch])
                bad = want & ~edge & ~ok
                if bad.any():
                    yy, xx = np.argwhere(bad)[0]
                    t.fail(f"sprite size {size} at ({x}, {y}): {nm} wrong at {int(bad.sum())} pixels, "
                           f"first (x={xx}, y={yy}): texel {v[yy, xx] / 4:.2f}, want {lo[yy, xx] / 4:.0f}")
    finally:
        gl.glDisable(gl.GL_POINT_SPRITE_OES)
        gl.glTexEnvi(gl.GL_POINT_SPRITE_OES, gl.GL_COORD_REPLACE_OES, 0)
        gl.glDisable(gl.GL_TEXTURE_2D)
        gl.glDeleteTextures(1, [name])
    t.check_gl_error("PointSprite")


# {============================================================
# LineRaster, LineHV


def _line_check(got: np.ndarray, p0: tuple, p1: tuple, slack: int) -> str | None:
    (x0, y0), (x1, y1) = p0, p1
    xmajor = abs(x1 - x0) >= abs(y1 - y0)
    g = got if xmajor else got.T
    a0, b0, a1, b1 = (x0, y0, x1, y1) if xmajor else (y0, x0, y1, x1)
    c = np.arange(g.shape[1]) + 0.5
    lo_a, hi_a = min(a0, a1), max(a0, a1)
    span = np.nonzero((c >= lo_a) & (c <= hi_a))[0]
    allowed = np.zeros(g.shape[1], dtype=bool)
    allowed[max(span.min() - slack, 0):span.max() + slack + 1] = True
    if g[:, ~allowed].any():
        return f"fragments beyond the endpoints at columns {np.nonzero(g[:, ~allowed].any(axis=0))[0][:4]}"
    for col in span[slack:len(span) - slack]:
        rows = np.nonzero(g[:, col])[0]
        if len(rows) != 1:
            return f"column {col}: {len(rows)} fragments, want 1"
        m = b0 + (b1 - b0) * (col + 0.5 - a0) / (a1 - a0)
        if abs(rows[0] + 0.5 - m) > 1.0:
            return f"column {col}: fragment at {rows[0]}, line at {m:.3f}"
    return None


@conformance_test("LineRaster", section="3.4", size=(128, 128))
def line_raster(t: TestContext) -> None:
    """Aliased width-1 lines: one fragment per column (row when y-major), 1 px endpoint slack (3.4.1)."""
    gl = t.gl
    t.ortho_pixels()
    rng = np.random.default_rng(13)
    n = 0
    while n < 60:
        p = _q16(rng.uniform(4, 124, size=4))
        if abs(abs(p[2] - p[0]) - abs(p[3] - p[1])) < 1:
            continue                              # near-diagonal: the major axis is ambiguous
        n += 1
        a, b = (float(p[0]), float(p[1])), (float(p[2]), float(p[3]))
        t.clear()
        gl.glLineWidthx(ONE)
        t.draw(gl.GL_LINES, [a, b], [WHITE, WHITE])
        err = _line_check(_covered(t), a, b, slack=1)
        if err:
            t.fail(f"line {a}-{b}: {err}")
    t.check_gl_error("LineRaster")


@conformance_test("LineHV", section="3.4", size=(64, 64))
def line_hv(t: TestContext) -> None:
    """H/V lines between pixel centres: half-open spans; a strip hits each pixel once (3.4.1)."""
    gl = t.gl
    t.ortho_pixels()
    cases = [((2.5, 5.5), (40.5, 5.5), [(x, 5) for x in range(2, 40)]),
             ((40.5, 9.5), (2.5, 9.5), [(x, 9) for x in range(3, 41)]),
             ((7.5, 3.5), (7.5, 50.5), [(7, y) for y in range(3, 50)]),
             ((11.5, 50.5), (11.5, 3.5), [(11, y) for y in range(4, 51)]),
             ((0.5, 63.5), (64.5, 63.5), [(x, 63) for x in range(0, 64)])]
    for a, b, pix in cases:
        t.clear()
        t.draw(gl.GL_LINES, [a, b], [WHITE, WHITE])
        want = np.zeros((t.height, t.width), dtype=bool)
        for x, y in pix:
            want[y, x] = True
        # §3.4.1 lets the endpoint rule differ by one fragment: the span of
        # the reversed segment (first pixel left out, last drawn) is allowed too
        alt = np.zeros_like(want)
        for x, y in pix:
            step = -1 if (b[1] < a[1] if a[0] == b[0] else b[0] < a[0]) else 1
            ax, ay = (x, y + step) if a[0] == b[0] else (x + step, y)
            if 0 <= ax < t.width and 0 <= ay < t.height:
                alt[ay, ax] = True
        got = _covered(t)
        if not (np.array_equal(got, want) or np.array_equal(got, alt)):
            t.fail(f"line {a}-{b}: {_describe(got, want)}")
    # a strip around a rectangle: every border pixel exactly once
    t.clear()
    gl.glEnable(gl.GL_BLEND)
    gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE)
    grey = (64, 64, 64, 64)
    rect = [(2.5, 2.5), (30.5, 2.5), (30.5, 20.5), (2.5, 20.5), (2.5, 2.5)]
    t.draw(gl.GL_LINE_STRIP, rect, [grey] * 5)
    gl.glDisable(gl.GL_BLEND)
    hits = np.round(t.read()[..., 0] * 255 / 64).astype(int)
    want = np.zeros((t.height, t.width), dtype=int)
    want[2, 2:31] = want[20, 2:31] = 1
    want[2:21, 2] = want[2:21, 30] = 1
    # §3.4.1 rule 4 binds only joins of two x-major or two y-major segments:
    # the corners here join one of each and may go either way
    for cy, cx in ((2, 2), (2, 30), (20, 30), (20, 2)):
        hits[cy, cx] = want[cy, cx]
    if not np.array_equal(hits, want):
        t.fail(f"line strip rectangle: {int((hits > 1).sum())} pixels hit twice, "
               f"{_describe(hits > 0, want > 0)}")
    t.check_gl_error("LineHV")


# {============================================================
# LineAntiAlias


@conformance_test("LineAntiAlias", section="3.4.2", uses=("blend", "alpha"), size=(128, 128))
def line_antialias(t: TestContext) -> None:
    """Smooth lines: alpha in (0, 1] near the line, 0 far from it (3.4.2)."""
    gl = t.gl
    if t.visual.bits[3] == 0:
        raise Unsupported("the visual has no alpha bits")
    t.ortho_pixels()
    gl.glEnable(gl.GL_LINE_SMOOTH)
    top = _size_range(t, "GL_SMOOTH_LINE_WIDTH_RANGE")
    X, Y = _centres(t)
    tol = t.visual.color_tolerance()[3]
    x0, y0, x1, y1 = 10.25, 20.5, 110.75, 80.125
    dx, dy = x1 - x0, y1 - y0
    L = np.hypot(dx, dy)
    along = ((X - x0) * dx + (Y - y0) * dy) / L
    across = np.abs((X - x0) * dy - (Y - y0) * dx) / L
    for width in (1.0, 2.0, 3.5):
        if width > top:
            continue
        t.clear()
        gl.glLineWidthx(int(width * ONE))
        t.draw(gl.GL_LINES, [(x0, y0), (x1, y1)], [WHITE, WHITE])
        a = t.read()[..., 3]
        far = (across > width / 2 + 1.0) | (along < -1.0) | (along > L + 1.0)
        if (a[far] > tol).any():
            t.fail(f"smooth line width {width}: {int((a[far] > tol).sum())} pixels far from the line "
                   "have alpha")
        body = (along > 2) & (along < L - 2)
        for col in range(int(x0) + 3, int(x1) - 3):
            if a[:, col][body[:, col]].max() <= tol:
                t.fail(f"smooth line width {width}: column {col} has no coverage")
        if width >= 2.5:
            full = (across <= width / 2 - 0.75) & body
            if (a[full] < 1 - tol).any():
                t.fail(f"smooth line width {width}: pixels inside the line not fully covered")
    gl.glDisable(gl.GL_LINE_SMOOTH)
    gl.glLineWidthx(ONE)
    t.check_gl_error("LineAntiAlias")


# {============================================================
# DrawTex


@conformance_test("DrawTex", section="OES_draw_texture", uses=("texture",), size=(64, 64))
def draw_tex(t: TestContext) -> None:
    """DrawTex maps the crop rectangle onto the window: 1:1, stretched, flipped (OES_draw_texture)."""
    gl = t.gl
    t.need_extension("GL_OES_draw_texture")
    n = 8
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    tex = np.stack([i * 32, j * 32, 255 - 16 * (i + j), np.full_like(i, 255)], axis=-1).astype(np.uint8)
    name = int(np.asarray(gl.glGenTextures(1)).reshape(-1)[0])
    gl.glBindTexture(gl.GL_TEXTURE_2D, name)
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST)
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST)
    gl.glTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_RGBA, n, n, 0, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE,
                    np.ascontiguousarray(tex))
    gl.glEnable(gl.GL_TEXTURE_2D)
    gl.glTexEnvi(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE, gl.GL_REPLACE)
    want = tex.astype(np.float64) / 255

    def crop(r: list[int]) -> None:
        gl.glTexParameteriv(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_CROP_RECT_OES, np.array(r, dtype=np.int32))

    def region(x: int, y: int, w: int, h: int, rgba: np.ndarray, where: str) -> None:
        img = t.read()
        tol = t.visual.color_tolerance()
        bad = (np.abs(img[y:y + h, x:x + w] - rgba) > tol).any(axis=-1)
        if bad.any():
            yy, xx = np.argwhere(bad)[0]
            t.fail(f"{where}: {int(bad.sum())} pixels differ, first (x={x + xx}, y={y + yy}): "
                   f"{np.round(img[y + yy, x + xx], 3).tolist()} want {np.round(rgba[yy, xx], 3).tolist()}")
        outside = np.ones(img.shape[:2], dtype=bool)
        outside[y:y + h, x:x + w] = False
        if (img[outside] > tol).any():
            t.fail(f"{where}: pixels outside the rectangle were drawn")

    try:
        t.clear()
        crop([0, 0, n, n])
        gl.glDrawTexiOES(10, 12, 0, n, n)
        region(10, 12, n, n, want, "DrawTexi one-to-one")
        t.clear()
        gl.glDrawTexxOES(20 * ONE, 4 * ONE, 0, 16 * ONE, 24 * ONE)
        region(20, 4, 16, 24, np.repeat(np.repeat(want, 3, axis=0), 2, axis=1), "DrawTexx stretched 2x3")
        t.clear()
        crop([n, 0, -n, n])
        gl.glDrawTexivOES(np.array([30, 30, 0, n, n], dtype=np.int32))
        region(30, 30, n, n, want[:, ::-1], "negative crop width")
        t.clear()
        crop([2, 3, 4, 2])
        gl.glDrawTexsOES(40, 40, 0, 4, 2)
        region(40, 40, 4, 2, want[3:5, 2:6], "sub-rectangle crop")
        t.check_gl_error("DrawTex")
        gl.glDrawTexiOES(0, 0, 0, 0, 8)
        t.check_gl_error("DrawTex width 0", gl.GL_INVALID_VALUE)
        gl.glDrawTexxOES(0, 0, 0, 8 * ONE, -ONE)
        t.check_gl_error("DrawTex height < 0", gl.GL_INVALID_VALUE)
    finally:
        gl.glDisable(gl.GL_TEXTURE_2D)
        gl.glDeleteTextures(1, [name])
