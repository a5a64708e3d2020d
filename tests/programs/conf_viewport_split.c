/* conf_viewport_split.c: a split-screen frame, as a two-player game or a
 * four-view modeller draws it: the window cleared whole, then each
 * quadrant drawn in its own viewport with its own perspective camera
 * looking at the same three coloured triangles from another side. The
 * first draw's viewport is a quadrant, not the window. Unlit. */
#include "harness.h"

#include <raygl/gl.h>

static void scene(void)
{
    static const float c[3][3] = {{0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.3f, 0.4f, 0.9f}};
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
        float x = -1.6f + 1.6f * (float)i, z = -0.5f * (float)i;
        glColor3fv(c[i]);
        glVertex3f(x - 0.7f, -0.6f, z);
        glVertex3f(x + 0.7f, -0.6f, z);
        glVertex3f(x, 0.9f, z + 0.3f);
    }
    glEnd();
}

static int draw(int w, int h)
{
    int hw = w / 2, hh = h / 2;
    glViewport(0, 0, w, h);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    static const double eye[4][3] = {{0.3, 0.4, 6.0}, {4.0, 1.5, 4.0}, {-4.5, 2.0, 3.0}, {0.2, 6.0, 1.0}};
    for (int q = 0; q < 4; q++) {
        glViewport((q % 2) * hw, (q / 2) * hh, hw, hh);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        gluPerspective(45.0, (double)hw / hh, 1.0, 20.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        gluLookAt(eye[q][0], eye[q][1], eye[q][2], 0.0, 0.0, -0.4, 0.0, 1.0, 0.0);
        scene();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
