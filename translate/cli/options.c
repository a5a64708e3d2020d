/* options.c: the option table, the command-line and settings-file parsers,
 * --help, and the setters of the options this file owns (options.h).
 */
#include "options.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "naming.h"
#include "talloc.h"

#define SETTINGS_MAX_DEPTH OPT_SETTINGS_MAX_DEPTH
#define SETTINGS_MAX_LINE 65536

const opt_def opt_table[] = {
#define OPT(id, name, sh, arg, meta, scope, help) {name, sh, arg, meta, scope, help, opt_set_##id},
#include "options.def"
};
const size_t opt_table_count = sizeof opt_table / sizeof opt_table[0];

typedef struct opt_string {
    struct opt_string *next;
    char s[];
} opt_string;

void opt_init(options *o)
{
    memset(o, 0, sizeof *o);
    o->render.task = -1;
}

bool opt_applies(const opt_def *d, bool render_tool)
{
    return render_tool ? (d->scope & (OPT_RENDER | OPT_RENDER_ONLY)) != 0
                       : (d->scope & OPT_RENDER_ONLY) == 0;
}

void opt_free(options *o)
{
    while (o->owned) {
        opt_string *n = o->owned->next;
        tr_free(o->owned);
        o->owned = n;
    }
    tr_free(o->ranges);
    look_free(&o->look);
    memset(o, 0, sizeof *o);
}

bool opt_fail(opt_err *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return false;
}

static char *own(options *o, const char *a, size_t an, const char *b, opt_err *err)
{
    size_t bn = b ? strlen(b) : 0;
    opt_string *s = tr_realloc(NULL, sizeof *s + an + bn + 1);
    if (!s) {
        opt_fail(err, "out of memory");
        return NULL;
    }
    memcpy(s->s, a, an);
    if (bn)
        memcpy(s->s + an, b, bn);
    s->s[an + bn] = '\0';
    s->next = o->owned;
    o->owned = s;
    return s->s;
}

char *opt_strdup(options *o, const char *s, opt_err *err)
{
    return own(o, s, strlen(s), NULL, err);
}

const char *opt_path(options *o, const char *value, const opt_ctx *ctx, opt_err *err)
{
    if (!ctx || !ctx->file || value[0] == '/' || !value[0])
        return opt_strdup(o, value, err);
    const char *slash = strrchr(ctx->file, '/');
    if (!slash)
        return opt_strdup(o, value, err);
    return own(o, ctx->file, (size_t)(slash - ctx->file) + 1, value, err);
}

bool opt_bool(const char *value, bool *out, const opt_ctx *ctx, opt_err *err)
{
    static const char *const yes[] = {"on", "yes", "true", "1"};
    static const char *const no[] = {"off", "no", "false", "0"};
    if (!value) {
        *out = true;
        return true;
    }
    for (size_t i = 0; i < 4; i++) {
        if (strcmp(value, yes[i]) == 0) {
            *out = true;
            return true;
        }
        if (strcmp(value, no[i]) == 0) {
            *out = false;
            return true;
        }
    }
    return opt_fail(err, "%s '%s': expected on or off", ctx->option, value);
}

/* ---- Numbers and frame lists ------------------------------------------------------------ */

bool opt_set_frames(options *o, const char *spec, const opt_ctx *ctx, opt_err *err)
{
    const char *p = spec;
    size_t n0 = o->nranges;
    while (*p) {
        frame_range r;
        switch (rgl_framesel_next(&p, &r)) {
        case RGL_FRAMESEL_OK: break;
        case RGL_FRAMESEL_NUMBER:
            return opt_fail(err, "%s '%s': expected a frame number at '%s'", ctx->option, spec, p);
        case RGL_FRAMESEL_BACKWARDS:
            return opt_fail(err, "%s '%s': range %llu-%llu runs backwards", ctx->option, spec,
                            (unsigned long long)r.first, (unsigned long long)r.last);
        case RGL_FRAMESEL_STEP:
            return opt_fail(err, "%s '%s': expected a step of 1 or more at '%s'", ctx->option,
                            spec, p);
        case RGL_FRAMESEL_UNEXPECTED:
            return opt_fail(err, "%s '%s': unexpected '%c'", ctx->option, spec, *p);
        }
        if (tr_grow((void **)&o->ranges, &o->cap_ranges, o->nranges + 1, sizeof r) != 0)
            return opt_fail(err, "out of memory");
        o->ranges[o->nranges++] = r;
    }
    if (o->nranges == n0)
        return opt_fail(err, "%s: empty list", ctx->option);
    return true;
}

