/*
** texsample.c -- texture sampling (ES 1.1 §3.7.7-3.7.8).
** Consumes: a complete texture and coordinates after the division by q.
** Produces: the filtered texel as RGBA in FRAGV.
** REPEAT wraps the coordinate exactly before it is scaled to texel space,
** so large coordinates never overflow; the level of detail uses
** rho = max(|du/dx|, |du/dy|, |dv/dx|, |dv/dy|), the lower bound the spec
** allows, from the coordinates one pixel right and up: a triangle's or
** line's along the weights' tangents (wgt_tangent), so the differences are
** the derivatives at the fragment; a rectangle's at the next pixels.
*/
#include "state.h"
#include "texture.h"
#include "span.h"
#include "fragment.h"   /* span_avx2.h's logic op body */

/* the most fragments lod_block takes at once (lod_blocks gives it a chunk
** in such pieces) */
#define SPAN_SAMPLE_MAX 64

#if SIMD_X86
#pragma GCC push_options
SIMD_TARGET_AVX2
#include "span_avx2.h"
#pragma GCC pop_options
#if SIMD_AVX512_INSTANCE
#pragma GCC push_options
SIMD_TARGET_AVX512
#include "span_avx512.h"
#pragma GCC pop_options
#endif
#if SIMD_AVX512_FX
#pragma GCC push_options
SIMD_TARGET_AVX512
#include "span_fx512.h"
#pragma GCC pop_options
#endif
#endif

/* i mod m in [0, m): a mask for a power of two, else a division
** (OES_texture_npot sizes) */
static inline int64_t wrap_mod(int64_t i, int64_t m)
{
    if ((m & (m - 1)) == 0)
        return i & (m - 1);
    const int64_t r = i % m;
    return r < 0 ? r + m : r;
}

/* wrap a texel index into [0, n) */
static inline int wrap_index(int64_t i, int n, unsigned int mode)
{
    switch (mode) {
    case GL_REPEAT:
        return (int)wrap_mod(i, n);
    case GL_MIRRORED_REPEAT_OES: {
        int64_t r = wrap_mod(i, 2 * (int64_t)n);
        return (int)(r < n ? r : 2 * (int64_t)n - 1 - r);
    }
    default: /* GL_CLAMP_TO_EDGE */
        return (int)(i < 0 ? 0 : (i >= n ? n - 1 : i));
    }
}

/* the coordinate reduced before scaling: REPEAT keeps the fraction, the
** mirror folds into [0, 2), CLAMP_TO_EDGE leaves it (indices clamp) */
static inline TEXC reduce_coord(TEXC s, unsigned int mode)
{
    if (mode == GL_REPEAT)
        return s - texc_floor(s);
    if (mode == GL_MIRRORED_REPEAT_OES)
        return s - 2 * texc_floor(s / 2);   /* [0, 2): indices mirror past 1 */
    /* clamp far values so scaling by the size cannot overflow */
    if (s < -TEXC_ONE)
        return -TEXC_ONE;
    if (s > 2 * TEXC_ONE)
        return 2 * TEXC_ONE;
    return s;
}

static inline void texel(const TexImage *li, int i, int j, FRAGV out[4], const FRAGV *unorm)
{
    uint32_t c = li->texels[(size_t)j * li->width + i];
    out[0] = unorm[c & 0xFF];
    out[1] = unorm[(c >> 8) & 0xFF];
    out[2] = unorm[(c >> 16) & 0xFF];
    out[3] = unorm[c >> 24];
}

/* The sampling functions take the wrap modes as arguments so that the
** span samplers below can pass constants and have the switches folded;
** always inlined for that reason. */
#define SAMPLE_INLINE static inline __attribute__((always_inline))

SAMPLE_INLINE void sample_level(const Texture *t, int level, unsigned int filter, TEXC s, TEXC tc, FRAGV out[4],
                                  const FRAGV *unorm, unsigned int ws, unsigned int wt, int simd)
{
    const TexImage *li = &t->level[level];
    int w = li->width, h = li->height;
    TEXC u = texc_scale(reduce_coord(s, ws), w);
    TEXC v = texc_scale(reduce_coord(tc, wt), h);
    if (filter == GL_NEAREST) {
        /* §3.7.7: i = floor(u), wrapped (CLAMP_TO_EDGE clamps to [0, n-1]) */
        texel(li, wrap_index(texc_ifloor(u), w, ws), wrap_index(texc_ifloor(v), h, wt), out, unorm);
        return;
    }
    TEXC uu = u - TEXC_HALF, vv = v - TEXC_HALF;
    int64_t i0 = texc_ifloor(uu), j0 = texc_ifloor(vv);
    TEXW a = texc_frac_weight(uu), b = texc_frac_weight(vv);
    int x0 = wrap_index(i0, w, ws), x1 = wrap_index(i0 + 1, w, ws);
    int y0 = wrap_index(j0, h, wt), y1 = wrap_index(j0 + 1, h, wt);
    const uint32_t *r0 = li->texels + (size_t)y0 * w, *r1 = li->texels + (size_t)y1 * w;
#if SIMD_X86
    if (simd) {
        avx2_bilerp_rgba8(r0[x0], r0[x1], r1[x0], r1[x1], a, b, out);
        return;
    }
#endif
    (void)simd;
    frag_bilerp_rgba8(r0[x0], r0[x1], r1[x0], r1[x1], a, b, out, unorm);
}

/* what §3.7.7-3.7.8 ask of one fragment: level `level` with `filter`, and
** where `two`, also level + 1, mixed by frac */
typedef struct LodChoice {
    int level, two;
    unsigned int filter;
    FRAGV frac;
} LodChoice;

/* §3.7.8: c = 0.5 when MAG is LINEAR and MIN is NEAREST_MIPMAP_*, else 0 */
static inline LODV lod_cshift(const Texture *t)
{
    const unsigned int minf = t->min_filter;
    return (t->mag_filter == GL_LINEAR && (minf == GL_NEAREST_MIPMAP_NEAREST || minf == GL_NEAREST_MIPMAP_LINEAR))
               ? lod_from_ratio(1, 2) : 0;
}

/* the filter of a minified fragment (lambda > c) */
static inline unsigned int lod_min_filter(unsigned int minf)
{
    return (minf == GL_NEAREST || minf == GL_NEAREST_MIPMAP_NEAREST || minf == GL_NEAREST_MIPMAP_LINEAR) ? GL_NEAREST
                                                                                                        : GL_LINEAR;
}

SAMPLE_INLINE LodChoice lod_select(const Texture *t, LODV lambda);

/* a fragment's footprint: (xs, xt) and (ys, yt) the coordinate steps to
** its x and y neighbours, and their magnitudes in texel units of level 0;
** coordinates are first limited to +-2^18 so that differences scaled by
** the size stay in range even where q -> 0 saturated them */
typedef struct Footprint {
    TEXC cs, ct, xs, xt, ys, yt;
    TEXC xs_texels, ys_texels, xt_texels, yt_texels;
} Footprint;

SAMPLE_INLINE Footprint footprint(const Texture *t, const TexCoord *c, const TexCoord *dx, const TexCoord *dy)
{
    const int w = t->level[0].width, h = t->level[0].height;
    const TEXC lim = texc_scale(TEXC_ONE, 1 << 18);
    Footprint f;
    f.cs = texc_clamp(c->s, lim);
    f.ct = texc_clamp(c->t, lim);
    f.xs = texc_clamp(dx->s, lim) - f.cs;
    f.xt = texc_clamp(dx->t, lim) - f.ct;
    f.ys = texc_clamp(dy->s, lim) - f.cs;
    f.yt = texc_clamp(dy->t, lim) - f.ct;
    f.xs_texels = texc_abs(texc_scale(f.xs, w));
    f.ys_texels = texc_abs(texc_scale(f.ys, w));
    f.xt_texels = texc_abs(texc_scale(f.xt, h));
    f.yt_texels = texc_abs(texc_scale(f.yt, h));
    return f;
}

