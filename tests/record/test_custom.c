/* test_custom.c: the hand-written entry points against the stub GL (no
 * context, as in batch use), and allocation failure at every allocation.
 * Part of test_entry; see that file. */
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "check.h"
#include "raygl.h"
#include "recorder.h"
#include "stubgl.h"

void test_custom(const char *dir);
void test_alloc_failures(const char *dir);
void test_too_large(const char *dir);
void test_unpack(const char *dir);
void test_pixel_rules(const char *dir);
void test_raster(const char *dir);
void test_texcopy_nocontext(const char *dir);
void test_buffer_reuse(const char *dir);

/* The BLOB argument of a decoded command of frame f, command i. */
static const uint8_t *blob_of(rgl_reader *r, size_t f, size_t i, unsigned arg, size_t *n)
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

static void expect_lines(const trace_cmds *c, const char *const *want, size_t n, const char *what)
{
    bool ok = CHECKM(c->count == n, "%s: %zu commands, want %zu", what, c->count, n);
    for (size_t i = 0; i < n && i < c->count; i++)
        ok &= CHECKM(strcmp(c->lines[i], want[i]) == 0, "%s[%zu]: got %s, want %s", what, i,
                     c->lines[i], want[i]);
    if (!ok)
        trace_cmds_print(c, what);
}

static const float verts[4][4] = {{0, 1, 2, -1}, {3, 4, 5, -1}, {6, 7, 8, -1}, {9, 10, 11, -1}};
static const GLubyte names[6] = {0, 1, 0, 2, 0, 3};
static const GLubyte colors[4][4] = {{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16}};

static void record_frames(bool first_run)
{
    GLuint t[2] = {77, 77};
    rayglGenTextures(2, t);
    CHECK(!first_run || (t[0] == 1 && t[1] == 2));
    rayglBindTexture(GL_TEXTURE_2D, t[1]);
    const GLfloat bc[4] = {0.5f, 0.25f, 0, 1};
    rayglTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, bc);
    /* 3x2 RGB, rows padded to 12 bytes under the default alignment. */
    GLubyte padded[2 * 12];
    for (int i = 0; i < 24; i++)
        padded[i] = (GLubyte)(i % 12 < 9 ? 100 + i : 0xEE);
    stub_reset();
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, padded);
    CHECK(stub_nlog == 1 && stub_log[0].p[8] == padded);
    rayglTexImage2D(GL_TEXTURE_2D, 1, GL_RGB, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, padded);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);

    GLuint first = rayglGenLists(3);
    CHECK(!first_run || first == 1);
    rayglNewList(2, GL_COMPILE);
    rayglBegin(GL_LINES);
    rayglVertex2i(1, 2);
    rayglEnd();
    rayglEndList();
    rayglCallLists(3, GL_2_BYTES, names);

    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglEnableClientState(GL_COLOR_ARRAY);
    rayglVertexPointer(3, GL_FLOAT, 16, verts);
    rayglColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    rayglDrawArrays(GL_TRIANGLES, 1, 2);
    const GLushort idx[3] = {3, 1, 2};
    rayglDrawElements(GL_POINTS, 3, GL_UNSIGNED_SHORT, idx);
    rayglDrawRangeElements(GL_POINTS, 0, 9, 3, GL_UNSIGNED_SHORT, idx);
    rayglutSwapBuffers();

    /* Frame 1: interleaved arrays, then elements one by one. */
    struct { float t[2]; GLubyte c[4]; float v[3]; } il[2] = {
        {{0.5f, 0.25f}, {1, 2, 3, 4}, {1, 2, 3}}, {{0.75f, 1}, {5, 6, 7, 8}, {4, 5, 6}}};
    rayglInterleavedArrays(GL_T2F_C4UB_V3F, 0, il);
    rayglDrawArrays(GL_POINTS, 0, 2);
    rayglDisableClientState(GL_COLOR_ARRAY);
    rayglDisableClientState(GL_TEXTURE_COORD_ARRAY);
    rayglBegin(GL_POINTS);
    rayglArrayElement(1);
    rayglEnd();
    rayglDisableClientState(GL_VERTEX_ARRAY);
    /* An enabled array without a pointer: GL would fault; forwarded only. */
    rayglEnableClientState(GL_NORMAL_ARRAY);
    stub_reset();
    rayglDrawArrays(GL_POINTS, 0, 1);
    CHECK(stub_nlog == 1);
    rayglDisableClientState(GL_NORMAL_ARRAY);

    GLUquadric *q = raygluNewQuadric();
    raygluQuadricDrawStyle(q, GLU_LINE);
    raygluQuadricTexture(q, GL_TRUE);
    raygluCylinder(q, 1, 0.5, 2, 8, 3);
    raygluPartialDisk(q, 0.5, 1, 6, 2, 45.5, 92.5);
    raygluDeleteQuadric(q);
    rayglDeleteLists(1, 3);
    rayglDeleteTextures(2, t);
    /* Ends frame 1 (it holds commands), starts frame 2. */
    rayglFrameBegin("a.pov", 1, 2, 3, 4, 5, 6, 7, 8, 9);
    rayglVertex3f(1, 2, 3);
    rayglFrameEnd();
    rayglutSwapBuffers();
}

