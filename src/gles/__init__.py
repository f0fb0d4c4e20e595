"""gles: OpenGL ES 1.1 (Common and Common-Lite) in software.

A 16.16 fixed-point renderer in C with float and double builds of the same
code, for Python: numpy in and out, PyOpenGL-style names, PNG output.

    import gles
    from gles import gl
    ctx = gles.Context(256, 256, numeric="fixed")
    ctx.make_current()
    gl.glClearColorx(0, 0, 0, 65536)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT)
    ctx.save("out.png")
"""

from __future__ import annotations

__version__ = "0.1.0"

from typing import Any  # noqa: E402

from .context import Context  # noqa: E402
from .errors import GLError  # noqa: E402
from .profile import RangeError, RangeWarning  # noqa: E402

__all__ = ["Context", "GLError", "RangeError", "RangeWarning", "compare", "trace", "__version__"]

# the evaluation lab (gles.lab) and the trace and target tools under their
# public names, imported on first use so that the product does not load them
# (callable modules: gles.compare(scene, w, h, ...), gles.trace(scene, ...))
_LAB_MODULES = ("compare", "report", "gallery", "hardcases", "mesa", "trace", "target")


def __getattr__(name: str) -> Any:
    if name in _LAB_MODULES:
        import importlib

        return importlib.import_module(f"{__name__}.{name}")    # callable: gles.compare(scene, w, h, ...)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
