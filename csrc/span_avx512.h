/*
** span_avx512.h -- the double build's bilinear kernel, RGBA8888 writers,
** perspective stage with a level of detail (d8_persp_lod) and fused
** sample/modulate/write stage (span_float8.h's kernel, also
** with the DOT3 pair before the MODULATE) in eight lanes of AVX-512 (F,
** DQ, BW), taken where the CPU has it (simd.h); AVX2 holds four of its
** fragments to a register. The fixed and float
** builds' bilinear kernels hold eight in AVX2's 32-bit lanes already
** (avx2_sample_linear, f8_sample_linear).
** Included after span_avx2.h (by texsample.c and span_chain.c: the guard
** keeps one copy), inside a target pragma for these instructions; every
** function is static.
*/
#ifndef GLES_SPAN_AVX512_H
#define GLES_SPAN_AVX512_H

#if SIMD_AVX512_INSTANCE
#include <immintrin.h>

#include "span_edges8.h"

#define AVX512_INLINE static inline __attribute__((always_inline))

/* v4_linear_axis in eight lanes: the same IEEE operations in the same
** order (reduce_coord, the scale, the floor and the weight), the indices
** wrapped or clamped as int32 */
AVX512_INLINE void v8_linear_axis(__m512d s, int n, int repeat, __m256i *i0, __m256i *i1, __m512d *w)
{
    if (repeat)
        s = _mm512_sub_pd(s, _mm512_roundscale_pd(s, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
    else
        s = _mm512_min_pd(_mm512_max_pd(s, _mm512_set1_pd(-1)), _mm512_set1_pd(2));
    const __m512d uu = _mm512_sub_pd(_mm512_mul_pd(s, _mm512_set1_pd((double)n)), _mm512_set1_pd(0.5));
    const __m512d fl = _mm512_roundscale_pd(uu, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    *w = _mm512_sub_pd(uu, fl);
    const __m256i i = _mm512_cvttpd_epi32(fl), j = _mm256_add_epi32(i, _mm256_set1_epi32(1));
    if (repeat) {
        const __m256i mask = _mm256_set1_epi32(n - 1);
        *i0 = _mm256_and_si256(i, mask);
        *i1 = _mm256_and_si256(j, mask);
    } else {
        const __m256i zero = _mm256_setzero_si256(), top = _mm256_set1_epi32(n - 1);
        *i0 = _mm256_min_epi32(_mm256_max_epi32(i, zero), top);
        *i1 = _mm256_min_epi32(_mm256_max_epi32(j, zero), top);
    }
}

/* Unsigned normalized values without a division. The 64-bit integer
** d 0x0101010101010101 (the byte d in all eight bytes) converts to
** round(d 2^64 / 255): d / 255 is d's eight bits repeated in binary, and
** the conversion rounds the first 53 of them as the division does (checked
** for all 256 bytes), so times 2^-64 it is frag_from_unorm(d, 255). In the
** same way d times 1 repeated every 5 or 6 bits (60 bits) converts to
** d / 31 or d / 63 times 2^60 (checked for every d). */
#define UNORM8_REPEAT 0x0101010101010101ull
#define UNORM5_REPEAT 0x0084210842108421ull     /* 1 every 5 bits, 60 bits */
#define UNORM6_REPEAT 0x0041041041041041ull     /* 1 every 6 bits, 60 bits */

/* eight words zero-extended to 64-bit lanes, and byte c of each repeated
** through its lane */
AVX512_INLINE __m512i v8_words64(__m256i words) { return _mm512_cvtepu32_epi64(words); }
AVX512_INLINE __m512i v8_byte_repeated(__m512i words64, int c)
{
    /* a lane's low dword is the word: its byte c to all eight bytes */
    const long long lo = (long long)(UNORM8_REPEAT * (unsigned)c), hi = (long long)(UNORM8_REPEAT * (unsigned)(c + 8));
    return _mm512_shuffle_epi8(words64, _mm512_setr_epi64(lo, hi, lo, hi, lo, hi, lo, hi));
}

/* the byte at `shift` of eight texel words as d / 255 (texel_unorm8's value) */
AVX512_INLINE __m512d v8_byte_unorm8(__m256i words, int shift)
{
    return _mm512_mul_pd(_mm512_cvtepu64_pd(v8_byte_repeated(v8_words64(words), shift / 8)),
                         _mm512_set1_pd(0x1p-64));
}

/* frag_from_unorm(d, 31) or (d, 63) of integer lanes d <= maxval */
AVX512_INLINE __m512d v8_from_unorm56(__m256i d, int maxval)
{
    const __m512i rep = _mm512_set1_epi64((long long)(maxval == 31 ? UNORM5_REPEAT : UNORM6_REPEAT));
    return _mm512_mul_pd(_mm512_cvtepu64_pd(_mm512_mullo_epi64(v8_words64(d), rep)), _mm512_set1_pd(0x1p-60));
}

/* frag_bilerp_rgba8 of eight fragments (lane k fragment k) channel by
** channel into ch[0..3]: texel words g[0..3] (c00, c10, c01, c11),
** weights a and b. The texel values are taken scaled by 2^64 (the
** converted repeated bytes, above): every product and sum of the filter
** then stays far from the subnormals (the weights are 0 or at least about
** 2^-60, the values 0 or at least 2^-8), so each rounds to the unscaled
** one's times 2^64, and one exact product by 2^-64 per channel ends it */
AVX512_INLINE void v8_bilerp_channels(const __m256i g[4], __m512d a, __m512d b, __m512d ch[4])
{
    const __m512d one = _mm512_set1_pd(1);
    const __m512d ia = _mm512_sub_pd(one, a), ib = _mm512_sub_pd(one, b);
    const __m512i q[4] = { v8_words64(g[0]), v8_words64(g[1]), v8_words64(g[2]), v8_words64(g[3]) };
    for (int c = 0; c < 4; c++) {
        __m512d v[4];
        for (int i = 0; i < 4; i++)
            v[i] = _mm512_cvtepu64_pd(v8_byte_repeated(q[i], c));
        const __m512d top = _mm512_add_pd(_mm512_mul_pd(v[0], ia), _mm512_mul_pd(v[1], a));
        const __m512d bot = _mm512_add_pd(_mm512_mul_pd(v[2], ia), _mm512_mul_pd(v[3], a));
        ch[c] = _mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(top, ib), _mm512_mul_pd(bot, b)), _mm512_set1_pd(0x1p-64));
    }
}

/* eight fragments' channels ch[0..3] (lane k fragment k) stored as
** out[k stride + channel] */
AVX512_INLINE void v8_store_channels8(const __m512d ch[4], double *out, size_t stride)
{
    /* channels of eight fragments to eight fragments' channels: pairs
    ** (r, g) and (b, a) of fragments 0 2 4 6 and 1 3 5 7, then one
    ** fragment's two pairs per 256-bit half */
    const __m512d rg_even = _mm512_unpacklo_pd(ch[0], ch[1]), rg_odd = _mm512_unpackhi_pd(ch[0], ch[1]);
    const __m512d ba_even = _mm512_unpacklo_pd(ch[2], ch[3]), ba_odd = _mm512_unpackhi_pd(ch[2], ch[3]);
    const __m512i lo = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11);
    const __m512i hi = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    const __m512d f02 = _mm512_permutex2var_pd(rg_even, lo, ba_even);
    const __m512d f46 = _mm512_permutex2var_pd(rg_even, hi, ba_even);
    const __m512d f13 = _mm512_permutex2var_pd(rg_odd, lo, ba_odd), f57 = _mm512_permutex2var_pd(rg_odd, hi, ba_odd);
    _mm256_storeu_pd(out, _mm512_castpd512_pd256(f02));
    _mm256_storeu_pd(out + stride, _mm512_castpd512_pd256(f13));
    _mm256_storeu_pd(out + 2 * stride, _mm512_extractf64x4_pd(f02, 1));
    _mm256_storeu_pd(out + 3 * stride, _mm512_extractf64x4_pd(f13, 1));
    _mm256_storeu_pd(out + 4 * stride, _mm512_castpd512_pd256(f46));
    _mm256_storeu_pd(out + 5 * stride, _mm512_castpd512_pd256(f57));
    _mm256_storeu_pd(out + 6 * stride, _mm512_extractf64x4_pd(f46, 1));
    _mm256_storeu_pd(out + 7 * stride, _mm512_extractf64x4_pd(f57, 1));
}

