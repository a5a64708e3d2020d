/* entry_buffer.c: buffer objects (GL 1.5, ARB_vertex_buffer_object) and
 * the multi-draws (GL 1.4).
 *
 * The recorder keeps its own copy of every buffer's contents, filled at
 * glBufferData and glBufferSubData and, for a buffer mapped for writing, at
 * glUnmapBuffer (the mapped bytes are read just before GL unmaps them).
 * Each of those also goes into the trace, as a BYTES resource referenced
 * by glBufferData / glBufferSubData (an unmap is recorded as a
 * glBufferSubData of the whole buffer, then glUnmapBuffer). With a buffer
 * bound to GL_ARRAY_BUFFER, a pointer call's pointer is an offset into it;
 * with one bound to GL_ELEMENT_ARRAY_BUFFER, so are the indices of a draw.
 * The draws (entry_custom.c) read both from the copy, so every draw still
 * carries the elements it uses and a frame translates on its own.
 *
 * Buffers are shared between contexts like lists and textures, so the
 * table is process-wide under one lock; bindings are per context (per
 * stream). None of these calls is compiled into a display list: they are
 * recorded into the frame even while a list is compiled.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <errno.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>

#include <GL/gl.h>
#include <GL/glext.h>

#include "raygl.h"
#include "recorder.h"

typedef struct buffer_obj {
    uint32_t name;
    size_t size;
    uint8_t *data;       /* the recorder's copy */
    void *mapped;        /* what GL's glMapBuffer returned */
    GLenum access;       /* of the mapping */
} buffer_obj;

static struct {
    pthread_mutex_t mu;
    buffer_obj *v;
    size_t n, cap;
    uint32_t next_name; /* RayGL's own names when GL has no context */
} bufs = {.mu = PTHREAD_MUTEX_INITIALIZER};

/* Calls GL executes at once: into the frame even while a list compiles. */
#define RECORD_NOW(s, op, ...) \
    ((s)->compiling ? rgl_emit(&(s)->frame, (op), __VA_ARGS__) : rgl_record((op), __VA_ARGS__))

/* The object `name`, created when create is set; bufs.mu held. */
static buffer_obj *find(uint32_t name, bool create)
{
    for (size_t i = 0; i < bufs.n; i++)
        if (bufs.v[i].name == name)
            return &bufs.v[i];
    if (!create || name == 0)
        return NULL;
    if (bufs.n == bufs.cap) {
        size_t cap = bufs.cap ? 2 * bufs.cap : 16;
        buffer_obj *v = rgl_realloc(bufs.v, cap * sizeof *v);
        if (!v) {
            rgl_fail(ENOMEM, "allocation failed");
            return NULL;
        }
        bufs.v = v;
        bufs.cap = cap;
    }
    buffer_obj *b = &bufs.v[bufs.n++];
    memset(b, 0, sizeof *b);
    b->name = name;
    return b;
}

const uint8_t *rgl_buffer_acquire(uint32_t name, size_t *size)
{
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = find(name, false);
    *size = b ? b->size : 0;
    return b ? b->data : NULL;
}

void rgl_buffer_release(void) { pthread_mutex_unlock(&bufs.mu); }

/* The stream's binding for target, or NULL for a target RayGL does not
 * track (GL keeps others; they do not feed fixed-function draws). */
static uint32_t *binding(rgl_stream *s, GLenum target)
{
    if (target == GL_ARRAY_BUFFER)
        return &s->array_buffer;
    if (target == GL_ELEMENT_ARRAY_BUFFER)
        return &s->element_buffer;
    return NULL;
}

/* ---- Names and bindings ------------------------------------------------------------ */

static void gen_buffers(uint32_t op, GLsizei n, GLuint *names)
{
    rgl_stream *s;
    if (n <= 0 || !names || !rgl_reserve(&s, 1))
        return;
    if (names[0] == 0) { /* GL has no context: RayGL names them */
        pthread_mutex_lock(&bufs.mu);
        for (GLsizei k = 0; k < n; k++)
            names[k] = ++bufs.next_name;
        pthread_mutex_unlock(&bufs.mu);
    }
    for (GLsizei k = 0; k < n; k += RGL_ARRAY_MAX) {
        int m = n - k < RGL_ARRAY_MAX ? (int)(n - k) : RGL_ARRAY_MAX;
        RECORD_NOW(s, op, "U", names + k, m);
    }
}

