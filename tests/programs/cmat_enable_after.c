/* cmat_enable_after.c: glEnable(GL_COLOR_MATERIAL) after glMaterialfv set
 * the ambient and diffuse to grey, with no glColor since the enable: the
 * current colour is GL's initial white. GL 2.1 2.14.3: while
 * COLOR_MATERIAL is on, the material's tracked terms follow the current
 * colour, from the glEnable on; Mesa copies the current colour into the
 * material at the glEnable (enable.c, _mesa_update_color_material). The
 * left sphere is drawn so; the right one gets a glColor3f(0.5, 0.5, 0.5)
 * first, which both must follow. Local viewer.
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
    glEnable(GL_COLOR_MATERIAL);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.8f);
    glColor3f(0.5f, 0.3f, 0.2f);
    lit_sphere(0.95f, 0.05f, -5.0f, 0.8f);
    return 0;
}

RGL_TEST_MAIN(draw)
