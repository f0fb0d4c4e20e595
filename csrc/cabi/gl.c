/*
** gl.c -- libGLESv1_CM: the OpenGL ES 1.1 entry points of Khronos's
** GLES/gl.h (and the OES ones of glext.h that the core implements) on the
** core library of one numeric build. Compiled once per numeric build and
** profile: GLES_CABI_COMMON is 1 for the Common profile (float commands
** exported) and 0 for Common-Lite.
**
** Every entry point acts on the calling thread's current context (set by
** eglMakeCurrent; with none, commands do nothing and queries return 0) and
** converts its arguments exactly as src/gles/gl.py does before it calls the
** same core function: a 16.16 value x becomes the double x / 65536, a float
** is widened to double, and the Get commands apply the rules of §6.1.2 to
** the values gles_get returns. The one-line entry points are generated
** (gl_entry.h, tools/gen_cabi.py); the helpers they call are below.
**
** Unlike the Python binding, C callers give no array lengths: pointers reach
** the core with length -1 (unknown), as client arrays in C always are.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* the library is built -fvisibility=hidden: the entry points take their
** (default) visibility from these declarations */
#define GL_GLEXT_PROTOTYPES 1
#pragma GCC visibility push(default)
#include <GLES/gl.h>
#include <GLES/glext.h>
#pragma GCC visibility pop
/* KHR_debug's types as GLES2/gl2ext.h declares them: the ES 1 glext.h names
** the extension only (its entry points, in gl_entry.h, are exported there) */
typedef char GLchar;
typedef void (GL_APIENTRY *GLDEBUGPROCKHR)(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                          const GLchar *message, const void *userParam);

#include "cabi/cabi.h"
#include "cabi/gl_strings.h"
#include "cabi/procs.h"

#ifndef GLES_CABI_COMMON
#error "define GLES_CABI_COMMON to 1 (Common) or 0 (Common-Lite)"
#endif

#define X(v) ((double)(v) / 65536.0)
#define B(v) ((unsigned char)((v) != 0))

enum { KIND_INT = 1, KIND_ENUM = 2, KIND_BOOL = 3, KIND_FLOAT = 4, KIND_NORM = 5 };

/* {====================================================================
** conversions of query results (those of gl.py) */

/* a real to GLint: clamped to the GLint range, NaN to 0 */
static GLint clamp_int(double v)
{
    if (v != v)
        return 0;
    if (v <= -2147483648.0)
        return INT32_MIN;
    if (v >= 2147483647.0)
        return INT32_MAX;
    return (GLint)v;
}

static GLint round_int(double v) { return clamp_int(floor(v + 0.5)); }

/* §6.1.2: [-1, 1] to the whole GLint range, ((2^32 - 1) v - 1) / 2 rounded */
static GLint norm_to_int(double v) { return clamp_int(floor((4294967295.0 * v - 1.0) / 2.0 + 0.5)); }

static GLfixed to_fixed(double v) { return clamp_int(floor(v * 65536.0 + 0.5)); }

/* run a query whose core function records a GL error but still returns a
** value: reports whether the call recorded one, keeping the spec's sticky
** first error (as gl.py's glReadPixels does) */
static unsigned int error_before(GlesContext *C) { return gles_GetError(C); }

static int error_after(GlesContext *C, unsigned int before)
{
    unsigned int err = gles_GetError(C);
    if (before || err)
        gles_set_error(C, before ? before : err);
    return err != GL_NO_ERROR;
}

/* {====================================================================
** state queries */

static void get_integerv(GlesContext *C, GLenum pname, GLint *data)
{
    double v[16];
    int kind = 0;
    int n = gles_get(C, pname, v, &kind);
    for (int i = 0; i < n; i++)
        data[i] = kind == KIND_NORM ? norm_to_int(v[i]) : round_int(v[i]);
}

static void get_fixedv(GlesContext *C, GLenum pname, GLfixed *data)
{
    double v[16];
    int kind = 0;
    int n = gles_get(C, pname, v, &kind);
    for (int i = 0; i < n; i++)
        data[i] = kind == KIND_ENUM ? clamp_int(v[i]) : to_fixed(v[i]);
}

