"""Generate the trace format's call table from csrc/gles_core.h.

    python tools/gen_replay.py           # write both files
    python tools/gen_replay.py --check   # exit 1 if either is stale

Every core function that takes the context first and changes or reads GL
state gets a call id (its position in the header) and one argument code per
parameter after the context:

    i int (4 bytes)    u unsigned int (4)    b unsigned char (1)
    d double (8)       l int64_t (8)
    D const double *        a count (4) then that many doubles
    U const unsigned int *  a count (4) then that many values
    V const void *          a tagged datum: null, buffer offset, bytes, region
    N int64_t nbytes after a V or O: not stored, the replayer passes the
      length of what it hands the core
    O an output pointer: the byte size (4) of the caller's buffer

Written: csrc/replay/calls.h (the replayer's decoder, one case per call) and
src/gles/_trace_table.py (the recorder's table). The table's hash goes into
every trace header, so a trace and a replayer of different tables refuse
each other.
"""

from __future__ import annotations

import re
import sys
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEADER = ROOT / "csrc" / "gles_core.h"
C_OUT = ROOT / "csrc" / "replay" / "calls.h"
PY_OUT = ROOT / "src" / "gles" / "_trace_table.py"

# functions that take the context but neither change GL state nor set a GL
# error: queries of the framebuffer, messages and names (not recorded)
SKIP = {
    "gles_context_create", "gles_context_destroy", "gles_last_message", "gles_color_buffer",
    "gles_depth_buffer", "gles_stencil_buffer", "gles_memory_used", "gles_width", "gles_height",
    "gles_last_span_name", "gles_simd_name", "gles_GetPointer", "texture_image_bytes",
    "gles_GetBufferPointervOES", "gles_draw_size",
    # a function address, which a trace cannot carry: a replay has no
    # callback, so its messages go to the log (or the queue, if recorded on)
    "gles_DebugMessageCallbackKHR",
}

SCALARS = {"int": "i", "unsigned int": "u", "unsigned char": "b", "double": "d", "int64_t": "l"}
C_TYPES = {"i": "int", "u": "unsigned int", "b": "unsigned char", "d": "double", "l": "int64_t"}
READERS = {"i": "rd_i32", "u": "rd_u32", "b": "rd_u8", "d": "rd_f64", "l": "rd_i64"}

# the buffer binding an offset refers to, per function taking a V with an N
ARRAY_BUFFER_BINDING, ELEMENT_ARRAY_BUFFER_BINDING = 0x8894, 0x8895


def parse() -> list[tuple[str, list[tuple[str, str]]]]:
    """(name, [(code, parameter name)]) of every recorded core function."""
    text = re.sub(r"/\*.*?\*/", "", HEADER.read_text(), flags=re.S)
    out = []
    for m in re.finditer(r"^[\w ]+?[\s*]+(\w+)\(([^;]*?)\);", text, flags=re.M):
        name, params = m.group(1), " ".join(m.group(2).split())
        if name in SKIP or not params.startswith(("GlesContext *ctx", "const GlesContext *ctx")):
            continue
        args: list[tuple[str, str]] = []
        for p in params.split(",")[1:]:
            p = p.strip()
            pm = re.fullmatch(r"(const )?([\w ]+?)\s*(\*?)\s*(\w+)(\[\d+\])?", p)
            if pm is None:
                raise SystemExit(f"{name}: cannot read parameter {p!r}")
            const, ctype, star, pname, arr = pm.groups()
            pointer = bool(star or arr)
            if not pointer:
                code = SCALARS[ctype]
                if ctype == "int64_t" and pname == "nbytes" and args and args[-1][0] in "VO":
                    code = "N"
            elif not const:
                code = "O"
            else:
                code = {"double": "D", "unsigned int": "U", "void": "V"}[ctype]
            args.append((code, pname))
        out.append((name, args))
    return out


def signature_text(calls: list[tuple[str, list[tuple[str, str]]]]) -> str:
    return "\n".join(f"{name}({''.join(c for c, _ in args)})" for name, args in calls)


def table_hash(calls: list[tuple[str, list[tuple[str, str]]]]) -> int:
    return zlib.crc32(signature_text(calls).encode())


