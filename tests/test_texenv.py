"""Texture environments (ES 1.1 §3.7.12-3.7.13, OES_texture_env_crossbar).

Each pixel is checked against numpy evaluations of Tables 3.14-3.19: the five
classic functions for every base format, COMBINE with every function,
source, operand and scale, DOT3 on biased normals, crossbar sources, and
chains of two to four units. Textures are drawn 1:1 with NEAREST, so each
pixel's texture colour is exactly one texel; the primary colour is flat.
Tolerance: the visual's one 8-bit step plus 2^-13 (gles keeps every stage
unrounded); llvmpipe rounds each stage's result to 8 bits, so it gets half a
step per earlier rounding, times the scale, on top.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any, NamedTuple

import numpy as np
import pytest
from test_texture import (
    NEAREST,
    TARGETS,
    Quad,
    Target,
    base_color,
    client_bytes,
    draw_quad,
    expect_close,
    open_target,
    ortho,
    region,
    tolerance,
    unorm,
)

from gles import constants as C


@pytest.fixture(params=TARGETS)
def target(request: pytest.FixtureRequest) -> Iterator[Target]:
    """Each gles build, then Mesa llvmpipe (skipped where it cannot run)."""
    yield from open_target(request)


FORMATS = (C.GL_ALPHA, C.GL_LUMINANCE, C.GL_LUMINANCE_ALPHA, C.GL_RGB, C.GL_RGBA)
MODES = (C.GL_REPLACE, C.GL_MODULATE, C.GL_DECAL, C.GL_BLEND, C.GL_ADD)
RGB_FUNCS = (C.GL_REPLACE, C.GL_MODULATE, C.GL_ADD, C.GL_ADD_SIGNED, C.GL_INTERPOLATE, C.GL_SUBTRACT,
             C.GL_DOT3_RGB, C.GL_DOT3_RGBA)
ALPHA_FUNCS = RGB_FUNCS[:6]
ARGS_USED = {C.GL_REPLACE: 1, C.GL_MODULATE: 2, C.GL_ADD: 2, C.GL_ADD_SIGNED: 2, C.GL_INTERPOLATE: 3,
             C.GL_SUBTRACT: 2, C.GL_DOT3_RGB: 2, C.GL_DOT3_RGBA: 2}
RGB_OPS = (C.GL_SRC_COLOR, C.GL_ONE_MINUS_SRC_COLOR, C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
ALPHA_OPS = (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
SOURCES = (C.GL_TEXTURE, C.GL_CONSTANT, C.GL_PRIMARY_COLOR, C.GL_PREVIOUS, C.GL_TEXTURE0, C.GL_TEXTURE1)
TEX = 8                       # texture size; quads are TEX x TEX pixels (one texel each)


def name(v: int) -> str:
    return C.NAMES[v].replace("GL_", "")


def stage_tol(kind: str, roundings: int = 0, scale: float = 1.0) -> float:
    """gles: the visual's; llvmpipe: plus half a step per 8-bit rounding before, times the scale."""
    tol = tolerance(kind)
    if kind == "llvmpipe":
        tol += roundings * scale * 0.5 / 255
    return tol


# {================================================================
# the model


def classic_env(mode: int, fmt: int, cp: np.ndarray, cs: np.ndarray, cc: np.ndarray) -> np.ndarray:
    """Tables 3.15 and 3.16: (Cv, Av) from the previous colour, the texture source
    colour of Table 3.14 and the environment colour."""
    out = np.array(cp, dtype=np.float64, copy=True)
    rgb = slice(0, 3)
    has_rgb = fmt != C.GL_ALPHA
    has_a = fmt in (C.GL_ALPHA, C.GL_LUMINANCE_ALPHA, C.GL_RGBA)
    if mode == C.GL_REPLACE:
        if has_rgb:
            out[..., rgb] = cs[..., rgb]
        if has_a:
            out[..., 3] = cs[..., 3]
    elif mode == C.GL_MODULATE:
        if has_rgb:
            out[..., rgb] = cp[..., rgb] * cs[..., rgb]
        if has_a:
            out[..., 3] = cp[..., 3] * cs[..., 3]
    elif mode == C.GL_DECAL:
        if fmt == C.GL_RGB:
            out[..., rgb] = cs[..., rgb]
        else:                 # RGBA (the others are undefined)
            a = cs[..., 3:4]
            out[..., rgb] = cp[..., rgb] * (1 - a) + cs[..., rgb] * a
    elif mode == C.GL_BLEND:
        if has_rgb:
            out[..., rgb] = cp[..., rgb] * (1 - cs[..., rgb]) + cc[..., rgb] * cs[..., rgb]
        if has_a:
            out[..., 3] = cp[..., 3] * cs[..., 3]
    elif mode == C.GL_ADD:
        if has_rgb:
            out[..., rgb] = np.minimum(cp[..., rgb] + cs[..., rgb], 1.0)
        if has_a:
            out[..., 3] = cp[..., 3] * cs[..., 3]
    return out


