/* ortho.c: glOrtho with an off-centre volume, a negative near plane and an
 * aspect (6:5) unlike the viewport's (4:3), so GL stretches the image.
 *
 * Covers: the orthographic camera (position from the off-centre volume),
 * geometry with positive eye-space z (visible because near is -3, i.e. the
 * near plane is at z_eye = +3), near-plane clipping of a triangle that
 * crosses z_eye = +3, depth testing, a rotated cube.
 */
#include "harness.h"

#include "raygl.h"
#include "shapes.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglOrtho(-1.0, 5.0, -2.0, 3.0, -3.0, 10.0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);

    /* A cube around z_eye = 1: part of it lies at positive eye-space z. */
    rayglPushMatrix();
    rayglTranslatef(2.8f, 0.6f, 1.0f);
    rayglRotatef(40.0f, 0.3f, 1.0f, 0.2f);
    rayglScalef(1.1f, 1.1f, 1.1f);
    shape_cube(shape_face_colors);
    rayglPopMatrix();

    /* A triangle from z_eye = 1 to z_eye = 6: GL clips it at z_eye = 3, so
     * its right part is cut off along the vertical line x = 0. */
    rayglColor3f(1.0f, 0.7f, 0.2f);
    rayglBegin(GL_TRIANGLES);
    rayglVertex3f(-0.8f, -1.7f, 1.0f);
    rayglVertex3f(1.2f, 0.4f, 6.0f);
    rayglVertex3f(-0.8f, 2.7f, 1.0f);
    rayglEnd();

    /* A strip behind the cube, partly hidden by it. */
    rayglColor3f(0.3f, 0.5f, 1.0f);
    rayglBegin(GL_TRIANGLE_STRIP);
    rayglVertex3f(1.3f, -1.8f, -4.0f);
    rayglVertex3f(4.8f, -1.8f, -4.0f);
    rayglVertex3f(1.3f, -0.2f, -4.0f);
    rayglVertex3f(4.8f, 0.2f, -4.0f);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