/* v4_bilerp4 of eight fragments (lane k fragment k), stored as
** out[k stride + channel] */
AVX512_INLINE void v8_bilerp8(const __m256i g[4], __m512d a, __m512d b, double *out, size_t stride)
{
    __m512d ch[4];
    v8_bilerp_channels(g, a, b, ch);
    v8_store_channels8(ch, out, stride);
}

/* a coordinate at eight fragments' weights o0, o1, o2 (lanes):
** v4_tex_coord_affine4's (a0 o0 + a1 o1) + a2 o2 */
AVX512_INLINE __m512d v8_lerp3(const double a[3], __m512d o0, __m512d o1, __m512d o2)
{
    return _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(_mm512_set1_pd(a[0]), o0), _mm512_mul_pd(_mm512_set1_pd(a[1]), o1)),
                         _mm512_mul_pd(_mm512_set1_pd(a[2]), o2));
}

/* eight fragments' s and t (lanes) stored as TexCoord out[0..7] */
AVX512_INLINE void v8_store_st8(__m512d s, __m512d t, TexCoord *out)
{
    const __m512d lo = _mm512_unpacklo_pd(s, t), hi = _mm512_unpackhi_pd(s, t);   /* s0 t0 s2 t2 ..., s1 t1 s3 t3 ... */
    _mm512_storeu_pd(&out[0].s, _mm512_permutex2var_pd(lo, _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11), hi));
    _mm512_storeu_pd(&out[4].s, _mm512_permutex2var_pd(lo, _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15), hi));
}

