/*
** fx_avx2.h -- the fixed build's base-2 logarithm and power (num.h's
** fx_log2 and fx_exp2) in four 64-bit lanes, with the scalar code's bits
** on every lane: the level of detail (span_avx2.h) and the specular and
** spot powers (vertex_avx2.h) share them. Included inside an AVX2 target
** region; fixed build only.
*/
#ifndef GLES_FX_AVX2_H
#define GLES_FX_AVX2_H

#if SIMD_X86 && NUM_IS_FIXED
#include <immintrin.h>

#define FXV_INLINE static inline __attribute__((always_inline))

/* fx_log2 of lanes x in [1, 2^31), in 0.30. Every product fx_log2 forms
** has both factors below 2^32 (the mantissa's low 22 bits times
** fx_recip_tab <= 2^30; y < 2^22; y2 < 2^14; ln1p <= y times 1/ln 2 <
** 2^31), so vpmuludq forms each exactly and the logical shifts are its
** shifts (every operand is non-negative). b - 1 is the exponent of x as a
** double (exact through the 2^52 bias), y2 / 2 a shift, and y3 / 3 =
** (y3 43691) >> 17, exact for y3 < 2^17 (here y3 < 2^6). */
FXV_INLINE __m256i fxv_log2(__m256i x)
{
    const __m256d two52 = _mm256_set1_pd(4503599627370496.0);
    const __m256d xd = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(x, _mm256_castpd_si256(two52))), two52);
    const __m256i e = _mm256_srli_epi64(_mm256_castpd_si256(xd), 52);          /* b - 1 + 1023 */
    const __m256i m = _mm256_sllv_epi64(x, _mm256_sub_epi64(_mm256_set1_epi64x(1053), e)); /* x << (31 - b) */
    const __m256i frac = _mm256_sub_epi64(m, _mm256_set1_epi64x((int64_t)1 << 30));
    const __m256i i = _mm256_srli_epi64(frac, 22);
    /* both tables' row i in one gather (fx_log2_recip_tab): the
    ** reciprocal is the low dword, which vpmuludq reads */
    const __m256i rt = _mm256_i64gather_epi64((const long long *)(const void *)fx_log2_recip_tab, i, 8);
    const __m256i lt = _mm256_srli_epi64(rt, 32);
    const __m256i y = _mm256_srli_epi64(
        _mm256_mul_epu32(_mm256_and_si256(frac, _mm256_set1_epi64x((1 << 22) - 1)), rt), 30);
    const __m256i y2 = _mm256_srli_epi64(_mm256_mul_epu32(y, y), 30);
    const __m256i y3 = _mm256_srli_epi64(_mm256_mul_epu32(y2, y), 30);
    const __m256i ln1p = _mm256_add_epi64(_mm256_sub_epi64(y, _mm256_srli_epi64(y2, 1)),
                                          _mm256_srli_epi64(_mm256_mul_epu32(y3, _mm256_set1_epi64x(43691)), 17));
    const __m256i l = _mm256_sub_epi64(_mm256_slli_epi64(e, 30), _mm256_set1_epi64x((int64_t)(1023 + 16) << 30));
    return _mm256_add_epi64(_mm256_add_epi64(l, lt),
                            _mm256_srli_epi64(_mm256_mul_epu32(ln1p, _mm256_set1_epi64x(1549082005)), 30));
}

