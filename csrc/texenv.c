/*
** texenv.c -- the texture environment's arithmetic (ES 1.1 §3.7.12,
** Tables 3.15-3.19, OES_texture_env_crossbar): REPLACE, MODULATE, DECAL,
** BLEND, ADD and COMBINE in FRAGV. The TexEnv command is texture.c's.
*/
#include "state.h"
#include "texture.h"
#include "span.h"
#include "fragment.h"   /* span_avx2.h's logic op body */

#if SIMD_X86
#pragma GCC push_options
SIMD_TARGET_AVX2
#include "span_avx2.h"
#pragma GCC pop_options
#endif

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

/* the arguments COMBINE's rgb and alpha functions read (DOT3 reads two;
** DOT3_RGBA's alpha is its rgb result, so its alpha function reads none) */
static void combine_arg_counts(const TexUnit *tu, int *nrgb, int *nalpha)
{
    const int dot3 = tu->combine_rgb == GL_DOT3_RGB || tu->combine_rgb == GL_DOT3_RGBA;
    *nrgb = dot3 ? 2 : combine_args(tu->combine_rgb);
    *nalpha = tu->combine_rgb == GL_DOT3_RGBA ? 0 : combine_args(tu->combine_alpha);
}

/* the unit's environment colour in the fragment format */
static void env_color(const TexUnit *tu, FRAGV cc[4])
{
    for (int i = 0; i < 4; i++)
        cc[i] = frag_from_num(tu->n_env_color[i]);
}

