/*
** span.c -- choosing the fragment stage for a triangle's rows.
** Consumes: a TriSetup and a covered run (y, x0 .. x0+n-1).
** Produces: framebuffer writes after every per-fragment operation.
** Fused instances of span_fused.h cover the plain untextured states, the
** chain of stages (span_chain.c) every other; span_generic runs each
** fragment through fragment_process and is the reference both must match
** bit for bit. fragment_inputs gives a primitive's fragment inputs at
** given edge values, for the reference and for points.
*/
#include <string.h>
#include "raster.h"
#include "span.h"
#include "fragment.h"
#include "texture.h"
#include "texcube.h"

uint32_t span_pack_color(const GlesContext *ctx, const FRAGV *c)
{
    FRAGV f[4];
    for (int i = 0; i < 4; i++)
        f[i] = frag_clamp01(c[i]);
    if (ctx->color_format != GLES_COLOR_RGBA8888)
        return fragment_pack16(color_layout16(ctx->color_format), f, 0, 0);
    return fragment_channel(f[0], 8, 0, 0) | (fragment_channel(f[1], 8, 0, 0) << 8)
         | (fragment_channel(f[2], 8, 0, 0) << 16) | (fragment_channel(f[3], 8, 0, 0) << 24);
}

/* a cube map unit's direction (s, t, r) at perspective weights p, q left
** out (texcube.c); a point sprite's s and t where COORD_REPLACE is on */
static void span_cube_str(const TriSetup *t, int u, const WGT p[3], const TexCoord *sprite, TEXC str[3])
{
    const NUM *a = t->v[0]->tex[u], *b = t->v[1]->tex[u], *c = t->v[2]->tex[u];
    for (int k = 0; k < 3; k++)
        str[k] = texc_lerp3(a[k], b[k], c[k], p[0], p[1], p[2]);
    if (sprite) {
        str[0] = sprite->s;
        str[1] = sprite->t;
    }
}

/* The fragment at (x, y) of a primitive described by a TriSetup, with edge
** values e (weights come from t->wgt; the level of detail's neighbours are
** the coordinates at the weights' tangents t->tan along the edge steps to
** the right and upper pixels, t->ea and t->eb). Triangles, lines and points
** all end here. */
void fragment_inputs(const GlesContext *ctx, const TriSetup *t, const int64_t e[3], FRAGV coverage,
                     const TexCoord *sprite, const TexCoord *sprite_dx, const TexCoord *sprite_dy, FragIn *out)
{
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    const unsigned int units = ctx->tex_units_on;
    out->coverage = coverage;
    out->z = 0;
    out->fog = 0;
    /* with the level of detail's neighbours: the weights' tangents */
    WGT p[3], px[3] = { 0 }, py[3] = { 0 };
    wgt_persp_tangents(&t->wgt, t->lod ? t->tan : NULL, e, p, px, py);
    for (int i = 0; i < 4; i++)
        out->c[i] = t->smooth ? frag_lerp3f(t->col[0][i], t->col[1][i], t->col[2][i], p[0], p[1], p[2]) : t->flat[i];
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
        if (!(units & (1u << u)))
            continue;
        if (ctx->cube_units & (1u << u)) {
            const int replace = sprite && ctx->units[u].coord_replace, lod = texture_needs_lod(ctx->units[u].bound);
            TEXC c[3], cx[3], cy[3];
            span_cube_str(t, u, p, replace ? sprite : NULL, c);
            if (lod) {
                span_cube_str(t, u, px, replace ? sprite_dx : NULL, cx);
                span_cube_str(t, u, py, replace ? sprite_dy : NULL, cy);
            }
            texcube_coords(c, lod ? cx : NULL, lod ? cy : NULL, &out->tc[u], &out->tdx[u], &out->tdy[u],
                           &out->face[u]);
            continue;
        }
        if (sprite && ctx->units[u].coord_replace) {
            out->tc[u] = *sprite;
            out->tdx[u] = *sprite_dx;
            out->tdy[u] = *sprite_dy;
            continue;
        }
        span_tex_coord(t, u, p, &out->tc[u]);
        if (texture_needs_lod(ctx->units[u].bound)) {
            span_tex_coord(t, u, px, &out->tdx[u]);
            span_tex_coord(t, u, py, &out->tdy[u]);
        }
    }
    if (ctx->fog)
        out->fog = ctx->fog_per_fragment
                     ? frag_from_num(fog_factor(ctx, wgt_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2])))
                     : frag_clamp01(frag_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2]));
    if (ctx->depth_test && ctx->depth) {
        WGT l[3];
        wgt_linear(&t->wgt, e, l);
        out->z = wgt_depth3(v0->wz, v1->wz, v2->wz, l[0], l[1], l[2], ctx->depth_max);
        out->z = raster_offset_depth(ctx, t, out->z);
    }
}