SAMPLE_INLINE LodChoice lod_choose(const Texture *t, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                                   LODV bias)
{
    /* rho: the largest of the four magnitudes, in this order (lod_choose4_f
    ** forms it in the same order, so a NaN takes the same branches) */
    const Footprint f = footprint(t, c, dx, dy);
    TEXC rho = f.xs_texels;
    if (f.ys_texels > rho) rho = f.ys_texels;
    if (f.xt_texels > rho) rho = f.xt_texels;
    if (f.yt_texels > rho) rho = f.yt_texels;
    /* EXT_texture_lod_bias: the unit's bias, before every clamp */
    return lod_select(t, lod_log2(rho) + bias);
}

/* §3.7.7-3.7.8's choice for one lambda */
SAMPLE_INLINE LodChoice lod_select(const Texture *t, LODV lambda)
{
    LodChoice ch = { 0, 0, t->mag_filter, 0 };
    unsigned int minf = t->min_filter;
    if (lambda <= lod_cshift(t))
        return ch;
    ch.filter = lod_min_filter(minf);
    if (minf == GL_NEAREST || minf == GL_LINEAR)
        return ch;
    int q = t->max_level;
    if (minf == GL_NEAREST_MIPMAP_NEAREST || minf == GL_LINEAR_MIPMAP_NEAREST) {
        /* d = ceil(lambda + 1/2) - 1 for lambda > 1/2, else 0 */
        int64_t d = 0;
        if (lambda > lod_from_ratio(1, 2)) {
            LODV x = lambda + lod_from_ratio(1, 2);
            int64_t fl = lod_ifloor(x);
            d = (lod_frac(x) != 0 ? fl + 1 : fl) - 1;
        }
        ch.level = (int)(d > q ? q : d);
        return ch;
    }
    /* *_MIPMAP_LINEAR: levels floor(lambda) and the next, by frac(lambda) */
    int64_t d1i = lod_ifloor(lambda);
    if (d1i >= q) {
        ch.level = q;
        return ch;
    }
    ch.level = (int)d1i;
    ch.two = 1;
    ch.frac = lod_frac(lambda);
    return ch;
}

/* the trilinear mix of two levels' texels */
static inline void lod_mix(FRAGV f, const FRAGV t1[4], const FRAGV t2[4], FRAGV out[4])
{
    for (int k = 0; k < 4; k++)
        out[k] = t1[k] + frag_mul(f, t2[k] - t1[k]);
}

/* one sample at (s, t) by a level-of-detail choice */
SAMPLE_INLINE void sample_at(const Texture *t, LodChoice ch, TEXC s, TEXC tc, FRAGV out[4], const FRAGV *unorm,
                             unsigned int ws, unsigned int wt, int simd)
{
    if (!ch.two) {
        sample_level(t, ch.level, ch.filter, s, tc, out, unorm, ws, wt, simd);
        return;
    }
    FRAGV t1[4], t2[4];
    sample_level(t, ch.level, ch.filter, s, tc, t1, unorm, ws, wt, simd);
    sample_level(t, ch.level + 1, ch.filter, s, tc, t2, unorm, ws, wt, simd);
    lod_mix(ch.frac, t1, t2, out);
}

/* EXT_texture_filter_anisotropic, the extension's own scheme: Fx and Fy
** the larger of |du|, |dv| along x and along y (its allowed
** approximation of Px, Py), N = min(ceil(Fmax / Fmin), maxAniso) samples
** at lambda = log2(Fmax / N) spread evenly along the major axis (at
** i / (N + 1) - 1/2 of its step, i = 1..N), averaged */
static void sample_aniso(const Texture *t, const TexCoord *c, const TexCoord *dx, const TexCoord *dy, FRAGV out[4],
                         const FRAGV *unorm, unsigned int ws, unsigned int wt, int simd, LODV bias)
{
    const Footprint f = footprint(t, c, dx, dy);
    TEXC fx = f.xs_texels, fy = f.ys_texels;
    if (f.xt_texels > fx) fx = f.xt_texels;
    if (f.yt_texels > fy) fy = f.yt_texels;
    const int major_x = fx > fy;
    const TEXC fmax = major_x ? fx : fy, fmin = major_x ? fy : fx;
    const int top = (int)(t->max_aniso < TEXTURE_MAX_ANISOTROPY ? t->max_aniso : TEXTURE_MAX_ANISOTROPY);
    int n = top;
    if (fmin > 0) {
        const int64_t ratio = texc_ceil_ratio(fmax, fmin);
        n = ratio < top ? (int)ratio : top;
    }
    if (n < 1)
        n = 1;
    const LodChoice ch = lod_select(t, lod_log2(texc_div_int(fmax, n)) + bias);
    const TEXC ds = major_x ? f.xs : f.ys, dt = major_x ? f.xt : f.yt;
    FRAGV sum[4] = { 0, 0, 0, 0 };
    for (int i = 1; i <= n; i++) {
        /* the step's (2i - n - 1) / (2 (n + 1)) */
        const TEXC ss = f.cs + texc_mul_ratio(ds, 2 * i - n - 1, 2 * (n + 1));
        const TEXC tt = f.ct + texc_mul_ratio(dt, 2 * i - n - 1, 2 * (n + 1));
        FRAGV one[4];
        sample_at(t, ch, ss, tt, one, unorm, ws, wt, simd);
        for (int k = 0; k < 4; k++)
            sum[k] += one[k];
    }
    for (int k = 0; k < 4; k++)
        out[k] = frag_div_int(sum[k], n);
}

SAMPLE_INLINE void sample_w(const Texture *t, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                            FRAGV out[4], const FRAGV *unorm, unsigned int ws, unsigned int wt, int simd, LODV bias)
{
    if (!dx || !dy) {
        sample_level(t, 0, t->mag_filter, c->s, c->t, out, unorm, ws, wt, simd);
        return;
    }
    if (t->max_aniso > 1.0) {
        sample_aniso(t, c, dx, dy, out, unorm, ws, wt, simd, bias);
        return;
    }
    sample_at(t, lod_choose(t, c, dx, dy, bias), c->s, c->t, out, unorm, ws, wt, simd);
}

void texture_sample(const Texture *t, double lod_bias, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                    FRAGV out[4], const FRAGV *unorm)
{
    /* EXT_texture_lod_bias: clamped to MAX_TEXTURE_LOD_BIAS_EXT */
    const double b = lod_bias != lod_bias ? 0.0
                   : (lod_bias < -TEXTURE_MAX_LOD_BIAS ? -TEXTURE_MAX_LOD_BIAS
                   : (lod_bias > TEXTURE_MAX_LOD_BIAS ? TEXTURE_MAX_LOD_BIAS : lod_bias));
    const LODV bias = lod_from_double(b);
    sample_w(t, c, dx, dy, out, unorm, t->wrap_s, t->wrap_t, 0, bias);
}

/* {====================================================================
** span samplers: n fragments' coordinates to n texels, out[j * stride],
** with the wrap modes (and without a level of detail, the filter) fixed */

