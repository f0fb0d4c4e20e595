/*
** vertex_avx2.h -- AVX2 kernels of the fixed build's vertex batch
** (vertex_batch.c, light.c) and of the range check's scan (range.c), and
** the switches that choose them.
**
** Each vx_* function takes `simd` (ctx_simd(ctx) >= SIMD_AVX2) and runs
** either the AVX2 kernel or the scalar code of num.h / the caller. The
** kernels give the scalar code's bits on every input; the arguments are in
** the comments, and tests/test_vertex_simd.py compares both on random and
** edge inputs through gles_debug_vertex_lanes.
**
** The float and double builds' lanes are mostly plain IEEE loops that the
** compiler vectorizes on the baseline already; what it cannot vectorize
** (the window coordinates' rounding, a positional light's branches) has
** kernels here too (VERTEX_AVX2_FP), with the same IEEE operations in the
** same order. The range check's scan of FLOAT arrays (range.c) is the same
** in every build and has its kernel in all three.
*/
#ifndef GLES_VERTEX_AVX2_H
#define GLES_VERTEX_AVX2_H

#include <string.h>
#include "num.h"
#include "simd.h"

#if SIMD_X86 && NUM_IS_FIXED
#define VERTEX_AVX2 1   /* the arithmetic kernels: fixed build only */
#else
#define VERTEX_AVX2 0
#endif
#define RANGE_AVX2 SIMD_X86   /* the range check's scan: every build */
#if SIMD_X86 && !NUM_IS_FIXED
#define VERTEX_AVX2_FP 1    /* the float builds' window coordinates */
#else
#define VERTEX_AVX2_FP 0
#endif

#if SIMD_X86
#include <immintrin.h>
#pragma GCC push_options
SIMD_TARGET_AVX2
#define VX_INLINE static inline __attribute__((always_inline))
#include "fx_avx2.h"
#endif

#if SIMD_X86
/* a positional light's parameters for vx_positional_avx2 (fixed) and
** vx_positional_fp_avx2 (float and double) */
typedef struct VxPositional {
    NUM p[3];                   /* the light's position over its w */
    NUM ka[3];                  /* attenuation factors */
    NUM sdir[3];                /* unit spot direction */
    NUM cos_cutoff, spot_exp, shin;
    NUM lamb[3], ldif[3];       /* the light's ambient and diffuse (COLOR_MATERIAL) */
    NUM amb[3], dif[3], spec[3];    /* the material products */
    int attenuate, spot, specular;
} VxPositional;
#endif

#if VERTEX_AVX2

/* {====================================================================
** Exact sums of products, rounded once.
**
** The scalar num_dot4_lanes adds up to four products p = m x of two int32
** (|p| <= 2^62) exactly in NumAcc and rounds with num_acc_round:
** sat(round_half_away(acc / 2^16)), where sat clamps to [INT32_MIN,
** INT32_MAX]. (num_acc_round's early returns for |acc| >= 2^63 - 2^31 give
** NUM_MAX / NUM_MIN, which is also sat of the rounded quotient, since that
** quotient's magnitude exceeds 2^46; so sat(round(acc / 2^16)) is the
** scalar result for every acc.)
**
** Here each product is formed exactly by vpmuldq (32x32 -> 64, signed) and
** split as p = 2^16 ph + pl with ph = floor(p / 2^16), pl = p mod 2^16 in
** [0, 2^16). Without a 64-bit arithmetic shift, ph comes from a logical one:
** p + 2^62 lies in [2^31, 2^63] (p >= INT32_MIN * INT32_MAX > -2^62), so as
** an unsigned 64-bit value it is exact and (p + 2^62) >> 16 = ph + 2^46;
** the 2^46 per term is subtracted once at the start. And pl is the low 16
** bits of p + 2^62 (2^62 is a multiple of 2^16). For k <= 4 terms plus a
** constant c (the w term when every w is 1, split the same way):
**     S_h = sum ph, |S_h| <= 5 * 2^46 < 2^49;   S_l = sum pl in [0, 5 * 2^16)
** and the lanes' wrapping adds compute both exactly (their true values fit
** 64 bits). Then acc = 2^16 S_h + S_l = 2^16 T + r with
**     T = S_h + (S_l >> 16),   r = S_l & 0xFFFF in [0, 2^16),
** so T = floor(acc / 2^16), and acc < 0 exactly when T < 0 (T >= 0 gives
** acc >= 0; T <= -1 gives acc <= -2^16 + r < 0). Rounding half away:
**  * acc >= 0: floor((acc + 2^15) / 2^16) = T + floor((r + 2^15) / 2^16)
**    = T + [r >= 2^15];
**  * acc < 0: -floor((-acc + 2^15) / 2^16); -acc + 2^15 = 2^16 (-T) +
**    (2^15 - r), so this is T - floor((2^15 - r) / 2^16) = T + [r > 2^15]
**    (2^15 - r lies in (-2^15, 2^15]: its floor over 2^16 is -1 exactly when
**    it is negative).
** Both are T + ((r + 2^15 - [T < 0]) >> 16), the operand of the shift being
** in [2^15 - 1, 2^16 + 2^15). The rounded value lies within 2^49 + 1 in
** magnitude, and saturating it to int32 is num_acc_round's result. The
** scalar code skips terms whose coefficient is zero; they add exactly 0,
** and the kernel skips them too. */

/* the split of the constant c (|c| <= 2^47): floor(c / 2^16), c mod 2^16 */
static inline void vx_split(int64_t c, int64_t *h, int64_t *l)
{
    uint64_t b = (uint64_t)c + ((uint64_t)1 << 62);
    *h = (int64_t)(b >> 16) - ((int64_t)1 << 46);
    *l = (int64_t)(b & 0xFFFF);
}

/* sat(round_half_away((2^16 S_h + S_l) / 2^16)) per 64-bit lane */
VX_INLINE __m256i vx_acc_round(__m256i sh, __m256i sl)
{
    const __m256i low = _mm256_set1_epi64x(0xFFFF);
    __m256i t = _mm256_add_epi64(sh, _mm256_srli_epi64(sl, 16));
    __m256i r = _mm256_and_si256(sl, low);
    __m256i neg = _mm256_cmpgt_epi64(_mm256_setzero_si256(), t);       /* -1 where T < 0 */
    r = _mm256_add_epi64(_mm256_add_epi64(r, _mm256_set1_epi64x(1 << 15)), neg);
    t = _mm256_add_epi64(t, _mm256_srli_epi64(r, 16));
    const __m256i hi = _mm256_set1_epi64x(INT32_MAX), lo = _mm256_set1_epi64x(INT32_MIN);
    t = _mm256_blendv_epi8(t, hi, _mm256_cmpgt_epi64(t, hi));
    return _mm256_blendv_epi8(t, lo, _mm256_cmpgt_epi64(lo, t));
}

/* the even (0, 2, 4, 6) and odd lanes' int32 results of two vx_acc_round
** (each in [INT32_MIN, INT32_MAX], so its low 32 bits are the value) */
VX_INLINE __m256i vx_merge(__m256i even, __m256i odd)
{
    return _mm256_blend_epi32(even, _mm256_slli_epi64(odd, 32), 0xAA);
}

/* out[i] = sum over t < k of coef[t] src[t][i], plus c, rounded once */
static void vx_dot_terms(const NUM *coef, const NUM *const *src, int k, int64_t c, NUM *restrict out, int cnt)
{
    const __m256i bias = _mm256_set1_epi64x((int64_t)1 << 62), low = _mm256_set1_epi64x(0xFFFF);
    int64_t h0, l0;
    vx_split(c, &h0, &l0);
    const __m256i sh0 = _mm256_set1_epi64x(h0 - k * ((int64_t)1 << 46)), sl0 = _mm256_set1_epi64x(l0);
    __m256i m[4];
    for (int t = 0; t < k; t++)
        m[t] = _mm256_set1_epi64x(coef[t]);      /* vpmuldq reads the low 32 bits, signed */
    for (int i = 0; i < cnt; i += 8) {
        __m256i she = sh0, sho = sh0, sle = sl0, slo = sl0;
        for (int t = 0; t < k; t++) {
            __m256i x = _mm256_loadu_si256((const __m256i *)(const void *)(src[t] + i));
            __m256i pe = _mm256_add_epi64(_mm256_mul_epi32(x, m[t]), bias);
            __m256i po = _mm256_add_epi64(_mm256_mul_epi32(_mm256_srli_epi64(x, 32), m[t]), bias);
            she = _mm256_add_epi64(she, _mm256_srli_epi64(pe, 16));
            sho = _mm256_add_epi64(sho, _mm256_srli_epi64(po, 16));
            sle = _mm256_add_epi64(sle, _mm256_and_si256(pe, low));
            slo = _mm256_add_epi64(slo, _mm256_and_si256(po, low));
        }
        __m256i r = vx_merge(vx_acc_round(she, sle), vx_acc_round(sho, slo));
        _mm256_storeu_si256((__m256i *)(void *)(out + i), r);
    }
}

