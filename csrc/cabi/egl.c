/*
** egl.c -- libEGL: a minimal EGL 1.4 for the core (compiled once per numeric
** build and profile; GLES_CABI_COMMON as in gl.c).
**
** One display (eglGetDisplay(EGL_DEFAULT_DISPLAY), or the surfaceless
** platform through eglGetPlatformDisplay(EXT)); twenty-four configs,
** RGBA8888, RGB565, RGBA4444 and RGBA5551 by depth 0/16/24 by stencil 0/8,
** all pbuffer-only and OpenGL ES 1 (the 16-bit RGBA ones last, IDs 13-24,
** so that eglChooseConfig's sort, whose ties go to the lower ID, still puts
** first what it put first with twelve);
** pbuffer surfaces; OpenGL ES 1 contexts; a current context per thread.
** There is no window system: window and pixmap surfaces give
** EGL_BAD_NATIVE_WINDOW / EGL_BAD_NATIVE_PIXMAP.
**
** The core keeps the framebuffer inside its context, so an EGL context
** creates its core context when it is first made current, with the size
** and formats of that draw surface. A surface's pixels live in the core of
** the context last bound to it; when a context moves to another surface, or
** a surface to another context, the pixels move with the surface. A core's
** framebuffer keeps its first size: binding a context to a surface of
** another size is EGL_BAD_MATCH, as is draw != read (one framebuffer per
** context).
*/
#define _GNU_SOURCE 1   /* dladdr */
#include <dlfcn.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* built -fvisibility=hidden: the entry points take their (default)
** visibility from these declarations */
#define EGL_EGLEXT_PROTOTYPES 1
#pragma GCC visibility push(default)
#include <EGL/egl.h>
#include <EGL/eglext.h>
#pragma GCC visibility pop

#include "cabi/cabi.h"
#include "cabi/procs.h"

#ifndef GLES_CABI_COMMON
#error "define GLES_CABI_COMMON to 1 (Common) or 0 (Common-Lite)"
#endif

#define MAX_PBUFFER 4096   /* the core's largest framebuffer side */

/* {====================================================================
** objects */

typedef struct {
    EGLint id, red, green, blue, alpha, depth, stencil;
    int color_format;      /* GLES_COLOR_* */
} Config;

#define NCONFIGS 24
static const Config configs[NCONFIGS] = {
    {1, 8, 8, 8, 8, 0, 0, GLES_COLOR_RGBA8888},  {2, 8, 8, 8, 8, 0, 8, GLES_COLOR_RGBA8888},
    {3, 8, 8, 8, 8, 16, 0, GLES_COLOR_RGBA8888}, {4, 8, 8, 8, 8, 16, 8, GLES_COLOR_RGBA8888},
    {5, 8, 8, 8, 8, 24, 0, GLES_COLOR_RGBA8888}, {6, 8, 8, 8, 8, 24, 8, GLES_COLOR_RGBA8888},
    {7, 5, 6, 5, 0, 0, 0, GLES_COLOR_RGB565},    {8, 5, 6, 5, 0, 0, 8, GLES_COLOR_RGB565},
    {9, 5, 6, 5, 0, 16, 0, GLES_COLOR_RGB565},   {10, 5, 6, 5, 0, 16, 8, GLES_COLOR_RGB565},
    {11, 5, 6, 5, 0, 24, 0, GLES_COLOR_RGB565},  {12, 5, 6, 5, 0, 24, 8, GLES_COLOR_RGB565},
    {13, 4, 4, 4, 4, 0, 0, GLES_COLOR_RGBA4444}, {14, 4, 4, 4, 4, 0, 8, GLES_COLOR_RGBA4444},
    {15, 4, 4, 4, 4, 16, 0, GLES_COLOR_RGBA4444}, {16, 4, 4, 4, 4, 16, 8, GLES_COLOR_RGBA4444},
    {17, 4, 4, 4, 4, 24, 0, GLES_COLOR_RGBA4444}, {18, 4, 4, 4, 4, 24, 8, GLES_COLOR_RGBA4444},
    {19, 5, 5, 5, 1, 0, 0, GLES_COLOR_RGBA5551}, {20, 5, 5, 5, 1, 0, 8, GLES_COLOR_RGBA5551},
    {21, 5, 5, 5, 1, 16, 0, GLES_COLOR_RGBA5551}, {22, 5, 5, 5, 1, 16, 8, GLES_COLOR_RGBA5551},
    {23, 5, 5, 5, 1, 24, 0, GLES_COLOR_RGBA5551}, {24, 5, 5, 5, 1, 24, 8, GLES_COLOR_RGBA5551},
};

typedef struct Context Context;

typedef struct Surface {
    struct Surface *next;
    const Config *config;
    EGLint width, height, largest, mipmap_level;
    Context *owner;        /* the context whose core holds the pixels */
    unsigned char *saved;  /* else the pixels (colour, depth, stencil), or NULL */
    int current;           /* current in some thread */
    int destroyed;         /* the handle is dead; freed once not current */
} Surface;

struct Context {
    Context *next;
    const Config *config;
    GlesContext *core;     /* created at the first eglMakeCurrent */
    Surface *surface;      /* the surface its core renders */
    int current, destroyed;
    int debug;             /* EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR: a KHR_debug debug context */
};

typedef struct {
    int initialized;
    Surface *surfaces;
    Context *contexts;
} Display;

static Display display;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

static _Thread_local EGLint last_error = EGL_SUCCESS;
static _Thread_local EGLenum bound_api = EGL_OPENGL_ES_API;
static _Thread_local Context *cur_context;
static _Thread_local Surface *cur_surface;

/* {====================================================================
** errors and handle checks (call with the lock held) */

static EGLBoolean fail(EGLint err)
{
    last_error = err;
    return EGL_FALSE;
}

static EGLBoolean ok(void)
{
    last_error = EGL_SUCCESS;
    return EGL_TRUE;
}

/* the display, or NULL with BAD_DISPLAY / NOT_INITIALIZED recorded */
static Display *check_display(EGLDisplay dpy)
{
    if (dpy != (EGLDisplay)&display) {
        fail(EGL_BAD_DISPLAY);
        return NULL;
    }
    if (!display.initialized) {
        fail(EGL_NOT_INITIALIZED);
        return NULL;
    }
    return &display;
}

