"""The Mesa peer: an independent OpenGL ES 1.1 implementation reached through EGL.

Mesa's software rasterizers (``llvmpipe`` and ``softpipe``) run OpenGL ES-CM 1.1
through libEGL.so.1 and libGLESv1_CM.so.1. This module drives them with ctypes
only, offscreen (EGL platform "surfaceless", a pbuffer surface), and exposes the
GL through the same Python conventions as ``gles`` itself, so that one scene
function runs on both::

    from gles import mesa
    if mesa.available() is None:
        with mesa.MesaContext(64, 64) as ctx:
            gl = ctx.gl
            gl.glClearColorx(0, 0, 0, 65536)
            gl.glClear(gl.GL_COLOR_BUFFER_BIT)
            px = gl.glReadPixels(0, 0, 64, 64, gl.GL_RGBA, gl.GL_UNSIGNED_BYTE)

Conventions of ``ctx.gl`` (shared with ``gles``):

* names, argument order and constants are the C API's; the namespace also
  carries every ``GL_*`` constant of :mod:`gles.constants`;
* pointer arguments take a C-contiguous numpy array, bytes/bytearray, a
  sequence of numbers, ``None`` or an int byte offset (while a buffer object is
  bound); arrays given to ``gl*Pointer*`` functions are kept alive until the next
  call of the same function (per client-active texture unit for texture
  coordinates);
* ``glGen*(n)`` returns an int for ``n == 1``, else a uint32 array;
  ``glDelete*(names)`` takes an int or a sequence (the C form ``(n, names)``
  works too); ``glBufferData(target, data, usage)`` and
  ``glBufferSubData(target, offset, data)`` take the size from the data;
* ``glGet*v(...)`` take every argument except the output pointer and return a
  scalar for one value, else a numpy array, shape (4, 4) for a matrix;
  ``glGetString`` returns bytes;
* ``glReadPixels(x, y, w, h, format, type)`` returns a new unpadded array of
  the part of the rectangle inside the surface, bottom row first: uint8
  (h, w, 4) for RGBA/UNSIGNED_BYTE, (h, w, 3) for RGB, uint16 (h, w) for the
  packed 16-bit types; for a pair it does not know, GL is still
  called (so that it records its error) and the result is None;
* ``glQueryMatrixxOES()`` returns (mantissa[16], exponent[16], status);
  ``glGetPointerv`` and ``glMapBufferOES`` return addresses as ints;
* misuse (a float for a GLfixed, a wrong dtype, an array shorter than the
  command reads, a non-contiguous array) raises TypeError/ValueError before
  any C code runs.

Each ``ctx.gl`` function is bound to ``ctx``: if another :class:`MesaContext`
was made current since, the call makes ``ctx`` current again first. The check
is a single identity test (contexts are meant to be used from one thread at a
time; EGL forbids a context current in two threads anyway).

Both drivers can live in one process at the same time. Mesa reads
``GALLIUM_DRIVER`` when an EGL display is initialised, and hands out two
distinct surfaceless displays (one for a NULL attribute list, one for an empty
list), so each driver gets its own display; a display whose contexts are all
closed is re-initialised when a driver needs it.
"""

from __future__ import annotations

import ctypes
import os
import re
import shutil
import subprocess
import sysconfig
import threading
from typing import Any

import numpy as np

from gles import constants as C
from gles.commands import COMMANDS

__all__ = ["DRIVERS", "COLOR_FORMATS", "MESA_COLOR_FORMATS", "LibraryContext", "MesaContext", "available"]

DRIVERS = ("llvmpipe", "softpipe")
COLOR_FORMATS = {"rgba8888": (8, 8, 8, 8), "rgb565": (5, 6, 5, 0), "rgba4444": (4, 4, 4, 4),
                 "rgba5551": (5, 5, 5, 1)}
# the formats Mesa's EGL (llvmpipe, softpipe) has pbuffer configs of; its
# framebuffer objects take RGBA4_OES and RGB5_A1_OES renderbuffers
MESA_COLOR_FORMATS = ("rgba8888", "rgb565")

_EGL_LIB = "libEGL.so.1"
_GLES_LIB = "libGLESv1_CM.so.1"

# EGL tokens (EGL/egl.h, EGL/eglext.h).
_EGL_SUCCESS = 0x3000
_EGL_ALPHA_SIZE = 0x3021
_EGL_BLUE_SIZE = 0x3022
_EGL_GREEN_SIZE = 0x3023
_EGL_RED_SIZE = 0x3024
_EGL_DEPTH_SIZE = 0x3025
_EGL_STENCIL_SIZE = 0x3026
_EGL_CONFIG_ID = 0x3028
_EGL_SAMPLES = 0x3031
_EGL_SURFACE_TYPE = 0x3033
_EGL_NONE = 0x3038
_EGL_EXTENSIONS = 0x3055
_EGL_RENDERABLE_TYPE = 0x3040
_EGL_HEIGHT = 0x3056
_EGL_WIDTH = 0x3057
_EGL_CONTEXT_CLIENT_VERSION = 0x3098
_EGL_OPENGL_ES_API = 0x30A0
_EGL_PBUFFER_BIT = 0x0001
_EGL_OPENGL_ES_BIT = 0x0001
_EGL_PLATFORM_SURFACELESS_MESA = 0x31DD

_EGL_ERRORS = {
    0x3000: "EGL_SUCCESS", 0x3001: "EGL_NOT_INITIALIZED", 0x3002: "EGL_BAD_ACCESS",
    0x3003: "EGL_BAD_ALLOC", 0x3004: "EGL_BAD_ATTRIBUTE", 0x3005: "EGL_BAD_CONFIG",
    0x3006: "EGL_BAD_CONTEXT", 0x3007: "EGL_BAD_CURRENT_SURFACE",
    0x3008: "EGL_BAD_DISPLAY", 0x3009: "EGL_BAD_MATCH",
    0x300A: "EGL_BAD_NATIVE_PIXMAP", 0x300B: "EGL_BAD_NATIVE_WINDOW",
    0x300C: "EGL_BAD_PARAMETER", 0x300D: "EGL_BAD_SURFACE",
    0x300E: "EGL_CONTEXT_LOST",
}

