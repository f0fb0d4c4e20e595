/*
** span_avx2.h -- AVX2 kernels of the fixed build's hottest fragment work,
** for the AVX2 instance of the span stages (span_stages.h) and samplers
** (texsample.c); included only where SIMD_TARGET_AVX2 (simd.h) holds.
**
** A fragment's four FRAGV channels (0.30 in int64) are one 256-bit
** register. Each kernel is the scalar function's arithmetic, lane by lane:
** the products the scalar code forms in 64 bits have operands that fit in
** 32 bits (colours and weights of at most 2^30 in magnitude), so one
** 32x32->64 multiply (vpmuludq, vpmuldq) forms each exactly, and the
** rounding shifts are the same. Kernels whose operands could leave that
** range check it and leave such fragments to the scalar code.
*/
#ifndef GLES_SPAN_AVX2_H
#define GLES_SPAN_AVX2_H

#if SIMD_X86
#include <immintrin.h>
#include <string.h>
#include "fx_avx2.h"

#define AVX2_INLINE static inline __attribute__((always_inline))

/* int64 lanes of magnitude below 2^51 as doubles (exact: the bias 2^52 +
** 2^51 puts the integer in the mantissa's low bits) */
#define AVX2_I64_BIAS 6755399441055744.0
AVX2_INLINE __m256d avx2_i64_to_pd(__m256i v)
{
    const __m256d magic = _mm256_set1_pd(AVX2_I64_BIAS);
    return _mm256_sub_pd(_mm256_castsi256_pd(_mm256_add_epi64(v, _mm256_castpd_si256(magic))), magic);
}

/* the edge values e0 + ea k at slots' offsets k, four at a time: k ea is
** formed as k ea_lo + ((k ea_hi) << 32), the product mod 2^64, which is the
** scalar code's product wherever that fits int64 (chunk_edges forms it).
** The broadcasts live in a local struct so that a loop keeps them in
** registers (stores to the span buffer could otherwise alias t and b). */
typedef struct Edges4 {
    __m256i e0[3], lo[3], hi[3];
    int narrow;     /* every ea_i in int32 range: k ea is one vpmuldq (k < 2^8) */
} Edges4;

AVX2_INLINE void avx2_edges4_setup(const int64_t e0[3], const int64_t ea[3], Edges4 *ed)
{
    for (int i = 0; i < 3; i++) {
        ed->e0[i] = _mm256_set1_epi64x(e0[i]);
        ed->lo[i] = _mm256_set1_epi64x(ea[i]);
        ed->hi[i] = _mm256_set1_epi64x((int64_t)((uint64_t)ea[i] >> 32));
    }
    ed->narrow = 1;
    for (int i = 0; i < 3; i++)
        ed->narrow &= ea[i] >= INT32_MIN && ea[i] <= INT32_MAX;
}

AVX2_INLINE void avx2_edges4(const Edges4 *ed, const uint8_t *k, __m256i ev[3])
{
    uint32_t k4;
    memcpy(&k4, k, sizeof k4);
    const __m256i kv = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128((int)k4));
    if (ed->narrow) {
        for (int i = 0; i < 3; i++)
            ev[i] = _mm256_add_epi64(ed->e0[i], _mm256_mul_epi32(kv, ed->lo[i]));
        return;
    }
    for (int i = 0; i < 3; i++)
        ev[i] = _mm256_add_epi64(ed->e0[i], _mm256_add_epi64(_mm256_mul_epu32(kv, ed->lo[i]),
                                                              _mm256_slli_epi64(_mm256_mul_epu32(kv, ed->hi[i]), 32)));
}

/* three vectors of four 32-bit lanes a, b, c stored interleaved as
** a0 b0 c0 a1 b1 c1 a2 b2 c2 a3 b3 c3 (four fragments' three weights) */
AVX2_INLINE void avx2_store3x4_32(__m128i a, __m128i b, __m128i c, void *out)
{
    const __m256i ab = _mm256_inserti128_si256(_mm256_castsi128_si256(a), b, 1);
    const __m256i cc = _mm256_castsi128_si256(c);
    const __m256i first = _mm256_blend_epi32(_mm256_permutevar8x32_epi32(ab, _mm256_setr_epi32(0, 4, 0, 1, 5, 0, 2, 6)),
                                             _mm256_permutevar8x32_epi32(cc, _mm256_setr_epi32(0, 0, 0, 0, 0, 1, 0, 0)),
                                             0x24);
    const __m128i last = _mm_blend_epi32(_mm256_castsi256_si128(_mm256_permutevar8x32_epi32(ab, _mm256_setr_epi32(0, 3, 7, 0, 0, 0, 0, 0))),
                                         _mm_shuffle_epi32(c, _MM_SHUFFLE(3, 0, 0, 2)), 0x9);
    _mm256_storeu_si256((__m256i *)out, first);
    _mm_storeu_si128((__m128i *)((char *)out + 32), last);
}

/* the byte shuffle that takes byte i (0..3) of every dword to the dword,
** zero-extended */
AVX2_INLINE __m256i avx2_byte_pick8(int i)
{
    return _mm256_setr_epi8(i, -1, -1, -1, 4 + i, -1, -1, -1, 8 + i, -1, -1, -1, 12 + i, -1, -1, -1, i, -1, -1, -1,
                            4 + i, -1, -1, -1, 8 + i, -1, -1, -1, 12 + i, -1, -1, -1);
}
/* byte i of every dword of g, zero-extended: a mask for the low byte, a
** shift for the high one, the shuffle between. (Where the same shuffle
** serves four texel words, as in avx2_bilerp8_float and f8_byte, the
** shuffle alone measured fewer instructions.) */
AVX2_INLINE __m256i avx2_byte_lanes8(__m256i g, int i)
{
    if (i == 0)
        return _mm256_and_si256(g, _mm256_set1_epi32(0xFF));
    if (i == 3)
        return _mm256_srli_epi32(g, 24);
    return _mm256_shuffle_epi8(g, avx2_byte_pick8(i));
}

/* 24 consecutive 32-bit values in q0, q1, q2 (eight fragments' three
** values each) as three registers: lane L of w[i] is value 3L + i */
AVX2_INLINE void avx2_deinterleave3x8(__m256i q0, __m256i q1, __m256i q2, __m256i w[3])
{
    w[0] = _mm256_permutevar8x32_epi32(_mm256_blend_epi32(_mm256_blend_epi32(q0, q1, 0x92), q2, 0x24),
                                       _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
    w[1] = _mm256_permutevar8x32_epi32(_mm256_blend_epi32(_mm256_blend_epi32(q0, q1, 0x24), q2, 0x49),
                                       _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6));
    w[2] = _mm256_permutevar8x32_epi32(_mm256_blend_epi32(_mm256_blend_epi32(q0, q1, 0x49), q2, 0x92),
                                       _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
}

/* The texel words of a bilinear group of eight fragments (every build's
** kernel): lanes xa, xb the columns and ya, yb the rows of its four texels
** on a level w texels wide of `total` texels, g[0..3] the words at (xa, ya),
** (xb, ya), (xa, yb), (xb, yb). Where every lane reads the same two rows
** and its columns lie in the eight from lane 0's xa on (a magnified or
** axis-aligned texture: blits, sprites, screen-aligned quads), a load of
** eight texels from each row and four permutations give the words the
** gathers would, in a fraction of their time on CPUs whose gathers are
** slow; where they lie in the sixteen from there (a texture minified up
** to about 2:1), two loads per row, and each word the permutation of the
** half its column is in. 0 (g untouched) where that does not hold or a
** load would pass the level's end. */
AVX2_INLINE int avx2_row_texels8(const void *texels, int64_t w, int64_t total, __m256i xa, __m256i xb, __m256i ya,
                                 __m256i yb, __m256i g[4])
{
    const __m256i lane0 = _mm256_setzero_si256();
    const __m256i x0 = _mm256_permutevar8x32_epi32(xa, lane0);
    const __m256i da = _mm256_sub_epi32(xa, x0), db = _mm256_sub_epi32(xb, x0);
    const __m256i same_rows = _mm256_and_si256(_mm256_cmpeq_epi32(ya, _mm256_permutevar8x32_epi32(ya, lane0)),
                                               _mm256_cmpeq_epi32(yb, _mm256_permutevar8x32_epi32(yb, lane0)));
    const __m256i offsets = _mm256_or_si256(da, db);
    if (_mm256_movemask_epi8(same_rows) != -1 || !_mm256_testz_si256(offsets, _mm256_set1_epi32(~15)))
        return 0;
    /* (permutevar8x32 reads the low three bits of an offset) */
    const int wide = !_mm256_testz_si256(offsets, _mm256_set1_epi32(8));
    const int64_t col = _mm256_cvtsi256_si32(xa);
    const int64_t first0 = _mm256_cvtsi256_si32(ya) * w + col, first1 = _mm256_cvtsi256_si32(yb) * w + col;
    const int64_t span = wide ? 16 : 8;
    if (first0 + span > total || first1 + span > total)
        return 0;
    const int *tx32 = texels;
    const __m256i row0 = _mm256_loadu_si256((const __m256i *)(const void *)(tx32 + first0));
    const __m256i row1 = _mm256_loadu_si256((const __m256i *)(const void *)(tx32 + first1));
    g[0] = _mm256_permutevar8x32_epi32(row0, da);
    g[1] = _mm256_permutevar8x32_epi32(row0, db);
    g[2] = _mm256_permutevar8x32_epi32(row1, da);
    g[3] = _mm256_permutevar8x32_epi32(row1, db);
    if (wide) {
        const __m256i next0 = _mm256_loadu_si256((const __m256i *)(const void *)(tx32 + first0 + 8));
        const __m256i next1 = _mm256_loadu_si256((const __m256i *)(const void *)(tx32 + first1 + 8));
        const __m256i in_a = _mm256_cmpgt_epi32(da, _mm256_set1_epi32(7));
        const __m256i in_b = _mm256_cmpgt_epi32(db, _mm256_set1_epi32(7));
        g[0] = _mm256_blendv_epi8(g[0], _mm256_permutevar8x32_epi32(next0, da), in_a);
        g[1] = _mm256_blendv_epi8(g[1], _mm256_permutevar8x32_epi32(next0, db), in_b);
        g[2] = _mm256_blendv_epi8(g[2], _mm256_permutevar8x32_epi32(next1, da), in_a);
        g[3] = _mm256_blendv_epi8(g[3], _mm256_permutevar8x32_epi32(next1, db), in_b);
    }
    return 1;
}

/* the texels at indices i (eight lanes) and i + 1, as two registers of
** eight lanes, by two gathers of four 64-bit words (each word is the pair) */
AVX2_INLINE void avx2_gather_pairs(const int *tx32, __m256i i, __m256i *left, __m256i *right)
{
    const long long *base = (const long long *)(const void *)tx32;
    const __m256i lo = _mm256_i32gather_epi64(base, _mm256_castsi256_si128(i), 4);
    const __m256i hi = _mm256_i32gather_epi64(base, _mm256_extracti128_si256(i, 1), 4);
    const __m256i split = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
    const __m256i a = _mm256_permutevar8x32_epi32(lo, split), b = _mm256_permutevar8x32_epi32(hi, split);
    *left = _mm256_permute2x128_si256(a, b, 0x20);
    *right = _mm256_permute2x128_si256(a, b, 0x31);
}

/* eight words w into dst[k[0..7]]: one store where the offsets are eight
** neighbouring pixels (run), else eight */
AVX2_INLINE void avx2_store_words8(uint32_t *dst, const uint8_t *k, int run, __m256i w)
{
    if (run) {
        _mm256_storeu_si256((__m256i *)(void *)&dst[k[0]], w);
        return;
    }
    uint32_t words[8];
    _mm256_storeu_si256((__m256i *)(void *)words, w);
    for (int i = 0; i < 8; i++)
        dst[k[i]] = words[i];
}

/* the same for eight 16-bit words w (RGB565) */
AVX2_INLINE void avx2_store_halves8(uint16_t *dst, const uint8_t *k, int run, __m128i w)
{
    if (run) {
        _mm_storeu_si128((__m128i *)(void *)&dst[k[0]], w);
        return;
    }
    uint16_t halves[8];
    _mm_storeu_si128((__m128i *)(void *)halves, w);
    for (int i = 0; i < 8; i++)
        dst[k[i]] = halves[i];
}

/* the same words by avx2_row_texels8 where `rows` asks for it and it
** applies, else, where no lane's pair wraps, by gathers of the pairs as
** 64-bit words (half the elements), else by four gathers of eight (the
** float and double builds' kernels, on levels of any width) */
AVX2_INLINE void avx2_texel_words8(const void *texels, int w, int64_t total, __m256i xa, __m256i xb, __m256i ya,
                                   __m256i yb, int rows, __m256i g[4])
{
    if (rows && avx2_row_texels8(texels, w, total, xa, xb, ya, yb, g))
        return;
    const int *tx32 = texels;
    const __m256i r0 = _mm256_mullo_epi32(ya, _mm256_set1_epi32(w)), r1 = _mm256_mullo_epi32(yb, _mm256_set1_epi32(w));
    if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(xb, _mm256_add_epi32(xa, _mm256_set1_epi32(1)))) == -1) {
        /* no lane wraps or clamps at the right edge: each row's two
        ** texels are one 64-bit word (avx2_linear_texels8's pairs) */
        avx2_gather_pairs(tx32, _mm256_add_epi32(r0, xa), &g[0], &g[1]);
        avx2_gather_pairs(tx32, _mm256_add_epi32(r1, xa), &g[2], &g[3]);
        return;
    }
    g[0] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r0, xa), 4);
    g[1] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r0, xb), 4);
    g[2] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r1, xa), 4);
    g[3] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r1, xb), 4);
}
#endif

#if SIMD_X86 && NUM_IS_FIXED
/* avx2_linear_axis8's constants of an axis 2^L texels wide (a kernel that
** keeps them per primitive reads them from memory in its loop) */
typedef struct Avx2Axis {
    __m256i half, top;          /* 2^(31 - L) and 2^L - 1 in every lane */
    __m128i to_index, up;       /* the shift counts 32 - L and L */
} Avx2Axis;

AVX2_INLINE void avx2_axis_setup(int log2n, Avx2Axis *ax)
{
    ax->half = _mm256_set1_epi32((int)(0x80000000u >> log2n));
    ax->top = _mm256_set1_epi32((1 << log2n) - 1);
    ax->to_index = _mm_cvtsi32_si128(32 - log2n);
    ax->up = _mm_cvtsi32_si128(log2n);
}

/* the weights of eight fragments in lanes, for the fixed build's fused stage
** (where WGT is 32 bits) */
/* the three weights of fragments p[0..7] as eight 32-bit lanes each: the
** 24 stride-3 integers are three loads; lane L of w[i] is integer 3L + i */
AVX2_INLINE void avx2_wgt_lanes8(const WGT (*p)[3], __m256i w[3])
{
    const __m256i *q = (const __m256i *)(const void *)&p[0][0];
    avx2_deinterleave3x8(_mm256_loadu_si256(q), _mm256_loadu_si256(q + 1), _mm256_loadu_si256(q + 2), w);
}

/* the four channels of a FRAGV[4] */
AVX2_INLINE __m256i avx2_load4(const FRAGV *c) { return _mm256_loadu_si256((const __m256i *)(const void *)c); }
AVX2_INLINE void avx2_store4(FRAGV *c, __m256i v) { _mm256_storeu_si256((__m256i *)(void *)c, v); }

/* frag_clamp01 per lane */
AVX2_INLINE __m256i avx2_clamp01(__m256i v)
{
    const __m256i one = _mm256_set1_epi64x(FRAG_ONE);
    v = _mm256_andnot_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), v), v);
    return _mm256_blendv_epi8(v, one, _mm256_cmpgt_epi64(v, one));
}

/* frag_mul of lanes in [0, 2^32): (a b + 2^29) >> 30 */
AVX2_INLINE __m256i avx2_mul_u(__m256i a, __m256i b)
{
    return _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(a, b), _mm256_set1_epi64x((int64_t)1 << 29)), 30);
}

/* 1 when every lane lies in [0, 2^31) (a valid operand of avx2_mul_u) */
AVX2_INLINE int avx2_fits_u31(__m256i v)
{
    return _mm256_testz_si256(v, _mm256_set1_epi64x(~(int64_t)0x7FFFFFFF));
}

/* the 0.30 values of the four bytes of a framebuffer or texel word,
** frag_from_unorm(d, 255) = d * 4210752 + ((d + 2) >> 2) exactly for every
** d in [0, 255] (ctx->unorm8's entries) */
AVX2_INLINE __m256i avx2_unorm8(uint32_t word)
{
    __m256i d = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128((int)word));
    __m256i hi = _mm256_mul_epu32(d, _mm256_set1_epi64x(4210752));
    return _mm256_add_epi64(hi, _mm256_srli_epi64(_mm256_add_epi64(d, _mm256_set1_epi64x(2)), 2));
}

/* frag_to_unorm(v, 255, 1/2) of lanes >= 0, packed as RGBA8888 */
AVX2_INLINE uint32_t avx2_pack_unorm8(__m256i v)
{
    const __m256i one = _mm256_set1_epi64x(FRAG_ONE);
    v = _mm256_blendv_epi8(v, one, _mm256_cmpgt_epi64(v, one));
    v = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(v, _mm256_set1_epi64x(255)),
                                           _mm256_set1_epi64x((int64_t)1 << 29)), 30);
    /* the low byte of each 64-bit lane, in lane order: lanes 0, 1 to bytes
    ** 0, 1 of the low half, lanes 2, 3 to bytes 2, 3 of the high half */
    const __m256i pick = _mm256_setr_epi8(0, 8, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
                                          -1, -1, 0, 8, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
    v = _mm256_shuffle_epi8(v, pick);
    return (uint32_t)_mm_cvtsi128_si32(_mm_or_si128(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1)));
}

/* frag_bilerp_rgba8: the same sum, as ib (c00 ia + c10 a) + b (c01 ia + c11 a)
** (an exact regrouping: every partial sum fits its lanes). Not forced
** inline: sample_level names it in the baseline samplers too, where the
** branch that calls it is folded away. */
static inline void avx2_bilerp_rgba8(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, TEXW a, TEXW b,
                                   FRAGV out[4])
{
    const int ia = 65536 - a, ib = 65536 - b;
    const __m256i wa = _mm256_setr_epi32(ia, ia, ia, ia, a, a, a, a);
    __m256i x0 = _mm256_mullo_epi32(_mm256_cvtepu8_epi32(_mm_set_epi32(0, 0, (int)c10, (int)c00)), wa);
    __m256i x1 = _mm256_mullo_epi32(_mm256_cvtepu8_epi32(_mm_set_epi32(0, 0, (int)c11, (int)c01)), wa);
    __m128i h0 = _mm_add_epi32(_mm256_castsi256_si128(x0), _mm256_extracti128_si256(x0, 1));   /* < 2^24 */
    __m128i h1 = _mm_add_epi32(_mm256_castsi256_si128(x1), _mm256_extracti128_si256(x1, 1));
    __m256i acc = _mm256_add_epi64(_mm256_mul_epu32(_mm256_cvtepu32_epi64(h0), _mm256_set1_epi64x(ib)),
                                   _mm256_mul_epu32(_mm256_cvtepu32_epi64(h1), _mm256_set1_epi64x(b)));
    __m256i r = _mm256_srli_epi64(_mm256_add_epi64(acc, _mm256_set1_epi64x(128)), 8);     /* < 2^32 */
    r = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(r, _mm256_set1_epi64x(16843009)),
                                           _mm256_set1_epi64x((int64_t)1 << 25)), 26);
    avx2_store4(out, r);
}

/* {====================================================================
** signs and conversions of 64-bit lanes */

/* all ones in the lanes that are negative */
AVX2_INLINE __m256i avx2_negative(__m256i v) { return _mm256_cmpgt_epi64(_mm256_setzero_si256(), v); }
/* v where mask is 0, -v where it is all ones (so |v| with mask = avx2_negative(v),
** and the sign put back on a magnitude) */
AVX2_INLINE __m256i avx2_negate_where(__m256i v, __m256i mask) { return _mm256_sub_epi64(_mm256_xor_si256(v, mask), mask); }
AVX2_INLINE __m256i avx2_abs64(__m256i v) { return avx2_negate_where(v, avx2_negative(v)); }

/* each lane rounded half away from zero to `shift` fewer fraction bits:
** with h = 2^(shift - 1), (x + h) >> shift for x >= 0 and -((h - x) >> shift)
** = floor((x + h - 1) / 2^shift) for x < 0, so floor((x + h + s) / 2^shift)
** with s = -1 where x < 0. AVX2 has no 64-bit arithmetic shift: z + 2^63
** (mod 2^64, the unsigned order of signed z) shifted logically is
** floor(z / 2^shift) + 2^(63 - shift), which comes off after. */
AVX2_INLINE __m256i avx2_round_shift(__m256i acc, int shift)
{
    const __m256i bias = _mm256_set1_epi64x(INT64_MIN + ((int64_t)1 << (shift - 1)));   /* 2^63 + h mod 2^64 */
    const __m256i z = _mm256_add_epi64(_mm256_add_epi64(acc, avx2_negative(acc)), bias);
    return _mm256_sub_epi64(_mm256_srli_epi64(z, shift), _mm256_set1_epi64x((int64_t)1 << (63 - shift)));
}

/* four fragments' s and t (lanes = fragments) stored as TexCoord out[0..3] */
AVX2_INLINE void avx2_store_st4(__m256i s, __m256i t, TexCoord *out)
{
    const __m256i lo = _mm256_unpacklo_epi64(s, t), hi = _mm256_unpackhi_epi64(s, t);   /* s0 t0 s2 t2, s1 t1 s3 t3 */
    /* a 128-bit store per fragment: the halves need no lane-crossing shuffle */
    _mm_storeu_si128((__m128i *)(void *)out, _mm256_castsi256_si128(lo));
    _mm_storeu_si128((__m128i *)(void *)(out + 1), _mm256_castsi256_si128(hi));
    _mm_storeu_si128((__m128i *)(void *)(out + 2), _mm256_extracti128_si256(lo, 1));
    _mm_storeu_si128((__m128i *)(void *)(out + 3), _mm256_extracti128_si256(hi, 1));
}

/* }==================================================================== */

/* a0 w0 + a1 w1 + a2 w2 per lane, rounded half away from zero to `shift`
** fewer fraction bits: the a lanes in int32 range, the weights any WGT */
AVX2_INLINE __m256i avx2_lerp3w(__m256i a0, __m256i a1, __m256i a2, __m128i w, int shift)
{
    /* the three weights w0..w2, each in the low dword of every lane (vpmuldq reads those) */
    const __m256i ww = _mm256_broadcastsi128_si256(w);
    __m256i acc = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(a0, _mm256_shuffle_epi32(ww, 0x00)),
                                                    _mm256_mul_epi32(a1, _mm256_shuffle_epi32(ww, 0x55))),
                                   _mm256_mul_epi32(a2, _mm256_shuffle_epi32(ww, 0xAA)));
    return avx2_round_shift(acc, shift);
}

/* the same with the weights p[0..2] read from memory */
AVX2_INLINE __m256i avx2_lerp3(__m256i a0, __m256i a1, __m256i a2, const WGT *p, int shift)
{
    return avx2_lerp3w(a0, a1, a2, _mm_insert_epi32(_mm_loadl_epi64((const __m128i *)(const void *)p), p[2], 2),
                       shift);
}

/* frag_lerp3f of the four channels */
AVX2_INLINE __m256i avx2_lerp3f(__m256i a0, __m256i a1, __m256i a2, const WGT *p)
{
    return avx2_lerp3(a0, a1, a2, p, 30);
}

/* a vertex's texture coordinates s, t, r, q (16.16) as four lanes */
AVX2_INLINE __m256i avx2_load_num4(const NUM *a)
{
    return _mm256_cvtepi32_epi64(_mm_loadu_si128((const __m128i *)(const void *)a));
}

/* span_tex_coord: texc_lerp3 of s, t (and q) in one register */
AVX2_INLINE void avx2_tex_coord(int projective, const __m256i a[3], const WGT p[3], TexCoord *out)
{
    const __m256i v = avx2_lerp3(a[0], a[1], a[2], p, 14);
    if (!projective) {
        _mm_storeu_si128((__m128i *)(void *)out, _mm256_castsi256_si128(v));   /* s, t */
        return;
    }
    int64_t lanes[4];
    _mm256_storeu_si256((__m256i *)(void *)lanes, v);
    out->s = texc_div(lanes[0], lanes[3]);
    out->t = texc_div(lanes[1], lanes[3]);
}

/* the weights p[0..3][i] of four fragments as the low dwords of 64-bit
** lanes (what vpmuldq reads): the twelve WGT as two overlapping loads of
** eight, permuted */
AVX2_INLINE void avx2_wgt_lanes4(const WGT (*p)[3], __m256i w[3])
{
    const int32_t *q = &p[0][0];
    const __m256i a = _mm256_loadu_si256((const __m256i *)(const void *)q);         /* ints 0..7 */
    const __m256i b = _mm256_loadu_si256((const __m256i *)(const void *)(q + 4));   /* ints 4..11 */
    w[0] = _mm256_blend_epi32(_mm256_permutevar8x32_epi32(a, _mm256_setr_epi32(0, 0, 3, 3, 6, 6, 6, 6)),
                              _mm256_permutevar8x32_epi32(b, _mm256_set1_epi32(5)), 0xC0);
    w[1] = _mm256_blend_epi32(_mm256_permutevar8x32_epi32(a, _mm256_setr_epi32(1, 1, 4, 4, 7, 7, 7, 7)),
                              _mm256_permutevar8x32_epi32(b, _mm256_set1_epi32(6)), 0xC0);
    w[2] = _mm256_blend_epi32(_mm256_permutevar8x32_epi32(a, _mm256_setr_epi32(2, 2, 5, 5, 5, 5, 5, 5)),
                              _mm256_permutevar8x32_epi32(b, _mm256_setr_epi32(4, 4, 4, 4, 4, 4, 7, 7)), 0xF0);
}

