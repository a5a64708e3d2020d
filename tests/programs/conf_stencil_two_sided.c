/* conf_stencil_two_sided.c: two-sided stencil (glStencilFuncSeparate,
 * glStencilOpSeparate). A counter-clockwise (front) and a clockwise
 * (back) rectangle, overlapping, drawn with colour writes off: front
 * faces replace the stencil with 1, back faces with 2. Then full-window
 * quads with glStencilFunc(GL_EQUAL, 1) in red and (GL_EQUAL, 2) in blue:
 * the front rectangle shows red, the back one blue where it was drawn
 * last (the overlap: 2, drawn after). Unlit, window pixels. */
#define GL_GLEXT_PROTOTYPES
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static void rect_cw(int x0, int y0, int x1, int y1)
{
    glBegin(GL_QUADS);
    glVertex2f((float)x0 + 0.25f, (float)y0 + 0.25f);
    glVertex2f((float)x0 + 0.25f, (float)y1 + 0.25f);
    glVertex2f((float)x1 + 0.25f, (float)y1 + 0.25f);
    glVertex2f((float)x1 + 0.25f, (float)y0 + 0.25f);
    glEnd();
}

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.1f);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFuncSeparate(GL_FRONT, GL_ALWAYS, 1, 0xff);
    glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 2, 0xff);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_REPLACE);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_REPLACE);
    conf_box(20, 30, 180, 200, 0.0f);
    rect_cw(120, 60, 300, 220);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glColor3f(0.9f, 0.2f, 0.2f);
    conf_box(0, 0, w, h, 0.0f);
    glStencilFunc(GL_EQUAL, 2, 0xff);
    glColor3f(0.2f, 0.3f, 0.9f);
    conf_box(0, 0, w, h, 0.0f);
    glDisable(GL_STENCIL_TEST);
    return 0;
}

RGL_TEST_MAIN(draw)
