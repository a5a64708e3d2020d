/* blend_funcs.c: blend functions of the source alpha other than
 * GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, unlit, over opaque vertical bars
 * and the background: premultiplied alpha (GL_ONE, GL_ONE_MINUS_SRC_ALPHA),
 * additive (GL_SRC_ALPHA, GL_ONE and GL_ONE, GL_ONE), darkening (GL_ZERO,
 * GL_ONE_MINUS_SRC_ALPHA), the reversed pair (GL_ONE_MINUS_SRC_ALPHA,
 * GL_SRC_ALPHA) and a scaled opaque one (GL_SRC_ALPHA, GL_ZERO), each a
 * horizontal band. raygl2pov maps them onto transmit (docs/mapping.md
 * section 18): exact, additive within 1/128 of the colour behind. The
 * bars lie deeper than the bands (z -0.5 in eye space), with a depth
 * test: a ray tracer does not see a surface a hair behind another.
 */
#include "harness.h"

#include <raygl/gl.h>

static void rect(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.25f, 0.25f, 0);
    glClearColor(0.2f, 0.25f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    /* Opaque bars behind. */
    static const float bars[4][3] = {{0.8f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.3f}, {0.9f, 0.9f, 0.85f}, {0.1f, 0.1f, 0.1f}};
    for (int i = 0; i < 4; i++) {
        glColor3fv(bars[i]);
        rect(40.0f + 64 * i, 10, 80.0f + 64 * i, 230, -0.5f);
    }

    glEnable(GL_BLEND);
    static const struct {
        GLenum src, dst;
        float c[4];
    } bands[6] = {
        {GL_ONE, GL_ONE_MINUS_SRC_ALPHA, {0.3f, 0.1f, 0.05f, 0.5f}},
        {GL_SRC_ALPHA, GL_ONE, {0.6f, 0.3f, 0.1f, 0.5f}},
        {GL_ONE, GL_ONE, {0.15f, 0.2f, 0.35f, 1.0f}},
        {GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, {0.9f, 0.9f, 0.9f, 0.6f}},
        {GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, {0.2f, 0.4f, 0.9f, 0.3f}},
        {GL_SRC_ALPHA, GL_ZERO, {0.9f, 0.8f, 0.3f, 0.7f}},
    };
    for (int i = 0; i < 6; i++) {
        glBlendFunc(bands[i].src, bands[i].dst);
        glColor4fv(bands[i].c);
        rect(20, 20.0f + 36 * i, 300, 44.0f + 36 * i, 0.0f);
    }
    return 0;
}

RGL_TEST_MAIN(draw)
