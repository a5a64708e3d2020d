/* unrec.h: the calls a trace says were not recorded (@NotRecorded,
 * format 1.3), counted by entry point, and what each can change in the
 * picture (format/unrecorded.def).
 *
 * The interpreter fills one table per frame (interp_unrecorded.c), with the
 * frame's uses: what it draws that an unrecorded call can act on (blended
 * draws, textures, ...). The driver adds the frames' tables up in frame order
 * into one for the trace and prints it once, so the report does not depend
 * on -j: a name is reported when its effect can change a frame from its
 * first frame on (it "matters"); the others only when verbose. A table is bounded
 * against a hostile trace: names are cut to UNREC_NAME_MAX bytes of
 * [A-Za-z0-9_] (any other byte shows as '?'), and names beyond the first
 * UNREC_MAX_NAMES are counted together as others.
 */
#ifndef RGL_UNREC_H
#define RGL_UNREC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define UNREC_NAME_MAX 64
#define UNREC_MAX_NAMES 1024

/* The facts of a frame that unrecorded calls may act on (UNREC_USE rows). */
typedef enum unrec_use {
#define UNREC_USE(id, text) UNREC_USE_##id,
#include "unrecorded.def"
    UNREC_USE_COUNT
} unrec_use;

/* What an unrecorded entry point can change (an UNREC_EFFECT row): `needs`
 * holds the uses (1 << UNREC_USE_*) a frame must all have for it to matter
 * there, 0 for always; never is true for calls that change nothing in the
 * picture whatever the frame draws. */
typedef struct unrec_effect {
    uint32_t needs;
    bool never;
    const char *text;
} unrec_effect;

/* The effect of the entry point `name` (NUL-terminated), or NULL for a name
 * the table does not hold: an older recorder's name for a call recorded now,
 * or a name this version does not know; such calls always matter. */
const unrec_effect *unrec_effect_of(const char *name);

/* The text of one use ("blended draws"), or "" for a bad one. */
const char *unrec_use_text(unrec_use u);

typedef struct unrec_entry {
    char name[UNREC_NAME_MAX + 1];
    uint64_t count;       /* saturates at UINT64_MAX */
    uint64_t first_frame; /* the first frame (file order) that names it */
    bool matters;         /* its effect can change a frame merged since its first */
} unrec_entry;

typedef struct unrec_table {
    unrec_entry *e;
    size_t n, cap;
    uint64_t other_calls;  /* calls of names past UNREC_MAX_NAMES */
    uint64_t other_frame;  /* the first frame with such a call */
    uint32_t uses;         /* the frame's uses (1 << UNREC_USE_*), per-frame tables */
} unrec_table;

void unrec_init(unrec_table *t);
void unrec_finish(unrec_table *t);

/* Empties the table (and its uses), keeping its memory. */
void unrec_clear(unrec_table *t);

/* Adds count calls of the entry point named by the len bytes at name (not
 * NUL-terminated), seen in frame `frame`. Returns 0, or -1 when memory ran
 * out (the calls are then counted as others). */
int unrec_add(unrec_table *t, const uint8_t *name, size_t len, uint64_t count, uint64_t frame);

/* Adds every entry of src, seen in frame `frame`, to dst (call in frame
 * order: the first frame of a name is the earliest one added), then marks
 * every entry of dst whose effect src's uses (those of frame `frame`)
 * satisfy as mattering. */
int unrec_merge(unrec_table *dst, const unrec_table *src, uint64_t frame);

/* Copies src, its uses too, into dst (dst initialised). Returns 0 or -1
 * (memory). */
int unrec_copy(unrec_table *dst, const unrec_table *src);

/* Which entries a report shows. */
typedef enum unrec_mode {
    UNREC_REPORT_MATTERS, /* those that matter (the default) */
    UNREC_REPORT_VERBOSE, /* all; those that do not matter marked (--verbose) */
    UNREC_REPORT_DUMP,    /* all, by their effect alone: no frame was translated (--dump) */
} unrec_mode;

/* The report, one line per entry point, sorted by name. The entries that
 * matter, and names the table does not hold, say what is missing:
 *   "glBlendColor: 1,204 calls not recorded, from frame 3: the blend colour: ..."
 * then "N calls of other entry points not recorded, from frame F" for the
 * others. Verbose adds the entries that do not matter, marked:
 *   "glutInit: 1 call not recorded, from frame 0 (cannot change the
 *    picture: nothing in the picture: the window system ...)"
 * and the dump's report says of each effect what it needs:
 *   "glBlendColor: 3 calls not recorded, from frame 0 (changes the picture
 *    only with draws blended with a GL_CONSTANT_* factor): the blend ..."
 * Calls line(text, user) for each line. */
void unrec_report(unrec_table *t, unrec_mode mode, void (*line)(const char *text, void *user),
                  void *user);

#endif
