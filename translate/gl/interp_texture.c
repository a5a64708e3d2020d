/* interp_texture.c: texture objects, texture environment, texture
 * coordinate generation (issue 5).
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
 * Pixels arrive tightly packed: the recorder applies GL_UNPACK_* when it
 * records the call (record/entry_custom.c, pixels_put), so glPixelStorei
 * is kept as state but never applied again here.
 */
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>

#include "interp_internal.h"
#include "interp_teximage.h"
#include "namemap.h"
#include "talloc.h"

/* Pixels above this per image are refused (an error value, not an attempt
 * to allocate what a hostile trace asks for). 16384 x 16384 RGBA is 1 GiB. */
#define TEX_MAX_TEXELS (1u << 26)

/* Levels 0..14: a 16384-texel side halves to 1 in 14 steps (Mesa's
 * GL_MAX_TEXTURE_LEVELS is 15). */
#define TEX_LEVELS 15

typedef struct tex_obj {
    uint32_t name;
    GLenum target;        /* 0 until first bound */
    GLenum base_format;   /* of level 0 */
    tex_image *img;       /* level 0, or NULL */
    tex_image *lv[TEX_LEVELS]; /* levels 1.., or NULL (lv[0] unused: img) */
    int32_t lw[TEX_LEVELS], lh[TEX_LEVELS]; /* each defined level's size, no border */
    uint32_t levels;      /* bit k: level k defined */
    int32_t base_level, max_level; /* GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL */
    float min_lod, max_lod;        /* GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD */
    float lod_bias;                /* GL_TEXTURE_LOD_BIAS */
    bool generate_mipmap;          /* GL_GENERATE_MIPMAP */
    tex_image *face[6];            /* a cube map's level 0: +X, -X, +Y, -Y, +Z, -Z */
    GLenum wrap_s, wrap_t, min_filter, mag_filter;
    GLenum wrap_r;   /* GL_TEXTURE_WRAP_R (3D) */
    int depth3;      /* a 3D texture's images: img holds them one above the
                        other (height = rows x depth3); 0 for 1D and 2D */
    float border[4]; /* GL_TEXTURE_BORDER_COLOR */
    GLenum depth_mode; /* GL_DEPTH_TEXTURE_MODE */
    GLenum compare_mode, compare_func; /* GL_TEXTURE_COMPARE_MODE, _FUNC */
    bool depth;        /* the base level (or level 0) has a depth internal format:
                          every level drawn as depth_mode */
    uint32_t lost;   /* pixels whose damage left the image missing or partly
                        stale (0: none): every frame drawing with it says so */
} tex_obj;

/* GL_MAX_TEXTURE_LOD_BIAS of Mesa (llvmpipe's PIPE_CAPF_MAX_TEXTURE_LOD_BIAS). */
#define TEX_MAX_LOD_BIAS 16.0

struct interp_textures {
    tex_obj *objs; /* named objects, unordered */
    size_t n, cap;
    namemap names; /* name -> index in objs */
    /* object 0 of GL_TEXTURE_1D, GL_TEXTURE_2D, rectangle, 3D, GL_TEXTURE_CUBE_MAP */
    tex_obj zero[5];
    int32_t unpack[8];       /* glPixelStorei values, by pname - GL_UNPACK_SWAP_BYTES */
    /* The scene textures made since the scene last dropped any (a clear,
     * a new frame), by what each was made from: a draw of the same image
     * sampled alike takes its scene texture again without copying texels
     * or charging the frame budget (docs/mapping.md "Bounds"). */
    struct tex_made {
        uint64_t serial; /* the image's (tex_image.serial) */
        uint64_t how;    /* MADE_* and what else the texels depend on */
        double r;        /* a 3D texture's slice: its coordinate */
        int32_t index;   /* in the scene's textures */
    } *made;
    size_t nmade, cap_made;
    const scene *made_sc;
    uint32_t made_gen; /* the scene's generation they belong to */
    /* The range of r over the primitive being drawn, per unit: a 3D
     * texture is drawn as a slice where it is constant. */
    double r_min[INTERP_TEX_UNITS], r_max[INTERP_TEX_UNITS];
    /* Sphere map: the modelview whose inverse transpose is in nrm_mat. */
    mat4 nrm_of, nrm_mat;
    bool nrm_ok;
};

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
static tex_image **level_slot(tex_obj *o, int k) { return k == 0 ? &o->img : &o->lv[k]; }

/* A rectangle texture's defaults (ARB_texture_rectangle): no mipmaps, no
 * repeat. */
static void obj_rect_defaults(tex_obj *o)
{
    o->wrap_s = o->wrap_t = GL_CLAMP_TO_EDGE;
    o->min_filter = GL_LINEAR;
}

#define ZEROS(t) (sizeof (t)->zero / sizeof (t)->zero[0])

static void image_release(tex_image *img)
{
    if (img && --img->refs == 0)
        tr_free(img);
}

static void obj_retain(tex_obj *o)
{
    for (int k = 0; k < TEX_LEVELS; k++)
        if (*level_slot(o, k))
            (*level_slot(o, k))->refs++;
    for (int f = 0; f < 6; f++)
        if (o->face[f])
            o->face[f]->refs++;
}

static void obj_release(tex_obj *o)
{
    image_release(o->img);
    for (int k = 1; k < TEX_LEVELS; k++)
        image_release(o->lv[k]);
    for (int f = 0; f < 6; f++)
        image_release(o->face[f]);
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
    if (ip->tex)
        r_reset(ip->tex);
}

static interp_textures *textures(interp *ip)
{
    if (ip->tex)
        return ip->tex;
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
    ip->tex = t;
    return t;
}

