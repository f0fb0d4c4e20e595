"""Lighting: the lighting equation of section 2.12.1 and OES_matrix_palette.

Categories AmbLight AmbMat AmbScene DifLight DifMat DifMatNorm DifMatPos
EmitMat SpecExp SpecExpNorm SpecLight SpecMat SpecNorm SpotPos SpotExpPos
SpotExpDir AtnConst AtnPos RescaleNormal XFormNormal MatrixPalette.

Each test draws a grid of 8 x 8 cells, one case per cell, with flat shading:
a cell is two triangles whose provoking vertex is the cell's top-right
corner, so the whole cell shows the colour lit at that vertex and nothing is
interpolated. Expected colours come from the equation of 2.12.1 evaluated
here in float64 (:class:`Equation`), from the values the x commands were
given, with normals transformed as 2.10.3 says and light positions and spot
directions by the modelview current at the glLight call. Cases are chosen
away from the equation's discontinuities (a spot cone's edge, n . VP = 0
where the specular term switches on) and from exact rounding ties (a colour
halfway between two framebuffer values may round either way, and path
levels must not change the picture); a case closer than :data:`EDGE` or on a
tie is a bug in the test. Colours must match within the visual's tolerance.

Only x commands and FIXED, SHORT and UNSIGNED_BYTE arrays are used, so
every test runs in Common-Lite.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..harness import TestContext, Unsupported, conformance_test
from .geometry import MARGIN, ONE, WHITE, coverage, expect_coverage, fx, q16, rotate, scale, translate

EDGE = 1e-3              # distance (in cosine or n . VP) a case keeps from a discontinuity
N = 8                    # cells per row and column
USES = ("lighting", "shademodel")

# {============================================================
# the lighting equation (2.12.1) in float64


def unit(v: Sequence[float]) -> np.ndarray:
    a = np.asarray(v, dtype=np.float64)
    return a / np.linalg.norm(a)


class Equation:
    """The state 2.12.1 reads (eye coordinates) and the equation."""

    def __init__(self) -> None:
        self.lights: list[dict[str, Any]] = []
        for i in range(8):
            on = [1.0, 1.0, 1.0, 1.0] if i == 0 else [0.0, 0.0, 0.0, 1.0]
            self.lights.append({
                "ambient": np.array([0.0, 0.0, 0.0, 1.0]), "diffuse": np.array(on),
                "specular": np.array(on), "position": np.array([0.0, 0.0, 1.0, 0.0]),
                "direction": np.array([0.0, 0.0, -1.0]), "exponent": 0.0, "cutoff": 180.0,
                "k": [1.0, 0.0, 0.0], "enabled": False,
            })
        self.material = {
            "ambient": np.array([0.2, 0.2, 0.2, 1.0]), "diffuse": np.array([0.8, 0.8, 0.8, 1.0]),
            "specular": np.array([0.0, 0.0, 0.0, 1.0]), "emission": np.array([0.0, 0.0, 0.0, 1.0]),
            "shininess": 0.0,
        }
        self.model_ambient = np.array([0.2, 0.2, 0.2, 1.0])
        self.color_material = False

    def color(self, v: np.ndarray, n: np.ndarray,
              current: np.ndarray | None = None) -> tuple[np.ndarray, float]:
        """RGBA at eye position `v` (4) with eye normal `n` (3), and how far the
        case is from a discontinuity."""
        m = self.material
        track = self.color_material and current is not None
        a_cm = current if track else m["ambient"]
        d_cm = current if track else m["diffuse"]
        c = m["emission"][:3] + a_cm[:3] * self.model_ambient[:3]
        edge = math.inf
        vpos = v[:3] / v[3]
        for lt in self.lights:
            if not lt["enabled"]:
                continue
            p = lt["position"]
            att = 1.0
            if p[3] != 0:
                d = p[:3] / p[3] - vpos
                dist = float(np.linalg.norm(d))
                vp = d / dist
                k0, k1, k2 = lt["k"]
                att = 1.0 / (k0 + k1 * dist + k2 * dist * dist)
            else:
                vp = unit(p[:3])
            spot = 1.0
            if lt["cutoff"] != 180.0:
                cosang = float(-vp @ unit(lt["direction"]))
                cc = math.cos(math.radians(lt["cutoff"]))
                edge = min(edge, abs(cosang - cc))
                spot = max(cosang, 0.0) ** lt["exponent"] if cosang >= cc else 0.0
            ndvp = float(n @ vp)
            term = a_cm[:3] * lt["ambient"][:3] + max(ndvp, 0.0) * d_cm[:3] * lt["diffuse"][:3]
            spec = m["specular"][:3] * lt["specular"][:3]
            if spec.any():
                edge = min(edge, abs(ndvp))
            if ndvp > 0:
                ndh = float(n @ unit(vp + [0.0, 0.0, 1.0]))
                if ndh <= 0 and m["shininess"] == 0 and spec.any():
                    edge = 0.0        # 0^0 is not a case to test
                term = term + max(ndh, 0.0) ** m["shininess"] * spec
            c = c + att * spot * term
        out = np.empty(4)
        out[:3] = np.clip(c, 0.0, 1.0)
        out[3] = min(max(d_cm[3], 0.0), 1.0)
        return out, edge


def normal_from(values: Sequence[float], gltype: str) -> tuple[np.ndarray, np.ndarray]:
    """(array data, the normal the GL receives) for a normal given as FIXED or SHORT (Table 2.7)."""
    if gltype == "short":
        s = np.round(np.asarray(values, dtype=np.float64) * 32767).astype(np.int16)
        return s, (2.0 * s + 1.0) / 65535.0
    f = np.array([fx(a) for a in values], dtype=np.int32)
    return f, f / ONE


# {============================================================
# lit scenes


class Lit:
    """A lit grid of N x N flat-shaded cells: the GL state set with x
    commands and mirrored into an :class:`Equation`."""

    def __init__(self, t: TestContext) -> None:
        self.t = t
        self.gl = gl = t.gl
        t.ortho_pixels()
        t.clear()
        self.eq = Equation()
        self.mv = np.eye(4)
        self.size = t.width // N
        self.expected = np.zeros((t.height, t.width, 4))
        self.drawn = np.zeros((t.height, t.width), dtype=bool)
        self.labels: dict[int, str] = {}
        self.rescale = self.normalize = False
        gl.glShadeModel(gl.GL_FLAT)
        gl.glEnable(gl.GL_LIGHTING)
        t.check_gl_error("lighting set-up")

    # state

    def enable(self, cap: str, on: bool = True) -> None:
        gl = self.gl
        (gl.glEnable if on else gl.glDisable)(getattr(gl, cap))
        if cap.startswith("GL_LIGHT") and cap[8:].isdigit():
            self.eq.lights[int(cap[8:])]["enabled"] = on
        elif cap == "GL_COLOR_MATERIAL":
            self.eq.color_material = on
        elif cap == "GL_RESCALE_NORMAL":
            self.rescale = on
        elif cap == "GL_NORMALIZE":
            self.normalize = on

    def light(self, i: int, pname: str, *vals: float) -> None:
        gl = self.gl
        v = q16(vals)
        enum = getattr(gl, pname)
        if len(v) > 1:
            gl.glLightxv(gl.GL_LIGHT0 + i, enum, [fx(a) for a in v])
        else:
            gl.glLightx(gl.GL_LIGHT0 + i, enum, fx(v[0]))
        lt = self.eq.lights[i]
        if pname == "GL_POSITION":
            lt["position"] = self.mv @ v
        elif pname == "GL_SPOT_DIRECTION":
            lt["direction"] = self.mv[:3, :3] @ v
        elif pname == "GL_SPOT_EXPONENT":
            lt["exponent"] = float(v[0])
        elif pname == "GL_SPOT_CUTOFF":
            lt["cutoff"] = float(v[0])
        elif pname.endswith("_ATTENUATION"):
            lt["k"] = list(lt["k"])
            lt["k"][("GL_CONSTANT", "GL_LINEAR", "GL_QUADRATIC").index(pname.rsplit("_", 1)[0])] = float(v[0])
        else:
            lt[pname[3:].lower()] = v

    def material(self, pname: str, *vals: float) -> None:
        gl = self.gl
        v = q16(vals)
        if len(v) > 1:
            gl.glMaterialxv(gl.GL_FRONT_AND_BACK, getattr(gl, pname), [fx(a) for a in v])
        else:
            gl.glMaterialx(gl.GL_FRONT_AND_BACK, getattr(gl, pname), fx(v[0]))
        if pname == "GL_AMBIENT_AND_DIFFUSE":
            self.eq.material["ambient"] = self.eq.material["diffuse"] = v
        else:
            self.eq.material[pname[3:].lower()] = v if len(v) > 1 else float(v[0])

    def model_ambient(self, *rgba: float) -> None:
        v = q16(rgba)
        self.gl.glLightModelxv(self.gl.GL_LIGHT_MODEL_AMBIENT, [fx(a) for a in v])
        self.eq.model_ambient = v

    def black(self) -> None:
        """Everything zero (alpha 1) but LIGHT0 on, directional along +z: each test adds what it checks."""
        zero = (0.0, 0.0, 0.0, 1.0)
        for p in ("GL_AMBIENT", "GL_DIFFUSE", "GL_SPECULAR", "GL_EMISSION"):
            self.material(p, *zero)
        self.material("GL_SHININESS", 0.0)
        self.model_ambient(*zero)
        for p in ("GL_AMBIENT", "GL_DIFFUSE", "GL_SPECULAR"):
            self.light(0, p, *zero)
        self.light(0, "GL_POSITION", 0.0, 0.0, 1.0, 0.0)
        self.enable("GL_LIGHT0")

    def modelview(self, m: np.ndarray) -> np.ndarray:
        """glLoadMatrixx with `m` rounded to 16.16; returns the matrix loaded."""
        mq = q16(m)
        gl = self.gl
        gl.glMatrixMode(gl.GL_MODELVIEW)
        gl.glLoadMatrixx([fx(a) for a in mq.T.reshape(-1)])
        self.mv = mq
        return mq

    # drawing

    def sample(self, k: int) -> np.ndarray:
        """Eye position of cell k's provoking vertex at z = 0 (cells row-major from the bottom left)."""
        s = self.size
        return np.array([(k % N + 1) * s, (k // N + 1) * s, 0.0])

    def eye_normal(self, n: Sequence[float]) -> np.ndarray:
        """2.10.3: n M^-1 (M the modelview's 3x3), rescaled and normalised as enabled."""
        inv = np.linalg.inv(self.mv[:3, :3])
        n_eye = np.asarray(n, dtype=np.float64) @ inv
        if self.rescale:
            n_eye = n_eye / np.linalg.norm(inv[2, :])
        if self.normalize:
            n_eye = unit(n_eye)
        return n_eye

    def edge(self, k: int, normal: Sequence[float]) -> float:
        """How far cell k with `normal` would lie from a discontinuity (for choosing cases)."""
        return self.eq.color(np.append(self.sample(k), 1.0), self.eye_normal(normal), None)[1]

    def cell(self, k: int, normal: Sequence[float], label: str, *, z: float = 0.0, back: bool = False,
             gltype: str = "current", color: Sequence[float] | None = None, two_side: bool = False) -> None:
        """Draw cell k with `normal` (object space) given as the current normal
        ("current") or a FIXED or SHORT normal array, optionally a ubyte colour
        array, and record the colour 2.12.1 gives it. `back` winds it
        clockwise; `two_side` says back faces are lit with -n."""
        gl, s = self.gl, self.size
        x0, y0 = (k % N) * s, (k // N) * s
        x1, y1 = x0 + s, y0 + s
        corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0), (x1, y1)]
        if back:
            corners = [corners[1], corners[0], corners[2], corners[4], corners[3], corners[5]]
        inv = np.linalg.inv(self.mv)
        obj = q16([(inv @ [cx, cy, z, 1.0])[:3] for cx, cy in corners])
        gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
        gl.glVertexPointer(3, gl.GL_FIXED, 0, np.round(obj.reshape(-1) * ONE).astype(np.int32))
        if gltype == "current":
            n = q16(normal)
            gl.glNormal3x(*[fx(a) for a in n])
            gl.glDisableClientState(gl.GL_NORMAL_ARRAY)
        else:
            data, n = normal_from(normal, gltype)
            gl.glEnableClientState(gl.GL_NORMAL_ARRAY)
            gl.glNormalPointer(gl.GL_SHORT if gltype == "short" else gl.GL_FIXED, 0, np.tile(data, 6))
        current = None
        if color is not None:
            cub = np.asarray(color, dtype=np.uint8)
            gl.glEnableClientState(gl.GL_COLOR_ARRAY)
            gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, np.tile(cub, 6))
            current = cub / 255.0
        gl.glDrawArrays(gl.GL_TRIANGLES, 0, 6)
        gl.glDisableClientState(gl.GL_COLOR_ARRAY)
        gl.glDisableClientState(gl.GL_NORMAL_ARRAY)
        self.t.check_gl_error(f"drawing cell {k} ({label})")
        v = self.mv @ np.append(obj[5], 1.0)
        n_eye = self.eye_normal(n)
        if back and two_side:
            n_eye = -n_eye
        rgba, edge = self.eq.color(v, n_eye, current)
        if edge < EDGE:
            self.t.fail(f"test bug: cell {k} ({label}) lies {edge:.2g} from a discontinuity of 2.12.1")
        for c, bits in zip(rgba, self.t.visual.bits):
            top = (1 << bits) - 1
            if bits and abs(c * top - math.floor(c * top) - 0.5) < 1e-6:
                self.t.fail(f"test bug: cell {k} ({label}) expects {c} = a rounding tie at {bits} bits")
        self.expected[y0:y1, x0:x1] = rgba
        self.drawn[y0:y1, x0:x1] = True
        self.labels[k] = label

    def check(self, where: str) -> None:
        """Every drawn cell has its expected colour within the visual's tolerance."""
        img = self.t.read()
        tol = self.t.visual.color_tolerance()
        bad = self.drawn & (np.abs(img - self.expected) > tol).any(axis=-1)
        if bad.any():
            cells = sorted({int(y) // self.size * N + int(x) // self.size for y, x in zip(*np.nonzero(bad))})
            k = cells[0]
            y, x = (k // N) * self.size + self.size // 2, (k % N) * self.size + self.size // 2
            self.t.fail(f"{where}: {len(cells)} cells differ from 2.12.1; first cell {k} "
                        f"({self.labels[k]}): got {np.round(img[y, x], 4).tolist()}, "
                        f"expected {np.round(self.expected[y, x], 4).tolist()}")


def spot_case(lit: Lit, k: int, axis: Sequence[float], angle: float, dist: float = 12.0) -> None:
    """Place LIGHT0 so that the direction from it to cell k's sample makes
    `angle` degrees with the spot `axis`; set the spot direction to `axis`."""
    s = unit(axis)
    perp = unit(np.cross(s, [0.3, 1.0, 0.2]))
    u = rotate(angle, *perp)[:3, :3] @ s
    p = lit.sample(k) - dist * u
    lit.light(0, "GL_POSITION", *p, 1.0)
    lit.light(0, "GL_SPOT_DIRECTION", *s)


LEVELS = [0.0, 0.1, 0.23, 0.37, 0.44, 0.58, 0.71, 0.86, 1.0]


def levels3(k: int) -> tuple[float, float, float]:
    """A different RGB triple for each k < 64."""
    return LEVELS[k % 9], LEVELS[(k // 3 + 2) % 9], LEVELS[(5 * k + 1) % 9]


def fib_normals(count: int) -> np.ndarray:
    """Unit vectors spread over the sphere (a Fibonacci lattice)."""
    i = np.arange(count) + 0.5
    z = 1 - 2 * i / count
    r = np.sqrt(1 - z * z)
    ph = math.pi * (3 - math.sqrt(5)) * i
    return np.stack([r * np.cos(ph), r * np.sin(ph), z], axis=1)


# {============================================================
# ambient


@conformance_test("AmbLight", section="2.12.1", uses=USES)
def amb_light(t: TestContext) -> None:
    """a_cm * a_cl for light ambient colours, attenuated and cut by the cone like the other terms (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_AMBIENT", 1.0, 0.8, 0.55, 1.0)
    for k in range(48):
        rgb = levels3(k)
        lit.light(0, "GL_AMBIENT", *rgb, 1.0)
        lit.cell(k, (0.0, 0.0, 1.0), f"light ambient {rgb}")
    # a positional light: its ambient term is attenuated
    lit.light(0, "GL_AMBIENT", 1.0, 1.0, 1.0, 1.0)
    for k, k0 in zip(range(48, 56), (0.55, 1.0, 1.3, 1.7, 2.2, 3.1, 4.3, 7.9)):
        lit.light(0, "GL_POSITION", *(lit.sample(k) + [5.0, -3.0, 8.0]), 1.0)
        lit.light(0, "GL_CONSTANT_ATTENUATION", k0)
        lit.cell(k, (0.0, 0.0, 1.0), f"positional light, constant attenuation {k0}")
    lit.light(0, "GL_CONSTANT_ATTENUATION", 1.0)
    # a spotlight: no ambient outside its cone, all of it inside (exponent 0)
    lit.light(0, "GL_SPOT_CUTOFF", 30.0)
    for k, angle in zip(range(56, 64), (0.0, 10.0, 20.0, 27.0, 33.0, 45.0, 60.0, 120.0)):
        spot_case(lit, k, (0.2, -0.3, -1.0), angle)
        lit.cell(k, (0.0, 0.0, 1.0), f"spotlight, {angle} degrees off its axis (cutoff 30)")
    lit.check("AmbLight")


@conformance_test("AmbMat", section="2.12.1", uses=USES)
def amb_mat(t: TestContext) -> None:
    """a_cm * (a_cs + a_cl) for material ambient colours, with one and with two lights (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.model_ambient(0.3, 0.15, 0.4, 1.0)
    lit.light(0, "GL_AMBIENT", 0.55, 0.65, 0.3, 1.0)
    lit.light(1, "GL_AMBIENT", 0.3, 0.3, 0.55, 1.0)
    lit.light(1, "GL_POSITION", 1.0, 1.0, 1.0, 0.0)
    for k in range(64):
        if k == 32:
            lit.enable("GL_LIGHT1")
        rgb = levels3(k)
        lit.material("GL_AMBIENT", *rgb, 1.0)
        lit.cell(k, (0.0, 0.0, 1.0), f"material ambient {rgb}" + (", two lights" if k >= 32 else ""))
    lit.check("AmbMat")


@conformance_test("AmbScene", section="2.12.1", uses=USES)
def amb_scene(t: TestContext) -> None:
    """e_cm + a_cm * a_cs with no light enabled, for scene ambient colours (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.enable("GL_LIGHT0", False)
    lit.material("GL_AMBIENT", 0.8, 1.0, 0.55, 1.0)
    for k in range(64):
        rgb = levels3(k)
        if k == 48:
            lit.material("GL_AMBIENT", 1.0, 0.3, 0.65, 1.0)
            lit.material("GL_EMISSION", 0.15, 0.3, 0.0, 1.0)
        lit.model_ambient(*rgb, 1.0)
        lit.cell(k, fib_normals(64)[k], f"scene ambient {rgb}" + (", emission" if k >= 48 else ""))
    lit.check("AmbScene")


# {============================================================
# diffuse


@conformance_test("DifLight", section="2.12.1", uses=USES)
def dif_light(t: TestContext) -> None:
    """(n . VP) d_cm * d_cl for light diffuse colours (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 1.0, 0.8, 0.55, 1.0)
    for k in range(64):
        rgb = levels3(k)
        lit.light(0, "GL_DIFFUSE", *rgb, 1.0)
        lit.cell(k, (0.6, 0.0, 0.8), f"light diffuse {rgb}")
    lit.check("DifLight")


@conformance_test("DifMat", section="2.12.1", uses=USES)
def dif_mat(t: TestContext) -> None:
    """(n . VP) d_cm * d_cl for material diffuse colours; alpha is the diffuse material's (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.light(0, "GL_DIFFUSE", 1.0, 0.9, 0.8, 1.0)
    lit.light(0, "GL_POSITION", 0.0, 0.6, 0.8, 0.0)
    for k in range(64):
        rgb = levels3(k)
        alpha = LEVELS[(k * 7) % 9]
        lit.material("GL_DIFFUSE", *rgb, alpha)
        lit.cell(k, (0.0, 0.28, 0.96), f"material diffuse {rgb}, alpha {alpha}")
    lit.check("DifMat")


@conformance_test("DifMat.colormaterial", section="2.12.1", uses=USES)
def dif_mat_color_material(t: TestContext) -> None:
    """With COLOR_MATERIAL the current colour and the colour array are a_cm and d_cm (2.12.1, 2.12.3)."""
    lit = Lit(t)
    gl = lit.gl
    lit.black()
    lit.model_ambient(0.3, 0.3, 0.3, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.8, 0.8, 0.8, 1.0)
    lit.light(0, "GL_AMBIENT", 0.15, 0.15, 0.15, 1.0)
    lit.light(0, "GL_SPECULAR", 1.0, 1.0, 1.0, 1.0)
    lit.material("GL_SPECULAR", 0.3, 0.15, 0.0, 1.0)   # not tracked
    lit.material("GL_SHININESS", 4.0)
    lit.enable("GL_COLOR_MATERIAL")
    for k in range(32):
        rgba = [*levels3(k), LEVELS[(3 * k) % 9]]
        gl.glColor4x(*[fx(a) for a in rgba])
        lit.eq.material["ambient"] = lit.eq.material["diffuse"] = q16(rgba)
        lit.cell(k, (0.28, 0.0, 0.96), f"glColor4x {rgba} tracked")
    for k in range(32, 64):
        cub = [(37 * k) % 256, (91 * k + 40) % 256, (53 * k + 7) % 256, (29 * k + 100) % 256]
        lit.cell(k, (0.0, -0.28, 0.96), f"colour array {cub} tracked", color=cub)
    lit.check("DifMat.colormaterial")
    lit.enable("GL_COLOR_MATERIAL", False)


@conformance_test("DifMatNorm", section="2.12.1", uses=USES)
def dif_mat_norm(t: TestContext) -> None:
    """max(n . VP, 0) for normals all round, as glNormal3x, FIXED and SHORT arrays (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 0.8, 1.0, 0.55, 1.0)
    lit.light(0, "GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    lit.light(0, "GL_POSITION", 0.48, 0.6, 0.64, 0.0)
    normals = fib_normals(64)
    for k in range(64):
        kind = ("current", "fixed", "short")[k % 3]
        lit.cell(k, normals[k], f"normal {np.round(normals[k], 3).tolist()} ({kind})", gltype=kind)
    lit.check("DifMatNorm")


@conformance_test("DifMatNorm.twoside", section="2.12.1", uses=USES)
def dif_mat_norm_two_side(t: TestContext) -> None:
    """LIGHT_MODEL_TWO_SIDE: back faces are lit with -n; without it like front faces (2.12.1)."""
    lit = Lit(t)
    gl = lit.gl
    lit.black()
    lit.material("GL_DIFFUSE", 0.8, 1.0, 0.55, 1.0)
    lit.material("GL_AMBIENT", 0.3, 0.15, 0.3, 1.0)
    lit.model_ambient(0.55, 0.55, 0.55, 1.0)
    lit.light(0, "GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    lit.light(0, "GL_POSITION", 0.48, 0.6, 0.64, 0.0)
    normals = fib_normals(32)
    for two in (False, True):
        gl.glLightModelx(gl.GL_LIGHT_MODEL_TWO_SIDE, ONE if two else 0)
        if bool(gl.glGetBooleanv(gl.GL_LIGHT_MODEL_TWO_SIDE)) != two:
            t.fail(f"LIGHT_MODEL_TWO_SIDE does not read {two} after glLightModelx set it")
        for j in range(32):
            k = 32 * two + j
            back = j % 2 == 1
            lit.cell(k, normals[j], f"{'back' if back else 'front'} face, two-sided {two}", back=back,
                     two_side=two)
    lit.check("DifMatNorm.twoside")
    gl.glLightModelx(gl.GL_LIGHT_MODEL_TWO_SIDE, 0)


@conformance_test("DifMatPos", section="2.12.1", uses=USES)
def dif_mat_pos(t: TestContext) -> None:
    """VP from positional lights (w = 1, 2, 1/2) and directional ones (w = 0) (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 1.0, 0.9, 0.65, 1.0)
    lit.light(0, "GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    offsets = fib_normals(64) * 20.0
    for k in range(64):
        off = offsets[k] * [1.0, 1.0, 0.5] + [0.0, 0.0, 6.0]
        w = (1.0, 2.0, 0.5, 0.0)[k % 4]
        pos = off if w == 0 else (lit.sample(k) + off) * w
        lit.light(0, "GL_POSITION", *pos, w)
        lit.cell(k, (0.0, 0.0, 1.0), f"light at {np.round(pos, 2).tolist()}, w {w}")
    lit.check("DifMatPos")


# {============================================================
# emission


@conformance_test("EmitMat", section="2.12.1", uses=USES)
def emit_mat(t: TestContext) -> None:
    """e_cm adds to the rest, and the sum is clamped to [0, 1] (2.12.1, 2.12.6)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 0.55, 0.3, 0.8, 1.0)
    lit.material("GL_AMBIENT", 0.3, 0.55, 0.3, 1.0)
    lit.model_ambient(0.3, 0.3, 0.3, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.55, 0.55, 0.55, 1.0)
    for k in range(64):
        rgb = levels3(k)
        if k == 32:
            lit.enable("GL_LIGHT0", False)
        lit.material("GL_EMISSION", *rgb, 1.0)
        lit.cell(k, (0.0, 0.6, 0.8), f"emission {rgb}" + (", no light" if k >= 32 else ""))
    lit.check("EmitMat")


# {============================================================
# specular


def _specular_setup(lit: Lit) -> None:
    lit.black()
    lit.light(0, "GL_SPECULAR", 1.0, 1.0, 1.0, 1.0)
    lit.material("GL_SPECULAR", 1.0, 0.8, 0.55, 1.0)


def tilted(nz: float, azimuth: float = 0.0) -> np.ndarray:
    """A unit normal at angle acos(nz) from +z."""
    r = math.sqrt(max(1.0 - nz * nz, 0.0))
    return np.array([r * math.cos(azimuth), r * math.sin(azimuth), nz])


SHININESS = [0.0, 0.5, 1.0, 2.0, 3.5, 5.0, 8.0, 10.0, 16.0, 20.0, 25.5, 32.0, 40.0, 50.0, 64.0, 75.25,
             80.0, 90.0, 100.0, 110.0, 120.0, 125.0, 127.0, 128.0]


@conformance_test("SpecExp", section="2.12.1", uses=USES)
def spec_exp(t: TestContext) -> None:
    """(n . h)^s_rm for shininess 0..128 (h = VP + (0, 0, 1), normalised) (2.12.1)."""
    lit = Lit(t)
    _specular_setup(lit)
    for k in range(64):
        s = SHININESS[k % len(SHININESS)]
        nz = (0.999, 0.99, 0.97)[k // len(SHININESS)]
        lit.material("GL_SHININESS", s)
        lit.cell(k, tilted(nz, k), f"shininess {s}, n . h = {nz}")
    lit.check("SpecExp")


@conformance_test("SpecExpNorm", section="2.12.1", uses=USES)
def spec_exp_norm(t: TestContext) -> None:
    """Shininess against the angle between n and h, with a light off the viewing axis (2.12.1)."""
    lit = Lit(t)
    _specular_setup(lit)
    lit.light(0, "GL_POSITION", 0.3, -0.2, 1.0, 0.0)
    h = unit(unit([0.3, -0.2, 1.0]) + [0.0, 0.0, 1.0])
    perp = unit(np.cross(h, [1.0, 0.0, 0.0]))
    for k in range(64):
        s = (1.0, 4.0, 10.0, 24.0, 50.0, 80.0, 112.0, 128.0)[k // 8]
        ang = (0.0, 1.0, 2.5, 5.0, 8.0, 12.0, 20.0, 35.0)[k % 8]
        n = rotate(ang, *perp)[:3, :3] @ h
        lit.material("GL_SHININESS", s)
        lit.cell(k, n, f"shininess {s}, n {ang} degrees from h")
    lit.check("SpecExpNorm")


@conformance_test("SpecLight", section="2.12.1", uses=USES)
def spec_light(t: TestContext) -> None:
    """(n . h)^s s_cm * s_cl for light specular colours (2.12.1)."""
    lit = Lit(t)
    _specular_setup(lit)
    lit.material("GL_SPECULAR", 1.0, 1.0, 1.0, 1.0)
    lit.material("GL_SHININESS", 10.0)
    for k in range(64):
        rgb = levels3(k)
        lit.light(0, "GL_SPECULAR", *rgb, 1.0)
        lit.cell(k, tilted(0.97, k), f"light specular {rgb}")
    lit.check("SpecLight")


@conformance_test("SpecMat", section="2.12.1", uses=USES)
def spec_mat(t: TestContext) -> None:
    """(n . h)^s s_cm * s_cl for material specular colours, with diffuse and ambient terms (2.12.1)."""
    lit = Lit(t)
    _specular_setup(lit)
    lit.material("GL_SHININESS", 6.0)
    lit.material("GL_DIFFUSE", 0.3, 0.3, 0.3, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.55, 0.55, 0.55, 1.0)
    lit.light(0, "GL_SPECULAR", 1.0, 0.9, 0.8, 1.0)
    for k in range(64):
        rgb = levels3(k)
        lit.material("GL_SPECULAR", *rgb, 1.0)
        lit.cell(k, tilted(0.95, 2 * k), f"material specular {rgb}")
    lit.check("SpecMat")


@conformance_test("SpecNorm", section="2.12.1", uses=USES)
def spec_norm(t: TestContext) -> None:
    """Specular for normals all round; none where n . VP <= 0 even if n . h > 0 (f_i of 2.12.1)."""
    lit = Lit(t)
    _specular_setup(lit)
    lit.material("GL_SHININESS", 4.0)
    lit.material("GL_DIFFUSE", 0.15, 0.15, 0.15, 1.0)
    lit.light(0, "GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    # a grazing directional light: many normals see h but not the light
    lit.light(0, "GL_POSITION", 0.995, 0.0, 0.1, 0.0)
    vp = unit([0.995, 0.0, 0.1])
    for k in range(32):
        n = tilted(math.cos(math.radians(3.0 * k - 40.0)), 0.0 if k < 27 else 0.5)
        if 3.0 * k - 40.0 < 0:
            n[0] = -n[0]
        if abs(n @ vp) < 0.01:
            n = tilted(0.9, 2.0)
        lit.cell(k, n, f"grazing light, normal {np.round(n, 3).tolist()}, n . VP {n @ vp:.3f}")
    # a positional light over the grid
    lit.light(0, "GL_POSITION", 30.0, 34.0, 10.0, 1.0)
    normals = fib_normals(40)[:32]
    for j in range(32):
        k = 32 + j
        n = normals[j]
        vp = unit(np.array([30.0, 34.0, 10.0]) - lit.sample(k))
        if abs(n @ vp) < 0.01:
            n = unit(n + [0.0, 0.0, 0.2])
        lit.cell(k, n, f"positional light, normal {np.round(n, 3).tolist()}")
    lit.check("SpecNorm")


# {============================================================
# spotlights


@conformance_test("SpotPos", section="2.12.1", uses=USES)
def spot_pos(t: TestContext) -> None:
    """A spotlight lights exactly the cases inside its cone, for cutoffs 5..90 and 180 (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_AMBIENT", 0.55, 0.8, 1.0, 1.0)
    lit.material("GL_DIFFUSE", 1.0, 0.8, 0.55, 1.0)
    lit.light(0, "GL_AMBIENT", 0.3, 0.3, 0.3, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.8, 0.8, 0.8, 1.0)
    fractions = (0.0, 0.4, 0.8, 0.9, 1.1, 1.25, 1.6, 2.5)
    for k in range(64):
        cutoff = (5.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0, 180.0)[k // 8]
        frac = fractions[k % 8]
        angle = min(frac * (cutoff if cutoff != 180.0 else 60.0), 170.0)
        if cutoff < 30.0 and frac in (0.9, 1.1):
            angle = cutoff * (0.75 if frac < 1 else 1.3)
        lit.light(0, "GL_SPOT_CUTOFF", cutoff)
        spot_case(lit, k, (0.3, -0.2, -1.0), angle)
        lit.cell(k, (0.0, 0.0, 1.0), f"cutoff {cutoff}, {angle:.2f} degrees off the axis")
    lit.check("SpotPos")


EXPONENTS = (0.0, 1.0, 2.0, 5.0, 10.0, 30.0, 64.0, 128.0)


@conformance_test("SpotExpPos", section="2.12.1", uses=USES)
def spot_exp_pos(t: TestContext) -> None:
    """(-VP . s)^s_rl for spot exponents 0..128 and light positions round the axis (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    lit.material("GL_AMBIENT", 1.0, 0.8, 0.55, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.8, 1.0, 0.55, 1.0)
    lit.light(0, "GL_AMBIENT", 0.3, 0.3, 0.3, 1.0)
    lit.light(0, "GL_SPOT_CUTOFF", 70.0)
    for k in range(64):
        e = EXPONENTS[k // 8]
        angle = (0.0, 2.0, 5.0, 10.0, 18.0, 30.0, 45.0, 65.0)[k % 8]
        lit.light(0, "GL_SPOT_EXPONENT", e)
        spot_case(lit, k, (-0.25, 0.1, -1.0), angle, dist=10.0 + k % 5)
        lit.cell(k, (0.0, 0.0, 1.0), f"exponent {e}, {angle} degrees off the axis")
    lit.check("SpotExpPos")


@conformance_test("SpotExpDir", section="2.12.1", uses=USES)
def spot_exp_dir(t: TestContext) -> None:
    """(-VP . s)^s_rl for spot exponents 0..128 as the spot direction turns, the light fixed (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    lit.light(0, "GL_DIFFUSE", 1.0, 0.8, 1.0, 1.0)
    lit.light(0, "GL_SPOT_CUTOFF", 90.0)
    for k in range(64):
        e = EXPONENTS[k // 8]
        angle = (0.0, 3.0, 7.0, 12.0, 20.0, 32.0, 50.0, 80.0)[k % 8]
        lit.light(0, "GL_SPOT_EXPONENT", e)
        lit.light(0, "GL_POSITION", *(lit.sample(k) + [2.0, 3.0, 9.0]), 1.0)
        axis = unit([-2.0, -3.0, -9.0])
        perp = unit(np.cross(axis, [1.0, 0.0, 0.0]))
        lit.light(0, "GL_SPOT_DIRECTION", *(rotate(angle, *perp)[:3, :3] @ axis))
        lit.cell(k, (0.0, 0.0, 1.0), f"exponent {e}, axis {angle} degrees away from the sample")
    lit.check("SpotExpDir")


# {============================================================
# attenuation


@conformance_test("AtnConst", section="2.12.1", uses=USES)
def atn_const(t: TestContext) -> None:
    """1 / k0 scales a positional light's whole term; directional lights are not attenuated (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_AMBIENT", 0.55, 0.55, 0.55, 1.0)
    lit.material("GL_DIFFUSE", 0.8, 0.55, 1.0, 1.0)
    lit.material("GL_SPECULAR", 0.55, 0.55, 0.55, 1.0)
    lit.material("GL_SHININESS", 5.0)
    lit.light(0, "GL_AMBIENT", 0.3, 0.3, 0.3, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.55, 0.55, 0.55, 1.0)
    lit.light(0, "GL_SPECULAR", 0.55, 0.55, 0.55, 1.0)
    for k in range(64):
        k0 = (0.75, 1.0, 1.25, 1.5, 2.0, 3.0, 5.0, 16.0)[k % 8]
        w = 0.0 if k >= 48 else 1.0
        off = [3.0 - k % 5, 2.0 - k % 3, 8.0]
        lit.light(0, "GL_CONSTANT_ATTENUATION", k0)
        lit.light(0, "GL_POSITION", *(off if w == 0 else lit.sample(k) + off), w)
        lit.cell(k, tilted(0.98, k), f"k0 {k0}, " + ("directional" if w == 0 else "positional"))
    lit.check("AtnConst")


@conformance_test("AtnPos", section="2.12.1", uses=USES)
def atn_pos(t: TestContext) -> None:
    """1 / (k0 + k1 d + k2 d^2) for distances 2..120 (2.12.1)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_AMBIENT", 0.55, 0.55, 0.55, 1.0)
    lit.material("GL_DIFFUSE", 1.0, 0.8, 0.55, 1.0)
    lit.light(0, "GL_AMBIENT", 0.55, 0.55, 0.55, 1.0)
    lit.light(0, "GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    dists = (2.0, 5.0, 10.0, 20.0, 35.0, 50.0, 80.0, 120.0)
    for k in range(64):
        d = dists[k % 8]
        row = k // 8
        k0 = (1.0, 1.0, 0.5, 1.0, 1.0, 1.0, 0.25, 1.0)[row]
        k1 = (1 / 16, 1 / 64, 1 / 128, 0.0, 0.0, 0.0, 1 / 32, 1 / 256)[row]
        k2 = (0.0, 0.0, 0.0, 1 / 256, 1 / 1024, 1 / 8192, 1 / 1024, 1 / 4096)[row]
        for pname, v in (("GL_CONSTANT", k0), ("GL_LINEAR", k1), ("GL_QUADRATIC", k2)):
            lit.light(0, f"{pname}_ATTENUATION", v)
        lit.light(0, "GL_POSITION", *(lit.sample(k) + d * unit([0.3, -0.4, 1.0])), 1.0)
        lit.cell(k, (0.0, 0.0, 1.0), f"distance {d}, k = ({k0}, {k1:.4g}, {k2:.4g})")
    lit.check("AtnPos")


# {============================================================
# normal transformation


def affine(lin: np.ndarray, tr: Sequence[float] = (0.0, 0.0, 0.0)) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = lin
    m[:3, 3] = tr
    return m


@conformance_test("RescaleNormal", section="2.10.3", uses=USES)
def rescale_normal(t: TestContext) -> None:
    """RESCALE_NORMAL multiplies by 1/|third row of M^-1|: unit normals stay unit under uniform scales."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 0.55, 0.8, 1.0, 1.0)
    lit.material("GL_AMBIENT", 0.15, 0.15, 0.15, 1.0)
    lit.light(0, "GL_AMBIENT", 1.0, 1.0, 1.0, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.8, 0.8, 0.8, 1.0)
    lit.light(0, "GL_POSITION", 0.3, 0.4, 0.866, 0.0)
    scales = (0.25, 0.5, 0.75, 1.5, 2.0, 3.0, 4.0, 8.0)
    normals = fib_normals(96)[:64]
    normals[:, 2] = np.abs(normals[:, 2])
    for k in range(64):
        row, s = k // 8, scales[k % 8]
        on = row not in (3, 7)
        lit.enable("GL_RESCALE_NORMAL", on)
        if row < 4:
            m, what = np.diag([s, s, s]), f"uniform scale {s}"
        elif row < 6:
            m, what = s * rotate(20.0 * k, 1.0, 2.0, 2.0)[:3, :3], f"uniform scale {s}, rotated"
        else:
            m, what = np.diag([s, 1.0, 2.0]) if row == 6 else np.diag([1.0, 0.5, s]), "non-uniform scale"
        lit.modelview(affine(m, (5.0, -3.0, 0.0)))
        lit.cell(k, normals[k], f"{what}, RESCALE_NORMAL {'on' if on else 'off'}")
    lit.enable("GL_RESCALE_NORMAL", False)
    lit.modelview(np.eye(4))
    lit.check("RescaleNormal")


@conformance_test("XFormNormal", section="2.10.3", uses=USES)
def xform_normal(t: TestContext) -> None:
    """Normals go through the inverse transpose of the modelview's 3x3; NORMALIZE makes them unit (2.10.3)."""
    lit = Lit(t)
    lit.black()
    lit.material("GL_DIFFUSE", 0.8, 1.0, 0.55, 1.0)
    lit.material("GL_SPECULAR", 0.55, 0.55, 0.55, 1.0)
    lit.material("GL_SHININESS", 8.0)
    lit.light(0, "GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    lit.light(0, "GL_SPECULAR", 1.0, 1.0, 1.0, 1.0)
    lit.light(0, "GL_POSITION", 0.2, 0.5, 0.84, 0.0)
    normals = fib_normals(100)[:64]
    normals[:, 2] = np.abs(normals[:, 2]) + 0.2
    rng = np.random.default_rng(7)
    for k in range(64):
        row = k // 8
        for _ in range(20):   # a matrix that keeps the case away from n . VP = 0
            if row < 2:
                m, what, norm = rotate(23.0 * k + 5.0, *rng.normal(size=3))[:3, :3], "rotation", False
            elif row < 4:
                m, what, norm = np.diag(rng.uniform(0.3, 3.0, size=3)), "non-uniform scale", True
            elif row < 6:
                m = np.eye(3) + rng.uniform(-0.6, 0.6, size=(3, 3))
                what, norm = "general matrix", True
            elif row < 7:
                m, what, norm = np.eye(3), "translation only", False
            else:
                m = rotate(40.0 * k, 1.0, -1.0, 0.5)[:3, :3] @ np.diag([2.0, 0.5, 1.0])
                what, norm = "scale then rotation", True
            lit.enable("GL_NORMALIZE", norm)
            lit.modelview(affine(m, (1.0 * row, -2.0, 0.5)))
            n = unit(normals[k] @ lit.mv[:3, :3]) if not norm else normals[k]
            if lit.edge(k, n) > 0.01:
                break
        lit.cell(k, n, f"{what}, NORMALIZE {'on' if norm else 'off'}")
    lit.enable("GL_NORMALIZE", False)
    lit.modelview(np.eye(4))
    lit.check("XFormNormal")


@conformance_test("XFormNormal.light", section="2.12.1", uses=USES)
def xform_normal_light(t: TestContext) -> None:
    """Light positions and spot directions take the modelview of the glLight call, and stay (2.12.1)."""
    lit = Lit(t)
    gl = lit.gl
    lit.black()
    lit.material("GL_DIFFUSE", 1.0, 1.0, 1.0, 1.0)
    lit.material("GL_AMBIENT", 1.0, 1.0, 1.0, 1.0)
    lit.light(0, "GL_DIFFUSE", 0.8, 0.55, 1.0, 1.0)
    lit.light(0, "GL_AMBIENT", 0.15, 0.15, 0.15, 1.0)
    lit.light(1, "GL_DIFFUSE", 0.3, 0.55, 0.0, 1.0)
    lit.enable("GL_LIGHT1")
    # non-uniform scale: the spot direction takes M's 3x3, not its inverse transpose
    m1 = lit.modelview(translate(40.0, 24.0, 3.0) @ rotate(70.0, 0.0, 0.0, 1.0) @ scale(2.0, 0.5, 1.5))
    lit.light(0, "GL_POSITION", 4.0, -8.0, 6.0, 1.0)
    lit.light(0, "GL_SPOT_DIRECTION", 0.5, 0.25, -1.0)
    lit.light(0, "GL_SPOT_CUTOFF", 50.0)
    lit.light(0, "GL_SPOT_EXPONENT", 2.0)
    lit.light(1, "GL_POSITION", 1.0, 0.0, 1.0, 0.0)
    want = m1 @ q16([4.0, -8.0, 6.0, 1.0])
    got = np.asarray(gl.glGetLightxv(gl.GL_LIGHT0, gl.GL_POSITION), dtype=np.float64) / ONE
    if np.abs(got - want).max() > 2.0**-8:
        t.fail(f"POSITION set under a modelview reads back {got.tolist()}, expected eye coordinates "
               f"{want.tolist()}")
    mvs = [m1, np.eye(4), translate(-10.0, 5.0, 2.0) @ rotate(-35.0, 1.0, 1.0, 0.0) @ scale(3.0, 3.0, 3.0),
           rotate(90.0, 0.0, 1.0, 0.0)]
    for k in range(64):
        lit.modelview(mvs[k // 16])
        n_eye = fib_normals(64)[k]
        n_eye[2] = abs(n_eye[2]) + 0.3
        # send the object normal whose eye normal is n_eye (n_eye = n M^-1)
        lit.cell(k, n_eye @ lit.mv[:3, :3], f"drawn under modelview {k // 16}")
    lit.check("XFormNormal.light")
    lit.modelview(np.eye(4))


# {============================================================
# errors (2.5): the command is ignored


def _light_state(gl: Any) -> list:
    out = []
    for i in range(8):
        for p in ("GL_AMBIENT", "GL_DIFFUSE", "GL_SPECULAR", "GL_POSITION", "GL_SPOT_DIRECTION",
                  "GL_SPOT_EXPONENT", "GL_SPOT_CUTOFF", "GL_CONSTANT_ATTENUATION", "GL_LINEAR_ATTENUATION",
                  "GL_QUADRATIC_ATTENUATION"):
            out.append((i, p, np.atleast_1d(gl.glGetLightxv(gl.GL_LIGHT0 + i, getattr(gl, p))).tolist()))
    for face in ("GL_FRONT", "GL_BACK"):
        for p in ("GL_AMBIENT", "GL_DIFFUSE", "GL_SPECULAR", "GL_EMISSION", "GL_SHININESS"):
            v = gl.glGetMaterialxv(getattr(gl, face), getattr(gl, p))
            out.append((face, p, np.atleast_1d(v).tolist()))
    model = np.atleast_1d(gl.glGetFixedv(gl.GL_LIGHT_MODEL_AMBIENT)).tolist()
    out.append(("model", "GL_LIGHT_MODEL_AMBIENT", model))
    return out


def _expect_errors(t: TestContext, calls: list[tuple[str, Any, str]]) -> None:
    """Each call records its error and leaves every light, material and light-model value as it was."""
    gl = t.gl
    t.clear()
    gl.glLightx(gl.GL_LIGHT0, gl.GL_SPOT_EXPONENT, 7 * ONE)
    gl.glLightx(gl.GL_LIGHT0, gl.GL_SPOT_CUTOFF, 33 * ONE)
    gl.glMaterialx(gl.GL_FRONT_AND_BACK, gl.GL_SHININESS, 9 * ONE)
    t.check_gl_error("setting known values")
    before = _light_state(gl)
    problems = []
    for what, call, err in calls:
        call(gl)
        got = gl.glGetError()
        if got != getattr(gl, err):
            problems.append(f"{what}: glGetError() is 0x{got:04X}, expected {err}")
        after = _light_state(gl)
        if after != before:
            changed = [f"{a[:2]} {a[2]} -> {b[2]}" for a, b in zip(before, after) if a != b][:2]
            problems.append(f"{what} changed the state: {'; '.join(changed)}")
            before = after
    if problems:
        t.fail(f"illegal calls misbehave ({len(problems)} problems in {len(calls)} calls): "
               + " | ".join(problems))


@conformance_test("AmbLight.errors", section="2.12.1")
def amb_light_errors(t: TestContext) -> None:
    """Light enums beyond MAX_LIGHTS and scalar commands with vector pnames are INVALID_ENUM (2.5, 2.12.1)."""
    n = int(t.gl.glGetIntegerv(t.gl.GL_MAX_LIGHTS))
    if n < 8:
        t.fail(f"MAX_LIGHTS is {n}, at least 8 required")
    _expect_errors(t, [
        ("glLightxv(LIGHT0 + MAX_LIGHTS, AMBIENT)",
         lambda g: g.glLightxv(g.GL_LIGHT0 + n, g.GL_AMBIENT, [ONE, ONE, ONE, ONE]), "GL_INVALID_ENUM"),
        ("glLightx(LIGHT0, AMBIENT)", lambda g: g.glLightx(g.GL_LIGHT0, g.GL_AMBIENT, ONE),
         "GL_INVALID_ENUM"),
        ("glLightx(LIGHT0, POSITION)", lambda g: g.glLightx(g.GL_LIGHT0, g.GL_POSITION, ONE),
         "GL_INVALID_ENUM"),
        ("glLightx(LIGHT0, SPOT_DIRECTION)", lambda g: g.glLightx(g.GL_LIGHT0, g.GL_SPOT_DIRECTION, ONE),
         "GL_INVALID_ENUM"),
        ("glLightModelx(LIGHT_MODEL_AMBIENT)", lambda g: g.glLightModelx(g.GL_LIGHT_MODEL_AMBIENT, ONE),
         "GL_INVALID_ENUM"),
    ])


@conformance_test("AmbMat.errors", section="2.12.1")
def amb_mat_errors(t: TestContext) -> None:
    """Faces other than FRONT_AND_BACK and scalar forms of colour pnames are INVALID_ENUM (2.5, 2.12.1)."""
    _expect_errors(t, [
        ("glMaterialxv(FRONT, AMBIENT)",
         lambda g: g.glMaterialxv(g.GL_FRONT, g.GL_AMBIENT, [ONE, 0, 0, ONE]), "GL_INVALID_ENUM"),
        ("glMaterialxv(BACK, DIFFUSE)",
         lambda g: g.glMaterialxv(g.GL_BACK, g.GL_DIFFUSE, [ONE, 0, 0, ONE]), "GL_INVALID_ENUM"),
        ("glMaterialx(FRONT_AND_BACK, AMBIENT)",
         lambda g: g.glMaterialx(g.GL_FRONT_AND_BACK, g.GL_AMBIENT, ONE), "GL_INVALID_ENUM"),
        ("glMaterialx(FRONT_AND_BACK, EMISSION)",
         lambda g: g.glMaterialx(g.GL_FRONT_AND_BACK, g.GL_EMISSION, ONE), "GL_INVALID_ENUM"),
    ])


@conformance_test("SpecExp.errors", section="2.12.1")
def spec_exp_errors(t: TestContext) -> None:
    """Shininess outside [0, 128] is INVALID_VALUE and changes nothing (2.5, 2.12.1)."""
    _expect_errors(t, [
        (f"glMaterialx(SHININESS, {v / ONE})",
         lambda g, v=v: g.glMaterialx(g.GL_FRONT_AND_BACK, g.GL_SHININESS, v), "GL_INVALID_VALUE")
        for v in (-ONE, -1, 128 * ONE + 1, 1000 * ONE)
    ])


@conformance_test("SpotExpPos.errors", section="2.12.1")
def spot_exp_errors(t: TestContext) -> None:
    """Spot exponents outside [0, 128] are INVALID_VALUE and change nothing (2.5, 2.12.1)."""
    _expect_errors(t, [
        (f"glLightx(SPOT_EXPONENT, {v / ONE})", lambda g, v=v: g.glLightx(g.GL_LIGHT0, g.GL_SPOT_EXPONENT, v),
         "GL_INVALID_VALUE") for v in (-ONE, -1, 128 * ONE + 1, 129 * ONE)
    ])


@conformance_test("SpotPos.errors", section="2.12.1")
def spot_pos_errors(t: TestContext) -> None:
    """Cutoffs outside [0, 90] other than 180 are INVALID_VALUE and change nothing (2.5, 2.12.1)."""
    _expect_errors(t, [
        (f"glLightx(SPOT_CUTOFF, {v / ONE})", lambda g, v=v: g.glLightx(g.GL_LIGHT0, g.GL_SPOT_CUTOFF, v),
         "GL_INVALID_VALUE") for v in (-ONE, -1, 90 * ONE + 1, 91 * ONE, 179 * ONE, 181 * ONE, 360 * ONE)
    ])


@conformance_test("AtnConst.errors", section="2.12.1")
def atn_errors(t: TestContext) -> None:
    """Negative attenuation factors are INVALID_VALUE and change nothing (2.5, 2.12.1)."""
    _expect_errors(t, [
        (f"glLightx({p}, {v / ONE})", lambda g, p=p, v=v: g.glLightx(g.GL_LIGHT0, getattr(g, p), v),
         "GL_INVALID_VALUE")
        for p in ("GL_CONSTANT_ATTENUATION", "GL_LINEAR_ATTENUATION", "GL_QUADRATIC_ATTENUATION")
        for v in (-1, -ONE)
    ])


# {============================================================
# MatrixPalette (OES_matrix_palette)


def _has_palette(gl: Any) -> None:
    ext = (gl.glGetString(gl.GL_EXTENSIONS) or b"").decode().split()
    if "GL_OES_matrix_palette" not in ext:
        raise Unsupported("GL_OES_matrix_palette is not in GL_EXTENSIONS (an optional extension)")


def _palette_strip() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A strip of 8 quads along x in object units, as separate triangles:
    positions (n, 3), bone indices (n, 2), weights (n, 2), normals (n, 3).
    The weight of bone 1 grows from 0 to 1 along the strip."""
    xs = np.linspace(-24.0, 24.0, 9)
    pos, idx, wts, nrm = [], [], [], []
    for i in range(8):
        quad = [(xs[i], -6.0), (xs[i + 1], -6.0), (xs[i + 1], 6.0), (xs[i], 6.0)]
        for j in (0, 1, 2, 0, 2, 3):
            x, y = quad[j]
            w1 = min(max((x + 16.0) / 32.0, 0.0), 1.0)
            pos.append((x, y, 0.0))
            idx.append((0, 1))
            wts.append((1.0 - w1, w1))
            nrm.append(unit([0.2 * x / 24.0, 0.3 * y / 6.0, 1.0]))
    return np.array(pos), np.array(idx, dtype=np.uint8), np.array(wts), np.array(nrm)


@conformance_test("MatrixPalette", section="OES_matrix_palette", uses=USES)
def matrix_palette(t: TestContext) -> None:
    """Skinning: eye = sum w_i M_i v for positions; lit normals per either form the extension allows."""
    gl = t.gl
    _has_palette(gl)
    w, h = t.width, t.height
    for pname, least in (("GL_MAX_PALETTE_MATRICES_OES", 9), ("GL_MAX_VERTEX_UNITS_OES", 3)):
        v = int(gl.glGetIntegerv(getattr(gl, pname)))
        if v < least:
            t.fail(f"{pname} is {v}, at least {least} required")
    units = int(gl.glGetIntegerv(gl.GL_MAX_VERTEX_UNITS_OES))
    npal = int(gl.glGetIntegerv(gl.GL_MAX_PALETTE_MATRICES_OES))
    gl.glCurrentPaletteMatrixOES(npal)
    t.check_gl_error(f"glCurrentPaletteMatrixOES({npal})", gl.GL_INVALID_VALUE)
    gl.glMatrixIndexPointerOES(units + 1, gl.GL_UNSIGNED_BYTE, 0, np.zeros(64, dtype=np.uint8))
    t.check_gl_error(f"glMatrixIndexPointerOES(size {units + 1})", gl.GL_INVALID_VALUE)
    gl.glWeightPointerOES(units + 1, gl.GL_FIXED, 0, np.zeros(64, dtype=np.int32))
    t.check_gl_error(f"glWeightPointerOES(size {units + 1})", gl.GL_INVALID_VALUE)

    t.ortho_pixels()
    t.clear()
    # bone 0: the strip's rest place; bone 1: bent 40 degrees about the joint at x = 32
    m0 = translate(32.0, 30.0, 0.0)
    m1 = translate(32.0, 30.0, 0.0) @ rotate(40.0, 0.0, 0.0, 1.0)
    gl.glMatrixMode(gl.GL_MATRIX_PALETTE_OES)
    gl.glCurrentPaletteMatrixOES(0)
    gl.glLoadMatrixx([fx(a) for a in q16(m0).T.reshape(-1)])
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadMatrixx([fx(a) for a in q16(m1).T.reshape(-1)])
    gl.glMatrixMode(gl.GL_MATRIX_PALETTE_OES)
    gl.glCurrentPaletteMatrixOES(1)
    gl.glLoadPaletteFromModelViewMatrixOES()
    if int(gl.glGetIntegerv(gl.GL_CURRENT_PALETTE_MATRIX_OES)) != 1:
        t.fail("CURRENT_PALETTE_MATRIX_OES does not read 1 after glCurrentPaletteMatrixOES(1)")
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()
    t.check_gl_error("palette set-up")
    mats = [q16(m0), q16(m1)]

    pos, idx, wts, nrm = _palette_strip()
    wq = q16(wts)
    posq = q16(pos)
    gl.glEnable(gl.GL_MATRIX_PALETTE_OES)
    gl.glEnableClientState(gl.GL_MATRIX_INDEX_ARRAY_OES)
    gl.glEnableClientState(gl.GL_WEIGHT_ARRAY_OES)
    gl.glMatrixIndexPointerOES(2, gl.GL_UNSIGNED_BYTE, 0, idx.reshape(-1))
    gl.glWeightPointerOES(2, gl.GL_FIXED, 0, np.round(wq * ONE).astype(np.int32).reshape(-1))
    gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, gl.GL_FIXED, 0, np.round(posq * ONE).astype(np.int32).reshape(-1))
    gl.glColor4x(ONE, ONE, ONE, ONE)
    gl.glDrawArrays(gl.GL_TRIANGLES, 0, len(pos))
    t.check_gl_error("skinned strip, unlit")
    eye = np.stack([sum(wq[v, i] * (mats[idx[v, i]] @ np.append(posq[v], 1.0)) for i in range(2))
                    for v in range(len(pos))])
    win = eye[:, :2] / eye[:, 3:4]
    polys = [win[3 * i: 3 * i + 3] for i in range(len(win) // 3)]
    inside, either = coverage(polys, w, h, MARGIN)
    expect_coverage(t, t.read(), inside, either, WHITE, "skinned strip (positions)")

    # lit: a directional light; each triangle flat shaded with its provoking vertex
    t.clear()
    gl.glShadeModel(gl.GL_FLAT)
    gl.glEnable(gl.GL_LIGHTING)
    gl.glEnable(gl.GL_LIGHT0)
    gl.glEnable(gl.GL_NORMALIZE)
    eq = Equation()
    eq.lights[0]["enabled"] = True
    light_dir = q16([0.3, 0.5, 0.8, 0.0])
    gl.glLightxv(gl.GL_LIGHT0, gl.GL_POSITION, [fx(a) for a in light_dir])
    eq.lights[0]["position"] = light_dir
    gl.glMaterialxv(gl.GL_FRONT_AND_BACK, gl.GL_DIFFUSE, [ONE, 3 * ONE // 4, ONE // 2, ONE])
    eq.material["diffuse"] = np.array([1.0, 0.75, 0.5, 1.0])
    nq = q16(nrm)
    gl.glEnableClientState(gl.GL_NORMAL_ARRAY)
    gl.glNormalPointer(gl.GL_FIXED, 0, np.round(nq * ONE).astype(np.int32).reshape(-1))
    gl.glDrawArrays(gl.GL_TRIANGLES, 0, len(pos))
    t.check_gl_error("skinned strip, lit")
    img = t.read()
    tol = t.visual.color_tolerance()
    for tri in range(len(pos) // 3):
        v = 3 * tri + 2
        # the two forms: n Inv(sum w_i Mu_i), or sum w_i n Inv(Mu_i) (then NORMALIZE)
        blend = sum(wq[v, i] * mats[idx[v, i]][:3, :3] for i in range(2))
        forms = [unit(nq[v] @ np.linalg.inv(blend)),
                 unit(sum(wq[v, i] * (nq[v] @ np.linalg.inv(mats[idx[v, i]][:3, :3])) for i in range(2)))]
        want = [eq.color(eye[v], n)[0] for n in forms]
        ins, _ = coverage([polys[tri]], w, h, 0.75)
        if not ins.any():
            continue
        got = img[ins]
        if not any(np.all(np.abs(got - c) <= tol) for c in want):
            worst = got[np.argmax(np.abs(got - want[0]).max(axis=-1))]
            t.fail(f"skinned strip, lit: triangle {tri} (weights {wq[v].tolist()}) has colour "
                   f"{np.round(worst, 4).tolist()}, expected {np.round(want[0], 4).tolist()} or "
                   f"{np.round(want[1], 4).tolist()} ({int(ins.sum())} pixels)")

    # no index or no weight array: nothing is drawn
    for off in ("GL_MATRIX_INDEX_ARRAY_OES", "GL_WEIGHT_ARRAY_OES"):
        t.clear()
        gl.glDisableClientState(getattr(gl, off))
        gl.glDrawArrays(gl.GL_TRIANGLES, 0, len(pos))
        t.check_gl_error(f"draw with {off} disabled")
        if (t.read()[..., :3] > 0).any():
            t.fail(f"with {off} disabled the skinned draw produced pixels (it must draw nothing)")
        gl.glEnableClientState(getattr(gl, off))
    gl.glDisable(gl.GL_MATRIX_PALETTE_OES)
    gl.glDisable(gl.GL_LIGHTING)
    gl.glDisableClientState(gl.GL_NORMAL_ARRAY)
    gl.glDisableClientState(gl.GL_MATRIX_INDEX_ARRAY_OES)
    gl.glDisableClientState(gl.GL_WEIGHT_ARRAY_OES)