static void get_booleanv(GlesContext *C, GLenum pname, GLboolean *data)
{
    double v[16];
    int kind = 0;
    int n = gles_get(C, pname, v, &kind);
    for (int i = 0; i < n; i++)
        data[i] = v[i] != 0 ? GL_TRUE : GL_FALSE;
}

#if GLES_CABI_COMMON
static void get_floatv(GlesContext *C, GLenum pname, GLfloat *data)
{
    double v[16];
    int kind = 0;
    int n = gles_get(C, pname, v, &kind);
    for (int i = 0; i < n; i++)
        data[i] = (GLfloat)v[i];
}
#endif

static void get_pointerv(GlesContext *C, GLenum pname, void **params)
{
    unsigned int before = error_before(C);
    uintptr_t p = gles_GetPointer(C, pname);
    if (!error_after(C, before))
        *params = (void *)p;
}

/* KHR_debug: ES 1.1 has no sync objects, so no ptr names one and the core
** takes none (INVALID_VALUE) */
static void object_ptr_label(GlesContext *C, const void *ptr, GLsizei length, const GLchar *label)
{
    (void)ptr;
    gles_ObjectPtrLabelKHR(C, length, label, -1);
}

static void get_object_ptr_label(GlesContext *C, const void *ptr, GLsizei bufSize, GLsizei *length, GLchar *label)
{
    (void)ptr;
    gles_GetObjectPtrLabelKHR(C, bufSize, length, label);
}

static const GLubyte *get_string(GlesContext *C, GLenum name)
{
    const char *s = NULL;
    switch (name) {
    case GL_VENDOR: s = "gles"; break;
    case GL_RENDERER: {
        const char *numeric = gles_numeric_name();
        s = strcmp(numeric, "fixed") == 0 ? "gles software renderer (fixed)"
          : strcmp(numeric, "float") == 0 ? "gles software renderer (float)"
          : "gles software renderer (double)";
        break;
    }
#if GLES_CABI_COMMON
    case GL_VERSION: s = "OpenGL ES-CM 1.1"; break;
    case GL_EXTENSIONS: s = GLES_CABI_EXTENSIONS_COMMON; break;
#else
    case GL_VERSION: s = "OpenGL ES-CL 1.1"; break;
    case GL_EXTENSIONS: s = GLES_CABI_EXTENSIONS_COMMON_LITE; break;
#endif
    default: gles_set_error(C, GL_INVALID_ENUM); break;
    }
    return (const GLubyte *)s;
}

static void get_clip_plane(GlesContext *C, GLenum plane, double eq[4], int *ok)
{
    unsigned int before = error_before(C);
    gles_GetClipPlane(C, plane, eq);
    *ok = !error_after(C, before);
}

static void get_clip_plane_x(GlesContext *C, GLenum plane, GLfixed *equation)
{
    double eq[4] = {0, 0, 0, 0};
    int ok;
    get_clip_plane(C, plane, eq, &ok);
    for (int i = 0; ok && i < 4; i++)
        equation[i] = to_fixed(eq[i]);
}

#if GLES_CABI_COMMON
static void get_clip_plane_f(GlesContext *C, GLenum plane, GLfloat *equation)
{
    double eq[4] = {0, 0, 0, 0};
    int ok;
    get_clip_plane(C, plane, eq, &ok);
    for (int i = 0; ok && i < 4; i++)
        equation[i] = (GLfloat)eq[i];
}
#endif

/* EXT_multi_draw_arrays: the spec's loop of DrawArrays / DrawElements over
** the lists with count > 0, up to the first draw that records a GL error or
** is refused (an array too short), as gl.py; a negative primcount is
** INVALID_VALUE (as the commands' GL 1.4 form). An error recorded before
** the call stays the first. */
/* draw list i of a multi-draw; GLES_OK or the core's refusal */
typedef int (*MultiDraw)(GlesContext *C, GLenum mode, GLsizei i, const void *lists);

typedef struct MultiArrays { const GLint *first; const GLsizei *count; } MultiArrays;
typedef struct MultiElements { const GLsizei *count; GLenum type; const void *const *indices; } MultiElements;

static int multi_arrays_draw(GlesContext *C, GLenum mode, GLsizei i, const void *lists)
{
    const MultiArrays *m = lists;
    return gles_DrawArrays(C, mode, m->first[i], m->count[i]);
}

