/* entry_custom.c: the hand-written recorder entry points (rows with gen
 * CUSTOM in format/commands.def).
 *
 * These are the calls whose arguments point at client memory of a size the
 * table cannot express (pixels, list names), that return names, or that
 * mark frame boundaries; the client arrays are entry_arrays.c's. Client
 * memory is copied into the trace: pixel data as resources, tightly
 * packed (pixels.c). Texture and
 * display-list objects are tracked per stream so the frame-start snapshot
 * can re-create them.
 *
 * As with the generated entry points, each call is recorded and then made
 * for real; a call GL would reject or fault on (a NULL pointer, a negative
 * count, an unknown type) is forwarded unrecorded, and none of its memory
 * is read: the recorder reads what GL reads, no more (docs/design.md, "As
 * safe as GL"). A call GL may carry out but the recorder cannot record
 * leaves @Skipped in its place.
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

#define RGL_NAMES_PER_RECORD RGL_ARRAY_MAX

/* ---- Helpers --------------------------------------------------------------- */

rgl_texture *rgl_texture_get(rgl_stream *s, uint32_t name, bool create)
{
    rgl_objects *o = &s->objs;
    for (size_t i = 0; i < o->ntextures; i++)
        if (o->textures[i].name == name)
            return &o->textures[i];
    if (!create)
        return NULL;
    if (o->ntextures == o->cap_textures) {
        size_t cap = o->cap_textures ? 2 * o->cap_textures : 16;
        rgl_texture *t = rgl_realloc(o->textures, cap * sizeof *t);
        if (!t) {
            rgl_fail(ENOMEM, "allocation failed");
            return NULL;
        }
        o->textures = t;
        o->cap_textures = cap;
    }
    rgl_texture *t = &o->textures[o->ntextures++];
    memset(t, 0, sizeof *t);
    t->name = name;
    return t;
}

static void texture_forget(rgl_stream *s, uint32_t name)
{
    rgl_objects *o = &s->objs;
    for (size_t i = 0; i < o->ntextures; i++) {
        if (o->textures[i].name == name) {
            rgl_buf_finish(&o->textures[i].defs);
            o->textures[i] = o->textures[--o->ntextures];
            return;
        }
    }
}

/* Whether a call made now takes effect now: not while a list is compiled
 * with GL_COMPILE (GL stores it in the list instead). Client-state calls
 * and the object-name calls always execute at once. */
static bool executes(const rgl_stream *s)
{
    return !s->compiling || s->list_mode == GL_COMPILE_AND_EXECUTE;
}


/* The texture object bound to target (a cube-map face: the cube map) on
 * the active unit in s, created on first use. */
static rgl_texture *bound_texture(rgl_stream *s, GLenum target)
{
    int slot = rgl_tex_slot(target);
    if (slot < 0)
        return NULL;
    rgl_texture *t = rgl_texture_get(s, s->objs.bound[rgl_tex_active_unit(s)][slot], true);
    if (t && !t->target)
        t->target = rgl_tex_slot_target(slot);
    return t;
}

/* Appends the bytes just committed to the stream, [from, s->pos), to the
 * texture's definition; `reset` starts the definition afresh (level 0 or a
 * whole mipmap chain replaces what was there). */
static void texture_define(rgl_stream *s, GLenum target, const uint8_t *from, bool reset)
{
    if (!executes(s))
        return;
    rgl_texture *t = bound_texture(s, target);
    if (!t)
        return;
    /* A cube map's faces are defined one by one: a new +X face starts its
     * definition afresh, the other faces add to it. */
    if (target > GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z)
        reset = false;
    if (reset)
        t->defs.size = 0;
    size_t n = (size_t)(s->pos - from);
    uint8_t *p = rgl_buf_reserve(&t->defs, n);
    if (p)
        rgl_buf_commit(&t->defs, (uint8_t *)memcpy(p, from, n) + n);
}

