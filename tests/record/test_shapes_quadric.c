/* test_shapes_quadric.c: GLU quadric state and display lists, and user
 * clip planes in the snapshot (issue 14).
 * GLU draws a shape compiled into a list with the quadric's state of
 * compile time, and a quadric call made while a list is compiled is done at
 * once, never stored: the recorder writes quadric calls into the frame, a
 * compiled shape's quadric state into the body before the shape, and every
 * live quadric with its state into the frame-start snapshot. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GL/osmesa.h>

#include "check.h"
#include "raygl.h"

static unsigned char pixels[32 * 32 * 4];

/* The body of the list named in frame c's glNewList(list=name...). */
static trace_cmds list_body(rgl_reader *r, const trace_cmds *c, unsigned name)
{
    char want[64];
    snprintf(want, sizeof want, "glNewList(list=%u, mode=GL_COMPILE, body=#", name);
    long i = trace_cmds_find(c, 0, want);
    unsigned id = 0;
    if (CHECK(i >= 0))
        id = (unsigned)strtoul(c->lines[i] + strlen(want), NULL, 10);
    return trace_resource_cmds(r, id);
}

static void test_lists(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    GLUquadric *q = raygluNewQuadric();
    raygluQuadricDrawStyle(q, GLU_LINE);
    raygluQuadricNormals(q, GLU_NONE);
    rayglNewList(1, GL_COMPILE);
    raygluDisk(q, 0.25, 1.0, 20, 4);
    rayglEndList();
    rayglNewList(2, GL_COMPILE);
    raygluQuadricDrawStyle(q, GLU_SILHOUETTE); /* done now, not stored */
    raygluPartialDisk(q, 0.0, 1.0, 20, 4, 0.0, 225.0);
    rayglEndList();
    raygluQuadricDrawStyle(q, GLU_POINT);
    raygluQuadricDrawStyle(q, 0x1234); /* GLU refuses it: the state stays */
    rayglCallList(1);
    rayglutSwapBuffers();
    rayglCallList(2);
    rayglutSwapBuffers();
    raygluDeleteQuadric(q);
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) >= 2);
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    /* The style set inside the compile is in the frame, before the list. */
    long s = trace_cmds_find(&c, 0, "gluQuadricDrawStyle(quad=#1, draw=GLU_SILHOUETTE)");
    long n2 = trace_cmds_find(&c, 0, "glNewList(list=2,");
    CHECK(s >= 0 && n2 > s);

    trace_cmds b1 = list_body(r, &c, 1);
    long st = trace_cmds_find(&b1, 0, "gluQuadricDrawStyle(quad=#1, draw=GLU_LINE)");
    long nn = trace_cmds_find(&b1, 0, "gluQuadricNormals(quad=#1, normal=GLU_NONE)");
    long d = trace_cmds_find(&b1, 0, "gluDisk(quad=#1,");
    CHECK(st >= 0 && nn >= 0 && d > st && d > nn);
    CHECK(trace_cmds_find(&b1, 0, "gluQuadricOrientation(quad=#1, orientation=GLU_OUTSIDE)") >= 0);
    CHECK(trace_cmds_find(&b1, 0, "gluQuadricTexture(quad=#1, texture=GL_FALSE)") >= 0);
    if (check_failures)
        trace_cmds_print(&b1, "list 1");
    trace_cmds b2 = list_body(r, &c, 2);
    CHECK(trace_cmds_find(&b2, 0, "gluQuadricDrawStyle(quad=#1, draw=GLU_SILHOUETTE)") >= 0);
    CHECK(trace_cmds_find(&b2, 0, "gluQuadricDrawStyle(quad=#1, draw=GLU_LINE)") < 0);
    if (check_failures)
        trace_cmds_print(&b2, "list 2");
    trace_cmds_free(&b1);
    trace_cmds_free(&b2);
    trace_cmds_free(&c);

    /* Frame 1 alone: its snapshot re-creates the quadric with its state. */
    trace_cmds f1 = trace_frame(r, 1, &fi);
    trace_cmds_free(&f1);
    if (CHECK(fi.state != 0)) {
        trace_cmds snap = trace_resource_cmds(r, fi.state);
        long nq = trace_cmds_find(&snap, 0, "gluNewQuadric(quad=#1)");
        long ds = trace_cmds_find(&snap, 0, "gluQuadricDrawStyle(quad=#1, draw=GLU_POINT)");
        long nl = trace_cmds_find(&snap, 0, "glNewList(list=1,");
        CHECK(nq >= 0 && ds > nq && nl > ds);
        CHECK(trace_cmds_find(&snap, 0, "gluQuadricNormals(quad=#1, normal=GLU_NONE)") > nq);
        trace_cmds_done(&snap, "snapshot");
    }
    rgl_reader_destroy(r);
}

/* A clip plane set under a modelview: the next frame's snapshot holds it
 * in eye space (GL's, read back), with its enable. */
static void test_clip_snapshot(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0, 0, -5);
    const GLdouble eq[4] = {0, 0, 1, 0}; /* z >= 0 here: z_eye >= -5 */
    rayglClipPlane(GL_CLIP_PLANE1, eq);
    rayglEnable(GL_CLIP_PLANE1);
    rayglutSwapBuffers();
    rayglLoadIdentity();
    rayglutSwapBuffers();
    rayglRecordClose();
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds f0 = trace_frame(r, 0, &fi);
    CHECK(trace_cmds_find(&f0, 0, "glClipPlane(plane=GL_CLIP_PLANE1, equation=[0, 0, 1, 0])") >= 0);
    trace_cmds_free(&f0);
    trace_cmds f1 = trace_frame(r, 1, &fi);
    trace_cmds_free(&f1);
    if (CHECK(fi.state != 0)) {
        trace_cmds snap = trace_resource_cmds(r, fi.state);
        CHECK(trace_cmds_find(&snap, 0, "glClipPlane(plane=GL_CLIP_PLANE1, equation=[0, 0, 1, 5])") >= 0);
        CHECK(trace_cmds_find(&snap, 0, "glEnable(cap=GL_CLIP_PLANE1)") >= 0);
        CHECK(trace_cmds_find(&snap, 0, "glClipPlane(plane=GL_CLIP_PLANE0,") < 0);
        trace_cmds_done(&snap, "snapshot");
    }
    rgl_reader_destroy(r);
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!CHECK(ctx != NULL) || !CHECK(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 32, 32)))
        return check_exit();
    char dir[] = "/tmp/raygl-shapes-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    char p[64], p2[64];
    snprintf(p, sizeof p, "%s/quadric.raygl", dir);
    snprintf(p2, sizeof p2, "%s/clip.raygl", dir);
    test_lists(p);
    test_clip_snapshot(p2);
    glFinish();
    OSMesaDestroyContext(ctx);
    if (!check_failures) {
        unlink(p);
        unlink(p2);
        rmdir(dir);
    }
    return check_exit();
}
