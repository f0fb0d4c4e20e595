/*
** texenv.c -- the texture environment's arithmetic (ES 1.1 §3.7.12,
** Tables 3.15-3.19, OES_texture_env_crossbar): REPLACE, MODULATE, DECAL,
** BLEND, ADD and COMBINE in FRAGV. The TexEnv command is texture.c's.
*/
#include "state.h"
#include "texture.h"

/* {====================================================================
** the texture environment (§3.7.12, Tables 3.15-3.19) */

static FRAGV one_minus(FRAGV v) { return FRAG_ONE - v; }

static const FRAGV zero4[4] = { 0, 0, 0, 0 };

static int scale_factor(double scale) { return scale == 4.0 ? 4 : (scale == 2.0 ? 2 : 1); }

/* {====================================================================
** COMBINE over a run of fragments: the same arithmetic as texture_env,
** with each argument's source, operand and function chosen once */

#define ENV_BLOCK 32

/* where argument `n` of half `alpha` (0 rgb, 1 alpha) reads: a base and a
** stride in FRAGV per fragment (stride 0 for a constant) */
static const FRAGV *combine_source(const GlesContext *ctx, const TexUnit *tu, int u, int n, int alpha,
                                   const FRAGV (*cf)[4], FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4],
                                   const FRAGV (*cp)[4], const FRAGV *cc, size_t *stride)
{
    unsigned int src = alpha ? tu->src_alpha[n] : tu->src_rgb[n];
    const size_t tstride = GLES_MAX_TEXTURE_UNITS * 4;
    switch (src) {
    case GL_TEXTURE: *stride = tstride; return ct[0][u];
    case GL_CONSTANT: *stride = 0; return cc;
    case GL_PRIMARY_COLOR: *stride = 4; return cf[0];
    case GL_PREVIOUS: *stride = 4; return cp[0];
    default:
        if ((ctx->tex_units_on >> (src - GL_TEXTURE0)) & 1u) {
            *stride = tstride;
            return ct[0][src - GL_TEXTURE0];
        }
        *stride = 0;
        return zero4;
    }
}

/* one argument for fragments 0..m-1, components k0..k1-1 */
static void combine_arg_span(unsigned int op, const FRAGV *base, size_t stride, int m, int k0, int k1,
                             FRAGV (*a)[4])
{
    switch (op) {
    case GL_SRC_COLOR:
        for (int j = 0; j < m; j++)
            for (int k = k0; k < k1; k++)
                a[j][k] = base[j * stride + (size_t)k];
        break;
    case GL_ONE_MINUS_SRC_COLOR:
        for (int j = 0; j < m; j++)
            for (int k = k0; k < k1; k++)
                a[j][k] = one_minus(base[j * stride + (size_t)k]);
        break;
    case GL_SRC_ALPHA:
        for (int j = 0; j < m; j++)
            for (int k = k0; k < k1; k++)
                a[j][k] = base[j * stride + 3];
        break;
    default: /* GL_ONE_MINUS_SRC_ALPHA */
        for (int j = 0; j < m; j++)
            for (int k = k0; k < k1; k++)
                a[j][k] = one_minus(base[j * stride + 3]);
        break;
    }
}

/* the function of the combiner for fragments 0..m-1, components k0..k1-1,
** scaled by `scale` and clamped (combine_fn's arithmetic, one case a loop) */
#define COMBINE_LOOP(expr) \
    for (int j = 0; j < m; j++) \
        for (int k = k0; k < k1; k++) \
            out[j][k] = frag_clamp01(scale * (expr))
static void combine_fn_span(unsigned int fn, int scale, int m, int k0, int k1, FRAGV (*a)[ENV_BLOCK][4],
                            FRAGV (*out)[4])
{
    switch (fn) {
    case GL_REPLACE: COMBINE_LOOP(a[0][j][k]); break;
    case GL_MODULATE: COMBINE_LOOP(frag_mul(a[0][j][k], a[1][j][k])); break;
    case GL_ADD: COMBINE_LOOP(a[0][j][k] + a[1][j][k]); break;
    case GL_ADD_SIGNED: COMBINE_LOOP(a[0][j][k] + a[1][j][k] - FRAG_ONE / 2); break;
    case GL_INTERPOLATE:
        COMBINE_LOOP(frag_mul(a[0][j][k], a[2][j][k]) + frag_mul(a[1][j][k], one_minus(a[2][j][k])));
        break;
    default: COMBINE_LOOP(a[0][j][k] - a[1][j][k]); break; /* GL_SUBTRACT */
    }
}
#undef COMBINE_LOOP

static int combine_args(unsigned int fn)
{
    return fn == GL_REPLACE ? 1 : (fn == GL_INTERPOLATE ? 3 : 2);
}

