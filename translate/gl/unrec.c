/* unrec.c: tables of unrecorded calls and what each can change
 * (unrec.h, format/unrecorded.def). */
#include "unrec.h"

#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "talloc.h"

/* ---- format/unrecorded.def -------------------------------------------------------------- */

static const char *const use_texts[UNREC_USE_COUNT] = {
#define UNREC_USE(id, text) text,
#include "unrecorded.def"
};

enum {
#define UNREC_EFFECT(id, needs, seen, text) EFFECT_##id,
#include "unrecorded.def"
    EFFECT_COUNT
};

#define UNREC_NEED(u) (1u << UNREC_USE_##u)
#define UNREC_ALWAYS 0u
#define UNREC_NEVER_ 0x80000000u /* never is no set of uses */
#define UNREC_NEVER UNREC_NEVER_
_Static_assert(UNREC_USE_COUNT < 31, "unrec_effect.needs has room for 31 uses");

static const unrec_effect effects[EFFECT_COUNT] = {
#define UNREC_EFFECT(id, needs_, seen, text_) \
    {.needs = (needs_) & ~UNREC_NEVER_, .never = ((needs_) & UNREC_NEVER_) != 0, .text = text_},
#include "unrecorded.def"
};

typedef struct unrec_row {
    const char *name;
    uint8_t effect;
} unrec_row;

static const unrec_row rows[] = {
#define UNREC(name, effect, state) {#name, EFFECT_##effect},
#include "unrecorded.def"
};

static int row_cmp(const void *key, const void *row)
{
    return strcmp((const char *)key, ((const unrec_row *)row)->name);
}

const unrec_effect *unrec_effect_of(const char *name)
{
    /* The rows are in strcmp order: tools/gen_unrecorded.py fails the
     * build otherwise. */
    const unrec_row *r = bsearch(name, rows, sizeof rows / sizeof rows[0], sizeof rows[0], row_cmp);
    return r ? &effects[r->effect] : NULL;
}

const char *unrec_use_text(unrec_use u)
{
    return (unsigned)u < UNREC_USE_COUNT ? use_texts[u] : "";
}

/* Whether a frame of these uses lets the call named `name` change it. */
static bool matters_with(const char *name, uint32_t uses)
{
    const unrec_effect *ef = unrec_effect_of(name);
    return !ef || (!ef->never && (ef->needs & uses) == ef->needs);
}

/* ---- Tables ------------------------------------------------------------------------------ */

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
    t->uses = 0;
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
    e->matters = false;
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
    for (size_t i = 0; i < dst->n; i++)
        if (!dst->e[i].matters)
            dst->e[i].matters = matters_with(dst->e[i].name, src->uses);
    return rc;
}

int unrec_copy(unrec_table *dst, const unrec_table *src)
{
    unrec_clear(dst);
    int rc = unrec_merge(dst, src, 0);
    dst->uses = src->uses;
    return rc;
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

/* The uses an effect needs, "A in B", into out. */
static void needs_text(char *out, size_t cap, const unrec_effect *ef)
{
    int n = 0;
    out[0] = '\0';
    for (int u = 0, k = 0; u < UNREC_USE_COUNT && n >= 0 && (size_t)n < cap; u++)
        if (ef->needs & (1u << u))
            n += snprintf(out + n, cap - (size_t)n, "%s%s", k++ ? " in " : "", use_texts[u]);
}

void unrec_report(unrec_table *t, unrec_mode mode, void (*line)(const char *text, void *user),
                  void *user)
{
    if (t->n > 1)
        qsort(t->e, t->n, sizeof *t->e, by_name);
    char text[UNREC_NAME_MAX + 768], num[32], needs[320];
    for (size_t i = 0; i < t->n; i++) {
        const unrec_entry *e = &t->e[i];
        const unrec_effect *ef = unrec_effect_of(e->name);
        bool matters = ef ? (mode == UNREC_REPORT_DUMP ? !ef->never : e->matters) : true;
        if (!matters && mode == UNREC_REPORT_MATTERS)
            continue;
        group_digits(num, e->count);
        int n = snprintf(text, sizeof text, "%s: %s call%s not recorded, from frame %" PRIu64,
                         e->name, num, e->count == 1 ? "" : "s", e->first_frame);
        if (n < 0 || (size_t)n >= sizeof text)
            continue;
        size_t cap = sizeof text - (size_t)n;
        if (ef)
            needs_text(needs, sizeof needs, ef);
        if (!ef)
            snprintf(text + n, cap, ": what it does is missing from the trace");
        else if (ef->never)
            snprintf(text + n, cap, " (cannot change the picture: %s)", ef->text);
        else if (mode == UNREC_REPORT_DUMP && ef->needs)
            snprintf(text + n, cap, " (changes the picture only with %s): %s", needs, ef->text);
        else if (matters)
            snprintf(text + n, cap, ": %s", ef->text);
        else
            snprintf(text + n, cap,
                     " (cannot change the picture: it acts only on %s, which no frame from it "
                     "on has): %s", needs, ef->text);
        line(text, user);
    }
    if (t->other_calls) {
        group_digits(num, t->other_calls);
        snprintf(text, sizeof text, "%s call%s of other entry points not recorded, from frame %" PRIu64,
                 num, t->other_calls == 1 ? "" : "s", t->other_frame);
        line(text, user);
    }
}
