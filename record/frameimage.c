/* frameimage.c: the frame snapshot, the image the program showed, taken at
 * the frame's end when RAYGL_SNAPSHOTS=1 (or rayglRecordSnapshots(1)).
 *
 * Before the swap (or at the flush that ends a single-buffered frame) the
 * viewport rectangle of the buffer the program draws into is read with
 * glReadPixels as 8-bit RGBA, reduced to RGB, compressed with zlib at its
 * fastest level and written as a BYTES resource that an @Snapshot command,
 * the frame's last, names (docs/format.md 3.1). zlib rather than PNG: it is
 * all the recorder needs (libpng would add a library around the same
 * deflate), and the fastest level keeps the frame end short.
 *
 * GL errors: the snapshot never calls glGetError, which would read and
 * clear the program's own pending error. Instead it makes only calls that
 * cannot fail in the state it checks first: a live context, outside
 * glBegin/glEnd, no framebuffer object bound for drawing, a readable draw
 * buffer, queries only of enums the context's version has. Everything it
 * changes (read buffer, pixel pack state and pack buffer, pixel transfer
 * scales, biases and colour mapping) is read first and put back after.
 * rgl_read_rgba reads glCopyPixels' source rectangle the same way, from
 * the program's read buffer.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/gl.h>
#include <GL/glext.h>

#include "recorder.h"
#include "unrecorded.h"

#define SENTINEL_I 0x7ead7ead

/* The context's version and kind, from GL_VERSION ("4.5 (Compatibility
 * Profile) Mesa ...", "OpenGL ES 3.2 Mesa ..."). */
typedef struct gl_version {
    int major, minor;
    bool es;
    bool compat; /* the fixed-function pixel transfer state exists */
} gl_version;

static bool version_at_least(const gl_version *v, int major, int minor)
{
    return v->major > major || (v->major == major && v->minor >= minor);
}

static bool read_version(gl_version *v)
{
    const char *s = (const char *)glGetString(GL_VERSION);
    memset(v, 0, sizeof *v);
    if (!s)
        return false;
    if (strncmp(s, "OpenGL ES", 9) == 0) {
        v->es = true;
        s += 9;
        while (*s && (*s < '0' || *s > '9'))
            s++;
    }
    if (sscanf(s, "%d.%d", &v->major, &v->minor) != 2 || v->major < 1)
        return false;
    v->compat = !v->es;
    if (!v->es && version_at_least(v, 3, 2)) {
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        v->compat = (mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
    } else if (!v->es && v->major == 3 && v->minor == 1) {
        v->compat = false; /* 3.1 has it only with ARB_compatibility: assume not */
    }
    return true;
}

/* Pixel-pack and pixel-transfer state that glReadPixels obeys. */
static const GLenum pack_pnames[] = {GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS,
                                     GL_PACK_SKIP_PIXELS};
static const GLint pack_defaults[] = {4, 0, 0, 0};
#define NPACK (sizeof pack_pnames / sizeof pack_pnames[0])

static const GLenum transfer_pnames[] = {GL_RED_SCALE,  GL_GREEN_SCALE, GL_BLUE_SCALE,
                                         GL_ALPHA_SCALE, GL_RED_BIAS,   GL_GREEN_BIAS,
                                         GL_BLUE_BIAS,  GL_ALPHA_BIAS};
#define NTRANSFER (sizeof transfer_pnames / sizeof transfer_pnames[0])

typedef struct saved_state {
    GLint pack[NPACK];
    bool pack_changed[NPACK];
    GLfloat transfer[NTRANSFER];
    bool transfer_changed[NTRANSFER];
    GLboolean map_color;
    GLint pack_buffer;
    GLint read_buffer;
    bool set_read_buffer;
} saved_state;

/* The buffer to read: the one the program draws into, on the default
 * framebuffer. Returns false when there is none that can be read. */
static bool choose_read_buffer(const gl_version *v, GLint *buf)
{
    if (v->es) {
        *buf = GL_BACK; /* ES reads the default framebuffer's only colour buffer */
        return true;
    }
    if (version_at_least(v, 3, 0)) {
        GLint fbo = SENTINEL_I;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
        if (fbo != 0)
            return false;
        fbo = SENTINEL_I;
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &fbo);
        /* Reading the default framebuffer would take rebinding the
         * program's read framebuffer; a frame ending so is rare. */
        if (fbo != 0)
            return false;
    }
    GLint draw = SENTINEL_I;
    glGetIntegerv(GL_DRAW_BUFFER, &draw);
    switch (draw) {
    case GL_FRONT_AND_BACK: {
        GLboolean dbl = GL_FALSE;
        glGetBooleanv(GL_DOUBLEBUFFER, &dbl);
        *buf = dbl ? GL_BACK : GL_FRONT;
        return true;
    }
    case GL_FRONT: case GL_BACK: case GL_LEFT: case GL_RIGHT: case GL_FRONT_LEFT:
    case GL_FRONT_RIGHT: case GL_BACK_LEFT: case GL_BACK_RIGHT:
        *buf = draw;
        return true;
    default: /* GL_NONE, auxiliary buffers, or no answer */
        return false;
    }
}

