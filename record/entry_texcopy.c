/* entry_texcopy.c: the recorder entry points of glCopyTexImage1D/2D,
 * glCopyTexSubImage1D/2D/3D (render to texture) and glTexImage3D,
 * glTexSubImage3D (rows with gen CUSTOM in format/commands.def).
 *
 * A copy reads no client memory: what it copies is the framebuffer's,
 * which a trace does not hold, so the source rectangle is read back
 * (rgl_read_rgba, as for glCopyPixels) before GL copies it, when a context
 * is current and the call executes now; the record carries it as an 8-bit
 * RGBA resource, 0 when it could not be read. A call GL rejects (checked as
 * glTexImage is, pixels.c) reads nothing and is not recorded. The 3D
 * images are read by pixels.c's rules like the 2D ones.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include "raygl.h"
#include "recorder.h"

/* Room for one record, so that it stays where rgl_record wrote it. */
#define TEXCOPY_RECORD_ROOM 128

/* GL executes the call now, not only compiles it into a list. */
static bool copy_executes(const rgl_stream *s)
{
    return !s->compiling || s->list_mode == GL_COMPILE_AND_EXECUTE;
}

/* Depth and stencil images copy the depth buffer, which rgl_read_rgba does
 * not read: such a copy carries no pixels. */
static bool copies_colour(int32_t internal)
{
    switch (internal) {
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32: case GL_DEPTH_STENCIL: case GL_DEPTH24_STENCIL8:
    case GL_DEPTH_COMPONENT32F: case GL_DEPTH32F_STENCIL8:
        return false;
    default:
        return true;
    }
}

/* The w x h rectangle at (x, y) of the read buffer as an RGBA resource, or
 * 0 when it cannot be read now. */
static uint32_t copy_read(rgl_stream *s, int32_t x, int32_t y, int32_t w, int32_t h)
{
    if (!copy_executes(s) || w <= 0 || h <= 0 ||
        (size_t)w > RGL_CHUNK_MAX_PAYLOAD / 4 / (size_t)h)
        return 0;
    size_t n = (size_t)w * (size_t)h * 4;
    uint8_t *px = rgl_alloc(n);
    uint32_t id = 0;
    if (!px)
        rgl_fail(0, "allocation failed (glCopyTexImage)");
    else if (rgl_read_rgba(x, y, w, h, px))
        id = rgl_resource_put(RGL_RES_BYTES, px, n);
    rgl_free(px);
    return id;
}

static void copy_teximage1d(uint32_t op, GLenum target, GLint level, GLenum internalformat, GLint x,
                            GLint y, GLsizei width, GLint border)
{
    rgl_stream *s;
    const uint8_t *from = NULL;
    if (rgl_reserve(&s, 1)) {
        int64_t r = rgl_tex_check(s, 1, false, target, level, (int32_t)internalformat, 0, 0,
                                  width, 1, border);
        rgl_note_skipped(op, r);
        if (r == RGL_PX_NONE && !rgl_tex_is_proxy(target)) {
            uint32_t id = copies_colour((int32_t)internalformat) ? copy_read(s, x, y, width, 1) : 0;
            if (rgl_reserve(&s, TEXCOPY_RECORD_ROOM)) {
                from = s->pos;
                if (!rgl_record(op, "eiiiiiie", target, level,
                                (int32_t)internalformat, x, y, width, border, id))
                    from = NULL;
            }
        }
    }
    glCopyTexImage1D(target, level, internalformat, x, y, width, border);
    if (from)
        rgl_texture_defined(s, target, from, level == 0);
}

static void copy_teximage2d(uint32_t op, GLenum target, GLint level, GLenum internalformat, GLint x,
                            GLint y, GLsizei width, GLsizei height, GLint border)
{
    rgl_stream *s;
    const uint8_t *from = NULL;
    if (rgl_reserve(&s, 1)) {
        int64_t r = rgl_tex_check(s, 2, false, target, level, (int32_t)internalformat, 0, 0,
                                  width, height, border);
        rgl_note_skipped(op, r);
        if (r == RGL_PX_NONE && !rgl_tex_is_proxy(target)) {
            uint32_t id =
                copies_colour((int32_t)internalformat) ? copy_read(s, x, y, width, height) : 0;
            if (rgl_reserve(&s, TEXCOPY_RECORD_ROOM)) {
                from = s->pos;
                if (!rgl_record(op, "eiiiiiiie", target, level,
                                (int32_t)internalformat, x, y, width, height, border, id))
                    from = NULL;
            }
        }
    }
    glCopyTexImage2D(target, level, internalformat, x, y, width, height, border);
    if (from)
        rgl_texture_defined(s, target, from, level == 0);
}

