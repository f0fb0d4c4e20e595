/*
** texture.c -- texture objects, images and parameters (ES 1.1 §3.7,
** OES_compressed_paletted_texture, OES_texture_mirrored_repeat,
** OES_texture_env_crossbar).
** Owns: Gen/Bind/Delete/IsTexture, TexImage2D and friends, TexParameter,
**       TexEnv, mipmap completeness, GENERATE_MIPMAP; OES_texture_cube_map's
**       cube map objects (six faces, each a Texture of its own images with
**       the cube map's parameters) and their cube completeness.
** Storage: every level is expanded to RGBA8888 at specification time; the
**       base format decides which components the environment uses.
** Sampling is texsample.c; the environment's arithmetic is texenv.c.
*/
#include <stdlib.h>
#include <string.h>
#include "state.h"
#include "raster.h"
#include "array.h"
#include "texture.h"
#include "fbo.h"
#include "debug.h"

static int is_base_format(unsigned int f)
{
    return f == GL_ALPHA || f == GL_LUMINANCE || f == GL_LUMINANCE_ALPHA || f == GL_RGB || f == GL_RGBA;
}

/* the formats TexImage2D and TexSubImage2D take: Table 3.8's and
** EXT_texture_format_BGRA8888's BGRA_EXT, which is an RGBA texture with
** its bytes in the other order */
static int is_upload_format(unsigned int f) { return is_base_format(f) || f == GL_BGRA_EXT; }

unsigned int texture_base_format(unsigned int f)
{
    return f == GL_BGRA_EXT ? GL_RGBA : (f == GL_ETC1_RGB8_OES ? GL_RGB : f);
}

static void texture_defaults(Texture *t, unsigned int name)
{
    memset(t, 0, sizeof *t);
    t->name = name;
    t->min_filter = GL_NEAREST_MIPMAP_LINEAR;
    t->mag_filter = GL_LINEAR;
    t->wrap_s = t->wrap_t = GL_REPEAT;
    t->level_limit = 1000;
    t->max_aniso = 1.0;
}

/* bytes a level's texels hold (the memory budget counts them) */
static int64_t level_bytes(const TexImage *li)
{
    return li->texels ? (int64_t)li->width * li->height * (int64_t)sizeof *li->texels : 0;
}

/* bytes held by levels [from, to) */
static int64_t levels_bytes(const Texture *t, int from, int to)
{
    int64_t n = 0;
    for (int i = from; i < to; i++)
        n += level_bytes(&t->level[i]);
    return n;
}

/* bytes of the levels GENERATE_MIPMAP derives below a w x h level 0 */
static int64_t chain_bytes(int w, int h)
{
    int64_t n = 0;
    if (w <= 0 || h <= 0)
        return 0;
    while (w > 1 || h > 1) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        n += (int64_t)w * h * (int64_t)sizeof(uint32_t);
    }
    return n;
}

static void texture_release(GlesContext *ctx, Texture *t)
{
    for (int i = 0; i < GLES_MAX_TEXTURE_LEVELS; i++) {
        ctx->mem_used -= level_bytes(&t->level[i]);
        free(t->level[i].texels);
        t->level[i].texels = NULL;
    }
    if (t->face[0]) {
        for (int f = 0; f < 6; f++)
            texture_release(ctx, t->face[f]);
        free(t->face[0]);      /* the six are one block */
        memset(t->face, 0, sizeof t->face);
    }
}

/* make t (a name's first binding) a texture of `target` for life: a cube
** map gets its six faces; 0 when there is no memory for them */
static int texture_make(Texture *t, unsigned int target)
{
    t->target = target;
    if (target != GL_TEXTURE_CUBE_MAP_OES)
        return 1;
    Texture *faces = malloc(6 * sizeof *faces);
    if (!faces)
        return 0;
    for (int f = 0; f < 6; f++) {
        texture_defaults(&faces[f], t->name);
        faces[f].target = GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + (unsigned int)f;
        faces[f].cube = t;
        t->face[f] = &faces[f];
    }
    return 1;
}

void texture_unit_update(TexUnit *tu)
{
    tu->enabled = tu->enabled_2d || tu->enabled_cube;
    /* §3.8.10: with both enabled, cube map texturing is used */
    tu->bound = tu->enabled_cube ? tu->bound_cube : tu->bound_2d;
}

int texture_init(GlesContext *ctx)
{
    names_init(&ctx->textures);
    texture_defaults(&ctx->default_texture, 0);
    texture_make(&ctx->default_texture, GL_TEXTURE_2D);
    texture_defaults(&ctx->default_cube, 0);
    const int faces = texture_make(&ctx->default_cube, GL_TEXTURE_CUBE_MAP_OES);
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
        TexUnit *tu = &ctx->units[u];
        memset(tu, 0, sizeof *tu);
        tu->bound_2d = tu->bound = &ctx->default_texture;
        tu->bound_cube = &ctx->default_cube;
        tu->texgen_mode = GL_REFLECTION_MAP_OES;
        tu->env_mode = GL_MODULATE;
        tu->combine_rgb = tu->combine_alpha = GL_MODULATE;
        tu->src_rgb[0] = tu->src_alpha[0] = GL_TEXTURE;
        tu->src_rgb[1] = tu->src_alpha[1] = GL_PREVIOUS;
        tu->src_rgb[2] = tu->src_alpha[2] = GL_CONSTANT;
        tu->op_rgb[0] = tu->op_rgb[1] = GL_SRC_COLOR;
        tu->op_rgb[2] = GL_SRC_ALPHA;
        tu->op_alpha[0] = tu->op_alpha[1] = tu->op_alpha[2] = GL_SRC_ALPHA;
        tu->rgb_scale = tu->alpha_scale = 1.0;
    }
    for (uint32_t c = 0; c < 256; c++)
        ctx->texel_unorm8[c] = frag_from_unorm(c, 255);
    return faces;
}

void texture_free(GlesContext *ctx)
{
    NameTable *nt = &ctx->textures;
    for (uint32_t i = 0; i < nt->capacity; i++) {
        Texture *t = nt->keys[i] && nt->keys[i] != ~0u ? nt->values[i] : NULL;
        if (t) {
            texture_release(ctx, t);
            free(t);
        }
    }
    names_free(nt);
    texture_release(ctx, &ctx->default_texture);
    texture_release(ctx, &ctx->default_cube);
}

static TexUnit *active_unit(GlesContext *ctx) { return &ctx->units[ctx->active_texture - GL_TEXTURE0]; }

static int needs_mipmaps(unsigned int min_filter)
{
    return min_filter != GL_NEAREST && min_filter != GL_LINEAR;
}

