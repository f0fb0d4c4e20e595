/*
** texgen.c -- OES_texture_cube_map's texture coordinate generation
** (§2.11.4 as the extension changes it): TexGen*OES, GetTexGen*OES and
** the per-vertex (s, t, r) of the two modes, in the build's arithmetic.
** Consumes: a vertex's eye position (REFLECTION_MAP_OES) and normal.
** Produces: s, t, r before the texture matrix; q stays the vertex's.
**   NORMAL_MAP_OES      (s, t, r) = nf, the eye-space normal of §2.11.3
**   REFLECTION_MAP_OES  (s, t, r) = u - 2 nf (nf . u), u the unit vector
**                       from the eye to the vertex (SPHERE_MAP's r)
** Never does: OBJECT_LINEAR, EYE_LINEAR, SPHERE_MAP (not in ES).
*/
#include <string.h>
#include "state.h"
#include "array.h"
#include "vertex.h"
#include "texgen.h"

int texgen_any(const GlesContext *ctx)
{
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (ctx->units[u].texgen)
            return 1;
    return 0;
}

int texgen_needs_eye(const GlesContext *ctx)
{
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (ctx->units[u].texgen && ctx->units[u].texgen_mode == GL_REFLECTION_MAP_OES)
            return 1;
    return 0;
}

void texgen_coords(unsigned int mode, const NUM eye[4], const NUM nf[3], NUM tc[4])
{
    if (mode == GL_NORMAL_MAP_OES) {
        for (int k = 0; k < 3; k++)
            tc[k] = nf[k];
        return;
    }
    /* the vertex's position (divided by w, as lighting takes it) to unit
    ** length; a vertex at the eye keeps u = 0 and so r = 0 */
    NUM u[3];
    for (int k = 0; k < 3; k++)
        u[k] = eye[3] == NUM_ONE || eye[3] == NUM_ZERO ? eye[k] : num_div(eye[k], eye[3]);
    num_normalize3(u);
    const NUM d = num_dot(nf, 1, u, 1, 3);
    const NUM twice = num_add(d, d);
    for (int k = 0; k < 3; k++)
        tc[k] = num_sub(u[k], num_mul(twice, nf[k]));
}

/* {====================================================================
** TexGen*OES, GetTexGen*OES */

void gles_TexGen(GlesContext *ctx, unsigned int coord, unsigned int pname, const double *p, int vector)
{
    (void)vector;
    const unsigned int v = (unsigned int)dbl_to_i64(p[0], 0, UINT32_MAX);
    if (coord != GL_TEXTURE_GEN_STR_OES || pname != GL_TEXTURE_GEN_MODE_OES
        || (v != GL_NORMAL_MAP_OES && v != GL_REFLECTION_MAP_OES) || p[0] != (double)v) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->units[ctx->active_texture - GL_TEXTURE0].texgen_mode = v;
    /* REFLECTION_MAP_OES needs eye coordinates */
    ctx->dirty |= DIRTY_TEXTURE | DIRTY_CLIP | DIRTY_LIGHT;
}

int gles_GetTexGen(GlesContext *ctx, unsigned int coord, unsigned int pname, double *out)
{
    if (coord != GL_TEXTURE_GEN_STR_OES || pname != GL_TEXTURE_GEN_MODE_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    out[0] = ctx->units[ctx->active_texture - GL_TEXTURE0].texgen_mode;
    return 1;
}
