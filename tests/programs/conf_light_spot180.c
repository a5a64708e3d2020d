/* conf_light_spot180.c: a positional light whose GL_SPOT_CUTOFF is 180
 * (GL's default: no spotlight) while GL_SPOT_EXPONENT is 60 and the spot
 * direction points away from the scene: GL ignores both, the light shines
 * everywhere. A second light with cutoff 90 exactly (a half-space) aimed
 * across the scene, exponent 0: lit where the angle is within 90 degrees.
 * Local viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat white[4] = {0.8f, 0.8f, 0.75f, 1.0f};
    GLfloat pos0[4] = {-2.0f, 2.0f, 0.0f, 1.0f}, away[3] = {0.0f, 0.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, away);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 60.0f);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
    glEnable(GL_LIGHT0);
    GLfloat blue[4] = {0.2f, 0.3f, 0.7f, 1.0f};
    GLfloat pos1[4] = {0.0f, -0.2f, -5.0f, 1.0f}, right[3] = {1.0f, 0.0f, 0.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
    glLightfv(GL_LIGHT1, GL_SPECULAR, blue);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, right);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 90.0f);
    glEnable(GL_LIGHT1);
    lit_material(0.7f, 0.6f, 0.5f, 0.5f, 30.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
