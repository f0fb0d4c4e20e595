/* procs.h -- the name -> entry point table of libGLESv1_CM (gl.c) */
#ifndef GLES_CABI_PROCS_H
#define GLES_CABI_PROCS_H

typedef void (*GlesProcFn)(void);

typedef struct {
    const char *name;
    GlesProcFn fn;
} GlesProc;

#endif