static void vx_dot4_lanes_avx2(NUM m0, NUM m1, NUM m2, NUM m3, const NUM *x, const NUM *y, const NUM *z,
                               const NUM *w, NUM *restrict out, int cnt, int w_one)
{
    const NUM mm[4] = { m0, m1, m2, m3 };
    const NUM *rows[4] = { x, y, z, w };
    NUM coef[4];
    const NUM *src[4];
    int k = 0;
    for (int t = 0; t < (w_one ? 3 : 4); t++)
        if (mm[t] != 0) {
            coef[k] = mm[t];
            src[k++] = rows[t];
        }
    vx_dot_terms(coef, src, k, w_one ? (int64_t)m3 * NUM_ONE : 0, out, cnt);
}

static void vx_dot3_lanes_avx2(NUM m0, NUM m1, NUM m2, const NUM *x, const NUM *y, const NUM *z,
                               NUM *restrict out, int cnt)
{
    const NUM mm[3] = { m0, m1, m2 };
    const NUM *rows[3] = { x, y, z };
    NUM coef[3];
    const NUM *src[3];
    int k = 0;
    for (int t = 0; t < 3; t++)
        if (mm[t] != 0) {
            coef[k] = mm[t];
            src[k++] = rows[t];
        }
    vx_dot_terms(coef, src, k, 0, out, cnt);
}
/* }==================================================================== */

/* {====================================================================
** FLOAT array components to 16.16 (num_from_float), four at a time.
**
** num_from_float: v = (double)f * 65536 (exact: a float has 24 significant
** bits and the product stays far inside double's range); NaN gives 0,
** v <= INT32_MIN gives NUM_MIN, v >= INT32_MAX gives NUM_MAX, else
** floor(v + 1/2) with v + 1/2 rounded as a double. Here: the same v and the
** same addition (vaddpd rounds as addsd does, to nearest), vroundpd's exact
** floor, then a clamp to [INT32_MIN, INT32_MAX]. For v <= INT32_MIN,
** floor(v + 1/2) <= INT32_MIN (v + 1/2 <= INT32_MIN + 1/2, rounding is
** monotonic), so the clamp gives NUM_MIN; symmetrically v >= INT32_MAX
** gives NUM_MAX (infinities included); between, floor(v + 1/2) already lies
** in the range. NaN lanes are zeroed before the clamp (vmaxpd would pass a
** NaN operand's partner through). The clamped doubles are integers in
** int32's range, which vcvttpd2dq converts exactly. */
VX_INLINE __m128i vx_from_float4(__m128 f)
{
    __m256d v = _mm256_mul_pd(_mm256_cvtps_pd(f), _mm256_set1_pd(65536.0));
    __m256d x = _mm256_floor_pd(_mm256_add_pd(v, _mm256_set1_pd(0.5)));
    x = _mm256_and_pd(x, _mm256_cmp_pd(v, v, _CMP_ORD_Q));
    x = _mm256_max_pd(x, _mm256_set1_pd((double)INT32_MIN));
    x = _mm256_min_pd(x, _mm256_set1_pd((double)INT32_MAX));
    return _mm256_cvttpd_epi32(x);
}

/* fetch_float's rows: `size` (1..4) floats of elements index[0..n), `step`
** bytes apart, converted into out[c][i]; four elements are read (each as
** the scalar code reads it: `size` floats, nothing beyond), transposed and
** converted a row at a time */
VX_INLINE void vx_fetch_float_size(const uint8_t *base, int step, const int64_t *index, int n,
                                   NUM (*out)[NUM_BATCH], const int size)
{
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        float f[4][4] = { { 0 } };
        for (int j = 0; j < 4; j++)
            memcpy(f[j], base + index[i + j] * step, (size_t)size * sizeof(float));
        __m128 r0 = _mm_loadu_ps(f[0]), r1 = _mm_loadu_ps(f[1]), r2 = _mm_loadu_ps(f[2]), r3 = _mm_loadu_ps(f[3]);
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
        const __m128 rows[4] = { r0, r1, r2, r3 };
        for (int c = 0; c < size; c++)
            _mm_storeu_si128((__m128i *)(void *)(out[c] + i), vx_from_float4(rows[c]));
    }
    for (; i < n; i++) {
        float f[4];
        memcpy(f, base + index[i] * step, (size_t)size * sizeof f[0]);
        for (int c = 0; c < size; c++)
            out[c][i] = num_from_float(f[c]);
    }
}

/* one instance per size, so that each element's copy is a fixed move */
static void vx_fetch_float_avx2(const uint8_t *base, int step, const int64_t *index, int n, NUM (*out)[NUM_BATCH],
                                int size)
{
    switch (size) {
    case 1: vx_fetch_float_size(base, step, index, n, out, 1); break;
    case 2: vx_fetch_float_size(base, step, index, n, out, 2); break;
    case 3: vx_fetch_float_size(base, step, index, n, out, 3); break;
    default: vx_fetch_float_size(base, step, index, n, out, 4); break;
    }
}
/* }==================================================================== */

/* {====================================================================
** A directional light's term (directional_batch in light.c), four lanes
** at a time in 64-bit lanes holding sign-extended NUMs.
**
** num_mul(a, b) = sat(round_half_away(a b / 2^16)) is the one-term case of
** the sums above: vpmuldq forms a b exactly, and vx_acc_round of its split
** rounds and saturates it. num_add(a, b) = sat(a + b), exact in 64 bits. */

VX_INLINE __m256i vx_load4(const NUM *p)
{
    return _mm256_cvtepi32_epi64(_mm_loadu_si128((const __m128i *)(const void *)p));
}

VX_INLINE void vx_store4(NUM *p, __m256i v)
{
    const __m256i pick = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    _mm_storeu_si128((__m128i *)(void *)p, _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, pick)));
}

/* num_mul per lane (operands in int32's range) */
VX_INLINE __m256i vx_mul(__m256i a, __m256i b)
{
    __m256i p = _mm256_add_epi64(_mm256_mul_epi32(a, b), _mm256_set1_epi64x((int64_t)1 << 62));
    __m256i h = _mm256_sub_epi64(_mm256_srli_epi64(p, 16), _mm256_set1_epi64x((int64_t)1 << 46));
    return vx_acc_round(h, _mm256_and_si256(p, _mm256_set1_epi64x(0xFFFF)));
}

/* num_add per lane */
VX_INLINE __m256i vx_add(__m256i a, __m256i b)
{
    const __m256i hi = _mm256_set1_epi64x(INT32_MAX), lo = _mm256_set1_epi64x(INT32_MIN);
    __m256i t = _mm256_add_epi64(a, b);
    t = _mm256_blendv_epi8(t, hi, _mm256_cmpgt_epi64(t, hi));
    return _mm256_blendv_epi8(t, lo, _mm256_cmpgt_epi64(lo, t));
}

/* the term of every lane before its specular part, per channel k < 3:
**   cm:  num_mul(col[k], lamb[k]), plus num_mul(d, num_mul(col[k], ldif[k])) where d > 0
**   else amb[k],                   plus num_mul(d, dif[k])                   where d > 0
** with num_add; d = n . VP of the lane */
static void vx_dir_terms_avx2(const NUM *d, NUM (*col)[NUM_BATCH], const NUM *lamb, const NUM *ldif,
                              const NUM *amb, const NUM *dif, int cm, NUM (*term)[NUM_BATCH], int cnt)
{
    const __m256i zero = _mm256_setzero_si256();
    for (int i = 0; i < cnt; i += 4) {
        __m256i dv = vx_load4(d + i);
        __m256i pos = _mm256_cmpgt_epi64(dv, zero);
        for (int k = 0; k < 3; k++) {
            __m256i t, f;
            if (cm) {
                __m256i c = vx_load4(col[k] + i);
                t = vx_mul(c, _mm256_set1_epi64x(lamb[k]));
                f = vx_mul(c, _mm256_set1_epi64x(ldif[k]));
            } else {
                t = _mm256_set1_epi64x(amb[k]);
                f = _mm256_set1_epi64x(dif[k]);
            }
            __m256i lit = vx_add(t, vx_mul(dv, f));
            vx_store4(term[k] + i, _mm256_blendv_epi8(t, lit, pos));
        }
    }
}

/* acc[k] = num_add(acc[k], num_mul(scale, term[k])) for k < 3 */
static void vx_scale_add_avx2(NUM scale, NUM (*term)[NUM_BATCH], NUM (*acc)[NUM_BATCH], int cnt)
{
    const __m256i s = _mm256_set1_epi64x(scale);
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < cnt; i += 4)
            vx_store4(acc[k] + i, vx_add(vx_load4(acc[k] + i), vx_mul(s, vx_load4(term[k] + i))));
}
/* }==================================================================== */

