/*
** span.h -- the fragment stage's interface: span functions for triangles
** (span.c: the generic reference and fused special cases; span_chain.c:
** the composed chain of span-wide stages) and the buffer a chunk of a span
** flows through.
*/
#ifndef GLES_SPAN_H
#define GLES_SPAN_H

#include "state.h"
#include "texture.h"
#include "fragment.h"

/* the pixels a chunk holds: the chain cuts longer runs. Each stage has a
** fixed cost per chunk, which 128 pays half as often as 64 did on long
** rows; 256 saves a little more but doubles the SpanBuf on the stack
** (benchmarks/README.md) */
#define SPAN_CHUNK 128
/* a bit per slot of a chunk, in 64-bit words (the tests' outcomes) */
#define SPAN_KEEP_WORDS (SPAN_CHUNK / 64)
_Static_assert(SPAN_CHUNK % 64 == 0 && SPAN_CHUNK <= 256, "slots are whole words of bits, offsets are bytes");

/* what a fetch stage leaves: each unit's texels (b->ct), the texel as the
** colour (b->c), or the coordinates only (a later stage samples), in b->tc
** (FETCH_COORDS) or, for a unit without a level of detail whose
** coordinates b->tc cannot keep (a later unit's go there), in b->tx
** (FETCH_COORDS_TX) */
enum { FETCH_TEXELS, FETCH_DIRECT, FETCH_COORDS, FETCH_COORDS_TX };

/* A screen-aligned rectangle of fragments whose inputs are constant but
** for the texture coordinates (DrawTex in drawtex.c, points in point.c):
** colour, depth and fog come from `in`; each enabled unit's coordinates
** are constant (in.tc, in.tdx, in.tdy), linear in the window position
** (s = as + bs X, t = at + bt Y at pixel centre (X, Y), formed in double),
** or a point sprite's (from the point's centre and size in subpixels). */
enum { RECT_COORD_CONST, RECT_COORD_LINEAR, RECT_COORD_SPRITE };
typedef struct RectSetup {
    FragIn in;
    int coord[GLES_MAX_TEXTURE_UNITS];                  /* RECT_COORD_* */
    double as[GLES_MAX_TEXTURE_UNITS], bs[GLES_MAX_TEXTURE_UNITS];
    double at[GLES_MAX_TEXTURE_UNITS], bt[GLES_MAX_TEXTURE_UNITS];
    int64_t sprite_x, sprite_y, sprite_size;            /* subpixels */
    /* span_rect's columns: unit u's s (which depends on the column only) at
    ** column col_x0 + i is col_s[u][i], or col_s[u] is NULL */
    const TEXC *col_s[GLES_MAX_TEXTURE_UNITS];
    int64_t col_x0;
    uint64_t serial;            /* span_rect's ctx->prim_serial (the fused stage's setup) */
} RectSetup;

/* DrawTex's coordinates of unit u: s at pixel column px, t at row py,
** linear in the window position at the pixel centre, formed in double */
static inline TEXC rect_linear_s(const RectSetup *r, int u, int64_t px)
{
    return texc_from_double(r->as[u] + r->bs[u] * ((double)px + 0.5));
}
static inline TEXC rect_linear_t(const RectSetup *r, int u, int64_t py)
{
    return texc_from_double(r->at[u] + r->bt[u] * ((double)py + 0.5));
}

/* the coordinates at pixel (px, py) and its right and upper neighbours */
static inline void rect_linear_coords(const RectSetup *r, int u, int64_t px, int64_t py, TexCoord *tc, TexCoord *tx,
                                      TexCoord *ty)
{
    tc->s = rect_linear_s(r, u, px);
    tc->t = rect_linear_t(r, u, py);
    tx->s = rect_linear_s(r, u, px + 1);
    tx->t = tc->t;
    ty->s = tc->s;
    ty->t = rect_linear_t(r, u, py + 1);
}

/* A point sprite's coordinates for a point at window (x, y) of `size`,
** all in subpixels (OES_point_sprite): s = 1/2 + (x_f + 1/2 - x_w) / size
** at pixel column px, t = 1/2 - (y_f + 1/2 - y_w) / size at row py */
/* s's numerator: the pixel centre's distance from the sprite's left edge */
static inline int64_t sprite_s_num(int64_t x, int64_t size, int64_t px)
{
    return size / 2 + px * GLES_SUBPIXEL_ONE + GLES_SUBPIXEL_ONE / 2 - x;
}
static inline TEXC sprite_s(int64_t x, int64_t size, int64_t px) { return texc_ratio(sprite_s_num(x, size, px), size); }
static inline TEXC sprite_t(int64_t y, int64_t size, int64_t py)
{
    return texc_ratio(size / 2 - (py * GLES_SUBPIXEL_ONE + GLES_SUBPIXEL_ONE / 2 - y), size);
}

