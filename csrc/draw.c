/*
** draw.c -- DrawArrays and DrawElements: validation and primitive assembly
** (ES 1.1 §2.8, §2.6.1).
** Consumes: the arrays (array.c), vertex processing (vertex_batch.c, and
**       vertex.c for the reference path), clipping (clip.c) and the
**       rasterizer (raster.c).
** Order of work per draw: positions and clip codes of the draw's vertices
**       in batches (the contiguous range of DrawArrays; DrawElements' whole
**       index range when it is no larger than the index count, else the
**       referenced vertices, gathered once each through the post-transform
**       cache); then per primitive trivial reject and culling; surviving
**       primitives are queued and their vertices' attributes (lighting,
**       fog, texture coordinates) computed in batches, once per vertex,
**       before the queue is rasterized in order; clipping of the few that
**       cross a plane happens then.
** The reference path (GLES_DEBUG_VERTEX_REFERENCE) does the same per
** vertex, through stamps: a vertex whose stamp is base has its position,
** base + 1 also its attributes; base advances by 2 per draw, so the cache
** is never cleared.
** Points and lines are assembled and clipped here and rasterized by
** point.c and line.c.
*/
#include <stdlib.h>
#include <string.h>
#include "state.h"
#include "array.h"
#include "vertex.h"
#include "vertex_batch.h"
#include "clip.h"
#include "raster.h"
#include "point.h"
#include "line.h"
#include "range.h"
#include "fbo.h"

/* stamps: a vertex whose stamp is base has its position, base + 1 also its
** attributes; base advances by 2 per draw */
static int draw_begin(GlesContext *ctx, int64_t nverts)
{
    raster_join_next(ctx);  /* the last threaded draw's workers read the vertices */
    if (nverts > ctx->verts_capacity) {
        int64_t cap = ctx->verts_capacity ? ctx->verts_capacity : 1024;
        while (cap < nverts)
            cap *= 2;
        Vertex *v = malloc((size_t)cap * sizeof *v);
        uint32_t *s = calloc((size_t)cap, sizeof *s);
        if (!v || !s) {
            free(v);
            free(s);
            ctx_error(ctx, GL_OUT_OF_MEMORY);
            return ctx_message(ctx, GLES_EMEMORY, "no memory for %lld vertices", (long long)nverts);
        }
        free(ctx->verts);
        free(ctx->vert_stamp);
        ctx->verts = v;
        ctx->vert_stamp = s;
        ctx->verts_capacity = cap;
        ctx->draw_stamp = 0;
    }
    if (ctx->draw_stamp >= UINT32_MAX - 4) {
        memset(ctx->vert_stamp, 0, (size_t)ctx->verts_capacity * sizeof *ctx->vert_stamp);
        ctx->draw_stamp = 0;
    }
    ctx->draw_stamp += 2;
    return GLES_OK;
}

void draw_validate(GlesContext *ctx)
{
    if (ctx->dirty) {
        vertex_validate(ctx);
        if (ctx->dirty & (DIRTY_SPAN | DIRTY_TEXTURE))
            span_choose(ctx);
        ctx->dirty = 0;
    }
}

/* a primitive that survived rejection and culling, waiting for its
** vertices' attributes */
enum { PRIM_TRIANGLE, PRIM_LINE, PRIM_POINT };
typedef struct Prim {
    int64_t i[3];
    int64_t area2;       /* triangles inside every plane: the window area */
    unsigned int codes;  /* union of the vertices' clip codes */
    int kind;
} Prim;

#define DRAW_QUEUE 256

typedef struct Batch {
    GlesContext *ctx;
    int64_t base;        /* array index of cache slot 0 */
    int64_t last;        /* array index of the last slot */
    int visible;         /* viewport meets the framebuffer */
    int reference;       /* GLES_DEBUG_VERTEX_REFERENCE: per vertex */
    ClipRect clip;       /* the pixels fragments may reach */
    /* threaded: the queue's primitives go to ctx->draw_prims (ndeferred
    ** of them) after their attributes, rasterized once the draw's vertex
    ** work is done; `work` estimates their pixels */
    int deferred;
    int64_t ndeferred, work;
    int64_t npend_all;   /* threaded: vertices waiting in ctx->draw_pend */
    /* vertices waiting for attributes, and the primitives that use them */
    int npend, nprim;
    int64_t pend[VERTEX_BATCH];
    Vertex *pendv[VERTEX_BATCH];
    Prim prim[DRAW_QUEUE];
} Batch;

