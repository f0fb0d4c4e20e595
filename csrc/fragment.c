/*
** fragment.c -- per-fragment operation state and arithmetic (ES 1.1 §4.1).
** Owns: AlphaFunc, StencilFunc/Op/Mask, BlendFunc (and the OES separate
**       and subtract forms), LogicOp, SampleCoverage; the stencil, blend,
**       logic-op and dither arithmetic the span functions call.
** Order in a span (span.c): alpha test, stencil test, depth test, blend,
**       dither, logic op, masks.
** Colour values: framebuffer channels are integers; blending works in
**       FRAGV (num.h) so that exact 8-bit products round exactly.
*/
#include "state.h"
#include "fragment.h"
#include "texture.h"

void fragment_init(GlesContext *ctx)
{
    ctx->dither = 1;
    ctx->alpha_func = GL_ALWAYS;
    ctx->stencil_func = GL_ALWAYS;
    ctx->stencil_value_mask = 0xFFFFFFFFu;
    ctx->stencil_writemask = 0xFFFFFFFFu;
    ctx->stencil_fail = ctx->stencil_zfail = ctx->stencil_zpass = GL_KEEP;
    ctx->blend_src_rgb = ctx->blend_src_alpha = GL_ONE;
    ctx->blend_dst_rgb = ctx->blend_dst_alpha = GL_ZERO;
    ctx->blend_eq_rgb = ctx->blend_eq_alpha = GL_FUNC_ADD_OES;
    ctx->logic_op = GL_COPY;
    ctx->sample_coverage_value = 1.0;
    for (uint32_t d = 0; d < 256; d++)
        ctx->unorm8[d] = frag_from_unorm(d, 255);
    for (uint32_t d = 0; d < 32; d++)
        ctx->unorm5[d] = frag_from_unorm(d, 31);
    for (uint32_t d = 0; d < 64; d++)
        ctx->unorm6[d] = frag_from_unorm(d, 63);
    for (uint32_t d = 0; d < 16; d++)
        ctx->unorm4[d] = frag_from_unorm(d, 15);
    for (uint32_t d = 0; d < 2; d++)
        ctx->unorm1[d] = frag_from_unorm(d, 1);
}

