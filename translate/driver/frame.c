/* frame.c: one worker's translation of frames (frame.h).
 *
 * Carried state: each translator keeps, per stream, a state-only
 * interpreter (a "cursor") that has replayed the stream's frames before
 * some position. Frames reach a worker in increasing file order, so a
 * cursor only moves forward and every earlier frame is replayed at most
 * once per worker; a request for an earlier frame rewinds the cursor to the
 * start of the file.
 */
#include "frame.h"

#include "frame_front.h"

#include <stdio.h>
#include <string.h>

#include "interp.h"
#include "talloc.h"

typedef struct cursor {
    uint32_t stream;
    size_t pos; /* frames [0, pos) of the file are replayed */
    interp *ip;
    /* Since the stream's last frame that did not carry state: the first
     * replayed frame whose commands (or snapshot) were cut short by damage,
     * plus one (0: none), and the number of the last frame replayed (-1:
     * none). Frames are numbered from 0 in each stream, so a gap in the
     * numbers is a frame lost to damage. */
    size_t bad;
    int64_t last;
} cursor;

struct translator {
    rgl_reader *reader;
    pthread_mutex_t *lock;
    scene scene;
    interp *ip;
    unsigned budget_shift;
    cursor *cursors;
    size_t ncursors, cap_cursors;
    char name[RGL_STRING_MAX + 1];
};

static rgl_status fetch_resource(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err);

translator *translator_create(rgl_reader *reader, pthread_mutex_t *reader_lock)
{
    translator *t = tr_realloc(NULL, sizeof *t);
    if (!t)
        return NULL;
    memset(t, 0, sizeof *t);
    t->reader = reader;
    t->lock = reader_lock;
    scene_init(&t->scene);
    t->ip = interp_create(&t->scene, NULL);
    if (!t->ip) {
        translator_destroy(t);
        return NULL;
    }
    interp_set_resources(t->ip, fetch_resource, t);
    return t;
}

void translator_set_budget_shift(translator *t, unsigned shift)
{
    t->budget_shift = shift;
    interp_set_budget_shift(t->ip, shift);
    for (size_t k = 0; k < t->ncursors; k++)
        interp_set_budget_shift(t->cursors[k].ip, shift);
}

void translator_set_shadows(translator *t, bool on) { interp_set_shadows(t->ip, on); }
void translator_set_pov(translator *t, bool on) { interp_set_pov(t->ip, on); }

void translator_set_vertex_lighting(translator *t, bool on)
{
    interp_set_vertex_lighting(t->ip, on);
}

void translator_destroy(translator *t)
{
    if (!t)
        return;
    for (size_t i = 0; i < t->ncursors; i++)
        interp_destroy(t->cursors[i].ip);
    tr_free(t->cursors);
    interp_destroy(t->ip);
    scene_finish(&t->scene);
    tr_free(t);
}

const scene *translator_scene(const translator *t) { return &t->scene; }

void translator_trim(translator *t)
{
    scene_finish(&t->scene);
    scene_init(&t->scene);
}

void translator_set_heavy(translator *t, void (*fn)(void *ctx), void *ctx)
{
    interp_set_heavy(t->ip, fn, ctx);
}
scene *translator_scene_edit(translator *t) { return &t->scene; }

static rgl_status get_frame(translator *t, size_t i, rgl_frame_info *fi, rgl_error *err)
{
    if (t->lock)
        pthread_mutex_lock(t->lock);
    rgl_status st = rgl_reader_frame(t->reader, i, fi, err);
    if (t->lock)
        pthread_mutex_unlock(t->lock);
    return st;
}

static rgl_status get_resource(translator *t, uint32_t id, rgl_resource *res, rgl_error *err)
{
    if (t->lock)
        pthread_mutex_lock(t->lock);
    rgl_status st = rgl_reader_resource(t->reader, id, res, err);
    if (t->lock)
        pthread_mutex_unlock(t->lock);
    return st;
}

/* interp_resource_fn over the translator's reader: display-list bodies. */
static rgl_status fetch_resource(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err)
{
    return get_resource(ctx, id, out, err);
}

/* Replays snapshot resource `id` into ip from its current state. */
static rgl_status run_snapshot(translator *t, interp *ip, uint32_t id, rgl_error *err)
{
    rgl_resource res;
    rgl_status st = get_resource(t, id, &res, err);
    if (st != RGL_OK)
        return st;
    if (res.kind != RGL_RES_COMMANDS) {
        memset(err, 0, sizeof *err);
        err->status = RGL_E_RESOURCE;
        err->offset = res.data_offset;
        snprintf(err->detail, sizeof err->detail, "state snapshot #%u is not a command sequence",
                 id);
        return RGL_E_RESOURCE;
    }
    return interp_run(ip, res.data, res.size, res.data_offset, err);
}

/* The state-only interpreter of `stream`, advanced to just before frame i;
 * *bad and *last receive the cursor's (above). */