static tex_obj *find_obj(interp_textures *t, uint32_t name)
{
    int64_t i = namemap_get(&t->names, name);
    return i >= 0 ? &t->objs[i] : NULL;
}

/* The object `name` (created when create is set); object 0 is per target. */
static tex_obj *get_obj(interp *ip, GLenum target, uint32_t name, bool create)
{
    interp_textures *t = textures(ip);
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
static tex_obj *bound_obj(interp *ip, GLenum target, bool create)
{
    if (target == GL_TEXTURE_1D)
        return get_obj(ip, target, ip->st.a.texture.binding_1d, create);
    if (target == GL_TEXTURE_2D)
        return get_obj(ip, target, ip->st.a.texture.binding_2d, create);
    if (target == GL_TEXTURE_RECTANGLE)
        return get_obj(ip, target, ip->st.a.texture.binding_rect, create);
    if (target == GL_TEXTURE_3D)
        return get_obj(ip, target, ip->st.a.texture.binding_3d, create);
    if (target == GL_TEXTURE_CUBE_MAP)
        return get_obj(ip, target, ip->st.a.texture.binding_cube, create);
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
    interp_textures *t = ip->tex;
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
    tex_obj *o = get_obj(ip, target, name, true);
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

/* ---- Pixels ---------------------------------------------------------------------- */

/* Components of an external format, and where each goes (0 R, 1 G, 2 B,
 * 3 A, 4 luminance to R, G and B); 0 for a format not handled. */
static int format_layout(GLenum format, int dst[4])
{
    switch (format) {
    case GL_RED: dst[0] = 0; return 1;
    case GL_GREEN: dst[0] = 1; return 1;
    case GL_BLUE: dst[0] = 2; return 1;
    case GL_ALPHA: dst[0] = 3; return 1;
    case GL_LUMINANCE: dst[0] = 4; return 1;
    case GL_LUMINANCE_ALPHA: dst[0] = 4; dst[1] = 3; return 2;
    case GL_RGB: dst[0] = 0; dst[1] = 1; dst[2] = 2; return 3;
    case GL_BGR: dst[0] = 2; dst[1] = 1; dst[2] = 0; return 3;
    case GL_RGBA: dst[0] = 0; dst[1] = 1; dst[2] = 2; dst[3] = 3; return 4;
    case GL_BGRA: dst[0] = 2; dst[1] = 1; dst[2] = 0; dst[3] = 3; return 4;
    default: return 0;
    }
}

static size_t type_bytes(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
    }
}

/* Component k of type at p as GL converts it to [0, 1] (GL 1.5 table 2.9;
 * signed values below 0 clamp to 0 in a fixed-point texture). */
static float component(const uint8_t *p, GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return p[0] / 255.0f;
    case GL_BYTE: return (2.0f * (int8_t)p[0] + 1) / 255.0f;
    case GL_UNSIGNED_SHORT: return (uint16_t)(p[0] | p[1] << 8) / 65535.0f;
    case GL_SHORT: return (2.0f * (int16_t)(p[0] | p[1] << 8) + 1) / 65535.0f;
    case GL_UNSIGNED_INT: {
        uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
        return (float)(u / 4294967295.0);
    }
    case GL_INT: {
        int32_t i = (int32_t)((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                              (uint32_t)p[3] << 24);
        return (float)((2.0 * i + 1) / 4294967295.0);
    }
    default: { /* GL_FLOAT */
        uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
        float f;
        memcpy(&f, &u, sizeof f);
        return f;
    }
    }
}

/* A texture image's format: the pixel formats, and GL_DEPTH_COMPONENT,
 * whose depth goes where luminance does (GL 2.1 3.8.1: a depth texture's
 * texels are drawn as its GL_DEPTH_TEXTURE_MODE says, tex_depth_mode). */
static int tex_layout(GLenum format, int dst[4])
{
    if (format == GL_DEPTH_COMPONENT) {
        dst[0] = 4;
        return 1;
    }
    return format_layout(format, dst);
}

/* Bytes of one pixel of format/type, 0 for a pair not translated or a
 * packed type of another component count than the format's (GL refuses
 * it: GL_INVALID_OPERATION). tex: a texture image's format (tex_layout). */
static size_t pixel_bytes(GLenum format, GLenum type, bool tex)
{
    int layout[4];
    int nc = tex ? tex_layout(format, layout) : format_layout(format, layout);
    size_t pb;
    int pc = interp_packed_layout(type, &pb);
    if (pc)
        return pc == nc ? pb : 0;
    return (size_t)nc * type_bytes(type);
}

/* The components of the pixel at src placed into c by layout: R, G, B,
 * A, or luminance (4) to R, G and B. */
static void pixel_read(const uint8_t *src, GLenum type, const int *layout, int nc, float c[4])
{
    float v[4] = {0, 0, 0, 0};
    size_t tb = type_bytes(type);
    if (tb == 0)
        interp_packed_decode(src, type, v);
    else
        for (int k = 0; k < nc && k < 4; k++)
            v[k] = component(src + (size_t)k * tb, type);
    for (int k = 0; k < nc && k < 4; k++) {
        if (layout[k] == 4)
            c[0] = c[1] = c[2] = v[k];
        else
            c[layout[k]] = v[k];
    }
}

size_t interp_pixel_bytes(GLenum format, GLenum type, int64_t w, int64_t h)
{
    size_t ps = pixel_bytes(format, type, false);
    if (!ps || w < 0 || h < 0 || (uint64_t)w * (uint64_t)h > TEX_MAX_TEXELS)
        return 0;
    return (size_t)w * (size_t)h * ps;
}

void interp_pixels_float(float *dst, const uint8_t *src, size_t n, GLenum format, GLenum type)
{
    int layout[4] = {0, 0, 0, 0};
    int nc = format_layout(format, layout);
    size_t ps = pixel_bytes(format, type, false);
    for (size_t i = 0; i < n; i++, src += ps, dst += 4) {
        /* GL 2.1 3.6.4, "Conversion to RGBA": missing R, G, B are 0, A is 1. */
        dst[0] = dst[1] = dst[2] = 0;
        dst[3] = 1;
        pixel_read(src, type, layout, nc, dst);
    }
}

/* The base internal format (GL 1.5 table 3.15) of an internal format, or 0. */
static GLenum base_format(int32_t internal)
{
    switch (internal) {
    case 1: case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8: case GL_LUMINANCE12:
    case GL_LUMINANCE16:
        return GL_LUMINANCE;
    case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE4_ALPHA4: case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8: case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
        return GL_LUMINANCE_ALPHA;
    case 3: case GL_RGB: case GL_R3_G3_B2: case GL_RGB4: case GL_RGB5: case GL_RGB8: case GL_RGB10:
    case GL_RGB12: case GL_RGB16:
        return GL_RGB;
    case 4: case GL_RGBA: case GL_RGBA2: case GL_RGBA4: case GL_RGB5_A1: case GL_RGBA8:
    case GL_RGB10_A2: case GL_RGBA12: case GL_RGBA16:
        return GL_RGBA;
    case GL_ALPHA: case GL_ALPHA4: case GL_ALPHA8: case GL_ALPHA12: case GL_ALPHA16:
        return GL_ALPHA;
    case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_INTENSITY12:
    case GL_INTENSITY16:
        return GL_INTENSITY;
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
        return GL_DEPTH_COMPONENT;
    default:
        return 0;
    }
}

static uint8_t to_u8(float f)
{
    f = clamp01(f);
    return (uint8_t)(f * 255.0f + 0.5f);
}

/* Converts w x h pixels of format/type at src (tightly packed, bottom row
 * first) into RGBA texels of base format `base` at dst. */
static void convert_pixels(uint8_t *dst, const uint8_t *src, size_t n, GLenum format, GLenum type,
                           GLenum base)
{
    int layout[4] = {0, 0, 0, 0};
    int nc = tex_layout(format, layout);
    size_t ps = pixel_bytes(format, type, true);
    for (size_t i = 0; i < n; i++, src += ps, dst += 4) {
        float c[4] = {0, 0, 0, 1};
        pixel_read(src, type, layout, nc, c);
        /* Table 3.15: which components the texel keeps. The others take
         * the neutral value of MODULATE (1), so that MODULATE and the
         * writer's image need no case of their own. */
        switch (base) {
        case GL_LUMINANCE: c[1] = c[2] = c[0]; c[3] = 1; break;
        case GL_LUMINANCE_ALPHA: c[1] = c[2] = c[0]; break;
        case GL_INTENSITY: c[1] = c[2] = c[3] = c[0]; break;
        case GL_ALPHA: c[0] = c[1] = c[2] = 1; break;
        case GL_RGB: c[3] = 1; break;
        default: break;
        }
        for (int k = 0; k < 4; k++)
            dst[k] = to_u8(c[k]);
    }
}

/* Process-wide: interpreters share images (interp_copy_state). */
static atomic_uint_least64_t image_serials = 1;

/* img's texels are final (made or changed): a new serial. */
static void image_seal(tex_image *img) { img->serial = atomic_fetch_add(&image_serials, 1); }

/* The texel bytes of pixel resource `id` holding exactly `need` bytes, or
 * NULL after a diagnostic; *lost is set to id when the trace's damage is
 * why. */
const uint8_t *interp_pixels_fetch(interp *ip, uint32_t id, size_t need, uint32_t *lost)
{
    if (!ip->res_fn) {
        interp_diag(ip, DIAG_IGNORED, "texture image: no resources to read pixels #%u from", id);
        return NULL;
    }
    if (!interp_budget_texels(ip, need))
        return NULL;
    rgl_resource res;
    rgl_error err;
    memset(&err, 0, sizeof err);
    if (ip->res_fn(ip->res_ctx, id, &res, &err) != RGL_OK) {
        interp_diag(ip, DIAG_IGNORED, "texture image: pixels #%u unreadable (%s)", id,
                    rgl_status_str(err.status));
        char what[DIAG_TEXT];
        snprintf(what, sizeof what, "a texture image (pixels #%u unreadable: %s)", id,
                 rgl_status_str(err.status));
        interp_missing(ip, what);
        *lost = id;
        return NULL;
    }
    if (res.kind != RGL_RES_BYTES || res.size != need) {
        interp_diag(ip, DIAG_IGNORED,
                    "texture image: pixels #%u hold %zu bytes, the image needs %zu", id,
                    res.size, need);
        return NULL;
    }
    return res.data;
}

/* Checks format, type and size as GL does; sets *bytes (tightly packed
 * size). False after the GL error. */
static bool check_image(interp *ip, GLenum format, GLenum type, int64_t w, int64_t h,
                        size_t *bytes)
{
    int layout[4];
    int nc = tex_layout(format, layout);
    if (!nc) {
        interp_bad_enum(ip, "pixel format", format);
        return false;
    }
    size_t pb, ps = pixel_bytes(format, type, true);
    int pc = interp_packed_layout(type, &pb);
    if (pc && pc != nc) {
        interp_bad_op(ip, "packed pixel type of another component count than the format");
        return false;
    }
    if (!ps) {
        interp_diag(ip, DIAG_IGNORED, "texture image: pixel type 0x%x not translated", type);
        return false;
    }
    if (w < 0 || h < 0 || w > INTERP_MAX_TEXTURE_SIZE || h > INTERP_MAX_TEXTURE_SIZE ||
        (uint64_t)w * (uint64_t)h > TEX_MAX_TEXELS) {
        interp_diag(ip, DIAG_GL_INVALID_VALUE,
                    "invalid value: texture of %lld x %lld texels (at most %d per side, %u in all)",
                    (long long)w, (long long)h, INTERP_MAX_TEXTURE_SIZE, TEX_MAX_TEXELS);
        return false;
    }
    *bytes = (size_t)w * (size_t)h * ps;
    return true;
}

/* Levels base+1 .. down to 1 x 1 from the base level, each texel the mean
 * of the 2 x 2 (or 2 x 1) below it (GL_GENERATE_MIPMAP, gluBuild2DMipmaps:
 * GL leaves the filter to the implementation; Mesa's is this box). */
static void generate_levels(interp *ip, tex_obj *o, int b)
{
    if (b < 0 || b >= TEX_LEVELS || !*level_slot(o, b))
        return;
    for (int k = b + 1; k < TEX_LEVELS; k++) {
        const tex_image *src = *level_slot(o, k - 1);
        if (!src || (src->width == 1 && src->height == 1))
            return;
        int nw = src->width > 1 ? src->width / 2 : 1, nh = src->height > 1 ? src->height / 2 : 1;
        if (!interp_budget_texels(ip, (uint64_t)nw * (uint64_t)nh * 4))
            return;
        tex_image *img = tr_realloc(NULL, sizeof *img + (size_t)nw * (size_t)nh * 4);
        if (!img) {
            if (ip->scene)
                ip->scene->failed = true;
            return;
        }
        img->refs = 1;
        img->width = nw;
        img->height = nh;
        int fx = src->width > 1 ? 2 : 1, fy = src->height > 1 ? 2 : 1;
        for (int y = 0; y < nh; y++)
            for (int x = 0; x < nw; x++)
                for (int c = 0; c < 4; c++) {
                    unsigned sum = 0;
                    for (int j = 0; j < fy; j++)
                        for (int i = 0; i < fx; i++)
                            sum += src->rgba[((size_t)(y * fy + j) * (size_t)src->width +
                                              (size_t)(x * fx + i)) * 4 + (size_t)c];
                    img->rgba[((size_t)y * (size_t)nw + (size_t)x) * 4 + (size_t)c] =
                        (uint8_t)((sum + (unsigned)(fx * fy) / 2) / (unsigned)(fx * fy));
                }
        image_seal(img);
        tex_image **slot = level_slot(o, k);
        image_release(*slot);
        *slot = img;
        o->levels |= 1u << k;
        o->lw[k] = nw;
        o->lh[k] = nh;
    }
}

/* The size of level k of a side of s0 texels (GL 2.1 3.8.8). */
static int64_t level_size(int64_t s0, int k)
{
    int64_t s = s0 >> k;
    return s > 0 ? s : 1;
}

/* Sets level `level` of o from w x h pixels (resource id, 0: none). */
static void tex_image_set(interp *ip, GLenum target, int32_t level, int32_t internal, int64_t w,
                          int64_t h, int32_t border, GLenum format, GLenum type, uint32_t id)
{
    if (interp_reject_in_begin(ip))
        return;
    if (target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D ||
        target == GL_PROXY_TEXTURE_RECTANGLE || target == GL_PROXY_TEXTURE_CUBE_MAP)
        return;
    int face = target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z
                   ? (int)(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X)
                   : -1;
    if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_RECTANGLE &&
        face < 0) {
        interp_bad_enum(ip, "texture target", target);
        return;
    }
    if (face >= 0 && w != h) {
        interp_bad_value(ip, "cube map face not square");
        return;
    }
    GLenum base = base_format(internal);
    if (!base) {
        interp_bad_value(ip, "texture internal format");
        return;
    }
    /* ARB_texture_rectangle: level 0 alone, no border. */
    if (level < 0 || level >= TEX_LEVELS || (border != 0 && border != 1) ||
        (target == GL_TEXTURE_RECTANGLE && (level != 0 || border != 0))) {
        interp_bad_value(ip, "texture level or border");
        return;
    }
    /* GL 2.1 3.8.1: depth pixels for a depth format, and only there. */
    if ((base == GL_DEPTH_COMPONENT) != (format == GL_DEPTH_COMPONENT)) {
        interp_bad_op(ip, "depth pixels and a colour internal format, or the reverse");
        return;
    }
    /* GL 2.1 3.8.1: depth textures are 1D or 2D (and rectangles,
     * ARB_texture_rectangle), never a cube map's face. */
    if (base == GL_DEPTH_COMPONENT && face >= 0) {
        interp_bad_op(ip, "a depth internal format for a cube map face");
        return;
    }
    size_t bytes;
    if (!check_image(ip, format, type, w, h, &bytes))
        return;
    tex_obj *o = bound_obj(ip, face >= 0 ? GL_TEXTURE_CUBE_MAP : target, true);
    if (!o) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    if (face >= 0) {
        if (level > 0)
            return; /* a cube map's levels: its level 0 is drawn (the mipmap note) */
        target = GL_TEXTURE_2D; /* a face is a 2D image */
    }
    bool depth = base == GL_DEPTH_COMPONENT;
    bool two = target != GL_TEXTURE_1D;
    int64_t iw = w - 2 * border, ih = two ? h - 2 * border : 1;
    tex_image **slot = face >= 0 ? &o->face[face] : level_slot(o, level);
    image_release(*slot);
    *slot = NULL;
    o->levels |= 1u << level;
    o->lw[level] = (int32_t)(iw > 0 ? iw : 0);
    o->lh[level] = (int32_t)(ih > 0 ? ih : 0);
    if (level == 0 && face <= 0)
        o->lost = 0;
    if (depth)
        base = o->depth_mode; /* the depth is drawn as luminance, intensity or alpha */
    if (level == 0 || level == o->base_level) {
        o->depth = depth;
        o->base_format = base;
    }
    if (face >= 0)
        o->levels &= ~(1u << level); /* faces live in o->face */
    if (iw <= 0 || ih <= 0 || !id)
        return; /* an image with no texels, or undefined contents: no texturing */
    const uint8_t *px = interp_pixels_fetch(ip, id, bytes, &o->lost);
    /* Held as RGBA: 4 bytes a texel whatever the trace's format. */
    if (!px || !interp_budget_texels(ip, (uint64_t)w * (uint64_t)h * 4))
        return;
    tex_image *img = tr_realloc(NULL, sizeof *img + (size_t)w * (size_t)h * 4);
    if (!img) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    img->refs = 1;
    img->width = (int)iw;
    img->height = (int)ih;
    size_t ps = pixel_bytes(format, type, true);
    /* A border is dropped: POV-Ray has no border texels. */
    for (int64_t y = 0; y < ih; y++)
        convert_pixels(img->rgba + (size_t)y * (size_t)iw * 4,
                       px + ((size_t)(y + (two ? border : 0)) * (size_t)w +
                             (size_t)border) * ps,
                       (size_t)iw, format, type, base);
    image_seal(img);
    *slot = img;
    /* A rectangle has no mipmaps (ARB_texture_rectangle), whatever
     * GL_GENERATE_MIPMAP says. */
    if (o->generate_mipmap && level == o->base_level && face < 0 &&
        o->target != GL_TEXTURE_RECTANGLE)
        generate_levels(ip, o, level);
}