#define SPAN_SAMPLER(name, WS, WT, FILTER, SIMD)                                                           \
    static void name(const Texture *t, int n, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,   \
                     FRAGV *out, size_t stride, const FRAGV *unorm)                                        \
    {                                                                                                      \
        const unsigned int ws = WS ? WS : t->wrap_s, wt = WT ? WT : t->wrap_t;                             \
        if (FILTER) {                                                                                      \
            int j = SIMD && FILTER == GL_LINEAR ? linear_block(SIMD, t, n, c, out, stride, ws, wt) : 0;   \
            for (; j < n; j++)                                                                             \
                sample_level(t, 0, FILTER, c[j].s, c[j].t, out + (size_t)j * stride, unorm, ws, wt, SIMD); \
        } else if (!(SIMD && lod_blocks(SIMD, t, n, c, dx, dy, out, stride, unorm, ws, wt))) {              \
            for (int j = 0; j < n; j++)                                                                    \
                sample_w(t, &c[j], &dx[j], &dy[j], out + (size_t)j * stride, unorm, ws, wt, SIMD, 0);      \
        }                                                                                                  \
    }

/* whether the bilinear kernels (sample_linear4) can filter a level of this
** texture: its sizes are powers of two (so are every smaller level's) and
** each wrap mode is REPEAT or CLAMP_TO_EDGE */
static inline int linear_kernel_fits(const Texture *t, unsigned int ws, unsigned int wt)
{
    const TexImage *l0 = &t->level[0];
    const int pot = (l0->width & (l0->width - 1)) == 0 && (l0->height & (l0->height - 1)) == 0;
    return pot && (ws == GL_REPEAT || ws == GL_CLAMP_TO_EDGE) && (wt == GL_REPEAT || wt == GL_CLAMP_TO_EDGE);
}

#if SIMD_X86
/* the vector kernel of this build and instance (simd: SIMD_AVX2 or
** SIMD_AVX512) over the first n (a multiple of 4) of a level's GL_LINEAR
** samples; returns how many it did from the start. `rows`: the level is
** read where it is not minified past the next level (a lone level, not
** one of a trilinear pair), so groups of eight often read one row's
** neighbouring texels (avx2_row_texels8) */
static inline int sample_linear4(int simd, const TexImage *li, int n, const TexCoord *c, FRAGV *out, size_t stride,
                                 int rs, int rt, int rows)
{
#if NUM_IS_FIXED
    (void)simd;
    avx2_sample_linear(li, n, c, out, stride, rs, rt, rows);
    return n;
#else
    int j = 0;
#if SIMD_AVX512_INSTANCE
    if (simd >= SIMD_AVX512)    /* eight at a time, the last four (or from a coordinate not finite) by AVX2 */
        j = avx512_sample_linear_real(li, n, c, out, stride, rs, rt, rows);
#elif defined(GLES_NUM_FLOAT)
    (void)simd;
    j = f8_sample_linear(li, n, c, out, stride, rs, rt, rows);     /* eight at a time in AVX2's float lanes, likewise */
#else
    (void)simd;
#endif
    return j + avx2_sample_linear_real(li, n - j, c + j, out + (size_t)j * stride, stride, rs, rt, rows);
#endif
}
#endif

/* the vector kernel's share of n level-0 GL_LINEAR samples, from the start
** (a multiple of four; 0 where it does not apply: see linear_kernel_fits) */
static inline int linear_block(int simd, const Texture *t, int n, const TexCoord *c, FRAGV *out, size_t stride,
                               unsigned int ws, unsigned int wt)
{
#if SIMD_X86
    if (linear_kernel_fits(t, ws, wt))
        return sample_linear4(simd, &t->level[0], n & ~3, c, out, stride, ws == GL_REPEAT, wt == GL_REPEAT, 1);
#endif
    (void)simd, (void)t, (void)n, (void)c, (void)out, (void)stride, (void)ws, (void)wt;
    return 0;
}

#if SIMD_X86
/* a LodChoice as one int, so that runs of fragments that read the same
** levels the same way are runs of equal keys */
_Static_assert(SPAN_SAMPLE_MAX <= 64, "lod_block marks run starts in a 64-bit mask");
#define LOD_KEY_TWO 0x100
#define LOD_KEY_LINEAR 0x200
static inline int32_t lod_key(int level, int two, unsigned int filter)
{
    return level | (two ? LOD_KEY_TWO : 0) | (filter == GL_LINEAR ? LOD_KEY_LINEAR : 0);
}

#pragma GCC push_options
SIMD_TARGET_AVX2
#if !NUM_IS_FIXED
/* lod_choose's constants for lod_choose4_f and lod_choose4_d */
typedef struct LodParamsR {
    TEXC w, h, lim, cshift;
    int mode;                   /* 0: no mipmap, 1: *_MIPMAP_NEAREST, 2: *_MIPMAP_LINEAR */
    int q;
    int32_t kmag, kmin, ktwo;   /* keys of lambda <= c, of lambda > c (level 0), and of `two` */
} LodParamsR;
#endif

#if LOD_LOG2_FAST
_Static_assert(sizeof(TexCoord) == 2 * sizeof(float), "four TexCoords are eight float lanes");

