/* povwrite_light.c: GL lighting, blending and fog in POV-Ray terms
 * (povwrite_light.h; docs/mapping.md "Lighting").
 *
 * GL lights each vertex with (GL 1.x 2.13.1)
 *   e + a Ga + sum_i att_i spot_i (a la_i + (N.L) d ld_i + (N.H)^s k ls_i).
 * POV-Ray lights each pixel with pigment P and finish
 *   P A ambient_light + P E + sum_j fade_j spot_j C_j (D P (N.L) + S (N.H)^(1/r)),
 * its specular belonging to the surface and its light having one colour.
 * So P = d (at least 1e-3 per channel), A = a (Ga + sum la_i) / P with
 * ambient_light 1, E = e / P, D = 1, S = mean(k), r = 1 / s; and with
 * --no-shadows each GL light becomes up to two POV-Ray lights at its
 * place: one of colour ls (diffuse and highlights) and a shadowless one of
 * colour ld - ls (POV-Ray gives shadowless lights no highlights), so a
 * light without specular makes none. Shadowless lights ignore a
 * spotlight's cone, so a spot whose specular colour differs from its
 * diffuse is one light of its diffuse colour (approximate). With shadows a
 * shadow must take the whole light: each GL light is one shadow-casting
 * light, of colour ld with S scaled by the light set's specular multiple,
 * or of colour ls with P = d / t where the multiple t is per channel (see
 * put_gl_light). The lights of each light set light only its objects
 * (light_group, povwrite.c). Attenuation maps onto fade_distance/fade_power (exact when
 * one of GL's linear and quadratic terms is zero), spots onto spotlight
 * with radius = falloff = cutoff and tightness = exponent (exact).
 */
#include "povwrite_light.h"

#include <math.h>
#include <string.h>

#define MIN_PIGMENT 1e-3f

/* A number for SDL: finite, within float range. */
static float fin(double v)
{
    if (!isfinite(v))
        return 0;
    if (v > 1e30)
        return 1e30f;
    if (v < -1e30)
        return -1e30f;
    return (float)v;
}

static void put_num(outbuf *ob, double v) { outbuf_f32(ob, fin(v)); }

static void put_vec(outbuf *ob, const double v[3])
{
    outbuf_putc(ob, '<');
    put_num(ob, v[0]);
    outbuf_putc(ob, ',');
    put_num(ob, v[1]);
    outbuf_putc(ob, ',');
    put_num(ob, v[2]);
    outbuf_putc(ob, '>');
}

static void put_rgb3(outbuf *ob, const double c[3])
{
    outbuf_puts(ob, "rgb");
    put_vec(ob, c);
}

static bool nonzero3(const double c[3])
{
    return c[0] != 0 || c[1] != 0 || c[2] != 0;
}

/* ---- The scene's extent ------------------------------------------------------------ */

static void grow_box(double lo[3], double hi[3], const double p[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = p[k] < lo[k] ? p[k] : lo[k];
        hi[k] = p[k] > hi[k] ? p[k] : hi[k];
    }
}

static void scene_box(const scene *s, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (size_t i = 0; i < s->nmeshes; i++) {
        const scene_mesh *m = &s->meshes[i];
        if (m->tri_count == 0)
            continue; /* s->tris may be NULL */
        const double *a = m->to_eye.m;
        const scene_tri *tri = s->tris + m->first_tri;
        /* mat4_apply's sums, the w row left out and w = 1 not multiplied
         * (m * 1 is m): the same doubles, a third of the work. */
        double lx = lo[0], ly = lo[1], lz = lo[2], hx = hi[0], hy = hi[1], hz = hi[2];
        for (size_t t = 0; t < m->tri_count; t++) {
            if (t + POOL_AHEAD < m->tri_count)
                __builtin_prefetch(&s->verts[tri[t + POOL_AHEAD].v[2]]);
            for (int c = 0; c < 3; c++) {
                uint32_t vi = tri[t].v[c];
                /* A strip's or fan's next triangle shares two corners with
                 * the one before: taken once (the box is the same). */
                if (t > 0 && (vi == tri[t - 1].v[0] || vi == tri[t - 1].v[1] ||
                              vi == tri[t - 1].v[2]))
                    continue;
                const float *p = s->verts[vi].pos;
                double x = p[0], y = p[1], z = p[2];
                if (!m->in_eye) {
                    double ox = a[0] * x + a[4] * y + a[8] * z + a[12];
                    double oy = a[1] * x + a[5] * y + a[9] * z + a[13];
                    double oz = a[2] * x + a[6] * y + a[10] * z + a[14];
                    x = ox, y = oy, z = oz;
                }
                if (isfinite(x) && isfinite(y) && isfinite(z)) {
                    lx = x < lx ? x : lx, ly = y < ly ? y : ly, lz = z < lz ? z : lz;
                    hx = x > hx ? x : hx, hy = y > hy ? y : hy, hz = z > hz ? z : hz;
                }
            }
        }
        lo[0] = lx, lo[1] = ly, lo[2] = lz, hi[0] = hx, hi[1] = hy, hi[2] = hz;
    }
    for (size_t i = 0; i < s->nlines; i++)
        for (int e = 0; e < 2; e++) {
            double p[3] = {s->lines[i].p[e][0], s->lines[i].p[e][1], s->lines[i].p[e][2]};
            if (isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]))
                grow_box(lo, hi, p);
        }
    for (size_t i = 0; i < s->nsolids; i++) { /* their centres (GLU/GLUT solids) */
        const double *m = s->solids[i].to_eye.m;
        double p[3] = {m[12], m[13], m[14]};
        if (isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]))
            grow_box(lo, hi, p);
    }
    for (size_t i = 0; i < s->npoints; i++) {
        double p[3] = {s->points[i].p[0], s->points[i].p[1], s->points[i].p[2]};
        if (isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]))
            grow_box(lo, hi, p);
    }
}

