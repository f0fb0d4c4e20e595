"""Render a smooth-shaded triangle over a depth-tested wave mesh, in 16.16
fixed point, and write it to first_triangle.png.

    python examples/first_triangle.py [out.png]
"""

from __future__ import annotations

import sys

import numpy as np

import gles
from gles import gl


def wave_mesh(n: int = 40) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """An (n+1)^2 grid in [-1,1]^2 with a sine height, per-vertex colours and
    triangle indices."""
    xs = np.linspace(-1.0, 1.0, n + 1)
    x, y = np.meshgrid(xs, xs)
    z = 0.15 * np.sin(4 * x) * np.cos(4 * y)
    verts = np.stack([x, y, z], -1).reshape(-1, 3).astype(np.float32)
    colors = np.empty((len(verts), 4), dtype=np.uint8)
    colors[:, 0] = (verts[:, 0] * 0.5 + 0.5) * 255
    colors[:, 1] = (verts[:, 2] / 0.3 + 0.5) * 255
    colors[:, 2] = (verts[:, 1] * 0.5 + 0.5) * 255
    colors[:, 3] = 255
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    a = (j * (n + 1) + i).ravel()
    quads = np.stack([a, a + 1, a + n + 2, a, a + n + 2, a + n + 1], -1)
    return verts, colors, quads.astype(np.uint16).ravel()


def main(path: str = "first_triangle.png") -> None:
    ctx = gles.Context(320, 240, numeric="fixed")
    ctx.make_current()

    gl.glClearColor(0.08, 0.08, 0.12, 1.0)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT | gl.GL_DEPTH_BUFFER_BIT)
    gl.glEnable(gl.GL_DEPTH_TEST)

    gl.glMatrixMode(gl.GL_PROJECTION)
    gl.glFrustumf(-0.4, 0.4, -0.3, 0.3, 1.0, 10.0)
    gl.glMatrixMode(gl.GL_MODELVIEW)
    gl.glTranslatef(0.0, -0.2, -3.0)
    gl.glRotatef(-60.0, 1.0, 0.0, 0.0)

    verts, colors, indices = wave_mesh()
    gl.glEnableClientState(gl.GL_VERTEX_ARRAY)
    gl.glEnableClientState(gl.GL_COLOR_ARRAY)
    gl.glVertexPointer(3, gl.GL_FLOAT, 0, verts)
    gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, colors)
    gl.glDrawElements(gl.GL_TRIANGLES, len(indices), gl.GL_UNSIGNED_SHORT, indices)

    # a triangle standing in the mesh, given in 16.16 fixed point
    gl.glLoadIdentity()
    gl.glTranslatef(0.0, 0.0, -3.0)
    one = 65536
    tri = np.array([-one // 2, -one // 4, 0, one // 2, -one // 4, 0, 0, one // 2, 0], dtype=np.int32)
    tri_colors = np.array([255, 60, 60, 255, 60, 255, 60, 255, 60, 60, 255, 255], dtype=np.uint8)
    gl.glVertexPointer(3, gl.GL_FIXED, 0, tri)
    gl.glColorPointer(4, gl.GL_UNSIGNED_BYTE, 0, tri_colors)
    gl.glDrawArrays(gl.GL_TRIANGLES, 0, 3)

    ctx.save(path)
    print(f"wrote {path} ({ctx.width}x{ctx.height}, {ctx.numeric} build)")


if __name__ == "__main__":
    main(*sys.argv[1:2])
