/* povwrite_mipmap.c: mipmapped minification (GL 2.1 3.8.8, 3.8.9) in
 * POV-Ray, which has no mipmaps (issue 14; docs/mapping.md section 24).
 *
 * GL picks a level per fragment from lambda = log2(rho), rho the texel
 * footprint of one pixel: the larger of the lengths of d(u W, v H)/dx and
 * /dy in window coordinates. The writer knows the camera, so over a run of
 * triangles on one plane whose (u, v) map affinely to eye space (the runs:
 * scene_mip_split, scene/scene_mip.c), the
 * camera's image coordinates are ratios of affine functions of (u, v), and
 * rho is a closed form of (u, v): a POV-Ray function, evaluated per pixel
 * at the surface's uv. The levels are a pigment_map indexed by lambda: for
 * GL_*_MIPMAP_LINEAR consecutive levels at consecutive indices (the
 * pigment_map's linear blend is GL's blend of two levels), for
 * GL_*_MIPMAP_NEAREST each level over its half-open band (equal indices
 * make the step). Curved meshes (each triangle its own plane) take each
 * triangle's lambda at its centroid, rounded to 1/SCENE_MIP_STEPS of a level
 * so that the writer draws the triangles of one value as one mesh.
 */
#include "povwrite_mipmap.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "numfmt.h"
#include "sdltext.h"

#define MIP_LEVELS 15

int povmip_pigment(outbuf *ob, povtex *pt, const scene *s, int32_t t, const scene_mip_run *r,
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
