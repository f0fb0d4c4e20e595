/*
** span_fused.h -- the fused span functions of the plain untextured states,
** a template that span.c instantiates once per instruction set (as
** span_chain.c does span_stages.h): SPAN_FN(name) gives the instance's
** names, CHAIN_SIMD is 1 in the AVX2 instance, where the blends and the
** write work on the four channels at once (V4, span_avx2.h).
**
** Every instance is span_fused with its parameters fixed (the compiler
** folds them): smooth (interpolate colour perspective-correctly, else the
** flat colour), depth (depth test LESS with depth writes) and blend (0 none,
** 1 SRC_ALPHA, ONE_MINUS_SRC_ALPHA, 2 ONE, ONE, both with FUNC_ADD).
** Preconditions (span_choose checks them): RGBA8888, colour mask all on, no
** alpha test, stencil, fog, logic op or polygon offset, scissor applied by
** the caller. The arithmetic is fragment_process's for these states, so
** the pixels are the same; the random-state tests check it.
*/

#if NUM_IS_FIXED
/* span_smooth_setup's stepped span over the row (see there); 0 where it
** does not apply (the general loop then draws the row) */
static inline __attribute__((always_inline)) int SPAN_FN(span_smooth_stepped)(GlesContext *ctx, const TriSetup *t,
                                                                              const int64_t e[3], uint32_t *dst,
                                                                              uint32_t *zb, int n, const int depth,
                                                                              const int blend)
{
    SmoothStep *const s = &ctx->smooth_step;
    if (ctx->smooth_serial != t->serial) {
        /* the vector instance's colour as v4_lerp_deltas takes it: the
        ** differences are vpmuldq's int32 operands */
#if CHAIN_SIMD
        const V4 a0 = v4_load(t->col[0]);
        const V4 d1 = _mm256_sub_epi64(v4_load(t->col[1]), a0), d2 = _mm256_sub_epi64(v4_load(t->col[2]), a0);
        const int colour_ok = v4_lerp_fits(a0) && v4_lerp_fits(d1) && v4_lerp_fits(d2);
        v4_store(s->base, v4_lerp_base(a0));
        v4_store(s->d1, d1);
        v4_store(s->d2, d2);
#else
        const int colour_ok = 1;    /* (frag_lerp3f takes any colour) */
#endif
        span_smooth_setup(t, s, colour_ok);
        ctx->smooth_serial = t->serial;
    }
    if (!s->ok)
        return 0;
    /* e_i is linear in the column: non-negative at both ends, at every pixel */
    for (int i = 0; i < 3; i++)
        if (e[i] < 0 || e[i] + t->ea[i] * (n - 1) < 0)
            return 0;
#if CHAIN_SIMD
    const V4 base = v4_load(s->base), d1 = v4_load(s->d1), d2 = v4_load(s->d2);
#else
    const FRAGV *c0 = t->col[0], *c1 = t->col[1], *c2 = t->col[2];
#endif
    const uint64_t half = (uint64_t)1 << 30;
    uint64_t lin1 = (uint64_t)e[1] * s->r + half, lin2 = (uint64_t)e[2] * s->r + half;
    uint64_t per0 = (uint64_t)e[0] * s->mant[0], per1 = (uint64_t)e[1] * s->mant[1];
    uint64_t per2 = (uint64_t)e[2] * s->mant[2];
    const uint64_t lin1_step = s->lin_step[1], lin2_step = s->lin_step[2];
    const uint64_t per0_step = s->per_step[0], per1_step = s->per_step[1], per2_step = s->per_step[2];
    const int qs0 = s->qs[0], qs1 = s->qs[1], qs2 = s->qs[2], affine = s->affine;
    const int64_t zbase = s->zbase, dz1 = s->dz1, dz2 = s->dz2, zmax = ctx->depth_max;
    for (int k = 0; k < n; k++) {
        const int64_t l1 = (int64_t)(lin1 >> 31), l2 = (int64_t)(lin2 >> 31);
        int draw = 1;
        if (depth) {
            int64_t z = (zbase + l1 * dz1 + l2 * dz2) >> 34;
            z = z < 0 ? 0 : (z > zmax ? zmax : z);
            draw = (uint32_t)z < zb[k];
            if (draw)
                zb[k] = (uint32_t)z;
        }
        if (draw) {
            WGT p[3] = { (WGT)(WGT_ONE - l1 - l2), (WGT)l1, (WGT)l2 };
            if (!affine) {
                const int64_t n0 = (int64_t)(per0 >> qs0), n1 = (int64_t)(per1 >> qs1);
                const int64_t n2 = (int64_t)(per2 >> qs2);
                if (n0 + n1 + n2 > 0)
                    wgt_persp_quotients(n0 + n1 + n2, n1, n2, p, NULL);
            }
#if CHAIN_SIMD
            const V4 c = v4_lerp_deltas(base, d1, d2, p[1], p[2]);
            dst[k] = blend ? v4_rgba8(c, dst[k], blend) : avx2_pack_unorm8(c);
#else
            FRAGV c[4];
            for (int i = 0; i < 4; i++)
                c[i] = frag_lerp3f(c0[i], c1[i], c2[i], p[0], p[1], p[2]);
            dst[k] = span_rgba8(ctx, c, dst[k], blend);
#endif
        }
        lin1 += lin1_step;
        lin2 += lin2_step;
        per0 += per0_step;
        per1 += per1_step;
        per2 += per2_step;
    }
    return 1;
}
#endif