/* lod_choose of fragments 0..3 in the float build (key[k], frac[k], frac 0
** where not two); 0 (nothing stored) where a lane needs the scalar code.
** The coordinates' clamp, difference, scale and magnitude are the scalar
** float operations in lanes (s and t interleaved): min(lim, a) then
** max(-lim, .) are texc_clamp's compares (a NaN passes both), the
** magnitude negates where a < 0, and rho is formed in the scalar order,
** each max(d, rho) being `d > rho ? d : rho`. Lambda: lod_log2_approx's
** operations in double lanes (the exponent plus 2^52 read back as a
** double gives (double)e exactly; the table rows by gathers), converted to
** float as the scalar code converts; a lane whose y is near a midpoint
** (lod_log2_near_mid) or whose rho is infinite returns 0. The decisions:
** lambda > c; for *_MIPMAP_NEAREST, floor(x) + (frac(x) != 0) - 1 for
** x = lambda + 1/2 is ceil(x) - 1 (x finite, below 2^24), 0 where
** lambda <= 1/2, then min(d, q); for *_MIPMAP_LINEAR floor(lambda) (an
** integer in [0, 2^24), exact as int32) against q, and lambda - floor(lambda). */
AVX2_INLINE int lod_choose4_f(const LodParamsR *p, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                              int32_t key[4], FRAGV frac[4])
{
    const __m256 lim = _mm256_set1_ps(p->lim), nlim = _mm256_set1_ps(-p->lim);
    const __m256 sign = _mm256_set1_ps(-0.0f), zero = _mm256_setzero_ps();
    const __m256 wh = _mm256_setr_ps(p->w, p->h, p->w, p->h, p->w, p->h, p->w, p->h);
#define LOD_CLAMP8(v) _mm256_max_ps(nlim, _mm256_min_ps(lim, (v)))
    const __m256 cc = LOD_CLAMP8(_mm256_loadu_ps(&c[0].s));
    __m256 a = _mm256_mul_ps(_mm256_sub_ps(LOD_CLAMP8(_mm256_loadu_ps(&dx[0].s)), cc), wh);
    __m256 b = _mm256_mul_ps(_mm256_sub_ps(LOD_CLAMP8(_mm256_loadu_ps(&dy[0].s)), cc), wh);
#undef LOD_CLAMP8
    a = _mm256_blendv_ps(a, _mm256_xor_ps(a, sign), _mm256_cmp_ps(a, zero, _CMP_LT_OQ));
    b = _mm256_blendv_ps(b, _mm256_xor_ps(b, sign), _mm256_cmp_ps(b, zero, _CMP_LT_OQ));
    /* (d1 of the four | d3 of the four), (d2 | d4) */
    const __m256i deint = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
    a = _mm256_permutevar8x32_ps(a, deint);
    b = _mm256_permutevar8x32_ps(b, deint);
    __m128 rho = _mm256_castps256_ps128(a);
    rho = _mm_max_ps(_mm256_castps256_ps128(b), rho);
    rho = _mm_max_ps(_mm256_extractf128_ps(a, 1), rho);
    rho = _mm_max_ps(_mm256_extractf128_ps(b, 1), rho);

    const __m128 pos = _mm_cmpgt_ps(rho, _mm_setzero_ps());
    if (_mm_movemask_ps(_mm_andnot_ps(_mm_cmple_ps(rho, _mm_set1_ps(NUM_MAX)), pos)))
        return 0;
    const __m256i xb = _mm256_castpd_si256(_mm256_cvtps_pd(rho));
    const __m256i fold = _mm256_and_si256(_mm256_srli_epi64(xb, 51), _mm256_set1_epi64x(1));
    const __m256d two52 = _mm256_set1_pd(4503599627370496.0);
    const __m256d e = _mm256_sub_pd(
        _mm256_castsi256_pd(_mm256_or_si256(_mm256_add_epi64(_mm256_srli_epi64(xb, 52), fold),
                                            _mm256_castpd_si256(two52))),
        _mm256_set1_pd(4503599627370496.0 + 1023));
    const __m256d m = _mm256_castsi256_pd(_mm256_or_si256(
        _mm256_and_si256(xb, _mm256_set1_epi64x((int64_t)(((uint64_t)1 << 52) - 1))),
        _mm256_sub_epi64(_mm256_set1_epi64x((int64_t)1023 << 52), _mm256_slli_epi64(fold, 52))));
    const __m256i row = _mm256_and_si256(_mm256_srli_epi64(xb, 45), _mm256_set1_epi64x(127));
    const __m256d r = _mm256_sub_pd(_mm256_mul_pd(m, _mm256_i64gather_pd(lod_log2_c, row, 8)), _mm256_set1_pd(1));
#define LOD_STEP(acc, k) _mm256_add_pd(_mm256_set1_pd(LOD_LOG2_A##k), _mm256_mul_pd(r, (acc)))
    const __m256d poly = _mm256_mul_pd(
        r, LOD_STEP(LOD_STEP(LOD_STEP(LOD_STEP(LOD_STEP(_mm256_set1_pd(LOD_LOG2_A6), 5), 4), 3), 2), 1));
#undef LOD_STEP
    const __m256d y = _mm256_add_pd(_mm256_add_pd(e, _mm256_i64gather_pd(lod_log2_l, row, 8)), poly);
    const __m256i dm = _mm256_sub_epi64(_mm256_and_si256(_mm256_castpd_si256(y), _mm256_set1_epi64x((1 << 29) - 1)),
                                        _mm256_set1_epi64x(((int64_t)1 << 28) - LOD_LOG2_NEAR));
    const __m256i far = _mm256_or_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), dm),
                                        _mm256_cmpgt_epi64(dm, _mm256_set1_epi64x(2 * LOD_LOG2_NEAR)));
    const int near4 = ~_mm256_movemask_pd(_mm256_castsi256_pd(far)) & _mm_movemask_ps(pos);
    if (near4)
        return 0;
    const __m128 lam = _mm_blendv_ps(_mm_set1_ps((NUM)-1e30), _mm256_cvtpd_ps(y), pos);

    const __m128 above = _mm_cmpgt_ps(lam, _mm_set1_ps(p->cshift));
    const __m128i q = _mm_set1_epi32(p->q);
    __m128i k = _mm_set1_epi32(p->kmin);
    __m128 f = _mm_setzero_ps();
    if (p->mode == 1) {
        const __m128 d = _mm_and_ps(_mm_sub_ps(_mm_ceil_ps(_mm_add_ps(lam, _mm_set1_ps(0.5f))), _mm_set1_ps(1)),
                                    _mm_cmpgt_ps(lam, _mm_set1_ps(0.5f)));
        k = _mm_or_si128(k, _mm_min_epi32(_mm_cvttps_epi32(_mm_and_ps(d, above)), q));
    } else if (p->mode == 2) {
        const __m128 fl = _mm_floor_ps(_mm_and_ps(lam, above));
        const __m128i d = _mm_cvttps_epi32(fl);
        const __m128i two = _mm_cmpgt_epi32(q, d);        /* floor(lambda) < q */
        k = _mm_or_si128(k, _mm_blendv_epi8(q, d, two));
        k = _mm_or_si128(k, _mm_and_si128(two, _mm_set1_epi32(p->ktwo)));
        f = _mm_and_ps(_mm_sub_ps(lam, fl), _mm_castsi128_ps(two));
    }
    k = _mm_blendv_epi8(_mm_set1_epi32(p->kmag), k, _mm_castps_si128(above));
    _mm_storeu_si128((__m128i *)(void *)key, k);
    _mm_storeu_ps(frac, _mm_and_ps(f, above));
    return 1;
}
#elif !NUM_IS_FIXED
_Static_assert(sizeof(TexCoord) == 2 * sizeof(double), "two TexCoords are four double lanes");

/* lod_log2_dd (num.h) of four lanes x: its operations in its order, the
** rows' constants by gathers, e as a double through the bits of 2^52 + e;
** every lane's value is that of the scalar code for a positive normal x
** (other lanes give some value, and read the tables within bounds) */
AVX2_INLINE __m256d lod_log2_dd4(__m256d x)
{
    const __m256i b = _mm256_castpd_si256(x), one = _mm256_set1_epi64x(1);
    const __m256i fold = _mm256_and_si256(_mm256_srli_epi64(b, 51), one);       /* m >= 1.5: m / 2, e + 1 */
    const __m256i biased = _mm256_add_epi64(_mm256_srli_epi64(b, 52), fold);   /* e + 1023, below 2^13 */
    const __m256d two52 = _mm256_set1_pd(0x1p52);
    const __m256d e = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(biased, _mm256_castpd_si256(two52))),
                                    _mm256_set1_pd(0x1p52 + 1023));
    const __m256d m = _mm256_castsi256_pd(
        _mm256_or_si256(_mm256_and_si256(b, _mm256_set1_epi64x((int64_t)(((uint64_t)1 << 52) - 1))),
                        _mm256_slli_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(1023), fold), 52)));
    const __m256i row = _mm256_and_si256(_mm256_srli_epi64(b, 45), _mm256_set1_epi64x(127));
    const __m256d c = _mm256_i64gather_pd(lod_log2_c, row, 8);
    const __m256d lh = _mm256_i64gather_pd(lod_log2_l, row, 8), llo = _mm256_i64gather_pd(lod_log2_l_lo, row, 8);
    const __m256d a1 = _mm256_set1_pd(LOD_LOG2_A1);
    const __m256d mc = _mm256_mul_pd(m, c), mc_lo = _mm256_fmsub_pd(m, c, mc);
    const __m256d r = _mm256_sub_pd(mc, _mm256_set1_pd(1.0));
    const __m256d ph = _mm256_mul_pd(r, a1), pl = _mm256_fmsub_pd(r, a1, ph);
    static const double coef[7] = { LOD_LOG2_A2, LOD_LOG2_A3, LOD_LOG2_A4, LOD_LOG2_A5,
                                    LOD_LOG2_A6, LOD_LOG2_A7, LOD_LOG2_A8 };
    __m256d h = _mm256_set1_pd(coef[6]);
    for (int k = 5; k >= 0; k--)
        h = _mm256_add_pd(_mm256_set1_pd(coef[k]), _mm256_mul_pd(r, h));
    const __m256d q = _mm256_mul_pd(_mm256_mul_pd(r, r), h);
    const __m256d s1 = _mm256_add_pd(e, lh), err1 = _mm256_sub_pd(lh, _mm256_sub_pd(s1, e));
    const __m256d s2 = _mm256_add_pd(s1, ph), v = _mm256_sub_pd(s2, s1);
    const __m256d err2 = _mm256_add_pd(_mm256_sub_pd(s1, _mm256_sub_pd(s2, v)), _mm256_sub_pd(ph, v));
    const __m256d lo = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(r, _mm256_set1_pd(LOD_LOG2_A1_LO)),
                      _mm256_mul_pd(mc_lo, _mm256_sub_pd(a1, _mm256_mul_pd(r, a1)))),
        q);
    return _mm256_add_pd(s2, _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(err1, err2), _mm256_add_pd(pl, llo)), lo));
}

