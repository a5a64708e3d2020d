/* real_morph_poly.c: a morphing polyhedron in the style of the morph3d
 * screensaver: an octahedron's faces subdivided and pushed out toward a
 * sphere by an amount that changes each frame, each face flat-lit in its
 * own colour (GL_FLAT, per-face normals), turning. Two directional lights,
 * infinite viewer. Five frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

static void norm(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

static void morph(const float a[3], const float b[3], const float c[3], float t, int n)
{
    /* Barycentric grid of n x n small triangles, each vertex moved from
     * the flat face toward the unit sphere by t. */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n - i; j++)
            for (int up = 0; up < (j < n - i - 1 ? 2 : 1); up++) {
                int ij[3][2] = {{i, j}, {i + 1, j}, {i, j + 1}};
                if (up) {
                    ij[0][0] = i + 1, ij[0][1] = j + 1;
                    ij[1][0] = i, ij[1][1] = j + 1;
                    ij[2][0] = i + 1, ij[2][1] = j;
                }
                float p[3][3];
                for (int k = 0; k < 3; k++) {
                    float u = (float)ij[k][0] / n, v = (float)ij[k][1] / n;
                    float f[3], s[3];
                    for (int d = 0; d < 3; d++)
                        f[d] = a[d] + u * (b[d] - a[d]) + v * (c[d] - a[d]);
                    for (int d = 0; d < 3; d++)
                        s[d] = f[d];
                    norm(s);
                    for (int d = 0; d < 3; d++)
                        p[k][d] = f[d] + t * (s[d] - f[d]);
                }
                float e1[3], e2[3], nn[3];
                for (int d = 0; d < 3; d++)
                    e1[d] = p[1][d] - p[0][d], e2[d] = p[2][d] - p[0][d];
                nn[0] = e1[1] * e2[2] - e1[2] * e2[1];
                nn[1] = e1[2] * e2[0] - e1[0] * e2[2];
                nn[2] = e1[0] * e2[1] - e1[1] * e2[0];
                norm(nn);
                glNormal3fv(nn);
                for (int k = 0; k < 3; k++)
                    glVertex3fv(p[k]);
            }
}

static void draw(int frame, int w, int h)
{
    static const float v[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    static const GLfloat col[8][4] = {{0.9f, 0.2f, 0.2f, 1}, {0.2f, 0.9f, 0.2f, 1},
                                      {0.2f, 0.3f, 0.9f, 1}, {0.9f, 0.9f, 0.2f, 1},
                                      {0.9f, 0.2f, 0.9f, 1}, {0.2f, 0.9f, 0.9f, 1},
                                      {0.9f, 0.6f, 0.3f, 1}, {0.6f, 0.6f, 0.6f, 1}};
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const GLfloat p0[4] = {1, 1, 1, 0}, p1[4] = {-1, -0.5f, 1, 0};
    const GLfloat d0[4] = {0.8f, 0.8f, 0.8f, 1}, d1[4] = {0.3f, 0.3f, 0.4f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, p0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, d0);
    glLightfv(GL_LIGHT1, GL_POSITION, p1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, d1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glShadeModel(GL_FLAT);
    glTranslatef(0.0013f, 0.0017f, -5.0f);
    glRotatef(15.0f + 11.0f * (float)frame, 1, 0, 0);
    glRotatef(25.0f + 17.0f * (float)frame, 0, 1, 0);
    float t = 0.5f - 0.5f * cosf(0.7f * (float)frame);
    for (int i = 0; i < 8; i++) {
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, col[i]);
        glBegin(GL_TRIANGLES);
        morph(v[f[i][0]], v[f[i][1]], v[f[i][2]], t, 6);
        glEnd();
    }
}

RGL_REAL_MAIN(draw, 5)
