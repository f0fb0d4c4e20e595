"""The two profiles' command sets, and range checks for 16.16 arithmetic.

Common-Lite has only the fixed-point commands (``x`` forms); Common adds the
float commands (``f`` forms). On the fixed core every real a float command
passes becomes a 16.16 value: round to nearest, saturate on overflow. That
conversion loses information in two ways, and this module watches both:

* **Per value.** A real with ``|x| >= 32768`` (or NaN, or an infinity)
  overflows; a nonzero real that rounds to 0 (``|x| <= 2^-17``) underflows.
  Each float command's real arguments are checked before the core sees them;
  FLOAT vertex arrays (positions, normals, colours, texture coordinates, point
  sizes, weights) are checked by the core at each draw over the vertices
  drawn, for overflow (an array value that rounds to 0 is not reported: a
  weight or a normal component below 2^-17 is harmless).
* **Per draw.** McReynolds and Blythe (*Advanced Graphics Programming Using
  OpenGL*, 8.3.2): with ``s`` the largest ``|element|`` of the upper 3x3 of
  P*MV, ``t`` the largest ``|element|`` of its 4th column, and ``c`` the largest
  ``|component|`` of the vertices a draw reads, a pipeline with range
  ``[-X, X]`` stays clear of overflow while ``c*s + t < X/2``; for 16.16,
  ``X/2 = 16384``. The core evaluates the rule in double at each draw from
  the matrices the application built (with OES_matrix_palette, over every
  palette matrix), scanning the drawn vertices of a client array and caching
  the bound of a buffer object's contents.

The policy is the context's ``range_check``:

``"warn"``
    issue a :class:`RangeWarning` naming the call (or the draw, with c, s
    and t) and the margin, and go on; the core saturates. The default for
    ``numeric="fixed"``.
``"raise"``
    raise :class:`RangeError` before the call reaches the core (a draw that
    breaks the rule draws nothing); state is unchanged.
``"clamp"``
    replace each offending real by the nearest value 16.16 keeps apart
    from 0: overflows become +-32767.99998, underflows +-2^-16, NaN 0.
    Draws that break the rule go on (the core saturates). No warnings.
``"off"``
    no checks and no cost. The default for the float and double builds,
    where nothing overflows; turn it on there to see what the fixed build
    would meet.

Every event is counted; ``ctx.range_report()`` returns the counts.
"""

from __future__ import annotations

import inspect
import math
import os
import sys
import warnings
from collections import Counter
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from . import constants as C
from .commands import COMMANDS
from .gl import (
    _PARAM_COUNT,
    _TEX_REAL,
    COMMON_COMMANDS,
    COMMON_LITE_COMMANDS,
    FLOAT_COMMANDS,
    GLCommon,
)

__all__ = [
    "COMMON_COMMANDS", "COMMON_LITE_COMMANDS", "FLOAT_COMMANDS", "POLICIES",
    "RangeError", "RangeEvent", "RangeMonitor", "RangeReport", "RangeWarning",
    "classify", "RULE_LIMIT",
]

POLICIES = ("warn", "raise", "clamp", "off")

OVERFLOW_LIMIT = 32768.0            # |x| >= this overflows
FIXED_MAX = 0x7FFFFFFF / 65536.0    # the largest 16.16 value
FIXED_STEP = 1.0 / 65536.0
UNDERFLOW_LIMIT = 2.0 ** -17        # nonzero x in [-2^-17, 2^-17) rounds to 0
RULE_LIMIT = OVERFLOW_LIMIT / 2     # X/2 of the per-draw rule
MAX_EVENTS = 100                    # events kept in a report (all are counted)


_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))


def _caller_stacklevel() -> int:
    """The stacklevel of the first frame outside this package, so that a
    warning points at the application's line however the call arrived
    (bound, module-level, error-checked)."""
    frame = sys._getframe(1)
    level = 1
    while frame is not None and os.path.dirname(os.path.abspath(frame.f_code.co_filename)) == _PACKAGE_DIR:
        frame = frame.f_back
        level += 1
    return level


