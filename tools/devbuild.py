"""Rebuild the three cores in place for an editable install, atomically.

    python tools/devbuild.py

Compiles each build into build/cffi and renames the result over
src/gles/_core_<kind>.abi3.so, so processes that have the old library loaded
keep running on it (a copy over the open file would not be safe).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src" / "_gles_build"))

import build  # noqa: E402


def main() -> None:
    tmp = ROOT / "build" / "cffi"
    for kind in ("fixed", "float", "double"):
        ffi = getattr(build, f"ffi_{kind}")
        out = Path(ffi.compile(tmpdir=str(tmp)))
        dest = ROOT / "src" / "gles" / f"_core_{kind}.abi3.so"
        staged = dest.with_suffix(".new")
        staged.write_bytes(out.read_bytes())
        os.replace(staged, dest)
        print(f"{kind}: {dest}")


if __name__ == "__main__":
    main()
