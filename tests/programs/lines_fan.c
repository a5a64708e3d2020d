/* lines_fan.c: 1-pixel lines as real programs draw them, in window pixels
 * (gluOrtho2D over the whole window) with no care for where pixel centres
 * are: a fan from one point at every 5 degrees (45 degrees and the axes
 * among them), axis-aligned lines on pixel centres and on pixel edges,
 * lines whose ends sit exactly on pixel centres, corners or edges, and
 * very short lines (a fifth of a pixel to two pixels) at many sub-pixel
 * places. GL lights the pixels whose diamonds the lines leave (GL 2.1
 * 3.4.1); the translation must light the same ones, to the pixel. */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

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

    /* The fan: 72 spokes around (80, 120), alternating colours, from 18
     * pixels out (nearer the hub neighbours overlap, and which of two
     * overlapping lines of one draw shows is the note's business). */
    glBegin(GL_LINES);
    for (int i = 0; i < 72; i++) {
        double a = i * 5.0 * 3.14159265358979 / 180.0;
        glColor3f(i % 3 == 0 ? 1.0f : 0.3f, i % 3 == 1 ? 1.0f : 0.4f, i % 3 == 2 ? 1.0f : 0.5f);
        glVertex2f((float)(80 + 18 * cos(a)), (float)(120 + 18 * sin(a)));
        glVertex2f((float)(80 + 70 * cos(a)), (float)(120 + 70 * sin(a)));
    }
    glEnd();

    /* Axis-aligned: on pixel centres (x.5) and on pixel edges (x.0). */
    glColor3f(1, 1, 0.3f);
    glBegin(GL_LINES);
    for (int i = 0; i < 6; i++) {
        float y = 10.0f + 4.0f * (float)i + (i % 2 ? 0.5f : 0.0f);
        glVertex2f(170, y);
        glVertex2f(250.0f + (float)i, y);
        float x = 260.0f + 4.0f * (float)i + (i % 2 ? 0.0f : 0.5f);
        glVertex2f(x, 10);
        glVertex2f(x, 60.0f + (float)i);
    }
    glEnd();

    /* Ends on pixel centres, corners and edges, at several slopes. */
    glColor3f(0.4f, 1, 1);
    glBegin(GL_LINES);
    static const float ends[4][2] = {{0.5f, 0.5f}, {0, 0}, {0.5f, 0}, {0, 0.5f}};
    for (int e = 0; e < 4; e++)
        for (int s = 0; s < 6; s++) {
            float x0 = 170.0f + 35.0f * (float)e + ends[e][0], y0 = 80.0f + ends[e][1];
            float dx = (float)(s < 3 ? 30 : 10 + 4 * s), dy = (float)(s < 3 ? 4 + 12 * s : 30);
            glVertex2f(x0 + (float)s, y0 + (float)(s * 2));
            glVertex2f(x0 + (float)s + dx, y0 + (float)(s * 2) + dy);
        }
    glEnd();

    /* Short lines: lengths 0.2 to 2 pixels, all directions, every quarter
     * and tenth of a pixel. */
    glColor3f(1, 0.5f, 1);
    glBegin(GL_LINES);
    for (int j = 0; j < 10; j++)
        for (int i = 0; i < 28; i++) {
            double len = 0.2 + 0.2 * (i % 10), a = (i * 37 + j * 11) * 3.14159265358979 / 90.0;
            float x = 170.0f + 5.3f * (float)i + 0.25f * (float)(j % 4);
            float y = 150.0f + 8.1f * (float)j + 0.1f * (float)(i % 10);
            glVertex2f(x, y);
            glVertex2f((float)(x + len * cos(a)), (float)(y + len * sin(a)));
        }
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
