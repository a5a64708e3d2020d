/* flat_colors.c: unlit, single-coloured shapes under gluOrtho2D.
 *
 * Covers: constant colour per primitive from several glColor entry points
 * (3f, 3ub, 3d, 3fv, 4f with alpha ignored as blending is off), the issue's
 * exact-colour example glColor3f(0.5, 0.25, 1), triangles, a quad and a
 * convex polygon with straight, slanted and steep edges. The scene is laid
 * out in a 320x240 logical space whatever the image size; a translation of
 * (0.13, 0.37) keeps slanted edges off pixel centres at 320x240, so edge
 * pixels are decided by geometry, not by tie-breaking rules.
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

    rayglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);

    /* The example colour: must come out as (128, 64, 255). */
    rayglColor3f(0.5f, 0.25f, 1.0f);
    rayglBegin(GL_TRIANGLES);
    rayglVertex2f(12, 14);
    rayglVertex2f(150, 20);
    rayglVertex2f(60, 130);
    rayglEnd();

    rayglColor3ub(200, 100, 50);
    rayglBegin(GL_QUADS);
    rayglVertex2f(170, 12);
    rayglVertex2f(305, 12);
    rayglVertex2f(305, 90);
    rayglVertex2f(170, 90);
    rayglEnd();

    /* A convex hexagon as one GL_POLYGON. */
    static const GLfloat green[3] = {0.1f, 0.8f, 0.3f};
    rayglColor3fv(green);
    rayglBegin(GL_POLYGON);
    rayglVertex2f(230, 110);
    rayglVertex2f(290, 125);
    rayglVertex2f(300, 175);
    rayglVertex2f(255, 220);
    rayglVertex2f(195, 200);
    rayglVertex2f(185, 140);
    rayglEnd();

    /* Grey levels: 0.2 .. 0.8 must come out as 51, 102, 153, 204. */
    for (int i = 0; i < 4; i++) {
        double g = 0.2 * (i + 1);
        rayglColor3d(g, g, g);
        float x = 20.0f + 40.0f * (float)i;
        rayglBegin(GL_TRIANGLES);
        rayglVertex2f(x, 150);
        rayglVertex2f(x + 33, 155);
        rayglVertex2f(x + 12, 226);
        rayglEnd();
    }

    /* Alpha is ignored while blending is off. */
    rayglColor4f(1.0f, 1.0f, 0.0f, 0.25f);
    rayglBegin(GL_TRIANGLES);
    rayglVertex2f(120, 100);
    rayglVertex2f(160, 95);
    rayglVertex2f(165, 140);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
