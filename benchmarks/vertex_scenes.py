"""Vertex-heavy scenes for instruction counts and timing of the vertex stage.

    python benchmarks/vertex_scenes.py SCENE BUILD FRAMES [--size 320x240] [--time]

SCENE is lit_mesh (gles.gallery), city (about 400 lit boxes, each its own
draw, GL_NORMALIZE on, fog, a flythrough camera) or smooth_mesh
(benchmarks/scenes.py). Renders FRAMES frames after setup. For stable
numbers run it under a counter with FRAMES = N and FRAMES = 0 and take
(I_N - I_0) / N, e.g.

    valgrind --tool=callgrind --callgrind-out-file=/dev/null \\
        python benchmarks/vertex_scenes.py city fixed 4

With --time it prints the median wall time per frame of FRAMES frames.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np

import gles
from gles import constants as C
from gles import gallery

sys.path.insert(0, str(Path(__file__).resolve().parent))
import scenes  # noqa: E402


def _box() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A unit cube, 24 vertices (4 per face, with the face normal) and 36 indices."""
    verts, normals, idx = [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            n = np.zeros(3)
            n[axis] = sign
            u = np.zeros(3)
            u[(axis + 1) % 3] = 1.0
            v = np.cross(n, u)
            base = len(verts)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                verts.append(0.5 * (n + a * u + b * v))
                normals.append(n)
            idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return (np.array(verts, np.float32), np.array(normals, np.float32), np.array(idx, np.uint16))


def city(gl: Any, w: int, h: int) -> Callable[[], None]:
    """400 boxes on a 20 x 20 grid, each translated and scaled (so GL_NORMALIZE
    matters), a sun and an attenuated street light, linear fog, culling."""
    gl.glClearColor(0.5, 0.6, 0.7, 1.0)
    gl.glClearDepthf(1.0)
    gl.glDisable(C.GL_DITHER)
    gl.glEnable(C.GL_DEPTH_TEST)
    gl.glEnable(C.GL_CULL_FACE)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_NORMAL_ARRAY)
    verts, normals, idx = _box()
    scenes._perspective(gl, w, h, 0.2, 60.0, half_height=0.1)
    gl.glEnable(C.GL_LIGHTING)
    gl.glEnable(C.GL_NORMALIZE)
    gl.glEnable(C.GL_LIGHT0)
    gl.glEnable(C.GL_LIGHT1)
    gl.glLightfv(C.GL_LIGHT0, C.GL_DIFFUSE, [0.8, 0.75, 0.7, 1.0])
    gl.glLightfv(C.GL_LIGHT0, C.GL_SPECULAR, [0.3, 0.3, 0.3, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_DIFFUSE, [0.9, 0.7, 0.4, 1.0])
    gl.glLightfv(C.GL_LIGHT1, C.GL_SPECULAR, [0.0, 0.0, 0.0, 1.0])
    gl.glLightf(C.GL_LIGHT1, C.GL_LINEAR_ATTENUATION, 0.2)
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_AMBIENT, [0.3, 0.3, 0.35, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_DIFFUSE, [0.7, 0.7, 0.75, 1.0])
    gl.glMaterialfv(C.GL_FRONT_AND_BACK, C.GL_SPECULAR, [0.5, 0.5, 0.5, 1.0])
    gl.glMaterialf(C.GL_FRONT_AND_BACK, C.GL_SHININESS, 20.0)
    gl.glEnable(C.GL_FOG)
    gl.glFogf(C.GL_FOG_MODE, C.GL_LINEAR)
    gl.glFogf(C.GL_FOG_START, 10.0)
    gl.glFogf(C.GL_FOG_END, 50.0)
    gl.glFogfv(C.GL_FOG_COLOR, [0.5, 0.6, 0.7, 1.0])
    rng = np.random.default_rng(7)
    boxes = [(float(i * 2.0 - 19.0), float(j * 2.0 - 19.0), float(rng.uniform(0.8, 1.4)),
              float(rng.uniform(1.0, 6.0))) for i in range(20) for j in range(20)]
    count = [0]

    def frame() -> None:
        t = count[0]
        count[0] += 1
        gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT)
        gl.glLoadIdentity()
        gl.glLightfv(C.GL_LIGHT0, C.GL_POSITION, [0.4, 0.8, 0.45, 0.0])
        gl.glRotatef(25.0, 1.0, 0.0, 0.0)
        gl.glRotatef(10.0 + 2.0 * t, 0.0, 1.0, 0.0)
        gl.glTranslatef(-2.0, -14.0, -28.0 + 0.5 * t)
        gl.glLightfv(C.GL_LIGHT1, C.GL_POSITION, [0.0, 2.0, 0.0, 1.0])
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glNormalPointer(C.GL_FLOAT, 0, normals)
        for x, z, s, hgt in boxes:
            gl.glPushMatrix()
            gl.glTranslatef(x, 0.5 * hgt, z)
            gl.glScalef(s, hgt, s)
            gl.glDrawElements(C.GL_TRIANGLES, len(idx), C.GL_UNSIGNED_SHORT, idx)
            gl.glPopMatrix()

    return frame


def smooth_mesh(gl: Any, w: int, h: int) -> Callable[[], None]:
    """benchmarks/scenes.py's smooth_mesh."""
    state = scenes.smooth_mesh_setup(gl, w, h)
    return lambda: scenes.smooth_mesh_frame(gl, state)


SCENES = {"lit_mesh": gallery.lit_mesh, "city": city, "smooth_mesh": smooth_mesh}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("scene", choices=sorted(SCENES))
    ap.add_argument("build", choices=("fixed", "float", "double"))
    ap.add_argument("frames", type=int)
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--time", action="store_true")
    ap.add_argument("--debug", type=int, default=0)
    ap.add_argument("--save")
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.split("x"))
    ctx = gles.Context(w, h, numeric=args.build, depth=16)
    ctx.range_check = "off"
    ctx.debug(args.debug)
    ctx.make_current()
    frame = SCENES[args.scene](ctx.gl, w, h)
    times = []
    for _ in range(args.frames):
        t0 = time.perf_counter()
        frame()
        ctx.gl.glFinish()
        times.append(time.perf_counter() - t0)
    if args.time and times:
        print(f"{args.scene} {args.build}: median {1000 * statistics.median(times):.2f} ms/frame")
    if args.save:
        np.save(args.save, ctx.image())


if __name__ == "__main__":
    main()
