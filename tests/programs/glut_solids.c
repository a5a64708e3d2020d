/* glut_solids.c: every GLUT solid, filled and unlit, in a 4 x 3 grid
 * (GLUT window: run under Xvfb).
 *
 * Row 1: sphere, cube, cone (apex up), torus; row 2: dodecahedron,
 * octahedron, tetrahedron, icosahedron; row 3: freeglut's cylinder and
 * rhombic dodecahedron, a sphere with cull GL_BACK (exact: no change) and
 * a cube under a non-uniform scale. Each is tilted so that its 3D shape
 * shows. The curved ones become POV-Ray's exact solids, so their
 * silhouettes differ from GL's facets by under a pixel at these slice
 * counts; the polyhedra are meshes of GL's own faces.
 */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static const GLfloat colours[12][3] = {
    {0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.3f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f},
    {0.8f, 0.3f, 0.8f}, {0.2f, 0.8f, 0.8f}, {0.9f, 0.6f, 0.3f}, {0.6f, 0.9f, 0.4f},
    {0.5f, 0.5f, 1.0f}, {1.0f, 0.5f, 0.6f}, {0.7f, 0.7f, 0.7f}, {0.4f, 0.7f, 0.3f},
};

static void cell(int k)
{
    glLoadIdentity();
    glTranslatef(-4.5f + 3.0f * (float)(k % 4), 3.0f - 3.0f * (float)(k / 4), -14.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    glColor3fv(colours[k]);
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

    cell(0);
    glutSolidSphere(1.0, 48, 24);
    cell(1);
    glutSolidCube(1.4);
    cell(2);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutSolidCone(0.8, 1.5, 48, 6);
    cell(3);
    glutSolidTorus(0.3, 0.8, 32, 64);
    cell(4);
    glScalef(0.6f, 0.6f, 0.6f);
    glutSolidDodecahedron();
    cell(5);
    glutSolidOctahedron();
    cell(6);
    glutSolidTetrahedron();
    cell(7);
    glutSolidIcosahedron();
    cell(8);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutSolidCylinder(0.7, 1.4, 48, 3);
    cell(9);
    glutSolidRhombicDodecahedron();
    cell(10);
    glEnable(GL_CULL_FACE);
    glutSolidSphere(0.9, 48, 24);
    glDisable(GL_CULL_FACE);
    cell(11);
    glScalef(1.4f, 0.6f, 0.9f);
    glutSolidCube(1.0);
    return 0;
}

RGL_TEST_MAIN(draw)
