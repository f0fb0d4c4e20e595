"""Threaded rasterization (``gles.Context(threads=N)``): the bytes of every
image are those of one thread.

Each thread rasterizes every primitive of a draw on its own bands of 16 rows,
in submission order, so no pixel sees its fragments in another order; the
draw's vertex work is shared in slices of vertices. The reference here is
``threads=1`` on the same build. The debug switch 64 makes every draw
threaded, also the small ones a context keeps on its calling thread, so that
the small images of these tests take the threaded path; the
images are tall enough (at least 64 rows, four bands or more) that each
thread owns several bands and primitives cross band edges.
"""

from __future__ import annotations

import gc
import os
import signal
import threading
from typing import Any, Callable

import numpy as np
import pytest

import gles
from gles import constants as C
from gles.gallery import GALLERY
from gles.hardcases import HARD_CASES

THREADS_ALWAYS = 64          # gles_debug_set: threaded draws however small
COUNTS = (2, 3)


def _render(scene: Callable[..., Any], threads: int, numeric: str = "fixed", size: tuple[int, int] = (80, 72),
            always: bool = True, frames: int = 1, **kw: Any) -> np.ndarray:
    ctx = gles.Context(size[0], size[1], numeric=numeric, range_check="off", threads=threads)
    if always:
        ctx.debug(THREADS_ALWAYS)
    frame = scene(ctx.gl, size[0], size[1], **kw)
    for _ in range(frames):
        frame()
    assert int(ctx.gl.glGetError()) == 0
    return ctx.image()


def _assert_same(scene: Callable[..., Any], **kw: Any) -> None:
    one = _render(scene, 1, **kw)
    for n in COUNTS:
        many = _render(scene, n, **kw)
        differ = int(np.sum(np.any(one != many, axis=2)))
        assert differ == 0, f"threads={n}: {differ} pixels differ"


def test_threads_option() -> None:
    ctx = gles.Context(8, 8, threads=3)
    assert ctx.threads == 3
    ctx.threads = 1
    assert ctx.threads == 1
    ctx.threads = 2
    assert ctx.threads == 2
    assert gles.Context(8, 8).threads == gles.context.default_threads()
    for bad, exc in ((0, ValueError), (gles.context.MAX_THREADS + 1, ValueError), (-1, ValueError),
                     (True, TypeError), ("2", TypeError), (2.0, TypeError)):
        with pytest.raises(exc, match="threads"):
            gles.Context(8, 8, threads=bad)
        with pytest.raises(exc, match="threads"):
            ctx.threads = bad
        assert ctx.threads == 2


@pytest.mark.parametrize("numeric", ["fixed", "double"])
@pytest.mark.parametrize("name", list(GALLERY))
def test_gallery(name: str, numeric: str) -> None:
    _assert_same(lambda gl, w, h: GALLERY[name][1](gl, w, h), numeric=numeric, frames=2)


@pytest.mark.parametrize("name", list(HARD_CASES))
def test_hard_cases(name: str) -> None:
    _assert_same(HARD_CASES[name].scene)


def test_large_draws_without_the_switch() -> None:
    """Draws over the size threshold are threaded on their own."""
    _assert_same(lambda gl, w, h: GALLERY["ground_plane"][1](gl, w, h), size=(256, 200), always=False)


# {====================================================================
# a randomized sweep of state: each case one draw of many primitives

KINDS = ("triangles", "strip", "lines", "points")