bool opt_frame_selected(const options *o, uint64_t i)
{
    return frames_selected(o->ranges, o->nranges, i);
}

static bool parse_count(const char *s, uint64_t lo, uint64_t hi, uint64_t *out)
{
    const char *e;
    return rgl_parse_u64(s, &e, out) && !*e && *out >= lo && *out <= hi;
}

/* ---- The setters of this file's options ---------------------------------------------------- */

bool opt_set_output(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!*v)
        return opt_fail(err, "%s: empty output folder name", ctx->option);
    return (o->outdir = opt_path(o, v, ctx, err)) != NULL;
}

bool opt_set_jobs(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    uint64_t n;
    if (!parse_count(v, 1, OPT_MAX_JOBS, &n))
        return opt_fail(err, "%s '%s': expected a number of jobs from 1 to %d", ctx->option, v,
                        OPT_MAX_JOBS);
    o->jobs = (int)n;
    return true;
}

bool opt_set_settings(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    const char *path = opt_path(o, v, ctx, err);
    if (!path)
        return false;
    /* A file that reads itself, directly or through others: one error. */
    struct stat st;
    for (int i = 0; i < o->settings_depth && stat(path, &st) == 0; i++)
        if (o->settings_open[i][0] == (unsigned long long)st.st_dev &&
            o->settings_open[i][1] == (unsigned long long)st.st_ino)
            return opt_fail(err, "%s '%s': that settings file is already being read (a cycle)",
                            ctx->option, v);
    return opt_parse_file(o, path, err);
}

bool opt_set_format(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    const writer_def *w = driver_writer(v);
    if (w) {
        o->writer = w;
        return true;
    }
    char names[256] = "";
    size_t n = 0;
    while (driver_writers[n])
        n++;
    for (size_t i = 0; i < n; i++) {
        size_t l = strlen(names);
        snprintf(names + l, sizeof names - l, "%s%s", i == 0 ? "" : i + 1 == n ? " or " : ", ",
                 driver_writers[i]->name);
    }
    return opt_fail(err, "%s '%.100s': expected %s", ctx->option, v, names);
}

bool opt_set_name_pattern(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!*v)
        return opt_fail(err, "%s: empty pattern", ctx->option);
    for (const char *p = v; *p; p++) {
        if (*p == '/' || *p == '\\')
            return opt_fail(err, "%s '%s': a name, not a path: no '%c'", ctx->option, v, *p);
        if (*p == '{') {
            if (!name_is_placeholder(p))
                return opt_fail(err, "%s '%s': unknown placeholder at '%s' (use {index}, "
                                "{index:N}, {stream}, {number}, {name} or {trace})",
                                ctx->option, v, p);
        }
    }
    if (strchr(v, '{') == NULL)
        return opt_fail(err, "%s '%s': every frame would get the same name; use {index}",
                        ctx->option, v);
    return (o->name_pattern = opt_strdup(o, v, err)) != NULL;
}

bool opt_set_dump(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->dump, ctx, err);
}

/* --quiet and --verbose: the later one wins. */
bool opt_set_quiet(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!opt_bool(v, &o->quiet, ctx, err))
        return false;
    if (o->quiet)
        o->verbose = false;
    return true;
}

bool opt_set_verbose(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!opt_bool(v, &o->verbose, ctx, err))
        return false;
    if (o->verbose)
        o->quiet = false;
    return true;
}

bool opt_set_help(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->help, ctx, err);
}

bool opt_set_version(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->version, ctx, err);
}

/* ---- The command line ------------------------------------------------------------------------ */

static const opt_def *find_long(const char *name, size_t len)
{
    for (size_t i = 0; i < opt_table_count; i++)
        if (strlen(opt_table[i].name) == len && strncmp(opt_table[i].name, name, len) == 0)
            return &opt_table[i];
    return NULL;
}

static const opt_def *find_short(char c)
{
    for (size_t i = 0; i < opt_table_count; i++)
        if (opt_table[i].short_name == c)
            return &opt_table[i];
    return NULL;
}

