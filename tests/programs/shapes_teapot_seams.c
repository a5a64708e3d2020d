/* shapes_teapot_seams.c: one large lit glutSolidTeapot (GLUT window: run
 * under Xvfb). The teapot is POV-Ray bicubic patches; along the seams
 * between patches no ray may slip through (dark dots: issue 14, "the
 * bicubic-patch teapot"). Directional light and a local viewer, as
 * glut_lit. */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(30.0, (double)w / (double)h, 2.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat dir[4] = {1.0f, 1.5f, 2.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    GLfloat diffuse[4] = {0.9f, 0.7f, 0.3f, 1.0f}, ambient[4] = {0.3f, 0.25f, 0.1f, 1.0f};
    GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
    glTranslatef(0.0f, 0.0f, -7.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-35.0f, 0.0f, 1.0f, 0.0f);
    glutSolidTeapot(1.3);
    return 0;
}

RGL_TEST_MAIN(draw)
