/* scissor_geometry.c: geometry drawn with GL_SCISSOR_TEST on shows only
 * inside the scissor box, through a perspective camera.
 *
 * Covers: a quad and a GLU sphere (an exact POV-Ray solid) crossing the
 * edges of one box, a triangle fan in another box set after them, a draw
 * whose box lies outside the window (nothing shows) and a draw after the
 * test is turned off (whole). The drop-in header turns the gl* calls into
 * raygl* calls.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glEnable(GL_SCISSOR_TEST);
    glScissor(50, 40, 130, 110);
    glColor3f(0.9f, 0.6f, 0.2f);
    glBegin(GL_QUADS);
    glVertex3f(-4, -3, -12);
    glVertex3f(0, -3, -12);
    glVertex3f(0, 1, -12);
    glVertex3f(-4, 1, -12);
    glEnd();
    GLUquadric *q = gluNewQuadric();
    glColor3f(0.3f, 0.8f, 0.5f);
    glTranslatef(0, 0, -10);
    gluSphere(q, 1.5, 32, 16);
    glLoadIdentity();

    glScissor(200, 120, 90, 100);
    glColor3f(0.8f, 0.3f, 0.7f);
    glBegin(GL_TRIANGLE_FAN);
    glVertex3f(1, 1, -8);
    glVertex3f(4, 0, -8);
    glVertex3f(4, 4, -8);
    glVertex3f(0, 4, -8);
    glEnd();

    glScissor(w + 10, 0, 50, 50); /* outside the window */
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex3f(-5, -5, -9);
    glVertex3f(5, -5, -9);
    glVertex3f(0, 5, -9);
    glEnd();

    glDisable(GL_SCISSOR_TEST);
    glColor3f(0.9f, 0.9f, 0.9f);
    glBegin(GL_TRIANGLES);
    glVertex3f(1.5f, -3, -12);
    glVertex3f(3.5f, -3, -12);
    glVertex3f(2.5f, -1.5f, -12);
    glEnd();
    gluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
