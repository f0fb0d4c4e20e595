"""The command table (gles.commands) against Khronos's GLES/gl.h: every ES 1.1
command exists in each profile with the C argument count, and its signature
comes from the table."""

from __future__ import annotations

import importlib.util
import inspect
import re
from pathlib import Path

import pytest

import gles
from gles import gl, mesa
from gles.commands import COMMANDS
from gles.gl import GLBase, GLCommon

ROOT = Path(__file__).resolve().parents[1]
HEADER = ROOT / "csrc" / "khronos" / "GLES" / "gl.h"


def header_prototypes() -> dict[str, list[str]]:
    """name -> the C parameter declarations of each prototype of gl.h, read here
    with a regular expression of its own."""
    out = {}
    for m in re.finditer(r"GL_API\s+[\w\s\*]+?GL_APIENTRY\s+(gl\w+)\s*\(([^)]*)\);", HEADER.read_text()):
        params = [p.strip() for p in m.group(2).split(",")]
        out[m.group(1)] = [] if params == ["void"] else params
    return out


PROTOTYPES = header_prototypes()


def load_generator():
    spec = importlib.util.spec_from_file_location("gen_commands", ROOT / "tools" / "gen_commands.py")
    gen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(gen)
    return gen


GEN = load_generator()


def test_the_header_has_every_es11_command() -> None:
    assert len(PROTOTYPES) == 145          # the ES 1.1 header's count
    assert set(PROTOTYPES) <= set(COMMANDS)


@pytest.mark.parametrize("name", sorted(PROTOTYPES))
def test_each_command_in_each_profile_with_the_c_argument_count(name: str) -> None:
    decls = PROTOTYPES[name]
    # what the caller passes: every parameter but those the command writes
    given = [d for d in decls if "*" not in d or d.startswith("const")]
    is_float = any(re.match(r"(const\s+)?GL(float|clampf)\b", d) for d in decls)
    profiles = [GLCommon] if is_float else [GLCommon, GLBase]
    assert hasattr(GLBase, name) != is_float
    for cls in profiles:
        params = list(inspect.signature(getattr(cls, name)).parameters.values())[1:]
        required = [p for p in params if p.default is inspect.Parameter.empty]
        # PyOpenGL's shorter forms (Delete* without n, BufferData without the
        # size) leave some trailing arguments optional; ReadPixels adds an optional buffer
        assert len(required) <= len(given) <= len(params), (name, given, params)
    row = COMMANDS[name]
    renamed = GEN.RENAMES.get(name, {})
    header_names = [re.findall(r"\w+", d)[-1] for d in decls]
    assert [p.name for p in row.params] == [renamed.get(n, n) for n in header_names]
    assert row.profile == ("common" if is_float else "both")


def test_plain_commands_take_the_table_signature() -> None:
    generated = [c for c in COMMANDS.values() if gl._is_plain(c)
                 and "<gles.gl" in getattr(GLCommon, c.name).__code__.co_filename]
    assert len(generated) >= 70
    for cmd in generated:
        names = list(inspect.signature(getattr(GLCommon, cmd.name)).parameters)[1:]
        assert names == [p.name for p in cmd.params], cmd.name
        assert getattr(GLCommon, cmd.name).__doc__.startswith(cmd.prototype())


def test_module_functions_and_sets_come_from_the_table() -> None:
    assert gl.COMMON_COMMANDS == sorted(COMMANDS)
    for name in COMMANDS:
        assert callable(getattr(gl, name))
    lite = gles.Context(2, 2, profile="common-lite").gl
    for name in gl.FLOAT_COMMANDS:
        assert not hasattr(lite, name)
    # the module functions show and take the table's parameter names
    frustum = [p.name for p in COMMANDS["glFrustumf"].params]
    assert list(inspect.signature(gl.glFrustumf).parameters) == frustum
    ctx = gles.Context(2, 2)
    ctx.make_current()
    try:
        gl.glTranslatef(x=1.0, y=2.0, z=3.0)
        ctx.check_errors = True
        ctx.gl.glScalef(2.0, y=1.0, z=1.0)
        assert list(gl.glGetFloatv(gl.GL_MODELVIEW_MATRIX)[3]) == [1.0, 2.0, 3.0, 1.0]
        assert list(gl.glGetFloatv(gl.GL_MODELVIEW_MATRIX)[0]) == [2.0, 0.0, 0.0, 0.0]
    finally:
        gl._set_current(None)


def test_the_mesa_peer_takes_its_es11_prototypes_from_the_table() -> None:
    core = {p.name for p in mesa._PROTOS if p.extension is None}
    assert core == {n for n, c in COMMANDS.items() if c.extension is None}


def test_the_checked_in_table_is_what_the_headers_give() -> None:
    assert (ROOT / "src" / "gles" / "commands.py").read_text() == GEN.render()


def test_range_checks_cover_every_float_argument() -> None:
    from gles import profile

    for cmd in COMMANDS.values():
        if cmd.profile == "common" and any(p.kind in ("float", "values", "values_by_pname")
                                           and "GLfloat" in p.ctype for p in cmd.params):
            assert cmd.name in profile.CHECKED_COMMANDS or cmd.name in profile.UNCHECKED_FLOAT_COMMANDS, \
                cmd.name
