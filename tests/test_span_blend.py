"""Specialised blend spans against the generic one (csrc/span.c, span_fused.h).

SRC_ALPHA/ONE_MINUS_SRC_ALPHA and ONE/ONE (FUNC_ADD for colour and alpha)
have their own span functions, flat or smooth, without depth or with depth
LESS and writes, on RGBA8888 with every channel writable and no alpha test,
stencil, fog, logic op or texturing. ``ctx.debug(1)`` forces the generic
path; each scene is rendered both ways and the colour and depth buffers must
be bit-identical, and ``ctx.last_span_path()`` must name the path the state
calls for, so the comparison is never generic against generic.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import BUILDS, draw_arrays, make_ctx, random_triangles, set_frustum, set_ortho
from hypothesis import given, settings
from hypothesis import strategies as st

from gles import constants as C

W = H = 32

# state changes that leave a blend out of the specialised spans
BREAKERS = ("separate", "subtract", "logic_op", "color_mask", "alpha_test", "fog", "stencil", "rgb565",
            "rgba4444", "rgba5551", "other_func")

states = st.fixed_dictionaries({
    "numeric": st.sampled_from(BUILDS),
    "blend": st.sampled_from(["alpha", "add"]),
    "depth_bits": st.sampled_from([0, 16, 24]),
    "smooth": st.booleans(),
    "depth_test": st.booleans(),
    "depth_func": st.sampled_from(["LESS", "LESS", "LESS", "LEQUAL", "ALWAYS", "GREATER"]),
    "depth_mask": st.sampled_from([True, True, True, False]),
    "breaker": st.sampled_from((None,) * 11 + BREAKERS),
    "persp": st.booleans(),
    "seed": st.integers(0, 2**32 - 1),
})


def expected_path(s: dict) -> str:
    """The span function span_choose must pick for state `s`."""
    if s["breaker"] is not None:
        return "chain"
    name = "smooth" if s["smooth"] else "flat"
    if s["depth_test"] and s["depth_bits"]:
        if s["depth_func"] != "LESS" or not s["depth_mask"]:
            return "chain"
        name += "_zless"
    return f"{name}_{s['blend']}"


def render(s: dict, generic: bool):
    """Draw the scene of state `s`; return (colour buffer, depth buffer, path name)."""
    rng = np.random.default_rng(s["seed"])
    verts, cols = random_triangles(rng, s["persp"], 10, W)
    brk = s["breaker"]
    color = brk if brk in ("rgb565", "rgba4444", "rgba5551") else "rgba8888"
    ctx = make_ctx(s["numeric"], W, H, color=color, depth=s["depth_bits"])
    gl = ctx.gl
    if generic:
        ctx.debug(1)
    gl.glClearColor(*(float(v) for v in rng.uniform(0, 1, size=4)))
    gl.glClearDepthf(float(rng.uniform(0.2, 1.0)))
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    gl.glShadeModel(C.GL_SMOOTH if s["smooth"] else C.GL_FLAT)
    (gl.glEnable if s["depth_test"] else gl.glDisable)(C.GL_DEPTH_TEST)
    gl.glDepthFunc(getattr(C, "GL_" + s["depth_func"]))
    gl.glDepthMask(s["depth_mask"])
    gl.glEnable(C.GL_BLEND)
    if s["blend"] == "alpha":
        gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    else:
        gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    # each breaker changes nothing or little in the picture, but leaves the fast path
    if brk == "separate":
        gl.glBlendFuncSeparateOES(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA, C.GL_ONE,
                                  C.GL_ONE_MINUS_SRC_ALPHA)
    elif brk == "subtract":
        gl.glBlendEquationSeparateOES(C.GL_FUNC_ADD_OES, C.GL_FUNC_REVERSE_SUBTRACT_OES)
    elif brk == "logic_op":
        gl.glEnable(C.GL_COLOR_LOGIC_OP)
        gl.glLogicOp(C.GL_XOR)
    elif brk == "color_mask":
        gl.glColorMask(True, True, False, True)
    elif brk == "alpha_test":
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glAlphaFunc(C.GL_GEQUAL, 0.2)
    elif brk == "fog":
        gl.glEnable(C.GL_FOG)
        gl.glFogf(C.GL_FOG_MODE, C.GL_LINEAR)
        gl.glFogf(C.GL_FOG_START, 0.0)
        gl.glFogf(C.GL_FOG_END, 8.0)
    elif brk == "stencil":
        gl.glEnable(C.GL_STENCIL_TEST)
        gl.glStencilOp(C.GL_KEEP, C.GL_INCR, C.GL_INCR)
    elif brk == "other_func":
        gl.glBlendFunc(C.GL_ONE, C.GL_ONE_MINUS_SRC_ALPHA)
    (set_frustum(gl, W, H, 1.0, 3.0) if s["persp"] else set_ortho(gl, W, H))
    half = len(verts) // 6 * 3
    draw_arrays(gl, verts[:half], cols[:half])
    for i in range(half, len(verts), 3):
        draw_arrays(gl, verts[i:i + 3], cols[i:i + 3])
    assert gl.glGetError() == 0
    return ctx.color_buffer(), ctx.depth_buffer(), ctx.last_span_path()


def check_state(s: dict) -> None:
    col_g, dep_g, path_g = render(s, generic=True)
    col_s, dep_s, path_s = render(s, generic=False)
    assert path_g == "generic"
    assert path_s == expected_path(s), s
    np.testing.assert_array_equal(col_s, col_g, err_msg=str(s))
    if dep_g is not None:
        np.testing.assert_array_equal(dep_s, dep_g, err_msg=str(s))


@settings(max_examples=120, deadline=None)
@given(states)
def test_blend_spans_match_generic(s):
    """Random blend states: identical buffers with and without the forced generic path."""
    check_state(s)


PATHS = [f"{shade}{z}_{b}" for b in ("alpha", "add") for z in ("", "_zless") for shade in ("flat", "smooth")]


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("path", PATHS)
@pytest.mark.parametrize("persp", [False, True], ids=["ortho", "persp"])
def test_each_blend_path(numeric, path, persp):
    """Every specialised blend span, in every build, 16- and 24-bit depth, against the generic one."""
    for seed, depth_bits in ((1, 16), (2, 24), (3, 24)):
        s = {"numeric": numeric, "blend": path.rsplit("_", 1)[1], "depth_bits": depth_bits,
             "smooth": path.startswith("smooth"), "depth_test": "_zless" in path, "depth_func": "LESS",
             "depth_mask": True, "breaker": None, "persp": persp, "seed": seed}
        assert expected_path(s) == path
        check_state(s)


@pytest.mark.parametrize("breaker", BREAKERS)
def test_each_breaker_leaves_the_fast_path(breaker):
    """Each state outside a blend span's preconditions selects the generic path (and matches it)."""
    s = {"numeric": "fixed", "blend": "alpha", "depth_bits": 24, "smooth": True, "depth_test": True,
         "depth_func": "LESS", "depth_mask": True, "breaker": None, "persp": False, "seed": 4}
    assert render(s, False)[2] == "smooth_zless_alpha"
    check_state({**s, "breaker": breaker})


