"""Generate csrc/cabi/gl_entry.h: every GL entry point of the C ABI.

    python tools/gen_cabi.py

The prototypes come from the Khronos headers (csrc/khronos/GLES/gl.h and
glext.h); the table below says which core call each entry point makes, in
the argument conversions of src/gles/gl.py (``X(v)`` is the exact real v/65536
of a 16.16 value, ``B(v)`` a GLboolean as 0/1, ``C`` the current context).
Entries marked ``F`` are the Common profile's float commands: the generated
file guards them with ``#if GLES_CABI_COMMON``. An entry whose body is a
helper (lower-case name) calls the hand-written function of that name in
csrc/cabi/gl.c. An entry point given NULL for a pointer the command reads or
writes does nothing (NULL_OK lists the pointers that may be NULL). The file also carries the name -> function table
eglGetProcAddress uses; gl_strings.h the GL_EXTENSIONS strings of
src/gles/context.py.
"""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
KHRONOS = ROOT / "csrc" / "khronos" / "GLES"
OUT = ROOT / "csrc" / "cabi" / "gl_entry.h"
OUT_STRINGS = ROOT / "csrc" / "cabi" / "gl_strings.h"

# name  [F]  core call (an expression; `return` is added for non-void commands)
TABLE = """
glActiveTexture                 gles_ActiveTexture(C, texture)
glAlphaFunc                F    gles_AlphaFunc(C, func, ref)
glAlphaFuncx                    gles_AlphaFunc(C, func, X(ref))
glBindBuffer                    gles_BindBuffer(C, target, buffer)
glBindTexture                   gles_BindTexture(C, target, texture)
glBlendFunc                     gles_BlendFunc(C, sfactor, dfactor)
glBufferData                    gles_BufferData(C, target, (int64_t)size, data, usage)
glBufferSubData                 gles_BufferSubData(C, target, (int64_t)offset, (int64_t)size, data)
glClear                         gles_Clear(C, mask)
glClearColor               F    gles_ClearColor(C, red, green, blue, alpha)
glClearColorx                   gles_ClearColor(C, X(red), X(green), X(blue), X(alpha))
glClearDepthf              F    gles_ClearDepth(C, d)
glClearDepthx                   gles_ClearDepth(C, X(depth))
glClearStencil                  gles_ClearStencil(C, s)
glClientActiveTexture           gles_ClientActiveTexture(C, texture)
glClipPlanef               F    clip_plane_f(C, p, eqn)
glClipPlanex                    clip_plane_x(C, plane, equation)
glColor4f                  F    gles_Color4(C, red, green, blue, alpha)
glColor4ub                      gles_Color4(C, red / 255.0, green / 255.0, blue / 255.0, alpha / 255.0)
glColor4x                       gles_Color4(C, X(red), X(green), X(blue), X(alpha))
glColorMask                     gles_ColorMask(C, B(red), B(green), B(blue), B(alpha))
glColorPointer                  gles_ColorPointer(C, size, type, stride, pointer, -1)
glCompressedTexImage2D          gles_CompressedTexImage2D(C, target, level, internalformat, width, height, border, imageSize, data, -1)
glCompressedTexSubImage2D       gles_CompressedTexSubImage2D(C, target, level, xoffset, yoffset, width, height, format, imageSize, data)
glCopyTexImage2D                gles_CopyTexImage2D(C, target, level, internalformat, x, y, width, height, border)
glCopyTexSubImage2D             gles_CopyTexSubImage2D(C, target, level, xoffset, yoffset, x, y, width, height)
glCullFace                      gles_CullFace(C, mode)
glDeleteBuffers                 gles_DeleteBuffers(C, n, buffers)
glDeleteTextures                gles_DeleteTextures(C, n, textures)
glDepthFunc                     gles_DepthFunc(C, func)
glDepthMask                     gles_DepthMask(C, B(flag))
glDepthRangef              F    gles_DepthRange(C, n, f)
glDepthRangex                   gles_DepthRange(C, X(n), X(f))
glDisable                       gles_Disable(C, cap)
glDisableClientState            gles_DisableClientState(C, array)
glDrawArrays                    gles_DrawArrays(C, mode, first, count)
glDrawElements                  gles_DrawElements(C, mode, count, type, indices, -1)
glEnable                        gles_Enable(C, cap)
glEnableClientState             gles_EnableClientState(C, array)
glFinish                        gles_Finish(C)
glFlush                         gles_Flush(C)
glFogf                     F    fog_f(C, pname, param)
glFogfv                    F    fog_fv(C, pname, params)
glFogx                          fog_x(C, pname, param)
glFogxv                         fog_xv(C, pname, param)
glFrontFace                     gles_FrontFace(C, mode)
glFrustumf                 F    gles_Frustum(C, l, r, b, t, n, f)
glFrustumx                      gles_Frustum(C, X(l), X(r), X(b), X(t), X(n), X(f))
glGenBuffers                    gles_GenBuffers(C, n, buffers)
glGenTextures                   gles_GenTextures(C, n, textures)
glGetBooleanv                   get_booleanv(C, pname, data)
glGetBufferParameteriv          gles_GetBufferParameteriv(C, target, pname, params)
glGetClipPlanef            F    get_clip_plane_f(C, plane, equation)
glGetClipPlanex                 get_clip_plane_x(C, plane, equation)
glGetError                      gles_GetError(C)
glGetFixedv                     get_fixedv(C, pname, params)
glGetFloatv                F    get_floatv(C, pname, data)
glGetIntegerv                   get_integerv(C, pname, data)
glGetLightfv               F    get_light_f(C, light, pname, params)
glGetLightxv                    get_light_x(C, light, pname, params)
glGetMaterialfv            F    get_material_f(C, face, pname, params)
glGetMaterialxv                 get_material_x(C, face, pname, params)
glGetPointerv                   get_pointerv(C, pname, params)
glGetString                     get_string(C, name)
glGetTexEnvfv              F    get_tex_env_f(C, target, pname, params)
glGetTexEnviv                   get_tex_env_i(C, target, pname, params)
glGetTexEnvxv                   get_tex_env_x(C, target, pname, params)
glGetTexParameterfv        F    get_tex_parameter_f(C, target, pname, params)
glGetTexParameteriv             get_tex_parameter_i(C, target, pname, params)
glGetTexParameterxv             get_tex_parameter_x(C, target, pname, params)
glHint                          gles_Hint(C, target, mode)
glIsBuffer                      gles_IsBuffer(C, buffer)
glIsEnabled                     gles_IsEnabled(C, cap)
glIsTexture                     gles_IsTexture(C, texture)
glLightModelf              F    light_model_f(C, pname, param)
glLightModelfv             F    light_model_fv(C, pname, params)
glLightModelx                   light_model_x(C, pname, param)
glLightModelxv                  light_model_xv(C, pname, param)
glLightf                   F    light_f(C, light, pname, param)
glLightfv                  F    light_fv(C, light, pname, params)
glLightx                        light_x(C, light, pname, param)
glLightxv                       light_xv(C, light, pname, params)
glLineWidth                F    gles_LineWidth(C, width)
glLineWidthx                    gles_LineWidth(C, X(width))
glLoadIdentity                  gles_LoadIdentity(C)
glLoadMatrixf              F    load_matrix_f(C, m, 0)
glLoadMatrixx                   load_matrix_x(C, m, 0)
glLogicOp                       gles_LogicOp(C, opcode)
glMaterialf                F    material_f(C, face, pname, param)
glMaterialfv               F    material_fv(C, face, pname, params)
glMaterialx                     material_x(C, face, pname, param)
glMaterialxv                    material_xv(C, face, pname, param)
glMatrixMode                    gles_MatrixMode(C, mode)
glMultMatrixf              F    load_matrix_f(C, m, 1)
glMultMatrixx                   load_matrix_x(C, m, 1)
glMultiTexCoord4f          F    gles_MultiTexCoord4(C, target, s, t, r, q)
glMultiTexCoord4x               gles_MultiTexCoord4(C, texture, X(s), X(t), X(r), X(q))
glNormal3f                 F    gles_Normal3(C, nx, ny, nz)
glNormal3x                      gles_Normal3(C, X(nx), X(ny), X(nz))
glNormalPointer                 gles_NormalPointer(C, type, stride, pointer, -1)
glOrthof                   F    gles_Ortho(C, l, r, b, t, n, f)
glOrthox                        gles_Ortho(C, X(l), X(r), X(b), X(t), X(n), X(f))
glPixelStorei                   gles_PixelStorei(C, pname, param)
glPointParameterf          F    point_parameter_f(C, pname, param)
glPointParameterfv         F    point_parameter_fv(C, pname, params)
glPointParameterx               point_parameter_x(C, pname, param)
glPointParameterxv              point_parameter_xv(C, pname, params)
glPointSize                F    gles_PointSize(C, size)
glPointSizePointerOES           gles_PointSizePointerOES(C, type, stride, pointer, -1)
glPointSizex                    gles_PointSize(C, X(size))
glPolygonOffset            F    gles_PolygonOffset(C, factor, units)
glPolygonOffsetx                gles_PolygonOffset(C, X(factor), X(units))
glPopMatrix                     gles_PopMatrix(C)
glPushMatrix                    gles_PushMatrix(C)
glReadPixels                    gles_ReadPixels(C, x, y, width, height, format, type, pixels, INT64_MAX)
glRotatef                  F    gles_Rotate(C, angle, x, y, z)
glRotatex                       gles_Rotate(C, X(angle), X(x), X(y), X(z))
glSampleCoverage           F    gles_SampleCoverage(C, value, B(invert))
glSampleCoveragex               gles_SampleCoverage(C, X(value), B(invert))
glScalef                   F    gles_Scale(C, x, y, z)
glScalex                        gles_Scale(C, X(x), X(y), X(z))
glScissor                       gles_Scissor(C, x, y, width, height)
glShadeModel                    gles_ShadeModel(C, mode)
glStencilFunc                   gles_StencilFunc(C, func, ref, mask)
glStencilMask                   gles_StencilMask(C, mask)
glStencilOp                     gles_StencilOp(C, fail, zfail, zpass)
glTexCoordPointer               gles_TexCoordPointer(C, size, type, stride, pointer, -1)
glTexEnvf                  F    tex_env_f(C, target, pname, param)
glTexEnvfv                 F    tex_env_fv(C, target, pname, params)
glTexEnvi                       tex_env_i(C, target, pname, param)
glTexEnviv                      tex_env_iv(C, target, pname, params)
glTexEnvx                       tex_env_x(C, target, pname, param)
glTexEnvxv                      tex_env_xv(C, target, pname, params)
glTexImage2D                    gles_TexImage2D(C, target, level, internalformat, width, height, border, format, type, pixels, -1)
glTexParameterf            F    tex_parameter_f(C, target, pname, param)
glTexParameterfv           F    tex_parameter_fv(C, target, pname, params)
glTexParameteri                 tex_parameter_i(C, target, pname, param)
glTexParameteriv                tex_parameter_iv(C, target, pname, params)
glTexParameterx                 tex_parameter_x(C, target, pname, param)
glTexParameterxv                tex_parameter_xv(C, target, pname, params)
glTexSubImage2D                 gles_TexSubImage2D(C, target, level, xoffset, yoffset, width, height, format, type, pixels, -1)
glTranslatef               F    gles_Translate(C, x, y, z)
glTranslatex                    gles_Translate(C, X(x), X(y), X(z))
glVertexPointer                 gles_VertexPointer(C, size, type, stride, pointer, -1)
glViewport                      gles_Viewport(C, x, y, width, height)
glBlendEquationOES              gles_BlendEquationOES(C, mode)
glBlendEquationSeparateOES      gles_BlendEquationSeparateOES(C, modeRGB, modeAlpha)
glBlendFuncSeparateOES          gles_BlendFuncSeparateOES(C, srcRGB, dstRGB, srcAlpha, dstAlpha)
glCurrentPaletteMatrixOES       gles_CurrentPaletteMatrixOES(C, matrixpaletteindex)
glDrawTexfOES              F    gles_DrawTexOES(C, x, y, z, width, height)
glDrawTexfvOES             F    gles_DrawTexOES(C, coords[0], coords[1], coords[2], coords[3], coords[4])
glDrawTexiOES                   gles_DrawTexOES(C, x, y, z, width, height)
glDrawTexivOES                  gles_DrawTexOES(C, coords[0], coords[1], coords[2], coords[3], coords[4])
glDrawTexsOES                   gles_DrawTexOES(C, x, y, z, width, height)
glDrawTexsvOES                  gles_DrawTexOES(C, coords[0], coords[1], coords[2], coords[3], coords[4])
glDrawTexxOES                   gles_DrawTexOES(C, X(x), X(y), X(z), X(width), X(height))
glDrawTexxvOES                  gles_DrawTexOES(C, X(coords[0]), X(coords[1]), X(coords[2]), X(coords[3]), X(coords[4]))
glLoadPaletteFromModelViewMatrixOES  gles_LoadPaletteFromModelViewMatrixOES(C)
glMatrixIndexPointerOES         gles_MatrixIndexPointerOES(C, size, type, stride, pointer, -1)
glQueryMatrixxOES               query_matrix(C, mantissa, exponent)
glWeightPointerOES              gles_WeightPointerOES(C, size, type, stride, pointer, -1)
glBindVertexArrayOES            gles_BindVertexArrayOES(C, array)
glDeleteVertexArraysOES         gles_DeleteVertexArraysOES(C, n, arrays)
glGenVertexArraysOES            gles_GenVertexArraysOES(C, n, arrays)
glIsVertexArrayOES              gles_IsVertexArrayOES(C, array)
glMapBufferOES                  gles_MapBufferOES(C, target, access)
glUnmapBufferOES                gles_UnmapBufferOES(C, target)
glGetBufferPointervOES          gles_GetBufferPointervOES(C, target, pname, params)
glMapBufferRangeEXT             gles_MapBufferRangeEXT(C, target, (int64_t)offset, (int64_t)length, access)
glFlushMappedBufferRangeEXT     gles_FlushMappedBufferRangeEXT(C, target, (int64_t)offset, (int64_t)length)
glMultiDrawArraysEXT            multi_draw_arrays(C, mode, first, count, primcount)
glMultiDrawElementsEXT          multi_draw_elements(C, mode, count, type, indices, primcount)
glGenFramebuffersOES            gles_GenFramebuffersOES(C, n, framebuffers)
glGenRenderbuffersOES           gles_GenRenderbuffersOES(C, n, renderbuffers)
glBindFramebufferOES            gles_BindFramebufferOES(C, target, framebuffer)
glBindRenderbufferOES           gles_BindRenderbufferOES(C, target, renderbuffer)
glDeleteFramebuffersOES         gles_DeleteFramebuffersOES(C, n, framebuffers)
glDeleteRenderbuffersOES        gles_DeleteRenderbuffersOES(C, n, renderbuffers)
glIsFramebufferOES              gles_IsFramebufferOES(C, framebuffer)
glIsRenderbufferOES             gles_IsRenderbufferOES(C, renderbuffer)
glRenderbufferStorageOES        gles_RenderbufferStorageOES(C, target, internalformat, width, height)
glFramebufferTexture2DOES       gles_FramebufferTexture2DOES(C, target, attachment, textarget, texture, level)
glFramebufferRenderbufferOES    gles_FramebufferRenderbufferOES(C, target, attachment, renderbuffertarget, renderbuffer)
glCheckFramebufferStatusOES     gles_CheckFramebufferStatusOES(C, target)
glGetFramebufferAttachmentParameterivOES  gles_GetFramebufferAttachmentParameterivOES(C, target, attachment, pname, params)
glGetRenderbufferParameterivOES  gles_GetRenderbufferParameterivOES(C, target, pname, params)
glGenerateMipmapOES             gles_GenerateMipmapOES(C, target)
glDiscardFramebufferEXT         gles_DiscardFramebufferEXT(C, target, numAttachments, attachments)
glTexGenfOES               F    tex_gen_f(C, coord, pname, param)
glTexGenfvOES              F    tex_gen_fv(C, coord, pname, params)
glTexGeniOES                    tex_gen_i(C, coord, pname, param)
glTexGenivOES                   tex_gen_iv(C, coord, pname, params)
glTexGenxOES                    tex_gen_x(C, coord, pname, param)
glTexGenxvOES                   tex_gen_xv(C, coord, pname, params)
glGetTexGenfvOES           F    get_tex_gen_f(C, coord, pname, params)
glGetTexGenivOES                get_tex_gen_i(C, coord, pname, params)
glGetTexGenxvOES                get_tex_gen_x(C, coord, pname, params)
glDebugMessageControlKHR        gles_DebugMessageControlKHR(C, source, type, severity, count, ids, B(enabled))
glDebugMessageInsertKHR         gles_DebugMessageInsertKHR(C, source, type, id, severity, length, buf, -1)
glDebugMessageCallbackKHR       gles_DebugMessageCallbackKHR(C, (GlesDebugProc)callback, userParam)
glGetDebugMessageLogKHR         gles_GetDebugMessageLogKHR(C, count, bufSize, sources, types, ids, severities, lengths, messageLog)
glPushDebugGroupKHR             gles_PushDebugGroupKHR(C, source, id, length, message, -1)
glPopDebugGroupKHR              gles_PopDebugGroupKHR(C)
glObjectLabelKHR                gles_ObjectLabelKHR(C, identifier, name, length, label, -1)
glGetObjectLabelKHR             gles_GetObjectLabelKHR(C, identifier, name, bufSize, length, label)
glObjectPtrLabelKHR             object_ptr_label(C, ptr, length, label)
glGetObjectPtrLabelKHR          get_object_ptr_label(C, ptr, bufSize, length, label)
glGetPointervKHR                get_pointerv(C, pname, params)
"""

