/* shapes_line_stipple.c: line stipple (OSMesa). Stippled GL_LINES at many
 * slopes (the pattern restarts at each segment), a stippled line strip
 * and loop (it runs on across their segments), factors 1, 2 and 3, width
 * 1 and 2, in glOrtho pixels; then stippled lines in perspective, whose
 * dashes GL cuts in window space (issue 14, "line stipple"). Unlit. */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_LINE_STIPPLE);

    glLineStipple(1, 0x0F0F);
    glBegin(GL_LINES);
    for (int i = 0; i < 12; i++) {
        float a = (float)i * 0.2618f + 0.07f;
        glColor3f(1.0f, 0.4f + 0.05f * (float)i, 0.2f);
        glVertex2f(70.3f + 6.0f * cosf(a), 170.3f + 6.0f * sinf(a));
        glVertex2f(70.3f + 62.0f * cosf(a), 170.3f + 62.0f * sinf(a));
    }
    glEnd();

    glLineStipple(2, 0x1C47);
    glColor3f(0.3f, 0.9f, 1.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 8; i++)
        glVertex2f(150.3f + 20.1f * (float)i, 130.3f + (float)((i % 2) * 60) + 4.2f * (float)i);
    glEnd();

    glLineStipple(3, 0xAAAA);
    glLineWidth(2.0f);
    glColor3f(0.9f, 0.5f, 1.0f);
    glBegin(GL_LINE_LOOP);
    glVertex2f(180.3f, 20.3f);
    glVertex2f(300.6f, 35.2f);
    glVertex2f(285.1f, 110.4f);
    glVertex2f(170.2f, 100.7f);
    glEnd();
    glLineWidth(1.0f);

    /* Perspective: the dashes shorten in eye space with distance. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / (double)h, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLineStipple(1, 0x00FF);
    glBegin(GL_LINES);
    for (int i = 0; i < 5; i++) {
        glColor3f(0.3f, 1.0f, 0.3f + 0.15f * (float)i);
        glVertex3f(-3.0f + 0.3f * (float)i, -1.6f - 0.1f * (float)i, -3.0f);
        glVertex3f(-0.6f + 0.3f * (float)i, -0.4f - 0.1f * (float)i, -12.0f);
    }
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    return 0;
}

RGL_TEST_MAIN(draw)
