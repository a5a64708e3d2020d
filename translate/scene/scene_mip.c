/* scene_mip.c: GL's level of detail of mipmapped minification (GL 2.1
 * 3.8.8) over a mesh's triangles, seen from the scene's camera: the runs
 * of triangles on one plane map of their (u, v), over which lambda is a
 * closed form a writer can evaluate per pixel, and the one value of the
 * others (docs/mapping.md section 24). Shared by the POV-Ray writer, which
 * draws it, and the interpreter, which says where that is not exact.
 */
#include "scene.h"

#include <math.h>
#include <string.h>

#include "mat4.h"

/* Triangles share a plane map when their coefficients agree this closely. */
#define MAP_EPS 1e-4

static void eye_of(const mat4 *to_eye, const float p[3], double out[3])
{
    double in[4] = {p[0], p[1], p[2], 1}, o[4];
    if (!to_eye) {
        for (int k = 0; k < 3; k++)
            out[k] = p[k];
        return;
    }
    mat4_apply(to_eye, in, o);
    for (int k = 0; k < 3; k++)
        out[k] = o[k];
}

/* Eye position = P u + Q v + R over triangle t (m: P, Q, R); false when
 * its (u, v) have no area. */
static bool tri_map(const mat4 *to_eye, const scene_vertex *verts, const scene_tri *t,
                    double m[9])
{
    const float *t0 = verts[t->v[0]].tex, *t1 = verts[t->v[1]].tex, *t2 = verts[t->v[2]].tex;
    double e[3][3];
    for (int i = 0; i < 3; i++)
        eye_of(to_eye, verts[t->v[i]].pos, e[i]);
    double d1[2] = {(double)t1[0] - t0[0], (double)t1[1] - t0[1]};
    double d2[2] = {(double)t2[0] - t0[0], (double)t2[1] - t0[1]};
    double det = d1[0] * d2[1] - d2[0] * d1[1];
    if (!isfinite(det) || fabs(det) < 1e-12)
        return false;
    for (int r = 0; r < 3; r++) {
        double e1 = e[1][r] - e[0][r], e2 = e[2][r] - e[0][r];
        double p = (e1 * d2[1] - e2 * d1[1]) / det, q = (e2 * d1[0] - e1 * d2[0]) / det;
        m[r] = p;
        m[3 + r] = q;
        m[6 + r] = e[0][r] - p * t0[0] - q * t0[1];
    }
    for (int k = 0; k < 9; k++)
        if (!isfinite(m[k]))
            return false;
    return true;
}

static bool map_close(const double a[9], const double b[9])
{
    double scale = 0;
    for (int k = 0; k < 9; k++)
        scale = fmax(scale, fabs(a[k]));
    for (int k = 0; k < 9; k++)
        if (fabs(a[k] - b[k]) > MAP_EPS * (1 + scale))
            return false;
    return true;
}

/* The camera's image coordinates of the plane map m: x = A / C, y = B / C
 * in [-1/2, 1/2] across the image (C = 1 for an orthographic camera). */
static void image_map(const scene_camera *cam, const double m[9], scene_mip_run *r)
{
    const double *axis[3] = {cam->right, cam->up, cam->direction};
    double *out[3] = {r->a, r->b, r->c};
    for (int i = 0; i < 3; i++) {
        double n2 = dot3(axis[i], axis[i]);
        if (i == 2 && cam->kind == SCENE_CAMERA_ORTHOGRAPHIC) {
            out[i][0] = out[i][1] = 0;
            out[i][2] = 1;
            continue;
        }
        double rel[3] = {m[6] - cam->location[0], m[7] - cam->location[1], m[8] - cam->location[2]};
        out[i][0] = n2 > 0 ? dot3(m, axis[i]) / n2 : 0;
        out[i][1] = n2 > 0 ? dot3(m + 3, axis[i]) / n2 : 0;
        out[i][2] = n2 > 0 ? dot3(rel, axis[i]) / n2 : 0;
    }
}

/* GL's lambda at (u, v) of run r (the C form of the SDL function). */
static double lambda_at(const scene_mip_run *r, double u, double v, double W, double H, int tw,
                        int th)
{
    double A = r->a[0] * u + r->a[1] * v + r->a[2], B = r->b[0] * u + r->b[1] * v + r->b[2];
    double C = r->c[0] * u + r->c[1] * v + r->c[2];
    if (!(fabs(C) > 1e-12))
        return 0;
    double xu = W * (r->a[0] * C - A * r->c[0]) / (C * C), xv = W * (r->a[1] * C - A * r->c[1]) / (C * C);
    double yu = H * (r->b[0] * C - B * r->c[0]) / (C * C), yv = H * (r->b[1] * C - B * r->c[1]) / (C * C);
    double det = fabs(xu * yv - xv * yu);
    double rho = fmax(hypot(yv * tw, yu * th), hypot(xv * tw, xu * th)) / fmax(det, 1e-30);
    double l = log2(fmax(rho, 1e-9));
    return isfinite(l) ? l : 0;
}

size_t scene_mip_split(const scene_camera *cam, const mat4 *to_eye, const scene_vertex *verts,
                    const scene_tri *tris, size_t nt, int tw, int th, scene_mip_run *out)
{
    memset(out, 0, sizeof *out);
    double W = cam->width > 0 ? cam->width : 1, H = cam->height > 0 ? cam->height : 1;
    double m0[9];
    bool have = tri_map(to_eye, verts, &tris[0], m0);
    size_t i = 1;
    if (have) {
        for (; i < nt; i++) {
            double m[9];
            if (!tri_map(to_eye, verts, &tris[i], m) || !map_close(m0, m))
                break;
        }
        if (i > 1 || nt == 1) {
            out->planar = true;
            image_map(cam, m0, out);
            /* Where lambda varies by less than a rounding step over the
             * run (a small face of a curved mesh), it is one value, as a
             * curved mesh's triangle's: the run joins the others of that
             * value, one mesh for all, not a mesh and functions of its own
             * (the 450 tori of real_tori_lattice: 15,000 meshes). */
            double lo = INFINITY, hi = -INFINITY;
            for (size_t k = 0; k < i; k++)
                for (int c = 0; c < 3; c++) {
                    const float *t = verts[tris[k].v[c]].tex;
                    double l = lambda_at(out, t[0], t[1], W, H, tw, th);
                    lo = fmin(lo, l);
                    hi = fmax(hi, l);
                }
            out->lo = lo;
            out->hi = hi;
            if (hi - lo < 1.0 / SCENE_MIP_STEPS) {
                out->planar = false;
                out->lambda = (lo + hi) / 2;
            }
            return i;
        }
    }
    /* A triangle on a plane of its own: its lambda at its centroid. */
    if (have) {
        scene_mip_run r;
        image_map(cam, m0, &r);
        const float *t0 = verts[tris[0].v[0]].tex, *t1 = verts[tris[0].v[1]].tex,
                    *t2 = verts[tris[0].v[2]].tex;
        out->lambda = lambda_at(&r, ((double)t0[0] + t1[0] + t2[0]) / 3,
                                ((double)t0[1] + t1[1] + t2[1]) / 3, W, H, tw, th);
        out->lo = out->hi = out->lambda;
        for (int c = 0; c < 3; c++) {
            const float *t = verts[tris[0].v[c]].tex;
            double l = lambda_at(&r, t[0], t[1], W, H, tw, th);
            out->lo = fmin(out->lo, l);
            out->hi = fmax(out->hi, l);
        }
    }
    return 1;
}