class Combine(NamedTuple):
    """One unit's COMBINE state."""

    rgb: int
    alpha: int
    src_rgb: tuple[int, int, int]
    op_rgb: tuple[int, int, int]
    src_alpha: tuple[int, int, int]
    op_alpha: tuple[int, int, int]
    rgb_scale: float
    alpha_scale: float
    const: tuple[float, float, float, float]

    def apply(self, gl: Any) -> None:
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_COMBINE)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_RGB, self.rgb)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_COMBINE_ALPHA, self.alpha)
        for n in range(3):
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_RGB + n, self.src_rgb[n])
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_SRC0_ALPHA + n, self.src_alpha[n])
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND0_RGB + n, self.op_rgb[n])
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_OPERAND0_ALPHA + n, self.op_alpha[n])
        gl.glTexEnvx(C.GL_TEXTURE_ENV, C.GL_RGB_SCALE, int(self.rgb_scale * 65536))
        gl.glTexEnvx(C.GL_TEXTURE_ENV, C.GL_ALPHA_SCALE, int(self.alpha_scale * 65536))
        gl.glTexEnvxv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, [int(round(c * 65536)) for c in self.const])

    def __str__(self) -> str:
        rgb = ", ".join(f"{name(s)}.{name(o)}" for s, o in zip(self.src_rgb, self.op_rgb))
        alpha = ", ".join(f"{name(s)}.{name(o)}" for s, o in zip(self.src_alpha, self.op_alpha))
        return (f"RGB {name(self.rgb)}({rgb}) x{self.rgb_scale:g}, "
                f"ALPHA {name(self.alpha)}({alpha}) x{self.alpha_scale:g}")


def combine_model(cfg: Combine, unit: int, cf: np.ndarray, cp: np.ndarray,
                  ct: list[np.ndarray]) -> np.ndarray:
    """Tables 3.17-3.19 with crossbar sources: ct[n] is unit n's texture source colour."""
    cc = np.broadcast_to(np.asarray(cfg.const, dtype=np.float64), cp.shape)

    def source(src: int) -> np.ndarray:
        if src == C.GL_TEXTURE:
            return ct[unit]
        if src == C.GL_CONSTANT:
            return cc
        if src == C.GL_PRIMARY_COLOR:
            return cf
        if src == C.GL_PREVIOUS:
            return cp
        return ct[src - C.GL_TEXTURE0]

    def arg_rgb(n: int) -> np.ndarray:
        c, op = source(cfg.src_rgb[n]), cfg.op_rgb[n]
        v = c[..., :3] if op in (C.GL_SRC_COLOR, C.GL_ONE_MINUS_SRC_COLOR) else np.repeat(c[..., 3:4], 3, -1)
        return 1 - v if op in (C.GL_ONE_MINUS_SRC_COLOR, C.GL_ONE_MINUS_SRC_ALPHA) else v

    def arg_alpha(n: int) -> np.ndarray:
        v = source(cfg.src_alpha[n])[..., 3]
        return 1 - v if cfg.op_alpha[n] == C.GL_ONE_MINUS_SRC_ALPHA else v

    def fn(f: int, a0: np.ndarray, a1: np.ndarray, a2: np.ndarray) -> np.ndarray:
        return {C.GL_REPLACE: lambda: a0, C.GL_MODULATE: lambda: a0 * a1, C.GL_ADD: lambda: a0 + a1,
                C.GL_ADD_SIGNED: lambda: a0 + a1 - 0.5, C.GL_INTERPOLATE: lambda: a0 * a2 + a1 * (1 - a2),
                C.GL_SUBTRACT: lambda: a0 - a1}[f]()

    out = np.empty(cp.shape)
    r = [arg_rgb(n) for n in range(3)]
    a = [arg_alpha(n) for n in range(3)]
    if cfg.rgb in (C.GL_DOT3_RGB, C.GL_DOT3_RGBA):
        dot = 4 * ((r[0] - 0.5) * (r[1] - 0.5)).sum(axis=-1)
        out[..., :3] = dot[..., None] * cfg.rgb_scale
        # the scalar goes into alpha too for DOT3_RGBA; ALPHA results take ALPHA_SCALE
        out[..., 3] = (dot if cfg.rgb == C.GL_DOT3_RGBA else fn(cfg.alpha, *a)) * cfg.alpha_scale
    else:
        out[..., :3] = fn(cfg.rgb, *r) * cfg.rgb_scale
        out[..., 3] = fn(cfg.alpha, *a) * cfg.alpha_scale
    return np.clip(out, 0.0, 1.0)


