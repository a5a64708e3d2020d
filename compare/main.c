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
 * floor, 2 on bad usage.
 */
#include <errno.h>
#include <limits.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "format.h"
#include "imagediff.h"

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
          "Render the frames of TRACE that hold a snapshot (recorded with RAYGL_SNAPSHOTS=1)\n"
          "with raygl2pov and POV-Ray, and compare each with the image the program showed.\n"
          "\n"
          "  -o, --output DIR        write DIR/pov/ (the scenes, rendered) and, per frame,\n"
          "                          DIR/compare-NNNNN.png: OpenGL | POV-Ray | difference\n"
          "      --frames LIST       only these frames (file order, from 0): N, A-B, A-\n"
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

/* Marks the frames of LIST (N, A-B, A-; comma-separated) in sel[0..n).
 * Returns 0 or -1 for a malformed list. */
static int select_frames(const char *list, bool *sel, size_t n)
{
    const char *s = list;
    if (!*s)
        return -1;
    for (;;) {
        char *end;
        errno = 0;
        unsigned long a = strtoul(s, &end, 10), b = a;
        if (errno || end == s || *s == '-' || *s == '+')
            return -1;
        s = end;
        if (*s == '-') {
            s++;
            if (*s == ',' || *s == '\0') {
                b = n ? n - 1 : 0;
            } else {
                b = strtoul(s, &end, 10);
                if (errno || end == s || *s == '-' || *s == '+' || b < a)
                    return -1;
                s = end;
            }
        }
        for (unsigned long k = a; k <= b && k < n; k++)
            sel[k] = true;
        if (*s == '\0')
            return 0;
        if (*s != ',')
            return -1;
        s++;
    }
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

/* raygl2pov beside this program, else the name for PATH. */
static const char *find_raygl2pov(char *buf, size_t cap)
{
    ssize_t n = readlink("/proc/self/exe", buf, cap - 1);
    if (n > 0) {
        buf[n] = '\0';
        char *slash = strrchr(buf, '/');
        if (slash && (size_t)(slash - buf) + sizeof "/raygl2pov" <= cap) {
            strcpy(slash, "/raygl2pov");
            if (access(buf, X_OK) == 0)
                return buf;
        }
    }
    return "raygl2pov";
}

/* Runs raygl2pov in DIR over the frames of `list`; returns its exit
 * status, or -1 when it could not run. */
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
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (chdir(o->dir) != 0)
            _exit(127);
        execvp(r2p, (char *const *)args);
        fprintf(stderr, PROG ": %s: %s\n", r2p, strerror(errno));
        _exit(127);
    }
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int main(int argc, char **argv)
{
    setlocale(LC_ALL, "");
    cmp_options o;
    if (parse_args(argc, argv, &o) != 0) {
        fprintf(stderr, "Try '" PROG " --help' for more information.\n");
        return 2;
    }
    char trace_abs[PATH_MAX];
    if (!realpath(o.trace, trace_abs)) {
        fprintf(stderr, PROG ": %s: %s\n", o.trace, strerror(errno));
        return 1;
    }
    rgl_reader *r;
    rgl_error err;
    if (rgl_reader_open_file(trace_abs, &r, &err) != RGL_OK) {
        fprintf(stderr, PROG ": %s: @0x%llx: %s (%s)\n", o.trace, (unsigned long long)err.offset,
                rgl_status_str(err.status), err.detail);
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
            fprintf(stderr, PROG ": --frames %s: expected N, A-B or A-, comma-separated\n",
                    o.frames);
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
                "RAYGL_SNAPSHOTS=1)\n", o.trace, o.frames ? "selected " : "");
        rc = 1;
        goto out;
    }
    if (mkdir(o.dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, PROG ": %s: %s\n", o.dir, strerror(errno));
        rc = 1;
        goto out;
    }
    char r2p_buf[PATH_MAX];
    const char *r2p = o.raygl2pov ? o.raygl2pov : find_raygl2pov(r2p_buf, sizeof r2p_buf);
    int r2p_rc = run_raygl2pov(&o, r2p, trace_abs, list);
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
        snprintf(path, sizeof path, "%s/compare-%05zu.png", o.dir, i);
        if (img_side_by_side(&a, &b, o.tol, &side) != 0 ||
            img_write_png(path, side.rgb, side.w, side.h) != 0) {
            fprintf(stderr, PROG ": %s: cannot write\n", path);
            rc = 1;
        }
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
