/* points_smooth.c: round points (GL_POINT_SMOOTH) under gluOrtho2D.
 *
 * With GL_POINT_SMOOTH on and blending off, Mesa draws every pixel whose
 * centre lies within size/2 of the point, at full colour: a disc, which a
 * sphere or a camera-facing disc reproduces exactly. Sizes 3 to 24, even
 * sizes centred on pixel corners, odd sizes on pixel centres (no pixel
 * centre lies exactly on a rim). gluOrtho2D's depth range is only 2 units
 * (near -1, far 1) while these points are up to 24 units across: a solid
 * that reaches beyond the near or far plane must not be cut by it (GL clips
 * a point by its centre only).
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

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglEnable(GL_POINT_SMOOTH);

    for (int i = 0; i < 6; i++) {
        rayglPointSize(4.0f + 4.0f * (float)i); /* 4 .. 24 */
        rayglBegin(GL_POINTS);
        rayglColor3f(1.0f, 1.0f - 0.15f * (float)i, 0.3f);
        rayglVertex2f(30.0f + 52.0f * (float)i, 160.0f);
        rayglEnd();
        rayglPointSize(3.0f + 4.0f * (float)i); /* 3 .. 23 */
        rayglBegin(GL_POINTS);
        rayglColor3f(0.3f, 0.6f + 0.08f * (float)i, 1.0f);
        rayglVertex2f(30.5f + 52.0f * (float)i, 80.5f);
        rayglEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
