/* interp_texture.c: texture objects, their parameters, the texture
 * environment, texgen state and copies between contexts (issue 5); the
 * images are interp_teximage.c's, what a draw samples interp_texdraw.c's.
 *
 * A texture object keeps the image of each level converted to 8-bit RGBA
 * as GL's texture environment sees it (GL 1.5 table 3.15: the components
 * the base internal format lacks are given the values the environment
 * functions treat as neutral), bottom row first, and each level's size,
 * so that an incomplete texture (GL 2.1 3.8.10, from GL_TEXTURE_BASE_LEVEL
 * to GL_TEXTURE_MAX_LEVEL) turns texturing off, as in GL, and a
 * mipmapping minification filter finds its levels (issue 14: the writer
 * chooses among them, povwrite_mipmap.c). Images are shared,
 * reference counted, between the interpreters that copy a context's state
 * (frame.c's carried state) and copied before a change.
 *
 */
#include <stdio.h>
#include <string.h>

#include "interp_internal.h"
#include "interp_teximage.h"
#include "namemap.h"
#include "talloc.h"


/* ---- Objects --------------------------------------------------------------------- */

static void obj_defaults(tex_obj *o, uint32_t name)
{
    memset(o, 0, sizeof *o);
    o->name = name;
    o->wrap_s = o->wrap_t = o->wrap_r = GL_REPEAT;
    o->min_filter = GL_NEAREST_MIPMAP_LINEAR;
    o->mag_filter = GL_LINEAR;
    o->max_level = 1000;
    o->min_lod = -1000;
    o->max_lod = 1000;
    o->depth_mode = GL_LUMINANCE;
    o->compare_mode = GL_NONE;
    o->compare_func = GL_LEQUAL;
}

/* The image of level k, or NULL. */
tex_image **interp_tex_level_slot(tex_obj *o, int k) { return k == 0 ? &o->img : &o->lv[k]; }

/* A rectangle texture's defaults (ARB_texture_rectangle): no mipmaps, no
 * repeat. */
static void obj_rect_defaults(tex_obj *o)
{
    o->wrap_s = o->wrap_t = GL_CLAMP_TO_EDGE;
    o->min_filter = GL_LINEAR;
}

void interp_tex_image_release(tex_image *img)
{
    if (img && --img->refs == 0)
        tr_free(img);
}

static void obj_retain(tex_obj *o)
{
    for (int k = 0; k < TEX_LEVELS; k++)
        if (*interp_tex_level_slot(o, k))
            (*interp_tex_level_slot(o, k))->refs++;
    for (int f = 0; f < 6; f++)
        if (o->face[f])
            o->face[f]->refs++;
}

static void obj_release(tex_obj *o)
{
    interp_tex_image_release(o->img);
    for (int k = 1; k < TEX_LEVELS; k++)
        interp_tex_image_release(o->lv[k]);
    for (int f = 0; f < 6; f++)
        interp_tex_image_release(o->face[f]);
}

static void r_reset(interp_textures *t)
{
    for (int k = 0; k < INTERP_TEX_UNITS; k++) {
        t->r_min[k] = INFINITY;
        t->r_max[k] = -INFINITY;
    }
}

void interp_texture_r_reset(interp *ip)
{
    if (ip->st.tex)
        r_reset(ip->st.tex);
}

interp_textures *interp_tex_state(interp *ip)
{
    if (ip->st.tex)
        return ip->st.tex;
    interp_textures *t = tr_realloc(NULL, sizeof *t);
    if (!t)
        return NULL;
    memset(t, 0, sizeof *t);
    for (size_t k = 0; k < ZEROS(t); k++)
        obj_defaults(&t->zero[k], 0);
    t->zero[0].target = GL_TEXTURE_1D;
    t->zero[1].target = GL_TEXTURE_2D;
    t->zero[2].target = GL_TEXTURE_RECTANGLE;
    obj_rect_defaults(&t->zero[2]);
    t->zero[3].target = GL_TEXTURE_3D;
    t->zero[4].target = GL_TEXTURE_CUBE_MAP;
    r_reset(t);
    t->unpack[GL_UNPACK_ALIGNMENT - GL_UNPACK_SWAP_BYTES] = 4;
    ip->st.tex = t;
    return t;
}

