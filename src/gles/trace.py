"""Record a scene's core calls into a trace file, and replay one in C.

    import gles
    from gles.gallery import GALLERY
    t = gles.trace(GALLERY["lit_mesh"][1], 96, 72, numeric="fixed", path="lit_mesh.glestrace")
    image = gles.trace.replay("lit_mesh.glestrace")      # the C replayer's image
    assert (image == t.image).all()

or ``python -m gles trace scene.py -o scene.glestrace``.

A trace holds the calls the Python binding makes into the core (the
functions of csrc/gles_core.h, each with every argument as C received it),
so a replay against the same build is exact: the C replayer (csrc/replay/)
makes the same calls with the same bits and ends with the same framebuffer.
Client arrays are stored when a draw reads them (GL reads client memory at
draw time), texture and buffer data when they are given, and buffer offsets
as offsets.

File format (little-endian; version 1):

* header, 40 bytes: magic ``GLESTRC\\x1a``, u16 version, u16 header size,
  u32 hash of the call table (gles._trace_table), u16 width, u16 height, u8
  colour format, depth bits, stencil bits, profile, numeric build
  (0 fixed, 1 float, 2 double), range-check mode, u16 0, u32 0, i64 memory
  limit;
* records, each a u16 id: a call id of the table followed by its arguments
  (see tools/gen_replay.py for the argument codes), or 0xFF00 define client
  array (u32 id, u64 size), 0xFF01 client array data (u32 id, u64 size,
  bytes), 0xFF02 the frame begins, 0xFF03 end (the last record).
  Blobs start at a multiple of 8 bytes from the start of the file (zero
  padding), so the replayer hands them to the core in place.

The frame record separates setup from the frame that is measured: for a
scene that returns a frame function, the trace holds the setup, one warm-up
frame, the frame record, then one more frame (what compare times); for a
scene that draws directly, the whole scene is the frame.
"""

from __future__ import annotations

import struct
import subprocess
import sys
import tempfile
import types
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Union

import numpy as np

from ._trace_table import CALLS, TABLE_HASH
from .context import Context, expand_color

MAGIC = b"GLESTRC\x1a"
VERSION = 1
HEADER_SIZE = 40
NUMERICS = ("fixed", "float", "double")
COLORS = ("rgba8888", "rgb565", "rgba4444", "rgba5551")    # GLES_COLOR_* order
PROFILES = ("common", "common-lite")
RANGE_MODES = {"off": 0, "warn": 1, "raise": 1, "clamp": 1}

REC_REGION_DEF, REC_REGION_DATA, REC_FRAME, REC_END = 0xFF00, 0xFF01, 0xFF02, 0xFF03
TAG_NULL, TAG_OFFSET, TAG_BYTES, TAG_REGION = 0, 1, 2, 3
_POINTER_CALLS = {name for name, (_, codes) in CALLS.items() if name.endswith(("Pointer", "PointerOES"))}
_DRAW_CALLS = {"gles_DrawArrays", "gles_DrawElements"}
_SCALAR_FORMATS = {"i": "<i", "u": "<I", "b": "<B", "d": "<d", "l": "<q"}

Scene = Callable[[Any, int, int], Any]
PathLike = Union[str, Path]

_PACKAGE = Path(__file__).resolve().parent


@dataclass
class Trace:
    """A recorded scene: the trace file's bytes, and the image and raw colour
    buffer the Python run ended with."""

    data: bytes
    image: np.ndarray          # uint8 RGBA (h, w, 4), top row first, as Context.image()
    color_buffer: bytes        # the colour buffer as stored (bottom row first)
    width: int
    height: int
    numeric: str
    color: str
    calls: int                 # core calls recorded

    def save(self, path: PathLike) -> Path:
        """Write the trace file; returns its path."""
        path = Path(path)
        path.write_bytes(self.data)
        return path


