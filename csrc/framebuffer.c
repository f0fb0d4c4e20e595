/*
** framebuffer.c -- Clear and ReadPixels (ES 1.1 §4.2.3, §4.3.1).
** Owns: writing clear values through the scissor box and the masks, and
**       reading the colour buffer in RGBA/UNSIGNED_BYTE or the buffer's own
**       OES_read_format pair, honouring PACK_ALIGNMENT.
*/
#include <string.h>
#include "state.h"
#include "raster.h"
#include "fragment.h"
#include "fbo.h"

/* the clear rectangle: the framebuffer, cut by the scissor box when enabled */
static void clear_rect(const GlesContext *ctx, int *x0, int *y0, int *x1, int *y1)
{
    ClipRect r = raster_clip_rect(ctx);
    *x0 = (int)i64_clamp(r.x0, 0, ctx->width);
    *y0 = (int)i64_clamp(r.y0, 0, ctx->height);
    *x1 = (int)i64_clamp(r.x1, 0, ctx->width);
    *y1 = (int)i64_clamp(r.y1, 0, ctx->height);
}

/* a Clear's values and rectangle: each thread clears its own rows of it */
typedef struct ClearJob {
    unsigned int mask;
    int x0, y0, x1, y1;
    FRAGV c[4];                 /* the colour (a 16-bit format's dither) */
    uint32_t packed, keep;      /* the colour packed, and the bits the mask keeps */
    uint32_t z;
    uint8_t s, wm;
} ClearJob;

static void clear_rows(GlesContext *ctx, void *arg)
{
    const ClearJob *j = arg;
    const size_t w = (size_t)ctx->width;
    const int x0 = j->x0, x1 = j->x1;
    const uint32_t packed = j->packed, keep = j->keep;
    for (int y = j->y0; y < j->y1; y++) {
        if (!raster_owns_row(ctx, y))
            continue;
        if ((j->mask & GL_COLOR_BUFFER_BIT) && ctx->color_format != GLES_COLOR_RGBA8888) {
            /* §4.2.3: Clear is dithered like fragments (every channel, as
            ** fragment_write dithers), the masks apply */
            /* the threshold depends on x & 3 in a row: four words */
            uint32_t v[4] = { packed, packed, packed, packed };
            if (ctx->dither)
                for (int i = 0; i < 4; i++)
                    v[i] = fragment_pack16(color_layout16(ctx->color_format), j->c, 1,
                                           fragment_dither_threshold(i, y));
            uint16_t *row = (uint16_t *)ctx->color + (size_t)y * w;
            if (!keep) {
                for (int x = x0; x < x1; x++)
                    row[x] = (uint16_t)v[x & 3];
            } else {
                for (int x = x0; x < x1; x++)
                    row[x] = (uint16_t)((row[x] & keep) | (v[x & 3] & ~keep));
            }
        } else if (j->mask & GL_COLOR_BUFFER_BIT) {
            uint32_t *row = (uint32_t *)ctx->color + (size_t)y * w;
            /* every channel written: a fill, no read of what is there */
            if (!keep) {
                for (int x = x0; x < x1; x++)
                    row[x] = packed;
            } else {
                for (int x = x0; x < x1; x++)
                    row[x] = (row[x] & keep) | (packed & ~keep);
            }
        }
        if ((j->mask & GL_DEPTH_BUFFER_BIT) && ctx->depth && ctx->depth_mask) {
            uint32_t *row = ctx->depth + (size_t)y * w;
            for (int x = x0; x < x1; x++)
                row[x] = j->z;
        }
        if ((j->mask & GL_STENCIL_BUFFER_BIT) && ctx->stencil) {
            /* §4.2.3: the stencil write mask applies */
            uint8_t *row = ctx->stencil + (size_t)y * w;
            if (j->wm == 0xFF) {
                memset(row + x0, j->s, (size_t)(x1 - x0));
            } else {
                for (int x = x0; x < x1; x++)
                    row[x] = (uint8_t)((row[x] & ~j->wm) | (j->s & j->wm));
            }
        }
    }
}

int gles_Clear(GlesContext *ctx, unsigned int mask)
{
    const unsigned int legal = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
    if (mask & ~legal) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (!fbo_sync(ctx))
        return GLES_OK;
    ClearJob j = { .mask = mask };
    clear_rect(ctx, &j.x0, &j.y0, &j.x1, &j.y1);
    if (j.x0 >= j.x1 || j.y0 >= j.y1)
        return GLES_OK;
    if (mask & GL_COLOR_BUFFER_BIT) {
        for (int i = 0; i < 4; i++)
            j.c[i] = frag_clamp01(frag_from_double(ctx->clear_color[i]));
        j.packed = span_pack_color(ctx, j.c);
        j.keep = color_mask_keep(ctx->color_format, ctx->color_mask);
    }
    j.z = (uint32_t)dbl_to_i64(ctx->clear_depth * ctx->depth_max, 0, ctx->depth_max);
    j.s = (uint8_t)(ctx->clear_stencil & 0xFF);
    j.wm = (uint8_t)(ctx->stencil_writemask & 0xFF);
    const int64_t pixels = (int64_t)(j.x1 - j.x0) * (j.y1 - j.y0);
    /* a whole-buffer fill is cheap per pixel: threads only for large ones */
    if (!raster_threaded(ctx, pixels / 16, clear_rows, &j, sizeof j, 0))
        clear_rows(ctx, &j);
    return GLES_OK;
}

