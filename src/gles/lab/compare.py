"""Float against fixed: render one scene on several builds and peers, and measure.

A *scene* is a function ``scene(gl, w, h)`` that issues OpenGL ES 1.1 calls on
``gl`` (a :class:`gles.Context`'s command set, or a Mesa peer's: both take the
same calls). It may return a zero-argument callable ``frame()``; then the
calls before the return are setup, and ``frame()`` draws one frame, which is
what is timed and what the image shows (after the last run). A scene that
returns nothing is timed whole, on a fresh context per run (after one
untimed warm-up call, as a frame function gets one untimed warm-up frame).

:func:`compare` renders the scene on each build (``"fixed"``, ``"float"``,
``"double"``) and each peer (``"mesa-llvmpipe"``, ``"mesa-softpipe"``), and
returns per renderer: the image, the median time per frame over ``runs``
runs, the error against the reference build (double, by default) and a diff
heatmap. The error is taken over the R, G and B channels of 8-bit images:

* ``max_abs``, ``mean_abs``: of |image - reference| over every channel value;
* ``rmse``: root of the mean squared difference;
* ``psnr``: 20 log10(255 / rmse) in dB (``inf`` for identical images);
* ``share_over_1lsb``: share of pixels where some channel differs by more
  than 1.

The fixed build's range checks are counted during the render (warnings
silenced) and returned as its ``range`` report.
"""

from __future__ import annotations

import importlib.util
import math
import os
import statistics
import sys
import time
import types
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .._binding import NUMERICS
from ..context import Context
from ..profile import RangeReport

Scene = Callable[[Any, int, int], Any]

BUILDS = NUMERICS
PEERS = ("mesa-llvmpipe", "mesa-softpipe")


@dataclass(frozen=True)
class Metrics:
    """Error of an 8-bit image against a reference, over R, G and B."""

    max_abs: int
    mean_abs: float
    rmse: float
    psnr: float            # dB; inf when the images are identical
    share_over_1lsb: float  # share of pixels with a channel off by more than 1

    def row(self) -> list[str]:
        psnr = "inf" if math.isinf(self.psnr) else f"{self.psnr:.1f}"
        return [str(self.max_abs), f"{self.mean_abs:.3f}", f"{self.rmse:.3f}", psnr,
                f"{100 * self.share_over_1lsb:.2f}%"]


@dataclass
class Render:
    """One renderer's result for a scene."""

    renderer: str                     # "fixed", ..., "mesa-llvmpipe"
    image: np.ndarray | None          # uint8 (h, w, 4), top row first
    times_ms: list[float] = field(default_factory=list)
    metrics: Metrics | None = None    # against the reference
    heatmap: np.ndarray | None = None  # uint8 (h, w, 3)
    range: RangeReport | None = None  # the fixed build's range checks
    gl_error: int = 0                 # glGetError after the last frame
    skipped: str | None = None        # why it did not run: a peer this machine lacks
    error: str | None = None          # why it failed: the exception the scene or renderer raised

    @property
    def time_ms(self) -> float:
        """Median time per frame in milliseconds (nan when it did not run)."""
        return statistics.median(self.times_ms) if self.times_ms else math.nan


@dataclass
class Comparison:
    """Every renderer's result for one scene."""

    scene: str
    width: int
    height: int
    reference: str
    renders: dict[str, Render]

    @property
    def failed(self) -> dict[str, str]:
        """Renderer -> the exception it failed with (a skipped peer is not a failure)."""
        return {n: r.error for n, r in self.renders.items() if r.error is not None}

    def table(self) -> str:
        """A Markdown table: one row per renderer."""
        head = ("| renderer | ms/frame | max abs | mean abs | RMSE | PSNR (dB) | >1 LSB | range events |\n"
                "|---|--:|--:|--:|--:|--:|--:|--:|")
        rows = [head]
        for r in self.renders.values():
            if r.skipped:
                rows.append(f"| {r.renderer} | skipped: {r.skipped} | | | | | | |")
                continue
            if r.error:
                rows.append(f"| {r.renderer} | FAILED: {r.error} | | | | | | |")
                continue
            m = r.metrics.row() if r.metrics else ["", "", "", "", ""]
            rng = str(r.range.total) if r.range is not None else ""
            rows.append(f"| {r.renderer} | {r.time_ms:.2f} | " + " | ".join(m) + f" | {rng} |")
        return "\n".join(rows)


# {====================================================================
# metrics

def metrics(image: np.ndarray, reference: np.ndarray) -> Metrics:
    """The error of `image` against `reference` (uint8, (h, w, 3 or 4)) over R, G, B."""
    if image.shape[:2] != reference.shape[:2]:
        raise ValueError(f"image {image.shape} and reference {reference.shape} differ in size")
    a = image[..., :3].astype(np.int32)
    b = reference[..., :3].astype(np.int32)
    d = np.abs(a - b)
    mse = float(np.mean(d.astype(np.float64) ** 2))
    rmse = math.sqrt(mse)
    psnr = math.inf if mse == 0 else 20.0 * math.log10(255.0 / rmse)
    return Metrics(int(d.max()), float(d.mean()), rmse, psnr, float(np.mean(d.max(axis=2) > 1)))


# a dark-to-bright ramp: black, blue, magenta, orange, yellow, white
_RAMP = np.array([[0, 0, 0], [40, 30, 150], [180, 40, 150], [250, 120, 40], [250, 230, 60],
                  [255, 255, 255]], dtype=np.float64)


