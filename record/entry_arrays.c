/* entry_arrays.c: the client-array entry points (rows with gen CUSTOM in
 * format/commands.def): the array pointers, their enables, and the draws
 * that read them (glDrawArrays, glDrawElements, glDrawRangeElements,
 * glArrayElement, glMultiDraw*, glInterleavedArrays).
 *
 * Pointer calls record only the layout; each draw records @ArrayData with
 * the used range of every enabled array, packed, before the draw command.
 * As with every entry point, a call GL would reject or fault on is
 * forwarded unrecorded, and none of its memory is read (docs/design.md,
 * "As safe as GL"); entry_custom.c holds the other hand-written ones.
 */
#include <errno.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <GL/freeglut.h>

#include "raygl.h"
#include "recorder.h"

/* Bytes of one component of a GL data type; 0 for anything else. */
static size_t type_size(GLenum type)
{
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
    }
}

static const GLenum array_enums[RGL_MAX_CLIENT_ARRAYS] = {
    GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY,
    GL_FOG_COORD_ARRAY, GL_SECONDARY_COLOR_ARRAY,
};

static int array_slot(GLenum array)
{
    for (int k = 0; k < RGL_MAX_CLIENT_ARRAYS; k++)
        if (array_enums[k] == array)
            return k;
    return -1;
}

static size_t element_size(const rgl_client_array_state *a)
{
    return (size_t)a->size * type_size(a->type);
}

/* Whether a draw (not glArrayElement) is one GL carries out and RayGL
 * records: outside glBegin/glEnd, a mode of GL 1.x, the vertex array
 * enabled. GL refuses a bad mode (INVALID_ENUM) or a draw inside
 * glBegin/glEnd (INVALID_OPERATION) and reads no element, and without the
 * vertex array it draws nothing. The later modes (lines and triangles with
 * adjacency, patches) are GL's but not RayGL's: @Skipped. */
static bool draw_ok(rgl_stream *s, uint32_t op, GLenum mode)
{
    if (s->in_begin || !s->arrays[RGL_CA_VERTEX].enabled)
        return false;
    if (mode > GL_POLYGON && mode <= GL_PATCHES)
        rgl_note_skipped(op, RGL_PX_SKIP_ENUM);
    return mode <= GL_POLYGON;
}

/* Where array a's element `first` starts and how far its data runs: in
 * client memory, or in the recorder's copy of its buffer (which is then
 * acquired: release it after the copy). False when the elements
 * [first, first+count) are not all inside the buffer (GL would refuse or
 * read past it: the draw goes unrecorded). */
static bool array_source(const rgl_client_array_state *a, int64_t first, int64_t count,
                         const uint8_t **src)
{
    size_t es = element_size(a);
    size_t stride = a->stride ? (size_t)a->stride : es;
    if (!a->buffer) {
        *src = (const uint8_t *)a->pointer + (size_t)first * stride;
        return true;
    }
    size_t size;
    const uint8_t *data = rgl_buffer_acquire(a->buffer, &size);
    uint64_t offset = (uintptr_t)a->pointer;
    uint64_t end = offset + (uint64_t)(first + count - 1) * stride + es;
    if (!data || count <= 0 || end > size) {
        rgl_buffer_release();
        return false;
    }
    *src = data + offset + (size_t)first * stride;
    return true;
}

/* The texture-coordinate array of unit u. */
static const rgl_client_array_state *tc_array(const rgl_stream *s, uint32_t u)
{
    return u == s->client_unit ? &s->arrays[RGL_CA_TEXCOORD] : &s->tc_parked[u];
}