void test_custom(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/custom.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    record_frames(true);
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 4);
    rgl_frame_info fi;
    static const char *const f0[] = {
        "glGenTextures(textures=[1, 2])",
        "glBindTexture(target=GL_TEXTURE_2D, texture=2)",
        "glTexParameterfv(target=GL_TEXTURE_2D, pname=GL_TEXTURE_BORDER_COLOR, params=[0.5, 0.25, 0, 1])",
        "glTexImage2D(target=GL_TEXTURE_2D, level=0, internalformat=6407, width=3, height=2, border=0, format=GL_RGB, type=GL_UNSIGNED_BYTE, pixels=#1)",
        "glTexImage2D(target=GL_TEXTURE_2D, level=1, internalformat=6407, width=3, height=2, border=0, format=GL_RGB, type=GL_UNSIGNED_BYTE, pixels=#1)",
        "glTexImage2D(target=GL_TEXTURE_2D, level=0, internalformat=6407, width=4, height=4, border=0, format=GL_RGB, type=GL_UNSIGNED_BYTE, pixels=#0)",
        "glGenLists(range=3, first=1)",
        "glNewList(list=2, mode=GL_COMPILE, body=#2)",
        "glEndList()",
        "glCallLists(n=3, type=GL_2_BYTES, lists=<6 bytes>)",
        "glEnableClientState(array=GL_VERTEX_ARRAY)",
        "glEnableClientState(array=GL_COLOR_ARRAY)",
        "glVertexPointer(size=3, type=GL_FLOAT, stride=16)",
        "glColorPointer(size=4, type=GL_UNSIGNED_BYTE, stride=0)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=1, size=3, type=GL_FLOAT, data=<24 bytes>)",
        "@ArrayData(array=GL_COLOR_ARRAY, first=1, size=4, type=GL_UNSIGNED_BYTE, data=<8 bytes>)",
        "glDrawArrays(mode=GL_TRIANGLES, first=1, count=2)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=1, size=3, type=GL_FLOAT, data=<36 bytes>)",
        "@ArrayData(array=GL_COLOR_ARRAY, first=1, size=4, type=GL_UNSIGNED_BYTE, data=<12 bytes>)",
        "glDrawElements(mode=GL_POINTS, count=3, type=GL_UNSIGNED_SHORT, indices=<6 bytes>)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=1, size=3, type=GL_FLOAT, data=<36 bytes>)",
        "@ArrayData(array=GL_COLOR_ARRAY, first=1, size=4, type=GL_UNSIGNED_BYTE, data=<12 bytes>)",
        "glDrawRangeElements(mode=GL_POINTS, start=0, end=9, count=3, type=GL_UNSIGNED_SHORT, indices=<6 bytes>)",
        "glutSwapBuffers()",
    };
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(c.clean && fi.flags == RGL_FRAME_STATE_CARRIED && fi.state == 0 && fi.number == 0);
    expect_lines(&c, f0, sizeof f0 / sizeof f0[0], "frame 0");
    trace_cmds_free(&c);

    /* Packed: the vertex array's stride of 16 is gone; elements 1 and 2. */
    size_t n;
    const uint8_t *b = blob_of(r, 0, 14, 4, &n);
    if (CHECK(b && n == 24)) {
        float got[6];
        memcpy(got, b, sizeof got);
        CHECK(got[0] == 3 && got[2] == 5 && got[3] == 6 && got[5] == 8);
    }
    b = blob_of(r, 0, 18, 4, &n);
    CHECK(b && n == 12 && b[0] == 5 && b[11] == 16);
    b = blob_of(r, 0, 9, 2, &n);
    CHECK(b && n == 6 && memcmp(b, names, 6) == 0);

    /* The texels, tight; the same image twice is one resource. */
    rgl_resource res;
    if (CHECK(rgl_reader_resource(r, 1, &res, NULL) == RGL_OK)) {
        CHECK(res.kind == RGL_RES_BYTES && res.size == 18);
        CHECK(res.size == 18 && res.data[0] == 100 && res.data[8] == 108 && res.data[9] == 112 &&
              res.data[17] == 120);
    }
    trace_cmds body = trace_resource_cmds(r, 2);
    static const char *const lb[] = {"glBegin(mode=GL_LINES)", "glVertex2i(x=1, y=2)", "glEnd()"};
    expect_lines(&body, lb, 3, "list body");
    trace_cmds_free(&body);

    static const char *const f1[] = {
        "glInterleavedArrays(format=GL_T2F_C4UB_V3F, stride=0)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=0, size=3, type=GL_FLOAT, data=<24 bytes>)",
        "@ArrayData(array=GL_COLOR_ARRAY, first=0, size=4, type=GL_UNSIGNED_BYTE, data=<8 bytes>)",
        "@ArrayData(array=GL_TEXTURE_COORD_ARRAY, first=0, size=2, type=GL_FLOAT, data=<16 bytes>)",
        "glDrawArrays(mode=GL_POINTS, first=0, count=2)",
        "glDisableClientState(array=GL_COLOR_ARRAY)",
        "glDisableClientState(array=GL_TEXTURE_COORD_ARRAY)",
        "glBegin(mode=GL_POINTS)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=1, size=3, type=GL_FLOAT, data=<12 bytes>)",
        "glArrayElement(i=1)",
        "glEnd()",
        "glDisableClientState(array=GL_VERTEX_ARRAY)",
        "glEnableClientState(array=GL_NORMAL_ARRAY)",
        "glDisableClientState(array=GL_NORMAL_ARRAY)",
        "gluNewQuadric(quad=#1)",
        "gluQuadricDrawStyle(quad=#1, draw=GLU_LINE)",
        "gluQuadricTexture(quad=#1, texture=GL_TRUE)",
        "gluCylinder(quad=#1, base=1, top=0.5, height=2, slices=8, stacks=3)",
        "gluPartialDisk(quad=#1, inner=0.5, outer=1, slices=6, loops=2, start=45.5, sweep=92.5)",
        "gluDeleteQuadric(quad=#1)",
        "glDeleteLists(list=1, range=3)",
        "glDeleteTextures(textures=[1, 2])",
    };
    c = trace_frame(r, 1, &fi);
    CHECK(c.clean && fi.number == 1);
    expect_lines(&c, f1, sizeof f1 / sizeof f1[0], "frame 1");
    trace_cmds_free(&c);
    b = blob_of(r, 1, 1, 4, &n);
    if (CHECK(b && n == 24)) {
        float got[6];
        memcpy(got, b, sizeof got);
        CHECK(got[0] == 1 && got[2] == 3 && got[3] == 4 && got[5] == 6);
    }
    b = blob_of(r, 1, 3, 4, &n);
    if (CHECK(b && n == 16)) {
        float got[4];
        memcpy(got, b, sizeof got);
        CHECK(got[0] == 0.5f && got[1] == 0.25f && got[2] == 0.75f && got[3] == 1);
    }

    static const char *const f2[] = {
        "rayglFrameBegin(file=\"a.pov\", locx=1, locy=2, locz=3, lookx=4, looky=5, lookz=6, lightx=7, lighty=8, lightz=9)",
        "glVertex3f(x=1, y=2, z=3)",
        "rayglFrameEnd()",
    };
    c = trace_frame(r, 2, &fi);
    expect_lines(&c, f2, 3, "frame 2");
    trace_cmds_free(&c);
    c = trace_frame(r, 3, &fi);
    CHECK(c.count == 1 && fi.number == 3);
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}

