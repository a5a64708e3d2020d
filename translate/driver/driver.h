/* driver.h: the frame driver: a trace's frames through the pipeline.
 *
 *   format/ (decode) -> gl/ (GL state machine) -> scene -> look/ -> a writer
 *
 * driver_run opens the trace, says what its damage is, and (with an output
 * folder) runs the selected frames: workers (one translator each,
 * frame.h) take them in file order, build each scene, apply the look and
 * have the writer write it to a temporary file; the main thread takes the
 * results in frame order, prints their diagnostics, picks the final names
 * and has the writer put the files in place. So the output and the
 * messages do not depend on -j, and an interrupted or failed run leaves no
 * half-written scene under a final name. Then it renders what was written
 * when asked (render.h).
 *
 * Messages: "PROG: TRACE: frame 12, cmd 1234 (glLightfv) @0x1f0: ...".
 */
#ifndef RGL_DRIVER_H
#define RGL_DRIVER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "framesel.h"
#include "look.h"
#include "render.h"
#include "writer.h"

#define DRIVER_MAX_JOBS 256
#define DRIVER_EXIT_INPUT 1 /* a damaged trace, output that cannot be written */

/* Frames first..last (inclusive; last = UINT64_MAX for "A-"), every
 * step-th: one item of a --frames list (format/framesel.h). */
typedef rgl_frame_range frame_range;

/* Whether frame (or scene) i is selected by ranges (all of them when n is 0). */
bool frames_selected(const frame_range *ranges, size_t n, uint64_t i);

typedef struct driver_settings {
    const char *prog;   /* for messages */
    const char *trace;
    const char *outdir; /* NULL: no translation (--dump alone) */
    const frame_range *ranges;
    size_t nranges;
    int jobs;           /* 1 .. DRIVER_MAX_JOBS */
    bool dump, quiet;
    bool verbose;                 /* also the notes held and calls not recorded
                                     that cannot change the picture */
    bool vertex_lighting;         /* interp_set_vertex_lighting */
    bool pov;                     /* the scenes are for POV-Ray (interp_set_pov) */
    bool quality_note;            /* POV-Ray renders below quality 6: say so of a
                                     frame that needs more (scene_needs_quality6) */
    const writer_def *writer;
    const char *name_pattern;     /* naming.h; NULL: the default */
    const look_settings *look;
    const render_settings *render; /* what to render afterwards (render_wanted) */
} driver_settings;

/* The writers (translate/meson.build's list), and the one named name
 * (NULL: none). */
extern const writer_def *const driver_writers[];
const writer_def *driver_writer(const char *name);

/* Runs everything d asks for. Returns the exit status: 0, or
 * DRIVER_EXIT_INPUT (every intact frame is still written). Prints its
 * messages on stderr, --dump's listing on stdout. */
int driver_run(const driver_settings *d);

#endif
