"""``python -m gles report``: what 16.16 does to real scenes, and what each precision costs.

Renders the gallery (:mod:`gles.gallery`: the techniques the renderer is used
for) and the hard cases (:mod:`gles.hardcases`: where fixed point is
stressed), or the scenes of your own Python file, on the fixed, float and
double builds and on Mesa's llvmpipe and softpipe where present, and writes
into one directory:

* ``report.html`` and ``report.md``: a summary table (per scene this host's
  time per frame and the PSNR against the double build for each renderer,
  the no-FPU target's instructions per frame for fixed and float and their
  ratio, the fixed build's range events and the verdict), then per scene the
  images side by side with their diff heatmaps against the double build
  (under a colour bar that gives the heatmaps' scale), a table of time and
  error (max abs, mean abs, RMSE, PSNR, share of pixels off by more than
  1 LSB) and the fixed build's range checks;
* ``speed_vs_psnr.svg``: two panels, host time per frame against PSNR and
  target instructions per frame against PSNR; a line joins each scene's
  builds, each point names itself on hover, and a legend numbers the scenes;
* ``colorbar.svg``: the heatmaps' colour scale;
* ``report.json``: every number of the page, for scripts and CI;
* ``img/``: every image and heatmap as PNG.

With ``min_psnr`` (and ``max_over_1lsb``) each scene gets a verdict: it
passes when every build other than the reference reaches the PSNR and stays
under the share of pixels off by more than 1 LSB. ``python -m gles report``
exits 1 when a scene falls short, so a CI job can gate on its own scenes::

    python -m gles report --scenes my_scenes.py --min-psnr 40

A scene file is a Python file with a dict ``SCENES`` (name to function, or
to a (title, function) pair, like :data:`gles.gallery.GALLERY`), or else
every public function ``name(gl, w, h)`` it defines (see :func:`scene_file`).
"""

from __future__ import annotations

import datetime
import html
import importlib.util
import inspect
import json
import math
import os
import platform
import re
import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

from . import __version__
from ._png import write_png
from .compare import BUILDS, PEERS, Comparison, Render, check_color, compare_scenes
from .context import COLOR_LAYOUTS

# one colour per renderer, for the plots and the legend
COLORS = {"fixed": "#d62728", "float": "#1f77b4", "double": "#2ca02c",
          "mesa-llvmpipe": "#9467bd", "mesa-softpipe": "#8c564b"}

SCHEMA_VERSION = 1           # of report.json


@dataclass(frozen=True)
class Entry:
    """One scene of the report."""

    name: str
    title: str
    group: str          # "Techniques", "Hard cases" or "Scenes of FILE.py"
    scene: Callable
    note: str = ""


def entries(only: Sequence[str] | None = None) -> list[Entry]:
    """The gallery's scenes, then the hard cases (those named in `only`, if given)."""
    from .gallery import GALLERY
    from .hardcases import HARD_CASES

    out = [Entry(name, title, "Techniques", fn) for name, (title, fn) in GALLERY.items()]
    out += [Entry(name, case.title, "Hard cases", case.scene, case.stresses)
            for name, case in HARD_CASES.items()]
    if only:
        known = {e.name for e in out}
        unknown = [n for n in only if n not in known]
        if unknown:
            raise ValueError(f"unknown scenes {unknown}; known: {sorted(known)}")
        out = [e for e in out if e.name in only]
    return out


_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]*")


def _takes_gl_w_h(fn: Callable) -> bool:
    try:
        inspect.signature(fn).bind(None, 0, 0)
    except (TypeError, ValueError):
        return False
    return True


def scene_file(path: str | Path) -> list[Entry]:
    """The scenes of a Python file, for the report.

    The file either defines ``SCENES`` (or ``GALLERY``): a dict from a scene's
    name to its function ``scene(gl, w, h)`` or to a ``(title, function)``
    pair; or else every public function it defines (not imports) that takes
    ``(gl, w, h)`` is a scene, in the order of the file, named after the
    function and titled by its docstring's first line. Helpers named with a
    leading underscore are left out. A function may draw directly or return
    a ``frame()`` callable (see :mod:`gles.compare`).
    """
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"{path}: no such scene file")
    spec = importlib.util.spec_from_file_location(f"gles_report_scenes_{path.stem}", path)
    if spec is None or spec.loader is None:
        raise ValueError(f"{path}: not a Python file")
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except Exception as exc:  # noqa: BLE001 -- the file's own error, named with the file
        raise ValueError(f"{path}: {type(exc).__name__}: {exc}") from exc
    group = f"Scenes of {path.name}"
    table = getattr(module, "SCENES", None)
    if table is None:
        table = getattr(module, "GALLERY", None)
    out = []
    if table is not None:
        if not isinstance(table, dict):
            raise ValueError(f"{path}: SCENES must be a dict of name -> scene or (title, scene)")
        for name, value in table.items():
            title, fn = value if isinstance(value, tuple) and len(value) == 2 else ("", value)
            if not isinstance(name, str) or not _NAME.fullmatch(name):
                raise ValueError(f"{path}: scene name {name!r} must be letters, digits, _ . -")
            if not callable(fn) or not _takes_gl_w_h(fn):
                raise ValueError(f"{path}: scene {name!r} is not a function scene(gl, w, h)")
            out.append(Entry(name, str(title) or _doc_title(fn, name), group, fn))
    else:
        for name, fn in vars(module).items():
            if (name.startswith("_") or not inspect.isfunction(fn)
                    or fn.__module__ != module.__name__ or not _takes_gl_w_h(fn)):
                continue
            out.append(Entry(name, _doc_title(fn, name), group, fn))
    if not out:
        raise ValueError(f"{path}: defines no scene: a function name(gl, w, h), or a dict SCENES")
    return out


