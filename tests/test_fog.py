"""Fog (ES 1.1 §3.8) against the spec's formulas in numpy.

f = exp(-d c) (EXP), exp(-(d c)^2) (EXP2) or (e - c)/(e - s) (LINEAR),
clamped to [0, 1]; C = f C_r + (1 - f) C_f for R, G, B; alpha unchanged.
The eye distance c is |z_eye| (the approximation §3.8 allows). FOG_HINT
NICEST evaluates f per fragment from the interpolated distance; FASTEST and
DONT_CARE evaluate it per vertex and interpolate f. Scenes use an
orthographic projection, where z_eye is linear in window x and both ways are
exactly predictable, and a perspective one, where they are perspective-correct.

Tolerances (8-bit steps, beyond the 0.5 of rounding) are derived per build:
the fixed build rounds c, d c, the LINEAR scale 1/(e - s), the exp and the fog
colour to 16.16 (each within 2^-17, exp within 2^-16); float32 keeps ~1e-6.
``pytest -s tests/test_fog.py`` prints the measured errors, including the
fixed build's exp against the double build (docs/numerics.md).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import BUILDS

import gles
from gles import constants as C

W, H = 64, 8
LSB16 = 2.0**-16


def fog_factor(mode: str, c: Any, d: float = 1.0, s: float = 0.0, e: float = 1.0) -> np.ndarray:
    """Equations 3.22-3.24, clamped to [0, 1]."""
    c = np.asarray(c, dtype=np.float64)
    if mode == "EXP":
        f = np.exp(-d * c)
    elif mode == "EXP2":
        f = np.exp(-((d * c) ** 2))
    else:
        f = (e - c) / (e - s)
    return np.clip(f, 0.0, 1.0)


def tolerance(numeric: str, mode: str, d: float, s: float, e: float, cmax: float) -> float:
    """Allowed error of a channel in 8-bit steps beyond rounding (see the module docstring)."""
    if numeric == "double":
        return 1e-6
    if numeric == "float":
        return 0.01
    # fixed: colours and the final blend 3 * 2^-17; c within 2^-17 times |df/dc|
    err = 3 * 2.0**-17
    if mode == "LINEAR":
        err += (e - s + 2) * 2.0**-17 + 2.0**-17 / (e - s)
    elif mode == "EXP":
        err += LSB16 + 2.0**-17 * (1 + d)
    else:
        err += LSB16 + 2.0**-17 * (1 + 2 * d * cmax) * (1 + 2 * d * cmax)
    return 255 * err


def make(numeric: str, w: int = W, h: int = H, **kw: Any) -> gles.Context:
    ctx = gles.Context(w, h, numeric=numeric, **kw)
    gl = ctx.gl
    gl.glViewport(0, 0, w, h)
    gl.glShadeModel(C.GL_FLAT)
    gl.glDisable(C.GL_DITHER)
    return ctx


def ortho(gl: Any, w: int, h: int, near: float, far: float) -> None:
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0.0, float(w), 0.0, float(h), near, far)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()


def set_fog(gl: Any, mode: str, d: float, s: float, e: float, colour: Any, hint: int) -> None:
    gl.glEnable(C.GL_FOG)
    gl.glFogf(C.GL_FOG_MODE, getattr(C, "GL_" + mode))
    gl.glFogf(C.GL_FOG_DENSITY, d)
    gl.glFogf(C.GL_FOG_START, s)
    gl.glFogf(C.GL_FOG_END, e)
    gl.glFogfv(C.GL_FOG_COLOR, colour)
    gl.glHint(C.GL_FOG_HINT, hint)


def draw(gl: Any, verts: Any, rgba: Any, mode: int = C.GL_TRIANGLE_FAN) -> None:
    v = np.ascontiguousarray(verts, dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(v.shape[1], C.GL_FLOAT, 0, v)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)
    gl.glColor4ub(*rgba)
    gl.glDrawArrays(mode, 0, len(v))


def expected(f: np.ndarray, rgba: Any, fog_colour: Any) -> np.ndarray:
    """C = f C_r + (1 - f) C_f in 8-bit units (unrounded), alpha = C_r's."""
    cr = np.asarray(rgba, dtype=np.float64) / 255.0
    cf = np.asarray(fog_colour, dtype=np.float64)
    out = f[..., None] * cr[:3] + (1 - f[..., None]) * cf[:3]
    return np.concatenate([out, np.broadcast_to(cr[3], f.shape)[..., None]], axis=-1) * 255.0


