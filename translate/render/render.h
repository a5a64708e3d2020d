/* render.h: rendering translated frames with POV-Ray, here or elsewhere.
 *
 * A frame is a stem "DIR/NAME" relative to the folder raygl2pov ran in:
 * STEM.ini renders STEM.pov into STEM.png (POV-Ray reads the .ini's paths
 * from that folder, so every povray runs there). DIR/render.list holds the
 * stems, one per line, for the renderers that run elsewhere:
 *
 *   local     povray processes, -j at once, each writing a hidden partial
 *             PNG renamed into place when complete: an interrupted run
 *             never leaves a half-written PNG under its final name, and a
 *             PNG newer than its .pov and .ini is not rendered again; the
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

typedef struct render_settings {
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

/* Whether any render action is asked for. */
bool render_wanted(const render_settings *r);

/* Checks the tools an action needs (povray, ffmpeg, sbatch, parallel)
 * before anything is done. Returns 0, or 1 with a message printed. */
int render_check_tools(const render_settings *r, const char *prog);

/* Does what r asks for over the job's frames: writes DIR/render.list, then
 * renders locally, or over SSH, or writes and submits the Slurm script,
 * then the video. Returns the exit status: 0, or 1 when a frame failed or
 * a file could not be written (the others are still rendered). */
int render_run(const render_job *j);

/* The stems of DIR: every visible NAME.ini in it, sorted. Returns 0 or -1
 * (message printed). Free with render_free_stems. */
int render_scan_dir(const char *prog, const char *dir, char ***stems, size_t *n);
void render_free_stems(char **stems, size_t n);

/* --task N: renders entry N (from 0) of DIR/render.list. Exit status. */
int render_task(const render_settings *r, const char *prog, const char *dir, long n);

#endif
