/*
** point.c -- point rasterization (ES 1.1 §3.3, OES_point_sprite,
** OES_point_size_array).
** Consumes: one vertex with window coordinates.
** Size: the vertex's size (array) or POINT_SIZE, scaled by the distance
**       attenuation sqrt(1 / (a + b d + c d^2)) with d the eye distance,
**       clamped to [POINT_SIZE_MIN, POINT_SIZE_MAX] and the supported range.
**       Fading below POINT_FADE_THRESHOLD_SIZE applies with multisampling,
**       which this renderer does not have (SAMPLE_BUFFERS 0).
** Footprints: aliased points are w x w pixels, w the rounded size, centred
**       on the pixel centre (odd w) or the pixel corner (even w); smooth
**       points cover a disc, with coverage from 4x4 samples per pixel; point
**       sprites cover every pixel whose centre lies in the size x size square
**       and replace texture coordinates where COORD_REPLACE_OES is on.
*/
#include "state.h"
#include "raster.h"
#include "point.h"

#define POINT_SIZE_LIMIT 64

NUM point_derived_size(const GlesContext *ctx, const Vertex *v)
{
    NUM size = ctx->arrays[ARR_POINT_SIZE].enabled ? v->point_size : ctx->n_point_size;
    const NUM *k = ctx->n_point_attenuation;
    if (k[0] != NUM_ONE || k[1] != NUM_ZERO || k[2] != NUM_ZERO) {
        NUM e[3] = { v->eye[0], v->eye[1], v->eye[2] };
        NUM m = num_max(num_abs(e[0]), num_max(num_abs(e[1]), num_abs(e[2])));
        NUM d = NUM_ZERO;
        if (m != NUM_ZERO) {
            NUM u[3] = { num_div(e[0], m), num_div(e[1], m), num_div(e[2], m) };
            d = num_mul(m, num_sqrt(num_dot(u, 1, u, 1, 3)));
        }
        /* c d first, then times d, as for light attenuation */
        NUM den = num_add(k[0], num_add(num_mul(k[1], d), num_mul(num_mul(k[2], d), d)));
        size = num_mul(size, num_rsqrt(den));
    }
    size = num_max(size, ctx->n_point_size_min);
    size = num_min(size, ctx->n_point_size_max);
    return num_clamp_range(size, NUM_ONE, num_from_int(POINT_SIZE_LIMIT));
}

/* a TriSetup whose three vertices are the point: every weight lands on it */
static void point_setup(GlesContext *ctx, TriSetup *t, const Vertex *v)
{
    t->serial = ++ctx->prim_serial;
    t->v[0] = t->v[1] = t->v[2] = v;
    t->col[0] = t->col[1] = t->col[2] = v->color;
    for (int k = 0; k < 4; k++)
        t->flat[k] = v->color[k];
    t->smooth = 0;
    NUM w[3] = { v->clip[3], v->clip[3], v->clip[3] };
    RecipW q[3] = { v->rw, v->rw, v->rw };
    wgt_setup(&t->wgt, 1, w, q);
    t->tex_projective = 0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (v->tex[u][3] != NUM_ONE)
            t->tex_projective |= 1u << u;
    for (int i = 0; i < 3; i++)
        t->ea[i] = t->eb[i] = t->ec[i] = 0;
    t->depth_offset = 0;
    raster_tangent_setup(ctx, t, 1);
}

