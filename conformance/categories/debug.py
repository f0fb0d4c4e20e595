"""KHR_debug in an OpenGL ES 1.1 context (extensions/KHR/KHR_debug.txt, its
ES form: KHR-suffixed commands and tokens).

Categories Debug.state, Debug.errors, Debug.log, Debug.labels, Debug.insert
and Debug.vaolabel. Every test clears the callback first, so that messages
go to the message log, which it reads back; the contexts are not debug
contexts, so each turns DEBUG_OUTPUT on itself ("the level of debug output
... is defined by the GL implementation" there: the tests expect the
messages the spec requires of a debug context, which both gles and Mesa
give).
"""

from __future__ import annotations

import numpy as np

from ..harness import TestContext, conformance_test

ONE = 1 << 16


def _start(t: TestContext) -> None:
    gl = t.gl
    t.need_extension("GL_KHR_debug")
    gl.glDebugMessageCallbackKHR(None, None)
    gl.glEnable(gl.GL_DEBUG_OUTPUT_KHR)
    gl.glGetDebugMessageLogKHR(1 << 16, 0, None, None, None, None, None, None)   # an empty log


def _int(t: TestContext, pname: int) -> int:
    return int(np.atleast_1d(t.gl.glGetIntegerv(pname))[0])


def _log(t: TestContext) -> list[tuple[int, int, int, int, bytes]]:
    """The messages in the log, oldest first: (source, type, id, severity, text)."""
    gl = t.gl
    n = max(_int(t, gl.GL_DEBUG_LOGGED_MESSAGES_KHR), 1)
    size = n * _int(t, gl.GL_MAX_DEBUG_MESSAGE_LENGTH_KHR)
    arrays = [np.zeros(n, np.uint32) for _ in range(4)]
    lengths = np.zeros(n, np.int32)
    text = np.zeros(size, np.uint8)
    got = int(gl.glGetDebugMessageLogKHR(n, size, *arrays, lengths, text))
    out, off = [], 0
    for k in range(got):
        out.append((int(arrays[0][k]), int(arrays[1][k]), int(arrays[2][k]), int(arrays[3][k]),
                    text[off:off + lengths[k] - 1].tobytes()))
        off += int(lengths[k])
    return out


def _end(t: TestContext, what: str) -> None:
    """No error left; a cleared window, the same final image at every path level."""
    gl = t.gl
    gl.glClearColorx(0, 0, 0, ONE)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT)
    t.check_gl_error(what)


def _expect_error(t: TestContext, what: str, expected: int) -> None:
    err = t.gl.glGetError()
    if err != expected:
        t.fail(f"{what}: glGetError() is 0x{err:04X}, expected 0x{expected:04X}")


@conformance_test("Debug.state", section="KHR_debug New State")
def debug_state(t: TestContext) -> None:
    """The initial state of a context created without the debug flag (DEBUG_OUTPUT and
    DEBUG_OUTPUT_SYNCHRONOUS FALSE, DEBUG_GROUP_STACK_DEPTH 1, an empty log), the
    implementation limits at or above their minimums in GetIntegerv and GetFixedv, and the
    two enables."""
    gl = t.gl
    t.need_extension("GL_KHR_debug")
    for cap, name in ((gl.GL_DEBUG_OUTPUT_KHR, "DEBUG_OUTPUT"),
                      (gl.GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR, "DEBUG_OUTPUT_SYNCHRONOUS")):
        if gl.glIsEnabled(cap):
            t.fail(f"{name} starts enabled in a context without the debug flag")
        gl.glEnable(cap)
        if not gl.glIsEnabled(cap):
            t.fail(f"glEnable({name}) did not enable it")
        gl.glDisable(cap)
        if gl.glIsEnabled(cap):
            t.fail(f"glDisable({name}) did not disable it")
    initial = ((gl.GL_DEBUG_GROUP_STACK_DEPTH_KHR, "DEBUG_GROUP_STACK_DEPTH", 1),
               (gl.GL_DEBUG_LOGGED_MESSAGES_KHR, "DEBUG_LOGGED_MESSAGES", 0),
               (gl.GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR, "DEBUG_NEXT_LOGGED_MESSAGE_LENGTH", 0))
    for pname, name, want in initial:
        if _int(t, pname) != want:
            t.fail(f"{name} starts at {_int(t, pname)}, not {want}")
    for pname, name, least in ((gl.GL_MAX_DEBUG_MESSAGE_LENGTH_KHR, "MAX_DEBUG_MESSAGE_LENGTH", 1),
                               (gl.GL_MAX_DEBUG_LOGGED_MESSAGES_KHR, "MAX_DEBUG_LOGGED_MESSAGES", 1),
                               (gl.GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR, "MAX_DEBUG_GROUP_STACK_DEPTH", 64),
                               (gl.GL_MAX_LABEL_LENGTH_KHR, "MAX_LABEL_LENGTH", 256)):
        v = _int(t, pname)
        if v < least:
            t.fail(f"{name} is {v}, below the minimum {least}")
        x = int(np.atleast_1d(gl.glGetFixedv(pname))[0])
        if x != min(v * ONE, 2**31 - 1):
            t.fail(f"GetFixedv({name}) is {x}, not {v} * 65536 (§6.1.2)")
    _end(t, "Debug.state")


