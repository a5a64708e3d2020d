/* reader.c: a whole trace, from memory or a read-only mapping.
 *
 * Opening checks the file header, then finds every chunk: through the index
 * named by the END trailer when the trailer, the index and every chunk it
 * lists check out, otherwise by a scan that walks chunk headers by their
 * length and, past a damaged region, resynchronises on the next sync pattern
 * whose header checksum holds. Payload checksums are verified when a frame
 * or resource is fetched, so one damaged frame leaves the others readable.
 * Every allocation is bounded by the file size: a chunk takes at least 20
 * bytes, an index entry at least one.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "errset.h"
#include "format.h"
#include "wire.h"

#define CHUNK_MIN (RGL_CHUNK_HEADER_SIZE + RGL_CHUNK_TRAILER_SIZE)
#define END_CHUNK_SIZE (CHUNK_MIN + 8)
/* Damaged regions kept in detail; a file can have more, they are not listed. */
#define DAMAGE_MAX 1024

typedef struct chunk_loc {
    uint64_t offset; /* of the chunk header */
    uint32_t length; /* payload bytes */
    uint32_t id;     /* resources: their id */
} chunk_loc;

struct rgl_reader {
    const uint8_t *data;
    size_t size;
    void *map; /* rgl_reader_open_file: the mapping to release */
    size_t map_size;
    uint64_t header_size;
    chunk_loc *frames, *res;
    size_t nframes, cap_frames, nres, cap_res;
    rgl_error *damage;
    size_t ndamage, cap_damage;
    char *info; /* NUL-terminated copy of the INFO text */
    size_t info_size;
    bool closed;   /* the file ends with an END trailer */
    uint64_t tail; /* not closed: offset of the chunk the file's end cuts
                      short, or the file size */
};

rgl_status rgl_set_error(rgl_error *err, rgl_status status, uint64_t offset, uint32_t opcode,
                         const char *fmt, ...)
{
    va_list ap;
    if (!err)
        return status;
    memset(err, 0, sizeof *err);
    err->status = status;
    err->offset = offset;
    err->opcode = opcode;
    va_start(ap, fmt);
    vsnprintf(err->detail, sizeof err->detail, fmt, ap);
    va_end(ap);
    return status;
}

/* The reader's errors name no command. */
#define set_error(err, status, offset, ...) rgl_set_error((err), (status), (offset), 0, __VA_ARGS__)