/* Records @ArrayData(array, ...) of a's elements [first, first+count). */
static bool put_array(rgl_stream **sp, const rgl_client_array_state *a, GLenum array,
                      int64_t first, int64_t count)
{
    rgl_stream *s = *sp;
    size_t es = element_size(a);
    size_t stride = a->stride ? (size_t)a->stride : es;
    size_t bytes = (size_t)count * es;
    uint8_t *p = rgl_reserve(&s, 4 * RGL_VARINT32_MAX + RGL_VARINT64_MAX + 2 + bytes);
    *sp = s;
    if (!p)
        return false;
    const uint8_t *src = NULL;
    if (count > 0 && !array_source(a, first, count, &src))
        return false; /* a buffer changed under us: the draw goes unrecorded */
    p = rgl_put_opcode(p, RGL_OP_ArrayData);
    p = rgl_put_e(p, array);
    p = rgl_put_i(p, (int32_t)first);
    p = rgl_put_i(p, a->size);
    p = rgl_put_e(p, a->type);
    p = rgl_put_varint(p, bytes);
    if (count > 0 && stride == es) {
        memcpy(p, src, bytes);
        p += bytes;
    } else if (count > 0) {
        for (int64_t i = 0; i < count; i++, src += stride, p += es)
            memcpy(p, src, es);
    }
    if (count > 0 && a->buffer)
        rgl_buffer_release();
    rgl_commit(s, p);
    return true;
}

/* Records @ArrayData for the elements [first, first+count) of every enabled
 * array, packed. Returns false (nothing recorded) when an enabled array
 * has no pointer (GL would fault: the draw goes on unrecorded), or buffer
 * data that does not hold the elements: GL may refuse the draw, or draw
 * from a buffer filled in a way the recorder did not see; op, the draw,
 * is then marked @Skipped. */
static bool record_arrays(uint32_t op, int64_t first, int64_t count)
{
    rgl_stream *s = rgl_tls_stream;
    if (!s)
        return false;
    for (int k = 0; k < RGL_MAX_CLIENT_ARRAYS; k++)
        if (s->arrays[k].enabled && !s->arrays[k].pointer && !s->arrays[k].buffer)
            return false;
    for (uint32_t u = 0; u < RGL_MAX_TEX_UNITS; u++) {
        const rgl_client_array_state *a = tc_array(s, u);
        if (a->enabled && !a->pointer && !a->buffer)
            return false;
    }
    if (first < 0 || count < 0 || first > INT32_MAX)
        return false;
    /* Check every buffer first: a draw is recorded whole or not at all. */
    for (int k = 0; k < RGL_MAX_CLIENT_ARRAYS; k++) {
        const uint8_t *src;
        if (s->arrays[k].enabled && s->arrays[k].buffer && count > 0) {
            if (!array_source(&s->arrays[k], first, count, &src)) {
                rgl_note_skipped(op, RGL_PX_SKIP_DATA);
                return false;
            }
            rgl_buffer_release();
        }
    }
    for (uint32_t u = 0; u < RGL_MAX_TEX_UNITS; u++) {
        const uint8_t *src;
        const rgl_client_array_state *a = tc_array(s, u);
        if (u != s->client_unit && a->enabled && a->buffer && count > 0) {
            if (!array_source(a, first, count, &src)) {
                rgl_note_skipped(op, RGL_PX_SKIP_DATA);
                return false;
            }
            rgl_buffer_release();
        }
    }
    /* Texture coordinates of every unit: each @ArrayData of them belongs
     * to the unit the last glClientActiveTexture record names. */
    uint32_t rec_unit = s->client_unit;
    for (int k = 0; k < RGL_MAX_CLIENT_ARRAYS; k++) {
        if (k == RGL_CA_TEXCOORD) {
            for (uint32_t u = 0; u < RGL_MAX_TEX_UNITS; u++) {
                const rgl_client_array_state *a = tc_array(s, u);
                if (!a->enabled)
                    continue;
                /* Beside the @ArrayData (a list body or the frame). */
                if (u != rec_unit) {
                    rgl_record(RGL_OP_ClientActiveTexture, "e", GL_TEXTURE0 + u);
                    rec_unit = u;
                }
                if (!put_array(&s, a, GL_TEXTURE_COORD_ARRAY, first, count))
                    break;
            }
            if (rec_unit != s->client_unit)
                rgl_record(RGL_OP_ClientActiveTexture, "e", GL_TEXTURE0 + s->client_unit);
            continue;
        }
        if (s->arrays[k].enabled && !put_array(&s, &s->arrays[k], array_enums[k], first, count))
            return false;
    }
    return true;
}

