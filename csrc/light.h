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
/* lit colours of a vertex; `normal` is in object space, or already in eye
** space when `eye_normal` (matrix palette); `back` may be NULL */
void light_vertex(const GlesContext *ctx, const NUM eye[4], const NUM normal[3], int eye_normal,
                  const NUM color[4], NUM front[4], NUM back[4]);

#endif
