/* lit_color_material.c: GL_COLOR_MATERIAL in several modes, with a colour
 * per vertex: the sphere in GL_AMBIENT_AND_DIFFUSE (the default), the
 * torus in GL_DIFFUSE (ambient from the material), a small sphere in
 * GL_EMISSION and another in GL_SPECULAR. Local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.5f, 0.5f, 0.5f, 0.5f, 30.0f);
    lit_vertex_colours = 1;
    glEnable(GL_COLOR_MATERIAL);

    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);
    glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
    GLfloat amb[4] = {0.6f, 0.1f, 0.1f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);

    glDisable(GL_COLOR_MATERIAL);
    lit_material(0.3f, 0.3f, 0.3f, 0.3f, 30.0f);
    glColorMaterial(GL_FRONT, GL_EMISSION);
    glEnable(GL_COLOR_MATERIAL);
    lit_sphere(-0.35f, -1.0f, -4.5f, 0.3f);
    glDisable(GL_COLOR_MATERIAL);
    lit_material(0.3f, 0.3f, 0.3f, 0.0f, 12.0f);
    glColorMaterial(GL_FRONT, GL_SPECULAR);
    glEnable(GL_COLOR_MATERIAL);
    lit_sphere(0.35f, 0.95f, -4.5f, 0.3f);
    return 0;
}

RGL_TEST_MAIN(draw)
