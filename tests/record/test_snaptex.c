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
        long next = trace_cmds_find(&s, (size_t)u1 + 1, "glActiveTexture(");
        CHECK(b > u1 && next > b);
        long en = trace_cmds_find(&s, (size_t)u1, "glEnable(cap=GL_TEXTURE_3D)");
        CHECK(en > u1 && en < next);
        /* Each unit named once (and the active unit again at the end),
         * each enable once. */
        GLint nunits = 1;
        glGetIntegerv(GL_MAX_TEXTURE_UNITS, &nunits);
        CHECK(trace_cmds_count(&s, RGL_OP_ActiveTexture) == (size_t)nunits + 1);
        CHECK(trace_cmds_find(&s, (size_t)en + 1, "glEnable(cap=GL_TEXTURE_3D)") < 0);
        CHECK(trace_cmds_find(&s, (size_t)u1, "glEnable(cap=GL_TEXTURE_RECTANGLE") < 0);
    }
    long last = find_last(&s, s.count, "glActiveTexture(");
    CHECK(last >= 0 && strcmp(s.lines[last], "glActiveTexture(texture=GL_TEXTURE1)") == 0);
    trace_cmds_done(&s, "snapshot");
    rgl_reader_destroy(r);
}

static void test_ext(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    rayglClearColor(0.25f, 0.5f, 0.75f, 1);
    rayglClear(GL_COLOR_BUFFER_BIT);
    GLuint tex[2];
    rayglGenTextures(2, tex);
    rayglBindTextureEXT(GL_TEXTURE_2D, tex[0]);
    rayglCopyTexImage2DEXT(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
    rayglCopyTexSubImage2DEXT(GL_TEXTURE_2D, 0, 1, 1, 0, 0, 2, 2);
    GLubyte px[2 * 2 * 2 * 4] = {0};
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    rayglTexSubImage2DEXT(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglBindTextureEXT(GL_TEXTURE_1D, tex[1]);
    rayglCopyTexImage1DEXT(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 4, 0);
    rayglCopyTexSubImage1DEXT(GL_TEXTURE_1D, 0, 1, 0, 0, 2);
    GLuint t3;
    rayglGenTextures(1, &t3);
    rayglBindTextureEXT(GL_TEXTURE_3D, t3);
    rayglTexImage3DEXT(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglTexSubImage3DEXT(GL_TEXTURE_3D, 0, 0, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglCopyTexSubImage3DEXT(GL_TEXTURE_3D, 0, 1, 1, 0, 0, 0, 1, 1);
    rayglBlendEquationEXT(GL_FUNC_ADD);
    /* The EXT array draws. */
    static const GLfloat v[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const GLushort idx[4] = {0, 1, 2, 3};
    const GLint first[1] = {0};
    const GLsizei count[1] = {4};
    const void *const idxs[1] = {idx};
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglVertexPointer(2, GL_FLOAT, 0, v);
    rayglDrawArraysEXT(GL_QUADS, 0, 4);
    rayglDrawRangeElementsEXT(GL_QUADS, 0, 3, 4, GL_UNSIGNED_SHORT, idx);
    rayglMultiDrawArraysEXT(GL_QUADS, first, count, 1);
    rayglMultiDrawElementsEXT(GL_QUADS, count, GL_UNSIGNED_SHORT, idxs, 1);
    rayglBegin(GL_QUADS);
    for (GLint k = 0; k < 4; k++)
        rayglArrayElementEXT(k);
    rayglEnd();
    rayglDisableClientState(GL_VERTEX_ARRAY);
    /* Rejected as the core names are: not recorded. */
    rayglCopyTexImage2DEXT(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -1, 4, 0);
    CHECK(glGetError() != GL_NO_ERROR);
    while (glGetError() != GL_NO_ERROR)
        ;
    /* GL carried them out: the 2D texture is the clear colour. */
    GLint w = 0;
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    CHECK(w == 4);
    rayglutSwapBuffers();
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglutSwapBuffers();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 0, &fi);
    CHECK(c.clean);
    static const struct {
        uint32_t op;
        size_t n;
    } want[] = {
        {RGL_OP_BindTextureEXT, 3},        {RGL_OP_CopyTexImage2DEXT, 1},
        {RGL_OP_CopyTexSubImage2DEXT, 1},  {RGL_OP_TexSubImage2DEXT, 1},
        {RGL_OP_CopyTexImage1DEXT, 1},     {RGL_OP_CopyTexSubImage1DEXT, 1},
        {RGL_OP_TexImage3DEXT, 1},         {RGL_OP_TexSubImage3DEXT, 1},
        {RGL_OP_CopyTexSubImage3DEXT, 1},  {RGL_OP_BlendEquationEXT, 1},
        {RGL_OP_CopyTexImage2D, 0},        {RGL_OP_TexImage3D, 0},
        {RGL_OP_BindTexture, 0},
        {RGL_OP_DrawArraysEXT, 1},         {RGL_OP_DrawRangeElementsEXT, 1},
        {RGL_OP_MultiDrawArraysEXT, 1},    {RGL_OP_MultiDrawElementsEXT, 1},
        {RGL_OP_ArrayElementEXT, 4},       {RGL_OP_DrawArrays, 0},
        {RGL_OP_ArrayElement, 0},          {RGL_OP_ArrayData, 8},
    };
    for (size_t k = 0; k < sizeof want / sizeof want[0]; k++)
        CHECKM(trace_cmds_count(&c, want[k].op) == want[k].n, "opcode 0x%x: %zu", want[k].op,
               trace_cmds_count(&c, want[k].op));
    long k = trace_cmds_find(&c, 0, "glCopyTexImage2DEXT(target=GL_TEXTURE_2D, level=0");
    CHECK(k >= 0 && strstr(c.lines[k], "pixels=#") && !strstr(c.lines[k], "pixels=#0"));
    trace_cmds_done(&c, "EXT");
    /* The next frame's snapshot re-creates the textures from them. */
    c = trace_frame(r, 1, &fi);
    trace_cmds s = trace_resource_cmds(r, fi.state);
    CHECK(trace_cmds_find(&s, 0, "glCopyTexImage2DEXT(target=GL_TEXTURE_2D") >= 0);
    CHECK(trace_cmds_find(&s, 0, "glTexSubImage2DEXT(target=GL_TEXTURE_2D") >= 0);
    CHECK(trace_cmds_find(&s, 0, "glCopyTexImage1DEXT(target=GL_TEXTURE_1D") >= 0);
    CHECK(trace_cmds_find(&s, 0, "glTexImage3DEXT(target=GL_TEXTURE_3D") >= 0);
    CHECK(trace_cmds_find(&s, 0, "glTexSubImage3DEXT(target=GL_TEXTURE_3D") >= 0);
    trace_cmds_done(&s, "EXT snapshot");
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
}

static size_t count_prefix(const trace_cmds *c, const char *prefix)
{
    size_t n = 0;
    for (size_t i = 0; i < c->count; i++)
        n += strncmp(c->lines[i], prefix, strlen(prefix)) == 0;
    return n;
}

static void test_updates(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    GLuint tex[3];
    rayglGenTextures(3, tex);
    GLubyte img[4 * 4 * 4 * 4] = {0};
    rayglBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]);
    rayglTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    rayglBindTexture(GL_TEXTURE_3D, tex[1]);
    rayglTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    rayglBindTexture(GL_TEXTURE_CUBE_MAP, tex[2]);
    for (GLenum f = GL_TEXTURE_CUBE_MAP_POSITIVE_X; f <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z; f++)
        rayglTexImage2D(f, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    const int frames = 300;
    for (int f = 0; f < frames; f++) {
        GLubyte texel[4] = {(GLubyte)f, (GLubyte)(f >> 8), 7, 255};
        rayglBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]);
        rayglTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, f % 4, (f / 4) % 4, 1, 1, GL_RGBA,
                           GL_UNSIGNED_BYTE, texel);
        rayglBindTexture(GL_TEXTURE_3D, tex[1]);
        rayglTexSubImage3D(GL_TEXTURE_3D, 0, f % 4, (f / 4) % 4, (f / 16) % 4, 1, 1, 1, GL_RGBA,
                           GL_UNSIGNED_BYTE, texel);
        /* A face made anew every frame. */
        rayglBindTexture(GL_TEXTURE_CUBE_MAP, tex[2]);
        GLubyte face[2 * 2 * 4];
        memset(face, f & 255, sizeof face);
        rayglTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, 2, 2, 0, GL_RGBA,
                        GL_UNSIGNED_BYTE, face);
        rayglutSwapBuffers();
    }
    CHECK(glGetError() == GL_NO_ERROR);
    rayglRecordClose();
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    if (CHECK(rgl_reader_frame(r, (size_t)frames - 1, &fi, NULL) == RGL_OK)) {
        trace_cmds s = trace_resource_cmds(r, fi.state);
        size_t rect = count_prefix(&s, "glTexSubImage2D(target=GL_TEXTURE_RECTANGLE");
        size_t vol = count_prefix(&s, "glTexSubImage3D(target=GL_TEXTURE_3D");
        size_t faces = count_prefix(&s, "glTexImage2D(target=GL_TEXTURE_CUBE_MAP_");
        CHECKM(rect < 200 && vol < 200 && faces < 200, "%zu, %zu sub-images, %zu faces", rect,
               vol, faces);
        /* Compacted: whole images read back, every cube face kept. */
        CHECK(count_prefix(&s, "glTexImage3D(target=GL_TEXTURE_3D") == 1);
        CHECK(count_prefix(&s, "glTexImage2D(target=GL_TEXTURE_RECTANGLE") == 1);
        for (GLenum f = GL_TEXTURE_CUBE_MAP_POSITIVE_X; f <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
             f++) {
            char want[96];
            snprintf(want, sizeof want, "glTexImage2D(target=%s",
                     rgl_enum_name(f, "target"));
            CHECKM(trace_cmds_find(&s, 0, want) >= 0, "%s", want);
        }
        trace_cmds_done(&s, "updated");
    }
    rgl_reader_destroy(r);
}

