"""Vertex arrays and buffer objects (ES 1.1 §2.8, §2.9, Table 2.4).

Draws go through an orthographic projection that maps object x, y straight to
window x, y, so every expected pixel is a hand value: a pixel is lit when its
centre is strictly inside the triangle (§3.5.1); centres exactly on an edge are
not checked, since the spec lets either neighbour own them. Colours are exact:
a ubyte colour c lands as c (§2.12.8), other colours as round(255 v).
"""

from __future__ import annotations

import gc

import numpy as np
import pytest

import gles
from gles import gl as G

BUILDS = ("fixed", "float", "double")
W = H = 32

NP_TYPE = {G.GL_BYTE: np.int8, G.GL_UNSIGNED_BYTE: np.uint8, G.GL_SHORT: np.int16,
           G.GL_UNSIGNED_SHORT: np.uint16, G.GL_FIXED: np.int32, G.GL_FLOAT: np.float32}
VERTEX_TYPES = (G.GL_BYTE, G.GL_SHORT, G.GL_FIXED, G.GL_FLOAT)
COLOR_TYPES = (G.GL_UNSIGNED_BYTE, G.GL_FIXED, G.GL_FLOAT)
GL_INT, GL_DOUBLE = 0x1404, 0x140A  # desktop GL types that ES 1.1 does not have
ALL_TYPES = (G.GL_BYTE, G.GL_UNSIGNED_BYTE, G.GL_SHORT, G.GL_UNSIGNED_SHORT, G.GL_FIXED, G.GL_FLOAT,
             GL_INT, GL_DOUBLE)

# a triangle in window coordinates with integer corners; no pixel centre lies on an edge
TRI = np.array([[3, 2], [27, 5], [9, 29]], dtype=np.float64)


def context(numeric: str = "fixed", *, profile: str = "common", depth: int = 0, w: int = W,
            h: int = H) -> gles.Context:
    """A cleared context whose projection maps object (x, y) to window (x, y); z in [-64, 64]."""
    ctx = gles.Context(w, h, numeric=numeric, profile=profile, depth=depth, stencil=0)
    g = ctx.gl
    g.glClear(G.GL_COLOR_BUFFER_BIT)  # to the initial clear colour, (0, 0, 0, 0)
    g.glMatrixMode(G.GL_PROJECTION)
    g.glOrthox(0, w << 16, 0, h << 16, -64 << 16, 64 << 16)
    g.glMatrixMode(G.GL_MODELVIEW)
    return ctx


def read(ctx: gles.Context) -> np.ndarray:
    return ctx.gl.glReadPixels(0, 0, ctx.width, ctx.height, G.GL_RGBA, G.GL_UNSIGNED_BYTE)


def coverage(tris, width: int = W, height: int = H) -> tuple[np.ndarray, np.ndarray]:
    """(must, must_not), rows bottom first: centres strictly inside some
    triangle, and strictly outside all of them. Exact for corners on the
    1/256 grid (float64 arithmetic is exact there)."""
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    must = np.zeros((height, width), bool)
    must_not = np.ones((height, width), bool)
    for t in tris:
        t = np.asarray(t, dtype=np.float64)
        area = (t[1, 0] - t[0, 0]) * (t[2, 1] - t[0, 1]) - (t[2, 0] - t[0, 0]) * (t[1, 1] - t[0, 1])
        if area < 0:
            t = t[[0, 2, 1]]
        inside = np.ones_like(must)
        outside = np.zeros_like(must)
        for i in range(3):
            p, q = t[i], t[(i + 1) % 3]
            e = (q[0] - p[0]) * (ys - p[1]) - (q[1] - p[1]) * (xs - p[0])
            inside &= e > 0
            outside |= e < 0
        must |= inside
        must_not &= outside
    return must, must_not


def assert_drawn(px: np.ndarray, tris, color, background=(0, 0, 0, 0)) -> None:
    """Pixels inside the triangles have `color`, pixels outside `background`."""
    must, must_not = coverage(tris, px.shape[1], px.shape[0])
    assert must.sum() > 0
    np.testing.assert_array_equal(px[must], np.broadcast_to(np.asarray(color, np.uint8), (must.sum(), 4)))
    np.testing.assert_array_equal(px[must_not],
                                  np.broadcast_to(np.asarray(background, np.uint8), (must_not.sum(), 4)))


def encode(values, gltype: int) -> np.ndarray:
    """Values as an array of a GL type (FIXED is 16.16)."""
    v = np.asarray(values, dtype=np.float64)
    if gltype == G.GL_FIXED:
        return np.round(v * 65536).astype(np.int32)
    return v.astype(NP_TYPE[gltype])


def positions(size: int, tri=TRI) -> tuple[np.ndarray, np.ndarray]:
    """Object positions of `size` components for the window triangle, and the
    window depth (in [0, 1]) they must produce. Size 3 carries z = 16; size 4
    multiplies (x, y, z) = (x, y, 16) by w = 2."""
    n = len(tri)
    if size == 2:
        return tri.copy(), np.full(n, 0.5)
    xyz = np.column_stack([tri, np.full(n, 16.0)])
    # ortho n=-64, f=64: z_ndc = -z/64; z_w = (z_ndc + 1) / 2
    depth = np.full(n, (1 - 16 / 64) / 2)
    if size == 3:
        return xyz, depth
    return np.column_stack([xyz * 2, np.full(n, 2.0)]), depth


def interleave(pos: np.ndarray, pos_type: int, col: np.ndarray, col_type: int) -> tuple[np.ndarray, int, int]:
    """A numpy structured array of records (position, padding, colour, padding):
    returns the raw bytes as uint8, the stride and the colour's byte offset."""
    pos_bytes = pos.shape[1] * np.dtype(NP_TYPE[pos_type]).itemsize
    col_off = (pos_bytes + 3) // 4 * 4 + 4  # 4 bytes of padding, 4-byte aligned
    stride = col_off + 4 * np.dtype(NP_TYPE[col_type]).itemsize + 4
    rec = np.dtype({"names": ["pos", "col"],
                    "formats": [(NP_TYPE[pos_type], pos.shape[1]), (NP_TYPE[col_type], 4)],
                    "offsets": [0, col_off], "itemsize": stride})
    arr = np.zeros(len(pos), dtype=rec)
    arr["pos"] = encode(pos, pos_type)
    arr["col"] = encode(col, col_type)
    return arr.view(np.uint8).reshape(-1), stride, col_off