/* a[0] w[0] + a[1] w[1] + a[2] w[2] per lane (four fragments' weights w as
** avx2_wgt_lanes4 gives them, vertex values a in int32 range, in every
** lane), the 64-bit sum of avx2_lerp3w's lanes */
AVX2_INLINE __m256i avx2_dot3_lanesv(const __m256i a[3], const __m256i w[3])
{
    return _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(a[0], w[0]), _mm256_mul_epi32(a[1], w[1])),
                            _mm256_mul_epi32(a[2], w[2]));
}

/* the same of the vertex values a0, a1, a2 */
AVX2_INLINE __m256i avx2_dot3_lanes(int64_t a0, int64_t a1, int64_t a2, const __m256i w[3])
{
    const __m256i a[3] = { _mm256_set1_epi64x(a0), _mm256_set1_epi64x(a1), _mm256_set1_epi64x(a2) };
    return avx2_dot3_lanesv(a, w);
}

/* texc_lerp3 of one coordinate (vertex values a[0..2], 16.16) for four
** fragments (lanes) whose weights are w: each lane's sum and rounding are
** avx2_lerp3's */
AVX2_INLINE __m256i avx2_texc_lerp3x4(const NUM a[3], const __m256i w[3])
{
    return avx2_round_shift(avx2_dot3_lanes(a[0], a[1], a[2], w), 14);
}

/* the same from the vertex values in every lane (a kept setup's) */
AVX2_INLINE __m256i avx2_texc_lerp3x4v(const __m256i a[3], const __m256i w[3])
{
    return avx2_round_shift(avx2_dot3_lanesv(a, w), 14);
}

/* span_tex_coord without q (an affine unit) for four fragments: s and t
** of vertex values sv[0..2], tv[0..2] at weights p[0..3], into out[0..3] */
AVX2_INLINE void avx2_tex_coord_affine4(const NUM sv[3], const NUM tv[3], const WGT (*p)[3], TexCoord *out)
{
    __m256i w[3];
    avx2_wgt_lanes4(p, w);
    avx2_store_st4(avx2_texc_lerp3x4(sv, w), avx2_texc_lerp3x4(tv, w), out);
}

/* 1 when every lane lies in the int32 range (an operand of vpmuldq) */
AVX2_INLINE int avx2_fits_i32(__m256i v)
{
    const __m256i lo = _mm256_set1_epi64x(INT32_MIN), hi = _mm256_set1_epi64x(INT32_MAX);
    return _mm256_testz_si256(_mm256_or_si256(_mm256_cmpgt_epi64(lo, v), _mm256_cmpgt_epi64(v, hi)),
                              _mm256_set1_epi64x(-1));
}

_Static_assert(sizeof(TexCoord) == 2 * sizeof(TEXC), "TexCoord is s then t");

/* frag_bilerp_rgba8's value of one channel (bits sh..sh+7 of the texel
** words) for eight fragments at once, in 32-bit lanes. With h0 = c00 ia +
** c10 a and h1 = c01 ia + c11 a (each < 2^24), the scalar code's
** (ib h0 + b h1 + 128) >> 8 needs 40 bits; split h = 2^8 hh + hl, it is
** ib hh0 + b hh1 + ((ib hl0 + b hl1 + 128) >> 8) exactly (the first sum
** is a multiple of 2^8 in the whole), and with ib + b = 2^16 both parts
** fit 32 unsigned bits, as does their sum (< 2^32, the scalar bound). */
AVX2_INLINE __m256i avx2_bilerp8_channel(const __m256i g[4], int sh, __m256i a, __m256i ia, __m256i b, __m256i ib)
{
    const __m256i byte = _mm256_set1_epi32(0xFF);
    __m256i c[4];
    for (int i = 0; i < 4; i++)
        c[i] = sh == 24 ? _mm256_srli_epi32(g[i], 24) : _mm256_and_si256(_mm256_srli_epi32(g[i], sh), byte);
    const __m256i h0 = _mm256_add_epi32(_mm256_mullo_epi32(c[0], ia), _mm256_mullo_epi32(c[1], a));
    const __m256i h1 = _mm256_add_epi32(_mm256_mullo_epi32(c[2], ia), _mm256_mullo_epi32(c[3], a));
    const __m256i hi = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_srli_epi32(h0, 8), ib),
                                        _mm256_mullo_epi32(_mm256_srli_epi32(h1, 8), b));
    __m256i lo = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_and_si256(h0, byte), ib),
                                  _mm256_mullo_epi32(_mm256_and_si256(h1, byte), b));
    lo = _mm256_srli_epi32(_mm256_add_epi32(lo, _mm256_set1_epi32(128)), 8);
    return _mm256_add_epi32(hi, lo);
}

/* r (< 2^32) to 0.30 as frag_bilerp_rgba8 converts it: (r 16843009 + 2^25) >> 26,
** for the four fragments of one 128-bit half */
AVX2_INLINE __m256i avx2_bilerp_to_frag(__m128i r)
{
    const __m256i p = _mm256_mul_epu32(_mm256_cvtepu32_epi64(r), _mm256_set1_epi64x(16843009));
    return _mm256_srli_epi64(_mm256_add_epi64(p, _mm256_set1_epi64x((int64_t)1 << 25)), 26);
}

/* four fragments' channels, one register per channel (lane = fragment),
** stored as each fragment's FRAGV[4] at out + k * stride */
AVX2_INLINE void avx2_store_transposed4(__m256i r, __m256i g, __m256i b, __m256i a, FRAGV *out, size_t stride)
{
    const __m256i t0 = _mm256_unpacklo_epi64(r, g), t1 = _mm256_unpackhi_epi64(r, g);
    const __m256i t2 = _mm256_unpacklo_epi64(b, a), t3 = _mm256_unpackhi_epi64(b, a);
    avx2_store4(out, _mm256_permute2x128_si256(t0, t2, 0x20));
    avx2_store4(out + stride, _mm256_permute2x128_si256(t1, t3, 0x20));
    avx2_store4(out + 2 * stride, _mm256_permute2x128_si256(t0, t2, 0x31));
    avx2_store4(out + 3 * stride, _mm256_permute2x128_si256(t1, t3, 0x31));
}


/* the low and high dwords of the s and t of eight fragments' coordinates
** c[0..7] (lane = fragment): four loads, two rounds of shuffles (which
** leave the fragments in the order 0 2 4 6 | 1 3 5 7) and a permutation */
AVX2_INLINE void avx2_load_st8(const TexCoord *c, __m256i *s_lo, __m256i *s_hi, __m256i *t_lo, __m256i *t_hi)
{
    const __m256 q0 = _mm256_loadu_ps((const float *)(const void *)&c[0]);   /* fragments 0 | 1 */
    const __m256 q1 = _mm256_loadu_ps((const float *)(const void *)&c[2]);
    const __m256 q2 = _mm256_loadu_ps((const float *)(const void *)&c[4]);
    const __m256 q3 = _mm256_loadu_ps((const float *)(const void *)&c[6]);
    /* s_lo t_lo of fragments 0 2 | 1 3, and their high dwords */
    const __m256 lo01 = _mm256_shuffle_ps(q0, q1, _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 hi01 = _mm256_shuffle_ps(q0, q1, _MM_SHUFFLE(3, 1, 3, 1));
    const __m256 lo23 = _mm256_shuffle_ps(q2, q3, _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 hi23 = _mm256_shuffle_ps(q2, q3, _MM_SHUFFLE(3, 1, 3, 1));
    const __m256i order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
#define AVX2_PICK(x, y, m) _mm256_permutevar8x32_epi32(_mm256_castps_si256(_mm256_shuffle_ps(x, y, m)), order)
    *s_lo = AVX2_PICK(lo01, lo23, _MM_SHUFFLE(2, 0, 2, 0));
    *t_lo = AVX2_PICK(lo01, lo23, _MM_SHUFFLE(3, 1, 3, 1));
    *s_hi = AVX2_PICK(hi01, hi23, _MM_SHUFFLE(2, 0, 2, 0));
    *t_hi = AVX2_PICK(hi01, hi23, _MM_SHUFFLE(3, 1, 3, 1));
#undef AVX2_PICK
}

/* sample_level's GL_LINEAR index and weight along one axis of a level n =
** 2^L texels wide (u = reduce(s) n - 1/2, i0 = floor(u), the weight the 16
** bits below the point; REPEAT masks i0 and i0 + 1, CLAMP_TO_EDGE clamps
** them to [0, n - 1]) for eight coordinates in 32-bit lanes, from their low
** (lo, the fraction in 0.32) and high (hi, the signed integer part)
** dwords. With L = log2n and g = lo - 2^(31 - L) mod 2^32 (a borrow where
** lo < 2^(31 - L)), s n - 1/2 = (hi - borrow) n + g 2^L / 2^32 exactly, so
** i0 = floor of that is (hi - borrow) n + (g >> (32 - L)), and the weight
** is bits 16..31 of g << L, the 64-bit form's bits. REPEAT keeps i0 mod n
** (the top L bits of g alone); CLAMP_TO_EDGE first clamps s to [-1, 2] as
** reduce_coord does (hi < -1 gives -1.0, hi >= 2 gives 2.0), then the
** indices to [0, n - 1]. half, top, to_index and up are the axis'
** Avx2Axis values. */
AVX2_INLINE void avx2_linear_axis8v(__m256i lo, __m256i hi, __m256i half, __m256i top, __m128i to_index, __m128i up,
                                    int repeat, __m256i *i0, __m256i *i1, __m256i *w)
{
    if (repeat) {
        const __m256i g = _mm256_sub_epi32(lo, half);
        *i0 = _mm256_and_si256(_mm256_srl_epi32(g, to_index), top);
        *i1 = _mm256_and_si256(_mm256_add_epi32(*i0, _mm256_set1_epi32(1)), top);
        *w = _mm256_srli_epi32(_mm256_sll_epi32(g, up), 16);
        return;
    }
    const __m256i below = _mm256_cmpgt_epi32(_mm256_set1_epi32(-1), hi);     /* s < -1 */
    const __m256i above = _mm256_cmpgt_epi32(hi, _mm256_set1_epi32(1));      /* s >= 2 */
    hi = _mm256_blendv_epi8(_mm256_blendv_epi8(hi, _mm256_set1_epi32(-1), below), _mm256_set1_epi32(2), above);
    lo = _mm256_andnot_si256(_mm256_or_si256(below, above), lo);
    const __m256i g = _mm256_sub_epi32(lo, half);
    const __m256i sign = _mm256_set1_epi32(INT32_MIN);
    const __m256i borrow = _mm256_cmpgt_epi32(_mm256_xor_si256(half, sign), _mm256_xor_si256(lo, sign));   /* -1 */
    const __m256i ip = _mm256_add_epi32(_mm256_sll_epi32(_mm256_add_epi32(hi, borrow), up),
                                        _mm256_srl_epi32(g, to_index));
    const __m256i zero = _mm256_setzero_si256();
    *i0 = _mm256_min_epi32(_mm256_max_epi32(ip, zero), top);
    *i1 = _mm256_min_epi32(_mm256_max_epi32(_mm256_add_epi32(ip, _mm256_set1_epi32(1)), zero), top);
    *w = _mm256_srli_epi32(_mm256_sll_epi32(g, up), 16);
}

/* the same with an axis' constants ax (Avx2Axis) */
AVX2_INLINE void avx2_linear_axis8c(__m256i lo, __m256i hi, const Avx2Axis *ax, int repeat, __m256i *i0,
                                    __m256i *i1, __m256i *w)
{
    avx2_linear_axis8v(lo, hi, ax->half, ax->top, ax->to_index, ax->up, repeat, i0, i1, w);
}

/* the same on an axis 2^log2n texels wide */
AVX2_INLINE void avx2_linear_axis8(__m256i lo, __m256i hi, int log2n, int repeat, __m256i *i0, __m256i *i1,
                                   __m256i *w)
{
    avx2_linear_axis8v(lo, hi, _mm256_set1_epi32((int)(0x80000000u >> log2n)), _mm256_set1_epi32((1 << log2n) - 1),
                       _mm_cvtsi32_si128(32 - log2n), _mm_cvtsi32_si128(log2n), repeat, i0, i1, w);
}

/* avx2_linear_texels8's words g[0..3] at the columns xa, xb and rows ya, yb
** of a level 2^log2w x 2^log2h texels */
AVX2_INLINE void avx2_linear_words8(const int *tx32, int log2w, int log2h, __m256i xa, __m256i xb, __m256i ya,
                                    __m256i yb, int rows, __m256i g[4])
{
    if (rows && avx2_row_texels8(tx32, (int64_t)1 << log2w, (int64_t)1 << (log2w + log2h), xa, xb, ya, yb, g))
        return;
    const __m256i r0 = _mm256_slli_epi32(ya, log2w), r1 = _mm256_slli_epi32(yb, log2w);
    if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(xb, _mm256_add_epi32(xa, _mm256_set1_epi32(1)))) == -1) {
        /* no lane wraps or clamps at the right edge: each row's two
        ** texels are one 64-bit word, so gather half the elements */
        avx2_gather_pairs(tx32, _mm256_add_epi32(r0, xa), &g[0], &g[1]);
        avx2_gather_pairs(tx32, _mm256_add_epi32(r1, xa), &g[2], &g[3]);
    } else {
        g[0] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r0, xa), 4);
        g[1] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r0, xb), 4);
        g[2] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r1, xa), 4);
        g[3] = _mm256_i32gather_epi32(tx32, _mm256_add_epi32(r1, xb), 4);
    }
}

/* the four texels and the weights of sample_level's GL_LINEAR for the
** coordinates c[0..7] on a power-of-two level (2^log2w texels wide), REPEAT
** or CLAMP_TO_EDGE on each axis: g[0..3] the texel words at (i0, j0),
** (i1, j0), (i0, j1), (i1, j1), *a and *b the 16-bit weights along s and t;
** with `rows`, by avx2_row_texels8 where it applies (magnified levels: a
** minified one's columns spread too far for it to pay its test) */
AVX2_INLINE void avx2_linear_texels8(const int *tx32, int log2w, int log2h, const TexCoord *c, int repeat_s,
                                     int repeat_t, int rows, __m256i g[4], __m256i *a, __m256i *b)
{
    __m256i s_lo, s_hi, t_lo, t_hi, xa, xb, ya, yb;
    avx2_load_st8(c, &s_lo, &s_hi, &t_lo, &t_hi);
    avx2_linear_axis8(s_lo, s_hi, log2w, repeat_s, &xa, &xb, a);
    avx2_linear_axis8(t_lo, t_hi, log2h, repeat_t, &ya, &yb, b);
    avx2_linear_words8(tx32, log2w, log2h, xa, xb, ya, yb, rows, g);
}

/* the same with the axes' constants ax_s and ax_t (Avx2Axis, a fused
** kernel's per primitive; the trilinear mix forms its own in registers, where
** a struct of them measured more instructions) */
AVX2_INLINE void avx2_linear_texels8c(const int *tx32, int log2w, int log2h, const Avx2Axis *ax_s,
                                      const Avx2Axis *ax_t, const TexCoord *c, int repeat_s, int repeat_t, int rows,
                                      __m256i g[4], __m256i *a, __m256i *b)
{
    __m256i s_lo, s_hi, t_lo, t_hi, xa, xb, ya, yb;
    avx2_load_st8(c, &s_lo, &s_hi, &t_lo, &t_hi);
    avx2_linear_axis8c(s_lo, s_hi, ax_s, repeat_s, &xa, &xb, a);
    avx2_linear_axis8c(t_lo, t_hi, ax_t, repeat_t, &ya, &yb, b);
    avx2_linear_words8(tx32, log2w, log2h, xa, xb, ya, yb, rows, g);
}

/* sample_level's GL_LINEAR of a power-of-two level for fragments 0..n-1
** (n a multiple of 4), REPEAT or CLAMP_TO_EDGE on each axis: eight
** fragments at a time in 32-bit lanes (texels gathered, channels apart),
** a last four padded to such a group (not forced inline, as
** avx2_bilerp_rgba8) */
/* the trilinear mix t1 + frag_mul(f, t2 - t1) of texels in [0, 2^30], per
** lane: t2 - t1 and f fit vpmuldq's operands, and adding 2^60 before the
** shift makes frag_mul's arithmetic shift a logical one (then 2^30 comes
** off) */
AVX2_INLINE __m256i avx2_lod_mix_lanes(__m256i f, __m256i t1, __m256i t2)
{
    const __m256i p = _mm256_add_epi64(_mm256_mul_epi32(_mm256_sub_epi64(t2, t1), f),
                                       _mm256_set1_epi64x(((int64_t)1 << 60) + ((int64_t)1 << 29)));
    return _mm256_add_epi64(t1, _mm256_sub_epi64(_mm256_srli_epi64(p, 30), _mm256_set1_epi64x(FRAG_ONE)));
}

/* avx2_lod_mix_lanes of one fragment's four channels */
static inline void avx2_lod_mix(FRAGV f, const FRAGV t1[4], const FRAGV t2[4], FRAGV out[4])
{
    avx2_store4(out, avx2_lod_mix_lanes(_mm256_set1_epi64x(f), avx2_load4(t1), avx2_load4(t2)));
}

/* the bilerp8 channels ch[0..3] of eight coordinates cj on a level (as
** avx2_sample_linear samples each group) */
AVX2_INLINE void avx2_linear_channels8(const TexImage *li, const TexCoord *cj, int repeat_s, int repeat_t, int rows,
                                       __m256i ch[4])
{
    const int log2w = __builtin_ctz((unsigned)li->width), log2h = __builtin_ctz((unsigned)li->height);
    const __m256i one16 = _mm256_set1_epi32(65536);
    __m256i g[4], a, b;
    avx2_linear_texels8((const int *)(const void *)li->texels, log2w, log2h, cj, repeat_s, repeat_t, rows, g, &a, &b);
    const __m256i ia = _mm256_sub_epi32(one16, a), ib = _mm256_sub_epi32(one16, b);
    for (int k = 0; k < 4; k++)
        ch[k] = avx2_bilerp8_channel(g, 8 * k, a, ia, b, ib);
}

/* c[j..j+7], or (a last four of n) c[j..j+3] padded with copies of the
** last into pad */
AVX2_INLINE const TexCoord *avx2_group8_coords(const TexCoord *c, int j, int n, TexCoord pad[8])
{
    if (j + 8 <= n)
        return &c[j];
    memcpy(pad, &c[j], 4 * sizeof *pad);
    for (int k = 4; k < 8; k++)
        pad[k] = pad[3];
    return pad;
}

static inline void avx2_sample_linear(const TexImage *li, int n, const TexCoord *c, FRAGV *out, size_t stride,
                                    int repeat_s, int repeat_t, int rows)
{
    for (int j = 0; j < n; j += 8) {
        TexCoord pad[8];
        __m256i ch[4];
        avx2_linear_channels8(li, avx2_group8_coords(c, j, n, pad), repeat_s, repeat_t, rows, ch);
        for (int h = 0; h < (j + 8 > n ? 1 : 2); h++) {
            __m256i v[4];
            for (int k = 0; k < 4; k++)
                v[k] = avx2_bilerp_to_frag(h ? _mm256_extracti128_si256(ch[k], 1) : _mm256_castsi256_si128(ch[k]));
            avx2_store_transposed4(v[0], v[1], v[2], v[3], out + (size_t)(j + 4 * h) * stride, stride);
        }
    }
}

/* avx2_sample_linear of two levels l1, l2 at the same coordinates, mixed
** by frac[0..n) as lod_mix mixes them (avx2_lod_mix_lanes, per channel),
** with no store of either level's texels between */
static void avx2_sample_linear_mix(const TexImage *l1, const TexImage *l2, int n, const TexCoord *c,
                                   const FRAGV *frac, FRAGV *out, size_t stride, int repeat_s, int repeat_t)
{
    for (int j = 0; j < n; j += 8) {
        TexCoord pad[8];
        const TexCoord *cj = avx2_group8_coords(c, j, n, pad);
        __m256i ch1[4], ch2[4];
        avx2_linear_channels8(l1, cj, repeat_s, repeat_t, 0, ch1);
        avx2_linear_channels8(l2, cj, repeat_s, repeat_t, 0, ch2);
        for (int h = 0; h < (j + 8 > n ? 1 : 2); h++) {
            const __m256i f = avx2_load4(&frac[j + 4 * h]);
            __m256i v[4];
            for (int k = 0; k < 4; k++) {
                const __m128i q1 = h ? _mm256_extracti128_si256(ch1[k], 1) : _mm256_castsi256_si128(ch1[k]);
                const __m128i q2 = h ? _mm256_extracti128_si256(ch2[k], 1) : _mm256_castsi256_si128(ch2[k]);
                v[k] = avx2_lod_mix_lanes(f, avx2_bilerp_to_frag(q1), avx2_bilerp_to_frag(q2));
            }
            avx2_store_transposed4(v[0], v[1], v[2], v[3], out + (size_t)(j + 4 * h) * stride, stride);
        }
    }
}

/* {====================================================================
** lod_choose (texsample.c) for four fragments at a time: the level-0
** footprint rho, lambda = lod_log2(rho) and §3.7.8's decisions, with the
** result coded as key = level | two * ktwo | (filter LINEAR) * klinear
** (the caller's coding, as kmag, kmin, ktwo) and frac. */

typedef struct Avx2LodParams {
    int log2w, log2h;           /* level 0 is 2^log2w x 2^log2h */
    int mode;                   /* 0: no mipmap, 1: *_MIPMAP_NEAREST, 2: *_MIPMAP_LINEAR */
    int q;                      /* max_level */
    int64_t cshift;             /* §3.7.8's c in 0.30 */
    int32_t kmag, kmin, ktwo;   /* keys of lambda <= c, of lambda > c (level 0), and of `two` */
} Avx2LodParams;

/* the larger of two lanes (vpmaxsq is AVX-512) */
AVX2_INLINE __m256i avx2_max64(__m256i a, __m256i b) { return _mm256_blendv_epi8(a, b, _mm256_cmpgt_epi64(b, a)); }

/* lod_log2 of rho lanes in [0, 2^63): fx_log2 of r = rho >> 16 clamped
** to int32 (fxv_log2), r = 0 taken as 1 for the tables and replaced */
AVX2_INLINE __m256i avx2_lod_log2(__m256i rho)
{
    const __m256i zero = _mm256_setzero_si256(), imax = _mm256_set1_epi64x(INT32_MAX);
    __m256i r = _mm256_srli_epi64(rho, 16);
    r = _mm256_blendv_epi8(r, imax, _mm256_cmpgt_epi64(r, imax));
    const __m256i r0 = _mm256_cmpeq_epi64(r, zero);
    const __m256i l = _mm256_blendv_epi8(fxv_log2(_mm256_sub_epi64(r, r0)), _mm256_set1_epi64x(-((int64_t)17 << 30)),
                                         r0);
    return _mm256_blendv_epi8(l, _mm256_set1_epi64x(-((int64_t)1 << 40)), _mm256_cmpeq_epi64(rho, zero));
}

/* lod_choose of fragments 0..3 in three steps: rho (avx2_lod_rho4),
** lambda (avx2_lod_log2) and the decisions (avx2_lod_decide4), which give
** key[k] and frac[k] (0 where not two). The six coordinates are clamped to +-2^50 as texc_clamp does (skipped
** when all lie in [-2^50, 2^50), where it changes nothing); s and t stay
** interleaved, each difference (|.| <= 2^51) shifted by its axis's log2
** size (texc_scale by a power of two, <= 2^62), and max(|a| w, |b| w) =
** w max(|a|, |b|), so rho is the scalar maximum. Lambda is lod_log2's
** (above); the decisions are lod_choose's in lanes: lambda > c; for
** *_MIPMAP_NEAREST (where lambda > c >= 0) d = ceil(lambda + 1/2) - 1 =
** ((lambda + 2^29 + 2^30 - 1) >> 30) - 1, which is the scalar 0 for
** lambda <= 1/2 too, then min(d, q); for *_MIPMAP_LINEAR floor(lambda)
** and frac(lambda) as the shift and mask of a positive lambda. */
AVX2_INLINE __m256i avx2_lod_rho4(const Avx2LodParams *p, const TexCoord *c, const TexCoord *dx,
                                   const TexCoord *dy)
{
    __m256i v[6] = { _mm256_loadu_si256((const __m256i *)(const void *)&c[0]),
                     _mm256_loadu_si256((const __m256i *)(const void *)&c[2]),
                     _mm256_loadu_si256((const __m256i *)(const void *)&dx[0]),
                     _mm256_loadu_si256((const __m256i *)(const void *)&dx[2]),
                     _mm256_loadu_si256((const __m256i *)(const void *)&dy[0]),
                     _mm256_loadu_si256((const __m256i *)(const void *)&dy[2]) };
    const __m256i lim = _mm256_set1_epi64x((int64_t)1 << 50);
    __m256i far = _mm256_setzero_si256();
    for (int k = 0; k < 6; k++)
        far = _mm256_or_si256(far, _mm256_add_epi64(v[k], lim));
    if (!_mm256_testz_si256(far, _mm256_set1_epi64x(~(((int64_t)1 << 51) - 1)))) {
        const __m256i nlim = _mm256_sub_epi64(_mm256_setzero_si256(), lim);
        for (int k = 0; k < 6; k++)
            v[k] = avx2_max64(_mm256_blendv_epi8(v[k], lim, _mm256_cmpgt_epi64(v[k], lim)), nlim);
    }
    const __m256i sh = _mm256_setr_epi64x(p->log2w, p->log2h, p->log2w, p->log2h);
    const __m256i m01 = _mm256_sllv_epi64(avx2_max64(avx2_abs64(_mm256_sub_epi64(v[2], v[0])),
                                                     avx2_abs64(_mm256_sub_epi64(v[4], v[0]))), sh);
    const __m256i m23 = _mm256_sllv_epi64(avx2_max64(avx2_abs64(_mm256_sub_epi64(v[3], v[1])),
                                                     avx2_abs64(_mm256_sub_epi64(v[5], v[1]))), sh);
    /* (s0 s2 s1 s3) and (t0 t2 t1 t3), back to fragment order */
    return _mm256_permute4x64_epi64(
        avx2_max64(_mm256_unpacklo_epi64(m01, m23), _mm256_unpackhi_epi64(m01, m23)), 0xD8);
}

