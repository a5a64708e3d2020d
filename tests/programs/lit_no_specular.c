/* lit_no_specular.c: GL_LIGHT1 with only a diffuse colour (GL_LIGHT1..7
 * have no specular by default) on a shiny material: GL draws no
 * highlight, and neither may POV-Ray, whose specular belongs to the
 * surface. Local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat col[4] = {1.0f, 0.95f, 0.85f, 1.0f}, pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, col);
    glEnable(GL_LIGHT1);
    lit_material(0.7f, 0.5f, 0.9f, 1.0f, 20.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
