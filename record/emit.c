/* emit.c: records the recorder writes itself: @Matrix, the modelview and
 * projection read back before a draw (docs/design.md "Resolved
 * matrices"), and the encoder of the hand-written entry points' records
 * (rgl_emit, rgl_record: a format string of argument kinds, recorder.h).
 * Everything goes through the stream API of recorder.h.
 */
#include <stdarg.h>
#include <stdint.h>
#include <string.h>

#include <GL/gl.h>

#include "recorder.h"

/* @Matrix: opcode, mode, 16 floats. */
#define RGL_MATRIX_RECORD_MAX (2 + RGL_WMAX_e + 16 * RGL_WMAX_f)

void rgl_resolve_matrices(void)
{
    rgl_stream *s;
    uint8_t *p = rgl_reserve(&s, 2 * RGL_MATRIX_RECORD_MAX);
    /* glGet between glBegin and glEnd is a GL error (a glCallList there);
     * the primitive's matrices were read at its glBegin. */
    if (!p || s->compiling || s->in_begin)
        return;
    static const GLenum pnames[2] = {GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX};
    static const GLenum modes[2] = {GL_MODELVIEW, GL_PROJECTION};
    for (int k = 0; k < 2; k++) {
        /* A NaN sentinel: GL with no current context leaves it untouched. */
        float m[16];
        for (int j = 0; j < 16; j++)
            m[j] = rgl_bits_f32(0x7fc0dead);
        glGetFloatv(pnames[k], m);
        if (rgl_f32_bits(m[0]) == 0x7fc0dead)
            return;
        if (s->have_matrix[k] && memcmp(m, s->matrix[k], sizeof m) == 0)
            continue;
        memcpy(s->matrix[k], m, sizeof m);
        s->have_matrix[k] = true;
        p = rgl_put_opcode(p, RGL_OP_Matrix);
        p = rgl_put_e(p, modes[k]);
        for (int j = 0; j < 16; j++)
            p = rgl_put_f(p, m[j]);
    }
    rgl_commit(s, p);
}

/* ---- Hand-written records -------------------------------------------------- */

static size_t emit_size(const char *fmt, va_list ap)
{
    size_t n = 2 * RGL_VARINT32_MAX;
    for (const char *c = fmt; *c; c++) {
        switch (*c) {
        case 'e': case 'i': (void)va_arg(ap, uint32_t); n += RGL_VARINT32_MAX; break;
        case 'f': (void)va_arg(ap, double); n += 4; break;
        case 'd': (void)va_arg(ap, double); n += 8; break;
        case 'o': (void)va_arg(ap, int); n += 1; break;
        case 'q': (void)va_arg(ap, int64_t); n += RGL_VARINT64_MAX; break;
        case 'A': case 'N': case 'I': case 'U':
            (void)va_arg(ap, const void *);
            n += RGL_VARINT32_MAX + (size_t)va_arg(ap, int) * RGL_VARINT32_MAX;
            break;
        case 'B': {
            (void)va_arg(ap, const void *);
            n += RGL_VARINT64_MAX + va_arg(ap, size_t);
            break;
        }
        case 'S': n += RGL_VARINT32_MAX + strnlen(va_arg(ap, const char *), RGL_STRING_MAX); break;
        default: break;
        }
    }
    return n;
}

static uint8_t *emit_put(uint8_t *p, uint32_t op, const char *fmt, va_list ap)
{
    p = rgl_put_opcode(p, op);
    for (const char *c = fmt; *c; c++) {
        switch (*c) {
        case 'e': p = rgl_put_varint(p, va_arg(ap, uint32_t)); break;
        case 'i': p = rgl_put_i(p, va_arg(ap, int32_t)); break;
        case 'f': p = rgl_put_f(p, (float)va_arg(ap, double)); break;
        case 'd': p = rgl_put_d(p, va_arg(ap, double)); break;
        case 'o': p = rgl_put_bo(p, (uint8_t)va_arg(ap, int)); break;
        case 'q': p = rgl_put_ip(p, va_arg(ap, int64_t)); break;
        case 'A': case 'N': {
            const float *v = va_arg(ap, const float *);
            int n = va_arg(ap, int);
            if (*c == 'N')
                p = rgl_put_varint(p, (uint32_t)n);
            for (int k = 0; k < n; k++)
                p = rgl_put_f(p, v[k]);
            break;
        }
        case 'I': {
            const GLint *v = va_arg(ap, const GLint *);
            int n = va_arg(ap, int);
            p = rgl_put_varint(p, (uint32_t)n);
            for (int k = 0; k < n; k++)
                p = rgl_put_i(p, v[k]);
            break;
        }
        case 'U': {
            const GLuint *v = va_arg(ap, const GLuint *);
            int n = va_arg(ap, int);
            p = rgl_put_varint(p, (uint32_t)n);
            for (int k = 0; k < n; k++)
                p = rgl_put_ui(p, v[k]);
            break;
        }
        case 'B': {
            const void *v = va_arg(ap, const void *);
            size_t n = va_arg(ap, size_t);
            p = rgl_put_varint(p, n);
            if (n)
                memcpy(p, v, n);
            p += n;
            break;
        }
        case 'S': {
            const char *v = va_arg(ap, const char *);
            size_t n = strnlen(v, RGL_STRING_MAX);
            p = rgl_put_varint(p, n);
            memcpy(p, v, n);
            p += n;
            break;
        }
        default: break;
        }
    }
    return p;
}

bool rgl_emit(rgl_buf *b, uint32_t op, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    size_t n = emit_size(fmt, ap);
    va_end(ap);
    uint8_t *p = rgl_buf_reserve(b, n);
    if (!p)
        return false;
    va_start(ap, fmt);
    p = emit_put(p, op, fmt, ap);
    va_end(ap);
    rgl_buf_commit(b, p);
    return true;
}

bool rgl_record(uint32_t op, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    size_t n = emit_size(fmt, ap);
    va_end(ap);
    rgl_stream *s;
    uint8_t *p = rgl_reserve(&s, n);
    if (!p)
        return false;
    va_start(ap, fmt);
    p = emit_put(p, op, fmt, ap);
    va_end(ap);
    rgl_commit(s, p);
    return true;
}
