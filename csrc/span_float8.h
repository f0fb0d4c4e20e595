/*
** span_float8.h -- the float and double builds' fused stage: the colour,
** a lone unit's MODULATE of an RGBA or RGB texture (or REPLACE of an RGBA
** texture), the alpha test and the RGBA8888 or RGB565 write of eight
** fragments at a time, with the bilinear sampling of level 0 inside where
** the unit's sampler is the vector kernel. Lanes are GCC vectors of eight
** NUMs, one register per channel: eight floats in AVX2 (the float build,
** included by span_avx2.h inside its AVX2 target), eight doubles in
** AVX-512F (the double build, included by span_avx512.h inside its target:
** the same kernel in AVX2's four double lanes measured 10-20% slower than
** the separate stages). Every lane does the scalar code's IEEE operations
** in their order (frag_lerp3f, frag_clamp01, frag_mul, sample_level's
** GL_LINEAR and frag_bilerp_rgba8, fragment_alpha8, span_rgba8,
** fragment_channel), so every word is the separate stages' without a proof.
*/
#if SIMD_X86 && (defined(GLES_NUM_FLOAT) || SIMD_AVX512_INSTANCE)
#ifndef GLES_SPAN_FLOAT8_H
#define GLES_SPAN_FLOAT8_H

/* F8_N lanes of NUM; their comparisons' lanes (-1 or 0, as wide as a
** NUM); int32 lanes; F8_N stored RGB565 words */
#define F8_N 8
#if defined(GLES_NUM_FLOAT)
typedef float f8_num __attribute__((vector_size(32)));
typedef int32_t f8_mask __attribute__((vector_size(32)));
#else
typedef double f8_num __attribute__((vector_size(64)));
typedef int64_t f8_mask __attribute__((vector_size(64)));
#endif
typedef int32_t f8_i32 __attribute__((vector_size(32)));
typedef uint16_t f8_u16 __attribute__((vector_size(16)));

/* x in every lane (a broadcast: {0} + x would add 0 at every use) */
AVX2_INLINE f8_num f8_set1(NUM x)
{
#if defined(GLES_NUM_FLOAT)
    return (f8_num)_mm256_set1_ps(x);
#else
    return (f8_num)_mm512_set1_pd(x);
#endif
}

/* 1 when every lane of m is set */
AVX2_INLINE int f8_all(f8_mask m)
{
#if defined(GLES_NUM_FLOAT)
    return _mm256_movemask_ps((__m256)m) == 0xFF;
#else
    return _mm512_test_epi64_mask((__m512i)m, (__m512i)m) == 0xFF;
#endif
}

