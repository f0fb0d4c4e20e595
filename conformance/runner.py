"""The runner: plan runs, execute them, report.

A run is one (test, backend, profile, visual, path level) on a fresh
context, so no state leaks from one run into the next. Its result is
pass, fail (a check failed, with its message), skip (with the reason) or
error (an exception the test did not expect). After a test returns, the
runner also requires ``glGetError() == 0``: a test that provokes an error
on purpose must read it.

Reports: a Markdown or JSON file with a summary table (test by backend),
the path states each backend could not apply, and every failure, error and
skip with its reason. ``main`` is ``python -m conformance``.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import platform
import sys
import time
import traceback
from collections import Counter, defaultdict
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, TextIO

from .backends import BACKENDS, PROFILES, BackendSpec
from .harness import VISUALS, ConformanceTest, Failure, TestContext, Unsupported, load_categories
from .paths import MAX_LEVEL, apply_path, parse_levels

STATUSES = ("pass", "fail", "error", "skip")
MAX_LISTED = 20   # failures printed on the terminal; the report lists all


@dataclass(frozen=True)
class Job:
    """One planned run."""

    test: ConformanceTest
    backend: BackendSpec
    profile: str
    visual: str
    path: int

    @property
    def id(self) -> str:
        return f"{self.test.name}-{self.backend.name}-{self.profile}-{self.visual}-p{self.path}"


@dataclass
class Result:
    """The outcome of one run."""

    test: str
    backend: str
    profile: str
    visual: str
    path: int
    status: str
    message: str = ""
    seconds: float = 0.0
    unapplied: dict[str, str] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    digest: str = ""          # hash of the final colour buffer of a passing run

    @property
    def group(self) -> tuple[str, str, str, str]:
        """The runs that differ only in path level."""
        return (self.test, self.backend, self.profile, self.visual)


class PathInvariance:
    """Fails a passing run whose final image differs from path level 0's.

    A path level must not change any result, and that includes the pixels a
    test leaves behind, not only its verdict. Level 0 has to run first (the
    planner puts the level innermost, so it does).
    """

    def __init__(self) -> None:
        self.base: dict[tuple[str, str, str, str], str] = {}

    def check(self, res: Result) -> Result:
        if res.status != "pass" or not res.digest:
            return res
        if res.path == 0:
            self.base[res.group] = res.digest
        elif res.group in self.base and self.base[res.group] != res.digest:
            res.status = "fail"
            res.message = (f"path level {res.path} changed the final image: it differs from the one "
                           "path level 0 left (the verdicts agree, the pixels do not)")
        return res


def select_tests(registry: dict[str, ConformanceTest], keywords: Sequence[str] = ()) -> list[ConformanceTest]:
    """The tests `keywords` select (all if none). A keyword selects the tests
    it names or whose category (the name before a dot) it names; failing
    that, the tests whose name contains it. Case-insensitive."""
    tests = sorted(registry.values(), key=lambda t: t.name.lower())
    if not keywords:
        return tests
    chosen: set[str] = set()
    for key in (k.lower() for k in keywords):
        exact = {t.name for t in tests if key in (t.name.lower(), t.name.split(".")[0].lower())}
        chosen |= exact or {t.name for t in tests if key in t.name.lower()}
    return [t for t in tests if t.name in chosen]


def plan(tests: Iterable[ConformanceTest], backends: Iterable[BackendSpec], profiles: Iterable[str],
         levels: Iterable[int], visuals: Iterable[str] | None = None) -> list[Job]:
    """Every run of `tests` on `backends`: each profile a test applies to, each
    of its visuals (restricted to `visuals` when given), each path level."""
    wanted = None if visuals is None else set(visuals)
    jobs = []
    levels = list(levels)
    profiles = list(profiles)
    backends = list(backends)
    for test in tests:
        for spec in backends:
            for profile in profiles:
                if profile not in test.profiles or profile not in spec.profiles:
                    continue
                for vis in test.visuals:
                    if wanted is not None and vis not in wanted:
                        continue
                    for level in levels:
                        jobs.append(Job(test, spec, profile, vis, level))
    return jobs


def _short_trace(exc: BaseException) -> str:
    lines = traceback.format_exception(type(exc), exc, exc.__traceback__)
    return "".join(lines[-4:]).strip()


def run_job(job: Job, *, debug_flags: int = 0) -> Result:
    """Run one job on a fresh context and return its result (never raises)."""
    test = job.test
    res = Result(job.test.name, job.backend.name, job.profile, job.visual, job.path, "pass")
    start = time.perf_counter()
    why = job.backend.available()
    if why is not None:
        res.status, res.message = "skip", why
        return res
    w, h = test.size
    try:
        backend = job.backend.make(job.profile, job.visual, width=w, height=h, debug_flags=debug_flags)
    except Unsupported as exc:
        res.status, res.message = "skip", f"unsupported: {exc}"
        return res
    except Exception as exc:
        res.status, res.message = "error", f"could not create the context: {type(exc).__name__}: {exc}"
        return res
    try:
        res.notes.extend(getattr(backend, "notes", []))
        report = apply_path(backend, job.path, test.uses)
        res.unapplied = dict(report.unapplied)
        t = TestContext(backend=backend, gl=backend.gl, width=w, height=h, visual=backend.visual,
                        profile=job.profile)
        test.func(t)
        res.notes.extend(t.notes)
        err = backend.gl.glGetError()
        if err:
            raise Failure(f"glGetError() is 0x{err:04X} after the test")
        res.digest = hashlib.sha1(backend.read_rgba().tobytes()).hexdigest()[:16]
    except Unsupported as exc:
        res.status, res.message = "skip", f"unsupported: {exc}"
    except NotImplementedError as exc:
        res.status, res.message = "skip", f"not implemented: {exc}"
    except Failure as exc:
        res.status, res.message = "fail", str(exc)
    except Exception as exc:
        res.status, res.message = "error", _short_trace(exc)
    finally:
        try:
            backend.close()
        except Exception as exc:  # a close failure must not hide the verdict
            res.notes.append(f"close failed: {type(exc).__name__}: {exc}")
        res.seconds = time.perf_counter() - start
    return res


class Progress:
    """A one-line counter on a stream, rewritten with carriage returns."""

    def __init__(self, total: int, stream: TextIO, enabled: bool) -> None:
        self.total, self.stream, self.enabled = total, stream, enabled
        self.done = 0
        self.bad = 0
        self.width = 0
        self.start = time.perf_counter()

    def update(self, job: Job, res: Result | None = None) -> None:
        if res is not None:
            self.done += 1
            self.bad += res.status in ("fail", "error")
        if not self.enabled:
            return
        line = (f"[{self.done:>{len(str(self.total))}}/{self.total}] {self.bad} failed  "
                f"{job.test.name} {job.backend.name} {job.profile} {job.visual} p{job.path}")
        pad = max(self.width - len(line), 0)
        self.width = len(line)
        self.stream.write("\r" + line + " " * pad)
        self.stream.flush()

    def finish(self) -> None:
        if self.enabled:
            elapsed = time.perf_counter() - self.start
            self.stream.write(f"\r{' ' * self.width}\r{self.done} runs in {elapsed:.1f} s, "
                              f"{self.bad} failed or errored\n")
            self.stream.flush()


def run(jobs: Sequence[Job], *, debug_flags: int = 0, progress: Progress | None = None) -> list[Result]:
    """Run every job in order; a path level that changes the final image fails."""
    results = []
    invariance = PathInvariance()
    for job in jobs:
        if progress is not None:
            progress.update(job)
        res = invariance.check(run_job(job, debug_flags=debug_flags))
        results.append(res)
        if progress is not None:
            progress.update(job, res)
    if progress is not None:
        progress.finish()
    return results


# {============================================================
# reports

def _cell(counts: Counter) -> str:
    n = sum(counts.values())
    if counts["error"]:
        return f"ERROR {counts['error']}/{n}" + (f", FAIL {counts['fail']}" if counts["fail"] else "")
    if counts["fail"]:
        return f"FAIL {counts['fail']}/{n}"
    if counts["pass"] == 0:
        return "skip"
    if counts["skip"]:
        return f"pass {counts['pass']}/{n} ({counts['skip']} skip)"
    return f"pass {n}/{n}"


def summary(results: Sequence[Result]) -> dict[str, dict[str, dict[str, int]]]:
    """{test: {backend: {status: count}}}."""
    table: dict[str, dict[str, Counter]] = defaultdict(lambda: defaultdict(Counter))
    for r in results:
        table[r.test][r.backend][r.status] += 1
    return {t: {b: {s: c[s] for s in STATUSES} for b, c in row.items()} for t, row in table.items()}


def unapplied_states(results: Sequence[Result]) -> dict[str, dict[str, str]]:
    """{backend: {path state: reason}} over every run."""
    out: dict[str, dict[str, str]] = defaultdict(dict)
    for r in results:
        for key, why in r.unapplied.items():
            out[r.backend].setdefault(key, why)
    return {b: dict(sorted(v.items())) for b, v in out.items()}


def _ordered_backends(results: Sequence[Result]) -> list[str]:
    seen = {r.backend for r in results}
    return [b for b in BACKENDS if b in seen] + sorted(seen - set(BACKENDS))


def totals(results: Sequence[Result]) -> dict[str, int]:
    c = Counter(r.status for r in results)
    return {s: c[s] for s in STATUSES}


def markdown_report(results: Sequence[Result], meta: dict[str, Any]) -> str:
    """The report as Markdown."""
    backends = _ordered_backends(results)
    table = summary(results)
    lines = ["# OpenGL ES 1.1 conformance report", ""]
    lines.append(f"Command: `{meta.get('command', '')}`  ")
    lines.append(f"Profiles: {', '.join(meta.get('profiles', []))}; path levels: "
                 f"{', '.join(str(p) for p in meta.get('paths', []))}; "
                 f"{len(results)} runs in {meta.get('seconds', 0):.1f} s.")
    tot = totals(results)
    lines.append(f"Totals: {tot['pass']} pass, {tot['fail']} fail, {tot['error']} error, {tot['skip']} skip.")
    lines += ["", "## Summary (runs per test and backend)", ""]
    lines.append("| test | " + " | ".join(backends) + " |")
    lines.append("| --- | " + " | ".join("---" for _ in backends) + " |")
    for test in sorted(table, key=str.lower):
        row = table[test]
        cells = [_cell(Counter(row[b])) if b in row else "-" for b in backends]
        lines.append(f"| {test} | " + " | ".join(cells) + " |")
    un = unapplied_states(results)
    lines += ["", "## Path states not applied", ""]
    if un:
        lines.append("A run on these backends does not show invariance for these states.")
        lines.append("")
        lines.append("| backend | state | why |")
        lines.append("| --- | --- | --- |")
        for b in backends:
            for key, why in un.get(b, {}).items():
                lines.append(f"| {b} | {key} | {why} |")
    else:
        lines.append("Every path state was applied on every backend.")
    bad = [r for r in results if r.status in ("fail", "error")]
    lines += ["", "## Failures and errors", ""]
    if not bad:
        lines.append("None.")
    for r in bad:
        msg = r.message.replace("\n", "\n    ")
        lines.append(f"- **{r.test}** {r.backend} {r.profile} {r.visual} path {r.path}: {r.status}  \n"
                     f"    {msg}")
    skips: dict[tuple[str, str], int] = Counter((r.backend, r.message) for r in results if r.status == "skip")
    if skips:
        lines += ["", "## Skips", ""]
        for (b, why), n in sorted(skips.items()):
            lines.append(f"- {b} ({n} runs): {why}")
    notes = Counter((r.backend, n) for r in results for n in r.notes)
    if notes:
        lines += ["", "## Notes", ""]
        for (b, note), n in sorted(notes.items()):
            lines.append(f"- {b} ({n} runs): {note}")
    return "\n".join(lines) + "\n"


def json_report(results: Sequence[Result], meta: dict[str, Any]) -> str:
    """The report as JSON."""
    doc = {
        "meta": meta,
        "totals": totals(results),
        "summary": summary(results),
        "unapplied_path_states": unapplied_states(results),
        "results": [asdict(r) for r in results],
    }
    return json.dumps(doc, indent=1) + "\n"


def summary_text(results: Sequence[Result]) -> str:
    """The summary table as aligned text (for the terminal)."""
    backends = _ordered_backends(results)
    table = summary(results)
    rows = [["test"] + backends]
    for test in sorted(table, key=str.lower):
        rows.append([test] + [_cell(Counter(table[test][b])) if b in table[test] else "-" for b in backends])
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    out = ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows]
    out.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(out)


# {============================================================
# command line

def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m conformance",
        description="OpenGL ES 1.1 conformance suite: runs the registered tests on gles builds "
                    "and on Mesa through EGL, at path levels 0..4.")
    p.add_argument("--backend", action="append", choices=sorted(BACKENDS), metavar="NAME",
                   help="backend to run (repeatable): " + ", ".join(BACKENDS) + "; default: all")
    p.add_argument("--library", metavar="EGL:GLES",
                   help="the EGL and GLES 1 libraries of the 'library' backend, as two paths joined "
                        "by ':' (sets GLES_CONFORMANCE_LIBRARY; implies --backend library)")
    p.add_argument("--profile", action="append", choices=PROFILES,
                   help="profile (repeatable); default: both")
    p.add_argument("--path", default=f"0-{MAX_LEVEL}", metavar="LEVELS",
                   help=f"path levels: a level 0..{MAX_LEVEL}, a range 'a-b', a list 'a,b' or 'all' "
                        f"(default 0-{MAX_LEVEL})")
    p.add_argument("--visual", action="append", choices=sorted(VISUALS),
                   help="only these visuals (repeatable); default: each test's own")
    p.add_argument("-k", action="append", default=[], metavar="NAME", dest="keywords",
                   help="only the test or category NAME, else the tests whose name contains NAME "
                        "(case-insensitive, repeatable)")
    p.add_argument("--report", metavar="FILE", help="write a report: FILE.md (Markdown) or FILE.json")
    p.add_argument("--progress", action="store_true", help="show progress even when stderr is not a tty")
    p.add_argument("--list", action="store_true", help="list the tests and exit")
    p.add_argument("--debug-flags", type=int, default=0, help=argparse.SUPPRESS)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``python -m conformance``; returns the exit status."""
    args = _parser().parse_args(argv)
    try:
        levels = parse_levels(args.path)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.report and Path(args.report).suffix.lower() not in (".md", ".markdown", ".json"):
        print(f"error: --report needs a .md or .json file name, not {args.report!r}", file=sys.stderr)
        return 2
    registry = load_categories()
    tests = select_tests(registry, args.keywords)
    if args.list:
        for t in tests:
            print(f"{t.name:<24} §{t.section:<8} {t.description}")
        return 0
    if not tests:
        print("error: no test matches " + ", ".join(args.keywords), file=sys.stderr)
        return 2
    if args.library:
        if ":" not in args.library:
            print("error: --library needs /path/libEGL.so.1:/path/libGLESv1_CM.so.1", file=sys.stderr)
            return 2
        os.environ["GLES_CONFORMANCE_LIBRARY"] = args.library
        args.backend = [*(args.backend or []), "library"]
    names = args.backend or [n for n in BACKENDS if n != "library" or BACKENDS[n].available() is None]
    specs = [BACKENDS[n] for n in dict.fromkeys(names)]
    profiles = list(dict.fromkeys(args.profile or PROFILES))
    for spec in specs:
        why = spec.available()
        if why is not None:
            print(f"{spec.name}: skipped: {why}", file=sys.stderr)
    jobs = plan(tests, specs, profiles, levels, args.visual)
    progress = Progress(len(jobs), sys.stderr, args.progress or sys.stderr.isatty())
    start = time.perf_counter()
    results = run(jobs, debug_flags=args.debug_flags, progress=progress)
    meta = {
        "command": " ".join(["python -m conformance"] + list(sys.argv[1:] if argv is None else argv)),
        "backends": {s.name: s.available() for s in specs},
        "profiles": profiles,
        "paths": levels,
        "tests": [t.name for t in tests],
        "python": platform.python_version(),
        "seconds": round(time.perf_counter() - start, 3),
        "debug_flags": args.debug_flags,
    }
    print(summary_text(results))
    tot = totals(results)
    print(f"\n{len(results)} runs: {tot['pass']} pass, {tot['fail']} fail, {tot['error']} error, "
          f"{tot['skip']} skip")
    bad = [r for r in results if r.status in ("fail", "error")]
    for r in bad[:MAX_LISTED]:
        first = r.message.splitlines()[0] if r.message else ""
        print(f"  {r.status.upper()}: {r.test} {r.backend} {r.profile} {r.visual} p{r.path}: {first}")
    if len(bad) > MAX_LISTED:
        print(f"  ... and {len(bad) - MAX_LISTED} more" + (" (see the report)" if args.report else
                                                          " (--report FILE.md lists them all)"))
    if args.report:
        out = Path(args.report)
        if out.suffix.lower() == ".json":
            out.write_text(json_report(results, meta))
        else:
            out.write_text(markdown_report(results, meta))
        print(f"report written to {out}")
    return 1 if tot["fail"] or tot["error"] else 0
