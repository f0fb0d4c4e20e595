/*
** fragment.h -- per-fragment operations (ES 1.1 §4.1) and fog (§3.8).
*/
#ifndef GLES_FRAGMENT_H
#define GLES_FRAGMENT_H

#include "state.h"

void fragment_init(GlesContext *ctx);
int fragment_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
int fragment_compare(unsigned int func, uint32_t a, uint32_t b);
int fragment_alpha_pass(const GlesContext *ctx, NUM alpha);
int fragment_stencil_pass(const GlesContext *ctx, uint8_t stored);
uint8_t fragment_stencil_op(const GlesContext *ctx, unsigned int op, uint8_t s);
/* blended colour (not yet clamped) from source and destination in BLENDV */
void fragment_blend(const GlesContext *ctx, const BLENDV src[4], const BLENDV dst[4], BLENDV out[4]);
uint32_t fragment_logic_op(unsigned int op, uint32_t s, uint32_t d);
BLENDV fragment_dither_threshold(int x, int y);

/* fog.c */
void fog_init(GlesContext *ctx);
int fog_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
void fog_validate(GlesContext *ctx);
/* the fog factor for eye distance c (clamped to [0,1]) */
NUM fog_factor(const GlesContext *ctx, NUM c);
/* per vertex: the factor, or the eye distance when fog is per fragment */
NUM fog_vertex_value(const GlesContext *ctx, const NUM eye[4]);

#endif