def _doc_title(fn: Callable, name: str) -> str:
    doc = inspect.getdoc(fn)
    return doc.strip().splitlines()[0] if doc else name


def select(only: Sequence[str] | None = None) -> list[Entry]:
    """The report's scenes: every gallery scene and hard case, or those `only`
    names; an item ending in ``.py`` is a scene file (:func:`scene_file`),
    whose scenes come after the named ones."""
    if not only:
        return entries()
    files = [item for item in only if item.endswith(".py")]
    names = [item for item in only if not item.endswith(".py")]
    out = entries(names) if names else []
    for f in files:
        out += scene_file(f)
    seen: set[str] = set()
    for e in out:
        if e.name in seen:
            raise ValueError(f"two scenes are named {e.name!r}")
        seen.add(e.name)
    return out


class Progress:
    """A one-line progress bar on stderr (a line per step when not a terminal)."""

    def __init__(self, total: int, enabled: bool = True) -> None:
        self.total, self.done, self.enabled = total, 0, enabled
        self.tty = sys.stderr.isatty()
        self.start = time.perf_counter()

    def step(self, label: str) -> None:
        if not self.enabled:
            return
        self.done += 1
        width = 30
        filled = width * self.done // max(self.total, 1)
        bar = "#" * filled + "-" * (width - filled)
        elapsed = time.perf_counter() - self.start
        line = f"[{bar}] {self.done}/{self.total} {elapsed:5.0f}s  {label}"
        if self.tty:
            sys.stderr.write("\r" + line[:110].ljust(110))
        else:
            sys.stderr.write(line + "\n")
        sys.stderr.flush()

    def finish(self) -> None:
        if self.enabled and self.tty:
            sys.stderr.write("\n")
            sys.stderr.flush()


# {====================================================================
# verdicts

@dataclass
class Verdict:
    """A scene against the thresholds: "pass", "fail", or "not gated" when none was given."""

    status: str
    failures: list[str] = field(default_factory=list)   # one phrase per shortfall
    checked: list[str] = field(default_factory=list)    # the builds held to the thresholds

    def text(self) -> str:
        if self.status == "fail":
            return "FAIL: " + "; ".join(self.failures)
        return self.status


def verdict(comp: Comparison, min_psnr: float | None = None,
            max_over_1lsb: float | None = None) -> Verdict:
    """Hold each build of `comp` but the reference to the thresholds: PSNR
    against the reference at least `min_psnr` dB, share of pixels off by more
    than 1 LSB at most `max_over_1lsb` (a fraction). Peers are shown, not
    gated. A build that failed, or has no reference to be measured against,
    falls short."""
    if min_psnr is None and max_over_1lsb is None:
        return Verdict("not gated")
    out = Verdict("pass")
    for name, r in comp.renders.items():
        if name not in BUILDS or name == comp.reference:
            continue
        out.checked.append(name)
        if r.error is not None or r.skipped is not None:
            out.failures.append(f"{name} failed")
        elif r.metrics is None:
            out.failures.append(f"{name} has no {comp.reference} image to be measured against")
        else:
            m = r.metrics
            if min_psnr is not None and m.psnr < min_psnr:
                out.failures.append(f"{name} {m.psnr:.1f} dB < {min_psnr:g} dB")
            if max_over_1lsb is not None and m.share_over_1lsb > max_over_1lsb:
                out.failures.append(f"{name} {100 * m.share_over_1lsb:.2f}% of pixels > 1 LSB "
                                    f"(at most {100 * max_over_1lsb:g}%)")
    if out.failures:
        out.status = "fail"
    return out


def _thresholds_text(min_psnr: float | None, max_over_1lsb: float | None) -> str:
    parts = []
    if min_psnr is not None:
        parts.append(f"PSNR against double at least {min_psnr:g} dB")
    if max_over_1lsb is not None:
        parts.append(f"at most {100 * max_over_1lsb:g}% of pixels off by more than 1 LSB")
    if not parts:
        return ("No thresholds were given (--min-psnr, --max-over-1lsb), so no scene is gated.")
    return ("A scene passes when each build other than the reference has " + " and ".join(parts)
            + "; Mesa is shown but not gated.")


# {====================================================================
# the plots (SVG by hand: no plotting dependency)

def _psnr_y(psnr: float, top: float) -> float:
    return top if math.isinf(psnr) else min(psnr, top - 4)


def _psnr_range(psnrs: Sequence[float]) -> tuple[float, float]:
    """(bottom, top) of a PSNR axis: identical images sit on the top line."""
    finite = [p for p in psnrs if not math.isinf(p)]
    top = max(60.0, math.ceil((max(finite) if finite else 50.0) / 10) * 10 + 10)
    bottom = min(0.0, math.floor(min(finite) / 10) * 10) if finite else 0.0
    return bottom, top


def _log_range(values: Sequence[float]) -> tuple[int, int]:
    xs = [math.log10(v) for v in values] or [0.0, 1.0]
    x0, x1 = math.floor(min(xs)), math.ceil(max(xs))
    return x0, (x1 if x1 > x0 else x0 + 1)


def _tick(v: float) -> str:
    """A power of ten for an axis: 0.01, 1, 100, 10k, 1M, 1G."""
    for unit, suffix in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if v >= unit:
            return f"{v / unit:g}{suffix}"
    return f"{v:g}"


