"""Matrices: modes, stacks and the matrix commands (ES 1.1 §2.10.2), and the
transformation of vertices to window coordinates (§2.10, §2.10.1).

Expected matrices are built with numpy from the formulas of §2.10.2. Queries
return the matrix as the application built it (double arithmetic) in every
numeric build, read back through glGetFloatv, i.e. rounded to float32.
Tolerances:

* QUERY_RTOL / QUERY_ATOL: two float32 ulps relative to the matrix's largest
  entry. The query is float32; the core and numpy may order double sums
  differently, which can move a float32 rounding by one ulp.
* Matrices built only from dyadic values (LoadMatrix, Translate, Scale,
  quarter-turn rotations, Frustum/Ortho with power-of-two spans) must match
  exactly.
* Rendered positions: see WINDOW_MARGIN.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import gles
from gles import gl as G

BUILDS = ("fixed", "float", "double")

QUERY_RTOL = 2.0**-22
QUERY_ATOL = 2.0**-22

# A pixel is checked only when its centre lies farther than this (in pixels)
# from every edge of the predicted window-space triangle. Window x, y snap to
# 1/256 pixel (error <= 1/512); the fixed build's 16.16 matrices and sin/cos
# add well under 1/100 pixel at these sizes. 1/16 pixel leaves a wide margin
# while still pinning every vertex to a small fraction of a pixel.
WINDOW_MARGIN = 1.0 / 16.0


def make(numeric: str = "double", w: int = 8, h: int = 8) -> gles.Context:
    return gles.Context(w, h, numeric=numeric, depth=0, stencil=0)


def gl_of(m: np.ndarray) -> list[float]:
    """A numpy 4x4 (row-major maths) as GL's column-major 16 values."""
    return [float(v) for v in np.asarray(m, dtype=np.float64).flatten(order="F")]


def queried(g, pname: int) -> np.ndarray:
    """A matrix query as a numpy 4x4 (float64 of the float32 answer)."""
    return np.asarray(g.glGetFloatv(pname), dtype=np.float64).reshape(4, 4).T


def assert_matrix(got: np.ndarray, want: np.ndarray, exact: bool = False) -> None:
    want32 = np.asarray(want, dtype=np.float64).astype(np.float32).astype(np.float64)
    if exact:
        np.testing.assert_array_equal(got, want32)
    else:
        scale = max(1.0, float(np.max(np.abs(want))))
        np.testing.assert_allclose(got, want, rtol=QUERY_RTOL, atol=QUERY_ATOL * scale)


def translate(x: float, y: float, z: float) -> np.ndarray:
    m = np.eye(4)
    m[:3, 3] = (x, y, z)
    return m


def scale(x: float, y: float, z: float) -> np.ndarray:
    return np.diag([x, y, z, 1.0])


def rotate(angle: float, x: float, y: float, z: float, sc: tuple[float, float] | None = None) -> np.ndarray:
    """§2.10.2: R = uu^T + cos(a)(I - uu^T) + sin(a) S; `sc` gives exact (sin, cos)."""
    u = np.array([x, y, z], dtype=np.float64)
    u = u / np.linalg.norm(u)
    s, c = sc if sc is not None else (math.sin(math.radians(angle)), math.cos(math.radians(angle)))
    S = np.array([[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]])
    uu = np.outer(u, u)
    m = np.eye(4)
    m[:3, :3] = uu + c * (np.eye(3) - uu) + s * S
    return m


def frustum(left, r, b, t, n, f) -> np.ndarray:
    l = left  # noqa: E741 - the spec's name
    return np.array([
        [2 * n / (r - l), 0, (r + l) / (r - l), 0],
        [0, 2 * n / (t - b), (t + b) / (t - b), 0],
        [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)],
        [0, 0, -1, 0],
    ], dtype=np.float64)


def ortho(left, r, b, t, n, f) -> np.ndarray:
    l = left  # noqa: E741 - the spec's name
    return np.array([
        [2 / (r - l), 0, 0, -(r + l) / (r - l)],
        [0, 2 / (t - b), 0, -(t + b) / (t - b)],
        [0, 0, -2 / (f - n), -(f + n) / (f - n)],
        [0, 0, 0, 1],
    ], dtype=np.float64)


def fx(v: float) -> int:
    """16.16 of a value that is exactly representable."""
    k = v * 65536
    assert k == int(k)
    return int(k)


