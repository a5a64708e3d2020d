/* main.c: raygl2pov, the command line.
 *
 *   raygl2pov TRACE -o DIR [--frames A-B[,C...]] [-j N] [--dump] [--quiet | --verbose]
 *
 * Workers (one translator each) take the selected frames in file order and
 * write each scene to a temporary file in DIR; the main thread then takes
 * the results in frame order: it prints their diagnostics, picks the final
 * names, writes the .ini and renames both files into place. So the output
 * and the messages do not depend on -j, and an interrupted or failed run
 * leaves no half-written scene under a final name.
 *
 * Messages: "raygl2pov: TRACE: frame 12, cmd 1234 (glLightfv) @0x1f0: ...".
 * Exit status: 0 success, 1 bad input (damaged trace, unwritable output),
 * 2 bad usage.
 */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <limits.h>
#include <locale.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cleanup.h"
#include "diag.h"
#include "format.h"
#include "frame.h"
#include "gltfwrite.h"
#include "look.h"
#include "mkdirs.h"
#include "naming.h"
#include "outbuf.h"
#include "options.h"
#include "povwrite.h"
#include "render.h"
#include "talloc.h"
#include "unrecorded.h"

#ifndef RAYGL_VERSION
#define RAYGL_VERSION "unknown"
#endif

#define PROG "raygl2pov"
#define EXIT_INPUT 1
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

/* The options that only a POV-Ray scene can use, or NULL. */
static const char *pov_only_option(const options *o)
{
    if (render_wanted(&o->render) && o->render.engine == RENDER_ENGINE_POVRAY)
        return "--engine povray";
    if (o->look.nincludes)
        return "--include";
    if (o->look.antialias)
        return "--antialias";
    if (o->look.quality)
        return "--quality";
    if (o->look.radiosity)
        return "--radiosity";
    if (o->pov.no_shadows)
        return "--no-shadows";
    if (o->pov.reflection != 0)
        return "--reflection";
    if (o->pov.area_lights)
        return "--area-lights";
    return NULL;
}

/* The scene files' suffix. */
static const char *scene_ext(const options *o) { return o->gltf ? ".glb" : ".pov"; }

static void parse_args(int argc, char **argv, options *o)
{
    opt_err err;
    opt_init(o);
    /* raygl2gltf: the same program, glTF by default. */
    const char *base = argc > 0 && argv[0] ? strrchr(argv[0], '/') : NULL;
    base = base ? base + 1 : argc > 0 && argv[0] ? argv[0] : "";
    o->gltf = strcmp(base, "raygl2gltf") == 0;
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
    const char *pov_only = o->gltf ? pov_only_option(o) : NULL;
    if (pov_only) {
        snprintf(err.msg, sizeof err.msg, "%s: POV-Ray only, not with --format gltf", pov_only);
        usage_error(err.msg);
    }
    if (render_wanted(&o->render) && !o->outdir)
        usage_error("rendering needs an output folder (-o DIR)");
    /* Each format has its engine: .glb frames render with Blender. */
    if (!o->gltf && o->render.engine == RENDER_ENGINE_BLENDER)
        usage_error("--engine blender renders glTF frames: add --format gltf");
    o->render.engine = o->gltf ? RENDER_ENGINE_BLENDER : RENDER_ENGINE_POVRAY;
    if (o->render.video && !o->render.render && !o->render.sshloginfile)
        o->render.render = true; /* a video needs the PNGs */
    if (render_wanted(&o->render) && render_check_tools(&o->render, PROG) != 0)
        exit(EXIT_INPUT);
    if (o->outdir && !o->gltf && !pov_ini_path_ok(o->outdir)) {
        snprintf(err.msg, sizeof err.msg,
                 "output folder '%.200s': a double quote or control character cannot be "
                 "written into POV-Ray's .ini", o->outdir);
        usage_error(err.msg);
    }
}

/* ---- Messages ---------------------------------------------------------------- */

static bool progress_shown;