# {================================================================
# drawing


def bind_unit(gl: Any, unit: int, rgba_u8: np.ndarray, fmt: int = C.GL_RGBA) -> None:
    """Texture `rgba_u8` (stored as `fmt`) on `unit`, NEAREST, enabled."""
    gl.glActiveTexture(C.GL_TEXTURE0 + unit)
    gl.glBindTexture(C.GL_TEXTURE_2D, 100 + unit)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    h, w = rgba_u8.shape[:2]
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, fmt, w, h, 0, fmt, C.GL_UNSIGNED_BYTE, client_bytes(rgba_u8, fmt))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, NEAREST)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, NEAREST)
    gl.glEnable(C.GL_TEXTURE_2D)


def cell(k: int, units: int = 1) -> Quad:
    """The k-th TEX x TEX cell of a 64x64 window, texture coordinates 0..1 on `units` units."""
    x, y = TEX * (k % 8), TEX * (k // 8)
    return Quad(x, y, x + TEX, y + TEX, (((0.0, 0.0), (1.0, 1.0)),) * units)


def draw_cells(t: Target, draws: list[tuple[Quad, Any, Any]]) -> np.ndarray:
    """Clear, then per cell: set its state with `setup(gl)`, draw it in its flat colour; read back."""
    gl = t.gl
    ortho(gl, t.w, t.h)
    gl.glClearColorx(0, 0, 0, 0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    gl.glShadeModel(C.GL_FLAT)
    for q, color, setup in draws:
        setup(gl)
        draw_quad(gl, q, color)
    assert gl.glGetError() == 0
    return t.read()


# {================================================================
# the classic functions (Tables 3.14-3.16)


@pytest.mark.parametrize("fmt", FORMATS, ids=name)
@pytest.mark.parametrize("mode", MODES, ids=name)
def test_classic_env_per_base_format(target: Target, mode: int, fmt: int):
    """REPLACE, MODULATE, DECAL, BLEND and ADD on each base format (DECAL only on RGB
    and RGBA, where it is defined), over 16 primary colours and environment colours."""
    if mode == C.GL_DECAL and fmt not in (C.GL_RGB, C.GL_RGBA):
        pytest.skip("Table 3.15: DECAL is undefined for ALPHA, LUMINANCE and LUMINANCE_ALPHA")
    rng = np.random.default_rng(mode * 10 + fmt)
    tex_u8 = rng.integers(0, 256, size=(TEX, TEX, 4), dtype=np.uint8)
    tex_u8[0, :4] = ((0, 0, 0, 0), (255, 255, 255, 255), (255, 0, 128, 0), (0, 255, 0, 255))
    cs = base_color(unorm(tex_u8), fmt)
    gl = target.gl
    bind_unit(gl, 0, tex_u8, fmt)
    colors = rng.integers(0, 256, size=(16, 4))
    colors[:2] = ((255, 255, 255, 255), (0, 0, 0, 0))
    envs = rng.integers(0, 256, size=(16, 4)) / 255

    def setup(k: int) -> Any:
        def f(g: Any) -> None:
            g.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, mode)
            g.glTexEnvxv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, [int(round(c * 65536)) for c in envs[k]])
        return f

    img = draw_cells(target, [(cell(k), colors[k], setup(k)) for k in range(16)])
    for k in range(16):
        cp = np.broadcast_to(unorm(colors[k]), cs.shape)
        want = classic_env(mode, fmt, cp, cs, np.broadcast_to(envs[k], cs.shape))
        expect_close(region(img, cell(k)), want, stage_tol(target.kind, 1),
                     f"{name(mode)} {name(fmt)} colour {colors[k].tolist()} env {np.round(envs[k], 3)}")