# Pointer arguments a C caller may pass as NULL: the core gives NULL its
# meaning (no data yet, or offset 0 in a buffer object). Any other pointer
# argument is checked: with it NULL the entry point does nothing, since NULL
# is the one bad pointer C can recognise. KHR_debug gives NULL a meaning
# for most of its pointers (no IDs, no callback, no label, outputs not wanted).
NULL_OK: dict[str, str | tuple[str, ...]] = {
    "glBufferData": "data",
    "glBufferSubData": "data",
    "glTexImage2D": "pixels",
    "glTexSubImage2D": "pixels",
    "glCompressedTexImage2D": "data",
    "glCompressedTexSubImage2D": "data",
    "glDrawElements": "indices",
    "glColorPointer": "pointer",
    "glNormalPointer": "pointer",
    "glPointSizePointerOES": "pointer",
    "glTexCoordPointer": "pointer",
    "glVertexPointer": "pointer",
    "glMatrixIndexPointerOES": "pointer",
    "glWeightPointerOES": "pointer",
    "glDebugMessageControlKHR": ("ids",),
    "glDebugMessageCallbackKHR": ("callback", "userParam"),
    "glGetDebugMessageLogKHR": ("sources", "types", "ids", "severities", "lengths", "messageLog"),
    "glObjectLabelKHR": ("label",),
    "glGetObjectLabelKHR": ("length", "label"),
    "glObjectPtrLabelKHR": ("ptr", "label"),
    "glGetObjectPtrLabelKHR": ("ptr", "length", "label"),
}


