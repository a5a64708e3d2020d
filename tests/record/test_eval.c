/* test_eval.c: glMap1 and glMap2 record exactly the control points GL
 * reads, against the stub GL (no context). Part of test_entry; see that
 * file.
 *
 * The points sit against a PROT_NONE page: the last value GL reads is the
 * last readable one, so a recorder that reads a whole stride past the last
 * point, or any point of a call GL rejects, faults. The records hold the
 * points packed, u major, in the order GL reads them; calls GL rejects and
 * calls inside glBegin/glEnd are forwarded and not recorded.
 */
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include <GL/gl.h>

#include "check.h"
#include "raygl.h"
#include "recorder.h"
#include "stubgl.h"

void test_eval(const char *dir);

/* Command i of frame f, decoded (valid until the next call). */
static const rgl_cmd *command(rgl_reader *r, size_t f, size_t i)
{
    rgl_frame_info fi;
    rgl_cmd_iter it;
    static rgl_cmd cmd;
    if (rgl_reader_frame(r, f, &fi, NULL) != RGL_OK)
        return NULL;
    rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
    for (size_t k = 0; k <= i; k++)
        if (rgl_cmd_next(&it, &cmd) != RGL_OK)
            return NULL;
    return &cmd;
}

/* The record's points are exactly want[0..n) (floats, or doubles). */
static void expect_points(const rgl_cmd *c, uint32_t op, const double *want, size_t n,
                          bool dbl, const char *what)
{
    if (!CHECKM(c && c->opcode == op, "%s: not the command expected", what))
        return;
    const rgl_arg *b = &c->arg[c->nargs - 1];
    size_t size = dbl ? 8 : 4;
    if (!CHECKM(b->count == n * size, "%s: %u bytes, want %zu", what, b->count, n * size))
        return;
    for (size_t i = 0; i < n; i++) {
        double got = dbl ? rgl_bits_f64(rgl_get_u64(b->bytes + 8 * i))
                         : rgl_bits_f32(rgl_get_u32(b->bytes + 4 * i));
        CHECKM(got == want[i], "%s: point value %zu is %g, want %g", what, i, got, want[i]);
    }
}

