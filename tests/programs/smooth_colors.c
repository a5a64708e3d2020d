/* smooth_colors.c: per-vertex colours with smooth shading, written with
 * plain gl* calls and the drop-in header (every gl* call below is recorded).
 *
 * Covers: Gouraud interpolation across triangles, a quad whose corner
 * colours are not affine (opposite corners alike, so the diagonal GL splits
 * it along shows: Mesa splits quad v0..v3 along v0-v2), a fan with a white
 * centre, colours set with glColor3ub/3f/4ub, and the drop-in header itself.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.21f, 0.43f, 0.0f);

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);

    /* Red, green, blue corners. */
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex2f(14, 12);
    glColor3f(0, 1, 0);
    glVertex2f(150, 18);
    glColor3f(0, 0, 1);
    glVertex2f(70, 125);
    glEnd();

    /* Opposite corners alike: the split diagonal is white or black. */
    glBegin(GL_QUADS);
    glColor3ub(255, 255, 255);
    glVertex2f(170, 12);
    glColor3ub(0, 0, 0);
    glVertex2f(305, 14);
    glColor3ub(255, 255, 255);
    glVertex2f(300, 118);
    glColor3ub(20, 20, 20);
    glVertex2f(172, 110);
    glEnd();

    /* A fan: white centre, coloured rim. */
    static const GLubyte rim[6][4] = {
        {255, 0, 0, 255},   {255, 255, 0, 255}, {0, 255, 0, 255},
        {0, 255, 255, 255}, {0, 0, 255, 255},   {255, 0, 255, 255},
    };
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex2f(90, 180);
    for (int i = 0; i <= 6; i++) {
        static const float dx[6] = {60, 30, -30, -60, -30, 30};
        static const float dy[6] = {0, 50, 50, 0, -45, -45};
        glColor4ubv(rim[i % 6]);
        glVertex2f(90 + dx[i % 6], 180 + dy[i % 6]);
    }
    glEnd();

    /* Dark to light, two colours only, across a long thin triangle. */
    glBegin(GL_TRIANGLES);
    glColor3f(0.1f, 0.05f, 0.0f);
    glVertex2f(175, 140);
    glColor3f(1.0f, 0.6f, 0.2f);
    glVertex2f(310, 150);
    glColor3f(0.1f, 0.05f, 0.0f);
    glVertex2f(190, 225);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
