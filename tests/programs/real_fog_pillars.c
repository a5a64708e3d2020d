/* real_fog_pillars.c: a corridor of pillars fading into linear fog (a
 * classic fog demo), flat-coloured boxes, two frames walking forward. */
#include "real.h"

#include <raygl/gl.h>

static void pillar(float x, float z)
{
    glBegin(GL_QUAD_STRIP);
    const float s = 0.3f;
    const float c[5][2] = {{-s, -s}, {s, -s}, {s, s}, {-s, s}, {-s, -s}};
    for (int i = 0; i < 5; i++) {
        glColor3f(0.8f - 0.1f * (float)(i % 2), 0.6f, 0.3f);
        glVertex3f(x + c[i][0], 0, z + c[i][1]);
        glVertex3f(x + c[i][0], 3, z + c[i][1]);
    }
    glEnd();
}

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.5f, 0.5f, 0.55f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(55, (double)w / h, 0.5, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.01, 1.5, 4.0 - frame, 0.01, 1.2, -10, 0, 1, 0);
    glEnable(GL_FOG);
    const GLfloat fc[4] = {0.5f, 0.5f, 0.55f, 1};
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogfv(GL_FOG_COLOR, fc);
    glFogf(GL_FOG_START, 2);
    glFogf(GL_FOG_END, 18);
    glShadeModel(GL_FLAT);
    for (int k = 0; k < 6; k++) {
        pillar(-1.5f, -3.0f * (float)k);
        pillar(1.5f, -3.0f * (float)k - 1.5f);
    }
    glColor3f(0.3f, 0.35f, 0.3f);
    glBegin(GL_QUADS);
    glVertex3f(-3, 0, 5);
    glVertex3f(3, 0, 5);
    glVertex3f(3, 0, -20);
    glVertex3f(-3, 0, -20);
    glEnd();
    glDisable(GL_FOG);
}

RGL_REAL_MAIN(draw, 2)
