"""``python -m gles report``: what 16.16 does to real scenes, and what each precision costs.

Renders the gallery (:mod:`gles.gallery`: the techniques the renderer is used
for) and the hard cases (:mod:`gles.hardcases`: where fixed point is
stressed) on the fixed, float and double builds and on Mesa's llvmpipe and
softpipe where present, and writes into one directory:

* ``report.html`` and ``report.md``: per scene the images side by side with
  their diff heatmaps against the double build, a table of time per frame
  and error (max abs, mean abs, RMSE, PSNR, share of pixels off by more than
  1 LSB) and the fixed build's range-check counts; a summary table;
* ``speed_vs_psnr.svg``: time per frame against PSNR versus double, one
  point per build and peer per scene, plus one small plot per scene;
* ``img/``: every image and heatmap as PNG.
"""

from __future__ import annotations

import datetime
import html
import math
import os
import platform
import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from . import __version__
from ._png import write_png
from .compare import BUILDS, PEERS, Comparison, Render, compare_scenes

# one colour per renderer, for the plots and the legend
COLORS = {"fixed": "#d62728", "float": "#1f77b4", "double": "#2ca02c",
          "mesa-llvmpipe": "#9467bd", "mesa-softpipe": "#8c564b"}


@dataclass(frozen=True)
class Entry:
    """One scene of the report."""

    name: str
    title: str
    group: str          # "Techniques" or "Hard cases"
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
# the speed-versus-error plot (SVG by hand: no plotting dependency)

def _psnr_y(psnr: float, top: float) -> float:
    return top if math.isinf(psnr) else min(psnr, top - 4)


def speed_error_svg(results: list[tuple[Entry, Comparison]], width: int = 720, height: int = 420,
                    title: str = "time per frame against PSNR versus double", labels: bool = True) -> str:
    """Time per frame (log scale) against PSNR versus the reference, one point
    per renderer per scene; identical images sit on the top line."""
    pts = []
    for entry, comp in results:
        for r in comp.renders.values():
            if r.metrics is None or not r.times_ms:
                continue
            pts.append((entry.name, r.renderer, max(r.time_ms, 1e-3), r.metrics.psnr))
    finite = [p[3] for p in pts if not math.isinf(p[3])]
    top = max(60.0, math.ceil((max(finite) if finite else 50.0) / 10) * 10 + 10)
    bottom = min(0.0, math.floor(min(finite) / 10) * 10) if finite else 0.0
    xs = [math.log10(p[2]) for p in pts] or [0.0, 1.0]
    x0, x1 = math.floor(min(xs)), math.ceil(max(xs))
    if x1 <= x0:
        x1 = x0 + 1
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
    for d in range(x0, x1 + 1):
        x = ml + (d - x0) / (x1 - x0) * pw
        out.append(f'<line x1="{x:.1f}" y1="{mt}" x2="{x:.1f}" y2="{mt + ph}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{mt + ph + 14}" text-anchor="middle">{10.0 ** d:g}</text>')
    for v in range(int(bottom), int(top) + 1, 10):
        y = sy(v)
        label = "identical" if v == top else f"{v}"
        out.append(f'<line x1="{ml}" y1="{y:.1f}" x2="{ml + pw}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{ml - 4}" y="{y + 4:.1f}" text-anchor="end">{label}</text>')
    out.append(f'<text x="{ml + pw / 2}" y="{height - 6}" text-anchor="middle">'
               'ms per frame (log scale)</text>')
    out.append(f'<text x="14" y="{mt + ph / 2}" transform="rotate(-90 14 {mt + ph / 2})" '
               f'text-anchor="middle">PSNR vs double (dB)</text>')
    for scene, renderer, ms, psnr in pts:
        color = COLORS.get(renderer, "#333")
        tip = f"{scene} on {renderer}: {ms:.2f} ms, {_fmt_psnr(psnr)}"
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


# {====================================================================
# the documents

def _fmt_psnr(p: float) -> str:
    return "identical" if math.isinf(p) else f"{p:.1f} dB"


def _machine() -> str:
    return (f"gles {__version__}, Python {platform.python_version()}, {platform.machine()}, "
            f"{os.cpu_count()} CPUs, {platform.platform(terse=True)}; Mesa with LP_NUM_THREADS="
            f"{os.environ.get('LP_NUM_THREADS', '1')}")


