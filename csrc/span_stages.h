/*
** span_stages.h -- the span chain's stages, a template that span_chain.c
** instantiates twice: for the baseline instruction set, and (on x86-64)
** for AVX2, chosen at run time. STAGE(name) gives each instance's names;
** CHAIN_SIMD is 1 in the AVX2 instance, where the hottest stages work on
** a fragment's four channels at once (V4, span_avx2.h) and the rest are
** the same loops, vectorized by the compiler for AVX2. Every instance computes the
** same bits as the per-fragment reference (fragment_process).
*/
/* {====================================================================
** weights */

/* the weights of slot j */
static inline void STAGE(persp1)(const TriSetup *t, SpanBuf *b, int j)
{
    int64_t e[3];
    chunk_edges(t, b, b->k[j], e);
    wgt_persp(&t->wgt, e, b->p[j]);
}

#if CHAIN_SIMD
/* the weights of four fragments from their edge values (wgt_persp is
** wgt_linear where the triangle is affine); 0 where a lane leaves the
** kernels' ranges */
static inline int STAGE(persp4)(const WgtSetup *ws, const __m256i e[3], WGT (*p)[3])
{
#if NUM_IS_FIXED
    __m256i l[3];
    if (ws->affine ? !avx2_linear4v(ws, e[1], e[2], l) : !avx2_persp4(ws, e, l))
        return 0;
    avx2_store_wgt4(l, p);
    return 1;
#else
    return v4_persp4(ws, e, p);
#endif
}
#endif

#if CHAIN_SIMD
/* the lanes of the stepped weights' coordinates: the fixed build's 64-bit
** integers, the others' V4 */
#if NUM_IS_FIXED
typedef __m256i PerspLane;
#define PERSP_SET1(x) _mm256_set1_epi64x(x)
#else
typedef V4 PerspLane;
#define PERSP_SET1(x) v4_set1(x)
#endif

/* unit u's (0) and v's (1) s and t at the three vertices, in every lane */
static inline void STAGE(persp_units_st)(const TriSetup *t, int u, int v, PerspLane st[2][2][3])
{
    const int unit[2] = { u, v };
    for (int c = 0; c < 2; c++) {
        NUM sv[3], tv[3];
        span_unit_st(t, unit[c], sv, tv);
        for (int i = 0; i < 3; i++) {
            st[c][0][i] = PERSP_SET1(sv[i]);
            st[c][1][i] = PERSP_SET1(tv[i]);
        }
    }
}
#undef PERSP_SET1
#endif

#if CHAIN_SIMD && NUM_IS_FIXED
/* STAGE(persp_affine_run)'s constants of a primitive, formed by
** STAGE(persp_affine_setup) for its first chunk and kept in the context
** (ctx->persp_setup) for the rest: a triangle of small rows would form them
** again for every row, in more instructions than the row's weights */
typedef struct PerspAffine {
    __m256i st[2][2][3];    /* unit u's (0) and v's (1) s and t at the three vertices, broadcast */
    __m256i step[2];        /* edges 1 and 2's sums' step from one group of four slots to the next */
    __m256i lane_ea[2];     /* k ea_i in lane k (0..3) */
    __m256i r_lo, r_hi;     /* lin_recip's low and high 32 bits, in every lane */
    int ok;                 /* the triangle's conditions for the run (below) hold */
    int u, v;               /* the units whose coordinates the run forms into b->tc and b->tx, else -1 */
} PerspAffine;
_Static_assert(sizeof(PerspAffine) <= GLES_PERSP_SETUP_BYTES, "the context has room for the setup");

/* a triangle's PerspAffine, with unit u's coordinates into b->tc (u >= 0:
** an affine unit) and unit v's (v >= 0, with u) into b->tx. The run
** applies where the triangle is affine and the step of four slots, 4 ea_i,
** is a multiple of 2^eshift on both edges (STAGE(persp_affine_run)) */
static void STAGE(persp_affine_setup)(const TriSetup *t, int u, int v, PerspAffine *pa)
{
    const WgtSetup *ws = &t->wgt;
    const int sh = ws->eshift;
    pa->ok = ws->affine && ws->lin_recip >= 0 && sh <= 62 && !(u < 0 && v >= 0);
    pa->u = u, pa->v = v;
    if (!pa->ok)
        return;
    const uint64_t r = (uint64_t)ws->lin_recip;
    for (int i = 1; i < 3; i++) {
        const int64_t ea = t->ea[i], e4 = 4 * ea;
        pa->ok &= !(e4 & (((int64_t)1 << sh) - 1));
        pa->step[i - 1] = _mm256_set1_epi64x((int64_t)((uint64_t)(e4 >> sh) * r));
        pa->lane_ea[i - 1] = _mm256_setr_epi64x(0, ea, 2 * ea, 3 * ea);
    }
    pa->r_lo = _mm256_set1_epi64x((int64_t)(r & 0xFFFFFFFFu));
    pa->r_hi = _mm256_set1_epi64x((int64_t)(r >> 32));
    STAGE(persp_units_st)(t, u, v, pa->st);
}

/* STAGE(persp_affine_run)'s loop over groups of four slots to n4 from the
** running sums of edges 1 and 2 (lanes = four slots): the weights, and
** the coordinates of `units` units (pa->u's into b->tc, pa->v's into b->tx) */
static inline __attribute__((always_inline)) void STAGE(persp_affine_loop)(const PerspAffine *pa,
                                                                          SpanBuf *b, int n4, __m256i sum1,
                                                                          __m256i sum2, const int units)
{
    const __m256i one = _mm256_set1_epi64x(WGT_ONE), step1 = pa->step[0], step2 = pa->step[1];
    WGT (*const p)[3] = b->p;
    TexCoord *const tc = b->tc, *const tx = b->tx;
    for (int j = 0; j < n4; j += 4) {
        __m256i l[3];
        l[1] = _mm256_srli_epi64(sum1, 31);
        l[2] = _mm256_srli_epi64(sum2, 31);
        l[0] = _mm256_sub_epi64(_mm256_sub_epi64(one, l[1]), l[2]);
        avx2_store_wgt4(l, &p[j]);
        if (units >= 1)
            avx2_store_st4(avx2_texc_lerp3x4v(pa->st[0][0], l), avx2_texc_lerp3x4v(pa->st[0][1], l), &tc[j]);
        if (units == 2)
            avx2_store_st4(avx2_texc_lerp3x4v(pa->st[1][0], l), avx2_texc_lerp3x4v(pa->st[1][1], l), &tx[j]);
        sum1 = _mm256_add_epi64(sum1, step1);
        sum2 = _mm256_add_epi64(sum2, step2);
    }
}

/* wgt_linear of an affine triangle's slots 0..n-1 when they are offsets
** (k[j] = j: no test has dropped a fragment): l_i = (q_i R + 2^30) >> 31
** with q_i = e_i >> eshift and e_i = e0_i + j ea_i. From one group of four
** to the next e_i grows by 4 ea_i, a multiple of 2^eshift (pa->ok; so
** wherever eshift <= 10, as ea_i is a multiple of 2^8 and eshift is at most
** 10 below MAX_VIEWPORT_DIMS 4096), so q_i grows by 4 ea_i >> eshift and
** the sum by that times R. Sums are kept mod
** 2^64, so each is the scalar code's value wherever that fits int64 (as
** avx2_linear4v's products are). The kernels' range, 0 <= e_i and q_i <
** 2^31, holds at every slot when it holds at the first and the last (e_i
** is linear in j); there the first four lanes' q_i R is q_i R_lo + (q_i R_hi
** << 32) mod 2^64, two vpmuludq. The units' coordinates (pa->u, pa->v) are
** formed from the same lanes as stage_fetch forms them from the stored
** weights (avx2_tex_coord_affine4 reads a weight's int32, the lane's low
** dword). A last group of fewer than four slots is formed whole: the slots
** past n are free, and what lands there (the sums' continuation, in or out
** of the range, from a lane past n that may be negative) is never read.
** Returns the slots done (n), or 0 where it does not apply. */
static int STAGE(persp_affine_run)(const PerspAffine *pa, const TriSetup *t, SpanBuf *b)
{
    _Static_assert(SPAN_CHUNK % 4 == 0, "a last group rounded up to four stays within the chunk");
    const int n = b->n, sh = t->wgt.eshift;
    if (!pa->ok || n < 1 || b->k[n - 1] != n - 1)
        return 0;
    const __m128i shift = _mm_cvtsi32_si128(sh);
    const __m256i half = _mm256_set1_epi64x((int64_t)1 << 30);
    __m256i sum[2];
    for (int i = 0; i < 2; i++) {
        const int64_t first = b->e0[i + 1], last = first + t->ea[i + 1] * (n - 1);
        if (first < 0 || last < 0 || (first >> sh) > INT32_MAX || (last >> sh) > INT32_MAX)
            return 0;
        const __m256i q = _mm256_srl_epi64(_mm256_add_epi64(_mm256_set1_epi64x(first), pa->lane_ea[i]), shift);
        sum[i] = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epu32(q, pa->r_lo),
                                                   _mm256_slli_epi64(_mm256_mul_epu32(q, pa->r_hi), 32)),
                                  half);
    }
    const int n4 = (n + 3) & ~3;
    /* the loop's instances: the units' coordinates asked for */
    if (pa->u < 0)
        STAGE(persp_affine_loop)(pa, b, n4, sum[0], sum[1], 0);
    else if (pa->v < 0)
        STAGE(persp_affine_loop)(pa, b, n4, sum[0], sum[1], 1);
    else
        STAGE(persp_affine_loop)(pa, b, n4, sum[0], sum[1], 2);
    return n;
}
#endif

#if CHAIN_SIMD && !NUM_IS_FIXED
/* whether slots 0..n4-1 are offsets (the chain's first stage) whose edge
** values e0 + ea k (edges 1 and 2) stay integers of magnitude at most 2^51,
** which holds wherever it does at k = 0 and k = n4 (with |ea| <= 2^44):
** each double sum of STAGE(edge_steps) is then exact, the value the
** conversion of the int64 gives */
static inline int STAGE(edge_steps_exact)(const TriSetup *t, const SpanBuf *b, int n4)
{
    const uint64_t lim51 = (uint64_t)1 << 51, lim_ea = (uint64_t)1 << 44;
    int steps = n4 && b->k[b->n - 1] == b->n - 1;
    for (int i = 1; i <= 2 && steps; i++) {
        /* -lim <= v < lim as one unsigned comparison of v + lim */
        const int64_t first = b->e0[i];
        steps = (uint64_t)t->ea[i] + lim_ea < 2 * lim_ea && (uint64_t)first + lim51 < 2 * lim51
             && (uint64_t)(first + t->ea[i] * n4) + lim51 < 2 * lim51;
    }
    return steps;
}

/* edges 1 and 2's values at slots 0..3 as doubles, and their step to the
** next four */
static inline void STAGE(edge_steps)(const TriSetup *t, const SpanBuf *b, __m256d *d1, __m256d *d2, __m256d *step1,
                                     __m256d *step2)
{
    const __m256d k4 = _mm256_setr_pd(0, 1, 2, 3);
    const double a1 = (double)t->ea[1], a2 = (double)t->ea[2];
    *d1 = _mm256_add_pd(_mm256_set1_pd((double)b->e0[1]), _mm256_mul_pd(k4, _mm256_set1_pd(a1)));
    *d2 = _mm256_add_pd(_mm256_set1_pd((double)b->e0[2]), _mm256_mul_pd(k4, _mm256_set1_pd(a2)));
    *step1 = _mm256_set1_pd(4 * a1);
    *step2 = _mm256_set1_pd(4 * a2);
}

/* the float and double builds' PerspAffine: STAGE(persp_affine_steps)'s
** units' vertex coordinates in every lane, formed by an affine primitive's
** first chunk and kept in the context (ctx->persp_setup) for the rest */
typedef struct PerspAffine {
    V4 st[2][2][3];     /* unit u's (0) and v's (1) s and t at the three vertices */
} PerspAffine;
_Static_assert(sizeof(PerspAffine) <= GLES_PERSP_SETUP_BYTES, "the context has room for the setup");

static void STAGE(persp_affine_setup)(const TriSetup *t, int u, int v, PerspAffine *ps)
{
    STAGE(persp_units_st)(t, u, v, ps->st);
}