# {====================================================================
# modes, load, mult


@pytest.mark.parametrize("numeric", BUILDS)
def test_initial_state(numeric):
    """Every matrix starts as the identity, mode MODELVIEW, each stack depth 1 (§2.10.2)."""
    g = make(numeric).gl
    assert g.glGetIntegerv(G.GL_MATRIX_MODE) == G.GL_MODELVIEW
    for pname in (G.GL_MODELVIEW_MATRIX, G.GL_PROJECTION_MATRIX, G.GL_TEXTURE_MATRIX):
        assert_matrix(queried(g, pname), np.eye(4), exact=True)
    for pname in (G.GL_MODELVIEW_STACK_DEPTH, G.GL_PROJECTION_STACK_DEPTH, G.GL_TEXTURE_STACK_DEPTH):
        assert g.glGetIntegerv(pname) == 1
    assert g.glGetError() == G.GL_NO_ERROR


@pytest.mark.parametrize("numeric", BUILDS)
def test_matrix_mode_selects_the_stack(numeric):
    """MatrixMode directs commands to the model-view, projection or texture matrix."""
    g = make(numeric).gl
    g.glMatrixMode(G.GL_PROJECTION)
    assert g.glGetIntegerv(G.GL_MATRIX_MODE) == G.GL_PROJECTION
    g.glTranslatef(1, 2, 3)
    g.glMatrixMode(G.GL_TEXTURE)
    assert g.glGetIntegerv(G.GL_MATRIX_MODE) == G.GL_TEXTURE
    g.glScalef(2, 4, 8)
    g.glMatrixMode(G.GL_MODELVIEW)
    g.glTranslatef(-5, 0, 0.5)
    assert_matrix(queried(g, G.GL_PROJECTION_MATRIX), translate(1, 2, 3), exact=True)
    assert_matrix(queried(g, G.GL_TEXTURE_MATRIX), scale(2, 4, 8), exact=True)
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), translate(-5, 0, 0.5), exact=True)
    assert g.glGetError() == G.GL_NO_ERROR


@pytest.mark.parametrize("numeric", BUILDS)
def test_load_and_mult_are_column_major(numeric):
    """LoadMatrix reads column-major; MultMatrix gives C' = C . M (§2.10.2); LoadIdentity resets."""
    rng = np.random.default_rng(7)
    a = rng.integers(-64, 64, (4, 4)) / 8.0  # dyadic: every product below is exact
    b = rng.integers(-64, 64, (4, 4)) / 8.0
    g = make(numeric).gl
    g.glLoadMatrixf(gl_of(a))
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), a, exact=True)
    # the query is column-major, 4 to a row (as PyOpenGL): [3, 0] is row 0, column 3
    assert g.glGetFloatv(G.GL_MODELVIEW_MATRIX)[3, 0] == a[0, 3]
    g.glMultMatrixf(gl_of(b))
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), a @ b, exact=True)
    g.glLoadIdentity()
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), np.eye(4), exact=True)
    assert g.glGetError() == G.GL_NO_ERROR


@pytest.mark.parametrize("numeric", BUILDS)
def test_translate_scale_exact(numeric):
    """Translate and Scale multiply the spec's matrices on the right, exactly for dyadic values."""
    g = make(numeric).gl
    g.glTranslatef(1.5, -2.25, 3.0)
    g.glScalef(2.0, 0.5, -4.0)
    g.glTranslatef(-0.125, 8.0, 0.75)
    want = translate(1.5, -2.25, 3.0) @ scale(2.0, 0.5, -4.0) @ translate(-0.125, 8.0, 0.75)
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), want, exact=True)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("angle, sc", [(90.0, (1.0, 0.0)), (180.0, (0.0, -1.0)), (270.0, (-1.0, 0.0)),
                                       (-90.0, (-1.0, 0.0)), (450.0, (1.0, 0.0))])
@pytest.mark.parametrize("axis", [(0, 0, 1), (1, 0, 0), (0, 1, 0), (0, 0, -3)])
def test_rotate_quarter_turns_exact(numeric, angle, sc, axis):
    """Quarter-turn rotations about coordinate axes are exact (sin and cos are 0, +-1)."""
    g = make(numeric).gl
    g.glRotatef(angle, *axis)
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), rotate(angle, *axis, sc=sc), exact=True)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("angle, axis", [(30.0, (1, 2, 3)), (-73.5, (0.2, -1, 0.4)), (123.0, (0, 0, 5)),
                                         (400.0, (-1, -1, 1)), (1.0, (3, 0, 4))])
