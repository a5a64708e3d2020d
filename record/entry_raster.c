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