# {====================================================================
# Table 2.4: vertex and colour arrays, every size and type


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("size", [2, 3, 4])
@pytest.mark.parametrize("gltype", VERTEX_TYPES, ids=str)
@pytest.mark.parametrize("layout", ["packed", "interleaved"])
def test_vertex_pointer_sizes_and_types(numeric, size, gltype, layout):
    """VertexPointer with each size and type of Table 2.4, tightly packed or interleaved
    with a colour (non-zero stride), draws the same triangle at the same depth."""
    ctx = context(numeric, depth=16)
    g = ctx.gl
    g.glEnable(G.GL_DEPTH_TEST)  # so that depth is written and z can be checked
    g.glClear(G.GL_DEPTH_BUFFER_BIT)  # to the clear depth, 1.0
    pos, depth = positions(size)
    color = np.array([[200, 17, 99, 255]] * 3)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    if layout == "packed":
        g.glVertexPointer(size, gltype, 0, encode(pos, gltype))
        g.glColor4ub(200, 17, 99, 255)
    else:
        raw, stride, col_off = interleave(pos, gltype, color, G.GL_UNSIGNED_BYTE)
        mv = memoryview(raw)
        g.glVertexPointer(size, gltype, stride, mv)
        g.glColorPointer(4, G.GL_UNSIGNED_BYTE, stride, mv[col_off:])
        g.glEnableClientState(G.GL_COLOR_ARRAY)
        g.glColor4ub(1, 2, 3, 4)  # not used: the colour array is enabled
        assert g.glGetIntegerv(G.GL_VERTEX_ARRAY_STRIDE) == stride
    assert g.glGetIntegerv(G.GL_VERTEX_ARRAY_SIZE) == size
    assert g.glGetIntegerv(G.GL_VERTEX_ARRAY_TYPE) == gltype
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], (200, 17, 99, 255))
    must, _ = coverage([TRI])
    z = ctx.depth_buffer()[must].astype(np.float64)
    # one depth unit: the window z is rounded to the 16-bit buffer
    np.testing.assert_allclose(z, depth[0] * 65535, atol=1.0)


COLOR_CASES = [
    (G.GL_UNSIGNED_BYTE, [0, 77, 128, 255], (0, 77, 128, 255)),
    (G.GL_UNSIGNED_BYTE, [1, 254, 127, 3], (1, 254, 127, 3)),
    (G.GL_FIXED, [0x4000, 0xC000, 0x10000, 0], (64, 191, 255, 0)),
    (G.GL_FIXED, [0x33333, -0x8000, 0x3333, 0x10000], (255, 0, 51, 255)),  # clamped to [0, 1] (§2.12.5)
    (G.GL_FLOAT, [0.25, 0.75, 1.0, 0.0], (64, 191, 255, 0)),
    (G.GL_FLOAT, [1.5, -0.5, 0.2, 3.0], (255, 0, 51, 255)),
]


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("gltype, value, want", COLOR_CASES)
@pytest.mark.parametrize("layout", ["packed", "interleaved"])
def test_color_pointer_types(numeric, gltype, value, want, layout):
    """ColorPointer with UNSIGNED_BYTE, FIXED and FLOAT (size 4), packed or interleaved:
    the framebuffer holds round(255 * clamp(v)), and exactly c for a ubyte c."""
    ctx = context(numeric)
    g = ctx.gl
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glEnableClientState(G.GL_COLOR_ARRAY)
    raw_color = np.array([value] * 3, dtype=np.float64)
    if gltype == G.GL_FIXED:
        col_values = raw_color / 65536.0  # encode() scales FIXED by 2^16 again
    else:
        col_values = raw_color
    if layout == "packed":
        g.glVertexPointer(2, G.GL_SHORT, 0, encode(TRI, G.GL_SHORT))
        g.glColorPointer(4, gltype, 0, encode(col_values, gltype))
    else:
        raw, stride, col_off = interleave(TRI, G.GL_FLOAT, col_values, gltype)
        g.glVertexPointer(2, G.GL_FLOAT, stride, memoryview(raw))
        g.glColorPointer(4, gltype, stride, memoryview(raw)[col_off:])
        assert g.glGetIntegerv(G.GL_COLOR_ARRAY_STRIDE) == stride
    assert g.glGetIntegerv(G.GL_COLOR_ARRAY_TYPE) == gltype
    assert g.glGetIntegerv(G.GL_COLOR_ARRAY_SIZE) == 4
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], want)


@pytest.mark.parametrize("numeric", BUILDS)
def test_every_ubyte_colour_is_exact(numeric):
    """All 256 ubyte values in every channel land unchanged in an RGBA8888 framebuffer
    (§2.12.8: lighting off, no clipping, ubyte input). One draw, one quad per pixel,
    from an interleaved SHORT position / UNSIGNED_BYTE colour array."""
    n = 16
    ctx = context(numeric, w=n, h=n)
    g = ctx.gl
    i = np.arange(256)
    colors = np.stack([i, 255 - i, (i * 37) % 256, (i * 101) % 256], axis=1)
    rec = np.dtype({"names": ["pos", "col"], "formats": [(np.int16, 2), (np.uint8, 4)],
                    "offsets": [0, 8], "itemsize": 12})
    verts = np.zeros(256 * 6, dtype=rec)
    corners = np.array([[0, 0], [1, 0], [1, 1], [0, 0], [1, 1], [0, 1]])
    for k in range(256):
        x, y = k % n, k // n
        verts["pos"][6 * k:6 * k + 6] = corners + [x, y]
        verts["col"][6 * k:6 * k + 6] = colors[k]
    raw = memoryview(verts.view(np.uint8).reshape(-1))
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glEnableClientState(G.GL_COLOR_ARRAY)
    g.glVertexPointer(2, G.GL_SHORT, 12, raw)
    g.glColorPointer(4, G.GL_UNSIGNED_BYTE, 12, raw[8:])
    g.glDrawArrays(G.GL_TRIANGLES, 0, 256 * 6)
    px = read(ctx).reshape(256, 4)
    np.testing.assert_array_equal(px, colors.astype(np.uint8))