void fragment_from_setup(GlesContext *ctx, const TriSetup *t, const int64_t e[3], int x, int y, FRAGV coverage,
                         const TexCoord *sprite, const TexCoord *sprite_dx, const TexCoord *sprite_dy)
{
    FragIn in;
    fragment_inputs(ctx, t, e, coverage, sprite, sprite_dx, sprite_dy, &in);
    fragment_process(ctx, x, y, &in);
}

/* Every state: the reference path for triangles. */
static void span_generic(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    int64_t e[3];
    tri_edges_at(t, x0, y, e);
    for (int k = 0; k < n; k++, e[0] += t->ea[0], e[1] += t->ea[1], e[2] += t->ea[2])
        fragment_from_setup(ctx, t, e, x0 + k, y, FRAG_ONE, NULL, NULL, NULL);
}

/* A flat colour's blend (blend 1 SRC_ALPHA, ONE_MINUS_SRC_ALPHA, 2 ONE,
** ONE) maps each channel's destination byte alone to its result: the
** table of those results, every byte of every channel done by
** span_fused's scalar arithmetic, or NULL while the colour has blended
** fewer than GLES_FLAT_TABLE_AFTER fragments (n more now) since it became
** the key. */
static const uint32_t (*span_flat_table(GlesContext *ctx, const FRAGV sterm[4], FRAGV da, int blend, int n))[256]
{
    FlatTable *ft = &ctx->flat_table;
    if (ft->blend != blend || ft->da != da || ft->sterm[0] != sterm[0] || ft->sterm[1] != sterm[1]
        || ft->sterm[2] != sterm[2] || ft->sterm[3] != sterm[3]) {
        memcpy(ft->sterm, sterm, sizeof ft->sterm);
        ft->da = da;
        ft->blend = blend;
        ft->ready = 0;
        ft->seen = 0;
    }
    if (ft->ready)
        return (const uint32_t (*)[256])ft->word;
    ft->seen += n;
    if (ft->seen < GLES_FLAT_TABLE_AFTER)
        return NULL;
    for (int i = 0; i < 4; i++)
        for (int d = 0; d < 256; d++) {
            const FRAGV dv = ctx->unorm8[d];
            const FRAGV v = sterm[i] + (blend == 1 ? frag_mul(dv, da) : dv);
            ft->word[i][d] = frag_to_unorm(v, 255, FRAG_ONE / 2) << (8 * i);
        }
    ft->ready = 1;
    return (const uint32_t (*)[256])ft->word;
}

/* the blend of destination word d through a span_flat_table */
static inline uint32_t span_flat_word(const uint32_t (*table)[256], uint32_t d)
{
    return table[0][d & 0xFFu] | table[1][(d >> 8) & 0xFFu] | table[2][(d >> 16) & 0xFFu] | table[3][d >> 24];
}