/* NUM_FLOOR per lane, for any finite value */
AVX2_INLINE f8_num f8_floor(f8_num v)
{
#if defined(GLES_NUM_FLOAT)
    return (f8_num)_mm256_floor_ps((__m256)v);
#else
    return (f8_num)_mm512_roundscale_pd((__m512d)v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
#endif
}

/* the min and max instructions per lane: the second operand where either
** is NaN or both are zeros */
AVX2_INLINE f8_num f8_min(f8_num a, f8_num b)
{
#if defined(GLES_NUM_FLOAT)
    return (f8_num)_mm256_min_ps((__m256)a, (__m256)b);
#else
    return (f8_num)_mm512_min_pd((__m512d)a, (__m512d)b);
#endif
}
AVX2_INLINE f8_num f8_max(f8_num a, f8_num b)
{
#if defined(GLES_NUM_FLOAT)
    return (f8_num)_mm256_max_ps((__m256)a, (__m256)b);
#else
    return (f8_num)_mm512_max_pd((__m512d)a, (__m512d)b);
#endif
}

/* frag_clamp01 (NaN and -0 pass as there: v4_clamp01's operand order) */
AVX2_INLINE f8_num f8_clamp01(f8_num v) { return f8_min(f8_set1(1), f8_max(f8_set1(0), v)); }

/* frag_to_unorm(v, maxval, t) for thresholds 0 <= t < 1 whose sum with
** maxval is exact (1/2 and the dither's odd 32nds): 0 unless v > 0 (x =
** v maxval + t is then below 1, or NaN, which max turns to 0), maxval
** from 1 up (x >= maxval), else x truncated; there fl(v maxval) <= maxval,
** so x <= maxval + t < maxval + 1 and the minimum with maxval truncates
** alike */
AVX2_INLINE f8_i32 f8_unorm(f8_num v, NUM maxval, f8_num t)
{
    const f8_num x = f8_min(f8_max(v * maxval + t, f8_set1(0)), f8_set1(maxval));
    return __builtin_convertvector(x, f8_i32);
}

/* frag_to_msb(v, bits): floor(v 2^bits), 0 unless v > 0 (max turns a
** product <= 0 or NaN to 0), at most 2^bits - 1 (the minimum with it
** truncates alike) */
AVX2_INLINE f8_i32 f8_msb(f8_num v, int bits)
{
    const NUM top = (NUM)(1 << bits);
    const f8_num x = f8_min(f8_max(v * top, f8_set1(0)), f8_set1(top - 1));
    return __builtin_convertvector(x, f8_i32);      /* x >= 0: truncation is the floor */
}

/* int32 lanes as floats */
AVX2_INLINE f8_num f8_from_i32(f8_i32 c)
{
#if defined(GLES_NUM_FLOAT)
    return (f8_num)_mm256_cvtepi32_ps((__m256i)c);
#else
    return (f8_num)_mm512_cvtepi32_pd((__m256i)c);
#endif
}

/* frag_from_unorm(c, maxval) of integer lanes */
AVX2_INLINE f8_num f8_from_unorm(f8_i32 c, NUM maxval)
{
#if defined(GLES_NUM_FLOAT)
    return f8_from_i32(c) / maxval;
#else
    return (f8_num)v8_from_unorm56((__m256i)c, (int)maxval);    /* 31 or 63 */
#endif
}

/* fragment_channel(v, bits, dither, t) of RGB565's 5- or 6-bit channels */
AVX2_INLINE f8_i32 f8_channel(f8_num v, int bits, int dither, f8_num t)
{
    return dither ? f8_unorm(v, (NUM)((1 << bits) - 1), t) : f8_msb(v, bits);
}

/* lanes L of out[i] = base[L stride + i] (i < 4), for F8_N slots */
AVX2_INLINE void f8_gather_rows(const NUM *base, size_t stride, f8_num out[4])
{
    for (int i = 0; i < 4; i++) {
        f8_num v = { 0 };
        for (int L = 0; L < F8_N; L++)
            v[L] = base[(size_t)L * stride + (size_t)i];
        out[i] = v;
    }
}

/* the three weights of fragments p[0..F8_N-1] as lanes: lane L of w[i] is
** value 3L + i of the three vectors that hold them */
AVX2_INLINE void f8_weights(const WGT (*p)[3], f8_num w[3])
{
    f8_num q0, q1, q2;
    memcpy(&q0, &p[0][0], sizeof q0);
    memcpy(&q1, &p[0][0] + F8_N, sizeof q1);
    memcpy(&q2, &p[0][0] + 2 * F8_N, sizeof q2);
    const f8_num a0 = __builtin_shuffle(q0, q1, (f8_mask){ 0, 3, 6, 9, 12, 15, 0, 0 });
    const f8_num a1 = __builtin_shuffle(q0, q1, (f8_mask){ 1, 4, 7, 10, 13, 0, 0, 0 });
    const f8_num a2 = __builtin_shuffle(q0, q1, (f8_mask){ 2, 5, 8, 11, 14, 0, 0, 0 });
    w[0] = __builtin_shuffle(a0, q2, (f8_mask){ 0, 1, 2, 3, 4, 5, 10, 13 });
    w[1] = __builtin_shuffle(a1, q2, (f8_mask){ 0, 1, 2, 3, 4, 8, 11, 14 });
    w[2] = __builtin_shuffle(a2, q2, (f8_mask){ 0, 1, 2, 3, 4, 9, 12, 15 });
}

/* the s and t of coordinates tc[0..F8_N-1] as lanes */
AVX2_INLINE void f8_coords(const TexCoord *tc, f8_num *s, f8_num *t)
{
    _Static_assert(sizeof(TexCoord) == 2 * sizeof(NUM), "TexCoord is s, t");
    f8_num q0, q1;
    memcpy(&q0, tc, sizeof q0);
    memcpy(&q1, tc + F8_N / 2, sizeof q1);
    *s = __builtin_shuffle(q0, q1, (f8_mask){ 0, 2, 4, 6, 8, 10, 12, 14 });
    *t = __builtin_shuffle(q0, q1, (f8_mask){ 1, 3, 5, 7, 9, 11, 13, 15 });
}

#if !defined(GLES_NUM_FLOAT)
/* what the double build's fused stage needs to form an affine triangle's
** weights and coordinates in its lanes, where stage_persp leaves them
** (SpanBuf.lanes): edges 1 and 2 at slot 0 (e1, e2) and their steps per
** slot (a1, a2), exact integers as doubles at every slot of the chunk
** (edge_steps_exact), 1 / area, and the vertex s and t of the sampled
** unit (s, t) and of the DOT3 pair's first unit (s0, t0) */
typedef struct F8Affine {
    double e1, e2, a1, a2, inv_area;
    double s[3], t[3], s0[3], t0[3];
} F8Affine;

/* the weights of the slots at offsets k[0..7] in d8_affine_steps'
** operations: o_1 = e_1 inv_area, o_2 likewise, o_0 = (1 - o_1) - o_2,
** each edge value e + k a an exact integer however it is summed (the
** product k a, |a| <= 2^44 and k < 2^8, is exact too) */
AVX2_INLINE void f8_affine_weights(const F8Affine *af, const uint8_t *k, f8_num w[3])
{
    const f8_num kd = (f8_num)_mm512_cvtepi32_pd(_mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)k)));
    w[1] = (af->e1 + kd * af->a1) * af->inv_area;
    w[2] = (af->e2 + kd * af->a2) * af->inv_area;
    w[0] = (1 - w[1]) - w[2];
}

