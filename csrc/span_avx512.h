/*
** span_avx512.h -- the double build's bilinear kernel and RGBA8888
** writers in eight lanes of AVX-512F, taken where the CPU has it (simd.h);
** AVX2 holds four of its fragments to a register. The fixed and float
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

/* the byte at `shift` of eight texel words as d / 255 (texel_unorm8's value) */
AVX512_INLINE __m512d v8_byte_unorm8(__m256i words, int shift)
{
    const __m256i d = _mm256_and_si256(_mm256_srli_epi32(words, shift), _mm256_set1_epi32(0xFF));
    /* v4_div255's d / 255 */
    const __m512d x = _mm512_cvtepi32_pd(d);
    return _mm512_fmadd_pd(x, _mm512_set1_pd(UNORM8_RECIP_HI), _mm512_mul_pd(x, _mm512_set1_pd(UNORM8_RECIP_LO)));
}

/* v4_bilerp4 of eight fragments (lane k fragment k), one register per
** channel */
AVX512_INLINE void v8_bilerp_channels(const __m256i g[4], __m512d a, __m512d b, __m512d ch[4])
{
    const __m512d one = _mm512_set1_pd(1);
    const __m512d ia = _mm512_sub_pd(one, a), ib = _mm512_sub_pd(one, b);
    for (int c = 0; c < 4; c++) {
        __m512d v[4];
        for (int i = 0; i < 4; i++)
            v[i] = v8_byte_unorm8(g[i], 8 * c);
        const __m512d top = _mm512_add_pd(_mm512_mul_pd(v[0], ia), _mm512_mul_pd(v[1], a));
        const __m512d bot = _mm512_add_pd(_mm512_mul_pd(v[2], ia), _mm512_mul_pd(v[3], a));
        ch[c] = _mm512_add_pd(_mm512_mul_pd(top, ib), _mm512_mul_pd(bot, b));
    }
}

/* eight fragments' channels ch[0..3] (lane k fragment k) stored as
** out[k stride + channel] */
AVX512_INLINE void v8_store_channels(const __m512d ch[4], double *out, size_t stride)
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

/* the s and t of eight coordinates c[0..7] as lanes */
AVX512_INLINE void v8_load_st(const TexCoord *c, __m512d *s, __m512d *t)
{
    const __m512d p0 = _mm512_loadu_pd(&c[0].s), p1 = _mm512_loadu_pd(&c[4].s);
    *s = _mm512_permutex2var_pd(p0, _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), p1);
    *t = _mm512_permutex2var_pd(p0, _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15), p1);
}

/* whether every lane of s and t is finite */
AVX512_INLINE int v8_finite(__m512d s, __m512d t)
{
    const __m512d inf = _mm512_set1_pd(INFINITY);
    return (__mmask8)(_mm512_cmp_pd_mask(_mm512_abs_pd(s), inf, _CMP_LT_OQ)
                      & _mm512_cmp_pd_mask(_mm512_abs_pd(t), inf, _CMP_LT_OQ)) == 0xFF;
}

/* avx2_sample_linear_real's texels of eight fragments at finite
** coordinates (s, t) on level li, one register per channel */
AVX512_INLINE void v8_linear_channels(const TexImage *li, __m512d s, __m512d t, int repeat_s, int repeat_t,
                                      int rows, __m512d ch[4])
{
    const int w = li->width, h = li->height;
    __m256i x0, x1, y0, y1;
    __m512d a, b;
    v8_linear_axis(s, w, repeat_s, &x0, &x1, &a);
    v8_linear_axis(t, h, repeat_t, &y0, &y1, &b);
    __m256i g[4];
    avx2_texel_words8(li->texels, w, (int64_t)w * h, x0, x1, y0, y1, rows, g);
    v8_bilerp_channels(g, a, b, ch);
}