static void clear_progress(void)
{
    if (progress_shown) {
        fputs("\r\033[K", stderr);
        progress_shown = false;
    }
}

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void say(const options *o, const char *fmt, ...)
{
    va_list ap;
    clear_progress();
    fprintf(stderr, PROG ": %s: ", o->trace);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* say() for a line of text, as a callback. */
static void say_line(const char *text, void *user) { say(user, "%s", text); }

/* "@0x1f0: truncated: detail", with the command when the error names one. */
static void say_decode_error(const options *o, const char *where, const rgl_error *e)
{
    const rgl_cmd_info *info = e->opcode ? rgl_cmd_info_get(e->opcode) : NULL;
    char cmdpart[96] = "";
    if (info)
        snprintf(cmdpart, sizeof cmdpart, ", cmd %" PRIu64 " (%s)", e->cmd_index, info->name);
    const char *st = rgl_status_str(e->status);
    bool detail = e->detail[0] && strcmp(e->detail, st) != 0;
    say(o, "%s%s%s@0x%" PRIx64 ": %s%s%s", where, cmdpart, *where || *cmdpart ? " " : "",
        e->offset, st, detail ? ": " : "", detail ? e->detail : "");
}

/* ---- Names and files -------------------------------------------------------------- */

static char *join_path(const char *dir, const char *file)
{
    size_t dl = strlen(dir), fl = strlen(file);
    bool slash = dl > 0 && dir[dl - 1] == '/';
    char *p = tr_realloc(NULL, dl + fl + 2);
    if (!p)
        return NULL;
    memcpy(p, dir, dl);
    if (!slash)
        p[dl++] = '/';
    memcpy(p + dl, file, fl + 1);
    return p;
}

static int fd_flush(void *user, const char *data, size_t n)
{
    int fd = *(int *)user;
    while (n > 0) {
        ssize_t w = write(fd, data, n);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        data += w;
        n -= (size_t)w;
    }
    return 0;
}

/* Temporary file names: hidden, per process and per frame slot. */
static char *temp_path(const char *dir, size_t slot, const char *ext)
{
    char name[96];
    snprintf(name, sizeof name, ".raygl2pov-%ld-%zu%s.tmp", (long)getpid(), slot, ext);
    return join_path(dir, name);
}

/* ---- The work ----------------------------------------------------------------------- */

typedef struct slot {
    size_t frame;       /* index in the file */
    atomic_int done;    /* the worker finished with it */
    rgl_status status;  /* translation */
    rgl_error error;
    rgl_frame_info info;
    diag_log *log;
    char *frame_name;   /* rayglFrameBegin's, or NULL */
    int width, height;
    int antialias_depth; /* the scene's, for the .ini */
    int write_errno;    /* writing the temporary .pov failed */
    char *write_failed; /* the file it could not write (a texture), or NULL:
                           the temporary .pov */
    const char *look_note; /* look_apply's, static */
    char *published;       /* "DIR/NAME" once written */
    long tmp_id;           /* the temporary .pov's cleanup entry, or -1 */
    unrec_table unrec;     /* the frame's calls not recorded */
    char *incomplete;      /* why the scene is incomplete: the cut, then what
                              damage took (frame_result), or NULL */
    bool damaged;          /* a part of it was lost to damage */
    interp_budget_use used, limit; /* of the frame budget (--dump) */
} slot;

typedef struct job {
    const options *o;
    rgl_reader *reader;
    pthread_mutex_t reader_lock;
    slot *slots;
    size_t nslots;
    atomic_size_t next;
    atomic_int abort;
    pthread_mutex_t done_lock;
    pthread_cond_t done_cond;
    char **includes; /* --include files' names in the output folder */
    /* Held by the worker whose frame is heavy (interp_set_heavy) until it
     * is written: one heavy frame at a time bounds the memory of -j N. */
    pthread_mutex_t heavy_lock;
    int nworkers; /* threads asked for: one alone keeps its memory for the next frame */
} job;

typedef struct worker_ctx {
    job *j;
    bool heavy; /* holds j->heavy_lock */
} worker_ctx;

static void heavy_enter(void *ctx)
{
    worker_ctx *w = ctx;
    /* A frame translated twice (a second camera, frame.c) is heavy twice:
     * its turn is held already. */
    if (w->heavy)
        return;
    pthread_mutex_lock(&w->j->heavy_lock);
    w->heavy = true;
}

/* After a heavy frame is written: its memory goes back before the next
 * heavy frame may start, when other workers could start one. A worker
 * alone keeps it: its next frame reuses the arrays instead of faulting
 * in fresh pages (32k page faults fell to 9k on the 4-frame strips trace).
 * False when the translator cannot go on. */
static bool heavy_leave(worker_ctx *w, translator *t)
{
    bool ok = true;
    if (w->heavy) {
        if (w->j->nworkers > 1)
            ok = translator_trim(t) == 0;
        pthread_mutex_unlock(&w->j->heavy_lock);
    }
    w->heavy = false;
    return ok;
}

static void finish_slot(job *j, slot *s)
{
    pthread_mutex_lock(&j->done_lock);
    atomic_store(&s->done, 1);
    pthread_cond_broadcast(&j->done_cond);
    pthread_mutex_unlock(&j->done_lock);
}

/* Writes the scene to the slot's temporary file. */
static void write_temp(job *j, translator *t, size_t k, slot *s, outbuf *ob)
{
    char *path = temp_path(j->o->outdir, k, scene_ext(j->o));
    if (!path) {
        s->write_errno = ENOMEM;
        return;
    }
    /* Registered before it exists, so a stop removes it (cleanup.h). */
    cleanup_lock();
    s->tmp_id = cleanup_file(path);
    int fd = s->tmp_id >= 0 ? open(path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666) : -1;
    int open_errno = s->tmp_id >= 0 ? errno : ENOMEM;
    cleanup_unlock();
    if (fd < 0) {
        s->write_errno = open_errno;
        cleanup_drop(s->tmp_id);
        s->tmp_id = -1;
        tr_free(path);
        return;
    }
    char fname[NAME_MAX_STEM + 32];
    name_vars nv = {s->frame, s->info.stream, s->info.number, s->frame_name, j->o->trace};
    name_stem(j->o->name_pattern, &nv, fname, NAME_MAX_STEM + 1);
    strcat(fname, ".pov");
    pov_frame_info info = {fname, j->o->trace, s->frame, s->info.stream, s->info.number,
                           s->frame_name, &j->o->pov, s->incomplete};
    ob->len = 0;
    ob->failed = false;
    ob->user = &fd;
    errno = 0;
    int rc;
    if (j->o->gltf) {
        gltf_frame_info gi = {j->o->trace, s->frame, s->frame_name, s->incomplete};
        rc = gltf_write(ob, translator_scene(t), &gi, NULL);
        if (rc == 0)
            rc = outbuf_flush(ob);
    } else {
        rc = translator_write_pov(t, ob, &info);
        if (rc == 0)
            rc = look_write_scene(ob, &j->o->look, translator_scene(t),
                                  (const char *const *)j->includes, j->o->look.nincludes);
        if (rc == 0)
            rc = outbuf_flush(ob);
        errno = 0;
        char failed[PATH_MAX] = "";
        if (rc == 0)
            rc = translator_write_images(t, j->o->outdir, failed, sizeof failed);
        if (rc != 0 && failed[0]) {
            int fe = errno;
            s->write_failed = tr_realloc(NULL, strlen(failed) + 1);
            if (s->write_failed)
                strcpy(s->write_failed, failed);
            errno = fe;
        }
    }
    int e = errno ? errno : ENOMEM;
    if (close(fd) != 0 && rc == 0) {
        rc = -1;
        e = errno;
    }
    if (rc != 0) {
        s->write_errno = e;
        unlink(path);
        cleanup_drop(s->tmp_id);
        s->tmp_id = -1;
    }
    tr_free(path);
}

/* "cut at ...\nwritten without ..." for a frame written incomplete, or
 * NULL (no memory: the details are then lost, not the frame). */
static char *incomplete_text(const frame_result *res)
{
    char more[48] = "";
    if (res->nmissing > 1)
        snprintf(more, sizeof more, " and %" PRIu32 " more part%s", res->nmissing - 1,
                 res->nmissing > 2 ? "s" : "");
    size_t cap = strlen(res->cut) + strlen(res->missing) + sizeof more + 32;
    char *t = tr_realloc(NULL, cap);
    if (!t)
        return NULL;
    snprintf(t, cap, "%s%s%s%s%s", res->cut, res->cut[0] && res->nmissing ? "\n" : "",
             res->nmissing ? "written without " : "", res->missing, more);
    return t;
}

static void *worker(void *arg)
{
    job *j = arg;
    worker_ctx w = {j, false};
    translator *t = translator_create(j->reader, &j->reader_lock);
    if (t) {
        translator_set_heavy(t, heavy_enter, &w);
        translator_set_vertex_lighting(t, j->o->vertex_lighting);
        translator_set_shadows(t, !j->o->pov.no_shadows);
        translator_set_pov(t, !j->o->gltf);
    }
    outbuf ob;
    bool ob_ok = outbuf_init(&ob, 1 << 20, fd_flush, NULL) == 0;
    for (;;) {
        size_t k = atomic_fetch_add(&j->next, 1);
        if (k >= j->nslots)
            break;
        slot *s = &j->slots[k];
        if (atomic_load(&j->abort) || !t || !ob_ok) {
            s->status = RGL_E_NOMEM;
            finish_slot(j, s);
            continue;
        }
        s->log = tr_realloc(NULL, sizeof *s->log);
        if (s->log)
            diag_clear(s->log);
        frame_result res;
        s->status = translator_build(t, s->frame, j->o->quiet ? NULL : s->log, &res);
        s->error = res.error;
        s->info = res.info;
        s->used = res.used;
        s->limit = res.limit;
        if (res.unrecorded)
            (void)unrec_copy(&s->unrec, res.unrecorded);
        if (res.frame_name) {
            s->frame_name = tr_realloc(NULL, strlen(res.frame_name) + 1);
            if (s->frame_name)
                strcpy(s->frame_name, res.frame_name);
        }
        if (s->status == RGL_OK && (res.cut[0] || res.nmissing)) {
            s->incomplete = incomplete_text(&res);
            s->damaged = res.nmissing > 0;
        }
        scene *sc = translator_scene_edit(t);
        if (s->status == RGL_OK)
            s->look_note = look_apply(&j->o->look, sc);
        if (s->status == RGL_OK && s->log && !j->o->gltf && j->o->pov.quick && scene_needs_quality6(sc)) {
            char prefix[32];
            snprintf(prefix, sizeof prefix, "frame %zu", s->frame);
            diag_add(s->log, DIAG_NOTE_QUALITY, prefix, "%s", diag_kind_name(DIAG_NOTE_QUALITY));
        }
        if (s->status == RGL_OK && j->o->gltf && look_add_lights(&j->o->look, sc) != 0)
            s->status = RGL_E_NOMEM;
        s->width = sc->camera.width;
        s->height = sc->camera.height;
        s->antialias_depth = sc->antialias_depth;
        if (s->status == RGL_OK && j->o->outdir)
            write_temp(j, t, k, s, &ob);
        if (!heavy_leave(&w, t)) {
            translator_destroy(t);
            t = NULL; /* the next slots fail as out of memory */
        }
        finish_slot(j, s);
    }
    outbuf_finish(&ob);
    translator_destroy(t);
    return NULL;
}

/* ---- The main thread's side ------------------------------------------------------------ */

typedef struct names {
    char **v;
    size_t n, cap;
} names;

static bool name_used(const names *u, const char *s)
{
    for (size_t i = 0; i < u->n; i++)
        if (strcmp(u->v[i], s) == 0)
            return true;
    return false;
}

static void name_add(names *u, const char *s)
{
    if (tr_grow((void **)&u->v, &u->cap, u->n + 1, sizeof *u->v) != 0)
        return;
    char *c = tr_realloc(NULL, strlen(s) + 1);
    if (!c)
        return;
    strcpy(c, s);
    u->v[u->n++] = c;
}

typedef struct totals {
    diag_log log;      /* counts of everything; the messages already printed */
    uint64_t printed[DIAG_COUNT];
    uint64_t printed_held[DIAG_COUNT]; /* held notes printed (--verbose) */
    int status;        /* exit status so far */
    size_t written;
} totals;

/* Each note once per run: the first said, and with --verbose the first
 * held (marked); other kinds DIAG_KEEP times, then a count. */
static void print_diags(const options *o, totals *tot, const diag_log *log)
{
    for (int k = 0; k < DIAG_COUNT; k++) {
        const diag_entry *e = &log->e[k];
        tot->log.e[k].count += e->count;
        tot->log.e[k].dropped += e->dropped;
        tot->log.e[k].held += e->held;
        bool note = diag_is_note((diag_kind)k);
        for (uint32_t m = 0; m < e->kept; m++) {
            if (note && diag_is_held(e, m)) {
                if (!o->verbose || tot->printed_held[k] >= 1)
                    continue;
                tot->printed_held[k]++;
            } else {
                if (tot->printed[k] >= (note ? 1u : DIAG_KEEP))
                    continue;
                tot->printed[k]++;
            }
            say(o, "%s", e->text[m]);
        }
    }
}

/* Renames tmp to fin, unless fin already holds the same bytes: then fin
 * keeps its time, so a PNG rendered from it still counts as up to date
 * (re-running with --render renders only what changed). */
static int place(const char *tmp, const char *fin)
{
    if (files_same(tmp, fin))
        return unlink(tmp);
    return rename(tmp, fin);
}

/* Renames slot k's temporary .glb into place as STEM.glb. */
static void publish_glb(const options *o, totals *tot, size_t k, slot *s, const char *stem)
{
    char glb[NAME_MAX_STEM + 64];
    snprintf(glb, sizeof glb, "%s.glb", stem);
    char *tmp = temp_path(o->outdir, k, ".glb"), *fin = join_path(o->outdir, glb);
    if (!tmp || !fin) {
        say(o, "frame %zu: out of memory", s->frame);
        tot->status = EXIT_INPUT;
    } else if (place(tmp, fin) != 0) {
        say(o, "%s: cannot write: %s", fin, strerror(errno));
        unlink(tmp);
        tot->status = EXIT_INPUT;
    } else {
        tot->written++;
        s->published = join_path(o->outdir, stem);
    }
    cleanup_drop(s->tmp_id);
    s->tmp_id = -1;
    tr_free(tmp);
    tr_free(fin);
}

/* DIR/POV_FOLDER_CHECK, read first by every .ini (povwrite.h); kept as
 * it is when unchanged, so rendered frames stay up to date. Returns 0, or
 * -1 with the message said. */
static int write_folder_check(const options *o)
{
    char *tmp = temp_path(o->outdir, 0, ".inc"), *fin = join_path(o->outdir, POV_FOLDER_CHECK);
    int rc = -1, e = ENOMEM, fd = -1;
    long id = -1;
    if (tmp && fin) {
        cleanup_lock();
        id = cleanup_file(tmp);
        fd = id >= 0 ? open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666) : -1;
        e = id >= 0 ? errno : ENOMEM;
        cleanup_unlock();
    }
    if (fd >= 0) {
        outbuf ob;
        errno = 0;
        rc = outbuf_init(&ob, 4096, fd_flush, &fd);
        if (rc == 0)
            rc = pov_write_folder_check(&ob, o->outdir);
        if (rc == 0)
            rc = outbuf_flush(&ob);
        e = errno ? errno : EIO;
        outbuf_finish(&ob);
        if (close(fd) != 0 && rc == 0) {
            rc = -1;
            e = errno;
        }
        if (rc == 0 && place(tmp, fin) != 0) {
            rc = -1;
            e = errno;
        }
        if (rc != 0)
            unlink(tmp);
    }
    if (rc != 0)
        say(o, "%s: cannot write: %s", fin ? fin : o->outdir, strerror(e));
    cleanup_drop(id);
    tr_free(tmp);
    tr_free(fin);
    return rc;
}

