"""Python-level misuse: every command, fed wrong Python types and sizes in
each argument, raises only TypeError or ValueError (naming the argument where
one is at fault) or records a GL error, and never changes state when it
raises or errs."""

from __future__ import annotations

import inspect
import math
import warnings
from typing import Any

import numpy as np
import pytest
from test_errors import assert_same, snapshot

import gles
from gles import constants as C
from gles.gl import COMMON_COMMANDS, GLCommon

# arguments that take arrays, sequences or buffers rather than one number
ARRAY_ARGS = {"params", "m", "equation", "coords", "pointer", "pixels", "data", "textures", "buffers",
              "indices", "array"}

# wrong values of every sort: non-numbers, non-integers, ints past every C
# type, non-finite reals, arrays of the wrong dtype, shape or size
WRONG: list[Any] = [
    "projection", None, object(), {"a": 1}, 1j, 1.5, math.nan, math.inf, -math.inf,
    2**31, -(2**31) - 1, 2**32, 2**40, -(2**40), 2**64, -(2**64),
    [], [1, 2], [[1, 2], [3]], ["a", "b"], (1.5,) * 20, b"", b"\x01\x02\x03",
    np.zeros(3, np.complex128), np.array(["a", "b"]), np.zeros((2, 2, 4), np.float32),
    np.zeros(2, np.float64), np.full(20, np.nan, np.float32), np.full(20, 2**40, np.int64),
    np.zeros((4, 4), np.int8)[:, ::2], np.zeros(0, np.uint8), np.float64(np.nan), np.int64(2**40),
    np.uint32(2**32 - 1),
]


# each argument of each command meets these, plus a few of the rest in turn
CORE_WRONG: list[Any] = ["projection", None, 1.5, math.nan, 2**40, np.zeros(2, np.complex128)]
EXTRA_WRONG = [w for w in WRONG if not any(w is c for c in CORE_WRONG)]


def parameters(name: str) -> list[str]:
    return list(inspect.signature(getattr(GLCommon, name)).parameters)[1:]


def baseline(names: list[str]) -> list[Any]:
    """Plausible values: 0 for numbers, a small array for array arguments."""
    return [np.zeros(64, np.uint8) if p in ARRAY_ARGS else 0 for p in names if p != "array"]


def fresh(numeric: str) -> gles.Context:
    return gles.Context(8, 8, numeric=numeric, range_check="raise" if numeric == "fixed" else "off")


def try_call(ctx: gles.Context, name: str, args: list[Any], before: dict[str, Any]) -> dict[str, Any]:
    """Call ctx.gl.name(*args): an exception must be TypeError or ValueError and
    leave state as `before` holds it; so must a GL error. Returns the state now."""
    raised = None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            getattr(ctx.gl, name)(*args)
    except (TypeError, ValueError) as exc:
        raised = exc
    except Exception as exc:  # noqa: BLE001 -- the failure this test looks for
        pytest.fail(f"{name}{tuple(args)!r} raised {type(exc).__name__}: {exc}")
    err = ctx.gl.glGetError()
    if raised is not None:
        assert err == 0, f"{name}{tuple(args)!r} raised and also recorded {err:#x}"
    after = snapshot(ctx)
    if (raised is not None or err) and not same(before, after):
        assert_same(before, after)          # names what changed
    return after


def same(a: dict[str, Any], b: dict[str, Any]) -> bool:
    """Quick equality of two snapshots (NaN equals NaN)."""
    return a.keys() == b.keys() and all(
        np.array_equal(np.asarray(a[k]), np.asarray(b[k]), equal_nan=np.asarray(a[k]).dtype.kind == "f")
        for k in a)


@pytest.mark.parametrize("name", COMMON_COMMANDS)
def test_each_argument_with_each_wrong_value(name: str) -> None:
    names = parameters(name)
    ctx = fresh("fixed")
    state = snapshot(ctx)
    base = baseline(names)
    turn = sum(map(ord, name))
    for i in range(len(base)):
        extra = [EXTRA_WRONG[(turn + 3 * i + k) % len(EXTRA_WRONG)] for k in range(3)]
        for wrong in CORE_WRONG + extra:
            args = list(base)
            args[i] = wrong
            state = try_call(ctx, name, args, state)


