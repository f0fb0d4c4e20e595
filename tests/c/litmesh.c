/* litmesh.c -- a lit paraboloid from buffer objects: interleaved float
** positions and normals, unsigned short indices, two lights (Common) */
#include "harness.h"

#define N 9   /* grid points per side */

int main(int argc, char **argv)
{
    harness_begin(24, 0);
    static GLfloat vertex[N * N * 6];
    static GLushort index[(N - 1) * (N - 1) * 6];
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            GLfloat x = (GLfloat)(i - 4) * 0.25f, y = (GLfloat)(j - 4) * 0.25f;
            GLfloat *v = &vertex[(j * N + i) * 6];
            v[0] = x;
            v[1] = y;
            v[2] = (x * x + y * y) * 0.25f;
            v[3] = -x * 0.5f;   /* the surface normal, not unit length: GL_NORMALIZE */
            v[4] = -y * 0.5f;
            v[5] = 1.0f;
        }
    int k = 0;
    for (int j = 0; j < N - 1; j++)
        for (int i = 0; i < N - 1; i++) {
            GLushort a = (GLushort)(j * N + i), b = (GLushort)(a + 1), c = (GLushort)(a + N), d = (GLushort)(c + 1);
            index[k++] = a; index[k++] = b; index[k++] = d;
            index[k++] = a; index[k++] = d; index[k++] = c;
        }
    GLuint buffers[2];
    glGenBuffers(2, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof vertex, vertex, GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof index, index, GL_STATIC_DRAW);

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_NORMALIZE);
    static const GLfloat pos0[] = {1.0f, 1.0f, 2.0f, 0.0f}, pos1[] = {-1.0f, 0.5f, 1.0f, 1.0f};
    static const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f}, blue[] = {0.25f, 0.5f, 1.0f, 1.0f};
    static const GLfloat diffuse[] = {0.75f, 0.5f, 0.25f, 1.0f}, ambient[] = {0.125f, 0.125f, 0.125f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.5f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
    glMatrixMode(GL_PROJECTION);
    glFrustumf(-0.5f, 0.5f, -0.5f, 0.5f, 1.0f, 10.0f);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(GLfloat), (const void *)0);
    glNormalPointer(GL_FLOAT, 6 * sizeof(GLfloat), (const void *)(3 * sizeof(GLfloat)));
    glDrawElements(GL_TRIANGLES, (N - 1) * (N - 1) * 6, GL_UNSIGNED_SHORT, (const void *)0);
    glDeleteBuffers(2, buffers);
    return harness_end(argc, argv);
}
