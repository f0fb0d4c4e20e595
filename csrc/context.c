/*
** context.c -- context lifetime, enables, simple state and the state query.
** Owns: GlesContext creation with the spec's initial state (ES 1.1 §6.2),
**       error recording, Enable/Disable, viewport, depth range, clear
**       values, masks, and gles_get, the one table every Get* is built on.
** Never does: arithmetic on vertices or fragments.
*/
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "state.h"
#include "matrix.h"
#include "array.h"
#include "light.h"
#include "fragment.h"
#include "texture.h"
#include "raster.h"
#include "fbo.h"
#include "debug.h"

static int cap_index(unsigned int cap);

const char *gles_numeric_name(void) { return NUM_NAME; }

int ctx_message(GlesContext *ctx, int status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->message, sizeof ctx->message, fmt, ap);
    va_end(ap);
    return status;
}

const char *gles_last_message(GlesContext *ctx) { return ctx->message; }

void ctx_set_clamped_color(double *d, NUM *n, const double *rgba)
{
    for (int i = 0; i < 4; i++) {
        double c = !(rgba[i] > 0) ? 0.0 : (rgba[i] > 1 ? 1.0 : rgba[i]);
        d[i] = c;
        n[i] = num_from_double(c);
    }
}
/* the window's buffers, whichever framebuffer is bound */
/* the window's buffers, with every draw's rows in them (raster_join) */
void *gles_color_buffer(GlesContext *ctx)
{
    raster_join(ctx);
    return fbo_window(ctx)->color;
}
void *gles_depth_buffer(GlesContext *ctx)
{
    raster_join(ctx);
    return fbo_window(ctx)->depth;
}
void *gles_stencil_buffer(GlesContext *ctx)
{
    raster_join(ctx);
    return fbo_window(ctx)->stencil;
}
int gles_width(GlesContext *ctx) { return fbo_window(ctx)->width; }
int gles_height(GlesContext *ctx) { return fbo_window(ctx)->height; }
const char *gles_last_span_name(GlesContext *ctx) { return ctx->span_name ? ctx->span_name : ""; }
const char *gles_simd_name(GlesContext *ctx) { return simd_name(ctx_simd(ctx)); }

void gles_debug_set(GlesContext *ctx, int flags)
{
    ctx->debug = flags;
    ctx->dirty |= DIRTY_SPAN;
}

/* errors the binding finds itself (e.g. glGen* past the memory budget): no
** core function to name in the debug message */
void gles_set_error(GlesContext *ctx, unsigned int err) { ctx_error_at(ctx, err, NULL, NULL); }

double gles_num_eval(int op, double a, double b)
{
    NUM x = num_from_double(a), y = num_from_double(b), s, c;
    switch (op) {
    case GLES_NUMOP_FROM: return num_to_double(x);
    case GLES_NUMOP_ADD: return num_to_double(num_add(x, y));
    case GLES_NUMOP_SUB: return num_to_double(num_sub(x, y));
    case GLES_NUMOP_MUL: return num_to_double(num_mul(x, y));
    case GLES_NUMOP_DIV: return num_to_double(num_div(x, y));
    case GLES_NUMOP_RECIP: return num_to_double(num_recip(x));
    case GLES_NUMOP_SQRT: return num_to_double(num_sqrt(x));
    case GLES_NUMOP_RSQRT: return num_to_double(num_rsqrt(x));
    case GLES_NUMOP_SIN_DEG: num_sincos_deg(x, &s, &c); return num_to_double(s);
    case GLES_NUMOP_COS_DEG: num_sincos_deg(x, &s, &c); return num_to_double(c);
    case GLES_NUMOP_TO_UNORM8: return num_to_unorm(x, 255);
    case GLES_NUMOP_POW01: return num_to_double(num_pow(x, y));
    case GLES_NUMOP_FROM_UNORM8: return num_to_double(num_from_unorm((uint32_t)dbl_to_i64(a, 0, 255), 255));
    default: return 0.0;
    }
}

/* the per-primitive scratch a context rasterizes with (its own, or a
** worker's copy's): 0 where some of it could not be had (what was is
** freed by scratch_free) */
static int scratch_alloc(GlesContext *c, int width)
{
    /* a row of the widest buffer drawn into: the window, or a framebuffer
    ** object's (OES_framebuffer_object), up to MAX_RENDERBUFFER_SIZE */
    if (width < GLES_MAX_TEXTURE_SIZE)
        width = GLES_MAX_TEXTURE_SIZE;
    c->rect_s = calloc(((size_t)width + 1) * GLES_MAX_TEXTURE_UNITS, sizeof *c->rect_s);
    _Static_assert(GLES_FUSED_SETUP_BYTES % 64 == 0, "aligned_alloc takes a multiple of the alignment");
    c->fused_setup = aligned_alloc(64, GLES_FUSED_SETUP_BYTES);
    _Static_assert(GLES_TESTS_SETUP_BYTES % 64 == 0, "aligned_alloc takes a multiple of the alignment");
    c->tests_setup = aligned_alloc(64, GLES_TESTS_SETUP_BYTES);
    _Static_assert(GLES_PERSP_SETUP_BYTES % 64 == 0, "aligned_alloc takes a multiple of the alignment");
    c->persp_setup = aligned_alloc(64, GLES_PERSP_SETUP_BYTES);
    return c->rect_s && c->fused_setup && c->tests_setup && c->persp_setup;
}

