/* polygon_mode.c: glPolygonMode GL_LINE and GL_POINT.
 *
 * Covers, with GL_FRONT_AND_BACK GL_LINE and 2-pixel lines: a triangle, a
 * quad and a convex pentagon (outlines only: the diagonals GL splits them
 * along are not edges), a triangle strip (every triangle outlined, shared
 * edges included), a polygon with one edge flagged off by glEdgeFlag (that
 * edge is not drawn). Then GL_FRONT GL_LINE with GL_BACK GL_FILL (a
 * counter-clockwise triangle outlined, a clockwise one filled) and GL_POINT
 * with 6-pixel points (a quad shows its four corners only).
 */
#include "harness.h"

#include "raygl.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.13f, 0.37f, 0.0f);

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    rayglLineWidth(2.0f);

    rayglColor3f(1.0f, 0.3f, 0.3f);
    rayglBegin(GL_TRIANGLES);
    rayglVertex2f(12, 130);
    rayglVertex2f(95, 140);
    rayglVertex2f(40, 226);
    rayglEnd();

    rayglColor3f(0.3f, 1.0f, 0.4f);
    rayglBegin(GL_QUADS);
    rayglVertex2f(112, 132);
    rayglVertex2f(200, 138);
    rayglVertex2f(192, 222);
    rayglVertex2f(118, 214);
    rayglEnd();

    rayglColor3f(0.4f, 0.6f, 1.0f);
    rayglBegin(GL_POLYGON);
    rayglVertex2f(262, 226);
    rayglVertex2f(218, 196);
    rayglVertex2f(232, 136);
    rayglVertex2f(292, 136);
    rayglVertex2f(306, 196);
    rayglEnd();

    rayglColor3f(1.0f, 0.9f, 0.3f);
    rayglBegin(GL_TRIANGLE_STRIP);
    rayglVertex2f(12, 70);
    rayglVertex2f(20, 114);
    rayglVertex2f(52, 66);
    rayglVertex2f(60, 112);
    rayglVertex2f(94, 70);
    rayglVertex2f(100, 116);
    rayglEnd();

    /* The edge from the second vertex to the third is not drawn. */
    rayglColor3f(1.0f, 0.5f, 1.0f);
    rayglBegin(GL_POLYGON);
    rayglEdgeFlag(GL_TRUE);
    rayglVertex2f(12, 12);
    rayglEdgeFlag(GL_FALSE);
    rayglVertex2f(96, 16);
    rayglEdgeFlag(GL_TRUE);
    rayglVertex2f(90, 56);
    rayglVertex2f(16, 52);
    rayglEnd();

    /* Front faces outlined, back faces filled. */
    rayglPolygonMode(GL_FRONT, GL_LINE);
    rayglPolygonMode(GL_BACK, GL_FILL);
    rayglColor3f(0.3f, 1.0f, 1.0f);
    rayglBegin(GL_TRIANGLES);
    rayglVertex2f(116, 70); /* counter-clockwise: outlined */
    rayglVertex2f(170, 74);
    rayglVertex2f(140, 118);
    rayglVertex2f(116, 14); /* clockwise: filled */
    rayglVertex2f(142, 60);
    rayglVertex2f(170, 18);
    rayglEnd();

    /* Points at the vertices only. */
    rayglPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    rayglPointSize(6.0f);
    rayglColor3f(1.0f, 1.0f, 1.0f);
    rayglBegin(GL_QUADS);
    rayglVertex2f(200, 20);
    rayglVertex2f(300, 24);
    rayglVertex2f(296, 110);
    rayglVertex2f(206, 104);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