/* n stored words through a span_flat_table: a function of its own, at a
** 64-byte boundary, so that the loop (the same machine code in every
** build) sits the same way in each library (inlined in span_fused, its
** placement made blended_quads take 4.6 ms in one build and 6.5 in
** another on this machine's AMD EPYC), and two words per iteration, which
** was the fastest of the placements and unrollings measured (4.2-4.5 ms
** in all three). It uses no SSE register, so GCC's AVX2 callers need
** -fno-ipa-ra to place their vzeroupper (docs/architecture.md, Compiler
** flags). */
static __attribute__((noinline, aligned(64))) void span_flat_run(const uint32_t (*table)[256], uint32_t *dst, int n)
{
    int k = 0;
    for (; k + 2 <= n; k += 2) {
        const uint32_t d0 = dst[k], d1 = dst[k + 1];
        dst[k] = span_flat_word(table, d0);
        dst[k + 1] = span_flat_word(table, d1);
    }
    if (k < n)
        dst[k] = span_flat_word(table, dst[k]);
}

#if NUM_IS_FIXED
/* The smooth spans of the fixed build with their weights stepped along a
** row. Where the edge values take no shift (eshift 0, so area2 < 2^31:
** every triangle below about 16000 pixels), wgt_linear's products e_i R
** (plus its 2^30) and wgt_persp's e_i mant_i are linear in the column, so
** each pixel's is the last one's plus a step of the triangle: an add where
** the general loop multiplies, and no range tests per pixel. A covered
** pixel has 0 <= e_i <= area2 (the three sum to area2), so every product
** lies in [0, 2^62) (R = 2^61 / area2, mant < 2^30) and the sums, kept mod
** 2^64, are the scalar code's. The depth is wgt_depth3 with l0 = 1 - l1 -
** l2 taken out, z0 + l1 (z1 - z0) + l2 (z2 - z0), and the colour likewise
** (v4_lerp_deltas): the same integers. The constants are the triangle's,
** found at its first row. */
static void span_smooth_setup(const TriSetup *t, SmoothStep *s, int colour_ok)
{
    const WgtSetup *ws = &t->wgt;
    s->ok = colour_ok && ws->eshift == 0 && ws->lin_recip > 0;
    if (!s->ok)
        return;
    s->affine = ws->affine;
    s->r = (uint64_t)ws->lin_recip;
    for (int i = 0; i < 3; i++) {
        /* wgt_persp's n_i is 0 from a shift of 63 */
        s->mant[i] = ws->qshift[i] < 63 ? (uint64_t)ws->mant[i] : 0;
        s->qs[i] = ws->qshift[i] < 63 ? ws->qshift[i] : 0;
        s->per_step[i] = (uint64_t)t->ea[i] * s->mant[i];
        s->lin_step[i] = i ? (uint64_t)t->ea[i] * s->r : 0;
    }
    const int64_t z0 = t->v[0]->wz >> 12;
    s->dz1 = (t->v[1]->wz >> 12) - z0;
    s->dz2 = (t->v[2]->wz >> 12) - z0;
    s->zbase = z0 * WGT_ONE + ((int64_t)1 << 33);
}
#endif

/* the fused spans: name, smooth, depth, blend (span_fused.h) */
#define FUSED_SPANS(X)                                                                             \
    X(flat, 0, 0, 0) X(smooth, 1, 0, 0) X(flat_zless, 0, 1, 0) X(smooth_zless, 1, 1, 0)              \
    X(flat_alpha, 0, 0, 1) X(smooth_alpha, 1, 0, 1) X(flat_zless_alpha, 0, 1, 1)                      \
    X(smooth_zless_alpha, 1, 1, 1) X(flat_add, 0, 0, 2) X(smooth_add, 1, 0, 2) X(flat_zless_add, 0, 1, 2) \
    X(smooth_zless_add, 1, 1, 2)

#define SPAN_FN(name) name##_base
#define CHAIN_SIMD 0
#include "span_fused.h"
#undef SPAN_FN
#undef CHAIN_SIMD

