"""Texturing: images, mipmaps, wrap modes, paletted textures, environments.

Categories Mip, MipLevels, MipLin, MipSelect, MultiTex, TexDecal, TexPalet,
TexETC1, TexBGRA, TexNPOT, TextureEdgeClamp, TexCombine, CopyTex,
PackedPixels, TexCube and TexGen (spec sections 3.6.2, 3.7 and
OES_compressed_paletted_texture, OES_compressed_ETC1_RGB8_texture,
EXT_texture_format_BGRA8888, OES_texture_npot, OES_texture_env_crossbar,
OES_texture_mirrored_repeat, OES_texture_cube_map).

Every test uses Common-Lite commands only (x and i forms; GL_SHORT vertices,
GL_FIXED / GL_SHORT / GL_BYTE texture coordinates), so it runs in both
profiles. Quads are screen-aligned in window pixels (``t.ortho_pixels()``)
with edges on pixel boundaries. Expected colours are the spec's formulas
(§3.7.6 wrapping, equations 3.16-3.21, Tables 3.14-3.19) evaluated in float64
at pixel centres; tolerances are the visual's.

Level of detail: the spec lets f, the approximation of rho, lie anywhere in
[max(mu, mv), mu + mv] (§3.7.7). The mipmap tests map t to a constant, so
mv = 0 and every conforming f equals mu: lambda is pinned down. They still
grant lambda a precision of 1/16 of a level where a result depends on its
fraction (the spec gives none, and implementations carry lambda in a few
fraction bits or through an approximate log2).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..harness import TestContext, conformance_test

ONE = 1 << 16
VISUALS = ("rgba8888", "rgb565")
LOD_PRECISION = 1.0 / 16


# {============================================================
# helpers: textures and quads


def _fx(v: float) -> int:
    return int(round(v * 65536))


def _q16(v: float) -> float:
    """The nearest 16.16 value (what a GL_FIXED coordinate holds)."""
    return round(v * 65536) / 65536


_SEL = {"RGBA": [0, 1, 2, 3], "RGB": [0, 1, 2], "LUMINANCE_ALPHA": [0, 3], "LUMINANCE": [0], "ALPHA": [3]}


def _upload(t: TestContext, level: int, fmt: str, rgba_u8: np.ndarray) -> None:
    """TexImage2D of uint8 RGBA (h, w, 4) as UNSIGNED_BYTE data of base format `fmt`."""
    gl = t.gl
    h, w = rgba_u8.shape[:2]
    gl.glPixelStorei(gl.GL_UNPACK_ALIGNMENT, 1)
    data = np.ascontiguousarray(rgba_u8[..., _SEL[fmt]], dtype=np.uint8)
    f = getattr(gl, "GL_" + fmt)
    gl.glTexImage2D(gl.GL_TEXTURE_2D, level, f, w, h, 0, f, gl.GL_UNSIGNED_BYTE, data)


def _params(t: TestContext, minf: str = "NEAREST", magf: str = "NEAREST", wrap: str = "REPEAT") -> None:
    gl = t.gl
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MIN_FILTER, getattr(gl, "GL_" + minf))
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAG_FILTER, getattr(gl, "GL_" + magf))
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_WRAP_S, getattr(gl, "GL_" + wrap))
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_WRAP_T, getattr(gl, "GL_" + wrap))


def _env(t: TestContext, mode: str, color: Sequence[float] | None = None) -> None:
    gl = t.gl
    gl.glTexEnvi(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_MODE, getattr(gl, "GL_" + mode))
    if color is not None:
        gl.glTexEnvxv(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_COLOR, [_fx(c) for c in color])


def _texture(t: TestContext, levels: Sequence[np.ndarray], fmt: str = "RGBA", *, minf: str = "NEAREST",
             magf: str = "NEAREST", wrap: str = "REPEAT", mode: str = "REPLACE", unit: int = 0) -> int:
    """A new texture object on `unit` with `levels`, enabled, with its environment."""
    gl = t.gl
    gl.glActiveTexture(gl.GL_TEXTURE0 + unit)
    name = int(gl.glGenTextures(1))
    gl.glBindTexture(gl.GL_TEXTURE_2D, name)
    for d, img in enumerate(levels):
        _upload(t, d, fmt, img)
    _params(t, minf, magf, wrap)
    gl.glEnable(gl.GL_TEXTURE_2D)
    _env(t, mode)
    gl.glActiveTexture(gl.GL_TEXTURE0)
    return name


_TC_TYPES = ("FIXED", "SHORT", "BYTE")


def _quad(t: TestContext, x0: int, y0: int, x1: int, y1: int, coords: Sequence[Any],
          color: Sequence[int] | None = (255, 255, 255, 255), tc_type: Sequence[str] | None = None) -> None:
    """Draw the window rectangle [x0, x1] x [y0, y1] as a strip; coords[u] is
    ((s0, t0), (s1, t1)) for unit u (corner values) or None for no array.
    Coordinates go as GL_FIXED unless tc_type[u] names SHORT or BYTE (then
    they must be integers)."""
    gl = t.gl
    v = np.array([x0, y0, x1, y0, x0, y1, x1, y1], dtype=np.int16)
    gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, gl.GL_SHORT, 0, v)
    gl.glDisableClientState(gl.GL_COLOR_ARRAY)
    if color is not None:
        gl.glColor4x(*[_fx(c / 255) for c in color])
    keep = []
    for u, c in enumerate(coords):
        gl.glClientActiveTexture(gl.GL_TEXTURE0 + u)
        if c is None:
            gl.glDisableClientState(gl.GL_TEXTURE_COORD_ARRAY)
            continue
        (s0, t0), (s1, t1) = c
        vals = [s0, t0, s1, t0, s0, t1, s1, t1]
        kind = tc_type[u] if tc_type else "FIXED"
        if kind == "FIXED":
            arr = np.array([_fx(x) for x in vals], dtype=np.int32)
        else:
            arr = np.array(vals, dtype=np.int16 if kind == "SHORT" else np.int8)
        keep.append(arr)
        gl.glEnableClientState(gl.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(2, getattr(gl, "GL_" + kind), 0, arr)
    gl.glDrawArrays(gl.GL_TRIANGLE_STRIP, 0, 4)
    for u in range(len(coords)):
        gl.glClientActiveTexture(gl.GL_TEXTURE0 + u)
        gl.glDisableClientState(gl.GL_TEXTURE_COORD_ARRAY)
    gl.glClientActiveTexture(gl.GL_TEXTURE0)


def _st(x0: int, y0: int, x1: int, y1: int, c: Any) -> tuple[np.ndarray, np.ndarray]:
    """s, t at the pixel centres of the rectangle (rows bottom first)."""
    (s0, t0), (s1, t1) = c
    px, py = np.meshgrid(np.arange(x0, x1) + 0.5, np.arange(y0, y1) + 0.5)
    return s0 + (px - x0) / (x1 - x0) * (s1 - s0), t0 + (py - y0) / (y1 - y0) * (t1 - t0)


# {============================================================
# helpers: the model


def _wrap(s: np.ndarray, n: int, mode: str) -> np.ndarray:
    """§3.7.6 (and OES_texture_mirrored_repeat) before scaling to texels."""
    if mode == "REPEAT":
        return s - np.floor(s)
    if mode == "MIRRORED_REPEAT_OES":
        f = s - np.floor(s)
        s = np.where(np.floor(s) % 2 == 0, f, 1 - f)
    return np.clip(s, 0.5 / n, 1 - 0.5 / n)


def _sample(tex: np.ndarray, s: Any, t: Any, filt: str, wrap: str = "REPEAT") -> np.ndarray:
    """Equations 3.16-3.18 on float RGBA texels (rows from the bottom)."""
    h, w = tex.shape[:2]
    s, t = np.broadcast_arrays(np.asarray(s, np.float64), np.asarray(t, np.float64))
    u, v = _wrap(s, w, wrap) * w, _wrap(t, h, wrap) * h
    if filt == "NEAREST":
        return tex[np.clip(np.floor(v), 0, h - 1).astype(int), np.clip(np.floor(u), 0, w - 1).astype(int)]

    def idx(x: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        i0 = np.floor(x - 0.5)
        a = x - 0.5 - i0
        i0 = i0.astype(int)
        if wrap == "REPEAT":
            return i0 % n, (i0 + 1) % n, a
        return np.clip(i0, 0, n - 1), np.clip(i0 + 1, 0, n - 1), a

    i0, i1, a = idx(u, w)
    j0, j1, b = idx(v, h)
    a, b = a[..., None], b[..., None]
    return ((1 - a) * (1 - b) * tex[j0, i0] + a * (1 - b) * tex[j0, i1] + (1 - a) * b * tex[j1, i0]
            + a * b * tex[j1, i1])


def _mip(levels: Sequence[np.ndarray], s: Any, t: Any, lam: float, minf: str, magf: str,
         wrap: str = "REPEAT") -> np.ndarray:
    """§3.7.7-3.7.8 for one lambda: the c switch, equations 3.19-3.21."""
    c = 0.5 if magf == "LINEAR" and minf in ("NEAREST_MIPMAP_NEAREST", "NEAREST_MIPMAP_LINEAR") else 0.0
    if lam <= c:
        return _sample(levels[0], s, t, magf, wrap)
    filt = "NEAREST" if minf.startswith("NEAREST") else "LINEAR"
    if minf in ("NEAREST", "LINEAR"):
        return _sample(levels[0], s, t, filt, wrap)
    q = len(levels) - 1
    if minf.endswith("MIPMAP_NEAREST"):
        d = 0 if lam <= 0.5 else (int(np.ceil(lam + 0.5)) - 1 if lam <= q + 0.5 else q)
        return _sample(levels[d], s, t, filt, wrap)
    if lam >= q:
        return _sample(levels[q], s, t, filt, wrap)
    d1 = int(np.floor(lam))
    f = lam - d1
    return (1 - f) * _sample(levels[d1], s, t, filt, wrap) + f * _sample(levels[d1 + 1], s, t, filt, wrap)


def _mip_range(levels: Sequence[np.ndarray], s: Any, t: Any, lam: float, slack: float, minf: str,
               magf: str) -> tuple[np.ndarray, np.ndarray]:
    """Per-channel bounds of `_mip` for lambda within `slack` of `lam`."""
    pts = {lam - slack, lam, lam + slack}
    for k in range(-1, len(levels) + 2):
        for b in (k, k + 0.5):
            for e in (-1e-9, 1e-9):
                if lam - slack <= b + e <= lam + slack:
                    pts.add(b + e)
    vals = [_mip(levels, s, t, p, minf, magf) for p in sorted(pts)]
    return np.min(vals, axis=0), np.max(vals, axis=0)


def _base(rgba: np.ndarray, fmt: str) -> np.ndarray:
    """Table 3.14: texture source colour of texels stored in base format `fmt`."""
    out = np.array(rgba, dtype=np.float64, copy=True)
    if fmt == "ALPHA":
        out[..., :3] = 0.0
    if fmt.startswith("LUMINANCE"):
        out[..., 1] = out[..., 2] = out[..., 0]
    if fmt in ("LUMINANCE", "RGB"):
        out[..., 3] = 1.0
    return out


def _classic(mode: str, fmt: str, cp: np.ndarray, cs: np.ndarray,
             cc: Sequence[float] = (0, 0, 0, 0)) -> np.ndarray:
    """Tables 3.15 and 3.16."""
    out = np.array(cp, dtype=np.float64, copy=True)
    rgb = fmt != "ALPHA"
    alpha = fmt in ("ALPHA", "LUMINANCE_ALPHA", "RGBA")
    cc_ = np.broadcast_to(np.asarray(cc, np.float64), cp.shape)
    if mode == "DECAL":
        a = cs[..., 3:4] if fmt == "RGBA" else 1.0
        out[..., :3] = cp[..., :3] * (1 - a) + cs[..., :3] * a
        return out
    if rgb:
        out[..., :3] = {"REPLACE": cs[..., :3], "MODULATE": cp[..., :3] * cs[..., :3],
                        "BLEND": cp[..., :3] * (1 - cs[..., :3]) + cc_[..., :3] * cs[..., :3],
                        "ADD": np.minimum(cp[..., :3] + cs[..., :3], 1.0)}[mode]
    if alpha:
        out[..., 3] = cs[..., 3] if mode == "REPLACE" else cp[..., 3] * cs[..., 3]
    return out


def _u(rgba_u8: Any) -> np.ndarray:
    return np.asarray(rgba_u8, dtype=np.float64) / 255.0


def _check(t: TestContext, img: np.ndarray, x0: int, y0: int, want: np.ndarray, where: str,
           lo: np.ndarray | None = None, hi: np.ndarray | None = None, storage: float = 0.0) -> None:
    """The pixels of the rectangle at (x0, y0) of want's shape match `want` (or lie in
    [lo, hi]) within the visual's tolerance. Channels of fewer than 8 bits are
    compared as the buffer holds them: the 8-bit value ReadPixels returns is mapped
    back to its k / (2^b - 1). `storage` widens the tolerance where a texel holds a
    packed value the GL may store with its own resolution (§3.7.1): 8 bits or more,
    so within half an 8-bit step."""
    h, w = want.shape[:2]
    got = np.array(img[y0:y0 + h, x0:x0 + w], copy=True)
    for c, bits in enumerate(t.visual.bits):
        if 0 < bits < 8:
            top = (1 << bits) - 1
            got[..., c] = np.round(got[..., c] * top) / top
    lo = want if lo is None else lo
    hi = want if hi is None else hi
    err = np.maximum(lo - got, got - hi).clip(0)
    bad = (err > t.visual.color_tolerance() + storage).any(axis=-1)
    if bad.any():
        y, x = (int(v) for v in np.argwhere(bad)[0])
        t.fail(f"{where}: {int(bad.sum())} pixels differ; first at (x={x0 + x}, y={y0 + y}): "
               f"{np.round(got[y, x], 3).tolist()}, expected {np.round(lo[y, x], 3).tolist()}"
               + ("" if hi is lo else f"..{np.round(hi[y, x], 3).tolist()}"))


def _prepare(t: TestContext) -> None:
    t.ortho_pixels()
    t.clear((0, 0, 0, 0))


# one colour per mipmap level, 32x32 down to 1x1 (q = 5)
_LEVEL_COLORS = np.array([(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 0, 255),
                          (0, 255, 255, 255), (255, 0, 255, 255)], dtype=np.uint8)


def _colour_levels(w: int = 32, h: int = 32) -> list[np.ndarray]:
    out, d = [], 0
    while True:
        out.append(np.broadcast_to(_LEVEL_COLORS[d % 6], (h, w, 4)).copy())
        if w == 1 and h == 1:
            return out
        w, h, d = max(w // 2, 1), max(h // 2, 1), d + 1


def _lambda_quad(x: int, y: int, width: int, height: int, lam: float, size: int = 32) -> tuple[Any, float]:
    """Texture coordinates for a `width` x `height` quad at lambda (t constant, so
    mv = 0 and f = mu); returns them and the exact lambda the 16.16 values give."""
    s1 = _q16(2.0**lam * width / size)
    return ((0.0, 0.5), (s1, 0.5)), float(np.log2(s1 * size / width))


def _level_rows(t: TestContext, x: int, d: int, w0: int, h0: int,
                color: Sequence[int] = (255, 255, 255, 255)) -> None:
    """Level d of a w0 x h0 mipmap one texel per pixel at (x, 0): one quad per texel
    row, s across the image (lambda = d exactly), t constant at the row's centre."""
    w, h = max(w0 >> d, 1), max(h0 >> d, 1)
    for j in range(h):
        tj = (j + 0.5) / h
        _quad(t, x, j, x + w, j + 1, [((0.0, tj), (1.0, tj))], color=color)


