/* test_buffers.c: buffer objects, the multi-draws and the calls that list
 * compilation must not swallow, against the stub GL (no context). Part of
 * test_entry; see that file.
 *
 * Checks: glBufferData / glBufferSubData recorded with their bytes as
 * resources; pointers that are offsets into a bound array buffer and
 * indices that are offsets into a bound element buffer, resolved into
 * @ArrayData and index blobs; a mapped buffer's bytes recorded at unmap
 * (a write mapping) and not (a read-only one); the ARB names; a draw past
 * a buffer's end left unrecorded; glMultiDrawArrays / glMultiDrawElements;
 * glGenLists, glDeleteLists, pointer and client-state calls made while a
 * list compiles go to the frame, and @ArrayData stays in the list.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GL/gl.h>
#include <GL/glext.h>

#include "check.h"
#include "raygl.h"
#include "recorder.h"
#include "stubgl.h"

void test_buffers(const char *dir);

static void expect(const trace_cmds *c, const char *const *want, size_t n, const char *what)
{
    bool ok = CHECKM(c->count == n, "%s: %zu commands, want %zu", what, c->count, n);
    for (size_t i = 0; i < n && i < c->count; i++)
        ok &= CHECKM(strcmp(c->lines[i], want[i]) == 0, "%s[%zu]: got %s, want %s", what, i,
                     c->lines[i], want[i]);
    if (!ok)
        trace_cmds_print(c, what);
}

/* The BLOB argument `arg` of command i of frame f. */
static const uint8_t *blob(rgl_reader *r, size_t f, size_t i, unsigned arg, size_t *n)
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
    *n = cmd.arg[arg].count;
    return cmd.arg[arg].bytes;
}

