"""Trace capture and the C replayer (gles.trace, csrc/replay/).

A trace records the calls the binding makes into the core, with every
argument as C received it, so the replayer (gles-replay, linked with the
same build's core) must end with a framebuffer byte-identical to the Python
run's, and the Python run itself must be unchanged by being recorded (the
reference is an unrecorded run on a fresh context). Bad files must give the
replayer's clean error (exit status 1 and a reason), never a crash.
"""

from __future__ import annotations

import random
import struct
import subprocess
import warnings
from typing import Any

import numpy as np
import pytest

import gles
from gles import constants as C
from gles import trace as T
from gles.gallery import GALLERY

W, H = 64, 48
SCENES = ("lit_mesh", "dot3_bump", "env_map_dual_paraboloid", "env_map_cube", "stencil_reflection",
          "alpha_sprites")


def plain_run(scene: Any, numeric: str, w: int = W, h: int = H, color: str = "rgba8888") -> np.ndarray:
    """The scene on a fresh, unrecorded context, as gles.trace runs it."""
    ctx = gles.Context(w, h, numeric=numeric, color=color,
                       range_check="warn" if numeric == "fixed" else "off")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        frame = scene(ctx.gl, w, h)
        if callable(frame):
            frame()
            frame()
        ctx.gl.glFinish()
    return ctx.image()


