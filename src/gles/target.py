"""What a frame costs on a CPU without an FPU: instructions per frame, counted.

The target is a 32-bit ARM of the ARM926EJ-S class (ARMv5TE, ARM state, no
floating-point unit): float arithmetic there is the compiler's soft-float
library. The trace replayer (csrc/replay/) is cross-built for it, statically,
with the core of the fixed and of the float build (``gles-replay-armel-*``,
see src/_gles_build/target_build.py), and run here by the unicorn emulator
with a small Linux system-call layer. A block hook adds up the instructions
of every basic block the CPU enters: in ARM state every instruction is 4
bytes, so a block of n bytes is n / 4 instructions, and the count is exact
and the same on every run. The frame is what lies between the replayer's two
markers (see gles.trace: a steady-state frame, or the whole scene when it
draws directly), so reading the trace, setting up the context and writing
the image are not counted.

    from gles import target
    if target.target_available():
        n = target.target_cost(scene, "fixed", (96, 72))    # instructions per frame

Without the cross compiler (apt) or unicorn (pip) :func:`target_missing`
says what to install, and :func:`target_cost` raises :class:`TargetUnavailable`.
``GLES_TARGET=off`` in the environment turns the target off (the report then
skips its target section's emulation, which takes a few seconds a scene).
"""

from __future__ import annotations

import bisect
import ctypes
import os
import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

BUILDS = ("fixed", "float")
TARGET = "ARMv5TE (ARM926EJ-S class), ARM state, no FPU (soft-float)"
APT_COMMAND = "apt-get install -y gcc-arm-linux-gnueabi"
PIP_COMMAND = "pip install unicorn"
DEFAULT_SIZE = (96, 72)

_PACKAGE = Path(__file__).resolve().parent
_COUNTER_LIB = _PACKAGE / "lib" / "target" / "libgles_blockcount.so"
_MARK_SYSCALL = 0x0F1E5          # replay_main.c's GLES_MARK_SYSCALL
_MARK_BEGIN, _MARK_END = 1, 2

# memory layout of the emulated process
_STACK_TOP = 0xBF000000
_STACK_SIZE = 8 << 20
_MMAP_BASE = 0x40000000
_KUSER_PAGE = 0xFFFF0000
_PAGE = 0x1000
_MAX_MEMORY = 1 << 30             # brk and mmap together

# AT_HWCAP of an ARM926EJ-S: swp, half, thumb, fast_mult, edsp, java; no vfp
_HWCAP = 0x1 | 0x2 | 0x4 | 0x10 | 0x80 | 0x100
_ENOSYS, _EBADF, _ENOTTY = 38, 9, 25


class TargetUnavailable(RuntimeError):
    """The target toolchain or emulator is not installed."""


class TargetError(RuntimeError):
    """The target program faulted, or exited with an error."""


def program(build: str) -> Path:
    """The target replayer of one build (it may not exist)."""
    if build not in BUILDS:
        raise ValueError(f"build must be one of {BUILDS}, not {build!r}")
    return _PACKAGE / "lib" / "target" / f"gles-replay-armel-{build}"


def target_missing() -> str | None:
    """None when target costs can be measured here, else what to install
    (or that the environment variable GLES_TARGET=off turned them off)."""
    if os.environ.get("GLES_TARGET", "").lower() == "off":
        return "n/a: turned off (GLES_TARGET=off)"
    need = []
    if not all(program(b).is_file() for b in BUILDS) or not _COUNTER_LIB.is_file():
        need.append(f"the cross compiler ({APT_COMMAND}, then reinstall gles: it builds "
                    "the target replayers when the compiler is there)")
    try:
        import unicorn  # noqa: F401
    except ImportError:
        need.append(f"the unicorn emulator ({PIP_COMMAND})")
    return None if not need else "n/a: needs " + " and ".join(need)


def target_available() -> bool:
    """True when target instruction counts can be measured here."""
    return target_missing() is None


