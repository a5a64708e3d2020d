/* render.c: POV-Ray or Blender over the frames, here, on Slurm or over SSH
 * (render.h). The engines differ in the scene file a frame is (STEM.ini or
 * STEM.glb), the command that renders it (start_frame) and the line of
 * its log that explains a failure (log_error); all else is shared. */
#include "render.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <dirent.h>
#include <unistd.h>

#include "cleanup.h"
#include "sibling.h"
#include "talloc.h"

/* What a render declares so that the POV-Ray writer's check of the folder
 * (povwrite.h, POV_RENDER_DECLARE: the same name) lets it through; render/
 * includes no writer (docs/design.md "Layers"), and tests/render renders
 * through it, so the two names cannot part unnoticed. */
#define RENDER_POV_DECLARE "raygl_render"

extern char **environ;

#define RENDER_MAX_JOBS 256
#define RENDER_PATH_MAX 4096

/* ---- Small helpers ------------------------------------------------------------------- */

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static char *xprintf(char *unused, const char *fmt, ...)
{
    (void)unused;
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0)
        return NULL;
    char *s = tr_realloc(NULL, (size_t)n + 1);
    if (!s)
        return NULL;
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}
#define aprintf(...) xprintf(NULL, __VA_ARGS__)

/* Atomic: the stop (cleanup.h) reads it on its own thread. */
static atomic_bool progress_shown;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void say(const char *prog, const char *fmt, ...)
{
    if (atomic_exchange(&progress_shown, false))
        fputs("\r\033[K", stderr);
    va_list ap;
    fprintf(stderr, "%s: ", prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* name found in PATH (or name itself when it holds a '/'), or NULL. */
static char *find_program(const char *name)
{
    if (strchr(name, '/'))
        return access(name, X_OK) == 0 ? aprintf("%s", name) : NULL;
    const char *path = getenv("PATH");
    if (!path)
        path = "/usr/bin:/bin";
    while (*path) {
        size_t n = strcspn(path, ":");
        char *cand = aprintf("%.*s/%s", (int)n, n ? path : ".", name);
        if (cand && access(cand, X_OK) == 0) {
            struct stat st;
            if (stat(cand, &st) == 0 && S_ISREG(st.st_mode))
                return cand;
        }
        tr_free(cand);
        path += n + (path[n] == ':');
    }
    return NULL;
}

static bool is_blender(const render_settings *r) { return r->engine == RENDER_ENGINE_BLENDER; }

/* The file of a frame an engine renders: STEM.ini or STEM.glb. */
static const char *frame_ext(const render_settings *r) { return is_blender(r) ? ".glb" : ".ini"; }

static const char *engine_program(const render_settings *r)
{
    if (is_blender(r))
        return r->blender ? r->blender : "blender";
    return r->povray ? r->povray : "povray";
}

#define BLENDER_SCRIPT "raygl-blender.py"

/* The installed import script (sibling.h), or NULL. */
static char *blender_script(void)
{
    char buf[PATH_MAX];
    return sibling_data(BLENDER_SCRIPT, buf, sizeof buf) ? aprintf("%s", buf) : NULL;
}

/* 'text' for sh, with ' as '\''. */
static char *sh_quote(const char *s)
{
    size_t n = 2;
    for (const char *p = s; *p; p++)
        n += *p == '\'' ? 4 : 1;
    char *q = tr_realloc(NULL, n + 1), *o = q;
    if (!q)
        return NULL;
    *o++ = '\'';
    for (const char *p = s; *p; p++) {
        if (*p == '\'') {
            memcpy(o, "'\\''", 4);
            o += 4;
        } else {
            *o++ = *p;
        }
    }
    *o++ = '\'';
    *o = '\0';
    return q;
}

/* DIR/.NAME.partial.SUFFIX for stem DIR/NAME: what a render writes before
 * its output is complete (png, log; pov-state: POV-Ray's render state,
 * written all through the render and kept when stopped). */
static char *partial_file(const char *stem, const char *suffix)
{
    const char *slash = strrchr(stem, '/');
    if (!slash)
        return aprintf(".%s.partial.%s", stem, suffix);
    return aprintf("%.*s/.%s.partial.%s", (int)(slash - stem), stem, slash + 1, suffix);
}

static bool newer(const struct stat *a, const struct stat *b)
{
    return a->st_mtim.tv_sec > b->st_mtim.tv_sec ||
           (a->st_mtim.tv_sec == b->st_mtim.tv_sec && a->st_mtim.tv_nsec > b->st_mtim.tv_nsec);
}

/* The newest time of the copied --include files of a folder (look.c names
 * them include-*): a changed include makes every frame out of date. */
static struct stat include_time;

static void scan_includes(const char *dir)
{
    memset(&include_time, 0, sizeof include_time);
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (strncmp(e->d_name, "include-", 8) != 0)
            continue;
        char *p = aprintf("%s/%s", dir, e->d_name);
        struct stat st;
        if (p && stat(p, &st) == 0 && newer(&st, &include_time))
            include_time = st;
        tr_free(p);
    }
    closedir(d);
}

/* STEM.png exists and is newer than STEM.pov, STEM.ini and the includes
 * (with Blender: than STEM.glb). */
static bool up_to_date(const render_settings *r, const char *stem)
{
    char *png = aprintf("%s.png", stem), *pov = aprintf("%s.pov", stem),
         *ini = aprintf("%s%s", stem, frame_ext(r));
    struct stat sp, sv, si;
    bool ok = png && pov && ini && stat(png, &sp) == 0 && sp.st_size > 0 &&
              stat(ini, &si) == 0 && newer(&sp, &si) &&
              (is_blender(r) || (stat(pov, &sv) == 0 && newer(&sp, &sv) &&
                                 !newer(&include_time, &sp)));
    tr_free(png);
    tr_free(pov);
    tr_free(ini);
    return ok;
}

static int cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > RENDER_MAX_JOBS ? RENDER_MAX_JOBS : (int)n;
}