/* the coordinates at pixel (px, py) and its right and upper neighbours */
static inline void sprite_coords(int64_t x, int64_t y, int64_t size, int64_t px, int64_t py, TexCoord *tc,
                                 TexCoord *tx, TexCoord *ty)
{
    tc->s = sprite_s(x, size, px);
    tc->t = sprite_t(y, size, py);
    tx->s = sprite_s(x, size, px + 1);
    tx->t = tc->t;
    ty->s = tc->s;
    ty->t = sprite_t(y, size, py + 1);
}

/* One chunk of a row's run: the live fragments and what the stages have
** computed for them so far. Slot j holds the fragment at x0 + k[j]; the
** tests drop fragments by compacting the slots. */
struct SpanBuf {
    int y, x0;                      /* the chunk's first pixel */
    int n;                          /* live fragments */
    uint8_t k[SPAN_CHUNK];          /* their offsets from x0, ascending */
    int64_t e0[3];                  /* edge values at x0 (triangles) */
    const RectSetup *rect;          /* the rectangle (DrawTex, points), else NULL */
    uint32_t z[SPAN_CHUNK];         /* window depth */
    WGT p[SPAN_CHUNK][3];           /* perspective weights */
    WGT px[SPAN_CHUNK][3];          /* the right neighbour's (level of detail) */
    WGT py[SPAN_CHUNK][3];          /* the upper neighbour's */
    FRAGV c[SPAN_CHUNK][4];         /* the colour so far */
    FRAGV cf[SPAN_CHUNK][4];        /* the primary colour, clamped (environments) */
    FRAGV ct[SPAN_CHUNK][GLES_MAX_TEXTURE_UNITS][4];   /* each unit's texel */
    TexCoord tc[SPAN_CHUNK], tx[SPAN_CHUNK], ty[SPAN_CHUNK];   /* one unit's, and its neighbours' */
    int tc_unit, tc_done;           /* tc[0..tc_done) holds unit tc_unit's already (-1: none) */
    int tx_unit, tx_done;           /* likewise tx[0..tx_done), unit tx_unit's (FETCH_COORDS_TX) */
    int lod_unit, lod_done;         /* tc, tx and ty[0..lod_done) hold unit lod_unit's and its neighbours' */
    int lanes;                      /* stage_persp left p, tc and tx to the fused stage (ctx->chain_fused_lanes) */
};

/* 1 when the four slots from k are four neighbouring pixels (offsets
** ascend, so the last one tells) */
static inline int slots_adjacent4(const uint8_t *k) { return k[3] == k[0] + 3; }

/* 1 when the colour mask leaves every channel of the colour buffer as it
** is (RGB565 has no alpha to write) */
static inline int span_no_color(const GlesContext *ctx)
{
    return !ctx->color_mask[0] && !ctx->color_mask[1] && !ctx->color_mask[2]
        && (ctx->color_format == GLES_COLOR_RGB565 || !ctx->color_mask[3]);
}


/* fragment_write's arithmetic on RGBA8888 with every channel written and no
** logic op, for blend kind 0 (none), 1 (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) or
** 2 (ONE, ONE), both FUNC_ADD: colour c over the stored word d */
static inline uint32_t span_rgba8(const GlesContext *ctx, const FRAGV c[4], uint32_t d, int kind)
{
    const FRAGV sa = kind == 1 ? frag_clamp01(c[3]) : FRAG_ONE, da = kind == 1 ? FRAG_ONE - sa : FRAG_ONE;
    uint32_t out = 0;
    for (int i = 0; i < 4; i++) {
        FRAGV v = c[i];
        if (kind)
            v = frag_mul(frag_clamp01(c[i]), sa) + frag_mul(ctx->unorm8[(d >> (8 * i)) & 0xFFu], da);
        out |= frag_to_unorm(v, 255, FRAG_ONE / 2) << (8 * i);
    }
    return out;
}

/* choose the span function (and compose the chain) for the current state */
void span_choose(GlesContext *ctx);
/* the chain's stages for the current state, into ctx->chain */
void span_chain_compose(GlesContext *ctx);
/* run a row's covered run through ctx->chain */
void span_chain(GlesContext *ctx, const TriSetup *t, int y, int x0, int n);
/* the pixels [x0, x1) x [y0, y1) of a rectangle, clipped already */
void span_rect(GlesContext *ctx, const RectSetup *r, int64_t x0, int64_t y0, int64_t x1, int64_t y1);
/* which blend a fused RGBA8888 writer covers: 0 none, 1 SRC_ALPHA,
** ONE_MINUS_SRC_ALPHA, 2 ONE, ONE (FUNC_ADD, the same for alpha), -1 other */
int span_blend_kind(const GlesContext *ctx);
/* pack a [0,1] colour into the framebuffer's format */
uint32_t span_pack_color(const GlesContext *ctx, const FRAGV *c);

#endif