static int is_func(unsigned int f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

/* {====================================================================
** commands */

void gles_AlphaFunc(GlesContext *ctx, unsigned int func, double ref)
{
    if (!is_func(func)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->alpha_func = func;
    ctx->alpha_ref = !(ref > 0) ? 0.0 : (ref > 1 ? 1.0 : ref);
    ctx->n_alpha_ref = num_from_double(ctx->alpha_ref);
    ctx->dirty |= DIRTY_SPAN;
}

void gles_StencilFunc(GlesContext *ctx, unsigned int func, int ref, unsigned int mask)
{
    if (!is_func(func)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->stencil_func = func;
    ctx->stencil_ref = ref;
    ctx->stencil_value_mask = mask;
    ctx->dirty |= DIRTY_SPAN;
}

static int is_stencil_op(unsigned int op)
{
    switch (op) {
    case GL_KEEP: case GL_ZERO: case GL_REPLACE: case GL_INCR: case GL_DECR: case GL_INVERT:
    case GL_INCR_WRAP_OES: case GL_DECR_WRAP_OES:
        return 1;
    default:
        return 0;
    }
}

void gles_StencilOp(GlesContext *ctx, unsigned int fail, unsigned int zfail, unsigned int zpass)
{
    if (!is_stencil_op(fail) || !is_stencil_op(zfail) || !is_stencil_op(zpass)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->stencil_fail = fail;
    ctx->stencil_zfail = zfail;
    ctx->stencil_zpass = zpass;
    ctx->dirty |= DIRTY_SPAN;
}

void gles_StencilMask(GlesContext *ctx, unsigned int mask)
{
    ctx->stencil_writemask = mask;
    ctx->dirty |= DIRTY_SPAN;
}

/* Tables 4.1 and 4.2 (GL 1.3 rules, kept by ES 1.1): the colour factors of
** the other side are not allowed on each side */
static int is_src_factor(unsigned int f)
{
    switch (f) {
    case GL_ZERO: case GL_ONE: case GL_DST_COLOR: case GL_ONE_MINUS_DST_COLOR: case GL_SRC_ALPHA:
    case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA: case GL_ONE_MINUS_DST_ALPHA: case GL_SRC_ALPHA_SATURATE:
        return 1;
    default:
        return 0;
    }
}

static int is_dst_factor(unsigned int f)
{
    switch (f) {
    case GL_ZERO: case GL_ONE: case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR: case GL_SRC_ALPHA:
    case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA: case GL_ONE_MINUS_DST_ALPHA:
        return 1;
    default:
        return 0;
    }
}

void gles_BlendFuncSeparateOES(GlesContext *ctx, unsigned int src_rgb, unsigned int dst_rgb,
                               unsigned int src_alpha, unsigned int dst_alpha)
{
    if (!is_src_factor(src_rgb) || !is_dst_factor(dst_rgb) || !is_src_factor(src_alpha)
        || !is_dst_factor(dst_alpha)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->blend_src_rgb = src_rgb;
    ctx->blend_dst_rgb = dst_rgb;
    ctx->blend_src_alpha = src_alpha;
    ctx->blend_dst_alpha = dst_alpha;
    ctx->dirty |= DIRTY_SPAN;
}

void gles_BlendFunc(GlesContext *ctx, unsigned int src, unsigned int dst)
{
    gles_BlendFuncSeparateOES(ctx, src, dst, src, dst);
}

static int is_equation(unsigned int e)
{
    return e == GL_FUNC_ADD_OES || e == GL_FUNC_SUBTRACT_OES || e == GL_FUNC_REVERSE_SUBTRACT_OES
        || e == GL_MIN_EXT || e == GL_MAX_EXT;      /* EXT_blend_minmax */
}

void gles_BlendEquationSeparateOES(GlesContext *ctx, unsigned int rgb, unsigned int alpha)
{
    if (!is_equation(rgb) || !is_equation(alpha)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->blend_eq_rgb = rgb;
    ctx->blend_eq_alpha = alpha;
    ctx->dirty |= DIRTY_SPAN;
}

void gles_BlendEquationOES(GlesContext *ctx, unsigned int mode) { gles_BlendEquationSeparateOES(ctx, mode, mode); }

void gles_LogicOp(GlesContext *ctx, unsigned int op)
{
    if (op < GL_CLEAR || op > GL_SET) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->logic_op = op;
    ctx->dirty |= DIRTY_SPAN;
}

void gles_SampleCoverage(GlesContext *ctx, double value, unsigned char invert)
{
    /* with SAMPLE_BUFFERS 0 there are no samples to cover: state only */
    ctx->sample_coverage_value = !(value > 0) ? 0.0 : (value > 1 ? 1.0 : value);
    ctx->sample_coverage_invert = invert != 0;
}

int fragment_get(GlesContext *ctx, unsigned int pname, double *out, int *kind)
{
    *kind = GLES_KIND_ENUM;
    switch (pname) {
    case GL_ALPHA_TEST_FUNC: out[0] = ctx->alpha_func; return 1;
    case GL_ALPHA_TEST_REF: *kind = GLES_KIND_NORM; out[0] = ctx->alpha_ref; return 1;
    case GL_STENCIL_FUNC: out[0] = ctx->stencil_func; return 1;
    case GL_STENCIL_FAIL: out[0] = ctx->stencil_fail; return 1;
    case GL_STENCIL_PASS_DEPTH_FAIL: out[0] = ctx->stencil_zfail; return 1;
    case GL_STENCIL_PASS_DEPTH_PASS: out[0] = ctx->stencil_zpass; return 1;
    case GL_STENCIL_REF: *kind = GLES_KIND_INT; out[0] = ctx->stencil_ref; return 1;
    case GL_STENCIL_VALUE_MASK: *kind = GLES_KIND_INT; out[0] = (double)ctx->stencil_value_mask; return 1;
    case GL_STENCIL_WRITEMASK: *kind = GLES_KIND_INT; out[0] = (double)ctx->stencil_writemask; return 1;
    case GL_BLEND_SRC: /* == GL_BLEND_SRC_RGB_OES's old name */ out[0] = ctx->blend_src_rgb; return 1;
    case GL_BLEND_DST: out[0] = ctx->blend_dst_rgb; return 1;
    case GL_BLEND_SRC_RGB_OES: out[0] = ctx->blend_src_rgb; return 1;
    case GL_BLEND_DST_RGB_OES: out[0] = ctx->blend_dst_rgb; return 1;
    case GL_BLEND_SRC_ALPHA_OES: out[0] = ctx->blend_src_alpha; return 1;
    case GL_BLEND_DST_ALPHA_OES: out[0] = ctx->blend_dst_alpha; return 1;
    case GL_BLEND_EQUATION_RGB_OES: out[0] = ctx->blend_eq_rgb; return 1;
    case GL_BLEND_EQUATION_ALPHA_OES: out[0] = ctx->blend_eq_alpha; return 1;
    case GL_LOGIC_OP_MODE: out[0] = ctx->logic_op; return 1;
    case GL_SAMPLE_COVERAGE_VALUE: *kind = GLES_KIND_FLOAT; out[0] = ctx->sample_coverage_value; return 1;
    case GL_SAMPLE_COVERAGE_INVERT: *kind = GLES_KIND_BOOL; out[0] = ctx->sample_coverage_invert; return 1;
    case GL_SAMPLE_BUFFERS: case GL_SAMPLES: *kind = GLES_KIND_INT; out[0] = 0; return 1;
    default: return 0;
    }
}

/* {====================================================================
** per-pixel arithmetic */

int fragment_alpha_pass(const GlesContext *ctx, FRAGV alpha)
{
    return fragment_compare(ctx->alpha_func, fragment_alpha8(alpha), fragment_alpha_ref8(ctx));
}

/* one blend factor for channel k (0..2 colour, 3 alpha), Table 4.1 */
static FRAGV factor(unsigned int f, int k, const FRAGV *src, const FRAGV *dst)
{
    switch (f) {
    case GL_ZERO: return 0;
    case GL_ONE: return FRAG_ONE;
    case GL_SRC_COLOR: return src[k];
    case GL_ONE_MINUS_SRC_COLOR: return FRAG_ONE - src[k];
    case GL_DST_COLOR: return dst[k];
    case GL_ONE_MINUS_DST_COLOR: return FRAG_ONE - dst[k];
    case GL_SRC_ALPHA: return src[3];
    case GL_ONE_MINUS_SRC_ALPHA: return FRAG_ONE - src[3];
    case GL_DST_ALPHA: return dst[3];
    case GL_ONE_MINUS_DST_ALPHA: return FRAG_ONE - dst[3];
    default: /* GL_SRC_ALPHA_SATURATE: min(As, 1 - Ad) for colour, 1 for alpha */
        return k == 3 ? FRAG_ONE : frag_min(src[3], FRAG_ONE - dst[3]);
    }
}

static FRAGV equation(unsigned int eq, FRAGV s, FRAGV d)
{
    if (eq == GL_FUNC_SUBTRACT_OES)
        return s - d;
    if (eq == GL_FUNC_REVERSE_SUBTRACT_OES)
        return d - s;
    return s + d;
}

void fragment_blend(const GlesContext *ctx, const FRAGV src[4], const FRAGV dst[4], FRAGV out[4])
{
    for (int k = 0; k < 4; k++) {
        int a = k == 3;
        const unsigned int eq = a ? ctx->blend_eq_alpha : ctx->blend_eq_rgb;
        /* EXT_blend_minmax: the colours themselves, no factors */
        if (eq == GL_MIN_EXT || eq == GL_MAX_EXT) {
            out[k] = (src[k] < dst[k]) == (eq == GL_MIN_EXT) ? src[k] : dst[k];
            continue;
        }
        FRAGV sf = factor(a ? ctx->blend_src_alpha : ctx->blend_src_rgb, k, src, dst);
        FRAGV df = factor(a ? ctx->blend_dst_alpha : ctx->blend_dst_rgb, k, src, dst);
        out[k] = equation(eq, frag_mul(src[k], sf), frag_mul(dst[k], df));
    }
}

/* 4x4 ordered-dither thresholds in [0, 1), centred: (b + 1/2) / 16 */
FRAGV fragment_dither_threshold(int x, int y)
{
    static const uint8_t bayer[4][4] = { { 0, 8, 2, 10 }, { 12, 4, 14, 6 }, { 3, 11, 1, 9 }, { 15, 7, 13, 5 } };
    return frag_ratio(2 * bayer[y & 3][x & 3] + 1, 32);
}

/* {====================================================================
** one fragment, every state: the reference the span chain matches */

/* One fragment through texturing, fog, coverage and the per-fragment
** operations, in the spec's order (§3.7-3.9, §4.1): the shared tail of
** every primitive's generic path. */
void fragment_process(GlesContext *ctx, int x, int y, const FragIn *in)
{
    const size_t at = (size_t)y * (size_t)ctx->width + (size_t)x;
    const unsigned int units = ctx->tex_units_on;
    FRAGV c[4];
    for (int i = 0; i < 4; i++)
        c[i] = in->c[i];
    if (units) {
        FRAGV cf[4], ct[GLES_MAX_TEXTURE_UNITS][4];
        for (int i = 0; i < 4; i++)
            cf[i] = c[i] = frag_clamp01(c[i]);
        for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
            if (units & (1u << u)) {
                const Texture *tex = ctx->units[u].bound;
                if (ctx->cube_units & (1u << u))
                    tex = tex->face[in->face[u]];
                const double bias = ctx->units[u].lod_bias;
                if (texture_needs_lod(tex))
                    texture_sample(tex, bias, &in->tc[u], &in->tdx[u], &in->tdy[u], ct[u], ctx->texel_unorm8);
                else
                    texture_sample(tex, bias, &in->tc[u], NULL, NULL, ct[u], ctx->texel_unorm8);
            }
        for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
            if (units & (1u << u))
                texture_env(ctx, u, cf, ct, c);
    }
    if (ctx->fog) {
        FRAGV fc[3];
        fragment_fog_color(ctx, fc);
        fragment_fog(c, in->fog, fc);
    }
    if (in->coverage != FRAG_ONE) /* §3.11: antialiasing scales alpha */
        c[3] = frag_mul(frag_clamp01(c[3]), in->coverage);
    if (ctx->alpha_test && !fragment_alpha_pass(ctx, c[3]))
        return;
    FragTests ft;
    fragment_tests_setup(ctx, &ft);
    if (!fragment_tests(&ft, at, in->z, ft.depth_func))
        return;
    FragWrite w;
    fragment_write_setup(ctx, &w);
    fragment_write(ctx, &w, x, y, at, c);
}