/* ---- Attenuation and spots ------------------------------------------------------------ */

/* GL's attenuation 1 / (kc + kl d + kq d^2) as POV-Ray's fade, which is
 * 2 / (1 + (d / D)^P), times a scale of the light's colour:
 *   kl = kq = 0: no fade, scale 1 / kc (exact);
 *   kl = 0: P = 2, D = sqrt(kc / kq), scale 1 / (2 kc) (exact);
 *   kq = 0: P = 1, D = kc / kl, scale 1 / (2 kc) (exact);
 *   kc = 0 with one term: a tiny D, 2 (D / d)^P (relative error D / d);
 *   otherwise a fit: for each P from 1 to 3, D and the scale match GL's
 *   value and slope at d0 (the light's distance to the scene's centre),
 *   and the P with the smallest largest relative error over the scene's
 *   distances d0 - r .. d0 + r wins. */
typedef struct fade {
    bool on;
    double distance, power, scale;
} fade;

static double gl_att(const float att[3], double d)
{
    double q = att[0] + att[1] * d + att[2] * d * d;
    return q > 0 ? 1 / q : 0;
}

static fade fit_fade(const float att[3], double d0, double r)
{
    fade f = {false, 0, 0, 1};
    double kc = att[0], kl = att[1], kq = att[2];
    if (!(d0 > 1e-6))
        d0 = 1e-6;
    if (kl == 0 && kq == 0) {
        f.scale = kc > 0 ? 1 / kc : 1e30;
        return f;
    }
    f.on = true;
    if (kc > 0 && kl == 0) {
        f.power = 2, f.distance = sqrt(kc / kq), f.scale = 1 / (2 * kc);
    } else if (kc > 0 && kq == 0) {
        f.power = 1, f.distance = kc / kl, f.scale = 1 / (2 * kc);
    } else if (kc == 0 && kq == 0) {
        f.power = 1, f.distance = 1e-5 * d0, f.scale = 1 / (2 * kl * f.distance);
    } else if (kc == 0 && kl == 0) {
        f.power = 2, f.distance = 1e-3 * d0;
        f.scale = 1 / (2 * kq * f.distance * f.distance);
    } else {
        double a0 = gl_att(att, d0);
        double gamma = d0 * (kl + 2 * kq * d0) * a0; /* -d a'(d) / a(d) at d0, in (0, 2) */
        double lo = d0 - r > 0.05 * d0 ? d0 - r : 0.05 * d0, hi = d0 + r;
        double best = INFINITY;
        for (int i = 0; i <= 200; i++) {
            double p = 1 + i * 0.01;
            if (!(p > gamma * 1.0001))
                continue;
            double u = gamma / (p - gamma); /* (d0 / D)^P */
            double dist = d0 / pow(u, 1 / p), sc = a0 * (1 + u) / 2;
            double worst = 0;
            for (int k = 0; k <= 16; k++) {
                double d = lo + (hi - lo) * k / 16;
                double want = gl_att(att, d), got = 2 * sc / (1 + pow(d / dist, p));
                double e = fabs(got - want) / want;
                worst = e > worst ? e : worst;
            }
            if (worst < best && isfinite(dist) && dist > 0) {
                best = worst;
                f.power = p, f.distance = dist, f.scale = sc;
            }
        }
        if (!(best < INFINITY)) { /* cannot happen for kc, kl, kq > 0; stay safe */
            f.power = 2, f.distance = d0, f.scale = a0;
        }
    }
    return f;
}

/* GL's attenuation and spot factor of light l at eye point p. */
static double gl_att_spot(const scene_light *l, const double p[3])
{
    if (l->kind == SCENE_LIGHT_PARALLEL)
        return 1;
    double v[3] = {p[0] - l->position[0], p[1] - l->position[1], p[2] - l->position[2]};
    double d = len3(v);
    double q = l->attenuation[0] + l->attenuation[1] * d + l->attenuation[2] * d * d;
    double f = q > 0 ? 1 / q : 0;
    if (l->kind == SCENE_LIGHT_SPOT) {
        double dl = len3(l->direction);
        double c = d > 0 && dl > 0 ? (v[0] * l->direction[0] + v[1] * l->direction[1] +
                                      v[2] * l->direction[2]) / (d * dl)
                                   : 0;
        f *= c >= cos(l->spot_cutoff * M_PI / 180) ? pow(fmax(c, 0), l->spot_exponent) : 0;
    }
    return f;
}

