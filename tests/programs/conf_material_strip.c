/* conf_material_strip.c: a lit, shiny surface drawn as quad strips with
 * glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE) before every
 * vertex (a colour that varies smoothly over it), under all eight lights
 * configured (dim, coloured, directional and positional) and a white
 * specular: a wavy sheet seen from above. Local viewer. */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    for (int i = 0; i < 8; i++) {
        GLfloat c[4] = {0.12f + 0.03f * (float)(i % 3), 0.1f + 0.02f * (float)i, 0.14f - 0.01f * (float)i, 1};
        GLfloat p[4] = {-3.0f + (float)i, 2.0f + 0.3f * (float)(i % 2), -3.0f - 0.2f * (float)i,
                        i % 3 == 0 ? 0.0f : 1.0f};
        glLightfv(GL_LIGHT0 + i, GL_POSITION, p);
        glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, c);
        glLightfv(GL_LIGHT0 + i, GL_SPECULAR, c);
        glEnable(GL_LIGHT0 + i);
    }
    GLfloat spec[4] = {0.8f, 0.8f, 0.8f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 50.0f);
    const int n = 48;
    for (int j = 0; j < n; j++) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= n; i++)
            for (int k = 0; k < 2; k++) {
                float u = (float)i / n, v = (float)(j + k) / n;
                float x = -2.2f + 4.4f * u, z = -3.5f - 3.0f * v;
                float y = -1.2f + 0.25f * sinf(6.0f * u) * cosf(5.0f * v);
                float dx = 0.25f * 6.0f * cosf(6.0f * u) * cosf(5.0f * v) / 4.4f;
                float dz = -0.25f * 5.0f * sinf(6.0f * u) * sinf(5.0f * v) / -3.0f;
                GLfloat col[4] = {0.3f + 0.6f * u, 0.3f + 0.5f * v, 0.8f - 0.5f * u, 1};
                glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, col);
                glNormal3f(-dx, 1.0f, -dz);
                glVertex3f(x, y, z);
            }
        glEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
