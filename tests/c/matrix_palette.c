/* matrix_palette.c -- OES_matrix_palette: a strip skinned between two
** palette matrices with per-vertex weights, the extension's entry points
** found through eglGetProcAddress; fixed-point commands only (both
** profiles) */
#include "harness.h"

#include <string.h>

int main(int argc, char **argv)
{
    harness_begin(0, 0);
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    if (!ext || !strstr(ext, "GL_OES_matrix_palette")) {
        fprintf(stderr, "no GL_OES_matrix_palette\n");
        return 4;
    }
    PFNGLCURRENTPALETTEMATRIXOESPROC current_palette =
        (PFNGLCURRENTPALETTEMATRIXOESPROC)eglGetProcAddress("glCurrentPaletteMatrixOES");
    PFNGLLOADPALETTEFROMMODELVIEWMATRIXOESPROC load_palette =
        (PFNGLLOADPALETTEFROMMODELVIEWMATRIXOESPROC)eglGetProcAddress("glLoadPaletteFromModelViewMatrixOES");
    PFNGLMATRIXINDEXPOINTEROESPROC index_pointer =
        (PFNGLMATRIXINDEXPOINTEROESPROC)eglGetProcAddress("glMatrixIndexPointerOES");
    PFNGLWEIGHTPOINTEROESPROC weight_pointer = (PFNGLWEIGHTPOINTEROESPROC)eglGetProcAddress("glWeightPointerOES");
    if (!current_palette || !load_palette || !index_pointer || !weight_pointer) {
        fprintf(stderr, "eglGetProcAddress found no OES_matrix_palette entry point\n");
        return 4;
    }
    glClearColorx(0, 0, 0, FX(1));
    glClear(GL_COLOR_BUFFER_BIT);
    /* palette 0: the modelview (a shift left); palette 1: a turn and a shift up */
    glMatrixMode(GL_MODELVIEW);
    glTranslatex(FX(-0.25), 0, 0);
    glMatrixMode(GL_MATRIX_PALETTE_OES);
    current_palette(0);
    load_palette();
    current_palette(1);
    glLoadIdentity();
    glTranslatex(0, FX(0.25), 0);
    glRotatex(FX(40), 0, 0, FX(1));
    glEnable(GL_MATRIX_PALETTE_OES);
    /* a horizontal strip of 5 column pairs; the weight of palette 1 rises
    ** from 0 to 1 along it */
    static GLfixed vertices[10 * 2];
    static GLfixed weights[10 * 2];
    static GLubyte indices[10 * 2];
    static GLubyte colors[10 * 4];
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 2; j++) {
            int v = i * 2 + j;
            vertices[v * 2] = FX(-0.625) + i * FX(0.3125);
            vertices[v * 2 + 1] = j ? FX(0.125) : FX(-0.375);
            weights[v * 2] = FX(1) - i * FX(0.25);
            weights[v * 2 + 1] = i * FX(0.25);
            indices[v * 2] = 0;
            indices[v * 2 + 1] = 1;
            colors[v * 4] = (GLubyte)(255 - i * 60);
            colors[v * 4 + 1] = (GLubyte)(j ? 255 : 64);
            colors[v * 4 + 2] = (GLubyte)(i * 60);
            colors[v * 4 + 3] = 255;
        }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_MATRIX_INDEX_ARRAY_OES);
    glEnableClientState(GL_WEIGHT_ARRAY_OES);
    glVertexPointer(2, GL_FIXED, 0, vertices);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    index_pointer(2, GL_UNSIGNED_BYTE, 0, indices);
    weight_pointer(2, GL_FIXED, 0, weights);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    return harness_end(argc, argv);
}
