/* culling.c: face culling, written with plain gl* calls and the drop-in
 * header.
 *
 * Top two rows, one column per setting, a counter-clockwise triangle above a
 * clockwise one:
 *   culling off | cull GL_BACK | cull GL_FRONT | glFrontFace(GL_CW) + cull GL_BACK
 * Bottom row, with cull GL_BACK and counter-clockwise front faces:
 *   - a mirrored pair (glScalef(-1, 1, 1) flips the window-space winding:
 *     the quad wound counter-clockwise in object space is culled, the
 *     clockwise triangle is drawn);
 *   - two triangle strips, one starting counter-clockwise (drawn whole: the
 *     odd triangles' reversed order does not make them back faces), one
 *     starting clockwise (culled whole);
 *   - a cube with the depth test off: only culling hides its back faces;
 *   - GL_FRONT_AND_BACK: the triangle is culled, the line loop around it
 *     is drawn (culling applies to polygons only).
 * Culling happens in window space, under a perspective projection here.
 */
#include "harness.h"

#include <raygl/gl.h>

#include "shapes.h"

static void tri(GLfloat x, GLfloat y, int ccw)
{
    glBegin(GL_TRIANGLES);
    glVertex3f(x - 1.0f, y - 0.7f, 0.0f);
    if (ccw) {
        glVertex3f(x + 1.0f, y - 0.7f, 0.0f);
        glVertex3f(x, y + 0.8f, 0.0f);
    } else {
        glVertex3f(x, y + 0.8f, 0.0f);
        glVertex3f(x + 1.0f, y - 0.7f, 0.0f);
    }
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -12.0f);

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    static const GLfloat col_x[4] = {-4.8f, -1.6f, 1.6f, 4.8f};
    for (int c = 0; c < 4; c++) {
        switch (c) {
        case 0:
            glDisable(GL_CULL_FACE);
            break;
        case 1:
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            glFrontFace(GL_CCW);
            break;
        case 2:
            glCullFace(GL_FRONT);
            break;
        case 3:
            glFrontFace(GL_CW);
            glCullFace(GL_BACK);
            break;
        }
        glColor3f(0.9f, 0.3f + 0.2f * (float)c, 0.2f);
        tri(col_x[c], 3.0f, 1);
        glColor3f(0.2f, 0.4f + 0.15f * (float)c, 0.95f);
        tri(col_x[c], 0.8f, 0);
    }

    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);

    /* Mirrored: windings flip in window space. */
    glPushMatrix();
    glTranslatef(-5.0f, -2.6f, 0.0f);
    glScalef(-1.0f, 1.0f, 1.0f);
    glColor3f(1.0f, 0.0f, 0.0f); /* culled */
    shape_rect(-0.6f, -0.6f, 0.6f, 0.6f);
    glColor3f(0.2f, 1.0f, 0.4f); /* drawn */
    tri(0.0f, 0.0f, 0);
    glPopMatrix();

    /* Strips: the first starts counter-clockwise, the second clockwise. */
    glColor3f(1.0f, 0.85f, 0.3f);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex3f(-3.9f, -3.4f, 0.0f);
    glVertex3f(-2.5f, -3.3f, 0.0f);
    glVertex3f(-4.0f, -2.5f, 0.0f);
    glVertex3f(-2.6f, -2.3f, 0.0f);
    glVertex3f(-3.8f, -1.6f, 0.0f);
    glVertex3f(-2.4f, -1.5f, 0.0f);
    glEnd();
    glColor3f(1.0f, 0.0f, 1.0f); /* culled */
    glBegin(GL_TRIANGLE_STRIP);
    glVertex3f(-1.5f, -3.3f, 0.0f);
    glVertex3f(-2.2f, -3.4f, 0.0f);
    glVertex3f(-1.4f, -2.3f, 0.0f);
    glVertex3f(-2.3f, -2.5f, 0.0f);
    glEnd();

    /* A cube, depth test off: culling alone hides the back faces. */
    glDisable(GL_DEPTH_TEST);
    glPushMatrix();
    glTranslatef(1.0f, -2.5f, 0.0f);
    glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-40.0f, 0.0f, 1.0f, 0.0f);
    glScalef(0.8f, 0.8f, 0.8f);
    shape_cube(shape_face_colors);
    glPopMatrix();

    /* Everything polygonal culled; lines are not polygons. */
    glCullFace(GL_FRONT_AND_BACK);
    glColor3f(1.0f, 0.0f, 0.0f); /* culled */
    tri(4.6f, -2.6f, 1);
    glColor3f(0.9f, 0.9f, 0.9f);
    glLineWidth(2.0f);
    glBegin(GL_LINE_LOOP);
    glVertex3f(3.3f, -3.6f, 0.0f);
    glVertex3f(5.9f, -3.6f, 0.0f);
    glVertex3f(5.9f, -1.5f, 0.0f);
    glVertex3f(3.3f, -1.5f, 0.0f);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
