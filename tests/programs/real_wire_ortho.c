/* real_wire_ortho.c: a wireframe cube and axes in glOrtho with zNear = 0
 * (an engineering viewer's projection), depth test off, two frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int e[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    glViewport(0, 0, w, h);
    glClearColor(0.15f, 0.15f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-3.2, 3.2, -2.4, 2.4, 0, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.003f, 0.005f, -5);
    glRotatef(25, 1, 0, 0);
    glRotatef(30.0f + 20.0f * (float)frame, 0, 1, 0);
    glColor3f(0.9f, 0.9f, 0.3f);
    glBegin(GL_LINES);
    for (int i = 0; i < 12; i++) {
        glVertex3fv(v[e[i][0]]);
        glVertex3fv(v[e[i][1]]);
    }
    glEnd();
    glBegin(GL_LINES);
    glColor3f(1, 0.2f, 0.2f);
    glVertex3f(0, 0, 0);
    glVertex3f(2, 0, 0);
    glColor3f(0.2f, 1, 0.2f);
    glVertex3f(0, 0, 0);
    glVertex3f(0, 2, 0);
    glColor3f(0.3f, 0.5f, 1);
    glVertex3f(0, 0, 0);
    glVertex3f(0, 0, 2);
    glEnd();
}

RGL_REAL_MAIN(draw, 2)