def _random_scene(seed: int) -> Callable[..., Any]:
    def scene(gl: Any, w: int, h: int) -> Callable[[], None]:
        rng = np.random.default_rng(seed)
        gl.glViewport(0, 0, w, h)
        gl.glMatrixMode(C.GL_PROJECTION)
        gl.glLoadIdentity()
        gl.glFrustumf(-1, 1, -1, 1, 1, 10) if rng.random() < 0.5 else gl.glOrthof(-1, 1, -1, 1, -10, 10)
        gl.glMatrixMode(C.GL_MODELVIEW)
        gl.glLoadIdentity()
        gl.glTranslatef(0, 0, -3)
        gl.glClearColor(*rng.random(3), 1.0)
        gl.glClearStencil(int(rng.integers(0, 4)))
        kind = KINDS[int(rng.integers(0, len(KINDS)))]
        n = int(rng.integers(30, 120))
        nv = {"triangles": 3 * n, "strip": n + 2, "lines": 2 * n, "points": n}[kind]
        xy, z = rng.uniform(-1.6, 1.6, (nv, 2)), rng.uniform(-1.5, 1.5, (nv, 1))
        verts = np.ascontiguousarray(np.concatenate([xy, z], axis=1), dtype=np.float32)
        colors = np.ascontiguousarray(rng.integers(0, 256, (nv, 4)), dtype=np.uint8)
        tcs = np.ascontiguousarray(rng.uniform(-2, 3, (nv, 2)), dtype=np.float32)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, verts)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, colors)
        gl.glShadeModel(C.GL_SMOOTH if rng.random() < 0.7 else C.GL_FLAT)
        if rng.random() < 0.6:
            size = int(rng.choice([4, 16, 64]))
            tex = np.ascontiguousarray(rng.integers(0, 256, (size, size, 4)), dtype=np.uint8)
            gl.glBindTexture(C.GL_TEXTURE_2D, gl.glGenTextures(1))
            mip = rng.random() < 0.5
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, int(mip))
            gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, size, size, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, tex)
            mins = [C.GL_NEAREST, C.GL_LINEAR] + ([C.GL_LINEAR_MIPMAP_LINEAR] if mip else [])
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, int(rng.choice(mins)))
            mag = int(rng.choice([C.GL_NEAREST, C.GL_LINEAR]))
            gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, mag)
            gl.glEnable(C.GL_TEXTURE_2D)
            gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE,
                         int(rng.choice([C.GL_MODULATE, C.GL_REPLACE, C.GL_DECAL, C.GL_BLEND, C.GL_ADD])))
            gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
            gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tcs)
        if rng.random() < 0.5:
            gl.glEnable(C.GL_BLEND)
            dst = int(rng.choice([C.GL_ONE_MINUS_SRC_ALPHA, C.GL_ONE, C.GL_SRC_COLOR]))
            gl.glBlendFunc(C.GL_SRC_ALPHA, dst)
        if rng.random() < 0.4:
            gl.glEnable(C.GL_DEPTH_TEST)
            gl.glDepthFunc(int(rng.choice([C.GL_LESS, C.GL_LEQUAL, C.GL_GREATER, C.GL_ALWAYS])))
        if rng.random() < 0.3:
            gl.glEnable(C.GL_STENCIL_TEST)
            func = int(rng.choice([C.GL_ALWAYS, C.GL_EQUAL, C.GL_LESS]))
            gl.glStencilFunc(func, int(rng.integers(0, 4)), 0xFF)
            gl.glStencilOp(C.GL_KEEP, C.GL_INCR, int(rng.choice([C.GL_INCR, C.GL_INVERT, C.GL_REPLACE])))
        if rng.random() < 0.3:
            gl.glEnable(C.GL_ALPHA_TEST)
            gl.glAlphaFunc(C.GL_GREATER, float(rng.random()))
        if rng.random() < 0.3:
            gl.glEnable(C.GL_FOG)
            gl.glFogf(C.GL_FOG_MODE, C.GL_EXP)
            gl.glFogf(C.GL_FOG_DENSITY, 0.3)
        if rng.random() < 0.2:
            gl.glEnable(C.GL_COLOR_LOGIC_OP)
            gl.glLogicOp(C.GL_XOR)
        if rng.random() < 0.3:
            gl.glEnable(C.GL_SCISSOR_TEST)
            gl.glScissor(int(rng.integers(0, w // 2)), int(rng.integers(0, h // 2)), w // 2 + 7, h // 2 + 5)
        if kind == "points":
            gl.glPointSize(float(rng.choice([1.0, 3.0, 9.5])))
            if rng.random() < 0.5:
                gl.glEnable(C.GL_POINT_SMOOTH)
        if kind == "lines":
            gl.glLineWidth(float(rng.choice([1.0, 2.0, 5.0])))
            if rng.random() < 0.5:
                gl.glEnable(C.GL_LINE_SMOOTH)
        mode = {"triangles": C.GL_TRIANGLES, "strip": C.GL_TRIANGLE_STRIP, "lines": C.GL_LINES,
                "points": C.GL_POINTS}[kind]

        def frame() -> None:
            gl.glClear(C.GL_COLOR_BUFFER_BIT | C.GL_DEPTH_BUFFER_BIT | C.GL_STENCIL_BUFFER_BIT)
            gl.glDrawArrays(mode, 0, nv)
            gl.glDrawArrays(mode, 0, nv)       # over itself: depth, stencil and blend see the first

        return frame
    return scene


@pytest.mark.parametrize("seed", range(40))
def test_random_state(seed: int) -> None:
    _assert_same(_random_scene(seed), size=(64, 96))


def test_contexts_in_python_threads() -> None:
    """Contexts drawing at once from several Python threads share the worker
    threads (one draws threaded while the others wait their turn or draw
    alone), and each gets its own picture."""
    scene = lambda gl, w, h: GALLERY["lit_mesh"][1](gl, w, h)  # noqa: E731
    expect = _render(scene, 1, size=(96, 80))
    out: list[np.ndarray] = [np.empty(0)] * 4
    errors: list[BaseException] = []

    def work(i: int) -> None:
        try:
            out[i] = _render(scene, 2 + i % 2, size=(96, 80), frames=3)
        except BaseException as e:     # reported below, not lost in the thread
            errors.append(e)

    ts = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    assert not errors
    for img in out:
        assert np.array_equal(img, expect)


def _drawtex_scene(gl: Any, w: int, h: int) -> Callable[[], None]:
    """Overlapping DrawTex rectangles with blending, two units, one cropped
    and minified with mipmaps, at fractional positions."""
    rng = np.random.default_rng(3)
    for unit in (0, 1):
        gl.glActiveTexture(C.GL_TEXTURE0 + unit)
        gl.glBindTexture(C.GL_TEXTURE_2D, gl.glGenTextures(1))
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
        img = np.ascontiguousarray(rng.integers(0, 256, (32, 32, 4)), dtype=np.uint8)
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 32, 32, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
        crop = [2, 3, 27, 25] if unit else [0, 0, 32, 32]
        gl.glTexParameteriv(C.GL_TEXTURE_2D, C.GL_TEXTURE_CROP_RECT_OES, crop)
        gl.glEnable(C.GL_TEXTURE_2D)
        gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE if unit else C.GL_REPLACE)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    rects = rng.uniform([-10, -10, 5, 5], [w, h, w, h], (12, 4))

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        for x, y, rw, rh in rects:
            gl.glColor4f(*rng.random(4))
            gl.glDrawTexfOES(float(x), float(y), 0.5, float(rw), float(rh))
    return frame


def test_drawtex() -> None:
    _assert_same(_drawtex_scene, size=(72, 96))


# {====================================================================
# a threaded draw's workers may still run when the command returns: every
# command that changes what they read, or reads what they write, waits first

def _between_draws_scene(gl: Any, w: int, h: int) -> Callable[[], None]:
    """Draws of a textured quad, each followed by a command that changes the
    texture the draw samples, reads the framebuffer it writes, or renders
    into another target: a missing wait shows as other bytes or a race."""
    rng = np.random.default_rng(11)
    gl.glViewport(0, 0, w, h)
    gl.glEnableClientState(C.GL_VERTEX_ARRAY)
    gl.glEnableClientState(C.GL_TEXTURE_COORD_ARRAY)
    quad = np.array([[-1, -1], [1, -1], [-1, 1], [1, 1]], dtype=np.float32)
    gl.glVertexPointer(2, C.GL_FLOAT, 0, quad)
    tex = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, tex)
    img = np.ascontiguousarray(rng.integers(0, 256, (32, 32, 4)), dtype=np.uint8)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 32, 32, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, img)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_LINEAR)
    gl.glEnable(C.GL_TEXTURE_2D)
    gl.glTexEnvi(C.GL_TEXTURE_ENV, C.GL_TEXTURE_ENV_MODE, C.GL_MODULATE)
    gl.glEnable(C.GL_BLEND)
    gl.glBlendFunc(C.GL_SRC_ALPHA, C.GL_ONE_MINUS_SRC_ALPHA)
    # a texture the frame renders into through a framebuffer object
    target = gl.glGenTextures(1)
    gl.glBindTexture(C.GL_TEXTURE_2D, target)
    gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 64, 64, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE, None)
    gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_NEAREST)
    fbo = gl.glGenFramebuffersOES(1)
    gl.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, fbo)
    gl.glFramebufferTexture2DOES(C.GL_FRAMEBUFFER_OES, C.GL_COLOR_ATTACHMENT0_OES, C.GL_TEXTURE_2D, target, 0)
    gl.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, 0)
    state = {"tex": tex}

    def draw(shift: float) -> None:
        tc = np.ascontiguousarray(quad * (0.8 + shift) + shift, dtype=np.float32)
        state["tc"] = tc                         # alive until the next draw has read it
        gl.glTexCoordPointer(2, C.GL_FLOAT, 0, tc)
        gl.glColor4f(*rng.uniform(0.3, 1.0, 4))
        gl.glDrawArrays(C.GL_TRIANGLE_STRIP, 0, 4)

    def frame() -> None:
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glBindTexture(C.GL_TEXTURE_2D, state["tex"])
        draw(0.1)
        patch = np.ascontiguousarray(rng.integers(0, 256, (8, 16, 4)), dtype=np.uint8)
        gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 4, 5, 16, 8, C.GL_RGBA, C.GL_UNSIGNED_BYTE, patch)
        draw(0.2)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MAG_FILTER, C.GL_NEAREST)
        draw(0.3)
        gl.glCopyTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 3, 7, 24, 20)
        draw(0.4)
        read = np.asarray(gl.glReadPixels(5, 9, 16, 16, C.GL_RGBA, C.GL_UNSIGNED_BYTE), dtype=np.uint8)
        gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 16, 16, 16, 16, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                           np.ascontiguousarray(read.reshape(16, 16, 4)))
        draw(0.5)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_GENERATE_MIPMAP, 1)
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR_MIPMAP_LINEAR)
        gl.glTexSubImage2D(C.GL_TEXTURE_2D, 0, 0, 0, 8, 8, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                           np.ascontiguousarray(rng.integers(0, 256, (8, 8, 4)), dtype=np.uint8))
        draw(0.6)
        # the texture deleted right after a draw that samples it
        gl.glDeleteTextures([state["tex"]])
        state["tex"] = gl.glGenTextures(1)
        gl.glBindTexture(C.GL_TEXTURE_2D, state["tex"])
        gl.glTexImage2D(C.GL_TEXTURE_2D, 0, C.GL_RGBA, 32, 32, 0, C.GL_RGBA, C.GL_UNSIGNED_BYTE,
                        np.ascontiguousarray(rng.integers(0, 256, (32, 32, 4)), dtype=np.uint8))
        gl.glTexParameteri(C.GL_TEXTURE_2D, C.GL_TEXTURE_MIN_FILTER, C.GL_LINEAR)
        draw(0.7)
        # into the framebuffer object's texture, then sampling it in the window
        gl.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, fbo)
        gl.glViewport(0, 0, 64, 64)
        draw(0.8)
        gl.glBindFramebufferOES(C.GL_FRAMEBUFFER_OES, 0)
        gl.glViewport(0, 0, w, h)
        gl.glBindTexture(C.GL_TEXTURE_2D, target)
        draw(0.9)
        gl.glDrawTexiOES(3, 4, 0, 40, 50)
        gl.glBindTexture(C.GL_TEXTURE_2D, state["tex"])
        draw(1.0)
    return frame


