/*
** fbo.h -- framebuffer and renderbuffer objects (OES_framebuffer_object and
** the formats with it: OES_rgb8_rgba8, OES_depth24, OES_stencil8,
** OES_packed_depth_stencil, OES_fbo_render_mipmap).
*/
#ifndef GLES_FBO_H
#define GLES_FBO_H

#include "state.h"

void fbo_init(GlesContext *ctx);
/* every object freed, the window's buffers back in the context */
void fbo_free(GlesContext *ctx);
/* before a command draws into or reads the bound framebuffer: 1 when it
** can (the window, or a complete object, whose buffers are now the
** context's), else 0 with INVALID_FRAMEBUFFER_OPERATION_OES recorded */
int fbo_sync(GlesContext *ctx);
/* a texture being deleted: detached from every framebuffer object */
void fbo_texture_deleted(GlesContext *ctx, const Texture *t);
/* the texture the bound framebuffer draws into, if any (threads keep off
** a draw that samples it) */
const Texture *fbo_color_texture(const GlesContext *ctx);
/* the window's buffers, whichever framebuffer is bound */
const DrawBuffers *fbo_window(GlesContext *ctx);
/* whether alpha is written under ColorMask alpha `mask`: not into an
** RGBA8888 buffer that keeps no alpha (RGB8, an RGB texture), where the
** stored 1 must stay for DST_ALPHA */
static inline int fbo_alpha_written(const GlesContext *ctx, int mask)
{
    return mask && (ctx->color_alpha || ctx->color_format != GLES_COLOR_RGBA8888);
}
/* framebuffer state queries (FRAMEBUFFER_BINDING_OES, ...): count or 0 */
int fbo_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);

#endif