static tex_obj *find_obj(interp_textures *t, uint32_t name)
{
    int64_t i = namemap_get(&t->names, name);
    return i >= 0 ? &t->objs[i] : NULL;
}

/* The object `name` (created when create is set); object 0 is per target. */
tex_obj *interp_tex_get_obj(interp *ip, GLenum target, uint32_t name, bool create)
{
    interp_textures *t = interp_tex_state(ip);
    if (!t)
        return NULL;
    if (name == 0)
        return &t->zero[target == GL_TEXTURE_1D          ? 0
                        : target == GL_TEXTURE_RECTANGLE ? 2
                        : target == GL_TEXTURE_3D        ? 3
                        : target == GL_TEXTURE_CUBE_MAP  ? 4
                                                         : 1];
    tex_obj *o = find_obj(t, name);
    if (o || !create)
        return o;
    if (t->n >= UINT32_MAX || tr_grow((void **)&t->objs, &t->cap, t->n + 1, sizeof *t->objs) != 0 ||
        namemap_put(&t->names, name, (uint32_t)t->n) != 0)
        return NULL;
    o = &t->objs[t->n++];
    obj_defaults(o, name);
    if (target == GL_TEXTURE_RECTANGLE)
        obj_rect_defaults(o);
    return o;
}

/* The object bound to target (GL_TEXTURE_1D or GL_TEXTURE_2D), else NULL. */
tex_obj *interp_tex_bound_obj(interp *ip, GLenum target, bool create)
{
    if (target == GL_TEXTURE_1D)
        return interp_tex_get_obj(ip, target, ip->st.a.texture.binding_1d, create);
    if (target == GL_TEXTURE_2D)
        return interp_tex_get_obj(ip, target, ip->st.a.texture.binding_2d, create);
    if (target == GL_TEXTURE_RECTANGLE)
        return interp_tex_get_obj(ip, target, ip->st.a.texture.binding_rect, create);
    if (target == GL_TEXTURE_3D)
        return interp_tex_get_obj(ip, target, ip->st.a.texture.binding_3d, create);
    if (target == GL_TEXTURE_CUBE_MAP)
        return interp_tex_get_obj(ip, target, ip->st.a.texture.binding_cube, create);
    return NULL;
}

void interp_gentextures(interp *ip, const rgl_cmd *cmd)
{
    (void)ip;
    (void)cmd; /* names are the program's; objects appear when bound */
}

void interp_deletetextures(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    const rgl_arg *a = &cmd->arg[0];
    interp_textures *t = ip->st.tex;
    if (!t)
        return;
    for (uint32_t k = 0; k < a->count; k++) {
        uint32_t name = (uint32_t)a->array[k];
        if (name == 0)
            continue;
        tex_obj *o = find_obj(t, name);
        if (!o)
            continue;
        obj_release(o);
        namemap_del(&t->names, name);
        *o = t->objs[--t->n];
        if (o != &t->objs[t->n]) /* the last object moved into o's place */
            namemap_put(&t->names, o->name, (uint32_t)(o - t->objs));
        /* GL binds 0 in place of a deleted bound texture. */
        if (ip->st.a.texture.binding_1d == name)
            ip->st.a.texture.binding_1d = 0;
        if (ip->st.a.texture.binding_2d == name)
            ip->st.a.texture.binding_2d = 0;
        if (ip->st.a.texture.binding_rect == name)
            ip->st.a.texture.binding_rect = 0;
        if (ip->st.a.texture.binding_3d == name)
            ip->st.a.texture.binding_3d = 0;
        if (ip->st.a.texture.binding_cube == name)
            ip->st.a.texture.binding_cube = 0;
        interp_multitex_unbind(ip, name);
    }
}