@pytest.mark.parametrize("numeric", BUILDS)
def test_flat_shading_uses_the_provoking_vertex(numeric):
    """With FLAT shading a triangle takes the colour of its last vertex (Table 2.10);
    in a strip and a fan triangle i takes vertex i + 2's colour."""
    quad = np.array([[4, 4], [28, 4], [28, 28], [4, 28]], dtype=np.float64)
    cols = np.array([[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [9, 99, 199, 255]], np.uint8)
    cases = [
        # mode, vertex order, (triangle corners, colour index) per triangle
        (G.GL_TRIANGLES, [0, 1, 2, 2, 3, 0], [((0, 1, 2), 2), ((2, 3, 0), 0)]),
        (G.GL_TRIANGLE_STRIP, [0, 1, 3, 2], [((0, 1, 3), 3), ((1, 3, 2), 2)]),
        (G.GL_TRIANGLE_FAN, [0, 1, 2, 3], [((0, 1, 2), 2), ((0, 2, 3), 3)]),
    ]
    for mode, order, tris in cases:
        ctx = context(numeric)
        g = ctx.gl
        g.glShadeModel(G.GL_FLAT)
        g.glEnableClientState(G.GL_VERTEX_ARRAY)
        g.glEnableClientState(G.GL_COLOR_ARRAY)
        g.glVertexPointer(2, G.GL_FLOAT, 0, quad[order].astype(np.float32))
        g.glColorPointer(4, G.GL_UNSIGNED_BYTE, 0, cols[order])
        g.glDrawArrays(mode, 0, len(order))
        px = read(ctx)
        for corners, ci in tris:
            must, _ = coverage([quad[list(corners)]])
            assert (px[must] == cols[ci]).all(), str(mode)


@pytest.mark.parametrize("numeric", BUILDS)
def test_draw_arrays_with_a_first_element(numeric):
    """DrawArrays(first, count) uses elements first .. first + count - 1 (§2.8)."""
    ctx = context(numeric)
    g = ctx.gl
    far = [[-50, -50], [90, -50], [-50, 90]]  # would cover the whole window
    verts = np.concatenate([far, far[:2], TRI, far]).astype(np.float32)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, verts)
    g.glDrawArrays(G.GL_TRIANGLES, 5, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], (255, 255, 255, 255))


def _churn() -> list:
    """Collect garbage and allocate many small arrays, so that freed memory gets reused."""
    gc.collect()
    return [np.full(n, -1e30, np.float32) for n in range(1, 64) for _ in range(20)]


@pytest.mark.parametrize("kind", ["ndarray", "list", "bytes", "bytearray", "memoryview", "strided view"])
def test_pointer_argument_kinds_are_kept_alive(kind):
    """A pointer may be a numpy array, a sequence, bytes, a bytearray, a memoryview or a
    non-contiguous array view; the data stays valid after the caller drops it."""
    ctx = context()
    g = ctx.gl
    flat = TRI.astype(np.float32).reshape(-1)
    if kind == "ndarray":
        data = flat.copy()
    elif kind == "list":
        data = flat.tolist()
    elif kind == "bytes":
        data = flat.tobytes()
    elif kind == "bytearray":
        data = bytearray(flat.tobytes())
    elif kind == "memoryview":
        data = memoryview(bytearray(flat.tobytes()))
    else:
        wide = np.zeros(12, np.float32)
        wide[::2] = flat
        data = wide[::2]
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, data)
    del data
    junk = _churn()
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    del junk
    assert_drawn(read(ctx), [TRI], (255, 255, 255, 255))


@pytest.mark.parametrize("bad", [
    ("glVertexPointer", (2, G.GL_UNSIGNED_BYTE, 0, np.zeros(6, np.uint8))),  # INVALID_ENUM
    ("glVertexPointer", (7, G.GL_FLOAT, 0, np.zeros(6, np.float32))),        # INVALID_VALUE
    ("glVertexPointer", (2, G.GL_FLOAT, -8, np.zeros(6, np.float32))),       # INVALID_VALUE
    ("glColorPointer", (4, G.GL_SHORT, 0, np.zeros(12, np.int16))),          # INVALID_ENUM
])
def test_erring_pointer_call_keeps_the_old_array(bad):
    """A Pointer call that records a GL error changes nothing (§2.5): the array set
    before stays in use and must stay alive, even if the caller dropped it."""
    ctx = context()
    g = ctx.gl
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, TRI.astype(np.float32).reshape(-1))  # gles holds the only reference
    g.glColorPointer(4, G.GL_UNSIGNED_BYTE, 0, np.tile(np.uint8([9, 8, 7, 6]), 3))
    g.glEnableClientState(G.GL_COLOR_ARRAY)
    cmd, args = bad
    getattr(g, cmd)(*args)
    assert g.glGetError() in (G.GL_INVALID_ENUM, G.GL_INVALID_VALUE)
    junk = _churn()
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    del junk
    assert_drawn(read(ctx), [TRI], (9, 8, 7, 6))


# {====================================================================
# the other pointers: legal types accepted, others rejected, state kept

