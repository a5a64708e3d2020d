/* stencil_two_side.c: two-sided stencil (GL 2.0 glStencilFuncSeparate,
 * glStencilOpSeparate, glStencilMaskSeparate; OSMesa, 8 stencil bits).
 * With colour writes off, a front-facing (CCW) hexagon and a back-facing
 * (CW) triangle are drawn under GL_REPLACE ref 1 for both faces, but the
 * back faces' operation is GL_KEEP: only the hexagon marks the buffer.
 * Then, with separate functions, a front-facing quad is drawn where the
 * stencil is 1 (GL_EQUAL for front faces), and with the front faces culled
 * a back-facing quad where it is not (GL_NOTEQUAL for back faces); the
 * back faces' write mask is 0 throughout. Each draw shows one facing, so
 * the translation is exact. Unlit, depth test on (GL_LESS).
 */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

/* CCW seen from the eye unless cw. */
static void quad(float x0, float y0, float x1, float y1, float z, int cw)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    if (cw) {
        glVertex3f(x0, y1, z);
        glVertex3f(x1, y1, z);
        glVertex3f(x1, y0, z);
    } else {
        glVertex3f(x1, y0, z);
        glVertex3f(x1, y1, z);
        glVertex3f(x0, y1, z);
    }
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, 0.0f);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);

    /* The marks: only front faces write. */
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMaskSeparate(GL_BACK, 0x00);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glBegin(GL_TRIANGLE_FAN); /* front: CCW */
    glVertex3f(-1.2f, 0.3f, -4.0f);
    for (int i = 0; i <= 6; i++) {
        float a = (float)i * 1.0471976f + 0.3f;
        glVertex3f(-1.2f + 1.1f * cosf(a), 0.3f + 1.1f * sinf(a), -4.0f);
    }
    glEnd();
    glBegin(GL_TRIANGLES); /* back: CW, writes nothing */
    glVertex3f(0.9f, -1.0f, -4.0f);
    glVertex3f(1.5f, 1.3f, -4.0f);
    glVertex3f(2.3f, -0.8f, -4.0f);
    glEnd();
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);

    /* Front faces where the mark is, back faces where it is not. */
    glStencilFuncSeparate(GL_FRONT, GL_EQUAL, 1, 0xFF);
    glStencilFuncSeparate(GL_BACK, GL_NOTEQUAL, 1, 0xFF);
    glColor3f(1.0f, 0.5f, 0.2f);
    quad(-3.0f, -0.4f, 3.0f, 1.8f, -6.0f, 0);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glColor3f(0.2f, 0.6f, 1.0f);
    quad(-3.2f, -2.2f, 3.2f, 0.5f, -7.0f, 1);
    glDisable(GL_CULL_FACE);
    return 0;
}

RGL_TEST_MAIN(draw)
