/* shapes.h: small shapes drawn with raygl* calls, shared by the test
 * programs (the drawing is part of the recorded frame). */
#ifndef RGL_TEST_SHAPES_H
#define RGL_TEST_SHAPES_H

#include <GL/gl.h>

/* Six face colours used when a cube is given none. */
extern const GLfloat shape_face_colors[6][3];

/* The cube [-1, 1]^3 as six GL_QUADS, counter-clockwise seen from outside,
 * face i in colour colors[i] (order +x, -x, +y, -y, +z, -z). */
void shape_cube(const GLfloat colors[6][3]);

/* The axis-aligned rectangle [x0, x1] x [y0, y1] at z = 0 as one GL_QUADS,
 * counter-clockwise, in the current colour. */
void shape_rect(GLfloat x0, GLfloat y0, GLfloat x1, GLfloat y1);

#endif