def speed_error_svg(results: list[tuple[Entry, Comparison]], width: int = 720, height: int = 420,
                    title: str = "host time per frame against PSNR versus double",
                    labels: bool = True) -> str:
    """This host's time per frame (log scale) against PSNR versus the
    reference, one point per renderer per scene; identical images sit on the
    top line. (The report's overview is :func:`overview_svg`.)"""
    pts = []
    for entry, comp in results:
        for r in comp.renders.values():
            if r.metrics is None or not r.times_ms:
                continue
            pts.append((entry.name, r.renderer, max(r.time_ms, 1e-3), r.metrics.psnr))
    bottom, top = _psnr_range([p[3] for p in pts])
    x0, x1 = _log_range([p[2] for p in pts])
    ml, mr, mt, mb = 60, 150 if labels else 10, 30, 40
    pw, ph = width - ml - mr, height - mt - mb

    def sx(v: float) -> float:
        return ml + (math.log10(v) - x0) / (x1 - x0) * pw

    def sy(v: float) -> float:
        return mt + (top - v) / (top - bottom) * ph

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="11">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{ml}" y="16" font-size="13">{html.escape(title)}</text>']
    out += _axes(ml, mt, pw, ph, x0, x1, bottom, top, "host ms per frame (this machine, log scale)", height)
    for scene, renderer, ms, psnr in pts:
        color = COLORS.get(renderer, "#333")
        tip = f"{scene} on {renderer}: {ms:.2f} ms on this host, {_fmt_psnr(psnr)}"
        out.append(f'<circle cx="{sx(ms):.1f}" cy="{sy(_psnr_y(psnr, top)):.1f}" r="4" fill="{color}" '
                   f'fill-opacity="0.75"><title>{html.escape(tip)}</title></circle>')
    if labels:
        renderers = list(dict.fromkeys(p[1] for p in pts))
        for i, name in enumerate(renderers):
            y = mt + 10 + 16 * i
            out.append(f'<circle cx="{ml + pw + 16}" cy="{y}" r="5" fill="{COLORS.get(name, "#333")}"/>')
            out.append(f'<text x="{ml + pw + 24}" y="{y + 4}">{html.escape(name)}</text>')
    out.append("</svg>")
    return "\n".join(out)


def _axes(ml: float, mt: float, pw: float, ph: float, x0: int, x1: int, bottom: float, top: float,
          xlabel: str, height: float) -> list[str]:
    """Grid, tick labels and axis titles of one panel (x log scale, y PSNR)."""
    out = []
    for d in range(x0, x1 + 1):
        x = ml + (d - x0) / (x1 - x0) * pw
        out.append(f'<line x1="{x:.1f}" y1="{mt}" x2="{x:.1f}" y2="{mt + ph}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{mt + ph + 14}" text-anchor="middle">{_tick(10.0 ** d)}</text>')
    for v in range(int(bottom), int(top) + 1, 10):
        y = mt + (top - v) / (top - bottom) * ph
        label = "identical" if v == top else f"{v}"
        out.append(f'<line x1="{ml}" y1="{y:.1f}" x2="{ml + pw}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{ml - 4}" y="{y + 4:.1f}" text-anchor="end">{label}</text>')
    out.append(f'<text x="{ml + pw / 2}" y="{height - 6}" text-anchor="middle">{html.escape(xlabel)}</text>')
    out.append(f'<text x="{ml - 42}" y="{mt + ph / 2}" transform="rotate(-90 {ml - 42} {mt + ph / 2})" '
               f'text-anchor="middle">PSNR vs double (dB)</text>')
    return out


_SVG_STYLE = ("<style>.scene polyline{stroke:#999;stroke-width:1;fill:none}"
              ".scene:hover polyline{stroke:#000;stroke-width:2.5}"
              ".scene:hover text{font-weight:bold;fill:#000}"
              ".scene text{fill:#555;font-size:9px}</style>")


