/* test_osmesa.c: records two frames with a real (software) GL context and
 * reads the trace back: immediate-mode drawing, a display list, a texture
 * and a GLU sphere. Checks the frame flags, the state snapshot, the
 * resolved matrices and the dump text of a few commands. Also (the paper's
 * example) plain glLoadIdentity/glTranslatef/glRotatef between raygl calls
 * must come out as an @Matrix with the resolved modelview. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GL/osmesa.h>

#include "check.h"
#include "wire.h"
#include "raygl.h"

static unsigned char pixels[64 * 64 * 4];

static void draw_frame(GLuint list, GLUquadric *q, float dx)
{
    rayglClearColor(0.25f, 0.5f, 0.75f, 1);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(dx, 0, -5);
    rayglBegin(GL_TRIANGLES);
    rayglColor3f(1, 0, 0);
    rayglNormal3f(0, 0, 1);
    rayglVertex3f(0, 0, 0);
    rayglVertex3f(1, 0, 0);
    rayglVertex3f(0, 1, 0);
    rayglEnd();
    rayglCallList(list);
    raygluSphere(q, 0.5, 12, 8);
    rayglutSwapBuffers();
}

static void test_two_frames(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    CHECK(rayglRecordStatus() == RAYGL_RECORDING);

    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglFrustum(-1, 1, -1, 1, 1, 10);
    rayglEnable(GL_LIGHTING);
    rayglEnable(GL_LIGHT0);
    const GLfloat lpos[4] = {1, 2, 3, 0};
    rayglLightfv(GL_LIGHT0, GL_POSITION, lpos);

    GLuint list = rayglGenLists(1);
    CHECK(list != 0);
    rayglNewList(list, GL_COMPILE);
    rayglBegin(GL_QUADS);
    rayglVertex2f(0, 0);
    rayglVertex2f(1, 0);
    rayglVertex2f(1, 1);
    rayglVertex2f(0, 1);
    rayglEnd();
    rayglEndList();

    GLuint tex = 0;
    rayglGenTextures(1, &tex);
    CHECK(tex != 0);
    rayglBindTexture(GL_TEXTURE_2D, tex);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    GLubyte texels[3 * 3 * 3];
    for (int i = 0; i < 27; i++)
        texels[i] = (GLubyte)(i * 9);
    /* Rows of 9 bytes, padded to 12 under the default alignment of 4. */
    GLubyte padded[3 * 12];
    for (int y = 0; y < 3; y++)
        memcpy(padded + 12 * y, texels + 9 * y, 9);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 3, 0, GL_RGB, GL_UNSIGNED_BYTE, padded);
    rayglEnable(GL_TEXTURE_2D);

    /* A light placed under a modelview: GL keeps it in eye space. */
    rayglMatrixMode(GL_MODELVIEW);
    rayglPushMatrix();
    rayglTranslatef(0, 0, -5);
    const GLfloat l1pos[4] = {0, 1, 0, 1};
    rayglLightfv(GL_LIGHT1, GL_POSITION, l1pos);
    rayglPopMatrix();

    GLUquadric *q = raygluNewQuadric();
    draw_frame(list, q, 0);
    draw_frame(list, q, 1);
    /* Starts a third frame, written by the close. */
    raygluDeleteQuadric(q);
    rayglRecordClose();
    CHECK(rayglRecordStatus() == RAYGL_DISABLED);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 3);
    CHECK(rgl_reader_damage_count(r) == 0);
    size_t isz;
    const char *info = rgl_reader_info(r, &isz);
    CHECK(info && strstr(info, "program=test_osmesa"));
    uint32_t states[2] = {0, 0};
    for (size_t f = 0; f < 2 && f < rgl_reader_frame_count(r); f++) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, f, &fi);
        CHECK(c.clean);
        CHECK(fi.number == f);
        CHECK(fi.stream == 1);
        CHECK(fi.flags == RGL_FRAME_LIVE_CONTEXT);
        CHECK(fi.state != 0);
        states[f] = fi.state;
        if (f == 0) {
            CHECK(trace_cmds_find(&c, 0, "glGenLists(range=1, first=1)") >= 0);
            long nl = trace_cmds_find(&c, 0, "glNewList(list=1, mode=GL_COMPILE, body=#");
            CHECK(nl >= 0 && trace_cmds_find(&c, (size_t)nl, "glEndList()") == nl + 1);
            CHECK(trace_cmds_find(&c, 0, "glTexImage2D(target=GL_TEXTURE_2D, level=0") >= 0);
            CHECK(trace_cmds_find(&c, 0, "gluNewQuadric(quad=#1)") >= 0);
        }
        long b = trace_cmds_find(&c, 0, "glBegin(mode=GL_TRIANGLES)");
        CHECK(b > 0);
        /* The resolved matrices come right before the primitive. */
        CHECK(b > 1 && strncmp(c.lines[b - 2], "@Matrix(mode=GL_MODELVIEW", 25) == 0);
        CHECK(b > 1 && strncmp(c.lines[b - 1], "@Matrix(mode=GL_PROJECTION", 26) == 0);
        /* Unchanged matrices are not recorded again for the later shapes. */
        CHECK(trace_cmds_count(&c, RGL_OP_Matrix) == 2);
        CHECK(trace_cmds_find(&c, 0, "@Matrix(mode=GL_PROJECTION") >= 0);
        CHECK(trace_cmds_find(&c, 0, "glVertex3f(x=1, y=0, z=0)") > b);
        CHECK(trace_cmds_find(&c, 0, "gluSphere(quad=#1, radius=0.5, slices=12, stacks=8)") > b);
        CHECK(trace_cmds_count(&c, RGL_OP_SwapBuffers) == 1);
        CHECK(c.count > 0 && c.opcodes[c.count - 1] == RGL_OP_SwapBuffers);
        if (f == 1) {
            char want[128];
            snprintf(want, sizeof want, "@Matrix(mode=GL_MODELVIEW, m=[1, 0, 0, 0, 0, 1, 0, 0, "
                                        "0, 0, 1, 0, 1, 0, -5, 1])");
            CHECK(trace_cmds_find(&c, 0, want) >= 0);
        }
        trace_cmds_done(&c, "frame");
    }
    rgl_frame_info fi;
    trace_cmds last = trace_frame(r, 2, &fi);
    CHECK(last.count == 1 && trace_cmds_find(&last, 0, "gluDeleteQuadric(quad=#1)") == 0);
    trace_cmds_free(&last);
    /* Two snapshots: the first from GL's defaults (the frame starts with
     * the first call), the second with what frame 0 set up. */
    for (int f = 0; f < 2; f++) {
        trace_cmds s = trace_resource_cmds(r, states[f]);
        CHECK(s.clean);
        CHECK(s.count > 50);
        CHECK(trace_cmds_find(&s, 0, "glMatrixMode(mode=GL_MODELVIEW)") == 0);
        CHECK(trace_cmds_find(&s, 0, "glLoadIdentity()") == 1);
        CHECK(trace_cmds_find(&s, 0, "glLoadMatrixf(") > 0);
        CHECK(trace_cmds_find(&s, 0, "glViewport(x=0, y=0, width=64, height=64)") > 0);
        /* Restores the matrix mode current at the frame start after the
         * matrices; only format 1.4's rows follow (a 1.3 reader stops there). */
        size_t mm = s.count;
        for (size_t i = 0; i < s.count; i++)
            if (strncmp(s.lines[i], "glMatrixMode(", 13) == 0)
                mm = i;
        CHECK(mm < s.count && strcmp(s.lines[mm], "glMatrixMode(mode=GL_MODELVIEW)") == 0);
        static const char *const tail[] = {"glBlendColor(", "glBlendFuncSeparate(",
                                           "glBlendEquation", "glLogicOp(", "glPixelTransfer",
                                           "glPixelMap", "glStencilFuncSeparate(",
                                           "glStencilOpSeparate(", "glStencilMaskSeparate(",
                                           "glDrawBuffer("};
        for (size_t i = mm + 1; i < s.count; i++) {
            bool known = false;
            for (size_t t = 0; t < sizeof tail / sizeof tail[0]; t++)
                known = known || strncmp(s.lines[i], tail[t], strlen(tail[t])) == 0;
            CHECKM(known, "after the matrices: %s", s.lines[i]);
        }
        CHECK(trace_cmds_find(&s, mm, "glBlendColor(") > (long)mm);
        if (f == 1) {
            /* Set during frame 0: in eye space, under an identity modelview. */
            CHECK(trace_cmds_find(&s, 0, "glLightfv(light=GL_LIGHT0, pname=GL_POSITION, params=[1, 2, 3, 0])") == 2);
            CHECK(trace_cmds_find(&s, 0, "glLightfv(light=GL_LIGHT1, pname=GL_POSITION, params=[0, 1, -5, 1])") == 4);
            CHECK(trace_cmds_find(&s, 0, "glEnable(cap=GL_LIGHTING)") >= 0);
            CHECK(trace_cmds_find(&s, 0, "glClearColor(red=0.25, green=0.5, blue=0.75, alpha=1)") >= 0);
            CHECK(trace_cmds_find(&s, 0, "glLoadMatrixf(m=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1])") >= 0);
            CHECK(trace_cmds_find(&s, 0, "glEnable(cap=GL_TEXTURE_2D)") >= 0);
            CHECK(trace_cmds_find(&s, 0, "glNewList(list=1, mode=GL_COMPILE, body=#") >= 0);
            CHECK(trace_cmds_find(&s, 0, "glTexImage2D(target=GL_TEXTURE_2D, level=0") >= 0);
            CHECK(trace_cmds_find(&s, 0, "glTexParameteri(target=GL_TEXTURE_2D, pname=GL_TEXTURE_MIN_FILTER, param=") >= 0);
            CHECK(trace_cmds_find(&s, 0, "glBindTexture(target=GL_TEXTURE_2D, texture=1)") >= 0);
        }
        trace_cmds_done(&s, "snapshot");
    }
    /* The texels went in tightly packed. */
    rgl_resource res;
    rgl_error err;
    bool found = false;
    for (uint32_t id = 1; id < 16; id++) {
        if (rgl_reader_resource(r, id, &res, &err) == RGL_OK && res.kind == RGL_RES_BYTES) {
            found = true;
            CHECK(res.size == sizeof texels && memcmp(res.data, texels, sizeof texels) == 0);
        }
    }
    CHECK(found);
    rgl_reader_destroy(r);

    /* A closed trace ends with the 28-byte END chunk naming the INDEX. */
    FILE *f = fopen(path, "rb");
    uint8_t buf[1 << 16];
    size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
    if (f)
        fclose(f);
    if (CHECK(n > 28 && n < sizeof buf)) {
        const uint8_t *end = buf + n - 28;
        CHECK(memcmp(end, "\xC3RGC\x05\x00\x00\x00\x08\x00\x00\x00", 12) == 0);
        uint64_t index = rgl_get_u64(end + 16);
        CHECK(index < n - 28 && memcmp(buf + index, "\xC3RGC\x04", 5) == 0);
    }
}

