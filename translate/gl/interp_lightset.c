/* interp_lightset.c: the frame's light sets (docs/mapping.md "Lights per
 * object").
 *
 * GL lights each draw with the lights enabled when it is drawn; a frame may
 * light one object with some lights and the next with others (enabled,
 * disabled, moved, recoloured). Each lit draw's lights, as scene lights in
 * eye space, form a set; identical sets are one (the writer groups the
 * objects of a set in one light_group), so a frame whose lights never
 * change has one set and the SDL of a single set. interp_light.c calls
 * interp_lightset_current for every lit draw and stores the result in the
 * draw's material.
 */
#include "interp_internal.h"

#include <string.h>

/* The scene light of GL light g (enabled), zeroed first so that sets compare
 * bytewise. */
static void make_light(const gl_light *g, uint32_t set, scene_light *l)
{
    memset(l, 0, sizeof *l);
    float w = g->position[3];
    float f = 1;
    if (w == 0) {
        l->kind = SCENE_LIGHT_PARALLEL;
        for (int k = 0; k < 3; k++)
            l->direction[k] = g->position[k];
        f = (float)interp_spot_parallel(g);
    } else {
        l->kind = g->spot_cutoff == 180 ? SCENE_LIGHT_POINT : SCENE_LIGHT_SPOT;
        for (int k = 0; k < 3; k++) {
            l->position[k] = (double)g->position[k] / w;
            l->direction[k] = g->spot_direction[k];
        }
    }
    memcpy(l->color, g->diffuse, sizeof l->color);
    memcpy(l->ambient, g->ambient, sizeof l->ambient);
    memcpy(l->specular, g->specular, sizeof l->specular);
    for (int k = 0; k < 3 && f != 1; k++) { /* a directional light's spot: one factor */
        l->color[k] *= f;
        l->ambient[k] *= f;
        l->specular[k] *= f;
    }
    l->spot_exponent = w == 0 ? 0 : g->spot_exponent;
    l->spot_cutoff = w == 0 ? 180 : g->spot_cutoff;
    memcpy(l->attenuation, g->attenuation, sizeof l->attenuation);
    l->set = set;
}

/* Where set k starts in s->lights and how many lights it has: kept when
 * the set is made, so that a trace switching between many sets costs one
 * lookup per draw (interp_internal.h, lsets). */
static size_t set_range(const interp *ip, uint32_t k, size_t *n)
{
    *n = ip->lsets.n[k];
    return ip->lsets.first[k];
}

/* FNV-1a over the candidate lights (made with set 0). */
static uint64_t hash_lights(const scene_light *l, size_t n)
{
    const unsigned char *p = (const unsigned char *)l;
    uint64_t h = 14695981039346656037ull;
    for (size_t i = 0; i < n * sizeof *l; i++)
        h = (h ^ p[i]) * 1099511628211ull;
    return h ^ n;
}

#define SLOTS (sizeof ((interp *)0)->lsets.slot / sizeof ((interp *)0)->lsets.slot[0])

/* Notes what a set's lights cost the default (shadowed) render: a set
 * whose specular colours are neither one multiple of their diffuse colours
 * nor one multiple per channel gets highlights of one fitted multiple
 * (povwrite_light.c), and a spot whose specular differs from its diffuse
 * is approximated with --no-shadows. */
void interp_set_shadows(interp *ip, bool on) { ip->no_shadows = !on; }

void interp_set_pov(interp *ip, bool on) { ip->not_pov = !on; }

/* Each approximation holds for one of the two renders: said for the one
 * the scenes are made for, held for the other, and for glTF output. */
static void note_render(interp *ip, diag_kind kind, bool with_shadows)
{
    if (ip->not_pov)
        interp_note_held(ip, kind, "written as glTF, not for POV-Ray");
    else if (with_shadows != ip->no_shadows)
        interp_note(ip, kind);
    else
        interp_note_held(ip, kind, with_shadows ? "rendered without shadows (--no-shadows)"
                                                : "rendered with shadows");
}

