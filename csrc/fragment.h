/*
** fragment.h -- per-fragment operations (ES 1.1 §4.1) and fog (§3.8).
*/
#ifndef GLES_FRAGMENT_H
#define GLES_FRAGMENT_H

#include "state.h"
#include "texture.h"

void fragment_init(GlesContext *ctx);

/* the inputs of one fragment (fragment_process) */
typedef struct FragIn {
    FRAGV c[4];                             /* primary colour */
    TexCoord tc[GLES_MAX_TEXTURE_UNITS];    /* per enabled unit */
    TexCoord tdx[GLES_MAX_TEXTURE_UNITS];   /* the right and upper neighbours', */
    TexCoord tdy[GLES_MAX_TEXTURE_UNITS];   /* read when the filter needs LOD */
    FRAGV fog;                              /* fog factor f */
    FRAGV coverage;                         /* antialiasing coverage, FRAG_ONE if none */
    uint32_t z;                             /* window depth (with the depth test on) */
} FragIn;

/* texturing, fog, coverage and the per-fragment operations for one fragment */
void fragment_process(GlesContext *ctx, int x, int y, const FragIn *in);


/* A colour channel into a framebuffer channel of `bits` bits (§2.12.8,
** §4.1.8). 8 bits round to nearest. Fewer bits without dithering keep the
** high bits of an exact ubyte colour (floor(v * 2^bits)), as the spec
** requires for unlit, unclipped ubyte input; with dithering, the ordered
** threshold t picks between the two nearest values. */
static inline uint32_t fragment_channel(FRAGV v, int bits, int dither, FRAGV t)
{
    if (bits == 8)
        return frag_to_unorm(v, 255, FRAG_ONE / 2);
    return dither ? frag_to_unorm(v, (1u << bits) - 1, t) : frag_to_msb(v, bits);
}
int fragment_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
int fragment_compare(unsigned int func, uint32_t a, uint32_t b);
int fragment_alpha_pass(const GlesContext *ctx, FRAGV alpha);
int fragment_stencil_pass(const GlesContext *ctx, uint8_t stored);
uint8_t fragment_stencil_op(const GlesContext *ctx, unsigned int op, uint8_t s);
/* blended colour (not yet clamped) from source and destination in FRAGV */
void fragment_blend(const GlesContext *ctx, const FRAGV src[4], const FRAGV dst[4], FRAGV out[4]);
uint32_t fragment_logic_op(unsigned int op, uint32_t s, uint32_t d);
FRAGV fragment_dither_threshold(int x, int y);

/* fog.c */
void fog_init(GlesContext *ctx);
int fog_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
void fog_validate(GlesContext *ctx);
/* the fog factor for eye distance c (clamped to [0,1]) */
NUM fog_factor(const GlesContext *ctx, NUM c);
/* per vertex: the factor, or the eye distance when fog is per fragment */
NUM fog_vertex_value(const GlesContext *ctx, const NUM eye[4]);

#endif
