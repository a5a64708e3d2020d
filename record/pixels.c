/* pixels.c: what the recorder reads of a pixel call (glTexImage1D/2D,
 * glTexSubImage2D, gluBuild2DMipmaps, glDrawPixels, glBitmap) and how it
 * turns it into a pixel resource.
 *
 * GL's rules, applied before a byte is read: the format/type pairs GL
 * takes and their pixel sizes (packed types included); the unpack state
 * (alignment, row length, skipped rows and pixels; swap bytes and bitmap
 * bit order, which are undone so resources are plain); the targets,
 * levels, sizes and borders GL takes; a buffer bound to
 * GL_PIXEL_UNPACK_BUFFER, whose offset is never taken for an address. A
 * call GL refuses reads nothing; one GL may carry out that the recorder
 * cannot record is marked @Skipped (rgl_note_skipped). The entry points
 * themselves are in entry_custom.c; glPixelStorei, which keeps the unpack
 * state for recording without a context, is here.
 */
#include <errno.h>
#include <stdint.h>
#include <string.h>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include "raygl.h"
#include "recorder.h"

/* What the recorder makes of a call's enums: GL takes them (as far as
 * RayGL knows), GL refuses them (and reads nothing), or RayGL does not
 * know them (the call goes unrecorded, with @Skipped). */
enum px_status { PX_OK, PX_REJECT, PX_UNKNOWN };

/* Components of a pixel format (GL 2.1 table 3.6; GL 3.0 adds RG, the
 * integer formats and GL_DEPTH_STENCIL); 0 for one RayGL does not know. */
static int format_components(GLenum format)
{
    switch (format) {
    case GL_COLOR_INDEX: case GL_STENCIL_INDEX: case GL_DEPTH_COMPONENT: case GL_RED:
    case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: case GL_RED_INTEGER:
    case GL_GREEN_INTEGER: case GL_BLUE_INTEGER: case GL_ALPHA_INTEGER:
        return 1;
    case GL_LUMINANCE_ALPHA: case GL_RG: case GL_RG_INTEGER: case GL_DEPTH_STENCIL:
        return 2;
    case GL_RGB: case GL_BGR: case GL_RGB_INTEGER: case GL_BGR_INTEGER:
        return 3;
    case GL_RGBA: case GL_BGRA: case GL_RGBA_INTEGER: case GL_BGRA_INTEGER:
        return 4;
    default:
        return 0;
    }
}

/* How GL reads one pixel of format/type (GL 2.1 tables 3.5 and 3.8, GL 3.0
 * 3.7.3): *ps its bytes (0 for GL_BITMAP, one bit), *es the bytes of one
 * element, the unit GL_UNPACK_SWAP_BYTES swaps. A packed type needs a
 * format of as many components; GL refuses other pairs (INVALID_ENUM or
 * INVALID_OPERATION) without reading. */
static enum px_status pixel_layout(GLenum format, GLenum type, size_t *ps, size_t *es)
{
    int comps = format_components(format);
    if (!comps)
        return PX_UNKNOWN;
    bool rgb = format == GL_RGB || format == GL_RGB_INTEGER;
    bool rgba = format == GL_RGBA || format == GL_BGRA || format == GL_RGBA_INTEGER ||
                format == GL_BGRA_INTEGER;
    bool integer = (format >= GL_RED_INTEGER && format <= GL_BGRA_INTEGER) ||
                   format == GL_RG_INTEGER;
    bool ok;
    size_t cs = 0;
    switch (type) {
    case GL_BITMAP:
        *ps = *es = 0;
        return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? PX_OK : PX_REJECT;
    case GL_UNSIGNED_BYTE: case GL_BYTE: cs = 1; break;
    case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT: cs = 2; break;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: cs = 4; break;
    case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV:
        *ps = *es = 1;
        ok = rgb;
        break;
    case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
        *ps = *es = 2;
        ok = rgb;
        break;
    case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV:
        *ps = *es = 2;
        ok = rgba;
        break;
    case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV:
        *ps = *es = 4;
        ok = rgba;
        break;
    case GL_UNSIGNED_INT_10F_11F_11F_REV: case GL_UNSIGNED_INT_5_9_9_9_REV:
        *ps = *es = 4;
        ok = format == GL_RGB;
        break;
    case GL_UNSIGNED_INT_24_8:
        *ps = *es = 4;
        ok = format == GL_DEPTH_STENCIL;
        break;
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
        *ps = 8;
        *es = 4;
        ok = format == GL_DEPTH_STENCIL;
        break;
    default:
        return PX_UNKNOWN;
    }
    if (cs) {
        *ps = (size_t)comps * cs;
        *es = cs;
        ok = format != GL_DEPTH_STENCIL &&
             !(integer && (type == GL_FLOAT || type == GL_HALF_FLOAT));
    }
    return ok ? PX_OK : PX_REJECT;
}

