/* mat4.h: 4x4 matrices in OpenGL's column-major layout, in double.
 *
 * m[c * 4 + r] is row r, column c, as glLoadMatrix takes it; a point is a
 * column vector (x' = M x). The constructors follow the GL 1.x specification
 * and SGI's GLU sample implementation so that the interpreter reproduces the
 * matrices a real GL computes. Pure functions, thread-safe.
 */
#ifndef RGL_MAT4_H
#define RGL_MAT4_H

#include <math.h>
#include <stdbool.h>

typedef struct mat4 {
    double m[16];
} mat4;

/* 3-vectors, as the camera, lights and patches need them. */
static inline double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double len3(const double v[3]) { return sqrt(dot3(v, v)); }

/* The identity. */
mat4 mat4_identity(void);

/* a * b (b applied first, as glMultMatrix(b) on current a). */
mat4 mat4_mul(const mat4 *a, const mat4 *b);

/* The transpose. */
mat4 mat4_transpose(const mat4 *a);

/* The inverse; returns false (and leaves *out the identity) when a is
 * singular or not finite. */
bool mat4_invert(const mat4 *a, mat4 *out);

/* Determinant of the upper-left 3x3 block. */
double mat4_det3(const mat4 *a);

/* True when every element is finite. */
bool mat4_finite(const mat4 *a);

/* True when the bottom row is (0, 0, 0, 1): no projective part. */
bool mat4_affine(const mat4 *a);

/* Equal after rounding every element to float, the precision GL keeps. */
bool mat4_equal_f32(const mat4 *a, const mat4 *b);

/* out = M (x, y, z, w). */
/* Inline: called for every vertex, at several stages. */
static inline void mat4_apply(const mat4 *a, const double in[4], double out[4])
{
    const double *m = a->m;
    double o[4];
    for (int r = 0; r < 4; r++)
        o[r] = m[r] * in[0] + m[4 + r] * in[1] + m[8 + r] * in[2] + m[12 + r] * in[3];
    for (int r = 0; r < 4; r++)
        out[r] = o[r];
}

/* glTranslate, glScale. */
mat4 mat4_translate(double x, double y, double z);
mat4 mat4_scale(double x, double y, double z);

/* glRotate(angle in degrees, axis). An axis too short to normalise gives the
 * identity, as Mesa does. */
mat4 mat4_rotate(double angle, double x, double y, double z);

/* glFrustum and glOrtho, unchecked: callers reject the arguments GL rejects
 * (see mat4_frustum_valid, mat4_ortho_valid). */
mat4 mat4_frustum(double l, double r, double b, double t, double n, double f);
mat4 mat4_ortho(double l, double r, double b, double t, double n, double f);
bool mat4_frustum_valid(double l, double r, double b, double t, double n, double f);
bool mat4_ortho_valid(double l, double r, double b, double t, double n, double f);

/* gluPerspective as SGI GLU computes it; false (no matrix) in the cases GLU
 * silently ignores (zero depth range, zero sine, zero aspect). */
bool mat4_perspective(double fovy, double aspect, double n, double f, mat4 *out);

/* gluLookAt as SGI GLU computes it (float arithmetic for the rotation,
 * then the translation by -eye). */
mat4 mat4_lookat(double ex, double ey, double ez, double cx, double cy, double cz, double ux,
                 double uy, double uz);

#endif
