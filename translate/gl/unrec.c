/* unrec.c: tables of unrecorded calls (unrec.h). */
#include "unrec.h"

#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "talloc.h"

void unrec_init(unrec_table *t) { memset(t, 0, sizeof *t); }

void unrec_finish(unrec_table *t)
{
    tr_free(t->e);
    unrec_init(t);
}

void unrec_clear(unrec_table *t)
{
    t->n = 0;
    t->other_calls = 0;
    t->other_frame = 0;
}

static uint64_t sat_add(uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

static void add_other(unrec_table *t, uint64_t count, uint64_t frame)
{
    if (t->other_calls == 0 || frame < t->other_frame)
        t->other_frame = frame;
    t->other_calls = sat_add(t->other_calls, count);
}

/* The printable form of a name: [A-Za-z0-9_] kept, anything else '?'. */
static void clean_name(char *out, const uint8_t *name, size_t len)
{
    if (len > UNREC_NAME_MAX)
        len = UNREC_NAME_MAX;
    for (size_t i = 0; i < len; i++) {
        uint8_t c = name[i];
        bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                  c == '_';
        out[i] = ok ? (char)c : '?';
    }
    out[len] = '\0';
}

static int add_clean(unrec_table *t, const char *name, uint64_t count, uint64_t frame)
{
    if (count == 0)
        return 0;
    for (size_t i = 0; i < t->n; i++) {
        if (strcmp(t->e[i].name, name) == 0) {
            t->e[i].count = sat_add(t->e[i].count, count);
            if (frame < t->e[i].first_frame)
                t->e[i].first_frame = frame;
            return 0;
        }
    }
    if (t->n >= UNREC_MAX_NAMES) {
        add_other(t, count, frame);
        return 0;
    }
    if (tr_grow((void **)&t->e, &t->cap, t->n + 1, sizeof *t->e) != 0) {
        add_other(t, count, frame);
        return -1;
    }
    unrec_entry *e = &t->e[t->n++];
    strcpy(e->name, name);
    e->count = count;
    e->first_frame = frame;
    return 0;
}

int unrec_add(unrec_table *t, const uint8_t *name, size_t len, uint64_t count, uint64_t frame)
{
    char clean[UNREC_NAME_MAX + 1];
    clean_name(clean, name, len);
    return add_clean(t, clean, count, frame);
}

int unrec_merge(unrec_table *dst, const unrec_table *src, uint64_t frame)
{
    int rc = 0;
    for (size_t i = 0; i < src->n; i++)
        if (add_clean(dst, src->e[i].name, src->e[i].count, frame) != 0)
            rc = -1;
    if (src->other_calls)
        add_other(dst, src->other_calls, frame);
    return rc;
}

int unrec_copy(unrec_table *dst, const unrec_table *src)
{
    unrec_clear(dst);
    return unrec_merge(dst, src, 0);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(((const unrec_entry *)a)->name, ((const unrec_entry *)b)->name);
}

/* n with a comma every three digits, whatever the locale: 1,204. */
static void group_digits(char *out, uint64_t n)
{
    char digits[24];
    int len = snprintf(digits, sizeof digits, "%" PRIu64, n);
    int k = 0;
    for (int i = 0; i < len; i++) {
        if (i > 0 && (len - i) % 3 == 0)
            out[k++] = ',';
        out[k++] = digits[i];
    }
    out[k] = '\0';
}

void unrec_report(unrec_table *t, void (*line)(const char *text, void *user), void *user)
{
    if (t->n > 1)
        qsort(t->e, t->n, sizeof *t->e, by_name);
    char text[UNREC_NAME_MAX + 96], num[32];
    for (size_t i = 0; i < t->n; i++) {
        group_digits(num, t->e[i].count);
        snprintf(text, sizeof text, "%s: %s call%s not recorded, from frame %" PRIu64,
                 t->e[i].name, num, t->e[i].count == 1 ? "" : "s", t->e[i].first_frame);
        line(text, user);
    }
    if (t->other_calls) {
        group_digits(num, t->other_calls);
        snprintf(text, sizeof text, "%s call%s of other entry points not recorded, from frame %" PRIu64,
                 num, t->other_calls == 1 ? "" : "s", t->other_frame);
        line(text, user);
    }
}
