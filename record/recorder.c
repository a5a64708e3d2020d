/* recorder.c: libraygl's runtime: the trace file, per-thread streams,
 * frames, resources, the failed state, and the raygl control API; the
 * records it writes itself (@Matrix, the hand-written ones) are emit.c's.
 *
 * The hot path lives in recorder.h (rgl_reserve/rgl_commit). Everything here
 * runs in the slow path, at frame ends, or from the control API. Locks, in
 * the order they may nest: g.list_mu (the stream list) > a stream's lock >
 * g.file_mu (the file, the resource table, the index). A stream's own thread
 * takes its lock only in the slow path and at frame end; close and exit take
 * it to write the frames of other threads.
 *
 * The file is written with one writev per chunk under g.file_mu (a large
 * frame: its whole O_DIRECT blocks through a second descriptor, the rest
 * with writev; write_frame_chunk), so a frame is in the kernel when
 * rayglutSwapBuffers returns and survives a SIGKILL right after; nothing
 * is buffered in user space between chunks.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <GL/gl.h>
#include <GL/freeglut.h>

#include "raygl.h"
#include "recorder.h"
#include "unrecorded.h"

#ifndef RAYGL_VERSION
#define RAYGL_VERSION "0.0.0"
#endif

#define RGL_BUF_INITIAL (64u * 1024u)
/* Buffers from this capacity on (frames of more than ~150k calls) are
 * mapped apart, 2 MiB aligned, with transparent huge pages asked for: a
 * frame of a million calls is 13 MB, which in 4 KiB pages costs 3,000 page
 * faults the first time it fills, and 7 in huge pages. */
#define RGL_BUF_HUGE (2u * 1024u * 1024u)
#define RGL_DEFAULT_NAME_TRIES 1000
/* The frame payload prefix: stream, number, flags, state, each a varint. */
#define RGL_FRAME_PREFIX_MAX (4 * RGL_VARINT32_MAX)

#if defined(__GNUC__)
__thread rgl_stream *rgl_tls_stream __attribute__((tls_model("initial-exec")));
__thread int rgl_tls_passthrough __attribute__((tls_model("initial-exec")));
#else
_Thread_local rgl_stream *rgl_tls_stream;
_Thread_local int rgl_tls_passthrough;
#endif

/* One entry of the INDEX chunk. */
typedef struct index_entry {
    uint8_t type; /* RGL_CHUNK_FRAME or RGL_CHUNK_RESOURCE */
    uint32_t a;   /* frame: stream; resource: id */
    uint32_t b;   /* frame: number; resource: kind */
    uint64_t offset;
} index_entry;

/* One written resource, for deduplication. */
typedef struct res_entry {
    uint64_t hash;
    uint64_t size;
    uint64_t data_offset; /* where its bytes are in the file, to compare */
    uint32_t id;
    uint32_t kind;
} res_entry;

static struct recorder {
    pthread_once_t once;
    pthread_key_t key;
    pthread_mutex_t list_mu;
    pthread_mutex_t file_mu;
    rgl_stream *streams;

    _Atomic int status;        /* enum raygl_record_status */
    _Atomic uint32_t gen;      /* bumps at every open: streams reset */
    _Atomic bool report_pending;
    bool env_disabled;         /* RAYGL_RECORD=0, or stood down */
    bool stood_down;           /* rgl_recorder_stand_down() */
    _Atomic bool snapshots;    /* RAYGL_SNAPSHOTS=1, rayglRecordSnapshots() */
    bool forked_child;
    bool trace_excl;           /* RAYGL_TRACE_EXCL=1: never overwrite (raygl record) */

    /* Which ended frames are kept: RAYGL_FRAMES=LIST (format/framesel.h;
     * none: every frame), RAYGL_EVERY=N (folded into each item's step),
     * RAYGL_SIGNAL=SIG (only the first frame ending after each signal). */
    rgl_frame_range sel[RGL_SEL_MAX];
    size_t nsel;
    uint64_t sel_end; /* the last frame it can keep; UINT64_MAX: no end */
    int sel_signal;
    _Atomic bool sel_armed;

    /* Under file_mu. */
    int fd;
    int dfd;           /* the same file opened O_DIRECT, or -1 (write_frame_chunk) */
    size_t dio_align;  /* offset, length and memory alignment of a direct write */
    uint64_t offset;
    char path[PATH_MAX];
    uint32_t next_stream_id;
    uint32_t next_resource_id;
    index_entry *index;
    size_t nindex, cap_index;
    res_entry *res;    /* open-addressed hash table, cap_res a power of 2 */
    size_t nres, cap_res;

    char error[320];   /* rayglRecordError(); set once per trace */
    void (*handler)(const char *message, void *user);
    void *handler_user;
    bool handler_set;

    _Atomic unsigned long alloc_count;
    _Atomic unsigned long alloc_fail_at;
    _Atomic unsigned long allocs; /* every allocation, for tests */
} g = {
    .once = PTHREAD_ONCE_INIT,
    .list_mu = PTHREAD_MUTEX_INITIALIZER,
    .file_mu = PTHREAD_MUTEX_INITIALIZER,
    .fd = -1,
    .dfd = -1,
    .sel = {{0, UINT64_MAX, 1}},
    .nsel = 1,
    .sel_end = UINT64_MAX,
};

static void stream_destroy_key(void *arg);
static void close_trace(void);

/* ---- Allocation ------------------------------------------------------------ */

static bool alloc_should_fail(void)
{
    atomic_fetch_add_explicit(&g.allocs, 1, memory_order_relaxed);
    unsigned long at = atomic_load_explicit(&g.alloc_fail_at, memory_order_relaxed);
    if (at == 0)
        return false;
    return atomic_fetch_add(&g.alloc_count, 1) + 1 == at;
}

void rgl_test_fail_alloc(unsigned long n)
{
    atomic_store(&g.alloc_count, 0);
    atomic_store(&g.alloc_fail_at, n);
}

void *rgl_alloc(size_t size)
{
    if (alloc_should_fail())
        return NULL;
    return malloc(size ? size : 1);
}

void *rgl_realloc(void *p, size_t size)
{
    if (alloc_should_fail())
        return NULL;
    return realloc(p, size ? size : 1);
}

void rgl_free(void *p) { free(p); }

unsigned long rgl_test_alloc_count(void) { return atomic_load(&g.allocs); }

