"""Command line: ``python -m gles report|compare|render ...``.

* ``report [--out DIR] [--scenes NAMES|FILE.py] [--min-psnr DB] [--jobs N]``:
  the gallery and the hard cases (or your scenes) on every build and on
  Mesa, as report.html, report.md and report.json (the project's main job);
  ``--jobs N`` renders in N worker processes; exits 1 when a render fails or
  a scene falls short of the thresholds.
* ``compare SCENE.py``: one scene on the builds and peers, a table of time
  against error, and optionally the images and heatmaps.
* ``render SCENE.py -o OUT.png``: one scene on one build, to a PNG.
* ``libdir [--numeric N] [--profile P] [--include]``: the directory of
  libGLESv1_CM and libEGL (and their pkg-config files) for C programs, or
  with ``--include`` that of the Khronos headers.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from . import compare as cmp
from ._png import write_png


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"size must look like 256x256, not {text!r}") from None
    if not (1 <= w <= 4096 and 1 <= h <= 4096):
        raise argparse.ArgumentTypeError(f"size {w}x{h} is outside 1..4096")
    return w, h


def _jobs(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"jobs must be a whole number, not {text!r}") from None
    if not 1 <= n <= 256:
        raise argparse.ArgumentTypeError(f"jobs {n} is outside 1..256")
    return n


def _names(text: str) -> list[str]:
    return [n for n in text.split(",") if n]


def _cmd_compare(args: argparse.Namespace) -> int:
    scene = cmp.load_scene(args.scene, args.function)
    w, h = args.size
    result = cmp.compare(scene, w, h, builds=args.builds, peers=args.peers, runs=args.runs,
                         progress=lambda name: print(f"  rendered on {name}", file=sys.stderr),
                         jobs=args.jobs)
    print(f"{result.scene} at {w}x{h}, error against {result.reference}, median of {args.runs} frames\n")
    print(result.table())
    fixed = result.renders.get("fixed")
    if fixed is not None and fixed.range is not None and fixed.range.total:
        print()
        print(fixed.range)
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        for r in result.renders.values():
            if r.image is not None:
                write_png(out / f"{result.scene}_{r.renderer}.png", r.image)
            if r.heatmap is not None:
                write_png(out / f"{result.scene}_{r.renderer}_diff.png", r.heatmap)
        print(f"\nimages in {out}")
    for r in result.renders.values():
        if r.error is not None:
            _print_failure("compare", None, r)
    return 1 if result.failed else 0


def _print_failure(command: str, scene: str | None, r: cmp.Render) -> None:
    where = f"{scene}: " if scene else ""
    print(f"python -m gles {command}: {where}{r.renderer} failed: {r.error}", file=sys.stderr)
    if r.traceback:
        print(r.traceback.rstrip("\n"), file=sys.stderr)


def _cmd_render(args: argparse.Namespace) -> int:
    scene = cmp.load_scene(args.scene, args.function)
    w, h = args.size
    try:
        r = cmp.render(scene, args.numeric, w, h, runs=1)
    except Exception as exc:  # noqa: BLE001 -- the scene's own failure, reported
        print(f"{args.numeric}: {type(exc).__name__}: {exc}", file=sys.stderr)
        return 1
    if r.image is None:
        print(f"{args.numeric}: {r.skipped}", file=sys.stderr)
        return 1
    write_png(args.output, r.image)
    print(f"{args.output}: {w}x{h} on {args.numeric}, {r.time_ms:.2f} ms")
    return 0


def _cmd_report(args: argparse.Namespace) -> int:
    import json

    from . import report

    w, h = args.size
    failed: list[str] = []

    def on_failure(scene: str, r: cmp.Render) -> None:
        failed.append(f"{scene} on {r.renderer}")
        _print_failure("report", scene, r)

    path = report.build_report(args.out, w, h, runs=args.runs, only=args.only, builds=args.builds,
                               peers=args.peers, progress=not args.quiet, jobs=args.jobs,
                               on_failure=on_failure, color=args.color,
                               min_psnr=args.min_psnr, max_over_1lsb=args.max_over_1lsb)
    print(f"report: {path} (and {path.with_suffix('.md')}, {path.with_suffix('.json')})")
    status = 0
    if failed:
        print(f"python -m gles report: {len(failed)} renders failed: {', '.join(failed)}", file=sys.stderr)
        status = 1
    data = json.loads(path.with_suffix(".json").read_text(encoding="utf-8"))
    failing = [s for s in data["scenes"] if s["verdict"]["status"] == "fail"]
    if failing:
        detail = "; ".join(f"{s['name']} ({', '.join(s['verdict']['failures'])})" for s in failing)
        print(f"python -m gles report: {len(failing)} of {len(data['scenes'])} scenes fall short: {detail}",
              file=sys.stderr)
        status = 1
    return status


def _psnr(text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"--min-psnr must be a number of dB, not {text!r}") from None
    if math.isnan(v):
        raise argparse.ArgumentTypeError("--min-psnr must be a number of dB, not nan")
    return v


def _share(text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        v = math.nan
    if not 0.0 <= v <= 1.0:
        raise argparse.ArgumentTypeError(
            f"--max-over-1lsb must be a fraction in 0..1 (0.01 is 1%), not {text!r}")
    return v


def _cmd_trace(args: argparse.Namespace) -> int:
    from . import trace

    scene = cmp.load_scene(args.scene, args.function)
    w, h = args.size
    t = trace.trace(scene, w, h, numeric=args.numeric, color=args.color, path=args.output)
    print(f"{args.output}: {t.calls} calls, {len(t.data)} bytes, {w}x{h} on {args.numeric}")
    try:
        print(f"replay: {trace.replayer(args.numeric)} {args.output} -o image.raw")
    except FileNotFoundError as exc:
        print(exc, file=sys.stderr)
    return 0


def _cmd_libdir(args: argparse.Namespace) -> int:
    from . import cabi

    print(cabi.include_dir() if args.include else cabi.libdir(args.numeric, args.profile))
    return 0


_REPORT_HELP = """\
Render scenes on the fixed, float and double builds and on Mesa; write
report.html, report.md, report.json and speed_vs_psnr.svg into --out.