/* GL's unpack state (GL 2.1 table 6.17), in pname order from
 * GL_UNPACK_SWAP_BYTES. */
enum { UP_SWAP, UP_LSB, UP_ROW_LENGTH, UP_SKIP_ROWS, UP_SKIP_PIXELS, UP_ALIGNMENT, UP_COUNT };

/* The unpack state: read back from a live context (six glGetIntegerv per
 * pixel call), the values set through the recorder without one (a batch
 * program's glPixelStorei is recorded but not seen here). */
static void unpack_get(rgl_stream *s, GLint u[UP_COUNT])
{
    static const GLint defaults[UP_COUNT] = {0, 0, 0, 0, 0, 4};
    for (int k = 0; k < UP_COUNT; k++)
        u[k] = defaults[k];
    if (!rgl_live_context()) {
        for (int k = 0; k < UP_COUNT; k++)
            if (s->objs.unpack[k])
                u[k] = s->objs.unpack[k];
        return;
    }
    for (int k = 0; k < UP_COUNT; k++)
        glGetIntegerv(GL_UNPACK_SWAP_BYTES + (GLenum)k, &u[k]);
    /* Never trust a value into a size: GL itself keeps them valid. */
    for (int k = UP_ROW_LENGTH; k <= UP_SKIP_PIXELS; k++)
        if (u[k] < 0)
            u[k] = 0;
    if (u[UP_ALIGNMENT] != 1 && u[UP_ALIGNMENT] != 2 && u[UP_ALIGNMENT] != 4 &&
        u[UP_ALIGNMENT] != 8)
        u[UP_ALIGNMENT] = 4;
}

/* Client state: executed at once, never compiled into a list (GL 1.x
 * 5.4); kept for pixels_put when there is no context to ask. */
RGL_EXPORT void rayglPixelStorei(GLenum pname, GLint param)
{
    /* Kept while not recording too: a trace opened later starts from it. */
    rgl_stream *s;
    bool rec = rgl_reserve(&s, 1) != NULL;
    if (!rec)
        s = rgl_tls_stream;
    if (s && !s->in_begin && pname >= GL_UNPACK_SWAP_BYTES && pname <= GL_UNPACK_ALIGNMENT) {
        int k = (int)(pname - GL_UNPACK_SWAP_BYTES);
        bool ok = k == UP_ALIGNMENT ? param == 1 || param == 2 || param == 4 || param == 8
                : k <= UP_LSB        ? true
                                     : param >= 0;
        if (ok)
            s->objs.unpack[k] = k <= UP_LSB ? param != 0 : param;
    }
    if (rec)
        RECORD_NOW(s, RGL_OP_PixelStorei, "ei", pname, param);
    glPixelStorei(pname, param);
}

/* Where the bytes GL reads for a w x h image lie, from the pointer (or the
 * buffer offset) on (GL 2.1 3.6.4, "Unpacking"): the first row at `start`,
 * rows `stride` apart, `span` bytes read of each (a bitmap's row starts at
 * bit `bit` of its first byte); `row`, a row's bytes once tightly packed.
 * False when the numbers pass what memory could hold. */
typedef struct px_span {
    uint64_t start, stride, span, row;
    unsigned bit;
} px_span;

