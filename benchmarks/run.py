"""Time the scenes on gles (fixed, float, double) and Mesa (llvmpipe, softpipe) in one run.

    python benchmarks/run.py [--size 640x480] [--frames N] [--scenes a,b] [--out FILE.md]

Each (backend, scene) gets a fresh context: setup, warm-up frames, then N
timed frames, each ending with glFinish (so Mesa's deferred rendering is
counted). The median ms per frame is reported. The last frame's image is
checked (enough pixels differ from the clear colour, no GL error), so a
broken scene cannot post a fast time.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

import gles
from gles import mesa

sys.path.insert(0, str(Path(__file__).resolve().parent))
from scenes import CLEAR, SCENES  # noqa: E402

GLES_BUILDS = ("fixed", "float", "double")
MESA_DRIVERS = ("llvmpipe", "softpipe")


@dataclass
class Result:
    ms: float | None = None                 # median ms per frame
    spread: tuple[float, float] | None = None   # min, max ms per frame
    coverage: float | None = None           # pixels differing from the clear colour
    vs_llvmpipe: float | None = None        # pixels differing from llvmpipe's image by > 2 levels
    problems: list[str] = field(default_factory=list)


def backends(w: int, h: int) -> dict[str, tuple[Callable[[], Any] | None, str]]:
    """name -> (context factory or None, description or why unavailable)."""
    out: dict[str, tuple[Callable[[], Any] | None, str]] = {}
    for b in GLES_BUILDS:
        out[f"gles-{b}"] = ((lambda b=b: gles.Context(w, h, numeric=b)), f"gles {gles.__version__} ({b})")
    for d in MESA_DRIVERS:
        reason = mesa.available(d)
        if reason is None:
            out[d] = ((lambda d=d: mesa.MesaContext(w, h, driver=d)), "")
        else:
            out[d] = (None, reason)
    return out


def run_one(make: Callable[[], Any], scene: Any, w: int, h: int, frames: int,
            warmup: int) -> tuple[Result, Any]:
    ctx = make()
    try:
        gl = ctx.gl
        if hasattr(ctx, "make_current"):
            ctx.make_current()
        state = scene.setup(gl, w, h)
        for _ in range(warmup):
            scene.frame(gl, state)
            gl.glFinish()
        times = []
        for _ in range(frames):
            t0 = time.perf_counter()
            scene.frame(gl, state)
            gl.glFinish()
            times.append(time.perf_counter() - t0)
        res = Result(ms=1000 * statistics.median(times), spread=(1000 * min(times), 1000 * max(times)))
        err = gl.glGetError()
        if err:
            res.problems.append(f"GL error 0x{err:04X}")
        img = ctx.image()
        clear = np.array([round(255 * c) for c in CLEAR[:3]], dtype=np.uint8)
        res.coverage = float((img[..., :3] != clear).any(axis=-1).mean())
        want = scene.min_coverage(w, h)
        if res.coverage < want:
            res.problems.append(f"only {100 * res.coverage:.1f}% of pixels drawn (want >= {100 * want:.0f}%)")
        return res, img
    finally:
        close = getattr(ctx, "close", None)
        if close is not None:
            close()


def fmt(v: float | None, spec: str = ".2f", none: str = "n/a") -> str:
    return none if v is None else format(v, spec)


def table(header: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(r[i]) for r in [header, *rows]) for i in range(len(header))]
    line = "| " + " | ".join(h.ljust(wd) for h, wd in zip(header, widths)) + " |"
    sep = "|" + "|".join("-" * (wd + 2) if i == 0 else "-" * (wd + 1) + ":"
                         for i, wd in enumerate(widths)) + "|"
    body = ["| " + " | ".join(c.ljust(wd) if i == 0 else c.rjust(wd)
                              for i, (c, wd) in enumerate(zip(r, widths))) + " |" for r in rows]
    return "\n".join([line, sep, *body])


def check_cell(r: Result) -> str:
    def pct(v: float | None, spec: str) -> str:
        return fmt(None if v is None else 100 * v, spec)
    return f"{pct(r.coverage, '.1f')} / {pct(r.vs_llvmpipe, '.2f')}"


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} CPUs, Python {platform.python_version()}, numpy {np.__version__}"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--size", default="640x480", help="WxH (default 640x480)")
    ap.add_argument("--frames", type=int, default=20, help="timed frames per scene (default 20)")
    ap.add_argument("--warmup", type=int, default=2, help="untimed frames first (default 2)")
    ap.add_argument("--scenes", default=",".join(SCENES),
                    help=f"comma-separated subset of {','.join(SCENES)}")
    ap.add_argument("--out", help="also write the report as Markdown to this file")
    args = ap.parse_args(argv)
    try:
        w, h = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        ap.error(f"--size must be WxH, not {args.size!r}")
    names = [s for s in args.scenes.split(",") if s]
    unknown = [s for s in names if s not in SCENES]
    if unknown:
        ap.error(f"unknown scenes {unknown}; known: {list(SCENES)}")
    if args.frames < 1:
        ap.error("--frames must be at least 1")

    # llvmpipe on one thread: compared with a single-threaded renderer. Mesa
    # reads this when its display is initialised, i.e. at the first context.
    os.environ["LP_NUM_THREADS"] = "1"

    avail = backends(w, h)
    results: dict[tuple[str, str], Result] = {}
    for name in names:
        scene = SCENES[name]
        images: dict[str, Any] = {}
        for bname, (make, why) in avail.items():
            if make is None:
                results[bname, name] = Result(problems=[f"unavailable: {why}"])
                continue
            print(f"{name:14s} {bname:12s} ...", end="", flush=True, file=sys.stderr)
            res, images[bname] = run_one(make, scene, w, h, args.frames, args.warmup)
            results[bname, name] = res
            print(f" {res.ms:9.2f} ms/frame", " ".join(res.problems), file=sys.stderr)
        ref = images.get("llvmpipe")
        for bname, img in images.items():
            if ref is not None:
                diff = np.abs(img[..., :3].astype(np.int16) - ref[..., :3].astype(np.int16)).max(axis=-1)
                results[bname, name].vs_llvmpipe = float((diff > 2).mean())

    bnames = list(avail)
    mesa_info = []
    for d in MESA_DRIVERS:
        if avail[d][0] is not None:
            with mesa.MesaContext(1, 1, driver=d) as c:
                mesa_info.append(f"{c.renderer}, {c.version}")
    cmd = "python benchmarks/run.py " + " ".join(argv if argv is not None else sys.argv[1:])
    lines = [f"Command: `{cmd.strip()}`", "",
             f"{w}x{h}, {args.frames} timed frames after {args.warmup} warm-up, median ms per frame "
             "(each frame ends with glFinish); LP_NUM_THREADS=1.", "",
             f"Machine: {machine()}.", ""]
    if mesa_info:
        lines += ["Mesa: " + "; ".join(mesa_info) + ".", ""]

    lines += ["Milliseconds per frame (lower is faster):", ""]
    lines.append(table(["scene", *bnames],
                       [[n, *(fmt(results[b, n].ms) for b in bnames)] for n in names]))
    ratio_cols = [(g, m) for m in MESA_DRIVERS for g in GLES_BUILDS]
    lines += ["", "Time ratio gles / Mesa: below 1 means gles is faster, above 1 means Mesa is "
              "faster (2.00 = gles takes twice as long):", ""]
    rows = []
    for n in names:
        row = [n]
        for g, m in ratio_cols:
            a, b = results[f"gles-{g}", n].ms, results[m, n].ms
            row.append(fmt(a / b if a is not None and b else None))
        rows.append(row)
    lines.append(table(["scene", *(f"{g} / {m}" for g, m in ratio_cols)], rows))
    lines += ["", "Image check: % of pixels drawn (differing from the clear colour), and % differing "
              "from llvmpipe's image by more than 2 levels in a channel:", ""]
    lines.append(table(["scene", *bnames], [[n, *(check_cell(results[b, n]) for b in bnames)]
                                            for n in names]))
    problems = [f"- {b} {n}: {p}" for (b, n), r in results.items() for p in r.problems]
    failed = [p for p in problems if "unavailable" not in p]
    if problems:
        lines += ["", "Problems:", "", *problems]
    report = "\n".join(lines) + "\n"
    print(report)
    if args.out:
        Path(args.out).write_text(report)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
