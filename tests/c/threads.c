/* threads.c -- the current context is per thread: two threads render at the
** same time, each into its own pbuffer with its own context, and a context
** current in one thread cannot be made current in another (EGL_BAD_ACCESS).
** Prints one line per failed check; exit 1 if any failed. */
#define _POSIX_C_SOURCE 200809L   /* pthread barriers */
#include <EGL/egl.h>
#include <GLES/gl.h>
#include <pthread.h>
#include <stdio.h>

#define SIZE 32
#define FRAMES 20

static EGLDisplay dpy;
static EGLConfig config;
static pthread_barrier_t barrier;
static EGLContext contexts[2];
static int failures[2];

static void *worker(void *arg)
{
    int id = (int)(size_t)arg;
    const EGLint size[] = {EGL_WIDTH, SIZE, EGL_HEIGHT, SIZE, EGL_NONE};
    EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
    contexts[id] = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (!eglMakeCurrent(dpy, surface, surface, contexts[id])) {
        printf("FAIL thread %d: eglMakeCurrent 0x%04x\n", id, (unsigned)eglGetError());
        failures[id]++;
    }
    pthread_barrier_wait(&barrier);   /* both current: the main thread tries to steal one */
    pthread_barrier_wait(&barrier);
    /* each frame clears to this thread's colour and draws a triangle of the other's */
    static const GLfixed tri[] = {-65536, -65536, 65536, -65536, 0, 65536};
    GLfixed mine = id ? 0 : 65536, other = id ? 65536 : 0;
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FIXED, 0, tri);
    for (int f = 0; f < FRAMES; f++) {
        glClearColorx(mine, 0, other, 65536);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor4x(other, 65536, mine, 65536);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        GLubyte corner[4], centre[4];
        glReadPixels(0, SIZE - 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, corner);
        glReadPixels(SIZE / 2, SIZE / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, centre);
        int want_r = id ? 0 : 255, want_b = id ? 255 : 0;
        if (corner[0] != want_r || corner[1] != 0 || corner[2] != want_b
            || centre[0] != want_b || centre[1] != 255 || centre[2] != want_r) {
            printf("FAIL thread %d frame %d: corner %d,%d,%d centre %d,%d,%d\n", id, f, corner[0], corner[1],
                   corner[2], centre[0], centre[1], centre[2]);
            failures[id]++;
            break;
        }
    }
    if (glGetError() != GL_NO_ERROR)
        failures[id]++;
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, contexts[id]);
    eglDestroySurface(dpy, surface);
    return NULL;
}

int main(void)
{
    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_NONE};
    EGLint n;
    if (!eglInitialize(dpy, NULL, NULL) || !eglChooseConfig(dpy, want, &config, 1, &n) || n != 1) {
        printf("FAIL no config\n");
        return 1;
    }
    pthread_barrier_init(&barrier, NULL, 3);
    pthread_t threads[2];
    for (int i = 0; i < 2; i++)
        pthread_create(&threads[i], NULL, worker, (void *)(size_t)i);
    pthread_barrier_wait(&barrier);
    int bad = 0;
    const EGLint size[] = {EGL_WIDTH, SIZE, EGL_HEIGHT, SIZE, EGL_NONE};
    EGLSurface mine = eglCreatePbufferSurface(dpy, config, size);
    if (eglMakeCurrent(dpy, mine, mine, contexts[0]) || eglGetError() != EGL_BAD_ACCESS) {
        printf("FAIL a context current in another thread: expected EGL_BAD_ACCESS\n");
        bad++;
    }
    if (eglGetCurrentContext() != EGL_NO_CONTEXT) {
        printf("FAIL the main thread has a current context\n");
        bad++;
    }
    pthread_barrier_wait(&barrier);
    for (int i = 0; i < 2; i++)
        pthread_join(threads[i], NULL);
    eglDestroySurface(dpy, mine);
    eglTerminate(dpy);
    bad += failures[0] + failures[1];
    printf(bad ? "%d checks failed\n" : "all checks passed\n", bad);
    return bad ? 1 : 0;
}
