/*
** draw.c -- DrawArrays and DrawElements: validation and primitive assembly
** (ES 1.1 §2.8, §2.6.1).
** Consumes: the arrays (array.c), vertex processing (vertex.c), clipping
**       (clip.c) and the rasterizer (raster.c).
** Order of work per draw: positions of every referenced vertex once
**       (a post-transform cache indexed by vertex number, with stamps so it
**       is never cleared); then per primitive trivial reject and culling;
**       then attributes only for vertices of primitives that survive; then
**       clipping of the few that cross a plane, and rasterization.
** Points and lines are assembled and clipped here and rasterized by
** point.c and line.c.
*/
#include <stdlib.h>
#include <string.h>
#include "state.h"
#include "array.h"
#include "vertex.h"
#include "clip.h"
#include "raster.h"
#include "point.h"
#include "line.h"
#include "range.h"

/* stamps: a vertex whose stamp is base has its position, base + 1 also its
** attributes; base advances by 2 per draw */
static int draw_begin(GlesContext *ctx, int64_t nverts)
{
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

typedef struct Batch {
    GlesContext *ctx;
    int64_t base;        /* array index of cache slot 0 */
    int visible;         /* viewport meets the framebuffer */
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
        raster_triangle(ctx, v0, v1, v2, v2, !is_front(ctx, area2));
        return;
    }
    attribs(b, i0, v0);
    attribs(b, i1, v1);
    attribs(b, i2, v2);
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
    int64_t area2 = 0;
    for (int i = 1; i + 1 < n; i++)
        area2 += raster_area2(poly[0], poly[i], poly[i + 1]);
    if (area2 == 0 || culled(ctx, area2))
        return;
    for (int i = 1; i + 1 < n; i++)
        raster_triangle(ctx, poly[0], poly[i], poly[i + 1], v2, !is_front(ctx, area2));
}

static void line(Batch *b, int64_t i0, int64_t i1)
{
    GlesContext *ctx = b->ctx;
    Vertex *v0 = position(b, i0), *v1 = position(b, i1);
    if (v0->outcode & v1->outcode)
        return;
    attribs(b, i0, v0);
    attribs(b, i1, v1);
    const Vertex *pa = v0, *pb = v1;
    Vertex scratch[CLIP_MAX_VERTS];
    unsigned int codes = v0->outcode | v1->outcode;
    if (codes && !clip_line(ctx, v0, v1, codes, &pa, &pb, scratch))
        return;
    if (pa->outcode & CLIP_NEW_VERTEX)
        vertex_window(ctx, (Vertex *)pa);
    if (pb->outcode & CLIP_NEW_VERTEX)
        vertex_window(ctx, (Vertex *)pb);
    /* Table 2.10: a line's provoking vertex is its second */
    raster_line(ctx, pa, pb, v1);
}

static void point(Batch *b, int64_t i0)
{
    Vertex *v = position(b, i0);
    if (v->outcode)
        return;
    attribs(b, i0, v);
    raster_point(b->ctx, v);
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
    uint16_t v;
    memcpy(&v, ix->p + 2 * i, 2);
    return v;
}

static void assemble(Batch *b, unsigned int mode, int count, const Indices *ix)
{
    if (!b->visible)
        return;
    switch (mode) {
    case GL_POINTS:
        for (int i = 0; i < count; i++)
            point(b, index_at(ix, i));
        break;
    case GL_LINES:
        for (int i = 0; i + 1 < count; i += 2)
            line(b, index_at(ix, i), index_at(ix, i + 1));
        break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
        for (int i = 0; i + 1 < count; i++)
            line(b, index_at(ix, i), index_at(ix, i + 1));
        if (mode == GL_LINE_LOOP && count > 1)
            line(b, index_at(ix, count - 1), index_at(ix, 0));
        break;
    case GL_TRIANGLES:
        for (int i = 0; i + 2 < count; i += 3)
            triangle(b, index_at(ix, i), index_at(ix, i + 1), index_at(ix, i + 2));
        break;
    case GL_TRIANGLE_STRIP:
        /* Table 2.10: the provoking vertex is i + 2; odd triangles swap the
        ** first two to keep a consistent winding */
        for (int i = 0; i + 2 < count; i++) {
            if (i & 1)
                triangle(b, index_at(ix, i + 1), index_at(ix, i), index_at(ix, i + 2));
            else
                triangle(b, index_at(ix, i), index_at(ix, i + 1), index_at(ix, i + 2));
        }
        break;
    case GL_TRIANGLE_FAN:
        for (int i = 1; i + 1 < count; i++)
            triangle(b, index_at(ix, 0), index_at(ix, i), index_at(ix, i + 1));
        break;
    default:
        break;
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
    Batch b = { ctx, first, viewport_visible(ctx) };
    Indices ix = { NULL, 0, first };
    assemble(&b, mode, count, &ix);
    return range;
}

int gles_DrawElements(GlesContext *ctx, unsigned int mode, int count, unsigned int type,
                      const void *indices, int64_t nbytes)
{
    if (!mode_ok(mode) || (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return GLES_OK;
    }
    if (count < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (count == 0 || !ctx->arrays[ARR_VERTEX].enabled)
        return GLES_OK;
    int isize = type == GL_UNSIGNED_BYTE ? 1 : 2;
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
    Batch b = { ctx, lo, viewport_visible(ctx) };
    assemble(&b, mode, count, &ix);
    return range;
}
