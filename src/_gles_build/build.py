"""cffi build script: one C core, three numeric builds.

Each numeric build's core is a plain shared library, lib/libgles_<kind>.so
(csrc/core_all.c as one translation unit with GLES_NUM_FIXED, _FLOAT or
_DOUBLE defined; built by native.py, which also builds the C ABI on it). The
cffi modules gles._core_fixed, _core_float and _core_double are only the
glue: each links against its core library (rpath $ORIGIN/lib), so Python and
C programs run the same compiled core. The cdef is csrc/gles_core.h itself,
less its preprocessor lines.

Environment:
  GLES_CFLAGS   extra compiler flags (the sanitizer build in CI sets
                "-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer")
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from cffi import FFI

try:
    from . import native
except ImportError:     # loaded by path (setup.py's cffi_modules, tools/devbuild.py)
    import native  # type: ignore[no-redef]

ROOT = Path(__file__).resolve().parent.parent.parent
CSRC = ROOT / "csrc"


def _cdef() -> str:
    text = re.sub(r"/\*.*?\*/", "", (CSRC / "gles_core.h").read_text(), flags=re.S)
    keep = []
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("#"):
            # integer #defines become cffi constants; guards and includes go
            if re.match(r"#define\s+GLES_\w+\s+-?\d+", stripped):
                keep.append(stripped)
            continue
        keep.append(line)
    return "\n".join(keep)


def _make(kind: str) -> FFI:
    ffi = FFI()
    ffi.cdef(_cdef())
    extra = os.environ.get("GLES_CFLAGS", "").split()
    # the core's own flags (-O3, -ffp-contract=off: see native.cflags) are
    # those of its library; this module is the call glue only
    ffi.set_source(
        f"gles._core_{kind}",
        '#include "gles_core.h"\n',
        include_dirs=[str(CSRC)],
        libraries=[f"gles_{kind}"],
        library_dirs=[str(native.OUT / "lib")],
        extra_compile_args=["-std=c11", "-Wall", "-Wextra", *extra],
        extra_link_args=["-Wl,-rpath,$ORIGIN/lib", *[f for f in extra if f.startswith("-fsanitize")]],
        depends=[str(CSRC / "gles_core.h"), str(native.OUT / "lib" / native.core_lib_name(kind))],
    )
    return ffi


ffi_fixed = _make("fixed")
ffi_float = _make("float")
ffi_double = _make("double")


if __name__ == "__main__":
    native.build()
    for f in (ffi_fixed, ffi_float, ffi_double):
        f.compile(tmpdir=str(ROOT / "build" / "cffi"), verbose=True)
