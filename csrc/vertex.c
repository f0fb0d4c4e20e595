/*
** vertex.c -- vertex transformation (ES 1.1 §2.10-2.11).
** Consumes: array elements (array.c) and the matrix stacks (matrix.c).
** Produces: Vertex records with clip coordinates, clip codes and window
**       coordinates (positions); colours and texture coordinates separately,
**       only for vertices of primitives that survive rejection and culling.
** Window x, y are integers in subpixels: round(vx*ONE + vw*ONE/2 *
** (1 + x/w)), the division done by num_proj so the fixed build never forms a
** 16.16 x/w (which would cost 4 bits at 4096-pixel viewports).
*/
#include <string.h>
#include "vertex.h"
#include "matrix.h"
#include "array.h"
#include "light.h"

void vertex_validate(GlesContext *ctx)
{
    if (ctx->dirty & DIRTY_MATRIX) {
        matrix_mul_num(ctx->mvp, ctx->projection.top->n, ctx->modelview.top->n);
        ctx->mvp_kind = matrix_kind(ctx->mvp);
    }
    if (ctx->dirty & (DIRTY_CLIP | DIRTY_MATRIX)) {
        unsigned int mask = CLIP_LEFT | CLIP_RIGHT | CLIP_BOTTOM | CLIP_TOP | CLIP_NEAR | CLIP_FAR | CLIP_W;
        ctx->need_eye = ctx->lighting;
        for (int i = 0; i < GLES_MAX_CLIP_PLANES; i++)
            if (ctx->clip_plane_enabled[i]) {
                mask |= CLIP_USER0 << i;
                ctx->need_eye = 1;
            }
        ctx->clip_mask = mask;
    }
    if (ctx->dirty & (DIRTY_LIGHT | DIRTY_MATRIX))
        light_validate(ctx);
}

NUM vertex_plane_distance(const GlesContext *ctx, const Vertex *v, unsigned int bit)
{
    const NUM *c = v->clip;
    switch (bit) {
    case CLIP_LEFT: return num_add(c[3], c[0]);
    case CLIP_RIGHT: return num_sub(c[3], c[0]);
    case CLIP_BOTTOM: return num_add(c[3], c[1]);
    case CLIP_TOP: return num_sub(c[3], c[1]);
    case CLIP_NEAR: return num_add(c[3], c[2]);
    case CLIP_FAR: return num_sub(c[3], c[2]);
    case CLIP_W: return num_sub(c[3], NUM_EPS);
    default: {
        int i = 0;
        while ((CLIP_USER0 << i) != bit)
            i++;
        return num_dot(ctx->clip_plane_n[i], 1, v->eye, 1, 4);
    }
    }
}

unsigned int vertex_clipcode(const GlesContext *ctx, const Vertex *v)
{
    unsigned int code = 0;
    for (unsigned int bit = 1; bit <= CLIP_W; bit <<= 1)
        if (vertex_plane_distance(ctx, v, bit) < 0)
            code |= bit;
    if (ctx->need_eye)
        for (int i = 0; i < GLES_MAX_CLIP_PLANES; i++)
            if (ctx->clip_plane_enabled[i] && vertex_plane_distance(ctx, v, CLIP_USER0 << i) < 0)
                code |= CLIP_USER0 << i;
    return code;
}

void vertex_window(const GlesContext *ctx, Vertex *v)
{
    const int64_t one = GLES_SUBPIXEL_ONE;
    const int *vp = ctx->viewport;
    NUM w = v->clip[3];
    v->wx = (int64_t)vp[0] * one + (int64_t)vp[2] * (one / 2) + num_proj(v->clip[0], w, (int64_t)vp[2] * (one / 2));
    v->wy = (int64_t)vp[1] * one + (int64_t)vp[3] * (one / 2) + num_proj(v->clip[1], w, (int64_t)vp[3] * (one / 2));
    v->rw = recipw_of(w);
    v->wz = depthv_from_clip(v->clip[2], w, num_from_double(ctx->depth_range[0]),
                             num_from_double(ctx->depth_range[1]), ctx->depth_max);
}

void vertex_position(GlesContext *ctx, int64_t index, Vertex *v)
{
    const ArrayState *a = &ctx->arrays[ARR_VERTEX];
    NUM obj[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ONE };
    array_fetch(a, array_base(a), index, 0, obj);
    if (ctx->need_eye) {
        matrix_xform4(ctx->modelview.top->n, ctx->modelview.top->kind, obj, v->eye);
        matrix_xform4(ctx->projection.top->n, ctx->projection.top->kind, v->eye, v->clip);
    } else {
        matrix_xform4(ctx->mvp, ctx->mvp_kind, obj, v->clip);
    }
    v->outcode = vertex_clipcode(ctx, v);
    if (v->outcode == 0)
        vertex_window(ctx, v);
}

void vertex_attribs(GlesContext *ctx, int64_t index, Vertex *v)
{
    const ArrayState *c = &ctx->arrays[ARR_COLOR];
    NUM color[4];
    if (c->enabled)
        array_fetch(c, array_base(c), index, 1, color);
    else
        memcpy(color, ctx->cur_color_n, sizeof color);
    if (ctx->lighting) {
        const ArrayState *na = &ctx->arrays[ARR_NORMAL];
        NUM normal[3];
        if (na->enabled)
            array_fetch(na, array_base(na), index, 1, normal);
        else
            memcpy(normal, ctx->cur_normal_n, sizeof normal);
        light_vertex(ctx, v->eye, normal, color, v->color, ctx->two_sided ? v->color_back : NULL);
    } else {
        /* §2.12.6: colours are clamped to [0,1] */
        for (int i = 0; i < 4; i++)
            v->color[i] = num_clamp01(color[i]);
    }
    const ArrayState *ps = &ctx->arrays[ARR_POINT_SIZE];
    if (ps->enabled) {
        array_fetch(ps, array_base(ps), index, 0, &v->point_size);
    } else {
        v->point_size = NUM_ONE;
    }
}
