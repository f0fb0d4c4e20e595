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
#include "fragment.h"
#include "texture.h"
#include "texgen.h"

void vertex_validate(GlesContext *ctx)
{
    if (ctx->dirty & DIRTY_MATRIX)
        ctx->mvp_stale = 1;
    if (ctx->dirty & (DIRTY_CLIP | DIRTY_MATRIX)) {
        unsigned int mask = CLIP_LEFT | CLIP_RIGHT | CLIP_BOTTOM | CLIP_TOP | CLIP_NEAR | CLIP_FAR | CLIP_W;
        const NUM *pa = ctx->n_point_attenuation;
        int point_distance = pa[0] != NUM_ONE || pa[1] != NUM_ZERO || pa[2] != NUM_ZERO;
        ctx->need_eye = ctx->lighting || ctx->matrix_palette || ctx->fog || point_distance || texgen_needs_eye(ctx);
        for (int i = 0; i < GLES_MAX_CLIP_PLANES; i++)
            if (ctx->clip_plane_enabled[i]) {
                mask |= CLIP_USER0 << i;
                ctx->need_eye = 1;
            }
        ctx->clip_mask = mask;
    }
    /* P*MV only when vertices use it: with eye coordinates they go through
    ** MV and then P, each rounded (a scene of many small lit draws changes
    ** MV for every draw and never needs the product) */
    if (ctx->mvp_stale && !ctx->need_eye) {
        matrix_mul_num(ctx->mvp, ctx->projection.top->n, ctx->modelview.top->n);
        ctx->mvp_kind = matrix_kind(ctx->mvp);
        ctx->mvp_stale = 0;
    }
    if (ctx->dirty & (DIRTY_LIGHT | DIRTY_MATRIX))
        light_validate(ctx);
    if (ctx->dirty & DIRTY_SPAN)
        fog_validate(ctx);
    if (ctx->dirty & (DIRTY_TEXTURE | DIRTY_SPAN))
        texture_validate(ctx);
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

/* OES_matrix_palette: the vertex's matrix indices and weights (n units) */
static int palette_units(const GlesContext *ctx, int64_t index, int idx[GLES_MAX_VERTEX_UNITS],
                         NUM w[GLES_MAX_VERTEX_UNITS])
{
    const ArrayState *ia = &ctx->arrays[ARR_MATRIX_INDEX], *wa = &ctx->arrays[ARR_WEIGHT];
    NUM iv[4] = { 0, 0, 0, 0 }, wv[4] = { 0, 0, 0, 0 };
    array_fetch(ia, array_base(ia), index, 0, iv);
    array_fetch(wa, array_base(wa), index, 0, wv);
    int n = ia->size;
    for (int i = 0; i < n; i++) {
        /* indices were range-checked before the draw (draw.c) */
        idx[i] = (int)num_to_double(iv[i]);
        w[i] = i < wa->size ? wv[i] : NUM_ZERO;
    }
    return n;
}

/* eye = sum_i w_i * (M[idx_i] * obj) */
void vertex_palette_eye(const GlesContext *ctx, int64_t index, const NUM obj[4], NUM eye[4])
{
    int idx[GLES_MAX_VERTEX_UNITS];
    NUM w[GLES_MAX_VERTEX_UNITS];
    int n = palette_units(ctx, index, idx, w);
    NUM acc[4] = { 0, 0, 0, 0 };
    for (int i = 0; i < n; i++) {
        const Matrix *m = &ctx->palette[idx[i]];
        NUM e[4];
        matrix_xform4(m->n, m->kind, obj, e);
        for (int k = 0; k < 4; k++)
            acc[k] = num_add(acc[k], num_mul(w[i], e[k]));
    }
    memcpy(eye, acc, sizeof acc);
}

/* eye-space normal with the palette: sum_i w_i * n Inv(Mu_i) (the
** extension's second, per-matrix form) */
void vertex_palette_normal(const GlesContext *ctx, int64_t index, const NUM n[3], NUM out[3])
{
    int idx[GLES_MAX_VERTEX_UNITS];
    NUM w[GLES_MAX_VERTEX_UNITS];
    int cnt = palette_units(ctx, index, idx, w);
    NUM acc[3] = { 0, 0, 0 };
    for (int i = 0; i < cnt; i++) {
        const NUM *nm = ctx->palette_normal[idx[i]];
        for (int r = 0; r < 3; r++) {
            NUM e = num_dot(nm + r * 3, 1, n, 1, 3);
            if (ctx->rescale_normal)
                e = num_mul(e, ctx->palette_rescale[idx[i]]);
            acc[r] = num_add(acc[r], num_mul(w[i], e));
        }
    }
    memcpy(out, acc, sizeof acc);
}

/* the eye-space normal of array element `index` that lighting and texture
** coordinate generation read (§2.11.3): the object normal (its array or
** the current one) by the normal matrix, or the palette's; RESCALE_NORMAL;
** NORMALIZE */
void vertex_eye_normal(const GlesContext *ctx, int64_t index, NUM n[3])
{
    const ArrayState *na = &ctx->arrays[ARR_NORMAL];
    NUM normal[3];
    if (na->enabled)
        array_fetch(na, array_base(na), index, 1, normal);
    else
        memcpy(normal, ctx->cur_normal_n, sizeof normal);
    if (ctx->matrix_palette) {
        vertex_palette_normal(ctx, index, normal, n);
    } else {
        for (int r = 0; r < 3; r++)
            n[r] = num_dot(ctx->normal_matrix + r * 3, 1, normal, 1, 3);
        if (ctx->rescale_normal)
            for (int r = 0; r < 3; r++)
                n[r] = num_mul(n[r], ctx->rescale);
    }
    if (ctx->normalize)
        num_normalize3(n);
}

void vertex_position(GlesContext *ctx, int64_t index, Vertex *v)
{
    const ArrayState *a = &ctx->arrays[ARR_VERTEX];
    NUM obj[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ONE };
    array_fetch(a, array_base(a), index, 0, obj);
    if (ctx->matrix_palette) {
        vertex_palette_eye(ctx, index, obj, v->eye);
        matrix_xform4(ctx->projection.top->n, ctx->projection.top->kind, v->eye, v->clip);
    } else if (ctx->need_eye) {
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
    FRAGV exact[4];     /* the colour at fragment precision, when it is known exactly */
    if (c->enabled) {
        array_fetch(c, array_base(c), index, 1, color);
        if (c->type == GL_UNSIGNED_BYTE) {
            /* c / 255 to 2^-31, not to 16.16: 8-bit colours blend exactly */
            uint8_t ub[4];
            memcpy(ub, array_base(c) + index * c->step, 4);
            for (int i = 0; i < 4; i++)
                exact[i] = ctx->texel_unorm8[ub[i]];
        } else {
            for (int i = 0; i < 4; i++)
                exact[i] = frag_from_num(color[i]);
        }
    } else {
        memcpy(color, ctx->cur_color_n, sizeof color);
        for (int i = 0; i < 4; i++)
            exact[i] = frag_from_double(ctx->cur_color[i]);
    }
    NUM nf[3];      /* the eye-space normal lighting and texture coordinate generation read */
    if (ctx->lighting || ctx->texgen_units)
        vertex_eye_normal(ctx, index, nf);
    if (ctx->lighting) {
        NUM front[4], back[4];
        NUM *pb = ctx->two_sided ? back : NULL;
        light_vertex(ctx, v->eye, nf, color, front, pb);
        for (int i = 0; i < 4; i++) {
            v->color[i] = frag_from_num(front[i]);
            if (pb)
                v->color_back[i] = frag_from_num(back[i]);
        }
    } else {
        /* §2.12.6: colours are clamped to [0,1] */
        for (int i = 0; i < 4; i++)
            v->color[i] = frag_clamp01(exact[i]);
    }
    if (ctx->fog)
        v->fog = fog_vertex_value(ctx, v->eye);
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
        if (!(ctx->tex_units_on & (1u << u)))
            continue;
        const ArrayState *ta = &ctx->arrays[ARR_TEXCOORD0 + u];
        NUM tc[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ONE };
        if (ta->enabled)
            array_fetch(ta, array_base(ta), index, 0, tc);
        else
            memcpy(tc, ctx->cur_tex_n[u], sizeof tc);
        if (ctx->texgen_units & (1u << u))
            texgen_coords(ctx->units[u].texgen_mode, v->eye, nf, tc);
        const Matrix *tm = ctx->texture[u].top;
        matrix_xform4(tm->n, tm->kind, tc, v->tex[u]);
    }
    const ArrayState *ps = &ctx->arrays[ARR_POINT_SIZE];
    if (ps->enabled) {
        array_fetch(ps, array_base(ps), index, 0, &v->point_size);
    } else {
        v->point_size = NUM_ONE;
    }
}
