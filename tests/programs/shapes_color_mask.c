/* shapes_color_mask.c: a pass with every colour channel masked (OSMesa).
 * As a program that marks a stencil region first: glColorMask all
 * GL_FALSE and glDepthMask(GL_FALSE), a large white quad and a sphere
 * (nothing shows in GL), then the masks back on and a scene of coloured
 * triangles (issue 14, "glColorMask where it changes the picture").
 * Unlit. */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glTranslatef(0.0f, 0.0f, -6.0f);

    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glColor3f(1.0f, 1.0f, 1.0f);
    glRectf(-1.5f, -1.0f, 1.5f, 1.0f);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 0.8, 16, 12);
    gluDeleteQuadric(q);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 5; i++) {
        float x = -2.0f + 0.9f * (float)i;
        glColor3f(0.2f * (float)i, 0.9f - 0.15f * (float)i, 0.5f);
        glVertex3f(x, -1.2f, 0.0f);
        glVertex3f(x + 0.8f, -1.0f, -0.5f);
        glVertex3f(x + 0.3f, 0.2f + 0.2f * (float)i, 0.2f);
    }
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