void interp_bindtexture(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum target = arg_enum(cmd, 0);
    uint32_t name = (uint32_t)cmd->arg[1].v.u;
    if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_RECTANGLE &&
        target != GL_TEXTURE_3D && target != GL_TEXTURE_CUBE_MAP) {
        interp_bad_enum(ip, "texture target", target);
        return;
    }
    tex_obj *o = interp_tex_get_obj(ip, target, name, true);
    if (!o) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    if (o->target && o->target != target) {
        interp_bad_op(ip, "texture object bound to another target");
        return;
    }
    o->target = target;
    if (target == GL_TEXTURE_1D)
        ip->st.a.texture.binding_1d = name;
    else if (target == GL_TEXTURE_RECTANGLE)
        ip->st.a.texture.binding_rect = name;
    else if (target == GL_TEXTURE_3D)
        ip->st.a.texture.binding_3d = name;
    else if (target == GL_TEXTURE_CUBE_MAP)
        ip->st.a.texture.binding_cube = name;
    else
        ip->st.a.texture.binding_2d = name;
}

/* ---- Parameters and environment ------------------------------------------------------- */

bool interp_mirror_clamp(GLenum wrap)
{
    return wrap == GL_MIRROR_CLAMP_EXT || wrap == GL_MIRROR_CLAMP_TO_EDGE_EXT ||
           wrap == GL_MIRROR_CLAMP_TO_BORDER_EXT;
}

/* GL_DEPTH_TEXTURE_MODE: a depth texture's texels are (d, d, d, 1), (d, d,
 * d, d) or alpha d (GL 2.1 3.8.13). The depth is recovered from the texels
 * kept (red, or alpha in GL_ALPHA mode), so the image is redrawn exactly. */
void interp_tex_depth_mode(interp *ip, tex_obj *o, GLenum mode)
{
    GLenum was = o->depth_mode;
    o->depth_mode = mode;
    if (!o->depth || was == mode)
        return;
    o->base_format = mode;
    for (int k = 0; k < TEX_LEVELS; k++) { /* every level (a depth texture's mipmaps) */
        tex_image **slot = interp_tex_level_slot(o, k);
        tex_image *img = *slot ? interp_tex_image_own(ip, slot) : NULL;
        if (!img)
            continue;
        size_t n = (size_t)img->width * (size_t)img->height;
        for (size_t i = 0; i < n; i++) {
            uint8_t *t = img->rgba + i * 4, d = was == GL_ALPHA ? t[3] : t[0];
            bool alpha = mode == GL_ALPHA;
            t[0] = t[1] = t[2] = alpha ? 255 : d;
            t[3] = mode == GL_LUMINANCE ? 255 : d;
        }
        interp_tex_image_seal(img);
    }
}