AVX2_INLINE void avx2_lod_decide4(const Avx2LodParams *p, __m256i l, int32_t key[4], FRAGV frac[4])
{
    const __m256i above = _mm256_cmpgt_epi64(l, _mm256_set1_epi64x(p->cshift));
    const __m256i lp = _mm256_and_si256(l, above);          /* lambda > 0 where above, else 0 */
    const __m256i q = _mm256_set1_epi64x(p->q);
    __m256i k = _mm256_set1_epi64x(p->kmin), f = _mm256_setzero_si256();
    if (p->mode == 1) {
        __m256i d = _mm256_sub_epi64(
            _mm256_srli_epi64(_mm256_add_epi64(lp, _mm256_set1_epi64x(((int64_t)1 << 29) + ((int64_t)1 << 30) - 1)), 30),
            _mm256_set1_epi64x(1));
        d = _mm256_blendv_epi8(d, q, _mm256_cmpgt_epi64(d, q));
        k = _mm256_or_si256(k, d);
    } else if (p->mode == 2) {
        const __m256i d = _mm256_srli_epi64(lp, 30);
        const __m256i two = _mm256_cmpgt_epi64(q, d);        /* floor(lambda) < q */
        k = _mm256_or_si256(k, _mm256_blendv_epi8(q, d, two));
        k = _mm256_or_si256(k, _mm256_and_si256(two, _mm256_set1_epi64x(p->ktwo)));
        f = _mm256_and_si256(_mm256_and_si256(lp, _mm256_set1_epi64x(((int64_t)1 << 30) - 1)), two);
    }
    k = _mm256_blendv_epi8(_mm256_set1_epi64x(p->kmag), k, above);
    _mm_storeu_si128((__m128i *)(void *)key,
                     _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(k, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6))));
    _mm256_storeu_si256((__m256i *)(void *)frac, f);
}

/* lod_choose of fragments 0..3 (above) */
AVX2_INLINE void avx2_lod_choose4(const Avx2LodParams *p, const TexCoord *c, const TexCoord *dx,
                                  const TexCoord *dy, int32_t key[4], FRAGV frac[4])
{
    avx2_lod_decide4(p, avx2_lod_log2(avx2_lod_rho4(p, c, dx, dy)), key, frac);
}

/* the same for fragments 0..7, both fours' table gathers (avx2_lod_log2's)
** issued together: the second does not wait behind the first's arithmetic
** (trilinear_fog's fixed build about 5% faster) */
AVX2_INLINE void avx2_lod_choose8(const Avx2LodParams *p, const TexCoord *c, const TexCoord *dx,
                                  const TexCoord *dy, int32_t key[8], FRAGV frac[8])
{
    const __m256i r0 = avx2_lod_rho4(p, c, dx, dy), r1 = avx2_lod_rho4(p, c + 4, dx + 4, dy + 4);
    const __m256i l0 = avx2_lod_log2(r0), l1 = avx2_lod_log2(r1);
    avx2_lod_decide4(p, l0, key, frac);
    avx2_lod_decide4(p, l1, key + 4, frac + 4);
}

/* }==================================================================== */

/* four fragments' weights l[0..2] (lanes whose low 32 bits are the WGT
** values) stored as out[lane][0..2] */
AVX2_INLINE void avx2_store_wgt4(const __m256i l[3], WGT (*out)[3])
{
    /* a0 b0 a1 b1 | a2 b2 a3 b3 (the lanes' high dwords are not read) */
    const __m256i ab = _mm256_blend_epi32(l[0], _mm256_slli_epi64(l[1], 32), 0xAA);
    /* c2 . c0 c3 . c1 . .: c0 and c1 where the first eight take them, c2
    ** and c3 where the last four do */
    const __m256i c = _mm256_permutevar8x32_epi32(l[2], _mm256_setr_epi32(4, 0, 0, 6, 0, 2, 0, 0));
    const __m256i first = _mm256_blend_epi32(_mm256_permutevar8x32_epi32(ab, _mm256_setr_epi32(0, 1, 0, 2, 3, 0, 4, 5)),
                                             c, 0x24);
    const __m128i last = _mm_blend_epi32(_mm256_castsi256_si128(_mm256_permutevar8x32_epi32(ab, _mm256_setr_epi32(0, 6, 7, 0, 0, 0, 0, 0))),
                                         _mm256_castsi256_si128(c), 0x9);
    int32_t *o = &out[0][0];
    _mm256_storeu_si256((__m256i *)(void *)o, first);
    _mm_storeu_si128((__m128i *)(void *)(o + 8), last);
}

/* wgt_persp of four fragments of a triangle that is not affine, edge values
** as lanes e[i]; 0 (nothing written) where a lane leaves the kernel's
** ranges, for the scalar code. Ranges: e_i >= 0 and e_i >> eshift < 2^31 (a
** covered fragment's), mant_i < 2^30, so each n_i = (e_i mant_i) >> qshift_i is a
** 32x32 unsigned product (vpmuludq) and their sum den < 3 2^61 fits int64.
** The normalising shift is the bit length of den >> 32 (below 2^31, so its
** double is exact and its exponent gives the length). Lanes need
** 2^31 <= den < 2^32 after it (true wherever the unshifted sum reaches
** 2^31): then recip = (2^62 + den / 2) / den <= 2^31 + 1, the double
** quotient (numerator rounded once, one division) is within 1 of it, and the
** exact remainder 2^62 + den / 2 - q den (q den < 2^64 from vpmuludq; the
** true value is near 2^62) corrects it. n_i <= den, so n_i recip <= 2^62
** + den and p_i = (n_i recip + 2^31) >> 32 is one vpmuludq and a shift. */
AVX2_INLINE int avx2_persp4_den(const WgtSetup *s, const __m256i e[3], __m256i l[3], __m256i *den_out)
{
    const __m128i esh = _mm_cvtsi32_si128(s->eshift);
    __m256i n[3], any = _mm256_setzero_si256();
    for (int i = 0; i < 3; i++) {
        const __m256i ei = _mm256_srl_epi64(e[i], esh);
        any = _mm256_or_si256(any, ei);
        /* qshift >= 64 shifts everything out, as the scalar code's 0 for >= 63
        ** does (a product below 2^61 shifted by 63 is 0 too) */
        n[i] = _mm256_srl_epi64(_mm256_mul_epu32(ei, _mm256_set1_epi64x(s->mant[i])),
                                _mm_cvtsi32_si128(s->qshift[i] < 64 ? s->qshift[i] : 64));
    }
    /* e >> eshift >= 2^31, or e < 0: eshift <= 32 (wgt_setup), so the
    ** logical shift of a negative e keeps a bit at 31 or above */
    if (!_mm256_testz_si256(any, _mm256_set1_epi64x(~(int64_t)0x7FFFFFFF)))
        return 0;
    __m256i den = _mm256_add_epi64(_mm256_add_epi64(n[0], n[1]), n[2]);
    /* sh = max(bit length of den - 32, 0) */
    const __m256i hi_bits = _mm256_srli_epi64(_mm256_castpd_si256(avx2_i64_to_pd(_mm256_srli_epi64(den, 32))), 52);
    /* (a negative difference, small, is a lane of two negative dwords: the
    ** 32-bit max takes both to 0) */
    const __m256i sh = _mm256_max_epi32(_mm256_sub_epi64(hi_bits, _mm256_set1_epi64x(1022)), _mm256_setzero_si256());
    den = _mm256_srlv_epi64(den, sh);
    const __m256i n1 = _mm256_srlv_epi64(n[1], sh), n2 = _mm256_srlv_epi64(n[2], sh);
    if (_mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x((int64_t)1 << 31), den))))
        return 0;
    const __m256i half = _mm256_srli_epi64(den, 1);
    const __m256d qd = _mm256_div_pd(_mm256_add_pd(_mm256_set1_pd(4611686018427387904.0), avx2_i64_to_pd(half)),
                                     avx2_i64_to_pd(den));
    /* qd lies in (2^30, 2^31 + 1], so its truncation is below 2^31 but
    ** where it is 2^31 (den = 2^31), which vcvttpd2dq gives as 0x80000000:
    ** zero-extended, 2^31 too */
    __m256i q = _mm256_cvtepu32_epi64(_mm256_cvttpd_epi32(qd));
    const __m256i r = _mm256_sub_epi64(_mm256_add_epi64(_mm256_set1_epi64x((int64_t)1 << 62), half),
                                       _mm256_mul_epu32(q, den));
    /* r < 0: one too many; r >= den: one too few */
    q = _mm256_add_epi64(q, avx2_negative(r));
    q = _mm256_sub_epi64(q, _mm256_cmpgt_epi64(r, _mm256_sub_epi64(den, _mm256_set1_epi64x(1))));
    const __m256i round = _mm256_set1_epi64x((int64_t)1 << 31);
    l[1] = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(n1, q), round), 32);
    l[2] = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(n2, q), round), 32);
    l[0] = _mm256_sub_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(WGT_ONE), l[1]), l[2]);
    if (den_out)
        /* WgtDen's half in the low 32 bits, sh in the high ones */
        *den_out = _mm256_or_si256(_mm256_srli_epi64(q, 1), _mm256_slli_epi64(sh, 32));
    return 1;
}

AVX2_INLINE int avx2_persp4(const WgtSetup *s, const __m256i e[3], __m256i l[3])
{
    return avx2_persp4_den(s, e, l, NULL);
}

/* a triangle's WgtTangent pair as the lanes avx2_tangents4 reads (set up
** outside its loop: broadcasts the loop would otherwise form again) */
typedef struct Avx2Tangents {
    __m256i ashift, asum[2], a[2][2];    /* a[d][i - 1] = a_i + 2^32 of step d */
} Avx2Tangents;

AVX2_INLINE void avx2_tangents_setup(const WgtTangent g[2], Avx2Tangents *c)
{
    c->ashift = _mm256_set1_epi64x(g[0].ashift);
    for (int d = 0; d < 2; d++) {
        c->asum[d] = _mm256_set1_epi64x(g[d].asum);
        for (int i = 1; i < 3; i++)
            c->a[d][i - 1] = _mm256_set1_epi64x((int64_t)g[d].a[i] + ((int64_t)1 << 32));
    }
}

/* wgt_tangent along both steps (g: their Avx2Tangents) of four fragments
** of a triangle that is not affine: their weights l[1], l[2] (lanes in
** [0, 2^30 + 1]) and
** WgtDen lanes (half in the low 32 bits, sh >= 0 in the high ones,
** avx2_persp4_den's), the tangent weights as lanes out[k][i] whose low 32
** bits are the WGT values; 0 (nothing written) where a lane has sh <
** ashift - 30, for the scalar code. Then |n_i| < 2^31 (|a_i| < 2^29, |p_i
** asum| < 3 2^59), so floor(n_i 2^-k) for k >= 0 is vpsravd's of the low
** dword, and with kn = max(-k, 0) both of wgt_tangent's quotients are
** floor((m half + 2^(30 - kn)) / 2^(31 - kn)): |m half| < 2^61 (vpmuldq),
** and the floor is a logical shift of it plus 2^62, less 2^(62 - 31 + kn).
** Here its sums before the clamps: o[d][i - 1] = p_i + dp_i of step d (i =
** 1, 2), and in *steps each lane's dp_i + 2^28 or-ed together (bits 29 and
** up clear where every dp_i lies in [-2^28, 2^28)). */
AVX2_INLINE int avx2_tangent_sums4(const Avx2Tangents *g, const __m256i l[3], __m256i den, __m256i o[2][2],
                                   __m256i *steps)
{
    const __m256i one = _mm256_set1_epi64x(1);
    const __m256i k = _mm256_sub_epi64(_mm256_srli_epi64(den, 32), g->ashift);
    if (_mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(-30), k))))
        return 0;
    const __m256i neg = avx2_negative(k), kp = _mm256_andnot_si256(neg, k);
    const __m256i s = _mm256_add_epi64(_mm256_set1_epi64x(31), _mm256_and_si256(neg, k));      /* 31 - kn */
    const __m256i bias = _mm256_add_epi64(_mm256_set1_epi64x((int64_t)1 << 62), _mm256_sllv_epi64(one, _mm256_sub_epi64(s, one)));
    const __m256i unbias = _mm256_sllv_epi64(one, _mm256_sub_epi64(_mm256_set1_epi64x(62), s));
    const __m256i bias29 = _mm256_set1_epi64x(((int64_t)1 << 62) + ((int64_t)1 << 29));
    /* x + window = dp + 2^28 for the shifted quotient x = dp + unbias */
    const __m256i window = _mm256_sub_epi64(_mm256_set1_epi64x((int64_t)1 << 28), unbias);
    *steps = _mm256_setzero_si256();
    for (int d = 0; d < 2; d++)
        for (int i = 1; i < 3; i++) {
            /* n = (a_i + 2^32) - ((p_i asum + 2^62 + 2^29) >> 30) */
            const __m256i n = _mm256_sub_epi64(g->a[d][i - 1],
                                               _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epi32(l[i], g->asum[d]), bias29), 30));
            const __m256i m = _mm256_srav_epi32(n, kp);
            /* p_i + dp_i = (p_i - 2^(31 + kn)) + ((m half + 2^62 + 2^(30 - kn)) >> (31 - kn)) */
            const __m256i x = _mm256_srlv_epi64(_mm256_add_epi64(_mm256_mul_epi32(m, den), bias), s);
            *steps = _mm256_or_si256(*steps, _mm256_add_epi64(x, window));
            o[d][i - 1] = _mm256_add_epi64(_mm256_sub_epi64(l[i], unbias), x);
        }
    return 1;
}

/* the same sums clamped to +-(2^31 - 1), and o_0 = 2^30 - o_1 - o_2 clamped */
AVX2_INLINE int avx2_tangents4(const Avx2Tangents *g, const __m256i l[3], __m256i den, __m256i out[2][3])
{
    __m256i o[2][2], steps;
    if (!avx2_tangent_sums4(g, l, den, o, &steps))
        return 0;
    const __m256i lim = _mm256_set1_epi64x(((int64_t)1 << 31) - 1), nlim = _mm256_set1_epi64x(-(((int64_t)1 << 31) - 1));
    for (int d = 0; d < 2; d++) {
        for (int i = 1; i < 3; i++) {
            const __m256i v = _mm256_blendv_epi8(o[d][i - 1], lim, _mm256_cmpgt_epi64(o[d][i - 1], lim));
            out[d][i] = _mm256_blendv_epi8(v, nlim, _mm256_cmpgt_epi64(nlim, v));
        }
        __m256i o0 = _mm256_sub_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(WGT_ONE), out[d][1]), out[d][2]);
        o0 = _mm256_blendv_epi8(o0, lim, _mm256_cmpgt_epi64(o0, lim));
        out[d][0] = _mm256_blendv_epi8(o0, nlim, _mm256_cmpgt_epi64(nlim, o0));
    }
    return 1;
}

/* a unit's vertex coordinates for avx2_lod_coords4: s0 2^30 and the
** differences s1 - s0, s2 - s0 (the same of t) in every lane; ok 0 where a
** difference leaves the int32 range (what vpmuldq reads) */
typedef struct Avx2CoordDeltas {
    __m256i base[2], d[2][2];     /* [0]: s, [1]: t */
    int ok;
} Avx2CoordDeltas;

AVX2_INLINE void avx2_coord_deltas_setup(const NUM sv[3], const NUM tv[3], Avx2CoordDeltas *c)
{
    c->ok = 1;
    for (int a = 0; a < 2; a++) {
        const NUM *v = a ? tv : sv;
        c->base[a] = _mm256_set1_epi64x((int64_t)((uint64_t)(int64_t)v[0] << 30));
        for (int i = 1; i < 3; i++) {
            const int64_t d = (int64_t)v[i] - v[0];
            c->ok &= d >= INT32_MIN && d <= INT32_MAX;
            c->d[a][i - 1] = _mm256_set1_epi64x(d);
        }
    }
}

/* base + d1 w1 + d2 w2 rounded as avx2_texc_lerp3x4 rounds */
AVX2_INLINE __m256i avx2_texc_delta_lerp(__m256i base, const __m256i d[2], __m256i w1, __m256i w2)
{
    return avx2_round_shift(_mm256_add_epi64(_mm256_add_epi64(base, _mm256_mul_epi32(d[0], w1)),
                                             _mm256_mul_epi32(d[1], w2)), 14);
}

/* the coordinates of a unit (c: its Avx2CoordDeltas) at the weights l and
** at the tangent weights along ea and along eb, as tc[0..3], tx[0..3] and
** ty[0..3], where no clamp of avx2_tangents4 acts: each tangent's step
** dp_i = o_i - p_i (i = 1, 2) in [-2^28, 2^28), so that with p_i in [0,
** 2^30 + 1] and p_0 = 2^30 - p_1 - p_2 every o_i, and o_0 = 2^30 - o_1 -
** o_2, lies well within +-(2^31 - 1). Then s0 o0 + s1 o1 + s2 o2 = s0 2^30
** + (s1 - s0) o1 + (s2 - s0) o2 as integers (mod 2^64, where the three
** products' sum wraps): one product fewer per coordinate and no clamps,
** the same bits. 0 (nothing written) elsewhere, for avx2_tangents4. */
AVX2_INLINE int avx2_lod_coords4(const Avx2Tangents *g, const Avx2CoordDeltas *c, const __m256i l[3], __m256i den,
                                 TexCoord *tc, TexCoord *tx, TexCoord *ty)
{
    __m256i o[2][2], steps;
    if (!avx2_tangent_sums4(g, l, den, o, &steps)
        || !_mm256_testz_si256(steps, _mm256_set1_epi64x(~(((int64_t)1 << 29) - 1))))
        return 0;
    avx2_store_st4(avx2_texc_delta_lerp(c->base[0], c->d[0], l[1], l[2]),
                   avx2_texc_delta_lerp(c->base[1], c->d[1], l[1], l[2]), tc);
    for (int d = 0; d < 2; d++)
        avx2_store_st4(avx2_texc_delta_lerp(c->base[0], c->d[0], o[d][0], o[d][1]),
                       avx2_texc_delta_lerp(c->base[1], c->d[1], o[d][0], o[d][1]), d ? ty : tx);
    return 1;
}

/* wgt_linear of four fragments, edge values e[lane][1], e[lane][2] as lanes
** r1, r2: the weights l0..l2 as 64-bit lanes whose low 32 bits are the
** scalar code's (WGT) casts (what vpmuldq reads); 0 when an operand leaves
** the kernel's range (edge values e_i >> eshift outside [0, 2^31)) */
AVX2_INLINE int avx2_linear4v(const WgtSetup *s, __m256i r1, __m256i r2, __m256i l[3])
{
    if (s->lin_recip < 0)
        return 0;
    const __m128i sh = _mm_cvtsi32_si128(s->eshift);
    const __m256i e1 = _mm256_srl_epi64(r1, sh), e2 = _mm256_srl_epi64(r2, sh);
    if (!_mm256_testz_si256(_mm256_or_si256(r1, r2), _mm256_set1_epi64x(INT64_MIN))
        || !_mm256_testz_si256(_mm256_or_si256(e1, e2), _mm256_set1_epi64x(~(int64_t)0x7FFFFFFF)))
        return 0;
    /* e lin_recip as e lo + (e hi << 32): the scalar product, which fits int64 */
    const __m256i lo = _mm256_set1_epi64x(s->lin_recip & 0xFFFFFFFF), hi = _mm256_set1_epi64x(s->lin_recip >> 32);
    const __m256i round = _mm256_set1_epi64x((int64_t)1 << 30);
    const __m256i p1 = _mm256_add_epi64(_mm256_mul_epu32(e1, lo), _mm256_slli_epi64(_mm256_mul_epu32(e1, hi), 32));
    const __m256i p2 = _mm256_add_epi64(_mm256_mul_epu32(e2, lo), _mm256_slli_epi64(_mm256_mul_epu32(e2, hi), 32));
    l[1] = _mm256_srli_epi64(_mm256_add_epi64(p1, round), 31);
    l[2] = _mm256_srli_epi64(_mm256_add_epi64(p2, round), 31);
    l[0] = _mm256_sub_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(WGT_ONE), l[1]), l[2]);
    return 1;
}

/* avx2_linear4v of four fragments' edge values e[lane] */
AVX2_INLINE int avx2_linear4(const WgtSetup *s, const int64_t e[4][3], __m256i l[3])
{
    return avx2_linear4v(s, _mm256_setr_epi64x(e[0][1], e[1][1], e[2][1], e[3][1]),
                         _mm256_setr_epi64x(e[0][2], e[1][2], e[2][2], e[3][2]), l);
}

/* avx2_linear4 of edge lanes r1, r2 (of e[lane][1], e[lane][2]) that the
** caller has checked: each >= 0 and below 2^(31 + eshift); hi is
** lin_recip >> 32, whose product is left out when it is 0 */
AVX2_INLINE void avx2_linear4_checked(const WgtSetup *s, __m256i r1, __m256i r2, int hi, __m256i l[3])
{
    const __m128i sh = _mm_cvtsi32_si128(s->eshift);
    const __m256i e1 = _mm256_srl_epi64(r1, sh), e2 = _mm256_srl_epi64(r2, sh);
    const __m256i lo = _mm256_set1_epi64x(s->lin_recip & 0xFFFFFFFF), round = _mm256_set1_epi64x((int64_t)1 << 30);
    __m256i p1 = _mm256_mul_epu32(e1, lo), p2 = _mm256_mul_epu32(e2, lo);
    if (hi) {
        const __m256i hv = _mm256_set1_epi64x(s->lin_recip >> 32);
        p1 = _mm256_add_epi64(p1, _mm256_slli_epi64(_mm256_mul_epu32(e1, hv), 32));
        p2 = _mm256_add_epi64(p2, _mm256_slli_epi64(_mm256_mul_epu32(e2, hv), 32));
    }
    l[1] = _mm256_srli_epi64(_mm256_add_epi64(p1, round), 31);
    l[2] = _mm256_srli_epi64(_mm256_add_epi64(p2, round), 31);
    l[0] = _mm256_sub_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(WGT_ONE), l[1]), l[2]);
}

/* 1 when an edge value is in avx2_linear4's range: >= 0, and below 2^31
** after the shift by eshift */
static inline int avx2_edge_fits(int64_t e, int eshift) { return e >= 0 && (e >> eshift) < ((int64_t)1 << 31); }

/* avx2_depth4 of l into out[0..3], the sum's terms z[i] >> 12 as lanes zs[i]
** and the clamp's top as uint32 lanes top: (acc + 2^33) >> 34 is the high
** dword of the sum (|acc| < 2^63) shifted right by 2 more, arithmetically,
** and both it and the clamps fit int32 lanes */
AVX2_INLINE void avx2_depth4_pre(const __m256i l[3], const __m256i zs[3], __m128i top, uint32_t out[4])
{
    __m256i acc = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(zs[0], l[0]), _mm256_mul_epi32(zs[1], l[1])),
                                   _mm256_mul_epi32(zs[2], l[2]));
    acc = _mm256_add_epi64(acc, _mm256_set1_epi64x((int64_t)1 << 33));
    const __m128i hi = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(acc, _mm256_setr_epi32(1, 3, 5, 7, 0, 2, 4, 6)));
    const __m128i v = _mm_min_epi32(_mm_max_epi32(_mm_srai_epi32(hi, 2), _mm_setzero_si128()), top);
    _mm_storeu_si128((__m128i *)(void *)out, v);
}

/* the low 32 bits of each lane, as int32 lanes 0..3 */
AVX2_INLINE __m128i avx2_low32(__m256i v)
{
    return _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7)));
}

/* wgt_depth3 of the four fragments' linear weights l */
AVX2_INLINE void avx2_depth4(const __m256i l[3], const DEPTHV z[3], uint32_t maxval, uint32_t out[4])
{
    __m256i acc = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(_mm256_set1_epi64x(z[0] >> 12), l[0]),
                                                    _mm256_mul_epi32(_mm256_set1_epi64x(z[1] >> 12), l[1])),
                                   _mm256_mul_epi32(_mm256_set1_epi64x(z[2] >> 12), l[2]));
    acc = _mm256_add_epi64(acc, _mm256_set1_epi64x((int64_t)1 << 33));
    acc = _mm256_andnot_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), acc), acc);   /* v < 0 clamps to 0 */
    __m256i v = _mm256_srli_epi64(acc, 34);
    const __m256i top = _mm256_set1_epi64x(maxval);
    v = _mm256_blendv_epi8(v, top, _mm256_cmpgt_epi64(v, top));
    _mm_storeu_si128((__m128i *)(void *)out, avx2_low32(v));
}

