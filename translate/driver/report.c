/* report.c: the driver's messages (driver_internal.h): one line each, on
 * stderr, prefixed "PROG: TRACE: ", in frame order; a progress line on a
 * terminal.
 */
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "driver_internal.h"
#include "talloc.h"

static bool progress_shown;

bool drv_clear_progress(void)
{
    bool was = progress_shown;
    if (progress_shown) {
        fputs("\r\033[K", stderr);
        progress_shown = false;
    }
    return was;
}

void drv_say(const driver_settings *d, const char *fmt, ...)
{
    va_list ap;
    drv_clear_progress();
    fprintf(stderr, "%s: %s: ", d->prog, d->trace);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

void drv_say_line(const char *text, void *user) { drv_say(user, "%s", text); }

void drv_say_decode_error(const driver_settings *d, const char *where, const rgl_error *e)
{
    const rgl_cmd_info *info = e->opcode ? rgl_cmd_info_get(e->opcode) : NULL;
    char cmdpart[96] = "";
    if (info)
        snprintf(cmdpart, sizeof cmdpart, ", cmd %" PRIu64 " (%s)", e->cmd_index, info->name);
    const char *st = rgl_status_str(e->status);
    bool detail = e->detail[0] && strcmp(e->detail, st) != 0;
    drv_say(d, "%s%s%s@0x%" PRIx64 ": %s%s%s", where, cmdpart, *where || *cmdpart ? " " : "",
            e->offset, st, detail ? ": " : "", detail ? e->detail : "");
}

char *drv_incomplete_text(const frame_result *res)
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

void drv_print_diags(const driver_settings *d, totals *tot, const diag_log *log)
{
    for (int k = 0; k < DIAG_COUNT; k++) {
        const diag_entry *e = &log->e[k];
        tot->log.e[k].count += e->count;
        tot->log.e[k].dropped += e->dropped;
        tot->log.e[k].held += e->held;
        bool note = diag_is_note((diag_kind)k);
        for (uint32_t m = 0; m < e->kept; m++) {
            if (note && diag_is_held(e, m)) {
                if (!d->verbose || tot->printed_held[k] >= 1)
                    continue;
                tot->printed_held[k]++;
            } else {
                if (tot->printed[k] >= (note ? 1u : DIAG_KEEP))
                    continue;
                tot->printed[k]++;
            }
            drv_say(d, "%s", e->text[m]);
        }
    }
}

/* The cut is a note (the frame is what the budget allows); a part lost
 * to damage is damage (raygl2pov(1), "Damage"). */
void drv_say_incomplete(const driver_settings *d, totals *tot, const slot *s)
{
    if (!s->published)
        return;
    if (s->damaged && !s->incomplete)
        drv_say(d, "frame %zu: written without a part lost to damage", s->frame);
    for (const char *p = s->incomplete; p && *p; p += *p == '\n') {
        const char *nl = strchr(p, '\n');
        int len = nl ? (int)(nl - p) : (int)strlen(p);
        bool cut = strncmp(p, "cut ", 4) == 0;
        if (!cut || !d->quiet)
            drv_say(d, "frame %zu: %.*s", s->frame, len, p);
        p += len;
    }
    if (s->damaged)
        tot->status = DRIVER_EXIT_INPUT;
}

/* docs/mapping.md "Bounds". */
void drv_say_budget(const driver_settings *d, const slot *s)
{
    if (!d->dump)
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

void drv_progress(const driver_settings *d, size_t done, size_t total)
{
    if (d->quiet || total < 2 || !isatty(STDERR_FILENO))
        return;
    fprintf(stderr, "\r%s: %zu of %zu frames", d->prog, done, total);
    progress_shown = true;
}

void drv_print_summary(const driver_settings *d, const totals *tot)
{
    if (d->quiet)
        return;
    for (int k = 0; k < DIAG_FIRST_NOTE; k++) {
        uint64_t n = tot->log.e[k].count;
        if (n > tot->printed[k])
            drv_say(d, "%" PRIu64 " calls skipped in all (%s), %" PRIu64 " shown", n,
                    diag_kind_name((diag_kind)k), tot->printed[k]);
    }
    /* --verbose: how often each note was said and held, frames counted
     * once each (a frame logs a note at most once either way). */
    for (int k = DIAG_FIRST_NOTE; d->verbose && k < DIAG_COUNT; k++) {
        const diag_entry *e = &tot->log.e[k];
        if (e->held)
            drv_say(d, "note held in %" PRIu64 " frame%s where it cannot change a pixel, said in %"
                    PRIu64 ": %s", e->held, e->held == 1 ? "" : "s", e->count - e->held,
                    diag_kind_name((diag_kind)k));
    }
    for (int k = 0; k < DIAG_COUNT; k++)
        if (tot->log.e[k].dropped)
            drv_say(d, "%" PRIu64 " message%s (%s) left out whole: longer than %d characters",
                    tot->log.e[k].dropped, tot->log.e[k].dropped > 1 ? "s" : "",
                    diag_kind_name((diag_kind)k), DIAG_TEXT - 1);
}