static void texture_param(GLenum target, GLenum pname, bool is_float, const GLfloat *f,
                          const GLint *i, uint32_t count)
{
    rgl_stream *s = rgl_tls_stream;
    if (!s || !executes(s) || count == 0 || count > 4)
        return;
    rgl_texture *t = bound_texture(s, target);
    if (!t)
        return;
    rgl_tex_param *p = NULL;
    for (uint32_t k = 0; k < t->nparams; k++)
        if (t->params[k].pname == pname)
            p = &t->params[k];
    if (!p) {
        if (t->nparams == RGL_TEX_PARAMS_MAX)
            return;
        p = &t->params[t->nparams++];
    }
    p->pname = pname;
    p->count = (uint8_t)count;
    p->is_float = is_float;
    for (uint32_t k = 0; k < count; k++) {
        if (is_float)
            p->f[k] = f[k];
        else
            p->i[k] = i[k];
    }
}

/* ---- Textures -------------------------------------------------------------- */

RGL_EXPORT void rayglGenTextures(GLsizei n, GLuint *textures)
{
    if (n <= 0 || !textures) {
        glGenTextures(n, textures);
        return;
    }
    memset(textures, 0, (size_t)n * sizeof *textures);
    glGenTextures(n, textures);
    rgl_stream *s;
    if (!rgl_reserve(&s, 1))
        return;
    /* Names stay 0 when GL has no context: RayGL names them itself, so a
     * batch program still gets distinct textures. */
    if (textures[0] == 0) {
        for (GLsizei k = 0; k < n; k++)
            textures[k] = ++s->objs.next_texture_name;
    }
    for (GLsizei k = 0; k < n; k += RGL_NAMES_PER_RECORD) {
        int m = n - k < RGL_NAMES_PER_RECORD ? (int)(n - k) : RGL_NAMES_PER_RECORD;
        rgl_record(RGL_OP_GenTextures, "U", textures + k, m);
    }
}

RGL_EXPORT void rayglDeleteTextures(GLsizei n, const GLuint *textures)
{
    rgl_stream *s;
    if (n > 0 && textures && rgl_reserve(&s, 1)) {
        for (GLsizei k = 0; k < n; k += RGL_NAMES_PER_RECORD) {
            int m = n - k < RGL_NAMES_PER_RECORD ? (int)(n - k) : RGL_NAMES_PER_RECORD;
            rgl_record(RGL_OP_DeleteTextures, "U", textures + k, m);
        }
        for (GLsizei k = 0; k < n; k++) {
            if (textures[k] == 0)
                continue;
            texture_forget(s, textures[k]);
            /* Deleting a bound texture binds 0 (GL 1.5, 3.8.12). */
            for (int u = 0; u < RGL_MAX_TEX_UNITS; u++)
                for (int b = 0; b < RGL_TEX_TARGETS; b++)
                    if (s->objs.bound[u][b] == textures[k])
                        s->objs.bound[u][b] = 0;
        }
    }
    glDeleteTextures(n, textures);
}

static void bind_texture(uint32_t op, GLenum target, GLuint texture)
{
    int slot = rgl_tex_slot(target);
    rgl_stream *s;
    /* A cube-map face is no target of glBindTexture. */
    if (slot >= 0 && target == rgl_tex_slot_target(slot) && rgl_reserve(&s, 1)) {
        if (executes(s) && !s->in_begin) {
            s->objs.bound[rgl_tex_active_unit(s)][slot] = texture;
            rgl_texture *t = rgl_texture_get(s, texture, true);
            if (t && !t->target)
                t->target = target;
        }
        rgl_record(op, "ee", target, texture);
    }
    glBindTexture(target, texture);
}

RGL_EXPORT void rayglBindTexture(GLenum target, GLuint texture)
{
    bind_texture(RGL_OP_BindTexture, target, texture);
}

/* Forwarded to the core function, which gl.xml makes the same. */
RGL_EXPORT void rayglBindTextureEXT(GLenum target, GLuint texture)
{
    bind_texture(RGL_OP_BindTextureEXT, target, texture);
}

/* A texture's definition past this many bytes of records is read back from
 * GL and replaced by one image per level: a texture updated every frame
 * would otherwise make every snapshot longer than the last. */
#define RGL_TEX_DEFS_COMPACT 4096

