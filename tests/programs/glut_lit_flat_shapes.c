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

#include "glut_flat_scene.h"

static int draw(int w, int h)
{
    flat_scene_begin(w, h);
    flat_cell(0, 0.3f, 0.5f, 0.9f);
    glutSolidSphere(0.9, 16, 10);
    flat_cell(1, 0.4f, 0.8f, 0.4f);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glutSolidTorus(0.3, 0.7, 10, 20);
    flat_cell(2, 0.8f, 0.3f, 0.7f);
    glRotatef(165.0f, 0.0f, 1.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutSolidCone(0.8, 1.4, 16, 3);
    flat_cell(3, 0.9f, 0.6f, 0.3f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -0.7f);
    glutSolidCylinder(0.7, 1.4, 16, 3);
    return 0;
}

RGL_TEST_MAIN(draw)
