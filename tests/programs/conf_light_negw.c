/* conf_light_negw.c: a light position with w = -1. GL transforms the
 * position by the modelview and, w being non-zero, takes the light as
 * positional at (x/w, y/w, z/w): (2, -2, 1, -1) is the point (-2, 2, -1),
 * above left of the scene. Beside it a second light given with w = 2
 * ((2, 0.5, -4, 2) is (1, 0.25, -2)), both attenuated linearly, so a
 * light placed wrong shows in the falloff too. Local viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat warm[4] = {0.9f, 0.7f, 0.5f, 1.0f}, cool[4] = {0.3f, 0.4f, 0.8f, 1.0f};
    GLfloat pos0[4] = {2.0f, -2.0f, 1.0f, -1.0f}, pos1[4] = {2.0f, 0.5f, -4.0f, 2.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT0, GL_SPECULAR, warm);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1f);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, cool);
    glLightfv(GL_LIGHT1, GL_SPECULAR, cool);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glEnable(GL_LIGHT1);
    lit_material(0.7f, 0.7f, 0.7f, 0.4f, 25.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