/* The sibling raygl-render of this executable: the command remote tasks run. */
static char *render_command(void)
{
    char buf[PATH_MAX];
    return sibling_path("raygl-render", buf, sizeof buf) ? aprintf("%s", buf) : NULL;
}

bool render_wanted(const render_settings *r)
{
    return r->render || r->slurm || r->submit || r->sshloginfile || r->video;
}

int render_check_tools(const render_settings *r, const char *prog)
{
    const char *pov = engine_program(r);
    char *p;
    if ((r->render || r->video || r->task >= 0) && is_blender(r)) {
        if (!(p = find_program(pov))) {
            say(prog, "%s: Blender not found%s (install Blender 3.4 or later with numpy, e.g. "
                      "apt-get install blender python3-numpy, or give --blender PATH)", pov,
                strchr(pov, '/') ? "" : " in PATH");
            return 1;
        }
        tr_free(p);
        if (!(p = blender_script())) {
            say(prog, BLENDER_SCRIPT ": Blender's import script is not installed beside this "
                      "program (share/raygl/" BLENDER_SCRIPT ")");
            return 1;
        }
        tr_free(p);
    } else if (r->render || r->video || r->task >= 0) {
        if (!(p = find_program(pov))) {
            say(prog, "%s: POV-Ray not found%s (install POV-Ray 3.7, e.g. apt-get install povray, "
                      "or give --povray PATH)", pov, strchr(pov, '/') ? "" : " in PATH");
            return 1;
        }
        tr_free(p);
    }
    if (r->video) {
        if (!(p = find_program("ffmpeg"))) {
            say(prog, "--video needs ffmpeg, which is not installed (apt-get install ffmpeg)");
            return 1;
        }
        tr_free(p);
        /* Its folder now, not after hours of rendering. */
        const char *slash = strrchr(r->video, '/');
        char *dir = slash ? aprintf("%.*s", (int)(slash - r->video + (slash == r->video)),
                                    r->video)
                          : aprintf(".");
        struct stat st;
        const char *why = !dir                          ? strerror(ENOMEM)
                          : stat(dir, &st) != 0         ? strerror(errno)
                          : !S_ISDIR(st.st_mode)        ? "not a folder"
                          : access(dir, W_OK | X_OK) != 0 ? strerror(errno)
                                                        : NULL;
        if (why) {
            say(prog, "--video %s: cannot write into '%s': %s", r->video, dir ? dir : "",
                why);
            tr_free(dir);
            return 1;
        }
        tr_free(dir);
    }
    if (r->submit) {
        if (!(p = find_program("sbatch"))) {
            say(prog, "--submit needs sbatch (Slurm), which is not in PATH");
            return 1;
        }
        tr_free(p);
    }
    if (r->sshloginfile) {
        if (!(p = find_program("parallel"))) {
            say(prog, "--sshloginfile needs GNU parallel, which is not installed "
                      "(apt-get install parallel)");
            return 1;
        }
        tr_free(p);
        if (access(r->sshloginfile, R_OK) != 0) {
            say(prog, "%s: cannot read the SSH login file: %s", r->sshloginfile, strerror(errno));
            return 1;
        }
    }
    if (r->slurm || r->submit || r->sshloginfile) {
        if (!(p = render_command())) {
            say(prog, "raygl-render is not installed next to this program: the tasks need it");
            return 1;
        }
        tr_free(p);
    }
    return 0;
}

/* ---- The list --------------------------------------------------------------------------- */

static char *list_path(const char *dir)
{
    size_t n = strlen(dir);
    return aprintf("%s%srender.list", dir, n && dir[n - 1] == '/' ? "" : "/");
}

static int write_list(const render_job *j)
{
    char *path = list_path(j->dir), *tmp = path ? aprintf("%s.tmp", path) : NULL;
    int rc = -1;
    cleanup_lock();
    long id = tmp ? cleanup_file(tmp) : -1;
    FILE *f = id >= 0 ? fopen(tmp, "w") : NULL;
    cleanup_unlock();
    if (f) {
        for (size_t i = 0; i < j->nstems; i++)
            fprintf(f, "%s\n", j->stems[i]);
        rc = ferror(f) ? -1 : 0;
        if (fclose(f) != 0)
            rc = -1;
        if (rc == 0)
            rc = rename(tmp, path);
        if (rc != 0)
            unlink(tmp);
    }
    cleanup_drop(id);
    if (rc != 0)
        say(j->prog, "%s: cannot write: %s", path ? path : j->dir, strerror(errno));
    tr_free(path);
    tr_free(tmp);
    return rc;
}

/* Entry n of DIR/render.list, or NULL with a message. */
static char *list_entry(const char *prog, const char *dir, long n)
{
    char *path = list_path(dir);
    FILE *f = path ? fopen(path, "r") : NULL;
    if (!f) {
        say(prog, "%s: cannot read: %s", path ? path : dir, strerror(errno));
        tr_free(path);
        return NULL;
    }
    char *line = NULL, *out = NULL;
    size_t cap = 0;
    ssize_t len;
    long i = 0;
    while ((len = getline(&line, &cap, f)) >= 0) {
        if (len > 0 && line[len - 1] == '\n')
            line[--len] = '\0';
        if (i++ == n) {
            out = aprintf("%s", line);
            break;
        }
    }
    if (!out)
        say(prog, "%s: no entry %ld (the list has %ld)", path, n, i);
    free(line);
    fclose(f);
    tr_free(path);
    return out;
}

/* ---- One frame ---------------------------------------------------------------------------- */

typedef struct running {
    pid_t pid;
    size_t index;
    int retried; /* started again after a transient failure */
    /* The partial PNG, log, POV-Ray's state file, and the import script's
     * own temporary image (Blender; its --temp). */
    char *tmp_png, *tmp_log, *tmp_state, *tmp_script;
    long ids[5]; /* cleanup entries: the child, then the four files */
} running;

