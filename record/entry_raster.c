/* entry_raster.c: the recorder entry points of glBitmap, glDrawPixels and
 * glCopyPixels (rows with gen CUSTOM in format/commands.def; glRasterPos,
 * glWindowPos, glPixelZoom and glPixelTransfer are generated).
 *
 * glBitmap and glDrawPixels read client memory (or the unpack buffer) as
 * the unpack state says: pixels.c's rgl_pixels_put reads exactly that. A
 * call GL rejects (a negative size, inside glBegin/glEnd, a bad format or
 * type) reads nothing and is not recorded. glCopyPixels reads no client
 * memory: what it copies is the framebuffer's, which a trace does not
 * hold, so the source rectangle is read back (rgl_read_rgba) before GL
 * copies over it, when a context is current and the call executes now.
 */
#include <GL/gl.h>
#include <string.h>

#include "raygl.h"
#include "recorder.h"

/* GL executes the call now (not only compiles it) and rejects it between
 * glBegin and glEnd (GL 2.1 2.6.3). */
static bool raster_in_begin(const rgl_stream *s)
{
    return s->in_begin && (!s->compiling || s->list_mode == GL_COMPILE_AND_EXECUTE);
}

RGL_EXPORT void rayglBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig,
                            GLfloat xmove, GLfloat ymove, const GLubyte *bitmap)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1) && !raster_in_begin(s) && width >= 0 && height >= 0) {
        int64_t id = rgl_pixels_put(s, GL_COLOR_INDEX, GL_BITMAP, width, height, bitmap, false);
        rgl_note_skipped(RGL_OP_Bitmap, id);
        if (id >= 0)
            rgl_record(RGL_OP_Bitmap, "iiffffe", width, height, (double)xorig, (double)yorig,
                       (double)xmove, (double)ymove, (uint32_t)id);
    }
    glBitmap(width, height, xorig, yorig, xmove, ymove, bitmap);
}

RGL_EXPORT void rayglDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type,
                                const GLvoid *pixels)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1) && !raster_in_begin(s) && width >= 0 && height >= 0) {
        int64_t id = rgl_pixels_put(s, format, type, width, height, pixels, false);
        rgl_note_skipped(RGL_OP_DrawPixels, id);
        if (id >= 0)
            rgl_record(RGL_OP_DrawPixels, "iieee", width, height, format, type, (uint32_t)id);
    }
    glDrawPixels(width, height, format, type, pixels);
}

RGL_EXPORT void rayglCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type)
{
    rgl_stream *s;
    bool type_ok = type == GL_COLOR || type == GL_DEPTH || type == GL_STENCIL;
    if (rgl_reserve(&s, 1) && !raster_in_begin(s) && width >= 0 && height >= 0 && type_ok) {
        uint32_t id = 0;
        /* Compiled only (GL_COMPILE): the list copies what is there when it
         * runs, which the recorder cannot see now. */
        bool now = !s->compiling || s->list_mode == GL_COMPILE_AND_EXECUTE;
        if (type == GL_COLOR && now && width > 0 && height > 0 &&
            (size_t)width <= RGL_CHUNK_MAX_PAYLOAD / 4 / (size_t)height) {
            size_t n = (size_t)width * (size_t)height * 4;
            uint8_t *px = rgl_alloc(n);
            if (!px)
                rgl_fail(0, "allocation failed (glCopyPixels)");
            else if (rgl_read_rgba(x, y, width, height, px))
                id = rgl_resource_put(RGL_RES_BYTES, px, n);
            rgl_free(px);
        }
        if (type == GL_COLOR && id == 0 && width > 0 && height > 0)
            rgl_record(RGL_OP_Skipped, "ee", (uint32_t)RGL_OP_CopyPixels,
                       (uint32_t)RGL_SKIP_NO_DATA);
        else
            rgl_record(RGL_OP_CopyPixels, "iiiiee", x, y, width, height, type, id);
    }
    glCopyPixels(x, y, width, height, type);
}

/* The 32 x 32 mask is read under the unpack state as glBitmap's is (GL 2.1
 * 3.6.4); GL rejects the call only between glBegin and glEnd. */
RGL_EXPORT void rayglPolygonStipple(const GLubyte *mask)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1) && !raster_in_begin(s)) {
        int64_t id = rgl_pixels_put(s, GL_COLOR_INDEX, GL_BITMAP, 32, 32, mask, false);
        rgl_note_skipped(RGL_OP_PolygonStipple, id);
        if (id >= 0)
            rgl_record(RGL_OP_PolygonStipple, "e", (uint32_t)id);
    }
    glPolygonStipple(mask);
}

/* GL 2.1 3.6.3: the maps GL knows, with 1 to GL_MAX_PIXEL_MAP_TABLE (256
 * in Mesa) entries, a power of two for those indexed by an index. */
static bool pixel_map_ok(GLenum map, GLsizei size)
{
    if (map < GL_PIXEL_MAP_I_TO_I || map > GL_PIXEL_MAP_A_TO_A || size < 1 || size > 256)
        return false;
    bool indexed = map <= GL_PIXEL_MAP_I_TO_A;
    return !indexed || (size & (size - 1)) == 0;
}

/* Records a pixel map of size elements of es bytes (4: float or unsigned
 * int, 2: unsigned short) as a blob of little-endian values. */
static void pixel_map(uint32_t op, GLenum map, GLsizei size, const void *values, size_t es)
{
    rgl_stream *s;
    if (!rgl_reserve(&s, 1) || raster_in_begin(s) || !pixel_map_ok(map, size))
        return;
    uint8_t raw[256 * 4], le[256 * 4];
    size_t n = (size_t)size * es;
    uint32_t pbo = rgl_buffer_binding(s, GL_PIXEL_UNPACK_BUFFER);
    bool ok;
    if (pbo)
        ok = rgl_buffer_gather(GL_PIXEL_UNPACK_BUFFER, pbo, rgl_buffer_live(), (uintptr_t)values, n,
                               n, 1, raw);
    else
        ok = values && memcpy(raw, values, n);
    if (!ok) {
        rgl_record(RGL_OP_Skipped, "ee", op, (uint32_t)RGL_SKIP_NO_DATA);
        return;
    }
    for (size_t i = 0; i < (size_t)size; i++) {
        if (es == 2) {
            uint16_t v;
            memcpy(&v, raw + i * 2, 2);
            rgl_put_us(le + i * 2, v);
        } else {
            uint32_t v;
            memcpy(&v, raw + i * 4, 4);
            rgl_put_u32(le + i * 4, v);
        }
    }
    rgl_record(op, "eiB", map, size, (const void *)le, n);
}

RGL_EXPORT void rayglPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat *values)
{
    pixel_map(RGL_OP_PixelMapfv, map, mapsize, values, 4);
    glPixelMapfv(map, mapsize, values);
}

RGL_EXPORT void rayglPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint *values)
{
    pixel_map(RGL_OP_PixelMapuiv, map, mapsize, values, 4);
    glPixelMapuiv(map, mapsize, values);
}

RGL_EXPORT void rayglPixelMapusv(GLenum map, GLsizei mapsize, const GLushort *values)
{
    pixel_map(RGL_OP_PixelMapusv, map, mapsize, values, 2);
    glPixelMapusv(map, mapsize, values);
}