/* an affine triangle's weights (wgt_linear reads edges 1 and 2 alone)
** four at a time from the stepped edge values, where STAGE(edge_steps)
** is exact, with unit u's coordinates (u >= 0: an affine unit) formed from
** the same lanes into b->tc, and unit v's (v >= 0) into b->tx; a last
** group of fewer than four slots whole (the slots past n are free; the
** exactness holds to the group's end, as the test covers it); with wide
** (AVX-512 runs) the double build's eight at a time (d8_affine_steps).
** ps is the triangle's setup. Returns the slots done (n), or 0. */
static int STAGE(persp_affine_steps)(const TriSetup *t, SpanBuf *b, int u, int v, const PerspAffine *ps, int wide)
{
    _Static_assert(SPAN_CHUNK % 8 == 0, "a last group rounded up to eight stays within the chunk");
    const int n4 = (b->n + 3) & ~3;
    if (!t->wgt.affine)
        return 0;
#if SIMD_AVX512_INSTANCE
    /* eight slots at a time where AVX-512 runs and the chunk fills more
    ** than one group (a last one whole, as below) */
    const int n8 = (b->n + 7) & ~7;
    if (wide && b->n > 8 && STAGE(edge_steps_exact)(t, b, n8)) {
        NUM sv[3], tv[3], sv2[3], tv2[3];
        span_unit_st(t, u, sv, tv);
        span_unit_st(t, v, sv2, tv2);
        d8_affine_steps(t->wgt.inv_area, b->e0, t->ea, n8, b, u >= 0, sv, tv, v >= 0, sv2, tv2);
        return b->n;
    }
#else
    (void)wide;
#endif
    if (!STAGE(edge_steps_exact)(t, b, n4))
        return 0;
    __m256d d1, d2, step1, step2;
    STAGE(edge_steps)(t, b, &d1, &d2, &step1, &step2);
    /* the loop's constants in locals (stores to b->p could alias t and b);
    ** the coordinates' read in place as operands */
    const WgtSetup ws = t->wgt;
    WGT (*const p)[3] = b->p;
    TexCoord *const tc = b->tc, *const tx = b->tx;
    for (int j = 0; j < n4; j += 4) {
        const V4 ev[3] = { v4_edge_num(d1), v4_edge_num(d1), v4_edge_num(d2) };
        V4 o[3];
        v4_persp4_lanes(&ws, ev, o);
        v4_store_wgt4(o, &p[j]);
        if (u >= 0)
            v4_tex_coord_affine4v(ps->st[0][0], ps->st[0][1], o, &tc[j]);
        if (v >= 0)
            v4_tex_coord_affine4v(ps->st[1][0], ps->st[1][1], o, &tx[j]);
        d1 = _mm256_add_pd(d1, step1);
        d2 = _mm256_add_pd(d2, step2);
    }
    return b->n;
}
#endif

static void STAGE(stage_persp)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)ctx;
    int j = 0;
#if CHAIN_SIMD
    /* an affine triangle's weights by steps, with the chain's first unit's
    ** coordinates where it has no level of detail and no q, and a second
    ** such unit's into b->tx (stage_fetch then starts past them) */
    const int u = ctx ? ctx->chain_coords_unit : -1;     /* (the debug entry has no context) */
    const int v = ctx ? ctx->chain_coords_tx_unit : -1;
    const int coords = u >= 0 && !((t->tex_projective >> u) & 1);
    const int coords_tx = v >= 0 && !((t->tex_projective >> v) & 1);
#if SIMD_AVX512_INSTANCE
    /* the fused stage forms the weights and both coordinates itself, in
    ** its lanes, from an affine triangle's edges stepped exactly over the
    ** chunk's whole groups (it would read them back from memory) */
    b->lanes = ctx && ctx->chain_fused_lanes && coords && (v < 0 || coords_tx) && t->wgt.affine
            && ctx_simd(ctx) >= SIMD_AVX512 && STAGE(edge_steps_exact)(t, b, (b->n + 7) & ~7);
    if (b->lanes)
        return;
#endif
    if (t->wgt.affine) {
        /* the stepped weights' constants once per primitive (the debug
        ** entry, without a context, forms them for its chunk) */
        PerspAffine local;
        PerspAffine *pa = ctx ? ctx->persp_setup : &local;
        if (!ctx || ctx->persp_serial != t->serial) {
            STAGE(persp_affine_setup)(t, coords ? u : -1, coords_tx ? v : -1, pa);
            if (ctx)
                ctx->persp_serial = t->serial;
        }
#if NUM_IS_FIXED
        j = STAGE(persp_affine_run)(pa, t, b);
#else
        j = STAGE(persp_affine_steps)(t, b, coords ? u : -1, coords_tx ? v : -1, pa,
                                      ctx && ctx_simd(ctx) >= SIMD_AVX512);
#endif
    }
    if (coords && j) {
        b->tc_unit = u;
        b->tc_done = j;
    }
    if (coords_tx && j) {
        b->tx_unit = v;
        b->tx_done = j;
    }
    const int n = b->n;
    if (j + 4 <= n) {   /* (the stepped run above often leaves none) */
        /* the loop's constants in locals (stores to b->p could alias t and b) */
        const WgtSetup ws = t->wgt;
        Edges4 ed;
        avx2_edges4_setup(b->e0, t->ea, &ed);
        WGT (*const p)[3] = b->p;
        for (; j + 4 <= n; j += 4) {
            __m256i e[3];
            avx2_edges4(&ed, &b->k[j], e);
            if (!STAGE(persp4)(&ws, e, &p[j]))
                /* a lane out of the kernels' ranges: the group by the scalar code */
                for (int k = j; k < j + 4; k++)
                    STAGE(persp1)(t, b, k);
        }
    }
#endif
    for (; j < b->n; j++)
        STAGE(persp1)(t, b, j);
}

/* slot j's weights and the level of detail's neighbours: the weights'
** tangents along ea (b->px) and eb (b->py) */
static inline void STAGE(persp_lod1)(const TriSetup *t, SpanBuf *b, int j)
{
    int64_t e[3];
    chunk_edges(t, b, b->k[j], e);
    wgt_persp_tangents(&t->wgt, t->tan, e, b->p[j], b->px[j], b->py[j]);
}

/* stage_persp, with the weights' tangents (the level of detail's
** neighbours) from the same division */
static void STAGE(stage_persp_lod)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    const int n = b->n;
    int j = 0;
    if (t->wgt.affine) {
        /* the tangents step by the linear weights' constant steps */
        STAGE(stage_persp)(ctx, t, b);
#if NUM_IS_FIXED
        const WgtDen lin = { 0, 0 };
#else
        const WgtDen lin = 0;
#endif
        for (; j < n; j++) {
            wgt_tangent(&t->tan[0], b->p[j], lin, b->px[j]);
            wgt_tangent(&t->tan[1], b->p[j], lin, b->py[j]);
        }
        return;
    }
#if CHAIN_SIMD
    /* the loop's constants in locals (stores to b->p could alias t and b) */
    const WgtSetup ws = t->wgt;
    const WgtTangent tan[2] = { t->tan[0], t->tan[1] };
    Edges4 ed;
    avx2_edges4_setup(b->e0, t->ea, &ed);
    WGT (*const p)[3] = b->p, (*const px)[3] = b->px, (*const py)[3] = b->py;
    /* the chain's one unit with a level of detail, where it has no q: its
    ** coordinates at the weights and the tangents from the same lanes
    ** (stage_fetch forms them so from the stored weights), into b->tc, tx
    ** and ty, up to the first group the scalar code takes; from there the
    ** tangents' weights are stored, for stage_fetch */
    const int u = ctx ? ctx->chain_lod_unit : -1;     /* (the debug entry has no context) */
    int done = u >= 0 && !((t->tex_projective >> u) & 1) ? 0 : -1;
    NUM sv[3], tv[3];
    span_unit_st(t, done == 0 ? u : -1, sv, tv);
    TexCoord *const tc = b->tc, *const tx = b->tx, *const ty = b->ty;
    /* a tail past the last whole group padded with copies of the last slot
    ** (the slots past n are free, and nothing reads what lands there): one
    ** more group of eight in place of the AVX2 groups and the scalar slots
    ** (trilinear_fog's fixed build about 2% faster; in AVX2 the same work) */
    _Static_assert(SPAN_CHUNK % 8 == 0, "a padded group stays within the chunk");
#if SIMD_AVX512_FX || SIMD_AVX512_INSTANCE
    const int wide = ctx && ctx_simd(ctx) >= SIMD_AVX512;
#else
    const int wide = 0;     /* (this build's groups here are AVX2's) */
#endif
    const int np = n > 0 ? avx2_pad_group(wide ? 8 : 4, n, b->k, b->p, 0, NULL, NULL, 0) : 0;
#if SIMD_AVX512_FX || SIMD_AVX512_INSTANCE
    /* groups of eight by AVX-512 where it runs, as far as they go (the
    ** fixed build's span_fx512.h, the double build's span_avx512.h) */
    if (wide) {
        b->n = np;      /* (what the kernels read) */
#if SIMD_AVX512_FX
        j = fx512_persp_lod(&ws, tan, t->ea, b, done == 0, sv, tv);
#else
        j = d8_persp_lod(&ws, tan, t->ea, b, done == 0, sv, tv);
#endif
        b->n = n;
        if (done == 0)
            done = j;
    }
#endif
#if NUM_IS_FIXED
    /* the weights and their divisions first, then the tangents: as one
    ** loop, each group's division, tangents and stores form one long chain
    ** of dependent operations, and the groups overlap less (measured) */
    __m256i lanes[SPAN_CHUNK / 4][3], dens[SPAN_CHUNK / 4];
    const int simd_from = j;    /* the slots past the AVX-512 groups */
#endif
    for (; j + 4 <= np; j += 4) {
        __m256i e[3];
        avx2_edges4(&ed, &b->k[j], e);
#if NUM_IS_FIXED
        __m256i *const l = lanes[j / 4];
        if (!avx2_persp4_den(&ws, e, l, &dens[j / 4])) {
            /* a lane out of the kernels' ranges: the group by the scalar
            ** code (a WgtDen of 0 marks it done) */
            dens[j / 4] = _mm256_setzero_si256();
            for (int k = j; k < j + 4; k++)
                STAGE(persp_lod1)(t, b, k);
            continue;
        }
        avx2_store_wgt4(l, &p[j]);
#else
        V4 ev[3], l[3], inv, o[3];
        if (!v4_edge_lanes(e, ev)) {
            for (int k = j; k < j + 4; k++)
                STAGE(persp_lod1)(t, b, k);
            continue;
        }
        v4_persp4_lanes_den(&ws, ev, l, &inv);
        v4_store_wgt4(l, &p[j]);
        if (done == j) {
            /* the coordinates at the lanes (v4_tex_coord_affine4 is
            ** span_tex_coord's operations for a unit without q) */
            v4_tex_coord_affine4(sv, tv, l, &tc[j]);
            v4_tangent4(&tan[0], l, inv, o);
            v4_tex_coord_affine4(sv, tv, o, &tx[j]);
            v4_tangent4(&tan[1], l, inv, o);
            v4_tex_coord_affine4(sv, tv, o, &ty[j]);
            done += 4;
            continue;
        }
        v4_tangent4(&tan[0], l, inv, o);
        v4_store_wgt4(o, &px[j]);
        v4_tangent4(&tan[1], l, inv, o);
        v4_store_wgt4(o, &py[j]);
#endif
    }
#if NUM_IS_FIXED
    Avx2Tangents g;
    avx2_tangents_setup(tan, &g);
    Avx2CoordDeltas cd;
    avx2_coord_deltas_setup(sv, tv, &cd);
    for (int i = simd_from; i + 4 <= j; i += 4) {
        __m256i o[2][3];
        if (_mm256_testz_si256(dens[i / 4], dens[i / 4]))
            continue;   /* the scalar code's group (above) */
        const __m256i *const l = lanes[i / 4];      /* (the first loop's weights) */
        if (done == i && cd.ok && avx2_lod_coords4(&g, &cd, l, dens[i / 4], &tc[i], &tx[i], &ty[i])) {
            done += 4;
            continue;
        }
        if (!avx2_tangents4(&g, l, dens[i / 4], o)) {
            for (int k = i; k < i + 4; k++)
                STAGE(persp_lod1)(t, b, k);
        } else if (done == i) {
            avx2_store_st4(avx2_texc_lerp3x4(sv, l), avx2_texc_lerp3x4(tv, l), &tc[i]);
            avx2_store_st4(avx2_texc_lerp3x4(sv, o[0]), avx2_texc_lerp3x4(tv, o[0]), &tx[i]);
            avx2_store_st4(avx2_texc_lerp3x4(sv, o[1]), avx2_texc_lerp3x4(tv, o[1]), &ty[i]);
            done += 4;
        } else {
            avx2_store_wgt4(o[0], &px[i]);
            avx2_store_wgt4(o[1], &py[i]);
        }
    }
#endif
    if (done > 0) {     /* (a padded group's slots past n are not the chunk's) */
        b->lod_unit = u;
        b->lod_done = done < n ? done : n;
    }
#endif
    for (; j < n; j++)
        STAGE(persp_lod1)(t, b, j);
}

/* }==================================================================== */

/* {====================================================================
** depth, stencil (§4.1.5, §4.1.6) */