#define RUN_CHILD 0

static void forget(running *r)
{
    for (int i = 0; i < 5; i++) {
        cleanup_drop(r->ids[i]);
        r->ids[i] = -1;
    }
}

/* The child is reaped: a stop must not signal its pid again. */
static void reaped(running *r)
{
    cleanup_drop(r->ids[RUN_CHILD]);
    r->ids[RUN_CHILD] = -1;
    r->pid = 0;
}

/* Drops the names of r's partial files (not the files). */
static void free_names(running *r)
{
    tr_free(r->tmp_png);
    tr_free(r->tmp_log);
    tr_free(r->tmp_state);
    tr_free(r->tmp_script);
    r->tmp_png = r->tmp_log = r->tmp_state = r->tmp_script = NULL;
}

/* POV-Ray gives up when its worker threads are slow to start, which
 * happens on a loaded machine and says nothing about the scene: such a
 * frame is worth one more try. */
static bool transient_failure(int st, const char *log)
{
    if (!(WIFEXITED(st) && WEXITSTATUS(st) != 0) || !log)
        return false;
    FILE *f = fopen(log, "r");
    if (!f)
        return false;
    char line[512];
    bool found = false;
    while (!found && fgets(line, sizeof line, f))
        found = strstr(line, "Timed out waiting for worker thread startup") != NULL;
    fclose(f);
    return found;
}

/* Starts the engine's program for stem in r, dropping the names of an
 * earlier attempt; 0, or -1 (message printed) with r emptied. The partial
 * files and the child are registered for a stop (cleanup.h) before they
 * exist. */
static int start_frame(const char *prog, const render_settings *rs, const char *stem, int threads,
                       running *r)
{
    const char *program = engine_program(rs);
    cleanup_lock();
    forget(r);
    free_names(r);
    r->tmp_png = partial_file(stem, "png");
    r->tmp_log = partial_file(stem, "log");
    r->tmp_state = partial_file(stem, "pov-state");
    /* The import script writes its image under this name and renames it
     * to --output: named here, so a stop during the write removes it. */
    r->tmp_script = partial_file(stem, "tmp.png");
    if (r->tmp_png && r->tmp_log && r->tmp_state && r->tmp_script) {
        r->ids[1] = cleanup_file(r->tmp_png);
        r->ids[2] = cleanup_file(r->tmp_log);
        r->ids[3] = cleanup_file(r->tmp_state);
        r->ids[4] = cleanup_file(r->tmp_script);
    }
    char *ini = aprintf("%s%s", stem, frame_ext(rs)),
         *oarg = r->tmp_png ? aprintf(is_blender(rs) ? "%s" : "+O%s", r->tmp_png) : NULL,
         *wt = aprintf(is_blender(rs) ? "%d" : "+WT%d", threads),
         *script = is_blender(rs) ? blender_script() : aprintf("-");
    char samples[24];
    snprintf(samples, sizeof samples, "%d", rs->samples > 0 ? rs->samples : RENDER_BLENDER_SAMPLES);
    /* The stem's folder as a library path too: the .ini's own Library_Path
     * is relative to the folder raygl2pov ran in, this one to ours. */
    const char *slash = strrchr(stem, '/');
    char *larg = slash ? aprintf("+L%.*s", (int)(slash - stem), stem) : aprintf("+L.");
    int rc = -1;
    if (ini && oarg && wt && larg && script && r->tmp_state && r->ids[1] >= 0 &&
        r->ids[2] >= 0 && r->ids[3] >= 0 && r->ids[4] >= 0) {
        posix_spawn_file_actions_t fa;
        posix_spawn_file_actions_init(&fa);
        posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
        posix_spawn_file_actions_addopen(&fa, 1, r->tmp_log, O_WRONLY | O_CREAT | O_TRUNC, 0666);
        posix_spawn_file_actions_adddup2(&fa, 1, 2);
        /* povray starts with the signals unheld and at their defaults. */
        posix_spawnattr_t at;
        posix_spawnattr_init(&at);
        cleanup_spawnattr(&at);
        /* Its own library path and output name work from any folder: the
         * .ini's check of the folder (RENDER_POV_DECLARE) is skipped. */
        char *pargv[] = {(char *)program, ini, larg, wt, oarg, "-D",
                         "Declare=" RENDER_POV_DECLARE "=1", NULL};
        /* Blender's own options first, the script's after "--". */
        char *bargv[] = {(char *)program, "-b", "-noaudio", "--factory-startup",
                         "--python-exit-code", "1", "-P", script, "--", "--input", ini,
                         "--output", oarg, "--temp", r->tmp_script, "--samples", samples,
                         "--threads", wt, NULL};
        char **argv = is_blender(rs) ? bargv : pargv;
        int e = posix_spawnp(&r->pid, program, &fa, &at, argv, environ);
        posix_spawnattr_destroy(&at);
        posix_spawn_file_actions_destroy(&fa);
        if (e == 0) {
            rc = 0;
            r->ids[RUN_CHILD] = cleanup_child(r->pid);
        } else {
            say(prog, "%s: cannot run %s: %s", ini, program, strerror(e));
        }
    } else if (ini && oarg && wt && larg && !script) {
        say(prog, "%s: " BLENDER_SCRIPT " is not installed beside this program", ini);
    } else if (ini && oarg && wt && larg) {
        say(prog, "out of memory");
    }
    tr_free(script);
    tr_free(ini);
    tr_free(oarg);
    tr_free(wt);
    tr_free(larg);
    if (rc != 0) {
        forget(r);
        free_names(r);
        r->pid = 0;
    }
    cleanup_unlock();
    return rc;
}

/* The import script's own one-line error ("raygl-blender: FILE: why"),
 * without the prefix, when the log holds one. */
