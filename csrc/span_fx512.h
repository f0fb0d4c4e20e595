/*
** span_fx512.h -- the fixed build's 64-bit-lane work of trilinear
** texturing in AVX-512 (F, DQ, BW), taken where the CPU has it (simd.h):
** the perspective weights with the level of detail's tangents and the
** unit's coordinates (stage_persp_lod), the level of detail's choice
** (lod_block), the two-level bilinear mix and the fog stage. AVX2 holds
** four 64-bit lanes (span_avx2.h's avx2_persp4_den, avx2_tangents4,
** avx2_texc_lerp3x4, avx2_lod_choose4, avx2_sample_linear_mix,
** avx2_fog4 and avx2_fog_mix4); these hold eight (sixteen 32-bit lanes
** for the bilinear sums). Every lane does the AVX2 kernels' integer
** operations, so the bits are theirs and the scalar code's; what AVX-512
** adds is the width and the 64-bit operations AVX2 builds from several
** (vpsraq, vpmaxsq, vpminsq, vpabsq, vpmullq, the int64/double
** conversions, mask registers).
** Included by span_chain.c after span_avx2.h, inside a target pragma for
** these instructions, and by texsample.c (the level of detail's choice
** and the mix); the guard keeps one copy in the core's one unit. Every
** function is static.
*/
#ifndef GLES_SPAN_FX512_H
#define GLES_SPAN_FX512_H

#if SIMD_AVX512_FX
#include <immintrin.h>

#include "span_edges8.h"

#define FX512_INLINE static inline __attribute__((always_inline))

/* avx2_persp4_den of eight fragments (the same ranges, the same operations:
** the numerators, the normalising shift from the exponent of den >> 32 as
** a double, the double quotient corrected by the exact remainder) */
FX512_INLINE int fx512_persp8_den(const WgtSetup *s, const __m512i e[3], __m512i l[3], __m512i *den_out)
{
    const __m128i esh = _mm_cvtsi32_si128(s->eshift);
    const __m512i sign = _mm512_set1_epi64(INT64_MIN), high = _mm512_set1_epi64(~(int64_t)0x7FFFFFFF);
    const __m512i zero = _mm512_setzero_si512();
    __m512i n[3], bad = zero;
    for (int i = 0; i < 3; i++) {
        const __m512i ei = _mm512_srl_epi64(e[i], esh);
        bad = _mm512_or_si512(bad, _mm512_or_si512(_mm512_and_si512(e[i], sign), _mm512_and_si512(ei, high)));
        n[i] = _mm512_srl_epi64(_mm512_mul_epu32(ei, _mm512_set1_epi64(s->mant[i])),
                                _mm_cvtsi32_si128(s->qshift[i] < 64 ? s->qshift[i] : 64));
    }
    if (_mm512_test_epi64_mask(bad, bad))
        return 0;
    __m512i den = _mm512_add_epi64(_mm512_add_epi64(n[0], n[1]), n[2]);
    /* sh = max(bit length of den - 32, 0); den >> 32 < 2^31 converts exactly */
    const __m512i hi_bits = _mm512_srli_epi64(_mm512_castpd_si512(_mm512_cvtepi64_pd(_mm512_srli_epi64(den, 32))), 52);
    const __m512i sh = _mm512_max_epi64(_mm512_sub_epi64(hi_bits, _mm512_set1_epi64(1022)), zero);
    den = _mm512_srlv_epi64(den, sh);
    const __m512i n1 = _mm512_srlv_epi64(n[1], sh), n2 = _mm512_srlv_epi64(n[2], sh);
    if (_mm512_cmpgt_epi64_mask(_mm512_set1_epi64((int64_t)1 << 31), den))
        return 0;
    const __m512i half = _mm512_srli_epi64(den, 1);
    const __m512d qd = _mm512_div_pd(_mm512_add_pd(_mm512_set1_pd(4611686018427387904.0), _mm512_cvtepi64_pd(half)),
                                     _mm512_cvtepi64_pd(den));
    __m512i q = _mm512_cvttpd_epi64(qd);
    const __m512i r = _mm512_sub_epi64(_mm512_add_epi64(_mm512_set1_epi64((int64_t)1 << 62), half),
                                       _mm512_mul_epu32(q, den));
    /* r < 0: one too many; r >= den: one too few */
    const __mmask8 low = _mm512_cmpgt_epi64_mask(r, _mm512_sub_epi64(den, _mm512_set1_epi64(1)));
    q = _mm512_add_epi64(q, _mm512_srai_epi64(r, 63));
    q = _mm512_mask_add_epi64(q, low, q, _mm512_set1_epi64(1));
    const __m512i round = _mm512_set1_epi64((int64_t)1 << 31);
    l[1] = _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epu32(n1, q), round), 32);
    l[2] = _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epu32(n2, q), round), 32);
    l[0] = _mm512_sub_epi64(_mm512_sub_epi64(_mm512_set1_epi64(WGT_ONE), l[1]), l[2]);
    /* WgtDen's half in the low 32 bits, sh in the high ones */
    *den_out = _mm512_or_si512(_mm512_srli_epi64(q, 1), _mm512_slli_epi64(sh, 32));
    return 1;
}

