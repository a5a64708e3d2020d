/* conf_color_mask.c: glColorMask with some channels off. Over a
 * background of four coloured bands, white rectangles drawn with only
 * red, only green, only blue, red and blue, and none of the channels
 * enabled, and a black one with only green enabled: each leaves the
 * masked channels of the bands as they were. Then a rectangle drawn with
 * the alpha channel alone masked (no change to the colour). Unlit, window
 * pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.2f, 0.2f, 0.2f);
    static const float band[4][3] = {
        {0.8f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.3f}, {0.3f, 0.3f, 0.8f}, {0.5f, 0.5f, 0.5f}};
    for (int i = 0; i < 4; i++) {
        glColor3fv(band[i]);
        conf_box(0, 20 + 50 * i, w, 60 + 50 * i, 0.0f);
    }
    static const GLboolean masks[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                          {1, 0, 1}, {0, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 6; i++) {
        glColorMask(masks[i][0], masks[i][1], masks[i][2], GL_TRUE);
        if (i == 5)
            glColor3f(0.0f, 0.0f, 0.0f);
        else
            glColor3f(1.0f, 1.0f, 1.0f);
        conf_box(8 + 44 * i, 10, 44 + 44 * i, 230, 0.0f);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glColor3f(0.9f, 0.9f, 0.2f);
    conf_box(276, 10, 312, 230, 0.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