static bool script_error(const char *log, char *out, size_t cap)
{
    FILE *f = fopen(log, "r");
    if (!f)
        return false;
    char line[1024];
    bool found = false;
    while (!found && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        if (strncmp(line, "raygl-blender: ", 15) == 0) {
            /* The frame is named by the caller's message already. */
            const char *why = strstr(line + 15, ": ");
            snprintf(out, cap, "%s", why ? why + 2 : line + 15);
            found = true;
        }
    }
    fclose(f);
    return found;
}

/* The import script's notes (what the render cannot show: "raygl-blender:
 * FILE: note: what"), said with the frame. */
static void relay_notes(const char *prog, const char *stem, const char *log)
{
    FILE *f = fopen(log, "r");
    if (!f)
        return;
    char line[1024];
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        const char *note =
            strncmp(line, "raygl-blender: ", 15) == 0 ? strstr(line, ": note: ") : NULL;
        if (note)
            say(prog, "%s.glb: %s", stem, note + 2);
    }
    fclose(f);
}

/* The engine's own error: the import script's line; else the first line
 * of the log that says "Error" with its continuation lines (they start
 * with a blank), else the log's last non-empty line. */
static void log_error(const render_settings *rs, const char *log, char *out, size_t cap)
{
    snprintf(out, cap, "no message from %s", is_blender(rs) ? "Blender" : "POV-Ray");
    if (is_blender(rs) && script_error(log, out, cap))
        return;
    FILE *f = fopen(log, "r");
    if (!f)
        return;
    char line[1024];
    int state = 0; /* 0 looking, 1 in the error, 2 done */
    while (state < 2 && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        if (state == 1) {
            if (line[0] == ' ' && line[1] != ' ') {
                size_t n = strlen(out);
                snprintf(out + n, cap - n, "%s", line);
                continue;
            }
            state = 2;
        } else if (line[0] && (strstr(line, "Error") || strstr(line, "error"))) {
            snprintf(out, cap, "%s", line);
            state = 1;
        } else if (line[0]) {
            snprintf(out, cap, "%s", line);
        }
    }
    fclose(f);
}

/* After the engine ended with status st: the PNG into place (and, unless
 * quiet, Blender's notes said), or the failure reported with the log kept
 * as STEM.log. Returns true on success. */
static bool finish_frame(const char *prog, const render_settings *rs, const char *stem, int st,
                         bool quiet, running *r)
{
    const char *ext = frame_ext(rs), *tool = is_blender(rs) ? "blender" : "povray";
    char *png = aprintf("%s.png", stem), *log = aprintf("%s.log", stem);
    struct stat sb;
    bool ok = WIFEXITED(st) && WEXITSTATUS(st) == 0 && r->tmp_png && stat(r->tmp_png, &sb) == 0 &&
              sb.st_size > 0;
    if (ok && png && rename(r->tmp_png, png) != 0) {
        say(prog, "%s: cannot write: %s", png, strerror(errno));
        ok = false;
    } else if (ok && log) {
        unlink(log); /* an earlier failure's */
        if (is_blender(rs) && !quiet)
            relay_notes(prog, stem, r->tmp_log);
    } else if (!ok) {
        char msg[1024], why[64];
        log_error(rs, r->tmp_log, msg, sizeof msg);
        if (WIFEXITED(st))
            snprintf(why, sizeof why, "exit status %d", WEXITSTATUS(st));
        else if (WIFSIGNALED(st))
            snprintf(why, sizeof why, "signal %d", WTERMSIG(st));
        else
            snprintf(why, sizeof why, "no image");
        if (WIFEXITED(st) && WEXITSTATUS(st) == 0)
            snprintf(why, sizeof why, "no image written");
        if (WIFSIGNALED(st) && (WTERMSIG(st) == SIGINT || WTERMSIG(st) == SIGTERM ||
                                WTERMSIG(st) == SIGHUP)) {
            /* Stopped, as by Ctrl-C to the group: no failure log to keep. */
            say(prog, "%s%s: %s stopped (signal %d)", stem, ext, tool, WTERMSIG(st));
            goto clean;
        }
        bool kept = log && rename(r->tmp_log, log) == 0;
        say(prog, "%s%s: %s failed (%s): %s%s%s%s", stem, ext, tool, why, msg,
            kept ? " (log: " : "", kept ? log : "", kept ? ")" : "");
    }
clean:
    if (r->tmp_png)
        unlink(r->tmp_png);
    if (r->tmp_log)
        unlink(r->tmp_log);
    if (r->tmp_state)
        unlink(r->tmp_state);
    if (r->tmp_script)
        unlink(r->tmp_script);
    forget(r);
    tr_free(png);
    tr_free(log);
    free_names(r);
    return ok;
}

/* ---- Local rendering -------------------------------------------------------------------------- */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void hms(double s, char *out, size_t cap)
{
    long t = (long)(s + 0.5);
    snprintf(out, cap, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
}

/* "12.3": one decimal, with a point whatever the locale, and no float
 * conversion (tests/translate/test_sources.sh keeps those out). */
static void tenths(double v, char *out, size_t cap)
{
    unsigned long t = v > 0 && v < 1e15 ? (unsigned long)(v * 10 + 0.5) : 0;
    snprintf(out, cap, "%lu.%lu", t / 10, t % 10);
}

static void progress(const render_job *j, size_t done, size_t total, size_t rendered, double t0)
{
    if (j->quiet || !isatty(STDERR_FILENO))
        return;
    enum { BAR = 24 };
    char bar[BAR + 1], left[32] = "--:--:--", rate[32] = "-";
    size_t fill = total ? done * BAR / total : BAR;
    for (size_t i = 0; i < BAR; i++)
        bar[i] = i < fill ? '#' : '.';
    bar[BAR] = '\0';
    double dt = now() - t0;
    if (rendered > 0 && dt > 0) {
        double fpm = rendered * 60.0 / dt;
        tenths(fpm, rate, sizeof rate);
        hms((double)(total - done) * 60.0 / fpm, left, sizeof left);
    }
    fprintf(stderr, "\r\033[K%s: [%s] %zu/%zu frames, %s frames/min, %s left", j->prog, bar, done,
            total, rate, left);
    atomic_store(&progress_shown, true);
}

/* What a local render has done so far, for the stop's line. */
static struct {
    const char *prog;
    atomic_size_t total, rendered, skipped, active;
} tally;

static void tally_set(size_t rendered, size_t skipped, int active)
{
    atomic_store(&tally.rendered, rendered);
    atomic_store(&tally.skipped, skipped);
    atomic_store(&tally.active, (size_t)active);
}

static const char *stop_name(int sig)
{
    switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    }
    return "a signal";
}

