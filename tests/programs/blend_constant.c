/* blend_constant.c: the blend colour, separate blend functions and blend
 * equations (issue 22), unlit, one horizontal band each under gluOrtho2D.
 * Left of x 200 the bands cross opaque vertical bars drawn before them
 * (deeper, depth-tested); right of it they lie over the clear colour
 * alone. Over the bars, what transmit and filter reproduce exactly:
 * GL_CONSTANT_ALPHA / GL_ONE_MINUS_CONSTANT_ALPHA, glBlendFuncSeparate
 * (the colour's factors count), the multiplying blends (GL_ZERO,
 * GL_SRC_COLOR and GL_DST_COLOR, GL_ZERO, smooth-shaded),
 * GL_FUNC_REVERSE_SUBTRACT, a grey GL_CONSTANT_COLOR, GL_ONE_MINUS_SRC_COLOR
 * as destination factor with a grey source. Over the clear colour, those
 * that read what is behind: GL_MIN, GL_MAX, a coloured GL_CONSTANT_COLOR,
 * GL_ONE_MINUS_DST_COLOR, GL_DST_ALPHA, GL_FUNC_SUBTRACT. */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

#include <raygl/gl.h>
#include <GL/glext.h>

static void rect(float x0, float y0, float x1, float y1, float z, const GLfloat (*c)[4])
{
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        if (c)
            glColor4fv(c[k]);
        glVertex3f(k == 0 || k == 3 ? x0 : x1, k < 2 ? y0 : y1, z);
    }
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
    glClearColor(0.2f, 0.35f, 0.6f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    static const float bars[3][3] = {{0.8f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.3f}, {0.9f, 0.9f, 0.85f}};
    for (int i = 0; i < 3; i++) {
        glColor3fv(bars[i]);
        rect(20.0f + 60 * i, 6, 60.0f + 60 * i, 234, -0.5f, NULL);
    }
    glEnable(GL_BLEND);
    glBlendColor(0.2f, 0.5f, 0.8f, 0.3f);
    static const GLfloat warm[4][4] = {{0.9f, 0.6f, 0.1f, 0.5f}, {0.3f, 0.8f, 0.6f, 0.5f},
                                       {0.3f, 0.8f, 0.6f, 0.5f}, {0.9f, 0.6f, 0.1f, 0.5f}};
    float y = 8;
#define BAND(x0, x1, smooth) (rect((x0), y, (x1), y + 14, 0, (smooth) ? warm : NULL), y += 19)
    glColor4f(0.9f, 0.6f, 0.1f, 0.5f);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    BAND(10, 200, 1);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    BAND(10, 200, 1);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);
    BAND(10, 200, 1);
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    BAND(10, 200, 0);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    BAND(10, 200, 0);
    glBlendEquation(GL_FUNC_ADD);
    glBlendColor(0.4f, 0.4f, 0.4f, 1);
    glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR);
    BAND(10, 200, 1);
    glColor4f(0.5f, 0.5f, 0.5f, 1);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_COLOR);
    BAND(10, 200, 0);
    /* Over the clear colour alone. */
    glColor4f(0.9f, 0.6f, 0.1f, 0.5f);
    glBlendColor(0.2f, 0.5f, 0.8f, 0.3f);
    y = 8;
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_MIN);
    BAND(210, 310, 0);
    glBlendEquation(GL_MAX);
    BAND(210, 310, 0);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR);
    BAND(210, 310, 0);
    glBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ZERO);
    BAND(210, 310, 0);
    glBlendFunc(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
    BAND(210, 310, 0);
    glBlendEquation(GL_FUNC_SUBTRACT);
    glBlendFunc(GL_ONE, GL_ONE);
    BAND(210, 310, 0);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    return 0;
}

RGL_TEST_MAIN(draw)