def test_rotate_general(numeric, angle, axis):
    """Rotate matches R = uu^T + cos(I - uu^T) + sin S with u the normalised axis."""
    g = make(numeric).gl
    g.glTranslatef(0.5, 0.25, -1.0)
    g.glRotatef(angle, *axis)
    want = translate(0.5, 0.25, -1.0) @ rotate(angle, *axis)
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), want)
    # a rotation is orthonormal with determinant 1
    r = queried(g, G.GL_MODELVIEW_MATRIX)[:3, :3]
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-6)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("args", [(-1, 1, -1, 1, 1, 9), (-2, 6, -1, 3, 0.5, 100), (1, 3, 2, 6, 2, 10)])
def test_frustum(numeric, args):
    """Frustum multiplies the §2.10.2 perspective matrix onto the current one."""
    g = make(numeric).gl
    g.glMatrixMode(G.GL_PROJECTION)
    g.glScalef(2.0, 2.0, 1.0)
    g.glFrustumf(*args)
    assert_matrix(queried(g, G.GL_PROJECTION_MATRIX), scale(2, 2, 1) @ frustum(*args))
    assert g.glGetError() == G.GL_NO_ERROR


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("args", [(-1, 1, -1, 1, -1, 1), (0, 64, 0, 32, -8, 8), (-3, 5, 7, -1, 2, -6),
                                  (10, 20, -5, 5, 0.1, 1000)])
def test_ortho(numeric, args):
    """Ortho multiplies the §2.10.2 parallel projection onto the current one (n, f may be negative)."""
    g = make(numeric).gl
    g.glMatrixMode(G.GL_PROJECTION)
    g.glTranslatef(0.5, 0.0, 0.0)
    g.glOrthof(*args)
    assert_matrix(queried(g, G.GL_PROJECTION_MATRIX), translate(0.5, 0, 0) @ ortho(*args))
    assert g.glGetError() == G.GL_NO_ERROR


def test_frustum_and_ortho_exact_for_power_of_two_spans():
    """With power-of-two spans every entry is dyadic, so the query is exact."""
    g = make("fixed").gl
    g.glMatrixMode(G.GL_PROJECTION)
    g.glFrustumf(-2, 2, -1, 1, 1, 3)
    assert_matrix(queried(g, G.GL_PROJECTION_MATRIX), frustum(-2, 2, -1, 1, 1, 3), exact=True)
    g.glLoadIdentity()
    g.glOrthof(0, 64, 0, 32, -8, 8)
    assert_matrix(queried(g, G.GL_PROJECTION_MATRIX), ortho(0, 64, 0, 32, -8, 8), exact=True)


def _sequence(g) -> None:
    g.glMatrixMode(G.GL_PROJECTION)
    g.glFrustumf(-0.7, 0.9, -0.4, 0.6, 0.3, 17.0)
    g.glMatrixMode(G.GL_MODELVIEW)
    g.glTranslatef(0.1, -0.3, -2.7)
    g.glRotatef(33.3, 0.3, 1.0, -0.2)
    g.glScalef(1.1, 0.9, 1.3)
    g.glMultMatrixf([1, 0.1, 0, 0, 0.2, 1, 0, 0, 0, 0.3, 1, 0, 0.01, 0.02, 0.03, 1])


def test_queries_return_the_double_form_in_every_build():
    """The same commands give bit-identical matrix queries in the fixed, float and double builds."""
    answers = []
    for numeric in BUILDS:
        g = make(numeric).gl
        _sequence(g)
        answers.append((g.glGetFloatv(G.GL_MODELVIEW_MATRIX), g.glGetFloatv(G.GL_PROJECTION_MATRIX),
                        g.glGetFixedv(G.GL_MODELVIEW_MATRIX)))
    for other in answers[1:]:
        for a, b in zip(answers[0], other):
            np.testing.assert_array_equal(a, b)
    want = (translate(0.1, -0.3, -2.7) @ rotate(33.3, 0.3, 1.0, -0.2) @ scale(1.1, 0.9, 1.3)
            @ np.array([1, 0.1, 0, 0, 0.2, 1, 0, 0, 0, 0.3, 1, 0, 0.01, 0.02, 0.03, 1.0]).reshape(4, 4).T)
    assert_matrix(answers[0][0].astype(np.float64).reshape(4, 4).T, want)
    # GetFixedv: each entry times 2^16, rounded to nearest (§6.1.2)
    np.testing.assert_array_equal(answers[0][2].reshape(16), np.floor(want.flatten(order="F") * 65536 + 0.5))


