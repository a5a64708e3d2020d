/* shadow_matte.c: shadow.c's sphere over a floor for the Blender tests of
 * --area-lights and --radiosity, its colour 0.94 of shadow.c's so that
 * GL's ambient and diffuse terms stay within 1 in every channel (red:
 * 0.8 x (1 + 0.2)). shadow.c's sphere (0.85 x 1.2 in red) may saturate,
 * so the interpreter takes GL's own lit colours for it (interp_relit.c,
 * interp_relit_may_saturate): an unlit mesh, which Blender's glTF import
 * leaves out of shadow and bounce rays. Here the writer lights the sphere
 * and Blender shadows and bounces it.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    GLfloat pos[4] = {0.0f, 1.0f, 0.3f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.8f, 0.28f, 0.23f, 0.5f, 40.0f);
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