/* Level `level` of `target` (a cube map's face for a cube map) read back as
 * GL_RGBA / GL_UNSIGNED_BYTE and appended to defs as the glTexImage that
 * makes it. Returns false when the level is empty; *ok false on failure. */
static bool compact_level(rgl_buf *defs, GLenum target, GLint level, bool *ok)
{
    GLint w = 0, h = 0, d = 1, fmt = 0, border = 0;
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
    if (target == GL_TEXTURE_3D)
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_DEPTH, &d);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_BORDER, &border);
    if (w <= 0 || h <= 0 || d <= 0)
        return false;
    size_t bytes = (size_t)w * (size_t)h * (size_t)d * 4;
    if (bytes > RGL_CHUNK_MAX_PAYLOAD) { /* no resource holds it: keep the records */
        *ok = false;
        return false;
    }
    uint8_t *px = rgl_alloc(bytes);
    if (!px) {
        rgl_fail(ENOMEM, "allocation failed");
        *ok = false;
        return false;
    }
    glGetTexImage(target, level, GL_RGBA, GL_UNSIGNED_BYTE, px);
    uint32_t id = rgl_resource_put(RGL_RES_BYTES, px, bytes);
    rgl_free(px);
    if (target == GL_TEXTURE_1D)
        *ok = id && rgl_emit(defs, RGL_OP_TexImage1D, "eiiiieee", target, level, fmt, w, border,
                             GL_RGBA, GL_UNSIGNED_BYTE, id);
    else if (target == GL_TEXTURE_3D)
        *ok = id && rgl_emit(defs, RGL_OP_TexImage3D, "eiiiiiieee", target, level, fmt, w, h, d,
                             border, GL_RGBA, GL_UNSIGNED_BYTE, id);
    else
        *ok = id && rgl_emit(defs, RGL_OP_TexImage2D, "eiiiiieee", target, level, fmt, w, h,
                             border, GL_RGBA, GL_UNSIGNED_BYTE, id);
    return *ok;
}

/* Replaces the definition of the texture bound to target by its images read
 * back from a live context (GL_RGBA, GL_UNSIGNED_BYTE; every level, every
 * face of a cube map), once it has grown past RGL_TEX_DEFS_COMPACT. The
 * pack state is saved and restored. */
static void texture_compact(GLenum target)
{
    rgl_stream *s = rgl_tls_stream;
    int slot = rgl_tex_slot(target);
    if (!s || slot < 0 || !executes(s) || !rgl_live_context())
        return;
    rgl_texture *t = rgl_texture_get(s, s->objs.bound[rgl_tex_active_unit(s)][slot], false);
    if (!t || t->defs.size <= RGL_TEX_DEFS_COMPACT)
        return;
    GLenum obj = rgl_tex_slot_target(slot);
    /* The 3D ones only where 3D textures are (GL 1.2). */
    static const GLenum pack[6] = {GL_PACK_ALIGNMENT,  GL_PACK_ROW_LENGTH,
                                   GL_PACK_SKIP_ROWS,  GL_PACK_SKIP_PIXELS,
                                   GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES};
    int npack = obj == GL_TEXTURE_3D ? 6 : 4;
    GLint saved[6] = {4, 0, 0, 0, 0, 0};
    for (int k = 0; k < npack; k++) {
        glGetIntegerv(pack[k], &saved[k]);
        glPixelStorei(pack[k], k == 0 ? 4 : 0);
    }
    rgl_buf defs = {0};
    bool ok = true;
    bool cube = obj == GL_TEXTURE_CUBE_MAP;
    GLenum first = cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X : obj;
    GLenum last = cube ? GL_TEXTURE_CUBE_MAP_NEGATIVE_Z : obj;
    for (GLenum face = first; ok && face <= last; face++)
        /* A rectangle texture has level 0 only. */
        for (GLint level = 0; level < (obj == GL_TEXTURE_RECTANGLE_ARB ? 1 : 32); level++)
            if (!compact_level(&defs, face, level, &ok))
                break;
    for (int k = 0; k < npack; k++)
        glPixelStorei(pack[k], saved[k]);
    if (ok && defs.size) {
        rgl_buf_finish(&t->defs);
        t->defs = defs;
    } else {
        rgl_buf_finish(&defs);
    }
}

