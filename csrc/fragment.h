/*
** fragment.h -- per-fragment operations (ES 1.1 §4.1) and fog (§3.8).
*/
#ifndef GLES_FRAGMENT_H
#define GLES_FRAGMENT_H

#include "state.h"
#include "texture.h"

void fragment_init(GlesContext *ctx);

/* the inputs of one fragment (fragment_process) */
typedef struct FragIn {
    FRAGV c[4];                             /* primary colour */
    TexCoord tc[GLES_MAX_TEXTURE_UNITS];    /* per enabled unit */
    TexCoord tdx[GLES_MAX_TEXTURE_UNITS];   /* one pixel right and up (along the */
    TexCoord tdy[GLES_MAX_TEXTURE_UNITS];   /* tangent), read when the filter needs LOD */
    uint8_t face[GLES_MAX_TEXTURE_UNITS];   /* a cube map unit's face (texcube.c) */
    FRAGV fog;                              /* fog factor f */
    FRAGV coverage;                         /* antialiasing coverage, FRAG_ONE if none */
    uint32_t z;                             /* window depth (with the depth test on) */
} FragIn;

/* texturing, fog, coverage and the per-fragment operations for one fragment */
void fragment_process(GlesContext *ctx, int x, int y, const FragIn *in);


/* A colour channel into a framebuffer channel of `bits` bits (§2.12.8,
** §4.1.8). 8 bits round to nearest. Fewer bits without dithering keep the
** high bits of an exact ubyte colour (floor(v * 2^bits)), as the spec
** requires for unlit, unclipped ubyte input; with dithering, the ordered
** threshold t picks between the two nearest values. */
static inline uint32_t fragment_channel(FRAGV v, int bits, int dither, FRAGV t)
{
    if (bits == 8)
        return frag_to_unorm(v, 255, FRAG_ONE / 2);
    return dither ? frag_to_unorm(v, (1u << bits) - 1, t) : frag_to_msb(v, bits);
}
int fragment_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
/* the comparison of a test function (§4.1.4-4.1.6): a FUNC b */
static inline int fragment_compare(unsigned int func, uint32_t a, uint32_t b)
{
    switch (func) {
    case GL_NEVER: return 0;
    case GL_LESS: return a < b;
    case GL_EQUAL: return a == b;
    case GL_LEQUAL: return a <= b;
    case GL_GREATER: return a > b;
    case GL_NOTEQUAL: return a != b;
    case GL_GEQUAL: return a >= b;
    default: return 1;
    }
}
/* §4.1.4, compared at 8 bits as the framebuffer's colour precision: an
** EQUAL test then matches the alpha a ubyte colour or texel gives */
static inline uint32_t fragment_alpha8(FRAGV alpha) { return frag_to_unorm(alpha, 255, FRAG_ONE / 2); }
static inline uint32_t fragment_alpha_ref8(const GlesContext *ctx)
{
    return (uint32_t)dbl_to_i64(ctx->alpha_ref * 255.0, 0, 255);
}
int fragment_alpha_pass(const GlesContext *ctx, FRAGV alpha);
/* blended colour (not yet clamped) from source and destination in FRAGV */
void fragment_blend(const GlesContext *ctx, const FRAGV src[4], const FRAGV dst[4], FRAGV out[4]);
FRAGV fragment_dither_threshold(int x, int y);

/* The pieces of fragment_process that the span chain shares, so that the
** two paths are one arithmetic. */

/* the fog colour's RGB in FRAGV */
static inline void fragment_fog_color(const GlesContext *ctx, FRAGV fc[3])
{
    for (int i = 0; i < 3; i++)
        fc[i] = frag_from_num(ctx->n_fog_color[i]);
}

/* §3.8: C = f C + (1 - f) C_fog, in that form so f = 1 and f = 0 are exact */
static inline void fragment_fog(FRAGV c[4], FRAGV f, const FRAGV fc[3])
{
    for (int i = 0; i < 3; i++)
        c[i] = frag_mul(f, frag_clamp01(c[i])) + frag_mul(FRAG_ONE - f, fc[i]);
}

/* what the stencil and depth tests need of the state, found once per span
** (the tests' buffer writes could otherwise alias every field) */
typedef struct FragTests {
    uint8_t *stencil;           /* NULL: no stencil test */
    uint32_t *depth;            /* NULL: no depth test */
    int depth_mask;
    unsigned int stencil_func, depth_func, fail, zfail, zpass;
    uint32_t ref, value_mask, write_mask;   /* 8 bits; ref clamped (§4.1.5) */
    /* NULL, or per stored value: the test's outcome, then the value after
    ** the fail, zfail and zpass ops (fragment_stencil_lut) */
    const uint8_t (*lut)[256];
} FragTests;

