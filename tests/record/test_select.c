/* test_select.c: glRenderMode, glSelectBuffer and glFeedbackBuffer against
 * the stub GL (no context). Part of test_entry; see that file.
 *
 * glRenderMode returns GL's answer to the program unchanged and records
 * it; the buffers are forwarded, their pointers never recorded nor read;
 * calls GL rejects for their enum or size, and calls inside glBegin/glEnd,
 * are forwarded unrecorded; none of the three goes into a display list
 * being compiled. glEnable of a client array is recorded as
 * glEnableClientState.
 */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <GL/gl.h>

#include "check.h"
#include "raygl.h"
#include "recorder.h"
#include "stubgl.h"

void test_select(const char *dir);

void test_select(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/select.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    stub_reset();
    GLuint sel[8];
    GLfloat fb[8];
    rayglSelectBuffer(8, sel);
    CHECK(stub_nlog == 1 && stub_log[0].p[1] == sel); /* GL gets the program's buffer */
    rayglRenderMode(GL_SELECT);
    rayglInitNames();
    rayglPushName(3);
    rayglLoadName(4);
    rayglPopName();
    rayglPassThrough(2.5f);
    stub_render_mode_result = 5;
    CHECK(rayglRenderMode(GL_RENDER) == 5);
    rayglFeedbackBuffer(8, GL_3D, fb);
    rayglScissor(1, 2, 3, 4);
    /* Rejected by GL: forwarded, not recorded. */
    rayglRenderMode(0x1234);
    rayglSelectBuffer(-1, sel);
    rayglFeedbackBuffer(8, 0x1234, fb);
    rayglBegin(GL_POINTS);
    rayglRenderMode(GL_SELECT);
    rayglEnd();
    /* Executed at once, not compiled. */
    rayglNewList(1, GL_COMPILE);
    rayglSelectBuffer(4, sel);
    rayglPushName(9);
    rayglEndList();
    /* glEnable of a client array: forwarded as glEnable, recorded as
     * glEnableClientState (Mesa takes it so); other caps as they are. */
    rayglEnable(GL_VERTEX_ARRAY);
    rayglDisable(GL_COLOR_ARRAY);
    rayglEnable(GL_LIGHTING);
    CHECKM(stub_nlog == 23, "%zu calls forwarded", stub_nlog);
    CHECK(strcmp(stub_log[20].name, "glEnable") == 0 && stub_log[20].v[0] == GL_VERTEX_ARRAY);
    CHECK(strcmp(stub_log[21].name, "glDisable") == 0 && stub_log[22].v[0] == GL_LIGHTING);
    stub_render_mode_result = 0;
    rayglFrameEnd();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (r) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, 0, &fi);
        CHECK(c.clean);
        CHECK(trace_cmds_count(&c, RGL_OP_RenderMode) == 2);
        CHECK(trace_cmds_count(&c, RGL_OP_SelectBuffer) == 2);
        CHECK(trace_cmds_count(&c, RGL_OP_FeedbackBuffer) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_InitNames) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_PushName) == 1); /* the compiled one is in the list */
        CHECK(trace_cmds_count(&c, RGL_OP_LoadName) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_PopName) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_PassThrough) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_Scissor) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_EnableClientState) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_DisableClientState) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_Enable) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_Disable) == 0);
        /* glRenderMode(GL_RENDER) carries GL's 5. */
        bool found = false;
        for (size_t i = 0; i < c.count; i++)
            if (strcmp(c.lines[i], "glRenderMode(mode=GL_RENDER, result=5)") == 0)
                found = true;
        if (!CHECK(found))
            trace_cmds_print(&c, "select");
        trace_cmds_free(&c);
        rgl_reader_destroy(r);
    }
    unlink(path);
}