/* lod_choose of fragments 0..3 in the double build (key[k], frac[k], frac 0
** where not two), in three steps: rho (lod_rho4_d), lambda
** (lod_lambda_ends4_d and lod_log2_dd4) and the decisions (lod_decide4_d).
** rho: the scalar double operations in lanes, as in
** lod_choose4_f (s and t interleaved in two registers per array, then
** unpacked to one register per derivative). Lambda is lod_log2's
** (lod_log2_dd4, the same bits) wherever its value is used; it is not
** where 1 < rho < 2^(q+1) fails:
** for rho <= 1, log2 rho <= 0 and log2 (within 1 ulp, so of the same
** sign, and 0 at 1) gives lambda <= 0 <= c: magnification, as -1e30 gives
** (rho <= 0 or NaN is -1e30 in the scalar code too); for rho >= 2^(q+1),
** lambda >= q + 1 - 1 ulp > q (infinity for an infinite rho), and every
** decision (lambda > c, min(ceil(lambda + 1/2) - 1, q) = q,
** floor(lambda) >= q) is the one q + 1 gives. The decisions are
** lod_choose4_f's in double lanes (floor(lambda) <= 1025, exact as int32). */
AVX2_INLINE __m256d lod_rho4_d(const LodParamsR *p, const TexCoord *c, const TexCoord *dx, const TexCoord *dy)
{
    const __m256d lim = _mm256_set1_pd(p->lim), nlim = _mm256_set1_pd(-p->lim);
    const __m256d sign = _mm256_set1_pd(-0.0), zero = _mm256_setzero_pd();
    const __m256d wh = _mm256_setr_pd(p->w, p->h, p->w, p->h);
    __m256d d[2][2];            /* [dx, dy][fragments 0-1, 2-3] */
    for (int h = 0; h < 2; h++) {
        const __m256d cc = _mm256_max_pd(nlim, _mm256_min_pd(lim, _mm256_loadu_pd(&c[2 * h].s)));
        for (int g = 0; g < 2; g++) {
            const TexCoord *o = g ? dy : dx;
            __m256d a = _mm256_max_pd(nlim, _mm256_min_pd(lim, _mm256_loadu_pd(&o[2 * h].s)));
            a = _mm256_mul_pd(_mm256_sub_pd(a, cc), wh);
            d[g][h] = _mm256_blendv_pd(a, _mm256_xor_pd(a, sign), _mm256_cmp_pd(a, zero, _CMP_LT_OQ));
        }
    }
    /* (s0 s2 s1 s3) and (t0 t2 t1 t3), back to fragment order */
    const __m256d d1 = _mm256_permute4x64_pd(_mm256_unpacklo_pd(d[0][0], d[0][1]), 0xD8);
    const __m256d d3 = _mm256_permute4x64_pd(_mm256_unpackhi_pd(d[0][0], d[0][1]), 0xD8);
    const __m256d d2 = _mm256_permute4x64_pd(_mm256_unpacklo_pd(d[1][0], d[1][1]), 0xD8);
    const __m256d d4 = _mm256_permute4x64_pd(_mm256_unpackhi_pd(d[1][0], d[1][1]), 0xD8);
    return _mm256_max_pd(d4, _mm256_max_pd(d3, _mm256_max_pd(d2, d1)));
}

/* lambda of rho lanes outside the logarithm's range (above); *used: the
** lanes whose lambda is the logarithm's, which the caller blends in */
AVX2_INLINE __m256d lod_lambda_ends4_d(const LodParamsR *p, __m256d rho, __m256d *used)
{
    const double top = (double)((int64_t)2 << p->q);     /* 2^(q+1); q <= 11 */
    const __m256d gt1 = _mm256_cmp_pd(rho, _mm256_set1_pd(1), _CMP_GT_OQ);
    *used = _mm256_and_pd(gt1, _mm256_cmp_pd(rho, _mm256_set1_pd(top), _CMP_LT_OQ));
    return _mm256_blendv_pd(_mm256_set1_pd(-1e30), _mm256_set1_pd(p->q + 1), gt1);
}

/* the decisions (above) of lambda lanes lam */
AVX2_INLINE void lod_decide4_d(const LodParamsR *p, __m256d lam, int32_t key[4], FRAGV frac[4])
{
    const __m256d above = _mm256_cmp_pd(lam, _mm256_set1_pd(p->cshift), _CMP_GT_OQ);
    const __m256i pick = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    const __m128i above32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(_mm256_castpd_si256(above), pick));
    const __m128i q = _mm_set1_epi32(p->q);
    __m128i k = _mm_set1_epi32(p->kmin);
    __m256d f = _mm256_setzero_pd();
    if (p->mode == 1) {
        const __m256d dd = _mm256_and_pd(
            _mm256_sub_pd(_mm256_ceil_pd(_mm256_add_pd(lam, _mm256_set1_pd(0.5))), _mm256_set1_pd(1)),
            _mm256_cmp_pd(lam, _mm256_set1_pd(0.5), _CMP_GT_OQ));
        k = _mm_or_si128(k, _mm_min_epi32(_mm256_cvttpd_epi32(_mm256_and_pd(dd, above)), q));
    } else if (p->mode == 2) {
        const __m256d fl = _mm256_floor_pd(_mm256_and_pd(lam, above));
        const __m128i dl = _mm256_cvttpd_epi32(fl);
        const __m128i two = _mm_cmpgt_epi32(q, dl);        /* floor(lambda) < q */
        k = _mm_or_si128(k, _mm_blendv_epi8(q, dl, two));
        k = _mm_or_si128(k, _mm_and_si128(two, _mm_set1_epi32(p->ktwo)));
        f = _mm256_and_pd(_mm256_sub_pd(lam, fl), _mm256_castsi256_pd(_mm256_cvtepi32_epi64(two)));
    }
    k = _mm_blendv_epi8(_mm_set1_epi32(p->kmag), k, above32);
    _mm_storeu_si128((__m128i *)(void *)key, k);
    _mm256_storeu_pd(frac, _mm256_and_pd(f, above));
}

AVX2_INLINE void lod_choose4_d(const LodParamsR *p, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                               int32_t key[4], FRAGV frac[4])
{
    const __m256d rho = lod_rho4_d(p, c, dx, dy);
    __m256d used, lam = lod_lambda_ends4_d(p, rho, &used);
    if (_mm256_movemask_pd(used))       /* (the lanes used are normal: 1 < rho < 2^12) */
        lam = _mm256_blendv_pd(lam, lod_log2_dd4(rho), used);
    lod_decide4_d(p, lam, key, frac);
}

