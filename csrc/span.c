/*
** span.c -- the fragment stage for a run of pixels in one row.
** Consumes: a TriSetup and a covered run (y, x0 .. x0+n-1).
** Produces: framebuffer writes after the per-fragment operations built so
**       far: depth test (all eight functions) and depth mask, colour mask,
**       RGBA8888 or RGB565 colour.
** Specialised instances of span_tmpl.h cover the common states; span_generic
** covers every state and is the reference they must match bit for bit.
*/
#include "raster.h"
#include "fragment.h"
#include "texture.h"

uint32_t span_pack_color(const GlesContext *ctx, const FRAGV *c)
{
    FRAGV f[4];
    for (int i = 0; i < 4; i++)
        f[i] = frag_clamp01(c[i]);
    if (ctx->color_format == GLES_COLOR_RGB565)
        return (fragment_channel(f[0], 5, 0, 0) << 11) | (fragment_channel(f[1], 6, 0, 0) << 5)
             | fragment_channel(f[2], 5, 0, 0);
    return fragment_channel(f[0], 8, 0, 0) | (fragment_channel(f[1], 8, 0, 0) << 8)
         | (fragment_channel(f[2], 8, 0, 0) << 16) | (fragment_channel(f[3], 8, 0, 0) << 24);
}

/* texture coordinates of unit u at edge values e (perspective weights p) */
static void tex_coord(const TriSetup *t, int u, const WGT p[3], TexCoord *out)
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

