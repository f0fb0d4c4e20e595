"""Generate src/gles/commands.py, the command table, from the Khronos headers.

Run: python tools/gen_commands.py [--check]

Every prototype of GLES/gl.h (OpenGL ES 1.1) and those of GLES/glext.h that
belong to the extensions gles implements become one row (KHR_debug's come
from GLES2/gl2ext.h: the ES 1 glext.h names the extension without its
commands, which the registry gives to the gles2 API only, but KHR_debug
says an ES context of any version has them with the KHR suffix): the name, the C
return type, each parameter's name (the header's, with the one-letter names
of Frustum, Ortho, DepthRange, ClearDepth and ClipPlane spelled out), C type
and kind, the profile and the extension. gles.gl builds its plain commands from the rows, profile.py finds
the real arguments to check in them, gles.mesa takes its ES 1.1 prototypes
from them, and tests/test_command_table.py holds every command of gl.h to
its row. With --check, exit 1 if the checked-in file is not what the
headers give.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEADERS = ROOT / "csrc" / "khronos" / "GLES"
OUT = ROOT / "src" / "gles" / "commands.py"

# the glext.h extensions whose commands gles implements
EXTENSIONS = (
    "GL_OES_blend_equation_separate", "GL_OES_blend_func_separate", "GL_OES_blend_subtract",
    "GL_OES_draw_texture", "GL_OES_matrix_palette", "GL_OES_query_matrix", "GL_OES_vertex_array_object",
    "GL_OES_mapbuffer", "GL_EXT_map_buffer_range", "GL_EXT_multi_draw_arrays", "GL_OES_framebuffer_object",
    "GL_EXT_discard_framebuffer", "GL_OES_texture_cube_map",
)

# commands a header lists under another extension's block than the one
# gles implements them for: OES_texture_cube_map's fixed-point forms sit in
# glext.h's OES_fixed_point block
BORROWED = {"glTexGenxOES": "GL_OES_texture_cube_map", "glTexGenxvOES": "GL_OES_texture_cube_map",
            "glGetTexGenxvOES": "GL_OES_texture_cube_map"}

# the extensions whose commands come from GLES2/gl2ext.h
GLES2_EXTENSIONS = ("GL_KHR_debug",)

PROTO = re.compile(
    r"^GL_API(?:CALL)?\s+(?P<ret>[\w\s\*]+?)\s*GL_APIENTRY\s+(?P<name>gl\w+)\s*\((?P<params>[^)]*)\);")
EXT_OPEN = re.compile(r"^#ifndef\s+(GL_[A-Z]+_\w+)\s*$")

# the header's one-letter parameter names that Python messages would show
# ("glFrustumf: f = 1e+05 ..."): spelled out, as the x forms and the spec do
_CLIP = {"l": "left", "r": "right", "b": "bottom", "t": "top", "n": "near", "f": "far"}
RENAMES = {
    **{name: _CLIP for name in ("glFrustumf", "glFrustumx", "glOrthof", "glOrthox", "glDepthRangef",
                                "glDepthRangex")},
    "glClearDepthf": {"d": "depth"}, "glClipPlanef": {"p": "plane", "eqn": "equation"},
}

# the kind of each scalar C type (value kinds the binding converts by)
SCALAR_KINDS = {
    "GLenum": "enum", "GLint": "int", "GLsizei": "sizei", "GLuint": "uint", "GLbitfield": "bitfield",
    "GLboolean": "bool", "GLubyte": "ubyte", "GLshort": "short", "GLfixed": "fixed", "GLclampx": "fixed",
    "GLfloat": "float", "GLclampf": "float", "GLintptr": "intptr", "GLsizeiptr": "sizeiptr",
    "GLDEBUGPROCKHR": "callback",
}


def kind_of(ctype: str, name: str, names: list[str]) -> str:
    """The argument kind: a scalar kind ("callback" for a GLDEBUGPROCKHR), or
    for pointers "string" (characters read), "values" (read,
    how many by pname where there is one), "data" (untyped bytes read),
    "out" (written), "out_pointer" (a pointer written) or "pointers" (a list
    of pointers read)."""
    if "*" not in ctype:
        return SCALAR_KINDS[ctype]
    if ctype.count("*") == 2:
        # const void *const *: a list of pointers read (MultiDrawElementsEXT)
        return "pointers" if ctype.startswith("const") else "out_pointer"
    if not ctype.startswith("const"):
        return "out"
    if ctype == "const GLchar*":
        return "string"
    if "void" in ctype:
        return "data"
    return "values_by_pname" if "pname" in names else "values"


Row = tuple[str, str, list[tuple[str, str]], "str | None"]


def parse(path: Path, wanted: tuple[str, ...] | None) -> list[Row]:
    """(name, return type, [(param name, C type)], extension) for each prototype."""
    out = []
    ext = None
    for line in path.read_text().splitlines():
        m = EXT_OPEN.match(line.strip())
        if m:
            ext = m.group(1)
            continue
        m = PROTO.match(line.strip())
        if not m:
            continue
        if wanted is not None and ext not in wanted and m.group("name") not in BORROWED:
            continue
        params = []
        text = m.group("params").strip()
        if text and text != "void":
            for part in text.split(","):
                pm = re.match(r"^(?P<type>.*?)(?P<name>\w+)$", part.strip())
                assert pm, part
                ctype = " ".join(pm.group("type").replace("*", " * ").split()).replace(" *", "*")
                pname = RENAMES.get(m.group("name"), {}).get(pm.group("name"), pm.group("name"))
                params.append((pname, ctype.replace("* *", "**")))
        out.append((m.group("name"), " ".join(m.group("ret").split()), params,
                    None if wanted is None else BORROWED.get(m.group("name"), ext)))
    return out


def profile_of(name: str, params: list[tuple[str, str]]) -> str:
    """"common" for the float commands (a GLfloat or GLclampf anywhere),
    "both" for the rest (Common-Lite has them too)."""
    for _, ctype in params:
        if ctype.replace("const ", "").rstrip("*") in ("GLfloat", "GLclampf"):
            return "common"
    return "both"


def render() -> str:
    rows = (parse(HEADERS / "gl.h", None) + parse(HEADERS / "glext.h", EXTENSIONS)
            + parse(HEADERS.parent / "GLES2" / "gl2ext.h", GLES2_EXTENSIONS))
    lines = [
        '"""The OpenGL ES 1.1 command table: every command gles implements, one row each.',
        "",
        "Generated by tools/gen_commands.py from csrc/khronos/GLES/gl.h and glext.h",
        "(KHR_debug from GLES2/gl2ext.h); do not edit by hand. A row gives the name, the C return type, each",
        "parameter as (name, C type, kind), the profile (\"both\", or \"common\" for",
        "the float commands Common-Lite lacks) and the extension (None for core).",
        "Kinds: enum int sizei uint bitfield bool ubyte short fixed float intptr",
        "sizeiptr, callback for scalars; string (characters read), values,",
        "values_by_pname (read; how many depends on pname), data (untyped bytes",
        "read), out and out_pointer (written).",
        '"""',
        "",
        "from __future__ import annotations",
        "",
        "from typing import NamedTuple",
        "",
        "",
        "class Param(NamedTuple):",
        "    name: str",
        "    ctype: str",
        "    kind: str",
        "",
        "",
        "class Command(NamedTuple):",
        "    name: str",
        "    ret: str",
        "    params: tuple[Param, ...]",
        "    profile: str",
        "    extension: str | None",
        "",
        "    def prototype(self) -> str:",
        '        """The C prototype, as in the header (without the API macros)."""',
        '        args = ", ".join(f"{p.ctype.rstrip(\'*\')} {p.ctype[len(p.ctype.rstrip(\'*\')):]}{p.name}"',
        '                         for p in self.params) or "void"',
        '        return f"{self.ret} {self.name}({args});"',
        "",
        "",
        "COMMANDS: dict[str, Command] = {",
    ]
    seen = set()
    for name, ret, params, ext in rows:
        if name in seen:
            continue
        seen.add(name)
        names = [p for p, _ in params]
        ps = ", ".join(f"Param({p!r}, {t!r}, {kind_of(t, p, names)!r})" for p, t in params)
        ps = f"({ps},)" if len(params) == 1 else f"({ps})"
        profile = profile_of(name, params)
        lines.append(f"    {name!r}: Command({name!r}, {ret!r}, {ps}, {profile!r}, {ext!r}),")
    lines.append("}")
    lines.append("")
    return "\n".join(lines)


def main() -> int:
    text = render()
    if "--check" in sys.argv[1:]:
        if OUT.read_text() != text:
            print(f"{OUT} is not what the headers give: run python tools/gen_commands.py", file=sys.stderr)
            return 1
        return 0
    OUT.write_text(text)
    print(f"wrote {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
