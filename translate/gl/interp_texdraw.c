/* interp_texdraw.c: what a draw samples (issue 5): a unit's complete
 * texture as a scene texture (the level, the slice of a 3D texture, a cube
 * map's faces, the mipmap chain, a depth texture compared with r, the
 * environment and the alpha test), and
 * the texture coordinates GL gives each vertex: texgen (object and eye
 * linear, sphere, normal and reflection maps), the texture matrix, q.
 */
#include <stdio.h>
#include <string.h>

#include "interp_internal.h"
#include "interp_teximage.h"
#include "talloc.h"

/* ---- Scene textures, made once -------------------------------------------------------- */

/* tex_made.how: the image as it is, mirrored (mirror clamp) along s or t,
 * a cube map's face, a 3D texture's slice (linear between two, the wrap
 * mode of r above bit 32), a depth texture compared with r (the compare
 * function above bit 16, the depth texture mode above bit 32). */
enum {
    MADE_PLAIN = 1,
    MADE_MIRROR_S = 2,
    MADE_MIRROR_T = 4,
    MADE_FACE = 8,
    MADE_SLICE = 16,
    MADE_SLICE_LINEAR = 32,
    MADE_COMPARE = 64
};

void interp_texture_begin_frame(interp *ip)
{
    if (ip->st.tex) {
        ip->st.tex->nmade = 0;
        ip->st.tex->made_sc = NULL;
    }
}

/* The scene texture made from image `serial` by `how` (at r) and sampled
 * as st (its texels aside), or -1. A scene that dropped textures since
 * forgets them all. */
static int32_t made_find(interp *ip, uint64_t serial, uint64_t how, double r,
                         const scene_texture *st)
{
    interp_textures *t = ip->st.tex;
    const scene *s = ip->scene;
    if (t->made_sc != s || t->made_gen != s->generation) {
        t->nmade = 0;
        t->made_sc = s;
        t->made_gen = s->generation;
        return -1;
    }
    for (size_t i = t->nmade; i-- > 0;) {
        const struct tex_made *m = &t->made[i];
        if (m->serial == serial && m->how == how && m->r == r && m->index >= 0 &&
            (size_t)m->index < s->ntextures &&
            scene_texture_sampling_same(&s->textures[m->index], st))
            return m->index;
    }
    return -1;
}

/* Remembers that scene texture index was made so (made_find). Without
 * memory, the next draw makes it again, and no more. */
static void made_add(interp *ip, uint64_t serial, uint64_t how, double r, int32_t index)
{
    interp_textures *t = ip->st.tex;
    if (index < 0 || !serial || t->made_sc != ip->scene ||
        tr_grow((void **)&t->made, &t->cap_made, t->nmade + 1, sizeof *t->made) != 0)
        return;
    t->made[t->nmade++] = (struct tex_made){serial, how, r, index};
}

/* ---- Drawing -------------------------------------------------------------------------- */

static bool mipmap_filter(GLenum f) { return f != GL_NEAREST && f != GL_LINEAR; }

/* The last level of the mipmap chain from base b (GL 2.1 3.8.8: q, at
 * most GL_TEXTURE_MAX_LEVEL). */
static int last_level(const tex_obj *o, int b)
{
    int p = 0;
    while ((o->lw[b] >> p) > 1 || (o->lh[b] >> p) > 1)
        p++;
    int q = b + p;
    if (q > o->max_level)
        q = o->max_level;
    return q < TEX_LEVELS ? q : TEX_LEVELS - 1;
}

/* A 3D texture's completeness: level 0 and, for a mipmapping
 * minification filter, every level down to 1 x 1 x 1 defined with the
 * size halving gives (interp_tex_image3d counts them). */
static bool complete3d(const tex_obj *o)
{
    if (!o->img || !o->depth3)
        return false;
    if (!mipmap_filter(o->min_filter))
        return true;
    int top = 0, h = o->img->height / o->depth3;
    while ((o->img->width >> top) > 1 || (h >> top) > 1 || (o->depth3 >> top) > 1)
        top++;
    for (int k = 0; k <= top && k < 32; k++)
        if (!(o->levels & (1u << k)))
            return false;
    return true;
}

/* GL 2.1 3.8.10: complete when the base level (GL_TEXTURE_BASE_LEVEL) has
 * an image and, for a mipmapping minification filter, every level from it
 * to q has the size halving gives. A base level past the levels GL can
 * hold, or above GL_TEXTURE_MAX_LEVEL, is incomplete. */
