/* glut_lit_flat.c: freeglut's teapot lit under GL_FLAT (GLUT window: run
 * under Xvfb).
 *
 * GL lights each triangle once, at its provoking (last) vertex, with that
 * vertex's normal: for the teapot, the surface's normal at that corner,
 * not the face's. Four teapots of different sizes and turns, drawn as
 * freeglut's own triangles, lit by one directional light with no specular,
 * so that the colour is constant across each face in POV-Ray as in GL. */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

#include "glut_flat_scene.h"

static int draw(int w, int h)
{
    flat_scene_begin(w, h);
    flat_cell(0, 0.9f, 0.6f, 0.3f);
    glutSolidTeapot(1.0);
    flat_cell(1, 0.3f, 0.5f, 0.9f);
    glRotatef(70.0f, 0.0f, 1.0f, 0.0f);
    glutSolidTeapot(0.9);
    flat_cell(2, 0.4f, 0.8f, 0.4f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glutSolidTeapot(0.8);
    flat_cell(3, 0.8f, 0.3f, 0.7f);
    glRotatef(160.0f, 0.0f, 1.0f, 0.0f);
    glutSolidTeapot(1.1);
    return 0;
}

RGL_TEST_MAIN(draw)
