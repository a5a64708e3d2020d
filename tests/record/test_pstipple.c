/* test_pstipple.c: glPolygonStipple's recorder entry (record/entry_raster.c)
 * on the stub GL: the 32 x 32 mask read under the unpack state (exactly
 * the bytes GL reads: the last ends at a page's end), nothing read or
 * recorded for a call GL refuses (between glBegin and glEnd: its pointer
 * faults), a mask in a GL_PIXEL_UNPACK_BUFFER read at its offset, and
 * every call forwarded. */
#include <GL/gl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "check.h"
#include "raygl.h"
#include "stubgl.h"

static uint8_t rev8(uint8_t b)
{
    uint8_t r = 0;
    for (int i = 0; i < 8; i++)
        if (b & (1u << i))
            r |= (uint8_t)(0x80u >> i);
    return r;
}

/* The mask resource of the nth glPolygonStipple line of c (CHECKs it). */
static bool mask_of(rgl_reader *r, const trace_cmds *c, int nth, uint8_t out[128])
{
    long i = -1;
    for (int k = 0; k <= nth; k++) {
        i = trace_cmds_find(c, (size_t)(i + 1), "glPolygonStipple(");
        if (!CHECK(i >= 0))
            return false;
    }
    unsigned id = 0;
    if (!CHECK(sscanf(c->lines[i], "glPolygonStipple(mask=#%u)", &id) == 1 && id > 0))
        return false;
    rgl_resource res;
    if (!CHECK(rgl_reader_resource(r, id, &res, NULL) == RGL_OK) ||
        !CHECK(res.kind == RGL_RES_BYTES && res.size == 128))
        return false;
    memcpy(out, res.data, 128);
    return true;
}

void test_pstipple(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/pstipple.raygl", dir);
    long pg = sysconf(_SC_PAGESIZE);
    uint8_t *page = mmap(NULL, (size_t)pg * 2, PROT_READ | PROT_WRITE,
                         MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (!CHECK(page != MAP_FAILED))
        return;
    CHECK(mprotect(page + pg, (size_t)pg, PROT_NONE) == 0);
    uint8_t *bad = page + pg;
    CHECK(rayglRecordOpen(path) == 0);
    stub_reset();
    /* Rows of 64 pixels (8 bytes), one row and 32 pixels skipped, least
     * significant bit first: row r's 4 bytes at (1 + r) * 8 + 4, the last
     * ending at the page's end. */
    uint8_t *m = bad - 33 * 8;
    for (int r = 0; r < 32; r++)
        for (int b = 0; b < 4; b++)
            m[(1 + r) * 8 + 4 + b] = (uint8_t)(r * 4 + b + 1);
    rayglPixelStorei(GL_UNPACK_LSB_FIRST, 1);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 64);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 32);
    rayglPolygonStipple(m);
    rayglPixelStorei(GL_UNPACK_LSB_FIRST, 0);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    /* Refused: nothing read, nothing recorded. */
    rayglBegin(GL_TRIANGLES);
    rayglPolygonStipple(bad);
    rayglEnd();
    /* From an unpack buffer: mask is an offset into it. */
    static uint8_t bytes[256];
    for (size_t i = 0; i < sizeof bytes; i++)
        bytes[i] = (uint8_t)(255 - i);
    GLuint b[1] = {0};
    rayglGenBuffers(1, b);
    rayglBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[0]);
    rayglBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof bytes, bytes, GL_STREAM_DRAW);
    rayglPolygonStipple((const GLubyte *)(uintptr_t)16);
    rayglPolygonStipple((const GLubyte *)(uintptr_t)200); /* past the end: GL refuses */
    rayglBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    rayglDeleteBuffers(1, b);
    size_t fw = 0;
    for (size_t i = 0; i < stub_nlog && i < STUB_LOG_MAX; i++)
        fw += strcmp(stub_log[i].name, "glPolygonStipple") == 0;
    CHECK(fw == 4);
    rayglFrameEnd();
    rayglRecordClose();
    munmap(page, (size_t)pg * 2);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    size_t n = 0;
    for (long i = trace_cmds_find(&c, 0, "glPolygonStipple("); i >= 0;
         i = trace_cmds_find(&c, (size_t)i + 1, "glPolygonStipple("))
        n++;
    CHECK(n == 2);
    uint8_t got[128];
    if (mask_of(r, &c, 0, got)) {
        bool same = true;
        for (int i = 0; i < 128; i++)
            same = same && got[i] == rev8((uint8_t)(i + 1));
        CHECKM(same, "mask read under the unpack state");
    }
    if (mask_of(r, &c, 1, got))
        CHECKM(got[0] == 255 - 16 && got[127] == 255 - 143, "mask read from the buffer");
    if (check_failures)
        trace_cmds_print(&c, "pstipple");
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
}