/* ---- Light sets ---------------------------------------------------------------------- */

static int32_t material_set(const scene *s, const scene_look *look)
{
    if (!look->lit || look->material < 0 || (size_t)look->material >= s->nmaterials)
        return POVLIGHT_UNGROUPED;
    uint32_t k = s->materials[look->material].lightset;
    return k < SCENE_MAX_LIGHTSETS ? (int32_t)k : POVLIGHT_UNGROUPED;
}

/* Which sets the frame's objects use (the frame may hold sets of draws a
 * glClear erased), and each set's highlight multiple. */
static void begin_sets(povlight *pl, const scene *s)
{
    size_t nused = 0;
    uint8_t textured[SCENE_MAX_LIGHTSETS];
    memset(textured, 0, sizeof textured);
    for (size_t i = 0; i < s->nmeshes + s->nsolids; i++) {
        const scene_look *look = i < s->nmeshes ? &s->meshes[i].look
                                                : &s->solids[i - s->nmeshes].look;
        if (i < s->nmeshes && s->meshes[i].tri_count == 0)
            continue;
        int32_t k = material_set(s, look);
        if (k >= 0 && look->texture >= 0)
            textured[k] = 1;
        if (k >= 0 && !pl->used[k]) {
            pl->used[k] = 1;
            nused++;
        }
    }
    pl->groups = nused > 1;
    pl->pass = POVLIGHT_ALL;
    for (uint32_t k = 0; k < s->nlightsets && k < SCENE_MAX_LIGHTSETS; k++) {
        size_t first = 0, n = 0;
        while (first < s->nlights && (s->lights[first].aimed || s->lights[first].set != k))
            first++;
        while (first + n < s->nlights && !s->lights[first + n].aimed &&
               s->lights[first + n].set == k)
            n++;
        double r = 1; /* no GL light: the user's (--light) keep the material's */
        double t[3];
        if (n > 0 && !scene_lights_specular_ratio(s->lights + first, n, &r) && !textured[k] &&
            scene_lights_specular_channels(s->lights + first, n, t))
            memcpy(pl->set_channel[k], t, sizeof t);
        pl->set_ratio[k] = r;
    }
}

int32_t povlight_look_set(const povlight *pl, const scene_look *look)
{
    return pl->groups ? material_set(pl->s, look) : POVLIGHT_UNGROUPED;
}

bool povlight_in_pass(const povlight *pl, const scene_look *look)
{
    return pl->pass == POVLIGHT_ALL || povlight_look_set(pl, look) == pl->pass;
}

/* ---- Per frame --------------------------------------------------------------------- */

void povlight_begin(povlight *pl, const scene *s)
{
    memset(pl, 0, sizeof *pl);
    pl->s = s;
    pl->opt = s->options;
    double lo[3], hi[3];
    scene_box(s, lo, hi);
    if (lo[0] <= hi[0]) {
        double d[3];
        for (int k = 0; k < 3; k++) {
            pl->centre[k] = (lo[k] + hi[k]) / 2;
            d[k] = hi[k] - lo[k];
        }
        pl->radius = len3(d) / 2;
    }
    if (!(pl->radius > 1e-6) || !isfinite(pl->radius))
        pl->radius = 1e-6;
    /* GL attenuates and spots each light's ambient term too; POV-Ray's
     * ambient has no place, so it is taken at the scene's centre. */
    for (size_t i = 0; i < s->nlights; i++) {
        const scene_light *l = &s->lights[i];
        if (l->aimed)
            continue;
        double f = gl_att_spot(l, pl->centre);
        for (int k = 0; k < 3; k++) {
            pl->light_ambient[k] += fin(l->ambient[k] * f);
            if (l->set < SCENE_MAX_LIGHTSETS)
                pl->set_ambient[l->set][k] += fin(l->ambient[k] * f);
        }
    }
    begin_sets(pl, s);
}

/* ---- Surfaces ------------------------------------------------------------------------ */

bool povlight_special(const scene_look *look)
{
    return look->lit || look->fog || look->blend != SCENE_BLEND_OPAQUE;
}

void povlight_texture(const povlight *pl, outbuf *ob, const scene_look *look, const float c[4],
                      int side)
{
    outbuf_puts(ob, "texture{");
    povlight_texture_body(pl, ob, look, c, side);
    outbuf_putc(ob, '}');
}

/* pigment NULL: the material's diffuse colour; else that pigment text (a
 * texture image MODULATE multiplies the lit colour by), with the finish's
 * terms unscaled and diffuse the mean of the material's (POV-Ray's diffuse
 * is one number). */
