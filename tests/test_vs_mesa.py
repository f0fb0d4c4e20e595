"""Triangle coverage against Mesa llvmpipe, pixel for pixel.

llvmpipe snaps window coordinates to 8 subpixel bits, as gles does, and
uses the same tie rule: a pixel centre exactly on an edge belongs to the
triangle when the edge is a left edge or a bottom edge (GL window
coordinates, y up). With a power-of-two viewport, an orthographic projection
and vertices on the 1/256 grid, both compute the snapped positions exactly,
so the covered pixel sets must be identical, except where clipping makes
new vertices (each with its own arithmetic). A perspective case bounds the
differences that rounding in the projection may cause.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import gles
from gles import constants as C
from gles.mesa import MesaContext, available

_REASON = available("llvmpipe")
pytestmark = pytest.mark.skipif(_REASON is not None, reason=f"Mesa llvmpipe unavailable: {_REASON}")

W = H = 64
SUB = 256                       # subpixels per pixel
BUILDS = ("fixed", "float", "double")
PER_KIND = 1000                 # triangles of each kind in each group

# Viewport and orthographic bounds. "wide" puts the window inside a larger
# viewport, so triangles reach past the window without being clipped.
SETUPS = {
    "window": ((0, 0, W, H), (0.0, float(W), 0.0, float(H))),
    "wide": ((-64, -64, 256, 256), (-64.0, 192.0, -64.0, 192.0)),
}
# group: (setup, range of vertex coordinates in pixels, whether every vertex
# stays inside the viewport)
GROUPS = {
    "inside": ("window", (0, W), True),
    "beyond-window": ("wide", (-40, W + 40), True),
    "clipped": ("window", (-40, W + 40), False),
}


# {================================================================
# drawing

class Coverage:
    """Draws one flat-coloured triangle per frame and reads back its pixels."""

    def __init__(self, gl: Any) -> None:
        self.gl = gl
        gl.glDisable(C.GL_DEPTH_TEST)
        gl.glDisable(C.GL_CULL_FACE)
        gl.glDisable(C.GL_DITHER)
        gl.glShadeModel(C.GL_FLAT)
        gl.glClearColorx(0, 0, 0, 0)
        gl.glColor4x(65536, 65536, 65536, 65536)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glDisableClientState(C.GL_COLOR_ARRAY)

    def ortho(self, setup: str) -> None:
        gl = self.gl
        (vx, vy, vw, vh), bounds = SETUPS[setup]
        gl.glViewport(vx, vy, vw, vh)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glOrthof(*bounds, -1.0, 1.0)
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glLoadIdentity()

    def frustum(self) -> None:
        gl = self.gl
        gl.glViewport(0, 0, W, H)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glFrustumf(*FRUSTUM)
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glLoadIdentity()
        gl.glTranslatef(*TRANSLATE)
        gl.glRotatef(*ROTATE)

    def __call__(self, tris: np.ndarray) -> np.ndarray:
        """Coverage (n, H, W) of each triangle of float32 (n, 3, 2|3), bottom row first."""
        gl = self.gl
        out = np.empty((len(tris), H, W), dtype=bool)
        for i, tri in enumerate(tris):
            v = np.ascontiguousarray(tri, dtype=np.float32)
            gl.glClear(C.GL_COLOR_BUFFER_BIT)
            gl.glVertexPointer(v.shape[1], C.GL_FLOAT, 0, v)
            gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
            px = gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
            out[i] = px[..., 0] != 0
        return out


@pytest.fixture(scope="module")
def llvmpipe():
    # With a depth buffer llvmpipe clips triangles against the x and y planes
    # of the view volume as gles does (measured: its clipped coverage then
    # equals gles float's). Without one it rasterizes these triangles
    # unclipped, so the depth buffer keeps the comparison like for like.
    with MesaContext(W, H, driver="llvmpipe", depth=24, stencil=8) as ctx:
        yield ctx


_MESA_CACHE: dict[str, np.ndarray] = {}


def mesa_coverage(ctx: MesaContext, key: str, draw: Any) -> np.ndarray:
    """llvmpipe's coverage for a case set, computed once per module run."""
    if key not in _MESA_CACHE:
        ctx.make_current()
        _MESA_CACHE[key] = draw(Coverage(ctx.gl))
    return _MESA_CACHE[key]


def gles_coverage(numeric: str, draw: Any) -> np.ndarray:
    ctx = gles.Context(W, H, numeric=numeric, depth=24, stencil=8)
    return draw(Coverage(ctx.gl))


# {================================================================
# cases (vertex coordinates in subpixels, int64)

