/*
** raster.h -- triangle setup and scan conversion, and the span interface.
*/
#ifndef GLES_RASTER_H
#define GLES_RASTER_H

#include "state.h"
#include "texture.h"
#include "span.h"
#include "fragment.h"

/* Everything a span function needs about the triangle being drawn. */
struct TriSetup {
    const Vertex *v[3];     /* counter-clockwise in window space */
    /* edge i is opposite vertex i: E_i(px, py) = ea*px + eb*py + ec for
    ** pixel indices; positive inside, zero on the edge */
    int64_t ea[3], eb[3], ec[3];
    WgtSetup wgt;
    WgtTangent tan[2];      /* the weights' tangents along ea and eb, where lod */
    int lod;                /* a unit needs the level of detail (raster_tangent_setup) */
    const FRAGV *col[3];    /* each vertex's colour for the visible face */
    int smooth;             /* colours vary over the triangle */
    unsigned int tex_projective;  /* bit per unit whose q varies (divide by q) */
    uint64_t serial;        /* ctx->prim_serial of this setup (the stages' per-primitive setups) */
    int64_t depth_offset;         /* polygon offset in depth units, 0 when off */
    FRAGV flat[4];          /* colour of the provoking vertex */
    uint32_t flat_packed;   /* the same in the framebuffer's format */
};

/* the three edge values E_i at pixel (x, y) */
static inline void tri_edges_at(const TriSetup *t, int64_t x, int64_t y, int64_t e[3])
{
    for (int i = 0; i < 3; i++)
        e[i] = t->ea[i] * x + t->eb[i] * y + t->ec[i];
}

/* unit u's s and t at the three vertices (0 where u < 0: no unit) */
static inline void span_unit_st(const TriSetup *t, int u, NUM s[3], NUM tt[3])
{
    for (int i = 0; i < 3; i++) {
        s[i] = u >= 0 ? t->v[i]->tex[u][0] : 0;
        tt[i] = u >= 0 ? t->v[i]->tex[u][1] : 0;
    }
}

/* whether an enabled unit's filter needs the level of detail */
static inline int raster_needs_lod(const GlesContext *ctx)
{
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if ((ctx->tex_units_on & (1u << u)) && texture_needs_lod(ctx->units[u].bound))
            return 1;
    return 0;
}

/* t->lod, and t->tan from t->wgt, t->ea and t->eb (twice the area area2)
** where it is set */
static inline void raster_tangent_setup(const GlesContext *ctx, TriSetup *t, int64_t area2)
{
    t->lod = raster_needs_lod(ctx);
    if (t->lod)
        wgt_tangents_setup(&t->wgt, area2, t->ea, t->eb, t->tan);
}

/* texture coordinates of unit u at perspective weights p */
static inline void span_tex_coord(const TriSetup *t, int u, const WGT p[3], TexCoord *out)
{
    const NUM *a = t->v[0]->tex[u], *b = t->v[1]->tex[u], *c = t->v[2]->tex[u];
    TEXC s = texc_lerp3(a[0], b[0], c[0], p[0], p[1], p[2]);
    TEXC tt = texc_lerp3(a[1], b[1], c[1], p[0], p[1], p[2]);
    if (t->tex_projective & (1u << u)) {
        TEXC q = texc_lerp3(a[3], b[3], c[3], p[0], p[1], p[2]);
        s = texc_div(s, q);
        tt = texc_div(tt, q);
    }
    out->s = s;
    out->t = tt;
}

/* rasterize a triangle whose vertices have window coordinates and whose
** raster_area2 the caller has found; `pv` is the provoking vertex (flat
** shading); `back` selects the back colours of two-sided lighting */
void raster_triangle(GlesContext *ctx, const Vertex *a, const Vertex *b, const Vertex *c, int64_t area2,
                     const Vertex *pv, int back);
/* the signed window-space area (x2) of a triangle, counter-clockwise > 0 */
int64_t raster_area2(const Vertex *a, const Vertex *b, const Vertex *c);

/* the inputs of the fragment at edge values e of a primitive described by
** a TriSetup (sprite coordinates replace a unit's where COORD_REPLACE is on) */
void fragment_inputs(const GlesContext *ctx, const TriSetup *t, const int64_t e[3], FRAGV coverage,
                     const TexCoord *sprite, const TexCoord *sprite_dx, const TexCoord *sprite_dy, FragIn *out);
void fragment_from_setup(GlesContext *ctx, const TriSetup *t, const int64_t e[3], int x, int y, FRAGV coverage,
                         const TexCoord *sprite, const TexCoord *sprite_dx, const TexCoord *sprite_dy);
/* polygon offset (§3.5.2) applied to a triangle fragment's depth */
uint32_t raster_offset_depth(const GlesContext *ctx, const TriSetup *t, uint32_t z);

/* the pixels fragments may reach: the framebuffer, cut by the scissor box
** when the scissor test is on; [x0, x1) x [y0, y1), possibly empty */
typedef struct ClipRect {
    int64_t x0, y0, x1, y1;
} ClipRect;
ClipRect raster_clip_rect(const GlesContext *ctx);