static void texture_body(const povlight *pl, outbuf *ob, const scene_look *look, const float c[4],
                         int side, const char *pigment, const float *kdp, double gain)
{
    const scene *s = pl->s;
    double t = 1 - (double)c[3];
    t = t > 0 ? (t < 1 ? t : 1) : 0;
    outbuf_puts(ob, "pigment{");
    if (pigment && (!look->lit || look->material < 0 || (size_t)look->material >= s->nmaterials)) {
        outbuf_puts(ob, pigment);
        outbuf_puts(ob, "}finish{emission ");
        double e[3] = {c[0], c[1], c[2]};
        put_rgb3(ob, e);
        outbuf_putc(ob, '}');
        return;
    }
    if (!look->lit || look->material < 0 || (size_t)look->material >= s->nmaterials) {
        /* Unlit: the #default finish makes the pixel the pigment. A
         * filter (interp_blend.c) passes filter x colour of what is behind,
         * transmit the rest of 1 - alpha unchanged. */
        double rgb[3] = {c[0], c[1], c[2]};
        double f = look->blend == SCENE_BLEND_ALPHA && look->filter > 0 ? look->filter : 0;
        if (f > 0) {
            f = f < 1 ? f : 1;
            t = 1 - f - c[3];
            t = t > 0 ? t : 0;
        }
        outbuf_puts(ob, f > 0 ? "rgbft<" : t > 0 ? "rgbt<" : "rgb<");
        for (int k = 0; k < 3; k++) {
            put_num(ob, rgb[k]);
            if (k < 2)
                outbuf_putc(ob, ',');
        }
        if (f > 0) {
            outbuf_putc(ob, ',');
            put_num(ob, f);
        }
        if (t > 0 || f > 0) {
            outbuf_putc(ob, ',');
            put_num(ob, t);
        }
        outbuf_puts(ob, ">}");
        return;
    }
    const scene_material *m = &s->materials[look->material];
    int f = m->two_sided ? side : 0;
    uint8_t cm = m->color_material[f];
    const float *ka = cm & SCENE_CM_AMBIENT ? c : m->ambient[f];
    const float *kd = cm & SCENE_CM_DIFFUSE ? c : m->diffuse[f];
    const float *ks = cm & SCENE_CM_SPECULAR ? c : m->specular[f];
    const float *ke = cm & SCENE_CM_EMISSION ? c : m->emission[f];
    double p[3], amb[3], em[3];
    bool in_set = m->lightset < SCENE_MAX_LIGHTSETS && m->lightset < s->nlightsets;
    const float *la = in_set ? pl->set_ambient[m->lightset] : pl->light_ambient;
    /* The per-channel form belongs to untextured sets (begin_sets): a
     * pigment never meets it. */
    const double *chan = in_set && !pl->opt.no_shadows && pl->set_channel[m->lightset][0] > 0
                             ? pl->set_channel[m->lightset]
                             : NULL;
    /* kdp: the pigment is the texel times kdp / max(kdp) (povlight_modulate_tint),
     * and diffuse max(kdp) makes the product the texel times kd per channel. */
    double kmax = kdp ? fmax(kdp[0], fmax(kdp[1], kdp[2])) : 1;
    for (int k = 0; k < 3; k++) {
        /* Per-channel form: lights of colour ls = t ld, so kd ld = (kd / t) ls. */
        double kdk = chan && !pigment ? kd[k] / chan[k] : kd[k];
        p[k] = pigment ? (kdp ? kdp[k] / kmax : 1) : kdk > MIN_PIGMENT ? kdk : MIN_PIGMENT;
        amb[k] = gain * ka[k] * ((double)m->model_ambient[k] + la[k]) / p[k];
        em[k] = gain * ke[k] / p[k];
    }
    if (pigment) {
        outbuf_puts(ob, pigment);
        outbuf_puts(ob, "}finish{diffuse ");
        put_num(ob, gain * (kdp ? kmax : ((double)kd[0] + kd[1] + kd[2]) / 3));
        outbuf_puts(ob, " ambient ");
    } else {
        outbuf_puts(ob, t > 0 ? "rgbt<" : "rgb<");
        for (int k = 0; k < 3; k++) {
            put_num(ob, p[k]);
            if (k < 2)
                outbuf_putc(ob, ',');
        }
        if (t > 0) {
            outbuf_putc(ob, ',');
            put_num(ob, t);
        }
        outbuf_puts(ob, ">}finish{diffuse ");
        put_num(ob, gain);
        outbuf_puts(ob, " ambient ");
    }
    put_rgb3(ob, amb);
    /* Always named: the #default finish (unlit surfaces) has emission 1. */
    outbuf_puts(ob, " emission ");
    if (nonzero3(em))
        put_rgb3(ob, em);
    else
        outbuf_putc(ob, '0');
    /* POV-Ray's highlights are not dimmed by transmit; GL blends them
     * with the rest of the colour, by alpha. */
    double spec = gain * ((double)ks[0] + ks[1] + ks[2]) / 3 * (1 - t);
    /* With shadows each light is one light of its diffuse colour
     * (povlight_lights): the highlight is the set's multiple of it. */
    if (!pl->opt.no_shadows && in_set && !chan)
        spec *= pl->set_ratio[m->lightset];
    if (spec > 0) {
        double sh = m->shininess[f];
        outbuf_puts(ob, " specular ");
        put_num(ob, spec);
        outbuf_puts(ob, " roughness ");
        put_num(ob, 1 / (sh > 1e-3 ? sh : 1e-3));
    }
    if (pl->opt.reflection > 0) {
        outbuf_puts(ob, " reflection ");
        put_num(ob, pl->opt.reflection);
    }
    outbuf_putc(ob, '}');
}

