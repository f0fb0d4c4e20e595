"""The OpenGL ES 1.1 commands, PyOpenGL style.

Two ways to call them:

* ``ctx.gl.glEnable(GL_DEPTH_TEST)``: the commands bound to one context
  (a :class:`GLCommon` or :class:`GLCommonLite` instance); no current context
  is needed.
* ``from gles.gl import *`` then ``glEnable(GL_DEPTH_TEST)``: module-level
  functions that act on the calling thread's current context
  (``ctx.make_current()``).

Conventions (PyOpenGL's; README.md's "PyOpenGL → gles" table lists every
difference):

* Names, argument order, parameter names and constants are the C API's
  (gles.commands, from the Khronos headers). ``x`` forms take 16.16 ints;
  ``f`` forms (Common profile only) take floats. Every command set also
  carries the GL_* constants (``ctx.gl.GL_TEXTURE_2D``).
* Pointer arguments take a numpy array, bytes, a sequence of numbers, or an
  int byte offset while a buffer object is bound. Arrays given to the
  ``*Pointer`` commands are kept alive until the pointer is replaced.
* ``glGen*(n)`` returns an int for n == 1, else a numpy array;
  ``glDelete*(names)`` takes the names alone (or the C form ``(n, names)``);
  ``glBufferData(target, data, usage)`` takes the size from the data;
  ``glGet*v`` returns a scalar for a single value, a (4, 4) array for a
  matrix, else a numpy array; ``glGetString`` returns bytes.
* GL errors are recorded and returned by ``glGetError`` as the spec says.
  Python-level misuse (a dtype that does not fit the type, an array shorter
  than a draw reads, an int past its C type, a non-number) raises TypeError
  or ValueError naming the argument before the core reads any memory.
"""

from __future__ import annotations

import inspect
import math
import operator
import sys
import threading
from collections.abc import Sequence
from typing import Any, NamedTuple, Union

import numpy as np

from . import _binding
from . import constants as C
from .commands import COMMANDS, Command, Param
from .constants import *  # noqa: F403  (the GL_* names are part of this module's API)
from .debug import log_message
from .errors import GLError

Pointer = Union[np.ndarray, bytes, bytearray, memoryview, Sequence, int, None]

_DTYPES = {
    C.GL_BYTE: np.dtype(np.int8),
    C.GL_UNSIGNED_BYTE: np.dtype(np.uint8),
    C.GL_SHORT: np.dtype(np.int16),
    C.GL_UNSIGNED_SHORT: np.dtype(np.uint16),
    C.GL_FIXED: np.dtype(np.int32),
    C.GL_FLOAT: np.dtype(np.float32),
}
# a target's binding query (buffer objects)
_BUFFER_BINDINGS = {C.GL_ARRAY_BUFFER: C.GL_ARRAY_BUFFER_BINDING,
                    C.GL_ELEMENT_ARRAY_BUFFER: C.GL_ELEMENT_ARRAY_BUFFER_BINDING}


class _Mapping(NamedTuple):
    """A mapped range as Python holds it: its copy, where it starts, its access bits."""
    array: np.ndarray
    offset: int
    access: int


# glDrawElements' index types (GL_UNSIGNED_INT: OES_element_index_uint)
_INDEX_DTYPES = {
    C.GL_UNSIGNED_BYTE: np.dtype(np.uint8),
    C.GL_UNSIGNED_SHORT: np.dtype(np.uint16),
    C.GL_UNSIGNED_INT: np.dtype(np.uint32),
}

# the core's own numbers, read from it (every build exports the same)
_CORE_LIB = _binding.core(_binding.NUMERICS[0]).lib
_FFI = _binding.core(_binding.NUMERICS[0]).ffi
# what gles_get says a state value is: enums are returned unscaled by
# GetFixedv, normalized values map to the whole int range
_KIND_ENUM, _KIND_NORM = _CORE_LIB.GLES_KIND_ENUM, _CORE_LIB.GLES_KIND_NORM
_STATUS_MEMORY, _STATUS_RANGE = _CORE_LIB.GLES_EMEMORY, _CORE_LIB.GLES_RANGE
_RANGE_ARRAYS = _CORE_LIB.GLES_RANGE_ARRAYS
_FIX = 1.0 / 65536.0
# KHR_debug's limits: MAX_DEBUG_MESSAGE_LENGTH_KHR and MAX_LABEL_LENGTH_KHR
_DEBUG_TEXT, _DEBUG_LABEL = _CORE_LIB.GLES_DEBUG_MAX_MESSAGE_LENGTH, _CORE_LIB.GLES_DEBUG_MAX_LABEL_LENGTH



# the dtype of client pixel data of each pixel type (§3.6.2, Table 3.4)
_PIXEL_DTYPES = {
    C.GL_UNSIGNED_BYTE: np.dtype(np.uint8),
    C.GL_UNSIGNED_SHORT_5_6_5: np.dtype(np.uint16),
    C.GL_UNSIGNED_SHORT_4_4_4_4: np.dtype(np.uint16),
    C.GL_UNSIGNED_SHORT_5_5_5_1: np.dtype(np.uint16),
}

# texture parameters whose values are reals (x forms scale them by 2^16,
# i forms map them like colours); every other one is an enum or an integer
_TEX_REAL = {C.GL_TEXTURE_ENV_COLOR, C.GL_RGB_SCALE, C.GL_ALPHA_SCALE, C.GL_TEXTURE_LOD_BIAS_EXT,
             C.GL_TEXTURE_MAX_ANISOTROPY_EXT}
_TEX_COUNT = {C.GL_TEXTURE_ENV_COLOR: 4, C.GL_TEXTURE_CROP_RECT_OES: 4}

# how many values each lighting pname takes (others take one)
_PARAM_COUNT = {
    C.GL_AMBIENT: 4, C.GL_DIFFUSE: 4, C.GL_SPECULAR: 4, C.GL_POSITION: 4, C.GL_EMISSION: 4,
    C.GL_AMBIENT_AND_DIFFUSE: 4, C.GL_LIGHT_MODEL_AMBIENT: 4, C.GL_SPOT_DIRECTION: 3,
    C.GL_FOG_COLOR: 4, C.GL_POINT_DISTANCE_ATTENUATION: 3,
}


_INT_MIN, _INT_MAX = -(2**31), 2**31 - 1

# the C types of the core's integer parameters: (lowest, highest, GL name)
_C_RANGES = {
    "int": (_INT_MIN, _INT_MAX, "GLint (32-bit signed)"),
    "unsigned int": (0, 2**32 - 1, "GLenum/GLuint (32-bit unsigned)"),
    "unsigned char": (0, 255, "GLboolean/GLubyte (8-bit unsigned)"),
    "int64_t": (-(2**63), 2**63 - 1, "GLsizeiptr/GLintptr (64-bit signed)"),
}


def _arg_name(value: Any) -> tuple[str | None, str | None]:
    """(command, parameter) of the innermost gl* command on the stack that
    was given `value`; (None, None) when none was (the value was derived)."""
    f = sys._getframe(1)
    for _ in range(12):
        if f is None:
            break
        code = f.f_code
        if code.co_name.startswith("gl"):
            for pname in code.co_varnames[:code.co_argcount]:
                if pname == "self":
                    continue
                v = f.f_locals.get(pname)
                if v is value or (type(v) is type(value) and not isinstance(v, np.ndarray) and v == value):
                    return code.co_name, pname
        f = f.f_back
    return None, None


def _describe(value: Any, fallback: str) -> str:
    """'glX: name=value' for an argument value, naming it as the caller did."""
    cmd, pname = _arg_name(value)
    if pname is None:
        return f"{fallback}={value!r}"
    return f"{cmd}: {pname}={value!r}"


def _index(v: Any) -> int:
    """An integer argument; floats are refused rather than truncated."""
    try:
        return operator.index(v)
    except TypeError:
        raise TypeError(f"{_describe(v, 'argument')} is not an integer") from None


def _glint(v: Any, name: str) -> int:
    """A GLint or GLsizei argument: TypeError for a non-integer, ValueError
    outside 32 bits, both naming the argument."""
    i = _index(v)
    if not _INT_MIN <= i <= _INT_MAX:
        raise ValueError(f"{_describe(v, name)} does not fit GLint (32-bit signed)")
    return i


def _real(v: Any) -> float:
    """A real argument; strings and other non-numbers are refused, naming it."""
    if isinstance(v, (str, bytes, bytearray)):
        raise TypeError(f"{_describe(v, 'argument')} is not a number")
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError(f"{_describe(v, 'argument')} is not a number") from None


def _finite_or_zero(v: float) -> float:
    return 0.0 if math.isnan(v) else v


def _to_int(v: float) -> int:
    """§6.1.2: a real as an integer query answers it: rounded to nearest and
    clamped to the GLint range (NaN, which has no nearest integer, gives 0)."""
    v = _finite_or_zero(v)
    return int(min(max(math.floor(v + 0.5), _INT_MIN), _INT_MAX)) if math.isfinite(v) else \
        (_INT_MAX if v > 0 else _INT_MIN)


def _to_fixed(v: float) -> int:
    """§6.1.2: a real as a fixed-point query answers it: times 2^16, rounded,
    saturated to the GLfixed range (NaN gives 0)."""
    return _to_int(_finite_or_zero(v) * 65536.0)


def _norm_to_int(v: float) -> int:
    """§6.1.2: a value in [-1, 1] to the whole int range, ((2^32 - 1) v - 1) / 2."""
    return _to_int(((2.0**32 - 1) * _finite_or_zero(v) - 1) / 2)


def _mask(v: Any) -> int:
    """A GLuint bit mask; -1 and other negative GLint values stand for their
    32-bit two's complement, as they would in C."""
    i = _index(v)
    if not _INT_MIN <= i <= 2**32 - 1:
        raise ValueError(f"{_describe(v, 'mask')} does not fit a 32-bit mask")
    return i & 0xFFFFFFFF


class _Infer:
    """The default of an argument PyOpenGL lets the caller leave out."""

    def __repr__(self) -> str:
        return "<inferred>"


_INFER: Any = _Infer()

# the queries that answer a 4x4 matrix: returned with shape (4, 4)
_MATRIX_PNAMES = frozenset({
    C.GL_MODELVIEW_MATRIX, C.GL_PROJECTION_MATRIX, C.GL_TEXTURE_MATRIX,
    C.GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES, C.GL_PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES,
    C.GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES,
})


def _count_names(n: Any, names: Any, what: str) -> tuple[int, Any]:
    """(n, names) of a Delete* call given as (names) or as (n, names)."""
    if names is _INFER:
        names = n
        if isinstance(names, (int, np.integer)) and not isinstance(names, bool):
            return 1, [names]
        try:
            return len(names), names
        except TypeError:
            raise TypeError(f"{what}: names must be a sequence of ints or an int, "
                            f"not {type(names).__name__}") from None
    return _index(n), names