static bool pixel_span(const GLint u[UP_COUNT], size_t ps, uint64_t w, px_span *sp)
{
    uint64_t l = u[UP_ROW_LENGTH] > 0 ? (uint64_t)u[UP_ROW_LENGTH] : w;
    uint64_t a = (uint64_t)u[UP_ALIGNMENT];
    uint64_t rows = (uint64_t)u[UP_SKIP_ROWS], pixels = (uint64_t)u[UP_SKIP_PIXELS];
    if (ps == 0) { /* bits, rows padded to the alignment in bytes */
        sp->stride = (l + 8 * a - 1) / (8 * a) * a;
        sp->bit = (unsigned)(pixels % 8);
        sp->span = (sp->bit + w + 7) / 8;
        sp->row = (w + 7) / 8;
        pixels /= 8;
    } else {
        sp->stride = (l * ps + a - 1) / a * a;
        sp->bit = 0;
        sp->span = sp->row = w * ps;
        pixels *= ps;
    }
    return !__builtin_mul_overflow(rows, sp->stride, &sp->start) &&
           !__builtin_add_overflow(sp->start, pixels, &sp->start);
}

/* Turns h gathered bitmap rows of `span` bytes, starting at bit `bit`, in
 * GL_UNPACK_LSB_FIRST order `lsb`, into rows of `row` bytes from bit 0,
 * most significant bit first: the layout of a trace's bitmaps. */
static void bits_pack(const uint8_t *in, size_t span, unsigned bit, bool lsb, uint8_t *out,
                      size_t row, size_t w, size_t h)
{
    memset(out, 0, row * h);
    for (size_t y = 0; y < h; y++, in += span, out += row) {
        for (size_t i = 0; i < w; i++) {
            size_t k = bit + i;
            unsigned v = lsb ? (in[k / 8] >> (k % 8)) & 1u : (in[k / 8] >> (7 - k % 8)) & 1u;
            out[i / 8] |= (uint8_t)(v << (7 - i % 8));
        }
    }
}

static void bytes_swap(uint8_t *p, size_t n, size_t es)
{
    for (size_t i = 0; i + es <= n; i += es)
        for (size_t j = 0; j < es / 2; j++) {
            uint8_t t = p[i + j];
            p[i + j] = p[i + es - 1 - j];
            p[i + es - 1 - j] = t;
        }
}

/* With a buffer bound to GL_PIXEL_UNPACK_BUFFER the pixels are at offset
 * `pixels` in it (GL 2.1 6.1.13). Reads no byte GL would not read, and none
 * when GL refuses the call: the format/type pair, a negative size, a
 * mapped buffer, a range past the buffer's end. */