def check(got: np.ndarray, want: np.ndarray, tol: float, what: str) -> float:
    """|got - want| <= 1/2 + tol on every channel; returns the largest |got - want|."""
    err = np.abs(got.astype(np.float64) - want)
    worst = float(err.max())
    if worst > 0.5 + tol:
        i = tuple(np.argwhere(err > 0.5 + tol)[0])
        pytest.fail(f"{what}: {int((err > 0.5 + tol).sum())} channels off by more than 0.5 + {tol:.4f} "
                    f"steps; first at {i}: got {got[i]}, exact {want[i]:.4f}")
    return worst


# (mode, density, start, end, near |z|, far |z|): the quad's eye distance runs
# from near to far along x, across the factor's interesting range
CASES = [
    ("LINEAR", 1.0, 2.0, 10.0, 1.0, 12.0),
    ("LINEAR", 1.0, -4.0, 40.0, 0.5, 30.0),
    ("EXP", 0.5, 0.0, 1.0, 0.25, 6.0),
    ("EXP", 2.25, 0.0, 1.0, 0.125, 2.0),
    ("EXP2", 0.375, 0.0, 1.0, 0.5, 6.0),
    ("EXP2", 1.5, 0.0, 1.0, 0.0625, 2.0),
]
HINTS = {"NICEST": C.GL_NICEST, "FASTEST": C.GL_FASTEST, "DONT_CARE": C.GL_DONT_CARE}
MEASURED: dict[str, float] = {}


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("hint", list(HINTS))
@pytest.mark.parametrize("case", CASES, ids=[f"{c[0]}-{c[1]}-{c[4]}-{c[5]}" for c in CASES])
def test_fog_ortho(numeric, hint, case):
    """A quad whose |z_eye| runs linearly along x: NICEST gives f(|z(x)|) per fragment, the
    other hints f at the vertices interpolated; C = f C_r + (1 - f) C_f; alpha unchanged."""
    mode, d, s, e, z0, z1 = case
    rng = np.random.default_rng(len(mode) + int(d * 8))
    rgba = tuple(int(v) for v in rng.integers(0, 256, 4))
    fog_colour = [float(v) for v in rng.integers(0, 256, 4) / 255.0]
    ctx = make(numeric)
    gl = ctx.gl
    ortho(gl, W, H, 0.0, 64.0)
    set_fog(gl, mode, d, s, e, fog_colour, HINTS[hint])
    draw(gl, [(0, 0, -z0), (W, 0, -z1), (W, H, -z1), (0, H, -z0)], rgba)
    t = (np.arange(W) + 0.5) / W
    if hint == "NICEST":
        f = fog_factor(mode, z0 + (z1 - z0) * t, d, s, e)
    else:
        f0, f1 = fog_factor(mode, [z0, z1], d, s, e)
        f = f0 + (f1 - f0) * t
    want = np.broadcast_to(expected(f, rgba, fog_colour), (H, W, 4))
    got = ctx.color_buffer()
    worst = check(got, want, tolerance(numeric, mode, d, s, e, z1), f"{numeric} {hint} {case}")
    key = f"{numeric} {mode}"
    MEASURED[key] = max(MEASURED.get(key, 0.0), worst)
    assert (got[..., 3] == rgba[3]).all(), "fog changed alpha"


