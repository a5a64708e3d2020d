/* driver_internal.h: what the driver's files share (run.c, report.c,
 * tracedump.c); not for other users.
 */
#ifndef RGL_DRIVER_INTERNAL_H
#define RGL_DRIVER_INTERNAL_H

#include <pthread.h>
#include <stdatomic.h>

#include "diag.h"
#include "driver.h"
#include "format.h"
#include "frame.h"
#include "unrec.h"

/* One selected frame on its way: filled by a worker, published by the
 * main thread in frame order. */
typedef struct slot {
    size_t frame;       /* index in the file */
    atomic_int done;    /* the worker finished with it */
    rgl_status status;  /* translation */
    rgl_error error;
    rgl_frame_info info;
    diag_log *log;
    char *frame_name;   /* rayglFrameBegin's, or NULL */
    writer_kept kept;   /* what publishing needs of the scene */
    int write_errno;    /* writing the temporary scene file failed */
    char *write_failed; /* the file it could not write (a side file such as a
                           texture), or NULL: the temporary scene file */
    const char *look_note; /* look_apply's, static */
    char *published;       /* "DIR/NAME" once written */
    long tmp_id;           /* the temporary scene file's cleanup entry, or -1 */
    unrec_table unrec;     /* the frame's calls not recorded */
    char *incomplete;      /* why the scene is incomplete: the cut, then what
                              damage took (frame_result), or NULL */
    bool damaged;          /* a part of it was lost to damage */
    interp_budget_use used, limit; /* of the frame budget (--dump) */
} slot;

typedef struct totals {
    diag_log log;      /* counts of everything; the messages already printed */
    uint64_t printed[DIAG_COUNT];
    uint64_t printed_held[DIAG_COUNT]; /* held notes printed (--verbose) */
    int status;        /* exit status so far */
    size_t written;
} totals;

/* ---- Messages (report.c) ---------------------------------------------------------------- */

/* "PROG: TRACE: " and the text, on its own line (over the progress line). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void drv_say(const driver_settings *d, const char *fmt, ...);
/* drv_say for a line of text, as a callback (user: the settings). */
void drv_say_line(const char *text, void *user);
/* "WHERE, cmd N (glName) @0x1f0: truncated: detail". */
void drv_say_decode_error(const driver_settings *d, const char *where, const rgl_error *e);
/* Clears the progress line; whether one was shown before. */
bool drv_clear_progress(void);
void drv_progress(const driver_settings *d, size_t done, size_t total);
/* A frame's diagnostics, counted into tot: each note once per run (the
 * first said, and with --verbose the first held, marked), other kinds
 * DIAG_KEEP times, then a count. */
void drv_print_diags(const driver_settings *d, totals *tot, const diag_log *log);
/* A frame written incomplete: the cut is a note, damage is said and
 * counted in the exit status even with --quiet. */
void drv_say_incomplete(const driver_settings *d, totals *tot, const slot *s);
/* --dump while translating: what the frame used of each budget, on
 * standard output after the dump. */
void drv_say_budget(const driver_settings *d, const slot *s);
/* How many calls were skipped in all, notes held (--verbose), messages
 * left out. */
void drv_print_summary(const driver_settings *d, const totals *tot);
/* "cut at ...\nwritten without ..." for a frame written incomplete, or
 * NULL (no memory: the details are then lost, not the frame). */
char *drv_incomplete_text(const frame_result *res);

/* ---- --dump (tracedump.c) -------------------------------------------------------------------- */

/* Prints every selected frame and command; DRIVER_EXIT_INPUT on damage. */
int drv_dump(const driver_settings *d, rgl_reader *r);

#endif