# {================================================================
# COMBINE (Tables 3.17-3.19) with crossbar sources


def combine_configs() -> list[Combine]:
    """Every (function, argument, source, operand) of the RGB and the alpha combiner,
    the other arguments, scales and the constant colour drawn at random."""
    rng = np.random.default_rng(2024)
    out = []

    def rand_cfg(**fixed: Any) -> Combine:
        rgb = fixed.get("rgb", RGB_FUNCS[rng.integers(len(RGB_FUNCS))])
        alpha = fixed.get("alpha", ALPHA_FUNCS[rng.integers(len(ALPHA_FUNCS))])
        src_rgb = [SOURCES[i] for i in rng.integers(len(SOURCES), size=3)]
        op_rgb = [RGB_OPS[i] for i in rng.integers(4, size=3)]
        src_alpha = [SOURCES[i] for i in rng.integers(len(SOURCES), size=3)]
        op_alpha = [ALPHA_OPS[i] for i in rng.integers(2, size=3)]
        for key, (srcs, ops) in (("rgb_arg", (src_rgb, op_rgb)), ("alpha_arg", (src_alpha, op_alpha))):
            if key in fixed:
                n, s, o = fixed[key]
                srcs[n], ops[n] = s, o
        scales = (1.0, 2.0, 4.0)
        rs, as_ = scales[rng.integers(3)], scales[rng.integers(3)]
        if rgb == C.GL_DOT3_RGBA:
            as_ = rs          # the alpha scale of DOT3_RGBA has a test of its own
        const = tuple(float(c) for c in rng.integers(0, 256, size=4) / 255)
        return Combine(rgb, alpha, tuple(src_rgb), tuple(op_rgb), tuple(src_alpha), tuple(op_alpha), rs, as_,
                       const)

    for f in RGB_FUNCS:
        for n in range(ARGS_USED[f]):
            for s in SOURCES:
                for o in RGB_OPS:
                    out.append(rand_cfg(rgb=f, rgb_arg=(n, s, o)))
    for f in ALPHA_FUNCS:
        for n in range(ARGS_USED[f]):
            for s in SOURCES:
                for o in ALPHA_OPS:
                    out.append(rand_cfg(rgb=C.GL_MODULATE, alpha=f, alpha_arg=(n, s, o)))
    return out


CONFIGS = combine_configs()


