/* accum.h: the accumulation-buffer test scene. Flat unlit quads at three
 * depths, drawn ACCUM_PASSES times into the accumulation buffer, each pass
 * with the projection and eye of accum_pass(i) (of the including program),
 * and returned: GL's image is the average of the passes. Included by
 * accum_*.c.
 */
#include "harness.h"

#include <raygl/gl.h>

#define ACCUM_PASSES 8

/* A perspective projection (fovy 40, near 1, far 30) whose image is moved
 * by (pixdx, pixdy) pixels, seen from an eye moved by (eyedx, eyedy) in its
 * own plane with the plane at distance focus keeping its image: the eye's
 * move shears the frustum by eyed * near / focus. */
static void accum_camera(int w, int h, double pixdx, double pixdy, double eyedx, double eyedy,
                         double focus)
{
    const double n = 1.0, f = 30.0;
    double top = n * 0.36397023426620234; /* tan(20 degrees) */
    double right = top * w / h;
    double dx = -(pixdx * 2 * right / w + eyedx * n / focus);
    double dy = -(pixdy * 2 * top / h + eyedy * n / focus);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-right + dx, right + dx, -top + dy, top + dy, n, f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslated(-eyedx, -eyedy, 0);
}

/* Pass i's sample in [-1/2, 1/2)^2: one per row and column of an 8 x 8
 * grid (no two share an x or a y). */
static inline void accum_sample(int i, double *x, double *y)
{
    *x = (i + 0.5) / ACCUM_PASSES - 0.5;
    *y = ((i * 3) % ACCUM_PASSES + 0.5) / ACCUM_PASSES - 0.5;
}

static void accum_quad(float x, float y, float z, float s, float angle, float r, float g, float b)
{
    glPushMatrix();
    glTranslatef(x, y, z);
    glRotatef(angle, 0, 0, 1);
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex3f(-s, -s, 0);
    glVertex3f(s, -s, 0);
    glVertex3f(s, s, 0);
    glVertex3f(-s, s, 0);
    glEnd();
    glPopMatrix();
}

static void accum_pass(int i, int w, int h); /* the including program's */

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClearAccum(0, 0, 0, 0);
    glClear(GL_ACCUM_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    for (int i = 0; i < ACCUM_PASSES; i++) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        accum_pass(i, w, h);
        accum_quad(-1.2f, 0.3f, -3.0f, 0.35f, 17.0f, 0.9f, 0.3f, 0.2f);
        accum_quad(0.2f, -0.2f, -5.0f, 0.8f, 31.0f, 0.3f, 0.8f, 0.35f);
        accum_quad(2.5f, 1.0f, -9.0f, 1.2f, 8.0f, 0.3f, 0.4f, 0.9f);
        glAccum(GL_ACCUM, 1.0f / ACCUM_PASSES);
    }
    glAccum(GL_RETURN, 1.0f);
    return glGetError() == GL_NO_ERROR ? 0 : 1;
}

RGL_TEST_MAIN(draw)
