/* quiet_unrec_blend.c: glBlendColor where a draw blends with its colour
 * (GL_CONSTANT_COLOR), through the drop-in header (issue 22). Not recorded
 * before format 1.4, the scene lacked it and raygl2pov said which call and
 * what it changes; recorded now, the frame is exact and nothing is said.
 *
 * GL draws the white rectangle as the source times the constant colour,
 * (0.25, 0.5, 1). The other two rectangles are exact either way.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.8f, 0.3f, 0.2f);
    glRectf(20.13f, 20.37f, 300.13f, 100.37f);
    glEnable(GL_BLEND);
    glBlendColor(0.25f, 0.5f, 1.0f, 1.0f);
    glBlendFunc(GL_CONSTANT_COLOR, GL_ZERO);
    glColor3f(1.0f, 1.0f, 1.0f);
    glRectf(60.13f, 120.37f, 260.13f, 220.37f);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.2f, 0.9f, 0.3f, 0.5f);
    glRectf(180.13f, 60.37f, 300.13f, 160.37f);
    return 0;
}

RGL_TEST_MAIN(draw)