/* {====================================================================
** V4: a fragment's four channels, the interface span_stages.h uses in
** every build. v4_mul01 and v4_lerp3 take operands for which v4_fits and
** v4_lerp_fits hold; the stages check and leave other fragments to the
** scalar code. */
typedef __m256i V4;
AVX2_INLINE V4 v4_load(const FRAGV *c) { return avx2_load4(c); }
AVX2_INLINE void v4_store(FRAGV *c, V4 v) { avx2_store4(c, v); }
AVX2_INLINE V4 v4_clamp01(V4 v) { return avx2_clamp01(v); }
AVX2_INLINE int v4_fits(V4 v) { return avx2_fits_u31(v); }
AVX2_INLINE V4 v4_mul01(V4 a, V4 b) { return avx2_mul_u(a, b); }
AVX2_INLINE V4 v4_add(V4 a, V4 b) { return _mm256_add_epi64(a, b); }
AVX2_INLINE V4 v4_one_minus(V4 a) { return _mm256_sub_epi64(_mm256_set1_epi64x(FRAG_ONE), a); }
AVX2_INLINE V4 v4_alpha(V4 a) { return _mm256_permute4x64_epi64(a, 0xFF); }
AVX2_INLINE V4 v4_set1(FRAGV f) { return _mm256_set1_epi64x(f); }
AVX2_INLINE V4 v4_rgb0(const FRAGV c[3]) { return _mm256_setr_epi64x(c[0], c[1], c[2], 0); }
/* lanes 0-2 of m, lane 3 of c */
AVX2_INLINE V4 v4_keep_alpha(V4 m, V4 c) { return _mm256_blend_epi32(m, c, 0xC0); }
AVX2_INLINE V4 v4_unorm8(uint32_t word) { return avx2_unorm8(word); }
/* frag_to_unorm(v, 255, 1/2) of each channel, packed as RGBA8888 */
AVX2_INLINE uint32_t v4_pack_unorm8(V4 v) { return avx2_pack_unorm8(avx2_clamp01(v)); }
AVX2_INLINE int v4_lerp_fits(V4 a) { return avx2_fits_i32(a); }
/* pack565 of lanes 0-2 (lane 3 is ignored): fragment_channel with 5, 6, 5
** bits, dithered by threshold t, or keeping the high bits */
AVX2_INLINE uint32_t v4_pack565(V4 v, int dither, FRAGV t)
{
    const __m256i top = _mm256_setr_epi64x(31, 63, 31, 0);
    v = _mm256_andnot_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), v), v);
    __m256i r;
    if (dither) {
        const __m256i one = _mm256_set1_epi64x(FRAG_ONE);
        v = _mm256_blendv_epi8(v, one, _mm256_cmpgt_epi64(v, one));
        r = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(v, top), _mm256_set1_epi64x(t)), 30);
    } else {
        r = _mm256_srlv_epi64(v, _mm256_setr_epi64x(25, 24, 25, 63));
        r = _mm256_blendv_epi8(r, top, _mm256_cmpgt_epi64(r, top));
    }
    r = _mm256_sllv_epi64(r, _mm256_setr_epi64x(11, 5, 0, 0));
    __m128i x = _mm_or_si128(_mm256_castsi256_si128(r), _mm256_extracti128_si256(r, 1));
    x = _mm_or_si128(x, _mm_unpackhi_epi64(x, x));
    return (uint32_t)_mm_cvtsi128_si32(x);
}
AVX2_INLINE V4 v4_lerp3f(V4 a0, V4 a1, V4 a2, const WGT *p) { return avx2_lerp3f(a0, a1, a2, p); }
/* frag_clamp01(frag_lerp3f(...)): clamped, the rounding needs no sign (a
** negative sum rounds to at most 0 and clamps to 0, as max(sum, 0)
** rounded does) */
AVX2_INLINE V4 v4_lerp3f_clamp01(V4 a0, V4 a1, V4 a2, const WGT *p)
{
    const __m128i w = _mm_insert_epi32(_mm_loadl_epi64((const __m128i *)(const void *)p), p[2], 2);
    const __m256i ww = _mm256_broadcastsi128_si256(w), one = _mm256_set1_epi64x(FRAG_ONE);
    const __m256i acc = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(a0, _mm256_shuffle_epi32(ww, 0x00)),
                                                          _mm256_mul_epi32(a1, _mm256_shuffle_epi32(ww, 0x55))),
                                         _mm256_mul_epi32(a2, _mm256_shuffle_epi32(ww, 0xAA)));
    const __m256i pos = _mm256_andnot_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), acc), acc);
    const __m256i r = _mm256_srli_epi64(_mm256_add_epi64(pos, _mm256_set1_epi64x((int64_t)1 << 29)), 30);
    return _mm256_blendv_epi8(r, one, _mm256_cmpgt_epi64(r, one));
}
/* v4_lerp3f_clamp01's sum regrouped for weights with p0 = 1 - p1 - p2 (as
** wgt_persp and wgt_linear form p0): a0 2^30 + d1 p1 + d2 p2, d_i = a_i -
** a0 in lanes that fit int32, from base = a0 2^30 + 2^29 (the rounding
** added). The result, max(sum, 0) >> 30, is frag_lerp3f's where that is
** positive and 0 where it is not, which every consumer's clamp takes alike. */
AVX2_INLINE V4 v4_lerp_base(V4 a0)
{
    return _mm256_add_epi64(_mm256_slli_epi64(a0, 30), _mm256_set1_epi64x((int64_t)1 << 29));
}
AVX2_INLINE V4 v4_lerp_deltas(V4 base, V4 d1, V4 d2, WGT p1, WGT p2)
{
    const __m256i acc = _mm256_add_epi64(_mm256_add_epi64(base, _mm256_mul_epi32(d1, _mm256_set1_epi64x(p1))),
                                         _mm256_mul_epi32(d2, _mm256_set1_epi64x(p2)));
    return _mm256_srli_epi64(_mm256_andnot_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), acc), acc), 30);
}
/* the same for weights just computed, in registers: a vector load of
** three scalar stores would wait for them (no store forwarding) */
AVX2_INLINE V4 v4_lerp3f_w(V4 a0, V4 a1, V4 a2, WGT w0, WGT w1, WGT w2)
{
    return avx2_lerp3w(a0, a1, a2, _mm_setr_epi32(w0, w1, w2, 0), 30);
}
/* }==================================================================== */
#endif

#if SIMD_X86 && !NUM_IS_FIXED

/* V4 (see the fixed build's above) for NUM = float (SSE) or double (AVX):
** the same IEEE operations, lane by lane, in the scalar code's order */
#if defined(GLES_NUM_FLOAT)
typedef __m128 V4;
#define V4_OP(op) _mm_##op##_ps
AVX2_INLINE V4 v4_from_i32(__m128i v) { return _mm_cvtepi32_ps(v); }
AVX2_INLINE __m128i v4_trunc_i32(V4 v) { return _mm_cvttps_epi32(v); }
AVX2_INLINE V4 v4_keep_alpha(V4 m, V4 c) { return _mm_blend_ps(m, c, 8); }
AVX2_INLINE V4 v4_alpha(V4 a) { return _mm_shuffle_ps(a, a, 0xFF); }
#else
typedef __m256d V4;
#define V4_OP(op) _mm256_##op##_pd
AVX2_INLINE V4 v4_from_i32(__m128i v) { return _mm256_cvtepi32_pd(v); }
AVX2_INLINE __m128i v4_trunc_i32(V4 v) { return _mm256_cvttpd_epi32(v); }
AVX2_INLINE V4 v4_keep_alpha(V4 m, V4 c) { return _mm256_blend_pd(m, c, 8); }
AVX2_INLINE V4 v4_alpha(V4 a) { return _mm256_permute4x64_pd(a, 0xFF); }
#endif

/* wgt_persp (wgt_linear where affine) of four fragments whose edge values,
** lanes e[i], lie within +-2^51 (0 otherwise, for the scalar code): they
** convert to double exactly, and in the float build from there to float
** with one rounding, as (NUM)e does; then the scalar code's IEEE operations
** in its order. Stored as out[lane][0..2]. */
/* the edge values' doubles d (exact integers) as the build's numbers,
** (NUM)e as wgt_persp converts them */
AVX2_INLINE V4 v4_edge_num(__m256d d)
{
#if defined(GLES_NUM_FLOAT)
    return _mm256_cvtpd_ps(d);
#else
    return d;
#endif
}

/* v4_persp4's weights from the edge values ev as the build's numbers
** (ev[0] read only where the triangle is not affine) */
AVX2_INLINE void v4_persp4_ev(const WgtSetup *s, const V4 ev[3], WGT (*out)[3]);

/* edge value lanes e as the build's numbers ev; 0 where one leaves
** (-2^51, 2^51), where the conversion is exact */
AVX2_INLINE int v4_edge_lanes(const __m256i e[3], V4 ev[3])
{
    const __m256i bias = _mm256_set1_epi64x((int64_t)1 << 51);
    for (int i = 0; i < 3; i++) {
        /* e + 2^51 in [0, 2^52) */
        if (!_mm256_testz_si256(_mm256_add_epi64(e[i], bias), _mm256_set1_epi64x(~(((int64_t)1 << 52) - 1))))
            return 0;
        ev[i] = v4_edge_num(avx2_i64_to_pd(e[i]));
    }
    return 1;
}

AVX2_INLINE int v4_persp4(const WgtSetup *s, const __m256i e[3], WGT (*out)[3])
{
    V4 ev[3];
    if (!v4_edge_lanes(e, ev))
        return 0;
    v4_persp4_ev(s, ev, out);
    return 1;
}

/* v4_persp4_ev's weights o[0..2] of four fragments, in lanes, and where
** inv is not NULL, their WgtDen (1/den; 0 where the triangle is affine) */
AVX2_INLINE void v4_persp4_lanes_den(const WgtSetup *s, const V4 ev[3], V4 o[3], V4 *inv_out)
{
    if (inv_out)
        *inv_out = V4_OP(setzero)();
    if (s->affine) {
        o[1] = V4_OP(mul)(ev[1], V4_OP(set1)(s->inv_area));
        o[2] = V4_OP(mul)(ev[2], V4_OP(set1)(s->inv_area));
    } else {
        const V4 n0 = V4_OP(mul)(ev[0], V4_OP(set1)(s->q[0]));
        const V4 n1 = V4_OP(mul)(ev[1], V4_OP(set1)(s->q[1]));
        const V4 n2 = V4_OP(mul)(ev[2], V4_OP(set1)(s->q[2]));
        const V4 inv = V4_OP(div)(V4_OP(set1)(1), V4_OP(add)(V4_OP(add)(n0, n1), n2));
        o[1] = V4_OP(mul)(n1, inv);
        o[2] = V4_OP(mul)(n2, inv);
        if (inv_out)
            *inv_out = inv;
    }
    o[0] = V4_OP(sub)(V4_OP(sub)(V4_OP(set1)(1), o[1]), o[2]);
}

AVX2_INLINE void v4_persp4_lanes(const WgtSetup *s, const V4 ev[3], V4 o[3]) { v4_persp4_lanes_den(s, ev, o, NULL); }

/* wgt_tangent of four fragments of a triangle that is not affine, from
** their weights o and 1/den (lanes), in wgt_tangent's order */
AVX2_INLINE void v4_tangent4(const WgtTangent *g, const V4 o[3], V4 inv, V4 out[3])
{
    const V4 a0 = V4_OP(mul)(V4_OP(set1)(g->a[0]), inv), a1 = V4_OP(mul)(V4_OP(set1)(g->a[1]), inv);
    const V4 a2 = V4_OP(mul)(V4_OP(set1)(g->a[2]), inv);
    const V4 r = V4_OP(add)(V4_OP(add)(a0, a1), a2);
    out[1] = V4_OP(add)(o[1], V4_OP(sub)(a1, V4_OP(mul)(o[1], r)));
    out[2] = V4_OP(add)(o[2], V4_OP(sub)(a2, V4_OP(mul)(o[2], r)));
    out[0] = V4_OP(sub)(V4_OP(sub)(V4_OP(set1)(1), out[1]), out[2]);
}

/* four fragments' weights o[0..2] (lanes) stored as out[lane][0..2] */
AVX2_INLINE void v4_store_wgt4(const V4 o[3], WGT (*out)[3])
{
#if defined(GLES_NUM_FLOAT)
    avx2_store3x4_32(_mm_castps_si128(o[0]), _mm_castps_si128(o[1]), _mm_castps_si128(o[2]), out);
#else
    /* a0 b0 c0 a1 | b1 c1 a2 b2 | c2 a3 b3 c3 */
    const __m256d ab = _mm256_unpacklo_pd(o[0], o[1]), bc = _mm256_unpackhi_pd(o[1], o[2]);
    double *d = &out[0][0];
    _mm256_storeu_pd(d, _mm256_blend_pd(_mm256_blend_pd(ab, _mm256_permute4x64_pd(o[2], 0x00), 4),
                                        _mm256_permute4x64_pd(o[0], 0x55), 8));
    _mm256_storeu_pd(d + 4, _mm256_blend_pd(bc, ab, 0xC));
    _mm256_storeu_pd(d + 8, _mm256_blend_pd(_mm256_blend_pd(bc, _mm256_permute4x64_pd(o[2], 0xAA), 1),
                                            _mm256_permute4x64_pd(o[0], 0xFF), 2));
#endif
}

AVX2_INLINE void v4_persp4_ev(const WgtSetup *s, const V4 ev[3], WGT (*out)[3])
{
    V4 o[3];
    v4_persp4_lanes(s, ev, o);
    v4_store_wgt4(o, out);
}

/* span_tex_coord of an affine unit (vertex values sv[i], tv[i], in every lane) at four
** fragments' weights o (lanes): texc_lerp3's operations in its order,
** (a0 w0 + a1 w1) + a2 w2, stored as out[0..3] */
AVX2_INLINE void v4_tex_coord_affine4v(const V4 sv[3], const V4 tv[3], const V4 o[3], TexCoord *out)
{
#define V4_LERP3(a) V4_OP(add)(V4_OP(add)(V4_OP(mul)(a[0], o[0]), V4_OP(mul)(a[1], o[1])), V4_OP(mul)(a[2], o[2]))
    const V4 s = V4_LERP3(sv), t = V4_LERP3(tv);
#undef V4_LERP3
#if defined(GLES_NUM_FLOAT)
    _Static_assert(sizeof(TexCoord) == 2 * sizeof(float), "four TexCoords are eight floats");
    _mm_storeu_ps(&out[0].s, _mm_unpacklo_ps(s, t));
    _mm_storeu_ps(&out[2].s, _mm_unpackhi_ps(s, t));
#else
    _Static_assert(sizeof(TexCoord) == 2 * sizeof(double), "four TexCoords are eight doubles");
    const __m256d lo = _mm256_unpacklo_pd(s, t), hi = _mm256_unpackhi_pd(s, t);   /* s0 t0 s2 t2, s1 t1 s3 t3 */
    _mm256_storeu_pd(&out[0].s, _mm256_permute2f128_pd(lo, hi, 0x20));
    _mm256_storeu_pd(&out[2].s, _mm256_permute2f128_pd(lo, hi, 0x31));
#endif
}

/* the same with the vertex values sv[0..2], tv[0..2] */
AVX2_INLINE void v4_tex_coord_affine4(const NUM sv[3], const NUM tv[3], const V4 o[3], TexCoord *out)
{
    const V4 s3[3] = { V4_OP(set1)(sv[0]), V4_OP(set1)(sv[1]), V4_OP(set1)(sv[2]) };
    const V4 t3[3] = { V4_OP(set1)(tv[0]), V4_OP(set1)(tv[1]), V4_OP(set1)(tv[2]) };
    v4_tex_coord_affine4v(s3, t3, o, out);
}

AVX2_INLINE V4 v4_load(const FRAGV *c) { return V4_OP(loadu)(c); }
AVX2_INLINE void v4_store(FRAGV *c, V4 v) { V4_OP(storeu)(c, v); }
AVX2_INLINE V4 v4_set1(FRAGV f) { return V4_OP(set1)(f); }
/* (lane 3 cleared by a blend: GCC forms setr(c0, c1, c2, 0) with the
** register form of VEX vmovq, which valgrind does not decode, and the
** instruction counts of benchmarks/run.py need it to) */
AVX2_INLINE V4 v4_rgb0(const FRAGV c[3])
{
    return V4_OP(blend)(V4_OP(setr)(c[0], c[1], c[2], c[2]), V4_OP(setzero)(), 8);
}
AVX2_INLINE V4 v4_add(V4 a, V4 b) { return V4_OP(add)(a, b); }
AVX2_INLINE V4 v4_mul(V4 a, V4 b) { return V4_OP(mul)(a, b); }
AVX2_INLINE V4 v4_mul01(V4 a, V4 b) { return V4_OP(mul)(a, b); }
AVX2_INLINE V4 v4_one_minus(V4 a) { return V4_OP(sub)(V4_OP(set1)(1), a); }
AVX2_INLINE int v4_fits(V4 v) { (void)v; return 1; }
AVX2_INLINE int v4_lerp_fits(V4 v) { (void)v; return 1; }
/* frag_clamp01: v < 0 ? 0 : (v > 1 ? 1 : v); max and min return their
** second operand when unordered or equal, so NaN and -0 pass as there */
AVX2_INLINE V4 v4_clamp01(V4 v) { return V4_OP(min)(V4_OP(set1)(1), V4_OP(max)(V4_OP(setzero)(), v)); }
/* d / 255 of integers d in [0, 255], correctly rounded as the division
** rounds, without a division: 1/255 split as UNORM8_RECIP_HI + LO (the
** first rounded, the second the rounded rest), then d HI + (d LO) in one
** fused multiply-add. d / 255 is d's eight bits repeated in binary, never
** within 2^-8 of a rounding midpoint relative to the last place, and the
** sum is within about 2^-100 of it, so its one rounding is the quotient's
** (test_simd checks all 256 values in each build against the scalar
** code's division) */
#if defined(GLES_NUM_FLOAT)
#define UNORM8_RECIP_HI 0x1.010102p-8f
#define UNORM8_RECIP_LO (-0x1.fdfdfep-33f)
#else
#define UNORM8_RECIP_HI 0x1.0101010101010p-8
#define UNORM8_RECIP_LO 0x1.0101010101010p-64
#endif
AVX2_INLINE V4 v4_div255(V4 d)
{
#if defined(GLES_NUM_FLOAT)
    return _mm_fmadd_ps(d, _mm_set1_ps(UNORM8_RECIP_HI), _mm_mul_ps(d, _mm_set1_ps(UNORM8_RECIP_LO)));
#else
    return _mm256_fmadd_pd(d, _mm256_set1_pd(UNORM8_RECIP_HI), _mm256_mul_pd(d, _mm256_set1_pd(UNORM8_RECIP_LO)));
#endif
}
/* ((0 + p0) + p1) + p2 in every lane (combine_block's DOT3 sum) */
AVX2_INLINE V4 v4_sum3(V4 p)
{
#if defined(GLES_NUM_FLOAT)
    __m128 s = _mm_add_ss(_mm_setzero_ps(), p);
    s = _mm_add_ss(_mm_add_ss(s, _mm_shuffle_ps(p, p, 1)), _mm_movehl_ps(p, p));
    return _mm_shuffle_ps(s, s, 0);
#else
    const __m128d lo = _mm256_castpd256_pd128(p);
    __m128d s = _mm_add_sd(_mm_setzero_pd(), lo);
    s = _mm_add_sd(_mm_add_sd(s, _mm_unpackhi_pd(lo, lo)), _mm256_extractf128_pd(p, 1));
    return _mm256_broadcastsd_pd(s);
#endif
}
/* the four bytes of a word as d / 255 (frag_from_unorm, ctx->unorm8) */
AVX2_INLINE V4 v4_unorm8(uint32_t word)
{
    return v4_div255(v4_from_i32(_mm_cvtepu8_epi32(_mm_cvtsi32_si128((int)word))));
}
/* the same of one byte (bits shift .. shift + 7) of four words, lane by
** lane (avx2_byte_lanes8's taking, in the low half) */
AVX2_INLINE V4 v4_byte_unorm8(__m128i words, int shift)
{
    const __m256i d = avx2_byte_lanes8(_mm256_castsi128_si256(words), shift / 8);
    return v4_div255(v4_from_i32(_mm256_castsi256_si128(d)));
}
/* x (= v maxval + t, or v 2^bits) within [0, top] and truncated, per
** lane: frag_to_unorm(v, maxval, t) with top = maxval, for thresholds 0
** <= t < 1 whose sum with maxval is exact, and frag_to_msb(v, bits) with
** top = 2^bits - 1. Where v <= 0, x < 1 and gives 0; a NaN x (v NaN) is
** max's second operand, 0. Where v >= 1, x >= top. Else fl(v maxval) <=
** maxval, so x < maxval + 1 and the minimum truncates as x does; and
** v 2^bits's floor is its truncation. (span_float8.h's f8_unorm, f8_msb.) */
AVX2_INLINE __m128i v4_trunc_within(V4 x, V4 top)
{
    return v4_trunc_i32(V4_OP(min)(V4_OP(max)(x, V4_OP(setzero)()), top));
}
/* frag_to_unorm(v, 255, 1/2) per lane, as int32: 0 unless v > 0, 255
** from 1 up, else v 255 + 1/2 truncated */
AVX2_INLINE __m128i v4_to_unorm8(V4 v)
{
    return v4_trunc_within(V4_OP(add)(V4_OP(mul)(v, V4_OP(set1)(255)), V4_OP(set1)(0.5)), V4_OP(set1)(255));
}
/* the four channels' v4_to_unorm8 as one RGBA8888 word */
AVX2_INLINE uint32_t v4_pack_unorm8(V4 v)
{
    __m128i i = v4_to_unorm8(v);
    i = _mm_packus_epi16(_mm_packus_epi32(i, i), _mm_setzero_si128());
    return (uint32_t)_mm_cvtsi128_si32(i);
}
/* pack565 of red, green and blue (fragment_channel of 5, 6 and 5 bits;
** the alpha lane gives 0): with dither frag_to_unorm (0 unless v > 0,
** maxval from 1 up, else v maxval + t truncated), else frag_to_msb
** (floor(v 2^bits), 0 unless v > 0, at most 2^bits - 1; the floor of a
** larger value, or of infinity, is at least 2^bits, so the minimum is it) */
AVX2_INLINE uint32_t v4_pack565(V4 v, int dither, FRAGV t)
{
    const V4 top = V4_OP(setr)(31, 63, 31, 0);
    const V4 x = dither ? V4_OP(add)(V4_OP(mul)(v, top), V4_OP(set1)(t)) : V4_OP(mul)(v, V4_OP(setr)(32, 64, 32, 1));
    const __m128i i = _mm_sllv_epi32(v4_trunc_within(x, top), _mm_setr_epi32(11, 5, 0, 0));
    return (uint32_t)_mm_cvtsi128_si32(_mm_or_si128(_mm_or_si128(i, _mm_srli_si128(i, 4)), _mm_srli_si128(i, 8)));
}
/* v4_pack565 of four fragments, channel by channel: red, green and blue
** of the four in lanes (rgb[0..2]), the dither thresholds t (lanes); the
** same operations lane by lane, the four words in int32 lanes */
AVX2_INLINE __m128i v4_pack565x4(const V4 rgb[3], int dither, V4 t)
{
    static const int bits[3] = { 5, 6, 5 }, shift[3] = { 11, 5, 0 };
    __m128i w = _mm_setzero_si128();
    for (int i = 0; i < 3; i++) {
        const V4 v = rgb[i], top = V4_OP(set1)((NUM)((1 << bits[i]) - 1));
        const V4 x = dither ? V4_OP(add)(V4_OP(mul)(v, top), t) : V4_OP(mul)(v, V4_OP(set1)((NUM)(1 << bits[i])));
        w = _mm_or_si128(w, _mm_slli_epi32(v4_trunc_within(x, top), shift[i]));
    }
    return w;
}
/* frag_lerp3f: a0 w0 + a1 w1 + a2 w2 */
AVX2_INLINE V4 v4_lerp3f(V4 a0, V4 a1, V4 a2, const WGT *p)
{
    return V4_OP(add)(V4_OP(add)(V4_OP(mul)(a0, V4_OP(set1)(p[0])), V4_OP(mul)(a1, V4_OP(set1)(p[1]))),
                      V4_OP(mul)(a2, V4_OP(set1)(p[2])));
}
AVX2_INLINE V4 v4_lerp3f_w(V4 a0, V4 a1, V4 a2, WGT w0, WGT w1, WGT w2)
{
    const WGT p[3] = { w0, w1, w2 };
    return v4_lerp3f(a0, a1, a2, p);
}
AVX2_INLINE V4 v4_lerp3f_clamp01(V4 a0, V4 a1, V4 a2, const WGT *p) { return v4_clamp01(v4_lerp3f(a0, a1, a2, p)); }
/* frag_bilerp_rgba8: (v00 (1-a) + v10 a)(1-b) + (v01 (1-a) + v11 a) b per channel */
static inline void avx2_bilerp_rgba8(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, TEXW a, TEXW b,
                                     FRAGV out[4])
{
    const V4 va = V4_OP(set1)(a), vb = V4_OP(set1)(b), ia = V4_OP(set1)(1 - a), ib = V4_OP(set1)(1 - b);
    const V4 top = V4_OP(add)(V4_OP(mul)(v4_unorm8(c00), ia), V4_OP(mul)(v4_unorm8(c10), va));
    const V4 bot = V4_OP(add)(V4_OP(mul)(v4_unorm8(c01), ia), V4_OP(mul)(v4_unorm8(c11), va));
    v4_store(out, V4_OP(add)(V4_OP(mul)(top, ib), V4_OP(mul)(bot, vb)));
}

/* wgt_linear then wgt_depth3 of four fragments with edge values e1[k],
** e2[k], given as the doubles d1, d2 (|e| <= 2^53: the conversion to
** double is exact, so the float build's conversion from it rounds once, as
** (NUM)e does), the same IEEE operations in lanes; dbl_to_i64's tests as
** selects (NaN and v <= 0 give 0, v >= maxval gives maxval, else
** floor(v + 1/2)); maxval <= INT32_MAX */
AVX2_INLINE void v4_depth4_pd(const WgtSetup *s, __m256d d1, __m256d d2, const DEPTHV z[3], uint32_t maxval,
                              uint32_t *out)
{
#if defined(GLES_NUM_FLOAT)
    const V4 l1 = _mm_mul_ps(_mm256_cvtpd_ps(d1), _mm_set1_ps(s->inv_area));
    const V4 l2 = _mm_mul_ps(_mm256_cvtpd_ps(d2), _mm_set1_ps(s->inv_area));
#else
    const V4 l1 = _mm256_mul_pd(d1, _mm256_set1_pd(s->inv_area));
    const V4 l2 = _mm256_mul_pd(d2, _mm256_set1_pd(s->inv_area));
#endif
    const V4 l0 = V4_OP(sub)(V4_OP(sub)(V4_OP(set1)(1), l1), l2);
    const V4 v = V4_OP(add)(V4_OP(add)(V4_OP(mul)(V4_OP(set1)(z[0]), l0), V4_OP(mul)(V4_OP(set1)(z[1]), l1)),
                            V4_OP(mul)(V4_OP(set1)(z[2]), l2));
#if defined(GLES_NUM_FLOAT)
    const __m256d vd = _mm256_cvtps_pd(v);
#else
    const __m256d vd = v;
#endif
    const __m256d zero = _mm256_setzero_pd(), top = _mm256_set1_pd((double)maxval);
    __m256d r = _mm256_floor_pd(_mm256_add_pd(vd, _mm256_set1_pd(0.5)));
    r = _mm256_blendv_pd(r, top, _mm256_cmp_pd(vd, top, _CMP_GE_OQ));
    r = _mm256_blendv_pd(r, zero, _mm256_cmp_pd(vd, zero, _CMP_LE_OQ));
    r = _mm256_blendv_pd(r, zero, _mm256_cmp_pd(vd, vd, _CMP_UNORD_Q));
    _mm_storeu_si128((__m128i *)(void *)out, _mm256_cvttpd_epi32(r));
}
/* the same of edge values as int64 */
AVX2_INLINE void v4_depth4(const WgtSetup *s, const int64_t e1[4], const int64_t e2[4], const DEPTHV z[3],
                           uint32_t maxval, uint32_t *out)
{
    v4_depth4_pd(s, _mm256_setr_pd((double)e1[0], (double)e1[1], (double)e1[2], (double)e1[3]),
                 _mm256_setr_pd((double)e2[0], (double)e2[1], (double)e2[2], (double)e2[3]), z, maxval, out);
}