static const Config *check_config(EGLConfig config)
{
    for (int i = 0; i < NCONFIGS; i++)
        if (config == (EGLConfig)&configs[i])
            return &configs[i];
    fail(EGL_BAD_CONFIG);
    return NULL;
}

static Surface *find_surface(EGLSurface s)
{
    for (Surface *p = display.surfaces; p; p = p->next)
        if ((EGLSurface)p == s && !p->destroyed)
            return p;
    return NULL;
}

static Context *find_context(EGLContext c)
{
    for (Context *p = display.contexts; p; p = p->next)
        if ((EGLContext)p == c && !p->destroyed)
            return p;
    return NULL;
}

/* the live surface (context) of a valid display, or NULL with the error recorded */
static Surface *check_surface(EGLDisplay dpy, EGLSurface surface)
{
    if (!check_display(dpy))
        return NULL;
    Surface *s = find_surface(surface);
    if (!s)
        fail(EGL_BAD_SURFACE);
    return s;
}

static Context *check_context(EGLDisplay dpy, EGLContext context)
{
    if (!check_display(dpy))
        return NULL;
    Context *c = find_context(context);
    if (!c)
        fail(EGL_BAD_CONTEXT);
    return c;
}

/* the bytes of a core context's colour, depth and stencil buffers */
static size_t pixel_bytes(GlesContext *core, const Config *cfg, size_t part[3])
{
    size_t n = (size_t)gles_width(core) * (size_t)gles_height(core);
    part[0] = n * (cfg->color_format == GLES_COLOR_RGBA8888 ? 4 : 2);
    part[1] = cfg->depth ? n * 4 : 0;
    part[2] = cfg->stencil ? n : 0;
    return part[0] + part[1] + part[2];
}

/* move the pixels of c's core into its surface and unbind the two;
** 0 if there is no memory for them */
static int detach(Context *c)
{
    Surface *s = c->surface;
    size_t part[3];
    size_t total = pixel_bytes(c->core, c->config, part);
    if (!s->saved && !(s->saved = malloc(total)))
        return 0;
    memcpy(s->saved, gles_color_buffer(c->core), part[0]);
    if (part[1])
        memcpy(s->saved + part[0], gles_depth_buffer(c->core), part[1]);
    if (part[2])
        memcpy(s->saved + part[0] + part[1], gles_stencil_buffer(c->core), part[2]);
    s->owner = NULL;
    c->surface = NULL;
    return 1;
}

/* the surface's saved pixels (if it has any) into c's core */
static void attach(Context *c, Surface *s)
{
    if (s->saved) {
        size_t part[3];
        pixel_bytes(c->core, c->config, part);
        memcpy(gles_color_buffer(c->core), s->saved, part[0]);
        if (part[1])
            memcpy(gles_depth_buffer(c->core), s->saved + part[0], part[1]);
        if (part[2])
            memcpy(gles_stencil_buffer(c->core), s->saved + part[0] + part[1], part[2]);
    }
    c->surface = s;
    s->owner = c;
}

/* free the destroyed objects no thread has current */
static void collect(void)
{
    for (Context **pp = &display.contexts; *pp;) {
        Context *c = *pp;
        if (c->destroyed && !c->current) {
            *pp = c->next;
            /* the surface keeps its pixels (if there is memory for them) */
            if (c->surface && !detach(c)) {
                c->surface->owner = NULL;
                c->surface = NULL;
            }
            if (c->core)
                gles_context_destroy(c->core);
            free(c);
        } else {
            pp = &c->next;
        }
    }
    for (Surface **pp = &display.surfaces; *pp;) {
        Surface *s = *pp;
        if (s->destroyed && !s->current) {
            *pp = s->next;
            if (s->owner)
                s->owner->surface = NULL;
            free(s->saved);
            free(s);
        } else {
            pp = &s->next;
        }
    }
}

/* make nothing current in the calling thread */
static void release_current(void)
{
    if (cur_context)
        cur_context->current = 0;
    if (cur_surface)
        cur_surface->current = 0;
    cur_context = NULL;
    cur_surface = NULL;
    gles_cabi_set_current(NULL);
    collect();
}

/* {====================================================================
** displays */

EGLAPI EGLDisplay EGLAPIENTRY eglGetDisplay(EGLNativeDisplayType display_id)
{
    /* no window system: only the default display exists */
    if (display_id != EGL_DEFAULT_DISPLAY)
        return EGL_NO_DISPLAY;
    return (EGLDisplay)&display;
}

static EGLDisplay platform_display(EGLenum platform, void *native_display, int attribs_nonempty)
{
    if (platform != EGL_PLATFORM_SURFACELESS_MESA) {
        fail(EGL_BAD_PARAMETER);
        return EGL_NO_DISPLAY;
    }
    if (native_display != NULL) {
        fail(EGL_BAD_PARAMETER);
        return EGL_NO_DISPLAY;
    }
    if (attribs_nonempty) {
        fail(EGL_BAD_ATTRIBUTE);
        return EGL_NO_DISPLAY;
    }
    ok();
    return (EGLDisplay)&display;
}

EGLAPI EGLDisplay EGLAPIENTRY eglGetPlatformDisplay(EGLenum platform, void *native_display,
                                                    const EGLAttrib *attrib_list)
{
    return platform_display(platform, native_display, attrib_list && attrib_list[0] != EGL_NONE);
}

EGLAPI EGLDisplay EGLAPIENTRY eglGetPlatformDisplayEXT(EGLenum platform, void *native_display,
                                                       const EGLint *attrib_list)
{
    return platform_display(platform, native_display, attrib_list && attrib_list[0] != EGL_NONE);
}

EGLAPI EGLBoolean EGLAPIENTRY eglInitialize(EGLDisplay dpy, EGLint *major, EGLint *minor)
{
    if (dpy != (EGLDisplay)&display)
        return fail(EGL_BAD_DISPLAY);
    pthread_mutex_lock(&lock);
    display.initialized = 1;
    pthread_mutex_unlock(&lock);
    if (major)
        *major = 1;
    if (minor)
        *minor = 4;
    return ok();
}

EGLAPI EGLBoolean EGLAPIENTRY eglTerminate(EGLDisplay dpy)
{
    if (dpy != (EGLDisplay)&display)
        return fail(EGL_BAD_DISPLAY);
    pthread_mutex_lock(&lock);
    /* every handle dies now; what is current stays usable until released */
    for (Context *c = display.contexts; c; c = c->next)
        c->destroyed = 1;
    for (Surface *s = display.surfaces; s; s = s->next)
        s->destroyed = 1;
    display.initialized = 0;
    collect();
    pthread_mutex_unlock(&lock);
    return ok();
}