bool opt_parse_args(options *o, int argc, char **argv, opt_err *err)
{
    bool only_args = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (only_args || a[0] != '-' || strcmp(a, "-") == 0) {
            if (o->trace)
                return opt_fail(err, "more than one trace given ('%s' and '%s')", o->trace, a);
            o->trace = a;
            continue;
        }
        if (strcmp(a, "--") == 0) {
            only_args = true;
            continue;
        }
        const opt_def *d;
        const char *value = NULL;
        char shown[80];
        if (a[1] == '-') {
            const char *eq = strchr(a + 2, '=');
            size_t len = eq ? (size_t)(eq - (a + 2)) : strlen(a + 2);
            d = find_long(a + 2, len);
            if (!d || !opt_applies(d, o->render_tool))
                return opt_fail(err, "unknown option '%.*s'", (int)(len + 2), a);
            if (eq) {
                if (d->arg == OPT_FLAG)
                    return opt_fail(err, "option '--%s' takes no value", d->name);
                value = eq + 1;
            }
            snprintf(shown, sizeof shown, "--%s", d->name);
        } else {
            d = find_short(a[1]);
            if (!d || !opt_applies(d, o->render_tool) || (a[2] && d->arg == OPT_FLAG))
                return opt_fail(err, "unknown option '%s'", a);
            if (a[2])
                value = a + 2;
            snprintf(shown, sizeof shown, "-%c", a[1]);
        }
        if (d->arg == OPT_VALUE && !value) {
            if (i + 1 >= argc)
                return opt_fail(err, "option '%s' needs a value", shown);
            value = argv[++i];
        }
        opt_ctx ctx = {NULL, 0, shown};
        if (!d->set(o, value, &ctx, err))
            return false;
    }
    return true;
}

/* ---- Settings files -------------------------------------------------------------------------- */

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r'))
        s[--n] = '\0';
    return s;
}

/* One line: "name = value", "name value", "--name value", "--name=value",
 * "name" (a flag). A '#' at the start or after a blank starts a comment;
 * a value in double quotes keeps its blanks and '#'. */
static bool settings_line(options *o, char *line, const opt_ctx *where, opt_err *err)
{
    bool quoted = false;
    for (char *p = line; *p; p++) {
        if (*p == '"')
            quoted = !quoted;
        else if (*p == '#' && !quoted && (p == line || p[-1] == ' ' || p[-1] == '\t')) {
            *p = '\0';
            break;
        }
    }
    if (quoted)
        return opt_fail(err, "unterminated quote (a '\"' without its closing '\"')");
    char *s = trim(line);
    if (!*s)
        return true;
    if (s[0] == '-' && s[1] == '-')
        s += 2;
    char *name = s;
    while (*s && *s != ' ' && *s != '\t' && *s != '=')
        s++;
    size_t len = (size_t)(s - name);
    char *value = trim(s);
    if (*value == '=')
        value = trim(value + 1);
    else if (value != s && value[0] == '\0')
        value = s;
    size_t vl = strlen(value);
    if (vl >= 2 && value[0] == '"' && value[vl - 1] == '"') {
        value[vl - 1] = '\0';
        value++;
    }
    const opt_def *d = find_long(name, len);
    if (!d || (d->scope & OPT_RENDER_ONLY))
        return opt_fail(err, "unknown option '%.*s'", (int)len, name);
    if (d->scope & OPT_CLI_ONLY)
        return opt_fail(err, "'%s' is a command-line option", d->name);
    bool has_value = *s != '\0';
    if (d->arg == OPT_VALUE && !has_value)
        return opt_fail(err, "'%s' needs a value", d->name);
    char shown[80];
    snprintf(shown, sizeof shown, "%s", d->name);
    opt_ctx ctx = {where->file, where->line, shown};
    return d->set(o, has_value ? value : NULL, &ctx, err);
}

