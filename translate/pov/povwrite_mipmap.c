/* povwrite_mipmap.c: mipmapped minification (GL 2.1 3.8.8, 3.8.9) in
 * POV-Ray, which has no mipmaps (issue 14; docs/mapping.md section 24).
 *
 * GL picks a level per fragment from lambda = log2(rho), rho the texel
 * footprint of one pixel: the larger of the lengths of d(u W, v H)/dx and
 * /dy in window coordinates. The writer knows the camera, so over a run of
 * triangles on one plane whose (u, v) map affinely to eye space, the
 * camera's image coordinates are ratios of affine functions of (u, v), and
 * rho is a closed form of (u, v): a POV-Ray function, evaluated per pixel
 * at the surface's uv. The levels are a pigment_map indexed by lambda: for
 * GL_*_MIPMAP_LINEAR consecutive levels at consecutive indices (the
 * pigment_map's linear blend is GL's blend of two levels), for
 * GL_*_MIPMAP_NEAREST each level over its half-open band (equal indices
 * make the step). Curved meshes (each triangle its own plane) take each
 * triangle's lambda at its centroid, rounded to 1/POVMIP_STEPS of a level
 * so that the writer draws the triangles of one value as one mesh.
 */
#include "povwrite_mipmap.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "numfmt.h"
#include "sdltext.h"

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
static void image_map(const scene_camera *cam, const double m[9], povmip_run *r)
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
static double lambda_at(const povmip_run *r, double u, double v, double W, double H, int tw,
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

size_t povmip_split(const scene_camera *cam, const mat4 *to_eye, const scene_vertex *verts,
                    const scene_tri *tris, size_t nt, int tw, int th, povmip_run *out)
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
            if (hi - lo < 1.0 / POVMIP_STEPS) {
                out->planar = false;
                out->lambda = (lo + hi) / 2;
            }
            return i;
        }
    }
    /* A triangle on a plane of its own: its lambda at its centroid. */
    if (have) {
        povmip_run r;
        image_map(cam, m0, &r);
        const float *t0 = verts[tris[0].v[0]].tex, *t1 = verts[tris[0].v[1]].tex,
                    *t2 = verts[tris[0].v[2]].tex;
        out->lambda = lambda_at(&r, ((double)t0[0] + t1[0] + t2[0]) / 3,
                                ((double)t0[1] + t1[1] + t2[1]) / 3, W, H, tw, th);
    }
    return 1;
}

#define MIP_LEVELS 15