/* Said by the stop (cleanup_on_stop) once the renders under way are
 * stopped and their partial files removed: what is done, what is not,
 * and that the same command renders the rest. On the stop's thread, with
 * the registry's lock held: the tally is as the stop found it. */
static void say_stopped(int sig)
{
    size_t total = atomic_load(&tally.total), now = atomic_load(&tally.rendered),
           before = atomic_load(&tally.skipped), stopped = atomic_load(&tally.active);
    size_t have = now + before;
    fprintf(stderr,
            "%s%s: stopped (%s): %zu of %zu frame%s rendered (%zu in this run, %zu before), "
            "%zu render%s stopped and removed; the same command again renders the other %zu\n",
            atomic_exchange(&progress_shown, false) ? "\r\033[K" : "", tally.prog,
            stop_name(sig), have, total, total == 1 ? "" : "s", now, before, stopped,
            stopped == 1 ? "" : "s", total > have ? total - have : 0);
    fflush(stderr);
}

/* "6 frames rendered in 0:00:02 (..., 2 at once), 0 already rendered, 0
 * failed": printed unless quiet, and always when a frame failed. */
static void summary(const render_job *j, size_t rendered, double dt, const char *how,
                    size_t skipped, size_t failed, size_t notrun)
{
    if (j->quiet && !failed && !notrun)
        return;
    char t[32], rate[32];
    hms(dt, t, sizeof t);
    tenths(dt > 0 ? rendered * 60.0 / dt : 0.0, rate, sizeof rate);
    fprintf(stderr,
            "%s: %zu frame%s rendered in %s (%s frames/min, %s), %zu already rendered, %zu "
            "failed%s\n",
            j->prog, rendered, rendered == 1 ? "" : "s", t, rate, how, skipped, failed + notrun,
            notrun ? " or not started" : "");
}

static int render_local(const render_job *j, size_t *nfailed)
{
    int jobs = j->jobs > 0 ? j->jobs : cores();
    if (jobs > RENDER_MAX_JOBS)
        jobs = RENDER_MAX_JOBS;
    /* POV-Ray and Cycles thread themselves: the cores are shared among the
     * processes. */
    int threads = cores() / jobs > 0 ? cores() / jobs : 1;
    running *run = tr_realloc(NULL, (size_t)jobs * sizeof *run);
    if (!run) {
        say(j->prog, "out of memory");
        return 1;
    }
    memset(run, 0, (size_t)jobs * sizeof *run);
    for (int s = 0; s < jobs; s++)
        for (int k = 0; k < 5; k++)
            run[s].ids[k] = -1;
    scan_includes(j->dir);

    size_t skipped = 0, rendered = 0, failed = 0, done = 0, next = 0;
    bool stop = false;
    double t0 = now();
    int active = 0;
    tally.prog = j->prog;
    atomic_store(&tally.total, j->nstems);
    tally_set(0, 0, 0);
    cleanup_on_stop(say_stopped);
    while (next < j->nstems || active > 0) {
        /* The tally changes with the lock held, with what it counts: a
         * stop finds it as things were when the stop came. */
        cleanup_lock();
        while (!stop && active < jobs && next < j->nstems) {
            size_t i = next++;
            if (up_to_date(j->r, j->stems[i])) {
                skipped++;
                done++;
                continue;
            }
            int slot = 0;
            while (run[slot].pid > 0)
                slot++;
            run[slot].index = i;
            run[slot].retried = 0;
            if (start_frame(j->prog, j->r, j->stems[i], threads, &run[slot]) != 0) {
                failed++;
                done++;
                stop = true; /* the engine cannot be started: the next would fail alike */
                continue;
            }
            active++;
        }
        tally_set(rendered, skipped, active);
        cleanup_unlock();
        if (stop && active == 0)
            break;
        if (active == 0)
            continue;
        progress(j, done, j->nstems, rendered, t0);
        int st;
        pid_t pid = waitpid(-1, &st, 0);
        if (pid < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        cleanup_lock();
        for (int s = 0; s < jobs; s++) {
            if (run[s].pid != pid)
                continue;
            reaped(&run[s]);
            /* Ctrl-C to the group ends the engines as it reaches us: the
             * stop, if one came, counts this render as stopped, not
             * failed, and none starts after it. */
            cleanup_check();
            if (!run[s].retried && !is_blender(j->r) && transient_failure(st, run[s].tmp_log)) {
                run[s].retried = 1;
                if (start_frame(j->prog, j->r, j->stems[run[s].index], threads, &run[s]) == 0)
                    break; /* still active */
                active--;
                done++;
                failed++;
                break;
            }
            if (finish_frame(j->prog, j->r, j->stems[run[s].index], st, j->quiet, &run[s]))
                rendered++;
            else
                failed++;
            run[s].pid = 0;
            active--;
            done++;
        }
        tally_set(rendered, skipped, active);
        cleanup_unlock();
    }
    cleanup_on_stop(NULL);
    progress(j, done, j->nstems, rendered, t0);
    if (atomic_exchange(&progress_shown, false))
        fputs("\r\033[K", stderr);
    tr_free(run);
    size_t notrun = j->nstems - done;
    char how[32];
    snprintf(how, sizeof how, "%d at once", jobs);
    summary(j, rendered, now() - t0, how, skipped, failed, notrun);
    *nfailed = failed + notrun;
    return failed + notrun ? 1 : 0;
}

/* ---- Video ------------------------------------------------------------------------------------ */

/* Runs argv and waits; a stop signal stops it too (cleanup.h). */
static int run_wait(char *const argv[], const char *prog)
{
    pid_t pid;
    posix_spawnattr_t at;
    posix_spawnattr_init(&at);
    cleanup_spawnattr(&at);
    cleanup_lock();
    int e = posix_spawnp(&pid, argv[0], NULL, &at, argv, environ);
    long id = e == 0 ? cleanup_child(pid) : -1;
    cleanup_unlock();
    posix_spawnattr_destroy(&at);
    if (e != 0) {
        say(prog, "cannot run %s: %s", argv[0], strerror(e));
        return -1;
    }
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR) {
            cleanup_drop(id);
            return -1;
        }
    cleanup_drop(id);
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
}