int64_t rgl_pixels_put(rgl_stream *s, uint32_t format, uint32_t type, int32_t w, int32_t h,
                       const void *pixels, bool glu)
{
    size_t ps, es;
    enum px_status st = pixel_layout(format, type, &ps, &es);
    if (st != PX_OK)
        return st == PX_UNKNOWN ? RGL_PX_SKIP_ENUM : RGL_PX_REFUSED;
    if (w < 0 || h < 0)
        return RGL_PX_REFUSED;
    uint32_t pbo = rgl_buffer_binding(s, GL_PIXEL_UNPACK_BUFFER);
    if (pbo && glu)
        return RGL_PX_SKIP_DATA; /* GLU would read the offset as an address */
    if ((!pixels && !pbo) || w == 0 || h == 0)
        return RGL_PX_NONE;
    GLint u[UP_COUNT];
    unpack_get(s, u);
    px_span sp;
    if (!pixel_span(u, ps, (uint64_t)w, &sp))
        return RGL_PX_REFUSED;
    if (sp.row > RGL_CHUNK_MAX_PAYLOAD / (size_t)h) {
        rgl_fail(EFBIG, "a texture image is larger than a chunk can hold");
        return RGL_PX_REFUSED;
    }
    size_t total = sp.row * (size_t)h, gathered = sp.span * (size_t)h;
    bool swap = u[UP_SWAP] && es > 1, bits = ps == 0;
    const uint8_t *src = (const uint8_t *)pixels + (pbo ? 0 : sp.start);
    if (!pbo && !swap && (!bits || (sp.bit == 0 && !u[UP_LSB])) &&
        (sp.stride == sp.row || h == 1)) {
        uint32_t id = rgl_resource_put(RGL_RES_BYTES, src, total);
        return id ? (int64_t)id : RGL_PX_REFUSED;
    }
    uint8_t *tmp = rgl_alloc(gathered + (bits ? total : 0));
    if (!tmp) {
        rgl_fail(ENOMEM, "allocation failed");
        return RGL_PX_REFUSED;
    }
    int64_t ret = RGL_PX_REFUSED;
    if (pbo) {
        uint64_t offset = (uintptr_t)pixels;
        if (__builtin_add_overflow(offset, sp.start, &offset) ||
            !rgl_buffer_gather(GL_PIXEL_UNPACK_BUFFER, pbo, rgl_buffer_live(), offset, sp.stride,
                               sp.span, (size_t)h, tmp))
            goto out; /* GL refuses it: mapped, or past the buffer's end */
    } else {
        for (size_t y = 0; y < (size_t)h; y++)
            memcpy(tmp + y * sp.span, src + y * sp.stride, sp.span);
    }
    uint8_t *image = tmp;
    if (bits) {
        image = tmp + gathered;
        bits_pack(tmp, sp.span, sp.bit, u[UP_LSB] != 0, image, sp.row, (size_t)w, (size_t)h);
    } else if (swap) {
        bytes_swap(image, total, es);
    }
    uint32_t id = rgl_resource_put(RGL_RES_BYTES, image, total);
    ret = id ? (int64_t)id : RGL_PX_REFUSED;
out:
    rgl_free(tmp);
    return ret;
}

void rgl_note_skipped(uint32_t op, int64_t why)
{
    uint32_t reason = why == RGL_PX_SKIP_ENUM ? RGL_SKIP_UNKNOWN_ENUM
                    : why == RGL_PX_SKIP_DATA ? RGL_SKIP_NO_DATA
                                          : 0;
    if (reason) /* where the call would have been: in a list body too */
        rgl_record(RGL_OP_Skipped, "ee", op, reason);
}

bool rgl_tex_is_proxy(uint32_t target)
{
    switch (target) {
    case GL_PROXY_TEXTURE_1D: case GL_PROXY_TEXTURE_2D: case GL_PROXY_TEXTURE_CUBE_MAP:
    case GL_PROXY_TEXTURE_RECTANGLE: case GL_PROXY_TEXTURE_1D_ARRAY: case GL_PROXY_TEXTURE_3D:
        return true;
    default:
        return false;
    }
}

/* Whether target names images of `dims` dimensions for glTexImage (sub:
 * glTexSubImage, which takes no proxy): GL 4.6 8.5 lists every one. */
static bool tex_target_ok(int dims, GLenum target, bool sub)
{
    if (sub && rgl_tex_is_proxy(target))
        return false;
    if (dims == 1)
        return target == GL_TEXTURE_1D || target == GL_PROXY_TEXTURE_1D;
    if (dims == 3)
        return target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D;
    switch (target) {
    case GL_TEXTURE_2D: case GL_PROXY_TEXTURE_2D: case GL_TEXTURE_RECTANGLE:
    case GL_PROXY_TEXTURE_RECTANGLE: case GL_TEXTURE_1D_ARRAY: case GL_PROXY_TEXTURE_1D_ARRAY:
    case GL_PROXY_TEXTURE_CUBE_MAP:
        return true;
    default:
        return target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
    }
}

/* Whether GL knows internalformat for glTexImage: the GL 1.x counts and
 * base formats, and the sized, float, integer, depth, sRGB and compressed
 * ones of GL 4.6 tables 8.12-8.14 and of the usual extensions. */
