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
 * With a buffer bound to GL_PIXEL_UNPACK_BUFFER (GL 2.1), the pixels of a
 * texture image are an offset into it: entry_custom.c reads them through
 * rgl_buffer_copy, from GL itself with a live context (its buffer may have
 * been written by GL: glReadPixels into a pack buffer), else from the copy.
 *
 * Which buffer is bound is asked of GL where a live context has buffer
 * objects (rgl_buffer_binding: one glGetIntegerv per pointer call, pixel
 * call or indexed draw, never per vertex): the recorder's own tracking
 * misses bindings GL changes by itself (glPopClientAttrib, a vertex array
 * object, another context), and mistaking an offset for an address would
 * crash the program. Without a context the tracking is all there is.
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
    switch (target) {
    case GL_ARRAY_BUFFER: return &s->array_buffer;
    case GL_ELEMENT_ARRAY_BUFFER: return &s->element_buffer;
    case GL_PIXEL_UNPACK_BUFFER: return &s->unpack_buffer;
    case GL_PIXEL_PACK_BUFFER: return &s->pack_buffer;
    default: return NULL;
    }
}

/* ---- What GL says ---------------------------------------------------------- */

enum { CAP_LIVE = 1, CAP_VBO = 2, CAP_PBO = 4 };

/* Whether `ext` is a whole name in the extension string. */
static bool has_extension(const char *all, const char *ext)
{
    size_t n = strlen(ext);
    for (const char *p = all; p && (p = strstr(p, ext)) != NULL; p += n)
        if ((p == all || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    return false;
}

/* What the current context has: CAP_LIVE when there is one, CAP_VBO for
 * buffer objects (GL 1.5, ES 1.1, ARB_vertex_buffer_object), CAP_PBO for
 * pixel buffers (GL 2.1, ES 3.0, ARB/EXT_pixel_buffer_object). Their
 * binding queries are GL errors without them. glGetString is not allowed
 * between glBegin and glEnd: callers check first. */
static unsigned gl_caps(void)
{
    const char *v = (const char *)glGetString(GL_VERSION);
    if (!v)
        return 0;
    bool es = strncmp(v, "OpenGL ES", 9) == 0;
    while (*v && (*v < '0' || *v > '9'))
        v++;
    int major = 0, minor = 0;
    for (; *v >= '0' && *v <= '9'; v++)
        major = major * 10 + (*v - '0');
    if (*v == '.')
        for (v++; *v >= '0' && *v <= '9'; v++)
            minor = minor * 10 + (*v - '0');
    unsigned caps = CAP_LIVE;
    int ver = major * 10 + (minor > 9 ? 9 : minor);
    if (es ? ver >= 11 : ver >= 15)
        caps |= CAP_VBO;
    if (es ? ver >= 30 : ver >= 21)
        caps |= CAP_PBO;
    if (!es && ver < 21) { /* before 3.0: the extension string is valid */
        const char *ext = (const char *)glGetString(GL_EXTENSIONS);
        if (has_extension(ext, "GL_ARB_vertex_buffer_object"))
            caps |= CAP_VBO;
        if (has_extension(ext, "GL_ARB_pixel_buffer_object") ||
            has_extension(ext, "GL_EXT_pixel_buffer_object"))
            caps |= CAP_PBO;
    }
    return caps;
}

uint32_t rgl_buffer_binding(rgl_stream *s, GLenum target)
{
    uint32_t *slot = binding(s, target);
    uint32_t tracked = slot ? *slot : 0;
    if (s->in_begin)
        return tracked;
    GLenum pname;
    unsigned need;
    switch (target) {
    case GL_ARRAY_BUFFER: pname = GL_ARRAY_BUFFER_BINDING; need = CAP_VBO; break;
    case GL_ELEMENT_ARRAY_BUFFER: pname = GL_ELEMENT_ARRAY_BUFFER_BINDING; need = CAP_VBO; break;
    case GL_PIXEL_UNPACK_BUFFER: pname = GL_PIXEL_UNPACK_BUFFER_BINDING; need = CAP_PBO; break;
    default: return tracked;
    }
    /* What a live context has is asked once a frame (glGetString costs
     * three times the binding query in Mesa): a thread that makes a
     * context of another GL version current within a frame gets the first
     * one's answer until the next frame. Whether there is a context at all
     * is seen at every call: the query leaves its output alone without. */
    unsigned caps = s->frame_open ? s->gl_caps : 0;
    if (!caps) {
        caps = gl_caps();
        if (!(caps & CAP_LIVE))
            return tracked;
        if (s->frame_open)
            s->gl_caps = caps;
    }
    if (!(caps & need))
        return 0; /* GL has no such binding: the pointer is an address */
    GLint b = -1;
    glGetIntegerv(pname, &b);
    return b == -1 ? tracked : (uint32_t)b;
}

bool rgl_buffer_live(void) { return gl_caps() & CAP_LIVE; }

bool rgl_buffer_gather(uint32_t target, uint32_t name, bool live, uint64_t offset,
                       uint64_t stride, size_t row, size_t rows, uint8_t *out)
{
    uint64_t end;
    if (rows == 0 || row == 0)
        return true;
    if (__builtin_mul_overflow((uint64_t)(rows - 1), stride, &end) ||
        __builtin_add_overflow(end, offset, &end) || __builtin_add_overflow(end, row, &end))
        return false;
    if (live) {
        GLint size = 0, mapped = GL_TRUE;
        glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
        glGetBufferParameteriv(target, GL_BUFFER_MAPPED, &mapped);
        if (mapped || size < 0 || end > (uint64_t)size)
            return false;
        if (stride == row) {
            glGetBufferSubData(target, (GLintptr)offset, (GLsizeiptr)(row * rows), out);
        } else {
            for (size_t y = 0; y < rows; y++)
                glGetBufferSubData(target, (GLintptr)(offset + y * stride), (GLsizeiptr)row,
                                   out + y * row);
        }
        return true;
    }
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = find(name, false);
    /* GL takes no pixels from a mapped buffer (GL 2.1, 2.9.3). */
    bool ok = b && b->data && !b->mapped && end <= b->size;
    for (size_t y = 0; ok && y < rows; y++)
        memcpy(out + y * row, b->data + offset + y * stride, row);
    pthread_mutex_unlock(&bufs.mu);
    return ok;
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
        uint32_t *slots[4] = {&s->array_buffer, &s->element_buffer, &s->unpack_buffer,
                              &s->pack_buffer};
        for (int j = 0; j < 4; j++)
            if (names[k] && *slots[j] == names[k])
                *slots[j] = 0;
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
    /* The binding is kept while not recording too (a trace opened later
     * must not take an offset for an address); the object is made then. */
    rgl_stream *s;
    bool rec = rgl_reserve(&s, 1) != NULL;
    if (!rec)
        s = rgl_tls_stream;
    uint32_t *slot = s ? binding(s, target) : NULL;
    if (!slot)
        return; /* another target: not recorded (it feeds no fixed-function call) */
    *slot = buffer;
    if (!rec)
        return;
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
/* The buffer a data call on target changes: GL's answer with a live
 * context (rgl_buffer_binding), 0 for a target RayGL does not keep. Asked
 * before bufs.mu is taken. */
static uint32_t bound_name(rgl_stream *s, GLenum target)
{
    return binding(s, target) ? rgl_buffer_binding(s, target) : 0;
}

/* The object of a name from bound_name, or NULL (bufs.mu held). */
static buffer_obj *bound(uint32_t name) { return name ? find(name, true) : NULL; }

/* GL 1.5 table 2.7: a usage GL refuses (INVALID_ENUM) reads no data. */
static bool usage_ok(GLenum usage)
{
    return usage >= GL_STREAM_DRAW && usage <= GL_DYNAMIC_COPY && usage != 0x88E3 &&
           usage != 0x88E7;
}

static void buffer_data(uint32_t op, GLenum target, GLsizeiptr size, const void *data,
                        GLenum usage)
{
    rgl_stream *s;
    if (size < 0 || !usage_ok(usage) || !rgl_reserve(&s, 1) || s->in_begin)
        return;
    uint32_t name = bound_name(s, target);
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(name);
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
    if (offset < 0 || size < 0 || !data || !rgl_reserve(&s, 1) || s->in_begin)
        return;
    uint32_t name = bound_name(s, target);
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(name);
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
    uint32_t name = bound_name(s, target);
    /* The mapping is as long as GL's buffer, which the copy may not be
     * (filled through a call RayGL does not see): unmap reads that many. */
    GLint size = -1;
    if (name && rgl_buffer_live())
        glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(name);
    if (b && size >= 0 && (size_t)size != b->size) {
        uint8_t *copy = rgl_realloc(b->data, size ? (size_t)size : 1);
        if (copy) {
            if ((size_t)size > b->size)
                memset(copy + b->size, 0, (size_t)size - b->size);
            b->data = copy;
            b->size = (size_t)size;
        } else {
            rgl_fail(ENOMEM, "allocation failed");
            b = NULL;
        }
    }
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
    uint32_t name = bound_name(s, target);
    pthread_mutex_lock(&bufs.mu);
    buffer_obj *b = bound(name);
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
