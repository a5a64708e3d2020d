/* transforms.c: nested modelview transforms under glOrtho.
 *
 * Covers: glPushMatrix/glPopMatrix nesting (an articulated arm, and a chain
 * six levels deep, each part nearer than its parent so that depth decides
 * the overlaps), glTranslate/glRotate/glScale in float and double forms,
 * rotation about an oblique axis (a depth-tested cube), non-uniform scale,
 * a mirroring scale (an asymmetric "F" drawn with x negated), glMultMatrixf
 * (a shear) and glLoadMatrixd (a whole matrix replacing the stack top).
 */
#include "harness.h"

#include <math.h>

#include "raygl.h"
#include "shapes.h"

static void triangle(void)
{
    rayglBegin(GL_TRIANGLES);
    rayglVertex2f(0.0f, -0.3f);
    rayglVertex2f(0.6f, 0.0f);
    rayglVertex2f(0.0f, 0.3f);
    rayglEnd();
}

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    /* Shifted by (0.13, 0.37) pixel at 320x240, so that edges between
     * whole-pixel vertices do not run through pixel centres. */
    rayglOrtho(-4 + 0.00325, 4 + 0.00325, -3 + 0.00925, 3 + 0.00925, -10, 10);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();

    rayglClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    rayglClearDepth(1.0);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);

    /* An articulated arm: base, upper arm, hand. */
    rayglPushMatrix();
    rayglTranslatef(-3.6f, -2.6f, 0.0f);
    rayglRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    rayglColor3f(0.9f, 0.5f, 0.1f);
    shape_rect(0.0f, -0.25f, 2.0f, 0.25f);
    /* Each part sits 0.2 nearer than its parent, so overlaps at the joints
     * are decided by depth, not by drawing order. */
    rayglTranslatef(2.0f, 0.0f, 0.2f);
    rayglRotatef(50.0f, 0.0f, 0.0f, 1.0f);
    rayglPushMatrix();
    rayglScalef(1.5f, 0.3f, 1.0f);
    rayglColor3f(0.3f, 0.9f, 0.4f);
    shape_rect(0.0f, -0.5f, 1.0f, 0.5f);
    rayglPopMatrix();
    rayglTranslatef(1.5f, 0.0f, 0.2f);
    rayglRotatef(-70.0f, 0.0f, 0.0f, 1.0f);
    rayglScaled(1.4, 1.4, 1.0);
    rayglColor3f(0.4f, 0.5f, 1.0f);
    triangle();
    rayglPopMatrix();

    /* A cube turned about an oblique axis, in doubles. */
    rayglPushMatrix();
    rayglTranslated(2.4, 1.3, 0.0);
    rayglRotated(35.0, 1.0, 1.0, 0.3);
    rayglScaled(0.8, 0.8, 0.8);
    shape_cube(shape_face_colors);
    rayglPopMatrix();

    /* A shear through glMultMatrixf: x += 0.6 y. */
    static const GLfloat shear[16] = {1, 0, 0, 0, 0.6f, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    rayglPushMatrix();
    rayglTranslatef(-3.5f, 0.9f, 0.0f);
    rayglMultMatrixf(shear);
    rayglColor3f(0.95f, 0.95f, 0.3f);
    shape_rect(0.0f, 0.0f, 1.2f, 1.6f);
    rayglPopMatrix();

    /* glLoadMatrixd replaces the top of the stack: translate (0.7, -0.5),
     * rotate 30 degrees about z, scale y by 0.5. */
    double c30 = cos(M_PI / 6), s30 = sin(M_PI / 6);
    const GLdouble m[16] = {c30, s30, 0, 0, -0.5 * s30, 0.5 * c30, 0, 0,
                            0,   0,   1, 0, 0.7,        -0.5,      0, 1};
    rayglPushMatrix();
    rayglLoadMatrixd(m);
    rayglColor3f(1.0f, 0.4f, 0.7f);
    shape_rect(-0.8f, -0.8f, 0.8f, 0.8f);
    rayglPopMatrix();

    /* A mirrored "F": drawn with x negated, its arms point left. */
    rayglPushMatrix();
    rayglTranslatef(-0.2f, 1.0f, 0.0f);
    rayglScalef(-1.0f, 1.0f, 1.0f);
    rayglColor3f(0.6f, 0.9f, 0.9f);
    shape_rect(0.0f, 0.0f, 0.3f, 1.8f);
    shape_rect(0.3f, 1.5f, 1.3f, 1.8f);
    shape_rect(0.3f, 0.8f, 0.9f, 1.1f);
    rayglPopMatrix();

    /* A chain six levels deep. */
    rayglPushMatrix();
    rayglTranslatef(0.6f, -2.6f, 0.0f);
    for (int i = 0; i < 6; i++) {
        rayglPushMatrix();
        rayglTranslatef(0.5f, 0.0f, 0.1f);
        rayglRotatef(14.0f, 0.0f, 0.0f, 1.0f);
        rayglScalef(0.93f, 0.93f, 1.0f);
        rayglColor3f(0.3f + 0.12f * (float)i, 0.2f, 0.9f - 0.12f * (float)i);
        triangle();
    }
    for (int i = 0; i < 6; i++)
        rayglPopMatrix();
    rayglPopMatrix();

    /* After all the pops the modelview is the identity again. */
    rayglColor3f(0.8f, 0.8f, 0.8f);
    shape_rect(3.2f, -2.8f, 3.8f, -2.2f);
    return 0;
}

RGL_TEST_MAIN(draw)