/* avx2_tangents4 of eight fragments (its ranges and operations; the
** clamps are vpminsq and vpmaxsq) */
FX512_INLINE int fx512_tangents8(const WgtTangent g[2], const __m512i l[3], __m512i den, __m512i out[2][3])
{
    const __m512i one = _mm512_set1_epi64(1), zero = _mm512_setzero_si512();
    const __m512i k = _mm512_sub_epi64(_mm512_srli_epi64(den, 32), _mm512_set1_epi64(g[0].ashift));
    if (_mm512_cmpgt_epi64_mask(_mm512_set1_epi64(-30), k))
        return 0;
    const __m512i kp = _mm512_max_epi64(k, zero);
    const __m512i s = _mm512_add_epi64(_mm512_set1_epi64(31), _mm512_min_epi64(k, zero));      /* 31 - kn */
    const __m512i bias = _mm512_add_epi64(_mm512_set1_epi64((int64_t)1 << 62),
                                          _mm512_sllv_epi64(one, _mm512_sub_epi64(s, one)));
    const __m512i unbias = _mm512_sllv_epi64(one, _mm512_sub_epi64(_mm512_set1_epi64(62), s));
    const __m512i lim = _mm512_set1_epi64(((int64_t)1 << 31) - 1), nlim = _mm512_set1_epi64(-(((int64_t)1 << 31) - 1));
    const __m512i bias29 = _mm512_set1_epi64(((int64_t)1 << 62) + ((int64_t)1 << 29));
    const __m512i pb[3] = { l[0], _mm512_sub_epi64(l[1], unbias), _mm512_sub_epi64(l[2], unbias) };
    for (int d = 0; d < 2; d++) {
        const __m512i asum = _mm512_set1_epi64(g[d].asum);
        for (int i = 1; i < 3; i++) {
            /* n = (a_i + 2^32) - ((p_i asum + 2^62 + 2^29) >> 30) */
            const __m512i n = _mm512_sub_epi64(
                _mm512_set1_epi64((int64_t)g[d].a[i] + ((int64_t)1 << 32)),
                _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epi32(l[i], asum), bias29), 30));
            const __m512i m = _mm512_srav_epi32(n, kp);
            const __m512i o = _mm512_add_epi64(
                pb[i], _mm512_srlv_epi64(_mm512_add_epi64(_mm512_mul_epi32(m, den), bias), s));
            out[d][i] = _mm512_max_epi64(_mm512_min_epi64(o, lim), nlim);
        }
        const __m512i o0 = _mm512_sub_epi64(_mm512_sub_epi64(_mm512_set1_epi64(WGT_ONE), out[d][1]), out[d][2]);
        out[d][0] = _mm512_max_epi64(_mm512_min_epi64(o0, lim), nlim);
    }
    return 1;
}

/* avx2_texc_lerp3x4 of eight fragments: a0 w0 + a1 w1 + a2 w2 (the
** weights' low dwords, signed) rounded half away from zero by 14 bits, as
** floor((x + 2^13 - [x < 0]) / 2^14) with vpsraq */
FX512_INLINE __m512i fx512_texc_lerp3x8(const NUM a[3], const __m512i w[3])
{
    const __m512i acc = _mm512_add_epi64(_mm512_add_epi64(_mm512_mul_epi32(_mm512_set1_epi64(a[0]), w[0]),
                                                          _mm512_mul_epi32(_mm512_set1_epi64(a[1]), w[1])),
                                         _mm512_mul_epi32(_mm512_set1_epi64(a[2]), w[2]));
    return _mm512_srai_epi64(
        _mm512_add_epi64(_mm512_add_epi64(acc, _mm512_set1_epi64((int64_t)1 << 13)), _mm512_srai_epi64(acc, 63)), 14);
}

/* eight fragments' s and t (lanes = fragments) stored as TexCoord out[0..7] */
FX512_INLINE void fx512_store_st8(__m512i s, __m512i t, TexCoord *out)
{
    const __m512i lo = _mm512_unpacklo_epi64(s, t), hi = _mm512_unpackhi_epi64(s, t);   /* s0 t0 s2 t2 ..., s1 t1 s3 t3 ... */
    const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11), second = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    _mm512_storeu_si512((void *)out, _mm512_permutex2var_epi64(lo, first, hi));
    _mm512_storeu_si512((void *)(out + 4), _mm512_permutex2var_epi64(lo, second, hi));
}

/* eight fragments' weights l[0..2] (lanes whose low 32 bits are the WGT
** values) stored as out[lane][0..2] */
FX512_INLINE void fx512_store_wgt8(const __m512i l[3], WGT (*out)[3])
{
    /* a's dwords at 0..7 and b's at 8..15 of one table, c's at 16..23 */
    const __m512i ab = _mm512_inserti64x4(_mm512_castsi256_si512(_mm512_cvtepi64_epi32(l[0])),
                                          _mm512_cvtepi64_epi32(l[1]), 1);
    const __m512i c = _mm512_castsi256_si512(_mm512_cvtepi64_epi32(l[2]));
    const __m512i first = _mm512_setr_epi32(0, 8, 16, 1, 9, 17, 2, 10, 18, 3, 11, 19, 4, 12, 20, 5);
    const __m512i second = _mm512_setr_epi32(13, 21, 6, 14, 22, 7, 15, 23, 0, 0, 0, 0, 0, 0, 0, 0);
    int32_t *o = &out[0][0];
    _mm512_storeu_si512((void *)o, _mm512_permutex2var_epi32(ab, first, c));
    _mm256_storeu_si256((__m256i *)(void *)(o + 16), _mm512_castsi512_si256(_mm512_permutex2var_epi32(ab, second, c)));
}

/* stage_persp_lod's division and tangents for the groups of eight slots
** from slot 0 of a triangle that is not affine, up to the first group a
** lane of which leaves the kernels' ranges (which the AVX2 code then
** takes): the weights into b->p, and where coords (the chain's unit with
** a level of detail, without q: its s and t at the vertices sv, tv) its
** coordinates at the weights and at both tangents into b->tc, tx and ty,
** else the tangent weights into b->px and b->py. Returns the slots done
** (a multiple of eight). */
static __attribute__((noinline)) int fx512_persp_lod(const WgtSetup *ws, const WgtTangent tan[2], const int64_t ea[3],
                                                     SpanBuf *b, int coords, const NUM sv[3], const NUM tv[3])
{
    /* the loop's constants in locals (stores to b->p could alias them) */
    const WgtSetup s = *ws;
    const WgtTangent g[2] = { tan[0], tan[1] };
    const NUM a_s[3] = { sv[0], sv[1], sv[2] }, a_t[3] = { tv[0], tv[1], tv[2] };
    Edges8 ed;
    edges8_setup(b->e0, ea, &ed);
    const int n8 = b->n & ~7;
    WGT (*const p)[3] = b->p, (*const px)[3] = b->px, (*const py)[3] = b->py;
    TexCoord *const tc = b->tc, *const tx = b->tx, *const ty = b->ty;
    /* the divisions first, then the tangents: one loop of both makes each
    ** group one long chain of dependent operations (the division's latency
    ** among them), and the groups overlap less (measured, as in the AVX2
    ** stage) */
    __m512i lanes[SPAN_CHUNK / 8][3], dens[SPAN_CHUNK / 8];
    int groups = 0;
    for (; 8 * groups < n8; groups++) {
        __m512i e[3];
        edges8(&ed, &b->k[8 * groups], e);
        if (!fx512_persp8_den(&s, e, lanes[groups], &dens[groups]))
            break;
        fx512_store_wgt8(lanes[groups], &p[8 * groups]);
    }
    int j = 0;
    for (int i = 0; i < groups; i++, j += 8) {
        const __m512i *l = lanes[i];
        __m512i o[2][3];
        if (!fx512_tangents8(g, l, dens[i], o))
            break;
        if (coords) {
            fx512_store_st8(fx512_texc_lerp3x8(a_s, l), fx512_texc_lerp3x8(a_t, l), &tc[j]);
            fx512_store_st8(fx512_texc_lerp3x8(a_s, o[0]), fx512_texc_lerp3x8(a_t, o[0]), &tx[j]);
            fx512_store_st8(fx512_texc_lerp3x8(a_s, o[1]), fx512_texc_lerp3x8(a_t, o[1]), &ty[j]);
        } else {
            fx512_store_wgt8(o[0], &px[j]);
            fx512_store_wgt8(o[1], &py[j]);
        }
    }
    return j;
}

