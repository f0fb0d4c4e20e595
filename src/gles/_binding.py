"""The only module that imports the compiled cores.

Each numeric build is a separate extension module with the same C API:
gles._core_fixed (16.16), gles._core_float and gles._core_double.
"""

from __future__ import annotations

import importlib
from typing import Any

# the numeric builds, the one list of them in the package
NUMERICS = ("fixed", "float", "double")
_cache: dict[str, Any] = {}


def core(numeric: str) -> Any:
    """Return the cffi module (with .ffi and .lib) of a numeric build."""
    if numeric not in NUMERICS:
        raise ValueError(f"numeric must be one of {NUMERICS}, not {numeric!r}")
    mod = _cache.get(numeric)
    if mod is None:
        mod = importlib.import_module(f"gles._core_{numeric}")
        name = mod.ffi.string(mod.lib.gles_numeric_name()).decode()
        if name != numeric:
            raise ImportError(f"gles._core_{numeric} reports the {name!r} build")
        _cache[numeric] = mod
    return mod
