/*
** light.h -- lighting (ES 1.1 §2.12).
*/
#ifndef GLES_LIGHT_H
#define GLES_LIGHT_H

#include "state.h"

void light_init(GlesContext *ctx);
/* derived lighting state: normal matrix, rescale factor, active lights */
void light_validate(GlesContext *ctx);
/* COLOR_MATERIAL: copy the current colour into ambient and diffuse */
void light_track_color(GlesContext *ctx);
/* lit colours of a vertex at eye position `eye` with the eye-space normal
** n (vertex_eye_normal); `back` may be NULL */
void light_vertex(const GlesContext *ctx, const NUM eye[4], const NUM n[3], const NUM color[4], NUM front[4],
                  NUM back[4]);

/* {====================================================================
** the lighting equation for a batch of vertices, in structure-of-arrays
** form: the same operations in the same order as light_vertex, with what
** does not depend on the vertex prepared once (LightPrep) */
#define LIGHT_BATCH NUM_BATCH   /* vertices per batch */
#define LIGHT_LANES NUM_LANES   /* lanes are padded to whole groups of this many */

typedef struct LightBatch {
    int n;                          /* vertices; lanes up to the next multiple
                                    ** of LIGHT_LANES hold defined padding */
    NUM nrm[3][LIGHT_BATCH];        /* eye-space normal, as light_side gets it */
    NUM v[3][LIGHT_BATCH];          /* eye position divided by w */
    NUM col[4][LIGHT_BATCH];        /* vertex colour (read with COLOR_MATERIAL) */
    NUM out[2][4][LIGHT_BATCH];     /* front and back colour */
} LightBatch;

/* front (and, when `two_sided`, back) colours of b->n vertices */
void light_batch(const GlesContext *ctx, LightBatch *b, int two_sided);
/* gles_debug_vertex_lanes' kernel 3 (one directional light's term, through
** the AVX2 kernels or the scalar loop) */
int light_debug_directional(int simd, int n, const int32_t *m, const int32_t *in, int32_t *out);
/* kernel 6 (every build): one positional light's term (m: the light, in:
** positions, normals, colours and accumulators of n lanes, m[31] of them
** vertices; numbers 16.16, or float bit patterns in the float builds; out:
** three rows of 64 NUMs) */
int light_debug_positional(int simd, int n, const int32_t *m, const int32_t *in, int32_t *out);

#endif