static bool internal_format_known(GLint f)
{
    static const struct { GLint lo, hi; } ranges[] = {
        {1, 4},
        {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT}, {GL_RED, GL_ALPHA},
        {GL_RGB, GL_LUMINANCE_ALPHA}, {GL_R3_G3_B2, GL_R3_G3_B2},
        {GL_ALPHA4, GL_RGBA16}, /* 0x803b .. 0x805b: the GL 1.1 sized formats */
        {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT32},
        {GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT},
        {GL_COMPRESSED_ALPHA, GL_COMPRESSED_RGBA}, {GL_DEPTH_STENCIL, GL_DEPTH_STENCIL},
        {GL_COMPRESSED_RED, GL_RG32UI}, /* 0x8225 .. 0x823c: RED, RG and their sizes */
        {GL_RGBA32F, 0x881f}, /* through GL_LUMINANCE_ALPHA16F_ARB */
        {GL_DEPTH24_STENCIL8, GL_DEPTH24_STENCIL8},
        {GL_R11F_G11F_B10F, GL_R11F_G11F_B10F}, {GL_RGB9_E5, GL_RGB9_E5},
        {GL_SRGB, GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT},
        {GL_DEPTH_COMPONENT32F, GL_DEPTH32F_STENCIL8}, {GL_STENCIL_INDEX8, GL_STENCIL_INDEX8},
        {GL_RGB565, GL_RGB565}, {GL_RGBA32UI, GL_RGB8I},
        {GL_COMPRESSED_RED_RGTC1, GL_COMPRESSED_SIGNED_RG_RGTC2},
        {GL_COMPRESSED_RGBA_BPTC_UNORM, GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT},
        {GL_R8_SNORM, GL_RGBA16_SNORM}, {GL_RGB10_A2UI, GL_RGB10_A2UI},
    };
    for (size_t k = 0; k < sizeof ranges / sizeof ranges[0]; k++)
        if (f >= ranges[k].lo && f <= ranges[k].hi)
            return true;
    return false;
}

/* Checks a glTexImage1D/2D or glTexSubImage2D (sub) call as GL does
 * before it reads a pixel (GL 2.1 3.8.1, 3.8.2): target, level, sizes and
 * border; with a live context also the largest size, and for a sub-image
 * the rectangle inside the level it changes. */
static enum px_status tex_check(rgl_stream *s, int dims, bool sub, GLenum target, GLint level,
                                GLint internal, GLint x, GLint y, GLsizei w, GLsizei h,
                                GLint border)
{
    if (s->in_begin || level < 0 || w < 0 || h < 0 || border < 0 || border > 1 ||
        !tex_target_ok(dims, target, sub))
        return PX_REJECT;
    bool rect = target == GL_TEXTURE_RECTANGLE || target == GL_PROXY_TEXTURE_RECTANGLE;
    if (rect && (level > 0 || border > 0))
        return PX_REJECT;
    if (!sub && (w < 2 * border || (dims == 2 && h < 2 * border && target != GL_TEXTURE_1D_ARRAY &&
                                    target != GL_PROXY_TEXTURE_1D_ARRAY)))
        return PX_REJECT;
    if (!sub && internal <= 0)
        return PX_REJECT;
    if (!sub && !internal_format_known(internal))
        return PX_UNKNOWN;
    /* The queries below only for the GL 1.1 targets: those of later GLs
     * are enum errors of their own in a context that lacks them. */
    bool basic = target == GL_TEXTURE_1D || target == GL_TEXTURE_2D ||
                 target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D;
    if (!basic || !rgl_live_context())
        return PX_OK;
    GLint max = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
    if (max > 0) {
        int levels = 0;
        while ((max >> levels) > 1)
            levels++;
        if (level > levels)
            return PX_REJECT;
        if (!sub && (w - 2 * border > max || (dims == 2 && h - 2 * border > max)))
            return rgl_tex_is_proxy(target) ? PX_OK : PX_REJECT;
    }
    if (sub) {
        GLint tw = 0, th = 0, tb = 0;
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &tw);
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &th);
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_BORDER, &tb);
        if ((int64_t)x < -tb || (int64_t)x + w > (int64_t)tw - tb || (int64_t)y < -tb ||
            (int64_t)y + h > (int64_t)th - tb)
            return PX_REJECT;
    }
    return PX_OK;
}

