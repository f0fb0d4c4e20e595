/*
** span_edges8.h -- a chunk's edge values at eight slots in AVX-512 lanes,
** for the fixed and double builds' eight-lane perspective stages
** (span_fx512.h, span_avx512.h). Included inside their target pragma for
** AVX-512 (F, DQ); every function is static.
*/
#ifndef GLES_SPAN_EDGES8_H
#define GLES_SPAN_EDGES8_H

#if SIMD_AVX512_FX || SIMD_AVX512_INSTANCE
#include <immintrin.h>

/* the chunk's edge values at offset 0 and their steps along x, in every
** lane (a local copy, so that a loop keeps them in registers where stores
** to the span buffer could alias the triangle's and the buffer's fields) */
typedef struct Edges8 {
    __m512i e0[3], ea[3];
} Edges8;

static inline __attribute__((always_inline)) void edges8_setup(const int64_t e0[3], const int64_t ea[3], Edges8 *ed)
{
    for (int i = 0; i < 3; i++) {
        ed->e0[i] = _mm512_set1_epi64(e0[i]);
        ed->ea[i] = _mm512_set1_epi64(ea[i]);
    }
}

/* the edge values e0 + ea k at eight slots' offsets k: vpmullq's product
** mod 2^64, which is the scalar code's wherever that fits int64 (as
** avx2_edges4 forms it) */
static inline __attribute__((always_inline)) void edges8(const Edges8 *ed, const uint8_t *k, __m512i e[3])
{
    const __m512i kv = _mm512_cvtepu8_epi64(_mm_loadl_epi64((const __m128i *)(const void *)k));
    for (int i = 0; i < 3; i++)
        e[i] = _mm512_add_epi64(ed->e0[i], _mm512_mullo_epi64(kv, ed->ea[i]));
}

#endif
#endif
