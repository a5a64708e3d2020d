/* glut_wire.c: every GLUT wire form, unlit, in a 4 x 3 grid (GLUT window:
 * run under Xvfb). The same layout as glut_solids.c; lines 1 pixel wide
 * except the last cell's (3 pixels), and a solid sphere drawn with
 * glPolygonMode(GL_LINE), which GL draws as the edges of its facets. */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static void cell(int k)
{
    glLoadIdentity();
    glTranslatef(-4.5f + 3.0f * (float)(k % 4), 3.0f - 3.0f * (float)(k / 4), -14.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.4f + 0.05f * (float)k, 1.0f - 0.05f * (float)k, 0.6f);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    cell(0);
    glutWireSphere(1.0, 10, 7);
    cell(1);
    glutWireCube(1.4);
    cell(2);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutWireCone(0.8, 1.5, 10, 3);
    cell(3);
    glutWireTorus(0.3, 0.8, 6, 12);
    cell(4);
    glScalef(0.6f, 0.6f, 0.6f);
    glutWireDodecahedron();
    cell(5);
    glutWireOctahedron();
    cell(6);
    glutWireTetrahedron();
    cell(7);
    glutWireIcosahedron();
    cell(8);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutWireCylinder(0.7, 1.4, 10, 2);
    cell(9);
    glutWireRhombicDodecahedron();
    cell(10);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glutSolidSphere(0.9, 8, 6);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    cell(11);
    glLineWidth(3.0f);
    glutWireCube(1.2);
    glLineWidth(1.0f);
    return 0;
}

RGL_TEST_MAIN(draw)
