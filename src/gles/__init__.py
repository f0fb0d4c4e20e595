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

from . import compare, trace  # noqa: E402  (callable: gles.compare(scene, w, h, ...), gles.trace(...))
from .context import Context  # noqa: E402
from .errors import GLError  # noqa: E402
from .profile import RangeError, RangeWarning  # noqa: E402

__all__ = ["Context", "GLError", "RangeError", "RangeWarning", "compare", "trace", "__version__"]
