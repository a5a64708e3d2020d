/* conf_viewport_scissor.c: glViewport and glScissor changed between the
 * draws of one frame. A frame of four bars in the whole window first (so
 * the first draw's viewport is the window's: conf_viewport_split starts in
 * a quadrant), then four viewports (the quadrants, then one in the
 * middle over them), each with its own projection: a perspective
 * triangle, an orthographic fan, a gluOrtho2D quad, a frustum whose aspect
 * differs from its viewport's, and a middle viewport that clears nothing
 * and draws a rectangle reaching past its edges (cut at them). Then, in
 * the whole window again, a rectangle drawn with the scissor box at the
 * upper left, another with the box moved to the lower right, and one after
 * the scissor test is turned off. Unlit. */
#include "harness.h"

#include <math.h>
#include <raygl/gl.h>

static void tri(float z)
{
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.2f, 0.2f);
    glVertex3f(-1.0f, -0.8f, z);
    glColor3f(0.2f, 0.9f, 0.2f);
    glVertex3f(1.0f, -0.7f, z);
    glColor3f(0.2f, 0.2f, 0.9f);
    glVertex3f(0.1f, 0.9f, z);
    glEnd();
}

static int draw(int w, int h)
{
    int hw = w / 2, hh = h / 2;
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glViewport(0, 0, w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (double)w, 0.0, (double)h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(0.35f, 0.35f, 0.4f);
    glBegin(GL_QUADS);
    for (int i = 0; i < 2; i++) {
        float y = i ? (float)hh - 2.75f : 0.25f, x = i ? (float)hw - 2.75f : 0.25f;
        glVertex2f(0.25f, y);
        glVertex2f((float)w - 0.75f, y);
        glVertex2f((float)w - 0.75f, y + 3.0f);
        glVertex2f(0.25f, y + 3.0f);
        glVertex2f(x, 0.25f);
        glVertex2f(x + 3.0f, 0.25f);
        glVertex2f(x + 3.0f, (float)h - 0.75f);
        glVertex2f(x, (float)h - 0.75f);
    }
    glEnd();

    glViewport(0, hh, hw, hh);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)hw / hh, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    tri(-2.5f);

    glViewport(hw, hh, hw, hh);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.0, 2.0, -1.5, 1.5, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(0.9f, 0.9f, 0.3f);
    glVertex2f(0.01f, 0.01f);
    for (int i = 0; i <= 6; i++) {
        float a = 0.9f * (float)i;
        glColor3f(0.3f + 0.1f * (float)i, 0.5f, 0.9f - 0.1f * (float)i);
        glVertex2f(1.3f * cosf(a) + 0.01f, 1.1f * sinf(a) + 0.01f);
    }
    glEnd();

    glViewport(0, 0, hw, hh);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (double)hw, 0.0, (double)hh);
    glMatrixMode(GL_MODELVIEW);
    glColor3f(0.3f, 0.8f, 0.8f);
    glBegin(GL_QUADS);
    glVertex2f(20.25f, 15.25f);
    glVertex2f(140.25f, 25.25f);
    glVertex2f(120.25f, 100.25f);
    glVertex2f(30.25f, 90.25f);
    glEnd();

    glViewport(hw, 0, hw, hh);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    tri(-2.0f);

    glViewport(hw / 2, hh / 2, hw, hh);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 1.0, 0.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glColor3f(0.8f, 0.5f, 0.9f);
    glBegin(GL_QUADS);
    glVertex2f(-0.2f, 0.3f);
    glVertex2f(1.3f, 0.3f);
    glVertex2f(1.3f, 0.6f);
    glVertex2f(-0.2f, 0.6f);
    glEnd();

    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (double)w, 0.0, (double)h);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, h - 60, 100, 50);
    glColor3f(1.0f, 0.6f, 0.1f);
    glBegin(GL_QUADS);
    glVertex2f(5.25f, (float)h - 35.75f);
    glVertex2f((float)w - 5.75f, (float)h - 35.75f);
    glVertex2f((float)w - 5.75f, (float)h - 25.75f);
    glVertex2f(5.25f, (float)h - 25.75f);
    glEnd();
    glScissor(w - 110, 10, 100, 50);
    glColor3f(0.1f, 1.0f, 0.6f);
    glBegin(GL_QUADS);
    glVertex2f(5.25f, 30.25f);
    glVertex2f((float)w - 5.75f, 30.25f);
    glVertex2f((float)w - 5.75f, 40.25f);
    glVertex2f(5.25f, 40.25f);
    glEnd();
    glDisable(GL_SCISSOR_TEST);
    glColor3f(0.9f, 0.9f, 0.9f);
    glBegin(GL_QUADS);
    glVertex2f(150.25f, 5.25f);
    glVertex2f(170.25f, 5.25f);
    glVertex2f(170.25f, (float)h - 5.75f);
    glVertex2f(150.25f, (float)h - 5.75f);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
