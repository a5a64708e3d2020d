/* main.c: raygl-compare, the OpenGL frame beside the ray-traced one.
 *
 *   raygl-compare TRACE -o DIR [--frames LIST] [--tol N] [--min-match F]
 *                 [--min-silhouette S] [--raygl2pov PROG] [--povray PROG]
 *                 [-j N] [-- RAYGL2POV-OPTION...]
 *
 * For every frame of TRACE that holds a snapshot (@Snapshot, recorded with
 * RAYGL_SNAPSHOTS=1): raygl2pov translates and renders it into DIR/pov/
 * (run in DIR, as povray must be), the snapshot is decoded, and
 * DIR/compare-NNNNN.png shows OpenGL | POV-Ray | amplified difference
 * (compare/imagediff.h defines the figures printed). Nothing is written
 * outside DIR. Exit 0, 1 on bad input, a failed frame or a figure under a
 * floor, 2 on bad usage. Its own options, raygl2pov's (after --), the
 * programs and the output folder are checked before anything is rendered.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cleanup.h"
#include "format.h"
#include "framesel.h"
#include "imagediff.h"
#include "mkdirs.h"
#include "sibling.h"

#ifndef RAYGL_VERSION
#define RAYGL_VERSION "unknown"
#endif

#define PROG "raygl-compare"
#define MAX_PASS 64

typedef struct cmp_options {
    const char *trace, *dir, *frames, *raygl2pov, *povray, *jobs;
    int tol;
    double min_match, min_sil; /* < 0: no floor */
    const char *pass[MAX_PASS];
    int npass;
} cmp_options;

static void usage(FILE *f)
{
    fputs("Usage: " PROG " TRACE -o DIR [OPTION]... [-- RAYGL2POV-OPTION...]\n"
          "Render the frames of TRACE that hold a snapshot (recorded with `raygl record\n"
          "--snapshots`, or RAYGL_SNAPSHOTS=1) with raygl2pov and POV-Ray, and compare each\n"
          "with the image the program showed.\n"
          "\n"
          "  -o, --output DIR        write DIR/pov/ (the scenes, rendered) and, per frame,\n"
          "                          DIR/compare-NNNNN.png: OpenGL | POV-Ray | difference\n"
          "      --frames LIST       only these frames (file order, from 0): N, A-B, A-,\n"
          "                          each optionally with :STEP (0-100:10)\n"
          "      --tol N             per-channel tolerance in levels (default 2)\n"
          "      --min-match F       fail when a frame's fraction within N is below F\n"
          "      --min-silhouette S  fail when a frame's silhouette agreement is below S\n"
          "      --raygl2pov PROG    the translator (default: beside " PROG ", else PATH)\n"
          "      --povray PROG       the POV-Ray program (default: povray in PATH)\n"
          "  -j, --jobs N            frames rendered at once\n"
          "  -h, --help              print this help and exit\n"
          "  -V, --version           print the version and exit\n"
          "\n"
          "Per frame it prints the fraction of pixels whose channels all differ by at\n"
          "most N, the mean absolute difference, and the silhouette agreement (pixels\n"
          "unlike the GL image's border colour, intersection over union).\n"
          "Exit status: 0 success, 1 bad input, a failed frame or a figure under a floor,\n"
          "2 bad usage.\n",
          f);
}

static int parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !(v >= 0 && v <= 1))
        return -1;
    *out = v;
    return 0;
}