/* Applies the RGBA TexImage2D/TexSubImage2D records of a 4x4 level 0 in a
 * command sequence to img. */
static void apply_texels(rgl_reader *r, const uint8_t *data, size_t size, uint64_t offset,
                         GLubyte img[4 * 4 * 4])
{
    rgl_cmd_iter it;
    static rgl_cmd cmd;
    rgl_cmd_iter_init(&it, data, size, offset);
    while (rgl_cmd_next(&it, &cmd) == RGL_OK) {
        bool full = cmd.opcode == RGL_OP_TexImage2D;
        if (!full && cmd.opcode != RGL_OP_TexSubImage2D)
            continue;
        rgl_resource px;
        uint32_t id = (uint32_t)rgl_arg_i(&cmd.arg[8], 0);
        int x = full ? 0 : (int)rgl_arg_i(&cmd.arg[2], 0);
        int y = full ? 0 : (int)rgl_arg_i(&cmd.arg[3], 0);
        int w = (int)rgl_arg_i(&cmd.arg[full ? 3 : 4], 0);
        int h = (int)rgl_arg_i(&cmd.arg[full ? 4 : 5], 0);
        if (!CHECK(rgl_arg_i(&cmd.arg[6], 0) == GL_RGBA) ||
            !CHECK(rgl_reader_resource(r, id, &px, NULL) == RGL_OK) ||
            !CHECK(px.size == (size_t)(w * h * 4)))
            continue;
        for (int row = 0; row < h; row++)
            memcpy(img + 16 * (y + row) + 4 * x, px.data + 4 * w * row, (size_t)(4 * w));
    }
}

