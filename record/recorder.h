/* recorder.h: libraygl's internal interface between the entry points and
 * the recorder.
 *
 * Each thread records into its own stream (its GL context is current on that
 * thread only), so the hot path takes no lock: rgl_reserve() checks that the
 * thread's buffer has room, the caller encodes the command in place, and
 * rgl_commit() moves the write position. Everything else (starting a frame,
 * growing the buffer, opening the file, the failed state) happens in the
 * slow path, reached because `end` is pulled back to `pos` whenever the
 * next call needs attention.
 */
#ifndef RGL_RECORDER_H
#define RGL_RECORDER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "format.h"
#include "framesel.h"
#include "wire.h"

#if defined(__GNUC__)
#define RGL_LIKELY(x) __builtin_expect(!!(x), 1)
#define RGL_UNLIKELY(x) __builtin_expect(!!(x), 0)
#define RGL_EXPORT __attribute__((visibility("default")))
#else
#define RGL_LIKELY(x) (x)
#define RGL_UNLIKELY(x) (x)
#define RGL_EXPORT
#endif

/* GL's own limits, mirrored where the recorder needs them. */
#define RGL_MAX_CLIENT_ARRAYS 7 /* vertex, normal, color, texcoord, edge flag, fog coord, secondary */
#define RGL_MAX_EVAL_ORDER 30   /* Mesa's GL_MAX_EVAL_ORDER */
#define RGL_MAX_TEX_UNITS 8     /* Mesa's GL_MAX_TEXTURE_COORDS of GL 2.1 */

enum rgl_client_array {
    RGL_CA_VERTEX, RGL_CA_NORMAL, RGL_CA_COLOR, RGL_CA_TEXCOORD, RGL_CA_EDGEFLAG,
    RGL_CA_FOGCOORD, RGL_CA_SECONDARY,
};

typedef struct rgl_client_array_state {
    bool enabled;
    int32_t size;     /* components */
    uint32_t type;    /* GL type enum */
    int32_t stride;   /* as given (0 = tightly packed) */
    const void *pointer;
    uint32_t buffer;  /* GL_ARRAY_BUFFER bound at the pointer call: pointer
                         is then an offset into that buffer */
} rgl_client_array_state;

/* Buffer: a growable byte buffer that commands are encoded into. Its memory
 * belongs to rgl_buf_reserve (large ones are mapped apart): move the struct
 * whole, release it only with rgl_buf_finish. */
typedef struct rgl_buf {
    uint8_t *data;
    size_t size, cap;
    size_t pad; /* bytes before data in its own mapping (recorder.c) */
} rgl_buf;

/* Texture and display-list objects created through raygl calls, kept per
 * stream (one context per thread) so the snapshot can re-create them. */
#define RGL_TEX_PARAMS_MAX 16

/* Texture targets whose objects are kept: 1D, 2D, rectangle, 3D, cube map
 * (slots of rgl_tex_slot, snaptex.c). */
#define RGL_TEX_TARGETS 5
#define RGL_TEX_SLOT_RECT 2
#define RGL_TEX_SLOT_CUBE 4

typedef struct rgl_tex_param {
    uint32_t pname;
    uint8_t count;  /* values held */
    bool is_float;
    float f[4];
    int32_t i[4];
} rgl_tex_param;

typedef struct rgl_texture {
    uint32_t name;
    uint32_t target; /* 0 until first bound */
    rgl_buf defs;    /* TexImage/TexSubImage/Build2DMipmaps records, encoded */
    uint32_t nparams;
    rgl_tex_param params[RGL_TEX_PARAMS_MAX];
} rgl_texture;

typedef struct rgl_list_rec {
    uint32_t name;
    uint32_t body; /* resource id of its command sequence */
} rgl_list_rec;