# {====================================================================
# x forms


def _x_and_f(numeric):
    cx, cf = make(numeric), make(numeric)
    return cx.gl, cf.gl, cx, cf


@pytest.mark.parametrize("numeric", BUILDS)
def test_x_forms_equal_f_forms(numeric):
    """For values exactly representable in 16.16 every x command equals its f command."""
    gx, gf, cx, cf = _x_and_f(numeric)
    m = [1.5, -0.25, 0, 0, 0.5, 2, 0, 0, 0, 0, 1, 0, 3.25, -1, 0.125, 1]
    n = [1, 0, 0.5, 0, 0, 1, 0, 0, 0.25, 0, 1, 0, 0, 0, 0, 1]
    gx.glMatrixMode(G.GL_PROJECTION)
    gf.glMatrixMode(G.GL_PROJECTION)
    gx.glFrustumx(*map(fx, (-1.5, 1.25, -1, 0.75, 0.5, 20)))
    gf.glFrustumf(-1.5, 1.25, -1, 0.75, 0.5, 20)
    gx.glMatrixMode(G.GL_TEXTURE)
    gf.glMatrixMode(G.GL_TEXTURE)
    gx.glOrthox(*map(fx, (-2, 3.5, -1, 1, -4, 4)))
    gf.glOrthof(-2, 3.5, -1, 1, -4, 4)
    gx.glMatrixMode(G.GL_MODELVIEW)
    gf.glMatrixMode(G.GL_MODELVIEW)
    gx.glLoadMatrixx([fx(v) for v in m])
    gf.glLoadMatrixf(m)
    gx.glMultMatrixx([fx(v) for v in n])
    gf.glMultMatrixf(n)
    gx.glTranslatex(fx(0.5), fx(-1.25), fx(-3))
    gf.glTranslatef(0.5, -1.25, -3)
    gx.glRotatex(fx(37.5), fx(1), fx(0.5), fx(-2))
    gf.glRotatef(37.5, 1, 0.5, -2)
    gx.glScalex(fx(1.5), fx(0.75), fx(2))
    gf.glScalef(1.5, 0.75, 2)
    for pname in (G.GL_MODELVIEW_MATRIX, G.GL_PROJECTION_MATRIX, G.GL_TEXTURE_MATRIX):
        np.testing.assert_array_equal(gx.glGetFloatv(pname), gf.glGetFloatv(pname))
        np.testing.assert_array_equal(gx.glGetFixedv(pname), gf.glGetFixedv(pname))
    # and both forms transform vertices identically
    for g in (gx, gf):
        g.glEnableClientState(G.GL_VERTEX_ARRAY)
        g.glVertexPointer(3, G.GL_FLOAT, 0, np.array([-1, -1, 0, 1, -1, 0.5, 0, 1, -0.5], np.float32))
        g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    np.testing.assert_array_equal(cx.color_buffer(), cf.color_buffer())
    assert gx.glGetError() == gf.glGetError() == G.GL_NO_ERROR


# {====================================================================
# stacks

STACKS = [
    (G.GL_MODELVIEW, G.GL_MODELVIEW_MATRIX, G.GL_MODELVIEW_STACK_DEPTH,
     G.GL_MAX_MODELVIEW_STACK_DEPTH, 32),
    (G.GL_PROJECTION, G.GL_PROJECTION_MATRIX, G.GL_PROJECTION_STACK_DEPTH,
     G.GL_MAX_PROJECTION_STACK_DEPTH, 4),
    (G.GL_TEXTURE, G.GL_TEXTURE_MATRIX, G.GL_TEXTURE_STACK_DEPTH,
     G.GL_MAX_TEXTURE_STACK_DEPTH, 4),
]


def _marker(k: int) -> np.ndarray:
    return translate(k, -k, 0.5 * k) @ scale(k + 1, 1, 1)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("mode, mpname, dpname, maxpname, depth", STACKS)
