/* render.h: rendering translated frames with POV-Ray or Blender, here or
 * elsewhere.
 *
 * A frame is a stem "DIR/NAME" relative to the folder raygl2pov ran in.
 * With POV-Ray, STEM.ini renders STEM.pov into STEM.png (POV-Ray reads the
 * .ini's paths from that folder, so every povray runs there); with Blender
 * (--engine blender), the import script raygl-blender.py renders STEM.glb
 * with Cycles into STEM.png. Only the per-frame command differs: the
 * machinery below serves both. DIR/render.list holds the stems, one per
 * line, for the renderers that run elsewhere:
 *
 *   local     povray processes, -j at once, each writing a hidden partial
 *             PNG renamed into place when complete: an interrupted run
 *             never leaves a half-written PNG under its final name, and a
 *             PNG newer than its .pov and .ini (or its .glb) is not
 *             rendered again; the
 *             partial files (PNG, log, POV-Ray's .pov-state) and the
 *             children are registered with cleanup.h, so a stop signal
 *             leaves none of them;
 *   Slurm     a job-array script (DIR/render.slurm), one frame per task,
 *             each task running `raygl-render DIR --task N`;
 *   parallel  GNU parallel over SSH (--sshloginfile), each job running
 *             `raygl-render DIR --task N` on some host.
 *
 * Nothing here calls exit; messages go to stderr, prefixed with prog.
 */
#ifndef RGL_RENDER_H
#define RGL_RENDER_H

#include <stdbool.h>
#include <stddef.h>

typedef enum render_engine {
    RENDER_ENGINE_AUTO,    /* POV-Ray, or Blender for a folder of .glb frames */
    RENDER_ENGINE_POVRAY,  /* STEM.ini */
    RENDER_ENGINE_BLENDER, /* STEM.glb */
} render_engine;

/* Cycles samples per pixel when --samples is not given: GL's lights are
 * points without shadows, lit directly, so a pixel converges in a few. */
#define RENDER_BLENDER_SAMPLES 16

typedef struct render_settings {
    render_engine engine;     /* --engine */
    const char *blender;      /* NULL: "blender" from PATH */
    int samples;              /* Cycles samples; 0: RENDER_BLENDER_SAMPLES */
    bool render;              /* render here */
    bool slurm, submit;       /* write (and submit) DIR/render.slurm */
    const char *povray;       /* NULL: "povray" from PATH */
    const char *video;        /* assemble the PNGs with ffmpeg, or NULL */
    int fps;                  /* 0: 25 */
    const char *sshloginfile; /* GNU parallel over SSH, or NULL */
    long task;                /* --task N: render entry N of render.list; -1 none */
} render_settings;

typedef struct render_job {
    const render_settings *r;
    const char *prog;  /* for messages */
    const char *dir;   /* the output folder as given */
    char **stems;      /* borrowed */
    size_t nstems;
    int jobs;          /* processes at once */
    bool quiet;
} render_job;

/* The engine called name ("povray", "blender"), AUTO for another name. */
render_engine render_engine_named(const char *name);

/* Whether any render action is asked for. */
bool render_wanted(const render_settings *r);

/* Checks the tools an action needs (povray or blender and its import
 * script, ffmpeg, sbatch, parallel) before anything is done. Returns 0,
 * or 1 with a message printed. RENDER_ENGINE_AUTO counts as POV-Ray. */
int render_check_tools(const render_settings *r, const char *prog);

/* Does what r asks for over the job's frames: writes DIR/render.list, then
 * renders locally, or over SSH, or writes and submits the Slurm script,
 * then the video. Returns the exit status: 0, or 1 when a frame failed or
 * a file could not be written (the others are still rendered). */
int render_run(const render_job *j);

/* The stems of DIR: every visible NAME.ini in it (NAME.glb with Blender),
 * sorted. With RENDER_ENGINE_AUTO, a folder with no .ini but .glb frames
 * is Blender's: r->engine is set to what was found. Returns 0 or -1
 * (message printed). Free with render_free_stems. */
int render_scan_dir(render_settings *r, const char *prog, const char *dir, char ***stems,
                    size_t *n);
void render_free_stems(char **stems, size_t n);

/* --task N: renders entry N (from 0) of DIR/render.list with r->engine
 * (AUTO: POV-Ray). Exit status. */
int render_task(const render_settings *r, const char *prog, const char *dir, long n);

#endif