class RangeWarning(UserWarning):
    """A value or a draw outside what 16.16 fixed point holds."""


class RangeError(ValueError):
    """Raised under ``range_check="raise"``; the call did nothing."""


def classify(x: float) -> str | None:
    """"overflow", "underflow" or None for one real headed for 16.16."""
    if math.isnan(x) or abs(x) >= OVERFLOW_LIMIT:
        return "overflow"
    if x != 0.0 and -UNDERFLOW_LIMIT <= x < UNDERFLOW_LIMIT:
        return "underflow"
    return None


def _clamped(x: float, kind: str) -> float:
    if math.isnan(x):
        return 0.0
    if kind == "overflow":
        return math.copysign(FIXED_MAX, x)
    return math.copysign(FIXED_STEP, x)


def _margin(x: float, kind: str) -> float:
    """How many times beyond the limit: >= 1 for every event."""
    if math.isnan(x):
        return math.inf
    if kind == "overflow":
        return abs(x) / OVERFLOW_LIMIT
    return UNDERFLOW_LIMIT / abs(x)


def _times(margin: float, side: str = "") -> str:
    """'2.5x' (and `side`) for a margin; an infinite one (an inf or NaN
    value, or a subnormal too small to divide by) has no multiple."""
    if math.isfinite(margin):
        return f"{margin:.3g}x" + (f" {side}" if side else "")
    return f"infinitely {side or 'beyond'}"


@dataclass(frozen=True)
class RangeEvent:
    """One value or draw outside the 16.16 range."""

    kind: str          # "overflow", "underflow" or "rule"
    source: str        # "glFrustumf(far)", "glDrawArrays"
    value: float       # the real, or c*s + t for the rule
    margin: float      # times beyond the limit (>= 1)
    message: str


@dataclass
class RangeReport:
    """What the range checks met so far (``ctx.range_report()``)."""

    policy: str
    counts: dict[str, int]                # per kind
    by_source: dict[str, int]             # per call (and argument) or draw command
    worst: dict[str, float]               # largest margin per kind
    draws_checked: int                    # draws the rule was evaluated for
    draws_breaking_rule: int
    events: list[RangeEvent] = field(default_factory=list)   # the first MAX_EVENTS

    @property
    def total(self) -> int:
        return sum(self.counts.values())

    def __str__(self) -> str:
        lines = [f"range checks ({self.policy}): {self.counts['overflow']} overflow, "
                 f"{self.counts['underflow']} underflow, {self.counts['rule']} draws breaking "
                 f"c*s + t < {RULE_LIMIT:g} of {self.draws_checked} checked"]
        for src, n in sorted(self.by_source.items(), key=lambda kv: -kv[1]):
            lines.append(f"  {n:6d}  {src}")
        return "\n".join(lines)


