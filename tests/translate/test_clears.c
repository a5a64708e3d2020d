/* test_clears.c: clears of the depth and accumulation buffers between
 * draws (interp_dest.c, interp_accum.c), and what they say.
 *
 * A depth clear after draws lets GL's later draws cover earlier ones they
 * lie behind; the scene keeps depth order, so a note says so where a later
 * draw inside the cleared box lies behind an earlier one it overlaps on
 * screen, and nowhere else. The accumulation buffer's passes start from
 * zero in the scene: a clear to another value, one cut by the scissor box,
 * and passes onto a buffer the frame did not clear are noted at the return.
 */
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "tracegen.h"

static void view(seq *s)
{
    CMD(s, Viewport, 0, 0, 100, 100);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD(s, Ortho, 0, 100, 0, 100, -1, 1);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    CMD(s, Enable, GL_DEPTH_TEST);
}

static void quad(seq *s, double x0, double y0, double x1, double y1, double z)
{
    CMD(s, Begin, GL_QUADS);
    CMD(s, Vertex3f, x0, y0, z);
    CMD(s, Vertex3f, x1, y0, z);
    CMD(s, Vertex3f, x1, y1, z);
    CMD(s, Vertex3f, x0, y1, z);
    CMD0(s, End);
}

static void test_depth(void)
{
    /* [case]: the later quad's box and depth (z toward the viewer), the
     * clear's scissor box (width 0: none), whether a note is due. */
    static const struct {
        double later[4], z;
        int box[4];
        bool colour_after, note;
    } cases[] = {
        {{20, 20, 60, 60}, -0.5, {0, 0, 0, 0}, false, true},     /* behind, overlapping */
        {{20, 20, 60, 60}, 0.8, {0, 0, 0, 0}, false, false},     /* in front */
        {{60, 60, 90, 90}, -0.5, {0, 0, 0, 0}, false, false},    /* beside it */
        {{20, 20, 60, 60}, -0.5, {70, 70, 20, 20}, false, false}, /* box elsewhere */
        {{20, 20, 60, 60}, -0.5, {30, 30, 10, 10}, false, true},  /* box over both */
        {{20, 20, 60, 60}, -0.5, {0, 0, 0, 0}, true, false},     /* a colour clear after */
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        view(&s);
        quad(&s, 10, 10, 50, 50, 0.5);
        if (cases[c].box[2]) {
            CMD(&s, Enable, GL_SCISSOR_TEST);
            CMD(&s, Scissor, cases[c].box[0], cases[c].box[1], cases[c].box[2], cases[c].box[3]);
        }
        CMD(&s, Clear, GL_DEPTH_BUFFER_BIT);
        CMD(&s, Disable, GL_SCISSOR_TEST);
        if (cases[c].colour_after)
            CMD(&s, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const double *l = cases[c].later;
        quad(&s, l[0], l[1], l[2], l[3], cases[c].z);
        run(ip, &s);
        interp_end_frame(ip);
        if (count(DIAG_NOTE_DEPTH_CLEAR) != cases[c].note)
            fprintf(stderr, "depth clear case %zu\n", c);
        CHECK_EQ_U(count(DIAG_NOTE_DEPTH_CLEAR), cases[c].note);
        interp_destroy(ip);
    }
    /* A depth clear before anything is drawn: nothing under it. */
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    view(&s);
    CMD(&s, Clear, GL_DEPTH_BUFFER_BIT);
    quad(&s, 10, 10, 50, 50, 0.5);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(count(DIAG_NOTE_DEPTH_CLEAR), 0);
    interp_destroy(ip);
}

static void test_accum(void)
{
    /* 0: cleared to zero, two passes: fine; 1: a scissored clear between
     * the load and the return; 2: a clear value other than zero; 3: passes
     * onto a buffer never cleared; 4: cleared to zero under a scissor box
     * that holds the whole viewport: fine. */
    for (int c = 0; c < 5; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        view(&s);
        if (c == 2)
            CMD(&s, ClearAccum, 0.1, 0.2, 0.3, 0);
        if (c == 4) {
            CMD(&s, Enable, GL_SCISSOR_TEST);
            CMD(&s, Scissor, 0, 0, 100, 100);
        }
        if (c != 3)
            CMD(&s, Clear, GL_ACCUM_BUFFER_BIT);
        quad(&s, 10, 10, 50, 50, 0.5);
        CMD(&s, Accum, c == 1 ? GL_LOAD : GL_ACCUM, 0.5);
        if (c == 1) {
            CMD(&s, Enable, GL_SCISSOR_TEST);
            CMD(&s, Scissor, 20, 20, 10, 10);
            CMD(&s, Clear, GL_ACCUM_BUFFER_BIT);
            CMD(&s, Disable, GL_SCISSOR_TEST);
        }
        CMD(&s, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        quad(&s, 10, 10, 50, 50, 0.5);
        CMD(&s, Accum, GL_ACCUM, 0.5);
        CMD(&s, Accum, GL_RETURN, 1);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_ACCUM_CLEAR), c == 1 || c == 2 || c == 3);
        interp_destroy(ip);
    }
}

int main(void)
{
    scene_init(&sc);
    test_depth();
    test_accum();
    scene_finish(&sc);
    return CHECK_RESULT("test_clears");
}
