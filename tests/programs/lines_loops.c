/* lines_loops.c: circles as GL_LINE_LOOP of many short segments (radius
 * 3 to 60 pixels, 12 to 96 sides), a spiral GL_LINE_STRIP, and the same
 * circles turned in perspective, as plotting and teaching programs draw
 * them: centred on whole coordinates, no offset. Each segment lights the
 * pixels its own diamond-exit rule gives (the strip's ends meet there). */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static void circle(float cx, float cy, float r, int n)
{
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < n; i++) {
        double a = 2 * 3.14159265358979 * i / n;
        glVertex2f((float)(cx + r * cos(a)), (float)(cy + r * sin(a)));
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
    glClearColor(0.05f, 0.05f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    static const float rad[8] = {3, 5, 8, 12, 18, 26, 40, 60};
    static const int sides[8] = {12, 16, 24, 32, 48, 64, 80, 96};
    for (int i = 0; i < 8; i++) {
        glColor3f(1.0f - 0.1f * (float)i, 0.4f + 0.07f * (float)i, 0.3f);
        circle(80, 120, rad[i], sides[i]);
    }
    for (int i = 0; i < 6; i++) {
        glColor3f(0.3f, 1, 0.5f);
        circle(170.0f + 12.0f * (float)i, 20.0f + 3.0f * (float)i, 2.0f + (float)i, 10 + 2 * i);
    }

    /* A spiral strip: ever shorter segments toward its centre. */
    glColor3f(1, 1, 0.4f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 400; i++) {
        double a = i * 0.08, r = 1 + i * 0.11;
        glVertex2f((float)(250 + r * cos(a)), (float)(70 + r * sin(a)));
    }
    glEnd();

    /* The same circles turned in perspective. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, (double)w / h, 1, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(1.6f, 0.9f, -6);
    glRotatef(60, 1, 0, 0);
    glRotatef(20, 0, 1, 0);
    glScalef(0.02f, 0.02f, 0.02f);
    for (int i = 0; i < 8; i++) {
        glColor3f(0.4f, 0.6f + 0.05f * (float)i, 1);
        circle(0, 0, rad[i], sides[i]);
    }
    return 0;
}

RGL_TEST_MAIN(draw)
