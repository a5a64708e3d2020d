/* test_buffers.c: buffer objects, the multi-draws and the calls that list
 * compilation must not swallow, against the stub GL (no context). Part of
 * test_entry; see that file.
 *
 * Checks: glBufferData / glBufferSubData recorded with their bytes as
 * resources; pointers that are offsets into a bound array buffer and
 * indices that are offsets into a bound element buffer, resolved into
 * @ArrayData and index blobs; a mapped buffer's bytes recorded at unmap
 * (a write mapping) and not (a read-only one); the ARB names; a draw past
 * a buffer's end left unrecorded, with @Skipped; glMultiDrawArrays / glMultiDrawElements;
 * glGenLists, glDeleteLists, pointer and client-state calls made while a
 * list compiles go to the frame, and @ArrayData stays in the list.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
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
    rayglDrawArrays(GL_POINTS, 5, 2); /* 5, 6 end at byte 72 > 64: @Skipped */
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
        "@Skipped(opcode=0x7e, reason=0x2)", /* past the buffer's end: said */
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
    d = blob(r, 0, 16, 3, &n);
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

/* A buffer bound to GL_PIXEL_UNPACK_BUFFER: the pixels argument is an
 * offset into it (the conformance test that crashed the recorder: 4092
 * bytes, then 32 x 32 RGBA at offset 0 and 32 x 16 at 0x800, both past the
 * end, which GL refuses). Without a context the recorder's copy is read;
 * the unpack state applies inside the buffer; a mapped buffer is not read;
 * GLU, which reads client memory whatever is bound, leaves @Skipped;
 * unbinding or deleting the buffer makes pointers addresses again. */