/* The PNGs in list order, as numbered links in a hidden folder, for
 * ffmpeg's image2 reader; the video is written under a partial name and
 * renamed into place. */
static int make_video(const render_job *j)
{
    size_t dl = strlen(j->dir);
    const char *sep = dl && j->dir[dl - 1] == '/' ? "" : "/";
    char *seq = aprintf("%s%s.video-%ld", j->dir, sep, (long)getpid());
    const char *out = j->r->video;
    const char *slash = strrchr(out, '/');
    char *tmp = slash ? aprintf("%.*s/.%s.partial%s", (int)(slash - out), out, slash + 1,
                                strrchr(slash, '.') ? strrchr(slash, '.') : "")
                      : aprintf(".%s.partial%s", out, strrchr(out, '.') ? strrchr(out, '.') : "");
    /* The folder, its links and the partial video go on a stop. */
    cleanup_lock();
    long seq_id = seq ? cleanup_dir(seq) : -1, tmp_id = tmp ? cleanup_file(tmp) : -1;
    if (seq_id < 0 || tmp_id < 0 || mkdir(seq, 0777) != 0) {
        cleanup_drop(seq_id);
        cleanup_drop(tmp_id);
        cleanup_unlock();
        say(j->prog, "%s: cannot create: %s", seq ? seq : j->dir, strerror(errno));
        tr_free(seq);
        tr_free(tmp);
        return 1;
    }
    cleanup_unlock();
    long *link_ids = tr_realloc(NULL, (j->nstems ? j->nstems : 1) * sizeof *link_ids);
    int rc = link_ids ? 0 : 1;
    size_t n = 0;
    for (size_t i = 0; i < j->nstems && rc == 0; i++) {
        char *png = aprintf("%s.png", j->stems[i]);
        char *abs = png ? realpath(png, NULL) : NULL;
        char *link = aprintf("%s/%06zu.png", seq, n);
        if (abs && link) {
            cleanup_lock();
            link_ids[n] = cleanup_file(link);
            if (link_ids[n] >= 0 && symlink(abs, link) == 0)
                n++;
            else
                cleanup_drop(link_ids[n]);
            cleanup_unlock();
        }
        tr_free(png);
        free(abs);
        tr_free(link);
    }
    char *pattern = aprintf("%s/%%06d.png", seq);
    char fps[16];
    snprintf(fps, sizeof fps, "%d", j->r->fps > 0 ? j->r->fps : 25);
    if (rc != 0) {
        say(j->prog, "out of memory");
    } else if (n == 0) {
        say(j->prog, "--video: no rendered frames to assemble");
        rc = 1;
    } else if (tmp && pattern) {
        char *argv[] = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate", fps,
                        "-i", pattern, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt",
                        "yuv420p", tmp, NULL};
        int st = run_wait(argv, j->prog);
        if (st != 0) {
            say(j->prog, "%s: ffmpeg failed (exit status %d); the PNGs are kept", out, st);
            unlink(tmp);
            rc = 1;
        } else if (rename(tmp, out) != 0) {
            say(j->prog, "%s: cannot write: %s", out, strerror(errno));
            unlink(tmp);
            rc = 1;
        } else if (!j->quiet) {
            fprintf(stderr, "%s: %s: %zu frame%s at %s frames/s\n", j->prog, out, n,
                    n == 1 ? "" : "s", fps);
        }
    }
    for (size_t i = 0; i < n; i++) {
        char *link = aprintf("%s/%06zu.png", seq, i);
        if (link)
            unlink(link);
        tr_free(link);
        cleanup_drop(link_ids[i]);
    }
    rmdir(seq);
    cleanup_drop(seq_id);
    cleanup_drop(tmp_id);
    tr_free(link_ids);
    tr_free(seq);
    tr_free(tmp);
    tr_free(pattern);
    return rc;
}

/* ---- Slurm and GNU parallel -------------------------------------------------------------------- */

/* The options a task needs to render as this run does, for sh: the
 * engine, its program, the samples (each starting with a space). */
static char *task_options(const render_settings *r)
{
    const char *prog = is_blender(r) ? r->blender : r->povray;
    char *q = prog ? sh_quote(prog) : NULL;
    char *out = NULL;
    if (prog && !q)
        return NULL;
    if (is_blender(r))
        out = aprintf(" --engine blender --samples %d%s%s",
                      r->samples > 0 ? r->samples : RENDER_BLENDER_SAMPLES, q ? " --blender " : "",
                      q ? q : "");
    else
        out = aprintf("%s%s", q ? " --povray " : "", q ? q : "");
    tr_free(q);
    return out;
}

static char *cwd_now(void)
{
    char *c = getcwd(NULL, 0);
    char *r = c ? aprintf("%s", c) : NULL;
    free(c);
    return r;
}

/* Slurm's default MaxArraySize is 1001: larger lists go in several arrays,
 * each task adding RAYGL_OFFSET to its index. */
#define SLURM_ARRAY_CHUNK 1000