static void copy_texsubimage1d(uint32_t op, GLenum target, GLint level, GLint xoffset, GLint x,
                               GLint y, GLsizei width)
{
    rgl_stream *s;
    const uint8_t *from = NULL;
    if (rgl_reserve(&s, 1)) {
        int64_t r = rgl_tex_check(s, 1, true, target, level, 0, xoffset, 0, width, 1, 0);
        rgl_note_skipped(op, r);
        if (r == RGL_PX_NONE) {
            uint32_t id = copy_read(s, x, y, width, 1);
            if (rgl_reserve(&s, TEXCOPY_RECORD_ROOM)) {
                from = s->pos;
                if (!rgl_record(op, "eiiiiie", target, level, xoffset, x,
                                y, width, id))
                    from = NULL;
            }
        }
    }
    glCopyTexSubImage1D(target, level, xoffset, x, y, width);
    if (from)
        rgl_texture_defined(s, target, from, false);
}

static void copy_texsubimage2d(uint32_t op, GLenum target, GLint level, GLint xoffset,
                               GLint yoffset, GLint x, GLint y, GLsizei width, GLsizei height)
{
    rgl_stream *s;
    const uint8_t *from = NULL;
    if (rgl_reserve(&s, 1)) {
        int64_t r =
            rgl_tex_check(s, 2, true, target, level, 0, xoffset, yoffset, width, height, 0);
        rgl_note_skipped(op, r);
        if (r == RGL_PX_NONE) {
            uint32_t id = copy_read(s, x, y, width, height);
            if (rgl_reserve(&s, TEXCOPY_RECORD_ROOM)) {
                from = s->pos;
                if (!rgl_record(op, "eiiiiiiie", target, level, xoffset,
                                yoffset, x, y, width, height, id))
                    from = NULL;
            }
        }
    }
    glCopyTexSubImage2D(target, level, xoffset, yoffset, x, y, width, height);
    if (from)
        rgl_texture_defined(s, target, from, false);
}

static void copy_texsubimage3d(uint32_t op, GLenum target, GLint level, GLint xoffset,
                               GLint yoffset, GLint zoffset, GLint x, GLint y, GLsizei width,
                               GLsizei height)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1)) {
        int64_t r = rgl_tex_check3d(s, true, target, level, 0, xoffset, yoffset, zoffset, width,
                                    height, 1, 0);
        rgl_note_skipped(op, r);
        if (r == RGL_PX_NONE) {
            uint32_t id = copy_read(s, x, y, width, height);
            rgl_record(op, "eiiiiiiiie", target, level, xoffset, yoffset,
                       zoffset, x, y, width, height, id);
        }
    }
    glCopyTexSubImage3D(target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

static void tex_image3d(uint32_t op, GLenum target, GLint level, GLint internalFormat,
                        GLsizei width, GLsizei height, GLsizei depth, GLint border, GLenum format,
                        GLenum type, const GLvoid *pixels)
{
    rgl_stream *s;
    const uint8_t *from = NULL;
    if (rgl_reserve(&s, 1)) {
        int64_t id = rgl_tex_pixels3d(s, false, target, level, internalFormat, 0, 0, 0, width,
                                      height, depth, border, format, type, pixels);
        rgl_note_skipped(op, id);
        /* Kept as the texture's definition for the snapshot (snaptex.c). */
        if (id >= 0 && rgl_reserve(&s, TEXCOPY_RECORD_ROOM)) {
            from = s->pos;
            if (!rgl_record(op, "eiiiiiieee", target, level, internalFormat,
                            width, height, depth, border, format, type, (uint32_t)id))
                from = NULL;
        }
    }
    glTexImage3D(target, level, internalFormat, width, height, depth, border, format, type,
                 pixels);
    if (from)
        rgl_texture_defined(s, target, from, level == 0);
}

static void tex_subimage3d(uint32_t op, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                           GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                           GLenum format, GLenum type, const GLvoid *pixels)
{
    rgl_stream *s;
    const uint8_t *from = NULL;
    if (rgl_reserve(&s, 1)) {
        int64_t id = rgl_tex_pixels3d(s, true, target, level, 0, xoffset, yoffset, zoffset, width,
                                      height, depth, 0, format, type, pixels);
        rgl_note_skipped(op, id);
        if (id > 0 && rgl_reserve(&s, TEXCOPY_RECORD_ROOM)) {
            from = s->pos;
            if (!rgl_record(op, "eiiiiiiieee", target, level, xoffset,
                            yoffset, zoffset, width, height, depth, format, type, (uint32_t)id))
                from = NULL;
        }
    }
    glTexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format,
                    type, pixels);
    if (from)
        rgl_texture_defined(s, target, from, false);
}