MIN_FILTERS = ("NEAREST", "LINEAR", "NEAREST_MIPMAP_NEAREST", "LINEAR_MIPMAP_NEAREST",
               "NEAREST_MIPMAP_LINEAR", "LINEAR_MIPMAP_LINEAR")


# {============================================================
# Mip


@conformance_test("Mip", section="3.7.7", visuals=VISUALS, size=(192, 8))
def mip(t: TestContext) -> None:
    """A 32x32 mipmap with one colour per level under each minification filter, at
    lambda = -1, 0, 1, ..., 5 and 6 > q: the mipmapped filters show level
    min(lambda, q), NEAREST and LINEAR level 0."""
    levels = _colour_levels()
    lams = (-1, 0, 1, 2, 3, 4, 5, 6)
    for minf in MIN_FILTERS:
        _prepare(t)
        _texture(t, levels, minf=minf)
        x, spans = 0, []
        for lam in lams:
            width = 64 if lam < 0 else max(32 >> lam, 1)
            coords, _ = _lambda_quad(x, 0, width, 4, lam)
            _quad(t, x, 0, x + width, 4, [coords])
            spans.append((x, width, lam))
            x += width + 1
        img = t.read()
        for x0, width, lam in spans:
            d = 0 if lam <= 0 or minf in ("NEAREST", "LINEAR") else min(lam, 5)
            want = np.broadcast_to(_u(_LEVEL_COLORS[d]), (4, width, 4))
            _check(t, img, x0, 0, want, f"MIN_FILTER {minf}, lambda {lam}")
    t.check_gl_error("Mip")


# {============================================================
# MipLevels


@conformance_test("MipLevels", section="3.7.9", visuals=VISUALS, size=(96, 8))
def mip_levels(t: TestContext) -> None:
    """A 32x8 mipmap (6 levels, 1-texel-wide ones included) specified level by level
    in shuffled order: each level shows at its lambda; a level of the wrong size
    or format makes the texture incomplete and disables texturing; respecifying
    one level changes only that level."""
    gl = t.gl
    levels = _colour_levels(32, 8)
    _prepare(t)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 5)
    for d in (3, 0, 5, 1, 4, 2):
        _upload(t, d, "RGBA", levels[d])
    _params(t, "NEAREST_MIPMAP_NEAREST")
    gl.glEnable(gl.GL_TEXTURE_2D)
    _env(t, "REPLACE")
    frag = (40, 80, 120, 160)

    def draw_all() -> np.ndarray:
        _prepare(t)
        x = 0
        for d in range(6):
            width = max(32 >> d, 1)
            coords, _ = _lambda_quad(x, 0, width, 4, d)
            _quad(t, x, 0, x + width, 4, [coords], color=frag)
            x += width + 1
        return t.read()

    def check_levels(img: np.ndarray, colors: Sequence[Any], where: str) -> None:
        x = 0
        for d in range(6):
            width = max(32 >> d, 1)
            _check(t, img, x, 0, np.broadcast_to(_u(colors[d]), (4, width, 4)), f"{where}, level {d}")
            x += width + 1

    colors = [levels[d][0, 0] for d in range(6)]
    check_levels(draw_all(), colors, "complete mipmap")
    _upload(t, 2, "RGBA", np.zeros((4, 4, 4), np.uint8))           # 4x4 where 8x2 belongs
    check_levels(draw_all(), [frag] * 6, "level 2 of the wrong size (incomplete: texturing off)")
    _upload(t, 2, "RGB", levels[2])                                  # right size, other format
    check_levels(draw_all(), [frag] * 6, "level 2 in another format (incomplete)")
    _upload(t, 2, "RGBA", levels[2])
    new4 = np.full_like(levels[4], (10, 200, 30, 255))
    _upload(t, 4, "RGBA", new4)
    colors[4] = new4[0, 0]
    check_levels(draw_all(), colors, "after respecifying level 4")
    t.check_gl_error("MipLevels")


# {============================================================
# MipLin