bool interp_tex_complete(tex_obj *o)
{
    if (o->target == GL_TEXTURE_3D) /* drawn from level 0; the others only counted */
        return complete3d(o);
    int b = o->base_level;
    if (b < 0 || b >= TEX_LEVELS || b > o->max_level || !*interp_tex_level_slot(o, b))
        return false;
    if (!mipmap_filter(o->min_filter))
        return true;
    int q = last_level(o, b);
    for (int k = b + 1; k <= q; k++) {
        int32_t ew = o->lw[b] >> (k - b), eh = o->lh[b] >> (k - b);
        if (!(o->levels & (1u << k)) || o->lw[k] != (ew > 0 ? ew : 1) ||
            o->lh[k] != (eh > 0 ? eh : 1) || !*interp_tex_level_slot(o, k))
            return false;
    }
    return true;
}

#define UCAP(name) (INTERP_CAP_##name - INTERP_CAP_TEXTURE_1D)

bool interp_texture_rect_on(const interp *ip, uint32_t k)
{
    if (k >= INTERP_TEX_UNITS)
        return false;
    const gl_state *st = &ip->st;
    bool active = k == st->active_unit;
    const uint8_t *c = active ? &st->a.caps[INTERP_CAP_TEXTURE_1D] : st->units[k].caps;
    bool rect = active ? st->a.caps[INTERP_CAP_TEXTURE_RECTANGLE] : st->units[k].rect;
    return rect && !c[UCAP(TEXTURE_3D)] && !c[UCAP(TEXTURE_CUBE_MAP)];
}

/* The unit's enabled target, by GL's priority when several are enabled
 * (GL 2.1 3.8.15 with ARB_texture_rectangle: cube map, 3D, rectangle, 2D,
 * 1D). */
static tex_obj *draw_obj(interp *ip, const interp_tex_unit *u, uint32_t k)
{
    if (u->caps[UCAP(TEXTURE_CUBE_MAP)])
        return interp_tex_get_obj(ip, GL_TEXTURE_CUBE_MAP, u->texture->binding_cube, false);
    if (u->caps[UCAP(TEXTURE_3D)])
        return interp_tex_get_obj(ip, GL_TEXTURE_3D, u->texture->binding_3d, false);
    if (interp_texture_rect_on(ip, k))
        return interp_tex_get_obj(ip, GL_TEXTURE_RECTANGLE, u->texture->binding_rect, false);
    if (u->caps[UCAP(TEXTURE_2D)])
        return interp_tex_get_obj(ip, GL_TEXTURE_2D, u->texture->binding_2d, false);
    if (u->caps[UCAP(TEXTURE_1D)])
        return interp_tex_get_obj(ip, GL_TEXTURE_1D, u->texture->binding_1d, false);
    return NULL;
}

static bool clamps(GLenum wrap) { return wrap != GL_REPEAT && wrap != GL_MIRRORED_REPEAT; }

/* A cube map's six faces as scene textures, -Z first, each linked to the
 * next, +X holding the sampling (scene_texture.cube); the base's index or
 * -1 (incomplete: a face missing or of another size, GL 2.1 3.8.10, and
 * GL then draws untextured). A second unit with it is drawn without it. */
static int32_t cube_for_draw(interp *ip, tex_obj *o, const interp_tex_unit *u, int k)
{
    for (int f = 0; f < 6; f++)
        if (!o->face[f] || o->face[f]->width != o->face[0]->width ||
            o->face[f]->height != o->face[0]->height)
            return -1;
    if (ip->draw_unit[1] >= 0) {
        interp_note(ip, DIAG_NOTE_MULTITEX);
        if (ip->draw_unit[1] == k)
            return -1;
    }
    if (mipmap_filter(o->min_filter))
        interp_note(ip, DIAG_NOTE_TEX_MIPMAP);
    GLenum env = u->texture->env_mode;
    if (env != GL_MODULATE && env != GL_REPLACE) {
        interp_note(ip, DIAG_NOTE_TEXTURE);
        env = GL_MODULATE;
    }
    int32_t next = -1;
    for (int f = 5; f >= 0; f--) {
        const tex_image *im = o->face[f];
        scene_texture st;
        memset(&st, 0, sizeof st);
        st.width = im->width;
        st.height = im->height;
        st.linear = o->mag_filter == GL_LINEAR;
        st.env_mode = interp_scene_env(env);
        memcpy(st.env_color, u->texture->env_color, sizeof st.env_color);
        st.colour_is_texel = env == GL_REPLACE && o->base_format != GL_ALPHA;
        st.cube = f == 0;
        st.mip_next = next;
        int32_t have = made_find(ip, im->serial, MADE_FACE, 0, &st);
        if (have >= 0) {
            next = have;
            continue;
        }
        size_t n = (size_t)im->width * (size_t)im->height * 4;
        if (!interp_budget_texels(ip, n))
            return -1;
        st.rgba = tr_realloc(NULL, n);
        if (!st.rgba) {
            ip->scene->failed = true;
            return -1;
        }
        memcpy(st.rgba, im->rgba, n);
        next = scene_add_texture(ip->scene, &st);
        if (next < 0)
            return -1;
        made_add(ip, im->serial, MADE_FACE, 0, next);
    }
    return next;
}