/* every live fragment's window depth, with polygon offset */
static void STAGE(stage_depth)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    int j = 0;
#if CHAIN_SIMD && NUM_IS_FIXED
    const DEPTHV zv[3] = { t->v[0]->wz, t->v[1]->wz, t->v[2]->wz };
    const int n4 = b->n & ~3;
    /* slots that are offsets (the chain's first stage): the edge values step
    ** by ea per slot, and, linear in the offset, lie in the kernel's range
    ** at every slot when they do at the first and the last */
    if (n4 && b->k[b->n - 1] == b->n - 1 && t->wgt.lin_recip >= 0 && !t->depth_offset
        && ctx->depth_max <= INT32_MAX) {
        const int64_t l1 = b->e0[1] + t->ea[1] * (n4 - 1), l2 = b->e0[2] + t->ea[2] * (n4 - 1);
        const int sh = t->wgt.eshift;
        if (avx2_edge_fits(b->e0[1], sh) && avx2_edge_fits(b->e0[2], sh) && avx2_edge_fits(l1, sh)
            && avx2_edge_fits(l2, sh)) {
            /* e0 + ea k per lane, the values chunk_edges forms */
            __m256i r1 = _mm256_add_epi64(_mm256_set1_epi64x(b->e0[1]),
                                          _mm256_setr_epi64x(0, t->ea[1], 2 * t->ea[1], 3 * t->ea[1]));
            __m256i r2 = _mm256_add_epi64(_mm256_set1_epi64x(b->e0[2]),
                                          _mm256_setr_epi64x(0, t->ea[2], 2 * t->ea[2], 3 * t->ea[2]));
            const __m256i step1 = _mm256_slli_epi64(_mm256_set1_epi64x(t->ea[1]), 2);
            const __m256i step2 = _mm256_slli_epi64(_mm256_set1_epi64x(t->ea[2]), 2);
            const int hi = (t->wgt.lin_recip >> 32) != 0;
            /* the loop's constants in locals (the stores to b->z could alias fields) */
            const WgtSetup ws = t->wgt;
            const __m256i zs[3] = { _mm256_set1_epi64x(zv[0] >> 12), _mm256_set1_epi64x(zv[1] >> 12),
                                    _mm256_set1_epi64x(zv[2] >> 12) };
            const __m128i top = _mm_set1_epi32((int)ctx->depth_max);
            uint32_t *const z = b->z;
            for (; j < n4; j += 4) {
                __m256i l[3];
                avx2_linear4_checked(&ws, r1, r2, hi, l);
                avx2_depth4_pre(l, zs, top, &z[j]);
                r1 = _mm256_add_epi64(r1, step1);
                r2 = _mm256_add_epi64(r2, step2);
            }
        }
    }
    for (; j + 4 <= b->n; j += 4) {
        int64_t e[4][3];
        for (int k = 0; k < 4; k++)
            chunk_edges(t, b, b->k[j + k], e[k]);
        __m256i l[3];
        if (!avx2_linear4(&t->wgt, (const int64_t (*)[3])e, l))
            break;
        avx2_depth4(l, zv, ctx->depth_max, &b->z[j]);
        if (t->depth_offset)
            for (int k = 0; k < 4; k++)
                b->z[j + k] = raster_offset_depth(ctx, t, b->z[j + k]);
    }
#endif
#if CHAIN_SIMD && !NUM_IS_FIXED
    if (!t->depth_offset && ctx->depth_max <= INT32_MAX) {
        const DEPTHV zv[3] = { t->v[0]->wz, t->v[1]->wz, t->v[2]->wz };
        const int n4 = b->n & ~3;
        if (STAGE(edge_steps_exact)(t, b, n4)) {
            __m256d d1, d2, step1, step2;
            STAGE(edge_steps)(t, b, &d1, &d2, &step1, &step2);
            /* the loop's constants in locals (the stores to b->z could alias fields) */
            const WgtSetup ws = t->wgt;
            const uint32_t top = ctx->depth_max;
            uint32_t *const z = b->z;
            for (; j < n4; j += 4) {
                v4_depth4_pd(&ws, d1, d2, zv, top, &z[j]);
                d1 = _mm256_add_pd(d1, step1);
                d2 = _mm256_add_pd(d2, step2);
            }
        }
        const int64_t lim = (int64_t)1 << 53;
        for (; j + 4 <= b->n; j += 4) {
            int64_t e1[4], e2[4], e[3];
            int fits = 1;
            for (int k = 0; k < 4; k++) {
                chunk_edges(t, b, b->k[j + k], e);
                e1[k] = e[1];
                e2[k] = e[2];
                fits &= e[1] >= -lim && e[1] <= lim && e[2] >= -lim && e[2] <= lim;
            }
            if (!fits)
                break;
            v4_depth4(&t->wgt, e1, e2, zv, ctx->depth_max, &b->z[j]);
        }
    }
#endif
    for (; j < b->n; j++) {
        int64_t e[3];
        chunk_edges(t, b, b->k[j], e);
        WGT l[3];
        wgt_linear(&t->wgt, e, l);
        uint32_t z = wgt_depth3(t->v[0]->wz, t->v[1]->wz, t->v[2]->wz, l[0], l[1], l[2], ctx->depth_max);
        b->z[j] = raster_offset_depth(ctx, t, z);
    }
}

/* The stencil and depth tests of the chunk's live fragments (fragment_tests
** of each, the depth function fixed per chunk), then the survivors
** compacted (with their colours when it is computed already). The buffer
** pointers and tables are locals: the stencil's byte stores may alias
** anything, and fields read through a pointer would be read again after
** each. The stencil op is a table lookup whose row is computed (1 fail, 2
** depth fail, 3 pass), with no branch on the outcome. */
#define TESTS_SCALAR(FUNC) \
    for (int j = 0; j < n; j++) { \
        const size_t k = b->k[j]; \
        const uint32_t z = b->z[j]; \
        const uint32_t d = zb ? zb[k] : 0; \
        unsigned int pass = zb ? (unsigned int)fragment_compare(FUNC, z, d) : 1u; \
        if (st) { \
            const unsigned int s = st[k], sp = lut[0][s]; \
            st[k] = lut[1 + sp + (sp & pass)][s]; \
            pass &= sp; \
        } \
        if (zwrite) \
            zb[k] = pass ? z : d; \
        keep[j] = (uint8_t)pass; \
    } \
    break;

#if CHAIN_SIMD
/* the vector tests of n fragments in slots: stored stencil values s[0..n)
** and depths d[0..n), window depths z[0..n) (avx2_tests8's flags); the
** passing slots' bits into keep (slot j: bit j % 64 of word j / 64; a
** group of eight never straddles two words) */
static inline __attribute__((always_inline)) void STAGE(tests_slots)(const Avx2Tests *v, uint8_t *s, uint32_t *d,
                                                                        const uint32_t *z, int n, int stencil,
                                                                        int swrite, int depth, int dwrite,
                                                                        unsigned int dfunc,
                                                                        uint64_t keep[SPAN_KEEP_WORDS])
{
    for (int i = 0; i < SPAN_KEEP_WORDS; i++)
        keep[i] = 0;
    /* (a buffer whose test is off is NULL: no offset is added to it) */
    for (int j = 0; j < n; j += 8)
        keep[j >> 6] |= (uint64_t)avx2_tests8(v, stencil ? s + j : s, d ? d + j : d, z + j, n - j < 8 ? n - j : 8,
                                              stencil, swrite, depth, dwrite, dfunc)
                        << (j & 63);
}
#endif

static void STAGE(tests)(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int with_color)
{
    const size_t row = (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
#if CHAIN_SIMD
    /* a primitive's chunks share the tests' setup: the first forms it in
    ** the context, the rest read it there */
    _Static_assert(sizeof(Avx2TestsSetup) <= GLES_TESTS_SETUP_BYTES, "the context has room for the setup");
    Avx2TestsSetup *const ts = ctx->tests_setup;
    const uint64_t serial = t ? t->serial : b->rect->serial;
    if (ctx->tests_serial != serial) {
        fragment_tests_setup(ctx, &ts->ft);
        ts->swrite = ts->ft.stencil && avx2_stencil_writes(&ts->ft);
        ts->dwrite = ts->ft.depth && ts->ft.depth_mask;
        avx2_tests_setup(&ts->ft, ts->swrite, ts->ops, &ts->v);
        ctx->tests_serial = serial;
    }
    const FragTests ft = ts->ft;
#else
    (void)t;
    FragTests ft;
    fragment_tests_setup(ctx, &ft);
#endif
    const unsigned int dfunc = ft.depth ? ft.depth_func : GL_ALWAYS;
    uint8_t *const st = ft.stencil ? ft.stencil + row : NULL;
    uint32_t *const zb = ft.depth ? ft.depth + row : NULL;
    const int n = b->n;
#if CHAIN_SIMD
    const int swrite = ts->swrite, dwrite = ts->dwrite;
    const Avx2Tests v = ts->v;
    /* slots that are offsets (k[j] = j, as before any compaction) are the
    ** buffers' own; else the values are gathered first, and scattered after */
    const int dense = b->k[n - 1] == n - 1;
    uint8_t ls[SPAN_CHUNK];
    uint32_t ld[SPAN_CHUNK];
    uint8_t *s = st;
    uint32_t *d = zb;
    if (!dense) {
        if (st)
            for (int j = 0; j < n; j++)
                ls[j] = st[b->k[j]];
        if (zb)
            for (int j = 0; j < n; j++)
                ld[j] = zb[b->k[j]];
        s = st ? ls : NULL;
        d = zb ? ld : NULL;
    }
    uint64_t keep[SPAN_KEEP_WORDS];
#define TESTS_VECTOR(FUNC) \
    if (st) \
        STAGE(tests_slots)(&v, s, d, b->z, n, 1, swrite, zb != NULL, dwrite, FUNC, keep); \
    else \
        STAGE(tests_slots)(&v, s, d, b->z, n, 0, 0, 1, dwrite, FUNC, keep); \
    break;
    switch (dfunc) {
    case GL_NEVER: TESTS_VECTOR(GL_NEVER)
    case GL_LESS: TESTS_VECTOR(GL_LESS)
    case GL_EQUAL: TESTS_VECTOR(GL_EQUAL)
    case GL_LEQUAL: TESTS_VECTOR(GL_LEQUAL)
    case GL_GREATER: TESTS_VECTOR(GL_GREATER)
    case GL_NOTEQUAL: TESTS_VECTOR(GL_NOTEQUAL)
    case GL_GEQUAL: TESTS_VECTOR(GL_GEQUAL)
    default: TESTS_VECTOR(GL_ALWAYS)
    }
#undef TESTS_VECTOR
    if (!dense) {
        if (swrite)
            for (int j = 0; j < n; j++)
                st[b->k[j]] = ls[j];
        if (dwrite)
            for (int j = 0; j < n; j++)
                zb[b->k[j]] = ld[j];
    }
    int all = 1;
    for (int i = 0; i < SPAN_KEEP_WORDS; i++) {
        const int w = n - 64 * i;
        all &= keep[i] == (w >= 64 ? ~(uint64_t)0 : w > 0 ? ((uint64_t)1 << w) - 1 : 0);
    }
    if (all)
        return;     /* every fragment passes */
    if (with_color) {
        int m = 0;
        for (int i = 0; i < SPAN_KEEP_WORDS; i++)
            for (uint64_t bits = keep[i]; bits; bits &= bits - 1, m++) {
                const int j = 64 * i + __builtin_ctzll(bits);
                if (m != j)
                    v4_store(b->c[m], v4_load(b->c[j]));
            }
    }
    b->n = avx2_compact_offsets(b->k, n, keep);
#else
    uint8_t keep[SPAN_CHUNK];
    const int zwrite = zb && ft.depth_mask;
    const uint8_t (*const lut)[256] = (const uint8_t (*)[256])ctx->stencil_lut;
    switch (dfunc) {
    case GL_NEVER: TESTS_SCALAR(GL_NEVER)
    case GL_LESS: TESTS_SCALAR(GL_LESS)
    case GL_EQUAL: TESTS_SCALAR(GL_EQUAL)
    case GL_LEQUAL: TESTS_SCALAR(GL_LEQUAL)
    case GL_GREATER: TESTS_SCALAR(GL_GREATER)
    case GL_NOTEQUAL: TESTS_SCALAR(GL_NOTEQUAL)
    case GL_GEQUAL: TESTS_SCALAR(GL_GEQUAL)
    default: TESTS_SCALAR(GL_ALWAYS)
    }
    chunk_compact(b, keep, with_color);
#endif
}
#undef TESTS_SCALAR

static void STAGE(stage_tests_early)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(tests)(ctx, t, b, 0);
}

static void STAGE(stage_tests_late)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(tests)(ctx, t, b, 1);
}

/* depth LESS with writes and no stencil: the common case, without the
** per-fragment switches (the vector instance's tests are that already) */
static void STAGE(stage_zless_early)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
#if CHAIN_SIMD
    STAGE(tests)(ctx, t, b, 0);
#else
    uint32_t *zb = ctx->depth + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    int m = 0;
    for (int j = 0; j < b->n; j++) {
        const int k = b->k[j];
        uint32_t z = b->z[j];
        if (z < zb[k]) {
            zb[k] = z;
            b->k[m++] = (uint8_t)k;
        }
    }
    b->n = m;
#endif
}

/* }==================================================================== */

/* {====================================================================
** colour, texturing, fog, alpha test */

static void STAGE(stage_color)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    const int texturing = ctx->tex_units_on != 0;
#if CHAIN_SIMD
    if (t->smooth) {
        const V4 a0 = v4_load(t->col[0]), a1 = v4_load(t->col[1]), a2 = v4_load(t->col[2]);
        if (v4_lerp_fits(a0) && v4_lerp_fits(a1) && v4_lerp_fits(a2)) {
            if (texturing) {
                for (int j = 0; j < b->n; j++) {
                    const V4 c = v4_lerp3f_clamp01(a0, a1, a2, b->p[j]);
                    v4_store(b->cf[j], c);
                    v4_store(b->c[j], c);
                }
            } else {
                for (int j = 0; j < b->n; j++)
                    v4_store(b->c[j], v4_lerp3f(a0, a1, a2, b->p[j]));
            }
            return;
        }
    } else {
        const V4 c = texturing ? v4_clamp01(v4_load(t->flat)) : v4_load(t->flat);
        for (int j = 0; j < b->n; j++) {
            v4_store(b->c[j], c);
            if (texturing)
                v4_store(b->cf[j], c);
        }
        return;
    }
