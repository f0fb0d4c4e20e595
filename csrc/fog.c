/*
** fog.c -- fog (ES 1.1 §3.8).
** Owns: Fog state; the fog factor f (LINEAR, EXP, EXP2) of an eye distance.
** The distance is |z_eye|, which the spec allows in place of the true
** eye distance. FOG_HINT NICEST evaluates f per fragment from the
** perspective-correct interpolated distance; otherwise f is computed per
** vertex and interpolated. The fixed build's exp is exp2 of a 0.30 argument
** (num_exp_neg), accurate to about half an LSB of 16.16.
*/
#include "state.h"
#include "fragment.h"

void fog_init(GlesContext *ctx)
{
    ctx->fog_mode = GL_EXP;
    ctx->fog_density = 1.0;
    ctx->fog_end = 1.0;
    ctx->n_fog_density = NUM_ONE;
    ctx->n_fog_end = NUM_ONE;
}

void gles_Fog(GlesContext *ctx, unsigned int pname, const double *p, int vector)
{
    switch (pname) {
    case GL_FOG_MODE: {
        unsigned int mode = (unsigned int)dbl_to_i64(p[0], 0, UINT32_MAX);
        if (mode != GL_LINEAR && mode != GL_EXP && mode != GL_EXP2) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        ctx->fog_mode = mode;
        break;
    }
    case GL_FOG_DENSITY:
        if (!(p[0] >= 0)) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        ctx->fog_density = p[0];
        ctx->n_fog_density = num_from_double(p[0]);
        break;
    case GL_FOG_START:
        ctx->fog_start = p[0];
        ctx->n_fog_start = num_from_double(p[0]);
        break;
    case GL_FOG_END:
        ctx->fog_end = p[0];
        ctx->n_fog_end = num_from_double(p[0]);
        break;
    case GL_FOG_COLOR:
        if (!vector) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        ctx_set_clamped_color(ctx->fog_color, ctx->n_fog_color, p);
        break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->dirty |= DIRTY_SPAN;
}

int fog_get(GlesContext *ctx, unsigned int pname, double *out, int *kind)
{
    switch (pname) {
    case GL_FOG_MODE: *kind = GLES_KIND_ENUM; out[0] = ctx->fog_mode; return 1;
    case GL_FOG_DENSITY: *kind = GLES_KIND_FLOAT; out[0] = ctx->fog_density; return 1;
    case GL_FOG_START: *kind = GLES_KIND_FLOAT; out[0] = ctx->fog_start; return 1;
    case GL_FOG_END: *kind = GLES_KIND_FLOAT; out[0] = ctx->fog_end; return 1;
    case GL_FOG_COLOR:
        *kind = GLES_KIND_NORM;
        for (int i = 0; i < 4; i++)
            out[i] = ctx->fog_color[i];
        return 4;
    default: return 0;
    }
}

void fog_validate(GlesContext *ctx)
{
    ctx->fog_per_fragment = ctx->fog && ctx->hints[3] == GL_NICEST;
    NUM range = num_sub(ctx->n_fog_end, ctx->n_fog_start);
    /* end == start: LINEAR is undefined; a step at the end is the limit */
    ctx->n_fog_scale = range == NUM_ZERO ? NUM_MAX : num_recip(range);
}

NUM fog_factor(const GlesContext *ctx, NUM c)
{
    NUM f;
    switch (ctx->fog_mode) {
    case GL_LINEAR:
        f = num_mul(num_sub(ctx->n_fog_end, c), ctx->n_fog_scale);
        break;
    case GL_EXP:
        f = num_exp_neg(num_mul(ctx->n_fog_density, c));
        break;
    default: { /* GL_EXP2 */
        NUM dc = num_mul(ctx->n_fog_density, c);
        f = num_exp_neg(num_mul(dc, dc));
        break;
    }
    }
    return num_clamp01(f);
}

NUM fog_vertex_value(const GlesContext *ctx, const NUM eye[4])
{
    NUM z = eye[2];
    if (eye[3] != NUM_ONE && eye[3] != NUM_ZERO)
        z = num_div(z, eye[3]);
    NUM c = num_abs(z);
    return ctx->fog_per_fragment ? c : fog_factor(ctx, c);
}