static Vertex *position(Batch *b, int64_t index)
{
    GlesContext *ctx = b->ctx;
    int64_t slot = index - b->base;
    Vertex *v = &ctx->verts[slot];
    if (ctx->vert_stamp[slot] < ctx->draw_stamp) {
        vertex_position(ctx, index, v);
        ctx->vert_stamp[slot] = ctx->draw_stamp;
    }
    return v;
}

static void attribs(Batch *b, int64_t index, Vertex *v)
{
    GlesContext *ctx = b->ctx;
    int64_t slot = index - b->base;
    if (ctx->vert_stamp[slot] != ctx->draw_stamp + 1) {
        vertex_attribs(ctx, index, v);
        ctx->vert_stamp[slot] = ctx->draw_stamp + 1;
    }
}

/* §3.5.1: facing from the sign of the window-space area */
static int is_front(const GlesContext *ctx, int64_t area2)
{
    return (area2 > 0) == (ctx->front_face == GL_CCW);
}

static int culled(const GlesContext *ctx, int64_t area2)
{
    if (!ctx->cull_enabled)
        return 0;
    if (ctx->cull_mode == GL_FRONT_AND_BACK)
        return 1;
    int front = is_front(ctx, area2);
    return ctx->cull_mode == GL_FRONT ? front : !front;
}

/* a line clipped against planes `codes` (none: as it is) and rasterised;
** Table 2.10: a line's provoking vertex is its second */
static void clipped_line(GlesContext *ctx, const Vertex *v0, const Vertex *v1, unsigned int codes)
{
    const Vertex *pa = v0, *pb = v1;
    Vertex scratch[CLIP_MAX_VERTS];
    if (codes && !clip_line(ctx, v0, v1, codes, &pa, &pb, scratch))
        return;
    if (pa->outcode & CLIP_NEW_VERTEX)
        vertex_window(ctx, (Vertex *)pa);
    if (pb->outcode & CLIP_NEW_VERTEX)
        vertex_window(ctx, (Vertex *)pb);
    raster_line(ctx, pa, pb, v1);
}

/* a triangle that crosses clip planes `codes`: clipped, then culled on the
** clipped polygon's area and rasterised as a fan (v2 provokes) */
static void clipped_triangle(GlesContext *ctx, const Vertex *v0, const Vertex *v1, const Vertex *v2,
                             unsigned int codes)
{
    const Vertex *in[3] = { v0, v1, v2 };
    const Vertex *poly[CLIP_MAX_VERTS];
    Vertex scratch[2 * CLIP_MAX_VERTS];
    int n = clip_polygon(ctx, in, 3, codes, poly, scratch);
    if (n < 3)
        return;
    /* an original vertex survives clipping only when it is inside every
    ** plane, so it has window coordinates; new ones (in scratch) need them */
    for (int i = 0; i < n; i++)
        if (poly[i]->outcode & CLIP_NEW_VERTEX)
            vertex_window(ctx, (Vertex *)poly[i]);
    int64_t area2 = 0, part[CLIP_MAX_VERTS];
    for (int i = 1; i + 1 < n; i++)
        area2 += part[i] = raster_area2(poly[0], poly[i], poly[i + 1]);
    if (area2 == 0 || culled(ctx, area2))
        return;
    for (int i = 1; i + 1 < n; i++)
        raster_triangle(ctx, poly[0], poly[i], poly[i + 1], part[i], v2, !is_front(ctx, area2));
}

static void triangle(Batch *b, int64_t i0, int64_t i1, int64_t i2)
{
    GlesContext *ctx = b->ctx;
    Vertex *v0 = position(b, i0), *v1 = position(b, i1), *v2 = position(b, i2);
    if (v0->outcode & v1->outcode & v2->outcode)
        return;
    unsigned int codes = v0->outcode | v1->outcode | v2->outcode;
    if (!codes) {
        int64_t area2 = raster_area2(v0, v1, v2);
        if (area2 == 0 || culled(ctx, area2))
            return;
        attribs(b, i0, v0);
        attribs(b, i1, v1);
        attribs(b, i2, v2);
        raster_triangle(ctx, v0, v1, v2, area2, v2, !is_front(ctx, area2));
        return;
    }
    attribs(b, i0, v0);
    attribs(b, i1, v1);
    attribs(b, i2, v2);
    clipped_triangle(ctx, v0, v1, v2, codes);
}

