"""KHR_debug: debug output and object labels, against the extension's text
(KhronosGroup/OpenGL-Registry extensions/KHR/KHR_debug.txt, its OpenGL ES
form), Mesa's ES-CM 1.1 where it has the extension, and a C program through
the C ABI.

Expected values are the spec's: each error case cites the rule it checks;
message order and filtering follow the worked examples of its "Usage
Examples" section; the limits are its minimums.
"""

from __future__ import annotations

import logging
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import gles
from gles import cabi
from gles import constants as C

A, T, API = C.GL_DEBUG_SOURCE_APPLICATION_KHR, C.GL_DEBUG_SOURCE_THIRD_PARTY_KHR, C.GL_DEBUG_SOURCE_API_KHR
MARKER, OTHER, ERROR = C.GL_DEBUG_TYPE_MARKER_KHR, C.GL_DEBUG_TYPE_OTHER_KHR, C.GL_DEBUG_TYPE_ERROR_KHR
PUSH, POP = C.GL_DEBUG_TYPE_PUSH_GROUP_KHR, C.GL_DEBUG_TYPE_POP_GROUP_KHR
HIGH, MEDIUM, LOW = C.GL_DEBUG_SEVERITY_HIGH_KHR, C.GL_DEBUG_SEVERITY_MEDIUM_KHR, C.GL_DEBUG_SEVERITY_LOW_KHR
NOTE, DC = C.GL_DEBUG_SEVERITY_NOTIFICATION_KHR, C.GL_DONT_CARE
NUMERICS = ("fixed", "float", "double")


def log_context(numeric: str = "fixed", **kw: object) -> gles.Context:
    """A debug context whose messages stay in the log (no callback)."""
    ctx = gles.Context(8, 8, numeric=numeric, debug=True, **kw)
    ctx.debug_callback = None
    return ctx


def fetch(g, count: int = 256) -> list[tuple[int, int, int, int, bytes]]:
    """Every message in the log, oldest first: (source, type, id, severity, text)."""
    n = max(count, 1)
    s, t, i, v = (np.zeros(n, np.uint32) for _ in range(4))
    lengths = np.zeros(n, np.int32)
    log = bytearray(n * 1024)
    got = g.glGetDebugMessageLogKHR(count, len(log), s, t, i, v, lengths, log)
    out, off = [], 0
    for k in range(got):
        text = bytes(log[off:off + lengths[k]])
        assert text.endswith(b"\0")
        out.append((int(s[k]), int(t[k]), int(i[k]), int(v[k]), text[:-1]))
        off += int(lengths[k])
    return out


def insert(g, text: str, id: int = 1, source: int = A, type: int = MARKER, severity: int = NOTE) -> None:
    g.glDebugMessageInsertKHR(source, type, id, severity, -1, text)


# {====================================================================
# state (New State, New Implementation Dependent State)