/* Bytes of one index of type; 0 for a type GL refuses. */
static size_t index_size(GLenum type)
{
    return type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2
         : type == GL_UNSIGNED_INT ? 4 : 0;
}

/* Smallest and largest index of an index array; false for a bad type. */
static bool index_range(GLsizei count, GLenum type, const void *indices, uint32_t *lo,
                        uint32_t *hi, size_t *bytes)
{
    size_t ts = index_size(type);
    if (!ts || count < 0 || !indices)
        return false;
    uint32_t mn = UINT32_MAX, mx = 0;
    for (GLsizei i = 0; i < count; i++) {
        uint32_t v = ts == 1 ? ((const GLubyte *)indices)[i]
                   : ts == 2 ? ((const GLushort *)indices)[i] : ((const GLuint *)indices)[i];
        if (v < mn)
            mn = v;
        if (v > mx)
            mx = v;
    }
    *lo = mn;
    *hi = mx;
    *bytes = (size_t)count * ts;
    return true;
}

/* The indices of a draw: client memory, or (with buffer `eb` bound to
 * GL_ELEMENT_ARRAY_BUFFER) the recorder's copy of the buffer from offset
 * `indices` on, acquired (*locked set: release after use). NULL when the
 * buffer does not hold `bytes` bytes there. */
static const void *index_source(uint32_t eb, const void *indices, size_t bytes, bool *locked)
{
    *locked = false;
    if (!eb)
        return indices;
    size_t size;
    const uint8_t *data = rgl_buffer_acquire(eb, &size);
    uint64_t offset = (uintptr_t)indices;
    if (!data || offset + bytes > size) {
        rgl_buffer_release();
        return NULL;
    }
    *locked = true;
    return data + offset;
}

/* Records a draw by indices: the arrays over the used range, then the
 * command with the indices as a blob. */
static bool record_elements(uint32_t op, GLenum mode, GLuint start, GLuint end, GLsizei count,
                            GLenum type, const void *indices)
{
    uint32_t lo, hi;
    size_t bytes;
    bool locked;
    rgl_stream *s = rgl_tls_stream;
    if (!s || !index_size(type) || count < 0 || !draw_ok(s, op, mode))
        return false;
    uint32_t eb = rgl_buffer_binding(s, GL_ELEMENT_ARRAY_BUFFER);
    const void *idx = index_source(eb, indices, (size_t)count * index_size(type), &locked);
    bool ok = idx && index_range(count, type, idx, &lo, &hi, &bytes);
    if (locked)
        rgl_buffer_release();
    if (!idx && eb)
        rgl_note_skipped(op, RGL_PX_SKIP_DATA); /* see record_arrays */
    if (!ok)
        return false;
    rgl_resolve_matrices();
    if (count > 0 && !record_arrays(op, lo, (int64_t)hi - lo + 1))
        return false;
    if (!(idx = index_source(eb, indices, bytes, &locked)))
        return false;
    if (op == RGL_OP_DrawElements)
        ok = rgl_record(op, "eieB", mode, count, type, idx, bytes);
    else
        ok = rgl_record(op, "eeeieB", mode, start, end, count, type, idx, bytes);
    if (locked)
        rgl_buffer_release();
    return ok;
}

static void array_element(uint32_t op, GLint i)
{
    /* Inside glBegin/glEnd: no matrix read-back here (glGet is illegal). */
    if (i >= 0 && record_arrays(op, i, 1))
        rgl_record(op, "i", i);
    glArrayElement(i);
}

RGL_EXPORT void rayglArrayElement(GLint i)
{
    array_element(RGL_OP_ArrayElement, i);
}