/* a coordinate at weights w, v8_lerp3's (a0 w0 + a1 w1) + a2 w2 */
AVX2_INLINE f8_num f8_lerp3(const double a[3], const f8_num w[3]) { return a[0] * w[0] + a[1] * w[1] + a[2] * w[2]; }
#else
typedef struct F8Affine F8Affine;   /* (the float build forms them in memory) */
#endif

/* m ? a : b of int32 lanes */
AVX2_INLINE f8_i32 f8_sel_i32(f8_i32 m, f8_i32 a, f8_i32 b) { return (a & m) | (b & ~m); }

/* sample_level's GL_LINEAR indices and weight along one axis of size n (a
** power of two), REPEAT or CLAMP_TO_EDGE, for finite coordinates: the
** operations of reduce_coord, texc_scale, texc_ifloor, texc_frac_weight and
** wrap_index (v4_linear_axis's, in F8_N lanes) */
AVX2_INLINE void f8_linear_axis(f8_num s, int n, int repeat, f8_i32 *i0, f8_i32 *i1, f8_num *w)
{
    if (repeat)
        s = s - f8_floor(s);
    else
        s = f8_min(f8_max(s, f8_set1(-1)), f8_set1(2));     /* s is finite */
    const f8_num uu = s * (NUM)n - (NUM)0.5;
    const f8_num fl = f8_floor(uu);
    *w = uu - fl;
    const f8_i32 i = __builtin_convertvector(fl, f8_i32), j = i + 1;   /* |fl| <= 2n + 1 */
    if (repeat) {
        *i0 = i & (n - 1);
        *i1 = j & (n - 1);
    } else {
        const f8_i32 zero = { 0 }, top = zero + (n - 1);
        *i0 = f8_sel_i32(i > top, top, f8_sel_i32(i < zero, zero, i));
        *i1 = f8_sel_i32(j > top, top, f8_sel_i32(j < zero, zero, j));
    }
}

/* fragment_compare(f, a, ref) of int32 lanes (values 0..255) */
AVX2_INLINE f8_i32 f8_compare(const ModWriteAlpha *f, f8_i32 a)
{
    f8_i32 lt, eq, gt;
    memcpy(&lt, &f->cmp.lt, sizeof lt);
    memcpy(&eq, &f->cmp.eq, sizeof eq);
    memcpy(&gt, &f->cmp.gt, sizeof gt);
    const f8_i32 ref = (f8_i32){ 0 } + (int32_t)f->ref;
    const f8_i32 below = a < ref, above = a > ref;
    return (below & lt) | (above & gt) | (~(below | above) & eq);
}

/* the fused stage's state for one chunk */
typedef struct F8ModWrite {
    NUM col[3][4];               /* the vertex colours, or the flat colour clamped in col[0] */
    int smooth, rgb, replace, kind;
    ModWriteAlpha alpha;         /* the alpha test */
    int dither;
    FRAGV t_row[4];              /* the dither thresholds by x & 3 */
    NUM thr[4][F8_N];            /* those of F8_N neighbouring pixels from x & 3 = r */
    ModWriteTexture tx;          /* where the kernel samples (source 1) */
    /* the DOT3 pair (span_dot3_pair): 0, or 1 for the first unit's
    ** DOT3_RGB, 2 for DOT3_RGBA; tx0 where its texels are sampled here */
    int dot3;
    ModWriteTexture tx0;
} F8ModWrite;

static inline void f8_modwrite_setup(F8ModWrite *m, const FRAGV *const a[3], int smooth, int rgb, int replace,
                                     int kind, unsigned int alpha_func, uint32_t alpha_ref)
{
    memset(m, 0, sizeof *m);
    m->smooth = smooth, m->rgb = rgb && !replace, m->replace = replace, m->kind = kind;
    modwrite_alpha_setup(&m->alpha, alpha_func, alpha_ref);
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 4; c++)
            m->col[i][c] = smooth ? a[i][c] : frag_clamp01(a[0][c]);
}