/* the s (or t, odd = 1) of four fragments' coordinates c[0..3] */
AVX2_INLINE V4 v4_coord4(const TexCoord *c, int odd)
{
#if defined(GLES_NUM_FLOAT)
    const __m128 p01 = _mm_loadu_ps(&c[0].s), p23 = _mm_loadu_ps(&c[2].s);
    return odd ? _mm_shuffle_ps(p01, p23, _MM_SHUFFLE(3, 1, 3, 1)) : _mm_shuffle_ps(p01, p23, _MM_SHUFFLE(2, 0, 2, 0));
#else
    const __m256d p01 = _mm256_loadu_pd(&c[0].s), p23 = _mm256_loadu_pd(&c[2].s);
    const __m256d v = odd ? _mm256_unpackhi_pd(p01, p23) : _mm256_unpacklo_pd(p01, p23);
    return _mm256_permute4x64_pd(v, 0xD8);
#endif
}

/* whether every lane is finite (not NaN nor infinite) */
AVX2_INLINE int v4_finite(V4 v)
{
    const V4 inf = V4_OP(set1)((NUM)INFINITY);
#if defined(GLES_NUM_FLOAT)
    const V4 abs = _mm_andnot_ps(_mm_set1_ps(-0.0f), v);
    return _mm_movemask_ps(_mm_cmplt_ps(abs, inf)) == 0xF;
#else
    const V4 abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), v);
    return _mm256_movemask_pd(_mm256_cmp_pd(abs, inf, _CMP_LT_OQ)) == 0xF;
#endif
}

/* sample_level's GL_LINEAR indices and weight along one axis of size n (a
** power of two), REPEAT or CLAMP_TO_EDGE, for four finite coordinates: the
** same operations as reduce_coord, texc_scale, texc_ifloor,
** texc_frac_weight and wrap_index, lane by lane (the floor of a value this
** small is exact as an int32, and is texc_ifloor's integer) */
AVX2_INLINE void v4_linear_axis(V4 s, int n, int repeat, __m128i *i0, __m128i *i1, V4 *w)
{
#if defined(GLES_NUM_FLOAT)
#define V4_FLOOR(v) _mm_floor_ps(v)
#else
#define V4_FLOOR(v) _mm256_floor_pd(v)
#endif
    if (repeat)
        s = V4_OP(sub)(s, V4_FLOOR(s));
    else
        s = V4_OP(min)(V4_OP(max)(s, V4_OP(set1)(-1)), V4_OP(set1)(2));
    const V4 uu = V4_OP(sub)(V4_OP(mul)(s, V4_OP(set1)((NUM)n)), V4_OP(set1)((NUM)0.5));
    const V4 fl = V4_FLOOR(uu);
#undef V4_FLOOR
    *w = V4_OP(sub)(uu, fl);
    const __m128i i = v4_trunc_i32(fl), j = _mm_add_epi32(i, _mm_set1_epi32(1));
    if (repeat) {
        const __m128i mask = _mm_set1_epi32(n - 1);
        *i0 = _mm_and_si128(i, mask);
        *i1 = _mm_and_si128(j, mask);
    } else {
        const __m128i zero = _mm_setzero_si128(), top = _mm_set1_epi32(n - 1);
        *i0 = _mm_min_epi32(_mm_max_epi32(i, zero), top);
        *i1 = _mm_min_epi32(_mm_max_epi32(j, zero), top);
    }
}

/* the 4x4 transpose of v[0..3]: lane i of v[k] to lane k of v[i] */
AVX2_INLINE void v4_transpose4(V4 v[4])
{
#if defined(GLES_NUM_FLOAT)
    _MM_TRANSPOSE4_PS(v[0], v[1], v[2], v[3]);
#else
    const __m256d t0 = _mm256_unpacklo_pd(v[0], v[1]), t1 = _mm256_unpackhi_pd(v[0], v[1]);
    const __m256d t2 = _mm256_unpacklo_pd(v[2], v[3]), t3 = _mm256_unpackhi_pd(v[2], v[3]);
    v[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
    v[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
    v[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
    v[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
#endif
}

/* frag_bilerp_rgba8 of four fragments, lane k fragment k: texel words
** g[0..3] (c00, c10, c01, c11), weights a and b; each channel's bytes d
** as d / 255 (ctx->texel_unorm8's values), then the scalar code's IEEE
** operations in its order, one channel of the four fragments at a time,
** as lanes ch[0..3] (v4_bilerp4 stores them as out[k stride + channel]) */
AVX2_INLINE void v4_bilerp4_channels(const __m128i g[4], V4 a, V4 b, V4 ch[4])
{
    const V4 ia = V4_OP(sub)(V4_OP(set1)(1), a), ib = V4_OP(sub)(V4_OP(set1)(1), b);
    for (int c = 0; c < 4; c++) {
        V4 v[4];
        for (int i = 0; i < 4; i++)
            v[i] = v4_byte_unorm8(g[i], 8 * c);
        const V4 top = V4_OP(add)(V4_OP(mul)(v[0], ia), V4_OP(mul)(v[1], a));
        const V4 bot = V4_OP(add)(V4_OP(mul)(v[2], ia), V4_OP(mul)(v[3], a));
        ch[c] = V4_OP(add)(V4_OP(mul)(top, ib), V4_OP(mul)(bot, b));
    }
}

/* channels ch[0..3] of four fragments (lanes) stored as out[k stride + channel] */
AVX2_INLINE void v4_store_channels4(V4 ch[4], FRAGV *out, size_t stride)
{
    v4_transpose4(ch);      /* channels of four fragments to four fragments' channels */
    for (int k = 0; k < 4; k++)
        v4_store(out + (size_t)k * stride, ch[k]);
}

AVX2_INLINE void v4_bilerp4(const __m128i g[4], V4 a, V4 b, FRAGV *out, size_t stride)
{
    V4 ch[4];
    v4_bilerp4_channels(g, a, b, ch);
    v4_store_channels4(ch, out, stride);
}

/* the coordinates c[0..7] as lanes: s of fragments 4q..4q+3 in s[q], t in
** t[q]; 0 where one is not finite */
AVX2_INLINE int v4_coords8(const TexCoord *c, V4 s[2], V4 t[2])
{
    int finite = 1;
    for (int q = 0; q < 2; q++) {
        s[q] = v4_coord4(&c[4 * q], 0);
        t[q] = v4_coord4(&c[4 * q], 1);
        finite &= v4_finite(s[q]) && v4_finite(t[q]);
    }
    return finite;
}

/* the GL_LINEAR indices' weights a, b (fragments 4q..4q+3 in a[q], b[q])
** and texel words g of the finite coordinates s, t (v4_coords8's lanes)
** on a power-of-two level (texels, w x h), REPEAT or CLAMP_TO_EDGE on each
** axis: both
** fours' indices in one register each, their words by avx2_texel_words8
** (row loads where `rows` asks and they apply, else gathers of the pairs
** where no pair wraps: the words four gathers of four would give, in a
** fraction of their time) */
AVX2_INLINE void v4_linear_lanes8(const void *texels, int w, int h, const V4 s[2], const V4 t[2], int repeat_s,
                                  int repeat_t, int rows, V4 a[2], V4 b[2], __m256i g[4])
{
    __m128i x0[2], x1[2], y0[2], y1[2];
    for (int q = 0; q < 2; q++) {
        v4_linear_axis(s[q], w, repeat_s, &x0[q], &x1[q], &a[q]);
        v4_linear_axis(t[q], h, repeat_t, &y0[q], &y1[q], &b[q]);
    }
    avx2_texel_words8(texels, w, (int64_t)w * h, _mm256_set_m128i(x0[1], x0[0]), _mm256_set_m128i(x1[1], x1[0]),
                      _mm256_set_m128i(y0[1], y0[0]), _mm256_set_m128i(y1[1], y1[0]), rows, g);
}

/* v4_linear_lanes8 of level li at the coordinates c[0..7]; 0 (nothing
** read) where one is not finite */
AVX2_INLINE int v4_linear_group8(const TexImage *li, const TexCoord *c, int repeat_s, int repeat_t, int rows,
                                 V4 a[2], V4 b[2], __m256i g[4])
{
    V4 sv[2], tv[2];
    if (!v4_coords8(c, sv, tv))
        return 0;
    v4_linear_lanes8(li->texels, li->width, li->height, sv, tv, repeat_s, repeat_t, rows, a, b, g);
    return 1;
}

/* the filtered channels (v4_bilerp4_channels) of half q of a group's
** words g, weights a and b */
AVX2_INLINE void v4_linear_half4(const __m256i g[4], int q, V4 a, V4 b, V4 ch[4])
{
    __m128i h[4];
    for (int i = 0; i < 4; i++)
        h[i] = q ? _mm256_extracti128_si256(g[i], 1) : _mm256_castsi256_si128(g[i]);
    v4_bilerp4_channels(h, a, b, ch);
}

/* sample_level's GL_LINEAR of a power-of-two level for fragments 0..n-1
** (n a multiple of 4), REPEAT or CLAMP_TO_EDGE on each axis, filtered by
** v4_bilerp4: two groups of eight at a time (v4_linear_group8), both
** groups' words before either's filtering, so that the second group's
** gathers do not wait behind the first's arithmetic (trilinear_fog's
** double build about 6% faster); then a last group of eight, then four at
** a time by gathers. Stops before the first four coordinates of which one
** is not finite (NaN and the infinities take sample_level's tests);
** returns the number of fragments done. */
static inline int avx2_sample_linear_real(const TexImage *li, int n, const TexCoord *c, FRAGV *out, size_t stride,
                                          int repeat_s, int repeat_t, int rows)
{
    const int w = li->width, h = li->height;
    const uint32_t *tx = li->texels;
    int j = 0;
    while (j + 8 <= n) {
        const int groups = j + 16 <= n ? 2 : 1;
        V4 a[2][2], b[2][2];
        __m256i g[2][4];
        if (!v4_linear_group8(li, c + j, repeat_s, repeat_t, rows, a[0], b[0], g[0])
            || (groups == 2 && !v4_linear_group8(li, c + j + 8, repeat_s, repeat_t, rows, a[1], b[1], g[1])))
            break;      /* (the fours below stop at the first of them) */
        for (int k = 0; k < groups; k++)
            for (int q = 0; q < 2; q++) {
                V4 ch[4];
                v4_linear_half4(g[k], q, a[k][q], b[k][q], ch);
                v4_store_channels4(ch, out + (size_t)(j + 8 * k + 4 * q) * stride, stride);
            }
        j += 8 * groups;
    }
    for (; j < n; j += 4) {
        const V4 sv = v4_coord4(&c[j], 0), tv = v4_coord4(&c[j], 1);
        if (!(v4_finite(sv) && v4_finite(tv)))
            return j;
        __m128i x0, x1, y0, y1;
        V4 a, b;
        v4_linear_axis(sv, w, repeat_s, &x0, &x1, &a);
        v4_linear_axis(tv, h, repeat_t, &y0, &y1, &b);
        const __m128i r0 = _mm_mullo_epi32(y0, _mm_set1_epi32(w)), r1 = _mm_mullo_epi32(y1, _mm_set1_epi32(w));
        const int *t32 = (const int *)(const void *)tx;
        const __m128i g[4] = { _mm_i32gather_epi32(t32, _mm_add_epi32(r0, x0), 4),
                               _mm_i32gather_epi32(t32, _mm_add_epi32(r0, x1), 4),
                               _mm_i32gather_epi32(t32, _mm_add_epi32(r1, x0), 4),
                               _mm_i32gather_epi32(t32, _mm_add_epi32(r1, x1), 4) };
        v4_bilerp4(g, a, b, out + (size_t)j * stride, stride);
    }
    return n;
}

#if !defined(GLES_NUM_FLOAT)
/* avx2_sample_linear_real of two levels l1, l2 at the same coordinates
** (not read by rows), mixed by frac[0..n) as lod_block mixes them (t1 +
** frac (t2 - t1) per channel), eight at a time with no store of either
** level's texels between, both levels from one load of the coordinates
** (the double build's trilinear_fog 8% fewer instructions); stops before
** the first eight coordinates of which one is not finite; returns the
** number of fragments done */
static inline int avx2_sample_linear_mix_real(const TexImage *l1, const TexImage *l2, int n, const TexCoord *c,
                                              const FRAGV *frac, FRAGV *out, size_t stride, int repeat_s, int repeat_t)
{
    int j = 0;
    for (; j + 8 <= n; j += 8) {
        V4 s[2], t[2], a1[2], b1[2], a2[2], b2[2];
        __m256i g1[4], g2[4];
        if (!v4_coords8(c + j, s, t))
            break;
        v4_linear_lanes8(l1->texels, l1->width, l1->height, s, t, repeat_s, repeat_t, 0, a1, b1, g1);
        v4_linear_lanes8(l2->texels, l2->width, l2->height, s, t, repeat_s, repeat_t, 0, a2, b2, g2);
        for (int q = 0; q < 2; q++) {
            V4 t1[4], t2[4];
            v4_linear_half4(g1, q, a1[q], b1[q], t1);
            v4_linear_half4(g2, q, a2[q], b2[q], t2);
            const V4 f = v4_load(frac + j + 4 * q);
            for (int k = 0; k < 4; k++)
                t1[k] = V4_OP(add)(t1[k], V4_OP(mul)(f, V4_OP(sub)(t2[k], t1[k])));
            v4_store_channels4(t1, out + (size_t)(j + 4 * q) * stride, stride);
        }
    }
    return j;
}
#endif
#endif

#if SIMD_X86
/* span_rgba8 of a fragment's four channels (the same arithmetic: for kind
** 2, frag_mul(x, FRAG_ONE) is x) */
AVX2_INLINE uint32_t v4_rgba8(V4 c, uint32_t d, int kind)
{
    if (kind == 0)
        return v4_pack_unorm8(c);
    const V4 cv = v4_clamp01(c);
    if (kind == 2)
        return v4_pack_unorm8(v4_add(cv, v4_unorm8(d)));
    const V4 va = v4_alpha(cv);
    return v4_pack_unorm8(v4_add(v4_mul01(cv, va), v4_mul01(v4_unorm8(d), v4_one_minus(va))));
}

/* fragment_logic_op on four words: its body on vector lanes */
typedef uint32_t avx2_u32x4 __attribute__((vector_size(16)));
AVX2_INLINE avx2_u32x4 avx2_logic_op_u32x4(unsigned int op, avx2_u32x4 s, avx2_u32x4 d)
{
    FRAGMENT_LOGIC_OP_BODY(op, s, d)
}
AVX2_INLINE __m128i avx2_logic_op4(unsigned int op, __m128i sv, __m128i dv)
{
    return (__m128i)avx2_logic_op_u32x4(op, (avx2_u32x4)sv, (avx2_u32x4)dv);
}

/* four words (slots k[0..3] of dst) as one vector: one load when the
** offsets are consecutive (run), else four */
AVX2_INLINE __m128i avx2_load_words4(const uint32_t *dst, uint32_t k4, int run)
{
    if (run)
        return _mm_loadu_si128((const __m128i *)(const void *)&dst[k4 & 0xFFu]);
    return _mm_setr_epi32((int)dst[k4 & 0xFFu], (int)dst[(k4 >> 8) & 0xFFu], (int)dst[(k4 >> 16) & 0xFFu],
                          (int)dst[k4 >> 24]);
}
AVX2_INLINE void avx2_store_words4(uint32_t *dst, uint32_t k4, int run, __m128i w)
{
    if (run) {
        _mm_storeu_si128((__m128i *)(void *)&dst[k4 & 0xFFu], w);
        return;
    }
    dst[k4 & 0xFFu] = (uint32_t)_mm_cvtsi128_si32(w);
    dst[(k4 >> 8) & 0xFFu] = (uint32_t)_mm_extract_epi32(w, 1);
    dst[(k4 >> 16) & 0xFFu] = (uint32_t)_mm_extract_epi32(w, 2);
    dst[k4 >> 24] = (uint32_t)_mm_extract_epi32(w, 3);
}

#if !NUM_IS_FIXED
/* v4_rgba8 of four fragments c[0..3] over the stored words d (lanes 0..3),
** into *out, one channel of the four fragments per V4: the same IEEE
** operations lane by lane (v4_clamp01, the blend, then v4_to_unorm8).
** Returns 1: every value is in range in these builds (the fixed build's
** kernel of the same name may leave a group to v4_rgba8). */
AVX2_INLINE int avx2_rgba8x4(const FRAGV (*c)[4], __m128i d, int kind, __m128i *out)
{
    V4 v[4] = { v4_load(c[0]), v4_load(c[1]), v4_load(c[2]), v4_load(c[3]) };
    v4_transpose4(v);
    if (kind)
        for (int i = 0; i < 4; i++)
            v[i] = v4_clamp01(v[i]);
    const V4 va = v[3], ia = v4_one_minus(va);
    __m128i w = _mm_setzero_si128();
    for (int i = 0; i < 4; i++) {
        V4 x = v[i];
        if (kind) {
            const V4 dv = v4_byte_unorm8(d, 8 * i);
            x = kind == 2 ? v4_add(x, dv) : v4_add(v4_mul01(x, va), v4_mul01(dv, ia));
        }
        w = _mm_or_si128(w, _mm_slli_epi32(v4_to_unorm8(x), 8 * i));
    }
    *out = w;
    return 1;
}
#endif

#if NUM_IS_FIXED
/* v4_rgba8 of four fragments c[0..3] over the stored words d (lanes 0..3),
** into *out; 0 (nothing done) unless every channel lies in [0, 2^31).
** Each fragment stays one register; only the packing merges them.
** Exact: with every lane in [0, 2^31) the high dwords are 0, so an unsigned
** dword minimum against (2^30, 0) is frag_clamp01 (the lower bound holds
** already). The stored bytes are widened by a byte shuffle, and
** frag_from_unorm(d, 255) = d 4210752 + ((d + 2) >> 2) (avx2_unorm8) is
** (16843009 d + 2) >> 2, as 16843009 = 4 4210752 + 1. Kind 2's sum stays
** below 2^31 + 1, so the same minimum is frag_to_unorm's upper test; kind
** 1's two frag_mul terms (operands in [0, 2^30], one vpmuludq each,
** v4_mul01's rounding) are at most sa and 2^30 - sa (cv <= 2^30 and
** u <= 2^30), so their sum needs no clamp. frag_to_unorm's lower test
** (v <= 0 gives 0) is what the formula gives at v = 0, and
** (255 v + 2^29) >> 30 = (1020 v + 2^31) >> 32, the product's high dword
** (below 2^8), which the packs gather. */
AVX2_INLINE int avx2_rgba8x4(const FRAGV (*c)[4], __m128i d, int kind, __m128i *out)
{
    __m256i v[4];
    for (int i = 0; i < 4; i++)
        v[i] = avx2_load4(c[i]);
    const __m256i any = _mm256_or_si256(_mm256_or_si256(v[0], v[1]), _mm256_or_si256(v[2], v[3]));
    if (!_mm256_testz_si256(any, _mm256_set1_epi64x(~(int64_t)0x7FFFFFFF)))
        return 0;
    const __m256i one = _mm256_set1_epi64x(FRAG_ONE);
    const __m256i db = _mm256_broadcastsi128_si256(d);
    for (int i = 0; i < 4; i++) {
        __m256i x = _mm256_min_epu32(v[i], one);
        if (kind) {
            /* fragment i's stored bytes, one per 64-bit lane, as 0.30 */
            const __m256i pick = _mm256_setr_epi8(4 * i, -1, -1, -1, -1, -1, -1, -1, 4 * i + 1, -1, -1, -1, -1, -1,
                                                  -1, -1, 4 * i + 2, -1, -1, -1, -1, -1, -1, -1, 4 * i + 3, -1, -1,
                                                  -1, -1, -1, -1, -1);
            const __m256i db8 = _mm256_shuffle_epi8(db, pick);
            const __m256i u = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(db8, _mm256_set1_epi64x(16843009)),
                                                                 _mm256_set1_epi64x(2)), 2);
            if (kind == 2) {
                x = _mm256_min_epu32(_mm256_add_epi64(x, u), one);
            } else {
                const __m256i sa = _mm256_permute4x64_epi64(x, 0xFF);
                x = _mm256_add_epi64(avx2_mul_u(x, sa), avx2_mul_u(u, _mm256_sub_epi64(one, sa)));
            }
        }
        v[i] = _mm256_add_epi64(_mm256_mul_epu32(x, _mm256_set1_epi64x(1020)), _mm256_set1_epi64x((int64_t)1 << 31));
    }
    /* the high dwords: lane halves (R0 G0 R1 G1 | B0 A0 B1 A1), then
    ** (R2 G2 R3 G3 | B2 A2 B3 A3), to words, to bytes, halves interleaved */
    const __m256i h01 = _mm256_castps_si256(_mm256_shuffle_ps(_mm256_castsi256_ps(v[0]), _mm256_castsi256_ps(v[1]),
                                                              _MM_SHUFFLE(3, 1, 3, 1)));
    const __m256i h23 = _mm256_castps_si256(_mm256_shuffle_ps(_mm256_castsi256_ps(v[2]), _mm256_castsi256_ps(v[3]),
                                                              _MM_SHUFFLE(3, 1, 3, 1)));
    __m256i w = _mm256_packus_epi32(h01, h23);
    w = _mm256_packus_epi16(w, w);
    *out = _mm_unpacklo_epi16(_mm256_castsi256_si128(w), _mm256_extracti128_si256(w, 1));
    return 1;
}

#endif

/* {====================================================================
** The stencil and depth tests (§4.1.5, §4.1.6), eight fragments at a time
** in 32-bit lanes, in every build (they are integer work): the outcome of
** fragment_tests and the buffers' new values, lane by lane. */

/* a comparison function (fragment_compare) as the lanes of its outcomes
** a < b, a == b, a > b: all ones where that outcome passes */
typedef struct Avx2Cmp {
    __m256i lt, eq, gt;
} Avx2Cmp;

static inline Avx2Cmp avx2_cmp_setup(unsigned int func)
{
    int lt = 1, eq = 1, gt = 1;    /* GL_ALWAYS, and any other value */
    switch (func) {
    case GL_NEVER: lt = eq = gt = 0; break;
    case GL_LESS: eq = gt = 0; break;
    case GL_EQUAL: lt = gt = 0; break;
    case GL_LEQUAL: gt = 0; break;
    case GL_GREATER: lt = eq = 0; break;
    case GL_NOTEQUAL: eq = 0; break;
    case GL_GEQUAL: lt = 0; break;
    default: break;
    }
    return (Avx2Cmp){ _mm256_set1_epi32(-lt), _mm256_set1_epi32(-eq), _mm256_set1_epi32(-gt) };
}

/* fragment_compare(func, a, b) of int32 lanes, all ones where it holds */
AVX2_INLINE __m256i avx2_cmp_i32(const Avx2Cmp *f, __m256i a, __m256i b)
{
    const __m256i lt = _mm256_cmpgt_epi32(b, a), gt = _mm256_cmpgt_epi32(a, b);
    return _mm256_or_si256(_mm256_or_si256(_mm256_and_si256(lt, f->lt), _mm256_and_si256(gt, f->gt)),
                           _mm256_andnot_si256(_mm256_or_si256(lt, gt), f->eq));
}

/* fragment_compare(func, a, b) of uint32 lanes for a func known where it
** is inlined (the depth test's, fixed per chunk); the sign bit flipped
** makes the signed comparison the unsigned one */
AVX2_INLINE __m256i avx2_cmp_u32(unsigned int func, __m256i a, __m256i b)
{
    const __m256i ones = _mm256_set1_epi32(-1);
    if (func == GL_NEVER)
        return _mm256_setzero_si256();
    if (func == GL_EQUAL)
        return _mm256_cmpeq_epi32(a, b);
    if (func == GL_NOTEQUAL)
        return _mm256_xor_si256(_mm256_cmpeq_epi32(a, b), ones);
    const __m256i bias = _mm256_set1_epi32(INT32_MIN);
    a = _mm256_xor_si256(a, bias);
    b = _mm256_xor_si256(b, bias);
    switch (func) {
    case GL_LESS: return _mm256_cmpgt_epi32(b, a);
    case GL_LEQUAL: return _mm256_xor_si256(_mm256_cmpgt_epi32(a, b), ones);
    case GL_GREATER: return _mm256_cmpgt_epi32(a, b);
    case GL_GEQUAL: return _mm256_xor_si256(_mm256_cmpgt_epi32(b, a), ones);
    default: return ones;
    }
}

/* A stencil op (fragment_stencil_op) as arithmetic on the stored value s
** in 0..255: v = min(max((s & and_s) + add, lo), hi) ^ flip, then the
** write mask wm (8 bits) takes v's bits and leaves s's elsewhere. KEEP is
** v = s; ZERO and REPLACE drop s (and_s = 0) and add 0 or ref; INCR and
** DECR add +-1 and clamp to 0..255; INVERT flips the 8 bits; the wrapping
** ops add 1 or 255, whose bits above 8 the write mask drops. */
typedef struct Avx2StencilOp {
    __m256i and_s, add, lo, hi, flip, wm;
} Avx2StencilOp;

static inline Avx2StencilOp avx2_stencil_op_setup(unsigned int op, uint32_t ref, uint32_t write_mask)
{
    int and_s = 0xFF, add = 0, lo = 0, hi = 0x1FF, flip = 0;
    switch (op) {
    case GL_ZERO: and_s = 0; break;
    case GL_REPLACE: and_s = 0, add = (int)ref; break;
    case GL_INCR: add = 1, hi = 0xFF; break;
    case GL_DECR: add = -1; break;
    case GL_INVERT: flip = 0xFF; break;
    case GL_INCR_WRAP_OES: add = 1; break;
    case GL_DECR_WRAP_OES: add = 0xFF; break;
    default: break; /* GL_KEEP */
    }
    return (Avx2StencilOp){ _mm256_set1_epi32(and_s), _mm256_set1_epi32(add), _mm256_set1_epi32(lo),
                            _mm256_set1_epi32(hi), _mm256_set1_epi32(flip), _mm256_set1_epi32((int)write_mask) };
}

/* the stencil value after op o, of int32 lanes s in 0..255 */
AVX2_INLINE __m256i avx2_stencil_op(const Avx2StencilOp *o, __m256i s)
{
    __m256i v = _mm256_add_epi32(_mm256_and_si256(s, o->and_s), o->add);
    v = _mm256_xor_si256(_mm256_min_epi32(_mm256_max_epi32(v, o->lo), o->hi), o->flip);
    return _mm256_or_si256(_mm256_andnot_si256(o->wm, s), _mm256_and_si256(v, o->wm));
}

/* what the eight-fragment tests need of FragTests, as lanes (the ops only
** where some op can change a stored value) */
typedef struct Avx2Tests {
    Avx2Cmp sfunc;
    __m256i ref, value_mask;            /* ref & value_mask, value_mask */
    const Avx2StencilOp *op;            /* fail, zfail, zpass; NULL without writes */
} Avx2Tests;

/* 1 when some stencil op can change a stored value: an op other than KEEP
** (every other valid op) with a bit written */
static inline int avx2_stencil_writes(const FragTests *ft)
{
    return ft->write_mask != 0 && (ft->fail != GL_KEEP || ft->zfail != GL_KEEP || ft->zpass != GL_KEEP);
}

/* v for the state in ft, with ops[0..2] set and used when writes */
static inline void avx2_tests_setup(const FragTests *ft, int writes, Avx2StencilOp ops[3], Avx2Tests *v)
{
    v->sfunc = avx2_cmp_setup(ft->stencil_func);
    v->ref = _mm256_set1_epi32((int)(ft->ref & ft->value_mask));
    v->value_mask = _mm256_set1_epi32((int)ft->value_mask);
    v->op = NULL;
    if (writes) {
        ops[0] = avx2_stencil_op_setup(ft->fail, ft->ref, ft->write_mask);
        ops[1] = avx2_stencil_op_setup(ft->zfail, ft->ref, ft->write_mask);
        ops[2] = avx2_stencil_op_setup(ft->zpass, ft->ref, ft->write_mask);
        v->op = ops;
    }
}

/* the tests' state of a primitive, kept in the context (ctx->tests_setup)
** for its chunks; v.op points at ops */
typedef struct Avx2TestsSetup {
    FragTests ft;
    int swrite, dwrite;             /* the stencil and depth buffers can change */
    Avx2Tests v;
    Avx2StencilOp ops[3];
} Avx2TestsSetup;

/* fragment_tests of r <= 8 fragments (lanes 0..r-1): stored stencil values
** s[0..r) and depths d[0..r), both updated in place, and window depths
** z[0..r). stencil and depth say which tests are on, swrite and dwrite
** whether their buffers can change; with r < 8 only r lanes are read and
** written. The depth function dfunc and the flags are constants where this
** is inlined. Bit i of the result is 1 when fragment i passes. */
AVX2_INLINE unsigned avx2_tests8(const Avx2Tests *v, uint8_t *s, uint32_t *d, const uint32_t *z, int r,
                                 int stencil, int swrite, int depth, int dwrite, unsigned int dfunc)
{
    const __m256i ones = _mm256_set1_epi32(-1);
    const __m256i lanes = r == 8 ? ones : _mm256_cmpgt_epi32(_mm256_set1_epi32(r), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    __m256i zv = ones, dv = ones, zpass = ones, pass;
    if (depth) {
        if (r == 8) {
            zv = _mm256_loadu_si256((const __m256i *)(const void *)z);
            dv = _mm256_loadu_si256((const __m256i *)(const void *)d);
        } else {
            zv = _mm256_maskload_epi32((const int *)(const void *)z, lanes);
            dv = _mm256_maskload_epi32((const int *)(const void *)d, lanes);
        }
        zpass = avx2_cmp_u32(dfunc, zv, dv);
    }
    pass = zpass;
    if (stencil) {
        uint64_t bytes = 0;
        if (r == 8)
            memcpy(&bytes, s, 8);
        else
            for (int i = 0; i < r; i++)
                bytes |= (uint64_t)s[i] << (8 * i);
        const __m256i sv = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128((long long)bytes));
        const __m256i spass = avx2_cmp_i32(&v->sfunc, v->ref, _mm256_and_si256(sv, v->value_mask));
        pass = _mm256_and_si256(spass, zpass);
        if (swrite && v->op) {
            const __m256i after = _mm256_blendv_epi8(avx2_stencil_op(&v->op[1], sv), avx2_stencil_op(&v->op[2], sv), zpass);
            const __m256i ns = _mm256_blendv_epi8(avx2_stencil_op(&v->op[0], sv), after, spass);
            /* the low byte of each lane, in lane order */
            const __m256i w = _mm256_permute4x64_epi64(_mm256_packus_epi32(ns, ns), 0x08);
            const __m128i b8 = _mm_packus_epi16(_mm256_castsi256_si128(w), _mm256_castsi256_si128(w));
            if (r == 8) {
                _mm_storel_epi64((__m128i *)(void *)s, b8);
            } else {
                const uint64_t out = (uint64_t)_mm_cvtsi128_si64(b8);
                for (int i = 0; i < r; i++)
                    s[i] = (uint8_t)(out >> (8 * i));
            }
        }
    }
    if (dwrite) {
        if (r == 8)
            _mm256_storeu_si256((__m256i *)(void *)d, _mm256_blendv_epi8(dv, zv, pass));
        else
            _mm256_maskstore_epi32((int *)(void *)d, _mm256_and_si256(pass, lanes), zv);
    }
    return (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_and_si256(pass, lanes)));
}

/* the offsets of the set bits of an 8-bit mask, packed from byte 0 (a
** byte shuffle that compacts eight slots) */
#define AVX2_POP8(m) (((m) & 1) + (((m) >> 1) & 1) + (((m) >> 2) & 1) + (((m) >> 3) & 1) + (((m) >> 4) & 1) \
                      + (((m) >> 5) & 1) + (((m) >> 6) & 1) + (((m) >> 7) & 1))