/* Room for one texture record: rgl_record then writes it at s->pos without
 * the buffer moving, so the record can be copied into the texture's
 * definition from there. */
#define RGL_TEX_RECORD_ROOM 128

void rgl_texture_defined(rgl_stream *s, uint32_t target, const uint8_t *from, bool reset)
{
    texture_define(s, target, from, reset);
    if (!reset)
        texture_compact(target);
}

RGL_EXPORT void rayglTexImage1D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                                GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1)) {
        int64_t id = rgl_tex_pixels(s, 1, false, target, level, internalFormat, 0, 0, width, 1,
                                    border, format, type, pixels);
        rgl_note_skipped(RGL_OP_TexImage1D, id);
        if (id >= 0 && rgl_reserve(&s, RGL_TEX_RECORD_ROOM)) {
            const uint8_t *from = s->pos;
            if (rgl_record(RGL_OP_TexImage1D, "eiiiieee", target, level, internalFormat, width,
                           border, format, type, (uint32_t)id) &&
                !rgl_tex_is_proxy(target))
                texture_define(s, target, from, level == 0);
        }
    }
    glTexImage1D(target, level, internalFormat, width, border, format, type, pixels);
}

RGL_EXPORT void rayglTexImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                                GLsizei height, GLint border, GLenum format, GLenum type,
                                const GLvoid *pixels)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1)) {
        int64_t id = rgl_tex_pixels(s, 2, false, target, level, internalFormat, 0, 0, width,
                                    height, border, format, type, pixels);
        rgl_note_skipped(RGL_OP_TexImage2D, id);
        if (id >= 0 && rgl_reserve(&s, RGL_TEX_RECORD_ROOM)) {
            const uint8_t *from = s->pos;
            if (rgl_record(RGL_OP_TexImage2D, "eiiiiieee", target, level, internalFormat, width,
                           height, border, format, type, (uint32_t)id) &&
                !rgl_tex_is_proxy(target))
                texture_define(s, target, from, level == 0);
        }
    }
    glTexImage2D(target, level, internalFormat, width, height, border, format, type, pixels);
    /* A cube map's faces add to its definition (texture_define): bounded
     * as sub-images are. */
    if (target > GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z)
        texture_compact(target);
}

static void tex_subimage2d(uint32_t op, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                           GLsizei width, GLsizei height, GLenum format, GLenum type,
                           const GLvoid *pixels)
{
    rgl_stream *s;
    if (rgl_reserve(&s, 1)) {
        int64_t id = rgl_tex_pixels(s, 2, true, target, level, 0, xoffset, yoffset, width,
                                    height, 0, format, type, pixels);
        rgl_note_skipped(op, id);
        if (id > 0 && rgl_reserve(&s, RGL_TEX_RECORD_ROOM)) {
            const uint8_t *from = s->pos;
            if (rgl_record(op, "eiiiiieee", target, level, xoffset, yoffset,
                           width, height, format, type, (uint32_t)id))
                texture_define(s, target, from, false);
        }
    }
    glTexSubImage2D(target, level, xoffset, yoffset, width, height, format, type, pixels);
    texture_compact(target);
}

RGL_EXPORT void rayglTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                   GLsizei width, GLsizei height, GLenum format, GLenum type,
                                   const GLvoid *pixels)
{
    tex_subimage2d(RGL_OP_TexSubImage2D, target, level, xoffset, yoffset, width, height, format,
                   type, pixels);
}

/* Forwarded to the core function (libOSMesa exports no glTexSubImage2DEXT). */
RGL_EXPORT void rayglTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                      GLsizei width, GLsizei height, GLenum format, GLenum type,
                                      const void *pixels)
{
    tex_subimage2d(RGL_OP_TexSubImage2DEXT, target, level, xoffset, yoffset, width, height,
                   format, type, pixels);
}