typedef struct rgl_objects {
    rgl_texture *textures;
    size_t ntextures, cap_textures;
    rgl_list_rec *lists;
    size_t nlists, cap_lists;
    /* texture bound per unit to each target of rgl_tex_slot */
    uint32_t bound[RGL_MAX_TEX_UNITS][RGL_TEX_TARGETS];
    uint32_t next_texture_name; /* RayGL's own names when GL has no context */
    /* GL_UNPACK_SWAP_BYTES .. GL_UNPACK_ALIGNMENT (0x0CF0 .. 0x0CF5) as the
     * program set them (alignment 0: GL's 4), for recording without a
     * context. */
    int32_t unpack[6];
    uint32_t next_list_name;
} rgl_objects;

typedef struct rgl_stream {
    /* Hot: the write window of the current buffer. `end` may be pulled back
     * to `pos` to send the next call through rgl_reserve_slow(). */
    uint8_t *pos;
    uint8_t *end;

    uint8_t *base;      /* start of the buffer being written */
    uint8_t *limit;     /* true end of that buffer */
    rgl_buf frame;      /* the frame's commands (data == base unless compiling) */
    rgl_buf list;       /* a display list body while compiling */
    bool compiling;     /* between glNewList and glEndList */
    bool in_begin;      /* between glBegin and glEnd as GL executes them */
    uint32_t list_name, list_mode;

    uint32_t id;           /* stream id, from 1 */
    uint32_t frame_number; /* next frame's number within the stream */
    uint32_t shown;        /* frames the program ended, kept or not (RAYGL_FRAMES) */
    bool frame_open;       /* the current frame has started (snapshot taken) */
    bool image_taken;      /* rgl_frame_image() ran for the current frame */
    uint32_t frame_flags;  /* enum rgl_frame_flags */
    uint32_t state_resource;

    /* Matrices last recorded as @Matrix, to emit only changes. */
    bool have_matrix[2];
    float matrix[2][16]; /* [0] modelview, [1] projection */

    /* Calls of each unrecorded entry point since the stream's last written
     * frame, by id (unrecorded.h); written by the stream's thread only. */
    uint64_t *unrecorded;

    rgl_client_array_state arrays[RGL_MAX_CLIENT_ARRAYS]; /* texcoord: the client
                                                             active unit's */
    uint32_t client_unit; /* glClientActiveTexture */
    rgl_client_array_state tc_parked[RGL_MAX_TEX_UNITS]; /* the other units' texcoord
                                                            arrays (client_unit's: stale) */
    uint32_t array_buffer, element_buffer; /* buffer bindings (GL 1.5) */
    uint32_t unpack_buffer, pack_buffer;   /* pixel buffer bindings (GL 2.1) */
    uint32_t gl_caps; /* what the context has (entry_buffer.c), 0: not asked
                         in this frame yet */
    rgl_objects objs;

    /* Recorder bookkeeping (recorder.c): never touched on the hot path. */
    uint32_t gen;           /* trace generation the stream belongs to */
    rgl_buf snap;           /* scratch for the state snapshot */
    void *lock;             /* pthread_mutex_t: slow path vs close/exit */
    struct rgl_stream *next; /* all streams, for close and exit */
} rgl_stream;

#if defined(__GNUC__)
extern __thread rgl_stream *rgl_tls_stream __attribute__((tls_model("initial-exec")));
extern __thread int rgl_tls_passthrough __attribute__((tls_model("initial-exec")));
#else
extern _Thread_local rgl_stream *rgl_tls_stream;
extern _Thread_local int rgl_tls_passthrough;
#endif
/* rgl_tls_passthrough > 0: the thread is inside a real GLU or GLUT call
 * (libraygl-preload.so, preload.h); its calls are forwarded unrecorded. It
 * is raised with the stream's `end` pulled back, so the check costs the hot
 * path nothing. Always 0 in libraygl. */

/* Initialises the recorder (environment, fork and exit handlers, the
 * RAYGL_SIGNAL handler) ahead of the first recorded call. */
void rgl_recorder_init(void);

