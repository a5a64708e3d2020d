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
    char *t = e->text[e->kept++];
    int n = snprintf(t, DIAG_TEXT, "%s%s", prefix ? prefix : "", prefix && *prefix ? ": " : "");
    if (n < 0 || n >= DIAG_TEXT)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(t + n, DIAG_TEXT - (size_t)n, fmt, ap);
    va_end(ap);
}

void diag_merge(diag_log *dst, const diag_log *src)
{
    for (int k = 0; k < DIAG_COUNT; k++) {
        diag_entry *d = &dst->e[k];
        const diag_entry *s = &src->e[k];
        d->count += s->count;
        for (uint32_t i = 0; i < s->kept && d->kept < DIAG_KEEP; i++)
            memcpy(d->text[d->kept++], s->text[i], DIAG_TEXT);
    }
}

uint64_t diag_error_total(const diag_log *log)
{
    uint64_t n = 0;
    for (int k = 0; k < DIAG_FIRST_NOTE; k++)
        n += log->e[k].count;
    return n;
}
