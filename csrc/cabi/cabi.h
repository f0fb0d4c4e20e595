/*
** cabi.h -- what the C ABI's libraries (libGLESv1_CM, libEGL: csrc/cabi/)
** need from the core library besides gles_core.h: the calling thread's
** current context. libEGL sets it in eglMakeCurrent, every GL entry point of
** libGLESv1_CM reads it. It lives in the core library because both of them
** link that one library (and neither may depend on the other's soname, which
** a system EGL or GLES library of the same name would satisfy instead).
*/
#ifndef GLES_CABI_H
#define GLES_CABI_H

#include "gles_core.h"

GlesContext *gles_cabi_current(void);
void gles_cabi_set_current(GlesContext *ctx);

#endif