static int multi_elements_draw(GlesContext *C, GLenum mode, GLsizei i, const void *lists)
{
    const MultiElements *m = lists;
    return gles_DrawElements(C, mode, m->count[i], m->type, m->indices[i], -1);
}

static void multi_draw(GlesContext *C, GLenum mode, const GLsizei *count, GLsizei primcount, MultiDraw draw,
                       const void *lists)
{
    if (primcount < 0) {
        gles_set_error(C, GL_INVALID_VALUE);
        return;
    }
    for (GLsizei i = 0; i < primcount; i++) {
        if (count[i] <= 0)
            continue;
        const unsigned int before = gles_GetError(C);
        const int status = draw(C, mode, i, lists);
        const unsigned int err = gles_GetError(C);
        if (before || err)
            gles_set_error(C, before ? before : err);
        if (err || status != GLES_OK)
            return;
    }
}

static void multi_draw_arrays(GlesContext *C, GLenum mode, const GLint *first, const GLsizei *count,
                              GLsizei primcount)
{
    const MultiArrays m = { first, count };
    multi_draw(C, mode, count, primcount, multi_arrays_draw, &m);
}

static void multi_draw_elements(GlesContext *C, GLenum mode, const GLsizei *count, GLenum type,
                                const void *const *indices, GLsizei primcount)
{
    const MultiElements m = { count, type, indices };
    multi_draw(C, mode, count, primcount, multi_elements_draw, &m);
}

/* OES_query_matrix: element i is mantissa[i] / 65536 * 2^exponent[i]; bit i
** of the result is set when element i is not finite (as gl.py) */
static GLbitfield query_matrix(GlesContext *C, GLfixed *mantissa, GLint *exponent)
{
    double v[16];
    int kind = 0;
    gles_get(C, GL_MATRIX_MODE, v, &kind);
    unsigned int pname = 0;
    switch ((unsigned int)v[0]) {
    case GL_MODELVIEW: pname = GL_MODELVIEW_MATRIX; break;
    case GL_PROJECTION: pname = GL_PROJECTION_MATRIX; break;
    case GL_TEXTURE: pname = GL_TEXTURE_MATRIX; break;
    default: break;
    }
    GLbitfield status = 0;
    if (pname) {
        gles_get(C, pname, v, &kind);
    } else {
        /* the palette matrix is not gettable (OES_matrix_palette) */
        for (int i = 0; i < 16; i++)
            v[i] = i % 5 == 0 ? 1.0 : 0.0;
        status = 0xFFFF;
    }
    for (int i = 0; i < 16; i++) {
        mantissa[i] = 0;
        exponent[i] = 0;
        if (!isfinite(v[i])) {
            status |= 1u << i;
            continue;
        }
        int e;
        double m = frexp(v[i], &e);
        mantissa[i] = to_fixed(m);
        exponent[i] = e;
    }
    return status;
}

/* {====================================================================
** lighting, fog, points: scalar and vector parameters */

/* how many values a vector command reads for pname: the count of a pname
** the command accepts, else 1 (the core then records INVALID_ENUM), so that
** a bad enum never reads past the one value every vector form points at */
enum { P_LIGHT, P_MATERIAL, P_LIGHT_MODEL, P_FOG, P_POINT };

static int param_count(int command, GLenum pname)
{
    switch (command) {
    case P_LIGHT:
        return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR || pname == GL_POSITION ? 4
             : pname == GL_SPOT_DIRECTION ? 3 : 1;
    case P_MATERIAL:
        return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR || pname == GL_EMISSION
                   || pname == GL_AMBIENT_AND_DIFFUSE ? 4 : 1;
    case P_LIGHT_MODEL: return pname == GL_LIGHT_MODEL_AMBIENT ? 4 : 1;
    case P_FOG: return pname == GL_FOG_COLOR ? 4 : 1;
    default: return pname == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1;
    }
}

#define PARAMS_X(buf, command, pname, params) \
    double buf[4] = {0, 0, 0, 0}; \
    for (int i_ = 0, n_ = param_count(command, pname); i_ < n_; i_++) \
        buf[i_] = X((params)[i_])
#define PARAMS_F(buf, command, pname, params) \
    double buf[4] = {0, 0, 0, 0}; \
    for (int i_ = 0, n_ = param_count(command, pname); i_ < n_; i_++) \
        buf[i_] = (double)(params)[i_]

