/*
** span_chain.c -- the fragment stage as a chain of span-wide stages.
** Consumes: a TriSetup and a covered run of one row (from raster.c).
** Produces: the same framebuffer writes as span_generic, bit for bit.
**
** A run is cut into chunks of SPAN_CHUNK pixels. Each chunk flows through
** the stages span_chain_compose picked from the enabled state only: the
** depth and stencil tests (before any colour work when nothing later can
** discard the fragment, else after the alpha test), weights, colour, one
** fetch per enabled texture unit, one environment per unit, fog, alpha
** test, and the write (blend, dither, logic op, masks). Every stage is a
** loop over the chunk's live fragments; the tests compact the list. The
** arithmetic is the generic path's own functions, called in the same order
** per fragment, so the images are identical: what goes is the per-fragment
** state dispatch, and the colour work for fragments that fail the tests.
*/
#include "span.h"
#include "fragment.h"
#include "texture.h"

/* the edge values of the chunk's pixel at offset k */
static inline void chunk_edges(const TriSetup *t, const SpanBuf *b, int k, int64_t e[3])
{
    for (int i = 0; i < 3; i++)
        e[i] = b->e0[i] + t->ea[i] * k;
}

/* {====================================================================
** weights */

static void stage_persp(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)ctx;
    for (int j = 0; j < b->n; j++) {
        int64_t e[3];
        chunk_edges(t, b, b->k[j], e);
        wgt_persp(&t->wgt, e, b->p[j]);
    }
}

/* the right and upper neighbours' weights, shared by every unit whose
** filter needs a level of detail */
static void stage_neighbours(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)ctx;
    for (int j = 0; j < b->n; j++) {
        int64_t e[3];
        chunk_edges(t, b, b->k[j], e);
        int64_t ex[3] = { e[0] + t->ea[0], e[1] + t->ea[1], e[2] + t->ea[2] };
        int64_t ey[3] = { e[0] + t->eb[0], e[1] + t->eb[1], e[2] + t->eb[2] };
        wgt_persp_any(&t->wgt, ex, b->px[j]);
        wgt_persp_any(&t->wgt, ey, b->py[j]);
    }
}

/* }==================================================================== */

/* {====================================================================
** depth, stencil (§4.1.5, §4.1.6) */

/* every live fragment's window depth, with polygon offset */
static void stage_depth(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    for (int j = 0; j < b->n; j++) {
        int64_t e[3];
        chunk_edges(t, b, b->k[j], e);
        WGT l[3];
        wgt_linear(&t->wgt, e, l);
        uint32_t z = wgt_depth3(t->v[0]->wz, t->v[1]->wz, t->v[2]->wz, l[0], l[1], l[2], ctx->depth_max);
        b->z[j] = raster_offset_depth(ctx, t, z);
    }
}

/* keep the fragments at slots where keep[j]; c moves with them once the
** colour is computed */
static void chunk_compact(SpanBuf *b, const uint8_t *keep, int with_color)
{
    int m = 0;
    for (int j = 0; j < b->n; j++) {
        if (!keep[j])
            continue;
        b->k[m] = b->k[j];
        if (with_color && m != j)
            for (int i = 0; i < 4; i++)
                b->c[m][i] = b->c[j][i];
        m++;
    }
    b->n = m;
}