/* size bytes of zeroed memory, RGL_BUF_HUGE aligned, huge pages asked for
 * (a hint: without them it is plain anonymous memory). Freed with
 * munmap(p, size). */
static void *alloc_huge(size_t size)
{
    if (alloc_should_fail())
        return NULL;
    size_t span = size + RGL_BUF_HUGE;
    uint8_t *m = mmap(NULL, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED)
        return NULL;
    uint8_t *p = (uint8_t *)(((uintptr_t)m + RGL_BUF_HUGE - 1) & ~(uintptr_t)(RGL_BUF_HUGE - 1));
    if (p > m)
        munmap(m, (size_t)(p - m));
    if (m + span > p + size)
        munmap(p + size, (size_t)(m + span - (p + size)));
#ifdef MADV_HUGEPAGE
    madvise(p, size, MADV_HUGEPAGE);
#endif
    return p;
}

/* ---- Failure --------------------------------------------------------------- */

static void default_handler(const char *message, void *user)
{
    (void)user;
    /* One write so lines from several processes do not interleave. */
    char line[sizeof g.error + 2];
    size_t n = strlen(message);
    memcpy(line, message, n);
    line[n++] = '\n';
    ssize_t r = write(STDERR_FILENO, line, n);
    (void)r;
}

/* Enters the failed state and formats the message; returns whether this call
 * was the first. Takes no lock: callers may hold file_mu. */
static bool fail_set(int err, const char *what)
{
    int st = atomic_load(&g.status);
    for (;;) {
        if (st != RAYGL_RECORDING && st != RAYGL_IDLE)
            return false;
        if (atomic_compare_exchange_weak(&g.status, &st, RAYGL_FAILED))
            break;
    }
    char ebuf[128];
    const char *es = err ? strerror_r(err, ebuf, sizeof ebuf) : NULL;
    if (es)
        snprintf(g.error, sizeof g.error, "raygl: recording stopped: %s: %s", what, es);
    else
        snprintf(g.error, sizeof g.error, "raygl: recording stopped: %s", what);
    atomic_store(&g.report_pending, true);
    return true;
}

/* Delivers the failure message once. Called with no recorder lock held, so
 * the handler may call back into the control API. */
static void fail_report(void)
{
    if (!atomic_exchange(&g.report_pending, false))
        return;
    void (*h)(const char *, void *) = g.handler_set ? g.handler : default_handler;
    if (h)
        h(g.error, g.handler_user);
    rgl_session_failed();
}

void rgl_fail(int err, const char *what)
{
    fail_set(err, what);
    fail_report();
}

static bool recording(void) { return atomic_load(&g.status) == RAYGL_RECORDING; }

/* ---- Buffers --------------------------------------------------------------- */

/* Whether b's memory is a mapping of its own (alloc_huge): it starts at
 * data - pad and holds pad + cap bytes. Smaller buffers are malloc's, with
 * no pad. */
static bool buf_mapped(const rgl_buf *b) { return b->pad + b->cap >= RGL_BUF_HUGE; }

uint8_t *rgl_buf_reserve(rgl_buf *b, size_t n)
{
    if (b->cap - b->size >= n)
        return b->data + b->size;
    size_t need = b->size + n;
    if (n > RGL_CHUNK_MAX_PAYLOAD || need > RGL_CHUNK_MAX_PAYLOAD - RGL_FRAME_PREFIX_MAX) {
        fail_set(EFBIG, "a frame or resource is larger than a chunk can hold");
        return NULL;
    }
    size_t cap = b->pad + b->cap ? b->pad + b->cap : RGL_BUF_INITIAL;
    while (cap - b->pad < need)
        cap *= 2;
    uint8_t *data;
    if (cap < RGL_BUF_HUGE) {
        data = rgl_realloc(b->data, cap);
    } else if (buf_mapped(b)) {
        /* The pages move to a larger aligned mapping with no copy, and only
         * the new half is cleared. */
        uint8_t *m = alloc_huge(cap);
        void *moved = m ? mremap(b->data - b->pad, b->pad + b->cap, cap,
                                 MREMAP_MAYMOVE | MREMAP_FIXED, m)
                        : MAP_FAILED;
        data = NULL;
        if (moved != MAP_FAILED) {
#ifdef MADV_HUGEPAGE
            madvise(moved, cap, MADV_HUGEPAGE);
#endif
            data = (uint8_t *)moved + b->pad;
        } else if (m) {
            munmap(m, cap);
        }
    } else {
        /* Kept until the stream ends: later frames reuse these pages. */
        uint8_t *m = alloc_huge(cap);
        data = m ? m + b->pad : NULL;
        if (data) {
            if (b->size)
                memcpy(data, b->data, b->size);
            rgl_free(b->data);
        }
    }
    if (!data) {
        fail_set(ENOMEM, "allocation failed");
        return NULL;
    }
    b->data = data;
    b->cap = cap - b->pad;
    return data + b->size;
}

void rgl_buf_finish(rgl_buf *b)
{
    if (buf_mapped(b))
        munmap(b->data - b->pad, b->pad + b->cap);
    else
        rgl_free(b->data);
    b->data = NULL;
    b->size = b->cap = b->pad = 0;
}

/* Moves the start of an empty mapped buffer `pad` bytes into its mapping
 * (less than a quarter of it); other buffers stay as they are. */
static void buf_set_pad(rgl_buf *b, size_t pad)
{
    if (b->size || !buf_mapped(b) || pad >= (b->pad + b->cap) / 4)
        return;
    b->data = b->data - b->pad + pad;
    b->cap = b->cap + b->pad - pad;
    b->pad = pad;
}

/* ---- The file -------------------------------------------------------------- */

/* Writes all of iov; returns 0 or an errno value. */
static int write_iov(struct iovec *iov, int n)
{
    while (n > 0) {
        ssize_t w = writev(g.fd, iov, n);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        if (w == 0)
            return EIO;
        g.offset += (uint64_t)w;
        size_t left = (size_t)w;
        while (n > 0 && left >= iov->iov_len) {
            left -= iov->iov_len;
            iov++;
            n--;
        }
        if (n > 0) {
            iov->iov_base = (uint8_t *)iov->iov_base + left;
            iov->iov_len -= left;
        }
    }
    return 0;
}

/* Frames from this size on have their middle written with O_DIRECT. */
#define RGL_DIRECT_MIN (1u * 1024u * 1024u)

