/* frustum.c: an off-axis glFrustum (left != -right, bottom != -top) whose
 * aspect differs from the viewport's, so GL stretches the image.
 *
 * Covers: the off-axis perspective camera (direction not along -z), the
 * stretch when frustum and viewport aspects differ (the test runs at
 * 400x200), depth testing between interpenetrating objects.
 */
#include "harness.h"

#include <math.h>

#include "raygl.h"
#include "shapes.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglFrustum(-0.35, 0.65, -0.25, 0.45, 1.0, 30.0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.5f, 1.0f, -10.0f);
    rayglRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    rayglRotatef(-30.0f, 0.0f, 1.0f, 0.0f);

    rayglClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);

    /* A cube pierced by a long slab: depth decides which shows where. */
    shape_cube(shape_face_colors);
    static const GLfloat slab[6][3] = {{1.0f, 1.0f, 1.0f}, {0.6f, 0.6f, 0.6f}, {0.9f, 0.9f, 0.5f},
                                       {0.5f, 0.5f, 0.3f}, {0.7f, 0.8f, 1.0f}, {0.4f, 0.5f, 0.7f}};
    rayglPushMatrix();
    rayglRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    rayglScalef(2.6f, 0.3f, 0.4f);
    shape_cube(slab);
    rayglPopMatrix();

    /* A ground ring of triangles around the cube, near and far. */
    rayglBegin(GL_TRIANGLES);
    for (int i = 0; i < 12; i++) {
        float a = (float)i * 0.5235988f;
        float x = 3.0f * cosf(a), z = 3.0f * sinf(a);
        rayglColor3f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 0.4f);
        rayglVertex3f(x - 0.4f, -1.2f, z + 0.3f);
        rayglVertex3f(x + 0.4f, -1.2f, z + 0.3f);
        rayglVertex3f(x, -0.5f, z - 0.3f);
    }
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
