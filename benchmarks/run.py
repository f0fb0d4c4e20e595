"""Time the scenes on gles (fixed, float, double) and Mesa (llvmpipe, softpipe) in one run.

    python benchmarks/run.py [--size 640x480] [--frames N] [--warmup N] [--rounds R] [--scenes a,b]
                             [--backends gles-fixed,llvmpipe] [--instructions] [--out FILE.md]

Each (backend, scene) gets a fresh context: setup and warm-up frames, then N
timed frames, each ending with glFinish (so Mesa's deferred rendering is
counted). The backends of a scene take their timed frames side by side: in
--rounds rounds, each backend in turn (the order rotating) draws one untimed
frame and then its share of the N, so a slow spell of the machine falls on
every backend alike instead of on whichever ran then. The median ms per
frame is reported, and the ratio llvmpipe ms / gles ms (above 1: gles is
faster) with its geometric mean over the scenes.
The last frame's image is checked (enough pixels differ from the clear
colour, no GL error), so a broken scene cannot post a fast time.

``--instructions`` also counts user-space instructions per frame: each
(backend, scene) runs twice in a subprocess (``run.py --one BACKEND SCENE``)
under ``perf stat -e instructions:u`` or, where the CPU's counters are not
available, ``valgrind --tool=callgrind``, once with F frames and once with
none after the same setup and warm-up; (I_F - I_0) / F is the figure, every
thread of the process included.
"""

from __future__ import annotations

import argparse
import ctypes
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

# numpy's BLAS threads spin for a while after a call (the scenes' setup makes
# some): on a machine of few CPUs they would take one from llvmpipe's two
# threads (its binning and its rasteriser) or from ours. One thread each,
# unless the caller says otherwise, before numpy starts them.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

import gles  # noqa: E402
from gles import mesa  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from scenes import ALIASES, CLEAR, SCENES, Scene  # noqa: E402

GLES_BUILDS = ("fixed", "float", "double")
MESA_DRIVERS = ("llvmpipe", "softpipe")
BACKENDS = tuple(f"gles-{b}" for b in GLES_BUILDS) + MESA_DRIVERS
# The builds whose fragment stages have an AVX-512 instance, capped at their
# AVX2 one (ctx.debug(32)): what a CPU without AVX-512 runs. Not in the
# default set; on such a CPU they equal gles-fixed and gles-double.
AVX2_CAPPED = ("gles-fixed-avx2", "gles-double-avx2")
CHOICES = BACKENDS + AVX2_CAPPED

# Under callgrind the counted subprocess starts instrumentation itself, after
# setup and warm-up (a client request in a small library built here with the C
# compiler), so the interpreter start-up, setup and llvmpipe's shader compiles
# run uninstrumented, at a few times native speed instead of about 40x slower;
# both runs start counting at the same point and count the same exit.
START_ENV = "GLES_BENCH_CALLGRIND_START"
_START_C = """#include <valgrind/callgrind.h>
void gles_bench_start(void) { CALLGRIND_START_INSTRUMENTATION; }
"""

# Environment of the instruction-count subprocesses: no Mesa shader disk cache
# (a cache hit in one run and a compile in the other would not cancel), no
# hash randomisation, no .pyc writes.
COUNT_ENV = {"MESA_SHADER_CACHE_DISABLE": "true", "PYTHONHASHSEED": "0", "PYTHONDONTWRITEBYTECODE": "1"}


@dataclass
class Result:
    """What one (backend, scene) pair measured."""

    ms: float | None = None                     # median ms per frame
    spread: tuple[float, float] | None = None   # min, max ms per frame
    coverage: float | None = None               # pixels differing from the clear colour
    vs_llvmpipe: float | None = None            # pixels differing from llvmpipe's image beyond tolerance
    instructions: float | None = None           # user-space instructions per frame
    problems: list[str] = field(default_factory=list)


# {================================================================
# contexts and one (backend, scene) run

def backend_status(name: str) -> str | None:
    """None if the backend can run here, else why not."""
    if name.startswith("gles-"):
        return None
    return mesa.available(name)


# the threads a gles context rasterizes with (--threads; llvmpipe's are LP_NUM_THREADS)
THREADS = 1