def _summary_rows(results: list[tuple[Entry, Comparison]], renderers: list[str]) -> list[list[str]]:
    rows = []
    for entry, comp in results:
        row = [entry.name]
        for name in renderers:
            r = comp.renders.get(name)
            if r is None or r.skipped or r.error or r.metrics is None:
                row.append("–")
            else:
                row.append(f"{r.time_ms:.2f} ms, {_fmt_psnr(r.metrics.psnr)}")
        fixed = comp.renders.get("fixed")
        rng = fixed.range if fixed is not None else None
        row.append("–" if rng is None else
                   f"{rng.counts['overflow']}/{rng.counts['underflow']}/{rng.counts['rule']}")
        rows.append(row)
    return rows


def _markdown(results: list[tuple[Entry, Comparison]], renderers: list[str], w: int, h: int,
              runs: int, elapsed: float) -> str:
    lines = ["# gles report: what 16.16 fixed point does to a scene, and what each precision costs", "",
             f"{w}x{h} pixels, median of {runs} frames per renderer, error against the double build "
             f"over R, G and B. {_machine()}. Rendered in {elapsed:.0f} s.", "",
             "![time per frame against PSNR](speed_vs_psnr.svg)", "",
             "## Summary", "",
             "Each cell: time per frame, PSNR against double. Range events: the fixed build's "
             "overflows / underflows / draws breaking c*s + t < 16384.", "",
             "| scene | " + " | ".join(renderers) + " | range events |",
             "|---|" + "--:|" * len(renderers) + "--:|"]
    for row in _summary_rows(results, renderers):
        lines.append("| " + " | ".join(row) + " |")
    group = None
    for entry, comp in results:
        if entry.group != group:
            group = entry.group
            lines += ["", f"## {group}"]
        lines += ["", f"### {entry.name}: {entry.title}", ""]
        if entry.note:
            lines += [entry.note, ""]
        present = [r for r in comp.renders.values() if r.image is not None]
        lines.append("| " + " | ".join(r.renderer for r in present) + " |")
        lines.append("|" + "---|" * len(present))
        lines.append("| " + " | ".join(f"![{r.renderer}](img/{entry.name}_{r.renderer}.png)" for r in present)
                     + " |")
        lines.append("| " + " | ".join(f"![diff](img/{entry.name}_{r.renderer}_diff.png)" for r in present)
                     + " |")
        lines += ["", comp.table()]
        fixed = comp.renders.get("fixed")
        if fixed is not None and fixed.range is not None and fixed.range.total:
            lines += ["", "Range checks on the fixed build:", "", "```", str(fixed.range), "```"]
    return "\n".join(lines) + "\n"


_CSS = """
body { font-family: sans-serif; margin: 2em; color: #222; max-width: 1400px; }
table { border-collapse: collapse; margin: 0.5em 0 1em; font-size: 13px; }
td, th { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
td:first-child, th:first-child { text-align: left; }
.images { display: flex; flex-wrap: wrap; gap: 10px; }
figure { margin: 0; text-align: center; font-size: 12px; }
figure img { display: block; image-rendering: pixelated; border: 1px solid #ccc; }
pre { background: #f6f6f6; padding: 0.5em; font-size: 12px; }
.note { color: #555; }
"""