# The OpenGL ES 1.1 commands of GLES/gl.h, from gles's command table, then the
# entry points of GLES/glext.h that belong to extensions Mesa advertises for
# ES 1 (plus OES_matrix_palette, which it does not, kept so that a Mesa that
# adds it is picked up), copied from the Khronos header so that the peer needs
# only the runtime libraries.
_PROTOTYPES = "\n".join(cmd.prototype() for cmd in COMMANDS.values() if cmd.extension is None) + """
/* GL_KHR_debug */
void glDebugMessageControlKHR(GLenum source, GLenum type, GLenum severity, GLsizei count, const GLuint *ids,
    GLboolean enabled);
void glDebugMessageInsertKHR(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
    const GLchar *buf);
void glDebugMessageCallbackKHR(GLDEBUGPROCKHR callback, const void *userParam);
GLuint glGetDebugMessageLogKHR(GLuint count, GLsizei bufSize, GLenum *sources, GLenum *types, GLuint *ids,
    GLenum *severities, GLsizei *lengths, GLchar *messageLog);
void glPushDebugGroupKHR(GLenum source, GLuint id, GLsizei length, const GLchar *message);
void glPopDebugGroupKHR(void);
void glObjectLabelKHR(GLenum identifier, GLuint name, GLsizei length, const GLchar *label);
void glGetObjectLabelKHR(GLenum identifier, GLuint name, GLsizei bufSize, GLsizei *length, GLchar *label);
void glObjectPtrLabelKHR(const void *ptr, GLsizei length, const GLchar *label);
void glGetObjectPtrLabelKHR(const void *ptr, GLsizei bufSize, GLsizei *length, GLchar *label);
void glGetPointervKHR(GLenum pname, void **params);
/* GL_OES_EGL_image */
void glEGLImageTargetTexture2DOES(GLenum target, GLeglImageOES image);
void glEGLImageTargetRenderbufferStorageOES(GLenum target, GLeglImageOES image);
/* GL_OES_blend_equation_separate */
void glBlendEquationSeparateOES(GLenum modeRGB, GLenum modeAlpha);
/* GL_OES_blend_func_separate */
void glBlendFuncSeparateOES(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha,
    GLenum dstAlpha);
/* GL_OES_blend_subtract */
void glBlendEquationOES(GLenum mode);
/* GL_OES_draw_texture */
void glDrawTexsOES(GLshort x, GLshort y, GLshort z, GLshort width, GLshort height);
void glDrawTexiOES(GLint x, GLint y, GLint z, GLint width, GLint height);
void glDrawTexxOES(GLfixed x, GLfixed y, GLfixed z, GLfixed width, GLfixed height);
void glDrawTexsvOES(const GLshort *coords);
void glDrawTexivOES(const GLint *coords);
void glDrawTexxvOES(const GLfixed *coords);
void glDrawTexfOES(GLfloat x, GLfloat y, GLfloat z, GLfloat width, GLfloat height);
void glDrawTexfvOES(const GLfloat *coords);
/* GL_OES_fixed_point */
void glAlphaFuncxOES(GLenum func, GLfixed ref);
void glClearColorxOES(GLfixed red, GLfixed green, GLfixed blue, GLfixed alpha);
void glClearDepthxOES(GLfixed depth);
void glClipPlanexOES(GLenum plane, const GLfixed *equation);
void glColor4xOES(GLfixed red, GLfixed green, GLfixed blue, GLfixed alpha);
void glDepthRangexOES(GLfixed n, GLfixed f);
void glFogxOES(GLenum pname, GLfixed param);
void glFogxvOES(GLenum pname, const GLfixed *param);
void glFrustumxOES(GLfixed l, GLfixed r, GLfixed b, GLfixed t, GLfixed n,
    GLfixed f);
void glGetClipPlanexOES(GLenum plane, GLfixed *equation);
void glGetFixedvOES(GLenum pname, GLfixed *params);
void glGetTexEnvxvOES(GLenum target, GLenum pname, GLfixed *params);
void glGetTexParameterxvOES(GLenum target, GLenum pname, GLfixed *params);
void glLightModelxOES(GLenum pname, GLfixed param);
void glLightModelxvOES(GLenum pname, const GLfixed *param);
void glLightxOES(GLenum light, GLenum pname, GLfixed param);
void glLightxvOES(GLenum light, GLenum pname, const GLfixed *params);
void glLineWidthxOES(GLfixed width);
void glLoadMatrixxOES(const GLfixed *m);
void glMaterialxOES(GLenum face, GLenum pname, GLfixed param);
void glMaterialxvOES(GLenum face, GLenum pname, const GLfixed *param);
void glMultMatrixxOES(const GLfixed *m);
void glMultiTexCoord4xOES(GLenum texture, GLfixed s, GLfixed t, GLfixed r,
    GLfixed q);
void glNormal3xOES(GLfixed nx, GLfixed ny, GLfixed nz);
void glOrthoxOES(GLfixed l, GLfixed r, GLfixed b, GLfixed t, GLfixed n, GLfixed f);
void glPointParameterxvOES(GLenum pname, const GLfixed *params);
void glPointSizexOES(GLfixed size);
void glPolygonOffsetxOES(GLfixed factor, GLfixed units);
void glRotatexOES(GLfixed angle, GLfixed x, GLfixed y, GLfixed z);
void glScalexOES(GLfixed x, GLfixed y, GLfixed z);
void glTexEnvxOES(GLenum target, GLenum pname, GLfixed param);
void glTexEnvxvOES(GLenum target, GLenum pname, const GLfixed *params);
void glTexParameterxOES(GLenum target, GLenum pname, GLfixed param);
void glTexParameterxvOES(GLenum target, GLenum pname, const GLfixed *params);
void glTranslatexOES(GLfixed x, GLfixed y, GLfixed z);
void glGetLightxvOES(GLenum light, GLenum pname, GLfixed *params);
void glGetMaterialxvOES(GLenum face, GLenum pname, GLfixed *params);
void glPointParameterxOES(GLenum pname, GLfixed param);
void glSampleCoveragexOES(GLclampx value, GLboolean invert);
void glGetTexGenxvOES(GLenum coord, GLenum pname, GLfixed *params);
void glTexGenxOES(GLenum coord, GLenum pname, GLfixed param);
void glTexGenxvOES(GLenum coord, GLenum pname, const GLfixed *params);
/* GL_OES_framebuffer_object */
GLboolean glIsRenderbufferOES(GLuint renderbuffer);
void glBindRenderbufferOES(GLenum target, GLuint renderbuffer);
void glDeleteRenderbuffersOES(GLsizei n, const GLuint *renderbuffers);
void glGenRenderbuffersOES(GLsizei n, GLuint *renderbuffers);
void glRenderbufferStorageOES(GLenum target, GLenum internalformat, GLsizei width,
    GLsizei height);
void glGetRenderbufferParameterivOES(GLenum target, GLenum pname, GLint *params);
GLboolean glIsFramebufferOES(GLuint framebuffer);
void glBindFramebufferOES(GLenum target, GLuint framebuffer);
void glDeleteFramebuffersOES(GLsizei n, const GLuint *framebuffers);
void glGenFramebuffersOES(GLsizei n, GLuint *framebuffers);
GLenum glCheckFramebufferStatusOES(GLenum target);
void glFramebufferRenderbufferOES(GLenum target, GLenum attachment,
    GLenum renderbuffertarget, GLuint renderbuffer);
void glFramebufferTexture2DOES(GLenum target, GLenum attachment, GLenum textarget,
    GLuint texture, GLint level);
void glGetFramebufferAttachmentParameterivOES(GLenum target, GLenum attachment,
    GLenum pname, GLint *params);
void glGenerateMipmapOES(GLenum target);
/* GL_OES_mapbuffer */
void * glMapBufferOES(GLenum target, GLenum access);
GLboolean glUnmapBufferOES(GLenum target);
void glGetBufferPointervOES(GLenum target, GLenum pname, void **params);
/* GL_OES_matrix_palette */
void glCurrentPaletteMatrixOES(GLuint matrixpaletteindex);
void glLoadPaletteFromModelViewMatrixOES(void);
void glMatrixIndexPointerOES(GLint size, GLenum type, GLsizei stride,
    const void *pointer);
void glWeightPointerOES(GLint size, GLenum type, GLsizei stride,
    const void *pointer);
/* GL_OES_query_matrix */
GLbitfield glQueryMatrixxOES(GLfixed *mantissa, GLint *exponent);
/* GL_OES_single_precision */
void glClearDepthfOES(GLclampf depth);
void glClipPlanefOES(GLenum plane, const GLfloat *equation);
void glDepthRangefOES(GLclampf n, GLclampf f);
void glFrustumfOES(GLfloat l, GLfloat r, GLfloat b, GLfloat t, GLfloat n,
    GLfloat f);
void glGetClipPlanefOES(GLenum plane, GLfloat *equation);
void glOrthofOES(GLfloat l, GLfloat r, GLfloat b, GLfloat t, GLfloat n, GLfloat f);
/* GL_OES_texture_cube_map */
void glTexGenfOES(GLenum coord, GLenum pname, GLfloat param);
void glTexGenfvOES(GLenum coord, GLenum pname, const GLfloat *params);
void glTexGeniOES(GLenum coord, GLenum pname, GLint param);
void glTexGenivOES(GLenum coord, GLenum pname, const GLint *params);
void glGetTexGenfvOES(GLenum coord, GLenum pname, GLfloat *params);
void glGetTexGenivOES(GLenum coord, GLenum pname, GLint *params);
/* GL_OES_vertex_array_object */
void glBindVertexArrayOES(GLuint array);
void glDeleteVertexArraysOES(GLsizei n, const GLuint *arrays);
void glGenVertexArraysOES(GLsizei n, GLuint *arrays);
GLboolean glIsVertexArrayOES(GLuint array);
/* GL_EXT_discard_framebuffer */
void glDiscardFramebufferEXT(GLenum target, GLsizei numAttachments,
    const GLenum *attachments);
/* GL_EXT_map_buffer_range */
void * glMapBufferRangeEXT(GLenum target, GLintptr offset, GLsizeiptr length,
    GLbitfield access);
void glFlushMappedBufferRangeEXT(GLenum target, GLintptr offset, GLsizeiptr length);
/* GL_EXT_multi_draw_arrays */
void glMultiDrawArraysEXT(GLenum mode, const GLint *first, const GLsizei *count,
    GLsizei primcount);
void glMultiDrawElementsEXT(GLenum mode, const GLsizei *count, GLenum type,
    const void *const*indices, GLsizei primcount);
"""


# --------------------------------------------------------------------------
# Prototype table -> parsed signatures