static int parse_args(int argc, char **argv, cmp_options *o)
{
    memset(o, 0, sizeof *o);
    o->tol = 2;
    o->min_match = o->min_sil = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--") == 0) {
            for (i++; i < argc; i++) {
                if (o->npass == MAX_PASS) {
                    fprintf(stderr, PROG ": at most %d raygl2pov options\n", MAX_PASS);
                    return -1;
                }
                o->pass[o->npass++] = argv[i];
            }
            break;
        }
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            exit(0);
        }
        if (strcmp(a, "-V") == 0 || strcmp(a, "--version") == 0) {
            printf(PROG " " RAYGL_VERSION "\n");
            exit(0);
        }
        if (a[0] != '-') {
            if (o->trace) {
                fprintf(stderr, PROG ": one trace only (%s, %s)\n", o->trace, a);
                return -1;
            }
            o->trace = a;
            continue;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, PROG ": %s: missing value\n", a);
            return -1;
        }
        const char *v = argv[++i];
        int bad = 0;
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            o->dir = v;
            bad = !*v;
        } else if (!strcmp(a, "--frames")) {
            o->frames = v;
        } else if (!strcmp(a, "--tol")) {
            char *end;
            errno = 0;
            long t = strtol(v, &end, 10);
            bad = errno || end == v || *end || t < 0 || t > 255;
            o->tol = (int)t;
        } else if (!strcmp(a, "--min-match")) {
            bad = parse_double(v, &o->min_match);
        } else if (!strcmp(a, "--min-silhouette")) {
            bad = parse_double(v, &o->min_sil);
        } else if (!strcmp(a, "--raygl2pov")) {
            o->raygl2pov = v;
        } else if (!strcmp(a, "--povray")) {
            o->povray = v;
        } else if (!strcmp(a, "-j") || !strcmp(a, "--jobs")) {
            o->jobs = v;
        } else {
            fprintf(stderr, PROG ": unknown option %s\n", a);
            return -1;
        }
        if (bad) {
            fprintf(stderr, PROG ": %s %s: bad value\n", a, v);
            return -1;
        }
    }
    if (!o->trace || !o->dir) {
        fprintf(stderr, PROG ": %s\n", !o->trace ? "no trace given" : "no output folder (-o DIR)");
        return -1;
    }
    return 0;
}

/* Marks the frames of LIST (format/framesel.h: as raygl2pov takes it) in
 * sel[0..n). Returns 0 or -1 for a malformed list. */
static int select_frames(const char *list, bool *sel, size_t n)
{
    const char *s = list;
    if (!*s)
        return -1;
    while (*s) {
        rgl_frame_range r;
        if (rgl_framesel_next(&s, &r) != RGL_FRAMESEL_OK)
            return -1;
        for (uint64_t k = r.first; k < n && k <= r.last; k = r.step < n ? k + r.step : n)
            sel[k] = true;
    }
    return 0;
}

/* Snapshot images that did not decode, with the frames that share them:
 * the recorder shares one image among frames that showed the same, so one
 * damaged image is said once, with its frames, not once a frame. */
typedef struct bad_image {
    uint32_t id;
    size_t first, last, n; /* frames */
    rgl_error err;
} bad_image;

typedef struct bad_images {
    bad_image *v;
    size_t n, cap;
} bad_images;

static bad_image *bad_find(bad_images *b, uint32_t id)
{
    for (size_t k = 0; k < b->n; k++)
        if (b->v[k].id == id)
            return &b->v[k];
    return NULL;
}

/* Records frame i as sharing bad image id; false when out of memory. */
static bool bad_add(bad_images *b, uint32_t id, size_t i, const rgl_error *err)
{
    bad_image *e = bad_find(b, id);
    if (!e) {
        if (b->n == b->cap) {
            size_t cap = b->cap ? 2 * b->cap : 8;
            bad_image *v = realloc(b->v, cap * sizeof *v);
            if (!v)
                return false;
            b->v = v;
            b->cap = cap;
        }
        e = &b->v[b->n++];
        e->id = id;
        e->first = i;
        e->n = 0;
        e->err = *err;
    }
    e->last = i;
    e->n++;
    return true;
}

/* The frame's @Snapshot decoded (top row first), or NULL: *had says
 * whether there was one; a bad command is reported, a bad image is kept in
 * bad for one message per image. */