POINTERS = {
    # name: (command, legal sizes (None: no size argument), legal types, size/type/stride pnames)
    "vertex": ("glVertexPointer", (2, 3, 4), VERTEX_TYPES,
               (G.GL_VERTEX_ARRAY_SIZE, G.GL_VERTEX_ARRAY_TYPE, G.GL_VERTEX_ARRAY_STRIDE)),
    "color": ("glColorPointer", (4,), COLOR_TYPES,
              (G.GL_COLOR_ARRAY_SIZE, G.GL_COLOR_ARRAY_TYPE, G.GL_COLOR_ARRAY_STRIDE)),
    "normal": ("glNormalPointer", None, VERTEX_TYPES,
               (None, G.GL_NORMAL_ARRAY_TYPE, G.GL_NORMAL_ARRAY_STRIDE)),
    "texcoord": ("glTexCoordPointer", (2, 3, 4), VERTEX_TYPES,
                 (G.GL_TEXTURE_COORD_ARRAY_SIZE, G.GL_TEXTURE_COORD_ARRAY_TYPE,
                  G.GL_TEXTURE_COORD_ARRAY_STRIDE)),
    "pointsize": ("glPointSizePointerOES", None, (G.GL_FIXED, G.GL_FLOAT),
                  (None, G.GL_POINT_SIZE_ARRAY_TYPE_OES, G.GL_POINT_SIZE_ARRAY_STRIDE_OES)),
}


def _set(g, name: str, size: int, gltype: int, stride: int) -> None:
    cmd, sizes = POINTERS[name][0], POINTERS[name][1]
    if sizes is None:
        getattr(g, cmd)(gltype, stride, None)
    else:
        getattr(g, cmd)(size, gltype, stride, None)


def _state(g, name: str) -> tuple:
    return tuple(None if p is None else g.glGetIntegerv(p) for p in POINTERS[name][3])


@pytest.mark.parametrize("name", list(POINTERS))
def test_pointer_initial_state(name):
    """Arrays start with size 4 (where there is a size), type FLOAT, stride 0, disabled (§2.8)."""
    g = context().gl
    size, gltype, stride = _state(g, name)
    assert size in (None, 4)
    assert (gltype, stride) == (G.GL_FLOAT, 0)


@pytest.mark.parametrize("name", list(POINTERS))
def test_pointer_legal_and_illegal_types(name):
    """Every Table 2.4 type is accepted; any other is INVALID_ENUM and changes nothing."""
    g = context().gl
    _, sizes, legal, _ = POINTERS[name]
    size = sizes[-1] if sizes else None
    for gltype in legal:
        _set(g, name, size, gltype, 8)
        assert g.glGetError() == G.GL_NO_ERROR
        assert _state(g, name) == (size, gltype, 8)
    before = _state(g, name)
    for gltype in ALL_TYPES:
        if gltype in legal:
            continue
        _set(g, name, size, gltype, 4)
        assert g.glGetError() == G.GL_INVALID_ENUM, hex(gltype)
        assert _state(g, name) == before


@pytest.mark.parametrize("name", [n for n, p in POINTERS.items() if p[1] is not None])
def test_pointer_legal_and_illegal_sizes(name):
    """Sizes outside Table 2.4 are INVALID_VALUE and change nothing."""
    g = context().gl
    _, sizes, legal, _ = POINTERS[name]
    for size in sizes:
        _set(g, name, size, G.GL_FIXED, 0)
        assert g.glGetError() == G.GL_NO_ERROR
        assert _state(g, name) == (size, G.GL_FIXED, 0)
    _set(g, name, sizes[0], G.GL_FLOAT, 20)
    before = _state(g, name)
    for size in (-1, 0, 1, 2, 3, 5, 16):
        if size in sizes:
            continue
        _set(g, name, size, G.GL_FIXED, 0)
        assert g.glGetError() == G.GL_INVALID_VALUE, size
        assert _state(g, name) == before


@pytest.mark.parametrize("name", list(POINTERS))
def test_pointer_negative_stride(name):
    """A negative stride is INVALID_VALUE and changes nothing (§2.8)."""
    g = context().gl
    sizes = POINTERS[name][1]
    size = sizes[0] if sizes else None
    _set(g, name, size, G.GL_FIXED, 12)
    before = _state(g, name)
    _set(g, name, size, G.GL_FIXED, -4)
    assert g.glGetError() == G.GL_INVALID_VALUE
    assert _state(g, name) == before


def test_texcoord_pointer_per_client_unit():
    """TexCoordPointer and its queries follow CLIENT_ACTIVE_TEXTURE (§2.8)."""
    g = context().gl
    g.glClientActiveTexture(G.GL_TEXTURE1)
    g.glTexCoordPointer(2, G.GL_SHORT, 20, None)
    g.glEnableClientState(G.GL_TEXTURE_COORD_ARRAY)
    assert _state(g, "texcoord") == (2, G.GL_SHORT, 20)
    assert g.glIsEnabled(G.GL_TEXTURE_COORD_ARRAY)
    g.glClientActiveTexture(G.GL_TEXTURE0)
    assert _state(g, "texcoord") == (4, G.GL_FLOAT, 0)
    assert not g.glIsEnabled(G.GL_TEXTURE_COORD_ARRAY)
    assert g.glGetError() == G.GL_NO_ERROR


def test_enable_client_state_queries():
    """EnableClientState/DisableClientState flip each array's IsEnabled answer."""
    g = context().gl
    caps = (G.GL_VERTEX_ARRAY, G.GL_NORMAL_ARRAY, G.GL_COLOR_ARRAY, G.GL_POINT_SIZE_ARRAY_OES,
            G.GL_TEXTURE_COORD_ARRAY)
    for cap in caps:
        assert not g.glIsEnabled(cap)
        g.glEnableClientState(cap)
        assert g.glIsEnabled(cap)
        assert g.glGetBooleanv(cap)
    for cap in caps:
        g.glDisableClientState(cap)
        assert not g.glIsEnabled(cap)
    assert g.glGetError() == G.GL_NO_ERROR