def null_ok(name: str) -> tuple[str, ...]:
    """The pointer arguments of command `name` that may be NULL."""
    v = NULL_OK.get(name, ())
    return (v,) if isinstance(v, str) else v

_PROTO_RE = re.compile(r"^GL_API(?:CALL)?\s+(?P<ret>[^\n]*?)\s*GL_APIENTRY\s+(?P<name>gl\w+)\s*\((?P<args>[^)]*)\);", re.M)


def prototypes() -> dict[str, tuple[str, str, list[str]]]:
    """name -> (return type, argument list text, argument names) from gl.h and
    glext.h, and KHR_debug's from GLES2/gl2ext.h (the ES 1 glext.h names the
    extension only; gl.c declares its GLDEBUGPROCKHR)."""
    out: dict[str, tuple[str, str, list[str]]] = {}
    texts = [(KHRONOS / header).read_text() for header in ("gl.h", "glext.h")]
    gl2ext = (KHRONOS.parent / "GLES2" / "gl2ext.h").read_text()
    start = gl2ext.index("#ifndef GL_KHR_debug\n")
    texts.append(gl2ext[start:gl2ext.index("#endif /* GL_KHR_debug */", start)])
    for text in texts:
        for m in _PROTO_RE.finditer(text):
            args = m.group("args").strip()
            names = [] if args == "void" else [re.findall(r"\w+", a)[-1] for a in args.split(",")]
            out.setdefault(m.group("name"), (m.group("ret"), args, names))
    return out


