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
silenced) and returned as its ``range`` report, per frame: the events of the
setup and of the frame the image shows (of the whole call, for a scene that
returns nothing), so they are the same whatever ``runs`` is.

Every (scene, renderer) pair is a job. By default the jobs run one after the
other in this process; ``jobs=N`` runs them in N worker processes, and
``executor=`` takes any :class:`concurrent.futures.Executor` (a process pool,
a ``dask.distributed`` client's ``get_executor()``, ...). The scene must then
pickle: a function defined at the top level of an importable module (the
gallery's and the hard cases' scenes are), or what :func:`load_scene` returns
for a scene file (it pickles as the file's path and the function's name). The
images, metrics and range counts do not depend on the executor; the times
do, since processes that run side by side compete for the cores and caches.

A renderer that raises (the scene, the renderer, or a name that is neither a
build nor a peer) is *failed*, not skipped: its ``error`` holds the exception
and its ``traceback`` the formatted traceback, and :attr:`Comparison.failed`
lists it. Only a known peer that this machine lacks is skipped.
"""

from __future__ import annotations

import base64
import concurrent.futures as cf
import html
import importlib.util
import math
import multiprocessing
import os
import pickle
import statistics
import sys
import time
import traceback
import types
import warnings
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .._binding import NUMERICS
from .._png import encode_png
from ..context import Context
from ..profile import MAX_EVENTS, RangeReport

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
    traceback: str | None = None      # the failure's formatted traceback

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

    def _repr_html_(self) -> str:
        """An HTML table for notebooks: per renderer the time, the error
        against the reference, the range events (overflow / underflow / draws
        breaking the rule), why it was skipped or failed, and the image and
        its diff heatmap as inline PNGs."""
        e = html.escape
        shown = min(160, max(self.width, 48))
        head = ["renderer", "ms/frame", "max abs", "mean abs", "RMSE", "PSNR (dB)", "&gt;1 LSB",
                "range events", "image", f"diff against {e(self.reference)}"]
        parts = [f"<div><p><b>{e(self.scene)}</b> at {self.width}x{self.height}, error against "
                 f"{e(self.reference)} over R, G and B</p>",
                 "<table><tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr>"]
        for r in self.renders.values():
            cells = [f"<td>{e(r.renderer)}</td>"]
            if r.skipped is not None or r.error is not None:
                why = f"skipped: {r.skipped}" if r.skipped is not None else f"FAILED: {r.error}"
                detail = (f"<details><summary>traceback</summary><pre>{e(r.traceback)}</pre></details>"
                          if r.traceback else "")
                cells.append(f"<td colspan='{len(head) - 1}' style='text-align:left'>{e(why)}{detail}</td>")
            else:
                m = r.metrics.row() if r.metrics else [""] * 5
                rng = (f"{r.range.counts['overflow']}/{r.range.counts['underflow']}/{r.range.counts['rule']}"
                       if r.range is not None else "")
                cells += [f"<td>{r.time_ms:.2f}</td>", *(f"<td>{e(c)}</td>" for c in m), f"<td>{rng}</td>"]
                for img in (r.image, r.heatmap):
                    cells.append("<td></td>" if img is None else
                                 f"<td><img src='{_data_url(img)}' width='{shown}' "
                                 "style='image-rendering: pixelated'></td>")
            parts.append("<tr>" + "".join(cells) + "</tr>")
        parts.append("</table></div>")
        return "\n".join(parts)


def _data_url(image: np.ndarray) -> str:
    return "data:image/png;base64," + base64.b64encode(encode_png(image)).decode("ascii")


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

COLOR_FORMATS = ("rgba8888", "rgb565", "rgba4444", "rgba5551")


def check_color(color: str) -> None:
    """A ValueError unless `color` names a framebuffer format of :data:`COLOR_FORMATS`."""
    if color not in COLOR_FORMATS:
        raise ValueError(f"color must be one of {COLOR_FORMATS}, not {color!r}")


def _open(renderer: str, width: int, height: int, color: str = "rgba8888") -> Any:
    check_color(color)
    if renderer in BUILDS:
        check = "warn" if renderer == "fixed" else "off"
        # one thread, as Mesa's figures beside it (LP_NUM_THREADS=1 below)
        return Context(width, height, numeric=renderer, range_check=check, color=color, threads=1)
    if renderer in PEERS:
        from . import mesa

        # the single-thread figure the benchmarks use; read when Mesa starts
        os.environ.setdefault("LP_NUM_THREADS", "1")
        return mesa.MesaContext(width, height, driver=renderer[5:], color=color)
    raise ValueError(f"unknown renderer {renderer!r}: builds are {BUILDS}, peers {PEERS}")


def _close(ctx: Any) -> None:
    close = getattr(ctx, "close", None)
    if close is not None:
        close()


def _peer_missing(renderer: str, color: str = "rgba8888") -> str | None:
    """Why a known peer cannot run here (None when it can, or for anything
    else: an unknown name is an error, not a skipped peer): Mesa missing, or
    no window of the `color` format (its EGL has no RGBA4444 or RGBA5551
    config)."""
    if renderer not in PEERS:
        return None
    from . import mesa

    if color not in mesa.MESA_COLOR_FORMATS:
        return f"Mesa has no {color.upper()} window"
    return mesa.available(renderer[5:])


def render(scene: Scene, renderer: str, width: int, height: int, runs: int = 5,
           color: str = "rgba8888") -> Render:
    """Render `scene` on one renderer into a `color` framebuffer (one of
    :data:`COLOR_FORMATS`), timing `runs` frames."""
    why = _peer_missing(renderer, color)
    if why is not None:
        return Render(renderer, None, skipped=why)
    out = Render(renderer, None)
    ctx = _open(renderer, width, height, color)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")     # range events are counted, not printed
            gl = ctx.gl
            frame = scene(gl, width, height)
            if callable(frame):
                setup = _range(ctx, reset=True)
                frame()                         # warm-up: first-use allocations
                gl.glFinish()
                runs = max(1, runs)
                for i in range(runs):
                    if i == runs - 1:
                        _range(ctx, reset=True)  # count the setup and the frame shown, once each
                    t0 = time.perf_counter()
                    frame()
                    gl.glFinish()
                    out.times_ms.append(1e3 * (time.perf_counter() - t0))
            else:
                # the first call was the warm-up; each timed run gets a fresh context
                for _ in range(max(1, runs)):
                    _close(ctx)
                    ctx = _open(renderer, width, height, color)
                    gl = ctx.gl
                    t0 = time.perf_counter()
                    scene(gl, width, height)
                    gl.glFinish()
                    out.times_ms.append(1e3 * (time.perf_counter() - t0))
                setup = None
            out.gl_error = int(gl.glGetError())
            out.image = ctx.image()
            out.range = _merge(setup, _range(ctx))
    finally:
        _close(ctx)
    return out


def _range(ctx: Any, reset: bool = False) -> RangeReport | None:
    """The context's range report, if it is a build with the checks on."""
    if isinstance(ctx, Context) and ctx.range_check != "off":
        return ctx.range_report(reset=reset)
    return None


def _merge(a: RangeReport | None, b: RangeReport | None) -> RangeReport | None:
    """The events of two spans of one context's life, as one report."""
    if a is None or b is None:
        return b if a is None else a
    by_source = dict(a.by_source)
    for src, n in b.by_source.items():
        by_source[src] = by_source.get(src, 0) + n
    return RangeReport(b.policy, {k: a.counts[k] + b.counts[k] for k in b.counts}, by_source,
                       {k: max(a.worst[k], b.worst[k]) for k in b.worst},
                       a.draws_checked + b.draws_checked, a.draws_breaking_rule + b.draws_breaking_rule,
                       (a.events + b.events)[:MAX_EVENTS])


def _failure(renderer: str, exc: BaseException) -> Render:
    return Render(renderer, None, error=f"{type(exc).__name__}: {exc}",
                  traceback="".join(traceback.format_exception(type(exc), exc, exc.__traceback__)))


def render_job(scene: Scene, renderer: str, width: int, height: int, runs: int = 5,
               color: str = "rgba8888") -> Render:
    """:func:`render`, with an exception returned as a failed :class:`Render`
    (its ``error`` and ``traceback``) instead of raised: one job of
    :func:`compare`, run in this process or on an executor's worker."""
    try:
        return render(scene, renderer, width, height, runs, color)
    except Exception as exc:  # noqa: BLE001 -- reported per renderer
        return _failure(renderer, exc)


def _process_pool(jobs: int) -> cf.ProcessPoolExecutor:
    # forkserver where there is one: workers start from a clean server process,
    # not a fork of one holding cffi and EGL state (spawn elsewhere)
    method = "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() else "spawn"
    return cf.ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context(method))


