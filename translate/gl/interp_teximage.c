/* interp_teximage.c: texture images (issue 5): glTexImage1D/2D/3D,
 * glTexSubImage2D/3D, gluBuild2DMipmaps, glPixelStore, GL's external
 * formats and types converted to the 8-bit RGBA the interpreter keeps
 * (interp_teximage.h), and the pixels a call refers to (a resource).
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
#include "talloc.h"

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
GLenum interp_tex_base_format(int32_t internal)
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

void interp_tex_image_seal(tex_image *img) { img->serial = atomic_fetch_add(&image_serials, 1); }

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
    if (b < 0 || b >= TEX_LEVELS || !*interp_tex_level_slot(o, b))
        return;
    for (int k = b + 1; k < TEX_LEVELS; k++) {
        const tex_image *src = *interp_tex_level_slot(o, k - 1);
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
        interp_tex_image_seal(img);
        tex_image **slot = interp_tex_level_slot(o, k);
        interp_tex_image_release(*slot);
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
    GLenum base = interp_tex_base_format(internal);
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
    tex_obj *o = interp_tex_bound_obj(ip, face >= 0 ? GL_TEXTURE_CUBE_MAP : target, true);
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
    tex_image **slot = face >= 0 ? &o->face[face] : interp_tex_level_slot(o, level);
    interp_tex_image_release(*slot);
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
    interp_tex_image_seal(img);
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
tex_image *interp_tex_image_own(interp *ip, tex_image **slot)
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
    tex_obj *o = interp_tex_bound_obj(ip, face >= 0 ? GL_TEXTURE_CUBE_MAP : target, false);
    if (level < 0 || level >= TEX_LEVELS) {
        interp_bad_value(ip, "texture sub-image level");
        return;
    }
    if (face >= 0 && level > 0)
        return; /* a cube map's levels are not drawn (tex_image_set) */
    tex_image **slot = !o ? NULL : face >= 0 ? &o->face[face] : interp_tex_level_slot(o, (int)level);
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
    tex_image *img = px ? interp_tex_image_own(ip, slot) : NULL;
    if (!img)
        return;
    size_t ps = pixel_bytes(format, type, true);
    for (int64_t y = 0; y < h; y++)
        convert_pixels(img->rgba + ((size_t)(y0 + y) * (size_t)img->width + (size_t)x0) * 4,
                       px + (size_t)y * (size_t)w * ps, (size_t)w, format, type, o->base_format);
    interp_tex_image_seal(img);
    if (o->generate_mipmap && level == o->base_level && face < 0 &&
        o->target != GL_TEXTURE_RECTANGLE)
        generate_levels(ip, o, (int)level);
}

void interp_tex_image3d(interp *ip, int32_t level, int32_t internal, int64_t w, int64_t h,
                        int64_t d, int32_t border, GLenum format, GLenum type, uint32_t id)
{
    GLenum base = interp_tex_base_format(internal);
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
    tex_obj *o = interp_tex_bound_obj(ip, GL_TEXTURE_3D, true);
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
    interp_tex_image_release(o->img);
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
    interp_tex_image_seal(img);
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
    tex_obj *o = interp_tex_bound_obj(ip, GL_TEXTURE_3D, false);
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
    tex_image *img = px ? interp_tex_image_own(ip, &o->img) : NULL;
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
    interp_tex_image_seal(img);
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
    tex_obj *o = interp_tex_bound_obj(ip, target, false);
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
        interp_tex_image_seal(img);
        interp_tex_image_release(src);
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
    interp_textures *t = interp_tex_state(ip);
    if (t && pname >= GL_UNPACK_SWAP_BYTES && pname <= GL_UNPACK_ALIGNMENT)
        t->unpack[pname - GL_UNPACK_SWAP_BYTES] = (int32_t)v;
}
