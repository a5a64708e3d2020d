/* litnotes_fog_behind.c: a fogged floor reaching behind the eye. GL fogs
 * by |z_eye| at the vertices, interpolated across the near-plane cut, so
 * the floor's near part takes the fog of |z| folded at the eye, not of its
 * distance; the pillar, wholly in front, is fogged by its distance. Unlit
 * flat colours, GL_LINEAR fog. docs/mapping.md "Faces lit and fogged as GL
 * does them".
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
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
    glTranslatef(0.01f, -1.5f, 0);
    glEnable(GL_FOG);
    const GLfloat fc[4] = {0.5f, 0.5f, 0.55f, 1};
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogfv(GL_FOG_COLOR, fc);
    glFogf(GL_FOG_START, 2);
    glFogf(GL_FOG_END, 18);
    glColor3f(0.8f, 0.6f, 0.3f);
    glBegin(GL_QUADS); /* a pillar's front face */
    glVertex3f(-1.8f, 0, -6);
    glVertex3f(-1.2f, 0, -6);
    glVertex3f(-1.2f, 3, -6);
    glVertex3f(-1.8f, 3, -6);
    glEnd();
    glColor3f(0.3f, 0.35f, 0.3f);
    glBegin(GL_QUADS); /* the floor, from 3 behind the eye to 20 ahead */
    glVertex3f(-3, 0, 3);
    glVertex3f(3, 0, 3);
    glVertex3f(3, 0, -20);
    glVertex3f(-3, 0, -20);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