/* lod_choose4_d of fragments 0..7, both fours' table gathers
** (lod_log2_dd4's) issued together: the second does not wait behind the
** first's arithmetic */
AVX2_INLINE void lod_choose8_d(const LodParamsR *p, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                               int32_t key[8], FRAGV frac[8])
{
    const __m256d rho0 = lod_rho4_d(p, c, dx, dy), rho1 = lod_rho4_d(p, c + 4, dx + 4, dy + 4);
    __m256d used0, used1;
    __m256d lam0 = lod_lambda_ends4_d(p, rho0, &used0), lam1 = lod_lambda_ends4_d(p, rho1, &used1);
    if (_mm256_movemask_pd(_mm256_or_pd(used0, used1))) {
        const __m256d l0 = lod_log2_dd4(rho0), l1 = lod_log2_dd4(rho1);
        lam0 = _mm256_blendv_pd(lam0, l0, used0);
        lam1 = _mm256_blendv_pd(lam1, l1, used1);
    }
    lod_decide4_d(p, lam0, key, frac);
    lod_decide4_d(p, lam1, key + 4, frac + 4);
}
#endif

/* lod_block's widest mix of a run's two levels in this build and
** instance (simd): its group and the least instance it needs (the fixed
** build's sixteen in AVX-512, the float build's eight in AVX2, the double
** build's eight in AVX-512 or else AVX2) */
#if SIMD_AVX512_FX
#define LOD_MIX(simd, ...) fx512_sample_linear_mix(__VA_ARGS__)
#define LOD_MIX_GROUP 16
#define LOD_MIX_SIMD SIMD_AVX512
#elif SIMD_AVX512_INSTANCE
#define LOD_MIX(simd, ...)                                                                                        \
    ((simd) >= SIMD_AVX512 ? avx512_sample_linear_mix_real(__VA_ARGS__) : avx2_sample_linear_mix_real(__VA_ARGS__))
#define LOD_MIX_GROUP 8
#define LOD_MIX_SIMD SIMD_AVX2
#elif defined(GLES_NUM_FLOAT)
#define LOD_MIX(simd, ...) f8_sample_linear_mix(__VA_ARGS__)
#define LOD_MIX_GROUP 8
#define LOD_MIX_SIMD SIMD_AVX2
#else
#define LOD_MIX_GROUP 0
#endif

#if NUM_IS_FIXED || defined(GLES_NUM_DOUBLE)
/* a run [j, e) of fragments with one GL_LINEAR level, or (two) that level
** and the next mixed by frac, through the fog and write of fw
** (avx2_fog_write_texels8) eight at a time, the last group padded with
** copies of its last fragment; where a lane is not proved, the exact
** texel (sample_level and lod_mix, as lod_block forms it) at out + j
** stride, left to the exact stages. s0 is fragment 0's slot in the chunk */
static void lod_fog_run(const Texture *t, int level, int two, int j, int e, const TexCoord *c, const FRAGV *frac,
                        FRAGV *out, size_t stride, const FRAGV *unorm, unsigned int ws, unsigned int wt,
                        const TexFogWrite *fw, int s0)
{
    const Avx2Level l1 = avx2_level(&t->level[level]), l2 = avx2_level(&t->level[level + two]);
    const int rs = ws == GL_REPEAT, rt = wt == GL_REPEAT;
    for (int i = j; i < e; i += 8) {
        const int m = e - i < 8 ? e - i : 8;
        TexCoord cpad[8];
        WGT ppad[8][3];
        FRAGV fpad[8];
        uint8_t kpad[8];
        const TexCoord *ci = c + i;
        const WGT (*pi)[3] = fw->p + s0 + i;
        const uint8_t *ki = fw->k + s0 + i;
        const FRAGV *fi = frac + i;
        if (m < 8) {
            for (int q = 0; q < 8; q++) {
                const int from = i + (q < m ? q : m - 1);
                cpad[q] = c[from];
                memcpy(ppad[q], fw->p[s0 + from], sizeof ppad[q]);
                kpad[q] = fw->k[s0 + from];
                fpad[q] = frac[from];
            }
            ci = cpad, pi = (const WGT (*)[3])ppad, ki = kpad, fi = fpad;
        }
        const unsigned written = avx2_fog_write_texels8(fw, s0 + i, m, l1, l2, two, ci, pi, ki, fi, rs, rt);
        for (unsigned r = ~written & ((1u << m) - 1); r; r &= r - 1) {
            const int q = i + __builtin_ctz(r);
            FRAGV *o = out + (size_t)q * stride;
            sample_level(t, level, GL_LINEAR, c[q].s, c[q].t, o, unorm, ws, wt, 1);
            if (two) {
                FRAGV t2[4];
                sample_level(t, level + 1, GL_LINEAR, c[q].s, c[q].t, t2, unorm, ws, wt, 1);
                lod_mix(frac[q], o, t2, o);
            }
        }
    }
}
#endif