class RangeMonitor:
    """Counts and acts on range events for one context."""

    def __init__(self, policy: str) -> None:
        self.policy = policy
        self.reset()

    def reset(self) -> None:
        self.counts = {"overflow": 0, "underflow": 0, "rule": 0}
        self.by_source: Counter[str] = Counter()
        self.worst = {"overflow": 0.0, "underflow": 0.0, "rule": 0.0}
        self.events: list[RangeEvent] = []

    def _record(self, event: RangeEvent) -> None:
        self.counts[event.kind] += 1
        self.by_source[event.source] += 1
        if event.margin > self.worst[event.kind]:
            self.worst[event.kind] = event.margin
        if len(self.events) < MAX_EVENTS:
            self.events.append(event)
        if self.policy == "raise":
            raise RangeError(event.message)
        if self.policy == "warn":
            warnings.warn(event.message, RangeWarning, stacklevel=_caller_stacklevel())

    def value(self, call: str, arg: str, x: float, kind: str) -> float:
        """Record one offending real; return what to pass on instead."""
        margin = _margin(x, kind)
        if x != x:
            msg = f"{call}: {arg} is NaN, which 16.16 cannot hold; the fixed core takes it as 0"
        elif kind == "overflow":
            msg = (f"{call}: {arg} = {x:g} is outside 16.16 (|x| >= 32768, {_times(margin)} the limit); "
                   + ("the fixed core saturates it to "
                   + (f"{math.copysign(FIXED_MAX, x):.5f}" if x == x else "0 (NaN)")))
        else:
            msg = (f"{call}: {arg} = {x:g} is nonzero but rounds to 0 in 16.16 "
                   f"(|x| <= 2^-17, {_times(margin, 'below')} the smallest value kept)")
        self._record(RangeEvent(kind, f"{call}({arg})", x, margin, msg))
        return _clamped(x, kind) if self.policy == "clamp" else x

    def draw(self, call: str, rule: tuple[float, float, float, float], arrays: dict[int, float]) -> None:
        """Record a draw the core flagged: `rule` is (c, s, t, c*s + t); `arrays`
        maps the ARR_* index of each FLOAT array holding a drawn value 16.16
        cannot hold to its largest |value|. Under "raise" the first event raises."""
        for index, big in arrays.items():
            source = _ARRAY_SOURCES[index]
            margin = big / OVERFLOW_LIMIT if big == big else math.inf
            msg = (f"{call}: the {_ARRAY_NAMES[index]} array ({source}) holds |x| = {big:g} in the vertices "
                   f"drawn, outside 16.16 ({_times(margin)} the limit); the fixed core saturates it")
            if self.policy == "raise":
                msg += "; nothing was drawn"
            self._record(RangeEvent("overflow", f"{call}: {source}", big, margin, msg))
        lhs = rule[3]
        if not lhs < RULE_LIMIT:
            self.rule(call, *rule)

    def rule(self, call: str, c: float, s: float, t: float, lhs: float) -> None:
        """Record a draw that broke c*s + t < X/2."""
        margin = lhs / RULE_LIMIT if lhs == lhs else math.inf
        msg = (f"{call}: P*MV and the vertex array break the 16.16 overflow rule c*s + t < {RULE_LIMIT:g}: "
               f"c = {c:g} (largest |vertex component|), s = {s:g} (largest |upper 3x3 element| of P*MV), "
               f"t = {t:g} (largest |4th column element|), c*s + t = {lhs:g}, {_times(margin)} the limit")
        if self.policy == "raise":
            msg += "; nothing was drawn"
        self._record(RangeEvent("rule", call, lhs, margin, msg))

    def report(self, draws: tuple[int, int]) -> RangeReport:
        return RangeReport(self.policy, dict(self.counts), dict(self.by_source), dict(self.worst),
                           draws[0], draws[1], list(self.events))


# the core's ARR_* order (state.h)
_ARRAY_SOURCES = ["glVertexPointer", "glNormalPointer", "glColorPointer", "glPointSizePointerOES",
                  "glMatrixIndexPointerOES", "glWeightPointerOES"] + [
                  f"glTexCoordPointer, unit {u}" for u in range(4)]
_ARRAY_NAMES = ["vertex", "normal", "colour", "point size", "matrix index", "weight"] + [
                "texture coordinate"] * 4


# {====================================================================
# which arguments of each float command are reals bound for 16.16

def _all_of(count: int) -> Callable[[tuple], int]:
    return lambda args: count


def _by_pname(table: dict[int, int], pname_at: int, default: int = 1,
              skip: frozenset[int] = frozenset()) -> Callable[[tuple], int]:
    def count(args: tuple) -> int:
        try:
            pname = int(args[pname_at])
        except (TypeError, ValueError, OverflowError, IndexError):
            return 0
        return 0 if pname in skip else table.get(pname, default)
    return count


def _tex_parameter_count(args: tuple) -> int:
    try:
        pname = int(args[1])
    except (TypeError, ValueError, OverflowError, IndexError):
        return 0
    return 1 if pname == C.GL_TEXTURE_MAX_ANISOTROPY_EXT else 0   # the rest are enums and integers


