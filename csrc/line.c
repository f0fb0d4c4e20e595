/*
** line.c -- line rasterization (ES 1.1 §3.4).
** Consumes: two vertices with window coordinates (after clipping).
** Aliased lines: for an x-major line, each pixel column whose centre lies in
**       the half-open span from the first endpoint to the second gets the
**       fragments whose centres are within width/2 of the line, measured
**       vertically (one fragment for width 1: the diamond-exit rule away
**       from the endpoints); y-major lines likewise by rows. Shared endpoints
**       of strips and loops are therefore drawn once.
** Smooth lines: the coverage of a width x length rectangle, from 4x4
**       samples per pixel (an estimate, as §3.4.2 allows; computed in
**       double), multiplies alpha.
** Attributes: perspective-correct along the line, through the triangle
**       weights with the edge values (|D| - |n|, |n|, 0); depth linear.
** Aliased lines of width 1 go through the span function for the state, a
**       row's run (x-major) or a row's one fragment (y-major) at a time;
**       wider and smooth lines, one fragment at a time.
*/
#include <math.h>
#include "state.h"
#include "raster.h"
#include "line.h"

#define LINE_WIDTH_LIMIT 64

/* the minor coordinate at major offset n of a line from na with minor
** extent dn over major extent D (|n| <= |D|): exact while the product
** fits 64 bits, else in double (only window coordinates far outside any
** viewport get there) */
static int64_t line_minor(int64_t na, int64_t dn, int64_t n, int64_t D)
{
    const int64_t lim = (int64_t)1 << 31;
    if (dn > -lim && dn < lim && n > -lim && n < lim)
        return na + i64_round_div(dn * n, D);
    double m = (double)na + (double)dn * ((double)n / (double)D);
    const double big = 4611686018427387904.0;   /* 2^62 */
    return m < -big ? -((int64_t)1 << 62) : (m > big ? (int64_t)1 << 62 : (int64_t)m);
}

static void line_setup(GlesContext *ctx, TriSetup *t, const Vertex *a, const Vertex *b, const Vertex *pv,
                       int64_t len)
{
    t->serial = ++ctx->prim_serial;
    t->v[0] = a;
    t->v[1] = t->v[2] = b;
    t->col[0] = a->color;
    t->col[1] = t->col[2] = b->color;
    for (int k = 0; k < 4; k++)
        t->flat[k] = pv->color[k];
    t->smooth = ctx->shade_model == GL_SMOOTH;
    NUM w[3] = { a->clip[3], b->clip[3], b->clip[3] };
    RecipW q[3] = { a->rw, b->rw, b->rw };
    wgt_setup(&t->wgt, len > 0 ? len : 1, w, q);
    t->tex_projective = 0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (a->tex[u][3] != NUM_ONE || b->tex[u][3] != NUM_ONE)
            t->tex_projective |= 1u << u;
    for (int i = 0; i < 3; i++)
        t->ea[i] = t->eb[i] = t->ec[i] = 0;
    /* one pixel along the major axis: the level of detail's neighbour */
    t->ea[0] = -GLES_SUBPIXEL_ONE;
    t->ea[1] = GLES_SUBPIXEL_ONE;
    t->depth_offset = 0;
    raster_tangent_setup(ctx, t, len > 0 ? len : 1);
}