void povlight_texture_body(const povlight *pl, outbuf *ob, const scene_look *look,
                           const float c[4], int side)
{
    texture_body(pl, ob, look, c, side, NULL, NULL, 1);
}

void povlight_texture_mapped(const povlight *pl, outbuf *ob, const scene_look *look,
                             const float c[4], int side, const char *pigment)
{
    texture_body(pl, ob, look, c, side, pigment, NULL, 1);
}

void povlight_texture_tinted(const povlight *pl, outbuf *ob, const scene_look *look,
                             const float c[4], int side, const char *pigment, const float kdp[3])
{
    texture_body(pl, ob, look, c, side, pigment, kdp, 1);
}

void povlight_texture_env(const povlight *pl, outbuf *ob, const scene_look *look, const float c[4],
                          int side, const char *lit_pigment, const float *kdp,
                          const char *env_pigment)
{
    /* average halves the sum: each term at twice its weight. */
    outbuf_puts(ob, "texture{average texture_map{[1 ");
    texture_body(pl, ob, look, c, side, lit_pigment, kdp, 2);
    outbuf_puts(ob, "][1 pigment{");
    outbuf_puts(ob, env_pigment);
    outbuf_puts(ob, "}finish{emission 2 diffuse 0 ambient 0}]}}");
}

/* A tint channel is kept at least this share of the largest, so that the
 * 8-bit image still carries the texel for the ambient and emission terms
 * of a channel the diffuse colour lacks (the diffuse term there is then
 * at most this share of the light too bright). */
#define TINT_FLOOR (4.0f / 255.0f)

bool povlight_modulate_tint(const povlight *pl, const scene_look *look, const float *c,
                            float kdp[3], float tint[3])
{
    const scene *s = pl->s;
    if (!look->lit || look->material < 0 || (size_t)look->material >= s->nmaterials)
        return false;
    const scene_material *m = &s->materials[look->material];
    bool from_c = (m->color_material[0] & SCENE_CM_DIFFUSE) != 0;
    if (from_c && !c)
        return false; /* the diffuse colour varies over the mesh */
    const float *kd = from_c ? c : m->diffuse[0];
    if (m->two_sided) {
        /* One image serves both sides: their diffuse colours must agree. */
        const float *kb = m->color_material[1] & SCENE_CM_DIFFUSE ? c : m->diffuse[1];
        if (!kb || memcmp(kb, kd, 3 * sizeof *kd) != 0)
            return false;
    }
    if (kd[0] == kd[1] && kd[1] == kd[2])
        return false; /* grey: one diffuse number is exact */
    float mx = 0;
    for (int k = 0; k < 3; k++)
        mx = isfinite(kd[k]) && kd[k] > mx ? kd[k] : mx;
    if (!(mx > MIN_PIGMENT))
        return false;
    for (int k = 0; k < 3; k++) {
        kdp[k] = isfinite(kd[k]) && kd[k] > mx * TINT_FLOOR ? kd[k] : mx * TINT_FLOOR;
        tint[k] = kdp[k] / mx;
    }
    return true;
}

/* ---- Normals ----------------------------------------------------------------------------- */

bool povlight_front_facing(const povlight *pl, const double pa[3], const double pb[3],
                           const double pc[3])
{
    double e10 = pb[0] - pa[0], e11 = pb[1] - pa[1], e12 = pb[2] - pa[2];
    double e20 = pc[0] - pa[0], e21 = pc[1] - pa[1], e22 = pc[2] - pa[2];
    double g0 = e11 * e22 - e12 * e21, g1 = e12 * e20 - e10 * e22, g2 = e10 * e21 - e11 * e20;
    /* Only the sign matters: the view vector needs no normalising. */
    const scene_camera *cam = &pl->s->camera;
    if (cam->kind == SCENE_CAMERA_ORTHOGRAPHIC)
        return g0 * -cam->direction[0] + g1 * -cam->direction[1] + g2 * -cam->direction[2] > 0;
    return g0 * (cam->location[0] - pa[0]) + g1 * (cam->location[1] - pa[1]) +
               g2 * (cam->location[2] - pa[2]) >
           0;
}

