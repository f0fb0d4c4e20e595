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

from .context import Context
from .errors import GLError

__version__ = "0.1.0"
__all__ = ["Context", "GLError", "__version__"]
