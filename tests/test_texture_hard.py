"""Texturing at the edges of the number ranges.

* A dual-paraboloid environment lookup through the texture matrix, where q
  reaches 0 at the back pole (and, with stretched reflection vectors, changes
  sign inside triangles): no crash, and no wrapped garbage. With NEAREST every
  pixel must be one of the texture's colours; with LINEAR and mipmaps, a
  texture of red and blue texels only must give pixels with G = 0, A = 1 and
  R + B = 1 (any blend of texels keeps that, up to rounding per level).
* High repeat counts and s near +-1024 on 2048-texel textures.
* The fixed and float builds against double on the same scenes: the measured
  differences are printed (``pytest -s``) and bounded.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest
from test_texture import (
    CLAMP,
    LINEAR,
    MESA_REASON,
    MIRROR,
    NEAREST,
    REPEAT,
    TARGETS,
    Quad,
    Target,
    env,
    make_texture,
    open_target,
    ortho,
    render_quads,
)

from gles import constants as C


@pytest.fixture(params=TARGETS)
def target(request: pytest.FixtureRequest) -> Iterator[Target]:
    """Each gles build, then Mesa llvmpipe (skipped where it cannot run)."""
    yield from open_target(request)


W = H = 64
PALETTE = np.array([(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 0, 255),
                    (0, 255, 255, 255), (255, 0, 255, 255), (255, 255, 255, 255), (40, 90, 160, 255)],
                   dtype=np.uint8)
WRAPS = {"repeat": REPEAT, "clamp": CLAMP, "mirror": MIRROR}

# the front paraboloid: s = rx / (2 (1 + rz)) + 1/2 = (rx + rz + 1) / (2 rz + 2), t alike
PARABOLOID = np.array([[1, 0, 1, 1],
                       [0, 1, 1, 1],
                       [0, 0, 1, 0],
                       [0, 0, 2, 2]], dtype=np.float64)


def palette_texture(seed: int, size: int = 32) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return PALETTE[rng.integers(len(PALETTE), size=(size, size))]


def red_blue_texture(seed: int, size: int = 32) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.where(rng.integers(2, size=(size, size, 1)) == 1, np.array([255, 0, 0, 255], np.uint8),
                    np.array([0, 0, 255, 255], np.uint8)).astype(np.uint8)


def sphere_grid(n: int = 17, stretch: float = 1.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A grid over the window (vertices on 4-pixel steps) whose texture coordinates are
    reflection directions from the front pole (top row) to the back pole (bottom row,
    rz = -1, q = 0); `stretch` scales rz, so q < 0 near the bottom when it exceeds 1.
    Returns float32 vertices (n*n, 2), texcoords (n*n, 3) and uint16 triangle indices."""
    xs = np.linspace(0, W, n)
    x, y = np.meshgrid(xs, xs)
    theta = np.linspace(np.pi, 0, n)[:, None] * np.ones((1, n))     # row 0 (bottom) at the back pole
    phi = np.linspace(0, 2 * np.pi, n)[None, :] * np.ones((n, 1))
    d = np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), stretch * np.cos(theta)], -1)
    d[0, :, :2] = 0.0                  # exactly the pole: rx = ry = 0, rz = -stretch
    verts = np.stack([x, y], -1).reshape(-1, 2).astype(np.float32)
    tc = d.reshape(-1, 3).astype(np.float32)
    i = np.arange(n - 1)
    a = (i[:, None] * n + i[None, :]).reshape(-1)
    idx = np.stack([a, a + 1, a + n, a + 1, a + n + 1, a + n], -1).reshape(-1).astype(np.uint16)
    return verts, tc, idx