static void scratch_free(GlesContext *c)
{
    free(c->rect_s);
    free(c->fused_setup);
    free(c->tests_setup);
    free(c->persp_setup);
}

GlesContext *gles_context_create(int width, int height, int color_format,
                                 int depth_bits, int stencil_bits, int profile)
{
    if (width < 1 || height < 1 || width > GLES_MAX_FRAMEBUFFER_DIM || height > GLES_MAX_FRAMEBUFFER_DIM)
        return NULL;
    if (color_format != GLES_COLOR_RGBA8888 && color_format != GLES_COLOR_RGB565
        && color_format != GLES_COLOR_RGBA4444 && color_format != GLES_COLOR_RGBA5551)
        return NULL;
    if (depth_bits != 0 && depth_bits != 16 && depth_bits != 24)
        return NULL;
    if (stencil_bits != 0 && stencil_bits != 8)
        return NULL;
    GlesContext *ctx = calloc(1, sizeof *ctx);
    if (!ctx)
        return NULL;
    size_t npix = (size_t)width * (size_t)height;
    ctx->width = width;
    ctx->height = height;
    ctx->color_format = color_format;
    ctx->flat_cache_format = -1;
    ctx->depth_bits = depth_bits;
    ctx->stencil_bits = stencil_bits;
    ctx->depth_max = depth_bits ? (uint32_t)((1ull << depth_bits) - 1) : 0;
    ctx->color_alpha = color_format != GLES_COLOR_RGB565;
    ctx->color_mask_alpha = 1;
    ctx->profile = profile;
    ctx->threads = ctx->band_count = 1;
    ctx->band_caller_rows = RASTER_BAND_ROWS;
    ctx->simd = simd_detect();
    ctx->chain_coords_unit = ctx->chain_coords_tx_unit = ctx->chain_lod_unit = -1;
    ctx->chain_fused_lanes = 0;
    ctx->color = calloc(npix, (size_t)color_bytes(color_format));
    ctx->depth = depth_bits ? calloc(npix, sizeof(uint32_t)) : NULL;
    ctx->stencil = stencil_bits ? calloc(npix, 1) : NULL;
    const int scratch = scratch_alloc(ctx, width);
    if (!ctx->color || (depth_bits && !ctx->depth) || (stencil_bits && !ctx->stencil) || !scratch
        || !debug_init(ctx)) {
        gles_context_destroy(ctx);
        return NULL;
    }

    /* initial state, ES 1.1 Tables 6.1-6.19 */
    ctx->viewport[2] = width;
    ctx->viewport[3] = height;
    ctx->scissor[2] = width;
    ctx->scissor[3] = height;
    ctx->depth_range[1] = 1.0;
    ctx->clear_depth = 1.0;
    memset(ctx->color_mask, 1, 4);
    ctx->depth_mask = 1;
    ctx->depth_func = GL_LESS;
    ctx->cull_mode = GL_BACK;
    ctx->front_face = GL_CCW;
    ctx->shade_model = GL_SMOOTH;
    for (int i = 0; i < 4; i++)
        ctx->hints[i] = GL_DONT_CARE;
    ctx->hint_generate_mipmap = GL_DONT_CARE;
    ctx->pack_alignment = ctx->unpack_alignment = 4;
    ctx->mem_limit = GLES_DEFAULT_MEMORY_LIMIT;
    ctx->active_texture = ctx->client_active_texture = GL_TEXTURE0;

    matrix_stack_init(&ctx->modelview, GLES_MODELVIEW_STACK_DEPTH);
    matrix_stack_init(&ctx->projection, GLES_PROJECTION_STACK_DEPTH);
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        matrix_stack_init(&ctx->texture[u], GLES_TEXTURE_STACK_DEPTH);
    matrix_palette_init(ctx);
    ctx->matrix_mode = GL_MODELVIEW;
    ctx->current_stack = &ctx->modelview;

    ctx->cur_color[0] = ctx->cur_color[1] = ctx->cur_color[2] = ctx->cur_color[3] = 1.0;
    ctx->cur_normal[2] = 1.0;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        ctx->cur_tex[u][3] = 1.0;
    for (int i = 0; i < 4; i++)
        ctx->cur_color_n[i] = NUM_ONE;
    ctx->cur_normal_n[2] = NUM_ONE;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        ctx->cur_tex_n[u][3] = NUM_ONE;

    /* §4.1.8 and Table 6.x: dither and multisample start enabled */
    ctx->enable_bits = (1u << cap_index(GL_DITHER)) | (1u << cap_index(GL_MULTISAMPLE));
    light_init(ctx);
    fragment_init(ctx);
    fog_init(ctx);
    if (!texture_init(ctx)) {
        gles_context_destroy(ctx);
        return NULL;
    }
    /* Tables 6.x: point and line state */
    ctx->point_size = ctx->line_width = 1.0;
    ctx->n_point_size = NUM_ONE;
    ctx->point_size_max = 64.0;
    ctx->n_point_size_max = num_from_int(64);
    ctx->point_fade_threshold = 1.0;
    ctx->point_attenuation[0] = 1.0;
    ctx->n_point_attenuation[0] = NUM_ONE;
    array_init(ctx);
    fbo_init(ctx);
    ctx->dirty = DIRTY_ALL;
    return ctx;
}