static int handler_calls;
static void count_handler(const char *message, void *user)
{
    (void)user;
    CHECK(strncmp(message, "raygl: recording stopped: ", 26) == 0);
    handler_calls++;
}

/* Fails the Nth allocation for N = 1.. until a run has no failure: the
 * program goes on, the recorder fails once, and what was written reads. */
void test_alloc_failures(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/alloc.raygl", dir);
    rayglRecordSetErrorHandler(count_handler, NULL);
    bool clean_run = false;
    for (unsigned long nth = 1; nth < 200 && !clean_run; nth++) {
        handler_calls = 0;
        CHECK(rayglRecordOpen(path) == 0);
        rgl_test_fail_alloc(nth);
        /* A new thread-free stream each round: drop the old one's buffers. */
        for (int k = 0; k < 3; k++) {
            record_frames(false);
            for (int v = 0; v < 20000; v++)
                rayglVertex3f((float)v, 1, 2);
            rayglutSwapBuffers();
        }
        int st = rayglRecordStatus();
        clean_run = st == RAYGL_RECORDING;
        CHECKM(st == RAYGL_RECORDING || st == RAYGL_FAILED, "round %lu: status %d", nth, st);
        CHECKM(handler_calls == (st == RAYGL_FAILED), "round %lu: %d messages", nth, handler_calls);
        CHECK(st != RAYGL_FAILED || rayglRecordError() != NULL);
        rgl_test_fail_alloc(0);
        rayglRecordClose();
        rgl_reader *r = NULL;
        if (rgl_reader_open_file(path, &r, NULL) == RGL_OK) {
            for (size_t f = 0; f < rgl_reader_frame_count(r); f++) {
                rgl_frame_info fi;
                trace_cmds c = trace_frame(r, f, &fi);
                CHECKM(c.clean, "round %lu frame %zu", nth, f);
                trace_cmds_free(&c);
            }
            rgl_reader_destroy(r);
        }
    }
    CHECK(clean_run);
    rayglRecordSetErrorHandler(NULL, NULL);
    unlink(path);
}

/* A frame or a texture past the largest chunk stops recording cleanly,
 * before anything is read or allocated. */
void test_too_large(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/large.raygl", dir);
    rayglRecordSetErrorHandler(count_handler, NULL);
    for (int which = 0; which < 2; which++) {
        handler_calls = 0;
        CHECK(rayglRecordOpen(path) == 0);
        rayglVertex3f(1, 2, 3);
        rayglutSwapBuffers();
        stub_reset();
        if (which == 0) {
            rayglEnableClientState(GL_VERTEX_ARRAY);
            rayglVertexPointer(3, GL_FLOAT, 0, verts);
            rayglDrawArrays(GL_POINTS, 0, 100000000); /* 1.2 GB of vertices */
            rayglDisableClientState(GL_VERTEX_ARRAY);
        } else {
            rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 40000, 40000, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                            verts);
        }
        CHECK(stub_nlog >= 1); /* still forwarded */
        CHECK(rayglRecordStatus() == RAYGL_FAILED);
        CHECK(handler_calls == 1);
        const char *e = rayglRecordError();
        CHECK(e && strstr(e, "larger than a chunk can hold: File too large"));
        rayglRecordClose();
        rgl_reader *r = trace_open(path);
        if (r) {
            CHECK(rgl_reader_frame_count(r) == 1);
            rgl_reader_destroy(r);
        }
    }
    rayglRecordSetErrorHandler(NULL, NULL);
    unlink(path);
}

