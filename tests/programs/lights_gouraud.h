/* lights_gouraud.h: where GL's per-vertex lighting (Gouraud) and POV-Ray's
 * per-pixel lighting part: a large floor quad (four vertices) under a point
 * light close above it, whose highlight and falloff GL interpolates from
 * the corners, and a sphere of 8 x 6 facets with smooth normals. Included
 * by lights_gouraud_local.c (local viewer), lights_gouraud_infinite.c and
 * lights_gouraud_vertex.c (local viewer, translated with --vertex-lighting).
 */
#ifndef RGL_TEST_LIGHTS_GOURAUD_H
#define RGL_TEST_LIGHTS_GOURAUD_H

#include "lit_scene.h"

static inline void gouraud_scene(int w, int h, int local)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local ? GL_TRUE : GL_FALSE);
    GLfloat pos[4] = {0.3f, 0.4f, -4.5f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.6f, 0.65f, 0.7f, 0.6f, 20.0f);
    /* two triangles, so that the diagonal is the program's, not a quad
     * split's */
    glBegin(GL_TRIANGLES);
    glNormal3f(0, 1, 0);
    glVertex3f(-4.0f, -1.0f, -2.5f);
    glVertex3f(4.0f, -1.0f, -2.5f);
    glVertex3f(4.0f, -1.0f, -9.0f);
    glVertex3f(-4.0f, -1.0f, -2.5f);
    glVertex3f(4.0f, -1.0f, -9.0f);
    glVertex3f(-4.0f, -1.0f, -9.0f);
    glEnd();
    lit_material(0.8f, 0.35f, 0.3f, 0.6f, 30.0f);
    const int slices = 8, stacks = 6;
    const float cx = -0.9f, cy = 0.3f, cz = -5.5f, r = 0.6f;
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < stacks; i++)
        for (int j = 0; j < slices; j++) {
            double th[4] = {M_PI * i / stacks, M_PI * (i + 1) / stacks, M_PI * (i + 1) / stacks,
                            M_PI * i / stacks};
            double ph[4] = {2 * M_PI * j / slices, 2 * M_PI * j / slices,
                            2 * M_PI * (j + 1) / slices, 2 * M_PI * (j + 1) / slices};
            float n[4][3];
            for (int k = 0; k < 4; k++) {
                n[k][0] = (float)(sin(th[k]) * cos(ph[k]));
                n[k][1] = (float)cos(th[k]);
                n[k][2] = (float)(-sin(th[k]) * sin(ph[k]));
            }
            static const int t[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int q = 0; q < 2; q++)
                for (int k = 0; k < 3; k++) {
                    const float *v = n[t[q][k]];
                    lit_vertex(v[0], v[1], v[2], cx + r * v[0], cy + r * v[1], cz + r * v[2]);
                }
        }
    glEnd();
}

#endif
