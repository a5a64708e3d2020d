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
    if (w == 0) {
        l->kind = SCENE_LIGHT_PARALLEL;
        for (int k = 0; k < 3; k++)
            l->direction[k] = g->position[k];
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
    l->spot_exponent = g->spot_exponent;
    l->spot_cutoff = g->spot_cutoff;
    memcpy(l->attenuation, g->attenuation, sizeof l->attenuation);
    l->set = set;
}

/* Where set k starts in s->lights and how many lights it has. */
static size_t set_range(const scene *s, uint32_t k, size_t *n)
{
    size_t first = 0;
    while (first < s->nlights && (s->lights[first].aimed || s->lights[first].set != k))
        first++;
    size_t e = first;
    while (e < s->nlights && !s->lights[e].aimed && s->lights[e].set == k)
        e++;
    *n = e - first;
    return first;
}

/* Notes what a set's lights cost the default (shadowed) render: a set
 * whose specular colours are neither one multiple of their diffuse colours
 * nor one multiple per channel gets highlights of one fitted multiple
 * (povwrite_light.c), and a spot whose specular differs from its diffuse
 * is approximated with --no-shadows. */
static void note_set(interp *ip, const scene_light *l, size_t n)
{
    double ratio, t[3];
    if (!scene_lights_specular_ratio(l, n, &ratio) && !scene_lights_specular_channels(l, n, t))
        interp_note(ip, DIAG_NOTE_SHADOW_HIGHLIGHT);
    for (size_t i = 0; i < n; i++)
        if (l[i].kind == SCENE_LIGHT_SPOT &&
            memcmp(l[i].color, l[i].specular, sizeof l[i].color) != 0)
            interp_note(ip, DIAG_NOTE_SPOT_SPECULAR);
}

void interp_lightset_textured(interp *ip, const scene_look *look)
{
    const scene *s = ip->scene;
    if (!look->lit || look->texture < 0 || look->material < 0 ||
        (size_t)look->material >= s->nmaterials)
        return;
    size_t n, first = set_range(s, s->materials[look->material].lightset, &n);
    double ratio;
    /* The per-channel form scales the pigment, which a texture replaces. */
    if (!scene_lights_specular_ratio(s->lights + first, n, &ratio))
        interp_note(ip, DIAG_NOTE_SHADOW_HIGHLIGHT);
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
    /* The same lights as an earlier draw of the frame: its set. */
    for (uint32_t k = 0; k < s->nlightsets; k++) {
        size_t m, first = set_range(s, k, &m);
        bool same = m == n;
        for (size_t i = 0; i < n && same; i++) {
            cand[i].set = k;
            same = memcmp(&cand[i], &s->lights[first + i], sizeof cand[i]) == 0;
        }
        if (same) {
            s->lights_fixed = true;
            return ip->seen_set = k;
        }
    }
    if (s->nlightsets >= SCENE_MAX_LIGHTSETS) {
        /* Against a trace that changes its lights at every draw: later
         * sets are lit by the last one kept. */
        interp_note(ip, DIAG_NOTE_LIGHTING);
        return ip->seen_set = s->nlightsets - 1;
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
    s->nlightsets++;
    s->lights_fixed = true;
    note_set(ip, s->lights + first, s->nlights - first);
    return ip->seen_set = k;
}
