/*
** texcube.h -- OES_texture_cube_map's sampling: a fragment's (s, t, r) to
** a face and that face's 2D coordinates.
*/
#ifndef GLES_TEXCUBE_H
#define GLES_TEXCUBE_H

#include "state.h"
#include "texture.h"

/* the face (0..5: POSITIVE_X, NEGATIVE_X, ..., NEGATIVE_Z) whose axis has
** the largest magnitude in str; ties go to x, then y */
int texcube_face(const TEXC str[3]);
/* the coordinates on `face` of direction str: s = (sc / |ma| + 1) / 2,
** t = (tc / |ma| + 1) / 2 by the extension's table */
void texcube_on_face(int face, const TEXC str[3], TexCoord *out);
/* a fragment's face and face coordinates from its direction c, with its
** neighbours' (dx, dy: NULL when the filter needs no level of detail) on
** the same face, which the level of detail then differences */
void texcube_coords(const TEXC c[3], const TEXC *dx, const TEXC *dy, TexCoord *tc, TexCoord *tdx, TexCoord *tdy,
                    uint8_t *face);

#endif