@conformance_test("MipLin", section="3.7.7", visuals=VISUALS, size=(64, 64))
def mip_lin(t: TestContext) -> None:
    """NEAREST_MIPMAP_LINEAR and LINEAR_MIPMAP_LINEAR between white and black levels:
    the value is the blend by frac(lambda) of equation 3.21's two levels, over a
    sweep of 16 lambdas (lambda to 1/16 of a level), and it changes monotonically."""
    levels = [np.full((32 >> d, 32 >> d, 4), 255 * (1 - d % 2), np.uint8) for d in range(6)]
    levels_f = [_u(v) for v in levels]
    for minf in ("NEAREST_MIPMAP_LINEAR", "LINEAR_MIPMAP_LINEAR"):
        _prepare(t)
        _texture(t, levels, minf=minf, magf="NEAREST")
        quads = []
        for k in range(16):
            lam = 1.0 + k / 16 + 1.0 / 32          # one level and a bit, 1/32 off the sixteenths
            x, y = 8 * (k % 8), 8 * (k // 8)
            coords, exact = _lambda_quad(x, y, 8, 8, lam)
            _quad(t, x, y, x + 8, y + 8, [coords])
            quads.append((x, y, exact))
        img = t.read()
        values = []
        for x, y, lam in quads:
            lo, hi = _mip_range(levels_f, 0.0, 0.5, lam, LOD_PRECISION, minf, "NEAREST")
            _check(t, img, x, y, np.broadcast_to(lo, (8, 8, 4)), f"{minf} lambda {lam:.3f}",
                   np.broadcast_to(lo, (8, 8, 4)), np.broadcast_to(hi, (8, 8, 4)))
            values.append(float(img[y:y + 8, x:x + 8, 0].mean()))
        # level 1 black -> level 2 white: brighter as lambda grows
        if any(b < a - t.visual.color_tolerance()[0] for a, b in zip(values, values[1:])):
            t.fail(f"{minf}: the blend is not monotonic in lambda: {np.round(values, 3).tolist()}")
    t.check_gl_error("MipLin")


# {============================================================
# MipSelect


@conformance_test("MipSelect", section="3.7.7", visuals=VISUALS, size=(64, 64))
def mip_select(t: TestContext) -> None:
    """NEAREST_MIPMAP_NEAREST and LINEAR_MIPMAP_NEAREST select level
    ceil(lambda + 1/2) - 1 (equation 3.19): lambda k + 0.3 gives level k, k + 0.7
    level k + 1; lambda <= 1/2 level 0; lambda > q + 1/2 level q."""
    levels = _colour_levels()
    for minf in ("NEAREST_MIPMAP_NEAREST", "LINEAR_MIPMAP_NEAREST"):
        _prepare(t)
        _texture(t, levels, minf=minf, magf="NEAREST")
        cases = [0.2, 0.3, 0.7, 1.3, 1.7, 2.3, 2.7, 3.3, 3.7, 4.3, 4.7, 5.3, 5.7, 6.5]
        quads = []
        for k, lam in enumerate(cases):
            x, y = 8 * (k % 8), 8 * (k // 8)
            coords, exact = _lambda_quad(x, y, 8, 8, lam)
            _quad(t, x, y, x + 8, y + 8, [coords])
            quads.append((x, y, exact))
        img = t.read()
        for x, y, lam in quads:
            d = 0 if lam <= 0.5 else min(int(np.ceil(lam + 0.5)) - 1, 5)
            _check(t, img, x, y, np.broadcast_to(_u(_LEVEL_COLORS[d]), (8, 8, 4)),
                   f"{minf} lambda {lam:.3f}: level {d}")
    t.check_gl_error("MipSelect")


@conformance_test("MipSelect.bias", section="EXT_texture_lod_bias", visuals=VISUALS, size=(64, 64))
def mip_select_bias(t: TestContext) -> None:
    """EXT_texture_lod_bias: lambda' = log2(rho) + bias, the bias clamped to
    MAX_TEXTURE_LOD_BIAS_EXT: quads at lambda 1.3 and 2.7 under biases from -3 to +3
    (and beyond the maximum) select ceil(lambda' + 1/2) - 1 with NEAREST_MIPMAP_NEAREST."""
    gl = t.gl
    t.need_extension("GL_EXT_texture_lod_bias")
    top = float(np.atleast_1d(gl.glGetFixedv(gl.GL_MAX_TEXTURE_LOD_BIAS_EXT))[0]) / ONE
    levels = _colour_levels()
    _prepare(t)
    _texture(t, levels, minf="NEAREST_MIPMAP_NEAREST", magf="NEAREST")
    cases = [(lam, bias) for lam in (1.3, 2.7) for bias in (-3.0, -1.5, -0.5, 0.5, 1.0, 2.25, 3.0, 100.0)]
    for k, (lam, bias) in enumerate(cases):
        x, y = 8 * (k % 8), 8 * (k // 8)
        gl.glTexEnvx(gl.GL_TEXTURE_FILTER_CONTROL_EXT, gl.GL_TEXTURE_LOD_BIAS_EXT, _fx(bias))
        coords, exact = _lambda_quad(x, y, 8, 8, lam)
        _quad(t, x, y, x + 8, y + 8, [coords])
        cases[k] = (exact, bias)
    img = t.read()
    for k, (lam, bias) in enumerate(cases):
        x, y = 8 * (k % 8), 8 * (k // 8)
        lb = lam + max(-top, min(top, bias))
        d = 0 if lb <= 0.5 else min(int(np.ceil(lb + 0.5)) - 1, 5)
        _check(t, img, x, y, np.broadcast_to(_u(_LEVEL_COLORS[d]), (8, 8, 4)),
               f"lambda {lam:.3f}, bias {bias}: level {d}")
    gl.glTexEnvx(gl.GL_TEXTURE_FILTER_CONTROL_EXT, gl.GL_TEXTURE_LOD_BIAS_EXT, 0)
    t.check_gl_error("MipSelect.bias")


@conformance_test("TexAniso.state", section="EXT_texture_filter_anisotropic")
def tex_aniso_state(t: TestContext) -> None:
    """EXT_texture_filter_anisotropic's state: MAX_TEXTURE_MAX_ANISOTROPY_EXT at least 2, a
    texture's TEXTURE_MAX_ANISOTROPY_EXT initially 1 and settable to any value >= 1, a value
    below 1 INVALID_VALUE with the value kept. (The filtering scheme itself is the
    implementation's choice.)"""
    gl = t.gl
    t.need_extension("GL_EXT_texture_filter_anisotropic")
    top = float(np.atleast_1d(gl.glGetFixedv(gl.GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT))[0]) / ONE
    if top < 2.0:
        t.fail(f"MAX_TEXTURE_MAX_ANISOTROPY_EXT is {top}, below 2")
    gl.glBindTexture(gl.GL_TEXTURE_2D, 7)
    get = lambda: float(np.atleast_1d(gl.glGetTexParameterxv(  # noqa: E731
        gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAX_ANISOTROPY_EXT))[0]) / ONE
    if get() != 1.0:
        t.fail(f"TEXTURE_MAX_ANISOTROPY_EXT starts at {get()}, not 1")
    gl.glTexParameterx(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAX_ANISOTROPY_EXT, 2 * ONE)
    t.check_gl_error("TEXTURE_MAX_ANISOTROPY_EXT 2")
    gl.glTexParameterx(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAX_ANISOTROPY_EXT, ONE // 2)
    t.check_gl_error("TEXTURE_MAX_ANISOTROPY_EXT 0.5", gl.GL_INVALID_VALUE)
    if get() != 2.0:
        t.fail(f"TEXTURE_MAX_ANISOTROPY_EXT reads {get()} after 2 and a refused 0.5")
    gl.glDeleteTextures(1, [7])
    t.check_gl_error("TexAniso.state")


@conformance_test("MipSelect.magswitch", section="3.7.8", visuals=VISUALS, size=(64, 16))
def mip_select_switch(t: TestContext) -> None:
    """The switch-over point c (§3.7.8): with MAG LINEAR and NEAREST_MIPMAP_LINEAR,
    c = 0.5, so lambda 0.25 is magnification (level 0 only); with MAG NEAREST, or
    with LINEAR_MIPMAP_LINEAR, c = 0 and lambda 0.25 blends levels 0 and 1."""
    levels = _colour_levels()
    levels_f = [_u(v) for v in levels]
    cases = (("NEAREST_MIPMAP_LINEAR", "LINEAR"), ("NEAREST_MIPMAP_LINEAR", "NEAREST"),
             ("LINEAR_MIPMAP_LINEAR", "LINEAR"), ("LINEAR_MIPMAP_LINEAR", "NEAREST"))
    for minf, magf in cases:
        _prepare(t)
        _texture(t, levels, minf=minf, magf=magf)
        coords, lam = _lambda_quad(0, 0, 16, 16, 0.25)
        _quad(t, 0, 0, 16, 16, [coords])
        img = t.read()
        lo, hi = _mip_range(levels_f, 0.0, 0.5, lam, LOD_PRECISION, minf, magf)
        _check(t, img, 0, 0, np.broadcast_to(lo, (16, 16, 4)), f"MIN {minf}, MAG {magf}, lambda {lam:.3f}",
               np.broadcast_to(lo, (16, 16, 4)), np.broadcast_to(hi, (16, 16, 4)))
    t.check_gl_error("MipSelect.magswitch")


# {============================================================
# MultiTex


@conformance_test("MultiTex", section="3.7.13", visuals=VISUALS)
def multi_tex(t: TestContext) -> None:
    """Two to four units (as many as MAX_TEXTURE_UNITS allows, at least 2) each with its
    texture, environment and coordinates (FIXED, SHORT and BYTE arrays, and one unit
    fed by glMultiTexCoord4x): each unit applies its function to the previous unit's
    result; a disabled unit passes it on (§3.7.13)."""
    gl = t.gl
    units = int(gl.glGetIntegerv(gl.GL_MAX_TEXTURE_UNITS))
    if units < 2:
        t.fail(f"MAX_TEXTURE_UNITS is {units}; ES 1.1 requires at least 2 (Table 6.20)")
    units = min(units, 4)
    rng = np.random.default_rng(3)
    texs = [rng.integers(0, 256, size=(4, 4, 4), dtype=np.uint8) for _ in range(4)]
    fmts = ("RGBA", "LUMINANCE", "RGB", "ALPHA")
    modes = ("MODULATE", "ADD", "BLEND", "MODULATE")
    envc = (0.25, 0.75, 0.5, 1.0)
    frag = (200, 150, 100, 220)
    for n in range(2, units + 1):
        for off in ([None, 1] if n >= 3 else [None]):
            _prepare(t)
            for u in range(4):
                gl.glActiveTexture(gl.GL_TEXTURE0 + u)
                gl.glDisable(gl.GL_TEXTURE_2D)
            for u in range(n):
                _texture(t, [texs[u]], fmts[u], mode=modes[u], unit=u)
                gl.glActiveTexture(gl.GL_TEXTURE0 + u)
                _env(t, modes[u], envc)
                if u == off:
                    gl.glDisable(gl.GL_TEXTURE_2D)
            gl.glActiveTexture(gl.GL_TEXTURE0)
            # unit 0 FIXED 0..1, unit 1 SHORT 0..1 mirrored, unit 2 BYTE 0..2 (repeats), last: current
            arrays = [((0.0, 0.0), (1.0, 1.0)), ((1, 0), (0, 1)), ((0, 0), (2, 2))][: n - 1]
            gl.glMultiTexCoord4x(gl.GL_TEXTURE0 + n - 1, _fx(0.625), _fx(0.375), 0, ONE)
            _quad(t, 0, 0, 16, 16, arrays, color=frag, tc_type=("FIXED", "SHORT", "BYTE"))
            img = t.read()
            cp = np.broadcast_to(_u(frag), (16, 16, 4))
            maps = [((0.0, 0.0), (1.0, 1.0)), ((1.0, 0.0), (0.0, 1.0)), ((0.0, 0.0), (2.0, 2.0))]
            for u in range(n):
                if u == off:
                    continue
                if u == n - 1:
                    cs = np.broadcast_to(_u(texs[u])[1, 2], (16, 16, 4))      # s 0.625, t 0.375
                else:
                    s, tt = _st(0, 0, 16, 16, maps[u])
                    cs = _sample(_u(texs[u]), s, tt, "NEAREST")
                cp = _classic(modes[u], fmts[u], cp, _base(cs, fmts[u]), envc)
            _check(t, img, 0, 0, cp, f"{n} units" + (f", unit {off} disabled" if off is not None else ""))
    for u in range(4):
        gl.glActiveTexture(gl.GL_TEXTURE0 + u)
        gl.glDisable(gl.GL_TEXTURE_2D)
    gl.glActiveTexture(gl.GL_TEXTURE0)
    t.check_gl_error("MultiTex")


# {============================================================
# TexDecal


@conformance_test("TexDecal", section="3.7.12", visuals=VISUALS)
def tex_decal(t: TestContext) -> None:
    """DECAL: an RGB texture replaces the colour, an RGBA texture blends over it by its
    alpha (Cv = Cp (1 - As) + Cs As); alpha stays the fragment's (Table 3.15)."""
    rng = np.random.default_rng(4)
    tex = rng.integers(0, 256, size=(8, 8, 4), dtype=np.uint8)
    tex[0, :4, 3] = (0, 255, 128, 64)
    for fmt in ("RGB", "RGBA"):
        for frag in ((255, 255, 255, 255), (30, 60, 90, 120)):
            _prepare(t)
            _texture(t, [tex], fmt, mode="DECAL")
            _quad(t, 0, 0, 32, 32, [((0.0, 0.0), (1.0, 1.0))], color=frag)
            img = t.read()
            s, tt = _st(0, 0, 32, 32, ((0.0, 0.0), (1.0, 1.0)))
            cs = _base(_sample(_u(tex), s, tt, "NEAREST"), fmt)
            want = _classic("DECAL", fmt, np.broadcast_to(_u(frag), cs.shape), cs)
            _check(t, img, 0, 0, want, f"DECAL {fmt}, fragment {frag}")
    t.check_gl_error("TexDecal")


# {============================================================
# TexPalet

_PALETTE_FORMATS = {
    "PALETTE4_RGB8_OES": (4, "RGB", 3), "PALETTE4_RGBA8_OES": (4, "RGBA", 4),
    "PALETTE4_R5_G6_B5_OES": (4, "565", 2), "PALETTE4_RGBA4_OES": (4, "4444", 2),
    "PALETTE4_RGB5_A1_OES": (4, "5551", 2), "PALETTE8_RGB8_OES": (8, "RGB", 3),
    "PALETTE8_RGBA8_OES": (8, "RGBA", 4), "PALETTE8_R5_G6_B5_OES": (8, "565", 2),
    "PALETTE8_RGBA4_OES": (8, "4444", 2), "PALETTE8_RGB5_A1_OES": (8, "5551", 2),
}


def _decode_entries(raw: np.ndarray, kind: str, count: int) -> np.ndarray:
    """Palette entries (Table 3.11) as float RGBA: bytes or packed 16-bit values (§3.6.2)."""
    out = np.ones((count, 4))
    if kind in ("RGB", "RGBA"):
        n = len(kind)
        out[:, :n] = raw[: count * n].reshape(count, n) / 255.0
        return out
    v = raw[: 2 * count].view("<u2").astype(np.int64)
    if kind == "565":
        out[:, 0], out[:, 1], out[:, 2] = (v >> 11) / 31, ((v >> 5) & 63) / 63, (v & 31) / 31
    elif kind == "4444":
        for c in range(4):
            out[:, c] = ((v >> (12 - 4 * c)) & 15) / 15
    else:
        out[:, 0], out[:, 1], out[:, 2] = (v >> 11) / 31, ((v >> 6) & 31) / 31, ((v >> 1) & 31) / 31
        out[:, 3] = v & 1
    return out


def _paletted(rng: np.random.Generator, fmt: str, w: int, h: int,
              nlevels: int) -> tuple[bytes, list[np.ndarray]]:
    """Palette then the levels' indices (4-bit: first texel in the high nibble)."""
    bits, kind, ebytes = _PALETTE_FORMATS[fmt]
    entries = 1 << bits
    raw = rng.integers(0, 256, size=entries * ebytes, dtype=np.uint8)
    pal = _decode_entries(raw, kind, entries)
    chunks, out = [raw.tobytes()], []
    for _ in range(nlevels):
        idx = rng.integers(0, entries, size=w * h)
        out.append(pal[idx].reshape(h, w, 4))
        if bits == 8:
            chunks.append(idx.astype(np.uint8).tobytes())
        else:
            p = np.append(idx, 0) if idx.size % 2 else idx
            chunks.append(((p[0::2] << 4) | p[1::2]).astype(np.uint8).tobytes())
        w, h = max(w // 2, 1), max(h // 2, 1)
    return b"".join(chunks), out


@conformance_test("TexPalet", section="3.7.4", visuals=VISUALS, size=(64, 16))
def tex_palet(t: TestContext) -> None:
    """The 10 PALETTE*_OES formats are listed in COMPRESSED_TEXTURE_FORMATS and decode:
    level -4 gives all five levels (16x4 to 1x1) in one image, each shown at its
    lambda with NEAREST_MIPMAP_NEAREST; level 0 gives one level."""
    gl = t.gl
    listed = {int(v) for v in np.atleast_1d(gl.glGetIntegerv(gl.GL_COMPRESSED_TEXTURE_FORMATS))}
    if gl.glGetIntegerv(gl.GL_NUM_COMPRESSED_TEXTURE_FORMATS) < 10:
        t.fail("NUM_COMPRESSED_TEXTURE_FORMATS is below 10")
    rng = np.random.default_rng(8)
    for fmt in _PALETTE_FORMATS:
        token = getattr(gl, "GL_" + fmt)
        if token not in listed:
            t.fail(f"GL_{fmt} is not in COMPRESSED_TEXTURE_FORMATS")
        for nlev in (5, 1):
            data, levels = _paletted(rng, fmt, 16, 4, nlev)
            _prepare(t)
            gl.glBindTexture(gl.GL_TEXTURE_2D, 3)
            gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, 1 - nlev, token, 16, 4, 0, len(data), data)
            t.check_gl_error(f"glCompressedTexImage2D({fmt}, level {1 - nlev})")
            _params(t, "NEAREST_MIPMAP_NEAREST" if nlev > 1 else "NEAREST")
            gl.glEnable(gl.GL_TEXTURE_2D)
            _env(t, "REPLACE")
            base = "RGB" if _PALETTE_FORMATS[fmt][1] in ("RGB", "565") else "RGBA"
            x = 0
            for d in range(nlev):
                _level_rows(t, x, d, 16, 4)
                x += (16 >> d) + 2
            img = t.read()
            x = 0
            for d in range(nlev):
                _check(t, img, x, 0, _base(levels[d], base), f"{fmt}, {nlev} levels, level {d}",
                       storage=0.5 / 255)
                x += (16 >> d) + 2
    t.check_gl_error("TexPalet")


@conformance_test("TexPalet.errors", section="3.7.4")
def tex_palet_errors(t: TestContext) -> None:
    """Paletted errors (§3.7.4): a positive level or an inconsistent imageSize is
    INVALID_VALUE; CompressedTexSubImage2D with a PALETTE format is INVALID_OPERATION."""
    gl = t.gl
    token = gl.GL_PALETTE4_RGB8_OES
    data, _ = _paletted(np.random.default_rng(1), "PALETTE4_RGB8_OES", 4, 4, 1)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 2)
    gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, 1, token, 4, 4, 0, len(data), data)
    t.check_gl_error("CompressedTexImage2D level 1", gl.GL_INVALID_VALUE)
    gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, 0, token, 4, 4, 0, len(data) - 1, data)
    t.check_gl_error("CompressedTexImage2D with imageSize one short", gl.GL_INVALID_VALUE)
    gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, 0, token, 4, 4, 0, len(data), data)
    t.check_gl_error("CompressedTexImage2D")
    gl.glCompressedTexSubImage2D(gl.GL_TEXTURE_2D, 0, 0, 0, 4, 4, token, len(data), data)
    t.check_gl_error("CompressedTexSubImage2D of a paletted texture", gl.GL_INVALID_OPERATION)


# {============================================================
# TexETC1: OES_compressed_ETC1_RGB8_texture, decoded here from the
# extension's tables and bit layout

# table codeword -> the modifiers of pixel index values 0..3: "00" the small
# positive, "01" the large positive, "10" the small negative, "11" the large negative
ETC1_MODIFIERS = np.array([[2, 8, -2, -8], [5, 17, -5, -17], [9, 29, -9, -29], [13, 42, -13, -42],
                           [18, 60, -18, -60], [24, 80, -24, -80], [33, 106, -33, -106],
                           [47, 183, -47, -183]])


def etc1_decode(data: bytes, w: int, h: int) -> np.ndarray:
    """(h, w, 3) uint8 texels of a w x h ETC1 image: 64-bit blocks, most
    significant byte first, four by four texels, in rows of blocks."""
    bw, bh = (w + 3) // 4, (h + 3) // 4
    out = np.zeros((bh * 4, bw * 4, 3), np.int64)
    blocks = np.frombuffer(data, dtype=">u8").reshape(bh, bw)
    for by in range(bh):
        for bx in range(bw):
            v = int(blocks[by, bx])

            def bits(hi: int, lo: int, v: int = v) -> int:
                return (v >> lo) & ((1 << (hi - lo + 1)) - 1)

            if bits(33, 33):        # differential: 5-bit base, signed 3-bit offset to the second
                base1 = [bits(63, 59), bits(55, 51), bits(47, 43)]
                delta = [bits(58, 56), bits(50, 48), bits(42, 40)]
                base2 = [b + (d - 8 if d >= 4 else d) for b, d in zip(base1, delta)]
                if not all(0 <= b <= 31 for b in base2):
                    raise ValueError("an ETC1 block whose second colour is undefined")
                colors = [[(c << 3) | (c >> 2) for c in b] for b in (base1, base2)]
            else:                   # individual: two 4-bit bases
                base1 = [bits(63, 60), bits(55, 52), bits(47, 44)]
                base2 = [bits(59, 56), bits(51, 48), bits(43, 40)]
                colors = [[c * 17 for c in b] for b in (base1, base2)]
            tables, flip = (bits(39, 37), bits(36, 34)), bits(32, 32)
            for x in range(4):
                for y in range(4):
                    k = x * 4 + y               # texels by columns
                    index = (bits(k + 16, k + 16) << 1) | bits(k, k)
                    half = int(y >= 2) if flip else int(x >= 2)
                    mod = ETC1_MODIFIERS[tables[half], index]
                    out[by * 4 + y, bx * 4 + x] = np.clip(np.array(colors[half]) + mod, 0, 255)
    return out[:h, :w].astype(np.uint8)


def etc1_random(rng: np.random.Generator, w: int, h: int) -> bytes:
    """Random blocks of both modes and both flips, none whose differential
    second colour leaves 0..31 (undefined by the extension)."""
    out = bytearray()
    for _ in range(((w + 3) // 4) * ((h + 3) // 4)):
        b = bytearray(rng.integers(0, 256, 8, dtype=np.uint8).tobytes())
        if b[3] & 2:
            for c in range(3):
                d = b[c] & 7
                if not 0 <= (b[c] >> 3) + (d - 8 if d >= 4 else d) <= 31:
                    b[c] ^= 4       # the offset's other sign stays in range
        out += b
    return bytes(out)


@conformance_test("TexETC1", section="OES_compressed_ETC1_RGB8_texture", visuals=VISUALS, size=(64, 16))
def tex_etc1(t: TestContext) -> None:
    """ETC1_RGB8_OES is in COMPRESSED_TEXTURE_FORMATS and decodes to the extension's texels
    (an RGB texture): 16x4, 4x4, 2x2 and 1x1 images of random blocks shown one texel a pixel,
    and a mipmap chain of ETC1 levels complete under NEAREST_MIPMAP_NEAREST."""
    gl = t.gl
    listed = {int(v) for v in np.atleast_1d(gl.glGetIntegerv(gl.GL_COMPRESSED_TEXTURE_FORMATS))}
    if gl.GL_ETC1_RGB8_OES not in listed:
        t.fail("GL_ETC1_RGB8_OES is not in COMPRESSED_TEXTURE_FORMATS")
    rng = np.random.default_rng(12)
    for w, h in ((16, 4), (4, 4), (2, 2), (1, 1)):
        data = etc1_random(rng, w, h)
        _prepare(t)
        gl.glBindTexture(gl.GL_TEXTURE_2D, 4)
        gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_ETC1_RGB8_OES, w, h, 0, len(data), data)
        t.check_gl_error(f"glCompressedTexImage2D(ETC1_RGB8_OES, {w}x{h})")
        _params(t)
        gl.glEnable(gl.GL_TEXTURE_2D)
        _env(t, "REPLACE")
        _level_rows(t, 0, 0, w, h)
        rgba = np.concatenate([etc1_decode(data, w, h), np.full((h, w, 1), 255, np.uint8)], -1)
        want = _base(_u(rgba), "RGB")
        _check(t, t.read(), 0, 0, want, f"ETC1 {w}x{h}")
    # levels 0..2 of a 4x4 chain, each at its lambda
    levels = [etc1_random(rng, s, s) for s in (4, 2, 1)]
    _prepare(t)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 5)
    for d, (s, data) in enumerate(zip((4, 2, 1), levels)):
        gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, d, gl.GL_ETC1_RGB8_OES, s, s, 0, len(data), data)
    t.check_gl_error("ETC1 levels 0..2")
    _params(t, "NEAREST_MIPMAP_NEAREST")
    gl.glEnable(gl.GL_TEXTURE_2D)
    _env(t, "REPLACE")
    x = 0
    for d in range(3):
        _level_rows(t, x, d, 4, 4)
        x += (4 >> d) + 2
    img = t.read()
    x = 0
    for d, s in enumerate((4, 2, 1)):
        rgb = etc1_decode(levels[d], s, s)
        want = _base(_u(np.concatenate([rgb, np.full((s, s, 1), 255, np.uint8)], -1)), "RGB")
        _check(t, img, x, 0, want, f"ETC1 mipmap level {d}")
        x += s + 2
    t.check_gl_error("TexETC1")


