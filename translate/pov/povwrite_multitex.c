/* povwrite_multitex.c: a mesh textured by two units as one POV-Ray pigment
 * (docs/mapping.md "Multitexture").
 *
 * mesh2 has one uv set. Over a triangle, any second set of coordinates is
 * an affine function of the first (both interpolate linearly across it),
 * so the writer splits a mesh into runs that share that function (a quad
 * or a grid mapped as one is one run) and samples the second image at the
 * first coordinates through it. Each image becomes a pigment function; the
 * texture environment chain (GL 2.1 3.8.13) is then computed per channel
 * in a function pattern, and an average of the three channels, each mapped
 * to three times its primary, puts them back together. A channel's value
 * is kept below 1 (halved) so that the pattern never wraps.
 */
#include "povwrite_multitex.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "numfmt.h"
#include "sdltext.h"

/* Runs share a map when their coefficients agree this closely. */
#define MAP_EPS 1e-4

/* The affine map of one triangle; false when its first coordinates have
 * no area. */
static bool tri_map(const scene_vertex *verts, const scene_tri *t, double m[6])
{
    const float *p0 = verts[t->v[0]].tex, *p1 = verts[t->v[1]].tex, *p2 = verts[t->v[2]].tex;
    const float *q0 = verts[t->v[0]].tex1, *q1 = verts[t->v[1]].tex1, *q2 = verts[t->v[2]].tex1;
    double d1[2] = {(double)p1[0] - p0[0], (double)p1[1] - p0[1]};
    double d2[2] = {(double)p2[0] - p0[0], (double)p2[1] - p0[1]};
    double det = d1[0] * d2[1] - d2[0] * d1[1];
    if (!isfinite(det) || fabs(det) < 1e-12)
        return false;
    for (int r = 0; r < 2; r++) {
        double e1 = (double)q1[r] - q0[r], e2 = (double)q2[r] - q0[r];
        /* M = E D^-1 */
        double a = (e1 * d2[1] - e2 * d1[1]) / det;
        double b = (e2 * d1[0] - e1 * d2[0]) / det;
        m[3 * r] = a;
        m[3 * r + 1] = b;
        m[3 * r + 2] = q0[r] - a * p0[0] - b * p0[1];
        if (!isfinite(m[3 * r]) || !isfinite(m[3 * r + 1]) || !isfinite(m[3 * r + 2]))
            return false;
    }
    return true;
}

static bool map_close(const double a[6], const double b[6])
{
    for (int k = 0; k < 6; k++)
        if (fabs(a[k] - b[k]) > MAP_EPS * (1 + fabs(a[k])))
            return false;
    return true;
}

size_t povmt_run(const scene_vertex *verts, const scene_tri *tris, size_t nt, double map[6])
{
    bool have = false;
    size_t i = 0;
    for (; i < nt; i++) {
        double m[6];
        if (!tri_map(verts, &tris[i], m))
            continue;
        if (!have) {
            memcpy(map, m, sizeof m);
            have = true;
        } else if (!map_close(map, m)) {
            break;
        }
    }
    if (!have) { /* no area anywhere: the second coordinates of the first vertex */
        const float *q = verts[tris[0].v[0]].tex1;
        double m[6] = {0, 0, isfinite(q[0]) ? q[0] : 0, 0, 0, isfinite(q[1]) ? q[1] : 0};
        memcpy(map, m, sizeof m);
    }
    return i ? i : 1;
}

bool povmt_texel(const scene_texture *t0, const scene_texture *t1)
{
    return !(t0->env_mode == SCENE_ENV_MODULATE && !t0->colour_is_texel &&
             t1->env_mode == SCENE_ENV_MODULATE);
}

/* The `image_map{...}` of image i: its pigment text past `uv_mapping `. */
static bool image_map(const povtex *pt, size_t i, bool linear, char out[POVTEX_PIGMENT_MAX])
{
    if (povtex_image_pigment(pt, i, linear, out) == 0)
        return false;
    static const char uv[] = "uv_mapping ";
    if (strncmp(out, uv, sizeof uv - 1) == 0)
        memmove(out, out + sizeof uv - 1, strlen(out) - (sizeof uv - 1) + 1);
    return true;
}

static const char *const chan[3] = {"red", "green", "blue"};
static const char *const prim[3] = {"<3,0,0>", "<0,3,0>", "<0,0,3>"};