# {====================================================================
# current colour


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("how, args, want", [
    ("glColor4ub", (12, 250, 128, 77), (12, 250, 128, 77)),
    ("glColor4f", (0.25, 0.75, 1.0, 0.0), (64, 191, 255, 0)),
    ("glColor4f", (2.0, -1.0, 0.2, 0.6), (255, 0, 51, 153)),
    ("glColor4x", (0x4000, 0xC000, 0x10000, 0), (64, 191, 255, 0)),
    ("glColor4x", (0x20000, -0x10000, 0x3333, 0x9999), (255, 0, 51, 153)),
])
def test_current_colour_when_array_disabled(numeric, how, args, want):
    """With the colour array disabled every vertex takes the current colour (§2.8),
    clamped to [0, 1] (§2.12.5); a colour array that is set but disabled is ignored."""
    ctx = context(numeric)
    g = ctx.gl
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_BYTE, 0, encode(TRI, G.GL_BYTE))
    g.glColorPointer(4, G.GL_UNSIGNED_BYTE, 0, np.full(12, 99, np.uint8))  # never enabled
    getattr(g, how)(*args)
    g.glDrawArrays(G.GL_TRIANGLE_STRIP, 0, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], want)


def test_current_colour_query():
    """Color4ub stores c / 255 (Table 2.7), Color4x stores x / 2^16."""
    g = context().gl
    g.glColor4ub(255, 0, 51, 102)
    np.testing.assert_allclose(g.glGetFloatv(G.GL_CURRENT_COLOR), [1.0, 0.0, 0.2, 0.4], rtol=1e-7)
    g.glColor4x(0x8000, 0x4000, 0, 0x10000)
    np.testing.assert_array_equal(g.glGetFixedv(G.GL_CURRENT_COLOR), [0x8000, 0x4000, 0, 0x10000])


# {====================================================================
# buffer objects


def test_buffer_object_lifecycle():
    """GenBuffers, BindBuffer, BufferData/SubData, parameters, IsBuffer and DeleteBuffers (§2.9)."""
    g = context().gl
    a = g.glGenBuffers(1)
    names = g.glGenBuffers(3)
    assert isinstance(a, int) and a != 0
    assert len(names) == 3 and 0 not in names and a not in names and len(set(names.tolist())) == 3
    # generated names are not buffer objects until bound
    assert not g.glIsBuffer(a) and not g.glIsBuffer(0)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, a)
    assert g.glIsBuffer(a)
    assert g.glGetIntegerv(G.GL_ARRAY_BUFFER_BINDING) == a
    # Table 2.5 initial state
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_SIZE) == 0
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_USAGE) == G.GL_STATIC_DRAW
    g.glBufferData(G.GL_ARRAY_BUFFER, 48, np.arange(48, dtype=np.uint8), G.GL_DYNAMIC_DRAW)
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_SIZE) == 48
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_USAGE) == G.GL_DYNAMIC_DRAW
    g.glBufferData(G.GL_ARRAY_BUFFER, 20, None, G.GL_STATIC_DRAW)
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_SIZE) == 20
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_USAGE) == G.GL_STATIC_DRAW
    g.glBufferSubData(G.GL_ARRAY_BUFFER, 4, 16, bytes(16))
    g.glBufferSubData(G.GL_ARRAY_BUFFER, 20, 0, b"")  # an empty range at the end is legal
    assert g.glGetError() == G.GL_NO_ERROR
    # a second buffer on the element target; the array binding is unaffected
    g.glBindBuffer(G.GL_ELEMENT_ARRAY_BUFFER, int(names[0]))
    g.glBufferData(G.GL_ELEMENT_ARRAY_BUFFER, 6, bytes(6), G.GL_STATIC_DRAW)
    assert g.glGetBufferParameteriv(G.GL_ELEMENT_ARRAY_BUFFER, G.GL_BUFFER_SIZE) == 6
    assert g.glGetBufferParameteriv(G.GL_ARRAY_BUFFER, G.GL_BUFFER_SIZE) == 20
    # deleting: unused names and zero are ignored silently
    g.glDeleteBuffers(4, [a, 0, int(names[2]), 9999])
    assert g.glGetError() == G.GL_NO_ERROR
    assert not g.glIsBuffer(a)
    assert g.glIsBuffer(int(names[0]))
    # binding an unused name creates the object; Gen never returns a name in use
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 77)
    assert g.glIsBuffer(77)
    fresh = g.glGenBuffers(100)
    assert 77 not in fresh and int(names[0]) not in fresh
    assert g.glGetError() == G.GL_NO_ERROR


def test_delete_bound_buffer_unbinds_it():
    """Deleting a bound buffer resets every binding to it to zero (§2.9)."""
    g = context().gl
    b, e = g.glGenBuffers(2)
    b, e = int(b), int(e)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, b)
    g.glBufferData(G.GL_ARRAY_BUFFER, 24, None, G.GL_STATIC_DRAW)
    g.glVertexPointer(2, G.GL_FLOAT, 0, 0)
    g.glColorPointer(4, G.GL_UNSIGNED_BYTE, 0, 8)
    g.glBindBuffer(G.GL_ELEMENT_ARRAY_BUFFER, e)
    assert g.glGetIntegerv(G.GL_VERTEX_ARRAY_BUFFER_BINDING) == b
    assert g.glGetIntegerv(G.GL_COLOR_ARRAY_BUFFER_BINDING) == b
    g.glDeleteBuffers(2, [b, e])
    assert g.glGetIntegerv(G.GL_ARRAY_BUFFER_BINDING) == 0
    assert g.glGetIntegerv(G.GL_ELEMENT_ARRAY_BUFFER_BINDING) == 0
    assert g.glGetIntegerv(G.GL_VERTEX_ARRAY_BUFFER_BINDING) == 0
    assert g.glGetIntegerv(G.GL_COLOR_ARRAY_BUFFER_BINDING) == 0
    assert not g.glIsBuffer(b) and not g.glIsBuffer(e)
    assert g.glGetError() == G.GL_NO_ERROR


def test_draw_after_deleting_the_arrays_buffer_raises():
    """An array whose buffer was deleted has no data left: the draw raises, nothing is read."""
    ctx = context()
    g = ctx.gl
    b = g.glGenBuffers(1)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, b)
    g.glBufferData(G.GL_ARRAY_BUFFER, 24, encode(TRI, G.GL_FLOAT), G.GL_STATIC_DRAW)
    g.glVertexPointer(2, G.GL_FLOAT, 0, 0)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glDeleteBuffers(1, [b])
    with pytest.raises(ValueError):
        g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert not read(ctx).any()


