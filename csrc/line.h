/*
** line.h -- line rasterization (ES 1.1 §3.4).
*/
#ifndef GLES_LINE_H
#define GLES_LINE_H

#include "state.h"

/* rasterize the segment a-b; `pv` is the provoking vertex (flat shading) */
void raster_line(GlesContext *ctx, const Vertex *a, const Vertex *b, const Vertex *pv);

#endif
