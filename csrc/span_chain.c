/*
** span_chain.c -- the fragment stage as a chain of span-wide stages.
** Consumes: a TriSetup and a covered run of one row (from raster.c).
** Produces: the same framebuffer writes as span_generic, bit for bit.
**
** A run is cut into chunks of SPAN_CHUNK pixels. Each chunk flows through
** the stages span_chain_compose picked from the enabled state only: the
** depth and stencil tests (before any colour work when nothing later can
** discard the fragment, else after the alpha test), weights, colour, one
** fetch per enabled texture unit, one environment per unit, fog, alpha
** test, and the write (blend, dither, logic op, masks). Every stage is a
** loop over the chunk's live fragments; the tests compact the list. The
** arithmetic is the generic path's own functions, called in the same order
** per fragment, so the images are identical: what goes is the per-fragment
** state dispatch, and the colour work for fragments that fail the tests.
*/
#include <string.h>
#include "span.h"
#include "fragment.h"
#include "raster.h"
#include "texture.h"

/* the edge values of the chunk's pixel at offset k */
static inline void chunk_edges(const TriSetup *t, const SpanBuf *b, int k, int64_t e[3])
{
    for (int i = 0; i < 3; i++)
        e[i] = b->e0[i] + t->ea[i] * k;
}

/* keep the fragments at slots where keep[j]; c moves with them once the
** colour is computed */
static void chunk_compact(SpanBuf *b, const uint8_t *keep, int with_color)
{
    int m = 0;
    for (int j = 0; j < b->n; j++) {
        if (!keep[j])
            continue;
        b->k[m] = b->k[j];
        if (with_color && m != j)
            for (int i = 0; i < 4; i++)
                b->c[m][i] = b->c[j][i];
        m++;
    }
    b->n = m;
}

/* RGB565 with red, green and blue written, dithered or not (fragment_write's
** conversion for these states) */
/* the dither thresholds of the chunk's row by x & 3 (1/2 without dither) */
static inline void dither_row(const SpanBuf *b, int dither, FRAGV t_row[4])
{
    for (int x = 0; x < 4; x++)
        t_row[x] = dither ? fragment_dither_threshold(x, b->y) : FRAG_ONE / 2;
}

