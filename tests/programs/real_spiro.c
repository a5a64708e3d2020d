/* real_spiro.c: a spirograph of line strips in glOrtho (a classic 2D
 * demo), two frames as the pattern turns. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.6, 1.6, -1.2, 1.2, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(10.0f * (float)frame, 0, 0, 1);
    glLineWidth(2);
    for (int c = 0; c < 3; c++) {
        glColor3f(c == 0 ? 0.8f : 0.1f, c == 1 ? 0.6f : 0.1f, c == 2 ? 0.8f : 0.2f);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= 360; i++) {
            double t = i * 3.14159265358979 / 90.0, R = 1.0, r = 0.3 + 0.1 * c, d = 0.5;
            double x = (R - r) * cos(t) + d * cos((R - r) / r * t);
            double y = (R - r) * sin(t) - d * sin((R - r) / r * t);
            glVertex2d(x * 0.8, y * 0.8);
        }
        glEnd();
    }
    glLineWidth(1);
}

RGL_REAL_MAIN(draw, 2)
