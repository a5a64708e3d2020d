/* test_proj.c: issue 14's projections, depth and draw order, and notes.
 *
 * Notes kept whole (never cut mid-word, a message too long to keep left
 * out whole and counted).
 */
#include <GL/gl.h>
#include <string.h>

#include "check.h"
#include "diag.h"
#include "interp.h"
#include "interp_internal.h"
#include "scenes.h"
#include "tracegen.h"

static scene sc;
static diag_log dlog;

static bool ends_with(const char *s, const char *tail)
{
    size_t a = strlen(s), b = strlen(tail);
    return a >= b && strcmp(s + a - b, tail) == 0;
}

/* Every note, after the longest prefix a frame label allows, is kept whole. */
static void test_notes_whole(void)
{
    scene_reset(&sc);
    diag_clear(&dlog);
    interp *ip = interp_create(&sc, &dlog);
    interp_begin_frame(ip);
    memset(ip->label, 'x', sizeof ip->label - 1);
    ip->label[sizeof ip->label - 1] = '\0';
    ip->frame_index = UINT64_MAX;
    for (int k = DIAG_FIRST_NOTE; k < DIAG_COUNT; k++) {
        interp_note(ip, (diag_kind)k);
        CHECK_EQ_U(dlog.e[k].kept, 1);
        CHECK(ends_with(dlog.e[k].text[0], diag_kind_name((diag_kind)k)));
        CHECK(strstr(dlog.e[k].text[0], ip->label) != NULL);
        CHECK_EQ_U(dlog.e[k].dropped, 0);
    }
    interp_destroy(ip);
}

/* A message longer than DIAG_TEXT (a hostile trace's text) is counted and
 * left out whole, never kept cut; shorter ones are still kept after it. */
static void test_long_message_dropped(void)
{
    static char big[5000];
    memset(big, 'y', sizeof big - 1);
    diag_clear(&dlog);
    diag_add(&dlog, DIAG_IGNORED, "frame 1", "%s", big);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].count, 1);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].kept, 0);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].dropped, 1);
    diag_add(&dlog, DIAG_IGNORED, "frame 1", "%s", "short");
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].kept, 1);
    CHECK(strcmp(dlog.e[DIAG_IGNORED].text[0], "frame 1: short") == 0);

    /* The interpreter's own formatting: the same rule. */
    scene_reset(&sc);
    diag_clear(&dlog);
    interp *ip = interp_create(&sc, &dlog);
    interp_begin_frame(ip);
    interp_diag(ip, DIAG_IGNORED, "%s", big);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].count, 1);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].kept, 0);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].dropped, 1);
    diag_log sum;
    diag_clear(&sum);
    diag_merge(&sum, &dlog);
    CHECK_EQ_U(sum.e[DIAG_IGNORED].dropped, 1);
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    test_notes_whole();
    test_long_message_dropped();
    scene_finish(&sc);
    return CHECK_RESULT("test_proj");
}
