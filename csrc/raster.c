/*
** raster.c -- triangle setup and scan conversion (ES 1.1 §3.5.1).
** Consumes: three vertices with window x, y in subpixels (GLES_SUBPIXEL_BITS
**       fraction bits; integers, the same in every build) and window depth.
** Produces: calls of the chosen span function for each row's run of pixels.
**
** The fill rule. A pixel belongs to a triangle when its centre is strictly
** inside every edge, or exactly on an edge that is a "left" or "bottom" edge.
** With the vertices made counter-clockwise (y up, GL window coordinates), an
** edge from P to Q is left when it goes down (Qy < Py) and bottom when it is
** horizontal and goes right (Qx > Px). An edge shared by two triangles runs
** in opposite directions in each, so exactly one of them owns the pixels on
** it: no gaps, no double hits. This is the rule Mesa's llvmpipe applies in
** GL window coordinates (the top-left rule of y-down memory order), so our
** coverage can be compared with it pixel for pixel.
**
** Scan conversion is exact and per row: for each pixel row the three edge
** inequalities E_i(px) = alpha_i * px + beta_i > 0 (or >= 0) are solved for
** px with integer division, giving the covered run directly. There is no
** per-pixel inside test, so every pixel a span function receives is covered;
** this does the work a block rasterizer does for fully covered blocks on
** every pixel, and never tests a pixel outside the triangle. Edge functions
** are in int64: window coordinates stay within about +-2^22 subpixels (the
** viewport's offset plus num_proj's clamp of x/w to +-2^20, NUM_PROJ_GUARD;
** draw.c skips drawing when the viewport misses the framebuffer), so
** products stay below 2^46.
*/
#include <string.h>
#include "raster.h"
#include "fbo.h"

int64_t raster_area2(const Vertex *a, const Vertex *b, const Vertex *c)
{
    return (b->wx - a->wx) * (c->wy - a->wy) - (c->wx - a->wx) * (b->wy - a->wy);
}

/* Set up edge i from P to Q in pixel-index form. Pixel (px, py) has its
** centre at subpixel (px * ONE + ONE/2, py * ONE + ONE/2). */
static void edge_setup(TriSetup *t, int i, const Vertex *p, const Vertex *q, int *tie)
{
    int64_t A = -(q->wy - p->wy); /* E = A (X - Px) + B (Y - Py) */
    int64_t B = q->wx - p->wx;
    const int64_t one = GLES_SUBPIXEL_ONE, half = GLES_SUBPIXEL_ONE / 2;
    t->ea[i] = A * one;
    t->eb[i] = B * one;
    t->ec[i] = A * (half - p->wx) + B * (half - p->wy);
    /* left edges go down (A > 0), bottom edges go right (A == 0, B > 0);
    ** bitwise, not a branch (the winding changes from triangle to triangle) */
    tie[i] = (A > 0) | ((A == 0) & (B > 0));
}

/* One edge's covered-run bound, stepped row by row. With
** E(px) = al * px + be(py), be(py) = eb * py + ec, the bound for
** al > 0 is the least px with E > 0 (E >= 0 on a tie edge):
**     tie: ceil(-be / al) = -floor(be / al);  else floor(-be / al) + 1
** and for al < 0 the exclusive upper bound:
**     tie: floor(be / -al) + 1;  else ceil(be / -al) = -floor(-be / -al).
** Each is sign * floor(n / d) + bias with n = +-be, d = |al|; n changes by
** +-eb per row, so q = floor(n / d) and r = n - q d step exactly. */
typedef struct EdgeStep {
    int kind;          /* +1 lower bound, -1 upper bound, 0 horizontal */
    int tie;
    int64_t be, eb;    /* horizontal edges: E of the row, and its step */
    int64_t sign, bias;
    int64_t q, r, d;   /* n = q d + r, 0 <= r < d */
    int64_t dq, dr;    /* the per-row step of n, as dq d + dr */
} EdgeStep;

