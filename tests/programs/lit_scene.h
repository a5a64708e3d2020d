/* lit_scene.h: the lit test scene shared by the lighting image tests
 * (tests/programs/lit_*.c, blend_*.c, fog_*.c, shadow.c).
 *
 * A finely tessellated sphere and torus drawn with plain glBegin
 * triangles and per-vertex normals (no GLU/GLUT), under a perspective
 * camera at the origin looking down -z. Each program sets its lights and
 * materials, then draws. Header-only: each program includes it once.
 */
#ifndef RGL_TEST_LIT_SCENE_H
#define RGL_TEST_LIT_SCENE_H

#include "harness.h"

#include <math.h>
#include <raygl/gl.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define LIT_SLICES 96
#define LIT_STACKS 64

/* Camera and clear: fovy 40, near 1, far 30, dark grey background, depth
 * test, smooth shading, lighting on, no light enabled yet. The view is
 * shifted by a fraction of a pixel so that no edge runs through pixel
 * centres. */
static inline void lit_begin(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, 0);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
}

/* Optional per-vertex colour of the sphere and torus (for
 * GL_COLOR_MATERIAL): a smooth function of the normal. */
static int lit_vertex_colours;

static inline void lit_vertex(float nx, float ny, float nz, float x, float y, float z)
{
    if (lit_vertex_colours)
        glColor4f(0.5f + 0.45f * nx, 0.5f + 0.45f * ny, 0.6f - 0.35f * nz, 1.0f);
    glNormal3f(nx, ny, nz);
    glVertex3f(x, y, z);
}

/* Sphere of radius r at (cx, cy, cz), outward normals, counter-clockwise
 * seen from outside. */
static inline void lit_sphere(float cx, float cy, float cz, float r)
{
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < LIT_STACKS; i++) {
        double t0 = M_PI * i / LIT_STACKS, t1 = M_PI * (i + 1) / LIT_STACKS;
        for (int j = 0; j < LIT_SLICES; j++) {
            double p0 = 2 * M_PI * j / LIT_SLICES, p1 = 2 * M_PI * (j + 1) / LIT_SLICES;
            double th[4] = {t0, t1, t1, t0}, ph[4] = {p0, p0, p1, p1};
            float n[4][3];
            for (int k = 0; k < 4; k++) {
                n[k][0] = (float)(sin(th[k]) * cos(ph[k]));
                n[k][1] = (float)cos(th[k]);
                n[k][2] = (float)(-sin(th[k]) * sin(ph[k]));
            }
            static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int t = 0; t < 2; t++) { /* at the poles one is degenerate: GL draws nothing */
                for (int k = 0; k < 3; k++) {
                    const float *v = n[tri[t][k]];
                    lit_vertex(v[0], v[1], v[2], cx + r * v[0], cy + r * v[1], cz + r * v[2]);
                }
            }
        }
    }
    glEnd();
}

/* Torus around the axis (ax, ay, az) through (cx, cy, cz): ring radius R,
 * tube radius r, outward normals. The axis is the ring's normal. */
static inline void lit_torus(float cx, float cy, float cz, float R, float r, float ax, float ay, float az)
{
    /* An orthonormal frame (u, v, a) from the axis. */
    double a[3] = {ax, ay, az}, l = sqrt(ax * ax + ay * ay + az * az);
    for (int k = 0; k < 3; k++)
        a[k] /= l;
    double u[3] = {a[1], -a[0], 0};
    if (fabs(a[2]) > 0.9)
        u[0] = 1, u[1] = 0, u[2] = 0;
    double d = u[0] * a[0] + u[1] * a[1] + u[2] * a[2];
    for (int k = 0; k < 3; k++)
        u[k] -= d * a[k];
    l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++)
        u[k] /= l;
    double v[3] = {a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2], a[0] * u[1] - a[1] * u[0]};
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < LIT_SLICES; i++)
        for (int j = 0; j < LIT_STACKS; j++) {
            double s[4] = {i, i + 1, i + 1, i}, t[4] = {j, j, j + 1, j + 1};
            float pos[4][3], nor[4][3];
            for (int k = 0; k < 4; k++) {
                double ps = 2 * M_PI * s[k] / LIT_SLICES, pt = 2 * M_PI * t[k] / LIT_STACKS;
                for (int c = 0; c < 3; c++) {
                    double ring = cos(ps) * u[c] + sin(ps) * v[c];
                    double n = cos(pt) * ring + sin(pt) * a[c];
                    nor[k][c] = (float)n;
                    pos[k][c] = (float)((c == 0 ? cx : c == 1 ? cy : cz) + R * ring + r * n);
                }
            }
            static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int q = 0; q < 2; q++)
                for (int k = 0; k < 3; k++) {
                    const int m = tri[q][k];
                    lit_vertex(nor[m][0], nor[m][1], nor[m][2], pos[m][0], pos[m][1], pos[m][2]);
                }
        }
    glEnd();
}

/* A material: ambient and diffuse d, specular s (grey), shininess, on
 * GL_FRONT_AND_BACK. */
static inline void lit_material(float r, float g, float b, float s, float shininess)
{
    GLfloat amb[4] = {r, g, b, 1}, dif[4] = {r, g, b, 1}, spe[4] = {s, s, s, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spe);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

/* The standard pair: a sphere on the left, a torus on the right tilted
 * toward the viewer. */
static inline void lit_pair(void)
{
    lit_sphere(-0.95f, 0.05f, -5.0f, 0.85f);
    lit_torus(1.0f, -0.05f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);
}

#endif
