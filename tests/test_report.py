"""python -m gles report, end to end at a small size (the README's main command)."""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest

from gles import mesa
from gles.gallery import GALLERY
from gles.hardcases import HARD_CASES
from gles.report import entries, speed_error_svg


def test_entries_cover_the_gallery_and_the_hard_cases() -> None:
    names = [e.name for e in entries()]
    assert names == list(GALLERY) + list(HARD_CASES)
    first = names[0]
    assert [e.name for e in entries([first])] == [first]
    with pytest.raises(ValueError, match="unknown scenes"):
        entries(["no_such_scene"])


def test_report_end_to_end(tmp_path: Path) -> None:
    peers = [p for p in ("mesa-llvmpipe", "mesa-softpipe") if mesa.available(p[5:]) is None]
    out = tmp_path / "report"
    cmd = [sys.executable, "-m", "gles", "report", "--out", str(out), "--size", "40x32", "--runs", "1",
           "--peers", ",".join(peers)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr
    # the progress bar reached the end (a line per step when stderr is not a terminal)
    total = len(entries()) * (3 + len(peers))
    assert f"{total}/{total}" in proc.stderr
    page = (out / "report.html").read_text()
    md = (out / "report.md").read_text()
    svg = (out / "speed_vs_psnr.svg").read_text()
    renderers = ["fixed", "float", "double", *peers]
    for e in entries():
        assert f"id='{e.name}'" in page
        assert re.search(rf"^### \d+\. {e.name}:", md, re.M)
        for r in renderers:
            png = out / "img" / f"{e.name}_{r}.png"
            assert png.read_bytes().startswith(b"\x89PNG"), png
            assert (out / "img" / f"{e.name}_{r}_diff.png").exists()
            assert f"img/{e.name}_{r}.png" in page and f"img/{e.name}_{r}.png" in md
    # the host panel: one point per renderer and scene, each with a hover title naming it
    host_tips = re.findall(r"<title>\d+ (\w+) on ([\w-]+): [\d.]+ ms on this host", svg)
    assert sorted(host_tips) == sorted((e.name, r) for e in entries() for r in renderers)
    # a line joins each scene's builds in the host panel (and in the target panel when it ran)
    data = json.loads((out / "report.json").read_text())
    target_ran = data["target"]["available"]
    assert svg.count("<polyline") == len(entries()) * (2 if target_ran else 1)
    for i, e in enumerate(entries(), 1):
        assert f"{i:>2}  {e.name}</text>" in svg                    # the legend
    if target_ran:
        assert len(re.findall(r"target instructions per frame, ", svg)) == 2 * len(entries())
    # the summary table: a row per scene with host ms and PSNR per renderer, target counts, verdict
    header = next(line for line in md.splitlines() if line.startswith("| # | scene |"))
    assert "fixed: host ms, PSNR" in header and "target fixed (instr/frame)" in header
    assert header.endswith("| range events | verdict |")
    rows = [line for line in md.splitlines() if re.match(r"\| \d+ \| \w+ \| .* ms, ", line)]
    assert len(rows) == len(entries())
    assert all(row.endswith("| not gated |") for row in rows)
    # host timings are called so; the colour bar comes before the first scene's heatmaps
    assert "Times are host timings" in md and "Times are host timings" in page
    assert page.index("heatmap: largest channel difference") < page.index("_diff.png")
    assert "colorbar.svg" in md and (out / "colorbar.svg").read_text().startswith("<svg")
    # report.json has every scene and renderer, with the same PSNRs the summary shows
    assert [s["name"] for s in data["scenes"]] == [e.name for e in entries()]
    for s, row in zip(data["scenes"], rows):
        for r in renderers:
            m = s["renders"][r]["metrics"]
            shown = "identical" if m["identical"] else f"{m['psnr_db']:.1f} dB"
            assert f"{s['renders'][r]['host_ms_per_frame']:.2f} ms, {shown}" in row
    # the double build is the reference: identical to itself
    assert "identical" in md


def test_svg_places_points_by_time_and_psnr() -> None:
    from gles.compare import Comparison, Metrics, Render
    from gles.report import Entry

    def comp(ms: float, psnr: float) -> Comparison:
        r = Render("fixed", None, times_ms=[ms], metrics=Metrics(1, 0.1, 0.2, psnr, 0.0))
        d = Render("double", None, times_ms=[ms * 2], metrics=Metrics(0, 0, 0, math.inf, 0.0))
        return Comparison("s", 4, 4, "double", {"fixed": r, "double": d})

    e = Entry("a", "A", "Techniques", lambda gl, w, h: None)
    svg = speed_error_svg([(e, comp(1.0, 30.0)), (e, comp(10.0, 50.0))])
    pts = [(float(x), float(y)) for x, y in re.findall(r'<circle cx="([\d.]+)" cy="([\d.]+)" r="4"', svg)]
    assert len(pts) == 4
    (x1, y1), _, (x2, y2), _ = pts
    assert x2 > x1 and y2 < y1          # slower to the right, higher PSNR further up
    assert "identical" in svg