@pytest.mark.parametrize("numeric", BUILDS)
def test_arrays_from_a_buffer_object(numeric):
    """Vertex and colour arrays read from one interleaved buffer object at int offsets;
    BufferSubData changes what the next draw reads (§2.9.1)."""
    ctx = context(numeric)
    g = ctx.gl
    raw, stride, col_off = interleave(TRI, G.GL_FIXED, np.array([[10, 20, 30, 40]] * 3), G.GL_UNSIGNED_BYTE)
    pad = 8  # the records start 8 bytes into the buffer
    data = np.concatenate([np.full(pad, 0xFF, np.uint8), raw])
    b = g.glGenBuffers(1)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, b)
    g.glBufferData(G.GL_ARRAY_BUFFER, data.nbytes, data, G.GL_STATIC_DRAW)
    g.glVertexPointer(2, G.GL_FIXED, stride, pad)
    g.glColorPointer(4, G.GL_UNSIGNED_BYTE, stride, pad + col_off)
    assert g.glGetPointerv(G.GL_COLOR_ARRAY_POINTER) == pad + col_off
    assert g.glGetIntegerv(G.GL_VERTEX_ARRAY_BUFFER_BINDING) == b
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 0)  # the arrays keep their own binding
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glEnableClientState(G.GL_COLOR_ARRAY)
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert_drawn(read(ctx), [TRI], (10, 20, 30, 40))
    # new colours for all three records
    g.glBindBuffer(G.GL_ARRAY_BUFFER, b)
    for k in range(3):
        g.glBufferSubData(G.GL_ARRAY_BUFFER, pad + k * stride + col_off, 4, bytes([250, 5, 6, 7]))
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], (250, 5, 6, 7))


@pytest.mark.parametrize("numeric", BUILDS)
def test_mixed_client_and_buffer_arrays(numeric):
    """One draw may take its vertex array from a buffer and its colour array from client memory."""
    ctx = context(numeric)
    g = ctx.gl
    b = g.glGenBuffers(1)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, b)
    g.glBufferData(G.GL_ARRAY_BUFFER, 12, encode(TRI, G.GL_SHORT), G.GL_STATIC_DRAW)
    g.glVertexPointer(2, G.GL_SHORT, 0, 0)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, 0)
    g.glColorPointer(4, G.GL_FLOAT, 0, np.tile(np.float32([0.2, 0.4, 0.6, 0.8]), 3))
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glEnableClientState(G.GL_COLOR_ARRAY)
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], (51, 102, 153, 204))


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("itype", [G.GL_UNSIGNED_BYTE, G.GL_UNSIGNED_SHORT])
def test_draw_elements_from_an_element_buffer(numeric, itype):
    """DrawElements reads its indices from the bound element buffer at an int offset (§2.9.2)."""
    ctx = context(numeric)
    g = ctx.gl
    verts = np.array([[0, 0], [9, 29], [31, 31], [3, 2], [27, 5]], dtype=np.float32)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, verts)
    idx = np.array([2, 2, 0, 3, 4, 1, 2], dtype=NP_TYPE[itype])  # the triangle is elements 3..5
    e = g.glGenBuffers(1)
    g.glBindBuffer(G.GL_ELEMENT_ARRAY_BUFFER, e)
    g.glBufferData(G.GL_ELEMENT_ARRAY_BUFFER, idx.nbytes, idx, G.GL_STATIC_DRAW)
    g.glDrawElements(G.GL_TRIANGLES, 3, itype, 3 * idx.itemsize)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], (255, 255, 255, 255))


# {====================================================================
# primitive modes

QUAD = np.array([[4.25, 3.25], [27.75, 3.25], [27.75, 28.75], [4.25, 28.75]])
QUAD_TRIS = [QUAD[[0, 1, 2]], QUAD[[0, 2, 3]]]
# vertex storage for DrawElements: the quad's corners scattered among vertices
# that would cover the whole window if they were ever used
STORE = np.array([[-40, -40], QUAD[2], [80, -40], QUAD[0], QUAD[3], QUAD[1], [0, 90]], dtype=np.float32)
ORDERS = {  # corners 0..3 for each mode
    G.GL_TRIANGLES: [0, 1, 2, 0, 2, 3],
    G.GL_TRIANGLE_STRIP: [0, 1, 3, 2],
    G.GL_TRIANGLE_FAN: [0, 1, 2, 3],
    G.GL_POINTS: [0, 1, 2, 3],
    G.GL_LINES: [0, 1, 2, 3],
    G.GL_LINE_STRIP: [0, 1, 2, 3],
    G.GL_LINE_LOOP: [0, 1, 2, 3],
}
WHERE = {0: 3, 1: 5, 2: 1, 3: 4}  # corner -> index in STORE