#define CLIENT_EXTENSIONS "EGL_EXT_client_extensions EGL_EXT_platform_base EGL_KHR_client_get_all_proc_addresses " \
                          "EGL_MESA_platform_surfaceless"
#define DISPLAY_EXTENSIONS "EGL_KHR_create_context EGL_KHR_get_all_proc_addresses"

EGLAPI const char *EGLAPIENTRY eglQueryString(EGLDisplay dpy, EGLint name)
{
    if (dpy == EGL_NO_DISPLAY && name == EGL_EXTENSIONS) {
        ok();
        return CLIENT_EXTENSIONS;
    }
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (!d)
        return NULL;
    switch (name) {
    case EGL_VENDOR: ok(); return "gles";
#if GLES_CABI_COMMON
    case EGL_VERSION: ok(); return "1.4 gles (OpenGL ES-CM 1.1)";
#else
    case EGL_VERSION: ok(); return "1.4 gles (OpenGL ES-CL 1.1)";
#endif
    case EGL_CLIENT_APIS: ok(); return "OpenGL_ES";
    case EGL_EXTENSIONS: ok(); return DISPLAY_EXTENSIONS;
    default: fail(EGL_BAD_PARAMETER); return NULL;
    }
}

EGLAPI EGLint EGLAPIENTRY eglGetError(void)
{
    EGLint e = last_error;
    last_error = EGL_SUCCESS;
    return e;
}

/* {====================================================================
** configs */

/* a config's attribute: 1, or 0 for an attribute EGL does not define */
static int config_attrib(const Config *c, EGLint attribute, EGLint *value)
{
    EGLint v;
    switch (attribute) {
    case EGL_BUFFER_SIZE: v = c->red + c->green + c->blue + c->alpha; break;
    case EGL_RED_SIZE: v = c->red; break;
    case EGL_GREEN_SIZE: v = c->green; break;
    case EGL_BLUE_SIZE: v = c->blue; break;
    case EGL_ALPHA_SIZE: v = c->alpha; break;
    case EGL_LUMINANCE_SIZE: v = 0; break;
    case EGL_ALPHA_MASK_SIZE: v = 0; break;
    case EGL_DEPTH_SIZE: v = c->depth; break;
    case EGL_STENCIL_SIZE: v = c->stencil; break;
    case EGL_CONFIG_ID: v = c->id; break;
    case EGL_CONFIG_CAVEAT: v = EGL_NONE; break;
    case EGL_COLOR_BUFFER_TYPE: v = EGL_RGB_BUFFER; break;
    case EGL_LEVEL: v = 0; break;
    case EGL_MAX_PBUFFER_WIDTH: v = MAX_PBUFFER; break;
    case EGL_MAX_PBUFFER_HEIGHT: v = MAX_PBUFFER; break;
    case EGL_MAX_PBUFFER_PIXELS: v = MAX_PBUFFER * MAX_PBUFFER; break;
    case EGL_MAX_SWAP_INTERVAL: v = 1; break;
    case EGL_MIN_SWAP_INTERVAL: v = 0; break;
    case EGL_NATIVE_RENDERABLE: v = EGL_FALSE; break;
    case EGL_NATIVE_VISUAL_ID: v = 0; break;
    case EGL_NATIVE_VISUAL_TYPE: v = EGL_NONE; break;
    case EGL_RENDERABLE_TYPE: v = EGL_OPENGL_ES_BIT; break;
    case EGL_CONFORMANT: v = EGL_OPENGL_ES_BIT; break;
    case EGL_SAMPLE_BUFFERS: v = 0; break;
    case EGL_SAMPLES: v = 0; break;
    case EGL_SURFACE_TYPE: v = EGL_PBUFFER_BIT; break;
    case EGL_TRANSPARENT_TYPE: v = EGL_NONE; break;
    case EGL_TRANSPARENT_RED_VALUE: v = 0; break;
    case EGL_TRANSPARENT_GREEN_VALUE: v = 0; break;
    case EGL_TRANSPARENT_BLUE_VALUE: v = 0; break;
    case EGL_BIND_TO_TEXTURE_RGB: v = EGL_FALSE; break;
    case EGL_BIND_TO_TEXTURE_RGBA: v = EGL_FALSE; break;
    default: return 0;
    }
    *value = v;
    return 1;
}

EGLAPI EGLBoolean EGLAPIENTRY eglGetConfigs(EGLDisplay dpy, EGLConfig *out, EGLint config_size, EGLint *num_config)
{
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (!d)
        return EGL_FALSE;
    if (!num_config)
        return fail(EGL_BAD_PARAMETER);
    if (!out) {
        *num_config = NCONFIGS;
        return ok();
    }
    EGLint n = config_size < NCONFIGS ? (config_size > 0 ? config_size : 0) : NCONFIGS;
    for (EGLint i = 0; i < n; i++)
        out[i] = (EGLConfig)&configs[i];
    *num_config = n;
    return ok();
}

EGLAPI EGLBoolean EGLAPIENTRY eglGetConfigAttrib(EGLDisplay dpy, EGLConfig config, EGLint attribute, EGLint *value)
{
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (!d)
        return EGL_FALSE;
    const Config *c = check_config(config);
    if (!c)
        return EGL_FALSE;
    EGLint v;
    if (!config_attrib(c, attribute, &v))
        return fail(EGL_BAD_ATTRIBUTE);
    if (!value)
        return fail(EGL_BAD_PARAMETER);
    *value = v;
    return ok();
}

/* how eglChooseConfig matches an attribute (EGL 1.4, Table 3.4) */
enum { M_ATLEAST, M_EXACT, M_MASK, M_IGNORE };

typedef struct {
    EGLint attribute, fallback;
    int match;
} Criterion;