def _check_executor(executor: Any, jobs: int) -> None:
    if isinstance(jobs, bool) or not isinstance(jobs, int):
        raise TypeError(f"jobs must be an int, not {type(jobs).__name__}")
    if jobs < 1:
        raise ValueError(f"jobs must be at least 1, not {jobs}")
    if executor is not None and not callable(getattr(executor, "submit", None)):
        raise TypeError(f"executor must have a submit() method (a concurrent.futures.Executor), "
                        f"not {type(executor).__name__}")
    if executor is not None and jobs != 1:
        raise ValueError("give executor or jobs, not both")


def _run(work: list[tuple[Scene, str, int]], width: int, height: int, color: str,
         executor: Any) -> Iterator[tuple[int, Render]]:
    """Run each (scene, renderer, runs) job; yield (its index, its Render) as each ends."""
    if executor is None:
        for i, (scene, name, runs) in enumerate(work):
            yield i, render_job(scene, name, width, height, runs, color)
        return
    if isinstance(executor, cf.ProcessPoolExecutor):
        for scene in {id(s): s for s, _, _ in work}.values():
            _picklable(scene)       # a clear error now, not a pickling error per job
    futures = {executor.submit(render_job, scene, name, width, height, runs, color): i
               for i, (scene, name, runs) in enumerate(work)}
    if all(isinstance(f, cf.Future) for f in futures):
        order: Iterator[Any] = cf.as_completed(futures)
    else:
        order = iter(list(futures))
    for f in order:
        i = futures[f]
        try:
            yield i, f.result()
        except Exception as exc:  # noqa: BLE001 -- the job could not run there (lost worker, ...)
            yield i, _failure(work[i][1], exc)