static void draw_arrays(uint32_t op, GLenum mode, GLint first, GLsizei count)
{
    rgl_stream *s = rgl_tls_stream;
    if (first >= 0 && count >= 0 && s && draw_ok(s, op, mode)) {
        rgl_resolve_matrices();
        if (record_arrays(op, first, count))
            rgl_record(op, "eii", mode, first, count);
    }
    glDrawArrays(mode, first, count);
}

RGL_EXPORT void rayglDrawArrays(GLenum mode, GLint first, GLsizei count)
{
    draw_arrays(RGL_OP_DrawArrays, mode, first, count);
}

RGL_EXPORT void rayglDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices)
{
    record_elements(RGL_OP_DrawElements, mode, 0, 0, count, type, indices);
    glDrawElements(mode, count, type, indices);
}

RGL_EXPORT void rayglDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                       GLenum type, const GLvoid *indices)
{
    if (end >= start)
        record_elements(RGL_OP_DrawRangeElements, mode, start, end, count, type, indices);
    glDrawRangeElements(mode, start, end, count, type, indices);
}

/* glMultiDrawArrays: one @ArrayData range covering every draw, then the
 * firsts and counts as two blobs of little-endian int32. */
static void multi_draw_arrays(uint32_t op, GLenum mode, const GLint *first, const GLsizei *count,
                              GLsizei drawcount)
{
    rgl_stream *s = rgl_tls_stream;
    bool ok = drawcount >= 0 && (drawcount == 0 || (first && count)) && s &&
              draw_ok(s, op, mode);
    int64_t lo = INT64_MAX, hi = 0;
    for (GLsizei i = 0; ok && i < drawcount; i++) {
        if (first[i] < 0 || count[i] < 0)
            ok = false;
        else if (count[i] > 0) {
            lo = first[i] < lo ? first[i] : lo;
            hi = (int64_t)first[i] + count[i] > hi ? (int64_t)first[i] + count[i] : hi;
        }
    }
    if (ok) {
        rgl_resolve_matrices();
        if (lo == INT64_MAX)
            lo = hi = 0;
        if (record_arrays(op, lo, hi - lo))
            rgl_record(op, "eBBi", mode, (const void *)first,
                       (size_t)drawcount * 4, (const void *)count, (size_t)drawcount * 4,
                       drawcount);
    }
    glMultiDrawArrays(mode, first, count, drawcount);
}

RGL_EXPORT void rayglMultiDrawArrays(GLenum mode, const GLint *first, const GLsizei *count,
                                     GLsizei drawcount)
{
    multi_draw_arrays(RGL_OP_MultiDrawArrays, mode, first, count, drawcount);
}

/* glMultiDrawElements: the index arrays of all the draws, one after the
 * other, in one blob; one @ArrayData range covering every index. */
static void record_multi_elements(uint32_t op, GLenum mode, const GLsizei *count, GLenum type,
                                  const void *const *indices, GLsizei drawcount)
{
    size_t ts = index_size(type);
    rgl_stream *s = rgl_tls_stream;
    if (!s || !ts || drawcount < 0 || (drawcount > 0 && (!count || !indices)) ||
        !draw_ok(s, op, mode))
        return;
    uint32_t eb = rgl_buffer_binding(s, GL_ELEMENT_ARRAY_BUFFER);
    size_t total = 0;
    for (GLsizei i = 0; i < drawcount; i++) {
        if (count[i] < 0)
            return;
        total += (size_t)count[i] * ts;
    }
    uint8_t *all = rgl_alloc(total ? total : 1);
    if (!all) {
        rgl_fail(ENOMEM, "allocation failed");
        return;
    }
    uint32_t lo = UINT32_MAX, hi = 0;
    size_t at = 0;
    bool ok = true;
    for (GLsizei i = 0; ok && i < drawcount; i++) {
        size_t bytes = (size_t)count[i] * ts;
        bool locked;
        const void *idx = index_source(eb, indices[i], bytes, &locked);
        uint32_t l, h;
        size_t b;
        ok = idx && index_range(count[i], type, idx, &l, &h, &b);
        if (!idx && eb)
            rgl_note_skipped(op, RGL_PX_SKIP_DATA); /* see record_arrays */
        if (ok && bytes) {
            memcpy(all + at, idx, bytes);
            at += bytes;
            lo = l < lo ? l : lo;
            hi = h > hi ? h : hi;
        }
        if (locked)
            rgl_buffer_release();
    }
    if (ok) {
        rgl_resolve_matrices();
        if (lo == UINT32_MAX)
            lo = hi = 0;
        else
            hi++;
        if (record_arrays(op, lo, (int64_t)hi - lo))
            rgl_record(op, "eBeBi", mode, (const void *)count,
                       (size_t)drawcount * 4, type, (const void *)all, total, drawcount);
    }
    rgl_free(all);
}

