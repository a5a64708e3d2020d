/* glut_wire_fine.c: GLUT wire forms as demos draw them: glutWireSphere,
 * glutWireTorus and glutWireTeapot, large and small (where their segments
 * are a pixel or two long), 1-pixel lines, no offsets; plus a solid torus
 * in glPolygonMode(GL_LINE) (GLUT window: run under Xvfb). */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glLoadIdentity();
    glTranslatef(-2.2f, 1.0f, -7);
    glRotatef(20, 1, 0, 0);
    glColor3f(0.4f, 1, 0.5f);
    glutWireSphere(1.2, 16, 12);

    glLoadIdentity();
    glTranslatef(0.6f, 1.1f, -7);
    glRotatef(50, 1, 0, 0);
    glColor3f(1, 0.6f, 0.3f);
    glutWireTorus(0.35, 0.9, 10, 20);

    glLoadIdentity();
    glTranslatef(2.9f, 1.2f, -7);
    glRotatef(15, 1, 0, 0);
    glColor3f(0.5f, 0.7f, 1);
    glutWireTeapot(0.8);

    /* Small: a few pixels across. */
    for (int i = 0; i < 5; i++) {
        glLoadIdentity();
        glTranslatef(-3.0f + 0.9f * (float)i, -1.6f, -8);
        glRotatef(30.0f * (float)i, 1, 1, 0);
        glColor3f(1, 1, 0.4f);
        double r = 0.08 + 0.06 * i;
        if (i % 3 == 0)
            glutWireSphere(r, 10, 8);
        else if (i % 3 == 1)
            glutWireTorus(r * 0.3, r, 8, 12);
        else
            glutWireTeapot(r);
    }

    glLoadIdentity();
    glTranslatef(2.2f, -1.4f, -7);
    glRotatef(60, 1, 0, 0);
    glColor3f(0.9f, 0.4f, 1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glutSolidTorus(0.3, 0.8, 8, 16);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    return 0;
}

RGL_TEST_MAIN(draw)