/* s and t of coordinates c[0..7] as lanes; 0 where one is not finite */
AVX512_INLINE int v8_coords8(const TexCoord *c, __m512d *s, __m512d *t)
{
    const __m512i even = _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14);
    const __m512i odd = _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15);
    const __m512d inf = _mm512_set1_pd(INFINITY);
    const __m512d p0 = _mm512_loadu_pd(&c[0].s), p1 = _mm512_loadu_pd(&c[4].s);
    *s = _mm512_permutex2var_pd(p0, even, p1), *t = _mm512_permutex2var_pd(p0, odd, p1);
    return (__mmask8)(_mm512_cmp_pd_mask(_mm512_abs_pd(*s), inf, _CMP_LT_OQ)
                      & _mm512_cmp_pd_mask(_mm512_abs_pd(*t), inf, _CMP_LT_OQ)) == 0xFF;
}

/* the bilinear channels ch[0..3] of a w x h level at lanes s, t (finite) */
AVX512_INLINE void v8_linear_channels(const int *t32, int w, int h, __m512d s, __m512d t, int repeat_s, int repeat_t,
                                      int rows, __m512d ch[4])
{
    __m256i x0, x1, y0, y1;
    __m512d a, b;
    v8_linear_axis(s, w, repeat_s, &x0, &x1, &a);
    v8_linear_axis(t, h, repeat_t, &y0, &y1, &b);
    __m256i g[4];
    avx2_texel_words8(t32, w, (int64_t)w * h, x0, x1, y0, y1, rows, g);
    v8_bilerp_channels(g, a, b, ch);
}