/* A frame starting while the program compiles a list: GL's unit is not
 * changed and nothing goes into the list; the active unit (0) is read
 * back, unit 1's block holds the binding RayGL tracked. */
static void test_in_list(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    GLuint tex;
    rayglGenTextures(1, &tex);
    GLubyte px[2 * 2 * 4] = {0};
    rayglActiveTexture(GL_TEXTURE1);
    rayglBindTexture(GL_TEXTURE_2D, tex);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglActiveTexture(GL_TEXTURE0);
    rayglEnable(GL_TEXTURE_GEN_S);
    GLint b2d0 = -1;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &b2d0);
    GLuint list = rayglGenLists(1);
    rayglNewList(list, GL_COMPILE);
    rayglutSwapBuffers();
    rayglColor3f(1, 0, 0); /* frame 1 starts in the list: its snapshot */
    rayglEndList();
    CHECKM(glGetError() == GL_NO_ERROR, "the snapshot left a GL error");
    GLint active = 0, b2d = -1;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &b2d);
    CHECK(active == GL_TEXTURE0 && b2d == b2d0);
    /* The list holds the colour alone: unit 1 stays as it was. */
    rayglCallList(list);
    glActiveTexture(GL_TEXTURE1);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &b2d);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    CHECK(b2d == (GLint)tex && active == GL_TEXTURE1);
    glActiveTexture(GL_TEXTURE0);
    rayglDisable(GL_TEXTURE_GEN_S);
    rayglDeleteLists(list, 1);
    rayglutSwapBuffers();
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 1, &fi);
    trace_cmds s = trace_resource_cmds(r, fi.state);
    CHECK(c.clean && s.clean && fi.state != 0);
    long u0 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE0)");
    long u1 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE1)");
    long u2 = trace_cmds_find(&s, 0, "glActiveTexture(texture=GL_TEXTURE2)");
    CHECK(u0 >= 0 && u1 > u0 && u2 > u1);
    long gen = trace_cmds_find(&s, 0, "glEnable(cap=GL_TEXTURE_GEN_S)");
    CHECK(gen > u0 && gen < u1);
    char want[96];
    snprintf(want, sizeof want, "glBindTexture(target=GL_TEXTURE_2D, texture=%u)", tex);
    long b = trace_cmds_find(&s, (size_t)(u1 > 0 ? u1 : 0), want);
    CHECK(b > u1 && b < u2);
    /* Unit 0 is the program's: named last. */
    long last = find_last(&s, s.count, "glActiveTexture(");
    CHECK(last > u2 && strcmp(s.lines[last], "glActiveTexture(texture=GL_TEXTURE0)") == 0);
    trace_cmds_done(&s, "in-list snapshot");
    trace_cmds_free(&c);
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
    char p1[64], p2[64], p3[64], p4[64];
    snprintf(p1, sizeof p1, "%s/objects.raygl", dir);
    snprintf(p2, sizeof p2, "%s/ext.raygl", dir);
    snprintf(p3, sizeof p3, "%s/updates.raygl", dir);
    snprintf(p4, sizeof p4, "%s/inlist.raygl", dir);
    test_objects(p1);
    test_ext(p2);
    test_updates(p3);
    test_in_list(p4);
    glFinish();
    OSMesaDestroyContext(ctx);
    if (!check_failures) {
        unlink(p1);
        unlink(p2);
        unlink(p3);
        unlink(p4);
        rmdir(dir);
    }
    return check_exit();
}