/* A texture updated every frame: its definition in the snapshot stays
 * bounded (read back and compacted), and still holds its latest texels. */
static void test_texture_updates(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    GLuint tex;
    rayglGenTextures(1, &tex);
    rayglBindTexture(GL_TEXTURE_2D, tex);
    GLubyte img[4 * 4 * 4] = {0};
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    const int frames = 300;
    for (int f = 0; f < frames; f++) {
        GLubyte texel[4] = {(GLubyte)f, (GLubyte)(f >> 8), 7, 255};
        rayglTexSubImage2D(GL_TEXTURE_2D, 0, f % 4, (f / 4) % 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                           texel);
        rayglutSwapBuffers();
    }
    rayglRecordClose();
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == (size_t)frames);
    rgl_frame_info fi;
    if (CHECK(rgl_reader_frame(r, (size_t)frames - 1, &fi, NULL) == RGL_OK)) {
        trace_cmds s = trace_resource_cmds(r, fi.state);
        size_t subs = trace_cmds_count(&s, RGL_OP_TexSubImage2D);
        CHECKM(subs < 200, "%zu sub-images in the last snapshot", subs);
        /* Replaying the snapshot's definition and then the frame gives the
         * texels GL holds. */
        GLubyte want[4 * 4 * 4], got[4 * 4 * 4];
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, want);
        memset(got, 0, sizeof got);
        rgl_resource res;
        if (CHECK(rgl_reader_resource(r, fi.state, &res, NULL) == RGL_OK))
            apply_texels(r, res.data, res.size, res.data_offset, got);
        apply_texels(r, fi.commands, fi.commands_size, fi.commands_offset, got);
        CHECK(memcmp(got, want, sizeof want) == 0);
        trace_cmds_free(&s);
    }
    rgl_reader_destroy(r);
}