void interp_teximage1d(interp *ip, const rgl_cmd *cmd)
{
    interp_unrec_pixel_uses(ip, false, false, true);
    tex_image_set(ip, arg_enum(cmd, 0), (int32_t)cmd->arg[1].v.i, (int32_t)cmd->arg[2].v.i,
                  cmd->arg[3].v.i, 1, (int32_t)cmd->arg[4].v.i, arg_enum(cmd, 5),
                  arg_enum(cmd, 6), (uint32_t)cmd->arg[7].v.u);
}

void interp_teximage2d(interp *ip, const rgl_cmd *cmd)
{
    interp_unrec_pixel_uses(ip, false, false, true);
    tex_image_set(ip, arg_enum(cmd, 0), (int32_t)cmd->arg[1].v.i, (int32_t)cmd->arg[2].v.i,
                  cmd->arg[3].v.i, cmd->arg[4].v.i, (int32_t)cmd->arg[5].v.i, arg_enum(cmd, 6),
                  arg_enum(cmd, 7), (uint32_t)cmd->arg[8].v.u);
}

/* A private copy of the image in *slot (one of o's levels) before a change. */
static tex_image *image_own(interp *ip, tex_image **slot)
{
    tex_image *old = *slot;
    if (old->refs == 1)
        return old;
    size_t n = sizeof *old + (size_t)old->width * (size_t)old->height * 4;
    if (!interp_budget_texels(ip, n))
        return NULL;
    tex_image *c = tr_realloc(NULL, n);
    if (!c) {
        if (ip->scene)
            ip->scene->failed = true;
        return NULL;
    }
    memcpy(c, old, n);
    c->refs = 1;
    old->refs--;
    *slot = c;
    return c;
}

