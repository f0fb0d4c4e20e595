"""ctx.check_errors: GL errors raised as gles.GLError at the offending call."""

from __future__ import annotations

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import gl


def test_error_raises_with_function_and_code() -> None:
    """A command that records an error raises GLError naming both."""
    ctx = gles.Context(8, 8)
    ctx.check_errors = True
    with pytest.raises(gles.GLError) as info:
        ctx.gl.glDepthFunc(0x1234)
    assert info.value.err == C.GL_INVALID_ENUM
    assert info.value.function == "glDepthFunc"
    assert "GL_INVALID_ENUM" in str(info.value)
    # the error was consumed: nothing is left for glGetError
    assert ctx.gl.glGetError() == C.GL_NO_ERROR


def test_good_calls_and_state_pass_through() -> None:
    """Legal calls behave as without checking, and state set before is kept."""
    ctx = gles.Context(8, 8, profile="common-lite")
    verts = np.array([-1, -1, 1, -1, 0, 1], dtype=np.int32) << 16
    ctx.gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    ctx.gl.glVertexPointer(2, C.GL_FIXED, 0, verts)
    del verts  # the context must keep the array alive across the switch
    ctx.check_errors = True
    ctx.gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    assert ctx.image()[4, 4, 0] == 255
    with pytest.raises(gles.GLError):
        ctx.gl.glStencilOp(0x1234, C.GL_KEEP, C.GL_KEEP)
    ctx.check_errors = False
    ctx.gl.glStencilOp(0x1234, C.GL_KEEP, C.GL_KEEP)
    assert ctx.gl.glGetError() == C.GL_INVALID_ENUM


def test_module_functions_follow_the_switch() -> None:
    """The module-level commands of the current context check too."""
    ctx = gles.Context(8, 8).make_current()
    ctx.check_errors = True
    with pytest.raises(gles.GLError):
        gl.glMatrixMode(0)
    ctx.check_errors = False
    gl.glMatrixMode(0)
    assert gl.glGetError() == C.GL_INVALID_ENUM