static uint8_t *frame_snapshot(rgl_reader *r, const char *trace, size_t i, rgl_snapshot *snap,
                               bool *had, bad_images *bad)
{
    static rgl_cmd cmd;
    rgl_frame_info fi;
    rgl_error err;
    *had = false;
    if (rgl_reader_frame(r, i, &fi, &err) != RGL_OK) {
        fprintf(stderr, PROG ": %s: frame %zu @0x%llx: %s (%s)\n", trace, i,
                (unsigned long long)err.offset, rgl_status_str(err.status), err.detail);
        return NULL;
    }
    rgl_cmd_iter it;
    rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
    bool found = false;
    rgl_status st;
    while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
        if (cmd.opcode != RGL_OP_Snapshot)
            continue;
        *had = true;
        found = rgl_snapshot_from_cmd(&cmd, snap, &err) == RGL_OK;
        if (!found) {
            fprintf(stderr, PROG ": %s: frame %zu, cmd %llu (@Snapshot) @0x%llx: %s: %s\n", trace,
                    i, (unsigned long long)cmd.index, (unsigned long long)err.offset,
                    rgl_status_str(err.status), err.detail);
        }
    }
    if (st != RGL_END && !*had) {
        fprintf(stderr, PROG ": %s: frame %zu, cmd %llu @0x%llx: %s (%s)\n", trace, i,
                (unsigned long long)it.error.cmd_index, (unsigned long long)it.error.offset,
                rgl_status_str(it.error.status), it.error.detail);
        *had = true; /* a frame cut before its snapshot counts as failed */
        return NULL;
    }
    if (!found)
        return NULL;
    rgl_resource res;
    uint8_t *rgb = NULL;
    if (bad_find(bad, snap->image)) {
        bad_add(bad, snap->image, i, NULL);
        return NULL;
    }
    if (rgl_reader_resource(r, snap->image, &res, &err) != RGL_OK ||
        rgl_snapshot_decode(snap, &res, &rgb, &err) != RGL_OK) {
        if (!bad_add(bad, snap->image, i, &err))
            fprintf(stderr, PROG ": %s: frame %zu, @Snapshot image #%u @0x%llx: %s: %s\n", trace,
                    i, (unsigned)snap->image, (unsigned long long)err.offset,
                    rgl_status_str(err.status), err.detail);
        return NULL;
    }
    return rgb;
}

/* name found in PATH (or name itself when it holds a '/'): whether it runs. */
static bool in_path(const char *name)
{
    if (strchr(name, '/'))
        return access(name, X_OK) == 0;
    const char *path = getenv("PATH");
    char cand[PATH_MAX];
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        size_t n = strcspn(p, ":");
        struct stat st;
        if (snprintf(cand, sizeof cand, "%.*s/%s", (int)n, n ? p : ".", name) < (int)sizeof cand &&
            stat(cand, &st) == 0 && S_ISREG(st.st_mode) && access(cand, X_OK) == 0)
            return true;
        p += n + (p[n] == ':');
    }
    return false;
}

/* raygl2pov beside this program (sibling.h), else the name for PATH. */
static const char *find_raygl2pov(char *buf, size_t cap)
{
    return sibling_path("raygl2pov", buf, cap) ? buf : "raygl2pov";
}

/* raygl2pov's options that raygl-compare sets itself. */
static const char *const own_options[] = {"-o", "--output", "--frames", "--name-pattern",
                                          "--render", "--povray", "-j", "--jobs", "--video",
                                          "--slurm", "--submit", "--sshloginfile", NULL};

/* Checks what can be checked before rendering: the options after --, the
 * programs, the output folder. Returns 0, or the exit status with one
 * line printed. */
