"""The conformance harness: test registry, visuals, tolerances, test context.

A conformance test is a function ``def test(t: TestContext) -> None`` that
draws with ``t.gl`` and checks pixels with the ``t.expect_*`` helpers (each
raises :class:`Failure` with a message saying what differed and where).
Register it with :func:`conformance_test`; category modules live in
``conformance/categories/`` and are imported by :func:`load_categories`.

Tests are written from the spec's rules and the published pass rules
(SPEC-NOTES.md): tolerances come from the visual's bits, never from what an
implementation happens to produce.
"""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np


class Failure(AssertionError):
    """A conformance check failed; the message says what and where."""


class Unsupported(Exception):
    """The backend lacks something the test needs (reported as skipped)."""


@dataclass(frozen=True)
class Visual:
    """The framebuffer a test runs on, as the Khronos harness chooses them."""

    color: str = "rgba8888"   # or "rgb565", "rgba4444", "rgba5551"
    depth: int = 24
    stencil: int = 8

    @property
    def bits(self) -> tuple[int, int, int, int]:
        """Bits of red, green, blue, alpha."""
        return {"rgb565": (5, 6, 5, 0), "rgba4444": (4, 4, 4, 4), "rgba5551": (5, 5, 5, 1)}.get(
            self.color, (8, 8, 8, 8))

    def color_tolerance(self) -> np.ndarray:
        """Per-channel tolerance 1/(2^bits - 1) + 2^-13 (alpha of a buffer
        without alpha bits is not compared: tolerance 1)."""
        return np.array([1.0 / ((1 << b) - 1) + 2.0**-13 if b else 1.0 for b in self.bits])

    def depth_tolerance(self) -> float:
        return 1.0 / ((1 << self.depth) - 1) + 2.0**-13 if self.depth else 1.0

    @property
    def name(self) -> str:
        return f"{self.color}-d{self.depth}-s{self.stencil}"


VISUALS = {
    "rgba8888": Visual("rgba8888", 24, 8),
    "rgba8888-d16": Visual("rgba8888", 16, 8),
    "rgb565": Visual("rgb565", 16, 8),
    "rgba4444": Visual("rgba4444", 16, 8),
    "rgba5551": Visual("rgba5551", 16, 8),
}


@dataclass
class ConformanceTest:
    name: str
    func: Callable[[TestContext], None]
    section: str               # the spec section it checks, e.g. "3.5.1"
    description: str
    uses: frozenset[str]       # state the test sets itself ("depth", "blend", ...): paths leave it alone
    profiles: frozenset[str]   # profiles it applies to
    visuals: tuple[str, ...]   # visuals it runs on (keys of VISUALS)
    size: tuple[int, int] = (64, 64)   # window width, height


REGISTRY: dict[str, ConformanceTest] = {}


def conformance_test(name: str, *, section: str, uses: Iterable[str] = (),
                     profiles: Iterable[str] = ("common", "common-lite"),
                     visuals: Iterable[str] = ("rgba8888",),
                     size: tuple[int, int] = (64, 64)) -> Callable:
    """Register a test under `name` (the Khronos category name, or
    ``Category.detail`` for several tests of one category); `size` is the
    window's width and height."""

    def deco(func: Callable[[TestContext], None]) -> Callable[[TestContext], None]:
        if name in REGISTRY:
            raise ValueError(f"conformance test {name!r} registered twice")
        REGISTRY[name] = ConformanceTest(
            name=name, func=func, section=section,
            description=(func.__doc__ or "").strip().splitlines()[0] if func.__doc__ else "",
            uses=frozenset(uses), profiles=frozenset(profiles), visuals=tuple(visuals),
            size=(int(size[0]), int(size[1])),
        )
        return func

    return deco


def load_categories() -> dict[str, ConformanceTest]:
    """Import every module of conformance.categories (registering its tests)."""
    from . import categories

    for mod in pkgutil.iter_modules(categories.__path__):
        importlib.import_module(f"{categories.__name__}.{mod.name}")
    return REGISTRY