RGL_EXPORT GLint raygluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width,
                                      GLsizei height, GLenum format, GLenum type, const void *data)
{
    rgl_stream *s;
    if (data && rgl_reserve(&s, 1) && !s->in_begin) {
        int64_t id = rgl_glu_pixels(s, width, height, format, type, data);
        rgl_note_skipped(RGL_OP_Build2DMipmaps, id);
        if (id > 0 && rgl_reserve(&s, RGL_TEX_RECORD_ROOM)) {
            const uint8_t *from = s->pos;
            if (rgl_record(RGL_OP_Build2DMipmaps, "eiiieee", target, internalFormat, width,
                           height, format, type, (uint32_t)id))
                texture_define(s, target, from, true);
        }
    }
    return gluBuild2DMipmaps(target, internalFormat, width, height, format, type, data);
}

RGL_EXPORT void rayglTexParameterf(GLenum target, GLenum pname, GLfloat param)
{
    if (rgl_record(RGL_OP_TexParameterf, "eef", target, pname, (double)param))
        texture_param(target, pname, true, &param, NULL, 1);
    glTexParameterf(target, pname, param);
}

RGL_EXPORT void rayglTexParameteri(GLenum target, GLenum pname, GLint param)
{
    if (rgl_record(RGL_OP_TexParameteri, "eei", target, pname, param))
        texture_param(target, pname, false, NULL, &param, 1);
    glTexParameteri(target, pname, param);
}

RGL_EXPORT void rayglTexParameterfv(GLenum target, GLenum pname, const GLfloat *params)
{
    uint32_t n = rgl_pname_count_in(RGL_PN_TEX_PARAMETER, pname);
    if (params && n <= RGL_ARRAY_MAX &&
        rgl_record(RGL_OP_TexParameterfv, "eeN", target, pname, params, (int)n))
        texture_param(target, pname, true, params, NULL, n);
    glTexParameterfv(target, pname, params);
}

RGL_EXPORT void rayglTexParameteriv(GLenum target, GLenum pname, const GLint *params)
{
    uint32_t n = rgl_pname_count_in(RGL_PN_TEX_PARAMETER, pname);
    if (params && n <= RGL_ARRAY_MAX &&
        rgl_record(RGL_OP_TexParameteriv, "eeI", target, pname, params, (int)n))
        texture_param(target, pname, false, NULL, params, n);
    glTexParameteriv(target, pname, params);
}

/* ---- Display lists --------------------------------------------------------- */

static void list_forget(rgl_stream *s, uint32_t lo, uint64_t hi)
{
    rgl_objects *o = &s->objs;
    for (size_t i = 0; i < o->nlists;) {
        if (o->lists[i].name >= lo && o->lists[i].name < hi)
            o->lists[i] = o->lists[--o->nlists];
        else
            i++;
    }
}

static void list_remember(rgl_stream *s, uint32_t name, uint32_t body)
{
    rgl_objects *o = &s->objs;
    for (size_t i = 0; i < o->nlists; i++) {
        if (o->lists[i].name == name) {
            o->lists[i].body = body;
            return;
        }
    }
    if (o->nlists == o->cap_lists) {
        size_t cap = o->cap_lists ? 2 * o->cap_lists : 16;
        rgl_list_rec *l = rgl_realloc(o->lists, cap * sizeof *l);
        if (!l) {
            rgl_fail(ENOMEM, "allocation failed");
            return;
        }
        o->lists = l;
        o->cap_lists = cap;
    }
    o->lists[o->nlists++] = (rgl_list_rec){name, body};
}

RGL_EXPORT GLuint rayglGenLists(GLsizei range)
{
    GLuint first = glGenLists(range);
    rgl_stream *s;
    if (range > 0 && rgl_reserve(&s, 1)) {
        /* Without a context GL returns 0: RayGL names the lists itself. */
        if (first == 0 && !rgl_live_context()) {
            first = s->objs.next_list_name + 1;
            s->objs.next_list_name += (uint32_t)range;
        }
        if (first)
            RECORD_NOW(s, RGL_OP_GenLists, "ie", range, first);
    }
    return first;
}

RGL_EXPORT void rayglNewList(GLuint list, GLenum mode)
{
    rgl_stream *s;
    if (list != 0 && (mode == GL_COMPILE || mode == GL_COMPILE_AND_EXECUTE) &&
        rgl_reserve(&s, 1) && !s->compiling)
        rgl_list_compile_begin(s, list, mode);
    glNewList(list, mode);
}

