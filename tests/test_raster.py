"""Polygon rasterization (ES 1.1 §3.5.1, Appendix A invariance rules), every build.

The reference is an exact integer model of the fill rule written here from
the rule in csrc/raster.c's header: a pixel belongs to a polygon when its
centre is strictly inside, or exactly on an edge that is "left" (goes down,
counter-clockwise in y-up window coordinates) or "bottom" (horizontal, goes
right). An edge shared by two triangles runs opposite ways in each, so
exactly one owns the centres on it. The rule is the same as sampling the
point (x + e, y + e^2) for an infinitesimal e > 0: moving right enters
through left edges, and a second-order step up enters through bottom edges.
``rule_coverage`` evaluates that perturbed point-in-polygon test
symbolically, in integers on the 1/256 subpixel grid, so it is exact.

Scenes use 64x64 framebuffers and vertices on the 1/256 grid (window pixels
under the 1:1 ortho setup), which every build turns into the same window
coordinates without rounding; the perspective scenes are chosen so the
projection cannot round differently either (see ``persp_window``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import (
    BUILDS,
    clear,
    coverage,
    draw_arrays,
    draw_tris,
    make_ctx,
    read_rgba,
    set_frustum,
    set_ortho,
)
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from gles import constants as C

W = H = 64
SUB = 256  # subpixels per pixel (csrc/state.h GLES_SUBPIXEL_BITS = 8)

SETTINGS = settings(max_examples=20, deadline=None,
                    suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
seeds = st.integers(0, 2**32 - 1)

# largest fixed-vs-double colour difference seen on smooth triangles
MEASURED: dict[str, int] = {}


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    print("\nraster measurements:", MEASURED)


# {================================================================
# the exact model


def units(pts) -> np.ndarray:
    """Window coordinates (pixels, on the 1/256 grid) as int64 subpixels."""
    u = np.asarray(pts, dtype=np.float64) * SUB
    r = np.round(u)
    assert np.array_equal(r, u), "vertices must lie on the 1/256 grid"
    return r.astype(np.int64)


def rule_coverage(poly, w: int = W, h: int = H) -> np.ndarray:
    """Boolean (h, w), bottom row first: pixels the fill rule assigns to the
    polygon `poly` (window pixels, either winding, simple or a union of a
    consistently wound fan)."""
    p = units(poly)[:, :2]
    n = len(p)
    px = (np.arange(w, dtype=np.int64) * SUB + SUB // 2)[None, :]
    py = (np.arange(h, dtype=np.int64) * SUB + SUB // 2)[:, None]
    wind = np.zeros((h, w), dtype=np.int64)
    for k in range(n):
        ax, ay = (int(v) for v in p[k])
        bx, by = (int(v) for v in p[(k + 1) % n])
        # isLeft(a, b, q) at q = (px + e, py + e^2):
        # c0 - e (by - ay) + e^2 (bx - ax); its sign is lexicographic
        c0 = (bx - ax) * (py - ay) - (px - ax) * (by - ay)
        tail = np.sign(-(by - ay)) if by != ay else np.sign(bx - ax)
        s = np.where(c0 != 0, np.sign(c0), tail)
        # crossing rule ay <= q.y < by (upward) with q.y = py + e^2:
        # ay <= q.y  <=>  ay <= py ;  q.y < by  <=>  py < by
        up = (ay <= py) & (py < by) & (s > 0)
        down = (by <= py) & (py < ay) & (s < 0)
        wind += up.astype(np.int64) - down.astype(np.int64)
    return wind != 0


def area2(a, b, c) -> int:
    """Twice the signed area in subpixel units (exact)."""
    a, b, c = units([a, b, c])[:, :2]
    return int((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))


def quant(pts, snap: bool) -> np.ndarray:
    """Round to the 1/256 grid, or to pixel centres when `snap`."""
    pts = np.asarray(pts, dtype=np.float64)
    if snap:
        return np.floor(pts) + 0.5
    return np.round(pts * SUB) / SUB


def id_colour(t: int) -> tuple[int, int, int, int]:
    """A distinct non-zero RGBA colour for triangle number t."""
    t += 1
    return (t & 0xFF, (t >> 8) & 0xFF, 0x5A, 0xFF)


# {================================================================
# meshes: vertices, the triangles as index triples, and how to draw one
# triangle alone and the whole mesh at once


class Mesh:
    """A set of triangles sharing edges whose union is a simple polygon."""

    def __init__(self, verts, mode: int, order, tris, outline):
        self.verts = np.asarray(verts, dtype=np.float64)  # (n, 2) window pixels
        self.mode = mode  # how the whole mesh is drawn
        self.order = np.asarray(order, dtype=np.uint16)  # vertex sequence for `mode`
        self.tris = [tuple(int(i) for i in t) for t in tris]  # triangle i's vertices
        self.outline = np.asarray(outline, dtype=np.float64)

    def valid(self) -> bool:
        """Every triangle non-degenerate and wound the same way: with a simple
        outline that makes the triangles tile it exactly once."""
        s = [area2(*self.verts[list(t)]) for t in self.tris]
        return all(v > 0 for v in s) or all(v < 0 for v in s)


def grid_mesh(rng: np.random.Generator, snap: bool, nx: int = 0, ny: int = 0,
              jitter: float = 0.2) -> Mesh:
    """A grid of nx x ny quads over [8, 56]^2 (random sizes when 0), corners
    jittered by up to `jitter` cells, each quad split along a random diagonal
    (GL_TRIANGLES)."""
    nx = nx or int(rng.integers(2, 6))
    ny = ny or int(rng.integers(2, 6))
    xs, ys = np.linspace(8, 56, nx + 1), np.linspace(8, 56, ny + 1)
    gx, gy = np.meshgrid(xs, ys)
    gx = gx + rng.uniform(-jitter, jitter, gx.shape) * (48 / nx)
    gy = gy + rng.uniform(-jitter, jitter, gy.shape) * (48 / ny)
    verts = quant(np.stack([gx.ravel(), gy.ravel()], axis=1), snap)

    def at(i, j):
        return j * (nx + 1) + i

    tris = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
            tris += [(a, b, c), (a, c, d)] if rng.random() < 0.5 else [(a, b, d), (b, c, d)]
    outline = ([at(i, 0) for i in range(nx + 1)] + [at(nx, j) for j in range(1, ny + 1)]
               + [at(i, ny) for i in range(nx - 1, -1, -1)] + [at(0, j) for j in range(ny - 1, 0, -1)])
    return Mesh(verts, C.GL_TRIANGLES, np.ravel(tris), tris, verts[outline])


def fan_mesh(rng: np.random.Generator, snap: bool) -> Mesh:
    """A closed triangle fan around a random centre (GL_TRIANGLE_FAN)."""
    k = int(rng.integers(5, 13))
    centre = rng.uniform(26, 38, size=2)
    ang = rng.uniform(0, 2 * np.pi) + 2 * np.pi * (np.arange(k) + rng.uniform(-0.3, 0.3, k)) / k
    rad = rng.uniform(5, 24, size=k)
    rim = centre + rad[:, None] * np.stack([np.cos(ang), np.sin(ang)], axis=1)
    verts = quant(np.vstack([centre, rim]), snap)
    order = [0] + list(range(1, k + 1)) + [1]
    tris = [(order[0], order[i], order[i + 1]) for i in range(1, len(order) - 1)]
    return Mesh(verts, C.GL_TRIANGLE_FAN, order, tris, verts[1:])


def strip_mesh(rng: np.random.Generator, snap: bool) -> Mesh:
    """A wavy triangle strip, bottom and top vertices alternating (GL_TRIANGLE_STRIP)."""
    n = int(rng.integers(3, 9))
    cell = 52 / n
    bx = 6 + np.arange(n) * cell + rng.uniform(-0.2, 0.2, n) * cell
    tx = 6 + (np.arange(n) + 0.5) * cell + rng.uniform(-0.2, 0.2, n) * cell
    bottom = np.stack([bx, rng.uniform(6, 26, n)], axis=1)
    top = np.stack([tx, rng.uniform(38, 58, n)], axis=1)
    verts = quant(np.stack([bottom, top], axis=1).reshape(-1, 2), snap)  # b0 t0 b1 t1 ...
    order = list(range(2 * n))
    # Table 2.10 assembly: odd triangles take their first two vertices swapped
    tris = [(i + 1, i, i + 2) if i % 2 else (i, i + 1, i + 2) for i in range(2 * n - 2)]
    outline = np.vstack([verts[0::2], verts[1::2][::-1]])
    return Mesh(verts, C.GL_TRIANGLE_STRIP, order, tris, outline)


MESHES = {"grid": grid_mesh, "fan": fan_mesh, "strip": strip_mesh}


def per_triangle_counts(ctx, mesh: Mesh) -> tuple[np.ndarray, np.ndarray]:
    """Draw each triangle alone (flat colour id_colour(t)) into a cleared
    framebuffer; return how often each pixel was covered and by which triangle."""
    gl = ctx.gl
    set_ortho(gl, ctx.width, ctx.height)
    gl.glShadeModel(C.GL_FLAT)
    counts = np.zeros((ctx.height, ctx.width), dtype=np.int64)
    owner = np.full((ctx.height, ctx.width), -1, dtype=np.int64)
    for t, tri in enumerate(mesh.tris):
        clear(ctx)
        gl.glColor4ub(*id_colour(t))
        draw_arrays(gl, mesh.verts[list(tri)])
        img = read_rgba(ctx)
        cov = img.any(axis=2)
        assert (img[cov] == id_colour(t)).all(), "a flat triangle wrote another colour"
        counts += cov
        owner[cov] = t
    return counts, owner


def tiling_problems(counts: np.ndarray, outline) -> dict[str, int]:
    """Pixels covered twice, pixels of the outline (by the fill rule) left
    uncovered, and pixels outside it that were covered."""
    want = rule_coverage(outline, counts.shape[1], counts.shape[0])
    return {
        "double": int((counts > 1).sum()),
        "gap": int((want & (counts == 0)).sum()),
        "outside": int((~want & (counts > 0)).sum()),
    }


def draw_whole_mesh(ctx, mesh: Mesh) -> np.ndarray:
    """Draw the mesh in one call, flat shaded, with the provoking vertex of
    triangle t coloured id_colour(t); return the image."""
    gl = ctx.gl
    clear(ctx)
    gl.glShadeModel(C.GL_FLAT)
    if mesh.mode == C.GL_TRIANGLES:
        # a list needs its own copy of each vertex: the last one provokes
        verts = mesh.verts[np.ravel(mesh.tris)]
        cols = np.array([id_colour(t) for t in range(len(mesh.tris)) for _ in range(3)], dtype=np.uint8)
        draw_tris(gl, verts, cols)
    else:
        # strips and fans: vertex t + 2 of the sequence provokes triangle t
        verts = mesh.verts[mesh.order]
        cols = np.zeros((len(verts), 4), dtype=np.uint8)
        for t in range(len(verts) - 2):
            cols[t + 2] = id_colour(t)
        draw_tris(gl, verts, cols, mode=mesh.mode)
    return read_rgba(ctx)


# {================================================================
# the fill rule, by hand


def hand_rule(tri, w: int = 8, h: int = 8) -> set[tuple[int, int]]:
    """The fill rule spelled out: centres strictly inside all three edges, or
    on an edge that is left (goes down) or bottom (horizontal, goes right),
    with the vertices taken counter-clockwise."""
    (ax, ay), (bx, by), (cx, cy) = tri
    tri_ccw = tri if (bx - ax) * (cy - ay) - (cx - ax) * (by - ay) > 0 else tri[::-1]
    out = set()
    for j in range(h):
        for i in range(w):
            cx, cy = i + 0.5, j + 0.5
            ok = True
            for k in range(3):
                (px, py), (qx, qy) = tri_ccw[k], tri_ccw[(k + 1) % 3]
                e = (qx - px) * (cy - py) - (cx - px) * (qy - py)  # > 0 inside (ccw)
                left, bottom = qy < py, qy == py and qx > px
                ok = ok and (e > 0 or (e == 0 and (left or bottom)))
            if ok:
                out.add((i, j))
    return out


def covered_set(ctx) -> set[tuple[int, int]]:
    ys, xs = np.nonzero(coverage(ctx))
    return {(int(x), int(y)) for x, y in zip(xs, ys)}


# Worked by hand. (0,0),(4,0),(0,4), counter-clockwise: the edges are the
# bottom (goes right), the hypotenuse (goes up-left: a right edge) and the
# left side (goes down). The six centres with i + j <= 2 are strictly inside;
# the four on the hypotenuse (i + j = 3) belong to the neighbour across it;
# no centre lies on x = 0 or y = 0. Six pixels.
LOWER = [(0, 0), (4, 0), (0, 4)]
LOWER_PIXELS = {(0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (0, 2)}
# The neighbour (4,0),(4,4),(0,4): right side, top (goes left, no centres on
# y = 4) and the hypotenuse going down, a left edge: six centres strictly
# inside (i + j >= 4) plus the four on the hypotenuse. Ten pixels.
UPPER = [(4, 0), (4, 4), (0, 4)]
UPPER_PIXELS = {(1, 3), (2, 2), (3, 1), (2, 3), (3, 2), (3, 3), (0, 3), (1, 2), (2, 1), (3, 0)}
# A square with corners on pixel centres 0.5 .. 4.5 (two triangles): centres
# on its left (x = 0.5) and bottom (y = 0.5) sides are kept, those on its
# right and top sides are not: columns 0..3, rows 0..3.
SQUARE = [(0.5, 0.5), (4.5, 0.5), (4.5, 4.5), (0.5, 4.5)]
SQUARE_PIXELS = {(i, j) for i in range(4) for j in range(4)}
# Two triangles sharing the horizontal edge y = 4.5 from x = 2 to 6. Above:
# the shared edge is its bottom (kept: centres x = 2.5 .. 5.5 of row 4); at
# y = 5.5 it spans x in [2.8, 5.2] (centres 3.5, 4.5); at y = 6.5 [3.6, 4.4]
# holds no centre. Below: the shared edge is its top (not kept); at y = 3.5
# it spans [2.8, 5.2] (centres 3.5, 4.5), at y = 2.5 [3.6, 4.4] none.
ABOVE = [(2, 4.5), (6, 4.5), (4, 7)]
ABOVE_PIXELS = {(2, 4), (3, 4), (4, 4), (5, 4), (3, 5), (4, 5)}
BELOW = [(2, 4.5), (6, 4.5), (4, 2)]
BELOW_PIXELS = {(3, 3), (4, 3)}
# The same pair turned on its side: a shared vertical edge x = 4.5 from
# y = 2 to 6. To its right the edge goes down (a left edge, kept).
RIGHT = [(4.5, 6), (4.5, 2), (7, 4)]
RIGHT_PIXELS = {(4, 2), (4, 3), (4, 4), (4, 5), (5, 3), (5, 4)}
LEFT = [(4.5, 2), (4.5, 6), (2, 4)]
LEFT_PIXELS = {(3, 3), (3, 4)}

HAND_CASES = {
    "lower": ([LOWER], LOWER_PIXELS),
    "upper": ([UPPER], UPPER_PIXELS),
    "square": ([SQUARE[:3], [SQUARE[0], SQUARE[2], SQUARE[3]]], SQUARE_PIXELS),
    "above": ([ABOVE], ABOVE_PIXELS),
    "below": ([BELOW], BELOW_PIXELS),
    "right": ([RIGHT], RIGHT_PIXELS),
    "left": ([LEFT], LEFT_PIXELS),
}


@pytest.mark.parametrize("case", sorted(HAND_CASES))
def test_hand_rule_matches_the_worked_examples(case):
    """The spelled-out rule and the exact model give the hand-counted pixel sets."""
    tris, want = HAND_CASES[case]
    got: set = set()
    for tri in tris:
        got |= hand_rule(tri)
    assert got == want
    ys, xs = np.nonzero(np.any([rule_coverage(t, 8, 8) for t in tris], axis=0))
    assert set(zip(xs.tolist(), ys.tolist())) == want


def draw_case(ctx, tris, reverse: bool = False) -> set[tuple[int, int]]:
    clear(ctx)
    ctx.gl.glColor4ub(255, 255, 255, 255)
    verts = [v for t in tris for v in t]
    draw_tris(ctx.gl, verts[::-1] if reverse else verts)
    return covered_set(ctx)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("case", sorted(HAND_CASES))
@pytest.mark.parametrize("reverse", [False, True], ids=["as-given", "reversed"])
def test_fill_rule_by_hand(numeric, case, reverse):
    """Triangles with vertices on pixel corners and centres cover exactly the
    hand-computed pixels, whichever way they are wound."""
    tris, want = HAND_CASES[case]
    assert draw_case(make_ctx(numeric, 16, 16), tris, reverse) == want


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("flag", [2, 4])
def test_fill_rule_by_hand_fails_under_debug_switches(numeric, flag):
    """The hand checks notice a flipped tie-break (2) and a dropped span end (4)."""
    ctx = make_ctx(numeric, 16, 16)
    ctx.debug(flag)
    got = {case: draw_case(ctx, tris) for case, (tris, _) in HAND_CASES.items()}
    assert got != {case: want for case, (_, want) in HAND_CASES.items()}


@pytest.mark.parametrize("numeric", BUILDS)
@SETTINGS
@given(seed=seeds, persp=st.booleans())
def test_random_triangles_follow_the_rule(numeric, seed, persp):
    """Random triangles cover exactly the pixels of the exact model: under the
    1:1 ortho setup (1/256 grid, some vertices on pixel centres) and under
    glFrustumf (window positions derived in persp_window)."""
    rng = np.random.default_rng(seed)
    ctx = make_ctx(numeric, W, H)
    ctx.gl.glColor4ub(255, 255, 255, 255)
    (set_frustum if persp else set_ortho)(ctx.gl, W, H)
    for _ in range(4):
        if persp:
            obj = random_eye_triangle(rng)
            win = persp_window(obj)
        else:
            obj = win = quant(rng.uniform(1, 63, size=(3, 2)), False)
            k = int(rng.integers(0, 4))
            win[:k] = quant(win[:k], True)
        if area2(*win) == 0:
            continue
        clear(ctx)
        draw_arrays(ctx.gl, obj)
        np.testing.assert_array_equal(coverage(ctx), rule_coverage(win))


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("baseline", [False, True])
@SETTINGS
@given(seed=seeds)
def test_small_triangles_follow_the_rule(numeric, baseline, seed):
    """Triangles a few pixels across, many with vertices on pixel centres or
    on the 1/2-pixel grid (so centres fall exactly on edges), cover exactly
    the pixels of the exact model. The rasterizer tests the centres of small
    bounding boxes (four at a time where AVX2 runs; one by one in the
    baseline instance, ctx.debug(16)) and solves row bounds for larger ones;
    each must give the rule's pixels, ties included."""
    rng = np.random.default_rng(seed)
    ctx = make_ctx(numeric, W, H)
    if baseline:
        ctx.debug(16)
    ctx.gl.glColor4ub(255, 255, 255, 255)
    set_ortho(ctx.gl, W, H)
    for _ in range(12):
        centre = rng.uniform(8, 56, size=2)             # inside the window: no clipping
        size = rng.choice([0.6, 1.5, 3.0, 7.0])
        win = centre + rng.uniform(-size, size, size=(3, 2))
        grid = int(rng.integers(0, 3))
        if grid == 0:
            win = quant(win, False)
        elif grid == 1:
            win = quant(win, True)
        else:
            win = np.round(win * 2) / 2          # pixel corners and centres
        if area2(*win) == 0:
            continue
        clear(ctx)
        draw_arrays(ctx.gl, win)
        np.testing.assert_array_equal(coverage(ctx), rule_coverage(win))


