/* teapot.h: Newell's teapot as freeglut 3 draws it (glutSolidTeapot,
 * glutWireTeapot), for the interpreter's meshes and lines and for the
 * POV-Ray writer's bicubic patches.
 *
 * Object space is GL's for size 1: the data's z axis up along GL's +y, the
 * spout toward +x, centred in height (y from -0.7875 to 0.7875); a call of
 * size s scales it by s. docs/mapping.md gives the measurements. */
#ifndef RGL_TEAPOT_H
#define RGL_TEAPOT_H

#include <stdint.h>

#define TEAPOT_PATCHES 32

/* freeglut's tessellation: GLUT_SOLID points per patch side for the solid
 * teapot (7 x 7 cells, two triangles each), lines per side for the wire. */
#define TEAPOT_SOLID_GRID 8
#define TEAPOT_WIRE_GRID 10

/* The 16 control points of a patch in object space, row by row (u the
 * row, v the column). */
void teapot_control_points(int patch, double out[16][3]);

/* The point of a patch at (u, v) in [0,1]^2 and its outward unit normal,
 * in object space. At a degenerate edge (the bottom's centre) the normal
 * is the limit from inside the patch. */
void teapot_eval(int patch, double u, double v, double p[3], double n[3]);

#endif