/* Initialises the recorder never to record: libraygl-preload.so in a
 * program that links libraygl, which records (preload.c). It then reads
 * neither the frame selection nor raygl record's variables, and sets no
 * signal handler. Before any other recorder call. */
void rgl_recorder_stand_down(void);

/* Slow path of rgl_reserve: initialises the recorder and the thread's stream
 * on first use, starts a frame (state snapshot), grows the buffer. Returns
 * the stream, with n bytes free at its pos, or NULL when not recording
 * (disabled, failed, fork child, passthrough). */
rgl_stream *rgl_reserve_slow(size_t n);

/* The calling thread's stream, created if need be (also before the trace
 * opens at the first recorded call), without starting a frame; NULL when
 * recording is off, closed or failed. For calls that count without
 * recording (unrecorded.h). */
rgl_stream *rgl_stream_current(void);

/* Room for n bytes in the calling thread's current buffer, or NULL when not
 * recording (*sp is NULL then). Encode into the returned pointer, then
 * rgl_commit(). The slow path takes no pointer to the caller's locals, so
 * the inlined fast path keeps everything in registers. */
static inline uint8_t *rgl_reserve(rgl_stream **sp, size_t n)
{
    rgl_stream *s = rgl_tls_stream;
    if (RGL_UNLIKELY(s == NULL || (size_t)(s->end - s->pos) < n)) {
        s = rgl_reserve_slow(n);
        if (!s) {
            *sp = NULL;
            return NULL;
        }
    }
    *sp = s;
    return s->pos;
}

static inline void rgl_commit(rgl_stream *s, uint8_t *p) { s->pos = p; }

static inline uint8_t *rgl_put_opcode(uint8_t *p, uint32_t opcode)
{
    if (opcode < 0x80)
        return rgl_put_u8(p, (uint8_t)opcode);
    return rgl_put_varint(p, opcode);
}

/* Before a call that draws: records @Matrix for the modelview and projection
 * read back from a live GL context when they differ from the last recorded
 * ones. No-op without a context, while compiling a list, or not recording. */
void rgl_resolve_matrices(void);

/* Ends the calling thread's frame: writes the FRAME chunk (one writev; a
 * large frame's whole blocks with O_DIRECT) under the file lock (the
 * frame's resources are already in the file), so it
 * is in the kernel when this returns and survives a crash right after; then
 * arranges for the next call to start a new frame. A frame with no commands
 * writes nothing. */
void rgl_frame_end(void);

/* The most items RAYGL_FRAMES may list (raygl record checks it). */
#define RGL_SEL_MAX 64

/* raygl record's side of the recorder (session.c). rgl_session_init reads
 * RAYGL_STATUS_FILE and RAYGL_EXIT (from the recorder's initialisation);
 * rgl_session_failed appends "failed" to the status file (after the
 * failure message); rgl_session_selection_over is called by
 * rgl_frame_end(), with no recorder lock held, after each frame end that
 * leaves the thread's stream no later frame to keep (the last frame of
 * RAYGL_FRAMES ended; with RAYGL_SIGNAL, a frame was kept): with
 * RAYGL_EXIT=1 it closes the trace and ends the program. */
void rgl_session_init(void);
void rgl_session_failed(void);
void rgl_session_selection_over(void);

/* Whether the frame s is recording will be kept when it ends (RAYGL_FRAMES,
 * RAYGL_EVERY, RAYGL_SIGNAL; `raygl record`); a dropped frame's image is
 * not read. */
bool rgl_frame_wanted(const rgl_stream *s);

/* Frame snapshots (frameimage.c): when enabled, reads the image the calling
 * thread's frame shows (the viewport of the buffer it draws into), and
 * records it as an @Snapshot command, the frame's last. Once per frame;
 * rgl_frame_end() calls it too, but a frame-ending entry point that swaps
 * buffers must call it BEFORE forwarding the swap (the back buffer is
 * undefined after it). Never raises or clears a GL error (frameimage.c). */
void rgl_frame_image(void);