RGL_EXPORT void rayglMultiDrawElements(GLenum mode, const GLsizei *count, GLenum type,
                                       const void *const *indices, GLsizei drawcount)
{
    record_multi_elements(RGL_OP_MultiDrawElements, mode, count, type, indices, drawcount);
    glMultiDrawElements(mode, count, type, indices, drawcount);
}

/* The EXT names of the array draws: rows of their own, forwarded to the
 * core functions, which gl.xml makes the same. */
RGL_EXPORT void rayglArrayElementEXT(GLint i)
{
    array_element(RGL_OP_ArrayElementEXT, i);
}

RGL_EXPORT void rayglDrawArraysEXT(GLenum mode, GLint first, GLsizei count)
{
    draw_arrays(RGL_OP_DrawArraysEXT, mode, first, count);
}

RGL_EXPORT void rayglDrawRangeElementsEXT(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                          GLenum type, const void *indices)
{
    if (end >= start)
        record_elements(RGL_OP_DrawRangeElementsEXT, mode, start, end, count, type, indices);
    glDrawRangeElements(mode, start, end, count, type, indices);
}

RGL_EXPORT void rayglMultiDrawArraysEXT(GLenum mode, const GLint *first, const GLsizei *count,
                                        GLsizei primcount)
{
    multi_draw_arrays(RGL_OP_MultiDrawArraysEXT, mode, first, count, primcount);
}

RGL_EXPORT void rayglMultiDrawElementsEXT(GLenum mode, const GLsizei *count, GLenum type,
                                          const void *const *indices, GLsizei primcount)
{
    record_multi_elements(RGL_OP_MultiDrawElementsEXT, mode, count, type, indices, primcount);
    glMultiDrawElements(mode, count, type, indices, primcount);
}

/* Keeps a pointer call's layout in the stream (GL changes nothing on error)
 * and records it. */
static void array_pointer(int slot, uint32_t op, GLint size, GLenum type, GLsizei stride,
                          const GLvoid *ptr)
{
    /* Kept while not recording too: a pointer the recorder missed would be
     * read, when a trace is opened later, after the program freed it. */
    rgl_stream *s;
    bool rec = rgl_reserve(&s, 1) != NULL;
    if (!rec && !(s = rgl_tls_stream))
        return;
    rgl_client_array_state *a = &s->arrays[slot];
    a->size = size;
    a->type = type;
    a->stride = stride;
    a->pointer = ptr;
    a->buffer = rgl_buffer_binding(s, GL_ARRAY_BUFFER);
    if (!rec)
        return;
    switch (slot) {
    case RGL_CA_NORMAL: case RGL_CA_FOGCOORD: RECORD_NOW(s, op, "ei", type, stride); break;
    case RGL_CA_EDGEFLAG: RECORD_NOW(s, op, "i", stride); break;
    default: RECORD_NOW(s, op, "iei", size, type, stride); break;
    }
}

