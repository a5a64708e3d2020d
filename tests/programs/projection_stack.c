/* projection_stack.c: two projections in one frame through the projection
 * matrix stack, as programs draw a 3D scene and then a 2D overlay.
 *
 * Covers: glMatrixMode(GL_PROJECTION) with glPushMatrix/glPopMatrix, a
 * perspective scene (a depth-tested cube), then gluOrtho2D overlay shapes
 * drawn with the modelview stack pushed and reset, then the scene again
 * after both pops (the projection and modelview must be the restored
 * ones). The overlay does not overlap the scene: which one GL shows where
 * they overlap is a matter of depth testing, not of the matrix stacks.
 */
#include "harness.h"

#include "raygl.h"
#include "shapes.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(50.0, (double)w / (double)h, 1.0, 50.0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.0f, 0.3f, -7.0f);
    rayglRotatef(30.0f, 1.0f, 1.0f, 0.0f);

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);
    shape_cube(shape_face_colors);

    /* The overlay: a bar and a triangle in window coordinates. */
    rayglMatrixMode(GL_PROJECTION);
    rayglPushMatrix();
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglPushMatrix();
    rayglLoadIdentity();
    rayglColor3f(0.2f, 0.9f, 0.4f);
    shape_rect(10.3f, 10.4f, 150.3f, 36.4f);
    rayglColor3f(1.0f, 0.9f, 0.2f);
    rayglBegin(GL_TRIANGLES);
    rayglVertex2f(262.3f, 12.4f);
    rayglVertex2f(310.3f, 14.4f);
    rayglVertex2f(290.3f, 60.4f);
    rayglEnd();
    rayglPopMatrix();
    rayglMatrixMode(GL_PROJECTION);
    rayglPopMatrix();
    rayglMatrixMode(GL_MODELVIEW);

    /* Back in the scene: a slab beside the cube. */
    static const GLfloat grey[6][3] = {{0.8f, 0.8f, 0.8f}, {0.5f, 0.5f, 0.5f}, {0.9f, 0.9f, 0.9f},
                                       {0.4f, 0.4f, 0.4f}, {0.7f, 0.7f, 0.7f}, {0.6f, 0.6f, 0.6f}};
    rayglTranslatef(2.4f, 0.0f, 0.0f);
    rayglScalef(0.3f, 1.2f, 0.3f);
    shape_cube(grey);
    return 0;
}

RGL_TEST_MAIN(draw)