#endif
    for (int j = 0; j < b->n; j++) {
        FRAGV *c = b->c[j];
        if (t->smooth) {
            const WGT *p = b->p[j];
            for (int i = 0; i < 4; i++)
                c[i] = frag_lerp3f(t->col[0][i], t->col[1][i], t->col[2][i], p[0], p[1], p[2]);
        } else {
            for (int i = 0; i < 4; i++)
                c[i] = t->flat[i];
        }
        if (texturing)
            for (int i = 0; i < 4; i++)
                b->cf[j][i] = c[i] = frag_clamp01(c[i]);
    }
}

/* one unit's texels for the chunk's coordinates b->tc (and b->tx, b->ty),
** into b->ct, or (direct) straight into the colour b->c: a lone REPLACE
** unit of an RGBA texture is the colour, so it needs no environment */
static void STAGE(chunk_sample_at)(GlesContext *ctx, SpanBuf *b, int u, int direct, TexCoord *tc)
{
    /* a tail past the kernel's last whole group is padded with copies of
    ** the last coordinate when the kernel takes the group whole for less
    ** than the scalar code takes the tail: from half a group of eight, or
    ** three of four (measured); the slots past n are free, and nothing
    ** reads what lands there */
    _Static_assert(SPAN_CHUNK % 8 == 0, "a padded group stays within the chunk");
    const int g = ctx->sample_group[u];
    int n = b->n;
    if (g > 1 && n % g >= (g == 8 ? 4 : 3)) {
        const int padded = (n + g - 1) & ~(g - 1);
        for (int j = n; j < padded; j++)
            tc[j] = tc[n - 1];
        n = padded;
    }
    /* (at coordinates other than b->tc the unit has no level of detail) */
    ctx->samplers[u](ctx->units[u].bound, n, tc, tc == b->tc ? b->tx : tc, tc == b->tc ? b->ty : tc,
                     direct ? b->c[0] : b->ct[0][u], direct ? 4 : GLES_MAX_TEXTURE_UNITS * 4, ctx->texel_unorm8);
}

/* unit u's texels at the coordinates in b->tc */
static void STAGE(chunk_sample)(GlesContext *ctx, SpanBuf *b, int u, int direct)
{
    STAGE(chunk_sample_at)(ctx, b, u, direct, b->tc);
}

/* a triangle's coordinates of unit u for every live fragment, then its
** texels: into b->ct (FETCH_TEXELS), into the colour (FETCH_DIRECT), or
** none (FETCH_COORDS, FETCH_COORDS_TX: a later stage samples) */
static void STAGE(stage_fetch)(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int u, int mode)
{
    /* FETCH_COORDS_TX is for a unit without a level of detail, so b->tx is free */
    const int lod = mode != FETCH_COORDS_TX && texture_needs_lod(ctx->units[u].bound);
    if (b->tx_unit == u) {
        /* stage_persp formed b->tx[0..tx_done) (a unit without a level of
        ** detail): the rest, then its texels at them (FETCH_COORDS_TX
        ** leaves them to a later stage) */
        for (int j = b->tx_done; j < b->n; j++)
            span_tex_coord(t, u, b->p[j], &b->tx[j]);
        b->tx_unit = -1;
        if (mode == FETCH_TEXELS || mode == FETCH_DIRECT)
            STAGE(chunk_sample_at)(ctx, b, u, mode == FETCH_DIRECT, b->tx);
        return;
    }
    /* stage_persp may have formed the first ones (not with neighbours), or
    ** stage_persp_lod the first ones with them */
    const int from = b->tc_unit == u && !lod ? b->tc_done : b->lod_unit == u && lod ? b->lod_done : 0;
    if (mode == FETCH_COORDS && from >= b->n && b->lod_unit != u) {
        /* every coordinate formed, and a later stage samples: nothing to do
        ** (a chunk of a small triangle pays the setup below otherwise) */
        b->tc_unit = -1;
        return;
    }
    b->tc_unit = -1;
    if (b->lod_unit == u)
        b->lod_unit = -1;
#if CHAIN_SIMD && NUM_IS_FIXED
    const __m256i a[3] = { avx2_load_num4(t->v[0]->tex[u]), avx2_load_num4(t->v[1]->tex[u]),
                           avx2_load_num4(t->v[2]->tex[u]) };
    const int proj = (t->tex_projective >> u) & 1;
#define TEX_COORD(p, out) avx2_tex_coord(proj, a, p, out)
    /* an affine unit's s and t for four fragments at a time */
    NUM sv[3], tv[3];
    span_unit_st(t, u, sv, tv);
    const int four = proj ? 0 : b->n & ~3;
    const int tail = from > four ? from : four;     /* it forms a last group whole */
    for (int j = from; j < four; j += 4) {
        avx2_tex_coord_affine4(sv, tv, &b->p[j], &b->tc[j]);
        if (lod) {
            avx2_tex_coord_affine4(sv, tv, &b->px[j], &b->tx[j]);
            avx2_tex_coord_affine4(sv, tv, &b->py[j], &b->ty[j]);
        }
    }
#else
#define TEX_COORD(p, out) span_tex_coord(t, u, p, out)
    const int tail = from;
#endif
    for (int j = tail; j < b->n; j++)
        TEX_COORD(b->p[j], &b->tc[j]);
    if (lod)
        for (int j = tail; j < b->n; j++) {
            TEX_COORD(b->px[j], &b->tx[j]);
            TEX_COORD(b->py[j], &b->ty[j]);
        }
#undef TEX_COORD
    /* (formed in b->tc and copied: with its stores named b->tc the
    ** compiler vectorizes the loop above in the float builds) */
    if (mode == FETCH_COORDS_TX)
        memcpy(b->tx, b->tc, (size_t)b->n * sizeof b->tc[0]);
    if (mode == FETCH_TEXELS || mode == FETCH_DIRECT)
        STAGE(chunk_sample)(ctx, b, u, mode == FETCH_DIRECT);
}

/* a rectangle's coordinates of one unit from its columns' s (col[i] at
** the chunk's column x0 + i, through x0 + n for the right neighbours) and
** the row's t0, with the neighbours' (the upper one's t1) where lod */
static inline void STAGE(rect_from_columns)(SpanBuf *b, const TEXC *col, TEXC t0, TEXC t1, int lod)
{
    const int n = b->n;
    if (b->k[n - 1] == n - 1) {     /* slots that are offsets */
        int j = 0;
#if CHAIN_SIMD
        if (sizeof(TEXC) == 8) {
            /* four (s, t0) pairs from four s: the 64-bit lanes interleaved */
            __m256i tv;
            memcpy(&tv, (const TEXC[4]){ t0, t0, t0, t0 }, sizeof tv);
            for (; j + 4 <= n; j += 4) {
                const __m256i sv = _mm256_loadu_si256((const __m256i *)(const void *)&col[j]);
                const __m256i lo = _mm256_unpacklo_epi64(sv, tv), hi = _mm256_unpackhi_epi64(sv, tv);
                _mm256_storeu_si256((__m256i *)(void *)&b->tc[j], _mm256_permute2x128_si256(lo, hi, 0x20));
                _mm256_storeu_si256((__m256i *)(void *)&b->tc[j + 2], _mm256_permute2x128_si256(lo, hi, 0x31));
            }
        }
#endif
        for (; j < n; j++)
            b->tc[j] = (TexCoord){ col[j], t0 };
    } else
        for (int j = 0; j < n; j++)
            b->tc[j] = (TexCoord){ col[b->k[j]], t0 };
    if (lod)
        for (int j = 0; j < b->n; j++) {
            b->tx[j] = (TexCoord){ col[b->k[j] + 1], t0 };
            b->ty[j] = (TexCoord){ b->tc[j].s, t1 };
        }
}

/* a rectangle's coordinates of unit u for every live fragment, then its texels */
static void STAGE(stage_fetch_rect)(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int u, int mode)
{
    (void)t;
    const RectSetup *r = b->rect;
    const int lod = texture_needs_lod(ctx->units[u].bound);
    switch (r->coord[u]) {
    case RECT_COORD_LINEAR:
    case RECT_COORD_SPRITE: {
        /* rect_linear_coords or sprite_coords: s from the columns span_rect
        ** formed (every enabled unit's), t once per row, the neighbours only
        ** where the filter reads them */
        const int sprite = r->coord[u] == RECT_COORD_SPRITE;
        const TEXC t0 = sprite ? sprite_t(r->sprite_y, r->sprite_size, b->y) : rect_linear_t(r, u, b->y);
        const TEXC t1 = !lod ? 0
                      : sprite ? sprite_t(r->sprite_y, r->sprite_size, b->y + 1) : rect_linear_t(r, u, b->y + 1);
        STAGE(rect_from_columns)(b, r->col_s[u] + (b->x0 - r->col_x0), t0, t1, lod);
        break;
    }
    default:
        for (int j = 0; j < b->n; j++) {
            b->tc[j] = r->in.tc[u];
            b->tx[j] = r->in.tdx[u];
            b->ty[j] = r->in.tdy[u];
        }
        break;
    }
    if (mode != FETCH_COORDS)
        STAGE(chunk_sample)(ctx, b, u, mode == FETCH_DIRECT);
}

static void STAGE(stage_env)(GlesContext *ctx, SpanBuf *b, int u)
{
    const TexUnit *tu = &ctx->units[u];
    const unsigned int fmt = tu->bound->format;
    /* texture_env's REPLACE and MODULATE of RGBA and RGB textures, inline
    ** (an RGB texture leaves the alpha as it is) */
    const int k1 = fmt == GL_RGBA ? 4 : 3;
    if (tu->env_mode == GL_MODULATE && (fmt == GL_RGBA || fmt == GL_RGB)) {
        for (int j = 0; j < b->n; j++) {
#if CHAIN_SIMD
            const V4 c = v4_load(b->c[j]), ct = v4_load(b->ct[j][u]);
            if (v4_fits(c) && v4_fits(ct)) {
                const V4 m = v4_mul01(c, ct);
                v4_store(b->c[j], k1 == 4 ? m : v4_keep_alpha(m, c));
                continue;
            }
#endif
            for (int i = 0; i < k1; i++)
                b->c[j][i] = frag_mul(b->c[j][i], b->ct[j][u][i]);
        }
        return;
    }
    if (tu->env_mode == GL_REPLACE && (fmt == GL_RGBA || fmt == GL_RGB)) {
        for (int j = 0; j < b->n; j++) {
#if CHAIN_SIMD
            const V4 ct = v4_load(b->ct[j][u]);
            v4_store(b->c[j], k1 == 4 ? ct : v4_keep_alpha(ct, v4_load(b->c[j])));
#else
            for (int i = 0; i < k1; i++)
                b->c[j][i] = b->ct[j][u][i];
#endif
        }
        return;
    }
#if CHAIN_SIMD
    texture_env_span_avx2(ctx, u, b->n, (const FRAGV (*)[4])b->cf, b->ct, b->c);
#else
    texture_env_span(ctx, u, b->n, (const FRAGV (*)[4])b->cf, b->ct, b->c);
#endif
}

#if CHAIN_SIMD
/* stage_color_modulate's loop; smooth is a constant where it is inlined,
** and `alpha` keeps the colour's alpha (an RGB texture) as v4_keep_alpha */
static inline void STAGE(color_modulate_loop)(SpanBuf *b, int u, int smooth, int keep_cf, int alpha, V4 a0, V4 a1,
                                              V4 a2)
{
    const int n = b->n;
    const V4 flat = v4_clamp01(a0);
    for (int j = 0; j < n; j++) {
        /* the clamped colour is in [0, 1], so it fits v4_mul01 */
        const V4 c = smooth ? v4_lerp3f_clamp01(a0, a1, a2, b->p[j]) : flat;
        if (keep_cf)
            v4_store(b->cf[j], c);
        const V4 ct = v4_load(b->ct[j][u]);
        if (v4_fits(ct)) {
            const V4 m = v4_mul01(c, ct);
            v4_store(b->c[j], alpha ? v4_keep_alpha(m, c) : m);
        } else {
            v4_store(b->c[j], c);
            for (int i = 0; i < (alpha ? 3 : 4); i++)
                b->c[j][i] = frag_mul(b->c[j][i], b->ct[j][u][i]);
        }
    }
}
#endif

static void STAGE(stage_rect_source)(GlesContext *ctx, const TriSetup *t, SpanBuf *b);

/* stage_color (a rectangle's: stage_rect_source's), then stage_env's
** MODULATE of unit u (an RGBA or RGB texture) in one pass: the colour goes
** from registers into the product. The chain runs it after the unit's
** fetch (which does not read the colour); the primary colour b->cf is
** kept only for later units. */
static void STAGE(stage_color_modulate)(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int u)
{
#if CHAIN_SIMD
    const int alpha = ctx->units[u].bound->format != GL_RGBA;
    const int keep_cf = (ctx->tex_units_on & ~(1u << u)) != 0;
    if (b->rect || !t->smooth) {
        const V4 f = v4_load(b->rect ? b->rect->in.c : t->flat);
        if (alpha)
            STAGE(color_modulate_loop)(b, u, 0, keep_cf, 1, f, f, f);
        else
            STAGE(color_modulate_loop)(b, u, 0, keep_cf, 0, f, f, f);
        return;
    }
    const V4 a0 = v4_load(t->col[0]), a1 = v4_load(t->col[1]), a2 = v4_load(t->col[2]);
    if (v4_lerp_fits(a0) && v4_lerp_fits(a1) && v4_lerp_fits(a2)) {
        if (alpha)
            STAGE(color_modulate_loop)(b, u, 1, keep_cf, 1, a0, a1, a2);
        else
            STAGE(color_modulate_loop)(b, u, 1, keep_cf, 0, a0, a1, a2);
        return;
    }
#endif
    if (b->rect)
        STAGE(stage_rect_source)(ctx, t, b);
    else
        STAGE(stage_color)(ctx, t, b);
    STAGE(stage_env)(ctx, b, u);
}