def _names(n: Any, names: Any, what: str) -> Any:
    """n GLuint object names as a C array (Delete*)."""
    try:
        arr = np.atleast_1d(np.asarray(names, dtype=np.int64)).reshape(-1)
    except OverflowError:
        raise ValueError(f"{what}: a name does not fit GLuint") from None
    except (TypeError, ValueError) as e:
        raise type(e)(f"{what}: {e}") from None
    if n > arr.size:
        raise ValueError(f"{what}: n is {n} but {arr.size} names were given")
    head = arr[: max(n, 0)]
    if head.size and (head.min() < 0 or head.max() > 2**32 - 1):
        raise ValueError(f"{what}: a name does not fit GLuint (32-bit unsigned)")
    return head


def _string(value: Any, length: Any, what: str) -> tuple[Any, int]:
    """A KHR_debug string argument as (C chars, bytes the core may read):
    str (UTF-8) or bytes-like; with length >= 0 the core reads that many
    characters and no further than the data (a longer length is
    ValueError, unless the GL rule on the length decides first), with
    length < 0 up to the terminator added here."""
    if isinstance(value, str):
        data = value.encode("utf-8")
    elif isinstance(value, (bytes, bytearray, memoryview)):
        data = bytes(value)
    else:
        raise TypeError(f"{what} must be str or bytes, not {type(value).__name__}")
    length = _glint(length, "length")
    return _FFI.new("char[]", data), (len(data) if length >= 0 else len(data) + 1)


def _out_array(a: Any, dtype: Any, count: int, what: str) -> np.ndarray | None:
    """An output array for count values of dtype (None: not wanted): a
    writable, contiguous numpy array of that dtype (a bytearray for bytes)."""
    if a is None:
        return None
    if isinstance(a, bytearray) and dtype is np.uint8:
        a = np.frombuffer(a, dtype=np.uint8)
    if not isinstance(a, np.ndarray):
        raise TypeError(f"{what} must be a numpy array of {np.dtype(dtype)} or None, not {type(a).__name__}")
    if a.dtype != np.dtype(dtype):
        raise TypeError(f"{what}: array dtype {a.dtype} is not {np.dtype(dtype)}")
    if not (a.flags.c_contiguous and a.flags.writeable):
        raise ValueError(f"{what}: the array must be contiguous and writable")
    if a.size < count:
        raise ValueError(f"{what}: {a.size} elements, fewer than the {count} asked for")
    return a


def _delivering(gl: Any, name: str, method: Any) -> Any:
    """gl's command `name` followed by the delivery of the debug messages it
    raised (also when it raised an exception itself)."""
    bound = method.__get__(gl)

    def command(*args: Any, **kwargs: Any) -> Any:
        try:
            return bound(*args, **kwargs)
        finally:
            gl._debug_deliver()

    command.__name__ = name
    command.__doc__ = method.__doc__
    return command


def _converted(data: Any, dtype: np.dtype, what: str) -> np.ndarray:
    """A sequence (or one number) as a contiguous array of dtype: TypeError
    for what is not numbers, ValueError for a value the dtype cannot hold."""
    try:
        src = np.asarray(data)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what}: data must be an array, bytes or a sequence of numbers ({e})") from None
    if src.dtype.kind not in "biuf":
        raise TypeError(f"{what}: data must be numbers, not {src.dtype} values")
    if dtype.kind in "iu":
        if src.dtype.kind == "f":
            raise TypeError(f"{what}: {dtype} data expected, got reals")
        if src.size and (src.min() < np.iinfo(dtype).min or src.max() > np.iinfo(dtype).max):
            raise ValueError(f"{what}: a value does not fit {dtype}")
    return np.ascontiguousarray(src.astype(dtype))


def _fixed(v: Any) -> float:
    """A 16.16 (GLfixed) argument as the exact real it stands for."""
    i = _index(v)
    if not _INT_MIN <= i <= _INT_MAX:
        raise ValueError(f"{_describe(v, 'argument')} does not fit GLfixed (32-bit signed)")
    return i * _FIX


def _values(data: Any, n: int, what: str, dtype: Any = np.float64) -> np.ndarray:
    """At least n values of `data` as a flat array of dtype; an integer
    dtype (GLfixed, GLint and GLshort vectors) takes 32-bit values only."""
    try:
        arr = np.asarray(data, dtype=dtype).reshape(-1)
    except OverflowError:
        raise ValueError(f"{what}: a value does not fit 32 bits") from None
    except (TypeError, ValueError) as e:
        raise type(e)(f"{what}: {e}") from None
    if arr.size < n:
        raise ValueError(f"{what} needs {n} values, got {arr.size}")
    head = arr[:n]
    if arr.dtype.kind == "i" and head.size and (head.min() < _INT_MIN or head.max() > _INT_MAX):
        raise ValueError(f"{what}: a value does not fit 32 bits")
    return arr


_EXACT = 2**53      # ints below this in magnitude are exact as doubles


def _plain_or_values(src: Any, n: int, form: str, what: str) -> Any:
    """The first n values of a pname command's `src`. A list or tuple of
    Python numbers that _values would take unchanged is returned as it is,
    with no array: floats, or ints below 2^53 (exact as doubles), for the f
    forms; ints within 32 bits for the x and i forms (ints include the GL_*
    constants and bools, as numpy reads them). Anything else goes through
    _values, which converts or raises."""
    if type(src) in (list, tuple) and len(src) >= n:
        reals = form == "f"
        for i in range(n):
            v = src[i]
            if type(v) is float:
                if not reals:
                    break
            elif not isinstance(v, int) or not (-_EXACT < v < _EXACT if reals else _INT_MIN <= v <= _INT_MAX):
                break
        else:
            return src
    return _values(src, n, what, np.float64 if form == "f" else np.int64)


def _c_arg_error(name: str, ctype: Any, args: tuple, exc: Exception) -> Exception:
    """The TypeError or ValueError naming the argument the core's function
    `name` could not take (cffi converts before any C code runs)."""
    for i, (a, t) in enumerate(zip(args, ctype.args)):
        if t.kind != "primitive":
            continue
        rng = _C_RANGES.get(t.cname)
        fallback = f"{name} argument {i}"
        if rng is not None:
            if isinstance(a, bool):
                continue
            try:
                v = operator.index(a)
            except TypeError:
                return TypeError(f"{_describe(a, fallback)} is not an integer")
            if not rng[0] <= v <= rng[1]:
                return ValueError(f"{_describe(a, fallback)} does not fit {rng[2]}")
        elif t.cname in ("double", "float"):
            try:
                float(a)
            except OverflowError:
                return ValueError(f"{_describe(a, fallback)} is too large for a real")
            except (TypeError, ValueError):
                return TypeError(f"{_describe(a, fallback)} is not a number")
    if isinstance(exc, OverflowError):
        return ValueError(f"{name}: {exc}")
    return TypeError(f"{name}: {exc}")


class _CoreFunctions:
    """The core's functions with argument conversion errors (cffi's
    OverflowError, TypeError) turned into ValueError/TypeError naming the
    argument. Nothing reaches C when conversion fails."""

    def __init__(self, lib: Any, ffi: Any) -> None:
        self._lib_ = lib
        self._ffi_ = ffi

    def __getattr__(self, name: str) -> Any:
        fn = getattr(self._lib_, name)
        try:
            ctype = self._ffi_.typeof(fn)
        except TypeError:
            return fn
        if ctype.kind != "function":
            return fn
        if all(t.kind == "pointer" for t in ctype.args):
            # only the context's and the binding's own pointers: nothing the
            # caller passes can fail conversion
            setattr(self, name, fn)
            return fn

        def call(*args: Any) -> Any:
            try:
                return fn(*args)
            except (OverflowError, TypeError) as e:
                raise _c_arg_error(name, ctype, args, e) from None

        call.__name__ = name
        setattr(self, name, call)
        return call


_CORE_FUNCTIONS: dict[int, _CoreFunctions] = {}


def _core_functions(lib: Any, ffi: Any) -> _CoreFunctions:
    """One wrapper per compiled core, shared by its contexts."""
    key = id(lib)
    if key not in _CORE_FUNCTIONS:
        _CORE_FUNCTIONS[key] = _CoreFunctions(lib, ffi)
    return _CORE_FUNCTIONS[key]


class CoreHandle:
    """What a command set needs of its context, and nothing more: the core's
    functions, the context's pointer and lock, its range monitor, the
    framebuffer size, the GetString answers and the memory budget (which the
    context updates)."""

    __slots__ = ("lib", "ffi", "ptr", "lock", "range", "width", "height", "strings", "memory_limit",
                 "debug_callback", "debug_user_param")

    def __init__(self, lib: Any, ffi: Any, ptr: Any, lock: threading.Lock, range_monitor: Any,
                 width: int, height: int, strings: dict[int, str], memory_limit: int) -> None:
        self.lib = _core_functions(lib, ffi)
        self.ffi = ffi
        self.ptr = ptr
        self.lock = lock
        self.range = range_monitor
        self.width, self.height = width, height
        self.strings = strings
        self.memory_limit = memory_limit
        # KHR_debug: the Python callback (gles.debug) and its user_param
        self.debug_callback: Any = log_message
        self.debug_user_param: Any = None


