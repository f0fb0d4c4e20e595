/*
** texture.h -- texture objects, images and sampling (ES 1.1 §3.7).
*/
#ifndef GLES_TEXTURE_H
#define GLES_TEXTURE_H

#include "state.h"

/* 0 without memory for the default cube map's faces */
int texture_init(GlesContext *ctx);
/* a unit's derived `enabled` and `bound` from its enables and bindings */
void texture_unit_update(TexUnit *tu);
void texture_free(GlesContext *ctx);
int texture_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
/* the unit's bound texture when it is enabled and complete, else NULL */
const Texture *texture_active(const GlesContext *ctx, int unit);
/* derived per-draw texture state: enabled units and their samplers */
void texture_validate(GlesContext *ctx);
/* the base format (Table 3.15's row) of a level's internal format */
unsigned int texture_base_format(unsigned int internal_format);

/* texture coordinates of a pixel: s, t after the division by q */
struct TexCoord {
    TEXC s, t;
};

/* the filtered texel for texture coordinates at a pixel and, when the
** filter needs a level of detail, at its right and upper neighbours
** (dx, dy may be NULL otherwise); out is RGBA in FRAGV; unorm is the
** context's table of c / 255 */
void texture_sample(const Texture *tex, double lod_bias, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                    FRAGV out[4], const FRAGV *unorm);
/* EXT_texture_lod_bias: MAX_TEXTURE_LOD_BIAS_EXT, the largest |bias| used */
#define TEXTURE_MAX_LOD_BIAS 16.0
/* EXT_texture_filter_anisotropic: MAX_TEXTURE_MAX_ANISOTROPY_EXT */
#define TEXTURE_MAX_ANISOTROPY 16.0
/* texture_sample for n fragments, with the texture's filter and wrap
** modes fixed: fragment j's coordinates c[j] (and dx[j], dy[j] when the
** filter needs a level of detail), its texel at out + j * stride */
TexSpanSampler texture_span_sampler(const Texture *tex, int simd);
/* the group size of that sampler's vector kernel: where it is 8 or 4, the
** kernel samples any multiple of it whole, with every coordinate a copy of
** one given to it as safe as that one (the chain pads a chunk's tail with
** copies rather than leave it to the scalar code); 1 where there is none */
int texture_span_sample_group(const Texture *tex, int simd);
/* does sampling this texture need the neighbours' coordinates */
int texture_needs_lod(const Texture *tex);

/* texture_span_fog_write's fog and write of the texels: slot j (the
** chunk's fragment j) has the weights p[j] and the pixel k[j] of dst, an
** RGBA8888 word or (rgb565) an RGB565 one dithered by t_row[(x0 + k[j]) & 3] */
typedef struct TexFogWrite {
    float a[3];             /* the vertices' fog factors (|a| <= 2; the fixed build's 16.16 times 2^-46) */
    float fc[3];            /* the fog colour's channels (in [0, 1]; the fixed build's 0.30 times 2^-30) */
    const WGT (*p)[3];
    void *dst;
    const uint8_t *k;
    int rgb565, dither, x0;
    float t_row[4];         /* the dither thresholds (the fixed build's 0.30 times 2^-30) */
    uint64_t *done;         /* bit j (word j / 64) set where slot j's pixel was written */
} TexFogWrite;
/* texture_span_sampler's texels of a lone REPLACE unit (its texture has a
** level of detail), then the fog with the factor from the weights and the
** write, each pixel proved equal to the exact stages' (the fixed and
** double builds' AVX2 kernel); a fragment left unproved gets its texel at out + j stride,
** its bit in fw->done clear, for the exact stages. 0 (nothing done) where
** the kernel does not apply */
int texture_span_fog_write(const Texture *tex, int n, const TexCoord *c, const TexCoord *dx, const TexCoord *dy,
                           FRAGV *out, size_t stride, const FRAGV *unorm, const TexFogWrite *fw);
/* the texture environment of unit u: cp is the previous colour (in and
** out), cf the primary (fragment) colour, ct[u] every unit's texel */
void texture_env(const GlesContext *ctx, int u, const FRAGV cf[4], FRAGV ct[][4], FRAGV cp[4]);
/* the same for n fragments: cf[j], ct[j], cp[j] are fragment j's */
void texture_env_span(const GlesContext *ctx, int u, int n, const FRAGV (*cf)[4],
                      FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4]);
#if SIMD_X86
/* texture_env_span with COMBINE's arithmetic in AVX2 (the same bits) */
void texture_env_span_avx2(const GlesContext *ctx, int u, int n, const FRAGV (*cf)[4],
                           FRAGV (*ct)[GLES_MAX_TEXTURE_UNITS][4], FRAGV (*cp)[4]);
#endif

#endif
