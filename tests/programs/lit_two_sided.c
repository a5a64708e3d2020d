/* lit_two_sided.c: GL_LIGHT_MODEL_TWO_SIDE with different GL_FRONT and
 * GL_BACK materials on open surfaces seen partly from inside: a bowl (the
 * lower half of a sphere, opening toward the viewer and up) and a tube
 * (an open cylinder). Back faces take the back material and the reversed
 * normal. Local viewer.
 */
#include "lit_scene.h"

static void half_sphere(float cx, float cy, float cz, float r)
{
    glBegin(GL_TRIANGLES);
    for (int i = LIT_STACKS / 2 - 8; i < LIT_STACKS; i++) {
        double t0 = M_PI * i / LIT_STACKS, t1 = M_PI * (i + 1) / LIT_STACKS;
        for (int j = 0; j < LIT_SLICES; j++) {
            double p0 = 2 * M_PI * j / LIT_SLICES, p1 = 2 * M_PI * (j + 1) / LIT_SLICES;
            double th[4] = {t0, t1, t1, t0}, ph[4] = {p0, p0, p1, p1};
            float n[4][3];
            for (int k = 0; k < 4; k++) {
                /* the pole axis tilted toward the viewer */
                double x = sin(th[k]) * cos(ph[k]), y = cos(th[k]), z = -sin(th[k]) * sin(ph[k]);
                double c = cos(0.6), s = sin(0.6);
                n[k][0] = (float)x;
                n[k][1] = (float)(c * y - s * z);
                n[k][2] = (float)(s * y + c * z);
            }
            static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int t = 0; t < 2; t++)
                for (int k = 0; k < 3; k++) {
                    const float *v = n[tri[t][k]];
                    glNormal3f(v[0], v[1], v[2]);
                    glVertex3f(cx + r * v[0], cy + r * v[1], cz + r * v[2]);
                }
        }
    }
    glEnd();
}

static void tube(float cx, float cy, float cz, float r, float len)
{
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= LIT_SLICES; j++) {
        double p = 2 * M_PI * j / LIT_SLICES;
        /* axis along (0.5, 0.2, 1), roughly toward the viewer */
        double a[3] = {0.45, 0.2, 0.87}, u[3] = {0.87, 0, -0.45}, v[3];
        double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), lu = sqrt(u[0] * u[0] + u[2] * u[2]);
        for (int k = 0; k < 3; k++) {
            a[k] /= la;
            u[k] /= lu;
        }
        double au = a[0] * u[0] + a[1] * u[1] + a[2] * u[2];
        for (int k = 0; k < 3; k++)
            u[k] -= au * a[k];
        lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (int k = 0; k < 3; k++)
            u[k] /= lu;
        v[0] = a[1] * u[2] - a[2] * u[1];
        v[1] = a[2] * u[0] - a[0] * u[2];
        v[2] = a[0] * u[1] - a[1] * u[0];
        float n[3];
        for (int k = 0; k < 3; k++)
            n[k] = (float)(cos(p) * u[k] + sin(p) * v[k]);
        glNormal3f(n[0], n[1], n[2]);
        glVertex3f(cx + r * n[0] + (float)(len / 2 * a[0]), cy + r * n[1] + (float)(len / 2 * a[1]),
                   cz + r * n[2] + (float)(len / 2 * a[2]));
        glVertex3f(cx + r * n[0] - (float)(len / 2 * a[0]), cy + r * n[1] - (float)(len / 2 * a[1]),
                   cz + r * n[2] - (float)(len / 2 * a[2]));
    }
    glEnd();
}

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
#ifdef LIT_TWO_SIDED_EXTRA
    LIT_TWO_SIDED_EXTRA;
#endif
    GLfloat pos[4] = {0.5f, 2.0f, 0.5f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    GLfloat fd[4] = {0.85f, 0.3f, 0.2f, 1.0f}, bd[4] = {0.2f, 0.5f, 0.85f, 1.0f};
    GLfloat fs[4] = {0.5f, 0.5f, 0.5f, 1.0f}, bs[4] = {0.2f, 0.2f, 0.2f, 1.0f};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, fd);
    glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, bd);
    glMaterialfv(GL_FRONT, GL_SPECULAR, fs);
    glMaterialfv(GL_BACK, GL_SPECULAR, bs);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    glMaterialf(GL_BACK, GL_SHININESS, 10.0f);
#ifdef LIT_TWO_SIDED_MATERIALS
    LIT_TWO_SIDED_MATERIALS;
#endif
    half_sphere(-0.9f, 0.1f, -5.0f, 0.85f);
    tube(1.0f, 0.0f, -5.5f, 0.5f, 1.6f);
    return 0;
}

RGL_TEST_MAIN(draw)
