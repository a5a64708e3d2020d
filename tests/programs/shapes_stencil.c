/* shapes_stencil.c: the stencil test's common pattern (OSMesa). A
 * window shape (a hexagon and a triangle) is drawn into the stencil
 * buffer with colour writes off (glStencilOp GL_REPLACE, ref 1); then a
 * sphere and a strip of triangles drawn where the stencil is 1, and a
 * backdrop of quads where it is not (GL_NOTEQUAL), as a program shows a
 * scene through a window (issue 14, "stencil test"). Unlit. */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static void window_shape(void)
{
    glBegin(GL_TRIANGLE_FAN);
    glVertex3f(-0.6f, 0.1f, -4.0f);
    for (int i = 0; i <= 6; i++) {
        float a = (float)i * 1.0471976f + 0.3f;
        glVertex3f(-0.6f + 1.5f * cosf(a), 0.1f + 1.5f * sinf(a), -4.0f);
    }
    glEnd();
    glBegin(GL_TRIANGLES);
    glVertex3f(1.0f, -1.6f, -4.0f);
    glVertex3f(2.4f, -1.2f, -4.0f);
    glVertex3f(1.6f, 1.3f, -4.0f);
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    /* The window, into the stencil buffer only. */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    window_shape();
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);

    /* Through the window. */
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    GLUquadric *q = gluNewQuadric();
    glColor3f(1.0f, 0.6f, 0.2f);
    glPushMatrix();
    glTranslatef(0.2f, 0.0f, -7.0f);
    gluSphere(q, 1.6, 24, 16);
    glPopMatrix();
    gluDeleteQuadric(q);
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= 10; i++) {
        glColor3f(0.2f, 0.4f + 0.05f * (float)i, 1.0f - 0.06f * (float)i);
        glVertex3f(-3.0f + 0.6f * (float)i, -1.5f, -6.0f);
        glVertex3f(-3.0f + 0.6f * (float)i, -0.6f, -6.0f);
    }
    glEnd();

    /* Around it. */
    glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++) {
        float x = -4.5f + 1.5f * (float)i;
        glColor3f(0.3f + 0.1f * (float)i, 0.8f, 0.3f);
        glVertex3f(x, -3.0f, -9.0f);
        glVertex3f(x + 1.2f, -3.0f, -9.0f);
        glVertex3f(x + 1.2f, 3.0f, -9.0f);
        glVertex3f(x, 3.0f, -9.0f);
    }
    glEnd();
    glDisable(GL_STENCIL_TEST);
    return 0;
}

RGL_TEST_MAIN(draw)
