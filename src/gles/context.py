"""gles.Context: one offscreen OpenGL ES 1.1 context and its framebuffer."""

from __future__ import annotations

import os
import threading
from typing import Any, BinaryIO

import numpy as np

from . import _binding
from . import constants as C
from ._png import encode_png, write_png
from .gl import CoreHandle, GLBase, GLCommon, _checked_class, _current, _set_current
from .profile import POLICIES, RangedGLCommon, RangeMonitor, RangeReport

_LIB = _binding.core(_binding.NUMERICS[0]).lib    # the core's numbers (every build exports the same)
PROFILES = {"common": _LIB.GLES_PROFILE_COMMON, "common-lite": _LIB.GLES_PROFILE_COMMON_LITE}
# the core's per-draw rule under each policy: "raise" skips the draw that breaks it
_RANGE_MODE = {"off": _LIB.GLES_RANGE_OFF, "warn": _LIB.GLES_RANGE_CHECK, "clamp": _LIB.GLES_RANGE_CHECK,
               "raise": _LIB.GLES_RANGE_SKIP}

# the command-set class for (profile, range checks on, check_errors)
_GL_CLASSES: dict[tuple[str, bool, bool], type] = {}
for _base, _key in ((GLBase, "common-lite"), (GLCommon, "common")):
    for _ranged in (False, True):
        _cls = RangedGLCommon if (_ranged and _base is GLCommon) else _base
        _GL_CLASSES[(_key, _ranged, False)] = _cls
        _GL_CLASSES[(_key, _ranged, True)] = _checked_class(_cls)

COLOR_FORMATS = {"rgba8888": _LIB.GLES_COLOR_RGBA8888, "rgb565": _LIB.GLES_COLOR_RGB565,
                 "rgba4444": _LIB.GLES_COLOR_RGBA4444, "rgba5551": _LIB.GLES_COLOR_RGBA5551}

# the 16-bit formats' channels R, G, B, A as (bits, lowest bit) in the word,
# as GL's packed types (red in the high bits); (0, 0) for none
COLOR_LAYOUTS: dict[str, tuple[tuple[int, int], ...]] = {
    "rgb565": ((5, 11), (6, 5), (5, 0), (0, 0)),
    "rgba4444": ((4, 12), (4, 8), (4, 4), (4, 0)),
    "rgba5551": ((5, 11), (5, 6), (5, 1), (1, 0)),
}


