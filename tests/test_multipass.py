"""Multipass techniques built from the per-fragment operations, end to end.

Four scenes an application draws with stencil, depth, clip planes and
blending: a stencil decal on coplanar polygons, a stencil-masked planar
mirror with a user clip plane, z-fail shadow-volume counting around a biased
zero (128), and additive light passes. Each runs unchanged on a gles context
and on Mesa (``gles.mesa.MesaContext``), and each picture is checked for what
the technique must show, then compared:

* fixed and float against double: every colour write rounds once to 8 bits,
  and the builds' arithmetic differs far below a step (16.16 and float32
  colours and lighting err by < 1e-4), so a pixel may differ by one step per
  rounding that reaches it (``STEPS``);
* every build against Mesa llvmpipe: the spec's tolerance, one step per
  channel (1/255 + 2^-13) per rounding, so ``STEPS`` again.

Pixels whose centre is near an edge may be covered by one implementation and
not the other (clipped or perspective vertices are computed with different
arithmetic); such pixels are those of the double picture with a neighbour of
another colour, and only they may differ by more, and at most 1% of the
window.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import mesa

W = H = 64
EDGE_SHARE = 0.01


# {============================================================
# drawing helpers (the same calls on gles and on Mesa)

def draw(gl: Any, verts: Any, rgba: Any = None, normals: Any = None, mode: int = C.GL_TRIANGLES) -> None:
    v = np.ascontiguousarray(verts, dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
    gl.glDisableClientState(C.GL_COLOR_ARRAY)
    if rgba is not None:
        gl.glColor4f(*(c / 255.0 for c in rgba))
    if normals is None:
        gl.glDisableClientState(C.GL_NORMAL_ARRAY)
    else:
        gl.glEnableClientState(C.GL_NORMAL_ARRAY)
        gl.glNormalPointer(C.GL_FLOAT, 0, np.ascontiguousarray(normals, dtype=np.float32))
    gl.glDrawArrays(mode, 0, len(v))


def quad(a: Any, b: Any, c: Any, d: Any) -> list:
    return [a, b, c, a, c, d]


def view(gl: Any, tilt: float = 35.0) -> None:
    """A camera above and in front of the origin, looking at it."""
    gl.glViewport(0, 0, W, H)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glFrustumf(-0.5, 0.5, -0.5, 0.5, 1.0, 40.0)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glTranslatef(0.0, -0.2, -4.2)
    gl.glRotatef(tilt, 1.0, 0.0, 0.0)


def start(gl: Any, tilt: float = 35.0) -> None:
    gl.glDisable(C.GL_DITHER)
    gl.glClearColor(0.0, 0.0, 0.0, 1.0)
    gl.glClearDepthf(1.0)
    gl.glClearStencil(0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_LESS)
    view(gl, tilt)


# {============================================================
# the four scenes; each returns the RGBA image (bottom row first)

FLOOR = quad((-1.5, 0, 1.5), (1.5, 0, 1.5), (1.5, 0, -1.5), (-1.5, 0, -1.5))
GREY, RED, BLUE = (120, 120, 120, 255), (220, 30, 30, 255), (40, 60, 230, 255)


def decal(gl: Any) -> np.ndarray:
    """A decal coplanar with the floor: stencil marks where the floor is visible, then the decal
    is drawn with the depth test off and stencil EQUAL 1 (so no depth fighting, and it is cut to
    the floor and hidden behind the occluder)."""
    start(gl)
    draw(gl, quad((-0.5, -0.1, 1.2), (0.8, -0.1, 1.2), (0.8, 0.6, 1.2), (-0.5, 0.6, 1.2)), RED)
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(C.GL_ALWAYS, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_REPLACE)
    draw(gl, FLOOR, GREY)
    gl.glStencilFunc(C.GL_EQUAL, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
    gl.glDisable(C.GL_DEPTH_TEST)
    decal_tris = [(-1.0, 0, -1.0), (2.2, 0, 0.4), (-0.6, 0, 1.45),      # reaches past the floor's edge
                  (0.2, 0, -1.4), (1.4, 0, -1.4), (1.4, 0, -0.2)]
    draw(gl, decal_tris, BLUE)
    gl.glEnable(C.GL_DEPTH_TEST)
    return gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)


PYRAMID_BASE = [(-0.6, -0.3, -1.2), (0.6, -0.3, -1.2), (0.6, -0.3, -0.2), (-0.6, -0.3, -0.2)]
PYRAMID_APEX = (0.0, 1.0, -0.7)


def pyramid(gl: Any) -> None:
    """Four smooth-coloured sides, the base below the floor (y = -0.3)."""
    cols = [(255, 60, 0, 255), (0, 200, 60, 255), (40, 80, 255, 255), (250, 220, 0, 255)]
    v, c = [], []
    for i in range(4):
        v += [PYRAMID_BASE[i], PYRAMID_BASE[(i + 1) % 4], PYRAMID_APEX]
        c += [cols[i], cols[(i + 1) % 4], (255, 255, 255, 255)]
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, np.asarray(c, dtype=np.uint8))
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, np.asarray(v, dtype=np.float32))
    gl.glDrawArrays(C.GL_TRIANGLES, 0, len(v))
    gl.glDisableClientState(C.GL_COLOR_ARRAY)


def mirror(gl: Any) -> np.ndarray:
    """A floor mirror: its area into stencil, the pyramid reflected (scale y by -1) where stencil
    is 1 and clipped to y <= 0 by a user clip plane (the reflected base would poke above the
    mirror), the mirror blended over it, then the pyramid itself."""
    start(gl, 18.0)
    gl.glShadeModel(C.GL_SMOOTH)
    mirror_quad = quad((-1.4, 0, 0.4), (1.4, 0, 0.4), (1.4, 0, -1.4), (-1.4, 0, -1.4))
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(C.GL_ALWAYS, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_REPLACE)
    gl.glColorMask(False, False, False, False)
    gl.glDepthMask(False)
    draw(gl, mirror_quad)
    gl.glColorMask(True, True, True, True)
    gl.glDepthMask(True)
    gl.glStencilFunc(C.GL_EQUAL, 1, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
    gl.glClipPlanef(C.GL_CLIP_PLANE0, [0.0, -1.0, 0.0, 0.0])     # keep world y <= 0
    gl.glEnable(C.GL_CLIP_PLANE0)
    gl.glPushMatrix()
    gl.glScalef(1.0, -1.0, 1.0)
    pyramid(gl)
    gl.glPopMatrix()
    gl.glDisable(C.GL_CLIP_PLANE0)
    gl.glDisable(C.GL_STENCIL_TEST)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    draw(gl, mirror_quad, (60, 90, 160, 128))
    gl.glDisable(C.GL_BLEND)
    pyramid(gl)
    return gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)


LIGHT = np.array([0.6, 3.0, 0.4])
OCCLUDER = np.array([(-0.5, 1.0, -0.4), (0.0, 1.0, 0.7), (0.7, 1.0, -0.2)])   # wound as the front cap


def shadow_volume() -> list:
    """The occluder's shadow volume, closed (two caps, three sides), faces wound outwards."""
    far = OCCLUDER + (OCCLUDER - LIGHT) * 2.0            # extruded to y = -3, below the floor
    faces = [list(OCCLUDER), list(far[::-1])]
    for i in range(3):
        j = (i + 1) % 3
        faces += [[OCCLUDER[i], far[i], far[j]], [OCCLUDER[i], far[j], OCCLUDER[j]]]
    centre = np.vstack([OCCLUDER, far]).mean(axis=0)
    tris = []
    for f in faces:
        a, b, c = (np.asarray(p) for p in f)
        if np.dot(np.cross(b - a, c - a), (a + b + c) / 3 - centre) < 0:
            b, c = c, b
        tris += [a, b, c]
    return tris