_SCALAR_CTYPES: dict[str, Any] = {
    "GLenum": ctypes.c_uint, "GLbitfield": ctypes.c_uint, "GLuint": ctypes.c_uint,
    "GLint": ctypes.c_int, "GLsizei": ctypes.c_int, "GLfixed": ctypes.c_int,
    "GLclampx": ctypes.c_int, "GLshort": ctypes.c_short,
    "GLushort": ctypes.c_ushort, "GLbyte": ctypes.c_byte,
    "GLubyte": ctypes.c_ubyte, "GLboolean": ctypes.c_ubyte,
    "GLfloat": ctypes.c_float, "GLclampf": ctypes.c_float,
    "GLintptr": ctypes.c_ssize_t, "GLsizeiptr": ctypes.c_ssize_t,
    "GLeglImageOES": ctypes.c_void_p, "GLDEBUGPROCKHR": ctypes.c_void_p,
}

# Element dtype of a typed pointer parameter (``const GLfloat *params``).
_ELEMENT_DTYPES: dict[str, np.dtype] = {
    "GLfloat": np.dtype(np.float32), "GLclampf": np.dtype(np.float32),
    "GLfixed": np.dtype(np.int32), "GLclampx": np.dtype(np.int32),
    "GLint": np.dtype(np.int32), "GLsizei": np.dtype(np.int32),
    "GLuint": np.dtype(np.uint32), "GLenum": np.dtype(np.uint32),
    "GLshort": np.dtype(np.int16), "GLushort": np.dtype(np.uint16),
    "GLbyte": np.dtype(np.int8), "GLubyte": np.dtype(np.uint8),
    "GLboolean": np.dtype(np.uint8),
}

_PROTO_RE = re.compile(r"/\*\s*(?P<ext>GL_\w+)\s*\*/|(?P<proto>[^;/]+);")
_DECL_RE = re.compile(r"^(?P<ret>.*?)\b(?P<name>gl\w+)\s*\((?P<args>.*)\)$", re.S)
_PARAM_RE = re.compile(
    r"^(?P<const>const\s+)?(?P<base>\w+)\s*(?P<stars>(?:\*\s*(?:const\s*)?)*)"
    r"(?P<name>\w+)$"
)


class _Param:
    """One parameter of a GL command."""

    __slots__ = ("name", "base", "pointer", "const")

    def __init__(self, name: str, base: str, pointer: int, const: bool) -> None:
        self.name = name
        self.base = base
        self.pointer = pointer
        self.const = const


class _Proto:
    """One GL command: name, return type, parameters and owning extension."""

    __slots__ = ("name", "ret", "params", "extension", "text")

    def __init__(self, name: str, ret: str, params: list[_Param],
                 extension: str | None, text: str) -> None:
        self.name = name
        self.ret = ret
        self.params = params
        self.extension = extension
        self.text = text


def _parse_prototypes(text: str) -> list[_Proto]:
    protos = []
    extension = None
    for m in _PROTO_RE.finditer(text):
        if m.group("ext"):
            extension = m.group("ext")
            continue
        decl = " ".join(m.group("proto").split())
        d = _DECL_RE.match(decl)
        if d is None:
            raise ValueError(f"cannot parse prototype {decl!r}")
        params = []
        args = d.group("args").strip()
        if args != "void":
            for arg in args.split(","):
                p = _PARAM_RE.match(arg.strip())
                if p is None:
                    raise ValueError(f"cannot parse parameter {arg!r} in {decl!r}")
                params.append(_Param(p.group("name"), p.group("base"),
                                     p.group("stars").count("*"),
                                     bool(p.group("const"))))
        protos.append(_Proto(d.group("name"), " ".join(d.group("ret").split()),
                             params, extension, decl + ";"))
    return protos


_PROTOS: list[_Proto] = _parse_prototypes(_PROTOTYPES)
CORE_COMMANDS: tuple[str, ...] = tuple(p.name for p in _PROTOS if p.extension is None)


def _restype(ret: str) -> Any:
    if ret == "void":
        return None
    if ret == "const GLubyte *":
        return ctypes.c_char_p
    if ret.endswith("*"):
        return ctypes.c_void_p
    return _SCALAR_CTYPES[ret]


def _argtype(p: _Param) -> Any:
    return ctypes.c_void_p if p.pointer else _SCALAR_CTYPES[p.base]


# --------------------------------------------------------------------------
# Argument converters (used by the generated wrappers)

_DATA_OFFSET = 16  # offsetof(PyArrayObject_fields, data) on CPython


def _probe_data_offset() -> bool:
    # ``arr.ctypes.data`` costs about a microsecond; reading the ``data`` field of
    # the array object directly is ten times cheaper. Used only if it checks out.
    try:
        read = ctypes.c_void_p.from_address
        for a in (np.zeros(3, np.float32), np.arange(10, dtype=np.int16)[2:]):
            if read(id(a) + _DATA_OFFSET).value != a.ctypes.data:
                return False
        return True
    except Exception:
        return False


if _probe_data_offset():
    _read_pointer = ctypes.c_void_p.from_address

    def _addr(a: np.ndarray) -> int:
        """Address of a numpy array's first element."""
        return _read_pointer(id(a) + _DATA_OFFSET).value or 0
else:  # pragma: no cover - non-CPython layouts
    def _addr(a: np.ndarray) -> int:
        """Address of a numpy array's first element."""
        return a.ctypes.data


# dtype of client data named by a GL ``type`` argument.
_GLTYPE_DTYPES: dict[int, np.dtype] = {
    int(C.GL_BYTE): np.dtype(np.int8),
    int(C.GL_UNSIGNED_BYTE): np.dtype(np.uint8),
    int(C.GL_SHORT): np.dtype(np.int16),
    int(C.GL_UNSIGNED_SHORT): np.dtype(np.uint16),
    int(C.GL_FIXED): np.dtype(np.int32),
    int(C.GL_FLOAT): np.dtype(np.float32),
    int(C.GL_UNSIGNED_INT): np.dtype(np.uint32),
    int(C.GL_UNSIGNED_SHORT_5_6_5): np.dtype(np.uint16),
    int(C.GL_UNSIGNED_SHORT_4_4_4_4): np.dtype(np.uint16),
    int(C.GL_UNSIGNED_SHORT_5_5_5_1): np.dtype(np.uint16),
}

_BYTES_LIKE = (bytes, bytearray, memoryview)
_INTEGER = (int, np.integer)


def _from_sequence(obj: Any, dt: np.dtype) -> np.ndarray:
    try:
        a = np.asarray(obj)
    except Exception as exc:
        raise TypeError(f"expected an array, bytes or a sequence of numbers, got "
                        f"{type(obj).__name__}") from exc
    if a.size == 0:
        return np.zeros(0, dt)
    kind = a.dtype.kind
    if kind not in "biuf":
        raise TypeError(f"expected a sequence of numbers, got {a.dtype} data")
    if kind == "f" and dt.kind != "f":
        raise TypeError(f"integer ({dt}) data expected, got floats")
    return np.ascontiguousarray(a, dt).reshape(-1)


def _check_array(a: np.ndarray) -> None:
    if not a.flags.c_contiguous:
        raise ValueError("array must be C-contiguous")


def _vec(obj: Any, dt: np.dtype, need: int | None) -> tuple[int, Any]:
    """Typed input vector (``const GLfloat *params``) -> (address, keepalive)."""
    if type(obj) is np.ndarray:
        a = obj
        adt = a.dtype
        # Signed and unsigned integers of the right size share a bit pattern.
        if (adt is not dt and adt != dt
                and not (adt.kind in "iu" and dt.kind in "iu"
                         and adt.itemsize == dt.itemsize)):
            raise TypeError(f"array of {dt} expected, got {adt}")
        _check_array(a)
    elif isinstance(obj, _BYTES_LIKE):
        a = np.frombuffer(obj, dt)
    elif obj is None or isinstance(obj, _INTEGER):
        raise TypeError(f"array of {dt} expected, got {type(obj).__name__}")
    else:
        a = _from_sequence(obj, dt)
    if need is not None and a.size < need:
        raise ValueError(f"{need} values expected, got {a.size}")
    return _addr(a), a


def _data(obj: Any, gltype: int) -> tuple[int, Any]:
    """Client data whose element type a GL ``type`` argument names."""
    if type(obj) is np.ndarray:
        dt = _GLTYPE_DTYPES.get(gltype)
        adt = obj.dtype
        # ``is`` first: builtin dtypes are singletons, and ``!=`` is slow.
        if (adt is not dt and dt is not None and adt != dt and adt.itemsize != 1
                and adt.kind != "V"
                and not (adt.kind in "iu" and dt.kind in "iu"
                         and adt.itemsize == dt.itemsize)):
            raise TypeError(f"array of {dt} (or raw bytes) expected for this type, "
                            f"got {adt}")
        _check_array(obj)
        return _addr(obj), obj
    if obj is None:
        return 0, None
    if isinstance(obj, _INTEGER) and not isinstance(obj, bool):
        return int(obj), None
    if isinstance(obj, _BYTES_LIKE):
        a = np.frombuffer(obj, np.uint8)
        return _addr(a), a
    dt = _GLTYPE_DTYPES.get(gltype)
    if dt is None:
        raise TypeError("unknown GL type: pass a numpy array or bytes")
    a = _from_sequence(obj, dt)
    return _addr(a), a