void interp_texsubimage2d(interp *ip, const rgl_cmd *cmd)
{
    interp_unrec_pixel_uses(ip, false, false, true);
    interp_tex_subimage(ip, 2, arg_enum(cmd, 0), cmd->arg[1].v.i, cmd->arg[2].v.i,
                        cmd->arg[3].v.i, cmd->arg[4].v.i, cmd->arg[5].v.i, arg_enum(cmd, 6),
                        arg_enum(cmd, 7), (uint32_t)cmd->arg[8].v.u);
}

void interp_tex_image(interp *ip, GLenum target, int32_t level, int32_t internal, int64_t w,
                      int64_t h, int32_t border, GLenum format, GLenum type, uint32_t id)
{
    tex_image_set(ip, target, level, internal, w, h, border, format, type, id);
}

void interp_tex_subimage(interp *ip, int dims, GLenum target, int64_t level, int64_t x0,
                         int64_t y0, int64_t w, int64_t h, GLenum format, GLenum type,
                         uint32_t id)
{
    if (interp_reject_in_begin(ip))
        return;
    int face = target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z
                   ? (int)(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X)
                   : -1;
    if (dims == 1 ? target != GL_TEXTURE_1D
                  : target != GL_TEXTURE_2D && target != GL_TEXTURE_RECTANGLE && face < 0) {
        interp_bad_enum(ip, "texture target", target);
        return;
    }
    size_t bytes;
    if (!check_image(ip, format, type, w, h, &bytes))
        return;
    tex_obj *o = bound_obj(ip, face >= 0 ? GL_TEXTURE_CUBE_MAP : target, false);
    if (level < 0 || level >= TEX_LEVELS) {
        interp_bad_value(ip, "texture sub-image level");
        return;
    }
    if (face >= 0 && level > 0)
        return; /* a cube map's levels are not drawn (tex_image_set) */
    tex_image **slot = !o ? NULL : face >= 0 ? &o->face[face] : level_slot(o, (int)level);
    if (!slot || !*slot) {
        interp_bad_op(ip, "texture sub-image on a texture level with no image");
        return;
    }
    if (x0 < 0 || y0 < 0 || x0 + w > (*slot)->width || y0 + h > (*slot)->height) {
        interp_bad_value(ip, "texture sub-image region outside the texture");
        return;
    }
    if (o->depth != (format == GL_DEPTH_COMPONENT)) {
        interp_bad_op(ip, "depth pixels and a colour texture, or the reverse");
        return;
    }
    if (w == 0 || h == 0 || !id)
        return;
    const uint8_t *px = interp_pixels_fetch(ip, id, bytes, &o->lost);
    tex_image *img = px ? image_own(ip, slot) : NULL;
    if (!img)
        return;
    size_t ps = pixel_bytes(format, type, true);
    for (int64_t y = 0; y < h; y++)
        convert_pixels(img->rgba + ((size_t)(y0 + y) * (size_t)img->width + (size_t)x0) * 4,
                       px + (size_t)y * (size_t)w * ps, (size_t)w, format, type, o->base_format);
    image_seal(img);
    if (o->generate_mipmap && level == o->base_level && face < 0 &&
        o->target != GL_TEXTURE_RECTANGLE)
        generate_levels(ip, o, (int)level);
}