/* Without a context the recorder applies the unpack state the program set
 * through it: alignment 1 (rows of 9 bytes), then row length, skipped
 * rows and pixels at alignment 4. glPixelStorei is client state: while a
 * list compiles it goes to the frame, not into the body. */
void test_unpack(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/unpack.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    GLubyte tight[18], big[4 * 16];
    for (int i = 0; i < 18; i++)
        tight[i] = (GLubyte)(i + 1);
    for (int i = 0; i < 64; i++)
        big[i] = (GLubyte)i;
    rayglBindTexture(GL_TEXTURE_2D, 1);
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, tight);
    /* rows of 5 RGB pixels = 15 bytes, padded to 16; the 2 x 2 image at
     * pixel 2 of row 1: bytes 16 + 6 .. 16 + 11 and 32 + 6 .. 32 + 11 */
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, big);
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 3); /* invalid: ignored */
    rayglNewList(1, GL_COMPILE);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    rayglEndList();
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_resource res;
    if (CHECK(rgl_reader_resource(r, 1, &res, NULL) == RGL_OK))
        CHECK(res.kind == RGL_RES_BYTES && res.size == 18 && memcmp(res.data, tight, 18) == 0);
    if (CHECK(rgl_reader_resource(r, 2, &res, NULL) == RGL_OK)) {
        static const GLubyte want[12] = {22, 23, 24, 25, 26, 27, 38, 39, 40, 41, 42, 43};
        CHECK(res.size == 12 && memcmp(res.data, want, 12) == 0);
    }
    rgl_frame_info fi;
    trace_cmds f = trace_frame(r, 0, &fi);
    CHECK(trace_cmds_count(&f, RGL_OP_PixelStorei) == 7); /* the list's too, run at once */
    trace_cmds_free(&f);
    trace_cmds body = trace_resource_cmds(r, 3);
    CHECK(trace_cmds_count(&body, RGL_OP_PixelStorei) == 0);
    trace_cmds_free(&body);
    rgl_reader_destroy(r);
}

/* A page that faults on any access, and the page before it readable: a
 * read of one byte more than GL reads, or of any byte of a call GL
 * refuses, kills the test. */
static uint8_t *guard_pages(uint8_t **fault)
{
    long pg = sysconf(_SC_PAGESIZE);
    uint8_t *p = mmap(NULL, (size_t)pg * 2, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                      -1, 0);
    if (!CHECK(p != MAP_FAILED))
        return NULL;
    CHECK(mprotect(p + pg, (size_t)pg, PROT_NONE) == 0);
    memset(p, 0, (size_t)pg);
    *fault = p + pg;
    return p;
}

/* The dump lines of frame 0 of path that name op (a prefix). */
static size_t count_lines(const trace_cmds *c, const char *prefix)
{
    size_t n = 0;
    for (long i = trace_cmds_find(c, 0, prefix); i >= 0; i = trace_cmds_find(c, (size_t)i + 1, prefix))
        n++;
    return n;
}

/* Every pixel and draw call GL refuses reads nothing (its pointer faults),
 * an enum RayGL does not know leaves @Skipped, and an image that ends at
 * a page's end is read to its last byte and no further: the last row's
 * alignment padding and a bitmap's bits past its width are not read. The
 * unpack state is applied whole: skipped pixels inside a bitmap byte,
 * GL_UNPACK_LSB_FIRST and GL_UNPACK_SWAP_BYTES. */