RGL_EXPORT void rayglEndList(void)
{
    rgl_stream *s = rgl_tls_stream;
    if (s && s->compiling) {
        uint32_t name = s->list_name, mode = s->list_mode;
        const rgl_buf *body = rgl_list_compile_end(s);
        uint32_t id = rgl_resource_put(RGL_RES_COMMANDS, body->data, body->size);
        /* The list is recorded where it ends, NewList carrying its body. */
        if (id && rgl_record(RGL_OP_NewList, "eee", name, mode, id) &&
            rgl_record(RGL_OP_EndList, ""))
            list_remember(s, name, id);
    }
    glEndList();
}

RGL_EXPORT void rayglCallLists(GLsizei n, GLenum type, const GLvoid *lists)
{
    size_t ts;
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: ts = 1; break;
    case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_2_BYTES: ts = 2; break;
    case GL_3_BYTES: ts = 3; break;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: case GL_4_BYTES: ts = 4; break;
    default: ts = 0; break;
    }
    if (ts && n >= 0 && lists) {
        rgl_resolve_matrices();
        rgl_record(RGL_OP_CallLists, "ieB", n, type, lists, (size_t)n * ts);
    }
    glCallLists(n, type, lists);
}

RGL_EXPORT void rayglDeleteLists(GLuint list, GLsizei range)
{
    rgl_stream *s;
    if (range >= 0 && rgl_reserve(&s, 1)) {
        RECORD_NOW(s, RGL_OP_DeleteLists, "ei", list, range);
        list_forget(s, list, (uint64_t)list + (uint64_t)range);
    }
    glDeleteLists(list, range);
}

/* ---- Quadrics -------------------------------------------------------------- */

/* GLU quadric objects are process-wide pointers; the trace names them by
 * small ids. A quadric made by plain gluNewQuadric gets an id when first
 * seen. The table also keeps each quadric's state (GLU has no query for
 * it): a shape compiled into a display list is drawn by GLU with the state
 * of compile time, so the body carries that state (docs/format.md 3.2), and
 * the frame-start snapshot re-creates the quadrics with theirs. */
typedef struct quad_entry {
    const GLUquadric *q;
    uint32_t id;
    uint32_t draw, normals, orientation, texture;
} quad_entry;

static struct {
    pthread_mutex_t mu;
    quad_entry *v;
    size_t n, cap;
    uint32_t next;
} quads = {.mu = PTHREAD_MUTEX_INITIALIZER};

/* The entry of q, added with GLU's initial state when new; NULL when out
 * of memory. Called with quads.mu held. */
static quad_entry *quad_find(const GLUquadric *q)
{
    for (size_t i = 0; i < quads.n; i++)
        if (quads.v[i].q == q)
            return &quads.v[i];
    if (quads.n == quads.cap) {
        size_t cap = quads.cap ? 2 * quads.cap : 8;
        quad_entry *v = rgl_realloc(quads.v, cap * sizeof *v);
        if (!v)
            return NULL;
        quads.v = v;
        quads.cap = cap;
    }
    quads.v[quads.n] = (quad_entry){q, ++quads.next, GLU_FILL, GLU_SMOOTH, GLU_OUTSIDE, 0};
    return &quads.v[quads.n++];
}

static uint32_t quad_id(const GLUquadric *q, bool forget)
{
    uint32_t id = 0;
    pthread_mutex_lock(&quads.mu);
    if (forget) {
        for (size_t i = 0; i < quads.n; i++)
            if (quads.v[i].q == q) {
                id = quads.v[i].id;
                quads.v[i] = quads.v[--quads.n];
                break;
            }
    } else {
        quad_entry *e = quad_find(q);
        id = e ? e->id : 0;
    }
    pthread_mutex_unlock(&quads.mu);
    return id;
}

