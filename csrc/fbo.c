/*
** fbo.c -- framebuffer and renderbuffer objects (fbo.h).
** Owns: the objects, their completeness (EXT_framebuffer_object §4.4.4 as
**       OES_framebuffer_object restricts it), and which buffers the context
**       draws into. The context's buffer fields (ctx->color, ->depth,
**       ->stencil, ->width, ...) are the window's, or, while a complete
**       object is bound, its attachments' (fbo_sync puts them there before
**       every command that draws or reads), so every stage renders into
**       either alike. Texture attachments render into the level's RGBA8888
**       texels in place. Between commands the fields may point at storage
**       a texture or renderbuffer call has since replaced: nothing reads
**       them before the next fbo_sync.
*/
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "state.h"
#include "raster.h"
#include "array.h"
#include "fbo.h"
#include "texture.h"
#include "debug.h"

/* {====================================================================
** the buffers */

static void buffers_of_context(const GlesContext *ctx, DrawBuffers *d)
{
    d->width = ctx->width;
    d->height = ctx->height;
    d->color_format = ctx->color_format;
    d->color_alpha = ctx->color_alpha;
    d->depth_bits = ctx->depth_bits;
    d->stencil_bits = ctx->stencil_bits;
    d->depth_max = ctx->depth_max;
    d->color = ctx->color;
    d->depth = ctx->depth;
    d->stencil = ctx->stencil;
}

/* the context draws into d from now on (every derived choice redone when
** anything changed) */
static void buffers_load(GlesContext *ctx, const DrawBuffers *d)
{
    DrawBuffers now;
    buffers_of_context(ctx, &now);
    if (memcmp(&now, d, sizeof now) != 0) {
        ctx->width = d->width;
        ctx->height = d->height;
        ctx->color_format = d->color_format;
        ctx->color_alpha = d->color_alpha;
        ctx->depth_bits = d->depth_bits;
        ctx->stencil_bits = d->stencil_bits;
        ctx->depth_max = d->depth_max;
        ctx->color = d->color;
        ctx->depth = d->depth;
        ctx->stencil = d->stencil;
        ctx->dirty = DIRTY_ALL;
    }
    const int alpha = fbo_alpha_written(ctx, ctx->color_mask_alpha);
    if (ctx->color_mask[3] != alpha) {
        ctx->color_mask[3] = alpha;
        ctx->dirty |= DIRTY_SPAN;
    }
}

/* {====================================================================
** formats */

static int rb_color_format(unsigned int f)
{
    return f == GL_RGBA8_OES || f == GL_RGB8_OES || f == GL_RGB565_OES || f == GL_RGBA4_OES || f == GL_RGB5_A1_OES;
}
static int rb_depth_format(unsigned int f)
{
    return f == GL_DEPTH_COMPONENT16_OES || f == GL_DEPTH_COMPONENT24_OES || f == GL_DEPTH24_STENCIL8_OES;
}
static int rb_stencil_format(unsigned int f) { return f == GL_STENCIL_INDEX8_OES || f == GL_DEPTH24_STENCIL8_OES; }

/* the colour buffer format (GLES_COLOR_*) a colour renderbuffer stores */
static int rb_color_layout(unsigned int f)
{
    switch (f) {
    case GL_RGB565_OES: return GLES_COLOR_RGB565;
    case GL_RGBA4_OES: return GLES_COLOR_RGBA4444;
    case GL_RGB5_A1_OES: return GLES_COLOR_RGBA5551;
    default: return GLES_COLOR_RGBA8888;    /* RGBA8, RGB8 */
    }
}

/* RED, GREEN, BLUE, ALPHA, DEPTH, STENCIL sizes of a renderbuffer format */
static void rb_sizes(unsigned int f, int out[6])
{
    memset(out, 0, 6 * sizeof *out);
    switch (f) {
    case GL_RGBA8_OES: out[0] = out[1] = out[2] = out[3] = 8; break;
    case GL_RGB8_OES: out[0] = out[1] = out[2] = 8; break;
    case GL_RGB565_OES: out[0] = 5; out[1] = 6; out[2] = 5; break;
    case GL_RGBA4_OES: out[0] = out[1] = out[2] = out[3] = 4; break;
    case GL_RGB5_A1_OES: out[0] = out[1] = out[2] = 5; out[3] = 1; break;
    case GL_DEPTH_COMPONENT16_OES: out[4] = 16; break;
    case GL_DEPTH_COMPONENT24_OES: out[4] = 24; break;
    case GL_STENCIL_INDEX8_OES: out[5] = 8; break;
    case GL_DEPTH24_STENCIL8_OES: out[4] = 24; out[5] = 8; break;
    default: break;
    }
}