/* the colour buffer at the chunk's first pixel: 16-bit words where `is16`
** (the caller's test of the format, which it has made already), else
** RGBA8888 ones */
static inline void *chunk_color(const GlesContext *ctx, const SpanBuf *b, int is16)
{
    const size_t at = (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    return is16 ? (void *)((uint16_t *)ctx->color + at) : (void *)((uint32_t *)ctx->color + at);
}

static inline uint32_t pack565(const FRAGV v[3], int dither, FRAGV t_d)
{
    return (fragment_channel(v[0], 5, dither, t_d) << 11) | (fragment_channel(v[1], 6, dither, t_d) << 5)
         | fragment_channel(v[2], 5, dither, t_d);
}

/* the stages of one instance of span_stages.h */
/* an instance's stages that sample, combine and write in one pass (NULL
** where it has none) */
typedef struct FusedStages {
    SpanStage modulate_write, sample_write;
    SpanStage dot3_write, dot3_sample_write;
    int modulate_write_565;     /* they also write RGB565 */
    /* the DOT3 pair repeats the separate stages' operations (the float
    ** build's lanes, the double build's AVX-512 ones), so it may take
    ** DOT3_RGBA under SRC_ALPHA blending; the fixed build's float lanes and
    ** the double build's AVX2 ones are approximations bounded per byte */
    int dot3_exact;
} FusedStages;

typedef struct ChainStages {
    SpanStage persp, persp_lod, depth, tests_early, tests_late, zless_early, color;
    SpanStage fetch[GLES_MAX_TEXTURE_UNITS], fetch_rect[GLES_MAX_TEXTURE_UNITS], env[GLES_MAX_TEXTURE_UNITS];
    SpanStage fetch_direct[GLES_MAX_TEXTURE_UNITS], fetch_rect_direct[GLES_MAX_TEXTURE_UNITS];
    SpanStage color_modulate[GLES_MAX_TEXTURE_UNITS];
    SpanStage fog, fog_const, alpha;
    SpanStage write, write_rgba8, write_rgba8_alpha, write_rgba8_add, write_rgba8_logic, write_rgba8_masked;
    SpanStage write_565, write_565_alpha;
    SpanStage fog_write_rgba8, fog_write_565;  /* the fixed build's AVX2 instance */
    SpanStage sample_fog_write_rgba8, sample_fog_write_565;     /* the same */
    SpanStage rect_source;
    SpanStage color_dot3_modulate;  /* float and double builds, AVX2 */
    SpanStage coords[GLES_MAX_TEXTURE_UNITS], coords_rect[GLES_MAX_TEXTURE_UNITS];
    SpanStage coords_tx[GLES_MAX_TEXTURE_UNITS];
    /* the fused stages of the AVX2 instances (the double build's in float
    ** lanes, proved), and of the double build's for a CPU that runs its
    ** AVX-512 kernel (fused_avx512) */
    FusedStages fused, fused_avx512;
} ChainStages;

/* the baseline instance */
#define STAGE(name) name##_base
#define CHAIN_SIMD 0
#include "span_stages.h"
#undef STAGE
#undef CHAIN_SIMD

#if SIMD_X86
/* the AVX2 instance: every function until pop_options may use AVX2 */
#pragma GCC push_options
SIMD_TARGET_AVX2
#include "span_avx2.h"
#if SIMD_AVX512_INSTANCE
#pragma GCC push_options
SIMD_TARGET_AVX512
#include "span_avx512.h"   /* the double build's writer (as texsample.c includes it: once) */
#pragma GCC pop_options
#endif
#if SIMD_AVX512_FX
#pragma GCC push_options
SIMD_TARGET_AVX512
#include "span_fx512.h"    /* the fixed build's perspective stage in eight lanes */
#pragma GCC pop_options
#endif
/* a test's fragments for a fused stage's kernel: copies with room for the
** padded group, as the stage pads its chunk */
typedef struct DebugGroup {
    uint8_t k[SPAN_CHUNK];
    WGT p[SPAN_CHUNK][3];
    FRAGV ct[SPAN_CHUNK][4];
    FRAGV ct0[SPAN_CHUNK][4];       /* a first unit's texels (DOT3) */
} DebugGroup;

/* n fragments into g, padded to a whole group of `group` when pad (n > 0);
** returns the count */
static int debug_group(DebugGroup *g, int n, const uint8_t *k, const WGT *p, const FRAGV *ct, int smooth, int pad,
                       int group)
{
    memcpy(g->k, k, (size_t)n);
    memcpy(g->p, p, (size_t)n * sizeof g->p[0]);
    memcpy(g->ct, ct, (size_t)n * sizeof g->ct[0]);
    return pad && n > 0 ? avx2_pad_group(group, n, g->k, g->p, smooth, NULL, g->ct[0], 4) : n;
}
#define STAGE(name) name##_avx2
#define CHAIN_SIMD 1
#include "span_stages.h"
#undef STAGE
#undef CHAIN_SIMD
#if NUM_IS_FIXED
/* the kernels of four points' edge values e[lane] as the span stages run
** them: wgt_persp (persp4_avx2, the weights stage's), and where g is not
** NULL, also the tangents along g[0] and g[1] into tx and ty
** (stage_persp_lod's); 0 where they leave a group to the scalar code */
static int debug_persp4_avx2(const WgtSetup *s, const WgtTangent *g, const int64_t e[4][3], WGT out[4][3],
                             WGT tx[4][3], WGT ty[4][3])
{
    __m256i ev[3], l[3], den, o[2][3];
    for (int i = 0; i < 3; i++)
        ev[i] = _mm256_setr_epi64x(e[0][i], e[1][i], e[2][i], e[3][i]);
    if (!g)
        return persp4_avx2(s, ev, out);
    Avx2Tangents gv;
    avx2_tangents_setup(g, &gv);
    if (s->affine || !avx2_persp4_den(s, ev, l, &den) || !avx2_tangents4(&gv, l, den, o))
        return 0;
    avx2_store_wgt4(l, out);
    avx2_store_wgt4(o[0], tx);
    avx2_store_wgt4(o[1], ty);
    return 1;
}
/* gles_debug_color's vector path: stage_color's kernels */
static void debug_color_avx2(int clamp, const FRAGV *const col[3], int n, const WGT (*p)[3], FRAGV (*out)[4])
{
    const V4 a0 = v4_load(col[0]), a1 = v4_load(col[1]), a2 = v4_load(col[2]);
    for (int j = 0; j < n; j++)
        v4_store(out[j], clamp ? v4_lerp3f_clamp01(a0, a1, a2, p[j]) : v4_lerp3f(a0, a1, a2, p[j]));
}
#endif
#if NUM_IS_FIXED || defined(GLES_NUM_DOUBLE)
/* gles_debug_modulate_write's kernel run (gles_debug_modulate_write_d's
** in the double build), with the count of the lanes the kernel leaves to
** the exact code, group by group */
static int debug_modulate_write_avx2(Avx2ModWrite *m, const FRAGV *const a[3], int n, const uint8_t *k_in,
                                     const WGT (*p_in)[3], int rgba_dot, const FRAGV *ct0_in, const FRAGV *ct_in,
                                     int pad, int rgb565, int x0, void *dst, const FRAGV unorm5[32],
                                     const FRAGV unorm6[64])
{
    const int smooth = m->smooth, kind = m->kind;
    DebugGroup g;
    const int live = n;
    n = debug_group(&g, n, k_in, p_in[0], ct_in, smooth, pad, 8);
    uint8_t *const k = g.k;
    WGT (*const p)[3] = g.p;
    FRAGV (*const ct)[4] = g.ct;
    ModWriteDot3 d3;
    if (rgba_dot >= 0) {
        /* the first unit's texels, padded as the stage pads them */
        memcpy(g.ct0, ct0_in, (size_t)live * sizeof g.ct0[0]);
        for (int j = live; j < n; j++)
            memcpy(g.ct0[j], g.ct0[live - 1], sizeof g.ct0[0]);
        d3 = (ModWriteDot3){ .rgba = rgba_dot, .ct0 = g.ct0[0], .ct0_stride = 4 };
        m->dot3 = &d3;
    }
    const int dot3 = m->dot3 != NULL;
    int exact = n % 8;
    for (int j = 0; j + 8 <= n; j += 8) {
        uint32_t d[8];
        for (int i = 0; i < 8; i++)
            d[i] = rgb565 ? ((const uint16_t *)dst)[k[j + i]] : ((const uint32_t *)dst)[k[j + i]];
        const __m256i dv = _mm256_loadu_si256((const __m256i *)(const void *)d);
        const __m256i x3 = _mm256_and_si256(
            _mm256_add_epi32(_mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)&k[j])),
                             _mm256_set1_epi32(x0)),
            _mm256_set1_epi32(3));
        __m256i w;
        __m256 T[4], T0[4] = { _mm256_setzero_ps() };
        if (!avx2_texels_ct8(ct[j], 4, 0, T) || (dot3 && !avx2_texels_ct8(g.ct0[j], 4, 1, T0)))
            exact += 8;
        else
            exact += __builtin_popcount(
                rgb565 ? avx2_modwrite565_8(m, smooth, kind, dot3, (const WGT (*)[3])&p[j], T0, T, dv, x3, &w)
                       : avx2_modwrite8(m, smooth, kind, dot3, (const WGT (*)[3])&p[j], T0, T, dv, &w));
    }
    const TexCoord tc[SPAN_CHUNK] = { { 0, 0 } };   /* source 0 reads no coordinates */
    avx2_modwrite_dispatch(m, a, 0, rgb565, n, live, k, x0, (const WGT (*)[3])p, ct[0], 4, tc, dst, unorm5, unorm6, 0);
    return exact;
}