void gles_memory_limit(GlesContext *ctx, int64_t limit)
{
    ctx->mem_limit = limit < 0 ? 0 : limit;
}

int64_t gles_memory_used(GlesContext *ctx) { return ctx->mem_used; }

void gles_context_destroy(GlesContext *ctx)
{
    if (!ctx)
        return;
    raster_join(ctx);       /* the workers first: they read what follows frees */
    fbo_free(ctx);          /* first: the window's buffers back in the context */
    array_free(ctx);
    texture_free(ctx);
    debug_free(ctx);
    free(ctx->color);
    free(ctx->depth);
    free(ctx->stencil);
    gles_threads_set(ctx, 1);
    scratch_free(ctx);
    free(ctx->verts);
    free(ctx->vert_stamp);
    free(ctx->draw_prims);
    free(ctx->draw_pend);
    free(ctx->draw_pendv);
    free(ctx);
}

static void worker_free(GlesContext *w)
{
    scratch_free(w);
    free(w);
}

/* a worker's copy of the context, with its own per-primitive scratch
** (draw.c's worker_prepare fills in the rest per draw); NULL without memory */
static GlesContext *worker_create(const GlesContext *ctx)
{
    GlesContext *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    if (!scratch_alloc(w, ctx->width)) {
        worker_free(w);
        return NULL;
    }
    /* the tail's fixed tables, once (state.h) */
    const size_t tail = offsetof(GlesContext, unorm8), tables_end = offsetof(GlesContext, flat_table);
    memcpy((char *)w + tail, (const char *)ctx + tail, tables_end - tail);
    return w;
}

/* workers[0..n) and the array */
static void workers_free(GlesContext **workers, int n)
{
    for (int i = 0; workers && i < n; i++)
        worker_free(workers[i]);
    free(workers);
}

int gles_threads_set(GlesContext *ctx, int threads)
{
    if (threads < 1)
        threads = 1;
    if (threads > GLES_MAX_THREADS)
        threads = GLES_MAX_THREADS;
    WorkPool *pool = threads > 1 ? pool_shared(threads) : NULL;
    if (pool && pool_threads(pool) < threads)
        threads = pool_threads(pool);   /* the workers that could be started */
    if (!pool)
        threads = 1;
    if (threads == ctx->threads)
        return threads;
    raster_join(ctx);
    GlesContext **workers = threads > 1 ? calloc((size_t)threads - 1, sizeof *workers) : NULL;
    int made = 0;
    while (workers && made < threads - 1 && (workers[made] = worker_create(ctx)) != NULL)
        made++;
    if (threads > 1 && made < threads - 1) {
        /* no memory for the workers' copies: keep what there is */
        workers_free(workers, made);
        return ctx->threads;
    }
    workers_free(ctx->worker_ctx, ctx->threads - 1);
    ctx->pool = pool;
    ctx->worker_ctx = workers;
    ctx->threads = threads;
    ctx->band_caller_rows = RASTER_BAND_ROWS;
    ctx->band_votes = 0;
    return threads;
}

int gles_threads(GlesContext *ctx) { return ctx->threads; }

unsigned int gles_GetError(GlesContext *ctx)
{
    unsigned int e = ctx->error;
    ctx->error = GL_NO_ERROR;
    return e;
}

/* {====================================================================
** enables */

/* Capabilities whose stage is in a later part of the pipeline are accepted
** and remembered (IsEnabled answers) without effect until that stage exists.
** Each has a bit in enable_bits; the order is fixed by this table. */
static const unsigned int cap_table[] = {
    GL_ALPHA_TEST, GL_BLEND, GL_COLOR_LOGIC_OP, GL_COLOR_MATERIAL, GL_CULL_FACE,
    GL_DEPTH_TEST, GL_DITHER, GL_FOG, GL_LIGHTING, GL_LINE_SMOOTH, GL_MULTISAMPLE,
    GL_NORMALIZE, GL_POINT_SMOOTH, GL_POLYGON_OFFSET_FILL, GL_RESCALE_NORMAL,
    GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE,
    GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_TEXTURE_2D, GL_POINT_SPRITE_OES,
    GL_MATRIX_PALETTE_OES,
};
enum { CAP_COUNT = sizeof cap_table / sizeof cap_table[0] };

static int cap_index(unsigned int cap)
{
    for (int i = 0; i < CAP_COUNT; i++)
        if (cap_table[i] == cap)
            return i;
    return -1;
}

