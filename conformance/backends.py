"""Backends: one thin object per implementation under test.

A backend owns one context of one implementation and exposes what a test
needs and nothing more: ``name``, ``gl`` (the GL commands and GL_* constants,
gles conventions), ``width``, ``height``, ``visual`` (the framebuffer it really
got), ``profile``, ``read_rgba()`` and ``close()``.

* :class:`GlesBackend` wraps a ``gles.Context`` of one numeric build.
* :class:`MesaBackend` wraps a ``gles.mesa.MesaContext`` (EGL and
  libGLESv1_CM through ctypes; nothing is compiled against Mesa). Mesa always
  makes a Common context; with profile "common-lite" its ``gl`` hides the
  Common-only float commands, so a test written for Common-Lite cannot use
  them by accident.
* :class:`LibraryBackend` wraps a ``gles.mesa.LibraryContext``: any EGL +
  GLES 1 library pair by path, driven like Mesa. The ``cabi-*`` backends run
  it on gles's own C ABI (``gles.cabi``: libEGL and libGLESv1_CM of one
  numeric build, the Common or Common-Lite library as the profile asks);
  ``library`` on the pair named by ``GLES_CONFORMANCE_LIBRARY``
  ("/path/libEGL.so.1:/path/libGLESv1_CM.so.1"), a Common library whose
  ``gl`` hides the float commands in Common-Lite runs, as Mesa's does.

:data:`BACKENDS` names every backend the suite knows, each as a
:class:`BackendSpec` that says whether it can run here and makes contexts.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from .harness import VISUALS, Unsupported, Visual

PROFILES = ("common", "common-lite")

# Path states whose fixed-function stage a gles build may lack, and the
# command whose presence in gles.gl.MISSING says so. Dither has no command of
# its own; it belongs to the per-fragment stage that glLogicOp stands for.
_GLES_STAGE_PROBES = {
    "alpha": "glAlphaFuncx",
    "blend": "glBlendFunc",
    "stencil": "glStencilFunc",
    "fog": "glFogx",
    "dither": "glLogicOp",
}


class Backend(Protocol):
    """What the harness and the tests use of a backend."""

    name: str
    gl: Any
    width: int
    height: int
    visual: Visual
    profile: str
    inert_states: dict[str, str]
    notes: list[str]

    def read_rgba(self) -> np.ndarray: ...

    def close(self) -> None: ...


def _read_rgba(gl: Any, width: int, height: int) -> np.ndarray:
    """glReadPixels RGBA/UNSIGNED_BYTE as float (h, w, 4) in [0, 1], bottom row first."""
    px = gl.glReadPixels(0, 0, width, height, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE)
    if px is None:
        raise RuntimeError("glReadPixels(RGBA, UNSIGNED_BYTE) of the whole window failed")
    return np.asarray(px, dtype=np.float64).reshape(height, width, 4) / 255.0


class _GlesNamespace:
    """A gles GL object plus every GL_* constant (as the Mesa namespace has)."""

    def __init__(self, gl: Any) -> None:
        from gles import constants

        self._gl = gl
        self._constants = constants

    def __getattr__(self, name: str) -> Any:
        if name.startswith("GL_"):
            value = getattr(self._constants, name)
        else:
            value = getattr(self._gl, name)
        setattr(self, name, value)  # later look-ups skip __getattr__
        return value


class GlesBackend:
    """A gles.Context of one numeric build ("fixed", "float", "double")."""

    def __init__(self, numeric: str, profile: str, visual: Visual, *, width: int = 64,
                 height: int = 64, debug_flags: int = 0) -> None:
        import gles
        from gles import gl as glmod

        self.name = f"gles-{numeric}"
        self.profile = profile
        self.visual = visual
        self.width, self.height = width, height
        self.context = gles.Context(width, height, profile=profile, numeric=numeric,
                                    color=visual.color, depth=visual.depth, stencil=visual.stencil)
        if debug_flags:
            self.context.debug(debug_flags)
        self.gl: Any = _GlesNamespace(self.context.gl)
        self.notes: list[str] = []
        self.inert_states = {
            state: f"{cmd} is not implemented ({glmod.MISSING[cmd]} stage missing)"
            for state, cmd in _GLES_STAGE_PROBES.items() if cmd in glmod.MISSING
        }

    def read_rgba(self) -> np.ndarray:
        """The window as float RGBA in [0, 1], bottom row first."""
        return _read_rgba(self.gl, self.width, self.height)

    def close(self) -> None:
        """Drop the context."""
        self.gl = None
        self.context = None


class _CommonLiteView:
    """A Mesa GL namespace without the Common-only (float) commands."""

    def __init__(self, gl: Any, hidden: frozenset[str]) -> None:
        self._gl = gl
        self._hidden = hidden

    def __getattr__(self, name: str) -> Any:
        base = name[:-3] if name.endswith("OES") else name
        if name in self._hidden or base in self._hidden:
            raise AttributeError(f"{name} is a Common-profile command; this run is Common-Lite")
        value = getattr(self._gl, name)
        setattr(self, name, value)  # later look-ups skip __getattr__
        return value


class MesaBackend:
    """A Mesa context (llvmpipe or softpipe) on an EGL pbuffer."""

    def __init__(self, driver: str, visual: Visual, *, profile: str = "common", width: int = 64,
                 height: int = 64) -> None:
        from gles import gl as glmod
        from gles import mesa

        self.name = f"mesa-{driver}"
        self.profile = profile
        self.width, self.height = width, height
        if visual.color not in mesa.MESA_COLOR_FORMATS:
            raise Unsupported(f"Mesa's EGL has no {visual.color.upper()} config")
        self.context = mesa.MesaContext(width, height, driver=driver, color=visual.color,
                                        depth=visual.depth, stencil=visual.stencil)
        cfg = self.context.config
        # Tolerances follow the buffer Mesa really made (it has no 16-bit depth
        # with stencil, and gives 24 bits instead).
        self.visual = Visual(visual.color, int(cfg["depth"]), int(cfg["stencil"]))
        self.notes = []
        if (self.visual.depth, self.visual.stencil) != (visual.depth, visual.stencil):
            self.notes.append(f"asked for {visual.name}, EGL gave {self.visual.name}")
        self.inert_states: dict[str, str] = {}
        gl = self.context.gl
        self.gl = gl if profile == "common" else _CommonLiteView(gl, frozenset(glmod.FLOAT_COMMANDS))

    def read_rgba(self) -> np.ndarray:
        """The window as float RGBA in [0, 1], bottom row first."""
        return _read_rgba(self.gl, self.width, self.height)

    def close(self) -> None:
        """Destroy the EGL context and surface."""
        if self.context is not None:
            self.context.close()
        self.context = None
        self.gl = None


class LibraryBackend:
    """A context of an EGL + GLES 1 library pair on an EGL pbuffer."""

    def __init__(self, name: str, egl: str, gles_lib: str, visual: Visual, *, profile: str = "common",
                 hide_float: bool = False, width: int = 64, height: int = 64) -> None:
        from gles import gl as glmod
        from gles import mesa

        self.name = name
        self.profile = profile
        self.width, self.height = width, height
        self.context = mesa.LibraryContext(width, height, egl, gles_lib, color=visual.color,
                                           depth=visual.depth, stencil=visual.stencil)
        cfg = self.context.config
        self.visual = Visual(visual.color, int(cfg["depth"]), int(cfg["stencil"]))
        self.notes = []
        if (self.visual.depth, self.visual.stencil) != (visual.depth, visual.stencil):
            self.notes.append(f"asked for {visual.name}, EGL gave {self.visual.name}")
        self.inert_states: dict[str, str] = {}
        gl = self.context.gl
        self.gl = _CommonLiteView(gl, frozenset(glmod.FLOAT_COMMANDS)) if hide_float else gl

    def read_rgba(self) -> np.ndarray:
        """The window as float RGBA in [0, 1], bottom row first."""
        return _read_rgba(self.gl, self.width, self.height)

    def close(self) -> None:
        """Destroy the EGL context and surface."""
        if self.context is not None:
            self.context.close()
        self.context = None
        self.gl = None


def _library_env() -> tuple[str, str] | None:
    value = os.environ.get("GLES_CONFORMANCE_LIBRARY", "")
    if ":" not in value:
        return None
    egl, gles_lib = value.split(":", 1)
    return egl, gles_lib


@dataclass(frozen=True)
class BackendSpec:
    """A named backend: can it run here, and how to make one of its contexts."""

    name: str
    kind: str                      # "gles" or "mesa"
    variant: str                   # numeric build or Mesa driver
    profiles: tuple[str, ...] = PROFILES
    _reason: Callable[[], str | None] = field(default=lambda: None, compare=False, repr=False)

    def available(self) -> str | None:
        """None if the backend can run here, else why not (one line)."""
        return self._reason()

    def make(self, profile: str, visual: str | Visual, *, width: int = 64, height: int = 64,
             debug_flags: int = 0) -> Backend:
        """A fresh context of this backend."""
        vis = VISUALS[visual] if isinstance(visual, str) else visual
        if self.kind == "gles":
            return GlesBackend(self.variant, profile, vis, width=width, height=height,
                               debug_flags=debug_flags)
        if self.kind == "cabi":
            from gles import cabi

            return LibraryBackend(self.name, str(cabi.library("EGL", self.variant, profile)),
                                  str(cabi.library("GLESv1_CM", self.variant, profile)), vis,
                                  profile=profile, width=width, height=height)
        if self.kind == "library":
            pair = _library_env()
            if pair is None:
                raise RuntimeError("GLES_CONFORMANCE_LIBRARY is not set")
            return LibraryBackend(self.name, pair[0], pair[1], vis, profile=profile,
                                  hide_float=profile == "common-lite", width=width, height=height)
        return MesaBackend(self.variant, vis, profile=profile, width=width, height=height)


def _gles_reason(numeric: str) -> Callable[[], str | None]:
    def reason() -> str | None:
        try:
            from gles import _binding

            _binding.core(numeric)
        except Exception as exc:  # a build that cannot load is a reason, not a crash
            return f"gles {numeric} build unavailable: {type(exc).__name__}: {exc}"
        return None

    return reason


def _mesa_reason(driver: str) -> Callable[[], str | None]:
    def reason() -> str | None:
        try:
            from gles import mesa
        except Exception as exc:
            return f"gles.mesa cannot be imported: {type(exc).__name__}: {exc}"
        why = mesa.available(driver)
        return None if why is None else f"Mesa {driver} unavailable: {why}"

    return reason


def _cabi_reason(numeric: str) -> Callable[[], str | None]:
    def reason() -> str | None:
        try:
            from gles import cabi

            for profile in PROFILES:
                cabi.libdir(numeric, profile)
        except Exception as exc:
            return f"gles C ABI ({numeric}) unavailable: {type(exc).__name__}: {exc}"
        return None

    return reason


def _library_reason() -> str | None:
    pair = _library_env()
    if pair is None:
        return "GLES_CONFORMANCE_LIBRARY is not set (/path/libEGL.so.1:/path/libGLESv1_CM.so.1)"
    missing = [p for p in pair if not os.path.exists(p)]
    return f"no such library: {', '.join(missing)}" if missing else None


BACKENDS: dict[str, BackendSpec] = {
    "gles-fixed": BackendSpec("gles-fixed", "gles", "fixed", _reason=_gles_reason("fixed")),
    "gles-float": BackendSpec("gles-float", "gles", "float", _reason=_gles_reason("float")),
    "gles-double": BackendSpec("gles-double", "gles", "double", _reason=_gles_reason("double")),
    "mesa-llvmpipe": BackendSpec("mesa-llvmpipe", "mesa", "llvmpipe", _reason=_mesa_reason("llvmpipe")),
    "mesa-softpipe": BackendSpec("mesa-softpipe", "mesa", "softpipe", _reason=_mesa_reason("softpipe")),
    "cabi-fixed": BackendSpec("cabi-fixed", "cabi", "fixed", _reason=_cabi_reason("fixed")),
    "cabi-float": BackendSpec("cabi-float", "cabi", "float", _reason=_cabi_reason("float")),
    "cabi-double": BackendSpec("cabi-double", "cabi", "double", _reason=_cabi_reason("double")),
    "library": BackendSpec("library", "library", "env", _reason=_library_reason),
}
