/* conf_arrays_draw.c: the vertex-array draws. One shared array of 2D
 * positions and RGB colours (a grid of rectangles' corners), drawn with
 * glDrawElements in GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_UNSIGNED_INT
 * indices, glDrawRangeElements, glMultiDrawArrays, glMultiDrawElements,
 * glDrawArrays from a first vertex, glArrayElement between glBegin and
 * glEnd (mixed with a glVertex of its own), a colour array turned off
 * (the current colour then, as last set). Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

#define COLS 8
#define ROWS 5

static GLfloat pos[ROWS][COLS][4][2];
static GLubyte col[ROWS][COLS][4][3];

static GLuint corner(int r, int c, int k) { return (GLuint)(((r * COLS) + c) * 4 + k); }

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.1f);
    for (int r = 0; r < ROWS; r++)
        for (int c = 0; c < COLS; c++) {
            float x0 = 6.25f + 39.0f * (float)c, y0 = 6.25f + 46.0f * (float)r;
            const float xs[4] = {x0, x0 + 33, x0 + 33, x0}, ys[4] = {y0, y0, y0 + 40, y0 + 40};
            for (int k = 0; k < 4; k++) {
                pos[r][c][k][0] = xs[k];
                pos[r][c][k][1] = ys[k];
                col[r][c][k][0] = (GLubyte)(60 + 24 * c + (k == 1 ? 40 : 0));
                col[r][c][k][1] = (GLubyte)(40 + 40 * r + (k == 2 ? 50 : 0));
                col[r][c][k][2] = (GLubyte)(200 - 20 * c);
            }
        }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, col);

    GLubyte ub[8];
    GLushort us[8];
    GLuint ui[8];
    for (int k = 0; k < 4; k++) {
        ub[k] = (GLubyte)corner(0, 0, k);
        ub[4 + k] = (GLubyte)corner(0, 2, k);
        us[k] = (GLushort)corner(0, 3, k);
        us[4 + k] = (GLushort)corner(0, 5, k);
        ui[k] = corner(1, 0, k);
        ui[4 + k] = corner(1, 1, k);
    }
    glDrawElements(GL_QUADS, 8, GL_UNSIGNED_BYTE, ub);
    glDrawElements(GL_QUADS, 8, GL_UNSIGNED_SHORT, us);
    glDrawElements(GL_QUADS, 8, GL_UNSIGNED_INT, ui);
    GLuint tri[6] = {corner(1, 3, 0), corner(1, 3, 1), corner(1, 3, 2),
                     corner(1, 3, 0), corner(1, 3, 2), corner(1, 3, 3)};
    glDrawRangeElements(GL_TRIANGLES, corner(1, 3, 0), corner(1, 3, 3), 6, GL_UNSIGNED_INT, tri);

    GLint first[3] = {(GLint)corner(2, 0, 0), (GLint)corner(2, 2, 0), (GLint)corner(2, 5, 0)};
    GLsizei count[3] = {4, 4, 4};
    glMultiDrawArrays(GL_TRIANGLE_FAN, first, count, 3);
    GLushort e0[4] = {(GLushort)corner(3, 0, 0), (GLushort)corner(3, 0, 1),
                      (GLushort)corner(3, 0, 3), (GLushort)corner(3, 0, 2)};
    GLushort e1[4] = {(GLushort)corner(3, 4, 0), (GLushort)corner(3, 4, 1),
                      (GLushort)corner(3, 4, 3), (GLushort)corner(3, 4, 2)};
    const GLvoid *ei[2] = {e0, e1};
    GLsizei ec[2] = {4, 4};
    glMultiDrawElements(GL_TRIANGLE_STRIP, ec, GL_UNSIGNED_SHORT, ei, 2);
    glDrawArrays(GL_QUADS, (GLint)corner(3, 6, 0), 8);

    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++)
        glArrayElement((GLint)corner(4, 0, k));
    glArrayElement((GLint)corner(4, 2, 0));
    glArrayElement((GLint)corner(4, 2, 1));
    glArrayElement((GLint)corner(4, 2, 2));
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2fv(pos[4][2][3]); /* the colour array's last colour is replaced */
    glEnd();

    glDisableClientState(GL_COLOR_ARRAY);
    glColor3f(0.9f, 0.9f, 0.3f);
    glDrawArrays(GL_QUADS, (GLint)corner(4, 4, 0), 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    return 0;
}

RGL_TEST_MAIN(draw)
