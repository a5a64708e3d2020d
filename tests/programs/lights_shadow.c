/* lights_shadow.c: a shadow blocks the whole light. As shadow.c, a sphere
 * floats above a floor under a directional GL_LIGHT0 (direction (0, 1,
 * 0.3)), but the light's diffuse colour (1, 0.7, 0.4) differs from its
 * specular (0.3, 0.3, 0.3). In the sphere's shadow only the ambient term
 * is left: the floor's ambient (0.7, 0.7, 0.65) times GL's default model
 * ambient 0.2 (the light's ambient is 0): (0.14, 0.14, 0.13), levels (36,
 * 36, 33). tests/image/meson.build expects that colour in the box x
 * 150..170, y 179..185 (shadow.c's) within 3 levels: a shadow that kept
 * part of the light (the diffuse beyond the specular, as before) comes out
 * orange there.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    GLfloat pos[4] = {0.0f, 1.0f, 0.3f, 0.0f};
    GLfloat dif[4] = {1.0f, 0.7f, 0.4f, 1.0f}, spe[4] = {0.3f, 0.3f, 0.3f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spe);
    glEnable(GL_LIGHT0);
    lit_material(0.85f, 0.3f, 0.25f, 0.5f, 40.0f);
    lit_sphere(0.0f, 0.2f, -5.0f, 0.7f);
    lit_material(0.7f, 0.7f, 0.65f, 0.0f, 0.0f);
    glBegin(GL_QUADS);
    glNormal3f(0, 1, 0);
    glVertex3f(-6.0f, -1.0f, -2.5f);
    glVertex3f(6.0f, -1.0f, -2.5f);
    glVertex3f(6.0f, -1.0f, -12.0f);
    glVertex3f(-6.0f, -1.0f, -12.0f);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