@pytest.mark.parametrize("seed", range(4))
def test_random_calls(seed: int) -> None:
    """Random commands with random mixes of good and wrong values, and wrong
    argument counts, on one context whose state builds up."""
    rng = np.random.default_rng(seed)
    ctx = fresh("fixed" if seed % 2 else "float")
    state = snapshot(ctx)
    good = [0, 1, 2, 3, C.GL_TEXTURE_2D, C.GL_RGBA, C.GL_UNSIGNED_BYTE, C.GL_FLOAT, C.GL_ARRAY_BUFFER,
            C.GL_LIGHT0, C.GL_DIFFUSE, C.GL_FRONT_AND_BACK, 65536, 0.5, np.ones(16, np.float32),
            np.ones(64, np.uint8), [1, 2, 3, 4]]
    pool = good + WRONG
    for _ in range(250):
        name = COMMON_COMMANDS[rng.integers(len(COMMON_COMMANDS))]
        n = len([p for p in parameters(name) if p != "array"]) + int(rng.choice([0, 0, 0, 0, -1, 1]))
        args = [pool[rng.integers(len(pool))] for _ in range(max(n, 0))]
        state = try_call(ctx, name, args, state)


# {====================================================================
# the misuse named in the issue, each with its exception

def test_pixels_of_the_wrong_dtype_are_a_type_error() -> None:
    g = fresh("fixed").gl
    with pytest.raises(TypeError, match="glTexImage2D: pixels dtype float32 does not fit GL_UNSIGNED_BYTE"):
        g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 2, 2, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                       np.ones((2, 2, 4), np.float32))
    with pytest.raises(TypeError, match="GL_UNSIGNED_SHORT_5_6_5"):
        g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGB, 2, 2, 0, C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5,
                       np.ones((2, 2), np.float32))
    with pytest.raises(TypeError, match="glTexImage2D: pixels hold float64"):
        g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                       [0.5, 0.5, 0.5, 1.0])
    with pytest.raises(ValueError, match="does not fit uint8"):
        g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, [0, 0, 0, 256])
    # the right dtype, and a list of values converted to it, are taken
    g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGB, 1, 1, 0, C.GL_RGB, C.GL_UNSIGNED_SHORT_5_6_5,
                   np.array([0xF800], np.uint16))
    g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, [1, 2, 3, 4])
    assert g.glGetError() == 0
    with pytest.raises(TypeError, match="glTexSubImage2D: pixels dtype int32"):
        g.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 1, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                          np.ones(4, np.int32))
    with pytest.raises(ValueError, match="reads 16 bytes, the pixel data holds 3"):
        g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 2, 2, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                       np.ones(3, np.uint8))
    assert g.glGetError() == 0