static inline void fragment_tests_setup(const GlesContext *ctx, FragTests *ft)
{
    ft->stencil = ctx->stencil_test && ctx->stencil ? ctx->stencil : NULL;
    ft->depth = ctx->depth_test && ctx->depth ? ctx->depth : NULL;
    ft->depth_mask = ctx->depth_mask;
    ft->stencil_func = ctx->stencil_func;
    ft->depth_func = ctx->depth_func;
    ft->fail = ctx->stencil_fail;
    ft->zfail = ctx->stencil_zfail;
    ft->zpass = ctx->stencil_zpass;
    ft->ref = (uint32_t)i64_clamp(ctx->stencil_ref, 0, 255);
    ft->value_mask = ctx->stencil_value_mask & 0xFFu;
    ft->write_mask = ctx->stencil_writemask & 0xFFu;
    ft->lut = NULL;
}

/* §4.1.5: the reference and the stored value, both masked */
static inline int fragment_stencil_pass(const FragTests *ft, uint8_t stored)
{
    return fragment_compare(ft->stencil_func, ft->ref & ft->value_mask, stored & ft->value_mask);
}

/* the stencil value after `op`, through the write mask */
static inline uint8_t fragment_stencil_op(const FragTests *ft, unsigned int op, uint8_t s)
{
    uint32_t v;
    switch (op) {
    case GL_ZERO: v = 0; break;
    case GL_REPLACE: v = ft->ref; break;
    case GL_INCR: v = s == 255 ? 255 : s + 1u; break;
    case GL_DECR: v = s == 0 ? 0 : s - 1u; break;
    case GL_INVERT: v = ~(uint32_t)s & 0xFFu; break;
    case GL_INCR_WRAP_OES: v = (s + 1u) & 0xFFu; break;
    case GL_DECR_WRAP_OES: v = (s + 255u) & 0xFFu; break;
    default: v = s; break; /* GL_KEEP */
    }
    return (uint8_t)((s & ~ft->write_mask) | (v & ft->write_mask));
}

/* the table of ft->lut for the state in ft */
static inline void fragment_stencil_lut(const FragTests *ft, uint8_t lut[4][256])
{
    for (uint32_t s = 0; s < 256; s++) {
        lut[0][s] = (uint8_t)fragment_stencil_pass(ft, (uint8_t)s);
        lut[1][s] = fragment_stencil_op(ft, ft->fail, (uint8_t)s);
        lut[2][s] = fragment_stencil_op(ft, ft->zfail, (uint8_t)s);
        lut[3][s] = fragment_stencil_op(ft, ft->zpass, (uint8_t)s);
    }
}

/* the stencil and depth tests of the fragment at index `at` with window
** depth z, with their writes (§4.1.5-4.1.6); 1 when it passes both.
** depth_func is ft->depth_func (an argument, so that a caller can fix it) */
/* always inline: the chain calls it in loops with depth_func a constant */
static inline __attribute__((always_inline)) int fragment_tests(const FragTests *ft, size_t at, uint32_t z,
                                                                 unsigned int depth_func)
{
    uint8_t s = 0;
    if (ft->stencil) {
        s = ft->stencil[at];
        if (!(ft->lut ? ft->lut[0][s] : fragment_stencil_pass(ft, s))) {
            ft->stencil[at] = ft->lut ? ft->lut[1][s] : fragment_stencil_op(ft, ft->fail, s);
            return 0;
        }
    }
    int zpass = ft->depth ? fragment_compare(depth_func, z, ft->depth[at]) : 1;
    if (ft->stencil)
        ft->stencil[at] = ft->lut ? ft->lut[zpass ? 3 : 2][s] : fragment_stencil_op(ft, zpass ? ft->zpass : ft->zfail, s);
    if (!zpass)
        return 0;
    if (ft->depth && ft->depth_mask)
        ft->depth[at] = z;
    return 1;
}

/* what the write needs of the state, found once per span */
typedef struct FragWrite {
    int is16, dither, blend;    /* is16: a 16-bit format (layout) */
    uint32_t keep;              /* framebuffer bits the colour mask protects */
    const ColorLayout *layout;
    const FRAGV *unorm[4];      /* a 16-bit format's stored channel c as c / (2^bits - 1) */
} FragWrite;

/* ctx's table of c / (2^bits - 1) for a channel of `bits` (4, 5, 6 or 1) */
static inline const FRAGV *fragment_unorm_table(const GlesContext *ctx, int bits)
{
    switch (bits) {
    case 1: return ctx->unorm1;
    case 4: return ctx->unorm4;
    case 5: return ctx->unorm5;
    case 6: return ctx->unorm6;
    default: return ctx->unorm8;
    }
}

static inline void fragment_write_setup(const GlesContext *ctx, FragWrite *w)
{
    w->is16 = ctx->color_format != GLES_COLOR_RGBA8888;
    /* every channel of a 16-bit format is dithered, alpha too (§4.1.7
    ** allows it on each); RGBA8888's rounding is exact, never dithered */
    w->dither = ctx->dither && w->is16;
    w->blend = ctx->blend && !ctx->color_logic_op;
    w->keep = 0;
    w->layout = NULL;
    if (!w->is16) {
        /* (the RGBA8888 writers call this per chunk: nothing more for them) */
        for (int i = 0; i < 4; i++)
            if (!ctx->color_mask[i])
                w->keep |= 0xFFu << (8 * i);
        return;
    }
    w->keep = color_mask_keep(ctx->color_format, ctx->color_mask);
    w->layout = color_layout16(ctx->color_format);
    for (int i = 0; i < 4; i++)
        w->unorm[i] = fragment_unorm_table(ctx, w->layout->bits[i]);
}