/* Opens the direct-write descriptor of the trace just opened (g.fd, g.path):
 * a regular file on a file system that takes O_DIRECT. Without one, every
 * chunk is written through the page cache as before. Under file_mu. */
static void direct_open(void)
{
    g.dfd = -1;
    struct stat st;
    const char *v = getenv("RAYGL_DIRECT");
    if ((v && strcmp(v, "0") == 0) || fstat(g.fd, &st) != 0 || !S_ISREG(st.st_mode))
        return;
    g.dio_align = 4096; /* whole pages: the buffered head and tail share none with it */
#ifdef STATX_DIOALIGN
    struct statx sx;
    if (statx(g.fd, "", AT_EMPTY_PATH, STATX_DIOALIGN, &sx) == 0 &&
        (sx.stx_mask & STATX_DIOALIGN)) {
        if (sx.stx_dio_offset_align == 0)
            return; /* the file system has no direct I/O */
        if (sx.stx_dio_offset_align > g.dio_align)
            g.dio_align = sx.stx_dio_offset_align;
        if (sx.stx_dio_mem_align > g.dio_align)
            g.dio_align = sx.stx_dio_mem_align;
    }
#endif
    if (g.dio_align > RGL_BUF_HUGE)
        return;
    char self[64];
    snprintf(self, sizeof self, "/proc/self/fd/%d", g.fd);
    g.dfd = open(self, O_WRONLY | O_DIRECT | O_CLOEXEC);
    if (g.dfd < 0) /* no /proc: the name just opened */
        g.dfd = open(g.path, O_WRONLY | O_DIRECT | O_CLOEXEC);
}

static void direct_close(void)
{
    if (g.dfd >= 0)
        close(g.dfd);
    g.dfd = -1;
}

/* Writes len bytes from src, at an aligned address, at file offset `at`
 * through dfd; len and at are multiples of g.dio_align. Returns 0, EINVAL
 * when the file system refuses the direct write (nothing was written: the
 * caller writes the range through the page cache), or an errno value.
 * Under file_mu. */
static int write_direct(const uint8_t *src, size_t len, uint64_t at)
{
    size_t done = 0;
    while (done < len) {
        ssize_t w = pwrite(g.dfd, src + done, len - done, (off_t)(at + done));
        if (w < 0 && errno == EINTR)
            continue;
        if (w < 0 && done == 0 && errno == EINVAL)
            return EINVAL;
        if (w <= 0 || (size_t)w % g.dio_align) /* nothing aligned left to go on with */
            return w < 0 ? errno : EIO;
        done += (size_t)w;
    }
    return 0;
}

/* Writes a frame chunk, iov = header, prefix, commands, trailer (total
 * bytes), at g.offset: the commands' whole O_DIRECT blocks straight from
 * memory, the rest through the page cache. The kernel's copy into new
 * page-cache pages cost 3 to 30 ms for a 13 MB frame here; the direct
 * write costs about a millisecond. The commands must sit in memory at the
 * offset within a block they have in the file: frame_align() arranges it
 * at the frame's start, and when a chunk written since spoiled that, they
 * are moved up in the buffer `frame` (NULL: another thread's, which must
 * not move) when it has the room. Returns 0 or an errno value. Under
 * file_mu. */
static int write_frame_chunk(struct iovec iov[4], size_t total, rgl_buf *frame)
{
    if (g.dfd < 0 || total < RGL_DIRECT_MIN)
        return write_iov(iov, 4);
    size_t a = g.dio_align;
    size_t d0 = iov[0].iov_len + iov[1].iov_len, d1 = d0 + iov[2].iov_len;
    uint8_t *data = iov[2].iov_base;
    size_t want = (size_t)((g.offset + d0) % a), have = (size_t)((uintptr_t)data % a);
    if (have != want) {
        size_t shift = (want + a - have) % a;
        if (!frame || frame->data != data || frame->cap - frame->size < shift)
            return write_iov(iov, 4);
        memmove(data + shift, data, iov[2].iov_len);
        data += shift;
        iov[2].iov_base = data;
    }
    /* Chunk offsets of the commands' first and last block boundaries. */
    size_t from = d0 + (a - want) % a, to = d1 - (size_t)((g.offset + d1) % a);
    if (to <= from)
        return write_iov(iov, 4);
    struct iovec head[3] = {iov[0], iov[1], {data, from - d0}};
    int err = write_iov(head, 3);
    if (err)
        return err;
    uint64_t at = g.offset;
    err = write_direct(data + (from - d0), to - from, at);
    if (err == EINVAL) {
        direct_close(); /* not for this file: the page cache from now on */
        to = from;
    } else if (err) {
        return err;
    } else {
        g.offset = at + (to - from);
        if (lseek(g.fd, (off_t)g.offset, SEEK_SET) < 0)
            return errno;
    }
    struct iovec tail[2] = {{data + (to - d0), d1 - to}, iov[3]};
    return write_iov(tail, 2);
}

/* Writes one chunk: header, prefix and data as its payload, CRC-32C trailer,
 * in one writev (a frame: write_frame_chunk; movable is the frame's buffer
 * when it may be moved, else NULL). Under file_mu, recording. On failure
 * the partial chunk is cut off (best effort) and the recorder fails;
 * returns false. */
static bool write_chunk(uint8_t type, const void *prefix, size_t plen, const void *data,
                        size_t dlen, uint64_t *chunk_offset, rgl_buf *movable)
{
    uint8_t header[RGL_CHUNK_HEADER_SIZE], trailer[RGL_CHUNK_TRAILER_SIZE];
    if (!prefix)
        prefix = "";
    if (!data)
        data = "";
    uint32_t crc = rgl_crc32c(0, prefix, plen);
    crc = rgl_crc32c(crc, data, dlen);
    rgl_chunk_header_encode(header, type, (uint32_t)(plen + dlen));
    rgl_put_u32(trailer, crc);
    struct iovec iov[4] = {
        {header, sizeof header},
        {(void *)prefix, plen},
        {(void *)data, dlen},
        {trailer, sizeof trailer},
    };
    uint64_t start = g.offset;
    int err = type == RGL_CHUNK_FRAME
                  ? write_frame_chunk(iov, RGL_CHUNK_HEADER_SIZE + plen + dlen + sizeof trailer,
                                      movable)
                  : write_iov(iov, 4);
    if (err) {
        if (ftruncate(g.fd, (off_t)start) == 0)
            g.offset = start;
        fail_set(err, g.path);
        return false;
    }
    if (chunk_offset)
        *chunk_offset = start;
    return true;
}

