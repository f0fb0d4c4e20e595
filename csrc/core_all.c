/*
** core_all.c -- the whole core as one translation unit, compiled once per
** numeric build (the build defines GLES_NUM_FIXED, _FLOAT or _DOUBLE).
** One unit lets the compiler inline across stages, and lets the three
** builds share no object files.
*/
#include "context.c"
#include "matrix.c"
#include "array.c"
#include "light.c"
#include "vertex.c"
#include "vertex_batch.c"
#include "clip.c"
#include "raster.c"
#include "fragment.c"
#include "fog.c"
#include "texture.c"
#include "texsample.c"
#include "texcube.c"
#include "texgen.c"
#include "texenv.c"
#include "span.c"
#include "span_chain.c"
#include "point.c"
#include "line.c"
#include "drawtex.c"
#include "range.c"
#include "draw.c"
#include "framebuffer.c"
#include "fbo.c"
#include "debug.c"
#include "pool.c"
