/* points_round.c: round points (GL_POINT_SMOOTH) of sizes 1 to 12,
 * fractional ones among them, placed on pixel centres, edges and corners
 * and at arbitrary places, under gluOrtho2D and in perspective, blending
 * off. Mesa lights the pixels whose centres lie inside the circle of the
 * point's size (at least 2) around it, all at the point's colour. */
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
    glEnable(GL_POINT_SMOOTH);

    static const float size[12] = {1, 2, 2.5f, 3, 3.5f, 4, 5, 6, 7.5f, 8, 10, 12};
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
