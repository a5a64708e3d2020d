/* real_starfield.c: the starfield screensaver: points of a few sizes
 * streaming towards the viewer, three frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60, (double)w / h, 0.1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    unsigned s = 12345;
    for (int size = 1; size <= 3; size++) {
        glPointSize((float)size);
        glBegin(GL_POINTS);
        for (int i = 0; i < 60; i++) {
            s = s * 1103515245u + 12345u;
            float x = (float)((s >> 8) % 2000) / 100.0f - 10;
            s = s * 1103515245u + 12345u;
            float y = (float)((s >> 8) % 1500) / 100.0f - 7.5f;
            s = s * 1103515245u + 12345u;
            float z = -5 - (float)((s >> 8) % 3000) / 100.0f + 2.0f * (float)frame;
            float b = 0.4f + 0.2f * (float)size;
            glColor3f(b, b, 0.8f + 0.06f * (float)size);
            glVertex3f(x, y, z);
        }
        glEnd();
    }
}

RGL_REAL_MAIN(draw, 3)