@dataclass
class TestContext:
    """What a test gets: the backend's GL namespace and checking helpers.

    Attributes:
        gl: the GL commands and GL_* constants (same conventions as gles.gl).
        width, height: the window size.
        visual: the framebuffer's Visual.
        profile: "common" or "common-lite"; tests use only x forms and
            non-FLOAT arrays when it is "common-lite" (see ``t.common``).
        backend: the backend object (name, read_rgba()).
    """

    backend: Any
    gl: Any
    width: int
    height: int
    visual: Visual
    profile: str
    notes: list[str] = field(default_factory=list)

    @property
    def common(self) -> bool:
        return self.profile == "common"

    # {============================================================
    # set-up helpers

    def ortho_pixels(self) -> None:
        """Projection and modelview so that object x, y are window pixels
        (0..width, 0..height) and z in [-1, 1] maps to depth [1, 0]...[0, 1]
        as glOrtho(0, w, 0, h, -1, 1) defines; viewport the whole window."""
        gl = self.gl
        gl.glViewport(0, 0, self.width, self.height)
        gl.glMatrixMode(gl.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glOrthox(0, self.width << 16, 0, self.height << 16, -(1 << 16), 1 << 16)
        gl.glMatrixMode(gl.GL_MODELVIEW)
        gl.glLoadIdentity()

    def clear(self, rgba: tuple[float, float, float, float] = (0, 0, 0, 0)) -> None:
        """Clear colour (and depth to 1, stencil to 0) with x commands."""
        gl = self.gl
        gl.glClearColorx(*[int(round(c * 65536)) for c in rgba])
        gl.glClearDepthx(1 << 16)
        gl.glClearStencil(0)
        gl.glClear(gl.GL_COLOR_BUFFER_BIT | gl.GL_DEPTH_BUFFER_BIT | gl.GL_STENCIL_BUFFER_BIT)

    def draw(self, mode: int, verts: Any, colors: Any = None, *, size: int = 2,
             indices: Any = None, index_type: int | None = None) -> None:
        """Draw client arrays: vertices as 16.16 GL_FIXED (values given as
        reals are converted), colours as GL_UNSIGNED_BYTE RGBA (0..255) or
        None for the current colour; `indices` as GL_UNSIGNED_SHORT, or
        `index_type` (GL_UNSIGNED_INT: OES_element_index_uint)."""
        gl = self.gl
        v = np.round(np.asarray(verts, dtype=np.float64).reshape(-1) * 65536).astype(np.int32)
        gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
        gl.glVertexPointer(size, gl.GL_FIXED, 0, v)
        if colors is not None:
            c = np.asarray(colors, dtype=np.uint8).reshape(-1)
            gl.glEnableClientState(gl.GL_COLOR_ARRAY)
            gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, c)
        else:
            gl.glDisableClientState(gl.GL_COLOR_ARRAY)
        if indices is None:
            gl.glDrawArrays(mode, 0, len(v) // size)
        else:
            kind = gl.GL_UNSIGNED_SHORT if index_type is None else index_type
            idx = np.asarray(indices, dtype=np.uint32 if kind == gl.GL_UNSIGNED_INT else np.uint16)
            gl.glDrawElements(mode, len(idx), kind, idx)
        gl.glDisableClientState(gl.GL_COLOR_ARRAY)

    # {============================================================
    # reading and checking

    def read(self) -> np.ndarray:
        """The window as float RGBA in [0, 1], shape (h, w, 4), bottom row first."""
        return self.backend.read_rgba()

    def fail(self, msg: str) -> None:
        raise Failure(msg)

    def has_extension(self, name: str) -> bool:
        """Whether GL_EXTENSIONS names `name` (a whole word of the list)."""
        ext = self.gl.glGetString(self.gl.GL_EXTENSIONS) or b""
        return name in (ext.decode() if isinstance(ext, bytes) else ext).split()

    def need_extension(self, name: str) -> None:
        """Raise Unsupported (the test is skipped) unless GL_EXTENSIONS names `name`."""
        if not self.has_extension(name):
            raise Unsupported(f"{name} is not in GL_EXTENSIONS")

    def check_gl_error(self, where: str, expected: int = 0) -> None:
        err = self.gl.glGetError()
        if err != expected:
            self.fail(f"{where}: glGetError() is 0x{err:04X}, expected 0x{expected:04X}")

    def expect_pixels(self, mask: np.ndarray, rgba: Any, where: str, *,
                      img: np.ndarray | None = None) -> None:
        """Every pixel where `mask` is True has colour `rgba` within the visual's tolerance."""
        img = self.read() if img is None else img
        want = np.asarray(rgba, dtype=np.float64)
        tol = self.visual.color_tolerance()
        diff = np.abs(img - want) > tol
        bad = mask & diff.any(axis=-1)
        if bad.any():
            ys, xs = np.nonzero(bad)
            y, x = int(ys[0]), int(xs[0])
            self.fail(f"{where}: {int(bad.sum())} pixels differ from {np.round(want, 4).tolist()}; "
                      f"first at (x={x}, y={y}): {np.round(img[y, x], 4).tolist()}")

    def expect_color(self, x: int, y: int, rgba: Any, where: str, *, img: np.ndarray | None = None) -> None:
        """One pixel (window coordinates, y up) has colour `rgba` within tolerance."""
        mask = np.zeros((self.height, self.width), dtype=bool)
        mask[y, x] = True
        self.expect_pixels(mask, rgba, where, img=img)