int64_t rgl_tex_pixels(rgl_stream *s, int dims, bool sub, uint32_t target, int32_t level,
                       int32_t internal, int32_t x, int32_t y, int32_t w, int32_t h,
                       int32_t border, uint32_t format, uint32_t type, const void *pixels)
{
    enum px_status st = tex_check(s, dims, sub, target, level, internal, x, y, w, h, border);
    if (st != PX_OK)
        return st == PX_UNKNOWN ? RGL_PX_SKIP_ENUM : RGL_PX_REFUSED;
    if (rgl_tex_is_proxy(target)) { /* GL reads no pixels for a proxy: only the enums */
        size_t ps, es;
        st = pixel_layout(format, type, &ps, &es);
        return st == PX_OK ? RGL_PX_NONE : st == PX_UNKNOWN ? RGL_PX_SKIP_ENUM : RGL_PX_REFUSED;
    }
    return rgl_pixels_put(s, format, type, w, h, pixels, false);
}

/* GLU reads client memory itself, checking first what gluBuild2DMipmaps
 * documents: sizes of at least 1, the formats and types of GL 1.2. */
static bool glu_pixels_ok(GLsizei w, GLsizei h, GLenum format, GLenum type)
{
    if (w < 1 || h < 1 || format == GL_STENCIL_INDEX || format == GL_RG ||
        format == GL_DEPTH_STENCIL || (format >= GL_RED_INTEGER && format <= GL_BGRA_INTEGER) ||
        format == GL_RG_INTEGER)
        return false;
    switch (type) {
    case GL_HALF_FLOAT: case GL_UNSIGNED_INT_10F_11F_11F_REV: case GL_UNSIGNED_INT_5_9_9_9_REV:
    case GL_UNSIGNED_INT_24_8: case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
        return false;
    default:
        return true;
    }
}

int64_t rgl_glu_pixels(rgl_stream *s, int32_t w, int32_t h, uint32_t format, uint32_t type,
                       const void *data)
{
    if (!glu_pixels_ok(w, h, format, type))
        return RGL_PX_REFUSED;
    return rgl_pixels_put(s, format, type, w, h, data, true);
}

int64_t rgl_tex_check(rgl_stream *s, int dims, bool sub, uint32_t target, int32_t level,
                      int32_t internal, int32_t x, int32_t y, int32_t w, int32_t h,
                      int32_t border)
{
    enum px_status st = tex_check(s, dims, sub, target, level, internal, x, y, w, h, border);
    return st == PX_OK ? RGL_PX_NONE : st == PX_UNKNOWN ? RGL_PX_SKIP_ENUM : RGL_PX_REFUSED;
}

/* GL 1.2's 3D unpack state (GL 2.1 3.8.1): rows of an image, images to skip. */
static void unpack_get3d(GLint *image_height, GLint *skip_images)
{
    *image_height = *skip_images = 0;
    if (!rgl_live_context())
        return; /* without a context, GL's defaults: the recorder keeps only the 2D state */
    glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, image_height);
    glGetIntegerv(GL_UNPACK_SKIP_IMAGES, skip_images);
    if (*image_height < 0)
        *image_height = 0;
    if (*skip_images < 0)
        *skip_images = 0;
}

/* The pixels of a 3D image: d images of h rows, each laid out as
 * rgl_pixels_put reads one, images GL_UNPACK_IMAGE_HEIGHT rows apart (h
 * when 0) after GL_UNPACK_SKIP_IMAGES of them (GL 2.1 3.8.1, figure 3.9). */
