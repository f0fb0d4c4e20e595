/* paletted.c -- an OES_compressed_paletted_texture image with its whole
** mip chain in one call (PALETTE4_RGBA8, 8x8 down to 1x1, each level its own
** indices): magnified over the window, then minified by exactly 2, 4 and 8
** so that NEAREST_MIPMAP_NEAREST shows levels 1, 2 and 3 texel for pixel;
** fixed-point commands only (both profiles) */
#include "harness.h"

int main(int argc, char **argv)
{
    harness_begin(0, 0);
    /* 16 palette entries, then the 4-bit indices of the 8x8, 4x4, 2x2 and
    ** 1x1 levels, two per byte, high nibble first, each level from a byte */
    static GLubyte data[16 * 4 + 32 + 8 + 2 + 1];
    for (int i = 0; i < 16; i++) {
        data[i * 4 + 0] = (GLubyte)(i * 17);
        data[i * 4 + 1] = (GLubyte)(255 - i * 17);
        data[i * 4 + 2] = (GLubyte)((i & 3) * 85);
        data[i * 4 + 3] = 255;
    }
    GLubyte *idx = data + 64;
    int n = 0;
    for (int size = 8, level = 0; size >= 1; size /= 2, level++) {
        for (int t = 0; t < size * size; t++) {
            int v = (t % size + 2 * (t / size) + 5 * level) & 15;
            if (n & 1)
                idx[n / 2] = (GLubyte)(idx[n / 2] | v);
            else
                idx[n / 2] = (GLubyte)(v << 4);
            n++;
        }
        n = (n + 1) & ~1;
    }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glCompressedTexImage2D(GL_TEXTURE_2D, -3, GL_PALETTE4_RGBA8_OES, 8, 8, 0, (GLsizei)sizeof data, data);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColorx(FX(0.5), 0, FX(0.5), FX(1));
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrthox(0, FX(W), 0, FX(H), FX(-1), FX(1));
    glMatrixMode(GL_MODELVIEW);
    /* the window (texture magnified 8x), then quads of 32, 16 and 8 pixels
    ** each showing the texture 8 times across */
    static const GLshort vertices[] = {
        0, 0, 64, 0, 0, 64, 64, 64,
        0, 0, 32, 0, 0, 32, 32, 32,
        32, 0, 48, 0, 32, 16, 48, 16,
        48, 0, 56, 0, 48, 8, 56, 8,
    };
    static const GLbyte texcoords[] = {
        0, 0, 1, 0, 0, 1, 1, 1,
        0, 0, 8, 0, 0, 8, 8, 8,
        0, 0, 8, 0, 0, 8, 8, 8,
        0, 0, 8, 0, 0, 8, 8, 8,
    };
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_SHORT, 0, vertices);
    glTexCoordPointer(2, GL_BYTE, 0, texcoords);
    for (int q = 0; q < 4; q++)
        glDrawArrays(GL_TRIANGLE_STRIP, q * 4, 4);
    return harness_end(argc, argv);
}