void interp_tex_image3d(interp *ip, int32_t level, int32_t internal, int64_t w, int64_t h,
                        int64_t d, int32_t border, GLenum format, GLenum type, uint32_t id)
{
    GLenum base = base_format(internal);
    if (!base || base == GL_DEPTH_COMPONENT) {
        interp_bad_value(ip, "3D texture internal format");
        return;
    }
    size_t bytes;
    if (!check_image(ip, format, type, w, h, &bytes))
        return;
    if (d < 0 || d > INTERP_MAX_TEXTURE_SIZE || (uint64_t)w * (uint64_t)h * (uint64_t)d >
                                                   TEX_MAX_TEXELS) {
        interp_bad_value(ip, "3D texture depth");
        return;
    }
    bytes *= (size_t)d;
    tex_obj *o = bound_obj(ip, GL_TEXTURE_3D, true);
    if (!o) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    if (level > 0) {
        bool fits = o->img && w - 2 * border == level_size(o->img->width, level) &&
                    h - 2 * border == level_size(o->img->height / o->depth3, level) &&
                    d - 2 * border == level_size(o->depth3, level);
        if (fits)
            o->levels |= 1u << level;
        else
            o->levels &= ~(1u << level);
        return;
    }
    image_release(o->img);
    o->img = NULL;
    o->levels = 0;
    o->lost = 0;
    o->depth = false;
    o->base_format = base;
    o->depth3 = 0;
    int64_t iw = w - 2 * border, ih = h - 2 * border, id3 = d - 2 * border;
    if (iw <= 0 || ih <= 0 || id3 <= 0 || !id)
        return;
    const uint8_t *px = interp_pixels_fetch(ip, id, bytes, &o->lost);
    if (!px || !interp_budget_texels(ip, (uint64_t)iw * (uint64_t)ih * (uint64_t)id3 * 4))
        return;
    tex_image *img = tr_realloc(NULL, sizeof *img + (size_t)(iw * ih * id3) * 4);
    if (!img) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    img->refs = 1;
    img->width = (int)iw;
    img->height = (int)(ih * id3);
    size_t ps = pixel_bytes(format, type, true);
    for (int64_t z = 0; z < id3; z++)
        for (int64_t y = 0; y < ih; y++)
            convert_pixels(img->rgba + ((size_t)(z * ih + y) * (size_t)iw) * 4,
                           px + (((size_t)(z + border) * (size_t)h + (size_t)(y + border)) *
                                     (size_t)w +
                                 (size_t)border) *
                                    ps,
                           (size_t)iw, format, type, base);
    image_seal(img);
    o->img = img;
    /* GL_GENERATE_MIPMAP: the levels follow (a 3D texture is drawn from
     * its level 0, so only their presence matters). */
    o->levels = o->generate_mipmap ? ~0u : 1u;
    o->depth3 = (int)id3;
}