/* {====================================================================
** num_normalize3 of four lanes at a time (GL_NORMALIZE).
**
** The scalar steps, per lane, and how each is formed here exactly:
**  * m = the largest num_abs of the three components: vpabsd gives |v| as
**    an unsigned 32-bit value (2^31 for INT32_MIN), vpminud with INT32_MAX
**    saturates it as num_abs does, vpmaxud takes the largest. m = 0 leaves
**    the lane unchanged (blended back at the end).
**  * sh = u64_bits(m) - 16: m (1 <= m < 2^31) converts to double exactly,
**    and its biased exponent e gives u64_bits(m) = e - 1022, so sh = e -
**    1038, in [-15, 15].
**  * w = v / 2^sh truncated toward zero for sh >= 0, v 2^-sh otherwise:
**    as sign and magnitude, (|v| >> max(sh, 0)) << max(-sh, 0) with the
**    sign put back (C's division truncates toward zero, so the quotient's
**    magnitude is floor(|v| / 2^sh)). |w| <= 2^16.
**  * ss = w0^2 + w1^2 + w2^2 (vpmuldq, exact; below 3 2^32), and
**    a = num_from_scaled(ss, 32) = (ss + 2^15) >> 16 for ss >= 0. The
**    largest |w| is at least 2^15, so a lies in [2^14, 3 2^16].
**  * num_rsqrt(a) = (isqrt(floor(2^62 / a)) + 64) >> 7, and for real X >= 0
**    floor(sqrt(floor(X))) = floor(sqrt(X)) (k = floor(sqrt(X)) has k^2 <=
**    floor(X)), so the root is r = floor(z) with z = 2^31 / sqrt(a), the one
**    integer with r^2 a <= 2^62 < (r + 1)^2 a. In double, y = 2^31 /
**    sqrt(a) with two correctly rounded operations (vsqrtpd, vdivpd) is
**    within 2^-52 z (1 + 2^-50) < 2^-27 of z (z <= 2^24), so floor(y) can
**    differ from r only where z lies within 2^-27 of an integer; over the
**    whole domain (the 180,225 values of a) floor(y) = r, which
**    tests/test_vertex_simd.py checks value by value with the same IEEE
**    operations, so floor(y) is the root.
**  * each component num_from_scaled(w inv, 32), |w inv| <= 2^33: vx_mul.
** The other lanes' values stay as they were (m = 0). */
/* the steps above for four lanes of int32 components v32[k]: out[k] the
** normalised components (sign-extended), *zero all-ones in the lanes whose
** vector is zero (out holds v there, as the scalar code leaves it) */
VX_INLINE void vx_normalize3_4(const __m128i v32[3], __m256i out[3], __m256i *zero)
{
    const __m256i z0 = _mm256_setzero_si256();
    const __m256i pick = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    __m256i v[3], w[3];
    __m128i m = _mm_setzero_si128();
    for (int k = 0; k < 3; k++) {
        m = _mm_max_epu32(m, _mm_min_epu32(_mm_abs_epi32(v32[k]), _mm_set1_epi32(INT32_MAX)));
        v[k] = _mm256_cvtepi32_epi64(v32[k]);
    }
    __m256i e = _mm256_srli_epi64(_mm256_castpd_si256(_mm256_cvtepi32_pd(m)), 52);
    __m256i sh = _mm256_sub_epi64(e, _mm256_set1_epi64x(1038)), nsh = _mm256_sub_epi64(z0, sh);
    __m256i shr = _mm256_andnot_si256(_mm256_cmpgt_epi64(z0, sh), sh);
    __m256i shl = _mm256_andnot_si256(_mm256_cmpgt_epi64(z0, nsh), nsh);
    __m256i ss = z0;
    for (int k = 0; k < 3; k++) {
        __m256i sg = _mm256_cmpgt_epi64(z0, v[k]);
        __m256i mag = _mm256_sub_epi64(_mm256_xor_si256(v[k], sg), sg);
        mag = _mm256_sllv_epi64(_mm256_srlv_epi64(mag, shr), shl);
        w[k] = _mm256_sub_epi64(_mm256_xor_si256(mag, sg), sg);
        ss = _mm256_add_epi64(ss, _mm256_mul_epi32(w[k], w[k]));
    }
    __m256i a = _mm256_srli_epi64(_mm256_add_epi64(ss, _mm256_set1_epi64x(1 << 15)), 16);
    __m256d ad = _mm256_cvtepi32_pd(_mm256_castsi256_si128(_mm256_permutevar8x32_epi32(a, pick)));
    __m256d yd = _mm256_floor_pd(_mm256_div_pd(_mm256_set1_pd(2147483648.0), _mm256_sqrt_pd(ad)));
    __m256i r = _mm256_cvtepi32_epi64(_mm256_cvttpd_epi32(yd));
    __m256i inv = _mm256_srli_epi64(_mm256_add_epi64(r, _mm256_set1_epi64x(64)), 7);
    *zero = _mm256_cmpeq_epi64(e, z0);                                      /* m = 0 */
    for (int k = 0; k < 3; k++)
        out[k] = _mm256_blendv_epi8(vx_mul(w[k], inv), v[k], *zero);
}

static void vx_normalize3_avx2(NUM *x, NUM *y, NUM *z, int cnt)
{
    NUM *rows[3] = { x, y, z };
    for (int i = 0; i < cnt; i += 4) {
        __m128i v32[3];
        __m256i out[3], zero;
        for (int k = 0; k < 3; k++)
            v32[k] = _mm_loadu_si128((const __m128i *)(const void *)(rows[k] + i));
        vx_normalize3_4(v32, out, &zero);
        for (int k = 0; k < 3; k++)
            vx_store4(rows[k] + i, out[k]);
    }
}
/* }==================================================================== */

/* {====================================================================
** A positional light's term (positional_batch in light.c), four lanes at
** a time in 64-bit lanes holding sign-extended NUMs. Every lane runs the
** whole body; a lane that the scalar code leaves with `continue` (the
** light at the vertex, the vertex outside the cone) or that is padding
** keeps its acc. num_pow is fxv_pow (fx_avx2.h) for the lanes that reach
** it.
**  * num_sub, num_add, num_neg: 64-bit sums clamped to int32's range;
**    num_mul: vx_mul; num_dot: the exact split sum of vx_dot_terms (three
**    lane-by-lane products, rounded once by vx_acc_round); num_normalize3:
**    vx_normalize3_4 (its zero mask is the scalar return value 0).
**  * The divisions i64_round_div(n, d) = sign * floor((|n| + floor(|d| /
**    2)) / |d|) are formed in double: with N = |n| + floor(|d| / 2) and
**    D = |d| > 0 integers, N + D < 2^53, q = floor(N / D) and q D <= N,
**    N / D lies in [q, q + 1 - 1/D]; rounding is monotone and q, q + 1 are
**    doubles, and fl(N / D) = q + 1 would need 1/D <= (q + 1) 2^-53, i.e.
**    (q + 1) D >= 2^53 > N + D. So floor(fl(N / D)) = q. Integers below
**    2^52 convert both ways exactly through the bits of 2^52 + x.
**  * length3: m the largest num_abs (m = 0 gives 0; dividing by max(m, 1)
**    then gives u = 0 and 0 too); u_k = num_div(vp_k, m), |u_k| <= 2^16
**    (|vp_k| <= m + 1 and 2^47 / (2^31 - 1) rounds to 2^16); the sum of
**    squares is below 3 2^32 and non-negative, so num_dot rounds it as
**    (S + 2^15) >> 16 = a; num_sqrt(a): v = 2^16 a < 2^34 and k = isqrt(v)
**    is floor(fl(sqrt(v))) (sqrt(v) < k + 1 - 1/(2k + 2), further from
**    k + 1 than its rounding error (k + 1) 2^-52), then k + 1 when
**    k^2 + k < v, as num_sqrt rounds; d = num_mul(m, root).
**  * att = num_recip(den) = num_div(2^16, den): N = 2^32 + floor(|den| /
**    2) < 2^33; den = 0 divides by 1 instead, 2^32, which saturates to
**    NUM_MAX as num_div's zero case returns. */
/* (the parameters are VxPositional, above) */

/* num_sub per lane */
VX_INLINE __m256i vx_sub(__m256i a, __m256i b)
{
    const __m256i hi = _mm256_set1_epi64x(INT32_MAX), lo = _mm256_set1_epi64x(INT32_MIN);
    __m256i t = _mm256_sub_epi64(a, b);
    t = _mm256_blendv_epi8(t, hi, _mm256_cmpgt_epi64(t, hi));
    return _mm256_blendv_epi8(t, lo, _mm256_cmpgt_epi64(lo, t));
}

/* the four int32 values of 64-bit lanes in int32 range */
VX_INLINE __m128i vx_pack4(__m256i v)
{
    return _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
}

/* x in [0, 2^52) to double and back, through the bits of 2^52 + x */
VX_INLINE __m256d vx_u52_to_pd(__m256i x)
{
    const __m256d two52 = _mm256_set1_pd(4503599627370496.0);
    return _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(x, _mm256_castpd_si256(two52))), two52);
}