/* {====================================================================
** lod_choose (texsample.c) for eight fragments at a time: avx2_lod_choose4's
** operations (span_avx2.h), its rho, lambda and decisions, lane by lane */

/* fxv_log2 (fx_avx2.h) of eight lanes x in [1, 2^31): the bit length from
** the exponent of x as a double (vcvtqq2pd: exact below 2^53, the value
** fxv_log2's bias trick forms), the table row by one gather of both
** tables, and the same series */
FX512_INLINE __m512i fx512_log2(__m512i x)
{
    const __m512i e = _mm512_srli_epi64(_mm512_castpd_si512(_mm512_cvtepi64_pd(x)), 52);   /* b - 1 + 1023 */
    const __m512i m = _mm512_sllv_epi64(x, _mm512_sub_epi64(_mm512_set1_epi64(1053), e));      /* x << (31 - b) */
    const __m512i frac = _mm512_sub_epi64(m, _mm512_set1_epi64((int64_t)1 << 30));
    const __m512i i = _mm512_srli_epi64(frac, 22);
    const __m512i rt = _mm512_i64gather_epi64(i, (const void *)fx_log2_recip_tab, 8);
    const __m512i lt = _mm512_srli_epi64(rt, 32);
    const __m512i y = _mm512_srli_epi64(
        _mm512_mul_epu32(_mm512_and_si512(frac, _mm512_set1_epi64((1 << 22) - 1)), rt), 30);
    const __m512i y2 = _mm512_srli_epi64(_mm512_mul_epu32(y, y), 30);
    const __m512i y3 = _mm512_srli_epi64(_mm512_mul_epu32(y2, y), 30);
    const __m512i ln1p = _mm512_add_epi64(_mm512_sub_epi64(y, _mm512_srli_epi64(y2, 1)),
                                          _mm512_srli_epi64(_mm512_mul_epu32(y3, _mm512_set1_epi64(43691)), 17));
    const __m512i l = _mm512_sub_epi64(_mm512_slli_epi64(e, 30), _mm512_set1_epi64((int64_t)(1023 + 16) << 30));
    return _mm512_add_epi64(_mm512_add_epi64(l, lt),
                            _mm512_srli_epi64(_mm512_mul_epu32(ln1p, _mm512_set1_epi64(1549082005)), 30));
}

/* avx2_lod_log2 of eight rho lanes in [0, 2^63) */
FX512_INLINE __m512i fx512_lod_log2(__m512i rho)
{
    const __m512i zero = _mm512_setzero_si512();
    const __m512i r = _mm512_min_epi64(_mm512_srli_epi64(rho, 16), _mm512_set1_epi64(INT32_MAX));
    const __mmask8 r0 = _mm512_cmpeq_epi64_mask(r, zero);
    /* r = 0 taken as 1 for the tables, and replaced */
    const __m512i l = _mm512_mask_mov_epi64(fx512_log2(_mm512_mask_mov_epi64(r, r0, _mm512_set1_epi64(1))), r0,
                                            _mm512_set1_epi64(-((int64_t)17 << 30)));
    return _mm512_mask_mov_epi64(l, _mm512_cmpeq_epi64_mask(rho, zero), _mm512_set1_epi64(-((int64_t)1 << 40)));
}