/* GL lights a front face with its vertex normals as given, even where they
 * face away from the viewer (near silhouettes, inside a torus); POV-Ray
 * turns every shading normal toward the viewer, which there lights the
 * surface from the wrong side. Tilting such a normal until it is just
 * past perpendicular to the view changes N.L by (N.V)(V.L), small where
 * N.V is, instead of mirroring it. */
#define FRONT_MARGIN 0.02

void povlight_front_normal(const povlight *pl, const mat4 *to_eye, const mat4 *to_eye_inv,
                           const double p[3], const float n[3], float out[3])
{
    memcpy(out, n, 3 * sizeof *out);
    /* In scalars: arrays stored one by one and read back two at a time
     * stalled on store forwarding at every vertex. */
    double e0, e1, e2;
    if (to_eye) { /* eye normal = M^-T n */
        if (!to_eye_inv)
            return;
        const double *inv = to_eye_inv->m;
        e0 = n[0] * inv[0] + n[1] * inv[1] + n[2] * inv[2];
        e1 = n[0] * inv[4] + n[1] * inv[5] + n[2] * inv[6];
        e2 = n[0] * inv[8] + n[1] * inv[9] + n[2] * inv[10];
    } else {
        e0 = n[0], e1 = n[1], e2 = n[2];
    }
    /* Most normals face the camera well past the margin: seen without a
     * square root or a division, (N.V)^2 >= m^2 |N|^2 |V|^2 with a slack
     * of 1e-6, far above the rounding of the exact test below, which
     * decides every case near the margin. */
    const scene_camera *cam = &pl->s->camera;
    bool ortho = cam->kind == SCENE_CAMERA_ORTHOGRAPHIC;
    double v0 = ortho ? -cam->direction[0] : cam->location[0] - p[0];
    double v1 = ortho ? -cam->direction[1] : cam->location[1] - p[1];
    double v2 = ortho ? -cam->direction[2] : cam->location[2] - p[2];
    double dot = e0 * v0 + e1 * v1 + e2 * v2;
    double nn = e0 * e0 + e1 * e1 + e2 * e2;
    double vv = v0 * v0 + v1 * v1 + v2 * v2;
    if (dot > 0 && isfinite(dot * dot) && nn * vv > 0 &&
        dot * dot >= FRONT_MARGIN * FRONT_MARGIN * (1 + 1e-6) * (nn * vv))
        return;
    /* The unit vector toward the camera (toward_camera's sums). */
    double lv = sqrt(vv);
    if (!(lv > 0) || !isfinite(lv))
        return;
    v0 /= lv, v1 /= lv, v2 /= lv;
    double l = sqrt(nn); /* len3(ne) */
    if (!(l > 0) || !isfinite(l))
        return;
    e0 /= l, e1 /= l, e2 /= l;
    double d = e0 * v0 + e1 * v1 + e2 * v2;
    if (d >= FRONT_MARGIN)
        return;
    e0 += (FRONT_MARGIN - d) * v0;
    e1 += (FRONT_MARGIN - d) * v1;
    e2 += (FRONT_MARGIN - d) * v2;
    /* Back to object space: n = M^T ne (POV-Ray normalises). */
    double o0 = e0, o1 = e1, o2 = e2;
    if (to_eye) {
        const double *m = to_eye->m;
        o0 = m[0] * e0 + m[1] * e1 + m[2] * e2;
        o1 = m[4] * e0 + m[5] * e1 + m[6] * e2;
        o2 = m[8] * e0 + m[9] * e1 + m[10] * e2;
    }
    float f0 = fin(o0), f1 = fin(o1), f2 = fin(o2);
    if (f0 != 0 || f1 != 0 || f2 != 0)
        out[0] = f0, out[1] = f1, out[2] = f2;
}

/* ---- Fog -------------------------------------------------------------------------------- */

/* GL fogs a fragment by f of its eye distance c (GL 1.x 3.10; Mesa takes
 * |z_eye| unless GL_FOG_DISTANCE_MODE_NV says z_eye or the radial
 * distance): LINEAR (end - c) / (end - start) (fog_span), EXP e^(-density c), EXP2
 * e^(-(density c)^2), clamped to [0, 1], and shows f C + (1 - f) fog
 * colour. The layer is the fog colour with transmit f, over the surface's
 * own texture: POV-Ray shows (1 - f) fog + f C, and leaves the background
 * alone as GL does. The pattern is evaluated in the mesh's object space,
 * so the eye coordinates are the rows of its matrix. */
static void put_eye_row(outbuf *ob, const mat4 *to_eye, int row)
{
    double r[4] = {0, 0, 0, 0};
    r[row] = 1;
    if (to_eye)
        for (int k = 0; k < 4; k++)
            r[k] = to_eye->m[k * 4 + row];
    static const char *axis[3] = {"*x+", "*y+", "*z+"};
    for (int k = 0; k < 3; k++) {
        put_num(ob, r[k]);
        outbuf_puts(ob, axis[k]);
    }
    put_num(ob, r[3]);
}

