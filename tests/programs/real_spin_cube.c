/* real_spin_cube.c: the classic spinning colour cube (perspective, depth
 * test, smooth colours at the corners), four frames of its turn. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, -7);
    glRotatef(20.0f + 17.0f * (float)frame, 1, 0, 0);
    glRotatef(30.0f + 23.0f * (float)frame, 0, 1, 0);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 4; k++) {
            const float *p = v[f[i][k]];
            glColor3f(0.5f + 0.5f * p[0], 0.5f + 0.5f * p[1], 0.5f + 0.5f * p[2]);
            glVertex3fv(p);
        }
    glEnd();
}

RGL_REAL_MAIN(draw, 4)