#define AVX2_CBIT(m, i) (((m) >> (i) & 1) ? (uint64_t)(i) << (8 * AVX2_POP8((m) & ((1u << (i)) - 1))) : 0)
#define AVX2_CENTRY(m) (AVX2_CBIT(m, 0) | AVX2_CBIT(m, 1) | AVX2_CBIT(m, 2) | AVX2_CBIT(m, 3) | AVX2_CBIT(m, 4) \
                        | AVX2_CBIT(m, 5) | AVX2_CBIT(m, 6) | AVX2_CBIT(m, 7))
#define AVX2_C4(m) AVX2_CENTRY(m), AVX2_CENTRY((m) + 1), AVX2_CENTRY((m) + 2), AVX2_CENTRY((m) + 3)
#define AVX2_C16(m) AVX2_C4(m), AVX2_C4((m) + 4), AVX2_C4((m) + 8), AVX2_C4((m) + 12)
#define AVX2_C64(m) AVX2_C16(m), AVX2_C16((m) + 16), AVX2_C16((m) + 32), AVX2_C16((m) + 48)
static const uint64_t avx2_compact8[256] = { AVX2_C64(0u), AVX2_C64(64u), AVX2_C64(128u), AVX2_C64(192u) };
#undef AVX2_C64
#undef AVX2_C16
#undef AVX2_C4
#undef AVX2_CENTRY
#undef AVX2_CBIT
#undef AVX2_POP8

/* keep the n offsets k[j] whose bit is set in keep, in order, at the front
** of k (which has room for SPAN_CHUNK); returns how many */
AVX2_INLINE int avx2_compact_offsets(uint8_t *k, int n, const uint64_t keep[SPAN_KEEP_WORDS])
{
    int m = 0, j = 0;
    for (; j + 8 <= n; j += 8) {
        const unsigned bits = (unsigned)(keep[j >> 6] >> (j & 63)) & 0xFFu;
        const __m128i idx = _mm_loadl_epi64((const __m128i *)(const void *)&avx2_compact8[bits]);
        const __m128i src = _mm_loadl_epi64((const __m128i *)(const void *)(k + j));
        /* m <= j: the eight bytes stored stay within the slots read so far */
        _mm_storel_epi64((__m128i *)(void *)(k + m), _mm_shuffle_epi8(src, idx));
        m += __builtin_popcount(bits);
    }
    for (; j < n; j++)
        if ((keep[j >> 6] >> (j & 63)) & 1)
            k[m++] = k[j];
    return m;
}
/* }==================================================================== */
#endif

/* {====================================================================
** Fog factors, the alpha test's comparisons and RGBA8888 logic ops for
** several fragments at a time (span_stages.h: stage_fog, stage_alpha) */
#if SIMD_X86 && NUM_IS_FIXED
/* frag_clamp01(frag_lerp3(a[0], a[1], a[2], p[k][0..2])) for the four
** fragments k (lanes): with |a[i]| <= 2^30 (the caller checks) each
** product is below 2^61 and their sum below 2^63, so the 64-bit sum is
** the scalar code's, and avx2_round_shift rounds it as frag_lerp3 does
** (half away from zero, 16 bits) */
AVX2_INLINE __m256i avx2_fog4(const NUM a[3], const WGT (*p)[3])
{
    __m256i w[3];
    avx2_wgt_lanes4(p, w);
    return avx2_clamp01(avx2_round_shift(avx2_dot3_lanes(a[0], a[1], a[2], w), 16));
}

/* the fog colour's channels fc[0..2], each as the lanes of a register */
AVX2_INLINE void avx2_fog_color_lanes(const FRAGV fc[3], __m256i fcv[3])
{
    for (int i = 0; i < 3; i++)
        fcv[i] = _mm256_set1_epi64x(fc[i]);
}

/* fragment_fog of four fragments c[0..3] with factors f (lanes, each in
** [0, 2^30]) and the fog colour's channels as lanes fcv[0..2] (each in
** [0, 2^31)): the colours transposed to one register per channel, then
** frag_mul(f, frag_clamp01(c)) + frag_mul(1 - f, fc) per channel, whose
** operands are in [0, 2^31) (avx2_mul_u is frag_mul there), as one
** register per channel ch[0..3] (the alphas as they were) */
AVX2_INLINE void avx2_fog_channels4(const FRAGV (*c)[4], __m256i f, const __m256i fcv[3], __m256i ch[4])
{
    const __m256i c0 = avx2_load4(c[0]), c1 = avx2_load4(c[1]), c2 = avx2_load4(c[2]), c3 = avx2_load4(c[3]);
    const __m256i t0 = _mm256_unpacklo_epi64(c0, c1), t1 = _mm256_unpackhi_epi64(c0, c1);   /* r0 r1 b0 b1, g0 g1 a0 a1 */
    const __m256i t2 = _mm256_unpacklo_epi64(c2, c3), t3 = _mm256_unpackhi_epi64(c2, c3);
    ch[0] = _mm256_permute2x128_si256(t0, t2, 0x20);
    ch[1] = _mm256_permute2x128_si256(t1, t3, 0x20);
    ch[2] = _mm256_permute2x128_si256(t0, t2, 0x31);
    ch[3] = _mm256_permute2x128_si256(t1, t3, 0x31);
    const __m256i g = _mm256_sub_epi64(_mm256_set1_epi64x(FRAG_ONE), f);
    for (int i = 0; i < 3; i++)
        ch[i] = _mm256_add_epi64(avx2_mul_u(f, avx2_clamp01(ch[i])), avx2_mul_u(g, fcv[i]));
}

/* avx2_fog_channels4, stored back as the colours */
AVX2_INLINE void avx2_fog_mix4(FRAGV (*c)[4], __m256i f, const __m256i fcv[3])
{
    __m256i ch[4];
    avx2_fog_channels4((const FRAGV (*)[4])c, f, fcv, ch);
    avx2_store_transposed4(ch[0], ch[1], ch[2], ch[3], c[0], 4);
}

/* avx2_fog_mix4 of four fragments c[0..3] and write_rgba8's kind 0 of
** the result in the same pass (fx512_fog_write_rgba8's operations lane by
** lane): each channel (the fogged colour, and the alpha as it is) clamped
** to [0, 2^30] and turned to a byte, (255 v + 2^29) >> 30, the four bytes
** packed into the words dst[k[0..3]] (one store for four neighbouring
** pixels); the colours are not stored back */
AVX2_INLINE void avx2_fog_write_rgba8x4(const FRAGV (*c)[4], __m256i f, const __m256i fcv[3], uint32_t *dst,
                                        const uint8_t *k)
{
    __m256i ch[4], word = _mm256_setzero_si256();
    avx2_fog_channels4(c, f, fcv, ch);
    for (int i = 0; i < 4; i++) {
        const __m256i byte = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(avx2_clamp01(ch[i]), _mm256_set1_epi64x(255)),
                                                                _mm256_set1_epi64x((int64_t)1 << 29)), 30);
        word = _mm256_or_si256(word, _mm256_slli_epi64(byte, 8 * i));
    }
    const __m128i w = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(word, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
    if (k[3] == k[0] + 3) {
        _mm_storeu_si128((__m128i *)(void *)&dst[k[0]], w);
    } else {
        dst[k[0]] = (uint32_t)_mm_cvtsi128_si32(w);
        dst[k[1]] = (uint32_t)_mm_extract_epi32(w, 1);
        dst[k[2]] = (uint32_t)_mm_extract_epi32(w, 2);
        dst[k[3]] = (uint32_t)_mm_extract_epi32(w, 3);
    }
}

/* avx2_fog_channels4 of four fragments c[0..3] and stage_write_565's
** pack565 of the result in the same pass (fx512_fog_write_565's
** operations lane by lane): red, green and blue taken to 5, 6 and 5 bits,
** dithered by the threshold t_row[(x0 + k[j]) & 3] as (min(max(v, 0),
** 2^30) top + t) >> 30, or without dither as min(max(v, 0) >> (30 - bits),
** top); the three packed into the words dst[k[0..3]] (one store for four
** neighbouring pixels); the colours are not stored back */
AVX2_INLINE void avx2_fog_write_565x4(const FRAGV (*c)[4], __m256i f, const __m256i fcv[3], uint16_t *dst,
                                      const uint8_t *k, int x0, int dither, const FRAGV t_row[4])
{
    __m256i ch[4], word = _mm256_setzero_si256(), t = _mm256_setzero_si256();
    avx2_fog_channels4(c, f, fcv, ch);
    if (dither) {
        /* each lane's threshold: the dwords 2 d and 2 d + 1 of the row's four, d = (x0 + k) & 3 */
        uint32_t k4;
        memcpy(&k4, k, sizeof k4);
        const __m256i d = _mm256_slli_epi64(_mm256_and_si256(_mm256_add_epi64(_mm256_cvtepu8_epi64(_mm_cvtsi32_si128((int)k4)),
                                                                               _mm256_set1_epi64x(x0)),
                                                              _mm256_set1_epi64x(3)), 1);
        const __m256i pick = _mm256_or_si256(d, _mm256_slli_epi64(_mm256_add_epi64(d, _mm256_set1_epi64x(1)), 32));
        t = _mm256_permutevar8x32_epi32(_mm256_loadu_si256((const __m256i *)(const void *)t_row), pick);
    }
    const int bits[3] = { 5, 6, 5 }, shift[3] = { 11, 5, 0 };
    for (int i = 0; i < 3; i++) {
        const __m256i top = _mm256_set1_epi64x((1 << bits[i]) - 1), one = _mm256_set1_epi64x(FRAG_ONE);
        const __m256i v = _mm256_andnot_si256(_mm256_cmpgt_epi64(_mm256_setzero_si256(), ch[i]), ch[i]);
        __m256i r;
        if (dither) {
            r = _mm256_mul_epu32(_mm256_blendv_epi8(v, one, _mm256_cmpgt_epi64(v, one)), top);
            r = _mm256_srli_epi64(_mm256_add_epi64(r, t), 30);
        } else {
            r = _mm256_srli_epi64(v, 30 - bits[i]);
            r = _mm256_blendv_epi8(r, top, _mm256_cmpgt_epi64(r, top));
        }
        word = _mm256_or_si256(word, _mm256_slli_epi64(r, shift[i]));
    }
    const __m128i w32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(word, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
    const __m128i w = _mm_packus_epi32(w32, w32);
    if (k[3] == k[0] + 3) {
        _mm_storel_epi64((__m128i *)(void *)&dst[k[0]], w);
    } else {
        dst[k[0]] = (uint16_t)_mm_extract_epi16(w, 0);
        dst[k[1]] = (uint16_t)_mm_extract_epi16(w, 1);
        dst[k[2]] = (uint16_t)_mm_extract_epi16(w, 2);
        dst[k[3]] = (uint16_t)_mm_extract_epi16(w, 3);
    }
}

/* fragment_alpha8 of the alphas of four fragments' colours c0..c3, as
** int32 lanes: after frag_clamp01 the alpha v lies in [0, 2^30], where
** (v 255 + 2^29) >> 30 is frag_to_unorm's value (0 for v <= 0, 255 for
** v >= 2^30) and v fits vpmuludq's 32 bits */
AVX2_INLINE __m128i v4_alpha8x4(V4 c0, V4 c1, V4 c2, V4 c3)
{
    /* g0 g1 a0 a1 and g2 g3 a2 a3, then the alphas */
    const __m256i x01 = _mm256_unpackhi_epi64(c0, c1), x23 = _mm256_unpackhi_epi64(c2, c3);
    const __m256i a = avx2_clamp01(_mm256_permute2x128_si256(x01, x23, 0x31));
    const __m256i u = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(a, _mm256_set1_epi64x(255)),
                                                         _mm256_set1_epi64x((int64_t)1 << 29)), 30);
    return avx2_low32(u);
}
#endif

#if SIMD_X86 && !NUM_IS_FIXED
/* frag_lerp3(a[0], a[1], a[2], p[k][0..2]) for the four fragments k
** (lanes): the same products and sums, in the scalar code's order */
AVX2_INLINE V4 v4_lerp3x4(const NUM a[3], const WGT (*p)[3])
{
    V4 acc = V4_OP(mul)(V4_OP(set1)(a[0]), V4_OP(setr)(p[0][0], p[1][0], p[2][0], p[3][0]));
    acc = V4_OP(add)(acc, V4_OP(mul)(V4_OP(set1)(a[1]), V4_OP(setr)(p[0][1], p[1][1], p[2][1], p[3][1])));
    return V4_OP(add)(acc, V4_OP(mul)(V4_OP(set1)(a[2]), V4_OP(setr)(p[0][2], p[1][2], p[2][2], p[3][2])));
}

/* fragment_alpha8 of the alphas of four fragments' colours c0..c3, as
** int32 lanes: frag_to_unorm's operations (0 unless v > 0, so NaN gives 0;
** 255 from 1 up; else v 255 + 1/2 truncated) */
AVX2_INLINE __m128i v4_alpha8x4(V4 c0, V4 c1, V4 c2, V4 c3)
{
#if defined(GLES_NUM_FLOAT)
    /* b0 b1 a0 a1 and b2 b3 a2 a3, then the alphas */
    const V4 v = _mm_movehl_ps(_mm_unpackhi_ps(c2, c3), _mm_unpackhi_ps(c0, c1));
#else
    /* g0 g1 a0 a1 and g2 g3 a2 a3, then the alphas */
    const V4 v = _mm256_permute2f128_pd(_mm256_unpackhi_pd(c0, c1), _mm256_unpackhi_pd(c2, c3), 0x31);
#endif
    return v4_to_unorm8(v);
}
#endif