static void tests(GlesContext *ctx, SpanBuf *b, int with_color)
{
    const size_t row = (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    uint8_t keep[SPAN_CHUNK];
    for (int j = 0; j < b->n; j++)
        keep[j] = (uint8_t)fragment_tests(ctx, row + b->k[j], b->z[j]);
    chunk_compact(b, keep, with_color);
}

static void stage_tests_early(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { (void)t; tests(ctx, b, 0); }
static void stage_tests_late(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { (void)t; tests(ctx, b, 1); }

/* depth LESS with writes and no stencil: the common case, without the
** per-fragment switches */
static void stage_zless_early(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint32_t *zb = ctx->depth + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    int m = 0;
    for (int j = 0; j < b->n; j++) {
        const int k = b->k[j];
        uint32_t z = b->z[j];
        if (z < zb[k]) {
            zb[k] = z;
            b->k[m++] = (uint8_t)k;
        }
    }
    b->n = m;
}

/* }==================================================================== */

/* {====================================================================
** colour, texturing, fog, alpha test */

static void stage_color(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    const int texturing = ctx->tex_units_on != 0;
    for (int j = 0; j < b->n; j++) {
        FRAGV *c = b->c[j];
        if (t->smooth) {
            const WGT *p = b->p[j];
            for (int i = 0; i < 4; i++)
                c[i] = frag_lerp3f(t->col[0][i], t->col[1][i], t->col[2][i], p[0], p[1], p[2]);
        } else {
            for (int i = 0; i < 4; i++)
                c[i] = t->flat[i];
        }
        if (texturing)
            for (int i = 0; i < 4; i++)
                b->cf[j][i] = c[i] = frag_clamp01(c[i]);
    }
}

/* one unit's texels for the chunk's coordinates b->tc (and b->tx, b->ty) */
static void chunk_sample(GlesContext *ctx, SpanBuf *b, int u)
{
    ctx->samplers[u](ctx->units[u].bound, b->n, b->tc, b->tx, b->ty, b->ct[0][u], GLES_MAX_TEXTURE_UNITS * 4,
                     ctx->texel_unorm8);
}

/* a triangle's coordinates of unit u for every live fragment, then its texels */
static void stage_fetch(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int u)
{
    for (int j = 0; j < b->n; j++)
        span_tex_coord(t, u, b->p[j], &b->tc[j]);
    if (texture_needs_lod(ctx->units[u].bound))
        for (int j = 0; j < b->n; j++) {
            span_tex_coord(t, u, b->px[j], &b->tx[j]);
            span_tex_coord(t, u, b->py[j], &b->ty[j]);
        }
    chunk_sample(ctx, b, u);
}

/* a rectangle's coordinates of unit u for every live fragment, then its texels */
static void stage_fetch_rect(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int u)
{
    (void)t;
    const RectSetup *r = b->rect;
    switch (r->coord[u]) {
    case RECT_COORD_LINEAR:
        for (int j = 0; j < b->n; j++)
            rect_linear_coords(r, u, b->x0 + b->k[j], b->y, &b->tc[j], &b->tx[j], &b->ty[j]);
        break;
    case RECT_COORD_SPRITE:
        for (int j = 0; j < b->n; j++)
            sprite_coords(r->sprite_x, r->sprite_y, r->sprite_size, b->x0 + b->k[j], b->y, &b->tc[j], &b->tx[j],
                          &b->ty[j]);
        break;
    default:
        for (int j = 0; j < b->n; j++) {
            b->tc[j] = r->in.tc[u];
            b->tx[j] = r->in.tdx[u];
            b->ty[j] = r->in.tdy[u];
        }
        break;
    }
    chunk_sample(ctx, b, u);
}

static void stage_env(GlesContext *ctx, SpanBuf *b, int u)
{
    const TexUnit *tu = &ctx->units[u];
    const unsigned int fmt = tu->bound->format;
    /* texture_env's REPLACE and MODULATE of RGBA and RGB textures, inline
    ** (an RGB texture leaves the alpha as it is) */
    const int k1 = fmt == GL_RGBA ? 4 : 3;
    if (tu->env_mode == GL_MODULATE && (fmt == GL_RGBA || fmt == GL_RGB)) {
        for (int j = 0; j < b->n; j++)
            for (int i = 0; i < k1; i++)
                b->c[j][i] = frag_mul(b->c[j][i], b->ct[j][u][i]);
        return;
    }
    if (tu->env_mode == GL_REPLACE && (fmt == GL_RGBA || fmt == GL_RGB)) {
        for (int j = 0; j < b->n; j++)
            for (int i = 0; i < k1; i++)
                b->c[j][i] = b->ct[j][u][i];
        return;
    }
    texture_env_span(ctx, u, b->n, (const FRAGV (*)[4])b->cf, b->ct, b->c);
}

#define UNIT_STAGES(u) \
    static void stage_fetch##u(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { stage_fetch(ctx, t, b, u); } \
    static void stage_fetch_rect##u(GlesContext *ctx, const TriSetup *t, SpanBuf *b) \
    { \
        stage_fetch_rect(ctx, t, b, u); \
    } \
    static void stage_env##u(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { (void)t; stage_env(ctx, b, u); }
UNIT_STAGES(0)
UNIT_STAGES(1)
UNIT_STAGES(2)
UNIT_STAGES(3)
#undef UNIT_STAGES

static const SpanStage fetch_stages[GLES_MAX_TEXTURE_UNITS] = { stage_fetch0, stage_fetch1, stage_fetch2, stage_fetch3 };
static const SpanStage fetch_rect_stages[GLES_MAX_TEXTURE_UNITS] = {
    stage_fetch_rect0, stage_fetch_rect1, stage_fetch_rect2, stage_fetch_rect3,
};
static const SpanStage env_stages[GLES_MAX_TEXTURE_UNITS] = { stage_env0, stage_env1, stage_env2, stage_env3 };

/* fog (§3.8) with the factor interpolated, or from the interpolated distance */
static void stage_fog(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    FRAGV fc[3];
    fragment_fog_color(ctx, fc);
    for (int j = 0; j < b->n; j++) {
        const WGT *p = b->p[j];
        FRAGV f = ctx->fog_per_fragment
                      ? frag_from_num(fog_factor(ctx, wgt_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2])))
                      : frag_clamp01(frag_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2]));
        fragment_fog(b->c[j], f, fc);
    }
}