/* sample_w of n fragments with the vector kernel doing the GL_LINEAR
** samples: each fragment's level of detail first (lod_choose, four at a
** time by avx2_lod_choose4, lod_choose4_f or lod_choose4_d), as a key;
** then each run of
** neighbouring fragments with the same key through sample_linear4 (a
** level's run, and the next level's into `second`), other samples one by
** one, and the run's mix of two levels. The same arithmetic per sample as
** sample_w; returns 0 where it does not apply (as linear_block) */
static int lod_block(int simd, const Texture *t, int n, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                     FRAGV *out, size_t stride, const FRAGV *unorm, unsigned int ws, unsigned int wt,
                     const TexFogWrite *fw, int s0)
{
    if (!linear_kernel_fits(t, ws, wt) || n > SPAN_SAMPLE_MAX)
        return 0;
    /* key[1 + j] is fragment j's; key[0] and those past n are -1 (no key) */
    int32_t key[SPAN_SAMPLE_MAX + 9];
    FRAGV frac[SPAN_SAMPLE_MAX];
    FRAGV second[SPAN_SAMPLE_MAX][4];
    int j = 0;
#if NUM_IS_FIXED
    const unsigned int minf = t->min_filter;
    const Avx2LodParams p = {
        __builtin_ctz((unsigned)t->level[0].width), __builtin_ctz((unsigned)t->level[0].height),
        minf == GL_NEAREST || minf == GL_LINEAR ? 0
        : (minf == GL_NEAREST_MIPMAP_NEAREST || minf == GL_LINEAR_MIPMAP_NEAREST ? 1 : 2),
        t->max_level, lod_cshift(t),
        lod_key(0, 0, t->mag_filter), lod_key(0, 0, lod_min_filter(minf)), LOD_KEY_TWO,
    };
#if SIMD_AVX512_FX
    if (simd >= SIMD_AVX512) {  /* eight at a time, the last eight again */
        j = fx512_lod_choose(&p, n, c, dx, dy, key + 1, frac);
        if (j < n && n >= 8) {
            fx512_lod_choose(&p, 8, c + n - 8, dx + n - 8, dy + n - 8, key + 1 + n - 8, frac + n - 8);
            j = n;
        }
    }
#endif
    for (; j + 8 <= n; j += 8)
        avx2_lod_choose8(&p, c + j, dx + j, dy + j, key + 1 + j, frac + j);
    for (; j + 4 <= n; j += 4)
        avx2_lod_choose4(&p, c + j, dx + j, dy + j, key + 1 + j, frac + j);
    if (j < n && n >= 4) {      /* the last four again: the same values where they overlap */
        avx2_lod_choose4(&p, c + n - 4, dx + n - 4, dy + n - 4, key + 1 + n - 4, frac + n - 4);
        j = n;
    }
#else
    const unsigned int minf = t->min_filter;
    const LodParamsR p = {
        (TEXC)t->level[0].width, (TEXC)t->level[0].height, texc_scale(TEXC_ONE, 1 << 18), lod_cshift(t),
        minf == GL_NEAREST || minf == GL_LINEAR ? 0
        : (minf == GL_NEAREST_MIPMAP_NEAREST || minf == GL_LINEAR_MIPMAP_NEAREST ? 1 : 2),
        t->max_level, lod_key(0, 0, t->mag_filter), lod_key(0, 0, lod_min_filter(minf)), LOD_KEY_TWO,
    };
#if LOD_LOG2_FAST
    for (; j + 4 <= n; j += 4)
        if (!lod_choose4_f(&p, c + j, dx + j, dy + j, key + 1 + j, frac + j))
            for (int i = j; i < j + 4; i++) {
                const LodChoice ch = lod_choose(t, &c[i], &dx[i], &dy[i], 0);
                key[1 + i] = lod_key(ch.level, ch.two, ch.filter);
                frac[i] = ch.frac;
            }
    if (j < n && n >= 4 && lod_choose4_f(&p, c + n - 4, dx + n - 4, dy + n - 4, key + 1 + n - 4, frac + n - 4))
        j = n;                  /* the last four again: the same values where they overlap */
#else
    for (; j + 8 <= n; j += 8)
        lod_choose8_d(&p, c + j, dx + j, dy + j, key + 1 + j, frac + j);
    for (; j + 4 <= n; j += 4)
        lod_choose4_d(&p, c + j, dx + j, dy + j, key + 1 + j, frac + j);
    if (j < n && n >= 4) {
        lod_choose4_d(&p, c + n - 4, dx + n - 4, dy + n - 4, key + 1 + n - 4, frac + n - 4);
        j = n;
    }
#endif
#endif
    for (; j < n; j++) {
        const LodChoice ch = lod_choose(t, &c[j], &dx[j], &dy[j], 0);
        key[1 + j] = lod_key(ch.level, ch.two, ch.filter);
        frac[j] = ch.frac;
    }
    key[0] = -1;
    _mm256_storeu_si256((__m256i *)(void *)(key + 1 + n), _mm256_set1_epi32(-1));
    /* bit j: fragment j starts a run */
    uint64_t starts = 0;
    for (int i = 0; i < n; i += 8) {
        const __m256i same = _mm256_cmpeq_epi32(_mm256_loadu_si256((const __m256i *)(const void *)(key + 1 + i)),
                                                _mm256_loadu_si256((const __m256i *)(const void *)(key + i)));
        starts |= (uint64_t)(~(unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(same)) & 0xFF) << i;
    }
    if (n < 64)
        starts &= ((uint64_t)1 << n) - 1;
    for (j = 0; j < n;) {
        starts &= starts - 1;                      /* the run that starts at j */
        const int e = starts ? __builtin_ctzll(starts) : n;
        const int32_t kj = key[1 + j];
        const int level = kj & 0xFF, two = (kj & LOD_KEY_TWO) != 0;
        const unsigned int filter = kj & LOD_KEY_LINEAR ? GL_LINEAR : GL_NEAREST;
        const int m4 = filter == GL_LINEAR ? (e - j) & ~3 : 0;
#if NUM_IS_FIXED || defined(GLES_NUM_DOUBLE)
        if (fw && filter == GL_LINEAR) {
            /* fogged and written where proved (else the exact texel) */
            lod_fog_run(t, level, two, j, e, c, frac, out, stride, unorm, ws, wt, fw, s0);
            j = e;
            continue;
        }
#else
        (void)fw, (void)s0;
#endif
        /* fragments whose two levels the kernel samples and mixes at once */
        int mixed = 0;
#if LOD_MIX_GROUP
        if (two && m4 && simd >= LOD_MIX_SIMD) {
            /* a group at a time where every coordinate is finite, a run's
            ** last partial group as its last group again (the same texels
            ** where they overlap), the rest as below */
            const TexImage *l1 = &t->level[level], *l2 = &t->level[level + 1];
            const int len = e - j, g = LOD_MIX_GROUP;
            mixed = LOD_MIX(simd, l1, l2, len, c + j, frac + j, out + (size_t)j * stride, stride, ws == GL_REPEAT,
                            wt == GL_REPEAT);
            if (mixed && mixed == (len & ~(g - 1)) && mixed < len
                && LOD_MIX(simd, l1, l2, g, c + e - g, frac + e - g, out + (size_t)(e - g) * stride, stride,
                           ws == GL_REPEAT, wt == GL_REPEAT) == g)
                mixed = len;
        }
#endif
#if NUM_IS_FIXED
        /* the whole fours left by the AVX2 mix (eight at a time) */
        if (two && mixed < m4) {
            avx2_sample_linear_mix(&t->level[level], &t->level[level + 1], m4 - mixed, c + j + mixed,
                                   frac + j + mixed, out + (size_t)(j + mixed) * stride, stride, ws == GL_REPEAT,
                                   wt == GL_REPEAT);
            mixed = m4;
        }
        /* the last four again (the same texels where they overlap) */
        if (two && m4 && mixed < e - j && e - j >= 4) {
            avx2_sample_linear_mix(&t->level[level], &t->level[level + 1], 4, c + e - 4, frac + e - 4,
                                   out + (size_t)(e - 4) * stride, stride, ws == GL_REPEAT, wt == GL_REPEAT);
            mixed = e - j;
        }
#endif
        for (int k = 0; k <= two; k++) {
            FRAGV *dst = k ? second[j] : out + (size_t)j * stride;
            const size_t dstride = k ? 4 : stride;
            /* (past what the mix did) */
            int done = mixed;
            if (m4 > mixed)
                done += sample_linear4(simd, &t->level[level + k], m4 - mixed, c + j + mixed,
                                       dst + (size_t)mixed * dstride, dstride, ws == GL_REPEAT, wt == GL_REPEAT,
                                       !two);
            for (int i = done; i < e - j; i++)
                sample_level(t, level + k, filter, c[j + i].s, c[j + i].t, dst + (size_t)i * dstride, unorm, ws,
                             wt, 1);
        }
        if (two)
            for (int i = j + mixed; i < e; i++)
#if NUM_IS_FIXED
                avx2_lod_mix(frac[i], out + (size_t)i * stride, second[i], out + (size_t)i * stride);
#else
            {
                /* lod_mix's operations, a fragment's four channels at once */
                FRAGV *o = out + (size_t)i * stride;
                const V4 a = v4_load(o);
                v4_store(o, V4_OP(add)(a, V4_OP(mul)(v4_set1(frac[i]), V4_OP(sub)(v4_load(second[i]), a))));
            }
#endif
        j = e;
    }
    return 1;
}
#undef LOD_MIX
#undef LOD_MIX_GROUP
#undef LOD_MIX_SIMD
#pragma GCC pop_options
#else
static int lod_block(int simd, const Texture *t, int n, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                     FRAGV *out, size_t stride, const FRAGV *unorm, unsigned int ws, unsigned int wt,
                     const TexFogWrite *fw, int s0)
{
    (void)simd, (void)t, (void)n, (void)c, (void)dx, (void)dy, (void)out, (void)stride, (void)unorm, (void)ws,
        (void)wt, (void)fw, (void)s0;
    return 0;
}
#endif