static void set_enable(GlesContext *ctx, unsigned int cap, int on)
{
    if (debug_set_enable(ctx, cap, on))
        return;
    if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + GLES_MAX_CLIP_PLANES) {
        ctx->clip_plane_enabled[cap - GL_CLIP_PLANE0] = on;
        ctx->dirty |= DIRTY_CLIP;
        return;
    }
    if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + GLES_MAX_LIGHTS) {
        ctx->light_enabled[cap - GL_LIGHT0] = on;
        ctx->dirty |= DIRTY_LIGHT;
        return;
    }
    if (cap == GL_TEXTURE_2D || cap == GL_TEXTURE_CUBE_MAP_OES) {
        /* per texture unit (§3.7.15); the sampled target by the cube map
        ** extension's precedence */
        TexUnit *tu = &ctx->units[ctx->active_texture - GL_TEXTURE0];
        *(cap == GL_TEXTURE_2D ? &tu->enabled_2d : &tu->enabled_cube) = on;
        texture_unit_update(tu);
        ctx->dirty |= DIRTY_TEXTURE | DIRTY_SPAN;
        return;
    }
    if (cap == GL_TEXTURE_GEN_STR_OES) {
        /* per texture unit; the vertex stage may now need eye coordinates
        ** and the normal matrix */
        ctx->units[ctx->active_texture - GL_TEXTURE0].texgen = on;
        ctx->dirty |= DIRTY_TEXTURE | DIRTY_CLIP | DIRTY_LIGHT;
        return;
    }
    int i = cap_index(cap);
    if (i < 0) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    unsigned int bit = 1u << i;
    ctx->enable_bits = on ? (ctx->enable_bits | bit) : (ctx->enable_bits & ~bit);
    switch (cap) {
    case GL_CULL_FACE: ctx->cull_enabled = on; break;
    case GL_DEPTH_TEST: ctx->depth_test = on; break;
    case GL_SCISSOR_TEST: ctx->scissor_test = on; break;
    case GL_ALPHA_TEST: ctx->alpha_test = on; break;
    case GL_STENCIL_TEST: ctx->stencil_test = on; break;
    case GL_BLEND: ctx->blend = on; break;
    case GL_DITHER: ctx->dither = on; break;
    case GL_COLOR_LOGIC_OP: ctx->color_logic_op = on; break;
    case GL_FOG: ctx->fog = on; ctx->dirty |= DIRTY_CLIP; break;
    case GL_POINT_SMOOTH: ctx->point_smooth = on; break;
    case GL_LINE_SMOOTH: ctx->line_smooth = on; break;
    case GL_POINT_SPRITE_OES: ctx->point_sprite = on; break;
    case GL_POLYGON_OFFSET_FILL: ctx->polygon_offset_fill = on; break;
    case GL_LIGHTING: ctx->lighting = on; ctx->dirty |= DIRTY_LIGHT | DIRTY_CLIP; break;
    case GL_MATRIX_PALETTE_OES: ctx->matrix_palette = on; ctx->dirty |= DIRTY_LIGHT | DIRTY_CLIP; break;
    case GL_NORMALIZE: ctx->normalize = on; break;
    case GL_RESCALE_NORMAL: ctx->rescale_normal = on; break;
    case GL_COLOR_MATERIAL:
        ctx->color_material = on;
        light_track_color(ctx);
        break;
    default: break;
    }
    ctx->dirty |= DIRTY_SPAN;
}

void gles_Enable(GlesContext *ctx, unsigned int cap) { set_enable(ctx, cap, 1); }
void gles_Disable(GlesContext *ctx, unsigned int cap) { set_enable(ctx, cap, 0); }

unsigned char gles_IsEnabled(GlesContext *ctx, unsigned int cap)
{
    unsigned char debug_on;
    if (debug_is_enabled(ctx, cap, &debug_on))
        return debug_on;
    if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + GLES_MAX_CLIP_PLANES)
        return (unsigned char)ctx->clip_plane_enabled[cap - GL_CLIP_PLANE0];
    if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + GLES_MAX_LIGHTS)
        return (unsigned char)ctx->light_enabled[cap - GL_LIGHT0];
    if (cap == GL_TEXTURE_2D)
        return (unsigned char)ctx->units[ctx->active_texture - GL_TEXTURE0].enabled_2d;
    if (cap == GL_TEXTURE_CUBE_MAP_OES)
        return (unsigned char)ctx->units[ctx->active_texture - GL_TEXTURE0].enabled_cube;
    if (cap == GL_TEXTURE_GEN_STR_OES)
        return (unsigned char)ctx->units[ctx->active_texture - GL_TEXTURE0].texgen;
    int i = cap_index(cap);
    if (i >= 0)
        return (ctx->enable_bits >> i) & 1;
    int a = array_index_of_cap(ctx, cap);
    if (a >= 0)
        return (unsigned char)ctx->arrays[a].enabled;
    ctx_error(ctx, GL_INVALID_ENUM);
    return 0;
}