/* {====================================================================
** completeness */

static const TexImage *attached_image(const FboAttachment *a)
{
    if (a->type != GL_TEXTURE || !a->tex || a->level < 0 || a->level >= GLES_MAX_TEXTURE_LEVELS)
        return NULL;
    const TexImage *li = &a->tex->level[a->level];
    return li->texels && li->width > 0 && li->height > 0 ? li : NULL;
}

/* the status, and with COMPLETE the buffers it draws into */
static unsigned int fbo_status(const Framebuffer *fb, DrawBuffers *d)
{
    const FboAttachment *c = &fb->at[FBO_COLOR], *z = &fb->at[FBO_DEPTH], *s = &fb->at[FBO_STENCIL];
    if (c->type == GL_NONE_OES && z->type == GL_NONE_OES && s->type == GL_NONE_OES)
        return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_OES;
    memset(d, 0, sizeof *d);
    int w = -1, h = -1, dims = 1, unsupported = 0;
#define FBO_SIZE(W, H) do { if (w < 0) { w = (W); h = (H); } else if (w != (W) || h != (H)) dims = 0; } while (0)
    if (c->type == GL_TEXTURE) {
        /* color-renderable: a texture of base format RGB or RGBA, neither
        ** paletted nor ETC1 (their levels are decoded copies) */
        const TexImage *li = attached_image(c);
        const unsigned int lf = li ? c->tex->level_format[c->level] : 0;
        const unsigned int base = texture_base_format(lf);
        if (!li || c->tex->paletted || lf == GL_ETC1_RGB8_OES || (base != GL_RGB && base != GL_RGBA))
            return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES;
        FBO_SIZE(li->width, li->height);
        d->color = li->texels;
        d->color_format = GLES_COLOR_RGBA8888;
        d->color_alpha = base == GL_RGBA;
    } else if (c->type == GL_RENDERBUFFER_OES) {
        const Renderbuffer *rb = c->rb;
        if (!rb || !rb_color_format(rb->format) || rb->width <= 0 || rb->height <= 0)
            return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES;
        FBO_SIZE(rb->width, rb->height);
        d->color = rb->color;
        d->color_format = rb_color_layout(rb->format);
        d->color_alpha = rb->format != GL_RGB8_OES && rb->format != GL_RGB565_OES;
    } else {
        unsupported = 1;    /* every draw writes a color buffer */
    }
    if (z->type != GL_NONE_OES) {
        const Renderbuffer *rb = z->type == GL_RENDERBUFFER_OES ? z->rb : NULL;
        if (!rb || !rb_depth_format(rb->format) || rb->width <= 0 || rb->height <= 0)
            return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES;
        FBO_SIZE(rb->width, rb->height);
        int sizes[6];
        rb_sizes(rb->format, sizes);
        d->depth = rb->depth;
        d->depth_bits = sizes[4];
        d->depth_max = (uint32_t)((1ull << sizes[4]) - 1);
    }
    if (s->type != GL_NONE_OES) {
        const Renderbuffer *rb = s->type == GL_RENDERBUFFER_OES ? s->rb : NULL;
        if (!rb || !rb_stencil_format(rb->format) || rb->width <= 0 || rb->height <= 0)
            return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES;
        FBO_SIZE(rb->width, rb->height);
        d->stencil = rb->stencil;
        d->stencil_bits = 8;
    }
#undef FBO_SIZE
    if (!dims)
        return GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_OES;
    if (unsupported)
        return GL_FRAMEBUFFER_UNSUPPORTED_OES;
    d->width = w;
    d->height = h;
    return GL_FRAMEBUFFER_COMPLETE_OES;
}