Scenes: by default the gallery and the hard cases. --scenes takes names
of those and/or Python files of your own scenes: a file defines a dict
SCENES = {"name": scene} (or {"name": ("title", scene)}), or else every
public function name(gl, w, h) in it is a scene (helpers start with _).
A scene issues GL ES 1.1 calls on gl and may return a frame() callable
(then only frame() is timed).

Verdicts: with --min-psnr (and/or --max-over-1lsb) every build but the
double reference must reach the thresholds in every scene; the report
says which fall short, and the command exits 1 (2 for a usage error), so
a CI job can gate on its own scenes:

  python -m gles report --scenes my_scenes.py --min-psnr 40
"""


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m gles", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)

    def common(p: argparse.ArgumentParser, size: str) -> None:
        p.add_argument("--size", type=_size, default=_size(size), help=f"WxH (default {size})")
        p.add_argument("--runs", type=int, default=5, help="frames timed per renderer (median reported)")
        p.add_argument("--builds", type=_names, default=list(cmp.BUILDS),
                       help="comma-separated builds (default fixed,float,double)")
        p.add_argument("--jobs", type=_jobs, default=1,
                       help="run the (scene, renderer) jobs in N worker processes (default 1: in this "
                            "process); the times are noisier, the images and errors the same")

    p = sub.add_parser("report", help="render the gallery and hard cases (or your scenes); write "
                       "report.html, report.md and report.json; gate on --min-psnr",
                       description=_REPORT_HELP, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default="gles-report", help="output directory (default ./gles-report)")
    common(p, "256x256")
    p.add_argument("--peers", type=_names, default=list(cmp.PEERS),
                   help="comma-separated peers (default mesa-llvmpipe,mesa-softpipe; '' for none)")
    p.add_argument("--scenes", "--only", dest="only", type=_names, default=None, metavar="NAMES,FILE.py",
                   help="comma-separated gallery or hard-case scene names and/or scene files (*.py); "
                   "default: the gallery and the hard cases")
    p.add_argument("--color", default="rgba8888", choices=list(cmp.COLOR_FORMATS),
                   help="framebuffer of every renderer, the double reference included (default rgba8888; "
                   "Mesa has no RGBA4444 or RGBA5551 window, so its peers are skipped there)")
    p.add_argument("--min-psnr", type=_psnr, default=None, metavar="DB",
                   help="a scene falls short when a build's PSNR against double is below DB")
    p.add_argument("--max-over-1lsb", type=_share, default=None, metavar="FRACTION",
                   help="a scene falls short when a build has more than FRACTION of its pixels off by "
                   "more than 1 LSB (0.01 is 1%%)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=_cmd_report)

    p = sub.add_parser("compare", help="one scene on the builds and peers: time against error")
    p.add_argument("scene", help="a Python file defining scene(gl, w, h)")
    p.add_argument("--function", default=None, help="the scene function's name (default: scene)")
    common(p, "256x256")
    p.add_argument("--peers", type=_names, default=["mesa-llvmpipe"],
                   help="comma-separated peers (default mesa-llvmpipe; '' for none)")
    p.add_argument("--out", default=None, help="write images and heatmaps to this directory")
    p.set_defaults(run=_cmd_compare)

    p = sub.add_parser("render", help="one scene on one build, to a PNG")
    p.add_argument("scene", help="a Python file defining scene(gl, w, h)")
    p.add_argument("-o", "--output", required=True, help="PNG file to write")
    p.add_argument("--function", default=None, help="the scene function's name (default: scene)")
    p.add_argument("--numeric", default="fixed", choices=[*cmp.BUILDS, *cmp.PEERS])
    p.add_argument("--size", type=_size, default=_size("256x256"), help="WxH (default 256x256)")
    p.set_defaults(run=_cmd_render)

    p = sub.add_parser("trace", help="record one scene's core calls into a trace file (see gles.trace)")
    p.add_argument("scene", help="a Python file defining scene(gl, w, h)")
    p.add_argument("-o", "--output", required=True, help="trace file to write (.glestrace)")
    p.add_argument("--function", default=None, help="the scene function's name (default: scene)")
    p.add_argument("--numeric", default="fixed", choices=list(cmp.BUILDS))
    p.add_argument("--color", default="rgba8888", choices=list(cmp.COLOR_FORMATS))
    p.add_argument("--size", type=_size, default=_size("256x256"), help="WxH (default 256x256)")
    p.set_defaults(run=_cmd_trace)

    p = sub.add_parser("libdir", help="print the directory of libGLESv1_CM and libEGL for C programs")
    p.add_argument("--numeric", default="fixed", choices=list(cmp.BUILDS))
    p.add_argument("--profile", default="common", choices=["common", "common-lite"])
    p.add_argument("--include", action="store_true", help="print the Khronos headers' directory instead")
    p.set_defaults(run=_cmd_libdir)

    args = parser.parse_args(argv)
    try:
        return int(args.run(args))
    except (OSError, ValueError, SyntaxError, AttributeError) as exc:
        # a missing or broken scene file, an unknown scene or renderer
        print(f"python -m gles {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