/* The scene textures of o's levels from the base to q, last first, each
 * linked to the next (scene_texture.mip_next); returns the base's index.
 * st holds the sampling they share; ms and mt double each level as the
 * mirror clamp does the base (interp_tex_mirror_fill), so the level of
 * detail the writer computes from the sizes stays GL's. */
static int32_t mip_chain(interp *ip, tex_obj *o, scene_texture *st, bool ms, bool mt, float unit_bias)
{
    int b = o->base_level, q = last_level(o, b);
    int32_t next = -1;
    st->mip_filter = interp_scene_mip(o->min_filter);
    st->min_lod = o->min_lod;
    st->max_lod = o->max_lod;
    /* GL 2.1 3.8.8: the object's bias and the unit's, clamped to
     * GL_MAX_TEXTURE_LOD_BIAS (Mesa's 16), added to lambda before the
     * GL_TEXTURE_MIN_LOD .. MAX_LOD clamp. */
    double bias = (double)o->lod_bias + unit_bias;
    st->lod_bias = (float)(bias < -TEX_MAX_LOD_BIAS ? -TEX_MAX_LOD_BIAS
                           : bias > TEX_MAX_LOD_BIAS ? TEX_MAX_LOD_BIAS
                                                     : bias);
    for (int k = q; k >= b; k--) {
        const tex_image *im = *interp_tex_level_slot(o, k);
        scene_texture lt = *st;
        lt.width = im->width * (ms ? 2 : 1);
        lt.height = im->height * (mt ? 2 : 1);
        lt.mip_next = next;
        uint64_t how = MADE_PLAIN | (ms ? MADE_MIRROR_S : 0) | (mt ? MADE_MIRROR_T : 0);
        int32_t have = made_find(ip, im->serial, how, 0, &lt);
        if (have >= 0) {
            next = have;
            continue;
        }
        size_t n = (size_t)lt.width * (size_t)lt.height * 4;
        if (!interp_budget_texels(ip, n))
            return -1;
        lt.rgba = tr_realloc(NULL, n);
        if (!lt.rgba) {
            ip->scene->failed = true;
            return -1;
        }
        if (ms || mt)
            interp_tex_mirror_fill(lt.rgba, im, ms, mt);
        else
            memcpy(lt.rgba, im->rgba, n);
        next = scene_add_texture(ip->scene, &lt);
        if (next < 0)
            return -1;
        made_add(ip, im->serial, how, 0, next);
    }
    return next;
}

/* The r at which a 3D texture shows the 2D image of one slice
 * (interp_tex_slice) on the primitive drawn: r constant over it. False,
 * with a note, when r varies (or is unknown: a GLU or GLUT solid). */
static bool slice_at(interp *ip, const tex_obj *o, int k, double *r)
{
    interp_textures *t = ip->st.tex;
    double lo = t->r_min[k], hi = t->r_max[k];
    if (!(lo <= hi) || hi - lo > 1e-6 || !isfinite(lo)) {
        interp_diag(ip, DIAG_IGNORED,
                    "3D texture %u drawn untextured: its r coordinate varies over a primitive",
                    o->name);
        interp_note(ip, DIAG_NOTE_TEX_3D);
        return false;
    }
    /* GL_LINEAR's blend of two slices is rounded to 8 bits before it is
     * filtered across s and t: a level off where GL rounds once. */
    if (o->mag_filter == GL_LINEAR)
        interp_note(ip, DIAG_NOTE_TEX_3D);
    else
        interp_note_held(ip, DIAG_NOTE_TEX_3D, "GL_NEAREST picks the one slice OpenGL samples");
    *r = lo;
    return true;
}

/* GL 2.1 3.8.14: with GL_COMPARE_R_TO_TEXTURE a depth texture's texel is
 * 1 where r (clamped to [0, 1]) passes the compare function against the
 * depth D and 0 elsewhere, then taken as luminance, intensity or alpha by
 * GL_DEPTH_TEXTURE_MODE; under GL_LINEAR Mesa filters the four results.
 * Where r is constant over the primitive that is an image of results,
 * which POV-Ray's filter samples as GL does; the depth comes from the
 * 8-bit texels of src kept, compared with r (the caller's: constant).
 * NULL over the budget or without memory. */
