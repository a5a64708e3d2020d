/* conf_depth_range.c: glDepthRange. Left: a rectangle at the near end of
 * the view volume drawn under glDepthRange(0.5, 1) lies behind one at the
 * far end drawn under glDepthRange(0, 0.5). Middle: glDepthRange(1, 0)
 * reverses depth, so of two overlapping rectangles the farther one (eye z)
 * covers the nearer one whatever the order. Right: glDepthRange(0.3, 0.3)
 * puts everything at one depth: under GL_LESS the first rectangle drawn
 * keeps the overlap. Then glDepthRange(0, 1) again and a white bar across
 * all three at eye z 0 (window depth 0.5): in front of the left panel's
 * red (0.525) and behind its green (0.475); behind the middle's yellow
 * (0.3) and in front of its blue (0.8); behind both of the right panel's
 * (0.3); over the background everywhere. Unlit,
 * window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.1f);
    glEnable(GL_DEPTH_TEST);
    int pw = w / 3;

    glDepthRange(0.5, 1.0);
    glColor3f(0.9f, 0.3f, 0.2f);
    conf_box(10, 60, pw - 30, 200, 0.9f);
    glDepthRange(0.0, 0.5);
    glColor3f(0.2f, 0.7f, 0.3f);
    conf_box(30, 40, pw - 10, 170, -0.9f);

    glDepthRange(1.0, 0.0);
    glColor3f(0.9f, 0.8f, 0.2f);
    conf_box(pw + 10, 60, 2 * pw - 30, 200, -0.4f);
    glColor3f(0.3f, 0.4f, 0.9f);
    conf_box(pw + 30, 40, 2 * pw - 10, 170, 0.6f);

    glDepthRange(0.3, 0.3);
    glColor3f(0.8f, 0.3f, 0.8f);
    conf_box(2 * pw + 10, 60, w - 30, 200, 0.7f);
    glColor3f(0.3f, 0.8f, 0.8f);
    conf_box(2 * pw + 30, 40, w - 10, 170, -0.7f);

    glDepthRange(0.0, 1.0);
    glColor3f(0.95f, 0.95f, 0.95f);
    conf_box(4, 100, w - 4, 120, 0.0f);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