int gles_ReadPixels(GlesContext *ctx, int x, int y, int width, int height,
                    unsigned int format, unsigned int type, void *out, int64_t nbytes)
{
    if (width < 0 || height < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (!fbo_sync(ctx))
        return GLES_OK;
    raster_join(ctx);
    /* the two pairs: RGBA/UNSIGNED_BYTE, and the buffer's implementation
    ** pair (OES_read_format): its own packed type (RGB/5_6_5, RGBA/4_4_4_4,
    ** RGBA/5_5_5_1), or BGRA_EXT/UNSIGNED_BYTE (EXT_read_format_bgra) */
    const int bgra = ctx->color_format == GLES_COLOR_RGBA8888 && format == GL_BGRA_EXT && type == GL_UNSIGNED_BYTE;
    const int rgba = (format == GL_RGBA && type == GL_UNSIGNED_BYTE) || bgra;
    unsigned int own_format = 0, own_type = 0;
    color_read_pair(ctx->color_format, &own_format, &own_type);
    const int packed16 = ctx->color_format != GLES_COLOR_RGBA8888 && format == own_format && type == own_type;
    if (!rgba && !packed16) {
        /* §4.3.1: a legal token pair that is not one of the two supported
        ** pairs is INVALID_OPERATION; an unknown token INVALID_ENUM */
        int fmt_known = format == GL_RGBA || format == GL_RGB || format == GL_ALPHA
                     || format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA || format == GL_BGRA_EXT;
        int type_known = type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT_5_6_5
                      || type == GL_UNSIGNED_SHORT_4_4_4_4 || type == GL_UNSIGNED_SHORT_5_5_5_1
                      || type == GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT || type == GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT;
        ctx_error(ctx, fmt_known && type_known ? GL_INVALID_OPERATION : GL_INVALID_ENUM);
        return GLES_OK;
    }
    int bpp = rgba ? 4 : 2;
    int64_t rowbytes = (int64_t)width * bpp;
    int64_t stride = (rowbytes + ctx->pack_alignment - 1) / ctx->pack_alignment * ctx->pack_alignment;
    /* width, height < 2^31 and stride < 2^34: the product can pass 2^63,
    ** so compare by division first (a huge read never fits a real buffer) */
    if (height > 1 && stride > (INT64_MAX - rowbytes) / (height - 1))
        return ctx_message(ctx, GLES_EVALUE, "ReadPixels of %d x %d pixels needs more bytes than the buffer holds",
                           width, height);
    int64_t need = height ? stride * (height - 1) + rowbytes : 0;
    if (need > nbytes)
        return ctx_message(ctx, GLES_EVALUE, "ReadPixels needs %lld bytes, the buffer holds %lld",
                           (long long)need, (long long)nbytes);
    /* row by row: the part inside the window is a block conversion (a
    ** copy for the buffer's own format); pixels outside the window are
    ** undefined (§4.3.1), we give 0 */
    /* a 16-bit format's channels to 8 bits, c * 255 / max rounded */
    ColorExpand8 expand = { 0 };   /* read only for a 16-bit format */
    if (rgba && ctx->color_format != GLES_COLOR_RGBA8888)
        color_expand8_init(&expand, ctx->color_format);
    int64_t ix0 = x < 0 ? -(int64_t)x : 0;                              /* first i inside */
    int64_t ix1 = (int64_t)ctx->width - x;                              /* past the last */
    if (ix1 > width)
        ix1 = width;
    if (ix1 < ix0)
        ix1 = ix0;
    uint8_t *dst = out;
    for (int j = 0; j < height; j++) {
        int64_t fy = (int64_t)y + j;
        uint8_t *row = dst + stride * j;
        memset(row, 0, (size_t)rowbytes);
        if (fy < 0 || fy >= ctx->height || ix0 >= ix1)
            continue;
        size_t at = (size_t)fy * (size_t)ctx->width + (size_t)(x + ix0);
        size_t n = (size_t)(ix1 - ix0);
        if (!rgba) {
            memcpy(row + 2 * ix0, (const uint16_t *)ctx->color + at, 2 * n);
        } else if (ctx->color_format == GLES_COLOR_RGBA8888) {
            const uint32_t *src = (const uint32_t *)ctx->color + at;
            uint8_t *o = row + 4 * ix0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
            memcpy(o, src, 4 * n);    /* R in the low byte is R first in memory */
#else
            for (size_t i = 0; i < n; i++) {
                uint32_t v = src[i];
                o[4 * i] = (uint8_t)v; o[4 * i + 1] = (uint8_t)(v >> 8);
                o[4 * i + 2] = (uint8_t)(v >> 16); o[4 * i + 3] = (uint8_t)(v >> 24);
            }
#endif
        } else {
            const uint16_t *src = (const uint16_t *)ctx->color + at;
            uint8_t *o = row + 4 * ix0;
            for (size_t i = 0; i < n; i++)
                color_expand8(&expand, src[i], o + 4 * i);
        }
        if (bgra)
            for (size_t i = 0; i < n; i++) {
                uint8_t *o = row + 4 * (ix0 + (int64_t)i), r = o[0];
                o[0] = o[2];
                o[2] = r;
            }
    }
    return GLES_OK;
}
