/* shapes_edge_flags.c: edge flags and thin lines (OSMesa). Polygons in
 * GL_LINE mode whose inner edges are flagged GL_FALSE (glEdgeFlag): GL
 * draws only the flagged edges, the outline of a hexagon split into
 * triangles and of a quad strip; with glEdgeFlagPointer arrays too. Then
 * 1-pixel lines at many slopes, a line loop and a strip (issue 14,
 * "thin lines and edge flags"). Unlit, glOrtho in pixels, the lines off
 * the pixel grid's edges. */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static void hexagon(float cx, float cy, float r)
{
    /* Six triangles around the centre: only the outer edge of each is
     * flagged (edge from its second to its third vertex). */
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; i++) {
        float a0 = (float)i * 1.0471976f + 0.2f, a1 = a0 + 1.0471976f;
        glEdgeFlag(GL_FALSE);
        glVertex2f(cx, cy);
        glEdgeFlag(GL_TRUE);
        glVertex2f(cx + r * cosf(a0), cy + r * sinf(a0));
        glEdgeFlag(GL_FALSE);
        glVertex2f(cx + r * cosf(a1), cy + r * sinf(a1));
    }
    glEnd();
    glEdgeFlag(GL_TRUE);
}

static void quads(float x, float y)
{
    /* Two quads side by side: the shared edge is flagged off on both. */
    glBegin(GL_QUADS);
    glEdgeFlag(GL_TRUE);
    glVertex2f(x, y);
    glEdgeFlag(GL_FALSE);
    glVertex2f(x + 40.3f, y + 3.1f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(x + 38.2f, y + 50.4f);
    glVertex2f(x - 2.1f, y + 47.6f);

    glVertex2f(x + 40.3f, y + 3.1f);
    glVertex2f(x + 81.7f, y + 6.3f);
    glVertex2f(x + 79.4f, y + 53.2f);
    glEdgeFlag(GL_FALSE);
    glVertex2f(x + 38.2f, y + 50.4f);
    glEnd();
    glEdgeFlag(GL_TRUE);
}

static void arrays(float x, float y)
{
    static GLfloat v[4][2];
    static const GLboolean flags[4] = {GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE};
    v[0][0] = x, v[0][1] = y;
    v[1][0] = x + 60.4f, v[1][1] = y + 5.2f;
    v[2][0] = x + 50.6f, v[2][1] = y + 44.3f;
    v[3][0] = x - 4.7f, v[3][1] = y + 38.1f;
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEdgeFlagPointer(0, flags);
    glDrawArrays(GL_POLYGON, 0, 4);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1.0f, 0.8f, 0.2f);
    hexagon(60.3f, 180.3f, 45.0f);
    glColor3f(0.3f, 0.9f, 1.0f);
    quads(130.3f, 150.3f);
    glColor3f(1.0f, 0.4f, 0.8f);
    arrays(240.3f, 160.3f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    /* Thin lines: a fan of slopes, centred off the pixel grid. */
    glBegin(GL_LINES);
    for (int i = 0; i < 16; i++) {
        float a = (float)i * 0.19635f + 0.05f;
        glColor3f(0.5f + 0.03f * (float)i, 1.0f - 0.04f * (float)i, 0.4f);
        glVertex2f(80.3f + 8.0f * cosf(a), 70.3f + 8.0f * sinf(a));
        glVertex2f(80.3f + 60.0f * cosf(a), 70.3f + 60.0f * sinf(a));
    }
    glEnd();
    glColor3f(0.9f, 0.9f, 0.9f);
    glBegin(GL_LINE_LOOP);
    glVertex2f(170.3f, 20.3f);
    glVertex2f(230.6f, 35.2f);
    glVertex2f(215.1f, 110.4f);
    glVertex2f(160.2f, 90.7f);
    glEnd();
    glColor3f(0.4f, 1.0f, 0.4f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 10; i++)
        glVertex2f(245.3f + 7.1f * (float)i, 20.3f + (float)((i % 2) * 70) + 3.3f * (float)i);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
