"""KHR_debug messages in Python: the default callback, which hands every
message to the standard :mod:`logging` module, and the names of the
extension's values.

A context's debug messages go to its callback while DEBUG_OUTPUT_KHR is
enabled (from the start in ``gles.Context(..., debug=True)``, a debug
context; else after ``glEnable(GL_DEBUG_OUTPUT_KHR)``). The callback is
:func:`log_message` until the application sets its own with
``glDebugMessageCallbackKHR(callable, user_param)`` or
``ctx.debug_callback = callable``; ``None`` keeps the messages in the
context's log for ``glGetDebugMessageLogKHR``, as the spec's NULL callback
does. A callback is called as in C, with the message as bytes::

    callback(source, type, id, severity, length, message, user_param)

on the thread that called the command, after the command has returned from
the core and released the context's lock (so the callback may call GL
commands). An exception it raises is re-raised by that command once every
message of the command has been delivered.
"""

from __future__ import annotations

import logging
from typing import Any

from . import constants as C

LOGGER = logging.getLogger("gles.debug")

# the logging level of each severity (Table 5.5)
LEVELS = {
    C.GL_DEBUG_SEVERITY_HIGH_KHR: logging.ERROR,
    C.GL_DEBUG_SEVERITY_MEDIUM_KHR: logging.WARNING,
    C.GL_DEBUG_SEVERITY_LOW_KHR: logging.INFO,
    C.GL_DEBUG_SEVERITY_NOTIFICATION_KHR: logging.DEBUG,
}

SOURCES = {int(v): n for n, v in vars(C).items() if n.startswith("GL_DEBUG_SOURCE_")}
TYPES = {int(v): n for n, v in vars(C).items() if n.startswith("GL_DEBUG_TYPE_")}
SEVERITIES = {int(v): n for n, v in vars(C).items() if n.startswith("GL_DEBUG_SEVERITY_")}


def log_message(source: int, type: int, id: int, severity: int, length: int, message: bytes,
                user_param: Any) -> None:
    """The default debug callback: one record on the "gles.debug" logger, at
    ERROR for HIGH severity, WARNING for MEDIUM, INFO for LOW and DEBUG for
    NOTIFICATION. The record carries the message's fields as attributes
    (gl_source, gl_type, gl_id, gl_severity, gl_message)."""
    level = LEVELS.get(severity, logging.INFO)
    if not LOGGER.isEnabledFor(level):
        return
    text = message.decode("utf-8", "replace")
    LOGGER.log(level, "%s %s 0x%x: %s", SOURCES.get(source, hex(source)), TYPES.get(type, hex(type)), id,
               text, extra={"gl_source": source, "gl_type": type, "gl_id": id, "gl_severity": severity,
                      "gl_message": text})