/* {====================================================================
** simple state */

void gles_Viewport(GlesContext *ctx, int x, int y, int width, int height)
{
    if (width < 0 || height < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    /* §2.11.1: sizes are silently clamped to MAX_VIEWPORT_DIMS */
    ctx->viewport[0] = x;
    ctx->viewport[1] = y;
    ctx->viewport[2] = width > GLES_MAX_VIEWPORT_DIM ? GLES_MAX_VIEWPORT_DIM : width;
    ctx->viewport[3] = height > GLES_MAX_VIEWPORT_DIM ? GLES_MAX_VIEWPORT_DIM : height;
}

void gles_Scissor(GlesContext *ctx, int x, int y, int width, int height)
{
    if (width < 0 || height < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    ctx->scissor[0] = x;
    ctx->scissor[1] = y;
    ctx->scissor[2] = width;
    ctx->scissor[3] = height;
}

static double clamp01(double v) { return !(v > 0.0) ? 0.0 : (v > 1.0 ? 1.0 : v); }

void gles_DepthRange(GlesContext *ctx, double n, double f)
{
    ctx->depth_range[0] = clamp01(n);
    ctx->depth_range[1] = clamp01(f);
}

void gles_ClearColor(GlesContext *ctx, double r, double g, double b, double a)
{
    ctx->clear_color[0] = clamp01(r);
    ctx->clear_color[1] = clamp01(g);
    ctx->clear_color[2] = clamp01(b);
    ctx->clear_color[3] = clamp01(a);
}

void gles_ClearDepth(GlesContext *ctx, double d) { ctx->clear_depth = clamp01(d); }
void gles_ClearStencil(GlesContext *ctx, int s) { ctx->clear_stencil = s; }

void gles_ColorMask(GlesContext *ctx, unsigned char r, unsigned char g, unsigned char b, unsigned char a)
{
    ctx->color_mask[0] = r != 0;
    ctx->color_mask[1] = g != 0;
    ctx->color_mask[2] = b != 0;
    ctx->color_mask_alpha = a != 0;
    ctx->color_mask[3] = fbo_alpha_written(ctx, a != 0);
    ctx->dirty |= DIRTY_SPAN;
}

void gles_DepthMask(GlesContext *ctx, unsigned char flag)
{
    ctx->depth_mask = flag != 0;
    ctx->dirty |= DIRTY_SPAN;
}

void gles_DepthFunc(GlesContext *ctx, unsigned int func)
{
    if (func < GL_NEVER || func > GL_ALWAYS) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->depth_func = func;
    ctx->dirty |= DIRTY_SPAN;
}

void gles_CullFace(GlesContext *ctx, unsigned int mode)
{
    if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->cull_mode = mode;
}

void gles_FrontFace(GlesContext *ctx, unsigned int mode)
{
    if (mode != GL_CW && mode != GL_CCW) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->front_face = mode;
}

void gles_ShadeModel(GlesContext *ctx, unsigned int mode)
{
    if (mode != GL_FLAT && mode != GL_SMOOTH) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->shade_model = mode;
    ctx->dirty |= DIRTY_SPAN;
}

void gles_Hint(GlesContext *ctx, unsigned int target, unsigned int mode)
{
    if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: ctx->hints[0] = mode; break;
    case GL_POINT_SMOOTH_HINT: ctx->hints[1] = mode; break;
    case GL_LINE_SMOOTH_HINT: ctx->hints[2] = mode; break;
    case GL_FOG_HINT: ctx->hints[3] = mode; ctx->dirty |= DIRTY_SPAN; break;
    case GL_GENERATE_MIPMAP_HINT: ctx->hint_generate_mipmap = mode; break;
    default: ctx_error(ctx, GL_INVALID_ENUM); break;
    }
}

void gles_PixelStorei(GlesContext *ctx, unsigned int pname, int param)
{
    if (pname != GL_PACK_ALIGNMENT && pname != GL_UNPACK_ALIGNMENT) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (param != 1 && param != 2 && param != 4 && param != 8) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    if (pname == GL_PACK_ALIGNMENT)
        ctx->pack_alignment = param;
    else
        ctx->unpack_alignment = param;
}

void gles_ActiveTexture(GlesContext *ctx, unsigned int texture)
{
    if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + GLES_MAX_TEXTURE_UNITS) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->active_texture = texture;
    if (ctx->matrix_mode == GL_TEXTURE)
        ctx->current_stack = &ctx->texture[texture - GL_TEXTURE0];
}

void gles_ClientActiveTexture(GlesContext *ctx, unsigned int texture)
{
    if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + GLES_MAX_TEXTURE_UNITS) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->client_active_texture = texture;
}

/* §5.1: Finish returns once every command's effect is complete, the
** threaded draws' rows among them; Flush, that they complete in finite
** time, which they do without waiting */
void gles_Finish(GlesContext *ctx) { raster_join(ctx); }
void gles_Flush(GlesContext *ctx) { (void)ctx; }

