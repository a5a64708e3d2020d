/* lines.c: lines of several widths under gluOrtho2D.
 *
 * Covers glLineWidth 1..8 on horizontal, vertical and slanted lines, a wide
 * line with smooth colour from red to blue, a wide line strip and line loop
 * (GL draws each segment separately: no joins at corners), and flat-shaded
 * GL_LINES whose colour is the segment's last vertex.
 *
 * GL draws a non-antialiased line of width w as a run of w pixels across its
 * minor axis (a horizontal-ish line is w pixels tall in every column it
 * covers), ending square across the major axis; a slanted wide line is
 * therefore thinner, measured perpendicular to it, than w. Horizontal and
 * vertical lines sit where their pixel rows and columns are unambiguous (odd
 * widths on pixel centres, even widths on pixel edges); endpoints at whole
 * coordinates.
 */
#include "harness.h"

#include "raygl.h"

static void line(GLfloat x0, GLfloat y0, GLfloat x1, GLfloat y1)
{
    rayglBegin(GL_LINES);
    rayglVertex2f(x0, y0);
    rayglVertex2f(x1, y1);
    rayglEnd();
}

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglShadeModel(GL_FLAT);

    /* Horizontal: widths 1, 2, 3, 4, 6, 8. */
    static const GLfloat hw[6] = {1, 2, 3, 4, 6, 8};
    static const GLfloat hy[6] = {16.5f, 30.0f, 44.5f, 60.0f, 78.0f, 100.0f};
    for (int i = 0; i < 6; i++) {
        rayglLineWidth(hw[i]);
        rayglColor3f(1.0f, 0.3f + 0.1f * (float)i, 0.2f);
        line(20, hy[i], 150, hy[i]);
    }

    /* Vertical: widths 1, 2, 3, 5, 8. */
    static const GLfloat vw[5] = {1, 2, 3, 5, 8};
    static const GLfloat vx[5] = {170.5f, 184.0f, 198.5f, 214.5f, 234.0f};
    for (int i = 0; i < 5; i++) {
        rayglLineWidth(vw[i]);
        rayglColor3f(0.2f, 0.5f + 0.1f * (float)i, 1.0f);
        line(vx[i], 14, vx[i], 120);
    }

    /* Slanted: widths 1, 2, 4 and a steep 3. */
    rayglColor3f(0.3f, 1.0f, 0.3f);
    rayglLineWidth(1);
    line(252.3f, 14.2f, 305.7f, 42.9f);
    rayglLineWidth(2);
    line(252.3f, 40.2f, 305.7f, 75.9f);
    rayglLineWidth(4);
    line(252.6f, 72.1f, 298.8f, 118.7f);
    rayglLineWidth(3);
    line(262.2f, 126.3f, 281.7f, 203.4f);

    /* A wide line, smooth from red to blue. */
    rayglShadeModel(GL_SMOOTH);
    rayglLineWidth(6);
    rayglBegin(GL_LINES);
    rayglColor3f(1.0f, 0.0f, 0.0f);
    rayglVertex2f(20, 126);
    rayglColor3f(0.0f, 0.0f, 1.0f);
    rayglVertex2f(150, 126);
    rayglEnd();
    rayglShadeModel(GL_FLAT);

    /* A zigzag strip, width 4. */
    rayglLineWidth(4);
    rayglColor3f(1.0f, 1.0f, 0.3f);
    rayglBegin(GL_LINE_STRIP);
    rayglVertex2f(20, 150);
    rayglVertex2f(60, 224);
    rayglVertex2f(95, 152);
    rayglVertex2f(130, 222);
    rayglVertex2f(150, 160);
    rayglEnd();

    /* A loop, width 2. */
    rayglLineWidth(2);
    rayglColor3f(1.0f, 0.5f, 1.0f);
    rayglBegin(GL_LINE_LOOP);
    rayglVertex2f(172, 142);
    rayglVertex2f(240, 150);
    rayglVertex2f(205, 224);
    rayglEnd();

    /* Flat-shaded segments take their last vertex's colour. */
    rayglLineWidth(5);
    rayglBegin(GL_LINES);
    rayglColor3f(1.0f, 0.0f, 0.0f);
    rayglVertex2f(292, 140);
    rayglColor3f(0.0f, 1.0f, 1.0f);
    rayglVertex2f(314, 226);
    rayglColor3f(1.0f, 0.0f, 0.0f);
    rayglVertex2f(285.5f, 140);
    rayglColor3f(1.0f, 1.0f, 1.0f);
    rayglVertex2f(285.5f, 190);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
