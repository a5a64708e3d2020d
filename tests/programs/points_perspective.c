/* points_perspective.c: points under gluPerspective at depths from 3 to 30.
 *
 * A point's size is in pixels whatever its distance: near and far points of
 * one size must come out as the same s x s squares. A 6x5 grid on screen,
 * one size per column (2 to 12 pixels), each point at its own depth (the
 * depths are mixed so that neighbours differ), each its own colour. The
 * eye-space positions are computed from the screen positions wanted.
 */
#include "harness.h"

#include <math.h>

#include "raygl.h"

static int draw(int w, int h)
{
    const double fovy = 60.0, aspect = (double)w / (double)h;
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(fovy, aspect, 1.0, 100.0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();

    rayglClearColor(0.05f, 0.05f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);

    static const GLfloat sizes[5] = {2, 4, 6, 9, 12};
    static const double depth[6] = {3, 30, 7, 18, 4.5, 11};
    const double ty = tan(fovy * M_PI / 360.0), tx = ty * aspect;
    for (int k = 0; k < 5; k++) {
        rayglPointSize(sizes[k]);
        rayglBegin(GL_POINTS);
        for (int i = 0; i < 6; i++) {
            double z = depth[(i + 2 * k) % 6];
            double nx = -0.8 + 0.4 * k + 0.013, ny = -0.75 + 0.3 * i + 0.021;
            rayglColor3f(0.2f + 0.16f * (float)i, 1.0f - 0.15f * (float)k, 0.3f + 0.12f * (float)k);
            rayglVertex3d(nx * tx * z, ny * ty * z, -z);
        }
        rayglEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