void interp_tex_subimage3d(interp *ip, int64_t level, int64_t x0, int64_t y0, int64_t z0,
                           int64_t w, int64_t h, int64_t d, GLenum format, GLenum type,
                           uint32_t id)
{
    size_t bytes;
    if (!check_image(ip, format, type, w, h, &bytes))
        return;
    tex_obj *o = bound_obj(ip, GL_TEXTURE_3D, false);
    if (level != 0)
        return; /* other levels are not translated */
    if (!o || !o->img || !o->depth3) {
        interp_bad_op(ip, "3D texture sub-image on a texture with no level 0");
        return;
    }
    int th = o->img->height / o->depth3;
    if (x0 < 0 || y0 < 0 || z0 < 0 || d < 0 || x0 + w > o->img->width || y0 + h > th ||
        z0 + d > o->depth3) {
        interp_bad_value(ip, "3D texture sub-image region outside the texture");
        return;
    }
    if (o->depth != (format == GL_DEPTH_COMPONENT)) {
        interp_bad_op(ip, "depth pixels and a colour texture, or the reverse");
        return;
    }
    if (w == 0 || h == 0 || d == 0 || !id)
        return;
    const uint8_t *px = interp_pixels_fetch(ip, id, bytes * (size_t)d, &o->lost);
    tex_image *img = px ? image_own(ip, &o->img) : NULL;
    if (!img)
        return;
    size_t ps = pixel_bytes(format, type, true);
    for (int64_t z = 0; z < d; z++)
        for (int64_t y = 0; y < h; y++)
            convert_pixels(img->rgba +
                               ((size_t)((z0 + z) * th + y0 + y) * (size_t)img->width +
                                (size_t)x0) * 4,
                           px + ((size_t)(z * h + y) * (size_t)w) * ps, (size_t)w, format, type,
                           o->base_format);
    image_seal(img);
}

/* gluBuild2DMipmaps: level 0 is the image scaled to powers of two no
 * larger than GL's limit (GLU 1.3 3.1, a box filter as gluScaleImage's),
 * and the chain is complete. */