static tex_image *tex_compared(interp *ip, const tex_obj *o, const tex_image *src, double r)
{
    size_t n = (size_t)src->width * (size_t)src->height;
    if (!interp_budget_texels(ip, n * 4))
        return NULL;
    tex_image *img = tr_realloc(NULL, sizeof *img + n * 4);
    if (!img) {
        ip->scene->failed = true;
        return NULL;
    }
    img->refs = 1;
    img->width = src->width;
    img->height = src->height;
    r = r < 0 ? 0 : r > 1 ? 1 : r;
    bool alpha = o->depth_mode == GL_ALPHA;
    for (size_t i = 0; i < n; i++) {
        const uint8_t *s = src->rgba + i * 4;
        double d = (alpha ? s[3] : s[0]) / 255.0;
        bool pass = scene_alpha_pass(interp_scene_cmp(o->compare_func), (float)r, (float)d);
        uint8_t v = pass ? 255 : 0, *q = img->rgba + i * 4;
        q[0] = q[1] = q[2] = alpha ? 255 : v;
        q[3] = o->depth_mode == GL_LUMINANCE ? 255 : v;
    }
    img->serial = 0; /* temporary: found by its source (made_find) */
    return img;
}

int32_t interp_texture_for_draw(interp *ip)
{
    interp_draw_units(ip);
    return ip->draw_unit[0] >= 0 ? interp_texture_for_unit(ip, ip->draw_unit[0]) : -1;
}