@pytest.mark.parametrize("numeric", ["fixed", "float"])
def test_commands_between_draws(numeric: str) -> None:
    _assert_same(_between_draws_scene, size=(72, 96), numeric=numeric, frames=2)


def test_wait_in_another_python_thread() -> None:
    """The draw's workers are waited for by whichever thread next uses the
    context: the image read from another Python thread, then more draws from
    this one, and a change of thread count between draws."""
    scene = lambda gl, w, h: GALLERY["ground_plane"][1](gl, w, h)  # noqa: E731
    expect = _render(scene, 1, frames=2)
    ctx = gles.Context(80, 72, range_check="off", threads=2)
    ctx.debug(THREADS_ALWAYS)
    frame = scene(ctx.gl, 80, 72)
    frame()
    seen: list[np.ndarray] = []
    t = threading.Thread(target=lambda: seen.append(ctx.image()))
    t.start()
    t.join()
    assert np.array_equal(seen[0], _render(scene, 1, frames=1))
    ctx.threads = 3
    frame()
    assert np.array_equal(ctx.image(), expect)
    frame()
    ctx.threads = 1
    frame()
    assert np.array_equal(ctx.image(), _render(scene, 1, frames=4))


def test_freed_with_draws_running() -> None:
    """A context freed (and another made) right after a threaded draw."""
    for _ in range(5):
        ctx = gles.Context(96, 96, range_check="off", threads=2)
        ctx.debug(THREADS_ALWAYS)
        GALLERY["ground_plane"][1](ctx.gl, 96, 96)()
        del ctx
        gc.collect()