# {================================================================
# watertightness


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("kind", sorted(MESHES))
@SETTINGS
@given(seed=seeds, snap=st.booleans())
def test_meshes_are_watertight(numeric, kind, seed, snap):
    """Triangles sharing edges (grids, fans, strips; subpixel-jittered or on
    pixel centres) cover every pixel of their outline exactly once and nothing
    else; drawing the whole mesh at once gives the same pixels, each in the
    colour of the provoking vertex of the triangle that owns it."""
    mesh = MESHES[kind](np.random.default_rng(seed), snap)
    assume(mesh.valid())
    ctx = make_ctx(numeric, W, H)
    counts, owner = per_triangle_counts(ctx, mesh)
    assert tiling_problems(counts, mesh.outline) == {"double": 0, "gap": 0, "outside": 0}
    img = draw_whole_mesh(ctx, mesh)
    want = np.zeros_like(img)
    for t in range(len(mesh.tris)):
        want[owner == t] = id_colour(t)
    np.testing.assert_array_equal(img, want)


def regular_grid() -> Mesh:
    """A 4x4 grid, no jitter, every vertex on a pixel centre: many centres lie
    on edges, including the outline's."""
    return grid_mesh(np.random.default_rng(5), True, 4, 4, 0.0)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("flag", [2, 4])