def expand_color(raw: np.ndarray, color: str) -> np.ndarray:
    """A 16-bit colour buffer's words (uint16, any shape) as uint8 RGBA
    (shape + (4,)): each channel c of m bits becomes c * 255 / (2^m - 1)
    rounded, a missing alpha 255; an RGBA8888 buffer (uint8 (..., 4)) is
    returned as it is."""
    if color == "rgba8888":
        return raw
    if color not in COLOR_LAYOUTS:
        raise ValueError(f"color must be one of {sorted(COLOR_FORMATS)}, not {color!r}")
    words = np.asarray(raw).astype(np.uint32)
    out = np.empty(words.shape + (4,), dtype=np.uint8)
    for i, (bits, shift) in enumerate(COLOR_LAYOUTS[color]):
        if not bits:
            out[..., i] = 255
            continue
        top = (1 << bits) - 1
        out[..., i] = (((words >> shift) & top) * 255 + top // 2) // top
    return out

DEFAULT_MEMORY_LIMIT = 256 << 20    # bytes of texture images and buffer data per context
MAX_THREADS = int(_LIB.GLES_MAX_THREADS)


def default_threads() -> int:
    """The threads a context rasterizes with by default: the CPUs this
    process may run on (os.sched_getaffinity where it exists)."""
    try:
        n = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        n = os.cpu_count() or 1
    return max(1, min(n, MAX_THREADS))

VENDOR = "gles"
# every extension and the profiles that have it: Common-Lite has all but the
# float commands (a literal, which tools/gen_cabi.py reads for the C ABI)
EXTENSION_PROFILES = {
    "GL_OES_byte_coordinates": "both", "GL_OES_fixed_point": "both", "GL_OES_single_precision": "common",
    "GL_OES_matrix_get": "both", "GL_OES_query_matrix": "both", "GL_OES_read_format": "both",
    "GL_OES_matrix_palette": "both", "GL_OES_blend_subtract": "both", "GL_OES_blend_func_separate": "both",
    "GL_OES_blend_equation_separate": "both", "GL_OES_stencil_wrap": "both",
    "GL_OES_compressed_paletted_texture": "both", "GL_OES_texture_mirrored_repeat": "both",
    "GL_OES_texture_env_crossbar": "both", "GL_OES_point_size_array": "both", "GL_OES_point_sprite": "both",
    "GL_OES_draw_texture": "both", "GL_OES_element_index_uint": "both",
    "GL_OES_compressed_ETC1_RGB8_texture": "both", "GL_EXT_texture_format_BGRA8888": "both",
    "GL_APPLE_texture_max_level": "both", "GL_EXT_blend_minmax": "both", "GL_EXT_read_format_bgra": "both",
    "GL_OES_texture_npot": "both", "GL_OES_vertex_array_object": "both", "GL_OES_mapbuffer": "both",
    "GL_EXT_map_buffer_range": "both", "GL_EXT_multi_draw_arrays": "both", "GL_EXT_texture_lod_bias": "both",
    "GL_OES_framebuffer_object": "both", "GL_OES_rgb8_rgba8": "both", "GL_OES_depth24": "both",
    "GL_OES_stencil8": "both", "GL_OES_packed_depth_stencil": "both", "GL_OES_fbo_render_mipmap": "both",
    "GL_EXT_discard_framebuffer": "both", "GL_EXT_texture_filter_anisotropic": "both",
    "GL_OES_texture_cube_map": "both", "GL_KHR_debug": "both",
}
EXTENSIONS = {profile: [e for e, where in EXTENSION_PROFILES.items() if where in ("both", profile)]
              for profile in ("common", "common-lite")}


class Context:
    """An offscreen OpenGL ES 1.1 context.

    Args:
        width, height: framebuffer size in pixels (1..4096).
        profile: "common" (float and fixed commands) or "common-lite"
            (fixed commands only; FLOAT arrays are rejected).
        numeric: the core's arithmetic: "fixed" (16.16, the product),
            "float" or "double" (the accuracy reference).
        color: the colour buffer: "rgba8888" (uint32 words, red in the low
            byte), "rgb565", "rgba4444" or "rgba5551" (uint16 words laid
            out as GL's packed types of those names, red in the high bits;
            DITHER, on by default, dithers every channel of these three).
        depth: depth buffer bits, 0, 16 or 24.
        stencil: stencil buffer bits, 0 or 8.
        range_check: what to do with reals 16.16 cannot hold and with draws
            that break the overflow rule c*s + t < 16384: "warn", "raise",
            "clamp" or "off" (see :mod:`gles.profile`). Default: "warn" for
            the fixed build, "off" for float and double.
        memory_limit: the bytes a context's texture images (4 per texel,
            every level) and buffer objects' data may hold together; a
            command that would pass it records GL_OUT_OF_MEMORY and changes
            nothing. Default 256 MiB. Settable later as ``ctx.memory_limit``.
        threads: how many threads share each draw's vertex work and
            rasterization (the calling one and ``threads - 1`` workers of one
            pool per process), each rasterizing its own bands of rows, so
            every image is byte-identical to ``threads=1``'s. Default: the
            CPUs this process may run on. Small draws stay on the calling
            thread. Settable later as ``ctx.threads``.
        debug: a debug context (KHR_debug): DEBUG_OUTPUT_KHR starts enabled,
            so every GL error and debug message reaches the debug callback
            (by default the "gles.debug" logger; see :mod:`gles.debug` and
            ``ctx.debug_callback``). Default False: debug output starts off
            (``glEnable(GL_DEBUG_OUTPUT_KHR)`` turns it on).

    Contexts are independent: each has its own lock, and draws release the
    GIL, so contexts in different threads render at the same time.
    """

    def __init__(self, width: int, height: int, *, profile: str = "common", numeric: str = "fixed",
                 color: str = "rgba8888", depth: int = 24, stencil: int = 8,
                 range_check: str | None = None, memory_limit: int | None = None,
                 threads: int | None = None, debug: bool = False) -> None:
        if profile not in PROFILES:
            raise ValueError(f"profile must be one of {sorted(PROFILES)}, not {profile!r}")
        if color not in COLOR_FORMATS:
            raise ValueError(f"color must be one of {sorted(COLOR_FORMATS)}, not {color!r}")
        if depth not in (0, 16, 24):
            raise ValueError(f"depth must be 0, 16 or 24, not {depth!r}")
        if stencil not in (0, 8):
            raise ValueError(f"stencil must be 0 or 8, not {stencil!r}")
        if range_check is None:
            range_check = "warn" if numeric == "fixed" else "off"
        if range_check not in POLICIES:
            raise ValueError(f"range_check must be one of {list(POLICIES)}, not {range_check!r}")
        if memory_limit is None:
            memory_limit = DEFAULT_MEMORY_LIMIT
        memory_limit = self._check_limit(memory_limit)
        threads = self._check_threads(default_threads() if threads is None else threads)
        width, height = int(width), int(height)
        if not (1 <= width <= 4096 and 1 <= height <= 4096):
            raise ValueError(f"width and height must be in 1..4096, not {width}x{height}")
        mod = _binding.core(numeric)
        self._ffi = mod.ffi
        self._lib = mod.lib
        ptr = self._lib.gles_context_create(width, height, COLOR_FORMATS[color], depth, stencil,
                                            PROFILES[profile])
        if ptr == self._ffi.NULL:
            raise MemoryError("could not allocate the framebuffer")
        self._ptr = self._ffi.gc(ptr, self._lib.gles_context_destroy)
        self._lock = threading.Lock()
        self.width, self.height = width, height
        self.profile, self.numeric, self.color = profile, numeric, color
        self.depth_bits, self.stencil_bits = depth, stencil
        self._check_errors = False
        self._range = RangeMonitor(range_check)
        self._lib.gles_range_set(self._ptr, _RANGE_MODE[range_check])
        self._lib.gles_memory_limit(self._ptr, memory_limit)
        self._lib.gles_threads_set(self._ptr, threads)
        self.debug_context = bool(debug)
        self._lib.gles_debug_context_set(self._ptr, self.debug_context)
        self._handle = CoreHandle(self._lib, self._ffi, self._ptr, self._lock, self._range, width, height,
                                  self._strings(), memory_limit)
        self.gl: GLBase = self._gl_class()(self._handle)
        self.gl._debug_route()

    def __repr__(self) -> str:
        return (f"<gles.Context {self.width}x{self.height} {self.profile} {self.numeric} "
                f"{self.color} depth={self.depth_bits} stencil={self.stencil_bits} "
                f"range_check={self._range.policy}>")

    def _gl_class(self) -> type:
        return _GL_CLASSES[(self.profile, self._range.policy != "off", self._check_errors)]

    def _rebind_gl(self) -> None:
        """Swap in the command-set class the current options call for."""
        cls = self._gl_class()
        if type(self.gl) is cls:
            return
        was_current = getattr(_current, "gl", None) is self.gl
        keep = self.gl._keep
        self.gl = cls(self._handle)
        self.gl._keep = keep          # arrays the core still points at
        self.gl._debug_route()
        if was_current:
            _set_current(self.gl)

    @property
    def range_check(self) -> str:
        """The range-check policy: "warn", "raise", "clamp" or "off" (settable)."""
        return self._range.policy

    @range_check.setter
    def range_check(self, policy: str) -> None:
        if policy not in POLICIES:
            raise ValueError(f"range_check must be one of {list(POLICIES)}, not {policy!r}")
        self._range.policy = policy
        with self._lock:
            self._lib.gles_range_set(self._ptr, _RANGE_MODE[policy])
        self._rebind_gl()

    def range_report(self, reset: bool = False) -> RangeReport:
        """What the range checks met since the context was made (or last reset):
        counts of overflows, underflows and draws breaking c*s + t < 16384,
        per call, with the worst margins and the first events."""
        counts = self._ffi.new("int64_t[2]")
        with self._lock:
            self._lib.gles_range_counts(self._ptr, counts)
        report = self._range.report((int(counts[0]), int(counts[1])))
        if reset:
            self._range.reset()
            with self._lock:
                self._lib.gles_range_reset(self._ptr)
        return report

    @staticmethod
    def _check_limit(limit: Any) -> int:
        if isinstance(limit, bool) or not isinstance(limit, (int, np.integer)):
            raise TypeError(f"memory_limit must be an int (bytes), not {type(limit).__name__}")
        if not 0 <= int(limit) <= 2**62:
            raise ValueError(f"memory_limit must be in 0..2**62 bytes, not {limit}")
        return int(limit)

    @staticmethod
    def _check_threads(threads: Any) -> int:
        if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)):
            raise TypeError(f"threads must be an int, not {type(threads).__name__}")
        if not 1 <= int(threads) <= MAX_THREADS:
            raise ValueError(f"threads must be in 1..{MAX_THREADS}, not {threads}")
        return int(threads)

    @property
    def threads(self) -> int:
        """Threads that rasterize each draw (settable; 1 where the core was
        built without threads or cannot start them)."""
        with self._lock:
            return int(self._lib.gles_threads(self._ptr))

    @threads.setter
    def threads(self, threads: int) -> None:
        threads = self._check_threads(threads)
        with self._lock:
            self._lib.gles_threads_set(self._ptr, threads)

    @property
    def memory_limit(self) -> int:
        """Bytes the context's texture images and buffer data may hold
        together (settable; a limit below the current use only stops growth)."""
        return self._handle.memory_limit

    @memory_limit.setter
    def memory_limit(self, limit: int) -> None:
        limit = self._check_limit(limit)
        with self._lock:
            self._lib.gles_memory_limit(self._ptr, limit)
        self._handle.memory_limit = limit

    @property
    def memory_used(self) -> int:
        """Bytes the context's texture images and buffer data hold now."""
        with self._lock:
            return int(self._lib.gles_memory_used(self._ptr))

    @property
    def check_errors(self) -> bool:
        """When True, every command raises gles.GLError at the call that
        records a GL error (naming the function and the error), as PyOpenGL's
        error checking does; the error is consumed. Off by default."""
        return self._check_errors

    @check_errors.setter
    def check_errors(self, on: bool) -> None:
        self._check_errors = bool(on)
        self._rebind_gl()

    @property
    def debug_callback(self) -> Any:
        """The KHR_debug callback: a callable taking (source, type, id,
        severity, length, message, user_param), message as bytes; by default
        gles.debug.log_message (the "gles.debug" logger); None keeps messages
        in the log for glGetDebugMessageLogKHR. Settable; the same state as
        ``glDebugMessageCallbackKHR``, whose user_param it keeps."""
        return self._handle.debug_callback

    @debug_callback.setter
    def debug_callback(self, callback: Any) -> None:
        self.gl.glDebugMessageCallbackKHR(callback, self._handle.debug_user_param)

    def make_current(self) -> Context:
        """Make this the calling thread's current context (for ``gles.gl``)."""
        _set_current(self.gl)
        return self

    def _strings(self) -> dict[int, str]:
        """The GetString answers (§6.1.5)."""
        return {
            C.GL_VENDOR: VENDOR,
            C.GL_RENDERER: f"gles software renderer ({self.numeric})",
            C.GL_VERSION: "OpenGL ES-CM 1.1" if self.profile == "common" else "OpenGL ES-CL 1.1",
            C.GL_EXTENSIONS: " ".join(EXTENSIONS[self.profile]),
        }

    # {================================================================
    # pixels

    def color_buffer(self) -> np.ndarray:
        """The colour buffer as stored, bottom row first: uint8 (h, w, 4) for
        RGBA8888 or uint16 (h, w) for RGB565, RGBA4444 and RGBA5551. A copy."""
        with self._lock:
            if self.color != "rgba8888":
                buf = self._ffi.buffer(self._lib.gles_color_buffer(self._ptr), self.width * self.height * 2)
                return np.frombuffer(buf, dtype=np.uint16).reshape(self.height, self.width).copy()
            buf = self._ffi.buffer(self._lib.gles_color_buffer(self._ptr), self.width * self.height * 4)
            return np.frombuffer(buf, dtype=np.uint8).reshape(self.height, self.width, 4).copy()

    def depth_buffer(self) -> np.ndarray | None:
        """The depth buffer (uint32 values 0..2^bits-1), bottom row first; None without one."""
        if not self.depth_bits:
            return None
        with self._lock:
            buf = self._ffi.buffer(self._lib.gles_depth_buffer(self._ptr), self.width * self.height * 4)
            return np.frombuffer(buf, dtype=np.uint32).reshape(self.height, self.width).copy()

    def stencil_buffer(self) -> np.ndarray | None:
        """The stencil buffer (uint8), bottom row first; None without one."""
        if not self.stencil_bits:
            return None
        with self._lock:
            buf = self._ffi.buffer(self._lib.gles_stencil_buffer(self._ptr), self.width * self.height)
            return np.frombuffer(buf, dtype=np.uint8).reshape(self.height, self.width).copy()

    def image(self) -> np.ndarray:
        """The colour buffer as uint8 RGBA (h, w, 4), top row first.

        The channels of a 16-bit buffer are expanded to 8 bits (c * 255 /
        max, rounded); RGB565's alpha is 255.
        """
        return expand_color(self.color_buffer(), self.color)[::-1].copy()

    def save(self, file: str | os.PathLike[str] | BinaryIO) -> None:
        """Write the colour buffer as PNG (top row first) to a path or to a
        binary file object (anything with ``write(bytes)``)."""
        if isinstance(file, (str, os.PathLike)):
            write_png(file, self.image())
            return
        write = getattr(file, "write", None)
        if not callable(write):
            raise TypeError(f"save() takes a path or a binary file object, not {type(file).__name__}")
        data = encode_png(self.image())
        try:
            write(data)
        except TypeError:
            raise TypeError("save(): the file object must be opened in binary mode ('wb')") from None

    def _repr_png_(self) -> bytes:
        """The colour buffer as PNG bytes: Jupyter shows a context as its image."""
        return encode_png(self.image())

    # {================================================================
    # introspection for tests

    def debug(self, flags: int) -> None:
        """Core debug switches: 1 forces the generic span path; 2 flips the
        fill rule's tie-break, 4 drops the last pixel of every span (both
        break the rasterizer on purpose, to show tests catch it); 8 runs the
        vertex stage per vertex, the reference of the batched path; 16 runs
        the baseline (portable) span stages where the CPU has AVX2; 32 runs
        at most the AVX2 instance where the double build would take its
        AVX-512 one; 64 shares every draw's vertex work and rasterization
        among the context's threads, however small the draw."""
        with self._lock:
            self._lib.gles_debug_set(self._ptr, int(flags))

    def last_span_path(self) -> str:
        """Name of the span function the last validated draw chose."""
        with self._lock:
            return self._ffi.string(self._lib.gles_last_span_name(self._ptr)).decode()

    @property
    def simd(self) -> str:
        """The instruction set the fragment stages run with here: "avx512"
        (the fixed and double builds, on x86-64 CPUs with AVX-512 F, DQ
        and BW: the fixed build's perspective stage and level-of-detail
        choice, the double build's bilinear kernel and fused stages, the
        rest as "avx2"), "avx2" (x86-64 CPUs that have it) or "baseline".
        All give the same bits."""
        with self._lock:
            return self._ffi.string(self._lib.gles_simd_name(self._ptr)).decode()

    def __enter__(self) -> Context:
        return self.make_current()

    def __exit__(self, *exc: Any) -> None:
        _set_current(None)