static void combine_block(const GlesContext *ctx, int u, int m, const FRAGV (*cf)[4],
                          FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4])
{
    const TexUnit *tu = &ctx->units[u];
    FRAGV cc[4];
    env_color(tu, cc);
    const int dot3 = tu->combine_rgb == GL_DOT3_RGB || tu->combine_rgb == GL_DOT3_RGBA;
    const int rgba_dot = tu->combine_rgb == GL_DOT3_RGBA;
    const int rgb_scale = scale_factor(tu->rgb_scale), alpha_scale = scale_factor(tu->alpha_scale);
    FRAGV a[3][ENV_BLOCK][4], out[ENV_BLOCK][4];
    int nrgb, nalpha;
    combine_arg_counts(tu, &nrgb, &nalpha);
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
        env_color(tu, cc);
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

#if SIMD_X86
#pragma GCC push_options
SIMD_TARGET_AVX2
/* {====================================================================
** COMBINE with a fragment's four channels in one register (V4): each
** argument is its rgb source's channels (or that source's alpha in every
** lane) with its alpha source's alpha in lane 3, complemented per lane
** where the operand says ONE_MINUS; the function then runs on all four
** lanes at once (the alpha function's result taking lane 3 where it
** differs), scaled per lane and clamped. DOT3_RGB with MODULATE alpha
** takes the DOT3 products with a bias of 0 in lane 3, which is then the
** alpha product.
**
** Exactness: the lanes are combine_block's values. In the fixed build
** every source channel x is checked to lie in [0, 2^31) (else the fragment
** goes to combine_block), so every operand (x or 2^30 - x), every
** a - 2^30/2 of DOT3 and INTERPOLATE's 2^30 - a2 lies in (-2^31, 2^31):
** vpmuldq forms frag_mul's product exactly (|a b| < 2^62), and with 2^62
** added it is positive, so a logical shift by 30 is the arithmetic one plus
** 2^32. Sums (the DOT3 sum in any order, the complement's 2^30 + 1 and
** DOT3's bias folded into one addition) are of integers that cannot
** overflow, and the scales are left shifts by 0-4 bits of values below
** 2^34 (to below 2^38). In the float and double builds the lanes take
** combine_block's IEEE operations in its order (the DOT3 sum from 0 as it
** starts, then times 4, then the scale). */

#if NUM_IS_FIXED
typedef __m256i EnvIdx;
/* frag_mul of signed lanes in (-2^31, 2^31) */
AVX2_INLINE V4 env_mul(V4 a, V4 b)
{
    const __m256i bias = _mm256_set1_epi64x(((int64_t)1 << 62) + ((int64_t)1 << 29));
    return _mm256_sub_epi64(_mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epi32(a, b), bias), 30),
                            _mm256_set1_epi64x((int64_t)1 << 32));
}
AVX2_INLINE V4 env_sub(V4 a, V4 b) { return _mm256_sub_epi64(a, b); }
/* x, or 2^30 - x = ~x + 2^30 + 1 in the lanes of mask, plus `add` (the
** offset env_offset(mask) and whatever is subtracted next, folded into one
** vector: the lanes are integers, so the order of the additions is free) */
AVX2_INLINE V4 env_offset(V4 mask) { return _mm256_and_si256(mask, _mm256_set1_epi64x(FRAG_ONE + 1)); }
AVX2_INLINE V4 env_operand(V4 x, V4 mask, V4 add) { return _mm256_add_epi64(_mm256_xor_si256(x, mask), add); }
/* the same less DOT3's bias b: `add` is env_offset(mask) - b */
AVX2_INLINE V4 env_offset_biased(V4 mask, V4 b) { return _mm256_sub_epi64(env_offset(mask), b); }
AVX2_INLINE V4 env_operand_biased(V4 x, V4 mask, V4 add) { return env_operand(x, mask, add); }
AVX2_INLINE V4 env_pick(V4 v, EnvIdx idx) { return _mm256_permutevar8x32_epi32(v, idx); }
AVX2_INLINE EnvIdx env_idx(int alpha) { return alpha ? _mm256_setr_epi32(6, 7, 6, 7, 6, 7, 6, 7) : _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7); }
AVX2_INLINE V4 env_mask(int rgb, int alpha) { return _mm256_setr_epi64x(-rgb, -rgb, -rgb, -alpha); }
/* the scales as shifts: s is log2 of each lane's factor */
AVX2_INLINE V4 env_scales(int rgb, int alpha, int extra)
{
    const int lr = rgb == 4 ? 2 : rgb - 1, la = alpha == 4 ? 2 : alpha - 1;
    return _mm256_setr_epi64x(lr + extra, lr + extra, lr + extra, la + extra);
}
AVX2_INLINE V4 env_scale(V4 v, V4 s) { return _mm256_sllv_epi64(v, s); }
/* d = p0 + p1 + p2 in every lane, then 4 d scaled (the scales carry the 4) */
AVX2_INLINE V4 env_dot3(V4 p, V4 s)
{
    const __m128i lo = _mm256_castsi256_si128(p);
    const __m128i d = _mm_add_epi64(_mm_add_epi64(lo, _mm_unpackhi_epi64(lo, lo)), _mm256_extracti128_si256(p, 1));
    return env_scale(_mm256_broadcastq_epi64(d), s);
}
/* DOT3 in lanes 0-2 and lane 3 of p, scaled: p0 + p1 + p2 in lanes 0-2
** as p + (p1 p2 p0 .) + (p2 p0 p1 .), then lane 3 of p; `s` holds the
** scales (DOT3's 4 in the rgb lanes only) */
AVX2_INLINE V4 env_dot3_alpha(V4 p, V4 s, V4 sa)
{
    (void)sa;
    const V4 d = _mm256_add_epi64(_mm256_add_epi64(p, _mm256_permute4x64_epi64(p, _MM_SHUFFLE(3, 0, 2, 1))),
                                  _mm256_permute4x64_epi64(p, _MM_SHUFFLE(3, 1, 0, 2)));
    return env_scale(v4_keep_alpha(d, p), s);
}
AVX2_INLINE int env_fits(V4 any) { return avx2_fits_u31(any); }
AVX2_INLINE V4 env_or(V4 a, V4 b) { return _mm256_or_si256(a, b); }
#else
#if defined(GLES_NUM_FLOAT)
typedef __m128i EnvIdx;
AVX2_INLINE V4 env_pick(V4 v, EnvIdx idx) { return _mm_permutevar_ps(v, idx); }
AVX2_INLINE EnvIdx env_idx(int alpha) { return alpha ? _mm_set1_epi32(3) : _mm_setr_epi32(0, 1, 2, 3); }
AVX2_INLINE V4 env_mask(int rgb, int alpha)
{
    return _mm_castsi128_ps(_mm_setr_epi32(-rgb, -rgb, -rgb, -alpha));
}
#else
typedef __m256i EnvIdx;
AVX2_INLINE V4 env_pick(V4 v, EnvIdx idx)
{
    return _mm256_castsi256_pd(_mm256_permutevar8x32_epi32(_mm256_castpd_si256(v), idx));
}
AVX2_INLINE EnvIdx env_idx(int alpha) { return alpha ? _mm256_setr_epi32(6, 7, 6, 7, 6, 7, 6, 7) : _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7); }
AVX2_INLINE V4 env_mask(int rgb, int alpha)
{
    return _mm256_castsi256_pd(_mm256_setr_epi64x(-rgb, -rgb, -rgb, -alpha));
}
#endif
AVX2_INLINE V4 env_mul(V4 a, V4 b) { return V4_OP(mul)(a, b); }
/* x, or 1 - x in the lanes of mask (the offsets are the fixed build's) */
AVX2_INLINE V4 env_offset(V4 mask) { return mask; }
AVX2_INLINE V4 env_operand(V4 x, V4 mask, V4 add)
{
    (void)add;
    return V4_OP(blendv)(x, v4_one_minus(x), mask);
}
/* the same less DOT3's bias b (`add` is b here) */
AVX2_INLINE V4 env_offset_biased(V4 mask, V4 b) { (void)mask; return b; }
AVX2_INLINE V4 env_operand_biased(V4 x, V4 mask, V4 add) { return V4_OP(sub)(env_operand(x, mask, add), add); }
AVX2_INLINE V4 env_sub(V4 a, V4 b) { return V4_OP(sub)(a, b); }
/* each lane's factor as FRAGV (combine_block's `scale *`: exact, as there) */
AVX2_INLINE V4 env_scales(int rgb, int alpha, int extra)
{
    (void)extra;
    return V4_OP(setr)((FRAGV)rgb, (FRAGV)rgb, (FRAGV)rgb, (FRAGV)alpha);
}
AVX2_INLINE V4 env_scale(V4 v, V4 s) { return V4_OP(mul)(v, s); }
/* scale * (4 * d), d the sum of lanes 0-2 in combine_block's order */
AVX2_INLINE V4 env_dot3(V4 p, V4 s) { return env_scale(V4_OP(mul)(v4_sum3(p), V4_OP(set1)(4)), s); }
/* DOT3 in lanes 0-2 (scales s) and lane 3 of p (scales sa) */
AVX2_INLINE V4 env_dot3_alpha(V4 p, V4 s, V4 sa) { return v4_keep_alpha(env_dot3(p, s), env_scale(p, sa)); }
AVX2_INLINE int env_fits(V4 any) { (void)any; return 1; }
AVX2_INLINE V4 env_or(V4 a, V4 b) { (void)b; return a; }
#endif