/* One fragment through texturing, fog, coverage and the per-fragment
** operations, in the spec's order (§3.7-3.9, §4.1): the shared tail of
** every primitive's generic path. */
void fragment_process(GlesContext *ctx, int x, int y, const FragIn *in)
{
    const size_t at = (size_t)y * (size_t)ctx->width + (size_t)x;
    const int is565 = ctx->color_format == GLES_COLOR_RGB565;
    const int dither = ctx->dither && is565;
    static const uint32_t max565[4] = { 31, 63, 31, 0 }, shift565[4] = { 11, 5, 0, 0 };
    static const int bits565[3] = { 5, 6, 5 };
    const unsigned int units = ctx->tex_units_on;
    FRAGV c[4];
    for (int i = 0; i < 4; i++)
        c[i] = in->c[i];
    if (units) {
        FRAGV cf[4], ct[GLES_MAX_TEXTURE_UNITS][4];
        for (int i = 0; i < 4; i++)
            cf[i] = c[i] = frag_clamp01(c[i]);
        for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
            if (units & (1u << u)) {
                const Texture *tex = ctx->units[u].bound;
                if (texture_needs_lod(tex))
                    texture_sample(tex, &in->tc[u], &in->tdx[u], &in->tdy[u], ct[u], ctx->texel_unorm8);
                else
                    texture_sample(tex, &in->tc[u], NULL, NULL, ct[u], ctx->texel_unorm8);
            }
        for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
            if (units & (1u << u))
                texture_env(ctx, u, cf, ct, c);
    }
    if (ctx->fog) {
        FRAGV f = in->fog;
        /* C = f C + (1 - f) C_fog, in that form so f = 1 and f = 0 are exact */
        for (int i = 0; i < 3; i++)
            c[i] = frag_mul(f, frag_clamp01(c[i])) + frag_mul(FRAG_ONE - f, frag_from_num(ctx->n_fog_color[i]));
    }
    if (in->coverage != FRAG_ONE) /* §3.11: antialiasing scales alpha */
        c[3] = frag_mul(frag_clamp01(c[3]), in->coverage);
    if (ctx->alpha_test && !fragment_alpha_pass(ctx, c[3]))
        return;
    const int stencil = ctx->stencil_test && ctx->stencil;
    uint8_t s = 0;
    if (stencil) {
        s = ctx->stencil[at];
        if (!fragment_stencil_pass(ctx, s)) {
            ctx->stencil[at] = fragment_stencil_op(ctx, ctx->stencil_fail, s);
            return;
        }
    }
    const int depth = ctx->depth_test && ctx->depth;
    int zpass = depth ? fragment_compare(ctx->depth_func, in->z, ctx->depth[at]) : 1;
    if (stencil)
        ctx->stencil[at] = fragment_stencil_op(ctx, zpass ? ctx->stencil_zpass : ctx->stencil_zfail, s);
    if (!zpass)
        return;
    if (depth && ctx->depth_mask)
        ctx->depth[at] = in->z;

    uint32_t keep = 0; /* framebuffer bits the colour mask protects */
    for (int i = 0; i < (is565 ? 3 : 4); i++)
        if (!ctx->color_mask[i])
            keep |= is565 ? max565[i] << shift565[i] : 0xFFu << (8 * i);
    uint32_t dpacked = is565 ? ((uint16_t *)ctx->color)[at] : ((uint32_t *)ctx->color)[at];
    FRAGV t_d = dither ? fragment_dither_threshold(x, y) : FRAG_ONE / 2;
    FRAGV out[4];
    if (ctx->blend && !ctx->color_logic_op) {
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
    for (int i = 0; i < (is565 ? 3 : 4); i++) {
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

/* The fragment at (x, y) of a primitive described by a TriSetup, with edge
** values e (weights come from t->wgt; t->ea and t->eb are the edge steps to
** the right and upper neighbours, for the level of detail). Triangles,
** lines and points all end here. */
void fragment_from_setup(GlesContext *ctx, const TriSetup *t, const int64_t e[3], int x, int y, FRAGV coverage,
                         const TexCoord *sprite, const TexCoord *sprite_dx, const TexCoord *sprite_dy)
{
    const Vertex *v0 = t->v[0], *v1 = t->v[1], *v2 = t->v[2];
    const unsigned int units = ctx->tex_units_on;
    FragIn in;
    in.coverage = coverage;
    in.z = 0;
    in.fog = 0;
    WGT p[3];
    wgt_persp(&t->wgt, e, p);
    for (int i = 0; i < 4; i++)
        in.c[i] = t->smooth ? frag_lerp3f(t->col[0][i], t->col[1][i], t->col[2][i], p[0], p[1], p[2]) : t->flat[i];
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
        if (!(units & (1u << u)))
            continue;
        if (sprite && ctx->units[u].coord_replace) {
            in.tc[u] = *sprite;
            in.tdx[u] = *sprite_dx;
            in.tdy[u] = *sprite_dy;
            continue;
        }
        tex_coord(t, u, p, &in.tc[u]);
        if (texture_needs_lod(ctx->units[u].bound)) {
            /* the right and upper neighbours' coordinates */
            int64_t ex[3] = { e[0] + t->ea[0], e[1] + t->ea[1], e[2] + t->ea[2] };
            int64_t ey[3] = { e[0] + t->eb[0], e[1] + t->eb[1], e[2] + t->eb[2] };
            WGT px[3], py[3];
            wgt_persp_any(&t->wgt, ex, px);
            wgt_persp_any(&t->wgt, ey, py);
            tex_coord(t, u, px, &in.tdx[u]);
            tex_coord(t, u, py, &in.tdy[u]);
        }
    }
    if (ctx->fog)
        in.fog = ctx->fog_per_fragment
                     ? frag_from_num(fog_factor(ctx, wgt_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2])))
                     : frag_clamp01(frag_lerp3(v0->fog, v1->fog, v2->fog, p[0], p[1], p[2]));
    if (ctx->depth_test && ctx->depth) {
        WGT l[3];
        wgt_linear(&t->wgt, e, l);
        in.z = wgt_depth3(v0->wz, v1->wz, v2->wz, l[0], l[1], l[2], ctx->depth_max);
        in.z = raster_offset_depth(ctx, t, in.z);
    }
    fragment_process(ctx, x, y, &in);
}

/* Every state: the reference path for triangles. */
static void span_generic(GlesContext *ctx, const TriSetup *t, int y, int x0, int n)
{
    int64_t e[3];
    for (int i = 0; i < 3; i++)
        e[i] = t->ea[i] * x0 + t->eb[i] * y + t->ec[i];
    for (int k = 0; k < n; k++, e[0] += t->ea[0], e[1] += t->ea[1], e[2] += t->ea[2])
        fragment_from_setup(ctx, t, e, x0 + k, y, FRAG_ONE, NULL, NULL, NULL);
}

#define SPAN_NAME span_flat
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 0
#define SPAN_BLEND 0
#include "span_tmpl.h"

#define SPAN_NAME span_smooth
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 0
#define SPAN_BLEND 0
#include "span_tmpl.h"

#define SPAN_NAME span_flat_zless
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 1
#define SPAN_BLEND 0
#include "span_tmpl.h"

#define SPAN_NAME span_smooth_zless
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 1
#define SPAN_BLEND 0
#include "span_tmpl.h"

#define SPAN_NAME span_flat_alpha
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 0
#define SPAN_BLEND 1
#include "span_tmpl.h"

#define SPAN_NAME span_smooth_alpha
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 0
#define SPAN_BLEND 1
#include "span_tmpl.h"