/* blending, dither, logic op and masks, then the framebuffer write of the
** fragment at (x, y), index `at` (§4.1.7-4.1.10) */
/* the logic op (§4.1.10) of source s and destination d; inline so that
** writers that fix the op per chunk have the switch folded */
/* the body of a logic op function of source s and destination d, for a
** word and for a vector of words (span_avx2.h's avx2_logic_op4) */
#define FRAGMENT_LOGIC_OP_BODY(op, s, d) \
    switch (op) { \
    case GL_CLEAR: return s & 0; \
    case GL_AND: return s & d; \
    case GL_AND_REVERSE: return s & ~d; \
    case GL_COPY: return s; \
    case GL_AND_INVERTED: return ~s & d; \
    case GL_NOOP: return d; \
    case GL_XOR: return s ^ d; \
    case GL_OR: return s | d; \
    case GL_NOR: return ~(s | d); \
    case GL_EQUIV: return ~(s ^ d); \
    case GL_INVERT: return ~d; \
    case GL_OR_REVERSE: return s | ~d; \
    case GL_COPY_INVERTED: return ~s; \
    case GL_OR_INVERTED: return ~s | d; \
    case GL_NAND: return ~(s & d); \
    default: return s | ~s; /* GL_SET */ \
    }

static inline uint32_t fragment_logic_op(unsigned int op, uint32_t s, uint32_t d)
{
    FRAGMENT_LOGIC_OP_BODY(op, s, d)
}

/* a 16-bit format's stored channels as FRAGV (1 for one it lacks) */
static inline void fragment_unpack16(const FragWrite *w, uint32_t d, FRAGV dst[4])
{
    const ColorLayout *l = w->layout;
    for (int i = 0; i < 4; i++)
        dst[i] = l->bits[i] ? w->unorm[i][(d >> l->shift[i]) & ((1u << l->bits[i]) - 1)] : FRAG_ONE;
}

/* a colour's channels into a 16-bit format's word (§2.12.8's conversion,
** or the dither threshold t_d's choice, per channel) */
static inline uint32_t fragment_pack16(const ColorLayout *l, const FRAGV c[4], int dither, FRAGV t_d)
{
    uint32_t packed = 0;
    for (int i = 0; i < 4; i++)
        if (l->bits[i])
            packed |= fragment_channel(c[i], l->bits[i], dither, t_d) << l->shift[i];
    return packed;
}

static inline void fragment_write(GlesContext *ctx, const FragWrite *w, int x, int y, size_t at, const FRAGV c[4])
{
    const int is16 = w->is16;
    uint32_t dpacked = is16 ? ((uint16_t *)ctx->color)[at] : ((uint32_t *)ctx->color)[at];
    FRAGV t_d = w->dither ? fragment_dither_threshold(x, y) : FRAG_ONE / 2;
    FRAGV out[4];
    if (w->blend) {
        FRAGV src[4], dst[4];
        for (int i = 0; i < 4; i++)
            src[i] = frag_clamp01(c[i]);
        if (is16)
            fragment_unpack16(w, dpacked, dst);
        else
            for (int i = 0; i < 4; i++)
                dst[i] = ctx->unorm8[(dpacked >> (8 * i)) & 0xFFu];
        fragment_blend(ctx, src, dst, out);
    } else {
        for (int i = 0; i < 4; i++)
            out[i] = c[i];
    }
    uint32_t packed = 0;
    if (is16)
        packed = fragment_pack16(w->layout, out, w->dither, t_d);
    else
        for (int i = 0; i < 4; i++)
            packed |= fragment_channel(out[i], 8, 0, t_d) << (8u * (uint32_t)i);
    if (ctx->color_logic_op)
        packed = fragment_logic_op(ctx->logic_op, packed, dpacked) & (is16 ? 0xFFFFu : 0xFFFFFFFFu);
    packed = (dpacked & w->keep) | (packed & ~w->keep);
    if (is16)
        ((uint16_t *)ctx->color)[at] = (uint16_t)packed;
    else
        ((uint32_t *)ctx->color)[at] = packed;
}


/* fog.c */
void fog_init(GlesContext *ctx);
int fog_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
void fog_validate(GlesContext *ctx);
/* the fog factor for eye distance c (clamped to [0,1]) */
NUM fog_factor(const GlesContext *ctx, NUM c);
/* per vertex: the factor, or the eye distance when fog is per fragment */
NUM fog_vertex_value(const GlesContext *ctx, const NUM eye[4]);

#endif
