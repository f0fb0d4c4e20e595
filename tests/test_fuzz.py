"""A short, fixed run of the stateful fuzzer (tools/fuzz.py), in this process.

Random call sequences of every command, with edge and invalid values, must
keep the invariant after every call: only GLError/TypeError/ValueError or a
GL error, a valid glGetError code, and a failing call leaves the snapshot of
state unchanged. The longer runs (worker processes, so crashes and hangs are
caught and shrunk) are ``python tools/fuzz.py``.

The same sequences also run through the C ABI (libGLESv1_CM and libEGL,
through the fuzzer's ctypes harness) and on contexts with check_errors=True.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tools"))

import fuzz  # noqa: E402

SEEDS = range(0, 60)
CABI_SEEDS = range(0, 40)
CHECKED_SEEDS = range(0, 30)


def test_every_command_has_a_generator() -> None:
    covered, missing = fuzz.commands_covered()
    assert not missing
    assert len(covered) > 150


def test_sequences_are_reproducible() -> None:
    a = fuzz.make_sequence(7)
    b = fuzz.make_sequence(7)
    assert fuzz.reproduction(*a) == fuzz.reproduction(*b)


@pytest.mark.parametrize("chunk", range(0, len(SEEDS), 20))
def test_fuzz_seed_range(chunk: int) -> None:
    calls = 0
    for seed in SEEDS[chunk:chunk + 20]:
        setup, seq = fuzz.make_sequence(seed)
        try:
            calls += fuzz.run_sequence(setup, seq)
        except fuzz.Failure as f:
            small = seq[: f.index + 1]
            pytest.fail(f"seed {seed}: {f}\n{fuzz.reproduction(setup, small)}")
    assert calls > 0


def test_the_invariant_catches_a_state_change(monkeypatch: pytest.MonkeyPatch) -> None:
    """The checker itself: a command that records an error yet changes state
    (simulated here) breaks the invariant at that call."""
    from gles import constants as C
    from gles import gl

    real = gl.GLCommon.glLineWidth

    def lying(self: gl.GLCommon, width: float) -> None:
        real(self, width)
        self._lib.gles_set_error(self._p, C.GL_INVALID_VALUE)

    monkeypatch.setattr(gl.GLCommon, "glLineWidth", lying)
    setup = fuzz.Setup(4, 4, "common", "fixed", "rgba8888", 16, 8, "off", 1 << 20)
    calls = [fuzz.Call("glFlush", []), fuzz.Call("glLineWidth", [fuzz.Val(3.0, "3.0")])]
    with pytest.raises(fuzz.Failure) as info:
        fuzz.run_sequence(setup, calls)
    assert info.value.index == 1
    assert info.value.kind == "state changed by glLineWidth"


def _run(seeds: range, backend: str) -> int:
    calls = 0
    for seed in seeds:
        setup, seq = fuzz.make_sequence(seed, backend=backend)
        try:
            calls += fuzz.run_sequence(setup, seq)
        except fuzz.Failure as f:
            small = seq[: f.index + 1]
            pytest.fail(f"seed {seed} ({backend}): {f}\n{fuzz.reproduction(setup, small)}")
    return calls


def test_a_seed_makes_the_same_calls_on_every_backend() -> None:
    texts = {b: fuzz.reproduction(*fuzz.make_sequence(11, backend=b)).splitlines() for b in fuzz.BACKENDS}
    calls = {b: [ln for ln in t if ln.startswith("g.")] for b, t in texts.items()}
    assert calls["python"] == calls["checked"]
    # the C ABI's sequence also replaces a few calls by the same ones with NULL pointers
    assert len(calls["cabi"]) == len(calls["python"])
    same = [a == b for a, b in zip(calls["python"], calls["cabi"])]
    assert all(ok or c.startswith("g.null_pointers('gl") for ok, c in zip(same, calls["cabi"]))
    assert sum(same) > 0.8 * len(same)
    assert any("fuzz.CabiContext(" in ln for ln in texts["cabi"])
    assert "ctx.check_errors = True" in texts["checked"]
    assert [fuzz.make_sequence(s, backend="mixed")[0].backend for s in range(3)] == list(fuzz.BACKENDS)


def test_fuzz_seeds_through_the_c_abi() -> None:
    assert _run(CABI_SEEDS, "cabi") > 0


def test_fuzz_seeds_with_check_errors() -> None:
    assert _run(CHECKED_SEEDS, "checked") > 0


def _cabi(**kw: object) -> fuzz.CabiContext:
    args = dict(profile="common", numeric="fixed", color="rgba8888", depth=16, stencil=8)
    args.update(memory_limit=1 << 20, **kw)
    return fuzz.CabiContext(8, 8, **args)  # type: ignore[arg-type]


def test_the_c_abi_harness_refuses_wild_reads() -> None:
    """What a C program must not pass never reaches C: a draw past the end
    of a client array, an int address without a buffer object, image data
    shorter than the image. What it may pass does."""
    from gles import constants as C

    with _cabi() as cc:
        g = cc.gl
        verts = np.zeros(6, np.float32)          # three 2D vertices
        g.glEnableClientState(C.GL_VERTEX_ARRAY)
        g.glVertexPointer(2, C.GL_FLOAT, 0, verts)
        g.glDrawArrays(C.GL_TRIANGLES, 0, 3)
        with pytest.raises(ValueError, match="harness: the draw reads 32 bytes of a 24-byte array"):
            g.glDrawArrays(C.GL_TRIANGLES, 0, 4)
        with pytest.raises(ValueError, match="harness: the draw reads"):
            g.glDrawElements(C.GL_POINTS, 1, C.GL_UNSIGNED_BYTE, np.array([3], np.uint8))
        g.glDrawElements(C.GL_POINTS, 1, C.GL_UNSIGNED_BYTE, np.array([2], np.uint8))
        with pytest.raises(ValueError, match="needs a bound array buffer"):
            g.glVertexPointer(2, C.GL_FLOAT, 0, 4096)
        with pytest.raises(ValueError, match="no pixel buffers"):
            g.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, 4096)
        with pytest.raises(ValueError, match="harness: the image reads 16 bytes"):
            g.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 2, 2, C.GL_RGBA, C.GL_UNSIGNED_BYTE, bytes(15))
        # an int past its C type reaches C as C converts it: here INT_MAX names
        with pytest.raises(ValueError, match="harness: room for 2147483647 names"):
            g.glGenTextures(-(2**31) - 1)
        # indices from a buffer object: the harness knows what the buffer holds
        name = g.glGenBuffers(1)
        g.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, name)
        g.glBufferData(C.GL_ELEMENT_ARRAY_BUFFER, 4, np.array([0, 1, 2, 5], np.uint8), C.GL_STATIC_DRAW)
        g.glDrawElements(C.GL_TRIANGLES, 3, C.GL_UNSIGNED_BYTE, 0)
        with pytest.raises(ValueError, match="harness: the draw reads 48 bytes"):
            g.glDrawElements(C.GL_POINTS, 1, C.GL_UNSIGNED_BYTE, 3)
        assert g.glGetError() == C.GL_NO_ERROR


def test_the_c_abi_snapshot_sees_the_c_context(monkeypatch: pytest.MonkeyPatch) -> None:
    """The checker on the C ABI: a call that records an error yet changes
    state (simulated: the error is set just before a valid glLineWidth)
    breaks the invariant, so the snapshot reads the context the C entry
    points act on."""
    from gles import constants as C

    real = fuzz._guard

    def lying(cc: fuzz.CabiContext, name: str, args: list) -> None:
        real(cc, name, args)
        if name == "glLineWidthx":
            cc.view.lib.gles_set_error(cc.view.p, C.GL_INVALID_VALUE)

    monkeypatch.setattr(fuzz, "_guard", lying)
    setup = fuzz.Setup(4, 4, "common-lite", "float", "rgb565", 0, 0, "off", 1 << 20, backend="cabi")
    calls = [fuzz.Call("glFlush", []), fuzz.Call("glLineWidthx", [fuzz.Val(3 << 16, "196608")])]
    with pytest.raises(fuzz.Failure) as info:
        fuzz.run_sequence(setup, calls)
    assert info.value.index == 1
    assert info.value.kind == "state changed by glLineWidthx"


def test_the_checked_invariant_catches_an_error_not_raised(monkeypatch: pytest.MonkeyPatch) -> None:
    """With check_errors=True every GL error must raise GLError at its call:
    a command that records one silently (simulated) breaks the invariant."""
    from gles import constants as C
    from gles import context

    checked = context._GL_CLASSES[("common", False, True)]

    def silent(self: object) -> None:
        self._lib.gles_set_error(self._p, C.GL_INVALID_OPERATION)  # type: ignore[attr-defined]

    monkeypatch.setattr(checked, "glFlush", silent)
    setup = fuzz.Setup(4, 4, "common", "double", "rgba8888", 0, 0, "off", 1 << 20, backend="checked")
    calls = [fuzz.Call("glLineWidth", [fuzz.Val(-1.0, "-1.0")]), fuzz.Call("glFlush", [])]
    with pytest.raises(fuzz.Failure) as info:
        fuzz.run_sequence(setup, calls)
    assert info.value.index == 1
    assert info.value.kind == "error not raised by glFlush"