/* Reads the w x h rectangle at x, y of the current read buffer as 8-bit
 * RGBA, bottom row first, into px (w * h * 4 bytes), with the pack and
 * transfer state at GL's defaults (put back after): what glCopyPixels
 * copies, before its pixel transfer (frameimage.c). False, px untouched,
 * without a live compatibility context. Outside glBegin/glEnd only. */
bool rgl_read_rgba(int32_t x, int32_t y, int32_t w, int32_t h, uint8_t *px);
/* The same from the buffer the program draws into (frameimage.c). */
bool rgl_read_drawn_rgba(int32_t x, int32_t y, int32_t w, int32_t h, uint8_t *px);

/* Whether frames get snapshots: RAYGL_SNAPSHOTS=1 at initialisation, or
 * rayglRecordSnapshots(). */
bool rgl_snapshots_enabled(void);

/* Switches the stream's write window to the display-list buffer (begin) or
 * back to the frame buffer (end). Returns the list body on end, owned by the
 * stream and valid until the next compile begins. Calling thread only. */
void rgl_list_compile_begin(rgl_stream *s, uint32_t list, uint32_t mode);
const rgl_buf *rgl_list_compile_end(rgl_stream *s);

/* Writes a resource chunk unless one with identical kind and bytes was
 * written before; returns its id (>= 1), or 0 when recording has failed. */
uint32_t rgl_resource_put(uint32_t kind, const void *data, size_t size);

/* Enters the sticky failed state: recording stops for every thread, GL
 * forwarding goes on, the error is kept for rayglRecordError() and reported
 * once. err is an errno value or 0; what names the failing step. */
void rgl_fail(int err, const char *what);

/* True once freeglut has been initialised (forwarding a GLUT shape before
 * glutInit would make freeglut exit the program). */
bool rgl_glut_ready(void);

/* Takes the resolved-state snapshot of a live context (record/snapshot.c):
 * encodes GL state as ordinary commands into out. Returns false when no live
 * context is current (nothing is written then). */
bool rgl_snapshot_take(rgl_stream *s, rgl_buf *out);

/* The context's colour buffers as @DrawBuffer's visual: 0 without a
 * context, else 1 | 2 double-buffered | 4 stereo (entry_raster.c). Not
 * between glBegin and glEnd. */
uint32_t rgl_draw_visual(void);

/* True when a GL context is current on the calling thread (a query that GL
 * without one leaves unanswered). */
bool rgl_live_context(void);

/* Buffer helpers. rgl_buf_reserve returns a pointer to n free bytes at the
 * end, growing the buffer, or NULL on allocation failure or when the buffer
 * would pass the largest chunk payload (the recorder has failed then). Write
 * there, then rgl_buf_commit() with the pointer past the last byte. */
uint8_t *rgl_buf_reserve(rgl_buf *b, size_t n);
static inline void rgl_buf_commit(rgl_buf *b, uint8_t *p) { b->size = (size_t)(p - b->data); }
void rgl_buf_finish(rgl_buf *b);

/* Encodes one command from a format string, for the hand-written records
 * (entry_custom.c, snapshot.c). Each character takes arguments:
 *   e  uint32_t, a plain varint (wire types e, ui, bf, h)
 *   i  int32_t, zigzag varint (wire types i, sz)
 *   f  double, written as float        d  double
 *   o  int, one byte (bo)          q  int64_t, zigzag varint64 (ip)
 *   A  const float *, int n: n floats, no count (an A() argument)
 *   N  const float *, int n: varint n, then n floats (an N() argument)
 *   I  const GLint *, int n: varint n, then n zigzag varints
 *   U  const GLuint *, int n: varint n, then n varints
 *   B  const void *, size_t n: a BLOB        S  const char *: a STR
 * rgl_emit appends to a buffer; rgl_record to the calling thread's stream.
 * Both return false when not recording or on failure (nothing written). */
bool rgl_emit(rgl_buf *b, uint32_t op, const char *fmt, ...);
bool rgl_record(uint32_t op, const char *fmt, ...);