/* Keeps what GLU accepts (an invalid value leaves the quadric unchanged). */
static void quad_track(const GLUquadric *q, uint32_t op, uint32_t v)
{
    pthread_mutex_lock(&quads.mu);
    quad_entry *e = quad_find(q);
    if (e) {
        if (op == RGL_OP_QuadricDrawStyle &&
            (v == GLU_FILL || v == GLU_LINE || v == GLU_SILHOUETTE || v == GLU_POINT))
            e->draw = v;
        else if (op == RGL_OP_QuadricNormals && (v == GLU_NONE || v == GLU_FLAT || v == GLU_SMOOTH))
            e->normals = v;
        else if (op == RGL_OP_QuadricOrientation && (v == GLU_OUTSIDE || v == GLU_INSIDE))
            e->orientation = v;
        else if (op == RGL_OP_QuadricTexture)
            e->texture = v != 0;
    }
    pthread_mutex_unlock(&quads.mu);
}

/* Writes the state of quadric e as its state commands into b (b NULL: the
 * calling thread's stream). Called with quads.mu held. */
static void quad_emit_state(rgl_buf *b, const quad_entry *e)
{
    if (b) {
        rgl_emit(b, RGL_OP_QuadricDrawStyle, "ee", e->id, e->draw);
        rgl_emit(b, RGL_OP_QuadricNormals, "ee", e->id, e->normals);
        rgl_emit(b, RGL_OP_QuadricOrientation, "ee", e->id, e->orientation);
        rgl_emit(b, RGL_OP_QuadricTexture, "eo", e->id, (int)e->texture);
    } else {
        rgl_record(RGL_OP_QuadricDrawStyle, "ee", e->id, e->draw);
        rgl_record(RGL_OP_QuadricNormals, "ee", e->id, e->normals);
        rgl_record(RGL_OP_QuadricOrientation, "ee", e->id, e->orientation);
        rgl_record(RGL_OP_QuadricTexture, "eo", e->id, (int)e->texture);
    }
}

void rgl_quadrics_snapshot(rgl_buf *b)
{
    pthread_mutex_lock(&quads.mu);
    for (size_t i = 0; i < quads.n; i++) {
        rgl_emit(b, RGL_OP_NewQuadric, "e", quads.v[i].id);
        quad_emit_state(b, &quads.v[i]);
    }
    pthread_mutex_unlock(&quads.mu);
}

/* Before a shape drawn into a list being compiled: the quadric's state
 * now, into the body. Returns the quadric's id (0: none). */
static uint32_t quad_shape(rgl_stream *s, const GLUquadric *q)
{
    if (!s->compiling)
        return quad_id(q, false);
    uint32_t id = 0;
    pthread_mutex_lock(&quads.mu);
    quad_entry *e = quad_find(q);
    if (e) {
        id = e->id;
        quad_emit_state(NULL, e);
    }
    pthread_mutex_unlock(&quads.mu);
    return id;
}

/* The quadric calls are GLU client state, done at once even while a list
 * is compiled: recorded into the frame, never into a list body. */
RGL_EXPORT GLUquadric *raygluNewQuadric(void)
{
    GLUquadric *q = gluNewQuadric();
    rgl_stream *s;
    if (q && rgl_reserve(&s, 1))
        RECORD_NOW(s, RGL_OP_NewQuadric, "e", quad_id(q, false));
    return q;
}

RGL_EXPORT void raygluDeleteQuadric(GLUquadric *quad)
{
    rgl_stream *s;
    if (quad && rgl_reserve(&s, 1))
        RECORD_NOW(s, RGL_OP_DeleteQuadric, "e", quad_id(quad, true));
    else if (quad)
        quad_id(quad, true);
    gluDeleteQuadric(quad);
}

/* The quadric state calls share one shape: handle, then one enum. */
static void quadric_state(uint32_t op, const GLUquadric *quad, GLenum value)
{
    rgl_stream *s;
    if (!quad)
        return;
    quad_track(quad, op, value);
    if (rgl_reserve(&s, 1))
        RECORD_NOW(s, op, "ee", quad_id(quad, false), value);
}

RGL_EXPORT void raygluQuadricDrawStyle(GLUquadric *quad, GLenum draw)
{
    quadric_state(RGL_OP_QuadricDrawStyle, quad, draw);
    gluQuadricDrawStyle(quad, draw);
}

