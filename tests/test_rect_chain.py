"""DrawTex rectangles and points through the span chain against the per-fragment path.

glDrawTex*OES and aliased points and point sprites run their rows through
the same chain of stages as triangles (csrc/span_chain.c), with their own
source of colour, depth, fog and texture coordinates. ``ctx.debug(1)``
sends every fragment through the reference, ``fragment_process``. For
random fragment states, textures, rectangles and points the colour, depth
and stencil buffers must be identical both ways.
"""

from __future__ import annotations

import numpy as np
from conftest import BUILDS, HAS_SIMD, make_ctx
from hypothesis import given, settings
from hypothesis import strategies as st

from gles import constants as C

W, H = 40, 32

FILTERS = ("NEAREST", "LINEAR", "NEAREST_MIPMAP_NEAREST", "LINEAR_MIPMAP_NEAREST",
           "NEAREST_MIPMAP_LINEAR", "LINEAR_MIPMAP_LINEAR")
FORMATS = ("RGBA", "RGB", "ALPHA", "LUMINANCE", "LUMINANCE_ALPHA")
ENVS = ("REPLACE", "MODULATE", "DECAL", "BLEND", "ADD")
FUNCS = ("NEVER", "LESS", "EQUAL", "LEQUAL", "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS")
BLENDS = (("SRC_ALPHA", "ONE_MINUS_SRC_ALPHA"), ("ONE", "ONE"), ("DST_COLOR", "ZERO"),
          ("SRC_ALPHA_SATURATE", "ONE"))

unit = st.fixed_dictionaries({
    "size": st.sampled_from([1, 4, 16, 32]),
    "format": st.sampled_from(FORMATS),
    "min": st.sampled_from(FILTERS),
    "mag": st.sampled_from(("NEAREST", "LINEAR")),
    "wrap": st.sampled_from(("REPEAT", "CLAMP_TO_EDGE")),
    "env": st.sampled_from(ENVS),
    "crop": st.tuples(st.integers(-4, 8), st.integers(-4, 8), st.integers(-20, 40), st.integers(-20, 40)),
})

STATE_FIELDS = {
    "numeric": st.sampled_from(BUILDS),
    "color": st.sampled_from(["rgba8888", "rgb565", "rgba4444", "rgba5551"]),
    "units": st.lists(unit, min_size=0, max_size=2),
    "rect": st.tuples(st.floats(-10, 30), st.floats(-10, 25), st.floats(-0.5, 1.5),
                      st.floats(0.5, 45), st.floats(0.5, 40)),
    "colour": st.tuples(*(st.floats(0, 1),) * 4),
    "blend": st.one_of(st.none(), st.sampled_from(BLENDS)),
    "alpha": st.one_of(st.none(), st.tuples(st.sampled_from(FUNCS), st.floats(0, 1))),
    "depth": st.one_of(st.none(), st.tuples(st.sampled_from(FUNCS), st.booleans())),
    "stencil": st.one_of(st.none(), st.tuples(st.sampled_from(FUNCS), st.integers(0, 3),
                                              st.sampled_from(("KEEP", "INCR", "INVERT", "REPLACE")))),
    "fog": st.booleans(),
    "dither": st.booleans(),
    "seed": st.integers(0, 2**16),
}
states = st.fixed_dictionaries(STATE_FIELDS)

# the states of the fused MODULATE + alpha test + write stage (one MODULATE
# unit of an RGBA or RGB texture, no fog, blending off, SRC_ALPHA or ONE)
modulate_write_states = st.fixed_dictionaries({
    **STATE_FIELDS,
    "units": st.lists(unit.map(lambda u: {**u, "env": "MODULATE",
                                          "format": "RGB" if u["format"] == "RGB" else "RGBA"}),
                      min_size=1, max_size=1),
    "blend": st.one_of(st.none(), st.sampled_from(BLENDS[:2])),
    "fog": st.just(False),
})