void interp_texparameter(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum target = arg_enum(cmd, 0), pname = arg_enum(cmd, 1);
    const rgl_arg *pa = &cmd->arg[2];
    double v = pa->kind == RGL_ARG_SCALAR ? arg_num(pa) : (pa->count ? pa->array[0] : 0);
    bool rect = target == GL_TEXTURE_RECTANGLE;
    if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && !rect && target != GL_TEXTURE_3D &&
        target != GL_TEXTURE_CUBE_MAP) {
        interp_bad_enum(ip, "texture target", target);
        return;
    }
    GLenum e = interp_enum_of(v);
    switch (pname) {
    case GL_TEXTURE_WRAP_S: case GL_TEXTURE_WRAP_T: case GL_TEXTURE_WRAP_R: {
        bool clamp = e == GL_CLAMP || e == GL_CLAMP_TO_EDGE || e == GL_CLAMP_TO_BORDER;
        bool other = e == GL_REPEAT || e == GL_MIRRORED_REPEAT || interp_mirror_clamp(e);
        /* ARB_texture_rectangle: the clamping modes alone. */
        if (!clamp && (!other || rect)) {
            interp_bad_enum(ip, "texture wrap mode", e);
            return;
        }
        break;
    }
    case GL_DEPTH_TEXTURE_MODE:
        if (e != GL_LUMINANCE && e != GL_INTENSITY && e != GL_ALPHA) {
            interp_bad_enum(ip, "depth texture mode", e);
            return;
        }
        break;
    case GL_TEXTURE_COMPARE_MODE:
        if (e != GL_NONE && e != GL_COMPARE_R_TO_TEXTURE) {
            interp_bad_enum(ip, "texture compare mode", e);
            return;
        }
        break;
    case GL_TEXTURE_COMPARE_FUNC:
        if (e < GL_NEVER || e > GL_ALWAYS) {
            interp_bad_enum(ip, "texture compare function", e);
            return;
        }
        break;
    case GL_TEXTURE_LOD_BIAS:
        if (!isfinite(v)) {
            interp_bad_value(ip, "texture level-of-detail bias");
            return;
        }
        break;
    case GL_TEXTURE_MAG_FILTER:
        if (e != GL_NEAREST && e != GL_LINEAR) {
            interp_bad_enum(ip, "texture magnification filter", e);
            return;
        }
        break;
    case GL_TEXTURE_MIN_FILTER:
        if (e != GL_NEAREST && e != GL_LINEAR &&
            (rect || (e != GL_NEAREST_MIPMAP_NEAREST && e != GL_LINEAR_MIPMAP_NEAREST &&
                      e != GL_NEAREST_MIPMAP_LINEAR && e != GL_LINEAR_MIPMAP_LINEAR))) {
            interp_bad_enum(ip, "texture minification filter", e);
            return;
        }
        break;
    case GL_TEXTURE_BORDER_COLOR:
        if (pa->kind == RGL_ARG_SCALAR || pa->count < 4) {
            interp_bad_enum(ip, "texture parameter of a scalar call", pname);
            return;
        }
        break;
    case GL_TEXTURE_BASE_LEVEL: case GL_TEXTURE_MAX_LEVEL:
        if (v < 0 || !isfinite(v)) {
            interp_bad_value(ip, "negative texture level");
            return;
        }
        /* ARB_texture_rectangle: level 0 is the base. */
        if (rect && pname == GL_TEXTURE_BASE_LEVEL && v != 0) {
            interp_bad_value(ip, "rectangle texture base level other than 0");
            return;
        }
        break;
    case GL_TEXTURE_MIN_LOD: case GL_TEXTURE_MAX_LOD:
        if (!isfinite(v)) {
            interp_bad_value(ip, "texture level of detail");
            return;
        }
        break;
    case GL_GENERATE_MIPMAP:
        break;
    default:
        return; /* priority: nothing POV-Ray shows */
    }
    tex_obj *o = interp_tex_bound_obj(ip, target, true);
    if (!o) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    if (pname == GL_TEXTURE_BORDER_COLOR) {
        bool is_int = pa->type == RGL_T_i;
        for (int k = 0; k < 4; k++) {
            double c = pa->array[k];
            o->border[k] = clamp01((float)(is_int ? (2 * c + 1) / 4294967295.0 : c));
        }
    } else if (pname == GL_TEXTURE_BASE_LEVEL) {
        o->base_level = v > 1000 ? 1000 : (int32_t)v;
    } else if (pname == GL_TEXTURE_MAX_LEVEL) {
        o->max_level = v > 1000 ? 1000 : (int32_t)v;
    } else if (pname == GL_TEXTURE_MIN_LOD) {
        o->min_lod = (float)(v < -1000 ? -1000 : v > 1000 ? 1000 : v);
    } else if (pname == GL_TEXTURE_MAX_LOD) {
        o->max_lod = (float)(v < -1000 ? -1000 : v > 1000 ? 1000 : v);
    } else if (pname == GL_TEXTURE_LOD_BIAS) {
        o->lod_bias = (float)(v < -1000 ? -1000 : v > 1000 ? 1000 : v);
    } else if (pname == GL_GENERATE_MIPMAP) {
        o->generate_mipmap = v != 0;
    } else if (pname == GL_DEPTH_TEXTURE_MODE) {
        interp_tex_depth_mode(ip, o, e);
    } else if (pname == GL_TEXTURE_COMPARE_MODE) {
        o->compare_mode = e;
    } else if (pname == GL_TEXTURE_COMPARE_FUNC) {
        o->compare_func = e;
    } else if (pname == GL_TEXTURE_WRAP_R) {
        o->wrap_r = e;
    } else if (pname == GL_TEXTURE_WRAP_S)
        o->wrap_s = e;
    else if (pname == GL_TEXTURE_WRAP_T)
        o->wrap_t = e;
    else if (pname == GL_TEXTURE_MAG_FILTER)
        o->mag_filter = e;
    else
        o->min_filter = e;
}

