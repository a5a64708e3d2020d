/* cmat_enable_drawn.c: glEnable(GL_COLOR_MATERIAL) where no glMaterial
 * came since the last draw: the tracked terms (GL_AMBIENT_AND_DIFFUSE)
 * take the current colour at the glEnable (GL 2.1 2.14.3; Mesa too). A
 * grey sphere is drawn with colour material off and a red current colour;
 * after the glEnable the middle sphere is red without a glColor; a
 * glMaterialfv of the tracked diffuse while colour material is on changes
 * nothing (Mesa's _mesa_Materialfv skips it), so after the glDisable the
 * right sphere is red too. Local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.4f, 0.4f, 0.4f, 0.3f, 20.0f);
    glColor3f(0.8f, 0.15f, 0.1f);
    lit_sphere(-1.3f, 0.05f, -5.0f, 0.55f);
    glEnable(GL_COLOR_MATERIAL);
    lit_sphere(0.0f, 0.05f, -5.0f, 0.55f);
    GLfloat green[4] = {0.1f, 0.7f, 0.1f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, green);
    glDisable(GL_COLOR_MATERIAL);
    lit_sphere(1.3f, 0.05f, -5.0f, 0.55f);
    return 0;
}

RGL_TEST_MAIN(draw)