/* §3.7.10: level 0 defined, and with a mipmapped filter every level down to
** 1x1 defined with halved sizes and the same format; with
** APPLE_texture_max_level, the levels down to TEXTURE_MAX_LEVEL_APPLE when
** that comes first, and no level past it is sampled */
static void texture_complete(Texture *t)
{
    const TexImage *l0 = &t->level[0];
    t->complete = 0;
    t->max_level = 0;
    if (l0->width <= 0 || l0->height <= 0 || !l0->texels)
        return;
    if (!needs_mipmaps(t->min_filter)) {
        t->complete = 1;
        return;
    }
    int w = l0->width, h = l0->height, i = 0;
    while ((w > 1 || h > 1) && i < t->level_limit) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        i++;
        const TexImage *li = &t->level[i];
        if (li->width != w || li->height != h || !li->texels || t->level_format[i] != t->level_format[0])
            return;
    }
    t->max_level = i;
    t->complete = 1;
}

/* after a change to t's images or parameters: its completeness; for a cube
** map (or one of its faces) the cube map's parameters copied into the
** faces, each face's mipmap completeness, and the cube map's: complete
** when every face is (with a mipmapped filter, "mipmap cube complete") and
** the six level-0 images are square, of one size and one internal format
** (§3.8.1, §3.8.5 of the extension). The cube map's level 0 holds the
** faces' size (no texels), which DrawTex's crop rectangle reads */
static void texture_update(Texture *t)
{
    if (t->cube)
        t = t->cube;
    if (!t->face[0]) {
        texture_complete(t);
        return;
    }
    for (int f = 0; f < 6; f++) {
        Texture *fc = t->face[f];
        fc->min_filter = t->min_filter;
        fc->mag_filter = t->mag_filter;
        fc->wrap_s = t->wrap_s;
        fc->wrap_t = t->wrap_t;
        fc->generate_mipmap = t->generate_mipmap;
        fc->level_limit = t->level_limit;
        fc->max_aniso = t->max_aniso;
        texture_complete(fc);
    }
    const Texture *f0 = t->face[0];
    const int size = f0->level[0].width;
    t->format = f0->format;
    t->level[0].width = size;
    t->level[0].height = f0->level[0].height;
    t->complete = 0;
    t->max_level = 0;
    for (int f = 0; f < 6; f++) {
        const Texture *fc = t->face[f];
        if (!fc->complete || fc->level[0].width != size || fc->level[0].height != size
            || fc->level_format[0] != f0->level_format[0])
            return;
    }
    t->max_level = f0->max_level;
    t->complete = 1;
}

const Texture *texture_active(const GlesContext *ctx, int unit)
{
    const TexUnit *tu = &ctx->units[unit];
    return tu->enabled && tu->bound->complete ? tu->bound : NULL;
}

void texture_validate(GlesContext *ctx)
{
    ctx->tex_units_on = ctx->cube_units = ctx->texgen_units = 0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (texture_active(ctx, u)) {
            ctx->tex_units_on |= 1u << u;
            ctx->cube_units |= (unsigned)(ctx->units[u].enabled_cube != 0) << u;
            ctx->texgen_units |= (unsigned)(ctx->units[u].texgen != 0) << u;
        }
}

/* the texture TexImage2D and its kin address on the active unit: the 2D
** binding's for TEXTURE_2D, a face of the cube map binding's for a face
** target; NULL for any other target (INVALID_ENUM) */
static Texture *image_target(GlesContext *ctx, unsigned int target)
{
    TexUnit *tu = &ctx->units[ctx->active_texture - GL_TEXTURE0];
    if (target == GL_TEXTURE_2D)
        return tu->bound_2d;
    if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_OES)
        return tu->bound_cube->face[target - GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES];
    return NULL;
}

/* the texture TexParameter and its kin address: TEXTURE_2D's or
** TEXTURE_CUBE_MAP_OES's binding on the active unit, else NULL */
static Texture *param_target(GlesContext *ctx, unsigned int target)
{
    TexUnit *tu = &ctx->units[ctx->active_texture - GL_TEXTURE0];
    return target == GL_TEXTURE_2D ? tu->bound_2d : (target == GL_TEXTURE_CUBE_MAP_OES ? tu->bound_cube : NULL);
}

/* a cube map face's images are square (the extension's INVALID_VALUE) */
static int face_not_square(const Texture *t, int width, int height) { return t->cube && width != height; }

/* {====================================================================
** objects */

void gles_GenTextures(GlesContext *ctx, int n, unsigned int *names)
{
    raster_join(ctx);
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    names_generate(&ctx->textures, n, names);
}

void gles_DeleteTextures(GlesContext *ctx, int n, const unsigned int *names)
{
    raster_join(ctx);
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    for (int i = 0; i < n; i++) {
        if (names[i] == 0)
            continue;
        Texture *t = names_remove(&ctx->textures, names[i]);
        if (!t)
            continue;
        debug_object_deleted(ctx, DEBUG_NS_TEXTURE, names[i]);
        /* §3.7.13: a deleted bound texture reverts the binding to 0 */
        for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++) {
            TexUnit *tu = &ctx->units[u];
            if (tu->bound_2d == t)
                tu->bound_2d = &ctx->default_texture;
            if (tu->bound_cube == t)
                tu->bound_cube = &ctx->default_cube;
            texture_unit_update(tu);
        }
        fbo_texture_deleted(ctx, t);
        for (int f = 0; f < 6 && t->face[f]; f++)
            fbo_texture_deleted(ctx, t->face[f]);
        texture_release(ctx, t);
        free(t);
    }
    ctx->dirty |= DIRTY_TEXTURE;
}

void gles_BindTexture(GlesContext *ctx, unsigned int target, unsigned int name)
{
    raster_join(ctx);
    if (target != GL_TEXTURE_2D && target != GL_TEXTURE_CUBE_MAP_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    Texture *t = target == GL_TEXTURE_2D ? &ctx->default_texture : &ctx->default_cube;
    if (name != 0) {
        t = names_lookup(&ctx->textures, name);
        if (!t) {
            t = malloc(sizeof *t);
            if (t)
                texture_defaults(t, name);
            if (!t || !texture_make(t, target) || !names_insert(&ctx->textures, name, t)) {
                if (t)
                    texture_release(ctx, t);
                free(t);
                ctx_error(ctx, GL_OUT_OF_MEMORY);
                return;
            }
        }
    }
    /* a name stays a texture of the target it was first bound to (§3.8.8
    ** of the extension) */
    if (t->target != target) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    TexUnit *tu = active_unit(ctx);
    if (target == GL_TEXTURE_2D)
        tu->bound_2d = t;
    else
        tu->bound_cube = t;
    texture_unit_update(tu);
    ctx->dirty |= DIRTY_TEXTURE;
}

unsigned char gles_IsTexture(GlesContext *ctx, unsigned int name)
{
    return name != 0 && names_lookup(&ctx->textures, name) != NULL;
}

/* {====================================================================
** images */

static uint32_t pack(uint32_t r, uint32_t g, uint32_t b, uint32_t a) { return r | (g << 8) | (b << 16) | (a << 24); }
static uint32_t x5(uint32_t c) { return (c * 255 + 15) / 31; }
static uint32_t x6(uint32_t c) { return (c * 255 + 31) / 63; }
static uint32_t x4(uint32_t c) { return c * 17; }

/* bytes per pixel of a legal format/type pair, 0 when the pair is illegal */
static int pixel_bytes(unsigned int format, unsigned int type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE:
        switch (format) {
        case GL_RGBA: case GL_BGRA_EXT: return 4;
        case GL_RGB: return 3;
        case GL_LUMINANCE_ALPHA: return 2;
        case GL_LUMINANCE: case GL_ALPHA: return 1;
        default: return 0;
        }
    case GL_UNSIGNED_SHORT_5_6_5: return format == GL_RGB ? 2 : 0;
    case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_5_5_5_1: return format == GL_RGBA ? 2 : 0;
    default: return 0;
    }
}