static void light_x(GlesContext *C, GLenum light, GLenum pname, GLfixed param)
{
    double b[4] = {X(param), 0, 0, 0};
    gles_Light(C, light, pname, b, 0);
}

static void light_xv(GlesContext *C, GLenum light, GLenum pname, const GLfixed *params)
{
    PARAMS_X(b, P_LIGHT, pname, params);
    gles_Light(C, light, pname, b, 1);
}

static void light_model_x(GlesContext *C, GLenum pname, GLfixed param)
{
    double b[4] = {X(param), 0, 0, 0};
    gles_LightModel(C, pname, b, 0);
}

static void light_model_xv(GlesContext *C, GLenum pname, const GLfixed *params)
{
    PARAMS_X(b, P_LIGHT_MODEL, pname, params);
    gles_LightModel(C, pname, b, 1);
}

static void material_x(GlesContext *C, GLenum face, GLenum pname, GLfixed param)
{
    double b[4] = {X(param), 0, 0, 0};
    gles_Material(C, face, pname, b, 0);
}

static void material_xv(GlesContext *C, GLenum face, GLenum pname, const GLfixed *params)
{
    PARAMS_X(b, P_MATERIAL, pname, params);
    gles_Material(C, face, pname, b, 1);
}

static void point_parameter_x(GlesContext *C, GLenum pname, GLfixed param)
{
    double b[4] = {X(param), 0, 0, 0};
    gles_PointParameter(C, pname, b, 0);
}

static void point_parameter_xv(GlesContext *C, GLenum pname, const GLfixed *params)
{
    PARAMS_X(b, P_POINT, pname, params);
    gles_PointParameter(C, pname, b, 1);
}

/* FOG_MODE takes an enum, never scaled */
static void fog_x(GlesContext *C, GLenum pname, GLfixed param)
{
    double b[4] = {pname == GL_FOG_MODE ? (double)param : X(param), 0, 0, 0};
    gles_Fog(C, pname, b, 0);
}

static void fog_xv(GlesContext *C, GLenum pname, const GLfixed *params)
{
    if (pname == GL_FOG_MODE) {
        double b[4] = {(double)params[0], 0, 0, 0};
        gles_Fog(C, pname, b, 1);
        return;
    }
    PARAMS_X(b, P_FOG, pname, params);
    gles_Fog(C, pname, b, 1);
}

static void get_lm_x(int n, const double *v, GLfixed *params)
{
    for (int i = 0; i < n; i++)
        params[i] = to_fixed(v[i]);
}

static void get_light_x(GlesContext *C, GLenum light, GLenum pname, GLfixed *params)
{
    double v[4];
    get_lm_x(gles_GetLight(C, light, pname, v), v, params);
}

static void get_material_x(GlesContext *C, GLenum face, GLenum pname, GLfixed *params)
{
    double v[4];
    get_lm_x(gles_GetMaterial(C, face, pname, v), v, params);
}

#if GLES_CABI_COMMON
static void light_f(GlesContext *C, GLenum light, GLenum pname, GLfloat param)
{
    double b[4] = {param, 0, 0, 0};
    gles_Light(C, light, pname, b, 0);
}

static void light_fv(GlesContext *C, GLenum light, GLenum pname, const GLfloat *params)
{
    PARAMS_F(b, P_LIGHT, pname, params);
    gles_Light(C, light, pname, b, 1);
}

static void light_model_f(GlesContext *C, GLenum pname, GLfloat param)
{
    double b[4] = {param, 0, 0, 0};
    gles_LightModel(C, pname, b, 0);
}

static void light_model_fv(GlesContext *C, GLenum pname, const GLfloat *params)
{
    PARAMS_F(b, P_LIGHT_MODEL, pname, params);
    gles_LightModel(C, pname, b, 1);
}

static void material_f(GlesContext *C, GLenum face, GLenum pname, GLfloat param)
{
    double b[4] = {param, 0, 0, 0};
    gles_Material(C, face, pname, b, 0);
}

static void material_fv(GlesContext *C, GLenum face, GLenum pname, const GLfloat *params)
{
    PARAMS_F(b, P_MATERIAL, pname, params);
    gles_Material(C, face, pname, b, 1);
}

