"""Scale-out: compare and report on worker processes and on any
concurrent.futures executor (dask.distributed when it is installed) give the
same images, errors and range counts as the serial run in this process.
Times are not compared: processes side by side compete for the cores."""

from __future__ import annotations

import concurrent.futures as cf
import json
import multiprocessing
from pathlib import Path

import numpy as np
import pytest

from gles import compare as cmp
from gles import mesa
from gles.__main__ import main
from gles.gallery import GALLERY
from gles.hardcases import HARD_CASES

SCENE_FILE = '''
import numpy as np
from gles import constants as C


def triangle(gl, w, h):
    """A smooth triangle under a perspective projection."""
    gl.glViewport(0, 0, w, h)
    gl.glMatrixMode(C.GL_PROJECTION)
    gl.glFrustumf(-1, 1, -1, 1, 1, 10)
    gl.glMatrixMode(C.GL_MODELVIEW)
    gl.glTranslatef(0.1, 0, -2.7)
    gl.glRotatef(17, 0.3, 0.2, 1)
    v = np.array([-1, -1, 0, 1, -1, 0.5, 0, 1, -0.5], np.float32)
    c = np.array([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255], np.uint8)

    def frame():
        gl.glClear(C.GL_COLOR_BUFFER_BIT)
        gl.glEnableClientState(C.GL_VERTEX_ARRAY)
        gl.glEnableClientState(C.GL_COLOR_ARRAY)
        gl.glVertexPointer(3, C.GL_FLOAT, 0, v)
        gl.glColorPointer(4, C.GL_UNSIGNED_BYTE, 0, c)
        gl.glDrawArrays(C.GL_TRIANGLES, 0, 3)
    return frame


def fails_on_float(gl, w, h):
    if b"(float)" in gl.glGetString(C.GL_RENDERER):
        raise RuntimeError("this scene does not run on float")
    gl.glClear(C.GL_COLOR_BUFFER_BIT)
'''

PEERS = tuple(p for p in ("mesa-llvmpipe",) if mesa.available(p[5:]) is None)


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("scenes") / "scenes.py"
    path.write_text(SCENE_FILE)
    return path


def scenes(scene_file: Path) -> list:
    """A gallery scene, a hard case with range events, and two scenes from a
    file (one of which fails on a build): each kind a worker must load."""
    return [GALLERY["lit_mesh"][1], HARD_CASES["rule_breaking_matrices"].scene,
            HARD_CASES["near_far_extreme"].scene,
            cmp.load_scene(scene_file, "triangle"), cmp.load_scene(scene_file, "fails_on_float")]


def run(scene_file: Path, **how) -> list[cmp.Comparison]:
    return cmp.compare_scenes(scenes(scene_file), 48, 40, peers=PEERS, runs=2, **how)


def assert_same(a: list[cmp.Comparison], b: list[cmp.Comparison]) -> None:
    """Everything but the times."""
    assert [c.scene for c in a] == [c.scene for c in b]
    for ca, cb in zip(a, b):
        assert list(ca.renders) == list(cb.renders)
        for name, ra in ca.renders.items():
            rb = cb.renders[name]
            assert (ra.error, ra.skipped, ra.gl_error) == (rb.error, rb.skipped, rb.gl_error), name
            assert len(ra.times_ms) == len(rb.times_ms)
            for x, y in ((ra.image, rb.image), (ra.heatmap, rb.heatmap)):
                assert (x is None and y is None) or np.array_equal(x, y), (ca.scene, name)
            assert ra.metrics == rb.metrics, (ca.scene, name)
            if ra.range is None:
                assert rb.range is None
            else:
                assert (ra.range.counts, ra.range.by_source, ra.range.draws_checked) == \
                       (rb.range.counts, rb.range.by_source, rb.range.draws_checked)


@pytest.fixture(scope="module")
def serial(scene_file: Path) -> list[cmp.Comparison]:
    res = run(scene_file)
    # the serial run itself: every renderer drew but float on the failing scene
    assert [list(c.failed) for c in res] == [[], [], [], [], ["float"]]
    assert res[1].renders["fixed"].range.counts["rule"] > 0          # rule_breaking_matrices
    assert res[2].renders["fixed"].range.counts["overflow"] == 1     # far = 1e5 in glFrustumf
    return res


