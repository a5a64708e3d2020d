/* lit_point.c: a positional GL_LIGHT0 (w = 1) without attenuation, in front
 * of and above the objects, local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {0.5f, 1.5f, -2.5f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.3f, 0.6f, 0.85f, 0.7f, 30.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