/* Buffer objects (entry_buffer.c): the recorder's copy of buffer `name`
 * (NULL when there is none; *size its bytes). Takes the buffer table's
 * lock: call rgl_buffer_release() when done with the data. */
const uint8_t *rgl_buffer_acquire(uint32_t name, size_t *size);
void rgl_buffer_release(void);

/* The buffer bound to target (GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER,
 * GL_PIXEL_UNPACK_BUFFER) for a call about to be made on s's thread: GL's
 * own answer with a live context (0 when it has no such buffers), the
 * recorder's tracking without one or between glBegin and glEnd. Raises no
 * GL error. */
uint32_t rgl_buffer_binding(rgl_stream *s, uint32_t target);

/* Whether a GL context is current (checked through glGetString, which
 * raises no error outside glBegin/glEnd). */
bool rgl_buffer_live(void);

/* Copies `rows` rows of `row` bytes, `stride` apart from `offset` on, of
 * buffer `name` bound to target, tightly into out: read from GL when live
 * (the context is current; raises no GL error), else from the recorder's
 * copy. False, with nothing read, when GL would refuse to read them: the
 * buffer is mapped or the rows pass its end. */
bool rgl_buffer_gather(uint32_t target, uint32_t name, bool live, uint64_t offset,
                       uint64_t stride, size_t row, size_t rows, uint8_t *out);

/* GLU quadrics (entry_custom.c): every live quadric as NewQuadric and its
 * state commands, into b (the frame-start snapshot). */
void rgl_quadrics_snapshot(rgl_buf *b);

/* Records a call GL executes at once even while a list is compiled
 * (client state, list names, buffer objects): into the frame, never into
 * the list body. */
#define RECORD_NOW(s, op, ...) \
    ((s)->compiling ? rgl_emit(&(s)->frame, (op), __VA_ARGS__) : rgl_record((op), __VA_ARGS__))

/* Pixels (pixels.c). What a pixel call came to: a resource id (> 0), or
 * one of these. */
enum rgl_px_result {
    RGL_PX_NONE = 0,       /* no data: NULL pixels, an empty image, a proxy */
    RGL_PX_REFUSED = -1,   /* GL refuses the call and reads nothing, or recording failed */
    RGL_PX_SKIP_ENUM = -2, /* not recorded: an enum RayGL does not know */
    RGL_PX_SKIP_DATA = -3, /* not recorded: the data could not be read */
};

/* Writes the w x h image at pixels (laid out as the unpack state says) as a
 * tightly packed RGL_RES_BYTES resource, reading only what GL reads: from
 * client memory, or from the buffer bound to GL_PIXEL_UNPACK_BUFFER (glu:
 * for GLU, which reads client memory whatever is bound; a bound buffer is
 * then RGL_PX_SKIP_DATA). Calling thread's stream s, outside glBegin/glEnd. */
int64_t rgl_pixels_put(rgl_stream *s, uint32_t format, uint32_t type, int32_t w, int32_t h,
                       const void *pixels, bool glu);

/* The pixels of glTexImage1D/2D (sub false) or glTexSubImage2D (sub true;
 * internal unused): checked as GL checks target, level, sizes and border
 * first (with a live context also the largest size and a sub-image's
 * place), then rgl_pixels_put. A proxy reads nothing (RGL_PX_NONE). */
int64_t rgl_tex_pixels(rgl_stream *s, int dims, bool sub, uint32_t target, int32_t level,
                       int32_t internal, int32_t x, int32_t y, int32_t w, int32_t h,
                       int32_t border, uint32_t format, uint32_t type, const void *pixels);

/* The pixels of gluBuild2DMipmaps, after GLU's own checks. */
int64_t rgl_glu_pixels(rgl_stream *s, int32_t w, int32_t h, uint32_t format, uint32_t type,
                       const void *data);