def test_read_pixels_allocates_only_the_inside() -> None:
    ctx = fresh("fixed")
    px = ctx.gl.glReadPixels(0, 0, 100000, 100000, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    assert px.shape == (8, 8, 4) and px.nbytes == 8 * 8 * 4
    assert ctx.gl.glReadPixels(-100000, 4, 100002, 2, C.GL_RGBA, C.GL_UNSIGNED_BYTE).shape == (2, 2, 4)
    with pytest.raises(ValueError, match="glReadPixels: width=4294967296 does not fit GLint"):
        ctx.gl.glReadPixels(0, 0, 2**32, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    assert ctx.gl.glReadPixels(0, 0, -1, 1, C.GL_RGBA, C.GL_UNSIGNED_BYTE) is None
    assert ctx.gl.glGetError() == C.GL_INVALID_VALUE


def test_ints_outside_their_c_type_name_the_argument() -> None:
    g = fresh("fixed").gl
    with pytest.raises(ValueError, match=r"glDrawArrays: count=1099511627776 does not fit GLint"):
        g.glDrawArrays(C.GL_TRIANGLES, 0, 2**40)
    with pytest.raises(ValueError, match=r"glEnable: cap=-1 does not fit GLenum"):
        g.glEnable(-1)
    with pytest.raises(ValueError, match=r"glBindTexture: texture=4294967296 does not fit"):
        g.glBindTexture(C.GL_TEXTURE_2D, 2**32)
    assert g.glGetError() == 0


def test_non_numbers_name_the_argument() -> None:
    g = fresh("fixed").gl
    with pytest.raises(TypeError, match=r"glMatrixMode: mode='projection' is not an integer"):
        g.glMatrixMode("projection")
    with pytest.raises(TypeError, match=r"glTranslatex: y=1.5 is not an integer"):
        g.glTranslatex(0, 1.5, 0)
    with pytest.raises(TypeError, match=r"glClearColor: green='red' is not a number"):
        fresh("float").gl.glClearColor(0, "red", 0, 1)
    assert g.glGetIntegerv(C.GL_MATRIX_MODE) == C.GL_MODELVIEW


def test_infinite_margins_read_as_words() -> None:
    ctx = gles.Context(8, 8, numeric="fixed", range_check="warn")
    with pytest.warns(gles.RangeWarning) as caught:
        ctx.gl.glTranslatef(math.inf, 0, 0)
    text = str(caught[0].message)
    assert "infx" not in text and "infinitely beyond the limit" in text
    with pytest.warns(gles.RangeWarning) as caught:
        ctx.gl.glTranslatef(5e-324, 0, 0)       # 2^-17 / 5e-324 overflows to inf
    text = str(caught[0].message)
    assert "infx" not in text and "infinitely below the smallest value kept" in text
    with pytest.warns(gles.RangeWarning) as caught:
        ctx.gl.glTranslatef(2.0**-20, 0, 0)
    assert "8x below the smallest value kept" in str(caught[0].message)


@pytest.mark.parametrize("bad", [math.nan, math.inf])
def test_nan_is_reported_like_inf(bad: float) -> None:
    ctx = gles.Context(8, 8, numeric="fixed", range_check="warn")
    g = ctx.gl
    with pytest.warns(gles.RangeWarning, match="glTranslatef"):
        g.glTranslatef(bad, 0, 0)
    g.glLoadIdentity()
    verts = np.array([bad, 0, 0, 1, 1, 0, 0, 1, 0], np.float32)
    g.glEnableClientState(C.GL_VERTEX_ARRAY)
    g.glVertexPointer(3, C.GL_FLOAT, 0, verts)
    with pytest.warns(gles.RangeWarning, match="the vertex array"):
        g.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    rep = ctx.range_report()
    assert rep.counts["overflow"] == 2 and rep.counts["rule"] == 1
    with pytest.raises(gles.RangeError):
        gles.Context(8, 8, numeric="fixed", range_check="raise").gl.glClearColor(bad, 0, 0, 1)


@pytest.mark.parametrize("bad", [math.nan, math.inf])
@pytest.mark.parametrize("where", ["buffer vertices", "normals", "colours"])
def test_nan_arrays_are_reported_like_inf(bad: float, where: str) -> None:
    ctx = gles.Context(8, 8, numeric="fixed", range_check="warn")
    g = ctx.gl
    verts = np.array([0, 0, 0, 1, 1, 0, 0, 1, 0], np.float32)
    g.glEnableClientState(C.GL_VERTEX_ARRAY)
    if where == "buffer vertices":
        verts[0] = bad
        g.glBindBuffer(C.GL_ARRAY_BUFFER, g.glGenBuffers(1))
        g.glBufferData(C.GL_ARRAY_BUFFER, verts, C.GL_STATIC_DRAW)
        g.glVertexPointer(3, C.GL_FLOAT, 0, 0)
    else:
        g.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        values = np.zeros(12, np.float32)
        values[1] = bad
        if where == "normals":
            g.glEnableClientState(C.GL_NORMAL_ARRAY)
            g.glNormalPointer(C.GL_FLOAT, 0, values)
        else:
            g.glEnableClientState(C.GL_COLOR_ARRAY)
            g.glColorPointer(4, C.GL_FLOAT, 0, values)
    with pytest.warns(gles.RangeWarning, match="outside 16.16"):
        g.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    counts = ctx.range_report().counts
    assert counts["overflow"] == 1
    assert counts["rule"] == (1 if where == "buffer vertices" else 0)