def test_watertightness_checker_catches_broken_rasterizers(numeric, flag):
    """With a fill rule whose ties go the other way (2) or spans missing their
    last pixel (4), the coverage checker reports problems it did not report
    before: it can fail."""
    mesh = regular_grid()
    assert mesh.valid()
    ctx = make_ctx(numeric, W, H)
    clean = tiling_problems(per_triangle_counts(ctx, mesh)[0], mesh.outline)
    ctx.debug(flag)
    broken = tiling_problems(per_triangle_counts(ctx, mesh)[0], mesh.outline)
    assert broken != clean and sum(broken.values()) > 0, (clean, broken)
    if flag == 4:
        assert broken["gap"] > clean["gap"]  # interior gaps where spans meet


# {================================================================
# invariance under integer translation (Appendix A)


@pytest.mark.parametrize("numeric", BUILDS)
@SETTINGS
@given(seed=seeds, dx=st.integers(0, 30), dy=st.integers(0, 30))
def test_integer_translation_invariance(numeric, seed, dx, dy):
    """A triangle moved by whole pixels (in its vertices or by glTranslatef)
    covers the same pixels moved by the same amount."""
    rng = np.random.default_rng(seed)
    tri = quant(rng.uniform(1, 31, size=(3, 2)), bool(rng.integers(0, 2)))
    assume(area2(*tri) != 0)
    ctx = make_ctx(numeric, W, H)
    gl = ctx.gl
    gl.glColor4ub(255, 255, 255, 255)
    clear(ctx)
    draw_tris(gl, tri)
    base = coverage(ctx)
    want = np.zeros_like(base)
    want[dy:, dx:] = base[: H - dy, : W - dx]
    assert not base[H - dy:, :].any() and not base[:, W - dx:].any()
    clear(ctx)
    draw_tris(gl, tri + [dx, dy])
    np.testing.assert_array_equal(coverage(ctx), want)
    clear(ctx)
    set_ortho(gl, W, H)
    gl.glTranslatef(float(dx), float(dy), 0.0)
    draw_arrays(gl, tri)
    np.testing.assert_array_equal(coverage(ctx), want)


