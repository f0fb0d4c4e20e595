"""Specialised span functions against the generic one (csrc/span.c).

``span_generic`` handles every fragment state and is the reference; the
specialised instances (flat or smooth colour, without depth or with depth
LESS and writes, on RGBA8888 with every colour channel writable) and the
composed chain of stages (every other state) must produce bit-identical
colour and depth buffers. ``ctx.debug(1)`` forces the
generic path, so each scene is rendered both ways and compared. The test
also checks that the state did pick the specialised path it should, so the
comparison is not between two runs of the generic code.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, draw_arrays, make_ctx, random_triangles, set_frustum, set_ortho
from hypothesis import given, settings
from hypothesis import strategies as st

from gles import constants as C

W = H = 32

DEPTH_FUNCS = ("NEVER", "LESS", "EQUAL", "LEQUAL", "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS")

states = st.fixed_dictionaries({
    "numeric": st.sampled_from(BUILDS),
    "color": st.sampled_from(["rgba8888", "rgb565", "rgba4444", "rgba5551"]),
    "depth_bits": st.sampled_from([0, 16, 24]),
    "smooth": st.booleans(),
    "depth_test": st.booleans(),
    "depth_func": st.sampled_from(DEPTH_FUNCS),
    "depth_mask": st.booleans(),
    "color_mask": st.one_of(st.just((True, True, True, True)),
                            st.tuples(st.booleans(), st.booleans(), st.booleans(), st.booleans())),
    "persp": st.booleans(),
    "seed": st.integers(0, 2**32 - 1),
})


def expected_path(s: dict) -> str:
    """The span function span_choose must pick for state `s` (see csrc/span.c)."""
    depth = s["depth_test"] and s["depth_bits"] > 0
    simple = s["color"] == "rgba8888" and all(s["color_mask"])
    shade = "smooth" if s["smooth"] else "flat"
    if simple and not depth:
        return shade
    if simple and s["depth_func"] == "LESS" and s["depth_mask"]:
        return shade + "_zless"
    return "chain"


def render(s: dict, generic: bool, flags: int = 0, size: int = W):
    """Draw the scene of state `s` in a `size` x `size` window (with debug
    `flags`); return (colour buffer, depth buffer, path name)."""
    rng = np.random.default_rng(s["seed"])
    verts, cols = random_triangles(rng, s["persp"], 8, size)
    clear_rgba = tuple(float(v) for v in rng.uniform(0, 1, size=4))
    clear_depth = float(rng.uniform(0.2, 1.0))
    ctx = make_ctx(s["numeric"], size, size, color=s["color"], depth=s["depth_bits"])
    gl = ctx.gl
    ctx.debug(flags | (1 if generic else 0))
    gl.glClearColor(*clear_rgba)
    gl.glClearDepthf(clear_depth)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    gl.glShadeModel(C.GL_SMOOTH if s["smooth"] else C.GL_FLAT)
    (gl.glEnable if s["depth_test"] else gl.glDisable)(C.GL_DEPTH_TEST)
    gl.glDepthFunc(getattr(C, "GL_" + s["depth_func"]))
    gl.glDepthMask(s["depth_mask"])
    gl.glColorMask(*s["color_mask"])
    (set_frustum(gl, size, size, 1.0, 3.0) if s["persp"] else set_ortho(gl, size, size))
    # half the triangles in one call, the rest one by one
    half = len(verts) // 6 * 3
    draw_arrays(gl, verts[:half], cols[:half])
    for i in range(half, len(verts), 3):
        draw_arrays(gl, verts[i:i + 3], cols[i:i + 3])
    return ctx.color_buffer(), ctx.depth_buffer(), ctx.last_span_path()


def check_state(s: dict, size: int = W) -> None:
    """The specialised path (the vector instance, and the baseline one where
    a vector instance runs) against the generic one, for state `s`."""
    col_g, dep_g, path_g = render(s, generic=True, size=size)
    assert path_g == "generic"
    for flags in (0, 16) if HAS_SIMD else (0,):
        col_s, dep_s, path_s = render(s, generic=False, flags=flags, size=size)
        assert path_s == expected_path(s)
        np.testing.assert_array_equal(col_s, col_g)
        if dep_g is not None:
            np.testing.assert_array_equal(dep_s, dep_g)


@settings(max_examples=150, deadline=None)
@given(states)
def test_specialised_spans_match_generic(s):
    """Random fragment states: identical colour and depth buffers with and
    without the forced generic path, and the expected path chosen."""
    check_state(s)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("path", ["flat", "smooth", "flat_zless", "smooth_zless"])
@pytest.mark.parametrize("depth_bits", [16, 24])
@pytest.mark.parametrize("persp", [False, True], ids=["ortho", "persp"])
def test_each_specialised_path(numeric, path, depth_bits, persp):
    """Every specialised path, in every build, against the generic one."""
    for seed in range(3):
        s = {
            "numeric": numeric, "color": "rgba8888", "depth_bits": depth_bits,
            "smooth": path.startswith("smooth"), "depth_test": path.endswith("zless"),
            "depth_func": "LESS", "depth_mask": True, "color_mask": (True, True, True, True),
            "persp": persp, "seed": seed,
        }
        assert expected_path(s) == path
        check_state(s)


def test_paths_change_with_state():
    """Turning one condition off leaves the specialised path (the names are live)."""
    base = {"numeric": "fixed", "color": "rgba8888", "depth_bits": 16, "smooth": True,
            "depth_test": True, "depth_func": "LESS", "depth_mask": True,
            "color_mask": (True, True, True, True), "persp": False, "seed": 1}
    assert render(base, False)[2] == "smooth_zless"
    for change in ({"depth_func": "LEQUAL"}, {"depth_mask": False}, {"color_mask": (True, False, True, True)},
                   {"color": "rgb565"}, {"color": "rgba4444"}, {"color": "rgba5551"}):
        s = {**base, **change}
        assert render(s, False)[2] == "chain", change
        check_state(s)


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("path", ["smooth", "smooth_zless"])
@pytest.mark.parametrize("persp", [False, True], ids=["ortho", "persp"])
def test_large_triangles(numeric, path, persp):
    """Triangles of up to about 100000 pixels (the fixed build's
    smooth spans step their weights only below about 16000, where the edge
    values need no shift) and small ones in one scene, against the generic path."""
    for seed in range(2):
        s = {
            "numeric": numeric, "color": "rgba8888", "depth_bits": 24, "smooth": True,
            "depth_test": path.endswith("zless"), "depth_func": "LESS", "depth_mask": True,
            "color_mask": (True, True, True, True), "persp": persp, "seed": 100 + seed,
        }
        check_state(s, size=512)
