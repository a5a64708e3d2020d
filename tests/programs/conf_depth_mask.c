/* conf_depth_mask.c: glDepthMask. With the mask off a near rectangle
 * writes no depth: a farther one drawn after it with the mask on covers
 * it. A third rectangle, between them in depth, covers the far one and,
 * where the far one is not, the near one too (nothing of the near one is
 * in the depth buffer). Right half: the mask off for a whole second scene
 * drawn far to near, then a rectangle behind all of it drawn last with the
 * mask on covers everything it overlaps. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.12f, 0.1f, 0.1f);
    glEnable(GL_DEPTH_TEST);
    int hw = w / 2;
    glDepthMask(GL_FALSE);
    glColor3f(0.9f, 0.3f, 0.2f);
    conf_box(10, 30, hw - 40, 150, 0.8f);
    glDepthMask(GL_TRUE);
    glColor3f(0.2f, 0.7f, 0.3f);
    conf_box(40, 90, hw - 10, 210, -0.8f);
    glColor3f(0.3f, 0.4f, 0.9f);
    conf_box(25, 10, 90, 230, 0.0f);

    glDepthMask(GL_FALSE);
    for (int i = 0; i < 4; i++) {
        glColor3f(0.3f + 0.2f * (float)i, 0.8f - 0.15f * (float)i, 0.4f);
        conf_box(hw + 10 + 25 * i, 20 + 30 * i, hw + 80 + 25 * i, 110 + 30 * i, -0.5f + 0.3f * (float)i);
    }
    glDepthMask(GL_TRUE);
    glColor3f(0.8f, 0.8f, 0.8f);
    conf_box(hw + 50, 60, w - 20, 140, -0.95f);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