static interp *carried_state(translator *t, uint32_t stream, size_t i, size_t *bad,
                             int64_t *last)
{
    cursor *c = NULL;
    for (size_t k = 0; k < t->ncursors; k++)
        if (t->cursors[k].stream == stream)
            c = &t->cursors[k];
    if (!c) {
        if (tr_grow((void **)&t->cursors, &t->cap_cursors, t->ncursors + 1, sizeof *c) != 0)
            return NULL;
        c = &t->cursors[t->ncursors];
        memset(c, 0, sizeof *c);
        c->stream = stream;
        c->last = -1;
        if (!(c->ip = interp_create(NULL, NULL)))
            return NULL;
        interp_set_budget_shift(c->ip, t->budget_shift);
        interp_set_resources(c->ip, fetch_resource, t);
        t->ncursors++;
    }
    if (c->pos > i) { /* asked for an earlier frame: start over */
        interp_reset(c->ip);
        c->pos = 0;
        c->bad = 0;
        c->last = -1;
    }
    for (; c->pos < i; c->pos++) {
        rgl_frame_info fi;
        rgl_error err;
        if (get_frame(t, c->pos, &fi, &err) != RGL_OK || fi.stream != stream)
            continue; /* a damaged earlier frame is reported when it is translated */
        interp_begin_frame(c->ip);
        if (!(fi.flags & RGL_FRAME_STATE_CARRIED)) {
            interp_reset(c->ip);
            c->bad = 0; /* a fresh start: nothing earlier counts */
        } else if (fi.number != c->last + 1 && !c->bad) {
            c->bad = c->pos + 1; /* carries from a lost frame */
        }
        c->last = fi.number;
        bool whole = !fi.state || run_snapshot(t, c->ip, fi.state, &err) == RGL_OK;
        whole &= interp_run(c->ip, fi.commands, fi.commands_size, fi.commands_offset, &err) ==
                 RGL_OK;
        interp_end_frame(c->ip);
        if (!whole && !c->bad)
            c->bad = c->pos + 1;
    }
    *bad = c->bad;
    *last = c->last;
    return c->ip;
}

/* The first frame whose drawing frame i shows: i itself, or for a
 * single-buffered frame (ended by glFlush or glFinish) that does not clear
 * the colour buffer, the earliest of the stream's directly preceding
 * single-buffered frames back to the last one that clears it
 * (frame_front.c). A frame with a state snapshot restores GL's state, not
 * the front buffer: the chain goes on through it. *capped: the chain went
 * on past FRONT_MAX_FRAMES; *flushed: frame i ends with glFlush or glFinish
 * (it shows the front buffer: interp_set_shown_front). */
static size_t front_first(translator *t, size_t i, const rgl_frame_info *fi, bool *capped,
                          bool *flushed)
{
    *capped = false;
    front_scan fs = front_scan_frame(fi);
    *flushed = fs.flushed;
    if (!fs.flushed || fs.clears_color)
        return i;
    size_t first = i;
    uint32_t number = fi->number;
    for (size_t k = i; k-- > 0;) {
        if (i - k > FRONT_MAX_FRAMES) {
            *capped = true;
            break;
        }
        rgl_frame_info e;
        rgl_error err;
        if (get_frame(t, k, &e, &err) != RGL_OK)
            break;
        if (e.stream != fi->stream)
            continue;
        front_scan es = front_scan_frame(&e);
        if (e.number + 1 != number || !es.flushed)
            break; /* a lost frame, or one that showed another buffer */
        first = k;
        number = e.number;
        if (es.clears_color)
            break;
    }
    return first;
}

/* Replays the drawing of the stream's frames [first, i) into ip's scene,
 * as the front buffer still shows it. Their calls' errors were said when
 * those frames were translated; their notes hold for this frame too. */
static void front_replay(translator *t, interp *ip, size_t first, size_t i, uint32_t stream,
                         diag_log *log)
{
    diag_log *tmp = log ? tr_realloc(NULL, sizeof *tmp) : NULL;
    if (tmp)
        diag_clear(tmp);
    interp_attach(ip, &t->scene, tmp);
    for (size_t k = first; k < i; k++) {
        rgl_frame_info e;
        rgl_error err;
        if (get_frame(t, k, &e, &err) != RGL_OK || e.stream != stream)
            continue;
        bool whole = !e.state || run_snapshot(t, ip, e.state, &err) == RGL_OK;
        whole &= interp_run(ip, e.commands, e.commands_size, e.commands_offset, &err) == RGL_OK;
        if (!whole) {
            char what[64];
            snprintf(what, sizeof what, "the drawing of frame %zu (damaged)", k);
            interp_missing(ip, what);
        }
    }
    interp_attach(ip, &t->scene, log);
    if (tmp) {
        interp_clear_notes(ip);
        for (int k = DIAG_FIRST_NOTE; k < DIAG_COUNT; k++)
            if (tmp->e[k].count > tmp->e[k].held)
                interp_frame_note(ip, (diag_kind)k);
            else if (tmp->e[k].held)
                interp_frame_note_held(ip, (diag_kind)k, "nor of the earlier frames it shows");
        tr_free(tmp);
    }
}

/* One translation of frame i into the scene; preset: the camera to use
 * (NULL: the first draw's). False when it stopped before the frame's
 * commands (out->status says why). */
