/* scissor_stencil_clear.c: glClear(GL_STENCIL_BUFFER_BIT) under the
 * scissor test clears only the box (GL 2.1 4.2.3; issue 22). Three panels
 * under glOrtho in pixels, unlit, each a green quad drawn last with
 * glStencilFunc(GL_EQUAL, ...): left, a scissored clear to 1 of an
 * untouched buffer (the quad shows in the box alone); middle, a red quad
 * that set 1 everywhere it covers, then a scissored clear to 0 (the quad
 * shows where the red one was, but for the box); right, a red quad
 * setting 1, then a scissored clear to 1 of a box reaching beyond it (the
 * quad shows over both). */
#include "harness.h"

#include <raygl/gl.h>

static void rect(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
    glEnd();
}

static void scissored_clear(int x, int y, int w, int h, int value)
{
    glClearStencil(value);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, w, h);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

static void green_where(int value, float x0)
{
    glStencilFunc(GL_EQUAL, value, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor3f(0.2f, 0.8f, 0.3f);
    rect(x0, 20, x0 + 90, 220);
}

static void red_sets_one(float x0)
{
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor3f(0.8f, 0.2f, 0.2f);
    rect(x0 + 10, 40, x0 + 80, 200);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.25f, 0.25f, 0);
    glClearColor(0.2f, 0.25f, 0.3f, 1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);

    scissored_clear(30, 60, 50, 80, 1);
    green_where(1, 10);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);

    red_sets_one(115);
    scissored_clear(140, 90, 40, 60, 0);
    green_where(1, 115);
    glClear(GL_STENCIL_BUFFER_BIT);

    red_sets_one(220);
    scissored_clear(260, 100, 60, 50, 1);
    green_where(1, 220);
    glDisable(GL_STENCIL_TEST);
    return 0;
}

RGL_TEST_MAIN(draw)
