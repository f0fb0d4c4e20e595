/*
** vertex.h -- per-vertex work: transform, clip codes, window coordinates,
** and the attributes a surviving primitive needs.
*/
#ifndef GLES_VERTEX_H
#define GLES_VERTEX_H

#include "state.h"

/* clip-code bits: six frustum planes, the w > 0 guard, then user planes */
#define CLIP_LEFT 1u
#define CLIP_RIGHT 2u
#define CLIP_BOTTOM 4u
#define CLIP_TOP 8u
#define CLIP_NEAR 16u
#define CLIP_FAR 32u
#define CLIP_W 64u
#define CLIP_USER0 128u
/* not a plane: set on vertices made by clipping, which need window
** coordinates once clipping is done */
#define CLIP_NEW_VERTEX 0x80000000u

/* derived state for transformation (composite matrix, clip mask) */
void vertex_validate(GlesContext *ctx);
/* position of array element `index` through to clip code and, when inside,
** window coordinates */
void vertex_position(GlesContext *ctx, int64_t index, Vertex *v);
/* colour (and later lighting, texture coordinates) of element `index` */
void vertex_attribs(GlesContext *ctx, int64_t index, Vertex *v);
/* window coordinates from clip coordinates (w > 0) */
void vertex_window(const GlesContext *ctx, Vertex *v);
/* signed distance of v to the plane of clip bit `bit` (inside >= 0) */
NUM vertex_plane_distance(const GlesContext *ctx, const Vertex *v, unsigned int bit);
/* the clip code of a vertex from its clip (and eye) coordinates */
unsigned int vertex_clipcode(const GlesContext *ctx, const Vertex *v);

/* OES_matrix_palette: the eye position sum_i w_i M[idx_i] obj of element
** `index`, and its eye-space normal sum_i w_i n Inv(Mu_i) */
void vertex_palette_eye(const GlesContext *ctx, int64_t index, const NUM obj[4], NUM eye[4]);
void vertex_palette_normal(const GlesContext *ctx, int64_t index, const NUM n[3], NUM out[3]);
/* the eye-space normal lighting and texgen read (normal matrix or palette,
** RESCALE_NORMAL, NORMALIZE) */
void vertex_eye_normal(const GlesContext *ctx, int64_t index, NUM n[3]);

#endif