/* combine_fn_span's function of one fragment's arguments, unscaled */
AVX2_INLINE V4 env_fn(unsigned int fn, V4 a0, V4 a1, V4 a2)
{
    switch (fn) {
    case GL_REPLACE: return a0;
    case GL_MODULATE: return env_mul(a0, a1);
    case GL_ADD: return v4_add(a0, a1);
    case GL_ADD_SIGNED: return env_sub(v4_add(a0, a1), v4_set1(FRAG_ONE / 2));
    case GL_INTERPOLATE: return v4_add(env_mul(a0, a2), env_mul(a1, v4_one_minus(a2)));
    default: return env_sub(a0, a1); /* GL_SUBTRACT */
    }
}

/* the run's state: each argument's sources (base and stride in FRAGV per
** fragment), its channel pick and complemented lanes; the functions and scales */
typedef struct EnvRun {
    const FRAGV *rgb[3], *alpha[3];
    size_t srgb[3], salpha[3];
    EnvIdx idx[3];  /* the rgb source's channels, or its alpha in every lane */
    V4 neg[3];      /* lanes taking 1 - x */
    V4 add[3], add_b[3];    /* env_operand's offsets, without and with DOT3's bias */
    V4 scales;      /* per lane; for DOT3 the rgb lanes (and DOT3_RGBA's alpha) carry its 4 */
    V4 alpha_scales, dot3_scales;   /* ALPHA_SCALE; DOT3's rgb scales with ALPHA_SCALE */
    unsigned int fn_rgb, fn_alpha;
    int nargs, dot3, rgba_dot;
} EnvRun;