def make_context(backend: str, w: int, h: int, color: str) -> Any:
    """A fresh context of the backend with the scene's colour format (24-bit depth, 8-bit stencil)."""
    if backend.startswith("gles-"):
        build = backend[len("gles-"):].removesuffix("-avx2")
        ctx = gles.Context(w, h, numeric=build, color=color, threads=THREADS)
        if backend in AVX2_CAPPED:
            ctx.debug(32)       # at most the AVX2 instance
        return ctx
    return mesa.MesaContext(w, h, driver=backend, color=color)


def close_context(ctx: Any) -> None:
    close = getattr(ctx, "close", None)
    if close is not None:
        close()


def prepare(backend: str, scene: Scene, w: int, h: int, warmup: int) -> tuple[Any, Any, Any]:
    """A fresh context made current, the scene set up and `warmup` frames drawn: (ctx, gl, state)."""
    ctx = make_context(backend, w, h, scene.color)
    gl = ctx.gl
    if hasattr(ctx, "make_current"):
        ctx.make_current()
    state = scene.setup(gl, w, h)
    for _ in range(warmup):
        scene.frame(gl, state)
        gl.glFinish()
    return ctx, gl, state


def run_scene(backends: Sequence[str], scene: Scene, w: int, h: int, frames: int, warmup: int,
              rounds: int) -> dict[str, tuple[Result, np.ndarray]]:
    """Every backend's context at once (setup and warm-up each), then `rounds` rounds of timed
    frames: in each, every backend in turn (the order rotating from round to round) draws one
    untimed frame (the caches the others left) and its share of the `frames`. Then each
    backend's image check. Returns each backend's result and last image."""
    live: dict[str, tuple[Any, Any, Any]] = {}
    if not backends:
        return {}
    try:
        for b in backends:
            live[b] = prepare(b, scene, w, h, warmup)
        times: dict[str, list[float]] = {b: [] for b in live}
        order = list(live)
        rounds = max(1, min(rounds, frames))
        for r in range(rounds):
            share = frames // rounds + (1 if r < frames % rounds else 0)
            for b in order[r % len(order):] + order[:r % len(order)]:
                ctx, gl, state = live[b]
                if hasattr(ctx, "make_current"):
                    ctx.make_current()
                if rounds > 1:
                    scene.frame(gl, state)
                    gl.glFinish()
                for _ in range(share):
                    t0 = time.perf_counter()
                    scene.frame(gl, state)
                    gl.glFinish()
                    times[b].append(time.perf_counter() - t0)
        out = {}
        for b, (ctx, gl, _state) in live.items():
            if hasattr(ctx, "make_current"):
                ctx.make_current()
            t = times[b]
            res = Result(ms=1000 * statistics.median(t), spread=(1000 * min(t), 1000 * max(t)))
            err = gl.glGetError()
            if err:
                res.problems.append(f"GL error 0x{err:04X}")
            img = ctx.image()
            res.coverage = float((img[..., :3] != clear_rgb(scene.color)).any(axis=-1).mean())
            want = scene.min_coverage(w, h)
            if res.coverage < want:
                res.problems.append(f"only {100 * res.coverage:.1f}% of pixels drawn "
                                    f"(want >= {100 * want:.0f}%)")
            out[b] = (res, img)
        return out
    finally:
        for ctx, _gl, _state in live.values():
            close_context(ctx)


def clear_rgb(color: str) -> np.ndarray:
    """The clear colour as the image reads it back: 8-bit, or a 5/6/5-bit value expanded to 8 bits."""
    bits = (5, 6, 5) if color == "rgb565" else (8, 8, 8)
    out = []
    for c, b in zip(CLEAR[:3], bits):
        m = (1 << b) - 1
        out.append(round(round(c * m) * 255 / m))
    return np.array(out, dtype=np.uint8)


def differing(img: np.ndarray, ref: np.ndarray, color: str) -> float:
    """Share of pixels differing from ref by more than 2 levels in a channel (rgba8888), or by more
    than one step of the 5- or 6-bit channel (rgb565, where one step is 8 or 4 levels)."""
    diff = np.abs(img[..., :3].astype(np.int16) - ref[..., :3].astype(np.int16))
    tol = np.array([255 / 31, 255 / 63, 255 / 31]) + 0.5 if color == "rgb565" else np.array([2, 2, 2])
    return float((diff > tol).any(axis=-1).mean())


