/* lit_directional.c: GL_LIGHT0 as a directional light (w = 0) with its
 * default white diffuse and specular, GL's default infinite viewer, a
 * shiny red material on a sphere and torus (the 95% regime of
 * docs/testing.md: POV-Ray's highlights follow the true view direction).
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.8f, 0.25f, 0.2f, 0.6f, 40.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