/* RGB565's dither thresholds t_row[x & 3] (dither) */
static inline void f8_modwrite_dither(F8ModWrite *m, int dither, const FRAGV t_row[4])
{
    m->dither = dither;
    for (int x = 0; x < 4; x++)
        m->t_row[x] = t_row[x];
    for (int r = 0; r < 4; r++)
        for (int L = 0; L < F8_N; L++)
            m->thr[r][L] = t_row[(r + L) & 3];
}

/* channel i (byte i) of RGBA8888 words as frag_from_unorm(., 255) */
AVX2_INLINE f8_num f8_byte(f8_i32 g, int i)
{
#if defined(GLES_NUM_FLOAT)
    /* v4_div255's d / 255 in eight lanes, the byte by a shuffle */
    const f8_num d = f8_from_i32((f8_i32)_mm256_shuffle_epi8((__m256i)g, avx2_byte_pick8(i)));
    return (f8_num)_mm256_fmadd_ps((__m256)d, _mm256_set1_ps(UNORM8_RECIP_HI),
                                   (__m256)(d * f8_set1(UNORM8_RECIP_LO)));
#else
    return (f8_num)v8_byte_unorm8((__m256i)g, 8 * i);
#endif
}

/* a group's four texel words per lane and its weights along s and t:
** what f8_sample_level reads from memory, apart from what it computes */
typedef struct F8Texels {
    __m256i g[4];
    f8_num a, b;
} F8Texels;

/* the texel words and weights of coordinates tc[0..F8_N-1] on a w x h
** level (powers of two; REPEAT or CLAMP_TO_EDGE per axis), as
** sample_level's GL_LINEAR finds them; 0 when a coordinate is not finite.
** `rows`: try avx2_row_texels8's loads before the gathers. */
AVX2_INLINE int f8_texels_st(const uint32_t *texels, int w, int h, int repeat_s, int repeat_t, int rows, f8_num s,
                             f8_num t, F8Texels *x)
{
    const NUM inf = (NUM)INFINITY;
    if (!f8_all((s < inf) & (s > -inf) & (t < inf) & (t > -inf)))
        return 0;
    f8_i32 x0, x1, y0, y1;
    f8_linear_axis(s, w, repeat_s, &x0, &x1, &x->a);
    f8_linear_axis(t, h, repeat_t, &y0, &y1, &x->b);
    avx2_texel_words8(texels, w, (int64_t)w * h, (__m256i)x0, (__m256i)x1, (__m256i)y0, (__m256i)y1, rows, x->g);
    return 1;
}

/* f8_texels_st at the coordinates tc[0..F8_N-1] */
AVX2_INLINE int f8_texels(const uint32_t *texels, int w, int h, int repeat_s, int repeat_t, int rows,
                          const TexCoord *tc, F8Texels *x)
{
    f8_num s, t;
    f8_coords(tc, &s, &t);
    return f8_texels_st(texels, w, h, repeat_s, repeat_t, rows, s, t, x);
}

/* the bilinear texels T of f8_texels' words and weights
** (frag_bilerp_rgba8's operations) */
AVX2_INLINE void f8_bilerp(const F8Texels *x, f8_num T[4])
{
    const __m256i *g = x->g;
    const f8_num a = x->a, b = x->b;
#if defined(GLES_NUM_FLOAT)
    const f8_i32 g00 = (f8_i32)g[0], g10 = (f8_i32)g[1], g01 = (f8_i32)g[2], g11 = (f8_i32)g[3];
    const f8_num ia = 1 - a, ib = 1 - b;
    for (int i = 0; i < 4; i++) {
        const f8_num top = f8_byte(g00, i) * ia + f8_byte(g10, i) * a;
        const f8_num bot = f8_byte(g01, i) * ia + f8_byte(g11, i) * a;
        T[i] = top * ib + bot * b;
    }
#else
    __m512d ch[4];
    v8_bilerp_channels(g, (__m512d)a, (__m512d)b, ch);
    for (int i = 0; i < 4; i++)
        T[i] = (f8_num)ch[i];
#endif
}

/* the texels of coordinates tc[0..F8_N-1] on a w x h level as
** sample_level's GL_LINEAR gives them (f8_texels, f8_bilerp); 0 when a
** coordinate is not finite */
AVX2_INLINE int f8_sample_level(const uint32_t *texels, int w, int h, int repeat_s, int repeat_t, int rows,
                                const TexCoord *tc, f8_num T[4])
{
    F8Texels x;
    if (!f8_texels(texels, w, h, repeat_s, repeat_t, rows, tc, &x))
        return 0;
    f8_bilerp(&x, T);
    return 1;
}