@dataclass
class TargetRun:
    """One run of the target replayer on a trace."""

    build: str
    frame_instructions: int     # between the frame markers
    total_instructions: int     # the whole program, start to exit
    color_buffer: bytes         # what the program wrote (the final colour buffer)
    exit_code: int
    stderr: str


def _page_up(n: int) -> int:
    return (n + _PAGE - 1) & ~(_PAGE - 1)


def _kuser_page() -> bytes:
    """The kernel's user helpers that armel's C library calls (ARMv5 has no
    TLS register or exclusive loads), implemented for one thread."""
    page = bytearray(_PAGE)

    def put(addr: int, *words: int) -> None:
        off = addr - _KUSER_PAGE
        page[off:off + 4 * len(words)] = struct.pack(f"<{len(words)}I", *words)

    bx_lr = 0xE12FFF1E
    put(0xFFFF0FA0, bx_lr)                                   # memory barrier: nothing to order
    # cmpxchg(oldval r0, newval r1, ptr r2): r0 = 0 and C set when stored
    put(0xFFFF0FC0, 0xE5923000,   # ldr   r3, [r2]
                    0xE0533000,   # subs  r3, r3, r0
                    0x05821000,   # streq r1, [r2]
                    0xE2730000,   # rsbs  r0, r3, #0
                    bx_lr)
    put(0xFFFF0FE0, 0xE59F0008, bx_lr)                       # get_tls: ldr r0, [pc, #8] (0xffff0ff0)
    put(0xFFFF0FFC, 3)                                       # helper version
    return bytes(page)


def _load_elf(uc: Any, image: bytes) -> tuple[int, int, int, int]:
    """Map a static ARM ELF executable; (entry, phdr address, phnum, end of data)."""
    if image[:4] != b"\x7fELF" or image[4] != 1 or image[5] != 1:
        raise TargetError("not a 32-bit little-endian ELF file")
    (e_type, e_machine, _v, entry, phoff, _sh, _fl, _eh, phentsize, phnum) = struct.unpack_from(
        "<HHIIIIIHHH", image, 16)
    if e_type != 2 or e_machine != 40:
        raise TargetError("not a static ARM executable")
    phdr_addr, end = 0, 0
    for i in range(phnum):
        p_type, p_off, p_vaddr, _pa, p_filesz, p_memsz, _flags, _align = struct.unpack_from(
            "<IIIIIIII", image, phoff + i * phentsize)
        if p_type != 1:        # PT_LOAD
            continue
        start = p_vaddr & ~(_PAGE - 1)
        stop = _page_up(p_vaddr + p_memsz)
        lo = max(start, _page_up(end)) if end > start else start
        if stop > lo:
            uc.mem_map(lo, stop - lo)
        uc.mem_write(p_vaddr, image[p_off:p_off + p_filesz])
        if p_off <= phoff < p_off + p_filesz:
            phdr_addr = p_vaddr + (phoff - p_off)
        end = max(end, p_vaddr + p_memsz)
    return entry, phdr_addr, phnum, end


