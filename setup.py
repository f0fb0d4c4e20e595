"""Build glue: setuptools compiles the core three times through cffi.

The numeric builds are listed in src/_gles_build/build.py; everything else
lives in pyproject.toml.
"""

from setuptools import setup

setup(
    cffi_modules=[
        "src/_gles_build/build.py:ffi_fixed",
        "src/_gles_build/build.py:ffi_float",
        "src/_gles_build/build.py:ffi_double",
    ],
)
