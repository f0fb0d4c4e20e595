/* triangle.c -- a smooth-shaded triangle, fixed-point commands only (runs on
** both profiles) */
#include "harness.h"

int main(int argc, char **argv)
{
    harness_begin(0, 0);
    static const GLfixed vertices[] = {FX(-0.75), FX(-0.625), 0, FX(0.8125), FX(-0.25), 0, FX(-0.125), FX(0.875), 0};
    static const GLubyte colors[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
    glClearColorx(0, 0, FX(0.25), FX(1));
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);
    glRotatex(FX(30), 0, 0, FX(1));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FIXED, 0, vertices);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return harness_end(argc, argv);
}
