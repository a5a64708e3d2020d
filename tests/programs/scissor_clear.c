/* scissor_clear.c: a glClear with GL_SCISSOR_TEST on clears only the
 * scissor box.
 *
 * Covers: a full clear, then two scissored clears of other colours (one
 * box partly outside the window), geometry drawn afterwards over part of a
 * box (it covers the cleared pixels), through a perspective camera fixed
 * by the first draw after the clears, and the scissor test turned off
 * before the draws (they are not scissored).
 */
#include "harness.h"

#include "raygl.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.2f, 0.2f, 0.4f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_SCISSOR_TEST);
    rayglScissor(40, 30, 120, 100);
    rayglClearColor(0.9f, 0.6f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglScissor(w - 60, h - 50, 100, 100);
    rayglClearColor(0.3f, 0.8f, 0.5f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglDisable(GL_SCISSOR_TEST);

    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglFrustum(-0.4 * w / h, 0.4 * w / h, -0.4, 0.4, 1, 20);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglEnable(GL_DEPTH_TEST);
    rayglColor3f(0.8f, 0.8f, 0.8f);
    rayglBegin(GL_QUADS);
    rayglVertex3f(-1.2f, -0.9f, -5);
    rayglVertex3f(0.3f, -0.9f, -5);
    rayglVertex3f(0.3f, 0.2f, -5);
    rayglVertex3f(-1.2f, 0.2f, -5);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