def shadow(gl: Any) -> np.ndarray:
    """Z-fail (Carmack's reverse): ambient pass; volume front faces DECR and back faces INCR
    where they fail the depth test, around a stencil zero biased to 128 (the front faces go
    first, so counts dip below the bias); lit pass added where the count is 128."""
    start(gl)
    floor_dim, occ_dim = (40, 40, 40, 255), (0, 50, 0, 255)
    floor_lit, occ_lit = (150, 140, 110, 255), (20, 160, 40, 255)
    draw(gl, FLOOR, floor_dim)
    draw(gl, OCCLUDER, occ_dim)
    gl.glClearStencil(128)
    gl.glClear(C.GL_STENCIL_BUFFER_BIT)
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(C.GL_ALWAYS, 0, 0xFF)
    gl.glColorMask(False, False, False, False)
    gl.glDepthMask(False)
    gl.glEnable(C.GL_CULL_FACE)
    vol = shadow_volume()
    gl.glCullFace(C.GL_BACK)
    gl.glStencilOp(C.GL_KEEP, C.GL_DECR, C.GL_KEEP)
    draw(gl, vol)
    gl.glCullFace(C.GL_FRONT)
    gl.glStencilOp(C.GL_KEEP, C.GL_INCR, C.GL_KEEP)
    draw(gl, vol)
    gl.glDisable(C.GL_CULL_FACE)
    gl.glColorMask(True, True, True, True)
    gl.glStencilFunc(C.GL_EQUAL, 128, 0xFF)
    gl.glStencilOp(C.GL_KEEP, C.GL_KEEP, C.GL_KEEP)
    gl.glDepthFunc(C.GL_EQUAL)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    draw(gl, FLOOR, floor_lit)
    draw(gl, OCCLUDER, occ_lit)
    gl.glDisable(C.GL_BLEND)
    gl.glDepthMask(True)
    gl.glDepthFunc(C.GL_LESS)
    return gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)