static inline __attribute__((always_inline)) void SPAN_FN(span_fused)(GlesContext *ctx, const TriSetup *t, int y,
                                                                      int x0, int n, const int smooth,
                                                                      const int depth, const int blend)
{
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)y * (size_t)ctx->width + x0;
    uint32_t *zb = depth ? ctx->depth + (size_t)y * (size_t)ctx->width + x0 : NULL;
    const uint32_t zmax = ctx->depth_max;
    if (!smooth && !depth && !blend) {
        /* one word, 32 a step: four 32-byte stores to each turn of the
        ** loop, wherever the compiler places it (the compiler's loop of one
        ** store, where it crossed a 64-byte line, took flat_overdraw's
        ** float and double builds 30% longer than the fixed build's) */
        const uint32_t word = t->flat_packed;      /* (a store could alias t) */
        int k = 0;
        for (; k + 32 <= n; k += 32)
            for (int i = 0; i < 32; i++)
                dst[k + i] = word;
        for (; k < n; k++)
            dst[k] = word;
        return;
    }
    int64_t e[3];
    tri_edges_at(t, x0, y, e);
#if NUM_IS_FIXED
    if (smooth && SPAN_FN(span_smooth_stepped)(ctx, t, e, dst, zb, n, depth, blend))
        return;
#endif
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    const FRAGV *c0 = t->col[0], *c1 = t->col[1], *c2 = t->col[2];
    /* a constant source: its blend term is the same for the whole span */
    FRAGV sterm[4], sa = 0, da = 0;
    if (!smooth && blend) {
        sa = frag_clamp01(t->flat[3]);
        da = FRAG_ONE - sa;
        for (int i = 0; i < 4; i++)
            sterm[i] = blend == 1 ? frag_mul(frag_clamp01(t->flat[i]), sa) : frag_clamp01(t->flat[i]);
    }
    /* ... so each channel's result is a function of its destination byte
    ** alone: a table of them once the colour has blended enough fragments */
    const uint32_t (*const table)[256] = !smooth && blend ? span_flat_table(ctx, sterm, da, blend, n) : NULL;
    if (!smooth && !depth && table) {
        span_flat_run(table, dst, n);
        return;
    }
#if CHAIN_SIMD
    const V4 sterm_v = !smooth && blend ? v4_load(sterm) : v4_set1(0), da_v = v4_set1(da);
    const int vector_ok = v4_fits(sterm_v) && v4_fits(da_v);
    const V4 a0 = v4_load(c0), a1 = v4_load(c1), a2 = v4_load(c2);
    const int lerp_ok = v4_lerp_fits(a0) && v4_lerp_fits(a1) && v4_lerp_fits(a2);
#endif
    for (int k = 0; k < n; k++, e[0] += t->ea[0], e[1] += t->ea[1], e[2] += t->ea[2]) {
        if (depth) {
            WGT l[3];
            wgt_linear(&t->wgt, e, l);
            uint32_t z = wgt_depth3(v0->wz, v1->wz, v2->wz, l[0], l[1], l[2], zmax);
            if (!(z < zb[k]))
                continue;
            zb[k] = z;
        }
        if (!smooth && !blend) {
            dst[k] = t->flat_packed;
            continue;
        }
        if (!smooth && table) {
            dst[k] = span_flat_word(table, dst[k]);
            continue;
        }
        FRAGV c[4];
        WGT p[3];
        if (smooth) {
            wgt_persp(&t->wgt, e, p);
#if CHAIN_SIMD
            if (!lerp_ok)
#endif
                for (int i = 0; i < 4; i++)
                    c[i] = frag_lerp3f(c0[i], c1[i], c2[i], p[0], p[1], p[2]);
        }
        const uint32_t d = dst[k];
#if CHAIN_SIMD
        if (smooth) {
            dst[k] = v4_rgba8(lerp_ok ? v4_lerp3f_w(a0, a1, a2, p[0], p[1], p[2]) : v4_load(c), d, blend);
            continue;
        }
        if (vector_ok) {
            dst[k] = v4_pack_unorm8(v4_add(sterm_v, blend == 1 ? v4_mul01(v4_unorm8(d), da_v) : v4_unorm8(d)));
            continue;
        }
#endif
        if (smooth) {
            dst[k] = span_rgba8(ctx, c, d, blend);
            continue;
        }
        uint32_t out = 0;
        for (int i = 0; i < 4; i++) {
            FRAGV dv = ctx->unorm8[(d >> (8 * i)) & 0xFFu];
            FRAGV v = sterm[i] + (blend == 1 ? frag_mul(dv, da) : dv);
            out |= frag_to_unorm(v, 255, FRAG_ONE / 2) << (8 * i);
        }
        dst[k] = out;
    }
}

#define FUSED_INSTANCE(name, SMOOTH, DEPTH, BLEND)                                                 \
    static void SPAN_FN(span_##name)(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)   \
    {                                                                                              \
        SPAN_FN(span_fused)(ctx, t, y, x0, n, SMOOTH, DEPTH, BLEND);                                \
    }
FUSED_SPANS(FUSED_INSTANCE)
#undef FUSED_INSTANCE

/* [depth][blend][smooth] */
#define FUSED_ENTRY(name, SMOOTH, DEPTH, BLEND) [DEPTH][BLEND][SMOOTH] = SPAN_FN(span_##name),
static const SpanFunc SPAN_FN(fused_spans)[2][3][2] = { FUSED_SPANS(FUSED_ENTRY) };
#undef FUSED_ENTRY