static void line(Batch *b, int64_t i0, int64_t i1)
{
    GlesContext *ctx = b->ctx;
    Vertex *v0 = position(b, i0), *v1 = position(b, i1);
    if (v0->outcode & v1->outcode)
        return;
    attribs(b, i0, v0);
    attribs(b, i1, v1);
    clipped_line(ctx, v0, v1, v0->outcode | v1->outcode);
}

static void point(Batch *b, int64_t i0)
{
    Vertex *v = position(b, i0);
    if (v->outcode)
        return;
    attribs(b, i0, v);
    raster_point(b->ctx, v);
}

/* {====================================================================
** the batched path */

static Vertex *slot_of(const Batch *b, int64_t index)
{
    return &b->ctx->verts[index - b->base];
}

/* rasterize a queued primitive on ctx (the draw's context or a worker's
** copy), the draw's cache slot 0 being array index base: its vertices
** have their attributes */
static void draw_prim(GlesContext *ctx, int64_t base, const Prim *p)
{
    Vertex *v0 = &ctx->verts[p->i[0] - base], *v1 = &ctx->verts[p->i[1] - base], *v2 = &ctx->verts[p->i[2] - base];
    switch (p->kind) {
    case PRIM_POINT:
        raster_point(ctx, v0);
        return;
    case PRIM_LINE:
        clipped_line(ctx, v0, v1, p->codes);
        return;
    default:
        break;
    }
    if (!p->codes) {
        raster_triangle(ctx, v0, v1, v2, p->area2, v2, !is_front(ctx, p->area2));
        return;
    }
    clipped_triangle(ctx, v0, v1, v2, p->codes);
}

/* {====================================================================
** threads: a draw's primitives rasterized by every thread of the pool,
** each on its bands of rows (raster_owns_row) */

/* A threaded draw's vertex work in slices of VERTEX_BATCH, each thread a
** contiguous share of them, all reading the draw's context (the batch
** functions write only the vertices they are given): positions of array
** indices first..first + n - 1, or the attributes of ctx->draw_pend[0..n) */
typedef struct VertexJob {
    GlesContext *ctx;
    int64_t base, first, n;
    int attribs;
} VertexJob;

static void vertex_slices(const VertexJob *j, int64_t s0, int64_t s1)
{
    GlesContext *ctx = j->ctx;
    int64_t idx[VERTEX_BATCH];
    for (int64_t s = s0; s < s1; s++) {
        const int64_t at = s * VERTEX_BATCH;
        const int n = j->n - at < VERTEX_BATCH ? (int)(j->n - at) : VERTEX_BATCH;
        if (j->attribs) {
            vertex_batch_attribs(ctx, (const int64_t *)ctx->draw_pend + at, (Vertex *const *)ctx->draw_pendv + at, n);
            continue;
        }
        for (int i = 0; i < n; i++)
            idx[i] = j->first + at + i;
        vertex_batch_positions(ctx, idx, n, ctx->verts, j->base);
    }
}

static void vertex_job(void *arg, int index)
{
    const VertexJob *j = arg;
    const int64_t slices = (j->n + VERTEX_BATCH - 1) / VERTEX_BATCH, t = j->ctx->threads;
    vertex_slices(j, slices * index / t, slices * (index + 1) / t);
}

/* below this many vertices a draw's vertex work stays on the calling thread */
#define DRAW_THREADED_VERTICES 1024

static void vertex_threaded(GlesContext *ctx, VertexJob *j)
{
    if (raster_pool_take(ctx, j->n, DRAW_THREADED_VERTICES)) {
        pool_run(ctx->pool, vertex_job, j, ctx->threads);
    } else {
        vertex_slices(j, 0, (j->n + VERTEX_BATCH - 1) / VERTEX_BATCH);
    }
}

