/*
** vertex_batch.c -- vertex transformation and attributes for up to
** VERTEX_BATCH vertices at a time (ES 1.1 §2.10-2.12).
** Consumes: array elements (array.c), the derived matrices of
**       vertex_validate, lighting (light_batch in light.c).
** Produces: the same Vertex records as vertex_position and vertex_attribs
**       (vertex.c), bit for bit: every value goes through the same NUM
**       operations in the same order. Only the loops differ: one lane per
**       vertex in structure-of-arrays rows, each matrix row and each light
**       set up once per batch, lanes padded with defined values to whole
**       groups of NUM_LANES so the inner loops have a constant count.
** The per-vertex functions stay as the reference path
** (GLES_DEBUG_VERTEX_REFERENCE); a test renders random scenes both ways.
*/
#include <string.h>
#include "vertex_batch.h"
#include "vertex.h"
#include "matrix.h"
#include "array.h"
#include "light.h"
#include "fragment.h"
#include "vertex_avx2.h"
#include "range.h"
#include "texgen.h"

typedef NUM VbRows[4][VERTEX_BATCH];

/* lanes a batch of n vertices runs: n rounded up to whole groups */
static int vb_lanes(int n)
{
    return (n + NUM_LANES - 1) / NUM_LANES * NUM_LANES;
}

/* FLOAT elements of `size` components (a constant at each call, so each
** instance is unrolled): num_from_double of each, as array_fetch does
** (num_from_float is that conversion without the call to floor) */
static inline void fetch_float(const uint8_t *base, int step, const int64_t *index, int n, NUM out[][VERTEX_BATCH],
                               const int size)
{
    for (int i = 0; i < n; i++) {
        float f[4];
        memcpy(f, base + index[i] * step, (size_t)size * sizeof f[0]);
        for (int c = 0; c < size; c++)
            out[c][i] = num_from_float(f[c]);
    }
}

/* rows 0..size-1 of lanes 0..n-1 from array `a`, converted as array_fetch
** converts them; other rows and lanes keep what the caller put there */
static void fetch_lanes(const ArrayState *a, const int64_t *index, int n, int normalized, NUM out[][VERTEX_BATCH],
                        int simd)
{
    const uint8_t *base = array_base(a);
#if VERTEX_AVX2
    if (simd && a->type == GL_FLOAT && a->size >= 1 && a->size <= 4) {
        vx_fetch_float_avx2(base, a->step, index, n, out, a->size);
        return;
    }
#endif
    (void)simd;
    if (a->type == GL_FLOAT) {
        switch (a->size) {
        case 1: fetch_float(base, a->step, index, n, out, 1); return;
        case 2: fetch_float(base, a->step, index, n, out, 2); return;
        case 3: fetch_float(base, a->step, index, n, out, 3); return;
        case 4: fetch_float(base, a->step, index, n, out, 4); return;
        default: break;
        }
    }
    for (int i = 0; i < n; i++) {
        NUM t[4];
        array_fetch(a, base, index[i], normalized, t);
        for (int c = 0; c < a->size; c++)
            out[c][i] = t[c];
    }
}

/* every lane of rows[0..3] set to (x, y, z, w) */
static void fill_rows(NUM rows[][VERTEX_BATCH], int count, const NUM *value, int cnt)
{
    for (int c = 0; c < count; c++)
        NUM_FOR_LANES(i, cnt)
            rows[c][i] = value[c];
}

/* out = m in for every lane, as matrix_xform4 computes it (identity copies,
** affine keeps w); out is not in. `w_one`: every lane of in[3] is NUM_ONE.
** Returns whether every lane of out[3] is NUM_ONE. */
static int xform_lanes(const NUM *m, int kind, VbRows in, VbRows out, int cnt, int w_one, int simd)
{
    if (kind == MAT_IDENTITY) {
        for (int r = 0; r < 4; r++)
            memcpy(out[r], in[r], (size_t)cnt * sizeof(NUM));
        return w_one;
    }
    for (int r = 0; r < 3; r++)
        vx_dot4_lanes(simd, m[r], m[4 + r], m[8 + r], m[12 + r], in[0], in[1], in[2], in[3], out[r], cnt, w_one);
    if (kind == MAT_AFFINE) {
        memcpy(out[3], in[3], (size_t)cnt * sizeof(NUM));
        return w_one;
    }
    vx_dot4_lanes(simd, m[3], m[7], m[11], m[15], in[0], in[1], in[2], in[3], out[3], cnt, w_one);
    return 0;
}