static bool build_pass(translator *t, size_t i, diag_log *log, frame_result *out,
                       const mat4 *preset, const int32_t *preset_vp, bool back_cleared,
                       uint32_t epochs, const int32_t *window)
{
    interp *ip = t->ip;
    const rgl_frame_info *fi = &out->info;
    interp_attach(ip, &t->scene, log);
    interp_reset(ip);
    size_t bad = 0;
    int64_t last = -1;
    bool capped = false, flushed = false;
    size_t first = front_first(t, i, fi, &capped, &flushed);
    rgl_frame_info f0 = *fi; /* the first frame shown: its state starts the replay */
    if (first < i && get_frame(t, first, &f0, &out->error) != RGL_OK) {
        first = i;
        f0 = *fi;
    }
    if (f0.flags & RGL_FRAME_STATE_CARRIED) {
        interp *src = carried_state(t, fi->stream, first, &bad, &last);
        if (!src) {
            out->status = RGL_E_NOMEM;
            return false;
        }
        interp_copy_state(ip, src);
    }
    interp_begin_frame(ip);
    interp_set_shown_front(ip, flushed); /* the front buffer, or the back one */
    if (!(fi->flags & RGL_FRAME_LIVE_CONTEXT))
        interp_unrecorded_batch(ip);
    if (preset)
        interp_proj_preset(ip, preset, preset_vp, back_cleared);
    interp_proj_preset_epochs(ip, epochs);
    if (window)
        interp_proj_preset_window(ip, window);
    if (first < i) {
        interp_set_frame(ip, i, NULL);
        front_replay(t, ip, first, i, fi->stream, log);
        if (capped)
            interp_frame_note(ip, DIAG_NOTE_FRONT_BUFFER);
    }
    if (f0.flags & RGL_FRAME_STATE_CARRIED) {
        /* The state comes from the stream's earlier frames: one cut short
         * by damage, or lost to it (a gap in the numbers), leaves this
         * frame without what that one set. */
        char what[DIAG_TEXT] = "";
        if (bad)
            snprintf(what, sizeof what, "the state carried from frame %zu (damaged)", bad - 1);
        else if (f0.number == last + 2)
            snprintf(what, sizeof what,
                     "the state carried from stream %u's frame %lld (lost to damage)",
                     f0.stream, (long long)(last + 1));
        else if (f0.number != last + 1)
            snprintf(what, sizeof what,
                     "the state carried from stream %u's frames %lld-%lld (lost to damage)",
                     f0.stream, (long long)(last + 1), (long long)f0.number - 1);
        if (what[0])
            interp_missing(ip, what);
    }
    if (fi->state) {
        char label[32];
        snprintf(label, sizeof label, "snapshot #%u", fi->state);
        interp_set_frame(ip, i, label);
        out->status = run_snapshot(t, ip, fi->state, &out->error);
        if (out->status != RGL_OK)
            return false;
    }
    interp_set_frame(ip, i, NULL);
    out->status = interp_run(ip, fi->commands, fi->commands_size, fi->commands_offset,
                             &out->error);
    interp_end_frame(ip);
    return true;
}

rgl_status translator_build(translator *t, size_t i, diag_log *log, frame_result *out)
{
    interp *ip = t->ip;
    memset(out, 0, sizeof *out);
    out->status = get_frame(t, i, &out->info, &out->error);
    if (out->status != RGL_OK)
        return out->status;
    if (!build_pass(t, i, log, out, NULL, NULL, false, 0, NULL))
        return out->status;
    /* A frame of several projections whose first draw was not the 3D
     * scene's: once more with the 3D scene's camera; a frame with
     * depth-only clears between draws: once more with their count; a
     * frame of several viewports: once more with the window they make
     * (interp_proj.c). */
    mat4 proj;
    int32_t vp[4], win[4];
    bool back_cleared = false;
    if (out->status == RGL_OK && !t->scene.failed) {
        bool chosen = interp_proj_choice(ip, &proj, vp, &back_cleared);
        uint32_t epochs = interp_proj_depth_epochs(ip, chosen ? &proj : NULL, chosen ? vp : NULL);
        bool widen = interp_proj_window(ip, win);
        if (chosen || epochs || widen) {
            if (log)
                diag_clear(log);
            if (!build_pass(t, i, log, out, chosen ? &proj : NULL, chosen ? vp : NULL,
                            back_cleared, epochs, widen ? win : NULL))
                return out->status;
        }
    }
    out->unrecorded = interp_unrecorded(ip);
    interp_budget_used(ip, &out->used, &out->limit);
    const char *cut = interp_frame_cut(ip);
    if (cut)
        snprintf(out->cut, sizeof out->cut, "%s", cut);
    const char *missing = interp_frame_missing(ip, &out->nmissing);
    if (missing)
        snprintf(out->missing, sizeof out->missing, "%s", missing);
    const char *name = interp_frame_name(ip);
    if (name) {
        snprintf(t->name, sizeof t->name, "%s", name);
        out->frame_name = t->name;
    }
    if (out->status == RGL_OK && t->scene.failed)
        out->status = RGL_E_NOMEM;
    return out->status;
}
