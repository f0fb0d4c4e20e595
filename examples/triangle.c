/* triangle.c -- an OpenGL ES 1.1 program against gles's libGLESv1_CM + libEGL:
**   cc triangle.c -L"$(python -m gles libdir)" -lGLESv1_CM -lEGL -o triangle
**   LD_LIBRARY_PATH="$(python -m gles libdir)" ./triangle   # writes triangle.ppm */
#include <EGL/egl.h>
#include <GLES/gl.h>
#include <stdio.h>

int main(void)
{
    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT,
                           EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE};
    const EGLint size[] = {EGL_WIDTH, 128, EGL_HEIGHT, 128, EGL_NONE};
    EGLConfig config;
    EGLint n;
    if (!eglInitialize(dpy, NULL, NULL) || !eglChooseConfig(dpy, want, &config, 1, &n) || n != 1)
        return 1;
    EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (!eglMakeCurrent(dpy, surface, surface, ctx))
        return 1;
    static const GLfixed xy[] = {-52428, -45875, 52428, -26214, 0, 55705};   /* 16.16 */
    static const GLubyte rgba[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
    glClearColorx(0, 0, 16384, 65536);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FIXED, 0, xy);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, rgba);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    static GLubyte px[128 * 128 * 4];
    glReadPixels(0, 0, 128, 128, GL_RGBA, GL_UNSIGNED_BYTE, px);
    FILE *f = fopen("triangle.ppm", "wb");
    if (!f || glGetError() != GL_NO_ERROR)
        return 1;
    fprintf(f, "P6 128 128 255\n");
    for (int y = 127; y >= 0; y--)          /* GL's rows are bottom first */
        for (int x = 0; x < 128; x++)
            fwrite(&px[(y * 128 + x) * 4], 1, 3, f);
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
    return fclose(f) != 0;
}