/* rows in periods of RASTER_BAND_ROWS x threads: in each, a band of rows
** per thread, which rasterizes every primitive's fragments in them, in
** order, so the bytes are the same for any number of threads and any
** split of the period. Bands near 16 rows keep most small triangles
** within one thread's band and spread a scene's busy rows evenly
** (benchmarks/README.md) */
#define RASTER_BAND_ROWS 16
/* y mod the period, in [0, period) */
static inline int64_t raster_band_phase(const GlesContext *ctx, int64_t y)
{
    const int64_t period = ctx->band_period;
    /* a mask for the usual periods (a division per row showed in profiles) */
    if (!(period & (period - 1)))
        return y & (period - 1);
    const int64_t m = y % period;
    return m < 0 ? m + period : m;
}
static inline int raster_owns_row(const GlesContext *ctx, int64_t y)
{
    if (ctx->band_count <= 1)
        return 1;
    const int64_t m = raster_band_phase(ctx, y);
    return m >= ctx->band_lo && m < ctx->band_hi;
}
/* below this many pixels a draw is rasterized on the calling thread:
** waking the workers and copying the context for them cost about as much
** as that (benchmarks/README.md) */
#define RASTER_THREADED_PIXELS 8192
typedef void (*RasterWork)(GlesContext *ctx, void *arg);
/* 1 when the context's pool is now the caller's for one job (pool_run or
** pool_start, whose end gives it back): the context has threads, the pool
** is free, and `amount` of work reaches `threshold` (or debug switch 64
** threads everything); the context's last job is waited for first */
int raster_pool_take(GlesContext *ctx, int64_t amount, int64_t threshold);
/* work(c, copy) on each thread of the context's pool, c the thread's
** context (this one on the calling thread) owning its bands of rows and
** copy the context's copy of the `size` bytes at arg; returns 1 once the
** calling thread's share is done, the workers' perhaps not (raster_join);
** `votes`: the next draw's wait for it moves the bands (raster_join_next);
** 0 (nothing done) where the context has one thread, the pool is busy
** with another context, or `pixels` is too few to gain */
int raster_threaded(GlesContext *ctx, int64_t pixels, RasterWork work, const void *arg, size_t size, int votes);
/* waits for the workers of the context's last threaded job, if any are
** still running: every command that changes what they read (the
** vertices, textures, buffers and framebuffer objects) or reads or
** writes the framebuffer calls it first */
void raster_join(GlesContext *ctx);
/* raster_join at the start of a draw or DrawTex, which also moves the
** caller's band towards the balance where the job waited for votes */
void raster_join_next(GlesContext *ctx);

/* the first row at or after y that the context rasterizes */
static inline int64_t raster_next_owned_row(const GlesContext *ctx, int64_t y)
{
    if (ctx->band_count <= 1)
        return y;
    const int64_t m = raster_band_phase(ctx, y);
    if (m < ctx->band_lo)
        return y + (ctx->band_lo - m);
    return m < ctx->band_hi ? y : y + (ctx->band_period - m) + ctx->band_lo;
}
/* whether the context rasterizes any row of y0..y1 */
static inline int raster_owns_rows(const GlesContext *ctx, int64_t y0, int64_t y1)
{
    return ctx->band_count <= 1 || raster_next_owned_row(ctx, y0) <= y1;
}

/* floor(v / GLES_SUBPIXEL_ONE) and ceil, for window coordinates in subpixels */
static inline int64_t raster_floor_px(int64_t v)
{
    return v >= 0 ? v / GLES_SUBPIXEL_ONE : -((-v + GLES_SUBPIXEL_ONE - 1) / GLES_SUBPIXEL_ONE);
}
static inline int64_t raster_ceil_px(int64_t v) { return -raster_floor_px(-v); }

/* the pixel indices whose centres lie in [min(p, q, r), max(p, q, r)]
** (subpixels), within [clip0, clip1): *first..*last, empty when first > last */
static inline void raster_centre_range(int64_t p, int64_t q, int64_t r, int64_t clip0, int64_t clip1,
                                       int64_t *first, int64_t *last)
{
    const int64_t half = GLES_SUBPIXEL_ONE / 2;
    int64_t lo = p < q ? p : q, hi = p < q ? q : p;
    if (r < lo) lo = r;
    if (r > hi) hi = r;
    *first = raster_ceil_px(lo - half);
    *last = raster_floor_px(hi - half);
    if (*first < clip0) *first = clip0;
    if (*last > clip1 - 1) *last = clip1 - 1;
}

/* The pixel centres of `clip` in the bounding box of a triangle's window
** coordinates, edges included (a centre on an edge may belong to the
** triangle): columns box->x0..x1 and rows box->y0..y1, inclusive. Returns 0
** when there is none: then the triangle yields no fragment under any fill
** rule, and can be dropped before its vertices are lit or its edges set up
** (small triangles far from the eye are often like this). */
static inline int raster_centre_box(const ClipRect *clip, const Vertex *a, const Vertex *b, const Vertex *c,
                                    ClipRect *box)
{
    raster_centre_range(a->wx, b->wx, c->wx, clip->x0, clip->x1, &box->x0, &box->x1);
    if (box->x0 > box->x1)
        return 0;
    raster_centre_range(a->wy, b->wy, c->wy, clip->y0, clip->y1, &box->y0, &box->y1);
    return box->y0 <= box->y1;
}

/* draw.c: bring derived state up to date before drawing */
void draw_validate(GlesContext *ctx);

#endif