/* The core names and their EXT twins (rows of their own). Both forward to
 * the core function, which gl.xml makes the same: libOSMesa exports no
 * glCopyTexImage*EXT. */
RGL_EXPORT void rayglCopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x,
                                    GLint y, GLsizei width, GLint border)
{
    copy_teximage1d(RGL_OP_CopyTexImage1D, target, level, internalformat, x, y, width, border);
}

RGL_EXPORT void rayglCopyTexImage1DEXT(GLenum target, GLint level, GLenum internalformat, GLint x,
                                       GLint y, GLsizei width, GLint border)
{
    copy_teximage1d(RGL_OP_CopyTexImage1DEXT, target, level, internalformat, x, y, width,
                    border);
}

RGL_EXPORT void rayglCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x,
                                    GLint y, GLsizei width, GLsizei height, GLint border)
{
    copy_teximage2d(RGL_OP_CopyTexImage2D, target, level, internalformat, x, y, width, height,
                    border);
}

RGL_EXPORT void rayglCopyTexImage2DEXT(GLenum target, GLint level, GLenum internalformat, GLint x,
                                       GLint y, GLsizei width, GLsizei height, GLint border)
{
    copy_teximage2d(RGL_OP_CopyTexImage2DEXT, target, level, internalformat, x, y, width,
                    height, border);
}

RGL_EXPORT void rayglCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x,
                                       GLint y, GLsizei width)
{
    copy_texsubimage1d(RGL_OP_CopyTexSubImage1D, target, level, xoffset, x, y, width);
}

RGL_EXPORT void rayglCopyTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLint x,
                                          GLint y, GLsizei width)
{
    copy_texsubimage1d(RGL_OP_CopyTexSubImage1DEXT, target, level, xoffset, x, y, width);
}

RGL_EXPORT void rayglCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                       GLint x, GLint y, GLsizei width, GLsizei height)
{
    copy_texsubimage2d(RGL_OP_CopyTexSubImage2D, target, level, xoffset, yoffset, x, y, width,
                       height);
}

RGL_EXPORT void rayglCopyTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset,
                                          GLint yoffset, GLint x, GLint y, GLsizei width,
                                          GLsizei height)
{
    copy_texsubimage2d(RGL_OP_CopyTexSubImage2DEXT, target, level, xoffset, yoffset, x, y,
                       width, height);
}

RGL_EXPORT void rayglCopyTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                       GLint zoffset, GLint x, GLint y, GLsizei width,
                                       GLsizei height)
{
    copy_texsubimage3d(RGL_OP_CopyTexSubImage3D, target, level, xoffset, yoffset, zoffset, x, y,
                       width, height);
}

RGL_EXPORT void rayglCopyTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset,
                                          GLint yoffset, GLint zoffset, GLint x, GLint y,
                                          GLsizei width, GLsizei height)
{
    copy_texsubimage3d(RGL_OP_CopyTexSubImage3DEXT, target, level, xoffset, yoffset, zoffset, x,
                       y, width, height);
}

RGL_EXPORT void rayglTexImage3D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                                GLsizei height, GLsizei depth, GLint border, GLenum format,
                                GLenum type, const GLvoid *pixels)
{
    tex_image3d(RGL_OP_TexImage3D, target, level, internalFormat, width, height, depth, border,
                format, type, pixels);
}

RGL_EXPORT void rayglTexImage3DEXT(GLenum target, GLint level, GLenum internalformat,
                                   GLsizei width, GLsizei height, GLsizei depth, GLint border,
                                   GLenum format, GLenum type, const void *pixels)
{
    tex_image3d(RGL_OP_TexImage3DEXT, target, level, (GLint)internalformat, width, height, depth,
                border, format, type, pixels);
}

RGL_EXPORT void rayglTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                   GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                   GLenum format, GLenum type, const GLvoid *pixels)
{
    tex_subimage3d(RGL_OP_TexSubImage3D, target, level, xoffset, yoffset, zoffset, width, height,
                   depth, format, type, pixels);
}

RGL_EXPORT void rayglTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                      GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                      GLenum format, GLenum type, const void *pixels)
{
    tex_subimage3d(RGL_OP_TexSubImage3DEXT, target, level, xoffset, yoffset, zoffset, width,
                   height, depth, format, type, pixels);
}
