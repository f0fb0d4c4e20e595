"""A short, fixed run of the stateful fuzzer (tools/fuzz.py), in this process.

Random call sequences of every command, with edge and invalid values, must
keep the invariant after every call: only GLError/TypeError/ValueError or a
GL error, a valid glGetError code, and a failing call leaves the snapshot of
state unchanged. The longer runs (worker processes, so crashes and hangs are
caught and shrunk) are ``python tools/fuzz.py``.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tools"))

import fuzz  # noqa: E402

SEEDS = range(0, 60)


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
