/* lit_vmat_two_side.c: a lit, shiny half-cylinder drawn as quad strips
 * with glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE) before every
 * vertex, under two-sided lighting, all eight lights configured and five
 * enabled (directional and positional), wound so that the faces seen are
 * back faces: GL lights them with the back material (the same colours) and
 * the normal turned. POV-Ray's interior_texture is one texture for the
 * whole mesh, so such back faces take GL's lit colours per vertex
 * (interp_relit.c).
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    for (int i = 0; i < 8; i++) {
        GLfloat pos[4] = {(float)(i % 3) - 1.0f, 1.0f + 0.2f * (float)i, 2.0f, (float)(i & 1)};
        GLfloat dif[4] = {0.12f + 0.02f * (float)i, 0.12f, 0.11f, 1};
        GLfloat spe[4] = {0.3f, 0.3f, 0.3f, 1}, amb[4] = {0.02f, 0.02f, 0.02f, 1};
        glLightfv(GL_LIGHT0 + i, GL_POSITION, pos);
        glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, dif);
        glLightfv(GL_LIGHT0 + i, GL_SPECULAR, spe);
        glLightfv(GL_LIGHT0 + i, GL_AMBIENT, amb);
        if (i < 5)
            glEnable(GL_LIGHT0 + i);
    }
    GLfloat spec[4] = {0.8f, 0.8f, 0.8f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    for (int i = 0; i < 24; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= 32; j++)
            for (int k = 0; k < 2; k++) {
                float a = (float)(i + k) / 24.0f * 3.14159f;
                float x = -1.6f + 3.2f * (float)j / 32.0f;
                GLfloat col[4] = {0.4f + 0.3f * sinf(x), 0.5f, 0.4f + 0.3f * cosf(a), 1};
                glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, col);
                glNormal3f(0, -cosf(a), sinf(a));
                glVertex3f(x, -cosf(a), -5.0f + sinf(a));
            }
        glEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