void interp_build2dmipmaps(interp *ip, const rgl_cmd *cmd)
{
    GLenum target = arg_enum(cmd, 0);
    int32_t internal = (int32_t)cmd->arg[1].v.i;
    int64_t w = cmd->arg[2].v.i, h = cmd->arg[3].v.i;
    GLenum format = arg_enum(cmd, 4), type = arg_enum(cmd, 5);
    uint32_t id = (uint32_t)cmd->arg[6].v.u;
    if (target != GL_TEXTURE_2D) {
        interp_bad_enum(ip, "gluBuild2DMipmaps target", target);
        return;
    }
    if (w < 1 || h < 1) {
        interp_bad_value(ip, "gluBuild2DMipmaps size");
        return;
    }
    tex_image_set(ip, target, 0, internal, w, h, 0, format, type, id);
    tex_obj *o = bound_obj(ip, target, false);
    if (!o || !o->img || o->img->width != w || o->img->height != h)
        return;
    /* GLU picks, per side, the power of two nearest in log scale, rounding
     * up from halfway ((s - 1) rounded up to a power when s is not one
     * already, then halved when s lies below 3/4 of it). */
    int64_t sz[2] = {w, h}, p[2];
    for (int k = 0; k < 2; k++) {
        int64_t q = 1;
        while (q < sz[k])
            q <<= 1;
        if (q != sz[k] && q / 2 >= 1 && sz[k] * 4 < q * 3)
            q /= 2;
        p[k] = q < INTERP_MAX_TEXTURE_SIZE ? q : INTERP_MAX_TEXTURE_SIZE;
    }
    if (p[0] != w || p[1] != h) {
        tex_image *src = o->img;
        if (!interp_budget_texels(ip, (uint64_t)p[0] * (uint64_t)p[1] * 4))
            return;
        tex_image *img = tr_realloc(NULL, sizeof *img + (size_t)p[0] * (size_t)p[1] * 4);
        if (!img) {
            if (ip->scene)
                ip->scene->failed = true;
            return;
        }
        img->refs = 1;
        img->width = (int)p[0];
        img->height = (int)p[1];
        /* Box filter: each destination texel averages the source area it covers. */
        double sx = (double)w / (double)p[0], sy = (double)h / (double)p[1];
        for (int64_t y = 0; y < p[1]; y++)
            for (int64_t x = 0; x < p[0]; x++) {
                double acc[4] = {0, 0, 0, 0}, wsum = 0;
                double x0 = x * sx, x1 = x0 + sx, y0 = y * sy, y1 = y0 + sy;
                for (int64_t yy = (int64_t)y0; yy < y1 && yy < h; yy++)
                    for (int64_t xx = (int64_t)x0; xx < x1 && xx < w; xx++) {
                        double wx = fmin(x1, (double)xx + 1) - fmax(x0, (double)xx);
                        double wy = fmin(y1, (double)yy + 1) - fmax(y0, (double)yy);
                        double wt = wx * wy;
                        const uint8_t *s = src->rgba + ((size_t)yy * (size_t)w + (size_t)xx) * 4;
                        for (int c = 0; c < 4; c++)
                            acc[c] += wt * s[c];
                        wsum += wt;
                    }
                uint8_t *d = img->rgba + ((size_t)y * (size_t)p[0] + (size_t)x) * 4;
                for (int c = 0; c < 4; c++)
                    d[c] = (uint8_t)(wsum > 0 ? acc[c] / wsum + 0.5 : 0);
            }
        image_seal(img);
        image_release(src);
        o->img = img;
        o->lw[0] = img->width;
        o->lh[0] = img->height;
    }
    generate_levels(ip, o, 0);
}

