/* lit_multi.c: three coloured lights at once: a reddish directional
 * GL_LIGHT0 (white specular), a green positional GL_LIGHT1 with no
 * specular (its default), which must make no highlight, and a blue spot
 * GL_LIGHT2 with a specular colour equal to its diffuse; local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat red[4] = {0.8f, 0.35f, 0.3f, 1.0f}, dir0[4] = {-1.0f, 0.6f, 0.8f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, red);
    glEnable(GL_LIGHT0);
    GLfloat green[4] = {0.2f, 0.7f, 0.3f, 1.0f}, pos1[4] = {2.0f, -1.0f, -2.0f, 1.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, green);
    glEnable(GL_LIGHT1);
    GLfloat blue[4] = {0.2f, 0.3f, 0.9f, 1.0f}, pos2[4] = {-0.5f, 3.0f, -4.0f, 1.0f};
    GLfloat sdir[3] = {0.0f, -1.0f, -0.3f};
    glLightfv(GL_LIGHT2, GL_POSITION, pos2);
    glLightfv(GL_LIGHT2, GL_DIFFUSE, blue);
    glLightfv(GL_LIGHT2, GL_SPECULAR, blue);
    glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, sdir);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 50.0f);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 2.0f);
    glEnable(GL_LIGHT2);
    lit_material(0.9f, 0.9f, 0.9f, 0.8f, 50.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