/* avx2_sample_linear_real eight fragments at a time: the first n - n % 8
** of fragments 0..n-1, stopping before the first eight coordinates of
** which one is not finite; returns the number of fragments done */
static __attribute__((noinline)) int avx512_sample_linear_real(const TexImage *li, int n, const TexCoord *c,
                                                               double *out, size_t stride, int repeat_s,
                                                               int repeat_t, int rows)
{
    const int *t32 = (const int *)(const void *)li->texels;
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        __m512d s, t, ch[4];
        if (!v8_coords8(c + j, &s, &t))
            break;
        v8_linear_channels(t32, li->width, li->height, s, t, repeat_s, repeat_t, rows, ch);
        v8_store_channels8(ch, out + (size_t)j * stride, stride);
    }
    return j;
}

/* avx512_sample_linear_real of two levels l1, l2 at the same coordinates
** (not read by rows), mixed by frac[0..n) as lod_block mixes them (t1 +
** frac (t2 - t1) per channel), with no store of either level's texels
** between; returns the number of fragments done (as there) */
static __attribute__((noinline)) int avx512_sample_linear_mix_real(const TexImage *l1, const TexImage *l2, int n,
                                                                   const TexCoord *c, const double *frac,
                                                                   double *out, size_t stride, int repeat_s,
                                                                   int repeat_t)
{
    const int *t1 = (const int *)(const void *)l1->texels, *t2 = (const int *)(const void *)l2->texels;
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        __m512d s, t, ch1[4], ch2[4];
        if (!v8_coords8(c + j, &s, &t))
            break;
        v8_linear_channels(t1, l1->width, l1->height, s, t, repeat_s, repeat_t, 0, ch1);
        v8_linear_channels(t2, l2->width, l2->height, s, t, repeat_s, repeat_t, 0, ch2);
        const __m512d f = _mm512_loadu_pd(frac + j);
        for (int k = 0; k < 4; k++)
            ch1[k] = _mm512_add_pd(ch1[k], _mm512_mul_pd(f, _mm512_sub_pd(ch2[k], ch1[k])));
        v8_store_channels8(ch1, out + (size_t)j * stride, stride);
    }
    return j;
}

/* avx2_rgba8x4 (the double build's) of eight fragments c[0..7] over the
** stored words d: the fragments' channels to channel lanes, then per lane
** the same IEEE operations (v4_clamp01, the blend of kind 1 or 2,
** v4_to_unorm8) and the packing */
AVX512_INLINE __m256i v8_rgba8x8(const double (*c)[4], __m256i d, int kind)
{
    /* fragments 0 | 4, 1 | 5, 2 | 6, 3 | 7; then each half's 4x4 transpose */
    __m512d q[4];
    for (int i = 0; i < 4; i++)
        q[i] = _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(c[i])), _mm256_loadu_pd(c[i + 4]), 1);
    const __m512d rb01 = _mm512_unpacklo_pd(q[0], q[1]), ga01 = _mm512_unpackhi_pd(q[0], q[1]);
    const __m512d rb23 = _mm512_unpacklo_pd(q[2], q[3]), ga23 = _mm512_unpackhi_pd(q[2], q[3]);
    const __m512i lo = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13), hi = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
    __m512d v[4] = { _mm512_permutex2var_pd(rb01, lo, rb23), _mm512_permutex2var_pd(ga01, lo, ga23),
                     _mm512_permutex2var_pd(rb01, hi, rb23), _mm512_permutex2var_pd(ga01, hi, ga23) };
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1);
    if (kind)
        for (int i = 0; i < 4; i++)
            v[i] = _mm512_min_pd(one, _mm512_max_pd(zero, v[i]));
    const __m512d va = v[3], ia = _mm512_sub_pd(one, va);
    __m256i w = _mm256_setzero_si256();
    for (int i = 0; i < 4; i++) {
        __m512d x = v[i];
        if (kind) {
            const __m512d dv = v8_byte_unorm8(d, 8 * i);
            x = kind == 2 ? _mm512_add_pd(x, dv) : _mm512_add_pd(_mm512_mul_pd(x, va), _mm512_mul_pd(dv, ia));
        }
        /* v4_to_unorm8: 0 unless x > 0, 255 from 1 up, else x 255 + 1/2 truncated */
        __m512d u = _mm512_add_pd(_mm512_mul_pd(x, _mm512_set1_pd(255)), _mm512_set1_pd(0.5));
        u = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(x, one, _CMP_GE_OQ), u, _mm512_set1_pd(255));
        u = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(x, zero, _CMP_GT_OQ), zero, u);
        w = _mm256_or_si256(w, _mm256_slli_epi32(_mm512_cvttpd_epi32(u), 8 * i));
    }
    return w;
}