/* The paper's example: plain GL matrix calls, then a raygl primitive. */
static void test_paper_example(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(45, 45, 45);
    glRotatef(45, 1, -1, 0);
    rayglBegin(GL_POINTS);
    rayglVertex3f(0, 0, 0);
    rayglEnd();
    rayglFrameEnd();
    rayglRecordClose();

    static const float want[16] = {0.853553f, -0.146447f, 0.5f, 0, -0.146447f, 0.853553f, 0.5f, 0,
                                   -0.5f, -0.5f, 0.707107f, 0, 45, 45, 45, 1};
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 1);
    rgl_frame_info fi;
    if (rgl_reader_frame(r, 0, &fi, NULL) == RGL_OK) {
        rgl_cmd_iter it;
        static rgl_cmd cmd;
        bool seen = false;
        rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
        while (rgl_cmd_next(&it, &cmd) == RGL_OK) {
            if (cmd.opcode != RGL_OP_Matrix || rgl_arg_i(&cmd.arg[0], 0) != GL_MODELVIEW)
                continue;
            seen = true;
            for (int k = 0; k < 16; k++)
                CHECKM(fabs(rgl_arg_f(&cmd.arg[1], (uint32_t)k) - want[k]) < 1e-5,
                       "m[%d] = %g, want %g", k, rgl_arg_f(&cmd.arg[1], (uint32_t)k), want[k]);
        }
        CHECK(seen);
    }
    rgl_reader_destroy(r);
}