/* An aliased line of width 1 has one fragment per major-axis pixel pm, at
** minor pixel ceil(m / one) - 1 (m the line's minor coordinate at pm's
** centre c), with edge values (len - an, an, 0), an = |c - ma| = sg (c - ma)
** for the sign sg of D: linear in pm. So an x-major line's columns in one
** row are a run of the span function for the state (a y-major line's
** fragments runs of one), whose reference (span_generic) gives each the
** fragment raster_line's loop would, with the same edge values: e = ea x
** + eb y + ec with ea (x-major) or eb (y-major) = (-sg, sg, 0) pixels. ea
** is also the level of detail's neighbour, which that step is for an
** x-major line with D > 0 only; the caller takes this path otherwise only
** where no unit needs that neighbour. */
static void line_runs(GlesContext *ctx, TriSetup *t, int xmajor, int64_t ma, int64_t na, int64_t nb, int64_t D,
                      int64_t len, int64_t p0, int64_t p1, int64_t cn0, int64_t cn1)
{
    const int64_t one = GLES_SUBPIXEL_ONE, half = one / 2, sg = D > 0 ? 1 : -1;
    int64_t *step = xmajor ? t->ea : t->eb, *across = xmajor ? t->eb : t->ea;
    across[0] = across[1] = 0;
    step[0] = -sg * one;
    step[1] = sg * one;
    t->ec[0] = len + sg * (ma - half);
    t->ec[1] = sg * (half - ma);
    SpanFunc span = ctx->span;
    if (!t->smooth) {
        t->flat_packed = span_pack_color(ctx, t->flat);
        span = ctx->span_const;
    }
#define LINE_MINOR_PIXEL(pm) (i64_ceil_div(line_minor(na, nb - na, (pm) * one + half - ma, D), one) - 1)
    if (!xmajor) {
        /* one fragment per row */
        for (int64_t pm = p0; pm <= p1; pm++) {
            if (!raster_owns_row(ctx, pm))
                continue;
            const int64_t col = LINE_MINOR_PIXEL(pm);
            if (col >= cn0 && col < cn1)
                span(ctx, t, (int)pm, (int)col, 1);
        }
        return;
    }
    int64_t run_y = 0, run_x = 0, run_n = 0;
    for (int64_t pm = p0; pm <= p1; pm++) {
        const int64_t row = LINE_MINOR_PIXEL(pm);
        if (run_n && row != run_y) {
            span(ctx, t, (int)run_y, (int)run_x, (int)run_n);
            run_n = 0;
        }
        if (row < cn0 || row >= cn1 || !raster_owns_row(ctx, row))
            continue;
        if (!run_n)
            run_y = row, run_x = pm;
        run_n++;
    }
#undef LINE_MINOR_PIXEL
    if (run_n)
        span(ctx, t, (int)run_y, (int)run_x, (int)run_n);
}