def heatmap(image: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """A diff heatmap, uint8 (h, w, 3): black where equal; the largest channel
    difference d on a log scale, 1 LSB dark blue through 255 white."""
    d = np.abs(image[..., :3].astype(np.int32) - reference[..., :3].astype(np.int32)).max(axis=2)
    pos = np.where(d > 0, 1.0 + np.log2(np.maximum(d, 1)) / 8.0 * (len(_RAMP) - 2), 0.0)
    lo = np.clip(np.floor(pos).astype(int), 0, len(_RAMP) - 1)
    hi = np.clip(lo + 1, 0, len(_RAMP) - 1)
    f = (pos - lo)[..., None]
    return np.rint(_RAMP[lo] * (1 - f) + _RAMP[hi] * f).astype(np.uint8)


# {====================================================================
# rendering

def _open(renderer: str, width: int, height: int) -> Any:
    if renderer in BUILDS:
        check = "warn" if renderer == "fixed" else "off"
        return Context(width, height, numeric=renderer, range_check=check)
    if renderer in PEERS:
        from . import mesa

        # the single-thread figure the benchmarks use; read when Mesa starts
        os.environ.setdefault("LP_NUM_THREADS", "1")
        return mesa.MesaContext(width, height, driver=renderer[5:])
    raise ValueError(f"unknown renderer {renderer!r}: builds are {BUILDS}, peers {PEERS}")


def _close(ctx: Any) -> None:
    close = getattr(ctx, "close", None)
    if close is not None:
        close()


def _peer_missing(renderer: str) -> str | None:
    """Why a known peer cannot run here (None when it can, or for anything
    else: an unknown name is an error, not a skipped peer)."""
    if renderer not in PEERS:
        return None
    from . import mesa

    return mesa.available(renderer[5:])


def render(scene: Scene, renderer: str, width: int, height: int, runs: int = 5) -> Render:
    """Render `scene` on one renderer, timing `runs` frames."""
    why = _peer_missing(renderer)
    if why is not None:
        return Render(renderer, None, skipped=why)
    out = Render(renderer, None)
    ctx = _open(renderer, width, height)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")     # range events are counted, not printed
            gl = ctx.gl
            frame = scene(gl, width, height)
            if callable(frame):
                frame()                         # warm-up: first-use allocations
                gl.glFinish()
                for _ in range(max(1, runs)):
                    t0 = time.perf_counter()
                    frame()
                    gl.glFinish()
                    out.times_ms.append(1e3 * (time.perf_counter() - t0))
            else:
                # the first call was the warm-up; each timed run gets a fresh context
                for _ in range(max(1, runs)):
                    _close(ctx)
                    ctx = _open(renderer, width, height)
                    gl = ctx.gl
                    t0 = time.perf_counter()
                    scene(gl, width, height)
                    gl.glFinish()
                    out.times_ms.append(1e3 * (time.perf_counter() - t0))
            out.gl_error = int(gl.glGetError())
            out.image = ctx.image()
            if isinstance(ctx, Context) and ctx.range_check != "off":
                out.range = ctx.range_report()
    finally:
        _close(ctx)
    return out


def compare(scene: Scene, width: int, height: int, builds: Sequence[str] = BUILDS,
            peers: Sequence[str] = ("mesa-llvmpipe",), runs: int = 5, reference: str = "double",
            progress: Callable[[str], None] | None = None) -> Comparison:
    """Render `scene` on each build and peer and measure each against `reference`.

    The reference is rendered even when it is not among `builds` (it is not
    timed then). A peer that is not available on this machine is reported as
    skipped. A renderer whose scene raised is reported as failed, with the
    exception's text in its ``error`` (and in ``Comparison.failed``), so that
    one failure does not lose the others yet is never mistaken for a skip.
    """
    names = list(dict.fromkeys([*builds, *peers]))
    renders: dict[str, Render] = {}
    for name in names:
        if progress:
            progress(name)
        try:
            renders[name] = render(scene, name, width, height, runs)
        except Exception as exc:  # noqa: BLE001 -- reported per renderer
            renders[name] = Render(name, None, error=f"{type(exc).__name__}: {exc}")
    ref = renders.get(reference)
    if ref is None:
        ref = render(scene, reference, width, height, runs=1)
    if ref.image is not None:
        for r in renders.values():
            if r.image is not None:
                r.metrics = metrics(r.image, ref.image)
                r.heatmap = heatmap(r.image, ref.image)
    return Comparison(getattr(scene, "__name__", "scene"), width, height, reference, renders)


def load_scene(path: str | Path, name: str | None = None) -> Scene:
    """The scene function of a Python file: `name`, else `scene`, else the
    only public function defined in it."""
    path = Path(path)
    spec = importlib.util.spec_from_file_location(f"gles_scene_{path.stem}", path)
    if spec is None or spec.loader is None:
        raise ValueError(f"{path}: not a Python file")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if name is not None:
        return getattr(module, name)
    if callable(getattr(module, "scene", None)):
        return module.scene
    funcs = [v for k, v in vars(module).items()
             if callable(v) and not k.startswith("_") and getattr(v, "__module__", None) == module.__name__]
    if len(funcs) != 1:
        raise ValueError(f"{path}: define a function named scene(gl, w, h)")
    return funcs[0]


class _CallableModule(types.ModuleType):
    """``gles.compare(scene, w, h, ...)`` calls :func:`compare`, while
    ``gles.compare.metrics`` and the rest stay reachable."""

    def __call__(self, *args: Any, **kwargs: Any) -> Comparison:
        return compare(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
