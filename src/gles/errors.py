"""Exceptions raised by gles."""

from __future__ import annotations

from .constants import NAMES


class GLError(Exception):
    """A GL error raised at the call that caused it (``ctx.check_errors``).

    Attributes:
        err: the GL error code (e.g. GL_INVALID_ENUM).
        function: the name of the GL function.
        args: the Python arguments it was called with.
    """

    def __init__(self, err: int, function: str, args: tuple = ()) -> None:
        self.err = err
        self.function = function
        self.py_args = args
        name = NAMES.get(int(err), hex(int(err)))
        super().__init__(f"{function}{args!r}: {name}")
