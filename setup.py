"""Build glue: the core libraries and the C ABI, then the three cffi modules.

build_ext first builds the plain shared libraries (src/_gles_build/native.py:
one core per numeric build, and libGLESv1_CM + libEGL on each) and copies
them into the package (gles/lib, gles/include); the cffi modules, listed in
src/_gles_build/build.py, then link against those cores. Everything else
lives in pyproject.toml.
"""

import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_ext import build_ext

sys.path.insert(0, str(Path(__file__).resolve().parent / "src" / "_gles_build"))

import native  # noqa: E402


class BuildExt(build_ext):
    """Build the shared libraries before the extension modules that link them."""

    def run(self) -> None:
        out = native.build()
        if self.inplace:
            package = Path(__file__).resolve().parent / "src" / "gles"
        else:
            package = Path(self.build_lib) / "gles"
        native.install(out, package)
        super().run()


setup(
    cmdclass={"build_ext": BuildExt},
    cffi_modules=[
        "src/_gles_build/build.py:ffi_fixed",
        "src/_gles_build/build.py:ffi_float",
        "src/_gles_build/build.py:ffi_double",
    ],
)