@conformance_test("Debug.errors", section="KHR_debug Errors")
def debug_errors(t: TestContext) -> None:
    """The errors of DebugMessageControl, DebugMessageInsert, Push/PopDebugGroup and
    GetDebugMessageLog, each also a message of source API and type ERROR with severity
    HIGH; the group stack's overflow at MAX_DEBUG_GROUP_STACK_DEPTH."""
    gl = t.gl
    _start(t)
    a, dc, marker, note = (gl.GL_DEBUG_SOURCE_APPLICATION_KHR, gl.GL_DONT_CARE, gl.GL_DEBUG_TYPE_MARKER_KHR,
                           gl.GL_DEBUG_SEVERITY_NOTIFICATION_KHR)
    longest = _int(t, gl.GL_MAX_DEBUG_MESSAGE_LENGTH_KHR)
    cases = [
        ("Control(source 0x1234)", lambda: gl.glDebugMessageControlKHR(0x1234, dc, dc, 0, None, True),
         gl.GL_INVALID_ENUM),
        ("Control(severity 0x1234)", lambda: gl.glDebugMessageControlKHR(dc, dc, 0x1234, 0, None, True),
         gl.GL_INVALID_ENUM),
        ("Control(count -1)", lambda: gl.glDebugMessageControlKHR(a, marker, dc, -1, None, True),
         gl.GL_INVALID_VALUE),
        ("Control(ids, source DONT_CARE)", lambda: gl.glDebugMessageControlKHR(dc, marker, dc, 1, [1], True),
         gl.GL_INVALID_OPERATION),
        ("Control(ids, a severity)", lambda: gl.glDebugMessageControlKHR(a, marker, note, 1, [1], True),
         gl.GL_INVALID_OPERATION),
        ("Insert(source API)",
         lambda: gl.glDebugMessageInsertKHR(gl.GL_DEBUG_SOURCE_API_KHR, marker, 1, note, -1, "x"),
         gl.GL_INVALID_ENUM),
        ("Insert(severity DONT_CARE)", lambda: gl.glDebugMessageInsertKHR(a, marker, 1, dc, -1, "x"),
         gl.GL_INVALID_ENUM),
        ("Insert(MAX_DEBUG_MESSAGE_LENGTH characters)",
         lambda: gl.glDebugMessageInsertKHR(a, marker, 1, note, -1, "x" * longest), gl.GL_INVALID_VALUE),
        ("PushDebugGroup(source API)", lambda: gl.glPushDebugGroupKHR(gl.GL_DEBUG_SOURCE_API_KHR, 1, -1, "g"),
         gl.GL_INVALID_ENUM),
        ("PopDebugGroup() of the default group", lambda: gl.glPopDebugGroupKHR(), gl.GL_STACK_UNDERFLOW),
        ("GetDebugMessageLog(bufSize -1)",
         lambda: gl.glGetDebugMessageLogKHR(1, -1, None, None, None, None, None, np.zeros(4, np.uint8)),
         gl.GL_INVALID_VALUE),
    ]
    for what, call, expected in cases:
        call()
        _expect_error(t, what, expected)
        msgs = [m for m in _log(t) if m[1] == gl.GL_DEBUG_TYPE_ERROR_KHR]
        if len(msgs) != 1 or (msgs[0][0], msgs[0][3]) != (gl.GL_DEBUG_SOURCE_API_KHR,
                                                          gl.GL_DEBUG_SEVERITY_HIGH_KHR):
            t.fail(f"{what}: the error's messages are {msgs}, not one of source API and severity HIGH")
    depth = _int(t, gl.GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR)
    for i in range(depth - 1):
        gl.glPushDebugGroupKHR(a, i, -1, "g")
    _expect_error(t, f"{depth - 1} pushes", gl.GL_NO_ERROR)
    gl.glPushDebugGroupKHR(a, depth, -1, "g")
    _expect_error(t, "a push onto a full stack", gl.GL_STACK_OVERFLOW)
    if _int(t, gl.GL_DEBUG_GROUP_STACK_DEPTH_KHR) != depth:
        t.fail(f"DEBUG_GROUP_STACK_DEPTH is {_int(t, gl.GL_DEBUG_GROUP_STACK_DEPTH_KHR)}, not {depth}")
    for _ in range(depth - 1):
        gl.glPopDebugGroupKHR()
    _end(t, "Debug.errors")


