/* texquad.c -- a textured quad in perspective with a full mipmap chain
** (each level the 2x2 average of the one above, made here and uploaded
** level by level), trilinear filtering (Common profile) */
#include "harness.h"

int main(int argc, char **argv)
{
    harness_begin(16, 0);
    static GLubyte levels[2][16 * 16 * 4];
    GLubyte *src = levels[0], *dst = levels[1];
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            GLubyte *p = &src[(y * 16 + x) * 4];
            p[0] = (GLubyte)(x * 17);
            p[1] = (GLubyte)(y * 17);
            p[2] = (GLubyte)(255 - (x + y) * 8);
            p[3] = 255;
        }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (int level = 0, size = 16; size >= 1; level++, size /= 2) {
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
        int half = size / 2;
        for (int y = 0; y < half; y++)
            for (int x = 0; x < half; x++)
                for (int c = 0; c < 4; c++) {
                    int sum = src[((2 * y) * size + 2 * x) * 4 + c] + src[((2 * y) * size + 2 * x + 1) * 4 + c]
                            + src[((2 * y + 1) * size + 2 * x) * 4 + c] + src[((2 * y + 1) * size + 2 * x + 1) * 4 + c];
                    dst[(y * half + x) * 4 + c] = (GLubyte)((sum + 2) / 4);
                }
        GLubyte *t = src;
        src = dst;
        dst = t;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.25f, 0.25f, 0.25f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glFrustumf(-0.5f, 0.5f, -0.5f, 0.5f, 1.0f, 10.0f);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, 0.0f, -2.5f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    static const GLfloat vertices[] = {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0};
    static const GLfloat texcoords[] = {0, 0, 2, 0, 0, 2, 2, 2};
    glColor4f(1.0f, 0.875f, 0.75f, 1.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, vertices);
    glTexCoordPointer(2, GL_FLOAT, 0, texcoords);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    return harness_end(argc, argv);
}