def bumpy_grid(n: int = 12) -> tuple[np.ndarray, np.ndarray]:
    """A height field over [-1.5, 1.5]^2 as triangles with analytic per-vertex normals."""
    u = np.linspace(-1.5, 1.5, n + 1)
    x, z = np.meshgrid(u, u)
    y = 0.25 * np.sin(2 * x) * np.cos(2 * z)
    nx, nz = -0.5 * np.cos(2 * x) * np.cos(2 * z), 0.5 * np.sin(2 * x) * np.sin(2 * z)
    pos = np.stack([x, y, z], axis=-1)
    nrm = np.stack([nx, np.ones_like(x), nz], axis=-1)
    nrm /= np.linalg.norm(nrm, axis=-1, keepdims=True)
    idx = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)
            idx += [a, d, c, a, c, b]
    ii = np.array(idx)
    return pos[ii[:, 0], ii[:, 1]], nrm[ii[:, 0], ii[:, 1]]


LIGHTS = [((0.8, 0.3, 0.2, 1.0), (-2.0, 2.0, 1.0, 1.0)),
          ((0.2, 0.7, 0.3, 1.0), (2.0, 1.5, 0.5, 1.0)),
          ((0.2, 0.3, 0.9, 1.0), (0.0, 1.0, -1.0, 0.0))]


def additive(gl: Any) -> np.ndarray:
    """One diffuse light per pass: the first pass with ambient writes depth, the others add
    with ONE, ONE where the depth is EQUAL."""
    start(gl)
    pos, nrm = bumpy_grid()
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_LIGHT0)
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_DIFFUSE, [0.9, 0.9, 0.9, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [1.0, 1.0, 1.0, 1.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_AMBIENT, [0.0, 0.0, 0.0, 1.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, [0.0, 0.0, 0.0, 1.0])
    for k, (colour, position) in enumerate(LIGHTS):
        ambient = [0.08, 0.08, 0.1, 1.0] if k == 0 else [0.0, 0.0, 0.0, 1.0]
        gl.glLightModelfv(C.GL_LIGHT_MODEL_AMBIENT, ambient)
        gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, list(colour))
        gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, list(position))
        if k == 1:
            gl.glEnable(C.GL_BLEND)
            gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
            gl.glDepthFunc(C.GL_EQUAL)
            gl.glDepthMask(False)
        draw(gl, pos, normals=nrm)
    gl.glDisable(C.GL_BLEND)
    gl.glDisable(C.GL_LIGHTING)
    gl.glDepthMask(True)
    return gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)


