/* texcopy_points.c: points whose size follows their distance from the eye
 * (glPointParameter, GL 1.4 3.3): size 24 attenuated by 1 / sqrt(a + b d +
 * c d^2) with (a, b, c) = (0, 0, 0.02), clamped to [3, 14] pixels, under
 * gluPerspective at depths 3 to 30; a 6 x 4 grid, one colour per point.
 */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static int draw(int w, int h)
{
    const double fovy = 60.0, aspect = (double)w / (double)h;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(fovy, aspect, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.05f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    static const GLfloat atten[3] = {0, 0, 0.02f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    glPointParameterf(GL_POINT_SIZE_MIN, 3);
    glPointParameteri(GL_POINT_SIZE_MAX, 14);
    glPointSize(24);
    static const double depth[6] = {3, 30, 7, 18, 4.5, 11};
    const double ty = tan(fovy * M_PI / 360.0), tx = ty * aspect;
    glBegin(GL_POINTS);
    for (int k = 0; k < 4; k++)
        for (int i = 0; i < 6; i++) {
            double z = depth[(i + 2 * k) % 6];
            double nx = -0.75 + 0.3 * i + 0.013, ny = -0.7 + 0.45 * k + 0.021;
            glColor3f(0.2f + 0.16f * (float)i, 1.0f - 0.2f * (float)k, 0.3f + 0.15f * (float)k);
            glVertex3d(nx * tx * z, ny * ty * z, -z);
        }
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
