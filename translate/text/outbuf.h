/* outbuf.h: a buffered text sink for the writers.
 *
 * Text goes into a buffer; when it fills, the buffer is handed to a flush
 * callback (a file descriptor, say), or, for a sink with no callback, the
 * buffer grows and keeps everything (the fuzz target, the golden tests).
 * The first failure is sticky: later writes are dropped and ob->failed
 * tells. Writers reserve space and write numbers straight into it, so the
 * hot path is a bounds check and a copy.
 */
#ifndef RGL_OUTBUF_H
#define RGL_OUTBUF_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "numfmt.h"

typedef struct outbuf {
    char *buf;
    size_t len, cap;
    /* Writes all n bytes or returns -1. NULL: keep everything in memory. */
    int (*flush)(void *user, const char *data, size_t n);
    void *user;
    uint64_t total; /* bytes accepted so far */
    bool failed;
} outbuf;

/* A sink flushing to `flush` every `cap` bytes (cap >= 256), or in memory
 * when flush is NULL. Returns 0, or -1 when the buffer cannot be allocated. */
int outbuf_init(outbuf *ob, size_t cap, int (*flush)(void *user, const char *data, size_t n),
                void *user);
/* Frees the buffer (without flushing). */
void outbuf_finish(outbuf *ob);

/* Hands everything buffered to the callback. Returns 0 or -1 (sticky). */
int outbuf_flush(outbuf *ob);

/* Makes room for n more bytes (n <= 256 for flushing sinks); returns the
 * write position, or NULL after a failure. Commit with outbuf_commit. */
char *outbuf_room_slow(outbuf *ob, size_t n);

static inline char *outbuf_room(outbuf *ob, size_t n)
{
    if (ob->cap - ob->len >= n)
        return ob->buf + ob->len;
    return outbuf_room_slow(ob, n);
}

static inline void outbuf_commit(outbuf *ob, size_t n)
{
    ob->len += n;
    ob->total += n;
}

/* Appends bytes (any length). */
void outbuf_write(outbuf *ob, const char *s, size_t n);

static inline void outbuf_puts(outbuf *ob, const char *s) { outbuf_write(ob, s, strlen(s)); }

static inline void outbuf_putc(outbuf *ob, char c)
{
    char *p = outbuf_room(ob, 1);
    if (p) {
        *p = c;
        outbuf_commit(ob, 1);
    }
}

/* A float, shortest round-trip text (numfmt_f32). */
static inline void outbuf_f32(outbuf *ob, float v)
{
    char *p = outbuf_room(ob, NUMFMT_F32_ROOM);
    if (p)
        outbuf_commit(ob, numfmt_f32(p, v));
}

static inline void outbuf_u64(outbuf *ob, uint64_t v)
{
    char *p = outbuf_room(ob, 24);
    if (p)
        outbuf_commit(ob, numfmt_u64(p, v));
}

static inline void outbuf_i64(outbuf *ob, int64_t v)
{
    char *p = outbuf_room(ob, 24);
    if (p)
        outbuf_commit(ob, numfmt_i64(p, v));
}

#endif
