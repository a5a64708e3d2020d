/* pixels_copy.c: glCopyPixels. An unlit scene of coloured triangles, then
 * a 60 x 50 region of the frame copied to a place given by glWindowPos2i,
 * once as it is and once with glPixelZoom(1.5, -1) (flipped) and the green
 * scale of glPixelTransfer; a copy overlapping its own source last, which
 * GL reads before it writes. The recorder reads each source back at the
 * call.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.2f);
    glVertex2f(10.5f, 10.5f);
    glColor3f(0.2f, 1.0f, 0.2f);
    glVertex2f(70.5f, 15.5f);
    glColor3f(0.2f, 0.2f, 1.0f);
    glVertex2f(30.5f, 58.5f);
    glColor3f(1.0f, 1.0f, 0.2f);
    glVertex2f(120.5f, 150.5f);
    glVertex2f(200.5f, 140.5f);
    glVertex2f(160.5f, 220.5f);
    glEnd();

    glWindowPos2i(200, 20);
    glCopyPixels(5, 5, 60, 50, GL_COLOR);
    glPixelZoom(1.5f, -1.0f);
    glPixelTransferf(GL_GREEN_SCALE, 0.5f);
    glWindowPos2i(20, 140);
    glCopyPixels(5, 5, 60, 50, GL_COLOR);
    glPixelTransferf(GL_GREEN_SCALE, 1.0f);
    glPixelZoom(1.0f, 1.0f);
    glWindowPos2i(140, 160);
    glCopyPixels(110, 130, 80, 60, GL_COLOR);
    return 0;
}

RGL_TEST_MAIN(draw)