/* Writes the .ini of slot k and renames both files into place. */
static void publish(const options *o, totals *tot, names *used, size_t k, slot *s)
{
    /* Stems are at most NAME_MAX_STEM bytes, suffixes at most 32. */
    char stem[NAME_MAX_STEM + 64];
    name_vars nv = {s->frame, s->info.stream, s->info.number, s->frame_name, o->trace};
    name_stem(o->name_pattern, &nv, stem, NAME_MAX_STEM + 1);
    if (name_used(used, stem)) {
        char base[NAME_MAX_STEM + 1];
        size_t bl = strnlen(stem, NAME_MAX_STEM);
        memcpy(base, stem, bl);
        base[bl] = '\0';
        snprintf(stem, sizeof stem, "%s-%05zu", base, s->frame);
        for (int n = 2; name_used(used, stem); n++)
            snprintf(stem, sizeof stem, "%s-%05zu-%d", base, s->frame, n);
        if (!o->quiet)
            say(o, "frame %zu: %s%s is taken by an earlier frame; writing %s%s", s->frame,
                base, scene_ext(o), stem, scene_ext(o));
    }
    name_add(used, stem);
    if (o->gltf) {
        publish_glb(o, tot, k, s, stem);
        return;
    }

    char pov[sizeof stem + 8], ini[sizeof stem + 8], png[sizeof stem + 8];
    snprintf(pov, sizeof pov, "%s.pov", stem);
    snprintf(ini, sizeof ini, "%s.ini", stem);
    snprintf(png, sizeof png, "%s.png", stem);
    char *tmp_pov = temp_path(o->outdir, k, ".pov"), *tmp_ini = temp_path(o->outdir, k, ".ini");
    char *fin_pov = join_path(o->outdir, pov), *fin_ini = join_path(o->outdir, ini);
    long ini_id = -1;
    if (!tmp_pov || !tmp_ini || !fin_pov || !fin_ini) {
        say(o, "frame %zu: out of memory", s->frame);
        tot->status = EXIT_INPUT;
        goto done;
    }

    scene dims;
    memset(&dims, 0, sizeof dims);
    dims.camera.width = s->width;
    dims.camera.height = s->height;
    dims.antialias_depth = s->antialias_depth;
    outbuf ob;
    cleanup_lock();
    ini_id = cleanup_file(tmp_ini);
    int fd = ini_id >= 0 ? open(tmp_ini, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666) : -1;
    int open_errno = ini_id >= 0 ? errno : ENOMEM;
    cleanup_unlock();
    if (fd < 0) {
        say(o, "%s: cannot create: %s", tmp_ini, strerror(open_errno));
        tot->status = EXIT_INPUT;
        unlink(tmp_pov);
        goto done;
    }
    int rc = outbuf_init(&ob, 4096, fd_flush, &fd);
    errno = 0;
    if (rc == 0)
        rc = pov_write_ini(&ob, &dims, o->outdir, pov, png);
    if (rc == 0)
        rc = look_write_ini(&ob, &o->look);
    if (rc == 0)
        rc = outbuf_flush(&ob);
    int e = errno ? errno : EIO;
    outbuf_finish(&ob);
    if (close(fd) != 0 && rc == 0) {
        rc = -1;
        e = errno;
    }
    if (rc != 0 || place(tmp_pov, fin_pov) != 0 || place(tmp_ini, fin_ini) != 0) {
        if (rc == 0)
            e = errno;
        say(o, "%s: cannot write: %s", fin_pov, strerror(e));
        unlink(tmp_pov);
        unlink(tmp_ini);
        tot->status = EXIT_INPUT;
        goto done;
    }
    tot->written++;
    s->published = join_path(o->outdir, stem);
done:
    cleanup_drop(ini_id);
    cleanup_drop(s->tmp_id);
    s->tmp_id = -1;
    tr_free(tmp_pov);
    tr_free(tmp_ini);
    tr_free(fin_pov);
    tr_free(fin_ini);
}