#if CHAIN_SIMD && !NUM_IS_FIXED
/* stage_color, then stage_env of the two units of span_dot3_pair (the
** first COMBINE DOT3_RGB with MODULATE alpha, or DOT3_RGBA, of its texture
** and the primary colour, scales 1; the second MODULATE of an RGBA or RGB
** texture) in one pass, the colour from registers: combine_loop's DOT3,
** (t - b)(c - b) with b = 1/2 in the rgb lanes and 0 in alpha (the product
** commutes, so the arguments' order is immaterial), 4 v4_sum3 in the rgb
** lanes (all four for DOT3_RGBA; the scales of 1 change nothing), clamped;
** then stage_env's MODULATE. Later stages read only b->c. */
static void STAGE(stage_color_dot3_modulate)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    const unsigned int units = ctx->tex_units_on;
    const int u0 = __builtin_ctz(units), u1 = __builtin_ctz(units & (units - 1));
    const int rgba_dot = ctx->units[u0].combine_rgb == GL_DOT3_RGBA;
    const int keep_alpha = ctx->units[u1].bound->format != GL_RGBA;
    const V4 bias = v4_keep_alpha(v4_set1(FRAG_ONE / 2), v4_set1(0)), four = v4_set1(4);
    const int smooth = t->smooth;
    const V4 a0 = v4_load(smooth ? t->col[0] : t->flat), a1 = v4_load(smooth ? t->col[1] : t->flat);
    const V4 a2 = v4_load(smooth ? t->col[2] : t->flat), flat = v4_clamp01(a0);
    const int n = b->n;
    for (int j = 0; j < n; j++) {
        const V4 c = smooth ? v4_lerp3f_clamp01(a0, a1, a2, b->p[j]) : flat;
        const V4 p = V4_OP(mul)(V4_OP(sub)(v4_load(b->ct[j][u0]), bias), V4_OP(sub)(c, bias));
        const V4 d = V4_OP(mul)(v4_sum3(p), four);
        const V4 v = v4_clamp01(rgba_dot ? d : v4_keep_alpha(d, p));
        const V4 m = v4_mul01(v, v4_load(b->ct[j][u1]));
        v4_store(b->c[j], keep_alpha ? v4_keep_alpha(m, v) : m);
    }
}
#endif

#define UNIT_STAGES(u) \
    static void STAGE(stage_fetch##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_fetch)(ctx, t, b, u, FETCH_TEXELS); \
    } \
    static void STAGE(stage_fetch_rect##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_fetch_rect)(ctx, t, b, u, FETCH_TEXELS); \
    } \
    static void STAGE(stage_fetch_direct##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_fetch)(ctx, t, b, u, FETCH_DIRECT); \
    } \
    static void STAGE(stage_fetch_rect_direct##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_fetch_rect)(ctx, t, b, u, FETCH_DIRECT); \
    } \
    static void STAGE(stage_coords##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_fetch)(ctx, t, b, u, FETCH_COORDS); \
    } \
    static void STAGE(stage_coords_tx##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_fetch)(ctx, t, b, u, FETCH_COORDS_TX); \
    } \
    static void STAGE(stage_coords_rect##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_fetch_rect)(ctx, t, b, u, FETCH_COORDS); \
    } \
    static void STAGE(stage_env##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        (void)t; \
        STAGE(stage_env)(ctx, b, u); \
    } \
    static void STAGE(stage_color_modulate##u)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(stage_color_modulate)(ctx, t, b, u); \
    }
UNIT_STAGES(0)
UNIT_STAGES(1)
UNIT_STAGES(2)
UNIT_STAGES(3)
#undef UNIT_STAGES

/* fragment_fog of one fragment */
#if CHAIN_SIMD
/* fragment_fog of a factor f in [0, 1] (so f and 1 - f fit) with the fog
** colour's RGB as `fog`, which fits; the colour is clamped first */
static inline void STAGE(chunk_fog_fits)(FRAGV c[4], FRAGV f, V4 fog)
{
    const V4 v = v4_load(c);
    v4_store(c, v4_keep_alpha(v4_add(v4_mul01(v4_set1(f), v4_clamp01(v)), v4_mul01(v4_set1(FRAG_ONE - f), fog)), v));
}
#endif

static inline void STAGE(chunk_fog)(FRAGV c[4], FRAGV f, const FRAGV fc[3])
{
#if CHAIN_SIMD
    /* f and the fog colour must fit */
    const V4 fog = v4_rgb0(fc);
    if (v4_fits(v4_set1(f)) && v4_fits(v4_set1(FRAG_ONE - f)) && v4_fits(fog)) {
        STAGE(chunk_fog_fits)(c, f, fog);
        return;
    }
#endif
    fragment_fog(c, f, fc);
}

#if CHAIN_SIMD
/* whether the fog's lanes take a triangle: the per-vertex factor (no
** per-fragment fog), its values a (in the fixed build within +-2^30) and
** the fog colour fc in the kernels' ranges */
static inline int STAGE(fog_in_lanes)(const GlesContext *ctx, const NUM a[3], const FRAGV fc[3])
{
#if NUM_IS_FIXED
    const int32_t lim = (int32_t)1 << 30;
    const int fits = a[0] >= -lim && a[0] <= lim && a[1] >= -lim && a[1] <= lim && a[2] >= -lim && a[2] <= lim;
#else
    const int fits = 1;
    (void)a;
#endif
    return !ctx->fog_per_fragment && fits && v4_fits(v4_rgb0(fc));
}
#endif

/* fog (§3.8) with the factor interpolated, or from the interpolated distance */
static void STAGE(stage_fog)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    FRAGV fc[3];
    fragment_fog_color(ctx, fc);
    int j = 0;
#if CHAIN_SIMD
    /* the per-vertex factor of four fragments at a time (lanes), then each
    ** fragment's mix */
    const NUM a[3] = { v0->fog, v1->fog, v2->fog };
    if (STAGE(fog_in_lanes)(ctx, a, fc)) {
#if NUM_IS_FIXED
        __m256i fcv[3];
        avx2_fog_color_lanes(fc, fcv);
#if SIMD_AVX512_FX
        if (ctx_simd(ctx) >= SIMD_AVX512)    /* eight at a time, the rest as below */
            j = fx512_fog(a, (const WGT (*)[3])b->p, b->c, b->n, fc);
#endif
        for (; j + 4 <= b->n; j += 4)
            avx2_fog_mix4(&b->c[j], avx2_fog4(a, (const WGT (*)[3])&b->p[j]), fcv);
#else
        const V4 fog = v4_rgb0(fc);
        for (; j + 4 <= b->n; j += 4) {
            FRAGV f[4];
            v4_store(f, v4_clamp01(v4_lerp3x4(a, (const WGT (*)[3])&b->p[j])));
            for (int k = 0; k < 4; k++)
                STAGE(chunk_fog_fits)(b->c[j + k], f[k], fog);
        }
#endif
    }
#endif
    for (; j < b->n; j++) {
        const WGT *p = b->p[j];
        FRAGV f = ctx->fog_per_fragment
                      ? frag_from_num(fog_factor(ctx, wgt_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2])))
                      : frag_clamp01(frag_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2]));
        STAGE(chunk_fog)(b->c[j], f, fc);
    }
}

/* fog with one factor for the whole rectangle */
static void STAGE(stage_fog_const)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    FRAGV fc[3];
    fragment_fog_color(ctx, fc);
    for (int j = 0; j < b->n; j++)
        STAGE(chunk_fog)(b->c[j], b->rect->in.fog, fc);
}

static void STAGE(stage_alpha)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    const uint32_t ref = fragment_alpha_ref8(ctx);
#if CHAIN_SIMD
    /* fragment_alpha_pass of four fragments at a time, the function fixed
    ** for the chunk; the survivors' colours and offsets move to the front
    ** as they go (slot m <= j: only slots read already are written), every
    ** group alike: a branch for groups that all pass or all fail costs more
    ** where the texture's alpha decides, as it mispredicts */
    const int n = b->n;
    const __m128i rv = _mm_set1_epi32((int)ref);
    int j, m = 0;
#define ALPHA_VECTOR(FUNC) \
    for (j = 0; j + 4 <= n; j += 4) { \
        const V4 c0 = v4_load(b->c[j]), c1 = v4_load(b->c[j + 1]), c2 = v4_load(b->c[j + 2]), \
                 c3 = v4_load(b->c[j + 3]); \
        const unsigned bits = avx2_cmp4_i32(FUNC, v4_alpha8x4(c0, c1, c2, c3), rv); \
        uint32_t k4; \
        memcpy(&k4, &b->k[j], sizeof k4); \
        k4 = (uint32_t)_mm_cvtsi128_si32(_mm_shuffle_epi8(_mm_cvtsi32_si128((int)k4), \
                                                          _mm_cvtsi32_si128((int)avx2_compact8[bits]))); \
        memcpy(&b->k[m], &k4, sizeof k4); \
        v4_store(b->c[m], c0); \
        m += bits & 1; \
        v4_store(b->c[m], c1); \
        m += (bits >> 1) & 1; \
        v4_store(b->c[m], c2); \
        m += (bits >> 2) & 1; \
        v4_store(b->c[m], c3); \
        m += bits >> 3; \
    } \
    for (; j < n; j++) \
        if (fragment_compare(FUNC, fragment_alpha8(b->c[j][3]), ref)) { \
            if (m != j) \
                v4_store(b->c[m], v4_load(b->c[j])); \
            b->k[m++] = b->k[j]; \
        } \
    break;
    switch (ctx->alpha_func) {
    case GL_NEVER: b->n = 0; return;
    case GL_LESS: ALPHA_VECTOR(GL_LESS)
    case GL_EQUAL: ALPHA_VECTOR(GL_EQUAL)
    case GL_LEQUAL: ALPHA_VECTOR(GL_LEQUAL)
    case GL_GREATER: ALPHA_VECTOR(GL_GREATER)
    case GL_NOTEQUAL: ALPHA_VECTOR(GL_NOTEQUAL)
    case GL_GEQUAL: ALPHA_VECTOR(GL_GEQUAL)
    default: return;    /* GL_ALWAYS */
    }
#undef ALPHA_VECTOR
    b->n = m;
#else
    uint8_t keep[SPAN_CHUNK];
    /* fragment_alpha_pass, with the function fixed for the chunk */
#define ALPHA_LOOP(FUNC) \
    for (int j = 0; j < b->n; j++) \
        keep[j] = (uint8_t)fragment_compare(FUNC, fragment_alpha8(b->c[j][3]), ref); \
    break;
    switch (ctx->alpha_func) {
    case GL_NEVER: ALPHA_LOOP(GL_NEVER)
    case GL_LESS: ALPHA_LOOP(GL_LESS)
    case GL_EQUAL: ALPHA_LOOP(GL_EQUAL)
    case GL_LEQUAL: ALPHA_LOOP(GL_LEQUAL)
    case GL_GREATER: ALPHA_LOOP(GL_GREATER)
    case GL_NOTEQUAL: ALPHA_LOOP(GL_NOTEQUAL)
    case GL_GEQUAL: ALPHA_LOOP(GL_GEQUAL)
    default: ALPHA_LOOP(GL_ALWAYS)
    }
#undef ALPHA_LOOP
    chunk_compact(b, keep, 1);
#endif
}

/* }==================================================================== */

/* {====================================================================
** the write: blending, dither, logic op, masks (§4.1.7-4.1.10) */

/* every state: fragment_process's tail */
static void STAGE(stage_write)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    const size_t row = (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    FragWrite w;
    fragment_write_setup(ctx, &w);
    for (int j = 0; j < b->n; j++)
        fragment_write(ctx, &w, b->x0 + b->k[j], b->y, row + b->k[j], b->c[j]);
}

/* RGBA8888, every channel written, no logic op, blend kind 0 (none), 1
** (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) or 2 (ONE, ONE), both with FUNC_ADD */
static inline void STAGE(write_rgba8)(GlesContext *ctx, SpanBuf *b, int kind)
{
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    int j = 0;
#if CHAIN_SIMD
    /* four fragments at a time (avx2_rgba8x4); a group with a channel
    ** outside the fixed build's kernel's range by v4_rgba8; first eight at
    ** a time where the double build runs AVX-512 */
    const int n = b->n;
#if SIMD_AVX512_INSTANCE
    if (ctx_simd(ctx) >= SIMD_AVX512)
        j = avx512_write_rgba8(dst, b->k, n, b->c, kind);
#endif
    for (; j + 4 <= n; j += 4) {
        uint32_t k4;
        memcpy(&k4, &b->k[j], sizeof k4);
        const int run = slots_adjacent4(&b->k[j]);
        const __m128i d = kind ? avx2_load_words4(dst, k4, run) : _mm_setzero_si128();
        __m128i w;
        if (avx2_rgba8x4(&b->c[j], d, kind, &w)) {
            avx2_store_words4(dst, k4, run, w);
        } else {
            for (int i = 0; i < 4; i++) {
                uint32_t *at = &dst[(k4 >> (8 * i)) & 0xFFu];
                *at = v4_rgba8(v4_load(b->c[j + i]), *at, kind);
            }
        }
    }
#endif
    for (; j < b->n; j++) {
        uint32_t *at = &dst[b->k[j]];
#if CHAIN_SIMD
        *at = v4_rgba8(v4_load(b->c[j]), *at, kind);
#else
        *at = span_rgba8(ctx, b->c[j], *at, kind);
#endif
    }
}

