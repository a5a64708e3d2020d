/* conf_alpha_func.c: every glAlphaFunc against one reference (0.6). Eight
 * columns, one function each (GL_NEVER, LESS, EQUAL, LEQUAL, GREATER,
 * NOTEQUAL, GEQUAL, ALWAYS), each with three rectangles of alpha 0.3, 0.6
 * and 0.9 (blending off, so a kept fragment is opaque): GL keeps the
 * rectangles whose alpha passes against 0.6, the one of alpha 0.6 under
 * GL_EQUAL, GL_LEQUAL and GL_GEQUAL. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    static const GLenum funcs[8] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const float alpha[3] = {0.3f, 0.6f, 0.9f};
    conf_pixels(w, h, 0.1f, 0.1f, 0.15f);
    glEnable(GL_ALPHA_TEST);
    int cw = w / 8;
    for (int i = 0; i < 8; i++) {
        glAlphaFunc(funcs[i], 0.6f);
        for (int k = 0; k < 3; k++) {
            glColor4f(0.3f + 0.3f * (float)k, 0.8f - 0.25f * (float)k, 0.3f + 0.2f * (float)i / 7.0f,
                      alpha[k]);
            conf_box(i * cw + 4, 20 + 72 * k, (i + 1) * cw - 4, 80 + 72 * k, 0.0f);
        }
    }
    glDisable(GL_ALPHA_TEST);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
