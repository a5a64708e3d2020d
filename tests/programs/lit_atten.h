/* lit_atten.h: a point light with GL attenuation LIT_KC, LIT_KL, LIT_KQ,
 * bright enough that the falloff shows across the sphere and torus, local
 * viewer. Included by lit_atten_*.c, which define the three terms.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {-2.2f, 1.2f, -3.2f, 1.0f};
    GLfloat col[4] = {LIT_GAIN, LIT_GAIN, LIT_GAIN, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, col);
    glLightfv(GL_LIGHT0, GL_SPECULAR, col);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, LIT_KC);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, LIT_KL);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, LIT_KQ);
    glEnable(GL_LIGHT0);
    lit_material(0.85f, 0.75f, 0.4f, 0.5f, 25.0f);
    lit_pair();
    return 0;
}

RGL_TEST_MAIN(draw)