/* GL_LINEAR's end - start, the divisor of (end - c). Where the two are
 * equal Mesa fogs by clamp(c - end) (its fog scale is 1 then, with the
 * sign of 1 / (end - start) lost), i.e. (end - c) / -1. */
static double fog_span(const scene_fog *fg)
{
    double span = (double)fg->end - fg->start;
    return span != 0 ? span : -1;
}

static void put_fog_distance(outbuf *ob, const mat4 *to_eye, int distance)
{
    switch (distance) {
    case SCENE_FOG_Z:
        outbuf_putc(ob, '(');
        put_eye_row(ob, to_eye, 2);
        outbuf_putc(ob, ')');
        break;
    case SCENE_FOG_RADIAL:
        outbuf_puts(ob, "sqrt(");
        for (int row = 0; row < 3; row++) {
            outbuf_puts(ob, row ? "+pow(" : "pow(");
            put_eye_row(ob, to_eye, row);
            outbuf_puts(ob, ",2)");
        }
        outbuf_putc(ob, ')');
        break;
    default:
        outbuf_puts(ob, "abs(");
        put_eye_row(ob, to_eye, 2);
        outbuf_putc(ob, ')');
        break;
    }
}

void povlight_fog_declare(const povlight *pl, outbuf *ob, const char *name, const mat4 *to_eye,
                          int distance)
{
    const scene_fog *fg = &pl->s->fog;
    outbuf_puts(ob, "#declare ");
    outbuf_puts(ob, name);
    outbuf_puts(ob, "=texture{pigment{function{min(1,max(0,");
    switch (fg->mode) {
    case SCENE_FOG_LINEAR:
        put_num(ob, fg->end / fog_span(fg));
        outbuf_putc(ob, '-');
        put_fog_distance(ob, to_eye, distance);
        outbuf_putc(ob, '/');
        put_num(ob, fog_span(fg));
        break;
    case SCENE_FOG_EXP2:
        outbuf_puts(ob, "exp(-pow(");
        put_fog_distance(ob, to_eye, distance);
        outbuf_putc(ob, '*');
        put_num(ob, fg->density);
        outbuf_puts(ob, ",2))");
        break;
    default:
        outbuf_puts(ob, "exp(-");
        put_fog_distance(ob, to_eye, distance);
        outbuf_putc(ob, '*');
        put_num(ob, fg->density);
        outbuf_puts(ob, ")");
        break;
    }
    double fc[3] = {fg->color[0], fg->color[1], fg->color[2]};
    outbuf_puts(ob, "))}color_map{[0 rgbt<");
    for (int k = 0; k < 3; k++) {
        put_num(ob, fc[k]);
        outbuf_putc(ob, ',');
    }
    outbuf_puts(ob, "0>][1 rgbt<");
    for (int k = 0; k < 3; k++) {
        put_num(ob, fc[k]);
        outbuf_putc(ob, ',');
    }
    outbuf_puts(ob, "1>]}}finish{ambient 0 diffuse 0 emission 1}}\n");
}

/* ---- Lights ------------------------------------------------------------------------------ */

/* One POV-Ray light_source of colour col at the GL light's place. */
static void put_light(const povlight *pl, outbuf *ob, const scene_light *l, const double col[3],
                      bool shadowless)
{
    double loc[3], at[3];
    double dist;
    if (l->kind == SCENE_LIGHT_PARALLEL) {
        /* Outside the scene, toward the light: POV-Ray's parallel light
         * casts no shadows from behind its location. */
        double dl = len3(l->direction);
        dist = 2 * pl->radius + 1;
        for (int k = 0; k < 3; k++) {
            loc[k] = pl->centre[k] + l->direction[k] / dl * dist;
            at[k] = pl->centre[k];
        }
    } else {
        for (int k = 0; k < 3; k++) {
            loc[k] = l->position[k];
            at[k] = l->position[k] + l->direction[k];
        }
        double v[3] = {pl->centre[0] - loc[0], pl->centre[1] - loc[1], pl->centre[2] - loc[2]};
        dist = len3(v);
    }
    fade fd = {false, 0, 0, 1};
    if (l->kind != SCENE_LIGHT_PARALLEL)
        fd = fit_fade(l->attenuation, dist, pl->radius);
    double c[3] = {col[0] * fd.scale, col[1] * fd.scale, col[2] * fd.scale};
    outbuf_puts(ob, "light_source{");
    put_vec(ob, loc);
    outbuf_putc(ob, ' ');
    put_rgb3(ob, c);
    if (l->kind == SCENE_LIGHT_PARALLEL) {
        outbuf_puts(ob, " parallel point_at");
        put_vec(ob, at);
    } else if (l->kind == SCENE_LIGHT_SPOT) {
        outbuf_puts(ob, " spotlight radius ");
        put_num(ob, l->spot_cutoff);
        outbuf_puts(ob, " falloff ");
        put_num(ob, l->spot_cutoff);
        outbuf_puts(ob, " tightness ");
        put_num(ob, l->spot_exponent);
        outbuf_puts(ob, " point_at");
        put_vec(ob, at);
    }
    if (fd.on) {
        outbuf_puts(ob, " fade_distance ");
        put_num(ob, fd.distance);
        outbuf_puts(ob, " fade_power ");
        put_num(ob, fd.power);
    }
    if (shadowless) {
        outbuf_puts(ob, " shadowless");
    } else if (pl->opt.area_lights > 1 && !pl->opt.no_shadows) {
        /* A disc facing the scene, a tenth of the distance across. */
        double a = 0.1 * (dist > 0 ? dist : pl->radius);
        double ax[3] = {a, 0, 0}, ay[3] = {0, a, 0};
        outbuf_puts(ob, " area_light");
        put_vec(ob, ax);
        outbuf_putc(ob, ',');
        put_vec(ob, ay);
        outbuf_putc(ob, ',');
        outbuf_u64(ob, (uint64_t)pl->opt.area_lights);
        outbuf_putc(ob, ',');
        outbuf_u64(ob, (uint64_t)pl->opt.area_lights);
        outbuf_puts(ob, " adaptive 1 circular orient");
    }
    outbuf_puts(ob, "}\n");
}