static void step_init(EdgeStep *e, int64_t al, int64_t eb, int64_t ec, int tie, int64_t y0)
{
    int64_t be = eb * y0 + ec;
    e->kind = al > 0 ? 1 : (al < 0 ? -1 : 0);
    e->tie = tie;
    e->be = be;
    e->eb = eb;
    if (e->kind == 0) {
        e->d = 1;
        e->q = e->r = e->dq = e->dr = e->sign = e->bias = 0;
        return;
    }
    int64_t n, s;
    if (al > 0) {
        e->d = al;
        if (tie) { n = be; s = eb; e->sign = -1; e->bias = 0; }
        else { n = -be; s = -eb; e->sign = 1; e->bias = 1; }
    } else {
        e->d = -al;
        if (tie) { n = be; s = eb; e->sign = 1; e->bias = 1; }
        else { n = -be; s = -eb; e->sign = -1; e->bias = 0; }
    }
    e->q = i64_floor_div(n, e->d);
    e->r = n - e->q * e->d;
    e->dq = i64_floor_div(s, e->d);
    e->dr = s - e->dq * e->d;
}

/* the step over `rows` rows at once (rows * eb in range, as eb * y0 is
** in step_init): the same (q, r) as `rows` calls of step_next */
typedef struct EdgeJump {
    int64_t dq, dr, dbe;
} EdgeJump;

static void jump_init(EdgeJump *j, const EdgeStep *e, int64_t rows)
{
    j->dbe = e->eb * rows;
    if (e->kind == 0) {
        j->dq = j->dr = 0;
        return;
    }
    /* n steps by rows * (dq d + dr) */
    const int64_t s = (e->dq * e->d + e->dr) * rows;
    j->dq = i64_floor_div(s, e->d);
    j->dr = s - j->dq * e->d;
}

static inline void step_jump(EdgeStep *e, const EdgeJump *j)
{
    if (e->kind == 0) {
        e->be += j->dbe;
        return;
    }
    e->q += j->dq;
    e->r += j->dr;
    const int64_t carry = e->r >= e->d;
    e->q += carry;
    e->r -= carry * e->d;
}

static inline void step_next(EdgeStep *e)
{
    if (e->kind == 0) {
        e->be += e->eb;
        return;
    }
    /* the carry without a branch: it is taken about dr / d of the rows,
    ** unpredictably */
    e->q += e->dq;
    e->r += e->dr;
    const int64_t carry = e->r >= e->d;
    e->q += carry;
    e->r -= carry * e->d;
}

static inline int same_color(const FRAGV *p, const FRAGV *q)
{
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2] && p[3] == q[3];
}

ClipRect raster_clip_rect(const GlesContext *ctx)
{
    ClipRect r = { 0, 0, ctx->width, ctx->height };
    if (ctx->scissor_test) {
        int64_t sx = ctx->scissor[0], sy = ctx->scissor[1];
        int64_t ex = sx + ctx->scissor[2], ey = sy + ctx->scissor[3];
        if (sx > r.x0) r.x0 = sx;
        if (sy > r.y0) r.y0 = sy;
        if (ex < r.x1) r.x1 = ex;
        if (ey < r.y1) r.y1 = ey;
    }
    return r;
}

/* Bounding boxes of at most this many pixel centres are scanned pixel by
** pixel: for the small triangles of a distant mesh that is cheaper than the
** row bounds' divisions, and it finds the same runs (below). */
#define RASTER_SCAN_MAX 32

/* The covered run of each row of a small triangle: every pixel centre of
** the bounding box is tested against the three edge inequalities that the
** row bounds solve (E > 0, or E == 0 on a tie edge). A row's covered
** pixels form one interval, as each inequality holds on a half-line of the
** row, so the first and last covered pixel give the same run [lo, hi) as
** the divisions. The test has no branch: with E biased by tie - 1 (E > 0
** is E - 1 >= 0 for integers), a centre is covered where no biased value
** is negative, the sign bit of their OR; the row's centres are bits of a
** mask (the box is at most RASTER_SCAN_MAX wide). scan_runs writes (row,
** lo, hi) per row with a run and returns their number; scan_runs_avx2 is
** the same with four centres to a test (for boxes four or more wide). */

/* the biased edge values at the box's first centre */
static void scan_first(const TriSetup *t, const int tie[3], const ClipRect *box, int64_t r[3])
{
    tri_edges_at(t, box->x0, box->y0, r);
    for (int i = 0; i < 3; i++)
        r[i] += tie[i] - 1;
}

