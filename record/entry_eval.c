/* entry_eval.c: the recorder entry points of glMap1 and glMap2 (rows with
 * gen CUSTOM in format/commands.def; the other evaluator calls are
 * generated).
 *
 * A map's control points sit in client memory at a stride the table cannot
 * express. GL reads `order` points of k values each (k fixed by the target),
 * point i at points + i * stride; glMap2 reads uorder x vorder points, point
 * (i, j) at points + i * ustride + j * vstride (GL 1.x section 5.1). Exactly
 * those values are copied into the record, packed, u major. A call GL
 * rejects (bad target, order outside 1..GL_MAX_EVAL_ORDER, u1 == u2, a
 * stride below k, inside glBegin/glEnd) or a NULL pointer is forwarded
 * without reading the points or recording anything, as the map then keeps
 * its previous definition.
 */
#include <GL/gl.h>

#include "raygl.h"
#include "recorder.h"

/* k, or 0 when GL rejects the one-dimensional part (u1, u2, stride, order)
 * of a map of dimension `two` (0: glMap1, 1: glMap2). */
static uint32_t map_check(GLenum target, bool want_two, double u1, double u2, GLint stride,
                          GLint order)
{
    bool two;
    uint32_t k = rgl_map_components(target, &two);
    if (k == 0 || two != want_two || order < 1 || order > RGL_MAX_EVAL_ORDER || u1 == u2 ||
        stride < (GLint)k)
        return 0;
    return k;
}

/* Whether GL executes the call now and rejects it between glBegin and glEnd. */
static bool map_in_begin(void)
{
    const rgl_stream *s = rgl_tls_stream;
    return s && s->in_begin && (!s->compiling || s->list_mode == GL_COMPILE_AND_EXECUTE);
}

/* The fixed arguments' worst-case size: opcode, enum, up to 4 domain
 * values (doubles), 4 ints, the blob's length. */
#define MAP_FIXED (2 + RGL_WMAX_e + 4 * RGL_WMAX_d + 4 * RGL_WMAX_i + RGL_VARINT32_MAX)

RGL_EXPORT void rayglMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                           const GLfloat *points)
{
    uint32_t k = map_check(target, false, u1, u2, stride, order);
    if (k && points && !map_in_begin()) {
        size_t n = (size_t)order * k;
        rgl_stream *s;
        uint8_t *p = rgl_reserve(&s, MAP_FIXED + n * 4);
        if (p) {
            p = rgl_put_opcode(p, RGL_OP_Map1f);
            p = rgl_put_e(p, target);
            p = rgl_put_f(p, u1);
            p = rgl_put_f(p, u2);
            p = rgl_put_i(p, stride);
            p = rgl_put_i(p, order);
            p = rgl_put_varint(p, n * 4);
            for (GLint i = 0; i < order; i++)
                for (uint32_t c = 0; c < k; c++)
                    p = rgl_put_f(p, points[(size_t)i * (size_t)stride + c]);
            rgl_commit(s, p);
        }
    }
    glMap1f(target, u1, u2, stride, order, points);
}

RGL_EXPORT void rayglMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                           const GLdouble *points)
{
    uint32_t k = map_check(target, false, u1, u2, stride, order);
    if (k && points && !map_in_begin()) {
        size_t n = (size_t)order * k;
        rgl_stream *s;
        uint8_t *p = rgl_reserve(&s, MAP_FIXED + n * 8);
        if (p) {
            p = rgl_put_opcode(p, RGL_OP_Map1d);
            p = rgl_put_e(p, target);
            p = rgl_put_d(p, u1);
            p = rgl_put_d(p, u2);
            p = rgl_put_i(p, stride);
            p = rgl_put_i(p, order);
            p = rgl_put_varint(p, n * 8);
            for (GLint i = 0; i < order; i++)
                for (uint32_t c = 0; c < k; c++)
                    p = rgl_put_d(p, points[(size_t)i * (size_t)stride + c]);
            rgl_commit(s, p);
        }
    }
    glMap1d(target, u1, u2, stride, order, points);
}

RGL_EXPORT void rayglMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
                           GLfloat v1, GLfloat v2, GLint vstride, GLint vorder,
                           const GLfloat *points)
{
    uint32_t k = map_check(target, true, u1, u2, ustride, uorder);
    if (k && map_check(target, true, v1, v2, vstride, vorder) && points && !map_in_begin()) {
        size_t n = (size_t)uorder * (size_t)vorder * k;
        rgl_stream *s;
        uint8_t *p = rgl_reserve(&s, MAP_FIXED + n * 4);
        if (p) {
            p = rgl_put_opcode(p, RGL_OP_Map2f);
            p = rgl_put_e(p, target);
            p = rgl_put_f(p, u1);
            p = rgl_put_f(p, u2);
            p = rgl_put_i(p, ustride);
            p = rgl_put_i(p, uorder);
            p = rgl_put_f(p, v1);
            p = rgl_put_f(p, v2);
            p = rgl_put_i(p, vstride);
            p = rgl_put_i(p, vorder);
            p = rgl_put_varint(p, n * 4);
            for (GLint i = 0; i < uorder; i++)
                for (GLint j = 0; j < vorder; j++)
                    for (uint32_t c = 0; c < k; c++)
                        p = rgl_put_f(p, points[(size_t)i * (size_t)ustride +
                                                (size_t)j * (size_t)vstride + c]);
            rgl_commit(s, p);
        }
    }
    glMap2f(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

RGL_EXPORT void rayglMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                           GLdouble v1, GLdouble v2, GLint vstride, GLint vorder,
                           const GLdouble *points)
{
    uint32_t k = map_check(target, true, u1, u2, ustride, uorder);
    if (k && map_check(target, true, v1, v2, vstride, vorder) && points && !map_in_begin()) {
        size_t n = (size_t)uorder * (size_t)vorder * k;
        rgl_stream *s;
        uint8_t *p = rgl_reserve(&s, MAP_FIXED + n * 8);
        if (p) {
            p = rgl_put_opcode(p, RGL_OP_Map2d);
            p = rgl_put_e(p, target);
            p = rgl_put_d(p, u1);
            p = rgl_put_d(p, u2);
            p = rgl_put_i(p, ustride);
            p = rgl_put_i(p, uorder);
            p = rgl_put_d(p, v1);
            p = rgl_put_d(p, v2);
            p = rgl_put_i(p, vstride);
            p = rgl_put_i(p, vorder);
            p = rgl_put_varint(p, n * 8);
            for (GLint i = 0; i < uorder; i++)
                for (GLint j = 0; j < vorder; j++)
                    for (uint32_t c = 0; c < k; c++)
                        p = rgl_put_d(p, points[(size_t)i * (size_t)ustride +
                                                (size_t)j * (size_t)vstride + c]);
            rgl_commit(s, p);
        }
    }
    glMap2d(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