def _texture(gl, rng: np.random.Generator, u: dict) -> None:
    n = u["size"]
    fmt = getattr(C, "GL_" + u["format"])
    comps = {"RGBA": 4, "RGB": 3, "ALPHA": 1, "LUMINANCE": 1, "LUMINANCE_ALPHA": 2}[u["format"]]
    level, size = 0, n
    while size >= 1:
        data = rng.integers(0, 256, (size, size, comps), dtype=np.uint8)
        gl.glTexImage2D(C.GL_TEXTURE_2D, level, fmt, size, size, 0, fmt, C.GL_UNSIGNED_BYTE, data)
        level, size = level + 1, size // 2
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, getattr(C, "GL_" + u["min"]))
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, getattr(C, "GL_" + u["mag"]))
    wrap = getattr(C, "GL_" + u["wrap"])
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_S, wrap)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_WRAP_T, wrap)
    gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, np.array(u["crop"], dtype=np.int32))
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, getattr(C, "GL_" + u["env"]))
    gl.glTexEnvfv(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_COLOR, [float(v) for v in rng.uniform(0, 1, 4)])
    gl.glEnable(C.GL_TEXTURE_2D)


def _state(gl, s: dict, rng: np.random.Generator) -> None:
    gl.glClearColor(*(float(v) for v in rng.uniform(0, 1, 4)))
    gl.glClearDepthf(float(rng.uniform(0.2, 1)))
    gl.glClearStencil(int(rng.integers(0, 4)))
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
    (gl.glEnable if s["dither"] else gl.glDisable)(C.GL_DITHER)
    gl.glPixelStorei(C.GL_UNPACK_ALIGNMENT, 1)
    for i, u in enumerate(s["units"]):
        gl.glActiveTexture(C.GL_TEXTURE0 + i)
        gl.glBindTexture(C.GL_TEXTURE_2D, int(np.atleast_1d(gl.glGenTextures(1))[0]))
        _texture(gl, rng, u)
    gl.glColor4f(*s["colour"])
    if s["blend"]:
        gl.glEnable(C.GL_BLEND)
        gl.glBlendFunc(*(getattr(C, "GL_" + f) for f in s["blend"]))
    if s["alpha"]:
        gl.glEnable(C.GL_ALPHA_TEST)
        gl.glAlphaFunc(getattr(C, "GL_" + s["alpha"][0]), s["alpha"][1])
    if s["depth"]:
        gl.glEnable(C.GL_DEPTH_TEST)
        gl.glDepthFunc(getattr(C, "GL_" + s["depth"][0]))
        gl.glDepthMask(s["depth"][1])
    if s["stencil"]:
        func, ref, op = s["stencil"]
        gl.glEnable(C.GL_STENCIL_TEST)
        gl.glStencilFunc(getattr(C, "GL_" + func), ref, 0xFF)
        gl.glStencilOp(C.GL_KEEP, getattr(C, "GL_" + op), getattr(C, "GL_" + op))
    if s["fog"]:
        gl.glEnable(C.GL_FOG)
        gl.glFogf(C.GL_FOG_MODE, C.GL_LINEAR)
        gl.glFogf(C.GL_FOG_START, -1.0)
        gl.glFogf(C.GL_FOG_END, 2.0)
        gl.glFogfv(C.GL_FOG_COLOR, [0.2, 0.7, 0.4, 1.0])


# the debug flags of each path: the per-fragment reference, the chain, and
# the chain's baseline instance where the CPU has a vector one
REFERENCE, CHAINS = 1, (0, 16) if HAS_SIMD else (0,)


def _begin(s: dict, flags: int):
    """A context for state `s`, with debug `flags` (REFERENCE, or one of CHAINS) and the state set."""
    rng = np.random.default_rng(s["seed"])
    ctx = make_ctx(s["numeric"], W, H, color=s["color"])
    if flags:
        ctx.debug(flags)
    _state(ctx.gl, s, rng)
    return ctx, ctx.gl, rng


def _outcome(ctx):
    """The error and the three buffers: what both paths must agree on."""
    return ctx.gl.glGetError(), ctx.color_buffer(), ctx.depth_buffer(), ctx.stencil_buffer()


