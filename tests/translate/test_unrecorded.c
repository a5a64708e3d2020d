/* test_unrecorded.c: the tables of calls not recorded (translate/gl/unrec.h)
 * against hostile input: long names, bytes outside the name alphabet, more
 * names than the bound, counts that overflow; the report's order and text. */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "unrec.h"

static char lines[8][160];
static int nlines;

static void keep_line(const char *text, void *user)
{
    (void)user;
    if (nlines < 8)
        snprintf(lines[nlines], sizeof lines[0], "%s", text);
    nlines++;
}

static void add(unrec_table *t, const char *name, uint64_t count, uint64_t frame)
{
    CHECK(unrec_add(t, (const uint8_t *)name, strlen(name), count, frame) == 0);
}

int main(void)
{
    unrec_table f, all;
    unrec_init(&f);
    unrec_init(&all);

    /* One frame: repeated names add up; count 0 is nothing. */
    add(&f, "glMap1f", 2, 0);
    add(&f, "glAccum", 1000, 0);
    add(&f, "glMap1f", 3, 0);
    add(&f, "glBitmap", 0, 0);
    CHECK(f.n == 2);
    CHECK(unrec_merge(&all, &f, 4) == 0);
    unrec_clear(&f);
    add(&f, "glAccum", 204, 0);
    add(&f, "glAccum", UINT64_MAX, 0); /* saturates */
    CHECK(unrec_merge(&all, &f, 9) == 0);
    nlines = 0;
    unrec_report(&all, keep_line, NULL);
    CHECK(nlines == 2);
    CHECK(strcmp(lines[0], "glAccum: 18,446,744,073,709,551,615 calls not recorded, from frame 4") == 0);
    CHECK(strcmp(lines[1], "glMap1f: 5 calls not recorded, from frame 4") == 0);

    /* Hostile names: cut to UNREC_NAME_MAX, bytes outside [A-Za-z0-9_] as '?'. */
    unrec_clear(&all);
    char big[300];
    memset(big, 'x', sizeof big);
    CHECK(unrec_add(&all, (const uint8_t *)big, sizeof big, 1, 0) == 0);
    const uint8_t odd[] = {'g', 'l', 0, '\n', 0xff, '%', 's'};
    CHECK(unrec_add(&all, odd, sizeof odd, 1, 2) == 0);
    CHECK(unrec_add(&all, odd, 0, 1, 3) == 0); /* empty name */
    nlines = 0;
    unrec_report(&all, keep_line, NULL);
    CHECK(nlines == 3);
    CHECK(strcmp(lines[0], ": 1 call not recorded, from frame 3") == 0);
    CHECK(strcmp(lines[1], "gl????s: 1 call not recorded, from frame 2") == 0);
    CHECK(strlen(lines[2]) == UNREC_NAME_MAX + strlen(": 1 call not recorded, from frame 0"));

    /* Past UNREC_MAX_NAMES distinct names: the rest count together. */
    unrec_clear(&all);
    char name[32];
    for (int i = 0; i < UNREC_MAX_NAMES + 10; i++) {
        snprintf(name, sizeof name, "glF%05d", i);
        add(&all, name, 2, (uint64_t)(i < UNREC_MAX_NAMES ? 1 : 7));
    }
    CHECK(all.n == UNREC_MAX_NAMES);
    CHECK(all.other_calls == 20 && all.other_frame == 7);
    nlines = 0;
    unrec_report(&all, keep_line, NULL);
    CHECK(nlines == UNREC_MAX_NAMES + 1);

    unrec_finish(&f);
    unrec_finish(&all);
    if (check_failures)
        fprintf(stderr, "test_unrecorded: %d failure(s)\n", check_failures);
    return check_failures != 0;
}