def one(backend: str, scene_name: str, w: int, h: int, frames: int, warmup: int) -> int:
    """The subprocess of --instructions: setup, warm-up, then `frames` frames, nothing else.

    Under callgrind with the start library in the environment, counting starts after the warm-up.
    """
    scene = SCENES[scene_name]
    ctx, gl, state = prepare(backend, scene, w, h, warmup)
    if os.environ.get(START_ENV):
        ctypes.CDLL(os.environ[START_ENV]).gles_bench_start()
    for _ in range(frames):
        scene.frame(gl, state)
        gl.glFinish()
    err = gl.glGetError()
    close_context(ctx)
    return 1 if err else 0


# {================================================================
# instruction counts

def counter_tool() -> tuple[str | None, str]:
    """("perf" or "callgrind" or None, a note): perf where instructions:u counts, else callgrind."""
    notes = []
    if shutil.which("perf"):
        try:
            p = subprocess.run(["perf", "stat", "-x,", "-e", "instructions:u", "true"],
                               capture_output=True, text=True, timeout=60)
            if _perf_count(p.stderr) is not None:
                return "perf", "perf stat -e instructions:u"
            notes.append("perf has no instructions:u counter here (no PMU)")
        except (OSError, subprocess.SubprocessError) as e:
            notes.append(f"perf failed: {e}")
    else:
        notes.append("no perf")
    if shutil.which("valgrind"):
        return "callgrind", "valgrind --tool=callgrind (" + "; ".join(notes) + ")"
    return None, "; ".join(notes + ["no valgrind"])


def build_start_library(tmp: str) -> str | None:
    """Compile the callgrind start request into tmp/start.so; None without a compiler or valgrind's header."""
    cc = shutil.which(os.environ.get("CC", "cc")) or shutil.which("gcc")
    if cc is None:
        return None
    src, lib = Path(tmp) / "start.c", Path(tmp) / "start.so"
    src.write_text(_START_C)
    p = subprocess.run([cc, "-O1", "-shared", "-fPIC", "-o", str(lib), str(src)], capture_output=True)
    return str(lib) if p.returncode == 0 else None


def _perf_count(stderr: str) -> int | None:
    for line in stderr.splitlines():
        parts = line.split(",")
        if len(parts) > 2 and parts[2].startswith("instructions"):
            return int(parts[0]) if parts[0].isdigit() else None
    return None


def count_instructions(tool: str, backend: str, scene: str, w: int, h: int, frames: int,
                       warmup: int, lp_threads: str, start_lib: str | None) -> tuple[int | None, str]:
    """Instructions of one `--one` subprocess (all its threads), or None and why.

    Under callgrind with `start_lib`, counting starts after setup; otherwise at the process start.
    """
    cmd = [sys.executable, str(Path(__file__).resolve()), "--one", backend, scene,
           "--size", f"{w}x{h}", "--frames", str(frames), "--warmup", str(warmup), "--threads", str(THREADS)]
    env = {**os.environ, **COUNT_ENV, "LP_NUM_THREADS": lp_threads}
    env.pop(START_ENV, None)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        if tool == "perf":
            cmd = ["perf", "stat", "-x,", "-e", "instructions:u", "--", *cmd]
        else:
            # one file for all threads (--separate-threads=no is the default); no children
            opts = ["--tool=callgrind", f"--callgrind-out-file={out}", "--trace-children=no"]
            if start_lib:
                opts.append("--instr-atstart=no")
                env[START_ENV] = start_lib
            cmd = ["valgrind", *opts, *cmd]
        p = subprocess.run(cmd, capture_output=True, text=True, env=env)
        if p.returncode != 0:
            tail = p.stderr.strip().splitlines()[-1:] or [f"exit {p.returncode}"]
            return None, f"subprocess failed: {tail[0]}"
        if tool == "perf":
            n = _perf_count(p.stderr)
        else:
            m = re.search(r"^totals:\s*(\d+)", out.read_text(), re.M) if out.exists() else None
            n = int(m.group(1)) if m else None
        return n, "" if n is not None else "no count in the tool's output"