/* vertex_clipcode for every lane: a plane is violated when its distance is
** below 0. Forced inline: clip_codes_avx2 is this loop compiled for AVX2
** (the same C operations, vectorized with 64-bit compares) */
static inline __attribute__((always_inline)) void clip_codes(VbRows clip, unsigned int *code, int cnt)
{
    NUM_FOR_LANES(i, cnt) {
        NUM x = clip[0][i], y = clip[1][i], z = clip[2][i], w = clip[3][i];
        unsigned int c = 0;
        c |= num_add(w, x) < NUM_ZERO ? CLIP_LEFT : 0u;
        c |= num_sub(w, x) < NUM_ZERO ? CLIP_RIGHT : 0u;
        c |= num_add(w, y) < NUM_ZERO ? CLIP_BOTTOM : 0u;
        c |= num_sub(w, y) < NUM_ZERO ? CLIP_TOP : 0u;
        c |= num_add(w, z) < NUM_ZERO ? CLIP_NEAR : 0u;
        c |= num_sub(w, z) < NUM_ZERO ? CLIP_FAR : 0u;
        c |= num_sub(w, NUM_EPS) < NUM_ZERO ? CLIP_W : 0u;
        code[i] = c;
    }
}

#if VERTEX_AVX2
#pragma GCC push_options
SIMD_TARGET_AVX2
static void clip_codes_avx2(VbRows clip, unsigned int *code, int cnt)
{
    clip_codes(clip, code, cnt);
}
#pragma GCC pop_options
#endif

/* lane i's clip coordinates, eye coordinates (when eye is given) and
** clip code into its vertex: every window path stores these alike */
static inline void vb_store_clip(Vertex *v, VbRows clip, VbRows eye, const unsigned int *code, int i)
{
    for (int k = 0; k < 4; k++)
        v->clip[k] = clip[k][i];
    if (eye)
        for (int k = 0; k < 4; k++)
            v->eye[k] = eye[k][i];
    v->outcode = code[i];
}