/* f8_texels of a fused stage's texture at tc[0..F8_N-1], or where af is
** not NULL at the weights w of its vertex values sv, tv */
AVX2_INLINE int f8_texels_of(const ModWriteTexture *tx, const TexCoord *tc, const F8Affine *af, const double *sv,
                             const double *tv, const f8_num w[3], F8Texels *x)
{
#if !defined(GLES_NUM_FLOAT)
    if (af)
        return f8_texels_st(tx->texels, tx->w, tx->h, tx->repeat_s, tx->repeat_t, 1, f8_lerp3(sv, w),
                            f8_lerp3(tv, w), x);
#else
    (void)af, (void)sv, (void)tv, (void)w;
#endif
    return f8_texels(tx->texels, tx->w, tx->h, tx->repeat_s, tx->repeat_t, 1, tc, x);
}

/* the coordinates f8_texels_of reads, in memory: tc + j, or where af is
** not NULL those at the weights w stored into buf */
AVX2_INLINE const TexCoord *f8_coords_at(const TexCoord *tc, int j, const F8Affine *af, const double *sv,
                                         const double *tv, const f8_num w[3], TexCoord buf[F8_N])
{
#if !defined(GLES_NUM_FLOAT)
    if (af) {
        v8_store_st8((__m512d)f8_lerp3(sv, w), (__m512d)f8_lerp3(tv, w), buf);
        return buf;
    }
#else
    (void)af, (void)sv, (void)tv, (void)w, (void)buf;
#endif
    return tc + j;
}

#if defined(GLES_NUM_FLOAT)
/* eight fragments' channels T[0..3] (lanes) stored as out[k stride + channel] */
AVX2_INLINE void f8_store_channels(const f8_num T[4], float *out, size_t stride)
{
    /* four channel registers to eight fragments' four channels */
    const __m256 rg_lo = _mm256_unpacklo_ps((__m256)T[0], (__m256)T[1]);
    const __m256 rg_hi = _mm256_unpackhi_ps((__m256)T[0], (__m256)T[1]);
    const __m256 ba_lo = _mm256_unpacklo_ps((__m256)T[2], (__m256)T[3]);
    const __m256 ba_hi = _mm256_unpackhi_ps((__m256)T[2], (__m256)T[3]);
    const __m256 f[4] = { _mm256_shuffle_ps(rg_lo, ba_lo, _MM_SHUFFLE(1, 0, 1, 0)),    /* fragments 0 | 4 */
                          _mm256_shuffle_ps(rg_lo, ba_lo, _MM_SHUFFLE(3, 2, 3, 2)),    /* 1 | 5 */
                          _mm256_shuffle_ps(rg_hi, ba_hi, _MM_SHUFFLE(1, 0, 1, 0)),    /* 2 | 6 */
                          _mm256_shuffle_ps(rg_hi, ba_hi, _MM_SHUFFLE(3, 2, 3, 2)) };  /* 3 | 7 */
    for (int k = 0; k < 4; k++) {
        _mm_storeu_ps(out + (size_t)k * stride, _mm256_castps256_ps128(f[k]));
        _mm_storeu_ps(out + (size_t)(k + 4) * stride, _mm256_extractf128_ps(f[k], 1));
    }
}

/* the float build's bilinear span kernel (sample_linear4): fragments
** 0..n-1 of a power-of-two level, REPEAT or CLAMP_TO_EDGE on each axis,
** eight at a time by f8_sample_level, stored as out[k stride + channel];
** stops before the first eight with a coordinate that is not finite and
** returns the count done (a multiple of 8; AVX2's four take the rest) */
static int f8_sample_linear(const TexImage *li, int n, const TexCoord *c, float *out, size_t stride, int repeat_s,
                            int repeat_t, int rows)
{
    int j = 0;
    for (; j + F8_N <= n; j += F8_N) {
        f8_num T[4];
        if (!f8_sample_level(li->texels, li->width, li->height, repeat_s, repeat_t, rows, c + j, T))
            break;
        f8_store_channels(T, out + (size_t)j * stride, stride);
    }
    return j;
}

