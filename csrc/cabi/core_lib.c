/*
** core_lib.c -- the translation unit of the core shared library of one
** numeric build (libgles_fixed.so, libgles_float.so, libgles_double.so).
** The cffi module of that build and the C ABI's libGLESv1_CM and libEGL all
** link this one library, so Python and C programs run the same compiled core.
** The library is built with -fvisibility=hidden: only the declarations of
** gles_core.h and cabi.h, made under the pragma below, are exported.
*/
#pragma GCC visibility push(default)
#include "gles_core.h"
#include "cabi/cabi.h"
#pragma GCC visibility pop

#include "core_all.c"

static _Thread_local GlesContext *cabi_current;

GlesContext *gles_cabi_current(void) { return cabi_current; }

void gles_cabi_set_current(GlesContext *ctx) { cabi_current = ctx; }
