"""Cross-build the trace replayer for the no-FPU target (see docs/target.md).

``lib/target/gles-replay-armel-<numeric>`` for the fixed and float builds: a
static 32-bit ARM (ARMv5TE, ARM state, soft-float) program of the core
(csrc/core_all.c) and the replayer (csrc/replay/), built with Debian's
``arm-linux-gnueabi-gcc`` when it is installed (nothing is built otherwise).
gles.target runs these under an emulator and counts their instructions,
with the block hook ``lib/target/libgles_blockcount.so`` (built for the host).

Environment: ``GLES_TARGET_CC`` (default ``arm-linux-gnueabi-gcc``; ``none``
skips the target build).
"""

from __future__ import annotations

import os
import shlex
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

CSRC = Path(__file__).resolve().parent.parent.parent / "csrc"
BUILDS = ("fixed", "float")
ARCH_FLAGS = ["-marm", "-march=armv5te", "-mtune=arm926ej-s", "-mfloat-abi=soft"]
# the host core's flags (native.cflags) for a static program
CFLAGS = ["-std=c11", "-Wall", "-Wextra", "-O3", "-ffp-contract=off", "-DNDEBUG",
          *ARCH_FLAGS, "-static"]


def compiler() -> str | None:
    """The cross compiler to use, or None when there is none."""
    cc = os.environ.get("GLES_TARGET_CC", "arm-linux-gnueabi-gcc")
    if cc == "none":
        return None
    return shutil.which(cc)


def exe_name(numeric: str) -> str:
    return f"gles-replay-armel-{numeric}"


def remove_stale(out: Path, newest: float) -> None:
    """Without a cross compiler, remove the replayers in `out` older than the
    sources (mtime `newest`): they would count another core's instructions,
    or fail on a changed trace format, where the target should read n/a."""
    for numeric in BUILDS:
        target = out / exe_name(numeric)
        if target.exists() and target.stat().st_mtime <= newest:
            target.unlink()
            target.with_name(target.name + ".flags").unlink(missing_ok=True)


def build(lib: Path) -> list[Path]:
    """Build the target replayers into ``lib/target`` if the cross compiler is
    there; returns the programs (up to date ones are not rebuilt)."""
    cc = compiler()
    out = lib / "target"
    inputs = [*CSRC.glob("*.[ch]"), *(CSRC / "replay").glob("*.[ch]")]
    newest = max(p.stat().st_mtime for p in inputs)
    if cc is None:
        remove_stale(out, newest)
        return []
    out.mkdir(parents=True, exist_ok=True)
    version = subprocess.run([cc, "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    inc = ["-I" + str(CSRC), "-I" + str(CSRC / "khronos")]

    def one(numeric: str) -> Path:
        target = out / exe_name(numeric)
        stamp = target.with_name(target.name + ".flags")
        cmd = [cc, *CFLAGS, f"-DGLES_NUM_{numeric.upper()}=1", *inc, str(CSRC / "core_all.c"),
               str(CSRC / "replay" / "replay.c"), str(CSRC / "replay" / "replay_main.c"),
               "-o", str(target) + ".tmp", "-lm"]
        key = version + "\n" + shlex.join(cmd)
        fresh = target.exists() and target.stat().st_mtime > newest
        if fresh and stamp.exists() and stamp.read_text() == key:
            return target
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0 or proc.stderr.strip():
            raise RuntimeError(f"{shlex.join(cmd)}\n{proc.stdout}{proc.stderr}")
        os.replace(str(target) + ".tmp", target)
        stamp.write_text(key)
        return target

    # the emulator's block-counting hook, for this host (csrc/replay/blockcount.c)
    host_cc = shlex.split(os.environ.get("CC", "cc"))
    counter = out / "libgles_blockcount.so"
    proc = subprocess.run([*host_cc, "-std=c11", "-Wall", "-Wextra", "-O2", "-fPIC", "-shared",
                           "-fvisibility=hidden", str(CSRC / "replay" / "blockcount.c"), "-o", str(counter)],
                          capture_output=True, text=True)
    if proc.returncode != 0 or proc.stderr.strip():
        raise RuntimeError(f"blockcount.c:\n{proc.stdout}{proc.stderr}")
    with ThreadPoolExecutor(max_workers=2) as pool:
        return [*pool.map(one, BUILDS), counter]