def random_points(rng: np.random.Generator, shape: tuple, lo: int, hi: int) -> np.ndarray:
    return rng.integers(lo * SUB, hi * SUB + 1, size=shape + (2,))


def ortho_cases(group: str) -> tuple[np.ndarray, list[str]]:
    """Triangles of five kinds, both windings: (n, 3, 2) subpixels and each one's kind."""
    setup, (lo, hi), contained = GROUPS[group]
    rng = np.random.default_rng(list(GROUPS).index(group) + 1)
    n = PER_KIND
    kinds: dict[str, np.ndarray] = {}
    # anywhere
    kinds["random"] = random_points(rng, (n, 3), lo, hi)
    # every vertex on a pixel centre
    kinds["centres"] = rng.integers(lo, hi, size=(n, 3, 2)) * SUB + SUB // 2
    # an edge through pixel centres: from centre A along an integer step d, its
    # ends moved along the edge by m/256 of d (still on the grid, off centre
    # for half of them); a third of the steps are axis-aligned
    a = rng.integers(lo, hi, size=(n, 2)) * SUB + SUB // 2
    d = rng.integers(-6, 7, size=(n, 2))
    axis = rng.integers(0, 3, size=n)
    d[axis == 1, 1] = 0
    d[axis == 2, 0] = 0
    d[(d == 0).all(axis=1)] = (1, 0)
    k = rng.integers(1, 9, size=(n, 1))
    m = rng.integers(-SUB // 2, SUB // 2, size=(n, 2)) * (rng.random((n, 2)) < 0.5)
    p0 = a - m[:, :1] * d
    p1 = a + k * d * SUB + m[:, 1:] * d
    kinds["through-centres"] = np.stack([p0, p1, random_points(rng, (n,), lo, hi)], axis=1)
    # slivers: the third vertex within a few subpixels of the other two's line
    p0, p1 = random_points(rng, (n,), lo, hi), random_points(rng, (n,), lo, hi)
    u = rng.random((n, 1))
    p2 = np.rint(p0 + u * (p1 - p0)).astype(np.int64) + rng.integers(-3, 4, size=(n, 2))
    kinds["sliver"] = np.stack([p0, p1, p2], axis=1)
    # small: within three pixels of a random point
    base = random_points(rng, (n, 1), lo, hi)
    kinds["small"] = base + rng.integers(-3 * SUB, 3 * SUB + 1, size=(n, 3, 2))
    tris = np.concatenate(list(kinds.values()))
    names = [name for name, t in kinds.items() for _ in range(len(t))]
    flip = rng.random(len(tris)) < 0.5          # the other winding for half
    tris[flip] = tris[flip][:, ::-1]
    if contained:
        (vx, vy, vw, vh), _ = SETUPS[setup]
        keep = ((tris[..., 0] >= vx * SUB) & (tris[..., 0] <= (vx + vw) * SUB)
                & (tris[..., 1] >= vy * SUB) & (tris[..., 1] <= (vy + vh) * SUB)).all(axis=1)
        tris, names = tris[keep], [name for name, k in zip(names, keep) if k]
    return tris, names


def exact_coverage(tri_sub: np.ndarray, setup: str) -> np.ndarray:
    """The fill rule evaluated exactly on the window (object units = window pixels)."""
    p = tri_sub.astype(np.int64)
    area = (p[1, 0] - p[0, 0]) * (p[2, 1] - p[0, 1]) - (p[2, 0] - p[0, 0]) * (p[1, 1] - p[0, 1])
    if area == 0:
        return np.zeros((H, W), dtype=bool)
    if area < 0:
        p = p[[0, 2, 1]]
    ys, xs = np.mgrid[0:H, 0:W] * SUB + SUB // 2
    inside = np.ones((H, W), dtype=bool)
    for i in range(3):
        (ax, ay), (bx, by) = p[i], p[(i + 1) % 3]
        e = (bx - ax) * (ys - ay) - (by - ay) * (xs - ax)
        tie = by < ay or (by == ay and bx > ax)
        inside &= (e > 0) | ((e == 0) & tie)
    (vx, vy, vw, vh), _ = SETUPS[setup]
    x0, y0 = max(vx, 0), max(vy, 0)
    view = np.zeros((H, W), dtype=bool)
    view[y0:vy + vh, x0:vx + vw] = True
    return inside & view


def segment_distance(px: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance of points (k, 2) to the segment a-b."""
    ab = b - a
    t = np.clip(((px - a) @ ab) / max(float(ab @ ab), 1e-300), 0.0, 1.0)
    return np.hypot(*(px - a - t[:, None] * ab).T)


def centres(yx: np.ndarray) -> np.ndarray:
    """Window coordinates (k, 2) of the centres of pixels given as (row, column)."""
    return yx[:, ::-1].astype(np.float64) + 0.5


# {================================================================
# orthographic: exact agreement

@pytest.mark.parametrize("group", list(GROUPS))
@pytest.mark.parametrize("numeric", BUILDS)
def test_ortho_coverage_matches_llvmpipe(llvmpipe: MesaContext, numeric: str, group: str) -> None:
    setup, _, contained = GROUPS[group]
    tris_sub, kinds = ortho_cases(group)
    tris = tris_sub / SUB

    def draw(cov: Coverage) -> np.ndarray:
        cov.ortho(setup)
        return cov(tris)

    ref = mesa_coverage(llvmpipe, f"ortho-{group}", draw)
    got = gles_coverage(numeric, draw)
    diff = got != ref
    bad = np.flatnonzero(diff.any(axis=(1, 2)))
    print(f"\n{group} {numeric}: {len(tris)} triangles, {ref.sum()} llvmpipe pixels, "
          f"{len(bad)} triangles / {diff.sum()} pixels differ")

    if contained:
        details = []
        for i in bad[:5]:
            exact = exact_coverage(tris_sub[i], setup)
            yx = np.argwhere(diff[i])[:4]
            at = tuple(yx.T)
            details.append(f"{kinds[i]} {tris[i].tolist()}: pixels (x, y) "
                           f"{[(int(x), int(y)) for y, x in yx]} gles {got[i][at].tolist()} "
                           f"llvmpipe {ref[i][at].tolist()} exact rule {exact[at].tolist()}")
        assert len(bad) == 0, "coverage differs from llvmpipe:\n" + "\n".join(details)
        return

    # Clipped triangles. Both clip against the view volume and snap the new
    # vertices, each with its own arithmetic (gles fixed: 16.16 clip
    # coordinates and a 0.30 parameter; llvmpipe: float). A new vertex can
    # land on the other side of a subpixel rounding boundary, moving a clipped
    # edge by less than 1/256 px; a pixel centre that close to the edge may
    # then flip. That is the only difference allowed here: every differing
    # pixel's centre is within 1/256 px of an edge that crosses the viewport
    # boundary. Edges with both ends inside are never moved by clipping.
    unexplained = []
    for i in bad:
        tri = tris[i].astype(np.float64)
        outside = ((tri < 0) | (tri > W)).any(axis=1)
        px = centres(np.argwhere(diff[i]))
        near = np.zeros(len(px), dtype=bool)
        for j in range(3):
            if outside[j] or outside[(j + 1) % 3]:
                near |= segment_distance(px, tri[j], tri[(j + 1) % 3]) <= 1 / SUB
        if not near.all():
            unexplained.append(f"{kinds[i]} {tris[i].tolist()}: pixel centres {px[~near][:4].tolist()}")
    assert not unexplained, "clipped coverage differs beyond clip rounding:\n" + "\n".join(unexplained[:5])


@pytest.mark.parametrize("numeric", BUILDS)
def test_horizontal_top_edge_through_pixel_centres(llvmpipe: MesaContext, numeric: str) -> None:
    """The smallest case of the tie rule on a horizontal edge: centres on a
    top edge are outside, on a bottom edge inside (either winding)."""
    tris = np.array([[[1.5, 1.5], [4.5, 4.5], [1.5, 4.5]],      # top edge y = 4.5
                     [[1.5, 4.5], [4.5, 4.5], [1.5, 1.5]],      # the same, clockwise
                     [[1.5, 1.5], [4.5, 1.5], [1.5, 4.5]],      # bottom edge y = 1.5
                     [[1.5, 4.5], [4.5, 1.5], [1.5, 1.5]]])     # the same, clockwise

    def draw(cov: Coverage) -> np.ndarray:
        cov.ortho("window")
        return cov(tris)

    ref = mesa_coverage(llvmpipe, "top-edge", draw)
    got = gles_coverage(numeric, draw)
    for tri, r, g in zip(tris, ref, got):
        assert np.array_equal(r, exact_coverage(np.rint(tri * SUB).astype(np.int64), "window"))
        rows = {y: [int(x) for x in np.flatnonzero(g[y])] for y in range(1, 5)}
        expected = {y: [int(x) for x in np.flatnonzero(r[y])] for y in range(1, 5)}
        assert rows == expected, f"{tri.tolist()}: covered columns per row {rows}, llvmpipe {expected}"


def test_exact_reference_agrees_with_llvmpipe(llvmpipe: MesaContext) -> None:
    """The exact fill rule used in the messages above is llvmpipe's."""
    tris_sub, _ = ortho_cases("inside")
    tris_sub = tris_sub[::10]

    def draw(cov: Coverage) -> np.ndarray:
        cov.ortho("window")
        return cov(tris_sub / SUB)

    llvmpipe.make_current()
    ref = draw(Coverage(llvmpipe.gl))
    for tri, cov in zip(tris_sub, ref):
        assert np.array_equal(cov, exact_coverage(tri, "window")), (tri / SUB).tolist()


# {================================================================
# perspective: rounding differences only, next to edges

FRUSTUM = (-0.6, 0.6, -0.6, 0.6, 1.0, 8.0)
TRANSLATE = (0.0, 0.0, -3.5)
ROTATE = (37.0, 0.3, 1.0, 0.2)
N_PERSPECTIVE = 3000


def perspective_cases() -> np.ndarray:
    """Object-space triangles (n, 3, 3) on the 2^-16 grid (exact in 16.16 and float)."""
    rng = np.random.default_rng(99)
    n = N_PERSPECTIVE
    big = rng.uniform(-1.2, 1.2, size=(n // 2, 3, 3))
    centre = rng.uniform(-1.0, 1.0, size=(n - n // 2, 1, 3))
    small = centre + rng.uniform(-0.15, 0.15, size=(n - n // 2, 3, 3))
    return np.rint(np.concatenate([big, small]) * 65536) / 65536


def rotation(angle: float, x: float, y: float, z: float) -> np.ndarray:
    c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
    x, y, z = np.array([x, y, z]) / np.linalg.norm([x, y, z])
    r = np.eye(4)
    r[:3, :3] = [[x * x * (1 - c) + c, x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                 [y * x * (1 - c) + z * s, y * y * (1 - c) + c, y * z * (1 - c) - x * s],
                 [x * z * (1 - c) - y * s, y * z * (1 - c) + x * s, z * z * (1 - c) + c]]
    return r


def window_coordinates(obj: np.ndarray) -> np.ndarray:
    """Float64 window x, y (..., 2) of object points (..., 3) under the perspective setup."""
    left, right, bottom, top, near, far = FRUSTUM
    proj = np.array([[2 * near / (right - left), 0, (right + left) / (right - left), 0],
                     [0, 2 * near / (top - bottom), (top + bottom) / (top - bottom), 0],
                     [0, 0, -(far + near) / (far - near), -2 * far * near / (far - near)],
                     [0, 0, -1, 0]])
    model = np.eye(4)
    model[:3, 3] = TRANSLATE
    model = model @ rotation(*ROTATE)
    clip = np.concatenate([obj, np.ones(obj.shape[:-1] + (1,))], axis=-1) @ (proj @ model).T
    ndc = clip[..., :2] / clip[..., 3:]
    return (ndc + 1) * np.array([W / 2, H / 2])


@pytest.mark.parametrize("numeric", BUILDS)
def test_perspective_coverage_near_llvmpipe(llvmpipe: MesaContext, numeric: str) -> None:
    """Differences come from rounding before the snap: a projected (or
    clip-generated) vertex whose exact window position is near a subpixel
    rounding boundary can snap to either side, moving its edges by less than
    1/256 px. So every differing pixel's centre must be within 1/256 px of an
    edge of the exact (float64) projected triangle, and such pixels are rare."""
    obj = perspective_cases()

    def draw(cov: Coverage) -> np.ndarray:
        cov.frustum()
        return cov(obj)

    ref = mesa_coverage(llvmpipe, "perspective", draw)
    got = gles_coverage(numeric, draw)
    win = window_coordinates(obj)
    diff = got != ref
    bad = np.flatnonzero(diff.any(axis=(1, 2)))
    pixels = int(ref.sum())
    far = []
    for i in bad:
        px = centres(np.argwhere(diff[i]))
        dist = np.min([segment_distance(px, win[i, j], win[i, (j + 1) % 3]) for j in range(3)], axis=0)
        if (dist > 1 / SUB).any():
            far.append(f"{obj[i].tolist()}: pixel centres {px[dist > 1 / SUB][:4].tolist()} "
                       f"at {dist[dist > 1 / SUB][:4].tolist()} px from an edge")
    rate = diff.sum() / max(pixels, 1)
    print(f"\nperspective {numeric}: {len(obj)} triangles, {pixels} llvmpipe pixels, "
          f"{len(bad)} triangles / {diff.sum()} pixels differ (rate {rate:.2e})")
    assert pixels > 20 * len(obj), "the perspective scene covers too little to say anything"
    assert not far, "differences away from edges:\n" + "\n".join(far[:5])
    assert rate < 1e-3
