/* test_nurbs_rec.c: the GLU NURBS entry points record exactly the knots
 * and control points GLU reads, against the stub GL. Part of test_entry.
 *
 * The control points end against a PROT_NONE page: a recorder that reads
 * a stride past the last point, or anything of a call GLU rejects, faults.
 * The records hold the points packed, s major; rejected calls are
 * forwarded and not recorded.
 */
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include <GL/gl.h>
#include <GL/glu.h>

#include "check.h"
#include "raygl.h"
#include "recorder.h"
#include "stubgl.h"

void test_nurbs_rec(const char *dir);

static bool blob_is(const rgl_arg *b, const double *want, size_t n)
{
    if (b->kind != RGL_ARG_BLOB || b->count != n * 4)
        return false;
    for (size_t i = 0; i < n; i++)
        if (rgl_bits_f32(rgl_get_u32(b->bytes + 4 * i)) != want[i])
            return false;
    return true;
}

void test_nurbs_rec(const char *dir)
{
    long page = sysconf(_SC_PAGESIZE);
    uint8_t *mem = mmap(NULL, (size_t)page * 2, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                        -1, 0);
    if (!CHECK(mem != MAP_FAILED))
        return;
    CHECK(mprotect(mem + page, (size_t)page, PROT_NONE) == 0);
    float *guard = (float *)(void *)(mem + page);
    for (float *f = (float *)(void *)mem; f < guard; f++)
        *f = -1; /* padding GLU skips */

    char path[128];
    snprintf(path, sizeof path, "%s/nurbs.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    stub_reset();
    GLUnurbs *n = raygluNewNurbsRenderer();
    raygluNurbsProperty(n, GLU_DISPLAY_MODE, GLU_OUTLINE_PATCH);
    raygluBeginSurface(n);
    /* 2 x 3 points of 4 values (orders 2 and 2: 4 and 5 knots); t major in
     * memory: sStride 4, tStride 11; GLU reads up to 1 * 4 + 2 * 11 + 4. */
    float *c = guard - (1 * 4 + 2 * 11 + 4);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 4; k++)
                c[4 * i + 11 * j + k] = (float)(100 * i + 10 * j + k);
    static GLfloat sk[4] = {0, 0, 1, 1}, tk[5] = {0, 0, 0.5f, 1, 1};
    raygluNurbsSurface(n, 4, sk, 5, tk, 4, 11, c, 2, 2, GL_MAP2_VERTEX_4);
    /* A trim: a pwl of 3 points of 3 values, stride 5, ending at the guard. */
    float *p = guard - (2 * 5 + 3);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            p[5 * i + k] = (float)(10 * i + k);
    raygluBeginTrim(n);
    raygluPwlCurve(n, 3, p, 5, GLU_MAP1_TRIM_3);
    raygluEndTrim(n);
    /* Calls GLU rejects: the pointers are the guard page itself. Each is
     * forwarded, none recorded. */
    GLfloat *bad = guard;
    raygluNurbsSurface(n, 4, bad, 4, bad, 3, 6, bad, 0, 2, GL_MAP2_VERTEX_3); /* order 0 */
    raygluNurbsSurface(n, 3, bad, 4, bad, 3, 6, bad, 2, 2, GL_MAP2_VERTEX_3); /* knots < 2 order */
    raygluNurbsSurface(n, 4, bad, 4, bad, 2, 6, bad, 2, 2, GL_MAP2_VERTEX_3); /* stride < 3 */
    raygluNurbsSurface(n, 4, bad, 4, bad, 3, 6, bad, 2, 2, GL_MAP1_VERTEX_3); /* a curve type */
    raygluNurbsCurve(n, 4, bad, 3, bad, 2, GL_MAP2_VERTEX_3);                  /* a surface type */
    raygluPwlCurve(n, 3, bad, 1, GLU_MAP1_TRIM_2);                             /* stride < 2 */
    raygluPwlCurve(n, 3, bad, 2, GL_MAP1_VERTEX_3);                            /* not a trim */
    raygluEndSurface(n);
    raygluDeleteNurbsRenderer(n);
    CHECK(stub_nlog == 16); /* 9 recorded calls, 7 rejected ones */
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (r) {
        rgl_frame_info fi;
        trace_cmds tc = trace_frame(r, 0, &fi);
        CHECK(tc.clean);
        CHECK(trace_cmds_count(&tc, RGL_OP_NurbsSurface) == 1);
        CHECK(trace_cmds_count(&tc, RGL_OP_PwlCurve) == 1);
        CHECK(trace_cmds_count(&tc, RGL_OP_NurbsCurve) == 0);
        CHECK(trace_cmds_find(&tc, 0, "gluNewNurbsRenderer(nurb=#") == 0);
        CHECK(trace_cmds_find(&tc, 0, "gluDeleteNurbsRenderer(nurb=#") > 0);
        trace_cmds_done(&tc, "nurbs");

        rgl_cmd_iter it;
        rgl_cmd cmd;
        rgl_reader_frame(r, 0, &fi, NULL);
        rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
        int seen = 0;
        while (rgl_cmd_next(&it, &cmd) == RGL_OK) {
            if (cmd.opcode == RGL_OP_NurbsSurface) {
                double want[24];
                size_t k = 0;
                for (int i = 0; i < 2; i++)
                    for (int j = 0; j < 3; j++)
                        for (int ch = 0; ch < 4; ch++)
                            want[k++] = 100 * i + 10 * j + ch;
                static const double wsk[4] = {0, 0, 1, 1}, wtk[5] = {0, 0, 0.5, 1, 1};
                CHECK(blob_is(&cmd.arg[7], want, 24));
                CHECK(blob_is(&cmd.arg[2], wsk, 4) && blob_is(&cmd.arg[4], wtk, 5));
                CHECK(rgl_arg_i(&cmd.arg[5], 0) == 4 && rgl_arg_i(&cmd.arg[6], 0) == 11);
                seen++;
            } else if (cmd.opcode == RGL_OP_PwlCurve) {
                static const double want[9] = {0, 1, 2, 10, 11, 12, 20, 21, 22};
                CHECK(blob_is(&cmd.arg[2], want, 9));
                seen++;
            }
        }
        CHECK(seen == 2);
        rgl_reader_destroy(r);
    }
    unlink(path);
    munmap(mem, (size_t)page * 2);
}