void test_pixel_rules(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/rules.raygl", dir);
    uint8_t *bad, *page = guard_pages(&bad);
    if (!page)
        return;
    long pg = sysconf(_SC_PAGESIZE);
    CHECK(rayglRecordOpen(path) == 0);
    rayglBindTexture(GL_TEXTURE_2D, 1);
    rayglDisableClientState(GL_VERTEX_ARRAY); /* whatever the tests before left */
    rayglDisableClientState(GL_NORMAL_ARRAY);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 0); /* test_unpack's, kept as GL keeps them */
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    stub_reset();
    /* Refused by GL: nothing read, everything forwarded. */
    rayglTexImage2D(0x1234, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 2, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGB, GL_BITMAP, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA_INTEGER, GL_FLOAT, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, -1, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 64, 64, GL_RGB, GL_UNSIGNED_INT_8_8_8_8, bad);
    CHECK(raygluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 0, 64, GL_RGBA, GL_UNSIGNED_BYTE, bad) == 0);
    raygluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 64, 64, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, bad);
    rayglBegin(GL_POINTS); /* no texture call inside glBegin/glEnd */
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglEnd();
    /* Draws GL refuses, or that draw nothing, read no element. */
    rayglEnableClientState(GL_COLOR_ARRAY);
    rayglColorPointer(4, GL_UNSIGNED_BYTE, 0, bad);
    rayglDrawArrays(GL_TRIANGLES, 0, 1000); /* no vertex array: nothing drawn */
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglVertexPointer(3, GL_FLOAT, 0, bad);
    rayglDrawArrays(0x20, 0, 1000);
    rayglDrawElements(0x20, 1000, GL_UNSIGNED_INT, bad);
    rayglDrawRangeElements(0x20, 0, 9, 1000, GL_UNSIGNED_INT, bad);
    static const GLint mf[1] = {0};
    static const GLsizei mc[1] = {1000};
    const void *const mi[1] = {bad};
    rayglMultiDrawArrays(0x20, mf, mc, 1);
    rayglMultiDrawElements(0x20, mc, GL_UNSIGNED_INT, mi, 1);
    rayglBegin(GL_POINTS);
    rayglDrawArrays(GL_POINTS, 0, 1000);
    rayglDrawElements(GL_POINTS, 1000, GL_UNSIGNED_INT, bad);
    rayglEnd();
    /* GL's, not RayGL's: forwarded, @Skipped. */
    rayglDrawArrays(GL_TRIANGLES_ADJACENCY, 0, 1000);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, 0x9999, GL_UNSIGNED_BYTE, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, 0x9999, bad);
    rayglTexImage2D(GL_TEXTURE_2D, 0, 0x9999, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, bad);
    rayglDisableClientState(GL_COLOR_ARRAY);
    rayglDisableClientState(GL_VERTEX_ARRAY);
    CHECK(stub_nlog == 38);
    /* A *v call reads the values of its pname only when the call takes
     * it: one float before the fault, names of other calls that take 4. */
    float *one = (float *)(void *)(bad - sizeof(float));
    *one = 2;
    rayglFogfv(GL_AMBIENT, one);
    rayglLightfv(GL_LIGHT0, GL_FOG_COLOR, one);
    rayglMaterialfv(GL_FRONT, GL_POSITION, one);
    rayglTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_BORDER_COLOR, one);
    rayglTexGenfv(GL_S, GL_TEXTURE_ENV_COLOR, one);
    rayglLightModelfv(GL_EYE_PLANE, one);
    rayglTexParameterfv(GL_TEXTURE_2D, GL_SPECULAR, one);
    rayglFogfv(GL_FOG_DENSITY, one); /* its own: 1 value */

    /* Exactly what GL reads, up to the page's end. 3 x 2 RGB at alignment
     * 4: a row of 12 bytes, then the last row's 9 (no padding read). */
    uint8_t *rgb = bad - 21;
    for (int i = 0; i < 21; i++)
        rgb[i] = (uint8_t)(i + 1);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    /* A 5-pixel bitmap row from bit 6 on, least significant bit first: two
     * bytes, the second the page's last. Pixels 6, 7 of byte 0 (bits 6, 7
     * from the bottom) and 8 .. 10 of byte 1 (bits 0 .. 2): 1 0 1 1 0. */
    uint8_t *bits = bad - 2;
    bits[0] = 0x40;
    bits[1] = 0x03 | 0xf8;
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 6);
    rayglPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 1, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    rayglPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    /* Two shorts, bytes swapped. */
    uint8_t *shorts = bad - 4;
    shorts[0] = 1, shorts[1] = 2, shorts[2] = 3, shorts[3] = 4;
    rayglPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 1, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT,
                    shorts);
    rayglPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    /* A 4-byte element type at alignment 8: rows padded to 8 bytes. */
    uint8_t *rows = bad - 12;
    for (int i = 0; i < 12; i++)
        rows[i] = (uint8_t)(0x10 + i);
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rows);
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (r) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, 0, &fi);
        CHECK(c.clean);
        CHECK(count_lines(&c, "glTexImage") == 4);
        CHECK(count_lines(&c, "glTexSubImage") == 0 && count_lines(&c, "gluBuild2DMipmaps") == 0);
        CHECK(count_lines(&c, "glDraw") == 0 && count_lines(&c, "glMultiDraw") == 0);
        CHECK(count_lines(&c, "@ArrayData") == 0);
        CHECK(count_lines(&c, "glFogfv(pname=GL_AMBIENT, params=[])") == 1);
        CHECK(count_lines(&c, "glLightfv(light=GL_LIGHT0, pname=GL_FOG_COLOR, params=[])") == 1);
        CHECK(count_lines(&c, "glFogfv(pname=GL_FOG_DENSITY, params=[2])") == 1);
        CHECK(count_lines(&c, "@Skipped(opcode=0x7e, reason=0x1)") == 1); /* glDrawArrays */
        CHECK(count_lines(&c, "@Skipped(opcode=0xb5, reason=0x1)") == 3); /* glTexImage2D */
        if (count_lines(&c, "@Skipped") != 4)
            trace_cmds_print(&c, "rules");
        trace_cmds_free(&c);
        rgl_resource res;
        if (CHECK(rgl_reader_resource(r, 1, &res, NULL) == RGL_OK)) {
            static const uint8_t want[18] = {1, 2, 3, 4, 5, 6, 7, 8, 9,
                                             13, 14, 15, 16, 17, 18, 19, 20, 21};
            CHECK(res.size == 18 && memcmp(res.data, want, 18) == 0);
        }
        if (CHECK(rgl_reader_resource(r, 2, &res, NULL) == RGL_OK))
            CHECKM(res.size == 1 && res.data[0] == 0xb0, "bitmap %zu bytes, %#x", (size_t)res.size,
                   res.size ? res.data[0] : 0u);
        if (CHECK(rgl_reader_resource(r, 3, &res, NULL) == RGL_OK))
            CHECK(res.size == 4 && res.data[0] == 2 && res.data[1] == 1 && res.data[3] == 3);
        if (CHECK(rgl_reader_resource(r, 4, &res, NULL) == RGL_OK))
            CHECK(res.size == 8 && res.data[3] == 0x13 && res.data[4] == 0x18 &&
                  res.data[7] == 0x1b);
        rgl_reader_destroy(r);
    }
    munmap(page, (size_t)pg * 2);
    if (!check_failures)
        unlink(path);
}