def _raw(obj: Any, nbytes: int) -> tuple[int, Any]:
    """Untyped data (buffer and compressed texture data): array or bytes."""
    if type(obj) is np.ndarray:
        _check_array(obj)
        a = obj
    elif obj is None:
        return 0, None
    elif isinstance(obj, _BYTES_LIKE):
        a = np.frombuffer(obj, np.uint8)
    elif isinstance(obj, _INTEGER) and not isinstance(obj, bool):
        return int(obj), None
    else:
        raise TypeError("untyped data: pass a numpy array or bytes, got "
                        f"{type(obj).__name__}")
    if nbytes > a.nbytes:
        raise ValueError(f"{nbytes} bytes expected, the data has {a.nbytes}")
    return _addr(a), a


# Bytes per pixel of client image data, by (format, type).
_PIXEL_BYTES: dict[tuple[int, int], int] = {
    (int(C.GL_RGBA), int(C.GL_UNSIGNED_BYTE)): 4,
    (int(C.GL_BGRA_EXT), int(C.GL_UNSIGNED_BYTE)): 4,
    (int(C.GL_RGB), int(C.GL_UNSIGNED_BYTE)): 3,
    (int(C.GL_LUMINANCE_ALPHA), int(C.GL_UNSIGNED_BYTE)): 2,
    (int(C.GL_LUMINANCE), int(C.GL_UNSIGNED_BYTE)): 1,
    (int(C.GL_ALPHA), int(C.GL_UNSIGNED_BYTE)): 1,
    (int(C.GL_RGB), int(C.GL_UNSIGNED_SHORT_5_6_5)): 2,
    (int(C.GL_RGBA), int(C.GL_UNSIGNED_SHORT_4_4_4_4)): 2,
    (int(C.GL_RGBA), int(C.GL_UNSIGNED_SHORT_5_5_5_1)): 2,
}


