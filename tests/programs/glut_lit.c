/* glut_lit.c: curved GLUT and GLU solids lit, with a local viewer (GLUT
 * window: run under Xvfb).
 *
 * Top row: freeglut's teapot, sphere, torus and capped cylinder; bottom
 * row: its cone, gluSphere, an open gluCylinder and a teapot under
 * glCullFace(GL_FRONT), which keeps its outside (freeglut winds it
 * clockwise) as freeglut's own triangles. One directional and one point
 * light, GL_LIGHT_MODEL_LOCAL_VIEWER so that GL's highlights use the true
 * view direction as POV-Ray's do. POV-Ray draws the true curved surfaces
 * with normals per pixel; GL draws facets lit per vertex, so the shading
 * differs inside the facets (issue 5's regime: 95% within 8/255,
 * docs/mapping.md section 10). */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static void cell(int k, float r, float g, float b)
{
    glLoadIdentity();
    glTranslatef(-3.3f + 2.2f * (float)(k % 4), 1.1f - 2.2f * (float)(k / 4), -9.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
    GLfloat diffuse[4] = {r, g, b, 1.0f}, ambient[4] = {0.3f * r, 0.3f * g, 0.3f * b, 1.0f};
    GLfloat specular[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
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
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat dir[4] = {1.0f, 1.5f, 2.0f, 0.0f}, point[4] = {-4.0f, 2.0f, -3.0f, 1.0f};
    GLfloat dim[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT1, GL_POSITION, point);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);
    glLightfv(GL_LIGHT1, GL_SPECULAR, dim);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);

    cell(0, 0.9f, 0.6f, 0.3f);
    glutSolidTeapot(0.8);
    cell(1, 0.3f, 0.5f, 0.9f);
    glutSolidSphere(0.8, 32, 16);
    cell(2, 0.4f, 0.8f, 0.4f);
    glutSolidTorus(0.25, 0.6, 24, 48);
    cell(3, 0.7f, 0.7f, 0.9f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.6f);
    glutSolidCylinder(0.6, 1.2, 32, 2);
    cell(4, 0.8f, 0.3f, 0.7f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutSolidCone(0.8, 1.4, 32, 4);
    GLUquadric *q = gluNewQuadric();
    if (!q)
        return 1;
    cell(5, 0.9f, 0.8f, 0.3f);
    gluSphere(q, 0.8, 32, 16);
    cell(6, 0.5f, 0.8f, 0.8f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    gluCylinder(q, 0.7, 0.5, 1.4, 32, 3);
    gluDeleteQuadric(q);
    cell(7, 0.9f, 0.5f, 0.5f);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glutSolidTeapot(0.8);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
    return 0;
}

RGL_TEST_MAIN(draw)
