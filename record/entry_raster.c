/* entry_raster.c: the recorder entry points of glBitmap, glDrawPixels,
 * glCopyPixels and glDrawBuffer (rows with gen CUSTOM in
 * format/commands.def; glRasterPos, glWindowPos, glPixelZoom and
 * glPixelTransfer are generated).
 *
 * glBitmap and glDrawPixels read client memory (or the unpack buffer) as
 * the unpack state says: pixels.c's rgl_pixels_put reads exactly that. A
 * call GL rejects (a negative size, inside glBegin/glEnd, a bad format or
 * type) reads nothing and is not recorded. glCopyPixels reads no client
 * memory: what it copies is the framebuffer's, which a trace does not
 * hold, so the source rectangle is read back (rgl_read_rgba) before GL
 * copies over it, when a context is current and the call executes now.
 */
#include <math.h>

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

/* The window rectangle a glCopyPixels of w x h pixels writes: the pixels
 * whose centres lie in [xr, xr + zx w) x [yr, yr + zy h) (GL 2.1 3.6.5),
 * from the raster position and zoom GL has now. False when the raster
 * position is invalid or the rectangle is empty or over the trace's
 * limits. */
static bool copy_rect(GLsizei w, GLsizei h, GLint r[4])
{
    GLboolean valid = GL_FALSE;
    GLfloat rp[4] = {0, 0, 0, 1}, zx = 1, zy = 1;
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    if (!valid)
        return false;
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    glGetFloatv(GL_ZOOM_X, &zx);
    glGetFloatv(GL_ZOOM_Y, &zy);
    double x0 = rp[0], x1 = rp[0] + (double)zx * w, y0 = rp[1], y1 = rp[1] + (double)zy * h;
    double lo[2] = {x0 < x1 ? x0 : x1, y0 < y1 ? y0 : y1}, hi[2] = {x0 < x1 ? x1 : x0, y0 < y1 ? y1 : y0};
    for (int k = 0; k < 2; k++) {
        double a = ceil(lo[k] - 0.5), b = ceil(hi[k] - 0.5);
        if (!(a >= 0) || !(b <= RGL_SNAPSHOT_SIDE_MAX) || !(b > a))
            return false;
        r[k] = (GLint)a;
        r[k + 2] = (GLint)(b - a);
    }
    return true;
}

/* A logic op (GL_COLOR_LOGIC_OP, not GL_COPY) combines the copy with what
 * is there; the recorder then reads back what GL left. */
static bool logic_op_on(void)
{
    if (!glIsEnabled(GL_COLOR_LOGIC_OP))
        return false;
    GLint op = GL_COPY;
    glGetIntegerv(GL_LOGIC_OP_MODE, &op);
    return op != GL_COPY;
}

RGL_EXPORT void rayglCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type)
{
    rgl_stream *s;
    bool type_ok = type == GL_COLOR || type == GL_DEPTH || type == GL_STENCIL;
    GLint dst[4];
    bool result = false;
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
        /* Not in a list: its result there is the result where it runs. */
        result = id != 0 && !s->compiling && logic_op_on() && copy_rect(width, height, dst) &&
                 (size_t)dst[2] <= RGL_CHUNK_MAX_PAYLOAD / 4 / (size_t)dst[3];
    }
    glCopyPixels(x, y, width, height, type);
    if (!result)
        return;
    size_t n = (size_t)dst[2] * (size_t)dst[3] * 4;
    uint8_t *px = rgl_alloc(n);
    uint32_t id = 0;
    if (!px)
        rgl_fail(0, "allocation failed (glCopyPixels)");
    else if (rgl_read_drawn_rgba(dst[0], dst[1], dst[2], dst[3], px))
        id = rgl_resource_put(RGL_RES_BYTES, px, n);
    rgl_free(px);
    if (id && rgl_reserve(&s, 1))
        rgl_record(RGL_OP_CopyPixelsResult, "iiiie", dst[0], dst[1], dst[2], dst[3], id);
}

/* The context's colour buffers, as DrawBuffer's visual (format.md 3.19):
 * 0 without a context (GL leaves the sentinel). GL_DOUBLEBUFFER and
 * GL_STEREO are in every version and profile. */
uint32_t rgl_draw_visual(void)
{
    GLboolean dbl = 2, stereo = GL_FALSE;
    glGetBooleanv(GL_DOUBLEBUFFER, &dbl);
    if (dbl == 2)
        return 0;
    glGetBooleanv(GL_STEREO, &stereo);
    return 1u | (dbl ? 2u : 0u) | (stereo ? 4u : 0u);
}

/* Recorded as given, before GL takes it: the translator knows GL's rules
 * for the visual (a missing back or right buffer is an error). */
RGL_EXPORT void rayglDrawBuffer(GLenum mode)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1) && !raster_in_begin(s))
        rgl_record(RGL_OP_DrawBuffer, "ee", mode, s->in_begin ? 0u : rgl_draw_visual());
    glDrawBuffer(mode);
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
