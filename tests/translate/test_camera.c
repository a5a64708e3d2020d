/* test_camera.c: cameras from GL projections, against the formulas of
 * docs/mapping.md and against GL's own projection of random points. */
#include <stdlib.h>

#include "check.h"
#include "mat4.h"
#include "scene.h"

static const int vp[4] = {0, 0, 320, 240};

static void check_vec(const double *v, double x, double y, double z, double eps)
{
    CHECK_NEAR(v[0], x, eps);
    CHECK_NEAR(v[1], y, eps);
    CHECK_NEAR(v[2], z, eps);
}

static void test_formulas(void)
{
    scene_camera c;
    mat4 p;
    /* gluPerspective(60, 4/3): right <a * 2 tan 30, 0, 0>, up <0, 2 tan 30, 0>. */
    CHECK(mat4_perspective(60, 4.0 / 3, 1, 100, &p));
    CHECK(scene_camera_from_gl(&c, &p, vp));
    CHECK(c.kind == SCENE_CAMERA_PERSPECTIVE);
    double t30 = tan(3.14159265358979323846 / 6);
    check_vec(c.location, 0, 0, 0, 1e-12);
    check_vec(c.right, 4.0 / 3 * 2 * t30, 0, 0, 1e-12);
    check_vec(c.up, 0, 2 * t30, 0, 1e-12);
    check_vec(c.direction, 0, 0, -1, 1e-12);
    CHECK(c.width == 320 && c.height == 240);

    /* Off-axis glFrustum(-2, 1, -1, 3, 2, 10): direction <p8/p0, p9/p5, -1>. */
    p = mat4_frustum(-2, 1, -1, 3, 2, 10);
    CHECK(scene_camera_from_gl(&c, &p, vp));
    CHECK(c.kind == SCENE_CAMERA_PERSPECTIVE);
    check_vec(c.direction, -0.25, 0.5, -1, 1e-12);
    check_vec(c.right, 1.5, 0, 0, 1e-12);
    check_vec(c.up, 0, 2, 0, 1e-12);
    /* GL's near and far planes: z = -2 and z = -10. */
    CHECK(c.has_clip);
    double in_near[3] = {0, 0, -2.001}, out_near[3] = {0, 0, -1.999}, out_far[3] = {0, 0, -10.01};
    double d0 = c.clip[0][0] * in_near[0] + c.clip[0][1] * in_near[1] +
                c.clip[0][2] * in_near[2] + c.clip[0][3];
    double d1 = c.clip[0][2] * out_near[2] + c.clip[0][3];
    double d2 = c.clip[1][2] * out_far[2] + c.clip[1][3];
    CHECK(d0 > 0 && d1 < 0 && d2 < 0);

    /* glOrtho(-3, 5, -1, 2, 1, 10): location <-p12/p0, -p13/p5, -n>. */
    p = mat4_ortho(-3, 5, -1, 2, 1, 10);
    CHECK(scene_camera_from_gl(&c, &p, vp));
    CHECK(c.kind == SCENE_CAMERA_ORTHOGRAPHIC);
    check_vec(c.location, 1, 0.5, -1, 1e-12);
    check_vec(c.right, 8, 0, 0, 1e-12);
    check_vec(c.up, 0, 3, 0, 1e-12);
    check_vec(c.direction, 0, 0, -1, 1e-12);
    /* A negative near plane puts the camera behind the eye (the paper). */
    p = mat4_ortho(0, 10, 0, 10, -100, 100);
    CHECK(scene_camera_from_gl(&c, &p, vp));
    check_vec(c.location, 5, 5, 100, 1e-9);

    /* Pixel size and projection. */
    CHECK(mat4_perspective(60, 4.0 / 3, 1, 100, &p));
    scene_camera_from_gl(&c, &p, vp);
    double px, py, pt[3] = {0, 0, -10}, w[2];
    CHECK(scene_camera_pixel_size(&c, pt, &px, &py));
    CHECK_NEAR(py, 10 * 2 * t30 / 240, 1e-12);
    CHECK_NEAR(px, 10 * 4.0 / 3 * 2 * t30 / 320, 1e-12);
    double edge[3] = {10 * 4.0 / 3 * t30, 0, -10};
    CHECK(scene_camera_project(&c, edge, w));
    CHECK_NEAR(w[0], 160, 1e-9);
    double behind[3] = {0, 0, 1};
    CHECK(!scene_camera_pixel_size(&c, behind, &px, &py));

    /* The paper's look-at camera: direction length 0.5 / tan(fovy / 2). */
    double loc[3] = {0, 0, 10}, look[3] = {0, 0, 0};
    CHECK(scene_camera_lookat(&c, loc, look, 60, 320, 240));
    check_vec(c.direction, 0, 0, -0.5 / t30, 1e-12);
    check_vec(c.right, 4.0 / 3, 0, 0, 1e-12);
    check_vec(c.up, 0, 1, 0, 1e-12);
    double side[3] = {10, 0, 0};
    CHECK(scene_camera_lookat(&c, side, look, 60, 320, 240));
    check_vec(c.right, 0, 0, -4.0 / 3, 1e-12); /* looking down -x, right is -z */
    CHECK(!scene_camera_lookat(&c, loc, loc, 60, 320, 240));

    /* Singular: no camera; the identity's stands in. */
    mat4 z = {{0}};
    CHECK(!scene_camera_from_gl(&c, &z, vp));
    CHECK(c.kind == SCENE_CAMERA_ORTHOGRAPHIC);
}

/* For many projections and points, the camera's image position equals
 * GL's window position (NDC scaled to the viewport, from the centre). */
static void test_against_gl(void)
{
    srand(7);
    for (int n = 0; n < 200; n++) {
        mat4 p;
        int kind = n % 4;
        double l = -1 - rand() % 5, r = 1 + rand() % 5, b = -1 - rand() % 3, t = 1 + rand() % 3;
        if (kind == 0)
            p = mat4_frustum(l, r, b, t, 0.5 + rand() % 3, 50);
        else if (kind == 1)
            p = mat4_ortho(l, r, b, t, -5, 50);
        else {
            /* Rotated and skewed projections (gluLookAt on the wrong stack). */
            mat4 f = kind == 2 ? mat4_frustum(l, r, b, t, 1, 50) : mat4_ortho(l, r, b, t, -5, 50);
            mat4 rot = mat4_rotate(rand() % 360, 0.3, 1, 0.2);
            mat4 sk = mat4_identity();
            sk.m[4] = 0.3;
            mat4 a = mat4_mul(&rot, &sk);
            p = mat4_mul(&f, &a);
        }
        scene_camera c;
        CHECK(scene_camera_from_gl(&c, &p, vp));
        for (int k = 0; k < 5; k++) {
            double e[4] = {(rand() % 200 - 100) / 10.0, (rand() % 200 - 100) / 10.0,
                           -1 - rand() % 30, 1},
                   clip[4], w[2];
            mat4_apply(&p, e, clip);
            if (!(clip[3] > 0.01))
                continue;
            if (!scene_camera_project(&c, e, w)) {
                CHECK(!"project failed");
                continue;
            }
            CHECK_NEAR(w[0], clip[0] / clip[3] * 160, 1e-6 * (1 + fabs(w[0])));
            CHECK_NEAR(w[1], clip[1] / clip[3] * 120, 1e-6 * (1 + fabs(w[1])));
        }
    }
}

int main(void)
{
    test_formulas();
    test_against_gl();
    return CHECK_RESULT("test_camera");
}
