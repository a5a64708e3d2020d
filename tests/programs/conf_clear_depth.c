/* conf_clear_depth.c: glClear(GL_DEPTH_BUFFER_BIT) in the middle of a
 * frame, as a program that draws a first-person weapon or an overlay model
 * over its scene does: near rectangles drawn, the depth buffer cleared
 * alone (the colours stay), then farther rectangles drawn over them,
 * which now cover them. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.12f, 0.1f);
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.9f, 0.3f, 0.2f);
    conf_box(20, 40, 160, 200, 0.6f);
    glColor3f(0.9f, 0.8f, 0.2f);
    conf_box(180, 40, 300, 200, 0.3f);
    glClear(GL_DEPTH_BUFFER_BIT);
    glColor3f(0.2f, 0.8f, 0.3f);
    conf_box(100, 20, 240, 150, -0.2f);
    glColor3f(0.3f, 0.4f, 0.9f);
    conf_box(140, 90, 300, 220, -0.6f);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