/* lod_block over a chunk, SPAN_SAMPLE_MAX fragments at a time (fw: with
** the fog and write); 0 (nothing done) where it does not apply, which is
** the same for every piece */
static inline int lod_blocks_fw(int simd, const Texture *t, int n, const TexCoord *c, const TexCoord *dx,
                                const TexCoord *dy, FRAGV *out, size_t stride, const FRAGV *unorm, unsigned int ws,
                                unsigned int wt, const TexFogWrite *fw)
{
    for (int j = 0; j < n; j += SPAN_SAMPLE_MAX) {
        const int m = n - j < SPAN_SAMPLE_MAX ? n - j : SPAN_SAMPLE_MAX;
        if (!lod_block(simd, t, m, c + j, dx + j, dy + j, out + (size_t)j * stride, stride, unorm, ws, wt, fw, j))
            return 0;
    }
    return 1;
}

static inline int lod_blocks(int simd, const Texture *t, int n, const TexCoord *c, const TexCoord *dx,
                             const TexCoord *dy, FRAGV *out, size_t stride, const FRAGV *unorm, unsigned int ws,
                             unsigned int wt)
{
    return lod_blocks_fw(simd, t, n, c, dx, dy, out, stride, unorm, ws, wt, NULL);
}

/* every [wrap: repeat, clamp, other][nearest, linear, with a level of
** detail] of one instruction set, with its names from SFX */
#define SPAN_SAMPLERS(SFX, SIMD)                                                     \
    SPAN_SAMPLER(span_nearest_repeat##SFX, GL_REPEAT, GL_REPEAT, GL_NEAREST, SIMD)     \
    SPAN_SAMPLER(span_linear_repeat##SFX, GL_REPEAT, GL_REPEAT, GL_LINEAR, SIMD)       \
    SPAN_SAMPLER(span_lod_repeat##SFX, GL_REPEAT, GL_REPEAT, 0, SIMD)                  \
    SPAN_SAMPLER(span_nearest_clamp##SFX, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_NEAREST, SIMD) \
    SPAN_SAMPLER(span_linear_clamp##SFX, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, SIMD)   \
    SPAN_SAMPLER(span_lod_clamp##SFX, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, 0, SIMD)     \
    SPAN_SAMPLER(span_nearest_any##SFX, 0, 0, GL_NEAREST, SIMD)                        \
    SPAN_SAMPLER(span_linear_any##SFX, 0, 0, GL_LINEAR, SIMD)                          \
    SPAN_SAMPLER(span_lod_any##SFX, 0, 0, 0, SIMD)                                     \
    static const TexSpanSampler span_samplers##SFX[3][3] = {                            \
        { span_nearest_repeat##SFX, span_linear_repeat##SFX, span_lod_repeat##SFX },    \
        { span_nearest_clamp##SFX, span_linear_clamp##SFX, span_lod_clamp##SFX },       \
        { span_nearest_any##SFX, span_linear_any##SFX, span_lod_any##SFX },             \
    };

SPAN_SAMPLERS(_base, 0)
#if SIMD_X86
#pragma GCC push_options
SIMD_TARGET_AVX2
SPAN_SAMPLERS(_avx2, SIMD_AVX2)
#if SIMD_AVX512_INSTANCE || SIMD_AVX512_FX
SPAN_SAMPLERS(_avx512, SIMD_AVX512)   /* the same code, with the AVX-512 kernels (span_avx512.h, span_fx512.h) */
#endif
#pragma GCC pop_options
#endif
#undef SPAN_SAMPLERS
#undef SPAN_SAMPLER

TexSpanSampler texture_span_sampler(const Texture *t, int simd)
{
    const TexSpanSampler(*table)[3] = span_samplers_base;
#if SIMD_X86
    if (simd >= SIMD_AVX2)
        table = span_samplers_avx2;
#if SIMD_AVX512_INSTANCE || SIMD_AVX512_FX
    if (simd >= SIMD_AVX512)
        table = span_samplers_avx512;
#endif
#else
    (void)simd;
#endif
    int wrap = t->wrap_s == GL_REPEAT && t->wrap_t == GL_REPEAT ? 0
             : (t->wrap_s == GL_CLAMP_TO_EDGE && t->wrap_t == GL_CLAMP_TO_EDGE ? 1 : 2);
    int filter = texture_needs_lod(t) ? 2 : (t->mag_filter == GL_LINEAR ? 1 : 0);
    return table[wrap][filter];
}

int texture_span_sample_group(const Texture *t, int simd)
{
#if SIMD_X86
    if (simd >= SIMD_AVX2 && !texture_needs_lod(t) && t->mag_filter == GL_LINEAR
        && linear_kernel_fits(t, t->wrap_s, t->wrap_t))
        /* the kernels' groups: eight fragments in the fixed build and in
        ** the double build's AVX-512 instance, so a chunk's tail is padded
        ** to eight there (not to four for the AVX2 kernel) */
        return NUM_IS_FIXED || simd >= SIMD_AVX512 ? 8 : 4;
#endif
    (void)t, (void)simd;
    return 1;
}



#if SIMD_X86 && (NUM_IS_FIXED || defined(GLES_NUM_DOUBLE))
#pragma GCC push_options
SIMD_TARGET_AVX2
static int span_fog_write_avx2(const Texture *t, int n, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                               FRAGV *out, size_t stride, const FRAGV *unorm, const TexFogWrite *fw)
{
    return lod_blocks_fw(SIMD_AVX2, t, n, c, dx, dy, out, stride, unorm, t->wrap_s, t->wrap_t, fw);
}
#pragma GCC pop_options
#endif

int texture_span_fog_write(const Texture *t, int n, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                           FRAGV *out, size_t stride, const FRAGV *unorm, const TexFogWrite *fw)
{
#if SIMD_X86 && (NUM_IS_FIXED || defined(GLES_NUM_DOUBLE))
    /* lod_block's samplers (texture_span_sampler's with a level of detail) */
    if (texture_needs_lod(t) && t->max_aniso <= 1.0)
        return span_fog_write_avx2(t, n, c, dx, dy, out, stride, unorm, fw);
#endif
    (void)t, (void)n, (void)c, (void)dx, (void)dy, (void)out, (void)stride, (void)unorm, (void)fw;
    return 0;
}

/* {====================================================================
** a test's view of the span samplers */

int gles_debug_sample(GlesContext *ctx, int unit, int simd, int n, const double *coords, double *out)
{
    if (unit < 0 || unit >= GLES_MAX_TEXTURE_UNITS || n < 0 || n > 4096)
        return 0;
    const Texture *t = texture_active(ctx, unit);
    if (!t)
        return 0;
    TexCoord *c = malloc(3 * (size_t)(n ? n : 1) * sizeof *c);
    FRAGV(*texels)[4] = malloc((size_t)(n ? n : 1) * sizeof *texels);
    if (!c || !texels) {
        free(c);
        free(texels);
        return 0;
    }
    TexCoord *dx = c + n, *dy = c + 2 * n;
    for (int j = 0; j < n; j++) {
        const double *p = coords + 6 * (size_t)j;
        c[j] = (TexCoord){ texc_from_double(p[0]), texc_from_double(p[1]) };
        dx[j] = (TexCoord){ texc_from_double(p[2]), texc_from_double(p[3]) };
        dy[j] = (TexCoord){ texc_from_double(p[4]), texc_from_double(p[5]) };
    }
    /* in chunks, as the span stages call it */
    const TexSpanSampler sampler = texture_span_sampler(t, simd < ctx->simd ? simd : ctx->simd);
    for (int j = 0; j < n; j += SPAN_SAMPLE_MAX) {
        const int m = n - j < SPAN_SAMPLE_MAX ? n - j : SPAN_SAMPLE_MAX;
        sampler(t, m, c + j, dx + j, dy + j, texels[j], 4, ctx->texel_unorm8);
    }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < 4; i++)
            out[4 * (size_t)j + i] = (double)texels[j][i];
    free(c);
    free(texels);
    return 1;
}

/* }==================================================================== */