/* the debug entries' run: their arguments checked (-1 where out of range),
** the kernel's setup for them (RGB565's dither row y = 0 from column x0,
** the stored channels' values as the context has them), then the kernel */
static int debug_modwrite(int smooth, int rgb, int kind, unsigned int alpha_func, uint32_t alpha_ref,
                          const FRAGV col[12], int n, const uint8_t *k, const WGT *p, int rgba_dot, const FRAGV *ct0,
                          const FRAGV *ct, int pad, int rgb565, int dither, int x0, void *dst)
{
    if (n < 0 || n > SPAN_CHUNK || kind < 0 || kind > (rgb565 ? 1 : 2) || x0 < 0 || simd_detect() < SIMD_AVX2)
        return -1;
    for (int i = 0; i < 12; i++)
        if (smooth && !(col[i] >= 0 && col[i] <= FRAG_ONE))
            return -1;
    const FRAGV *const a[3] = { col, smooth ? col + 4 : col, smooth ? col + 8 : col };
    Avx2ModWrite m;
    avx2_modwrite_setup(&m, a, smooth != 0, rgb != 0, kind, alpha_func, alpha_ref);
    FRAGV t_row[4], unorm5[32], unorm6[64];
    for (int x = 0; x < 4; x++)
        t_row[(x0 + x) & 3] = dither ? fragment_dither_threshold(x0 + x, 0) : FRAG_ONE / 2;
    avx2_modwrite_dither(&m, dither != 0, t_row);
    for (uint32_t d = 0; d < 64; d++) {
        if (d < 32)
            unorm5[d] = frag_from_unorm(d, 31);
        unorm6[d] = frag_from_unorm(d, 63);
    }
    return debug_modulate_write_avx2(&m, a, n, k, (const WGT (*)[3])p, rgba_dot, ct0, ct, pad, rgb565 != 0, x0, dst,
                                     unorm5, unorm6);
}
#endif
#if NUM_IS_FIXED
/* gles_debug_fog_write_texels's group: lane i's four texels at columns 2i,
** 2i + 1 and rows 0, 1 of a 16x2 level, its coordinates placed so that
** the bilinear weights are ab[2i], ab[2i + 1] */
static int debug_fog_write_avx2(const uint32_t tex1[32], const uint32_t tex2[32], const int32_t ab[16], int two,
                                const int64_t frac[8], const int32_t w[24], const int32_t fog[3],
                                const int64_t fc[3], int rgb565, int dither, const int64_t t_row[4],
                                uint32_t out[8])
{
    uint32_t level[2][32];
    TexCoord c[8];
    WGT p[8][3];
    uint8_t k[8];
    for (int i = 0; i < 8; i++) {
        for (int l = 0; l < 2; l++) {
            const uint32_t *src = l ? tex2 : tex1;
            level[l][2 * i] = src[4 * i], level[l][2 * i + 1] = src[4 * i + 1];
            level[l][16 + 2 * i] = src[4 * i + 2], level[l][16 + 2 * i + 1] = src[4 * i + 3];
        }
        if (ab[2 * i] < 0 || ab[2 * i] > 65535 || ab[2 * i + 1] < 0 || ab[2 * i + 1] > 65535 || frac[i] < 0
            || frac[i] >= FRAG_ONE)
            return -1;
        /* s 16 - 1/2 = 2i + a / 2^16, t 2 - 1/2 = b / 2^16, in 32.32 */
        c[i].s = (TEXC)((int64_t)(2 * i * 65536 + 32768 + ab[2 * i]) << 12);
        c[i].t = (TEXC)((int64_t)(32768 + ab[2 * i + 1]) << 15);
        for (int j = 0; j < 3; j++)
            p[i][j] = w[3 * i + j];
        k[i] = (uint8_t)i;
    }
    for (int j = 0; j < 3; j++)
        if (fog[j] < -2 * NUM_ONE || fog[j] > 2 * NUM_ONE || fc[j] < 0 || fc[j] > FRAG_ONE)
            return -1;
    uint16_t px565[8] = { 0 };
    uint64_t done[SPAN_CHUNK / 64] = { 0 };
    TexFogWrite fw = { .p = (const WGT (*)[3])p, .dst = rgb565 ? (void *)px565 : (void *)out, .k = k,
                       .rgb565 = rgb565 != 0, .dither = dither != 0, .x0 = 0, .done = done };
    for (int j = 0; j < 4; j++)
        fw.t_row[j] = dither ? (float)((double)t_row[j] * 0x1p-30) : 0.0f;
    for (int j = 0; j < 3; j++) {
        fw.a[j] = (float)((double)fog[j] * 0x1p-46);
        fw.fc[j] = (float)((double)fc[j] * 0x1p-30);
    }
    const Avx2Level l1 = { (const int *)(const void *)level[0], 4, 1 };
    const Avx2Level l2 = { (const int *)(const void *)level[1], 4, 1 };
    const unsigned ok = avx2_fog_write_texels8(&fw, 0, 8, l1, l2, two != 0, c, (const WGT (*)[3])p, k, frac, 1, 1);
    if (rgb565)
        for (int i = 0; i < 8; i++)
            if ((ok >> i) & 1)
                out[i] = px565[i];
    return (int)ok;
}
#endif
#pragma GCC pop_options
#endif

int gles_debug_modulate_write_f(int smooth, int rgb, int kind, unsigned int alpha_func, uint32_t alpha_ref,
                                const float col[12], int n, const uint8_t *k, const float *p, const float *ct,
                                uint32_t *dst)
{
#if SIMD_X86 && defined(GLES_NUM_FLOAT)
    if (n < 0 || n > SPAN_CHUNK || kind < 0 || kind > 2 || simd_detect() < SIMD_AVX2)
        return -1;
    const FRAGV *const a[3] = { col, smooth ? col + 4 : col, smooth ? col + 8 : col };
    F8ModWrite m;
    f8_modwrite_setup(&m, a, smooth != 0, rgb != 0, 0, kind, alpha_func, alpha_ref);
    DebugGroup g;
    const int padded = debug_group(&g, n, k, p, ct, smooth != 0, 1, F8_N);
    f8_modwrite_dispatch(&m, 0, 0, padded, n, g.k, (const WGT (*)[3])g.p, g.ct[0], 4, NULL, 0, dst, NULL);
    return 0;
#else
    (void)smooth, (void)rgb, (void)kind, (void)alpha_func, (void)alpha_ref, (void)col, (void)n, (void)k, (void)p,
        (void)ct, (void)dst;
    return -1;
#endif
}

int gles_debug_modulate_write_d(int smooth, int rgb, int kind, unsigned int alpha_func, uint32_t alpha_ref,
                                const double col[12], int n, const uint8_t *k, const double *p, int dot3,
                                const double *ct0, const double *ct, int rgb565, int dither, int x0, void *dst)
{
#if SIMD_X86 && defined(GLES_NUM_DOUBLE)
    if (dot3 < 0 || dot3 > 2)
        return -1;
    return debug_modwrite(smooth, rgb, kind, alpha_func, alpha_ref, col, n, k, p, dot3 - 1, ct0, ct, 1, rgb565,
                          dither, x0, dst);
#else
    (void)smooth, (void)rgb, (void)kind, (void)alpha_func, (void)alpha_ref, (void)col, (void)n, (void)k, (void)p,
        (void)dot3, (void)ct0, (void)ct, (void)rgb565, (void)dither, (void)x0, (void)dst;
    return -1;
#endif
}