#if SIMD_X86
/* fragment_compare(func, a, b) of four int32 lanes (the alpha test's
** values, 0..255) as four bits, for a func known where this is inlined */
AVX2_INLINE unsigned avx2_cmp4_i32(unsigned int func, __m128i a, __m128i b)
{
    __m128i m;
    switch (func) {
    case GL_NEVER: return 0;
    case GL_LESS: m = _mm_cmplt_epi32(a, b); break;
    case GL_EQUAL: m = _mm_cmpeq_epi32(a, b); break;
    case GL_LEQUAL: return 0xFu & ~(unsigned)_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(a, b)));
    case GL_GREATER: m = _mm_cmpgt_epi32(a, b); break;
    case GL_NOTEQUAL: return 0xFu & ~(unsigned)_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(a, b)));
    case GL_GEQUAL: return 0xFu & ~(unsigned)_mm_movemask_ps(_mm_castsi128_ps(_mm_cmplt_epi32(a, b)));
    default: return 0xF;
    }
    return (unsigned)_mm_movemask_ps(_mm_castsi128_ps(m));
}
#endif
/* }==================================================================== */
#if SIMD_X86
/* eight fragments' channel values (0..255 in 32-bit lanes, one register
** per channel) as eight RGBA8888 words: packed to bytes R0-3 G0-3 B0-3
** A0-3 | R4-7 ... per 128-bit lane, then interleaved */
AVX2_INLINE __m256i avx2_pack_rgba8x8(const __m256i v[4])
{
    const __m256i b8 = _mm256_packus_epi16(_mm256_packus_epi32(v[0], v[1]), _mm256_packus_epi32(v[2], v[3]));
    return _mm256_shuffle_epi8(b8, _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 0, 4, 8, 12,
                                                    1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
}

/* the alpha test of the fused stages: on (any function but ALWAYS), its
** function and 8-bit reference (fragment_alpha_ref8), and both as lanes */
typedef struct ModWriteAlpha {
    int test;
    unsigned int func;
    uint32_t ref;
    Avx2Cmp cmp;
    __m256i ref_v;
} ModWriteAlpha;

static inline void modwrite_alpha_setup(ModWriteAlpha *t, unsigned int func, uint32_t ref)
{
    t->test = func != GL_ALWAYS;
    t->func = func;
    t->ref = ref;
    t->cmp = avx2_cmp_setup(func);
    t->ref_v = _mm256_set1_epi32((int)ref);
}

/* pads fragments 0..n-1 (offsets k, weights p when smooth, coordinates tc
** and texels ct + j stride where given) to a whole group of `group` with
** copies of the last one, in the free slots past n; returns the padded
** count. A copy computes the last fragment's values again; in a writer,
** its word from the same stored word, in the same group, so writing it
** writes that word again. */
static inline int avx2_pad_group(int group, int n, uint8_t *k, WGT (*p)[3], int smooth, TexCoord *tc, FRAGV *ct,
                                 size_t stride)
{
    /* each copy from the last live slot, not the slot just written: no
    ** store waits for the one before it */
    const int last = n - 1;
    for (; n % group; n++) {
        k[n] = k[last];
        if (smooth)
            memcpy(p[n], p[last], sizeof p[n]);
        if (tc)
            tc[n] = tc[last];
        if (ct)
            memcpy(ct + (size_t)n * stride, ct + (size_t)last * stride, 4 * sizeof *ct);
    }
    return n;
}

/* the texture where a fused stage samples it: level 0, GL_LINEAR,
** power-of-two sizes and REPEAT or CLAMP_TO_EDGE on each axis
** (texture_span_sample_group > 1), and the span sampler that gives the
** exact texel of a fragment the lanes leave */
typedef struct ModWriteTexture {
#if NUM_IS_FIXED
    Avx2Axis ax_s, ax_t;        /* level 0's axes (the fixed build's avx2_linear_texels8c) */
#endif
    const Texture *tex;
    TexSpanSampler sampler;
    const FRAGV *unorm8;
    const uint32_t *texels;
    int w, h, log2w, log2h, repeat_s, repeat_t;
} ModWriteTexture;

/* whether a fused stage's kernel takes a chunk's last partial group of n
** fragments as their last `group` again, so that a lane written twice
** writes the same word: where there are that many and nothing reads the
** stored words (RGBA8888, blend kind 0, no alpha test); else the chunk is
** padded to whole groups */
AVX2_INLINE int modwrite_overlaps(int kind, int alpha_test, int rgb565, int n, int group)
{
    return n >= group && !rgb565 && !kind && !alpha_test;
}

static inline void modwrite_texture_setup(ModWriteTexture *m, const Texture *t, TexSpanSampler sampler,
                                          const FRAGV *unorm8)
{
    const TexImage *l0 = &t->level[0];
    m->tex = t;
    m->sampler = sampler;
    m->unorm8 = unorm8;
    m->texels = l0->texels;
    m->w = l0->width;
    m->h = l0->height;
    m->log2w = __builtin_ctz((unsigned)l0->width);
    m->log2h = __builtin_ctz((unsigned)l0->height);
#if NUM_IS_FIXED
    avx2_axis_setup(m->log2w, &m->ax_s);
    avx2_axis_setup(m->log2h, &m->ax_t);
#endif
    m->repeat_s = t->wrap_s == GL_REPEAT;
    m->repeat_t = t->wrap_t == GL_REPEAT;
}
#endif

#if SIMD_X86 && (NUM_IS_FIXED || defined(GLES_NUM_DOUBLE))
/* {====================================================================
** The colour, the first unit's MODULATE, the alpha test and the RGBA8888
** write (blend kind 0, 1 or 2 as write_rgba8) of eight fragments in float lanes, with
** a filter that proves each byte equal to the exact chain's (the 0.30
** integers of stage_color_modulate and v4_rgba8 in the fixed build, their
** doubles in the double build's AVX2 instance):
**
** The exact chain ends in byte = floor(255 Y + 1/2) of a value Y that
** float lanes approximate: Y_f with |Y_f - Y| <= 27 u (u = 2^-24; 49 u
** in the double build; the bounds, from the colours, weights and texels'
** ranges, are derived in docs/architecture.md). When 255 Y_f + 1/2 lies
** at least the state's margin (avx2_modwrite_margin: above 255 times the
** bound plus the rounding of that sum) from the nearest integer, 255 Y +
** 1/2 has the same floor. A lane nearer than that (0.1-0.4% of channels), or whose
** weights' magnitudes sum to more than 1 + 2^-7, gets the exact chain's
** bytes instead. */

#if NUM_IS_FIXED
/* the low dwords of four fragments' channels c + k stride (k = 0..3) as
** (R0..R3 | B0..B3) and (G0..G3 | A0..A3); *any collects the lanes' bits */
AVX2_INLINE void avx2_channels4(const FRAGV *c, size_t stride, __m256 *rb, __m256 *ga, __m256i *any)
{
    const __m256i f0 = avx2_load4(c), f1 = avx2_load4(c + stride);
    const __m256i f2 = avx2_load4(c + 2 * stride), f3 = avx2_load4(c + 3 * stride);
    *any = _mm256_or_si256(*any, _mm256_or_si256(_mm256_or_si256(f0, f1), _mm256_or_si256(f2, f3)));
    const __m256 s01 = _mm256_shuffle_ps(_mm256_castsi256_ps(f0), _mm256_castsi256_ps(f1), _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 s23 = _mm256_shuffle_ps(_mm256_castsi256_ps(f2), _mm256_castsi256_ps(f3), _MM_SHUFFLE(2, 0, 2, 0));
    *rb = _mm256_shuffle_ps(s01, s23, _MM_SHUFFLE(2, 0, 2, 0));
    *ga = _mm256_shuffle_ps(s01, s23, _MM_SHUFFLE(3, 1, 3, 1));
}

/* eight fragments' texels c + k stride (k = 0..7), channel i as the
** integer lanes of ch[i]; 0 unless every channel lies in [0, 2^31) */
AVX2_INLINE int avx2_channels8(const FRAGV *c, size_t stride, __m256i ch[4])
{
    __m256 rb0, ga0, rb1, ga1;
    __m256i any = _mm256_setzero_si256();
    avx2_channels4(c, stride, &rb0, &ga0, &any);
    avx2_channels4(c + 4 * stride, stride, &rb1, &ga1, &any);
    ch[0] = _mm256_castps_si256(_mm256_permute2f128_ps(rb0, rb1, 0x20));
    ch[1] = _mm256_castps_si256(_mm256_permute2f128_ps(ga0, ga1, 0x20));
    ch[2] = _mm256_castps_si256(_mm256_permute2f128_ps(rb0, rb1, 0x31));
    ch[3] = _mm256_castps_si256(_mm256_permute2f128_ps(ga0, ga1, 0x31));
    return _mm256_testz_si256(any, _mm256_set1_epi64x(~(int64_t)0x7FFFFFFF));
}
#endif

/* a first unit's COMBINE DOT3 (DOT3_RGB with MODULATE alpha, or rgba:
** DOT3_RGBA; scales 1) of its texels and the colour, before the MODULATE:
** the texels at ct0 + j ct0_stride, or (tc0 not NULL) sampled in the
** kernel at tc0[j] from tx0 */
typedef struct ModWriteDot3 {
    int rgba;
    const FRAGV *ct0;
    size_t ct0_stride;
    const TexCoord *tc0;
    ModWriteTexture tx0;
} ModWriteDot3;

/* the chain's constants: the vertex colours' channels times 2^-60 (so
** that a weight's integer times them is the term's value), or the flat
** colour's (clamped) times 2^-30 in col[0] (the double build's as they
** are, its weights being numbers); the alpha test; for RGB565 the dither
** thresholds of the row's x & 3 */
#if NUM_IS_FIXED
#define MODWRITE_FRAG_SCALE 0x1p-30     /* a FRAGV's value per unit */
#define MODWRITE_COL_SCALE(smooth) ((smooth) ? 0x1p-60 : MODWRITE_FRAG_SCALE)
#else
#define MODWRITE_COL_SCALE(smooth) 1.0
#define MODWRITE_FRAG_SCALE 1.0
#endif
typedef struct Avx2ModWrite {
    __m256 col[3][4];
    __m256 col_half[3][4];       /* the same less 1/2 (DOT3's operand; rgb) */
    int smooth, rgb, kind;
    ModWriteAlpha alpha;         /* the alpha test */
    int dither;
    FRAGV t_row[4];              /* 0.30 (1/2 without dither) */
    __m256 t_row_f;              /* t_row twice, as floats (0 without dither: the top bits are kept) */
    int replace;                 /* the texel is the colour (a lone REPLACE unit of an RGBA texture) */
    ModWriteTexture tx;          /* where the kernel samples (avx2_modwrite_run's source 1) */
    const ModWriteDot3 *dot3;    /* a first unit's DOT3 before the MODULATE, or NULL */
    /* the fused stage's choices for the primitive (span_stages.h): its
    ** units, whether it samples the first one, the colours and the DOT3
    ** (dot3 points here; its ct0 and tc0 are a chunk's) */
    int u0, u, sampled0;
    const FRAGV *a[3];
    ModWriteDot3 d3;
} Avx2ModWrite;

/* setup for vertex colours a[0..2] in [0, 2^30] (smooth), or the flat
** colour a[0] (any value: it is clamped, as stage_color_modulate does);
** the alpha test's function (GL_ALWAYS when it is off) and 8-bit reference */
static inline void avx2_modwrite_setup(Avx2ModWrite *m, const FRAGV *const a[3], int smooth, int rgb, int kind,
                                       unsigned int alpha_func, uint32_t alpha_ref)
{
    m->smooth = smooth, m->rgb = rgb, m->kind = kind;
    modwrite_alpha_setup(&m->alpha, alpha_func, alpha_ref);
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 4; c++) {
            const FRAGV v = smooth ? a[i][c] : frag_clamp01(a[0][c]);
            m->col[i][c] = _mm256_set1_ps((float)((double)v * MODWRITE_COL_SCALE(smooth)));
            m->col_half[i][c] = _mm256_set1_ps((float)((double)(v - FRAG_ONE / 2) * MODWRITE_COL_SCALE(smooth)));
        }
    m->dither = 0;
    m->replace = 0;
    m->tx.tex = NULL;
    m->dot3 = NULL;
}

/* the texel as the colour (REPLACE) instead of MODULATE */
static inline void avx2_modwrite_replace(Avx2ModWrite *m) { m->replace = 1, m->rgb = 0; }

/* the RGB565 writer's thresholds t_row[x & 3] (dither_row's) */
static inline void avx2_modwrite_dither(Avx2ModWrite *m, int dither, const FRAGV t_row[4])
{
    m->dither = dither;
    float f[4];
    for (int x = 0; x < 4; x++) {
        m->t_row[x] = t_row[x];
        f[x] = dither ? (float)((double)t_row[x] * MODWRITE_FRAG_SCALE) : 0.0f;
    }
    m->t_row_f = _mm256_setr_ps(f[0], f[1], f[2], f[3], f[0], f[1], f[2], f[3]);
}

/* how near an integer a lane's value may lie and still be proved: above
** the largest bound of the state's values (docs/architecture.md, in u =
** 2^-24 of a byte, an RGB565 step or the alpha test's byte) with room to
** spare. DOT3: SRC_ALPHA at most 19800u, under 2^-9 = 32768u, no blend
** and ONE / ONE 11300u under 2^-10 = 16384u; else SRC_ALPHA 9564u under
** 2^-10, no blend and ONE / ONE 3622u under 2^-11 = 8192u. A smaller
** margin leaves fewer lanes to the exact code (each margin's share of the
** values that lie that near) */
AVX2_INLINE float avx2_modwrite_margin(int kind, int dot3)
{
#if !NUM_IS_FIXED
    /* the double build's DOT3 with texels sampled in the kernel (8.1u
    ** each): no blend and ONE / ONE at most 22000u, under 2^-9 = 32768u;
    ** SRC_ALPHA 35000u, under 2^-8 (docs/architecture.md) */
    if (dot3)
        return kind == 1 ? 0x1p-8f : 0x1p-9f;
#endif
    return dot3 ? (kind == 1 ? 0x1p-9f : 0x1p-10f) : kind == 1 ? 0x1p-10f : 0x1p-11f;
}

/* floor(z) of lanes z >= 0, and in *bad the lanes where z lies within
** `margin` of an integer (where the exact value's floor may differ) */
AVX2_INLINE __m256i avx2_floor_proved(__m256 z, float margin, __m256 *bad)
{
    const __m256 fl = _mm256_floor_ps(z), f = _mm256_sub_ps(z, fl);
    *bad = _mm256_or_ps(*bad, _mm256_or_ps(_mm256_cmp_ps(f, _mm256_set1_ps(margin), _CMP_LT_OQ),
                                           _mm256_cmp_ps(f, _mm256_set1_ps(1.0f - margin), _CMP_GT_OQ)));
    return _mm256_cvttps_epi32(fl);
}

/* the same where the exact value is known to be >= 0 and its floor is
** clamped to `top`: an integer q nearby matters only for 1 <= q <= top
** (both neighbouring floors give 0, or both clamp to top, elsewhere) */
AVX2_INLINE __m256i avx2_floor_proved_upto(__m256 z, float top, float margin, __m256 *bad)
{
    __m256 near = _mm256_setzero_ps();
    const __m256i q = avx2_floor_proved(z, margin, &near);
    near = _mm256_and_ps(near, _mm256_and_ps(_mm256_cmp_ps(z, _mm256_set1_ps(0.5f), _CMP_GT_OQ),
                                             _mm256_cmp_ps(z, _mm256_set1_ps(top + 0.5f), _CMP_LT_OQ)));
    *bad = _mm256_or_ps(*bad, near);
    return q;
}

/* the two rows' bilinear sums of byte i of the texel words g (g[0..3]:
** c00, c10, c01, c11, exact integers as floats) at weights a and ia (the
** other): h0 = c00 ia + c10 a and h1 = c01 ia + c11 a */
AVX2_INLINE void avx2_bilerp8_rows(const __m256i g[4], int i, __m256 a, __m256 ia, __m256 *h0, __m256 *h1)
{
    const __m256i pick = avx2_byte_pick8(i);
    __m256 c[4];
    for (int q = 0; q < 4; q++)
        c[q] = _mm256_cvtepi32_ps(_mm256_shuffle_epi8(g[q], pick));
    *h0 = _mm256_fmadd_ps(c[0], ia, _mm256_mul_ps(c[1], a));
    *h1 = _mm256_fmadd_ps(c[2], ia, _mm256_mul_ps(c[3], a));
}

#if NUM_IS_FIXED
/* the three weights of fragments p[0..7] as float lanes: their 0.30
** integers (the colours carry the scale, 2^-60) */
AVX2_INLINE void avx2_wgt_float8(const WGT (*p)[3], __m256 *w0, __m256 *w1, __m256 *w2)
{
    __m256i wi[3];
    avx2_wgt_lanes8(p, wi);
    *w0 = _mm256_cvtepi32_ps(wi[0]), *w1 = _mm256_cvtepi32_ps(wi[1]), *w2 = _mm256_cvtepi32_ps(wi[2]);
}

/* eight fragments' texels ct + k stride (0.30) as floats T[0..3] (exact
** but for the conversion's rounding), with half_rgb T[0..2] less 1/2 (the
** integer less 2^29, then converted); 0 when a texel leaves [0, 2^31) */
AVX2_INLINE int avx2_texels_ct8(const FRAGV *ct, size_t stride, int half_rgb, __m256 T[4])
{
    __m256i ch[4];
    if (!avx2_channels8(ct, stride, ch))
        return 0;
    for (int i = 0; i < 4; i++) {
        const __m256i v = half_rgb && i < 3 ? _mm256_sub_epi32(ch[i], _mm256_set1_epi32(1 << 29)) : ch[i];
        T[i] = _mm256_mul_ps(_mm256_cvtepi32_ps(v), _mm256_set1_ps(0x1p-30f));
    }
    return 1;
}

/* the bilinear texels of avx2_linear_texels8's words g and weights a, b as
** floats T[0..3]: h0 = c00 (2^16 - a) + c10 a and h1 (integers below 2^24,
** exact in float), then (h0 (2^16 - b) + h1 b) / (255 2^32) with the
** factors' (2^16 - b) / (255 2^32) and b / (255 2^32) rounded: within 4u of
** the value, and within 4.02u of frag_bilerp_rgba8's 0.30 texel. With
** half_rgb, T[0..2] are the texel less 1/2 (DOT3's operand): h0' = 2 h0 -
** 255 2^16 (exact: |h0'| <= 255 2^16) and h1' over twice that divisor,
** within 2u of the value (it is at most 1/2), 2.01u of the 0.30 texel's. */
AVX2_INLINE void avx2_bilerp8_float(const __m256i g[4], __m256i a, __m256i b, int half_rgb, __m256 T[4])
{
    const __m256i one16 = _mm256_set1_epi32(65536);
    const __m256 af = _mm256_cvtepi32_ps(a), iaf = _mm256_cvtepi32_ps(_mm256_sub_epi32(one16, a));
    const __m256 k = _mm256_set1_ps((float)(1.0 / (255.0 * 4294967296.0)));
    const __m256 bk = _mm256_mul_ps(_mm256_cvtepi32_ps(b), k);
    const __m256 ibk = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_sub_epi32(one16, b)), k);
    /* (half_rgb's factors over twice the divisor: exact halvings) */
    const __m256 ibk_half = _mm256_mul_ps(ibk, _mm256_set1_ps(0.5f)), bk_half = _mm256_mul_ps(bk, _mm256_set1_ps(0.5f));
    for (int i = 0; i < 4; i++) {
        __m256 h0, h1;
        avx2_bilerp8_rows(g, i, af, iaf, &h0, &h1);
        if (half_rgb && i < 3) {
            const __m256 two = _mm256_set1_ps(2.0f), mid = _mm256_set1_ps(-255.0f * 65536.0f);
            T[i] = _mm256_fmadd_ps(_mm256_fmadd_ps(h0, two, mid), ibk_half,
                                   _mm256_mul_ps(_mm256_fmadd_ps(h1, two, mid), bk_half));
        } else {
            T[i] = _mm256_fmadd_ps(h0, ibk, _mm256_mul_ps(h1, bk));
        }
    }
}

#else
/* the double build's weights of fragments p[0..7] as float lanes, each
** rounded once */
AVX2_INLINE void avx2_wgt_float8(const WGT (*p)[3], __m256 *w0, __m256 *w1, __m256 *w2)
{
    const double *d = &p[0][0];
    __m256i q[3];
    for (int i = 0; i < 3; i++)
        q[i] = _mm256_castps_si256(_mm256_set_m128(_mm256_cvtpd_ps(_mm256_loadu_pd(d + 8 * i + 4)),
                                                   _mm256_cvtpd_ps(_mm256_loadu_pd(d + 8 * i))));
    __m256i w[3];
    avx2_deinterleave3x8(q[0], q[1], q[2], w);
    *w0 = _mm256_castsi256_ps(w[0]), *w1 = _mm256_castsi256_ps(w[1]), *w2 = _mm256_castsi256_ps(w[2]);
}

/* eight fragments' texels ct + k stride (doubles) as floats T[0..3], each
** rounded once; with half_rgb T[0..2] less 1/2 (DOT3's operand: the
** double difference, exact from 1/4 up, then rounded once); 0 unless
** every texel lies in [0, 1] (the bounds' range; NaN fails) */
AVX2_INLINE int avx2_texels_ct8(const FRAGV *ct, size_t stride, int half_rgb, __m256 T[4])
{
    const float h = half_rgb ? 0.5f : 0.0f;
    const __m256d shift = _mm256_setr_pd(h, h, h, 0);
    __m128 f[8];
    for (int k = 0; k < 8; k++)
        f[k] = _mm256_cvtpd_ps(_mm256_sub_pd(_mm256_loadu_pd(ct + (size_t)k * stride), shift));
    _MM_TRANSPOSE4_PS(f[0], f[1], f[2], f[3]);
    _MM_TRANSPOSE4_PS(f[4], f[5], f[6], f[7]);
    __m256 in = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
    for (int i = 0; i < 4; i++) {
        const float lo = i < 3 ? -h : 0.0f;
        T[i] = _mm256_set_m128(f[4 + i], f[i]);
        in = _mm256_and_ps(in, _mm256_and_ps(_mm256_cmp_ps(T[i], _mm256_set1_ps(lo), _CMP_GE_OQ),
                                             _mm256_cmp_ps(T[i], _mm256_set1_ps(1.0f + lo), _CMP_LE_OQ)));
    }
    return _mm256_movemask_ps(in) == 0xFF;
}

/* the bilinear texels of v4_linear_lanes8's words g and weights a, b (the
** exact sampler's, in double lanes) as floats T[0..3]: each of a, 1 - a,
** b and 1 - b rounded to float once; the bilinear sum of the texels' bytes
** (exact integers) h0 = c00 (1 - a) + c10 a, h1 = c01 (1 - a) + c11 a,
** then h0 (1 - b) / 255 + h1 b / 255 with the factors' (1 - b) / 255 and
** b / 255 rounded: within 8.1u of the exact sampler's texel
** (docs/architecture.md); with half_rgb T[0..2] less 1/2 in float (DOT3's
** operand) */
AVX2_INLINE void v4_bilerp8_float(const __m256i g[4], const V4 a[2], const V4 b[2], int half_rgb, __m256 T[4])
{
    const V4 one = V4_OP(set1)(1);
#define TEXELS_F8(v) _mm256_set_m128(_mm256_cvtpd_ps((v)[1]), _mm256_cvtpd_ps((v)[0]))
    const V4 ia[2] = { V4_OP(sub)(one, a[0]), V4_OP(sub)(one, a[1]) };
    const V4 ib[2] = { V4_OP(sub)(one, b[0]), V4_OP(sub)(one, b[1]) };
    const __m256 af = TEXELS_F8(a), iaf = TEXELS_F8(ia), k = _mm256_set1_ps((float)(1.0 / 255.0));
    const __m256 bk = _mm256_mul_ps(TEXELS_F8(b), k), ibk = _mm256_mul_ps(TEXELS_F8(ib), k);
#undef TEXELS_F8
    for (int i = 0; i < 4; i++) {
        __m256 h0, h1;
        avx2_bilerp8_rows(g, i, af, iaf, &h0, &h1);
        T[i] = _mm256_fmadd_ps(h0, ibk, _mm256_mul_ps(h1, bk));
        if (half_rgb && i < 3)
            T[i] = _mm256_sub_ps(T[i], _mm256_set1_ps(0.5f));
    }
}

/* sample_level's GL_LINEAR texel of the double build at the coordinates
** tc[0..7] on level 0 of tx, in float lanes (v4_bilerp8_float, the texel
** indices and weights in v4_linear_axis's double lanes, as the exact
** sampler has them); 0 when a coordinate is not finite */
AVX2_INLINE int avx2_texels_sampled8(const ModWriteTexture *tx, const TexCoord *tc, int half_rgb, __m256 T[4])
{
    /* (each half tested before the next half's loads: as v4_coords8, the
    ** kernel took 0.7% more instructions on combine_dot3, measured) */
    V4 s[2], t[2], a[2], b[2];
    for (int q = 0; q < 2; q++) {
        s[q] = v4_coord4(&tc[4 * q], 0);
        t[q] = v4_coord4(&tc[4 * q], 1);
        if (!(v4_finite(s[q]) && v4_finite(t[q])))
            return 0;
    }
    __m256i g[4];
    v4_linear_lanes8(tx->texels, tx->w, tx->h, s, t, tx->repeat_s, tx->repeat_t, 1, a, b, g);
    v4_bilerp8_float(g, a, b, half_rgb, T);
    return 1;
}
#endif

/* the three weights of fragments p[0..7] as float lanes (avx2_wgt_float8),
** and in *bad the lanes whose magnitudes sum past 1 + 2^-7 (or NaN): the
** fused kernels' bounds take weights of points near the triangle */
AVX2_INLINE void avx2_wgt_float8_near(const WGT (*p)[3], __m256 *w0, __m256 *w1, __m256 *w2, __m256 *bad)
{
    avx2_wgt_float8(p, w0, w1, w2);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    const __m256 mag = _mm256_add_ps(_mm256_add_ps(_mm256_andnot_ps(sign, *w0), _mm256_andnot_ps(sign, *w1)),
                                     _mm256_andnot_ps(sign, *w2));
    /* (not below: larger, or NaN) */
    *bad = _mm256_cmp_ps(mag, _mm256_set1_ps((float)(0x1.02p0 * (double)WGT_ONE)), _CMP_NLE_UQ);
}

/* eight RGBA8888 words of values y[0..3] in [0, 1]: each byte floor(255 y
** + 1/2), and in *bad the lanes where one lies within `margin` of a
** rounding point */
AVX2_INLINE __m256i avx2_rgba8_proved8(const __m256 y[4], float margin, __m256 *bad)
{
    __m256i v[4];
    for (int i = 0; i < 4; i++)
        v[i] = avx2_floor_proved(_mm256_fmadd_ps(y[i], _mm256_set1_ps(255.0f), _mm256_set1_ps(0.5f)), margin, bad);
    return avx2_pack_rgba8x8(v);
}

/* eight RGB565 words (32-bit lanes) of values y[0..2] >= 0: with dither
** floor(y maxval + t) (t the lanes' thresholds), else the top bits floor(y
** 2^bits), both clamped to maxval; in *bad the lanes where one lies
** within `margin` of a rounding point that matters */
AVX2_INLINE __m256i avx2_565_proved8(const __m256 y[3], int dither, __m256 t, float margin, __m256 *bad)
{
    static const int shift[3] = { 11, 5, 0 }, bits[3] = { 5, 6, 5 };
    __m256i w = _mm256_setzero_si256();
    for (int i = 0; i < 3; i++) {
        const int maxval = (1 << bits[i]) - 1;
        const __m256 z = dither ? _mm256_fmadd_ps(y[i], _mm256_set1_ps((float)maxval), t)
                                : _mm256_mul_ps(y[i], _mm256_set1_ps((float)(1 << bits[i])));
        const __m256i v = _mm256_min_epi32(avx2_floor_proved_upto(z, (float)maxval, margin, bad),
                                           _mm256_set1_epi32(maxval));
        w = _mm256_or_si256(w, _mm256_slli_epi32(v, shift[i]));
    }
    return w;
}

/* COMBINE DOT3 of texels T0 and colours c (in place): with the rgb lanes
** of both given less 1/2 (in [-1/2, 1/2]) and the alpha lanes in [0, 1],
** in the rgb lanes 4 sum((T0_i - 1/2)(c_i - 1/2)) clamped to [0, 1], in
** the alpha lane the same (DOT3_RGBA, rgba) or T0_a c_a (DOT3_RGB's
** MODULATE) */
AVX2_INLINE void avx2_dot3_float(int rgba, const __m256 T0[4], __m256 c[4])
{
    __m256 s = _mm256_mul_ps(T0[0], c[0]);
    s = _mm256_fmadd_ps(T0[1], c[1], s);
    s = _mm256_fmadd_ps(T0[2], c[2], s);
    const __m256 d = _mm256_min_ps(_mm256_max_ps(_mm256_mul_ps(s, _mm256_set1_ps(4.0f)), _mm256_setzero_ps()),
                                   _mm256_set1_ps(1.0f));
    c[3] = rgba ? d : _mm256_mul_ps(T0[3], c[3]);
    c[0] = c[1] = c[2] = d;
}

/* the source colour of eight fragments (weights p[0..7], texels T) after
** MODULATE (or the texel, for REPLACE), clamped to [0, 1], as floats
** y[0..3]; with dot3 (m->dot3 set) the colour first goes through DOT3
** with the first unit's texels T0. The alpha test's outcome in *pass, the lanes not
** proved (within `margin`) in *bad */
AVX2_INLINE void avx2_modwrite_source8(const Avx2ModWrite *m, int smooth, int dot3, const WGT (*p)[3],
                                       const __m256 T0[4], const __m256 T[4], float margin, __m256 y[4],
                                       __m256i *pass, __m256 *bad)
{
    const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
    *bad = zero;
    if (m->replace) {
        for (int i = 0; i < 4; i++)
            y[i] = _mm256_min_ps(T[i], one);
    } else {
        __m256 c[4];
        if (smooth) {
            __m256 w0, w1, w2;
            avx2_wgt_float8_near(p, &w0, &w1, &w2, bad);
            /* with dot3 the rgb lanes less 1/2, from the vertex
            ** colours less 1/2 (the weights sum to 1) */
            const __m256 half = _mm256_set1_ps(0.5f), nhalf = _mm256_set1_ps(-0.5f);
            for (int i = 0; i < 4; i++) {
                const __m256(*col)[4] = dot3 && i < 3 ? m->col_half : m->col;
                const __m256 sum = _mm256_fmadd_ps(col[0][i], w0, _mm256_fmadd_ps(col[1][i], w1, _mm256_mul_ps(col[2][i], w2)));
                c[i] = dot3 && i < 3 ? _mm256_min_ps(_mm256_max_ps(sum, nhalf), half)
                                     : _mm256_min_ps(_mm256_max_ps(sum, zero), one);
            }
        } else {
            for (int i = 0; i < 4; i++)
                c[i] = dot3 && i < 3 ? m->col_half[0][i] : m->col[0][i];
        }
        if (dot3)
            avx2_dot3_float(m->dot3->rgba, T0, c);
        for (int i = 0; i < 4; i++)
            y[i] = _mm256_min_ps(_mm256_mul_ps(c[i], T[i]), one);
        if (m->rgb)
            y[3] = c[3];
    }
    *pass = _mm256_set1_epi32(-1);
    if (m->alpha.test) {
        /* fragment_alpha8 of the alpha, proved as the bytes are */
        const __m256i a8 = avx2_floor_proved(_mm256_fmadd_ps(y[3], _mm256_set1_ps(255.0f), _mm256_set1_ps(0.5f)),
                                             margin, bad);
        *pass = avx2_cmp_i32(&m->alpha.cmp, a8, m->alpha.ref_v);
    }
}

/* the words written over d (eight stored RGBA8888 words) by eight
** fragments (as avx2_modwrite_source8), into *out; returns the lanes
** (bits) the float lanes do not prove (their words in *out are not the
** chain's) */
AVX2_INLINE unsigned avx2_modwrite8(const Avx2ModWrite *m, int smooth, int kind, int dot3, const WGT (*p)[3],
                                    const __m256 T0[4], const __m256 T[4], __m256i d, __m256i *out)
{
    __m256 y[4], bad;
    __m256i pass;
    const float margin = avx2_modwrite_margin(kind, dot3);
    avx2_modwrite_source8(m, smooth, dot3, p, T0, T, margin, y, &pass, &bad);
    const __m256 one = _mm256_set1_ps(1.0f);
    if (kind) {
        const __m256 inv255 = _mm256_set1_ps(1.0f / 255.0f);
        const __m256 b = _mm256_sub_ps(one, y[3]), a = y[3];
        for (int i = 0; i < 4; i++) {
            const __m256 dv = _mm256_mul_ps(_mm256_cvtepi32_ps(avx2_byte_lanes8(d, i)), inv255);
            y[i] = kind == 1 ? _mm256_fmadd_ps(y[i], a, _mm256_mul_ps(dv, b))
                             : _mm256_min_ps(_mm256_add_ps(y[i], dv), one);
        }
    }
    const __m256i w = avx2_rgba8_proved8(y, margin, &bad);
    /* a fragment that fails the alpha test leaves the stored word */
    *out = _mm256_blendv_epi8(d, w, pass);
    return (unsigned)_mm256_movemask_ps(bad);
}