/* write_rgba8 (blend kind 0, 1 or 2, a constant where inlined) of the
** chunk's fragments eight at a time, up to the last whole eight, at the
** ascending offsets k of dst; returns the count done */
AVX512_INLINE int v8_write_rgba8_kind(uint32_t *dst, const uint8_t *k, int n, const double (*c)[4], int kind)
{
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        const int run = k[j + 7] == k[j] + 7;
        __m256i d = _mm256_setzero_si256();
        if (kind && run)
            d = _mm256_loadu_si256((const __m256i *)(const void *)&dst[k[j]]);
        else if (kind)
            d = _mm256_i32gather_epi32((const int *)(const void *)dst,
                                       _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)&k[j])), 4);
        avx2_store_words8(dst, &k[j], run, v8_rgba8x8(&c[j], d, kind));
    }
    return j;
}

static __attribute__((noinline)) int avx512_write_rgba8(uint32_t *dst, const uint8_t *k, int n, const double (*c)[4],
                                                        int kind)
{
    return kind == 0 ? v8_write_rgba8_kind(dst, k, n, c, 0)
         : kind == 1 ? v8_write_rgba8_kind(dst, k, n, c, 1)
                     : v8_write_rgba8_kind(dst, k, n, c, 2);
}

#include "span_float8.h"

/* the fused stage's kernel (f8_modwrite_dispatch) in eight double lanes,
** for the AVX2 instance's stage_modulate_write and stage_sample_write;
** af not NULL where stage_persp left the weights and coordinates to it
** (SpanBuf.lanes) */
static __attribute__((noinline)) void avx512_modwrite(const F8ModWrite *m, int src, int rgb565, int n, int live,
                                                      const uint8_t *k, const WGT (*p)[3], const FRAGV *ct,
                                                      size_t stride, const TexCoord *tc, int x0, void *dst,
                                                      const F8Affine *af)
{
    f8_modwrite_dispatch(m, src, rgb565, n, live, k, p, ct, stride, tc, x0, dst, af);
}

/* the same with the DOT3 pair's first unit before the MODULATE (m->dot3),
** its texels fetched into ct0 or, where ct0 is NULL, sampled at tc0 */
static __attribute__((noinline)) void avx512_dot3_write(const F8ModWrite *m, int src, int rgb565, int n, int live,
                                                        const uint8_t *k, const WGT (*p)[3], const FRAGV *ct0,
                                                        const TexCoord *tc0, const FRAGV *ct, size_t stride,
                                                        const TexCoord *tc, int x0, void *dst, const F8Affine *af)
{
    f8_modwrite_dispatch_dot3(m, src, rgb565, 1, n, live, k, p, ct0, tc0, ct, stride, tc, x0, dst, af);
}
/* {====================================================================
** stage_persp_lod of the double build eight fragments at a time: the
** AVX2 stage's V4 operations (v4_persp4_lanes_den, v4_tangent4,
** v4_tex_coord_affine4: each a product, sum or quotient of doubles in the
** same order, no FMA) over eight lanes */