int32_t interp_texture_for_unit(interp *ip, int k)
{
    if (!ip->scene || k < 0 || k >= INTERP_TEX_UNITS)
        return -1;
    interp_tex_unit u = interp_unit(ip, (uint32_t)k);
    if (!u.caps[UCAP(TEXTURE_2D)] && !u.caps[UCAP(TEXTURE_1D)] && !u.caps[UCAP(TEXTURE_3D)] &&
        !u.caps[UCAP(TEXTURE_CUBE_MAP)] && !interp_texture_rect_on(ip, (uint32_t)k))
        return -1;
    tex_obj *o = draw_obj(ip, &u, (uint32_t)k);
    if (o && o->lost) {
        char what[DIAG_TEXT];
        snprintf(what, sizeof what, "texture %u (pixels #%u unreadable)", o->name, o->lost);
        interp_missing(ip, what);
    }
    if (o && o->target == GL_TEXTURE_CUBE_MAP)
        return cube_for_draw(ip, o, &u, k);
    if (!o || !interp_tex_complete(o))
        return -1;
    /* A 3D texture: the slice its r picks, when r is constant, made
     * below unless the scene has it. */
    double r = 0;
    if (o->depth3 && !slice_at(ip, o, k, &r))
        return -1;
    const tex_image *im = o->depth3 ? o->img : *interp_tex_level_slot(o, o->base_level); /* complete: not NULL */
    int iw = im->width, ih = o->depth3 ? im->height / o->depth3 : im->height;
    /* A depth texture compared with r: the image of results where r is
     * constant (tex_compared), made below unless the scene has it; else,
     * noted, its depth values. */
    bool compare = !o->depth3 && o->depth && o->compare_mode == GL_COMPARE_R_TO_TEXTURE;
    if (compare) {
        double lo = ip->st.tex->r_min[k], hi = ip->st.tex->r_max[k];
        if (mipmap_filter(o->min_filter) || !(lo <= hi) || hi - lo > 1e-6 || !isfinite(lo)) {
            interp_note(ip, DIAG_NOTE_TEX_COMPARE); /* level by level, or r varies */
            compare = false;
        } else {
            r = lo;
        }
    }
    GLenum env = u.texture->env_mode;
    if (env == GL_COMBINE) { /* as the fixed mode it equals, if any */
        GLenum m = interp_combine_mode(u.texture, k, ip->draw_unit[0] == k);
        env = m ? m : GL_COMBINE;
    }
    /* A second unit's ADD and BLEND are combined (povwrite's multitexture
     * pigment); a lone unit draws them as MODULATE. */
    bool chained = ip->draw_unit[1] == k && (env == GL_ADD || env == GL_BLEND);
    /* A lone unit's ADD and BLEND: povmt_env_texture, povmt_env_lit.
     * Of an alpha texture they keep the colour, as MODULATE of its white texels. */
    bool lone = ip->draw_unit[1] < 0 && (env == GL_ADD || env == GL_BLEND);
    if ((env == GL_ADD || env == GL_BLEND) && o->base_format == GL_ALPHA)
        env = GL_MODULATE;
    else if (lone && ip->prim_blend != SCENE_BLEND_OPAQUE)
        interp_note(ip, DIAG_NOTE_TEXTURE); /* drawn opaque */
    if (env != GL_MODULATE && env != GL_REPLACE && env != GL_DECAL && !chained && !lone) {
        interp_note(ip, DIAG_NOTE_TEXTURE);
        env = GL_MODULATE;
    }
    if (mipmap_filter(o->min_filter)) {
        /* per pixel on the POV-Ray writer's planar runs of a lone 1D or 2D
         * unit outside display lists: known once the triangles are */
        if (ip->mip_defer && !ip->mip_pending && ip->draw_unit[1] < 0 && ip->list_depth == 0 &&
            (o->target == GL_TEXTURE_2D || o->target == GL_TEXTURE_1D)) {
            ip->mip_pending = true;
            ip->mip_texture = -1;
        } else if (!ip->mip_pending) {
            interp_note(ip, DIAG_NOTE_TEX_MIPMAP);
        }
    } else if (o->min_filter != o->mag_filter)
        interp_note(ip, DIAG_NOTE_TEX_SAMPLING);
    /* GL_CLAMP under a linear filter blends the border colour into the
     * outer half of the edge texels (GL 2.1 3.8.8): the writer samples
     * GL's filter every half texel (povwrite_texture.c), except for the
     * levels of a mipmap, padded with the edge texels' mix with the border
     * (docs/mapping.md "Wrap"). */
    bool linear_levels = o->min_filter == GL_LINEAR_MIPMAP_NEAREST ||
                         o->min_filter == GL_LINEAR_MIPMAP_LINEAR ||
                         (mipmap_filter(o->min_filter) && o->mag_filter == GL_LINEAR);
    if (linear_levels &&
        (o->wrap_s == GL_CLAMP || (o->target != GL_TEXTURE_1D && o->wrap_t == GL_CLAMP)))
        interp_note(ip, DIAG_NOTE_TEX_CLAMP_BORDER);
    const gl_attribs *ga = &ip->st.a;
    GLenum cmm = ga->lighting.color_material_mode;
    if (env == GL_MODULATE && ga->caps[INTERP_CAP_LIGHTING] && interp_cm_on(ip) &&
        (cmm == GL_DIFFUSE || cmm == GL_AMBIENT_AND_DIFFUSE) &&
        (ip->prim_blend != SCENE_BLEND_OPAQUE || mipmap_filter(o->min_filter) ||
         o->target == GL_TEXTURE_CUBE_MAP || ga->lighting.two_side || ip->draw_unit[1] >= 0))
        interp_note(ip, DIAG_NOTE_TEX_MODULATE_CM); /* povwrite_mesh2.c mesh_tint */
    /* Mirror clamp: the image mirrored once beside itself, clamped beyond
     * (interp_vertex_texcoord maps [-1, 1] onto it). */
    bool ms = interp_mirror_clamp(o->wrap_s);
    bool mt = o->target != GL_TEXTURE_1D && interp_mirror_clamp(o->wrap_t);
    if ((ms && o->wrap_s == GL_MIRROR_CLAMP_EXT) || (mt && o->wrap_t == GL_MIRROR_CLAMP_EXT)) {
        /* The mirrored image clamped to its edge is GL's own sampling but
         * where GL_MIRROR_CLAMP_EXT blends the border colour into the
         * edge texels under linear filtering (as GL_CLAMP does). */
        bool linear = o->mag_filter == GL_LINEAR || o->min_filter == GL_LINEAR ||
                      o->min_filter == GL_LINEAR_MIPMAP_NEAREST ||
                      o->min_filter == GL_LINEAR_MIPMAP_LINEAR;
        if (linear)
            interp_note(ip, DIAG_NOTE_TEX_MIRROR_CLAMP);
        else
            interp_note_held(ip, DIAG_NOTE_TEX_MIRROR_CLAMP, "GL_NEAREST samples no border");
    } else if (ms || mt) {
        interp_note_held(ip, DIAG_NOTE_TEX_MIRROR_CLAMP,
                         "GL_MIRROR_CLAMP_TO_EDGE and _TO_BORDER are sampled as OpenGL does");
    }
    scene_texture st;
    memset(&st, 0, sizeof st);
    st.width = iw * (ms ? 2 : 1);
    st.height = ih * (mt ? 2 : 1);
    st.mip_next = -1;
    st.repeat_s = !clamps(o->wrap_s) && !ms;
    st.repeat_t = o->target == GL_TEXTURE_1D || (!clamps(o->wrap_t) && !mt);
    st.mirror_s = o->wrap_s == GL_MIRRORED_REPEAT;
    st.mirror_t = o->target != GL_TEXTURE_1D && o->wrap_t == GL_MIRRORED_REPEAT;
    st.linear = o->mag_filter == GL_LINEAR;
    st.border_s = o->wrap_s == GL_CLAMP || o->wrap_s == GL_CLAMP_TO_BORDER ||
                  o->wrap_s == GL_MIRROR_CLAMP_TO_BORDER_EXT;
    st.border_t = o->target != GL_TEXTURE_1D &&
                  (o->wrap_t == GL_CLAMP || o->wrap_t == GL_CLAMP_TO_BORDER ||
                   o->wrap_t == GL_MIRROR_CLAMP_TO_BORDER_EXT);
    st.to_border_s = o->wrap_s == GL_CLAMP_TO_BORDER;
    st.to_border_t = o->target != GL_TEXTURE_1D && o->wrap_t == GL_CLAMP_TO_BORDER;
    memcpy(st.border, o->border, sizeof st.border);
    st.env_mode = interp_scene_env(env);
    memcpy(st.env_color, u.texture->env_color, sizeof st.env_color);
    /* The alpha test per texel where the texel's alpha is the fragment's
     * (table 3.22: DECAL takes the vertex alpha, and so does a base
     * format without alpha); otherwise interp_alpha_face. */
    GLenum b0 = o->base_format;
    bool has_alpha = b0 == GL_RGBA || b0 == GL_LUMINANCE_ALPHA || b0 == GL_ALPHA ||
                     b0 == GL_INTENSITY;
    if (ga->caps[INTERP_CAP_ALPHA_TEST] && ga->color_buffer.alpha_func != GL_ALWAYS && has_alpha &&
        (env == GL_MODULATE || env == GL_REPLACE)) {
        st.alpha_func = interp_scene_cmp(ga->color_buffer.alpha_func);
        st.alpha_ref = ga->color_buffer.alpha_ref;
        st.alpha_uses_af = env != GL_REPLACE;
        float c[4];
        interp_surface_colour(ip, c); /* the current alpha (interp_alpha_face checks the vertices') */
        st.alpha_af = st.alpha_uses_af ? clamp01(c[3]) : 1;
        if (o->mag_filter == GL_LINEAR && !scene_alpha_crisp(&st))
            interp_note(ip, DIAG_NOTE_ALPHA_TEST); /* GL_EQUAL, GL_NOTEQUAL per texel */
    } else if (ga->caps[INTERP_CAP_ALPHA_TEST] && ga->color_buffer.alpha_func != GL_ALWAYS &&
               has_alpha && env != GL_DECAL) {
        interp_note(ip, DIAG_NOTE_TEXTURE); /* BLEND, ADD: drawn opaque, untested */
    }
    /* Table 3.22: REPLACE takes the texel's colour unless the texture has
     * only alpha; DECAL of RGB (and, undefined in GL, of the luminance
     * formats, which Mesa treats as RGB) takes it outright. */
    GLenum b = o->base_format;
    st.colour_is_texel = (env == GL_REPLACE && b != GL_ALPHA) ||
                         (env == GL_DECAL && b != GL_RGBA && b != GL_ALPHA);

    if (mipmap_filter(o->min_filter) && !o->depth3) { /* the levels, each its own scene texture */
        int32_t base = mip_chain(ip, o, &st, ms, mt, u.texture->lod_bias);
        if (ip->mip_pending && ip->mip_texture < 0)
            ip->mip_texture = base;
        return base;
    }
    uint64_t how = (o->depth3    ? MADE_SLICE | (o->mag_filter == GL_LINEAR ? MADE_SLICE_LINEAR : 0) |
                                    (uint64_t)o->wrap_r << 32
                    : compare ? MADE_COMPARE | (uint64_t)o->compare_func << 16 |
                                    (uint64_t)o->depth_mode << 32
                              : MADE_PLAIN) |
                   (ms ? MADE_MIRROR_S : 0) | (mt ? MADE_MIRROR_T : 0);
    int32_t idx = made_find(ip, im->serial, how, r, &st);
    if (idx >= 0)
        return idx;
    tex_image *slice = NULL;
    if (o->depth3) {
        if (!interp_budget_texels(ip, (uint64_t)iw * (uint64_t)ih * 4))
            return -1;
        slice = interp_tex_slice(o->img, o->depth3, r, o->mag_filter == GL_LINEAR, o->wrap_r);
        if (!slice) {
            ip->scene->failed = true;
            return -1;
        }
    } else if (compare && !(slice = tex_compared(ip, o, im, r))) {
        return -1;
    }
    const tex_image *src = slice ? slice : im;
    size_t n = (size_t)st.width * (size_t)st.height * 4;
    if (!interp_budget_texels(ip, n))
        goto out;
    st.rgba = tr_realloc(NULL, n);
    if (!st.rgba) {
        ip->scene->failed = true;
        goto out;
    }
    if (ms || mt)
        interp_tex_mirror_fill(st.rgba, src, ms, mt);
    else
        memcpy(st.rgba, src->rgba, n);
    idx = scene_add_texture(ip->scene, &st);
    made_add(ip, im->serial, how, r, idx);
out:
    tr_free(slice);
    return idx;
}