def render(s: dict, flags: int):
    ctx, gl, rng = _begin(s, flags)
    x, y, z, w, h = s["rect"]
    gl.glDrawTexfOES(x, y, z, w, h)
    gl.glDrawTexfOES(x + 3, y + 2, z, w, h)     # over the first: blending, depth and stencil see it
    return _outcome(ctx)


def _same(fast, ref) -> None:
    """The same error and buffers (what every path must agree on)."""
    assert fast[0] == ref[0]
    for a, b in zip(fast[1:], ref[1:]):
        np.testing.assert_array_equal(a, b)


@settings(max_examples=200, deadline=None)
@given(states)
def test_drawtex_chain_matches_reference(s):
    """Identical buffers and errors with and without the forced per-fragment path."""
    ref = render(s, REFERENCE)
    for flags in CHAINS:
        _same(render(s, flags), ref)


@settings(max_examples=100, deadline=None)
@given(modulate_write_states)
def test_drawtex_modulate_write_matches_reference(s):
    """DrawTex through the fused MODULATE + alpha test + write stage (on
    the fixed build with AVX2; the other builds and instances take the
    separate stages): identical buffers both ways."""
    ref = render(s, REFERENCE)
    for flags in CHAINS:
        _same(render(s, flags), ref)


points = st.fixed_dictionaries({
    "sprite": st.booleans(),
    "replace": st.tuples(st.booleans(), st.booleans()),
    "size": st.floats(1, 12),
    "size_array": st.booleans(),
    "count": st.integers(1, 12),
    "persp": st.booleans(),
})


def render_points(s: dict, p: dict, flags: int):
    ctx, gl, rng = _begin(s, flags)
    gl.glMatrixMode(C.GL_PROJECTION)
    if p["persp"]:
        gl.glFrustumf(-1, 1, -1, 1, 1, 4)
    else:
        gl.glOrthof(-1, 1, -1, 1, -2, 2)
    gl.glMatrixMode(C.GL_MODELVIEW)
    if p["persp"]:
        gl.glTranslatef(0, 0, -2)
    if p["sprite"]:
        gl.glEnable(C.GL_POINT_SPRITE_OES)
        for i in range(len(s["units"])):
            gl.glActiveTexture(C.GL_TEXTURE0 + i)
            gl.glTexEnvi(C.GL_POINT_SPRITE_OES, C.GL_COORD_REPLACE_OES, int(p["replace"][i]))
    n = p["count"]
    verts = rng.uniform(-1.1, 1.1, (n, 3)).astype(np.float32)
    cols = rng.integers(0, 256, (n, 4), dtype=np.uint8)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    gl.glEnableClientState(C.GL_COLOR_ARRAY)
    gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, cols)
    coords = rng.uniform(-1, 2, (n, 4)).astype(np.float32)
    coords[:, 3] = rng.choice([1.0, 0.5, 2.0], n)
    for i in range(len(s["units"])):
        gl.glClientActiveTexture(C.GL_TEXTURE0 + i)
        gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
        gl.glTexCoordPointer(4, C.GL_FLOAT, 0, coords)
    gl.glPointSize(p["size"])
    if p["size_array"]:
        sizes = rng.uniform(0.5, 14, n).astype(np.float32)
        gl.glEnableClientState(C.GL_POINT_SIZE_ARRAY_OES)
        gl.glPointSizePointerOES(C.GL_FLOAT, 0, sizes)
    gl.glDrawArrays(C.GL_POINTS, 0, n)
    return _outcome(ctx)


@settings(max_examples=150, deadline=None)
@given(states, points)
def test_points_chain_matches_reference(s, p):
    """Aliased points and sprites: identical buffers and errors both ways."""
    ref = render_points(s, p, REFERENCE)
    for flags in CHAINS:
        _same(render_points(s, p, flags), ref)


@settings(max_examples=100, deadline=None)
@given(modulate_write_states, points)
def test_points_modulate_write_matches_reference(s, p):
    """Points and sprites through the fused MODULATE + alpha test + write
    stage: identical buffers both ways."""
    ref = render_points(s, p, REFERENCE)
    for flags in CHAINS:
        _same(render_points(s, p, flags), ref)