def test_mesa_threads() -> None:
    """The Mesa runners take the same option (llvmpipe's LP_NUM_THREADS)."""
    from gles import mesa

    why = mesa.available("llvmpipe")
    if why is not None:
        pytest.skip(why)
    scene = lambda gl, w, h: GALLERY["dot3_bump"][1](gl, w, h)  # noqa: E731
    images = []
    for threads in (1, 2):
        try:
            ctx = mesa.MesaContext(64, 64, driver="llvmpipe", threads=threads)
        except RuntimeError as e:      # both of Mesa's displays held by other contexts
            if "every display is in use" not in str(e):
                raise
            pytest.skip(str(e))
        with ctx:
            assert ctx.threads == threads
            scene(ctx.gl, 64, 64)()
            images.append(ctx.image())
    assert np.array_equal(images[0], images[1])
    with pytest.raises(ValueError, match="threads"):
        mesa.MesaContext(8, 8, threads=-1)
    with pytest.raises(TypeError, match="threads"):
        mesa.MesaContext(8, 8, threads=1.5)  # type: ignore[arg-type]


@pytest.mark.skipif(not hasattr(os, "fork"), reason="no fork()")
def test_fork_child_renders() -> None:
    """A child of fork() has none of the pool's workers: its contexts, the
    inherited one included, render alone, and a new one starts workers."""
    scene = lambda gl, w, h: GALLERY["ground_plane"][1](gl, w, h)  # noqa: E731
    expect = _render(scene, 1)
    ctx = gles.Context(80, 72, range_check="off", threads=2)
    ctx.debug(THREADS_ALWAYS)
    frame = scene(ctx.gl, 80, 72)
    frame()                                     # the pool's workers are running
    pid = os.fork()
    if pid == 0:                                # the child: no pytest from here on
        code = 1
        try:
            signal.alarm(60)                    # a deadlock ends the child
            frame()
            same = np.array_equal(ctx.image(), expect)
            same = same and np.array_equal(_render(scene, 2), expect)
            code = 0 if same else 2
        finally:
            os._exit(code)
    _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    assert np.array_equal(ctx.image(), expect)
