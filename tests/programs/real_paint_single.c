/* real_paint_single.c: a single-buffered drawing program: each frame adds
 * strokes and a stamp to the front buffer and shows them with glFlush;
 * only the first frame clears. Four frames. */
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
    if (frame == 0) {
        glClearColor(1, 1, 0.95f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glColor3f(0.2f * (float)frame, 0.3f, 1 - 0.2f * (float)frame);
    glLineWidth(3);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 8; i++)
        glVertex2f(20.0f + 38.0f * (float)i, 30.0f + 50.0f * (float)frame + 12.0f * (float)(i % 2));
    glEnd();
    glLineWidth(1);
    glColor3f(0.9f, 0.4f, 0.1f);
    glRectf(250.0f - 50.0f * (float)frame, 180, 280.0f - 50.0f * (float)frame, 210);
    glFlush();
}

RGL_REAL_MAIN(draw, 4)
