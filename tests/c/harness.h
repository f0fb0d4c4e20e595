/*
** harness.h -- what the C test programs share: a W x H pbuffer context made
** through EGL on the surfaceless platform (which both gles and Mesa offer),
** and the pixels read back and written raw (RGBA, bottom row first) to the
** file named on the command line. Exit status: 0 done, 2 EGL failed, 3 the
** GL recorded an error.
*/
#ifndef TEST_HARNESS_H
#define TEST_HARNESS_H

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <stdio.h>
#include <stdlib.h>

#define W 64
#define H 64

/* a 16.16 constant */
#define FX(v) ((GLfixed)((v) * 65536.0))

static EGLDisplay harness_dpy;
static EGLSurface harness_surface;
static EGLContext harness_ctx;

static void harness_die(const char *what)
{
    fprintf(stderr, "%s failed: EGL error 0x%04x\n", what, (unsigned)eglGetError());
    exit(2);
}

/* a context on an RGBA8888 pbuffer with exactly these depth and stencil sizes
** where the implementation has them (else the first larger one), created
** with these EGL_CONTEXT_FLAGS_KHR (EGL_KHR_create_context) when not 0 */
static void harness_begin_flags(EGLint depth, EGLint stencil, EGLint flags)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_display)
        harness_die("eglGetProcAddress(eglGetPlatformDisplayEXT)");
    harness_dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (harness_dpy == EGL_NO_DISPLAY || !eglInitialize(harness_dpy, NULL, NULL))
        harness_die("eglInitialize");
    const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT,
                           EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                           EGL_DEPTH_SIZE, depth, EGL_STENCIL_SIZE, stencil, EGL_NONE};
    EGLConfig configs[256];
    EGLint n = 0;
    if (!eglChooseConfig(harness_dpy, want, configs, 256, &n) || n < 1)
        harness_die("eglChooseConfig");
    EGLConfig config = NULL;
    int best = 1 << 30;
    for (EGLint i = 0; i < n; i++) {
        EGLint r, g, b, a, d, s, samples;
        eglGetConfigAttrib(harness_dpy, configs[i], EGL_RED_SIZE, &r);
        eglGetConfigAttrib(harness_dpy, configs[i], EGL_GREEN_SIZE, &g);
        eglGetConfigAttrib(harness_dpy, configs[i], EGL_BLUE_SIZE, &b);
        eglGetConfigAttrib(harness_dpy, configs[i], EGL_ALPHA_SIZE, &a);
        eglGetConfigAttrib(harness_dpy, configs[i], EGL_DEPTH_SIZE, &d);
        eglGetConfigAttrib(harness_dpy, configs[i], EGL_STENCIL_SIZE, &s);
        eglGetConfigAttrib(harness_dpy, configs[i], EGL_SAMPLES, &samples);
        if (r != 8 || g != 8 || b != 8 || a != 8 || samples != 0)
            continue;
        int cost = (d - depth) * 64 + (s - stencil);
        if (cost < best) {
            best = cost;
            config = configs[i];
        }
    }
    if (!config)
        harness_die("finding an RGBA8888 config");
    const EGLint size[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
    harness_surface = eglCreatePbufferSurface(harness_dpy, config, size);
    if (harness_surface == EGL_NO_SURFACE)
        harness_die("eglCreatePbufferSurface");
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        harness_die("eglBindAPI");
    const EGLint version[] = {EGL_CONTEXT_CLIENT_VERSION, 1, flags ? EGL_CONTEXT_FLAGS_KHR : EGL_NONE, flags,
                              EGL_NONE};
    harness_ctx = eglCreateContext(harness_dpy, config, EGL_NO_CONTEXT, version);
    if (harness_ctx == EGL_NO_CONTEXT)
        harness_die("eglCreateContext");
    if (!eglMakeCurrent(harness_dpy, harness_surface, harness_surface, harness_ctx))
        harness_die("eglMakeCurrent");
}

static inline void harness_begin(EGLint depth, EGLint stencil)
{
    harness_begin_flags(depth, stencil, 0);
}

/* read the pixels back into argv[1], then tear everything down */
static int harness_end(int argc, char **argv)
{
    static GLubyte pixels[W * H * 4];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    GLenum err = glGetError();
    if (err != GL_NO_ERROR) {
        fprintf(stderr, "GL error 0x%04x\n", (unsigned)err);
        return 3;
    }
    if (argc > 1) {
        FILE *f = fopen(argv[1], "wb");
        if (!f || fwrite(pixels, 1, sizeof pixels, f) != sizeof pixels || fclose(f) != 0) {
            perror(argv[1]);
            return 1;
        }
    }
    if (!eglSwapBuffers(harness_dpy, harness_surface))
        harness_die("eglSwapBuffers");
    if (!eglMakeCurrent(harness_dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT))
        harness_die("eglMakeCurrent(release)");
    if (!eglDestroyContext(harness_dpy, harness_ctx) || !eglDestroySurface(harness_dpy, harness_surface))
        harness_die("eglDestroy*");
    if (!eglTerminate(harness_dpy))
        harness_die("eglTerminate");
    return 0;
}

#endif
