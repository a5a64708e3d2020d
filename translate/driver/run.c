/* run.c: the frame driver (driver.h): workers translate the selected
 * frames in file order, each through gl/ (frame.c), look/ and the writer
 * into a temporary file; the main thread publishes them in frame order.
 */
#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "driver_internal.h"
#include "mkdirs.h"
#include "naming.h"
#include "outbuf.h"
#include "talloc.h"

bool frames_selected(const frame_range *ranges, size_t n, uint64_t i)
{
    if (n == 0)
        return true;
    for (size_t k = 0; k < n; k++)
        if (rgl_framesel_has(&ranges[k], i))
            return true;
    return false;
}

/* ---- Names and files -------------------------------------------------------------- */

/* Temporary file names: hidden, per process and per frame slot (writer.h). */
static char *temp_path(const char *dir, size_t slot, const char *ext)
{
    return writer_temp_path(dir, slot, ext);
}

/* ---- The work ----------------------------------------------------------------------- */

typedef struct job {
    const driver_settings *d;
    const writer_def *wd;
    void *wrun; /* the writer's run (begin) */
    rgl_reader *reader;
    pthread_mutex_t reader_lock;
    slot *slots;
    size_t nslots;
    atomic_size_t next;
    atomic_int abort;
    pthread_mutex_t done_lock;
    pthread_cond_t done_cond;
    /* Held by the worker whose frame is heavy (interp_set_heavy) until it
     * is written: one heavy frame at a time bounds the memory of -j N. */
    pthread_mutex_t heavy_lock;
    int nworkers; /* threads asked for: one alone keeps its memory for the next frame */
} job;