@conformance_test("Debug.log", section="KHR_debug 5.5.3-5.5.6, 6.1.15")
def debug_log(t: TestContext) -> None:
    """The log: messages oldest first with their source, type, id, severity and text, LOW
    severity initially disabled, the spec's usage example 1 (Message 1, 2, 2, 5: a group's
    control ends with it, the push and pop messages repeat the push's text and id), the
    log's bound MAX_DEBUG_LOGGED_MESSAGES (later messages discarded), and a fetch that
    stops at the first message not fitting bufSize."""
    gl = t.gl
    _start(t)
    a, dc, marker, note = (gl.GL_DEBUG_SOURCE_APPLICATION_KHR, gl.GL_DONT_CARE, gl.GL_DEBUG_TYPE_MARKER_KHR,
                           gl.GL_DEBUG_SEVERITY_NOTIFICATION_KHR)
    gl.glDebugMessageInsertKHR(a, marker, 7, gl.GL_DEBUG_SEVERITY_LOW_KHR, -1, "low")
    gl.glDebugMessageInsertKHR(gl.GL_DEBUG_SOURCE_THIRD_PARTY_KHR, gl.GL_DEBUG_TYPE_OTHER_KHR, 8,
                               gl.GL_DEBUG_SEVERITY_MEDIUM_KHR, 3, "medium")
    got = _log(t)
    want = [(gl.GL_DEBUG_SOURCE_THIRD_PARTY_KHR, gl.GL_DEBUG_TYPE_OTHER_KHR, 8,
             gl.GL_DEBUG_SEVERITY_MEDIUM_KHR, b"med")]
    if got != want:
        t.fail(f"LOW disabled, a MEDIUM message of length 3: the log holds {got}, not {want}")
    gl.glDebugMessageControlKHR(dc, dc, dc, 0, None, True)
    gl.glDebugMessageInsertKHR(a, marker, 100, note, -1, "Message 1")
    gl.glPushDebugGroupKHR(a, 1, -1, "Message 2")
    gl.glDebugMessageControlKHR(dc, dc, dc, 0, None, False)
    gl.glDebugMessageInsertKHR(a, marker, 100, note, -1, "Message 3")
    gl.glPopDebugGroupKHR()
    gl.glDebugMessageInsertKHR(a, marker, 100, note, -1, "Message 5")
    got = _log(t)
    want = [(a, marker, 100, note, b"Message 1"), (a, gl.GL_DEBUG_TYPE_PUSH_GROUP_KHR, 1, note, b"Message 2"),
            (a, gl.GL_DEBUG_TYPE_POP_GROUP_KHR, 1, note, b"Message 2"), (a, marker, 100, note, b"Message 5")]
    if got != want:
        t.fail(f"usage example 1: the log holds {got}, not {want}")
    limit = _int(t, gl.GL_MAX_DEBUG_LOGGED_MESSAGES_KHR)
    for i in range(limit + 3):
        gl.glDebugMessageInsertKHR(a, marker, i, note, -1, f"m{i}")
    if _int(t, gl.GL_DEBUG_LOGGED_MESSAGES_KHR) != limit:
        t.fail(f"DEBUG_LOGGED_MESSAGES is {_int(t, gl.GL_DEBUG_LOGGED_MESSAGES_KHR)} after {limit + 3} "
               f"messages, not MAX_DEBUG_LOGGED_MESSAGES {limit}")
    if _int(t, gl.GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) != 3:
        t.fail("DEBUG_NEXT_LOGGED_MESSAGE_LENGTH is not 3 for the oldest message 'm0'")
    ids = [m[2] for m in _log(t)]
    if ids != list(range(limit)):
        t.fail(f"the log kept ids {ids}, not the first {limit}")
    for text in ("abc", "defgh", "ij"):
        gl.glDebugMessageInsertKHR(a, marker, 1, note, -1, text)
    buf = np.zeros(10, np.uint8)
    lengths = np.zeros(3, np.int32)
    n = int(gl.glGetDebugMessageLogKHR(3, 10, None, None, None, None, lengths, buf))
    if n != 2 or buf.tobytes() != b"abc\0defgh\0" or list(lengths[:2]) != [4, 6]:
        t.fail(f"a fetch into 10 bytes: {n} messages, {buf.tobytes()!r}, lengths {list(lengths[:n])}; "
               f"expected 2, b'abc\\0defgh\\0', [4, 6]")
    if _int(t, gl.GL_DEBUG_LOGGED_MESSAGES_KHR) != 1:
        t.fail("the message that did not fit did not stay in the log")
    _end(t, "Debug.log")