int gles_debug_modulate_write(int smooth, int rgb, int kind, unsigned int alpha_func, uint32_t alpha_ref,
                              const int64_t col[12], int n, const uint8_t *k, const int32_t *p, int dot3,
                              const int64_t *ct0, const int64_t *ct, int pad, int rgb565, int dither, int x0,
                              void *dst)
{
#if SIMD_X86 && NUM_IS_FIXED
    if (dot3 < 0 || dot3 > 2)
        return -1;
    return debug_modwrite(smooth, rgb, kind, alpha_func, alpha_ref, col, n, k, p, dot3 - 1, ct0, ct, pad, rgb565,
                          dither, x0, dst);
#else
    (void)smooth, (void)rgb, (void)kind, (void)alpha_func, (void)alpha_ref, (void)col, (void)n, (void)k, (void)p,
        (void)dot3, (void)ct0, (void)ct, (void)pad, (void)rgb565, (void)dither, (void)x0, (void)dst;
    return -1;
#endif
}

int gles_debug_fog_write_texels(const uint32_t tex1[32], const uint32_t tex2[32], const int32_t ab[16], int two,
                                const int64_t frac[8], const int32_t w[24], const int32_t fog[3],
                                const int64_t fc[3], int rgb565, int dither, const int64_t t_row[4],
                                uint32_t out[8])
{
#if SIMD_X86 && NUM_IS_FIXED
    if (simd_detect() < SIMD_AVX2)
        return -1;
    return debug_fog_write_avx2(tex1, tex2, ab, two, frac, w, fog, fc, rgb565, dither, t_row, out);
#else
    (void)tex1, (void)tex2, (void)ab, (void)two, (void)frac, (void)w, (void)fog, (void)fc, (void)rgb565,
        (void)dither, (void)t_row, (void)out;
    return -1;
#endif
}

#if NUM_IS_FIXED
/* a test's triangle weights setup into *s; 0 where a value is outside the
** ranges the setup makes (the mantissas recipw_of makes have 30 bits) */
static int debug_wgt_setup(WgtSetup *s, int eshift, int64_t lin_recip, const int64_t mant[3], const int qshift[3],
                           int affine)
{
    if (eshift < 0 || eshift > 32)
        return 0;
    *s = (WgtSetup){ .eshift = eshift, .lin_recip = lin_recip, .affine = affine };
    for (int i = 0; i < 3; i++) {
        if (qshift[i] < 0 || mant[i] < 0 || mant[i] >= ((int64_t)1 << 30))
            return 0;
        s->mant[i] = mant[i];
        s->qshift[i] = qshift[i];
    }
    return 1;
}

/* gles_debug_persp and gles_debug_persp_tangent: wgt_persp, and where g is
** not NULL its tangents along g[0] and g[1] (out: 3 or 9 values a point) */
static int debug_persp(int simd, const WgtSetup *s, const WgtTangent *g, int n, const int64_t *e, int32_t *out)
{
    const size_t per = g ? 9 : 3;
    int j = 0;
#if SIMD_X86
    if (simd && simd_detect() >= SIMD_AVX2)
        for (; j + 4 <= n; j += 4) {
            WGT o[3][4][3];
            const int64_t (*ej)[3] = (const int64_t (*)[3])(e + 3 * (size_t)j);
            if (!debug_persp4_avx2(s, g, ej, o[0], o[1], o[2]))
                /* stage_persp's fallback: the scalar code for the group */
                for (int k = 0; k < 4; k++)
                    wgt_persp_tangents(s, g, ej[k], o[0][k], o[1][k], o[2][k]);
            for (int k = 0; k < 4; k++)
                for (size_t m = 0; m < per; m++)
                    out[(size_t)(j + k) * per + m] = o[m / 3][k][m % 3];
        }
#endif
    (void)simd;
    for (; j < n; j++) {
        WGT o[3][3];
        wgt_persp_tangents(s, g, e + 3 * (size_t)j, o[0], o[1], o[2]);
        for (size_t m = 0; m < per; m++)
            out[(size_t)j * per + m] = o[m / 3][m % 3];
    }
    return 1;
}
#endif

int gles_span_chunk(void) { return SPAN_CHUNK; }

int gles_debug_persp_chunk(int simd, int eshift, int64_t lin_recip, const int64_t mant[3], const int qshift[3],
                           int affine, int n, const int64_t e0[3], const int64_t ea[3], int32_t *out)
{
#if NUM_IS_FIXED
    TriSetup t;
    SpanBuf b;
    memset(&t, 0, sizeof t);
    if (n < 0 || n > SPAN_CHUNK || !debug_wgt_setup(&t.wgt, eshift, lin_recip, mant, qshift, affine))
        return 0;
    for (int i = 0; i < 3; i++) {
        t.ea[i] = ea[i];
        b.e0[i] = e0[i];
    }
    b.n = n;
    for (int j = 0; j < n; j++)
        b.k[j] = (uint8_t)j;
#if SIMD_X86
    if (simd && simd_detect() >= SIMD_AVX2)
        stage_persp_avx2(NULL, &t, &b);
    else
#endif
        stage_persp_base(NULL, &t, &b);
    (void)simd;
    memcpy(out, b.p, (size_t)n * sizeof b.p[0]);
    return 1;
#else
    (void)simd, (void)eshift, (void)lin_recip, (void)mant, (void)qshift, (void)affine, (void)n, (void)e0, (void)ea,
        (void)out;
    return 0;
#endif
}

int gles_debug_persp(int simd, int eshift, int64_t lin_recip, const int64_t mant[3], const int qshift[3], int affine,
                     int n, const int64_t *e, int32_t *out)
{
#if NUM_IS_FIXED
    WgtSetup s;
    if (n < 0 || !debug_wgt_setup(&s, eshift, lin_recip, mant, qshift, affine))
        return 0;
    return debug_persp(simd, &s, NULL, n, e, out);
#else
    (void)simd, (void)eshift, (void)lin_recip, (void)mant, (void)qshift, (void)affine, (void)n, (void)e, (void)out;
    return 0;
#endif
}

