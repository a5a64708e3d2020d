/* edgeflag_strips.c: edge flags on strips and fans in GL_LINE and
 * GL_POINT polygon mode (issue 22). GL 2.1 2.6.2 has every edge of a
 * strip or fan a boundary edge, but Mesa flags them as it does separate
 * triangles: edge (a, b) of each triangle or quad it emits is drawn when
 * vertex a's flag is set, in its emission order (strip triangle i: i,
 * i+1, i+2, odd ones i+1, i, i+2; fan: 0, i+1, i+2; quad strip: i, i+1,
 * i+3, i+2). Top row: a triangle strip, a fan and a quad strip with
 * glEdgeFlag between their vertices; bottom row: the same from an edge
 * flag array (glDrawArrays, glDrawElements), and a strip in GL_POINT mode
 * (a vertex flagged off is not drawn). Unlit, 2-pixel lines under glOrtho
 * in pixels, the vertices off the pixel grid.
 */
#include "harness.h"

#include <raygl/gl.h>

static const GLfloat strip_v[6][2] = {{12, 10}, {22, 95}, {52, 14}, {66, 100}, {96, 12}, {108, 96}};
static const GLboolean strip_f[6] = {GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE};
static const GLfloat fan_v[6][2] = {{160, 14}, {210, 20}, {205, 60}, {185, 95}, {150, 98}, {124, 70}};
static const GLboolean fan_f[6] = {GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE};
static const GLfloat qs_v[6][2] = {{232, 12}, {236, 98}, {262, 16}, {266, 94}, {300, 12}, {306, 100}};
static const GLboolean qs_f[6] = {GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE};

static void immediate(GLenum mode, const GLfloat (*v)[2], const GLboolean *f, float dy)
{
    glBegin(mode);
    for (int k = 0; k < 6; k++) {
        glEdgeFlag(f[k]);
        glVertex2f(v[k][0], v[k][1] + dy);
    }
    glEnd();
    glEdgeFlag(GL_TRUE);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 320, 0, 240, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.37f, 0.41f, 0);
    glClearColor(0.15f, 0.15f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(2);

    glColor3f(1.0f, 0.8f, 0.2f);
    immediate(GL_TRIANGLE_STRIP, strip_v, strip_f, 125);
    glColor3f(0.3f, 0.9f, 1.0f);
    immediate(GL_TRIANGLE_FAN, fan_v, fan_f, 125);
    glColor3f(1.0f, 0.4f, 0.7f);
    immediate(GL_QUAD_STRIP, qs_v, qs_f, 125);

    /* The same from arrays: a strip by glDrawArrays, a fan by
     * glDrawElements (indices 0..5 in order). */
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glColor3f(1.0f, 0.8f, 0.2f);
    glVertexPointer(2, GL_FLOAT, 0, strip_v);
    glEdgeFlagPointer(0, strip_f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 6);
    static const GLubyte idx[6] = {0, 1, 2, 3, 4, 5};
    glColor3f(0.3f, 0.9f, 1.0f);
    glVertexPointer(2, GL_FLOAT, 0, fan_v);
    glEdgeFlagPointer(0, fan_f);
    glDrawElements(GL_TRIANGLE_FAN, 6, GL_UNSIGNED_BYTE, idx);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);

    /* GL_POINT: the quad strip's vertices flagged on. */
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(6);
    glColor3f(1.0f, 0.4f, 0.7f);
    immediate(GL_QUAD_STRIP, qs_v, qs_f, 0);
    return 0;
}

RGL_TEST_MAIN(draw)
