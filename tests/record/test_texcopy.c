/* test_texcopy.c: what the recorder reads for texture copies and 3D
 * textures, with a real (software) GL context.
 *
 * glCopyTexImage2D / glCopyTexSubImage2D carry exactly the framebuffer
 * rectangle GL copies (compared with glReadPixels of it); copies GL
 * rejects (a negative size, a bad level, a sub-image outside the texture,
 * inside glBegin) are not recorded and read nothing; glTexImage3D reads its
 * pixels as GL does, GL_UNPACK_IMAGE_HEIGHT and GL_UNPACK_SKIP_IMAGES
 * included; glProvokingVertex and glPointParameterfv are recorded.
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

/* The resource id after `name=#` in a dump line, 0 when absent. */
static uint32_t arg_id(const char *line, const char *name)
{
    char key[32];
    snprintf(key, sizeof key, "%s=#", name);
    const char *p = strstr(line, key);
    return p ? (uint32_t)strtoul(p + strlen(key), NULL, 10) : 0;
}

/* Whether resource id of r holds exactly n bytes equal to want. */
static bool resource_is(rgl_reader *r, uint32_t id, const void *want, size_t n)
{
    rgl_resource res;
    if (!id || rgl_reader_resource(r, id, &res, NULL) != RGL_OK)
        return false;
    return res.kind == RGL_RES_BYTES && res.size == n && memcmp(res.data, want, n) == 0;
}

static void pattern(void)
{
    rayglViewport(0, 0, SIDE, SIDE);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglOrtho(0, SIDE, 0, SIDE, -1, 1);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglClearColor(0.1f, 0.2f, 0.3f, 1);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglBegin(GL_TRIANGLES);
    rayglColor3f(1, 0, 0);
    rayglVertex2f(0, 0);
    rayglColor3f(0, 1, 0);
    rayglVertex2f(SIDE, 0);
    rayglColor3f(0, 0, 1);
    rayglVertex2f(0, SIDE);
    rayglEnd();
}

static void test_copies(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    pattern();
    GLuint tex;
    rayglGenTextures(1, &tex);
    rayglBindTexture(GL_TEXTURE_2D, tex);
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 5, 8, 4, 0);
    rayglCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 1, 10, 12, 3, 2);
    /* What GL copied, read directly. */
    GLubyte want[8 * 4 * 4], want_sub[3 * 2 * 4];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(3, 5, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, want);
    glReadPixels(10, 12, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, want_sub);
    /* Rejected: each forwarded, none recorded. */
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -1, 4, 0);
    rayglCopyTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 0, 0, 4, 4, 0);
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 2);
    rayglCopyTexSubImage2D(GL_TEXTURE_2D, 0, 6, 0, 0, 0, 4, 4); /* past the width 8 */
    rayglCopyTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 0);
    rayglBegin(GL_POINTS);
    rayglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
    rayglEnd();
    while (glGetError() != GL_NO_ERROR)
        ;
    rayglProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    const GLfloat atten[3] = {1, 0.5f, 0.25f};
    rayglPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    rayglutSwapBuffers();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(c.clean);
    CHECKM(trace_cmds_count(&c, RGL_OP_CopyTexImage2D) == 1, "%zu glCopyTexImage2D",
           trace_cmds_count(&c, RGL_OP_CopyTexImage2D));
    CHECK(trace_cmds_count(&c, RGL_OP_CopyTexSubImage2D) == 1);
    CHECK(trace_cmds_count(&c, RGL_OP_CopyTexImage1D) == 0);
    long k = trace_cmds_find(&c, 0, "glCopyTexImage2D(");
    if (CHECK(k >= 0))
        CHECKM(resource_is(r, arg_id(c.lines[k], "pixels"), want, sizeof want), "%s",
               c.lines[k]);
    k = trace_cmds_find(&c, 0, "glCopyTexSubImage2D(");
    if (CHECK(k >= 0))
        CHECKM(resource_is(r, arg_id(c.lines[k], "pixels"), want_sub, sizeof want_sub), "%s",
               c.lines[k]);
    CHECK(trace_cmds_find(&c, 0, "glProvokingVertex(mode=GL_FIRST_VERTEX_CONVENTION)") >= 0);
    CHECK(trace_cmds_find(&c, 0, "glPointParameterfv(pname=GL_POINT_DISTANCE_ATTENUATION, "
                                 "params=[1, 0.5, 0.25])") >= 0);
    trace_cmds_done(&c, "copies");
    rgl_reader_destroy(r);
}

static void test_teximage3d(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    /* 2 x 2 x 2 RGB bytes: rows of 6 bytes padded to 8 (alignment 4),
     * images 3 rows apart (GL_UNPACK_IMAGE_HEIGHT), the first image skipped. */
    GLubyte client[4 * 3 * 8];
    for (size_t i = 0; i < sizeof client; i++)
        client[i] = (GLubyte)i;
    GLuint tex;
    rayglGenTextures(1, &tex);
    rayglBindTexture(GL_TEXTURE_3D, tex);
    rayglPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
    rayglPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, client);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, -2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, client);
    rayglTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 2, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, client);
    rayglPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    while (glGetError() != GL_NO_ERROR)
        ;
    rayglutSwapBuffers();
    rayglRecordClose();

    GLubyte want[2 * 2 * 2 * 3];
    for (int z = 0; z < 2; z++)
        for (int y = 0; y < 2; y++)
            memcpy(want + (z * 2 + y) * 6, client + (size_t)((1 + z) * 3 + y) * 8, 6);
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(trace_cmds_count(&c, RGL_OP_TexImage3D) == 1);
    CHECK(trace_cmds_count(&c, RGL_OP_TexSubImage3D) == 0); /* z 1 + 2 past the depth */
    long k = trace_cmds_find(&c, 0, "glTexImage3D(");
    if (CHECK(k >= 0))
        CHECKM(resource_is(r, arg_id(c.lines[k], "pixels"), want, sizeof want), "%s",
               c.lines[k]);
    trace_cmds_done(&c, "3D");
    rgl_reader_destroy(r);
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!CHECK(ctx != NULL) || !CHECK(OSMesaMakeCurrent(ctx, fb, GL_UNSIGNED_BYTE, SIDE, SIDE)))
        return check_exit();
    char dir[] = "/tmp/raygl-texcopy-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    char p1[64], p2[64];
    snprintf(p1, sizeof p1, "%s/copies.raygl", dir);
    snprintf(p2, sizeof p2, "%s/tex3d.raygl", dir);
    test_copies(p1);
    test_teximage3d(p2);
    glFinish();
    OSMesaDestroyContext(ctx);
    if (!check_failures) {
        unlink(p1);
        unlink(p2);
        rmdir(dir);
    }
    return check_exit();
}