@conformance_test("TexETC1.errors", section="OES_compressed_ETC1_RGB8_texture")
def tex_etc1_errors(t: TestContext) -> None:
    """ETC1 errors: an imageSize other than ceil(w/4) ceil(h/4) 8 is INVALID_VALUE; the
    texture's ETC1 levels take no TexSubImage2D, CompressedTexSubImage2D (unless
    EXT_compressed_ETC1_RGB8_sub_texture is listed) or CopyTexSubImage2D (INVALID_OPERATION)."""
    gl = t.gl
    data = etc1_random(np.random.default_rng(2), 4, 4)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 2)
    gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_ETC1_RGB8_OES, 4, 4, 0, 7, data)
    t.check_gl_error("CompressedTexImage2D with imageSize one short", gl.GL_INVALID_VALUE)
    gl.glCompressedTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_ETC1_RGB8_OES, 4, 4, 0, 8, data)
    t.check_gl_error("CompressedTexImage2D")
    if not t.has_extension("GL_EXT_compressed_ETC1_RGB8_sub_texture"):
        # (that extension allows whole-block sub-images)
        gl.glCompressedTexSubImage2D(gl.GL_TEXTURE_2D, 0, 0, 0, 4, 4, gl.GL_ETC1_RGB8_OES, 8, data)
        t.check_gl_error("CompressedTexSubImage2D of an ETC1 texture", gl.GL_INVALID_OPERATION)
    gl.glTexSubImage2D(gl.GL_TEXTURE_2D, 0, 0, 0, 1, 1, gl.GL_RGB, gl.GL_UNSIGNED_BYTE, np.zeros(4, np.uint8))
    t.check_gl_error("TexSubImage2D of an ETC1 texture", gl.GL_INVALID_OPERATION)
    gl.glCopyTexSubImage2D(gl.GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1)
    t.check_gl_error("CopyTexSubImage2D of an ETC1 texture", gl.GL_INVALID_OPERATION)