void vertex_batch_positions(GlesContext *ctx, const int64_t *index, int n, Vertex *verts, int64_t base)
{
    static const NUM obj_default[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ONE };
    static const NUM zero[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ZERO };
    VbRows obj, eye, clip;
    unsigned int code[VERTEX_BATCH];
    const int cnt = vb_lanes(n);
    const int simd = ctx_simd(ctx) >= SIMD_AVX2;
    fill_rows(obj, 4, obj_default, cnt);
    fetch_lanes(&ctx->arrays[ARR_VERTEX], index, n, 0, obj, simd);
    const Matrix *proj = ctx->projection.top, *mv = ctx->modelview.top;
    const int has_eye = ctx->matrix_palette || ctx->need_eye;
    const ArrayState *va = &ctx->arrays[ARR_VERTEX];
    const int w_one = va->size < 4;     /* obj w is the default 1 in every lane */
    if (ctx->matrix_palette) {
        fill_rows(eye, 4, zero, cnt);
        for (int i = 0; i < n; i++) {
            NUM o[4] = { obj[0][i], obj[1][i], obj[2][i], obj[3][i] }, e[4];
            vertex_palette_eye(ctx, index[i], o, e);
            for (int k = 0; k < 4; k++)
                eye[k][i] = e[k];
        }
        xform_lanes(proj->n, proj->kind, eye, clip, cnt, 0, simd);
    } else if (ctx->need_eye) {
        int eye_w_one = xform_lanes(mv->n, mv->kind, obj, eye, cnt, w_one, simd);
        xform_lanes(proj->n, proj->kind, eye, clip, cnt, eye_w_one, simd);
    } else {
        xform_lanes(ctx->mvp, ctx->mvp_kind, obj, clip, cnt, w_one, simd);
    }
#if VERTEX_AVX2
    if (simd)
        clip_codes_avx2(clip, code, cnt);
    else
#endif
        clip_codes(clip, code, cnt);
    if (ctx->need_eye)
        for (int p = 0; p < GLES_MAX_CLIP_PLANES; p++) {
            if (!ctx->clip_plane_enabled[p])
                continue;
            const NUM *pl = ctx->clip_plane_n[p];
            NUM dist[VERTEX_BATCH];
            vx_dot4_lanes(simd, pl[0], pl[1], pl[2], pl[3], eye[0], eye[1], eye[2], eye[3], dist, cnt, 0);
            NUM_FOR_LANES(i, cnt)
                code[i] |= dist[i] < NUM_ZERO ? CLIP_USER0 << p : 0u;
        }
    /* vertex_window for the vertices inside every plane */
    const int64_t one = GLES_SUBPIXEL_ONE;
    const int *vp = ctx->viewport;
    const int64_t hx = (int64_t)vp[2] * (one / 2), hy = (int64_t)vp[3] * (one / 2);
    const int64_t ox = (int64_t)vp[0] * one + hx, oy = (int64_t)vp[1] * one + hy;
    const NUM dn = num_from_double(ctx->depth_range[0]), df = num_from_double(ctx->depth_range[1]);
#if VERTEX_AVX2
    /* the kernel's exact range: half sizes below 2^21 (a viewport of at
    ** most MAX_VIEWPORT_DIMS has 2^19) */
    if (simd && hx < ((int64_t)1 << 21) && hy < ((int64_t)1 << 21)) {
        int64_t wx[VERTEX_BATCH], wy[VERTEX_BATCH], mant[VERTEX_BATCH], rexp[VERTEX_BATCH], wz[VERTEX_BATCH];
        const VxWindow W = { ox, oy, hx, hy, (int64_t)dn * 16384, ((int64_t)df - dn) * 16384, ctx->depth_max };
        vx_window_avx2(&W, clip[0], clip[1], clip[2], clip[3], cnt, wx, wy, mant, rexp, wz);
        for (int i = 0; i < n; i++) {
            Vertex *v = &verts[index[i] - base];
            vb_store_clip(v, clip, has_eye ? eye : NULL, code, i);
            if (code[i] == 0) {
                v->wx = wx[i];
                v->wy = wy[i];
                v->rw.mant = mant[i];
                v->rw.exp = (int)rexp[i];
                v->wz = wz[i];
            }
        }
        return;
    }
#endif
#if VERTEX_AVX2_FP
    if (simd) {
        int64_t wx[VERTEX_BATCH], wy[VERTEX_BATCH];
        NUM rw[VERTEX_BATCH], wz[VERTEX_BATCH];
        vx_window_fp_avx2(clip[0], clip[1], clip[2], clip[3], cnt, ox, oy, hx, hy, dn, df, ctx->depth_max, wx, wy,
                          rw, wz);
        for (int i = 0; i < n; i++) {
            Vertex *v = &verts[index[i] - base];
            vb_store_clip(v, clip, has_eye ? eye : NULL, code, i);
            if (code[i] == 0) {
                v->wx = wx[i];
                v->wy = wy[i];
                v->rw = rw[i];
                v->wz = wz[i];
            }
        }
        return;
    }
#endif
    for (int i = 0; i < n; i++) {
        Vertex *v = &verts[index[i] - base];
        vb_store_clip(v, clip, has_eye ? eye : NULL, code, i);
        if (code[i] == 0) {
            NUM w = clip[3][i];
            v->wx = ox + num_proj(clip[0][i], w, hx);
            v->wy = oy + num_proj(clip[1][i], w, hy);
            v->rw = recipw_of(w);
            v->wz = depthv_from_clip(clip[2][i], w, dn, df, ctx->depth_max);
        }
    }
}

