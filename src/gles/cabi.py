"""Where the C ABI's libraries are: libGLESv1_CM and libEGL for C programs.

Each numeric build has one compiled core, ``gles/lib/libgles_<numeric>.so``,
which the Python binding uses too. Beside it, per build and profile, a
directory holds ``libGLESv1_CM.so.1`` and ``libEGL.so.1`` (and ``.so`` copies
for the link editor) made on that core, and the pkg-config files
``glesv1_cm.pc`` and ``egl.pc``::

    cc app.c -L"$(python -m gles libdir)" -lGLESv1_CM -lEGL
    LD_LIBRARY_PATH="$(python -m gles libdir)" ./app

The Khronos headers the libraries were built with are in :func:`include_dir`.
"""

from __future__ import annotations

from pathlib import Path

NUMERICS = ("fixed", "float", "double")
PROFILES = ("common", "common-lite")

_PACKAGE = Path(__file__).resolve().parent


def libdir(numeric: str = "fixed", profile: str = "common") -> Path:
    """The directory of libGLESv1_CM and libEGL for one numeric build and profile.

    Raises ValueError for an unknown build or profile and FileNotFoundError
    when this installation has no such libraries.
    """
    if numeric not in NUMERICS:
        raise ValueError(f"numeric must be one of {NUMERICS}, not {numeric!r}")
    if profile not in PROFILES:
        raise ValueError(f"profile must be one of {PROFILES}, not {profile!r}")
    path = _PACKAGE / "lib" / numeric / profile
    if not (path / "libGLESv1_CM.so.1").is_file() or not (path / "libEGL.so.1").is_file():
        raise FileNotFoundError(f"no libGLESv1_CM/libEGL in {path}: this installation was built without them")
    return path


def include_dir() -> Path:
    """The directory holding the Khronos headers GLES/gl.h, GLES/glext.h, EGL/egl.h ..."""
    path = _PACKAGE / "include"
    if not (path / "GLES" / "gl.h").is_file():
        raise FileNotFoundError(f"no Khronos headers in {path}")
    return path


def library(name: str, numeric: str = "fixed", profile: str = "common") -> Path:
    """The path of ``libGLESv1_CM.so.1`` (name "GLESv1_CM") or ``libEGL.so.1`` ("EGL")."""
    if name not in ("GLESv1_CM", "EGL"):
        raise ValueError(f"name must be 'GLESv1_CM' or 'EGL', not {name!r}")
    return libdir(numeric, profile) / f"lib{name}.so.1"