static void note_set(interp *ip, const scene_light *l, size_t n)
{
    double ratio, t[3];
    if (!scene_lights_specular_ratio(l, n, &ratio) && !scene_lights_specular_channels(l, n, t))
        note_render(ip, DIAG_NOTE_SHADOW_HIGHLIGHT, true);
    for (size_t i = 0; i < n; i++)
        if (l[i].kind == SCENE_LIGHT_SPOT &&
            memcmp(l[i].color, l[i].specular, sizeof l[i].color) != 0)
            note_render(ip, DIAG_NOTE_SPOT_SPECULAR, false);
}

void interp_lightset_textured(interp *ip, const scene_look *look)
{
    const scene *s = ip->scene;
    if (!look->lit || look->texture < 0 || look->material < 0 ||
        (size_t)look->material >= s->nmaterials)
        return;
    uint32_t k = s->materials[look->material].lightset;
    if (k >= ip->lsets.count)
        return;
    size_t n, first = set_range(ip, k, &n);
    double ratio;
    /* The per-channel form scales the pigment, which a texture replaces.
     * No lights (none could be kept): nothing to note, and s->lights may
     * be NULL. */
    if (n > 0 && !scene_lights_specular_ratio(s->lights + first, n, &ratio))
        note_render(ip, DIAG_NOTE_SHADOW_HIGHLIGHT, true);
}

uint32_t interp_lightset_current(interp *ip)
{
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    if (s->lights_fixed) {
        bool same = true;
        for (int i = 0; i < INTERP_MAX_LIGHTS && same; i++) {
            bool on = a->caps[INTERP_CAP_LIGHT0 + i] != 0;
            same = on == (ip->seen_light_on[i] != 0) &&
                   (!on || memcmp(&a->lighting.light[i], &ip->seen_light[i], sizeof(gl_light)) == 0);
        }
        if (same)
            return ip->seen_set;
    }
    scene_light cand[INTERP_MAX_LIGHTS];
    size_t n = 0;
    for (int i = 0; i < INTERP_MAX_LIGHTS; i++) {
        ip->seen_light_on[i] = a->caps[INTERP_CAP_LIGHT0 + i] != 0;
        ip->seen_light[i] = a->lighting.light[i];
        if (ip->seen_light_on[i])
            make_light(&a->lighting.light[i], 0, &cand[n++]);
    }
    if (ip->lsets.count > s->nlightsets) { /* a new frame's scene */
        ip->lsets.count = 0;
        memset(ip->lsets.slot, 0, sizeof ip->lsets.slot);
    }
    /* The same lights as an earlier draw of the frame: its set. */
    uint64_t h = hash_lights(cand, n);
    size_t at = (size_t)(h % SLOTS);
    for (; ip->lsets.slot[at] > 0; at = (at + 1) % SLOTS) {
        uint32_t k = (uint32_t)ip->lsets.slot[at] - 1;
        size_t m, first = set_range(ip, k, &m);
        bool same = ip->lsets.hash[k] == h && m == n;
        for (size_t i = 0; i < n && same; i++) {
            scene_light c = cand[i];
            c.set = k;
            same = memcmp(&c, &s->lights[first + i], sizeof c) == 0;
        }
        if (same) {
            s->lights_fixed = true;
            return ip->seen_set = k;
        }
    }
    if (s->nlightsets >= SCENE_MAX_LIGHTSETS || s->nlightsets != ip->lsets.count) {
        /* Against a trace that changes its lights at every draw: later
         * sets are lit by the last one kept. */
        interp_note(ip, DIAG_NOTE_LIGHTING);
        return ip->seen_set = s->nlightsets ? s->nlightsets - 1 : 0;
    }
    uint32_t k = s->nlightsets;
    size_t first = s->nlights;
    for (size_t i = 0; i < n; i++) {
        scene_light *l = scene_add_light(s);
        if (!l)
            break;
        cand[i].set = k;
        *l = cand[i];
    }
    ip->lsets.first[k] = (uint32_t)first;
    ip->lsets.n[k] = (uint8_t)(s->nlights - first);
    ip->lsets.hash[k] = h;
    ip->lsets.slot[at] = (int16_t)(k + 1);
    ip->lsets.count = ++s->nlightsets;
    s->lights_fixed = true;
    if (s->nlights > first) /* none kept: s->lights may be NULL */
        note_set(ip, s->lights + first, s->nlights - first);
    return ip->seen_set = k;
}