/* The @Snapshot of frame i decoded (top row first), or NULL. */
static uint8_t *frame_snapshot(rgl_reader *r, size_t i, rgl_snapshot *snap)
{
    rgl_frame_info fi;
    rgl_error err;
    if (!CHECK(rgl_reader_frame(r, i, &fi, &err) == RGL_OK))
        return NULL;
    rgl_cmd_iter it;
    static rgl_cmd cmd;
    rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
    bool found = false, last = false;
    while (rgl_cmd_next(&it, &cmd) == RGL_OK) {
        last = cmd.opcode == RGL_OP_Snapshot;
        if (last)
            found = CHECK(rgl_snapshot_from_cmd(&cmd, snap, &err) == RGL_OK);
    }
    if (!found)
        return NULL;
    CHECK(last); /* the frame's last command */
    rgl_resource res;
    uint8_t *rgb = NULL;
    if (CHECK(rgl_reader_resource(r, snap->image, &res, &err) == RGL_OK))
        CHECKM(rgl_snapshot_decode(snap, &res, &rgb, &err) == RGL_OK, "%s", err.detail);
    return rgb;
}

/* Pixels of the OSMesa buffer (bottom row first, RGBA) in the rectangle,
 * as RGB top row first. */
static bool same_as_buffer(const uint8_t *rgb, int x0, int y0, int w, int h)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint8_t *a = rgb + ((size_t)y * (size_t)w + (size_t)x) * 3;
            const uint8_t *b = pixels + ((size_t)(y0 + h - 1 - y) * 64 + (size_t)(x0 + x)) * 4;
            if (memcmp(a, b, 3) != 0) {
                fprintf(stderr, "snapshot (%d,%d) = %d,%d,%d, buffer %d,%d,%d\n", x, y, a[0],
                        a[1], a[2], b[0], b[1], b[2]);
                return false;
            }
        }
    return true;
}

/* RAYGL_SNAPSHOTS's API twin: each frame's image is in the trace, equal to
 * what GL drew; the program's pixel-pack state and pending GL error are as
 * it left them; no snapshot once turned off. */