int povmip_pigment(outbuf *ob, povtex *pt, const scene *s, int32_t t, const povmip_run *r,
                   unsigned id, const float uvlo[2], const float uvhi[2], bool keep_alpha,
                   const float tint[3], char *buf, size_t cap)
{
    const scene_texture *base = &s->textures[t];
    int32_t lv[MIP_LEVELS];
    int n = 0;
    for (int32_t k = t; k >= 0 && (size_t)k < s->ntextures && n < MIP_LEVELS;
         k = s->textures[k].mip_next) {
        lv[n++] = k;
        if (!s->textures[k].mip_filter)
            break;
    }
    const scene_camera *cam = &s->camera;
    double W = cam->width > 0 ? cam->width : 1, H = cam->height > 0 ? cam->height : 1;
    char f[12][NUMFMT_F32_ROOM + 3];
    /* lambda plus the bias, clamped to the LOD range (GL 2.1 3.8.8), as a
     * pigment_map index 0..1 over the levels: level k at k / (n - 1), so a
     * GL_TEXTURE_MIN_LOD above 0 starts past the base (0 at the base:
     * magnification takes it too). */
    double lo = fmax(0, base->min_lod), hi = fmin(n > 1 ? n - 1 : 1, base->max_lod);
    if (hi < lo)
        hi = lo;
    char lam[1200];
    if (r->planar) {
        char tmp[1400];
        snprintf(tmp, sizeof tmp,
                 "#declare rgl_mip%ua=function(x,y){%s*x+%s*y+%s}\n"
                 "#declare rgl_mip%ub=function(x,y){%s*x+%s*y+%s}\n"
                 "#declare rgl_mip%uc=function(x,y){%s*x+%s*y+%s}\n",
                 id, sdl_num(f[0], r->a[0]), sdl_num(f[1], r->a[1]), sdl_num(f[2], r->a[2]), id,
                 sdl_num(f[3], r->b[0]), sdl_num(f[4], r->b[1]), sdl_num(f[5], r->b[2]), id,
                 sdl_num(f[6], r->c[0]), sdl_num(f[7], r->c[1]), sdl_num(f[8], r->c[2]));
        outbuf_puts(ob, tmp);
        /* d(image)/du, dv in pixels: W (a_u C - A c_u) / C^2, ... */
        const char *name[4] = {"xu", "xv", "yu", "yv"};
        const char *fn[4] = {"a", "a", "b", "b"};
        const double *co[4] = {r->a, r->a, r->b, r->b};
        for (int k = 0; k < 4; k++) {
            int d = k % 2; /* 0: u, 1: v */
            snprintf(tmp, sizeof tmp,
                     "#declare rgl_mip%u%s=function(x,y){%s*(%s*rgl_mip%uc(x,y)-rgl_mip%u%s(x,y)*%s)"
                     "/max(1e-12,pow(rgl_mip%uc(x,y),2))}\n",
                     id, name[k], sdl_num(f[0], k < 2 ? W : H), sdl_num(f[1], co[k][d]), id, id, fn[k],
                     sdl_num(f[2], r->c[d]), id);
            outbuf_puts(ob, tmp);
        }
        char tws[NUMFMT_F32_ROOM + 3], ths[NUMFMT_F32_ROOM + 3];
        sdl_num(tws, base->width);
        sdl_num(ths, base->height);
        snprintf(tmp, sizeof tmp,
                 "#declare rgl_mip%ul=function(x,y){ln(max(1e-9,max(sqrt(pow(rgl_mip%uyv(x,y)*%s,2)+"
                 "pow(rgl_mip%uyu(x,y)*%s,2)),sqrt(pow(rgl_mip%uxv(x,y)*%s,2)+pow(rgl_mip%uxu(x,y)*%s,2)))"
                 "/max(1e-30,abs(rgl_mip%uxu(x,y)*rgl_mip%uyv(x,y)-rgl_mip%uxv(x,y)*rgl_mip%uyu(x,y)))))"
                 "/0.6931471805599453}\n",
                 id, id, tws, id, ths, id, tws, id, ths, id, id, id, id);
        outbuf_puts(ob, tmp);
        snprintf(lam, sizeof lam, "function{min(%s,max(%s,rgl_mip%ul(x,y)+%s))/%s}",
                 sdl_num(f[0], hi), sdl_num(f[1], lo), id, sdl_num(f[4], base->lod_bias),
                 sdl_num(f[3], n > 1 ? n - 1 : 1));
    } else {
        double l = fmin(hi, fmax(lo, r->lambda + base->lod_bias));
        /* Half way between two levels Mesa rounds up under
         * GL_*_MIPMAP_NEAREST (conf_tex_lod_bias: 2 + 1.5 takes level 4),
         * where the pigment_map's tie would take the lower. */
        bool nearest = base->mip_filter == SCENE_MIP_NEAREST_MIPMAP_NEAREST ||
                       base->mip_filter == SCENE_MIP_LINEAR_MIPMAP_NEAREST;
        if (nearest && fabs(l - floor(l) - 0.5) < 1e-6)
            l = fmin(hi, l + 1e-4);
        snprintf(lam, sizeof lam, "function{%s}", sdl_num(f[0], l / (n > 1 ? n - 1 : 1)));
    }
    (void)lam;
    size_t len = 0;
    if (!sdl_put(buf, cap, &len, "uv_mapping %s pigment_map{", lam))
        return -1;
    bool nearest_levels = base->mip_filter == SCENE_MIP_NEAREST_MIPMAP_NEAREST ||
                          base->mip_filter == SCENE_MIP_LINEAR_MIPMAP_NEAREST;
    bool linear_within = base->mip_filter == SCENE_MIP_LINEAR_MIPMAP_NEAREST ||
                         base->mip_filter == SCENE_MIP_LINEAR_MIPMAP_LINEAR;
    double span = n > 1 ? n - 1 : 1;
    for (int k = 0; k < n; k++) {
        float sc[2], off[2];
        int img = povtex_map(pt, s, lv[k], uvlo, uvhi, keep_alpha, tint, sc, off);
        if (img < 0)
            return -1;
        char body[POVTEX_DECLARED_MAX];
        /* Level 0 serves magnification too: its mag filter. */
        if (povtex_declared(ob, pt, (size_t)img, k == 0 ? base->linear : linear_within, body) == 0)
            return -1;
        char xf[200];
        snprintf(xf, sizeof xf, "translate<%s,%s,0>scale<%s,%s,1>", sdl_num(f[0], -off[0]),
                 sdl_num(f[1], -off[1]), sdl_num(f[2], 1.0 / sc[0]), sdl_num(f[3], 1.0 / sc[1]));
        /* GL_*_MIPMAP_NEAREST: level k for lambda in (k - 1/2, k + 1/2]. */
        double at[2] = {k, k};
        if (nearest_levels) {
            at[0] = k == 0 ? 0 : k - 0.5;
            at[1] = k == n - 1 ? span : k + 0.5;
        }
        for (int e = 0; e < (nearest_levels ? 2 : 1); e++) {
            double x = at[e] / span;
            if (!sdl_put(buf, cap, &len, "[%s %s %s]", sdl_num(f[4], x > 1 ? 1 : x), body, xf))
                return -1;
        }
    }
    return sdl_put(buf, cap, &len, "}") ? 0 : -1;
}
