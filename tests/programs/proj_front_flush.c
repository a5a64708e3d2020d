/* proj_front_flush.c: a single-buffered painter (issue 14).
 *
 * Draws into the front buffer and shows each frame with glFlush, as a
 * single-buffered GLUT program does: frame 0 clears and draws a square,
 * frame 1 adds a triangle, frame 2 only flushes (GL still shows both),
 * frame 3 clears the depth buffer alone and adds a fan, frame 4 clears the
 * colour buffer and draws one strip.
 */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.21f, 0.43f, 0);
    glClearColor(0.1f, 0.1f, 0.3f, 1);
    switch (frame) {
    case 0:
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glColor3f(1, 0.5f, 0);
        glRectf(20, 20, 120, 120);
        break;
    case 1:
        glBegin(GL_TRIANGLES);
        glColor3f(0, 1, 0);
        glVertex2f(150, 20);
        glColor3f(0, 0.4f, 1);
        glVertex2f(300, 40);
        glColor3f(1, 1, 1);
        glVertex2f(220, 200);
        glEnd();
        break;
    case 2:
        break;
    case 3:
        glClear(GL_DEPTH_BUFFER_BIT);
        glColor3f(1, 0, 0.5f);
        glBegin(GL_TRIANGLE_FAN);
        glVertex2f(70, 180);
        glVertex2f(120, 170);
        glVertex2f(90, 225);
        glVertex2f(30, 220);
        glEnd();
        break;
    default:
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3f(1, 1, 0);
        glRectf(100, 100, 200, 140);
        break;
    }
    glFlush();
}

RGL_REAL_MAIN(draw, 5)
