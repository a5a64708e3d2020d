/* lines_wide.c: wide lines (2, 3 and 5 pixels) as real programs draw
 * them: fans at every 7.5 degrees, short ones, strips with sharp turns,
 * on whole and half coordinates without care. GL draws each segment as
 * w pixels across its minor axis in every column (or row) its width-1
 * line lights (GL 2.1 3.4.2, the parallelogram). */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

/* One colour a fan: near the hub neighbours overlap, and which of two
 * overlapping lines of one draw shows is the note's business. */
static void fan(float cx, float cy, float r, float width)
{
    glLineWidth(width);
    glColor3f(0.3f + 0.1f * width, 0.8f, 1.0f - 0.1f * width);
    glBegin(GL_LINES);
    for (int i = 0; i < 48; i++) {
        double a = i * 7.5 * 3.14159265358979 / 180.0;
        glVertex2f(cx + (float)(0.3 * r * cos(a)), cy + (float)(0.3 * r * sin(a)));
        glVertex2f(cx + (float)(r * cos(a)), cy + (float)(r * sin(a)));
    }
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);

    fan(55, 180, 50, 2);
    fan(160, 180, 50, 3);
    fan(265, 180, 50, 5);

    /* Strips with sharp turns, colours smooth from vertex to vertex (a
     * strip's segments overlap only at its vertices, where their colours
     * agree). */
    static const float width[3] = {2, 3, 5};
    for (int k = 0; k < 3; k++) {
        glLineWidth(width[k]);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < 9; i++) {
            glColor3f(i % 2 ? 1.0f : 0.2f, 1, i % 2 ? 0.4f : 1.0f);
            glVertex2f(10.0f + 100.0f * (float)k + 10.0f * (float)i, i % 2 ? 110.0f : 70.0f + 3.0f * (float)i);
        }
        glEnd();
    }

    /* Short ones: one to four pixels long. */
    for (int k = 0; k < 3; k++) {
        glLineWidth(width[k]);
        glColor3f(0.5f, 1, 1);
        glBegin(GL_LINES);
        for (int i = 0; i < 12; i++) {
            double a = i * 0.55, len = 1 + 0.25 * i;
            float x = 12.0f + 100.0f * (float)k + 7.5f * (float)i, y = 30.0f + 0.25f * (float)(i % 4);
            glVertex2f(x, y);
            glVertex2f((float)(x + len * cos(a)), (float)(y + len * sin(a)));
        }
        glEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