/* --dump while translating: what the frame used of each budget
 * (docs/mapping.md "Bounds"), on standard output after the dump. */
static void say_budget(const options *o, const slot *s)
{
    if (!o->dump)
        return;
    const interp_budget_use *u = &s->used, *l = &s->limit;
    printf("frame %zu: budget: commands %" PRIu64 " of %" PRIu64 ", vertices assembled %" PRIu64
           " of %" PRIu64 ", vertices %" PRIu64 " of %" PRIu64 ", triangles %" PRIu64 " of %" PRIu64
           ", lines and points %" PRIu64 " of %" PRIu64 ", solids %" PRIu64 " of %" PRIu64
           ", instances %" PRIu64 " of %" PRIu64 ", texture bytes %" PRIu64 " of %" PRIu64 "\n",
           s->frame, u->commands, l->commands, u->assembled, l->assembled, u->vertices,
           l->vertices, u->triangles, l->triangles, u->lines, l->lines, u->solids, l->solids,
           u->instances, l->instances, u->texels, l->texels);
    fflush(stdout);
}

/* A frame written incomplete: the cut is a note (the frame is what the
 * budget allows); a part lost to damage is damage, said and counted in the
 * exit status even with --quiet (raygl2pov(1), "Damage"). */
static void say_incomplete(const options *o, totals *tot, const slot *s)
{
    if (!s->published)
        return;
    if (s->damaged && !s->incomplete)
        say(o, "frame %zu: written without a part lost to damage", s->frame);
    for (const char *p = s->incomplete; p && *p; p += *p == '\n') {
        const char *nl = strchr(p, '\n');
        int len = nl ? (int)(nl - p) : (int)strlen(p);
        bool cut = strncmp(p, "cut ", 4) == 0;
        if (!cut || !o->quiet)
            say(o, "frame %zu: %.*s", s->frame, len, p);
        p += len;
    }
    if (s->damaged)
        tot->status = EXIT_INPUT;
}