static bool index_add(uint8_t type, uint32_t a, uint32_t b, uint64_t offset)
{
    if (g.nindex == g.cap_index) {
        size_t cap = g.cap_index ? 2 * g.cap_index : 256;
        index_entry *p = rgl_realloc(g.index, cap * sizeof *p);
        if (!p) {
            fail_set(ENOMEM, "allocation failed");
            return false;
        }
        g.index = p;
        g.cap_index = cap;
    }
    g.index[g.nindex++] = (index_entry){type, a, b, offset};
    return true;
}

static void reset_tables(void)
{
    rgl_free(g.index);
    rgl_free(g.res);
    g.index = NULL;
    g.res = NULL;
    g.nindex = g.cap_index = g.nres = g.cap_res = 0;
    g.next_stream_id = 1;
    g.next_resource_id = 1;
}

/* Opens path (NULL: the default name) and writes the header and INFO chunk.
 * Under file_mu. Returns 0 or an errno value; on failure the recorder has
 * failed. */
static int open_trace(const char *path)
{
    int fd = -1;
    if (path) {
        if (strlen(path) >= sizeof g.path) {
            snprintf(g.path, sizeof g.path, "%.*s...", 64, path);
            fail_set(ENAMETOOLONG, g.path);
            return ENAMETOOLONG;
        }
        strcpy(g.path, path);
        if (!g.trace_excl) {
            fd = open(path, O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
        } else {
            /* raygl record removed the file: it exists when another process
             * of the run (a child that exec'd) took it first. */
            fd = open(path, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (fd < 0 && errno == EEXIST) {
                size_t n = strlen(path);
                if (n > 6 && strcmp(path + n - 6, ".raygl") == 0)
                    n -= 6;
                int k = snprintf(g.path, sizeof g.path, "%.*s.%ld.raygl", (int)n, path,
                                 (long)getpid());
                if (k < 0 || (size_t)k >= sizeof g.path) {
                    fail_set(ENAMETOOLONG, path);
                    return ENAMETOOLONG;
                }
                fd = open(g.path, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            }
        }
    } else {
        /* <program>.raygl, then <program>.1.raygl, ... like apitrace; O_EXCL
         * keeps two programs from taking the same name. */
        const char *prog = program_invocation_short_name;
        if (!prog || !*prog)
            prog = "raygl";
        for (int k = 0; k < RGL_DEFAULT_NAME_TRIES; k++) {
            if (k == 0)
                snprintf(g.path, sizeof g.path, "%s.raygl", prog);
            else
                snprintf(g.path, sizeof g.path, "%s.%d.raygl", prog, k);
            fd = open(g.path, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (fd >= 0 || errno != EEXIST)
                break;
        }
    }
    if (fd < 0) {
        int err = errno;
        fail_set(err, g.path);
        return err;
    }
    g.fd = fd;
    g.offset = 0;
    reset_tables();
    direct_open();

    uint8_t header[RGL_FILE_HEADER_SIZE];
    rgl_file_header_encode(header, 0);
    struct iovec iov = {header, sizeof header};
    int err = write_iov(&iov, 1);
    if (err) {
        fail_set(err, g.path);
        return err;
    }
    char info[512];
    const char *prog = program_invocation_short_name ? program_invocation_short_name : "";
    int n = snprintf(info, sizeof info, "program=%s\nrecorder=libraygl %s\n", prog, RAYGL_VERSION);
    if (n < 0 || (size_t)n >= sizeof info)
        n = 0;
    if (!write_chunk(RGL_CHUNK_INFO, NULL, 0, info, (size_t)n, NULL, NULL))
        return errno ? errno : EIO;
    return 0;
}

/* The INDEX chunk (docs/format.md): the frame count and each frame chunk's
 * offset, then the resource count and each resource's id and offset, all
 * varints. The END chunk: the INDEX chunk's offset as a u64. Under file_mu. */
static void write_index_and_end(void)
{
    size_t nframes = 0;
    for (size_t i = 0; i < g.nindex; i++)
        nframes += g.index[i].type == RGL_CHUNK_FRAME;
    rgl_buf b = {0};
    uint8_t *p = rgl_buf_reserve(&b, RGL_VARINT64_MAX * (2 + 2 * g.nindex));
    if (!p)
        return;
    p = rgl_put_varint(p, nframes);
    for (size_t i = 0; i < g.nindex; i++)
        if (g.index[i].type == RGL_CHUNK_FRAME)
            p = rgl_put_varint(p, g.index[i].offset);
    p = rgl_put_varint(p, g.nindex - nframes);
    for (size_t i = 0; i < g.nindex; i++) {
        if (g.index[i].type == RGL_CHUNK_RESOURCE) {
            p = rgl_put_varint(p, g.index[i].a);
            p = rgl_put_varint(p, g.index[i].offset);
        }
    }
    rgl_buf_commit(&b, p);
    uint64_t index_offset;
    if (write_chunk(RGL_CHUNK_INDEX, NULL, 0, b.data, b.size, &index_offset, NULL)) {
        uint8_t end[8];
        rgl_put_u64(end, index_offset);
        write_chunk(RGL_CHUNK_END, NULL, 0, end, sizeof end, NULL, NULL);
    }
    rgl_buf_finish(&b);
}

/* ---- Resources ------------------------------------------------------------- */

static uint64_t hash_bytes(const uint8_t *p, size_t n, uint64_t seed)
{
    const uint64_t m = 0x9E3779B97F4A7C15u;
    uint64_t h = seed ^ (n * m);
    while (n >= 8) {
        uint64_t v;
        memcpy(&v, p, 8);
        h = (h ^ (v * m)) * 0xBF58476D1CE4E5B9u;
        h ^= h >> 31;
        p += 8;
        n -= 8;
    }
    uint64_t v = 0;
    if (n)
        memcpy(&v, p, n);
    h = (h ^ (v * m)) * 0x94D049BB133111EBu;
    return h ^ (h >> 29);
}

/* Whether the file holds these bytes at offset: the dedup table keeps only
 * hashes, so a hash hit is confirmed against the trace itself. */
static bool file_equals(uint64_t offset, const uint8_t *data, size_t size)
{
    uint8_t tmp[16384];
    while (size > 0) {
        size_t n = size < sizeof tmp ? size : sizeof tmp;
        ssize_t r = pread(g.fd, tmp, n, (off_t)offset);
        if (r <= 0) {
            if (r < 0 && errno == EINTR)
                continue;
            return false;
        }
        if (memcmp(tmp, data, (size_t)r) != 0)
            return false;
        data += r;
        offset += (uint64_t)r;
        size -= (size_t)r;
    }
    return true;
}

static bool res_grow(void)
{
    size_t cap = g.cap_res ? 2 * g.cap_res : 256;
    res_entry *t = rgl_alloc(cap * sizeof *t);
    if (!t) {
        fail_set(ENOMEM, "allocation failed");
        return false;
    }
    memset(t, 0, cap * sizeof *t);
    for (size_t i = 0; i < g.cap_res; i++) {
        if (!g.res[i].id)
            continue;
        size_t j = g.res[i].hash & (cap - 1);
        while (t[j].id)
            j = (j + 1) & (cap - 1);
        t[j] = g.res[i];
    }
    rgl_free(g.res);
    g.res = t;
    g.cap_res = cap;
    return true;
}

/* rgl_resource_put without delivering a failure message (callers that hold
 * a stream lock deliver it after releasing it). */
static uint32_t resource_put(uint32_t kind, const void *data, size_t size)
{
    if (size > RGL_CHUNK_MAX_PAYLOAD - 2 * RGL_VARINT32_MAX) {
        fail_set(EFBIG, "a resource is larger than a chunk can hold");
        return 0;
    }
    if (!data)
        data = "";
    uint64_t h = hash_bytes(data, size, kind);
    uint32_t id = 0;
    pthread_mutex_lock(&g.file_mu);
    if (!recording())
        goto out;
    if (g.cap_res) {
        for (size_t j = h & (g.cap_res - 1); g.res[j].id; j = (j + 1) & (g.cap_res - 1)) {
            res_entry *e = &g.res[j];
            if (e->hash == h && e->size == size && e->kind == kind &&
                file_equals(e->data_offset, data, size)) {
                id = e->id;
                goto out;
            }
        }
    }
    if (2 * (g.nres + 1) > g.cap_res && !res_grow())
        goto out;
    if (g.next_resource_id > RGL_RESOURCE_ID_MAX) {
        fail_set(EOVERFLOW, "too many resources");
        goto out;
    }
    uint8_t prefix[2 * RGL_VARINT32_MAX];
    uint8_t *p = rgl_put_varint(prefix, g.next_resource_id);
    p = rgl_put_varint(p, kind);
    size_t plen = (size_t)(p - prefix);
    uint64_t off;
    if (!index_add(RGL_CHUNK_RESOURCE, g.next_resource_id, kind, 0))
        goto out;
    if (!write_chunk(RGL_CHUNK_RESOURCE, prefix, plen, data, size, &off, NULL)) {
        g.nindex--;
        goto out;
    }
    id = g.next_resource_id++;
    g.index[g.nindex - 1].offset = off;
    size_t j = h & (g.cap_res - 1);
    while (g.res[j].id)
        j = (j + 1) & (g.cap_res - 1);
    g.res[j] = (res_entry){h, size, off + RGL_CHUNK_HEADER_SIZE + plen, id, kind};
    g.nres++;
out:
    pthread_mutex_unlock(&g.file_mu);
    return id;
}

uint32_t rgl_resource_put(uint32_t kind, const void *data, size_t size)
{
    uint32_t id = resource_put(kind, data, size);
    fail_report();
    return id;
}

/* ---- Streams --------------------------------------------------------------- */

static rgl_buf *cur_buf(rgl_stream *s) { return s->compiling ? &s->list : &s->frame; }

/* Stores the window's write position into its buffer. */
static void stream_sync(rgl_stream *s)
{
    if (s->base)
        cur_buf(s)->size = (size_t)(s->pos - s->base);
}

/* Points the write window at the current buffer; `open` lets calls through
 * the hot path, otherwise the next call takes the slow path. */
static void stream_window(rgl_stream *s, bool open)
{
    rgl_buf *b = cur_buf(s);
    s->base = b->data;
    s->pos = b->data + b->size;
    s->limit = b->data + b->cap;
    s->end = open ? s->limit : s->pos;
}

static void objects_clear(rgl_objects *o, bool keep_names)
{
    for (size_t i = 0; i < o->ntextures; i++)
        rgl_buf_finish(&o->textures[i].defs);
    rgl_free(o->textures);
    rgl_free(o->lists);
    uint32_t bound[RGL_MAX_TEX_UNITS][RGL_TEX_TARGETS];
    memcpy(bound, o->bound, sizeof bound);
    uint32_t nt = o->next_texture_name, nl = o->next_list_name;
    int32_t unpack[6];
    memcpy(unpack, o->unpack, sizeof unpack);
    memset(o, 0, sizeof *o);
    if (keep_names) { /* GL state, not the trace's: a new trace keeps it */
        memcpy(o->bound, bound, sizeof bound);
        o->next_texture_name = nt;
        o->next_list_name = nl;
        memcpy(o->unpack, unpack, sizeof unpack);
    }
}

/* Moves the stream into the current trace generation: a new id, frame
 * numbers from 0, nothing buffered. Resource ids of the previous trace mean
 * nothing in the new one, so recorded texture and list bodies are dropped. */
static void stream_adopt(rgl_stream *s, uint32_t gen)
{
    pthread_mutex_lock(&g.file_mu);
    s->id = g.next_stream_id++;
    pthread_mutex_unlock(&g.file_mu);
    s->gen = gen;
    s->frame_number = 0;
    s->shown = 0;
    s->frame_open = false;
    s->frame.size = 0;
    if (s->compiling) {
        s->compiling = false;
        s->list.size = 0;
    }
    s->have_matrix[0] = s->have_matrix[1] = false;
    objects_clear(&s->objs, true);
    stream_window(s, false);
}

static rgl_stream *stream_create(void)
{
    rgl_stream *s = rgl_alloc(sizeof *s);
    pthread_mutex_t *mu = rgl_alloc(sizeof *mu);
    uint64_t *unrec = rgl_alloc(rgl_unrecorded_total * sizeof *unrec);
    if (!s || !mu || !unrec) {
        rgl_free(s);
        rgl_free(mu);
        rgl_free(unrec);
        rgl_fail(ENOMEM, "allocation failed");
        return NULL;
    }
    memset(s, 0, sizeof *s);
    memset(unrec, 0, rgl_unrecorded_total * sizeof *unrec);
    pthread_mutex_init(mu, NULL);
    s->lock = mu;
    s->unrecorded = unrec;
    for (int i = 0; i < RGL_MAX_CLIENT_ARRAYS; i++)
        s->arrays[i].size = 4;
    s->arrays[RGL_CA_VERTEX].type = s->arrays[RGL_CA_COLOR].type = GL_FLOAT;
    s->arrays[RGL_CA_NORMAL].type = s->arrays[RGL_CA_TEXCOORD].type = GL_FLOAT;
    s->arrays[RGL_CA_NORMAL].size = 3;
    s->arrays[RGL_CA_EDGEFLAG].size = 1;
    s->arrays[RGL_CA_EDGEFLAG].type = GL_UNSIGNED_BYTE;
    s->arrays[RGL_CA_FOGCOORD].size = 1;
    s->arrays[RGL_CA_FOGCOORD].type = GL_FLOAT;
    s->arrays[RGL_CA_SECONDARY].size = 3;
    s->arrays[RGL_CA_SECONDARY].type = GL_FLOAT;
    for (int i = 0; i < RGL_MAX_TEX_UNITS; i++)
        s->tc_parked[i] = s->arrays[RGL_CA_TEXCOORD];
    pthread_mutex_lock(&g.list_mu);
    s->next = g.streams;
    g.streams = s;
    pthread_mutex_unlock(&g.list_mu);
    pthread_setspecific(g.key, s);
    rgl_tls_stream = s;
    return s;
}

static void stream_free(rgl_stream *s)
{
    rgl_buf_finish(&s->frame);
    rgl_buf_finish(&s->list);
    rgl_buf_finish(&s->snap);
    objects_clear(&s->objs, false);
    rgl_free(s->unrecorded);
    pthread_mutex_destroy(s->lock);
    rgl_free(s->lock);
    rgl_free(s);
}

/* Whether RAYGL_FRAMES (with RAYGL_EVERY) selects the program's
 * `shown`th frame (from 0). */
static bool in_selection(uint64_t shown)
{
    for (size_t i = 0; i < g.nsel; i++)
        if (rgl_framesel_has(&g.sel[i], shown))
            return true;
    return false;
}

/* Whether the frame the program ended as its `shown`th (from 0) is kept.
 * A dropped frame costs nothing in the file: every frame starts with the
 * resolved state, and lists and textures are resources. */
static bool frame_selected(uint32_t shown)
{
    if (!in_selection(shown))
        return false;
    if (g.sel_signal)
        return atomic_exchange(&g.sel_armed, false);
    return true;
}

/* Whether no frame of s after the ones it ended can be kept: the last step
 * of RAYGL_FRAMES (with RAYGL_EVERY) has ended, or, with RAYGL_SIGNAL, a
 * frame was just kept. */
static bool selection_over(const rgl_stream *s, bool kept)
{
    if (g.sel_signal && kept)
        return true;
    return g.sel_end != UINT64_MAX && s->shown > g.sel_end;
}

bool rgl_frame_wanted(const rgl_stream *s)
{
    if (!in_selection(s->shown))
        return false;
    return !g.sel_signal || atomic_load(&g.sel_armed);
}

/* The frame payload's prefix: stream, number, flags, state. Returns its
 * length. */
static size_t frame_prefix(const rgl_stream *s, uint8_t prefix[RGL_FRAME_PREFIX_MAX])
{
    uint8_t *p = rgl_put_varint(prefix, s->id);
    p = rgl_put_varint(p, s->frame_number);
    p = rgl_put_varint(p, s->frame_flags);
    p = rgl_put_varint(p, s->state_resource);
    return (size_t)(p - prefix);
}

/* Places the start of the empty frame buffer so that the frame's commands
 * sit in memory at the offset within an O_DIRECT block that they will have
 * in the file, as predicted from the file's end now: the frame's middle is
 * then written from the buffer itself, with no copy (write_frame_chunk). A
 * chunk written before the frame's (a resource, another thread's frame)
 * spoils the prediction, and that frame is copied. Under the stream's
 * lock. */
static void frame_align(rgl_stream *s)
{
    uint8_t prefix[RGL_FRAME_PREFIX_MAX];
    size_t plen = frame_prefix(s, prefix);
    pthread_mutex_lock(&g.file_mu);
    bool direct = g.dfd >= 0;
    uint64_t at = g.offset + RGL_CHUNK_HEADER_SIZE + plen;
    size_t a = g.dio_align;
    pthread_mutex_unlock(&g.file_mu);
    if (direct)
        buf_set_pad(&s->frame, (size_t)(at % a));
}

/* Writes the stream's open frame, if it holds commands. Under the stream's
 * lock, not file_mu. With `reset` (only on the stream's own thread, whose
 * hot path moves pos without a lock) it leaves the frame closed and empty;
 * without it, the owner's next frame end finds the trace closed or
 * reopened and drops what it holds then. Returns whether the frame was
 * kept (selected). */
static bool frame_write(rgl_stream *s, bool reset)
{
    bool kept = false;
    stream_sync(s);
    if (s->frame_open && s->frame.size > 0 && s->gen == atomic_load(&g.gen) &&
        frame_selected(s->shown++)) {
        kept = true;
        /* Calls not recorded since the last written frame (a dropped
         * frame's too); rgl_frame_image() flushed them before a snapshot. */
        if (reset && !s->image_taken)
            rgl_unrecorded_flush(s, &s->frame);
        uint8_t prefix[RGL_FRAME_PREFIX_MAX];
        size_t plen = frame_prefix(s, prefix);
        pthread_mutex_lock(&g.file_mu);
        if (recording() && index_add(RGL_CHUNK_FRAME, s->id, s->frame_number, 0)) {
            uint64_t off;
            /* Only the owner, which empties it next, may move its frame. */
            if (write_chunk(RGL_CHUNK_FRAME, prefix, plen, s->frame.data, s->frame.size, &off,
                            reset ? &s->frame : NULL))
                g.index[g.nindex - 1].offset = off;
            else
                g.nindex--;
        }
        pthread_mutex_unlock(&g.file_mu);
        s->frame_number++;
    }
    if (!reset)
        return kept;
    s->frame_open = false;
    s->image_taken = false;
    s->frame.size = 0;
    stream_window(s, false);
    return kept;
}

/* Starts a frame: the resolved-state snapshot of a live context, or the
 * STATE_CARRIED flag without one. Under the stream's lock. */
static void frame_start(rgl_stream *s)
{
    s->frame_open = true;
    s->gl_caps = 0; /* asked again in the frame (entry_buffer.c) */
    s->have_matrix[0] = s->have_matrix[1] = false;
    s->snap.size = 0;
    if (rgl_snapshot_take(s, &s->snap)) {
        s->frame_flags = RGL_FRAME_LIVE_CONTEXT;
        s->state_resource = resource_put(RGL_RES_COMMANDS, s->snap.data, s->snap.size);
    } else {
        s->frame_flags = RGL_FRAME_STATE_CARRIED;
        s->state_resource = 0;
    }
    frame_align(s);
}

static void stream_destroy_key(void *arg)
{
    rgl_stream *s = arg;
    pthread_mutex_lock(&g.list_mu);
    for (rgl_stream **pp = &g.streams; *pp; pp = &(*pp)->next) {
        if (*pp == s) {
            *pp = s->next;
            break;
        }
    }
    pthread_mutex_unlock(&g.list_mu);
    pthread_mutex_lock(s->lock);
    if (s->compiling) {
        stream_sync(s);
        s->compiling = false;
    }
    frame_write(s, true);
    pthread_mutex_unlock(s->lock);
    rgl_tls_stream = NULL;
    stream_free(s);
    fail_report();
}

/* ---- Initialisation, exit, fork -------------------------------------------- */

static void at_exit(void)
{
    if (!g.forked_child)
        close_trace();
}

static void fork_prepare(void)
{
    pthread_mutex_lock(&g.list_mu);
    pthread_mutex_lock(&g.file_mu);
}

static void fork_parent(void)
{
    pthread_mutex_unlock(&g.file_mu);
    pthread_mutex_unlock(&g.list_mu);
}

/* The child shares the parent's file description: it must never write to
 * it, nor write the index at its exit. Its own descriptor is closed. */
static void fork_child(void)
{
    g.forked_child = true;
    atomic_store(&g.status, RAYGL_DISABLED);
    atomic_store(&g.report_pending, false);
    if (g.fd >= 0)
        close(g.fd);
    g.fd = -1;
    direct_close();
    rgl_stream *s = rgl_tls_stream;
    if (s)
        s->end = s->pos;
    pthread_mutex_unlock(&g.file_mu);
    pthread_mutex_unlock(&g.list_mu);
}

static void on_select_signal(int sig)
{
    (void)sig;
    atomic_store(&g.sel_armed, true);
}

/* A count from the environment: digits only, below UINT32_MAX. */
static bool parse_u32(const char *v, char **end, uint32_t *out)
{
    if (*v < '0' || *v > '9')
        return false;
    errno = 0;
    unsigned long long x = strtoull(v, end, 10);
    if (errno || x >= UINT32_MAX)
        return false;
    *out = (uint32_t)x;
    return true;
}

/* RAYGL_FRAMES=LIST (as raygl2pov --frames takes it), RAYGL_EVERY=N,
 * RAYGL_SIGNAL=number. `raygl record` checks the values and reports bad
 * ones; here a malformed value is ignored (the recorder never stops the
 * program). */
static void select_from_env(void)
{
    const char *v = getenv("RAYGL_FRAMES");
    rgl_frame_range sel[RGL_SEL_MAX];
    size_t n = 0;
    bool ok = v && *v;
    while (ok && *v) {
        ok = n < RGL_SEL_MAX && rgl_framesel_next(&v, &sel[n]) == RGL_FRAMESEL_OK;
        n++;
    }
    if (ok) {
        memcpy(g.sel, sel, n * sizeof sel[0]);
        g.nsel = n;
    }
    char *end;
    uint32_t a;
    v = getenv("RAYGL_EVERY");
    if (v && parse_u32(v, &end, &a) && *end == '\0' && a > 0)
        for (size_t i = 0; i < g.nsel; i++) /* one in a of each item's frames */
            g.sel[i].step = g.sel[i].step > UINT64_MAX / a ? UINT64_MAX : g.sel[i].step * a;
    g.sel_end = 0;
    for (size_t i = 0; i < g.nsel && g.sel_end != UINT64_MAX; i++) {
        uint64_t last = rgl_framesel_last(&g.sel[i]);
        if (last > g.sel_end)
            g.sel_end = last;
    }
    v = getenv("RAYGL_SIGNAL");
    if (v && parse_u32(v, &end, &a) && *end == '\0' && a > 0 && a < (uint32_t)NSIG) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_select_signal;
        sa.sa_flags = SA_RESTART;
        sigemptyset(&sa.sa_mask);
        if (sigaction((int)a, &sa, NULL) == 0)
            g.sel_signal = (int)a;
    }
}

static void init_once(void)
{
    const char *v = getenv("RAYGL_TEST_FAIL_ALLOC");
    if (v && *v)
        rgl_test_fail_alloc(strtoul(v, NULL, 10));
    v = getenv("RAYGL_SNAPSHOTS");
    if (v && strcmp(v, "1") == 0)
        atomic_store(&g.snapshots, true);
    v = getenv("RAYGL_RECORD");
    if ((v && strcmp(v, "0") == 0) || g.stood_down) {
        g.env_disabled = true;
        atomic_store(&g.status, RAYGL_DISABLED);
    }
    v = getenv("RAYGL_TRACE_EXCL");
    g.trace_excl = v && strcmp(v, "1") == 0;
    /* A recorder that stood down leaves the signal and raygl record's
     * status file to the one that records. */
    if (!g.stood_down) {
        select_from_env();
        rgl_session_init();
    }
    pthread_key_create(&g.key, stream_destroy_key);
    pthread_atfork(fork_prepare, fork_parent, fork_child);
    atexit(at_exit);
}

static void ensure_init(void) { pthread_once(&g.once, init_once); }

void rgl_recorder_init(void) { ensure_init(); }

void rgl_recorder_stand_down(void)
{
    g.stood_down = true;
    ensure_init();
}

/* Opens the trace named by RAYGL_TRACE (or the default name) at the first
 * recorded call. */
static void auto_open(void)
{
    pthread_mutex_lock(&g.file_mu);
    if (atomic_load(&g.status) == RAYGL_IDLE && !g.forked_child) {
        const char *path = getenv("RAYGL_TRACE");
        if (open_trace(path && *path ? path : NULL) == 0) {
            atomic_fetch_add(&g.gen, 1);
            atomic_store(&g.status, RAYGL_RECORDING);
        }
    }
    pthread_mutex_unlock(&g.file_mu);
    fail_report();
}

rgl_stream *rgl_stream_current(void)
{
    rgl_stream *s = rgl_tls_stream;
    if (s)
        return s;
    ensure_init();
    /* Before the trace opens (at the first recorded call) the stream is
     * made already, so what the program calls first is counted; a program
     * that records nothing leaves no file. */
    int st = atomic_load(&g.status);
    if (st != RAYGL_RECORDING && st != RAYGL_IDLE)
        return NULL;
    return stream_create();
}

rgl_stream *rgl_reserve_slow(size_t n)
{
    rgl_stream *s = rgl_tls_stream;
    if (RGL_UNLIKELY(rgl_tls_passthrough > 0)) {
        if (s)
            s->end = s->pos;
        return NULL;
    }
    if (RGL_UNLIKELY(!s || atomic_load(&g.status) != RAYGL_RECORDING)) {
        ensure_init();
        if (atomic_load(&g.status) == RAYGL_IDLE)
            auto_open();
        if (atomic_load(&g.status) != RAYGL_RECORDING) {
            /* Every later call comes back here and leaves at once. */
            if (s)
                s->end = s->pos;
            return NULL;
        }
        if (!s && !(s = stream_create()))
            return NULL;
    }
    rgl_stream *ready = NULL;
    pthread_mutex_lock(s->lock);
    uint32_t gen = atomic_load(&g.gen);
    if (s->gen != gen)
        stream_adopt(s, gen);
    stream_sync(s);
    if (!s->frame_open) {
#ifdef RGL_FORWARD_H
        /* The program may have made another GL's context current. */
        rgl_forward_select();
#endif
        frame_start(s);
    }
    if (recording() && rgl_buf_reserve(cur_buf(s), n)) {
        stream_window(s, true);
        ready = s;
    } else {
        stream_window(s, false);
    }
    pthread_mutex_unlock(s->lock);
    fail_report();
    return ready;
}

void rgl_frame_end(void)
{
#ifdef RGL_FORWARD_H
    /* Also when not recording: the calls of the next frame go to the GL
     * current now. */
    rgl_forward_select();
#endif
    rgl_stream *s = rgl_tls_stream;
    if (!s)
        return;
    rgl_frame_image();
    pthread_mutex_lock(s->lock);
    bool over = selection_over(s, frame_write(s, true));
    pthread_mutex_unlock(s->lock);
    fail_report();
    if (over)
        rgl_session_selection_over();
}

void rgl_list_compile_begin(rgl_stream *s, uint32_t list, uint32_t mode)
{
    stream_sync(s);
    s->compiling = true;
    s->list_name = list;
    s->list_mode = mode;
    s->list.size = 0;
    stream_window(s, false);
}

const rgl_buf *rgl_list_compile_end(rgl_stream *s)
{
    stream_sync(s);
    s->compiling = false;
    stream_window(s, false);
    return &s->list;
}

/* Writes every stream's open frame, then the index, and closes the file.
 * Other threads may still be recording: a frame they are in the middle of
 * is written as far as its last completed command. */
static void close_trace(void)
{
    ensure_init();
    pthread_mutex_lock(&g.list_mu);
    for (rgl_stream *s = g.streams; s; s = s->next) {
        pthread_mutex_lock(s->lock);
        frame_write(s, s == rgl_tls_stream);
        pthread_mutex_unlock(s->lock);
    }
    pthread_mutex_lock(&g.file_mu);
    int st = atomic_load(&g.status);
    if (st == RAYGL_RECORDING) {
        write_index_and_end();
        if (atomic_load(&g.status) == RAYGL_RECORDING)
            atomic_store(&g.status, RAYGL_DISABLED);
    }
    if (g.fd >= 0)
        close(g.fd);
    g.fd = -1;
    direct_close();
    reset_tables();
    pthread_mutex_unlock(&g.file_mu);
    pthread_mutex_unlock(&g.list_mu);
    fail_report();
}

/* ---- Control API ----------------------------------------------------------- */

RGL_EXPORT int rayglRecordOpen(const char *path)
{
    ensure_init();
    if (g.env_disabled) {
        errno = EPERM;
        return -1;
    }
    if (g.fd >= 0)
        close_trace();
    pthread_mutex_lock(&g.file_mu);
    /* A new trace gets a fresh failure state and message. */
    atomic_store(&g.status, RAYGL_IDLE);
    atomic_store(&g.report_pending, false);
    g.error[0] = '\0';
    int err = open_trace(path);
    if (!err) {
        g.forked_child = false;
        atomic_fetch_add(&g.gen, 1);
        atomic_store(&g.status, RAYGL_RECORDING);
    }
    pthread_mutex_unlock(&g.file_mu);
    fail_report();
    if (err) {
        errno = err;
        return -1;
    }
    return 0;
}

RGL_EXPORT void rayglRecordClose(void)
{
    ensure_init();
    /* Closed is final until the next rayglRecordOpen: no auto-open. */
    int st = RAYGL_IDLE;
    atomic_compare_exchange_strong(&g.status, &st, RAYGL_DISABLED);
    if (!g.forked_child)
        close_trace();
}

bool rgl_snapshots_enabled(void)
{
    ensure_init();
    return atomic_load_explicit(&g.snapshots, memory_order_relaxed);
}

RGL_EXPORT void rayglRecordSnapshots(int enable)
{
    ensure_init();
    atomic_store(&g.snapshots, enable != 0);
}

RGL_EXPORT int rayglRecordStatus(void) { return atomic_load(&g.status); }

RGL_EXPORT const char *rayglRecordPath(void) { return g.path[0] ? g.path : NULL; }

RGL_EXPORT const char *rayglRecordError(void)
{
    return atomic_load(&g.status) == RAYGL_FAILED && g.error[0] ? g.error : NULL;
}

RGL_EXPORT void rayglRecordSetErrorHandler(void (*handler)(const char *message, void *user),
                                           void *user)
{
    g.handler = handler;
    g.handler_user = user;
    g.handler_set = true;
}

/* ---- GLUT ------------------------------------------------------------------ */

bool rgl_glut_ready(void)
{
    static _Atomic bool ready;
    if (atomic_load_explicit(&ready, memory_order_relaxed))
        return true;
    if (glutGet(GLUT_INIT_STATE)) {
        atomic_store(&ready, true);
        return true;
    }
    return false;
}