def test_blend_path_exact_on_a_full_ramp():
    """The flat alpha span over every (source alpha, destination) pair of one channel gives the
    rounded A s + (1 - A) d exactly, like the generic path, in every build."""
    n = 256
    for numeric in BUILDS:
        out = []
        for generic in (True, False):
            ctx = make_ctx(numeric, n, n)
            gl = ctx.gl
            if generic:
                ctx.debug(1)
            set_ortho(gl, n, n)
            gl.glShadeModel(C.GL_FLAT)
            x = np.arange(n, dtype=np.float32)
            lo, hi = 0 * x, 0 * x + n
            # destination: column x has value x in every channel
            corners = ((x, lo), (x + 1, lo), (x + 1, hi), (x, lo), (x + 1, hi), (x, hi))
            v = np.stack([np.stack(c, 1) for c in corners], axis=1).reshape(-1, 2)
            ramp = np.repeat(np.arange(n, dtype=np.uint8)[:, None], 4, axis=1)
            draw_arrays(gl, v, np.repeat(ramp, 6, axis=0))
            gl.glEnable(C.GL_BLEND)
            gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
            # source: row y has colour 200 and alpha y
            rows = v[:, ::-1].copy()
            col = np.repeat(np.stack([np.full(n, 200), np.full(n, 200), np.full(n, 200), np.arange(n)],
                                     axis=1).astype(np.uint8), 6, axis=0)
            draw_arrays(gl, rows, col)
            out.append(ctx.color_buffer()[..., 0].astype(np.int64))
            assert ctx.last_span_path() == ("generic" if generic else "flat_alpha")
        a = np.arange(n)[:, None]
        d = np.arange(n)[None, :]
        want = (2 * (200 * a + d * (255 - a)) + 255) // 510
        np.testing.assert_array_equal(out[0], out[1], err_msg=numeric)
        np.testing.assert_array_equal(out[1], want, err_msg=numeric)