int gles_debug_persp_tangent(int simd, int eshift, int64_t lin_recip, const int64_t mant[3], const int qshift[3],
                             int affine, int64_t area2, const int64_t ea[3], const int64_t eb[3], int n,
                             const int64_t *e, int32_t *out)
{
#if NUM_IS_FIXED
    WgtSetup s;
    WgtTangent g[2];
    if (n < 0 || area2 <= 0 || !debug_wgt_setup(&s, eshift, lin_recip, mant, qshift, affine))
        return 0;
    wgt_tangents_setup(&s, area2, ea, eb, g);
    return debug_persp(simd, &s, g, n, e, out);
#else
    (void)simd, (void)eshift, (void)lin_recip, (void)mant, (void)qshift, (void)affine, (void)area2, (void)ea, (void)eb,
        (void)n, (void)e, (void)out;
    return 0;
#endif
}

int gles_debug_color(int simd, int clamp, const int64_t col[12], int n, const int32_t *p, int64_t *out)
{
#if NUM_IS_FIXED
    if (n < 0)
        return 0;
    const FRAGV *const c[3] = { col, col + 4, col + 8 };
    int fits = 1;
    for (int i = 0; i < 12; i++)
        fits &= col[i] >= INT32_MIN && col[i] <= INT32_MAX;
#if SIMD_X86
    if (simd && fits && simd_detect() >= SIMD_AVX2) {
        debug_color_avx2(clamp, c, n, (const WGT (*)[3])p, (FRAGV (*)[4])out);
        return 1;
    }
#endif
    (void)simd, (void)fits;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < 4; i++) {
            const FRAGV v = frag_lerp3f(c[0][i], c[1][i], c[2][i], p[3 * j], p[3 * j + 1], p[3 * j + 2]);
            out[4 * j + i] = clamp ? frag_clamp01(v) : v;
        }
    return 1;
#else
    (void)simd, (void)clamp, (void)col, (void)n, (void)p, (void)out;
    return 0;
#endif
}

/* {====================================================================
** composition and the driver */

/* which blend the RGBA8888 writers cover: 0 none, 1 alpha, 2 additive, -1 other */
int span_blend_kind(const GlesContext *ctx)
{
    if (!ctx->blend || ctx->color_logic_op)
        return 0;
    if (ctx->blend_eq_rgb != GL_FUNC_ADD_OES || ctx->blend_eq_alpha != GL_FUNC_ADD_OES)
        return -1;
    unsigned int s = ctx->blend_src_rgb, d = ctx->blend_dst_rgb;
    if (ctx->blend_src_alpha != s || ctx->blend_dst_alpha != d)
        return -1;
    if (s == GL_SRC_ALPHA && d == GL_ONE_MINUS_SRC_ALPHA)
        return 1;
    if (s == GL_ONE && d == GL_ONE)
        return 2;
    return -1;
}

/* whether arguments 0 and 1 (sources src, operands op) are the unit's
** texture and the primary colour (the previous colour at the first
** enabled unit), in either order, each with operand want_op */
static int dot3_args(const unsigned int src[3], const unsigned int op[3], unsigned int want_op)
{
    if (op[0] != want_op || op[1] != want_op)
        return 0;
    for (int t = 0; t < 2; t++)     /* the texture as argument t, the colour as the other */
        if (src[t] == GL_TEXTURE && (src[1 - t] == GL_PRIMARY_COLOR || src[1 - t] == GL_PREVIOUS))
            return 1;
    return 0;
}

/* exactly two units, the first COMBINE DOT3_RGB (its alpha MODULATE) or
** DOT3_RGBA of its texture and the primary colour (in either order) with
** scales 1, the second MODULATE of an RGBA or RGB texture: the pair the
** fused stage takes (stage_dot3_write) */
static int span_dot3_pair(const GlesContext *ctx)
{
    const unsigned int units = ctx->tex_units_on, rest = units & (units - 1);
    if (!units || !rest || (rest & (rest - 1)))
        return 0;
    const TexUnit *a = &ctx->units[__builtin_ctz(units)], *b = &ctx->units[__builtin_ctz(rest)];
    if (b->env_mode != GL_MODULATE || (b->bound->format != GL_RGBA && b->bound->format != GL_RGB))
        return 0;
    if (a->env_mode != GL_COMBINE || (a->combine_rgb != GL_DOT3_RGB && a->combine_rgb != GL_DOT3_RGBA)
        || a->rgb_scale != 1.0 || a->alpha_scale != 1.0 || !dot3_args(a->src_rgb, a->op_rgb, GL_SRC_COLOR))
        return 0;
    /* DOT3_RGBA's alpha is its rgb result; DOT3_RGB's the MODULATE */
    return a->combine_rgb == GL_DOT3_RGBA
        || (a->combine_alpha == GL_MODULATE && dot3_args(a->src_alpha, a->op_alpha, GL_SRC_ALPHA));
}

