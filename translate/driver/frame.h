/* frame.h: building the scene of one frame of a trace: state, commands.
 *
 * Frames are independent. To translate frame i the translator starts from
 * GL's initial state, or, for a frame flagged RGL_FRAME_STATE_CARRIED, from
 * the state its stream's earlier frames left (replayed with no scene: only
 * their state-setting effects count); then it replays the frame's state
 * snapshot resource when it has one, then its commands, into a scene. The
 * driver runs one translator per worker thread (run.c); the fuzz target
 * and the tests use one directly. Writing the scene is a writer's
 * (writer.h).
 */
#ifndef RGL_FRAME_H
#define RGL_FRAME_H

#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>

#include "diag.h"
#include "format.h"
#include "interp.h"
#include "scene.h"

typedef struct translator translator;

/* A translator over reader (borrowed; it must outlive the translator).
 * reader_lock, when not NULL, is held around every reader call (several
 * translators share one reader). NULL on allocation failure. */
translator *translator_create(rgl_reader *reader, pthread_mutex_t *reader_lock);
void translator_destroy(translator *t);

typedef struct frame_result {
    rgl_frame_info info;
    rgl_status status; /* RGL_OK, or why the frame could not be translated */
    rgl_error error;   /* where, when status != RGL_OK */
    const char *frame_name; /* rayglFrameBegin's name (owned by the translator,
                               valid until the next call), or NULL */
    const struct unrec_table *unrecorded; /* the frame's calls not recorded
                               (unrec.h; owned by the translator, valid
                               until the next call) */
    /* A frame built (RGL_OK) may still be incomplete: cut by the frame
     * budget (interp_frame_cut's line), or drawn without parts the damaged
     * trace could not supply (the first as a line, and how many). Empty
     * strings and 0 when complete. */
    char cut[DIAG_TEXT];
    char missing[DIAG_TEXT];
    uint32_t nmissing;
    /* What the frame used of its budget, and the budget (--dump). */
    interp_budget_use used, limit;
} frame_result;

/* Builds the scene of frame i (file order), logging diagnostics into log
 * (may be NULL). A frame whose chunk or commands are damaged reports the
 * decoder's error: the scene then holds what came before the damage, and
 * the caller does not write it. RGL_E_NOMEM when memory ran out. A frame
 * cut by its budget, or missing a part that damage took, is RGL_OK with
 * out->cut or out->missing set: the caller writes it and says so. */
rgl_status translator_build(translator *t, size_t i, diag_log *log, frame_result *out);

/* The frame budget divided by 2^shift (interp_set_budget_shift), for the
 * fuzz target. */
void translator_set_budget_shift(translator *t, unsigned shift);

/* GL's per-vertex lighting for the frames built from now on
 * (interp_set_vertex_lighting). */
void translator_set_vertex_lighting(translator *t, bool on);

/* Shadows in the scenes or not (interp_set_shadows). */
void translator_set_shadows(translator *t, bool on);
/* Scenes for POV-Ray or not (glTF; interp_set_pov). */
void translator_set_pov(translator *t, bool on);

/* Heavy frames (interp_set_heavy): fn(ctx) is called from translator_build
 * when its frame turns heavy, and may block. */
void translator_set_heavy(translator *t, void (*fn)(void *ctx), void *ctx);

/* Gives back the storage the scene keeps for the next frame (after a
 * heavy frame, so that its memory does not stay with the worker). */
void translator_trim(translator *t);

/* The scene the last translator_build made. */
const scene *translator_scene(const translator *t);

/* The same, for changes before it is written (raygl2pov's overrides). */
scene *translator_scene_edit(translator *t);

#endif