enum { ENV_ANY, ENV_MODULATE, ENV_DOT3_MODULATE };

/* argument n's source channels x of fragment j (before the operand's 1 - x) */
#define ENV_X(n) \
    v4_keep_alpha(env_pick(v4_load(r->rgb[n] + (size_t)j * r->srgb[n]), r->idx[n]), \
                  v4_load(r->alpha[n] + (size_t)j * r->salpha[n]))

/* the run's fragments; `kind` fixes the functions where it is not ENV_ANY
** (DOT3_MODULATE: DOT3_RGB with MODULATE alpha, whose alpha product is
** lane 3 of the DOT3 products when that lane's bias is 0) */
AVX2_INLINE void combine_loop(const GlesContext *ctx, int u, int m, const FRAGV (*cf)[4],
                              FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4], const EnvRun *run,
                              const int kind)
{
    const EnvRun rr = *run, *r = &rr;
    const int nargs = kind == ENV_ANY ? r->nargs : 2;
    for (int j = 0; j < m; j++) {
        const V4 x0 = ENV_X(0);
        const V4 x1 = nargs > 1 ? ENV_X(1) : x0;
        const V4 x2 = nargs > 2 ? ENV_X(2) : x0;
        if (!env_fits(env_or(env_or(x0, x1), x2))) {
            combine_block(ctx, u, 1, cf + j, ct + j, cp + j);
            continue;
        }
        V4 v;
        if (kind == ENV_DOT3_MODULATE || (kind == ENV_ANY && r->dot3)) {
            const V4 p = env_mul(env_operand_biased(x0, r->neg[0], r->add_b[0]),
                                 env_operand_biased(x1, r->neg[1], r->add_b[1]));
            if (kind == ENV_DOT3_MODULATE) {
                v = env_dot3_alpha(p, r->dot3_scales, r->alpha_scales);
            } else {
                v = env_dot3(p, r->scales);
                if (!r->rgba_dot) {
                    const V4 a0 = env_operand(x0, r->neg[0], r->add[0]);
                    const V4 a1 = env_operand(x1, r->neg[1], r->add[1]), a2 = env_operand(x2, r->neg[2], r->add[2]);
                    v = v4_keep_alpha(v, env_scale(env_fn(r->fn_alpha, a0, a1, a2), r->alpha_scales));
                }
            }
        } else if (kind == ENV_MODULATE) {
            v = env_scale(env_mul(env_operand(x0, r->neg[0], r->add[0]), env_operand(x1, r->neg[1], r->add[1])),
                          r->scales);
        } else {
            const V4 a0 = env_operand(x0, r->neg[0], r->add[0]), a1 = env_operand(x1, r->neg[1], r->add[1]);
            const V4 a2 = env_operand(x2, r->neg[2], r->add[2]);
            v = env_fn(r->fn_rgb, a0, a1, a2);
            if (r->fn_alpha != r->fn_rgb)
                v = v4_keep_alpha(v, env_fn(r->fn_alpha, a0, a1, a2));
            v = env_scale(v, r->scales);
        }
        v4_store(cp[j], v4_clamp01(v));
    }
}
#undef ENV_X