def _bound_objects(t: TestContext) -> list[tuple[int, int, str]]:
    gl = t.gl
    tex = int(np.atleast_1d(gl.glGenTextures(1))[0])
    gl.glBindTexture(gl.GL_TEXTURE_2D, tex)
    buf = int(np.atleast_1d(gl.glGenBuffers(1))[0])
    gl.glBindBuffer(gl.GL_ARRAY_BUFFER, buf)
    out = [(gl.GL_TEXTURE, tex, "TEXTURE"), (gl.GL_BUFFER_KHR, buf, "BUFFER")]
    if t.has_extension("GL_OES_framebuffer_object"):
        fb = int(np.atleast_1d(gl.glGenFramebuffersOES(1))[0])
        gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, fb)
        gl.glBindFramebufferOES(gl.GL_FRAMEBUFFER_OES, 0)
        rb = int(np.atleast_1d(gl.glGenRenderbuffersOES(1))[0])
        gl.glBindRenderbufferOES(gl.GL_RENDERBUFFER_OES, rb)
        out += [(gl.GL_FRAMEBUFFER_OES, fb, "FRAMEBUFFER"), (gl.GL_RENDERBUFFER_OES, rb, "RENDERBUFFER")]
    return out


@conformance_test("Debug.labels", section="KHR_debug 5.5.8, 6.1.16")
def debug_labels(t: TestContext) -> None:
    """Labels of textures, buffers and (with OES_framebuffer_object) framebuffer and
    renderbuffer objects: initially empty, set and read back, cut to bufSize - 1, removed by
    NULL and with the object; INVALID_ENUM for an identifier outside Table 5.1, INVALID_VALUE for a
    name that is no object of the type, and for ObjectPtrLabel (ES 1.1 has no sync objects)."""
    gl = t.gl
    _start(t)
    longest = _int(t, gl.GL_MAX_LABEL_LENGTH_KHR)
    if longest > 4096:
        t.fail(f"MAX_LABEL_LENGTH {longest}: the test reads labels up to 4096 bytes")
    for ident, name, what in _bound_objects(t):
        if gl.glGetObjectLabelKHR(ident, name, 64) != b"":
            t.fail(f"a new {what} object's label is not empty")
        gl.glObjectLabelKHR(ident, name, -1, f"{what} label")
        if gl.glGetObjectLabelKHR(ident, name, 64) != f"{what} label".encode():
            t.fail(f"the {what} object's label reads {gl.glGetObjectLabelKHR(ident, name, 64)!r}")
        if gl.glGetObjectLabelKHR(ident, name, 4) != what[:3].encode():
            t.fail(f"the {what} label with bufSize 4 is not its first 3 characters")
        gl.glObjectLabelKHR(ident, name, -1, "x" * (longest - 1))
        _expect_error(t, f"a {what} label of MAX_LABEL_LENGTH - 1 characters", gl.GL_NO_ERROR)
        if gl.glGetObjectLabelKHR(ident, name, longest + 8) != b"x" * (longest - 1):
            t.fail(f"the {what} object's label of MAX_LABEL_LENGTH - 1 characters does not read back")
        gl.glObjectLabelKHR(ident, name, 0, None)
        if gl.glGetObjectLabelKHR(ident, name, 64) != b"":
            t.fail(f"a NULL label did not remove the {what} object's label")
    tex = int(np.atleast_1d(gl.glGenTextures(1))[0])
    gl.glObjectLabelKHR(gl.GL_TEXTURE, tex, -1, "x")
    _expect_error(t, "a label on a texture name never bound", gl.GL_INVALID_VALUE)
    gl.glBindTexture(gl.GL_TEXTURE_2D, tex)
    gl.glObjectLabelKHR(gl.GL_TEXTURE, tex, -1, "x")
    gl.glDeleteTextures(1, [tex])
    gl.glBindTexture(gl.GL_TEXTURE_2D, tex)
    if gl.glGetObjectLabelKHR(gl.GL_TEXTURE, tex, 8) != b"":
        t.fail("a texture deleted and made again kept its label")
    gl.glObjectLabelKHR(0x1234, tex, -1, "x")
    _expect_error(t, "identifier 0x1234", gl.GL_INVALID_ENUM)
    gl.glObjectLabelKHR(gl.GL_SHADER_KHR, 1, -1, "x")
    _expect_error(t, "a SHADER label (no shaders in ES 1.1)", gl.GL_INVALID_VALUE)
    gl.glObjectPtrLabelKHR(None, -1, "x")
    _expect_error(t, "ObjectPtrLabel (no sync objects)", gl.GL_INVALID_VALUE)
    _end(t, "Debug.labels")


