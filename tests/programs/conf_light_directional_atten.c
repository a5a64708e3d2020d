/* conf_light_directional_atten.c: what GL ignores for a directional light
 * (w = 0): attenuation (constant 4, linear 1, quadratic 1). The scene
 * comes out as under a plain directional light. Local viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat col[4] = {0.9f, 0.85f, 0.8f, 1.0f}, dir[4] = {-1.0f, 1.5f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, col);
    glLightfv(GL_LIGHT0, GL_SPECULAR, col);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 4.0f);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1.0f);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 1.0f);
    glEnable(GL_LIGHT0);
    lit_material(0.4f, 0.6f, 0.8f, 0.6f, 40.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
