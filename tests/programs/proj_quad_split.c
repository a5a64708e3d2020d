/* proj_quad_split.c: which diagonal GL splits a quad along.
 *
 * Each quad has white corners v0, v2 and dark corners v1, v3, so the split
 * diagonal shows as a white or a dark ridge. Mesa splits a quad drawn
 * immediately along v0-v2, and one called from a display list or clipped
 * along v1-v3
 * (it compiles the list's quads into triangles (v0,v1,v3)(v1,v2,v3)); a
 * GL_COMPILE_AND_EXECUTE list runs as immediate calls while it is defined.
 * Covers: glBegin quads, quads from glCallList, from glDrawArrays in a
 * list, from GL_COMPILE_AND_EXECUTE, a quad strip and a polygon in a list
 * (those split as drawn immediately), and a quad crossing the window's
 * edge (Mesa's clipper splits it along v1-v3).
 */
#include "harness.h"

#include <raygl/gl.h>

static void quad(GLenum mode, float x, float y)
{
    static const float p[4][2] = {{0, 0}, {90, 4}, {86, 96}, {3, 92}};
    static const float c[4] = {1.0f, 0.1f, 1.0f, 0.15f};
    static const int strip[4] = {0, 1, 3, 2};
    glBegin(mode);
    for (int i = 0; i < 4; i++) {
        int k = mode == GL_QUAD_STRIP ? strip[i] : i;
        glColor3f(c[k], c[k] * 0.8f, c[k] * 0.5f);
        glVertex2f(x + p[k][0], y + p[k][1]);
    }
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.2f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);

    quad(GL_QUADS, 8, 130);

    GLuint l = glGenLists(4);
    glNewList(l, GL_COMPILE);
    quad(GL_QUADS, 112, 130);
    glEndList();
    glCallList(l);

    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    quad(GL_QUADS, 216, 130);
    glEndList();

    static const float ap[4][2] = {{8, 12}, {98, 16}, {94, 108}, {11, 104}};
    static const float ac[4][3] = {{1, 1, 1}, {0.1f, 0.3f, 0}, {1, 1, 1}, {0, 0.2f, 0.1f}};
    glNewList(l + 2, GL_COMPILE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, ap);
    glColorPointer(3, GL_FLOAT, 0, ac);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glEndList();
    glCallList(l + 2);

    glNewList(l + 3, GL_COMPILE);
    quad(GL_QUAD_STRIP, 112, 14);
    quad(GL_POLYGON, 204, 14);
    glEndList();
    glCallList(l + 3);

    /* Partly outside the view volume: Mesa clips it, and its clipper
     * splits quads along v1-v3 too. */
    quad(GL_QUADS, 296, 14);
    return 0;
}

RGL_TEST_MAIN(draw)