def buffers_scene(gl: Any, w: int, h: int) -> None:
    """Buffer objects with offsets, an element buffer, client arrays changed in
    place between draws, a texture, and queries: the trace's other paths."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glLoadIdentity()
    gl.glOrthof(0, w, 0, h, -1, 1)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glLoadIdentity()
    gl.glClearColor(0.1, 0.2, 0.3, 1.0)
    gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    checker = (np.indices((8, 8)).sum(axis=0) % 2 * 255).astype(np.uint8)
    rgba = np.stack([checker, 255 - checker, checker // 2, np.full_like(checker, 255)], axis=-1)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 8, 8, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, rgba)
    gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    gl.glTexParameterf(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
    # a textured quad from one interleaved buffer object (position, texcoord)
    quad = np.array([[4, 4, 0, 0], [w / 2, 4, 2, 0], [w / 2, h - 4, 2, 2], [4, h - 4, 0, 2]], np.float32)
    vbo, ibo = gl.glGenBuffers(2)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, vbo)
    gl.glBufferData(C.GL_ARRAY_BUFFER, quad.nbytes, quad, C.GL_STATIC_DRAW)
    gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, ibo)
    gl.glBufferData(C.GL_ELEMENT_ARRAY_BUFFER, 12, np.array([0, 1, 2, 0, 2, 3], np.uint16), C.GL_STATIC_DRAW)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glVertexPointer(2, C.GL_FLOAT, 16, 0)
    gl.glTexCoordPointer(2, C.GL_FLOAT, 16, 8)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glDrawElements(C.GL_TRIANGLES, 6, C.GL_UNSIGNED_SHORT, 0)
    gl.glDisable(C.GL_TEXTURE_2D)
    gl.glDisableClientState(C.GL_TEXTURE_COORD_ARRAY)
    gl.glBindBuffer(C.GL_ARRAY_BUFFER, 0)
    gl.glBindBuffer(C.GL_ELEMENT_ARRAY_BUFFER, 0)
    # a client array drawn, changed in place, drawn again: each draw reads its bytes then
    tri = np.array([[w / 2 + 2, 4], [w - 4, 4], [w - 4, h / 2]], np.float32)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, tri)
    gl.glColor4f(1.0, 0.5, 0.0, 1.0)
    gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    tri[:, 1] += h / 2 - 4
    gl.glColor4f(0.0, 1.0, 0.5, 1.0)
    gl.glDrawElements(C.GL_TRIANGLES, 3, C.GL_UNSIGNED_BYTE, np.array([0, 1, 2], np.uint8))
    gl.glGetError()
    gl.glEnable(0x1234)                 # INVALID_ENUM, recorded like any call
    gl.glReadPixels(0, 0, 4, 4, C.GL_RGBA, C.GL_UNSIGNED_BYTE)
    gl.glDeleteTextures(1, [tex])


def test_header_and_table() -> None:
    t = gles.trace(GALLERY["lit_mesh"][1], W, H)
    info = T.read_header(t.data)
    assert (info.width, info.height, info.numeric, info.color) == (W, H, "fixed", "rgba8888")
    assert t.data[:8] == T.MAGIC
    assert struct.unpack_from("<H", t.data, len(t.data) - 2)[0] == T.REC_END
    assert t.calls > 10


@pytest.mark.parametrize("numeric", T.NUMERICS)
@pytest.mark.parametrize("name", SCENES)
def test_replay_is_byte_identical(name: str, numeric: str) -> None:
    scene = GALLERY[name][1]
    t = gles.trace(scene, W, H, numeric=numeric)
    # recording changes nothing: the image of an unrecorded run
    np.testing.assert_array_equal(t.image, plain_run(scene, numeric))
    assert len(np.unique(t.image.reshape(-1, 4), axis=0)) > 20       # a real picture
    assert T.replay(t, raw=True) == t.color_buffer
    np.testing.assert_array_equal(T.replay(t), t.image)


@pytest.mark.parametrize("numeric", T.NUMERICS)
def test_buffers_offsets_and_changed_arrays(numeric: str) -> None:
    t = gles.trace(buffers_scene, W, H, numeric=numeric)
    expected = plain_run(buffers_scene, numeric)
    np.testing.assert_array_equal(t.image, expected)
    # the second triangle (drawn after its array changed) is there, in green
    assert (expected[:, :, 1] == 255).any() and (expected[:, :, 0] == 255).any()
    assert T.replay(t, raw=True) == t.color_buffer


@pytest.mark.parametrize("color", ["rgb565", "rgba4444", "rgba5551"])
def test_16bit_formats_and_file_round_trip(tmp_path: Any, color: str) -> None:
    scene = GALLERY["dot3_bump"][1]
    path = tmp_path / "dot3.glestrace"
    t = gles.trace(scene, W, H, numeric="fixed", color=color, path=path)
    assert T.read_header(path.read_bytes()).color == color
    np.testing.assert_array_equal(t.image, plain_run(scene, "fixed", color=color))
    assert len(t.color_buffer) == W * H * 2
    assert T.replay(path, raw=True) == t.color_buffer
    np.testing.assert_array_equal(T.replay(path), t.image)
    # the program itself, as the CLI prints it
    out = tmp_path / "image.raw"
    subprocess.run([str(T.replayer("fixed")), str(path), "-o", str(out)], check=True)
    assert out.read_bytes() == t.color_buffer


def test_cli_trace(tmp_path: Any) -> None:
    from gles.__main__ import main

    scene_file = tmp_path / "scene.py"
    scene_file.write_text("from gles.gallery import alpha_sprites as scene\n")
    out = tmp_path / "s.glestrace"
    assert main(["trace", str(scene_file), "-o", str(out), "--size", "40x30", "--numeric", "float"]) == 0
    info = T.read_header(out.read_bytes())
    assert (info.width, info.height, info.numeric) == (40, 30, "float")
    np.testing.assert_array_equal(T.replay(out), plain_run(GALLERY["alpha_sprites"][1], "float", 40, 30))


# {====================================================================
# bad traces

def run_replayer(data: bytes) -> subprocess.CompletedProcess:
    return subprocess.run([str(T.replayer("fixed")), "-"], input=data, capture_output=True, timeout=60)


@pytest.fixture(scope="module")
def small_trace() -> bytes:
    return gles.trace(buffers_scene, 16, 12).data


def test_every_truncation_is_refused_cleanly(small_trace: bytes) -> None:
    assert run_replayer(small_trace).returncode == 0
    cuts = sorted(set(range(0, 64)) | set(range(64, len(small_trace), max(1, len(small_trace) // 150))))
    for cut in cuts:
        proc = run_replayer(small_trace[:cut])
        assert proc.returncode == 1, (cut, proc.returncode, proc.stderr)
        assert b"gles-replay: -: " in proc.stderr
        assert b"truncated" in proc.stderr or b"magic" in proc.stderr or b"header" in proc.stderr, proc.stderr


def test_corrupted_bytes_never_crash(small_trace: bytes) -> None:
    rng = random.Random(17)
    refused = 0
    for _ in range(300):
        data = bytearray(small_trace)
        for _ in range(rng.choice((1, 1, 2, 8))):
            pos = rng.randrange(T.HEADER_SIZE, len(data))
            data[pos] = rng.randrange(256)
        proc = run_replayer(bytes(data))
        # either played (a changed value is still a valid call) or refused with a reason
        assert proc.returncode in (0, 1), (proc.returncode, proc.stderr)
        if proc.returncode == 1:
            refused += 1
            assert proc.stderr.startswith(b"gles-replay: -: ")
    assert refused > 0


def _with(data: bytes, offset: int, fmt: str, value: int) -> bytes:
    out = bytearray(data)
    struct.pack_into(fmt, out, offset, value)
    return bytes(out)


def test_header_errors(small_trace: bytes) -> None:
    cases = {
        "bad magic": b"NOTATRC\x1a" + small_trace[8:],
        "version 9": _with(small_trace, 8, "<H", 9),
        "call table": _with(small_trace, 12, "<I", T.TABLE_HASH ^ 1),
        "invalid context configuration": _with(small_trace, 16, "<H", 0),
    }
    for why, data in cases.items():
        proc = run_replayer(data)
        assert proc.returncode == 1 and why.encode() in proc.stderr, (why, proc.stderr)
        with pytest.raises(ValueError, match=why.split()[0]):
            T.read_header(data)


def _records(*records: bytes, header: bytes) -> bytes:
    out = bytearray(header)
    for r in records:
        out += r
    out += struct.pack("<H", T.REC_END)
    return bytes(out)


def test_record_errors(small_trace: bytes) -> None:
    header = small_trace[:T.HEADER_SIZE]
    cid = {name: T.CALLS[name][0] for name in T.CALLS}
    cases = {
        "unknown record": struct.pack("<H", 0x7777),
        # (the record starts at byte 40: blobs are padded to a multiple of 8 from the file's start)
        "n exceeds the names stored": struct.pack("<HiI", cid["gles_DeleteTextures"], 5, 1) + bytes(6)
        + struct.pack("<I", 7),
        "n exceeds the output stored": struct.pack("<HiI", cid["gles_GenTextures"], 100, 16),
        "a buffer offset with no buffer bound": struct.pack("<HiIiBQ", cid["gles_VertexPointer"], 2,
                                                            C.GL_FLOAT, 0, T.TAG_OFFSET, 4096),
        "undefined client array": struct.pack("<HiIiBI", cid["gles_VertexPointer"], 2, C.GL_FLOAT, 0,
                                              T.TAG_REGION, 3),
        "size exceeds the data stored": struct.pack("<HIqB", cid["gles_BufferData"], C.GL_ARRAY_BUFFER,
                                                    64, T.TAG_BYTES) + struct.pack("<Q", 8) + bytes(1 + 8)
        + struct.pack("<I", C.GL_STATIC_DRAW),
        "more than 16 values": struct.pack("<HI", cid["gles_LoadMatrix"], 17) + bytes(17 * 8),
        "more than one frame record": struct.pack("<HH", T.REC_FRAME, T.REC_FRAME),
        "client arrays too large": struct.pack("<HIQ", T.REC_REGION_DEF, 0, 1 << 40),
    }
    for why, record in cases.items():
        proc = run_replayer(_records(record, header=header))
        assert proc.returncode == 1 and why.encode() in proc.stderr, (why, proc.stderr)
    proc = run_replayer(small_trace + b"\0")
    assert proc.returncode == 1 and b"after the end record" in proc.stderr
    with pytest.raises(ValueError, match="truncated"):
        T.replay(small_trace[:-1])