static int precheck(const cmp_options *o, const char *r2p)
{
    for (int k = 0; k < o->npass; k++) {
        const char *a = o->pass[k];
        for (int i = 0; own_options[i]; i++) {
            size_t l = strlen(own_options[i]);
            if (strncmp(a, own_options[i], l) == 0 &&
                (a[l] == '\0' || a[l] == '=' || (a[1] != '-' && a[l] != '\0'))) {
                fprintf(stderr, PROG ": %s after --: raygl-compare sets it itself%s\n", a,
                        strcmp(own_options[i], "--render") ? " (give it before --)" : "");
                return 2;
            }
        }
    }
    if (!in_path(r2p)) {
        fprintf(stderr, PROG ": %s: raygl2pov not found %s (give --raygl2pov PROG)\n", r2p,
                strchr(r2p, '/') ? "or not executable" : "beside " PROG " nor in PATH");
        return 1;
    }
    if (o->povray && !in_path(o->povray)) {
        fprintf(stderr, PROG ": --povray %s: not found%s\n", o->povray,
                strchr(o->povray, '/') ? " or not executable" : " in PATH");
        return 1;
    }
    struct stat st;
    if (stat(o->dir, &st) == 0 && !S_ISDIR(st.st_mode)) {
        fprintf(stderr, PROG ": -o %s: not a folder\n", o->dir);
        return 1;
    }
    if (stat(o->dir, &st) == 0 && access(o->dir, W_OK | X_OK) != 0) {
        fprintf(stderr, PROG ": -o %s: cannot write into it: %s\n", o->dir, strerror(errno));
        return 1;
    }
    char pov[PATH_MAX];
    if (snprintf(pov, sizeof pov, "%s/pov", o->dir) < (int)sizeof pov && stat(pov, &st) == 0 &&
        !S_ISDIR(st.st_mode)) {
        fprintf(stderr, PROG ": %s: not a folder (raygl2pov writes the scenes there)\n", pov);
        return 1;
    }
    return 0;
}

/* Runs raygl2pov in DIR over the frames of `list`; returns its exit
 * status, or -1 when it could not run. Its messages are passed on when it
 * ends, except on bad usage (exit 2): then only its first line, as the
 * reason the options after -- are refused. */
static int run_raygl2pov(const cmp_options *o, const char *r2p, const char *trace_abs,
                         const char *list)
{
    const char *args[MAX_PASS + 20];
    int n = 0;
    args[n++] = r2p;
    args[n++] = trace_abs;
    for (int k = 0; k < o->npass; k++)
        args[n++] = o->pass[k];
    args[n++] = "-o";
    args[n++] = "pov";
    args[n++] = "--frames";
    args[n++] = list;
    args[n++] = "--name-pattern";
    args[n++] = "frame-{index:5}";
    args[n++] = "--render";
    args[n++] = "--quiet";
    if (o->povray) {
        args[n++] = "--povray";
        args[n++] = o->povray;
    }
    if (o->jobs) {
        args[n++] = "--jobs";
        args[n++] = o->jobs;
    }
    args[n] = NULL;
    fflush(NULL);
    int pfd[2];
    if (pipe2(pfd, O_CLOEXEC) != 0)
        return -1;
    /* Registered at once: a stop stops it too, and it cleans up its own. */
    cleanup_lock();
    pid_t pid = fork();
    long id = pid > 0 ? cleanup_tool(pid) : -1;
    cleanup_unlock();
    if (pid < 0) {
        close(pfd[0]);
        close(pfd[1]);
        return -1;
    }
    if (pid == 0) {
        cleanup_child_signals();
        if (dup2(pfd[1], 2) < 0 || chdir(o->dir) != 0)
            _exit(127);
        execvp(r2p, (char *const *)args);
        fprintf(stderr, PROG ": %s: %s\n", r2p, strerror(errno));
        _exit(127);
    }
    close(pfd[1]);
    char *msg = NULL;
    size_t len = 0, cap = 0;
    for (;;) {
        if (len + 4096 > cap) {
            char *m = realloc(msg, cap ? cap * 2 : 8192);
            if (!m)
                break;
            msg = m;
            cap = cap ? cap * 2 : 8192;
        }
        ssize_t r = read(pfd[0], msg + len, cap - len);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            break;
        len += (size_t)r;
    }
    close(pfd[0]);
    int status;
    int w;
    while ((w = (int)waitpid(pid, &status, 0)) < 0 && errno == EINTR)
        ;
    cleanup_drop(id);
    int rc = w < 0 ? -1 : WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (rc == 2 && len > 0) {
        size_t l = 0;
        while (l < len && msg[l] != '\n')
            l++;
        fprintf(stderr, PROG ": after --: %.*s\n", (int)l, msg);
    } else if (len > 0) {
        fwrite(msg, 1, len, stderr);
    }
    free(msg);
    return rc;
}