@conformance_test("TexBGRA", section="EXT_texture_format_BGRA8888", visuals=VISUALS, size=(64, 16))
def tex_bgra(t: TestContext) -> None:
    """BGRA_EXT / UNSIGNED_BYTE images are RGBA textures with the bytes swapped, by
    TexImage2D and TexSubImage2D, under REPLACE and MODULATE."""
    gl = t.gl
    rng = np.random.default_rng(6)
    rgba = rng.integers(0, 256, size=(4, 16, 4), dtype=np.uint8)
    patch = rng.integers(0, 256, size=(2, 3, 4), dtype=np.uint8)
    want_tex = rgba.copy()
    want_tex[1:3, 5:8] = patch
    for mode, frag in (("REPLACE", (255, 255, 255, 255)), ("MODULATE", (200, 100, 50, 128))):
        _prepare(t)
        gl.glPixelStorei(gl.GL_UNPACK_ALIGNMENT, 1)
        gl.glBindTexture(gl.GL_TEXTURE_2D, 6)
        bgra = np.ascontiguousarray(rgba[..., [2, 1, 0, 3]])
        gl.glTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_BGRA_EXT, 16, 4, 0, gl.GL_BGRA_EXT, gl.GL_UNSIGNED_BYTE,
                        bgra)
        gl.glTexSubImage2D(gl.GL_TEXTURE_2D, 0, 5, 1, 3, 2, gl.GL_BGRA_EXT, gl.GL_UNSIGNED_BYTE,
                           np.ascontiguousarray(patch[..., [2, 1, 0, 3]]))
        t.check_gl_error(f"BGRA uploads ({mode})")
        _params(t)
        gl.glEnable(gl.GL_TEXTURE_2D)
        _env(t, mode)
        _level_rows(t, 0, 0, 16, 4, color=frag)
        cs = _u(want_tex)
        want = _classic(mode, "RGBA", np.broadcast_to(_u(frag), cs.shape), cs)
        _check(t, t.read(), 0, 0, want, f"BGRA texture, {mode}")
    gl.glTexImage2D(gl.GL_TEXTURE_2D, 0, gl.GL_RGBA, 1, 1, 0, gl.GL_BGRA_EXT, gl.GL_UNSIGNED_BYTE,
                    np.zeros(4, np.uint8))
    t.check_gl_error("TexImage2D with internalformat RGBA, format BGRA_EXT", gl.GL_INVALID_OPERATION)


@conformance_test("MipLevels.maxlevel", section="APPLE_texture_max_level", visuals=VISUALS, size=(16, 8))
def mip_levels_max_level(t: TestContext) -> None:
    """APPLE_texture_max_level: TEXTURE_MAX_LEVEL_APPLE (initially 1000) ends the levels a mipmapped
    texture needs and samples: levels 0..2 of a 32x32 chain with the limit 2 are complete, and
    lambda 3 or 4 shows level 2; a negative limit is INVALID_VALUE."""
    gl = t.gl
    t.need_extension("GL_APPLE_texture_max_level")
    _prepare(t)
    levels = _colour_levels()[:3]
    _texture(t, levels, minf="NEAREST_MIPMAP_NEAREST")
    if gl.glGetTexParameteriv(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAX_LEVEL_APPLE) != 1000:
        t.fail("TEXTURE_MAX_LEVEL_APPLE is not initially 1000")
    gl.glTexParameteri(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAX_LEVEL_APPLE, -1)
    t.check_gl_error("TEXTURE_MAX_LEVEL_APPLE -1", gl.GL_INVALID_VALUE)
    gl.glTexParameterx(gl.GL_TEXTURE_2D, gl.GL_TEXTURE_MAX_LEVEL_APPLE, 2)
    for x, lam in ((0, 0.0), (4, 1.0), (8, 3.0), (12, 4.0)):
        coords, _ = _lambda_quad(x, 0, 4, 8, lam)
        _quad(t, x, 0, x + 4, 8, [coords])
    img = t.read()
    for x, level in ((0, 0), (4, 1), (8, 2), (12, 2)):
        want = np.broadcast_to(_u(_LEVEL_COLORS[level]), (8, 4, 4))
        _check(t, img, x, 0, want, f"max level 2, level {level} at x = {x}")
    t.check_gl_error("MipLevels.maxlevel")


@conformance_test("TexNPOT", section="OES_texture_npot", visuals=VISUALS, size=(64, 64))
def tex_npot(t: TestContext) -> None:
    """OES_texture_npot: textures of any size (7x5, 6x3, 5x9) sample by equations 3.16-3.18 with
    w_s and h_s for 2^n and 2^m, NEAREST and LINEAR under REPEAT, MIRRORED_REPEAT and
    CLAMP_TO_EDGE with coordinates from -1 to 2 (half a texel a pixel); a mipmap of
    floor-halved levels (12x10, 6x5, 3x2, 1x1) is complete and shows each level at its lambda."""
    t.need_extension("GL_OES_texture_npot")
    rng = np.random.default_rng(13)
    c = ((-1.0, -1.0), (2.0, 2.0))
    for w, h in ((7, 5), (6, 3), (5, 9)):
        tex = rng.integers(0, 256, size=(h, w, 4), dtype=np.uint8)
        for wrap in ("REPEAT", "MIRRORED_REPEAT_OES", "CLAMP_TO_EDGE"):
            for filt in ("NEAREST", "LINEAR"):
                _prepare(t)
                _texture(t, [tex], minf=filt, magf=filt, wrap=wrap)
                _quad(t, 0, 0, 6 * w, 6 * h, [c])
                s, tt = _st(0, 0, 6 * w, 6 * h, c)
                want = _sample(_u(tex), s, tt, filt, wrap)
                _check(t, t.read(), 0, 0, want, f"{w}x{h} {wrap} {filt}")
    sizes = ((12, 10), (6, 5), (3, 2), (1, 1))
    levels = [rng.integers(0, 256, size=(hh, ww, 4), dtype=np.uint8) for ww, hh in sizes]
    _prepare(t)
    _texture(t, levels, minf="NEAREST_MIPMAP_NEAREST", magf="NEAREST")
    for d in range(4):
        _level_rows(t, 16 * d, d, 12, 10)
    img = t.read()
    for d in range(4):
        _check(t, img, 16 * d, 0, _u(levels[d]), f"NPOT mipmap level {d}")
    t.check_gl_error("TexNPOT")


# {============================================================
# TextureEdgeClamp


@conformance_test("TextureEdgeClamp", section="3.7.6", visuals=VISUALS, size=(64, 64))
def texture_edge_clamp(t: TestContext) -> None:
    """CLAMP_TO_EDGE with NEAREST and LINEAR, coordinates from -1 to 2: beyond the image
    only edge texels show, and LINEAR never blends in the opposite edge (coordinates
    clamped to [1/2N, 1 - 1/2N]); also on every level of a minified mipmap."""
    rng = np.random.default_rng(6)
    tex = rng.integers(0, 256, size=(8, 8, 4), dtype=np.uint8)
    tex[:, 0] = (255, 0, 0, 255)
    tex[:, -1] = (0, 0, 255, 255)
    tex[0, 1:-1] = (0, 255, 0, 255)
    tex[-1, 1:-1] = (255, 255, 0, 255)
    c = ((-1.0, -1.0), (2.0, 2.0))
    for filt in ("NEAREST", "LINEAR"):
        _prepare(t)
        _texture(t, [tex], minf=filt, magf=filt, wrap="CLAMP_TO_EDGE")
        _quad(t, 0, 0, 48, 48, [c])
        img = t.read()
        s, tt = _st(0, 0, 48, 48, c)
        _check(t, img, 0, 0, _sample(_u(tex), s, tt, filt, "CLAMP_TO_EDGE"), f"CLAMP_TO_EDGE {filt}")
    # a mipmap seen at lambda 1 and 2 (t constant): every level clamps with its own N
    levels = [tex] + [rng.integers(0, 256, size=(n, n, 4), dtype=np.uint8) for n in (4, 2, 1)]
    levels_f = [_u(v) for v in levels]
    _prepare(t)
    _texture(t, levels, minf="LINEAR_MIPMAP_NEAREST", magf="LINEAR", wrap="CLAMP_TO_EDGE")
    c2 = ((-1.0, 0.3125), (2.0, 0.3125))
    for k, lam in enumerate((1, 2)):
        width = 3 * (8 >> lam)              # s from -1 to 2, three images, over 24 / 2^lambda pixels
        _quad(t, 0, 8 * k, width, 8 * k + 4, [c2])
    img = t.read()
    for k, lam in enumerate((1, 2)):
        width = 3 * (8 >> lam)
        s, tt = _st(0, 8 * k, width, 8 * k + 4, c2)
        want = _mip(levels_f, s, tt, lam, "LINEAR_MIPMAP_NEAREST", "LINEAR", "CLAMP_TO_EDGE")
        _check(t, img, 0, 8 * k, want, f"CLAMP_TO_EDGE on level {lam}")
    t.check_gl_error("TextureEdgeClamp")


