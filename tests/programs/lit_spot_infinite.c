/* lit_spot_infinite.c: lit_spot under GL's default infinite viewer (the
 * 95% regime of docs/testing.md): a spotlight with a hard cone over a dim
 * directional light, a coloured light whose specular equals its diffuse.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    GLfloat dim[4] = {0.25f, 0.25f, 0.3f, 1.0f}, dir0[4] = {0.0f, 0.3f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dim);
    glLightfv(GL_LIGHT0, GL_SPECULAR, dim);
    glEnable(GL_LIGHT0);
    GLfloat warm[4] = {1.0f, 0.85f, 0.6f, 1.0f};
    GLfloat pos[4] = {0.0f, 2.5f, -1.5f, 1.0f}, sdir[3] = {-0.1f, -0.75f, -1.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, sdir);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 25.0f);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3.0f);
    glEnable(GL_LIGHT1);
    lit_material(0.8f, 0.8f, 0.8f, 0.6f, 40.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