int main(int argc, char **argv)
{
    setlocale(LC_ALL, "");
    cmp_options o;
    if (parse_args(argc, argv, &o) != 0) {
        fprintf(stderr, "Try '" PROG " --help' for more information.\n");
        return 2;
    }
    char r2p_buf[PATH_MAX];
    const char *r2p = o.raygl2pov ? o.raygl2pov : find_raygl2pov(r2p_buf, sizeof r2p_buf);
    int pre = precheck(&o, r2p);
    if (pre != 0) {
        if (pre == 2)
            fprintf(stderr, "Try '" PROG " --help' for more information.\n");
        return pre;
    }
    if (cleanup_start() != 0) {
        fprintf(stderr, PROG ": cannot start: %s\n", strerror(errno));
        return 1;
    }
    char trace_abs[PATH_MAX];
    if (!realpath(o.trace, trace_abs)) {
        fprintf(stderr, PROG ": %s: %s\n", o.trace, strerror(errno));
        return 1;
    }
    rgl_reader *r;
    rgl_error err;
    rgl_status ost = rgl_reader_open_file(trace_abs, &r, &err);
    if (ost != RGL_OK) {
        /* The detail only when it adds to the status. */
        const char *st = rgl_status_str(err.status);
        bool detail = err.detail[0] && strcmp(err.detail, st) != 0;
        if (ost == RGL_E_IO)
            fprintf(stderr, PROG ": %s: cannot read: %s\n", o.trace, strerror(errno));
        else
            fprintf(stderr, PROG ": %s: @0x%llx: %s%s%s\n", o.trace,
                    (unsigned long long)err.offset, st, detail ? ": " : "",
                    detail ? err.detail : "");
        return 1;
    }
    size_t nframes = rgl_reader_frame_count(r);
    int rc = 0;
    bool *sel = calloc(nframes ? nframes : 1, sizeof *sel);
    uint8_t **gl = calloc(nframes ? nframes : 1, sizeof *gl);
    rgl_snapshot *snaps = calloc(nframes ? nframes : 1, sizeof *snaps);
    char *list = malloc(nframes * 21 + 2);
    if (!sel || !gl || !snaps || !list) {
        fprintf(stderr, PROG ": out of memory\n");
        rc = 1;
        goto out;
    }
    if (o.frames) {
        if (select_frames(o.frames, sel, nframes) != 0) {
            fprintf(stderr, PROG ": --frames %s: expected N, A-B or A-, each optionally with "
                    ":STEP, comma-separated\n", o.frames);
            rc = 2;
            goto out;
        }
    } else {
        for (size_t i = 0; i < nframes; i++)
            sel[i] = true;
    }
    size_t nsnap = 0, ll = 0;
    list[0] = '\0';
    bad_images bad = {NULL, 0, 0};
    for (size_t i = 0; i < nframes; i++) {
        if (!sel[i])
            continue;
        bool had;
        gl[i] = frame_snapshot(r, o.trace, i, &snaps[i], &had, &bad);
        if (had && !gl[i])
            rc = 1;
        if (gl[i]) {
            ll += (size_t)sprintf(list + ll, "%s%zu", nsnap ? "," : "", i);
            nsnap++;
        }
    }
    /* Only the comparison of those frames is lost: they are translated
     * as any other (raygl2pov never reads snapshot images). */
    for (size_t k = 0; k < bad.n; k++) {
        const bad_image *e = &bad.v[k];
        char frames[96];
        if (e->n == 1)
            snprintf(frames, sizeof frames, "frame %zu", e->first);
        else
            snprintf(frames, sizeof frames, "%zu frames from %zu to %zu", e->n, e->first,
                     e->last);
        fprintf(stderr, PROG ": %s: frame %zu, @Snapshot image #%u @0x%llx: %s: %s: %s not "
                "compared\n", o.trace, e->first, (unsigned)e->id,
                (unsigned long long)e->err.offset, rgl_status_str(e->err.status), e->err.detail,
                frames);
    }
    free(bad.v);
    if (nsnap == 0) {
        fprintf(stderr, PROG ": %s: no %sframe holds a usable snapshot (record with "
                "`raygl record --snapshots`, or RAYGL_SNAPSHOTS=1 for a program that links "
                "libraygl)\n", o.trace, o.frames ? "selected " : "");
        rc = 1;
        goto out;
    }
    /* -o NEW/SUB/DIR makes what is missing, as raygl2pov -o does. */
    size_t made;
    if (mkdirs(o.dir, &made) != 0) {
        fprintf(stderr, PROG ": %s: cannot create the output folder: %s\n", o.dir,
                strerror(errno));
        mkdirs_undo(o.dir, made);
        rc = 1;
        goto out;
    }
    int r2p_rc = run_raygl2pov(&o, r2p, trace_abs, list);
    if (r2p_rc == 2) {
        /* Its line (above) names the option; nothing was rendered, and the
         * folders go when this run made them. */
        mkdirs_undo(o.dir, made);
        rc = 2;
        goto out;
    }
    if (r2p_rc == 127 || r2p_rc < 0) {
        fprintf(stderr, PROG ": %s could not run; nothing rendered\n", r2p);
        rc = 1;
        goto out;
    }
    if (r2p_rc != 0) {
        fprintf(stderr, PROG ": %s exited with %d; comparing the frames it rendered\n", r2p,
                r2p_rc);
        rc = 1;
    }

    for (size_t i = 0; i < nframes; i++) {
        if (!gl[i])
            continue;
        const rgl_snapshot *s = &snaps[i];
        img a = {s->width, s->height, gl[i], false, 0, false}, b;
        char path[PATH_MAX], why[128];
        snprintf(path, sizeof path, "%s/pov/frame-%05zu.png", o.dir, i);
        if (img_read_png(path, &b, why, sizeof why) != 0) {
            printf("frame %zu: FAIL: %s: %s\n", i, path, why);
            rc = 1;
            continue;
        }
        if (b.w != a.w || b.h != a.h) {
            printf("frame %zu: FAIL: OpenGL %dx%d, POV-Ray %dx%d\n", i, a.w, a.h, b.w, b.h);
            free(b.rgb);
            rc = 1;
            continue;
        }
        int bg[3];
        img_border_mode(&a, bg);
        img_stats st;
        img_compare(&a, &b, o.tol, bg, &st);
        double frac = (double)st.within / (double)st.npix;
        img side;
        memset(&side, 0, sizeof side);
        snprintf(path, sizeof path, "%s/compare-%05zu.png", o.dir, i);
        /* Under a hidden name until complete (cleanup.h). */
        char tmp[PATH_MAX + 32];
        snprintf(tmp, sizeof tmp, "%s/.compare-%05zu.png.%ld.tmp", o.dir, i, (long)getpid());
        cleanup_lock();
        long tid = cleanup_file(tmp);
        if (tid < 0 || img_side_by_side(&a, &b, o.tol, &side) != 0 ||
            img_write_png(tmp, side.rgb, side.w, side.h) != 0 || rename(tmp, path) != 0) {
            fprintf(stderr, PROG ": %s: cannot write: %s\n", path, strerror(errno));
            unlink(tmp);
            rc = 1;
        }
        cleanup_drop(tid);
        cleanup_unlock();
        free(side.rgb);
        bool below = (o.min_match >= 0 && frac < o.min_match) ||
                     (o.min_sil >= 0 && st.silhouette < o.min_sil);
        printf("frame %zu: %dx%d within %d/255 %.5f, mean diff %.4f/255, silhouette %.5f "
               "(background %d,%d,%d), core %zu%s -> %s\n",
               i, a.w, a.h, o.tol, frac, st.mean_all, st.silhouette, bg[0], bg[1], bg[2],
               st.core, below ? " BELOW FLOOR" : "", path);
        if (below)
            rc = 1;
        free(b.rgb);
    }
out:
    for (size_t i = 0; gl && i < nframes; i++)
        rgl_format_realloc(gl[i], 0);
    free(gl);
    free(sel);
    free(snaps);
    free(list);
    rgl_reader_destroy(r);
    return rc;
}