# {================================================================
# user clip planes: p and -p


def persp_window(eye: np.ndarray, w: int = W, h: int = H) -> np.ndarray:
    """Window positions (on the 1/256 grid) of eye points under set_frustum().

    glFrustumf(-1, 1, -1, 1, 1, 3) gives clip x = x_e, y = y_e, w = -z_e
    exactly in every build. Window x = w/2 * (1 + x_e / -z_e), rounded to the
    1/256 grid. With eye coordinates on the 1/256 grid and |z_e| <= 3, the
    exact value times 256 is a fraction with denominator 2 * 256 |z_e| <= 1536
    that is never a half-integer (its numerator would need 2^14 | 256 |z_e|),
    so it is at least 1/1536 subpixel from a rounding boundary, more than a
    float quotient's error (2^-24 * 2^13 = 2^-11 subpixel): every build rounds
    to the same subpixel.
    """
    x = w / 2 * (1 + eye[:, 0] / -eye[:, 2])
    y = h / 2 * (1 + eye[:, 1] / -eye[:, 2])
    return np.round(np.stack([x, y], axis=1) * SUB) / SUB


def random_eye_triangle(rng: np.random.Generator) -> np.ndarray:
    """An eye-space triangle inside the frustum of set_frustum(), 1/256 grid."""
    z = -rng.uniform(1.1, 2.9, size=3)
    xy = rng.uniform(-0.95, 0.95, size=(3, 2)) * -z[:, None]
    return quant(np.column_stack([xy, z]), False)