/* avx2_lod_choose4 of fragments 0..7 (key[k], frac[k]); the clamp to
** +-2^50 is applied to every coordinate (where AVX2 skips it, it changes
** nothing) */
FX512_INLINE void fx512_lod_choose8(const Avx2LodParams *p, const TexCoord *c, const TexCoord *dx,
                                    const TexCoord *dy, int32_t key[8], FRAGV frac[8])
{
    const __m512i lim = _mm512_set1_epi64((int64_t)1 << 50), nlim = _mm512_set1_epi64(-((int64_t)1 << 50));
#define FX512_CLAMP(ptr) _mm512_max_epi64(_mm512_min_epi64(_mm512_loadu_si512((const void *)(ptr)), lim), nlim)
    /* (s, t) of fragments 0-3 and 4-7 */
    const __m512i c0 = FX512_CLAMP(&c[0]), c1 = FX512_CLAMP(&c[4]);
    const __m512i sh = _mm512_set_epi64(p->log2h, p->log2w, p->log2h, p->log2w, p->log2h, p->log2w, p->log2h,
                                        p->log2w);
    const __m512i m0 = _mm512_sllv_epi64(_mm512_max_epi64(_mm512_abs_epi64(_mm512_sub_epi64(FX512_CLAMP(&dx[0]), c0)),
                                                          _mm512_abs_epi64(_mm512_sub_epi64(FX512_CLAMP(&dy[0]), c0))),
                                         sh);
    const __m512i m1 = _mm512_sllv_epi64(_mm512_max_epi64(_mm512_abs_epi64(_mm512_sub_epi64(FX512_CLAMP(&dx[4]), c1)),
                                                          _mm512_abs_epi64(_mm512_sub_epi64(FX512_CLAMP(&dy[4]), c1))),
                                         sh);
#undef FX512_CLAMP
    /* (s0 s4 s1 s5 s2 s6 s3 s7) against (t0 t4 ...), back to fragment order */
    const __m512i rho = _mm512_permutexvar_epi64(
        _mm512_setr_epi64(0, 2, 4, 6, 1, 3, 5, 7),
        _mm512_max_epi64(_mm512_unpacklo_epi64(m0, m1), _mm512_unpackhi_epi64(m0, m1)));
    const __m512i l = fx512_lod_log2(rho);
    const __mmask8 above = _mm512_cmpgt_epi64_mask(l, _mm512_set1_epi64(p->cshift));
    const __m512i lp = _mm512_maskz_mov_epi64(above, l);          /* lambda > 0 where above, else 0 */
    const __m512i q = _mm512_set1_epi64(p->q);
    __m512i k = _mm512_set1_epi64(p->kmin), f = _mm512_setzero_si512();
    if (p->mode == 1) {
        const __m512i d = _mm512_sub_epi64(
            _mm512_srli_epi64(_mm512_add_epi64(lp, _mm512_set1_epi64(((int64_t)1 << 29) + ((int64_t)1 << 30) - 1)), 30),
            _mm512_set1_epi64(1));
        k = _mm512_or_si512(k, _mm512_min_epi64(d, q));
    } else if (p->mode == 2) {
        const __m512i d = _mm512_srli_epi64(lp, 30);
        const __mmask8 two = _mm512_cmpgt_epi64_mask(q, d);        /* floor(lambda) < q */
        k = _mm512_or_si512(k, _mm512_mask_mov_epi64(q, two, d));
        k = _mm512_mask_or_epi64(k, two, k, _mm512_set1_epi64(p->ktwo));
        f = _mm512_maskz_and_epi64(two, lp, _mm512_set1_epi64(((int64_t)1 << 30) - 1));
    }
    k = _mm512_mask_mov_epi64(_mm512_set1_epi64(p->kmag), above, k);
    _mm256_storeu_si256((__m256i *)(void *)key, _mm512_cvtepi64_epi32(k));
    _mm512_storeu_si512((void *)frac, f);
}

/* fx512_lod_choose8 over fragments 0..n-1 eight at a time; returns the
** fragments done (n rounded down to eight) */
static __attribute__((noinline)) int fx512_lod_choose(const Avx2LodParams *p, int n, const TexCoord *c,
                                                      const TexCoord *dx, const TexCoord *dy, int32_t *key,
                                                      FRAGV *frac)
{
    int j = 0;
    for (; j + 8 <= n; j += 8)
        fx512_lod_choose8(p, c + j, dx + j, dy + j, key + j, frac + j);
    return j;
}
/* }==================================================================== */

/* {====================================================================
** the trilinear mix (avx2_sample_linear_mix, span_avx2.h) sixteen
** fragments at a time: each level's bilinear sum in 32-bit lanes, the
** mix in 64-bit lanes, the AVX2 kernel's integer operations lane by lane */

/* the low and high dwords of the s and t of sixteen fragments'
** coordinates c[0..15] (lane = fragment) */
FX512_INLINE void fx512_load_st16(const TexCoord *c, __m512i *s_lo, __m512i *s_hi, __m512i *t_lo, __m512i *t_hi)
{
    const __m512i q0 = _mm512_loadu_si512((const void *)&c[0]), q1 = _mm512_loadu_si512((const void *)&c[4]);
    const __m512i q2 = _mm512_loadu_si512((const void *)&c[8]), q3 = _mm512_loadu_si512((const void *)&c[12]);
    /* s of fragments 0-7 in the low half, t in the high one (of 8-15 from q2, q3) */
    const __m512i lo = _mm512_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28, 2, 6, 10, 14, 18, 22, 26, 30);
    const __m512i hi = _mm512_setr_epi32(1, 5, 9, 13, 17, 21, 25, 29, 3, 7, 11, 15, 19, 23, 27, 31);
    const __m512i a = _mm512_permutex2var_epi32(q0, lo, q1), b = _mm512_permutex2var_epi32(q2, lo, q3);
    const __m512i c1 = _mm512_permutex2var_epi32(q0, hi, q1), d = _mm512_permutex2var_epi32(q2, hi, q3);
    *s_lo = _mm512_shuffle_i64x2(a, b, _MM_SHUFFLE(1, 0, 1, 0));
    *t_lo = _mm512_shuffle_i64x2(a, b, _MM_SHUFFLE(3, 2, 3, 2));
    *s_hi = _mm512_shuffle_i64x2(c1, d, _MM_SHUFFLE(1, 0, 1, 0));
    *t_hi = _mm512_shuffle_i64x2(c1, d, _MM_SHUFFLE(3, 2, 3, 2));
}

