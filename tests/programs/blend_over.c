/* blend_over.c: transparency over opaque objects, as programs draw it:
 * the opaque torus and sphere first, then with GL_BLEND and GL_SRC_ALPHA,
 * GL_ONE_MINUS_SRC_ALPHA a lit sphere of material alpha 0.45 (back faces
 * culled, so one layer shows, as GL draws it) in front of the torus, and
 * an unlit band of glColor4 alpha 0.6 across the picture. Local viewer.
 * The materials stay below white even in their highlights: GL clamps each
 * colour before blending, POV-Ray after (docs/mapping.md).
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.6f, 0.45f, 0.15f, 0.3f, 30.0f);
    lit_torus(0.6f, -0.05f, -6.0f, 0.7f, 0.28f, 0.3f, 0.8f, 0.55f);
    lit_material(0.25f, 0.5f, 0.25f, 0.3f, 30.0f);
    lit_sphere(-1.3f, 0.2f, -6.5f, 0.7f);

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_CULL_FACE);
    GLfloat d[4] = {0.3f, 0.4f, 0.7f, 0.45f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, d);
    GLfloat s[4] = {0.3f, 0.3f, 0.3f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
    lit_sphere(0.2f, 0.05f, -4.6f, 0.75f);
    glDisable(GL_CULL_FACE);

    glDisable(GL_LIGHTING);
    glColor4f(1.0f, 0.9f, 0.6f, 0.6f);
    glBegin(GL_QUADS);
    glVertex3f(-2.0f, -0.82f, -4.0f);
    glVertex3f(2.0f, -0.82f, -4.0f);
    glVertex3f(2.0f, -0.52f, -4.0f);
    glVertex3f(-2.0f, -0.52f, -4.0f);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