void test_buffers(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/buffers.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);

    GLuint b[2] = {0, 0};
    rayglGenBuffers(2, b);
    CHECK(b[0] == 1 && b[1] == 2); /* no context: RayGL names them */
    static const float pos[4][2] = {{1, 2}, {3, 4}, {5, 6}, {7, 8}};
    rayglBindBuffer(GL_ARRAY_BUFFER, b[0]);
    rayglBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);
    rayglBufferSubData(GL_ARRAY_BUFFER, 16, sizeof pos, pos);
    rayglBufferSubData(GL_ARRAY_BUFFER, 60, 8, pos); /* past the end: GL refuses */
    static const GLushort idx[4] = {3, 1, 2, 1};
    rayglBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
    rayglBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglVertexPointer(2, GL_FLOAT, 8, (const void *)16);
    stub_reset();
    rayglDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, (const void *)2); /* 1, 2, 1 */
    CHECK(stub_nlog == 1 && stub_log[0].p[3] == (const void *)2); /* GL gets the offset */
    rayglDrawArrays(GL_POINTS, 2, 3); /* elements 2..4: the buffer holds 0..3 (+ 2 of 0) */
    rayglDrawArrays(GL_POINTS, 5, 2); /* 5, 6 end at byte 72 > 64: not recorded */
    static const GLint mf[2] = {0, 2};
    static const GLsizei mc[2] = {1, 2};
    rayglMultiDrawArrays(GL_POINTS, mf, mc, 2);
    static const GLsizei ec[2] = {2, 1};
    const void *const eo[2] = {(const void *)0, (const void *)4};
    rayglMultiDrawElements(GL_POINTS, ec, GL_UNSIGNED_SHORT, eo, 2); /* 3, 1 and 2 */

    /* Mapped for writing: what the program wrote is recorded at unmap. */
    GLubyte *m = rayglMapBufferARB(GL_ARRAY_BUFFER_ARB, GL_WRITE_ONLY_ARB);
    CHECK(m == stub_mapped);
    if (m)
        for (int i = 0; i < 64; i++)
            m[i] = (GLubyte)(200 - i);
    CHECK(rayglUnmapBufferARB(GL_ARRAY_BUFFER_ARB) == GL_TRUE);
    rayglMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    rayglUnmapBuffer(GL_ARRAY_BUFFER);
    rayglBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    rayglDeleteBuffersARB(2, b);
    rayglFrameEnd();

    /* Frame 1: a list compiled with arrays around it. */
    static const float cv[3][2] = {{9, 9}, {8, 8}, {7, 7}};
    rayglBindBuffer(GL_ARRAY_BUFFER, 0);
    rayglNewList(5, GL_COMPILE);
    GLuint first = rayglGenLists(2);
    rayglVertexPointer(2, GL_FLOAT, 0, cv);
    rayglDrawArrays(GL_TRIANGLES, 0, 3);
    rayglDisableClientState(GL_VERTEX_ARRAY);
    rayglDeleteLists(first, 2);
    rayglEndList();
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 2);
    rgl_frame_info fi;
    static const char *const f0[] = {
        "glGenBuffers(buffers=[1, 2])",
        "glBindBuffer(target=GL_ARRAY_BUFFER, buffer=1)",
        "glBufferData(target=GL_ARRAY_BUFFER, size=64, data=#0, usage=GL_STATIC_DRAW)",
        "glBufferSubData(target=GL_ARRAY_BUFFER, offset=16, size=32, data=#1)",
        "glBindBuffer(target=GL_ELEMENT_ARRAY_BUFFER, buffer=2)",
        "glBufferData(target=GL_ELEMENT_ARRAY_BUFFER, size=8, data=#2, usage=GL_STATIC_DRAW)",
        "glEnableClientState(array=GL_VERTEX_ARRAY)",
        "glVertexPointer(size=2, type=GL_FLOAT, stride=8)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=1, size=2, type=GL_FLOAT, data=<16 bytes>)",
        "glDrawElements(mode=GL_TRIANGLES, count=3, type=GL_UNSIGNED_SHORT, indices=<6 bytes>)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=2, size=2, type=GL_FLOAT, data=<24 bytes>)",
        "glDrawArrays(mode=GL_POINTS, first=2, count=3)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=0, size=2, type=GL_FLOAT, data=<32 bytes>)",
        "glMultiDrawArrays(mode=GL_POINTS, first=<8 bytes>, count=<8 bytes>, drawcount=2)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=1, size=2, type=GL_FLOAT, data=<24 bytes>)",
        "glMultiDrawElements(mode=GL_POINTS, count=<8 bytes>, type=GL_UNSIGNED_SHORT, indices=<6 bytes>, drawcount=2)",
        "glMapBufferARB(target=GL_ARRAY_BUFFER, access=GL_WRITE_ONLY)",
        "glBufferSubDataARB(target=GL_ARRAY_BUFFER, offset=0, size=64, data=#3)",
        "glUnmapBufferARB(target=GL_ARRAY_BUFFER)",
        "glMapBuffer(target=GL_ARRAY_BUFFER, access=GL_READ_ONLY)",
        "glUnmapBuffer(target=GL_ARRAY_BUFFER)",
        "glBindBuffer(target=GL_ELEMENT_ARRAY_BUFFER, buffer=0)",
        "glDeleteBuffersARB(buffers=[1, 2])",
        "rayglFrameEnd()",
    };
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(c.clean);
    expect(&c, f0, sizeof f0 / sizeof f0[0], "buffers frame 0");
    trace_cmds_free(&c);

    /* The draws read the recorder's copy: elements 1 and 2 (pointer offset
     * 16 = pos[0], stride 8) are pos[1] and pos[2]. */
    size_t n;
    const uint8_t *d = blob(r, 0, 8, 4, &n);
    if (CHECK(d && n == 16)) {
        float got[4];
        memcpy(got, d, sizeof got);
        CHECK(got[0] == 3 && got[1] == 4 && got[2] == 5 && got[3] == 6);
    }
    d = blob(r, 0, 9, 3, &n);
    CHECK(d && n == 6 && d[0] == 1 && d[2] == 2 && d[4] == 1);
    d = blob(r, 0, 15, 3, &n);
    CHECK(d && n == 6 && d[0] == 3 && d[2] == 1 && d[4] == 2);
    rgl_resource res;
    if (CHECK(rgl_reader_resource(r, 3, &res, NULL) == RGL_OK))
        CHECK(res.kind == RGL_RES_BYTES && res.size == 64 && res.data[0] == 200 &&
              res.data[63] == 137);

    char gen[64], del[64];
    snprintf(gen, sizeof gen, "glGenLists(range=2, first=%u)", first);
    snprintf(del, sizeof del, "glDeleteLists(list=%u, range=2)", first);
    const char *const f1[] = {
        "glBindBuffer(target=GL_ARRAY_BUFFER, buffer=0)",
        gen,
        "glVertexPointer(size=2, type=GL_FLOAT, stride=0)",
        "glDisableClientState(array=GL_VERTEX_ARRAY)",
        del,
        "glNewList(list=5, mode=GL_COMPILE, body=#4)",
        "glEndList()",
        "rayglFrameEnd()",
    };
    c = trace_frame(r, 1, &fi);
    expect(&c, f1, sizeof f1 / sizeof f1[0], "buffers frame 1");
    trace_cmds_free(&c);
    trace_cmds body = trace_resource_cmds(r, 4);
    static const char *const lb[] = {
        "@ArrayData(array=GL_VERTEX_ARRAY, first=0, size=2, type=GL_FLOAT, data=<24 bytes>)",
        "glDrawArrays(mode=GL_TRIANGLES, first=0, count=3)",
    };
    expect(&body, lb, 2, "list body");
    trace_cmds_free(&body);
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}
