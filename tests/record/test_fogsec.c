/* test_fogsec.c: the fog-coordinate and secondary-colour arrays against
 * the stub GL: the pointer calls recorded with their layout, the draws'
 * @ArrayData of both arrays, the EXT names, and calls GL refuses (a bad
 * type or size) forwarded unrecorded. Part of test_entry. */
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "raygl.h"
#include "recorder.h"
#include "stubgl.h"

void test_fogsec_arrays(const char *dir);

void test_fogsec_arrays(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/fogsec.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    static const float verts[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    static const float fog[3] = {0.5f, 2, 4};
    static const double fogd[3] = {1, 2, 3};
    static const GLubyte sec[3][4] = {{255, 0, 0, 9}, {0, 255, 0, 9}, {0, 0, 255, 9}};
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglEnableClientState(GL_FOG_COORD_ARRAY);
    rayglEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    rayglVertexPointer(3, GL_FLOAT, 0, verts);
    stub_reset();
    rayglFogCoordPointer(GL_INT, 0, fog);              /* refused by GL: forwarded only */
    rayglSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 4, sec); /* size 4: refused */
    CHECK(stub_nlog == 2);
    rayglFogCoordPointer(GL_FLOAT, 0, fog);
    rayglSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 4, sec);
    rayglDrawArrays(GL_TRIANGLES, 0, 3);
    rayglFogCoordPointerEXT(GL_DOUBLE, 0, fogd);
    rayglSecondaryColorPointerEXT(3, GL_UNSIGNED_BYTE, 4, sec);
    rayglDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    rayglDrawArrays(GL_POINTS, 1, 2);
    rayglutSwapBuffers();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    static const char *const want[] = {
        "glEnableClientState(array=GL_VERTEX_ARRAY)",
        "glEnableClientState(array=GL_FOG_COORD_ARRAY)",
        "glEnableClientState(array=GL_SECONDARY_COLOR_ARRAY)",
        "glVertexPointer(size=3, type=GL_FLOAT, stride=0)",
        "glFogCoordPointer(type=GL_FLOAT, stride=0)",
        "glSecondaryColorPointer(size=3, type=GL_UNSIGNED_BYTE, stride=4)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=0, size=3, type=GL_FLOAT, data=<36 bytes>)",
        "@ArrayData(array=GL_FOG_COORD_ARRAY, first=0, size=1, type=GL_FLOAT, data=<12 bytes>)",
        "@ArrayData(array=GL_SECONDARY_COLOR_ARRAY, first=0, size=3, type=GL_UNSIGNED_BYTE, data=<9 bytes>)",
        "glDrawArrays(mode=GL_TRIANGLES, first=0, count=3)",
        "glFogCoordPointerEXT(type=GL_DOUBLE, stride=0)",
        "glSecondaryColorPointerEXT(size=3, type=GL_UNSIGNED_BYTE, stride=4)",
        "glDisableClientState(array=GL_SECONDARY_COLOR_ARRAY)",
        "@ArrayData(array=GL_VERTEX_ARRAY, first=1, size=3, type=GL_FLOAT, data=<24 bytes>)",
        "@ArrayData(array=GL_FOG_COORD_ARRAY, first=1, size=1, type=GL_DOUBLE, data=<16 bytes>)",
        "glDrawArrays(mode=GL_POINTS, first=1, count=2)",
        "glutSwapBuffers()",
    };
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    size_t n = sizeof want / sizeof want[0];
    bool ok = CHECKM(c.count == n, "fogsec arrays: %zu commands, want %zu", c.count, n);
    for (size_t i = 0; i < n && i < c.count; i++)
        ok &= CHECKM(strcmp(c.lines[i], want[i]) == 0, "fogsec arrays[%zu]: got %s, want %s", i,
                     c.lines[i], want[i]);
    if (!ok)
        trace_cmds_print(&c, "fogsec arrays");
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
    unlink(path);
}
