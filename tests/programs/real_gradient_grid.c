/* real_gradient_grid.c: a plasma-like grid of smooth-coloured quads
 * compiled once into a display list and called each frame under a turning
 * modelview (a screensaver's pattern). */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

static GLuint grid;

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-1.6, 1.6, -1.2, 1.2);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    if (!grid) {
        grid = glGenLists(1);
        glNewList(grid, GL_COMPILE);
        glBegin(GL_QUADS);
        for (int i = 0; i < 6; i++)
            for (int j = 0; j < 6; j++) {
                float x = -1 + i / 3.0f, y = -1 + j / 3.0f, d = 1 / 3.0f;
                float c[4][2] = {{x, y}, {x + d, y}, {x + d, y + d}, {x, y + d}};
                for (int k = 0; k < 4; k++) {
                    float s = (float)((i + j + k) % 2);
                    glColor3f(s, 0.5f * (c[k][0] + 1), 1 - s);
                    glVertex2f(c[k][0], c[k][1]);
                }
            }
        glEnd();
        glEndList();
    }
    glRotatef(12.0f * (float)frame + 3, 0, 0, 1);
    glCallList(grid);
}

RGL_REAL_MAIN(draw, 3)
