"""Rebuild the three cores and the C ABI in place for an editable install, atomically.

    python tools/devbuild.py

Builds the core libraries, libGLESv1_CM and libEGL (src/_gles_build/native.py)
into build/native and copies them into src/gles/lib and src/gles/include,
then compiles each cffi module into build/cffi and renames the result over
src/gles/_core_<kind>.abi3.so. Every file is renamed into place, so
processes that have the old libraries loaded keep running on them (a copy
over the open file would not be safe).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src" / "_gles_build"))

import native  # noqa: E402

import build  # noqa: E402


def main() -> None:
    out = native.build()
    native.install(out, ROOT / "src" / "gles")
    print(f"libraries: {ROOT / 'src' / 'gles' / 'lib'}")
    tmp = ROOT / "build" / "cffi"
    for kind in ("fixed", "float", "double"):
        ffi = getattr(build, f"ffi_{kind}")
        built = Path(ffi.compile(tmpdir=str(tmp)))
        dest = ROOT / "src" / "gles" / f"_core_{kind}.abi3.so"
        staged = dest.with_suffix(".new")
        staged.write_bytes(built.read_bytes())
        os.replace(staged, dest)
        print(f"{kind}: {dest}")


if __name__ == "__main__":
    main()
