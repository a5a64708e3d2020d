/* conf_blend_factors.c: glBlendFunc factor pairs beyond the usual
 * transparency, each in a column over the same four vertical bars:
 * (GL_ZERO, GL_SRC_COLOR) and (GL_DST_COLOR, GL_ZERO) multiply source
 * and destination, (GL_ONE_MINUS_DST_COLOR, GL_ZERO) takes the source
 * times the inverted destination, (GL_ONE, GL_ONE) adds (and saturates),
 * (GL_ZERO, GL_ONE)
 * leaves everything, (GL_ONE, GL_ZERO) replaces, (GL_SRC_ALPHA_SATURATE,
 * GL_ONE) adds a fraction, (GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA) is the
 * usual mix the other way round. The source is one colour of alpha 0.4
 * per column. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    static const GLenum f[8][2] = {
        {GL_ZERO, GL_SRC_COLOR},          {GL_ONE_MINUS_DST_COLOR, GL_ZERO},
        {GL_DST_COLOR, GL_ZERO},          {GL_ONE, GL_ONE},
        {GL_ZERO, GL_ONE},                {GL_ONE, GL_ZERO},
        {GL_SRC_ALPHA_SATURATE, GL_ONE},  {GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA},
    };
    conf_pixels(w, h, 0.1f, 0.1f, 0.1f);
    static const float bar[4][3] = {
        {0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.3f, 0.3f, 0.9f}, {0.8f, 0.8f, 0.8f}};
    for (int b = 0; b < 4; b++) {
        glColor3fv(bar[b]);
        conf_box(0, 16 + 56 * b, w, 56 + 56 * b, 0.0f);
    }
    glEnable(GL_BLEND);
    int cw = w / 8;
    for (int i = 0; i < 8; i++) {
        glBlendFunc(f[i][0], f[i][1]);
        glColor4f(0.7f, 0.5f - 0.05f * (float)i, 0.2f + 0.08f * (float)i, 0.4f);
        conf_box(i * cw + 5, 6, (i + 1) * cw - 5, 234, 0.0f);
    }
    glDisable(GL_BLEND);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
