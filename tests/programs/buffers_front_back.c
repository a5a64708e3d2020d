/* buffers_front_back.c: a frame drawn to the front and back buffers in
 * turn (glDrawBuffer; GLUT double-buffered window under Xvfb, whose back
 * buffer the frame shows at the swap). Both buffers are cleared (GL_FRONT_
 * AND_BACK), a red quad goes to the front buffer only, a green one to the
 * back, the front buffer alone is cleared to white, a blue quad goes to
 * both, and a yellow one over everything to GL_NONE: the back buffer holds
 * the green and blue quads on the first clear colour. Depth-tested
 * (GL_LESS); the draws that reach no shown buffer write no depth.
 */
#include "harness.h"

#include <raygl/gl.h>

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glDrawBuffer(GL_FRONT_AND_BACK);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glDrawBuffer(GL_FRONT);
    glDepthMask(GL_FALSE);
    glColor3f(0.9f, 0.2f, 0.2f);
    quad(-2.2f, -1.0f, -0.2f, 1.2f, -6.0f);
    glDepthMask(GL_TRUE);

    glDrawBuffer(GL_BACK);
    glColor3f(0.2f, 0.8f, 0.3f);
    quad(-1.5f, -1.6f, 1.0f, 0.4f, -7.0f);

    glDrawBuffer(GL_FRONT);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    glDrawBuffer(GL_FRONT_AND_BACK);
    glColor3f(0.2f, 0.4f, 1.0f);
    quad(0.3f, -0.6f, 2.4f, 1.5f, -6.5f);

    glDrawBuffer(GL_NONE);
    glDepthMask(GL_FALSE);
    glColor3f(1.0f, 0.9f, 0.1f);
    quad(-2.5f, -2.0f, 2.5f, 2.0f, -4.0f);
    glDepthMask(GL_TRUE);
    glDrawBuffer(GL_BACK);
    return 0;
}

RGL_TEST_MAIN(draw)
