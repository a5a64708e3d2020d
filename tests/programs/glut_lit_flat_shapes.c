/* glut_lit_flat_shapes.c: freeglut's sphere, torus, cone and cylinder lit
 * under GL_FLAT (GLUT window: run under Xvfb).
 *
 * freeglut fills these shapes with triangle strips; GL lights each
 * triangle with its provoking (last) vertex's normal, so which diagonal
 * splits a cell and which corner lights each half show facet by facet.
 * One directional light, no specular, so that the colour is constant
 * across each face in POV-Ray as in GL. The cone and the cylinder are
 * tipped so that the cone's base and the cylinder's top show. */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static void cell(int k, float r, float g, float b)
{
    glLoadIdentity();
    glTranslatef(-1.6f + 3.2f * (float)(k % 2), 1.2f - 2.4f * (float)(k / 2), -8.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
    GLfloat diffuse[4] = {r, g, b, 1.0f}, ambient[4] = {0.3f * r, 0.3f * g, 0.3f * b, 1.0f};
    GLfloat none[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, none);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glShadeModel(GL_FLAT);
    GLfloat dir[4] = {1.0f, 1.5f, 2.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glEnable(GL_LIGHT0);

    cell(0, 0.3f, 0.5f, 0.9f);
    glutSolidSphere(0.9, 16, 10);
    cell(1, 0.4f, 0.8f, 0.4f);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glutSolidTorus(0.3, 0.7, 10, 20);
    cell(2, 0.8f, 0.3f, 0.7f);
    glRotatef(165.0f, 0.0f, 1.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutSolidCone(0.8, 1.4, 16, 3);
    cell(3, 0.9f, 0.6f, 0.3f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutSolidCylinder(0.7, 1.4, 16, 3);
    return 0;
}

RGL_TEST_MAIN(draw)
