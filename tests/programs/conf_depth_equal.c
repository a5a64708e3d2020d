/* conf_depth_equal.c: multipass drawing with GL_EQUAL and GL_LEQUAL. A
 * first pass draws three overlapping rectangles at different depths with
 * GL_LESS; a second pass draws the same rectangles again (the same
 * vertices, so the same window depths) in lighter colours with GL_EQUAL
 * (left) or GL_LEQUAL (right): only the visible part of each shows the
 * second colour, the parts the nearer ones hide keep nothing of it. Then,
 * still GL_EQUAL, a rectangle nearer than all of them that GL does not
 * draw (its depth equals nothing stored), and with GL_LEQUAL one farther
 * that GL does not draw where it is behind. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static void pass(int x, int y, float light)
{
    float a = light;
    glColor3f(0.7f + 0.3f * a, 0.2f + 0.5f * a, 0.2f + 0.5f * a);
    conf_box(x, y, x + 90, y + 70, -0.6f);
    glColor3f(0.2f + 0.5f * a, 0.7f + 0.3f * a, 0.2f + 0.5f * a);
    conf_box(x + 30, y + 25, x + 120, y + 95, 0.1f);
    glColor3f(0.2f + 0.5f * a, 0.2f + 0.5f * a, 0.7f + 0.3f * a);
    conf_box(x + 60, y + 50, x + 140, y + 130, 0.4f);
}

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.05f, 0.05f, 0.05f);
    glEnable(GL_DEPTH_TEST);
    int x0 = 8, x1 = w / 2 + 8, y = 50;
    glDepthFunc(GL_LESS);
    pass(x0, y, 0.0f);
    pass(x1, y, 0.0f);
    glDepthFunc(GL_EQUAL);
    pass(x0, y, 1.0f);
    glColor3f(1.0f, 1.0f, 0.0f);
    conf_box(x0 + 10, y + 10, x0 + 50, y + 110, 0.8f);
    glDepthFunc(GL_LEQUAL);
    pass(x1, y, 1.0f);
    glColor3f(1.0f, 0.0f, 1.0f);
    conf_box(x1 + 10, y + 10, x1 + 150, y + 40, -0.9f);
    glDepthFunc(GL_LESS);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