def test_jobs_give_identical_results(scene_file: Path, serial: list[cmp.Comparison]) -> None:
    steps: list[tuple[int, str]] = []
    par = cmp.compare_scenes(scenes(scene_file), 48, 40, peers=PEERS, runs=2, jobs=2,
                             progress=lambda i, name: steps.append((i, name)))
    assert_same(serial, par)
    assert sorted(steps) == sorted((i, n) for i in range(5) for n in ("fixed", "float", "double", *PEERS))
    # the failure's traceback comes back from the worker
    tb = par[4].renders["float"].traceback
    assert "in fails_on_float" in tb and "RuntimeError: this scene does not run on float" in tb


def test_any_executor(scene_file: Path, serial: list[cmp.Comparison]) -> None:
    class Inline:
        """Just submit(), running the job at once: the duck type compare needs."""

        def submit(self, fn, *args):
            f: cf.Future = cf.Future()
            f.set_result(fn(*args))
            return f

    assert_same(serial, run(scene_file, executor=Inline()))
    with cf.ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as pool:
        assert_same(serial, run(scene_file, executor=pool))


def test_dask_distributed_executor(scene_file: Path, serial: list[cmp.Comparison]) -> None:
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        assert_same(serial, run(scene_file, executor=client.get_executor()))


def test_executor_and_jobs_misuse(scene_file: Path) -> None:
    def local(gl, w, h):        # a closure pickle cannot name
        gl.glClear(0x4000)

    with pytest.raises(TypeError, match="local.*does not pickle"):
        cmp.compare(local, 8, 8, peers=(), runs=1, jobs=2)
    with pytest.raises(ValueError, match="jobs must be at least 1"):
        cmp.compare(local, 8, 8, jobs=0)
    with pytest.raises(TypeError, match="jobs must be an int"):
        cmp.compare(local, 8, 8, jobs="2")
    with pytest.raises(TypeError, match="executor must have a submit"):
        cmp.compare(local, 8, 8, executor=object())
    with cf.ThreadPoolExecutor(1) as pool, pytest.raises(ValueError, match="not both"):
        cmp.compare(local, 8, 8, executor=pool, jobs=2)


def test_cli_jobs_identical_and_unknown_names(tmp_path: Path, scene_file: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    common = ["--size", "24x20", "--runs", "1", "--peers", ",".join(PEERS)]
    for jobs in ("1", "2"):
        assert main(["compare", str(scene_file), "--function", "triangle", *common, "--jobs", jobs,
                     "--out", str(tmp_path / f"c{jobs}")]) == 0
        assert main(["report", "--out", str(tmp_path / f"r{jobs}"), "--only",
                     "lit_mesh,rule_breaking_matrices", *common, "--jobs", jobs, "--quiet"]) == 0
    for kind in "cr":
        one = sorted(p.name for p in (tmp_path / f"{kind}1").rglob("*.png"))
        two = sorted(p.name for p in (tmp_path / f"{kind}2").rglob("*.png"))
        assert one == two and len(one) >= 2
        a, b = tmp_path / f"{kind}1", tmp_path / f"{kind}2"
        for p in a.rglob("*.png"):
            assert p.read_bytes() == (b / p.relative_to(a)).read_bytes(), p
    # the range events in the report's summary are the same (one frame's)
    counts = []
    for j in "12":
        data = json.loads((tmp_path / f"r{j}" / "report.json").read_text())
        scene = next(s for s in data["scenes"] if s["name"] == "rule_breaking_matrices")
        ev = scene["renders"]["fixed"]["range_events"]
        counts.append((ev["overflow"], ev["underflow"], ev["rule"]))
    assert counts[0] == counts[1] and counts[0][2] == 4
    capsys.readouterr()
    # unknown names are failures in worker processes too
    assert main(["compare", str(scene_file), "--function", "triangle", "--size", "8x8", "--runs", "1",
                 "--builds", "fixed,fixd", "--peers", "mesa-foo", "--jobs", "2"]) == 1
    err = capsys.readouterr().err
    assert "fixd failed: ValueError: unknown renderer 'fixd'" in err
    assert "mesa-foo failed: " in err
    with pytest.raises(SystemExit):
        main(["compare", str(scene_file), "--jobs", "0"])
