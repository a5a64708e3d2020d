/* conf_color_material_after.c: glEnable(GL_COLOR_MATERIAL) after
 * glMaterialfv set the diffuse, with no glColor since. GL (the spec's
 * "the current colour is applied when the colour material is enabled"
 * aside, Mesa) keeps the material's grey until the next glColor: the
 * sphere is grey. The torus follows a glColor made after the enable:
 * orange. Directional light, local viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat white[4] = {1, 1, 1, 1}, dir[4] = {0.5f, 1.0f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glEnable(GL_LIGHT0);
    glColor3f(1.0f, 1.0f, 1.0f);
    lit_material(0.45f, 0.45f, 0.45f, 0.3f, 20.0f);
    glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);
    glColor3f(0.9f, 0.5f, 0.1f);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);
    glDisable(GL_COLOR_MATERIAL);
    return 0;
}

RGL_TEST_MAIN(draw)
