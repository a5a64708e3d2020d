/* raygl_render.c: raygl-render, rendering a folder raygl2pov wrote: the
 * command line of the render driver (render.h).
 *
 *   raygl-render DIR [--frames LIST] [-j N] [--video FILE] [--slurm|--submit]
 *                [--sshloginfile F] [--engine povray|blender] [--samples N]
 *   raygl-render DIR --task N      (one entry of DIR/render.list: a cluster task)
 *
 * The options are the rendering rows of raygl2pov's table (options.def);
 * run it from the folder raygl2pov ran in, as povray itself must be.
 */
#include <errno.h>
#include <inttypes.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cleanup.h"
#include "format.h"
#include "options.h"
#include "render.h"
#include "talloc.h"

#ifndef RAYGL_VERSION
#define RAYGL_VERSION "unknown"
#endif

#define PROG "raygl-render"

/* --frames over the scenes of DIR in name order: keeps the selected stems
 * (the others are freed). Returns 0, or 1 with a message when a range
 * reaches past the last scene or selects none. */
static int select_stems(const options *o, const char *dir, char **stems, size_t *n)
{
    if (o->nranges == 0)
        return 0;
    for (size_t r = 0; r < o->nranges; r++) {
        uint64_t bad = o->ranges[r].first >= *n ? o->ranges[r].first
                       : o->ranges[r].last != UINT64_MAX && o->ranges[r].last >= *n
                           ? o->ranges[r].last
                           : UINT64_MAX;
        if (bad != UINT64_MAX) {
            fprintf(stderr, PROG ": --frames: scene %" PRIu64 " is outside %s (scenes 0-%zu)\n",
                    bad, dir, *n - 1);
            return 1;
        }
    }
    size_t kept = 0;
    for (size_t i = 0; i < *n; i++) {
        if (opt_frame_selected(o, i))
            stems[kept++] = stems[i];
        else
            tr_free(stems[i]);
    }
    *n = kept;
    return 0;
}

int main(int argc, char **argv)
{
    setlocale(LC_ALL, "");
    options o;
    opt_err err;
    opt_init(&o);
    o.render_tool = true;
    if (!opt_parse_args(&o, argc, argv, &err) ||
        (!o.help && !o.version && !opt_finish_parse(&o, &err))) {
        fprintf(stderr, PROG ": %s\nTry '" PROG " --help' for more information.\n", err.msg);
        opt_free(&o);
        return 2;
    }
    if (o.render.task >= 0 && o.nranges) {
        fprintf(stderr, PROG ": --frames with --task: a task renders its one entry\n"
                        "Try '" PROG " --help' for more information.\n");
        opt_free(&o);
        return 2;
    }
    if (o.help) {
        fputs("Usage: " PROG " DIR [OPTION]...\n"
              "Render the scenes raygl2pov wrote into DIR (every DIR/NAME.ini) with POV-Ray,\n"
              "or its glTF frames (every DIR/NAME.glb) with Blender, here, on a Slurm cluster\n"
              "or over SSH. Run it from the folder raygl2pov ran in.\n",
              stdout);
        opt_print_help(stdout, true);
        fputs("\nExit status: 0 when every frame was rendered (or submitted), 1 when a frame\n"
              "failed or a tool is missing, 2 on bad usage.\n",
              stdout);
        opt_free(&o);
        return 0;
    }
    if (o.version) {
        printf(PROG " " RAYGL_VERSION "\n");
        opt_free(&o);
        return 0;
    }
    if (cleanup_start() != 0) {
        fprintf(stderr, PROG ": cannot start: %s\n", strerror(errno));
        opt_free(&o);
        return 1;
    }
    const char *dir = o.trace;
    int rc;
    if (o.render.task >= 0) {
        rc = render_task(&o.render, PROG, dir, o.render.task);
    } else {
        /* With no action given, render here. */
        if (!render_wanted(&o.render))
            o.render.render = true;
        char **stems;
        size_t n;
        /* The folder first: it decides the engine when none is given. */
        rc = render_scan_dir(&o.render, PROG, dir, &stems, &n) != 0 ? 1 : 0;
        if (rc == 0 && render_check_tools(&o.render, PROG) != 0) {
            render_free_stems(stems, n);
            rc = 1;
        } else if (rc == 0 && select_stems(&o, dir, stems, &n) != 0) {
            render_free_stems(stems, n);
            rc = 1;
        } else if (rc == 0) {
            render_job j = {&o.render, PROG, dir, stems, n, o.jobs, o.quiet};
            rc = render_run(&j);
            render_free_stems(stems, n);
        }
    }
    opt_free(&o);
    return rc;
}