class _Process:
    """The emulated program and the system calls it makes."""

    def __init__(self, exe: Path, stdin: bytes, counter: str = "c") -> None:
        from unicorn import UC_ARCH_ARM, UC_HOOK_BLOCK, UC_HOOK_CODE, UC_HOOK_INTR, UC_MODE_ARM, Uc
        from unicorn.arm_const import UC_ARM_REG_SP, UC_CPU_ARM_926

        self.uc = uc = Uc(UC_ARCH_ARM, UC_MODE_ARM)
        uc.ctl_set_cpu_model(UC_CPU_ARM_926)       # ARMv5TE, no VFP: a float instruction would fault
        self.entry, phdr, phnum, end = _load_elf(uc, exe.read_bytes())
        self.brk_start = self.brk = _page_up(end)
        self.brk_mapped = self.brk
        self.mmap_next = _MMAP_BASE
        self.stdin, self.stdin_pos = stdin, 0
        self.stdout, self.stderr = bytearray(), bytearray()
        self.exit_code: int | None = None
        self._count = ctypes.c_uint64(0)
        self._hooks: list[Any] = []
        self.marks: dict[int, int] = {}
        self.tls = 0
        uc.mem_map(_KUSER_PAGE, _PAGE)
        uc.mem_write(_KUSER_PAGE, _kuser_page())
        uc.mem_map(_STACK_TOP - _STACK_SIZE, _STACK_SIZE)
        uc.reg_write(UC_ARM_REG_SP, self._initial_stack(phdr, phnum))
        if counter == "c":
            self._add_c_block_hook()
        elif counter == "python":
            uc.hook_add(UC_HOOK_BLOCK, self._on_block)
        elif counter == "profile":              # the Python block hook, counting per block address
            self.block_bytes: dict[int, int] = {}
            uc.hook_add(UC_HOOK_BLOCK, self._on_block_profiled)
        elif counter == "instruction":       # one callback per instruction: slow, for tests
            uc.hook_add(UC_HOOK_CODE, self._on_instruction)
        else:
            raise ValueError(f"counter must be 'c', 'python', 'profile' or 'instruction', not {counter!r}")
        uc.hook_add(UC_HOOK_INTR, self._on_interrupt)

    def _add_c_block_hook(self) -> None:
        """The block hook of libgles_blockcount.so, registered through unicorn's C API."""
        from unicorn import UC_HOOK_BLOCK
        from unicorn.unicorn_py3 import unicorn as binding

        lib = ctypes.CDLL(str(_COUNTER_LIB))
        self._hooks.append(lib)
        handle = ctypes.c_size_t(0)
        fn = ctypes.cast(lib.gles_count_block, ctypes.c_void_p)
        err = binding.uclib.uc_hook_add(self.uc._uch, ctypes.byref(handle), UC_HOOK_BLOCK, fn,
                                        ctypes.c_void_p(ctypes.addressof(self._count)), 1, 0)
        if err != 0:
            raise TargetError(f"unicorn refused the block hook (error {err})")

    @property
    def bytes_executed(self) -> int:
        return int(self._count.value)

    def _initial_stack(self, phdr: int, phnum: int) -> int:
        """argc, argv, envp and the auxiliary vector, as the kernel lays them out."""
        uc = self.uc
        strings = _STACK_TOP - 256
        argv = [b"gles-replay\0", b"-\0", b"-o\0", b"-\0"]
        pointers, at = [], strings
        for s in argv:
            uc.mem_write(at, s)
            pointers.append(at)
            at += len(s)
        random_bytes = _STACK_TOP - 32          # AT_RANDOM: fixed, so runs repeat exactly
        uc.mem_write(random_bytes, bytes(range(16)))
        auxv = [(3, phdr), (4, 32), (5, phnum), (6, _PAGE), (9, self.entry), (11, 0), (12, 0),
                (13, 0), (14, 0), (16, _HWCAP), (17, 100), (23, 0), (25, random_bytes), (0, 0)]
        words = [len(pointers), *pointers, 0, 0]          # argc, argv..., NULL, envp NULL
        for key, value in auxv:
            words += [key, value]
        sp = (strings - 4 * len(words) - 64) & ~15
        uc.mem_write(sp, struct.pack(f"<{len(words)}I", *words))
        return sp

    def _on_block(self, uc: Any, address: int, size: int, user: Any) -> None:
        self._count.value += size

    def _on_block_profiled(self, uc: Any, address: int, size: int, user: Any) -> None:
        self._count.value += size
        self.block_bytes[address] = self.block_bytes.get(address, 0) + size

    def _on_instruction(self, uc: Any, address: int, size: int, user: Any) -> None:
        self._count.value += size

    def _mmap(self, length: int) -> int:
        length = _page_up(length)
        if length == 0 or self._memory() + length > _MAX_MEMORY:
            return -12           # ENOMEM
        addr = self.mmap_next
        self.uc.mem_map(addr, length)
        self.mmap_next += length
        return addr

    def _memory(self) -> int:
        return (self.brk_mapped - self.brk_start) + (self.mmap_next - _MMAP_BASE)

    def _on_interrupt(self, uc: Any, intno: int, user: Any) -> None:
        from unicorn.arm_const import (
            UC_ARM_REG_C13_C0_3,
            UC_ARM_REG_R0,
            UC_ARM_REG_R1,
            UC_ARM_REG_R2,
            UC_ARM_REG_R3,
            UC_ARM_REG_R7,
        )

        if intno != 2:           # only svc is expected
            self.exit_code = -1
            self.stderr += f"unexpected exception {intno}\n".encode()
            uc.emu_stop()
            return
        nr = uc.reg_read(UC_ARM_REG_R7)
        a0, a1, a2 = (uc.reg_read(r) for r in (UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2))
        ret = 0
        if nr == _MARK_SYSCALL:
            self.marks[a0] = self.bytes_executed
        elif nr == 0xF0005:                      # set_tls
            self.tls = a0
            uc.mem_write(0xFFFF0FF0, struct.pack("<I", a0))
            uc.reg_write(UC_ARM_REG_C13_C0_3, a0)
        elif nr == 45:                           # brk
            if a0 >= self.brk_start and a0 - self.brk_start <= _MAX_MEMORY:
                want = _page_up(a0)
                if want > self.brk_mapped:
                    uc.mem_map(self.brk_mapped, want - self.brk_mapped)
                    self.brk_mapped = want
                self.brk = a0
            ret = self.brk
        elif nr == 192:                          # mmap2: anonymous memory only
            flags = uc.reg_read(UC_ARM_REG_R3)
            ret = self._mmap(a1) if (flags & 0x20) else -_EBADF
        elif nr in (91, 125, 6, 174, 175, 338):  # munmap, mprotect, close, signals, robust list
            ret = 0
        elif nr == 3:                            # read
            if a0 != 0:
                ret = -_EBADF
            else:
                chunk = self.stdin[self.stdin_pos:self.stdin_pos + a2]
                uc.mem_write(a1, chunk)
                self.stdin_pos += len(chunk)
                ret = len(chunk)
        elif nr == 4:                            # write
            ret = self._write(a0, bytes(uc.mem_read(a1, a2)))
        elif nr == 146:                          # writev
            ret = 0
            for i in range(a2):
                base, length = struct.unpack("<II", uc.mem_read(a1 + 8 * i, 8))
                ret += self._write(a0, bytes(uc.mem_read(base, length)))
        elif nr in (1, 248):                     # exit, exit_group
            self.exit_code = a0 if a0 < 2**31 else a0 - 2**32
            uc.emu_stop()
        elif nr in (256, 20, 224):               # set_tid_address, getpid, gettid
            ret = 1
        elif nr in (199, 200, 201, 202):         # get[e]uid32, get[e]gid32
            ret = 0
        elif nr == 384:                          # getrandom: fixed bytes, for repeatable runs
            uc.mem_write(a0, bytes(a1))
            ret = a1
        elif nr == 54:                           # ioctl
            ret = -_ENOTTY
        elif nr == 238 or nr == 268:             # tgkill, tkill (abort)
            self.exit_code = -6
            uc.emu_stop()
        else:
            ret = -_ENOSYS
        uc.reg_write(UC_ARM_REG_R0, ret & 0xFFFFFFFF)

    def _write(self, fd: int, data: bytes) -> int:
        if fd == 1:
            self.stdout += data
        elif fd == 2:
            self.stderr += data
        else:
            return -_EBADF
        return len(data)

    def run(self) -> None:
        from unicorn import UcError
        from unicorn.arm_const import UC_ARM_REG_PC

        try:
            self.uc.emu_start(self.entry, 0xFFFFFFFF)
        except UcError as exc:
            pc = self.uc.reg_read(UC_ARM_REG_PC)
            raise TargetError(f"the target program faulted at 0x{pc:08x}: {exc}") from None
        if self.exit_code is None:
            raise TargetError("the target program stopped without exiting")