def draw_paraboloid(gl: Any, tex_u8: np.ndarray, wrap: int, minf: int, magf: int, stretch: float) -> None:
    """The sphere grid through the paraboloid texture matrix, REPLACE."""
    ortho(gl, W, H)
    gl.glClearColorx(0, 0, 0, 0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    make_texture(gl, tex_u8, min_filter=minf, mag_filter=magf, wrap=(wrap, wrap), generate_mipmap=True)
    gl.glEnable(C.GL_TEXTURE_2D)
    env(gl, C.GL_REPLACE)
    gl.glMatrixMode(C.GL_TEXTURE)
    gl.glLoadMatrixx([int(v * 65536) for v in PARABOLOID.T.reshape(-1)])
    gl.glMatrixMode(C.GL_MODELVIEW)
    verts, tc, idx = sphere_grid(stretch=stretch)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(3, C.GL_FLOAT, 0, tc)
    gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
    gl.glMatrixMode(C.GL_TEXTURE)
    gl.glLoadIdentity()
    gl.glMatrixMode(C.GL_MODELVIEW)
    assert gl.glGetError() == 0


def not_in_palette(img_u8: np.ndarray, colors: np.ndarray) -> np.ndarray:
    """Pixels (h, w) whose colour is none of `colors` exactly."""
    return ~(img_u8[:, :, None, :] == colors[None, None]).all(-1).any(-1)


def red_blue_garbage(img_u8: np.ndarray, levels: int) -> np.ndarray:
    """Pixels that no blend of red and blue texels gives: G = 0, A = 255 and R + B = 255,
    allowing one unit of rounding per mipmap level and per filtering stage."""
    slack = levels + 2
    rb = img_u8[..., 0].astype(int) + img_u8[..., 2].astype(int)
    return (img_u8[..., 1] > slack) | (img_u8[..., 3] < 255 - slack) | (np.abs(rb - 255) > 2 * slack)


def first_bad(img: np.ndarray, bad: np.ndarray) -> str:
    y, x = np.argwhere(bad)[0]
    return f"{img[y, x].tolist()} at (x={x}, y={y})"


@pytest.mark.parametrize("stretch", [1.0, 1.25], ids=["q-to-0", "q-crosses-0"])
@pytest.mark.parametrize("wrap", list(WRAPS))
def test_paraboloid_nearest_gives_texture_colours(target: Target, wrap: str, stretch: float):
    """NEAREST, q down to 0 (and below): every pixel is one of the texture's colours."""
    gl = target.gl
    draw_paraboloid(gl, palette_texture(1), WRAPS[wrap], NEAREST, NEAREST, stretch)
    img = gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    bad = not_in_palette(img, PALETTE)
    assert not bad.any(), f"{int(bad.sum())} pixels are not texture colours, e.g. {first_bad(img, bad)}"


@pytest.mark.parametrize("minf", [LINEAR, C.GL_LINEAR_MIPMAP_LINEAR, C.GL_NEAREST_MIPMAP_LINEAR],
                         ids=["LINEAR", "LINEAR_MIPMAP_LINEAR", "NEAREST_MIPMAP_LINEAR"])
@pytest.mark.parametrize("stretch", [1.0, 1.25], ids=["q-to-0", "q-crosses-0"])
@pytest.mark.parametrize("wrap", list(WRAPS))
def test_paraboloid_filtered_gives_texel_blends(target: Target, wrap: str, stretch: float, minf: int):
    """LINEAR and mipmapped filters (lambda from coordinates that blow up near q = 0):
    every pixel is a blend of red and blue texels."""
    gl = target.gl
    draw_paraboloid(gl, red_blue_texture(2), WRAPS[wrap], minf, LINEAR, stretch)
    img = gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    bad = red_blue_garbage(img, 6)
    assert not bad.any(), f"{int(bad.sum())} pixels are no blend of red and blue, e.g. {first_bad(img, bad)}"


def test_paraboloid_vs_llvmpipe():
    """Away from the back pole (q > 1/2) the gles builds and llvmpipe draw the same
    environment map: at most 1% of pixels differ by more than 3 steps (texel and
    rounding ties in LINEAR filtering)."""
    if MESA_REASON is not None:
        pytest.skip(f"Mesa llvmpipe unavailable: {MESA_REASON}")
    images = {}
    for kind in TARGETS:
        t = Target(kind)
        draw_paraboloid(t.gl, palette_texture(3), CLAMP, LINEAR, LINEAR, 1.0)
        images[kind] = t.gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE).astype(int)
        t.close()
    # q = 2 + 2 cos(theta); theta runs from pi (row 0) to 0 (row 64): q > 1/2 above row ~21
    rows = slice(24, H)
    for kind in TARGETS[:3]:
        diff = np.abs(images[kind][rows] - images["llvmpipe"][rows]).max(-1)
        frac = float((diff > 3).mean())
        MEASURED[f"paraboloid {kind} vs llvmpipe, share of pixels > 3 steps (q > 1/2)"] = f"{frac:.4f}"
        assert frac <= 0.01


# {================================================================
# builds against double

MEASURED: dict[str, str] = {}