/* n elements of `size` bytes from src put at index len of the growable
** array *arr of *cap elements; 0 (nothing changed) without memory */
static int append(void **arr, int64_t *cap, int64_t len, const void *src, int64_t n, size_t size)
{
    if (n == 0)
        return 1;   /* (memcpy takes no NULL, not even for nothing) */
    if (len + n > *cap) {
        int64_t c = *cap ? *cap : 1024;
        while (c < len + n)
            c *= 2;
        void *p = realloc(*arr, (size_t)c * size);
        if (!p)
            return 0;
        *arr = p;
        *cap = c;
    }
    memcpy((char *)*arr + (size_t)len * size, src, (size_t)n * size);
    return 1;
}

/* the waiting vertices appended to ctx->draw_pend; 0 where there is no
** memory for them (the caller computes their attributes itself) */
static int defer_pending(Batch *b)
{
    GlesContext *ctx = b->ctx;
    if (!append(&ctx->draw_pend, &ctx->draw_pend_cap, b->npend_all, b->pend, b->npend, sizeof b->pend[0])
        || !append(&ctx->draw_pendv, &ctx->draw_pendv_cap, b->npend_all, b->pendv, b->npend, sizeof b->pendv[0]))
        return 0;
    b->npend_all += b->npend;
    return 1;
}

typedef struct DrawJob {
    const Prim *prims;
    int64_t n, base;
} DrawJob;

static void draw_job(GlesContext *ctx, void *arg)
{
    const DrawJob *j = arg;
    for (int64_t i = 0; i < j->n; i++)
        draw_prim(ctx, j->base, &j->prims[i]);
}

/* the deferred primitives, in order: on every thread where they cover
** enough pixels, else on the calling thread */
static void draw_deferred(Batch *b)
{
    GlesContext *ctx = b->ctx;
    VertexJob vj = { ctx, b->base, 0, b->npend_all, 1 };
    vertex_threaded(ctx, &vj);
    b->npend_all = 0;
    const Prim *prims = ctx->draw_prims;
    DrawJob job = { prims, b->ndeferred, b->base };
    if (!raster_threaded(ctx, b->work, draw_job, &job, sizeof job, 1))
        draw_job(ctx, &job);
    b->ndeferred = 0;
    b->work = 0;
}

/* the queue appended to the deferred primitives; 0 where there is no
** memory for them (the caller rasterizes the queue itself) */
static int defer_queue(Batch *b)
{
    GlesContext *ctx = b->ctx;
    if (!append(&ctx->draw_prims, &ctx->draw_prims_cap, b->ndeferred, b->prim, b->nprim, sizeof b->prim[0]))
        return 0;
    b->ndeferred += b->nprim;
    return 1;
}

/* }==================================================================== */

/* attributes of the waiting vertices in one batch, then the queue in
** order (threaded: kept for draw_deferred) */
static void flush(Batch *b)
{
    if (b->npend && !(b->deferred && defer_pending(b)))
        vertex_batch_attribs(b->ctx, b->pend, b->pendv, b->npend);
    b->npend = 0;
    if (!b->deferred || !defer_queue(b)) {
        if (b->deferred) {
            draw_deferred(b);   /* no memory to keep the queue: what came before it first */
            raster_join(b->ctx);
        }
        for (int i = 0; i < b->nprim; i++)
            draw_prim(b->ctx, b->base, &b->prim[i]);
    }
    b->nprim = 0;
}

/* queue a surviving primitive of `nv` vertices; each vertex joins the
** waiting list once per draw (stamp base + 1) */
static void enqueue(Batch *b, int kind, int nv, int64_t i0, int64_t i1, int64_t i2, unsigned int codes,
                    int64_t area2)
{
    GlesContext *ctx = b->ctx;
    if (b->nprim == DRAW_QUEUE || b->npend + nv > VERTEX_BATCH)
        flush(b);
    Prim *p = &b->prim[b->nprim++];
    p->i[0] = i0;
    p->i[1] = i1;
    p->i[2] = i2;
    p->codes = codes;
    p->area2 = area2;
    p->kind = kind;
    for (int k = 0; k < nv; k++) {
        int64_t s = p->i[k] - b->base;
        if (ctx->vert_stamp[s] != ctx->draw_stamp + 1) {
            ctx->vert_stamp[s] = ctx->draw_stamp + 1;
            b->pend[b->npend] = p->i[k];
            b->pendv[b->npend++] = &ctx->verts[s];
        }
    }
}