RGL_EXPORT void rayglVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    if (size >= 2 && size <= 4 && stride >= 0 && type_size(type) && type_size(type) != 1)
        array_pointer(RGL_CA_VERTEX, RGL_OP_VertexPointer, size, type, stride, ptr);
    glVertexPointer(size, type, stride, ptr);
}

RGL_EXPORT void rayglNormalPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
    if (stride >= 0 && type_size(type) && type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT &&
        type != GL_UNSIGNED_INT)
        array_pointer(RGL_CA_NORMAL, RGL_OP_NormalPointer, 3, type, stride, ptr);
    glNormalPointer(type, stride, ptr);
}

RGL_EXPORT void rayglColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    if ((size == 3 || size == 4) && stride >= 0 && type_size(type))
        array_pointer(RGL_CA_COLOR, RGL_OP_ColorPointer, size, type, stride, ptr);
    glColorPointer(size, type, stride, ptr);
}

RGL_EXPORT void rayglTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    if (size >= 1 && size <= 4 && stride >= 0 && type_size(type) && type_size(type) != 1)
        array_pointer(RGL_CA_TEXCOORD, RGL_OP_TexCoordPointer, size, type, stride, ptr);
    glTexCoordPointer(size, type, stride, ptr);
}

RGL_EXPORT void rayglEdgeFlagPointer(GLsizei stride, const GLvoid *ptr)
{
    /* GLboolean elements: recorded as one unsigned byte each. */
    if (stride >= 0)
        array_pointer(RGL_CA_EDGEFLAG, RGL_OP_EdgeFlagPointer, 1, GL_UNSIGNED_BYTE, stride, ptr);
    glEdgeFlagPointer(stride, ptr);
}

/* GL 2.1 2.8: fog coordinates are GL_FLOAT or GL_DOUBLE, one each;
 * secondary colours three components of any type (GL refuses the rest:
 * nothing recorded). */
static void fog_coord_pointer(uint32_t op, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    if (stride >= 0 && (type == GL_FLOAT || type == GL_DOUBLE))
        array_pointer(RGL_CA_FOGCOORD, op, 1, type, stride, ptr);
}

static void secondary_color_pointer(uint32_t op, GLint size, GLenum type, GLsizei stride,
                                    const GLvoid *ptr)
{
    if (size == 3 && stride >= 0 && type_size(type))
        array_pointer(RGL_CA_SECONDARY, op, size, type, stride, ptr);
}

RGL_EXPORT void rayglFogCoordPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
    fog_coord_pointer(RGL_OP_FogCoordPointer, type, stride, ptr);
    glFogCoordPointer(type, stride, ptr);
}

RGL_EXPORT void rayglFogCoordPointerEXT(GLenum type, GLsizei stride, const GLvoid *ptr)
{
    fog_coord_pointer(RGL_OP_FogCoordPointerEXT, type, stride, ptr);
    glFogCoordPointerEXT(type, stride, ptr);
}

RGL_EXPORT void rayglSecondaryColorPointer(GLint size, GLenum type, GLsizei stride,
                                           const GLvoid *ptr)
{
    secondary_color_pointer(RGL_OP_SecondaryColorPointer, size, type, stride, ptr);
    glSecondaryColorPointer(size, type, stride, ptr);
}

RGL_EXPORT void rayglSecondaryColorPointerEXT(GLint size, GLenum type, GLsizei stride,
                                              const GLvoid *ptr)
{
    secondary_color_pointer(RGL_OP_SecondaryColorPointerEXT, size, type, stride, ptr);
    glSecondaryColorPointerEXT(size, type, stride, ptr);
}

/* glClientActiveTexture: the texture-coordinate array calls change the
 * unit it names; the others' arrays are parked. GL refuses a unit past
 * its limit (GL_INVALID_ENUM): nothing recorded. */