static const Criterion criteria[] = {
    {EGL_BUFFER_SIZE, 0, M_ATLEAST},          {EGL_RED_SIZE, 0, M_ATLEAST},
    {EGL_GREEN_SIZE, 0, M_ATLEAST},           {EGL_BLUE_SIZE, 0, M_ATLEAST},
    {EGL_LUMINANCE_SIZE, 0, M_ATLEAST},       {EGL_ALPHA_SIZE, 0, M_ATLEAST},
    {EGL_ALPHA_MASK_SIZE, 0, M_ATLEAST},      {EGL_BIND_TO_TEXTURE_RGB, EGL_DONT_CARE, M_EXACT},
    {EGL_BIND_TO_TEXTURE_RGBA, EGL_DONT_CARE, M_EXACT}, {EGL_COLOR_BUFFER_TYPE, EGL_RGB_BUFFER, M_EXACT},
    {EGL_CONFIG_CAVEAT, EGL_DONT_CARE, M_EXACT}, {EGL_CONFIG_ID, EGL_DONT_CARE, M_EXACT},
    {EGL_CONFORMANT, 0, M_MASK},              {EGL_DEPTH_SIZE, 0, M_ATLEAST},
    {EGL_LEVEL, 0, M_EXACT},                  {EGL_MAX_PBUFFER_WIDTH, 0, M_IGNORE},
    {EGL_MAX_PBUFFER_HEIGHT, 0, M_IGNORE},    {EGL_MAX_PBUFFER_PIXELS, 0, M_IGNORE},
    {EGL_MAX_SWAP_INTERVAL, EGL_DONT_CARE, M_EXACT}, {EGL_MIN_SWAP_INTERVAL, EGL_DONT_CARE, M_EXACT},
    {EGL_NATIVE_RENDERABLE, EGL_DONT_CARE, M_EXACT}, {EGL_NATIVE_VISUAL_ID, 0, M_IGNORE},
    {EGL_NATIVE_VISUAL_TYPE, EGL_DONT_CARE, M_EXACT}, {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, M_MASK},
    {EGL_SAMPLE_BUFFERS, 0, M_ATLEAST},       {EGL_SAMPLES, 0, M_ATLEAST},
    {EGL_STENCIL_SIZE, 0, M_ATLEAST},         {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, M_MASK},
    {EGL_TRANSPARENT_TYPE, EGL_NONE, M_EXACT}, {EGL_TRANSPARENT_RED_VALUE, EGL_DONT_CARE, M_EXACT},
    {EGL_TRANSPARENT_GREEN_VALUE, EGL_DONT_CARE, M_EXACT}, {EGL_TRANSPARENT_BLUE_VALUE, EGL_DONT_CARE, M_EXACT},
};
#define NCRITERIA ((int)(sizeof criteria / sizeof criteria[0]))

/* sort keys of Table 3.4 that can differ between our configs: the colour
** bits asked for (more first), then buffer size, depth, stencil (fewer
** first), then the config ID */
static EGLint sort_want[4];   /* red, green, blue, alpha as asked; only under the lock */

static int config_order(const void *pa, const void *pb)
{
    const Config *a = *(const Config *const *)pa, *b = *(const Config *const *)pb;
    EGLint ca = 0, cb = 0;
    const EGLint av[4] = {a->red, a->green, a->blue, a->alpha}, bv[4] = {b->red, b->green, b->blue, b->alpha};
    for (int i = 0; i < 4; i++)
        if (sort_want[i] != 0 && sort_want[i] != EGL_DONT_CARE) {
            ca += av[i];
            cb += bv[i];
        }
    if (ca != cb)
        return cb - ca;
    EGLint ka[4] = {a->red + a->green + a->blue + a->alpha, a->depth, a->stencil, a->id};
    EGLint kb[4] = {b->red + b->green + b->blue + b->alpha, b->depth, b->stencil, b->id};
    for (int i = 0; i < 4; i++)
        if (ka[i] != kb[i])
            return ka[i] - kb[i];
    return 0;
}

EGLAPI EGLBoolean EGLAPIENTRY eglChooseConfig(EGLDisplay dpy, const EGLint *attrib_list, EGLConfig *out,
                                              EGLint config_size, EGLint *num_config)
{
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (!d)
        return EGL_FALSE;
    if (!num_config)
        return fail(EGL_BAD_PARAMETER);
    EGLint want[NCRITERIA];
    for (int i = 0; i < NCRITERIA; i++)
        want[i] = criteria[i].fallback;
    int pixmap = 0;
    for (const EGLint *a = attrib_list; a && a[0] != EGL_NONE; a += 2) {
        if (a[0] == EGL_MATCH_NATIVE_PIXMAP) {
            pixmap = a[1] != EGL_NONE;
            continue;
        }
        int k = 0;
        while (k < NCRITERIA && criteria[k].attribute != a[0])
            k++;
        if (k == NCRITERIA)
            return fail(EGL_BAD_ATTRIBUTE);
        want[k] = a[1];
    }
    const Config *match[NCONFIGS];
    int n = 0;
    EGLint id = EGL_DONT_CARE;
    for (int k = 0; k < NCRITERIA; k++)
        if (criteria[k].attribute == EGL_CONFIG_ID)
            id = want[k];
    for (int c = 0; c < NCONFIGS && !pixmap; c++) {
        int good = 1;
        if (id != EGL_DONT_CARE) {
            /* a given CONFIG_ID overrides every other attribute */
            good = configs[c].id == id;
        } else {
            for (int k = 0; k < NCRITERIA && good; k++) {
                EGLint w = want[k], v = 0;
                if (criteria[k].match == M_IGNORE || w == EGL_DONT_CARE)
                    continue;
                config_attrib(&configs[c], criteria[k].attribute, &v);
                switch (criteria[k].match) {
                case M_ATLEAST: good = v >= w; break;
                case M_EXACT: good = v == w; break;
                case M_MASK: good = (v & w) == w; break;
                default: break;
                }
            }
        }
        if (good)
            match[n++] = &configs[c];
    }
    pthread_mutex_lock(&lock);
    for (int k = 0; k < NCRITERIA; k++) {
        EGLint at = criteria[k].attribute;
        int slot = at == EGL_RED_SIZE ? 0 : at == EGL_GREEN_SIZE ? 1 : at == EGL_BLUE_SIZE ? 2
                 : at == EGL_ALPHA_SIZE ? 3 : -1;
        if (slot >= 0)
            sort_want[slot] = want[k];
    }
    qsort(match, (size_t)n, sizeof match[0], config_order);
    pthread_mutex_unlock(&lock);
    if (!out) {
        *num_config = n;
        return ok();
    }
    EGLint m = config_size < n ? (config_size > 0 ? config_size : 0) : n;
    for (EGLint i = 0; i < m; i++)
        out[i] = (EGLConfig)match[i];
    *num_config = m;
    return ok();
}

/* {====================================================================
** surfaces */