/* one client pixel to RGBA8888 */
static uint32_t unpack_pixel(unsigned int format, unsigned int type, const uint8_t *p)
{
    if (type == GL_UNSIGNED_BYTE) {
        switch (format) {
        case GL_RGBA: return pack(p[0], p[1], p[2], p[3]);
        case GL_BGRA_EXT: return pack(p[2], p[1], p[0], p[3]);
        case GL_RGB: return pack(p[0], p[1], p[2], 255);
        case GL_LUMINANCE_ALPHA: return pack(p[0], p[0], p[0], p[1]);
        case GL_LUMINANCE: return pack(p[0], p[0], p[0], 255);
        default: return pack(0, 0, 0, p[0]); /* GL_ALPHA */
        }
    }
    uint16_t v;
    memcpy(&v, p, 2);
    switch (type) {
    case GL_UNSIGNED_SHORT_5_6_5: return pack(x5(v >> 11), x6((v >> 5) & 63), x5(v & 31), 255);
    case GL_UNSIGNED_SHORT_4_4_4_4: return pack(x4(v >> 12), x4((v >> 8) & 15), x4((v >> 4) & 15), x4(v & 15));
    default: return pack(x5(v >> 11), x5((v >> 6) & 31), x5((v >> 1) & 31), (v & 1) ? 255 : 0);
    }
}

static int64_t unpack_stride(const GlesContext *ctx, int width, int bpp)
{
    int64_t row = (int64_t)width * bpp, a = ctx->unpack_alignment;
    return (row + a - 1) / a * a;
}

int64_t texture_image_bytes(const GlesContext *ctx, int width, int height, unsigned int format, unsigned int type)
{
    int bpp = pixel_bytes(format, type);
    if (!bpp || width <= 0 || height <= 0)
        return 0;
    return unpack_stride(ctx, width, bpp) * (height - 1) + (int64_t)width * bpp;
}

static int max_level_of_size(void)
{
    int l = 0;
    for (int s = GLES_MAX_TEXTURE_SIZE; s > 1; s /= 2)
        l++;
    return l;
}

/* (re)allocate a level; returns 0 on no memory (malloc's or the budget's) */
static int level_alloc(GlesContext *ctx, TexImage *li, int width, int height)
{
    size_t n = (size_t)width * (size_t)height;
    int64_t add = (int64_t)n * (int64_t)sizeof(uint32_t), release = level_bytes(li);
    if (!ctx_mem_fits(ctx, add, release))
        return 0;
    uint32_t *texels = n ? calloc(n, sizeof *texels) : NULL;
    if (n && !texels)
        return 0;
    free(li->texels);
    ctx->mem_used += add - release;
    li->texels = texels;
    li->width = width;
    li->height = height;
    return 1;
}

/* GENERATE_MIPMAP: every level below 0 from a 2x2 box filter, rounded; an
** empty level 0 leaves every level below it empty too */
static int generate_mipmaps(GlesContext *ctx, Texture *t)
{
    int w = t->level[0].width, h = t->level[0].height;
    if (w <= 0 || h <= 0 || !t->level[0].texels) {
        for (int i = 1; i < GLES_MAX_TEXTURE_LEVELS; i++)
            if (!level_alloc(ctx, &t->level[i], 0, 0))
                return 0;
        return 1;
    }
    for (int i = 1; w > 1 || h > 1; i++) {
        int nw = w > 1 ? w / 2 : 1, nh = h > 1 ? h / 2 : 1;
        TexImage *src = &t->level[i - 1], *dst = &t->level[i];
        if (!level_alloc(ctx, dst, nw, nh))
            return 0;
        t->level_format[i] = t->level_format[0];
        for (int y = 0; y < nh; y++)
            for (int x = 0; x < nw; x++) {
                int x0 = w > 1 ? 2 * x : 0, y0 = h > 1 ? 2 * y : 0;
                int x1 = w > 1 ? x0 + 1 : x0, y1 = h > 1 ? y0 + 1 : y0;
                uint32_t q[4] = { src->texels[y0 * w + x0], src->texels[y0 * w + x1],
                                  src->texels[y1 * w + x0], src->texels[y1 * w + x1] };
                uint32_t out = 0;
                for (int k = 0; k < 4; k++) {
                    uint32_t sum = 0;
                    for (int j = 0; j < 4; j++)
                        sum += (q[j] >> (8 * k)) & 0xFFu;
                    out |= ((sum + 2) / 4) << (8 * k);
                }
                dst->texels[y * nw + x] = out;
            }
        w = nw;
        h = nh;
    }
    return 1;
}

static void image_changed(GlesContext *ctx, Texture *t, int level)
{
    if (level == 0 && t->generate_mipmap && !generate_mipmaps(ctx, t))
        ctx_error(ctx, GL_OUT_OF_MEMORY);
    texture_update(t);
    ctx->dirty |= DIRTY_TEXTURE;
}

/* does the budget allow level `level` of t to become w x h, with the
** levels GENERATE_MIPMAP then derives from it */
static int image_fits(const GlesContext *ctx, const Texture *t, int level, int w, int h)
{
    int64_t add = (int64_t)w * h * (int64_t)sizeof(uint32_t), release = level_bytes(&t->level[level]);
    if (level == 0 && t->generate_mipmap) {
        add += chain_bytes(w, h);
        release += levels_bytes(t, 1, GLES_MAX_TEXTURE_LEVELS);
    }
    return ctx_mem_fits(ctx, add, release);
}

/* common checks of TexImage2D-like calls; returns the GL error or 0 */
static unsigned int check_image(int level, int width, int height, int border)
{
    if (level < 0 || level > max_level_of_size())
        return GL_INVALID_VALUE;
    /* any size up to the limit: OES_texture_npot lifts §3.7.1's powers of two */
    if (width < 0 || height < 0 || width > GLES_MAX_TEXTURE_SIZE || height > GLES_MAX_TEXTURE_SIZE || border != 0)
        return GL_INVALID_VALUE;
    return 0;
}

