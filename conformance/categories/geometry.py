"""Geometry: clipping, user clip planes, culling and triangle rasterization.

Categories Clip, UserClip, PolyCull, TriRaster, TriTile, VertexOrder, DivZero
and ViewportClamp (spec sections 2.6, 2.10.1, 2.11, 2.12.6 and 3.5.1).

Expected pictures come from the spec's formulas evaluated here in float64:
the vertex pipeline of section 2.10 (object -> eye -> clip -> window), the
clipping of section 2.11 done with Sutherland-Hodgman on homogeneous
coordinates, and the point-sampling rule of section 3.5.1 (a fragment is
produced when its pixel centre lies inside the polygon). A pixel whose centre
lies exactly on an edge may go either way, except where the spec's
shared-edge rule decides it. When window positions are not exact (rotations,
perspective, clipped vertices), pixels whose centres lie within a small
margin of an edge may also go either way; the margin covers rounding and the
minimum of 4 subpixel bits (Table 6.21), nothing more.

The helpers at the top are shared with ``xform``.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

from ..harness import TestContext, conformance_test

ONE = 1 << 16

# Margin (pixels) for window positions that the GL computes inexactly:
# half a 1/16 subpixel step of snapping plus generous room for rounding.
MARGIN = 1.0 / 8.0

WHITE = (255, 255, 255, 255)
RED = (255, 0, 0, 255)
GREEN = (0, 255, 0, 255)
BLUE = (0, 0, 255, 255)
BLACK = (0, 0, 0, 0)

# {============================================================
# numbers and matrices (section 2.10.2)


def fx(v: float) -> int:
    """A real as the 16.16 integer an x command takes (round to nearest)."""
    return int(np.floor(v * ONE + 0.5))


def unfx(i: int) -> float:
    return i / ONE


def q16(v: Any) -> Any:
    """Round reals to what a 16.16 argument can hold (the value the GL receives)."""
    return np.floor(np.asarray(v, dtype=np.float64) * ONE + 0.5) / ONE


def translate(x: float, y: float, z: float) -> np.ndarray:
    m = np.eye(4)
    m[:3, 3] = (x, y, z)
    return m


def scale(x: float, y: float, z: float) -> np.ndarray:
    return np.diag([x, y, z, 1.0])


def rotate(angle: float, x: float, y: float, z: float) -> np.ndarray:
    """R = uu^T + cos(a)(I - uu^T) + sin(a)S with u = v/|v| (section 2.10.2)."""
    u = np.array([x, y, z], dtype=np.float64)
    u = u / np.linalg.norm(u)
    uu = np.outer(u, u)
    s = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    a = np.radians(angle)
    m = np.eye(4)
    m[:3, :3] = uu + np.cos(a) * (np.eye(3) - uu) + np.sin(a) * s
    return m


def frustum(lf: float, r: float, b: float, t: float, n: float, f: float) -> np.ndarray:
    return np.array([
        [2 * n / (r - lf), 0, (r + lf) / (r - lf), 0],
        [0, 2 * n / (t - b), (t + b) / (t - b), 0],
        [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)],
        [0, 0, -1, 0],
    ])


def ortho(lf: float, r: float, b: float, t: float, n: float, f: float) -> np.ndarray:
    return np.array([
        [2 / (r - lf), 0, 0, -(r + lf) / (r - lf)],
        [0, 2 / (t - b), 0, -(t + b) / (t - b)],
        [0, 0, -2 / (f - n), -(f + n) / (f - n)],
        [0, 0, 0, 1],
    ])


def gl_ortho(gl: Any, lf: float, r: float, b: float, t: float, n: float, f: float) -> np.ndarray:
    """glOrthox with the 16.16 arguments nearest to the reals; returns the matrix the spec defines."""
    args = [fx(v) for v in (lf, r, b, t, n, f)]
    gl.glOrthox(*args)
    return ortho(*[unfx(a) for a in args])


def gl_frustum(gl: Any, lf: float, r: float, b: float, t: float, n: float, f: float) -> np.ndarray:
    args = [fx(v) for v in (lf, r, b, t, n, f)]
    gl.glFrustumx(*args)
    return frustum(*[unfx(a) for a in args])


def gl_translate(gl: Any, x: float, y: float, z: float) -> np.ndarray:
    args = [fx(v) for v in (x, y, z)]
    gl.glTranslatex(*args)
    return translate(*[unfx(a) for a in args])


def gl_scale(gl: Any, x: float, y: float, z: float) -> np.ndarray:
    args = [fx(v) for v in (x, y, z)]
    gl.glScalex(*args)
    return scale(*[unfx(a) for a in args])


def gl_rotate(gl: Any, angle: float, x: float, y: float, z: float) -> np.ndarray:
    args = [fx(v) for v in (angle, x, y, z)]
    gl.glRotatex(*args)
    return rotate(*[unfx(a) for a in args])


def gl_matrix(gl: Any, m: np.ndarray, *, load: bool) -> np.ndarray:
    """glLoadMatrixx / glMultMatrixx with `m` (column-major 16.16); returns the matrix given."""
    ints = [fx(v) for v in np.asarray(m, dtype=np.float64).T.reshape(-1)]
    (gl.glLoadMatrixx if load else gl.glMultMatrixx)(ints)
    return np.array([unfx(i) for i in ints]).reshape(4, 4).T


# {============================================================
# the vertex pipeline and clipping (sections 2.10, 2.11)

FRUSTUM_PLANES = np.array([
    [1, 0, 0, 1], [-1, 0, 0, 1],
    [0, 1, 0, 1], [0, -1, 0, 1],
    [0, 0, 1, 1], [0, 0, -1, 1],
], dtype=np.float64)


def clip_polygon(poly: np.ndarray, plane: np.ndarray) -> np.ndarray:
    """Sutherland-Hodgman: the part of `poly` (n, 4) where plane . v >= 0."""
    n = len(poly)
    if n == 0:
        return poly
    d = poly @ plane
    out = []
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        da, db = d[i], d[(i + 1) % n]
        if da >= 0:
            out.append(a)
        if (da >= 0) != (db >= 0):
            out.append(a + (da / (da - db)) * (b - a))
    return np.array(out) if out else np.zeros((0, 4))


def homogeneous(verts: Any) -> np.ndarray:
    """Vertices of 2, 3 or 4 components as (n, 4) with z = 0, w = 1 defaults (section 2.8)."""
    v = np.asarray(verts, dtype=np.float64)
    out = np.zeros((len(v), 4))
    out[:, 3] = 1.0
    out[:, : v.shape[1]] = v
    return out


class Pipe:
    """The transform and clipping of sections 2.10-2.11 in float64."""

    def __init__(self, width: int, height: int) -> None:
        self.width, self.height = width, height
        self.mv = np.eye(4)
        self.proj = np.eye(4)
        self.viewport = (0, 0, width, height)
        self.eye_planes: list[np.ndarray] = []

    def ortho_pixels(self) -> Pipe:
        """What TestContext.ortho_pixels sets."""
        self.mv = np.eye(4)
        self.proj = ortho(0, self.width, 0, self.height, -1, 1)
        self.viewport = (0, 0, self.width, self.height)
        return self

    def polygon(self, verts: Any) -> np.ndarray:
        """The window x, y of the clipped polygon of `verts` (object coordinates); (k, 2), maybe empty."""
        poly = homogeneous(verts) @ self.mv.T
        for p in self.eye_planes:
            poly = clip_polygon(poly, np.asarray(p, dtype=np.float64))
        poly = poly @ self.proj.T
        for q in FRUSTUM_PLANES:
            poly = clip_polygon(poly, q)
        if len(poly) < 3 or (poly[:, 3] <= 0).any():
            return np.zeros((0, 2))
        ndc = poly[:, :2] / poly[:, 3:4]
        x, y, w, h = self.viewport
        return np.stack([w / 2 * ndc[:, 0] + x + w / 2, h / 2 * ndc[:, 1] + y + h / 2], axis=1)

    def window(self, verts: Any) -> np.ndarray:
        """Window x, y of unclipped vertices (w > 0 assumed)."""
        c = homogeneous(verts) @ self.mv.T @ self.proj.T
        ndc = c[:, :2] / c[:, 3:4]
        x, y, w, h = self.viewport
        return np.stack([w / 2 * ndc[:, 0] + x + w / 2, h / 2 * ndc[:, 1] + y + h / 2], axis=1)


# {============================================================
# the point-sampling rule (section 3.5.1)


def centres(width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixel-centre x and y, arrays of shape (height, width), row 0 at the bottom."""
    return np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)