void test_eval(const char *dir)
{
    long page = sysconf(_SC_PAGESIZE);
    uint8_t *mem = mmap(NULL, (size_t)page * 2, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                        -1, 0);
    if (!CHECK(mem != MAP_FAILED))
        return;
    CHECK(mprotect(mem + page, (size_t)page, PROT_NONE) == 0);
    uint8_t *guard = mem + page;
    float *pf = (float *)(void *)mem;
    for (size_t i = 0; i < (size_t)page / sizeof(float); i++)
        pf[i] = -1; /* the padding GL skips */

    char path[128];
    snprintf(path, sizeof path, "%s/eval.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);

    /* glMap1f: 3 points of 3 values, 5 floats apart; GL reads 2 * 5 + 3. */
    float *a = (float *)(void *)guard - (2 * 5 + 3);
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 3; c++)
            a[5 * i + c] = (float)(10 * i + c);
    stub_reset();
    rayglMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 5, 3, a);
    CHECK(stub_nlog == 1 && stub_log[0].p[5] == a);

    /* glMap2f, u major in memory (ustride 13, vstride 4), 2 x 3 points of 4. */
    float *b = (float *)(void *)guard - (1 * 13 + 2 * 4 + 4);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            for (int c = 0; c < 4; c++)
                b[13 * i + 4 * j + c] = (float)(100 * i + 10 * j + c);
    rayglMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 13, 2, 2.0f, 3.0f, 4, 3, b);

    /* glMap2f, v major in memory (ustride 2, vstride 7), 3 x 2 points of 2. */
    float *t = (float *)(void *)guard - (2 * 2 + 1 * 7 + 2);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 2; j++)
            for (int c = 0; c < 2; c++)
                t[2 * i + 7 * j + c] = (float)(100 * i + 10 * j + c);
    rayglMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 3, 0.0f, 1.0f, 7, 2, t);

    /* glMap1d: 2 points of 4 doubles, 6 apart. */
    double *d = (double *)(void *)guard - (1 * 6 + 4);
    for (int i = 0; i < 2; i++)
        for (int c = 0; c < 4; c++)
            d[6 * i + c] = 0.5 + 10 * i + c;
    rayglMap1d(GL_MAP1_VERTEX_4, -1.0, 1.0, 6, 2, d);

    /* glMap2d: 1 x 2 normals, vstride exactly 3. */
    double *n = (double *)(void *)guard - 6;
    for (int k = 0; k < 6; k++)
        n[k] = 0.25 * k;
    rayglMap2d(GL_MAP2_NORMAL, 0.0, 1.0, 3, 1, 0.0, 1.0, 3, 2, n);

    /* Calls GL rejects: the pointer is the guard page itself, so reading
     * any of it faults. Each is forwarded. */
    const float *bad = (const float *)(const void *)guard;
    stub_reset();
    rayglMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 0, bad);      /* order 0 */
    rayglMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 31, bad);     /* past GL_MAX_EVAL_ORDER */
    rayglMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 2, 2, bad);      /* stride < 3 */
    rayglMap1f(GL_MAP1_VERTEX_3, 1.0f, 1.0f, 3, 2, bad);      /* u1 == u2 */
    rayglMap1f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, bad);      /* a glMap2 target */
    rayglMap1f(GL_TEXTURE_2D, 0.0f, 1.0f, 3, 2, bad);         /* not a map */
    rayglMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, 0.0f, 0.0f, 6, 2, bad); /* v1 == v2 */
    rayglMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 2, 2, bad); /* vstride < 3 */
    rayglMap2f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, bad); /* a glMap1 target */
    rayglMap2d(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 6, 40, (const double *)bad);
    rayglMap1d(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 2, NULL);
    rayglBegin(GL_POINTS);
    rayglMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 5, 3, a); /* inside glBegin */
    rayglEnd();
    CHECK(stub_nlog == 14);
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (r) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, 0, &fi);
        CHECK(c.clean);
        CHECK(trace_cmds_count(&c, RGL_OP_Map1f) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_Map2f) == 2);
        CHECK(trace_cmds_count(&c, RGL_OP_Map1d) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_Map2d) == 1);
        if (!CHECK(c.count == 8)) /* the five maps, glBegin, glEnd, rayglFrameEnd */
            trace_cmds_print(&c, "eval");
        static const double wa[] = {0, 1, 2, 10, 11, 12, 20, 21, 22};
        expect_points(command(r, 0, 0), RGL_OP_Map1f, wa, 9, false, "glMap1f");
        double wb[24], wt[12], wd[8], wn[6];
        size_t k = 0;
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 3; j++)
                for (int ch = 0; ch < 4; ch++)
                    wb[k++] = 100 * i + 10 * j + ch;
        expect_points(command(r, 0, 1), RGL_OP_Map2f, wb, 24, false, "glMap2f u major");
        k = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 2; j++)
                for (int ch = 0; ch < 2; ch++)
                    wt[k++] = 100 * i + 10 * j + ch;
        expect_points(command(r, 0, 2), RGL_OP_Map2f, wt, 12, false, "glMap2f v major");
        for (int i = 0; i < 2; i++)
            for (int ch = 0; ch < 4; ch++)
                wd[4 * i + ch] = 0.5 + 10 * i + ch;
        expect_points(command(r, 0, 3), RGL_OP_Map1d, wd, 8, true, "glMap1d");
        for (int q = 0; q < 6; q++)
            wn[q] = 0.25 * q;
        expect_points(command(r, 0, 4), RGL_OP_Map2d, wn, 6, true, "glMap2d");
        const rgl_cmd *m2 = command(r, 0, 1);
        if (m2) { /* the strides and orders as the program gave them */
            CHECK(rgl_arg_i(&m2->arg[3], 0) == 13 && rgl_arg_i(&m2->arg[4], 0) == 2);
            CHECK(rgl_arg_i(&m2->arg[7], 0) == 4 && rgl_arg_i(&m2->arg[8], 0) == 3);
            CHECK(rgl_arg_f(&m2->arg[5], 0) == 2.0 && rgl_arg_f(&m2->arg[6], 0) == 3.0);
        }
        trace_cmds_free(&c);
        rgl_reader_destroy(r);
    }
    unlink(path);
    munmap(mem, (size_t)page * 2);
}