RGL_EXPORT void rayglGenBuffers(GLsizei n, GLuint *buffers)
{
    if (n > 0 && buffers)
        memset(buffers, 0, (size_t)n * sizeof *buffers);
    glGenBuffers(n, buffers);
    gen_buffers(RGL_OP_GenBuffers, n, buffers);
}

RGL_EXPORT void rayglGenBuffersARB(GLsizei n, GLuint *buffers)
{
    if (n > 0 && buffers)
        memset(buffers, 0, (size_t)n * sizeof *buffers);
    glGenBuffersARB(n, buffers);
    gen_buffers(RGL_OP_GenBuffersARB, n, buffers);
}

static void delete_buffers(uint32_t op, GLsizei n, const GLuint *names)
{
    rgl_stream *s;
    if (n <= 0 || !names || !rgl_reserve(&s, 1))
        return;
    for (GLsizei k = 0; k < n; k += RGL_ARRAY_MAX) {
        int m = n - k < RGL_ARRAY_MAX ? (int)(n - k) : RGL_ARRAY_MAX;
        RECORD_NOW(s, op, "U", names + k, m);
    }
    pthread_mutex_lock(&bufs.mu);
    for (GLsizei k = 0; k < n; k++) {
        buffer_obj *b = find(names[k], false);
        if (b) {
            rgl_free(b->data);
            *b = bufs.v[--bufs.n];
        }
        /* Deleting a bound buffer binds 0 (GL 1.5, 2.9). */
        if (names[k] && s->array_buffer == names[k])
            s->array_buffer = 0;
        if (names[k] && s->element_buffer == names[k])
            s->element_buffer = 0;
    }
    pthread_mutex_unlock(&bufs.mu);
}

RGL_EXPORT void rayglDeleteBuffers(GLsizei n, const GLuint *buffers)
{
    delete_buffers(RGL_OP_DeleteBuffers, n, buffers);
    glDeleteBuffers(n, buffers);
}

RGL_EXPORT void rayglDeleteBuffersARB(GLsizei n, const GLuint *buffers)
{
    delete_buffers(RGL_OP_DeleteBuffersARB, n, buffers);
    glDeleteBuffersARB(n, buffers);
}

static void bind_buffer(uint32_t op, GLenum target, GLuint buffer)
{
    rgl_stream *s;
    if (!rgl_reserve(&s, 1))
        return;
    uint32_t *slot = binding(s, target);
    if (!slot)
        return; /* another target: not recorded (GL 1.5 has no other) */
    *slot = buffer;
    pthread_mutex_lock(&bufs.mu);
    find(buffer, true); /* binding a new name creates the object */
    pthread_mutex_unlock(&bufs.mu);
    RECORD_NOW(s, op, "ee", target, buffer);
}

RGL_EXPORT void rayglBindBuffer(GLenum target, GLuint buffer)
{
    bind_buffer(RGL_OP_BindBuffer, target, buffer);
    glBindBuffer(target, buffer);
}

RGL_EXPORT void rayglBindBufferARB(GLenum target, GLuint buffer)
{
    bind_buffer(RGL_OP_BindBufferARB, target, buffer);
    glBindBufferARB(target, buffer);
}

/* ---- Contents ---------------------------------------------------------------------- */

/* The bound object of target for a data call, or NULL (bufs.mu held). */
static buffer_obj *bound(rgl_stream *s, GLenum target)
{
    uint32_t *slot = binding(s, target);
    return slot && *slot ? find(*slot, true) : NULL;
}

static void buffer_data(uint32_t op, GLenum target, GLsizeiptr size, const void *data,
                        GLenum usage)
{
    rgl_stream *s;
    if (size < 0 || !rgl_reserve(&s, 1))
        return;
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(s, target);
    bool ok = false;
    if (b && !b->mapped) {
        uint8_t *copy = rgl_realloc(b->data, size ? (size_t)size : 1);
        if (!copy) {
            rgl_fail(ENOMEM, "allocation failed");
        } else {
            b->data = copy;
            b->size = (size_t)size;
            if (data)
                memcpy(copy, data, (size_t)size);
            else
                memset(copy, 0, (size_t)size); /* undefined in GL */
            ok = true;
        }
    }
    pthread_mutex_unlock(&bufs.mu);
    if (!ok)
        return;
    uint32_t id = data && size ? rgl_resource_put(RGL_RES_BYTES, data, (size_t)size) : 0;
    if (!data || !size || id)
        RECORD_NOW(s, op, "eqee", target, (int64_t)size, id, usage);
}