/* the lit colours of the batch: normals to eye space, rescaled and
** normalised as vertex_eye_normal does, then light_batch */
static void light_lanes(GlesContext *ctx, const int64_t *index, Vertex *const *out, int n, LightBatch *lb)
{
    static const NUM zero[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ZERO };
    const int cnt = vb_lanes(n);
    const int simd = ctx_simd(ctx) >= SIMD_AVX2;
    const ArrayState *na = &ctx->arrays[ARR_NORMAL];
    NUM obn[3][VERTEX_BATCH];
    if (na->enabled) {
        fill_rows(obn, 3, zero, cnt);
        fetch_lanes(na, index, n, 1, obn, simd);
    } else {
        fill_rows(obn, 3, ctx->cur_normal_n, cnt);
    }
    lb->n = n;
    if (ctx->matrix_palette) {
        fill_rows(lb->nrm, 3, zero, cnt);
        for (int i = 0; i < n; i++) {
            NUM o[3] = { obn[0][i], obn[1][i], obn[2][i] }, e[3];
            vertex_palette_normal(ctx, index[i], o, e);
            for (int k = 0; k < 3; k++)
                lb->nrm[k][i] = e[k];
        }
    } else {
        const NUM *nm = ctx->normal_matrix;
        for (int r = 0; r < 3; r++)
            vx_dot3_lanes(simd, nm[r * 3], nm[r * 3 + 1], nm[r * 3 + 2], obn[0], obn[1], obn[2], lb->nrm[r], cnt);
        if (ctx->rescale_normal)
            for (int r = 0; r < 3; r++)
                NUM_FOR_LANES(i, cnt)
                    lb->nrm[r][i] = num_mul(lb->nrm[r][i], ctx->rescale);
    }
    if (ctx->normalize)
        vx_normalize3_lanes(simd, lb->nrm[0], lb->nrm[1], lb->nrm[2], n, cnt);
    fill_rows(lb->v, 3, zero, cnt);
    for (int i = 0; i < n; i++) {
        const NUM *eye = out[i]->eye;
        if (eye[3] == NUM_ONE || eye[3] == NUM_ZERO) {
            for (int k = 0; k < 3; k++)
                lb->v[k][i] = eye[k];
        } else {
            for (int k = 0; k < 3; k++)
                lb->v[k][i] = num_div(eye[k], eye[3]);
        }
    }
    light_batch(ctx, lb, ctx->two_sided);
    for (int i = 0; i < n; i++) {
        Vertex *v = out[i];
        for (int k = 0; k < 4; k++)
            v->color[k] = frag_from_num(lb->out[0][k][i]);
        if (ctx->two_sided)
            for (int k = 0; k < 4; k++)
                v->color_back[k] = frag_from_num(lb->out[1][k][i]);
    }
}