#if SIMD_X86
#pragma GCC push_options
SIMD_TARGET_AVX2
#include "span_avx2.h"
#define SPAN_FN(name) name##_avx2
#define CHAIN_SIMD 1
#include "span_fused.h"
#undef SPAN_FN
#undef CHAIN_SIMD
#pragma GCC pop_options
#endif

#define FUSED_NAME(name, SMOOTH, DEPTH, BLEND) [DEPTH][BLEND][SMOOTH] = #name,
static const char *const fused_names[2][3][2] = { FUSED_SPANS(FUSED_NAME) };
#undef FUSED_NAME

/* {====================================================================
** stencil-only passes: every colour channel masked, no alpha test and no
** depth test (§4.1.6: then no depth write either), the stencil test on.
** A fragment changes nothing but its stencil value, which is a function of
** the stored value alone (the test against the reference, then the fail
** or the pass op, through the write mask): one table, built when the state
** is chosen, and the span is a byte loop. Masks drawn into the stencil
** buffer (reflections, shadow volumes' caps, decals) are such passes. */

static int stencil_only_state(const GlesContext *ctx)
{
    return span_no_color(ctx) && !ctx->alpha_test && !(ctx->depth_test && ctx->depth) && ctx->stencil_test
        && ctx->stencil && !ctx_generic_spans(ctx);
}

/* the value each stored value becomes (fragment_tests' op with no depth
** test: the fail op where the test fails, else the pass op) */
static void stencil_only_table(const GlesContext *ctx, uint8_t table[256])
{
    FragTests ft;
    fragment_tests_setup(ctx, &ft);
    uint8_t lut[4][256];
    fragment_stencil_lut(&ft, lut);
    for (int s = 0; s < 256; s++)
        table[s] = lut[0][s] ? lut[3][s] : lut[1][s];
}

static void span_stencil_only(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    (void)t;
    uint8_t *row = ctx->stencil + (size_t)y * (size_t)ctx->width + (size_t)x0;
    const uint8_t *table = ctx->stencil_only;
    for (int k = 0; k < n; k++)
        row[k] = table[row[k]];
}

/* }==================================================================== */

/* the state conditions every specialised span shares, texturing aside */
static int simple_but_texture(const GlesContext *ctx, int bk)
{
    return ctx->color_format == GLES_COLOR_RGBA8888 && ctx->color_mask[0] && ctx->color_mask[1]
        && ctx->color_mask[2] && ctx->color_mask[3] && !ctx_generic_spans(ctx)
        && !ctx->alpha_test && !(ctx->stencil_test && ctx->stencil) && !ctx->fog && !ctx->color_logic_op
        && !ctx->polygon_offset_fill && bk >= 0;
}

void span_choose(GlesContext *ctx)
{
    const SpanFunc(*table)[3][2] = fused_spans_base;
#if SIMD_X86
    if (ctx_simd(ctx) >= SIMD_AVX2)
        table = fused_spans_avx2;
#endif
    const int depth = ctx->depth_test && ctx->depth;
    const int smooth = ctx->shade_model == GL_SMOOTH;
    const int bk = span_blend_kind(ctx);
    const int simple = simple_but_texture(ctx, bk) && !ctx->tex_units_on;
    const int zless = depth && ctx->depth_func == GL_LESS && ctx->depth_mask;
    if (simple && (!depth || zless)) {
        ctx->span = table[depth][bk][smooth];
        ctx->span_const = table[depth][bk][0];
        ctx->span_name = fused_names[depth][bk][smooth];
    } else if (ctx_generic_spans(ctx)) {
        ctx->span = ctx->span_const = span_generic;
        ctx->span_name = "generic";
    } else if (stencil_only_state(ctx)) {
        stencil_only_table(ctx, ctx->stencil_only);
        ctx->span = ctx->span_const = span_stencil_only;
        ctx->span_name = "stencil_only";
    } else {
        span_chain_compose(ctx);
        ctx->span = ctx->span_const = span_chain;
        ctx->span_name = "chain";
    }
}
