/* conf_depth_func.c: every glDepthFunc. Eight columns, one function each
 * (GL_NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS): a
 * grey bar at window depth 0.5 drawn with GL_LESS, then with the column's
 * function a red rectangle nearer (depth 0.25) and a blue one farther
 * (0.75), each half over the bar and half over the cleared depth 1. GL
 * draws each half where its depth passes against what is there: e.g.
 * GL_GREATER shows the blue half over the bar only, GL_NOTEQUAL all four
 * halves, GL_NEVER and GL_EQUAL none. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    static const GLenum funcs[8] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    conf_pixels(w, h, 0.1f, 0.1f, 0.15f);
    glEnable(GL_DEPTH_TEST);
    int cw = w / 8;
    for (int i = 0; i < 8; i++) {
        int x = i * cw;
        glDepthFunc(GL_LESS);
        glColor3f(0.6f, 0.6f, 0.6f);
        conf_box(x + 3, h / 4, x + cw - 3, 3 * h / 4, 0.0f);
        glDepthFunc(funcs[i]);
        glColor3f(0.9f, 0.2f, 0.2f);
        conf_box(x + 8, h / 4 - 30, x + cw - 8, h / 4 + 30, 0.5f);
        glColor3f(0.2f, 0.3f, 0.9f);
        conf_box(x + 8, 3 * h / 4 - 30, x + cw - 8, 3 * h / 4 + 30, -0.5f);
    }
    glDepthFunc(GL_LESS);
    return 0;
}

RGL_TEST_MAIN(draw)