def overview_svg(results: list[tuple[Entry, Comparison]], costs: dict[str, Any] | None = None,
                 target_note: str = "", panel: tuple[int, int] = (460, 400),
                 target_size: tuple[int, int] | None = None) -> str:
    """The report's plot: two panels side by side, this host's time per frame
    and the no-FPU target's instructions per frame (fixed and float), each
    against PSNR versus double, and a legend.

    In each panel a grey line joins one scene's builds (fixed, float, double),
    the scene's number from the legend sits by its fixed-build point, and
    each point's hover text (``<title>``) names the scene, renderer and
    values. `costs` maps a scene's name to its :class:`gles.target.SceneCost`;
    without it the target panel shows `target_note` (what to install).
    `target_size` is the size the counts were taken at, when it is not the
    images' (whose PSNR both panels show).
    """
    pw, ph = panel
    ml, mt, mb, gap = 64, 40, 44, 70
    legend_w = 230
    width = ml + pw + gap + ml + pw + 20 + legend_w
    n = len(results)
    height = max(mt + ph + mb, mt + 20 + 16 * (len(COLORS) + 2) + 13 * n)
    host: list[tuple[int, str, str, float, float]] = []      # (index, scene, renderer, ms, psnr)
    tgt: list[tuple[int, str, str, float, float]] = []       # (index, scene, build, instructions, psnr)
    for i, (entry, comp) in enumerate(results, 1):
        for r in comp.renders.values():
            if r.metrics is None:
                continue
            if r.times_ms:
                host.append((i, entry.name, r.renderer, max(r.time_ms, 1e-3), r.metrics.psnr))
            cost = (costs or {}).get(entry.name)
            count = cost.instructions.get(r.renderer) if cost is not None else None
            if count:
                tgt.append((i, entry.name, r.renderer, float(count), r.metrics.psnr))
    bottom, top = _psnr_range([p[4] for p in host + tgt])
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="11">', _SVG_STYLE,
           f'<rect width="{width}" height="{height}" fill="white"/>']

    def panel_svg(left: float, title: str, xlabel: str, pts: list[tuple[int, str, str, float, float]],
                  unit: Callable[[float], str], empty: str) -> None:
        out.append(f'<text x="{left}" y="18" font-size="13">{html.escape(title)}</text>')
        x0, x1 = _log_range([p[3] for p in pts])
        out.extend(_axes(left, mt, pw, ph, x0, x1, bottom, top, xlabel, mt + ph + mb))

        def sx(v: float) -> float:
            return left + (math.log10(v) - x0) / (x1 - x0) * pw

        def sy(p: float) -> float:
            return mt + (top - _psnr_y(p, top)) / (top - bottom) * ph

        if not pts:
            for k, line in enumerate(_wrap(empty, 62)):
                out.append(f'<text x="{left + 10}" y="{mt + 30 + 15 * k}" fill="#a00">'
                           f'{html.escape(line)}</text>')
            return
        for i in sorted({p[0] for p in pts}):
            mine = [p for p in pts if p[0] == i]
            builds = [p for b in BUILDS for p in mine if p[2] == b]
            out.append(f'<g class="scene"><title>{i} {html.escape(mine[0][1])}</title>')
            if len(builds) > 1:
                coords = " ".join(f"{sx(p[3]):.1f},{sy(p[4]):.1f}" for p in builds)
                out.append(f'<polyline points="{coords}"/>')
            for _, scene, renderer, x, psnr in mine:
                tip = f"{i} {scene} on {renderer}: {unit(x)}, {_fmt_psnr(psnr)}"
                out.append(f'<circle cx="{sx(x):.1f}" cy="{sy(psnr):.1f}" r="4" '
                           f'fill="{COLORS.get(renderer, "#333")}" fill-opacity="0.8">'
                           f'<title>{html.escape(tip)}</title></circle>')
            anchor = next((p for p in mine if p[2] == "fixed"), mine[0])
            out.append(f'<text x="{sx(anchor[3]) + 5:.1f}" y="{sy(anchor[4]) - 4:.1f}">{i}</text>')
            out.append("</g>")

    panel_svg(ml, "host: time per frame against error", "host ms per frame (this machine, log scale)",
              host, lambda v: f"{v:.2f} ms on this host", "no timed renders")
    if target_size is not None and results and tgt:
        comp = results[0][1]
        out.append(f'<text x="{ml + pw + gap + ml}" y="32" fill="#555">counts at {target_size[0]}x'
                   f'{target_size[1]}; PSNR of the {comp.width}x{comp.height} images</text>')
    panel_svg(ml + pw + gap + ml, "no-FPU target: instructions per frame against error",
              "target instructions per frame (log scale)", tgt,
              lambda v: f"{v:,.0f} target instructions per frame", target_note or "no target counts")
    lx = ml + pw + gap + ml + pw + 20
    out.append(f'<text x="{lx}" y="{mt - 8}" font-size="12">renderers</text>')
    names = list(dict.fromkeys(p[2] for p in host)) or list(BUILDS)
    for k, name in enumerate(names):
        y = mt + 6 + 16 * k
        out.append(f'<circle cx="{lx + 6}" cy="{y}" r="5" fill="{COLORS.get(name, "#333")}"/>')
        out.append(f'<text x="{lx + 16}" y="{y + 4}">{html.escape(name)}</text>')
    y = mt + 16 * len(names) + 16
    out.append(f'<text x="{lx}" y="{y}" font-size="12">scenes (a line joins a scene\'s builds)</text>')
    for i, (entry, _comp) in enumerate(results, 1):
        out.append(f'<text x="{lx}" y="{y + 13 * i}">{i:>2}  {html.escape(entry.name)}</text>')
    out.append("</svg>")
    return "\n".join(out)


def _wrap(text: str, width: int) -> list[str]:
    lines, line = [], ""
    for word in text.split():
        if line and len(line) + 1 + len(word) > width:
            lines.append(line)
            line = word
        else:
            line = f"{line} {word}".strip()
    return [*lines, line] if line else lines


# the heatmaps' scale: black for equal, then the largest channel difference on a log scale
_BAR_TICKS = (1, 2, 4, 8, 16, 32, 64, 128, 255)


def colorbar_svg(width: int = 420) -> str:
    """The colour bar of the diff heatmaps, an SVG: the colours are those
    :func:`gles.compare.heatmap` gives each difference (not a copy of its ramp)."""
    from .compare import heatmap

    steps = 96
    ml, bar_w, swatch = 56, width - 56 - 20, 22
    diffs = np.array([min(255, max(1, round(2.0 ** (math.log2(255) * (k + 0.5) / steps))))
                      for k in range(steps)] + [0], dtype=np.uint8)
    ref = np.zeros((1, len(diffs), 3), dtype=np.uint8)
    img = np.zeros_like(ref)
    img[0, :, 0] = diffs
    colors = heatmap(img, ref)[0]

    def sx(d: float) -> float:
        return ml + math.log2(d) / math.log2(255) * bar_w

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="58" '
           f'font-family="sans-serif" font-size="11">',
           f'<rect width="{width}" height="58" fill="white"/>',
           '<text x="0" y="12">heatmap: largest channel difference against double, '
           '8-bit LSB (log scale)</text>']
    r, g, b = (int(c) for c in colors[-1])
    out.append(f'<rect class="equal" x="4" y="18" width="{swatch}" height="16" fill="#{r:02x}{g:02x}{b:02x}" '
               f'stroke="#999"><title>0: equal</title></rect>')
    out.append(f'<text x="{4 + swatch / 2}" y="48" text-anchor="middle">equal</text>')
    for k in range(steps):
        r, g, b = (int(c) for c in colors[k])
        x = ml + k * bar_w / steps
        out.append(f'<rect x="{x:.1f}" y="18" width="{bar_w / steps + 0.6:.1f}" height="16" '
                   f'fill="#{r:02x}{g:02x}{b:02x}"/>')
    for d in _BAR_TICKS:
        x = sx(d)
        out.append(f'<line x1="{x:.1f}" y1="34" x2="{x:.1f}" y2="38" stroke="#333"/>')
        out.append(f'<text x="{x:.1f}" y="48" text-anchor="middle">{d}</text>')
    out.append("</svg>")
    return "\n".join(out)