def run_trace(data: bytes, build: str, counter: str = "c") -> TargetRun:
    """Run the target replayer of `build` on a trace; counts its instructions.

    ``counter`` picks how: "c" (the block hook in C, the default), "python"
    (the same block hook in Python) or "instruction" (a hook on every
    instruction, which does not rely on blocks being 4 bytes an instruction);
    all three give the same count, at very different speeds.
    """
    why = target_missing()
    if why is not None:
        raise TargetUnavailable(why)
    proc = _Process(program(build), data, counter)
    proc.run()
    err = proc.stderr.decode(errors="replace")
    if proc.exit_code != 0:
        raise TargetError(f"the target replayer exited with {proc.exit_code}: {err.strip()}")
    if set(proc.marks) != {_MARK_BEGIN, _MARK_END}:
        raise TargetError("the target replayer did not mark its frame")
    frame_bytes = proc.marks[_MARK_END] - proc.marks[_MARK_BEGIN]
    return TargetRun(build, frame_bytes // 4, proc.bytes_executed // 4, bytes(proc.stdout),
                     proc.exit_code, err)


def _functions(image: bytes) -> list[tuple[int, int, str]]:
    """(address, size, name) of the function symbols of an ELF32 file, by address."""
    shoff, = struct.unpack_from("<I", image, 32)
    shentsize, shnum = struct.unpack_from("<HH", image, 46)
    sections = [struct.unpack_from("<IIIIIIIIII", image, shoff + i * shentsize) for i in range(shnum)]
    out = []
    for _name, sh_type, _fl, _addr, off, size, link, _info, _al, entsize in sections:
        if sh_type != 2 or entsize != 16:        # SHT_SYMTAB
            continue
        str_off = sections[link][4]
        for k in range(size // 16):
            st_name, value, st_size, info, _other, _shndx = struct.unpack_from("<IIIBBH", image, off + 16 * k)
            if info & 0xF == 2 and st_size:      # STT_FUNC
                end = image.index(b"\0", str_off + st_name)
                out.append((value & ~1, st_size, image[str_off + st_name:end].decode()))
    return sorted(out)


def profile_trace(data: bytes, build: str) -> dict[str, int]:
    """Instructions per function over the whole run of the target replayer on
    a trace (setup included), most first: where a frame's instructions go.
    Slow (a Python hook per block)."""
    why = target_missing()
    if why is not None:
        raise TargetUnavailable(why)
    exe = program(build)
    proc = _Process(exe, data, "profile")
    proc.run()
    funcs = _functions(exe.read_bytes())
    starts = [f[0] for f in funcs]
    per: dict[str, int] = {}
    for address, nbytes in proc.block_bytes.items():
        i = bisect.bisect_right(starts, address) - 1
        name = funcs[i][2] if i >= 0 and address < funcs[i][0] + funcs[i][1] else "?"
        per[name] = per.get(name, 0) + nbytes // 4
    return dict(sorted(per.items(), key=lambda kv: -kv[1]))


def target_cost(scene: Callable[[Any, int, int], Any], build: str,
                size: tuple[int, int] = DEFAULT_SIZE) -> int:
    """Instructions per frame of `scene` on the no-FPU target, for the fixed
    or float build, at `size` (width, height). The scene is recorded on this
    host's core of the same build (gles.trace) and replayed on the target."""
    from . import trace as _trace

    if build not in BUILDS:
        raise ValueError(f"build must be one of {BUILDS}, not {build!r}")
    why = target_missing()
    if why is not None:
        raise TargetUnavailable(why)
    w, h = size
    recorded = _trace.trace(scene, w, h, numeric=build)
    return run_trace(recorded.data, build).frame_instructions


# {====================================================================
# the report's target columns

REPORT_MAX_SIZE = (96, 72)      # an emulated float frame at this size takes a few seconds


@dataclass
class SceneCost:
    """One scene's target cost beside its host time."""

    scene: str
    host_ms: dict[str, float | None]        # per build: this host's ms per frame (None: not rendered)
    instructions: dict[str, int | None]     # per build: target instructions per frame (None: failed)
    error: str = ""

    @property
    def ratio(self) -> float | None:
        """Fixed over float target instructions (below 1: fixed is cheaper)."""
        fx, fl = self.instructions.get("fixed"), self.instructions.get("float")
        return fx / fl if fx and fl else None


def report_size(width: int, height: int) -> tuple[int, int]:
    """The size the report measures target costs at: its own, at most 96x72."""
    return min(width, REPORT_MAX_SIZE[0]), min(height, REPORT_MAX_SIZE[1])


def scene_costs(results: Any, width: int, height: int) -> list[SceneCost]:
    """Target costs of the report's scenes (``results``: (entry, Comparison)
    pairs, entry having ``name`` and ``scene``); empty when the target is missing."""
    if not target_available():
        return []
    size = report_size(width, height)
    out = []
    for entry, comp in results:
        host = {}
        for b in BUILDS:
            r = comp.renders.get(b)
            host[b] = r.time_ms if r is not None and r.times_ms else None
        counts: dict[str, int | None] = {}
        error = ""
        for b in BUILDS:
            try:
                counts[b] = target_cost(entry.scene, b, size)
            except (TargetError, ValueError, RuntimeError) as exc:   # a scene that fails is reported
                counts[b], error = None, f"{b}: {exc}"
        out.append(SceneCost(entry.name, host, counts, error))
    return out


def _cell_ms(v: float | None) -> str:
    return "–" if v is None else f"{v:.2f}"


def _cell_count(v: int | None) -> str:
    return "–" if v is None else f"{v:,}"


def _rows(costs: list[SceneCost]) -> list[list[str]]:
    return [[c.scene, _cell_ms(c.host_ms.get("fixed")), _cell_ms(c.host_ms.get("float")),
             _cell_count(c.instructions.get("fixed")), _cell_count(c.instructions.get("float")),
             "–" if c.ratio is None else f"{c.ratio:.2f}"] for c in costs]


_HEADER = ["scene", "host ms fixed", "host ms float", "target fixed (instr/frame)",
           "target float (instr/frame)", "target fixed / float"]


def report_section(results: Any, width: int, height: int,
                   costs: list[SceneCost] | None = None) -> tuple[str, str]:
    """The report's "Target cost" section, as (Markdown, HTML); `costs`, when
    given, are :func:`scene_costs` of the same results (not measured again)."""
    import html

    missing = target_missing()
    w, h = report_size(width, height)
    intro = (f"Instructions per frame on {TARGET} at {w}x{h}, counted exactly in an emulator "
             f"(docs/target.md), beside this host's time per frame. Fixed / float below 1: fixed point "
             f"runs fewer instructions where there is no FPU.")
    if missing is not None:
        md = f"\n## Target cost\n\nTarget instructions per frame: {missing}.\n"
        note = html.escape(missing)
        return md, f"<h2>Target cost</h2><p class='note'>Target instructions per frame: {note}.</p>"
    rows = _rows(scene_costs(results, width, height) if costs is None else costs)
    md_lines = ["", "## Target cost", "", intro, "", "| " + " | ".join(_HEADER) + " |",
                "|---|" + "--:|" * (len(_HEADER) - 1)]
    md_lines += ["| " + " | ".join(r) + " |" for r in rows]
    parts = ["<h2>Target cost</h2>", f"<p class='note'>{html.escape(intro)}</p>",
             "<table><tr>" + "".join(f"<th>{html.escape(c)}</th>" for c in _HEADER) + "</tr>"]
    parts += ["<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in rows]
    parts.append("</table>")
    return "\n".join(md_lines) + "\n", "\n".join(parts)