def compare_scenes(scenes: Sequence[Scene], width: int, height: int, builds: Sequence[str] = BUILDS,
                   peers: Sequence[str] = ("mesa-llvmpipe",), runs: int = 5, reference: str = "double",
                   progress: Callable[[int, str], None] | None = None, executor: Any = None,
                   jobs: int = 1, color: str = "rgba8888") -> list[Comparison]:
    """:func:`compare` for several scenes at once, as one pool of (scene,
    renderer) jobs; ``progress(i, renderer)`` is called as each job of
    ``scenes[i]`` ends. Returns a :class:`Comparison` per scene, in order."""
    _check_executor(executor, jobs)
    check_color(color)
    names = list(dict.fromkeys([*builds, *peers]))
    work: list[tuple[Scene, str, int]] = []
    for scene in scenes:
        work += [(scene, name, runs) for name in names]
        if reference not in names:
            work.append((scene, reference, 1))    # the reference alone: not timed
    per = len(names) + (reference not in names)
    own = None
    if executor is None and jobs > 1:
        executor = own = _process_pool(jobs)
    results: list[Render | None] = [None] * len(work)
    try:
        for i, r in _run(work, width, height, color, executor):
            results[i] = r
            if progress and work[i][1] in names:
                progress(i // per, work[i][1])
    finally:
        if own is not None:
            own.shutdown(cancel_futures=True)   # after an error, drop the jobs not started
    out = []
    for k, scene in enumerate(scenes):
        mine = results[k * per:(k + 1) * per]
        renders: dict[str, Render] = {r.renderer: r for r in mine[:len(names)]}
        ref = renders.get(reference) or mine[-1]
        if ref.error is not None and reference not in renders:
            renders[reference] = ref        # a failed reference is a failure, not lost
        if ref.image is not None:
            for r in renders.values():
                if r.image is not None:
                    r.metrics = metrics(r.image, ref.image)
                    r.heatmap = heatmap(r.image, ref.image)
        out.append(Comparison(getattr(scene, "__name__", "scene"), width, height, reference, renders))
    return out


def _picklable(scene: Scene) -> None:
    try:
        pickle.dumps(scene)
    except Exception as exc:  # noqa: BLE001 -- named in the error
        raise TypeError(f"scene {getattr(scene, '__name__', scene)!r} does not pickle, so it cannot run "
                        "in worker processes: define it at the top level of an importable module, or "
                        f"load it from its file with gles.compare.load_scene ({exc})") from None


def compare(scene: Scene, width: int, height: int, builds: Sequence[str] = BUILDS,
            peers: Sequence[str] = ("mesa-llvmpipe",), runs: int = 5, reference: str = "double",
            progress: Callable[[str], None] | None = None, executor: Any = None,
            jobs: int = 1, color: str = "rgba8888") -> Comparison:
    """Render `scene` on each build and peer and measure each against `reference`.

    Every renderer, the reference included, draws into a `color`
    framebuffer (one of :data:`COLOR_FORMATS`), so each error is measured against
    the reference rendered the same way.

    The reference is rendered even when it is not among `builds` (it is not
    timed then). A peer that is not available on this machine is reported as
    skipped. A renderer that raised is reported as failed, with the
    exception in its ``error`` and the traceback in its ``traceback`` (and in
    ``Comparison.failed``), so that one failure does not lose the others yet
    is never mistaken for a skip; a failed reference outside `builds` is
    listed too. ``progress(renderer)`` is called as each renderer ends.

    By default the renderers run one after the other in this process.
    ``jobs=N`` runs them in N worker processes; ``executor`` takes any
    :class:`concurrent.futures.Executor` instead (e.g. a
    ``dask.distributed.Client(...).get_executor()``). The scene must pickle
    for either (see the module's documentation); the results other than the
    times are the same whatever runs them.
    """
    return compare_scenes([scene], width, height, builds, peers, runs, reference,
                          None if progress is None else (lambda _i, name: progress(name)),
                          executor, jobs, color)[0]


# {====================================================================
# scene files

def _load(path: Path, name: str | None) -> tuple[str, Scene]:
    spec = importlib.util.spec_from_file_location(f"gles_scene_{path.stem}", path)
    if spec is None or spec.loader is None:
        raise ValueError(f"{path}: not a Python file")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if name is not None:
        fn = getattr(module, name)
        if not callable(fn):
            raise ValueError(f"{path}: {name} is not a function")
        return name, fn
    if callable(getattr(module, "scene", None)):
        return "scene", module.scene
    funcs = [(k, v) for k, v in vars(module).items()
             if callable(v) and not k.startswith("_") and getattr(v, "__module__", None) == module.__name__]
    if len(funcs) != 1:
        raise ValueError(f"{path}: define a function named scene(gl, w, h)")
    return funcs[0]


class SceneFile:
    """A scene function loaded from a Python file. It calls like the
    function and pickles as the file's path and the function's name, so a
    worker process (or a dask worker that shares the file system) loads it
    from the file itself."""

    def __init__(self, path: str | Path, function: str | None = None) -> None:
        self.path = str(Path(path).resolve())
        self.function, self._fn = _load(Path(self.path), function)
        self.__name__ = getattr(self._fn, "__name__", self.function)
        self.__doc__ = getattr(self._fn, "__doc__", None)

    def __call__(self, gl: Any, width: int, height: int) -> Any:
        return self._fn(gl, width, height)

    def __reduce__(self) -> tuple[Any, tuple[str, str]]:
        return (SceneFile, (self.path, self.function))

    def __repr__(self) -> str:
        return f"SceneFile({self.path!r}, {self.function!r})"


def load_scene(path: str | Path, name: str | None = None) -> SceneFile:
    """The scene function of a Python file: `name`, else `scene`, else the
    only public function defined in it (as a :class:`SceneFile`: callable
    like the function, and picklable for worker processes)."""
    return SceneFile(path, name)


class _CallableModule(types.ModuleType):
    """``gles.compare(scene, w, h, ...)`` calls :func:`compare`, while
    ``gles.compare.metrics`` and the rest stay reachable."""

    def __call__(self, *args: Any, **kwargs: Any) -> Comparison:
        return compare(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
