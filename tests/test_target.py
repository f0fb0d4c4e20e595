"""The no-FPU target (gles.target): the trace replayer cross-built for ARMv5TE
soft-float and run under unicorn, counting instructions.

The counts must be exact and repeatable: two runs agree, and three ways of
counting agree (the block hook in C, the same hook in Python, and a hook on
every single instruction, which does not rely on a block's size). The target
program's image must be the host's: the fixed build is integer arithmetic,
and soft-float is IEEE arithmetic like the host's SSE, with the same flags
(-ffp-contract=off). Skipped, with the reason, where the cross compiler or
unicorn is missing; the "n/a" path is tested everywhere.
"""

from __future__ import annotations

import sys
from typing import Any

import pytest
from test_trace import buffers_scene  # tests/ is on sys.path (pytest's rootdir-relative import)

import gles
from gles import target
from gles import trace as T
from gles.gallery import GALLERY

needs_target = pytest.mark.skipif(not target.target_available(), reason=str(target.target_missing()))


@needs_target
@pytest.mark.parametrize("build", target.BUILDS)
def test_counts_repeat_exactly(build: str) -> None:
    t = gles.trace(GALLERY["alpha_sprites"][1], 32, 24, numeric=build)
    first = target.run_trace(t.data, build)
    second = target.run_trace(t.data, build)
    assert first.frame_instructions == second.frame_instructions > 0
    assert first.total_instructions == second.total_instructions
    # the trace holds setup, a warm-up frame and the counted frame
    assert first.total_instructions > 2 * first.frame_instructions * 0.9


@needs_target
@pytest.mark.parametrize("build", target.BUILDS)
def test_three_counters_agree(build: str) -> None:
    t = gles.trace(buffers_scene, 16, 12, numeric=build)
    runs = [target.run_trace(t.data, build, counter) for counter in ("c", "python", "instruction")]
    assert len({r.frame_instructions for r in runs}) == 1, [r.frame_instructions for r in runs]
    assert len({r.total_instructions for r in runs}) == 1


@needs_target
@pytest.mark.parametrize("build", target.BUILDS)
@pytest.mark.parametrize("name", ["lit_mesh", "dot3_bump", "stencil_reflection"])
def test_target_image_is_the_hosts(name: str, build: str) -> None:
    t = gles.trace(GALLERY[name][1], 32, 24, numeric=build)
    run = target.run_trace(t.data, build)
    assert run.exit_code == 0
    assert run.color_buffer == t.color_buffer


@needs_target
def test_target_cost_is_the_frame_count() -> None:
    scene = GALLERY["alpha_sprites"][1]
    cost = target.target_cost(scene, "fixed", (32, 24))
    run = target.run_trace(gles.trace(scene, 32, 24, numeric="fixed").data, "fixed")
    assert cost == run.frame_instructions
    with pytest.raises(ValueError, match="build"):
        target.target_cost(scene, "double", (32, 24))


@needs_target
def test_bad_trace_on_the_target() -> None:
    t = gles.trace(buffers_scene, 16, 12)
    with pytest.raises(target.TargetError, match="truncated"):
        target.run_trace(t.data[:-5], "fixed")


def test_missing_toolchain_says_what_to_install(monkeypatch: Any, tmp_path: Any) -> None:
    monkeypatch.setattr(target, "_PACKAGE", tmp_path)
    monkeypatch.setattr(target, "_COUNTER_LIB", tmp_path / "none.so")
    why = target.target_missing()
    assert why is not None and why.startswith("n/a") and target.APT_COMMAND in why
    assert not target.target_available()
    with pytest.raises(target.TargetUnavailable, match="gcc-arm-linux-gnueabi"):
        target.target_cost(GALLERY["lit_mesh"][1], "fixed", (8, 8))
    monkeypatch.setitem(sys.modules, "unicorn", None)      # import unicorn fails
    assert target.PIP_COMMAND in str(target.target_missing())


def test_target_can_be_turned_off(monkeypatch: Any) -> None:
    monkeypatch.setenv("GLES_TARGET", "off")
    assert not target.target_available()
    assert "GLES_TARGET=off" in str(target.target_missing())
    md, _ = target.report_section([(_Entry(), _Comparison())], 40, 30)
    assert "n/a" in md


def _target_build_module() -> Any:
    """src/_gles_build/target_build.py, a build helper no install carries: loaded from the tree."""
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parent.parent / "src" / "_gles_build" / "target_build.py"
    spec = importlib.util.spec_from_file_location("_target_build_under_test", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_a_build_without_the_cross_compiler_removes_stale_replayers(monkeypatch: Any, tmp_path: Any) -> None:
    # a replayer older than the core's sources would count another core's
    # instructions (or fail on a changed trace format): the target must read n/a
    tb = _target_build_module()
    monkeypatch.setenv("GLES_TARGET_CC", "none")
    out = tmp_path / "target"
    out.mkdir()
    for numeric in tb.BUILDS:
        (out / tb.exe_name(numeric)).write_bytes(b"old")
        (out / (tb.exe_name(numeric) + ".flags")).write_text("old")
    import os
    for f in out.iterdir():
        os.utime(f, (0, 0))                                  # older than every source
    assert tb.build(tmp_path) == []
    assert sorted(p.name for p in out.iterdir()) == []
    # one newer than the sources stays (a build made from these sources)
    fresh = out / tb.exe_name("fixed")
    fresh.write_bytes(b"new")
    assert tb.build(tmp_path) == [] and fresh.exists()


def test_trace_module_needs_no_target() -> None:
    # recording and host replay do not depend on the target toolchain
    t = gles.trace(buffers_scene, 8, 8)
    assert T.replay(t, raw=True) == t.color_buffer


@needs_target
def test_profile_adds_up_to_the_count() -> None:
    t = gles.trace(buffers_scene, 16, 12, numeric="float")
    per_function = target.profile_trace(t.data, "float")
    assert sum(per_function.values()) == target.run_trace(t.data, "float").total_instructions
    # the float build's arithmetic is the soft-float library's
    assert any(name.startswith(("__aeabi_f", "__addsf3", "__mulsf3")) for name in per_function)


class _Render:
    def __init__(self, ms: float) -> None:
        self.times_ms = [ms]
        self.time_ms = ms


class _Comparison:
    def __init__(self) -> None:
        self.renders = {"fixed": _Render(1.5), "float": _Render(0.5)}


class _Entry:
    name = "alpha_sprites"
    scene = staticmethod(GALLERY["alpha_sprites"][1])


def test_report_section_without_the_target(monkeypatch: Any, tmp_path: Any) -> None:
    monkeypatch.setattr(target, "_COUNTER_LIB", tmp_path / "none.so")
    md, page = target.report_section([(_Entry(), _Comparison())], 40, 30)
    assert "## Target cost" in md and "n/a" in md and target.APT_COMMAND in md
    assert "n/a" in page and target.APT_COMMAND in page


@needs_target
def test_report_section_with_the_target() -> None:
    md, page = target.report_section([(_Entry(), _Comparison())], 40, 30)
    fixed = target.target_cost(_Entry.scene, "fixed", (40, 30))
    flt = target.target_cost(_Entry.scene, "float", (40, 30))
    row = f"| alpha_sprites | 1.50 | 0.50 | {fixed:,} | {flt:,} | {fixed / flt:.2f} |"
    assert row in md.splitlines()
    assert "host ms fixed" in md and "host ms fixed" in page and f"{fixed:,}" in page
    assert target.report_size(256, 256) == (96, 72)