@pytest.mark.parametrize("numeric", NUMERICS)
def test_initial_state_of_a_non_debug_context(numeric: str) -> None:
    g = gles.Context(8, 8, numeric=numeric).gl
    assert not g.glIsEnabled(C.GL_DEBUG_OUTPUT_KHR)     # "otherwise its FALSE"
    assert not g.glIsEnabled(C.GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR)
    assert g.glGetIntegerv(C.GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 1
    assert g.glGetIntegerv(C.GL_DEBUG_LOGGED_MESSAGES_KHR) == 0
    assert g.glGetIntegerv(C.GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == 0
    assert g.glGetError() == C.GL_NO_ERROR


def test_a_debug_context_starts_with_debug_output() -> None:
    ctx = gles.Context(8, 8, debug=True)
    assert ctx.gl.glIsEnabled(C.GL_DEBUG_OUTPUT_KHR)
    assert ctx.debug_context


@pytest.mark.parametrize("pname,minimum", [
    (C.GL_MAX_DEBUG_MESSAGE_LENGTH_KHR, 1), (C.GL_MAX_DEBUG_LOGGED_MESSAGES_KHR, 1),
    (C.GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR, 64), (C.GL_MAX_LABEL_LENGTH_KHR, 256)])
def test_limits_in_every_get_form(pname: int, minimum: int) -> None:
    g = gles.Context(8, 8, profile="common").gl
    v = g.glGetIntegerv(pname)
    assert v >= minimum
    # §6.1.2: an integer state value converts exactly to float and 16.16, and to TRUE
    assert g.glGetFloatv(pname) == float(v)
    assert g.glGetFixedv(pname) == v * 65536
    assert g.glGetBooleanv(pname)
    assert g.glGetError() == C.GL_NO_ERROR


@pytest.mark.parametrize("cap", [C.GL_DEBUG_OUTPUT_KHR, C.GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR])
def test_enables(cap: int) -> None:
    g = gles.Context(8, 8).gl
    g.glEnable(cap)
    assert g.glIsEnabled(cap) and g.glGetBooleanv(cap) and g.glGetIntegerv(cap) == 1
    g.glDisable(cap)
    assert not g.glIsEnabled(cap) and g.glGetIntegerv(cap) == 0
    assert g.glGetError() == C.GL_NO_ERROR


# {====================================================================
# error rules, each worked from the spec's text

def _max_msg(g) -> int:
    return int(g.glGetIntegerv(C.GL_MAX_DEBUG_MESSAGE_LENGTH_KHR))


# (what, call, expected error); each call runs on a fresh debug context
def _call(name: str):
    """A case's call: gl command `name` with the arguments given."""
    return lambda *args: (lambda g: getattr(g, name)(*args))


ctl, ins = _call("glDebugMessageControlKHR"), _call("glDebugMessageInsertKHR")
push = _call("glPushDebugGroupKHR")
lab, getlab = _call("glObjectLabelKHR"), _call("glGetObjectLabelKHR")


ERROR_CASES = [
    # §5.5.4
    ("control: source not DONT_CARE nor Table 5.3", ctl(0x1234, DC, DC, 0, None, True),
     C.GL_INVALID_ENUM),
    ("control: type not in Table 5.4", ctl(DC, 0x1234, DC, 0, None, True),
     C.GL_INVALID_ENUM),
    ("control: severity not in Table 5.5", ctl(DC, DC, 0x1234, 0, None, True),
     C.GL_INVALID_ENUM),
    ("control: count negative", ctl(A, MARKER, DC, -1, None, True),
     C.GL_INVALID_VALUE),
    ("control: ids with source DONT_CARE", ctl(DC, MARKER, DC, 1, [1], True),
     C.GL_INVALID_OPERATION),
    ("control: ids with type DONT_CARE", ctl(A, DC, DC, 1, [1], True),
     C.GL_INVALID_OPERATION),
    ("control: ids with a severity", ctl(A, MARKER, NOTE, 1, [1], True),
     C.GL_INVALID_OPERATION),
    ("control: ids of one source and type", ctl(A, MARKER, DC, 2, [1, 9], False),
     C.GL_NO_ERROR),
    ("control: push/pop types are controllable", ctl(A, PUSH, DC, 0, None, False),
     C.GL_NO_ERROR),
    # §5.5.5
    ("insert: source API", ins(API, MARKER, 1, NOTE, -1, "x"), C.GL_INVALID_ENUM),
    ("insert: type not in Table 5.4", ins(A, 0x1234, 1, NOTE, -1, "x"),
     C.GL_INVALID_ENUM),
    ("insert: severity DONT_CARE", ins(A, MARKER, 1, DC, -1, "x"),
     C.GL_INVALID_ENUM),
    ("insert: MAX_DEBUG_MESSAGE_LENGTH characters",
     lambda g: g.glDebugMessageInsertKHR(A, MARKER, 1, NOTE, -1, "x" * _max_msg(g)), C.GL_INVALID_VALUE),
    ("insert: the same with its length given",
     lambda g: g.glDebugMessageInsertKHR(T, OTHER, 1, LOW, _max_msg(g), "x" * _max_msg(g)),
     C.GL_INVALID_VALUE),
    ("insert: one character fewer",
     lambda g: g.glDebugMessageInsertKHR(A, MARKER, 1, NOTE, -1, "x" * (_max_msg(g) - 1)),
     C.GL_NO_ERROR),
    # §5.5.6
    ("push: source API", push(API, 1, -1, "g"), C.GL_INVALID_ENUM),
    ("push: message of MAX_DEBUG_MESSAGE_LENGTH",
     lambda g: g.glPushDebugGroupKHR(A, 1, -1, "x" * _max_msg(g)),
     C.GL_INVALID_VALUE),
    ("pop: only the default group", lambda g: g.glPopDebugGroupKHR(), C.GL_STACK_UNDERFLOW),
    # §5.5.8
    ("label: identifier not in Table 5.1", lab(0x1234, 1, -1, "l"), C.GL_INVALID_ENUM),
    ("label: DISPLAY_LIST (compatibility profile only)", lab(0x82E7, 1, -1, "l"),
     C.GL_INVALID_ENUM),
    ("label: PROGRAM_PIPELINE without pipelines", lab(C.GL_PROGRAM_PIPELINE_KHR, 1, -1, "l"),
     C.GL_INVALID_ENUM),
    ("label: a texture name never bound", lab(C.GL_TEXTURE, 5, -1, "l"),
     C.GL_INVALID_VALUE),
    ("label: name 0", lab(C.GL_BUFFER_KHR, 0, -1, "l"), C.GL_INVALID_VALUE),
    ("label: SHADER (ES 1.1 has none)", lab(C.GL_SHADER_KHR, 1, -1, "l"),
     C.GL_INVALID_VALUE),
    ("label: PROGRAM", lab(C.GL_PROGRAM_KHR, 1, -1, "l"), C.GL_INVALID_VALUE),
    ("label: QUERY", lab(C.GL_QUERY_KHR, 1, -1, "l"), C.GL_INVALID_VALUE),
    ("label: SAMPLER", lab(C.GL_SAMPLER_KHR, 1, -1, "l"), C.GL_INVALID_VALUE),
    ("get label: identifier not in Table 5.1", getlab(0x1234, 1, 8), C.GL_INVALID_ENUM),
    ("get label: not an object", getlab(C.GL_RENDERBUFFER_OES, 3, 8), C.GL_INVALID_VALUE),
    ("ptr label: ES 1.1 has no sync objects", lambda g: g.glObjectPtrLabelKHR(object(), -1, "l"),
     C.GL_INVALID_VALUE),
    ("get ptr label: the same", lambda g: g.glGetObjectPtrLabelKHR(None, 8), C.GL_INVALID_VALUE),
    # §6.1.15 (revision 13)
    ("log: bufSize negative with a messageLog",
     lambda g: g.glGetDebugMessageLogKHR(1, -1, None, None, None, None, None, bytearray(8)),
     C.GL_INVALID_VALUE),
    ("log: bufSize negative without one",
     lambda g: g.glGetDebugMessageLogKHR(1, -1, None, None, None, None, None, None), C.GL_NO_ERROR),
    ("get pointer: not a pointer pname", lambda g: g.glGetPointervKHR(0x1234), C.GL_INVALID_ENUM),
]


@pytest.mark.parametrize("what,call,expected", ERROR_CASES, ids=[c[0] for c in ERROR_CASES])
def test_error_rules(what: str, call, expected: int) -> None:
    g = log_context().gl
    call(g)
    assert g.glGetError() == expected
    # each error also raised its message (§2.5), with the error as its ID
    errors = [m for m in fetch(g) if m[1] == ERROR]
    assert [m[2] for m in errors] == ([expected] if expected else [])


def test_insert_while_debug_output_is_off_is_discarded_without_error() -> None:
    # §5.5.5: "calls to DebugMessageInsert are discarded and do not generate an error"
    ctx = gles.Context(8, 8)
    ctx.debug_callback = None
    g = ctx.gl
    g.glDebugMessageInsertKHR(API, 0x1234, 1, 0x1234, -1, "x")
    assert g.glGetError() == C.GL_NO_ERROR
    g.glEnable(C.GL_DEBUG_OUTPUT_KHR)
    assert g.glGetIntegerv(C.GL_DEBUG_LOGGED_MESSAGES_KHR) == 0


def test_group_stack_overflow_at_its_maximum_depth() -> None:
    g = log_context().gl
    depth = g.glGetIntegerv(C.GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR)
    for i in range(depth - 1):
        g.glPushDebugGroupKHR(A, i, -1, f"g{i}")
    assert g.glGetError() == C.GL_NO_ERROR
    assert g.glGetIntegerv(C.GL_DEBUG_GROUP_STACK_DEPTH_KHR) == depth
    g.glPushDebugGroupKHR(A, 99, -1, "one too many")
    assert g.glGetError() == C.GL_STACK_OVERFLOW
    assert g.glGetIntegerv(C.GL_DEBUG_GROUP_STACK_DEPTH_KHR) == depth
    for _ in range(depth - 1):
        g.glPopDebugGroupKHR()
    assert g.glGetError() == C.GL_NO_ERROR
    g.glPopDebugGroupKHR()
    assert g.glGetError() == C.GL_STACK_UNDERFLOW


# {====================================================================
# messages of real GL errors

@pytest.mark.parametrize("numeric", NUMERICS)
def test_messages_of_gl_errors(numeric: str) -> None:
    g = log_context(numeric).gl
    g.glEnable(0x1234)
    g.glTexImage2D(C.GL_TEXTURE_2D, -1, C.GL_RGBA, 1, 1, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, bytes(4))
    g.glPopMatrix()
    msgs = fetch(g)
    assert [m[:4] for m in msgs] == [(API, ERROR, C.GL_INVALID_ENUM, HIGH),
                                     (API, ERROR, C.GL_INVALID_VALUE, HIGH),
                                     (API, ERROR, C.GL_STACK_UNDERFLOW, HIGH)]
    assert msgs[0][4].startswith(b"GL_INVALID_ENUM in glEnable")
    assert msgs[1][4].startswith(b"GL_INVALID_VALUE in glTexImage2D")
    assert msgs[2][4].startswith(b"GL_STACK_UNDERFLOW in glPopMatrix")
    # only the first stays for GetError; every one raised a message
    assert g.glGetError() == C.GL_INVALID_ENUM and g.glGetError() == C.GL_NO_ERROR


def test_reasons_of_the_debug_commands_own_errors() -> None:
    g = log_context().gl
    g.glPushDebugGroupKHR(API, 1, -1, "g")
    g.glObjectLabelKHR(C.GL_TEXTURE, 77, -1, "l")
    texts = [m[4] for m in fetch(g)]
    assert texts == [b"GL_INVALID_ENUM in glPushDebugGroupKHR: source must be APPLICATION or THIRD_PARTY",
                     b"GL_INVALID_VALUE in glObjectLabelKHR: name is not an object of the identifier's type"]


def test_no_messages_while_debug_output_is_off() -> None:
    ctx = gles.Context(8, 8)
    ctx.debug_callback = None
    g = ctx.gl
    g.glEnable(0x1234)
    g.glPushDebugGroupKHR(A, 1, -1, "g")       # the group is pushed, silently
    assert g.glGetIntegerv(C.GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 2
    g.glEnable(C.GL_DEBUG_OUTPUT_KHR)
    assert fetch(g) == []
    g.glEnable(0x1234)
    assert [m[2] for m in fetch(g)] == [C.GL_INVALID_ENUM]


# {====================================================================
# filtering (§5.5.4) and groups (§5.5.6)

def test_low_severity_starts_disabled() -> None:
    g = log_context().gl
    for sev in (HIGH, MEDIUM, LOW, NOTE):
        insert(g, hex(sev), severity=sev)
    assert [m[3] for m in fetch(g)] == [HIGH, MEDIUM, NOTE]
    g.glDebugMessageControlKHR(DC, DC, LOW, 0, None, True)
    insert(g, "low", severity=LOW)
    assert [m[4] for m in fetch(g)] == [b"low"]


def test_control_by_source_type_and_ids() -> None:
    g = log_context().gl
    g.glDebugMessageControlKHR(T, DC, DC, 0, None, False)               # every third-party message
    g.glDebugMessageControlKHR(A, OTHER, DC, 2, [5, 6], False)          # two IDs of one namespace
    insert(g, "t", source=T)
    for i in (4, 5, 6, 7):
        insert(g, f"o{i}", id=i, type=OTHER)
    insert(g, "m5", id=5)                     # another namespace: its own ID 5
    assert [m[4] for m in fetch(g)] == [b"o4", b"o7", b"m5"]
    # a severity control reaches the IDs named too; an ID control sets an ID whole
    g.glDebugMessageControlKHR(A, OTHER, DC, 1, [5], True)
    g.glDebugMessageControlKHR(DC, DC, NOTE, 0, None, False)
    insert(g, "o5n", id=5, type=OTHER)
    insert(g, "o5h", id=5, type=OTHER, severity=HIGH)
    assert [m[4] for m in fetch(g)] == [b"o5h"]


def test_spec_usage_example_1() -> None:
    g = log_context().gl
    g.glDebugMessageControlKHR(DC, DC, DC, 0, None, True)
    insert(g, "Message 1", 100)
    g.glPushDebugGroupKHR(A, 1, -1, "Message 2")
    g.glDebugMessageControlKHR(DC, DC, DC, 0, None, False)
    insert(g, "Message 3", 100)
    g.glPopDebugGroupKHR()
    insert(g, "Message 5", 100)
    msgs = fetch(g)
    # "Expected debug output from the GL implementation: Message 1, Message 2, Message 2, Message 5"
    assert [m[4] for m in msgs] == [b"Message 1", b"Message 2", b"Message 2", b"Message 5"]
    assert [m[1] for m in msgs] == [MARKER, PUSH, POP, MARKER]
    assert msgs[1][:4] == (A, PUSH, 1, NOTE) and msgs[2][:4] == (A, POP, 1, NOTE)


def test_spec_usage_example_2() -> None:
    g = log_context().gl
    g.glDebugMessageControlKHR(DC, DC, DC, 0, None, False)
    g.glDebugMessageControlKHR(T, DC, DC, 0, None, False)
    g.glDebugMessageControlKHR(A, OTHER, DC, 4, [1234, 2345, 3456, 4567], False)
    g.glDebugMessageControlKHR(A, C.GL_DEBUG_TYPE_PORTABILITY_KHR, DC, 4, [1234, 2345, 3456, 4567], False)
    g.glPushDebugGroupKHR(A, 1, -1, "Message 1")
    g.glDebugMessageControlKHR(A, C.GL_DEBUG_TYPE_PERFORMANCE_KHR, DC, 0, None, True)
    g.glDebugMessageControlKHR(A, OTHER, DC, 2, [5678, 6789], False)
    insert(g, "Message 2", 1357, type=C.GL_DEBUG_TYPE_PERFORMANCE_KHR, severity=MEDIUM)
    insert(g, "Message 3", 3579, source=T, type=OTHER, severity=MEDIUM)
    g.glPopDebugGroupKHR()
    # "Expected debug output from the GL implementation: Message 2"
    assert [m[4] for m in fetch(g)] == [b"Message 2"]
    assert g.glGetError() == C.GL_NO_ERROR


def test_a_group_inherits_and_restores_its_parents_filters() -> None:
    g = log_context().gl
    g.glDebugMessageControlKHR(A, OTHER, DC, 1, [7], False)
    g.glPushDebugGroupKHR(T, 2, 5, "outer-ignored")
    insert(g, "hidden", 7, type=OTHER)              # inherited
    g.glDebugMessageControlKHR(A, OTHER, DC, 1, [7], True)
    insert(g, "shown", 7, type=OTHER)
    g.glPopDebugGroupKHR()
    insert(g, "hidden again", 7, type=OTHER)        # the parent's state is back
    msgs = fetch(g)
    assert [m[4] for m in msgs] == [b"outer", b"shown", b"outer"]
    assert [m[:3] for m in (msgs[0], msgs[2])] == [(T, PUSH, 2), (T, POP, 2)]


# {====================================================================
# the log (§5.5.3, §6.1.15)

def test_the_log_is_bounded_and_keeps_the_oldest() -> None:
    g = log_context().gl
    limit = g.glGetIntegerv(C.GL_MAX_DEBUG_LOGGED_MESSAGES_KHR)
    for i in range(limit + 5):
        insert(g, f"m{i}", id=i)
    assert g.glGetIntegerv(C.GL_DEBUG_LOGGED_MESSAGES_KHR) == limit
    # "the string length (including its null terminator) of the oldest message"
    assert g.glGetIntegerv(C.GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == len("m0") + 1
    msgs = fetch(g)
    assert [m[2] for m in msgs] == list(range(limit))
    assert g.glGetIntegerv(C.GL_DEBUG_LOGGED_MESSAGES_KHR) == 0
    assert g.glGetIntegerv(C.GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == 0


def test_fetch_stops_at_a_message_that_does_not_fit() -> None:
    g = log_context().gl
    for text in ("abc", "defgh", "ij"):
        insert(g, text)
    lengths = np.zeros(3, np.int32)
    log = bytearray(10)
    # "abc\0" (4) fits, "defgh\0" (6) fits exactly, "ij\0" does not: it stays
    assert g.glGetDebugMessageLogKHR(3, 10, None, None, None, None, lengths, log) == 2
    assert bytes(log) == b"abc\0defgh\0" and list(lengths[:2]) == [4, 6]
    assert g.glGetIntegerv(C.GL_DEBUG_LOGGED_MESSAGES_KHR) == 1
    # count limits; NULL outputs still remove ("to simply delete up to count messages")
    insert(g, "k")
    assert g.glGetDebugMessageLogKHR(1, 0, None, None, None, None, None, None) == 1
    assert [m[4] for m in fetch(g)] == [b"k"]


def test_message_length_includes_the_terminator_and_length_argument_cuts() -> None:
    g = log_context().gl
    g.glDebugMessageInsertKHR(A, MARKER, 3, NOTE, 4, "abcdef")
    assert g.glGetIntegerv(C.GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == 5
    assert fetch(g) == [(A, MARKER, 3, NOTE, b"abcd")]


# {====================================================================
# labels (§5.5.8, §6.1.16)

def _objects(g) -> dict[int, int]:
    """One object of each labelled type that ES 1.1 with its extensions has."""
    t = g.glGenTextures(1)
    g.glBindTexture(C.GL_TEXTURE_2D, t)
    b = g.glGenBuffers(1)
    g.glBindBuffer(C.GL_ARRAY_BUFFER, b)
    f = g.glGenFramebuffersOES(1)
    g.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, f)
    g.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, 0)
    r = g.glGenRenderbuffersOES(1)
    g.glBindRenderbufferOES(C.GL_RENDERBUFFER_OES, r)
    v = g.glGenVertexArraysOES(1)
    g.glBindVertexArrayOES(v)
    g.glBindVertexArrayOES(0)
    return {C.GL_TEXTURE: t, C.GL_BUFFER_KHR: b, C.GL_FRAMEBUFFER_OES: f, C.GL_RENDERBUFFER_OES: r,
            C.GL_VERTEX_ARRAY_KHR: v}


def test_labels_of_every_object_type() -> None:
    g = log_context().gl
    objs = _objects(g)
    for ident, name in objs.items():
        assert g.glGetObjectLabelKHR(ident, name, 64) == b""        # "initial state ... the empty string"
        g.glObjectLabelKHR(ident, name, -1, f"label {ident:#x}")
    for ident, name in objs.items():
        assert g.glGetObjectLabelKHR(ident, name, 64) == f"label {ident:#x}".encode()
    assert g.glGetError() == C.GL_NO_ERROR


def test_label_lengths_truncation_and_removal() -> None:
    g = log_context().gl
    t = _objects(g)[C.GL_TEXTURE]
    g.glObjectLabelKHR(C.GL_TEXTURE, t, -1, "x" * 255)                   # MAX_LABEL_LENGTH - 1 characters
    assert g.glGetError() == C.GL_NO_ERROR
    g.glObjectLabelKHR(C.GL_TEXTURE, t, -1, "y" * 256)                   # "not less than MAX_LABEL_LENGTH"
    assert g.glGetError() == C.GL_INVALID_VALUE
    assert g.glGetObjectLabelKHR(C.GL_TEXTURE, t, 300) == b"x" * 255     # unchanged
    g.glObjectLabelKHR(C.GL_TEXTURE, t, 3, "albedo")
    assert g.glGetObjectLabelKHR(C.GL_TEXTURE, t, 3) == b"al"            # bufSize counts the terminator
    assert g.glGetObjectLabelKHR(C.GL_TEXTURE, t, 1) == b""
    assert g.glGetObjectLabelKHR(C.GL_TEXTURE, t, 0) == b""
    g.glGetObjectLabelKHR(C.GL_TEXTURE, t, -1)
    assert g.glGetError() == C.GL_INVALID_VALUE                          # OpenGL 4.6 §20.9
    g.glObjectLabelKHR(C.GL_TEXTURE, t, 0, None)                         # "If label is NULL ... removed"
    assert g.glGetObjectLabelKHR(C.GL_TEXTURE, t, 8) == b""
    assert g.glGetError() == C.GL_NO_ERROR


@pytest.mark.parametrize("ident,delete,rebind", [
    (C.GL_TEXTURE, lambda g, n: g.glDeleteTextures([n]), lambda g, n: g.glBindTexture(C.GL_TEXTURE_2D, n)),
    (C.GL_BUFFER_KHR, lambda g, n: g.glDeleteBuffers([n]), lambda g, n: g.glBindBuffer(C.GL_ARRAY_BUFFER, n)),
    (C.GL_FRAMEBUFFER_OES, lambda g, n: g.glDeleteFramebuffersOES([n]),
     lambda g, n: g.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, n)),
    (C.GL_RENDERBUFFER_OES, lambda g, n: g.glDeleteRenderbuffersOES([n]),
     lambda g, n: g.glBindRenderbufferOES(C.GL_RENDERBUFFER_OES, n)),
    (C.GL_VERTEX_ARRAY_KHR, lambda g, n: g.glDeleteVertexArraysOES([n]), None),
])
def test_a_label_goes_with_its_object(ident: int, delete, rebind) -> None:
    g = log_context().gl
    name = _objects(g)[ident]
    g.glObjectLabelKHR(ident, name, -1, "gone")
    delete(g, name)
    g.glGetObjectLabelKHR(ident, name, 8)
    assert g.glGetError() == C.GL_INVALID_VALUE          # no longer an object
    if rebind is not None:
        rebind(g, name)                                  # the same name, a new object
        assert g.glGetObjectLabelKHR(ident, name, 8) == b""
    assert g.glGetError() == C.GL_NO_ERROR


def test_label_length_is_the_length_argument_not_the_terminator() -> None:
    g = log_context().gl
    b = _objects(g)[C.GL_BUFFER_KHR]
    g.glObjectLabelKHR(C.GL_BUFFER_KHR, b, 2, b"ab\0cd")
    assert g.glGetObjectLabelKHR(C.GL_BUFFER_KHR, b, 8) == b"ab"
    g.glObjectLabelKHR(C.GL_BUFFER_KHR, b, -1, b"ab\0cd")               # to the first terminator
    assert g.glGetObjectLabelKHR(C.GL_BUFFER_KHR, b, 8) == b"ab"


# {====================================================================
# the Python routes: logging by default, any callable, the log with None

def test_logging_route_by_default(caplog: pytest.LogCaptureFixture) -> None:
    ctx = gles.Context(8, 8, debug=True)
    g = ctx.gl
    with caplog.at_level(logging.DEBUG, logger="gles.debug"):
        g.glEnable(0x1234)
        insert(g, "marker")
        insert(g, "perf", type=C.GL_DEBUG_TYPE_PERFORMANCE_KHR, severity=MEDIUM)
    records = [r for r in caplog.records if r.name == "gles.debug"]
    assert [r.levelno for r in records] == [logging.ERROR, logging.DEBUG, logging.WARNING]
    assert "GL_INVALID_ENUM in glEnable" in records[0].getMessage()
    assert records[0].gl_id == C.GL_INVALID_ENUM and records[0].gl_severity == HIGH
    assert records[1].gl_message == "marker"
    assert g.glGetPointerv(C.GL_DEBUG_CALLBACK_FUNCTION_KHR) is gles.debug.log_message
    # the log stays empty: the messages went to the callback
    assert g.glGetIntegerv(C.GL_DEBUG_LOGGED_MESSAGES_KHR) == 0


def test_callable_route_and_user_param() -> None:
    ctx = gles.Context(8, 8)
    g = ctx.gl
    seen: list = []
    token = object()
    g.glDebugMessageCallbackKHR(lambda *a: seen.append(a), token)
    assert g.glGetPointervKHR(C.GL_DEBUG_CALLBACK_USER_PARAM_KHR) is token
    g.glEnable(0x1234)                       # debug output is off: nothing
    assert seen == []
    g.glEnable(C.GL_DEBUG_OUTPUT_KHR)
    g.glPushDebugGroupKHR(A, 3, -1, "pass")
    g.glPopDebugGroupKHR()
    assert [a[:6] for a in seen] == [(A, PUSH, 3, NOTE, 4, b"pass"), (A, POP, 3, NOTE, 4, b"pass")]
    assert all(a[6] is token for a in seen)
    # the module-level functions of the current context deliver too
    ctx.make_current()
    from gles import gl
    gl.glEnable(0x1234)
    assert seen[-1][2] == C.GL_INVALID_ENUM


def test_an_exception_in_the_callable_is_raised_by_the_command() -> None:
    ctx = gles.Context(8, 8, debug=True)
    g = ctx.gl
    seen: list = []

    def callback(source, type, id, severity, length, message, user):
        seen.append(message)
        raise KeyError(message)

    ctx.debug_callback = callback
    with pytest.raises(KeyError):
        g.glEnable(0x1234)
    # the command ran; the error is recorded; the core is intact
    assert g.glGetError() == C.GL_INVALID_ENUM
    ctx.debug_callback = None
    g.glEnable(0x1234)
    assert [m[2] for m in fetch(g)] == [C.GL_INVALID_ENUM]
    g.glClearColor(1, 0, 0, 1)
    g.glClear(C.GL_COLOR_BUFFER_BIT)
    assert (ctx.image()[0, 0] == [255, 0, 0, 255]).all()


def test_every_message_is_delivered_before_the_first_exception() -> None:
    ctx = gles.Context(8, 8, debug=True)
    seen: list = []

    def callback(*a):
        seen.append(a[5])
        raise ValueError(a[5])

    ctx.debug_callback = callback
    # two messages waiting in the core's queue (raised past the Python
    # layer), delivered by the next command
    for text in (b"one", b"two"):
        data = ctx._ffi.new("char[]", text)
        ctx._lib.gles_DebugMessageInsertKHR(ctx._ptr, A, MARKER, 1, NOTE, -1, data, -1)
    with pytest.raises(ValueError) as info:
        ctx.gl.glFlush()
    assert seen == [b"one", b"two"]
    assert info.value.args == (b"one",) and "two" in "".join(info.value.__notes__)


def test_a_callable_may_call_gl_commands() -> None:
    ctx = gles.Context(8, 8, debug=True)
    g = ctx.gl
    errors: list = []
    ctx.debug_callback = lambda *a: errors.append(g.glGetError())
    g.glEnable(0x1234)
    assert errors == [C.GL_INVALID_ENUM]


def test_check_errors_and_the_callback_together() -> None:
    ctx = gles.Context(8, 8, debug=True)
    seen: list = []
    ctx.debug_callback = lambda *a: seen.append(a[2])
    ctx.check_errors = True
    with pytest.raises(gles.GLError):
        ctx.gl.glEnable(0x1234)
    assert seen == [C.GL_INVALID_ENUM]


def test_no_per_command_wrappers_while_debug_output_is_off() -> None:
    ctx = gles.Context(8, 8)
    assert not [n for n in vars(ctx.gl) if n.startswith("gl")]
    ctx.gl.glEnable(C.GL_DEBUG_OUTPUT_KHR)
    assert "glDrawArrays" in vars(ctx.gl)
    ctx.gl.glDisable(C.GL_DEBUG_OUTPUT_KHR)
    assert not [n for n in vars(ctx.gl) if n.startswith("gl")]
    ctx.gl.glEnable(C.GL_DEBUG_OUTPUT_KHR)
    ctx.debug_callback = None               # the log: nothing to deliver in Python
    assert not [n for n in vars(ctx.gl) if n.startswith("gl")]


# {====================================================================
# Python-level misuse

@pytest.mark.parametrize("call,exc,word", [
    (lambda g: g.glObjectLabelKHR(C.GL_TEXTURE, 1, -1, 5), TypeError, "label"),
    (lambda g: g.glDebugMessageInsertKHR(A, MARKER, 1, NOTE, -1, ["x"]), TypeError, "buf"),
    (lambda g: g.glPushDebugGroupKHR(A, 1, -1, None), TypeError, "message"),
    (lambda g: g.glDebugMessageInsertKHR(A, MARKER, 1, NOTE, 9, "short"), ValueError, "length"),
    (lambda g: g.glObjectLabelKHR(C.GL_TEXTURE, 1, 2.5, "x"), TypeError, "length"),
    (lambda g: g.glDebugMessageCallbackKHR(42, None), TypeError, "callback"),
    (lambda g: g.glDebugMessageControlKHR(A, MARKER, DC, 3, [1], True), ValueError, "ids"),
    (lambda g: g.glGetDebugMessageLogKHR(4, 0, np.zeros(2, np.uint32)), ValueError, "sources"),
    (lambda g: g.glGetDebugMessageLogKHR(1, 0, None, np.zeros(2, np.int64)), TypeError, "types"),
    (lambda g: g.glGetDebugMessageLogKHR(1, 0, None, None, None, None, [0]), TypeError, "lengths"),
    (lambda g: g.glGetDebugMessageLogKHR(1, 16, None, None, None, None, None, bytearray(4)), ValueError,
     "messageLog"),
    (lambda g: g.glGetDebugMessageLogKHR(-1, 0), ValueError, "count"),
    (lambda g: g.glGetObjectLabelKHR(C.GL_TEXTURE, 1, 2**31), ValueError, "bufSize"),
])
def test_misuse_raises_naming_the_argument(call, exc: type, word: str) -> None:
    g = log_context().gl
    insert(g, "kept")
    with pytest.raises(exc, match=word):
        call(g)
    assert g.glGetError() == C.GL_NO_ERROR
    assert [m[4] for m in fetch(g)] == [b"kept"]          # nothing changed


def test_a_length_past_the_limit_is_the_gl_error_first() -> None:
    g = log_context().gl
    g.glDebugMessageInsertKHR(A, MARKER, 1, NOTE, 5000, "short")      # INVALID_VALUE, not ValueError
    assert g.glGetError() == C.GL_INVALID_VALUE


# {====================================================================
# trace and replay

def test_debug_commands_record_and_replay(tmp_path: Path) -> None:
    def scene(gl, width: int, height: int) -> None:
        gl.glEnable(C.GL_DEBUG_OUTPUT_KHR)
        gl.glDebugMessageCallbackKHR(None, None)
        gl.glPushDebugGroupKHR(A, 1, -1, "frame")
        t = gl.glGenTextures(1)
        gl.glBindTexture(C.GL_TEXTURE_2D, t)
        gl.glObjectLabelKHR(C.GL_TEXTURE, t, -1, "checker")
        gl.glDebugMessageControlKHR(A, MARKER, DC, 2, [1, 2], False)
        gl.glDebugMessageInsertKHR(A, MARKER, 3, NOTE, -1, "marker")
        gl.glGetDebugMessageLogKHR(4, 64, None, None, None, None, np.zeros(4, np.int32), bytearray(64))
        gl.glPopDebugGroupKHR()
        gl.glClearColor(0.25, 0.5, 0.75, 1)
        gl.glClear(C.GL_COLOR_BUFFER_BIT)

    path = tmp_path / "debug.glestrace"
    t = gles.trace(scene, 16, 16, numeric="fixed", path=str(path))
    image = gles.trace.replay(str(path))
    assert (image == t.image).all()


# {====================================================================
# the C ABI: a C program with its callback

CC = shutil.which(os.environ.get("CC", "cc"))
CDIR = Path(__file__).resolve().parent / "c"


@pytest.fixture(scope="module")
def debug_program(tmp_path_factory: pytest.TempPathFactory) -> Path:
    if CC is None:
        pytest.skip("no C compiler")
    out = tmp_path_factory.mktemp("debug") / "debug_output"
    cmd = [CC, "-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", f"-I{cabi.include_dir()}",
           str(CDIR / "debug_output.c"), "-o", str(out), f"-L{cabi.libdir('fixed', 'common')}", "-lGLESv1_CM",
           "-lEGL"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return out


@pytest.mark.parametrize("numeric,profile", [("fixed", "common"), ("float", "common-lite"),
                                             ("double", "common")])
def test_c_program_callback_through_the_c_abi(debug_program: Path, tmp_path: Path, numeric: str,
                                              profile: str) -> None:
    env = {**os.environ, "LD_LIBRARY_PATH": str(cabi.libdir(numeric, profile))}
    proc = subprocess.run([str(debug_program), str(tmp_path / "out.raw")], capture_output=True, text=True,
                          env=env, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "FAIL" not in proc.stdout and proc.stdout.count("ok ") >= 18


def test_c_program_against_mesa(debug_program: Path, tmp_path: Path) -> None:
    """The same program on Mesa's libraries: the same answers but one. Mesa
    hands the callback an inserted message as the application gave it, not
    terminated at `length` ("frame0" with length 5), where §5.5.1 says every
    message has a null-terminated string (docs/conformance.md)."""
    from gles.lab import mesa

    if mesa.available() is not None:
        pytest.skip(mesa.available())
    proc = subprocess.run([str(debug_program), str(tmp_path / "out.raw")], capture_output=True, text=True,
                          env={**os.environ, "LD_LIBRARY_PATH": "", "GALLIUM_DRIVER": "llvmpipe"}, timeout=60)
    failed = [line for line in proc.stdout.splitlines() if line.startswith("FAIL")]
    assert failed == ["FAIL an inserted marker: its id and its first 5 characters"], proc.stdout + proc.stderr
    assert '(id 42, length 5, message "frame0")' in proc.stdout
    assert proc.stdout.count("ok ") >= 17
