/* quiet_glut_dropin.c: a plain GLUT frame built with the drop-in header
 * (GLUT window: run under Xvfb) whose translation is exact, so raygl2pov
 * must print nothing (issue 22, "nothing said in vain").
 *
 * Besides what it draws, the frame makes the calls a GLUT program makes at
 * run time that cannot change the picture and are not recorded: the window
 * system's (glutSetWindowTitle, glutSetCursor, glutPostRedisplay,
 * glutSetWindow, glutReportErrors) and glDrawBuffer/glReadBuffer of the
 * buffers already current (their twins count nothing then). It draws a 2D
 * backdrop without the depth test (overlapping rectangles in one plane, in
 * order), then GLUT solids with it (a cube, an octahedron, a tetrahedron:
 * meshes of GL's own faces), then a HUD bar in window pixels without it.
 */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static void rect(float x0, float y0, float x1, float y1, float r, float g, float b)
{
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
    glEnd();
}

static void ortho(double w, double h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static int draw(int w, int h)
{
    glutSetWindowTitle("quiet_glut_dropin");
    glutSetCursor(GLUT_CURSOR_CROSSHAIR);
    glutSetWindow(glutGetWindow());
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
    glViewport(0, 0, w, h);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* The backdrop, in 320 x 240 units; edges off pixel centres. */
    ortho(320, 240);
    glTranslatef(0.13f, 0.37f, 0.0f);
    rect(10, 10, 200, 120, 0.6f, 0.2f, 0.2f);
    rect(100, 60, 310, 200, 0.2f, 0.5f, 0.3f);
    rect(40, 90, 160, 230, 0.3f, 0.3f, 0.7f);

    /* The solids, depth-tested, flat-coloured. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    const float x[3] = {-3.0f, 0.0f, 3.0f};
    const float col[3][3] = {{0.9f, 0.8f, 0.2f}, {0.8f, 0.3f, 0.8f}, {0.2f, 0.8f, 0.8f}};
    for (int k = 0; k < 3; k++) {
        glLoadIdentity();
        glTranslatef(x[k], -0.5f, -10.0f);
        glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
        glColor3fv(col[k]);
        if (k == 0)
            glutSolidCube(1.6);
        else if (k == 1)
            glutSolidOctahedron();
        else
            glutSolidTetrahedron();
    }
    glDisable(GL_DEPTH_TEST);

    /* The HUD: a bar in window pixels, over everything. */
    ortho(w, h);
    rect(8.25f, (float)h - 20.25f, (float)w * 0.6f, (float)h - 8.25f, 0.9f, 0.9f, 0.9f);
    glutPostRedisplay();
    glutReportErrors();
    return 0;
}

RGL_TEST_MAIN(draw)