SCENES: dict[str, tuple[Callable[[Any], np.ndarray], int]] = {
    # name: (scene, colour roundings that can reach one pixel)
    "decal": (decal, 1),
    "mirror": (mirror, 2),
    "shadow": (shadow, 2),
    "additive": (additive, 3),
}
STEPS = {name: steps for name, (_, steps) in SCENES.items()}


# {============================================================
# rendering and comparing

_IMAGES: dict[tuple[str, str], np.ndarray] = {}


def gles_image(scene: str, numeric: str) -> np.ndarray:
    key = (scene, numeric)
    if key not in _IMAGES:
        ctx = gles.Context(W, H, numeric=numeric, depth=24, stencil=8)
        _IMAGES[key] = SCENES[scene][0](ctx.gl).astype(np.int64)
        assert ctx.gl.glGetError() == 0
    return _IMAGES[key]


def mesa_image(scene: str, driver: str = "llvmpipe") -> np.ndarray:
    why = mesa.available(driver)
    if why is not None:
        pytest.skip(f"Mesa {driver} unavailable: {why}")
    key = (scene, "mesa-" + driver)
    if key not in _IMAGES:
        with mesa.MesaContext(W, H, driver=driver, depth=24, stencil=8) as m:
            _IMAGES[key] = SCENES[scene][0](m.gl).astype(np.int64)
            assert m.gl.glGetError() == 0
    return _IMAGES[key]