/* row py's run from its mask of covered centres, kept where it is not
** empty, without a branch (m < RASTER_SCAN_MAX: at most one run per row
** before); returns the runs kept so far */
static inline int scan_keep(int64_t runs[RASTER_SCAN_MAX][3], int m, int64_t py, uint32_t covered, int64_t x0,
                            int drop_last)
{
    const uint32_t any = covered ? covered : 1;
    const int64_t lo = x0 + __builtin_ctz(any);
    const int64_t hi = x0 + 32 - __builtin_clz(any) - (drop_last != 0);
    runs[m][0] = py;
    runs[m][1] = lo;
    runs[m][2] = hi;
    return m + ((covered != 0) & (lo < hi));
}

static int scan_runs(const TriSetup *t, const int tie[3], const ClipRect *box, int drop_last,
                     int64_t runs[RASTER_SCAN_MAX][3])
{
    _Static_assert(RASTER_SCAN_MAX <= 32, "a row's centres are bits of a uint32_t");
    const int width = (int)(box->x1 - box->x0 + 1);
    const int64_t a0 = t->ea[0], a1 = t->ea[1], a2 = t->ea[2];
    const int64_t b0 = t->eb[0], b1 = t->eb[1], b2 = t->eb[2];
    int64_t r[3];
    scan_first(t, tie, box, r);
    int64_t r0 = r[0], r1 = r[1], r2 = r[2];
    int m = 0;
    for (int64_t py = box->y0; py <= box->y1; py++) {
        int64_t e0 = r0, e1 = r1, e2 = r2;
        uint32_t covered = 0;
        for (int k = 0; k < width; k++) {
            covered |= (uint32_t)(~(uint64_t)(e0 | e1 | e2) >> 63) << k;
            e0 += a0;
            e1 += a1;
            e2 += a2;
        }
        m = scan_keep(runs, m, py, covered, box->x0, drop_last);
        r0 += b0;
        r1 += b1;
        r2 += b2;
    }
    return m;
}

#if SIMD_X86
#pragma GCC push_options
SIMD_TARGET_AVX2
#include <immintrin.h>
/* scan_runs with a row's centres four to a register (lane q the centre k +
** q): the sign bits of the three values' OR are movmskpd's bits, set
** where a centre is outside; the lanes past the row's end are masked off
** (their values, past the box, may wrap: vector adds are modular) */
static int scan_runs_avx2(const TriSetup *t, const int tie[3], const ClipRect *box, int drop_last,
                          int64_t runs[RASTER_SCAN_MAX][3])
{
    const int width = (int)(box->x1 - box->x0 + 1);
    const uint32_t in_row = (uint32_t)(((uint64_t)1 << width) - 1);
    __m256i step[3], down[3], row[3];
    int64_t r[3];
    scan_first(t, tie, box, r);
    for (int i = 0; i < 3; i++) {
        const int64_t a = t->ea[i];
        row[i] = _mm256_add_epi64(_mm256_set1_epi64x(r[i]), _mm256_setr_epi64x(0, a, 2 * a, 3 * a));
        step[i] = _mm256_set1_epi64x(4 * a);
        down[i] = _mm256_set1_epi64x(t->eb[i]);
    }
    int m = 0;
    for (int64_t py = box->y0; py <= box->y1; py++) {
        __m256i e0 = row[0], e1 = row[1], e2 = row[2];
        uint64_t outside = 0;
        for (int k = 0; k < width; k += 4) {
            const __m256i any = _mm256_or_si256(_mm256_or_si256(e0, e1), e2);
            outside |= (uint64_t)_mm256_movemask_pd(_mm256_castsi256_pd(any)) << k;
            e0 = _mm256_add_epi64(e0, step[0]);
            e1 = _mm256_add_epi64(e1, step[1]);
            e2 = _mm256_add_epi64(e2, step[2]);
        }
        m = scan_keep(runs, m, py, ~(uint32_t)outside & in_row, box->x0, drop_last);
        for (int i = 0; i < 3; i++)
            row[i] = _mm256_add_epi64(row[i], down[i]);
    }
    return m;
}
#pragma GCC pop_options
#endif

/* the flat colour in the framebuffer's format; neighbouring triangles of a
** flat-lit face share it, so the last one is kept */
static uint32_t packed_flat(GlesContext *ctx, const FRAGV c[4])
{
    if (ctx->flat_cache_format != ctx->color_format || !same_color(ctx->flat_cache_color, c)) {
        for (int k = 0; k < 4; k++)
            ctx->flat_cache_color[k] = c[k];
        ctx->flat_cache_format = ctx->color_format;
        ctx->flat_cache_packed = span_pack_color(ctx, c);
    }
    return ctx->flat_cache_packed;
}

