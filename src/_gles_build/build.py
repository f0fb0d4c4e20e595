"""cffi build script: one C core, three numeric builds.

Each build compiles csrc/core_all.c as a single translation unit with one of
GLES_NUM_FIXED, GLES_NUM_FLOAT or GLES_NUM_DOUBLE defined, into
gles._core_fixed, gles._core_float and gles._core_double. The cdef is
csrc/gles_core.h itself, less its preprocessor lines.

Environment:
  GLES_CFLAGS   extra compiler flags (the sanitizer build in CI sets
                "-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer")
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from cffi import FFI

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
    # -O3: the fragment chain's span loops (measured: 20-28% fewer instructions
    # per frame than -O2 on the textured scenes). -ffp-contract=off: a compiler
    # targeting a CPU with FMA must not fuse a*b+c, so the float and double
    # builds round the same on every machine.
    opt = [] if any(f.startswith("-O") for f in extra) else ["-O3"]
    ffi.set_source(
        f"gles._core_{kind}",
        f'#define GLES_NUM_{kind.upper()} 1\n#include "gles_core.h"\n#include "core_all.c"\n',
        include_dirs=[str(CSRC)],
        # -fno-wrapv undoes CPython's -fwrapv: signed overflow stays undefined,
        # so the sanitizer build reports it instead of wrapping silently
        extra_compile_args=["-std=c11", "-Wall", "-Wextra", "-fno-wrapv", "-ffp-contract=off", *opt, *extra],
        extra_link_args=[f for f in extra if f.startswith("-fsanitize")],
        depends=sorted(str(p) for p in CSRC.glob("*.[ch]")),
    )
    return ffi


ffi_fixed = _make("fixed")
ffi_float = _make("float")
ffi_double = _make("double")


if __name__ == "__main__":
    for f in (ffi_fixed, ffi_float, ffi_double):
        f.compile(tmpdir=str(ROOT / "build" / "cffi"), verbose=True)