def instructions_per_frame(tool: str, backend: str, scene: str, w: int, h: int, frames: int,
                           warmup: int, lp_threads: str, start_lib: str | None) -> tuple[float | None, str]:
    """(I_F - I_0) / F: the same subprocess with F frames and with none."""
    i_f, why = count_instructions(tool, backend, scene, w, h, frames, warmup, lp_threads, start_lib)
    if i_f is None:
        return None, why
    i_0, why = count_instructions(tool, backend, scene, w, h, 0, warmup, lp_threads, start_lib)
    if i_0 is None:
        return None, why
    return (i_f - i_0) / frames, ""


# {================================================================
# the report

def fmt(v: float | None, spec: str = ".2f", none: str = "n/a") -> str:
    """v formatted, or `none`."""
    return none if v is None else format(v, spec)


def table(header: list[str], rows: list[list[str]]) -> str:
    """A Markdown table, first column left-aligned, the others right-aligned."""
    widths = [max(len(r[i]) for r in [header, *rows]) for i in range(len(header))]
    line = "| " + " | ".join(h.ljust(wd) for h, wd in zip(header, widths)) + " |"
    sep = "|" + "|".join("-" * (wd + 2) if i == 0 else "-" * (wd + 1) + ":"
                         for i, wd in enumerate(widths)) + "|"
    body = ["| " + " | ".join(c.ljust(wd) if i == 0 else c.rjust(wd)
                              for i, (c, wd) in enumerate(zip(r, widths))) + " |" for r in rows]
    return "\n".join([line, sep, *body])


def geomean(values: Sequence[float | None]) -> float | None:
    """Geometric mean of the values present, None if there are none."""
    v = [x for x in values if x is not None and x > 0]
    return math.exp(sum(math.log(x) for x in v) / len(v)) if v else None


def ratio(a: float | None, b: float | None) -> float | None:
    """a / b, or None when either is missing."""
    return a / b if a is not None and b else None


def ratio_table(results: dict[tuple[str, str], Result], names: list[str], bnames: list[str],
                key: str) -> str | None:
    """Mesa / gles per scene and build, float/fixed and double/fixed, and a geometric-mean row."""
    cols: list[tuple[str, str, str]] = []        # (header, numerator backend, denominator backend)
    gles_names = [f"gles-{g}" for g in GLES_BUILDS] + list(AVX2_CAPPED)
    for m in MESA_DRIVERS:
        for g in gles_names:
            if m in bnames and g in bnames:
                cols.append((f"{m} / {g[len('gles-'):]}", m, g))
    for g in GLES_BUILDS[1:]:
        if "gles-fixed" in bnames and f"gles-{g}" in bnames:
            cols.append((f"{g} / fixed", f"gles-{g}", "gles-fixed"))
    if all(g in bnames for g in AVX2_CAPPED):
        cols.append(("double-avx2 / fixed-avx2", "gles-double-avx2", "gles-fixed-avx2"))
    for g in AVX2_CAPPED:
        plain = g[:-len("-avx2")]
        if plain in bnames and g in bnames:
            cols.append((f"{g[len('gles-'):]} / {plain[len('gles-'):]}", g, plain))
    if not cols:
        return None
    rows, per_col = [], [[] for _ in cols]
    for n in names:
        row = [n]
        for i, (_, a, b) in enumerate(cols):
            r = ratio(getattr(results[a, n], key), getattr(results[b, n], key))
            per_col[i].append(r)
            row.append(fmt(r))
        rows.append(row)
    rows.append(["geometric mean", *(fmt(geomean(v)) for v in per_col)])
    return table(["scene", *(c[0] for c in cols)], rows)


def check_cell(r: Result) -> str:
    """'coverage % / % differing from llvmpipe'."""
    def pct(v: float | None, spec: str) -> str:
        return fmt(None if v is None else 100 * v, spec)
    return f"{pct(r.coverage, '.1f')} / {pct(r.vs_llvmpipe, '.2f')}"


def machine() -> str:
    """CPU model, CPU count, Python and numpy versions."""
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} CPUs, Python {platform.python_version()}, numpy {np.__version__}"


# {================================================================
# command line

def parse_size(ap: argparse.ArgumentParser, s: str) -> tuple[int, int]:
    """'WxH' -> (w, h)."""
    try:
        w, h = (int(v) for v in s.lower().split("x"))
    except ValueError:
        ap.error(f"--size must be WxH, not {s!r}")
    return w, h


