/* unrecorded.c: the slow path and the frame-end flush of the counts of
 * unrecorded calls (unrecorded.h). */
#include "unrecorded.h"

#include <GL/gl.h>
#include <stdint.h>

void rgl_unrecorded_slow(unsigned id)
{
    if (rgl_tls_passthrough > 0)
        return;
    rgl_stream *s = rgl_stream_current();
    if (s && s->unrecorded)
        s->unrecorded[id]++;
}

void rgl_unrecorded_count_state(unsigned id, unsigned pname, int value)
{
    rgl_stream *s = rgl_tls_stream;
    if (rgl_tls_passthrough == 0 && !(s && s->in_begin)) {
        /* GL without a current context leaves the sentinel (as
         * rgl_live_context asks). */
        const GLint sentinel = (GLint)0x7eadbeef;
        GLint cur = sentinel;
        glGetIntegerv((GLenum)pname, &cur);
        if (cur != sentinel && cur == value)
            return;
    }
    rgl_unrecorded_count(id);
}

void rgl_unrecorded_flush(rgl_stream *s, rgl_buf *b)
{
    if (!s->unrecorded)
        return;
    for (unsigned i = 0; i < rgl_unrecorded_total; i++) {
        uint64_t n = s->unrecorded[i];
        s->unrecorded[i] = 0;
        /* The wire count is 32 bits: a larger one takes several records,
         * which readers add up. */
        while (n > 0) {
            uint32_t part = n > UINT32_MAX ? UINT32_MAX : (uint32_t)n;
            n -= part;
            bool ok = b ? rgl_emit(b, RGL_OP_NotRecorded, "Se", rgl_unrecorded_names[i], part)
                        : rgl_record(RGL_OP_NotRecorded, "Se", rgl_unrecorded_names[i], part);
            if (!ok)
                return;
        }
    }
}