/* The frame-start snapshot (record/snapshot.c): GL's all-ones mask is left
 * out; another is read back with the pack state at its defaults and no
 * pack buffer bound (both put back after), and comes as a glPolygonStipple
 * of its bytes, with the enable. */
void test_pstipple_snapshot(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/pstipple-snap.raygl", dir);
    stub_version = "2.1 Mesa";
    stub_ints[0] = (stub_int){GL_MATRIX_MODE, GL_MODELVIEW};
    stub_ints[1] = (stub_int){GL_PACK_ALIGNMENT, 8};
    stub_ints[2] = (stub_int){GL_PACK_LSB_FIRST, GL_TRUE};
    stub_nints = 3;
    memset(stub_pstipple_holes, 0, sizeof stub_pstipple_holes);
    CHECK(rayglRecordOpen(path) == 0);
    rayglFrameEnd();
    stub_reset();
    rayglFlush(); /* frame 1 starts: its snapshot, GL's mask */
    GLuint b[1] = {0};
    rayglGenBuffers(1, b);
    rayglBindBuffer(GL_PIXEL_PACK_BUFFER, b[0]);
    rayglFrameEnd();
    for (int i = 0; i < 128; i++)
        stub_pstipple_holes[i] = (uint8_t)(i % 4 == 0 ? 0xf0 : 0);
    stub_reset();
    rayglFlush(); /* frame 2: the mask */
    /* The pack state set for the read and put back, the buffer too. */
    size_t set_align = 0, put_align = 0, unbind = 0, rebind = 0, got = 0;
    for (size_t i = 0; i < stub_nlog && i < STUB_LOG_MAX; i++) {
        const stub_call *c = &stub_log[i];
        if (strcmp(c->name, "glPixelStorei") == 0 && c->v[0] == GL_PACK_ALIGNMENT) {
            set_align += c->v[1] == 4;
            put_align += c->v[1] == 8;
        }
        if (strcmp(c->name, "glBindBuffer") == 0 && c->v[0] == GL_PIXEL_PACK_BUFFER) {
            unbind += c->v[1] == 0;
            rebind += c->v[1] == b[0];
        }
        if (strcmp(c->name, "glGetPolygonStipple") == 0)
            got++;
    }
    /* The buffer set aside twice: for the mask and for the pixel maps. */
    CHECKM(set_align == 1 && put_align == 1 && unbind == 2 && rebind == 2 && got == 1,
           "%zu %zu %zu %zu %zu", set_align, put_align, unbind, rebind, got);
    rayglBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    rayglDeleteBuffers(1, b);
    rayglFrameEnd();
    rayglRecordClose();
    stub_nints = 0;
    stub_version = NULL;
    memset(stub_pstipple_holes, 0, sizeof stub_pstipple_holes);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    for (size_t f = 1; f <= 2; f++) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, f, &fi);
        trace_cmds s = trace_resource_cmds(r, fi.state);
        CHECK(s.clean && s.count > 0);
        long at = trace_cmds_find(&s, 0, "glPolygonStipple(");
        if (f == 1) {
            CHECK(at < 0);
        } else if (CHECK(at >= 0)) {
            uint8_t got_mask[128];
            if (mask_of(r, &s, 0, got_mask)) {
                bool same = true;
                for (int i = 0; i < 128; i++)
                    same = same && got_mask[i] == (uint8_t)(i % 4 == 0 ? 0x0f : 0xff);
                CHECKM(same, "the snapshot's mask");
            }
        }
        if (check_failures)
            trace_cmds_print(&s, "snapshot");
        trace_cmds_free(&s);
        trace_cmds_free(&c);
    }
    rgl_reader_destroy(r);
    if (!check_failures)
        unlink(path);
}