void raster_point(GlesContext *ctx, const Vertex *v)
{
    TriSetup t;
    const int64_t e[3] = { 1, 0, 0 };      /* all weight on the vertex */
    const int64_t one = GLES_SUBPIXEL_ONE, half = one / 2;
    NUM size = point_derived_size(ctx, v);
    int64_t size_sub = (int64_t)num_to_fixed(size) / (65536 / GLES_SUBPIXEL_ONE);  /* in subpixels */
    int64_t x0, x1, y0, y1;                 /* pixel rectangle, inclusive */
    int disc = 0, sprite = ctx->point_sprite;
    if (sprite || ctx->point_smooth) {
        /* pixels whose centres fall in the size x size square (or its disc) */
        x0 = i64_ceil_div(v->wx - size_sub / 2 - half, one);
        x1 = i64_floor_div(v->wx + size_sub / 2 - half - 1, one);
        y0 = i64_ceil_div(v->wy - size_sub / 2 - half, one);
        y1 = i64_floor_div(v->wy + size_sub / 2 - half - 1, one);
        disc = !sprite;
        if (disc) { /* partial coverage reaches one pixel further */
            x0--; y0--; x1++; y1++;
        }
    } else {
        int64_t w = (size_sub + half) / one;        /* round to an integer width */
        if (w < 1)
            w = 1;
        if (w & 1) {
            int64_t cx = i64_floor_div(v->wx, one), cy = i64_floor_div(v->wy, one);
            x0 = cx - (w - 1) / 2; x1 = cx + (w - 1) / 2;
            y0 = cy - (w - 1) / 2; y1 = cy + (w - 1) / 2;
        } else {
            int64_t cx = i64_floor_div(v->wx + half, one), cy = i64_floor_div(v->wy + half, one);
            x0 = cx - w / 2; x1 = cx + w / 2 - 1;
            y0 = cy - w / 2; y1 = cy + w / 2 - 1;
        }
    }
    const ClipRect clip = raster_clip_rect(ctx);   /* x1, y1 here are inclusive */
    if (x0 < clip.x0) x0 = clip.x0;
    if (y0 < clip.y0) y0 = clip.y0;
    if (x1 > clip.x1 - 1) x1 = clip.x1 - 1;
    if (y1 > clip.y1 - 1) y1 = clip.y1 - 1;
    if (y0 > y1 || !raster_owns_rows(ctx, y0, y1))
        return;     /* (threads: no row of this one's) */
    point_setup(ctx, &t, v);
    if (!disc && !ctx_generic_spans(ctx)) {
        /* a square of fragments whose inputs are the point's: only the
        ** sprite coordinates vary, so the rows run through the span chain */
        if (x0 > x1 || y0 > y1)
            return;
        RectSetup r;
        fragment_inputs(ctx, &t, e, FRAG_ONE, NULL, NULL, NULL, &r.in);
        for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
            r.coord[u] = sprite && ctx->units[u].coord_replace ? RECT_COORD_SPRITE : RECT_COORD_CONST;
        r.sprite_x = v->wx;
        r.sprite_y = v->wy;
        r.sprite_size = size_sub;
        span_rect(ctx, &r, x0, y0, x1 + 1, y1 + 1);
        return;
    }
    int64_t r2 = (size_sub / 2) * (size_sub / 2);  /* disc radius squared, subpixels */
    for (int64_t py = y0; py <= y1; py++) {
        if (!raster_owns_row(ctx, py))
            continue;                           /* (threads: another's row) */
        for (int64_t px = x0; px <= x1; px++) {
            FRAGV coverage = FRAG_ONE;
            if (disc) {
                int inside = 0;
                for (int sy = 0; sy < 4; sy++)
                    for (int sx = 0; sx < 4; sx++) {
                        int64_t dx = px * one + (2 * sx + 1) * one / 8 - v->wx;
                        int64_t dy = py * one + (2 * sy + 1) * one / 8 - v->wy;
                        inside += dx * dx + dy * dy <= r2;
                    }
                if (!inside)
                    continue;
                coverage = frag_ratio(inside, 16);
            }
            if (sprite) {
                TexCoord tc, tx, ty;
                sprite_coords(v->wx, v->wy, size_sub, px, py, &tc, &tx, &ty);
                fragment_from_setup(ctx, &t, e, (int)px, (int)py, coverage, &tc, &tx, &ty);
            } else {
                fragment_from_setup(ctx, &t, e, (int)px, (int)py, coverage, NULL, NULL, NULL);
            }
        }
    }
}
