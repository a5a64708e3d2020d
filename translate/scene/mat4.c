/* mat4.c: 4x4 matrix arithmetic and the GL/GLU matrix constructors.
 *
 * Column-major as GL: element (row r, column c) is m[c * 4 + r].
 */
#include "mat4.h"

#include <math.h>
#include <string.h>

#define M(a, r, c) ((a)->m[(c) * 4 + (r)])

mat4 mat4_identity(void)
{
    mat4 i = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
    return i;
}

mat4 mat4_mul(const mat4 *a, const mat4 *b)
{
    mat4 o;
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++)
            M(&o, r, c) = M(a, r, 0) * M(b, 0, c) + M(a, r, 1) * M(b, 1, c) +
                          M(a, r, 2) * M(b, 2, c) + M(a, r, 3) * M(b, 3, c);
    return o;
}

mat4 mat4_transpose(const mat4 *a)
{
    mat4 o;
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++)
            M(&o, r, c) = M(a, c, r);
    return o;
}

bool mat4_finite(const mat4 *a)
{
    for (int i = 0; i < 16; i++)
        if (!isfinite(a->m[i]))
            return false;
    return true;
}

bool mat4_affine(const mat4 *a)
{
    return a->m[3] == 0 && a->m[7] == 0 && a->m[11] == 0 && a->m[15] == 1;
}

bool mat4_equal_f32(const mat4 *a, const mat4 *b)
{
    for (int i = 0; i < 16; i++) {
        float x = (float)a->m[i], y = (float)b->m[i];
        if (memcmp(&x, &y, sizeof x) != 0)
            return false;
    }
    return true;
}

double mat4_det3(const mat4 *a)
{
    return M(a, 0, 0) * (M(a, 1, 1) * M(a, 2, 2) - M(a, 1, 2) * M(a, 2, 1)) -
           M(a, 0, 1) * (M(a, 1, 0) * M(a, 2, 2) - M(a, 1, 2) * M(a, 2, 0)) +
           M(a, 0, 2) * (M(a, 1, 0) * M(a, 2, 1) - M(a, 1, 1) * M(a, 2, 0));
}

bool mat4_invert(const mat4 *a, mat4 *out)
{
    /* Cofactor expansion through 2x2 sub-determinants of the row pairs. */
    const double *m = a->m;
    double s0 = m[0] * m[5] - m[4] * m[1];
    double s1 = m[0] * m[6] - m[4] * m[2];
    double s2 = m[0] * m[7] - m[4] * m[3];
    double s3 = m[1] * m[6] - m[5] * m[2];
    double s4 = m[1] * m[7] - m[5] * m[3];
    double s5 = m[2] * m[7] - m[6] * m[3];
    double c5 = m[10] * m[15] - m[14] * m[11];
    double c4 = m[9] * m[15] - m[13] * m[11];
    double c3 = m[9] * m[14] - m[13] * m[10];
    double c2 = m[8] * m[15] - m[12] * m[11];
    double c1 = m[8] * m[14] - m[12] * m[10];
    double c0 = m[8] * m[13] - m[12] * m[9];
    double det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;

    *out = mat4_identity();
    if (det == 0 || !isfinite(det))
        return false;
    double id = 1.0 / det;
    double *o = out->m;
    o[0] = (m[5] * c5 - m[6] * c4 + m[7] * c3) * id;
    o[1] = (-m[1] * c5 + m[2] * c4 - m[3] * c3) * id;
    o[2] = (m[13] * s5 - m[14] * s4 + m[15] * s3) * id;
    o[3] = (-m[9] * s5 + m[10] * s4 - m[11] * s3) * id;
    o[4] = (-m[4] * c5 + m[6] * c2 - m[7] * c1) * id;
    o[5] = (m[0] * c5 - m[2] * c2 + m[3] * c1) * id;
    o[6] = (-m[12] * s5 + m[14] * s2 - m[15] * s1) * id;
    o[7] = (m[8] * s5 - m[10] * s2 + m[11] * s1) * id;
    o[8] = (m[4] * c4 - m[5] * c2 + m[7] * c0) * id;
    o[9] = (-m[0] * c4 + m[1] * c2 - m[3] * c0) * id;
    o[10] = (m[12] * s4 - m[13] * s2 + m[15] * s0) * id;
    o[11] = (-m[8] * s4 + m[9] * s2 - m[11] * s0) * id;
    o[12] = (-m[4] * c3 + m[5] * c1 - m[6] * c0) * id;
    o[13] = (m[0] * c3 - m[1] * c1 + m[2] * c0) * id;
    o[14] = (-m[12] * s3 + m[13] * s1 - m[14] * s0) * id;
    o[15] = (m[8] * s3 - m[9] * s1 + m[10] * s0) * id;
    if (!mat4_finite(out)) {
        *out = mat4_identity();
        return false;
    }
    return true;
}