/* fx_exp2 of lanes y (0.30, |y| < 2^62), as 16.16. Between the two
** saturations y + 32 2^30 is positive, so its logical shift by 30 is
** floor(y / 2^30) + 32 and its low 30 bits are y's fraction f. Every
** product has both factors below 2^32 (f's low 22 bits times ln 2 < 2^30;
** x < 2^22; x2 < 2^14; fx_exp2_tab <= 2^31 times e < 2^31), x2 / 2 is a
** shift and x3 / 6 = (x3 43691) >> 18, exact for x3 < 2^17 (here x3 <
** 2^6). The shift to 16.16, sh = 14 - floor(y / 2^30), lies in [0, 34]:
** its rounding bit 2^(sh - 1) is a variable shift, 0 for sh = 0 (a shift
** count past 63 gives 0). */
FXV_INLINE __m256i fxv_exp2(__m256i y)
{
    const __m256i num_max = _mm256_set1_epi64x(NUM_MAX);
    const __m256i sat = _mm256_cmpgt_epi64(y, _mm256_set1_epi64x(((int64_t)15 << 30) - 1));     /* y >= 15 */
    const __m256i under = _mm256_cmpgt_epi64(_mm256_set1_epi64x(-((int64_t)20 << 30) + 1), y);  /* y <= -20 */
    const __m256i yb = _mm256_add_epi64(y, _mm256_set1_epi64x((int64_t)32 << 30));
    const __m256i ipb = _mm256_srli_epi64(yb, 30);                                   /* floor + 32 */
    const __m256i f = _mm256_and_si256(yb, _mm256_set1_epi64x(((int64_t)1 << 30) - 1));
    const __m256i i = _mm256_srli_epi64(f, 22);
    const __m256i x = _mm256_srli_epi64(
        _mm256_mul_epu32(_mm256_and_si256(f, _mm256_set1_epi64x((1 << 22) - 1)), _mm256_set1_epi64x(744261118)), 30);
    const __m256i x2 = _mm256_srli_epi64(_mm256_mul_epu32(x, x), 30);
    const __m256i x3 = _mm256_srli_epi64(_mm256_mul_epu32(x2, x), 30);
    const __m256i e = _mm256_add_epi64(
        _mm256_add_epi64(_mm256_set1_epi64x((int64_t)1 << 30), x),
        _mm256_add_epi64(_mm256_srli_epi64(x2, 1), _mm256_srli_epi64(_mm256_mul_epu32(x3, _mm256_set1_epi64x(43691)), 18)));
    const __m256i tab = _mm256_i64gather_epi64((const long long *)(const void *)fx_exp2_tab, i, 8);
    const __m256i r = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(tab, e), _mm256_set1_epi64x((int64_t)1 << 29)),
                                        30);
    const __m256i sh = _mm256_sub_epi64(_mm256_set1_epi64x(46), ipb);                /* 14 - floor */
    const __m256i half = _mm256_sllv_epi64(_mm256_set1_epi64x(1), _mm256_sub_epi64(sh, _mm256_set1_epi64x(1)));
    __m256i v = _mm256_srlv_epi64(_mm256_add_epi64(r, half), sh);
    v = _mm256_blendv_epi8(v, num_max, _mm256_cmpgt_epi64(v, num_max));               /* num_sat (v >= 0) */
    v = _mm256_blendv_epi8(v, num_max, sat);
    return _mm256_andnot_si256(under, v);
}

/* num_pow(x, s) of lanes x (int64 lanes holding NUMs) for an exponent s in
** [0, 128] (16.16, as GL bounds the spot exponent and the shininess).
** fx_log2 then (l s) / 65536 truncated toward zero: |l| < 17 2^30 and s <=
** 2^23, so |l| s < 2^58 is |l|'s low dword times s plus its high part's
** times s shifted (vpmuludq, exact), and the quotient is the magnitude's
** shift with the sign put back. */
FXV_INLINE __m256i fxv_pow(__m256i x, NUM s)
{
    const __m256i one = _mm256_set1_epi64x(NUM_ONE), zero = _mm256_setzero_si256();
    if (s == 0)
        return one;
    const __m256i pos = _mm256_cmpgt_epi64(x, zero);
    const __m256i l = fxv_log2(_mm256_blendv_epi8(_mm256_set1_epi64x(1), x, pos));
    const __m256i sign = _mm256_cmpgt_epi64(zero, l);
    const __m256i al = _mm256_sub_epi64(_mm256_xor_si256(l, sign), sign);
    const __m256i sv = _mm256_set1_epi64x(s);
    const __m256i prod = _mm256_add_epi64(_mm256_mul_epu32(al, sv),
                                          _mm256_slli_epi64(_mm256_mul_epu32(_mm256_srli_epi64(al, 32), sv), 32));
    const __m256i q = _mm256_srli_epi64(prod, 16);
    __m256i v = fxv_exp2(_mm256_sub_epi64(_mm256_xor_si256(q, sign), sign));
    v = _mm256_blendv_epi8(v, one, _mm256_cmpeq_epi64(x, one));
    return _mm256_and_si256(v, pos);
}

#undef FXV_INLINE
#endif
#endif