void test_pbo(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/pbo.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    static uint8_t bytes[4092];
    for (size_t i = 0; i < sizeof bytes; i++)
        bytes[i] = (uint8_t)(i * 7 + i / 256);
    GLuint b[1] = {0};
    rayglGenBuffers(1, b);
    rayglBindTexture(GL_TEXTURE_2D, 1);
    rayglBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[0]);
    rayglBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof bytes, bytes, GL_STREAM_DRAW);
    stub_reset();
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    (const void *)0x800);
    rayglTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE,
                       (const void *)(uintptr_t)-8); /* wraps around */
    CHECK(stub_nlog == 3 && stub_log[1].p[8] == (const void *)0x800); /* GL gets the offset */
    /* Inside: 16 x 16 at 0x400; a 2 x 2 RGB sub-image at offset 1 with
     * rows of 5 pixels, one row and two pixels skipped. */
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    (const void *)0x400);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    rayglTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, (const void *)1);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    /* Offset 0 is data, not "no pixels". */
    rayglTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    raygluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, (const void *)8);
    rayglMapBuffer(GL_PIXEL_UNPACK_BUFFER, GL_WRITE_ONLY);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    memcpy(stub_mapped, bytes, sizeof bytes);
    rayglUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
    rayglDeleteBuffers(1, b); /* unbinds it */
    static const uint8_t px[4] = {9, 8, 7, 6};
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    char gen[64], bind[96], del[64];
    snprintf(gen, sizeof gen, "glGenBuffers(buffers=[%u])", b[0]);
    snprintf(bind, sizeof bind, "glBindBuffer(target=GL_PIXEL_UNPACK_BUFFER, buffer=%u)", b[0]);
    snprintf(del, sizeof del, "glDeleteBuffers(buffers=[%u])", b[0]);
    const char *const want[] = {
        gen,
        "glBindTexture(target=GL_TEXTURE_2D, texture=1)",
        bind,
        "glBufferData(target=GL_PIXEL_UNPACK_BUFFER, size=4092, data=#1, usage=GL_STREAM_DRAW)",
        "glTexImage2D(target=GL_TEXTURE_2D, level=0, internalformat=6408, width=16, height=16, border=0, format=GL_RGBA, type=GL_UNSIGNED_BYTE, pixels=#2)",
        "glPixelStorei(pname=GL_UNPACK_ROW_LENGTH, param=5)",
        "glPixelStorei(pname=GL_UNPACK_SKIP_ROWS, param=1)",
        "glPixelStorei(pname=GL_UNPACK_SKIP_PIXELS, param=2)",
        "glTexSubImage2D(target=GL_TEXTURE_2D, level=0, xoffset=0, yoffset=0, width=2, height=2, format=GL_RGB, type=GL_UNSIGNED_BYTE, pixels=#3)",
        "glPixelStorei(pname=GL_UNPACK_ROW_LENGTH, param=0)",
        "glPixelStorei(pname=GL_UNPACK_SKIP_ROWS, param=0)",
        "glPixelStorei(pname=GL_UNPACK_SKIP_PIXELS, param=0)",
        "glTexSubImage2D(target=GL_TEXTURE_2D, level=0, xoffset=0, yoffset=0, width=1, height=1, format=GL_RGBA, type=GL_UNSIGNED_BYTE, pixels=#4)",
        "@Skipped(opcode=0xe3, reason=0x2)", /* gluBuild2DMipmaps */
        "glMapBuffer(target=GL_PIXEL_UNPACK_BUFFER, access=GL_WRITE_ONLY)",
        "glBufferSubData(target=GL_PIXEL_UNPACK_BUFFER, offset=0, size=4092, data=#1)",
        "glUnmapBuffer(target=GL_PIXEL_UNPACK_BUFFER)",
        del,
        "glTexImage2D(target=GL_TEXTURE_2D, level=0, internalformat=6408, width=1, height=1, border=0, format=GL_RGBA, type=GL_UNSIGNED_BYTE, pixels=#5)",
        "rayglFrameEnd()",
    };
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(c.clean);
    expect(&c, want, sizeof want / sizeof want[0], "pbo frame");
    trace_cmds_free(&c);
    rgl_resource res;
    if (CHECK(rgl_reader_resource(r, 2, &res, NULL) == RGL_OK))
        CHECK(res.size == 1024 && memcmp(res.data, bytes + 0x400, 1024) == 0);
    if (CHECK(rgl_reader_resource(r, 3, &res, NULL) == RGL_OK)) {
        /* rows of 15 bytes padded to 16: bytes 1 + 16 + 6 .. and 1 + 32 + 6 .. */
        CHECK(res.size == 12 && memcmp(res.data, bytes + 23, 6) == 0 &&
              memcmp(res.data + 6, bytes + 39, 6) == 0);
    }
    if (CHECK(rgl_reader_resource(r, 4, &res, NULL) == RGL_OK))
        CHECK(res.size == 4 && memcmp(res.data, bytes, 4) == 0);
    if (CHECK(rgl_reader_resource(r, 5, &res, NULL) == RGL_OK))
        CHECK(res.size == 4 && memcmp(res.data, px, 4) == 0);
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}

/* With a live context the recorder asks GL which buffer is bound, and
 * believes it over its own tracking (a binding glPopClientAttrib or a
 * vertex array object restored, which it never saw): the stub answers
 * like GL 2.1 would. Pixels come from GL's buffer (glGetBufferSubData),
 * not refused past GL's size or while mapped; array pointers and indices
 * are offsets into the buffers GL names. A GL 1.4 context without the
 * extensions has no such buffers: its pointers are addresses, and the
 * binding queries (an error there) are not made. */