static void client_active_texture(uint32_t op, GLenum texture)
{
    if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + RGL_MAX_TEX_UNITS)
        return;
    rgl_stream *s;
    bool rec = rgl_reserve(&s, 1) != NULL;
    if (!rec && !(s = rgl_tls_stream))
        return;
    uint32_t u = texture - GL_TEXTURE0;
    if (u != s->client_unit) {
        s->tc_parked[s->client_unit] = s->arrays[RGL_CA_TEXCOORD];
        s->arrays[RGL_CA_TEXCOORD] = s->tc_parked[u];
        s->client_unit = u;
    }
    if (rec)
        RECORD_NOW(s, op, "e", texture);
}

RGL_EXPORT void rayglClientActiveTexture(GLenum texture)
{
    client_active_texture(RGL_OP_ClientActiveTexture, texture);
    glClientActiveTexture(texture);
}

RGL_EXPORT void rayglClientActiveTextureARB(GLenum texture)
{
    client_active_texture(RGL_OP_ClientActiveTextureARB, texture);
    glClientActiveTextureARB(texture);
}

static void client_state(GLenum array, bool enable)
{
    int slot = array_slot(array);
    rgl_stream *s;
    bool rec = slot >= 0 && rgl_reserve(&s, 1) != NULL;
    if (!rec)
        s = rgl_tls_stream;
    if (slot >= 0 && s) /* kept while not recording too (array_pointer) */
        s->arrays[slot].enabled = enable;
    if (rec)
        RECORD_NOW(s, enable ? RGL_OP_EnableClientState : RGL_OP_DisableClientState, "e", array);
}

/* glEnable / glDisable. A compatibility context (Mesa) takes the client
 * arrays there too, as glEnableClientState does (checked with OSMesa: no
 * error): recorded as that, so the draws' @ArrayData follow. Other caps
 * are recorded as they are, into a list being compiled as GL compiles
 * them. */
static void record_cap(uint32_t op, GLenum cap)
{
    rgl_stream *s;
    uint8_t *p = rgl_reserve(&s, 2 + RGL_WMAX_e);
    if (p) {
        p = rgl_put_opcode(p, op);
        p = rgl_put_e(p, cap);
        rgl_commit(s, p);
    }
}

/* A client array enabled in a list being compiled (GL_COMPILE) takes
 * effect at glCallList: recorded in the list as it is. */
static bool cap_is_client_now(GLenum cap)
{
    const rgl_stream *s = rgl_tls_stream;
    return array_slot(cap) >= 0 && !(s && s->compiling && s->list_mode == GL_COMPILE);
}

RGL_EXPORT void rayglEnable(GLenum cap)
{
    if (cap_is_client_now(cap))
        client_state(cap, true);
    else
        record_cap(RGL_OP_Enable, cap);
    glEnable(cap);
}

RGL_EXPORT void rayglDisable(GLenum cap)
{
    if (cap_is_client_now(cap))
        client_state(cap, false);
    else
        record_cap(RGL_OP_Disable, cap);
    glDisable(cap);
}

RGL_EXPORT void rayglEnableClientState(GLenum array)
{
    client_state(array, true);
    glEnableClientState(array);
}

RGL_EXPORT void rayglDisableClientState(GLenum array)
{
    client_state(array, false);
    glDisableClientState(array);
}

/* glInterleavedArrays (GL 1.5, table 2.5): which arrays a format enables,
 * their sizes, the colour type, and the offsets in units of bytes. */
typedef struct interleaved_format {
    GLenum format;
    bool et, ec, en;
    uint8_t st, sc, sv;
    GLenum tc;
    uint8_t pc, pn, pv, s;
} interleaved_format;

