/* povwrite_cube.c: cube maps (GL_TEXTURE_CUBE_MAP) in POV-Ray (issue 14;
 * docs/mapping.md section 24).
 *
 * GL interpolates each vertex's (s, t, r) over a face (from
 * GL_REFLECTION_MAP or GL_NORMAL_MAP texgen, or given) and, per fragment,
 * takes the face of the major axis and the texel at the other two
 * coordinates divided by it. The mesh carries (s, t) as its uv; over a run
 * of triangles r is one affine function of (s, t) (povmt_run, as a second
 * unit's coordinates), so a pigment function of the uv computes GL's
 * direction, face and texel per pixel: GL's per-vertex-interpolated look,
 * not a ray-traced reflection.
 */
#include "povwrite_cube.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "numfmt.h"
#include "sdltext.h"

int povcube_declare(outbuf *ob, povtex *pt, const scene *s, int32_t t, unsigned id, povcube *c)
{
    c->id = id;
    int32_t f = t;
    for (int k = 0; k < 6; k++) {
        if (f < 0 || (size_t)f >= s->ntextures)
            return -1;
        const scene_texture *tx = &s->textures[f];
        float lo[2] = {0, 0}, hi[2] = {1, 1};
        int img = povtex_map(pt, s, f, lo, hi, false, NULL, c->scale[k], c->offset[k]);
        char im[POVTEX_PIGMENT_MAX];
        if (img < 0 || povtex_image_pigment(pt, (size_t)img, tx->linear, im) == 0)
            return -1;
        const char *body = strncmp(im, "uv_mapping ", 11) == 0 ? im + 11 : im;
        char decl[POVTEX_PIGMENT_MAX + 64];
        snprintf(decl, sizeof decl, "#declare rgl_cube%uf%d=function{pigment{%s}}\n", id, k, body);
        outbuf_puts(ob, decl);
        f = tx->mip_next;
    }
    /* Per channel, a function of the direction (x, y, z) = (s, t, r):
     * table 3.21, sc and tc over the major axis ma, per face. */
    static const char *const sc[6] = {"-z", "z", "x", "x", "x", "-x"};
    static const char *const tc[6] = {"-y", "-y", "z", "-z", "-y", "-y"};
    static const char *const ma[6] = {"x", "x", "y", "y", "z", "z"};
    static const char *const chan[3] = {"red", "green", "blue"};
    char n[4][NUMFMT_F32_ROOM + 3];
    for (int ch = 0; ch < 3; ch++) {
        char face[6][300];
        for (int k = 0; k < 6; k++)
            snprintf(face[k], sizeof face[k],
                     "rgl_cube%uf%d((%s/max(1e-30,abs(%s))+1)/2*%s+%s,(%s/max(1e-30,abs(%s))+1)/2*%s+%s,0).%s", id, k,
                     sc[k], ma[k], sdl_num(n[0], c->scale[k][0]), sdl_num(n[1], c->offset[k][0]), tc[k],
                     ma[k], sdl_num(n[2], c->scale[k][1]), sdl_num(n[3], c->offset[k][1]), chan[ch]);
        char decl[2400];
        snprintf(decl, sizeof decl,
                 "#declare rgl_cube%uc%d=function(x,y,z){select(min(abs(x)-abs(y),abs(x)-abs(z)),"
                 "select(abs(y)-abs(z),select(z,%s,%s),select(y,%s,%s)),select(x,%s,%s))}\n",
                 id, ch, face[5], face[4], face[3], face[2], face[1], face[0]);
        outbuf_puts(ob, decl);
    }
    return 0;
}

int povcube_pigment(const povcube *c, const double map[6], char *buf, size_t cap)
{
    char f[3][NUMFMT_F32_ROOM + 3];
    char r[160];
    snprintf(r, sizeof r, "%s*x+%s*y+%s", sdl_num(f[0], map[0]), sdl_num(f[1], map[1]), sdl_num(f[2], map[2]));
    static const char *const prim[3] = {"<3,0,0>", "<0,3,0>", "<0,0,3>"};
    size_t len = 0;
    if (!sdl_put(buf, cap, &len, "uv_mapping average pigment_map{"))
        return -1;
    for (int ch = 0; ch < 3; ch++)
        if (!sdl_put(buf, cap, &len,
                 "[1 function{min(1,max(0,rgl_cube%uc%d(x,y,%s)))*0.5}colour_map{[0 rgb 0][0.5 rgb %s]}]",
                 c->id, ch, r, prim[ch]))
            return -1;
    return sdl_put(buf, cap, &len, "}") ? 0 : -1;
}
