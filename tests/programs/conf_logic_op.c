/* conf_logic_op.c: glLogicOp on colour bars. Over four vertical bars,
 * one rectangle a row under GL_COLOR_LOGIC_OP with GL_XOR, GL_AND,
 * GL_OR, GL_INVERT, GL_COPY_INVERTED, GL_NOR, GL_EQUIV and GL_CLEAR, and a
 * glCopyPixels of the XOR row under GL_XOR. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.0f, 0.0f, 0.0f);
    static const float bar[4][3] = {{1.0f, 0.4f, 0.2f}, {0.2f, 0.8f, 0.4f}, {0.3f, 0.3f, 1.0f},
                                    {0.8f, 0.8f, 0.8f}};
    for (int b = 0; b < 4; b++) {
        glColor3fv(bar[b]);
        conf_box(8 + 64 * b, 4, 64 + 64 * b, 236, 0.0f);
    }
    static const GLenum ops[8] = {GL_XOR, GL_AND, GL_OR, GL_INVERT, GL_COPY_INVERTED, GL_NOR,
                                  GL_EQUIV, GL_CLEAR};
    glEnable(GL_COLOR_LOGIC_OP);
    for (int i = 0; i < 8; i++) {
        glLogicOp(ops[i]);
        glColor3f(0.6f, 0.5f, 0.2f + 0.1f * (float)i);
        conf_box(4, 8 + 26 * i, 292, 28 + 26 * i, 0.0f);
    }
    glLogicOp(GL_XOR);
    glRasterPos2i(292, 8);
    glCopyPixels(100, 8, 28, 20, GL_COLOR);
    glDisable(GL_COLOR_LOGIC_OP);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