int fbo_sync(GlesContext *ctx)
{
    if (!ctx->fbo)
        return 1;
    DrawBuffers d;
    if (fbo_status(ctx->fbo, &d) != GL_FRAMEBUFFER_COMPLETE_OES) {
        ctx_error(ctx, GL_INVALID_FRAMEBUFFER_OPERATION_OES);
        return 0;
    }
    buffers_load(ctx, &d);
    return 1;
}

const DrawBuffers *fbo_window(GlesContext *ctx)
{
    if (!ctx->fbo)
        buffers_of_context(ctx, &ctx->window);
    return &ctx->window;
}

const Texture *fbo_color_texture(const GlesContext *ctx)
{
    return ctx->fbo && ctx->fbo->at[FBO_COLOR].type == GL_TEXTURE ? ctx->fbo->at[FBO_COLOR].tex : NULL;
}

/* {====================================================================
** objects */

void fbo_init(GlesContext *ctx)
{
    names_init(&ctx->framebuffers);
    names_init(&ctx->renderbuffers);
    ctx->fbo = NULL;
    ctx->rbo = NULL;
}

static void rb_storage_free(GlesContext *ctx, Renderbuffer *rb)
{
    free(rb->color);
    free(rb->depth);
    free(rb->stencil);
    rb->color = NULL;
    rb->depth = NULL;
    rb->stencil = NULL;
    ctx->mem_used -= rb->bytes;
    rb->bytes = 0;
}

static void each_framebuffer_detach(GlesContext *ctx, const Texture *t, const Renderbuffer *rb)
{
    const NameTable *tab = &ctx->framebuffers;
    for (uint32_t i = 0; i < tab->capacity; i++)
        if (tab->keys[i] != NAME_EMPTY && tab->keys[i] != NAME_DELETED) {
            Framebuffer *fb = tab->values[i];
            for (int k = 0; k < FBO_POINTS; k++) {
                FboAttachment *a = &fb->at[k];
                if ((t && a->type == GL_TEXTURE && a->tex == t) || (rb && a->type == GL_RENDERBUFFER_OES && a->rb == rb))
                    memset(a, 0, sizeof *a);        /* GL_NONE_OES */
            }
        }
}

void fbo_texture_deleted(GlesContext *ctx, const Texture *t)
{
    /* EXT_framebuffer_object detaches it from the bound object; the others
    ** would keep a deleted texture alive, which gles does not: it is
    ** detached from every object (no pointer outlives the texture) */
    each_framebuffer_detach(ctx, t, NULL);
}

static void bind_framebuffer(GlesContext *ctx, Framebuffer *fb)
{
    if (fb == ctx->fbo)
        return;
    if (!ctx->fbo)
        buffers_of_context(ctx, &ctx->window);
    ctx->fbo = fb;
    if (!fb) {
        buffers_load(ctx, &ctx->window);
        return;
    }
    /* an incomplete object leaves the window's buffers in place (every
    ** command that draws or reads calls fbo_sync, which refuses it) */
    DrawBuffers d;
    buffers_load(ctx, fbo_status(fb, &d) == GL_FRAMEBUFFER_COMPLETE_OES ? &d : &ctx->window);
}

void fbo_free(GlesContext *ctx)
{
    bind_framebuffer(ctx, NULL);
    NameTable *t = &ctx->framebuffers;
    for (uint32_t i = 0; i < t->capacity; i++)
        if (t->keys[i] != NAME_EMPTY && t->keys[i] != NAME_DELETED)
            free(t->values[i]);
    names_free(t);
    t = &ctx->renderbuffers;
    for (uint32_t i = 0; i < t->capacity; i++)
        if (t->keys[i] != NAME_EMPTY && t->keys[i] != NAME_DELETED) {
            rb_storage_free(ctx, t->values[i]);
            free(t->values[i]);
        }
    names_free(t);
    ctx->rbo = NULL;
}

static void gen_names(GlesContext *ctx, NameTable *t, int n, unsigned int *names)
{
    if (n < 0)
        ctx_error(ctx, GL_INVALID_VALUE);
    else
        names_generate(t, n, names);
}

void gles_GenFramebuffersOES(GlesContext *ctx, int n, unsigned int *names)
{
    raster_join(ctx);
    gen_names(ctx, &ctx->framebuffers, n, names);
}

