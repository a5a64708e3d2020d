/* real_trails.c: a single-buffered screensaver leaving trails: the colour
 * buffer is cleared once, then each frame clears only the depth buffer,
 * draws a turned, depth-tested pyramid and flushes, so earlier ones stay
 * on screen. Four frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    if (frame == 0) {
        glClearColor(0.05f, 0.05f, 0.1f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(-2.4f + 1.6f * (float)frame, 0.0017f, -8);
    glRotatef(30.0f * (float)frame + 15, 0.3f, 1, 0);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex3f(0, 1, 0);
    const float b[5][2] = {
        {-0.8f, 0.8f}, {0.8f, 0.8f}, {0.8f, -0.8f}, {-0.8f, -0.8f}, {-0.8f, 0.8f}};
    for (int i = 0; i < 5; i++) {
        glColor3f(0.3f * (float)(i % 4), 0.4f + 0.15f * (float)frame, 1 - 0.2f * (float)(i % 4));
        glVertex3f(b[i][0], -0.8f, b[i][1]);
    }
    glEnd();
    glFlush();
}

RGL_REAL_MAIN(draw, 4)
