/* proj_hud.c: a HUD drawn last in glOrtho with the depth test off over a
 * perspective scene (issue 14): a floor of quads and a row of boxes, then
 * a status bar and a crosshair in window pixels. Two frames, the camera
 * moving.
 */
#include "real.h"

#include <raygl/gl.h>

static void box(float x, float z, float s)
{
    static const float f[6][4][3] = {
        {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
        {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}},
        {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}},
        {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
        {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}},
        {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
    };
    static const float c[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++) {
        glColor3fv(c[i]);
        for (int k = 0; k < 4; k++)
            glVertex3f(x + s * f[i][k][0], s + s * f[i][k][1], z + s * f[i][k][2]);
    }
    glEnd();
}

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.5f, 0.7f, 0.9f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60, (double)w / h, 0.5, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.3 * frame, 2.5, 6, 0, 0.5, 0, 0, 1, 0);
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    for (int i = -4; i < 4; i++)
        for (int j = -4; j < 4; j++) {
            float g = ((i + j) & 1) ? 0.35f : 0.55f;
            glColor3f(g, g * 0.9f, g * 0.7f);
            glVertex3f((float)i, 0, (float)j + 1);
            glVertex3f((float)i + 1, 0, (float)j + 1);
            glVertex3f((float)i + 1, 0, (float)j);
            glVertex3f((float)i, 0, (float)j);
        }
    glEnd();
    box(-2, -1, 0.5f);
    box(0, 0, 0.6f);
    box(2, -2, 0.4f);

    /* The HUD, in window pixels, over everything. */
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(0.1f, 0.1f, 0.1f);
    glRectf(0, 0, (float)w, 24);
    glColor3f(0.9f, 0.2f, 0.2f);
    glRectf(6, 6, 6 + 0.6f * (float)(w - 12), 18);
    glColor3f(1, 1, 1);
    glBegin(GL_LINES);
    glVertex2f(w / 2.0f - 10, h / 2.0f + 0.5f);
    glVertex2f(w / 2.0f + 10, h / 2.0f + 0.5f);
    glVertex2f(w / 2.0f + 0.5f, h / 2.0f - 10);
    glVertex2f(w / 2.0f + 0.5f, h / 2.0f + 10);
    glEnd();
}

RGL_REAL_MAIN(draw, 2)
