/* eval_curve.c: Bezier curves, unlit, under gluOrtho2D (OSMesa).
 *
 * A cubic GL_MAP1_VERTEX_3 (points 4 floats apart, the fourth skipped)
 * drawn by glMapGrid1f + glEvalMesh1(GL_LINE), 3 pixels wide; the same
 * curve, moved down, as an explicit glBegin(GL_LINE_STRIP) of
 * glEvalCoord1f with GL_MAP1_COLOR_4 colouring it from red to blue and a
 * glColor between the coordinates that the evaluated colour does not
 * overwrite; a quartic GL_MAP1_VERTEX_4 (homogeneous, doubles) from
 * glMap1d over the domain [-1, 3] drawn with glEvalMesh1(GL_POINT) and
 * glEvalPoint1 inside GL_POINTS; last a glVertex after the line strip that
 * must keep the glColor current before it.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    static const GLfloat cubic[4][4] = {
        {20.5f, 150.5f, 0.0f, -7.0f}, {80.5f, 235.5f, 0.0f, -7.0f},
        {150.5f, 110.5f, 0.0f, -7.0f}, {200.5f, 200.5f, 0.0f, -7.0f},
    };
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 4, 4, &cubic[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glLineWidth(3.0f);
    glColor3f(0.9f, 0.9f, 0.3f);
    glMapGrid1f(30, 0.0f, 1.0f);
    glEvalMesh1(GL_LINE, 0, 30);

    /* The same curve 80 pixels lower, by glEvalCoord1f, coloured by a map. */
    static const GLfloat colours[2][4] = {{1.0f, 0.1f, 0.1f, 1.0f}, {0.2f, 0.3f, 1.0f, 1.0f}};
    glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &colours[0][0]);
    glEnable(GL_MAP1_COLOR_4);
    glPushMatrix();
    glTranslatef(0.0f, -80.0f, 0.0f);
    glColor3f(0.2f, 1.0f, 0.2f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 24; i++)
        glEvalCoord1f((float)i / 24.0f);
    glEnd();
    /* The current colour is still green: the evaluated one did not stay. */
    glPopMatrix();
    glDisable(GL_MAP1_COLOR_4);
    glBegin(GL_LINES);
    glVertex2f(20.5f, 20.5f);
    glVertex2f(120.5f, 20.5f);
    glEnd();

    /* A rational quartic in doubles over [-1, 3], as points. */
    static const GLdouble quartic[5][4] = {
        {230.0, 40.0, 0.0, 1.0}, {2 * 250.0, 2 * 220.0, 0.0, 2.0}, {280.0, 40.0, 0.0, 1.0},
        {2 * 300.0, 2 * 220.0, 0.0, 2.0}, {310.0, 40.0, 0.0, 1.0},
    };
    glDisable(GL_MAP1_VERTEX_3);
    glMap1d(GL_MAP1_VERTEX_4, -1.0, 3.0, 4, 5, &quartic[0][0]);
    glEnable(GL_MAP1_VERTEX_4);
    glPointSize(4.0f);
    glColor3f(0.3f, 1.0f, 1.0f);
    glMapGrid1d(20, -1.0, 3.0);
    glEvalMesh1(GL_POINT, 0, 9);
    glColor3f(1.0f, 0.5f, 1.0f);
    glBegin(GL_POINTS);
    for (int i = 10; i <= 20; i++)
        glEvalPoint1(i);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