/* eight fragments' weights o[0..2] (lanes) stored as out[lane][0..2] */
AVX512_INLINE void d8_store_wgt8(const __m512d o[3], double (*out)[3])
{
    static const int64_t ab[3][8] = { { 0, 8, 0, 1, 9, 0, 2, 10 }, { 0, 3, 11, 0, 4, 12, 0, 5 },
                                      { 13, 0, 6, 14, 0, 7, 15, 0 } };
    static const int64_t abc[3][8] = { { 0, 1, 8, 3, 4, 9, 6, 7 }, { 10, 1, 2, 11, 4, 5, 12, 7 },
                                       { 0, 13, 2, 3, 14, 5, 6, 15 } };
    double *d = &out[0][0];
    for (int k = 0; k < 3; k++) {
        const __m512d x = _mm512_permutex2var_pd(o[0], _mm512_loadu_si512((const void *)ab[k]), o[1]);
        _mm512_storeu_pd(d + 8 * k, _mm512_permutex2var_pd(x, _mm512_loadu_si512((const void *)abc[k]), o[2]));
    }
}

/* v4_tex_coord_affine4 of eight fragments */
AVX512_INLINE void d8_tex_coord8(const double sv[3], const double tv[3], const __m512d o[3], TexCoord *out)
{
    v8_store_st8(v8_lerp3(sv, o[0], o[1], o[2]), v8_lerp3(tv, o[0], o[1], o[2]), out);
}

/* STAGE(persp_affine_steps) (span_stages.h) eight slots at a time: an
** affine triangle's weights from edges 1 and 2 at slots 0..n8-1, stepped
** in doubles from their values at slot 0 (e0) and their step (ea), which
** the caller has found exact to n8 (edge_steps_exact); o_1 = e_1
** inv_area, o_2 likewise, o_0 = (1 - o_1) - o_2 into b->p, with unit
** coordinates at them into b->tc (u: vertex values sv, tv) and b->tx (v:
** sv2, tv2) */
static __attribute__((noinline)) void d8_affine_steps(double inv_area, const int64_t e0[3], const int64_t ea[3],
                                                      int n8, SpanBuf *b, int u, const double sv[3],
                                                      const double tv[3], int v, const double sv2[3],
                                                      const double tv2[3])
{
    const double a_s[3] = { sv[0], sv[1], sv[2] }, a_t[3] = { tv[0], tv[1], tv[2] };
    const double a_s2[3] = { sv2[0], sv2[1], sv2[2] }, a_t2[3] = { tv2[0], tv2[1], tv2[2] };
    const __m512d k8 = _mm512_setr_pd(0, 1, 2, 3, 4, 5, 6, 7);
    const double a1 = (double)ea[1], a2 = (double)ea[2];
    __m512d d1 = _mm512_add_pd(_mm512_set1_pd((double)e0[1]), _mm512_mul_pd(k8, _mm512_set1_pd(a1)));
    __m512d d2 = _mm512_add_pd(_mm512_set1_pd((double)e0[2]), _mm512_mul_pd(k8, _mm512_set1_pd(a2)));
    const __m512d step1 = _mm512_set1_pd(8 * a1), step2 = _mm512_set1_pd(8 * a2);
    const __m512d ia = _mm512_set1_pd(inv_area), one = _mm512_set1_pd(1);
    WGT (*const p)[3] = b->p;
    TexCoord *const tc = b->tc, *const tx = b->tx;
    for (int j = 0; j < n8; j += 8) {
        __m512d o[3];
        o[1] = _mm512_mul_pd(d1, ia);
        o[2] = _mm512_mul_pd(d2, ia);
        o[0] = _mm512_sub_pd(_mm512_sub_pd(one, o[1]), o[2]);
        d8_store_wgt8(o, &p[j]);
        if (u)
            d8_tex_coord8(a_s, a_t, o, &tc[j]);
        if (v)
            d8_tex_coord8(a_s2, a_t2, o, &tx[j]);
        d1 = _mm512_add_pd(d1, step1);
        d2 = _mm512_add_pd(d2, step2);
    }
}