static void test_snapshots(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    rayglRecordSnapshots(1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 7);
    glPixelStorei(GL_PACK_SKIP_ROWS, 2);
    for (int f = 0; f < 3; f++) {
        if (f == 2)
            rayglRecordSnapshots(0);
        rayglViewport(0, 0, 64, 64);
        rayglClearColor(0.1f * (float)f, 0.2f, 0.3f, 1);
        rayglClear(GL_COLOR_BUFFER_BIT);
        if (f == 1)
            rayglViewport(8, 4, 40, 30);
        rayglMatrixMode(GL_MODELVIEW);
        rayglLoadIdentity();
        rayglBegin(GL_TRIANGLES);
        rayglColor3f(1, 0.5f, 0);
        rayglVertex2f(-0.8f, -0.8f);
        rayglColor3f(0, 1, 0.25f);
        rayglVertex2f(0.9f, -0.5f);
        rayglColor3f(0.2f, 0, 1);
        rayglVertex2f(0, 0.9f);
        rayglEnd();
        glEnable(0x7fff); /* the program's own error, pending at the frame end */
        rayglutSwapBuffers();
        CHECK(glGetError() == GL_INVALID_ENUM);
        CHECK(glGetError() == GL_NO_ERROR);
        GLint v = 0;
        glGetIntegerv(GL_PACK_ALIGNMENT, &v);
        CHECK(v == 1);
        glGetIntegerv(GL_PACK_ROW_LENGTH, &v);
        CHECK(v == 7);
        glGetIntegerv(GL_PACK_SKIP_ROWS, &v);
        CHECK(v == 2);
    }
    rayglRecordClose();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 3);
    rgl_snapshot snap;
    /* Frame 0: the whole 64x64 buffer; the buffer still holds frame 2's
     * image, so draw frame 0 again to compare. */
    uint8_t *rgb = frame_snapshot(r, 0, &snap);
    if (CHECK(rgb != NULL)) {
        CHECK(snap.x == 0 && snap.y == 0 && snap.width == 64 && snap.height == 64);
        glViewport(0, 0, 64, 64);
        glClearColor(0, 0.2f, 0.3f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        glColor3f(1, 0.5f, 0);
        glVertex2f(-0.8f, -0.8f);
        glColor3f(0, 1, 0.25f);
        glVertex2f(0.9f, -0.5f);
        glColor3f(0.2f, 0, 1);
        glVertex2f(0, 0.9f);
        glEnd();
        glFinish();
        CHECK(same_as_buffer(rgb, 0, 0, 64, 64));
        free(rgb);
    }
    /* Frame 1: the viewport rectangle only. */
    rgb = frame_snapshot(r, 1, &snap);
    if (CHECK(rgb != NULL)) {
        CHECK(snap.x == 8 && snap.y == 4 && snap.width == 40 && snap.height == 30);
        glViewport(0, 0, 64, 64);
        glClearColor(0.1f, 0.2f, 0.3f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glViewport(8, 4, 40, 30);
        glBegin(GL_TRIANGLES);
        glColor3f(1, 0.5f, 0);
        glVertex2f(-0.8f, -0.8f);
        glColor3f(0, 1, 0.25f);
        glVertex2f(0.9f, -0.5f);
        glColor3f(0.2f, 0, 1);
        glVertex2f(0, 0.9f);
        glEnd();
        glFinish();
        CHECK(same_as_buffer(rgb, 8, 4, 40, 30));
        free(rgb);
        glViewport(0, 0, 64, 64);
    }
    /* Frame 2: snapshots off. */
    CHECK(frame_snapshot(r, 2, &snap) == NULL);
    rgl_reader_destroy(r);
}

/* Evaluator state set in one frame reaches the next frame's snapshot: the
 * map enables, the grids and each map that is not GL's initial one, its
 * points read back with glGetMap and packed u major as glMap2 records
 * them. */
static void test_eval_snapshot(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    GLfloat p2[2][3][3];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            for (int c = 0; c < 3; c++)
                p2[i][j][c] = (GLfloat)(100 * i + 10 * j + c);
    static const GLfloat col[2][4] = {{1, 0, 0, 1}, {0, 0, 1, 0.5f}};
    rayglMap2f(GL_MAP2_VERTEX_3, 0, 2, 9, 2, -1, 1, 3, 3, &p2[0][0][0]);
    rayglMap1f(GL_MAP1_COLOR_4, 1, 3, 4, 2, &col[0][0]);
    rayglEnable(GL_MAP2_VERTEX_3);
    rayglEnable(GL_AUTO_NORMAL);
    rayglMapGrid2f(5, 0, 2, 4, -1, 1);
    rayglutSwapBuffers();
    rayglEvalMesh2(GL_FILL, 0, 5, 0, 4);
    rayglutSwapBuffers();
    rayglRecordClose();
    rayglDisable(GL_MAP2_VERTEX_3);
    rayglDisable(GL_AUTO_NORMAL);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    if (CHECK(rgl_reader_frame_count(r) == 2) &&
        CHECK(rgl_reader_frame(r, 1, &fi, NULL) == RGL_OK) && CHECK(fi.state != 0)) {
        trace_cmds s = trace_resource_cmds(r, fi.state);
        CHECK(trace_cmds_find(&s, 0, "glEnable(cap=GL_MAP2_VERTEX_3)") >= 0);
        CHECK(trace_cmds_find(&s, 0, "glEnable(cap=GL_AUTO_NORMAL)") >= 0);
        CHECK(trace_cmds_find(&s, 0, "glMapGrid2d(un=5, u1=0, u2=2, vn=4, v1=-1, v2=1)") >= 0);
        CHECK(trace_cmds_find(&s, 0,
                              "glMap2d(target=GL_MAP2_VERTEX_3, u1=0, u2=2, ustride=9, uorder=2, "
                              "v1=-1, v2=1, vstride=3, vorder=3, points=<144 bytes>)") >= 0);
        CHECK(trace_cmds_find(&s, 0, "glMap1d(target=GL_MAP1_COLOR_4, u1=1, u2=3, stride=4, "
                                     "order=2, points=<64 bytes>)") >= 0);
        CHECK(trace_cmds_count(&s, RGL_OP_Map2d) == 1 && trace_cmds_count(&s, RGL_OP_Map1d) == 1);
        /* The points: the resource's glMap2d blob, value by value. */
        rgl_resource res;
        if (CHECK(rgl_reader_resource(r, fi.state, &res, NULL) == RGL_OK)) {
            rgl_cmd_iter it;
            static rgl_cmd cmd;
            rgl_cmd_iter_init(&it, res.data, res.size, res.data_offset);
            bool found = false;
            while (rgl_cmd_next(&it, &cmd) == RGL_OK) {
                if (cmd.opcode != RGL_OP_Map2d || cmd.arg[9].count != 18 * 8)
                    continue;
                found = true;
                for (int k = 0; k < 18; k++)
                    CHECK(rgl_bits_f64(rgl_get_u64(cmd.arg[9].bytes + 8 * k)) ==
                          (&p2[0][0][0])[k]);
            }
            CHECK(found);
        }
        trace_cmds_free(&s);
    }
    rgl_reader_destroy(r);
}

/* Index of the last line before `to` that starts with prefix, or -1. */
static long find_prev(const trace_cmds *c, size_t to, const char *prefix)
{
    for (long k = (long)(to < c->count ? to : c->count) - 1; k >= 0; k--)
        if (strncmp(c->lines[k], prefix, strlen(prefix)) == 0)
            return k;
    return -1;
}

/* Per-unit texture state reaches the next frame's snapshot: one block per
 * unit in unit order, each unit's enables, environment, coordinates and
 * texture matrix after the one glActiveTexture naming it, and the
 * program's active unit (here unit 2) named again last. */
static void test_unit_snapshot(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    rayglActiveTexture(GL_TEXTURE3);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_SUBTRACT);
    rayglTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
    rayglActiveTexture(GL_TEXTURE1);
    rayglEnable(GL_TEXTURE_2D);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    rayglMatrixMode(GL_TEXTURE);
    rayglTranslatef(0.5f, 0, 0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglMultiTexCoord2f(GL_TEXTURE1, 0.25f, 0.75f);
    rayglActiveTexture(GL_TEXTURE2);
    rayglMultiTexCoord2f(GL_TEXTURE2, 0.5f, 0.125f);
    rayglutSwapBuffers();
    rayglBegin(GL_POINTS);
    rayglVertex2f(0, 0);
    rayglEnd();
    rayglutSwapBuffers();
    rayglRecordClose();
    rayglActiveTexture(GL_TEXTURE3);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);
    rayglTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1);
    rayglActiveTexture(GL_TEXTURE1);
    rayglDisable(GL_TEXTURE_2D);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    rayglMatrixMode(GL_TEXTURE);
    rayglLoadIdentity();
    rayglMatrixMode(GL_MODELVIEW);
    rayglActiveTexture(GL_TEXTURE0);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    if (CHECK(rgl_reader_frame_count(r) == 2) &&
        CHECK(rgl_reader_frame(r, 1, &fi, NULL) == RGL_OK) && CHECK(fi.state != 0)) {
        trace_cmds s = trace_resource_cmds(r, fi.state);
        /* One block per unit, in unit order, each after one glActiveTexture. */
        GLint nunits = 1;
        glGetIntegerv(GL_MAX_TEXTURE_UNITS, &nunits);
        CHECK(nunits >= 5);
        long u0 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE0)");
        long u1 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE1)");
        long u2 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE2)");
        long u3 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE3)");
        long u4 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE4)");
        CHECK(u0 > 0 && u1 > u0 && u2 > u1 && u3 > u2 && u4 > u3);
        /* Every unit named once, the active one again at the end. */
        CHECK(trace_cmds_count(&s, RGL_OP_ActiveTexture) == (size_t)nunits + 1);
        /* The active unit's current coordinates go to that unit. */
        long tc2 = trace_cmds_find(&s, 0, "glMultiTexCoord4f(target=GL_TEXTURE2, s=0.5, t=0.125, r=0, q=1)");
        CHECK(tc2 > u2 && tc2 < u3);
        long en = trace_cmds_find(&s, (size_t)(u1 > 0 ? u1 : 0), "glEnable(cap=GL_TEXTURE_2D)");
        CHECK(en > u1 && en < u2);
        CHECK(trace_cmds_find(&s, (size_t)(u2 > 0 ? u2 : 0), "glEnable(cap=GL_TEXTURE_2D)") < 0);
        long env = trace_cmds_find(&s, 0,
                                   "glTexEnvi(target=GL_TEXTURE_ENV, pname=GL_TEXTURE_ENV_MODE, param=260)");
        CHECK(env > u1 && env < u2);
        long tc = trace_cmds_find(&s, 0,
                                  "glMultiTexCoord4f(target=GL_TEXTURE1, s=0.25, t=0.75, r=0, q=1)");
        CHECK(tc > u1 && tc < u2);
        long tm = trace_cmds_find(&s, 0,
                                  "glLoadMatrixf(m=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5, 0, 0, 1])");
        CHECK(tm > u1 && tm < u2);
        long mm = find_prev(&s, (size_t)(tm > 0 ? tm : 0), "glMatrixMode(");
        CHECK(mm >= 0 && strcmp(s.lines[mm], "glMatrixMode(mode=GL_TEXTURE)") == 0);
        /* Unit 3's combiner, only where GL_COMBINE is the mode. */
        long sub = trace_cmds_find(&s, 0, "glTexEnvi(target=GL_TEXTURE_ENV, pname=GL_COMBINE_RGB, param=34023)");
        CHECK(sub > u3 && sub < u4);
        long sc = trace_cmds_find(&s, 0, "glTexEnvf(target=GL_TEXTURE_ENV, pname=GL_RGB_SCALE, param=2)");
        CHECK(sc > u3 && sc < u4);
        CHECK(trace_cmds_count(&s, RGL_OP_TexEnvf) == 2);
        /* The active unit again before the final matrices. */
        long last = -1;
        for (size_t i = 0; i < s.count; i++)
            if (strncmp(s.lines[i], "glActiveTexture(", 16) == 0)
                last = (long)i;
        CHECK(last > u4 && strcmp(s.lines[last], "glActiveTexture(texture=GL_TEXTURE2)") == 0);
        /* Units at GL's initial state add nothing past their glActiveTexture. */
        long u5 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE5)");
        CHECK(u5 > u4 && u5 == u4 + 1);
        trace_cmds_done(&s, "unit snapshot");
    }
    rgl_reader_destroy(r);
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!CHECK(ctx != NULL) || !CHECK(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 64, 64)))
        return check_exit();
    char dir[] = "/tmp/raygl-osmesa-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    char p1[64], p2[64], p3[64], p4[64], p5[64], p6[64];
    snprintf(p6, sizeof p6, "%s/units.raygl", dir);
    snprintf(p4, sizeof p4, "%s/snapshots.raygl", dir);
    snprintf(p5, sizeof p5, "%s/eval.raygl", dir);
    snprintf(p1, sizeof p1, "%s/two.raygl", dir);
    snprintf(p2, sizeof p2, "%s/paper.raygl", dir);
    snprintf(p3, sizeof p3, "%s/texture.raygl", dir);
    test_two_frames(p1);
    test_paper_example(p2);
    test_texture_updates(p3);
    test_snapshots(p4);
    test_eval_snapshot(p5);
    test_unit_snapshot(p6);
    /* This Mesa faults destroying a context with drawing still queued. */
    glFinish();
    OSMesaDestroyContext(ctx);
    if (!check_failures) {
        unlink(p1);
        unlink(p2);
        unlink(p3);
        unlink(p4);
        unlink(p5);
        unlink(p6);
        rmdir(dir);
    }
    return check_exit();
}