static int64_t pixels_put3d(rgl_stream *s, uint32_t format, uint32_t type, int32_t w, int32_t h,
                            int32_t d, const void *pixels)
{
    size_t ps, es;
    enum px_status st = pixel_layout(format, type, &ps, &es);
    if (st != PX_OK)
        return st == PX_UNKNOWN ? RGL_PX_SKIP_ENUM : RGL_PX_REFUSED;
    if (ps == 0 || w < 0 || h < 0 || d < 0)
        return RGL_PX_REFUSED;
    if (rgl_buffer_binding(s, GL_PIXEL_UNPACK_BUFFER))
        return pixels ? RGL_PX_SKIP_DATA : RGL_PX_NONE; /* read from a buffer: not recorded */
    if (!pixels || w == 0 || h == 0 || d == 0)
        return RGL_PX_NONE;
    GLint u[UP_COUNT], ih, si;
    unpack_get(s, u);
    unpack_get3d(&ih, &si);
    px_span sp;
    uint64_t istride, start;
    if (!pixel_span(u, ps, (uint64_t)w, &sp) ||
        __builtin_mul_overflow((uint64_t)(ih > 0 ? ih : h), sp.stride, &istride) ||
        __builtin_mul_overflow((uint64_t)si, istride, &start) ||
        __builtin_add_overflow(start, sp.start, &start))
        return RGL_PX_REFUSED;
    if (sp.row > RGL_CHUNK_MAX_PAYLOAD / (size_t)h / (size_t)d) {
        rgl_fail(EFBIG, "a texture image is larger than a chunk can hold");
        return RGL_PX_REFUSED;
    }
    size_t total = sp.row * (size_t)h * (size_t)d;
    uint8_t *tmp = rgl_alloc(total);
    if (!tmp) {
        rgl_fail(ENOMEM, "allocation failed");
        return RGL_PX_REFUSED;
    }
    const uint8_t *src = (const uint8_t *)pixels + start;
    for (size_t z = 0; z < (size_t)d; z++)
        for (size_t y = 0; y < (size_t)h; y++)
            memcpy(tmp + (z * (size_t)h + y) * sp.row, src + z * istride + y * sp.stride, sp.row);
    if (u[UP_SWAP] && es > 1)
        bytes_swap(tmp, total, es);
    uint32_t id = rgl_resource_put(RGL_RES_BYTES, tmp, total);
    rgl_free(tmp);
    return id ? (int64_t)id : RGL_PX_REFUSED;
}

int64_t rgl_tex_pixels3d(rgl_stream *s, bool sub, uint32_t target, int32_t level,
                         int32_t internal, int32_t x, int32_t y, int32_t z, int32_t w, int32_t h,
                         int32_t d, int32_t border, uint32_t format, uint32_t type,
                         const void *pixels)
{
    int64_t r = rgl_tex_check3d(s, sub, target, level, internal, x, y, z, w, h, d, border);
    if (r != RGL_PX_NONE)
        return r;
    if (rgl_tex_is_proxy(target)) {
        size_t ps, es;
        enum px_status st = pixel_layout(format, type, &ps, &es);
        return st == PX_OK ? RGL_PX_NONE : st == PX_UNKNOWN ? RGL_PX_SKIP_ENUM : RGL_PX_REFUSED;
    }
    return pixels_put3d(s, format, type, w, h, d, pixels);
}

int64_t rgl_tex_check3d(rgl_stream *s, bool sub, uint32_t target, int32_t level,
                        int32_t internal, int32_t x, int32_t y, int32_t z, int32_t w, int32_t h,
                        int32_t d, int32_t border)
{
    if (d < 0 || (!sub && d < 2 * border))
        return RGL_PX_REFUSED;
    int64_t r = rgl_tex_check(s, 3, sub, target, level, internal, x, y, w, h, border);
    if (r != RGL_PX_NONE || !rgl_live_context() || target != GL_TEXTURE_3D)
        return r;
    GLint max = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max);
    if (max > 0 && !sub && (w - 2 * border > max || h - 2 * border > max || d - 2 * border > max))
        return RGL_PX_REFUSED;
    if (sub) {
        GLint tw = 0, th = 0, td = 0, tb = 0;
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &tw);
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &th);
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_DEPTH, &td);
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_BORDER, &tb);
        if ((int64_t)x < -tb || (int64_t)x + w > (int64_t)tw - tb || (int64_t)y < -tb ||
            (int64_t)y + h > (int64_t)th - tb || (int64_t)z < -tb ||
            (int64_t)z + d > (int64_t)td - tb)
            return RGL_PX_REFUSED;
    }
    return RGL_PX_NONE;
}