VX_INLINE __m256i vx_pd_to_u52(__m256d x)
{
    const __m256d two52 = _mm256_set1_pd(4503599627370496.0);
    return _mm256_xor_si256(_mm256_castpd_si256(_mm256_add_pd(x, two52)), _mm256_castpd_si256(two52));
}

/* floor((n + floor(d / 2)) / d) for n >= 0, d > 0, n + d + d / 2 < 2^52 */
VX_INLINE __m256i vx_round_div_u(__m256i n, __m256i d)
{
    __m256d q = _mm256_div_pd(vx_u52_to_pd(_mm256_add_epi64(n, _mm256_srli_epi64(d, 1))), vx_u52_to_pd(d));
    return vx_pd_to_u52(_mm256_floor_pd(q));
}

/* num_dot of two lanes' 3-vectors */
VX_INLINE __m256i vx_dot3v(const __m256i a[3], const __m256i b[3])
{
    const __m256i bias = _mm256_set1_epi64x((int64_t)1 << 62), low = _mm256_set1_epi64x(0xFFFF);
    __m256i sh = _mm256_set1_epi64x(-3 * ((int64_t)1 << 46)), sl = _mm256_setzero_si256();
    for (int k = 0; k < 3; k++) {
        __m256i p = _mm256_add_epi64(_mm256_mul_epi32(a[k], b[k]), bias);
        sh = _mm256_add_epi64(sh, _mm256_srli_epi64(p, 16));
        sl = _mm256_add_epi64(sl, _mm256_and_si256(p, low));
    }
    return vx_acc_round(sh, sl);
}

/* length3 (light.c) per lane */
VX_INLINE __m256i vx_length3(const __m256i v[3])
{
    const __m256i z0 = _mm256_setzero_si256(), max32 = _mm256_set1_epi64x(INT32_MAX);
    __m256i a[3], m = z0;
    for (int k = 0; k < 3; k++) {
        __m256i sg = _mm256_cmpgt_epi64(z0, v[k]);
        a[k] = _mm256_sub_epi64(_mm256_xor_si256(v[k], sg), sg);                /* |v|, up to 2^31 */
        __m256i c = _mm256_blendv_epi8(a[k], max32, _mm256_cmpgt_epi64(a[k], max32));
        m = _mm256_blendv_epi8(m, c, _mm256_cmpgt_epi64(c, m));
    }
    __m256i d = _mm256_or_si256(m, _mm256_srli_epi64(_mm256_cmpeq_epi64(m, z0), 63));  /* max(m, 1) */
    __m256i s = z0;
    for (int k = 0; k < 3; k++) {
        __m256i u = vx_round_div_u(_mm256_slli_epi64(a[k], 16), d);           /* |u_k|: the sign squares away */
        s = _mm256_add_epi64(s, _mm256_mul_epu32(u, u));
    }
    __m256i v16 = _mm256_slli_epi64(_mm256_srli_epi64(_mm256_add_epi64(s, _mm256_set1_epi64x(1 << 15)), 16), 16);
    __m256i r = vx_pd_to_u52(_mm256_floor_pd(_mm256_sqrt_pd(vx_u52_to_pd(v16))));
    __m256i up = _mm256_cmpgt_epi64(v16, _mm256_add_epi64(_mm256_mul_epu32(r, r), r));   /* -1: round up */
    return vx_mul(m, _mm256_sub_epi64(r, up));
}

/* num_recip per lane */
VX_INLINE __m256i vx_recip(__m256i den)
{
    const __m256i z0 = _mm256_setzero_si256();
    __m256i sg = _mm256_cmpgt_epi64(z0, den);
    __m256i ad = _mm256_sub_epi64(_mm256_xor_si256(den, sg), sg);
    ad = _mm256_or_si256(ad, _mm256_srli_epi64(_mm256_cmpeq_epi64(ad, z0), 63));
    __m256i q = vx_round_div_u(_mm256_set1_epi64x((int64_t)1 << 32), ad);
    return vx_sub(_mm256_xor_si256(q, sg), sg);       /* the sign, then the clamp of num_sat */
}

/* num_pow(x[j], s) for the lanes j set in `bits`, 0 in the others:
** fxv_pow for an exponent in its range [0, 128], else lane by lane */
VX_INLINE __m256i vx_pow_lanes(__m256i x, NUM s, int bits)
{
    if (s >= 0 && s <= 128 * NUM_ONE) {
        const __m256i sel = _mm256_cmpgt_epi64(
            _mm256_and_si256(_mm256_set1_epi64x(bits), _mm256_setr_epi64x(1, 2, 4, 8)), _mm256_setzero_si256());
        return _mm256_and_si256(fxv_pow(x, s), sel);
    }
    int64_t xv[4], r[4] = { 0, 0, 0, 0 };
    _mm256_storeu_si256((__m256i *)(void *)xv, x);
    for (int j = 0; j < 4; j++)
        if (bits >> j & 1)
            r[j] = num_pow((NUM)xv[j], s);
    return _mm256_setr_epi64x(r[0], r[1], r[2], r[3]);
}

/* num_pow(x[i], s) of lanes 0..n-1 (n a multiple of 4) */
static void vx_pow_avx2(const NUM *x, NUM s, NUM *out, int n)
{
    for (int i = 0; i < n; i += 4)
        vx_store4(out + i, vx_pow_lanes(vx_load4(x + i), s, 15));
}

/* fx_exp2(y[i]) of lanes 0..n-1 (n a multiple of 4, |y| < 2^62) */
static void vx_exp2_avx2(const int64_t *y, NUM *out, int n)
{
    for (int i = 0; i < n; i += 4)
        vx_store4(out + i, fxv_exp2(_mm256_loadu_si256((const __m256i *)(const void *)(y + i))));
}

/* the specular terms of a directional light's lanes 0..n-1 (n <= cnt):
** where n . VP > 0 and n . h > 0, term[k] = num_add(term[k],
** num_mul(num_pow(n . h, shin), spec[k])) (light.c's directional_batch) */
static void vx_specular_avx2(const NUM *ndotvp, const NUM *ndoth, NUM shin, const NUM spec[3],
                             NUM (*term)[NUM_BATCH], int n)
{
    const __m256i z0 = _mm256_setzero_si256(), ramp = _mm256_setr_epi64x(0, 1, 2, 3);
    for (int i = 0; i < n; i += 4) {
        const __m256i d = vx_load4(ndotvp + i), h = vx_load4(ndoth + i);
        const __m256i live = _mm256_cmpgt_epi64(_mm256_set1_epi64x(n - i), ramp);
        const __m256i use = _mm256_and_si256(live, _mm256_and_si256(_mm256_cmpgt_epi64(d, z0),
                                                                     _mm256_cmpgt_epi64(h, z0)));
        const int bits = _mm256_movemask_pd(_mm256_castsi256_pd(use));
        if (!bits)
            continue;
        const __m256i sp = vx_pow_lanes(h, shin, bits);
        for (int k = 0; k < 3; k++) {
            const __m256i t = vx_load4(term[k] + i);
            vx_store4(term[k] + i,
                      _mm256_blendv_epi8(t, vx_add(t, vx_mul(sp, _mm256_set1_epi64x(spec[k]))), use));
        }
    }
}