/* {====================================================================
** current values */

void gles_Color4(GlesContext *ctx, double r, double g, double b, double a)
{
    double v[4] = { r, g, b, a };
    for (int i = 0; i < 4; i++) {
        ctx->cur_color[i] = v[i];
        ctx->cur_color_n[i] = num_from_double(v[i]);
    }
    light_track_color(ctx);
}

void gles_Normal3(GlesContext *ctx, double x, double y, double z)
{
    double v[3] = { x, y, z };
    for (int i = 0; i < 3; i++) {
        ctx->cur_normal[i] = v[i];
        ctx->cur_normal_n[i] = num_from_double(v[i]);
    }
}

void gles_MultiTexCoord4(GlesContext *ctx, unsigned int target, double s, double t, double r, double q)
{
    if (target < GL_TEXTURE0 || target >= GL_TEXTURE0 + GLES_MAX_TEXTURE_UNITS) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    unsigned int u = target - GL_TEXTURE0;
    double v[4] = { s, t, r, q };
    for (int i = 0; i < 4; i++) {
        ctx->cur_tex[u][i] = v[i];
        ctx->cur_tex_n[u][i] = num_from_double(v[i]);
    }
}

/* {====================================================================
** gles_get: the state table behind GetBooleanv/Integerv/Fixedv/Floatv */

static int put(double *out, int *kind, int k, int n, const double *v)
{
    for (int i = 0; i < n; i++)
        out[i] = v[i];
    *kind = k;
    return n;
}

static int put1(double *out, int *kind, int k, double v) { return put(out, kind, k, 1, &v); }

/* OES_matrix_get: each element's IEEE single bit pattern, as an integer */
static int put_float_bits(double *out, int *kind, const double *m)
{
    for (int i = 0; i < 16; i++) {
        float f = (float)m[i];
        int32_t bits;
        memcpy(&bits, &f, sizeof bits);
        out[i] = bits;
    }
    *kind = GLES_KIND_ENUM; /* returned unscaled by every Get */
    return 16;
}

/* the bound framebuffer's buffers for a query about them, recording no
** error when it is incomplete (then the values are the window's) */
static void quiet_sync(GlesContext *ctx)
{
    const unsigned int err = ctx->error;
    fbo_sync(ctx);
    ctx->error = err;
}

void gles_draw_size(GlesContext *ctx, int *wh)
{
    quiet_sync(ctx);
    wh[0] = ctx->width;
    wh[1] = ctx->height;
}