void raster_triangle(GlesContext *ctx, const Vertex *a, const Vertex *b, const Vertex *c, int64_t area2,
                     const Vertex *pv, int back)
{
    if (area2 == 0)
        return;
    if (area2 < 0) {
        const Vertex *tmp = b;
        b = c;
        c = tmp;
        area2 = -area2;
    }
    /* the rows and columns whose centres lie within the extent, clipped to
    ** the framebuffer and the scissor box: nothing to set up without one */
    const ClipRect clip = raster_clip_rect(ctx);
    ClipRect box;
    if (!raster_centre_box(&clip, a, b, c, &box) || !raster_owns_rows(ctx, box.y0, box.y1))
        return;
    const int64_t y0 = box.y0, y1 = box.y1, cx0 = clip.x0, cx1 = clip.x1;
    const int drop_last = (ctx->debug & GLES_DEBUG_DROP_LAST_PIXEL) != 0;
    TriSetup t;
    int tie[3];
    t.serial = ++ctx->prim_serial;
    t.v[0] = a;
    t.v[1] = b;
    t.v[2] = c;
    edge_setup(&t, 0, b, c, tie);
    edge_setup(&t, 1, c, a, tie);
    edge_setup(&t, 2, a, b, tie);
    if (ctx->debug & GLES_DEBUG_FLIP_TIE_RULE)
        for (int i = 0; i < 3; i++)
            tie[i] = !tie[i]; /* shared edges now double-hit or gap */
    int64_t runs[RASTER_SCAN_MAX][3];
    int nruns = -1;  /* -1: the rows are bounded by division below */
    if ((box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1) <= RASTER_SCAN_MAX) {
#if SIMD_X86
        /* (a box narrower than four centres takes the scalar loop: one
        ** or two steps of it cost less than the lanes' setup, and the
        ** width is tested first, as it is in a register) */
        if (box.x1 - box.x0 >= 3 && ctx_simd(ctx) >= SIMD_AVX2)
            nruns = scan_runs_avx2(&t, tie, &box, drop_last, runs);
        else
#endif
            nruns = scan_runs(&t, tie, &box, drop_last, runs);
        if (nruns == 0)
            return;
    }
    NUM w[3] = { a->clip[3], b->clip[3], c->clip[3] };
    RecipW q[3] = { a->rw, b->rw, c->rw };
    wgt_setup(&t.wgt, area2, w, q);
    raster_tangent_setup(ctx, &t, area2);
    int use_back = back && ctx->two_sided;
    for (int i = 0; i < 3; i++)
        t.col[i] = use_back ? t.v[i]->color_back : t.v[i]->color;
    const FRAGV *pc = use_back ? pv->color_back : pv->color;
    for (int k = 0; k < 4; k++)
        t.flat[k] = pc[k];
    /* smooth shading of three equal colours is that colour: use the
    ** constant-colour span, which every path agrees on */
    t.smooth = ctx->shade_model == GL_SMOOTH && !(same_color(t.col[0], t.col[1]) && same_color(t.col[0], t.col[2]));
    t.depth_offset = 0;
    if (ctx->polygon_offset_fill && ctx->depth) {
        /* §3.5.2: o = m factor + r units, m = max(|dz/dx|, |dz/dy|) (the
        ** allowed bound), r = one depth unit; the slope is a per-triangle
        ** quantity, computed in double in every build */
        double z0 = depthv_to_double(a->wz), z1 = depthv_to_double(b->wz), z2 = depthv_to_double(c->wz);
        double dx1 = (double)(b->wx - a->wx), dy1 = (double)(b->wy - a->wy);
        double dx2 = (double)(c->wx - a->wx), dy2 = (double)(c->wy - a->wy);
        double ar = (double)area2, one = GLES_SUBPIXEL_ONE;
        double gx = ((z1 - z0) * dy2 - (z2 - z0) * dy1) / ar * one;
        double gy = ((z2 - z0) * dx1 - (z1 - z0) * dx2) / ar * one;
        double m = fabs(gx) > fabs(gy) ? fabs(gx) : fabs(gy);
        t.depth_offset = dbl_to_i64(m * ctx->offset_factor + ctx->offset_units, -((int64_t)1 << 40), (int64_t)1 << 40);
    }
    t.tex_projective = 0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if ((ctx->tex_units_on & (1u << u)) && (a->tex[u][3] != NUM_ONE || b->tex[u][3] != NUM_ONE || c->tex[u][3] != NUM_ONE))
            t.tex_projective |= 1u << u;
    /* only the constant-colour spans read the packed colour */
    t.flat_packed = t.smooth ? 0 : packed_flat(ctx, t.flat);
    SpanFunc span = t.smooth ? ctx->span : ctx->span_const;
    if (nruns >= 0) {
        for (int r = 0; r < nruns; r++)
            if (raster_owns_row(ctx, runs[r][0]))
                span(ctx, &t, (int)runs[r][0], (int)runs[r][1], (int)(runs[r][2] - runs[r][1]));
        return;
    }

    /* Per edge, the row's bound is sign * floor(n / d) + bias with n linear
    ** in the row: one division at the first row, then exact stepping. */
    /* with threads, this thread's rows: from its first band in the box,
    ** band after band, the other threads' bands between (`skip` rows)
    ** stepped over at once */
    int64_t py = raster_next_owned_row(ctx, y0);
    const int64_t band_rows = ctx->band_count > 1 ? ctx->band_hi - ctx->band_lo : 0;
    const int64_t skip = ctx->band_count > 1 ? ctx->band_period - band_rows : 0;
    int64_t band_end = skip ? py - raster_band_phase(ctx, py) + ctx->band_hi : y1 + 1;
    EdgeStep st[3];
    EdgeJump jump[3];
    for (int i = 0; i < 3; i++) {
        step_init(&st[i], t.ea[i], t.eb[i], t.ec[i], tie[i], py);
        if (band_end + skip <= y1)
            jump_init(&jump[i], &st[i], skip);
    }
    for (; py <= y1; py++) {
        if (py == band_end) {
            py += skip;
            if (py > y1)
                break;
            for (int i = 0; i < 3; i++)
                step_jump(&st[i], &jump[i]);
            band_end = py + band_rows;
        }
        int64_t lo = cx0, hi = cx1; /* covered run is [lo, hi) */
        for (int i = 0; i < 3; i++) {
            const EdgeStep *e = &st[i];
            if (e->kind > 0) {
                int64_t m = e->sign * e->q + e->bias;
                if (m > lo) lo = m;
            } else if (e->kind < 0) {
                int64_t m = e->sign * e->q + e->bias;
                if (m < hi) hi = m;
            } else if (!(e->be > 0 || (e->be == 0 && e->tie))) {
                hi = lo; /* the row is outside a horizontal edge */
            }
        }
        for (int i = 0; i < 3; i++)
            step_next(&st[i]);
        if (drop_last && hi > lo)
            hi--;
        if (lo < hi)
            span(ctx, &t, (int)py, (int)lo, (int)(hi - lo));
    }
}

