/* diag.c: the diagnostics log (see diag.h). */
#include "diag.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static const char *const kind_names[DIAG_COUNT] = {
#define DIAG_NAME_(name, text) text,
    DIAG_KINDS(DIAG_NAME_)
#undef DIAG_NAME_
};

/* Every note fits whole after the longest prefix and ": ", held notes with
 * the mark, the longest reason and ")". */
#define DIAG_FITS_(name, text)                                                                   \
    _Static_assert(sizeof(text) + DIAG_PREFIX + 2 + sizeof DIAG_HELD_MARK + DIAG_WHY + 1 <=       \
                       DIAG_TEXT,                                                                \
                   "DIAG_TEXT too short for " #name);
DIAG_KINDS(DIAG_FITS_)
#undef DIAG_FITS_

void diag_clear(diag_log *log) { memset(log, 0, sizeof *log); }

const char *diag_kind_name(diag_kind kind)
{
    return (unsigned)kind < DIAG_COUNT ? kind_names[kind] : "unknown";
}

bool diag_is_note(diag_kind kind) { return kind >= DIAG_FIRST_NOTE && kind < DIAG_COUNT; }

void diag_add(diag_log *log, diag_kind kind, const char *prefix, const char *fmt, ...)
{
    if (!log || (unsigned)kind >= DIAG_COUNT)
        return;
    diag_entry *e = &log->e[kind];
    e->count++;
    if (e->kept >= DIAG_KEEP)
        return;
    char *t = e->text[e->kept];
    int n = snprintf(t, DIAG_TEXT, "%s%s", prefix ? prefix : "", prefix && *prefix ? ": " : "");
    int m = -1;
    if (n >= 0 && n < DIAG_TEXT) {
        va_list ap;
        va_start(ap, fmt);
        m = vsnprintf(t + n, DIAG_TEXT - (size_t)n, fmt, ap);
        va_end(ap);
    }
    if (m < 0 || m >= DIAG_TEXT - n) {
        e->dropped++; /* whole or not at all */
        t[0] = '\0';
        return;
    }
    e->kept++;
}

void diag_add_held(diag_log *log, diag_kind kind, const char *prefix, const char *why)
{
    if (!log || !diag_is_note(kind))
        return;
    diag_entry *e = &log->e[kind];
    uint32_t m = e->kept;
    diag_add(log, kind, prefix, "%s" DIAG_HELD_MARK "%.*s)", kind_names[kind], DIAG_WHY - 1,
             why ? why : "");
    e->held++;
    if (e->kept > m)
        e->held_kept |= 1u << m;
}

void diag_drop(diag_log *log, diag_kind kind)
{
    if (!log || (unsigned)kind >= DIAG_COUNT)
        return;
    log->e[kind].count++;
    log->e[kind].dropped++;
}

void diag_merge(diag_log *dst, const diag_log *src)
{
    for (int k = 0; k < DIAG_COUNT; k++) {
        diag_entry *d = &dst->e[k];
        const diag_entry *s = &src->e[k];
        d->count += s->count;
        d->dropped += s->dropped;
        d->held += s->held;
        for (uint32_t i = 0; i < s->kept && d->kept < DIAG_KEEP; i++) {
            if (diag_is_held(s, i))
                d->held_kept |= 1u << d->kept;
            memcpy(d->text[d->kept++], s->text[i], DIAG_TEXT);
        }
    }
}
