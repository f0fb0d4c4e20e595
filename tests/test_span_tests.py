"""The span chain's stencil and depth tests against the spec and the per-fragment path.

The chain (csrc/span_chain.c, span_stages.h) runs the stencil and depth
tests of a chunk of fragments at once: in the vector instance eight
fragments per step in 32-bit lanes, with the stencil ops as arithmetic; in
the baseline instance a scalar loop over table lookups. ``ctx.debug(1)``
forces the per-fragment reference (``fragment_tests``), ``ctx.debug(16)``
the baseline instance.

* A model test: every stored stencil value 0..255 meets a stored depth
  below, equal to and above the fragments' depth, under each stencil
  function, op in each of the three places (fail, depth fail, pass), write
  and value mask and reference (also outside 0..255, which clamps), and each
  depth function with and without depth writes, before and after an alpha
  test; and each function where failing keeps the stored value, the case in
  which the chain drops the failing ends of a chunk before any stage. The
  expected buffers come from the spec's formulas (§4.1.5, §4.1.6) in
  numpy; every path must produce them.
* A random test: random stored stencil and depth values (rich in 0, 255 and
  the reference and its neighbours), random triangles and points drawn
  twice (the second pass meets equal depths), random stencil, depth, alpha
  test and colour mask states; the chain's two instances and the reference
  must leave the colour, depth and stencil buffers identical.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import BUILDS, HAS_SIMD, SPAN_CHUNK, make_ctx, random_triangles, set_frustum, set_ortho
from hypothesis import given, settings
from hypothesis import strategies as st

from gles import constants as C

pytestmark = pytest.mark.filterwarnings("ignore::gles.RangeWarning")

FUNCS = (C.GL_NEVER, C.GL_LESS, C.GL_EQUAL, C.GL_LEQUAL, C.GL_GREATER, C.GL_NOTEQUAL, C.GL_GEQUAL,
         C.GL_ALWAYS)
OPS = (C.GL_KEEP, C.GL_ZERO, C.GL_REPLACE, C.GL_INCR, C.GL_DECR, C.GL_INVERT, C.GL_INCR_WRAP_OES,
       C.GL_DECR_WRAP_OES)

# the paths: (debug flags, name); the baseline instance only where a vector one exists
PATHS = ((1, "reference"), (0, "chain")) + (((16, "baseline chain"),) if HAS_SIMD else ())


def set_pixels(gl: Any, values: np.ndarray, bit: int, clear: Any) -> None:
    """Store values[y, x] in one buffer with scissored clears, a run of equal
    values in a row at a time (`clear` sets the clear value)."""
    gl.glEnable(C.GL_SCISSOR_TEST)
    h, w = values.shape
    for y in range(h):
        x = 0
        while x < w:
            end = x + 1
            while end < w and values[y, end] == values[y, x]:
                end += 1
            gl.glScissor(x, y, end - x, 1)
            clear(values[y, x])
            gl.glClear(bit)
            x = end
    gl.glDisable(C.GL_SCISSOR_TEST)


def compare(func: int, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a FUNC b (§4.1.4-4.1.6), elementwise."""
    return {
        C.GL_NEVER: lambda: np.zeros(np.broadcast(a, b).shape, bool),
        C.GL_LESS: lambda: a < b,
        C.GL_EQUAL: lambda: a == b,
        C.GL_LEQUAL: lambda: a <= b,
        C.GL_GREATER: lambda: a > b,
        C.GL_NOTEQUAL: lambda: a != b,
        C.GL_GEQUAL: lambda: a >= b,
        C.GL_ALWAYS: lambda: np.ones(np.broadcast(a, b).shape, bool),
    }[func]()


def stencil_op(op: int, s: np.ndarray, ref: int) -> np.ndarray:
    """The value an op computes from the stored s (§4.1.5), before the write mask."""
    s = s.astype(np.int64)
    return {
        C.GL_KEEP: s,
        C.GL_ZERO: np.zeros_like(s),
        C.GL_REPLACE: np.full_like(s, ref),
        C.GL_INCR: np.minimum(s + 1, 255),
        C.GL_DECR: np.maximum(s - 1, 0),
        C.GL_INVERT: ~s & 0xFF,
        C.GL_INCR_WRAP_OES: (s + 1) & 0xFF,
        C.GL_DECR_WRAP_OES: (s - 1) & 0xFF,
    }[op]


