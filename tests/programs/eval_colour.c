/* eval_colour.c: coloured and textured Bezier patches, unlit (OSMesa).
 *
 * Left: a flat bilinear GL_MAP2_VERTEX_3 with a GL_MAP2_COLOR_4 of four
 * corner colours (doubles, glMap2d) drawn by glEvalMesh2(GL_FILL) over part
 * of the grid. Right: a curved patch with GL_MAP2_TEXTURE_COORD_2 mapping
 * the test checkerboard twice across it (GL_REPEAT, GL_NEAREST), its points
 * given v major (ustride 2, vstride 4) by glMap2f, drawn by glEvalCoord2f
 * quad strips written out by the program; a GL_MAP2_TEXTURE_COORD_1 enabled
 * too, which the two-component map overrides.
 */
#include "harness.h"
#include "tex_scene.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    tex_view(w, h);
    glEnable(GL_DEPTH_TEST);

    static const GLdouble flat[2][2][3] = {
        {{15, 30, -0.5}, {15, 210, -0.5}},
        {{150, 30, -0.5}, {150, 210, -0.5}},
    };
    static const GLdouble corners[2][2][4] = {
        {{1, 0.1, 0.1, 1}, {0.1, 1, 0.2, 1}},
        {{0.2, 0.3, 1, 1}, {1, 1, 0.2, 1}},
    };
    glMap2d(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, &flat[0][0][0]);
    glMap2d(GL_MAP2_COLOR_4, 0, 1, 8, 2, 0, 1, 4, 2, &corners[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_COLOR_4);
    glMapGrid2f(10, 0.0f, 1.0f, 12, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 1, 10, 0, 11);
    glDisable(GL_MAP2_COLOR_4);

    /* 3 x 3 points in x, y, v major: point (i, j) at 2 * i + 6 * j... kept as
     * separate arrays: positions (xy, z fixed by a map of 3) and texcoords. */
    static const GLfloat pos[3][3][3] = {
        {{170, 30, 0}, {165, 120, 0}, {175, 215, 0}},
        {{235, 50, 0}, {230, 120, 0}, {240, 195, 0}},
        {{305, 30, 0}, {300, 120, 0}, {310, 215, 0}},
    };
    static const GLfloat st[2][2][2] = {{{0, 0}, {0, 2}}, {{2, 0}, {2, 2}}};
    static const GLfloat s1[2] = {5, 7};
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 9, 3, 0, 1, 3, 3, &pos[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 4, 2, 0, 1, 2, 2, &st[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_1, 0, 1, 1, 2, 0, 1, 1, 1, s1);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    glEnable(GL_MAP2_TEXTURE_COORD_1);
    tex_make(GL_RGBA, GL_REPEAT, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int j = 0; j < 16; j++) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= 16; i++) {
            glEvalCoord2f((float)i / 16.0f, (float)j / 16.0f);
            glEvalCoord2f((float)i / 16.0f, (float)(j + 1) / 16.0f);
        }
        glEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