typedef struct worker_ctx {
    job *j;
    bool heavy; /* holds j->heavy_lock */
    translator *t;
    void *w; /* the writer's */
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
 * False when the worker cannot go on. */
static bool heavy_leave(worker_ctx *w)
{
    bool ok = true;
    if (w->heavy) {
        if (w->j->nworkers > 1) {
            translator_trim(w->t);
            ok = !w->j->wd->trim || w->j->wd->trim(w->w) == 0;
        }
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

/* Has the writer write the scene to the slot's temporary file. */
static void write_temp(job *j, worker_ctx *w, size_t k, slot *s, outbuf *ob)
{
    const driver_settings *d = j->d;
    char *path = temp_path(d->outdir, k, j->wd->ext);
    if (!path) {
        s->write_errno = ENOMEM;
        return;
    }
    int fd = writer_temp_create(path, &s->tmp_id);
    if (fd < 0) {
        s->write_errno = errno;
        tr_free(path);
        return;
    }
    char fname[NAME_MAX_STEM + 32];
    name_vars nv = {s->frame, s->info.stream, s->info.number, s->frame_name, d->trace};
    name_stem(d->name_pattern, &nv, fname, NAME_MAX_STEM + 1);
    strcat(fname, j->wd->ext);
    writer_frame f = {fname,        d->trace,        s->frame, s->info.stream, s->info.number,
                      s->frame_name, s->incomplete};
    ob->len = 0;
    ob->failed = false;
    ob->user = &fd;
    errno = 0;
    char failed[PATH_MAX] = "";
    int rc = j->wd->frame(w->w, translator_scene(w->t), &f, ob, d->outdir, failed, sizeof failed);
    if (rc != 0 && failed[0]) {
        int fe = errno;
        s->write_failed = tr_realloc(NULL, strlen(failed) + 1);
        if (s->write_failed)
            strcpy(s->write_failed, failed);
        errno = fe;
    }
    int e = errno ? errno : ENOMEM;
    if (close(fd) != 0 && rc == 0) {
        rc = -1;
        e = errno;
    }
    if (rc != 0) {
        s->write_errno = e;
        unlink(path);
        writer_temp_done(s->tmp_id);
        s->tmp_id = -1;
    }
    tr_free(path);
}

/* Builds slot s's scene, applies the look and writes it. */
static void run_slot(job *j, worker_ctx *w, size_t k, slot *s, outbuf *ob)
{
    const driver_settings *d = j->d;
    s->log = tr_realloc(NULL, sizeof *s->log);
    if (s->log)
        diag_clear(s->log);
    frame_result res;
    s->status = translator_build(w->t, s->frame, d->quiet ? NULL : s->log, &res);
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
        s->incomplete = drv_incomplete_text(&res);
        s->damaged = res.nmissing > 0;
    }
    scene *sc = translator_scene_edit(w->t);
    if (s->status == RGL_OK && look_apply(d->look, sc, &s->look_note) != 0)
        s->status = RGL_E_NOMEM;
    if (s->status == RGL_OK && s->log && d->quality_note && scene_needs_quality6(sc)) {
        char prefix[32];
        snprintf(prefix, sizeof prefix, "frame %zu", s->frame);
        diag_add(s->log, DIAG_NOTE_QUALITY, prefix, "%s", diag_kind_name(DIAG_NOTE_QUALITY));
    }
    writer_keep(sc, &s->kept);
    if (s->status == RGL_OK && d->outdir)
        write_temp(j, w, k, s, ob);
}

static void *worker(void *arg)
{
    job *j = arg;
    worker_ctx w = {j, false, translator_create(j->reader, &j->reader_lock), NULL};
    if (w.t) {
        translator_set_heavy(w.t, heavy_enter, &w);
        translator_set_vertex_lighting(w.t, j->d->vertex_lighting);
        translator_set_shadows(w.t, !j->d->look->options.no_shadows);
        translator_set_pov(w.t, j->d->pov);
    }
    w.w = j->wd->create ? j->wd->create(j->wrun) : j->wrun;
    outbuf ob;
    bool ob_ok = outbuf_init(&ob, 1 << 20, writer_fd_flush, NULL) == 0;
    for (;;) {
        size_t k = atomic_fetch_add(&j->next, 1);
        if (k >= j->nslots)
            break;
        slot *s = &j->slots[k];
        if (atomic_load(&j->abort) || !w.t || !w.w || !ob_ok) {
            s->status = RGL_E_NOMEM;
            finish_slot(j, s);
            continue;
        }
        run_slot(j, &w, k, s, &ob);
        if (!heavy_leave(&w)) {
            translator_destroy(w.t);
            w.t = NULL; /* the next slots fail as out of memory */
        }
        finish_slot(j, s);
    }
    outbuf_finish(&ob);
    if (j->wd->destroy)
        j->wd->destroy(w.w);
    translator_destroy(w.t);
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

/* Picks slot k's final name and has the writer put its files in place. */
static void publish(job *j, totals *tot, names *used, size_t k, slot *s)
{
    const driver_settings *d = j->d;
    const char *ext = j->wd->ext;
    /* Stems are at most NAME_MAX_STEM bytes, suffixes at most 32. */
    char stem[NAME_MAX_STEM + 64];
    name_vars nv = {s->frame, s->info.stream, s->info.number, s->frame_name, d->trace};
    name_stem(d->name_pattern, &nv, stem, NAME_MAX_STEM + 1);
    if (name_used(used, stem)) {
        char base[NAME_MAX_STEM + 1];
        size_t bl = strnlen(stem, NAME_MAX_STEM);
        memcpy(base, stem, bl);
        base[bl] = '\0';
        snprintf(stem, sizeof stem, "%s-%05zu", base, s->frame);
        for (int n = 2; name_used(used, stem); n++)
            snprintf(stem, sizeof stem, "%s-%05zu-%d", base, s->frame, n);
        if (!d->quiet)
            drv_say(d, "frame %zu: %s%s is taken by an earlier frame; writing %s%s", s->frame,
                    base, ext, stem, ext);
    }
    name_add(used, stem);
    char *tmp = temp_path(d->outdir, k, ext), *tmp_stem = temp_path(d->outdir, k, NULL);
    char msg[4400] = "";
    int rc = -1;
    if (tmp && tmp_stem) {
        writer_place_info p = {d->outdir, stem, tmp, tmp_stem};
        rc = j->wd->publish(j->wrun, &s->kept, &p, msg, sizeof msg);
    }
    if (rc == 0) {
        tot->written++;
        s->published = writer_join(d->outdir, stem);
    } else {
        if (msg[0])
            drv_say(d, "%s", msg);
        else
            drv_say(d, "frame %zu: out of memory", s->frame);
        tot->status = DRIVER_EXIT_INPUT;
    }
    writer_temp_done(s->tmp_id);
    s->tmp_id = -1;
    tr_free(tmp);
    tr_free(tmp_stem);
}

/* The look's note, once each (look_apply's are static strings). */
static void say_look_note(const driver_settings *d, const slot *s, const char **notes,
                          int *nnotes)
{
    if (!s->look_note || d->quiet)
        return;
    for (int n = 0; n < *nnotes; n++)
        if (notes[n] == s->look_note)
            return;
    if (*nnotes < 4) {
        notes[(*nnotes)++] = s->look_note;
        drv_say(d, "frame %zu: %s", s->frame, s->look_note);
    }
}

/* What the main thread does with slot k once its worker is done. *fatal:
 * the output folder is unusable; later frames are dropped. */
static void take_slot(job *j, totals *tot, names *used, size_t k, bool *fatal)
{
    const driver_settings *d = j->d;
    slot *s = &j->slots[k];
    if (*fatal) {
        /* Already stopped: drop what the workers still made. */
    } else if (s->status != RGL_OK) {
        char where[64];
        snprintf(where, sizeof where, "frame %zu (not written)", s->frame);
        if (s->status == RGL_E_NOMEM && atomic_load(&j->abort) == 0)
            drv_say(d, "frame %zu: out of memory", s->frame);
        else if (s->status != RGL_E_NOMEM)
            drv_say_decode_error(d, where, &s->error);
        tot->status = DRIVER_EXIT_INPUT;
    } else if (s->write_errno) {
        char *tmp = s->write_failed ? NULL : temp_path(d->outdir, k, j->wd->ext);
        drv_clear_progress();
        fprintf(stderr, "%s: %s: cannot write: %s\n", d->prog,
                s->write_failed ? s->write_failed : tmp ? tmp : d->outdir,
                strerror(s->write_errno));
        tr_free(tmp);
        tot->status = DRIVER_EXIT_INPUT;
        /* The folder is unusable (full, read-only): stop here. */
        *fatal = true;
        atomic_store(&j->abort, 1);
    } else {
        publish(j, tot, used, k, s);
        drv_say_incomplete(d, tot, s);
        drv_say_budget(d, s);
    }
    if (*fatal && s->status == RGL_OK && !s->write_errno) {
        char *tmp = temp_path(d->outdir, k, j->wd->ext);
        if (tmp)
            unlink(tmp);
        tr_free(tmp);
        writer_temp_done(s->tmp_id);
        s->tmp_id = -1;
    }
}

/* Takes the slots in frame order as the workers finish them. Returns
 * whether the run stopped for an unusable output folder. */
static bool take_slots(job *j, totals *tot)
{
    const driver_settings *d = j->d;
    names used;
    memset(&used, 0, sizeof used);
    bool fatal = false;
    const char *notes[4];
    int nnotes = 0;
    unrec_table unrec; /* the whole trace's, reported once at the end */
    unrec_init(&unrec);
    for (size_t k = 0; k < j->nslots; k++) {
        slot *s = &j->slots[k];
        pthread_mutex_lock(&j->done_lock);
        while (!atomic_load(&s->done))
            pthread_cond_wait(&j->done_cond, &j->done_lock);
        pthread_mutex_unlock(&j->done_lock);

        if (s->log)
            drv_print_diags(d, tot, s->log);
        say_look_note(d, s, notes, &nnotes);
        take_slot(j, tot, &used, k, &fatal);
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
        drv_progress(d, k + 1, j->nslots);
    }
    for (size_t i = 0; i < used.n; i++)
        tr_free(used.v[i]);
    tr_free(used.v);
    drv_clear_progress();
    if (!d->quiet)
        unrec_report(&unrec, d->verbose ? UNREC_REPORT_VERBOSE : UNREC_REPORT_MATTERS,
                     drv_say_line, (void *)d);
    unrec_finish(&unrec);
    return fatal;
}

/* Renders the frames written, in frame order; a failed translation still
 * leaves the others to render (and the exit status says so). */
static void render_written(job *j, totals *tot)
{
    const driver_settings *d = j->d;
    char **stems = tr_realloc(NULL, (j->nslots ? j->nslots : 1) * sizeof *stems);
    size_t n = 0;
    for (size_t k = 0; stems && k < j->nslots; k++)
        if (j->slots[k].published)
            stems[n++] = j->slots[k].published;
    if (!stems) {
        drv_say(d, "out of memory");
        tot->status = DRIVER_EXIT_INPUT;
    } else {
        render_job rj = {d->render, d->prog, d->outdir, stems, n, d->jobs, d->quiet};
        if (render_run(&rj) != 0)
            tot->status = DRIVER_EXIT_INPUT;
    }
    tr_free(stems);
}

/* The selected frames, or -1 after saying why none can be. */
static long select_frames(const driver_settings *d, size_t nframes)
{
    for (size_t r = 0; r < d->nranges; r++) {
        uint64_t bad = d->ranges[r].first >= nframes ? d->ranges[r].first
                       : d->ranges[r].last != UINT64_MAX && d->ranges[r].last >= nframes
                           ? d->ranges[r].last
                           : UINT64_MAX;
        if (bad != UINT64_MAX) {
            if (nframes)
                drv_say(d, "--frames: frame %" PRIu64 " is outside the trace (frames 0-%zu)", bad,
                        nframes - 1);
            else
                drv_say(d, "--frames: frame %" PRIu64 " is outside the trace (no frames)", bad);
            return -1;
        }
    }
    long n = 0;
    for (size_t i = 0; i < nframes; i++)
        n += frames_selected(d->ranges, d->nranges, i);
    if (n == 0) {
        if (d->nranges)
            drv_say(d, "--frames selects none of the %zu frames", nframes);
        else
            drv_say(d, "no frames to translate");
        return -1;
    }
    return n;
}

/* The output folder and the writer's run: false after saying why not. */
static bool start_output(job *j)
{
    const driver_settings *d = j->d;
    if (mkdirs(d->outdir, NULL) != 0) {
        fprintf(stderr, "%s: %s: cannot create the output folder: %s\n", d->prog, d->outdir,
                strerror(errno));
        return false;
    }
    const look_settings *l = d->look;
    writer_trace wt = {d->outdir, d->trace, l->includes, l->nincludes};
    const char *note = NULL;
    char msg[600];
    j->wrun = j->wd->begin(&wt, &note, msg, sizeof msg);
    if (!j->wrun) {
        fprintf(stderr, "%s: %s\n", d->prog, msg);
        return false;
    }
    if (note && !d->quiet)
        drv_say(d, "%s", note);
    return true;
}

/* Translates the selected frames into d->outdir (and renders them). */
static int translate(const driver_settings *d, rgl_reader *reader, totals *tot)
{
    size_t nframes = rgl_reader_frame_count(reader);
    job j;
    memset(&j, 0, sizeof j);
    j.d = d;
    j.wd = d->writer;
    j.reader = reader;
    long nsel = select_frames(d, nframes);
    if (nsel < 0 || !start_output(&j))
        return DRIVER_EXIT_INPUT;
    j.nslots = (size_t)nsel;
    j.slots = tr_realloc(NULL, j.nslots * sizeof *j.slots);
    if (!j.slots) {
        drv_say(d, "out of memory");
        j.wd->end(j.wrun);
        return DRIVER_EXIT_INPUT;
    }
    memset(j.slots, 0, j.nslots * sizeof *j.slots);
    for (size_t i = 0, k = 0; i < nframes; i++)
        if (frames_selected(d->ranges, d->nranges, i)) {
            j.slots[k].tmp_id = -1;
            j.slots[k++].frame = i;
        }
    pthread_mutex_init(&j.reader_lock, NULL);
    pthread_mutex_init(&j.done_lock, NULL);
    pthread_mutex_init(&j.heavy_lock, NULL);
    pthread_cond_init(&j.done_cond, NULL);

    int nthreads = d->jobs < (int)j.nslots ? d->jobs : (int)j.nslots;
    j.nworkers = nthreads;
    pthread_t threads[DRIVER_MAX_JOBS];
    int started = 0;
    for (; started < nthreads; started++)
        if (pthread_create(&threads[started], NULL, worker, &j) != 0)
            break;
    if (started == 0)
        worker(&j); /* no thread: do it here */
    bool fatal = take_slots(&j, tot);
    for (int t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    drv_print_summary(d, tot);
    if (render_wanted(d->render) && !fatal)
        render_written(&j, tot);
    for (size_t k = 0; k < j.nslots; k++)
        tr_free(j.slots[k].published);
    tr_free(j.slots);
    j.wd->end(j.wrun);
    pthread_cond_destroy(&j.done_cond);
    pthread_mutex_destroy(&j.done_lock);
    pthread_mutex_destroy(&j.heavy_lock);
    pthread_mutex_destroy(&j.reader_lock);
    return tot->status;
}

/* Opens the trace, saying what cannot be read. NULL: exit status 1. */
static rgl_reader *open_trace(const driver_settings *d, totals *tot)
{
    rgl_reader *reader = NULL;
    rgl_error err;
    memset(&err, 0, sizeof err);
    rgl_status st = rgl_reader_open_file(d->trace, &reader, &err);
    if (st != RGL_OK) {
        struct stat sb;
        if (st == RGL_E_IO && stat(d->trace, &sb) == 0 && S_ISDIR(sb.st_mode))
            drv_say(d, "cannot read: a folder, not a trace (give the .raygl file)");
        else if (st == RGL_E_IO)
            drv_say(d, "cannot read: %s", strerror(errno));
        else
            drv_say_decode_error(d, "", &err);
        return NULL;
    }
    for (size_t i = 0; i < rgl_reader_damage_count(reader); i++) {
        const rgl_error *e = rgl_reader_damage(reader, i);
        drv_say(d, "damaged region @0x%" PRIx64 ": %s%s%s", e->offset, rgl_status_str(e->status),
                e->detail[0] ? ": " : "", e->detail);
        tot->status = DRIVER_EXIT_INPUT;
    }
    /* Not damage: what the recorder wrote before it stopped is whole. */
    if (!rgl_reader_closed(reader, NULL) && !d->quiet)
        drv_say(d, "trace not closed (the recording was killed or the disk filled): %zu "
                "complete frame%s, the frame in progress is lost",
                rgl_reader_frame_count(reader), rgl_reader_frame_count(reader) == 1 ? "" : "s");
    return reader;
}

int driver_run(const driver_settings *d)
{
    totals *tot = tr_realloc(NULL, sizeof *tot);
    if (!tot) {
        fprintf(stderr, "%s: out of memory\n", d->prog);
        return DRIVER_EXIT_INPUT;
    }
    memset(tot, 0, sizeof *tot);
    rgl_reader *reader = open_trace(d, tot);
    int status = DRIVER_EXIT_INPUT;
    if (reader) {
        if (d->dump && drv_dump(d, reader) != 0)
            tot->status = DRIVER_EXIT_INPUT;
        status = d->outdir ? translate(d, reader, tot) : tot->status;
        rgl_reader_destroy(reader);
    }
    tr_free(tot);
    return status;
}