/* fog with one factor for the whole rectangle */
static void stage_fog_const(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    FRAGV fc[3];
    fragment_fog_color(ctx, fc);
    for (int j = 0; j < b->n; j++)
        fragment_fog(b->c[j], b->rect->in.fog, fc);
}

static void stage_alpha(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint8_t keep[SPAN_CHUNK];
    for (int j = 0; j < b->n; j++)
        keep[j] = (uint8_t)fragment_alpha_pass(ctx, b->c[j][3]);
    chunk_compact(b, keep, 1);
}

/* }==================================================================== */

/* {====================================================================
** the write: blending, dither, logic op, masks (§4.1.7-4.1.10) */

/* every state: fragment_process's tail */
static void stage_write(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    const size_t row = (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    FragWrite w;
    fragment_write_setup(ctx, &w);
    for (int j = 0; j < b->n; j++)
        fragment_write(ctx, &w, b->x0 + b->k[j], b->y, row + b->k[j], b->c[j]);
}

/* RGBA8888, every channel written, no blend or logic op */
static void stage_write_rgba8(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    for (int j = 0; j < b->n; j++) {
        const FRAGV *c = b->c[j];
        dst[b->k[j]] = frag_to_unorm(c[0], 255, FRAG_ONE / 2) | (frag_to_unorm(c[1], 255, FRAG_ONE / 2) << 8)
                     | (frag_to_unorm(c[2], 255, FRAG_ONE / 2) << 16) | (frag_to_unorm(c[3], 255, FRAG_ONE / 2) << 24);
    }
}

/* RGBA8888, every channel written, SRC_ALPHA, ONE_MINUS_SRC_ALPHA with
** FUNC_ADD (fragment_blend's arithmetic for those factors) */
static void stage_write_rgba8_alpha(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    for (int j = 0; j < b->n; j++) {
        const FRAGV *c = b->c[j];
        uint32_t d = dst[b->k[j]], out = 0;
        FRAGV sa = frag_clamp01(c[3]), da = FRAG_ONE - sa;
        for (int i = 0; i < 4; i++) {
            FRAGV v = frag_mul(frag_clamp01(c[i]), sa) + frag_mul(ctx->unorm8[(d >> (8 * i)) & 0xFFu], da);
            out |= frag_to_unorm(v, 255, FRAG_ONE / 2) << (8 * i);
        }
        dst[b->k[j]] = out;
    }
}

/* RGBA8888, every channel written, ONE, ONE with FUNC_ADD */
static void stage_write_rgba8_add(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint32_t *dst = (uint32_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    for (int j = 0; j < b->n; j++) {
        const FRAGV *c = b->c[j];
        uint32_t d = dst[b->k[j]], out = 0;
        for (int i = 0; i < 4; i++) {
            FRAGV v = frag_mul(frag_clamp01(c[i]), FRAG_ONE) + frag_mul(ctx->unorm8[(d >> (8 * i)) & 0xFFu], FRAG_ONE);
            out |= frag_to_unorm(v, 255, FRAG_ONE / 2) << (8 * i);
        }
        dst[b->k[j]] = out;
    }
}

/* RGB565 with red, green and blue written, dithered or not (fragment_write's
** conversion for these states) */
static inline uint32_t pack565(const FRAGV v[3], int dither, FRAGV t_d)
{
    return (fragment_channel(v[0], 5, dither, t_d) << 11) | (fragment_channel(v[1], 6, dither, t_d) << 5)
         | fragment_channel(v[2], 5, dither, t_d);
}

/* RGB565, red, green and blue written, no blend or logic op */
static void stage_write_565(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint16_t *dst = (uint16_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    const int dither = ctx->dither;
    for (int j = 0; j < b->n; j++) {
        FRAGV t_d = dither ? fragment_dither_threshold(b->x0 + b->k[j], b->y) : FRAG_ONE / 2;
        dst[b->k[j]] = (uint16_t)pack565(b->c[j], dither, t_d);
    }
}

/* RGB565, red, green and blue written, SRC_ALPHA, ONE_MINUS_SRC_ALPHA with
** FUNC_ADD (fragment_blend's arithmetic for those factors) */
static void stage_write_565_alpha(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    uint16_t *dst = (uint16_t *)ctx->color + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    const int dither = ctx->dither;
    for (int j = 0; j < b->n; j++) {
        const FRAGV *c = b->c[j];
        uint32_t d = dst[b->k[j]];
        FRAGV sa = frag_clamp01(c[3]), da = FRAG_ONE - sa;
        FRAGV dv[3] = { ctx->unorm5[d >> 11], ctx->unorm6[(d >> 5) & 63], ctx->unorm5[d & 31] };
        FRAGV v[3];
        for (int i = 0; i < 3; i++)
            v[i] = frag_mul(frag_clamp01(c[i]), sa) + frag_mul(dv[i], da);
        FRAGV t_d = dither ? fragment_dither_threshold(b->x0 + b->k[j], b->y) : FRAG_ONE / 2;
        dst[b->k[j]] = (uint16_t)pack565(v, dither, t_d);
    }
}

/* }==================================================================== */

/* {====================================================================
** composition and the driver */

/* which blend the RGBA8888 writers cover: 0 none, 1 alpha, 2 additive, -1 other */
int span_blend_kind(const GlesContext *ctx)
{
    if (!ctx->blend || ctx->color_logic_op)
        return 0;
    if (ctx->blend_eq_rgb != GL_FUNC_ADD_OES || ctx->blend_eq_alpha != GL_FUNC_ADD_OES)
        return -1;
    unsigned int s = ctx->blend_src_rgb, d = ctx->blend_dst_rgb;
    if (ctx->blend_src_alpha != s || ctx->blend_dst_alpha != d)
        return -1;
    if (s == GL_SRC_ALPHA && d == GL_ONE_MINUS_SRC_ALPHA)
        return 1;
    if (s == GL_ONE && d == GL_ONE)
        return 2;
    return -1;
}

/* a rectangle's constant inputs for the chunk's slots (its first stage, so
** every later slot a fragment can move to is among them) */
static void stage_rect_source(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    (void)t;
    const FragIn *in = &b->rect->in;
    const int texturing = ctx->tex_units_on != 0;
    for (int j = 0; j < b->n; j++) {
        b->z[j] = in->z;
        for (int i = 0; i < 4; i++)
            b->c[j][i] = texturing ? frag_clamp01(in->c[i]) : in->c[i];
        if (texturing)
            for (int i = 0; i < 4; i++)
                b->cf[j][i] = b->c[j][i];
    }
}

/* the stages for the current state into s, for rectangles (rect) or
** triangles; returns their number */
static int compose(GlesContext *ctx, SpanStage *s, int rect)
{
    int n = 0;
    const unsigned int units = ctx->tex_units_on;
    const int stencil = ctx->stencil_test && ctx->stencil;
    const int depth = ctx->depth_test && ctx->depth;
    const int tests = stencil || depth;
    const int zless = depth && !stencil && ctx->depth_func == GL_LESS && ctx->depth_mask;
    /* the tests may run first when nothing after them can discard */
    const int early = !ctx->alpha_test;
    int lod = 0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (units & (1u << u)) {
            lod |= texture_needs_lod(ctx->units[u].bound);
            ctx->samplers[u] = texture_span_sampler(ctx->units[u].bound);
        }
    if (rect)
        s[n++] = stage_rect_source;
    if (tests && early) {
        if (!rect)
            s[n++] = stage_depth;
        s[n++] = zless ? stage_zless_early : stage_tests_early;
    }
    if (!rect) {
        s[n++] = stage_persp;
        if (lod)
            s[n++] = stage_neighbours;
        s[n++] = stage_color;
    }
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (units & (1u << u))
            s[n++] = rect ? fetch_rect_stages[u] : fetch_stages[u];
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (units & (1u << u))
            s[n++] = env_stages[u];
    if (ctx->fog)
        s[n++] = rect ? stage_fog_const : stage_fog;
    if (ctx->alpha_test)
        s[n++] = stage_alpha;
    if (tests && !early) {
        if (!rect)
            s[n++] = stage_depth;
        s[n++] = stage_tests_late;
    }
    const int bk = span_blend_kind(ctx);
    const int plain = ctx->color_format == GLES_COLOR_RGBA8888 && ctx->color_mask[0] && ctx->color_mask[1]
                   && ctx->color_mask[2] && ctx->color_mask[3];
    const int plain565 = ctx->color_format == GLES_COLOR_RGB565 && ctx->color_mask[0] && ctx->color_mask[1]
                      && ctx->color_mask[2];
    if (plain && bk == 0 && !ctx->color_logic_op)
        s[n++] = stage_write_rgba8;
    else if (plain && bk == 1)
        s[n++] = stage_write_rgba8_alpha;
    else if (plain && bk == 2)
        s[n++] = stage_write_rgba8_add;
    else if (plain565 && bk == 0 && !ctx->color_logic_op)
        s[n++] = stage_write_565;
    else if (plain565 && bk == 1)
        s[n++] = stage_write_565_alpha;
    else
        s[n++] = stage_write;
    return n;
}

void span_chain_compose(GlesContext *ctx) { ctx->chain_len = compose(ctx, ctx->chain, 0); }

/* one row's run [x0, x0 + n) through `count` stages, a chunk at a time */
static void run(GlesContext *ctx, const SpanStage *stages, int count, const TriSetup *t, const RectSetup *r, int y,
                int x0, int n)
{
    SpanBuf b;
    b.y = y;
    b.rect = r;
    for (int start = 0; start < n; start += SPAN_CHUNK) {
        int len = n - start < SPAN_CHUNK ? n - start : SPAN_CHUNK;
        b.x0 = x0 + start;
        b.n = len;
        for (int k = 0; k < len; k++)
            b.k[k] = (uint8_t)k;
        if (t)
            for (int i = 0; i < 3; i++)
                b.e0[i] = t->ea[i] * b.x0 + t->eb[i] * y + t->ec[i];
        for (int i = 0; i < count && b.n > 0; i++)
            stages[i](ctx, t, &b);
    }
}

void span_chain(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    run(ctx, ctx->chain, ctx->chain_len, t, NULL, y, x0, n);
}

void span_rect(GlesContext *ctx, const RectSetup *r, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    SpanStage stages[GLES_MAX_STAGES];
    int count = compose(ctx, stages, 1);
    for (int64_t y = y0; y < y1; y++)
        run(ctx, stages, count, NULL, r, (int)y, (int)x0, (int)(x1 - x0));
}

/* }==================================================================== */