def _html(results: list[tuple[Entry, Comparison]], renderers: list[str], w: int, h: int,
          runs: int, elapsed: float, svg: str) -> str:
    e = html.escape
    shown = max(w, min(256, 2 * w))
    parts = ["<!DOCTYPE html>", "<html><head><meta charset='utf-8'>",
             "<title>gles report</title>", f"<style>{_CSS}</style></head><body>",
             "<h1>gles report: what 16.16 fixed point does to a scene, and what each precision costs</h1>",
             f"<p>{w}x{h} pixels, median of {runs} frames per renderer, error against the double build over "
             f"R, G and B. {e(_machine())}. Rendered in {elapsed:.0f} s.</p>", svg,
             "<h2>Summary</h2><p class='note'>Each cell: time per frame, PSNR against double. Range events: "
             "the fixed build's overflows / underflows / draws breaking c*s + t &lt; 16384.</p>",
             "<table><tr><th>scene</th>" + "".join(f"<th>{e(n)}</th>" for n in renderers)
             + "<th>range events</th></tr>"]
    for row in _summary_rows(results, renderers):
        parts.append("<tr>" + "".join(f"<td>{e(c)}</td>" for c in row) + "</tr>")
    parts.append("</table>")
    group = None
    for entry, comp in results:
        if entry.group != group:
            group = entry.group
            parts.append(f"<h2>{e(group)}</h2>")
        parts.append(f"<h3 id='{e(entry.name)}'>{e(entry.name)}: {e(entry.title)}</h3>")
        if entry.note:
            parts.append(f"<p class='note'>{e(entry.note)}</p>")
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
        parts.append("<table><tr><th>renderer</th><th>ms/frame</th><th>max abs</th><th>mean abs</th>"
                     "<th>RMSE</th><th>PSNR (dB)</th><th>&gt;1 LSB</th><th>range events</th></tr>")
        for r in comp.renders.values():
            if r.skipped or r.error:
                why = f"skipped: {r.skipped}" if r.skipped else f"FAILED: {r.error}"
                parts.append(f"<tr><td>{e(r.renderer)}</td><td colspan='7'>{e(why)}</td></tr>")
                continue
            m = r.metrics.row() if r.metrics else [""] * 5
            rng = str(r.range.total) if r.range is not None else ""
            parts.append(f"<tr><td>{e(r.renderer)}</td><td>{r.time_ms:.2f}</td>"
                         + "".join(f"<td>{c}</td>" for c in m) + f"<td>{rng}</td></tr>")
        parts.append("</table>")
        parts.append(speed_error_svg([(entry, comp)], 420, 220, f"{entry.name}: time against PSNR"))
        fixed = comp.renders.get("fixed")
        if fixed is not None and fixed.range is not None and fixed.range.total:
            parts.append(f"<pre>{e(str(fixed.range))}</pre>")
    parts.append("<p class='note'>Heatmaps: black where a pixel equals the double build's; otherwise the "
                 "largest channel difference on a log scale, 1 LSB dark blue to 255 white.</p>")
    parts.append("</body></html>")
    return "\n".join(parts)


def build_report(out: str | Path, width: int = 256, height: int = 256, runs: int = 3,
                 only: Sequence[str] | None = None, builds: Sequence[str] = BUILDS,
                 peers: Sequence[str] = PEERS, progress: bool = True, executor: Any = None,
                 jobs: int = 1, on_failure: Callable[[str, Render], None] | None = None) -> Path:
    """Render every scene and write the report into `out`; returns report.html's path.

    The (scene, renderer) jobs run in this process one after the other by
    default, in `jobs` worker processes, or on `executor` (any
    concurrent.futures.Executor); see :func:`gles.compare.compare`. Each
    renderer that failed is passed to ``on_failure(scene name, render)``
    (its ``traceback`` says why) and shown as failed in the report."""
    out = Path(out)
    (out / "img").mkdir(parents=True, exist_ok=True)
    todo = entries(only)
    renderers = list(dict.fromkeys([*builds, *peers]))
    bar = Progress(len(todo) * len(renderers), progress)
    results: list[tuple[Entry, Comparison]] = []
    start = time.perf_counter()
    comps = compare_scenes([entry.scene for entry in todo], width, height, builds=builds, peers=peers,
                           runs=runs, progress=lambda i, name: bar.step(f"{todo[i].name} on {name}"),
                           executor=executor, jobs=jobs)
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
    elapsed = time.perf_counter() - start
    svg = speed_error_svg(results)
    (out / "speed_vs_psnr.svg").write_text(svg, encoding="utf-8")
    md = _markdown(results, renderers, width, height, runs, elapsed)
    page_html = _html(results, renderers, width, height, runs, elapsed, svg)
    # the no-FPU target's instructions per frame beside the host's ms (gles.target; n/a without it)
    from . import target
    target_md, target_html = target.report_section(results, width, height)
    md += target_md
    page_html = page_html.replace("</body></html>", target_html + "\n</body></html>")
    (out / "report.md").write_text(md, encoding="utf-8")
    page = out / "report.html"
    page.write_text(page_html, encoding="utf-8")
    stamp = datetime.datetime.now().isoformat(timespec="seconds")
    (out / "README.txt").write_text(f"gles report written {stamp}: open report.html\n", encoding="utf-8")
    return page