/* The checks of rgl_tex_pixels alone, for a call that reads no client
 * memory (glCopyTexImage, glCopyTexSubImage): RGL_PX_NONE when GL takes
 * it, else RGL_PX_REFUSED or RGL_PX_SKIP_ENUM. */
int64_t rgl_tex_check(rgl_stream *s, int dims, bool sub, uint32_t target, int32_t level,
                      int32_t internal, int32_t x, int32_t y, int32_t w, int32_t h,
                      int32_t border);

/* The same for a 3D image (glTexImage3D, glTexSubImage3D at x, y, z;
 * glCopyTexSubImage3D with d 1): with a live context also the largest
 * size and a sub-image's place. */
int64_t rgl_tex_check3d(rgl_stream *s, bool sub, uint32_t target, int32_t level,
                        int32_t internal, int32_t x, int32_t y, int32_t z, int32_t w, int32_t h,
                        int32_t d, int32_t border);

/* The pixels of glTexImage3D (sub false) or glTexSubImage3D: rgl_tex_check3d,
 * then the w x h x d image read as GL reads it, GL_UNPACK_IMAGE_HEIGHT and
 * GL_UNPACK_SKIP_IMAGES included (read from a live context; GL's defaults
 * without one). Pixels in a GL_PIXEL_UNPACK_BUFFER: RGL_PX_SKIP_DATA. */
int64_t rgl_tex_pixels3d(rgl_stream *s, bool sub, uint32_t target, int32_t level,
                         int32_t internal, int32_t x, int32_t y, int32_t z, int32_t w, int32_t h,
                         int32_t d, int32_t border, uint32_t format, uint32_t type,
                         const void *pixels);

/* Appends the record just written from `from` to the definition of the
 * texture bound to target (GL_TEXTURE_1D or GL_TEXTURE_2D; others are not
 * kept), which `reset` starts afresh; then, for a sub-image, compacts a
 * definition grown too long (entry_custom.c). */
void rgl_texture_defined(rgl_stream *s, uint32_t target, const uint8_t *from, bool reset);

/* The slot of a texture target (a cube-map face: the cube map's), -1 for
 * a target whose objects are not kept; and the target of a slot. */
int rgl_tex_slot(uint32_t target);
uint32_t rgl_tex_slot_target(int slot);

/* Whether the current context is GL major.minor or later, or lists
 * extension ext (a whole name). False without a context (snaptex.c). */
bool rgl_gl_has(int major, int minor, const char *ext);

/* The active texture unit of the current context (0 without a context,
 * without multitexture, inside glBegin/glEnd, or past RGL_MAX_TEX_UNITS). */
uint32_t rgl_tex_active_unit(const rgl_stream *s);

/* The snapshot's texture objects, then every unit's state in one block
 * after one glActiveTexture, the active unit last (snaptex.c). */
void rgl_snap_textures(rgl_stream *s, rgl_buf *out);

/* Whether target is a proxy texture target (GL reads no pixels for it). */
bool rgl_tex_is_proxy(uint32_t target);

/* Records @Skipped(op, reason) where a call was passed to GL unrecorded
 * with RGL_PX_SKIP_ENUM or RGL_PX_SKIP_DATA; nothing for other values. */
void rgl_note_skipped(uint32_t op, int64_t why);

/* Returns the texture record for `name` in s, creating it when create is set
 * (NULL when absent or on allocation failure). */
rgl_texture *rgl_texture_get(rgl_stream *s, uint32_t name, bool create);

/* Test hook: makes the nth allocation from now on fail (0: none). The
 * RAYGL_TEST_FAIL_ALLOC environment variable sets it at initialisation. */
void rgl_test_fail_alloc(unsigned long n);

/* Test hook: allocations made so far (rgl_alloc, rgl_realloc and the
 * recorder's own large buffers), counted from the start of the process. */
unsigned long rgl_test_alloc_count(void);

/* The one allocation wrapper, so a test can fail the Nth allocation. */
void *rgl_alloc(size_t size);
void *rgl_realloc(void *p, size_t size);
void rgl_free(void *p);

#endif
