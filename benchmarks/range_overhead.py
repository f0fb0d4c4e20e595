"""What the default range checks cost: the fixed build with range_check="warn"
against "off" on the benchmark scenes.

    python benchmarks/range_overhead.py [--size 640x480] [--frames 30] [scene ...]

Frames alternate between the two contexts and the minimum CPU time of each
is reported, so a busy machine disturbs both sides alike.
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import gles  # noqa: E402
from benchmarks.scenes import SCENES  # noqa: E402


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenes", nargs="*", default=list(SCENES))
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--frames", type=int, default=30)
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.split("x"))
    warnings.simplefilter("ignore")
    print("| scene | off (ms) | warn (ms) | overhead |\n|---|--:|--:|--:|")
    for name in args.scenes:
        scene = SCENES[name]
        runs = {}
        for policy in ("off", "warn"):
            ctx = gles.Context(w, h, numeric="fixed", range_check=policy, color=scene.color)
            runs[policy] = (ctx, scene.setup(ctx.gl, w, h), [])
        for _ in range(args.frames):
            for ctx, state, times in runs.values():
                t0 = time.process_time()
                scene.frame(ctx.gl, state)
                ctx.gl.glFinish()
                times.append(time.process_time() - t0)
        off, on = (1e3 * min(runs[p][2]) for p in ("off", "warn"))
        print(f"| {name} | {off:.2f} | {on:.2f} | {100 * (on / off - 1):+.1f}% |")


if __name__ == "__main__":
    main()