/* the same over eight stored RGB565 words d (32-bit lanes) for blend kind
** 0 or 1, the thresholds' lanes of x & 3 given (x3: 0..3 per lane) */
AVX2_INLINE unsigned avx2_modwrite565_8(const Avx2ModWrite *m, int smooth, int kind, int dot3, const WGT (*p)[3],
                                        const __m256 T0[4], const __m256 T[4], __m256i d, __m256i x3,
                                        __m256i *out)
{
    __m256 y[4], bad;
    __m256i pass;
    const float margin = avx2_modwrite_margin(kind, dot3);
    avx2_modwrite_source8(m, smooth, dot3, p, T0, T, margin, y, &pass, &bad);
    static const int shift[3] = { 11, 5, 0 }, bits[3] = { 5, 6, 5 };
    if (kind) {
        const __m256 b = _mm256_sub_ps(_mm256_set1_ps(1.0f), y[3]), a = y[3];
        for (int i = 0; i < 3; i++) {
            const int maxval = (1 << bits[i]) - 1;
            const __m256i di = _mm256_and_si256(_mm256_srli_epi32(d, shift[i]), _mm256_set1_epi32(maxval));
            const __m256 dv = _mm256_mul_ps(_mm256_cvtepi32_ps(di), _mm256_set1_ps(1.0f / (float)maxval));
            y[i] = _mm256_fmadd_ps(y[i], a, _mm256_mul_ps(dv, b));
        }
    }
    const __m256i w = avx2_565_proved8(y, m->dither, _mm256_permutevar_ps(m->t_row_f, x3), margin, &bad);
    *out = _mm256_blendv_epi8(d, w, pass);
    return (unsigned)_mm256_movemask_ps(bad);
}

#if NUM_IS_FIXED || defined(GLES_NUM_DOUBLE)
/* {====================================================================
** The fog and RGBA8888 write of a lone REPLACE unit's GL_LINEAR texels
** (one level, or two mixed by the level of detail's fraction) for eight
** fragments in float lanes, each byte proved equal to the exact stages'
** (sample_level's texels, lod_mix, stage_fog_write_rgba8): a texel within
** 4.02u of the exact one (avx2_bilerp8_float), the mix T1 + f (T2 - T1)
** within 7.04u, the fog factor's weighted sum within 8.1u (the weights'
** magnitudes summing to at most 1 + 2^-7, the vertices' factors at most 2
** in magnitude), the fogged channel within 19.2u, so 255 v + 1/2 within
** 5030u of the exact value, under the margin 2^-11 = 8192u; RGB565's
** steps 1250u (docs/architecture.md). The double build's texels come from
** the exact sampler's double indices and weights (v4_bilerp8_float, 8.1u),
** its fog factors rounded to float once: 255 v + 1/2 within 6610u. */

#if NUM_IS_FIXED
/* the low dwords of eight int64 at q, in order */
AVX2_INLINE __m256i avx2_low_dwords8(const int64_t *q)
{
    const __m256 lo = _mm256_castsi256_ps(_mm256_loadu_si256((const __m256i *)(const void *)q));
    const __m256 hi = _mm256_castsi256_ps(_mm256_loadu_si256((const __m256i *)(const void *)(q + 4)));
    /* q0 q1 q4 q5 | q2 q3 q6 q7 */
    return _mm256_permute4x64_epi64(_mm256_castps_si256(_mm256_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0))), 0xD8);
}
#endif

/* the level of detail's fractions frac[0..7] as float lanes, each rounded
** once (the fixed build's 0.30 integers are below 2^30: their low dwords) */
AVX2_INLINE __m256 avx2_frac_float8(const FRAGV *frac)
{
#if NUM_IS_FIXED
    return _mm256_mul_ps(_mm256_cvtepi32_ps(avx2_low_dwords8(frac)), _mm256_set1_ps(0x1p-30f));
#else
    return _mm256_set_m128(_mm256_cvtpd_ps(_mm256_loadu_pd(frac + 4)), _mm256_cvtpd_ps(_mm256_loadu_pd(frac)));
#endif
}

/* the two levels' texels T, T2 mixed into T by the fractions f: T + f (T2 - T) */
AVX2_INLINE void avx2_mix_levels8(__m256 f, __m256 T[4], const __m256 T2[4])
{
    for (int i = 0; i < 4; i++)
        T[i] = _mm256_fmadd_ps(f, _mm256_sub_ps(T2[i], T[i]), T[i]);
}

/* a level's texel words and log2 sizes, as the kernels read them */
typedef struct Avx2Level {
    const int *tx;
    int log2w, log2h;
} Avx2Level;

AVX2_INLINE Avx2Level avx2_level(const TexImage *li)
{
    return (Avx2Level){ (const int *)(const void *)li->texels, __builtin_ctz((unsigned)li->width),
                        __builtin_ctz((unsigned)li->height) };
}

/* slots s0..s0+m-1 (1 <= m <= 8) of a chunk, with coordinates c[0..7],
** weights p[0..7] and pixel offsets k[0..7] (copies of the last past m):
** level l1's texels, mixed with the next level's l2 by frac[0..7] (0.30)
** where two, fogged and written to fw->dst (RGBA8888, or RGB565 as
** avx2_modwrite565_8 writes it: its bound is 255/63 times smaller);
** returns the lanes written (bit i: slot s0 + i), each marked in fw->done */
AVX2_INLINE unsigned avx2_fog_write_texels8(const TexFogWrite *fw, int s0, int m, Avx2Level l1, Avx2Level l2,
                                            int two, const TexCoord *c, const WGT (*p)[3], const uint8_t *k,
                                            const FRAGV *frac, int rs, int rt)
{
    __m256 T[4];
#if NUM_IS_FIXED
    __m256i g[4], a, b;
    if (!two) {
        avx2_linear_texels8(l1.tx, l1.log2w, l1.log2h, c, rs, rt, 1, g, &a, &b);
        avx2_bilerp8_float(g, a, b, 0, T);
    } else {
        /* both levels' gathers before either's arithmetic, so that the
        ** second level's do not wait behind the first's bilerp
        ** (trilinear_fog about 5% faster; the same operations) */
        __m256 T2[4];
        __m256i g2[4], a2, b2;
        avx2_linear_texels8(l1.tx, l1.log2w, l1.log2h, c, rs, rt, 0, g, &a, &b);
        avx2_linear_texels8(l2.tx, l2.log2w, l2.log2h, c, rs, rt, 0, g2, &a2, &b2);
        avx2_bilerp8_float(g, a, b, 0, T);
        avx2_bilerp8_float(g2, a2, b2, 0, T2);
        avx2_mix_levels8(avx2_frac_float8(frac), T, T2);
    }
#else
    /* the coordinates once for both levels, both levels' words before
    ** either's arithmetic (as above); a coordinate not finite leaves the
    ** group to the exact code */
    V4 s[2], t[2], a[2], b[2];
    __m256i g[4];
    if (!v4_coords8(c, s, t))
        return 0;
    v4_linear_lanes8(l1.tx, 1 << l1.log2w, 1 << l1.log2h, s, t, rs, rt, !two, a, b, g);
    if (!two) {
        v4_bilerp8_float(g, a, b, 0, T);
    } else {
        V4 a2[2], b2[2];
        __m256i g2[4];
        __m256 T2[4];
        v4_linear_lanes8(l2.tx, 1 << l2.log2w, 1 << l2.log2h, s, t, rs, rt, 0, a2, b2, g2);
        v4_bilerp8_float(g, a, b, 0, T);
        v4_bilerp8_float(g2, a2, b2, 0, T2);
        avx2_mix_levels8(avx2_frac_float8(frac), T, T2);
    }
#endif
    __m256 w0, w1, w2, bad;
    avx2_wgt_float8_near(p, &w0, &w1, &w2, &bad);
    __m256 fog = _mm256_fmadd_ps(w0, _mm256_set1_ps(fw->a[0]),
                                 _mm256_fmadd_ps(w1, _mm256_set1_ps(fw->a[1]),
                                                 _mm256_mul_ps(w2, _mm256_set1_ps(fw->a[2]))));
    fog = _mm256_min_ps(_mm256_max_ps(fog, _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
    __m256 v[3];
    for (int i = 0; i < 3; i++) {
        const __m256 fc = _mm256_set1_ps(fw->fc[i]);
        v[i] = _mm256_fmadd_ps(fog, _mm256_sub_ps(T[i], fc), fc);
    }
    __m256i word;
    if (fw->rgb565) {
        const __m256i k8 = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)k));
        const __m256i x3 = _mm256_and_si256(_mm256_add_epi32(k8, _mm256_set1_epi32(fw->x0)), _mm256_set1_epi32(3));
        const __m256 t_row = _mm256_setr_ps(fw->t_row[0], fw->t_row[1], fw->t_row[2], fw->t_row[3], fw->t_row[0],
                                            fw->t_row[1], fw->t_row[2], fw->t_row[3]);
        word = avx2_565_proved8(v, fw->dither, _mm256_permutevar_ps(t_row, x3), 0x1p-11f, &bad);
    } else {
        const __m256 y[4] = { v[0], v[1], v[2], T[3] };
        word = avx2_rgba8_proved8(y, 0x1p-11f, &bad);
    }
    const unsigned ok = ~(unsigned)_mm256_movemask_ps(bad) & ((1u << m) - 1);
    uint32_t w[8];
    _mm256_storeu_si256((__m256i *)(void *)w, word);
    if (fw->rgb565) {
        uint16_t *dst = fw->dst;
        if (ok == 0xFF && k[7] == k[0] + 7)
            _mm_storeu_si128((__m128i *)(void *)&dst[k[0]],
                             _mm256_castsi256_si128(_mm256_permute4x64_epi64(_mm256_packus_epi32(word, word), 0x08)));
        else
            for (unsigned r = ok; r; r &= r - 1)
                dst[k[__builtin_ctz(r)]] = (uint16_t)w[__builtin_ctz(r)];
    } else {
        uint32_t *dst = fw->dst;
        if (ok == 0xFF && k[7] == k[0] + 7)
            _mm256_storeu_si256((__m256i *)(void *)&dst[k[0]], word);
        else
            for (unsigned r = ok; r; r &= r - 1)
                dst[k[__builtin_ctz(r)]] = w[__builtin_ctz(r)];
    }
    const int sh = s0 & 63;
    fw->done[s0 >> 6] |= (uint64_t)ok << sh;
    if (sh > 56 && ((uint64_t)ok >> (64 - sh)))     /* (a valid slot past the word: s0 < 64) */
        fw->done[(s0 >> 6) + 1] |= (uint64_t)ok >> (64 - sh);
    return ok;
}

/* }==================================================================== */
#endif

/* combine_block's DOT3 (scales 1) of the texel t0 and the clamped colour
** c: 4 sum(frag_mul(t0_i - 1/2, c_i - 1/2)) clamped, in every lane
** (rgba) or with frag_clamp01(frag_mul(t0_a, c_a)) as the alpha */
static inline V4 avx2_dot3_exact(int rgba, const FRAGV *t0, V4 c)
{
    FRAGV cc[4], out[4];
    v4_store(cc, c);
    FRAGV d = 0;
    for (int i = 0; i < 3; i++)
        d += frag_mul(t0[i] - FRAG_ONE / 2, cc[i] - FRAG_ONE / 2);
    out[0] = out[1] = out[2] = frag_clamp01(4 * d);
    out[3] = rgba ? out[0] : frag_clamp01(frag_mul(t0[3], cc[3]));
    return v4_load(out);
}

/* the exact chain's source colour for one fragment (stage_color_modulate,
** or with m->dot3 stage_color and the two units' stage_env): colour a[0..2]
** at weights p (smooth) or the flat colour a[0], then DOT3 with the first
** unit's texel t0 (m->dot3), texel ct (in [0, 2^31)), or the texel
** (REPLACE); 0 when it fails the alpha test */
AVX2_INLINE int avx2_modwrite_source1(const Avx2ModWrite *m, const FRAGV *const a[3], int smooth, const WGT *p,
                                      const FRAGV *t0, const FRAGV *ct, V4 *out)
{
    V4 mm = v4_load(ct);
    if (!m->replace) {
        V4 c = smooth ? v4_lerp3f_clamp01(v4_load(a[0]), v4_load(a[1]), v4_load(a[2]), p)
                      : v4_clamp01(v4_load(a[0]));
        if (t0)     /* (NULL where the instance has no DOT3) */
            c = avx2_dot3_exact(m->dot3->rgba, t0, c);
        mm = v4_mul01(c, mm);
        if (m->rgb)
            mm = v4_keep_alpha(mm, c);
    }
    *out = mm;
    FRAGV ch[4];
    v4_store(ch, mm);
    return !m->alpha.test || fragment_compare(m->alpha.func, fragment_alpha8(ch[3]), m->alpha.ref);
}

/* the exact chain for one fragment over the stored RGBA8888 word d
** (v4_rgba8) */
AVX2_INLINE uint32_t avx2_modwrite1(const Avx2ModWrite *m, const FRAGV *const a[3], int smooth, int kind,
                                    const WGT *p, const FRAGV *t0, const FRAGV *ct, uint32_t d)
{
    V4 mm;
    return avx2_modwrite_source1(m, a, smooth, p, t0, ct, &mm) ? v4_rgba8(mm, d, kind) : d;
}

/* the same over the stored RGB565 word d at column x (stage_write_565,
** stage_write_565_alpha) */
AVX2_INLINE uint32_t avx2_modwrite565_1(const Avx2ModWrite *m, const FRAGV *const a[3], int smooth, int kind,
                                        const WGT *p, const FRAGV *t0, const FRAGV *ct, uint32_t d, int x,
                                        const FRAGV unorm5[32], const FRAGV unorm6[64])
{
    V4 mm;
    if (!avx2_modwrite_source1(m, a, smooth, p, t0, ct, &mm))
        return d;
    const FRAGV t_d = m->t_row[x & 3];
    if (!kind)
        return v4_pack565(mm, m->dither, t_d);
    const FRAGV dv[3] = { unorm5[d >> 11], unorm6[(d >> 5) & 63], unorm5[d & 31] };
    const V4 cv = v4_clamp01(mm), va = v4_alpha(cv);
    return v4_pack565(v4_add(v4_mul01(cv, va), v4_mul01(v4_rgb0(dv), v4_one_minus(va))), m->dither, t_d);
}

/* eight fragments' texels from source 0 (the texels ct + k stride that a
** fetch stage sampled) or 1 (sampled here at the coordinates tc[0..7]);
** 0 when source 0 has a texel outside [0, 2^31) */
AVX2_INLINE int avx2_modwrite_texels8(const ModWriteTexture *tx, int src, const FRAGV *ct, size_t stride,
                                      const TexCoord *tc, int half_rgb, __m256 T[4])
{
    if (src == 0)
        return avx2_texels_ct8(ct, stride, half_rgb, T);
#if !NUM_IS_FIXED
    return avx2_texels_sampled8(tx, tc, half_rgb, T);
#else
    __m256i g[4], a, b;
    avx2_linear_texels8c((const int *)(const void *)tx->texels, tx->log2w, tx->log2h, &tx->ax_s, &tx->ax_t, tc,
                         tx->repeat_s, tx->repeat_t, 1, g, &a, &b);
    avx2_bilerp8_float(g, a, b, half_rgb, T);
    return 1;
#endif
}

/* the exact texel of one fragment: ct (source 0), or from the sampler at tc */
AVX2_INLINE const FRAGV *avx2_modwrite_texel1(const ModWriteTexture *tx, int src, const FRAGV *ct,
                                              const TexCoord *tc, FRAGV tmp[4])
{
    if (src == 0)
        return ct;
    tx->sampler(tx->tex, 1, tc, tc, tc, tmp, 4, tx->unorm8);
    return tmp;
}

/* fragment i's place in the first unit's texels or coordinates (DOT3), or
** NULL where they are not the source */
AVX2_INLINE const FRAGV *modwrite_ct0(const ModWriteDot3 *d, int i)
{
    return d->ct0 ? d->ct0 + (size_t)i * d->ct0_stride : NULL;
}
AVX2_INLINE const TexCoord *modwrite_tc0(const ModWriteDot3 *d, int i) { return d->tc0 ? d->tc0 + i : NULL; }

/* the kernel over fragments 0..n-1 at the offsets k of dst (RGBA8888
** words, or RGB565 words whose first is column x0): weights p, texels
** from source src (ct + j stride, or sampled at tc[j]); eight at a time,
** a last partial group as the last eight again where that applies
** (modwrite_overlaps), else exactly. The first `live` offsets ascend;
** slots from there to n repeat the last live fragment (a padded group). */
AVX2_INLINE void avx2_modwrite_run(const Avx2ModWrite *restrict m, const FRAGV *const a[3], int smooth, int kind,
                                   int src, int rgb565, int dot3, int n, int live, const uint8_t *k, int x0,
                                   const WGT (*p)[3],
                                   const FRAGV *ct, size_t stride, const TexCoord *tc, void *dst,
                                   const FRAGV unorm5[32], const FRAGV unorm6[64])
{
    /* (restrict: the framebuffer stores cannot change *m, so its constants
    ** stay in registers across the loop) */
    uint32_t *dst32 = dst;
    uint16_t *dst16 = dst;
    FRAGV tmp[4], tmp0[4];
    /* the first unit's texels (DOT3): from ct0, or sampled at tc0 */
    const ModWriteDot3 *const d3 = m->dot3;     /* (read only with dot3) */
    const int src0 = dot3 && d3->tc0 != NULL;
#define MODWRITE_T0(i) \
    (dot3 ? avx2_modwrite_texel1(&d3->tx0, src0, modwrite_ct0(d3, i), modwrite_tc0(d3, i), tmp0) : NULL)
#define MODWRITE_EXACT(i, d) \
    (rgb565 ? avx2_modwrite565_1(m, a, smooth, kind, p[i], MODWRITE_T0(i), \
                                 avx2_modwrite_texel1(&m->tx, src, ct + (size_t)(i) * stride, tc + (i), tmp), \
                                 d, x0 + k[i], unorm5, unorm6) \
            : avx2_modwrite1(m, a, smooth, kind, p[i], MODWRITE_T0(i), \
                             avx2_modwrite_texel1(&m->tx, src, ct + (size_t)(i) * stride, tc + (i), tmp), d))
    int j = 0;
    for (; j < n; j += 8) {
        if (j + 8 > n) {
            /* a last partial group: the last eight again, or the exact code */
            if (!modwrite_overlaps(kind, m->alpha.test, rgb565, n, 8))
                break;
            j = n - 8;
        }
        /* eight neighbouring pixels (a padded group never is) */
        const int run = j + 8 <= live && k[j + 7] == k[j] + 7;
        const __m256i idx = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)&k[j]));
        /* the stored words, where the blend or the alpha test reads them */
        __m256i d;
        if (rgb565 && run) {
            d = _mm256_cvtepu16_epi32(_mm_loadu_si128((const __m128i *)(const void *)&dst16[k[j]]));
        } else if (rgb565) {
            uint16_t w16[8];
            for (int i = 0; i < 8; i++)
                w16[i] = dst16[k[j + i]];
            d = _mm256_cvtepu16_epi32(_mm_loadu_si128((const __m128i *)(const void *)w16));
        } else {
            d = !kind && !m->alpha.test ? _mm256_setzero_si256()
              : run ? _mm256_loadu_si256((const __m256i *)(const void *)&dst32[k[j]])
                    : _mm256_i32gather_epi32((const int *)(const void *)dst32, idx, 4);
        }
        __m256 T[4], T0[4] = { _mm256_setzero_ps() };    /* read only with dot3 */
        __m256i w = d;
        unsigned bad = 0xFFu;
        if (avx2_modwrite_texels8(&m->tx, src, ct + (size_t)j * stride, stride, tc + j, 0, T)
            && (!dot3
                || avx2_modwrite_texels8(&d3->tx0, src0, modwrite_ct0(d3, j), d3->ct0_stride, modwrite_tc0(d3, j),
                                         1, T0))) {
            const __m256i x3 = _mm256_and_si256(_mm256_add_epi32(idx, _mm256_set1_epi32(x0)), _mm256_set1_epi32(3));
            bad = rgb565 ? avx2_modwrite565_8(m, smooth, kind, dot3, &p[j], T0, T, d, x3, &w)
                         : avx2_modwrite8(m, smooth, kind, dot3, &p[j], T0, T, d, &w);
        }
        uint32_t words[8];
        _mm256_storeu_si256((__m256i *)(void *)words, w);
        if (bad) {
            uint32_t before[8];
            _mm256_storeu_si256((__m256i *)(void *)before, d);
            for (int i = 0; i < 8; i++)
                if (bad >> i & 1u)
                    words[i] = MODWRITE_EXACT(j + i, before[i]);
        }
        if (rgb565 && run) {
            /* the eight words' low halves (each below 2^16), in order */
            const __m256i wv = _mm256_loadu_si256((const __m256i *)(const void *)words);
            const __m128i packed = _mm_packus_epi32(_mm256_castsi256_si128(wv), _mm256_extracti128_si256(wv, 1));
            _mm_storeu_si128((__m128i *)(void *)&dst16[k[j]], packed);
        } else if (rgb565) {
            for (int i = 0; i < 8; i++)
                dst16[k[j + i]] = (uint16_t)words[i];
        } else if (run)
            memcpy(&dst32[k[j]], words, sizeof words);
        else
            for (int i = 0; i < 8; i++)
                dst32[k[j + i]] = words[i];
    }
    for (; j < n; j++) {
        if (rgb565)
            dst16[k[j]] = (uint16_t)MODWRITE_EXACT(j, dst16[k[j]]);
        else
            dst32[k[j]] = MODWRITE_EXACT(j, dst32[k[j]]);
    }
#undef MODWRITE_EXACT
#undef MODWRITE_T0
}

/* avx2_modwrite_run with the texel source, the colour's interpolation
** (m->smooth), the blend (m->kind), the target and DOT3 (dot3, a constant
** where this is inlined) fixed per instance */
#define AVX2_MODWRITE_ARGS \
    const Avx2ModWrite *m, const FRAGV *const a[3], int src, int rgb565, int n, int live, const uint8_t *k, int x0, \
        const WGT (*p)[3], const FRAGV *ct, size_t stride, const TexCoord *tc, void *dst, const FRAGV unorm5[32], \
        const FRAGV unorm6[64]
AVX2_INLINE void avx2_modwrite_instances(AVX2_MODWRITE_ARGS, int dot3)
{
#define MODWRITE(S, K, F) \
    (src ? avx2_modwrite_run(m, a, S, K, 1, F, dot3, n, live, k, x0, p, ct, stride, tc, dst, unorm5, unorm6) \
         : avx2_modwrite_run(m, a, S, K, 0, F, dot3, n, live, k, x0, p, ct, stride, tc, dst, unorm5, unorm6))
    switch ((rgb565 ? 6 : 0) + (m->smooth ? 3 : 0) + m->kind) {
    case 0: MODWRITE(0, 0, 0); break;
    case 1: MODWRITE(0, 1, 0); break;
    case 2: MODWRITE(0, 2, 0); break;
    case 3: MODWRITE(1, 0, 0); break;
    case 4: MODWRITE(1, 1, 0); break;
    case 5: MODWRITE(1, 2, 0); break;
    case 6: MODWRITE(0, 0, 1); break;
    case 7: MODWRITE(0, 1, 1); break;
    case 9: MODWRITE(1, 0, 1); break;
    case 10: MODWRITE(1, 1, 1); break;
    default: break;    /* RGB565 takes blend kinds 0 and 1 only */
    }
#undef MODWRITE
}

/* the instances with and without DOT3 as two functions, prefix_modwrite_plain
** and prefix_modwrite_dot3: one function of all of them grows past what the
** compiler optimises as well (its register allocation), which cost the
** lone unit's kernel 2-3% */
#define AVX2_MODWRITE_FUNCTIONS(prefix) \
    static __attribute__((noinline)) void prefix##_modwrite_plain(AVX2_MODWRITE_ARGS) \
    { \
        avx2_modwrite_instances(m, a, src, rgb565, n, live, k, x0, p, ct, stride, tc, dst, unorm5, unorm6, 0); \
    } \
    static __attribute__((noinline)) void prefix##_modwrite_dot3(AVX2_MODWRITE_ARGS) \
    { \
        avx2_modwrite_instances(m, a, src, rgb565, n, live, k, x0, p, ct, stride, tc, dst, unorm5, unorm6, 1); \
    }
AVX2_MODWRITE_FUNCTIONS(avx2)
#if SIMD_AVX512_FX
/* the same functions compiled for AVX-512VL, where the CPU has it: the
** same AVX2 operations on the same lanes (so the same words), with
** AVX-512VL's 32 vector registers, which the kernel's constants and lanes
** fill without spills (combine_dot3: about 5% of the frame) */
#pragma GCC push_options
SIMD_TARGET_AVX512
AVX2_MODWRITE_FUNCTIONS(fx512)
#pragma GCC pop_options
#endif
#undef AVX2_MODWRITE_FUNCTIONS

/* the kernel's instance for the state (m->dot3), in AVX-512VL's registers
** where wide (the context runs AVX-512) */
static inline void avx2_modwrite_dispatch(AVX2_MODWRITE_ARGS, int wide)
{
#if SIMD_AVX512_FX
    if (wide) {
        (m->dot3 ? fx512_modwrite_dot3 : fx512_modwrite_plain)(m, a, src, rgb565, n, live, k, x0, p, ct, stride, tc,
                                                               dst, unorm5, unorm6);
        return;
    }
#else
    (void)wide;
#endif
    (m->dot3 ? avx2_modwrite_dot3 : avx2_modwrite_plain)(m, a, src, rgb565, n, live, k, x0, p, ct, stride, tc, dst,
                                                         unorm5, unorm6);
}
#undef AVX2_MODWRITE_ARGS
/* }==================================================================== */
#endif

#if defined(GLES_NUM_FLOAT)
#include "span_float8.h"    /* the double build's is in span_avx512.h's target */
#endif

#endif