A_COLOUR, B_COLOUR = (200, 17, 96, 77), (3, 250, 128, 160)


def _flat_table_scene(numeric: str, blend: str, zless: bool, generic: bool,
                      colours: tuple = (A_COLOUR, A_COLOUR, B_COLOUR, A_COLOUR)):
    """A destination holding every byte value in every channel (returned too), then full-window
    flat quads of the given colours blended over it. Each quad has 4096 fragments, so it goes
    through span_flat_table's table after the first 1024 of a colour; by default colours A, A, B,
    A: the second A reuses the table, B and the last A build it again. Under zless each quad is
    tilted in depth, so part of it fails the test."""
    n = 64
    ctx = make_ctx(numeric, n, n, depth=24 if zless else 0)
    gl = ctx.gl
    if generic:
        ctx.debug(1)
    set_ortho(gl, n, n, -1.0, 1.0)
    i = np.arange(n * n)
    dest = np.stack([(i * k + off) % 256 for k, off in ((1, 0), (7, 3), (13, 91), (101, 200))], axis=1)
    dest = np.ascontiguousarray(dest.reshape(n, n, 4), dtype=np.uint8)
    ids = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, int(np.ravel(ids)[0]))
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, n, n, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, dest)
    for p in (C.GL_TEXTURE_MIN_FILTER, C.GL_TEXTURE_MAG_FILTER):
        gl.glTexParameteri(C.GL_TEXTURE_2D, p, C.GL_NEAREST)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_REPLACE)
    gl.glClearDepthf(1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    quad = np.array([[0, 0, 0], [n, 0, 0], [n, n, 0], [0, 0, 0], [n, n, 0], [0, n, 0]], np.float32)
    if zless:
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDepthFunc(C.GL_LESS)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 0, np.ascontiguousarray(quad[:, :2] / n))
    draw_arrays(gl, quad + [0, 0, -0.9])     # window depth 0.95
    gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glShadeModel(C.GL_FLAT)
    gl.glEnable(C.GL_BLEND)
    if blend == "alpha":
        gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    else:
        gl.glBlendFunc(C.GL_ONE, C.GL_ONE)
    for k, col in enumerate(colours):
        v = quad.copy()
        if zless:
            # depth -z: the left edge in front of the previous quads, the right edge behind all
            v[:, 2] = np.where(v[:, 0] == 0, 0.7 + 0.1 * k, -0.95)
        draw_arrays(gl, v, np.array([col] * 6, np.uint8))
    assert gl.glGetError() == 0
    return ctx.color_buffer(), ctx.last_span_path(), dest


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("blend", ["alpha", "add"])
@pytest.mark.parametrize("zless", [False, True], ids=["plain", "zless"])
def test_flat_blend_table_matches_generic(numeric, blend, zless):
    """Large flat blends, through the per-byte table after their first fragments, equal the
    generic path bit for bit over a destination with every byte value in every channel."""
    got, path, dest = _flat_table_scene(numeric, blend, zless, generic=False)
    want, gpath, _ = _flat_table_scene(numeric, blend, zless, generic=True)
    assert path == ("flat_zless_" if zless else "flat_") + blend and gpath == "generic"
    np.testing.assert_array_equal(got, want)
    assert (got != dest).any()
    if zless:
        # the tilted quads' right parts failed the depth test
        assert (got[:, -1] == dest[:, -1]).all()


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("blend", ["alpha", "add"])
def test_flat_blend_table_formula(numeric, blend):
    """One large flat quad blended over every byte value: A s + (1 - A) d (or min(s + d, 1)) in
    real numbers, rounded to the byte, within the one step the conversion allows (§2.14.9)."""
    got, _, dest = _flat_table_scene(numeric, blend, False, generic=False, colours=(A_COLOUR,))
    d = dest.astype(np.float64)
    s = np.array(A_COLOUR, np.float64)
    want = np.minimum(d + s, 255) if blend == "add" else s * (s[3] / 255) + d * (1 - s[3] / 255)
    assert np.abs(got.astype(np.float64) - want).max() <= 1
