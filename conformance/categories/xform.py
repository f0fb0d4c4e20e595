"""Transformations: matrix stacks, the matrices of 2.10.2, the viewport, homogeneous
vertices and buffer objects.

Categories MatrixStack, XForm, XFormMix, XFormViewport, XFormHomogenous and
BufferObject (spec sections 2.8-2.10). Expected window positions are the
spec's formulas evaluated in float64 from the exact values the x commands
were given; coverage follows the point-sampling rule of section 3.5.1 with a
small margin around edges where positions are inexact (see ``geometry``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..harness import TestContext, conformance_test
from .geometry import (
    BLACK,
    MARGIN,
    ONE,
    WHITE,
    Pipe,
    coverage,
    draw_one,
    expect_coverage,
    first,
    fx,
    gl_frustum,
    gl_matrix,
    gl_ortho,
    gl_rotate,
    gl_scale,
    gl_translate,
    matches,
    q16,
    rotate,
    scale,
    signed_area,
    translate,
)

# {============================================================
# helpers


def _check_scene(t: TestContext, pipe: Pipe, tris: list, where: str, *, size: int = 3,
                 margin: float = MARGIN) -> np.ndarray:
    """Draw `tris` (object coordinates) as one GL_TRIANGLES call in white and
    compare with the coverage `pipe` predicts."""
    verts = np.concatenate([np.asarray(tr, dtype=np.float64)[:, :size] for tr in tris])
    img = draw_one(t, t.gl.GL_TRIANGLES, verts, size=size)
    polys = [pipe.polygon(tr) for tr in tris]
    inside, either = coverage(polys, t.width, t.height, margin)
    if not inside.any():
        t.fail(f"test bug: {where}: nothing is expected to be drawn")
    return expect_coverage(t, img, inside, either, WHITE, where)


def _unproject(pipe: Pipe, win: np.ndarray, zd: np.ndarray) -> np.ndarray:
    """Object coordinates (w = 1) that `pipe` maps to window x, y `win` and NDC depth `zd`,
    rounded to 16.16 (the values that will be drawn)."""
    x, y, w, h = pipe.viewport
    ndc = np.stack([(win[:, 0] - x - w / 2) * 2 / w, (win[:, 1] - y - h / 2) * 2 / h, zd,
                    np.ones(len(win))], axis=1)
    obj = ndc @ np.linalg.inv(pipe.proj @ pipe.mv).T
    if (obj[:, 3] <= 0).any():
        raise AssertionError("unprojected point behind the eye")
    return q16(obj[:, :3] / obj[:, 3:4])


def _window_tris(rng: np.random.Generator, n: int, lo: float = 2.0, hi: float = 62.0) -> list[np.ndarray]:
    out = []
    while len(out) < n:
        tri = np.round(rng.uniform(lo, hi, size=(3, 2)) * 16) / 16
        if abs(signed_area(tri)) > 60:
            out.append(tri)
    return out


def _probe(t: TestContext, pipe: Pipe, rng: np.random.Generator, where: str, n: int = 4,
           zlo: float = -0.75, zhi: float = 0.75) -> None:
    """Triangles chosen in the window, carried back to object space, drawn and checked."""
    tris = []
    for tri in _window_tris(rng, n):
        zd = rng.uniform(zlo, zhi, size=3)
        tris.append(_unproject(pipe, tri, zd))
    _check_scene(t, pipe, tris, where)


def _reset(t: TestContext) -> Pipe:
    gl = t.gl
    gl.glViewport(0, 0, t.width, t.height)
    for mode in (gl.GL_PROJECTION, gl.GL_MODELVIEW):
        gl.glMatrixMode(mode)
        gl.glLoadIdentity()
    return Pipe(t.width, t.height)


# the shape the single transforms move about: asymmetric, so mirror images and
# wrong rotation senses show
PROBE = [
    [(0, 0, 0), (14, 0, 0), (0, 7, 0)],
    [(16, 2, 0), (22.5, 11, 0), (9, 15.5, 0)],
    [(-12, -4, 0), (-2.5, -15, 0), (-4, -1.5, 0)],
    [(-3, 4, 0), (-9, 18.25, 0), (-14.5, 6, 0)],
]


# {============================================================
# MatrixStack


def _stack(t: TestContext, mode_name: str, where: str, minimum: int, max_name: str,
           depth_name: str, matrix_name: str, others: Any = None) -> None:
    gl = t.gl
    mode = getattr(gl, mode_name)
    gl.glMatrixMode(mode)
    t.check_gl_error(f"glMatrixMode({mode_name})")
    maxd = int(gl.glGetIntegerv(getattr(gl, max_name)))
    if maxd < minimum:
        t.fail(f"{max_name} is {maxd}, the minimum is {minimum}")

    def depth() -> int:
        return int(gl.glGetIntegerv(getattr(gl, depth_name)))

    def current() -> np.ndarray:
        return np.asarray(gl.glGetFixedv(getattr(gl, matrix_name)), dtype=np.int64).reshape(16)

    def expect(m: np.ndarray, d: int, what: str) -> None:
        got = current()
        if np.abs(got - m).max() > 1:
            t.fail(f"{where}: {what}: {matrix_name} is {(got / ONE).round(4).tolist()}, "
                   f"expected {(m / ONE).round(4).tolist()}")
        if depth() != d:
            t.fail(f"{where}: {what}: {depth_name} is {depth()}, expected {d}")

    ident = np.array([ONE if i % 5 == 0 else 0 for i in range(16)], dtype=np.int64)
    expect(ident, 1, "initially")
    # level k holds a matrix with 16 distinct entries
    mats = [np.array([fx(((-1) ** i) * (0.25 + k * 0.5 + i * 0.0625)) for i in range(16)], dtype=np.int64)
            for k in range(maxd)]
    for k in range(maxd):
        gl.glLoadMatrixx(mats[k].tolist())
        expect(mats[k], k + 1, f"after glLoadMatrixx at depth {k + 1}")
        if k < maxd - 1:
            gl.glPushMatrix()
            t.check_gl_error(f"{where}: glPushMatrix at depth {k + 1}")
            expect(mats[k], k + 2, f"after glPushMatrix to depth {k + 2} (the top is duplicated)")
    if others is not None:
        others()
    gl.glPushMatrix()
    t.check_gl_error(f"{where}: glPushMatrix on a full stack of {maxd}", gl.GL_STACK_OVERFLOW)
    expect(mats[-1], maxd, "after the overflowing glPushMatrix")
    for k in reversed(range(maxd)):
        expect(mats[k], k + 1, f"popping back to depth {k + 1}")
        if k > 0:
            gl.glPopMatrix()
            t.check_gl_error(f"{where}: glPopMatrix from depth {k + 1}")
    gl.glPopMatrix()
    t.check_gl_error(f"{where}: glPopMatrix at depth 1", gl.GL_STACK_UNDERFLOW)
    expect(mats[0], 1, "after the underflowing glPopMatrix")
    gl.glLoadIdentity()


def _stack_draw(t: TestContext, mode_name: str) -> None:
    """The matrix left by an overflowing push and an underflowing pop draws as before."""
    gl = t.gl
    pipe = _reset(t)
    t.ortho_pixels()
    pipe.ortho_pixels()
    mode = getattr(gl, mode_name)
    maxd = int(gl.glGetIntegerv(gl.GL_MAX_MODELVIEW_STACK_DEPTH if mode == gl.GL_MODELVIEW
                                else gl.GL_MAX_PROJECTION_STACK_DEPTH))
    gl.glMatrixMode(mode)
    base = pipe.mv if mode == gl.GL_MODELVIEW else pipe.proj
    first_m = base @ gl_translate(gl, 3.5, 2.25, 0)
    m = first_m
    for k in range(1, maxd):
        gl.glPushMatrix()
        m = m @ gl_translate(gl, 1.0 if k % 2 else -0.5, 0.5, 0)
    gl.glPushMatrix()
    t.check_gl_error(f"{mode_name}: overflowing glPushMatrix", gl.GL_STACK_OVERFLOW)
    if mode == gl.GL_MODELVIEW:
        pipe.mv = m
    else:
        pipe.proj = m
    tris = [np.array(tr) + (20, 20, 0) for tr in PROBE]
    _check_scene(t, pipe, tris, f"{mode_name}: drawn after the overflowing push", margin=0.0)
    for _ in range(maxd):
        gl.glPopMatrix()
    t.check_gl_error(f"{mode_name}: underflowing glPopMatrix", gl.GL_STACK_UNDERFLOW)
    if mode == gl.GL_MODELVIEW:
        pipe.mv = first_m
    else:
        pipe.proj = first_m
    _check_scene(t, pipe, tris, f"{mode_name}: drawn after the underflowing pop", margin=0.0)
    gl.glMatrixMode(gl.GL_MODELVIEW)


@conformance_test("MatrixStack.modelview", section="2.10.2")
def matrixstack_modelview(t: TestContext) -> None:
    """The modelview stack holds MAX_MODELVIEW_STACK_DEPTH (>= 16) matrices; overflow/underflow (2.10.2)."""
    _stack(t, "GL_MODELVIEW", "modelview", 16, "GL_MAX_MODELVIEW_STACK_DEPTH",
           "GL_MODELVIEW_STACK_DEPTH", "GL_MODELVIEW_MATRIX")
    _stack_draw(t, "GL_MODELVIEW")


@conformance_test("MatrixStack.projection", section="2.10.2")
def matrixstack_projection(t: TestContext) -> None:
    """The projection stack holds MAX_PROJECTION_STACK_DEPTH (>= 2) matrices; overflow/underflow (2.10.2)."""
    gl = t.gl

    def modelview_untouched() -> None:
        gl.glMatrixMode(gl.GL_MODELVIEW)
        if int(gl.glGetIntegerv(gl.GL_MODELVIEW_STACK_DEPTH)) != 1:
            t.fail("pushing the projection stack changed MODELVIEW_STACK_DEPTH")
        gl.glMatrixMode(gl.GL_PROJECTION)

    _stack(t, "GL_PROJECTION", "projection", 2, "GL_MAX_PROJECTION_STACK_DEPTH",
           "GL_PROJECTION_STACK_DEPTH", "GL_PROJECTION_MATRIX", modelview_untouched)
    _stack_draw(t, "GL_PROJECTION")


@conformance_test("MatrixStack.texture", section="2.10.2")
def matrixstack_texture(t: TestContext) -> None:
    """Each texture unit has its own stack of MAX_TEXTURE_STACK_DEPTH (>= 2), chosen by ActiveTexture."""
    gl = t.gl
    t.clear()
    units = int(gl.glGetIntegerv(gl.GL_MAX_TEXTURE_UNITS))
    if units < 2:
        t.fail(f"MAX_TEXTURE_UNITS is {units}, the minimum is 2")
    ident = np.array([ONE if i % 5 == 0 else 0 for i in range(16)], dtype=np.int64)
    for u in range(units):
        gl.glActiveTexture(gl.GL_TEXTURE0 + u)
        t.check_gl_error(f"glActiveTexture(TEXTURE{u})")

        def others_untouched(u: int = u) -> None:
            # the other units' stacks are still at depth 1 with the identity
            for v in range(units):
                if v == u:
                    continue
                gl.glActiveTexture(gl.GL_TEXTURE0 + v)
                d = int(gl.glGetIntegerv(gl.GL_TEXTURE_STACK_DEPTH))
                m = np.asarray(gl.glGetFixedv(gl.GL_TEXTURE_MATRIX), dtype=np.int64).reshape(16)
                if d != 1 or (m != ident).any():
                    t.fail(f"filling the stack of unit {u} changed unit {v}: depth {d}, "
                           f"matrix {(m / ONE).round(4).tolist()}")
            gl.glActiveTexture(gl.GL_TEXTURE0 + u)

        _stack(t, "GL_TEXTURE", f"texture unit {u}", 2, "GL_MAX_TEXTURE_STACK_DEPTH",
               "GL_TEXTURE_STACK_DEPTH", "GL_TEXTURE_MATRIX", others_untouched)
    # two units holding different matrices at different depths
    gl.glMatrixMode(gl.GL_TEXTURE)
    gl.glActiveTexture(gl.GL_TEXTURE0)
    gl.glPushMatrix()
    gl.glTranslatex(ONE, 2 * ONE, 0)
    gl.glActiveTexture(gl.GL_TEXTURE1)
    gl.glScalex(3 * ONE, ONE, ONE)
    d1 = int(gl.glGetIntegerv(gl.GL_TEXTURE_STACK_DEPTH))
    m1 = np.asarray(gl.glGetFixedv(gl.GL_TEXTURE_MATRIX)).reshape(16)
    gl.glActiveTexture(gl.GL_TEXTURE0)
    d0 = int(gl.glGetIntegerv(gl.GL_TEXTURE_STACK_DEPTH))
    m0 = np.asarray(gl.glGetFixedv(gl.GL_TEXTURE_MATRIX)).reshape(16)
    if d0 != 2 or d1 != 1 or m0[12] != ONE or m0[13] != 2 * ONE or m1[0] != 3 * ONE or m1[12] != 0:
        t.fail(f"texture stacks are not per unit: unit 0 depth {d0} matrix {(m0 / ONE).tolist()}, "
               f"unit 1 depth {d1} matrix {(m1 / ONE).tolist()}")
    gl.glPopMatrix()
    t.check_gl_error("texture stacks")
    # a unit beyond MAX_TEXTURE_UNITS is INVALID_ENUM and changes nothing
    gl.glActiveTexture(gl.GL_TEXTURE0 + units)
    t.check_gl_error(f"glActiveTexture(TEXTURE{units})", gl.GL_INVALID_ENUM)
    if int(gl.glGetIntegerv(gl.GL_ACTIVE_TEXTURE)) != gl.GL_TEXTURE0:
        t.fail("a failed glActiveTexture changed ACTIVE_TEXTURE")
    gl.glMatrixMode(gl.GL_MODELVIEW)


@conformance_test("MatrixStack.errors", section="2.10.2")
def matrixstack_errors(t: TestContext) -> None:
    """Initial matrix mode MODELVIEW; an invalid mode is INVALID_ENUM and changes nothing (2.10.2, 2.5)."""
    gl = t.gl
    t.clear()
    if int(gl.glGetIntegerv(gl.GL_MATRIX_MODE)) != gl.GL_MODELVIEW:
        t.fail("MATRIX_MODE is not MODELVIEW initially")
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glMatrixMode(gl.GL_COLOR_BUFFER_BIT)
    t.check_gl_error("glMatrixMode(an invalid mode)", gl.GL_INVALID_ENUM)
    if int(gl.glGetIntegerv(gl.GL_MATRIX_MODE)) != gl.GL_PROJECTION:
        t.fail("a failed glMatrixMode changed MATRIX_MODE")
    gl.glMatrixMode(gl.GL_MODELVIEW)
    # push and pop act on the current mode's stack only
    gl.glPushMatrix()
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glPopMatrix()
    t.check_gl_error("glPopMatrix on the projection stack after a modelview push", gl.GL_STACK_UNDERFLOW)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    if int(gl.glGetIntegerv(gl.GL_MODELVIEW_STACK_DEPTH)) != 2:
        t.fail("the modelview stack is not at depth 2 after one push")
    gl.glPopMatrix()
    t.check_gl_error("glPopMatrix")


# {============================================================
# XForm


def _xform_setup(t: TestContext, depth: float = 1.0) -> Pipe:
    """Pixel ortho with the z range [-depth, depth]; modelview translated to the window centre."""
    gl = t.gl
    pipe = _reset(t)
    gl.glMatrixMode(gl.GL_PROJECTION)
    pipe.proj = gl_ortho(gl, 0, t.width, 0, t.height, -depth, depth)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    pipe.mv = gl_translate(gl, 32, 32, 0)
    return pipe


@conformance_test("XForm.translate", section="2.10.2")
def xform_translate(t: TestContext) -> None:
    """glTranslatex moves vertices by (x, y, z) (2.10.2)."""
    gl = t.gl
    for v in ((12.5, -7.25, 0.0), (-20.0625, 15.5, 0.5), (0.3, -0.7, -0.25), (7.0, 9.0, 0.0)):
        pipe = _xform_setup(t)
        pipe.mv = pipe.mv @ gl_translate(gl, *v)
        _check_scene(t, pipe, PROBE, f"translate {v}")
    # translations alone (the modelview is a pure translation)
    pipe = _reset(t)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    pipe.mv = gl_translate(gl, 0.25, -0.125, 0)
    _check_scene(t, pipe, [[(-0.5, -0.5, 0), (0.5, -0.5, 0), (0, 0.5, 0)]],
                 "pure translation, identity projection")
    # translated beyond the far plane: clipped away
    pipe = _xform_setup(t)
    gl.glTranslatex(0, 0, fx(1.5))
    img = draw_one(t, gl.GL_TRIANGLES, np.concatenate(PROBE), size=3)
    if not matches(t, img, BLACK).all():
        t.fail(f"translate z by 1.5 beyond the far plane: drawn anyway: {first(~matches(t, img, BLACK))}")


@conformance_test("XForm.rotate", section="2.10.2")
def xform_rotate(t: TestContext) -> None:
    """glRotatex is the right-handed rotation R = uu^T + cos(I - uu^T) + sin S (2.10.2)."""
    gl = t.gl
    cases = [(30, 0, 0, 1), (90, 0, 0, 1), (-45, 0, 0, 1), (200.5, 0, 0, 1), (60, 1, 0, 0),
             (-75, 0, 1, 0), (45, 0, 0, 2), (120, 1, 2, 2), (33.3, -1, 0.5, 3), (-150, 0.25, -1, 0.5)]
    for angle, x, y, z in cases:
        pipe = _xform_setup(t, depth=64.0)
        pipe.mv = pipe.mv @ gl_rotate(gl, angle, x, y, z)
        _check_scene(t, pipe, PROBE, f"rotate {angle} degrees about ({x}, {y}, {z})")
    # a quarter turn about z maps the x axis onto the y axis
    pipe = _xform_setup(t)
    pipe.mv = pipe.mv @ gl_rotate(gl, 90, 0, 0, 1)
    thin = [(4, -2, 0), (20, -2, 0), (20, 2, 0)]
    img = draw_one(t, gl.GL_TRIANGLES, thin, size=3)
    # x in [4, 20] -> window y in [36, 52]; y in [-2, 2] -> window x in [34, 30] (reversed)
    inside, either = coverage([pipe.polygon(thin)], t.width, t.height, MARGIN)
    box = np.zeros((t.height, t.width), dtype=bool)
    box[36:52, 30:34] = True
    if (inside & ~box).any() or not inside.any():
        t.fail("test bug: the rotated triangle is not where the hand computation puts it")
    expect_coverage(t, img, inside, either, WHITE, "rotate 90 about z, a thin triangle along x")


@conformance_test("XForm.scale", section="2.10.2")
def xform_scale(t: TestContext) -> None:
    """glScalex scales each axis, negative factors mirror (2.10.2)."""
    gl = t.gl
    for v in ((2.0, 0.5, 1.0), (-1.5, 0.75, 1.0), (0.25, -2.0, 1.0), (-1.0, -1.0, 1.0), (1.3, 1.7, 3.0)):
        pipe = _xform_setup(t)
        pipe.mv = pipe.mv @ gl_scale(gl, *v)
        _check_scene(t, pipe, PROBE, f"scale {v}")
    # z scaled out of the depth range: clipped
    probe_z = [np.array(tr, dtype=np.float64) + (0, 0, 0.25) for tr in PROBE]
    for sz, visible in ((2.0, True), (5.0, False), (-3.0, True), (-4.5, False)):
        pipe = _xform_setup(t)
        pipe.mv = pipe.mv @ gl_scale(gl, 1.0, 1.0, sz)
        if visible:
            _check_scene(t, pipe, probe_z, f"scale z by {sz}, z = 0.25")
        else:
            img = draw_one(t, gl.GL_TRIANGLES, np.concatenate(probe_z), size=3)
            if not matches(t, img, BLACK).all():
                t.fail(f"scale z by {sz} puts z = 0.25 outside the depth range; drawn anyway: "
                       f"{first(~matches(t, img, BLACK))}")


@conformance_test("XForm.ortho", section="2.10.2")
def xform_ortho(t: TestContext) -> None:
    """glOrthox maps (l, b, -n) and (r, t, -f) to the corners of the clip volume (2.10.2)."""
    gl = t.gl
    rng = np.random.default_rng(21)
    for args in ((-10, 30, 5, 25, -1, 1), (100, 36, -8, 40, 0.5, 10), (0.5, 2.5, -1, 3, -2, 2),
                 (-300, 200, 150, -50, 10, -10), (0, 64, 0, 64, 1, 3)):
        pipe = _reset(t)
        gl.glMatrixMode(gl.GL_PROJECTION)
        pipe.proj = gl_ortho(gl, *args)
        gl.glMatrixMode(gl.GL_MODELVIEW)
        _probe(t, pipe, rng, f"glOrthox{args}")
    # (l, b) and (r, t) go to the window's corners: the quad between them fills the window
    for args in ((-10, 30, 5, 25, -1, 1), (7.5, -2.25, 3, 11, 2, 6)):
        pipe = _reset(t)
        gl.glMatrixMode(gl.GL_PROJECTION)
        gl_ortho(gl, *args)
        gl.glMatrixMode(gl.GL_MODELVIEW)
        lf, r, b, tp, n, f = args
        z = -(n + f) / 2
        img = draw_one(t, gl.GL_TRIANGLE_FAN, [(lf, b, z), (r, b, z), (r, tp, z), (lf, tp, z)], size=3)
        full = np.ones((t.height, t.width), dtype=bool)
        expect_coverage(t, img, full, ~full, WHITE, f"glOrthox{args}: the quad from (l, b) to (r, t)")
    # invalid arguments are INVALID_VALUE and leave the matrix alone
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    for bad in ((1, 1, 0, 1, 0, 1), (0, 1, 2, 2, 0, 1), (0, 1, 0, 1, 3, 3)):
        gl.glOrthox(*[fx(v) for v in bad])
        t.check_gl_error(f"glOrthox{bad}", gl.GL_INVALID_VALUE)
    got = np.asarray(gl.glGetFixedv(gl.GL_PROJECTION_MATRIX)).reshape(16)
    if (got != [ONE if i % 5 == 0 else 0 for i in range(16)]).any():
        t.fail("a failed glOrthox changed the projection matrix")
    gl.glMatrixMode(gl.GL_MODELVIEW)


@conformance_test("XForm.frustum", section="2.10.2")
def xform_frustum(t: TestContext) -> None:
    """glFrustumx is the perspective matrix of 2.10.2; vertices land where x_c/w_c says."""
    gl = t.gl
    rng = np.random.default_rng(22)
    for args in ((-1, 1, -1, 1, 1, 10), (-1, 2, -0.5, 1.5, 1, 10), (-0.5, 0.5, -0.25, 0.75, 0.25, 100),
                 (2, -1, 1, -1, 2, 5), (-3, 3, -3, 3, 4, 4.5)):
        pipe = _reset(t)
        gl.glMatrixMode(gl.GL_PROJECTION)
        pipe.proj = gl_frustum(gl, *args)
        gl.glMatrixMode(gl.GL_MODELVIEW)
        _probe(t, pipe, rng, f"glFrustumx{args}", zlo=-0.9, zhi=0.9)
    # a quad at z = -2 under frustum(-1, 1, -1, 1, 1, 3) covers half the window width
    pipe = _reset(t)
    gl.glMatrixMode(gl.GL_PROJECTION)
    pipe.proj = gl_frustum(gl, -1, 1, -1, 1, 1, 3)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    quad = [(-1, -1, -2), (1, -1, -2), (1, 1, -2), (-1, 1, -2)]
    img = draw_one(t, gl.GL_TRIANGLE_FAN, quad, size=3)
    want = np.zeros((t.height, t.width), dtype=bool)
    want[16:48, 16:48] = True
    expect_coverage(t, img, want, np.zeros_like(want), WHITE, "unit quad at z = -2, near 1: x/2")
    for bad in ((0, 1, 0, 1, 0, 1), (0, 1, 0, 1, 1, -1), (1, 1, 0, 1, 1, 2), (0, 1, 0, 1, 2, 2)):
        gl.glMatrixMode(gl.GL_PROJECTION)
        gl.glFrustumx(*[fx(v) for v in bad])
        t.check_gl_error(f"glFrustumx{bad}", gl.GL_INVALID_VALUE)
    gl.glMatrixMode(gl.GL_MODELVIEW)


@conformance_test("XForm.matrix", section="2.10.2")
def xform_matrix(t: TestContext) -> None:
    """glLoadMatrixx/glMultMatrixx take column-major matrices; MultMatrix post-multiplies (2.10.2)."""
    gl = t.gl
    rng = np.random.default_rng(23)
    pipe = _reset(t)
    gl.glMatrixMode(gl.GL_PROJECTION)
    pipe.proj = gl_ortho(gl, 0, t.width, 0, t.height, -8, 8)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    for k in range(4):
        m = np.eye(4)
        m[:3, :3] = rng.uniform(-1.2, 1.2, size=(3, 3)) + np.eye(3)
        m[:3, 3] = rng.uniform(20, 44, size=3) * (1, 1, 0)
        pipe.mv = gl_matrix(gl, m, load=True)
        got = np.asarray(gl.glGetFixedv(gl.GL_MODELVIEW_MATRIX)).reshape(16)
        want = [fx(v) for v in pipe.mv.T.reshape(-1)]
        if np.abs(got - want).max() > 1:
            t.fail(f"glLoadMatrixx then MODELVIEW_MATRIX: {(got / ONE).round(4).tolist()}, "
                   f"expected {(np.array(want) / ONE).round(4).tolist()}")
        _probe(t, pipe, rng, f"glLoadMatrixx, matrix {k}")
        n = np.eye(4)
        n[:3, :3] = rng.uniform(-0.5, 0.5, size=(3, 3)) + np.eye(3)
        n[:2, 3] = rng.uniform(-5, 5, size=2)
        pipe.mv = pipe.mv @ gl_matrix(gl, n, load=False)
        _probe(t, pipe, rng, f"glMultMatrixx after glLoadMatrixx, matrix {k}")


# {============================================================
# XFormMix


@conformance_test("XFormMix", section="2.10.2")
def xform_mix(t: TestContext) -> None:
    """Sequences of mixed matrix commands give the product of the 2.10.2 matrices in call order."""
    gl = t.gl
    rng = np.random.default_rng(31)
    for seq in range(12):
        pipe = _reset(t)
        log = []
        gl.glMatrixMode(gl.GL_PROJECTION)
        if rng.random() < 0.5:
            a = float(rng.uniform(0.5, 1.5))
            pipe.proj = gl_frustum(gl, -a, a * rng.uniform(0.5, 1.5), -a, a, 1, 50)
            log.append("frustum")
            depth = -float(rng.uniform(6, 12))
        else:
            pipe.proj = gl_ortho(gl, -40, 40, -40 * rng.uniform(0.5, 1.5), 40, -50, 50)
            log.append("ortho")
            depth = 0.0
        if rng.random() < 0.5:
            pipe.proj = pipe.proj @ gl_rotate(gl, float(rng.uniform(-20, 20)), 0, 0, 1)
            log.append("projection rotate")
        gl.glMatrixMode(gl.GL_MODELVIEW)
        pipe.mv = gl_translate(gl, 0, 0, depth)
        stack = []
        for _ in range(int(rng.integers(4, 9))):
            op = rng.choice(["translate", "rotate", "scale", "mult", "push", "pop", "load"])
            if op == "translate":
                v = rng.uniform(-4, 4, size=3)
                pipe.mv = pipe.mv @ gl_translate(gl, *v)
            elif op == "rotate":
                ax = rng.normal(size=3)
                pipe.mv = pipe.mv @ gl_rotate(gl, float(rng.uniform(-180, 180)), *ax)
            elif op == "scale":
                v = rng.uniform(0.6, 1.6, size=3) * rng.choice([-1, 1], size=3)
                pipe.mv = pipe.mv @ gl_scale(gl, *v)
            elif op == "mult":
                m = rotate(float(rng.uniform(-90, 90)), *rng.normal(size=3))
                m = m @ scale(*rng.uniform(0.7, 1.3, 3))
                m[:3, 3] = rng.uniform(-3, 3, size=3)
                pipe.mv = pipe.mv @ gl_matrix(gl, m, load=False)
            elif op == "load":
                m = translate(0, 0, depth) @ rotate(float(rng.uniform(-90, 90)), *rng.normal(size=3))
                pipe.mv = gl_matrix(gl, m, load=True)
            elif op == "push":
                gl.glPushMatrix()
                stack.append(pipe.mv)
            elif op == "pop" and stack:
                gl.glPopMatrix()
                pipe.mv = stack.pop()
            log.append(str(op))
        t.check_gl_error(f"sequence {seq}")
        _probe(t, pipe, rng, f"sequence {seq}: {', '.join(log)}")


# {============================================================
# XFormViewport


@conformance_test("XFormViewport", section="2.10.1")
def xform_viewport(t: TestContext) -> None:
    """x_w = (p_x/2) x_d + o_x with o_x = x + w/2, for odd sizes and negative origins (2.10.1)."""
    gl = t.gl
    rng = np.random.default_rng(41)
    pipe = _reset(t)
    quad = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    for vp in ((3, 5, 37, 21), (-7, -9, 45, 51), (11, -3, 63, 17), (0, 0, 1, 1), (31, 30, 3, 5),
               (-50, 10, 101, 33), (20, 40, 33, 64), (-1, -1, 66, 66), (5, 7, 64, 64)):
        gl.glViewport(*vp)
        pipe.viewport = vp
        got = [int(v) for v in gl.glGetIntegerv(gl.GL_VIEWPORT)]
        if got != list(vp):
            t.fail(f"glViewport{vp}: VIEWPORT is {got}")
        # the viewport-filling quad covers exactly the viewport rectangle within the window
        img = draw_one(t, gl.GL_TRIANGLE_FAN, quad)
        want = np.zeros((t.height, t.width), dtype=bool)
        want[max(vp[1], 0):max(vp[1] + vp[3], 0), max(vp[0], 0):max(vp[0] + vp[2], 0)] = True
        expect_coverage(t, img, want, np.zeros_like(want), WHITE, f"viewport {vp}, the quad x, y in [-1, 1]")
        # triangles in normalized device coordinates
        tris = []
        for _ in range(3):
            while True:
                tri = np.round(rng.uniform(-0.95, 0.95, size=(3, 2)) * 256) / 256
                if abs(signed_area(tri)) > 0.15:
                    break
            tris.append(np.concatenate([tri, rng.uniform(-0.9, 0.9, size=(3, 1)).round(4)], axis=1))
        win = [pipe.window(tr) for tr in tris]
        if vp[2] > 8 and not coverage(win, t.width, t.height, MARGIN)[0].any():
            continue
        if vp[2] > 8:
            _check_scene(t, pipe, tris, f"viewport {vp}, triangles")


@conformance_test("XFormViewport.depth", section="2.10.1", uses=("depth",), visuals=("rgba8888", "rgb565"))
def xform_viewport_depth(t: TestContext) -> None:
    """z_w = ((f - n)/2) z_d + (n + f)/2 with n, f clamped to [0, 1], seen through the depth test (2.10.1)."""
    gl = t.gl
    pipe = _reset(t)
    tri = [(-0.75, -0.75), (0.75, -0.5), (0.0, 0.8)]
    inside, either = coverage([pipe.window(tri)], t.width, t.height, MARGIN)
    got = np.asarray(gl.glGetFixedv(gl.GL_DEPTH_RANGE))
    if (got != [0, ONE]).any():
        t.fail(f"initial DEPTH_RANGE is {(got / ONE).tolist()}, expected [0, 1]")
    gl.glEnable(gl.GL_DEPTH_TEST)
    gl.glDepthFunc(gl.GL_LESS)
    gl.glDepthMask(True)
    cases = [(0.0, 1.0), (0.25, 0.75), (1.0, 0.0), (0.5, 0.5), (0.9, 0.3), (-0.5, 1.5), (0.2, 2.0)]
    for n, f in cases:
        gl.glDepthRangex(fx(n), fx(f))
        nc, fc = min(max(n, 0.0), 1.0), min(max(f, 0.0), 1.0)
        got = np.asarray(gl.glGetFixedv(gl.GL_DEPTH_RANGE)) / ONE
        if np.abs(got - [nc, fc]).max() > 2.0**-15:
            t.fail(f"glDepthRangex({n}, {f}): DEPTH_RANGE is {got.tolist()}, expected {[nc, fc]}")
        for zd in (-0.8, -0.3, 0.1, 0.6, 0.95):
            zw = (fc - nc) / 2 * zd + (nc + fc) / 2
            for clear_depth in (0.2, 0.45, 0.55, 0.8):
                if abs(zw - clear_depth) < 0.02:
                    continue
                gl.glClearDepthx(fx(clear_depth))
                gl.glClearColorx(0, 0, 0, 0)
                gl.glClear(gl.GL_COLOR_BUFFER_BIT | gl.GL_DEPTH_BUFFER_BIT)
                gl.glColor4x(ONE, ONE, ONE, ONE)
                t.draw(gl.GL_TRIANGLES, [(x, y, zd) for x, y in tri], size=3)
                img = t.read()
                where = f"DepthRange({n}, {f}), z_d {zd}: z_w {zw:.4f} against cleared depth {clear_depth}"
                if zw < clear_depth:
                    expect_coverage(t, img, inside, either, WHITE, where + " (passes LESS)")
                elif matches(t, img, WHITE).any():
                    t.fail(f"{where}: drawn though it fails LESS: {first(matches(t, img, WHITE))}")
    gl.glDepthRangex(0, ONE)
    gl.glDisable(gl.GL_DEPTH_TEST)


# {============================================================
# XFormHomogenous


def _with_w(tri: np.ndarray, ws: tuple[float, ...]) -> np.ndarray:
    """(x, y, z) -> (w x, w y, w z, w) per vertex."""
    w = np.array(ws)[:, None]
    return np.concatenate([tri * w, w], axis=1)


@conformance_test("XFormHomogenous", section="2.10")
def xform_homogenous(t: TestContext) -> None:
    """Vertices (wx, wy, wz, w) with w > 0 draw as (x, y, z); with all w < 0 nothing is drawn (2.10, 2.11)."""
    gl = t.gl
    rng = np.random.default_rng(51)
    w, h = t.width, t.height
    base = [np.concatenate([tr, rng.uniform(-0.75, 0.75, (3, 1)).round(3)], axis=1)
            for tr in _window_tris(rng, 6, 0.0, 64.0)]
    for proj_name in ("ortho", "frustum"):
        pipe = _reset(t)
        gl.glMatrixMode(gl.GL_PROJECTION)
        if proj_name == "ortho":
            pipe.proj = gl_ortho(gl, 0, w, 0, h, -1, 1)
            objs = [q16(tr) for tr in base]
        else:
            pipe.proj = gl_frustum(gl, -1, 1, -1, 1, 1, 5)
            objs = [_unproject(pipe, tr[:, :2], tr[:, 2]) for tr in base]
        gl.glMatrixMode(gl.GL_MODELVIEW)
        ref = _check_scene(t, pipe, objs, f"{proj_name}: w = 1 (3 components)", margin=0.0 if proj_name ==
                           "ortho" else MARGIN)
        for ws in ((2.0, 2.0, 2.0), (0.25, 4.0, 0.5), (8.0, 1.0, 0.125)):
            # powers of two: the divided values are exact, the picture must be identical
            tris = [_with_w(tr, ws) for tr in objs]
            drawn = _check_scene(t, pipe, tris, f"{proj_name}: w per vertex {ws}", size=4,
                                 margin=0.0 if proj_name == "ortho" else MARGIN)
            if proj_name == "ortho" and (drawn != ref).any():
                t.fail(f"ortho: w per vertex {ws} gives other pixels than w = 1: {first(drawn != ref)}")
        for ws in ((3.0, 1.5, 5.0), (0.3, 0.7, 1.1)):
            tris = [np.concatenate([q16(tr * np.array(ws)[:, None]), q16(np.array(ws)[:, None])], axis=1)
                    for tr in objs]
            _check_scene(t, pipe, tris, f"{proj_name}: w per vertex {ws}", size=4,
                         margin=1.0 / 64.0 if proj_name == "ortho" else MARGIN)
        # every vertex with w < 0: no point of the triangle satisfies -w_c <= x_c <= w_c
        for ws in ((-1.0, -1.0, -1.0), (-2.0, -0.5, -4.0)):
            tris = [_with_w(tr, ws) for tr in objs]
            img = draw_one(t, gl.GL_TRIANGLES, np.concatenate(tris), size=4)
            if not matches(t, img, BLACK).all():
                t.fail(f"{proj_name}: triangles with w {ws} < 0 drawn: {first(~matches(t, img, BLACK))}")


# {============================================================
# BufferObject


def _bo_scene() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vertices as shorts in 1/16 pixel, colours ubyte, indices: six triangles."""
    tris = [
        [(2, 2), (28, 4), (10, 26)], [(34, 3), (61, 8.5), (40, 29)], [(5, 34), (27, 33), (20, 61)],
        [(36, 36), (62, 40), (44, 62)], [(30.5, 20), (33.5, 20.25), (32, 44)],
        [(12, 28), (30, 30.5), (20, 31)],
    ]
    verts = np.round(np.array(tris, dtype=np.float64).reshape(-1, 2) * 16).astype(np.int16)
    palette = [(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 0, 255),
               (0, 255, 255, 255), (255, 0, 255, 255)]
    colors = np.array([palette[i // 3] for i in range(len(verts))], dtype=np.uint8)
    # drawn through indices in a shuffled storage order
    perm = np.array([7, 3, 12, 0, 16, 9, 1, 14, 5, 10, 2, 17, 4, 11, 15, 6, 13, 8])
    stored_v = np.zeros_like(verts)
    stored_c = np.zeros_like(colors)
    stored_v[perm] = verts
    stored_c[perm] = colors
    return stored_v, stored_c, perm.astype(np.uint16)


def _bo_expect(t: TestContext, img: np.ndarray, verts: np.ndarray, colors: np.ndarray, idx: np.ndarray,
               where: str) -> None:
    """Each triangle (flat coloured, none overlapping) covers the pixels the sampling rule gives."""
    tris = [verts[idx[3 * i: 3 * i + 3]].astype(np.float64) / 16 for i in range(len(idx) // 3)]
    covs = [coverage([tri], t.width, t.height) for tri in tris]
    for i, (inside, either) in enumerate(covs):
        others = np.zeros_like(inside)
        for j, (ins, eit) in enumerate(covs):
            if j != i:
                others |= ins | eit
        if (others & (inside | either)).any() and (others & inside).any():
            t.fail("test bug: the buffer-object triangles overlap")
        rgba = tuple(int(c) for c in colors[idx[3 * i]])
        expect_coverage(t, img, inside, either, rgba, f"{where}: triangle {i}", skip=others)


def _bo_setup(t: TestContext) -> None:
    gl = t.gl
    t.ortho_pixels()
    gl.glScalex(ONE // 16, ONE // 16, ONE)
    gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
    gl.glEnableClientState(gl.GL_COLOR_ARRAY)


@conformance_test("BufferObject", section="2.9", visuals=("rgba8888", "rgb565"))
def buffer_object(t: TestContext) -> None:
    """Arrays and indices in buffer objects (at offsets, after BufferSubData) draw as client arrays (2.9)."""
    gl = t.gl
    verts, colors, idx = _bo_scene()
    _bo_setup(t)

    def draw_client(v: np.ndarray, c: np.ndarray, i: np.ndarray) -> np.ndarray:
        gl.glBindBuffer(gl.GL_ARRAY_BUFFER, 0)
        gl.glBindBuffer(gl.GL_ELEMENT_ARRAY_BUFFER, 0)
        t.clear()
        gl.glVertexPointer(2, gl.GL_SHORT, 0, np.ascontiguousarray(v))
        gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(c))
        gl.glDrawElements(gl.GL_TRIANGLES, len(i), gl.GL_UNSIGNED_SHORT, np.ascontiguousarray(i))
        t.check_gl_error("client arrays")
        return t.read()

    def same(img: np.ndarray, ref: np.ndarray, where: str) -> None:
        bad = (np.abs(img - ref) > t.visual.color_tolerance()).any(axis=-1)
        if bad.any():
            t.fail(f"{where}: differs from the same data in client arrays: {first(bad)}")

    ref = draw_client(verts, colors, idx)
    _bo_expect(t, ref, verts, colors, idx, "client arrays")

    if gl.glIsBuffer(1) or int(gl.glGetIntegerv(gl.GL_ARRAY_BUFFER_BINDING)) != 0:
        t.fail("a buffer is bound or exists initially")
    names = gl.glGenBuffers(3)
    vbo, ibo, other = (int(n) for n in names)
    # interleaved x, y (shorts) and r, g, b, a (ubytes), stride 8, after 20 bytes of padding
    pad = 20
    inter = np.zeros(len(verts), dtype=[("xy", np.int16, 2), ("rgba", np.uint8, 4)])
    inter["xy"] = verts
    inter["rgba"] = colors
    data = np.concatenate([np.full(pad, 0xA5, dtype=np.uint8), inter.view(np.uint8)])
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, vbo)
    gl.glBufferData(gl.GL_ARRAY_BUFFER, data.nbytes, data, gl.GL_STATIC_DRAW)
    t.check_gl_error("glBufferData(ARRAY_BUFFER)")
    if not gl.glIsBuffer(vbo):
        t.fail("glIsBuffer is false for a bound buffer")
    size = int(gl.glGetBufferParameteriv(gl.GL_ARRAY_BUFFER, gl.GL_BUFFER_SIZE))
    usage = int(gl.glGetBufferParameteriv(gl.GL_ARRAY_BUFFER, gl.GL_BUFFER_USAGE))
    if size != data.nbytes or usage != gl.GL_STATIC_DRAW:
        t.fail(f"BUFFER_SIZE {size}, BUFFER_USAGE 0x{usage:04X}; expected {data.nbytes}, STATIC_DRAW")
    gl.glVertexPointer(2, gl.GL_SHORT, 8, pad)
    gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 8, pad + 4)
    if int(gl.glGetIntegerv(gl.GL_VERTEX_ARRAY_BUFFER_BINDING)) != vbo:
        t.fail("VERTEX_ARRAY_BUFFER_BINDING is not the buffer bound at glVertexPointer")
    # indices in an element buffer after 6 bytes of padding (shorts) and at 3 (bytes)
    ishort = np.concatenate([np.full(6, 0xFF, dtype=np.uint8), idx.view(np.uint8)])
    gl.glBindBuffer(gl.GL_ELEMENT_ARRAY_BUFFER, ibo)
    gl.glBufferData(gl.GL_ELEMENT_ARRAY_BUFFER, ishort.nbytes, ishort, gl.GL_DYNAMIC_DRAW)
    t.clear()
    gl.glDrawElements(gl.GL_TRIANGLES, len(idx), gl.GL_UNSIGNED_SHORT, 6)
    t.check_gl_error("draw from buffers")
    same(t.read(), ref, "vertices, colours and UNSIGNED_SHORT indices in buffers, at offsets")

    ibyte = np.concatenate([np.full(3, 0xEE, dtype=np.uint8), idx.astype(np.uint8)])
    gl.glBufferData(gl.GL_ELEMENT_ARRAY_BUFFER, ibyte.nbytes, ibyte, gl.GL_STATIC_DRAW)
    t.clear()
    gl.glDrawElements(gl.GL_TRIANGLES, len(idx), gl.GL_UNSIGNED_BYTE, 3)
    same(t.read(), ref, "UNSIGNED_BYTE indices in a buffer at offset 3")

    # the array binding is taken at glVertexPointer: rebinding ARRAY_BUFFER changes nothing
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, other)
    junk = np.full(data.nbytes, 0x7F, dtype=np.uint8)
    gl.glBufferData(gl.GL_ARRAY_BUFFER, junk.nbytes, junk, gl.GL_STATIC_DRAW)
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, 0)
    t.clear()
    gl.glDrawElements(gl.GL_TRIANGLES, len(idx), gl.GL_UNSIGNED_BYTE, 3)
    same(t.read(), ref, "after binding another buffer and then 0 to ARRAY_BUFFER")

    # BufferSubData: move triangle 0 and recolour triangle 1, in place
    new_v = verts.copy()
    new_c = colors.copy()
    tri0 = idx[0:3]
    tri1 = idx[3:6]
    new_v[tri0] = new_v[tri0] + np.array([16 * 3, -16], dtype=np.int16)
    new_c[tri1] = (255, 255, 255, 255)
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, vbo)
    for k in np.concatenate([tri0, tri1]):
        rec = np.zeros(1, dtype=inter.dtype)
        rec["xy"] = new_v[k]
        rec["rgba"] = new_c[k]
        gl.glBufferSubData(gl.GL_ARRAY_BUFFER, pad + 8 * int(k), 8, rec.view(np.uint8))
    t.check_gl_error("glBufferSubData")
    gl.glBufferSubData(gl.GL_ARRAY_BUFFER, data.nbytes - 4, 8, np.zeros(8, dtype=np.uint8))
    t.check_gl_error("glBufferSubData past the end", gl.GL_INVALID_VALUE)
    t.clear()
    gl.glDrawElements(gl.GL_TRIANGLES, len(idx), gl.GL_UNSIGNED_BYTE, 3)
    img = t.read()
    ref2 = draw_client(new_v, new_c, idx)
    _bo_expect(t, ref2, new_v, new_c, idx, "client arrays, second scene")
    same(img, ref2, "after glBufferSubData")

    # mixed sources: vertices from the buffer, colours from client memory, indices from client memory
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, vbo)
    gl.glVertexPointer(2, gl.GL_SHORT, 8, pad)
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, 0)
    gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(new_c))
    t.clear()
    gl.glDrawElements(gl.GL_TRIANGLES, len(idx), gl.GL_UNSIGNED_SHORT, np.ascontiguousarray(idx))
    same(t.read(), ref2, "vertices from a buffer, colours and indices from client memory")

    # DrawArrays with first > 0 from a separate GL_BYTE position buffer (whole pixels)
    pos = np.array([[0, 0], [0, 0], [0, 0], [4, 4], [40, 10], [20, 50]], dtype=np.int8)
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, other)
    gl.glBufferData(gl.GL_ARRAY_BUFFER, pos.nbytes, pos, gl.GL_STATIC_DRAW)
    gl.glVertexPointer(2, gl.GL_BYTE, 0, 0)
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, 0)
    gl.glDisableClientState(gl.GL_COLOR_ARRAY)
    gl.glLoadIdentity()
    gl.glColor4x(ONE, ONE, ONE, ONE)
    t.clear()
    gl.glDrawArrays(gl.GL_TRIANGLES, 3, 3)
    t.check_gl_error("glDrawArrays from a GL_BYTE buffer")
    inside, either = coverage([pos[3:].astype(np.float64)], t.width, t.height)
    expect_coverage(t, t.read(), inside, either, WHITE, "GL_BYTE positions from a buffer, first = 3")

    # deleting a bound buffer resets the binding to 0
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, other)
    gl.glDeleteBuffers(3, names)
    t.check_gl_error("glDeleteBuffers")
    if int(gl.glGetIntegerv(gl.GL_ARRAY_BUFFER_BINDING)) != 0:
        t.fail("ARRAY_BUFFER_BINDING is not 0 after deleting the bound buffer")
    if int(gl.glGetIntegerv(gl.GL_ELEMENT_ARRAY_BUFFER_BINDING)) != 0:
        t.fail("ELEMENT_ARRAY_BUFFER_BINDING is not 0 after deleting the bound buffer")
    if gl.glIsBuffer(vbo):
        t.fail("glIsBuffer is true for a deleted buffer")
    gl.glDisableClientState(gl.GL_VERTEX_ARRAY)
