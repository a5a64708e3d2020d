/* raygl2pov.c: raygl2pov (and raygl2gltf), the command line.
 *
 *   raygl2pov TRACE -o DIR [--frames A-B[,C...]] [-j N] [--dump] [--quiet | --verbose]
 *
 * Turns argv and settings files into one options value (options.h) and
 * hands it to the frame driver (driver.h), which does the work. Usage
 * errors are said here, before anything runs.
 *
 * Exit status: 0 success, 1 bad input (damaged trace, unwritable output),
 * 2 bad usage.
 */
#include <errno.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cleanup.h"
#include "driver.h"
#include "format.h"
#include "options.h"
#include "render.h"

#ifndef RAYGL_VERSION
#define RAYGL_VERSION "unknown"
#endif

#define PROG "raygl2pov"
#define EXIT_INPUT DRIVER_EXIT_INPUT
#define EXIT_USAGE 2

/* ---- Options (options.def) ----------------------------------------------------------------- */

static void usage_error(const char *msg)
{
    fprintf(stderr, PROG ": %s\nTry '" PROG " --help' for more information.\n", msg);
    exit(EXIT_USAGE);
}

static void print_help(void)
{
    fputs("Usage: " PROG " TRACE -o DIR [OPTION]...\n"
          "Translate a RayGL trace into POV-Ray 3.7 scenes that reproduce the OpenGL\n"
          "frames: DIR/frame-00000.pov and DIR/frame-00000.ini for the first frame, and\n"
          "so on (a frame started by rayglFrameBegin(\"name.pov\", ...) is written as\n"
          "DIR/name.pov). Render a frame with:  povray DIR/frame-00000.ini\n"
          "With --format gltf (or run as raygl2gltf): one binary glTF 2.0 file per\n"
          "frame instead, DIR/frame-00000.glb; --render then renders them with Blender.\n",
          stdout);
    opt_print_help(stdout, false);
    fputs("\n"
          "Exit status: 0 on success, 1 when the trace is damaged (every intact frame\n"
          "is still written) or the output cannot be written, 2 on bad usage.\n",
          stdout);
}

/* The options that only a POV-Ray scene can use, or NULL. The others the
 * look step puts into the scene, and every writer gives them as its
 * format can (the glTF writer: --area-lights and --radiosity as extras
 * that Blender's import script honours; --include it says it leaves out). */
static const char *pov_only_option(const options *o)
{
    if (render_wanted(&o->render) && o->render.engine == RENDER_ENGINE_POVRAY)
        return "--engine povray";
    if (o->look.options.antialias)
        return "--antialias";
    if (o->preview)
        return "--preview"; /* what the user typed, not the --quality it sets */
    if (o->look.options.quality)
        return "--quality";
    if (o->look.options.no_shadows)
        return "--no-shadows";
    if (o->look.options.reflection != 0)
        return "--reflection";
    return NULL;
}

/* The checks only the parsed whole can make; exits on bad usage. */
static void check_args(options *o)
{
    opt_err err;
    const writer_def *pov = driver_writer("pov");
    const char *pov_only = o->writer != pov ? pov_only_option(o) : NULL;
    if (pov_only) {
        snprintf(err.msg, sizeof err.msg, "%s: POV-Ray only, not with --format %s", pov_only,
                 o->writer->name);
        usage_error(err.msg);
    }
    if (render_wanted(&o->render) && !o->outdir)
        usage_error("rendering needs an output folder (-o DIR)");
    /* Each format has its engine: .glb frames render with Blender. */
    render_engine engine = render_engine_named(o->writer->engine);
    if (engine != RENDER_ENGINE_BLENDER && o->render.engine == RENDER_ENGINE_BLENDER)
        usage_error("--engine blender renders glTF frames: add --format gltf");
    o->render.engine = engine;
    if (o->render.video && !o->render.render && !o->render.sshloginfile)
        o->render.render = true; /* a video needs the PNGs */
    if (render_wanted(&o->render) && render_check_tools(&o->render, PROG) != 0)
        exit(EXIT_INPUT);
    const char *bad = o->outdir && o->writer->dir_problem ? o->writer->dir_problem(o->outdir)
                                                          : NULL;
    if (bad) {
        snprintf(err.msg, sizeof err.msg, "output folder '%.200s': %s", o->outdir, bad);
        usage_error(err.msg);
    }
}

static void parse_args(int argc, char **argv, options *o)
{
    opt_err err;
    opt_init(o);
    /* raygl2gltf: the same program, glTF by default. */
    const char *base = argc > 0 && argv[0] ? strrchr(argv[0], '/') : NULL;
    base = base ? base + 1 : argc > 0 && argv[0] ? argv[0] : "";
    o->writer = driver_writer(strcmp(base, "raygl2gltf") == 0 ? "gltf" : "pov");
    if (!opt_parse_args(o, argc, argv, &err))
        usage_error(err.msg);
    if (o->help) {
        print_help();
        exit(0);
    }
    if (o->version) {
        printf(PROG " " RAYGL_VERSION " (trace format %d.%d)\n", RGL_FORMAT_MAJOR,
               RGL_FORMAT_MINOR);
        exit(0);
    }
    if (!opt_finish_parse(o, &err))
        usage_error(err.msg);
    /* --dump shows everything: the notes and calls not recorded that
     * cannot change the picture too. */
    if (o->dump && !o->quiet)
        o->verbose = true;
    check_args(o);
}

int main(int argc, char **argv)
{
    /* The user's locale for messages only: every number in the output is
     * formatted by numfmt, which never reads it. */
    setlocale(LC_ALL, "");
    options o;
    parse_args(argc, argv, &o);
    if (cleanup_start() != 0) {
        fprintf(stderr, PROG ": cannot start: %s\n", strerror(errno));
        return EXIT_INPUT;
    }
    driver_settings d = {
        .prog = PROG,
        .trace = o.trace,
        .outdir = o.outdir,
        .ranges = o.ranges,
        .nranges = o.nranges,
        .jobs = o.jobs,
        .dump = o.dump,
        .quiet = o.quiet,
        .verbose = o.verbose,
        .vertex_lighting = o.vertex_lighting,
        .pov = o.writer == driver_writer("pov"),
        /* POV-Ray's quick colours below quality 6 (-1: Quality=0) */
        .quality_note = o.writer == driver_writer("pov") && o.look.options.quality != 0 &&
                        o.look.options.quality < 6,
        .writer = o.writer,
        .name_pattern = o.name_pattern,
        .look = &o.look,
        .render = &o.render,
    };
    int status = driver_run(&d);
    opt_free(&o);
    if (fflush(stdout) != 0)
        status = EXIT_INPUT;
    return status;
}