@pytest.mark.parametrize("numeric", BUILDS)
@pytest.mark.parametrize("mode", list(ORDERS), ids=str)
@pytest.mark.parametrize("how", ["arrays", "ubyte", "ushort"])
def test_all_modes(numeric, mode, how):
    """All seven modes are accepted by DrawArrays and by DrawElements with UNSIGNED_BYTE
    and UNSIGNED_SHORT indices; the triangle modes fill the quad."""
    ctx = context(numeric)
    g = ctx.gl
    g.glClearColorx(0, 0, 0x8000, 0x10000)
    g.glClear(G.GL_COLOR_BUFFER_BIT)
    before = read(ctx)
    g.glColor4ub(240, 120, 60, 255)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    order = ORDERS[mode]
    if how == "arrays":
        g.glVertexPointer(2, G.GL_FLOAT, 0, QUAD[order].astype(np.float32))
        g.glDrawArrays(mode, 0, len(order))
    else:
        g.glVertexPointer(2, G.GL_FLOAT, 0, STORE)
        itype = G.GL_UNSIGNED_BYTE if how == "ubyte" else G.GL_UNSIGNED_SHORT
        g.glDrawElements(mode, len(order), itype, np.array([WHERE[c] for c in order], NP_TYPE[itype]))
    assert g.glGetError() == G.GL_NO_ERROR
    px = read(ctx)
    if mode in (G.GL_TRIANGLES, G.GL_TRIANGLE_STRIP, G.GL_TRIANGLE_FAN):
        assert_drawn(px, QUAD_TRIS, (240, 120, 60, 255), background=(0, 0, 128, 255))
    else:
        drawn = np.any(px != before, axis=-1)
        color = np.array([240, 120, 60, 255], dtype=np.uint8)
        assert np.all(px[drawn] == color)
        corners = QUAD[order]
        if mode == G.GL_POINTS:
            # §3.3: a size-1 point is the pixel holding its vertex
            expect = np.zeros_like(drawn)
            for x, y in corners:
                expect[int(np.floor(y)), int(np.floor(x))] = True
            np.testing.assert_array_equal(drawn, expect)
        else:
            # §3.4: width-1 segments; every fragment lies within one pixel of
            # a segment, and segments of at least a few pixels are drawn
            segs = {G.GL_LINES: [(0, 1), (2, 3)], G.GL_LINE_STRIP: [(0, 1), (1, 2), (2, 3)],
                    G.GL_LINE_LOOP: [(0, 1), (1, 2), (2, 3), (3, 0)]}[mode]
            ys, xs = np.nonzero(drawn)
            centres = np.column_stack([xs + 0.5, ys + 0.5])
            dist = np.full(len(centres), np.inf)
            for i, j in segs:
                a, b = corners[i], corners[j]
                d = b - a
                t = np.clip(((centres - a) @ d) / (d @ d), 0, 1)
                dist = np.minimum(dist, np.linalg.norm(centres - (a + t[:, None] * d), axis=1))
            assert dist.max() <= 1.0
            assert drawn.sum() >= 20 * len(segs)


# {====================================================================
# Python-level misuse: raised before the core reads any memory


def _armed(numeric: str = "fixed"):
    """A context cleared to (16, 32, 48, 64) with a valid 3-vertex triangle array enabled."""
    ctx = context(numeric)
    g = ctx.gl
    g.glClearColorx(0x1000, 0x2000, 0x3000, 0x4000)
    g.glClear(G.GL_COLOR_BUFFER_BIT)
    g.glEnableClientState(G.GL_VERTEX_ARRAY)
    g.glVertexPointer(2, G.GL_FLOAT, 0, encode(TRI, G.GL_FLOAT))
    return ctx, g, ctx.color_buffer()


def _unchanged(ctx, g, fb) -> None:
    assert g.glGetError() == G.GL_NO_ERROR
    np.testing.assert_array_equal(ctx.color_buffer(), fb)


@pytest.mark.parametrize("first, count", [(0, 4), (1, 3), (3, 1), (2, 2)])
def test_drawarrays_beyond_client_array(first, count):
    """DrawArrays reading past the end of a client array raises ValueError."""
    ctx, g, fb = _armed()
    with pytest.raises(ValueError):
        g.glDrawArrays(G.GL_TRIANGLES, first, count)
    _unchanged(ctx, g, fb)


def test_strided_client_array_length():
    """With a stride, the last element needs only its own bytes: exactly
    stride * (n - 1) + element bytes are enough, one byte fewer is not."""
    ctx, g, fb = _armed()
    stride = 12
    raw = np.zeros(stride * 2 + 8, np.uint8)
    for k in range(3):
        raw[k * stride:k * stride + 8] = encode(TRI[k], G.GL_FLOAT).view(np.uint8)
    g.glVertexPointer(2, G.GL_FLOAT, stride, bytes(raw[:-1]))
    with pytest.raises(ValueError):
        g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    _unchanged(ctx, g, fb)
    g.glVertexPointer(2, G.GL_FLOAT, stride, bytes(raw))
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert g.glGetError() == G.GL_NO_ERROR
    assert_drawn(read(ctx), [TRI], (255, 255, 255, 255), background=(16, 32, 48, 64))


def test_short_colour_array_raises():
    """Every enabled array is checked, not only the vertex array."""
    ctx, g, fb = _armed()
    g.glEnableClientState(G.GL_COLOR_ARRAY)
    g.glColorPointer(4, G.GL_UNSIGNED_BYTE, 0, np.zeros(11, np.uint8))
    with pytest.raises(ValueError):
        g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    _unchanged(ctx, g, fb)
    with pytest.raises(ValueError):
        g.glDrawElements(G.GL_TRIANGLES, 3, G.GL_UNSIGNED_BYTE, np.array([0, 1, 2], np.uint8))
    _unchanged(ctx, g, fb)


@pytest.mark.parametrize("itype", [G.GL_UNSIGNED_BYTE, G.GL_UNSIGNED_SHORT])
def test_index_beyond_arrays(itype):
    """DrawElements with an index past the arrays' ends raises ValueError."""
    ctx, g, fb = _armed()
    with pytest.raises(ValueError):
        g.glDrawElements(G.GL_TRIANGLES, 3, itype, np.array([0, 1, 3], NP_TYPE[itype]))
    _unchanged(ctx, g, fb)


def test_client_index_array_shorter_than_count():
    """A client index array with fewer indices than count raises ValueError."""
    ctx, g, fb = _armed()
    with pytest.raises(ValueError):
        g.glDrawElements(G.GL_TRIANGLES, 3, G.GL_UNSIGNED_SHORT, np.array([0, 1], np.uint16))
    _unchanged(ctx, g, fb)
    with pytest.raises(ValueError):
        g.glDrawElements(G.GL_TRIANGLES, 6, G.GL_UNSIGNED_BYTE, bytes([0, 1, 2, 0, 1]))
    _unchanged(ctx, g, fb)


