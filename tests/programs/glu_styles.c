/* glu_styles.c: the quadric draw styles, unlit, in a 4 x 3 grid (OSMesa).
 * Columns: sphere, cone (gluCylinder), disk with a hole, partial disk.
 * Rows: GLU_LINE, GLU_SILHOUETTE, GLU_POINT (points 2 pixels). */
#include "harness.h"

#include <raygl/gl.h>

static void cell(int k)
{
    glLoadIdentity();
    glTranslatef(-4.5f + 3.0f * (float)(k % 4), 3.0f - 3.0f * (float)(k / 4), -14.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(1.0f - 0.06f * (float)k, 0.5f + 0.04f * (float)k, 0.4f);
}

static int draw(int w, int h)
{
    static const GLenum styles[3] = {GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glPointSize(2.0f);
    GLUquadric *q = gluNewQuadric();
    for (int r = 0; r < 3; r++) {
        gluQuadricDrawStyle(q, styles[r]);
        cell(4 * r);
        gluSphere(q, 1.0, 10, 6);
        cell(4 * r + 1);
        glTranslatef(0.0f, 0.0f, -0.7f);
        gluCylinder(q, 0.9, 0.3, 1.4, 10, 3);
        cell(4 * r + 2);
        gluDisk(q, 0.4, 1.0, 12, 2);
        cell(4 * r + 3);
        gluPartialDisk(q, 0.3, 1.0, 8, 2, 30.0, 250.0);
    }
    gluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