#define SPAN_NAME span_flat_zless_alpha
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 1
#define SPAN_BLEND 1
#include "span_tmpl.h"

#define SPAN_NAME span_smooth_zless_alpha
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 1
#define SPAN_BLEND 1
#include "span_tmpl.h"

#define SPAN_NAME span_flat_add
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 0
#define SPAN_BLEND 2
#include "span_tmpl.h"

#define SPAN_NAME span_smooth_add
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 0
#define SPAN_BLEND 2
#include "span_tmpl.h"

#define SPAN_NAME span_flat_zless_add
#define SPAN_SMOOTH 0
#define SPAN_DEPTH 1
#define SPAN_BLEND 2
#include "span_tmpl.h"

#define SPAN_NAME span_smooth_zless_add
#define SPAN_SMOOTH 1
#define SPAN_DEPTH 1
#define SPAN_BLEND 2
#include "span_tmpl.h"

#define SPAN_NAME span_tex
#define SPAN_DEPTH 0
#define SPAN_BLEND 0
#include "span_tex_tmpl.h"

#define SPAN_NAME span_tex_zless
#define SPAN_DEPTH 1
#define SPAN_BLEND 0
#include "span_tex_tmpl.h"

#define SPAN_NAME span_tex_alpha
#define SPAN_DEPTH 0
#define SPAN_BLEND 1
#include "span_tex_tmpl.h"

#define SPAN_NAME span_tex_zless_alpha
#define SPAN_DEPTH 1
#define SPAN_BLEND 1
#include "span_tex_tmpl.h"

/* which specialised blend a state is: 0 none, 1 alpha, 2 additive, -1 other */
static int blend_kind(const GlesContext *ctx)
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

/* the state conditions every specialised span shares, texturing aside */
static int simple_but_texture(const GlesContext *ctx, int bk)
{
    return ctx->color_format == GLES_COLOR_RGBA8888 && ctx->color_mask[0] && ctx->color_mask[1]
        && ctx->color_mask[2] && ctx->color_mask[3] && !(ctx->debug & GLES_DEBUG_GENERIC_SPANS)
        && !ctx->alpha_test && !(ctx->stencil_test && ctx->stencil) && !ctx->fog && !ctx->color_logic_op
        && !ctx->polygon_offset_fill && bk >= 0;
}

void span_choose(GlesContext *ctx)
{
    /* [depth][blend][smooth] */
    static const SpanFunc table[2][3][2] = {
        { { span_flat, span_smooth }, { span_flat_alpha, span_smooth_alpha }, { span_flat_add, span_smooth_add } },
        { { span_flat_zless, span_smooth_zless }, { span_flat_zless_alpha, span_smooth_zless_alpha },
          { span_flat_zless_add, span_smooth_zless_add } },
    };
    static const char *names[2][3][2] = {
        { { "flat", "smooth" }, { "flat_alpha", "smooth_alpha" }, { "flat_add", "smooth_add" } },
        { { "flat_zless", "smooth_zless" }, { "flat_zless_alpha", "smooth_zless_alpha" },
          { "flat_zless_add", "smooth_zless_add" } },
    };
    const int depth = ctx->depth_test && ctx->depth;
    const int smooth = ctx->shade_model == GL_SMOOTH;
    const int bk = blend_kind(ctx);
    const int simple = simple_but_texture(ctx, bk) && !ctx->tex_units_on;
    const int zless = depth && ctx->depth_func == GL_LESS && ctx->depth_mask;
    /* one texture unit (the first) with REPLACE or MODULATE */
    const unsigned int env = ctx->units[0].env_mode;
    const int tex1 = ctx->tex_units_on == 1u && (env == GL_REPLACE || env == GL_MODULATE);
    if (simple_but_texture(ctx, bk) && tex1 && bk <= 1 && (!depth || zless)) {
        static const SpanFunc ttable[2][2] = { { span_tex, span_tex_alpha }, { span_tex_zless, span_tex_zless_alpha } };
        static const char *tnames[2][2] = { { "tex", "tex_alpha" }, { "tex_zless", "tex_zless_alpha" } };
        ctx->span = ctx->span_const = ttable[depth][bk];
        ctx->span_name = tnames[depth][bk];
        return;
    }
    if (simple && (!depth || zless)) {
        ctx->span = table[depth][bk][smooth];
        ctx->span_const = table[depth][bk][0];
        ctx->span_name = names[depth][bk][smooth];
    } else {
        ctx->span = ctx->span_const = span_generic;
        ctx->span_name = "generic";
    }
}
