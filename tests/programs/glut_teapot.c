/* glut_teapot.c: freeglut's teapot, unlit (GLUT window: run under Xvfb).
 *
 * Left to right, top to bottom: a tilted teapot of size 1 and one of size
 * 0.7 seen from above its spout (both become Newell's curved patches), a
 * teapot under GL_CULL_FACE (freeglut winds it clockwise, so GL culls its
 * outside and shows the inside: drawn as freeglut's own triangles), and
 * the wire teapot. */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static void cell(int k)
{
    glLoadIdentity();
    glTranslatef(-1.8f + 3.6f * (float)(k % 2), 1.2f - 2.4f * (float)(k / 2), -8.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-35.0f, 0.0f, 1.0f, 0.0f);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    cell(0);
    glColor3f(0.9f, 0.6f, 0.3f);
    glutSolidTeapot(1.0);
    cell(1);
    glRotatef(50.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(70.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.3f, 0.7f, 0.9f);
    glutSolidTeapot(0.7);
    cell(2);
    glEnable(GL_CULL_FACE);
    glColor3f(0.6f, 0.9f, 0.4f);
    glutSolidTeapot(1.0);
    glDisable(GL_CULL_FACE);
    cell(3);
    glColor3f(1.0f, 1.0f, 1.0f);
    glutWireTeapot(1.0);
    return 0;
}

RGL_TEST_MAIN(draw)