EGLAPI EGLSurface EGLAPIENTRY eglCreatePbufferSurface(EGLDisplay dpy, EGLConfig config, const EGLint *attrib_list)
{
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (!d)
        return EGL_NO_SURFACE;
    const Config *c = check_config(config);
    if (!c)
        return EGL_NO_SURFACE;
    EGLint width = 0, height = 0, largest = EGL_FALSE;
    EGLint tex_format = EGL_NO_TEXTURE, tex_target = EGL_NO_TEXTURE;
    for (const EGLint *a = attrib_list; a && a[0] != EGL_NONE; a += 2) {
        switch (a[0]) {
        case EGL_WIDTH: width = a[1]; break;
        case EGL_HEIGHT: height = a[1]; break;
        case EGL_LARGEST_PBUFFER: largest = a[1] != EGL_FALSE; break;
        case EGL_TEXTURE_FORMAT: tex_format = a[1]; break;
        case EGL_TEXTURE_TARGET: tex_target = a[1]; break;
        case EGL_MIPMAP_TEXTURE: break;
        case EGL_VG_COLORSPACE: case EGL_VG_ALPHA_FORMAT: break;
        default: fail(EGL_BAD_ATTRIBUTE); return EGL_NO_SURFACE;
        }
    }
    if ((tex_format != EGL_NO_TEXTURE && tex_format != EGL_TEXTURE_RGB && tex_format != EGL_TEXTURE_RGBA)
        || (tex_target != EGL_NO_TEXTURE && tex_target != EGL_TEXTURE_2D)) {
        fail(EGL_BAD_ATTRIBUTE);
        return EGL_NO_SURFACE;
    }
    /* no config binds to textures; one of the two set without the other */
    if (tex_format != EGL_NO_TEXTURE || tex_target != EGL_NO_TEXTURE) {
        fail(EGL_BAD_MATCH);
        return EGL_NO_SURFACE;
    }
    if (width < 0 || height < 0) {
        fail(EGL_BAD_PARAMETER);
        return EGL_NO_SURFACE;
    }
    if (width > MAX_PBUFFER || height > MAX_PBUFFER) {
        if (!largest) {
            fail(EGL_BAD_ALLOC);
            return EGL_NO_SURFACE;
        }
        width = width > MAX_PBUFFER ? MAX_PBUFFER : width;
        height = height > MAX_PBUFFER ? MAX_PBUFFER : height;
    }
    Surface *s = calloc(1, sizeof *s);
    if (!s) {
        fail(EGL_BAD_ALLOC);
        return EGL_NO_SURFACE;
    }
    s->config = c;
    s->width = width;
    s->height = height;
    s->largest = largest;
    pthread_mutex_lock(&lock);
    s->next = display.surfaces;
    display.surfaces = s;
    pthread_mutex_unlock(&lock);
    ok();
    return (EGLSurface)s;
}

EGLAPI EGLSurface EGLAPIENTRY eglCreateWindowSurface(EGLDisplay dpy, EGLConfig config, EGLNativeWindowType win,
                                                     const EGLint *attrib_list)
{
    (void)win;
    (void)attrib_list;
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    /* there is no window system, so no handle is a native window; the
    ** configs have no EGL_WINDOW_BIT either (EGL_BAD_MATCH), and EGL lets
    ** an implementation report either error: this one says why */
    if (d && check_config(config))
        fail(EGL_BAD_NATIVE_WINDOW);
    return EGL_NO_SURFACE;
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePixmapSurface(EGLDisplay dpy, EGLConfig config, EGLNativePixmapType pixmap,
                                                     const EGLint *attrib_list)
{
    (void)pixmap;
    (void)attrib_list;
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (d && check_config(config))
        fail(EGL_BAD_NATIVE_PIXMAP);
    return EGL_NO_SURFACE;
}

EGLAPI EGLSurface EGLAPIENTRY eglCreatePbufferFromClientBuffer(EGLDisplay dpy, EGLenum buftype, EGLClientBuffer buffer,
                                                               EGLConfig config, const EGLint *attrib_list)
{
    (void)buftype;
    (void)buffer;
    (void)config;
    (void)attrib_list;
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (d)
        fail(EGL_BAD_PARAMETER);       /* no client API has client buffers here */
    return EGL_NO_SURFACE;
}

EGLAPI EGLBoolean EGLAPIENTRY eglDestroySurface(EGLDisplay dpy, EGLSurface surface)
{
    pthread_mutex_lock(&lock);
    EGLBoolean r;
    Surface *s;
    if (!check_display(dpy))
        r = EGL_FALSE;
    else if (!(s = find_surface(surface)))
        r = fail(EGL_BAD_SURFACE);
    else {
        s->destroyed = 1;
        collect();
        r = ok();
    }
    pthread_mutex_unlock(&lock);
    return r;
}

EGLAPI EGLBoolean EGLAPIENTRY eglQuerySurface(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint *value)
{
    pthread_mutex_lock(&lock);
    Surface *s = check_surface(dpy, surface);
    EGLint v = 0;
    int known = 1;
    if (s) {
        switch (attribute) {
        case EGL_WIDTH: v = s->width; break;
        case EGL_HEIGHT: v = s->height; break;
        case EGL_CONFIG_ID: v = s->config->id; break;
        case EGL_LARGEST_PBUFFER: v = s->largest; break;
        case EGL_TEXTURE_FORMAT: v = EGL_NO_TEXTURE; break;
        case EGL_TEXTURE_TARGET: v = EGL_NO_TEXTURE; break;
        case EGL_MIPMAP_TEXTURE: v = EGL_FALSE; break;
        case EGL_MIPMAP_LEVEL: v = s->mipmap_level; break;
        case EGL_RENDER_BUFFER: v = EGL_BACK_BUFFER; break;
        case EGL_SWAP_BEHAVIOR: v = EGL_BUFFER_DESTROYED; break;
        case EGL_MULTISAMPLE_RESOLVE: v = EGL_MULTISAMPLE_RESOLVE_DEFAULT; break;
        case EGL_HORIZONTAL_RESOLUTION: case EGL_VERTICAL_RESOLUTION: case EGL_PIXEL_ASPECT_RATIO:
            v = EGL_UNKNOWN;
            break;
        case EGL_VG_ALPHA_FORMAT: v = EGL_VG_ALPHA_FORMAT_NONPRE; break;
        case EGL_VG_COLORSPACE: v = EGL_VG_COLORSPACE_sRGB; break;
        default: known = 0; break;
        }
    }
    pthread_mutex_unlock(&lock);
    if (!s)
        return EGL_FALSE;
    if (!known)
        return fail(EGL_BAD_ATTRIBUTE);
    if (!value)
        return fail(EGL_BAD_PARAMETER);
    *value = v;
    return ok();
}

EGLAPI EGLBoolean EGLAPIENTRY eglSurfaceAttrib(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint value)
{
    pthread_mutex_lock(&lock);
    Surface *s = check_surface(dpy, surface);
    EGLBoolean r;
    if (!s)
        r = EGL_FALSE;
    else if (attribute == EGL_MIPMAP_LEVEL) {
        s->mipmap_level = value;
        r = ok();
    } else if (attribute == EGL_SWAP_BEHAVIOR) {
        r = value == EGL_BUFFER_DESTROYED ? ok()
          : value == EGL_BUFFER_PRESERVED ? fail(EGL_BAD_MATCH)   /* no config has the PRESERVED bit */
          : fail(EGL_BAD_PARAMETER);
    } else if (attribute == EGL_MULTISAMPLE_RESOLVE) {
        r = value == EGL_MULTISAMPLE_RESOLVE_DEFAULT ? ok()
          : value == EGL_MULTISAMPLE_RESOLVE_BOX ? fail(EGL_BAD_MATCH)
          : fail(EGL_BAD_PARAMETER);
    } else {
        r = fail(EGL_BAD_ATTRIBUTE);
    }
    pthread_mutex_unlock(&lock);
    return r;
}

static EGLBoolean tex_image(EGLDisplay dpy, EGLSurface surface, EGLint buffer)
{
    pthread_mutex_lock(&lock);
    Surface *s = check_surface(dpy, surface);
    pthread_mutex_unlock(&lock);
    if (!s)
        return EGL_FALSE;
    if (buffer != EGL_BACK_BUFFER)
        return fail(EGL_BAD_PARAMETER);
    return fail(EGL_BAD_MATCH);        /* EGL_TEXTURE_FORMAT is EGL_NO_TEXTURE */
}

EGLAPI EGLBoolean EGLAPIENTRY eglBindTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer)
{
    return tex_image(dpy, surface, buffer);
}