static void progress(const options *o, size_t done, size_t total)
{
    if (o->quiet || total < 2 || !isatty(STDERR_FILENO))
        return;
    fprintf(stderr, "\r" PROG ": %zu of %zu frames", done, total);
    progress_shown = true;
}

static void print_summary(const options *o, const totals *tot)
{
    if (o->quiet)
        return;
    for (int k = 0; k < DIAG_FIRST_NOTE; k++) {
        uint64_t n = tot->log.e[k].count;
        if (n > tot->printed[k])
            say(o, "%" PRIu64 " calls skipped in all (%s), %" PRIu64 " shown", n,
                diag_kind_name((diag_kind)k), tot->printed[k]);
    }
    /* --verbose: how often each note was said and held, frames counted
     * once each (a frame logs a note at most once either way). */
    for (int k = DIAG_FIRST_NOTE; o->verbose && k < DIAG_COUNT; k++) {
        const diag_entry *e = &tot->log.e[k];
        if (e->held)
            say(o, "note held in %" PRIu64 " frame%s where it cannot change a pixel, said in %"
                PRIu64 ": %s", e->held, e->held == 1 ? "" : "s", e->count - e->held,
                diag_kind_name((diag_kind)k));
    }
    for (int k = 0; k < DIAG_COUNT; k++)
        if (tot->log.e[k].dropped)
            say(o, "%" PRIu64 " message%s (%s) left out whole: longer than %d characters",
                tot->log.e[k].dropped, tot->log.e[k].dropped > 1 ? "s" : "",
                diag_kind_name((diag_kind)k), DIAG_TEXT - 1);
}

