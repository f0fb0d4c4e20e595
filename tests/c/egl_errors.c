/* egl_errors.c -- a walk through EGL's error cases, each checked against
** the error the EGL 1.4 specification gives for it; then one frame drawn
** to show the objects that survived work. Prints one line per failed check
** and exits 1 if any failed. */
#include <EGL/egl.h>
#include <GLES/gl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define W 16
#define H 16
#define FX(v) ((GLfixed)((v) * 65536.0))

static int failures;

#define EXPECT(cond, what) \
    do { \
        if (!(cond)) { \
            printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, what); \
            failures++; \
        } \
    } while (0)

/* the call returned `bad` and recorded `err` */
#define EXPECT_ERROR(call, bad, err) \
    do { \
        int ok_ = (call) == (bad); \
        EGLint got_ = eglGetError(); \
        if (!ok_ || got_ != (err)) { \
            printf("FAIL %s:%d: %s: error 0x%04x, expected 0x%04x\n", __FILE__, __LINE__, #call, \
                   (unsigned)got_, (unsigned)(err)); \
            failures++; \
        } \
    } while (0)

int main(void)
{
    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EXPECT(dpy != EGL_NO_DISPLAY, "eglGetDisplay(EGL_DEFAULT_DISPLAY)");
    EXPECT(eglGetError() == EGL_SUCCESS, "a new thread's error is EGL_SUCCESS");
    /* before eglInitialize */
    EGLint n = -1;
    EXPECT_ERROR(eglGetConfigs(dpy, NULL, 0, &n), EGL_FALSE, EGL_NOT_INITIALIZED);
    EXPECT_ERROR(eglQueryString(dpy, EGL_VENDOR), NULL, EGL_NOT_INITIALIZED);
    EXPECT_ERROR(eglInitialize((EGLDisplay)(uintptr_t)0x1234, NULL, NULL), EGL_FALSE, EGL_BAD_DISPLAY);
    /* client extensions need no display */
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    EXPECT(client && strstr(client, "EGL_EXT_platform_base"), "client extensions");
    EXPECT_ERROR(eglQueryString(EGL_NO_DISPLAY, EGL_VENDOR), NULL, EGL_BAD_DISPLAY);

    EGLint major = 0, minor = 0;
    EXPECT(eglInitialize(dpy, &major, &minor) && major == 1 && minor >= 4, "eglInitialize gives 1.4");
    EXPECT(eglGetError() == EGL_SUCCESS, "eglGetError after a success");
    EXPECT_ERROR(eglQueryString(dpy, 0x1234), NULL, EGL_BAD_PARAMETER);
    EXPECT(strstr(eglQueryString(dpy, EGL_CLIENT_APIS), "OpenGL_ES") != NULL, "EGL_CLIENT_APIS");

    /* configs */
    EXPECT_ERROR(eglGetConfigs(dpy, NULL, 0, NULL), EGL_FALSE, EGL_BAD_PARAMETER);
    EXPECT(eglGetConfigs(dpy, NULL, 0, &n) && n == 24, "twenty-four configs");
    const EGLint bad_attr[] = {0x7777, 1, EGL_NONE};
    EGLConfig config;
    EXPECT_ERROR(eglChooseConfig(dpy, bad_attr, &config, 1, &n), EGL_FALSE, EGL_BAD_ATTRIBUTE);
    EXPECT_ERROR(eglChooseConfig(dpy, NULL, &config, 1, NULL), EGL_FALSE, EGL_BAD_PARAMETER);
    /* the default EGL_SURFACE_TYPE is EGL_WINDOW_BIT: no config has it */
    EXPECT(eglChooseConfig(dpy, NULL, NULL, 0, &n) && n == 0, "no window configs");
    const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 5, EGL_DEPTH_SIZE, 16,
                           EGL_STENCIL_SIZE, 8, EGL_NONE};
    EXPECT(eglChooseConfig(dpy, want, &config, 1, &n) && n == 1, "eglChooseConfig");
    EGLint v[4];
    eglGetConfigAttrib(dpy, config, EGL_RED_SIZE, &v[0]);
    eglGetConfigAttrib(dpy, config, EGL_ALPHA_SIZE, &v[1]);
    eglGetConfigAttrib(dpy, config, EGL_DEPTH_SIZE, &v[2]);
    eglGetConfigAttrib(dpy, config, EGL_STENCIL_SIZE, &v[3]);
    /* larger colour first (8888 before 565), then the smallest depth and stencil */
    EXPECT(v[0] == 8 && v[1] == 8 && v[2] == 16 && v[3] == 8, "config sort order");
    EXPECT_ERROR(eglGetConfigAttrib(dpy, (EGLConfig)(uintptr_t)0x10, EGL_RED_SIZE, &v[0]), EGL_FALSE, EGL_BAD_CONFIG);
    EXPECT_ERROR(eglGetConfigAttrib(dpy, config, 0x7777, &v[0]), EGL_FALSE, EGL_BAD_ATTRIBUTE);

    /* surfaces */
    EXPECT_ERROR(eglCreateWindowSurface(dpy, config, (EGLNativeWindowType)0, NULL), EGL_NO_SURFACE,
                 EGL_BAD_NATIVE_WINDOW);
    EXPECT_ERROR(eglCreatePixmapSurface(dpy, config, (EGLNativePixmapType)0, NULL), EGL_NO_SURFACE,
                 EGL_BAD_NATIVE_PIXMAP);
    const EGLint negative[] = {EGL_WIDTH, -1, EGL_HEIGHT, 8, EGL_NONE};
    EXPECT_ERROR(eglCreatePbufferSurface(dpy, config, negative), EGL_NO_SURFACE, EGL_BAD_PARAMETER);
    const EGLint unknown[] = {EGL_WIDTH, 8, 0x7777, 8, EGL_NONE};
    EXPECT_ERROR(eglCreatePbufferSurface(dpy, config, unknown), EGL_NO_SURFACE, EGL_BAD_ATTRIBUTE);
    const EGLint textured[] = {EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D, EGL_NONE};
    EXPECT_ERROR(eglCreatePbufferSurface(dpy, config, textured), EGL_NO_SURFACE, EGL_BAD_MATCH);
    EXPECT_ERROR(eglCreatePbufferSurface(dpy, (EGLConfig)(uintptr_t)0x10, NULL), EGL_NO_SURFACE, EGL_BAD_CONFIG);
    const EGLint size[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
    EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
    EXPECT(surface != EGL_NO_SURFACE, "eglCreatePbufferSurface");
    EXPECT(eglQuerySurface(dpy, surface, EGL_WIDTH, &v[0]) && v[0] == W, "EGL_WIDTH");
    EXPECT_ERROR(eglQuerySurface(dpy, surface, 0x7777, &v[0]), EGL_FALSE, EGL_BAD_ATTRIBUTE);
    EXPECT_ERROR(eglQuerySurface(dpy, (EGLSurface)(uintptr_t)0x10, EGL_WIDTH, &v[0]), EGL_FALSE, EGL_BAD_SURFACE);
    EXPECT_ERROR(eglBindTexImage(dpy, surface, EGL_BACK_BUFFER), EGL_FALSE, EGL_BAD_MATCH);
    EXPECT_ERROR(eglCopyBuffers(dpy, surface, (EGLNativePixmapType)0), EGL_FALSE, EGL_BAD_NATIVE_PIXMAP);

    /* contexts */
    EXPECT_ERROR(eglBindAPI(EGL_OPENVG_API), EGL_FALSE, EGL_BAD_PARAMETER);
    EXPECT(eglQueryAPI() == EGL_OPENGL_ES_API, "the bound API is still OpenGL ES");
    const EGLint es2[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
    /* an OpenGL ES 2 context from a config without EGL_OPENGL_ES2_BIT */
    EXPECT_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, es2), EGL_NO_CONTEXT, EGL_BAD_CONFIG);
    const EGLint es7[] = {EGL_CONTEXT_CLIENT_VERSION, 7, EGL_NONE};
    EXPECT_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, es7), EGL_NO_CONTEXT, EGL_BAD_ATTRIBUTE);
    const EGLint odd[] = {0x7777, 1, EGL_NONE};
    EXPECT_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, odd), EGL_NO_CONTEXT, EGL_BAD_ATTRIBUTE);
    EXPECT_ERROR(eglCreateContext(dpy, config, (EGLContext)(uintptr_t)0x10, NULL), EGL_NO_CONTEXT, EGL_BAD_CONTEXT);
    EXPECT_ERROR(eglCreateContext(dpy, (EGLConfig)(uintptr_t)0x10, EGL_NO_CONTEXT, NULL), EGL_NO_CONTEXT, EGL_BAD_CONFIG);
    const EGLint es1[] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, es1);
    EXPECT(ctx != EGL_NO_CONTEXT, "eglCreateContext");
    EXPECT(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_VERSION, &v[0]) && v[0] == 1, "client version 1");
    EXPECT_ERROR(eglQueryContext(dpy, ctx, 0x7777, &v[0]), EGL_FALSE, EGL_BAD_ATTRIBUTE);

    /* making current */
    EXPECT_ERROR(eglMakeCurrent(dpy, surface, surface, EGL_NO_CONTEXT), EGL_FALSE, EGL_BAD_MATCH);
    EXPECT_ERROR(eglMakeCurrent(dpy, surface, surface, (EGLContext)(uintptr_t)0x10), EGL_FALSE, EGL_BAD_CONTEXT);
    EXPECT_ERROR(eglMakeCurrent(dpy, (EGLSurface)(uintptr_t)0x10, surface, ctx), EGL_FALSE, EGL_BAD_SURFACE);
    EXPECT_ERROR(eglMakeCurrent((EGLDisplay)(uintptr_t)0x10, surface, surface, ctx), EGL_FALSE, EGL_BAD_DISPLAY);
    EXPECT_ERROR(eglSwapInterval(dpy, 1), EGL_FALSE, EGL_BAD_CONTEXT);
    EXPECT(eglGetCurrentContext() == EGL_NO_CONTEXT, "nothing current yet");
    EXPECT(eglMakeCurrent(dpy, surface, surface, ctx), "eglMakeCurrent");
    EXPECT(eglGetCurrentContext() == ctx && eglGetCurrentSurface(EGL_DRAW) == surface, "current");
    EXPECT(eglGetCurrentDisplay() == dpy, "current display");
    EXPECT_ERROR(eglGetCurrentSurface(0x7777), EGL_NO_SURFACE, EGL_BAD_PARAMETER);
    EXPECT(eglSwapInterval(dpy, 1), "eglSwapInterval");
    EXPECT_ERROR(eglWaitNative(0x7777), EGL_FALSE, EGL_BAD_PARAMETER);

    /* a frame: the GL works on the context EGL made current */
    glClearColorx(0, FX(1), 0, FX(1));
    glClear(GL_COLOR_BUFFER_BIT);
    GLubyte px[4] = {0, 0, 0, 0};
    glReadPixels(W / 2, H / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    EXPECT(px[0] == 0 && px[1] == 255 && px[2] == 0 && px[3] == 255, "a green clear");
    EXPECT(glGetError() == GL_NO_ERROR, "no GL error");
    EXPECT(eglSwapBuffers(dpy, surface), "eglSwapBuffers on a pbuffer");

    /* a surface keeps its pixels when its context moves to another surface,
    ** and when another context takes it over */
    EGLSurface other = eglCreatePbufferSurface(dpy, config, size);
    EXPECT(other != EGL_NO_SURFACE && eglMakeCurrent(dpy, other, other, ctx), "a second surface");
    glClearColorx(0, 0, FX(1), FX(1));
    glClear(GL_COLOR_BUFFER_BIT);
    EXPECT(eglMakeCurrent(dpy, surface, surface, ctx), "back to the first surface");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    EXPECT(px[1] == 255 && px[2] == 0, "the first surface is still green");
    EGLContext ctx2 = eglCreateContext(dpy, config, EGL_NO_CONTEXT, es1);
    EXPECT(ctx2 != EGL_NO_CONTEXT && eglMakeCurrent(dpy, other, other, ctx2), "a second context");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    EXPECT(px[1] == 0 && px[2] == 255, "the second surface is still blue in another context");
    EXPECT_ERROR(eglMakeCurrent(dpy, surface, other, ctx2), EGL_FALSE, EGL_BAD_MATCH);  /* draw != read */
    const EGLint small[] = {EGL_WIDTH, W / 2, EGL_HEIGHT, H / 2, EGL_NONE};
    EGLSurface smaller = eglCreatePbufferSurface(dpy, config, small);
    EXPECT_ERROR(eglMakeCurrent(dpy, smaller, smaller, ctx2), EGL_FALSE, EGL_BAD_MATCH);  /* core size */
    EXPECT(eglGetCurrentContext() == ctx2, "a failed eglMakeCurrent changes nothing");
    EXPECT(eglMakeCurrent(dpy, surface, surface, ctx), "the first context again");
    EXPECT(eglDestroyContext(dpy, ctx2) && eglDestroySurface(dpy, other) && eglDestroySurface(dpy, smaller),
           "destroying what is not current");

    /* a current surface and context destroyed stay usable until released */
    EXPECT(eglDestroySurface(dpy, surface), "eglDestroySurface (current)");
    EXPECT(eglDestroyContext(dpy, ctx), "eglDestroyContext (current)");
    EXPECT_ERROR(eglQuerySurface(dpy, surface, EGL_WIDTH, &v[0]), EGL_FALSE, EGL_BAD_SURFACE);
    EXPECT_ERROR(eglDestroyContext(dpy, ctx), EGL_FALSE, EGL_BAD_CONTEXT);
    glClear(GL_COLOR_BUFFER_BIT);
    EXPECT(glGetError() == GL_NO_ERROR, "the GL still works until released");
    EXPECT(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT), "release");
    EXPECT(eglGetCurrentContext() == EGL_NO_CONTEXT, "released");
    /* with no current context GL commands do nothing */
    EXPECT(glGetError() == GL_NO_ERROR && glGetString(GL_VERSION) == NULL, "no context, no GL");

    EXPECT(eglTerminate(dpy), "eglTerminate");
    EXPECT_ERROR(eglGetConfigs(dpy, NULL, 0, &n), EGL_FALSE, EGL_NOT_INITIALIZED);
    EXPECT(eglReleaseThread(), "eglReleaseThread");
    if (failures)
        printf("%d checks failed\n", failures);
    else
        printf("all checks passed\n");
    return failures ? 1 : 0;
}