EGLAPI EGLBoolean EGLAPIENTRY eglReleaseTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer)
{
    return tex_image(dpy, surface, buffer);
}

EGLAPI EGLBoolean EGLAPIENTRY eglSwapBuffers(EGLDisplay dpy, EGLSurface surface)
{
    pthread_mutex_lock(&lock);
    Surface *s = check_surface(dpy, surface);
    pthread_mutex_unlock(&lock);
    if (!s)
        return EGL_FALSE;
    /* a pbuffer has no front buffer: no effect beyond the implied flush */
    if (cur_context && cur_surface == s)
        gles_Flush(cur_context->core);
    return ok();
}

EGLAPI EGLBoolean EGLAPIENTRY eglCopyBuffers(EGLDisplay dpy, EGLSurface surface, EGLNativePixmapType target)
{
    (void)target;
    pthread_mutex_lock(&lock);
    Surface *s = check_surface(dpy, surface);
    pthread_mutex_unlock(&lock);
    if (!s)
        return EGL_FALSE;
    return fail(EGL_BAD_NATIVE_PIXMAP);
}

EGLAPI EGLBoolean EGLAPIENTRY eglSwapInterval(EGLDisplay dpy, EGLint interval)
{
    (void)interval;
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    pthread_mutex_unlock(&lock);
    if (!d)
        return EGL_FALSE;
    if (!cur_context)
        return fail(EGL_BAD_CONTEXT);
    if (!cur_surface)
        return fail(EGL_BAD_SURFACE);
    return ok();
}

/* {====================================================================
** contexts */

EGLAPI EGLBoolean EGLAPIENTRY eglBindAPI(EGLenum api)
{
    if (api != EGL_OPENGL_ES_API)
        return fail(EGL_BAD_PARAMETER);   /* OpenGL and OpenVG are not supported */
    bound_api = api;
    return ok();
}

EGLAPI EGLenum EGLAPIENTRY eglQueryAPI(void)
{
    return bound_api;
}

EGLAPI EGLContext EGLAPIENTRY eglCreateContext(EGLDisplay dpy, EGLConfig config, EGLContext share_context,
                                               const EGLint *attrib_list)
{
    pthread_mutex_lock(&lock);
    Display *d = check_display(dpy);
    Context *share = share_context == EGL_NO_CONTEXT ? NULL : find_context(share_context);
    pthread_mutex_unlock(&lock);
    if (!d)
        return EGL_NO_CONTEXT;
    if (bound_api != EGL_OPENGL_ES_API) {
        fail(EGL_BAD_MATCH);
        return EGL_NO_CONTEXT;
    }
    const Config *c = check_config(config);
    if (!c)
        return EGL_NO_CONTEXT;
    if (share_context != EGL_NO_CONTEXT && !share) {
        fail(EGL_BAD_CONTEXT);
        return EGL_NO_CONTEXT;
    }
    if (share) {
        /* core contexts share no objects */
        fail(EGL_BAD_MATCH);
        return EGL_NO_CONTEXT;
    }
    EGLint version = 1, minor = 0, flags = 0;
    for (const EGLint *a = attrib_list; a && a[0] != EGL_NONE; a += 2) {
        /* EGL_KHR_create_context: EGL_CONTEXT_MAJOR_VERSION_KHR is
        ** EGL_CONTEXT_CLIENT_VERSION; of the flags an OpenGL ES context
        ** takes only the debug bit (the others are OpenGL's) */
        if (a[0] == EGL_CONTEXT_CLIENT_VERSION)
            version = a[1];
        else if (a[0] == EGL_CONTEXT_MINOR_VERSION_KHR)
            minor = a[1];
        else if (a[0] == EGL_CONTEXT_FLAGS_KHR)
            flags = a[1];
        else {
            fail(EGL_BAD_ATTRIBUTE);
            return EGL_NO_CONTEXT;
        }
    }
    if ((flags & ~EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR) || minor < 0 || (version == 1 && minor > 1)) {
        fail(EGL_BAD_ATTRIBUTE);       /* no OpenGL ES 1.2 exists; OpenGL-only flags */
        return EGL_NO_CONTEXT;
    }
    if (version == 2 || version == 3) {
        /* EGL: a config whose EGL_RENDERABLE_TYPE lacks the ES2 (ES3) bit
        ** cannot make that version's context; ours are OpenGL ES 1 only */
        fail(EGL_BAD_CONFIG);
        return EGL_NO_CONTEXT;
    }
    if (version != 1) {
        fail(EGL_BAD_ATTRIBUTE);       /* no OpenGL ES of that version exists */
        return EGL_NO_CONTEXT;
    }
    Context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        fail(EGL_BAD_ALLOC);
        return EGL_NO_CONTEXT;
    }
    ctx->config = c;
    ctx->debug = (flags & EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR) != 0;
    pthread_mutex_lock(&lock);
    ctx->next = display.contexts;
    display.contexts = ctx;
    pthread_mutex_unlock(&lock);
    ok();
    return (EGLContext)ctx;
}