/* avx2_linear_axis8 of sixteen coordinates */
FX512_INLINE void fx512_linear_axis16(__m512i lo, __m512i hi, int log2n, int repeat, __m512i *i0, __m512i *i1,
                                      __m512i *w)
{
    const __m128i to_index = _mm_cvtsi32_si128(32 - log2n), up = _mm_cvtsi32_si128(log2n);
    const __m512i half = _mm512_set1_epi32((int)(0x80000000u >> log2n));
    const __m512i one = _mm512_set1_epi32(1);
    const int n = 1 << log2n;
    if (repeat) {
        const __m512i g = _mm512_sub_epi32(lo, half);
        const __m512i mask = _mm512_set1_epi32(n - 1);
        *i0 = _mm512_and_si512(_mm512_srl_epi32(g, to_index), mask);
        *i1 = _mm512_and_si512(_mm512_add_epi32(*i0, one), mask);
        *w = _mm512_srli_epi32(_mm512_sll_epi32(g, up), 16);
        return;
    }
    const __mmask16 below = _mm512_cmpgt_epi32_mask(_mm512_set1_epi32(-1), hi);    /* s < -1 */
    const __mmask16 above = _mm512_cmpgt_epi32_mask(hi, one);                      /* s >= 2 */
    hi = _mm512_mask_mov_epi32(_mm512_mask_mov_epi32(hi, below, _mm512_set1_epi32(-1)), above, _mm512_set1_epi32(2));
    lo = _mm512_maskz_mov_epi32((__mmask16)~(below | above), lo);
    const __m512i g = _mm512_sub_epi32(lo, half);
    /* a borrow (-1) where lo < half, unsigned */
    const __m512i h = _mm512_mask_sub_epi32(hi, _mm512_cmplt_epu32_mask(lo, half), hi, one);
    const __m512i ip = _mm512_add_epi32(_mm512_sll_epi32(h, up), _mm512_srl_epi32(g, to_index));
    const __m512i zero = _mm512_setzero_si512(), top = _mm512_set1_epi32(n - 1);
    *i0 = _mm512_min_epi32(_mm512_max_epi32(ip, zero), top);
    *i1 = _mm512_min_epi32(_mm512_max_epi32(_mm512_add_epi32(ip, one), zero), top);
    *w = _mm512_srli_epi32(_mm512_sll_epi32(g, up), 16);
}

/* the texels at indices i (sixteen lanes) and i + 1 (no lane at the
** level's right edge), as two registers, by two gathers of eight 64-bit
** words (each word is the pair) */
FX512_INLINE void fx512_gather_pairs(const int *tx32, __m512i i, __m512i *left, __m512i *right)
{
    const __m512i lo = _mm512_i32gather_epi64(_mm512_castsi512_si256(i), (const void *)tx32, 4);
    const __m512i hi = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64(i, 1), (const void *)tx32, 4);
    *left = _mm512_permutex2var_epi32(lo, _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30),
                                      hi);
    *right = _mm512_permutex2var_epi32(lo, _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31),
                                       hi);
}

/* avx2_bilerp8_channel of sixteen fragments: channel `sh` of the texel
** words g[0..3] filtered by the 16-bit weights a, b (ia = 2^16 - a, ib) */
FX512_INLINE __m512i fx512_bilerp16_channel(const __m512i g[4], int sh, __m512i a, __m512i ia, __m512i b, __m512i ib)
{
    const __m512i byte = _mm512_set1_epi32(0xFF);
    __m512i c[4];
    for (int i = 0; i < 4; i++)
        c[i] = sh == 24 ? _mm512_srli_epi32(g[i], 24) : _mm512_and_si512(_mm512_srli_epi32(g[i], sh), byte);
    const __m512i h0 = _mm512_add_epi32(_mm512_mullo_epi32(c[0], ia), _mm512_mullo_epi32(c[1], a));
    const __m512i h1 = _mm512_add_epi32(_mm512_mullo_epi32(c[2], ia), _mm512_mullo_epi32(c[3], a));
    const __m512i hi = _mm512_add_epi32(_mm512_mullo_epi32(_mm512_srli_epi32(h0, 8), ib),
                                        _mm512_mullo_epi32(_mm512_srli_epi32(h1, 8), b));
    __m512i lo = _mm512_add_epi32(_mm512_mullo_epi32(_mm512_and_si512(h0, byte), ib),
                                  _mm512_mullo_epi32(_mm512_and_si512(h1, byte), b));
    lo = _mm512_srli_epi32(_mm512_add_epi32(lo, _mm512_set1_epi32(128)), 8);
    return _mm512_add_epi32(hi, lo);
}

/* sixteen fragments' texel words on a level and their 16-bit weights */
typedef struct Fx512Texels {
    __m512i g[4], a, b;
} Fx512Texels;

/* the four texel words of sixteen bilinear footprints (columns xa and
** xa + 1, rows ya and ya + 1 of a level 2^log2w wide holding `total`
** texels) out of a window of four rows of sixteen texels around lane 8's
** (rows ya8 - 1 to ya8 + 2, columns xa8 - 7 to xa8 + 8): four loads and
** permutes of them in place of four gathers, where every footprint lies
** that close (most groups: a level is chosen for about a texel a pixel);
** 0 where one does not, or the window leaves the level's texels. A
** texel's place in the window is its offset y w + x from the window's
** first, so a window's row may run on into the level's next row (a level
** narrower than sixteen) and the places stay right */
FX512_INLINE int fx512_window_texels16(const int *tx32, int log2w, int64_t total, __m512i xa, __m512i ya,
                                       __m512i g[4])
{
    const __m512i mid = _mm512_set1_epi32(8), one = _mm512_set1_epi32(1);
    const __m512i dx = _mm512_add_epi32(_mm512_sub_epi32(xa, _mm512_permutexvar_epi32(mid, xa)), _mm512_set1_epi32(7));
    const __m512i dy = _mm512_add_epi32(_mm512_sub_epi32(ya, _mm512_permutexvar_epi32(mid, ya)), one);
    if (_mm512_cmpgt_epu32_mask(dx, _mm512_set1_epi32(14)) | _mm512_cmpgt_epu32_mask(dy, _mm512_set1_epi32(2)))
        return 0;
    const int x8 = _mm_cvtsi128_si32(_mm512_extracti32x4_epi32(xa, 2));
    const int y8 = _mm_cvtsi128_si32(_mm512_extracti32x4_epi32(ya, 2));
    const int64_t w = (int64_t)1 << log2w, first = (int64_t)(y8 - 1) * w + x8 - 7;
    if (first < 0 || first + 3 * w + 16 > total)
        return 0;
    const int *at = tx32 + first;
    const __m512i r0 = _mm512_loadu_si512((const void *)at), r1 = _mm512_loadu_si512((const void *)(at + w));
    const __m512i r2 = _mm512_loadu_si512((const void *)(at + 2 * w));
    const __m512i r3 = _mm512_loadu_si512((const void *)(at + 3 * w));
    /* a texel of window row r, column x: x + 16 (r & 1) of (r0, r1) or,
    ** for rows 2 and 3, of (r2, r3) */
    const __m512i top = _mm512_or_si512(dx, _mm512_slli_epi32(_mm512_and_si512(dy, one), 4));
    const __m512i bottom = _mm512_xor_si512(top, _mm512_set1_epi32(16));
    const __mmask16 top_high = _mm512_cmpeq_epi32_mask(dy, _mm512_set1_epi32(2));
    const __mmask16 bottom_high = _mm512_cmpgt_epi32_mask(dy, _mm512_setzero_si512());
#define FX512_WINDOW(idx, high) \
    _mm512_mask_blend_epi32(high, _mm512_permutex2var_epi32(r0, idx, r1), _mm512_permutex2var_epi32(r2, idx, r3))
    g[0] = FX512_WINDOW(top, top_high);
    g[1] = FX512_WINDOW(_mm512_add_epi32(top, one), top_high);
    g[2] = FX512_WINDOW(bottom, bottom_high);
    g[3] = FX512_WINDOW(_mm512_add_epi32(bottom, one), bottom_high);
#undef FX512_WINDOW
    return 1;
}

