/* conf_blend_equation.c: glBlendEquation and the constant colour. Over
 * four bars, rectangles blended with GL_MIN, GL_MAX, GL_FUNC_SUBTRACT and
 * GL_FUNC_REVERSE_SUBTRACT (factors GL_ONE, GL_ONE), then with
 * glBlendColor and the factors (GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR)
 * and (GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA). Unlit, window
 * pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.1f);
    static const float bar[4][3] = {{0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.3f, 0.3f, 0.9f},
                                    {0.7f, 0.7f, 0.7f}};
    for (int b = 0; b < 4; b++) {
        glColor3fv(bar[b]);
        conf_box(0, 16 + 56 * b, w, 56 + 56 * b, 0.0f);
    }
    glEnable(GL_BLEND);
    static const GLenum eq[4] = {GL_MIN, GL_MAX, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT};
    glBlendFunc(GL_ONE, GL_ONE);
    int cw = w / 6;
    for (int i = 0; i < 4; i++) {
        glBlendEquation(eq[i]);
        glColor4f(0.5f, 0.45f, 0.6f, 1.0f);
        conf_box(i * cw + 5, 6, (i + 1) * cw - 5, 234, 0.0f);
    }
    glBlendEquation(GL_FUNC_ADD);
    glBlendColor(0.2f, 0.6f, 0.9f, 0.3f);
    glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR);
    glColor3f(0.9f, 0.9f, 0.2f);
    conf_box(4 * cw + 5, 6, 5 * cw - 5, 234, 0.0f);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    conf_box(5 * cw + 5, 6, 6 * cw - 5, 234, 0.0f);
    glDisable(GL_BLEND);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