static size_t forwarded(const char *name)
{
    size_t n = 0;
    for (size_t i = 0; i < stub_nlog && i < STUB_LOG_MAX; i++)
        n += strcmp(stub_log[i].name, name) == 0;
    return n;
}

/* glBitmap, glDrawPixels, glCopyPixels and glDrawBuffer
 * (record/entry_raster.c): the bits GL reads with the unpack state undone,
 * nothing read or recorded for a call GL refuses (its pointer faults),
 * everything forwarded, glCopyPixels without a context marked @Skipped,
 * glDrawBuffer with no visual where there is no context. */
void test_raster(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/raster.raygl", dir);
    uint8_t *bad, *page = guard_pages(&bad);
    if (!page)
        return;
    long pg = sysconf(_SC_PAGESIZE);
    CHECK(rayglRecordOpen(path) == 0);
    stub_reset();
    /* 5 x 2 bits from bit 3 of each byte, least significant bit first;
     * the rows end at the page's end. */
    uint8_t *bits = bad - 2;
    bits[0] = 0xa8; /* bits 3, 5, 7: pixels 0, 2, 4 */
    bits[1] = 0x50; /* bits 4, 6: pixels 1, 3 */
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    rayglPixelStorei(GL_UNPACK_LSB_FIRST, 1);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    rayglWindowPos2i(4, 5);
    rayglBitmap(5, 2, 0.5f, 1, 6, 0, bits);
    rayglPixelStorei(GL_UNPACK_LSB_FIRST, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    rayglBitmap(0, 0, 0, 0, 6, 0, NULL); /* moves only */
    /* Refused: nothing read, nothing recorded. */
    rayglBitmap(-1, 2, 0, 0, 0, 0, bad);
    rayglDrawPixels(4, -1, GL_RGB, GL_UNSIGNED_BYTE, bad);
    rayglDrawPixels(4, 4, GL_RGB, GL_BITMAP, bad);
    rayglCopyPixels(0, 0, 4, 4, GL_RGB);
    rayglBegin(GL_POINTS);
    rayglBitmap(8, 8, 0, 0, 0, 0, bad);
    rayglDrawPixels(4, 4, GL_RGB, GL_UNSIGNED_BYTE, bad);
    rayglCopyPixels(0, 0, 4, 4, GL_COLOR);
    rayglEnd();
    /* 2 x 1 RGB ending at the page's end. */
    uint8_t *rgb = bad - 6;
    for (int i = 0; i < 6; i++)
        rgb[i] = (uint8_t)(10 + i);
    rayglDrawPixels(2, 1, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    rayglCopyPixels(1, 2, 3, 4, GL_COLOR); /* no context: not read */
    rayglCopyPixels(1, 2, 3, 4, GL_DEPTH);
    rayglDrawBuffer(GL_FRONT); /* no context: the visual unknown */
    rayglBegin(GL_POINTS);
    rayglDrawBuffer(GL_BACK); /* refused between glBegin and glEnd */
    rayglEnd();
    CHECK(forwarded("glBitmap") == 4 && forwarded("glDrawPixels") == 4 &&
          forwarded("glCopyPixels") == 4 && forwarded("glDrawBuffer") == 2);
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 4); /* GL's default, for the tests after */
    rayglFrameEnd();
    rayglRecordClose();
    munmap(page, (size_t)pg * 2);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(count_lines(&c, "glWindowPos2i(x=4, y=5)") == 1);
    CHECK(count_lines(&c, "glBitmap(") == 2);
    CHECK(count_lines(&c, "glBitmap(width=5, height=2, xorig=0.5, yorig=1, xmove=6, ymove=0, bitmap=#") == 1);
    CHECK(count_lines(&c, "glBitmap(width=0, height=0, xorig=0, yorig=0, xmove=6, ymove=0, bitmap=#0)") == 1);
    CHECK(count_lines(&c, "glDrawPixels(") == 1);
    CHECK(count_lines(&c, "glDrawPixels(width=2, height=1, format=GL_RGB, type=GL_UNSIGNED_BYTE, pixels=#") == 1);
    CHECK(count_lines(&c, "glCopyPixels(") == 1);
    CHECK(count_lines(&c, "glCopyPixels(x=1, y=2, width=3, height=4, type=GL_DEPTH, pixels=#0)") == 1);
    CHECK(count_lines(&c, "@Skipped(opcode=0x14e, reason=0x2)") == 1);
    CHECK(count_lines(&c, "glDrawBuffer(") == 1);
    CHECK(count_lines(&c, "glDrawBuffer(mode=GL_FRONT, visual=0)") == 1);
    trace_cmds_free(&c);
    rgl_resource res;
    /* The bitmap: pixels 1 0 1 0 1 and 0 1 0 1 0, most significant bit first. */
    if (CHECK(rgl_reader_resource(r, 1, &res, NULL) == RGL_OK))
        CHECK(res.kind == RGL_RES_BYTES && res.size == 2 && res.data[0] == 0xa8 &&
              res.data[1] == 0x50);
    if (CHECK(rgl_reader_resource(r, 2, &res, NULL) == RGL_OK))
        CHECK(res.size == 6 && res.data[0] == 10 && res.data[5] == 15);
    rgl_reader_destroy(r);
}

/* Texture copies and 3D images without a context (record/entry_texcopy.c):
 * a copy is recorded with no pixels (nothing to read them from), one GL
 * refuses is not recorded; glTexImage3D reads exactly its image (it ends
 * at a page's end), nothing for a call GL refuses (its pointer faults),
 * and an unknown type is marked @Skipped; everything is forwarded. */
void test_texcopy_nocontext(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/texcopy.raygl", dir);
    uint8_t *bad, *page = guard_pages(&bad);
    if (!page)
        return;
    long pg = sysconf(_SC_PAGESIZE);
    CHECK(rayglRecordOpen(path) == 0);
    stub_reset();
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 2, 3, 4, 0);
    rayglCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 2, 3, 4);
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 2, -3, 4, 0);
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 2, 3, 4, 5);
    rayglBegin(GL_POINTS);
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 2, 3, 4, 0);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 1, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, bad);
    rayglEnd();
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    uint8_t *vox = bad - 12;
    for (int i = 0; i < 12; i++)
        vox[i] = (uint8_t)(40 + i);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 1, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, vox);
    rayglTexImage3D(GL_TEXTURE_2D, 0, GL_RGB, 2, 1, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, bad);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 1, -2, 0, GL_RGB, GL_UNSIGNED_BYTE, bad);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 1, 2, 0, GL_RGB, 0x1234, bad);
    rayglTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 1, -1, GL_RGB, GL_UNSIGNED_BYTE, bad);
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    CHECK(forwarded("glCopyTexImage2D") == 4 && forwarded("glCopyTexSubImage2D") == 1 &&
          forwarded("glTexImage3D") == 5 && forwarded("glTexSubImage3D") == 1);
    rayglFrameEnd();
    rayglRecordClose();
    munmap(page, (size_t)pg * 2);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(count_lines(&c, "glCopyTexImage2D(") == 1);
    CHECK(count_lines(&c, "glCopyTexImage2D(target=GL_TEXTURE_2D, level=0, internalformat=6407, "
                          "x=1, y=2, width=3, height=4, border=0, pixels=#0)") == 1);
    CHECK(count_lines(&c, "glCopyTexSubImage2D(") == 1);
    CHECK(count_lines(&c, "glTexImage3D(") == 1);
    CHECK(count_lines(&c, "glTexSubImage3D(") == 0);
    char skipped[64];
    snprintf(skipped, sizeof skipped, "@Skipped(opcode=0x%x, reason=0x%x)",
             (unsigned)RGL_OP_TexImage3D, (unsigned)RGL_SKIP_UNKNOWN_ENUM);
    CHECK(count_lines(&c, skipped) == 1);
    trace_cmds_done(&c, "texcopy");
    rgl_resource res;
    if (CHECK(rgl_reader_resource(r, 1, &res, NULL) == RGL_OK))
        CHECK(res.kind == RGL_RES_BYTES && res.size == 12 && res.data[0] == 40 &&
              res.data[11] == 51);
    rgl_reader_destroy(r);
}