/* the texel words and weights of a level at coordinates c[0..15]
** (avx2_linear_channels8's texels; fx512_window_texels16's where the
** footprints are neighbours, not wrapped, else by gathers) */
FX512_INLINE void fx512_linear_texels16(const TexImage *li, const TexCoord *c, int repeat_s, int repeat_t,
                                        Fx512Texels *x)
{
    const int log2w = __builtin_ctz((unsigned)li->width), log2h = __builtin_ctz((unsigned)li->height);
    const int *tx32 = (const int *)(const void *)li->texels;
    __m512i s_lo, s_hi, t_lo, t_hi, xa, xb, ya, yb, a, b, *g = x->g;
    fx512_load_st16(c, &s_lo, &s_hi, &t_lo, &t_hi);
    fx512_linear_axis16(s_lo, s_hi, log2w, repeat_s, &xa, &xb, &a);
    fx512_linear_axis16(t_lo, t_hi, log2h, repeat_t, &ya, &yb, &b);
    const __m512i r0 = _mm512_slli_epi32(ya, log2w), r1 = _mm512_slli_epi32(yb, log2w);
    const __m512i one = _mm512_set1_epi32(1);
    const int pairs = _mm512_cmpeq_epi32_mask(xb, _mm512_add_epi32(xa, one)) == 0xFFFF;
    if (pairs && _mm512_cmpeq_epi32_mask(yb, _mm512_add_epi32(ya, one)) == 0xFFFF
        && fx512_window_texels16(tx32, log2w, (int64_t)li->width * li->height, xa, ya, g)) {
        /* (the window's words) */
    } else if (pairs) {
        fx512_gather_pairs(tx32, _mm512_add_epi32(r0, xa), &g[0], &g[1]);
        fx512_gather_pairs(tx32, _mm512_add_epi32(r1, xa), &g[2], &g[3]);
    } else {
        g[0] = _mm512_i32gather_epi32(_mm512_add_epi32(r0, xa), (const void *)tx32, 4);
        g[1] = _mm512_i32gather_epi32(_mm512_add_epi32(r0, xb), (const void *)tx32, 4);
        g[2] = _mm512_i32gather_epi32(_mm512_add_epi32(r1, xa), (const void *)tx32, 4);
        g[3] = _mm512_i32gather_epi32(_mm512_add_epi32(r1, xb), (const void *)tx32, 4);
    }
    x->a = a, x->b = b;
}

/* a level's four channels of sixteen fragments from their texel words and
** weights (avx2_linear_channels8's sums) */
FX512_INLINE void fx512_linear_channels16(const Fx512Texels *x, __m512i ch[4])
{
    const __m512i one16 = _mm512_set1_epi32(65536);
    const __m512i ia = _mm512_sub_epi32(one16, x->a), ib = _mm512_sub_epi32(one16, x->b);
    for (int k = 0; k < 4; k++)
        ch[k] = fx512_bilerp16_channel(x->g, 8 * k, x->a, ia, x->b, ib);
}

/* avx2_bilerp_to_frag of eight fragments' sums r (< 2^32) */
FX512_INLINE __m512i fx512_bilerp_to_frag(__m256i r)
{
    const __m512i p = _mm512_mul_epu32(_mm512_cvtepu32_epi64(r), _mm512_set1_epi64(16843009));
    return _mm512_srli_epi64(_mm512_add_epi64(p, _mm512_set1_epi64((int64_t)1 << 25)), 26);
}

/* the four channels of eight fragments (lane = fragment, 64-bit lanes)
** stored as each fragment's FRAGV[4] at out + k * stride */
FX512_INLINE void fx512_store_transposed8(const __m512i v[4], FRAGV *out, size_t stride)
{
    const __m512i t0 = _mm512_unpacklo_epi64(v[0], v[1]), t1 = _mm512_unpackhi_epi64(v[0], v[1]);
    const __m512i t2 = _mm512_unpacklo_epi64(v[2], v[3]), t3 = _mm512_unpackhi_epi64(v[2], v[3]);
    /* (fragment 0 | 2), (1 | 3), (4 | 6), (5 | 7) */
    const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11), second = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    const __m512i f[4] = { _mm512_permutex2var_epi64(t0, first, t2), _mm512_permutex2var_epi64(t1, first, t3),
                           _mm512_permutex2var_epi64(t0, second, t2), _mm512_permutex2var_epi64(t1, second, t3) };
    for (int k = 0; k < 4; k++) {
        const int at = 4 * (k >> 1) + (k & 1);      /* fragments at, at + 2 */
        _mm256_storeu_si256((__m256i *)(void *)(out + (size_t)at * stride), _mm512_castsi512_si256(f[k]));
        _mm256_storeu_si256((__m256i *)(void *)(out + (size_t)(at + 2) * stride), _mm512_extracti64x4_epi64(f[k], 1));
    }
}