@conformance_test("Debug.labellength", section="KHR_debug 5.5.8, 2.5")
def debug_label_length(t: TestContext) -> None:
    """A label of MAX_LABEL_LENGTH characters is INVALID_VALUE, given with its length or
    terminated, and like every command that records an error (2.5) changes nothing: the
    object keeps its label."""
    gl = t.gl
    _start(t)
    longest = _int(t, gl.GL_MAX_LABEL_LENGTH_KHR)
    tex = int(np.atleast_1d(gl.glGenTextures(1))[0])
    gl.glBindTexture(gl.GL_TEXTURE_2D, tex)
    gl.glObjectLabelKHR(gl.GL_TEXTURE, tex, -1, "kept")
    for length in (-1, longest):
        gl.glObjectLabelKHR(gl.GL_TEXTURE, tex, length, "x" * longest)
        _expect_error(t, f"a label of MAX_LABEL_LENGTH characters, length {length}", gl.GL_INVALID_VALUE)
        if gl.glGetObjectLabelKHR(gl.GL_TEXTURE, tex, 64) != b"kept":
            t.fail(f"a refused label (length {length}) changed the texture's label")
    gl.glDeleteTextures(1, [tex])
    _end(t, "Debug.labellength")


@conformance_test("Debug.insert", section="KHR_debug 5.5.5")
def debug_insert(t: TestContext) -> None:
    """DebugMessageInsert discarded without an error while DEBUG_OUTPUT is off (5.5.5), and
    INVALID_ENUM for the PUSH_GROUP and POP_GROUP types, which New Tokens lists for
    DebugMessageControl and DEBUGPROC only."""
    gl = t.gl
    _start(t)
    a, note = gl.GL_DEBUG_SOURCE_APPLICATION_KHR, gl.GL_DEBUG_SEVERITY_NOTIFICATION_KHR
    for kind in (gl.GL_DEBUG_TYPE_PUSH_GROUP_KHR, gl.GL_DEBUG_TYPE_POP_GROUP_KHR):
        gl.glDebugMessageInsertKHR(a, kind, 1, note, -1, "x")
        _expect_error(t, f"DebugMessageInsert(type 0x{kind:04X})", gl.GL_INVALID_ENUM)
    gl.glDisable(gl.GL_DEBUG_OUTPUT_KHR)
    gl.glDebugMessageInsertKHR(gl.GL_DEBUG_SOURCE_API_KHR, 0x1234, 1, 0x1234, -1, "x")
    _expect_error(t, "DebugMessageInsert with DEBUG_OUTPUT off", gl.GL_NO_ERROR)
    _end(t, "Debug.insert")


@conformance_test("Debug.vaolabel", section="KHR_debug 5.5.8")
def debug_vao_label(t: TestContext) -> None:
    """With OES_vertex_array_object, VERTEX_ARRAY_KHR labels a vertex array object once it
    has been bound (before, its name is no object: INVALID_VALUE)."""
    gl = t.gl
    _start(t)
    t.need_extension("GL_OES_vertex_array_object")
    vao = int(np.atleast_1d(gl.glGenVertexArraysOES(1))[0])
    gl.glObjectLabelKHR(gl.GL_VERTEX_ARRAY_KHR, vao, -1, "x")
    _expect_error(t, "a label on a vertex array name never bound", gl.GL_INVALID_VALUE)
    gl.glBindVertexArrayOES(vao)
    gl.glBindVertexArrayOES(0)
    gl.glObjectLabelKHR(gl.GL_VERTEX_ARRAY_KHR, vao, -1, "mesh")
    _expect_error(t, "a label on a vertex array object", gl.GL_NO_ERROR)
    if gl.glGetObjectLabelKHR(gl.GL_VERTEX_ARRAY_KHR, vao, 16) != b"mesh":
        t.fail("the vertex array object's label does not read back")
    gl.glDeleteVertexArraysOES(1, [vao])
    _end(t, "Debug.vaolabel")