/* acc[k] += the light's term for lanes 0..cnt-1 (lanes n..cnt-1 untouched);
** v: the eye positions over w, nrm: the normals, col: the vertex colours,
** read when `cm`. In passes over the batch's groups of four, each a short
** chain (the distance and attenuation, the direction and spot factor, the
** half vector, the terms): the groups of one pass are independent, so the
** core overlaps their divisions, square roots and table lookups, which one
** long chain per group left waiting on each other. Each lane's operations
** are those of one pass per group, in the same order. */
static void vx_positional_avx2(const VxPositional *L, NUM (*v)[NUM_BATCH], NUM (*nrm)[NUM_BATCH],
                               NUM (*col)[NUM_BATCH], NUM (*acc)[NUM_BATCH], int n, int cnt, int cm)
{
    const __m256i z0 = _mm256_setzero_si256(), one = _mm256_set1_epi64x(NUM_ONE);
    const __m256i ramp = _mm256_setr_epi64x(0, 1, 2, 3);
    enum { GROUPS = NUM_BATCH / 4 };
    __m256i u[GROUPS][3], dist[GROUPS], dead[GROUPS], scale[GROUPS], h[GROUPS][3], hzero[GROUPS];
    const int groups = (cnt + 3) / 4;
    /* the direction to the light, its distance, the padding lanes */
    for (int g = 0; g < groups; g++) {
        const int i = 4 * g;
        __m256i vp[3];
        __m128i vp32[3];
        for (int k = 0; k < 3; k++) {
            vp[k] = vx_sub(_mm256_set1_epi64x(L->p[k]), vx_load4(v[k] + i));
            vp32[k] = vx_pack4(vp[k]);
        }
        if (L->attenuate)
            dist[g] = vx_length3(vp);
        vx_normalize3_4(vp32, u[g], &dead[g]);
        dead[g] = _mm256_or_si256(dead[g], _mm256_cmpgt_epi64(_mm256_add_epi64(ramp, _mm256_set1_epi64x(i)),
                                                              _mm256_set1_epi64x(n - 1)));   /* padding */
    }
    /* the attenuation and the spot factor */
    for (int g = 0; g < groups; g++) {
        __m256i att = one;
        if (L->attenuate) {
            const __m256i d = dist[g];
            __m256i t2 = vx_mul(vx_mul(_mm256_set1_epi64x(L->ka[2]), d), d);
            __m256i den = vx_add(_mm256_set1_epi64x(L->ka[0]), vx_add(vx_mul(_mm256_set1_epi64x(L->ka[1]), d), t2));
            att = vx_recip(den);
        }
        __m256i spot = one;
        if (L->spot) {
            __m256i sd[3] = { _mm256_set1_epi64x(L->sdir[0]), _mm256_set1_epi64x(L->sdir[1]),
                              _mm256_set1_epi64x(L->sdir[2]) };
            __m256i cosang = vx_sub(z0, vx_dot3v(u[g], sd));
            dead[g] = _mm256_or_si256(dead[g], _mm256_cmpgt_epi64(_mm256_set1_epi64x(L->cos_cutoff), cosang));
            int live = ~_mm256_movemask_pd(_mm256_castsi256_pd(dead[g])) & 15;
            if (!live)
                continue;
            spot = vx_pow_lanes(cosang, L->spot_exp, live);
        }
        scale[g] = vx_mul(att, spot);
    }
    /* the half vectors (u + (0, 0, 1), normalized) */
    if (L->specular)
        for (int g = 0; g < groups; g++) {
            if (_mm256_movemask_pd(_mm256_castsi256_pd(dead[g])) == 15)
                continue;
            __m128i h32[3] = { vx_pack4(u[g][0]), vx_pack4(u[g][1]), vx_pack4(vx_add(u[g][2], one)) };
            vx_normalize3_4(h32, h[g], &hzero[g]);
        }
    /* the terms, into acc */
    for (int g = 0; g < groups; g++) {
        const int i = 4 * g;
        if (_mm256_movemask_pd(_mm256_castsi256_pd(dead[g])) == 15)
            continue;
        __m256i nv[3];
        for (int k = 0; k < 3; k++)
            nv[k] = vx_load4(nrm[k] + i);
        __m256i ndotvp = vx_dot3v(nv, u[g]);
        __m256i pos = _mm256_cmpgt_epi64(ndotvp, z0);
        __m256i term[3];
        for (int k = 0; k < 3; k++) {
            __m256i t, f;
            if (cm) {
                __m256i c = vx_load4(col[k] + i);
                t = vx_mul(c, _mm256_set1_epi64x(L->lamb[k]));
                f = vx_mul(c, _mm256_set1_epi64x(L->ldif[k]));
            } else {
                t = _mm256_set1_epi64x(L->amb[k]);
                f = _mm256_set1_epi64x(L->dif[k]);
            }
            term[k] = _mm256_blendv_epi8(t, vx_add(t, vx_mul(ndotvp, f)), pos);
        }
        if (L->specular) {
            __m256i ndoth = vx_dot3v(nv, h[g]);
            __m256i use = _mm256_andnot_si256(_mm256_or_si256(dead[g], hzero[g]),
                                              _mm256_and_si256(pos, _mm256_cmpgt_epi64(ndoth, z0)));
            int bits = _mm256_movemask_pd(_mm256_castsi256_pd(use));
            if (bits) {
                __m256i sp = vx_pow_lanes(ndoth, L->shin, bits);
                for (int k = 0; k < 3; k++)
                    term[k] = _mm256_blendv_epi8(term[k], vx_add(term[k], vx_mul(sp, _mm256_set1_epi64x(L->spec[k]))), use);
            }
        }
        for (int k = 0; k < 3; k++) {
            __m256i a = vx_load4(acc[k] + i);
            vx_store4(acc[k] + i, _mm256_blendv_epi8(vx_add(a, vx_mul(scale[g], term[k])), a, dead[g]));
        }
    }
}
/* }==================================================================== */

/* {====================================================================
** Window coordinates of vertices inside every plane (vertex_window's
** num_proj, recipw_of and depthv_from_clip), four lanes at a time. Lanes
** with a clip code get meaningless values that the caller does not store.
** Inside every plane, w >= 1 and |x|, |y|, |z| <= w (each num_add(w, x) and
** num_sub(w, x) is an exact sum whose sign survives the saturation).
**  * num_proj: i64_round_div(x h, w) = sign(x) floor((|x| h + floor(w / 2))
**    / w) for the viewport's half size h >= 0 (a zero h gives 0 both
**    ways). With h < 2^21 (checked by the caller) N = |x| h + floor(w / 2)
**    < 2^53 is exact in double (|x| h is one product of integers below
**    2^31 and 2^21), and floor(fl(N / w)) = floor(N / w) by the argument
**    of vx_round_div_u. The clamp to +-2^20 is kept although |x| <= w
**    keeps the quotient within h.
**  * recipw_of: with k = floor(log2 w) (the exponent of w's exact double),
**    r = floor(2^62 / w) has 63 - k bits when w is a power of two and 62 - k
**    otherwise, so rb = 32 - k + [w is a power of two] (>= 2) and mant =
**    r >> rb = floor(2^(62 - rb) / w) (nested floors). The double quotient
**    of the exact 2^(62 - rb) by w is within 2^-22 of the true one (below
**    2^30), so its floor q0 is mant or mant + 1; q0 w > 2^(62 - rb), in
**    exact 64-bit integers (vpmuludq of values below 2^31), takes the 1
**    back.
**  * depthv_from_clip: zs = sign(z) floor((|z| 2^30 + floor(w / 2)) / w),
**    at most 2^30: the double quotient of the rounded numerator is within
**    2^-21 of the true one, and one exact comparison each way (q0 w against
**    the 64-bit numerator) corrects it. Then (f30 - n30)(zs + 2^30) / 2^31
**    truncates toward zero as sign(c) floor(|c| t / 2^31) with |c| <= 2^30
**    and t in [0, 2^31] (vpmuludq, exact), and the clamped d30 times the
**    depth maximum (below 2^32) is one exact vpmuludq. */
typedef struct VxWindow {
    int64_t ox, oy, hx, hy;      /* the viewport's centre and half size in subpixels */
    int64_t n30, c30;            /* near and far - near in 0.30 */
    uint32_t depth_max;
} VxWindow;

/* sign(x) floor((|x| h + floor(w / 2)) / w), w the lanes' double */
VX_INLINE __m256i vx_proj4(__m128i x32, __m256d wd, __m256d halfw, double h)
{
    __m256d x = _mm256_cvtepi32_pd(x32);
    __m256d sgn = _mm256_and_pd(x, _mm256_set1_pd(-0.0));
    __m256d n = _mm256_add_pd(_mm256_mul_pd(_mm256_andnot_pd(_mm256_set1_pd(-0.0), x), _mm256_set1_pd(h)), halfw);
    __m256d q = _mm256_or_pd(_mm256_floor_pd(_mm256_div_pd(n, wd)), sgn);
    q = _mm256_max_pd(_mm256_min_pd(q, _mm256_set1_pd(1048576.0)), _mm256_set1_pd(-1048576.0));
    return _mm256_cvtepi32_epi64(_mm256_cvttpd_epi32(q));
}