# {================================================================
# the model test: a constant-depth quad over every stored stencil value

# stencil (x mod 16) + 16 y: 0..255 in each third of the first 48 columns, the
# thirds at depths below, equal to and above the quad's; 50 columns: a row
# ends with a part of eight lanes
MW, MH = 50, 16
QUAD_RGBA = (255, 0, 128, 255)
CLEAR_RGBA = (0, 51, 102, 204)


def quad(gl: Any, z: float) -> None:
    """The whole window at object depth z, flat QUAD_RGBA (ortho, near -1, far 1)."""
    v = np.array([[0, 0, z], [MW, 0, z], [0, MH, z], [MW, MH, z]], dtype=np.float32)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
    gl.glColor4ub(*QUAD_RGBA)
    gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)


def model_case(numeric: str, flags: int, case: dict) -> dict:
    """Render `case` on the path `flags`: the stored buffers before and after the quad."""
    ctx = make_ctx(numeric, MW, MH, depth=24, stencil=8)
    gl = ctx.gl
    ctx.debug(flags)
    set_ortho(gl, MW, MH)
    gl.glClearColor(*[c / 255 for c in CLEAR_RGBA])
    gl.glClearDepthf(1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    # the depths: the quad itself at z = 0 in the middle third, nearer and farther quads beside it
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glDepthFunc(C.GL_ALWAYS)
    quad(gl, 0.0)
    zq = ctx.depth_buffer()
    gl.glEnable(C.GL_SCISSOR_TEST)
    for third, zobj in enumerate((0.5, 0.0, -0.5)):
        gl.glScissor(16 * third, 0, 16 if third < 2 else MW - 32, MH)
        quad(gl, zobj)
    gl.glDisable(C.GL_SCISSOR_TEST)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    x, y = np.meshgrid(np.arange(MW), np.arange(MH))
    stored = (x % 16 + 16 * y).astype(np.uint8)
    set_pixels(gl, stored, C.GL_STENCIL_BUFFER_BIT, gl.glClearStencil)
    before = {"stencil": ctx.stencil_buffer(), "depth": ctx.depth_buffer(), "color": ctx.color_buffer(),
              "z": zq}
    assert (before["stencil"] == stored).all()
    # the pass under test
    gl.glEnable(C.GL_STENCIL_TEST)
    gl.glStencilFunc(case["func"], case["ref"], case["value_mask"])
    gl.glStencilMask(case["write_mask"])
    gl.glStencilOp(*case["ops"])
    if case["depth_func"] is None:
        gl.glDisable(C.GL_DEPTH_TEST)
    else:
        gl.glDepthFunc(case["depth_func"])
    gl.glDepthMask(case["depth_mask"])
    if case["alpha"] is not None:
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glAlphaFunc(case["alpha"], 0.5)
    if not case.get("color_mask", True):
        gl.glColorMask(0, 0, 0, 0)
    quad(gl, 0.0)
    assert gl.glGetError() == C.GL_NO_ERROR
    return {"before": before, "stencil": ctx.stencil_buffer(), "depth": ctx.depth_buffer(),
            "color": ctx.color_buffer(), "span": ctx.last_span_path()}


def model_expect(case: dict, before: dict) -> dict:
    """The buffers §4.1.4-4.1.6 give after the quad, from the buffers before it."""
    s, d, z = (before[k].astype(np.int64) for k in ("stencil", "depth", "z"))
    # the quad's own depth at each pixel (drawn first over the whole window)
    assert (d[:, :16] < z[:, :16]).all() and (d[:, 16:32] == z[:, 16:32]).all()
    assert (d[:, 32:] > z[:, 32:]).all()
    if case["alpha"] == C.GL_NEVER:
        return {k: before[k] for k in ("stencil", "depth", "color")}
    ref = min(max(case["ref"], 0), 255)
    vm, wm = case["value_mask"] & 0xFF, case["write_mask"] & 0xFF
    spass = compare(case["func"], ref & vm, s & vm)
    zpass = np.ones_like(spass) if case["depth_func"] is None else compare(case["depth_func"], z, d)
    fail, zfail, zp = (stencil_op(op, s, ref) for op in case["ops"])
    v = np.where(~spass, fail, np.where(~zpass, zfail, zp))
    stencil = (s & ~wm) | (v & wm)
    passed = spass & zpass
    depth = np.where(passed & bool(case["depth_mask"]) & (case["depth_func"] is not None), z, d)
    color = np.where(passed[..., None], np.array(QUAD_RGBA, np.uint8), before["color"])
    if not case.get("color_mask", True):
        color = before["color"]
    return {"stencil": stencil.astype(np.uint8), "depth": depth.astype(np.uint32), "color": color}


def model_cases() -> list[dict]:
    """Each stencil function with each depth function; each op in each place
    under several write masks; value masks and references at the edges; the
    tests after an alpha test that passes everything or nothing."""
    rng = np.random.default_rng(13)
    base = {"func": C.GL_LEQUAL, "ref": 128, "value_mask": 0xFF, "write_mask": 0xFF,
            "ops": (C.GL_KEEP, C.GL_KEEP, C.GL_KEEP), "depth_func": C.GL_LESS, "depth_mask": True,
            "alpha": None}
    cases = []
    for func in FUNCS:
        for depth_func in FUNCS + (None,):
            ops = tuple(OPS[i] for i in rng.integers(0, len(OPS), size=3))
            cases.append({**base, "func": func, "depth_func": depth_func, "ops": ops,
                          "ref": int(rng.integers(0, 256)), "depth_mask": bool(rng.integers(0, 2))})
    for place in range(3):
        for op in OPS:
            for write_mask in (0xFF, 0x00, 0x0F, 0xA5):
                ops = [C.GL_KEEP] * 3
                ops[place] = op
                # LEQUAL 128 fails half the values; depth LEQUAL fails the farther third
                cases.append({**base, "ops": tuple(ops), "write_mask": write_mask, "depth_func": C.GL_LEQUAL,
                              "ref": int(rng.choice([0, 1, 128, 254, 255]))})
    for ref in (-7, 0, 255, 300):
        for value_mask in (0xFF, 0x80, 0x01, 0x3C, 0x00, 0x1FF):
            cases.append({**base, "func": FUNCS[int(rng.integers(0, 8))], "ref": ref,
                          "value_mask": value_mask, "write_mask": 0x1FF if value_mask == 0x1FF else 0xFF,
                          "ops": (C.GL_INVERT, C.GL_DECR, C.GL_REPLACE)})
    # a failing fragment that keeps the stored value (fail KEEP, or nothing
    # writable): the chain drops each chunk's failing ends before any stage
    # (run's stencil cull), sixteen values at a time where it can
    for func in FUNCS:
        for value_mask, ref in ((0xFF, 37), (0x3C, 200), (0x00, 5), (0xF0, 300), (0xFF, 0), (0xFF, 255)):
            cases.append({**base, "func": func, "ref": ref, "value_mask": value_mask,
                          "ops": (C.GL_KEEP, C.GL_INCR, C.GL_INVERT)})
        cases.append({**base, "func": func, "ref": 100, "write_mask": 0x00,
                      "ops": (C.GL_INVERT, C.GL_KEEP, C.GL_KEEP)})
    # a stencil-only pass (every colour channel masked, no depth or alpha
    # test): the span is a table lookup per stored value (span_stencil_only)
    for func in FUNCS:
        ops = tuple(OPS[i] for i in rng.integers(0, len(OPS), size=3))
        cases.append({**base, "func": func, "depth_func": None, "ops": ops, "color_mask": False,
                      "ref": int(rng.choice([0, 77, 255, 300])), "value_mask": int(rng.choice([0xFF, 0x3C])),
                      "write_mask": int(rng.choice([0xFF, 0x0F, 0x00]))})
    for alpha in (C.GL_ALWAYS, C.GL_NEVER):
        cases.append({**base, "alpha": alpha, "func": C.GL_NOTEQUAL, "ops": (C.GL_INCR, C.GL_DECR_WRAP_OES,
                                                                             C.GL_INCR_WRAP_OES)})
        cases.append({**base, "alpha": alpha, "depth_func": C.GL_EQUAL, "ops": (C.GL_ZERO, C.GL_REPLACE,
                                                                                 C.GL_INVERT)})
    return cases


MODEL_CASES = model_cases()


@pytest.mark.parametrize("numeric", BUILDS)
def test_tests_match_the_spec(numeric):
    """Every path gives the spec's stencil, depth and colour for every stored
    value, function, op, mask and reference of MODEL_CASES."""
    for i, case in enumerate(MODEL_CASES):
        for flags, name in PATHS:
            out = model_case(numeric, flags, case)
            want = model_expect(case, out["before"])
            if not case.get("color_mask", True):
                assert out["span"] == ("generic" if flags & 1 else "stencil_only"), name
            for buf in ("stencil", "depth", "color"):
                np.testing.assert_array_equal(out[buf], want[buf], err_msg=f"case {i} {case}, {name}, {buf}")


# {================================================================
# the random test: the chain's instances against the reference


def edge_value(ref: int) -> st.SearchStrategy[int]:
    """A stored stencil value, often at the edges of the ops and the test."""
    near = sorted({min(max(v, 0), 255) for v in (ref - 1, ref, ref + 1)})
    return st.one_of(st.sampled_from([0, 1, 254, 255] + near), st.integers(0, 255))


STENCIL = st.fixed_dictionaries({
    "on": st.sampled_from((True, True, True, False)),
    "func": st.sampled_from(FUNCS),
    "ref": st.one_of(st.integers(0, 255), st.sampled_from((0, 1, 254, 255, -3, 256, 1000))),
    "value_mask": st.one_of(st.sampled_from((0xFF, 0x0F, 0xF0, 0x01, 0x00, 0xFFFFFFFF)), st.integers(0, 255)),
    "write_mask": st.one_of(st.sampled_from((0xFF, 0x0F, 0xF0, 0x01, 0x00, 0xFFFFFFFF)), st.integers(0, 255)),
    "ops": st.tuples(*[st.sampled_from(OPS)] * 3),
})

PASS = st.fixed_dictionaries({
    "stencil": STENCIL,
    "depth": st.sampled_from((True, True, False)),
    "depth_func": st.sampled_from(FUNCS),
    "depth_mask": st.booleans(),
    "alpha": st.sampled_from((None, None, C.GL_GREATER, C.GL_LESS, C.GL_ALWAYS, C.GL_NEVER)),
    "alpha_ref": st.floats(0.0, 1.0),
    "color_mask": st.sampled_from(((True,) * 4, (False,) * 4, (True, False, True, False))),
})


@st.composite
def scenes(draw: Any) -> dict:
    wide = draw(st.booleans())
    w = draw(st.integers(SPAN_CHUNK + 1, 2 * SPAN_CHUNK + 22)) if wide else draw(st.integers(5, 40))
    h = draw(st.integers(2, 6)) if wide else draw(st.integers(4, 20))
    passes = draw(st.lists(PASS, min_size=1, max_size=3))
    ref = passes[0]["stencil"]["ref"]
    # stored values in runs along the rows
    n_runs = draw(st.integers(1, 24))
    runs = draw(st.lists(st.tuples(edge_value(ref), st.integers(1, 12)), min_size=n_runs, max_size=n_runs))
    depths = draw(st.lists(st.tuples(st.sampled_from((0.0, 1.0, 0.25, 0.5, 0.75)) | st.floats(0, 1),
                                     st.integers(1, 16)), min_size=1, max_size=12))
    return {
        "numeric": draw(st.sampled_from(BUILDS)),
        "size": (w, h),
        "depth_bits": draw(st.sampled_from((16, 24))),
        "persp": draw(st.booleans()),
        "geometry": draw(st.integers(0, 2**32 - 1)),
        "triangles": draw(st.integers(1, 6)),
        "full": draw(st.booleans()),
        "points": draw(st.sampled_from((0, 0, 1, 3))),
        "smooth": draw(st.booleans()),
        "stencil_runs": runs,
        "depth_runs": depths,
        "passes": passes,
    }


def fill(runs: list, w: int, h: int) -> np.ndarray:
    """An (h, w) array of the runs' values, repeated in row order."""
    out = []
    while len(out) < w * h:
        for v, n in runs:
            out += [v] * n
    return np.array(out[:w * h]).reshape(h, w)


def render(scene: dict, flags: int) -> dict:
    """Draw `scene` on the path `flags`; the buffers."""
    w, h = scene["size"]
    ctx = make_ctx(scene["numeric"], w, h, depth=scene["depth_bits"], stencil=8)
    gl = ctx.gl
    ctx.debug(flags)
    gl.glClearColor(0.2, 0.4, 0.6, 0.8)
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
    stored = fill(scene["stencil_runs"], w, h).astype(np.uint8)
    set_pixels(gl, stored, C.GL_STENCIL_BUFFER_BIT, gl.glClearStencil)
    set_pixels(gl, fill(scene["depth_runs"], w, h), C.GL_DEPTH_BUFFER_BIT, gl.glClearDepthf)
    rng = np.random.default_rng(scene["geometry"])
    verts, cols = random_triangles(rng, scene["persp"], scene["triangles"], w)
    if scene["persp"]:
        set_frustum(gl, w, h, 1.0, 3.0)
    else:
        set_ortho(gl, w, h)
        verts[:, 1] = (verts[:, 1] + 6) * ((h + 12) / (w + 12)) - 6
    if scene["full"]:
        # a quad over the whole window: rows longer than a chunk, every slot live
        z = verts[0, 2]
        if scene["persp"]:
            full = np.array([[-1, -1, -1.5], [1, -1, -1.5], [-1, 1, -1.5], [1, -1, -1.5], [1, 1, -1.5],
                             [-1, 1, -1.5]]) * [2, 2, 1]
        else:
            full = np.array([[-1, -1, z], [w + 1, -1, z], [-1, h + 1, z], [w + 1, -1, z], [w + 1, h + 1, z],
                             [-1, h + 1, z]])
        verts = np.vstack([full, verts])
        cols = np.vstack([rng.integers(0, 256, size=(6, 4)), cols]).astype(np.uint8)
    gl.glShadeModel(C.GL_SMOOTH if scene["smooth"] else C.GL_FLAT)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, np.ascontiguousarray(verts, dtype=np.float32))
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, np.ascontiguousarray(cols, dtype=np.uint8))
    for p in scene["passes"]:
        s = p["stencil"]
        (gl.glEnable if s["on"] else gl.glDisable)(C.GL_STENCIL_TEST)
        gl.glStencilFunc(s["func"], s["ref"], s["value_mask"])
        gl.glStencilMask(s["write_mask"])
        gl.glStencilOp(*s["ops"])
        (gl.glEnable if p["depth"] else gl.glDisable)(C.GL_DEPTH_TEST)
        gl.glDepthFunc(p["depth_func"])
        gl.glDepthMask(p["depth_mask"])
        (gl.glEnable if p["alpha"] is not None else gl.glDisable)(C.GL_ALPHA_TEST)
        if p["alpha"] is not None:
            gl.glAlphaFunc(p["alpha"], p["alpha_ref"])
        gl.glColorMask(*p["color_mask"])
        # the same geometry every pass: the later passes meet equal depths
        gl.glDrawArrays(C.GL_TRIANGLES, 0, len(verts))
        if scene["points"]:
            gl.glPointSize(scene["points"])
            gl.glDrawArrays(C.GL_POINTS, 0, len(verts))
    assert gl.glGetError() == C.GL_NO_ERROR
    return {"color": ctx.color_buffer(), "depth": ctx.depth_buffer(), "stencil": ctx.stencil_buffer()}


@settings(max_examples=150, deadline=None)
@given(scenes())
def test_random_tests_match_reference(scene):
    """The chain's instances leave the buffers the reference leaves, for random
    stored values, stencil and depth states, alpha tests and colour masks."""
    ref = render(scene, 1)
    for flags, name in PATHS[1:]:
        out = render(scene, flags)
        for buf in ("color", "depth", "stencil"):
            np.testing.assert_array_equal(out[buf], ref[buf], err_msg=f"{name}, {buf}")