static uint32_t bswap32(uint32_t v)
{
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

/* ---- Chunk headers ---------------------------------------------------------- */

typedef struct chunk_hdr {
    uint8_t type, flags;
    uint32_t length;
} chunk_hdr;

/* Checks the 16-byte header at off: room, sync, checksum, length limit. */
static rgl_status check_header(const rgl_reader *r, uint64_t off, chunk_hdr *h)
{
    const uint8_t *p;
    if (off > r->size || r->size - off < RGL_CHUNK_HEADER_SIZE)
        return RGL_E_TRUNCATED;
    p = r->data + off;
    if (memcmp(p, RGL_CHUNK_SYNC, 4) != 0)
        return RGL_E_CHUNK;
    if (rgl_crc32c(0, p, 12) != rgl_get_u32(p + 12))
        return RGL_E_CHECKSUM;
    h->type = p[4];
    h->flags = p[5];
    h->length = rgl_get_u32(p + 8);
    if (h->length > RGL_CHUNK_MAX_PAYLOAD)
        return RGL_E_CHUNK;
    return RGL_OK;
}

/* Whether the whole chunk at off (header, payload, trailer) ends by `limit`. */
static bool chunk_fits(uint64_t off, const chunk_hdr *h, uint64_t limit)
{
    return off <= limit && limit - off >= (uint64_t)CHUNK_MIN + h->length;
}

static bool payload_ok(const rgl_reader *r, uint64_t off, uint32_t length)
{
    const uint8_t *p = r->data + off + RGL_CHUNK_HEADER_SIZE;
    return rgl_crc32c(0, p, length) == rgl_get_u32(p + length);
}

/* ---- Growing arrays --------------------------------------------------------- */

static bool grow(void **arr, size_t *cap, size_t n, size_t elem)
{
    void *na;
    size_t ncap;
    if (n < *cap)
        return true;
    ncap = *cap ? *cap * 2 : 16;
    na = rgl_format_realloc(*arr, ncap * elem);
    if (!na)
        return false;
    *arr = na;
    *cap = ncap;
    return true;
}

static rgl_status push_chunk(chunk_loc **arr, size_t *n, size_t *cap, uint64_t off,
                             uint32_t length, uint32_t id)
{
    if (!grow((void **)arr, cap, *n, sizeof **arr))
        return RGL_E_NOMEM;
    (*arr)[*n].offset = off;
    (*arr)[*n].length = length;
    (*arr)[*n].id = id;
    (*n)++;
    return RGL_OK;
}

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static rgl_status add_damage(rgl_reader *r, rgl_status status, uint64_t offset, const char *fmt,
                             ...)
{
    rgl_error *e;
    va_list ap;
    if (r->ndamage >= DAMAGE_MAX)
        return RGL_OK;
    if (!grow((void **)&r->damage, &r->cap_damage, r->ndamage, sizeof *r->damage))
        return RGL_E_NOMEM;
    e = &r->damage[r->ndamage++];
    memset(e, 0, sizeof *e);
    e->status = status;
    e->offset = offset;
    va_start(ap, fmt);
    vsnprintf(e->detail, sizeof e->detail, fmt, ap);
    va_end(ap);
    return RGL_OK;
}

/* Reads a canonical varint of at most 10 bytes, at most `limit`. */
static bool get_var(const uint8_t **pp, const uint8_t *end, uint64_t limit, uint64_t *out)
{
    const uint8_t *p = *pp;
    uint64_t v;
    if (rgl_get_varint(&p, end, RGL_VARINT64_MAX, &v) != 0)
        return false;
    if ((p - *pp > 1 && p[-1] == 0) || v > limit)
        return false;
    *pp = p;
    *out = v;
    return true;
}

/* The id at the start of a resource payload, or 0 when it is not valid. */
static uint32_t resource_id(const rgl_reader *r, uint64_t off, uint32_t length)
{
    const uint8_t *p = r->data + off + RGL_CHUNK_HEADER_SIZE;
    uint64_t id;
    if (!get_var(&p, p + length, RGL_RESOURCE_ID_MAX, &id))
        return 0;
    return (uint32_t)id;
}

static rgl_status take_info(rgl_reader *r, uint64_t off, uint32_t length)
{
    if (r->info)
        return RGL_OK; /* the first INFO chunk counts */
    if (!payload_ok(r, off, length))
        return add_damage(r, RGL_E_CHECKSUM, off + RGL_CHUNK_HEADER_SIZE,
                          "INFO chunk at 0x%llx: payload checksum", (unsigned long long)off);
    r->info = rgl_format_realloc(NULL, (size_t)length + 1);
    if (!r->info)
        return RGL_E_NOMEM;
    memcpy(r->info, r->data + off + RGL_CHUNK_HEADER_SIZE, length);
    r->info[length] = '\0';
    r->info_size = length;
    return RGL_OK;
}

/* ---- The index path ------------------------------------------------------------- */

/* Uses the END trailer and the INDEX chunk. Returns RGL_OK with the chunk
 * lists filled, RGL_E_NOMEM, or RGL_E_CHUNK when there is no usable index
 * (the caller then scans). */
static rgl_status load_index(rgl_reader *r)
{
    uint64_t end_off, idx_off, n, v, id, prev = 0;
    const uint8_t *p, *pend;
    chunk_hdr h;

    if (r->size - r->header_size < END_CHUNK_SIZE + CHUNK_MIN)
        return RGL_E_CHUNK;
    end_off = r->size - END_CHUNK_SIZE;
    if (check_header(r, end_off, &h) != RGL_OK || h.type != RGL_CHUNK_END || h.length != 8 ||
        !payload_ok(r, end_off, 8))
        return RGL_E_CHUNK;
    idx_off = rgl_get_u64(r->data + end_off + RGL_CHUNK_HEADER_SIZE);
    if (idx_off < r->header_size || check_header(r, idx_off, &h) != RGL_OK ||
        h.type != RGL_CHUNK_INDEX || !chunk_fits(idx_off, &h, end_off) ||
        !payload_ok(r, idx_off, h.length))
        return RGL_E_CHUNK;

    p = r->data + idx_off + RGL_CHUNK_HEADER_SIZE;
    pend = p + h.length;
    /* Frames: offsets in file order. A count over the bytes left or over the
     * chunks the file can hold is rejected before anything is allocated. */
    if (!get_var(&p, pend, (uint64_t)(pend - p), &n) || n > r->size / CHUNK_MIN)
        return RGL_E_CHUNK;
    for (uint64_t i = 0; i < n; i++) {
        chunk_hdr fh;
        if (!get_var(&p, pend, UINT64_MAX, &v) || v < r->header_size || (i && v <= prev) ||
            check_header(r, v, &fh) != RGL_OK || fh.type != RGL_CHUNK_FRAME ||
            !chunk_fits(v, &fh, idx_off))
            return RGL_E_CHUNK;
        if (push_chunk(&r->frames, &r->nframes, &r->cap_frames, v, fh.length, 0) != RGL_OK)
            return RGL_E_NOMEM;
        prev = v;
    }
    if (!get_var(&p, pend, (uint64_t)(pend - p), &n) || n > r->size / CHUNK_MIN)
        return RGL_E_CHUNK;
    for (uint64_t i = 0; i < n; i++) {
        chunk_hdr rh;
        if (!get_var(&p, pend, RGL_RESOURCE_ID_MAX, &id) || id == 0 ||
            !get_var(&p, pend, UINT64_MAX, &v) || v < r->header_size ||
            check_header(r, v, &rh) != RGL_OK || rh.type != RGL_CHUNK_RESOURCE ||
            !chunk_fits(v, &rh, idx_off) || resource_id(r, v, rh.length) != id)
            return RGL_E_CHUNK;
        if (push_chunk(&r->res, &r->nres, &r->cap_res, v, rh.length, (uint32_t)id) != RGL_OK)
            return RGL_E_NOMEM;
    }
    r->closed = true;
    /* The index does not list INFO: it is the first chunk when there is one. */
    if (check_header(r, r->header_size, &h) == RGL_OK && h.type == RGL_CHUNK_INFO &&
        chunk_fits(r->header_size, &h, r->size))
        return take_info(r, r->header_size, h.length);
    return RGL_OK;
}

/* ---- The scan path --------------------------------------------------------------- */

/* The next offset from `from` holding a sync pattern whose header checks out,
 * or the file size. Each offset is looked at once, so the scan is linear. */
static uint64_t resync(const rgl_reader *r, uint64_t from)
{
    while (from + RGL_CHUNK_HEADER_SIZE <= r->size) {
        const uint8_t *q = memchr(r->data + from, RGL_CHUNK_SYNC[0],
                                  r->size - from - (RGL_CHUNK_HEADER_SIZE - 1));
        chunk_hdr h;
        if (!q)
            break;
        from = (uint64_t)(q - r->data);
        if (check_header(r, from, &h) == RGL_OK)
            return from;
        from++;
    }
    return r->size;
}

static const char *status_word(rgl_status st)
{
    switch (st) {
    case RGL_E_CHECKSUM: return "header checksum";
    case RGL_E_CHUNK: return "bad sync or length";
    default: return "header cut short";
    }
}

/* Whether the bytes from pos to the end of the file are the start of a
 * chunk that the end cuts short, as a recording stopped in mid-write
 * leaves it: a whole header whose chunk runs past the end, or the start of
 * a header, with nothing after it. */
static bool cut_tail(const rgl_reader *r, uint64_t pos, rgl_status hs)
{
    size_t left = (size_t)(r->size - pos);
    if (hs == RGL_OK)
        return resync(r, pos + 1) == r->size;
    return hs == RGL_E_TRUNCATED &&
           memcmp(r->data + pos, RGL_CHUNK_SYNC, left < 4 ? left : 4) == 0;
}

static rgl_status scan(rgl_reader *r)
{
    uint64_t pos = r->header_size;
    rgl_status st;
    bool last_end = false; /* the last chunk read is an END trailer */

    r->tail = r->size;
    while (pos < r->size) {
        chunk_hdr h;
        rgl_status hs = check_header(r, pos, &h);
        uint64_t next;

        if (hs == RGL_OK && chunk_fits(pos, &h, r->size)) {
            uint64_t payload = pos + RGL_CHUNK_HEADER_SIZE;
            st = RGL_OK;
            last_end = h.type == RGL_CHUNK_END;
            if (h.type == RGL_CHUNK_FRAME) {
                st = push_chunk(&r->frames, &r->nframes, &r->cap_frames, pos, h.length, 0);
            } else if (h.type == RGL_CHUNK_RESOURCE) {
                uint32_t id = resource_id(r, pos, h.length);
                if (id)
                    st = push_chunk(&r->res, &r->nres, &r->cap_res, pos, h.length, id);
                else
                    st = add_damage(r, RGL_E_RESOURCE, payload,
                                    "resource chunk at 0x%llx: bad id", (unsigned long long)pos);
            } else if (h.type == RGL_CHUNK_INFO) {
                st = take_info(r, pos, h.length);
            } /* INDEX, END and types of later minors: skipped */
            if (st != RGL_OK)
                return st;
            pos += (uint64_t)CHUNK_MIN + h.length;
            continue;
        }

        last_end = false;
        if (cut_tail(r, pos, hs)) {
            r->tail = pos; /* the chunk being written when the recording stopped */
            break;
        }
        next = resync(r, pos + 1);
        if (hs == RGL_OK)
            st = add_damage(r, RGL_E_TRUNCATED, pos,
                            "chunk of %lu bytes at 0x%llx runs past the end (0x%llx)",
                            (unsigned long)h.length, (unsigned long long)pos,
                            (unsigned long long)r->size);
        else
            st = add_damage(r, hs, pos, "damaged region 0x%llx..0x%llx: %s",
                            (unsigned long long)pos, (unsigned long long)next, status_word(hs));
        if (st != RGL_OK)
            return st;
        pos = next;
    }
    r->closed = last_end && r->tail == r->size;
    return RGL_OK;
}

/* ---- Opening ------------------------------------------------------------------------ */

static rgl_status check_file_header(const uint8_t *d, size_t size, uint64_t *header_size,
                                    rgl_error *err)
{
    uint16_t major;
    uint32_t hsize;

    if (size < RGL_FILE_MAGIC_SIZE) {
        if (memcmp(d, RGL_FILE_MAGIC, size) != 0)
            return set_error(err, RGL_E_MAGIC, 0, "not a RayGL trace");
        return set_error(err, RGL_E_TRUNCATED, size, "file of %zu bytes: no header", size);
    }
    if (memcmp(d, RGL_FILE_MAGIC, RGL_FILE_MAGIC_SIZE) != 0)
        return set_error(err, RGL_E_MAGIC, 0, "not a RayGL trace");
    if (size < RGL_FILE_HEADER_SIZE)
        return set_error(err, RGL_E_TRUNCATED, size, "file of %zu bytes: header cut short", size);
    major = rgl_get_u16(d + 8);
    if (major != RGL_FORMAT_MAJOR) {
        /* A writer that got the byte order wrong also swapped the version. */
        if (rgl_get_u32(d + 16) == bswap32(RGL_SAMPLE_U32))
            return set_error(err, RGL_E_BYTE_ORDER, 16, "samples are byte-swapped");
        return set_error(err, RGL_E_VERSION, 8, "format %u.%u, this reader knows %u.x", major,
                         rgl_get_u16(d + 10), RGL_FORMAT_MAJOR);
    }
    if (rgl_get_u32(d + 16) != RGL_SAMPLE_U32)
        return set_error(err, RGL_E_BYTE_ORDER, 16, "integer sample 0x%08lx, expected 0x%08lx",
                         (unsigned long)rgl_get_u32(d + 16), (unsigned long)RGL_SAMPLE_U32);
    if (rgl_get_u32(d + 20) != RGL_SAMPLE_F32)
        return set_error(err, RGL_E_BYTE_ORDER, 20, "float sample 0x%08lx, expected 0x%08lx",
                         (unsigned long)rgl_get_u32(d + 20), (unsigned long)RGL_SAMPLE_F32);
    if (rgl_crc32c(0, d, 28) != rgl_get_u32(d + 28))
        return set_error(err, RGL_E_CHECKSUM, 28, "file header checksum");
    hsize = rgl_get_u32(d + 24);
    if (hsize < RGL_FILE_HEADER_SIZE)
        return set_error(err, RGL_E_VERSION, 24, "header size %lu", (unsigned long)hsize);
    if (hsize > size)
        return set_error(err, RGL_E_TRUNCATED, size, "header of %lu bytes cut short",
                         (unsigned long)hsize);
    *header_size = hsize;
    return RGL_OK;
}

static int cmp_res(const void *a, const void *b)
{
    const chunk_loc *x = a, *y = b;
    if (x->id != y->id)
        return x->id < y->id ? -1 : 1;
    return x->offset < y->offset ? -1 : x->offset > y->offset;
}

static void reset_lists(rgl_reader *r)
{
    r->nframes = r->nres = 0;
}

static rgl_status open_common(rgl_reader *r, rgl_error *err)
{
    rgl_status st = check_file_header(r->data, r->size, &r->header_size, err);
    size_t w = 0;

    if (st != RGL_OK)
        return st;
    st = load_index(r);
    if (st == RGL_E_CHUNK) {
        reset_lists(r);
        rgl_format_realloc(r->info, 0);
        r->info = NULL;
        r->ndamage = 0;
        st = scan(r);
    }
    if (st != RGL_OK)
        return set_error(err, st, 0, "while finding chunks");

    /* Resources by id; of several with one id the first in the file wins,
     * unless its payload is damaged and a later one is whole (a damaged id
     * byte can make one resource claim another's id). */
    if (r->nres > 1) /* qsort's array must not be NULL, even for 0 elements */
        qsort(r->res, r->nres, sizeof *r->res, cmp_res);
    for (size_t i = 0; i < r->nres;) {
        size_t j = i, pick = i;
        while (j < r->nres && r->res[j].id == r->res[i].id)
            j++;
        if (j - i > 1)
            for (size_t k = i; k < j; k++)
                if (payload_ok(r, r->res[k].offset, r->res[k].length)) {
                    pick = k;
                    break;
                }
        r->res[w++] = r->res[pick];
        i = j;
    }
    r->nres = w;
    if (err)
        memset(err, 0, sizeof *err);
    return RGL_OK;
}

rgl_status rgl_reader_open_memory(const uint8_t *data, size_t size, rgl_reader **out,
                                  rgl_error *err)
{
    rgl_reader *r;
    rgl_status st;

    if (!out || (!data && size))
        return set_error(err, RGL_E_ARGUMENT, 0, "no output or no data");
    *out = NULL;
    r = rgl_format_realloc(NULL, sizeof *r);
    if (!r)
        return set_error(err, RGL_E_NOMEM, 0, "reader");
    memset(r, 0, sizeof *r);
    r->data = data ? data : (const uint8_t *)"";
    r->size = size;
    st = open_common(r, err);
    if (st != RGL_OK) {
        rgl_reader_destroy(r);
        return st;
    }
    *out = r;
    return RGL_OK;
}

rgl_status rgl_reader_open_file(const char *path, rgl_reader **out, rgl_error *err)
{
    struct stat sb;
    rgl_reader *r = NULL;
    rgl_status st;
    void *map;
    int fd, saved;

    if (!out || !path)
        return set_error(err, RGL_E_ARGUMENT, 0, "no path or no output");
    *out = NULL;
    fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return set_error(err, RGL_E_IO, 0, "open: %s", strerror(errno));
    if (fstat(fd, &sb) != 0) {
        st = set_error(err, RGL_E_IO, 0, "fstat: %s", strerror(errno));
        goto fail_fd;
    }
    if (!S_ISREG(sb.st_mode)) {
        st = set_error(err, RGL_E_IO, 0, "not a regular file");
        goto fail_fd;
    }
    if (sb.st_size == 0) {
        st = set_error(err, RGL_E_TRUNCATED, 0, "empty file");
        goto fail_fd;
    }
    if ((uint64_t)sb.st_size > SIZE_MAX) {
        st = set_error(err, RGL_E_LIMIT, 0, "file too large to map");
        goto fail_fd;
    }
    map = mmap(NULL, (size_t)sb.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (map == MAP_FAILED) {
        st = set_error(err, RGL_E_IO, 0, "mmap: %s", strerror(errno));
        goto fail_fd;
    }
    close(fd);
    r = rgl_format_realloc(NULL, sizeof *r);
    if (!r) {
        munmap(map, (size_t)sb.st_size);
        return set_error(err, RGL_E_NOMEM, 0, "reader");
    }
    memset(r, 0, sizeof *r);
    r->map = map;
    r->map_size = (size_t)sb.st_size;
    r->data = map;
    r->size = (size_t)sb.st_size;
    st = open_common(r, err);
    if (st != RGL_OK) {
        rgl_reader_destroy(r);
        return st;
    }
    *out = r;
    return RGL_OK;

fail_fd:
    saved = errno;
    close(fd);
    errno = saved;
    return st;
}

void rgl_reader_destroy(rgl_reader *r)
{
    if (!r)
        return;
    if (r->map)
        munmap(r->map, r->map_size);
    rgl_format_realloc(r->frames, 0);
    rgl_format_realloc(r->res, 0);
    rgl_format_realloc(r->damage, 0);
    rgl_format_realloc(r->info, 0);
    rgl_format_realloc(r, 0);
}

/* ---- Access -------------------------------------------------------------------------- */

size_t rgl_reader_frame_count(const rgl_reader *r) { return r ? r->nframes : 0; }

size_t rgl_reader_damage_count(const rgl_reader *r) { return r ? r->ndamage : 0; }

bool rgl_reader_closed(const rgl_reader *r, uint64_t *tail)
{
    if (tail)
        *tail = r && !r->closed ? r->tail : 0;
    return r && r->closed;
}

const rgl_error *rgl_reader_damage(const rgl_reader *r, size_t i)
{
    return r && i < r->ndamage ? &r->damage[i] : NULL;
}

const char *rgl_reader_info(const rgl_reader *r, size_t *size)
{
    if (size)
        *size = r && r->info ? r->info_size : 0;
    return r ? r->info : NULL;
}

rgl_status rgl_reader_frame(rgl_reader *r, size_t i, rgl_frame_info *out, rgl_error *err)
{
    const chunk_loc *c;
    const uint8_t *p, *start, *end;
    uint64_t v[4];

    if (!r || !out)
        return set_error(err, RGL_E_ARGUMENT, 0, "no reader or no output");
    if (i >= r->nframes)
        return set_error(err, RGL_E_ARGUMENT, 0, "frame %zu of %zu", i, r->nframes);
    c = &r->frames[i];
    start = p = r->data + c->offset + RGL_CHUNK_HEADER_SIZE;
    end = p + c->length;
    if (!payload_ok(r, c->offset, c->length))
        return set_error(err, RGL_E_CHECKSUM, c->offset + RGL_CHUNK_HEADER_SIZE,
                         "frame %zu (chunk at 0x%llx): payload checksum", i,
                         (unsigned long long)c->offset);
    for (int k = 0; k < 4; k++) {
        const uint8_t *at = p;
        if (!get_var(&p, end, UINT32_MAX, &v[k]))
            return set_error(err, p >= end ? RGL_E_TRUNCATED : RGL_E_VARINT,
                             c->offset + RGL_CHUNK_HEADER_SIZE + (uint64_t)(at - start),
                             "frame %zu: bad frame header field %d", i, k);
    }
    out->stream = (uint32_t)v[0];
    out->number = (uint32_t)v[1];
    out->flags = (uint32_t)v[2];
    out->state = (uint32_t)v[3];
    out->offset = c->offset;
    out->commands = p;
    out->commands_size = (size_t)(end - p);
    out->commands_offset = c->offset + RGL_CHUNK_HEADER_SIZE + (uint64_t)(p - start);
    if (err)
        memset(err, 0, sizeof *err);
    return RGL_OK;
}

rgl_status rgl_reader_resource(rgl_reader *r, uint32_t id, rgl_resource *out, rgl_error *err)
{
    size_t lo = 0, hi;
    const chunk_loc *c = NULL;
    const uint8_t *p, *start, *end;
    uint64_t rid, kind;

    if (!r || !out)
        return set_error(err, RGL_E_ARGUMENT, 0, "no reader or no output");
    hi = r->nres;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (r->res[mid].id == id) {
            c = &r->res[mid];
            break;
        }
        if (r->res[mid].id < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (!c)
        return set_error(err, RGL_E_RESOURCE, 0, "no resource #%lu", (unsigned long)id);
    start = p = r->data + c->offset + RGL_CHUNK_HEADER_SIZE;
    end = p + c->length;
    if (!payload_ok(r, c->offset, c->length))
        return set_error(err, RGL_E_CHECKSUM, c->offset + RGL_CHUNK_HEADER_SIZE,
                         "resource #%lu (chunk at 0x%llx): payload checksum", (unsigned long)id,
                         (unsigned long long)c->offset);
    if (!get_var(&p, end, RGL_RESOURCE_ID_MAX, &rid) || rid != id ||
        !get_var(&p, end, UINT32_MAX, &kind))
        return set_error(err, RGL_E_RESOURCE, c->offset + RGL_CHUNK_HEADER_SIZE,
                         "resource #%lu: bad id or kind", (unsigned long)id);
    out->id = id;
    out->kind = (uint32_t)kind;
    out->data = p;
    out->size = (size_t)(end - p);
    out->data_offset = c->offset + RGL_CHUNK_HEADER_SIZE + (uint64_t)(p - start);
    if (err)
        memset(err, 0, sizeof *err);
    return RGL_OK;
}

size_t rgl_reader_resource_count(const rgl_reader *r) { return r ? r->nres : 0; }

rgl_status rgl_reader_resource_at(rgl_reader *r, size_t i, rgl_resource *out, rgl_error *err)
{
    if (!r || !out)
        return set_error(err, RGL_E_ARGUMENT, 0, "no reader or no output");
    if (i >= r->nres)
        return set_error(err, RGL_E_ARGUMENT, 0, "resource %zu of %zu", i, r->nres);
    return rgl_reader_resource(r, r->res[i].id, out, err);
}