static void vx_window_avx2(const VxWindow *W, const NUM *x, const NUM *y, const NUM *z, const NUM *w, int cnt,
                           int64_t *wx, int64_t *wy, int64_t *mant, int64_t *rexp, int64_t *wz)
{
    const __m256i one64 = _mm256_set1_epi64x(1);
    const __m256i c_abs = _mm256_set1_epi64x(W->c30 < 0 ? -W->c30 : W->c30);
    const __m256i c_sg = _mm256_set1_epi64x(W->c30 < 0 ? -1 : 0);
    const __m256i max30 = _mm256_set1_epi64x((int64_t)1 << 30), min30 = _mm256_set1_epi64x(-((int64_t)1 << 30));
    for (int i = 0; i < cnt; i += 4) {
        __m128i w32 = _mm_loadu_si128((const __m128i *)(const void *)(w + i));
        __m256i w64 = _mm256_cvtepi32_epi64(w32);
        /* floor(w / 2) for w >= 1 (other lanes: any value below 2^31, unused) */
        __m256i hw64 = _mm256_and_si256(_mm256_srli_epi64(w64, 1), _mm256_set1_epi64x(0x7FFFFFFF));
        __m256d wd = _mm256_cvtepi32_pd(w32), halfw = _mm256_cvtepi32_pd(vx_pack4(hw64));
        __m256i px = vx_proj4(_mm_loadu_si128((const __m128i *)(const void *)(x + i)), wd, halfw, (double)W->hx);
        __m256i py = vx_proj4(_mm_loadu_si128((const __m128i *)(const void *)(y + i)), wd, halfw, (double)W->hy);
        _mm256_storeu_si256((__m256i *)(void *)(wx + i), _mm256_add_epi64(px, _mm256_set1_epi64x(W->ox)));
        _mm256_storeu_si256((__m256i *)(void *)(wy + i), _mm256_add_epi64(py, _mm256_set1_epi64x(W->oy)));
        /* recipw_of */
        __m256i k = _mm256_sub_epi64(_mm256_srli_epi64(_mm256_castpd_si256(wd), 52), _mm256_set1_epi64x(1023));
        __m256i p2 = _mm256_srli_epi64(
            _mm256_cmpeq_epi64(_mm256_and_si256(w64, _mm256_sub_epi64(w64, one64)), _mm256_setzero_si256()), 63);
        __m256i en = _mm256_sub_epi64(_mm256_add_epi64(k, _mm256_set1_epi64x(30)), p2);    /* 62 - rb */
        __m256d nd = _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(en, _mm256_set1_epi64x(1023)), 52));
        __m256i q0 = vx_pd_to_u52(_mm256_floor_pd(_mm256_div_pd(nd, wd)));
        __m256i over = _mm256_cmpgt_epi64(_mm256_mul_epu32(q0, w64), _mm256_sllv_epi64(one64, en));
        _mm256_storeu_si256((__m256i *)(void *)(mant + i), _mm256_add_epi64(q0, over));
        _mm256_storeu_si256((__m256i *)(void *)(rexp + i), _mm256_sub_epi64(_mm256_set1_epi64x(32), _mm256_sub_epi64(k, p2)));
        /* depthv_from_clip */
        __m128i z32 = _mm_loadu_si128((const __m128i *)(const void *)(z + i));
        __m256i z64 = _mm256_cvtepi32_epi64(z32);
        __m256i zsg = _mm256_cmpgt_epi64(_mm256_setzero_si256(), z64);
        __m256i za = _mm256_sub_epi64(_mm256_xor_si256(z64, zsg), zsg);
        __m256i nz = _mm256_add_epi64(_mm256_slli_epi64(za, 30), hw64);                  /* exact */
        __m256d nzd = _mm256_add_pd(_mm256_mul_pd(_mm256_andnot_pd(_mm256_set1_pd(-0.0), _mm256_cvtepi32_pd(z32)),
                                                  _mm256_set1_pd(1073741824.0)), halfw);
        __m256i zq = vx_pd_to_u52(_mm256_floor_pd(_mm256_div_pd(nzd, wd)));
        __m256i prod = _mm256_mul_epu32(zq, w64);
        zq = _mm256_add_epi64(zq, _mm256_cmpgt_epi64(prod, nz));                          /* q0 w > N: q0 - 1 */
        zq = _mm256_sub_epi64(zq, _mm256_cmpgt_epi64(_mm256_sub_epi64(nz, prod), _mm256_sub_epi64(w64, one64)));
        __m256i zs = _mm256_sub_epi64(_mm256_xor_si256(zq, zsg), zsg);
        zs = _mm256_blendv_epi8(zs, max30, _mm256_cmpgt_epi64(zs, max30));
        zs = _mm256_blendv_epi8(zs, min30, _mm256_cmpgt_epi64(min30, zs));
        __m256i t = _mm256_srli_epi64(_mm256_mul_epu32(c_abs, _mm256_add_epi64(zs, max30)), 31);
        __m256i d30 = _mm256_add_epi64(_mm256_set1_epi64x(W->n30), _mm256_sub_epi64(_mm256_xor_si256(t, c_sg), c_sg));
        d30 = _mm256_blendv_epi8(d30, max30, _mm256_cmpgt_epi64(d30, max30));
        d30 = _mm256_andnot_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), d30), d30);
        __m256i dz = _mm256_mul_epu32(d30, _mm256_set1_epi64x((int64_t)W->depth_max));
        _mm256_storeu_si256((__m256i *)(void *)(wz + i), _mm256_srli_epi64(_mm256_add_epi64(dz, _mm256_set1_epi64x(8192)), 14));
    }
}
/* }==================================================================== */

/* a directional light without a specular part in one pass: n . VP as in
** vx_dot3v (the split sum: a zero coefficient adds exactly 0, so this is
** the sum vx_dot3_lanes forms), the term of vx_dir_terms_avx2, and acc[k] =
** num_add(acc[k], num_mul(scale, term[k])) as vx_scale_add_avx2 forms it;
** num_mul(NUM_ONE, t) is t exactly (t 2^16 / 2^16 needs no rounding and t
** is in range), so a scale of one skips the product. */
static void vx_dir_fused_avx2(const NUM *vp, NUM (*nrm)[NUM_BATCH], NUM (*col)[NUM_BATCH], const NUM *lamb,
                              const NUM *ldif, const NUM *amb, const NUM *dif, int cm, NUM scale,
                              NUM (*acc)[NUM_BATCH], int cnt)
{
    const __m256i zero = _mm256_setzero_si256(), s = _mm256_set1_epi64x(scale);
    const __m256i p[3] = { _mm256_set1_epi64x(vp[0]), _mm256_set1_epi64x(vp[1]), _mm256_set1_epi64x(vp[2]) };
    for (int i = 0; i < cnt; i += 4) {
        __m256i nv[3] = { vx_load4(nrm[0] + i), vx_load4(nrm[1] + i), vx_load4(nrm[2] + i) };
        __m256i dv = vx_dot3v(nv, p);
        __m256i pos = _mm256_cmpgt_epi64(dv, zero);
        for (int k = 0; k < 3; k++) {
            __m256i t, f;
            if (cm) {
                __m256i c = vx_load4(col[k] + i);
                t = vx_mul(c, _mm256_set1_epi64x(lamb[k]));
                f = vx_mul(c, _mm256_set1_epi64x(ldif[k]));
            } else {
                t = _mm256_set1_epi64x(amb[k]);
                f = _mm256_set1_epi64x(dif[k]);
            }
            t = _mm256_blendv_epi8(t, vx_add(t, vx_mul(dv, f)), pos);
            if (scale != NUM_ONE)
                t = vx_mul(s, t);
            vx_store4(acc[k] + i, vx_add(vx_load4(acc[k] + i), t));
        }
    }
}

#endif /* VERTEX_AVX2 */

#if VERTEX_AVX2_FP
/* {====================================================================
** Window coordinates in the float builds (num_proj, recipw_of and
** depthv_from_clip of num.h), four lanes at a time with the same IEEE
** operations in the same order and precision: x / w, times (NUM)scale,
** widened to double (exact); then dbl_to_i64(|v|, 0, 2^20) as floor(|v| +
** 1/2) (vaddpd rounds as addsd, vroundpd's floor is exact) limited to
** 2^20 by a minimum (|v| >= 2^20 gives at least 2^20, infinity included;
** below, floor(|v| + 1/2) <= 2^20 already; |v| = 0 gives 0 as the early
** return does), NaN lanes zeroed, and the sign of v < 0 put back (the
** scalar code negates only for v < 0; -0 gives 0 either way). The clamps
** of depthv_from_clip are blends on the same comparisons, so a NaN passes
** through them as it does in C. Lanes outside a plane are not stored. */
#if defined(GLES_NUM_FLOAT)
typedef __m128 VxNum4;
#define VXN_LOAD(p) _mm_loadu_ps(p)
#define VXN_STORE(p, v) _mm_storeu_ps(p, v)
#define VXN_SET1(x) _mm_set1_ps(x)
#define VXN_DIV _mm_div_ps
#define VXN_MUL _mm_mul_ps
#define VXN_ADD _mm_add_ps
#define VXN_SUB _mm_sub_ps
#define VXN_LT(a, b) _mm_cmplt_ps(a, b)
#define VXN_BLEND(a, b, m) _mm_blendv_ps(a, b, m)
#define VXN_TO_PD(v) _mm256_cvtps_pd(v)
#define VXN_SQRT _mm_sqrt_ps
#define VXN_GT(a, b) _mm_cmpgt_ps(a, b)
#define VXN_EQ(a, b) _mm_cmpeq_ps(a, b)
#define VXN_OR _mm_or_ps
#define VXN_AND _mm_and_ps
#define VXN_ANDNOT _mm_andnot_ps
#define VXN_XOR _mm_xor_ps
#define VXN_MASK(m) _mm_movemask_ps(m)
#define VXN_SETR(a) _mm_setr_ps(a[0], a[1], a[2], a[3])
#else
typedef __m256d VxNum4;
#define VXN_LOAD(p) _mm256_loadu_pd(p)
#define VXN_STORE(p, v) _mm256_storeu_pd(p, v)
#define VXN_SET1(x) _mm256_set1_pd(x)
#define VXN_DIV _mm256_div_pd
#define VXN_MUL _mm256_mul_pd
#define VXN_ADD _mm256_add_pd
#define VXN_SUB _mm256_sub_pd
#define VXN_LT(a, b) _mm256_cmp_pd(a, b, _CMP_LT_OQ)
#define VXN_BLEND(a, b, m) _mm256_blendv_pd(a, b, m)
#define VXN_TO_PD(v) (v)
#define VXN_SQRT _mm256_sqrt_pd
#define VXN_GT(a, b) _mm256_cmp_pd(a, b, _CMP_GT_OQ)
#define VXN_EQ(a, b) _mm256_cmp_pd(a, b, _CMP_EQ_OQ)
#define VXN_OR _mm256_or_pd
#define VXN_AND _mm256_and_pd
#define VXN_ANDNOT _mm256_andnot_pd
#define VXN_XOR _mm256_xor_pd
#define VXN_MASK(m) _mm256_movemask_pd(m)
#define VXN_SETR(a) _mm256_setr_pd(a[0], a[1], a[2], a[3])
#endif