def edges(img: np.ndarray, tol: int) -> np.ndarray:
    """Pixels at a colour discontinuity of `img`, grown by one pixel: a second difference along
    a row, a column or a diagonal above 2 tol + 8 steps in some channel. Smooth shading, whose
    second differences are a few steps of rounding, is not an edge."""
    pad = np.pad(img, ((1, 1), (1, 1), (0, 0)), mode="edge")
    h, w = img.shape[:2]

    def at(dy: int, dx: int) -> np.ndarray:
        return pad[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]

    e = np.zeros((h, w), dtype=bool)
    for dy, dx in ((0, 1), (1, 0), (1, 1), (1, -1)):
        e |= (np.abs(at(dy, dx) + at(-dy, -dx) - 2 * img) > 2 * tol + 8).any(axis=-1)
    grown = np.pad(e, 1)
    out = np.zeros_like(e)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            out |= grown[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
    return out


def compare(got: np.ndarray, ref: np.ndarray, tol: int, what: str) -> str:
    """`got` within `tol` steps of `ref` except at edges of `ref` (at most EDGE_SHARE of the
    window); returns what was measured: the largest difference off the edges and the number
    of pixels beyond `tol`."""
    diff = np.abs(got - ref)
    bad = (diff > tol).any(axis=-1)
    edge = edges(ref, tol)
    inner = bad & ~edge
    if inner.any():
        y, x = np.argwhere(inner)[0]
        pytest.fail(f"{what}: {int(inner.sum())} pixels away from edges differ by more than {tol}; first at "
                    f"(x={x}, y={y}): {got[y, x].tolist()} vs {ref[y, x].tolist()}")
    assert bad.sum() <= EDGE_SHARE * W * H, f"{what}: {int(bad.sum())} edge pixels differ"
    return (f"max {int(diff[~edge].max(initial=0))} steps off edges ({int((~edge).sum())} pixels), "
            f"{int(bad.sum())} edge pixels beyond {tol} (largest {int(diff.max())})")


# {============================================================
# what each technique must show (checked on the double build and on Mesa)

def count(img: np.ndarray, rgba: Any, tol: int = 2) -> int:
    return int((np.abs(img - np.asarray(rgba)) <= tol).all(axis=-1).sum())


def expect_decal(img: np.ndarray) -> None:
    assert count(img, BLUE) > 300 and count(img, GREY) > 300 and count(img, RED) > 100
    # the decal never shows where the floor does not (background or occluder rows)
    bg = (img[..., :3] == 0).all(axis=-1)
    assert bg.sum() > 100


def expect_mirror(img: np.ndarray) -> None:
    # the reflection is seen through the mirror (blended: not the plain mirror colour everywhere)
    plain = np.round(np.array([60, 90, 160]) * 128 / 255).astype(int)
    on_mirror = (np.abs(img[..., :3] - plain) <= 2).all(axis=-1)
    assert on_mirror.sum() > 150
    assert (img[..., :3].sum(axis=-1) > 0).sum() > on_mirror.sum() + 100


def expect_shadow(img: np.ndarray) -> None:
    lit = count(img, (190, 180, 150, 255))
    dark = count(img, (40, 40, 40, 255))
    assert lit > 500 and dark > 30, (lit, dark)


def expect_additive(img: np.ndarray) -> None:
    assert (img[..., :3].max(axis=(0, 1)) > 100).all()


EXPECT = {"decal": expect_decal, "mirror": expect_mirror, "shadow": expect_shadow,
          "additive": expect_additive}
MEASURED: dict[str, str] = {}


@pytest.mark.parametrize("scene", list(SCENES))
def test_scene_shows_the_technique(scene):
    """The double build's picture shows what the technique is for."""
    EXPECT[scene](gles_image(scene, "double"))


class Without:
    """A GL namespace with some commands replaced (to take one part of a technique away)."""

    def __init__(self, gl: Any, **replace: Callable) -> None:
        self._gl, self._replace = gl, replace

    def __getattr__(self, name: str) -> Any:
        return self._replace.get(name) or getattr(self._gl, name)


def ablations(gl: Any) -> dict[str, tuple[str, Any]]:
    """scene -> (what is taken away, the GL namespace without it)."""
    def always(f: int, r: int, m: int) -> None:
        gl.glStencilFunc(C.GL_ALWAYS, r, m)

    return {
        "decal stencil": ("decal", Without(gl, glStencilFunc=always)),
        "mirror stencil": ("mirror", Without(gl, glStencilFunc=always)),
        "mirror clip plane": ("mirror", Without(gl, glEnable=lambda cap: None if cap == C.GL_CLIP_PLANE0
                                                else gl.glEnable(cap))),
        "shadow bias": ("shadow", Without(gl, glClearStencil=lambda s: gl.glClearStencil(0),
                                          glStencilFunc=lambda f, r, m: gl.glStencilFunc(f, r & 0x7F, m))),
    }


@pytest.mark.parametrize("part", ["decal stencil", "mirror stencil", "mirror clip plane", "shadow bias"])
def test_each_part_of_a_technique_matters(part):
    """Taking the stencil mask, the clip plane or the biased zero away changes the picture, so the
    comparisons above exercise them."""
    ctx = gles.Context(W, H, numeric="double", depth=24, stencil=8)
    scene, gl = ablations(ctx.gl)[part]
    changed = (SCENES[scene][0](gl).astype(np.int64) != gles_image(scene, "double")).any(axis=-1).sum()
    assert changed >= 15, f"without the {part.split(' ', 1)[1]} only {changed} pixels change"


@pytest.mark.parametrize("numeric", ["fixed", "float"])
@pytest.mark.parametrize("scene", list(SCENES))
def test_against_double(scene, numeric):
    """fixed and float within one step per rounding of the double build (edges aside)."""
    ref = gles_image(scene, "double")
    MEASURED[f"{scene} {numeric} vs double"] = compare(gles_image(scene, numeric), ref, STEPS[scene],
                                                       f"{scene} {numeric}")


@pytest.mark.parametrize("numeric", ["double", "float", "fixed"])
@pytest.mark.parametrize("scene", list(SCENES))
def test_against_mesa(scene, numeric):
    """Every build within the spec's tolerance of Mesa llvmpipe (edges aside); Mesa's picture
    shows the technique."""
    ref = mesa_image(scene)
    EXPECT[scene](ref)
    MEASURED[f"{scene} {numeric} vs llvmpipe"] = compare(gles_image(scene, numeric), ref, STEPS[scene],
                                                         f"{scene} {numeric} vs llvmpipe")


def test_zz_print_measured():
    """Print what each comparison measured (``pytest -s``)."""
    for key in sorted(MEASURED):
        print(f"multipass  {key}: {MEASURED[key]}")