class _Writer:
    """The trace being written, and the client arrays it has seen."""

    def __init__(self, ffi: Any) -> None:
        self.ffi = ffi
        self.out = bytearray()
        self.calls = 0
        # (address, size) -> [id, cdata kept alive, bytes last stored or None]
        self.regions: dict[tuple[int, int], list[Any]] = {}

    def pad(self) -> None:
        self.out += bytes(-len(self.out) % 8)

    def record(self, rid: int) -> None:
        self.out += struct.pack("<H", rid)

    def blob(self, data: bytes) -> None:
        self.out += struct.pack("<Q", len(data))
        self.pad()
        self.out += data

    def _buffer(self, cdata: Any) -> bytes:
        return bytes(self.ffi.buffer(cdata))

    def _length(self, cdata: Any) -> int:
        t = self.ffi.typeof(cdata)
        if t.kind == "array":
            return self.ffi.sizeof(cdata)
        return self.ffi.sizeof(t.item)

    def region(self, cdata: Any, size: int) -> int:
        address = int(self.ffi.cast("uintptr_t", cdata))
        key = (address, size)
        entry = self.regions.get(key)
        if entry is None:
            entry = [len(self.regions), cdata, None]
            self.regions[key] = entry
            self.record(REC_REGION_DEF)
            self.out += struct.pack("<IQ", entry[0], size)
        else:
            entry[1] = cdata
        return int(entry[0])

    def flush_regions(self) -> None:
        """Store every client array whose bytes changed since last stored
        (before a draw, which reads them)."""
        for (address, size), entry in self.regions.items():
            now = bytes(self.ffi.buffer(self.ffi.cast("char *", address), size)) if size else b""
            if now != entry[2]:
                entry[2] = now
                self.record(REC_REGION_DATA)
                self.out += struct.pack("<I", entry[0])
                self.blob(now)

    def call(self, name: str, cid: int, codes: str, args: tuple[Any, ...]) -> None:
        """Store one call: its id, then each argument by its code."""
        ffi = self.ffi
        if name in _DRAW_CALLS:
            self.flush_regions()
        if name in _POINTER_CALLS:
            # define a new client array before the record that refers to it
            for k, (code, a) in enumerate(zip(codes, args)):
                if code == "V" and a != ffi.NULL and ffi.typeof(a).kind == "array":
                    self.region(a, self._client_length(a, int(args[k + 1])))
        self.record(cid)
        for k, (code, a) in enumerate(zip(codes, args)):
            if code in _SCALAR_FORMATS:
                self.out += struct.pack(_SCALAR_FORMATS[code], a)
            elif code == "D":
                n = min(len(a), 16)
                self.out += struct.pack(f"<I{n}d", n, *(a[i] for i in range(n)))
            elif code == "U":
                data = self._buffer(a)
                self.out += struct.pack("<I", len(data) // 4)
                self.pad()
                self.out += data[: len(data) // 4 * 4]
            elif code == "O":
                self.out += struct.pack("<I", 0xFFFFFFFF if a == ffi.NULL else self._length(a))
            elif code == "V":
                with_len = k + 1 < len(codes) and codes[k + 1] == "N"
                self._datum(name, a, int(args[k + 1]) if with_len else None)
            # "N": not stored, the replayer passes the length of what it hands over
        self.calls += 1

    def _client_length(self, a: Any, nbytes: int | None) -> int:
        """The bytes of array `a` the core may read: all of it, or nbytes when less."""
        length = int(self.ffi.sizeof(a))
        return int(nbytes) if nbytes is not None and 0 <= nbytes < length else length

    def _datum(self, name: str, a: Any, nbytes: int | None) -> None:
        ffi = self.ffi
        if a == ffi.NULL:
            self.out += struct.pack("<B", TAG_NULL)
            return
        t = ffi.typeof(a)
        if t.kind != "array":
            # an offset into the bound buffer (gl.py casts the int to a pointer)
            self.out += struct.pack("<BQ", TAG_OFFSET, int(ffi.cast("uintptr_t", a)))
            return
        length = self._client_length(a, nbytes)
        if name in _POINTER_CALLS:
            rid = self.region(a, length)
            self.out += struct.pack("<BI", TAG_REGION, rid)
            return
        self.out += struct.pack("<B", TAG_BYTES)
        self.blob(bytes(ffi.buffer(a, length)))


class _RecordingLib:
    """The core's functions as the binding calls them, each call recorded
    after it returns (a call that raised before reaching C is not)."""

    def __init__(self, inner: Any, writer: _Writer) -> None:
        self._inner = inner
        self._writer = writer

    def __getattr__(self, name: str) -> Any:
        fn = getattr(self._inner, name)
        entry = CALLS.get(name)
        if entry is None:
            return fn
        cid, codes = entry
        writer = self._writer

        def call(*args: Any) -> Any:
            result = fn(*args)
            writer.call(name, cid, codes, args[1:])
            return result

        call.__name__ = name
        setattr(self, name, call)
        return call


def _header(ctx: Context, range_mode: int) -> bytes:
    return struct.pack(
        "<8sHHIHHBBBBBBHIq", MAGIC, VERSION, HEADER_SIZE, TABLE_HASH, ctx.width, ctx.height,
        COLORS.index(ctx.color), ctx.depth_bits, ctx.stencil_bits, PROFILES.index(ctx.profile),
        NUMERICS.index(ctx.numeric), range_mode, 0, 0, ctx.memory_limit)


def trace(scene: Scene, width: int, height: int, *, numeric: str = "fixed", profile: str = "common",
          color: str = "rgba8888", depth: int = 24, stencil: int = 8, range_check: str | None = None,
          path: PathLike | None = None) -> Trace:
    """Run ``scene(gl, width, height)`` on a new context and record its calls.

    The context is made as :func:`gles.compare.render` makes it (range checks
    "warn" on the fixed build, "off" on the others, unless ``range_check``
    says otherwise). Writes the trace to ``path`` if given. Returns the
    :class:`Trace` with the image the Python run produced.
    """
    if not callable(scene):
        raise TypeError(f"scene must be a function scene(gl, w, h), not {type(scene).__name__}")
    if numeric not in NUMERICS:
        raise ValueError(f"numeric must be one of {NUMERICS}, not {numeric!r}")
    if range_check is None:
        range_check = "warn" if numeric == "fixed" else "off"
    ctx = Context(width, height, numeric=numeric, profile=profile, color=color, depth=depth,
                  stencil=stencil, range_check=range_check)
    if width > 65535 or height > 65535:   # pragma: no cover - Context allows 4096 at most
        raise ValueError("size too large for a trace")
    writer = _Writer(ctx._ffi)
    writer.out += _header(ctx, RANGE_MODES[range_check])
    gl = ctx.gl
    gl._lib = _RecordingLib(gl._lib, writer)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")     # range events are counted, not printed
        frame = scene(gl, width, height)
        if callable(frame):
            frame()                         # warm-up, as compare does
            writer.record(REC_FRAME)
            frame()
        gl.glFinish()
    writer.record(REC_END)
    result = Trace(bytes(writer.out), ctx.image(), ctx.color_buffer().tobytes(), width, height,
                   numeric, color, writer.calls)
    if path is not None:
        result.save(path)
    return result


@dataclass
class TraceInfo:
    """What a trace file's header says."""

    width: int
    height: int
    color: str
    depth: int
    stencil: int
    profile: str
    numeric: str


def read_header(data: bytes) -> TraceInfo:
    """Check a trace's header; ValueError says what is wrong with it."""
    if len(data) < HEADER_SIZE:
        raise ValueError(f"not a gles trace: {len(data)} bytes, shorter than the header")
    (magic, version, size, table, w, h, color, depth, stencil, profile, numeric, _range, _p, _q,
     _limit) = struct.unpack_from("<8sHHIHHBBBBBBHIq", data)
    if magic != MAGIC:
        raise ValueError("not a gles trace (bad magic)")
    if version != VERSION or size != HEADER_SIZE:
        raise ValueError(f"trace format version {version}, this gles reads version {VERSION}")
    if table != TABLE_HASH:
        raise ValueError(f"trace call table 0x{table:08X}, this gles has 0x{TABLE_HASH:08X}")
    if color >= len(COLORS) or profile > 1 or numeric > 2 or not (1 <= w <= 4096 and 1 <= h <= 4096):
        raise ValueError("invalid context configuration in the trace header")
    return TraceInfo(w, h, COLORS[color], depth, stencil, PROFILES[profile], NUMERICS[numeric])


def replayer(numeric: str = "fixed") -> Path:
    """The path of the host's C replayer (gles-replay) linked with one build's core."""
    if numeric not in NUMERICS:
        raise ValueError(f"numeric must be one of {NUMERICS}, not {numeric!r}")
    path = _PACKAGE / "lib" / numeric / "gles-replay"
    if not path.is_file():
        raise FileNotFoundError(f"no replayer at {path}: this installation was built without it")
    return path


def raw_to_image(raw: bytes, info: TraceInfo) -> np.ndarray:
    """A replayed colour buffer (as stored) as uint8 RGBA, top row first (Context.image())."""
    if info.color != "rgba8888":
        px = np.frombuffer(raw, dtype="<u2").reshape(info.height, info.width)
        out = expand_color(px, info.color)
    else:
        out = np.frombuffer(raw, dtype=np.uint8).reshape(info.height, info.width, 4)
    return out[::-1].copy()


def replay(source: Trace | bytes | PathLike, numeric: str | None = None, *, raw: bool = False) -> Any:
    """Play a trace with the C replayer; returns the final image (as
    Context.image()), or with ``raw`` the colour buffer's bytes as stored.

    ``numeric`` picks the build's replayer (default: the build that recorded
    it). A bad trace raises ValueError with the replayer's reason.
    """
    if isinstance(source, Trace):
        data = source.data
    elif isinstance(source, (bytes, bytearray)):
        data = bytes(source)
    else:
        data = Path(source).read_bytes()
    info = read_header(data)
    exe = replayer(numeric or info.numeric)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "color.raw"
        proc = subprocess.run([str(exe), "-", "-o", str(out)], input=data, capture_output=True)
        if proc.returncode == 1:
            raise ValueError(proc.stderr.decode(errors="replace").strip())
        if proc.returncode != 0:
            raise RuntimeError(f"{exe} failed ({proc.returncode}): {proc.stderr.decode(errors='replace')}")
        buf = out.read_bytes()
    return buf if raw else raw_to_image(buf, info)


class _CallableModule(types.ModuleType):
    """``gles.trace(scene, ...)`` is :func:`trace`."""

    def __call__(self, *args: Any, **kwargs: Any) -> Trace:
        return trace(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