/* num_proj of four lanes: an int64 per lane */
VX_INLINE __m256i vx_proj4_fp(VxNum4 x, VxNum4 w, VxNum4 scale)
{
    __m256d v = VXN_TO_PD(VXN_MUL(VXN_DIV(x, w), scale));
    const __m256d sign = _mm256_set1_pd(-0.0);
    __m256d a = _mm256_andnot_pd(sign, v);
    __m256d r = _mm256_floor_pd(_mm256_add_pd(a, _mm256_set1_pd(0.5)));
    r = _mm256_min_pd(r, _mm256_set1_pd(1048576.0));
    r = _mm256_and_pd(r, _mm256_cmp_pd(v, v, _CMP_ORD_Q));                       /* NaN: 0 */
    r = _mm256_or_pd(r, _mm256_and_pd(sign, _mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_LT_OQ)));
    return _mm256_cvtepi32_epi64(_mm256_cvttpd_epi32(r));
}

static void vx_window_fp_avx2(const NUM *x, const NUM *y, const NUM *z, const NUM *w, int cnt, int64_t ox,
                              int64_t oy, int64_t hx, int64_t hy, NUM dn, NUM df, uint32_t maxval, int64_t *wx,
                              int64_t *wy, NUM *rw, NUM *wz)
{
    const VxNum4 sx = VXN_SET1((NUM)hx), sy = VXN_SET1((NUM)hy), one = VXN_SET1((NUM)1), zero = VXN_SET1((NUM)0);
    const VxNum4 mone = VXN_SET1((NUM)-1), half = VXN_SET1((NUM)0.5), n = VXN_SET1(dn), fn = VXN_SET1(df - dn);
    const VxNum4 mx = VXN_SET1((NUM)maxval);
    for (int i = 0; i < cnt; i += 4) {
        VxNum4 wv = VXN_LOAD(w + i);
        _mm256_storeu_si256((__m256i *)(void *)(wx + i),
                            _mm256_add_epi64(vx_proj4_fp(VXN_LOAD(x + i), wv, sx), _mm256_set1_epi64x(ox)));
        _mm256_storeu_si256((__m256i *)(void *)(wy + i),
                            _mm256_add_epi64(vx_proj4_fp(VXN_LOAD(y + i), wv, sy), _mm256_set1_epi64x(oy)));
        VXN_STORE(rw + i, VXN_DIV(one, wv));
        VxNum4 zs = VXN_DIV(VXN_LOAD(z + i), wv);
        zs = VXN_BLEND(VXN_BLEND(zs, one, VXN_LT(one, zs)), mone, VXN_LT(zs, mone));
        VxNum4 d = VXN_ADD(n, VXN_MUL(VXN_MUL(fn, VXN_ADD(zs, one)), half));
        d = VXN_BLEND(VXN_BLEND(d, one, VXN_LT(one, d)), zero, VXN_LT(d, zero));
        VXN_STORE(wz + i, VXN_MUL(d, mx));
    }
}
/* }==================================================================== */

/* {====================================================================
** A positional light's term in the float builds (positional_batch),
** four lanes at a time: num.h's float operations are single IEEE
** operations, here in the same order (num_dot from 0: ((0 + p0) + p1) +
** p2; num_abs, num_max, num_sqrt, num_rsqrt and the tests as blends on the
** same comparisons, so NaN and -0 take the scalar branches), with a lane
** mask for the scalar code's `continue`s and for padding; num_pow stays
** scalar for the lanes that reach it. */
/* (the parameters are VxPositional, above) */

VX_INLINE VxNum4 vxn_dot3(const VxNum4 a[3], const VxNum4 b[3])
{
    VxNum4 acc = VXN_ADD(VXN_SET1((NUM)0), VXN_MUL(a[0], b[0]));
    acc = VXN_ADD(acc, VXN_MUL(a[1], b[1]));
    return VXN_ADD(acc, VXN_MUL(a[2], b[2]));
}

/* num_max(num_abs(v0), num_max(num_abs(v1), num_abs(v2))) */
VX_INLINE VxNum4 vxn_maxabs3(const VxNum4 v[3])
{
    const VxNum4 z = VXN_SET1((NUM)0), sg = VXN_SET1((NUM)-0.0);
    VxNum4 a[3];
    for (int k = 0; k < 3; k++)
        a[k] = VXN_BLEND(v[k], VXN_XOR(v[k], sg), VXN_LT(v[k], z));
    VxNum4 m = VXN_BLEND(a[2], a[1], VXN_GT(a[1], a[2]));
    return VXN_BLEND(m, a[0], VXN_GT(a[0], m));
}

/* num_normalize3 in place; returns the mask of lanes where it returns 0 */
VX_INLINE VxNum4 vxn_normalize3(VxNum4 v[3])
{
    const VxNum4 z = VXN_SET1((NUM)0);
    VxNum4 zero = VXN_EQ(vxn_maxabs3(v), z);
    VxNum4 a = vxn_dot3(v, v);
    VxNum4 inv = VXN_BLEND(VXN_SET1(NUM_MAX), VXN_DIV(VXN_SET1((NUM)1), VXN_SQRT(a)), VXN_GT(a, z));
    for (int k = 0; k < 3; k++)
        v[k] = VXN_BLEND(VXN_MUL(v[k], inv), v[k], zero);
    return zero;
}

/* num_pow(x[j], s) for the lanes j set in `bits`, 0 in the others */
VX_INLINE VxNum4 vxn_pow_lanes(VxNum4 x, NUM s, int bits)
{
    NUM xv[4], r[4] = { 0, 0, 0, 0 };
    VXN_STORE(xv, x);
    for (int j = 0; j < 4; j++)
        if (bits >> j & 1)
            r[j] = num_pow(xv[j], s);
    return VXN_SETR(r);
}

