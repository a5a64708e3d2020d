/* unrec.h: the calls a trace says were not recorded (@NotRecorded,
 * format 1.3), counted by entry point.
 *
 * The interpreter fills one table per frame (interp_unrecorded.c); the
 * driver adds the frames' tables up in frame order into one for the trace and
 * prints it once, so the report does not depend on -j. A table is bounded
 * against a hostile trace: names are cut to UNREC_NAME_MAX bytes of
 * [A-Za-z0-9_] (any other byte shows as '?'), and names beyond the first
 * UNREC_MAX_NAMES are counted together as others.
 */
#ifndef RGL_UNREC_H
#define RGL_UNREC_H

#include <stddef.h>
#include <stdint.h>

#define UNREC_NAME_MAX 64
#define UNREC_MAX_NAMES 1024

typedef struct unrec_entry {
    char name[UNREC_NAME_MAX + 1];
    uint64_t count;       /* saturates at UINT64_MAX */
    uint64_t first_frame; /* the first frame (file order) that names it */
} unrec_entry;

typedef struct unrec_table {
    unrec_entry *e;
    size_t n, cap;
    uint64_t other_calls;  /* calls of names past UNREC_MAX_NAMES */
    uint64_t other_frame;  /* the first frame with such a call */
} unrec_table;

void unrec_init(unrec_table *t);
void unrec_finish(unrec_table *t);

/* Empties the table, keeping its memory. */
void unrec_clear(unrec_table *t);

/* Adds count calls of the entry point named by the len bytes at name (not
 * NUL-terminated), seen in frame `frame`. Returns 0, or -1 when memory ran
 * out (the calls are then counted as others). */
int unrec_add(unrec_table *t, const uint8_t *name, size_t len, uint64_t count, uint64_t frame);

/* Adds every entry of src, seen in frame `frame`, to dst (call in frame
 * order: the first frame of a name is the earliest one added). */
int unrec_merge(unrec_table *dst, const unrec_table *src, uint64_t frame);

/* Copies src into dst (dst initialised). Returns 0 or -1 (memory). */
int unrec_copy(unrec_table *dst, const unrec_table *src);

/* The report, one line per entry point, sorted by name:
 *   "glAccum: 1,204 calls not recorded, from frame 3"
 * then "N calls of other entry points not recorded, from frame F" for the
 * others. Calls line(text, user) for each line. */
void unrec_report(unrec_table *t, void (*line)(const char *text, void *user), void *user);

#endif