void raster_line(GlesContext *ctx, const Vertex *a, const Vertex *b, const Vertex *pv)
{
    const int64_t one = GLES_SUBPIXEL_ONE, half = one / 2;
    int64_t dx = b->wx - a->wx, dy = b->wy - a->wy;
    int xmajor = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
    /* major and minor coordinates of the endpoints */
    int64_t ma = xmajor ? a->wx : a->wy, mb = xmajor ? b->wx : b->wy;
    int64_t na = xmajor ? a->wy : a->wx, nb = xmajor ? b->wy : b->wx;
    int64_t D = mb - ma, len = D < 0 ? -D : D;
    if (len == 0)
        return;
    {
        /* threads: nothing to set up where no row the line (with its
        ** width, and a pixel besides) reaches is this thread's */
        const int64_t reach = (int64_t)(ctx->line_width < LINE_WIDTH_LIMIT ? ctx->line_width : LINE_WIDTH_LIMIT) + 2;
        const int64_t lo = i64_floor_div(a->wy < b->wy ? a->wy : b->wy, one) - reach;
        const int64_t hi = i64_floor_div(a->wy < b->wy ? b->wy : a->wy, one) + reach;
        if (ctx->band_count > 1 && hi >= 0 && !raster_owns_rows(ctx, lo < 0 ? 0 : lo, hi))
            return;
    }
    TriSetup t;
    line_setup(ctx, &t, a, b, pv, len);
    double width = ctx->line_width;
    if (width > LINE_WIDTH_LIMIT)
        width = LINE_WIDTH_LIMIT;
    /* pixels of the major axis whose centres lie in [ma, mb) (or (mb, ma]) */
    int64_t p0, p1;
    if (D > 0) {
        p0 = i64_ceil_div(ma - half, one);
        p1 = i64_ceil_div(mb - half, one) - 1;
    } else {
        p0 = i64_floor_div(mb - half, one) + 1;
        p1 = i64_floor_div(ma - half, one);
    }
    const ClipRect clip = raster_clip_rect(ctx);
    /* step only over the columns (rows) the clip rectangle holds: the
    ** others produce no fragment, and a line whose window coordinates are
    ** huge (non-finite input) then costs no more than one across the window */
    int64_t cm0 = xmajor ? clip.x0 : clip.y0, cm1 = xmajor ? clip.x1 : clip.y1;
    int64_t cn0 = xmajor ? clip.y0 : clip.x0, cn1 = xmajor ? clip.y1 : clip.x1;
    if (p0 < cm0)
        p0 = cm0;
    if (p1 > cm1 - 1)
        p1 = cm1 - 1;
    int smooth = ctx->line_smooth;
    int64_t w = (int64_t)floor(width + 0.5);
    if (w < 1)
        w = 1;
    /* (window coordinates below 2^40 subpixels: the edge values' constants
    ** stay far inside int64) */
    const int64_t lim = (int64_t)1 << 40;
    if (!smooth && w == 1 && ((xmajor && D > 0) || !raster_needs_lod(ctx)) && !ctx_generic_spans(ctx)
        && ma > -lim && ma < lim && mb > -lim && mb < lim && na > -lim && na < lim && nb > -lim && nb < lim) {
        if (p0 <= p1)
            line_runs(ctx, &t, xmajor, ma, na, nb, D, len, p0, p1, cn0, cn1);
        return;
    }
    double fx = (double)dx, fy = (double)dy, flen = sqrt(fx * fx + fy * fy);
    for (int64_t pm = p0; pm <= p1; pm++) {
        if (!xmajor && !raster_owns_row(ctx, pm))
            continue;                           /* (threads: another's row) */
        int64_t c = pm * one + half;            /* major coordinate of the centres */
        int64_t n = c - ma, an = n < 0 ? -n : n;
        int64_t e[3] = { len - an, an, 0 };
        /* minor coordinate of the line at the centre, in subpixels */
        int64_t m = line_minor(na, nb - na, n, D);
        int64_t q0, q1;                         /* the minor pixels */
        if (smooth) {
            int64_t reach = (int64_t)ceil(width / 2 * (double)one * flen / (double)len) + one;
            q0 = i64_floor_div(m - reach, one);
            q1 = i64_floor_div(m + reach, one);
        } else {
            /* centres within w/2 of the line: [m - w/2, m + w/2) */
            q0 = i64_ceil_div(m - w * one / 2 - half, one);
            q1 = i64_ceil_div(m + w * one / 2 - half, one) - 1;
        }
        if (q0 < cn0)
            q0 = cn0;
        if (q1 > cn1 - 1)
            q1 = cn1 - 1;
        for (int64_t pn = q0; pn <= q1; pn++) {
            int64_t px = xmajor ? pm : pn, py = xmajor ? pn : pm;
            if (px < clip.x0 || py < clip.y0 || px >= clip.x1 || py >= clip.y1 || !raster_owns_row(ctx, py))
                continue;
            FRAGV coverage = FRAG_ONE;
            if (smooth) {
                /* samples inside the width x length rectangle of the segment */
                int inside = 0;
                for (int sy = 0; sy < 4; sy++)
                    for (int sx = 0; sx < 4; sx++) {
                        double sxp = (double)(px * one + (2 * sx + 1) * one / 8 - a->wx);
                        double syp = (double)(py * one + (2 * sy + 1) * one / 8 - a->wy);
                        double along = (sxp * fx + syp * fy) / flen;
                        double across = (sxp * fy - syp * fx) / flen;
                        inside += along >= 0 && along <= flen && fabs(across) <= width / 2 * (double)one;
                    }
                if (!inside)
                    continue;
                coverage = frag_ratio(inside, 16);
            }
            fragment_from_setup(ctx, &t, e, (int)px, (int)py, coverage, NULL, NULL, NULL);
        }
    }
}