EGLAPI EGLBoolean EGLAPIENTRY eglDestroyContext(EGLDisplay dpy, EGLContext context)
{
    pthread_mutex_lock(&lock);
    EGLBoolean r;
    Context *c;
    if (!check_display(dpy))
        r = EGL_FALSE;
    else if (!(c = find_context(context)))
        r = fail(EGL_BAD_CONTEXT);
    else {
        c->destroyed = 1;
        collect();
        r = ok();
    }
    pthread_mutex_unlock(&lock);
    return r;
}

EGLAPI EGLBoolean EGLAPIENTRY eglQueryContext(EGLDisplay dpy, EGLContext context, EGLint attribute, EGLint *value)
{
    pthread_mutex_lock(&lock);
    Context *c = check_context(dpy, context);
    EGLint v = 0;
    int known = 1;
    if (c) {
        switch (attribute) {
        case EGL_CONFIG_ID: v = c->config->id; break;
        case EGL_CONTEXT_CLIENT_TYPE: v = EGL_OPENGL_ES_API; break;
        case EGL_CONTEXT_CLIENT_VERSION: v = 1; break;
        case EGL_RENDER_BUFFER: v = c->surface ? EGL_BACK_BUFFER : EGL_NONE; break;
        default: known = 0; break;
        }
    }
    pthread_mutex_unlock(&lock);
    if (!c)
        return EGL_FALSE;
    if (!known)
        return fail(EGL_BAD_ATTRIBUTE);
    if (!value)
        return fail(EGL_BAD_PARAMETER);
    *value = v;
    return ok();
}

/* bind ctx to s (under the lock): the core context is created at the first
** bind, with s's size and formats; the pixels move between a core and the
** surfaces it is bound to in turn */
static EGLint bind(Context *ctx, Surface *s)
{
    if (ctx->config != s->config)
        return EGL_BAD_MATCH;
    if (ctx->surface == s)
        return EGL_SUCCESS;
    /* the core's framebuffer is at least 1x1; a 0x0 pbuffer draws nowhere visible */
    int w = s->width ? s->width : 1, h = s->height ? s->height : 1;
    if (ctx->core && (gles_width(ctx->core) != w || gles_height(ctx->core) != h))
        return EGL_BAD_MATCH;          /* a core's framebuffer keeps the size of its first surface */
    if (!ctx->core) {
        ctx->core = gles_context_create(w, h, s->config->color_format, s->config->depth, s->config->stencil,
                                        GLES_CABI_COMMON ? GLES_PROFILE_COMMON : GLES_PROFILE_COMMON_LITE);
        if (!ctx->core)
            return EGL_BAD_ALLOC;
        gles_debug_context_set(ctx->core, ctx->debug);
        /* GLES_THREADS=N: draws rasterize on N threads (one when unset) */
        const char *threads = getenv("GLES_THREADS");
        if (threads && *threads) {
            const long n = strtol(threads, NULL, 10);
            gles_threads_set(ctx->core, n < 1 ? 1 : (n > GLES_MAX_THREADS ? GLES_MAX_THREADS : (int)n));
        }
    }
    /* s's pixels are in its previous context's core (not current anywhere,
    ** or current here and being replaced): take them back first */
    if (s->owner && !detach(s->owner))
        return EGL_BAD_ALLOC;
    if (ctx->surface && !detach(ctx))
        return EGL_BAD_ALLOC;
    attach(ctx, s);
    return EGL_SUCCESS;
}

EGLAPI EGLBoolean EGLAPIENTRY eglMakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read, EGLContext context)
{
    int release = context == EGL_NO_CONTEXT && draw == EGL_NO_SURFACE && read == EGL_NO_SURFACE;
    if (dpy == EGL_NO_DISPLAY && release) {
        /* EGL 1.5: releasing needs no display */
        pthread_mutex_lock(&lock);
        release_current();
        pthread_mutex_unlock(&lock);
        return ok();
    }
    if (dpy != (EGLDisplay)&display)
        return fail(EGL_BAD_DISPLAY);
    pthread_mutex_lock(&lock);
    EGLint err = EGL_SUCCESS;
    Context *c = NULL;
    Surface *s = NULL;
    if (release) {
        release_current();
    } else if (!display.initialized) {
        err = EGL_NOT_INITIALIZED;
    } else if (context == EGL_NO_CONTEXT) {
        err = EGL_BAD_MATCH;           /* surfaces without a context */
    } else if (!(c = find_context(context))) {
        err = EGL_BAD_CONTEXT;
    } else if (draw == EGL_NO_SURFACE || read == EGL_NO_SURFACE) {
        err = EGL_BAD_MATCH;           /* no EGL_KHR_surfaceless_context */
    } else if (!(s = find_surface(draw)) || !find_surface(read)) {
        err = EGL_BAD_SURFACE;
    } else if (draw != read) {
        err = EGL_BAD_MATCH;           /* one framebuffer per context: draw and read are one surface */
    } else if ((c->current && c != cur_context) || (s->current && s != cur_surface)) {
        err = EGL_BAD_ACCESS;          /* current in another thread */
    } else if ((err = bind(c, s)) == EGL_SUCCESS) {
        if (cur_context)
            cur_context->current = 0;
        if (cur_surface)
            cur_surface->current = 0;
        c->current = 1;
        s->current = 1;
        cur_context = c;
        cur_surface = s;
        gles_cabi_set_current(c->core);
        collect();
    }
    pthread_mutex_unlock(&lock);
    return err == EGL_SUCCESS ? ok() : fail(err);
}

EGLAPI EGLContext EGLAPIENTRY eglGetCurrentContext(void)
{
    return cur_context ? (EGLContext)cur_context : EGL_NO_CONTEXT;
}