def scene_image(kind: str, scene: str) -> np.ndarray:
    """One of the comparison scenes on a build, as int RGBA (h, w, 4)."""
    t = Target(kind)
    gl = t.gl
    rng = np.random.default_rng(17)
    if scene == "bilinear-rotated":
        make_texture(gl, rng.integers(0, 256, (16, 16, 4), dtype=np.uint8), min_filter=LINEAR,
                     mag_filter=LINEAR)
        gl.glEnable(C.GL_TEXTURE_2D)
        env(gl, C.GL_MODULATE)
        gl.glMatrixMode(C.GL_TEXTURE)
        gl.glRotatex(int(23.5 * 65536), 0, 0, 65536)
        gl.glMatrixMode(C.GL_MODELVIEW)
        render_quads(t, [Quad(0, 0, W, H, (((-0.3, 0.1), (1.7, 1.45)),))], color=(230, 200, 170, 255))
    elif scene in ("s=1024-linear", "s=1024-nearest"):
        filt = LINEAR if scene.endswith("linear") else NEAREST
        img_u8 = index_texture() if filt == NEAREST else rng.integers(0, 256, (2, 2048, 4), dtype=np.uint8)
        make_texture(gl, img_u8, min_filter=filt, mag_filter=filt)
        gl.glEnable(C.GL_TEXTURE_2D)
        env(gl, C.GL_REPLACE)
        # 26 texels over 64 pixels; s on the float32 grid near 1024 (2^-13), so every
        # build gets the same vertex values, and pixel centres 1/64 texel or more from edges
        k = 104 * 2.0**-13
        render_quads(t, [Quad(0, 0, W, 32, (((1024 - k, 0.25), (1024.0, 0.75)),)),
                         Quad(0, 32, W, H, (((-1024.0, 0.25), (-1024 + k, 0.75)),))])
    elif scene == "repeats-trilinear":
        make_texture(gl, rng.integers(0, 256, (64, 64, 4), dtype=np.uint8),
                     min_filter=C.GL_LINEAR_MIPMAP_LINEAR, mag_filter=LINEAR, generate_mipmap=True)
        gl.glEnable(C.GL_TEXTURE_2D)
        env(gl, C.GL_REPLACE)
        ortho(gl, W, H)
        gl.glViewport(0, 0, W, H)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glFrustumx(-65536, 65536, -65536, 65536, 65536, 200 * 65536)
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glLoadIdentity()
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        v = np.array([-1, -1, -1, 1, -1, -1, -100, -1, -100, 100, -1, -100], dtype=np.float32)
        tc = np.array([0, 0, 2, 0, -200, 200, 200, 200], dtype=np.float32)    # 200 repeats at the far edge
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)
    elif scene == "paraboloid":
        draw_paraboloid(gl, palette_texture(3), CLAMP, LINEAR, LINEAR, 1.0)
    assert gl.glGetError() == 0
    img = gl.glReadPixels(0, 0, W, H, C.GL_RGBA, C.GL_UNSIGNED_BYTE).astype(int)
    t.close()
    return img


def index_texture() -> np.ndarray:
    """A 2048x2 texture whose texel i is (i mod 256, i // 256, 0, 255): colours name texels."""
    i = np.arange(2048)
    row = np.stack([i % 256, i // 256, np.zeros_like(i), np.full_like(i, 255)], -1).astype(np.uint8)
    return np.ascontiguousarray(np.stack([row, row]))


def texel_index(img: np.ndarray) -> np.ndarray:
    return img[..., 0] + 256 * img[..., 1]


# scene -> (rows compared, max steps allowed for fixed, for float). Float at s = 1024
# may put u a quarter texel off (2^-13 of s), a quarter of a neighbouring texel difference.
SCENES = {
    "bilinear-rotated": (slice(0, H), 1, 1),
    "s=1024-linear": (slice(0, H), 1, 64),
    "s=1024-nearest": (slice(0, H), 0, 1),       # texel i is (i mod 256, i // 256, 0): a neighbour is 1 off
    "repeats-trilinear": (slice(0, 31), 2, 2),
    "paraboloid": (slice(24, H), 2, 2),
}


@pytest.mark.parametrize("scene", list(SCENES))
def test_builds_against_double(scene: str):
    """fixed and float against the double build on the same scene: the largest
    per-channel difference (8-bit steps) and the share of differing pixels are
    recorded; the bound is one rounding step, two where lambda or q feeds the
    result; float at s = 1024 keeps s to 2^-13, a quarter texel of a 2048-texel
    image, so its bilinear result may move by a quarter of a texel difference."""
    rows, fixed_bound, float_bound = SCENES[scene]
    ref = scene_image("double", scene)[rows]
    for kind, bound in (("fixed", fixed_bound), ("float", float_bound)):
        img = scene_image(kind, scene)[rows]
        diff = np.abs(img - ref).max(-1)
        MEASURED[f"{scene} {kind} vs double"] = (
            f"max {int(diff.max())} steps, {float((diff > 0).mean()):.4f} of pixels differ, "
            f"{float((diff > 1).mean()):.4f} by more than 1")
        assert diff.max() <= bound, f"{scene}: {kind} differs from double by {diff.max()} steps"


def test_texel_index_error_at_1024():
    """NEAREST at s near +-1024 on 2048 texels, each texel's colour naming its index:
    the fixed build picks exactly double's texels; float's index is off by at most
    2 (s interpolated in float32 from +-1024 keeps 2^-13 of s, a quarter texel, and
    the interpolation's few roundings add up to a couple of those)."""
    ref = texel_index(scene_image("double", "s=1024-nearest"))
    for kind, most in (("fixed", 0), ("float", 2)):
        idx = texel_index(scene_image(kind, "s=1024-nearest"))
        d = np.abs((idx - ref + 1024) % 2048 - 1024)
        MEASURED[f"s=1024 NEAREST {kind} vs double, texel index"] = (
            f"max {int(d.max())} texels off, {float((d > 0).mean()):.4f} of pixels on another texel")
        assert d.max() <= most


def test_zz_print_measured():
    """Print what the comparisons measured (run with -s)."""
    for k, v in sorted(MEASURED.items()):
        print(f"{k}: {v}")