static void combine_run_avx2(const GlesContext *ctx, int u, int m, const FRAGV (*cf)[4],
                             FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4])
{
    const TexUnit *tu = &ctx->units[u];
    FRAGV cc[4];
    env_color(tu, cc);
    EnvRun r;
    r.fn_rgb = tu->combine_rgb;
    r.fn_alpha = tu->combine_alpha;
    r.dot3 = r.fn_rgb == GL_DOT3_RGB || r.fn_rgb == GL_DOT3_RGBA;
    r.rgba_dot = r.fn_rgb == GL_DOT3_RGBA;
    const int rgb_scale = scale_factor(tu->rgb_scale), alpha_scale = scale_factor(tu->alpha_scale);
    int nrgb, nalpha;
    combine_arg_counts(tu, &nrgb, &nalpha);
    r.nargs = nrgb > nalpha ? nrgb : nalpha;
    /* DOT3's bias, 0 in the alpha lane (DOT3_RGB's MODULATE alpha is then
    ** lane 3 of its products) */
    const V4 bias = v4_keep_alpha(v4_set1(FRAG_ONE / 2), v4_set1(0));
    for (int n = 0; n < 3; n++) {
        if (n >= r.nargs) {
            r.rgb[n] = r.rgb[0], r.alpha[n] = r.alpha[0];
            r.srgb[n] = r.srgb[0], r.salpha[n] = r.salpha[0];
            r.idx[n] = r.idx[0], r.neg[n] = r.neg[0];
            r.add[n] = r.add[0], r.add_b[n] = r.add_b[0];
            continue;
        }
        /* a half that the functions do not read takes the other's source */
        const int hr = n < nrgb ? 0 : 1, ha = n < nalpha ? 1 : 0;
        r.rgb[n] = combine_source(ctx, tu, u, n, hr, cf, ct, (const FRAGV (*)[4])cp, cc, &r.srgb[n]);
        r.alpha[n] = combine_source(ctx, tu, u, n, ha, cf, ct, (const FRAGV (*)[4])cp, cc, &r.salpha[n]);
        const unsigned int opr = hr ? tu->op_alpha[n] : tu->op_rgb[n];
        const unsigned int opa = ha ? tu->op_alpha[n] : tu->op_rgb[n];
        r.idx[n] = env_idx(opr == GL_SRC_ALPHA || opr == GL_ONE_MINUS_SRC_ALPHA);
        r.neg[n] = env_mask(opr == GL_ONE_MINUS_SRC_COLOR || opr == GL_ONE_MINUS_SRC_ALPHA,
                            opa == GL_ONE_MINUS_SRC_COLOR || opa == GL_ONE_MINUS_SRC_ALPHA);
        r.add[n] = env_offset(r.neg[n]);
        r.add_b[n] = env_offset_biased(r.neg[n], bias);
    }
    r.scales = env_scales(rgb_scale, alpha_scale, r.dot3 ? 2 : 0);
    r.alpha_scales = env_scales(alpha_scale, alpha_scale, 0);
    r.dot3_scales = v4_keep_alpha(r.scales, r.alpha_scales);
    if (r.fn_rgb == GL_DOT3_RGB && r.fn_alpha == GL_MODULATE)
        combine_loop(ctx, u, m, cf, ct, cp, &r, ENV_DOT3_MODULATE);
    else if (r.fn_rgb == GL_MODULATE && r.fn_alpha == GL_MODULATE)
        combine_loop(ctx, u, m, cf, ct, cp, &r, ENV_MODULATE);
    else
        combine_loop(ctx, u, m, cf, ct, cp, &r, ENV_ANY);
}

void texture_env_span_avx2(const GlesContext *ctx, int u, int n, const FRAGV (*cf)[4],
                           FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4])
{
    if (ctx->units[u].env_mode != GL_COMBINE) {
        texture_env_span(ctx, u, n, cf, ct, cp);
        return;
    }
    combine_run_avx2(ctx, u, n, cf, ct, cp);
}
/* }==================================================================== */
#pragma GCC pop_options
#endif
