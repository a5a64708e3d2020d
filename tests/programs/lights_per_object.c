/* lights_per_object.c: lights that change between the draws of one frame.
 * The sphere is lit by a warm directional GL_LIGHT0 alone; then GL_LIGHT0
 * is disabled, a blue point GL_LIGHT1 enabled and the model ambient raised
 * for the torus; then GL_LIGHT0 comes back, moved and recoloured, with
 * GL_LIGHT1, for a small sphere. GL lights each draw with its own lights;
 * the ray-traced frame must too (three light sets, docs/mapping.md "Lights
 * per object"). Local viewer, no shadows.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat warm[4] = {0.9f, 0.6f, 0.35f, 1.0f}, dir0[4] = {-1.0f, 0.8f, 0.9f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, warm);
    glEnable(GL_LIGHT0);
    lit_material(0.9f, 0.9f, 0.9f, 0.7f, 40.0f);
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);

    glDisable(GL_LIGHT0);
    GLfloat blue[4] = {0.3f, 0.45f, 1.0f, 1.0f}, pos1[4] = {2.5f, 1.5f, -2.5f, 1.0f};
    GLfloat spec1[4] = {0.6f, 0.6f, 0.6f, 1.0f}, amb[4] = {0.05f, 0.25f, 0.1f, 1.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
    glLightfv(GL_LIGHT1, GL_SPECULAR, spec1);
    glEnable(GL_LIGHT1);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);

    GLfloat green[4] = {0.3f, 0.9f, 0.3f, 1.0f}, dir2[4] = {0.5f, -0.2f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir2);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, green);
    glEnable(GL_LIGHT0);
    lit_sphere(0.1f, 0.95f, -6.0f, 0.4f);
    return 0;
}

RGL_TEST_MAIN(draw)