static int write_slurm(const render_job *j, char **script_out)
{
    size_t dl = strlen(j->dir);
    const char *sep = dl && j->dir[dl - 1] == '/' ? "" : "/";
    char *path = aprintf("%s%srender.slurm", j->dir, sep);
    char *tmp = path ? aprintf("%s.tmp", path) : NULL;
    char *cwd = cwd_now(), *cmd = render_command();
    char *qcwd = cwd ? sh_quote(cwd) : NULL, *qcmd = cmd ? sh_quote(cmd) : NULL,
         *qdir = sh_quote(j->dir);
    char *absdir = cwd && j->dir[0] != '/' ? aprintf("%s/%s", cwd, j->dir) : aprintf("%s", j->dir);
    /* Slurm's %A (job) and %a (task), spelt out of a format string. */
    static const char ids[] = {'%', 'A', '_', '%', 'a', '\0'};
    char *qlog = absdir ? aprintf("%s%sslurm-%s.log", absdir, sep, ids) : NULL;
    char *topt = task_options(j->r);
    int rc = -1;
    cleanup_lock();
    long id = tmp ? cleanup_file(tmp) : -1;
    FILE *f = (id >= 0 && path && qcwd && qcmd && qdir && qlog && topt) ? fopen(tmp, "w") : NULL;
    cleanup_unlock();
    if (f) {
        size_t last = j->nstems < SLURM_ARRAY_CHUNK ? j->nstems - 1 : SLURM_ARRAY_CHUNK - 1;
        fprintf(f,
                "#!/bin/sh\n"
                "# Written by raygl2pov: renders the frames of render.list, one per task of a\n"
                "# Slurm job array. The output folder must be on storage every node shares,\n"
                "# at the same path, and raygl-render and %s installed on every node.\n"
                "#   sbatch %s\n"
                "# renders frames 0-%zu; for more than %d frames submit once per chunk:\n"
                "#   sbatch --array=0-999 --export=ALL,RAYGL_OFFSET=1000 %s\n"
                "# A task whose PNG is newer than its scene does nothing, so a job can be\n"
                "# submitted again after a failure.\n"
                "#SBATCH --job-name=raygl\n"
                "#SBATCH --array=0-%zu\n"
                "#SBATCH --ntasks=1\n"
                "#SBATCH --cpus-per-task=1\n"
                "#SBATCH --output=%s\n"
                "cd %s || exit 1\n"
                "exec %s %s --task \"$((${RAYGL_OFFSET:-0} + SLURM_ARRAY_TASK_ID))\"%s\n",
                is_blender(j->r) ? "blender" : "povray", path, last, SLURM_ARRAY_CHUNK, path,
                last, qlog, qcwd, qcmd, qdir, topt);
        rc = ferror(f) ? -1 : 0;
        if (fclose(f) != 0)
            rc = -1;
        if (rc == 0)
            rc = chmod(tmp, 0755);
        if (rc == 0)
            rc = rename(tmp, path);
        if (rc != 0)
            unlink(tmp);
    }
    cleanup_drop(id);
    if (rc != 0)
        say(j->prog, "%s: cannot write: %s", path ? path : j->dir,
            cmd ? strerror(errno) : "raygl-render not found next to this program");
    if (rc == 0)
        *script_out = path;
    else
        tr_free(path);
    tr_free(tmp);
    tr_free(cwd);
    tr_free(cmd);
    tr_free(qcwd);
    tr_free(qcmd);
    tr_free(qdir);
    tr_free(absdir);
    tr_free(qlog);
    tr_free(topt);
    return rc;
}

static int submit_slurm(const render_job *j, const char *script)
{
    int rc = 0;
    for (size_t first = 0; first < j->nstems && rc == 0; first += SLURM_ARRAY_CHUNK) {
        size_t n = j->nstems - first < SLURM_ARRAY_CHUNK ? j->nstems - first : SLURM_ARRAY_CHUNK;
        char array[64], exp[64];
        snprintf(array, sizeof array, "--array=0-%zu", n - 1);
        snprintf(exp, sizeof exp, "--export=ALL,RAYGL_OFFSET=%zu", first);
        char *argv[] = {"sbatch", array, exp, (char *)script, NULL};
        int st = run_wait(argv, j->prog);
        if (st != 0) {
            say(j->prog, "%s: sbatch failed (exit status %d)", script, st);
            rc = 1;
        }
    }
    return rc;
}

/* GNU parallel: one job per frame, `raygl-render DIR --task N` on the hosts
 * of the login file (":" is this machine), in the folder raygl2pov ran in. */
static int render_parallel(const render_job *j)
{
    char *cwd = cwd_now(), *cmd = render_command();
    char *qcmd = cmd ? sh_quote(cmd) : NULL, *qdir = sh_quote(j->dir);
    char *topt = task_options(j->r);
    char *line = (qcmd && qdir && topt) ? aprintf("%s %s%s --task {}", qcmd, qdir, topt) : NULL;
    char *last = aprintf("%zu", j->nstems - 1);
    int rc = 1;
    /* The summary counts PNGs up to date before and after, as the hosts'
     * tasks report nothing back but their exit status. */
    scan_includes(j->dir);
    size_t before = 0;
    for (size_t i = 0; i < j->nstems; i++)
        before += up_to_date(j->r, j->stems[i]);
    double t0 = now();
    if (cwd && line && last) {
        char *argv[] = {"parallel", "--will-cite", "--halt", "never", "--sshloginfile",
                        (char *)j->r->sshloginfile, "--workdir", cwd, line, ":::", NULL, NULL};
        /* The indices as arguments: {0..N-1} expanded here. */
        size_t n = j->nstems;
        char **full = tr_realloc(NULL, (11 + n + 1) * sizeof *full);
        char *nums = tr_realloc(NULL, n * 24 + 1);
        if (full && nums) {
            memcpy(full, argv, 10 * sizeof *full);
            char *p = nums;
            for (size_t i = 0; i < n; i++) {
                full[10 + i] = p;
                p += sprintf(p, "%zu", i) + 1;
            }
            full[10 + n] = NULL;
            int st = run_wait(full, j->prog);
            if (st != 0)
                say(j->prog, "GNU parallel: %d frame(s) failed (see the messages above)", st);
            rc = st == 0 ? 0 : 1;
            size_t after = 0;
            for (size_t i = 0; i < j->nstems; i++)
                after += up_to_date(j->r, j->stems[i]);
            size_t rendered = after > before ? after - before : 0;
            summary(j, rendered, now() - t0, "over SSH", before, j->nstems - after, 0);
        }
        tr_free(full);
        tr_free(nums);
    }
    tr_free(cwd);
    tr_free(cmd);
    tr_free(qcmd);
    tr_free(qdir);
    tr_free(topt);
    tr_free(line);
    tr_free(last);
    return rc;
}

