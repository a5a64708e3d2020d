/* perspective.c: a depth-tested 3D scene under gluPerspective + gluLookAt.
 *
 * Covers: the perspective camera (field of view, aspect from the viewport),
 * gluLookAt's view matrix, depth testing, a checkered floor receding to the
 * horizon, a cube with one colour per face, a pyramid as a triangle fan, and
 * a wall seen at a slant with one colour per corner, where GL interpolates
 * colours perspective-correctly (a screen-space interpolation would show).
 */
#include "harness.h"

#include "raygl.h"
#include "shapes.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(50.0, (double)w / (double)h, 1.0, 60.0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    raygluLookAt(5.0, 4.0, 7.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);
    rayglShadeModel(GL_SMOOTH);

    /* Floor: 10x10 checker on y = 0, from -5 to 5. */
    rayglBegin(GL_QUADS);
    for (int i = 0; i < 10; i++)
        for (int k = 0; k < 10; k++) {
            if ((i + k) % 2)
                rayglColor3f(0.85f, 0.85f, 0.8f);
            else
                rayglColor3f(0.25f, 0.3f, 0.35f);
            GLfloat x = (GLfloat)(i - 5), z = (GLfloat)(k - 5);
            rayglVertex3f(x, 0, z);
            rayglVertex3f(x, 0, z + 1);
            rayglVertex3f(x + 1, 0, z + 1);
            rayglVertex3f(x + 1, 0, z);
        }
    rayglEnd();

    /* The cube floats 0.05 above the floor: no face is coplanar with it. */
    rayglPushMatrix();
    rayglTranslatef(0.3f, 1.05f, 0.2f);
    shape_cube(shape_face_colors);
    rayglPopMatrix();

    /* A pyramid: apex and four sides as a fan, one colour per rim vertex. */
    rayglBegin(GL_TRIANGLE_FAN);
    rayglColor3f(1.0f, 1.0f, 1.0f);
    rayglVertex3f(2.8f, 2.2f, -2.0f);
    rayglColor3f(1.0f, 0.5f, 0.0f);
    rayglVertex3f(2.0f, 0.0f, -1.2f);
    rayglColor3f(0.0f, 0.6f, 1.0f);
    rayglVertex3f(3.6f, 0.0f, -1.2f);
    rayglColor3f(0.5f, 1.0f, 0.0f);
    rayglVertex3f(3.6f, 0.0f, -2.8f);
    rayglColor3f(1.0f, 0.0f, 0.5f);
    rayglVertex3f(2.0f, 0.0f, -2.8f);
    rayglColor3f(1.0f, 0.5f, 0.0f);
    rayglVertex3f(2.0f, 0.0f, -1.2f);
    rayglEnd();

    /* A wall seen at a slant; colours interpolate perspective-correctly.
     * It stays wholly in view: Mesa splits a GL_QUADS quad along v0-v2, but
     * along another diagonal once the quad is clipped (docs/testing.md), and
     * with these non-affine corner colours that would show. */
    rayglBegin(GL_QUADS);
    rayglColor3f(1.0f, 0.0f, 0.0f);
    rayglVertex3f(-4.5f, 0.0f, 1.5f);
    rayglColor3f(0.0f, 1.0f, 0.0f);
    rayglVertex3f(-4.5f, 0.0f, -4.0f);
    rayglColor3f(0.0f, 0.0f, 1.0f);
    rayglVertex3f(-4.5f, 2.5f, -4.0f);
    rayglColor3f(1.0f, 1.0f, 0.0f);
    rayglVertex3f(-4.5f, 2.5f, 1.5f);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