/* ---- --dump ---------------------------------------------------------------------------- */

/* Prints the commands of one sequence; adds its @NotRecorded counts to
 * unrec as frame `frame`'s. */
static bool dump_sequence(const options *o, const uint8_t *data, size_t size, uint64_t off,
                          const char *indent, const char *where, unrec_table *unrec,
                          uint64_t frame)
{
    rgl_cmd_iter it;
    rgl_cmd cmd;
    rgl_status st;
    char line[16384];
    rgl_cmd_iter_init(&it, data, size, off);
    while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
        rgl_cmd_format(&cmd, line, sizeof line);
        printf("%s%" PRIu64 " @0x%" PRIx64 " %s\n", indent, cmd.index, cmd.offset, line);
        if (cmd.opcode == RGL_OP_NotRecorded)
            (void)unrec_add(unrec, cmd.arg[0].bytes, cmd.arg[0].count, cmd.arg[1].v.u, frame);
    }
    if (st == RGL_END)
        return true;
    printf("%s<damaged: %s>\n", indent, rgl_status_str(st));
    say_decode_error(o, where, &it.error);
    return false;
}

static void dump_line(const char *text, void *user)
{
    (void)user;
    printf("#   %s\n", text);
}

static int dump(const options *o, rgl_reader *r)
{
    int status = 0;
    unrec_table unrec; /* the dumped frames' calls not recorded */
    unrec_init(&unrec);
    size_t isz;
    const char *info = rgl_reader_info(r, &isz);
    if (info) {
        printf("# info:\n");
        const char *p = info, *end = info + isz;
        while (p < end) {
            const char *nl = memchr(p, '\n', (size_t)(end - p));
            size_t len = nl ? (size_t)(nl - p) : (size_t)(end - p);
            printf("#   %.*s\n", (int)len, p);
            p += len + (nl ? 1 : 0);
        }
    }
    for (size_t i = 0; i < rgl_reader_frame_count(r); i++) {
        if (!opt_frame_selected(o, i))
            continue;
        rgl_frame_info fi;
        rgl_error err;
        char where[64];
        snprintf(where, sizeof where, "frame %zu", i);
        if (rgl_reader_frame(r, i, &fi, &err) != RGL_OK) {
            printf("frame %zu: <damaged: %s>\n", i, rgl_status_str(err.status));
            say_decode_error(o, where, &err);
            status = EXIT_INPUT;
            continue;
        }
        printf("frame %zu: stream %u, number %u, flags 0x%x%s%s, snapshot ", i, fi.stream,
               fi.number, fi.flags, fi.flags & RGL_FRAME_LIVE_CONTEXT ? " live-context" : "",
               fi.flags & RGL_FRAME_STATE_CARRIED ? " state-carried" : "");
        if (fi.state)
            printf("#%u", fi.state);
        else
            printf("none");
        printf(", @0x%" PRIx64 ", %zu bytes of commands\n", fi.offset, fi.commands_size);
        if (fi.state) {
            rgl_resource res;
            if (rgl_reader_resource(r, fi.state, &res, &err) != RGL_OK) {
                printf("  snapshot #%u: <damaged: %s>\n", fi.state, rgl_status_str(err.status));
                say_decode_error(o, where, &err);
                status = EXIT_INPUT;
            } else {
                printf("  snapshot #%u: @0x%" PRIx64 ", %zu bytes\n", fi.state, res.data_offset,
                       res.size);
                char w2[96];
                snprintf(w2, sizeof w2, "frame %zu, snapshot #%u", i, fi.state);
                if (res.kind == RGL_RES_COMMANDS &&
                    !dump_sequence(o, res.data, res.size, res.data_offset, "    ", w2, &unrec, i))
                    status = EXIT_INPUT;
            }
        }
        if (!dump_sequence(o, fi.commands, fi.commands_size, fi.commands_offset, "  ", where,
                           &unrec, i))
            status = EXIT_INPUT;
    }
    if (unrec.n || unrec.other_calls) {
        /* Every one, marked by what it can change (no frame is translated
         * here to tell whether it does). */
        printf("# not recorded (@NotRecorded) in these frames:\n");
        unrec_report(&unrec, UNREC_REPORT_DUMP, dump_line, NULL);
    }
    unrec_finish(&unrec);
    fflush(stdout);
    return status;
}