class GLBase:
    """The Common-Lite command set, bound to one context through its handle."""

    def __init__(self, handle: CoreHandle) -> None:
        self.handle = handle
        self._lib = handle.lib
        self._ffi = handle.ffi
        self._p = handle.ptr
        self._lock: threading.Lock = handle.lock
        self._keep: dict[Any, Any] = {}
        # buffer name -> its mapping's numpy copy (OES_mapbuffer, EXT_map_buffer_range)
        self._maps: dict[int, _Mapping] = {}
        self._d16 = self._ffi.new("double[16]")
        self._kind = self._ffi.new("int *")
        self._debug_out: Any = None     # gles_debug_take's outputs, made at the first message
        self._debug_wrapped = False     # the commands deliver debug messages (_debug_route)

    # {================================================================
    # helpers

    def _bound(self, pname: int) -> int:
        self._lib.gles_get(self._p, pname, self._d16, self._kind)
        return int(self._d16[0])

    def _pointer(self, data: Pointer, gltype: int | None, binding: int, what: str,
                 dtype: np.dtype | None = None) -> tuple[Any, int, Any]:
        """(C pointer, byte length or -1, object to keep alive) for `data`
        (whose elements are `dtype`, else the array type `gltype`'s)."""
        ffi = self._ffi
        if data is None:
            return ffi.NULL, 0, None
        if isinstance(data, (int, np.integer)) and not isinstance(data, bool):
            off = int(data)
            if off < 0:
                raise ValueError(f"{what}: negative buffer offset {off}")
            if off > 2**63 - 1:
                raise ValueError(f"{what}: buffer offset {off} does not fit GLintptr")
            if binding == 0 or (self._bound(binding) == 0 and off != 0):
                raise ValueError(f"{what}: an int is a byte offset and needs a bound buffer object")
            return ffi.cast("void *", off), -1, None
        want = dtype if dtype is not None else _DTYPES.get(gltype) if gltype is not None else None
        if isinstance(data, np.ndarray):
            if want is not None and data.dtype != want:
                raise TypeError(
                    f"{what}: array dtype {data.dtype} does not match {C.NAMES.get(gltype)} ({want})")
            arr = np.ascontiguousarray(data)
        elif isinstance(data, (bytes, bytearray, memoryview)):
            arr = np.frombuffer(data, dtype=np.uint8)
        else:
            arr = _converted(data, want if want is not None else np.dtype(np.uint8), what)
        return ffi.from_buffer(arr), arr.nbytes, arr

    def _status(self, st: int, call: str = "") -> None:
        if st == 0:
            return
        if st == _STATUS_RANGE:
            # the draw broke the overflow rule or read a FLOAT array value
            # 16.16 cannot hold (profile.py acts on the policy)
            last = self._ffi.new("double[4]")
            arrays = self._ffi.new("double[]", _RANGE_ARRAYS)
            with self._lock:
                mask = self._lib.gles_range_last(self._p, last, arrays)
            self.handle.range.draw(call, tuple(last),
                                   {i: arrays[i] for i in range(_RANGE_ARRAYS) if mask >> i & 1})
            return
        if st == _STATUS_MEMORY:
            return      # the core recorded OUT_OF_MEMORY and changed nothing
        msg = self._ffi.string(self._lib.gles_last_message(self._p)).decode()
        raise ValueError(msg)

    def _names_too_many(self, n: int) -> bool:
        """Glgen* of more names than the memory budget's bytes can list:
        OUT_OF_MEMORY, nothing generated."""
        if n > _INT_MAX:
            raise ValueError(f"{_describe(n, 'n')} does not fit GLsizei (32-bit signed)")
        if n * 4 <= self.handle.memory_limit:
            return False
        with self._lock:
            self._lib.gles_set_error(self._p, C.GL_OUT_OF_MEMORY)
        return True

    def _get(self, pname: int) -> tuple[list[float], int]:
        with self._lock:
            n = self._lib.gles_get(self._p, _index(pname), self._d16, self._kind)
            return [self._d16[i] for i in range(n)], self._kind[0]

    @staticmethod
    def _result(vals: list, dtype: Any, pname: Any = None) -> Any:
        if not vals:
            return None
        if len(vals) == 1:
            return vals[0]
        out = np.array(vals, dtype=dtype)
        if pname in _MATRIX_PNAMES:
            # as PyOpenGL: the 16 values in GL's (column-major) order, 4 to a row
            out = out.reshape(4, 4)
        return out

    # {================================================================
    # errors and queries

    def glGetError(self) -> int:
        """Return and clear the first error recorded since the last call."""
        with self._lock:
            return self._lib.gles_GetError(self._p)

    def glGetIntegerv(self, pname: int) -> Any:
        """Integer state; colours, depth values and normals map [-1, 1] to the int range (§6.1.2)."""
        vals, kind = self._get(pname)
        # unsigned masks (0xFFFFFFFF) clamp to the GLint range
        out = [_norm_to_int(v) if kind == _KIND_NORM else _to_int(v) for v in vals]
        return self._result(out, np.int32, pname)

    def glGetFixedv(self, pname: int) -> Any:
        """State as 16.16; enums are returned unscaled (§6.1.2)."""
        vals, kind = self._get(pname)
        if kind == _KIND_ENUM:
            out = [_to_int(v) for v in vals]
        else:
            out = [_to_fixed(v) for v in vals]
        return self._result(out, np.int32, pname)

    def glGetBooleanv(self, pname: int) -> Any:
        """State as booleans: nonzero is True."""
        vals, _ = self._get(pname)
        return self._result([bool(v != 0) for v in vals], np.bool_, pname)

    def glIsEnabled(self, cap: int) -> bool:
        with self._lock:
            return bool(self._lib.gles_IsEnabled(self._p, _index(cap)))

    def glGetString(self, name: int) -> bytes | None:
        """VENDOR, RENDERER, VERSION or EXTENSIONS, as bytes (PyOpenGL's
        habit: the C function returns a GLubyte string)."""
        text = self.handle.strings.get(_index(name))
        if text is None:
            with self._lock:
                self._lib.gles_set_error(self._p, C.GL_INVALID_ENUM)
            return None
        return text.encode("ascii")

    def glGetPointerv(self, pname: int) -> Any:
        """The pointer (as an address) or buffer offset last given for an
        array; for KHR_debug's DEBUG_CALLBACK_FUNCTION_KHR and
        DEBUG_CALLBACK_USER_PARAM_KHR the Python callback and its user_param."""
        pname = _index(pname)
        if pname == C.GL_DEBUG_CALLBACK_FUNCTION_KHR:
            return self.handle.debug_callback
        if pname == C.GL_DEBUG_CALLBACK_USER_PARAM_KHR:
            return self.handle.debug_user_param
        with self._lock:
            return int(self._lib.gles_GetPointer(self._p, pname))

    def glGetPointervKHR(self, pname: int) -> Any:
        """KHR_debug's GetPointerv: glGetPointerv under its ES name."""
        return self.glGetPointerv(pname)

    def glEnable(self, cap: int) -> None:
        with self._lock:
            self._lib.gles_Enable(self._p, cap)
        if cap == C.GL_DEBUG_OUTPUT_KHR:
            self._debug_route()

    def glDisable(self, cap: int) -> None:
        with self._lock:
            self._lib.gles_Disable(self._p, cap)
        if cap == C.GL_DEBUG_OUTPUT_KHR:
            self._debug_route()

    # {================================================================
    # KHR_debug (gles.debug describes the Python callback)

    def _debug_route(self) -> None:
        """While DEBUG_OUTPUT_KHR is on and a Python callback is set, every
        command of this command set delivers the messages it raised
        (instance attributes over the class's methods); otherwise the
        methods are the class's own, at no cost per command. (The instance
        dict is touched only to add or remove those attributes: reading
        ``vars(self)`` would make CPython keep the attributes in a dict and
        look every one up there, which a command pays for.)"""
        handle = self.handle
        with self._lock:
            self._lib.gles_debug_queue_set(self._p, handle.debug_callback is not None)
            output = bool(self._lib.gles_IsEnabled(self._p, C.GL_DEBUG_OUTPUT_KHR))
        on = handle.debug_callback is not None and output
        if on == self._debug_wrapped:
            return
        names = [n for n in dir(type(self)) if n.startswith("gl") and n != "glGetError"]
        for n in names:
            if on:
                setattr(self, n, _delivering(self, n, getattr(type(self), n)))
            else:
                delattr(self, n)
        self._debug_wrapped = on

    def _debug_deliver(self) -> None:
        """Hand the messages waiting in the core's queue to the callback,
        outside the lock; the first exception a call raises is re-raised
        after the last message."""
        lib, p, ffi = self._lib, self._p, self._ffi
        taken = []
        out = self._debug_out
        if out is None:
            out = (ffi.new("unsigned int[4]"), ffi.new("int[1]"), ffi.new("char[]", _DEBUG_TEXT))
            self._debug_out = out
        meta, length, text = out
        with self._lock:
            while lib.gles_debug_queued(p):
                if not lib.gles_debug_take(p, 1, _DEBUG_TEXT, meta, meta + 1, meta + 2, meta + 3, length,
                                           text):
                    break
                taken.append((int(meta[0]), int(meta[1]), int(meta[2]), int(meta[3]),
                              ffi.buffer(text, max(int(length[0]) - 1, 0))[:]))
        callback, user_param = self.handle.debug_callback, self.handle.debug_user_param
        if callback is None:
            return
        raised: BaseException | None = None
        for source, type_, id_, severity, message in taken:
            try:
                callback(source, type_, id_, severity, len(message), message, user_param)
            except Exception as e:      # noqa: BLE001 -- re-raised below, after every message
                if raised is None:
                    raised = e
                else:
                    raised.add_note(f"the debug callback also raised {e!r}")
        if raised is not None:
            raise raised

    def glDebugMessageCallbackKHR(self, callback: Any, userParam: Any = None) -> None:
        """The debug callback: a callable (see gles.debug), or None to keep
        messages in the log. userParam is any object, passed back as it is."""
        if callback is not None and not callable(callback):
            raise TypeError(f"glDebugMessageCallbackKHR: callback must be callable or None, "
                            f"not {type(callback).__name__}")
        self.handle.debug_callback = callback
        self.handle.debug_user_param = userParam
        self._debug_route()

    def glDebugMessageControlKHR(self, source: int, type: int, severity: int, count: int, ids: Any,
                                 enabled: Any) -> None:
        count = _glint(count, "count")
        buf = self._ffi.NULL
        if count > 0:
            if ids is None:
                raise ValueError(f"glDebugMessageControlKHR: count is {count} but ids is None")
            arr = _names(count, ids, "glDebugMessageControlKHR: ids").astype(np.uint32)
            buf = self._ffi.from_buffer("unsigned int[]", arr)
        with self._lock:
            self._lib.gles_DebugMessageControlKHR(self._p, source, type, severity, count, buf, bool(enabled))

    def glDebugMessageInsertKHR(self, source: int, type: int, id: int, severity: int, length: int,
                                buf: Any) -> None:
        """buf is str (UTF-8) or bytes; length < 0 reads it to its end."""
        data, nbytes = _string(buf, length, "glDebugMessageInsertKHR: buf")
        with self._lock:
            st = self._lib.gles_DebugMessageInsertKHR(self._p, source, type, id, severity, length, data,
                                                      nbytes)
        self._status(st)

    def glPushDebugGroupKHR(self, source: int, id: int, length: int, message: Any) -> None:
        data, nbytes = _string(message, length, "glPushDebugGroupKHR: message")
        with self._lock:
            st = self._lib.gles_PushDebugGroupKHR(self._p, source, id, length, data, nbytes)
        self._status(st)

    def glGetDebugMessageLogKHR(self, count: int, bufSize: int, sources: Any = None, types: Any = None,
                                ids: Any = None, severities: Any = None, lengths: Any = None,
                                messageLog: Any = None) -> int:
        """Fetch up to count messages from the log into the arrays given (C's
        form: numpy uint32 arrays for sources, types, ids and severities,
        int32 for lengths, a bytearray or uint8 array of at least bufSize
        bytes for messageLog; None discards). Returns the number fetched."""
        count = _index(count)
        if not 0 <= count <= 2**32 - 1:
            raise ValueError(f"glGetDebugMessageLogKHR: count={count} does not fit GLuint")
        bufSize = _glint(bufSize, "bufSize")
        outs = [_out_array(a, np.uint32, count, f"glGetDebugMessageLogKHR: {n}")
                for a, n in ((sources, "sources"), (types, "types"), (ids, "ids"),
                             (severities, "severities"))]
        outs.append(_out_array(lengths, np.int32, count, "glGetDebugMessageLogKHR: lengths"))
        log = _out_array(messageLog, np.uint8, max(bufSize, 0), "glGetDebugMessageLogKHR: messageLog")
        ffi = self._ffi
        kinds = ["unsigned int[]"] * 4 + ["int[]", "char[]"]
        ptrs = [ffi.NULL if a is None else ffi.from_buffer(k, a) for a, k in zip([*outs, log], kinds)]
        with self._lock:
            return int(self._lib.gles_GetDebugMessageLogKHR(self._p, count, bufSize, *ptrs))

    def glObjectLabelKHR(self, identifier: int, name: int, length: int, label: Any) -> None:
        """label is str (UTF-8), bytes, or None to remove the label."""
        data, nbytes = (self._ffi.NULL, 0) if label is None else _string(label, length,
                                                                             "glObjectLabelKHR: label")
        with self._lock:
            st = self._lib.gles_ObjectLabelKHR(self._p, identifier, name, length, data, nbytes)
        self._status(st)

    def glGetObjectLabelKHR(self, identifier: int, name: int, bufSize: int) -> bytes:
        """The object's label as bytes, at most bufSize - 1 of them (b"" on a GL error)."""
        return self._get_label(bufSize, lambda size, length, out: self._lib.gles_GetObjectLabelKHR(
            self._p, identifier, name, size, length, out))

    def glObjectPtrLabelKHR(self, ptr: Any, length: int, label: Any) -> None:
        """ES 1.1 has no sync objects, so no ptr names one: INVALID_VALUE.
        ptr may be any object; it is never used as an address."""
        data, nbytes = (self._ffi.NULL, 0) if label is None else _string(label, length,
                                                                             "glObjectPtrLabelKHR: label")
        with self._lock:
            st = self._lib.gles_ObjectPtrLabelKHR(self._p, length, data, nbytes)
        self._status(st)

    def glGetObjectPtrLabelKHR(self, ptr: Any, bufSize: int) -> bytes:
        """INVALID_VALUE (no sync objects in ES 1.1); returns b""."""
        return self._get_label(bufSize, lambda size, length, out: self._lib.gles_GetObjectPtrLabelKHR(
            self._p, size, length, out))

    def _get_label(self, bufSize: Any, call: Any) -> bytes:
        size = _glint(bufSize, "bufSize")
        # a label is shorter than MAX_LABEL_LENGTH_KHR: no larger buffer is needed
        room = min(size, _DEBUG_LABEL) if size > 0 else size
        length = self._ffi.new("int[1]")
        out = self._ffi.new("char[]", max(room, 1))
        with self._lock:
            ok = call(room, length, out)
        return self._ffi.buffer(out, int(length[0]))[:] if ok else b""

    def glGetClipPlanex(self, plane: int) -> np.ndarray:
        eq = self._ffi.new("double[4]")
        with self._lock:
            self._lib.gles_GetClipPlane(self._p, _index(plane), eq)
        return np.array([_to_fixed(eq[i]) for i in range(4)], dtype=np.int32)

    def glGetBufferParameteriv(self, target: int, pname: int) -> int:
        out = self._ffi.new("int[1]")
        with self._lock:
            self._lib.gles_GetBufferParameteriv(self._p, _index(target), _index(pname), out)
        return int(out[0])

    def glQueryMatrixxOES(self) -> tuple[np.ndarray, np.ndarray, int]:
        """OES_query_matrix: the current matrix as (mantissa, exponent, status):
        element i is mantissa[i] / 65536 * 2**exponent[i]; bit i of status is
        set when element i is not a finite number."""
        mode = self._bound(C.GL_MATRIX_MODE)
        pname = {C.GL_MODELVIEW: C.GL_MODELVIEW_MATRIX, C.GL_PROJECTION: C.GL_PROJECTION_MATRIX,
                 C.GL_TEXTURE: C.GL_TEXTURE_MATRIX}.get(mode)
        vals = self._get(pname)[0] if pname is not None else [1.0 if i % 5 == 0 else 0.0 for i in range(16)]
        if pname is None:  # the palette matrix is not gettable (OES_matrix_palette)
            status = 0xFFFF
        else:
            status = 0
        mant = np.zeros(16, dtype=np.int32)
        expo = np.zeros(16, dtype=np.int32)
        for i, v in enumerate(vals):
            if not np.isfinite(v):
                status |= 1 << i
                continue
            m, e = np.frexp(v)          # v = m 2^e, |m| in [0.5, 1)
            mant[i] = int(np.floor(m * 65536.0 + 0.5))
            expo[i] = int(e)
        return mant, expo, status

    # {================================================================
    # matrices

    def _vector(self, values: Any, count: int, ctype: str, what: str) -> Any:
        """The core's double[count] for a fixed-length vector argument:
        GLfixed values as the reals they stand for, GLfloat ones as they are."""
        if "GLfixed" in ctype:
            vals = _values(values, count, what, np.int64)[:count] * _FIX
        else:
            vals = _values(values, count, what)[:count]
        return self._ffi.new(f"double[{count}]", vals.tolist())

    # {================================================================
    # current values

    def glColor4ub(self, r: int, g: int, b: int, a: int) -> None:
        # Table 2.7: c / 255
        vals: Any = (r, g, b, a)
        if not (type(r) is int and type(g) is int and type(b) is int and type(a) is int
                and 0 <= r <= 255 and 0 <= g <= 255 and 0 <= b <= 255 and 0 <= a <= 255):
            # (four plain ints in range, the usual call, need no conversion)
            vals = [_index(c) for c in vals]
            for c in vals:
                if not 0 <= c <= 255:
                    raise ValueError(f"{_describe(c, 'glColor4ub argument')} does not fit GLubyte")
        with self._lock:
            self._lib.gles_Color4(self._p, vals[0] / 255.0, vals[1] / 255.0, vals[2] / 255.0, vals[3] / 255.0)

    # {================================================================
    # lighting (§2.12)

    def _params(self, pname: int, params: Any, fixed: bool, what: str) -> Any:
        n = _PARAM_COUNT.get(_index(pname), 1)
        vals = _plain_or_values(params, n, "x" if fixed else "f", what)
        out = [0.0, 0.0, 0.0, 0.0]
        for i in range(n):
            out[i] = float(vals[i]) * _FIX if fixed else float(vals[i])
        return self._ffi.new("double[4]", out)

    def _scalar(self, param: Any, fixed: bool) -> Any:
        return self._ffi.new("double[4]", [_fixed(param) if fixed else _real(param), 0.0, 0.0, 0.0])

    def _pname_values(self, family: str, pname: Any, value: Any, form: str, vector: bool, what: str) -> Any:
        """The core's double[4] for the value(s) of a pname command: `form` is
        its suffix (x: 16.16, f: reals, i: integers), `family` says how its
        pnames read them ("tex": _tex_values; "fog": FOG_MODE is an enum;
        "lighting": a count per pname, reals)."""
        if family == "tex":
            return self._tex_values(pname, value, form, vector, what)
        fixed = form == "x"
        if family == "fog" and _index(pname) == C.GL_FOG_MODE:
            mode = _values(value, 1, what, np.int64 if fixed else np.float64)[0] if vector else value
            return self._fog_scalar(pname, mode, fixed)
        return self._params(pname, value, fixed, what) if vector else self._scalar(value, fixed)

    def _get_lm(self, fn: Any, target: int, pname: int) -> list[float]:
        out = self._ffi.new("double[4]")
        with self._lock:
            n = fn(self._p, target, pname, out)
        return [out[i] for i in range(n)]

    def glGetLightxv(self, light: int, pname: int) -> Any:
        """Light state as 16.16, saturated to the GLfixed range (§6.1.2)."""
        vals = self._get_lm(self._lib.gles_GetLight, light, pname)
        return self._result([_to_fixed(v) for v in vals], np.int32)

    def glGetMaterialxv(self, face: int, pname: int) -> Any:
        """Material state as 16.16, saturated to the GLfixed range (§6.1.2)."""
        vals = self._get_lm(self._lib.gles_GetMaterial, face, pname)
        return self._result([_to_fixed(v) for v in vals], np.int32)

    # {================================================================
    # per-fragment operations (§4.1) and fog (§3.8)

    def _fog_scalar(self, pname: int, param: Any, fixed: bool) -> Any:
        # FOG_MODE takes an enum, never scaled
        if _index(pname) == C.GL_FOG_MODE:
            v = float(_index(param)) if fixed else _real(param)
        else:
            v = _fixed(param) if fixed else _real(param)
        return self._ffi.new("double[4]", [v, 0.0, 0.0, 0.0])

    # {================================================================
    # textures (§3.7)

    def _gen(self, core: Any, n: Any) -> Any:
        """glGen*: an int for n == 1, else a uint32 array (None on a GL error)."""
        n = _index(n)
        if self._names_too_many(n):
            return None
        out = self._ffi.new("unsigned int[]", max(n, 1))
        with self._lock:
            core(self._p, n, out if n >= 0 else self._ffi.NULL)
        if n < 0:
            return None
        names = [int(out[i]) for i in range(n)]
        return names[0] if n == 1 else np.array(names, dtype=np.uint32)

    def _delete(self, core: Any, n: Any, names: Any, what: str) -> None:
        """glDelete*: (names) with n their count, as PyOpenGL, or (n, names)."""
        n, names = _count_names(n, names, what)
        head = _names(n, names, what)
        buf = self._ffi.new("unsigned int[]", [int(v) for v in head] or [0])
        with self._lock:
            core(self._p, n, buf)

    def glGenTextures(self, n: int) -> Any:
        """Texture object names: an int for n == 1, else a uint32 array."""
        return self._gen(self._lib.gles_GenTextures, n)

    def glDeleteTextures(self, n: Any, textures: Any = _INFER) -> None:
        """Delete texture objects: ``glDeleteTextures(names)`` (n is the
        sequence's length, as PyOpenGL) or the C form ``(n, names)``."""
        self._delete(self._lib.gles_DeleteTextures, n, textures, "glDeleteTextures")

    def _pixels(self, data: Pointer, what: str, gltype: Any = None) -> tuple[Any, int, Any]:
        """Client image data: an array whose dtype fits `gltype` (uint8 for
        UNSIGNED_BYTE; uint16 for the packed 16-bit types, or uint8 as their
        raw bytes), bytes, or a sequence of values converted to that dtype.
        Compressed data (no `gltype`) is raw bytes."""
        if data is None:
            return self._ffi.NULL, -1, None
        if isinstance(data, (int, np.integer)) and not isinstance(data, bool):
            raise TypeError(f"{what}: pixel data must be an array or bytes (ES 1.1 has no pixel buffers)")
        want = _PIXEL_DTYPES.get(int(gltype)) if isinstance(gltype, (int, np.integer)) else None
        if want is None:
            # compressed data, or a type the core refuses with INVALID_ENUM
            return self._pointer(data, None, 0, what)
        if isinstance(data, np.ndarray):
            if data.dtype != want and data.dtype != np.uint8:
                raise TypeError(f"{what}: pixels dtype {data.dtype} does not fit {C.NAMES.get(int(gltype))} "
                                f"({want}" + (")" if want == np.uint8 else ", or uint8 raw bytes)"))
            return self._pointer(data, None, 0, what)
        if isinstance(data, (bytes, bytearray, memoryview)):
            return self._pointer(data, None, 0, what)
        try:
            arr = np.asarray(data)
        except (TypeError, ValueError) as e:
            raise TypeError(f"{what}: pixels must be an array, bytes or numbers ({e})") from None
        if arr.dtype.kind not in "biu":
            raise TypeError(f"{what}: pixels hold {arr.dtype} values; {C.NAMES.get(int(gltype))} takes "
                            f"integers ({want})")
        if arr.size and (arr.min() < 0 or arr.max() > np.iinfo(want).max):
            raise ValueError(f"{what}: a pixel value does not fit {want}")
        return self._pointer(arr.astype(want), None, 0, what)

    def _image(self, core: Any, args: tuple, type: Any, pixels: Pointer, what: str) -> None:
        """TexImage2D/TexSubImage2D: `args` up to the type, then the pixels
        (checked against the type) with their length."""
        ptr, nbytes, keep = self._pixels(pixels, what, type)
        with self._lock:
            st = core(self._p, *args, type, ptr, nbytes)
        del keep
        self._status(st)

    def glTexImage2D(self, target: int, level: int, internalformat: int, width: int, height: int, border: int,
                     format: int, type: int, pixels: Pointer) -> None:
        """Specify a texture image (§3.7.1); pixels None leaves it undefined."""
        self._image(self._lib.gles_TexImage2D, (target, level, internalformat, width, height, border, format),
                    type, pixels, "glTexImage2D")

    def glTexSubImage2D(self, target: int, level: int, xoffset: int, yoffset: int, width: int, height: int,
                        format: int, type: int, pixels: Pointer) -> None:
        """Replace a rectangle of a texture image (§3.7.2)."""
        self._image(self._lib.gles_TexSubImage2D, (target, level, xoffset, yoffset, width, height, format),
                    type, pixels, "glTexSubImage2D")

    def glCompressedTexImage2D(self, target: int, level: int, internalformat: int, width: int, height: int,
                               border: int, imageSize: int, data: Pointer) -> None:
        """OES_compressed_paletted_texture's ten PALETTE*_OES formats, where
        a negative level gives -level + 1 mip levels in one image, and
        OES_compressed_ETC1_RGB8_texture's ETC1_RGB8_OES, one level of 4x4
        blocks (imageSize = ceil(width / 4) * ceil(height / 4) * 8)."""
        # the GL rules (imageSize against the format, size and levels) come
        # first; the core raises for data shorter than it would read only after
        ptr, nbytes, keep = self._pixels(data, "glCompressedTexImage2D")
        with self._lock:
            st = self._lib.gles_CompressedTexImage2D(self._p, target, level, internalformat, width, height,
                                                     border, imageSize, ptr, nbytes)
        del keep
        self._status(st)

    def glCompressedTexSubImage2D(self, target: int, level: int, xoffset: int, yoffset: int, width: int,
                                  height: int, format: int, imageSize: int, data: Pointer) -> None:
        ptr, _, keep = self._pixels(data, "glCompressedTexSubImage2D")
        with self._lock:
            self._lib.gles_CompressedTexSubImage2D(self._p, target, level, xoffset, yoffset, width, height,
                                                   format, imageSize, ptr)
        del keep

    def _tex_values(self, pname: int, params: Any, form: str, vector: bool, what: str) -> Any:
        """Doubles for a texture parameter: x forms scale reals, i forms
        map reals like colours, enums and integers pass unchanged."""
        n = _TEX_COUNT.get(_index(pname), 1) if vector else 1
        raw = _plain_or_values(params if vector else (params,), n, form, what)
        real = _index(pname) in _TEX_REAL
        out = [0.0, 0.0, 0.0, 0.0]
        for i in range(n):
            v = raw[i]
            if form == "x" and real:
                out[i] = int(v) * _FIX
            elif form == "i" and real and _index(pname) == C.GL_TEXTURE_ENV_COLOR:
                out[i] = (2.0 * int(v) + 1.0) / (2.0**32 - 1.0)
            else:
                out[i] = float(v)
        return self._ffi.new("double[4]", out)

    def _tex_get(self, fn: Any, target: int, pname: int, form: str) -> Any:
        out = self._ffi.new("double[4]")
        with self._lock:
            n = fn(self._p, target, pname, out)
        vals = [out[i] for i in range(n)]
        real = _index(pname) in _TEX_REAL
        if form == "f":
            return self._result([float(v) for v in vals], np.float32)
        if form == "x":
            conv = [_to_fixed(v) if real else _to_int(v) for v in vals]
        elif _index(pname) == C.GL_TEXTURE_ENV_COLOR:
            conv = [_norm_to_int(v) for v in vals]
        else:
            conv = [_to_int(v) for v in vals]
        return self._result(conv, np.int32)

    def glGetTexParameteriv(self, target: int, pname: int) -> Any:
        return self._tex_get(self._lib.gles_GetTexParameter, target, pname, "i")

    def glGetTexParameterxv(self, target: int, pname: int) -> Any:
        return self._tex_get(self._lib.gles_GetTexParameter, target, pname, "x")

    def glGetTexEnviv(self, target: int, pname: int) -> Any:
        return self._tex_get(self._lib.gles_GetTexEnv, target, pname, "i")

    def glGetTexEnvxv(self, target: int, pname: int) -> Any:
        return self._tex_get(self._lib.gles_GetTexEnv, target, pname, "x")

    def glGetTexGenivOES(self, coord: int, pname: int) -> Any:
        """TEXTURE_GEN_MODE_OES of the active unit's TEXTURE_GEN_STR_OES (OES_texture_cube_map)."""
        return self._tex_get(self._lib.gles_GetTexGen, coord, pname, "i")

    def glGetTexGenxvOES(self, coord: int, pname: int) -> Any:
        """The same; the mode is an enum, unscaled (§6.1.2)."""
        return self._tex_get(self._lib.gles_GetTexGen, coord, pname, "x")

    # {================================================================
    # points, lines and polygon offset (§3.3-3.5)

    # {================================================================
    # OES_draw_texture

    def _draw_tex(self, vals: list[float]) -> None:
        with self._lock:
            self._lib.gles_DrawTexOES(self._p, *vals)

    def glDrawTexsOES(self, x: int, y: int, z: int, width: int, height: int) -> None:
        """Draw the enabled textures' crop rectangles to a window rectangle."""
        self._draw_tex([float(_index(v)) for v in (x, y, z, width, height)])

    def glDrawTexiOES(self, x: int, y: int, z: int, width: int, height: int) -> None:
        self._draw_tex([float(_index(v)) for v in (x, y, z, width, height)])

    def glDrawTexxOES(self, x: int, y: int, z: int, width: int, height: int) -> None:
        self._draw_tex([_fixed(v) for v in (x, y, z, width, height)])

    def glDrawTexsvOES(self, coords: Any) -> None:
        self._draw_tex([float(v) for v in _values(coords, 5, "glDrawTexsvOES", np.int64)[:5]])

    def glDrawTexivOES(self, coords: Any) -> None:
        self._draw_tex([float(v) for v in _values(coords, 5, "glDrawTexivOES", np.int64)[:5]])

    def glDrawTexxvOES(self, coords: Any) -> None:
        self._draw_tex([int(v) * _FIX for v in _values(coords, 5, "glDrawTexxvOES", np.int64)[:5]])

    # {================================================================
    # vertex arrays and buffer objects

    def _set_pointer(self, key: Any, fn: Any, args: tuple, gltype: int, pointer: Pointer, what: str) -> None:
        ptr, nbytes, keep = self._pointer(pointer, gltype, C.GL_ARRAY_BUFFER_BINDING, what)
        with self._lock:
            # a rejected call leaves the old array in use: keep holding it;
            # so does a call into a vertex array object (OES_vertex_array_object),
            # which holds buffer arrays only, while name 0's client arrays wait
            vao = self._bound(C.GL_VERTEX_ARRAY_BINDING_OES)
            if fn(self._p, *args, ptr, nbytes) and not vao:
                self._keep[key] = keep

    def glVertexPointer(self, size: int, type: int, stride: int, pointer: Pointer) -> None:
        self._set_pointer("vertex", self._lib.gles_VertexPointer, (size, type, stride), type, pointer,
                          "glVertexPointer")

    def glColorPointer(self, size: int, type: int, stride: int, pointer: Pointer) -> None:
        self._set_pointer("color", self._lib.gles_ColorPointer, (size, type, stride), type, pointer,
                          "glColorPointer")

    def glNormalPointer(self, type: int, stride: int, pointer: Pointer) -> None:
        self._set_pointer("normal", self._lib.gles_NormalPointer, (type, stride), type, pointer,
                          "glNormalPointer")

    def glTexCoordPointer(self, size: int, type: int, stride: int, pointer: Pointer) -> None:
        unit = self._bound(C.GL_CLIENT_ACTIVE_TEXTURE)
        self._set_pointer(("texcoord", unit), self._lib.gles_TexCoordPointer, (size, type, stride), type,
                          pointer, "glTexCoordPointer")

    def glPointSizePointerOES(self, type: int, stride: int, pointer: Pointer) -> None:
        self._set_pointer("pointsize", self._lib.gles_PointSizePointerOES, (type, stride), type, pointer,
                          "glPointSizePointerOES")

    def glMatrixIndexPointerOES(self, size: int, type: int, stride: int, pointer: Pointer) -> None:
        """OES_matrix_palette: per-vertex palette indices (UNSIGNED_BYTE)."""
        self._set_pointer("matrixindex", self._lib.gles_MatrixIndexPointerOES, (size, type, stride), type,
                          pointer, "glMatrixIndexPointerOES")

    def glWeightPointerOES(self, size: int, type: int, stride: int, pointer: Pointer) -> None:
        """OES_matrix_palette: per-vertex weights (FIXED or FLOAT)."""
        self._set_pointer("weight", self._lib.gles_WeightPointerOES, (size, type, stride), type, pointer,
                          "glWeightPointerOES")

    def glGenBuffers(self, n: int) -> Any:
        """Buffer object names: an int for n == 1, else a uint32 array."""
        return self._gen(self._lib.gles_GenBuffers, n)

    def glDeleteBuffers(self, n: Any, buffers: Any = _INFER) -> None:
        """Delete buffer objects: ``glDeleteBuffers(names)`` (n is the
        sequence's length, as PyOpenGL) or the C form ``(n, names)``."""
        self._delete(self._lib.gles_DeleteBuffers, n, buffers, "glDeleteBuffers")

    def glGenVertexArraysOES(self, n: int) -> Any:
        """OES_vertex_array_object names: an int for n == 1, else a uint32 array."""
        return self._gen(self._lib.gles_GenVertexArraysOES, n)

    def glDeleteVertexArraysOES(self, n: Any, arrays: Any = _INFER) -> None:
        """Delete vertex array objects: ``(names)`` or the C form ``(n, names)``;
        deleting the bound one binds 0."""
        self._delete(self._lib.gles_DeleteVertexArraysOES, n, arrays, "glDeleteVertexArraysOES")

    # {================================================================
    # framebuffer objects (OES_framebuffer_object)

    def glGenFramebuffersOES(self, n: int) -> Any:
        """Framebuffer object names: an int for n == 1, else a uint32 array."""
        return self._gen(self._lib.gles_GenFramebuffersOES, n)

    def glDeleteFramebuffersOES(self, n: Any, framebuffers: Any = _INFER) -> None:
        """Delete framebuffer objects: ``(names)`` or ``(n, names)``;
        deleting the bound one binds the window again."""
        self._delete(self._lib.gles_DeleteFramebuffersOES, n, framebuffers, "glDeleteFramebuffersOES")

    def glGenRenderbuffersOES(self, n: int) -> Any:
        """Renderbuffer object names: an int for n == 1, else a uint32 array."""
        return self._gen(self._lib.gles_GenRenderbuffersOES, n)

    def glDeleteRenderbuffersOES(self, n: Any, renderbuffers: Any = _INFER) -> None:
        """Delete renderbuffer objects (detached from every framebuffer object)."""
        self._delete(self._lib.gles_DeleteRenderbuffersOES, n, renderbuffers, "glDeleteRenderbuffersOES")

    def glDiscardFramebufferEXT(self, target: int, numAttachments: Any, attachments: Any = _INFER) -> None:
        """EXT_discard_framebuffer: ``(target, attachments)`` or the C form
        ``(target, n, attachments)``; a hint (gles keeps the contents)."""
        if attachments is _INFER:
            attachments, numAttachments = numAttachments, None
        vals = _values(attachments, 0, "glDiscardFramebufferEXT", np.int64)
        n = len(vals) if numAttachments is None else _glint(numAttachments, "numAttachments")
        if n > len(vals):
            raise ValueError(f"glDiscardFramebufferEXT: numAttachments is {n}, attachments holds {len(vals)}")
        if n > 0 and (vals[:n].min() < 0 or vals[:n].max() > 0xFFFFFFFF):
            raise ValueError("glDiscardFramebufferEXT: an attachment does not fit GLenum")
        buf = self._ffi.new("unsigned int[]", [int(v) for v in vals[:max(n, 0)]] or [0])
        with self._lock:
            self._lib.gles_DiscardFramebufferEXT(self._p, _index(target), n, buf)

    def glCheckFramebufferStatusOES(self, target: int) -> int:
        """FRAMEBUFFER_COMPLETE_OES or why the bound framebuffer object is
        not (0 on a GL error)."""
        with self._lock:
            return int(self._lib.gles_CheckFramebufferStatusOES(self._p, _index(target)))

    def glGetRenderbufferParameterivOES(self, target: int, pname: int) -> int | None:
        """One value of the bound renderbuffer (RENDERBUFFER_WIDTH_OES, ...); None on a GL error."""
        out = self._ffi.new("int[1]")
        with self._lock:
            ok = self._lib.gles_GetRenderbufferParameterivOES(self._p, _index(target), _index(pname), out)
        return int(out[0]) if ok else None

    def glGetFramebufferAttachmentParameterivOES(self, target: int, attachment: int,
                                                  pname: int) -> int | None:
        """One value of an attachment point of the bound framebuffer object
        (FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, ...); None on a GL error."""
        out = self._ffi.new("int[1]")
        args = (_index(target), _index(attachment), _index(pname))
        with self._lock:
            ok = self._lib.gles_GetFramebufferAttachmentParameterivOES(self._p, *args, out)
        return int(out[0]) if ok else None

    # {================================================================
    # mapped buffers (OES_mapbuffer, EXT_map_buffer_range)
    #
    # A mapping reaches Python as a numpy copy of the mapped bytes, written
    # into the buffer at glUnmapBufferOES (or, with MAP_FLUSH_EXPLICIT_BIT,
    # range by range at glFlushMappedBufferRangeEXT): an array kept past the
    # unmap, or past a glBufferData or glDeleteBuffers that ends the mapping,
    # is ordinary memory, never the freed store. The copies go through the
    # core, so traces hold them.

    def _map_copy(self, target: int, ptr: Any, offset: int, length: int, access: int) -> np.ndarray | None:
        if ptr == self._ffi.NULL:
            return None
        copy = np.frombuffer(self._ffi.buffer(ptr, length), dtype=np.uint8).copy()
        name = self._bound(_BUFFER_BINDINGS[target])
        self._maps[name] = _Mapping(copy, offset, access)
        return copy

    def _map_write(self, target: int, m: _Mapping, start: int, stop: int) -> None:
        """Bytes start..stop of the mapping's copy into the buffer."""
        part = np.ascontiguousarray(m.array[start:stop])
        st = self._lib.gles_buffer_map_write(self._p, target, m.offset + start, self._ffi.from_buffer(part),
                                             part.nbytes)
        self._status(st)

    def _mapped(self, target: int) -> _Mapping | None:
        """The live mapping of the buffer bound to target, if Python made it."""
        name = self._bound(_BUFFER_BINDINGS[target])
        out = self._ffi.new("int[1]")
        self._lib.gles_GetBufferParameteriv(self._p, target, C.GL_BUFFER_MAPPED_OES, out)
        return self._maps.get(name) if out[0] else None

    def glMapBufferOES(self, target: int, access: int) -> np.ndarray | None:
        """OES_mapbuffer: map the buffer bound to target (access
        GL_WRITE_ONLY_OES). Returns a writable uint8 array of its bytes, which
        glUnmapBufferOES writes into the buffer; None on a GL error."""
        target, access = _index(target), _index(access)
        with self._lock:
            ptr = self._lib.gles_MapBufferOES(self._p, target, access)
            size = self._bound_buffer_size(target) if ptr != self._ffi.NULL else 0
            return self._map_copy(target, ptr, 0, size or 0, C.GL_MAP_WRITE_BIT_EXT)

    def glMapBufferRangeEXT(self, target: int, offset: int, length: int, access: int) -> np.ndarray | None:
        """EXT_map_buffer_range: map `length` bytes from `offset` with the
        MAP_*_BIT_EXT `access`. Returns a uint8 array of those bytes (their
        current values, also where the range is invalidated), written back
        at glUnmapBufferOES when MAP_WRITE_BIT_EXT is set, or by
        glFlushMappedBufferRangeEXT with MAP_FLUSH_EXPLICIT_BIT_EXT; None on
        a GL error."""
        target, offset, length, access = _index(target), _index(offset), _index(length), _index(access)
        with self._lock:
            ptr = self._lib.gles_MapBufferRangeEXT(self._p, target, offset, length, access)
            return self._map_copy(target, ptr, offset, length, access)

    def glFlushMappedBufferRangeEXT(self, target: int, offset: int, length: int) -> None:
        """EXT_map_buffer_range: write bytes offset..offset + length of the
        mapping (from its start) into the buffer."""
        target, offset, length = _index(target), _index(offset), _index(length)
        with self._lock:
            before = self._lib.gles_GetError(self._p)
            self._lib.gles_FlushMappedBufferRangeEXT(self._p, target, offset, length)
            err = self._lib.gles_GetError(self._p)
            if before or err:
                self._lib.gles_set_error(self._p, before or err)
            m = None if err else self._mapped(target)
            if m is not None:
                self._map_write(target, m, offset, offset + length)

    def glUnmapBufferOES(self, target: int) -> bool:
        """OES_mapbuffer: end the mapping, its array's bytes written into the
        buffer (all of them for a write mapping without
        MAP_FLUSH_EXPLICIT_BIT_EXT); False on a GL error."""
        target = _index(target)
        with self._lock:
            if target in _BUFFER_BINDINGS:
                m = self._mapped(target)
                if m is not None and m.access & C.GL_MAP_WRITE_BIT_EXT \
                        and not m.access & C.GL_MAP_FLUSH_EXPLICIT_BIT_EXT:
                    self._map_write(target, m, 0, m.array.nbytes)
                self._maps.pop(self._bound(_BUFFER_BINDINGS[target]), None)
            return bool(self._lib.gles_UnmapBufferOES(self._p, target))

    def glGetBufferPointervOES(self, target: int, pname: int) -> np.ndarray | None:
        """OES_mapbuffer: BUFFER_MAP_POINTER_OES as the mapping's array (the
        one glMapBuffer* returned), None when the buffer is not mapped."""
        target, pname = _index(target), _index(pname)
        out = self._ffi.new("void *[1]")
        with self._lock:
            ok = self._lib.gles_GetBufferPointervOES(self._p, target, pname, out)
            if not ok or out[0] == self._ffi.NULL:
                return None
            m = self._mapped(target)
            return None if m is None else m.array

    def _buffer_data(self, data: Pointer, what: str) -> tuple[Any, int, Any]:
        """The bytes a Buffer(Sub)Data call copies from: an array, bytes or a
        sequence, never an int (no command reads from an address)."""
        if isinstance(data, (int, np.integer)):
            raise TypeError(f"{what}: data must be an array, bytes or None, not an int")
        return self._pointer(data, None, 0, what)

    def _bound_buffer_size(self, target: int) -> int | None:
        """Size of the buffer bound to target (None: no buffer or a bad target)."""
        binding = {C.GL_ARRAY_BUFFER: C.GL_ARRAY_BUFFER_BINDING,
                   C.GL_ELEMENT_ARRAY_BUFFER: C.GL_ELEMENT_ARRAY_BUFFER_BINDING}.get(target)
        if binding is None or self._bound(binding) == 0:
            return None
        out = self._ffi.new("int[1]")
        self._lib.gles_GetBufferParameteriv(self._p, target, C.GL_BUFFER_SIZE, out)
        return int(out[0])

    def glBufferData(self, target: int, size: Any, data: Pointer = _INFER, usage: Any = _INFER) -> None:
        """Replace the bound buffer's store with size bytes (zeros when data
        is None). Past the context's memory budget: OUT_OF_MEMORY, the buffer
        unchanged. ``glBufferData(target, data, usage)`` takes the size from
        the data, as PyOpenGL does."""
        if usage is _INFER:
            if data is _INFER:
                raise TypeError("glBufferData takes (target, size, data, usage) or (target, data, usage)")
            size, data, usage = _INFER, size, data
        if size is _INFER:
            if data is None or isinstance(data, (int, np.integer)):
                raise TypeError("glBufferData(target, data, usage): data must be an array, bytes or "
                                f"a sequence to take the size from, not {type(data).__name__}")
            _, size, _ = self._buffer_data(data, "glBufferData")
        size = _index(size)
        if data is None:
            ptr, nbytes, keep = self._ffi.NULL, size, None
        else:
            ptr, nbytes, keep = self._buffer_data(data, "glBufferData")
        with self._lock:
            if nbytes >= 0 and size > nbytes:
                # a GL error decides first; only a call that would copy
                # past the data raises
                if (target in (C.GL_ARRAY_BUFFER, C.GL_ELEMENT_ARRAY_BUFFER)
                        and usage in (C.GL_STATIC_DRAW, C.GL_DYNAMIC_DRAW)
                        and self._bound_buffer_size(target) is not None):
                    raise ValueError(f"glBufferData: size is {size} but the data holds {nbytes} bytes")
                ptr = self._ffi.NULL
            st = self._lib.gles_BufferData(self._p, target, size, ptr, usage)
        del keep
        self._status(st)

    def glBufferSubData(self, target: int, offset: int, size: Any, data: Pointer = _INFER) -> None:
        """Copy size bytes of data into the bound buffer at offset.
        ``glBufferSubData(target, offset, data)`` copies all of the data, as
        PyOpenGL does."""
        if data is _INFER:
            data = size
            if data is None or isinstance(data, (int, np.integer)):
                raise TypeError("glBufferSubData(target, offset, data): data must be an array, bytes or "
                                f"a sequence to take the size from, not {type(data).__name__}")
            _, size, _ = self._buffer_data(data, "glBufferSubData")
        size, offset = _index(size), _index(offset)
        ptr, nbytes, keep = self._buffer_data(data, "glBufferSubData")
        with self._lock:
            if nbytes >= 0 and size > nbytes:
                held = self._bound_buffer_size(target)
                if held is not None and 0 <= offset <= held and 0 <= size <= held - offset:
                    raise ValueError(f"glBufferSubData: size is {size} but the data holds {nbytes} bytes")
                ptr = self._ffi.NULL    # the core records the GL error and copies nothing
            self._lib.gles_BufferSubData(self._p, target, offset, size, ptr)
        del keep

    # {================================================================
    # drawing and pixels

    def glDrawArrays(self, mode: int, first: int, count: int) -> None:
        with self._lock:
            st = self._lib.gles_DrawArrays(self._p, mode, first, count)
        if st:
            self._status(st, "glDrawArrays")

    def glDrawElements(self, mode: int, count: int, type: int, indices: Pointer) -> None:
        if type not in _INDEX_DTYPES:
            # the core records INVALID_ENUM; nothing is read
            with self._lock:
                self._lib.gles_DrawElements(self._p, mode, count, type, self._ffi.NULL, 0)
            return
        ptr, nbytes, keep = self._pointer(indices, type, C.GL_ELEMENT_ARRAY_BUFFER_BINDING, "glDrawElements",
                                          _INDEX_DTYPES[type])
        with self._lock:
            st = self._lib.gles_DrawElements(self._p, mode, count, type, ptr, nbytes)
        del keep
        if st:
            self._status(st, "glDrawElements")

    def _multi_lists(self, primcount: Any, what: str, **lists: Any) -> tuple[int, dict[str, list[Any]]]:
        """primcount and the first primcount items of each list (ValueError
        when one is shorter); a negative primcount records INVALID_VALUE."""
        n = _glint(primcount, "primcount")
        out = {}
        for name, seq in lists.items():
            items = list(seq) if n > 0 else []
            if len(items) < n:
                raise ValueError(f"{what}: {name} holds {len(items)} items, primcount is {n}")
            out[name] = items[:n]
        if n < 0:
            with self._lock:
                self._lib.gles_set_error(self._p, C.GL_INVALID_VALUE)
        return n, out

    def _draw_each(self, draws: list[tuple[Any, ...]], draw: Any) -> None:
        """draw(*args) for each args of `draws` until one records a GL error
        or raises: one call never does both (the C ABI stops likewise). An
        error recorded before the call stays the first."""
        with self._lock:
            before = self._lib.gles_GetError(self._p)
        new = 0
        try:
            for args in draws:
                draw(*args)
                with self._lock:
                    new = self._lib.gles_GetError(self._p)
                if new:
                    break
        finally:
            if before or new:
                with self._lock:
                    self._lib.gles_set_error(self._p, before or new)

    def glMultiDrawArraysEXT(self, mode: int, first: Any, count: Any, primcount: Any) -> None:
        """EXT_multi_draw_arrays: glDrawArrays(mode, first[i], count[i]) for
        each i < primcount with count[i] > 0 (the extension's loop), up to the
        first draw that records a GL error or raises."""
        _, lists = self._multi_lists(primcount, "glMultiDrawArraysEXT", first=first, count=count)
        pairs = [(_glint(f, "first"), _glint(c, "count")) for f, c in zip(lists["first"], lists["count"])]
        self._draw_each([(mode, f, c) for f, c in pairs if c > 0], self.glDrawArrays)

    def glMultiDrawElementsEXT(self, mode: int, count: Any, type: int, indices: Any, primcount: Any) -> None:
        """EXT_multi_draw_arrays: glDrawElements(mode, count[i], type,
        indices[i]) for each i < primcount with count[i] > 0; indices[i] is
        an index array, or a byte offset while an element array buffer is
        bound. Stops as glMultiDrawArraysEXT does."""
        _, lists = self._multi_lists(primcount, "glMultiDrawElementsEXT", count=count, indices=indices)
        counts = [_glint(c, "count") for c in lists["count"]]
        self._draw_each([(mode, c, type, ix) for c, ix in zip(counts, lists["indices"]) if c > 0],
                        self.glDrawElements)

    def glReadPixels(self, x: int, y: int, width: int, height: int, format: int, type: int,
                     array: Any = None) -> Any:
        """Read a rectangle, bottom row first as GL defines.

        Returns the part of the rectangle inside the framebuffer (§4.3.1:
        pixels outside it are undefined, so they are neither read nor
        allocated): rows from max(y, 0), columns from max(x, 0); uint8
        (h, w, 4) for GL_RGBA/GL_UNSIGNED_BYTE and, on an RGBA8888 window,
        GL_BGRA_EXT/GL_UNSIGNED_BYTE (EXT_read_format_bgra: B, G, R, A), and
        uint16 (h, w) for a 16-bit buffer's own pair (GL_RGB/GL_UNSIGNED_SHORT_5_6_5 on
        RGB565, GL_RGBA/GL_UNSIGNED_SHORT_4_4_4_4 on RGBA4444, GL_RGBA/GL_UNSIGNED_SHORT_5_5_5_1
        on RGBA5551). With ``array`` (a writable buffer)
        the whole rectangle's raw rows are written into it with
        PACK_ALIGNMENT padding instead (zeros outside the framebuffer), and
        None is returned. On a GL error nothing is written and None is
        returned.
        """
        x, y, width, height = (_glint(v, name) for v, name in
                               ((x, "x"), (y, "y"), (width, "width"), (height, "height")))
        if array is not None:
            try:
                buf = self._ffi.from_buffer(array, require_writable=True)
            except TypeError:
                raise TypeError("glReadPixels: array must be a writable buffer") from None
            with self._lock:
                st = self._lib.gles_ReadPixels(self._p, x, y, width, height, format, type, buf, len(buf))
            self._status(st)
            return None
        if width >= 0 and height >= 0:
            # clip to the framebuffer read (the window, or a framebuffer
            # object's); a negative size goes on unchanged so that the core
            # records INVALID_VALUE
            size = self._ffi.new("int[2]")
            with self._lock:
                self._lib.gles_draw_size(self._p, size)
            x0, y0 = max(x, 0), max(y, 0)
            width = max(min(x + width, size[0]) - x0, 0)
            height = max(min(y + height, size[1]) - y0, 0)
            x, y = x0, y0
        bpp = 4 if type == C.GL_UNSIGNED_BYTE and format in (C.GL_RGBA, C.GL_BGRA_EXT) else 2
        align = self._bound(C.GL_PACK_ALIGNMENT)
        stride = -(-max(width, 0) * bpp // align) * align
        raw = np.zeros(max(stride * max(height, 0), 1), dtype=np.uint8)
        with self._lock:
            err_before = self._lib.gles_GetError(self._p)
            st = self._lib.gles_ReadPixels(self._p, x, y, width, height, format, type,
                                           self._ffi.from_buffer(raw), raw.nbytes)
            err = self._lib.gles_GetError(self._p)
            # keep the spec's sticky first error
            first = err_before or err
            if first:
                self._lib.gles_set_error(self._p, first)
        self._status(st)
        if err:
            return None
        rows = raw[: stride * height].reshape(height, stride)[:, : width * bpp]
        if bpp == 4:
            return rows.reshape(height, width, 4).copy()
        return rows.copy().view(np.uint16).reshape(height, width)


class GLCommon(GLBase):
    """The Common-profile command set: Common-Lite plus the float commands."""

    def glGetFloatv(self, pname: int) -> Any:
        vals, _ = self._get(pname)
        return self._result([float(v) for v in vals], np.float32, pname)

    def glGetLightfv(self, light: int, pname: int) -> Any:
        return self._result(self._get_lm(self._lib.gles_GetLight, light, pname), np.float32)

    def glGetMaterialfv(self, face: int, pname: int) -> Any:
        return self._result(self._get_lm(self._lib.gles_GetMaterial, face, pname), np.float32)

    def glGetTexParameterfv(self, target: int, pname: int) -> Any:
        return self._tex_get(self._lib.gles_GetTexParameter, target, pname, "f")

    def glGetTexEnvfv(self, target: int, pname: int) -> Any:
        return self._tex_get(self._lib.gles_GetTexEnv, target, pname, "f")

    def glGetTexGenfvOES(self, coord: int, pname: int) -> Any:
        return self._tex_get(self._lib.gles_GetTexGen, coord, pname, "f")

    def glDrawTexfOES(self, x: float, y: float, z: float, width: float, height: float) -> None:
        self._draw_tex([_real(v) for v in (x, y, z, width, height)])

    def glDrawTexfvOES(self, coords: Any) -> None:
        self._draw_tex([float(v) for v in _values(coords, 5, "glDrawTexfvOES")[:5]])

    def glGetClipPlanef(self, plane: int) -> np.ndarray:
        eq = self._ffi.new("double[4]")
        with self._lock:
            self._lib.gles_GetClipPlane(self._p, _index(plane), eq)
        return np.array([eq[i] for i in range(4)], dtype=np.float32)


def _checked_class(base: type) -> type:
    """A subclass of `base` whose every command raises GLError on a GL error,
    like PyOpenGL's error checking (glGetError itself is left alone)."""

    def wrap(name: str, fn: Any) -> Any:
        def command(self: GLBase, *args: Any, **kwargs: Any) -> Any:
            result = fn(self, *args, **kwargs)
            with self._lock:    # the core is not to be entered by two threads at once
                err = self._lib.gles_GetError(self._p)
            if err:
                raise GLError(err, name, args)
            return result

        command.__name__ = name
        command.__doc__ = fn.__doc__
        return command

    attrs = {n: wrap(n, getattr(base, n)) for n in dir(base)
             if n.startswith("gl") and n != "glGetError" and callable(getattr(base, n))}
    return type(f"Checked{base.__name__}", (base,), attrs)


# {====================================================================
# the commands built from the command table
#
# Three families are not written out by hand: their methods are generated
# from their rows of gles.commands, under the rows' parameter names, at
# import. A plain command's arguments are all scalars the core takes as they
# are (16.16 arguments become the reals they stand for, GLboolean ones
# bools); a pname command (glLightxv, glTexEnvi, ...) passes its value or
# values through _pname_values, by its x/f/i form, to the core function of
# its family; a vector command (glLoadMatrixx, glClipPlanef, ...) passes a
# fixed number of values through _vector. Only the commands that need more
# (pointers, Get*, Gen/Delete, DrawArrays' status) are written above.

def _core_entry(cmd: Command) -> str:
    """The core function of a plain command: gles_ plus its name without
    gl and, for the x and f forms, without the suffix (glTranslatex and
    glTranslatef both call gles_Translate)."""
    stem = cmd.name[2:]
    candidates = [stem]
    if any(p.kind in ("fixed", "float") for p in cmd.params) and stem[-1] in "xf":
        candidates.append(stem[:-1])
    for c in candidates:
        if hasattr(_CORE_LIB, f"gles_{c}"):
            return f"gles_{c}"
    raise ImportError(f"{cmd.name}: the core has none of {['gles_' + c for c in candidates]}")


def _plain_argument(param: Param) -> str:
    """The expression that passes one scalar argument on to the core."""
    if param.kind == "fixed":
        return f"_fixed({param.name})"
    if param.kind == "bool":
        return f"bool({param.name})"
    if param.kind == "uint" and param.name == "mask":
        return f"_mask({param.name})"      # -1 is all ones, as in C
    return param.name                      # _CoreFunctions names what cffi refuses


def _plain_source(cmd: Command) -> str:
    names = [p.name for p in cmd.params]
    call = f"self._lib.{_core_entry(cmd)}(self._p{''.join(', ' + _plain_argument(p) for p in cmd.params)})"
    result = f"bool({call})" if cmd.ret == "GLboolean" else call
    return (f"def {cmd.name}(self{''.join(', ' + n for n in names)}):\n"
            f"    with self._lock:\n"
            f"        return {result}\n")


def _is_plain(cmd: Command) -> bool:
    return cmd.ret in ("void", "GLboolean") and all(p.kind in _PLAIN_KINDS for p in cmd.params)


_PLAIN_KINDS = frozenset({"enum", "int", "sizei", "uint", "bitfield", "bool", "fixed", "float"})


# the pname commands (glLightxv, glTexEnvi, ...): how each family's values
# read, by the core function they call
_PNAME_FAMILIES = {"Light": "lighting", "LightModel": "lighting", "Material": "lighting",
                   "PointParameter": "lighting", "Fog": "fog", "TexParameter": "tex", "TexEnv": "tex",
                   "TexGen": "tex"}


def _unsuffixed(name: str) -> str:
    """A command's name without gl and an extension's OES suffix
    (glTexGenfvOES: TexGenfv); the core entry and the forms read the rest."""
    stem = name[2:]
    return stem[:-3] if stem.endswith("OES") and stem[:-3].rstrip("v")[-1:] in ("x", "f", "i") else stem


def _pname_form(cmd: Command) -> tuple[str, str, bool] | None:
    """(family, form, vector) of a pname command that sets state, else None."""
    if cmd.name.startswith("glGet") or not any(p.name == "pname" for p in cmd.params):
        return None
    stem = _unsuffixed(cmd.name)
    vector = stem.endswith("v")
    stem = stem[:-1] if vector else stem
    family = _PNAME_FAMILIES.get(stem[:-1])
    return None if family is None or stem[-1] not in "xfi" else (family, stem[-1], vector)


def _pname_source(cmd: Command, family: str, form: str, vector: bool) -> str:
    *lead, value = [p.name for p in cmd.params]
    core = "gles_" + _unsuffixed(cmd.name).rstrip("v")[:-1]
    return (f"def {cmd.name}(self, {', '.join(lead + [value])}):\n"
            f"    buf = self._pname_values({family!r}, pname, {value}, {form!r}, {vector}, {cmd.name!r})\n"
            f"    with self._lock:\n"
            f"        self._lib.{core}(self._p, {', '.join(lead)}, buf, {int(vector)})\n")


# the fixed-length vector commands: how many values each reads, by the core
# function it calls (§2.10.2, §2.11)
_VECTOR_COUNTS = {"LoadMatrix": 16, "MultMatrix": 16, "ClipPlane": 4}


def _vector_source(cmd: Command, count: int) -> str:
    *lead, values = cmd.params
    names = [p.name for p in lead]
    core = "gles_" + cmd.name[2:-1]
    return (f"def {cmd.name}(self, {', '.join(names + [values.name])}):\n"
            f"    buf = self._vector({values.name}, {count}, {values.ctype!r}, {cmd.name!r})\n"
            f"    with self._lock:\n"
            f"        self._lib.{core}(self._p, {''.join(n + ', ' for n in names)}buf)\n")


def _add_plain_commands() -> None:
    scope: dict[str, Any] = {"_fixed": _fixed, "_mask": _mask}
    for cmd in COMMANDS.values():
        cls = GLCommon if cmd.profile == "common" else GLBase
        if cmd.name in vars(cls):
            continue
        pname = _pname_form(cmd)
        count = _VECTOR_COUNTS.get(cmd.name[2:-1]) if cmd.params and cmd.params[-1].kind == "values" else None
        if pname is not None:
            source = _pname_source(cmd, *pname)
        elif count is not None:
            source = _vector_source(cmd, count)
        elif _is_plain(cmd):
            source = _plain_source(cmd)
        else:
            continue
        exec(compile(source, f"<gles.gl {cmd.name}>", "exec"), scope)  # noqa: S102 -- from the table
        fn = scope[cmd.name]
        fn.__qualname__ = f"{cls.__name__}.{cmd.name}"
        fn.__doc__ = cmd.prototype() + (f" ({cmd.extension[3:]})" if cmd.extension else "")
        setattr(cls, cmd.name, fn)
    missing = [c.name for c in COMMANDS.values()
               if not hasattr(GLCommon if c.profile == "common" else GLBase, c.name)]
    if missing:
        raise ImportError(f"table commands with neither a hand-written nor a generated method: {missing}")


_add_plain_commands()

# every GL_* constant is also an attribute of each command set, so that a
# scene written against ``gl`` (ctx.gl, or a Mesa peer's namespace) finds
# gl.GL_TEXTURE_2D wherever it runs
for _n in C.__all__:
    setattr(GLBase, _n, getattr(C, _n))

# ES 1.1 commands that exist but whose stage is not built (each would raise
# NotImplementedError naming it): none
MISSING: dict[str, str] = {}

# the command sets, from the table (the import checks above saw each has its method)
COMMON_LITE_COMMANDS = sorted(n for n, c in COMMANDS.items() if c.profile == "both")
COMMON_COMMANDS = sorted(COMMANDS)
FLOAT_COMMANDS = sorted(n for n, c in COMMANDS.items() if c.profile == "common")

# {====================================================================
# module-level functions on the current context

_current = threading.local()


def _set_current(gl: GLBase | None) -> None:
    _current.gl = gl


def current_gl() -> GLBase:
    """The calling thread's current context's commands."""
    gl = getattr(_current, "gl", None)
    if gl is None:
        raise RuntimeError("no current gles context in this thread: call ctx.make_current() first")
    return gl


def _forwarder(name: str) -> Any:
    def command(*args: Any, **kwargs: Any) -> Any:
        gl = getattr(_current, "gl", None)
        if gl is None:
            gl = current_gl()
        try:
            fn = getattr(gl, name)
        except AttributeError:
            raise AttributeError(
                f"{name} is a Common-profile command; the current context is Common-Lite"
            ) from None
        return fn(*args, **kwargs)

    command.__name__ = name
    command.__qualname__ = name
    method = getattr(GLCommon, name)
    command.__doc__ = method.__doc__
    # help() shows the command's own parameters (the method's, without self)
    sig = inspect.signature(method)
    command.__signature__ = sig.replace(parameters=list(sig.parameters.values())[1:])  # type: ignore[attr-defined]
    return command


for _n in COMMON_COMMANDS:
    globals()[_n] = _forwarder(_n)

__all__ = list(C.__all__) + COMMON_COMMANDS + ["current_gl", "GLBase", "GLCommon", "GLCommonLite"]

GLCommonLite = GLBase
CheckedGLCommon = _checked_class(GLCommon)
CheckedGLCommonLite = _checked_class(GLBase)