/* avx2_sample_linear_mix over fragments 0..n-1 sixteen at a time: level
** l1's and l2's bilinear texels, mixed by frac as frag_mul (the product
** of a difference and frac, both in int32 range, rounded by 2^29 and
** shifted arithmetically); returns the fragments done (n rounded down to
** sixteen) */
static __attribute__((noinline)) int fx512_sample_linear_mix(const TexImage *l1, const TexImage *l2, int n,
                                                             const TexCoord *c, const FRAGV *frac, FRAGV *out,
                                                             size_t stride, int repeat_s, int repeat_t)
{
    /* each group's texel words read one group ahead, so that their gathers
    ** overlap the sums of the group before */
    Fx512Texels next1 = { 0 }, next2 = { 0 };
    if (n >= 16) {
        fx512_linear_texels16(l1, c, repeat_s, repeat_t, &next1);
        fx512_linear_texels16(l2, c, repeat_s, repeat_t, &next2);
    }
    int j = 0;
    for (; j + 16 <= n; j += 16) {
        const Fx512Texels x1 = next1, x2 = next2;
        if (j + 32 <= n) {
            fx512_linear_texels16(l1, c + j + 16, repeat_s, repeat_t, &next1);
            fx512_linear_texels16(l2, c + j + 16, repeat_s, repeat_t, &next2);
        }
        __m512i ch1[4], ch2[4];
        fx512_linear_channels16(&x1, ch1);
        fx512_linear_channels16(&x2, ch2);
        for (int h = 0; h < 2; h++) {
            const __m512i f = _mm512_loadu_si512((const void *)&frac[j + 8 * h]);
            __m512i v[4];
            for (int k = 0; k < 4; k++) {
                const __m512i t1 = fx512_bilerp_to_frag(h ? _mm512_extracti64x4_epi64(ch1[k], 1)
                                                          : _mm512_castsi512_si256(ch1[k]));
                const __m512i t2 = fx512_bilerp_to_frag(h ? _mm512_extracti64x4_epi64(ch2[k], 1)
                                                          : _mm512_castsi512_si256(ch2[k]));
                const __m512i p = _mm512_add_epi64(_mm512_mul_epi32(_mm512_sub_epi64(t2, t1), f),
                                                   _mm512_set1_epi64((int64_t)1 << 29));
                v[k] = _mm512_add_epi64(t1, _mm512_srai_epi64(p, 30));
            }
            fx512_store_transposed8(v, out + (size_t)(j + 8 * h) * stride, stride);
        }
    }
    return j;
}
/* }==================================================================== */

/* {====================================================================
** fog (stage_fog's per-vertex factor) for eight fragments at a time:
** avx2_fog4's factor and avx2_fog_mix4's mix, lane by lane */

/* the weights p[0..7][i] of eight fragments as the low dwords of 64-bit
** lanes w[i] (what vpmuldq reads; the high dwords are any) */
FX512_INLINE void fx512_wgt_lanes8(const WGT (*p)[3], __m512i w[3])
{
    const int32_t *q = &p[0][0];
    const __m512i a = _mm512_loadu_si512((const void *)q);                                        /* ints 0..15 */
    const __m512i b = _mm512_castsi256_si512(_mm256_loadu_si256((const __m256i *)(const void *)(q + 16)));   /* 16..23 */
    for (int i = 0; i < 3; i++)
        w[i] = _mm512_permutex2var_epi32(a, _mm512_setr_epi32(i, 0, 3 + i, 0, 6 + i, 0, 9 + i, 0, 12 + i, 0, 15 + i, 0,
                                                              18 + i, 0, 21 + i, 0),
                                         b);
}

/* lanes clamped to [0, 1] (0.30) */
FX512_INLINE __m512i fx512_clamp01(__m512i v)
{
    return _mm512_min_epi64(_mm512_max_epi64(v, _mm512_setzero_si512()), _mm512_set1_epi64(FRAG_ONE));
}

/* frag_mul of lanes in [0, 2^32): (a b + 2^29) >> 30 */
FX512_INLINE __m512i fx512_mul_u(__m512i a, __m512i b)
{
    return _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epu32(a, b), _mm512_set1_epi64((int64_t)1 << 29)), 30);
}

/* fragments c[0..7]'s channels as lanes ch[0..3] (64-bit lanes, lane =
** fragment), the colour channels fogged: frag_mul(f, clamp01(c)) +
** frag_mul(1 - f, fc) with the factor f of the per-vertex factors av at
** the weights p (rounded half away from zero by 16 bits, clamped) */
FX512_INLINE void fx512_fog8(const __m512i av[3], const __m512i fcv[3], const WGT (*p)[3], const FRAGV (*c)[4],
                             __m512i ch[4])
{
    /* (r | g) and (b | a) of four fragments, from two registers of two */
    const __m512i rg = _mm512_setr_epi64(0, 4, 8, 12, 1, 5, 9, 13), ba = _mm512_setr_epi64(2, 6, 10, 14, 3, 7, 11, 15);
    __m512i w[3];
    fx512_wgt_lanes8(p, w);
    const __m512i acc = _mm512_add_epi64(_mm512_add_epi64(_mm512_mul_epi32(av[0], w[0]), _mm512_mul_epi32(av[1], w[1])),
                                         _mm512_mul_epi32(av[2], w[2]));
    const __m512i f = fx512_clamp01(_mm512_srai_epi64(
        _mm512_add_epi64(_mm512_add_epi64(acc, _mm512_set1_epi64((int64_t)1 << 15)), _mm512_srai_epi64(acc, 63)), 16));
    const __m512i g = _mm512_sub_epi64(_mm512_set1_epi64(FRAG_ONE), f);
    __m512i z[4];
    for (int k = 0; k < 4; k++)
        z[k] = _mm512_loadu_si512((const void *)c[2 * k]);
    const __m512i x0 = _mm512_permutex2var_epi64(z[0], rg, z[1]), y0 = _mm512_permutex2var_epi64(z[2], rg, z[3]);
    const __m512i x1 = _mm512_permutex2var_epi64(z[0], ba, z[1]), y1 = _mm512_permutex2var_epi64(z[2], ba, z[3]);
    ch[0] = _mm512_shuffle_i64x2(x0, y0, _MM_SHUFFLE(1, 0, 1, 0));
    ch[1] = _mm512_shuffle_i64x2(x0, y0, _MM_SHUFFLE(3, 2, 3, 2));
    ch[2] = _mm512_shuffle_i64x2(x1, y1, _MM_SHUFFLE(1, 0, 1, 0));
    ch[3] = _mm512_shuffle_i64x2(x1, y1, _MM_SHUFFLE(3, 2, 3, 2));
    for (int i = 0; i < 3; i++)
        ch[i] = _mm512_add_epi64(fx512_mul_u(f, fx512_clamp01(ch[i])), fx512_mul_u(g, fcv[i]));
}

