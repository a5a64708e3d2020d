/* conf_arrays_quad_split.c: which diagonal GL splits an array-drawn quad
 * along. Quads with white v0 and v2 corners and dark v1 and v3 ones show
 * the split as a white or a dark ridge. Drawn with glDrawArrays, with
 * glDrawElements (GL_UNSIGNED_BYTE, _SHORT, _INT indices),
 * glDrawRangeElements, glMultiDrawArrays, glMultiDrawElements and
 * glArrayElement between glBegin and glEnd, and a GL_QUAD_STRIP through
 * glDrawElements; all wholly in view. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

#define N 9

static GLfloat pos[N][4][2];
static GLubyte col[N][4][3];

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.2f, 0.1f, 0.1f);
    for (int q = 0; q < N; q++) {
        float x0 = 8.25f + 103.0f * (float)(q % 3), y0 = 8.25f + 78.0f * (float)(q / 3);
        const float xs[4] = {x0, x0 + 96, x0 + 96, x0}, ys[4] = {y0, y0, y0 + 70, y0 + 70};
        for (int k = 0; k < 4; k++) {
            pos[q][k][0] = xs[k];
            pos[q][k][1] = ys[k];
            GLubyte c = k % 2 == 0 ? 240 : 30;
            col[q][k][0] = c;
            col[q][k][1] = c;
            col[q][k][2] = (GLubyte)(k % 2 == 0 ? 240 : 90);
        }
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, col);
    glDrawArrays(GL_QUADS, 0, 4);
    const GLubyte ub[4] = {4, 5, 6, 7};
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, ub);
    const GLushort us[4] = {8, 9, 10, 11};
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_SHORT, us);
    const GLuint ui[4] = {12, 13, 14, 15};
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, ui);
    const GLuint ur[4] = {16, 17, 18, 19};
    glDrawRangeElements(GL_QUADS, 16, 19, 4, GL_UNSIGNED_INT, ur);
    const GLint first[1] = {20};
    const GLsizei count[1] = {4};
    glMultiDrawArrays(GL_QUADS, first, count, 1);
    const GLushort me[4] = {24, 25, 26, 27};
    const GLvoid *mi[1] = {me};
    glMultiDrawElements(GL_QUADS, count, GL_UNSIGNED_SHORT, mi, 1);
    glBegin(GL_QUADS);
    for (int k = 28; k < 32; k++)
        glArrayElement(k);
    glEnd();
    /* As a strip: 32 33 35 34 in strip order is the quad 32 33 34 35. */
    const GLushort st[4] = {32, 33, 35, 34};
    glDrawElements(GL_QUAD_STRIP, 4, GL_UNSIGNED_SHORT, st);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    return 0;
}

RGL_TEST_MAIN(draw)
