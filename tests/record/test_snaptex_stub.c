/* test_snaptex_stub.c: the snapshot's texture part asks the context only
 * what it supports (the stub GL as the context, record/snaptex.c).
 *
 * A GL 1.1 context without extensions: no glActiveTexture, no rectangle,
 * 3D or cube-map binding, neither called on GL nor in the snapshot. A GL
 * 2.1 context with 2 units, unit 1 active, no extensions: each unit made
 * active once, in turn (unit 1, the last, needs no restoring), 3D and
 * cube-map bindings but no rectangle ones (GL 3.1 or
 * GL_ARB_texture_rectangle), unit 1 active last in the snapshot.
 */
#include <string.h>
#include <unistd.h>

#include <GL/gl.h>
#include <GL/glext.h>

#include "check.h"
#include "raygl.h"
#include "stubgl.h"

static size_t logged(const char *name, double first_arg)
{
    size_t n = 0;
    for (size_t i = 0; i < stub_nlog && i < STUB_LOG_MAX; i++)
        n += strcmp(stub_log[i].name, name) == 0 && stub_log[i].v[0] == first_arg;
    return n;
}

static size_t logged_any(const char *name)
{
    size_t n = 0;
    for (size_t i = 0; i < stub_nlog && i < STUB_LOG_MAX; i++)
        n += strcmp(stub_log[i].name, name) == 0;
    return n;
}

void test_snaptex_support(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/snaptex.raygl", dir);
    stub_version = "1.1 Mesa";
    stub_ints[0] = (stub_int){GL_MATRIX_MODE, GL_MODELVIEW};
    stub_nints = 1;
    CHECK(rayglRecordOpen(path) == 0);
    rayglBindTexture(GL_TEXTURE_RECTANGLE_ARB, 5);
    rayglBindTexture(GL_TEXTURE_3D, 6);
    rayglBindTexture(GL_TEXTURE_CUBE_MAP, 7);
    rayglFrameEnd();
    stub_reset();
    rayglFlush(); /* frame 1 starts: its snapshot */
    CHECK(logged_any("glActiveTexture") == 0);
    /* No object of a supported target to read back: GL's bindings untouched. */
    CHECK(logged_any("glBindTexture") == 0);
    CHECK(logged("glBindTexture", GL_TEXTURE_RECTANGLE_ARB) == 0);
    CHECK(logged("glBindTexture", GL_TEXTURE_3D) == 0);
    CHECK(logged("glBindTexture", GL_TEXTURE_CUBE_MAP) == 0);
    rayglFrameEnd();

    stub_version = "2.1 Mesa";
    stub_ints[1] = (stub_int){GL_ACTIVE_TEXTURE, GL_TEXTURE1};
    stub_ints[2] = (stub_int){GL_MAX_TEXTURE_UNITS, 2};
    stub_nints = 3;
    stub_reset();
    rayglFlush(); /* frame 2's snapshot */
    /* Each unit made active once to be read; unit 1, the last one read,
     * is already the program's active unit again. */
    CHECK(logged("glActiveTexture", GL_TEXTURE0) == 1);
    CHECK(logged("glActiveTexture", GL_TEXTURE1) == 1);
    CHECK(logged_any("glActiveTexture") == 2);
    long last = -1;
    for (size_t i = 0; i < stub_nlog && i < STUB_LOG_MAX; i++)
        if (strcmp(stub_log[i].name, "glActiveTexture") == 0)
            last = (long)i;
    CHECK(last >= 0 && stub_log[last].v[0] == GL_TEXTURE1);
    rayglFrameEnd();
    rayglRecordClose();
    stub_version = NULL;
    stub_nints = 0;

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    for (size_t f = 1; f <= 2; f++) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, f, &fi);
        trace_cmds s = trace_resource_cmds(r, fi.state);
        CHECK(s.clean && s.count > 0);
        bool rect = trace_cmds_find(&s, 0, "glBindTexture(target=GL_TEXTURE_RECTANGLE") >= 0;
        bool tex3d = trace_cmds_find(&s, 0, "glBindTexture(target=GL_TEXTURE_3D") >= 0;
        bool cube = trace_cmds_find(&s, 0, "glBindTexture(target=GL_TEXTURE_CUBE_MAP") >= 0;
        long u0 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE0)");
        long u1 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE1)");
        if (f == 1) {
            CHECKM(!rect && !tex3d && !cube && u0 < 0 && u1 < 0, "GL 1.1: %d %d %d %ld %ld",
                   rect, tex3d, cube, u0, u1);
        } else {
            /* GL 2.1 without GL_ARB_texture_rectangle: no rectangle. */
            CHECK(!rect && tex3d && cube);
            /* One block per unit, unit 1 (active) last: no restore needed. */
            CHECK(u0 >= 0 && u1 > u0);
            CHECK(trace_cmds_count(&s, RGL_OP_ActiveTexture) == 2);
            long last = -1;
            for (size_t i = 0; i < s.count; i++)
                if (strncmp(s.lines[i], "glActiveTexture(", 16) == 0)
                    last = (long)i;
            CHECK(last == u1);
        }
        trace_cmds_done(&s, "snapshot");
        trace_cmds_free(&c);
    }
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}
