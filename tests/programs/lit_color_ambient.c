/* lit_color_ambient.c: the glColorMaterial modes lit_color_material leaves
 * out: GL_AMBIENT (the colour feeds only the ambient term, under a bright
 * GL_LIGHT_MODEL_AMBIENT so that it shows) on the sphere, and
 * GL_AMBIENT_AND_DIFFUSE on GL_FRONT only on the torus (whose back faces
 * are hidden). A colour per vertex, local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat model[4] = {0.55f, 0.55f, 0.55f, 1.0f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model);
    GLfloat dif[4] = {0.5f, 0.5f, 0.5f, 1.0f}, pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.3f, 0.3f, 0.45f, 0.4f, 30.0f);
    lit_vertex_colours = 1;

    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT);
    glEnable(GL_COLOR_MATERIAL);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);
    glDisable(GL_COLOR_MATERIAL);

    lit_material(0.3f, 0.3f, 0.3f, 0.4f, 30.0f);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);
    return 0;
}

RGL_TEST_MAIN(draw)