/* Channel k of environment t (GL 2.1 table 3.22) over the incoming colour
 * e0 with the texel at `at` (a pigment function call), as SDL, into out. */
static void env_channel(char *out, size_t cap, const scene_texture *t, int k, const char *e0,
                        const char *at)
{
    const char *ch = chan[k];
    char g[NUMFMT_F32_ROOM + 3];
    switch (t->env_mode) {
    case SCENE_ENV_ADD:
        snprintf(out, cap, "min(1,%s+%s.%s)", e0, at, ch);
        break;
    case SCENE_ENV_DECAL:
        snprintf(out, cap, "(%s*%s.transmit+%s.%s*(1-%s.transmit))", e0, at, at, ch, at);
        break;
    case SCENE_ENV_BLEND:
        snprintf(out, cap, "(%s*(1-%s.%s)+%s*%s.%s)", e0, at, ch, sdl_num(g, t->env_color[k]), at,
                 ch);
        break;
    case SCENE_ENV_REPLACE: /* of an alpha texture: the colour goes on */
        snprintf(out, cap, "%s", e0);
        break;
    default: /* GL_MODULATE */
        snprintf(out, cap, "(%s*%s.%s)", e0, at, ch);
        break;
    }
}

int povmt_pigment(outbuf *ob, const povtex *pt, size_t img0, size_t img1,
                  const scene_texture *t0, const scene_texture *t1, const float scale0[2],
                  const float offset0[2], const float scale1[2], const float offset1[2],
                  const double map[6], const float cf[4], unsigned id, char *buf, size_t cap)
{
    char im0[POVTEX_PIGMENT_MAX], im1[POVTEX_PIGMENT_MAX];
    if (!image_map(pt, img0, t0->linear, im0) || !image_map(pt, img1, t1->linear, im1))
        return -1;
    char decl[3 * POVTEX_PIGMENT_MAX];
    snprintf(decl, sizeof decl,
             "#declare rgl_mt%ua=function{pigment{%s}}\n#declare rgl_mt%ub=function{pigment{%s}}\n",
             id, im0, id, im1);
    outbuf_puts(ob, decl);

    /* Unit 1's file coordinates from the mesh's: w = S1 (M S0^-1 (u' - o0) + t) + o1. */
    double c[6];
    for (int r = 0; r < 2; r++) {
        double a = map[3 * r] / scale0[0], b = map[3 * r + 1] / scale0[1];
        double t = map[3 * r + 2] - a * offset0[0] - b * offset0[1];
        c[3 * r] = scale1[r] * a;
        c[3 * r + 1] = scale1[r] * b;
        c[3 * r + 2] = scale1[r] * t + offset1[r];
        for (int k = 0; k < 3; k++)
            if (!isfinite(c[3 * r + k]))
                c[3 * r + k] = 0;
    }
    char n[6][NUMFMT_F32_ROOM + 3];
    char at1[256];
    snprintf(at1, sizeof at1, "rgl_mt%ub(%s*x+%s*y+%s,%s*x+%s*y+%s,0)", id, sdl_num(n[0], c[0]),
             sdl_num(n[1], c[1]), sdl_num(n[2], c[2]), sdl_num(n[3], c[3]), sdl_num(n[4], c[4]),
             sdl_num(n[5], c[5]));
    char at0[64];
    snprintf(at0, sizeof at0, "rgl_mt%ua(x,y,z)", id);

    bool texel = povmt_texel(t0, t1);
    size_t len = 0;
    if (!sdl_put(buf, cap, &len, "uv_mapping average pigment_map{"))
        return -1;
    for (int k = 0; k < 3; k++) {
        const char *ch = chan[k];
        char e0[512], e1[1400], f[NUMFMT_F32_ROOM + 3];
        /* C0: unit 0's result, the fragment colour folded in when texel. */
        if (!texel || t0->colour_is_texel)
            snprintf(e0, sizeof e0, "%s.%s", at0, ch);
        else if (t0->env_mode == SCENE_ENV_DECAL) /* RGBA: by the texel's alpha (1 - transmit) */
            snprintf(e0, sizeof e0, "(%s*%s.transmit+%s.%s*(1-%s.transmit))", sdl_num(f, cf[k]), at0,
                     at0, ch, at0);
        else if (t0->env_mode == SCENE_ENV_REPLACE) /* of an alpha texture: the colour */
            snprintf(e0, sizeof e0, "%s", sdl_num(f, cf[k]));
        else
            snprintf(e0, sizeof e0, "(%s*%s.%s)", sdl_num(f, cf[k]), at0, ch);
        env_channel(e1, sizeof e1, t1, k, e0, at1);
        if (!sdl_put(buf, cap, &len, "[1 function{min(1,max(0,%s))*0.5}colour_map{[0 rgb 0][0.5 rgb %s]}]",
                 e1, prim[k]))
            return -1;
    }
    return sdl_put(buf, cap, &len, "}") ? 0 : -1;
}

