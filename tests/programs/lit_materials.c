/* lit_materials.c: materials with and without specular and emission, a
 * brighter GL_LIGHT_MODEL_AMBIENT and a light with its own ambient colour:
 * a dull emissive sphere, a glossy torus with a tight highlight, and a
 * small sphere with shininess 0 (GL: (N.H)^0 = 1 wherever N.L > 0). Local
 * viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat model[4] = {0.3f, 0.3f, 0.4f, 1.0f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model);
    GLfloat amb[4] = {0.1f, 0.05f, 0.0f, 1.0f}, pos[4] = {1.0f, 1.5f, 1.2f, 0.0f};
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);

    lit_material(0.35f, 0.4f, 0.2f, 0.0f, 0.0f);
    GLfloat em[4] = {0.15f, 0.05f, 0.2f, 1.0f}, none[4] = {0, 0, 0, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, em);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, none);
    lit_material(0.2f, 0.3f, 0.7f, 0.9f, 110.0f);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);
    lit_material(0.5f, 0.5f, 0.5f, 0.15f, 0.0f);
    lit_sphere(0.1f, -0.95f, -4.6f, 0.3f);
    return 0;
}

RGL_TEST_MAIN(draw)
