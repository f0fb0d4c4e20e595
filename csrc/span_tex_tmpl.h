/*
** span_tex_tmpl.h -- template for a textured span function, included by
** span.c after span_tex_coord().
** Parameters (each #undef'd at the end):
**   SPAN_NAME    MUST: the function's name
**   SPAN_DEPTH   1: depth test LESS with depth writes; 0: no depth test
**   SPAN_BLEND   0: none; 1: SRC_ALPHA, ONE_MINUS_SRC_ALPHA
** Preconditions (span_choose checks them): RGBA8888, colour mask all on, no
** alpha test, stencil, fog or logic op, exactly one texture unit on (the
** first), its environment REPLACE or MODULATE. The arithmetic is the
** generic path's own (texture_sample, texture_env), so the pixels are
** identical; what goes is the per-pixel state tests, and the depth test
** moves before texturing (nothing here can discard a fragment after it).
*/
static void SPAN_NAME(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)y * (size_t)ctx->width + x0;
#if SPAN_DEPTH
    uint32_t *zb = ctx->depth + (size_t)y * (size_t)ctx->width + x0;
    const uint32_t zmax = ctx->depth_max;
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
#endif
    const Texture *tex = ctx->units[0].bound;
    const int lod = texture_needs_lod(tex);
    const int modulate_rgba = ctx->units[0].env_mode == GL_MODULATE && tex->format == GL_RGBA;
    const int smooth = t->smooth;
    int64_t e[3];
    for (int i = 0; i < 3; i++)
        e[i] = t->ea[i] * x0 + t->eb[i] * y + t->ec[i];
    for (int k = 0; k < n; k++, e[0] += t->ea[0], e[1] += t->ea[1], e[2] += t->ea[2]) {
#if SPAN_DEPTH
        WGT l[3];
        wgt_linear(&t->wgt, e, l);
        uint32_t z = wgt_depth3(v0->wz, v1->wz, v2->wz, l[0], l[1], l[2], zmax);
        if (!(z < zb[k]))
            continue;
        zb[k] = z;
#endif
        WGT p[3];
        wgt_persp(&t->wgt, e, p);
        FRAGV c[4], cf[4], ct[GLES_MAX_TEXTURE_UNITS][4];
        for (int i = 0; i < 4; i++) {
            c[i] = smooth ? frag_lerp3f(t->col[0][i], t->col[1][i], t->col[2][i], p[0], p[1], p[2]) : t->flat[i];
            cf[i] = c[i] = frag_clamp01(c[i]);
        }
        TexCoord tc;
        span_tex_coord(t, 0, p, &tc);
        if (lod) {
            int64_t ex[3] = { e[0] + t->ea[0], e[1] + t->ea[1], e[2] + t->ea[2] };
            int64_t ey[3] = { e[0] + t->eb[0], e[1] + t->eb[1], e[2] + t->eb[2] };
            WGT px[3], py[3];
            TexCoord tx, ty;
            wgt_persp_any(&t->wgt, ex, px);
            wgt_persp_any(&t->wgt, ey, py);
            span_tex_coord(t, 0, px, &tx);
            span_tex_coord(t, 0, py, &ty);
            texture_sample(tex, &tc, &tx, &ty, ct[0], ctx->texel_unorm8);
        } else {
            texture_sample(tex, &tc, NULL, NULL, ct[0], ctx->texel_unorm8);
        }
        if (modulate_rgba) {
            /* texture_env's MODULATE of an RGBA texture, inline */
            for (int i = 0; i < 4; i++)
                c[i] = frag_mul(c[i], ct[0][i]);
        } else {
            texture_env(ctx, 0, cf, ct, c);
        }
#if SPAN_BLEND
        uint32_t d = dst[k], out = 0;
        FRAGV sa = frag_clamp01(c[3]), da = FRAG_ONE - sa;
        for (int i = 0; i < 4; i++) {
            FRAGV v = frag_mul(frag_clamp01(c[i]), sa) + frag_mul(ctx->unorm8[(d >> (8 * i)) & 0xFFu], da);
            out |= frag_to_unorm(v, 255, FRAG_ONE / 2) << (8 * i);
        }
        dst[k] = out;
#else
        dst[k] = frag_to_unorm(c[0], 255, FRAG_ONE / 2) | (frag_to_unorm(c[1], 255, FRAG_ONE / 2) << 8)
               | (frag_to_unorm(c[2], 255, FRAG_ONE / 2) << 16) | (frag_to_unorm(c[3], 255, FRAG_ONE / 2) << 24);
#endif
    }
}

#undef SPAN_NAME
#undef SPAN_DEPTH
#undef SPAN_BLEND