def pick(ap: argparse.ArgumentParser, given: str, known: Sequence[str], what: str,
         aliases: dict[str, str] | None = None) -> list[str]:
    """The comma-separated names in `given`, each known (or an alias), in the given order."""
    out = []
    for s in (s for s in given.split(",") if s):
        s = (aliases or {}).get(s, s)
        if s not in known:
            ap.error(f"unknown {what} {s!r}; known: {','.join(known)}")
        if s not in out:
            out.append(s)
    return out


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark (or, with --one, one counted subprocess) and print the report."""
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--size", default="640x480", help="WxH (default 640x480)")
    ap.add_argument("--frames", type=int, default=20, help="timed frames per scene (default 20)")
    ap.add_argument("--warmup", type=int, default=2, help="untimed frames first (default 2)")
    ap.add_argument("--rounds", type=int, default=5,
                    help="rounds the timed frames are split into, the backends taking turns in each "
                         "(default 5; 1: each backend's frames in one go)")
    ap.add_argument("--scenes", default=",".join(SCENES),
                    help=f"comma-separated subset of {','.join(SCENES)} (default all)")
    ap.add_argument("--backends", default=",".join(BACKENDS),
                    help=f"comma-separated subset of {','.join(CHOICES)} (default: all but the -avx2 ones, "
                         "the fixed and double builds capped at their AVX2 instance)")
    ap.add_argument("--instructions", action="store_true",
                    help="also count instructions per frame (perf stat, else callgrind)")
    ap.add_argument("--instr-frames", type=int, default=2, help="frames of the counted run (default 2)")
    ap.add_argument("--instr-warmup", type=int, default=1,
                    help="frames before them in both counted runs (default 1; at least 1, so that "
                         "llvmpipe compiles its shaders there)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                    help="counted subprocesses run at once (default: CPU count; counts do not depend on it)")
    ap.add_argument("--threads", type=int, default=1,
                    help="threads each gles context rasterizes with, and llvmpipe's LP_NUM_THREADS "
                         "unless --lp-threads says otherwise (default 1)")
    ap.add_argument("--lp-threads", help="LP_NUM_THREADS for llvmpipe (default: --threads)")
    ap.add_argument("--out", help="also write the report as Markdown to this file")
    ap.add_argument("--one", nargs=2, metavar=("BACKEND", "SCENE"),
                    help="run one backend and scene (setup, --warmup, --frames frames) and exit; "
                         "what --instructions counts")
    args = ap.parse_args(argv)
    w, h = parse_size(ap, args.size)
    if not 1 <= args.threads <= gles.context.MAX_THREADS:
        ap.error(f"--threads must be in 1..{gles.context.MAX_THREADS}")
    global THREADS
    THREADS = args.threads
    if args.lp_threads is None:
        args.lp_threads = str(args.threads)
    if args.one:
        backend, scene = args.one
        if backend not in CHOICES or scene not in SCENES:
            ap.error(f"--one takes one of {','.join(CHOICES)} and one of {','.join(SCENES)}")
        return one(backend, scene, w, h, args.frames, args.warmup)
    names = pick(ap, args.scenes, list(SCENES), "scene", ALIASES)
    bnames = pick(ap, args.backends, CHOICES, "backend")
    if args.frames < 1 or args.instr_frames < 1 or args.rounds < 1:
        ap.error("--frames, --instr-frames and --rounds must be at least 1")
    instr_warmup = max(1, args.instr_warmup)

    # llvmpipe's thread count: Mesa reads it when its display is initialised,
    # i.e. at the first context. With 1, rasterisation runs in one worker
    # thread while the calling thread binds, transforms and bins.
    os.environ["LP_NUM_THREADS"] = args.lp_threads

    status = {b: backend_status(b) for b in bnames}
    results: dict[tuple[str, str], Result] = {}
    for name in names:
        scene = SCENES[name]
        images: dict[str, np.ndarray] = {}
        for bname in bnames:
            if status[bname] is not None:
                results[bname, name] = Result(problems=[f"unavailable: {status[bname]}"])
        ready = [b for b in bnames if status[b] is None]
        print(f"{name:18s} ...", end="", flush=True, file=sys.stderr)
        for bname, (res, images[bname]) in run_scene(ready, scene, w, h, args.frames, args.warmup,
                                                      args.rounds).items():
            results[bname, name] = res
            print(f" {bname} {res.ms:.2f} ms", " ".join(res.problems), end="", file=sys.stderr)
        print(file=sys.stderr, flush=True)
        ref = images.get("llvmpipe")
        if ref is not None:
            for bname, img in images.items():
                results[bname, name].vs_llvmpipe = differing(img, ref, scene.color)

    tool, tool_note = (None, "")
    tmpdir = tempfile.TemporaryDirectory()
    if args.instructions:
        tool, tool_note = counter_tool()
        if tool is None:
            print(f"--instructions: no counter ({tool_note})", file=sys.stderr)
        else:
            start_lib = None
            if tool == "callgrind":
                start_lib = build_start_library(tmpdir.name)
                tool_note += (", counting from the end of warm-up" if start_lib else
                              ", counting from the process start (no C compiler or valgrind/callgrind.h)")
            pairs = [(b, n) for n in names for b in bnames if status[b] is None]
            print(f"counting instructions with {tool_note}, {len(pairs)} pairs, {args.jobs} at once",
                  file=sys.stderr)

            def work(pair: tuple[str, str]) -> None:
                b, n = pair
                t0 = time.perf_counter()
                ipf, why = instructions_per_frame(tool, b, n, w, h, args.instr_frames, instr_warmup,
                                                  args.lp_threads, start_lib)
                results[b, n].instructions = ipf
                if ipf is None:
                    results[b, n].problems.append(f"instruction count: {why}")
                print(f"{n:18s} {b:12s} {fmt(None if ipf is None else ipf / 1e6, '10.2f')} M instr/frame "
                      f"({time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)

            with ThreadPoolExecutor(max(1, args.jobs)) as pool:
                list(pool.map(work, pairs))
    tmpdir.cleanup()

    mesa_info = []
    for d in MESA_DRIVERS:
        if d in bnames and status[d] is None:
            with mesa.MesaContext(1, 1, driver=d) as c:
                mesa_info.append(f"{c.renderer}, {c.version}")
    cmd = "python benchmarks/run.py " + " ".join(argv if argv is not None else sys.argv[1:])
    rounds = max(1, min(args.rounds, args.frames))
    rounds_note = (f", in {rounds} rounds the backends take turns in (one untimed frame each before its "
                   f"share)" if rounds > 1 else "")
    lines = [f"Command: `{cmd.strip()}`", "",
             f"{w}x{h}, {args.frames} timed frames after {args.warmup} warm-up{rounds_note}, "
             f"median ms per frame "
             f"(each frame ends with glFinish); gles threads={args.threads}, "
             f"LP_NUM_THREADS={args.lp_threads}.", "",
             f"Machine: {machine()}.", ""]
    if mesa_info:
        lines += ["Mesa: " + "; ".join(mesa_info) + ".", ""]

    lines += ["Milliseconds per frame (lower is faster):", ""]
    lines.append(table(["scene", *bnames], [[n, *(fmt(results[b, n].ms) for b in bnames)] for n in names]))
    rt = ratio_table(results, names, bnames, "ms")
    if rt:
        lines += ["", "Time ratio Mesa / gles: above 1 means gles is faster (2.00 = Mesa takes twice as "
                  "long); float / fixed and double / fixed are time ratios of the gles builds (below 1: "
                  "faster than fixed):", "", rt]
    if tool is not None:
        lines += ["", f"Instructions per frame, millions (user space, all threads; {tool_note}; "
                  f"(I_F - I_0) / F with F = {args.instr_frames}, after {instr_warmup} warm-up):", ""]
        lines.append(table(["scene", *bnames], [[n, *(fmt(None if results[b, n].instructions is None
                                                             else results[b, n].instructions / 1e6)
                                                         for b in bnames)] for n in names]))
        it = ratio_table(results, names, bnames, "instructions")
        if it:
            lines += ["", "Instruction ratio Mesa / gles (above 1: gles executes fewer instructions):",
                      "", it]
    lines += ["", "Image check: % of pixels drawn (differing from the clear colour), and % differing "
              "from llvmpipe's image by more than 2 levels in a channel (for rgb565 scenes: by more than "
              "one step of the 5- or 6-bit channel):", ""]
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