def _tex_env_count(args: tuple) -> int:
    try:
        pname = int(args[1])
    except (TypeError, ValueError, OverflowError, IndexError):
        return 0
    if pname not in _TEX_REAL:
        return 0              # enums (modes, sources, operands) are not 16.16 values
    return 4 if pname == C.GL_TEXTURE_ENV_COLOR else 1


# command -> the argument positions that are real scalars: from the command
# table, every float argument of a command without a pname (those with one
# carry enums for some pnames, below)
_SCALAR_REALS: dict[str, tuple[int, ...]] = {
    cmd.name: tuple(i for i, p in enumerate(cmd.params) if p.kind == "float")
    for cmd in COMMANDS.values()
    if all(p.name != "pname" for p in cmd.params) and any(p.kind == "float" for p in cmd.params)
}

_FOG_ENUM = frozenset({C.GL_FOG_MODE})
_TWO_SIDE = frozenset({C.GL_LIGHT_MODEL_TWO_SIDE})

# command -> (argument position of the values, how many values given the args);
# scalar forms with a pname (glLightf) use the same table with one value
_VECTOR_REALS: dict[str, tuple[int, Callable[[tuple], int]]] = {
    "glLoadMatrixf": (0, _all_of(16)), "glMultMatrixf": (0, _all_of(16)),
    "glClipPlanef": (1, _all_of(4)), "glDrawTexfvOES": (0, _all_of(5)),
    "glLightf": (2, _all_of(1)), "glLightfv": (2, _by_pname(_PARAM_COUNT, 1)),
    "glLightModelf": (1, _by_pname({}, 0, 1, _TWO_SIDE)),
    "glLightModelfv": (1, _by_pname(_PARAM_COUNT, 0, 1, _TWO_SIDE)),
    "glMaterialf": (2, _all_of(1)), "glMaterialfv": (2, _by_pname(_PARAM_COUNT, 1)),
    "glFogf": (1, _by_pname({}, 0, 1, _FOG_ENUM)), "glFogfv": (1, _by_pname(_PARAM_COUNT, 0, 1, _FOG_ENUM)),
    "glTexEnvf": (2, _tex_env_count), "glTexEnvfv": (2, _tex_env_count),
    "glTexParameterf": (2, _tex_parameter_count), "glTexParameterfv": (2, _tex_parameter_count),
    "glPointParameterf": (1, _all_of(1)), "glPointParameterfv": (1, _by_pname(_PARAM_COUNT, 0)),
}

# every float command is checked (glTexParameterf/fv for its one real,
# EXT_texture_filter_anisotropic's TEXTURE_MAX_ANISOTROPY_EXT) but
# OES_texture_cube_map's glTexGenfOES/fvOES, whose one pname takes an enum
# given as a number (NORMAL_MAP_OES is 34065, past 16.16's range but no
# real: unscaled, as glTexEnvf's modes and glFogf's FOG_MODE)
UNCHECKED_FLOAT_COMMANDS: tuple[str, ...] = ("glTexGenfOES", "glTexGenfvOES")
CHECKED_COMMANDS = sorted(set(_SCALAR_REALS) | set(_VECTOR_REALS))


def _arg_names(name: str) -> list[str]:
    params = list(inspect.signature(getattr(GLCommon, name)).parameters)
    return params[1:]   # drop self


def _scalar_checker(name: str, positions: tuple[int, ...]) -> Callable[[RangeMonitor, tuple], tuple]:
    names = _arg_names(name)

    def check(mon: RangeMonitor, args: tuple) -> tuple:
        out = None
        for i in positions:
            if i >= len(args):
                break
            try:
                x = float(args[i])
            except (TypeError, ValueError, OverflowError):
                continue      # the command itself reports the misuse
            kind = classify(x)
            if kind:
                if out is None:
                    out = list(args)
                out[i] = mon.value(name, names[i], x, kind)
        return args if out is None else tuple(out)
    return check