mat4 mat4_translate(double x, double y, double z)
{
    mat4 o = mat4_identity();
    o.m[12] = x;
    o.m[13] = y;
    o.m[14] = z;
    return o;
}

mat4 mat4_scale(double x, double y, double z)
{
    mat4 o = mat4_identity();
    o.m[0] = x;
    o.m[5] = y;
    o.m[10] = z;
    return o;
}

mat4 mat4_rotate(double angle, double x, double y, double z)
{
    mat4 o = mat4_identity();
    double rad = angle * (3.14159265358979323846 / 180.0);
    double s = sin(rad), c = cos(rad);
    double mag = sqrt(x * x + y * y + z * z);

    if (!(mag > 1.0e-4)) /* Mesa leaves the matrix alone; also catches NaN */
        return o;
    x /= mag;
    y /= mag;
    z /= mag;
    double one_c = 1.0 - c;
    M(&o, 0, 0) = one_c * x * x + c;
    M(&o, 0, 1) = one_c * x * y - z * s;
    M(&o, 0, 2) = one_c * z * x + y * s;
    M(&o, 1, 0) = one_c * x * y + z * s;
    M(&o, 1, 1) = one_c * y * y + c;
    M(&o, 1, 2) = one_c * y * z - x * s;
    M(&o, 2, 0) = one_c * z * x - y * s;
    M(&o, 2, 1) = one_c * y * z + x * s;
    M(&o, 2, 2) = one_c * z * z + c;
    return o;
}

bool mat4_frustum_valid(double l, double r, double b, double t, double n, double f)
{
    /* GL 1.x: INVALID_VALUE when near or far is not positive, or any pair is
     * equal. The negated forms also reject NaN. */
    return n > 0 && f > 0 && !(l == r) && !(b == t) && !(n == f) && isfinite(l) && isfinite(r) &&
           isfinite(b) && isfinite(t) && isfinite(f);
}

bool mat4_ortho_valid(double l, double r, double b, double t, double n, double f)
{
    return !(l == r) && !(b == t) && !(n == f) && isfinite(l) && isfinite(r) && isfinite(b) &&
           isfinite(t) && isfinite(n) && isfinite(f);
}

mat4 mat4_frustum(double l, double r, double b, double t, double n, double f)
{
    mat4 o = {{0}};
    M(&o, 0, 0) = 2 * n / (r - l);
    M(&o, 1, 1) = 2 * n / (t - b);
    M(&o, 0, 2) = (r + l) / (r - l);
    M(&o, 1, 2) = (t + b) / (t - b);
    M(&o, 2, 2) = -(f + n) / (f - n);
    M(&o, 2, 3) = -(2 * f * n) / (f - n);
    M(&o, 3, 2) = -1;
    return o;
}

mat4 mat4_ortho(double l, double r, double b, double t, double n, double f)
{
    mat4 o = mat4_identity();
    M(&o, 0, 0) = 2 / (r - l);
    M(&o, 1, 1) = 2 / (t - b);
    M(&o, 2, 2) = -2 / (f - n);
    M(&o, 0, 3) = -(r + l) / (r - l);
    M(&o, 1, 3) = -(t + b) / (t - b);
    M(&o, 2, 3) = -(f + n) / (f - n);
    return o;
}

bool mat4_perspective(double fovy, double aspect, double n, double f, mat4 *out)
{
    double radians = fovy / 2 * 3.14159265358979323846 / 180;
    double delta = f - n, sine = sin(radians);
    if (delta == 0 || sine == 0 || aspect == 0)
        return false;
    double cotangent = cos(radians) / sine;
    *out = mat4_identity();
    M(out, 0, 0) = cotangent / aspect;
    M(out, 1, 1) = cotangent;
    M(out, 2, 2) = -(f + n) / delta;
    M(out, 3, 2) = -1;
    M(out, 2, 3) = -2 * n * f / delta;
    M(out, 3, 3) = 0;
    return true;
}

/* SGI GLU's helpers work in float; so do these. */
static void normalize_f(float v[3])
{
    float r = (float)sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (r == 0.0f)
        return;
    v[0] /= r;
    v[1] /= r;
    v[2] /= r;
}

static void cross_f(const float a[3], const float b[3], float out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

mat4 mat4_lookat(double ex, double ey, double ez, double cx, double cy, double cz, double ux,
                 double uy, double uz)
{
    float fw[3] = {(float)(cx - ex), (float)(cy - ey), (float)(cz - ez)};
    float up[3] = {(float)ux, (float)uy, (float)uz};
    float side[3];

    normalize_f(fw);
    cross_f(fw, up, side);
    normalize_f(side);
    cross_f(side, fw, up);

    mat4 r = mat4_identity();
    for (int i = 0; i < 3; i++) {
        M(&r, 0, i) = side[i];
        M(&r, 1, i) = up[i];
        M(&r, 2, i) = -fw[i];
    }
    mat4 t = mat4_translate(-ex, -ey, -ez);
    return mat4_mul(&r, &t);
}
