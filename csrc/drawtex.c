/*
** drawtex.c -- OES_draw_texture: DrawTex{sifx}[v]OES.
** A screen-aligned rectangle (Xs, Ys, Ws, Hs) in window coordinates at
** depth Zs, one fragment per pixel whose centre lies inside, coloured by the
** current colour, with every enabled unit's texture coordinates mapping its
** TEXTURE_CROP_RECT_OES linearly onto the rectangle:
**     s = (Ucr + (X - Xs) Wcr / Ws) / Wt,  t = (Vcr + (Y - Ys) Hcr / Hs) / Ht
** (the texture matrix, clip planes and lighting do not apply; fog sees
** distance 0; a unit sampling a cube map takes the direction (s, t, 0)).
** The level of detail is constant over the rectangle. The coordinates are
** formed in double from the real arguments and rounded once.
** Rows run through the span chain (span_chain.c); the per-fragment path
** stays as its reference (ctx.debug(1)).
*/
#include "state.h"
#include "raster.h"
#include "texture.h"
#include "texcube.h"
#include "fragment.h"
#include "fbo.h"

/* the rectangle's rows through the span chain, on each thread its own */
typedef struct DrawTexJob {
    RectSetup r;
    int64_t x0, y0, x1, y1;
} DrawTexJob;
_Static_assert(sizeof(DrawTexJob) <= GLES_JOB_ARG_BYTES, "raster_threaded keeps a copy of the job");

static void drawtex_job(GlesContext *ctx, void *arg)
{
    const DrawTexJob *j = arg;
    /* one primitive, so any split of its rows gives the same bytes: each
    ** thread its band's share of the period (an even one, unless the
    ** caller's is smaller or larger), where the bands would split a
    ** rectangle of a few of them unevenly */
    const int n = ctx->band_count;
    const int64_t h = j->y1 - j->y0, period = n > 1 ? ctx->band_period : 1;
    const int64_t lo = n > 1 ? ctx->band_lo : 0, hi = n > 1 ? ctx->band_hi : 1;
    ctx->band_count = 1;
    span_rect(ctx, &j->r, j->x0, j->y0 + h * lo / period, j->x1, j->y0 + h * hi / period);
    ctx->band_count = n;
}

void gles_DrawTexOES(GlesContext *ctx, double xs, double ys, double zs, double ws, double hs)
{
    if (!(ws > 0) || !(hs > 0)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    if (!fbo_sync(ctx))
        return;
    raster_join_next(ctx);
    draw_validate(ctx);
    DrawTexJob job;
    RectSetup *const rp = &job.r;
    FragIn *in = &rp->in;
    /* depth: n if z <= 0, f if z >= 1, n + z (f - n) otherwise */
    double z = zs <= 0 ? 0 : (zs >= 1 ? 1 : zs);
    double zw = ctx->depth_range[0] + z * (ctx->depth_range[1] - ctx->depth_range[0]);
    in->z = (uint32_t)dbl_to_i64(zw * ctx->depth_max, 0, ctx->depth_max);
    for (int i = 0; i < 4; i++)
        in->c[i] = frag_clamp01(frag_from_double(ctx->cur_color[i]));
    in->fog = ctx->fog ? frag_from_num(fog_factor(ctx, NUM_ZERO)) : 0;
    in->coverage = FRAG_ONE;
    /* per unit: s = a_s + b_s X, t = a_t + b_t Y */
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
        rp->coord[u] = RECT_COORD_LINEAR;
        rp->as[u] = rp->bs[u] = rp->at[u] = rp->bt[u] = 0;
        if (!(ctx->tex_units_on & (1u << u)))
            continue;
        const Texture *t = ctx->units[u].bound;
        double wt = t->level[0].width, ht = t->level[0].height;
        rp->bs[u] = t->crop[2] / ws / wt;
        rp->as[u] = t->crop[0] / wt - xs * rp->bs[u];
        rp->bt[u] = t->crop[3] / hs / ht;
        rp->at[u] = t->crop[1] / ht - ys * rp->bt[u];
    }
    int64_t x0 = dbl_to_i64(ceil(xs - 0.5), -(1 << 30), 1 << 30), x1 = dbl_to_i64(ceil(xs + ws - 0.5), -(1 << 30), 1 << 30);
    int64_t y0 = dbl_to_i64(ceil(ys - 0.5), -(1 << 30), 1 << 30), y1 = dbl_to_i64(ceil(ys + hs - 0.5), -(1 << 30), 1 << 30);
    const ClipRect clip = raster_clip_rect(ctx);
    if (x0 < clip.x0) x0 = clip.x0;
    if (y0 < clip.y0) y0 = clip.y0;
    if (x1 > clip.x1) x1 = clip.x1;
    if (y1 > clip.y1) y1 = clip.y1;
    if (x0 >= x1 || y0 >= y1)
        return;
    if (!ctx_generic_spans(ctx)) {
        job.x0 = x0;
        job.y0 = y0;
        job.x1 = x1;
        job.y1 = y1;
        if (!raster_threaded(ctx, (x1 - x0) * (y1 - y0), drawtex_job, &job, sizeof job, 1))
            drawtex_job(ctx, &job);
        return;
    }
    /* the reference: every fragment through fragment_process */
    for (int64_t py = y0; py < y1; py++)
        for (int64_t px = x0; px < x1; px++) {
            for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
                if (ctx->tex_units_on & (1u << u)) {
                    rect_linear_coords(rp, u, px, py, &in->tc[u], &in->tdx[u], &in->tdy[u]);
                    if (ctx->cube_units & (1u << u)) {
                        /* a cube map: the direction (s, t, 0) */
                        const TEXC c[3] = { in->tc[u].s, in->tc[u].t, 0 };
                        const TEXC cx[3] = { in->tdx[u].s, in->tdx[u].t, 0 };
                        const TEXC cy[3] = { in->tdy[u].s, in->tdy[u].t, 0 };
                        texcube_coords(c, cx, cy, &in->tc[u], &in->tdx[u], &in->tdy[u], &in->face[u]);
                    }
                }
            fragment_process(ctx, (int)px, (int)py, in);
        }
}
