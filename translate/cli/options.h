/* options.h: raygl2pov's options, from one table (options.def).
 *
 * The command line and settings files (--settings FILE) go through the same
 * rows and the same setters, so an option means the same wherever it is
 * given; --help is printed from the table and a test checks the man page
 * against it. Parsing never exits or prints: errors come back as text in an
 * opt_err, and main.c decides what to do with them.
 */
#ifndef RGL_OPTIONS_H
#define RGL_OPTIONS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "driver.h"
#include "look.h"
#include "render.h"

#define OPT_MAX_JOBS DRIVER_MAX_JOBS

typedef enum opt_arg { OPT_FLAG, OPT_VALUE } opt_arg;
enum {
    OPT_ANYWHERE = 0,
    OPT_CLI_ONLY = 1,    /* not in a settings file */
    OPT_RENDER = 2,      /* raygl-render takes it too */
    OPT_RENDER_ONLY = 4, /* only raygl-render takes it */
};

/* Settings files read from settings files, at most this deep. */
#define OPT_SETTINGS_MAX_DEPTH 8

typedef struct options {
    const char *trace;
    const char *outdir;
    frame_range *ranges;
    size_t nranges;
    int jobs; /* 0 until opt_finish_parse: one per core */
    bool dump, quiet, verbose, help, version;
    bool vertex_lighting; /* --vertex-lighting (interp_gouraud.c) */
    bool preview;         /* --preview set look's quality and no_shadows */
    const writer_def *writer; /* --format (driver_writers): NULL until parsing sets it */
    const char *name_pattern; /* NULL: frame-NNNNN, or rayglFrameBegin's name */
    look_settings look;       /* look.h; its options: --no-shadows ... (options_light.c) */
    render_settings render;   /* render.h */
    bool render_tool;         /* parsing for raygl-render (set before parsing):
                                 trace is then its folder */

    /* Private: strings the options own, and the settings-file nesting. */
    struct opt_string *owned;
    size_t cap_ranges;
    int settings_depth;
    unsigned long long settings_open[OPT_SETTINGS_MAX_DEPTH][2]; /* device, inode */
} options;

/* Where a value came from: the command line (file NULL) or a settings
 * file's line. Relative paths in a settings file are taken from its folder. */
typedef struct opt_ctx {
    const char *file;
    unsigned line;
    const char *option; /* the option as written, for messages */
} opt_ctx;

typedef struct opt_err {
    char msg[512];
} opt_err;

typedef bool (*opt_setter)(options *o, const char *value, const opt_ctx *ctx, opt_err *err);

typedef struct opt_def {
    const char *name;  /* long name without "--" */
    char short_name;   /* 0 for none */
    opt_arg arg;
    const char *metavar;
    unsigned scope;
    const char *help;
    opt_setter set;
} opt_def;

#define OPT(id, name, sh, arg, meta, scope, help)                                              \
    bool opt_set_##id(options *o, const char *value, const opt_ctx *ctx, opt_err *err);
#include "options.def"

/* The table, in options.def's order. */
extern const opt_def opt_table[];
extern const size_t opt_table_count;

/* Zeroed options; opt_free releases what parsing allocated. */
void opt_init(options *o);
void opt_free(options *o);

/* Parses argv[1..argc-1]: the trace (one positional argument), options as
 * `-x V`, `-xV`, `--name V`, `--name=V`, `--` ending them. Returns true, or
 * false with a message in err (bad usage). */
bool opt_parse_args(options *o, int argc, char **argv, opt_err *err);

/* Applies the settings file at path. Errors name "FILE:LINE". */
bool opt_parse_file(options *o, const char *path, opt_err *err);

/* Checks what only the whole set can tell and fills defaults (jobs). Not
 * needed when help or version is set. */
bool opt_finish_parse(options *o, opt_err *err);

/* Whether frame i (file order) is selected by --frames. */
bool opt_frame_selected(const options *o, uint64_t i);

/* The option list for --help, from the table (raygl-render's when
 * render_tool). */
void opt_print_help(FILE *f, bool render_tool);

/* Whether the row is an option of raygl2pov (or, render_tool, raygl-render). */
bool opt_applies(const opt_def *d, bool render_tool);

/* Helpers for setters. opt_fail writes the message and returns false. A copy the options own (NULL when memory ran out,
 * with err set), a path resolved against a settings file's folder, a
 * flag's value (NULL, on/off, yes/no, true/false, 1/0). */
char *opt_strdup(options *o, const char *s, opt_err *err);
const char *opt_path(options *o, const char *value, const opt_ctx *ctx, opt_err *err);
bool opt_bool(const char *value, bool *out, const opt_ctx *ctx, opt_err *err);
bool opt_fail(opt_err *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif
