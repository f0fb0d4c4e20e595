"""Build the plain shared libraries: one core per numeric build, and the C ABI on it.

For each numeric build ``n`` (fixed, float, double):

* ``lib/libgles_<n>.so``: the core (csrc/cabi/core_lib.c, which is
  csrc/core_all.c with the gles_core.h API exported and everything else
  hidden). The cffi module gles._core_<n> links against it (rpath
  ``$ORIGIN/lib``), so Python and C programs use the same compiled core.
* ``lib/<n>/<profile>/`` for profile ``common`` and ``common-lite``:
  ``libGLESv1_CM.so.1`` (csrc/cabi/gl.c) and ``libEGL.so.1`` (csrc/cabi/egl.c),
  both linked against that core (rpath ``$ORIGIN/../..``), a copy of each as
  ``.so`` for the link editor's ``-l``, and ``glesv1_cm.pc`` / ``egl.pc``.

``include/`` holds the Khronos headers (csrc/khronos). Everything is written
under one directory, laid out as it is inside the installed ``gles`` package.

Environment: ``CC`` (default ``cc``), and ``GLES_CFLAGS`` as for build.py.
"""

from __future__ import annotations

import functools
import os
import shlex
import shutil
import subprocess
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

try:
    from . import target_build
except ImportError:     # imported as a plain module (setup.py, tools/devbuild.py)
    import target_build  # type: ignore[no-redef]

ROOT = Path(__file__).resolve().parent.parent.parent
CSRC = ROOT / "csrc"
OUT = ROOT / "build" / "native"          # what build.py links the cffi modules against

NUMERICS = ("fixed", "float", "double")
PROFILES = ("common", "common-lite")
VERSION = "0.1.0"


def _extra() -> list[str]:
    return shlex.split(os.environ.get("GLES_CFLAGS", ""))


@functools.cache
def _is_gcc(cc: tuple[str, ...]) -> bool:
    """Whether the compiler is GCC (it defines __GNUC__ and not __clang__)."""
    proc = subprocess.run([*cc, "-dM", "-E", "-x", "c", os.devnull], capture_output=True, text=True)
    macros = proc.stdout.split()
    return proc.returncode == 0 and "__GNUC__" in macros and "__clang__" not in macros


def cflags(cc: Sequence[str] = ("cc",)) -> list[str]:
    """The compiler flags of every library (the core's, see docs/architecture.md).

    With GCC, -fno-ipa-ra: where interprocedural register allocation knows a
    local callee uses no SSE register, GCC 12 emits no vzeroupper before the
    call from AVX code, yet takes the upper halves as clean after it, so the
    function returns without one too, and the baseline code that runs next
    (SSE) pays for the dirty halves on its vector instructions: blended_quads
    took about 35% longer in the fixed build. Without the flag each such call
    gets its vzeroupper; the instruction counts stay within 0.1%."""
    extra = _extra()
    opt = [] if any(f.startswith("-O") for f in extra) else ["-O3"]
    gcc = ["-fno-ipa-ra"] if _is_gcc(tuple(cc)) else []
    return ["-std=c11", "-Wall", "-Wextra", "-ffp-contract=off", "-DNDEBUG", "-fPIC",
            "-fvisibility=hidden", *gcc, *opt, *extra]


def ldflags() -> list[str]:
    """Link flags: shared, every symbol defined, the sanitizer runtime if asked for."""
    return ["-shared", "-Wl,-z,defs", *[f for f in _extra() if f.startswith("-fsanitize")]]


def _run(cmd: list[str]) -> None:
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0 or proc.stderr.strip():
        # warnings count as failures: the libraries build -Wall -Wextra clean
        raise RuntimeError(f"{shlex.join(cmd)}\n{proc.stdout}{proc.stderr}")


def core_lib_name(numeric: str) -> str:
    return f"libgles_{numeric}.so"


def _pc(name: str, description: str, lib: str, numeric: str, profile: str) -> str:
    return (
        "libdir=${pcfiledir}\n"
        "includedir=${pcfiledir}/../../../include\n\n"
        f"Name: {name}\n"
        f"Description: {description} (gles, {numeric} build, {profile} profile)\n"
        f"Version: {VERSION}\n"
        "Cflags: -I${includedir}\n"
        f"Libs: -L${{libdir}} -l{lib}\n"
    )


def build(out: Path = OUT) -> Path:
    """Compile every library into ``out`` (lib/ and include/); returns ``out``."""
    cc = shlex.split(os.environ.get("CC", "cc"))
    lib = out / "lib"
    lib.mkdir(parents=True, exist_ok=True)
    flags = cflags(cc)
    inc = ["-I" + str(CSRC), "-I" + str(CSRC / "khronos")]

    core_inputs = [*CSRC.glob("*.[ch]"), CSRC / "cabi" / "core_lib.c", CSRC / "cabi" / "cabi.h"]
    newest = max(p.stat().st_mtime for p in core_inputs)

    def core(numeric: str) -> None:
        target = lib / core_lib_name(numeric)
        stamp = target.with_name(target.name + ".flags")
        key = shlex.join([*cc, *flags, *ldflags()])
        fresh = target.exists() and target.stat().st_mtime > newest
        if fresh and stamp.exists() and stamp.read_text() == key:
            return   # up to date (the core takes most of the build time)
        # GLES_THREADS: the core's worker threads (csrc/pool.c), POSIX threads
        _run([*cc, *flags, f"-DGLES_NUM_{numeric.upper()}=1", "-DGLES_THREADS=1", "-pthread", *inc,
              str(CSRC / "cabi" / "core_lib.c"), "-o", str(target) + ".tmp", *ldflags(),
              f"-Wl,-soname,{core_lib_name(numeric)}", "-Wl,-Bsymbolic", "-lm"])
        os.replace(str(target) + ".tmp", target)
        stamp.write_text(key)

    def abi(numeric: str, profile: str) -> None:
        d = lib / numeric / profile
        d.mkdir(parents=True, exist_ok=True)
        common = "1" if profile == "common" else "0"
        link = [f"-L{lib}", f"-lgles_{numeric}", "-Wl,-rpath,$ORIGIN/../..", "-lm"]
        for src, name, extra in (("gl.c", "libGLESv1_CM.so.1", []),
                                 ("egl.c", "libEGL.so.1", ["-ldl", "-lpthread"])):
            _run([*cc, *flags, f"-DGLES_CABI_COMMON={common}", *inc, str(CSRC / "cabi" / src),
                  "-o", str(d / name) + ".tmp", *ldflags(), f"-Wl,-soname,{name}", *link, *extra])
            os.replace(str(d / name) + ".tmp", d / name)
            shutil.copyfile(d / name, d / name[: -len(".1")])
        (d / "glesv1_cm.pc").write_text(_pc("glesv1_cm", "OpenGL ES 1.1 Common" +
                                            ("" if profile == "common" else "-Lite"),
                                            "GLESv1_CM", numeric, profile))
        (d / "egl.pc").write_text(_pc("egl", "EGL 1.4 (pbuffers)", "EGL", numeric, profile))

    def replayer(numeric: str) -> None:
        # gles-replay (csrc/replay/): plays a trace file on this build's core
        d = lib / numeric
        d.mkdir(parents=True, exist_ok=True)
        _run([*cc, *flags, *inc, str(CSRC / "replay" / "replay.c"), str(CSRC / "replay" / "replay_main.c"),
              "-o", str(d / "gles-replay") + ".tmp", *[f for f in _extra() if f.startswith("-fsanitize")],
              f"-L{lib}", f"-lgles_{numeric}", "-Wl,-rpath,$ORIGIN/..", "-lm"])
        os.replace(str(d / "gles-replay") + ".tmp", d / "gles-replay")

    with ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(core, NUMERICS))
        list(pool.map(lambda np: abi(*np), [(n, p) for n in NUMERICS for p in PROFILES]))
        list(pool.map(replayer, NUMERICS))
    target_build.build(lib)   # the no-FPU target's replayers, when the cross compiler is there
    include = out / "include"
    if include.exists():
        shutil.rmtree(include)
    shutil.copytree(CSRC / "khronos", include)
    return out


def install(src: Path, package_dir: Path) -> None:
    """Copy lib/ and include/ of a build into a ``gles`` package directory,
    each file renamed into place (processes with the old libraries loaded
    keep running on them)."""
    for sub in ("lib", "include"):
        for path in sorted((src / sub).rglob("*")):
            if path.is_dir() or path.name.endswith(".flags"):
                continue
            dest = package_dir / path.relative_to(src)
            dest.parent.mkdir(parents=True, exist_ok=True)
            staged = dest.with_name(dest.name + ".new")
            shutil.copyfile(path, staged)
            shutil.copymode(path, staged)
            os.replace(staged, dest)


if __name__ == "__main__":
    print(build())