static void STAGE(stage_write_rgba8)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    STAGE(write_rgba8)(ctx, b, 0);
}

#if CHAIN_SIMD && (NUM_IS_FIXED || defined(GLES_NUM_DOUBLE))
/* a fused fog-and-write stage's inputs: the triangle's per-vertex fog
** factors a and the fog colour fc; 1 where the fused pass takes them
** (stage_fog's lanes take the triangle) */
static inline int STAGE(fog_write_lanes)(GlesContext *ctx, const TriSetup *t, NUM a[3], FRAGV fc[3])
{
    for (int i = 0; i < 3; i++)
        a[i] = t->v[i]->fog;
    fragment_fog_color(ctx, fc);
    return STAGE(fog_in_lanes)(ctx, a, fc);
}

/* the fog and write of slot j's colour, one fragment (rgb565: as
** stage_write_565 writes, dithered by t_row) */
static inline void STAGE(fog_write1)(SpanBuf *b, int j, const NUM a[3], const FRAGV fc[3], void *dst, int rgb565,
                                     int dither, const FRAGV t_row[4])
{
    const WGT *p = b->p[j];
    STAGE(chunk_fog)(b->c[j], frag_clamp01(frag_lerp3(a[0], a[1], a[2], p[0], p[1], p[2])), fc);
    if (rgb565) {
        ((uint16_t *)dst)[b->k[j]] = (uint16_t)v4_pack565(v4_load(b->c[j]), dither, t_row[(b->x0 + b->k[j]) & 3]);
    } else {
        uint32_t *at = &((uint32_t *)dst)[b->k[j]];
        *at = v4_rgba8(v4_load(b->c[j]), *at, 0);
    }
}

/* stage_fog_write_rgba8's or (rgb565) stage_fog_write_565's pass over the
** slots whose bit in done (NULL: none) is clear: in the fixed build eight
** lanes at a time where AVX-512 runs (fx512_fog_write_rgba8,
** fx512_fog_write_565), four (avx2_fog_write_rgba8x4,
** avx2_fog_write_565x4), then one by one; in the double build (the slots
** its fused stage's float lanes left) one by one */
static void STAGE(fog_write_rest)(GlesContext *ctx, SpanBuf *b, const NUM a[3], const FRAGV fc[3],
                                  const uint64_t *done, int rgb565)
{
    void *dst = chunk_color(ctx, b, rgb565);
    const int n = b->n, dither = ctx->dither;
    FRAGV t_row[4] = { 0 };
    if (rgb565)
        dither_row(b, dither, t_row);
#if NUM_IS_FIXED
    int j = 0;
#if SIMD_AVX512_FX
    if (!done && ctx_simd(ctx) >= SIMD_AVX512)
        j = rgb565 ? fx512_fog_write_565(a, (const WGT (*)[3])b->p, (const FRAGV (*)[4])b->c, n, fc, dst, b->k, b->x0,
                                         dither, t_row)
                   : fx512_fog_write_rgba8(a, (const WGT (*)[3])b->p, (const FRAGV (*)[4])b->c, n, fc, dst, b->k);
#endif
    __m256i fcv[3];
    avx2_fog_color_lanes(fc, fcv);
#define FOG_WRITE4(j) \
    do { \
        const __m256i f_ = avx2_fog4(a, (const WGT (*)[3])&b->p[j]); \
        if (rgb565) \
            avx2_fog_write_565x4((const FRAGV (*)[4])&b->c[j], f_, fcv, dst, &b->k[j], b->x0, dither, t_row); \
        else \
            avx2_fog_write_rgba8x4((const FRAGV (*)[4])&b->c[j], f_, fcv, dst, &b->k[j]); \
    } while (0)
    if (!done) {
        for (; j + 4 <= n; j += 4)
            FOG_WRITE4(j);
        for (; j < n; j++)
            STAGE(fog_write1)(b, j, a, fc, dst, rgb565, dither, t_row);
        return;
    }
#else
    if (!done) {
        for (int j = 0; j < n; j++)
            STAGE(fog_write1)(b, j, a, fc, dst, rgb565, dither, t_row);
        return;
    }
#define FOG_WRITE4(j) ((void)0)     /* (the double build's slots go one by one) */
#endif
    /* the clear bits of each word of done: four in a row at once */
    for (int base = 0; base < n; base += 64) {
        uint64_t todo = ~done[base >> 6];
        if (n - base < 64)
            todo &= ((uint64_t)1 << (n - base)) - 1;
        while (todo) {
            const int i = __builtin_ctzll(todo);
            if (NUM_IS_FIXED && ((todo >> i) & 0xF) == 0xF) {
                FOG_WRITE4(base + i);
                todo &= ~((uint64_t)0xF << i);
            } else {
                STAGE(fog_write1)(b, base + i, a, fc, dst, rgb565, dither, t_row);
                todo &= todo - 1;
            }
        }
    }
#undef FOG_WRITE4
}
#endif

#if CHAIN_SIMD && NUM_IS_FIXED
/* stage_fog then stage_write_rgba8 (no blend, every channel written) in
** one pass where STAGE(fog_write_lanes) holds, the fogged colour going
** straight to the bytes (STAGE(fog_write_rest)); else the two stages */
static void STAGE(stage_fog_write_rgba8)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    NUM a[3];
    FRAGV fc[3];
    if (!STAGE(fog_write_lanes)(ctx, t, a, fc)) {
        STAGE(stage_fog)(ctx, t, b);
        STAGE(write_rgba8)(ctx, b, 0);
        return;
    }
    STAGE(fog_write_rest)(ctx, b, a, fc, NULL, 0);
}

#endif

static void STAGE(stage_write_rgba8_alpha)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    STAGE(write_rgba8)(ctx, b, 1);
}

static void STAGE(stage_write_rgba8_add)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    STAGE(write_rgba8)(ctx, b, 2);
}

/* RGBA8888 under any colour mask: blend kind 0..2 (as write_rgba8) or a
** logic op `op` (kind 0: the logic op turns blending off), GL_COPY for
** none; the bits of `keep` stay as stored. fragment_write's steps for
** these states (no dither on RGBA8888), with the op fixed per chunk. */
static inline __attribute__((always_inline)) void STAGE(write_rgba8_ops)(GlesContext *ctx, SpanBuf *b, int kind,
                                                                        unsigned int op, uint32_t keep)
{
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    int j = 0;
#if CHAIN_SIMD
    /* four fragments at a time, as write_rgba8 */
    const int n = b->n;
    const __m128i vkeep = _mm_set1_epi32((int)keep);
    for (; j + 4 <= n; j += 4) {
        uint32_t k4;
        memcpy(&k4, &b->k[j], sizeof k4);
        const int run = slots_adjacent4(&b->k[j]);
        const __m128i d = avx2_load_words4(dst, k4, run);
        __m128i s;
        if (avx2_rgba8x4(&b->c[j], d, kind, &s)) {
            const __m128i x = avx2_logic_op4(op, s, d);
            avx2_store_words4(dst, k4, run, _mm_or_si128(_mm_and_si128(d, vkeep), _mm_andnot_si128(vkeep, x)));
        } else {
            for (int i = 0; i < 4; i++) {
                uint32_t *at = &dst[(k4 >> (8 * i)) & 0xFFu];
                const uint32_t dd = *at;
                *at = (dd & keep) | (fragment_logic_op(op, v4_rgba8(v4_load(b->c[j + i]), dd, kind), dd) & ~keep);
            }
        }
    }
#endif
    for (; j < b->n; j++) {
        uint32_t *at = &dst[b->k[j]];
        const uint32_t d = *at;
#if CHAIN_SIMD
        const uint32_t s = v4_rgba8(v4_load(b->c[j]), d, kind);
#else
        const uint32_t s = span_rgba8(ctx, b->c[j], d, kind);
#endif
        *at = (d & keep) | (fragment_logic_op(op, s, d) & ~keep);
    }
}

/* RGBA8888 with a logic op, under any colour mask */
static void STAGE(stage_write_rgba8_logic)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    FragWrite w;
    fragment_write_setup(ctx, &w);
#define LOGIC_WRITE(OP) \
    case OP: STAGE(write_rgba8_ops)(ctx, b, 0, OP, w.keep); break;
    switch (ctx->logic_op) {
    LOGIC_WRITE(GL_CLEAR)
    LOGIC_WRITE(GL_AND)
    LOGIC_WRITE(GL_AND_REVERSE)
    LOGIC_WRITE(GL_COPY)
    LOGIC_WRITE(GL_AND_INVERTED)
    LOGIC_WRITE(GL_NOOP)
    LOGIC_WRITE(GL_XOR)
    LOGIC_WRITE(GL_OR)
    LOGIC_WRITE(GL_NOR)
    LOGIC_WRITE(GL_EQUIV)
    LOGIC_WRITE(GL_INVERT)
    LOGIC_WRITE(GL_OR_REVERSE)
    LOGIC_WRITE(GL_COPY_INVERTED)
    LOGIC_WRITE(GL_OR_INVERTED)
    LOGIC_WRITE(GL_NAND)
    default: STAGE(write_rgba8_ops)(ctx, b, 0, GL_SET, w.keep); break;
    }
#undef LOGIC_WRITE
}

/* RGBA8888 with some channel masked, no logic op, blend kind 0..2
** (span_blend_kind) */
static void STAGE(stage_write_rgba8_masked)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    FragWrite w;
    fragment_write_setup(ctx, &w);
    switch (span_blend_kind(ctx)) {
    case 1: STAGE(write_rgba8_ops)(ctx, b, 1, GL_COPY, w.keep); break;
    case 2: STAGE(write_rgba8_ops)(ctx, b, 2, GL_COPY, w.keep); break;
    default: STAGE(write_rgba8_ops)(ctx, b, 0, GL_COPY, w.keep); break;
    }
}

#if CHAIN_SIMD && !NUM_IS_FIXED
/* the float builds' RGB565 writes four fragments at a time (blend: SRC_ALPHA,
** ONE_MINUS_SRC_ALPHA): their colours transposed to channels, the stored
** words' channels as d / maxval (the division that ctx->unorm5 and
** unorm6 hold), then the per-fragment code's operations lane by lane;
** returns the slots done (the whole groups) */
static int STAGE(write_565x4)(GlesContext *ctx, SpanBuf *b, uint16_t *dst, const FRAGV t_row[4], int blend)
{
    const int n4 = b->n & ~3, dither = ctx->dither;
    for (int j = 0; j < n4; j += 4) {
        const uint8_t *k = &b->k[j];
        V4 ch[4] = { v4_load(b->c[j]), v4_load(b->c[j + 1]), v4_load(b->c[j + 2]), v4_load(b->c[j + 3]) };
        v4_transpose4(ch);
        const V4 t = V4_OP(setr)(t_row[(b->x0 + k[0]) & 3], t_row[(b->x0 + k[1]) & 3], t_row[(b->x0 + k[2]) & 3],
                                 t_row[(b->x0 + k[3]) & 3]);
        if (blend) {
            const __m128i d = _mm_setr_epi32(dst[k[0]], dst[k[1]], dst[k[2]], dst[k[3]]);
            const __m128i dc[3] = { _mm_srli_epi32(d, 11), _mm_and_si128(_mm_srli_epi32(d, 5), _mm_set1_epi32(63)),
                                    _mm_and_si128(d, _mm_set1_epi32(31)) };
            static const int maxval[3] = { 31, 63, 31 };
            const V4 va = v4_clamp01(ch[3]), ia = v4_one_minus(va);
            for (int i = 0; i < 3; i++) {
                const V4 dv = V4_OP(div)(v4_from_i32(dc[i]), V4_OP(set1)((NUM)maxval[i]));
                ch[i] = v4_add(v4_mul01(v4_clamp01(ch[i]), va), v4_mul01(dv, ia));
            }
        }
        const __m128i w = v4_pack565x4(ch, dither, t);
        dst[k[0]] = (uint16_t)_mm_extract_epi32(w, 0);
        dst[k[1]] = (uint16_t)_mm_extract_epi32(w, 1);
        dst[k[2]] = (uint16_t)_mm_extract_epi32(w, 2);
        dst[k[3]] = (uint16_t)_mm_extract_epi32(w, 3);
    }
    return n4;
}
#endif

/* RGB565, red, green and blue written, no blend or logic op */
static void STAGE(stage_write_565)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint16_t *dst = (uint16_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    const int dither = ctx->dither;
    FRAGV t_row[4];
    dither_row(b, dither, t_row);
    int j = 0;
#if CHAIN_SIMD && !NUM_IS_FIXED
    j = STAGE(write_565x4)(ctx, b, dst, t_row, 0);
#endif
    for (; j < b->n; j++) {
        const FRAGV t_d = t_row[(b->x0 + b->k[j]) & 3];
#if CHAIN_SIMD
        dst[b->k[j]] = (uint16_t)v4_pack565(v4_load(b->c[j]), dither, t_d);
#else
        dst[b->k[j]] = (uint16_t)pack565(b->c[j], dither, t_d);
#endif
    }
}