/* f8_sample_linear of two levels l1, l2 at the same coordinates (not read
** by rows), mixed by frac[0..n) as lod_block mixes them (t1 + frac (t2 -
** t1) per channel), with no store of either level's texels between;
** returns the number of fragments done (as there) */
static int f8_sample_linear_mix(const TexImage *l1, const TexImage *l2, int n, const TexCoord *c, const float *frac,
                                float *out, size_t stride, int repeat_s, int repeat_t)
{
    int j = 0;
    for (; j + F8_N <= n; j += F8_N) {
        f8_num T1[4], T2[4], f;
        if (!f8_sample_level(l1->texels, l1->width, l1->height, repeat_s, repeat_t, 0, c + j, T1)
            || !f8_sample_level(l2->texels, l2->width, l2->height, repeat_s, repeat_t, 0, c + j, T2))
            break;
        memcpy(&f, frac + j, sizeof f);
        for (int k = 0; k < 4; k++)
            T1[k] = T1[k] + f * (T2[k] - T1[k]);
        f8_store_channels(T1, out + (size_t)j * stride, stride);
    }
    return j;
}
#endif

/* the DOT3 pair's first unit over colour c with its texels T0, in
** stage_color_dot3_modulate's operations and order (combine_block's: the
** sum from 0, then times 4; the scales of 1 left out, as there): (T0 -
** 1/2)(c - 1/2) per rgb channel, 4 ((0 + p0) + p1) + p2 clamped into
** every rgb channel, and into alpha for DOT3_RGBA; else the clamped alpha
** product T0 c (MODULATE) */
AVX2_INLINE void f8_dot3(int rgba, const f8_num T0[4], f8_num c[4])
{
    const f8_num half = f8_set1((NUM)0.5);
    f8_num sum = f8_set1(0);
    for (int i = 0; i < 3; i++)
        sum = sum + (T0[i] - half) * (c[i] - half);
    const f8_num d = f8_clamp01(sum * (NUM)4);
    c[3] = rgba ? d : f8_clamp01(T0[3] * c[3]);
    c[0] = c[1] = c[2] = d;
}

/* the words written over d (lanes of the stored words) by F8_N fragments
** with texels T and weights w (lanes; read where smooth) (with dot3, T0
** the first unit's texels); thr: the dither thresholds (RGB565) */
AVX2_INLINE f8_i32 f8_modwrite(const F8ModWrite *m, int smooth, int kind, int rgb565, int dot3, const f8_num w[3],
                               const f8_num T0[4], const f8_num T[4], f8_i32 d, f8_num thr)
{
    f8_num y[4];
    if (m->replace) {
        for (int i = 0; i < 4; i++)
            y[i] = T[i];
    } else {
        f8_num c[4];
        if (smooth) {
            for (int i = 0; i < 4; i++)
                c[i] = f8_clamp01(f8_set1(m->col[0][i]) * w[0] + f8_set1(m->col[1][i]) * w[1]
                                  + f8_set1(m->col[2][i]) * w[2]);
        } else {
            for (int i = 0; i < 4; i++)
                c[i] = f8_set1(m->col[0][i]);
        }
        if (dot3)
            f8_dot3(m->dot3 == 2, T0, c);
        for (int i = 0; i < 4; i++)
            y[i] = c[i] * T[i];
        if (m->rgb)
            y[3] = c[3];
    }
    const f8_num half = f8_set1((NUM)0.5);
    f8_i32 pass = { 0 };
    pass = ~pass;
    if (m->alpha.test)
        pass = f8_compare(&m->alpha, f8_unorm(y[3], 255, half));
    if (kind) {
        for (int i = 0; i < 4; i++)
            y[i] = f8_clamp01(y[i]);
        const f8_num va = y[3], ia = 1 - va;
        for (int i = 0; i < (rgb565 ? 3 : 4); i++) {
            f8_num di;
            if (!rgb565)
                di = f8_byte(d, i);
            else if (i == 1)
                di = f8_from_unorm((d >> 5) & 63, 63);
            else
                di = f8_from_unorm((d >> (i == 0 ? 11 : 0)) & 31, 31);
            y[i] = kind == 1 ? y[i] * va + di * ia : y[i] + di;
        }
    }
    f8_i32 word;
    if (rgb565)
        word = (f8_channel(y[0], 5, m->dither, thr) << 11) | (f8_channel(y[1], 6, m->dither, thr) << 5)
             | f8_channel(y[2], 5, m->dither, thr);
    else
        word = f8_unorm(y[0], 255, half) | (f8_unorm(y[1], 255, half) << 8) | (f8_unorm(y[2], 255, half) << 16)
             | (f8_unorm(y[3], 255, half) << 24);
    return (pass & word) | (~pass & d);
}