static void vx_positional_fp_avx2(const VxPositional *L, NUM (*v)[NUM_BATCH], NUM (*nrm)[NUM_BATCH],
                                  NUM (*col)[NUM_BATCH], NUM (*acc)[NUM_BATCH], int n, int cnt, int cm)
{
    const VxNum4 z = VXN_SET1((NUM)0), one = VXN_SET1((NUM)1), sg = VXN_SET1((NUM)-0.0);
    for (int i = 0; i < cnt; i += 4) {
        VxNum4 vp[3], nv[3];
        for (int k = 0; k < 3; k++)
            vp[k] = VXN_SUB(VXN_SET1(L->p[k]), VXN_LOAD(v[k] + i));
        VxNum4 att = one;
        if (L->attenuate) {
            /* length3 */
            VxNum4 m = vxn_maxabs3(vp), u[3];
            for (int k = 0; k < 3; k++)
                u[k] = VXN_DIV(vp[k], m);
            VxNum4 a = vxn_dot3(u, u);
            VxNum4 r = VXN_AND(VXN_SQRT(a), VXN_GT(a, z));
            VxNum4 d = VXN_ANDNOT(VXN_EQ(m, z), VXN_MUL(m, r));
            VxNum4 t2 = VXN_MUL(VXN_MUL(VXN_SET1(L->ka[2]), d), d);
            VxNum4 den = VXN_ADD(VXN_SET1(L->ka[0]), VXN_ADD(VXN_MUL(VXN_SET1(L->ka[1]), d), t2));
            att = VXN_DIV(one, den);
        }
        VxNum4 dead = vxn_normalize3(vp);
        int pad = 0;
        for (int j = 0; j < 4; j++)
            pad |= (i + j >= n) << j;
        int live = ~(VXN_MASK(dead) | pad) & 15;
        VxNum4 spot = one;
        if (L->spot) {
            VxNum4 s[3] = { VXN_SET1(L->sdir[0]), VXN_SET1(L->sdir[1]), VXN_SET1(L->sdir[2]) };
            VxNum4 cosang = VXN_XOR(vxn_dot3(vp, s), sg);
            live &= ~VXN_MASK(VXN_LT(cosang, VXN_SET1(L->cos_cutoff)));
            if (!live)
                continue;
            spot = vxn_pow_lanes(cosang, L->spot_exp, live);
        }
        if (!live)
            continue;
        VxNum4 scale = VXN_MUL(att, spot);
        for (int k = 0; k < 3; k++)
            nv[k] = VXN_LOAD(nrm[k] + i);
        VxNum4 ndotvp = vxn_dot3(nv, vp);
        VxNum4 pos = VXN_GT(ndotvp, z);
        VxNum4 term[3];
        for (int k = 0; k < 3; k++) {
            VxNum4 t, f;
            if (cm) {
                VxNum4 c = VXN_LOAD(col[k] + i);
                t = VXN_MUL(c, VXN_SET1(L->lamb[k]));
                f = VXN_MUL(c, VXN_SET1(L->ldif[k]));
            } else {
                t = VXN_SET1(L->amb[k]);
                f = VXN_SET1(L->dif[k]);
            }
            term[k] = VXN_BLEND(t, VXN_ADD(t, VXN_MUL(ndotvp, f)), pos);
        }
        if (L->specular) {
            VxNum4 h[3] = { vp[0], vp[1], VXN_ADD(vp[2], one) };
            VxNum4 hzero = vxn_normalize3(h);
            VxNum4 ndoth = vxn_dot3(nv, h);
            int bits = live & VXN_MASK(pos) & ~VXN_MASK(hzero) & VXN_MASK(VXN_GT(ndoth, z));
            if (bits) {
                VxNum4 sp = vxn_pow_lanes(ndoth, L->shin, bits);
                NUM bm[4];
                for (int j = 0; j < 4; j++)
                    bm[j] = (bits >> j & 1) ? (NUM)1 : (NUM)0;
                VxNum4 use = VXN_EQ(VXN_SETR(bm), one);
                for (int k = 0; k < 3; k++)
                    term[k] = VXN_BLEND(term[k], VXN_ADD(term[k], VXN_MUL(sp, VXN_SET1(L->spec[k]))), use);
            }
        }
        NUM lm[4];
        for (int j = 0; j < 4; j++)
            lm[j] = (live >> j & 1) ? (NUM)1 : (NUM)0;
        VxNum4 keep = VXN_EQ(VXN_SETR(lm), one);
        for (int k = 0; k < 3; k++) {
            VxNum4 a = VXN_LOAD(acc[k] + i);
            VXN_STORE(acc[k] + i, VXN_BLEND(a, VXN_ADD(a, VXN_MUL(scale, term[k])), keep));
        }
    }
}
/* }==================================================================== */
#endif /* VERTEX_AVX2_FP */

#if RANGE_AVX2
/* {====================================================================
** The range check's scan of a FLOAT array (range_array_max in range.c).
**
** The scalar scan keeps c = 0, then for each component's v = |x| sets c to
** v when !(v <= c), to infinity when v is NaN. Its result is therefore
** infinity when any component is NaN (c becomes infinity then, and no
** later v exceeds it) and otherwise max |x|. On the bits: with the sign
** cleared, non-negative floats compare as their bit patterns do, infinity
** is 0x7F800000 and every NaN lies above it. So the largest of (bits &
** 0x7FFFFFFF) over the components, an unsigned integer maximum (vpmaxud),
** is a NaN exactly when a NaN was there, and otherwise the bits of max |x|,
** which converts to double exactly. */
/* the largest magnitude bits per component of strided elements lo..hi */
VX_INLINE __m128i vx_strided_max(const uint8_t *base, int step, const int size, int64_t lo, int64_t hi)
{
    __m128i m4 = _mm_setzero_si128();
    for (int64_t i = lo; i <= hi; i++) {
        uint32_t u[4] = { 0, 0, 0, 0 };
        memcpy(u, base + i * step, (size_t)size * sizeof(float));
        m4 = _mm_max_epu32(m4, _mm_and_si128(_mm_loadu_si128((const __m128i *)(const void *)u),
                                             _mm_set1_epi32(0x7FFFFFFF)));
    }
    return m4;
}

static double vx_float_abs_max_avx2(const uint8_t *base, int step, int size, int64_t lo, int64_t hi)
{
    const __m256i mag = _mm256_set1_epi32(0x7FFFFFFF);
    __m256i m8 = _mm256_setzero_si256();
    __m128i m4 = _mm_setzero_si128();
    uint32_t m = 0;
    if (hi >= lo && step == size * (int)sizeof(float)) {
        /* tightly packed: one run of components */
        const uint8_t *p = base + lo * step;
        const int64_t cnt = (hi - lo + 1) * size;
        int64_t j = 0;
        for (; j + 8 <= cnt; j += 8)
            m8 = _mm256_max_epu32(m8, _mm256_and_si256(_mm256_loadu_si256((const __m256i *)(const void *)(p + 4 * j)), mag));
        for (; j < cnt; j++) {
            uint32_t u;
            memcpy(&u, p + 4 * j, sizeof u);
            u &= 0x7FFFFFFFu;
            m = u > m ? u : m;
        }
    } else {
        switch (size) {
        case 1: m4 = vx_strided_max(base, step, 1, lo, hi); break;
        case 2: m4 = vx_strided_max(base, step, 2, lo, hi); break;
        case 3: m4 = vx_strided_max(base, step, 3, lo, hi); break;
        default: m4 = vx_strided_max(base, step, 4, lo, hi); break;
        }
    }
    m4 = _mm_max_epu32(m4, _mm_max_epu32(_mm256_castsi256_si128(m8), _mm256_extracti128_si256(m8, 1)));
    m4 = _mm_max_epu32(m4, _mm_shuffle_epi32(m4, 0x4E));
    m4 = _mm_max_epu32(m4, _mm_shuffle_epi32(m4, 0xB1));
    uint32_t v = (uint32_t)_mm_cvtsi128_si32(m4);
    m = v > m ? v : m;
    if (m > 0x7F800000u)
        return INFINITY;
    float f;
    memcpy(&f, &m, sizeof f);
    return f;
}
/* }==================================================================== */

#endif /* RANGE_AVX2 */

#if SIMD_X86
#pragma GCC pop_options
#endif

/* {====================================================================
** the switches: the AVX2 kernel where `simd` says so, else the scalar code */

static inline void vx_dot4_lanes(int simd, NUM m0, NUM m1, NUM m2, NUM m3, const NUM *x, const NUM *y, const NUM *z,
                                 const NUM *w, NUM *restrict out, int cnt, int w_one)
{
#if VERTEX_AVX2
    if (simd) {
        vx_dot4_lanes_avx2(m0, m1, m2, m3, x, y, z, w, out, cnt, w_one);
        return;
    }
#endif
    (void)simd;
    num_dot4_lanes(m0, m1, m2, m3, x, y, z, w, out, cnt, w_one);
}

static inline void vx_dot3_lanes(int simd, NUM m0, NUM m1, NUM m2, const NUM *x, const NUM *y, const NUM *z,
                                 NUM *restrict out, int cnt)
{
#if VERTEX_AVX2
    if (simd) {
        vx_dot3_lanes_avx2(m0, m1, m2, x, y, z, out, cnt);
        return;
    }
#endif
    (void)simd;
    num_dot3_lanes(m0, m1, m2, x, y, z, out, cnt);
}

/* num_pow(x[i], s) of lanes 0..n-1 (n a multiple of 4) */
static inline void vx_pow_all(int simd, const NUM *x, NUM s, NUM *out, int n)
{
#if VERTEX_AVX2
    if (simd) {
        vx_pow_avx2(x, s, out, n);
        return;
    }
#endif
    (void)simd;
    for (int i = 0; i < n; i++)
        out[i] = num_pow(x[i], s);
}

#if NUM_IS_FIXED
/* fx_exp2(y[i]) of lanes 0..n-1 (n a multiple of 4, |y| < 2^62) */
static inline void vx_exp2_all(int simd, const int64_t *y, NUM *out, int n)
{
#if VERTEX_AVX2
    if (simd) {
        vx_exp2_avx2(y, out, n);
        return;
    }
#endif
    (void)simd;
    for (int i = 0; i < n; i++)
        out[i] = fx_exp2(y[i]);
}
#endif

/* num_normalize3 of lanes 0..n-1 of rows x, y, z (the AVX2 kernel also
** normalises the padding lanes up to cnt) */
static inline void vx_normalize3_lanes(int simd, NUM *x, NUM *y, NUM *z, int n, int cnt)
{
#if VERTEX_AVX2
    if (simd) {
        vx_normalize3_avx2(x, y, z, cnt);
        return;
    }
#endif
    (void)simd, (void)cnt;
    for (int i = 0; i < n; i++) {
        NUM t[3] = { x[i], y[i], z[i] };
        num_normalize3(t);
        x[i] = t[0];
        y[i] = t[1];
        z[i] = t[2];
    }
}
/* }==================================================================== */

#endif