/* glTexEnv's other targets (GL 1.4, 2.0): the active unit's
 * GL_TEXTURE_FILTER_CONTROL GL_TEXTURE_LOD_BIAS (interp_texture_lod_bias)
 * and GL_POINT_SPRITE's GL_COORD_REPLACE (interp_sprite.c). */
static void interp_texenv_other(interp *ip, GLenum target, GLenum pname, const rgl_arg *pa)
{
    double v = pa->kind == RGL_ARG_SCALAR ? arg_num(pa) : (pa->count ? pa->array[0] : 0);
    if (target == GL_TEXTURE_FILTER_CONTROL) {
        if (pname != GL_TEXTURE_LOD_BIAS) {
            interp_bad_enum(ip, "texture filter control pname", pname);
            return;
        }
        if (!isfinite(v)) {
            interp_bad_value(ip, "texture level-of-detail bias");
            return;
        }
        ip->st.a.texture.lod_bias = (float)(v < -1000 ? -1000 : v > 1000 ? 1000 : v);
        return;
    }
    if (pname != GL_COORD_REPLACE) {
        interp_bad_enum(ip, "point sprite pname", pname);
        return;
    }
    GLenum e = interp_enum_of(v);
    if (e != GL_TRUE && e != GL_FALSE) {
        interp_bad_enum(ip, "GL_COORD_REPLACE value", e);
        return;
    }
    ip->st.a.texture.coord_replace = e == GL_TRUE;
}

void interp_texenv(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum target = arg_enum(cmd, 0), pname = arg_enum(cmd, 1);
    const rgl_arg *pa = &cmd->arg[2];
    if (target == GL_POINT_SPRITE || target == GL_TEXTURE_FILTER_CONTROL) {
        interp_texenv_other(ip, target, pname, pa);
        return;
    }
    if (target != GL_TEXTURE_ENV) {
        interp_bad_enum(ip, "texture environment target", target);
        return;
    }
    if (pname == GL_TEXTURE_ENV_MODE) {
        double v = pa->kind == RGL_ARG_SCALAR ? arg_num(pa) : (pa->count ? pa->array[0] : 0);
        GLenum m = interp_enum_of(v);
        if (m != GL_MODULATE && m != GL_REPLACE && m != GL_DECAL && m != GL_BLEND &&
            m != GL_ADD && m != GL_COMBINE) {
            interp_bad_enum(ip, "texture environment mode", m);
            return;
        }
        ip->st.a.texture.env_mode = m;
    } else if (pa->kind == RGL_ARG_SCALAR || pa->count >= 1) {
        if (pname != GL_TEXTURE_ENV_COLOR &&
            interp_combine_texenv(ip, pname, pa->kind == RGL_ARG_SCALAR ? arg_num(pa) : pa->array[0]))
            return;
    }
    if (pname == GL_TEXTURE_ENV_COLOR) {
        if (pa->kind == RGL_ARG_SCALAR || pa->count < 4)
            return;
        bool is_int = pa->type == RGL_T_i;
        for (int k = 0; k < 4; k++) {
            double c = pa->array[k];
            /* Integer colours map the full range to [-1, 1] (GL 2.14). */
            ip->st.a.texture.env_color[k] =
                clamp01((float)(is_int ? (2 * c + 1) / 4294967295.0 : c));
        }
    }
}