@conformance_test("TextureEdgeClamp.mirror", section="3.7.6", visuals=VISUALS)
def texture_mirror(t: TestContext) -> None:
    """OES_texture_mirrored_repeat: s - floor(s) on even integer parts, 1 - that on odd
    ones, then clamped like CLAMP_TO_EDGE, with NEAREST and LINEAR."""
    t.need_extension("GL_OES_texture_mirrored_repeat")
    rng = np.random.default_rng(7)
    tex = rng.integers(0, 256, size=(4, 8, 4), dtype=np.uint8)
    c = ((-2.1875, -1.0625), (2.3125, 1.9375))     # no pixel centre on a texel edge
    for filt in ("NEAREST", "LINEAR"):
        _prepare(t)
        _texture(t, [tex], minf=filt, magf=filt, wrap="MIRRORED_REPEAT_OES")
        _quad(t, 0, 0, 48, 32, [c])
        img = t.read()
        s, tt = _st(0, 0, 48, 32, c)
        _check(t, img, 0, 0, _sample(_u(tex), s, tt, filt, "MIRRORED_REPEAT_OES"), f"MIRRORED_REPEAT {filt}")
    t.check_gl_error("TextureEdgeClamp.mirror")


# {============================================================
# TexCombine

_RGB_FUNCS = ("REPLACE", "MODULATE", "ADD", "ADD_SIGNED", "INTERPOLATE", "SUBTRACT", "DOT3_RGB", "DOT3_RGBA")
_SOURCES = ("TEXTURE", "CONSTANT", "PRIMARY_COLOR", "PREVIOUS")
_RGB_OPS = ("SRC_COLOR", "ONE_MINUS_SRC_COLOR", "SRC_ALPHA", "ONE_MINUS_SRC_ALPHA")
_ALPHA_OPS = ("SRC_ALPHA", "ONE_MINUS_SRC_ALPHA")


def _combine(t: TestContext, cfg: dict) -> None:
    gl = t.gl
    e = lambda p, v: gl.glTexEnvi(gl.GL_TEXTURE_ENV, getattr(gl, "GL_" + p), getattr(gl, "GL_" + v))  # noqa: E731
    e("TEXTURE_ENV_MODE", "COMBINE")
    e("COMBINE_RGB", cfg["rgb"])
    e("COMBINE_ALPHA", cfg["alpha"])
    for n in range(3):
        e(f"SRC{n}_RGB", cfg["src_rgb"][n])
        e(f"OPERAND{n}_RGB", cfg["op_rgb"][n])
        e(f"SRC{n}_ALPHA", cfg["src_alpha"][n])
        e(f"OPERAND{n}_ALPHA", cfg["op_alpha"][n])
    gl.glTexEnvx(gl.GL_TEXTURE_ENV, gl.GL_RGB_SCALE, _fx(cfg["rgb_scale"]))
    gl.glTexEnvx(gl.GL_TEXTURE_ENV, gl.GL_ALPHA_SCALE, _fx(cfg["alpha_scale"]))
    gl.glTexEnvxv(gl.GL_TEXTURE_ENV, gl.GL_TEXTURE_ENV_COLOR, [_fx(c) for c in cfg["const"]])


def _combine_model(cfg: dict, cs: dict, cf: np.ndarray, cp: np.ndarray) -> np.ndarray:
    """Tables 3.17-3.19 (crossbar sources TEXTUREn from `cs`)."""
    cc = np.broadcast_to(np.asarray(cfg["const"], np.float64), cp.shape)
    src = {"TEXTURE": cs["TEXTURE"], "CONSTANT": cc, "PRIMARY_COLOR": cf, "PREVIOUS": cp, **cs}

    def arg(n: int, alpha: bool) -> np.ndarray:
        c = src[cfg["src_alpha" if alpha else "src_rgb"][n]]
        op = cfg["op_alpha" if alpha else "op_rgb"][n]
        v = c[..., 3] if alpha or "ALPHA" in op else None
        if v is None:
            v = c[..., :3]
        elif not alpha:
            v = np.repeat(v[..., None], 3, -1)
        return 1 - v if op.startswith("ONE_MINUS") else v

    def fn(f: str, a: list) -> np.ndarray:
        return {"REPLACE": lambda: a[0], "MODULATE": lambda: a[0] * a[1], "ADD": lambda: a[0] + a[1],
                "ADD_SIGNED": lambda: a[0] + a[1] - 0.5, "SUBTRACT": lambda: a[0] - a[1],
                "INTERPOLATE": lambda: a[0] * a[2] + a[1] * (1 - a[2])}[f]()

    r = [arg(n, False) for n in range(3)]
    a = [arg(n, True) for n in range(3)]
    out = np.empty(cp.shape)
    if cfg["rgb"].startswith("DOT3"):
        dot = 4 * ((r[0] - 0.5) * (r[1] - 0.5)).sum(-1)
        out[..., :3] = dot[..., None] * cfg["rgb_scale"]
        out[..., 3] = (dot if cfg["rgb"] == "DOT3_RGBA" else fn(cfg["alpha"], a)) * cfg["alpha_scale"]
    else:
        out[..., :3] = fn(cfg["rgb"], r) * cfg["rgb_scale"]
        out[..., 3] = fn(cfg["alpha"], a) * cfg["alpha_scale"]
    return np.clip(out, 0, 1)