/* stage_fog's mix of fragments 0..n-1's colours c with the per-vertex
** factors a[0..2] (each in [-2^30, 2^30]) at their weights p, eight at a
** time: the factor a0 w0 + a1 w1 + a2 w2 rounded half away from zero by 16
** bits and clamped to [0, 1], then frag_mul(f, clamp01(c)) + frag_mul(1 -
** f, fc) in the three colour channels (the fog colour's channels fc in
** [0, 2^31)); returns the fragments done (n rounded down to eight) */
static __attribute__((noinline)) int fx512_fog(const NUM a[3], const WGT (*p)[3], FRAGV (*c)[4], int n,
                                               const FRAGV fc[3])
{
    const __m512i av[3] = { _mm512_set1_epi64(a[0]), _mm512_set1_epi64(a[1]), _mm512_set1_epi64(a[2]) };
    const __m512i fcv[3] = { _mm512_set1_epi64(fc[0]), _mm512_set1_epi64(fc[1]), _mm512_set1_epi64(fc[2]) };
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        __m512i ch[4];
        fx512_fog8(av, fcv, &p[j], (const FRAGV (*)[4])&c[j], ch);
        fx512_store_transposed8(ch, c[j], 4);
    }
    return j;
}

/* fx512_fog of fragments 0..n-1 (eight at a time) and write_rgba8's kind 0
** of the result in the same pass: each channel (the fogged colour, and
** the alpha as it is) clamped to [0, 2^30] and turned to a byte as
** frag_to_unorm(v, 255) does, (255 v + 2^29) >> 30 (0 at 0, 255 at
** 2^30), the four bytes packed into the words dst[k[j]] (one store for
** eight neighbouring pixels); the colours are not stored back. Returns the
** fragments done (n rounded down to eight) */
static __attribute__((noinline)) int fx512_fog_write_rgba8(const NUM a[3], const WGT (*p)[3], const FRAGV (*c)[4],
                                                           int n, const FRAGV fc[3], uint32_t *dst,
                                                           const uint8_t *k)
{
    const __m512i av[3] = { _mm512_set1_epi64(a[0]), _mm512_set1_epi64(a[1]), _mm512_set1_epi64(a[2]) };
    const __m512i fcv[3] = { _mm512_set1_epi64(fc[0]), _mm512_set1_epi64(fc[1]), _mm512_set1_epi64(fc[2]) };
    const __m512i b255 = _mm512_set1_epi64(255), half = _mm512_set1_epi64((int64_t)1 << 29);
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        __m512i ch[4], word = _mm512_setzero_si512();
        fx512_fog8(av, fcv, &p[j], &c[j], ch);
        for (int i = 0; i < 4; i++) {
            const __m512i byte = _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epu32(fx512_clamp01(ch[i]), b255), half), 30);
            word = _mm512_or_si512(word, _mm512_slli_epi64(byte, 8 * i));
        }
        avx2_store_words8(dst, &k[j], k[j + 7] == k[j] + 7, _mm512_cvtepi64_epi32(word));
    }
    return j;
}
/* fx512_fog of fragments 0..n-1 (eight at a time) and stage_write_565's
** pack565 of the result in the same pass (v4_pack565's operations lane by
** lane): each colour channel taken to 5, 6 and 5 bits, dithered by the
** threshold t_row[(x0 + k[j]) & 3] as (min(max(v, 0), 2^30) top + t) >> 30,
** or without dither as min(max(v, 0) >> (30 - bits), top); the three
** packed into the words dst[k[j]] (one store for eight neighbouring
** pixels); the colours are not stored back. Returns the fragments done (n
** rounded down to eight) */
static __attribute__((noinline)) int fx512_fog_write_565(const NUM a[3], const WGT (*p)[3], const FRAGV (*c)[4],
                                                         int n, const FRAGV fc[3], uint16_t *dst, const uint8_t *k,
                                                         int x0, int dither, const FRAGV t_row[4])
{
    const __m512i av[3] = { _mm512_set1_epi64(a[0]), _mm512_set1_epi64(a[1]), _mm512_set1_epi64(a[2]) };
    const __m512i fcv[3] = { _mm512_set1_epi64(fc[0]), _mm512_set1_epi64(fc[1]), _mm512_set1_epi64(fc[2]) };
    const __m512i zero = _mm512_setzero_si512(), one = _mm512_set1_epi64(FRAG_ONE);
    const __m512i t4 = _mm512_setr_epi64(t_row[0], t_row[1], t_row[2], t_row[3], t_row[0], t_row[1], t_row[2],
                                         t_row[3]);
    const int bits[3] = { 5, 6, 5 }, shift[3] = { 11, 5, 0 };
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        __m512i ch[4], word = zero;
        fx512_fog8(av, fcv, &p[j], &c[j], ch);
        const __m512i x = _mm512_add_epi64(_mm512_cvtepu8_epi64(_mm_loadl_epi64((const __m128i *)(const void *)&k[j])),
                                           _mm512_set1_epi64(x0));
        const __m512i t = _mm512_permutexvar_epi64(x, t4);     /* (the index's low three bits; t4 repeats) */
        for (int i = 0; i < 3; i++) {
            const __m512i top = _mm512_set1_epi64((1 << bits[i]) - 1);
            const __m512i v = _mm512_max_epi64(ch[i], zero);
            const __m512i r = dither
                ? _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epu32(_mm512_min_epi64(v, one), top), t), 30)
                : _mm512_min_epi64(_mm512_srli_epi64(v, 30 - bits[i]), top);
            word = _mm512_or_si512(word, _mm512_slli_epi64(r, shift[i]));
        }
        avx2_store_halves8(dst, &k[j], k[j + 7] == k[j] + 7, _mm512_cvtepi64_epi16(word));
    }
    return j;
}
/* }==================================================================== */

#undef FX512_INLINE
#endif
#endif