def dist_to_boundary(tri: np.ndarray, w: int = W, h: int = H) -> np.ndarray:
    """Distance (pixels) from each pixel centre to the triangle's edges."""
    px = (np.arange(w) + 0.5)[None, :]
    py = (np.arange(h) + 0.5)[:, None]
    best = np.full((h, w), np.inf)
    for k in range(3):
        a, b = tri[k], tri[(k + 1) % 3]
        d = b - a
        t = np.clip(((px - a[0]) * d[0] + (py - a[1]) * d[1]) / (d @ d), 0, 1)
        best = np.minimum(best, np.hypot(px - a[0] - t * d[0], py - a[1] - t * d[1]))
    return best


# The two clipped pieces share their new vertices bit for bit (canonical
# interpolation), so they must be disjoint exactly. Their union differs from
# the unclipped triangle only where a new vertex, rounded to the subpixel
# grid, leaves the original edge: by at most sqrt(2)/512 px from rounding,
# plus, in 16.16, 2^-10 px from clip-space interpolation (clip coordinates
# rounded to 2^-16, times the viewport half-width 32, at most twice through
# x and w for w >= 1). Only centres that close to the triangle's edges may
# change; anywhere else the union must equal the unclipped coverage.
CLIP_BAND = math.sqrt(2) / 512 + 2.0**-10