/* the kernel over fragments 0..n-1 (n a multiple of F8_N, the first live
** ones live, the rest, fewer than F8_N, copies of the last live one: a
** group of copies alone would read the word its original wrote; or where
** modwrite_overlaps, n = live, a last partial group taken as the last
** F8_N again) at the ascending offsets k of dst (pixel x0 + k): texels
** from source 0 (ct + j stride, sampled by a fetch stage) or 1 (sampled
** here at tc). With dot3 the first unit's texels come from ct0 + j stride
** (fetched) or are sampled here at tc0 (where ct0 is NULL). Where af is
** not NULL (source 1, the double build) the weights and both coordinates
** are formed here from the offsets k instead of read from p, tc and tc0. */
AVX2_INLINE void f8_modwrite_run(const F8ModWrite *mw, int src, int smooth, int kind, int rgb565, int dot3, int n,
                                 int live, const uint8_t *k, const WGT (*p)[3], const FRAGV *ct0,
                                 const TexCoord *tc0, const FRAGV *ct, size_t stride, const TexCoord *tc, int x0,
                                 void *dst, const F8Affine *af)
{
    const F8ModWrite local = *mw, *m = &local;   /* not aliased by the framebuffer stores */
    uint32_t *d32 = dst;
    uint16_t *d16 = dst;
#if !defined(GLES_NUM_FLOAT)
    const double *sv = af ? af->s : NULL, *tv = af ? af->t : NULL, *sv0 = af ? af->s0 : NULL,
                 *tv0 = af ? af->t0 : NULL;
#else
    const double *sv = NULL, *tv = NULL, *sv0 = NULL, *tv0 = NULL;
#endif
    /* source 1: each group's texel words are read one group ahead, so that
    ** their loads (gathers, on a rotated texture) overlap the arithmetic of
    ** the group before (and where af, its weights formed then); not so for
    ** the double build's DOT3 pair, whose two textures' words held across
    ** the loop leave too few registers (measured slower, rotated or not) */
#if defined(GLES_NUM_FLOAT)
    const int ahead = 1;
#else
    const int ahead = !dot3;
#endif
    F8Texels next = { 0 }, next0 = { 0 };
    f8_num wnext[3] = { { 0 }, { 0 }, { 0 } };
    const int sample0 = dot3 && ct0 == NULL;      /* (the DOT3 unit's texels, the same way) */
#if !defined(GLES_NUM_FLOAT)
    if (ahead && af && n > 0)
        f8_affine_weights(af, k, wnext);
#endif
    int next_ok = ahead && src == 1 && n > 0 && f8_texels_of(&m->tx, tc, af, sv, tv, wnext, &next);
    int next0_ok = ahead && sample0 && n > 0 && f8_texels_of(&m->tx0, tc0, af, sv0, tv0, wnext, &next0);
    const int overlap = modwrite_overlaps(kind, m->alpha.test, rgb565, n, F8_N);
    for (int j = 0, jn; j < n; j = jn) {
        /* the next group; a last partial one as the last F8_N again */
        jn = overlap && j + F8_N < n && j + 2 * F8_N > n ? n - F8_N : j + F8_N;
        f8_num T[4], T0[4], w[3];
        F8Texels cur = next, cur0 = next0;
        int cur_ok = next_ok, cur0_ok = next0_ok;
        if (af) {
#if !defined(GLES_NUM_FLOAT)
            if (!ahead) {
                f8_affine_weights(af, k + j, w);
            } else {
                for (int i = 0; i < 3; i++)
                    w[i] = wnext[i];
                if (jn < n)
                    f8_affine_weights(af, k + jn, wnext);
            }
#endif
        } else if (smooth) {
            f8_weights(&p[j], w);
        }
        if (!ahead) {
            /* this group's words now */
            cur_ok = src == 1 && f8_texels_of(&m->tx, tc + j, af, sv, tv, w, &cur);
            cur0_ok = sample0 && f8_texels_of(&m->tx0, tc0 + j, af, sv0, tv0, w, &cur0);
        } else {
            if (src == 1 && jn < n)
                next_ok = f8_texels_of(&m->tx, tc + jn, af, sv, tv, wnext, &next);
            if (sample0 && jn < n)
                next0_ok = f8_texels_of(&m->tx0, tc0 + jn, af, sv0, tv0, wnext, &next0);
        }
        if (src == 1 && cur_ok) {
            f8_bilerp(&cur, T);
        } else {
            FRAGV texel[F8_N][4];
            TexCoord buf[F8_N];
            if (src == 1)
                m->tx.sampler(m->tx.tex, F8_N, f8_coords_at(tc, j, af, sv, tv, w, buf), NULL, NULL, texel[0], 4,
                              m->tx.unorm8);
            f8_gather_rows(src == 1 ? texel[0] : ct + (size_t)j * stride, src == 1 ? 4 : stride, T);
        }
        if (sample0 && cur0_ok) {
            f8_bilerp(&cur0, T0);
        } else if (dot3) {
            FRAGV texel[F8_N][4];
            TexCoord buf[F8_N];
            if (ct0 == NULL)
                m->tx0.sampler(m->tx0.tex, F8_N, f8_coords_at(tc0, j, af, sv0, tv0, w, buf), NULL, NULL, texel[0], 4,
                               m->tx0.unorm8);
            f8_gather_rows(ct0 == NULL ? texel[0] : ct0 + (size_t)j * stride, ct0 == NULL ? 4 : stride, T0);
        }
        /* a group with copies is never F8_N neighbouring pixels, whatever
        ** its offsets say */
        const int run = j + F8_N <= live && k[j + F8_N - 1] == k[j] + F8_N - 1;
        f8_i32 d = { 0 };
        if (kind || m->alpha.test) {
            if (run && rgb565) {
                f8_u16 h;
                memcpy(&h, &d16[k[j]], sizeof h);
                d = __builtin_convertvector(h, f8_i32);
            } else if (run) {
                memcpy(&d, &d32[k[j]], sizeof d);
            } else {
                for (int L = 0; L < F8_N; L++)
                    d[L] = rgb565 ? d16[k[j + L]] : (int32_t)d32[k[j + L]];
            }
        }
        f8_num thr = { 0 };
        if (rgb565 && m->dither) {
            if (run)
                memcpy(&thr, m->thr[(x0 + k[j]) & 3], sizeof thr);
            else
                for (int L = 0; L < F8_N; L++)
                    thr[L] = m->t_row[(x0 + k[j + L]) & 3];
        }
        const f8_i32 word = f8_modwrite(m, smooth, kind, rgb565, dot3, w, T0, T, d, thr);
        if (run && rgb565) {
            const f8_u16 h = __builtin_convertvector(word, f8_u16);
            memcpy(&d16[k[j]], &h, sizeof h);
        } else if (run) {
            memcpy(&d32[k[j]], &word, sizeof word);
        } else {
            /* padded lanes repeat the last fragment: the same word again */
            for (int L = 0; L < F8_N; L++) {
                if (rgb565)
                    d16[k[j + L]] = (uint16_t)word[L];
                else
                    d32[k[j + L]] = (uint32_t)word[L];
            }
        }
    }
}