#define F4 4
static const interleaved_format interleaved[] = {
    {GL_V2F, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2 * F4},
    {GL_V3F, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3 * F4},
    {GL_C4UB_V2F, 0, 1, 0, 0, 4, 2, GL_UNSIGNED_BYTE, 0, 0, 4, 4 + 2 * F4},
    {GL_C4UB_V3F, 0, 1, 0, 0, 4, 3, GL_UNSIGNED_BYTE, 0, 0, 4, 4 + 3 * F4},
    {GL_C3F_V3F, 0, 1, 0, 0, 3, 3, GL_FLOAT, 0, 0, 3 * F4, 6 * F4},
    {GL_N3F_V3F, 0, 0, 1, 0, 0, 3, 0, 0, 0, 3 * F4, 6 * F4},
    {GL_C4F_N3F_V3F, 0, 1, 1, 0, 4, 3, GL_FLOAT, 0, 4 * F4, 7 * F4, 10 * F4},
    {GL_T2F_V3F, 1, 0, 0, 2, 0, 3, 0, 0, 0, 2 * F4, 5 * F4},
    {GL_T4F_V4F, 1, 0, 0, 4, 0, 4, 0, 0, 0, 4 * F4, 8 * F4},
    {GL_T2F_C4UB_V3F, 1, 1, 0, 2, 4, 3, GL_UNSIGNED_BYTE, 2 * F4, 0, 4 + 2 * F4, 4 + 5 * F4},
    {GL_T2F_C3F_V3F, 1, 1, 0, 2, 3, 3, GL_FLOAT, 2 * F4, 0, 5 * F4, 8 * F4},
    {GL_T2F_N3F_V3F, 1, 0, 1, 2, 0, 3, 0, 0, 2 * F4, 5 * F4, 8 * F4},
    {GL_T2F_C4F_N3F_V3F, 1, 1, 1, 2, 4, 3, GL_FLOAT, 2 * F4, 6 * F4, 9 * F4, 12 * F4},
    {GL_T4F_C4F_N3F_V4F, 1, 1, 1, 4, 4, 4, GL_FLOAT, 4 * F4, 8 * F4, 11 * F4, 15 * F4},
};
#undef F4

RGL_EXPORT void rayglInterleavedArrays(GLenum format, GLsizei stride, const GLvoid *pointer)
{
    const interleaved_format *f = NULL;
    for (size_t k = 0; k < sizeof interleaved / sizeof interleaved[0]; k++)
        if (interleaved[k].format == format)
            f = &interleaved[k];
    rgl_stream *s; /* kept while not recording too (array_pointer) */
    bool rec = f && stride >= 0 && rgl_reserve(&s, 1) != NULL;
    if (!rec)
        s = rgl_tls_stream;
    if (f && stride >= 0 && s) {
        GLsizei st = stride ? stride : f->s;
        const uint8_t *p = pointer;
        rgl_client_array_state *a = s->arrays;
        a[RGL_CA_EDGEFLAG].enabled = false;
        a[RGL_CA_TEXCOORD].enabled = f->et;
        /* With an array buffer bound, pointer is an offset in it. */
        uint32_t buf = rgl_buffer_binding(s, GL_ARRAY_BUFFER);
        const uint8_t *q = p || buf ? p : NULL;
#define AT(off) (q || buf ? (const void *)((uintptr_t)q + (off)) : NULL)
        if (f->et)
            a[RGL_CA_TEXCOORD] = (rgl_client_array_state){true, f->st, GL_FLOAT, st, AT(0), buf};
        a[RGL_CA_COLOR].enabled = f->ec;
        if (f->ec)
            a[RGL_CA_COLOR] = (rgl_client_array_state){true, f->sc, f->tc, st, AT(f->pc), buf};
        a[RGL_CA_NORMAL].enabled = f->en;
        if (f->en)
            a[RGL_CA_NORMAL] = (rgl_client_array_state){true, 3, GL_FLOAT, st, AT(f->pn), buf};
        a[RGL_CA_VERTEX] = (rgl_client_array_state){true, f->sv, GL_FLOAT, st, AT(f->pv), buf};
#undef AT
        if (rec)
            RECORD_NOW(s, RGL_OP_InterleavedArrays, "ei", format, stride);
    }
    glInterleavedArrays(format, stride, pointer);
}