int gles_get(GlesContext *ctx, unsigned int pname, double *out, int *kind)
{
    double v[16];
    switch (pname) {
    /* implementation limits */
    case GL_MAX_MODELVIEW_STACK_DEPTH: return put1(out, kind, GLES_KIND_INT, GLES_MODELVIEW_STACK_DEPTH);
    case GL_MAX_PROJECTION_STACK_DEPTH: return put1(out, kind, GLES_KIND_INT, GLES_PROJECTION_STACK_DEPTH);
    case GL_MAX_TEXTURE_STACK_DEPTH: return put1(out, kind, GLES_KIND_INT, GLES_TEXTURE_STACK_DEPTH);
    case GL_MAX_CLIP_PLANES: return put1(out, kind, GLES_KIND_INT, GLES_MAX_CLIP_PLANES);
    case GL_MAX_TEXTURE_UNITS: return put1(out, kind, GLES_KIND_INT, GLES_MAX_TEXTURE_UNITS);
    case GL_MAX_LIGHTS: return put1(out, kind, GLES_KIND_INT, GLES_MAX_LIGHTS);
    case GL_ALIASED_POINT_SIZE_RANGE: case GL_SMOOTH_POINT_SIZE_RANGE:
    case GL_ALIASED_LINE_WIDTH_RANGE: case GL_SMOOTH_LINE_WIDTH_RANGE:
        v[0] = 1;
        v[1] = 64;
        return put(out, kind, GLES_KIND_FLOAT, 2, v);
    case GL_POINT_SIZE: return put1(out, kind, GLES_KIND_FLOAT, ctx->point_size);
    case GL_LINE_WIDTH: return put1(out, kind, GLES_KIND_FLOAT, ctx->line_width);
    case GL_POINT_SIZE_MIN: return put1(out, kind, GLES_KIND_FLOAT, ctx->point_size_min);
    case GL_POINT_SIZE_MAX: return put1(out, kind, GLES_KIND_FLOAT, ctx->point_size_max);
    case GL_POINT_FADE_THRESHOLD_SIZE: return put1(out, kind, GLES_KIND_FLOAT, ctx->point_fade_threshold);
    case GL_POINT_DISTANCE_ATTENUATION: return put(out, kind, GLES_KIND_FLOAT, 3, ctx->point_attenuation);
    case GL_POLYGON_OFFSET_FACTOR: return put1(out, kind, GLES_KIND_FLOAT, ctx->offset_factor);
    case GL_POLYGON_OFFSET_UNITS: return put1(out, kind, GLES_KIND_FLOAT, ctx->offset_units);
    case GL_MAX_PALETTE_MATRICES_OES: return put1(out, kind, GLES_KIND_INT, GLES_MAX_PALETTE_MATRICES);
    case GL_MAX_VERTEX_UNITS_OES: return put1(out, kind, GLES_KIND_INT, GLES_MAX_VERTEX_UNITS);
    case GL_CURRENT_PALETTE_MATRIX_OES: return put1(out, kind, GLES_KIND_INT, ctx->current_palette);
    case GL_LIGHT_MODEL_AMBIENT: return put(out, kind, GLES_KIND_NORM, 4, ctx->light_model_ambient);
    case GL_LIGHT_MODEL_TWO_SIDE: return put1(out, kind, GLES_KIND_BOOL, ctx->light_model_two_side);
    case GL_MAX_VIEWPORT_DIMS:
        v[0] = v[1] = GLES_MAX_VIEWPORT_DIM;
        return put(out, kind, GLES_KIND_INT, 2, v);
    case GL_SUBPIXEL_BITS: return put1(out, kind, GLES_KIND_INT, GLES_SUBPIXEL_BITS);
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: case GL_ALPHA_BITS: {
        quiet_sync(ctx);
        const int i = (int)(pname - GL_RED_BITS);
        /* an RGBA8888 buffer that keeps no alpha (RGB8, an RGB texture) has none */
        return put1(out, kind, GLES_KIND_INT, i == 3 && !ctx->color_alpha ? 0 : color_channel_bits(ctx->color_format, i));
    }
    case GL_DEPTH_BITS: quiet_sync(ctx); return put1(out, kind, GLES_KIND_INT, ctx->depth_bits);
    case GL_STENCIL_BITS: quiet_sync(ctx); return put1(out, kind, GLES_KIND_INT, ctx->stencil_bits);
    case GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES:
    case GL_IMPLEMENTATION_COLOR_READ_TYPE_OES: {
        quiet_sync(ctx);
        unsigned int f, t;
        color_read_pair(ctx->color_format, &f, &t);
        return put1(out, kind, GLES_KIND_ENUM, pname == GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES ? f : t);
    }

    /* transformation */
    case GL_MATRIX_MODE: return put1(out, kind, GLES_KIND_ENUM, ctx->matrix_mode);
    case GL_MODELVIEW_MATRIX: return put(out, kind, GLES_KIND_FLOAT, 16, ctx->modelview.top->d);
    case GL_PROJECTION_MATRIX: return put(out, kind, GLES_KIND_FLOAT, 16, ctx->projection.top->d);
    case GL_TEXTURE_MATRIX:
        return put(out, kind, GLES_KIND_FLOAT, 16, ctx->texture[ctx->active_texture - GL_TEXTURE0].top->d);
    case GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES:
        return put_float_bits(out, kind, ctx->modelview.top->d);
    case GL_PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES:
        return put_float_bits(out, kind, ctx->projection.top->d);
    case GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES:
        return put_float_bits(out, kind, ctx->texture[ctx->active_texture - GL_TEXTURE0].top->d);
    case GL_MODELVIEW_STACK_DEPTH: return put1(out, kind, GLES_KIND_INT, ctx->modelview.depth);
    case GL_PROJECTION_STACK_DEPTH: return put1(out, kind, GLES_KIND_INT, ctx->projection.depth);
    case GL_TEXTURE_STACK_DEPTH:
        return put1(out, kind, GLES_KIND_INT, ctx->texture[ctx->active_texture - GL_TEXTURE0].depth);
    case GL_VIEWPORT:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->viewport[i];
        return put(out, kind, GLES_KIND_INT, 4, v);
    case GL_DEPTH_RANGE: return put(out, kind, GLES_KIND_NORM, 2, ctx->depth_range);
    case GL_ACTIVE_TEXTURE: return put1(out, kind, GLES_KIND_ENUM, ctx->active_texture);
    case GL_CLIENT_ACTIVE_TEXTURE: return put1(out, kind, GLES_KIND_ENUM, ctx->client_active_texture);

    /* rasterization and fragments */
    case GL_CULL_FACE_MODE: return put1(out, kind, GLES_KIND_ENUM, ctx->cull_mode);
    case GL_FRONT_FACE: return put1(out, kind, GLES_KIND_ENUM, ctx->front_face);
    case GL_SHADE_MODEL: return put1(out, kind, GLES_KIND_ENUM, ctx->shade_model);
    case GL_SCISSOR_BOX:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->scissor[i];
        return put(out, kind, GLES_KIND_INT, 4, v);
    case GL_COLOR_CLEAR_VALUE: return put(out, kind, GLES_KIND_NORM, 4, ctx->clear_color);
    case GL_DEPTH_CLEAR_VALUE: return put1(out, kind, GLES_KIND_NORM, ctx->clear_depth);
    case GL_STENCIL_CLEAR_VALUE: return put1(out, kind, GLES_KIND_INT, ctx->clear_stencil);
    case GL_COLOR_WRITEMASK:
        for (int i = 0; i < 3; i++)
            v[i] = ctx->color_mask[i];
        v[3] = ctx->color_mask_alpha;
        return put(out, kind, GLES_KIND_BOOL, 4, v);
    case GL_DEPTH_WRITEMASK: return put1(out, kind, GLES_KIND_BOOL, ctx->depth_mask);
    case GL_DEPTH_FUNC: return put1(out, kind, GLES_KIND_ENUM, ctx->depth_func);
    case GL_PACK_ALIGNMENT: return put1(out, kind, GLES_KIND_INT, ctx->pack_alignment);
    case GL_UNPACK_ALIGNMENT: return put1(out, kind, GLES_KIND_INT, ctx->unpack_alignment);
    case GL_PERSPECTIVE_CORRECTION_HINT: return put1(out, kind, GLES_KIND_ENUM, ctx->hints[0]);
    case GL_POINT_SMOOTH_HINT: return put1(out, kind, GLES_KIND_ENUM, ctx->hints[1]);
    case GL_LINE_SMOOTH_HINT: return put1(out, kind, GLES_KIND_ENUM, ctx->hints[2]);
    case GL_FOG_HINT: return put1(out, kind, GLES_KIND_ENUM, ctx->hints[3]);
    case GL_GENERATE_MIPMAP_HINT: return put1(out, kind, GLES_KIND_ENUM, ctx->hint_generate_mipmap);

    /* current values */
    case GL_CURRENT_COLOR: return put(out, kind, GLES_KIND_NORM, 4, ctx->cur_color);
    case GL_CURRENT_NORMAL: return put(out, kind, GLES_KIND_NORM, 3, ctx->cur_normal);
    case GL_CURRENT_TEXTURE_COORDS:
        return put(out, kind, GLES_KIND_FLOAT, 4, ctx->cur_tex[ctx->active_texture - GL_TEXTURE0]);

    /* buffer bindings */
    case GL_ARRAY_BUFFER_BINDING:
        return put1(out, kind, GLES_KIND_INT, ctx->array_buffer ? ctx->array_buffer->name : 0);
    case GL_ELEMENT_ARRAY_BUFFER_BINDING:
        return put1(out, kind, GLES_KIND_INT, ctx->element_buffer ? ctx->element_buffer->name : 0);
    default:
        break;
    }
    int n = array_get(ctx, pname, out, kind);
    if (n > 0 || (n = fbo_get(ctx, pname, out, kind)) > 0)
        return n;
    if ((n = fragment_get(ctx, pname, out, kind)) > 0 || (n = fog_get(ctx, pname, out, kind)) > 0
        || (n = texture_get(ctx, pname, out, kind)) > 0 || (n = debug_get(ctx, pname, out, kind)) > 0)
        return n;
    /* an enable queried through Get*v answers like IsEnabled */
    if (cap_index(pname) >= 0 || pname == GL_TEXTURE_2D || pname == GL_TEXTURE_CUBE_MAP_OES
        || pname == GL_TEXTURE_GEN_STR_OES || (pname >= GL_CLIP_PLANE0 && pname < GL_CLIP_PLANE0 + GLES_MAX_CLIP_PLANES)
        || (pname >= GL_LIGHT0 && pname < GL_LIGHT0 + 8))
        return put1(out, kind, GLES_KIND_BOOL, gles_IsEnabled(ctx, pname));
    ctx_error(ctx, GL_INVALID_ENUM);
    return 0;
}

