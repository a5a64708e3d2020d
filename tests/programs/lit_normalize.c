/* lit_normalize.c: normals that are not unit length in eye space, made so
 * by GL itself: a sphere squashed by a non-uniform glScalef under
 * GL_NORMALIZE (the normals take the inverse transpose, then unit length),
 * a torus under a uniform glScalef(0.6) with GL_RESCALE_NORMAL, and a small
 * sphere whose glNormal3f are 2.5 long, under GL_NORMALIZE. GL lights all
 * three with unit normals; so does POV-Ray, which always normalises.
 * Local viewer.
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);

    glEnable(GL_NORMALIZE);
    lit_material(0.8f, 0.3f, 0.25f, 0.5f, 30.0f);
    glPushMatrix();
    glTranslatef(-1.0f, 0.1f, -5.0f);
    glScalef(1.2f, 0.75f, 0.9f);
    lit_sphere(0, 0, 0, 0.8f);
    glPopMatrix();
    glDisable(GL_NORMALIZE);

    glEnable(GL_RESCALE_NORMAL);
    lit_material(0.25f, 0.6f, 0.35f, 0.5f, 30.0f);
    glPushMatrix();
    glTranslatef(1.0f, -0.05f, -5.2f);
    glScalef(0.6f, 0.6f, 0.6f);
    lit_torus(0, 0, 0, 1.05f, 0.43f, 0.3f, 0.8f, 0.55f);
    glPopMatrix();
    glDisable(GL_RESCALE_NORMAL);

    /* glNormal3f of length 2.5: lit_vertex takes the unit normal, so draw
     * by hand with scaled normals. */
    glEnable(GL_NORMALIZE);
    lit_material(0.3f, 0.35f, 0.8f, 0.5f, 30.0f);
    const float cx = 0.05f, cy = -0.95f, cz = -4.5f, r = 0.3f;
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < LIT_STACKS; i++) {
        double t0 = M_PI * i / LIT_STACKS, t1 = M_PI * (i + 1) / LIT_STACKS;
        for (int j = 0; j < LIT_SLICES; j++) {
            double p0 = 2 * M_PI * j / LIT_SLICES, p1 = 2 * M_PI * (j + 1) / LIT_SLICES;
            double th[4] = {t0, t1, t1, t0}, ph[4] = {p0, p0, p1, p1};
            static const int tri[6] = {0, 1, 2, 0, 2, 3};
            for (int k = 0; k < 6; k++) {
                double t = th[tri[k]], p = ph[tri[k]];
                float n[3] = {(float)(sin(t) * cos(p)), (float)cos(t), (float)(-sin(t) * sin(p))};
                glNormal3f(2.5f * n[0], 2.5f * n[1], 2.5f * n[2]);
                glVertex3f(cx + r * n[0], cy + r * n[1], cz + r * n[2]);
            }
        }
    }
    glEnd();
    glDisable(GL_NORMALIZE);
    return 0;
}

RGL_TEST_MAIN(draw)