def test_stack_depth_overflow_underflow(numeric, mode, mpname, dpname, maxpname, depth):
    """Stack depths are 32/4/4; overflow and underflow are errors that change nothing (§2.10.2)."""
    g = make(numeric).gl
    assert g.glGetIntegerv(maxpname) == depth
    g.glMatrixMode(mode)
    g.glLoadMatrixf(gl_of(_marker(0)))
    for k in range(1, depth):
        g.glPushMatrix()
        assert g.glGetIntegerv(dpname) == k + 1
        # Push duplicates the top
        assert_matrix(queried(g, mpname), _marker(k - 1), exact=True)
        g.glLoadMatrixf(gl_of(_marker(k)))
    assert g.glGetError() == G.GL_NO_ERROR
    g.glPushMatrix()
    assert g.glGetError() == G.GL_STACK_OVERFLOW
    assert g.glGetIntegerv(dpname) == depth
    assert_matrix(queried(g, mpname), _marker(depth - 1), exact=True)
    # the entry below the top is untouched too
    g.glPopMatrix()
    assert_matrix(queried(g, mpname), _marker(depth - 2), exact=True)
    for k in range(depth - 2, 0, -1):
        g.glPopMatrix()
        assert g.glGetIntegerv(dpname) == k
        assert_matrix(queried(g, mpname), _marker(k - 1), exact=True)
    assert g.glGetError() == G.GL_NO_ERROR
    g.glPopMatrix()
    assert g.glGetError() == G.GL_STACK_UNDERFLOW
    assert g.glGetIntegerv(dpname) == 1
    assert_matrix(queried(g, mpname), _marker(0), exact=True)


def test_push_pop_restores_rendering_state():
    """A Pop restores the matrix used for drawing, not only the queried one."""
    ctx = make("fixed", 8, 8)
    g = ctx.gl
    g.glClear(G.GL_COLOR_BUFFER_BIT)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, np.array([-1, -1, 0, -1, -1, 0], np.float32))
    g.glPushMatrix()
    g.glTranslatef(1, 1, 0)  # moves the triangle to the top-right quadrant
    g.glPopMatrix()
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    px = g.glReadPixels(0, 0, 8, 8, G.GL_RGBA, G.GL_UNSIGNED_BYTE)
    assert px[0, 0, 0] == 255 and px[7, 7, 0] == 0


@pytest.mark.parametrize("numeric", BUILDS)
def test_texture_matrices_per_unit(numeric):
    """Each texture unit has its own texture matrix stack, selected by ActiveTexture (§2.10.2)."""
    g = make(numeric).gl
    units = g.glGetIntegerv(G.GL_MAX_TEXTURE_UNITS)
    assert units >= 2
    g.glMatrixMode(G.GL_TEXTURE)
    for u in range(units):
        g.glActiveTexture(G.GL_TEXTURE0 + u)
        g.glTranslatef(u + 1, 0, 0)
        for _ in range(u % 3):
            g.glPushMatrix()
    for u in range(units):
        g.glActiveTexture(G.GL_TEXTURE0 + u)
        assert_matrix(queried(g, G.GL_TEXTURE_MATRIX), translate(u + 1, 0, 0), exact=True)
        assert g.glGetIntegerv(G.GL_TEXTURE_STACK_DEPTH) == 1 + u % 3
    # ActiveTexture while in TEXTURE mode moves later commands to the new unit
    g.glActiveTexture(G.GL_TEXTURE1)
    g.glScalef(2, 2, 2)
    g.glActiveTexture(G.GL_TEXTURE0)
    assert_matrix(queried(g, G.GL_TEXTURE_MATRIX), translate(1, 0, 0), exact=True)
    g.glActiveTexture(G.GL_TEXTURE1)
    assert_matrix(queried(g, G.GL_TEXTURE_MATRIX), translate(2, 0, 0) @ scale(2, 2, 2), exact=True)
    # overflow is per unit: unit 0 has depth 1 and three free slots
    g.glActiveTexture(G.GL_TEXTURE0)
    for _ in range(3):
        g.glPushMatrix()
    assert g.glGetError() == G.GL_NO_ERROR
    g.glPushMatrix()
    assert g.glGetError() == G.GL_STACK_OVERFLOW
    # the model-view and projection matrices were never touched
    assert_matrix(queried(g, G.GL_MODELVIEW_MATRIX), np.eye(4), exact=True)
    assert_matrix(queried(g, G.GL_PROJECTION_MATRIX), np.eye(4), exact=True)