static int is_palette_format(unsigned int f) { return f >= GL_PALETTE4_RGB8_OES && f <= GL_PALETTE8_RGB5_A1_OES; }

int gles_TexImage2D(GlesContext *ctx, unsigned int target, int level, int internalformat, int width, int height,
                    int border, unsigned int format, unsigned int type, const void *pixels, int64_t nbytes)
{
    raster_join(ctx);
    /* a PALETTE* internal format is not one of Table 3.8's: INVALID_VALUE
    ** (§3.7.1), whatever format and type say (as piglit's paletted API
    ** test expects of ES; the extension's INVALID_OPERATION is for the
    ** sub-image commands) */
    Texture *t = image_target(ctx, target);
    if (t && is_palette_format((unsigned int)internalformat)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (!t || !is_upload_format(format)
        || (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT_5_6_5 && type != GL_UNSIGNED_SHORT_4_4_4_4
            && type != GL_UNSIGNED_SHORT_5_5_5_1)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return GLES_OK;
    }
    unsigned int err = check_image(level, width, height, border);
    if (!err && face_not_square(t, width, height))
        err = GL_INVALID_VALUE;
    if (!err && !is_upload_format((unsigned int)internalformat))
        err = GL_INVALID_VALUE;
    if (!err && ((unsigned int)internalformat != format || !pixel_bytes(format, type)))
        err = GL_INVALID_OPERATION;
    if (err) {
        ctx_error(ctx, err);
        return GLES_OK;
    }
    int64_t need = texture_image_bytes(ctx, width, height, format, type);
    if (pixels && nbytes >= 0 && need > nbytes)
        return ctx_message(ctx, GLES_EVALUE, "TexImage2D reads %lld bytes, the pixel data holds %lld",
                           (long long)need, (long long)nbytes);
    TexImage *li = &t->level[level];
    if (!image_fits(ctx, t, level, width, height) || !level_alloc(ctx, li, width, height)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return GLES_OK;
    }
    t->level_format[level] = format;
    if (level == 0) {
        t->format = texture_base_format(format);
        t->paletted = 0;
    }
    if (pixels) {
        int bpp = pixel_bytes(format, type);
        int64_t stride = unpack_stride(ctx, width, bpp);
        for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++)
                li->texels[(size_t)y * width + x] =
                    unpack_pixel(format, type, (const uint8_t *)pixels + y * stride + (int64_t)x * bpp);
    } else if (format == GL_RGB || format == GL_LUMINANCE) {
        /* no data: undefined contents, which we make zero bytes' texels;
        ** for a format without alpha that is alpha 1, what a framebuffer
        ** object drawing into it must read as its destination alpha */
        static const uint8_t zero[4];
        const uint32_t texel = unpack_pixel(format, type, zero);
        for (size_t i = 0; i < (size_t)width * (size_t)height; i++)
            li->texels[i] = texel;
    }
    image_changed(ctx, t, level);
    return GLES_OK;
}

int gles_TexSubImage2D(GlesContext *ctx, unsigned int target, int level, int xoffset, int yoffset, int width,
                       int height, unsigned int format, unsigned int type, const void *pixels, int64_t nbytes)
{
    raster_join(ctx);
    Texture *t = image_target(ctx, target);
    if (!t || !is_upload_format(format)
        || (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT_5_6_5 && type != GL_UNSIGNED_SHORT_4_4_4_4
            && type != GL_UNSIGNED_SHORT_5_5_5_1)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return GLES_OK;
    }
    if (level < 0 || level > max_level_of_size() || width < 0 || height < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    TexImage *li = &t->level[level];
    if (!li->texels && !(li->width == 0 || li->height == 0)) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return GLES_OK;
    }
    if (xoffset < 0 || yoffset < 0 || (int64_t)xoffset + width > li->width || (int64_t)yoffset + height > li->height) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (t->paletted || !pixel_bytes(format, type) || format != t->level_format[level]) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return GLES_OK;
    }
    if (!width || !height || !pixels)
        return GLES_OK;
    int64_t need = texture_image_bytes(ctx, width, height, format, type);
    if (nbytes >= 0 && need > nbytes)
        return ctx_message(ctx, GLES_EVALUE, "TexSubImage2D reads %lld bytes, the pixel data holds %lld",
                           (long long)need, (long long)nbytes);
    if (!image_fits(ctx, t, level, li->width, li->height)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return GLES_OK;
    }
    int bpp = pixel_bytes(format, type);
    int64_t stride = unpack_stride(ctx, width, bpp);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            li->texels[(size_t)(yoffset + y) * li->width + (xoffset + x)] =
                unpack_pixel(format, type, (const uint8_t *)pixels + y * stride + (int64_t)x * bpp);
    image_changed(ctx, t, level);
    return GLES_OK;
}

/* §3.7.2: the components kept for a base format copied from the framebuffer */
static uint32_t as_base_format(uint32_t c, unsigned int format)
{
    uint32_t r = c & 0xFF, g = (c >> 8) & 0xFF, b = (c >> 16) & 0xFF, a = c >> 24;
    switch (format) {
    case GL_ALPHA: return pack(0, 0, 0, a);
    case GL_LUMINANCE: return pack(r, r, r, 255);
    case GL_LUMINANCE_ALPHA: return pack(r, r, r, a);
    case GL_RGB: return pack(r, g, b, 255);
    default: return c;
    }
}

/* `n` framebuffer pixels of row y from column x, as texels of a base
** format (§3.7.2), into dst: a block copy of the row's part inside the
** window (a pixel outside it reads as 0) */
static void copy_framebuffer_row(const GlesContext *ctx, const ColorExpand8 *expand, int64_t x, int64_t y, int n,
                                 unsigned int format, uint32_t *dst)
{
    const uint32_t outside = as_base_format(0, format);
    int64_t lo = 0, hi = 0;     /* dst[lo, hi) lies inside the window */
    if (y >= 0 && y < ctx->height) {
        lo = x < 0 ? (-x < n ? -x : n) : 0;
        hi = ctx->width - x < n ? ctx->width - x : n;
        if (hi < lo)
            hi = lo;
    }
    for (int64_t i = 0; i < lo; i++)
        dst[i] = outside;
    const size_t at = hi > lo ? (size_t)y * (size_t)ctx->width + (size_t)(x + lo) : 0;
    if (hi > lo && ctx->color_format != GLES_COLOR_RGBA8888) {
        /* a 16-bit format's channels to 8 bits as texels of 4_4_4_4,
        ** 5_5_5_1 and 5_6_5 are (c * 255 / max rounded) */
        const uint16_t *src = (const uint16_t *)ctx->color + at;
        for (int64_t i = lo; i < hi; i++) {
            uint8_t c[4];
            color_expand8(expand, src[i - lo], c);
            dst[i] = as_base_format(pack(c[0], c[1], c[2], c[3]), format);
        }
    } else if (hi > lo && format == GL_RGBA) {
        memcpy(dst + lo, (const uint32_t *)ctx->color + at, (size_t)(hi - lo) * sizeof *dst);
    } else if (hi > lo) {
        const uint32_t *src = (const uint32_t *)ctx->color + at;
        for (int64_t i = lo; i < hi; i++)
            dst[i] = as_base_format(src[i - lo], format);
    }
    for (int64_t i = hi; i < n; i++)
        dst[i] = outside;
}