/* the stages for the current state into s, for rectangles (rect) or
** triangles; returns their number */
static int compose(GlesContext *ctx, SpanStage *s, int rect)
{
    int n = 0;
    const ChainStages *cs = &chain_stages_base;
#if SIMD_X86
    if (ctx_simd(ctx) >= SIMD_AVX2)
        cs = &chain_stages_avx2;
#endif
    /* the fused stages of this instance and CPU */
    const FusedStages *fs = &cs->fused;
    if (ctx_simd(ctx) >= SIMD_AVX512 && cs->fused_avx512.modulate_write)
        fs = &cs->fused_avx512;
    const unsigned int units = ctx->tex_units_on;
    const int stencil = ctx->stencil_test && ctx->stencil;
    const int depth = ctx->depth_test && ctx->depth;
    const int tests = stencil || depth;
    const int zless = depth && !stencil && ctx->depth_func == GL_LESS && ctx->depth_mask;
    /* the tests may run first when nothing after them can discard */
    const int early = !ctx->alpha_test;
    /* with every channel masked the write leaves the colour as it is: no
    ** write, and without an alpha test no colour work at all */
    const int no_color = span_no_color(ctx);
    const int color_work = !no_color || ctx->alpha_test;
    if (!rect) {
        ctx->chain_coords_unit = ctx->chain_coords_tx_unit = ctx->chain_lod_unit = -1;
        ctx->chain_fused_lanes = 0;
    }
    ctx->stencil_cull.on = 0;
    if (stencil) {
        FragTests ft;
        fragment_tests_setup(ctx, &ft);
        fragment_stencil_lut(&ft, ctx->stencil_lut);
        ctx->stencil_cull.on = ft.stencil_func != GL_ALWAYS && (ft.fail == GL_KEEP || ft.write_mask == 0);
        ctx->stencil_cull.func = ft.stencil_func;
        ctx->stencil_cull.ref = (uint8_t)(ft.ref & ft.value_mask);
        ctx->stencil_cull.mask = (uint8_t)ft.value_mask;
    }
    unsigned int lod_units = 0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (units & (1u << u)) {
            lod_units |= (unsigned)texture_needs_lod(ctx->units[u].bound) << u;
            ctx->samplers[u] = texture_span_sampler(ctx->units[u].bound, ctx_simd(ctx));
            ctx->sample_group[u] = texture_span_sample_group(ctx->units[u].bound, ctx_simd(ctx));
        }
    const int lod = lod_units != 0;
    /* a lone REPLACE unit of an RGBA texture: its texel is the colour
    ** (texture_env), so it is sampled into the colour and the primary
    ** colour is not formed */
    const int lone = units && !(units & (units - 1)) ? __builtin_ctz(units) : -1;
    const int direct = lone >= 0 && ctx->units[lone].env_mode == GL_REPLACE
                    && ctx->units[lone].bound->format == GL_RGBA;
    /* the first unit's MODULATE of an RGBA or RGB texture */
    const int first = units ? __builtin_ctz(units) : -1;
    const int first_modulates = first >= 0 && ctx->units[first].env_mode == GL_MODULATE
                             && (ctx->units[first].bound->format == GL_RGBA
                                 || ctx->units[first].bound->format == GL_RGB);
    /* it takes the colour as it is formed (stage_color_modulate), after
    ** the fetches */
    const int modulate = first_modulates;
    const int bk = span_blend_kind(ctx);
    const int plain = ctx->color_format == GLES_COLOR_RGBA8888 && ctx->color_mask[0] && ctx->color_mask[1]
                   && ctx->color_mask[2] && ctx->color_mask[3];
    /* that MODULATE of the only unit, the alpha test (before any depth or
    ** stencil test) and an RGBA8888 write with nothing else between them:
    ** one stage, where the instance has it (stage_modulate_write) */
    const int plain565 = ctx->color_format == GLES_COLOR_RGB565 && ctx->color_mask[0] && ctx->color_mask[1]
                      && ctx->color_mask[2];
    const int target_fused = !ctx->fog && !(ctx->alpha_test && tests)
                          && ((plain && bk >= 0) || (plain565 && (bk == 0 || bk == 1) && fs->modulate_write_565))
                          && !ctx->color_logic_op;
    const int writes_fused = lone >= 0 && target_fused && fs->modulate_write != NULL;
    const int modulate_write = writes_fused && first_modulates;
    /* a first unit's DOT3 before a second one's MODULATE, on triangles
    ** (stage_dot3_write; the second unit sampled there too where it can
    ** be, stage_dot3_sample_write). In the fixed build not DOT3_RGBA under
    ** SRC_ALPHA blending on RGBA8888: its alpha carries DOT3's error into
    ** both blend terms, past what the byte's margin proves
    ** (docs/architecture.md) */
    const int dot3 = !rect && target_fused && fs->dot3_write != NULL && span_dot3_pair(ctx)
                  && (fs->dot3_exact || !(bk == 1 && plain && ctx->units[first].combine_rgb == GL_DOT3_RGBA));
    /* where no fused stage takes that pair (a target or blend none takes;
    ** DOT3_RGBA under SRC_ALPHA on RGBA8888 in the double build's AVX2
    ** instance), the colour and both units' environments in one stage
    ** after the fetches (stage_color_dot3_modulate) */
    const int dot3_env = !rect && !dot3 && cs->color_dot3_modulate != NULL && span_dot3_pair(ctx);
    /* ... sampling too where the unit's sampler is a bilinear vector kernel
    ** (stage_sample_write), and then also for a lone REPLACE unit of an
    ** RGBA texture */
    const int sample_write = writes_fused && (first_modulates || direct) && ctx->sample_group[lone] > 1;
    /* a rectangle's colour and window depth; the fused stage and
    ** stage_color_modulate read the colour themselves and a lone REPLACE
    ** unit of an RGBA texture samples into it, so only the tests need it
    ** then */
    if (rect && (!(modulate_write || sample_write || direct || modulate) || tests))
        s[n++] = cs->rect_source;
    /* the window depth is for the depth test only */
    if (tests && early) {
        if (!rect && depth)
            s[n++] = cs->depth;
        s[n++] = zless ? cs->zless_early : cs->tests_early;
    }
    if (!color_work)
        return n;
    if (!rect) {
        /* the weights, with the level of detail's neighbours (their
        ** tangents) where a unit needs them */
        s[n++] = lod ? cs->persp_lod : cs->persp;
        /* ... and the coordinates of the one unit with a level of detail
        ** where it is the first unit: its fetch is the first stage to read
        ** or write b->tc, tx and ty (not so in the DOT3 pair's stages) */
        if (first >= 0 && lod_units == 1u << first && !dot3)
            ctx->chain_lod_unit = first;
        /* the first texture stage after it is the first unit's: its
        ** coordinates come with the weights where it needs no neighbours */
        if (first >= 0 && !texture_needs_lod(ctx->units[first].bound))
            ctx->chain_coords_unit = first;
        if (!direct && !modulate && !dot3 && !dot3_env)
            s[n++] = cs->color;
    }
    if (dot3) {
        const int second = __builtin_ctz(units & (units - 1));
        /* the first unit's coordinates only where the stage samples it:
        ** stage_persp forms them into b->tx then, and the second's into
        ** b->tc where it has no level of detail */
        if (ctx->sample_group[first] > 1 && ctx->chain_coords_unit == first
            && !texture_needs_lod(ctx->units[second].bound)) {
            ctx->chain_coords_tx_unit = first;
            ctx->chain_coords_unit = second;
        }
        if (ctx->sample_group[second] > 1) {
            /* (the fused stage forms both units' coordinates where
            ** stage_persp left any: STAGE(fused_coords)) */
            if (ctx->sample_group[first] <= 1)
                s[n++] = cs->fetch[first];
            /* both units' coordinates from stage_persp: the stage may form
            ** them and the weights itself */
            ctx->chain_fused_lanes = ctx->chain_coords_tx_unit == first && ctx->chain_coords_unit == second;
            s[n++] = fs->dot3_sample_write;
        } else {
            s[n++] = ctx->sample_group[first] > 1 ? cs->coords_tx[first] : cs->fetch[first];
            s[n++] = cs->fetch[second];
            s[n++] = fs->dot3_write;
        }
        return n;
    }
    if (sample_write) {
        if (rect)   /* (a triangle's, the fused stage forms: STAGE(fused_coords)) */
            s[n++] = cs->coords_rect[lone];
        else        /* (... or where stage_persp forms them, it may form them itself) */
            ctx->chain_fused_lanes = ctx->chain_coords_unit == lone;
        s[n++] = fs->sample_write;
        return n;
    }
    /* the fog and the plain write (RGBA8888 or RGB565) as one stage where
    ** the instance has it (nothing between them) */
    const int fog_then_write = ctx->fog && !rect && !ctx->alpha_test && !(tests && !early) && !no_color && bk == 0
                            && !ctx->color_logic_op;
    const int fog_write = fog_then_write && plain && cs->fog_write_rgba8;
    const int fog_write_565 = fog_then_write && plain565 && cs->fog_write_565;
    /* ... with the sampling of a lone REPLACE unit of an RGBA texture with
    ** a level of detail before them, where the CPU has AVX2 but not
    ** AVX-512 (the AVX-512 instance keeps its own kernels there): in the
    ** double build too, which has no fog-and-write stage of its own */
    if (direct && fog_then_write && (plain || plain565) && cs->sample_fog_write_rgba8
        && texture_needs_lod(ctx->units[lone].bound) && ctx_simd(ctx) < SIMD_AVX512) {
        s[n++] = plain ? cs->sample_fog_write_rgba8 : cs->sample_fog_write_565;
        return n;
    }
    if (direct) {
        s[n++] = rect ? cs->fetch_rect_direct[lone] : cs->fetch_direct[lone];
    } else {
        /* the second unit's coordinates into b->tx, with the first's,
        ** where neither has a level of detail (its fetch samples there) */
        const unsigned int rest = units & (units - 1);
        if (!rect && rest && ctx->chain_coords_unit == first
            && !texture_needs_lod(ctx->units[__builtin_ctz(rest)].bound))
            ctx->chain_coords_tx_unit = __builtin_ctz(rest);
        for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
            if (units & (1u << u))
                s[n++] = rect ? cs->fetch_rect[u] : cs->fetch[u];
        if (modulate_write) {
            s[n++] = fs->modulate_write;
            return n;
        }
        if (dot3_env)
            s[n++] = cs->color_dot3_modulate;
        else
            for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
                if (units & (1u << u))
                    s[n++] = modulate && u == first ? cs->color_modulate[u] : cs->env[u];
    }
    if (ctx->fog && !fog_write && !fog_write_565)
        s[n++] = rect ? cs->fog_const : cs->fog;
    if (ctx->alpha_test)
        s[n++] = cs->alpha;
    if (tests && !early) {
        if (!rect && depth)
            s[n++] = cs->depth;
        s[n++] = cs->tests_late;
    }
    if (no_color)
        ;
    else if (fog_write)
        s[n++] = cs->fog_write_rgba8;
    else if (fog_write_565)
        s[n++] = cs->fog_write_565;
    else if (plain && bk == 0 && !ctx->color_logic_op)
        s[n++] = cs->write_rgba8;
    else if (plain && bk == 1)
        s[n++] = cs->write_rgba8_alpha;
    else if (plain && bk == 2)
        s[n++] = cs->write_rgba8_add;
    else if (ctx->color_format == GLES_COLOR_RGBA8888 && ctx->color_logic_op)
        s[n++] = cs->write_rgba8_logic;
    else if (ctx->color_format == GLES_COLOR_RGBA8888 && bk >= 0)
        s[n++] = cs->write_rgba8_masked;
    else if (plain565 && bk == 0 && !ctx->color_logic_op)
        s[n++] = cs->write_565;
    else if (plain565 && bk == 1)
        s[n++] = cs->write_565_alpha;
    else
        s[n++] = cs->write;
    return n;
}