static void combine_block(const GlesContext *ctx, int u, int m, const FRAGV (*cf)[4],
                          FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4])
{
    const TexUnit *tu = &ctx->units[u];
    FRAGV cc[4];
    for (int i = 0; i < 4; i++)
        cc[i] = frag_from_num(tu->n_env_color[i]);
    const int dot3 = tu->combine_rgb == GL_DOT3_RGB || tu->combine_rgb == GL_DOT3_RGBA;
    const int rgba_dot = tu->combine_rgb == GL_DOT3_RGBA;
    const int rgb_scale = scale_factor(tu->rgb_scale), alpha_scale = scale_factor(tu->alpha_scale);
    FRAGV a[3][ENV_BLOCK][4], out[ENV_BLOCK][4];
    int nrgb = dot3 ? 2 : combine_args(tu->combine_rgb);
    int nalpha = rgba_dot ? 0 : combine_args(tu->combine_alpha);
    for (int n = 0; n < 3; n++) {
        size_t stride;
        const FRAGV *base;
        if (n < nrgb) {
            base = combine_source(ctx, tu, u, n, 0, cf, ct, (const FRAGV (*)[4])cp, cc, &stride);
            combine_arg_span(tu->op_rgb[n], base, stride, m, 0, 3, a[n]);
        }
        if (n < nalpha) {
            base = combine_source(ctx, tu, u, n, 1, cf, ct, (const FRAGV (*)[4])cp, cc, &stride);
            combine_arg_span(tu->op_alpha[n], base, stride, m, 3, 4, a[n]);
        }
    }
    if (dot3) {
        /* 4 * sum((a0 - 1/2)(a1 - 1/2)) into every channel */
        for (int j = 0; j < m; j++) {
            FRAGV d = 0;
            for (int k = 0; k < 3; k++)
                d += frag_mul(a[0][j][k] - FRAG_ONE / 2, a[1][j][k] - FRAG_ONE / 2);
            FRAGV raw = 4 * d;
            out[j][0] = out[j][1] = out[j][2] = frag_clamp01(rgb_scale * raw);
            if (rgba_dot) /* §3.7.12: the alpha result takes ALPHA_SCALE, also for DOT3_RGBA */
                out[j][3] = frag_clamp01(alpha_scale * raw);
        }
    } else {
        combine_fn_span(tu->combine_rgb, rgb_scale, m, 0, 3, a, out);
    }
    if (!rgba_dot)
        combine_fn_span(tu->combine_alpha, alpha_scale, m, 3, 4, a, out);
    for (int j = 0; j < m; j++)
        for (int k = 0; k < 4; k++)
            cp[j][k] = out[j][k];
}

void texture_env(const GlesContext *ctx, int u, const FRAGV cf[4], FRAGV ct[][4], FRAGV cp[4])
{
    const TexUnit *tu = &ctx->units[u];
    const FRAGV *cs = ct[u];
    unsigned int fmt = tu->bound->format;
    FRAGV cc[4] = { 0, 0, 0, 0 };
    if (tu->env_mode == GL_BLEND || tu->env_mode == GL_COMBINE)
        for (int i = 0; i < 4; i++)
            cc[i] = frag_from_num(tu->n_env_color[i]);
    FRAGV out[4];
    switch (tu->env_mode) {
    case GL_REPLACE:
        for (int k = 0; k < 3; k++)
            out[k] = fmt == GL_ALPHA ? cp[k] : cs[k];
        out[3] = (fmt == GL_LUMINANCE || fmt == GL_RGB) ? cp[3] : cs[3];
        break;
    case GL_MODULATE:
        for (int k = 0; k < 3; k++)
            out[k] = fmt == GL_ALPHA ? cp[k] : frag_mul(cp[k], cs[k]);
        out[3] = (fmt == GL_LUMINANCE || fmt == GL_RGB) ? cp[3] : frag_mul(cp[3], cs[3]);
        break;
    case GL_DECAL:
        /* defined for RGB and RGBA; the others keep the fragment */
        for (int k = 0; k < 3; k++) {
            if (fmt == GL_RGB)
                out[k] = cs[k];
            else if (fmt == GL_RGBA)
                out[k] = frag_mul(cp[k], one_minus(cs[3])) + frag_mul(cs[k], cs[3]);
            else
                out[k] = cp[k];
        }
        out[3] = cp[3];
        break;
    case GL_BLEND:
        for (int k = 0; k < 3; k++)
            out[k] = fmt == GL_ALPHA ? cp[k] : frag_mul(cp[k], one_minus(cs[k])) + frag_mul(cc[k], cs[k]);
        out[3] = (fmt == GL_LUMINANCE || fmt == GL_RGB) ? cp[3] : frag_mul(cp[3], cs[3]);
        break;
    case GL_ADD:
        for (int k = 0; k < 3; k++)
            out[k] = fmt == GL_ALPHA ? cp[k] : frag_clamp01(cp[k] + cs[k]);
        out[3] = (fmt == GL_LUMINANCE || fmt == GL_RGB) ? cp[3] : frag_mul(cp[3], cs[3]);
        break;
    default: /* GL_COMBINE */
        combine_block(ctx, u, 1, (const FRAGV (*)[4])cf, (FRAGV (*)[GLES_MAX_TEXTURE_UNITS][4])ct, (FRAGV (*)[4])cp);
        return;
    }
    for (int k = 0; k < 4; k++)
        cp[k] = out[k];
}

void texture_env_span(const GlesContext *ctx, int u, int n, const FRAGV (*cf)[4],
                      FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4])
{
    if (ctx->units[u].env_mode != GL_COMBINE) {
        for (int j = 0; j < n; j++)
            texture_env(ctx, u, cf[j], ct[j], cp[j]);
        return;
    }
    for (int j = 0; j < n; j += ENV_BLOCK)
        combine_block(ctx, u, n - j < ENV_BLOCK ? n - j : ENV_BLOCK, cf + j, ct + j, cp + j);
}

/* }==================================================================== */
