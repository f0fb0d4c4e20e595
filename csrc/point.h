/*
** point.h -- point rasterization (ES 1.1 §3.3).
*/
#ifndef GLES_POINT_H
#define GLES_POINT_H

#include "state.h"

/* the point's size after the size array, attenuation and clamping */
NUM point_derived_size(const GlesContext *ctx, const Vertex *v);
void raster_point(GlesContext *ctx, const Vertex *v);

#endif