/* Texture-coordinate arrays per client unit: glClientActiveTexture is
 * recorded and forwarded (a unit past GL's refused: forwarded only), each
 * enabled unit's @ArrayData follows a glClientActiveTexture record naming
 * it, and the program's client unit is named again after them. */
void test_multitex_arrays(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/multitex.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    static const float v[4] = {1, 2, 3, 4}, t0[4] = {5, 6, 7, 8}, t1[2] = {9, 10};
    rayglVertexPointer(2, GL_FLOAT, 0, v);
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglTexCoordPointer(2, GL_FLOAT, 0, t0);
    rayglEnableClientState(GL_TEXTURE_COORD_ARRAY);
    rayglClientActiveTexture(GL_TEXTURE2);
    rayglTexCoordPointer(1, GL_FLOAT, 0, t1);
    rayglEnableClientState(GL_TEXTURE_COORD_ARRAY);
    stub_reset();
    rayglClientActiveTextureARB(GL_TEXTURE0 + 40);
    CHECK(stub_nlog == 1 && strcmp(stub_log[0].name, "glClientActiveTextureARB") == 0);
    rayglDrawArrays(GL_POINTS, 0, 2);
    rayglFrameEnd();
    /* Back to the initial client state for the tests after this one. */
    rayglDisableClientState(GL_TEXTURE_COORD_ARRAY);
    rayglClientActiveTexture(GL_TEXTURE0);
    rayglDisableClientState(GL_TEXTURE_COORD_ARRAY);
    rayglDisableClientState(GL_VERTEX_ARRAY);
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    static const char *const f0[] = {
        "glVertexPointer(size=2, type=GL_FLOAT, stride=0)",
        "glEnableClientState(array=GL_VERTEX_ARRAY)",
        "glTexCoordPointer(size=2, type=GL_FLOAT, stride=0)",
        "glEnableClientState(array=GL_TEXTURE_COORD_ARRAY)",
        "glClientActiveTexture(texture=GL_TEXTURE2)",
        "glTexCoordPointer(size=1, type=GL_FLOAT, stride=0)",
        "glEnableClientState(array=GL_TEXTURE_COORD_ARRAY)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=0, size=2, type=GL_FLOAT, data=<16 bytes>)",
        "glClientActiveTexture(texture=GL_TEXTURE0)",
        "@ArrayData(array=GL_TEXTURE_COORD_ARRAY, first=0, size=2, type=GL_FLOAT, data=<16 bytes>)",
        "glClientActiveTexture(texture=GL_TEXTURE2)",
        "@ArrayData(array=GL_TEXTURE_COORD_ARRAY, first=0, size=1, type=GL_FLOAT, data=<8 bytes>)",
        "glDrawArrays(mode=GL_POINTS, first=0, count=2)",
        "rayglFrameEnd()",
    };
    trace_cmds c = trace_frame(r, 0, &fi);
    expect_lines(&c, f0, sizeof f0 / sizeof f0[0], "multitexture frame");
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
}