/* v4_tangent4 of eight fragments */
AVX512_INLINE void d8_tangent8(const WgtTangent *g, const __m512d o[3], __m512d inv, __m512d out[3])
{
    const __m512d a0 = _mm512_mul_pd(_mm512_set1_pd(g->a[0]), inv), a1 = _mm512_mul_pd(_mm512_set1_pd(g->a[1]), inv);
    const __m512d a2 = _mm512_mul_pd(_mm512_set1_pd(g->a[2]), inv);
    const __m512d r = _mm512_add_pd(_mm512_add_pd(a0, a1), a2);
    out[1] = _mm512_add_pd(o[1], _mm512_sub_pd(a1, _mm512_mul_pd(o[1], r)));
    out[2] = _mm512_add_pd(o[2], _mm512_sub_pd(a2, _mm512_mul_pd(o[2], r)));
    out[0] = _mm512_sub_pd(_mm512_sub_pd(_mm512_set1_pd(1), out[1]), out[2]);
}

/* stage_persp_lod's groups of eight slots from slot 0 of a triangle that
** is not affine, up to the first group with an edge value of magnitude
** 2^51 or more (v4_edge_lanes' range; the AVX2 code then takes it): the
** weights into b->p, and where coords (the chain's unit with a level of
** detail, without q: its s and t at the vertices sv, tv) its coordinates
** at the weights and at both tangents into b->tc, tx and ty, else the
** tangent weights into b->px and b->py. Returns the slots done (a
** multiple of eight). */
static __attribute__((noinline)) int d8_persp_lod(const WgtSetup *ws, const WgtTangent tan[2], const int64_t ea[3],
                                                  SpanBuf *b, int coords, const double sv[3], const double tv[3])
{
    const WgtSetup s = *ws;
    const WgtTangent g[2] = { tan[0], tan[1] };
    const double a_s[3] = { sv[0], sv[1], sv[2] }, a_t[3] = { tv[0], tv[1], tv[2] };
    Edges8 ed;
    edges8_setup(b->e0, ea, &ed);
    const __m512i bias = _mm512_set1_epi64((int64_t)1 << 51), high = _mm512_set1_epi64(~(((int64_t)1 << 52) - 1));
    const int n8 = b->n & ~7;
    int j = 0;
    for (; j < n8; j += 8) {
        __m512i e[3], far = _mm512_setzero_si512();
        __m512d ev[3];
        edges8(&ed, &b->k[j], e);
        for (int i = 0; i < 3; i++) {
            far = _mm512_or_si512(far, _mm512_and_si512(_mm512_add_epi64(e[i], bias), high));
            ev[i] = _mm512_cvtepi64_pd(e[i]);
        }
        if (_mm512_test_epi64_mask(far, far))
            break;
        const __m512d n0 = _mm512_mul_pd(ev[0], _mm512_set1_pd(s.q[0]));
        const __m512d n1 = _mm512_mul_pd(ev[1], _mm512_set1_pd(s.q[1]));
        const __m512d n2 = _mm512_mul_pd(ev[2], _mm512_set1_pd(s.q[2]));
        const __m512d inv = _mm512_div_pd(_mm512_set1_pd(1), _mm512_add_pd(_mm512_add_pd(n0, n1), n2));
        __m512d l[3], o[3];
        l[1] = _mm512_mul_pd(n1, inv);
        l[2] = _mm512_mul_pd(n2, inv);
        l[0] = _mm512_sub_pd(_mm512_sub_pd(_mm512_set1_pd(1), l[1]), l[2]);
        d8_store_wgt8(l, &b->p[j]);
        if (coords) {
            d8_tex_coord8(a_s, a_t, l, &b->tc[j]);
            d8_tangent8(&g[0], l, inv, o);
            d8_tex_coord8(a_s, a_t, o, &b->tx[j]);
            d8_tangent8(&g[1], l, inv, o);
            d8_tex_coord8(a_s, a_t, o, &b->ty[j]);
        } else {
            d8_tangent8(&g[0], l, inv, o);
            d8_store_wgt8(o, &b->px[j]);
            d8_tangent8(&g[1], l, inv, o);
            d8_store_wgt8(o, &b->py[j]);
        }
    }
    return j;
}
/* }==================================================================== */

#endif

#endif