void test_live_bindings(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/live.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    GLuint b[2] = {0, 0};
    rayglGenBuffers(2, b);
    static const float pos[3][2] = {{1, 2}, {3, 4}, {5, 6}};
    static const GLushort idx[2] = {2, 0};
    rayglBindBuffer(GL_ARRAY_BUFFER, b[0]);
    rayglBufferData(GL_ARRAY_BUFFER, sizeof pos, pos, GL_STATIC_DRAW);
    rayglBindBuffer(GL_ARRAY_BUFFER, 0);
    rayglBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
    rayglBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    rayglBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    for (int i = 0; i < 64; i++)
        stub_buffer[i] = (uint8_t)(100 + i);
    stub_version = "2.1 Mesa";
    stub_ints[0] = (stub_int){GL_PIXEL_UNPACK_BUFFER_BINDING, 7};
    stub_ints[1] = (stub_int){GL_ARRAY_BUFFER_BINDING, (int)b[0]};
    stub_ints[2] = (stub_int){GL_ELEMENT_ARRAY_BUFFER_BINDING, (int)b[1]};
    stub_nints = 3;
    stub_buffer_size = 64;
    stub_buffer_mapped = 0;
    rayglBindTexture(GL_TEXTURE_2D, 1);
    stub_reset();
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    (const void *)16);
    CHECK(stub_nlog == 2 && strcmp(stub_log[0].name, "glGetBufferSubData") == 0 &&
          stub_log[0].v[1] == 16 && stub_log[0].v[2] == 16);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    (const void *)52); /* ends at 68 > 64 */
    stub_buffer_mapped = 1;
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    stub_buffer_mapped = 0;
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglVertexPointer(2, GL_FLOAT, 0, (const void *)8); /* pos[1] on */
    rayglDrawArrays(GL_POINTS, 0, 2);
    rayglDrawElements(GL_POINTS, 1, GL_UNSIGNED_SHORT, (const void *)2); /* index 0 */
    /* GL 1.4, no extensions: the pointers are addresses. What the context
     * has is asked once a frame: a new frame. */
    rayglFrameEnd();
    stub_version = "1.4";
    static const uint8_t px[4] = {1, 2, 3, 4};
    static const float cv[2] = {9, 8};
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglVertexPointer(2, GL_FLOAT, 0, cv);
    rayglDrawArrays(GL_POINTS, 0, 1);
    rayglDisableClientState(GL_VERTEX_ARRAY);
    stub_version = NULL;
    stub_nints = 0;
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(c.clean);
    trace_cmds c1 = trace_frame(r, 1, &fi);
    CHECK(c1.clean);
    long t0 = trace_cmds_find(&c, 0, "glTexImage2D");
    CHECK(t0 >= 0 && strstr(c.lines[t0], "width=2") != NULL);
    CHECK(t0 >= 0 && trace_cmds_find(&c, (size_t)t0 + 1, "glTexImage2D") < 0);
    long t1 = trace_cmds_find(&c1, 0, "glTexImage2D");
    CHECK(t1 >= 0 && strstr(c1.lines[t1], "width=1") != NULL); /* the 1.4 one */
    long d0 = trace_cmds_find(&c, 0, "glDrawArrays");
    long e0 = trace_cmds_find(&c, 0, "glDrawElements");
    long d1 = trace_cmds_find(&c1, 0, "glDrawArrays");
    CHECK(d0 > 0 && e0 > d0 && d1 > 0);
    size_t n;
    const uint8_t *d = d0 > 0 ? blob(r, 0, (size_t)d0 - 1, 4, &n) : NULL;
    if (CHECK(d && n == 16)) {
        float got[4];
        memcpy(got, d, sizeof got);
        CHECK(got[0] == 3 && got[1] == 4 && got[2] == 5 && got[3] == 6);
    }
    d = e0 > 0 ? blob(r, 0, (size_t)e0, 3, &n) : NULL;
    CHECK(d && n == 2 && d[0] == 0 && d[1] == 0);
    d = d1 > 0 ? blob(r, 1, (size_t)d1 - 1, 4, &n) : NULL;
    if (CHECK(d && n == 8)) {
        float got[2];
        memcpy(got, d, sizeof got);
        CHECK(got[0] == 9 && got[1] == 8);
    }
    trace_cmds_free(&c);
    trace_cmds_free(&c1);
    rgl_resource res;
    bool found = false;
    for (uint32_t id = 1; id < 10; id++)
        if (rgl_reader_resource(r, id, &res, NULL) == RGL_OK && res.size == 16)
            found |= memcmp(res.data, stub_buffer + 16, 16) == 0;
    CHECK(found);
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}

/* Client state set while no trace is open is still GL's when one opens:
 * the recorder keeps it. A pointer replaced while closed (the old memory
 * then gone: here a page made unreadable) is not read, nor is an offset
 * into an unpack buffer bound while closed taken for an address. */