int povmt_env_texture(outbuf *ob, const scene_texture *t, unsigned id, const float cf[4])
{
    char at[64], buf[POVMT_PIGMENT_MAX];
    snprintf(at, sizeof at, "rgl_mt%ua(x,y,z)", id);
    size_t len = 0;
    if (!sdl_put(buf, sizeof buf, &len, "texture{pigment{uv_mapping average pigment_map{"))
        return -1;
    for (int k = 0; k < 3; k++) {
        char e0[NUMFMT_F32_ROOM + 3], e1[1400];
        env_channel(e1, sizeof e1, t, k, sdl_num(e0, cf[k]), at);
        if (!sdl_put(buf, sizeof buf, &len,
                 "[1 function{min(1,max(0,%s))*0.5}colour_map{[0 rgb 0][0.5 rgb %s]}]", e1,
                 prim[k]))
            return -1;
    }
    if (!sdl_put(buf, sizeof buf, &len, "}}}"))
        return -1;
    outbuf_puts(ob, buf);
    return 0;
}

/* buf: `uv_mapping average pigment_map{...}` of the three channel
 * expressions e (each in 0..1 after clamping). */
static int channels(char *buf, size_t cap, char e[3][600])
{
    size_t len = 0;
    if (!sdl_put(buf, cap, &len, "uv_mapping average pigment_map{"))
        return -1;
    for (int k = 0; k < 3; k++)
        if (!sdl_put(buf, cap, &len,
                 "[1 function{min(1,max(0,%s))*0.5}colour_map{[0 rgb 0][0.5 rgb %s]}]", e[k],
                 prim[k]))
            return -1;
    return sdl_put(buf, cap, &len, "}") ? 0 : -1;
}

int povmt_env_lit(const scene_texture *t, unsigned id, const float tint[3], char *lit, size_t lcap,
                  char *env, size_t ecap)
{
    char at[64], a[3][600], b[3][600], f[2][NUMFMT_F32_ROOM + 3];
    snprintf(at, sizeof at, "rgl_mt%ua(x,y,z)", id);
    for (int k = 0; k < 3; k++) {
        if (t->env_mode == SCENE_ENV_BLEND) { /* Cf (1 - Ct) + Cc Ct */
            snprintf(a[k], sizeof a[k], "(1-%s.%s)*%s", at, chan[k], sdl_num(f[0], tint ? tint[k] : 1));
            snprintf(b[k], sizeof b[k], "%s*%s.%s", sdl_num(f[1], t->env_color[k]), at, chan[k]);
        } else { /* GL_ADD: Cf + Ct */
            snprintf(b[k], sizeof b[k], "%s.%s", at, chan[k]);
        }
    }
    if (lit && lcap)
        lit[0] = '\0';
    if (t->env_mode == SCENE_ENV_BLEND && channels(lit, lcap, a) != 0)
        return -1;
    return channels(env, ecap, b);
}

int povmt_tinted(const scene_texture *t, unsigned id, const float tint[3], char *buf, size_t cap)
{
    (void)t;
    char at[64], e[3][600], f[NUMFMT_F32_ROOM + 3];
    snprintf(at, sizeof at, "rgl_mt%ua(x,y,z)", id);
    for (int k = 0; k < 3; k++)
        snprintf(e[k], sizeof e[k], "%s.%s*%s", at, chan[k], sdl_num(f, tint[k]));
    return channels(buf, cap, e);
}

int povmt_declare(outbuf *ob, const povtex *pt, size_t img, const scene_texture *t, unsigned id)
{
    char im[POVTEX_PIGMENT_MAX], decl[2 * POVTEX_PIGMENT_MAX];
    if (!image_map(pt, img, t->linear, im))
        return -1;
    snprintf(decl, sizeof decl, "#declare rgl_mt%ua=function{pigment{%s}}\n", id, im);
    outbuf_puts(ob, decl);
    return 0;
}
