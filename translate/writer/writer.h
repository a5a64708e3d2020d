/* writer.h: what every writer is to the frame driver (driver/run.c).
 *
 * A writer turns a finished scene (scene.h: built by gl/, edited by look/)
 * into files. Writers are peers: each is a folder (pov/, gltf/) whose
 * library defines one writer_def named writer_<folder>, listed once in
 * translate/meson.build ("writers"); the driver finds them by --format's
 * value. Nothing in a writer knows the command line, the interpreter or
 * another writer.
 *
 * A run: begin (the output folder and what every frame shares; files made
 * once per trace are the writer's business here), then per worker thread
 * create, frame for each of its frames, destroy; on the main thread, in
 * frame order, publish for each frame written; then end. frame writes the
 * scene file into an outbuf the driver sinks into a temporary file, and
 * may write side files (texture images) into the folder itself; publish
 * gets the final name and puts the scene file (and companions, such as
 * POV-Ray's .ini) in place.
 *
 * The helpers below (temporary files registered for the stop-signal
 * cleanup, placing a file unless an equal one is there) serve writers and
 * the driver alike.
 */
#ifndef RGL_WRITER_H
#define RGL_WRITER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "outbuf.h"
#include "scene.h"

/* What a run of frames shares. */
typedef struct writer_trace {
    const char *dir;   /* the output folder as the user gave it (made already) */
    const char *trace; /* the trace's name */
    /* Files the user adds to every frame (raygl2pov --include: POV-Ray
     * SDL), as paths; a writer that cannot take them says so in begin. */
    const char *const *includes;
    size_t nincludes;
} writer_trace;

/* One frame to write. Strings may be NULL; a writer escapes them. */
typedef struct writer_frame {
    const char *file_name;  /* the scene file's name as first chosen (STEM.ext) */
    const char *trace;      /* the trace's name */
    uint64_t index;         /* in file order */
    uint32_t stream, number;
    const char *frame_name; /* rayglFrameBegin's name */
    const char *incomplete; /* why the scene is incomplete, one reason a line */
} writer_frame;

/* What publish may read of a frame's scene, kept by frame (the worker's
 * scene is reused by the time the main thread publishes). */
typedef struct writer_kept {
    int width, height;    /* the image (scene.camera) */
    int antialias_depth;  /* scene.antialias_depth */
    scene_options options;
} writer_kept;

/* Where a frame's files go at publication. */
typedef struct writer_place_info {
    const char *dir;       /* the output folder */
    const char *stem;      /* the final name without suffix */
    const char *tmp_scene; /* the scene file frame wrote (DIR/...tmp) */
    const char *tmp_stem;  /* DIR/.raygl2pov-PID-K: other temporary files' prefix */
} writer_place_info;

typedef struct writer_def {
    const char *name;   /* --format's value: "pov" */
    const char *ext;    /* the scene file's suffix: ".pov" */
    const char *engine; /* what renders it (render.h): "povray", "blender" */
    /* Why the output folder cannot be used, or NULL (before anything runs;
     * may be NULL: any folder). */
    const char *(*dir_problem)(const char *dir);
    /* Per run: the writer's shared state (non-NULL), or NULL with a
     * message in msg. *note: set to a text said once for the run (what the
     * format cannot take), or left NULL. */
    void *(*begin)(const writer_trace *t, const char **note, char *msg, size_t cap);
    void (*end)(void *run);
    /* Per worker thread: its working memory (NULL: out of memory); trim
     * gives back what a heavy frame left (0, or -1: out of memory). */
    void *(*create)(void *run);
    void (*destroy)(void *w);
    int (*trim)(void *w);
    /* Writes scene s as the frame's scene file into ob (flushed) and its
     * side files into dir. Returns 0, or -1 with errno (0: out of memory)
     * and, when a side file is what could not be written, its path in
     * failed (cap bytes; left empty otherwise). */
    int (*frame)(void *w, const scene *s, const writer_frame *f, outbuf *ob, const char *dir,
                 char *failed, size_t cap);
    /* Puts the frame's files in place under p->stem. Returns 0, or -1 with
     * the reason in msg (the temporary files are removed). */
    int (*publish)(void *run, const writer_kept *k, const writer_place_info *p, char *msg,
                   size_t cap);
} writer_def;

/* What a frame's publication needs of scene s. */
void writer_keep(const scene *s, writer_kept *k);

/* "dir/file" (allocated: tr_free), or NULL. */
char *writer_join(const char *dir, const char *file);

/* A temporary file's path in dir: hidden, per process and per frame slot,
 * "dir/.raygl2pov-PID-SLOT" EXT ".tmp" (ext NULL: the prefix alone, for a
 * writer's other temporary files). Allocated (tr_free), or NULL. */
char *writer_temp_path(const char *dir, size_t slot, const char *ext);

/* Creates path (O_EXCL) registered for removal on a stop signal
 * (cleanup.h): the descriptor, with *id its registration, or -1 with
 * errno (nothing registered). writer_temp_done ends the registration. */
int writer_temp_create(const char *path, long *id);
void writer_temp_done(long id);

/* Whether files a and b hold the same bytes. */
bool writer_files_same(const char *a, const char *b);

/* Renames tmp to fin, unless fin already holds the same bytes: then tmp
 * goes and fin keeps its time, so what was rendered from it stays up to
 * date. 0, or -1 with errno. */
int writer_place(const char *tmp, const char *fin);

/* An outbuf sink writing to the descriptor *(int *)user. */
int writer_fd_flush(void *user, const char *data, size_t n);

#endif