static void point_parameter_f(GlesContext *C, GLenum pname, GLfloat param)
{
    double b[4] = {param, 0, 0, 0};
    gles_PointParameter(C, pname, b, 0);
}

static void point_parameter_fv(GlesContext *C, GLenum pname, const GLfloat *params)
{
    PARAMS_F(b, P_POINT, pname, params);
    gles_PointParameter(C, pname, b, 1);
}

static void fog_f(GlesContext *C, GLenum pname, GLfloat param)
{
    double b[4] = {param, 0, 0, 0};
    gles_Fog(C, pname, b, 0);
}

static void fog_fv(GlesContext *C, GLenum pname, const GLfloat *params)
{
    if (pname == GL_FOG_MODE) {
        double b[4] = {params[0], 0, 0, 0};
        gles_Fog(C, pname, b, 1);
        return;
    }
    PARAMS_F(b, P_FOG, pname, params);
    gles_Fog(C, pname, b, 1);
}

static void get_light_f(GlesContext *C, GLenum light, GLenum pname, GLfloat *params)
{
    double v[4];
    int n = gles_GetLight(C, light, pname, v);
    for (int i = 0; i < n; i++)
        params[i] = (GLfloat)v[i];
}

static void get_material_f(GlesContext *C, GLenum face, GLenum pname, GLfloat *params)
{
    double v[4];
    int n = gles_GetMaterial(C, face, pname, v);
    for (int i = 0; i < n; i++)
        params[i] = (GLfloat)v[i];
}
#endif

/* {====================================================================
** matrices and clip planes */

static void load_matrix_x(GlesContext *C, const GLfixed *m, int mult)
{
    double d[16];
    for (int i = 0; i < 16; i++)
        d[i] = X(m[i]);
    if (mult)
        gles_MultMatrix(C, d);
    else
        gles_LoadMatrix(C, d);
}

static void clip_plane_x(GlesContext *C, GLenum plane, const GLfixed *equation)
{
    double d[4] = {X(equation[0]), X(equation[1]), X(equation[2]), X(equation[3])};
    gles_ClipPlane(C, plane, d);
}

#if GLES_CABI_COMMON
static void load_matrix_f(GlesContext *C, const GLfloat *m, int mult)
{
    double d[16];
    for (int i = 0; i < 16; i++)
        d[i] = m[i];
    if (mult)
        gles_MultMatrix(C, d);
    else
        gles_LoadMatrix(C, d);
}

static void clip_plane_f(GlesContext *C, GLenum plane, const GLfloat *equation)
{
    double d[4] = {equation[0], equation[1], equation[2], equation[3]};
    gles_ClipPlane(C, plane, d);
}
#endif

/* {====================================================================
** texture parameters and environment (gl.py's _tex_values, _tex_get):
** x forms scale the real-valued pnames, i forms map TEXTURE_ENV_COLOR like
** colours, enums and integers pass unchanged */

/* the values TexParameter*v and TexEnv*v read: 4 for the one 4-value pname
** each accepts, else 1 (as param_count) */
static int tex_parameter_count(GLenum pname) { return pname == GL_TEXTURE_CROP_RECT_OES ? 4 : 1; }

static int tex_env_count(GLenum pname) { return pname == GL_TEXTURE_ENV_COLOR ? 4 : 1; }

/* TexGen*vOES reads one value (TEXTURE_GEN_MODE_OES, an enum) */
static int tex_gen_count(GLenum pname) { (void)pname; return 1; }

static int tex_real(GLenum pname)
{
    return pname == GL_TEXTURE_ENV_COLOR || pname == GL_RGB_SCALE || pname == GL_ALPHA_SCALE
        || pname == GL_TEXTURE_LOD_BIAS_EXT || pname == GL_TEXTURE_MAX_ANISOTROPY_EXT;
}

static void tex_values_x(GLenum pname, const GLfixed *p, int n, double out[4])
{
    for (int i = 0; i < n; i++)
        out[i] = tex_real(pname) ? X(p[i]) : (double)p[i];
}

static void tex_values_i(GLenum pname, const GLint *p, int n, double out[4])
{
    for (int i = 0; i < n; i++)
        out[i] = pname == GL_TEXTURE_ENV_COLOR ? (2.0 * p[i] + 1.0) / 4294967295.0 : (double)p[i];
}

