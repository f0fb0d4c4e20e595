"""The first frame after a state change against a steady frame, per scene and backend.

    python benchmarks/first_frame.py [--scenes a,b] [--backends gles-fixed,llvmpipe] [--rounds 12]

Each round changes state that the renderer derives its fragment path from
(dithering on or off, and the fog hint), times the next frame, then times
one more frame with the state unchanged. The report gives the median of
each and their ratio: what a state change costs the frame after it (gles
recomposes its chain of span stages; llvmpipe compiles a new shader
variant the first time it sees a state).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

from gles import constants as C
from gles import mesa

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run import close_context, prepare  # noqa: E402
from scenes import SCENES  # noqa: E402

BACKENDS = ("gles-fixed", "gles-float", "gles-double", "llvmpipe")


def measure(backend: str, name: str, rounds: int, w: int = 640, h: int = 480) -> tuple[float, float]:
    """Median ms of the first frame after a state change and of the frame after it."""
    scene = SCENES[name]
    ctx, gl, state = prepare(backend, scene, w, h, 1)
    try:
        first, steady = [], []
        for i in range(rounds):
            (gl.glEnable if i % 2 else gl.glDisable)(C.GL_DITHER)
            gl.glHint(C.GL_FOG_HINT, C.GL_NICEST if i % 2 else C.GL_DONT_CARE)
            for out in (first, steady):
                t0 = time.perf_counter()
                scene.frame(gl, state)
                gl.glFinish()
                out.append(1000 * (time.perf_counter() - t0))
        return statistics.median(first), statistics.median(steady)
    finally:
        close_context(ctx)


def main(argv: list[str] | None = None) -> int:
    """Print the table; 0 always (a missing Mesa driver is a row saying so)."""
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--scenes", default="textured_blend,combine_dot3,stencil_multipass,trilinear_fog")
    ap.add_argument("--backends", default=",".join(BACKENDS))
    ap.add_argument("--rounds", type=int, default=12)
    args = ap.parse_args(argv)
    os.environ.setdefault("LP_NUM_THREADS", "1")
    print("| scene | backend | first frame ms | steady ms | first / steady |")
    print("|---|---|---:|---:|---:|")
    for name in args.scenes.split(","):
        for backend in args.backends.split(","):
            if not backend.startswith("gles-") and mesa.available(backend) is not None:
                print(f"| {name} | {backend} | n/a | n/a | n/a |")
                continue
            f, s = measure(backend, name, args.rounds)
            print(f"| {name} | {backend} | {f:.2f} | {s:.2f} | {f / s:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
