"""Mipmapping (ES 1.1 §3.7.7-3.7.8): level of detail, level selection, blending.

The renderer computes rho at each pixel as the largest of |du/dx|, |du/dy|,
|dv/dx|, |dv/dy| (the derivatives at the pixel's centre, through the
perspective weights' tangents): the lower bound of the spec's allowed range
max(mu, mv) <= f <= mu + mv.
These tests hold it to exactly that choice: lambda = log2 rho, magnification
for lambda <= c (c = 0.5 for MAG LINEAR with NEAREST_MIPMAP_*, else 0),
d = ceil(lambda + 1/2) - 1 for *_MIPMAP_NEAREST, and for *_MIPMAP_LINEAR the
blend of floor(lambda) and the next level by frac(lambda) (equations
3.19-3.21). Mesa llvmpipe is held to the spec's latitude instead: any lambda
from log2 max(mu, mv) to log2(mu + mv), widened a little for its per-quad
derivatives and coarse lambda.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest
from test_texture import (
    LINEAR,
    MIN_FILTERS,
    NEAREST,
    TARGETS,
    Quad,
    Target,
    coord_slack,
    env,
    expect_close,
    open_target,
    quad_st,
    region,
    render_quads,
    sample_range,
    tolerance,
    unorm,
)

from gles import constants as C

NMN, LMN = C.GL_NEAREST_MIPMAP_NEAREST, C.GL_LINEAR_MIPMAP_NEAREST
NML, LML = C.GL_NEAREST_MIPMAP_LINEAR, C.GL_LINEAR_MIPMAP_LINEAR
SIZE = 64                     # level 0 is 64x64: q = 6
Q = 6
LEVEL_COLORS = np.array([(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 0, 255),
                         (255, 0, 255, 0), (0, 255, 255, 255), (255, 255, 255, 128)], dtype=np.uint8)
MESA_C_SWITCH = ("Mesa deviation: llvmpipe and softpipe minify for 0 < lambda <= 0.5 with MAG LINEAR and "
                 "NEAREST_MIPMAP_LINEAR; §3.7.8 makes c = 0.5 there (magnification, level 0 only)")
LAMBDA_SLACK = {"fixed": 2e-3, "float": 1e-4, "double": 1e-6}   # log2 of the derivatives


@pytest.fixture(params=TARGETS)
def target(request: pytest.FixtureRequest) -> Iterator[Target]:
    """Each gles build, then Mesa llvmpipe (skipped where it cannot run)."""
    yield from open_target(request)


def fname(f: int) -> str:
    return C.NAMES[f].replace("GL_", "")


# {================================================================
# the model (§3.7.7 Mipmapping, §3.7.8)


def c_switch(minf: int, magf: int) -> float:
    return 0.5 if magf == LINEAR and minf in (NMN, NML) else 0.0


class MipModel:
    """The texture value of §3.7.7-3.7.8 at s, t (arrays) as a function of lambda (an
    array of the same shape, or a scalar), as per-channel bounds: with coordinate
    slack ds, dt each level's value is the range `sample_range` gives."""

    def __init__(self, levels: list[np.ndarray], s: Any, t: Any, minf: int, magf: int,
                 ds: float = 0.0, dt: float = 0.0) -> None:
        self.minf, self.magf, self.q = minf, magf, len(levels) - 1
        self.c = c_switch(minf, magf)
        s, t = np.broadcast_arrays(np.asarray(s, np.float64), np.asarray(t, np.float64))
        self.mag = np.stack(sample_range(levels[0], s, t, ds, dt, magf))
        filt = NEAREST if minf in (NEAREST, NMN, NML) else LINEAR
        n = 1 if minf in (NEAREST, LINEAR) else len(levels)
        self.per = np.stack([np.stack(sample_range(levels[d], s, t, ds, dt, filt)) for d in range(n)])

    def at(self, lam: Any) -> tuple[np.ndarray, np.ndarray]:
        lam = np.broadcast_to(np.asarray(lam, dtype=np.float64), self.mag.shape[1:-1])
        q, per = self.q, self.per
        if self.minf in (NEAREST, LINEAR):
            mino = per[0]
        elif self.minf in (NMN, LMN):
            d = np.where(lam <= 0.5, 0, np.where(lam <= q + 0.5, np.ceil(lam + 0.5) - 1, q))
            mino = np.take_along_axis(per, d.astype(np.int64)[None, None, ..., None].clip(0, q), axis=0)[0]
        else:
            d1 = np.where(lam >= q, q, np.floor(lam)).clip(0, q).astype(np.int64)
            d2 = np.minimum(d1 + 1, q)
            f = np.where(lam >= q, 0.0, lam - np.floor(lam))[..., None]
            mino = ((1 - f) * np.take_along_axis(per, d1[None, None, ..., None], axis=0)[0]
                    + f * np.take_along_axis(per, d2[None, None, ..., None], axis=0)[0])
        out = np.where((lam <= self.c)[..., None], self.mag, mino)
        return out[0], out[1]

    def range(self, lam_lo: Any, lam_hi: Any) -> tuple[np.ndarray, np.ndarray]:
        """Per-channel min and max over lambda in [lam_lo, lam_hi]: the formulas are
        piecewise linear in lambda, so the ends and the breakpoints suffice."""
        shape = self.mag.shape[1:-1]
        lam_lo = np.broadcast_to(np.asarray(lam_lo, np.float64), shape)
        lam_hi = np.broadcast_to(np.asarray(lam_hi, np.float64), shape)
        lo, hi = self.at(lam_lo)
        points = [lam_hi]
        for k in range(-1, self.q + 2):
            for b in (k, k + 0.5):
                points += [np.clip(b - 1e-9, lam_lo, lam_hi), np.clip(b + 1e-9, lam_lo, lam_hi)]
        for p in points:
            a, b = self.at(p)
            lo, hi = np.minimum(lo, a), np.maximum(hi, b)
        return lo, hi