RGL_EXPORT void rayglBufferData(GLenum target, GLsizeiptr size, const void *data, GLenum usage)
{
    buffer_data(RGL_OP_BufferData, target, size, data, usage);
    glBufferData(target, size, data, usage);
}

RGL_EXPORT void rayglBufferDataARB(GLenum target, GLsizeiptrARB size, const void *data,
                                   GLenum usage)
{
    buffer_data(RGL_OP_BufferDataARB, target, size, data, usage);
    glBufferDataARB(target, size, data, usage);
}

static void buffer_sub_data(uint32_t op, GLenum target, GLintptr offset, GLsizeiptr size,
                            const void *data)
{
    rgl_stream *s;
    if (offset < 0 || size < 0 || !data || !rgl_reserve(&s, 1))
        return;
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(s, target);
    bool ok = b && !b->mapped && (uint64_t)offset + (uint64_t)size <= b->size;
    if (ok)
        memcpy(b->data + offset, data, (size_t)size);
    pthread_mutex_unlock(&bufs.mu);
    if (!ok || size == 0)
        return; /* GL rejects it (or it changes nothing) */
    uint32_t id = rgl_resource_put(RGL_RES_BYTES, data, (size_t)size);
    if (id)
        RECORD_NOW(s, op, "eqqe", target, (int64_t)offset, (int64_t)size, id);
}

RGL_EXPORT void rayglBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                                   const void *data)
{
    buffer_sub_data(RGL_OP_BufferSubData, target, offset, size, data);
    glBufferSubData(target, offset, size, data);
}

RGL_EXPORT void rayglBufferSubDataARB(GLenum target, GLintptrARB offset, GLsizeiptrARB size,
                                      const void *data)
{
    buffer_sub_data(RGL_OP_BufferSubDataARB, target, offset, size, data);
    glBufferSubDataARB(target, offset, size, data);
}

static void map_buffer(uint32_t op, GLenum target, GLenum access, void *ptr)
{
    rgl_stream *s;
    if (!ptr || !rgl_reserve(&s, 1))
        return;
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(s, target);
    if (b) {
        b->mapped = ptr;
        b->access = access;
    }
    pthread_mutex_unlock(&bufs.mu);
    if (b)
        RECORD_NOW(s, op, "ee", target, access);
}

RGL_EXPORT void *rayglMapBuffer(GLenum target, GLenum access)
{
    void *p = glMapBuffer(target, access);
    map_buffer(RGL_OP_MapBuffer, target, access, p);
    return p;
}

RGL_EXPORT void *rayglMapBufferARB(GLenum target, GLenum access)
{
    void *p = glMapBufferARB(target, access);
    map_buffer(RGL_OP_MapBufferARB, target, access, p);
    return p;
}

/* Before GL unmaps: what the program wrote through the mapping becomes
 * the buffer's contents, in the copy and in the trace. */
static void unmap_buffer(uint32_t op, uint32_t sub_op, GLenum target)
{
    rgl_stream *s;
    if (!rgl_reserve(&s, 1))
        return;
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(s, target);
    bool was_mapped = b && b->mapped;
    bool wrote = was_mapped && b->access != GL_READ_ONLY && b->size > 0;
    uint32_t id = 0;
    size_t size = 0;
    if (wrote) {
        memcpy(b->data, b->mapped, b->size);
        size = b->size;
        id = rgl_resource_put(RGL_RES_BYTES, b->data, b->size);
    }
    if (b)
        b->mapped = NULL;
    pthread_mutex_unlock(&bufs.mu);
    if (id)
        RECORD_NOW(s, sub_op, "eqqe", target, (int64_t)0, (int64_t)size, id);
    if (was_mapped)
        RECORD_NOW(s, op, "e", target);
}

RGL_EXPORT GLboolean rayglUnmapBuffer(GLenum target)
{
    unmap_buffer(RGL_OP_UnmapBuffer, RGL_OP_BufferSubData, target);
    return glUnmapBuffer(target);
}

RGL_EXPORT GLboolean rayglUnmapBufferARB(GLenum target)
{
    unmap_buffer(RGL_OP_UnmapBufferARB, RGL_OP_BufferSubDataARB, target);
    return glUnmapBufferARB(target);
}