/* the framebuffer's width x height pixels from (x, y), row j into
** dst + j * stride, as texels of base format `format` */
static void copy_framebuffer_rect(const GlesContext *ctx, int64_t x, int64_t y, int width, int height,
                                  unsigned int format, uint32_t *dst, size_t stride)
{
    ColorExpand8 expand = { 0 };   /* read only for a 16-bit format */
    if (ctx->color_format != GLES_COLOR_RGBA8888)
        color_expand8_init(&expand, ctx->color_format);
    for (int j = 0; j < height && width; j++)
        copy_framebuffer_row(ctx, &expand, x, y + j, width, format, dst + (size_t)j * stride);
}

/* may a base format be copied from this framebuffer (it needs alpha bits for
** ALPHA, LUMINANCE_ALPHA and RGBA) */
static int copy_compatible(const GlesContext *ctx, unsigned int format)
{
    int has_alpha = ctx->color_alpha;
    return has_alpha || !(format == GL_ALPHA || format == GL_LUMINANCE_ALPHA || format == GL_RGBA);
}

void gles_CopyTexImage2D(GlesContext *ctx, unsigned int target, int level, unsigned int internalformat, int x, int y,
                         int width, int height, int border)
{
    raster_join(ctx);
    Texture *t = image_target(ctx, target);
    if (!t) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (!fbo_sync(ctx))
        return;
    unsigned int err = check_image(level, width, height, border);
    if (!err && (face_not_square(t, width, height) || !is_base_format(internalformat)))
        err = GL_INVALID_VALUE;
    if (!err && !copy_compatible(ctx, internalformat))
        err = GL_INVALID_OPERATION;
    if (err) {
        ctx_error(ctx, err);
        return;
    }
    TexImage *li = &t->level[level];
    size_t count = (size_t)width * (size_t)height;
    if (!image_fits(ctx, t, level, width, height)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    uint32_t *tmp = count ? malloc(count * sizeof *tmp) : NULL;
    if (count && !tmp) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    if (count)
        copy_framebuffer_rect(ctx, x, y, width, height, internalformat, tmp, (size_t)width);
    ctx->mem_used -= level_bytes(li);
    free(li->texels);
    li->texels = tmp;
    li->width = width;
    li->height = height;
    ctx->mem_used += level_bytes(li);
    t->level_format[level] = internalformat;
    if (level == 0) {
        t->format = internalformat;
        t->paletted = 0;
    }
    image_changed(ctx, t, level);
}

void gles_CopyTexSubImage2D(GlesContext *ctx, unsigned int target, int level, int xoffset, int yoffset, int x, int y,
                            int width, int height)
{
    raster_join(ctx);
    Texture *t = image_target(ctx, target);
    if (!t) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (!fbo_sync(ctx))
        return;
    if (level < 0 || level > max_level_of_size() || width < 0 || height < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    TexImage *li = &t->level[level];
    if (xoffset < 0 || yoffset < 0 || (int64_t)xoffset + width > li->width || (int64_t)yoffset + height > li->height) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    /* ETC1 levels take no sub-images (OES_compressed_ETC1_RGB8_texture) */
    if (t->paletted || t->level_format[level] == GL_ETC1_RGB8_OES
        || !copy_compatible(ctx, texture_base_format(t->level_format[level]))) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    if (width && height && !image_fits(ctx, t, level, li->width, li->height)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    /* from the level itself (a framebuffer object drawing into it: the
    ** result is undefined, §4.4.3 of EXT_framebuffer_object, but the rows
    ** may overlap): through a copy */
    const int self = ctx->color == (void *)li->texels;
    uint32_t *from = self && width && height ? malloc((size_t)width * (size_t)height * sizeof *from) : NULL;
    if (self && width && height && !from) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    uint32_t *at = li->texels + (size_t)yoffset * (size_t)li->width + (size_t)xoffset;
    copy_framebuffer_rect(ctx, x, y, width, height, texture_base_format(t->level_format[level]), from ? from : at,
                          from ? (size_t)width : (size_t)li->width);
    for (int j = 0; from && j < height; j++)
        memcpy(li->texels + (size_t)(yoffset + j) * (size_t)li->width + (size_t)xoffset,
               from + (size_t)j * (size_t)width, (size_t)width * sizeof *from);
    free(from);
    if (width && height)
        image_changed(ctx, t, level);
}

/* OES_framebuffer_object: the levels below level 0, as GENERATE_MIPMAP
** makes them */
void gles_GenerateMipmapOES(GlesContext *ctx, unsigned int target)
{
    raster_join(ctx);
    Texture *t = param_target(ctx, target);
    if (!t) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    /* a cube map: each face's, when the six level-0 images are "cube
    ** complete" (EXT_framebuffer_object: INVALID_OPERATION otherwise) */
    const int faces = t->face[0] ? 6 : 1;
    Texture *const *each = t->face[0] ? t->face : &t;
    int64_t add = 0, release = 0;
    for (int f = 0; f < faces; f++) {
        const Texture *e = each[f];
        const TexImage *l0 = &e->level[0], *first = &each[0]->level[0];
        if (!l0->texels || l0->width <= 0 || l0->height <= 0 || e->paletted || e->level_format[0] == GL_ETC1_RGB8_OES
            || (faces == 6 && (l0->width != l0->height || l0->width != first->width
                               || e->level_format[0] != each[0]->level_format[0]))) {
            ctx_error(ctx, GL_INVALID_OPERATION);
            return;
        }
        add += chain_bytes(l0->width, l0->height);
        release += levels_bytes(e, 1, GLES_MAX_TEXTURE_LEVELS);
    }
    if (!ctx_mem_fits(ctx, add, release)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    for (int f = 0; f < faces; f++)
        if (!generate_mipmaps(ctx, each[f])) {
            ctx_error(ctx, GL_OUT_OF_MEMORY);
            break;
        }
    texture_update(t);
    ctx->dirty |= DIRTY_TEXTURE;
}

/* OES_compressed_paletted_texture: 16 or 256 palette entries, then 4- or
** 8-bit indices for -level + 1 mip levels (4-bit: first texel in the high
** nibble; each level starts on a byte) */
typedef struct PaletteFormat {
    unsigned int format;
    int index_bits, entry_bytes;
    unsigned int base;
    unsigned int type;          /* how an entry unpacks */
    unsigned int entry_format;
} PaletteFormat;

static const PaletteFormat palette_formats[10] = {
    { GL_PALETTE4_RGB8_OES, 4, 3, GL_RGB, GL_UNSIGNED_BYTE, GL_RGB },
    { GL_PALETTE4_RGBA8_OES, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, GL_RGBA },
    { GL_PALETTE4_R5_G6_B5_OES, 4, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, GL_RGB },
    { GL_PALETTE4_RGBA4_OES, 4, 2, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, GL_RGBA },
    { GL_PALETTE4_RGB5_A1_OES, 4, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, GL_RGBA },
    { GL_PALETTE8_RGB8_OES, 8, 3, GL_RGB, GL_UNSIGNED_BYTE, GL_RGB },
    { GL_PALETTE8_RGBA8_OES, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, GL_RGBA },
    { GL_PALETTE8_R5_G6_B5_OES, 8, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, GL_RGB },
    { GL_PALETTE8_RGBA4_OES, 8, 2, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, GL_RGBA },
    { GL_PALETTE8_RGB5_A1_OES, 8, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, GL_RGBA },
};

static const PaletteFormat *palette_format(unsigned int f)
{
    for (int i = 0; i < 10; i++)
        if (palette_formats[i].format == f)
            return &palette_formats[i];
    return NULL;
}

int64_t texture_paletted_bytes(unsigned int internalformat, int levels, int width, int height)
{
    const PaletteFormat *pf = palette_format(internalformat);
    if (!pf)
        return -1;
    int64_t bytes = (int64_t)(1 << pf->index_bits) * pf->entry_bytes;
    int w = width, h = height;
    for (int i = 0; i < levels; i++) {
        bytes += ((int64_t)w * h * pf->index_bits + 7) / 8;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    return bytes;
}

/* {====================================================================
** OES_compressed_ETC1_RGB8_texture: 4x4 blocks of 64 bits, most
** significant byte first, in rows of blocks from the image's first row;
** each block two half-blocks (2x4 side by side, or 4x2 one above the
** other with the flip bit) of a base colour and an intensity table, each
** texel the base plus one of its table's four modifiers, clamped */

static const int etc1_modifiers[8][2] = {
    { 2, 8 }, { 5, 17 }, { 9, 29 }, { 13, 42 }, { 18, 60 }, { 24, 80 }, { 33, 106 }, { 47, 183 },
};

static int64_t etc1_bytes(int width, int height)
{
    return (((int64_t)width + 3) / 4) * (((int64_t)height + 3) / 4) * 8;
}

static int etc1_clamp(int v) { return v < 0 ? 0 : (v > 255 ? 255 : v); }

/* one block's 16 texels into out (row stride `stride`), clipped to w x h */
static void etc1_block(const uint8_t *p, uint32_t *out, int64_t stride, int w, int h)
{
    const uint32_t hi = (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
    const uint32_t lo = (uint32_t)p[4] << 24 | (uint32_t)p[5] << 16 | (uint32_t)p[6] << 8 | p[7];
    int base[2][3];
    if (hi & 2) {
        /* differential: a 5-bit colour and a signed 3-bit offset to the
        ** second (a sum outside 0..31 is undefined; it wraps to 5 bits) */
        for (int c = 0; c < 3; c++) {
            const int shift = 27 - 8 * c;
            const int c1 = (int)(hi >> shift) & 31;
            const int d3 = (int)(hi >> (shift - 3)) & 7, d = d3 >= 4 ? d3 - 8 : d3;
            const int c2 = (c1 + d) & 31;
            base[0][c] = c1 << 3 | c1 >> 2;
            base[1][c] = c2 << 3 | c2 >> 2;
        }
    } else {
        /* individual: two 4-bit colours */
        for (int c = 0; c < 3; c++) {
            const int c1 = (int)(hi >> (28 - 8 * c)) & 15, c2 = (int)(hi >> (24 - 8 * c)) & 15;
            base[0][c] = c1 * 17;
            base[1][c] = c2 * 17;
        }
    }
    const int table[2] = { (int)(hi >> 5) & 7, (int)(hi >> 2) & 7 };
    const int flip = hi & 1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const int half = flip ? y >= 2 : x >= 2;
            const int bit = x * 4 + y;                  /* texels by columns */
            const int msb = (lo >> (bit + 16)) & 1, lsb = (lo >> bit) & 1;
            const int m = etc1_modifiers[table[half]][lsb];
            const int mod = msb ? -m : m;
            out[y * stride + x] = pack((uint32_t)etc1_clamp(base[half][0] + mod),
                                       (uint32_t)etc1_clamp(base[half][1] + mod),
                                       (uint32_t)etc1_clamp(base[half][2] + mod), 255);
        }
}

static void etc1_decode(const uint8_t *data, int width, int height, uint32_t *out)
{
    for (int by = 0; by < height; by += 4)
        for (int bx = 0; bx < width; bx += 4, data += 8)
            etc1_block(data, out + (int64_t)by * width + bx, width, width - bx < 4 ? width - bx : 4,
                       height - by < 4 ? height - by : 4);
}

static void compressed_etc1(GlesContext *ctx, Texture *t, int level, int width, int height, int border,
                            int image_size, const void *data, int64_t nbytes, int *status)
{
    *status = GLES_OK;
    /* the extension's own rule for a border (ES 1.1's general one is
    ** INVALID_VALUE) */
    if (border != 0) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    if (check_image(level, width, height, border) || face_not_square(t, width, height)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    const int64_t need = etc1_bytes(width, height);
    if (image_size < 0 || image_size != need) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    if (need && (!data || (nbytes >= 0 && nbytes < need))) {
        *status = ctx_message(ctx, GLES_EVALUE, "CompressedTexImage2D reads %lld bytes, the data holds %lld",
                              (long long)need, (long long)nbytes);
        return;
    }
    TexImage *li = &t->level[level];
    if (!image_fits(ctx, t, level, width, height) || !level_alloc(ctx, li, width, height)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    etc1_decode(data, width, height, li->texels);
    t->level_format[level] = GL_ETC1_RGB8_OES;
    if (level == 0) {
        t->format = GL_RGB;
        t->paletted = 0;
    }
    image_changed(ctx, t, level);
}

/* }==================================================================== */

int gles_CompressedTexImage2D(GlesContext *ctx, unsigned int target, int level, unsigned int internalformat,
                              int width, int height, int border, int image_size, const void *data, int64_t nbytes)
{
    raster_join(ctx);
    Texture *t = image_target(ctx, target);
    if (t && internalformat == GL_ETC1_RGB8_OES) {
        int st;
        compressed_etc1(ctx, t, level, width, height, border, image_size, data, nbytes, &st);
        return st;
    }
    const PaletteFormat *pf = palette_format(internalformat);
    if (!t || !pf) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return GLES_OK;
    }
    if (level > 0 || level < -max_level_of_size() || check_image(0, width, height, border)
        || face_not_square(t, width, height)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    int levels = -level + 1;
    int64_t need = texture_paletted_bytes(internalformat, levels, width, height);
    if (image_size < 0 || image_size != need) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    if (!data || (nbytes >= 0 && nbytes < need))
        return ctx_message(ctx, GLES_EVALUE, "CompressedTexImage2D reads %lld bytes, the data holds %lld",
                           (long long)need, (long long)nbytes);
    int64_t add = 0, release = levels_bytes(t, 0, levels);
    for (int l = 0, w = width, h = height; l < levels; l++) {
        add += (int64_t)w * h * (int64_t)sizeof(uint32_t);
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    if (levels == 1 && t->generate_mipmap) {
        add += chain_bytes(width, height);
        release = levels_bytes(t, 0, GLES_MAX_TEXTURE_LEVELS);
    }
    if (!ctx_mem_fits(ctx, add, release)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return GLES_OK;
    }
    const uint8_t *p = data;
    int entries = 1 << pf->index_bits;
    uint32_t palette[256];
    for (int i = 0; i < entries; i++)
        palette[i] = unpack_pixel(pf->entry_format, pf->type, p + i * pf->entry_bytes);
    const uint8_t *idx = p + entries * pf->entry_bytes;
    int w = width, h = height;
    for (int l = 0; l < levels; l++) {
        TexImage *li = &t->level[l];
        if (!level_alloc(ctx, li, w, h)) {
            ctx_error(ctx, GL_OUT_OF_MEMORY);
            return GLES_OK;
        }
        t->level_format[l] = pf->base;
        int64_t n = (int64_t)w * h;
        for (int64_t k = 0; k < n; k++) {
            unsigned int ix = pf->index_bits == 8 ? idx[k] : ((k & 1) ? idx[k / 2] & 15 : idx[k / 2] >> 4);
            li->texels[k] = palette[ix];
        }
        idx += (n * pf->index_bits + 7) / 8;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    t->format = pf->base;
    t->paletted = 1;
    image_changed(ctx, t, levels == 1 ? 0 : 1);
    return GLES_OK;
}

void gles_CompressedTexSubImage2D(GlesContext *ctx, unsigned int target, int level, int xoffset, int yoffset,
                                  int width, int height, unsigned int format, int image_size, const void *data)
{
    raster_join(ctx);
    (void)level; (void)xoffset; (void)yoffset; (void)width; (void)height; (void)image_size; (void)data;
    if (!image_target(ctx, target) || (!palette_format(format) && format != GL_ETC1_RGB8_OES)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    /* OES_compressed_paletted_texture and OES_compressed_ETC1_RGB8_texture:
    ** sub-images of their textures are not supported */
    ctx_error(ctx, GL_INVALID_OPERATION);
}

/* {====================================================================
** parameters */

void gles_TexParameter(GlesContext *ctx, unsigned int target, unsigned int pname, const double *p, int vector)
{
    raster_join(ctx);
    /* a cube map's parameters apply to the cube map as a whole */
    Texture *t = param_target(ctx, target);
    if (!t) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    unsigned int v = (unsigned int)dbl_to_i64(p[0], 0, UINT32_MAX);
    switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
        if (v != GL_NEAREST && v != GL_LINEAR && v != GL_NEAREST_MIPMAP_NEAREST && v != GL_LINEAR_MIPMAP_NEAREST
            && v != GL_NEAREST_MIPMAP_LINEAR && v != GL_LINEAR_MIPMAP_LINEAR) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        t->min_filter = v;
        break;
    case GL_TEXTURE_MAG_FILTER:
        if (v != GL_NEAREST && v != GL_LINEAR) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        t->mag_filter = v;
        break;
    case GL_TEXTURE_WRAP_S: case GL_TEXTURE_WRAP_T:
        if (v != GL_REPEAT && v != GL_CLAMP_TO_EDGE && v != GL_MIRRORED_REPEAT_OES) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        if (pname == GL_TEXTURE_WRAP_S)
            t->wrap_s = v;
        else
            t->wrap_t = v;
        break;
    case GL_GENERATE_MIPMAP:
        t->generate_mipmap = p[0] != 0.0;
        break;
    case GL_TEXTURE_MAX_ANISOTROPY_EXT:
        /* EXT_texture_filter_anisotropic: any real >= 1 (kept as given,
        ** MAX_TEXTURE_MAX_ANISOTROPY_EXT bounds what is used) */
        if (!(p[0] >= 1.0)) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        t->max_aniso = p[0];
        ctx->dirty |= DIRTY_SPAN;
        break;
    case GL_TEXTURE_MAX_LEVEL_APPLE: {
        /* an integer state: a real value rounds (§2.3.1) */
        const int64_t level = dbl_to_i64(p[0], INT32_MIN, INT32_MAX);
        if (level < 0) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        t->level_limit = (int)level;
        break;
    }
    case GL_TEXTURE_CROP_RECT_OES:
        if (!vector) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        for (int i = 0; i < 4; i++)
            t->crop[i] = (int)dbl_to_i64(p[i], INT32_MIN, INT32_MAX);
        break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    texture_update(t);
    ctx->dirty |= DIRTY_TEXTURE;
}

int gles_GetTexParameter(GlesContext *ctx, unsigned int target, unsigned int pname, double *out)
{
    const Texture *t = param_target(ctx, target);
    if (!t) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    switch (pname) {
    case GL_TEXTURE_MIN_FILTER: out[0] = t->min_filter; return 1;
    case GL_TEXTURE_MAG_FILTER: out[0] = t->mag_filter; return 1;
    case GL_TEXTURE_WRAP_S: out[0] = t->wrap_s; return 1;
    case GL_TEXTURE_WRAP_T: out[0] = t->wrap_t; return 1;
    case GL_GENERATE_MIPMAP: out[0] = t->generate_mipmap; return 1;
    case GL_TEXTURE_MAX_LEVEL_APPLE: out[0] = t->level_limit; return 1;
    case GL_TEXTURE_MAX_ANISOTROPY_EXT: out[0] = t->max_aniso; return 1;
    case GL_TEXTURE_CROP_RECT_OES:
        for (int i = 0; i < 4; i++)
            out[i] = t->crop[i];
        return 4;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
}

/* {====================================================================
** environment parameters */

static int is_combine_rgb(unsigned int f)
{
    return f == GL_REPLACE || f == GL_MODULATE || f == GL_ADD || f == GL_ADD_SIGNED || f == GL_INTERPOLATE
        || f == GL_SUBTRACT || f == GL_DOT3_RGB || f == GL_DOT3_RGBA;
}

static int is_combine_alpha(unsigned int f)
{
    return f == GL_REPLACE || f == GL_MODULATE || f == GL_ADD || f == GL_ADD_SIGNED || f == GL_INTERPOLATE
        || f == GL_SUBTRACT;
}

static int is_source(unsigned int s)
{
    /* OES_texture_env_crossbar adds TEXTUREn */
    return s == GL_TEXTURE || s == GL_CONSTANT || s == GL_PRIMARY_COLOR || s == GL_PREVIOUS
        || (s >= GL_TEXTURE0 && s < GL_TEXTURE0 + GLES_MAX_TEXTURE_UNITS);
}

void gles_TexEnv(GlesContext *ctx, unsigned int target, unsigned int pname, const double *p, int vector)
{
    TexUnit *tu = active_unit(ctx);
    if (target == GL_POINT_SPRITE_OES) {
        if (pname != GL_COORD_REPLACE_OES) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->coord_replace = p[0] != 0.0;
        return;
    }
    if (target == GL_TEXTURE_FILTER_CONTROL_EXT) {
        /* EXT_texture_lod_bias: kept as given, clamped where used */
        if (pname != GL_TEXTURE_LOD_BIAS_EXT) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->lod_bias = p[0];
        ctx->dirty |= DIRTY_SPAN | DIRTY_TEXTURE;
        return;
    }
    if (target != GL_TEXTURE_ENV) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    unsigned int v = (unsigned int)dbl_to_i64(p[0], 0, UINT32_MAX);
    switch (pname) {
    case GL_TEXTURE_ENV_MODE:
        if (v != GL_MODULATE && v != GL_DECAL && v != GL_BLEND && v != GL_ADD && v != GL_REPLACE && v != GL_COMBINE) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->env_mode = v;
        break;
    case GL_TEXTURE_ENV_COLOR:
        if (!vector) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        ctx_set_clamped_color(tu->env_color, tu->n_env_color, p);
        break;
    case GL_COMBINE_RGB:
        if (!is_combine_rgb(v)) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->combine_rgb = v;
        break;
    case GL_COMBINE_ALPHA:
        if (!is_combine_alpha(v)) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->combine_alpha = v;
        break;
    case GL_SRC0_RGB: case GL_SRC1_RGB: case GL_SRC2_RGB:
        if (!is_source(v)) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->src_rgb[pname - GL_SRC0_RGB] = v;
        break;
    case GL_SRC0_ALPHA: case GL_SRC1_ALPHA: case GL_SRC2_ALPHA:
        if (!is_source(v)) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->src_alpha[pname - GL_SRC0_ALPHA] = v;
        break;
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB:
        if (v != GL_SRC_COLOR && v != GL_ONE_MINUS_SRC_COLOR && v != GL_SRC_ALPHA && v != GL_ONE_MINUS_SRC_ALPHA) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->op_rgb[pname - GL_OPERAND0_RGB] = v;
        break;
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA:
        if (v != GL_SRC_ALPHA && v != GL_ONE_MINUS_SRC_ALPHA) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        tu->op_alpha[pname - GL_OPERAND0_ALPHA] = v;
        break;
    case GL_RGB_SCALE: case GL_ALPHA_SCALE:
        if (p[0] != 1.0 && p[0] != 2.0 && p[0] != 4.0) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        if (pname == GL_RGB_SCALE)
            tu->rgb_scale = p[0];
        else
            tu->alpha_scale = p[0];
        break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->dirty |= DIRTY_TEXTURE;
}

int gles_GetTexEnv(GlesContext *ctx, unsigned int target, unsigned int pname, double *out)
{
    const TexUnit *tu = active_unit(ctx);
    if (target == GL_POINT_SPRITE_OES && pname == GL_COORD_REPLACE_OES) {
        out[0] = tu->coord_replace;
        return 1;
    }
    if (target == GL_TEXTURE_FILTER_CONTROL_EXT && pname == GL_TEXTURE_LOD_BIAS_EXT) {
        out[0] = tu->lod_bias;
        return 1;
    }
    if (target != GL_TEXTURE_ENV) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    switch (pname) {
    case GL_TEXTURE_ENV_MODE: out[0] = tu->env_mode; return 1;
    case GL_TEXTURE_ENV_COLOR:
        for (int i = 0; i < 4; i++)
            out[i] = tu->env_color[i];
        return 4;
    case GL_COMBINE_RGB: out[0] = tu->combine_rgb; return 1;
    case GL_COMBINE_ALPHA: out[0] = tu->combine_alpha; return 1;
    case GL_SRC0_RGB: case GL_SRC1_RGB: case GL_SRC2_RGB: out[0] = tu->src_rgb[pname - GL_SRC0_RGB]; return 1;
    case GL_SRC0_ALPHA: case GL_SRC1_ALPHA: case GL_SRC2_ALPHA: out[0] = tu->src_alpha[pname - GL_SRC0_ALPHA]; return 1;
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB: out[0] = tu->op_rgb[pname - GL_OPERAND0_RGB]; return 1;
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA:
        out[0] = tu->op_alpha[pname - GL_OPERAND0_ALPHA];
        return 1;
    case GL_RGB_SCALE: out[0] = tu->rgb_scale; return 1;
    case GL_ALPHA_SCALE: out[0] = tu->alpha_scale; return 1;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
}

int texture_get(GlesContext *ctx, unsigned int pname, double *out, int *kind)
{
    *kind = GLES_KIND_INT;
    switch (pname) {
    case GL_MAX_TEXTURE_SIZE: out[0] = GLES_MAX_TEXTURE_SIZE; return 1;
    case GL_MAX_TEXTURE_LOD_BIAS_EXT: *kind = GLES_KIND_FLOAT; out[0] = TEXTURE_MAX_LOD_BIAS; return 1;
    case GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT: *kind = GLES_KIND_FLOAT; out[0] = TEXTURE_MAX_ANISOTROPY; return 1;
    case GL_TEXTURE_BINDING_2D: out[0] = active_unit(ctx)->bound_2d->name; return 1;
    case GL_TEXTURE_BINDING_CUBE_MAP_OES: out[0] = active_unit(ctx)->bound_cube->name; return 1;
    case GL_MAX_CUBE_MAP_TEXTURE_SIZE_OES: out[0] = GLES_MAX_TEXTURE_SIZE; return 1;
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS: out[0] = 11; return 1;
    case GL_COMPRESSED_TEXTURE_FORMATS:
        *kind = GLES_KIND_ENUM;
        for (int i = 0; i < 10; i++)
            out[i] = palette_formats[i].format;
        out[10] = GL_ETC1_RGB8_OES;
        return 11;
    default: return 0;
    }
}

/* does sampling this texture need the neighbours' coordinates */
int texture_needs_lod(const Texture *tex)
{
    /* (an anisotropic footprint needs the derivatives whatever the filters) */
    return needs_mipmaps(tex->min_filter) || tex->min_filter != tex->mag_filter || tex->max_aniso > 1.0;
}