/* Eye-space normal matrix (inverse transpose of the modelview), cached. */
static bool normal_matrix(interp_textures *t, const mat4 *mv)
{
    if (t->nrm_ok && memcmp(&t->nrm_of, mv, sizeof *mv) == 0)
        return true;
    mat4 inv;
    if (!mat4_invert(mv, &inv))
        return false;
    t->nrm_mat = mat4_transpose(&inv);
    t->nrm_of = *mv;
    t->nrm_ok = true;
    return true;
}

/* What the drawn texture makes of s and t: a rectangle texture's are in
 * texels (ARB_texture_rectangle), divided here by its size; a mirror
 * clamp's [-1, 1] lands on the doubled image of interp_texture_for_unit. */
static void texcoord_fit(interp *ip, const interp_tex_unit *u, int unit, float out[2])
{
    tex_obj *o = draw_obj(ip, u, (uint32_t)unit);
    if (!o || !o->img)
        return;
    if (o->target == GL_TEXTURE_RECTANGLE) {
        out[0] /= (float)o->img->width;
        out[1] /= (float)o->img->height;
    }
    if (interp_mirror_clamp(o->wrap_s))
        out[0] = (out[0] + 1) * 0.5f;
    if (o->target != GL_TEXTURE_1D && interp_mirror_clamp(o->wrap_t))
        out[1] = (out[1] + 1) * 0.5f;
}