uint32_t raster_offset_depth(const GlesContext *ctx, const TriSetup *t, uint32_t z)
{
    if (!t->depth_offset)
        return z;
    /* clamp after the offset (§3.5.2) */
    return (uint32_t)i64_clamp((int64_t)z + t->depth_offset, 0, ctx->depth_max);
}

/* {====================================================================
** threads */

/* thread `index`'s bands of a job, into its context c (ctx itself for the
** caller): of each period of RASTER_BAND_ROWS x threads rows, the
** caller's band_caller_rows first, then the workers' in equal parts of the
** rest */
static void raster_band_take(const GlesContext *ctx, GlesContext *c, int index)
{
    const int period = RASTER_BAND_ROWS * ctx->threads, caller = ctx->band_caller_rows;
    const int rest = period - caller, workers = ctx->threads - 1;
    c->band_index = index;
    c->band_count = ctx->threads;
    c->band_period = period;
    c->band_lo = index ? caller + rest * (index - 1) / workers : 0;
    c->band_hi = index ? caller + rest * index / workers : caller;
}

/* worker i's copy of ctx for a draw: the state as it is, its own
** per-primitive caches (emptied) and scratch buffers, band i. The matrix
** stacks (modelview to the palette, two thirds of the context) are left
** out: they are vertex state, and rasterization reads none of them (in a
** worker they hold zeros, so a read would show in tests/test_threads.py) */
static void worker_prepare(const GlesContext *ctx, GlesContext *w, int index)
{
    void *fused = w->fused_setup, *tests = w->tests_setup, *persp = w->persp_setup;
    TEXC *rect_s = w->rect_s;
    const size_t skip0 = offsetof(GlesContext, modelview), skip1 = offsetof(GlesContext, current_palette),
                 tail = offsetof(GlesContext, unorm8);
    memcpy(w, ctx, skip0);
    memcpy((char *)w + skip1, (const char *)ctx + skip1, tail - skip1);
    w->fused_setup = fused;
    w->tests_setup = tests;
    w->persp_setup = persp;
    w->rect_s = rect_s;
    w->fused_serial = w->smooth_serial = w->tests_serial = w->persp_serial = 0;
    w->flat_cache_format = -1;
    w->pool = NULL;
    w->worker_ctx = NULL;
    w->draw_prims = NULL;
    w->draw_pend = NULL;
    w->draw_pendv = NULL;
    w->threads = 1;
    w->job_pending = 0;
    raster_band_take(ctx, w, index);
}

