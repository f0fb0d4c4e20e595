/*
** span.c -- the fragment stage for a run of pixels in one row.
** Consumes: a TriSetup and a covered run (y, x0 .. x0+n-1).
** Produces: framebuffer writes after the per-fragment operations built so
**       far: depth test (all eight functions) and depth mask, colour mask,
**       RGBA8888 or RGB565 colour.
** Specialised instances of span_tmpl.h cover the common states; span_generic
** covers every state and is the reference they must match bit for bit.
*/
#include "raster.h"

uint32_t span_pack_color(const GlesContext *ctx, const NUM *c)
{
    if (ctx->color_format == GLES_COLOR_RGB565)
        return (num_to_unorm(c[0], 31) << 11) | (num_to_unorm(c[1], 63) << 5) | num_to_unorm(c[2], 31);
    return num_to_unorm(c[0], 255) | (num_to_unorm(c[1], 255) << 8) | (num_to_unorm(c[2], 255) << 16)
         | (num_to_unorm(c[3], 255) << 24);
}

static int depth_pass(unsigned int func, uint32_t z, uint32_t stored)
{
    switch (func) {
    case GL_NEVER: return 0;
    case GL_LESS: return z < stored;
    case GL_EQUAL: return z == stored;
    case GL_LEQUAL: return z <= stored;
    case GL_GREATER: return z > stored;
    case GL_NOTEQUAL: return z != stored;
    case GL_GEQUAL: return z >= stored;
    default: return 1; /* GL_ALWAYS */
    }
}

/* Every state: the reference path. */
static void span_generic(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    const int depth = ctx->depth_test && ctx->depth;
    const int smooth = t->smooth;
    const size_t row = (size_t)y * (size_t)ctx->width;
    int64_t e[3];
    for (int i = 0; i < 3; i++)
        e[i] = t->ea[i] * x0 + t->eb[i] * y + t->ec[i];
    uint32_t keep = 0; /* framebuffer bits the colour mask protects */
    if (ctx->color_format == GLES_COLOR_RGB565) {
        static const uint32_t m565[3] = { 0xF800, 0x07E0, 0x001F };
        for (int i = 0; i < 3; i++)
            if (!ctx->color_mask[i])
                keep |= m565[i];
    } else {
        for (int i = 0; i < 4; i++)
            if (!ctx->color_mask[i])
                keep |= 0xFFu << (8 * i);
    }
    for (int k = 0; k < n; k++, e[0] += t->ea[0], e[1] += t->ea[1], e[2] += t->ea[2]) {
        size_t at = row + (size_t)(x0 + k);
        if (depth) {
            WGT l[3];
            wgt_linear(&t->wgt, e, l);
            uint32_t z = wgt_depth3(v0->wz, v1->wz, v2->wz, l[0], l[1], l[2], ctx->depth_max);
            if (!depth_pass(ctx->depth_func, z, ctx->depth[at]))
                continue;
            if (ctx->depth_mask)
                ctx->depth[at] = z;
        }
        uint32_t packed;
        if (smooth) {
            WGT p[3];
            NUM c[4];
            wgt_persp(&t->wgt, e, p);
            for (int i = 0; i < 4; i++)
                c[i] = wgt_lerp3(t->col[0][i], t->col[1][i], t->col[2][i], p[0], p[1], p[2]);
            packed = span_pack_color(ctx, c);
        } else {
            packed = t->flat_packed;
        }
        if (ctx->color_format == GLES_COLOR_RGB565) {
            uint16_t *dst = (uint16_t *)ctx->color + at;
            *dst = (uint16_t)((*dst & keep) | (packed & ~keep));
        } else {
            uint32_t *dst = (uint32_t *)ctx->color + at;
            *dst = (*dst & keep) | (packed & ~keep);
        }
    }
}

#define SPAN_NAME span_flat
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 0
#include "span_tmpl.h"

#define SPAN_NAME span_smooth
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 0
#include "span_tmpl.h"

#define SPAN_NAME span_flat_zless
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 1
#include "span_tmpl.h"

#define SPAN_NAME span_smooth_zless
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 1
#include "span_tmpl.h"

void span_choose(GlesContext *ctx)
{
    const int depth = ctx->depth_test && ctx->depth;
    const int smooth = ctx->shade_model == GL_SMOOTH;
    const int simple = ctx->color_format == GLES_COLOR_RGBA8888 && ctx->color_mask[0] && ctx->color_mask[1]
                    && ctx->color_mask[2] && ctx->color_mask[3] && !(ctx->debug & GLES_DEBUG_GENERIC_SPANS);
    const int zless = depth && ctx->depth_func == GL_LESS && ctx->depth_mask;
    if (simple && !depth) {
        ctx->span = smooth ? span_smooth : span_flat;
        ctx->span_const = span_flat;
        ctx->span_name = smooth ? "smooth" : "flat";
    } else if (simple && zless) {
        ctx->span = smooth ? span_smooth_zless : span_flat_zless;
        ctx->span_const = span_flat_zless;
        ctx->span_name = smooth ? "smooth_zless" : "flat_zless";
    } else {
        ctx->span = ctx->span_const = span_generic;
        ctx->span_name = "generic";
    }
}