/* {====================================================================
** points, lines, polygon offset (§3.3-3.5) */

void gles_PointSize(GlesContext *ctx, double size)
{
    if (!(size > 0)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    ctx->point_size = size;
    ctx->n_point_size = num_from_double(size);
}

void gles_LineWidth(GlesContext *ctx, double width)
{
    if (!(width > 0)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    ctx->line_width = width;
}

void gles_PointParameter(GlesContext *ctx, unsigned int pname, const double *p, int vector)
{
    switch (pname) {
    case GL_POINT_SIZE_MIN: case GL_POINT_SIZE_MAX: case GL_POINT_FADE_THRESHOLD_SIZE:
        if (!(p[0] >= 0)) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        if (pname == GL_POINT_SIZE_MIN) {
            ctx->point_size_min = p[0];
            ctx->n_point_size_min = num_from_double(p[0]);
        } else if (pname == GL_POINT_SIZE_MAX) {
            ctx->point_size_max = p[0];
            ctx->n_point_size_max = num_from_double(p[0]);
        } else {
            ctx->point_fade_threshold = p[0];
        }
        break;
    case GL_POINT_DISTANCE_ATTENUATION:
        if (!vector) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        for (int i = 0; i < 3; i++) {
            ctx->point_attenuation[i] = p[i];
            ctx->n_point_attenuation[i] = num_from_double(p[i]);
        }
        ctx->dirty |= DIRTY_CLIP;
        break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
}

void gles_PolygonOffset(GlesContext *ctx, double factor, double units)
{
    ctx->offset_factor = factor;
    ctx->offset_units = units;
}