/* ---- Entry points ------------------------------------------------------------------------------ */

int render_task(const render_settings *r, const char *prog, const char *dir, long n)
{
    if (render_check_tools(r, prog) != 0)
        return 1;
    char *stem = list_entry(prog, dir, n);
    if (!stem)
        return 1;
    int rc = 0;
    scan_includes(dir);
    if (!up_to_date(r, stem)) {
        running run;
        memset(&run, 0, sizeof run);
        for (int k = 0; k < 5; k++)
            run.ids[k] = -1;
        for (int attempt = 0;; attempt++) {
            if (start_frame(prog, r, stem, 1, &run) != 0) {
                rc = 1;
                break;
            }
            int st;
            while (waitpid(run.pid, &st, 0) < 0 && errno == EINTR)
                ;
            cleanup_lock();
            reaped(&run);
            cleanup_check(); /* Ctrl-C to the group: a stop, not a failure */
            cleanup_unlock();
            if (attempt == 0 && !is_blender(r) && transient_failure(st, run.tmp_log))
                continue;
            rc = finish_frame(prog, r, stem, st, false, &run) ? 0 : 1;
            break;
        }
        forget(&run);
        free_names(&run);
    }
    tr_free(stem);
    return rc;
}

int render_run(const render_job *j)
{
    if (j->nstems == 0)
        return 0;
    if (write_list(j) != 0)
        return 1;
    int rc = 0;
    if (j->r->slurm || j->r->submit) {
        char *script = NULL;
        if (write_slurm(j, &script) != 0)
            return 1;
        if (!j->quiet)
            fprintf(stderr, "%s: %s: a Slurm job array of %zu frames%s\n", j->prog, script,
                    j->nstems, j->r->submit ? "" : " (submit it with sbatch)");
        if (j->r->submit)
            rc = submit_slurm(j, script);
        tr_free(script);
        return rc; /* the cluster renders; --video needs the PNGs first */
    }
    size_t failed = 0;
    if (j->r->sshloginfile)
        rc = render_parallel(j);
    else if (j->r->render || j->r->video)
        rc = render_local(j, &failed);
    if (j->r->video) {
        if (rc != 0)
            say(j->prog, "--video: not made, %s", "some frames were not rendered");
        else
            rc = make_video(j);
    }
    return rc;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The visible NAME.EXT of dir as stems DIR/NAME (unsorted); 0 or -1. */
static int scan_ext(const char *prog, const char *dir, const char *ext, char ***stems, size_t *n)
{
    DIR *d = opendir(dir);
    if (!d) {
        say(prog, "%s: cannot read the folder: %s", dir, strerror(errno));
        return -1;
    }
    size_t cap = 0, dl = strlen(dir), el = strlen(ext);
    const char *sep = dl && dir[dl - 1] == '/' ? "" : "/";
    struct dirent *e;
    int rc = 0;
    while ((e = readdir(d))) {
        size_t l = strlen(e->d_name);
        if (e->d_name[0] == '.' || l <= el || strcmp(e->d_name + l - el, ext) != 0)
            continue;
        if (tr_grow((void **)stems, &cap, *n + 1, sizeof **stems) != 0 ||
            !((*stems)[*n] = aprintf("%s%s%.*s", dir, sep, (int)(l - el), e->d_name))) {
            say(prog, "out of memory");
            rc = -1;
            break;
        }
        (*n)++;
    }
    closedir(d);
    return rc;
}

int render_scan_dir(render_settings *r, const char *prog, const char *dir, char ***stems,
                    size_t *n)
{
    *stems = NULL;
    *n = 0;
    int rc = scan_ext(prog, dir, frame_ext(r), stems, n);
    if (rc == 0 && *n == 0 && r->engine == RENDER_ENGINE_AUTO) {
        /* raygl2pov --format gltf's folder: Blender's frames. */
        rc = scan_ext(prog, dir, ".glb", stems, n);
        if (rc == 0 && *n > 0)
            r->engine = RENDER_ENGINE_BLENDER;
    }
    if (rc == 0 && *n == 0) {
        if (is_blender(r))
            say(prog, "%s: no .glb files: translate a trace into it with raygl2pov --format gltf "
                      "first", dir);
        else
            say(prog, "%s: no .ini files: translate a trace into it with raygl2pov first", dir);
        rc = -1;
    }
    if (rc != 0) {
        render_free_stems(*stems, *n);
        *stems = NULL;
        *n = 0;
        return -1;
    }
    qsort(*stems, *n, sizeof **stems, cmp_str);
    return 0;
}

void render_free_stems(char **stems, size_t n)
{
    for (size_t i = 0; stems && i < n; i++)
        tr_free(stems[i]);
    tr_free(stems);
}

render_engine render_engine_named(const char *name)
{
    if (strcmp(name, "povray") == 0)
        return RENDER_ENGINE_POVRAY;
    if (strcmp(name, "blender") == 0)
        return RENDER_ENGINE_BLENDER;
    return RENDER_ENGINE_AUTO;
}