@pytest.mark.parametrize("offset, count", [(0, 4), (2, 3), (6, 1), (8, 0)])
def test_element_buffer_too_short(offset, count):
    """An element buffer holding fewer bytes than count indices from the offset raises ValueError
    (count 0 draws nothing and reads nothing, so it is fine at any offset inside the buffer)."""
    ctx, g, fb = _armed()
    e = g.glGenBuffers(1)
    g.glBindBuffer(G.GL_ELEMENT_ARRAY_BUFFER, e)
    g.glBufferData(G.GL_ELEMENT_ARRAY_BUFFER, 6, np.array([0, 1, 2], np.uint16), G.GL_STATIC_DRAW)
    if count == 0:
        g.glDrawElements(G.GL_TRIANGLES, 0, G.GL_UNSIGNED_SHORT, offset)
    else:
        with pytest.raises(ValueError):
            g.glDrawElements(G.GL_TRIANGLES, count, G.GL_UNSIGNED_SHORT, offset)
    _unchanged(ctx, g, fb)


def test_vertex_buffer_too_short():
    """An array in a buffer object that ends before the draw's last vertex raises ValueError."""
    ctx, g, fb = _armed()
    b = g.glGenBuffers(1)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, b)
    g.glBufferData(G.GL_ARRAY_BUFFER, 24, encode(TRI, G.GL_FLOAT), G.GL_STATIC_DRAW)
    g.glVertexPointer(2, G.GL_FLOAT, 0, 4)  # 4 bytes in: the third vertex runs 4 bytes past the end
    with pytest.raises(ValueError):
        g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    _unchanged(ctx, g, fb)
    g.glVertexPointer(2, G.GL_FLOAT, 0, 0)
    g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    assert g.glGetError() == G.GL_NO_ERROR


def test_buffer_respecified_smaller_raises():
    """Re-specifying a buffer smaller than its arrays need makes the next draw raise ValueError."""
    ctx, g, fb = _armed()
    b = g.glGenBuffers(1)
    g.glBindBuffer(G.GL_ARRAY_BUFFER, b)
    g.glBufferData(G.GL_ARRAY_BUFFER, 24, encode(TRI, G.GL_FLOAT), G.GL_STATIC_DRAW)
    g.glVertexPointer(2, G.GL_FLOAT, 0, 0)
    g.glBufferData(G.GL_ARRAY_BUFFER, 16, None, G.GL_STATIC_DRAW)
    with pytest.raises(ValueError):
        g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    _unchanged(ctx, g, fb)


def test_int_offset_needs_a_bound_buffer():
    """An int pointer is a buffer offset: without a bound buffer it raises ValueError,
    and the array state is left as it was."""
    ctx, g, fb = _armed()
    before = _state(g, "vertex"), g.glGetPointerv(G.GL_VERTEX_ARRAY_POINTER)
    with pytest.raises(ValueError):
        g.glVertexPointer(3, G.GL_SHORT, 0, 16)
    assert (_state(g, "vertex"), g.glGetPointerv(G.GL_VERTEX_ARRAY_POINTER)) == before
    with pytest.raises(ValueError):
        g.glColorPointer(4, G.GL_UNSIGNED_BYTE, 0, 4)
    with pytest.raises(ValueError):
        g.glDrawElements(G.GL_TRIANGLES, 3, G.GL_UNSIGNED_BYTE, 2)
    _unchanged(ctx, g, fb)


def test_enabled_array_without_pointer_raises():
    """An enabled array that was never given data (a null pointer) raises instead of being read."""
    ctx, g, fb = _armed()
    g.glEnableClientState(G.GL_COLOR_ARRAY)
    with pytest.raises(ValueError):
        g.glDrawArrays(G.GL_TRIANGLES, 0, 3)
    _unchanged(ctx, g, fb)


@pytest.mark.parametrize("cmd, args", [
    ("glVertexPointer", (2, G.GL_FLOAT, 0, np.zeros(6, np.float64))),
    ("glVertexPointer", (2, G.GL_SHORT, 0, np.zeros(6, np.int32))),
    ("glVertexPointer", (3, G.GL_FIXED, 0, np.zeros(9, np.float32))),
    ("glVertexPointer", (2, G.GL_BYTE, 0, np.zeros(6, np.uint8))),
    ("glColorPointer", (4, G.GL_UNSIGNED_BYTE, 0, np.zeros(12, np.int8))),
    ("glColorPointer", (4, G.GL_FLOAT, 0, np.zeros(12, np.int32))),
    ("glNormalPointer", (G.GL_SHORT, 0, np.zeros(9, np.uint16))),
    ("glTexCoordPointer", (2, G.GL_FLOAT, 0, np.zeros(6, np.float16))),
    ("glPointSizePointerOES", (G.GL_FIXED, 0, np.zeros(3, np.int64))),
])
def test_dtype_mismatch_raises_type_error(cmd, args):
    """A numpy array whose dtype is not the type argument's raises TypeError; nothing changes."""
    ctx, g, fb = _armed()
    name = {"glVertexPointer": "vertex", "glColorPointer": "color", "glNormalPointer": "normal",
            "glTexCoordPointer": "texcoord", "glPointSizePointerOES": "pointsize"}[cmd]
    before = _state(g, name)
    with pytest.raises(TypeError):
        getattr(g, cmd)(*args)
    assert _state(g, name) == before
    _unchanged(ctx, g, fb)


@pytest.mark.parametrize("itype, dtype", [(G.GL_UNSIGNED_SHORT, np.uint8), (G.GL_UNSIGNED_BYTE, np.uint16),
                                          (G.GL_UNSIGNED_SHORT, np.int16), (G.GL_UNSIGNED_BYTE, np.int64)])
def test_index_dtype_mismatch_raises_type_error(itype, dtype):
    """DrawElements with an index array of the wrong dtype raises TypeError and draws nothing."""
    ctx, g, fb = _armed()
    with pytest.raises(TypeError):
        g.glDrawElements(G.GL_TRIANGLES, 3, itype, np.array([0, 1, 2], dtype))
    _unchanged(ctx, g, fb)