static void raster_job(void *arg, int index)
{
    GlesContext *ctx = arg;
    ctx->job_work(index ? ctx->worker_ctx[index - 1] : ctx, ctx->job_arg);
}

/* a draw sampling the texture it draws into (a framebuffer object's):
** undefined results, but threads would race on the texels (C11's data
** race), so it stays on one */
static int samples_own_target(const GlesContext *ctx)
{
    const Texture *t = fbo_color_texture(ctx);
    for (int u = 0; t && u < GLES_MAX_TEXTURE_UNITS; u++)
        if (ctx->units[u].enabled && (ctx->units[u].bound == t || ctx->units[u].bound == t->cube))
            return 1;
    return 0;
}

int raster_pool_take(GlesContext *ctx, int64_t amount, int64_t threshold)
{
    raster_join(ctx);
    return ctx->pool && amount > 0 && (amount >= threshold || (ctx->debug & GLES_DEBUG_THREADS_ALWAYS))
        && !samples_own_target(ctx) && pool_acquire(ctx->pool, ctx->threads);
}

/* the caller's rows of a period, moved towards the share at which the
** caller, back from its own rows and the commands since, finds the
** workers just done: each join of a draw's or DrawTex's job by the next
** one votes (workers still running: the caller had time to spare, and
** takes more; all done: they waited for it, and it takes fewer), and three
** votes more one way than the other move it a row, so it settles where the
** votes alternate; within a quarter band of each thread's even share.
** Other pairs would mislead: a Clear returns at once, a draw after it
** always finds it running */
static void raster_band_balance(GlesContext *ctx, int workers_were_running)
{
    const int even = RASTER_BAND_ROWS, lo = even - even / 4 * (ctx->threads > 2 ? 2 : 1), hi = even + even / 4;
    ctx->band_votes += workers_were_running ? 1 : -1;
    if (ctx->band_votes > -3 && ctx->band_votes < 3)
        return;
    const int rows = ctx->band_caller_rows + (ctx->band_votes > 0 ? 1 : -1);
    ctx->band_caller_rows = rows < lo ? lo : rows > hi ? hi : rows;
    ctx->band_votes = 0;
}

/* the wait of raster_join and raster_join_next, which votes where `vote` */
static void join(GlesContext *ctx, int vote)
{
    if (!ctx->job_pending)
        return;
    const int waited = pool_wait(ctx->pool, ctx->job_ticket);
    if (vote && ctx->job_votes)
        raster_band_balance(ctx, waited);
    ctx->job_pending = 0;
}

void raster_join(GlesContext *ctx) { join(ctx, 0); }
void raster_join_next(GlesContext *ctx) { join(ctx, 1); }

int raster_threaded(GlesContext *ctx, int64_t pixels, RasterWork work, const void *arg, size_t size, int votes)
{
    raster_join(ctx);       /* (also where the work then runs on this thread alone) */
    if (size > sizeof ctx->job_arg || !raster_pool_take(ctx, pixels, RASTER_THREADED_PIXELS))
        return 0;
    for (int i = 1; i < ctx->threads; i++)
        worker_prepare(ctx, ctx->worker_ctx[i - 1], i);
    /* the work's argument in the context: the workers read it after this returns */
    memcpy(ctx->job_arg, arg, size);
    ctx->job_work = work;
    ctx->job_votes = votes;
    raster_band_take(ctx, ctx, 0);
    ctx->job_ticket = pool_start(ctx->pool, raster_job, ctx, ctx->threads);
    ctx->band_count = 1;
    ctx->job_pending = 1;
    return 1;
}

/* }==================================================================== */
