"""Context.save to a path or a binary file, and _repr_png_ for notebooks."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest
from conftest import decode_png

import gles
from gles import constants as C


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