def signed_area(poly: np.ndarray) -> float:
    """Equation 2.6: a = 1/2 sum x_i y_(i+1) - x_(i+1) y_i."""
    p = np.asarray(poly, dtype=np.float64)
    if len(p) < 3:
        return 0.0
    q = np.roll(p, -1, axis=0)
    return 0.5 * float(np.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]))


def coverage(polys: Iterable[np.ndarray], width: int, height: int,
             margin: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """(inside, either): pixel centres strictly inside some convex polygon
    (by more than `margin`), and those on or within `margin` of a boundary
    that are not inside. Degenerate polygons contain no centres."""
    x, y = centres(width, height)
    inside = np.zeros((height, width), dtype=bool)
    near = np.zeros((height, width), dtype=bool)
    for poly in polys:
        p = np.asarray(poly, dtype=np.float64)
        area = signed_area(p)
        if area == 0.0:
            continue
        if area < 0:
            p = p[::-1]
        lo = np.ones((height, width), dtype=bool)
        hi = np.ones((height, width), dtype=bool)
        for i in range(len(p)):
            a, b = p[i], p[(i + 1) % len(p)]
            ex, ey = b - a
            length = float(np.hypot(ex, ey))
            if length == 0.0:
                continue
            e = ex * (y - a[1]) - ey * (x - a[0])
            if margin == 0.0:
                lo &= e > 0
                hi &= e >= 0
            else:
                lo &= e > margin * length
                hi &= e >= -margin * length
        inside |= lo
        near |= hi
    return inside, near & ~inside


def on_segment(p: Sequence[float], q: Sequence[float], width: int, height: int) -> np.ndarray:
    """Pixel centres lying on the open segment p-q (exact for coordinates on a 1/16 grid)."""
    x, y = centres(width, height)
    dx, dy = q[0] - p[0], q[1] - p[1]
    cross = dx * (y - p[1]) - dy * (x - p[0])
    dot = dx * (x - p[0]) + dy * (y - p[1])
    return (cross == 0) & (dot > 0) & (dot < dx * dx + dy * dy)


# {============================================================
# reading and checking


def rgba01(c: Sequence[int]) -> np.ndarray:
    return np.asarray(c, dtype=np.float64) / 255.0


def matches(t: TestContext, img: np.ndarray, rgba: Sequence[int]) -> np.ndarray:
    """Pixels equal to the ubyte colour `rgba` within the visual's tolerance."""
    return np.all(np.abs(img - rgba01(rgba)) <= t.visual.color_tolerance(), axis=-1)


def first(mask: np.ndarray) -> str:
    ys, xs = np.nonzero(mask)
    return f"{int(mask.sum())} pixels, first at (x={int(xs[0])}, y={int(ys[0])})"


def expect_coverage(t: TestContext, img: np.ndarray, inside: np.ndarray, either: np.ndarray,
                    rgba: Sequence[int], where: str, bg: Sequence[int] = BLACK,
                    skip: np.ndarray | None = None) -> np.ndarray:
    """Pixels in `inside` have colour `rgba`; those in neither mask keep `bg`;
    those in `either` have one of the two; pixels in `skip` are not looked
    at. Returns the drawn mask."""
    drawn = matches(t, img, rgba)
    clear = matches(t, img, bg)
    if skip is not None:
        clear = clear | skip
    missing = inside & ~drawn
    if missing.any():
        t.fail(f"{where}: pixels whose centres are inside are not drawn: {first(missing)}")
    extra = ~inside & ~either & ~clear
    if extra.any():
        t.fail(f"{where}: pixels whose centres are outside are drawn: {first(extra)}")
    other = either & ~drawn & ~clear
    if other.any():
        t.fail(f"{where}: edge pixels have neither the primitive's nor the background colour: "
               f"{first(other)}")
    return drawn


def draw_one(t: TestContext, mode: int, verts: Any, rgba: Sequence[int] = WHITE, *,
             size: int = 2, indices: Any = None) -> np.ndarray:
    """Clear, draw in one colour, check no GL error and return the image."""
    gl = t.gl
    t.clear()
    gl.glColor4x(*[fx(c / 255.0) for c in rgba])
    t.draw(mode, verts, size=size, indices=indices)
    t.check_gl_error("draw")
    return t.read()


def grid(rng: np.random.Generator, lo: float, hi: float, n: int) -> np.ndarray:
    """Random coordinates on the 1/16 grid in [lo, hi], a third snapped to
    pixel centres and a third to pixel corners (so edges pass through centres)."""
    v = np.round(rng.uniform(lo, hi, size=n) * 16) / 16
    kind = rng.integers(0, 3, size=n)
    v = np.where(kind == 0, np.floor(v) + 0.5, v)
    v = np.where(kind == 1, np.round(v), v)
    return v


def random_triangles(rng: np.random.Generator, n: int, lo: float = 0.0, hi: float = 64.0,
                     min_area: float = 2.0) -> list[np.ndarray]:
    """Triangles inside [lo, hi]^2 (inside the window no clipping moves their edges)."""
    tris = []
    while len(tris) < n:
        tri = np.stack([grid(rng, lo, hi, 3), grid(rng, lo, hi, 3)], axis=1)
        if abs(signed_area(tri)) >= min_area:
            tris.append(tri)
    return tris


# {============================================================
# Clip


@conformance_test("Clip.xy", section="2.11")
def clip_xy(t: TestContext) -> None:
    """Triangles crossing the left, right, bottom and top planes are drawn only inside the viewport (2.11)."""
    gl = t.gl
    vp = (8, 12, 44, 40)
    pipe = Pipe(t.width, t.height)
    gl.glViewport(*vp)
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    pipe.proj = gl_ortho(gl, 0, vp[2], 0, vp[3], -1, 1)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()
    pipe.viewport = vp
    cases = {
        "left": [(-30.25, 5.0625), (20.5, 10.5), (6.125, 30.75)],
        "right": [(30.5, 4.25), (80.0625, 20.5), (25.1875, 35.5)],
        "bottom": [(10.5, -50.25), (30.75, 15.5), (5.0, 20.0625)],
        "top": [(12.3125, 25.5), (40.5, 90.75), (2.5, 33.0)],
        "left+bottom": [(-20.0, -20.5), (20.25, -5.0), (-5.5, 20.125)],
        "right+top": [(60.0, 20.5), (30.0, 60.0), (50.5, 55.5)],
        "all four": [(-100.0, -100.5), (200.25, -50.0), (-30.0, 250.5)],
        "outside the viewport, inside the window": [(-7.0, 5.0), (-1.0, 20.5), (-6.5, 30.0)],
        "above the viewport": [(5.0, 41.0), (30.0, 45.5), (20.0, 50.0)],
    }
    for name, tri in cases.items():
        img = draw_one(t, gl.GL_TRIANGLES, tri)
        inside, either = coverage([pipe.polygon(tri)], t.width, t.height, MARGIN)
        expect_coverage(t, img, inside, either, WHITE, f"triangle crossing {name}")


@conformance_test("Clip.z", section="2.11")
def clip_z(t: TestContext) -> None:
    """Primitives crossing the near and far planes are clipped there, in ortho and in perspective (2.11)."""
    gl = t.gl
    t.ortho_pixels()
    pipe = Pipe(t.width, t.height).ortho_pixels()
    # z grows along x: only the band with |z| <= 1 remains
    quads = {
        "z from -2 to 2 along x": [(0, 4, -2), (64, 4, 2), (64, 28, 2), (0, 28, -2)],
        "z from 1.6 to -1.6 along x": [(0, 36, 1.6), (64, 36, -1.6), (64, 60, -1.6), (0, 60, 1.6)],
        "beyond far": [(8, 8, 1.25), (56, 8, 1.5), (32, 56, 1.0625)],
        "before near": [(8, 8, -1.25), (56, 8, -1.5), (32, 56, -1.0625)],
    }
    for name, quad in quads.items():
        mode = gl.GL_TRIANGLE_FAN if len(quad) == 4 else gl.GL_TRIANGLES
        img = draw_one(t, mode, quad, size=3)
        tris = [quad[:3]] + ([[quad[0], quad[2], quad[3]]] if len(quad) == 4 else [])
        inside, either = coverage([pipe.polygon(tr) for tr in tris], t.width, t.height, MARGIN)
        expect_coverage(t, img, inside, either, WHITE, f"ortho, {name}")
        if name.startswith("z from -2"):
            band = np.zeros_like(inside)
            band[4:28, 16:48] = True
            if (inside & ~band).any() or (band & ~(inside | either)).any():
                t.fail("test bug: the near/far band is not where it should be")

    # perspective: frustum with near 1 and far 4, triangles crossing near and/or far
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    pipe.proj = gl_frustum(gl, -1, 1, -1, 1, 1, 4)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()
    pipe.mv = np.eye(4)
    tris = {
        "crossing near and far": [(-0.5, -0.625, -0.5), (0.75, -0.25, -6.0), (-0.25, 1.5, -3.0)],
        "crossing near": [(-0.375, -0.375, -0.25), (0.9375, 0.25, -2.0), (-0.75, 0.5, -2.5)],
        "crossing far": [(-1.5, -1.0, -2.5), (2.0, -0.5, -6.5), (0.5, 1.75, -3.0)],
    }
    for name, tri in tris.items():
        tri = q16(tri)
        img = draw_one(t, gl.GL_TRIANGLES, tri, size=3)
        inside, either = coverage([pipe.polygon(tri)], t.width, t.height, MARGIN)
        expect_coverage(t, img, inside, either, WHITE, f"perspective, triangle {name}")


# {============================================================
# UserClip


def _full_window_quad(t: TestContext) -> list[list[float]]:
    return [[0, 0], [t.width, 0], [t.width, t.height], [0, t.height]]


def _draw_quad(t: TestContext, quad: Any, rgba: Sequence[int] = WHITE) -> np.ndarray:
    return draw_one(t, t.gl.GL_TRIANGLE_FAN, quad, rgba)


def _quad_cover(pipe: Pipe, quad: Any, t: TestContext, margin: float) -> tuple[np.ndarray, np.ndarray]:
    tris = [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
    return coverage([pipe.polygon(tr) for tr in tris], t.width, t.height, margin)


@conformance_test("UserClip.planes", section="2.11", uses=("clipplane",))
def userclip_planes(t: TestContext) -> None:
    """Each of MAX_CLIP_PLANES planes clips to its half-space; all together to the intersection (2.11)."""
    gl = t.gl
    t.ortho_pixels()
    n = int(gl.glGetIntegerv(gl.GL_MAX_CLIP_PLANES))
    if n < 1:
        t.fail(f"MAX_CLIP_PLANES is {n}, the minimum is 1")
    quad = _full_window_quad(t)
    pipe = Pipe(t.width, t.height).ortho_pixels()
    cx, cy, radius = 31.75, 32.25, 18.0
    eqs = []
    for i in range(n):
        a = 2 * np.pi * i / n + 0.3
        nx, ny = np.cos(a), np.sin(a)
        # inside where (x - c) . (-n) + radius >= 0: within `radius` of c along -n
        eqs.append([fx(-nx), fx(-ny), 0, fx(nx * cx + ny * cy + radius)])
    for i in range(n):
        plane = gl.GL_CLIP_PLANE0 + i
        if gl.glIsEnabled(plane):
            t.fail(f"CLIP_PLANE{i} is enabled initially")
        got = np.asarray(gl.glGetClipPlanex(plane))
        if np.any(got != 0):
            t.fail(f"CLIP_PLANE{i} is {got.tolist()} initially, expected zeros")
        # a plane left (0, 0, 0, 0) passes everything: 0 >= 0
        gl.glEnable(plane)
        img = _draw_quad(t, quad)
        expect_coverage(t, img, np.ones((t.height, t.width), dtype=bool), np.zeros((t.height, t.width), bool),
                        WHITE, f"CLIP_PLANE{i} enabled with its initial (0, 0, 0, 0)")
        gl.glClipPlanex(plane, eqs[i])
        t.check_gl_error(f"glClipPlanex(CLIP_PLANE{i})")
        if not gl.glIsEnabled(plane):
            t.fail(f"CLIP_PLANE{i} not enabled after glEnable")
        img = _draw_quad(t, quad)
        pipe.eye_planes = [np.array(eqs[i], dtype=np.float64) / ONE]
        inside, either = _quad_cover(pipe, quad, t, MARGIN)
        expect_coverage(t, img, inside, either, WHITE, f"CLIP_PLANE{i} alone")
        gl.glDisable(plane)
    # all planes together: the convex polygon they bound (a half-plane when n is 1)
    for i in range(n):
        gl.glEnable(gl.GL_CLIP_PLANE0 + i)
    img = _draw_quad(t, quad)
    pipe.eye_planes = [np.array(e, dtype=np.float64) / ONE for e in eqs]
    inside, either = _quad_cover(pipe, quad, t, MARGIN)
    expect_coverage(t, img, inside, either, WHITE, f"all {n} clip planes enabled")
    # disabling restores the unclipped picture
    for i in range(n):
        gl.glDisable(gl.GL_CLIP_PLANE0 + i)
    img = _draw_quad(t, quad)
    expect_coverage(t, img, np.ones((t.height, t.width), dtype=bool), np.zeros((t.height, t.width), bool),
                    WHITE, "all clip planes disabled again")
    # an invalid plane name is INVALID_ENUM
    gl.glClipPlanex(gl.GL_CLIP_PLANE0 + n, [ONE, 0, 0, 0])
    t.check_gl_error(f"glClipPlanex(CLIP_PLANE0 + {n})", gl.GL_INVALID_ENUM)


@conformance_test("UserClip.eye", section="2.11", uses=("clipplane",))
def userclip_eye(t: TestContext) -> None:
    """The plane is carried to eye space by the inverse modelview current at glClipPlane (2.11, 6.1)."""
    gl = t.gl
    t.ortho_pixels()
    pipe = Pipe(t.width, t.height).ortho_pixels()
    quad = _full_window_quad(t)
    plane = gl.GL_CLIP_PLANE0
    cases = [
        # (modelview at glClipPlane, object plane, modelview at draw time)
        ("translate", lambda: gl_translate(gl, 20.5, 30.25, 0), (1.0, 0.5, 0.0, -3.0), None),
        ("rotate 30 about z", lambda: (gl_translate(gl, 32, 32, 0) @ gl_rotate(gl, 30, 0, 0, 1)),
         (0.0, 1.0, 0.0, 2.5), None),
        ("scale and rotate", lambda: (gl_translate(gl, 24, 40, 0) @ gl_rotate(gl, -60, 0, 0, 1)
                                      @ gl_scale(gl, 2, 0.5, 1)), (1.0, 1.0, 0.0, 0.0), None),
        ("rotate about x", lambda: (gl_translate(gl, 32, 32, 0) @ gl_rotate(gl, 45, 1, 0, 0)),
         (0.0, 1.0, -1.0, 0.0), None),
        ("modelview changed before drawing", lambda: gl_translate(gl, 40, 20, 0), (-1.0, 0.25, 0.0, 0.0),
         lambda: gl_translate(gl, 7, -5, 0)),
    ]
    gl.glEnable(plane)
    for name, setup, eq, later in cases:
        gl.glMatrixMode(gl.GL_MODELVIEW)
        gl.glLoadIdentity()
        m = setup()
        eqx = [fx(v) for v in eq]
        gl.glClipPlanex(plane, eqx)
        t.check_gl_error(f"{name}: glClipPlanex")
        eye = (np.array(eqx, dtype=np.float64) / ONE) @ np.linalg.inv(m)
        got = np.asarray(gl.glGetClipPlanex(plane), dtype=np.float64) / ONE
        if np.any(np.abs(got - eye) > 2.0**-10 + 1e-4 * np.abs(eye)):
            t.fail(f"{name}: glGetClipPlanex gives {np.round(got, 5).tolist()}, "
                   f"expected the eye-space plane {np.round(eye, 5).tolist()}")
        gl.glLoadIdentity()
        pipe.mv = np.eye(4) if later is None else later()
        img = _draw_quad(t, quad)
        pipe.eye_planes = [eye]
        inside, either = _quad_cover(pipe, quad, t, MARGIN)
        expect_coverage(t, img, inside, either, WHITE, f"plane given under '{name}'")
    gl.glDisable(plane)
    gl.glLoadIdentity()


@conformance_test("UserClip.complement", section="2.11", uses=("clipplane",))
def userclip_complement(t: TestContext) -> None:
    """Drawing with plane p and then with -p covers each pixel of the primitive exactly once (2.11)."""
    gl = t.gl
    t.ortho_pixels()
    rng = np.random.default_rng(11)
    scenes = [
        [[(0, 0), (64, 0), (64, 64)], [(0, 0), (64, 64), (0, 64)]],
        [[(3.5, 5.0), (60.25, 12.5), (20.0, 61.5)]],
    ]
    # one primitive per scene: the criterion is per primitive (overlapping primitives
    # may each take a centre lying on the plane from a different side)
    scenes += [[list(map(tuple, tri))] for tri in random_triangles(rng, 4, 0, 64, 40.0)]
    planes = {
        "x - y >= 0 (through pixel centres)": (1.0, -1.0, 0.0, 0.0),
        "2x + y >= 60.5 (through pixel centres)": (2.0, 1.0, 0.0, -60.5),
        "y >= 31.5 (through pixel centres)": (0.0, 1.0, 0.0, -31.5),
        "x >= 20.5 (through pixel centres)": (1.0, 0.0, 0.0, -20.5),
        "oblique": (0.3125, -0.6875, 0.0, 11.1875),
        "steep": (-1.0, 0.0625, 0.0, 33.3125),
    }
    # modelview at glClipPlane: identity, or a translation whose inverse carries these
    # planes to eye space exactly, so that -p gives exactly the negated eye plane
    setups = {"identity": (0.0, 0.0), "translated": (-3.0625, 2.5)}
    plane = gl.GL_CLIP_PLANE0
    gl.glEnable(plane)
    for sname, (tx, ty) in setups.items():
        for pname, eq in planes.items():
            eqx = np.array([fx(v) for v in eq], dtype=np.int64)
            for k, scene in enumerate(scenes):
                imgs = []
                for sign in (1, -1):
                    gl.glLoadIdentity()
                    gl_translate(gl, tx, ty, 0)
                    gl.glClipPlanex(plane, (sign * eqx).tolist())
                    gl.glLoadIdentity()
                    t.clear()
                    gl.glColor4x(ONE, ONE, ONE, ONE)
                    for tri in scene:
                        t.draw(gl.GL_TRIANGLES, tri)
                    t.check_gl_error("draw")
                    imgs.append(matches(t, t.read(), WHITE))
                # the cut along the plane must be exact; along the primitive's own edges
                # the vertices clipping makes may be slightly off, hence the margin there
                inside, _ = coverage(scene, t.width, t.height)
                either = np.zeros_like(inside)
                for tri in scene:
                    either |= coverage([tri], t.width, t.height, MARGIN)[1]
                inside &= ~either
                both = imgs[0] & imgs[1] & inside
                neither = ~imgs[0] & ~imgs[1] & inside
                outside = (imgs[0] | imgs[1]) & ~inside & ~either
                where = f"plane {pname}, {sname} modelview, scene {k}"
                if both.any():
                    t.fail(f"{where}: drawn both with p and with -p: {first(both)}")
                if neither.any():
                    t.fail(f"{where}: drawn neither with p nor with -p: {first(neither)}")
                if outside.any():
                    t.fail(f"{where}: pixels outside the primitive drawn: {first(outside)}")
    gl.glDisable(plane)


# {============================================================
# PolyCull


def _facing_tris(t: TestContext) -> tuple[list, list]:
    ccw = [(4.5, 6.0), (28.25, 10.5), (14.0, 54.5)]       # counter-clockwise in window coordinates
    cw = [(36.0, 8.5), (44.5, 57.0), (60.25, 20.0)]        # clockwise
    return ccw, cw


@conformance_test("PolyCull", section="3.5.1", uses=("cull",))
def polycull(t: TestContext) -> None:
    """CullFace FRONT/BACK/FRONT_AND_BACK with FrontFace CW/CCW discard the right triangles (3.5.1)."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    if gl.glIsEnabled(gl.GL_CULL_FACE):
        t.fail("CULL_FACE is enabled initially")
    if int(gl.glGetIntegerv(gl.GL_CULL_FACE_MODE)) != gl.GL_BACK:
        t.fail("CULL_FACE_MODE is not BACK initially")
    if int(gl.glGetIntegerv(gl.GL_FRONT_FACE)) != gl.GL_CCW:
        t.fail("FRONT_FACE is not CCW initially")
    ccw, cw = _facing_tris(t)
    verts = ccw + cw
    colors = [RED] * 3 + [GREEN] * 3
    cov_ccw = coverage([np.array(ccw)], w, h)
    cov_cw = coverage([np.array(cw)], w, h)

    def run(where: str, draw_ccw: bool, draw_cw: bool) -> None:
        t.clear()
        t.draw(gl.GL_TRIANGLES, verts, colors)
        t.check_gl_error(where)
        img = t.read()
        for (inside, either), on, rgba, name, other in ((cov_ccw, draw_ccw, RED, "CCW", cov_cw),
                                                        (cov_cw, draw_cw, GREEN, "CW", cov_ccw)):
            if on:
                expect_coverage(t, img, inside, either, rgba, f"{where}: {name} triangle",
                                skip=other[0] | other[1])
            elif (matches(t, img, rgba)).any():
                t.fail(f"{where}: the {name} triangle is drawn but should be culled: "
                       f"{first(matches(t, img, rgba))}")

    for front in (gl.GL_CCW, gl.GL_CW):
        gl.glFrontFace(front)
        for mode in (gl.GL_FRONT, gl.GL_BACK, gl.GL_FRONT_AND_BACK):
            gl.glCullFace(mode)
            t.check_gl_error("glCullFace/glFrontFace")
            fname = "CCW" if front == gl.GL_CCW else "CW"
            mname = {gl.GL_FRONT: "FRONT", gl.GL_BACK: "BACK", gl.GL_FRONT_AND_BACK: "FRONT_AND_BACK"}[mode]
            gl.glDisable(gl.GL_CULL_FACE)
            run(f"culling disabled, CullFace {mname}, FrontFace {fname}", True, True)
            gl.glEnable(gl.GL_CULL_FACE)
            ccw_front = front == gl.GL_CCW
            keep_front = mode == gl.GL_BACK
            keep_back = mode == gl.GL_FRONT
            run(f"CullFace {mname}, FrontFace {fname}",
                keep_front if ccw_front else keep_back, keep_back if ccw_front else keep_front)

    # facing is decided in window coordinates: a y-flipped projection reverses it
    gl.glFrontFace(gl.GL_CCW)
    gl.glCullFace(gl.GL_BACK)
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthox(0, w * ONE, h * ONE, 0, -ONE, ONE)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    flip = [(x, h - y) for x, y in verts]
    t.clear()
    t.draw(gl.GL_TRIANGLES, flip, colors)
    img = t.read()
    if matches(t, img, GREEN).any():
        t.fail("y-flipped projection: the triangle that is CW in window coordinates (CCW in object "
               f"coordinates) is not culled: {first(matches(t, img, GREEN))}")
    expect_coverage(t, img, *cov_ccw, RED, "y-flipped projection: the triangle CCW in window coordinates",
                    skip=cov_cw[0] | cov_cw[1])
    t.ortho_pixels()

    # strips and fans: triangle i is (A, B, current), so orientation follows equation 2.6 per triangle
    strip = [(4, 4), (4, 20.5), (20.25, 4), (20, 20), (36.5, 20.5), (36, 4), (44, 12.5), (60, 20)]
    fan = [(32, 44), (8, 34.5), (20, 30), (44, 30.5), (56, 36), (60, 56), (44, 60), (50, 50)]
    for mode, vs, mname in ((gl.GL_TRIANGLE_STRIP, strip, "strip"), (gl.GL_TRIANGLE_FAN, fan, "fan")):
        tris = []
        for i in range(len(vs) - 2):
            if mode == gl.GL_TRIANGLE_STRIP:
                tri = (vs[i], vs[i + 1], vs[i + 2]) if i % 2 == 0 else (vs[i + 1], vs[i], vs[i + 2])
            else:
                tri = (vs[0], vs[i + 1], vs[i + 2])
            tris.append(np.array(tri, dtype=np.float64))
        for cull in (gl.GL_BACK, gl.GL_FRONT):
            gl.glCullFace(cull)
            keep = [tr for tr in tris if (signed_area(tr) > 0) == (cull == gl.GL_BACK)]
            if not keep or len(keep) == len(tris):
                t.fail(f"test bug: the {mname} should have triangles of both facings")
            inside, either = coverage(keep, w, h)
            t.clear()
            gl.glColor4x(ONE, ONE, ONE, ONE)
            t.draw(mode, vs)
            img = t.read()
            expect_coverage(t, img, inside, either, WHITE,
                            f"{mname} with CullFace {'BACK' if cull == gl.GL_BACK else 'FRONT'}")
    gl.glDisable(gl.GL_CULL_FACE)
    gl.glCullFace(gl.GL_BACK)


# {============================================================
# TriRaster


@conformance_test("TriRaster.sample", section="3.5.1")
def triraster_sample(t: TestContext) -> None:
    """Each triangle produces exactly the pixels whose centres lie inside it (3.5.1)."""
    gl = t.gl
    t.ortho_pixels()
    rng = np.random.default_rng(1)
    tris = random_triangles(rng, 36, 0.0, 64.0)
    tris += [np.array(tr, dtype=np.float64) for tr in (
        # vertices at pixel centres, edges through many centres
        [(2.5, 2.5), (40.5, 2.5), (2.5, 40.5)],
        [(10.5, 10.5), (50.5, 30.5), (20.5, 60.5)],
        # vertices at pixel corners
        [(0, 0), (33, 1), (7, 29)],
        # sub-pixel vertex positions
        [(5.0625, 60.9375), (61.4375, 33.3125), (30.1875, 2.8125)],
        # tiny: one centre inside, then none
        [(10.25, 10.25), (10.75, 10.3125), (10.5, 10.8125)],
        [(20.5625, 20.5625), (21.4375, 20.5625), (21.0, 21.4375)],
        # slivers
        [(1.0, 3.4375), (62.0, 3.5625), (62.0, 3.6875)],
        [(30.4375, 1.0), (30.5625, 1.0), (31.0, 63.0)],
        [(2.0, 2.0625), (62.0, 61.9375), (62.0, 62.0625)],
    )]
    for k, tri in enumerate(tris):
        for cw in (False, True):
            vs = tri[::-1] if cw else tri
            img = draw_one(t, gl.GL_TRIANGLES, vs)
            inside, either = coverage([tri], t.width, t.height)
            expect_coverage(t, img, inside, either, WHITE,
                            f"triangle {k} {np.round(vs, 4).tolist()} ({'CW' if cw else 'CCW'})")


@conformance_test("TriRaster.shared", section="3.5.1")
def triraster_shared(t: TestContext) -> None:
    """A centre on an edge shared by two triangles is produced by exactly one of them (3.5.1)."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    rng = np.random.default_rng(2)
    pairs = []
    # edges between pixel centres, in every direction class, with a third vertex on each side
    edges = [((4.5, 31.5), (60.5, 31.5)), ((31.5, 3.5), (31.5, 60.5)), ((3.5, 3.5), (60.5, 60.5)),
             ((60.5, 4.5), (4.5, 60.5)), ((2.5, 10.5), (62.5, 40.5)), ((12.5, 2.5), (42.5, 62.5)),
             ((2.5, 50.5), (62.5, 20.5)), ((50.5, 2.5), (20.5, 62.5)), ((3.5, 20.5), (61.5, 49.5))]
    for p, q in edges:
        d = np.array(q) - np.array(p)
        nrm = np.array([-d[1], d[0]]) / np.hypot(*d)
        mid = (np.array(p) + np.array(q)) / 2
        for _ in range(2):
            s1, s2 = rng.uniform(6, 25, size=2)
            along = rng.uniform(-0.4, 0.4, size=2) * np.hypot(*d)
            dd = d / np.hypot(*d)
            r1 = np.round((mid + nrm * s1 + dd * along[0]) * 16) / 16
            r2 = np.round((mid - nrm * s2 + dd * along[1]) * 16) / 16
            pairs.append((p, q, r1, r2))
    for k, (p, q, r1, r2) in enumerate(pairs):
        on_edge = on_segment(p, q, w, h)
        if not on_edge.any():
            t.fail("test bug: the shared edge passes through no pixel centre")
        drawn = []
        for tri in ([p, q, r1], [q, p, r2]):
            img = draw_one(t, gl.GL_TRIANGLES, tri)
            inside, either = coverage([np.array(tri, dtype=np.float64)], w, h)
            drawn.append(expect_coverage(t, img, inside, either, WHITE, f"pair {k}, triangle {tri}"))
        both = drawn[0] & drawn[1] & on_edge
        none = ~drawn[0] & ~drawn[1] & on_edge
        if both.any():
            t.fail(f"pair {k}: centres on the shared edge {p}-{q} drawn by both triangles: {first(both)}")
        if none.any():
            t.fail(f"pair {k}: centres on the shared edge {p}-{q} drawn by neither triangle: {first(none)}")


@conformance_test("TriRaster.fan", section="3.5.1")
def triraster_fan(t: TestContext) -> None:
    """Triangles around a common vertex: every centre on a shared spoke belongs to exactly one (3.5.1)."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    hub = (32.5, 32.5)
    # rim points whose spokes pass through pixel centres (directions (1,0), (1,1), (2,1), (1,2) ...)
    rim = [(62.5, 32.5), (60.5, 46.5), (58.5, 58.5), (46.5, 60.5), (32.5, 62.5), (18.5, 60.5),
           (4.5, 60.5), (2.5, 47.5), (2.5, 32.5), (4.5, 18.5), (6.5, 6.5), (18.5, 4.5),
           (32.5, 2.5), (46.5, 4.5), (58.5, 6.5), (60.5, 18.5)]
    tris = [[hub, rim[i], rim[(i + 1) % len(rim)]] for i in range(len(rim))]
    count = np.zeros((h, w), dtype=int)
    for k, tri in enumerate(tris):
        img = draw_one(t, gl.GL_TRIANGLES, tri)
        inside, either = coverage([np.array(tri, dtype=np.float64)], w, h)
        count += expect_coverage(t, img, inside, either, WHITE, f"fan triangle {k}")
    interior, _ = coverage([np.array(rim, dtype=np.float64)], w, h)
    spokes = np.zeros((h, w), dtype=bool)
    for r in rim:
        spokes |= on_segment(hub, r, w, h)
    bad = spokes & interior & (count != 1)
    if bad.any():
        t.fail(f"centres on the shared spokes not drawn exactly once: {first(bad)}")


# {============================================================
# TriTile


def _tile_strips(w: int, h: int) -> list[tuple[list, list[list]]]:
    """Horizontal bands, each one strip; rows shared by neighbouring bands have identical vertices."""
    ys = [0.0, 10.5, 21.25, 32.5, 40.0, 53.5, float(h)]
    xs_rows = [
        [0.0, 7.5, 15.0, 24.5, 32.5, 40.0, 47.5, 56.0, float(w)],
        [0.0, 4.5, 12.0, 20.5, 30.0, 37.5, 45.5, 55.5, float(w)],
        [0.0, 8.5, 16.5, 24.5, 32.5, 40.5, 48.5, 56.5, float(w)],
        [0.0, 6.0, 16.0, 22.5, 33.5, 41.0, 50.0, 57.5, float(w)],
        [0.0, 8.5, 16.5, 24.5, 32.5, 40.5, 48.5, 56.5, float(w)],
        [0.0, 5.0625, 13.9375, 25.5, 31.5, 43.25, 47.5, 58.5, float(w)],
        [0.0, 7.5, 15.0, 24.5, 32.5, 40.0, 47.5, 56.0, float(w)],
    ]
    out = []
    for b in range(len(ys) - 1):
        vs = []
        for xb, xt in zip(xs_rows[b], xs_rows[b + 1]):
            vs += [(xb, ys[b]), (xt, ys[b + 1])]
        tris = [[vs[i], vs[i + 1], vs[i + 2]] if i % 2 == 0 else [vs[i + 1], vs[i], vs[i + 2]]
                for i in range(len(vs) - 2)]
        out.append((vs, tris))
    return out


def _tile_fans(w: int, h: int) -> list[tuple[list, list[list]]]:
    """Four fans, one per quadrant around the window centre, sharing their spokes' rims."""
    c = (32.5, 32.5)
    # the window boundary walked counter-clockwise from (0, 0), with points whose spokes pass
    # through pixel centres (slopes 0, 1/2, 1, 2 from the hub)
    border = [(0.0, 0.0), (16.25, 0.0), (32.5, 0.0), (48.75, 0.0), (64.0, 0.0),
              (64.0, 16.75), (64.0, 32.5), (64.0, 48.25), (64.0, 64.0),
              (48.25, 64.0), (32.5, 64.0), (16.75, 64.0), (0.0, 64.0),
              (0.0, 48.75), (0.0, 32.5), (0.0, 16.25)]
    out = []
    q = len(border) // 4
    for k in range(4):
        rim = [border[(k * q + i) % len(border)] for i in range(q + 1)]
        vs = [c] + rim
        tris = [[vs[0], vs[i + 1], vs[i + 2]] for i in range(len(vs) - 2)]
        out.append((vs, tris))
    return out


def _tile_lists(w: int, h: int) -> list[tuple[list, list[list]]]:
    """A 6x6 grid of jittered vertices, each cell split along alternating diagonals."""
    rng = np.random.default_rng(5)
    n = 6
    gx = np.linspace(0, w, n + 1)
    gy = np.linspace(0, h, n + 1)
    px = np.zeros((n + 1, n + 1))
    py = np.zeros((n + 1, n + 1))
    for i in range(n + 1):
        for j in range(n + 1):
            x, y = gx[i], gy[j]
            if 0 < i < n:
                x = np.floor(x + rng.uniform(-2, 2)) + rng.choice([0.5, 0.0, 0.25, 0.6875])
            if 0 < j < n:
                y = np.floor(y + rng.uniform(-2, 2)) + rng.choice([0.5, 0.0, 0.75, 0.3125])
            px[i, j], py[i, j] = x, y
    vs = []
    tris = []
    for i in range(n):
        for j in range(n):
            a, b = (px[i, j], py[i, j]), (px[i + 1, j], py[i + 1, j])
            c, d = (px[i + 1, j + 1], py[i + 1, j + 1]), (px[i, j + 1], py[i, j + 1])
            pair = [[a, b, c], [a, c, d]] if (i + j) % 2 == 0 else [[a, b, d], [b, c, d]]
            for tri in pair:
                vs += tri
                tris.append(tri)
    return [(vs, tris)]


def _check_tiling(t: TestContext, prims: list[tuple[list, list[list]]]) -> None:
    areas = [signed_area(np.array(tri)) for _, tris in prims for tri in tris]
    if min(abs(a) for a in areas) <= 0 or abs(sum(abs(a) for a in areas) - t.width * t.height) > 1e-6:
        t.fail("test bug: the triangles do not tile the window")


def _tritile(t: TestContext, mode_name: str, prims: list[tuple[list, list[list]]]) -> None:
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    mode = getattr(gl, mode_name)
    _check_tiling(t, prims)
    count = np.zeros((h, w), dtype=int)
    for p, (_, tris) in enumerate(prims):
        for k, tri in enumerate(tris):
            img = draw_one(t, gl.GL_TRIANGLES, tri)
            inside, either = coverage([np.array(tri, dtype=np.float64)], w, h)
            count += expect_coverage(t, img, inside, either, WHITE, f"{mode_name} {p}, triangle {k}")
    if (count == 0).any():
        t.fail(f"{mode_name} tiling: pixels covered by no triangle: {first(count == 0)}")
    if (count > 1).any():
        t.fail(f"{mode_name} tiling: pixels covered more than once: {first(count > 1)}")
    # drawn as the primitives themselves, one call each, the window is covered
    t.clear()
    gl.glColor4x(ONE, ONE, ONE, ONE)
    for vs, _ in prims:
        t.draw(mode, vs)
    t.check_gl_error(f"glDrawArrays({mode_name})")
    img = t.read()
    missing = ~matches(t, img, WHITE)
    if missing.any():
        t.fail(f"{mode_name} drawn in one call each: pixels not covered: {first(missing)}")


@conformance_test("TriTile.strip", section="3.5.1")
def tritile_strip(t: TestContext) -> None:
    """Triangle strips tiling the window cover every pixel exactly once (3.5.1, 2.6.1)."""
    _tritile(t, "GL_TRIANGLE_STRIP", _tile_strips(t.width, t.height))


@conformance_test("TriTile.fan", section="3.5.1")
def tritile_fan(t: TestContext) -> None:
    """Triangle fans tiling the window cover every pixel exactly once (3.5.1, 2.6.1)."""
    _tritile(t, "GL_TRIANGLE_FAN", _tile_fans(t.width, t.height))


@conformance_test("TriTile.list", section="3.5.1")
def tritile_list(t: TestContext) -> None:
    """Separate triangles tiling the window cover every pixel exactly once (3.5.1, 2.6.1)."""
    _tritile(t, "GL_TRIANGLES", _tile_lists(t.width, t.height))


# {============================================================
# VertexOrder


@conformance_test("VertexOrder.rotate", section="3.5.1")
def vertexorder_rotate(t: TestContext) -> None:
    """A triangle given as abc, bca or cab covers the same pixels; acb, cba, bac likewise (3.5.1)."""
    gl = t.gl
    t.ortho_pixels()
    w, h = t.width, t.height
    rng = np.random.default_rng(3)
    tris = random_triangles(rng, 24, 0.0, 64.0)
    tris.append(np.array([(2.5, 2.5), (40.5, 2.5), (2.5, 40.5)]))
    tris.append(np.array([(10.5, 10.5), (50.5, 30.5), (20.5, 60.5)]))
    for k, tri in enumerate(tris):
        inside, either = coverage([tri], w, h)
        for orders in (((0, 1, 2), (1, 2, 0), (2, 0, 1)), ((0, 2, 1), (2, 1, 0), (1, 0, 2))):
            ref = None
            for order in orders:
                img = draw_one(t, gl.GL_TRIANGLES, tri[list(order)])
                drawn = expect_coverage(t, img, inside, either, WHITE, f"triangle {k} in order {order}")
                if ref is None:
                    ref = drawn
                elif (drawn != ref).any():
                    t.fail(f"triangle {k} {tri.tolist()}: order {order} covers different pixels than "
                           f"{orders[0]}: {first(drawn != ref)}")


@conformance_test("VertexOrder.flat", section="2.12.6", uses=("shademodel",), visuals=("rgba8888", "rgb565"))
def vertexorder_flat(t: TestContext) -> None:
    """Flat shading takes the colour of vertex 3i, i+2, i+2 for lists, strips, fans (Table 2.10)."""
    gl = t.gl
    t.ortho_pixels()
    palette = [RED, GREEN, BLUE, (255, 255, 0, 255), (0, 255, 255, 255), (255, 0, 255, 255), WHITE]
    gl.glShadeModel(gl.GL_FLAT)
    lists = [(2, 2), (20, 3), (10, 18.5), (24, 2), (44, 6), (30, 20),
             (46, 2), (62, 4), (54, 19), (6, 24), (18, 26.5), (8, 40)]
    strip = [(2, 44), (4, 62), (14, 45), (18, 61), (28, 44), (30, 62.5), (42, 46), (46, 60)]
    fan = [(56, 42), (62, 30), (62, 62), (48, 62), (40, 52), (40, 34)]
    # for DrawElements the array is stored shuffled; vertices are numbered in index order
    perm = [5, 2, 9, 0, 11, 7, 3, 10, 1, 8, 4, 6]
    cases = [
        ("TRIANGLES", gl.GL_TRIANGLES, lists, None, lambda i: 3 * i + 2),
        ("TRIANGLE_STRIP", gl.GL_TRIANGLE_STRIP, strip, None, lambda i: i + 2),
        ("TRIANGLE_FAN", gl.GL_TRIANGLE_FAN, fan, None, lambda i: i + 2),
        ("TRIANGLES by DrawElements", gl.GL_TRIANGLES, lists, perm, lambda i: 3 * i + 2),
        ("TRIANGLE_STRIP by DrawElements", gl.GL_TRIANGLE_STRIP, strip, [3, 6, 0, 7, 1, 5, 2, 4],
         lambda i: i + 2),
        ("TRIANGLE_FAN by DrawElements", gl.GL_TRIANGLE_FAN, fan, [4, 0, 5, 2, 1, 3], lambda i: i + 2),
    ]
    for name, mode, vs, order, prov in cases:
        colors = [palette[i % len(palette)] for i in range(len(vs))]
        t.clear()
        if order is None:
            t.draw(mode, vs, colors)
        else:
            arr = [None] * len(vs)
            carr = [None] * len(vs)
            for k, p in enumerate(order):
                arr[p], carr[p] = vs[k], colors[k]
            t.draw(mode, arr, carr, indices=order)
        t.check_gl_error(name)
        _expect_flat(t, name, mode, vs, colors, prov)
    gl.glShadeModel(gl.GL_SMOOTH)


def _expect_flat(t: TestContext, name: str, mode: int, vs: Sequence[Any], colors: Sequence[Any],
                 prov: Any) -> None:
    """Each triangle of the drawn `mode` over `vs` covers its pixels in the
    colour of vertex prov(i)."""
    gl = t.gl
    w, h = t.width, t.height
    img = t.read()
    ntri = len(vs) // 3 if mode == gl.GL_TRIANGLES else len(vs) - 2
    for i in range(ntri):
        if mode == gl.GL_TRIANGLES:
            tri = [vs[3 * i], vs[3 * i + 1], vs[3 * i + 2]]
        elif mode == gl.GL_TRIANGLE_STRIP:
            tri = [vs[i], vs[i + 1], vs[i + 2]]
        else:
            tri = [vs[0], vs[i + 1], vs[i + 2]]
        inside, _ = coverage([np.array(tri, dtype=np.float64)], w, h, 0.5)
        if not inside.any():
            t.fail("test bug: triangle too thin")
        want = colors[prov(i)]
        wrong = inside & ~matches(t, img, want)
        if wrong.any():
            t.fail(f"{name}: triangle {i + 1} is not flat shaded with vertex {prov(i) + 1}'s colour "
                   f"{want}: {first(wrong)}")


@conformance_test("VertexOrder.uint", section="OES_element_index_uint", uses=("shademodel",))
def vertexorder_uint(t: TestContext) -> None:
    """DrawElements with UNSIGNED_INT indices past 65535 draws the triangles they name, flat
    shaded by the provoking vertex (OES_element_index_uint, Table 2.10)."""
    gl = t.gl
    t.ortho_pixels()
    gl.glShadeModel(gl.GL_FLAT)
    palette = [RED, GREEN, BLUE, (255, 255, 0, 255), WHITE]
    strip = [(2, 4), (6, 60), (20, 3), (24, 62), (40, 2), (44, 61.5), (58, 5), (62, 60)]
    base = 70000                       # the vertices sit past the reach of 16-bit indices
    order = [base + 3, base + 6, base + 0, base + 7, base + 1, base + 5, base + 2, base + 4]
    colors = [palette[i % len(palette)] for i in range(len(strip))]
    arr = [(-100.0, -100.0)] * (base + len(strip))
    carr = [BLACK] * (base + len(strip))
    for k, p in enumerate(order):
        arr[p], carr[p] = strip[k], colors[k]
    t.clear()
    t.draw(gl.GL_TRIANGLE_STRIP, arr, carr, indices=order, index_type=gl.GL_UNSIGNED_INT)
    t.check_gl_error("TRIANGLE_STRIP by DrawElements, UNSIGNED_INT")
    _expect_flat(t, "TRIANGLE_STRIP by DrawElements, UNSIGNED_INT", gl.GL_TRIANGLE_STRIP, strip, colors,
                 lambda i: i + 2)
    gl.glShadeModel(gl.GL_SMOOTH)


# {============================================================
# DivZero


@conformance_test("DivZero", section="2.11")
def divzero(t: TestContext) -> None:
    """Vertices with w = 0 and degenerate triangles draw nothing wrong and raise no error (2.1.1, 2.11)."""
    gl = t.gl
    w, h = t.width, t.height
    t.ortho_pixels()
    pipe = Pipe(w, h).ortho_pixels()
    none = np.zeros((h, w), dtype=bool)

    # one vertex at infinity (w = 0): the part with w > 0 is the band swept from
    # the other two vertices towards the direction (x, y) of the w = 0 vertex
    cases = {
        "one vertex w = 0": [(8, 40, 0, 1), (24, 8, 0, 1), (1, 1, 0, 0)],
        "one vertex w = 0, pointing left": [(56, 20, 0, 1), (60, 44, 0, 1), (-2, 0.5, 0, 0)],
        "two vertices w = 0": [(32, 32, 0, 1), (1, 0, 0, 0), (0, 1, 0, 0)],
        "three vertices w = 0": [(1, 0, 0, 0), (0, 1, 0, 0), (-1, -1, 0, 0)],
    }
    for name, tri in cases.items():
        img = draw_one(t, gl.GL_TRIANGLES, tri, size=4)
        inside, either = coverage([pipe.polygon(tri)], w, h, MARGIN)
        if name.startswith("three"):
            inside, either = none, none
        expect_coverage(t, img, inside, either, WHITE, name)

    # a vertex that is all zeros ((0, 0, 0, 0) in clip coordinates): anything within the
    # triangle's hull is allowed, nothing must crash, later draws must be right
    for tri in ([(16, 16, 0, 1), (48, 16, 0, 1), (0, 0, 0, 0)],
                [(0, 0, 0, 0), (0, 0, 0, 0), (0, 0, 0, 0)]):
        gl.glMatrixMode(gl.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glMatrixMode(gl.GL_MODELVIEW)
        t.clear()
        t.draw(gl.GL_TRIANGLES, tri, size=4)
        t.check_gl_error(f"triangle {tri}")
    t.ortho_pixels()

    # a vertex at the eye under a perspective projection (w_c = 0 there)
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    pipe.proj = gl_frustum(gl, -1, 1, -1, 1, 1, 8)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    for tri in ([(0, 0, 0), (2, -1, -4), (-1, 3, -4)], [(0, 0, 0), (0, 0, 0), (1, 1, -2)],
                [(0.5, 0.25, 0), (0.5, -0.5, -3), (-2, 0.25, -3)]):
        img = draw_one(t, gl.GL_TRIANGLES, tri, size=3)
        inside, either = coverage([pipe.polygon(tri)], w, h, MARGIN)
        expect_coverage(t, img, inside, either, WHITE, f"perspective, vertex at the eye, {tri}")
    t.ortho_pixels()
    pipe.ortho_pixels()

    # degenerate triangles: zero area contains no centre; centres exactly on the
    # degenerate segment are allowed either way
    degenerate = [
        [(10.5, 10.5), (10.5, 10.5), (10.5, 10.5)],
        [(3.5, 3.5), (30.5, 30.5), (60.5, 60.5)],          # collinear, through pixel centres
        [(3.25, 5.0625), (30.25, 20.0625), (57.25, 35.0625)],  # collinear, through no centre
        [(5.0, 40.0), (60.0, 40.0), (30.0, 40.0)],        # horizontal on pixel edges
        [(5.0, 40.5), (60.0, 40.5), (30.0, 40.5)],        # horizontal through centres
        [(20.5, 2.0), (20.5, 62.0), (20.5, 30.0)],        # vertical through centres
        [(10.0, 10.0), (50.0, 12.0), (10.0, 10.0)],       # two equal vertices
        [(-1.0e4, -1.0e4), (1.0e4, 1.0e4), (0.0, 0.0)],   # huge, collinear
    ]
    for tri in degenerate:
        img = draw_one(t, gl.GL_TRIANGLES, tri)
        ends = np.array(tri)
        a = ends[np.argmin(ends[:, 0] + ends[:, 1] * 1e-3)]
        b = ends[np.argmax(ends[:, 0] + ends[:, 1] * 1e-3)]
        allowed = on_segment(a, b, w, h) if (a != b).any() else none.copy()
        for p in ends:
            px, py = p[0] - 0.5, p[1] - 0.5
            if px == int(px) and py == int(py) and 0 <= px < w and 0 <= py < h:
                allowed[int(py), int(px)] = True
        expect_coverage(t, img, none, allowed, WHITE, f"degenerate triangle {tri}")
    # edge-on in window space, though not in object space
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthox(0, w * ONE, 0, h * ONE, -64 * ONE, 64 * ONE)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glTranslatex(fx(32.25), fx(32.25), 0)
    gl.glRotatex(90 * ONE, 0, ONE, 0)
    img = draw_one(t, gl.GL_TRIANGLES, [(-20, -20, 0), (20, 20, 0), (10, -15, 0)], size=3)
    expect_coverage(t, img, none, none, WHITE, "triangle seen edge-on")
    # a singular modelview: everything collapses to one point; planes given under it are undefined
    gl.glLoadIdentity()
    gl.glScalex(0, 0, 0)
    gl.glClipPlanex(gl.GL_CLIP_PLANE0, [ONE, ONE, 0, 0])
    t.check_gl_error("glClipPlanex under a singular modelview")
    img = draw_one(t, gl.GL_TRIANGLES, [(1, 1), (50, 3), (20, 40)])
    expect_coverage(t, img, none, none, WHITE, "modelview scaled by 0")
    # everything still works
    t.ortho_pixels()
    tri = [(4.0625, 4.5), (60.5, 10.25), (30.0, 58.75)]
    img = draw_one(t, gl.GL_TRIANGLES, tri)
    inside, either = coverage([np.array(tri)], w, h)
    expect_coverage(t, img, inside, either, WHITE, "an ordinary triangle afterwards")


# {============================================================
# ViewportClamp


@conformance_test("ViewportClamp", section="2.10.1")
def viewport_clamp(t: TestContext) -> None:
    """Viewports beyond MAX_VIEWPORT_DIMS are clamped; partly off-window viewports map as 2.10.1 says."""
    gl = t.gl
    w, h = t.width, t.height
    maxw, maxh = (int(v) for v in gl.glGetIntegerv(gl.GL_MAX_VIEWPORT_DIMS))
    if maxw < w or maxh < h:
        t.fail(f"MAX_VIEWPORT_DIMS {maxw}x{maxh} is smaller than the window {w}x{h}")
    got = [int(v) for v in gl.glGetIntegerv(gl.GL_VIEWPORT)]
    if got != [0, 0, w, h]:
        t.fail(f"initial VIEWPORT is {got}, expected {[0, 0, w, h]}")
    for vp in ((0, 0, maxw + 1, maxh + 1), (-3, 5, maxw + 1000, maxh + 17), (7, -9, 2 * maxw, 40),
               (1, 2, 30, 3 * maxh), (0, 0, 1 << 30, 1 << 30)):
        gl.glViewport(*vp)
        t.check_gl_error(f"glViewport{vp}")
        want = [vp[0], vp[1], min(vp[2], maxw), min(vp[3], maxh)]
        got = [int(v) for v in gl.glGetIntegerv(gl.GL_VIEWPORT)]
        if got != want:
            t.fail(f"glViewport{vp}: VIEWPORT is {got}, expected {want} (clamped to MAX_VIEWPORT_DIMS)")
    # negative sizes are INVALID_VALUE and change nothing
    gl.glViewport(4, 5, 6, 7)
    for vp in ((0, 0, -1, 10), (0, 0, 10, -1)):
        gl.glViewport(*vp)
        t.check_gl_error(f"glViewport{vp}", gl.GL_INVALID_VALUE)
        got = [int(v) for v in gl.glGetIntegerv(gl.GL_VIEWPORT)]
        if got != [4, 5, 6, 7]:
            t.fail(f"glViewport{vp} failed but changed VIEWPORT to {got}")

    # drawing with identity matrices through viewports partly outside the window
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()
    pipe = Pipe(w, h)
    tri = q16([(-0.875, -0.75), (0.9375, -0.5), (0.125, 0.875)])
    quad = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    for vp in ((-20, 30, 50, 60), (40, -24, 48, 40), (-32, -32, 128, 128), (16, 8, 100, 90),
               (0, 0, maxw, maxh), (-maxw // 2 + 32, -maxh // 2 + 32, maxw, maxh)):
        gl.glViewport(*vp)
        pipe.viewport = vp
        for name, shape in (("triangle", tri), ("viewport-filling quad", quad)):
            img = draw_one(t, gl.GL_TRIANGLE_FAN, shape)
            polys = [pipe.polygon(shape[:3])] + ([pipe.polygon([shape[0], shape[2], shape[3]])]
                                                 if len(shape) == 4 else [])
            inside, either = coverage(polys, w, h, MARGIN)
            expect_coverage(t, img, inside, either, WHITE, f"viewport {vp}, {name}")
    # a clamped viewport maps as the clamped size
    gl.glViewport(-maxw + 40, -maxh + 40, maxw + 4096, maxh + 4096)
    pipe.viewport = (-maxw + 40, -maxh + 40, maxw, maxh)
    img = draw_one(t, gl.GL_TRIANGLE_FAN, quad)
    inside, either = coverage([pipe.polygon(quad[:3]), pipe.polygon([quad[0], quad[2], quad[3]])], w, h,
                              MARGIN)
    expect_coverage(t, img, inside, either, WHITE, "viewport larger than MAX_VIEWPORT_DIMS, clamped")
    t.ortho_pixels()