def mip_sample(levels: list[np.ndarray], s: Any, t: Any, lam: float, minf: int, magf: int) -> np.ndarray:
    """The texture value of §3.7.7-3.7.8 for one lambda."""
    return MipModel(levels, s, t, minf, magf).at(lam)[0]


def mip_range(levels: list[np.ndarray], s: Any, t: Any, lam_lo: Any, lam_hi: Any, minf: int,
              magf: int, ds: float = 0.0, dt: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Per-channel min and max of the texture value for lambda in [lam_lo, lam_hi]
    and coordinates within ds, dt."""
    return MipModel(levels, s, t, minf, magf, ds, dt).range(lam_lo, lam_hi)


def level_texture(gl: Any, levels_u8: list[np.ndarray], minf: int, magf: int) -> None:
    """Bind a new complete mipmapped RGBA texture, REPLACE, on unit 0."""
    gl.glBindTexture(C.GL_TEXTURE_2D, int(gl.glGenTextures(1)))
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    for d, img in enumerate(levels_u8):
        h, w = img.shape[:2]
        gl.glTexImage2D(C.GL_TEXTURE_2D, d, C.GL_RGBA, w, h, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, minf)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, magf)
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)


def one_colour_levels() -> list[np.ndarray]:
    return [np.broadcast_to(LEVEL_COLORS[d], (SIZE >> d, SIZE >> d, 4)).copy() for d in range(Q + 1)]


def random_levels(seed: int) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    return [rng.integers(0, 256, size=(SIZE >> d, SIZE >> d, 4), dtype=np.uint8) for d in range(Q + 1)]


def q16(v: float) -> float:
    """The nearest value every build holds exactly (16.16 and float)."""
    return round(v * 65536) / 65536


def scale_quad(x: int, y: int, px: int, rho_x: float, rho_y: float, s0: float = 0.0, t0: float = 0.0,
               ) -> tuple[Quad, float, float]:
    """A px-by-px screen-aligned quad whose texture coordinates advance rho_x texels
    of level 0 per pixel in x and rho_y in y; returns it with the exact rates sent."""
    s1 = q16(s0 + rho_x * px / SIZE)
    t1 = q16(t0 + rho_y * px / SIZE)
    return (Quad(x, y, x + px, y + px, (((s0, t0), (s1, t1)),)),
            (s1 - s0) * SIZE / px, (t1 - t0) * SIZE / px)


def lambda_bounds(kind: str, rx: float, ry: float) -> tuple[float, float]:
    """The lambda interval a target may use for a screen-aligned mapping with rates rx, ry."""
    mu, mv = abs(rx), abs(ry)
    if kind == "llvmpipe":
        return np.log2(max(mu, mv)) - 1.0 / 16, np.log2(mu + mv) + 1.0 / 16
    lam = np.log2(max(mu, mv))
    return lam - LAMBDA_SLACK[kind], lam + LAMBDA_SLACK[kind]


# lambdas away from the formulas' breakpoints (0, 0.5, integers, k + 0.5), and rates
LAMBDAS = (-1.3, 0.1, 0.3, 0.45, 0.55, 0.7, 0.95, 1.05, 1.2, 1.45, 1.55, 1.8, 2.25, 2.6, 2.95, 3.4,
           3.62, 4.1, 4.49, 4.51, 5.3, 5.7, 5.95, 6.2, 6.6, 7.4, 8.3)


def lambda_quads(aniso: bool) -> list[tuple[Quad, float, float]]:
    """8x8 quads on a 64x64 window, one lambda each; anisotropic ones scale y by 1/8
    (or x, alternately), so max(mu, mv) and mu + mv are close."""
    out = []
    for k, lam in enumerate(LAMBDAS):
        rho = 2.0**lam
        rx, ry = (rho, rho) if not aniso else ((rho, rho / 8) if k % 2 else (rho / 8, -rho))
        out.append(scale_quad(8 * (k % 8), 8 * (k // 8), 8, rx, ry, 0.1875, 0.3125))
    return out


@pytest.mark.parametrize("magf", [NEAREST, LINEAR], ids=fname)
@pytest.mark.parametrize("minf", MIN_FILTERS, ids=fname)
def test_level_selection_one_colour_per_level(target: Target, minf: int, magf: int,
                                              request: pytest.FixtureRequest):
    """One colour per level: for every lambda the pixel has the level (or the blend of
    two levels) of equations 3.19-3.21 with the c switch of §3.7.8."""
    if target.kind == "llvmpipe" and c_switch(minf, magf) == 0.5 and minf == NML:
        request.applymarker(pytest.mark.xfail(strict=True, reason=MESA_C_SWITCH))
    levels_u8 = one_colour_levels()
    levels = [unorm(v) for v in levels_u8]
    for aniso in (False, True):
        quads = lambda_quads(aniso)
        img = render_quads(target, [q for q, _, _ in quads],
                           lambda gl: level_texture(gl, levels_u8, minf, magf))
        check_quads(img, quads, levels, target.kind, minf, magf, f"{'an' if aniso else ''}isotropic")


def check_quads(img: np.ndarray, quads: list[tuple[Quad, float, float]], levels: list[np.ndarray], kind: str,
                minf: int, magf: int, what: str) -> None:
    """Every quad's pixels against the model for its rates (all quads in one evaluation)."""
    s, t, lam_lo, lam_hi, got = [], [], [], [], []
    for q, rx, ry in quads:
        qs, qt = quad_st(q)
        lo_l, hi_l = lambda_bounds(kind, rx, ry)
        s.append(qs.ravel())
        t.append(qt.ravel())
        lam_lo.append(np.full(qs.size, lo_l))
        lam_hi.append(np.full(qs.size, hi_l))
        got.append(region(img, q).reshape(-1, 4))
    lo, hi = mip_range(levels, np.concatenate(s), np.concatenate(t), np.concatenate(lam_lo),
                       np.concatenate(lam_hi), minf, magf)
    got_all = np.concatenate(got)
    at = 0
    for q, rx, ry in quads:
        n = int((q.x1 - q.x0) * (q.y1 - q.y0))
        sl = slice(at, at + n)
        at += n
        expect_close(got_all[sl], lo[sl], tolerance(kind),
                     f"{what} lambda {np.log2(max(abs(rx), abs(ry))):.3f}", lo[sl], hi[sl])


def test_c_switch(numeric: str):
    """0 < lambda <= 0.5: NEAREST_MIPMAP_LINEAR with MAG LINEAR magnifies (level 0 only),
    with MAG NEAREST it blends levels 0 and 1 by lambda; LINEAR_MIPMAP_LINEAR blends with
    either MAG filter (c = 0); at lambda 0.6 every mipmapped filter minifies (§3.7.8)."""
    t = Target(numeric)
    levels_u8 = one_colour_levels()
    c0, c1 = unorm(LEVEL_COLORS[0]), unorm(LEVEL_COLORS[1])
    for lam in (0.2, 0.4, 0.6):
        q, rx, ry = scale_quad(0, 0, 16, 2.0**lam, 2.0**lam)
        f = np.log2(rx)
        for minf, magf, magnified in ((NML, LINEAR, lam <= 0.5), (NML, NEAREST, False),
                                      (LML, LINEAR, False), (LML, NEAREST, False)):
            setup = lambda gl, a=minf, b=magf: level_texture(gl, levels_u8, a, b)  # noqa: E731
            img = region(render_quads(t, [q], setup), q)
            want = c0 if magnified else (1 - f) * c0 + f * c1
            expect_close(img, np.broadcast_to(want, img.shape), tolerance(numeric),
                         f"lambda {lam} {fname(minf)} MAG {fname(magf)}")


def test_c_switch_changes_the_filter(numeric: str):
    """A checkerboard level 0 at lambda 0.3: NEAREST_MIPMAP_NEAREST with MAG LINEAR is
    magnification (bilinear blends of the checker); with MAG NEAREST it is minification
    of level 0 with NEAREST (pure checker colours)."""
    t = Target(numeric)
    levels_u8 = one_colour_levels()
    chk = (np.indices((SIZE, SIZE)).sum(axis=0) % 2).astype(bool)
    levels_u8[0] = np.where(chk[..., None], np.uint8(255), np.uint8(0)).repeat(4, axis=-1).astype(np.uint8)
    levels = [unorm(v) for v in levels_u8]
    q, rx, ry = scale_quad(0, 0, 32, 2.0**0.3, 2.0**0.3, 0.0078125, 0.01171875)
    s, tt = quad_st(q)
    for magf in (LINEAR, NEAREST):
        img = region(render_quads(t, [q], lambda gl, m=magf: level_texture(gl, levels_u8, NMN, m)), q)
        want = mip_sample(levels, s, tt, np.log2(rx), NMN, magf)
        expect_close(img, want, tolerance(numeric), f"checker, MAG {fname(magf)}")
        mid = ((img > 0.05) & (img < 0.95)).any(axis=-1).mean()
        assert (mid > 0.5) if magf == LINEAR else (mid == 0)


def test_mipmap_linear_blend_factor(numeric: str):
    """*_MIPMAP_LINEAR with white and black alternating levels: the pixel value is the
    blend factor frac(lambda), within one 8-bit step, over a sweep of 64 lambdas."""
    t = Target(numeric)
    levels_u8 = [np.full((SIZE >> d, SIZE >> d, 4), 255 * (1 - d % 2), np.uint8) for d in range(Q + 1)]
    quads = []
    for k in range(64):
        lam = 0.03 + k * 5.9 / 64
        quads.append(scale_quad(8 * (k % 8), 8 * (k // 8), 8, 2.0**lam, 2.0**lam / 3))
    img = render_quads(t, [q for q, _, _ in quads], lambda gl: level_texture(gl, levels_u8, LML, LINEAR))
    worst = 0.0
    for q, rx, _ in quads:
        lam = np.log2(rx)
        f = lam - np.floor(lam)
        want = 1 - f if int(np.floor(lam)) % 2 == 0 else f
        worst = max(worst, float(np.abs(region(img, q)[..., 0] - want).max()))
    assert worst <= tolerance(numeric), f"blend factor off by {worst * 255:.2f}/255"


def test_rho_is_the_largest_derivative(numeric: str):
    """Texture coordinates rotated 45 degrees against the window: |du/dx| = |du/dy| =
    rho/sqrt(2), so the renderer's f = rho/sqrt(2) (lambda = log2 rho - 1/2), not
    equation 3.14's rho; both lie in the spec's bounds [mu, mu + mv] (here
    [rho/sqrt(2), rho sqrt(2)])."""
    t = Target(numeric)
    levels_u8 = one_colour_levels()
    levels = [unorm(v) for v in levels_u8]
    rho = 2.0**2.8                 # eq. 3.14 lambda 2.8; the renderer's 2.3
    k = rho * 16 / SIZE / np.sqrt(2)
    # corners in strip order: s = k (x + y) / 16, t = k (y - x) / 16 over a 16x16 quad
    strq = np.array([[0, 0, 0, 1], [k, -k, 0, 1], [k, k, 0, 1], [2 * k, 0, 0, 1]], dtype=np.float64)
    for minf in (NMN, LML):
        img = region(render_quads(t, [Quad(0, 0, 16, 16, (strq,))],
                                  lambda gl, m=minf: level_texture(gl, levels_u8, m, LINEAR)),
                     Quad(0, 0, 16, 16, ()))
        want = mip_sample(levels, 0.0, 0.0, 2.3, minf, LINEAR)
        expect_close(img, np.broadcast_to(want, img.shape), tolerance(numeric), f"rotated, {fname(minf)}")
        other = mip_sample(levels, 0.0, 0.0, 2.8, minf, LINEAR)
        assert np.abs(other - want).max() > 0.1     # the two choices are distinguishable


@pytest.mark.parametrize("minf", MIN_FILTERS, ids=fname)
def test_all_filters_random_levels(numeric: str, minf: int):
    """Random texels on every level, fractional lambdas and texel offsets, both MAG
    filters: texel selection, bilinear weights and the level blend together."""
    t = Target(numeric)
    levels_u8 = random_levels(minf)
    levels = [unorm(v) for v in levels_u8]
    quads = [scale_quad(16 * (k % 4), 16 * (k // 4), 16, 2.0**lam, 2.0**lam * (0.5 if k % 3 else 1.0),
                        0.0859375 * k, 0.1171875 * k)
             for k, lam in enumerate((-0.6, 0.2, 0.4, 0.7, 1.3, 1.6, 2.2, 2.45, 2.7, 3.3, 3.9, 4.6, 5.2,
                                      5.8, 6.4, 7.1))]
    for magf in (NEAREST, LINEAR):
        img = render_quads(t, [q for q, _, _ in quads],
                           lambda gl, m=magf: level_texture(gl, levels_u8, minf, m))
        check_quads(img, quads, levels, numeric, minf, magf, f"MAG {fname(magf)}")


# {================================================================
# a perspective ground plane: lambda per pixel


def ground_plane(gl: Any) -> None:
    """glFrustum(-1, 1, -1, 1, 1, 64) over 64x64; the plane y = -1 from z = -1 to
    z = -32, x spanning the view, s = x / 2, t = -z / 2: a 64x31 rectangle on screen."""
    gl.glViewport(0, 0, 64, 64)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumx(-65536, 65536, -65536, 65536, 65536, 64 * 65536)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    v = np.array([-1, -1, -1, 1, -1, -1, -32, -1, -32, 32, -1, -32], dtype=np.float32)
    tc = np.array([-0.5, 0.5, 0.5, 0.5, -16, 16, 16, 16], dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


def plane_st(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """s, t of `ground_plane` at window points: with w = -z, y_w = 32 - 32 / w, so
    1/w = (32 - y) / 32 and x_e = (x_w - 32) w / 32."""
    w = 32.0 / (32.0 - y)
    return (x - 32.0) * w / 32.0 / 2.0, w / 2.0


def plane_derivatives(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """ds/dx, ds/dy and dt/dy of `ground_plane` at window points (dt/dx is 0):
    s = (x - 32) w / 64, t = w / 2 with w = 32 / (32 - y), dw/dy = w^2 / 32."""
    w = 32.0 / (32.0 - y)
    dwdy = w * w / 32.0
    return w / 64.0, (x - 32.0) / 64.0 * dwdy, dwdy / 2.0


def plane_rho(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The renderer's rho for `ground_plane` at window points: the largest of the
    derivatives at the point, in texels of level 0 (max(mu, mv), the spec's lower bound)."""
    return SIZE * np.max(np.abs(plane_derivatives(x, y)), axis=0)


def plane_lambda_bounds(px: np.ndarray, py: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The spec's lambda bounds [log2 max(mu, mv), log2(mu + mv)] for `ground_plane`
    from derivatives taken anywhere within a pixel of (px, py): a difference over a
    2x2 quad is the derivative somewhere in it (mean value theorem)."""
    lo = np.full(px.shape, np.inf)
    hi = np.full(px.shape, -np.inf)
    for ox in np.linspace(-1, 1, 5):
        for oy in np.linspace(-1, 1, 5):
            dsdx, dsdy, dtdy = plane_derivatives(px + ox, py + oy)
            mu = np.maximum(np.abs(dsdx), np.abs(dsdy)) * SIZE
            mv = np.abs(dtdy) * SIZE
            lo = np.minimum(lo, np.log2(np.maximum(mu, mv)))
            hi = np.maximum(hi, np.log2(mu + mv))
    return lo, hi


def test_perspective_ground_plane(target: Target):
    """Trilinear and nearest-mipmap filtering of a ground plane in perspective: lambda
    varies per pixel as log2 of the largest derivative at the pixel's centre
    (llvmpipe: within the spec's bounds for derivatives taken within a pixel,
    plus 1/16)."""
    levels_u8 = one_colour_levels() if target.kind == "llvmpipe" else random_levels(77)
    levels = [unorm(v) for v in levels_u8]
    rows = np.arange(2, 29)             # away from the plane's top and bottom edges
    px, py = np.meshgrid(np.arange(64) + 0.5, rows + 0.5)
    s, t = plane_st(px, py)
    if target.kind == "llvmpipe":
        lo_l, hi_l = plane_lambda_bounds(px, py)
        lo_l, hi_l = lo_l - 1.0 / 16, hi_l + 1.0 / 16
    else:
        lam = np.log2(plane_rho(px, py))
        lo_l, hi_l = lam - LAMBDA_SLACK[target.kind], lam + LAMBDA_SLACK[target.kind]
    d = coord_slack(target.kind, 16.0)
    for minf in (LML, NMN):
        img = render_quads(target, [], lambda gl, m=minf: (level_texture(gl, levels_u8, m, LINEAR),
                                                           ground_plane(gl)))
        lo, hi = mip_range(levels, s, t, lo_l, hi_l, minf, LINEAR, d, d)
        expect_close(img[rows], lo, tolerance(target.kind), f"ground plane {fname(minf)}", lo, hi)
