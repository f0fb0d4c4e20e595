"""The best of several timed batches of one scene on one backend.

    python benchmarks/best_of.py BACKEND SCENE [--batches 7] [--frames 20] [--size 640x480]

A noisy machine slows some batches and never speeds one up, so the
smallest batch mean is the steadiest figure for comparing two builds of
the code: run this alternately in both trees (each with its own package
on PYTHONPATH) and compare the minima. Prints ``SCENE BACKEND ms`` (ms per
frame, each frame ending with glFinish). For llvmpipe on one thread, set
LP_NUM_THREADS=1 as benchmarks/run.py does.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import run  # noqa: E402
from scenes import SCENES  # noqa: E402


def best_of(backend: str, scene: str, batches: int, frames: int, w: int, h: int) -> float:
    """The smallest mean frame time (ms) of `batches` batches of `frames` frames, after 5 warm-up frames."""
    sc = SCENES[scene]
    _ctx, gl, state = run.prepare(backend, sc, w, h, 0)
    for _ in range(5):
        sc.frame(gl, state)
        gl.glFinish()
    best = float("inf")
    for _ in range(batches):
        t = time.perf_counter()
        for _ in range(frames):
            sc.frame(gl, state)
            gl.glFinish()
        best = min(best, (time.perf_counter() - t) / frames)
    return best * 1e3


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("backend", help="gles-fixed, gles-float, gles-double, llvmpipe, ...")
    ap.add_argument("scene", choices=sorted(SCENES))
    ap.add_argument("--batches", type=int, default=7)
    ap.add_argument("--frames", type=int, default=20)
    ap.add_argument("--size", default="640x480")
    a = ap.parse_args()
    w, h = (int(v) for v in a.size.split("x"))
    print(f"{a.scene} {a.backend} {best_of(a.backend, a.scene, a.batches, a.frames, w, h):.3f}")


if __name__ == "__main__":
    main()
