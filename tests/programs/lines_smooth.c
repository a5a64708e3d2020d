/* lines_smooth.c: antialiased lines (GL_LINE_SMOOTH) as programs draw
 * them: a fan of width 1, 2 and 3 at every 15 degrees blended over the
 * background (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, as AA lines want),
 * smooth colours along them, and the same without blending. Mesa draws a
 * rectangle max(1, w / 2 + 1/2) to each side of the line and half a
 * pixel longer at each end, every pixel in it, and puts the coverage in
 * alpha: blended, the rim fades out over its last pixel. The spokes start
 * 18 pixels out, where the widest do not overlap (blended parts of one
 * draw over each other in one plane are the depth note's business). */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static void fan(float cx, float cy, float width)
{
    glLineWidth(width);
    glBegin(GL_LINES);
    for (int i = 0; i < 12; i++) {
        double a = (i * 15.0 + 3.0) * 3.14159265358979 / 180.0;
        glColor3f(1.0f, 0.9f, 0.3f);
        glVertex2f(cx + (float)(18 * cos(a)), cy + (float)(18 * sin(a)));
        glColor3f(0.3f, 0.6f, 1.0f);
        glVertex2f(cx + (float)(45 * cos(a)), cy + (float)(45 * sin(a)));
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
    glClearColor(0.1f, 0.1f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_LINE_SMOOTH);

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    fan(55, 170, 1);
    fan(160, 170, 2);
    fan(265, 170, 3);
    glDisable(GL_BLEND);
    fan(55, 60, 1);
    fan(160, 60, 2);
    fan(265, 60, 3);
    return 0;
}

RGL_TEST_MAIN(draw)
