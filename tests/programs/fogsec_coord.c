/* fogsec_coord.c: fog coordinates and the secondary colour, unlit
 * (issue 13).
 *
 * Under gluPerspective: a ground grid from depth 3 to 30 whose GL_LINEAR
 * fog comes from glFogCoord (GL_FOG_COORD_SRC GL_FOG_COORD): a height fog,
 * thick in a valley across the middle and clear at the sides, whatever the
 * eye distance; above it, a strip fogged by the eye distance for
 * comparison, and three triangles with GL_COLOR_SUM on (their secondary
 * colours added to the primary ones, one clamped at 1). The grid's cells
 * each have one colour and their fog coordinates stay within
 * GL_FOG_START..GL_FOG_END, so the per-vertex fog blend is exact.
 */
#include "harness.h"

#include <raygl/gl.h>

/* The fog coordinate at ground point x: deep in the valley |x| < 2. */
static float coord_at(float x)
{
    float d = x < 0 ? -x : x;
    return d < 2.0f ? 10.0f : d < 6.0f ? 10.0f - 2.5f * (d - 2.0f) : 0.0f;
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / (double)h, 1.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.05f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);

    GLfloat fogc[4] = {0.8f, 0.8f, 0.75f, 1.0f};
    glFogfv(GL_FOG_COLOR, fogc);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 12.0f);
    glEnable(GL_FOG);

    /* The ground: cells of two colours, fog from the fog coordinate. */
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glBegin(GL_QUADS);
    for (int j = 0; j < 9; j++) {
        float z0 = -3.0f - 3.0f * (float)j, z1 = z0 - 3.0f;
        for (int i = 0; i < 16; i++) {
            float x0 = -12.0f + 1.5f * (float)i, x1 = x0 + 1.5f;
            if ((i + j) % 2)
                glColor3f(0.2f, 0.55f, 0.25f);
            else
                glColor3f(0.45f, 0.3f, 0.15f);
            glFogCoordf(coord_at(x0));
            glVertex3f(x0, -2.0f, z0);
            glFogCoordf(coord_at(x1));
            glVertex3f(x1, -2.0f, z0);
            glVertex3f(x1, -2.0f, z1);
            glFogCoordf(coord_at(x0));
            glVertex3f(x0, -2.0f, z1);
        }
    }
    glEnd();

    /* A strip from near to far, fogged by the eye distance. */
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    glColor3f(0.8f, 0.2f, 0.2f);
    glBegin(GL_QUADS);
    glVertex3f(-7.0f, 1.5f, -3.0f);
    glVertex3f(-7.0f, 1.5f, -25.0f);
    glVertex3f(-5.0f, 1.5f, -25.0f);
    glVertex3f(-5.0f, 1.5f, -3.0f);
    glEnd();
    glDisable(GL_FOG);

    /* The colour sum: primary + secondary, clamped. */
    glEnable(GL_COLOR_SUM);
    glBegin(GL_TRIANGLES);
    glColor3f(0.3f, 0.1f, 0.1f);
    glSecondaryColor3f(0.1f, 0.5f, 0.0f);
    glVertex3f(-2.5f, 0.0f, -6.0f);
    glColor3f(0.1f, 0.1f, 0.6f);
    glSecondaryColor3f(0.5f, 0.0f, 0.3f);
    glVertex3f(-0.5f, 0.0f, -6.0f);
    glColor3f(0.6f, 0.6f, 0.1f);
    glSecondaryColor3f(0.6f, 0.2f, 0.0f);
    glVertex3f(-1.5f, 1.8f, -6.0f);
    glEnd();
    glSecondaryColor3f(0.0f, 0.4f, 0.8f);
    glColor3f(0.5f, 0.1f, 0.0f);
    glBegin(GL_TRIANGLES);
    glVertex3f(0.5f, 0.0f, -6.0f);
    glVertex3f(2.5f, 0.0f, -6.0f);
    glVertex3f(1.5f, 1.8f, -6.0f);
    glEnd();
    glDisable(GL_COLOR_SUM);
    return 0;
}

RGL_TEST_MAIN(draw)