EGLAPI EGLSurface EGLAPIENTRY eglGetCurrentSurface(EGLint readdraw)
{
    if (readdraw != EGL_DRAW && readdraw != EGL_READ) {
        fail(EGL_BAD_PARAMETER);
        return EGL_NO_SURFACE;
    }
    ok();
    return cur_surface ? (EGLSurface)cur_surface : EGL_NO_SURFACE;
}

EGLAPI EGLDisplay EGLAPIENTRY eglGetCurrentDisplay(void)
{
    return cur_context ? (EGLDisplay)&display : EGL_NO_DISPLAY;
}

EGLAPI EGLBoolean EGLAPIENTRY eglReleaseThread(void)
{
    pthread_mutex_lock(&lock);
    release_current();
    pthread_mutex_unlock(&lock);
    bound_api = EGL_OPENGL_ES_API;
    return ok();
}

EGLAPI EGLBoolean EGLAPIENTRY eglWaitClient(void)
{
    if (cur_context)
        gles_Finish(cur_context->core);
    return ok();
}

EGLAPI EGLBoolean EGLAPIENTRY eglWaitGL(void)
{
    return eglWaitClient();
}

EGLAPI EGLBoolean EGLAPIENTRY eglWaitNative(EGLint engine)
{
    if (engine != EGL_CORE_NATIVE_ENGINE)
        return fail(EGL_BAD_PARAMETER);
    return ok();
}

/* {====================================================================
** eglGetProcAddress: our EGL functions by name, and the GL ones of the
** libGLESv1_CM.so.1 beside this library (opened by its path, never by
** soname, which could name another implementation's library) */

static const GlesProc egl_procs[] = {
    {"eglBindAPI", (GlesProcFn)eglBindAPI},
    {"eglBindTexImage", (GlesProcFn)eglBindTexImage},
    {"eglChooseConfig", (GlesProcFn)eglChooseConfig},
    {"eglCopyBuffers", (GlesProcFn)eglCopyBuffers},
    {"eglCreateContext", (GlesProcFn)eglCreateContext},
    {"eglCreatePbufferFromClientBuffer", (GlesProcFn)eglCreatePbufferFromClientBuffer},
    {"eglCreatePbufferSurface", (GlesProcFn)eglCreatePbufferSurface},
    {"eglCreatePixmapSurface", (GlesProcFn)eglCreatePixmapSurface},
    {"eglCreateWindowSurface", (GlesProcFn)eglCreateWindowSurface},
    {"eglDestroyContext", (GlesProcFn)eglDestroyContext},
    {"eglDestroySurface", (GlesProcFn)eglDestroySurface},
    {"eglGetConfigAttrib", (GlesProcFn)eglGetConfigAttrib},
    {"eglGetConfigs", (GlesProcFn)eglGetConfigs},
    {"eglGetCurrentContext", (GlesProcFn)eglGetCurrentContext},
    {"eglGetCurrentDisplay", (GlesProcFn)eglGetCurrentDisplay},
    {"eglGetCurrentSurface", (GlesProcFn)eglGetCurrentSurface},
    {"eglGetDisplay", (GlesProcFn)eglGetDisplay},
    {"eglGetError", (GlesProcFn)eglGetError},
    {"eglGetPlatformDisplay", (GlesProcFn)eglGetPlatformDisplay},
    {"eglGetPlatformDisplayEXT", (GlesProcFn)eglGetPlatformDisplayEXT},
    {"eglGetProcAddress", (GlesProcFn)eglGetProcAddress},
    {"eglInitialize", (GlesProcFn)eglInitialize},
    {"eglMakeCurrent", (GlesProcFn)eglMakeCurrent},
    {"eglQueryAPI", (GlesProcFn)eglQueryAPI},
    {"eglQueryContext", (GlesProcFn)eglQueryContext},
    {"eglQueryString", (GlesProcFn)eglQueryString},
    {"eglQuerySurface", (GlesProcFn)eglQuerySurface},
    {"eglReleaseTexImage", (GlesProcFn)eglReleaseTexImage},
    {"eglReleaseThread", (GlesProcFn)eglReleaseThread},
    {"eglSurfaceAttrib", (GlesProcFn)eglSurfaceAttrib},
    {"eglSwapBuffers", (GlesProcFn)eglSwapBuffers},
    {"eglSwapInterval", (GlesProcFn)eglSwapInterval},
    {"eglTerminate", (GlesProcFn)eglTerminate},
    {"eglWaitClient", (GlesProcFn)eglWaitClient},
    {"eglWaitGL", (GlesProcFn)eglWaitGL},
    {"eglWaitNative", (GlesProcFn)eglWaitNative},
};

static GlesProcFn (*gl_proc)(const char *);
static pthread_once_t gl_once = PTHREAD_ONCE_INIT;

static void open_gl(void)
{
    Dl_info info;
    if (!dladdr((void *)(uintptr_t)eglGetProcAddress, &info) || !info.dli_fname)
        return;
    const char *slash = strrchr(info.dli_fname, '/');
    size_t dir = slash ? (size_t)(slash - info.dli_fname + 1) : 0;
    static const char lib[] = "libGLESv1_CM.so.1";
    char *path = malloc(dir + sizeof lib);
    if (!path)
        return;
    memcpy(path, info.dli_fname, dir);
    memcpy(path + dir, lib, sizeof lib);
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    free(path);
    if (!handle)
        return;
    /* the handle stays open for the life of the process */
    void *sym = dlsym(handle, "gles_cabi_gl_proc");
    if (sym)
        memcpy(&gl_proc, &sym, sizeof gl_proc);
}

EGLAPI __eglMustCastToProperFunctionPointerType EGLAPIENTRY eglGetProcAddress(const char *procname)
{
    if (!procname)
        return NULL;
    if (strncmp(procname, "egl", 3) == 0) {
        for (size_t i = 0; i < sizeof egl_procs / sizeof egl_procs[0]; i++)
            if (strcmp(procname, egl_procs[i].name) == 0)
                return (__eglMustCastToProperFunctionPointerType)egl_procs[i].fn;
        return NULL;
    }
    if (strncmp(procname, "gl", 2) != 0)
        return NULL;
    pthread_once(&gl_once, open_gl);
    return gl_proc ? (__eglMustCastToProperFunctionPointerType)gl_proc(procname) : NULL;
}