/* trivial reject and culling on positions; survivors wait in the queue */
static void queue_triangle(Batch *b, int64_t i0, int64_t i1, int64_t i2)
{
    const Vertex *v0 = slot_of(b, i0), *v1 = slot_of(b, i1), *v2 = slot_of(b, i2);
    if (v0->outcode & v1->outcode & v2->outcode)
        return;
    unsigned int codes = v0->outcode | v1->outcode | v2->outcode;
    int64_t area2 = 0;
    if (!codes) {
        area2 = raster_area2(v0, v1, v2);
        ClipRect box;
        if (area2 == 0 || culled(b->ctx, area2) || !raster_centre_box(&b->clip, v0, v1, v2, &box))
            return;
        b->work += (box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
    } else {
        b->work += RASTER_THREADED_PIXELS;     /* it crosses a plane: likely large */
    }
    enqueue(b, PRIM_TRIANGLE, 3, i0, i1, i2, codes, area2);
}

static void queue_line(Batch *b, int64_t i0, int64_t i1)
{
    const Vertex *v0 = slot_of(b, i0), *v1 = slot_of(b, i1);
    if (v0->outcode & v1->outcode)
        return;
    b->work += 64;
    enqueue(b, PRIM_LINE, 2, i0, i1, i1, v0->outcode | v1->outcode, 0);
}

static void queue_point(Batch *b, int64_t i0)
{
    if (slot_of(b, i0)->outcode)
        return;
    b->work += 16;
    enqueue(b, PRIM_POINT, 1, i0, i0, i0, 0, 0);
}

/* positions of every vertex in lo..hi, in batches (threaded: on every
** thread, a share each) */
static void positions_range(Batch *b, int64_t lo, int64_t hi)
{
    VertexJob j = { b->ctx, b->base, lo, hi - lo + 1, 0 };
    if (b->deferred)
        vertex_threaded(b->ctx, &j);
    else
        vertex_slices(&j, 0, (j.n + VERTEX_BATCH - 1) / VERTEX_BATCH);
}

/* Assembly reads each vertex's clip codes and window position, long after
** the positions pass wrote them: a large indexed mesh's vertices (more
** than DRAW_PREFETCH_VERTICES, about 256 KiB) are no longer in the cache,
** so the triangle DRAW_PREFETCH ahead asks for them */
#define DRAW_PREFETCH 16
#define DRAW_PREFETCH_VERTICES 1200
static void prefetch_window(const Batch *b, int64_t index)
{
    __builtin_prefetch(&slot_of(b, index)->outcode, 0, 3);
}

/* the dispatch of assemble(): queue on the batched path, draw at once on
** the reference path */
static void emit_triangle(Batch *b, int64_t i0, int64_t i1, int64_t i2)
{
    if (b->reference)
        triangle(b, i0, i1, i2);
    else
        queue_triangle(b, i0, i1, i2);
}

static void emit_line(Batch *b, int64_t i0, int64_t i1)
{
    if (b->reference)
        line(b, i0, i1);
    else
        queue_line(b, i0, i1);
}

static void emit_point(Batch *b, int64_t i0)
{
    if (b->reference)
        point(b, i0);
    else
        queue_point(b, i0);
}

/* index source: either a range or an index array */
typedef struct Indices {
    const uint8_t *p;    /* NULL: element i is first + i */
    unsigned int type;
    int64_t first;
} Indices;

static int64_t index_at(const Indices *ix, int64_t i)
{
    if (!ix->p)
        return ix->first + i;
    if (ix->type == GL_UNSIGNED_BYTE)
        return ix->p[i];
    if (ix->type == GL_UNSIGNED_INT) {
        /* OES_element_index_uint */
        uint32_t v;
        memcpy(&v, ix->p + 4 * i, 4);
        return v;
    }
    uint16_t v;
    memcpy(&v, ix->p + 2 * i, 2);
    return v;
}

/* positions of the vertices an index array references, each once: the
** indices are walked and the first sight of each vertex (its stamp still
** below base) joins a batch */
static void positions_indexed(Batch *b, int count, const Indices *ix)
{
    GlesContext *ctx = b->ctx;
    int64_t idx[VERTEX_BATCH];
    int n = 0;
    for (int i = 0; i < count; i++) {
        int64_t v = index_at(ix, i);
        int64_t s = v - b->base;
        if (ctx->vert_stamp[s] >= ctx->draw_stamp)
            continue;
        ctx->vert_stamp[s] = ctx->draw_stamp;
        idx[n++] = v;
        if (n == VERTEX_BATCH) {
            vertex_batch_positions(ctx, idx, n, ctx->verts, b->base);
            n = 0;
        }
    }
    if (n)
        vertex_batch_positions(ctx, idx, n, ctx->verts, b->base);
}

static void assemble(Batch *b, unsigned int mode, int count, const Indices *ix)
{
    if (!b->visible)
        return;
    if (!b->reference) {
        if (!ix->p)
            positions_range(b, ix->first, ix->first + count - 1);
        else if (b->last - b->base + 1 <= count)
            positions_range(b, b->base, b->last);
        else
            positions_indexed(b, count, ix);
    }
    const int far = !b->reference && b->last - b->base + 1 > DRAW_PREFETCH_VERTICES;
    switch (mode) {
    case GL_POINTS:
        for (int i = 0; i < count; i++)
            emit_point(b, index_at(ix, i));
        break;
    case GL_LINES:
        for (int i = 0; i + 1 < count; i += 2)
            emit_line(b, index_at(ix, i), index_at(ix, i + 1));
        break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
        for (int i = 0; i + 1 < count; i++)
            emit_line(b, index_at(ix, i), index_at(ix, i + 1));
        if (mode == GL_LINE_LOOP && count > 1)
            emit_line(b, index_at(ix, count - 1), index_at(ix, 0));
        break;
    case GL_TRIANGLES:
        for (int i = 0; i + 2 < count; i += 3) {
            if (far && i + 3 * DRAW_PREFETCH + 2 < count)
                for (int k = 0; k < 3; k++)
                    prefetch_window(b, index_at(ix, i + 3 * DRAW_PREFETCH + k));
            emit_triangle(b, index_at(ix, i), index_at(ix, i + 1), index_at(ix, i + 2));
        }
        break;
    case GL_TRIANGLE_STRIP:
        /* Table 2.10: the provoking vertex is i + 2; odd triangles swap the
        ** first two to keep a consistent winding */
        for (int i = 0; i + 2 < count; i++) {
            if (i & 1)
                emit_triangle(b, index_at(ix, i + 1), index_at(ix, i), index_at(ix, i + 2));
            else
                emit_triangle(b, index_at(ix, i), index_at(ix, i + 1), index_at(ix, i + 2));
        }
        break;
    case GL_TRIANGLE_FAN:
        for (int i = 1; i + 1 < count; i++)
            emit_triangle(b, index_at(ix, 0), index_at(ix, i), index_at(ix, i + 1));
        break;
    default:
        break;
    }
    if (!b->reference) {
        flush(b);
        if (b->deferred)
            draw_deferred(b);
    }
}

static int mode_ok(unsigned int mode) { return mode <= GL_TRIANGLE_FAN; }

static int viewport_visible(const GlesContext *ctx)
{
    const int *vp = ctx->viewport;
    return vp[2] > 0 && vp[3] > 0 && (int64_t)vp[0] < ctx->width && (int64_t)vp[0] + vp[2] > 0
        && (int64_t)vp[1] < ctx->height && (int64_t)vp[1] + vp[3] > 0;
}

/* OES_matrix_palette: nothing is drawn without both palette arrays, and
** every matrix index a draw reads must name a palette matrix */
static int palette_check(GlesContext *ctx, int64_t lo, int64_t hi, int *skip)
{
    *skip = 0;
    if (!ctx->matrix_palette)
        return GLES_OK;
    const ArrayState *ia = &ctx->arrays[ARR_MATRIX_INDEX];
    if (!ia->enabled || !ctx->arrays[ARR_WEIGHT].enabled) {
        *skip = 1;
        return GLES_OK;
    }
    const uint8_t *base = array_base(ia);
    for (int64_t i = lo; i <= hi; i++) {
        const uint8_t *p = base + i * ia->step;
        for (int k = 0; k < ia->size; k++)
            if (p[k] >= GLES_MAX_PALETTE_MATRICES)
                return ctx_message(ctx, GLES_EVALUE, "matrix index %d of vertex %lld exceeds MAX_PALETTE_MATRICES_OES - 1 (%d)",
                                   p[k], (long long)i, GLES_MAX_PALETTE_MATRICES - 1);
    }
    return GLES_OK;
}

/* the per-draw state, without clearing the queue's storage */
static void batch_init(Batch *b, GlesContext *ctx, int64_t base, int64_t last)
{
    b->ctx = ctx;
    b->base = base;
    b->last = last;
    b->visible = viewport_visible(ctx);
    b->reference = (ctx->debug & GLES_DEBUG_VERTEX_REFERENCE) != 0;
    b->clip = raster_clip_rect(ctx);
    b->npend = 0;
    b->nprim = 0;
    b->deferred = ctx->pool != NULL && !b->reference;
    b->ndeferred = 0;
    b->work = 0;
    b->npend_all = 0;
}

int gles_DrawArrays(GlesContext *ctx, unsigned int mode, int first, int count)
{
    if (!mode_ok(mode)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return GLES_OK;
    }
    if (first < 0 || count < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (count == 0 || !ctx->arrays[ARR_VERTEX].enabled)
        return GLES_OK;
    if (array_reads_mapped(ctx, 0)) {
        ctx_error(ctx, GL_INVALID_OPERATION);   /* a mapped buffer is the client's */
        return GLES_OK;
    }
    if (!fbo_sync(ctx))
        return GLES_OK;
    int st = array_check_range(ctx, (int64_t)first + count - 1);
    if (st != GLES_OK)
        return st;
    int skip;
    if ((st = palette_check(ctx, first, (int64_t)first + count - 1, &skip)) != GLES_OK || skip)
        return st;
    int range = ctx->range_mode ? range_check_draw(ctx, first, (int64_t)first + count - 1) : GLES_OK;
    if (range && ctx->range_mode == GLES_RANGE_SKIP)
        return range;
    if ((st = draw_begin(ctx, count)) != GLES_OK)
        return st;
    draw_validate(ctx);
    Batch b;
    batch_init(&b, ctx, first, (int64_t)first + count - 1);
    Indices ix = { NULL, 0, first };
    assemble(&b, mode, count, &ix);
    return range;
}

int gles_DrawElements(GlesContext *ctx, unsigned int mode, int count, unsigned int type,
                      const void *indices, int64_t nbytes)
{
    if (!mode_ok(mode) || (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return GLES_OK;
    }
    if (count < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (count == 0 || !ctx->arrays[ARR_VERTEX].enabled)
        return GLES_OK;
    if (array_reads_mapped(ctx, 1)) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return GLES_OK;
    }
    if (!fbo_sync(ctx))
        return GLES_OK;
    int isize = type == GL_UNSIGNED_BYTE ? 1 : (type == GL_UNSIGNED_SHORT ? 2 : 4);
    int64_t need = (int64_t)count * isize;
    const uint8_t *p;
    if (ctx->element_buffer) {
        BufferObject *eb = ctx->element_buffer;
        uintptr_t off = (uintptr_t)indices;
        if (!eb->data || off > (uint64_t)eb->size || need > eb->size - (int64_t)off)
            return ctx_message(ctx, GLES_EVALUE,
                               "the draw reads %lld index bytes from offset %llu of buffer %u, which holds %lld",
                               (long long)need, (unsigned long long)off, eb->name, (long long)eb->size);
        p = eb->data + off;
    } else {
        if (!indices)
            return ctx_message(ctx, GLES_EVALUE, "no index array");
        if (nbytes >= 0 && need > nbytes)
            return ctx_message(ctx, GLES_EVALUE, "the index array holds %lld bytes, the draw reads %lld",
                               (long long)nbytes, (long long)need);
        p = indices;
    }
    Indices ix = { p, type, 0 };
    int64_t lo = INT64_MAX, hi = -1;
    for (int i = 0; i < count; i++) {
        int64_t v = index_at(&ix, i);
        if (v < lo) lo = v;
        if (v > hi) hi = v;
    }
    int st = array_check_range(ctx, hi);
    if (st != GLES_OK)
        return st;
    int skip;
    if ((st = palette_check(ctx, lo, hi, &skip)) != GLES_OK || skip)
        return st;
    int range = ctx->range_mode ? range_check_draw(ctx, lo, hi) : GLES_OK;
    if (range && ctx->range_mode == GLES_RANGE_SKIP)
        return range;
    if ((st = draw_begin(ctx, hi - lo + 1)) != GLES_OK)
        return st;
    draw_validate(ctx);
    Batch b;
    batch_init(&b, ctx, lo, hi);
    assemble(&b, mode, count, &ix);
    return range;
}