def _combine_configs(crossbar: bool) -> list[dict]:
    rng = np.random.default_rng(12)
    srcs = _SOURCES + (("TEXTURE0", "TEXTURE1") if crossbar else ())
    out = []
    for k in range(48):
        rgb = _RGB_FUNCS[k % len(_RGB_FUNCS)]
        scales = (1.0, 2.0, 4.0)
        rs = scales[(k // 8) % 3]
        out.append({
            "rgb": rgb, "alpha": _RGB_FUNCS[(k + 3) % 6],
            "src_rgb": [srcs[(k + n * 5) % len(srcs)] for n in range(3)],
            "op_rgb": [_RGB_OPS[(k // 3 + n) % 4] for n in range(3)],
            "src_alpha": [srcs[(k * 3 + n * 7) % len(srcs)] for n in range(3)],
            "op_alpha": [_ALPHA_OPS[(k + n) % 2] for n in range(3)],
            "rgb_scale": rs, "alpha_scale": rs if rgb == "DOT3_RGBA" else scales[(k // 3) % 3],
            "const": tuple(float(v) for v in rng.integers(0, 256, 4) / 255),
        })
    return out


def _run_combine(t: TestContext, configs: list[dict], where: str) -> None:
    """Unit 0 MODULATEs texture A into the primary colour, unit 1 runs each COMBINE
    configuration with texture B; 8x8 pixels per configuration."""
    gl = t.gl
    rng = np.random.default_rng(13)
    a_tex = rng.integers(0, 256, size=(8, 8, 4), dtype=np.uint8)
    b_tex = rng.integers(0, 256, size=(8, 8, 4), dtype=np.uint8)
    _prepare(t)
    _texture(t, [a_tex], mode="MODULATE", unit=0)
    _texture(t, [b_tex], unit=1)
    gl.glActiveTexture(gl.GL_TEXTURE1)
    frags = rng.integers(0, 256, size=(len(configs), 4))
    coords = [((0.0, 0.0), (1.0, 1.0))] * 2
    for k, cfg in enumerate(configs):
        _combine(t, cfg)
        x, y = 8 * (k % 8), 8 * (k // 8)
        _quad(t, x, y, x + 8, y + 8, coords, color=frags[k])
    gl.glActiveTexture(gl.GL_TEXTURE0)
    img = t.read()
    cs = {"TEXTURE": _u(b_tex), "TEXTURE0": _u(a_tex), "TEXTURE1": _u(b_tex)}
    for k, cfg in enumerate(configs):
        cf = np.broadcast_to(_u(frags[k]), (8, 8, 4))
        want = _combine_model(cfg, cs, cf, cf * _u(a_tex))
        _check(t, img, 8 * (k % 8), 8 * (k // 8), want, f"{where}: {cfg}")
    t.check_gl_error(where)


@conformance_test("TexCombine", section="3.7.12", visuals=VISUALS)
def tex_combine(t: TestContext) -> None:
    """COMBINE on unit 1 after a MODULATE unit: every RGB and alpha function (DOT3 too),
    the sources TEXTURE, CONSTANT, PRIMARY_COLOR and PREVIOUS, every operand, RGB and
    alpha scales 1, 2 and 4 (Tables 3.17-3.19)."""
    _run_combine(t, _combine_configs(False), "TexCombine")


@conformance_test("TexCombine.crossbar", section="3.7.12", visuals=VISUALS)
def tex_combine_crossbar(t: TestContext) -> None:
    """OES_texture_env_crossbar: TEXTURE0 and TEXTURE1 as sources of either unit."""
    t.need_extension("GL_OES_texture_env_crossbar")
    _run_combine(t, _combine_configs(True), "TexCombine.crossbar")


@conformance_test("TexCombine.dot3alpha", section="3.7.12", visuals=VISUALS)
def tex_combine_dot3_alpha(t: TestContext) -> None:
    """DOT3_RGBA places the dot product in alpha too, and the ALPHA result is
    multiplied by ALPHA_SCALE (§3.7.12): RGB_SCALE 1 with ALPHA_SCALE 2 or 4."""
    base = {"rgb": "DOT3_RGBA", "alpha": "REPLACE", "src_rgb": ["TEXTURE", "CONSTANT", "CONSTANT"],
            "op_rgb": ["SRC_COLOR", "SRC_COLOR", "SRC_ALPHA"], "src_alpha": ["TEXTURE"] * 3,
            "op_alpha": ["SRC_ALPHA"] * 3, "rgb_scale": 1.0, "const": (0.75, 0.5, 0.5, 1.0)}
    configs = [dict(base, alpha_scale=s, const=(c, 0.5, 0.5, 1.0)) for s in (2.0, 4.0)
               for c in (0.6, 0.75, 0.9)]
    _run_combine(t, configs, "TexCombine.dot3alpha")


# {============================================================
# CopyTex


def _paint(t: TestContext, seed: int) -> None:
    """Smooth random colours over the window (GL_UNSIGNED_BYTE colours, GL_SHORT vertices)."""
    gl = t.gl
    rng = np.random.default_rng(seed)
    w, h = t.width, t.height
    v = np.array([0, 0, w, 0, 0, h, w, h, w // 2, h // 2], dtype=np.int16)
    idx = np.array([0, 1, 4, 1, 3, 4, 3, 2, 4, 2, 0, 4], dtype=np.uint16)
    col = rng.integers(0, 256, size=(5, 4), dtype=np.uint8)
    gl.glShadeModel(gl.GL_SMOOTH)
    gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, gl.GL_SHORT, 0, v)
    gl.glEnableClientState(gl.GL_COLOR_ARRAY)
    gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, col)
    gl.glDrawElements(gl.GL_TRIANGLES, 12, gl.GL_UNSIGNED_SHORT, idx)
    gl.glDisableClientState(gl.GL_COLOR_ARRAY)


@conformance_test("CopyTex", section="3.7.2", visuals=VISUALS)
def copy_tex(t: TestContext) -> None:
    """CopyTexImage2D makes a texture of the pixels ReadPixels returns, keeping the
    components of Table 3.8; formats needing alpha are INVALID_OPERATION on a buffer
    without it (Table 3.9); CopyTexSubImage2D replaces just its rectangle."""
    gl = t.gl
    has_alpha = t.visual.bits[3] > 0
    frag = (60, 120, 180, 240)
    for fmt in ("ALPHA", "LUMINANCE", "LUMINANCE_ALPHA", "RGB", "RGBA"):
        legal = has_alpha or fmt in ("LUMINANCE", "RGB")
        _prepare(t)
        gl.glDisable(gl.GL_TEXTURE_2D)
        _paint(t, 1)
        ref = t.read()[4:20, 8:40]
        gl.glBindTexture(gl.GL_TEXTURE_2D, 9)
        gl.glCopyTexImage2D(gl.GL_TEXTURE_2D, 0, getattr(gl, "GL_" + fmt), 8, 4, 32, 16, 0)
        if not legal:
            t.check_gl_error(f"CopyTexImage2D {fmt} without alpha bits", gl.GL_INVALID_OPERATION)
            continue
        t.check_gl_error(f"CopyTexImage2D {fmt}")
        _params(t)
        gl.glEnable(gl.GL_TEXTURE_2D)
        _env(t, "REPLACE")
        t.clear((0, 0, 0, 0))
        _quad(t, 0, 32, 32, 48, [((0.0, 0.0), (1.0, 1.0))], color=frag)
        want = _classic("REPLACE", fmt, np.broadcast_to(_u(frag), ref.shape), _base(ref, fmt))
        _check(t, t.read(), 0, 32, want, f"CopyTexImage2D {fmt}")
    # CopyTexSubImage2D into an RGB texture (legal on every visual)
    _prepare(t)
    gl.glDisable(gl.GL_TEXTURE_2D)
    _paint(t, 2)
    fb = t.read()
    tex = np.full((8, 8, 4), (10, 20, 30, 255), np.uint8)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 10)
    _upload(t, 0, "RGB", tex)
    gl.glCopyTexSubImage2D(gl.GL_TEXTURE_2D, 0, 2, 3, 40, 20, 5, 4)
    t.check_gl_error("CopyTexSubImage2D")
    want = _u(tex).copy()
    want[3:7, 2:7, :3] = fb[20:24, 40:45, :3]
    _params(t)
    gl.glEnable(gl.GL_TEXTURE_2D)
    _env(t, "REPLACE")
    t.clear((0, 0, 0, 0))
    _quad(t, 0, 0, 32, 32, [((0.0, 0.0), (1.0, 1.0))], color=frag)
    want_px = np.repeat(np.repeat(want, 4, axis=0), 4, axis=1)
    want_px[..., 3] = frag[3] / 255
    _check(t, t.read(), 0, 0, want_px, "CopyTexSubImage2D")
    gl.glDisable(gl.GL_TEXTURE_2D)


# {============================================================
# PackedPixels

_PACKED = (("RGBA", "UNSIGNED_BYTE", 4), ("RGB", "UNSIGNED_BYTE", 3), ("LUMINANCE_ALPHA", "UNSIGNED_BYTE", 2),
           ("LUMINANCE", "UNSIGNED_BYTE", 1), ("ALPHA", "UNSIGNED_BYTE", 1),
           ("RGB", "UNSIGNED_SHORT_5_6_5", 2), ("RGBA", "UNSIGNED_SHORT_4_4_4_4", 2),
           ("RGBA", "UNSIGNED_SHORT_5_5_5_1", 2))


def _unpack(raw: np.ndarray, fmt: str, gltype: str, w: int, h: int, align: int) -> np.ndarray:
    """§3.6.2: client texels (rows padded to the alignment) as float RGBA, before Table 3.8."""
    bpp = dict((f + ty, n) for f, ty, n in _PACKED)[fmt + gltype]
    stride = -(-w * bpp // align) * align
    rows = np.stack([raw[j * stride: j * stride + w * bpp] for j in range(h)])
    out = np.ones((h, w, 4))
    if gltype == "UNSIGNED_BYTE":
        c = rows.reshape(h, w, bpp) / 255.0
        if fmt == "ALPHA":
            out[..., 3] = c[..., 0]
        elif fmt.startswith("LUMINANCE"):
            out[..., :3] = c[..., :1]
            if fmt == "LUMINANCE_ALPHA":
                out[..., 3] = c[..., 1]
        else:
            out[..., :bpp] = c
        return out
    kind = {"UNSIGNED_SHORT_5_6_5": "565", "UNSIGNED_SHORT_4_4_4_4": "4444", "UNSIGNED_SHORT_5_5_5_1": "5551"}
    return _decode_entries(np.ascontiguousarray(rows).reshape(-1), kind[gltype], w * h).reshape(h, w, 4)


@conformance_test("PackedPixels", section="3.6.2", visuals=VISUALS)
def packed_pixels(t: TestContext) -> None:
    """TexImage2D of every format/type pair, the packed 5_6_5, 4_4_4_4 and 5_5_5_1 types
    included, at UNPACK_ALIGNMENT 1, 2, 4 and 8 (rows of two texels, so padding
    varies): each texel is its components over 2^n - 1 (§3.6.2), seen via REPLACE."""
    gl = t.gl
    rng = np.random.default_rng(14)
    frag = (70, 140, 210, 35)
    w, h = 2, 8
    for fmt, gltype, bpp in _PACKED:
        _prepare(t)
        raws = []
        for k, align in enumerate((1, 2, 4, 8)):
            stride = -(-w * bpp // align) * align
            raw = rng.integers(0, 256, size=stride * (h - 1) + w * bpp, dtype=np.uint8)
            raws.append(raw)
            gl.glBindTexture(gl.GL_TEXTURE_2D, 20 + k)
            gl.glPixelStorei(gl.GL_UNPACK_ALIGNMENT, align)
            f, ty = getattr(gl, "GL_" + fmt), getattr(gl, "GL_" + gltype)
            gl.glTexImage2D(gl.GL_TEXTURE_2D, 0, f, w, h, 0, f, ty, raw)
            t.check_gl_error(f"TexImage2D {fmt}/{gltype}, alignment {align}")
            _params(t)
            gl.glEnable(gl.GL_TEXTURE_2D)
            _env(t, "REPLACE")
            _quad(t, 12 * k, 0, 12 * k + 8, 32, [((0.0, 0.0), (1.0, 1.0))], color=frag)
        img = t.read()
        for k, align in enumerate((1, 2, 4, 8)):
            texels = _unpack(raws[k], fmt, gltype, w, h, align)
            want = _classic("REPLACE", fmt, np.broadcast_to(_u(frag), texels.shape), _base(texels, fmt))
            want = np.repeat(np.repeat(want, 4, axis=0), 4, axis=1)
            _check(t, img, 12 * k, 0, want, f"{fmt}/{gltype}, UNPACK_ALIGNMENT {align}",
                   storage=0.0 if gltype == "UNSIGNED_BYTE" else 0.5 / 255)
        gl.glDisable(gl.GL_TEXTURE_2D)
    gl.glPixelStorei(gl.GL_UNPACK_ALIGNMENT, 4)
    t.check_gl_error("PackedPixels")


# {============================================================
# TexCube, TexGen (OES_texture_cube_map)

_FACE_COLORS = np.array([(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 0, 255),
                         (255, 0, 255, 255), (0, 255, 255, 255)], dtype=np.uint8)
# a direction into each face (+x, -x, +y, -y, +z, -z), off every diagonal
_FACE_DIRS = ((1.0, 0.25, -0.375), (-1.0, -0.25, 0.375), (0.25, 1.0, 0.375), (-0.375, -1.0, 0.25),
              (0.375, -0.25, 1.0), (-0.25, 0.375, -1.0))


def _cube(t: TestContext, faces: Sequence[np.ndarray], name: int = 9) -> None:
    """Cube map `name` with one RGBA image per face (NEAREST, CLAMP_TO_EDGE), enabled, REPLACE."""
    gl = t.gl
    gl.glBindTexture(gl.GL_TEXTURE_CUBE_MAP_OES, name)
    gl.glPixelStorei(gl.GL_UNPACK_ALIGNMENT, 1)
    for f, img in enumerate(faces):
        h, w = img.shape[:2]
        gl.glTexImage2D(gl.GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + f, 0, gl.GL_RGBA, w, h, 0, gl.GL_RGBA,
                        gl.GL_UNSIGNED_BYTE, np.ascontiguousarray(img))
    for p, v in ((gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST), (gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST),
                 (gl.GL_TEXTURE_WRAP_S, gl.GL_CLAMP_TO_EDGE), (gl.GL_TEXTURE_WRAP_T, gl.GL_CLAMP_TO_EDGE)):
        gl.glTexParameteri(gl.GL_TEXTURE_CUBE_MAP_OES, p, v)
    gl.glEnable(gl.GL_TEXTURE_CUBE_MAP_OES)
    _env(t, "REPLACE")


def _solid_faces(size: int = 4) -> list[np.ndarray]:
    return [np.broadcast_to(c, (size, size, 4)).copy() for c in _FACE_COLORS]


@conformance_test("TexCube", section="OES_texture_cube_map", visuals=VISUALS, size=(48, 32))
def tex_cube(t: TestContext) -> None:
    """Face selection by the major axis of (s, t, r) (the extension's table): a quad per face with
    a constant direction into it takes that face's colour, also with TEXTURE_2D enabled (the cube
    map wins) and with the coordinates and q = 2 doubled (a positive q only scales the direction;
    whether a negative one flips it is left open: the extension lets q be ignored, and dividing by
    it is the other reading); within a face, s = (sc/|ma| + 1)/2 and
    t = (tc/|ma| + 1)/2 pick the quadrant of a 2x2 image on +z and on -x."""
    gl = t.gl
    t.need_extension("GL_OES_texture_cube_map")
    _prepare(t)
    _texture(t, [np.full((2, 2, 4), 128, np.uint8)])            # a 2D texture, enabled too
    _cube(t, _solid_faces())
    for f, d in enumerate(_FACE_DIRS):
        q = 1.0 if f % 2 == 0 else 2.0
        gl.glMultiTexCoord4x(gl.GL_TEXTURE0, *[_fx(v * q) for v in d], _fx(q))
        _quad(t, 8 * f, 0, 8 * f + 8, 8, [None])
    # quadrants: texel (i, j) of a 2x2 face
    quad_img = np.array([[(255, 0, 0, 255), (0, 255, 0, 255)], [(0, 0, 255, 255), (255, 255, 255, 255)]],
                        dtype=np.uint8)                       # [row j][column i]
    faces = _solid_faces(2)
    faces[1] = faces[4] = quad_img
    _cube(t, faces, name=10)
    # +z: sc = rx, tc = -ry; -x: sc = rz, tc = -ry (|ma| = 1): (s, t) in {0.25, 0.75}
    cases = [(4, (0.5, 0.5, 1.0), (1, 0)), (4, (-0.5, -0.5, 1.0), (0, 1)), (4, (0.5, -0.5, 1.0), (1, 1)),
             (1, (-1.0, 0.5, -0.5), (0, 0)), (1, (-1.0, -0.5, 0.5), (1, 1)), (1, (-1.0, 0.5, 0.5), (1, 0))]
    for k, (_, d, _) in enumerate(cases):
        gl.glMultiTexCoord4x(gl.GL_TEXTURE0, *[_fx(v) for v in d], ONE)
        _quad(t, 8 * k, 16, 8 * k + 8, 24, [None])
    img = t.read()
    for f in range(6):
        _check(t, img, 8 * f, 0, np.broadcast_to(_u(_FACE_COLORS[f]), (8, 8, 4)), f"face {f}")
    for k, (_, d, (i, j)) in enumerate(cases):
        _check(t, img, 8 * k, 16, np.broadcast_to(_u(quad_img[j, i]), (8, 8, 4)), f"direction {d}")
    gl.glDisable(gl.GL_TEXTURE_CUBE_MAP_OES)
    gl.glDisable(gl.GL_TEXTURE_2D)
    gl.glDeleteTextures(2, [9, 10])
    t.check_gl_error("TexCube")


@conformance_test("TexCube.errors", section="OES_texture_cube_map")
def tex_cube_errors(t: TestContext) -> None:
    """The extension's errors and state: faces must be square (INVALID_VALUE from TexImage2D and
    CopyTexImage2D), the cube target names no image and a face no parameters (INVALID_ENUM), a
    name stays a texture of its first target (INVALID_OPERATION), TEXTURE_BINDING_CUBE_MAP_OES,
    MAX_CUBE_MAP_TEXTURE_SIZE_OES >= 16, the enables per unit; an incomplete cube map (faces of
    different sizes) disables texturing even with TEXTURE_2D enabled."""
    gl = t.gl
    t.need_extension("GL_OES_texture_cube_map")
    cube, px = gl.GL_TEXTURE_CUBE_MAP_OES, gl.GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES
    if int(np.atleast_1d(gl.glGetIntegerv(gl.GL_MAX_CUBE_MAP_TEXTURE_SIZE_OES))[0]) < 16:
        t.fail("MAX_CUBE_MAP_TEXTURE_SIZE_OES below 16")
    gl.glBindTexture(cube, 11)
    if int(np.atleast_1d(gl.glGetIntegerv(gl.GL_TEXTURE_BINDING_CUBE_MAP_OES))[0]) != 11:
        t.fail("TEXTURE_BINDING_CUBE_MAP_OES is not the bound name")
    img = np.zeros((4, 8, 4), np.uint8)
    gl.glPixelStorei(gl.GL_UNPACK_ALIGNMENT, 1)
    gl.glTexImage2D(px + 2, 0, gl.GL_RGBA, 8, 4, 0, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE, img)
    t.check_gl_error("TexImage2D of a 8x4 face", gl.GL_INVALID_VALUE)
    gl.glCopyTexImage2D(px, 0, gl.GL_RGB, 0, 0, 4, 2, 0)
    t.check_gl_error("CopyTexImage2D of a 4x2 face", gl.GL_INVALID_VALUE)
    gl.glTexImage2D(cube, 0, gl.GL_RGBA, 4, 4, 0, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE, img)
    t.check_gl_error("TexImage2D on TEXTURE_CUBE_MAP_OES", gl.GL_INVALID_ENUM)
    gl.glTexParameteri(px, gl.GL_TEXTURE_MIN_FILTER, gl.GL_NEAREST)
    t.check_gl_error("TexParameteri on a face", gl.GL_INVALID_ENUM)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 11)
    t.check_gl_error("BindTexture(TEXTURE_2D) of a cube map", gl.GL_INVALID_OPERATION)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 12)
    gl.glBindTexture(cube, 12)
    t.check_gl_error("BindTexture(TEXTURE_CUBE_MAP_OES) of a 2D texture", gl.GL_INVALID_OPERATION)
    gl.glBindTexture(gl.GL_TEXTURE_2D, 0)
    gl.glActiveTexture(gl.GL_TEXTURE1)
    gl.glEnable(cube)
    on1 = bool(gl.glIsEnabled(cube))
    gl.glActiveTexture(gl.GL_TEXTURE0)
    if not on1 or gl.glIsEnabled(cube):
        t.fail("TEXTURE_CUBE_MAP_OES is not enabled per unit")
    gl.glActiveTexture(gl.GL_TEXTURE1)
    gl.glDisable(cube)
    gl.glActiveTexture(gl.GL_TEXTURE0)
    # incomplete: one face 2x2, the others 4x4; with TEXTURE_2D also on, no texturing at all
    t.ortho_pixels()
    t.clear((0, 0, 0, 0))
    faces = _solid_faces()
    faces[3] = faces[3][:2, :2].copy()
    _texture(t, [np.full((2, 2, 4), 200, np.uint8)])
    _cube(t, faces, name=11)
    gl.glMultiTexCoord4x(gl.GL_TEXTURE0, ONE, 0, 0, ONE)
    _quad(t, 0, 0, 8, 8, [None], color=(10, 20, 30, 40))
    _check(t, t.read(), 0, 0, np.broadcast_to(_u((10, 20, 30, 40)), (8, 8, 4)), "incomplete cube map")
    gl.glDisable(cube)
    gl.glDisable(gl.GL_TEXTURE_2D)
    gl.glDeleteTextures(2, [11, 12])
    t.check_gl_error("TexCube.errors")


def _texgen_quads(t: TestContext, mode: str, normals: Sequence[tuple[float, float, float]]) -> np.ndarray:
    """A quad per normal through TEXTURE_GEN_STR_OES `mode` into the six-colour cube map, the eye
    at the origin looking down -z at quads 50 units away (projection [-w/2, w/2] x [-h/2, h/2])."""
    gl = t.gl
    w, h = t.width, t.height
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthox(-(w << 15), w << 15, -(h << 15), h << 15, ONE, 100 * ONE)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glLoadIdentity()
    t.clear((0, 0, 0, 0))
    _cube(t, _solid_faces())
    gl.glTexGeniOES(gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES, getattr(gl, "GL_" + mode))
    gl.glEnable(gl.GL_TEXTURE_GEN_STR_OES)
    gl.glDisableClientState(gl.GL_TEXTURE_COORD_ARRAY)
    for k, n in enumerate(normals):
        gl.glNormal3x(*[_fx(v) for v in n])
        x0 = 8 * k - w / 2
        t.draw(gl.GL_TRIANGLE_STRIP, [x0, -4, -50, x0 + 8, -4, -50, x0, 4, -50, x0 + 8, 4, -50], size=3)
    gl.glDisable(gl.GL_TEXTURE_GEN_STR_OES)
    gl.glDisable(gl.GL_TEXTURE_CUBE_MAP_OES)
    gl.glDeleteTextures(1, [9])
    return t.read()


@conformance_test("TexGen.normal", section="OES_texture_cube_map 2.11.4", visuals=VISUALS, size=(48, 8))
def tex_gen_normal(t: TestContext) -> None:
    """NORMAL_MAP_OES: (s, t, r) is the eye-space normal, so a quad with a normal into each face
    takes that face's colour; TEXTURE_GEN_MODE_OES starts as REFLECTION_MAP_OES."""
    gl = t.gl
    t.need_extension("GL_OES_texture_cube_map")
    mode = (gl.GL_TEXTURE_GEN_STR_OES, gl.GL_TEXTURE_GEN_MODE_OES)
    if int(np.atleast_1d(gl.glGetTexGenivOES(*mode))[0]) != gl.GL_REFLECTION_MAP_OES:
        t.fail("TEXTURE_GEN_MODE_OES does not start as REFLECTION_MAP_OES")
    gl.glTexGeniOES(*mode, 0x2402)                             # SPHERE_MAP: not in ES
    t.check_gl_error("TexGeniOES SPHERE_MAP", gl.GL_INVALID_ENUM)
    img = _texgen_quads(t, "NORMAL_MAP_OES", [tuple(v / np.linalg.norm(v)) for v in np.array(_FACE_DIRS)])
    for f in range(6):
        _check(t, img, 8 * f, 0, np.broadcast_to(_u(_FACE_COLORS[f]), (8, 8, 4)), f"normal into face {f}")
    t.check_gl_error("TexGen.normal")


@conformance_test("TexGen.reflection", section="OES_texture_cube_map 2.11.4", visuals=VISUALS, size=(32, 8))
def tex_gen_reflection(t: TestContext) -> None:
    """REFLECTION_MAP_OES: r = u - 2 n (n . u), u the unit vector from the eye to the vertex. Quads
    50 units ahead (u close to -z): normal (0, 0, 1) reflects into +z, (0.6, 0, 0.8) into +x,
    (0, -0.6, 0.8) into -y, (1, 0, 0) (n . u small) leaves u: -z."""
    t.need_extension("GL_OES_texture_cube_map")
    img = _texgen_quads(t, "REFLECTION_MAP_OES", [(0, 0, 1), (0.6, 0, 0.8), (0, -0.6, 0.8), (1, 0, 0)])
    for k, f in enumerate((4, 0, 3, 5)):
        _check(t, img, 8 * k, 0, np.broadcast_to(_u(_FACE_COLORS[f]), (8, 8, 4)), f"quad {k}: face {f}")
    t.check_gl_error("TexGen.reflection")


@conformance_test("TexCube.wrap", section="OES_texture_cube_map 3.8.10", visuals=("rgba8888",), size=(16, 8))
def tex_cube_wrap(t: TestContext) -> None:
    """A face is sampled by §3.7.7 with the cube map's own wrap modes (ARB_texture_cube_map's
    resolution: every wrap mode applies, CLAMP_TO_EDGE being the one suited to cube maps): on
    +x, (1, 0, 0.8) gives s = 0.1 on a 2x2 face of a red and a blue column, so LINEAR takes
    0.7 red + 0.3 blue under REPEAT (i0 = -1 wraps to the blue column) and red under
    CLAMP_TO_EDGE."""
    gl = t.gl
    t.need_extension("GL_OES_texture_cube_map")
    _prepare(t)
    red, blue = np.array((255, 0, 0, 255)), np.array((0, 0, 255, 255))
    faces = _solid_faces(2)
    faces[0] = np.array([[red, blue], [red, blue]], dtype=np.uint8)
    for k, wrap in enumerate(("REPEAT", "CLAMP_TO_EDGE")):
        _cube(t, faces, name=12 + k)
        for p in (gl.GL_TEXTURE_MIN_FILTER, gl.GL_TEXTURE_MAG_FILTER):
            gl.glTexParameteri(gl.GL_TEXTURE_CUBE_MAP_OES, p, gl.GL_LINEAR)
        for p in (gl.GL_TEXTURE_WRAP_S, gl.GL_TEXTURE_WRAP_T):
            gl.glTexParameteri(gl.GL_TEXTURE_CUBE_MAP_OES, p, getattr(gl, "GL_" + wrap))
        gl.glMultiTexCoord4x(gl.GL_TEXTURE0, ONE, 0, _fx(0.8), ONE)
        _quad(t, 8 * k, 0, 8 * k + 8, 8, [None])
    img = t.read()
    s = _q16(0.8) / 2                          # |sc/ma| as the 16.16 coordinate gives it
    a = (1 - s) * 2 - 0.5 - np.floor((1 - s) * 2 - 0.5)
    mixed = (1 - a) * _u(blue) + a * _u(red)   # texels -1 (wrapped: blue) and 0 (red)
    _check(t, img, 0, 0, np.broadcast_to(mixed, (8, 8, 4)), "REPEAT")
    _check(t, img, 8, 0, np.broadcast_to(_u(red), (8, 8, 4)), "CLAMP_TO_EDGE")
    gl.glDisable(gl.GL_TEXTURE_CUBE_MAP_OES)
    gl.glDeleteTextures(2, [12, 13])
    t.check_gl_error("TexCube.wrap")
