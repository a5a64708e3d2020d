/* fog.h: the fog test scene: spheres and a torus at depths from 3 to 14,
 * lit (local viewer), with the fog of the including program (FOG_SETUP).
 * GL fogs surfaces by their eye distance and leaves the cleared
 * background alone. The materials stay below white even in their
 * highlights: GL clamps a colour before fogging it, POV-Ray after
 * (docs/mapping.md). Included by fog_*.c.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    GLfloat fogc[4] = {0.6f, 0.65f, 0.7f, 1.0f};
    glFogfv(GL_FOG_COLOR, fogc);
    FOG_SETUP;
    glEnable(GL_FOG);
    lit_material(0.7f, 0.25f, 0.2f, 0.3f, 30.0f);
    lit_sphere(-1.0f, 0.0f, -3.6f, 0.6f);
    lit_material(0.25f, 0.6f, 0.25f, 0.3f, 30.0f);
    lit_torus(0.4f, 0.1f, -6.5f, 0.7f, 0.28f, 0.3f, 0.8f, 0.55f);
    lit_material(0.25f, 0.35f, 0.75f, 0.3f, 30.0f);
    lit_sphere(2.2f, 0.4f, -10.0f, 1.0f);
    lit_material(0.7f, 0.7f, 0.25f, 0.25f, 30.0f);
    lit_sphere(-3.0f, 1.0f, -14.0f, 1.2f);
    /* An unlit ground strip from near to far. */
    glDisable(GL_LIGHTING);
    glColor3f(0.35f, 0.3f, 0.25f);
    glBegin(GL_QUADS);
    glVertex3f(-6.0f, -1.5f, -2.5f);
    glVertex3f(6.0f, -1.5f, -2.5f);
    glVertex3f(6.0f, -1.5f, -20.0f);
    glVertex3f(-6.0f, -1.5f, -20.0f);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
