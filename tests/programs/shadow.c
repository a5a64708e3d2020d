/* shadow.c: the shadow a ray tracer adds. A sphere floats above a floor,
 * GL_LIGHT0 shines almost straight down (direction (0, 1, 0.3)); OpenGL
 * draws the floor evenly lit, POV-Ray (shadows on, the default) must
 * darken it under the sphere. Where: the sphere, centre (0, 0.2, -5),
 * radius 0.7, casts its shadow on y = -1 around (0, -1, -5.36), which
 * this camera (fovy 40, 320x240) shows around pixel (160, 182), about 85
 * pixels wide; the floor at x in [-2.9, -2.3], the same depths, shows
 * around pixels 40..65 in the same rows. tests/image/meson.build compares
 * the boxes x 150..170, y 179..185 and x 40..65, y 179..185.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    GLfloat pos[4] = {0.0f, 1.0f, 0.3f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
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