void interp_pixelstore(interp *ip, const rgl_cmd *cmd)
{
    GLenum pname = arg_enum(cmd, 0);
    int64_t v = cmd->arg[1].v.i;
    if (interp_reject_in_begin(ip))
        return;
    switch (pname) {
    case GL_UNPACK_ALIGNMENT: case GL_PACK_ALIGNMENT:
        if (v != 1 && v != 2 && v != 4 && v != 8) {
            interp_bad_value(ip, "pixel store alignment");
            return;
        }
        break;
    case GL_UNPACK_SWAP_BYTES: case GL_UNPACK_LSB_FIRST: case GL_UNPACK_ROW_LENGTH:
    case GL_UNPACK_SKIP_ROWS: case GL_UNPACK_SKIP_PIXELS: case GL_PACK_SWAP_BYTES:
    case GL_PACK_LSB_FIRST: case GL_PACK_ROW_LENGTH: case GL_PACK_SKIP_ROWS:
    case GL_PACK_SKIP_PIXELS: case GL_UNPACK_SKIP_IMAGES: case GL_UNPACK_IMAGE_HEIGHT:
    case GL_PACK_SKIP_IMAGES: case GL_PACK_IMAGE_HEIGHT:
        if (v < 0) {
            interp_bad_value(ip, "negative pixel store value");
            return;
        }
        break;
    default:
        interp_bad_enum(ip, "pixel store pname", pname);
        return;
    }
    /* Kept for completeness: the trace's pixels are already unpacked. */
    interp_textures *t = textures(ip);
    if (t && pname >= GL_UNPACK_SWAP_BYTES && pname <= GL_UNPACK_ALIGNMENT)
        t->unpack[pname - GL_UNPACK_SWAP_BYTES] = (int32_t)v;
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
static void tex_depth_mode(interp *ip, tex_obj *o, GLenum mode)
{
    GLenum was = o->depth_mode;
    o->depth_mode = mode;
    if (!o->depth || was == mode)
        return;
    o->base_format = mode;
    for (int k = 0; k < TEX_LEVELS; k++) { /* every level (a depth texture's mipmaps) */
        tex_image **slot = level_slot(o, k);
        tex_image *img = *slot ? image_own(ip, slot) : NULL;
        if (!img)
            continue;
        size_t n = (size_t)img->width * (size_t)img->height;
        for (size_t i = 0; i < n; i++) {
            uint8_t *t = img->rgba + i * 4, d = was == GL_ALPHA ? t[3] : t[0];
            bool alpha = mode == GL_ALPHA;
            t[0] = t[1] = t[2] = alpha ? 255 : d;
            t[3] = mode == GL_LUMINANCE ? 255 : d;
        }
        image_seal(img);
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
    tex_obj *o = bound_obj(ip, target, true);
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
        tex_depth_mode(ip, o, e);
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
    const interp_textures *s = src->tex;
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
    dst->tex = t;
    return 0;
}

void interp_textures_free(interp *ip)
{
    interp_textures *t = ip->tex;
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
    ip->tex = NULL;
}

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
    if (ip->tex) {
        ip->tex->nmade = 0;
        ip->tex->made_sc = NULL;
    }
}

/* The scene texture made from image `serial` by `how` (at r) and sampled
 * as st (its texels aside), or -1. A scene that dropped textures since
 * forgets them all. */
static int32_t made_find(interp *ip, uint64_t serial, uint64_t how, double r,
                         const scene_texture *st)
{
    interp_textures *t = ip->tex;
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
    interp_textures *t = ip->tex;
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
static bool complete(tex_obj *o)
{
    if (o->target == GL_TEXTURE_3D) /* drawn from level 0; the others only counted */
        return complete3d(o);
    int b = o->base_level;
    if (b < 0 || b >= TEX_LEVELS || b > o->max_level || !*level_slot(o, b))
        return false;
    if (!mipmap_filter(o->min_filter))
        return true;
    int q = last_level(o, b);
    for (int k = b + 1; k <= q; k++) {
        int32_t ew = o->lw[b] >> (k - b), eh = o->lh[b] >> (k - b);
        if (!(o->levels & (1u << k)) || o->lw[k] != (ew > 0 ? ew : 1) ||
            o->lh[k] != (eh > 0 ? eh : 1) || !*level_slot(o, k))
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
        return get_obj(ip, GL_TEXTURE_CUBE_MAP, u->texture->binding_cube, false);
    if (u->caps[UCAP(TEXTURE_3D)])
        return get_obj(ip, GL_TEXTURE_3D, u->texture->binding_3d, false);
    if (interp_texture_rect_on(ip, k))
        return get_obj(ip, GL_TEXTURE_RECTANGLE, u->texture->binding_rect, false);
    if (u->caps[UCAP(TEXTURE_2D)])
        return get_obj(ip, GL_TEXTURE_2D, u->texture->binding_2d, false);
    if (u->caps[UCAP(TEXTURE_1D)])
        return get_obj(ip, GL_TEXTURE_1D, u->texture->binding_1d, false);
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
        st.env_mode = env;
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
    st->mip_filter = o->min_filter;
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
        const tex_image *im = *level_slot(o, k);
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
    interp_textures *t = ip->tex;
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
        bool pass = scene_alpha_pass(o->compare_func, (float)r, (float)d);
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
    if (!o || !complete(o))
        return -1;
    /* A 3D texture: the slice its r picks, when r is constant, made
     * below unless the scene has it. */
    double r = 0;
    if (o->depth3 && !slice_at(ip, o, k, &r))
        return -1;
    const tex_image *im = o->depth3 ? o->img : *level_slot(o, o->base_level); /* complete: not NULL */
    int iw = im->width, ih = o->depth3 ? im->height / o->depth3 : im->height;
    /* A depth texture compared with r: the image of results where r is
     * constant (tex_compared), made below unless the scene has it; else,
     * noted, its depth values. */
    bool compare = !o->depth3 && o->depth && o->compare_mode == GL_COMPARE_R_TO_TEXTURE;
    if (compare) {
        double lo = ip->tex->r_min[k], hi = ip->tex->r_max[k];
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
    if (mipmap_filter(o->min_filter))
        interp_note(ip, DIAG_NOTE_TEX_MIPMAP);
    else if (o->min_filter != o->mag_filter)
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
    st.env_mode = env;
    memcpy(st.env_color, u.texture->env_color, sizeof st.env_color);
    /* The alpha test per texel where the texel's alpha is the fragment's
     * (table 3.22: DECAL takes the vertex alpha, and so does a base
     * format without alpha); otherwise interp_alpha_face. */
    GLenum b0 = o->base_format;
    bool has_alpha = b0 == GL_RGBA || b0 == GL_LUMINANCE_ALPHA || b0 == GL_ALPHA ||
                     b0 == GL_INTENSITY;
    if (ga->caps[INTERP_CAP_ALPHA_TEST] && ga->color_buffer.alpha_func != GL_ALWAYS && has_alpha &&
        (env == GL_MODULATE || env == GL_REPLACE)) {
        st.alpha_func = ga->color_buffer.alpha_func;
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

    if (mipmap_filter(o->min_filter) && !o->depth3) /* the levels, each its own scene texture */
        return mip_chain(ip, o, &st, ms, mt, u.texture->lod_bias);
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
                if (ip->tex && normal_matrix(ip->tex, mv)) {
                    const double *nm = ip->tex->nrm_mat.m;
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
    if (!u.caps[UCAP(TEXTURE_CUBE_MAP)] && ip->tex && unit >= 0 && unit < INTERP_TEX_UNITS) {
        double rq = r[2] / q;
        interp_textures *t = ip->tex;
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