void test_reopen(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/reopen.raygl", dir);
    long pg = sysconf(_SC_PAGESIZE);
    float *old = mmap(NULL, (size_t)pg, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (!CHECK(old != MAP_FAILED))
        return;
    static const float now[3][2] = {{1, 2}, {3, 4}, {5, 6}};
    CHECK(rayglRecordOpen(path) == 0);
    rayglBindBuffer(GL_ARRAY_BUFFER, 0);
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglVertexPointer(2, GL_FLOAT, 0, old);
    rayglRecordClose();
    rayglVertexPointer(2, GL_FLOAT, 0, now);
    CHECK(mprotect(old, (size_t)pg, PROT_NONE) == 0);
    GLuint b[1] = {0};
    rayglGenBuffers(1, b);
    rayglBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[0] ? b[0] : 99);
    CHECK(rayglRecordOpen(path) == 0);
    rayglDrawArrays(GL_TRIANGLES, 0, 3);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    (const void *)0x800);
    rayglBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    rayglDisableClientState(GL_VERTEX_ARRAY);
    rayglFrameEnd();
    rayglRecordClose();
    munmap(old, (size_t)pg);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    long d = trace_cmds_find(&c, 0, "glDrawArrays");
    CHECK(d > 0 && trace_cmds_find(&c, 0, "glTexImage2D") < 0);
    size_t n;
    const uint8_t *data = d > 0 ? blob(r, 0, (size_t)d - 1, 4, &n) : NULL;
    if (CHECK(data && n == sizeof now))
        CHECK(memcmp(data, now, sizeof now) == 0);
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}

/* glBufferData with a usage GL refuses reads no data (1 MiB asked of a
 * pointer to a page that faults); a mapping is as long as GL says the
 * buffer is (64 bytes), though the recorder's copy held 16: unmap records
 * all 64; a draw from a buffer mapped for reading is recorded. */
void test_buffer_rules(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/bufrules.raygl", dir);
    long pg = sysconf(_SC_PAGESIZE);
    uint8_t *bad = mmap(NULL, (size_t)pg, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (!CHECK(bad != MAP_FAILED))
        return;
    CHECK(rayglRecordOpen(path) == 0);
    GLuint b[1] = {0};
    rayglGenBuffers(1, b);
    rayglBindBuffer(GL_ARRAY_BUFFER, b[0]);
    stub_reset();
    rayglBufferData(GL_ARRAY_BUFFER, 1 << 20, bad, 0x1234);
    rayglBufferData(GL_ARRAY_BUFFER, 1 << 20, bad, GL_STATIC_DRAW + 3); /* 0x88e7: no usage */
    CHECK(stub_nlog == 2);
    static const uint8_t small[16] = {1, 2, 3};
    rayglBufferData(GL_ARRAY_BUFFER, sizeof small, small, GL_STATIC_DRAW);
    stub_version = "2.1 Mesa";
    stub_ints[0] = (stub_int){GL_ARRAY_BUFFER_BINDING, (int)b[0]};
    stub_nints = 1;
    stub_buffer_size = 64;
    uint8_t *m = rayglMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    if (CHECK(m == stub_mapped))
        for (int i = 0; i < 64; i++)
            m[i] = (uint8_t)(i + 1);
    rayglUnmapBuffer(GL_ARRAY_BUFFER);
    stub_version = NULL;
    stub_nints = 0;
    /* Drawn from while mapped for reading (Mesa draws): recorded from the
     * recorder's copy, which the mapping cannot change. */
    rayglMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    rayglDrawArrays(GL_POINTS, 0, 2);
    rayglDisableClientState(GL_VERTEX_ARRAY);
    rayglUnmapBuffer(GL_ARRAY_BUFFER);
    rayglBindBuffer(GL_ARRAY_BUFFER, 0);
    rayglFrameEnd();
    rayglRecordClose();
    munmap(bad, (size_t)pg);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(trace_cmds_count(&c, RGL_OP_BufferData) == 1);
    CHECK(trace_cmds_count(&c, RGL_OP_DrawArrays) == 1);
    long k = trace_cmds_find(&c, 0, "glBufferSubData(target=GL_ARRAY_BUFFER, offset=0, size=64,");
    CHECK(k > 0);
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}
