/* fogsec_lines.c: GL_LINEAR fog on lines and points (issue 14: a
 * fogged wire shape), unlit, under gluPerspective: rows of 3-pixel lines
 * and 6-pixel points from depth 3 to 15, each line one colour, fog from 2
 * to 18, and a wire cube of lines receding from 4 to 14. GL fogs each
 * fragment by its eye distance; a line's colour is then GL's blend
 * interpolated between its ends. */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / (double)h, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.05f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    GLfloat fogc[4] = {0.8f, 0.75f, 0.7f, 1.0f};
    glFogfv(GL_FOG_COLOR, fogc);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 18.0f);
    glEnable(GL_FOG);

    glLineWidth(3.0f);
    glBegin(GL_LINES);
    for (int k = 0; k < 7; k++) {
        float z = -3.0f - 2.0f * (float)k, s = -z / 3.0f;
        glColor3f(k % 2 ? 1.0f : 0.1f, 0.3f, k % 2 ? 0.1f : 0.9f);
        glVertex3f(-1.6f * s, (0.9f - 0.25f * (float)k) * s, z);
        glVertex3f(-0.2f * s, (0.9f - 0.25f * (float)k) * s, z);
    }
    glEnd();
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    for (int k = 0; k < 7; k++) {
        float z = -3.0f - 2.0f * (float)k, s = -z / 3.0f;
        glColor3f(0.1f, 0.9f, 0.2f);
        glVertex3f(0.2f * s, (0.9f - 0.25f * (float)k) * s, z);
        glVertex3f(0.5f * s, (0.9f - 0.25f * (float)k) * s, z);
    }
    glEnd();
    /* Lines receding in depth: one colour each, fogged along their length. */
    glColor3f(0.9f, 0.9f, 0.1f);
    glBegin(GL_LINES);
    for (int k = 0; k < 4; k++) {
        float x = 0.9f + 0.35f * (float)k;
        glVertex3f(x, -0.9f, -4.0f);
        glVertex3f(x * 3.0f, -2.5f, -14.0f);
    }
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
