/* clear_color.c: the background is the clear colour in force at glClear.
 *
 * Covers: glClearColor(0.3, 0.6, 0.9) as the background (0.3 may round to
 * 76 or 77: within the tolerance), a second glClearColor after the glClear
 * that must not change the background, and shapes in colours near the
 * background's so the silhouette test sees them only if colours are right.
 */
#include "harness.h"

#include "raygl.h"
#include "shapes.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.13f, 0.37f, 0.0f);

    rayglClearColor(0.3f, 0.6f, 0.9f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    /* Set after the clear: no effect on this frame's background. */
    rayglClearColor(1.0f, 0.0f, 0.0f, 1.0f);

    rayglColor3f(0.3f, 0.6f, 0.7f);
    shape_rect(40, 40, 140, 200);
    rayglColor3f(0.9f, 0.6f, 0.3f);
    shape_rect(180, 40, 280, 120);
    rayglColor3f(0.33f, 0.63f, 0.93f); /* 8 levels above the background */
    shape_rect(180, 150, 280, 200);
    return 0;
}

RGL_TEST_MAIN(draw)
