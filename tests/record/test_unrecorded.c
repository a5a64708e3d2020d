/* test_unrecorded.c: the calls passed through unrecorded, against the stub
 * GL (tools/gen_unrecorded.py, record/unrecorded.h).
 *
 * The generated list holds the entry points GL 1.0-2.1, GLU 1.3 and
 * freeglut have beyond commands.def, and no query; each raygl* twin makes
 * its real call once and is counted; the counts reach the trace as
 * @NotRecorded at the frame's end, per stream (thread), reset after each
 * frame written, carried over a frame with nothing recorded, split when
 * beyond 32 bits; nothing breaks when recording is off.
 */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "raygl.h"
#include "raygl/unrecorded.h"
#include "recorder.h"
#include "stubgl.h"
#include "unrecorded.h"

static long name_index(const char *name)
{
    for (unsigned i = 0; i < rgl_unrecorded_total; i++)
        if (strcmp(rgl_unrecorded_names[i], name) == 0)
            return (long)i;
    return -1;
}

static void test_list(void)
{
    static const char *const counted[] = {
        "glIndexMask", "glIndexi", "glCreateProgram", "glIndexsv", "glutStrokeCharacter",
        "glIndexdv", "glutBitmapCharacter", "glutBitmapString", "glPixelStoref", "glClearIndex",
        "glCompressedTexImage2DARB", "glUseProgram", "glUniform4fv", "glBlendFuncSeparateINGR", "glIndexs",
        "glIndexub", "gluNurbsCallback", "gluTessVertex", "gluBuild1DMipmaps", "glutInit",
        "glutStrokeCharacter", "glutSolidTeacup", "glReadBuffer",
    };
    for (size_t i = 0; i < sizeof counted / sizeof counted[0]; i++)
        CHECKM(name_index(counted[i]) >= 0, "%s not in the list", counted[i]);
    /* Queries, and calls that are recorded. */
    static const char *const not_counted[] = {
        "glGetError", "glGetIntegerv", "glGetFloatv", "glIsEnabled", "glIsTexture",
        "glReadPixels", "glAreTexturesResident", "gluErrorString", "gluProject",
        "gluGetTessProperty", "glutGet", "glutDeviceGet", "glutBitmapWidth",
        "glVertex3f", "glBegin", "glTexImage2D", "gluSphere", "glutSolidTeapot",
        "glutSwapBuffers", "glFlush", "glMap1f", "glEvalMesh2", "glRasterPos2i", "gluNurbsSurface",
        "gluPwlCurve", "gluNewNurbsRenderer",
        "glWindowPos2f", "glBitmap", "glDrawPixels", "glCopyPixels", "glPixelZoom",
        "glPixelTransferf", "glCopyTexImage2D", "glCopyTexSubImage3D", "glTexImage3D",
        "glPointParameterfv", "glProvokingVertex", "glPointParameterfARB",
        "glPointParameterfvEXT", "glTexImage3DEXT", "glTexSubImage3DEXT", "glCopyTexImage1DEXT",
        "glCopyTexImage2DEXT", "glCopyTexSubImage2DEXT", "glBindTextureEXT", "glTexSubImage2DEXT",
        "glBlendEquationEXT", "glDrawArraysEXT", "glArrayElementEXT", "glMultiDrawElementsEXT",
        "glActiveTexture", "glActiveTextureARB", "glClientActiveTexture", "glMultiTexCoord2f",
        "glMultiTexCoord4dvARB", "glLogicOp", "glAccum", "glSecondaryColor3f", "glRenderMode",
    };
    for (size_t i = 0; i < sizeof not_counted / sizeof not_counted[0]; i++)
        CHECKM(name_index(not_counted[i]) < 0, "%s is in the list", not_counted[i]);
    for (unsigned i = 0; i < rgl_unrecorded_total; i++) {
        const char *n = rgl_unrecorded_names[i];
        CHECKM(strncmp(n, "glGet", 5) != 0 && strncmp(n, "glIs", 4) != 0 &&
                   strncmp(n, "gluGet", 6) != 0 && strncmp(n, "glutGet", 7) != 0,
               "query %s in the list", n);
        if (i > 0)
            CHECKM(strcmp(rgl_unrecorded_names[i - 1], n) < 0, "%s out of order", n);
    }
    /* GL 2.1 has 551 entry points, GLU 1.3 about 50, freeglut over 100,
     * ARB/EXT aliases besides; commands.def records about 400 of them. */
    CHECKM(rgl_unrecorded_total > 400, "%u entry points", rgl_unrecorded_total);
}

static size_t stub_calls(const char *name)
{
    size_t n = 0;
    for (size_t i = 0; i < stub_nlog && i < STUB_LOG_MAX; i++)
        n += strcmp(stub_log[i].name, name) == 0;
    return n;
}

static void *other_thread(void *arg)
{
    (void)arg;
    rayglIndexf(1);
    rayglIndexf(2);
    rayglVertex2f(0, 0);
    rayglFrameEnd();
    return NULL;
}

