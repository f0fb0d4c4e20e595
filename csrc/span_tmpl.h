/*
** span_tmpl.h -- template for a span function, included by span.c.
** Parameters (each #undef'd at the end):
**   SPAN_NAME    MUST: the function's name
**   SPAN_SMOOTH  1: interpolate colour perspective-correctly; 0: flat colour
**   SPAN_DEPTH   1: depth test LESS with depth writes; 0: no depth test
** Preconditions for every instance (span_choose checks them): RGBA8888
** framebuffer, colour mask all on, scissor already applied by the caller.
** The generic path in span.c handles every other state, and a test renders
** random states through both and requires identical pixels.
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
    const NUM *c0 = t->col[0], *c1 = t->col[1], *c2 = t->col[2];
    (void)v0; (void)v1; (void)v2; (void)c0; (void)c1; (void)c2;
#endif
#if !SPAN_SMOOTH
    const uint32_t packed = t->flat_packed;
#endif
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
            uint32_t r = num_to_unorm(wgt_lerp3(c0[0], c1[0], c2[0], p[0], p[1], p[2]), 255);
            uint32_t g = num_to_unorm(wgt_lerp3(c0[1], c1[1], c2[1], p[0], p[1], p[2]), 255);
            uint32_t b = num_to_unorm(wgt_lerp3(c0[2], c1[2], c2[2], p[0], p[1], p[2]), 255);
            uint32_t a = num_to_unorm(wgt_lerp3(c0[3], c1[3], c2[3], p[0], p[1], p[2]), 255);
            dst[k] = r | (g << 8) | (b << 16) | (a << 24);
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
