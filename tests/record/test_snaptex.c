/* test_snaptex.c: texture objects past 1D and 2D in the frame-start
 * snapshot, with a real (software) GL context.
 *
 * Frame 0 makes a rectangle texture, a 3D texture and a cube map, and
 * leaves the 3D one bound and enabled on unit 1 with unit 1 active; frame
 * 1 makes none. Frame 1's snapshot must re-create all three, bind each on
 * the unit GL had it on, enable what GL had enabled, end with the active
 * unit GL had, and the snapshot must leave no GL error behind and GL's
 * bindings as they were.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>

#include "check.h"
#include "raygl.h"

#define SIDE 32

static unsigned char fb[SIDE * SIDE * 4];

/* Index of the last line at or before `to` that starts with prefix, or -1. */
static long find_last(const trace_cmds *c, size_t to, const char *prefix)
{
    for (long k = (long)(to < c->count ? to : c->count - 1); k >= 0; k--)
        if (strncmp(c->lines[k], prefix, strlen(prefix)) == 0)
            return k;
    return -1;
}

static void test_objects(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    GLubyte px[6 * 4 * 3 * 2];
    for (size_t i = 0; i < sizeof px; i++)
        px[i] = (GLubyte)(i * 7);
    GLuint tex[3];
    rayglGenTextures(3, tex);
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    rayglBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]);
    rayglTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGB, 6, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglEnable(GL_TEXTURE_RECTANGLE_ARB);
    rayglBindTexture(GL_TEXTURE_CUBE_MAP, tex[2]);
    for (GLenum f = GL_TEXTURE_CUBE_MAP_POSITIVE_X; f <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z; f++)
        rayglTexImage2D(f, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglActiveTexture(GL_TEXTURE1);
    rayglBindTexture(GL_TEXTURE_3D, tex[1]);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglEnable(GL_TEXTURE_3D);
    CHECK(glGetError() == GL_NO_ERROR);
    rayglutSwapBuffers();
    rayglClear(GL_COLOR_BUFFER_BIT); /* frame 1 starts: its snapshot */
    CHECKM(glGetError() == GL_NO_ERROR, "the snapshot left a GL error");
    GLint active = 0, b3d = 0, bcube = -1, brect = -1;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &b3d);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &bcube);
    glGetIntegerv(GL_TEXTURE_BINDING_RECTANGLE_ARB, &brect);
    CHECK(active == GL_TEXTURE1 && b3d == (GLint)tex[1] && bcube == 0 && brect == 0);
    rayglActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &bcube);
    glGetIntegerv(GL_TEXTURE_BINDING_RECTANGLE_ARB, &brect);
    CHECK(bcube == (GLint)tex[2] && brect == (GLint)tex[0]);
    rayglutSwapBuffers();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 1, &fi);
    CHECK(c.clean && fi.state != 0);
    CHECK(trace_cmds_count(&c, RGL_OP_TexImage2D) == 0);
    trace_cmds_free(&c);
    trace_cmds s = trace_resource_cmds(r, fi.state);
    CHECK(s.clean);
    char want[160];
    /* Each object: bound, then its images. */
    snprintf(want, sizeof want, "glBindTexture(target=GL_TEXTURE_RECTANGLE, texture=%u)",
             tex[0]);
    long k = trace_cmds_find(&s, 0, want);
    CHECKM(k >= 0, "%s", want);
    CHECK(k >= 0 && trace_cmds_find(&s, (size_t)k, "glTexImage2D(target=GL_TEXTURE_RECTANGLE") ==
                        k + 1);
    snprintf(want, sizeof want, "glBindTexture(target=GL_TEXTURE_3D, texture=%u)", tex[1]);
    k = trace_cmds_find(&s, 0, want);
    CHECKM(k >= 0, "%s", want);
    CHECK(k >= 0 && trace_cmds_find(&s, (size_t)k, "glTexImage3D(target=GL_TEXTURE_3D") == k + 1);
    snprintf(want, sizeof want, "glBindTexture(target=GL_TEXTURE_CUBE_MAP, texture=%u)", tex[2]);
    k = trace_cmds_find(&s, 0, want);
    CHECKM(k >= 0, "%s", want);
    size_t faces = 0;
    for (size_t i = 0; i < s.count; i++)
        faces += strncmp(s.lines[i], "glTexImage2D(target=GL_TEXTURE_CUBE_MAP_", 40) == 0;
    CHECKM(faces == 6, "%zu cube faces", faces);
    snprintf(want, sizeof want,
             "glTexParameteri(target=GL_TEXTURE_3D, pname=GL_TEXTURE_MAG_FILTER, param=%d)",
             GL_NEAREST);
    CHECK(trace_cmds_find(&s, 0, want) >= 0);
    /* The bindings per unit, and the active unit last. */
    long u1 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE1)");
    long u0 = find_last(&s, u1 < 0 ? 0 : (size_t)u1, "glActiveTexture(texture=GL_TEXTURE0)");
    CHECK(u0 >= 0 && u1 > u0);
    if (u0 >= 0 && u1 > u0) {
        snprintf(want, sizeof want, "glBindTexture(target=GL_TEXTURE_RECTANGLE, texture=%u)",
                 tex[0]);
        CHECK(trace_cmds_find(&s, (size_t)u0, want) < u1);
        CHECK(trace_cmds_find(&s, (size_t)u0, "glEnable(cap=GL_TEXTURE_RECTANGLE") < u1);
        snprintf(want, sizeof want, "glBindTexture(target=GL_TEXTURE_3D, texture=%u)", tex[1]);
        long b = trace_cmds_find(&s, (size_t)u1, want);
        CHECK(b > u1 && trace_cmds_find(&s, (size_t)u1 + 1, "glActiveTexture(") > b);
        CHECK(trace_cmds_find(&s, (size_t)u1, "glEnable(cap=GL_TEXTURE_3D)") == b + 1);
    }
    long last = find_last(&s, s.count, "glActiveTexture(");
    CHECK(last >= 0 && strcmp(s.lines[last], "glActiveTexture(texture=GL_TEXTURE1)") == 0);
    if (check_failures)
        trace_cmds_print(&s, "snapshot");
    trace_cmds_free(&s);
    rgl_reader_destroy(r);
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!CHECK(ctx != NULL) || !CHECK(OSMesaMakeCurrent(ctx, fb, GL_UNSIGNED_BYTE, SIDE, SIDE)))
        return check_exit();
    char dir[] = "/tmp/raygl-snaptex-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    char p1[64];
    snprintf(p1, sizeof p1, "%s/objects.raygl", dir);
    test_objects(p1);
    glFinish();
    OSMesaDestroyContext(ctx);
    if (!check_failures) {
        unlink(p1);
        rmdir(dir);
    }
    return check_exit();
}
