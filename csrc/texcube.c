/*
** texcube.c -- OES_texture_cube_map's face selection (§3.8.10 as the
** extension changes it), in the build's arithmetic (TEXC: 32.32 with
** saturating division in the fixed build).
** Consumes: a fragment's interpolated (s, t, r) (q is ignored: the
**       extension notes it only scales the direction), and the same at
**       the level of detail's neighbours.
** Produces: the face (by the major axis) and the face's (s, t), which
**       texsample.c filters like any 2D texture's with the cube map's
**       filters and wrap modes (copied into each face).
** The neighbours are projected on the fragment's own face, so that the
** level of detail differences coordinates of one image.
*/
#include "state.h"
#include "texcube.h"

int texcube_face(const TEXC str[3])
{
    const TEXC ax = texc_abs(str[0]), ay = texc_abs(str[1]), az = texc_abs(str[2]);
    if (ax >= ay && ax >= az)
        return str[0] >= 0 ? 0 : 1;
    if (ay >= az)
        return str[1] >= 0 ? 2 : 3;
    return str[2] >= 0 ? 4 : 5;
}

void texcube_on_face(int face, const TEXC str[3], TexCoord *out)
{
    const TEXC rx = str[0], ry = str[1], rz = str[2];
    TEXC sc, tc, ma;
    switch (face) {
    case 0: sc = -rz; tc = -ry; ma = rx; break;
    case 1: sc = rz; tc = -ry; ma = rx; break;
    case 2: sc = rx; tc = rz; ma = ry; break;
    case 3: sc = rx; tc = -rz; ma = ry; break;
    case 4: sc = rx; tc = -ry; ma = rz; break;
    default: sc = -rx; tc = -ry; ma = rz; break;
    }
    ma = texc_abs(ma);
    out->s = texc_unit_half(texc_div(sc, ma));
    out->t = texc_unit_half(texc_div(tc, ma));
}

void texcube_coords(const TEXC c[3], const TEXC *dx, const TEXC *dy, TexCoord *tc, TexCoord *tdx, TexCoord *tdy,
                    uint8_t *face)
{
    const int f = texcube_face(c);
    *face = (uint8_t)f;
    texcube_on_face(f, c, tc);
    if (dx && dy) {
        texcube_on_face(f, dx, tdx);
        texcube_on_face(f, dy, tdy);
    }
}