# {====================================================================
# Frustum / Ortho errors

FRUSTUM_BAD = [
    ("n = 0", (-1, 1, -1, 1, 0, 10)),
    ("n < 0", (-1, 1, -1, 1, -1, 10)),
    ("f = 0", (-1, 1, -1, 1, 1, 0)),
    ("f < 0", (-1, 1, -1, 1, 1, -10)),
    ("l = r", (1, 1, -1, 1, 1, 10)),
    ("b = t", (-1, 1, 2, 2, 1, 10)),
    ("n = f", (-1, 1, -1, 1, 3, 3)),
]
ORTHO_BAD = [
    ("l = r", (2, 2, -1, 1, -1, 1)),
    ("b = t", (-1, 1, 0, 0, -1, 1)),
    ("n = f", (-1, 1, -1, 1, 5, 5)),
]


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("form", ["f", "x"])
@pytest.mark.parametrize("cmd, why, args", [("Frustum", w, a) for w, a in FRUSTUM_BAD]
                         + [("Ortho", w, a) for w, a in ORTHO_BAD])
def test_frustum_ortho_invalid_value(numeric, form, cmd, why, args):
    """Frustum/Ortho with a degenerate volume give INVALID_VALUE and leave the matrix alone (§2.10.2)."""
    g = make(numeric).gl
    g.glMatrixMode(G.GL_PROJECTION)
    g.glLoadMatrixf(gl_of(_marker(3)))
    if form == "f":
        getattr(g, f"gl{cmd}f")(*args)
    else:
        getattr(g, f"gl{cmd}x")(*[fx(v) for v in args])
    assert g.glGetError() == G.GL_INVALID_VALUE, why
    assert g.glGetError() == G.GL_NO_ERROR
    assert_matrix(queried(g, G.GL_PROJECTION_MATRIX), _marker(3), exact=True)
    assert g.glGetIntegerv(G.GL_PROJECTION_STACK_DEPTH) == 1


# {====================================================================
# vertices through the whole transform


def window_of(obj: np.ndarray, mvp: np.ndarray, viewport: tuple[int, int, int, int]) -> np.ndarray:
    """Window x, y of object points (n, 4): clip = P M v, NDC = clip / w, then §2.10.1."""
    clip = obj @ mvp.T
    ndc = clip[:, :3] / clip[:, 3:4]
    x, y, w, h = viewport
    return np.stack([(w / 2) * ndc[:, 0] + (x + w / 2), (h / 2) * ndc[:, 1] + (y + h / 2)], axis=1)


