/* real_terrain.c: a smooth-coloured height field drawn as triangle strips
 * under a perspective fly-over (the classic terrain demo), three frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

static float height(int i, int j) { return 0.4f * sinf(0.7f * (float)i) * cosf(0.5f * (float)j); }

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.6f, 0.75f, 0.95f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 0.5, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.01, 3, 6 - 0.8 * frame, 0, 0, -4, 0, 1, 0);
    glShadeModel(GL_SMOOTH);
    for (int i = -8; i < 8; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = -12; j <= 4; j++) {
            for (int k = 0; k < 2; k++) {
                float y = height(i + k, j);
                glColor3f(0.2f + y, 0.5f + 0.8f * y, 0.2f);
                glVertex3f(0.5f * (float)(i + k), y, 0.5f * (float)j);
            }
        }
        glEnd();
    }
}

RGL_REAL_MAIN(draw, 3)
