/* fogsec_coord_lit.c: lit surfaces fogged by fog coordinates, one per
 * object (GL_FOG_COORD_SRC GL_FOG_COORD, GL_LINEAR fog 0..10): three
 * spheres and a torus at one depth, each with its own glFogCoord, so the
 * fog says how far each "is" whatever its depth. Local viewer. */
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
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 10.0f);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glEnable(GL_FOG);
    lit_material(0.7f, 0.25f, 0.2f, 0.3f, 30.0f);
    glFogCoordf(0.5f);
    lit_sphere(-1.6f, 0.7f, -6.0f, 0.7f);
    lit_material(0.25f, 0.6f, 0.25f, 0.3f, 30.0f);
    glFogCoordf(3.0f);
    lit_sphere(0.2f, 0.7f, -6.0f, 0.7f);
    lit_material(0.25f, 0.35f, 0.75f, 0.3f, 30.0f);
    glFogCoordf(6.0f);
    lit_sphere(2.0f, 0.7f, -6.0f, 0.7f);
    lit_material(0.7f, 0.7f, 0.25f, 0.25f, 30.0f);
    glFogCoordf(8.5f);
    lit_torus(0.0f, -1.0f, -6.0f, 0.9f, 0.3f, 0.3f, 0.8f, 0.55f);
    return 0;
}

RGL_TEST_MAIN(draw)