bool opt_parse_file(options *o, const char *path, opt_err *err)
{
    if (o->settings_depth >= SETTINGS_MAX_DEPTH)
        return opt_fail(err, "%s: settings files nested more than %d deep", path,
                        SETTINGS_MAX_DEPTH);
    FILE *f = fopen(path, "r");
    if (!f)
        return opt_fail(err, "%s: cannot read the settings file: %s", path, strerror(errno));
    struct stat st;
    memset(&st, 0, sizeof st);
    if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(f);
        return opt_fail(err, "%s: a folder, not a settings file", path);
    }
    o->settings_open[o->settings_depth][0] = (unsigned long long)st.st_dev;
    o->settings_open[o->settings_depth][1] = (unsigned long long)st.st_ino;
    o->settings_depth++;
    char *line = NULL;
    size_t cap = 0;
    ssize_t n;
    opt_ctx where = {path, 0, NULL};
    bool ok = true;
    errno = 0;
    while (ok && (n = getline(&line, &cap, f)) >= 0) {
        where.line++;
        if (n > 0 && line[n - 1] == '\n')
            line[--n] = '\0';
        opt_err e;
        if ((size_t)n > SETTINGS_MAX_LINE)
            ok = opt_fail(err, "%s:%u: line longer than %d bytes", path, where.line,
                          SETTINGS_MAX_LINE);
        else if (strlen(line) != (size_t)n)
            ok = opt_fail(err, "%s:%u: a NUL byte in the line", path, where.line);
        else if (!settings_line(o, line, &where, &e))
            ok = opt_fail(err, "%s:%u: %s", path, where.line, e.msg);
    }
    free(line);
    if (ok && ferror(f))
        ok = opt_fail(err, "%s: cannot read the settings file: %s", path, strerror(errno));
    fclose(f);
    o->settings_depth--;
    return ok;
}

/* ---- After parsing ---------------------------------------------------------------------------- */

bool opt_finish_parse(options *o, opt_err *err)
{
    if (o->render_tool) {
        if (!o->trace)
            return opt_fail(err, "no folder given");
    } else if (!o->trace) {
        return opt_fail(err, "no trace given");
    } else if (!o->outdir && !o->dump)
        return opt_fail(err, "no output folder given (-o DIR)");
    if (o->jobs == 0) {
        long n = sysconf(_SC_NPROCESSORS_ONLN);
        o->jobs = n < 1 ? 1 : (n > OPT_MAX_JOBS ? OPT_MAX_JOBS : (int)n);
    }
    return true;
}

/* ---- --help ------------------------------------------------------------------------------------ */

#define HELP_COLUMN 23

void opt_print_help(FILE *f, bool render_tool)
{
    const char *groups[] = {
#define OPT(id, name, sh, arg, meta, scope, help)
#define OPT_GROUP(title) title,
#include "options.def"
    };
    /* Group headings sit before the first row of their group: count rows. */
    size_t starts[sizeof groups / sizeof groups[0] + 1];
    size_t ng = 0, row = 0;
#define OPT(id, name, sh, arg, meta, scope, help) row++;
#define OPT_GROUP(title) starts[ng++] = row;
#include "options.def"
    size_t g = 0;
    for (size_t i = 0; i < opt_table_count; i++) {
        while (g < ng && starts[g] == i) {
            /* A heading only when its group has a row for this program. */
            size_t end = g + 1 < ng ? starts[g + 1] : opt_table_count;
            bool any = false;
            for (size_t k = i; k < end; k++)
                any = any || opt_applies(&opt_table[k], render_tool);
            if (any)
                fprintf(f, "\n%s\n", groups[g]);
            g++;
        }
        const opt_def *d = &opt_table[i];
        if (!opt_applies(d, render_tool))
            continue;
        char head[96];
        int n;
        if (d->short_name)
            n = snprintf(head, sizeof head, "  -%c, --%s%s%s", d->short_name, d->name,
                         d->metavar ? " " : "", d->metavar ? d->metavar : "");
        else
            n = snprintf(head, sizeof head, "      --%s%s%s", d->name, d->metavar ? " " : "",
                         d->metavar ? d->metavar : "");
        fputs(head, f);
        if (n + 1 > HELP_COLUMN)
            fprintf(f, "\n%*s", HELP_COLUMN, "");
        else
            fprintf(f, "%*s", HELP_COLUMN - n, "");
        for (const char *p = d->help; *p; p++) {
            fputc(*p, f);
            if (*p == '\n')
                fprintf(f, "%*s", HELP_COLUMN, "");
        }
        fputc('\n', f);
    }
}
