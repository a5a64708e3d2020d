/* entry_select.c: the recorder entry points of glRenderMode, glSelectBuffer
 * and glFeedbackBuffer (rows with gen CUSTOM in format/commands.def; the
 * name-stack calls and glPassThrough are generated).
 *
 * None of the three goes into a display list: GL executes them at once
 * (GL 1.x 5.4), so they are recorded where they are made (RECORD_NOW).
 * The buffers are GL's to write: the recorder keeps their size and type,
 * never reads them. glRenderMode is recorded after GL has answered, with
 * that answer, which the program gets unchanged. A call GL rejects for
 * its enum or inside glBegin/glEnd is forwarded unrecorded; the
 * interpreter checks the rest as GL does (a selection without a buffer).
 */
#include <GL/gl.h>

#include "raygl.h"
#include "recorder.h"

/* Whether GL executes a call now and rejects it between glBegin and glEnd. */
static bool now_in_begin(void)
{
    const rgl_stream *s = rgl_tls_stream;
    return s && s->in_begin && (!s->compiling || s->list_mode == GL_COMPILE_AND_EXECUTE);
}

RGL_EXPORT GLint rayglRenderMode(GLenum mode)
{
    GLint result = glRenderMode(mode);
    rgl_stream *s;
    if ((mode == GL_RENDER || mode == GL_SELECT || mode == GL_FEEDBACK) && !now_in_begin() &&
        rgl_reserve(&s, 1))
        RECORD_NOW(s, RGL_OP_RenderMode, "ei", mode, result);
    return result;
}

RGL_EXPORT void rayglSelectBuffer(GLsizei size, GLuint *buffer)
{
    rgl_stream *s;
    if (size >= 0 && !now_in_begin() && rgl_reserve(&s, 1))
        RECORD_NOW(s, RGL_OP_SelectBuffer, "i", size);
    glSelectBuffer(size, buffer);
}

RGL_EXPORT void rayglFeedbackBuffer(GLsizei size, GLenum type, GLfloat *buffer)
{
    rgl_stream *s;
    bool known = type == GL_2D || type == GL_3D || type == GL_3D_COLOR ||
                 type == GL_3D_COLOR_TEXTURE || type == GL_4D_COLOR_TEXTURE;
    if (known && size >= 0 && !now_in_begin() && rgl_reserve(&s, 1))
        RECORD_NOW(s, RGL_OP_FeedbackBuffer, "ie", size, type);
    glFeedbackBuffer(size, type, buffer);
}