def _vector_checker(name: str, at: int,
                    count: Callable[[tuple], int]) -> Callable[[RangeMonitor, tuple], tuple]:
    arg = _arg_names(name)[at]

    def check(mon: RangeMonitor, args: tuple) -> tuple:
        n = count(args)
        if n == 0 or at >= len(args):
            return args
        head = args[at]
        if type(head) in (list, tuple) and len(head) >= n:
            # a short list of plain numbers, all in range: no array needed
            # (a value at a limit, NaN or anything else takes the full test)
            try:
                for i in range(n):
                    x = head[i]
                    if not (UNDERFLOW_LIMIT < abs(x) < OVERFLOW_LIMIT or not x):
                        break
                else:
                    return args
            except TypeError:
                pass
        try:
            vals = np.asarray(args[at], dtype=np.float64).reshape(-1)
        except (TypeError, ValueError, OverflowError):
            return args
        if vals.size < n:
            return args       # the command raises for a short vector
        head = vals[:n]
        bad = np.isnan(head) | (np.abs(head) >= OVERFLOW_LIMIT) | \
            ((head != 0) & (head >= -UNDERFLOW_LIMIT) & (head < UNDERFLOW_LIMIT))
        if not bad.any():
            return args
        fixed = vals.copy()
        for i in np.flatnonzero(bad):
            x = float(head[i])
            label = f"{arg}[{i}]" if n > 1 else arg
            fixed[i] = mon.value(name, label, x, classify(x) or "overflow")
        out = list(args)
        out[at] = fixed if n > 1 or np.ndim(args[at]) else float(fixed[0])
        return tuple(out)
    return check


_CHECKERS: dict[str, Callable[[RangeMonitor, tuple], tuple]] = {
    **{n: _scalar_checker(n, pos) for n, pos in _SCALAR_REALS.items()},
    **{n: _vector_checker(n, at, cnt) for n, (at, cnt) in _VECTOR_REALS.items()},
}


def _fast_scalar(name: str, fn: Any, positions: tuple[int, ...], slow: Any) -> Any:
    """A command that tests its real arguments inline (a few comparisons per
    value, no calls) and takes the slow path only when one is out of range or
    not a plain number."""
    params = _arg_names(name)
    reals = [params[i] for i in positions]
    cond = " and ".join(f"(_UF < abs({p}) < 32768.0 or not {p})" for p in reals)
    src = (f"def {name}(self, {', '.join(params)}):\n"
           f"    try:\n"
           f"        ok = {cond}\n"
           f"    except TypeError:\n"
           f"        ok = False\n"
           f"    if ok:\n"
           f"        return _fn(self, {', '.join(params)})\n"
           f"    return _slow(self, {', '.join(params)})\n")
    scope: dict[str, Any] = {"_UF": UNDERFLOW_LIMIT, "_fn": fn, "_slow": slow}
    # compiled under this file's name, so warnings skip it on the way to the caller
    exec(compile(src, __file__, "exec"), scope)  # noqa: S102 -- generated from the signature above
    return scope[name]


def ranged_class(base: type) -> type:
    """A subclass of `base` whose float commands check their reals first."""

    def wrap(name: str, fn: Any, check: Callable[[RangeMonitor, tuple], tuple]) -> Any:
        params = inspect.signature(fn)

        def command(self: Any, *args: Any, **kwargs: Any) -> Any:
            if kwargs:
                bound = params.bind(self, *args, **kwargs)
                args = tuple(bound.args[1:])
            return fn(self, *check(self.handle.range, args))

        if name in _SCALAR_REALS:
            command = _fast_scalar(name, fn, _SCALAR_REALS[name], command)
        command.__name__ = name
        command.__qualname__ = f"Ranged{base.__name__}.{name}"
        command.__doc__ = fn.__doc__
        return command

    attrs = {n: wrap(n, getattr(base, n), chk) for n, chk in _CHECKERS.items() if hasattr(base, n)}
    return type(f"Ranged{base.__name__}", (base,), attrs)


RangedGLCommon = ranged_class(GLCommon)