/* One frame of n vertices, each with a colour: 2n + 3 commands (Begin, End,
 * SwapBuffers). */
static void big_frame(int n, float tag)
{
    rayglBegin(GL_TRIANGLES);
    for (int v = 0; v < n; v++) {
        rayglColor3f((float)v, tag, 0.5f);
        rayglVertex3f(tag, (float)v, 1);
    }
    rayglEnd();
    rayglutSwapBuffers();
}

/* Frames keep the buffers of the frames before them: after the first frame
 * of a size (which grows the buffer past the huge-page threshold), frames
 * of that size allocate nothing; a larger one does (the count can fail).
 * The frames, checksummed in three lanes, read back whole. */
void test_buffer_reuse(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/reuse.raygl", dir);
    enum { N = 150000 }; /* 3.9 MB a frame */
    CHECK(rayglRecordOpen(path) == 0);
    big_frame(N, 0);
    unsigned long first = rgl_test_alloc_count();
    for (int f = 1; f < 4; f++) {
        big_frame(N, (float)f);
        CHECKM(rgl_test_alloc_count() == first, "frame %d: %lu allocations after the first frame",
               f, rgl_test_alloc_count() - first);
    }
    big_frame(2 * N, 4);
    CHECKM(rgl_test_alloc_count() > first, "a larger frame grew the buffer");
    rayglRecordClose();
    CHECK(rayglRecordStatus() != RAYGL_FAILED);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 5);
    for (size_t f = 0; f < rgl_reader_frame_count(r); f++) {
        rgl_frame_info fi;
        if (!CHECKM(rgl_reader_frame(r, f, &fi, NULL) == RGL_OK, "frame %zu reads", f))
            continue;
        rgl_cmd_iter it;
        rgl_cmd cmd;
        rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
        size_t count = 0;
        float tag = -1;
        uint32_t last = 0;
        rgl_status st;
        while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
            if (cmd.opcode == RGL_OP_Color3f)
                tag = (float)cmd.arg[1].v.f;
            last = cmd.opcode;
            count++;
        }
        size_t want = 2 * (size_t)(f == 4 ? 2 * N : N) + 3;
        CHECKM(st == RGL_END && count == want, "frame %zu: %zu commands, want %zu", f, count,
               want);
        CHECKM(tag == (float)f, "frame %zu: last colour tag %g", f, (double)tag);
        CHECKM(last == RGL_OP_SwapBuffers, "frame %zu: last opcode 0x%x", f, last);
    }
    rgl_reader_destroy(r);

    /* Frames past RGL_DIRECT_MIN have their aligned middle written with
     * O_DIRECT (where the file system takes it); RAYGL_DIRECT=0 writes
     * everything through the page cache. The bytes are the same. */
    char path2[128];
    snprintf(path2, sizeof path2, "%s/reuse-buffered.raygl", dir);
    setenv("RAYGL_DIRECT", "0", 1);
    CHECK(rayglRecordOpen(path2) == 0);
    unsetenv("RAYGL_DIRECT");
    for (int f = 0; f < 4; f++)
        big_frame(N, (float)f);
    big_frame(2 * N, 4);
    rayglRecordClose();
    FILE *a = fopen(path, "rb"), *b = fopen(path2, "rb");
    if (CHECK(a && b)) {
        size_t n = 0, diff = 0;
        int ca, cb;
        do {
            ca = getc(a);
            cb = getc(b);
            diff += ca != cb;
            n++;
        } while (ca != EOF && cb != EOF);
        CHECKM(diff == 0 && n > 20u * N, "%zu of %zu bytes differ", diff, n);
    }
    if (a)
        fclose(a);
    if (b)
        fclose(b);
    unlink(path);
    unlink(path2);
}