def _case(cid: int, name: str, args: list[tuple[str, str]]) -> str:
    lines = [f"    case {cid}: {{ /* {name} */"]
    call_args = ["rp->ctx"]
    names = [p for _, p in args]
    outs = 0
    for k, (code, _pname) in enumerate(args):
        v = f"a{k}"
        if code in C_TYPES:
            lines.append(f"        {C_TYPES[code]} {v} = {READERS[code]}(r);")
            call_args.append(v)
        elif code == "D":
            lines.append(f"        double {v}[16]; rd_doubles(r, {v});")
            call_args.append(v)
        elif code == "U":
            lines.append(f"        const unsigned int *{v}; uint32_t {v}_n = rd_uints(r, &{v});")
            call_args.append(v)
        elif code == "V":
            with_len = k + 1 < len(args) and args[k + 1][0] == "N"
            binding = ELEMENT_ARRAY_BUFFER_BINDING if name == "gles_DrawElements" else ARRAY_BUFFER_BINDING
            lines.append(f"        ReplayDatum {v}; rd_datum(rp, r, &{v}, {1 if with_len else 0}, "
                         f"0x{binding:04X}u, run);")
            call_args.append(f"{v}.ptr")
        elif code == "O":
            lines.append(f"        ReplayDatum {v}; rd_output(rp, r, &{v}, {outs});")
            outs += 1
            call_args.append(f"{v}.ptr")
        elif code == "N":
            call_args.append(f"a{k - 1}.nbytes")
    # counts that the core trusts: n names, size bytes of data
    for k, (code, pname) in enumerate(args):
        if code == "U" and "n" in names:
            lines.append(f"        if (a{names.index('n')} > 0 && (uint32_t)a{names.index('n')} > a{k}_n) "
                         f"rd_fail(r, \"n exceeds the names stored\");")
        if code == "O" and "n" in names and pname == "names":
            lines.append(f"        if (a{names.index('n')} > 0 && (a{k}.ptr == NULL || "
                         f"(uint64_t)a{names.index('n')} * 4u > (uint64_t)a{k}.nbytes)) "
                         f"rd_fail(r, \"n exceeds the output stored\");")
        # outputs of `count` entries (GetDebugMessageLogKHR's arrays) and of
        # buf_size bytes (its message log, GetObjectLabelKHR's label), and a
        # single int written through `length`
        if code == "O" and "count" in names and pname in ("sources", "types", "ids", "severities", "lengths"):
            lines.append(f"        if (a{k}.ptr != NULL && (uint64_t)a{names.index('count')} * 4u > "
                         f"(uint64_t)a{k}.nbytes) rd_fail(r, \"count exceeds the output stored\");")
        if code == "O" and "buf_size" in names and pname in ("message_log", "label"):
            lines.append(f"        if (a{k}.ptr != NULL && a{names.index('buf_size')} > 0 && "
                         f"(uint64_t)a{names.index('buf_size')} > (uint64_t)a{k}.nbytes) "
                         f"rd_fail(r, \"buf_size exceeds the output stored\");")
        if code == "O" and pname == "length":
            lines.append(f"        if (a{k}.ptr != NULL && a{k}.nbytes < 4) "
                         f"rd_fail(r, \"length output too small\");")
        if code == "V" and not (k + 1 < len(args) and args[k + 1][0] == "N"):
            size = next((s for s in ("size", "image_size") if s in names), None)
            if size is None:
                raise SystemExit(f"{name}: {pname} has no length")
            lines.append(f"        if (a{k}.ptr != NULL && (a{names.index(size)} < 0 || "
                         f"(uint64_t)a{names.index(size)} > (uint64_t)a{k}.nbytes)) "
                         f"rd_fail(r, \"{size} exceeds the data stored\");")
    if outs > 8:
        raise SystemExit(f"{name}: more outputs than REPLAY_OUTPUT_SLOTS (csrc/replay/replay.h)")
    lines.append("        if (r->failed || !run) break;")
    lines.append(f"        (void){name}({', '.join(call_args)});")
    lines.append("        break;")
    lines.append("    }")
    return "\n".join(lines)


def render_c(calls: list[tuple[str, list[tuple[str, str]]]]) -> str:
    cases = "\n".join(_case(i, n, a) for i, (n, a) in enumerate(calls))
    return f"""/*
** calls.h -- generated by tools/gen_replay.py from gles_core.h: do not edit.
** One case per recorded core function: read its arguments from the trace,
** then (when run is set) call it. Included by replay.c only.
*/
#define REPLAY_CALL_COUNT {len(calls)}
#define REPLAY_TABLE_HASH 0x{table_hash(calls):08X}u

static const char *const replay_call_names[REPLAY_CALL_COUNT] = {{
{chr(10).join(f'    "{n}",' for n, _ in calls)}
}};

static void replay_call(Replay *rp, Reader *r, unsigned id, int run)
{{
    switch (id) {{
{cases}
    default:
        rd_fail(r, "unknown call id");
        break;
    }}
}}
"""


def render_py(calls: list[tuple[str, list[tuple[str, str]]]]) -> str:
    rows = "\n".join(f'    "{n}": ({i}, "{"".join(c for c, _ in a)}"),' for i, (n, a) in enumerate(calls))
    return f'''"""The trace format's call table (generated by tools/gen_replay.py from
csrc/gles_core.h: do not edit): core function -> (call id, argument codes)."""

TABLE_HASH = 0x{table_hash(calls):08X}

CALLS: dict[str, tuple[int, str]] = {{
{rows}
}}
'''


def main() -> int:
    calls = parse()
    wanted = {C_OUT: render_c(calls), PY_OUT: render_py(calls)}
    if "--check" in sys.argv[1:]:
        stale = [str(p) for p, text in wanted.items() if not p.exists() or p.read_text() != text]
        if stale:
            print("stale (run python tools/gen_replay.py): " + ", ".join(stale), file=sys.stderr)
            return 1
        return 0
    for path, text in wanted.items():
        path.write_text(text)
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