def coverage(tris: list[np.ndarray], width: int, height: int, margin: float,
             rect: tuple[int, int, int, int] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(must, must_not) masks, rows bottom first: pixel centres inside some
    triangle by more than `margin` pixels, and outside every one by more.
    `rect` (x, y, w, h) is the viewport: clipping to the view volume (§2.11)
    keeps fragments inside it."""
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    must = np.zeros((height, width), bool)
    must_not = np.ones((height, width), bool)
    if rect is not None:
        x0, y0, w, h = rect
        dist = np.minimum.reduce([xs - x0, x0 + w - xs, ys - y0, y0 + h - ys])  # > 0 inside
        in_rect, out_rect = dist > margin, dist < -margin
    else:
        in_rect, out_rect = np.ones_like(must), np.zeros_like(must)
    for t in tris:
        t = np.asarray(t, dtype=np.float64)
        area = (t[1, 0] - t[0, 0]) * (t[2, 1] - t[0, 1]) - (t[2, 0] - t[0, 0]) * (t[1, 1] - t[0, 1])
        if area == 0:
            continue
        if area < 0:
            t = t[[0, 2, 1]]
        inside = np.ones_like(must)
        outside = np.zeros_like(must)
        for i in range(3):
            p, q = t[i], t[(i + 1) % 3]
            e = q - p
            d = (e[0] * (ys - p[1]) - e[1] * (xs - p[0])) / math.hypot(*e)  # > 0 inside
            inside &= d > margin
            outside |= d < -margin
        must |= inside
        must_not &= outside
    return must & in_rect, must_not | out_rect


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("vp", [(6, 3, 52, 40), (0, 0, 64, 48), (-20, -9, 90, 70), (17, 11, 33, 29)])
@pytest.mark.parametrize("angle, axis", [(30.0, (1.0, 2.0, 3.0)), (-135.5, (0.0, 0.0, 1.0)),
                                         (400.0, (1.0, -1.0, 0.5))])
def test_transform_lands_where_numpy_predicts(numeric, vp, angle, axis):
    """Translate+Rotate+Scale under a perspective Frustum and a viewport (inside the window,
    the window itself, reaching past it, small) put each vertex where numpy's P.M.v,
    perspective division and the §2.10.1 viewport map predict."""
    W, H = 64, 48
    ctx = gles.Context(W, H, numeric=numeric, depth=0, stencil=0)
    g = ctx.gl
    g.glClear(G.GL_COLOR_BUFFER_BIT)  # to (0, 0, 0, 0)
    g.glViewport(*vp)
    g.glMatrixMode(G.GL_PROJECTION)
    g.glFrustumf(-0.8, 0.6, -0.5, 0.7, 1.0, 20.0)
    g.glMatrixMode(G.GL_MODELVIEW)
    g.glTranslatef(0.3, -0.2, -4.0)
    g.glRotatef(angle, *axis)
    g.glScalef(1.5, 0.8, 1.2)
    mvp = frustum(-0.8, 0.6, -0.5, 0.7, 1.0, 20.0) @ translate(0.3, -0.2, -4.0) @ rotate(angle, *axis) \
        @ scale(1.5, 0.8, 1.2)
    # a large triangle, partly clipped by the view volume (red), then a small one a few
    # pixels across near the object origin (green), drawn over it
    big = np.array([[-2.2, -1.8, 0.3, 1], [2.0, -1.2, -0.4, 1], [-0.4, 2.3, 0.5, 1]])
    p = np.array([0.1, 0.15, 0.05, 1.0])
    small = np.array([p + [0.25, 0, 0, 0], p + [-0.15, 0.25, 0.05, 0], p + [-0.1, -0.25, -0.05, 0]])
    obj = np.concatenate([big, small]).astype(np.float32)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(4, G.GL_FLOAT, 0, obj)
    g.glColor4ub(255, 0, 0, 255)
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    g.glColor4ub(0, 255, 0, 255)
    g.glDrawArrays(G.GL_TRIANGLES, 3, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    win = window_of(obj.astype(np.float64), mvp, vp)
    big_in, big_out = coverage([win[:3]], W, H, WINDOW_MARGIN, vp)
    small_in, small_out = coverage([win[3:]], W, H, WINDOW_MARGIN, vp)
    assert big_in.sum() > 100 and (big_out & small_out).sum() > 500
    # the small triangle covers only a few pixels: its corners are pinned closely
    assert 1 <= small_in.sum() <= 40
    px = g.glReadPixels(0, 0, W, H, G.GL_RGBA, G.GL_UNSIGNED_BYTE)[..., :3]
    red, green, black = [255, 0, 0], [0, 255, 0], [0, 0, 0]
    assert (px[small_in] == green).all()
    assert (px[big_in & small_out] == red).all()
    assert (px[big_out & small_out] == black).all()


@pytest.mark.parametrize("numeric", BUILDS)
def test_w_divides(numeric):
    """A homogeneous vertex (x, y, z, w) lands at (x/w, y/w) after the identity transform."""
    W = H = 16
    ctx = gles.Context(W, H, numeric=numeric, depth=0, stencil=0)
    g = ctx.gl
    g.glClear(G.GL_COLOR_BUFFER_BIT)
    tri = np.array([[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]], dtype=np.float64)
    verts = (tri * np.array([[4.0], [2.5], [0.5]])).astype(np.float32)  # scaled by w: same points
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(4, G.GL_FLOAT, 0, verts)
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    win = window_of(verts.astype(np.float64), np.eye(4), (0, 0, W, H))
    np.testing.assert_allclose(win, [[0, 0], [16, 0], [0, 16]])
    must, must_not = coverage([win], W, H, 0.0)
    lit = g.glReadPixels(0, 0, W, H, G.GL_RGBA, G.GL_UNSIGNED_BYTE)[..., 0] == 255
    assert np.array_equal(lit & (must | must_not), must)
    assert must.sum() == 120  # i + j <= 14 for i, j in 0..15 (the diagonal's centres are skipped)