def test_hints_differ():
    """NICEST and FASTEST give different pictures where f is not linear in z (EXP over a wide range)."""
    imgs = []
    for hint in (C.GL_NICEST, C.GL_FASTEST):
        ctx = make("double")
        gl = ctx.gl
        ortho(gl, W, H, 0.0, 64.0)
        set_fog(gl, "EXP", 0.5, 0.0, 1.0, [0, 0, 0, 1], hint)
        draw(gl, [(0, 0, -1), (W, 0, -5), (W, H, -5), (0, H, -1)], (255, 255, 255, 255))
        imgs.append(ctx.color_buffer()[0, :, 0].astype(int))
        assert gl.glGetIntegerv(C.GL_FOG_HINT) == hint
    assert np.abs(imgs[0] - imgs[1]).max() > 20


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("hint", ["NICEST", "FASTEST"])
def test_fog_perspective(numeric, hint):
    """Perspective: a plane z_e = a + b x_e seen through glFrustumf(-1, 1, -1, 1, 1, 20).
    Per fragment, c = |z_e| where the pixel's ray meets the plane; per vertex, f is linear
    in eye space (perspective-correct interpolation)."""
    a, b, d = -6.0, 0.25, 0.3
    ctx = make(numeric, W, W)
    gl = ctx.gl
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumf(-1.0, 1.0, -1.0, 1.0, 1.0, 20.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    set_fog(gl, "EXP", d, 0.0, 1.0, [0.2, 0.4, 1.0, 1.0], HINTS[hint])
    # the plane over x_e in [X0, X1], covering the window
    x_lo, x_hi = -12.0, 12.0
    z_lo, z_hi = a + b * x_lo, a + b * x_hi
    draw(gl, [(x_lo, -30, z_lo), (x_hi, -30, z_hi), (x_hi, 30, z_hi), (x_lo, 30, z_lo)], (255, 128, 0, 200))
    xn = (np.arange(W) + 0.5) / W * 2 - 1           # x_ndc of pixel centres
    z = a / (1 + b * xn)                             # z_e = a + b x_e with x_e = -z_e x_ndc
    if hint == "NICEST":
        f = fog_factor("EXP", np.abs(z), d)
    else:
        xe = -z * xn
        f0, f1 = fog_factor("EXP", np.abs([z_lo, z_hi]), d)
        f = f0 + (f1 - f0) * (xe - x_lo) / (x_hi - x_lo)
    want = np.broadcast_to(expected(f, (255, 128, 0, 200), [0.2, 0.4, 1.0, 1.0]), (W, W, 4))
    tol = tolerance(numeric, "EXP", d, 0, 1, 10.0)
    worst = check(ctx.color_buffer(), want, tol, f"{numeric} perspective {hint}")
    MEASURED[f"{numeric} perspective {hint}"] = worst


@pytest.mark.parametrize("numeric", BUILDS)
def test_distance_is_abs_z_eye(numeric):
    """c is |z_eye|: constant over a plane z_e = -4 seen in perspective (the Euclidean distance
    would grow towards the corners), and a quad at positive z_eye fogs like one at -z."""
    ctx = make(numeric, 32, 32)
    gl = ctx.gl
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumf(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    for hint in (C.GL_NICEST, C.GL_FASTEST):
        set_fog(gl, "EXP", 0.3, 0.0, 1.0, [0, 0, 0, 0], hint)
        draw(gl, [(-4, -4, -4), (4, -4, -4), (4, 4, -4), (-4, 4, -4)], (255, 255, 255, 255))
        img = ctx.color_buffer()[..., 0].astype(float)
        check(img, np.full(img.shape, 255 * np.exp(-1.2)), tolerance(numeric, "EXP", 0.3, 0, 1, 4),
              "plane at z_eye = -4")
    for zsign in (1, -1):
        ortho(gl, 32, 32, -10.0, 10.0)
        set_fog(gl, "LINEAR", 1.0, 0.0, 8.0, [0, 0, 0, 0], C.GL_NICEST)
        draw(gl, [(0, 0, 3 * zsign), (32, 0, 3 * zsign), (32, 32, 3 * zsign), (0, 32, 3 * zsign)],
             (255, 255, 255, 255))
        img = ctx.color_buffer()[..., 0].astype(float)
        check(img, np.full(img.shape, 255 * 5 / 8), tolerance(numeric, "LINEAR", 1, 0, 8, 3),
              f"quad at z_eye = {3 * zsign}")


@pytest.mark.parametrize("numeric", BUILDS)
def test_fog_colour_clamp_and_limits(numeric):
    """Beyond END (LINEAR) a fragment takes FOG_COLOR, before START its own colour; FOG_COLOR
    is clamped to [0, 1] when specified (Fogfv and Fogxv) and reads back so."""
    ctx = make(numeric, 16, 16)
    gl = ctx.gl
    ortho(gl, 16, 16, 0.0, 64.0)
    set_fog(gl, "LINEAR", 1.0, 4.0, 8.0, [1.5, -0.5, 0.25, 2.0], C.GL_NICEST)
    assert gl.glGetFloatv(C.GL_FOG_COLOR).tolist() == [1.0, 0.0, 0.25, 1.0]
    quad = [(0, 0, 0), (16, 0, 0), (16, 16, 0), (0, 16, 0)]
    for z, want in ((-20.0, [255, 0, 64, 77]), (-2.0, [10, 200, 30, 77])):
        draw(gl, [(x, y, z) for x, y, _ in quad], (10, 200, 30, 77))
        assert (ctx.color_buffer() == want).all(), f"z_eye {z}"
    gl.glFogxv(C.GL_FOG_COLOR, [-65536, 1 << 15, 3 << 16, 1 << 14])
    assert gl.glGetFixedv(C.GL_FOG_COLOR).tolist() == [0, 1 << 15, 1 << 16, 1 << 14]
    assert gl.glGetIntegerv(C.GL_FOG_COLOR)[2] == 2**31 - 1


def test_fog_state_defaults_and_queries():
    """Initial state (§3.8, Table 6.9) and the values set read back in every Get form."""
    gl = make("fixed").gl
    assert not gl.glIsEnabled(C.GL_FOG)
    assert gl.glGetIntegerv(C.GL_FOG_MODE) == C.GL_EXP
    assert gl.glGetFloatv(C.GL_FOG_DENSITY) == 1.0
    assert gl.glGetFloatv(C.GL_FOG_START) == 0.0
    assert gl.glGetFloatv(C.GL_FOG_END) == 1.0
    assert gl.glGetFloatv(C.GL_FOG_COLOR).tolist() == [0.0] * 4
    assert gl.glGetIntegerv(C.GL_FOG_HINT) == C.GL_DONT_CARE
    gl.glFogx(C.GL_FOG_MODE, C.GL_EXP2)
    gl.glFogx(C.GL_FOG_DENSITY, 3 << 15)
    gl.glFogx(C.GL_FOG_START, -(5 << 16))
    gl.glFogxv(C.GL_FOG_END, [7 << 16])
    assert gl.glGetIntegerv(C.GL_FOG_MODE) == C.GL_EXP2
    assert gl.glGetFixedv(C.GL_FOG_MODE) == C.GL_EXP2          # an enum is not scaled
    assert gl.glGetFloatv(C.GL_FOG_DENSITY) == 1.5
    assert gl.glGetFixedv(C.GL_FOG_START) == -(5 << 16)
    assert gl.glGetIntegerv(C.GL_FOG_END) == 7
    gl.glFogfv(C.GL_FOG_MODE, [C.GL_LINEAR])
    assert gl.glGetIntegerv(C.GL_FOG_MODE) == C.GL_LINEAR
    assert gl.glGetError() == 0


FOG_ERRORS = {
    "negative density": (lambda gl: gl.glFogf(C.GL_FOG_DENSITY, -0.5), C.GL_INVALID_VALUE),
    "negative density (x)": (lambda gl: gl.glFogx(C.GL_FOG_DENSITY, -1), C.GL_INVALID_VALUE),
    "bad mode": (lambda gl: gl.glFogf(C.GL_FOG_MODE, C.GL_FOG_DENSITY), C.GL_INVALID_ENUM),
    "bad mode (xv)": (lambda gl: gl.glFogxv(C.GL_FOG_MODE, [C.GL_FOG]), C.GL_INVALID_ENUM),
    "scalar FOG_COLOR": (lambda gl: gl.glFogx(C.GL_FOG_COLOR, 0), C.GL_INVALID_ENUM),
    "bad pname": (lambda gl: gl.glFogf(C.GL_FOG_HINT, 1.0), C.GL_INVALID_ENUM),
    "bad hint mode": (lambda gl: gl.glHint(C.GL_FOG_HINT, C.GL_FOG), C.GL_INVALID_ENUM),
}


@pytest.mark.parametrize("case", list(FOG_ERRORS))
def test_fog_errors_leave_state_unchanged(case):
    """Each bad call records its error (§3.8, §5.6) and changes no fog state."""
    call, err = FOG_ERRORS[case]
    gl = make("fixed").gl
    set_fog(gl, "EXP2", 0.75, -2.0, 9.0, [0.1, 0.2, 0.3, 0.4], C.GL_NICEST)
    names = (C.GL_FOG_MODE, C.GL_FOG_DENSITY, C.GL_FOG_START, C.GL_FOG_END, C.GL_FOG_COLOR, C.GL_FOG_HINT)
    before = [np.atleast_1d(gl.glGetFloatv(p)).tolist() for p in names]
    call(gl)
    assert gl.glGetError() == err
    assert [np.atleast_1d(gl.glGetFloatv(p)).tolist() for p in names] == before


# {============================================================
# the fixed build's exp, through rendered fog factors

def exp_fog_image(numeric: str, w: int = 256, h: int = 256) -> tuple[np.ndarray, np.ndarray]:
    """EXP fog with density 1 on one-pixel quads at |z_eye| = k/8192 (k = 0 .. w h - 1), white
    under black fog: each pixel is round(255 f) of its own exactly representable argument.
    Returns (red channel, arguments)."""
    ctx = make(numeric, w, h)
    gl = ctx.gl
    ortho(gl, w, h, 0.0, 16.0)
    set_fog(gl, "EXP", 1.0, 0.0, 1.0, [0, 0, 0, 0], C.GL_NICEST)
    args = np.arange(w * h, dtype=np.float64).reshape(h, w) / 8192.0
    ys, xs = np.mgrid[0:h, 0:w]
    x, y, z = xs.reshape(-1), ys.reshape(-1), -args.reshape(-1)
    corners = [(0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (0, 1)]
    v = np.stack([np.stack([x + dx, y + dy, z], axis=1) for dx, dy in corners], axis=1).reshape(-1, 3)
    draw(gl, v, (255, 255, 255, 255), C.GL_TRIANGLES)
    return ctx.color_buffer()[..., 0].astype(np.int64), args


def test_fixed_exp_against_double():
    """The fixed build's fog exp over 65536 arguments in [0, 8): within one 8-bit step of the
    double build, and where they differ the exact 255 e^-x lies within 0.01 step of a rounding
    boundary (so the 16.16 factor is off by less than 0.01/255)."""
    fixed, args = exp_fog_image("fixed")
    double, _ = exp_fog_image("double")
    exact = 255.0 * np.exp(-args)
    np.testing.assert_array_equal(double, np.floor(exact + 0.5).astype(np.int64))
    diff = fixed != double
    assert np.abs(fixed - double).max() <= 1
    tie_dist = np.abs(exact - np.floor(exact) - 0.5)
    witness = float(tie_dist[diff].max()) if diff.any() else 0.0
    assert witness < 0.01
    MEASURED["exp: pixels fixed != double (of 65536)"] = float(diff.sum())
    MEASURED["exp: max |fixed - 255 e^-x| (steps)"] = float(np.abs(fixed - exact).max())
    MEASURED["exp: max |double - 255 e^-x| (steps)"] = float(np.abs(double - exact).max())
    MEASURED["exp: largest tie distance where fixed != double (steps)"] = witness


def test_zz_print_measured():
    """Print what the fog tests measured (``pytest -s``)."""
    for key in sorted(MEASURED):
        print(f"fog measured  {key}: {MEASURED[key]:.5f}")
