/*
** span_tmpl.h -- template for a span function, included by span.c.
** Parameters (each #undef'd at the end):
**   SPAN_NAME    MUST: the function's name
**   SPAN_SMOOTH  1: interpolate colour perspective-correctly; 0: flat colour
**   SPAN_DEPTH   1: depth test LESS with depth writes; 0: no depth test
**   SPAN_BLEND   0: no blending; 1: SRC_ALPHA, ONE_MINUS_SRC_ALPHA;
**                2: ONE, ONE (both with FUNC_ADD, the same for alpha)
** Preconditions for every instance (span_choose checks them): RGBA8888
** framebuffer, colour mask all on, no alpha test, stencil, fog or logic op,
** scissor already applied by the caller. The generic path in span.c
** handles every other state, and a test renders random states through both
** and requires identical pixels.
*/
static void SPAN_NAME(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)y * (size_t)ctx->width + x0;
#if SPAN_DEPTH
    uint32_t *zb = ctx->depth + (size_t)y * (size_t)ctx->width + x0;
    const uint32_t zmax = ctx->depth_max;
#endif
#if SPAN_SMOOTH || SPAN_DEPTH
    int64_t e[3];
    for (int i = 0; i < 3; i++)
        e[i] = t->ea[i] * x0 + t->eb[i] * y + t->ec[i];
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    const FRAGV *c0 = t->col[0], *c1 = t->col[1], *c2 = t->col[2];
    (void)v0; (void)v1; (void)v2; (void)c0; (void)c1; (void)c2;
#endif
#if !SPAN_SMOOTH && !SPAN_BLEND
    const uint32_t packed = t->flat_packed;
#endif
#if !SPAN_SMOOTH && SPAN_BLEND
    /* a constant source: its blend term is the same for the whole span */
    FRAGV sterm[4];
#if SPAN_BLEND == 1
    const FRAGV sa = frag_clamp01(t->flat[3]), da = FRAG_ONE - sa;
    for (int i = 0; i < 4; i++)
        sterm[i] = frag_mul(frag_clamp01(t->flat[i]), sa);
#else
    for (int i = 0; i < 4; i++)
        sterm[i] = frag_clamp01(t->flat[i]);
#endif
#endif
    (void)ctx;
    for (int k = 0; k < n; k++) {
#if SPAN_DEPTH
        WGT l[3];
        wgt_linear(&t->wgt, e, l);
        uint32_t z = wgt_depth3(v0->wz, v1->wz, v2->wz, l[0], l[1], l[2], zmax);
        if (z < zb[k]) {
            zb[k] = z;
#else
        {
#endif
#if SPAN_SMOOTH
            WGT p[3];
            wgt_persp(&t->wgt, e, p);
            FRAGV c[4];
            for (int i = 0; i < 4; i++)
                c[i] = frag_lerp3f(c0[i], c1[i], c2[i], p[0], p[1], p[2]);
#endif
#if SPAN_BLEND
            uint32_t d = dst[k], out = 0;
#if SPAN_SMOOTH
            FRAGV sterm[4];
#if SPAN_BLEND == 1
            FRAGV sa = frag_clamp01(c[3]), da = FRAG_ONE - sa;
            for (int i = 0; i < 4; i++)
                sterm[i] = frag_mul(frag_clamp01(c[i]), sa);
#else
            for (int i = 0; i < 4; i++)
                sterm[i] = frag_clamp01(c[i]);
#endif
#endif
            for (int i = 0; i < 4; i++) {
                FRAGV dv = ctx->unorm8[(d >> (8 * i)) & 0xFFu];
#if SPAN_BLEND == 1
                FRAGV v = sterm[i] + frag_mul(dv, da);
#else
                FRAGV v = sterm[i] + dv;
#endif
                out |= frag_to_unorm(v, 255, FRAG_ONE / 2) << (8 * i);
            }
            dst[k] = out;
#elif SPAN_SMOOTH
            dst[k] = frag_to_unorm(c[0], 255, FRAG_ONE / 2) | (frag_to_unorm(c[1], 255, FRAG_ONE / 2) << 8)
                   | (frag_to_unorm(c[2], 255, FRAG_ONE / 2) << 16) | (frag_to_unorm(c[3], 255, FRAG_ONE / 2) << 24);
#else
            dst[k] = packed;
#endif
        }
#if SPAN_SMOOTH || SPAN_DEPTH
        for (int i = 0; i < 3; i++)
            e[i] += t->ea[i];
#endif
    }
}

#undef SPAN_NAME
#undef SPAN_SMOOTH
#undef SPAN_DEPTH
#undef SPAN_BLEND
