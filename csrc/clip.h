/*
** clip.h -- clipping of polygons and lines in homogeneous space.
*/
#ifndef GLES_CLIP_H
#define GLES_CLIP_H

#include "state.h"

/* the most vertices a clipped triangle can have: 3 + one per plane */
#define CLIP_MAX_VERTS (3 + 7 + GLES_MAX_CLIP_PLANES)

/* Clip the polygon in[0..n-1] against every plane in `codes` (the union of
** its vertices' clip codes). Output vertices go to out (capacity
** CLIP_MAX_VERTS), new ones are built in `scratch` (same capacity * 2).
** Returns the output count (0 when nothing is left). */
int clip_polygon(const GlesContext *ctx, const Vertex *const *in, int n, unsigned int codes,
                 const Vertex **out, Vertex *scratch);
/* Clip a segment; returns 0 when nothing is left, else fills *pa, *pb */
int clip_line(const GlesContext *ctx, const Vertex *a, const Vertex *b, unsigned int codes,
              const Vertex **pa, const Vertex **pb, Vertex *scratch);

#endif