/* avx2_sample_linear_real eight fragments at a time: the first n - n % 8
** of fragments 0..n-1, stopping before the first eight coordinates of
** which one is not finite; returns the number of fragments done */
static __attribute__((noinline)) int avx512_sample_linear_real(const TexImage *li, int n, const TexCoord *c,
                                                               double *out, size_t stride, int repeat_s,
                                                               int repeat_t, int rows)
{
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        __m512d st, tt, ch[4];
        v8_load_st(&c[j], &st, &tt);
        if (!v8_finite(st, tt))
            break;
        v8_linear_channels(li, st, tt, repeat_s, repeat_t, rows, ch);
        v8_store_channels(ch, out + (size_t)j * stride, stride);
    }
    return j;
}

/* avx2_rgba8x4 (the double build's) of eight fragments' channels v[0..3]
** (lane k fragment k) over the stored words d: per lane the same IEEE
** operations (v4_clamp01, the blend of kind 1 or 2, v4_to_unorm8) and the
** packing */
AVX512_INLINE __m256i v8_rgba8_lanes(__m512d v[4], __m256i d, int kind)
{
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

/* v8_rgba8_lanes of eight fragments c[0..7]: their channels to channel
** lanes first */
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
    return v8_rgba8_lanes(v, d, kind);
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
        const __m256i w = v8_rgba8x8(&c[j], d, kind);
        if (run) {
            _mm256_storeu_si256((__m256i *)(void *)&dst[k[j]], w);
        } else {
            uint32_t words[8];
            _mm256_storeu_si256((__m256i *)(void *)words, w);
            for (int i = 0; i < 8; i++)
                dst[k[j + i]] = words[i];
        }
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

/* the double build's DOT3 pair (span_dot3_pair) and RGBA8888 write in one
** pass of eight lanes (stage_dot3_sample_write): both units' texels as
** avx512_sample_linear_real forms them (level 0, GL_LINEAR), the colour as
** stage_color forms it (v4_lerp3f_clamp01 of the weights, or the clamped
** flat colour), stage_color_dot3_modulate's operations and write_rgba8's
** (v8_rgba8_lanes): each lane the same IEEE operations in the same order,
** with no texel or colour stored between */
typedef struct V8Dot3 {
    const TexImage *l0, *l1;        /* level 0 of the first unit (DOT3) and of the second (MODULATE) */
    int rs0, rt0, rs1, rt1;         /* their REPEAT axes (else CLAMP_TO_EDGE) */
    int smooth, rgba_dot, keep_alpha, kind;
    double col[4][3];               /* channel i of the three vertex colours (smooth) */
    double flat[4];                 /* the flat colour, clamped */
} V8Dot3;

/* three weights of eight fragments p[0..7] (24 doubles) as lanes: lane L
** of w[i] is double 3 L + i, from the first 16 and then the last 8 */
AVX512_INLINE void v8_wgt_lanes8(const double (*p)[3], __m512d w[3])
{
    const double *q = &p[0][0];
    const __m512d q0 = _mm512_loadu_pd(q), q1 = _mm512_loadu_pd(q + 8), q2 = _mm512_loadu_pd(q + 16);
    w[0] = _mm512_mask_permutexvar_pd(_mm512_permutex2var_pd(q0, _mm512_setr_epi64(0, 3, 6, 9, 12, 15, 0, 0), q1),
                                      0xC0, _mm512_setr_epi64(0, 0, 0, 0, 0, 0, 2, 5), q2);
    w[1] = _mm512_mask_permutexvar_pd(_mm512_permutex2var_pd(q0, _mm512_setr_epi64(1, 4, 7, 10, 13, 0, 0, 0), q1),
                                      0xE0, _mm512_setr_epi64(0, 0, 0, 0, 0, 0, 3, 6), q2);
    w[2] = _mm512_mask_permutexvar_pd(_mm512_permutex2var_pd(q0, _mm512_setr_epi64(2, 5, 8, 11, 14, 0, 0, 0), q1),
                                      0xE0, _mm512_setr_epi64(0, 0, 0, 0, 0, 1, 4, 7), q2);
}

/* the kernel over slots 0..n-1 in groups of eight (n a multiple of 8;
** slots from `live` on repeat the last live one and are not written) at
** the ascending offsets k of dst: weights p, the first unit's coordinates
** c0 and the second's c1. Returns 1, or 0 (nothing written) where a
** coordinate is not finite */
static __attribute__((noinline)) int avx512_dot3_write(const V8Dot3 *m, int n, int live, const uint8_t *k,
                                                       const double (*p)[3], const TexCoord *c0,
                                                       const TexCoord *c1, uint32_t *dst)
{
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1), half = _mm512_set1_pd(0.5);
    for (int j = 0; j < n; j += 8) {
        __m512d s0, s1, u0, u1;
        v8_load_st(&c0[j], &s0, &u0);
        v8_load_st(&c1[j], &s1, &u1);
        if (!v8_finite(s0, u0) || !v8_finite(s1, u1))
            return 0;
    }
    for (int j = 0; j < n; j += 8) {
        __m512d s, t, t0[4], t1[4], c[4], pr[4];
        v8_load_st(&c0[j], &s, &t);
        v8_linear_channels(m->l0, s, t, m->rs0, m->rt0, 1, t0);
        v8_load_st(&c1[j], &s, &t);
        v8_linear_channels(m->l1, s, t, m->rs1, m->rt1, 1, t1);
        if (m->smooth) {
            __m512d w[3];
            v8_wgt_lanes8(&p[j], w);
            for (int i = 0; i < 4; i++) {
                /* v4_lerp3f: (a0 p0 + a1 p1) + a2 p2, then v4_clamp01 */
                const __m512d v = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(_mm512_set1_pd(m->col[i][0]), w[0]),
                                                              _mm512_mul_pd(_mm512_set1_pd(m->col[i][1]), w[1])),
                                                _mm512_mul_pd(_mm512_set1_pd(m->col[i][2]), w[2]));
                c[i] = _mm512_min_pd(one, _mm512_max_pd(zero, v));
            }
        } else {
            for (int i = 0; i < 4; i++)
                c[i] = _mm512_set1_pd(m->flat[i]);
        }
        /* (t - b)(c - b), b = 1/2 in the rgb lanes and 0 in alpha; the
        ** sum ((0 + p_r) + p_g) + p_b times 4 */
        for (int i = 0; i < 4; i++)
            pr[i] = _mm512_mul_pd(_mm512_sub_pd(t0[i], i < 3 ? half : zero), _mm512_sub_pd(c[i], i < 3 ? half : zero));
        const __m512d d = _mm512_mul_pd(_mm512_add_pd(_mm512_add_pd(_mm512_add_pd(zero, pr[0]), pr[1]), pr[2]),
                                        _mm512_set1_pd(4));
        const __m512d v = _mm512_min_pd(one, _mm512_max_pd(zero, d));
        const __m512d va = m->rgba_dot ? v : _mm512_min_pd(one, _mm512_max_pd(zero, pr[3]));
        __m512d out[4] = { _mm512_mul_pd(v, t1[0]), _mm512_mul_pd(v, t1[1]), _mm512_mul_pd(v, t1[2]),
                           m->keep_alpha ? va : _mm512_mul_pd(va, t1[3]) };
        const int lanes = live - j < 8 ? live - j : 8;
        const int run = lanes == 8 && k[j + 7] == k[j] + 7;
        __m256i dw = _mm256_setzero_si256();
        if (m->kind && run)
            dw = _mm256_loadu_si256((const __m256i *)(const void *)&dst[k[j]]);
        else if (m->kind)
            dw = _mm256_i32gather_epi32((const int *)(const void *)dst,
                                        _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)&k[j])), 4);
        const __m256i w = v8_rgba8_lanes(out, dw, m->kind);
        if (run) {
            _mm256_storeu_si256((__m256i *)(void *)&dst[k[j]], w);
        } else {
            uint32_t words[8];
            _mm256_storeu_si256((__m256i *)(void *)words, w);
            for (int i = 0; i < lanes; i++)
                dst[k[j + i]] = words[i];
        }
    }
    return 1;
}
#endif

#endif