#if CHAIN_SIMD && NUM_IS_FIXED
/* stage_fog then stage_write_565 (no blend, red, green and blue written) in
** one pass where STAGE(fog_write_lanes) holds (STAGE(fog_write_rest));
** else the two stages */
static void STAGE(stage_fog_write_565)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    NUM a[3];
    FRAGV fc[3];
    if (!STAGE(fog_write_lanes)(ctx, t, a, fc)) {
        STAGE(stage_fog)(ctx, t, b);
        STAGE(stage_write_565)(ctx, t, b);
        return;
    }
    STAGE(fog_write_rest)(ctx, b, a, fc, NULL, 1);
}
#endif

#if CHAIN_SIMD && (NUM_IS_FIXED || defined(GLES_NUM_DOUBLE))

/* a lone REPLACE unit of an RGBA texture with a level of detail (its
** sampler lod_block's), the fog and the RGBA8888 or (rgb565) RGB565 write
** in one stage: the texels of GL_LINEAR levels fogged and written in float
** lanes where each pixel is proved (texture_span_fog_write), the rest by
** the exact pass of stage_fog_write_rgba8 or stage_fog_write_565. The
** float lanes' bound needs the vertices' fog factors within [-2, 2] and
** the fog colour in [0, 1]; else, or where the kernel does not apply, the
** separate stages */
static inline void STAGE(sample_fog_write)(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int rgb565)
{
    const int u = __builtin_ctz(ctx->tex_units_on);
    STAGE(stage_fetch)(ctx, t, b, u, FETCH_COORDS);
    NUM a[3];
    FRAGV fc[3];
    const int lanes = STAGE(fog_write_lanes)(ctx, t, a, fc);
    int fits = lanes;
    for (int i = 0; i < 3; i++)
        fits &= a[i] >= -2 * NUM_ONE && a[i] <= 2 * NUM_ONE && fc[i] >= 0 && fc[i] <= FRAG_ONE;
    if (fits) {
        uint64_t done[SPAN_CHUNK / 64] = { 0 };
        TexFogWrite fw = { .p = (const WGT (*)[3])b->p, .dst = chunk_color(ctx, b, rgb565), .k = b->k,
                           .rgb565 = rgb565, .dither = ctx->dither, .x0 = b->x0, .done = done };
        FRAGV t_row[4] = { 0 };
        if (rgb565)
            dither_row(b, ctx->dither, t_row);
        /* the kernel's float values: the fixed build's 16.16 factors
        ** against its 0.30 weights (2^-46) and 0.30 colours (2^-30) */
#if NUM_IS_FIXED
        const double num_scale = 0x1p-46, frag_scale = 0x1p-30;
#else
        const double num_scale = 1, frag_scale = 1;
#endif
        for (int i = 0; i < 4; i++)
            fw.t_row[i] = ctx->dither ? (float)((double)t_row[i] * frag_scale) : 0.0f;
        for (int i = 0; i < 3; i++) {
            fw.a[i] = (float)((double)a[i] * num_scale);
            fw.fc[i] = (float)((double)fc[i] * frag_scale);
        }
        if (texture_span_fog_write(ctx->units[u].bound, b->n, b->tc, b->tx, b->ty, b->c[0], 4, ctx->texel_unorm8,
                                   &fw)) {
            STAGE(fog_write_rest)(ctx, b, a, fc, done, rgb565);
            return;
        }
    }
    STAGE(chunk_sample)(ctx, b, u, 1);
#if NUM_IS_FIXED
    if (lanes) {
        STAGE(fog_write_rest)(ctx, b, a, fc, NULL, rgb565);
    } else
#endif
    {
        STAGE(stage_fog)(ctx, t, b);
        (rgb565 ? STAGE(stage_write_565) : STAGE(stage_write_rgba8))(ctx, t, b);
    }
}

static void STAGE(stage_sample_fog_write_rgba8)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(sample_fog_write)(ctx, t, b, 0);
}

static void STAGE(stage_sample_fog_write_565)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(sample_fog_write)(ctx, t, b, 1);
}
#endif

/* RGB565, red, green and blue written, SRC_ALPHA, ONE_MINUS_SRC_ALPHA with
** FUNC_ADD (fragment_blend's arithmetic for those factors) */
static void STAGE(stage_write_565_alpha)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint16_t *dst = (uint16_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    const int dither = ctx->dither;
    FRAGV t_row[4];
    dither_row(b, dither, t_row);
    int j = 0;
#if CHAIN_SIMD && !NUM_IS_FIXED
    j = STAGE(write_565x4)(ctx, b, dst, t_row, 1);
#endif
    for (; j < b->n; j++) {
        const FRAGV *c = b->c[j];
        uint32_t d = dst[b->k[j]];
        const FRAGV t_d = t_row[(b->x0 + b->k[j]) & 3];
        FRAGV dv[4] = { ctx->unorm5[d >> 11], ctx->unorm6[(d >> 5) & 63], ctx->unorm5[d & 31], 0 };
#if CHAIN_SIMD
        /* dv goes to the register lane by lane: a vector load of the four
        ** scalar stores just made would wait for them (no store forwarding) */
        const V4 cv = v4_clamp01(v4_load(c)), va = v4_alpha(cv);
        const V4 v = v4_add(v4_mul01(cv, va), v4_mul01(v4_rgb0(dv), v4_one_minus(va)));
        dst[b->k[j]] = (uint16_t)v4_pack565(v, dither, t_d);
#else
        FRAGV sa = frag_clamp01(c[3]), da = FRAG_ONE - sa;
        FRAGV v[3];
        for (int i = 0; i < 3; i++)
            v[i] = frag_mul(frag_clamp01(c[i]), sa) + frag_mul(dv[i], da);
        dst[b->k[j]] = (uint16_t)pack565(v, dither, t_d);
#endif
    }
}

/* }==================================================================== */

/* {====================================================================
** composition and the driver */

/* a rectangle's constant inputs for the chunk's slots (its first stage, so
** every later slot a fragment can move to is among them) */
static void STAGE(stage_rect_source)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    const FragIn *in = &b->rect->in;
    const int texturing = ctx->tex_units_on != 0;
    /* the colour once, in locals: the buffer's stores could alias the rectangle */
    FRAGV c[4];
    for (int i = 0; i < 4; i++)
        c[i] = texturing ? frag_clamp01(in->c[i]) : in->c[i];
    const uint32_t z = in->z;
    const int n = b->n;
    for (int j = 0; j < n; j++)
        b->z[j] = z;
#if CHAIN_SIMD
    const V4 cv = v4_load(c);
    for (int j = 0; j < n; j++)
        v4_store(b->c[j], cv);
    if (texturing)
        for (int j = 0; j < n; j++)
            v4_store(b->cf[j], cv);
#else
    for (int j = 0; j < n; j++)
        memcpy(b->c[j], c, sizeof c);
    if (texturing)
        for (int j = 0; j < n; j++)
            memcpy(b->cf[j], c, sizeof c);
#endif
}

/* }==================================================================== */

#if CHAIN_SIMD
/* a fused stage's coordinates where its lanes sample: where stage_persp
** left any of the first (DOT3) unit's in b->tx or the sampled unit's in
** b->tc unformed, the coordinate stages' work (in their order: the one
** into b->tx forms its values in b->tc first), in place of two stages
** that mostly find everything done */
static inline void STAGE(fused_coords)(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int u0, int u, int sampled0)
{
    if (sampled0 && !(b->tx_unit == u0 && b->tx_done >= b->n))
        STAGE(stage_fetch)(ctx, t, b, u0, FETCH_COORDS_TX);
    if (!(b->tc_unit == u && b->tc_done >= b->n))
        STAGE(stage_fetch)(ctx, t, b, u, FETCH_COORDS);
}

/* a fused stage's units: the first enabled one u0 and the one it
** modulates by u (the second with dot3, the DOT3 pair), and whether it
** samples u0's texels itself (its sampler has the vector kernel; its
** coordinates are in b->tx, FETCH_COORDS_TX) */
static inline void STAGE(fused_units)(const GlesContext *ctx, int dot3, int *u0, int *u, int *sampled0)
{
    const unsigned int units = ctx->tex_units_on;
    *u0 = __builtin_ctz(units);
    *u = dot3 ? __builtin_ctz(units & (units - 1)) : *u0;
    *sampled0 = dot3 && ctx->sample_group[*u0] > 1;
}
#endif

#if CHAIN_SIMD && (NUM_IS_FIXED || defined(GLES_NUM_DOUBLE))
/* stage_color_modulate of the one enabled unit (or a rectangle's colour
** and stage_env's MODULATE), the alpha test and write_rgba8 (blend kind 0,
** 1 or 2) or stage_write_565 / stage_write_565_alpha in one pass of eight
** float lanes, each byte proved equal to the exact chain's or taken from
** it (avx2_modwrite8). The double build's AVX2 instance has it too
** (stage_modulate_write_proved and the rest), where its own kernel in
** double lanes needs AVX-512. Source 0 takes the texels a fetch stage
** sampled; source 1 samples at the coordinates a coordinates stage left (a
** bilinear sampler with a vector kernel, texture_span_sample_group > 1), and
** there the unit may be a lone REPLACE of an RGBA texture. With dot3 the
** units are two (span_dot3_pair): the first one's COMBINE DOT3 of its
** texels (a fetch stage sampled them) and the colour comes before the
** second one's MODULATE. Vertex colours outside [0, 1] go through the
** separate stages. */
static inline __attribute__((always_inline)) void STAGE(modwrite_proved)(GlesContext *ctx, const TriSetup *t,
                                                                        SpanBuf *b, int src, int dot3)
{
    /* a primitive's chunks share the constants and the stage's choices,
    ** in the context: the first chunk forms them, each chunk completes
    ** them with its own DOT3 texels or coordinates and dither row */
    _Static_assert(sizeof(Avx2ModWrite) <= GLES_FUSED_SETUP_BYTES, "the context has room for the setup");
    Avx2ModWrite *const m = ctx->fused_setup;
    const uint64_t serial = b->rect ? b->rect->serial : t->serial;
    const size_t stride = GLES_MAX_TEXTURE_UNITS * 4;
    if (ctx->fused_serial != serial) {
        /* (the units are kept with the constants either way: the stage's
        ** colours out of range need them too) */
        STAGE(fused_units)(ctx, dot3, &m->u0, &m->u, &m->sampled0);
        const int u0 = m->u0, u = m->u;
        const Texture *tex = ctx->units[u].bound;
        const int kind = span_blend_kind(ctx);
        const int replace = ctx->units[u].env_mode == GL_REPLACE;
        const int smooth = !replace && !b->rect && t->smooth;
        const FRAGV *flat = b->rect ? b->rect->in.c : t->flat;
        const FRAGV *const a[3] = { smooth ? t->col[0] : flat, smooth ? t->col[1] : flat,
                                    smooth ? t->col[2] : flat };
        int in_range = 1;
        for (int i = 0; i < 3 && smooth; i++)
            for (int c = 0; c < 4; c++)
                in_range &= a[i][c] >= 0 && a[i][c] <= FRAG_ONE;
        ctx->fused_serial = serial, ctx->fused_in_range = in_range;
        if (in_range) {
            avx2_modwrite_setup(m, a, smooth, tex->format != GL_RGBA, kind,
                                ctx->alpha_test ? ctx->alpha_func : GL_ALWAYS, fragment_alpha_ref8(ctx));
            if (replace)
                avx2_modwrite_replace(m);
            if (src == 1)
                modwrite_texture_setup(&m->tx, tex, ctx->samplers[u], ctx->texel_unorm8);
            for (int i = 0; i < 3; i++)
                m->a[i] = a[i];
            if (dot3) {
                m->d3.rgba = ctx->units[u0].combine_rgb == GL_DOT3_RGBA;
                m->d3.ct0_stride = stride;
                if (m->sampled0)
                    modwrite_texture_setup(&m->d3.tx0, ctx->units[u0].bound, ctx->samplers[u0], ctx->texel_unorm8);
                m->dot3 = &m->d3;
            }
        }
    }
    const int u0 = m->u0, u = m->u, sampled0 = m->sampled0;
    const int rgb565 = ctx->color_format == GLES_COLOR_RGB565;
    if (src == 1 && !b->rect)
        STAGE(fused_coords)(ctx, t, b, u0, u, sampled0);
    if (!ctx->fused_in_range) {
        /* vertex colours outside [0, 1]: the separate stages */
        if (src == 1)
            STAGE(chunk_sample)(ctx, b, u, 0);
        if (sampled0)
            ctx->samplers[u0](ctx->units[u0].bound, b->n, b->tx, b->tx, b->tx, b->ct[0][u0], stride,
                              ctx->texel_unorm8);
        if (dot3) {
            STAGE(stage_color)(ctx, t, b);
            STAGE(stage_env)(ctx, b, u0);
            STAGE(stage_env)(ctx, b, u);
        } else {
            STAGE(stage_color_modulate)(ctx, t, b, u);
        }
        if (ctx->alpha_test)
            STAGE(stage_alpha)(ctx, t, b);
        const int kind = span_blend_kind(ctx);
        if (rgb565)
            (kind ? STAGE(stage_write_565_alpha) : STAGE(stage_write_565))(ctx, t, b);
        else
            STAGE(write_rgba8)(ctx, b, kind);
        return;
    }
    if (dot3) {
        m->d3.ct0 = sampled0 ? NULL : b->ct[0][u0];
        m->d3.tc0 = sampled0 ? b->tx : NULL;
    }
    int n = b->n;
    if (src == 1 && !modwrite_overlaps(m->kind, m->alpha.test, rgb565, n, 8)) {
        /* the tail padded to a group of eight (the slots past n are free) */
        _Static_assert(SPAN_CHUNK % 8 == 0, "a padded group stays within the chunk");
        n = avx2_pad_group(8, n, b->k, b->p, m->smooth, b->tc, dot3 && !sampled0 ? b->ct[0][u0] : NULL, stride);
        for (int j = b->n; j < n && sampled0; j++)
            b->tx[j] = b->tx[b->n - 1];
    }
    if (rgb565) {
        FRAGV t_row[4];
        dither_row(b, ctx->dither, t_row);
        avx2_modwrite_dither(m, ctx->dither, t_row);
    }
    avx2_modwrite_dispatch(m, m->a, src, rgb565, n, b->n, b->k, b->x0, (const WGT (*)[3])b->p, b->ct[0][u], stride,
                           b->tc, chunk_color(ctx, b, rgb565), ctx->unorm5, ctx->unorm6, ctx_simd(ctx) >= SIMD_AVX512);
}

