/* pixels_copy_xor.c: glCopyPixels right after drawing, and under
 * glLogicOp(GL_XOR) (GL_COLOR_LOGIC_OP). An unlit scene of coloured
 * triangles; a 60 x 50 region copied to a free place as it is; the same
 * region copied with XOR over the yellow triangle (the copy and what is
 * there combine bit by bit); and another region XORed twice onto one
 * place, which leaves it as it was. The recorder reads each source back at
 * the call, and after a copy under a logic op the pixels GL left.
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
    glColor3f(0.3f, 0.7f, 0.9f);
    glVertex2f(230.5f, 100.5f);
    glVertex2f(310.5f, 110.5f);
    glVertex2f(270.5f, 200.5f);
    glEnd();

    glWindowPos2i(200, 20);
    glCopyPixels(5, 5, 60, 50, GL_COLOR);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glWindowPos2i(130, 150);
    glCopyPixels(5, 5, 60, 50, GL_COLOR);
    for (int k = 0; k < 2; k++) {
        glWindowPos2i(240, 120);
        glCopyPixels(10, 10, 50, 40, GL_COLOR);
    }
    glLogicOp(GL_COPY);
    glDisable(GL_COLOR_LOGIC_OP);
    return 0;
}

RGL_TEST_MAIN(draw)