#define TEX_SETTERS(Name, core, count) \
    static void Name##_i(GlesContext *C, GLenum target, GLenum pname, GLint param) \
    { double b[4] = {0, 0, 0, 0}; tex_values_i(pname, &param, 1, b); core(C, target, pname, b, 0); } \
    static void Name##_iv(GlesContext *C, GLenum target, GLenum pname, const GLint *params) \
    { double b[4] = {0, 0, 0, 0}; tex_values_i(pname, params, count(pname), b); core(C, target, pname, b, 1); } \
    static void Name##_x(GlesContext *C, GLenum target, GLenum pname, GLfixed param) \
    { double b[4] = {0, 0, 0, 0}; tex_values_x(pname, &param, 1, b); core(C, target, pname, b, 0); } \
    static void Name##_xv(GlesContext *C, GLenum target, GLenum pname, const GLfixed *params) \
    { double b[4] = {0, 0, 0, 0}; tex_values_x(pname, params, count(pname), b); core(C, target, pname, b, 1); }

TEX_SETTERS(tex_parameter, gles_TexParameter, tex_parameter_count)
TEX_SETTERS(tex_env, gles_TexEnv, tex_env_count)
TEX_SETTERS(tex_gen, gles_TexGen, tex_gen_count)

#define TEX_GETTERS(Name, core) \
    static void Name##_i(GlesContext *C, GLenum target, GLenum pname, GLint *params) \
    { \
        double v[4]; \
        int n = core(C, target, pname, v); \
        for (int i = 0; i < n; i++) \
            params[i] = pname == GL_TEXTURE_ENV_COLOR ? norm_to_int(v[i]) : round_int(v[i]); \
    } \
    static void Name##_x(GlesContext *C, GLenum target, GLenum pname, GLfixed *params) \
    { \
        double v[4]; \
        int n = core(C, target, pname, v); \
        for (int i = 0; i < n; i++) \
            params[i] = tex_real(pname) ? to_fixed(v[i]) : clamp_int(v[i]); \
    }

TEX_GETTERS(get_tex_parameter, gles_GetTexParameter)
TEX_GETTERS(get_tex_env, gles_GetTexEnv)
TEX_GETTERS(get_tex_gen, gles_GetTexGen)

#if GLES_CABI_COMMON
#define TEX_FLOAT(Name, core, getcore, getname, count) \
    static void Name##_f(GlesContext *C, GLenum target, GLenum pname, GLfloat param) \
    { double b[4] = {param, 0, 0, 0}; core(C, target, pname, b, 0); } \
    static void Name##_fv(GlesContext *C, GLenum target, GLenum pname, const GLfloat *params) \
    { \
        double b[4] = {0, 0, 0, 0}; \
        for (int i = 0, n = count(pname); i < n; i++) \
            b[i] = params[i]; \
        core(C, target, pname, b, 1); \
    } \
    static void getname##_f(GlesContext *C, GLenum target, GLenum pname, GLfloat *params) \
    { \
        double v[4]; \
        int n = getcore(C, target, pname, v); \
        for (int i = 0; i < n; i++) \
            params[i] = (GLfloat)v[i]; \
    }

TEX_FLOAT(tex_parameter, gles_TexParameter, gles_GetTexParameter, get_tex_parameter, tex_parameter_count)
TEX_FLOAT(tex_env, gles_TexEnv, gles_GetTexEnv, get_tex_env, tex_env_count)
TEX_FLOAT(tex_gen, gles_TexGen, gles_GetTexGen, get_tex_gen, tex_gen_count)
#endif

/* {====================================================================
** the generated entry points and the lookup eglGetProcAddress uses */

#include "cabi/gl_entry.h"

static int proc_cmp(const void *key, const void *entry)
{
    return strcmp((const char *)key, ((const GlesProc *)entry)->name);
}

/* the entry point called `name` of this library, or NULL; exported under a
** name of our own for libEGL's eglGetProcAddress */
__attribute__((visibility("default"))) GlesProcFn gles_cabi_gl_proc(const char *name)
{
    if (!name)
        return NULL;
    const GlesProc *p = bsearch(name, gles_cabi_procs, sizeof gles_cabi_procs / sizeof gles_cabi_procs[0],
                                sizeof gles_cabi_procs[0], proc_cmp);
    return p ? p->fn : NULL;
}