void interp_vertex_texcoord(interp *ip, int unit, const double obj[4], const float nrm[3],
                            float out[2])
{
    float str[3];
    interp_vertex_texcoord3(ip, unit, obj, nrm, str);
    out[0] = str[0];
    out[1] = str[1];
}

void interp_vertex_texcoord3(interp *ip, int unit, const double obj[4], const float nrm[3],
                             float out[3])
{
    interp_tex_unit u = interp_unit(ip, (uint32_t)unit);
    const struct gl_texture_unit *ts = u.texture;
    double tc[4] = {u.texcoord[0], u.texcoord[1], u.texcoord[2], u.texcoord[3]};
    const uint8_t *caps = ip->st.a.caps;
    bool gen[4] = {u.caps[UCAP(TEXTURE_GEN_S)], u.caps[UCAP(TEXTURE_GEN_T)],
                   u.caps[UCAP(TEXTURE_GEN_R)], u.caps[UCAP(TEXTURE_GEN_Q)]};
    if (gen[0] || gen[1] || gen[2] || gen[3]) {
        const mat4 *mv = interp_matrix(ip, INTERP_MV);
        double eye[4];
        mat4_apply(mv, obj, eye);
        double refl[3] = {0, 0, 0};
        bool have_refl = false;
        for (int c = 0; c < 4; c++) {
            if (!gen[c])
                continue;
            GLenum m = ts->gen_mode[c];
            if (m == GL_OBJECT_LINEAR || m == GL_EYE_LINEAR) {
                const double *p = m == GL_OBJECT_LINEAR ? ts->obj_plane[c] : ts->eye_plane[c];
                const double *v = m == GL_OBJECT_LINEAR ? obj : eye;
                tc[c] = p[0] * v[0] + p[1] * v[1] + p[2] * v[2] + p[3] * v[3];
                continue;
            }
            if (!have_refl) {
                /* GL 2.10.4: u the unit vector to the vertex, n' the eye
                 * normal (normalised only under GL_NORMALIZE, as GL). */
                have_refl = true;
                double u[3] = {eye[0], eye[1], eye[2]};
                if (eye[3] != 0 && eye[3] != 1)
                    for (int k = 0; k < 3; k++)
                        u[k] /= eye[3];
                double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
                if (len > 0)
                    for (int k = 0; k < 3; k++)
                        u[k] /= len;
                double n[3] = {0, 0, 0};
                if (ip->st.tex && normal_matrix(ip->st.tex, mv)) {
                    const double *nm = ip->st.tex->nrm_mat.m;
                    for (int k = 0; k < 3; k++)
                        n[k] = nm[k] * nrm[0] + nm[4 + k] * nrm[1] + nm[8 + k] * nrm[2];
                }
                if (caps[INTERP_CAP_NORMALIZE]) {
                    double nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                    if (nl > 0)
                        for (int k = 0; k < 3; k++)
                            n[k] /= nl;
                }
                double d = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
                for (int k = 0; k < 3; k++)
                    refl[k] = u[k] - 2 * n[k] * d;
                if (m == GL_NORMAL_MAP)
                    memcpy(refl, n, sizeof refl);
            }
            if (m == GL_SPHERE_MAP) {
                double mm = 2 * sqrt(refl[0] * refl[0] + refl[1] * refl[1] +
                                     (refl[2] + 1) * (refl[2] + 1));
                tc[c] = mm > 0 ? refl[c] / mm + 0.5 : 0.5;
            } else {
                tc[c] = refl[c];
            }
        }
    }
    double r[4];
    mat4_apply(u.matrix, tc, r);
    double q = r[3];
    if (q == 0 || !isfinite(q))
        q = 1;
    out[0] = (float)(r[0] / q);
    out[1] = (float)(r[1] / q);
    out[2] = (float)(r[2] / q);
    /* r over the primitive: a 3D texture's slice, a depth comparison */
    if (!u.caps[UCAP(TEXTURE_CUBE_MAP)] && ip->st.tex && unit >= 0 && unit < INTERP_TEX_UNITS) {
        double rq = r[2] / q;
        interp_textures *t = ip->st.tex;
        t->r_min[unit] = fmin(t->r_min[unit], rq);
        t->r_max[unit] = fmax(t->r_max[unit], rq);
    }
    texcoord_fit(ip, &u, unit, out);
}