void gles_GenRenderbuffersOES(GlesContext *ctx, int n, unsigned int *names)
{
    raster_join(ctx);
    gen_names(ctx, &ctx->renderbuffers, n, names);
}

/* the object a Bind names: an unused name becomes one (zeroed, its name in
** its first field, as Framebuffer and Renderbuffer have it); NULL with
** OUT_OF_MEMORY recorded */
static void *bound_object(GlesContext *ctx, NameTable *t, unsigned int name, size_t size)
{
    void *o = names_lookup(t, name);
    if (o)
        return o;
    o = calloc(1, size);
    if (!o || !names_insert(t, name, o)) {
        free(o);
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return NULL;
    }
    _Static_assert(offsetof(Framebuffer, name) == 0 && offsetof(Renderbuffer, name) == 0,
                   "the name is an object's first field");
    *(unsigned int *)o = name;
    return o;
}

void gles_BindFramebufferOES(GlesContext *ctx, unsigned int target, unsigned int name)
{
    raster_join(ctx);
    if (target != GL_FRAMEBUFFER_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    Framebuffer *fb = name ? bound_object(ctx, &ctx->framebuffers, name, sizeof *fb) : NULL;
    if (name && !fb)
        return;
    bind_framebuffer(ctx, fb);
}

void gles_BindRenderbufferOES(GlesContext *ctx, unsigned int target, unsigned int name)
{
    raster_join(ctx);
    if (target != GL_RENDERBUFFER_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    Renderbuffer *rb = name ? bound_object(ctx, &ctx->renderbuffers, name, sizeof *rb) : NULL;
    if (name && !rb)
        return;
    ctx->rbo = rb;
}

void gles_DeleteFramebuffersOES(GlesContext *ctx, int n, const unsigned int *names)
{
    raster_join(ctx);
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    for (int i = 0; i < n; i++) {
        Framebuffer *fb = names[i] ? names_remove(&ctx->framebuffers, names[i]) : NULL;
        if (!fb)
            continue;
        debug_object_deleted(ctx, DEBUG_NS_FRAMEBUFFER, names[i]);
        if (fb == ctx->fbo)
            bind_framebuffer(ctx, NULL);    /* the binding reverts to the window */
        free(fb);
    }
}

void gles_DeleteRenderbuffersOES(GlesContext *ctx, int n, const unsigned int *names)
{
    raster_join(ctx);
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    for (int i = 0; i < n; i++) {
        Renderbuffer *rb = names[i] ? names_remove(&ctx->renderbuffers, names[i]) : NULL;
        if (!rb)
            continue;
        debug_object_deleted(ctx, DEBUG_NS_RENDERBUFFER, names[i]);
        if (rb == ctx->rbo)
            ctx->rbo = NULL;
        /* detached from every framebuffer object (see fbo_texture_deleted);
        ** the bound one's buffers are re-read at the next command */
        each_framebuffer_detach(ctx, NULL, rb);
        rb_storage_free(ctx, rb);
        free(rb);
    }
}

unsigned char gles_IsFramebufferOES(GlesContext *ctx, unsigned int name)
{
    return name && names_lookup(&ctx->framebuffers, name) != NULL;
}

unsigned char gles_IsRenderbufferOES(GlesContext *ctx, unsigned int name)
{
    return name && names_lookup(&ctx->renderbuffers, name) != NULL;
}

void gles_RenderbufferStorageOES(GlesContext *ctx, unsigned int target, unsigned int internalformat, int width,
                                 int height)
{
    raster_join(ctx);
    if (target != GL_RENDERBUFFER_OES || !(rb_color_format(internalformat) || rb_depth_format(internalformat)
                                           || rb_stencil_format(internalformat))) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (width < 0 || height < 0 || width > GLES_MAX_TEXTURE_SIZE || height > GLES_MAX_TEXTURE_SIZE) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    Renderbuffer *rb = ctx->rbo;
    if (!rb) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    int sizes[6];
    rb_sizes(internalformat, sizes);
    const size_t n = (size_t)width * (size_t)height;
    const int pixel_bytes = rb_color_format(internalformat) ? color_bytes(rb_color_layout(internalformat)) : 0;
    const int64_t bytes = (int64_t)n * (pixel_bytes + (sizes[4] ? 4 : 0) + (sizes[5] ? 1 : 0));
    if (!ctx_mem_fits(ctx, bytes, rb->bytes)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    void *color = pixel_bytes && n ? calloc(n, (size_t)pixel_bytes) : NULL;
    uint32_t *depth = sizes[4] && n ? calloc(n, sizeof *depth) : NULL;
    uint8_t *stencil = sizes[5] && n ? calloc(n, 1) : NULL;
    if ((pixel_bytes && n && !color) || (sizes[4] && n && !depth) || (sizes[5] && n && !stencil)) {
        free(color);
        free(depth);
        free(stencil);
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    if (color && internalformat == GL_RGB8_OES)
        for (size_t i = 0; i < n; i++)
            ((uint32_t *)color)[i] = 0xFF000000u;   /* the alpha an RGB buffer reads: 1 */
    rb_storage_free(ctx, rb);
    rb->format = internalformat;
    rb->width = width;
    rb->height = height;
    rb->color = color;
    rb->depth = depth;
    rb->stencil = stencil;
    rb->bytes = bytes;
    ctx->mem_used += bytes;
}

static FboAttachment *attachment_point(GlesContext *ctx, unsigned int target, unsigned int attachment)
{
    if (target != GL_FRAMEBUFFER_OES)
        return NULL;
    switch (attachment) {
    case GL_COLOR_ATTACHMENT0_OES: return ctx->fbo ? &ctx->fbo->at[FBO_COLOR] : NULL;
    case GL_DEPTH_ATTACHMENT_OES: return ctx->fbo ? &ctx->fbo->at[FBO_DEPTH] : NULL;
    case GL_STENCIL_ATTACHMENT_OES: return ctx->fbo ? &ctx->fbo->at[FBO_STENCIL] : NULL;
    default: return NULL;
    }
}

static int attachment_enum_ok(unsigned int target, unsigned int attachment)
{
    return target == GL_FRAMEBUFFER_OES && (attachment == GL_COLOR_ATTACHMENT0_OES
                                            || attachment == GL_DEPTH_ATTACHMENT_OES
                                            || attachment == GL_STENCIL_ATTACHMENT_OES);
}

void gles_FramebufferTexture2DOES(GlesContext *ctx, unsigned int target, unsigned int attachment,
                                  unsigned int textarget, unsigned int texture, int level)
{
    raster_join(ctx);
    const int face_target = textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES
                            && textarget <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_OES;
    if (!attachment_enum_ok(target, attachment) || (texture && textarget != GL_TEXTURE_2D && !face_target)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (!ctx->fbo) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    Texture *t = texture ? names_lookup(&ctx->textures, texture) : NULL;
    /* a 2D texture for TEXTURE_2D, a cube map for a face target (OES_texture_cube_map), whose face is attached */
    if (texture && (!t || t->target != (face_target ? GL_TEXTURE_CUBE_MAP_OES : GL_TEXTURE_2D))) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    if (t && face_target)
        t = t->face[textarget - GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES];
    /* any level: OES_fbo_render_mipmap */
    if (texture && (level < 0 || level >= GLES_MAX_TEXTURE_LEVELS)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    FboAttachment *a = attachment_point(ctx, target, attachment);
    memset(a, 0, sizeof *a);
    if (t) {
        a->type = GL_TEXTURE;
        a->name = texture;
        a->tex = t;
        a->level = level;
    }
    ctx->dirty = DIRTY_ALL;
}

void gles_FramebufferRenderbufferOES(GlesContext *ctx, unsigned int target, unsigned int attachment,
                                     unsigned int renderbuffertarget, unsigned int renderbuffer)
{
    raster_join(ctx);
    if (!attachment_enum_ok(target, attachment) || (renderbuffertarget != GL_RENDERBUFFER_OES)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (!ctx->fbo) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    Renderbuffer *rb = renderbuffer ? names_lookup(&ctx->renderbuffers, renderbuffer) : NULL;
    if (renderbuffer && !rb) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    FboAttachment *a = attachment_point(ctx, target, attachment);
    memset(a, 0, sizeof *a);
    if (rb) {
        a->type = GL_RENDERBUFFER_OES;
        a->name = renderbuffer;
        a->rb = rb;
    }
    ctx->dirty = DIRTY_ALL;
}

unsigned int gles_CheckFramebufferStatusOES(GlesContext *ctx, unsigned int target)
{
    if (target != GL_FRAMEBUFFER_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    if (!ctx->fbo)
        return GL_FRAMEBUFFER_COMPLETE_OES;
    DrawBuffers d;
    return fbo_status(ctx->fbo, &d);
}

int gles_GetFramebufferAttachmentParameterivOES(GlesContext *ctx, unsigned int target, unsigned int attachment,
                                                 unsigned int pname, int *params)
{
    if (!attachment_enum_ok(target, attachment)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    if (!ctx->fbo) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return 0;
    }
    const FboAttachment *a = attachment_point(ctx, target, attachment);
    switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES: params[0] = (int)a->type; return 1;
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES:
        if (a->type == GL_NONE_OES)
            break;
        params[0] = (int)a->name;
        return 1;
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_OES:
        if (a->type != GL_TEXTURE)
            break;
        params[0] = a->level;
        return 1;
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_OES:
        if (a->type != GL_TEXTURE)
            break;
        params[0] = a->tex->cube ? (int)a->tex->target : 0;
        return 1;
    default: break;
    }
    ctx_error(ctx, GL_INVALID_ENUM);
    return 0;
}

int gles_GetRenderbufferParameterivOES(GlesContext *ctx, unsigned int target, unsigned int pname, int *params)
{
    if (target != GL_RENDERBUFFER_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    const Renderbuffer *rb = ctx->rbo;
    int sizes[6];
    rb_sizes(rb ? rb->format : 0, sizes);
    int v;
    switch (pname) {
    case GL_RENDERBUFFER_WIDTH_OES: v = rb ? rb->width : 0; break;
    case GL_RENDERBUFFER_HEIGHT_OES: v = rb ? rb->height : 0; break;
    case GL_RENDERBUFFER_INTERNAL_FORMAT_OES: v = rb && rb->format ? (int)rb->format : GL_RGBA4_OES; break;
    case GL_RENDERBUFFER_RED_SIZE_OES: v = sizes[0]; break;
    case GL_RENDERBUFFER_GREEN_SIZE_OES: v = sizes[1]; break;
    case GL_RENDERBUFFER_BLUE_SIZE_OES: v = sizes[2]; break;
    case GL_RENDERBUFFER_ALPHA_SIZE_OES: v = sizes[3]; break;
    case GL_RENDERBUFFER_DEPTH_SIZE_OES: v = sizes[4]; break;
    case GL_RENDERBUFFER_STENCIL_SIZE_OES: v = sizes[5]; break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    if (!rb) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return 0;
    }
    params[0] = v;
    return 1;
}

/* EXT_discard_framebuffer: the contents may become undefined; gles keeps
** them (one of the allowed outcomes), after the extension's checks */
void gles_DiscardFramebufferEXT(GlesContext *ctx, unsigned int target, int n, const unsigned int *attachments)
{
    raster_join(ctx);
    if (target != GL_FRAMEBUFFER_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    for (int i = 0; i < n; i++) {
        const unsigned int a = attachments[i];
        const int ok = ctx->fbo ? (a == GL_COLOR_ATTACHMENT0_OES || a == GL_DEPTH_ATTACHMENT_OES
                                   || a == GL_STENCIL_ATTACHMENT_OES)
                                : (a == GL_COLOR_EXT || a == GL_DEPTH_EXT || a == GL_STENCIL_EXT);
        if (!ok) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
    }
}

int fbo_get(GlesContext *ctx, unsigned int pname, double *out, int *kind)
{
    *kind = GLES_KIND_INT;
    switch (pname) {
    case GL_FRAMEBUFFER_BINDING_OES: out[0] = ctx->fbo ? ctx->fbo->name : 0; return 1;
    case GL_RENDERBUFFER_BINDING_OES: out[0] = ctx->rbo ? ctx->rbo->name : 0; return 1;
    case GL_MAX_RENDERBUFFER_SIZE_OES: out[0] = GLES_MAX_TEXTURE_SIZE; return 1;
    default: return 0;
    }
}
