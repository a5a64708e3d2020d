/* test_unrecorded.c: the tables of calls not recorded (translate/gl/unrec.h)
 * against hostile input: long names, bytes outside the name alphabet, more
 * names than the bound, counts that overflow; the report's order and text;
 * what each name can change (format/unrecorded.def): a name reported only
 * from the frame on whose uses its effect needs, all of them with verbose. */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "unrec.h"

static char lines[8][1024];
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

/* Merges a frame naming `name` (count 1, or none for NULL) with uses `uses`. */
static void frame_with(unrec_table *all, const char *name, uint32_t uses, uint64_t frame)
{
    unrec_table f;
    unrec_init(&f);
    if (name)
        add(&f, name, 1, frame);
    f.uses = uses;
    CHECK(unrec_merge(all, &f, frame) == 0);
    unrec_finish(&f);
}

static bool line_is(int i, const char *want)
{
    if (i < nlines && strcmp(lines[i], want) == 0)
        return true;
    fprintf(stderr, "line %d: got '%s'\n      want '%s'\n", i, i < nlines ? lines[i] : "", want);
    return false;
}

#define USE(u) (1u << UNREC_USE_##u)

static void test_effects(void)
{
    /* Every row's effect: the window system changes nothing, stroke text
     * always can, a compressed texture image needs textured draws. */
    const unrec_effect *w = unrec_effect_of("glutInit"), *st = unrec_effect_of("glutStrokeCharacter");
    const unrec_effect *bc = unrec_effect_of("glCompressedTexImage2D"), *ps = unrec_effect_of("glPixelStoref");
    CHECK(w && w->never);
    CHECK(st && !st->never && st->needs == 0);
    CHECK(bc && !bc->never && bc->needs == USE(TEXTURE));
    CHECK(ps && ps->needs == (USE(IMAGES) | USE(BATCH)));
    CHECK(unrec_effect_of("glBegin") == NULL);   /* recorded */
    CHECK(unrec_effect_of("glutInitX") == NULL); /* not a name */
    CHECK(strcmp(unrec_use_text(UNREC_USE_BLEND), "blended draws") == 0);
    CHECK(strcmp(unrec_use_text(UNREC_USE_COUNT), "") == 0);

    unrec_table all;
    unrec_init(&all);
    frame_with(&all, "glutInit", ~0u, 0);      /* never, whatever the frame has */
    frame_with(&all, "glCompressedTexImage2D", 0, 1);    /* no use in frame 1 */
    frame_with(&all, "glPixelStoref", USE(IMAGES), 1);
    frame_with(&all, "glReadBuffer", 0, 2);
    frame_with(&all, "glutStrokeCharacter", 0, 2);
    frame_with(&all, "glBlendFuncSeparateINGR", 0, 3);
    frame_with(&all, NULL, USE(READ) | USE(BATCH), 3); /* uses, no call: glReadBuffer matters */
    frame_with(&all, NULL, USE(BLEND), 4);             /* not glCompressedTexImage2D's use */
    nlines = 0;
    unrec_report(&all, UNREC_REPORT_MATTERS, keep_line, NULL);
    CHECK(nlines == 3);
    CHECK(line_is(0, "glBlendFuncSeparateINGR: 1 call not recorded, from frame 3: separate colour "
                     "and alpha blending: blended draws use glBlendFunc's factors and "
                     "glBlendEquation's equation"));
    CHECK(line_is(1, "glReadBuffer: 1 call not recorded, from frame 2: the colour buffer "
                     "glAccum reads is taken as the default (copies read back hold what they "
                     "read)"));
    CHECK(line_is(2, "glutStrokeCharacter: 1 call not recorded, from frame 2: the stroke text is "
                     "missing (raygl record, which sees freeglut's own calls, records it)"));

    /* Verbose: the rest too, each saying why it cannot change the picture;
     * glPixelStoref needs both its uses in one frame, which none had. */
    nlines = 0;
    unrec_report(&all, UNREC_REPORT_VERBOSE, keep_line, NULL);
    CHECK(nlines == 6);
    CHECK(line_is(1, "glCompressedTexImage2D: 1 call not recorded, from frame 1 (cannot change "
                     "the picture: it acts only on textured draws, which no frame from it on "
                     "has): compressed texture images: the textures they fill are drawn without "
                     "them"));
    CHECK(strstr(lines[2], "glPixelStoref: 1 call not recorded, from frame 1 (cannot change the "
                           "picture: it acts only on images read from the program's memory "
                           "(textures, pixels, bitmaps, stipples) in frames recorded without a GL "
                           "context, which no frame from it on has)") == lines[2]);
    CHECK(line_is(4, "glutInit: 1 call not recorded, from frame 0 (cannot change the picture: "
                     "the window system (windows, menus, input, callbacks, the main loop))"));

    /* A use in an earlier frame than the call does not count; once it
     * matters, it stays so. */
    unrec_clear(&all);
    frame_with(&all, NULL, USE(TEXTURE), 0);
    frame_with(&all, "glCompressedTexImage2D", 0, 1);
    CHECK(all.n == 1 && !all.e[0].matters);
    frame_with(&all, "glCompressedTexImage2D", USE(TEXTURE), 2);
    frame_with(&all, NULL, 0, 3);
    CHECK(all.e[0].matters && all.e[0].first_frame == 1 && all.e[0].count == 2);

    /* --dump: no frame translated, each by what its effect needs. */
    nlines = 0;
    unrec_report(&all, UNREC_REPORT_DUMP, keep_line, NULL);
    CHECK(line_is(0, "glCompressedTexImage2D: 2 calls not recorded, from frame 1 (changes the "
                     "picture only with textured draws): compressed texture images: the textures "
                     "they fill are drawn without them"));

    /* A copy keeps the frame's uses. */
    unrec_table f, c;
    unrec_init(&f);
    unrec_init(&c);
    f.uses = USE(POINTS);
    CHECK(unrec_copy(&c, &f) == 0 && c.uses == USE(POINTS));
    unrec_clear(&c);
    CHECK(c.uses == 0);
    unrec_finish(&f);
    unrec_finish(&c);
    unrec_finish(&all);
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
    unrec_report(&all, UNREC_REPORT_MATTERS, keep_line, NULL);
    CHECK(nlines == 2);
    /* Names the table does not hold (recorded now, or unknown): always
     * reported, as missing. */
    CHECK(strcmp(lines[0], "glAccum: 18,446,744,073,709,551,615 calls not recorded, from frame 4: "
                           "what it does is missing from the trace") == 0);
    CHECK(strcmp(lines[1], "glMap1f: 5 calls not recorded, from frame 4: what it does is "
                           "missing from the trace") == 0);

    /* Hostile names: cut to UNREC_NAME_MAX, bytes outside [A-Za-z0-9_] as '?'. */
    unrec_clear(&all);
    char big[300];
    memset(big, 'x', sizeof big);
    CHECK(unrec_add(&all, (const uint8_t *)big, sizeof big, 1, 0) == 0);
    const uint8_t odd[] = {'g', 'l', 0, '\n', 0xff, '%', 's'};
    CHECK(unrec_add(&all, odd, sizeof odd, 1, 2) == 0);
    CHECK(unrec_add(&all, odd, 0, 1, 3) == 0); /* empty name */
    nlines = 0;
    unrec_report(&all, UNREC_REPORT_MATTERS, keep_line, NULL);
    CHECK(nlines == 3);
    CHECK(strcmp(lines[0], ": 1 call not recorded, from frame 3: what it does is missing from "
                           "the trace") == 0);
    CHECK(strcmp(lines[1], "gl????s: 1 call not recorded, from frame 2: what it does is missing "
                           "from the trace") == 0);
    CHECK(strlen(lines[2]) == UNREC_NAME_MAX + strlen(": 1 call not recorded, from frame 0: what "
                                                      "it does is missing from the trace"));

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
    unrec_report(&all, UNREC_REPORT_MATTERS, keep_line, NULL);
    CHECK(nlines == UNREC_MAX_NAMES + 1);

    test_effects();
    unrec_finish(&f);
    unrec_finish(&all);
    if (check_failures)
        fprintf(stderr, "test_unrecorded: %d failure(s)\n", check_failures);
    return check_failures != 0;
}
