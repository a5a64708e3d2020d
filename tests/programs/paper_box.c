/* paper_box.c: the RayGL paper's example.
 *
 * Three faces of a box, each a different colour, placed with the plain
 * OpenGL calls glLoadIdentity(); glTranslatef(45, 45, 45);
 * glRotatef(45, 1, -1, 0) made between raygl calls: libraygl does not see
 * them, and must still place the box exactly (it records the modelview read
 * back from GL before the draw). GL gives the modelview the paper printed:
 *
 *     0.853553 -0.146447 0.5       (column 0)
 *    -0.146447  0.853553 0.5       (column 1)
 *    -0.5      -0.5      0.707107  (column 2)
 *     45        45       45        (column 3)
 *
 * which the program checks. The faces are +x, +y and +z of the cube
 * [-10, 10]^3; in eye space their normals have positive z, so an
 * orthographic camera looking down -z sees all three. The box sits at eye
 * z = 45 +- 17, in front of the near plane of glOrtho(..., -100, 100): a
 * negative near plane (z_eye = +100) is what frames it.
 */
#include "harness.h"

#include <math.h>
#include <stdio.h>

#include "raygl.h"

static int draw(int w, int h)
{
    double aspect = (double)w / (double)h;
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    /* The box's silhouette edges run at exactly 45 degrees through whole
     * pixel coordinates, hence through pixel centres, where GL's and
     * POV-Ray's tie rules differ: shift the view by (0.13, 0.37) pixel. */
    double px = 50.0 / (double)h;
    double dx = 0.13 * px, dy = 0.37 * px;
    rayglOrtho(45.0 - 25.0 * aspect + dx, 45.0 + 25.0 * aspect + dx, 20.0 + dy, 70.0 + dy, -100.0,
               100.0);
    rayglMatrixMode(GL_MODELVIEW);

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);

    /* The paper's transform, with the real GL calls. */
    glLoadIdentity();
    glTranslatef(45.0f, 45.0f, 45.0f);
    glRotatef(45.0f, 1.0f, -1.0f, 0.0f);

    static const GLfloat expect[16] = {0.853553f,  -0.146447f, 0.5f, 0,   -0.146447f, 0.853553f,
                                       0.5f,       0,          -0.5f, -0.5f, 0.707107f, 0,
                                       45,         45,         45,   1};
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    for (int i = 0; i < 16; i++)
        if (fabsf(m[i] - expect[i]) > 1e-5f) {
            fprintf(stderr, "paper_box: GL's modelview m[%d] = %g, the paper printed %g\n", i,
                    (double)m[i], (double)expect[i]);
            return 1;
        }

    rayglBegin(GL_QUADS);
    rayglColor3f(0.9f, 0.2f, 0.2f); /* +x */
    rayglVertex3f(10, -10, -10);
    rayglVertex3f(10, 10, -10);
    rayglVertex3f(10, 10, 10);
    rayglVertex3f(10, -10, 10);
    rayglColor3f(0.2f, 0.8f, 0.3f); /* +y */
    rayglVertex3f(-10, 10, -10);
    rayglVertex3f(-10, 10, 10);
    rayglVertex3f(10, 10, 10);
    rayglVertex3f(10, 10, -10);
    rayglColor3f(0.2f, 0.4f, 0.9f); /* +z */
    rayglVertex3f(-10, -10, 10);
    rayglVertex3f(10, -10, 10);
    rayglVertex3f(10, 10, 10);
    rayglVertex3f(-10, 10, 10);
    rayglEnd();

    /* A second object placed by a raygl call on top of a real one: the
     * recorder sees only the translation, GL's matrix is what counts. */
    glLoadIdentity();
    rayglTranslatef(45.0f + 20.0f * (float)aspect, 25.0f, 0.0f);
    rayglColor3f(1.0f, 0.9f, 0.3f);
    rayglBegin(GL_TRIANGLES);
    rayglVertex3f(-2.7f, -1.8f, 0.0f);
    rayglVertex3f(2.6f, -1.9f, 0.0f);
    rayglVertex3f(0.1f, 2.9f, 0.0f);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