void vertex_batch_attribs(GlesContext *ctx, const int64_t *index, Vertex *const *out, int n)
{
    static const NUM zero[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ZERO };
    const ArrayState *c = &ctx->arrays[ARR_COLOR];
    const int lit = ctx->lighting;
    LightBatch lb;
    if (lit)
        fill_rows(lb.col, 4, zero, vb_lanes(n));
    /* the vertex colour: what lighting reads (COLOR_MATERIAL), or, unlit,
    ** the colour itself at fragment precision, exactly when it is known
    ** exactly (8-bit colours) */
    for (int i = 0; i < n; i++) {
        NUM color[4];
        if (c->enabled) {
            if (lit || c->type != GL_UNSIGNED_BYTE)
                array_fetch(c, array_base(c), index[i], 1, color);
            if (lit) {
                for (int k = 0; k < 4; k++)
                    lb.col[k][i] = color[k];
            } else if (c->type == GL_UNSIGNED_BYTE) {
                uint8_t ub[4];
                memcpy(ub, array_base(c) + index[i] * c->step, 4);
                for (int k = 0; k < 4; k++)
                    out[i]->color[k] = frag_clamp01(ctx->texel_unorm8[ub[k]]);
            } else {
                for (int k = 0; k < 4; k++)
                    out[i]->color[k] = frag_clamp01(frag_from_num(color[k]));
            }
        } else if (lit) {
            for (int k = 0; k < 4; k++)
                lb.col[k][i] = ctx->cur_color_n[k];
        } else {
            for (int k = 0; k < 4; k++)
                out[i]->color[k] = frag_clamp01(frag_from_double(ctx->cur_color[k]));
        }
    }
    if (lit)
        light_lanes(ctx, index, out, n, &lb);
    if (ctx->fog)
        for (int i = 0; i < n; i++)
            out[i]->fog = fog_vertex_value(ctx, out[i]->eye);
    /* the eye-space normals texture coordinate generation reads (vertex.c's
    ** per-vertex functions: the same bits) */
    NUM nf[VERTEX_BATCH][3];
    if (ctx->texgen_units)
        for (int i = 0; i < n; i++)
            vertex_eye_normal(ctx, index[i], nf[i]);
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
        if (!(ctx->tex_units_on & (1u << u)))
            continue;
        const ArrayState *ta = &ctx->arrays[ARR_TEXCOORD0 + u];
        const Matrix *tm = ctx->texture[u].top;
        const int gen = (ctx->texgen_units >> u) & 1;
        for (int i = 0; i < n; i++) {
            NUM tc[4] = { NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ONE };
            if (ta->enabled)
                array_fetch(ta, array_base(ta), index[i], 0, tc);
            else
                memcpy(tc, ctx->cur_tex_n[u], sizeof tc);
            if (gen)
                texgen_coords(ctx->units[u].texgen_mode, out[i]->eye, nf[i], tc);
            matrix_xform4(tm->n, tm->kind, tc, out[i]->tex[u]);
        }
    }
    const ArrayState *ps = &ctx->arrays[ARR_POINT_SIZE];
    for (int i = 0; i < n; i++) {
        if (ps->enabled)
            array_fetch(ps, array_base(ps), index[i], 0, &out[i]->point_size);
        else
            out[i]->point_size = NUM_ONE;
    }
}

#if NUM_IS_FIXED
/* the hook's FLOAT array: m[0] components, an element every m[1] floats, at in */
static int debug_float_array(ArrayState *a, const int32_t *m, const int32_t *in)
{
    if (m[0] < 1 || m[0] > 4 || m[1] < m[0])
        return 0;
    memset(a, 0, sizeof *a);
    a->type = GL_FLOAT;
    a->size = m[0];
    a->step = m[1] * (int)sizeof(float);
    a->ptr = (const uint8_t *)in;
    return 1;
}
#endif

