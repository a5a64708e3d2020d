/* conf_light_emission.c: emission without the rest. Under a white light
 * and no model ambient, the sphere's material is black but for
 * GL_EMISSION (a flat orange disc in GL); the torus has emission and a
 * diffuse, so its shading sits on top of the emitted colour. Local
 * viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat noamb[4] = {0, 0, 0, 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, noamb);
    GLfloat white[4] = {1, 1, 1, 1}, pos[4] = {1.0f, 2.0f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glEnable(GL_LIGHT0);
    GLfloat zero[4] = {0, 0, 0, 1}, emi[4] = {0.8f, 0.45f, 0.1f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, zero);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, zero);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, zero);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, emi);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);
    GLfloat emi2[4] = {0.1f, 0.2f, 0.35f, 1.0f}, dif[4] = {0.5f, 0.6f, 0.3f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, emi2);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);
    return 0;
}

RGL_TEST_MAIN(draw)