def clipped_coverages(ctx, draw, plane) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Coverage without clipping, with `plane`, and with its negation."""
    gl = ctx.gl
    out = []
    for eq in (None, plane, [-v for v in plane]):
        clear(ctx)
        if eq is None:
            gl.glDisable(C.GL_CLIP_PLANE0)
        else:
            gl.glClipPlanef(C.GL_CLIP_PLANE0, eq)
            gl.glEnable(C.GL_CLIP_PLANE0)
        draw()
        out.append(coverage(ctx))
    gl.glDisable(C.GL_CLIP_PLANE0)
    return out[0], out[1], out[2]


def check_complementary(full, a, b, window_tri) -> int:
    """Disjoint pieces; union = unclipped except within CLIP_BAND of an edge.
    Returns how many pixels used that allowance."""
    assert not (a & b).any(), "a pixel is covered by both p and -p"
    diff = (a | b) != full
    near = dist_to_boundary(window_tri) <= CLIP_BAND
    assert not (diff & ~near).any(), np.argwhere(diff & ~near)
    return int(diff.sum())


@pytest.mark.parametrize("numeric", BUILDS)
@SETTINGS
@given(seed=seeds)
def test_clip_plane_complementarity_ortho(numeric, seed):
    """Clipping by p and by -p (eye space, 1:1 ortho) splits a triangle into two
    disjoint pieces that together cover what the unclipped triangle covers."""
    rng = np.random.default_rng(seed)
    tri = quant(rng.uniform(2, 62, size=(3, 2)), bool(rng.integers(0, 2)))
    assume(abs(area2(*tri)) > SUB * SUB)
    q = rng.dirichlet([1, 1, 1]) @ tri
    n = rng.normal(size=3)
    plane = [float(n[0]), float(n[1]), float(n[2]), float(-(n[0] * q[0] + n[1] * q[1]))]
    ctx = make_ctx(numeric, W, H)
    ctx.gl.glColor4ub(255, 255, 255, 255)
    set_ortho(ctx.gl, W, H)
    full, a, b = clipped_coverages(ctx, lambda: draw_arrays(ctx.gl, tri), plane)
    used = check_complementary(full, a, b, tri)
    MEASURED["clip band pixels (ortho), max per triangle"] = max(
        used, MEASURED.get("clip band pixels (ortho), max per triangle", 0))


@pytest.mark.parametrize("numeric", BUILDS)
@SETTINGS
@given(seed=seeds)
def test_clip_plane_complementarity_perspective(numeric, seed):
    """The same under glFrustumf, with a random plane in eye space through the triangle."""
    rng = np.random.default_rng(seed)
    eye = random_eye_triangle(rng)
    win = persp_window(eye)
    assume(abs(area2(*win)) > SUB * SUB)
    q = rng.dirichlet([1, 1, 1]) @ eye
    n = rng.normal(size=3)
    plane = [float(n[0]), float(n[1]), float(n[2]), float(-(n @ q))]
    ctx = make_ctx(numeric, W, H)
    ctx.gl.glColor4ub(255, 255, 255, 255)
    set_frustum(ctx.gl, W, H)
    full, a, b = clipped_coverages(ctx, lambda: draw_arrays(ctx.gl, eye), plane)
    used = check_complementary(full, a, b, win)
    MEASURED["clip band pixels (perspective), max per triangle"] = max(
        used, MEASURED.get("clip band pixels (perspective), max per triangle", 0))


# {================================================================
# the three builds agree


@SETTINGS
@given(seed=seeds, persp=st.booleans())
def test_builds_cover_the_same_pixels(seed, persp):
    """Fixed, float and double cover exactly the same pixels
    for random triangles under ortho and perspective projections, and smooth
    colours from random ubyte vertex colours differ by at most 1 per channel
    between fixed and double: the fixed pipeline's colour error (inputs and
    weights rounded at 2^-16 and 2^-30) is far below half a step of 1/255, so
    the two round to the same or adjacent 8-bit values."""
    rng = np.random.default_rng(seed)
    images, covs = {}, {}
    tris = []
    for _ in range(4):
        if persp:
            eye = random_eye_triangle(rng)
            tris.append((eye, persp_window(eye)))
        else:
            tri = quant(rng.uniform(1, 63, size=(3, 2)), bool(rng.integers(0, 2)))
            tris.append((tri, tri))
    cols = [rng.integers(0, 256, size=(3, 4)).astype(np.uint8) for _ in tris]
    for numeric in BUILDS:
        ctx = make_ctx(numeric, W, H)
        gl = ctx.gl
        gl.glShadeModel(C.GL_SMOOTH)
        (set_frustum if persp else set_ortho)(gl, W, H)
        images[numeric], covs[numeric] = [], []
        for (obj, _win), col in zip(tris, cols):
            clear(ctx)
            gl.glColor4ub(255, 255, 255, 255)
            draw_arrays(gl, obj)
            covs[numeric].append(coverage(ctx))
            clear(ctx)
            draw_arrays(gl, obj, col)
            images[numeric].append(read_rgba(ctx).astype(np.int64))
    for i in range(len(tris)):
        want = covs["double"][i]
        for numeric in ("fixed", "float"):
            np.testing.assert_array_equal(covs[numeric][i], want, err_msg=numeric)
        diff = np.abs(images["fixed"][i] - images["double"][i])[want]
        worst = int(diff.max()) if diff.size else 0
        key = f"fixed vs double smooth colour ({'perspective' if persp else 'ortho'})"
        MEASURED[key] = max(worst, MEASURED.get(key, 0))
        assert worst <= 1
        fd = np.abs(images["float"][i] - images["double"][i])[want]
        key = f"float vs double smooth colour ({'perspective' if persp else 'ortho'})"
        MEASURED[key] = max(int(fd.max()) if fd.size else 0, MEASURED.get(key, 0))


# {================================================================
# flat shading and culling


def interior(tri, margin: float = 0.01, w: int = W, h: int = H) -> np.ndarray:
    """Pixels whose centres are inside the triangle by more than `margin` px."""
    tri = np.asarray(tri, dtype=np.float64)
    return (dist_to_boundary(tri, w, h) > margin) & rule_coverage(tri, w, h)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("mode", ["triangles", "strip", "fan"])
def test_flat_shading_uses_the_provoking_vertex(numeric, mode):
    """Table 2.10: flat triangles take the colour of their last vertex (3i+3 in
    lists, i+2 in strips and fans), exactly."""
    rng = np.random.default_rng(11)
    if mode == "triangles":
        verts = np.array([(4, 4), (30, 6), (8, 30), (34, 34), (60, 36), (40, 60)], dtype=float)
        glmode, tris = C.GL_TRIANGLES, [(0, 1, 2, 2), (3, 4, 5, 5)]
    elif mode == "strip":
        verts = np.array([(4, 4), (10, 40), (20, 6), (30, 44), (40, 8), (50, 50), (60, 10)], dtype=float)
        glmode, tris = C.GL_TRIANGLE_STRIP, [(i, i + 1, i + 2, i + 2) for i in range(5)]
    else:
        verts = np.array([(32, 32), (60, 34), (50, 58), (20, 60), (4, 40), (10, 6), (44, 4)], dtype=float)
        glmode, tris = C.GL_TRIANGLE_FAN, [(0, i, i + 1, i + 1) for i in range(1, 6)]
    cols = rng.integers(1, 256, size=(len(verts), 4)).astype(np.uint8)
    ctx = make_ctx(numeric, W, H)
    ctx.gl.glShadeModel(C.GL_FLAT)
    clear(ctx)
    draw_tris(ctx.gl, verts, cols, mode=glmode)
    img = read_rgba(ctx)
    for a, b, c, pv in tris:
        inside = interior(verts[[a, b, c]])
        assert inside.sum() > 10
        assert (img[inside] == cols[pv]).all(), (a, b, c)


CCW_TRI = [(4, 4), (28, 4), (4, 28)]
CW_TRI = [(36, 36), (36, 60), (60, 36)]


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("front", ["CCW", "CW"])
@pytest.mark.parametrize("cull", [None, "FRONT", "BACK", "FRONT_AND_BACK"])
def test_culling(numeric, front, cull):
    """§3.5.1: facing comes from the window-space winding and glFrontFace;
    glCullFace discards front, back or both."""
    ctx = make_ctx(numeric, W, H)
    gl = ctx.gl
    gl.glFrontFace(getattr(C, f"GL_{front}"))
    if cull is None:
        gl.glDisable(C.GL_CULL_FACE)
    else:
        gl.glEnable(C.GL_CULL_FACE)
        gl.glCullFace(getattr(C, f"GL_{cull}"))
    gl.glColor4ub(255, 255, 255, 255)
    clear(ctx)
    draw_tris(gl, CCW_TRI + CW_TRI)
    cov = coverage(ctx)
    ccw_front = front == "CCW"
    for tri, is_front in ((CCW_TRI, ccw_front), (CW_TRI, not ccw_front)):
        culled = (cull == "FRONT_AND_BACK" or (cull == "FRONT" and is_front)
                  or (cull == "BACK" and not is_front))
        want = np.zeros((H, W), dtype=bool) if culled else rule_coverage(tri)
        mask = rule_coverage(tri)
        np.testing.assert_array_equal(cov & mask, want, err_msg=str(tri))


@pytest.mark.parametrize("numeric", BUILDS)
def test_culling_uses_window_winding(numeric):
    """A projection that mirrors x turns a counter-clockwise object triangle
    clockwise on screen, so culling BACK (front CCW) removes it."""
    ctx = make_ctx(numeric, W, H)
    gl = ctx.gl
    gl.glEnable(C.GL_CULL_FACE)
    gl.glCullFace(C.GL_BACK)
    gl.glColor4ub(255, 255, 255, 255)
    clear(ctx)
    set_ortho(gl, W, H)
    draw_arrays(gl, np.array(CCW_TRI, dtype=float))
    assert coverage(ctx).any()
    clear(ctx)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(float(W), 0.0, 0.0, float(H), -1.0, 1.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    draw_arrays(gl, np.array(CCW_TRI, dtype=float))
    assert not coverage(ctx).any()
