"""Context.save to a path or a binary file, and _repr_png_ for notebooks."""

from __future__ import annotations

import io
import struct
import zlib
from pathlib import Path

import numpy as np
import pytest

import gles
from gles import constants as C


def decode_png(data: bytes) -> np.ndarray:
    """RGBA8 PNG with filter 0 rows (what gles writes) back to (h, w, 4), read
    from the chunks by hand."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, size = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        assert struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0] == zlib.crc32(kind + body)
        if kind == b"IHDR":
            w, h, depth, colour = struct.unpack(">IIBB", body[:10])
            assert (depth, colour) == (8, 6)
            size = (h, w)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    h, w = size
    rows = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + 4 * w)
    assert (rows[:, 0] == 0).all()
    return rows[:, 1:].reshape(h, w, 4)


def painted() -> gles.Context:
    """Bottom half red, top half blue (GL's bottom row is the image's last)."""
    ctx = gles.Context(6, 4)
    g = ctx.gl
    g.glEnable(C.GL_SCISSOR_TEST)
    g.glScissor(0, 0, 6, 2)
    g.glClearColor(1, 0, 0, 1)
    g.glClear(C.GL_COLOR_BUFFER_BIT)
    g.glScissor(0, 2, 6, 2)
    g.glClearColor(0, 0, 1, 1)
    g.glClear(C.GL_COLOR_BUFFER_BIT)
    return ctx


def expected() -> np.ndarray:
    img = np.zeros((4, 6, 4), np.uint8)
    img[:2] = (0, 0, 255, 255)
    img[2:] = (255, 0, 0, 255)
    return img


def test_repr_png_is_the_image() -> None:
    assert np.array_equal(decode_png(painted()._repr_png_()), expected())


def test_save_to_a_path_and_to_a_binary_file(tmp_path: Path) -> None:
    ctx = painted()
    ctx.save(tmp_path / "a.png")
    ctx.save(str(tmp_path / "b.png"))
    buf = io.BytesIO()
    ctx.save(buf)
    with open(tmp_path / "c.png", "wb") as f:
        ctx.save(f)
    for data in ((tmp_path / "a.png").read_bytes(), (tmp_path / "b.png").read_bytes(), buf.getvalue(),
                 (tmp_path / "c.png").read_bytes()):
        assert np.array_equal(decode_png(data), expected())


def test_save_refuses_text_files_and_non_files(tmp_path: Path) -> None:
    ctx = painted()
    with open(tmp_path / "t.txt", "w") as f, pytest.raises(TypeError, match="binary mode"):
        ctx.save(f)
    with pytest.raises(TypeError, match="path or a binary file object"):
        ctx.save(3)