# {====================================================================
# the color buffer format

def _check_color(comp: Comparison, color: str) -> None:
    """Every image of a 16-bit report (RGB565, RGBA4444, RGBA5551) comes from
    a buffer of that format: a build's holds only the 2^m levels per channel
    gles expands to, a peer's at most that many distinct levels (Mesa expands
    by its own rule). Anything else would be an RGBA8888 render under the
    wrong name."""
    if color not in COLOR_LAYOUTS:
        return
    bits = [b for b, _ in COLOR_LAYOUTS[color] if b]
    levels = [{(c * 255 + m // 2) // m for c in range(m + 1)} for m in ((1 << b) - 1 for b in bits)]
    for r in comp.renders.values():
        if r.image is None:
            continue
        for ch in range(len(bits)):
            seen = set(np.unique(r.image[..., ch]).tolist())
            ok = seen <= levels[ch] if r.renderer in BUILDS else len(seen) <= 1 << bits[ch]
            if not ok:
                raise RuntimeError(f"{comp.scene} on {r.renderer}: the image is not from an "
                                   f"{color.upper()} buffer")


# {====================================================================
# the numbers (shared by the documents and report.json)

def _fmt_psnr(p: float) -> str:
    return "identical" if math.isinf(p) else f"{p:.1f} dB"


def _machine() -> str:
    return (f"gles {__version__}, Python {platform.python_version()}, {platform.machine()}, "
            f"{os.cpu_count()} CPUs, {platform.platform(terse=True)}; gles on one thread, Mesa with "
            f"LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', '1')}")


def _peer_versions(peers: Sequence[str]) -> dict[str, str]:
    """The GL_VERSION and GL_RENDERER of each peer that runs here."""
    out: dict[str, str] = {}
    for p in peers:
        if p not in PEERS:
            continue
        try:
            from . import mesa

            if mesa.available(p[5:]) is not None:
                continue
            ctx = mesa.MesaContext(1, 1, driver=p[5:])
            try:
                out[p] = f"{ctx.version} ({ctx.renderer})"
            finally:
                ctx.close()
        except Exception:  # noqa: BLE001 -- a version string is not worth failing the report for
            continue
    return out


def _num(v: float | None) -> float | None:
    """A float for JSON: None for nan and infinities (JSON has neither)."""
    return None if v is None or math.isnan(v) or math.isinf(v) else float(v)


def _render_data(entry: Entry, r: Any, cost: Any) -> dict[str, Any]:
    status = "skipped" if r.skipped else "failed" if r.error else "ok"
    d: dict[str, Any] = {"status": status, "reason": r.skipped or r.error,
                         "host_ms_per_frame": _num(r.time_ms) if r.times_ms else None,
                         "host_times_ms": [float(t) for t in r.times_ms], "gl_error": int(r.gl_error),
                         "metrics": None, "range_events": None, "target_instructions_per_frame": None,
                         "image": None, "heatmap": None}
    if r.metrics is not None:
        m = r.metrics
        d["metrics"] = {"max_abs": int(m.max_abs), "mean_abs": float(m.mean_abs), "rmse": float(m.rmse),
                        "psnr_db": _num(m.psnr), "identical": math.isinf(m.psnr),
                        "share_over_1lsb": float(m.share_over_1lsb)}
    if r.range is not None:
        d["range_events"] = {**{k: int(v) for k, v in r.range.counts.items()}, "total": int(r.range.total),
                             "draws_checked": int(r.range.draws_checked),
                             "by_source": {k: int(v) for k, v in r.range.by_source.items()},
                             "worst_margin": {k: float(v) for k, v in r.range.worst.items()}}
    if cost is not None and r.renderer in cost.instructions:
        d["target_instructions_per_frame"] = cost.instructions[r.renderer]
    if r.image is not None:
        d["image"] = f"img/{entry.name}_{r.renderer}.png"
    if r.heatmap is not None:
        d["heatmap"] = f"img/{entry.name}_{r.renderer}_diff.png"
    return d


def report_data(results: list[tuple[Entry, Comparison]], verdicts: Sequence[Verdict],
                costs: dict[str, Any] | None = None, *, runs: int = 0, color: str = "rgba8888",
                min_psnr: float | None = None, max_over_1lsb: float | None = None,
                target_missing: str | None = None, target_size: tuple[int, int] | None = None,
                elapsed_s: dict[str, float] | None = None, peers: Sequence[str] = ()) -> dict[str, Any]:
    """Everything report.json holds: every number of the page, with the
    thresholds, the verdicts, the machine, the sizes and the versions.
    PSNR of identical images is null with ``identical: true`` (JSON has no
    infinity); a time that was not measured is null."""
    from . import target

    first = results[0][1] if results else None
    scenes = []
    for i, ((entry, comp), v) in enumerate(zip(results, verdicts), 1):
        cost = (costs or {}).get(entry.name)
        tgt = None
        if cost is not None:
            tgt = {"instructions_per_frame": dict(cost.instructions), "fixed_over_float": _num(cost.ratio),
                   "host_ms_per_frame": {k: _num(x) for k, x in cost.host_ms.items()},
                   "error": cost.error or None}
        scenes.append({"number": i, "name": entry.name, "title": entry.title, "group": entry.group,
                       "note": entry.note, "reference": comp.reference,
                       "renders": {n: _render_data(entry, r, cost) for n, r in comp.renders.items()},
                       "target": tgt,
                       "verdict": {"status": v.status, "failures": list(v.failures),
                                   "checked": list(v.checked)}})
    return {
        "schema": SCHEMA_VERSION,
        "generator": "python -m gles report",
        "created": datetime.datetime.now().isoformat(timespec="seconds"),
        "versions": {"gles": __version__, "python": platform.python_version(), "numpy": np.__version__,
                     "peers": _peer_versions(peers)},
        "machine": {"arch": platform.machine(), "cpus": os.cpu_count(),
                    "platform": platform.platform(terse=True),
                    "lp_num_threads": os.environ.get("LP_NUM_THREADS", "1"),
                    "summary": _machine()},
        "size": [first.width, first.height] if first is not None else None,
        "color": color,
        "runs": runs,
        "timing": "host: median wall-clock ms per frame on this machine",
        "elapsed_s": {k: float(v) for k, v in (elapsed_s or {}).items()},   # render, target
        "thresholds": {"min_psnr": min_psnr, "max_over_1lsb": max_over_1lsb},
        "target": {"description": target.TARGET, "available": target_missing is None,
                   "missing": target_missing,
                   "size": list(target_size) if target_size else None, "color": "rgba8888",
                   "unit": "instructions per frame"},
        "renderers": list(dict.fromkeys(n for _, c in results for n in c.renders)),
        "scenes": scenes,
        "failing": [s["name"] for s in scenes if s["verdict"]["status"] == "fail"],
    }


# {====================================================================
# the documents

def _cell(r: Any) -> str:
    if r is None:
        return "–"
    if r.skipped:
        return "skipped"
    if r.error:
        return "FAILED"
    if r.metrics is None or not r.times_ms:
        return "–"
    return f"{r.time_ms:.2f} ms, {_fmt_psnr(r.metrics.psnr)}"


def _count(v: int | None) -> str:
    return "–" if not v else f"{v:,}"


def _summary_header(renderers: list[str]) -> list[str]:
    return (["#", "scene"] + [f"{n}: host ms, PSNR" for n in renderers]
            + ["target fixed (instr/frame)", "target float (instr/frame)", "target fixed / float",
               "range events", "verdict"])


def _summary_rows(results: list[tuple[Entry, Comparison]], renderers: list[str],
                  costs: dict[str, Any], verdicts: Sequence[Verdict]) -> list[list[str]]:
    rows = []
    for i, ((entry, comp), v) in enumerate(zip(results, verdicts), 1):
        row = [str(i), entry.name] + [_cell(comp.renders.get(name)) for name in renderers]
        cost = costs.get(entry.name)
        if cost is None:
            row += ["n/a", "n/a", "n/a"]
        else:
            ratio = cost.ratio
            row += [_count(cost.instructions.get("fixed")), _count(cost.instructions.get("float")),
                    "–" if ratio is None else f"{ratio:.2f}"]
        fixed = comp.renders.get("fixed")
        rng = fixed.range if fixed is not None else None
        row.append("–" if rng is None else
                   f"{rng.counts['overflow']}/{rng.counts['underflow']}/{rng.counts['rule']}")
        row.append(v.text())
        rows.append(row)
    return rows


_SCENE_HEADER = ["renderer", "host ms/frame", "max abs", "mean abs", "RMSE", "PSNR (dB)", ">1 LSB",
                 "range events", "target instr/frame"]


def _scene_rows(comp: Comparison, cost: Any) -> list[list[str]]:
    """Per renderer: host time, error, range events, target count; a
    skipped or failed renderer is one cell saying why."""
    rows = []
    for r in comp.renders.values():
        if r.skipped or r.error:
            rows.append([r.renderer, f"skipped: {r.skipped}" if r.skipped else f"FAILED: {r.error}"])
            continue
        m = r.metrics.row() if r.metrics else [""] * 5
        rng = str(r.range.total) if r.range is not None else ""
        count = cost.instructions.get(r.renderer) if cost is not None else None
        rows.append([r.renderer, f"{r.time_ms:.2f}", *m, rng, "" if count is None else f"{count:,}"])
    return rows


def _md_table(header: list[str], rows: list[list[str]], left: int = 1) -> list[str]:
    """A Markdown table, its first `left` columns and its last verdict column
    (when named so) aligned left, the numbers right."""
    align = ["---" if i < left or c == "verdict" else "--:" for i, c in enumerate(header)]
    out = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    for row in rows:
        row = [c.replace("|", "\\|") for c in row] + [""] * (len(header) - len(row))
        out.append("| " + " | ".join(row) + " |")
    return out


def _intro(w: int, h: int, runs: int, color: str, rendered_s: float, target_s: float,
           target_size: tuple[int, int], target_missing: str | None) -> str:
    from . import target

    tgt = (f"Target columns: instructions per frame on the no-FPU target ({target.TARGET}) at "
           f"{target_size[0]}x{target_size[1]}, counted exactly in an emulator"
           + (" with an RGBA8888 buffer" if color != "rgba8888" else "") + "; fixed / float below 1: "
           "fixed point runs fewer instructions there."
           if target_missing is None else f"Target columns: {target_missing}.")
    dither = (f" gles dithers an {color.upper()} buffer (GL_DITHER is on by default) and Mesa's llvmpipe "
              "and softpipe do not, so a peer's error includes gles's dither pattern."
              if color != "rgba8888" else "")
    return (f"{w}x{h} pixels, {color.upper()} framebuffer, error against the double build (rendered "
            f"the same way) over R, G and B.{dither} Times are host timings: the median of {runs} frames "
            f"per renderer on this machine ({_machine()}), not the target's. {tgt} "
            f"Rendered in {rendered_s:.0f} s" + (f", target counts in {target_s:.0f} s." if
                                                  target_missing is None else "."))


def _markdown(results: list[tuple[Entry, Comparison]], renderers: list[str], intro: str,
              costs: dict[str, Any], verdicts: Sequence[Verdict], thresholds: str) -> str:
    lines = ["# gles report: what 16.16 fixed point does to a scene, and what each precision costs", "",
             intro, "",
             "![host time and target instructions against PSNR](speed_vs_psnr.svg)", "",
             "## Summary", "",
             "Per renderer: this host's time per frame and the PSNR against double. Range events: the "
             "fixed build's overflows / underflows / draws breaking c*s + t < 16384. " + thresholds, ""]
    lines += _md_table(_summary_header(renderers), _summary_rows(results, renderers, costs, verdicts), left=2)
    group = None
    for i, ((entry, comp), v) in enumerate(zip(results, verdicts), 1):
        if entry.group != group:
            group = entry.group
            lines += ["", f"## {group}", "", "![heatmap colour scale](colorbar.svg)"]
        lines += ["", f"### {i}. {entry.name}: {entry.title}", ""]
        if entry.note:
            lines += [entry.note, ""]
        if v.status != "not gated":
            lines += [f"Verdict: {v.text()}", ""]
        present = [r for r in comp.renders.values() if r.image is not None]
        lines.append("| " + " | ".join(r.renderer for r in present) + " |")
        lines.append("|" + "---|" * len(present))
        lines.append("| " + " | ".join(f"![{r.renderer}](img/{entry.name}_{r.renderer}.png)" for r in present)
                     + " |")
        lines.append("| " + " | ".join(f"![diff](img/{entry.name}_{r.renderer}_diff.png)" for r in present)
                     + " |")
        lines += [""] + _md_table(_SCENE_HEADER, _scene_rows(comp, costs.get(entry.name)))
        fixed = comp.renders.get("fixed")
        if fixed is not None and fixed.range is not None and fixed.range.total:
            lines += ["", "Range checks on the fixed build:", "", "```", str(fixed.range), "```"]
    return "\n".join(lines) + "\n"


_CSS = """
body { font-family: sans-serif; margin: 2em; color: #222; max-width: 1400px; }
table { border-collapse: collapse; margin: 0.5em 0 1em; font-size: 13px; }
td, th { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
td:first-child, th:first-child { text-align: left; }
.fail { color: #b00; font-weight: bold; }
.pass { color: #070; }
td.fail, td.pass { text-align: left; }
.images { display: flex; flex-wrap: wrap; gap: 10px; }
figure { margin: 0; text-align: center; font-size: 12px; }
figure img { display: block; image-rendering: pixelated; border: 1px solid #ccc; }
pre { background: #f6f6f6; padding: 0.5em; font-size: 12px; }
.note { color: #555; }
.key { position: sticky; top: 0; z-index: 1; background: white; padding: 4px 0;
       border-bottom: 1px solid #ddd; }
.plot { overflow-x: auto; }
"""


def _html(results: list[tuple[Entry, Comparison]], renderers: list[str], intro: str, svg: str,
          costs: dict[str, Any], verdicts: Sequence[Verdict], thresholds: str, bar: str) -> str:
    e = html.escape
    w = results[0][1].width if results else 0
    shown = max(w, min(256, 2 * w))
    parts = ["<!DOCTYPE html>", "<html><head><meta charset='utf-8'>",
             "<title>gles report</title>", f"<style>{_CSS}</style></head><body>",
             "<h1>gles report: what 16.16 fixed point does to a scene, and what each precision costs</h1>",
             f"<p>{e(intro)}</p>", f"<div class='plot'>{svg}</div>",
             "<h2>Summary</h2><p class='note'>Per renderer: this host's time per frame and the PSNR against "
             "double. Range events: the fixed build's overflows / underflows / draws breaking c*s + t &lt; "
             f"16384. {e(thresholds)}</p>",
             "<table><tr>" + "".join(f"<th>{e(c)}</th>" for c in _summary_header(renderers)) + "</tr>"]
    for row, v in zip(_summary_rows(results, renderers, costs, verdicts), verdicts):
        cells = [f"<td>{e(c)}</td>" for c in row[:-1]]
        cells[1] = f"<td><a href='#{e(row[1])}'>{e(row[1])}</a></td>"
        cls = {"pass": "pass", "fail": "fail"}.get(v.status, "")
        parts.append("<tr>" + "".join(cells) + f"<td class='{cls}'>{e(row[-1])}</td></tr>")
    parts.append("</table>")
    group = None
    first_group = True
    for i, ((entry, comp), v) in enumerate(zip(results, verdicts), 1):
        if entry.group != group:
            group = entry.group
            parts.append(f"<h2>{e(group)}</h2>")
            if first_group:     # sticks to the top of the window while the scenes scroll by
                parts.append(f"<div class='key'>{bar}</div>")
                first_group = False
        parts.append(f"<h3 id='{e(entry.name)}'>{i}. {e(entry.name)}: {e(entry.title)}</h3>")
        if entry.note:
            parts.append(f"<p class='note'>{e(entry.note)}</p>")
        if v.status != "not gated":
            parts.append(f"<p class='{'fail' if v.status == 'fail' else 'pass'}'>Verdict: {e(v.text())}</p>")
        parts.append("<div class='images'>")
        for r in comp.renders.values():
            if r.image is None:
                parts.append(f"<figure><figcaption>{e(r.renderer)}: {e(r.skipped or r.error or '')}"
                             "</figcaption></figure>")
                continue
            cap = e(r.renderer) + (f", {_fmt_psnr(r.metrics.psnr)}" if r.metrics else "")
            parts.append(f"<figure><img src='img/{e(entry.name)}_{e(r.renderer)}.png' width='{shown}'>"
                         f"<img src='img/{e(entry.name)}_{e(r.renderer)}_diff.png' width='{shown}'>"
                         f"<figcaption>{cap}</figcaption></figure>")
        parts.append("</div>")
        parts.append("<table><tr>" + "".join(f"<th>{e(c)}</th>" for c in _SCENE_HEADER) + "</tr>")
        for row in _scene_rows(comp, costs.get(entry.name)):
            if len(row) == 2:
                parts.append(f"<tr><td>{e(row[0])}</td>"
                             f"<td colspan='{len(_SCENE_HEADER) - 1}'>{e(row[1])}</td></tr>")
            else:
                parts.append("<tr>" + "".join(f"<td>{e(c)}</td>" for c in row) + "</tr>")
        parts.append("</table>")
        parts.append(speed_error_svg([(entry, comp)], 420, 220, f"{entry.name}: host time against PSNR"))
        fixed = comp.renders.get("fixed")
        if fixed is not None and fixed.range is not None and fixed.range.total:
            parts.append(f"<pre>{e(str(fixed.range))}</pre>")
    parts.append("</body></html>")
    return "\n".join(parts)


def build_report(out: str | Path, width: int = 256, height: int = 256, runs: int = 3,
                 only: Sequence[str] | None = None, builds: Sequence[str] = BUILDS,
                 peers: Sequence[str] = PEERS, progress: bool = True, executor: Any = None,
                 jobs: int = 1, on_failure: Callable[[str, Render], None] | None = None, *,
                 color: str = "rgba8888", min_psnr: float | None = None,
                 max_over_1lsb: float | None = None) -> Path:
    """Render every scene and write the report into `out`; returns report.html's path.

    `only` names scenes (of the gallery and the hard cases) or scene files
    (``*.py``, see :func:`scene_file`); `color` is the framebuffer of every
    renderer, "rgba8888" or "rgb565"; `min_psnr` and `max_over_1lsb` (a
    fraction) give each scene a verdict, written into the report (and
    report.json's ``failing`` list).

    The (scene, renderer) jobs run in this process one after the other by
    default, in `jobs` worker processes, or on `executor` (any
    concurrent.futures.Executor); see :func:`gles.compare.compare`. Each
    renderer that failed is passed to ``on_failure(scene name, render)``
    (its ``traceback`` says why) and shown as failed in the report."""
    check_color(color)
    out = Path(out)
    (out / "img").mkdir(parents=True, exist_ok=True)
    todo = select(only)
    renderers = list(dict.fromkeys([*builds, *peers]))
    bar = Progress(len(todo) * len(renderers), progress)
    results: list[tuple[Entry, Comparison]] = []
    start = time.perf_counter()
    comps = compare_scenes([entry.scene for entry in todo], width, height, builds=builds, peers=peers,
                           runs=runs, progress=lambda i, name: bar.step(f"{todo[i].name} on {name}"),
                           executor=executor, jobs=jobs, color=color)
    for entry, comp in zip(todo, comps):
        comp.scene = entry.name
        for r in comp.renders.values():
            if r.image is not None:
                write_png(out / "img" / f"{entry.name}_{r.renderer}.png", r.image)
            if r.heatmap is not None:
                write_png(out / "img" / f"{entry.name}_{r.renderer}_diff.png", r.heatmap)
            if r.error is not None and on_failure is not None:
                on_failure(entry.name, r)
        results.append((entry, comp))
    bar.finish()
    rendered_s = time.perf_counter() - start
    for _entry, comp in results:
        _check_color(comp, color)
    # the no-FPU target's instructions per frame beside the host's ms (gles.target; n/a without it)
    from . import target
    missing = target.target_missing()
    cost_list = target.scene_costs(results, width, height)
    costs = {c.scene: c for c in cost_list}
    elapsed = time.perf_counter() - start
    target_s = elapsed - rendered_s
    verdicts = [verdict(comp, min_psnr, max_over_1lsb) for _, comp in results]
    tsize = target.report_size(width, height)
    intro = _intro(width, height, runs, color, rendered_s, target_s, tsize, missing)
    thresholds = _thresholds_text(min_psnr, max_over_1lsb)
    svg = overview_svg(results, costs, "Target instructions per frame: " + (missing or "none measured"),
                       target_size=tsize if tsize != (width, height) else None)
    (out / "speed_vs_psnr.svg").write_text(svg, encoding="utf-8")
    key = colorbar_svg()
    (out / "colorbar.svg").write_text(key, encoding="utf-8")
    md = _markdown(results, renderers, intro, costs, verdicts, thresholds)
    page_html = _html(results, renderers, intro, svg, costs, verdicts, thresholds, key)
    target_md, target_html = target.report_section(results, width, height, costs=cost_list)
    md += target_md
    page_html = page_html.replace("</body></html>", target_html + "\n</body></html>")
    data = report_data(results, verdicts, costs, runs=runs, color=color, min_psnr=min_psnr,
                       max_over_1lsb=max_over_1lsb, target_missing=missing, target_size=tsize,
                       elapsed_s={"render": rendered_s, "target": target_s}, peers=peers)
    (out / "report.json").write_text(json.dumps(data, indent=1, allow_nan=False) + "\n", encoding="utf-8")
    (out / "report.md").write_text(md, encoding="utf-8")
    page = out / "report.html"
    page.write_text(page_html, encoding="utf-8")
    stamp = datetime.datetime.now().isoformat(timespec="seconds")
    (out / "README.txt").write_text(f"gles report written {stamp}: open report.html\n", encoding="utf-8")
    return page
