"""The cores' AVX2 code cleans the vector registers' upper halves before it
calls scalar code (docs/architecture.md, Compiler flags): GCC without
-fno-ipa-ra left them dirty across calls to local functions that use no SSE
register, and the SSE code that ran next paid for it on each vector
instruction. The fixed core's flat blended spans are such callers (their
AVX2 instances call the scalar ``span_flat_run``): each of those calls must
follow a ``vzeroupper``. Read from the installed core's machine code."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

import gles

CALLERS = re.compile(r"<(span_flat_(?:zless_)?(?:alpha|add)_avx2)>:$")


def disassembly(numeric: str) -> list[str]:
    """objdump's lines for the core of one build (skips without objdump)."""
    objdump = shutil.which("objdump")
    if objdump is None:
        pytest.skip("objdump is not installed")
    lib = Path(gles.__file__).resolve().parent / "lib" / f"libgles_{numeric}.so"
    proc = subprocess.run([objdump, "-d", "--no-show-raw-insn", str(lib)], capture_output=True, text=True,
                          check=True)
    return proc.stdout.splitlines()


def calls_after(lines: list[str], callee: str) -> dict[str, list[str]]:
    """For each flat span's AVX2 instance, the instruction before each of its calls (or tail
    calls) of `callee`."""
    out: dict[str, list[str]] = {}
    current = None
    previous = ""
    for line in lines:
        head = CALLERS.search(line)
        if head:
            current = head.group(1)
            out[current] = []
            continue
        if line.endswith(">:"):
            current = None
        if current is None or "\t" not in line:
            continue
        insn = line.split("\t", 1)[1].strip()
        if insn.startswith(("call", "jmp")) and f"<{callee}>" in insn:     # (a tail call jumps)
            out[current].append(previous)
        previous = insn
    return out


def test_flat_spans_clean_the_upper_halves_before_the_scalar_run():
    found = calls_after(disassembly("fixed"), "span_flat_run")
    if not found:
        pytest.skip("this core has no AVX2 flat spans (built without GCC's x86-64 vector instances)")
    calls = [(name, before) for name, befores in found.items() for before in befores]
    assert calls, found      # the blended flat spans do call the scalar run
    for name, before in calls:
        assert before.startswith("vzeroupper"), (name, before)