void interp_texgen(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum coord = arg_enum(cmd, 0), pname = arg_enum(cmd, 1);
    const rgl_arg *pa = &cmd->arg[2];
    if (coord < GL_S || coord > GL_Q) {
        interp_bad_enum(ip, "texture coordinate", coord);
        return;
    }
    int c = (int)(coord - GL_S);
    if (pname == GL_TEXTURE_GEN_MODE) {
        double v = pa->kind == RGL_ARG_SCALAR ? arg_num(pa) : (pa->count ? pa->array[0] : 0);
        GLenum m = interp_enum_of(v);
        bool ok = m == GL_OBJECT_LINEAR || m == GL_EYE_LINEAR ||
                  (m == GL_SPHERE_MAP && c < 2) ||
                  ((m == GL_NORMAL_MAP || m == GL_REFLECTION_MAP) && c < 3);
        if (!ok) {
            interp_bad_enum(ip, "texture generation mode", m);
            return;
        }
        ip->st.a.texture.gen_mode[c] = m;
        return;
    }
    if (pname != GL_OBJECT_PLANE && pname != GL_EYE_PLANE) {
        interp_bad_enum(ip, "glTexGen pname", pname);
        return;
    }
    if (pa->kind == RGL_ARG_SCALAR || pa->count < 4) {
        interp_bad_enum(ip, "glTexGen pname of a scalar call", pname);
        return;
    }
    double p[4] = {pa->array[0], pa->array[1], pa->array[2], pa->array[3]};
    if (pname == GL_OBJECT_PLANE) {
        memcpy(ip->st.a.texture.obj_plane[c], p, sizeof p);
        return;
    }
    /* GL 2.10.4: (p1 p2 p3 p4) M^-1, M the modelview now. */
    mat4 inv;
    if (!mat4_invert(interp_matrix(ip, INTERP_MV), &inv)) {
        memset(ip->st.a.texture.eye_plane[c], 0, sizeof p);
        return;
    }
    for (int j = 0; j < 4; j++) {
        double s = 0;
        for (int k = 0; k < 4; k++)
            s += p[k] * inv.m[j * 4 + k]; /* column j of the inverse (column-major) */
        ip->st.a.texture.eye_plane[c][j] = s;
    }
}

/* ---- Copies --------------------------------------------------------------------------- */

int interp_textures_copy(interp *dst, const interp *src)
{
    interp_textures_free(dst);
    const interp_textures *s = src->st.tex;
    if (!s)
        return 0;
    interp_textures *t = tr_realloc(NULL, sizeof *t);
    if (!t)
        return -1;
    *t = *s;
    t->objs = NULL;
    t->cap = 0;
    namemap_init(&t->names);
    if (namemap_copy(&t->names, &s->names) != 0) {
        tr_free(t);
        return -1;
    }
    t->made = NULL;
    t->nmade = t->cap_made = 0;
    t->made_sc = NULL;
    t->nrm_ok = false;
    if (s->n && tr_grow((void **)&t->objs, &t->cap, s->n, sizeof *t->objs) != 0) {
        namemap_finish(&t->names);
        tr_free(t);
        return -1;
    }
    if (s->n) /* objs is NULL for an empty table: memcpy(NULL, NULL, 0) is undefined */
        memcpy(t->objs, s->objs, s->n * sizeof *t->objs);
    for (size_t i = 0; i < t->n; i++)
        obj_retain(&t->objs[i]);
    for (size_t k = 0; k < ZEROS(t); k++)
        obj_retain(&t->zero[k]);
    dst->st.tex = t;
    return 0;
}

void interp_textures_free(interp *ip)
{
    interp_textures *t = ip->st.tex;
    if (!t)
        return;
    for (size_t i = 0; i < t->n; i++)
        obj_release(&t->objs[i]);
    for (size_t k = 0; k < ZEROS(t); k++)
        obj_release(&t->zero[k]);
    namemap_finish(&t->names);
    tr_free(t->objs);
    tr_free(t->made);
    tr_free(t);
    ip->st.tex = NULL;
}