def extensions() -> dict[str, str]:
    """The GL_EXTENSIONS strings of src/gles/context.py, per profile."""
    tree = ast.parse((ROOT / "src" / "gles" / "context.py").read_text())
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "EXTENSION_PROFILES" for t in node.targets):
            value = ast.literal_eval(node.value)
            return {p: " ".join(e for e, where in value.items() if where in ("both", p))
                    for p in ("common", "common-lite")}
    raise SystemExit("src/gles/context.py has no EXTENSION_PROFILES table")


def rows() -> list[tuple[str, bool, str]]:
    """The table as (name, Common only, core call)."""
    out = []
    for line in TABLE.strip().splitlines():
        m = re.match(r"(\w+)\s+(F\s+)?(.*)$", line.strip())
        if m is None:
            raise SystemExit(f"bad table line: {line!r}")
        out.append((m.group(1), bool(m.group(2)), m.group(3).strip()))
    return out


def generate() -> str:
    """The text of gl_entry.h."""
    protos = prototypes()
    table = rows()
    names = {r[0] for r in table}
    unknown = sorted(names - set(protos))
    if unknown:
        raise SystemExit(f"no Khronos prototype for: {', '.join(unknown)}")
    es11 = {m.group("name") for m in _PROTO_RE.finditer((KHRONOS / "gl.h").read_text())}
    declared = es11 | {m.group("name") for m in _PROTO_RE.finditer((KHRONOS / "glext.h").read_text())}
    uncovered = sorted(es11 - names)
    if uncovered:
        raise SystemExit(f"GLES/gl.h commands without a table entry: {', '.join(uncovered)}")
    lines = [
        "/* gl_entry.h -- generated by tools/gen_cabi.py from its table and the Khronos",
        "** headers; do not edit. Included once by csrc/cabi/gl.c. */",
        "",
    ]
    for name, common_only, body in table:
        ret, args, params = protos[name]
        # every name the call uses is an argument of the command (or C, X, B)
        for arg in re.findall(r"\b[A-Za-z_]\w*\b", re.sub(r"\w+\s*\(", "", body)):
            if arg not in params and arg not in {"C", "X", "B", "int64_t", "INT64_MAX", "GlesDebugProc"}:
                raise SystemExit(f"{name}: {arg!r} is not one of its arguments {params}")
        pointers = [p for p, a in zip(params, args.split(","))
                    if ("*" in a or "GLDEBUGPROCKHR" in a) and p not in null_ok(name)]
        ready = " && ".join(["C"] + pointers)
        if common_only:
            lines.append("#if GLES_CABI_COMMON")
        if name not in declared:
            # no declaration in the ES 1 headers (KHR_debug): exported here
            lines.append("#pragma GCC visibility push(default)")
        lines.append(f"GL_API {ret} GL_APIENTRY {name} ({args})")
        lines.append("{")
        lines.append("    GlesContext *C = gles_cabi_current();")
        if ret == "void":
            lines.append(f"    if ({ready})")
            lines.append(f"        {body};")
        else:
            lines.append(f"    return {ready} ? ({ret})({body}) : 0;")
        lines.append("}")
        if name not in declared:
            lines.append("#pragma GCC visibility pop")
        if common_only:
            lines.append("#endif")
        lines.append("")
    lines.append("/* every entry point by name, for eglGetProcAddress (sorted for bsearch) */")
    lines.append("static const GlesProc gles_cabi_procs[] = {")
    for name, common_only, _ in sorted(table):
        if common_only:
            lines.append("#if GLES_CABI_COMMON")
        lines.append(f'    {{"{name}", (GlesProcFn){name}}},')
        if common_only:
            lines.append("#endif")
    lines.append("};")
    return "\n".join(lines) + "\n"


def generate_strings() -> str:
    """The text of gl_strings.h."""
    ext = extensions()
    return ("/* gl_strings.h -- generated by tools/gen_cabi.py from src/gles/context.py; do not edit */\n"
            f'#define GLES_CABI_EXTENSIONS_COMMON "{ext["common"]}"\n'
            f'#define GLES_CABI_EXTENSIONS_COMMON_LITE "{ext["common-lite"]}"\n')


def main() -> int:
    outputs = {OUT: generate(), OUT_STRINGS: generate_strings()}
    if "--check" in sys.argv:
        stale = [str(p) for p, text in outputs.items() if not p.exists() or p.read_text() != text]
        for p in stale:
            print(f"{p} is out of date: run python tools/gen_cabi.py", file=sys.stderr)
        return 1 if stale else 0
    for p, text in outputs.items():
        p.write_text(text)
        print(f"wrote {p}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
