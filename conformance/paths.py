"""Path levels: harmless state turned on before a test runs.

The Khronos harness re-runs every test with state enabled whose values, by
the spec, change nothing: a test that passes at level 0 must pass at every
level, and leave the same pixels. Levels are cumulative:

    level 0  nothing
    level 1  dither on (§4.1.8); scissor test on, box = the window (§4.1.2)
    level 2  alpha test on, ALWAYS (§4.1.4); blending on, ONE/ZERO (§4.1.7)
    level 3  depth test on, ALWAYS (§4.1.6); stencil test on, ALWAYS with
             KEEP/KEEP/KEEP (§4.1.5)
    level 4  fog on, LINEAR from 16384 to 32767 (§3.8): f = 1 for every eye
             distance below 16384, so fog has no effect

A state is left alone when the test's ``uses`` names it ("nodither" for
dither): the test sets it itself. A state a backend cannot set (a command
raising NotImplementedError) or whose stage the backend declares missing
(``backend.inert_states``) is recorded as not applied: such a run proves
nothing about that state.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

from .harness import Failure

MAX_LEVEL = 4

FOG_START = 16384
FOG_END = 32767


@dataclass(frozen=True)
class PathState:
    """One harmless state of a path level."""

    key: str
    level: int
    description: str
    skip_tag: str                              # the `uses` tag that leaves it to the test
    cap: str                                   # the glEnable capability (GL_* name)
    setup: Callable[[Any, int, int], None]     # (gl, width, height): set the harmless values
    default_is_harmless: bool                  # enabling with the initial values changes nothing


def _dither(gl: Any, w: int, h: int) -> None:
    pass


def _scissor(gl: Any, w: int, h: int) -> None:
    gl.glScissor(0, 0, w, h)


def _alpha(gl: Any, w: int, h: int) -> None:
    gl.glAlphaFuncx(gl.GL_ALWAYS, 0)


def _blend(gl: Any, w: int, h: int) -> None:
    gl.glBlendFunc(gl.GL_ONE, gl.GL_ZERO)


def _depth(gl: Any, w: int, h: int) -> None:
    gl.glDepthFunc(gl.GL_ALWAYS)


def _stencil(gl: Any, w: int, h: int) -> None:
    gl.glStencilFunc(gl.GL_ALWAYS, 0, 0xFF)
    gl.glStencilOp(gl.GL_KEEP, gl.GL_KEEP, gl.GL_KEEP)


def _fog(gl: Any, w: int, h: int) -> None:
    gl.glFogx(gl.GL_FOG_MODE, gl.GL_LINEAR)
    gl.glFogx(gl.GL_FOG_START, FOG_START << 16)
    gl.glFogx(gl.GL_FOG_END, FOG_END << 16)
    # a colour that would show if fog were applied at all
    gl.glFogxv(gl.GL_FOG_COLOR, [1 << 16, 0, 1 << 16, 1 << 16])


STATES: tuple[PathState, ...] = (
    PathState("dither", 1, "dither on", "nodither", "GL_DITHER", _dither, True),
    PathState("scissor", 1, "scissor test on, box = the window", "scissor", "GL_SCISSOR_TEST",
              _scissor, False),
    PathState("alpha", 2, "alpha test on, ALWAYS", "alpha", "GL_ALPHA_TEST", _alpha, True),
    PathState("blend", 2, "blending on, ONE/ZERO", "blend", "GL_BLEND", _blend, True),
    PathState("depth", 3, "depth test on, ALWAYS", "depth", "GL_DEPTH_TEST", _depth, False),
    PathState("stencil", 3, "stencil test on, ALWAYS/KEEP", "stencil", "GL_STENCIL_TEST", _stencil, True),
    PathState("fog", 4, f"fog on, LINEAR {FOG_START}..{FOG_END} (no effect)", "fog", "GL_FOG", _fog, False),
)


class PathError(Failure):
    """A backend recorded a GL error while a path state was set (legal calls)."""


@dataclass
class PathReport:
    """What a path level did on one backend for one test."""

    level: int
    applied: list[str] = field(default_factory=list)
    left_to_test: list[str] = field(default_factory=list)
    unapplied: dict[str, str] = field(default_factory=dict)


def states_for(level: int) -> list[PathState]:
    """The states path `level` turns on."""
    if not 0 <= level <= MAX_LEVEL:
        raise ValueError(f"path level must be in 0..{MAX_LEVEL}, not {level}")
    return [s for s in STATES if s.level <= level]


def apply_path(backend: Any, level: int, uses: Iterable[str]) -> PathReport:
    """Turn on the harmless state of `level` on `backend` (fresh context)."""
    gl = backend.gl
    uses = set(uses)
    report = PathReport(level)
    inert: dict[str, str] = getattr(backend, "inert_states", {})
    for st in states_for(level):
        if st.skip_tag in uses:
            report.left_to_test.append(st.key)
            continue
        cap = getattr(gl, st.cap)
        try:
            if st.default_is_harmless:
                gl.glEnable(cap)
                st.setup(gl, backend.width, backend.height)
            else:
                st.setup(gl, backend.width, backend.height)
                gl.glEnable(cap)
        except NotImplementedError as exc:
            report.unapplied[st.key] = str(exc)
            continue
        err = gl.glGetError()
        if err:
            raise PathError(f"path level {level}, {st.description}: glGetError() is 0x{err:04X} "
                            "after legal calls")
        if st.key in inert:
            report.unapplied[st.key] = inert[st.key]
        else:
            report.applied.append(st.key)
    return report


def parse_levels(text: str) -> list[int]:
    """'2' -> [2]; '0-4' -> [0..4]; '0,4' -> [0, 4]; 'all' -> every level."""
    if text.strip() == "all":
        return list(range(MAX_LEVEL + 1))
    levels: set[int] = set()
    for part in text.split(","):
        part = part.strip()
        if "-" in part:
            lo, hi = (int(p) for p in part.split("-", 1))
            levels.update(range(lo, hi + 1))
        else:
            levels.add(int(part))
    bad = [lv for lv in levels if not 0 <= lv <= MAX_LEVEL]
    if bad or not levels:
        raise ValueError(f"path levels must be in 0..{MAX_LEVEL}: {text!r}")
    return sorted(levels)
