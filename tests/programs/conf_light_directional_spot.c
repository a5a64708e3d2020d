/* conf_light_directional_spot.c: the spot parameters of a directional
 * light (w = 0). GL applies them (the spot factor does not depend on w,
 * only the attenuation does), with the direction from the light toward
 * the vertex the same everywhere: the factor is one number for the whole
 * scene. LIGHT0 (warm, from (-1, 1.5, 1)) has cutoff 60 and exponent 3
 * about (0, -1, 0), 43.3 degrees off its rays: it shines at 0.727^3 =
 * 0.385 of its colour. LIGHT1 (cool, from (1, 1, 1)) has cutoff 30 about
 * the same direction, 54.7 degrees off: it gives nothing. Local viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat warm[4] = {1.0f, 0.9f, 0.7f, 1.0f}, dir0[4] = {-1.0f, 1.5f, 1.0f, 0.0f};
    GLfloat cool[4] = {0.3f, 0.5f, 1.0f, 1.0f}, dir1[4] = {1.0f, 1.0f, 1.0f, 0.0f};
    GLfloat down[3] = {0.0f, -1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT0, GL_SPECULAR, warm);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, down);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60.0f);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 3.0f);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT1, GL_POSITION, dir1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, cool);
    glLightfv(GL_LIGHT1, GL_SPECULAR, cool);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, down);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 30.0f);
    glEnable(GL_LIGHT1);
    lit_material(0.4f, 0.6f, 0.8f, 0.6f, 40.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
