/* points_sizes.c: square points of sizes 1 to 8, fractional sizes among
 * them (GL rounds them, GL 2.1 3.3.1), placed on pixel centres, edges and
 * corners and at arbitrary places, under gluOrtho2D and in perspective.
 * An odd size centres the square on the pixel the point falls in; an
 * even size on the pixel corner nearest to it. */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    static const float size[12] = {1, 1.5f, 2, 2.5f, 2.51f, 3, 3.49f, 4, 5, 6, 7.5f, 8};
    static const float sub[6][2] = {{0.5f, 0.5f}, {0, 0}, {0.5f, 0}, {0, 0.5f},
                                   {0.3f, 0.8f}, {0.77f, 0.12f}};
    for (int i = 0; i < 12; i++) {
        glPointSize(size[i]);
        glBegin(GL_POINTS);
        for (int k = 0; k < 6; k++) {
            glColor3f(1, 0.3f + 0.05f * (float)i, 0.2f + 0.15f * (float)k);
            glVertex2f(12.0f + 25.0f * (float)i + sub[k][0], 20.0f + 22.0f * (float)k + sub[k][1]);
        }
        glEnd();
    }

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, -1, -5);
    glRotatef(30, 1, 0, 0);
    glPointSize(3);
    glColor3f(0.4f, 1, 0.6f);
    glBegin(GL_POINTS);
    for (int i = -8; i <= 8; i++)
        for (int k = 0; k < 5; k++)
            glVertex3f(0.35f * (float)i, 0, -1.0f * (float)k);
    glEnd();
    glPointSize(2);
    glColor3f(0.6f, 0.6f, 1);
    glBegin(GL_POINTS);
    for (int i = -8; i <= 8; i++)
        for (int k = 0; k < 5; k++)
            glVertex3f(0.35f * (float)i + 0.17f, 0.5f, -1.0f * (float)k);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