/* One GL light. With --no-shadows: a light of colour ls (diffuse and
 * highlights) and a shadowless one of ld - ls (no highlights), exact. With
 * shadows, a shadow must take the whole light: one shadow-casting light of
 * colour ld, whose highlights the finish scales by the set's multiple
 * (texture_body; exact when ls is that multiple of ld). A light with
 * specular and no diffuse keeps the split (its diffuse parts cancel). */
static void put_gl_light(const povlight *pl, outbuf *ob, const scene_light *l)
{
    if (l->kind == SCENE_LIGHT_PARALLEL && !(len3(l->direction) > 0))
        return; /* GL: a direction of zero lights nothing but ambient */
    double spec[3], rest[3], dif[3];
    for (int k = 0; k < 3; k++) {
        spec[k] = l->specular[k];
        rest[k] = (double)l->color[k] - l->specular[k];
        dif[k] = l->color[k];
    }
    if (!pl->opt.no_shadows && nonzero3(dif)) {
        if (l->set < SCENE_MAX_LIGHTSETS && pl->set_channel[l->set][0] > 0)
            put_light(pl, ob, l, spec, false); /* the per-channel form: ls */
        else
            put_light(pl, ob, l, dif, false);
        return;
    }
    if (l->kind == SCENE_LIGHT_SPOT && nonzero3(rest)) {
        /* POV-Ray's shadowless lights ignore the spot cone: a spot is
         * one light of its diffuse colour, its highlights those of a
         * specular colour equal to it (approximate; noted). */
        for (int k = 0; k < 3; k++) {
            spec[k] = l->color[k];
            rest[k] = 0;
        }
    }
    if (nonzero3(spec))
        put_light(pl, ob, l, spec, false);
    if (nonzero3(rest)) {
        if (!pl->opt.no_shadows)
            outbuf_puts(ob, "// diffuse beyond the light's specular colour: no shadow, no "
                            "highlight (docs/mapping.md)\n");
        put_light(pl, ob, l, rest, true);
    }
}

/* rayglFrameBegin's white light, as the paper wrote it. */
static void put_aimed(outbuf *ob, const scene_light *l)
{
    double c[3] = {l->color[0], l->color[1], l->color[2]};
    outbuf_puts(ob, "light_source{");
    put_vec(ob, l->position);
    outbuf_putc(ob, ' ');
    put_rgb3(ob, c);
    outbuf_puts(ob, " parallel point_at");
    put_vec(ob, l->point_at);
    outbuf_puts(ob, "}\n");
}

void povlight_lights(const povlight *pl, outbuf *ob)
{
    const scene *s = pl->s;
    /* One set lights the objects: its lights, for every object. */
    int32_t only = -1;
    for (uint32_t k = 0; k < s->nlightsets && k < SCENE_MAX_LIGHTSETS && only < 0; k++)
        if (pl->used[k])
            only = (int32_t)k;
    for (size_t i = 0; i < s->nlights; i++) {
        const scene_light *l = &s->lights[i];
        if (l->added)
            continue; /* the look's, after the scene (povwrite_look.c) */
        if (l->aimed)
            put_aimed(ob, l);
        else if (!pl->groups && (only < 0 || l->set == (uint32_t)only))
            put_gl_light(pl, ob, l);
    }
}

void povlight_set_lights(const povlight *pl, outbuf *ob, uint32_t set)
{
    const scene *s = pl->s;
    for (size_t i = 0; i < s->nlights; i++)
        if (!s->lights[i].aimed && s->lights[i].set == set)
            put_gl_light(pl, ob, &s->lights[i]);
}