def test_combine_every_function_source_operand(target: Target):
    """Unit 0 MODULATEs texture A into the primary colour; unit 1 runs COMBINE with
    texture B: every function x argument x source (TEXTURE, CONSTANT, PRIMARY_COLOR,
    PREVIOUS, TEXTURE0, TEXTURE1) x operand of both combiners, scales 1/2/4,
    texture B in each base format in turn."""
    gl = target.gl
    rng = np.random.default_rng(7)
    a_u8 = rng.integers(0, 256, size=(TEX, TEX, 4), dtype=np.uint8)
    b_u8 = rng.integers(0, 256, size=(TEX, TEX, 4), dtype=np.uint8)
    a_u8[0, :3] = ((0, 0, 0, 0), (255, 255, 255, 255), (128, 128, 128, 128))
    b_u8[1, :3] = ((255, 255, 255, 255), (0, 0, 0, 0), (127, 128, 129, 128))
    cs_a = unorm(a_u8)
    colors = rng.integers(0, 256, size=(len(CONFIGS), 4))
    checked = 0
    for start in range(0, len(CONFIGS), 64):
        fmt = FORMATS[(start // 64) % len(FORMATS)]
        cs_b = base_color(unorm(b_u8), fmt)
        bind_unit(gl, 0, a_u8)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
        bind_unit(gl, 1, b_u8, fmt)
        batch = CONFIGS[start:start + 64]
        img = draw_cells(target, [(cell(k, 2), colors[start + k], cfg.apply) for k, cfg in enumerate(batch)])
        for k, cfg in enumerate(batch):
            cf = np.broadcast_to(unorm(colors[start + k]), cs_a.shape)
            cp = cf * cs_a
            want = combine_model(cfg, 1, cf, cp, [cs_a, cs_b])
            uses_prev = C.GL_PREVIOUS in cfg.src_rgb + cfg.src_alpha
            tol = stage_tol(target.kind, 1 + uses_prev, max(cfg.rgb_scale, cfg.alpha_scale))
            expect_close(region(img, cell(k)), want, tol, f"{cfg} (texture B {name(fmt)})")
            checked += 1
    assert checked == len(CONFIGS) > 500


def test_combine_state_queries():
    """COMBINE state reads back per unit with GetTexEnviv / GetTexEnvxv (§6.1.2)."""
    t = Target("fixed", 8, 8)
    gl = t.gl
    for u, cfg in enumerate(CONFIGS[:4]):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        cfg.apply(gl)
    for u, cfg in enumerate(CONFIGS[:4]):
        gl.glActiveTexture(C.GL_TEXTURE0 + u)
        e = lambda p: gl.glGetTexEnviv(C.GL_TEXTURE_ENV, p)  # noqa: E731
        assert (e(C.GL_COMBINE_RGB), e(C.GL_COMBINE_ALPHA)) == (cfg.rgb, cfg.alpha)
        assert tuple(e(C.GL_SRC0_RGB + n) for n in range(3)) == cfg.src_rgb
        assert tuple(e(C.GL_OPERAND0_ALPHA + n) for n in range(3)) == cfg.op_alpha
        assert gl.glGetTexEnvxv(C.GL_TEXTURE_ENV, C.GL_RGB_SCALE) == int(cfg.rgb_scale * 65536)
        got = gl.glGetTexEnvxv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR)
        assert np.abs(np.asarray(got) - np.round(np.asarray(cfg.const) * 65536)).max() <= 1
    assert gl.glGetError() == 0


# {================================================================
# DOT3 with biased normals


def normal_map(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """(uint8 RGB(A) texels, unit normals): n in the upper hemisphere stored as 0.5 + n / 2."""
    n = rng.normal(size=(TEX, TEX, 3))
    n[..., 2] = np.abs(n[..., 2]) + 0.3
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    tex = np.empty((TEX, TEX, 4), np.uint8)
    tex[..., :3] = np.round((n * 0.5 + 0.5) * 255)
    tex[..., 3] = 255
    return tex, n


@pytest.mark.parametrize("scale", [1.0, 2.0, 4.0])
def test_dot3_biased_normals(target: Target, scale: float):
    """DOT3_RGB and DOT3_RGBA of a biased normal map with biased light vectors (in the
    constant colour and in the primary colour): 4 sum((a0 - 1/2)(a1 - 1/2)) = N.L,
    scaled and clamped, in every channel (RGBA: alpha too)."""
    gl = target.gl
    rng = np.random.default_rng(int(scale))
    tex, normals = normal_map(rng)
    bind_unit(gl, 0, tex, C.GL_RGB)
    cs = base_color(unorm(tex), C.GL_RGB)
    lights = rng.normal(size=(16, 3))
    lights[:, 2] = np.abs(lights[:, 2])
    lights /= np.linalg.norm(lights, axis=-1, keepdims=True)
    biased = np.round((lights * 0.5 + 0.5) * 255).astype(int)
    draws, cfgs = [], []
    for k in range(16):
        func = C.GL_DOT3_RGBA if k % 2 else C.GL_DOT3_RGB
        src = C.GL_CONSTANT if k < 8 else C.GL_PRIMARY_COLOR
        const = tuple(float(v) for v in (*biased[k] / 255, 0.25))
        cfg = Combine(func, C.GL_REPLACE, (C.GL_TEXTURE, src, C.GL_CONSTANT),
                      (C.GL_SRC_COLOR, C.GL_SRC_COLOR, C.GL_SRC_ALPHA),
                      (C.GL_PRIMARY_COLOR, C.GL_PREVIOUS, C.GL_CONSTANT), (C.GL_SRC_ALPHA,) * 3,
                      scale, scale, const)
        cfgs.append(cfg)
        draws.append((cell(k), (*biased[k], 77), cfg.apply))
    img = draw_cells(target, draws)
    for k, cfg in enumerate(cfgs):
        cf = np.broadcast_to(unorm((*biased[k], 77)), cs.shape)
        want = combine_model(cfg, 0, cf, cf, [cs])
        got = region(img, cell(k))
        expect_close(got, want, stage_tol(target.kind, 1, scale), str(cfg))
        # against the unquantized geometry: N.L, within what 8-bit storage of n and l allows
        ideal = np.clip((normals @ lights[k]) * scale, 0, 1)
        bound = scale * 4 * 3 * (0.5 / 255) + stage_tol(target.kind, 1, scale)
        assert np.abs(got[..., 0] - ideal).max() <= bound


def test_dot3_rgba_alpha_takes_alpha_scale(target: Target):
    """DOT3_RGBA puts the dot product into alpha as well, and §3.7.12 multiplies the
    ALPHA result by ALPHA_SCALE: RGB_SCALE 1, ALPHA_SCALE 2 gives alpha = 2 x dot."""
    gl = target.gl
    bind_unit(gl, 0, np.full((TEX, TEX, 4), (255, 128, 64, 255), np.uint8), C.GL_RGBA)
    cfg = Combine(C.GL_DOT3_RGBA, C.GL_REPLACE, (C.GL_TEXTURE, C.GL_CONSTANT, C.GL_CONSTANT),
                  (C.GL_SRC_COLOR, C.GL_SRC_COLOR, C.GL_SRC_ALPHA), (C.GL_TEXTURE,) * 3,
                  (C.GL_SRC_ALPHA,) * 3, 1.0, 2.0, (0.75, 0.5, 0.5, 1.0))
    img = draw_cells(target, [(cell(0), (255, 255, 255, 255), cfg.apply)])
    # dot = 4 ((1 - 1/2)(3/4 - 1/2) + ...) = 0.5: RGB 0.5, alpha 2 x 0.5 = 1
    got = region(img, cell(0))
    expect_close(got, np.broadcast_to([0.5, 0.5, 0.5, 1.0], got.shape), stage_tol(target.kind, 1),
                 "DOT3_RGBA with RGB_SCALE 1, ALPHA_SCALE 2")


# {================================================================
# crossbar and multitexture (§3.7.13, OES_texture_env_crossbar)


def test_crossbar_four_units(target: Target):
    """Four units reading each other's textures, including later units: unit 0 takes
    TEXTURE3, unit 1 interpolates TEXTURE0 and TEXTURE2 by TEXTURE1's alpha, unit 2
    subtracts TEXTURE1 from PREVIOUS, unit 3 adds its own texture, signed."""
    gl = target.gl
    if gl.glGetIntegerv(C.GL_MAX_TEXTURE_UNITS) < 4:
        pytest.skip("fewer than 4 texture units")
    rng = np.random.default_rng(99)
    texs = [rng.integers(0, 256, size=(TEX, TEX, 4), dtype=np.uint8) for _ in range(4)]
    fmts = (C.GL_RGBA, C.GL_RGBA, C.GL_LUMINANCE_ALPHA, C.GL_RGB)
    cs = [base_color(unorm(tx), f) for tx, f in zip(texs, fmts)]
    sc, sa = (C.GL_SRC_COLOR,) * 3, (C.GL_SRC_ALPHA,) * 3
    k = 0.0, 0.0, 0.0, 0.0
    cfgs = [
        Combine(C.GL_REPLACE, C.GL_MODULATE, (C.GL_TEXTURE3,) * 3, sc, (C.GL_TEXTURE3, C.GL_PREVIOUS, 0), sa,
                1.0, 1.0, k),
        Combine(C.GL_INTERPOLATE, C.GL_INTERPOLATE, (C.GL_TEXTURE0, C.GL_TEXTURE2, C.GL_TEXTURE1),
                (C.GL_SRC_COLOR, C.GL_SRC_COLOR, C.GL_SRC_ALPHA),
                (C.GL_TEXTURE0, C.GL_TEXTURE2, C.GL_TEXTURE1), sa, 1.0, 1.0, k),
        Combine(C.GL_SUBTRACT, C.GL_ADD, (C.GL_PREVIOUS, C.GL_TEXTURE1, 0), sc,
                (C.GL_PREVIOUS, C.GL_TEXTURE0, 0), (C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA, C.GL_SRC_ALPHA),
                2.0, 1.0, k),
        Combine(C.GL_ADD_SIGNED, C.GL_REPLACE, (C.GL_PREVIOUS, C.GL_TEXTURE, 0), sc, (C.GL_TEXTURE2,) * 3, sa,
                1.0, 1.0, k),
    ]
    cfgs = [c._replace(src_rgb=tuple(s or C.GL_CONSTANT for s in c.src_rgb),
                       src_alpha=tuple(s or C.GL_CONSTANT for s in c.src_alpha)) for c in cfgs]

    def setup(g: Any) -> None:
        for u in range(4):
            bind_unit(g, u, texs[u], fmts[u])
            cfgs[u].apply(g)

    img = draw_cells(target, [(cell(0, 4), (200, 100, 50, 150), setup)])
    cf = np.broadcast_to(unorm((200, 100, 50, 150)), cs[0].shape)
    cp = cf
    for u in range(4):
        cp = combine_model(cfgs[u], u, cf, cp, cs)
    expect_close(region(img, cell(0)), cp, stage_tol(target.kind, 4, 2.0), "four-unit crossbar")


def test_multitexture_chain(target: Target):
    """Two to four units with classic functions and their own coordinates (one unit
    from glMultiTexCoord4x, no array): each unit takes the previous unit's result;
    a disabled unit in the middle passes it on unchanged (§3.7.13)."""
    rng = np.random.default_rng(5)
    texs = [rng.integers(0, 256, size=(TEX, TEX, 4), dtype=np.uint8) for _ in range(4)]
    fmts = (C.GL_RGBA, C.GL_LUMINANCE, C.GL_RGB, C.GL_ALPHA)
    modes = (C.GL_MODULATE, C.GL_ADD, C.GL_BLEND, C.GL_MODULATE)
    envc = (0.2, 0.9, 0.4, 0.6)
    color = (180, 90, 220, 160)
    for nunits in (2, 3, 4):
        for disabled in ([None, 1] if nunits >= 3 else [None]):
            def setup(g: Any, n: int = nunits, off: int | None = disabled) -> None:
                for u in range(4):
                    g.glActiveTexture(C.GL_TEXTURE0 + u)
                    g.glDisable(C.GL_TEXTURE_2D)
                for u in range(n):
                    bind_unit(g, u, texs[u], fmts[u])
                    g.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, modes[u])
                    g.glTexEnvxv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, [int(c * 65536) for c in envc])
                    if u == off:
                        g.glDisable(C.GL_TEXTURE_2D)
                # the last unit reads one texel through its current coordinates
                g.glMultiTexCoord4x(C.GL_TEXTURE0 + n - 1, int(0.6875 * 65536), int(0.3125 * 65536), 0, 65536)

            # unit u maps the cell mirrored in s on odd units; the last unit has no array
            coords = tuple(((0.0, 0.0), (1.0, 1.0)) if u % 2 == 0 else ((1.0, 0.0), (0.0, 1.0))
                           for u in range(nunits - 1))
            q = Quad(0, 0, TEX, TEX, coords)
            img = draw_cells(target, [(q, color, setup)])
            cf = np.broadcast_to(unorm(color), (TEX, TEX, 4))
            cp = cf
            for u in range(nunits):
                if u == disabled:
                    continue
                cs = base_color(unorm(texs[u]), fmts[u])
                if u == nunits - 1:
                    cs = np.broadcast_to(cs[2, 5], cs.shape)       # t = 0.3125, s = 0.6875
                elif u % 2:
                    cs = cs[:, ::-1]
                cp = classic_env(modes[u], fmts[u], cp, cs, np.broadcast_to(envc, cs.shape))
            expect_close(region(img, q), cp, stage_tol(target.kind, nunits),
                         f"{nunits} units, unit {disabled} disabled")