void span_chain_compose(GlesContext *ctx) { ctx->chain_len = compose(ctx, ctx->chain, 0); }

/* asks for the cache lines of `bytes` bytes at p ahead of the chain's
** stages: the writer reads the framebuffer last, after the texture work
** that can hide the wait for it (a row of a scattered small primitive is
** rarely cached) */
static void prefetch_bytes(const void *p, size_t bytes)
{
    const char *c = p;
    for (size_t i = 0; i < bytes; i += 64)
        __builtin_prefetch(c + i, 1, 3);
    __builtin_prefetch(c + bytes - 1, 1, 3);
}

/* a chunk's slots before any test: offsets 0, 1, 2, ... */
#define SPAN_OFFSETS4(i) (i), (i) + 1, (i) + 2, (i) + 3
#define SPAN_OFFSETS16(i) SPAN_OFFSETS4(i), SPAN_OFFSETS4((i) + 4), SPAN_OFFSETS4((i) + 8), SPAN_OFFSETS4((i) + 12)
#define SPAN_OFFSETS64(i) SPAN_OFFSETS16(i), SPAN_OFFSETS16((i) + 16), SPAN_OFFSETS16((i) + 32), SPAN_OFFSETS16((i) + 48)
static const uint8_t span_offsets[SPAN_CHUNK] = { SPAN_OFFSETS64(0), SPAN_OFFSETS64(64) };
#undef SPAN_OFFSETS64
#undef SPAN_OFFSETS16
#undef SPAN_OFFSETS4
_Static_assert(SPAN_CHUNK == 128, "span_offsets lists SPAN_CHUNK offsets");

/* {====================================================================
** the stencil cull: where a fragment that fails the stencil test leaves
** the stencil value as it is (its op is KEEP, or nothing of the value is
** writable), failing is all it does (§4.1.5: no depth, no colour), so a
** chunk's fragments before its first pass and after its last can go
** before any stage runs, and a chunk with no pass goes whole */

/* a row's stencil values with the cull's state (ctx->stencil_cull) and
** the chain's table of the test's outcome per stored value */
typedef struct StencilCull {
    const uint8_t *row;         /* NULL: no cull */
    const uint8_t *pass;        /* ctx->stencil_lut[0] */
    unsigned int func;
    uint8_t ref, mask;
} StencilCull;