/* ---- main -------------------------------------------------------------------------------- */

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

    rgl_reader *reader = NULL;
    rgl_error err;
    memset(&err, 0, sizeof err);
    rgl_status st = rgl_reader_open_file(o.trace, &reader, &err);
    if (st != RGL_OK) {
        struct stat sb;
        if (st == RGL_E_IO && stat(o.trace, &sb) == 0 && S_ISDIR(sb.st_mode))
            say(&o, "cannot read: a folder, not a trace (give the .raygl file)");
        else if (st == RGL_E_IO)
            say(&o, "cannot read: %s", strerror(errno));
        else
            say_decode_error(&o, "", &err);
        return EXIT_INPUT;
    }
    totals tot;
    memset(&tot, 0, sizeof tot);
    for (size_t i = 0; i < rgl_reader_damage_count(reader); i++) {
        const rgl_error *d = rgl_reader_damage(reader, i);
        say(&o, "damaged region @0x%" PRIx64 ": %s%s%s", d->offset, rgl_status_str(d->status),
            d->detail[0] ? ": " : "", d->detail);
        tot.status = EXIT_INPUT;
    }
    /* Not damage: what the recorder wrote before it stopped is whole. */
    if (!rgl_reader_closed(reader, NULL) && !o.quiet)
        say(&o, "trace not closed (the recording was killed or the disk filled): %zu complete "
            "frame%s, the frame in progress is lost", rgl_reader_frame_count(reader),
            rgl_reader_frame_count(reader) == 1 ? "" : "s");
    if (o.dump && dump(&o, reader) != 0)
        tot.status = EXIT_INPUT;
    if (!o.outdir) {
        rgl_reader_destroy(reader);
        opt_free(&o);
        return tot.status;
    }

    size_t nframes = rgl_reader_frame_count(reader);
    job j;
    memset(&j, 0, sizeof j);
    j.o = &o;
    j.reader = reader;
    for (size_t r = 0; r < o.nranges; r++) {
        uint64_t bad = o.ranges[r].first >= nframes ? o.ranges[r].first
                       : o.ranges[r].last != UINT64_MAX && o.ranges[r].last >= nframes
                           ? o.ranges[r].last
                           : UINT64_MAX;
        if (bad != UINT64_MAX) {
            if (nframes)
                say(&o, "--frames: frame %" PRIu64 " is outside the trace (frames 0-%zu)", bad,
                    nframes - 1);
            else
                say(&o, "--frames: frame %" PRIu64 " is outside the trace (no frames)", bad);
            rgl_reader_destroy(reader);
            opt_free(&o);
            return EXIT_INPUT;
        }
    }
    for (size_t i = 0; i < nframes; i++)
        if (opt_frame_selected(&o, i))
            j.nslots++;
    if (j.nslots == 0) {
        if (o.nranges)
            say(&o, "--frames selects none of the %zu frames", nframes);
        else
            say(&o, "no frames to translate");
        rgl_reader_destroy(reader);
        opt_free(&o);
        return EXIT_INPUT;
    }
    if (mkdirs(o.outdir, NULL) != 0) {
        fprintf(stderr, PROG ": %s: cannot create the output folder: %s\n", o.outdir,
                strerror(errno));
        rgl_reader_destroy(reader);
        opt_free(&o);
        return EXIT_INPUT;
    }
    if (!o.gltf && write_folder_check(&o) != 0) {
        rgl_reader_destroy(reader);
        opt_free(&o);
        return EXIT_INPUT;
    }
    char msg[600];
    if (look_copy_includes(&o.look, o.outdir, &j.includes, msg, sizeof msg) != 0) {
        fprintf(stderr, PROG ": %s\n", msg);
        rgl_reader_destroy(reader);
        opt_free(&o);
        return EXIT_INPUT;
    }
    j.slots = tr_realloc(NULL, j.nslots * sizeof *j.slots);
    if (!j.slots) {
        say(&o, "out of memory");
        rgl_reader_destroy(reader);
        return EXIT_INPUT;
    }
    memset(j.slots, 0, j.nslots * sizeof *j.slots);
    for (size_t i = 0, k = 0; i < nframes; i++)
        if (opt_frame_selected(&o, i)) {
            j.slots[k].tmp_id = -1;
            j.slots[k++].frame = i;
        }
    pthread_mutex_init(&j.reader_lock, NULL);
    pthread_mutex_init(&j.done_lock, NULL);
    pthread_mutex_init(&j.heavy_lock, NULL);
    pthread_cond_init(&j.done_cond, NULL);

    int nthreads = o.jobs < (int)j.nslots ? o.jobs : (int)j.nslots;
    j.nworkers = nthreads;
    pthread_t threads[OPT_MAX_JOBS];
    int started = 0;
    for (; started < nthreads; started++)
        if (pthread_create(&threads[started], NULL, worker, &j) != 0)
            break;
    if (started == 0)
        worker(&j); /* no thread: do it here */

    names used;
    memset(&used, 0, sizeof used);
    bool fatal = false;
    const char *notes[4];
    int nnotes = 0;
    unrec_table unrec; /* the whole trace's, reported once at the end */
    unrec_init(&unrec);
    for (size_t k = 0; k < j.nslots; k++) {
        slot *s = &j.slots[k];
        pthread_mutex_lock(&j.done_lock);
        while (!atomic_load(&s->done))
            pthread_cond_wait(&j.done_cond, &j.done_lock);
        pthread_mutex_unlock(&j.done_lock);

        if (s->log)
            print_diags(&o, &tot, s->log);
        if (s->look_note && !o.quiet) {
            bool seen = false;
            for (int n = 0; n < nnotes; n++)
                seen = seen || notes[n] == s->look_note;
            if (!seen && nnotes < 4) {
                notes[nnotes++] = s->look_note;
                say(&o, "frame %zu: %s", s->frame, s->look_note);
            }
        }
        if (fatal) {
            /* Already stopped: drop what the workers still made. */
        } else if (s->status != RGL_OK) {
            char where[64];
            snprintf(where, sizeof where, "frame %zu (not written)", s->frame);
            if (s->status == RGL_E_NOMEM && atomic_load(&j.abort) == 0)
                say(&o, "frame %zu: out of memory", s->frame);
            else if (s->status != RGL_E_NOMEM)
                say_decode_error(&o, where, &s->error);
            tot.status = EXIT_INPUT;
        } else if (s->write_errno) {
            char *tmp = s->write_failed ? NULL : temp_path(o.outdir, k, scene_ext(&o));
            fprintf(stderr, "%s" PROG ": %s: cannot write: %s\n", progress_shown ? "\r\033[K" : "",
                    s->write_failed ? s->write_failed : tmp ? tmp : o.outdir,
                    strerror(s->write_errno));
            progress_shown = false;
            tr_free(tmp);
            tot.status = EXIT_INPUT;
            /* The folder is unusable (full, read-only): stop here. */
            fatal = true;
            atomic_store(&j.abort, 1);
        } else {
            publish(&o, &tot, &used, k, s);
            say_incomplete(&o, &tot, s);
            say_budget(&o, s);
        }
        if (fatal && s->status == RGL_OK && !s->write_errno) {
            char *tmp = temp_path(o.outdir, k, scene_ext(&o));
            if (tmp)
                unlink(tmp);
            tr_free(tmp);
            cleanup_drop(s->tmp_id);
            s->tmp_id = -1;
        }
        tr_free(s->log);
        s->log = NULL;
        tr_free(s->frame_name);
        s->frame_name = NULL;
        (void)unrec_merge(&unrec, &s->unrec, s->frame);
        unrec_finish(&s->unrec);
        tr_free(s->incomplete);
        s->incomplete = NULL;
        tr_free(s->write_failed);
        s->write_failed = NULL;
        progress(&o, k + 1, j.nslots);
    }
    for (int t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    clear_progress();
    if (!o.quiet)
        unrec_report(&unrec, o.verbose ? UNREC_REPORT_VERBOSE : UNREC_REPORT_MATTERS, say_line,
                     &o);
    unrec_finish(&unrec);
    print_summary(&o, &tot);

    if (render_wanted(&o.render) && !fatal) {
        /* The frames written, in frame order; a failed translation still
         * leaves the others to render (and the exit status says so). */
        char **stems = tr_realloc(NULL, (j.nslots ? j.nslots : 1) * sizeof *stems);
        size_t n = 0;
        for (size_t k = 0; stems && k < j.nslots; k++)
            if (j.slots[k].published)
                stems[n++] = j.slots[k].published;
        if (!stems) {
            say(&o, "out of memory");
            tot.status = EXIT_INPUT;
        } else {
            render_job rj = {&o.render, PROG, o.outdir, stems, n, o.jobs, o.quiet};
            if (render_run(&rj) != 0)
                tot.status = EXIT_INPUT;
        }
        tr_free(stems);
    }
    for (size_t k = 0; k < j.nslots; k++)
        tr_free(j.slots[k].published);

    for (size_t i = 0; i < used.n; i++)
        tr_free(used.v[i]);
    tr_free(used.v);
    tr_free(j.slots);
    look_free_names(j.includes, o.look.nincludes);
    opt_free(&o);
    pthread_cond_destroy(&j.done_cond);
    pthread_mutex_destroy(&j.done_lock);
    pthread_mutex_destroy(&j.heavy_lock);
    pthread_mutex_destroy(&j.reader_lock);
    rgl_reader_destroy(reader);
    if (fflush(stdout) != 0)
        tot.status = EXIT_INPUT;
    return tot.status;
}