/* the kernel's four stages: sampled here or fetched (source 1 or 0), with
** and without the DOT3 pair; the double build's named _proved, beside its
** kernel in AVX-512's double lanes */
#define MODWRITE_PROVED_STAGES(suffix) \
    static void STAGE(stage_modulate_write##suffix)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(modwrite_proved)(ctx, t, b, 0, 0); \
    } \
    static void STAGE(stage_sample_write##suffix)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(modwrite_proved)(ctx, t, b, 1, 0); \
    } \
    static void STAGE(stage_dot3_write##suffix)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(modwrite_proved)(ctx, t, b, 0, 1); \
    } \
    static void STAGE(stage_dot3_sample_write##suffix)(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        STAGE(modwrite_proved)(ctx, t, b, 1, 1); \
    }
#if NUM_IS_FIXED
MODWRITE_PROVED_STAGES()
#else
MODWRITE_PROVED_STAGES(_proved)
#endif
#undef MODWRITE_PROVED_STAGES
#endif

#if CHAIN_SIMD && !NUM_IS_FIXED
/* stage_color_modulate of the one enabled unit (or a rectangle's colour
** and stage_env's MODULATE), the alpha test and write_rgba8 (blend kind 0,
** 1 or 2) or stage_write_565 / stage_write_565_alpha in one pass of eight
** lanes: the build's operations in their order (f8_modwrite), so the words
** are the separate stages'. The double build's lanes are AVX-512's
** (avx512_modwrite), and the chain takes the stage only where they run. Source 0 takes
** the texels a fetch stage sampled; source 1 samples at the coordinates a
** coordinates stage left (a bilinear sampler with a vector kernel), and
** there the unit may be a lone REPLACE of an RGBA texture. The chunk's
** tail is padded to a whole group with copies of its last fragment. With
** dot3 (the float build's lanes and the double build's AVX-512 ones) the units are two
** (span_dot3_pair): the first one's COMBINE DOT3 of its texels (fetched,
** or sampled here at the coordinates in b->tx) and the colour comes
** before the second one's MODULATE, in stage_color_dot3_modulate's
** operations (f8_dot3). */
static inline __attribute__((always_inline)) void STAGE(modulate_write)(GlesContext *ctx, const TriSetup *t,
                                                                       SpanBuf *b, int src, int dot3)
{
    int u0, u, sampled0;
    STAGE(fused_units)(ctx, dot3, &u0, &u, &sampled0);
    const Texture *tex = ctx->units[u].bound;
    const int replace = ctx->units[u].env_mode == GL_REPLACE;
    const int smooth = !replace && !b->rect && t->smooth;
    const FRAGV *flat = b->rect ? b->rect->in.c : t->flat;
    const FRAGV *const a[3] = { smooth ? t->col[0] : flat, smooth ? t->col[1] : flat, smooth ? t->col[2] : flat };
    /* the setup once per primitive (many rows of a small one are short) */
    _Static_assert(sizeof(F8ModWrite) <= GLES_FUSED_SETUP_BYTES, "the context has room for the setup");
    F8ModWrite *const m = ctx->fused_setup;
    const uint64_t serial = b->rect ? b->rect->serial : t->serial;
    /* stage_persp left the weights and coordinates to the lanes (source
    ** 1 of a triangle: the chain's ctx->chain_fused_lanes) */
#if SIMD_AVX512_INSTANCE
    const int lanes = src == 1 && !b->rect && b->lanes;
    F8Affine af;
    if (lanes) {
        af.e1 = (double)b->e0[1], af.e2 = (double)b->e0[2];
        af.a1 = (double)t->ea[1], af.a2 = (double)t->ea[2];
        af.inv_area = t->wgt.inv_area;
        span_unit_st(t, u, af.s, af.t);
        span_unit_st(t, sampled0 ? u0 : -1, af.s0, af.t0);
    }
#else
    const int lanes = 0;
#endif
    if (src == 1 && !b->rect && !lanes)
        STAGE(fused_coords)(ctx, t, b, u0, u, sampled0);
    if (ctx->fused_serial != serial) {
        f8_modwrite_setup(m, a, smooth, tex->format != GL_RGBA, replace, span_blend_kind(ctx),
                          ctx->alpha_test ? ctx->alpha_func : GL_ALWAYS, fragment_alpha_ref8(ctx));
        if (src == 1)
            modwrite_texture_setup(&m->tx, tex, ctx->samplers[u], ctx->texel_unorm8);
        if (dot3)
            m->dot3 = ctx->units[u0].combine_rgb == GL_DOT3_RGBA ? 2 : 1;
        if (sampled0)
            modwrite_texture_setup(&m->tx0, ctx->units[u0].bound, ctx->samplers[u0], ctx->texel_unorm8);
        ctx->fused_serial = serial;
    }
    const size_t stride = GLES_MAX_TEXTURE_UNITS * 4;
    const int rgb565 = ctx->color_format == GLES_COLOR_RGB565;
    int n = b->n;
    if (!modwrite_overlaps(m->kind, m->alpha.test, rgb565, n, F8_N)) {
        /* the tail padded to a whole group (the slots past n are free) */
        _Static_assert(SPAN_CHUNK % 8 == 0, "a padded group stays within the chunk");
        n = avx2_pad_group(F8_N, b->n, b->k, b->p, smooth && !lanes, src == 1 && !lanes ? b->tc : NULL,
                              src == 0 ? b->ct[0][u] : NULL, stride);
        for (int j = b->n; j < n && dot3 && !lanes; j++) {
            if (sampled0)
                b->tx[j] = b->tx[b->n - 1];
            else
                memcpy(b->ct[j][u0], b->ct[b->n - 1][u0], sizeof b->ct[j][u0]);
        }
    }
    if (rgb565) {
        FRAGV t_row[4];
        dither_row(b, ctx->dither, t_row);
        f8_modwrite_dither(m, ctx->dither, t_row);
    }
#if defined(GLES_NUM_FLOAT)
    if (dot3)
        f8_modwrite_dispatch_dot3(m, src, rgb565, 1, n, b->n, b->k, (const WGT (*)[3])b->p,
                                  sampled0 ? NULL : b->ct[0][u0], b->tx, b->ct[0][u], stride, b->tc, b->x0,
                                  chunk_color(ctx, b, rgb565), NULL);
    else
        f8_modwrite_dispatch(m, src, rgb565, n, b->n, b->k, (const WGT (*)[3])b->p, b->ct[0][u], stride, b->tc,
                             b->x0, chunk_color(ctx, b, rgb565), NULL);
#else
    if (dot3)
        avx512_dot3_write(m, src, rgb565, n, b->n, b->k, (const WGT (*)[3])b->p, sampled0 ? NULL : b->ct[0][u0],
                          b->tx, b->ct[0][u], stride, b->tc, b->x0, chunk_color(ctx, b, rgb565), lanes ? &af : NULL);
    else
        avx512_modwrite(m, src, rgb565, n, b->n, b->k, (const WGT (*)[3])b->p, b->ct[0][u], stride, b->tc, b->x0,
                        chunk_color(ctx, b, rgb565), lanes ? &af : NULL);
#endif
}

static void STAGE(stage_modulate_write)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(modulate_write)(ctx, t, b, 0, 0);
}

static void STAGE(stage_sample_write)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(modulate_write)(ctx, t, b, 1, 0);
}

#if SIMD_AVX512_INSTANCE || defined(GLES_NUM_FLOAT)
static void STAGE(stage_dot3_write)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(modulate_write)(ctx, t, b, 0, 1);
}

static void STAGE(stage_dot3_sample_write)(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    STAGE(modulate_write)(ctx, t, b, 1, 1);
}
#endif
#endif

static const ChainStages STAGE(chain_stages) = {
    .persp = STAGE(stage_persp),
    .persp_lod = STAGE(stage_persp_lod),
    .depth = STAGE(stage_depth),
    .tests_early = STAGE(stage_tests_early),
    .tests_late = STAGE(stage_tests_late),
    .zless_early = STAGE(stage_zless_early),
    .color = STAGE(stage_color),
    .fetch = { STAGE(stage_fetch0), STAGE(stage_fetch1), STAGE(stage_fetch2), STAGE(stage_fetch3) },
    .fetch_rect = { STAGE(stage_fetch_rect0), STAGE(stage_fetch_rect1), STAGE(stage_fetch_rect2),
                    STAGE(stage_fetch_rect3) },
    .fetch_direct = { STAGE(stage_fetch_direct0), STAGE(stage_fetch_direct1), STAGE(stage_fetch_direct2),
                      STAGE(stage_fetch_direct3) },
    .fetch_rect_direct = { STAGE(stage_fetch_rect_direct0), STAGE(stage_fetch_rect_direct1),
                           STAGE(stage_fetch_rect_direct2), STAGE(stage_fetch_rect_direct3) },
    .coords = { STAGE(stage_coords0), STAGE(stage_coords1), STAGE(stage_coords2), STAGE(stage_coords3) },
    .coords_tx = { STAGE(stage_coords_tx0), STAGE(stage_coords_tx1), STAGE(stage_coords_tx2), STAGE(stage_coords_tx3) },
    .coords_rect = { STAGE(stage_coords_rect0), STAGE(stage_coords_rect1), STAGE(stage_coords_rect2),
                     STAGE(stage_coords_rect3) },
    .env = { STAGE(stage_env0), STAGE(stage_env1), STAGE(stage_env2), STAGE(stage_env3) },
    .color_modulate = { STAGE(stage_color_modulate0), STAGE(stage_color_modulate1), STAGE(stage_color_modulate2),
                        STAGE(stage_color_modulate3) },
    .fog = STAGE(stage_fog),
    .fog_const = STAGE(stage_fog_const),
    .alpha = STAGE(stage_alpha),
    .write = STAGE(stage_write),
    .write_rgba8 = STAGE(stage_write_rgba8),
    .write_rgba8_alpha = STAGE(stage_write_rgba8_alpha),
    .write_rgba8_add = STAGE(stage_write_rgba8_add),
    .write_rgba8_logic = STAGE(stage_write_rgba8_logic),
    .write_rgba8_masked = STAGE(stage_write_rgba8_masked),
    .write_565 = STAGE(stage_write_565),
    .write_565_alpha = STAGE(stage_write_565_alpha),
#if CHAIN_SIMD && NUM_IS_FIXED
    .fog_write_rgba8 = STAGE(stage_fog_write_rgba8),
    .fog_write_565 = STAGE(stage_fog_write_565),
#endif
#if CHAIN_SIMD && (NUM_IS_FIXED || defined(GLES_NUM_DOUBLE))
    .sample_fog_write_rgba8 = STAGE(stage_sample_fog_write_rgba8),
    .sample_fog_write_565 = STAGE(stage_sample_fog_write_565),
#endif
#if CHAIN_SIMD && NUM_IS_FIXED
    .fused = { .modulate_write = STAGE(stage_modulate_write), .sample_write = STAGE(stage_sample_write),
               .dot3_write = STAGE(stage_dot3_write), .dot3_sample_write = STAGE(stage_dot3_sample_write),
               .modulate_write_565 = 1 },
#elif CHAIN_SIMD && defined(GLES_NUM_FLOAT)
    .fused = { .modulate_write = STAGE(stage_modulate_write), .sample_write = STAGE(stage_sample_write),
               .dot3_write = STAGE(stage_dot3_write), .dot3_sample_write = STAGE(stage_dot3_sample_write),
               .modulate_write_565 = 1, .dot3_exact = 1 },
#elif CHAIN_SIMD
    /* the double build's float lanes, proved */
    .fused = { .modulate_write = STAGE(stage_modulate_write_proved),
               .sample_write = STAGE(stage_sample_write_proved), .dot3_write = STAGE(stage_dot3_write_proved),
               .dot3_sample_write = STAGE(stage_dot3_sample_write_proved), .modulate_write_565 = 1 },
#endif
#if CHAIN_SIMD && SIMD_AVX512_INSTANCE
    .fused_avx512 = { .modulate_write = STAGE(stage_modulate_write), .sample_write = STAGE(stage_sample_write),
                      .dot3_write = STAGE(stage_dot3_write), .dot3_sample_write = STAGE(stage_dot3_sample_write),
                      .modulate_write_565 = 1, .dot3_exact = 1 },
#endif
#if CHAIN_SIMD && !NUM_IS_FIXED
    .color_dot3_modulate = STAGE(stage_color_dot3_modulate),
#endif
    .rect_source = STAGE(stage_rect_source),
};

