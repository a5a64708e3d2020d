/* conf_scissor_clear_depth.c: a scissored depth clear. Near rectangles
 * across the window; glScissor to the middle third and
 * glClear(GL_DEPTH_BUFFER_BIT) there only; then a far rectangle across
 * the window covers the near ones inside the box only. Unlit, window
 * pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.1f);
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.9f, 0.4f, 0.2f);
    conf_box(10, 120, w - 10, 220, 0.6f);
    glColor3f(0.3f, 0.8f, 0.4f);
    conf_box(10, 20, w - 10, 110, 0.4f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(w / 3, 0, w / 3, h);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColor3f(0.3f, 0.4f, 0.9f);
    conf_box(30, 60, w - 30, 180, -0.5f);
    return 0;
}

RGL_TEST_MAIN(draw)
