/* lit_local_viewer.c: lit_directional with GL_LIGHT_MODEL_LOCAL_VIEWER:
 * GL's highlights then use the true view direction as POV-Ray's do (the
 * 99% regime of docs/testing.md).
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.8f, 0.25f, 0.2f, 0.6f, 40.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
