/* conf_clear_depth_mask.c: glClear of the depth buffer under
 * glDepthMask(GL_FALSE), which clears nothing (the mask applies to
 * clears). A near rectangle drawn; the mask off, glClear(GL_DEPTH_BUFFER_BIT)
 * and the mask on again; then a farther rectangle drawn over it stays
 * behind it. (conf_clear_depth: the same clear unmasked.) Unlit, window
 * pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.12f, 0.1f);
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.9f, 0.3f, 0.2f);
    conf_box(20, 40, 160, 200, 0.6f);
    glDepthMask(GL_FALSE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDepthMask(GL_TRUE);
    glColor3f(0.2f, 0.8f, 0.3f);
    conf_box(100, 20, 240, 150, 0.2f);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