/* f8_modwrite_run with the source, the colour's interpolation, the blend
** and the format fixed per instance; dot3 (a constant) as there; af (the
** double build's, source 1) NULL or not per instance */
AVX2_INLINE void f8_modwrite_dispatch_dot3(const F8ModWrite *m, int src, int rgb565, int dot3, int n, int live,
                                           const uint8_t *k, const WGT (*p)[3], const FRAGV *ct0,
                                           const TexCoord *tc0, const FRAGV *ct, size_t stride, const TexCoord *tc,
                                           int x0, void *dst, const F8Affine *af)
{
#define F8_RUN(S, SM, K, F, AF) \
    f8_modwrite_run(m, S, SM, K, F, dot3, n, live, k, p, ct0, tc0, ct, stride, tc, x0, dst, AF)
#define F8_KINDS(S, SM, AF)                    \
    switch (m->kind + 3 * rgb565) {            \
    case 0: F8_RUN(S, SM, 0, 0, AF); break;    \
    case 1: F8_RUN(S, SM, 1, 0, AF); break;    \
    case 2: F8_RUN(S, SM, 2, 0, AF); break;    \
    case 3: F8_RUN(S, SM, 0, 1, AF); break;    \
    default: F8_RUN(S, SM, 1, 1, AF); break;   \
    }
#if defined(GLES_NUM_FLOAT)
    (void)af;
#define F8_SAMPLED(SM) F8_KINDS(1, SM, NULL)
#else
#define F8_SAMPLED(SM)            \
    if (af) {                     \
        F8_KINDS(1, SM, af)       \
    } else {                      \
        F8_KINDS(1, SM, NULL)     \
    }
#endif
    switch (src * 2 + m->smooth) {
    case 0: F8_KINDS(0, 0, NULL) break;
    case 1: F8_KINDS(0, 1, NULL) break;
    case 2: F8_SAMPLED(0) break;
    default: F8_SAMPLED(1) break;
    }
#undef F8_SAMPLED
#undef F8_KINDS
#undef F8_RUN
}

static inline void f8_modwrite_dispatch(const F8ModWrite *m, int src, int rgb565, int n, int live, const uint8_t *k,
                                        const WGT (*p)[3], const FRAGV *ct, size_t stride, const TexCoord *tc,
                                        int x0, void *dst, const F8Affine *af)
{
    f8_modwrite_dispatch_dot3(m, src, rgb565, 0, n, live, k, p, NULL, NULL, ct, stride, tc, x0, dst, af);
}

#endif
#endif
