/* glu_quadrics.c: GLU quadrics, filled, unlit, in a 4 x 3 grid (OSMesa).
 *
 * Row 1 (exact POV-Ray solids): gluSphere, gluCylinder as a cone,
 * gluCylinder as a cylinder (open: its inside shows), gluDisk with a hole.
 * Row 2 (meshes): gluPartialDisk (start 30, sweep 250), a partial disk
 * with a negative sweep, a sphere with GLU_INSIDE and cull GL_FRONT (GL
 * shows its far half from inside), an open cylinder with cull GL_BACK
 * (its inside is culled).
 * Row 3: a sphere with GLU_FLAT normals, a disk with GLU_INSIDE and
 * cull GL_BACK (culled: nothing), a cylinder with glFrontFace(GL_CW) and
 * cull GL_BACK (its outside is culled), and a sphere under
 * glPolygonMode(GL_FRONT, GL_LINE).
 */
#include "harness.h"

#include <raygl/gl.h>

static void cell(int k)
{
    glLoadIdentity();
    glTranslatef(-4.5f + 3.0f * (float)(k % 4), 3.0f - 3.0f * (float)(k / 4), -14.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.3f + 0.06f * (float)k, 0.9f - 0.05f * (float)k, 0.3f + 0.04f * (float)(k % 5));
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    GLUquadric *q = gluNewQuadric();

    cell(0);
    gluSphere(q, 1.0, 48, 24);
    cell(1);
    glTranslatef(0.0f, 0.0f, -0.7f);
    gluCylinder(q, 0.9, 0.2, 1.4, 48, 3);
    cell(2);
    glTranslatef(0.0f, 0.0f, -0.7f);
    gluCylinder(q, 0.7, 0.7, 1.4, 48, 1);
    cell(3);
    gluDisk(q, 0.4, 1.0, 48, 2);

    cell(4);
    gluPartialDisk(q, 0.3, 1.0, 24, 3, 30.0, 250.0);
    cell(5);
    gluPartialDisk(q, 0.0, 1.0, 16, 1, 90.0, -120.0);
    cell(6);
    gluQuadricOrientation(q, GLU_INSIDE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    gluSphere(q, 1.0, 32, 16);
    gluQuadricOrientation(q, GLU_OUTSIDE);
    cell(7);
    glCullFace(GL_BACK);
    glTranslatef(0.0f, 0.0f, -0.7f);
    gluCylinder(q, 0.7, 0.7, 1.4, 32, 1);

    cell(8);
    glDisable(GL_CULL_FACE);
    gluQuadricNormals(q, GLU_FLAT);
    gluSphere(q, 1.0, 48, 24);
    gluQuadricNormals(q, GLU_SMOOTH);
    cell(9);
    glEnable(GL_CULL_FACE);
    gluQuadricOrientation(q, GLU_INSIDE);
    gluDisk(q, 0.0, 1.0, 32, 1);
    gluQuadricOrientation(q, GLU_OUTSIDE);
    cell(10);
    glFrontFace(GL_CW);
    glTranslatef(0.0f, 0.0f, -0.7f);
    gluCylinder(q, 0.7, 0.7, 1.4, 32, 1);
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
    cell(11);
    glPolygonMode(GL_FRONT, GL_LINE);
    gluSphere(q, 1.0, 12, 8);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    gluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
