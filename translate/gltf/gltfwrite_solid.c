/* gltfwrite_solid.c: GLU/GLUT solids tessellated for glTF (gltfwrite_solid.h). */
#include "gltfwrite_solid.h"

#include <math.h>

#include "gltfwrite.h"
#include "teapot.h"

#define PI 3.14159265358979323846

/* A point of a parametric surface at (u, v) in [0,1]^2, and its normal. */
typedef void (*surface_fn)(const double *prm, int part, double u, double v, double p[3],
                           double n[3]);

static void sphere(const double *prm, int part, double u, double v, double p[3], double n[3])
{
    (void)part;
    double th = v * PI, ph = u * 2 * PI;
    n[0] = sin(th) * cos(ph);
    n[1] = sin(th) * sin(ph);
    n[2] = cos(th);
    for (int c = 0; c < 3; c++)
        p[c] = prm[0] * n[c];
}

static void box(const double *prm, int part, double u, double v, double p[3], double n[3])
{
    int axis = part / 2;
    double s = part % 2 ? 1 : -1;
    int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    n[0] = n[1] = n[2] = 0;
    n[axis] = s;
    p[axis] = s * prm[axis];
    p[a1] = (2 * u - 1) * prm[a1];
    p[a2] = (2 * v - 1) * prm[a2];
}

/* part 0 the side, 1 the base (z = 0), 2 the top */
static void cone(const double *prm, int part, double u, double v, double p[3], double n[3])
{
    double ph = u * 2 * PI, b = prm[0], t = prm[1], h = prm[2];
    if (part == 0) {
        double r = b + (t - b) * v, nl = sqrt(h * h + (b - t) * (b - t));
        p[0] = r * cos(ph);
        p[1] = r * sin(ph);
        p[2] = h * v;
        n[0] = h * cos(ph) / nl;
        n[1] = h * sin(ph) / nl;
        n[2] = (b - t) / nl;
    } else {
        double r = (part == 1 ? b : t) * v;
        p[0] = r * cos(ph);
        p[1] = r * sin(ph);
        p[2] = part == 1 ? 0 : h;
        n[0] = n[1] = 0;
        n[2] = part == 1 ? -1 : 1;
    }
}

static void torus(const double *prm, int part, double u, double v, double p[3], double n[3])
{
    (void)part;
    double a = u * 2 * PI, b = v * 2 * PI;
    n[0] = cos(b) * cos(a);
    n[1] = cos(b) * sin(a);
    n[2] = sin(b);
    p[0] = (prm[0] + prm[1] * cos(b)) * cos(a);
    p[1] = (prm[0] + prm[1] * cos(b)) * sin(a);
    p[2] = prm[1] * sin(b);
}

static void disc(const double *prm, int part, double u, double v, double p[3], double n[3])
{
    (void)part;
    double ph = u * 2 * PI, r = prm[1] + (prm[0] - prm[1]) * v;
    p[0] = r * cos(ph);
    p[1] = r * sin(ph);
    p[2] = 0;
    n[0] = n[1] = 0;
    n[2] = 1;
}

static void teapot(const double *prm, int part, double u, double v, double p[3], double n[3])
{
    teapot_eval(part, u, v, p, n);
    for (int c = 0; c < 3; c++)
        p[c] *= prm[0];
}

/* One part as a nu x nv grid of quads, each triangle turned so that its
 * front faces along the surface's normal (outward: GL's front). */
static void grid(writer *w, const scene_solid *so, surface_fn f, int part, int nu, int nv)
{
    size_t base = gltf_solid_count(w);
    if (!gltf_solid_reserve(w, (size_t)(nu + 1) * (size_t)(nv + 1)))
        return;
    double pts[(GLTF_SOLID_SLICES + 1) * (GLTF_SOLID_STACKS + 1)][3];
    double nrm[(GLTF_SOLID_SLICES + 1) * (GLTF_SOLID_STACKS + 1)][3];
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i <= nu; i++) {
            int k = j * (nu + 1) + i;
            f(so->params, part, (double)i / nu, (double)j / nv, pts[k], nrm[k]);
            gltf_solid_vertex(w, pts[k], nrm[k], so->color, &so->to_eye);
        }
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            int q[4] = {j * (nu + 1) + i, j * (nu + 1) + i + 1, (j + 1) * (nu + 1) + i + 1,
                        (j + 1) * (nu + 1) + i};
            for (int t = 0; t < 2; t++) {
                int a = q[0], b = q[1 + t], c = q[2 + t];
                double e1[3], e2[3], x[3], nsum[3];
                for (int k = 0; k < 3; k++) {
                    e1[k] = pts[b][k] - pts[a][k];
                    e2[k] = pts[c][k] - pts[a][k];
                    nsum[k] = nrm[a][k] + nrm[b][k] + nrm[c][k];
                }
                cross3(e1, e2, x);
                double d = dot3(x, nsum);
                if (d == 0)
                    continue; /* degenerate (a pole, a cone's tip) */
                if (d < 0) {
                    int s = b;
                    b = c;
                    c = s;
                }
                gltf_solid_index(w, (uint32_t)(base + (size_t)a));
                gltf_solid_index(w, (uint32_t)(base + (size_t)b));
                gltf_solid_index(w, (uint32_t)(base + (size_t)c));
            }
        }
}

static bool finite_pos(double v) { return isfinite(v) && v > 0 && v < 1e30; }

void gltf_solid_prim(writer *w, outbuf *pj, const scene_solid *so)
{
    const double *p = so->params;
    int ns = GLTF_SOLID_SLICES, nt = GLTF_SOLID_STACKS;
    switch (so->kind) {
    case SCENE_SOLID_SPHERE:
        if (finite_pos(p[0]))
            grid(w, so, sphere, 0, ns, nt);
        break;
    case SCENE_SOLID_BOX:
        if (finite_pos(p[0]) && finite_pos(p[1]) && finite_pos(p[2]))
            for (int f = 0; f < 6; f++)
                grid(w, so, box, f, 1, 1);
        break;
    case SCENE_SOLID_CONE:
        if (!finite_pos(p[2]) || !isfinite(p[0]) || !isfinite(p[1]) || p[0] < 0 || p[1] < 0 ||
            (p[0] == 0 && p[1] == 0))
            break;
        grid(w, so, cone, 0, ns, 1);
        if (!so->open && p[0] > 0)
            grid(w, so, cone, 1, ns, 1);
        if (!so->open && p[1] > 0)
            grid(w, so, cone, 2, ns, 1);
        break;
    case SCENE_SOLID_TORUS:
        if (finite_pos(p[0]) && finite_pos(p[1]) && p[0] > p[1])
            grid(w, so, torus, 0, ns, nt);
        break;
    case SCENE_SOLID_DISC:
        if (finite_pos(p[0]) && isfinite(p[1]) && p[1] >= 0 && p[1] < p[0])
            grid(w, so, disc, 0, ns, 1);
        break;
    case SCENE_SOLID_TEAPOT:
        if (finite_pos(p[0]))
            for (int k = 0; k < TEAPOT_PATCHES; k++)
                grid(w, so, teapot, k, 2 * (TEAPOT_SOLID_GRID - 1), 2 * (TEAPOT_SOLID_GRID - 1));
        break;
    }
    gltf_solid_flush(w, pj, &so->look);
}