def _check_image(ctx: MesaContext, width: int, height: int, fmt: int,
                 gltype: int, a: Any) -> None:
    """Refuse client image data shorter than TexImage2D/TexSubImage2D read."""
    bpp = _PIXEL_BYTES.get((fmt, gltype))
    if a is None or bpp is None or width <= 0 or height <= 0:
        return
    align = ctx._get_integer(C.GL_UNPACK_ALIGNMENT) or 1
    stride = -(-width * bpp // align) * align
    need = stride * (height - 1) + width * bpp
    if a.nbytes < need:
        raise ValueError(f"{width}x{height} image needs {need} bytes, "
                         f"the data has {a.nbytes}")


def _check_indices(count: int, gltype: int, a: Any) -> None:
    """Refuse an index array shorter than DrawElements reads."""
    dt = _GLTYPE_DTYPES.get(gltype)
    if a is not None and dt is not None and count > 0 and a.nbytes < count * dt.itemsize:
        raise ValueError(f"{count} indices expected, the array has "
                         f"{a.nbytes // dt.itemsize}")


# Number of values a glGet*v query returns, by pname (default 1). -1: as many
# as GL_NUM_COMPRESSED_TEXTURE_FORMATS says.
_COUNTS: dict[int, int] = {}
for _n, _names in (
    (4, "COLOR_CLEAR_VALUE VIEWPORT SCISSOR_BOX COLOR_WRITEMASK CURRENT_COLOR "
        "CURRENT_TEXTURE_COORDS FOG_COLOR LIGHT_MODEL_AMBIENT AMBIENT DIFFUSE "
        "SPECULAR EMISSION AMBIENT_AND_DIFFUSE POSITION TEXTURE_ENV_COLOR "
        "TEXTURE_CROP_RECT_OES"),
    (3, "CURRENT_NORMAL SPOT_DIRECTION POINT_DISTANCE_ATTENUATION"),
    (2, "DEPTH_RANGE ALIASED_POINT_SIZE_RANGE ALIASED_LINE_WIDTH_RANGE "
        "SMOOTH_POINT_SIZE_RANGE SMOOTH_LINE_WIDTH_RANGE MAX_VIEWPORT_DIMS"),
    (16, "MODELVIEW_MATRIX PROJECTION_MATRIX TEXTURE_MATRIX "
         "MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES "
         "PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES "
         "TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES"),
    (-1, "COMPRESSED_TEXTURE_FORMATS"),
):
    for _name in _names.split():
        _value = getattr(C, "GL_" + _name, None)
        if _value is not None:
            _COUNTS[int(_value)] = _n

# Array kind of each pointer function -> the pname that reads it back.
_POINTER_QUERY: dict[str, int] = {
    "glVertexPointer": int(C.GL_VERTEX_ARRAY_POINTER),
    "glColorPointer": int(C.GL_COLOR_ARRAY_POINTER),
    "glNormalPointer": int(C.GL_NORMAL_ARRAY_POINTER),
    "glTexCoordPointer": int(C.GL_TEXTURE_COORD_ARRAY_POINTER),
    "glPointSizePointerOES": int(C.GL_POINT_SIZE_ARRAY_POINTER_OES),
    "glMatrixIndexPointerOES": int(C.GL_MATRIX_INDEX_ARRAY_POINTER_OES),
    "glWeightPointerOES": int(C.GL_WEIGHT_ARRAY_POINTER_OES),
}

# Layout of glReadPixels results: (format, type) -> (dtype, components).
_READ_LAYOUTS: dict[tuple[int, int], tuple[np.dtype, int]] = {
    (int(C.GL_RGBA), int(C.GL_UNSIGNED_BYTE)): (np.dtype(np.uint8), 4),
    (int(C.GL_BGRA_EXT), int(C.GL_UNSIGNED_BYTE)): (np.dtype(np.uint8), 4),
    (int(C.GL_RGB), int(C.GL_UNSIGNED_BYTE)): (np.dtype(np.uint8), 3),
    (int(C.GL_LUMINANCE_ALPHA), int(C.GL_UNSIGNED_BYTE)): (np.dtype(np.uint8), 2),
    (int(C.GL_LUMINANCE), int(C.GL_UNSIGNED_BYTE)): (np.dtype(np.uint8), 1),
    (int(C.GL_ALPHA), int(C.GL_UNSIGNED_BYTE)): (np.dtype(np.uint8), 1),
    (int(C.GL_RGB), int(C.GL_UNSIGNED_SHORT_5_6_5)): (np.dtype(np.uint16), 1),
    (int(C.GL_RGBA), int(C.GL_UNSIGNED_SHORT_4_4_4_4)): (np.dtype(np.uint16), 1),
    (int(C.GL_RGBA), int(C.GL_UNSIGNED_SHORT_5_5_5_1)): (np.dtype(np.uint16), 1),
    (int(C.GL_BGRA_EXT), int(C.GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT)):
        (np.dtype(np.uint16), 1),
    (int(C.GL_BGRA_EXT), int(C.GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT)):
        (np.dtype(np.uint16), 1),
}


# --------------------------------------------------------------------------
# Wrapper generation: each command gets a factory, compiled once at import,
# that binds a wrapper to (context, foreign function).

class _State:
    """Which MesaContext was made current last."""

    __slots__ = ("current",)

    def __init__(self) -> None:
        self.current: MesaContext | None = None


_STATE = _State()

class _Infer:
    """The default of an argument PyOpenGL lets the caller leave out."""

    def __repr__(self) -> str:
        return "<inferred>"


_INFER: Any = _Infer()

_MATRIX_PNAMES = frozenset(int(getattr(C, "GL_" + n)) for n in (
    "MODELVIEW_MATRIX PROJECTION_MATRIX TEXTURE_MATRIX MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES "
    "PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES").split())


def _count(names: Any) -> tuple[int, Any]:
    """(n, names) of a one-argument Delete* call: an int or a sequence."""
    if isinstance(names, _INTEGER) and not isinstance(names, bool):
        return 1, names
    try:
        return len(names), names
    except TypeError:
        raise TypeError(f"names must be a sequence of ints or an int, not {type(names).__name__}") from None


def _nbytes(data: Any, what: str) -> int:
    """The size of data a size-less glBufferData/glBufferSubData copies."""
    if isinstance(data, np.ndarray):
        return int(data.nbytes)
    if isinstance(data, _BYTES_LIKE):
        return memoryview(data).nbytes
    raise TypeError(f"{what}: without a size, data must be a numpy array or bytes, "
                    f"not {type(data).__name__}")


def _chars(obj: Any) -> tuple[Any, Any]:
    """A GLchar string argument: str (UTF-8), bytes, or None (NULL)."""
    if obj is None:
        return None, None
    if not isinstance(obj, (str, bytes, bytearray, memoryview)):
        raise TypeError(f"a string must be str or bytes, not {type(obj).__name__}")
    data = obj.encode("utf-8") if isinstance(obj, str) else bytes(obj)
    buf = ctypes.create_string_buffer(data)
    return ctypes.addressof(buf), buf


_DEBUGPROC = ctypes.CFUNCTYPE(None, ctypes.c_uint, ctypes.c_uint, ctypes.c_uint, ctypes.c_uint, ctypes.c_int,
                              ctypes.c_void_p, ctypes.c_void_p)


def _debug_thunk(callback: Any, user_param: Any) -> Any:
    """A GLDEBUGPROCKHR calling a Python callable (None: NULL)."""
    if callback is None:
        return None
    if not callable(callback):
        raise TypeError("glDebugMessageCallbackKHR: callback must be callable or None, "
                        f"not {type(callback).__name__}")

    def thunk(source: int, type_: int, id_: int, severity: int, length: int, message: int, _up: int) -> None:
        callback(source, type_, id_, severity, length, ctypes.string_at(message, length), user_param)

    return _DEBUGPROC(thunk)


_GEN_GLOBALS: dict[str, Any] = {
    "_INFER": _INFER, "_count": _count, "_nbytes": _nbytes, "_MATRIX_PNAMES": _MATRIX_PNAMES,
    "np": np, "ctypes": ctypes, "_addr": _addr, "_vec": _vec, "_data": _data,
    "_raw": _raw, "_check_image": _check_image, "_check_indices": _check_indices,
    "_chars": _chars, "_debug_thunk": _debug_thunk,
    "_cnt": _COUNTS.get,
    "_READ_LAYOUTS": _READ_LAYOUTS, "_TEXTURE0": int(C.GL_TEXTURE0),
    "_PACK_ALIGNMENT": int(C.GL_PACK_ALIGNMENT),
}
for _key, _dt in _ELEMENT_DTYPES.items():
    _GEN_GLOBALS["_DT_" + _key] = _dt
for _key, _ct in _SCALAR_CTYPES.items():
    _GEN_GLOBALS["_CT_" + _key] = _ct

_ACTIVATE = ("        if _st.current is not _ctx:\n"
             "            _ctx._activate()\n")


def _vector_count(p: _Param, names: list[str]) -> str:
    """Python expression: how many elements a typed input vector must hold."""
    if p.name == "m":
        return "16"
    if p.name in ("eqn", "equation"):
        return "4"
    if p.name == "coords":
        return "5"
    if p.name in ("params", "param") and "pname" in names:
        return "_cnt(pname, 1)"
    for size_name in ("n", "primcount", "numAttachments", "count"):
        if size_name in names:
            return size_name
    return "None"


def _source(proto: _Proto) -> str:
    """Python source of the factory for one GL command."""
    name = proto.name
    params = proto.params
    names = [p.name for p in params]
    out_params = [p for p in params if p.pointer and not p.const]
    body = []
    sig = names
    ret = "return _fn({})"
    call = list(names)

    if name == "glGetString":
        ret = "return _fn({})"          # bytes, as PyOpenGL returns them
    elif name == "glBufferData":
        # (target, data, usage): the size is the data's, as in PyOpenGL
        sig = ["target", "size", "data=_INFER", "usage=_INFER"]
        body.append("        if usage is _INFER:\n"
                    "            size, data, usage = _INFER, size, data\n"
                    "        if size is _INFER:\n"
                    "            size = _nbytes(data, 'glBufferData')\n"
                    "        data_a, data_k = _raw(data, size)\n")
        call[2] = "data_a"
    elif name == "glBufferSubData":
        sig = ["target", "offset", "size", "data=_INFER"]
        body.append("        if data is _INFER:\n"
                    "            size, data = _nbytes(size, 'glBufferSubData'), size\n"
                    "        data_a, data_k = _raw(data, size)\n")
        call[3] = "data_a"
    elif name == "glReadPixels":
        sig = names[:-1]
        body.append(
            "        layout = _READ_LAYOUTS.get((format, type))\n"
            "        if width >= 0 and height >= 0:\n"
            "            # only the part inside the surface, as gles returns it\n"
            "            x0, y0 = max(x, 0), max(y, 0)\n"
            "            width = max(min(x + width, _ctx.width) - x0, 0)\n"
            "            height = max(min(y + height, _ctx.height) - y0, 0)\n"
            "            x, y = x0, y0\n"
            "        w = max(width, 0)\n"
            "        h = max(height, 0)\n"
            "        if layout is None:\n"
            "            # Still call, so that GL records its error; room for any format.\n"
            "            out = np.zeros(w * h * 16 + 16, np.uint8)\n"
            "        else:\n"
            "            dt, comps = layout\n"
            "            out = np.zeros((h, w, comps) if comps > 1 else (h, w), dt)\n"
            "        align = _ctx._get_integer(_PACK_ALIGNMENT)\n"
            "        if align != 1:\n"
            "            _ctx._raw['glPixelStorei'](_PACK_ALIGNMENT, 1)\n"
            "        _fn(x, y, width, height, format, type, _addr(out))\n"
            "        if align != 1:\n"
            "            _ctx._raw['glPixelStorei'](_PACK_ALIGNMENT, align)\n")
        ret = "return None if layout is None else out"
    elif name == "glDebugMessageCallbackKHR":
        # a Python callable, called as gles calls it (message as bytes);
        # ctypes keeps the thunk alive in _ctx._keep
        body.append("        thunk = _debug_thunk(callback, userParam)\n"
                    "        _ctx._keep['glDebugMessageCallbackKHR'] = thunk\n"
                    "        _fn(ctypes.cast(thunk, ctypes.c_void_p) if thunk is not None else None, None)\n")
        ret = "return None"
    elif name == "glGetDebugMessageLogKHR":
        sig = ["count", "bufSize", "sources=None", "types=None", "ids=None", "severities=None",
               "lengths=None", "messageLog=None"]
        body.append("        arrays = [a if a is None or isinstance(a, np.ndarray) "
                    "else np.frombuffer(a, np.uint8)\n"
                    "                  for a in (sources, types, ids, severities, lengths, messageLog)]\n"
                    "        ptrs = [None if a is None else _addr(a) for a in arrays]\n")
        ret = "return int(_fn(count, bufSize, *ptrs))"
    elif name in ("glGetObjectLabelKHR", "glGetObjectPtrLabelKHR"):
        sig = names[:-2]
        first = "ptr" if name == "glGetObjectPtrLabelKHR" else "identifier, name"
        body.append("        length = ctypes.c_int(0)\n"
                    "        out = ctypes.create_string_buffer(max(min(bufSize, 4096), 1))\n"
                    f"        _fn({first}, min(bufSize, 4096), ctypes.byref(length), out)\n")
        ret = "return out.raw[:max(length.value, 0)]"
    elif name == "glQueryMatrixxOES":
        sig = []
        body.append("        mantissa = np.zeros(16, np.int32)\n"
                    "        exponent = np.zeros(16, np.int32)\n"
                    "        status = _fn(_addr(mantissa), _addr(exponent))\n")
        ret = "return mantissa, exponent, int(status)"
    elif (name.startswith("glGen") and len(params) == 2 and names[0] == "n"
          and out_params):
        sig = ["n"]
        body.append("        out = np.zeros(max(n, 0), np.uint32)\n"
                    "        _fn(n, _addr(out))\n")
        ret = "return int(out[0]) if n == 1 else out"
    elif (name.startswith("glDelete") and len(params) == 2 and names[0] == "n"
          and params[1].pointer):
        p = names[1]
        sig = ["n", f"{p}=_INFER"]
        body.append(
            f"        if {p} is _INFER:\n"
            f"            n, {p} = _count(n)\n"
            f"        if isinstance({p}, (int, np.integer)):\n"
            f"            {p} = np.array([{p}], np.uint32)\n"
            f"        {p}_a, {p}_k = _vec({p}, _DT_GLuint, n)\n")
        call[1] = f"{p}_a"
    elif name.startswith("glGet") and params and out_params == [params[-1]]:
        sig = names[:-1]
        last = params[-1]
        if last.pointer == 2 or last.base == "void":
            body.append("        out = ctypes.c_void_p()\n"
                        "        _fn({}, ctypes.addressof(out))\n"
                        .format(", ".join(sig)))
            ret = "return out.value or 0"
        else:
            if "pname" in sig:
                count = "_cnt(pname, 1)"
            elif last.name in ("eqn", "equation"):
                count = "4"
            else:
                count = "1"
            body.append(f"        n = {count}\n")
            if sig == ["pname"]:
                body.append("        if n < 0:\n"
                            "            n = _ctx._num_compressed_formats()\n")
            body.append(f"        out = (_CT_{last.base} * max(n, 16))()\n"
                        f"        _fn({', '.join(sig + ['out'])})\n")
            ret = (f"return out[0] if n == 1 else "
                   f"np.array(out[:n], _DT_{last.base})")
            if "pname" in sig:
                # matrices come back (4, 4), as PyOpenGL returns them
                ret = (f"arr = np.array(out[:n], _DT_{last.base})\n"
                       f"        if n == 16 and pname in _MATRIX_PNAMES:\n"
                       f"            return arr.reshape(4, 4)\n"
                       f"        return out[0] if n == 1 else arr")
    elif name == "glMultiDrawElementsEXT":
        body.append(
            "        count_a, count_k = _vec(count, _DT_GLsizei, primcount)\n"
            "        keep = [_data(i, type) for i in indices[:max(primcount, 0)]]\n"
            "        if len(keep) < primcount:\n"
            "            raise ValueError(f'{primcount} index arrays expected')\n"
            "        ptrs = (ctypes.c_void_p * max(primcount, 1))"
            "(*[k[0] for k in keep])\n")
        call[1] = "count_a"
        call[3] = "ptrs"
    else:
        for i, p in enumerate(params):
            if not p.pointer:
                continue
            if not p.const:
                raise ValueError(f"no wrapper rule for output pointer in {name}")
            n = p.name
            if p.base == "GLchar":
                body.append(f"        {n}_a, {n}_k = _chars({n})\n")
            elif name == "glDebugMessageControlKHR":
                body.append("        ids_a, ids_k = (None, None) if ids is None else "
                            "_vec(ids, _DT_GLuint, count)\n")
            elif p.base == "void" and name == "glObjectPtrLabelKHR":
                body.append(f"        {n}_a = {n}\n")
            elif p.base == "void" and "type" in names:
                body.append(f"        {n}_a, {n}_k = _data({n}, type)\n")
            elif p.base == "void":
                size = "size" if "size" in names else (
                    "imageSize" if "imageSize" in names else "0")
                body.append(f"        {n}_a, {n}_k = _raw({n}, {size})\n")
            else:
                count = _vector_count(p, names)
                body.append(f"        {n}_a, {n}_k = _vec({n}, _DT_{p.base}, {count})\n")
            call[i] = f"{n}_a"
            if name in ("glTexImage2D", "glTexSubImage2D"):
                body.append(f"        _check_image(_ctx, width, height, format, type, {n}_k)\n")
            elif name == "glDrawElements":
                body.append(f"        _check_indices(count, type, {n}_k)\n")
        if name in _POINTER_QUERY:
            # Keep the array alive while GL may read it. A call that GL rejects
            # leaves the old pointer in place, so swap only if GL took the new one.
            n = params[-1].name
            key = (f"('{name}', _ctx._client_unit)" if name == "glTexCoordPointer"
                   else f"'{name}'")
            ret = (f"_fn({', '.join(call)})\n"
                   f"        if _ctx._pointer_value({_POINTER_QUERY[name]}) == {n}_a:\n"
                   f"            _ctx._keep[{key}] = {n}_k")
        elif name == "glClientActiveTexture":
            ret = ("_fn(texture)\n"
                   "        if 0 <= texture - _TEXTURE0 < _ctx._max_units:\n"
                   "            _ctx._client_unit = texture")

    inner = "".join(body) + "        " + ret.format(", ".join(call)) + "\n"
    inner = "".join("    " + line + "\n" for line in inner.splitlines())
    # ctypes reports a bad scalar (a float for a GLint) as ArgumentError; the
    # API contract says TypeError. The try costs nothing unless it fires.
    return (f"def _factory_{name}(_ctx, _fn, _st):\n"
            f"    def {name}({', '.join(sig)}):\n"
            f"{_ACTIVATE}"
            "        try:\n"
            f"{inner}"
            "        except ctypes.ArgumentError as exc:\n"
            f"            raise TypeError(f'{name}: {{exc}}') from None\n"
            f"    return {name}\n")


def _compile_factories() -> dict[str, Any]:
    ns: dict[str, Any] = {}
    source = "\n".join(_source(proto) for proto in _PROTOS)
    exec(compile(source, "<gles.mesa wrappers>", "exec"), _GEN_GLOBALS, ns)
    return {proto.name: ns["_factory_" + proto.name] for proto in _PROTOS}


_FACTORIES: dict[str, Any] = _compile_factories()


# --------------------------------------------------------------------------
# Libraries and displays

def _system_library(soname: str) -> str:
    """The path of the library the dynamic loader would find for `soname`.

    Mesa's libraries are opened by path, not by soname: once another library
    with the same soname is loaded (gles's own libEGL.so.1, through
    :class:`LibraryContext`), opening the soname would return that one.
    """
    dirs = [d for d in os.environ.get("LD_LIBRARY_PATH", "").split(":") if d]
    ldconfig = shutil.which("ldconfig") or next(
        (p for p in ("/sbin/ldconfig", "/usr/sbin/ldconfig") if os.path.exists(p)), None)
    cached: list[str] = []
    if ldconfig:
        try:
            out = subprocess.run([ldconfig, "-p"], capture_output=True, text=True, timeout=10).stdout
        except (OSError, subprocess.SubprocessError):
            out = ""
        for line in out.splitlines():
            name, _, path = line.strip().partition(" => ")
            if name.split(" ")[0] == soname:
                cached.append(path.strip())
    multiarch = sysconfig.get_config_var("MULTIARCH") or ""
    # this interpreter's architecture first (the cache lists 32-bit copies too)
    cached.sort(key=lambda p: not (multiarch and multiarch in p))
    dirs += [os.path.dirname(p) for p in cached]
    dirs += [f"/lib/{multiarch}", f"/usr/lib/{multiarch}", "/usr/lib64", "/lib64", "/usr/lib", "/lib"]
    for d in dirs:
        path = os.path.join(d, soname)
        if os.path.exists(path):
            return path
    return soname


class _Libs:
    """libEGL and libGLESv1_CM with their prototypes set, loaded once."""

    def __init__(self, egl_path: str | None = None, gles_path: str | None = None, mesa: bool = True) -> None:
        egl = ctypes.CDLL(egl_path or _system_library(_EGL_LIB))
        gles = ctypes.CDLL(gles_path or _system_library(_GLES_LIB))
        vp, i, u = ctypes.c_void_p, ctypes.c_int, ctypes.c_uint
        for fname, res, args in (
            ("eglGetProcAddress", vp, [ctypes.c_char_p]),
            ("eglGetError", i, []),
            ("eglQueryString", ctypes.c_char_p, [vp, i]),
            ("eglInitialize", u, [vp, vp, vp]),
            ("eglTerminate", u, [vp]),
            ("eglChooseConfig", u, [vp, vp, vp, i, vp]),
            ("eglGetConfigAttrib", u, [vp, vp, i, vp]),
            ("eglCreatePbufferSurface", vp, [vp, vp, vp]),
            ("eglCreateContext", vp, [vp, vp, vp, vp]),
            ("eglMakeCurrent", u, [vp, vp, vp, vp]),
            ("eglDestroyContext", u, [vp, vp]),
            ("eglDestroySurface", u, [vp, vp]),
            ("eglGetCurrentContext", vp, []),
            ("eglBindAPI", u, [u]),
            ("eglGetDisplay", vp, [vp]),
        ):
            f = getattr(egl, fname)
            f.restype = res
            f.argtypes = args
        client_extensions = (egl.eglQueryString(None, _EGL_EXTENSIONS) or b"").split()
        # the surfaceless platform where the library has it (Mesa must)
        self.get_platform_display: Any = None
        if b"EGL_MESA_platform_surfaceless" in client_extensions:
            addr = egl.eglGetProcAddress(b"eglGetPlatformDisplayEXT")
            if addr:
                self.get_platform_display = ctypes.CFUNCTYPE(vp, u, vp, vp)(addr)
        if mesa and b"EGL_MESA_platform_surfaceless" not in client_extensions:
            raise RuntimeError("EGL lacks EGL_MESA_platform_surfaceless (not Mesa?)")
        if mesa and self.get_platform_display is None:
            raise RuntimeError("EGL has no eglGetPlatformDisplayEXT")
        self.egl = egl
        self.gles = gles
        self._functions: dict[str, Any] | None = None

    def error(self) -> str:
        code = self.egl.eglGetError()
        return _EGL_ERRORS.get(code, hex(code))

    def functions(self) -> dict[str, Any]:
        """Foreign function of every command in the table (dispatch stubs)."""
        if self._functions is None:
            funcs = {}
            for proto in _PROTOS:
                restype = _restype(proto.ret)
                argtypes = [_argtype(p) for p in proto.params]
                fn = None
                if proto.extension is None:
                    fn = getattr(self.gles, proto.name, None)
                    if fn is not None:
                        fn.restype = restype
                        fn.argtypes = argtypes
                if fn is None:
                    addr = self.egl.eglGetProcAddress(proto.name.encode())
                    if addr:
                        fn = ctypes.CFUNCTYPE(restype, *argtypes)(addr)
                if fn is not None:
                    funcs[proto.name] = fn
            self._functions = funcs
        return self._functions


class _Display:
    """One surfaceless EGL display, initialised for one Gallium driver."""

    def __init__(self, attribs: Any) -> None:
        self.attribs = attribs
        self.handle: int | None = None
        self.driver: str | None = None
        self.threads = ""       # LP_NUM_THREADS the driver was initialised with
        self.users = 0


_LOCK = threading.RLock()
_LIBS: _Libs | None = None
# Mesa keys surfaceless displays by their attribute list, and a NULL list and an
# empty one compare different: two displays, so both drivers can coexist.
_DISPLAYS = [_Display(None), _Display((ctypes.c_int * 1)(_EGL_NONE))]
_AVAILABLE: dict[str, str | None] = {}


def _libs() -> _Libs:
    global _LIBS
    with _LOCK:
        if _LIBS is None:
            _LIBS = _Libs()
        return _LIBS


def _acquire_display(libs: _Libs, driver: str, threads: str) -> _Display:
    with _LOCK:
        for d in _DISPLAYS:
            if d.driver == driver and d.threads == threads:
                d.users += 1
                return d
        # A fresh display first; else re-initialise one nobody uses.
        idle = [d for d in _DISPLAYS if d.driver is None]
        idle += [d for d in _DISPLAYS if d.driver is not None and d.users == 0]
        for d in idle:
            if d.driver is not None:
                libs.egl.eglTerminate(d.handle)
                d.driver = None
            _initialise(libs, d, driver, threads)
            d.users += 1
            return d
    raise RuntimeError(f"cannot open a Mesa display for {driver!r} with {threads} threads: every "
                       "display is in use by another driver or thread count; use a subprocess")


def _initialise(libs: _Libs, d: _Display, driver: str, threads: str) -> None:
    # Mesa reads these when the display is initialised: the Gallium driver,
    # software rendering even where a GPU render node exists, and llvmpipe's
    # rasterizing threads.
    saved = {k: os.environ.get(k) for k in ("GALLIUM_DRIVER", "LIBGL_ALWAYS_SOFTWARE", "LP_NUM_THREADS")}
    os.environ["GALLIUM_DRIVER"] = driver
    os.environ["LIBGL_ALWAYS_SOFTWARE"] = "1"
    os.environ["LP_NUM_THREADS"] = threads
    try:
        handle = libs.get_platform_display(_EGL_PLATFORM_SURFACELESS_MESA, None,
                                           d.attribs)
        if not handle:
            raise RuntimeError(f"eglGetPlatformDisplayEXT(surfaceless) failed: "
                               f"{libs.error()}")
        major, minor = ctypes.c_int(), ctypes.c_int()
        if not libs.egl.eglInitialize(handle, ctypes.byref(major), ctypes.byref(minor)):
            raise RuntimeError(f"eglInitialize failed: {libs.error()}")
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    d.handle = handle
    d.driver = driver
    d.threads = threads


def _release_display(d: _Display) -> None:
    with _LOCK:
        d.users -= 1


def _choose_config(libs: _Libs, display: int, rgba: tuple[int, int, int, int],
                   depth: int, stencil: int) -> tuple[int, dict[str, int]]:
    egl = libs.egl
    r, g, b, a = rgba
    attribs = [_EGL_SURFACE_TYPE, _EGL_PBUFFER_BIT,
               _EGL_RENDERABLE_TYPE, _EGL_OPENGL_ES_BIT,
               _EGL_RED_SIZE, r, _EGL_GREEN_SIZE, g, _EGL_BLUE_SIZE, b,
               _EGL_ALPHA_SIZE, a, _EGL_DEPTH_SIZE, depth,
               _EGL_STENCIL_SIZE, stencil, _EGL_NONE]
    attrib_list = (ctypes.c_int * len(attribs))(*attribs)
    n = ctypes.c_int()
    if not egl.eglChooseConfig(display, attrib_list, None, 0, ctypes.byref(n)):
        raise RuntimeError(f"eglChooseConfig failed: {libs.error()}")
    if n.value == 0:
        raise RuntimeError(f"no EGL config for OpenGL ES 1 with RGBA {r}{g}{b}{a}, "
                           f"depth {depth}, stencil {stencil}")
    configs = (ctypes.c_void_p * n.value)()
    egl.eglChooseConfig(display, attrib_list, configs, n.value, ctypes.byref(n))

    def attr(cfg: int, name: int) -> int:
        v = ctypes.c_int()
        egl.eglGetConfigAttrib(display, cfg, name, ctypes.byref(v))
        return v.value

    best = None
    for cfg in configs[:n.value]:
        sizes = {"red": attr(cfg, _EGL_RED_SIZE), "green": attr(cfg, _EGL_GREEN_SIZE),
                 "blue": attr(cfg, _EGL_BLUE_SIZE), "alpha": attr(cfg, _EGL_ALPHA_SIZE),
                 "depth": attr(cfg, _EGL_DEPTH_SIZE),
                 "stencil": attr(cfg, _EGL_STENCIL_SIZE),
                 "samples": attr(cfg, _EGL_SAMPLES),
                 "config_id": attr(cfg, _EGL_CONFIG_ID)}
        # EGL sorts deeper colour first; prefer the exact sizes asked for.
        key = (sizes["samples"] != 0,
               abs(sizes["red"] - r) + abs(sizes["green"] - g)
               + abs(sizes["blue"] - b) + abs(sizes["alpha"] - a),
               abs(sizes["depth"] - depth), abs(sizes["stencil"] - stencil))
        if best is None or key < best[0]:
            best = (key, cfg, sizes)
    assert best is not None
    if best[0][1]:
        raise RuntimeError(f"no EGL config for OpenGL ES 1 with RGBA {r}{g}{b}{a} (the closest has "
                           f"{best[2]['red']}{best[2]['green']}{best[2]['blue']}{best[2]['alpha']})")
    return best[1], best[2]


# --------------------------------------------------------------------------
# Public API

def available(driver: str = "llvmpipe") -> str | None:
    """Return None if the Mesa peer can run with ``driver``, else why not.

    The answer (one line) is computed once per driver by opening a 1x1 context.
    Never raises.
    """
    if driver not in DRIVERS:
        return f"unknown Mesa driver {driver!r} (expected one of {', '.join(DRIVERS)})"
    with _LOCK:
        if driver not in _AVAILABLE:
            try:
                MesaContext(1, 1, driver=driver).close()
                _AVAILABLE[driver] = None
            except Exception as exc:  # any failure is a reason, not an error
                _AVAILABLE[driver] = " ".join(f"{type(exc).__name__}: {exc}".split())
        return _AVAILABLE[driver]


class _GLNamespace:
    """GL commands of one MesaContext, plus every GL_* constant."""

    def __repr__(self) -> str:
        return f"<gles.mesa GL namespace, {len(self.__dict__)} commands>"


for _key in dir(C):
    if _key.startswith("GL_"):
        setattr(_GLNamespace, _key, getattr(C, _key))


class _EGLContextBase:
    """What every EGL pbuffer context here shares: config, surface, context,
    the generated GL wrappers (see the module docstring), make_current, close."""

    width: int
    height: int
    color: str
    renderer: str
    version: str
    extensions: frozenset

    def _check_args(self, width: int, height: int, color: str) -> None:
        if color not in COLOR_FORMATS:
            raise ValueError(f"color must be one of {tuple(COLOR_FORMATS)}, got {color!r}")
        if width < 1 or height < 1:
            raise ValueError(f"bad size {width}x{height}")
        self.width = int(width)
        self.height = int(height)
        self.color = color
        self._closed = True
        self._keep: dict[Any, Any] = {}

    def _verify(self) -> None:
        """Raise if the context is not what was asked for (called once, made current)."""

    def _open(self, libs: _Libs, handle: int, depth: int, stencil: int) -> None:
        self._libs = libs
        egl = libs.egl
        self._surface = self._context = None
        try:
            cfg, self.config = _choose_config(libs, handle, COLOR_FORMATS[self.color],
                                              depth, stencil)
            surf_attribs = (ctypes.c_int * 5)(_EGL_WIDTH, self.width,
                                              _EGL_HEIGHT, self.height, _EGL_NONE)
            self._surface = egl.eglCreatePbufferSurface(handle, cfg, surf_attribs)
            if not self._surface:
                raise RuntimeError(f"eglCreatePbufferSurface failed: {libs.error()}")
            if not egl.eglBindAPI(_EGL_OPENGL_ES_API):
                raise RuntimeError(f"eglBindAPI(OpenGL ES) failed: {libs.error()}")
            ctx_attribs = (ctypes.c_int * 3)(_EGL_CONTEXT_CLIENT_VERSION, 1, _EGL_NONE)
            self._context = egl.eglCreateContext(handle, cfg, None, ctx_attribs)
            if not self._context:
                raise RuntimeError(f"eglCreateContext(ES 1) failed: {libs.error()}")
            self._closed = False
            self.make_current()
            funcs = libs.functions()
            self._raw = funcs
            get_string = funcs["glGetString"]
            self.renderer = (get_string(C.GL_RENDERER) or b"").decode()
            self.version = (get_string(C.GL_VERSION) or b"").decode()
            self.extensions = frozenset(
                (get_string(C.GL_EXTENSIONS) or b"").decode().split())
            self._verify()
        except BaseException:
            self.close()
            raise
        self._get_pointerv = funcs["glGetPointerv"]
        self._pointer_out = ctypes.c_void_p()
        self._pointer_out_address = ctypes.addressof(self._pointer_out)
        self._client_unit = int(C.GL_TEXTURE0)
        self._max_units = self._get_integer(C.GL_MAX_TEXTURE_UNITS)
        gl = _GLNamespace()
        for proto in _PROTOS:
            fn = funcs.get(proto.name)
            if fn is None or (proto.extension is not None
                              and proto.extension not in self.extensions):
                continue
            wrapper = _FACTORIES[proto.name](self, fn, _STATE)
            wrapper.__doc__ = proto.text
            setattr(gl, proto.name, wrapper)
        self.gl = gl

    # -- helpers used by the wrappers
    def _activate(self) -> None:
        self.make_current()

    def _get_integer(self, pname: int) -> int:
        out = (ctypes.c_int * 16)()
        self._raw["glGetIntegerv"](pname, out)
        return out[0]

    def _pointer_value(self, pname: int) -> int:
        self._get_pointerv(pname, self._pointer_out_address)
        return self._pointer_out.value or 0

    def _num_compressed_formats(self) -> int:
        return self._get_integer(C.GL_NUM_COMPRESSED_TEXTURE_FORMATS)

    # -- public
    def make_current(self) -> None:
        """Make this context current on the calling thread."""
        if self._closed:
            raise RuntimeError(f"{type(self).__name__} is closed")
        h = self._display.handle
        if not self._libs.egl.eglMakeCurrent(h, self._surface, self._surface,
                                             self._context):
            raise RuntimeError(f"eglMakeCurrent failed: {self._libs.error()}")
        _STATE.current = self

    def image(self) -> np.ndarray:
        """The colour buffer as numpy uint8 (height, width, 4), top row first."""
        px = self.gl.glReadPixels(0, 0, self.width, self.height,
                                  C.GL_RGBA, C.GL_UNSIGNED_BYTE)
        return np.ascontiguousarray(px[::-1])

    def close(self) -> None:
        """Destroy the context and its surface (idempotent)."""
        display = getattr(self, "_display", None)
        if display is None:
            return
        egl = self._libs.egl
        with _LOCK:
            self._closed = True
            if _STATE.current is self:
                _STATE.current = None
            if self._context and egl.eglGetCurrentContext() == self._context:
                egl.eglMakeCurrent(display.handle, None, None, None)
            if self._context:
                egl.eglDestroyContext(display.handle, self._context)
            if self._surface:
                egl.eglDestroySurface(display.handle, self._surface)
            self._context = self._surface = None
            self._keep.clear()
            self._display = None
            self._release(display)

    def _release(self, display: Any) -> None:
        """Give the display back (after the context and surface are gone)."""

    def __enter__(self) -> _EGLContextBase:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:
            pass


class MesaContext(_EGLContextBase):
    """An OpenGL ES 1.1 context of Mesa (llvmpipe or softpipe) on a pbuffer.

    ``ctx.gl`` holds the GL commands (see the module docstring for their Python
    conventions). The context is made current on creation. ``threads`` is
    llvmpipe's LP_NUM_THREADS (default: the environment's, else 1), read
    when Mesa initialises a display: contexts with another count get a
    display of their own (two at most in a process).
    """

    def __init__(self, width: int, height: int, driver: str = "llvmpipe",
                 color: str = "rgba8888", depth: int = 24, stencil: int = 8,
                 threads: int | None = None) -> None:
        if driver not in DRIVERS:
            raise ValueError(f"driver must be one of {DRIVERS}, got {driver!r}")
        self._check_args(width, height, color)
        if color not in MESA_COLOR_FORMATS:
            raise ValueError(f"Mesa's EGL has no {color.upper()} config: color must be one of "
                             f"{MESA_COLOR_FORMATS}, got {color!r}")
        if threads is None:
            threads = int(os.environ.get("LP_NUM_THREADS", "1") or 1)
        if isinstance(threads, bool) or not isinstance(threads, int):
            raise TypeError(f"threads must be an int, not {type(threads).__name__}")
        if not 0 <= threads <= 64:
            raise ValueError(f"threads must be in 0..64 (llvmpipe's LP_NUM_THREADS), not {threads}")
        self.driver = driver
        self.threads = threads
        libs = _libs()
        display = _acquire_display(libs, driver, str(threads))
        self._display = display
        self._open(libs, display.handle, depth, stencil)

    def _verify(self) -> None:
        if self.driver not in self.renderer:
            raise RuntimeError(f"asked for {self.driver}, Mesa gave {self.renderer!r}")

    def _release(self, display: Any) -> None:
        _release_display(display)

    def __enter__(self) -> MesaContext:
        return self

    def __repr__(self) -> str:
        state = "closed" if self._closed else self.renderer
        return (f"<MesaContext {self.width}x{self.height} {self.driver} "
                f"{self.color} ({state})>")


class _LibraryDisplay:
    """The one initialised display of a library pair (never terminated)."""

    def __init__(self, handle: int) -> None:
        self.handle = handle


_LIBRARIES: dict[tuple[str, str], tuple[_Libs, _LibraryDisplay]] = {}


def _library(egl: str, gles: str) -> tuple[_Libs, _LibraryDisplay]:
    key = (str(egl), str(gles))
    with _LOCK:
        if key not in _LIBRARIES:
            libs = _Libs(key[0], key[1], mesa=False)
            if libs.get_platform_display is not None:
                handle = libs.get_platform_display(_EGL_PLATFORM_SURFACELESS_MESA, None, None)
            else:
                handle = libs.egl.eglGetDisplay(None)
            if not handle:
                raise RuntimeError(f"no EGL display from {egl}: {libs.error()}")
            major, minor = ctypes.c_int(), ctypes.c_int()
            if not libs.egl.eglInitialize(handle, ctypes.byref(major), ctypes.byref(minor)):
                raise RuntimeError(f"eglInitialize failed: {libs.error()}")
            _LIBRARIES[key] = (libs, _LibraryDisplay(handle))
        return _LIBRARIES[key]


class LibraryContext(_EGLContextBase):
    """An OpenGL ES 1.1 context of any EGL + GLES 1 library pair, on a pbuffer.

    ``egl`` and ``gles`` are the paths of the two libraries (for example
    those of :func:`gles.cabi.library`, gles's own C ABI). The display is the
    surfaceless platform's where the library offers it, else the default
    display. ``ctx.gl`` follows the conventions of the module docstring;
    commands the library does not export (a Common-Lite library's float
    commands) are absent.
    """

    def __init__(self, width: int, height: int, egl: str, gles: str, color: str = "rgba8888",
                 depth: int = 24, stencil: int = 8) -> None:
        self._check_args(width, height, color)
        libs, display = _library(egl, gles)
        self._display = display
        self.libraries = (str(egl), str(gles))
        self._open(libs, display.handle, depth, stencil)

    def __enter__(self) -> LibraryContext:
        return self

    def __repr__(self) -> str:
        state = "closed" if self._closed else self.renderer
        return f"<LibraryContext {self.width}x{self.height} {self.libraries[0]} {self.color} ({state})>"
