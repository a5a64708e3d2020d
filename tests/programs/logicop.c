/* logicop.c: glLogicOp with GL_COLOR_LOGIC_OP (issue 22), unlit bands
 * under gluOrtho2D, one op each. Left of x 200 the bands cross opaque
 * bars drawn before them: the ops of the source alone (GL_CLEAR, GL_SET,
 * GL_COPY, GL_COPY_INVERTED smooth-shaded, GL_NOOP). Right of it over the
 * clear colour, whose value the ops read there: GL_XOR, GL_INVERT, GL_AND,
 * GL_OR, GL_EQUIV, GL_NAND, a GL_XOR triangle strip, GL_XOR points and
 * GL_AND_REVERSE lines. Blending is on throughout: GL ignores it while the
 * logic op is enabled. 0.9 and 0.1 are half steps of 8 bits: the ops see
 * the bytes Mesa rounds them to in single precision (230, 26). */
#include "harness.h"

#include <raygl/gl.h>

static void rect(float x0, float y0, float x1, float y1, int smooth)
{
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        if (smooth)
            glColor3f(k == 0 || k == 3 ? 0.9f : 0.2f, 0.6f, k == 0 || k == 3 ? 0.1f : 0.8f);
        glVertex2f(k == 0 || k == 3 ? x0 : x1, k < 2 ? y0 : y1);
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
    glClearColor(0.2f, 0.35f, 0.6f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    static const float bars[3][3] = {{0.8f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.3f}, {0.9f, 0.9f, 0.85f}};
    for (int i = 0; i < 3; i++) {
        glColor3fv(bars[i]);
        rect(20.0f + 60 * i, 6, 60.0f + 60 * i, 234, 0);
    }
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_COLOR_LOGIC_OP);
    glColor4f(0.9f, 0.6f, 0.1f, 0.5f);
    static const GLenum source[5] = {GL_CLEAR, GL_SET, GL_COPY, GL_COPY_INVERTED, GL_NOOP};
    for (int i = 0; i < 5; i++) {
        glLogicOp(source[i]);
        rect(10, 10.0f + 24 * i, 200, 28.0f + 24 * i, source[i] == GL_COPY_INVERTED);
    }
    static const GLenum dest[6] = {GL_XOR, GL_INVERT, GL_AND, GL_OR, GL_EQUIV, GL_NAND};
    for (int i = 0; i < 6; i++) {
        glLogicOp(dest[i]);
        rect(210, 10.0f + 24 * i, 310, 28.0f + 24 * i, 0);
    }
    /* A strip of four triangles, flat-shaded colours per triangle. */
    glLogicOp(GL_XOR);
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLE_STRIP);
    for (int k = 0; k < 6; k++) {
        glColor3f(0.3f + 0.1f * k, 0.8f - 0.1f * k, 0.4f);
        glVertex2f(212.0f + 19 * k, k % 2 ? 180 : 156);
    }
    glEnd();
    glShadeModel(GL_SMOOTH);
    glColor3f(0.1f, 0.9f, 0.7f);
    glPointSize(6);
    glBegin(GL_POINTS);
    for (int k = 0; k < 5; k++)
        glVertex2f(216.0f + 20 * k, 194);
    glEnd();
    glLogicOp(GL_AND_REVERSE);
    glLineWidth(3);
    glBegin(GL_LINES);
    glVertex2f(212, 212);
    glVertex2f(308, 218);
    glVertex2f(212, 226);
    glVertex2f(308, 230);
    glEnd();
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_BLEND);
    return 0;
}

RGL_TEST_MAIN(draw)
