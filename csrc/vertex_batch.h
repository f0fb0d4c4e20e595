/*
** vertex_batch.h -- the vertex stage for a batch of vertices at a time.
*/
#ifndef GLES_VERTEX_BATCH_H
#define GLES_VERTEX_BATCH_H

#include "state.h"

#define VERTEX_BATCH NUM_BATCH  /* the most vertices one call takes */

/* positions of array elements index[0..n) (n <= VERTEX_BATCH) into
** verts[index[i] - base]: what vertex_position computes, bit for bit */
void vertex_batch_positions(GlesContext *ctx, const int64_t *index, int n, Vertex *verts, int64_t base);
/* attributes of elements index[0..n) into out[i], whose positions are
** done: what vertex_attribs computes, bit for bit */
void vertex_batch_attribs(GlesContext *ctx, const int64_t *index, Vertex *const *out, int n);

#endif
