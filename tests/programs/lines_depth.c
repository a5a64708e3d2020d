/* lines_depth.c: 1-pixel lines at many depths in perspective: a grid
 * floor from 1.5 to 60 units away whose near rows cross the near plane
 * (GL clips them there), wire boxes at several depths, a tall mast seen
 * from below, and lines drawn over a solid face with the depth test on
 * (some hidden behind it). No offsets: the lines fall where the scene
 * puts them. */
#include "harness.h"

#include <raygl/gl.h>

static void box(float x, float y, float z, float s)
{
    static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int e[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    glBegin(GL_LINES);
    for (int i = 0; i < 12; i++)
        for (int k = 0; k < 2; k++) {
            const float *p = v[e[i][k]];
            glVertex3f(x + s * p[0], y + s * p[1], z + s * p[2]);
        }
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 1, 80);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 1.2, 4, 0, 0.4, -10, 0, 1, 0);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    /* A solid face the lines pass in front of and behind. */
    glColor3f(0.25f, 0.25f, 0.45f);
    glBegin(GL_QUADS);
    glVertex3f(-3, 0, -8);
    glVertex3f(1, 0, -8);
    glVertex3f(1, 3, -8);
    glVertex3f(-3, 3, -8);
    glEnd();

    /* The floor grid, rows and columns, from behind the camera to z = -56. */
    glColor3f(0.3f, 0.9f, 0.4f);
    glBegin(GL_LINES);
    for (int i = -12; i <= 12; i++) {
        glVertex3f((float)i, 0, 6);
        glVertex3f((float)i, 0, -56);
    }
    for (int k = 0; k <= 31; k++) {
        float z = 6.0f - 2.0f * (float)k;
        glVertex3f(-12, 0, z);
        glVertex3f(12, 0, z);
    }
    glEnd();

    glColor3f(1, 0.6f, 0.2f);
    box(2.2f, 0.6f, -3, 0.5f);
    box(-1.5f, 1.0f, -6, 0.7f);
    box(0.5f, 1.5f, -9, 0.8f);
    box(4, 2, -20, 1.5f);
    box(-6, 3, -35, 2.5f);
    glColor3f(1, 1, 0.5f);
    glBegin(GL_LINE_STRIP);
    glVertex3f(-0.8f, 0, -2);
    glVertex3f(-0.8f, 6, -2);
    glVertex3f(3, 6, -30);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
