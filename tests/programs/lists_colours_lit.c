/* lists_colours_lit.c: a lit sphere with a colour per vertex
 * (GL_COLOR_MATERIAL, GL_AMBIENT_AND_DIFFUSE) in a display list called
 * four times. In the prototype the colours are one image, the pigment of
 * the material's finish (docs/mapping.md section 9). Local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.5f, 0.5f, 0.5f, 0.5f, 30.0f);
    lit_vertex_colours = 1;
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);

    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    lit_sphere(0, 0, 0, 0.6f);
    glEndList();
    static const float at[4][3] = {
        {-0.8f, 0.7f, -5.0f}, {0.75f, 0.65f, -5.3f}, {-0.7f, -0.7f, -4.8f}, {0.8f, -0.75f, -5.1f}};
    for (int i = 0; i < 4; i++) {
        glPushMatrix();
        glTranslatef(at[i][0], at[i][1], at[i][2]);
        glRotatef(40.0f * (float)i, 0.3f, 1, 0.2f);
        glCallList(l);
        glPopMatrix();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