bool interp_unit_cube(interp *ip, int unit)
{
    if (unit < 0 || unit >= INTERP_TEX_UNITS)
        return false;
    interp_tex_unit u = interp_unit(ip, (uint32_t)unit);
    return u.caps[UCAP(TEXTURE_CUBE_MAP)] != 0;
}

/* GL's level choice over a run drawn with one lambda (scene_mip_split)
 * is that one: lambda constant over it (within 1/256 of a level), or one
 * level for all of it under a GL_*_MIPMAP_NEAREST filter. */
static bool one_level(const scene_texture *t, const scene_mip_run *r)
{
    if (!(r->hi - r->lo < 1.0 / 256) && t->mip_filter != SCENE_MIP_NEAREST_MIPMAP_NEAREST &&
        t->mip_filter != SCENE_MIP_LINEAR_MIPMAP_NEAREST)
        return false;
    double lo = fmax(t->min_lod, r->lo + t->lod_bias), hi = fmin(t->max_lod, r->hi + t->lod_bias);
    if (!isfinite(r->lo) || !isfinite(r->hi) || (lo <= 0) != (hi <= 0))
        return false; /* magnification on one side */
    /* GL 2.1 3.8.9: level ceil(lambda + 1/2) - 1 past 1/2, else 0 */
    double dl = lo <= 0.5 ? 0 : ceil(lo + 0.5) - 1, dh = hi <= 0.5 ? 0 : ceil(hi + 0.5) - 1;
    return dl == dh || r->hi - r->lo < 1.0 / 256;
}

static bool mip_exact(interp *ip, size_t first_tri)
{
    const scene *s = ip->scene;
    if (!s || ip->mip_texture < 0 || (size_t)ip->mip_texture >= s->ntextures ||
        s->ntris < first_tri + 2)
        return false;
    const scene_texture *t = &s->textures[ip->mip_texture];
    const mat4 *to_eye = ip->prim_in_eye ? NULL : &ip->prim_to_eye;
    size_t nt = s->ntris - first_tri;
    /* A run here is within one of the writer's (the mesh may hold earlier
     * triangles on the same map: a longer run, lambda varying more). */
    for (size_t i = 0; i < nt;) {
        scene_mip_run r;
        size_t run = scene_mip_split(&s->camera, to_eye, s->verts, s->tris + first_tri + i, nt - i,
                                     t->width, t->height, &r);
        if ((!r.planar || run < 2) && !one_level(t, &r))
            return false;
        i += run;
    }
    return true;
}

void interp_tex_mip_check(interp *ip, size_t first_tri)
{
    ip->mip_defer = false;
    if (!ip->mip_pending)
        return;
    ip->mip_pending = false;
    if (!mip_exact(ip, first_tri))
        interp_note(ip, DIAG_NOTE_TEX_MIPMAP);
}