static void save_and_set(const gl_version *v, saved_state *st, GLint read_buf)
{
    memset(st, 0, sizeof *st);
    bool es2 = v->es && v->major < 3;
    for (size_t k = 0; k < NPACK; k++) {
        if (es2 && pack_pnames[k] != GL_PACK_ALIGNMENT)
            continue;
        st->pack[k] = pack_defaults[k];
        glGetIntegerv(pack_pnames[k], &st->pack[k]);
        if (st->pack[k] != pack_defaults[k]) {
            st->pack_changed[k] = true;
            glPixelStorei(pack_pnames[k], pack_defaults[k]);
        }
    }
    if ((v->es && v->major >= 3) || (!v->es && version_at_least(v, 2, 1))) {
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &st->pack_buffer);
        if (st->pack_buffer != 0)
            glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    }
    if (v->compat) {
        for (size_t k = 0; k < NTRANSFER; k++) {
            GLfloat def = k < 4 ? 1.0f : 0.0f;
            st->transfer[k] = def;
            glGetFloatv(transfer_pnames[k], &st->transfer[k]);
            if (st->transfer[k] != def) {
                st->transfer_changed[k] = true;
                glPixelTransferf(transfer_pnames[k], def);
            }
        }
        glGetBooleanv(GL_MAP_COLOR, &st->map_color);
        if (st->map_color)
            glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    }
    if (!v->es) {
        st->read_buffer = SENTINEL_I;
        glGetIntegerv(GL_READ_BUFFER, &st->read_buffer);
        if (read_buf != SENTINEL_I && st->read_buffer != SENTINEL_I &&
            st->read_buffer != read_buf) {
            st->set_read_buffer = true;
            glReadBuffer((GLenum)read_buf);
        }
    }
}

static void restore(const saved_state *st)
{
    if (st->set_read_buffer)
        glReadBuffer((GLenum)st->read_buffer);
    if (st->map_color)
        glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    for (size_t k = 0; k < NTRANSFER; k++)
        if (st->transfer_changed[k])
            glPixelTransferf(transfer_pnames[k], st->transfer[k]);
    if (st->pack_buffer != 0)
        glBindBuffer(GL_PIXEL_PACK_BUFFER, (GLuint)st->pack_buffer);
    for (size_t k = 0; k < NPACK; k++)
        if (st->pack_changed[k])
            glPixelStorei(pack_pnames[k], st->pack[k]);
}

/* realloc semantics over the recorder's allocation wrapper, for zlib. */
static void *image_alloc(void *p, size_t n)
{
    if (n == 0) {
        rgl_free(p);
        return NULL;
    }
    return rgl_realloc(p, n);
}

bool rgl_read_rgba(int32_t x, int32_t y, int32_t w, int32_t h, uint8_t *px)
{
    gl_version v;
    if (!rgl_live_context() || !read_version(&v) || !v.compat)
        return false;
    saved_state st;
    save_and_set(&v, &st, SENTINEL_I); /* the program's read buffer, as glCopyPixels */
    glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    restore(&st);
    return true;
}

bool rgl_read_drawn_rgba(int32_t x, int32_t y, int32_t w, int32_t h, uint8_t *px)
{
    gl_version v;
    if (!rgl_live_context() || !read_version(&v) || !v.compat)
        return false;
    GLint buf;
    if (!choose_read_buffer(&v, &buf))
        return false;
    saved_state st;
    save_and_set(&v, &st, buf);
    glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    restore(&st);
    return true;
}

void rgl_frame_image(void)
{
    rgl_stream *s = rgl_tls_stream;
    if (!s || !rgl_snapshots_enabled() || s->image_taken || !s->frame_open || s->compiling ||
        s->in_begin || s->pos == s->base || !rgl_frame_wanted(s))
        return;
    s->image_taken = true;
    /* The snapshot stays the frame's last command: the counts go first. */
    rgl_unrecorded_flush(s, NULL);
    if (!rgl_live_context())
        return;
    gl_version v;
    if (!read_version(&v))
        return;
    GLint vp[4] = {0, 0, SENTINEL_I, SENTINEL_I};
    glGetIntegerv(GL_VIEWPORT, vp);
    if (vp[2] < 1 || vp[3] < 1 || vp[2] > RGL_SNAPSHOT_SIDE_MAX || vp[3] > RGL_SNAPSHOT_SIDE_MAX)
        return;
    GLint read_buf;
    if (!choose_read_buffer(&v, &read_buf))
        return;

    size_t npix = (size_t)vp[2] * (size_t)vp[3];
    uint8_t *px = rgl_alloc(npix * 4);
    if (!px) {
        rgl_fail(0, "allocation failed (frame snapshot)");
        return;
    }
    saved_state st;
    save_and_set(&v, &st, read_buf);
    glReadPixels(vp[0], vp[1], vp[2], vp[3], GL_RGBA, GL_UNSIGNED_BYTE, px);
    restore(&st);

    for (size_t i = 0; i < npix; i++)
        memmove(px + 3 * i, px + 4 * i, 3);
    uint8_t *z;
    size_t zsize;
    rgl_status zs = rgl_snapshot_encode(px, vp[2], vp[3], 1, image_alloc, &z, &zsize);
    rgl_free(px);
    if (zs != RGL_OK) {
        rgl_fail(0, "cannot compress the frame snapshot");
        return;
    }
    uint32_t id = rgl_resource_put(RGL_RES_BYTES, z, zsize);
    rgl_free(z);
    if (id)
        rgl_record(RGL_OP_Snapshot, "iiiieee", vp[0], vp[1], vp[2], vp[3],
                   (uint32_t)RGL_SNAPSHOT_FORMAT_RGB, (uint32_t)RGL_SNAPSHOT_CODEC_ZLIB, id);
}