static void check_frame(rgl_reader *r, size_t i, const char *const *want, size_t nwant)
{
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, i, &fi);
    CHECK(c.clean);
    bool ok = c.count == nwant;
    for (size_t k = 0; ok && k < nwant; k++)
        ok = strcmp(c.lines[k], want[k]) == 0;
    CHECKM(ok, "frame %zu differs", i);
    if (!ok)
        trace_cmds_print(&c, "frame");
    trace_cmds_free(&c);
}

static void test_trace(const char *dir)
{
    char path[128];
    snprintf(path, sizeof path, "%s/unrecorded.raygl", dir);

    /* Before anything is recorded: glutInit is counted, into the first
     * frame, and opens no trace (a program that records nothing leaves no
     * file). */
    setenv("RAYGL_TRACE", path, 1);
    stub_reset();
    int argc = 0;
    rayglutInit(&argc, NULL);
    CHECK(rayglRecordStatus() == RAYGL_IDLE && access(path, F_OK) != 0);
    CHECK(rgl_tls_stream != NULL);
    CHECK(rayglRecordOpen(path) == 0);
    rayglIndexi(1);
    rayglIndexi(2);
    rayglIndexi(3);
    rayglVertex3f(1, 2, 3);
    CHECK(stub_calls("glIndexi") == 3 &&
          stub_calls("glutInit") == 1 && stub_calls("glVertex3f") == 1);
    CHECK(rayglCreateProgram() == 0); /* the stub's answer, passed back */
    rayglFrameEnd();

    /* Frame 1: others, and nothing of frame 0's. */
    rayglIndexMask(2);
    rayglIndexMask(1);
    rayglIndexs(0);
    rayglutStrokeCharacter(NULL, 'A');
    rayglBegin(GL_POINTS);
    rayglVertex2f(0, 0);
    rayglEnd();
    rayglutSwapBuffers();

    /* Only unrecorded calls, then a frame end: nothing is written, and the
     * counts go with the next frame. */
    rayglClearIndex(0);
    rgl_frame_end();
    rayglVertex2f(1, 1);
    /* Counts past 32 bits take several records. */
    long id = name_index("glIndexub");
    CHECK(id >= 0 && rgl_tls_stream && rgl_tls_stream->unrecorded);
    if (id >= 0 && rgl_tls_stream && rgl_tls_stream->unrecorded)
        rgl_tls_stream->unrecorded[id] = 5000000000u;
    rayglFrameEnd();

    /* Another thread: its own stream, its own counts. */
    pthread_t t;
    CHECK(pthread_create(&t, NULL, other_thread, NULL) == 0);
    pthread_join(t, NULL);
    rayglRecordClose();

    /* Not recording: forwarded, not counted, nothing breaks. */
    stub_reset();
    rayglIndexf(1);
    CHECK(stub_calls("glIndexf") == 1);

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECKM(rgl_reader_frame_count(r) == 4, "%zu frames", rgl_reader_frame_count(r));
    static const char *const want0[] = {
        "glVertex3f(x=1, y=2, z=3)",
        "rayglFrameEnd()",
        "@NotRecorded(name=\"glCreateProgram\", count=1)",
        "@NotRecorded(name=\"glIndexi\", count=3)",
        "@NotRecorded(name=\"glutInit\", count=1)",
    };
    check_frame(r, 0, want0, sizeof want0 / sizeof want0[0]);
    static const char *const want1[] = {
        "glBegin(mode=GL_POINTS)",
        "glVertex2f(x=0, y=0)",
        "glEnd()",
        "glutSwapBuffers()",
        "@NotRecorded(name=\"glIndexMask\", count=2)",
        "@NotRecorded(name=\"glIndexs\", count=1)",
        "@NotRecorded(name=\"glutStrokeCharacter\", count=1)",
    };
    check_frame(r, 1, want1, sizeof want1 / sizeof want1[0]);
    static const char *const want2[] = {
        "glVertex2f(x=1, y=1)",
        "rayglFrameEnd()",
        "@NotRecorded(name=\"glClearIndex\", count=1)",
        "@NotRecorded(name=\"glIndexub\", count=4294967295)",
        "@NotRecorded(name=\"glIndexub\", count=705032705)",
    };
    check_frame(r, 2, want2, sizeof want2 / sizeof want2[0]);
    static const char *const want3[] = {
        "glVertex2f(x=0, y=0)",
        "rayglFrameEnd()",
        "@NotRecorded(name=\"glIndexf\", count=2)",
    };
    check_frame(r, 3, want3, sizeof want3 / sizeof want3[0]);
    rgl_reader_destroy(r);
    unlink(path);
}

int main(void)
{
    char dir[] = "/tmp/raygl-unrecorded-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    test_list();
    test_trace(dir);
    if (!check_failures)
        rmdir(dir);
    return check_exit();
}