static inline void stencil_cull_setup(const GlesContext *ctx, int y, StencilCull *sc)
{
    sc->row = ctx->stencil_cull.on ? ctx->stencil + (size_t)y * (size_t)ctx->width : NULL;
    sc->pass = ctx->stencil_lut[0];
    sc->func = ctx->stencil_cull.func;
    sc->ref = ctx->stencil_cull.ref;
    sc->mask = ctx->stencil_cull.mask;
}

/* whether the stencil test passes at pixel x */
static inline int stencil_cull_pass(const StencilCull *sc, int x) { return sc->pass[sc->row[x]]; }

#if defined(__SSE2__)
#include <emmintrin.h>
/* the test's outcome at the sixteen pixels from x, as bits */
static inline unsigned stencil_cull_pass16(const StencilCull *sc, int x)
{
    const __m128i v = _mm_and_si128(_mm_loadu_si128((const __m128i *)(const void *)(sc->row + x)),
                                    _mm_set1_epi8((char)sc->mask));
    const __m128i r = _mm_set1_epi8((char)sc->ref);
    /* le(a, b): a <= b as unsigned bytes */
#define STENCIL_LE(a, b) _mm_cmpeq_epi8(_mm_min_epu8(a, b), a)
    unsigned m;
    switch (sc->func) {
    case GL_EQUAL: m = (unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(r, v)); break;
    case GL_NOTEQUAL: m = ~(unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(r, v)); break;
    case GL_LESS: m = ~(unsigned)_mm_movemask_epi8(STENCIL_LE(v, r)); break;     /* r < v */
    case GL_LEQUAL: m = (unsigned)_mm_movemask_epi8(STENCIL_LE(r, v)); break;
    case GL_GREATER: m = ~(unsigned)_mm_movemask_epi8(STENCIL_LE(r, v)); break;  /* r > v */
    case GL_GEQUAL: m = (unsigned)_mm_movemask_epi8(STENCIL_LE(v, r)); break;
    default: m = 0; break;      /* GL_NEVER */
    }
#undef STENCIL_LE
    return m & 0xFFFFu;
}
#endif

/* the first pixel of [x, x + n) where the test passes, or x + n; sixteen
** at a time where SSE2 runs */
static int stencil_cull_first(const StencilCull *sc, int x, int n)
{
    int i = 0;
#if defined(__SSE2__)
    for (; i + 16 <= n; i += 16) {
        const unsigned m = stencil_cull_pass16(sc, x + i);
        if (m)
            return x + i + __builtin_ctz(m);
    }
#endif
    for (; i < n && !stencil_cull_pass(sc, x + i); i++)
        ;
    return x + i;
}

/* the last pixel of [x, x + n) where the test passes, given that it
** passes at x */
static int stencil_cull_last(const StencilCull *sc, int x, int n)
{
    int e = x + n;
#if defined(__SSE2__)
    for (; e - 16 >= x; e -= 16) {
        const unsigned m = stencil_cull_pass16(sc, e - 16);
        if (m)
            return e - 16 + 31 - __builtin_clz(m);
    }
#endif
    while (!stencil_cull_pass(sc, e - 1))
        e--;
    return e - 1;
}

/* }==================================================================== */

/* one row's run [x0, x0 + n) through `count` stages, a chunk at a time */
static void run(GlesContext *ctx, const SpanStage *stages, int count, const TriSetup *t, const RectSetup *r, int y,
                int x0, int n)
{
    SpanBuf b;
    b.y = y;
    b.rect = r;
    StencilCull cull;
    stencil_cull_setup(ctx, y, &cull);
    if (n > 0) {
        const size_t at = (size_t)y * (size_t)ctx->width + (size_t)x0;
        const size_t bpp = (size_t)color_bytes(ctx->color_format);
        prefetch_bytes((const char *)ctx->color + at * bpp, (size_t)n * bpp);
        if (ctx->depth_test && ctx->depth)
            prefetch_bytes(ctx->depth + at, (size_t)n * 4);
    }
    for (int start = 0; start < n; start += SPAN_CHUNK) {
        int len = n - start < SPAN_CHUNK ? n - start : SPAN_CHUNK;
        b.x0 = x0 + start;
        if (cull.row) {
            const int first = stencil_cull_first(&cull, b.x0, len);
            if (first == b.x0 + len)
                continue;
            len = stencil_cull_last(&cull, first, b.x0 + len - first) - first + 1;
            b.x0 = first;
        }
        b.n = len;
        b.tc_unit = -1;
        b.tx_unit = -1;
        b.lod_unit = -1;
        b.lanes = 0;
        memcpy(b.k, span_offsets, SPAN_CHUNK);
        if (t)
            tri_edges_at(t, b.x0, y, b.e0);
        for (int i = 0; i < count && b.n > 0; i++)
            stages[i](ctx, t, &b);
    }
}

void span_chain(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    run(ctx, ctx->chain, ctx->chain_len, t, NULL, y, x0, n);
}

/* each enabled unit's s of columns x0..x1 (x1 for the right neighbours),
** computed once for all the rectangle's rows: a unit's s depends on the
** column only (rect_linear_s, sprite_s) */
static void rect_columns(GlesContext *ctx, RectSetup *r, int64_t x0, int64_t x1)
{
    r->col_x0 = x0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
        r->col_s[u] = NULL;
        const int coord = r->coord[u];
        if (!(ctx->tex_units_on & (1u << u)) || (coord != RECT_COORD_LINEAR && coord != RECT_COORD_SPRITE))
            continue;
        /* 0 <= x0 < x1 <= width: x1 - x0 + 1 entries fit the unit's width + 1 */
        TEXC *col = ctx->rect_s + (size_t)u * ((size_t)ctx->width + 1);
        for (int64_t px = x0; px <= x1; px++)
            col[px - x0] = coord == RECT_COORD_LINEAR ? rect_linear_s(r, u, px)
                                                      : sprite_s(r->sprite_x, r->sprite_size, px);
        r->col_s[u] = col;
    }
}

void span_rect(GlesContext *ctx, const RectSetup *r, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    if (!raster_owns_rows(ctx, y0, y1 - 1))
        return;
    SpanStage stages[GLES_MAX_STAGES];
    int count = compose(ctx, stages, 1);
    RectSetup rc = *r;
    rc.serial = ++ctx->prim_serial;
    rect_columns(ctx, &rc, x0, x1);
    for (int64_t y = y0; y < y1; y++)
        if (raster_owns_row(ctx, y))
            run(ctx, stages, count, NULL, &rc, (int)y, (int)x0, (int)(x1 - x0));
}

/* }==================================================================== */
