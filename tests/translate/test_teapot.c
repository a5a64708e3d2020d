/* test_teapot.c: the teapot's patches against what freeglut 3 draws.
 *
 * The reference figures were measured from freeglut 3.4's glutSolidTeapot
 * with GL's feedback mode (docs/mapping.md): the extent of its vertices,
 * its clockwise winding and outward normals. The mirror test catches a
 * mistyped control point: the teapot is symmetric about its xy plane.
 */
#include <stdbool.h>

#include "check.h"
#include "teapot.h"

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static bool has_point(double x, double y, double z)
{
    for (int p = 0; p < TEAPOT_PATCHES; p++) {
        double cp[16][3];
        teapot_control_points(p, cp);
        for (int k = 0; k < 16; k++)
            if (fabs(cp[k][0] - x) < 1e-9 && fabs(cp[k][1] - y) < 1e-9 && fabs(cp[k][2] - z) < 1e-9)
                return true;
    }
    return false;
}

int main(void)
{
    double p[3], n[3];
    /* The rim's first point: data (1.4, 0, 2.4). */
    teapot_eval(0, 0, 0, p, n);
    CHECK_NEAR(p[0], 0.7, 1e-12);
    CHECK_NEAR(p[1], 0.4125, 1e-12);
    CHECK_NEAR(p[2], 0, 1e-12);

    for (int pt = 0; pt < TEAPOT_PATCHES; pt++) {
        double cp[16][3];
        teapot_control_points(pt, cp);
        for (int k = 0; k < 16; k++)
            CHECK(has_point(cp[k][0], cp[k][1], -cp[k][2]));
    }

    /* Extent, unit outward normals, clockwise patches, over a fine grid. */
    double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
    int bad_len = 0, bad_wind = 0;
    const int g = 40;
    for (int pt = 0; pt < TEAPOT_PATCHES; pt++)
        for (int i = 0; i <= g; i++)
            for (int j = 0; j <= g; j++) {
                double u = (double)i / g, v = (double)j / g;
                teapot_eval(pt, u, v, p, n);
                for (int k = 0; k < 3; k++) {
                    lo[k] = p[k] < lo[k] ? p[k] : lo[k];
                    hi[k] = p[k] > hi[k] ? p[k] : hi[k];
                }
                if (fabs(sqrt(dot(n, n)) - 1) > 1e-9)
                    bad_len++;
                if (i > 0 && i < g && j > 0 && j < g) {
                    double pu[3], pv[3], e1[3], e2[3], c[3], m[3];
                    teapot_eval(pt, u + 1e-4, v, pu, m);
                    teapot_eval(pt, u, v + 1e-4, pv, m);
                    for (int k = 0; k < 3; k++)
                        e1[k] = pu[k] - p[k], e2[k] = pv[k] - p[k];
                    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
                    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
                    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
                    if (dot(c, n) >= 0)
                        bad_wind++;
                }
            }
    CHECK_EQ_U(bad_len, 0);
    CHECK_EQ_U(bad_wind, 0);
    CHECK_NEAR(lo[0], -1.5, 1e-9);       /* the handle's back */
    CHECK_NEAR(hi[0], 1.717, 2e-4);      /* the spout's tip (freeglut's grid: 1.716908) */
    CHECK_NEAR(lo[1], -0.7875, 1e-9);    /* the bottom */
    CHECK_NEAR(hi[1], 0.7875, 1e-9);     /* the lid's knob */
    CHECK_NEAR(hi[2], 1.0, 1e-9);        /* the body's widest circle, radius 2 / 2 */
    CHECK_NEAR(lo[2], -1.0, 1e-9);

    /* Outward: the body's side, the lid's top and the bottom's centre. */
    teapot_eval(4, 0.5, 0.5, p, n);
    double radial[3] = {p[0], 0, p[2]};
    CHECK(dot(n, radial) > 0);
    for (int pt = 20; pt < 24; pt++) { /* freeglut: (0, 1, 0) all along the top row */
        teapot_eval(pt, 0, 0.5, p, n);
        CHECK_NEAR(n[1], 1, 1e-3);
        teapot_eval(pt, 0, 1.0 / 7, p, n);
        CHECK_NEAR(n[1], 1, 1e-3);
    }
    teapot_eval(28, 0, 0.5, p, n);
    CHECK_NEAR(n[1], -1, 1e-3);
    return CHECK_RESULT("teapot");
}
