/* conf_light_model_ambient.c: lighting on and no light enabled: GL's
 * colour is the material's emission plus GL_LIGHT_MODEL_AMBIENT times its
 * ambient, the same everywhere (flat discs of colour, no shading). The
 * sphere's material has ambient only, the torus's ambient and an emission
 * whose sum with it passes 1 in red (clamped). Local viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    GLfloat model[4] = {0.6f, 0.5f, 0.4f, 1.0f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model);
    GLfloat amb[4] = {0.9f, 0.4f, 0.3f, 1.0f}, zero[4] = {0, 0, 0, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, zero);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, zero);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);
    GLfloat amb2[4] = {0.5f, 0.9f, 0.6f, 1.0f}, emi[4] = {0.8f, 0.1f, 0.2f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb2);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, emi);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);
    return 0;
}

RGL_TEST_MAIN(draw)