int gles_debug_vertex_lanes(int simd, int kernel, int n, const int32_t *m, const int32_t *in, int32_t *out)
{
#if NUM_IS_FIXED
    if (n < 0 || n > VERTEX_BATCH || n % NUM_LANES != 0)
        return 0;
    simd = simd && simd_detect() >= SIMD_AVX2;
    switch (kernel) {
    case 0:
        vx_dot4_lanes(simd, m[0], m[1], m[2], m[3], in, in + 64, in + 128, in + 192, out, n, m[4] != 0);
        return 1;
    case 1:
        vx_dot3_lanes(simd, m[0], m[1], m[2], in, in + 64, in + 128, out, n);
        return 1;
    case 2: {
        ArrayState a;
        if (!debug_float_array(&a, m, in))
            return 0;
        int64_t index[VERTEX_BATCH];
        for (int i = 0; i < n; i++)
            index[i] = m[2] ? n - 1 - i : i;
        NUM rows[4][VERTEX_BATCH];
        memset(rows, 0, sizeof rows);
        fetch_lanes(&a, index, n, 0, rows, simd);
        for (int c = 0; c < m[0]; c++)
            memcpy(out + 64 * c, rows[c], (size_t)n * sizeof(NUM));
        return 1;
    }
    case 3:
        return light_debug_directional(simd, n, m, in, out);
    case 6:
        return light_debug_positional(simd, n, m, in, out);
    case 8:
        vx_pow_all(simd, in, m[0], out, n);
        return 1;
    case 9: {
        /* int64 lanes, |y| < 2^62, as little-endian pairs of int32 */
        int64_t y[VERTEX_BATCH];
        for (int i = 0; i < n; i++) {
            const uint64_t v = (uint64_t)(uint32_t)in[2 * i] | (uint64_t)(uint32_t)in[2 * i + 1] << 32;
            y[i] = (int64_t)v;
            if (y[i] >= ((int64_t)1 << 62) || y[i] <= -((int64_t)1 << 62))
                return 0;
        }
        vx_exp2_all(simd, y, out, n);
        return 1;
    }
    case 5: {
        NUM rows[3][VERTEX_BATCH];
        for (int k = 0; k < 3; k++)
            memcpy(rows[k], in + 64 * k, (size_t)n * sizeof(NUM));
        vx_normalize3_lanes(simd, rows[0], rows[1], rows[2], n, n);
        for (int k = 0; k < 3; k++)
            memcpy(out + 64 * k, rows[k], (size_t)n * sizeof(NUM));
        return 1;
    }
    case 7: {
        /* window coordinates of the lanes inside every plane (m: the
        ** viewport, near and far in 16.16, the depth maximum); out: wx, wy,
        ** 1/w's mantissa and exponent, depth as int64 rows of 64 */
        int64_t res[5][VERTEX_BATCH];
        memset(res, 0, sizeof res);
        const int64_t one = GLES_SUBPIXEL_ONE;
        const int64_t hx = (int64_t)m[2] * (one / 2), hy = (int64_t)m[3] * (one / 2);
        const int64_t ox = (int64_t)m[0] * one + hx, oy = (int64_t)m[1] * one + hy;
        const NUM *x = in, *y = in + 64, *z = in + 128, *w = in + 192;
#if VERTEX_AVX2
        if (simd) {
            const VxWindow W = { ox, oy, hx, hy, (int64_t)m[4] * 16384, ((int64_t)m[5] - m[4]) * 16384,
                                 (uint32_t)m[6] };
            vx_window_avx2(&W, x, y, z, w, n, res[0], res[1], res[2], res[3], res[4]);
        }
#endif
        VbRows c;
        unsigned int code[VERTEX_BATCH];
        for (int k = 0; k < 4; k++)
            memcpy(c[k], in + 64 * k, (size_t)n * sizeof(NUM));
        clip_codes(c, code, n);
        for (int i = 0; i < n; i++) {
            if (code[i]) {
                for (int k = 0; k < 5; k++)
                    res[k][i] = 0;
            } else if (!simd) {
                res[0][i] = ox + num_proj(x[i], w[i], hx);
                res[1][i] = oy + num_proj(y[i], w[i], hy);
                RecipW r = recipw_of(w[i]);
                res[2][i] = r.mant;
                res[3][i] = r.exp;
                res[4][i] = depthv_from_clip(z[i], w[i], m[4], m[5], (uint32_t)m[6]);
            }
        }
        memcpy(out, res, sizeof res);
        return 1;
    }
    case 4: {
        ArrayState a;
        if (m[2] < 0 || m[3] >= n || !debug_float_array(&a, m, in))
            return 0;
        float f = (float)range_array_max(&a, (const uint8_t *)in, m[2], m[3], simd);
        memcpy(out, &f, sizeof f);
        return 1;
    }
    default:
        return 0;
    }
#else
    if (kernel == 6)
        return light_debug_positional(simd, n, m, in, out);
    (void)simd, (void)kernel, (void)n, (void)m, (void)in, (void)out;
    return 0;
#endif
}
