/*
** texgen.h -- OES_texture_cube_map's texture coordinate generation
** (TEXTURE_GEN_STR_OES: NORMAL_MAP_OES, REFLECTION_MAP_OES).
*/
#ifndef GLES_TEXGEN_H
#define GLES_TEXGEN_H

#include "state.h"

/* whether any unit has TEXTURE_GEN_STR_OES on (the vertex stage then forms
** the normal matrix), and whether any with REFLECTION_MAP_OES (it then
** needs eye coordinates); from the API state, whatever the unit samples */
int texgen_any(const GlesContext *ctx);
int texgen_needs_eye(const GlesContext *ctx);
/* a unit's generated s, t, r into tc[0..2] from the vertex's eye position
** and eye normal nf (vertex_eye_normal; tc[3], q, is left as the vertex gave it) */
void texgen_coords(unsigned int mode, const NUM eye[4], const NUM nf[3], NUM tc[4]);

#endif