RGL_EXPORT void raygluQuadricNormals(GLUquadric *quad, GLenum normal)
{
    quadric_state(RGL_OP_QuadricNormals, quad, normal);
    gluQuadricNormals(quad, normal);
}

RGL_EXPORT void raygluQuadricOrientation(GLUquadric *quad, GLenum orientation)
{
    quadric_state(RGL_OP_QuadricOrientation, quad, orientation);
    gluQuadricOrientation(quad, orientation);
}

RGL_EXPORT void raygluQuadricTexture(GLUquadric *quad, GLboolean texture)
{
    rgl_stream *s;
    if (quad) {
        quad_track(quad, RGL_OP_QuadricTexture, texture);
        if (rgl_reserve(&s, 1))
            RECORD_NOW(s, RGL_OP_QuadricTexture, "eo", quad_id(quad, false), (int)texture);
    }
    gluQuadricTexture(quad, texture);
}

/* The shapes draw: the matrices first, then the shape itself (never the
 * triangles GLU draws for it, which go to GL directly). */
RGL_EXPORT void raygluSphere(GLUquadric *quad, GLdouble radius, GLint slices, GLint stacks)
{
    if (quad) {
        rgl_resolve_matrices();
        rgl_stream *s;
        if (rgl_reserve(&s, 1))
            rgl_record(RGL_OP_Sphere, "edii", quad_shape(s, quad), radius, slices, stacks);
    }
    gluSphere(quad, radius, slices, stacks);
}

RGL_EXPORT void raygluCylinder(GLUquadric *quad, GLdouble base, GLdouble top, GLdouble height,
                               GLint slices, GLint stacks)
{
    if (quad) {
        rgl_resolve_matrices();
        rgl_stream *s;
        if (rgl_reserve(&s, 1))
            rgl_record(RGL_OP_Cylinder, "edddii", quad_shape(s, quad), base, top, height, slices,
                       stacks);
    }
    gluCylinder(quad, base, top, height, slices, stacks);
}

RGL_EXPORT void raygluDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices,
                           GLint loops)
{
    if (quad) {
        rgl_resolve_matrices();
        rgl_stream *s;
        if (rgl_reserve(&s, 1))
            rgl_record(RGL_OP_Disk, "eddii", quad_shape(s, quad), inner, outer, slices, loops);
    }
    gluDisk(quad, inner, outer, slices, loops);
}

RGL_EXPORT void raygluPartialDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices,
                                  GLint loops, GLdouble start, GLdouble sweep)
{
    if (quad) {
        rgl_resolve_matrices();
        rgl_stream *s;
        if (rgl_reserve(&s, 1))
            rgl_record(RGL_OP_PartialDisk, "eddiidd", quad_shape(s, quad), inner, outer, slices,
                       loops, start, sweep);
    }
    gluPartialDisk(quad, inner, outer, slices, loops, start, sweep);
}

/* ---- Frames ---------------------------------------------------------------- */

RGL_EXPORT void rayglutSwapBuffers(void)
{
    rgl_record(RGL_OP_SwapBuffers, "");
    rgl_frame_image();
    if (rgl_glut_ready())
        glutSwapBuffers();
    rgl_frame_end();
}

RGL_EXPORT void rayglFrameBegin(const char *file, GLfloat locx, GLfloat locy, GLfloat locz,
                                GLfloat lookx, GLfloat looky, GLfloat lookz, GLfloat lightx,
                                GLfloat lighty, GLfloat lightz)
{
    rgl_stream *s = rgl_tls_stream;
    /* A named frame starts afresh: what was recorded before it is a frame
     * of its own. */
    if (s && s->frame_open) {
        size_t n = s->compiling ? s->frame.size : (size_t)(s->pos - s->base);
        if (n > 0)
            rgl_frame_end();
    }
    rgl_record(RGL_OP_FrameBegin, "Sfffffffff", file ? file : "", (double)locx, (double)locy,
               (double)locz, (double)lookx, (double)looky, (double)lookz, (double)lightx,
               (double)lighty, (double)lightz);
}

RGL_EXPORT void rayglFrameEnd(void)
{
    rgl_record(RGL_OP_FrameEnd, "");
    rgl_frame_end();
}
