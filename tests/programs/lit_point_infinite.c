/* lit_point_infinite.c: lit_point under GL's default infinite viewer, with
 * linear attenuation: the positional light's direction and fade are exact,
 * the highlights land a few pixels off (the 95% regime of
 * docs/testing.md).
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    GLfloat pos[4] = {0.5f, 1.5f, -2.5f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.12f);
    glEnable(GL_LIGHT0);
    lit_material(0.3f, 0.6f, 0.85f, 0.7f, 30.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
