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
** stencil and depth (§4.1.5, §4.1.6) */

static uint32_t fragment_depth(const GlesContext *ctx, const TriSetup *t, const SpanBuf *b, int k)
{
    int64_t e[3];
    chunk_edges(t, b, k, e);
    WGT l[3];
    wgt_linear(&t->wgt, e, l);
    uint32_t z = wgt_depth3(t->v[0]->wz, t->v[1]->wz, t->v[2]->wz, l[0], l[1], l[2], ctx->depth_max);
    return raster_offset_depth(ctx, t, z);
}

/* keep the fragments at slots where keep[j]; c moves with them when the
** colour is already computed */
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

static void depth_stencil(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int with_color)
{
    const size_t row = (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    const int stencil = ctx->stencil_test && ctx->stencil;
    const int depth = ctx->depth_test && ctx->depth;
    const unsigned int func = ctx->depth_func;
    const int write = depth && ctx->depth_mask;
    uint8_t keep[SPAN_CHUNK];
    for (int j = 0; j < b->n; j++) {
        const int k = b->k[j];
        const size_t at = row + (size_t)k;
        uint8_t s = 0;
        keep[j] = 0;
        if (stencil) {
            s = ctx->stencil[at];
            if (!fragment_stencil_pass(ctx, s)) {
                ctx->stencil[at] = fragment_stencil_op(ctx, ctx->stencil_fail, s);
                continue;
            }
        }
        uint32_t z = 0;
        int zpass = 1;
        if (depth) {
            z = fragment_depth(ctx, t, b, k);
            zpass = fragment_compare(func, z, ctx->depth[at]);
        }
        if (stencil)
            ctx->stencil[at] = fragment_stencil_op(ctx, zpass ? ctx->stencil_zpass : ctx->stencil_zfail, s);
        if (!zpass)
            continue;
        if (write)
            ctx->depth[at] = z;
        keep[j] = 1;
    }
    chunk_compact(b, keep, with_color);
}

static void stage_tests_early(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { depth_stencil(ctx, t, b, 0); }
static void stage_tests_late(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { depth_stencil(ctx, t, b, 1); }

/* depth LESS with writes and no stencil: the common case, without the
** per-fragment switches */
static void stage_zless_early(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    uint32_t *zb = ctx->depth + (size_t)b->y * (size_t)ctx->width + (size_t)b->x0;
    int m = 0;
    for (int j = 0; j < b->n; j++) {
        const int k = b->k[j];
        uint32_t z = fragment_depth(ctx, t, b, k);
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

/* one unit's texel for every live fragment */
static void stage_fetch(GlesContext *ctx, const TriSetup *t, SpanBuf *b, int u)
{
    const Texture *tex = ctx->units[u].bound;
    const int lod = texture_needs_lod(tex);
    for (int j = 0; j < b->n; j++)
        span_tex_coord(t, u, b->p[j], &b->tc[j]);
    if (lod)
        for (int j = 0; j < b->n; j++) {
            span_tex_coord(t, u, b->px[j], &b->tx[j]);
            span_tex_coord(t, u, b->py[j], &b->ty[j]);
        }
    ctx->samplers[u](tex, b->n, b->tc, b->tx, b->ty, b->ct[0][u], GLES_MAX_TEXTURE_UNITS * 4, ctx->texel_unorm8);
}

static void stage_env(GlesContext *ctx, SpanBuf *b, int u)
{
    const TexUnit *tu = &ctx->units[u];
    if (tu->env_mode == GL_MODULATE && tu->bound->format == GL_RGBA) {
        /* texture_env's MODULATE of an RGBA texture, inline */
        for (int j = 0; j < b->n; j++)
            for (int i = 0; i < 4; i++)
                b->c[j][i] = frag_mul(b->c[j][i], b->ct[j][u][i]);
        return;
    }
    texture_env_span(ctx, u, b->n, (const FRAGV (*)[4])b->cf, b->ct, b->c);
}

#define UNIT_STAGES(u) \
    static void stage_fetch##u(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { stage_fetch(ctx, t, b, u); } \
    static void stage_env##u(GlesContext *ctx, const TriSetup *t, SpanBuf *b) { (void)t; stage_env(ctx, b, u); }
UNIT_STAGES(0)
UNIT_STAGES(1)
UNIT_STAGES(2)
UNIT_STAGES(3)
#undef UNIT_STAGES

static const SpanStage fetch_stages[GLES_MAX_TEXTURE_UNITS] = { stage_fetch0, stage_fetch1, stage_fetch2, stage_fetch3 };
static const SpanStage env_stages[GLES_MAX_TEXTURE_UNITS] = { stage_env0, stage_env1, stage_env2, stage_env3 };

/* §3.8: C = f C + (1 - f) C_fog */
static void stage_fog(GlesContext *ctx, const TriSetup *t, SpanBuf *b)
{
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    FRAGV fc[3];
    for (int i = 0; i < 3; i++)
        fc[i] = frag_from_num(ctx->n_fog_color[i]);
    for (int j = 0; j < b->n; j++) {
        const WGT *p = b->p[j];
        FRAGV f = ctx->fog_per_fragment
                      ? frag_from_num(fog_factor(ctx, wgt_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2])))
                      : frag_clamp01(frag_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2]));
        FRAGV *c = b->c[j];
        for (int i = 0; i < 3; i++)
            c[i] = frag_mul(f, frag_clamp01(c[i])) + frag_mul(FRAG_ONE - f, fc[i]);
    }
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
    const int is565 = ctx->color_format == GLES_COLOR_RGB565;
    const int dither = ctx->dither && is565;
    static const uint32_t max565[4] = { 31, 63, 31, 0 }, shift565[4] = { 11, 5, 0, 0 };
    static const int bits565[3] = { 5, 6, 5 };
    const int channels = is565 ? 3 : 4;
    uint32_t keep = 0; /* framebuffer bits the colour mask protects */
    for (int i = 0; i < channels; i++)
        if (!ctx->color_mask[i])
            keep |= is565 ? max565[i] << shift565[i] : 0xFFu << (8 * i);
    const int blend = ctx->blend && !ctx->color_logic_op;
    for (int j = 0; j < b->n; j++) {
        const int x = b->x0 + b->k[j];
        const size_t at = row + b->k[j];
        const FRAGV *c = b->c[j];
        uint32_t dpacked = is565 ? ((uint16_t *)ctx->color)[at] : ((uint32_t *)ctx->color)[at];
        FRAGV t_d = dither ? fragment_dither_threshold(x, b->y) : FRAG_ONE / 2;
        FRAGV out[4];
        if (blend) {
            FRAGV src[4], dst[4];
            for (int i = 0; i < 4; i++) {
                src[i] = frag_clamp01(c[i]);
                if (is565)
                    dst[i] = i == 3 ? FRAG_ONE : (i == 1 ? ctx->unorm6 : ctx->unorm5)[(dpacked >> shift565[i]) & max565[i]];
                else
                    dst[i] = ctx->unorm8[(dpacked >> (8 * i)) & 0xFFu];
            }
            fragment_blend(ctx, src, dst, out);
        } else {
            for (int i = 0; i < 4; i++)
                out[i] = c[i];
        }
        uint32_t packed = 0;
        for (int i = 0; i < channels; i++) {
            if (is565)
                packed |= fragment_channel(out[i], bits565[i], dither, t_d) << shift565[i];
            else
                packed |= fragment_channel(out[i], 8, 0, t_d) << (8u * (uint32_t)i);
        }
        if (ctx->color_logic_op)
            packed = fragment_logic_op(ctx->logic_op, packed, dpacked) & (is565 ? 0xFFFFu : 0xFFFFFFFFu);
        packed = (dpacked & keep) | (packed & ~keep);
        if (is565)
            ((uint16_t *)ctx->color)[at] = (uint16_t)packed;
        else
            ((uint32_t *)ctx->color)[at] = packed;
    }
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

void span_chain_compose(GlesContext *ctx)
{
    SpanStage *s = ctx->chain;
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
    if (tests && early)
        s[n++] = zless ? stage_zless_early : stage_tests_early;
    s[n++] = stage_persp;
    if (lod)
        s[n++] = stage_neighbours;
    s[n++] = stage_color;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (units & (1u << u))
            s[n++] = fetch_stages[u];
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (units & (1u << u))
            s[n++] = env_stages[u];
    if (ctx->fog)
        s[n++] = stage_fog;
    if (ctx->alpha_test)
        s[n++] = stage_alpha;
    if (tests && !early)
        s[n++] = stage_tests_late;
    const int bk = span_blend_kind(ctx);
    const int plain = ctx->color_format == GLES_COLOR_RGBA8888 && ctx->color_mask[0] && ctx->color_mask[1]
                   && ctx->color_mask[2] && ctx->color_mask[3];
    if (plain && bk == 0 && !ctx->color_logic_op)
        s[n++] = stage_write_rgba8;
    else if (plain && bk == 1)
        s[n++] = stage_write_rgba8_alpha;
    else if (plain && bk == 2)
        s[n++] = stage_write_rgba8_add;
    else
        s[n++] = stage_write;
    ctx->chain_len = n;
}

void span_chain(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    SpanBuf b;
    b.y = y;
    for (int start = 0; start < n; start += SPAN_CHUNK) {
        int len = n - start < SPAN_CHUNK ? n - start : SPAN_CHUNK;
        b.x0 = x0 + start;
        b.n = len;
        for (int k = 0; k < len; k++)
            b.k[k] = (uint8_t)k;
        for (int i = 0; i < 3; i++)
            b.e0[i] = t->ea[i] * b.x0 + t->eb[i] * y + t->ec[i];
        for (int i = 0; i < ctx->chain_len && b.n > 0; i++)
            ctx->chain[i](ctx, t, &b);
    }
}

/* }==================================================================== */
