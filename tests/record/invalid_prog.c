/* invalid_prog.c: a GL program that makes many calls GL refuses (wrong
 * enums, sizes, calls inside glBegin/glEnd, pixel unpack buffer offsets
 * past the buffer's end or into a mapped one, draws with bad modes and
 * short index buffers), with small client buffers behind them, and a few
 * valid ones; it prints the GL error after each and a checksum of what it
 * drew. Built twice (tests/record/meson.build): plain, and with
 * -include raygl/gl.h so every recorded call goes through the recorder.
 * same_output.sh runs both: the recorder must not change a line or the
 * exit status (the recorder is as safe as GL: issue 12). OSMesa: no GPU,
 * no display. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <GL/osmesa.h>

#define SIDE 32

static int step;

static void report(const char *what)
{
    printf("%3d %#06x %s\n", step++, (unsigned)glGetError(), what);
}

/* Makes the call, then prints its text and GL's error. */
#define TRY(...)            \
    do {                    \
        __VA_ARGS__;        \
        report(#__VA_ARGS__); \
    } while (0)

#define AT(n) ((const void *)(uintptr_t)(n))

static GLubyte frame[SIDE * SIDE * 4];
static const GLfloat one3[1] = {1}; /* one value where some pnames take three */

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, frame, GL_UNSIGNED_BYTE, SIDE, SIDE)) {
        fprintf(stderr, "invalid_prog: no OSMesa context\n");
        return 1;
    }
    static GLubyte data[4092];
    for (size_t i = 0; i < sizeof data; i++)
        data[i] = (GLubyte)(i * 13 + (i >> 8));
    static GLubyte tiny[4] = {255, 128, 0, 255};
    static const GLuint tidx[1] = {0};

    GLuint tex = 0, pbo = 0, bufs[2] = {0, 0};
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    /* A pixel unpack buffer of 4092 bytes: offsets, not addresses. */
    TRY(glGenBuffers(1, &pbo));
    TRY(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo));
    TRY(glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof data, data, GL_STREAM_DRAW));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, AT(0)));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, AT(0x800)));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, AT(0x400)));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, AT(0xc00)));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, AT(-64)));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, AT(0x7fffffff)));
    TRY(glPixelStorei(GL_UNPACK_ROW_LENGTH, 2000));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, AT(0)));
    TRY(glPixelStorei(GL_UNPACK_ROW_LENGTH, 0));
    TRY(glPixelStorei(GL_UNPACK_SKIP_ROWS, 4));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, AT(4)));
    TRY(glPixelStorei(GL_UNPACK_SKIP_ROWS, 0));
    TRY(glMapBuffer(GL_PIXEL_UNPACK_BUFFER, GL_WRITE_ONLY));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, AT(0)));
    TRY(glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER));
    TRY(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 2048, 0, GL_RGBA, GL_UNSIGNED_BYTE, AT(0x100)));
    TRY(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, AT(16)));
    TRY(glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0));

    /* Client memory of 4 bytes behind images GL refuses. */
    TRY(glTexImage2D(0x1234, 0, GL_RGBA, 1024, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1024, 1024, 0, 0x1234, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1024, 1024, 0, GL_RGBA, 0x1234, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 1024, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1024, 1024, 0, GL_RGBA,
                     GL_UNSIGNED_SHORT_5_6_5, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1024, 1024, 0, GL_RGB, GL_BITMAP, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 1024, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 40, GL_RGBA, 1024, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1024, 1024, 2, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1 << 20, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 100, 100, 1024, 1024, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1024, 1024, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 1024, 1024, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1024, 1024, GL_RGBA, GL_UNSIGNED_BYTE,
                        tiny));
    TRY(glBegin(GL_POINTS);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1024, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny);
        glEnd());
    TRY(glTexSubImage2D(GL_TEXTURE_2D, 0, 15, 15, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    /* 3D images GL refuses over the same 4 bytes, and copies it refuses. */
    TRY(glTexImage3D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 64, -1, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 64, 64, 64, 0, GL_RGBA, 0x1234, tiny));
    TRY(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1 << 14, 1 << 14, 64, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, tiny));
    TRY(glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 64, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    TRY(glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1 << 20));
    TRY(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    TRY(glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0));
    TRY(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -1, 8, 0));
    TRY(glCopyTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA, 0, 0, 8, 8, 0));
    TRY(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1 << 20, 1 << 20, 0));
    TRY(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 30, 30, 0, 0, 8, 8));
    TRY(glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 5, 0, 0, 8, 8));
    TRY(glProvokingVertex(0x1234));
    TRY(glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION + 100, one3));

    /* GLU refuses these before it reads (its return value printed). */
    printf("gluBuild2DMipmaps %d\n",
           gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 0, 1024, GL_RGBA, GL_UNSIGNED_BYTE, tiny));
    printf("gluBuild2DMipmaps %d\n", gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 1024, 1024,
                                                      GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, tiny));
    report("glGetError after GLU");

    /* Parameter names of other calls, one value behind them. */
    static GLfloat one[1] = {2};
    static GLint ione[1] = {2};
    TRY(glFogfv(GL_AMBIENT, one));
    TRY(glLightfv(GL_LIGHT0, GL_FOG_COLOR, one));
    TRY(glMaterialfv(GL_FRONT, GL_POSITION, one));
    TRY(glLightModelfv(GL_EYE_PLANE, one));
    TRY(glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_BORDER_COLOR, one));
    TRY(glTexGenfv(GL_S, GL_TEXTURE_ENV_COLOR, one));
    TRY(glTexParameterfv(GL_TEXTURE_2D, GL_SPECULAR, one));
    TRY(glTexParameteriv(GL_TEXTURE_2D, GL_EMISSION, ione));
    TRY(glFogfv(GL_FOG_DENSITY, one));
    static const GLubyte lists[2] = {1, 2};
    TRY(glCallLists(-1, GL_UNSIGNED_BYTE, lists));
    TRY(glCallLists(1 << 20, 0x1234, lists));

    /* Draws GL refuses, or that draw nothing, over 3 vertices and 1 index. */
    static const GLfloat tri[9] = {-1, -1, 0, 1, -1, 0, 1, 1, 0};
    TRY(glEnableClientState(GL_VERTEX_ARRAY));
    TRY(glVertexPointer(3, GL_FLOAT, 0, tri));
    TRY(glDrawArrays(0x20, 0, 1 << 20));
    TRY(glDrawArrays(GL_TRIANGLES, 0, -1));
    TRY(glDrawArrays(GL_TRIANGLES, -1, 3));
    TRY(glDrawElements(0x20, 1 << 20, GL_UNSIGNED_INT, tidx));
    TRY(glDrawElements(GL_TRIANGLES, 1 << 20, GL_FLOAT, tidx));
    TRY(glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_INT, tidx));
    TRY(glDrawRangeElements(GL_TRIANGLES, 5, 1, 1 << 20, GL_UNSIGNED_INT, tidx));
    static const GLint mf[2] = {0, 0};
    static const GLsizei mc[2] = {1 << 20, 3};
    TRY(glMultiDrawArrays(0x20, mf, mc, 2));
    TRY(glMultiDrawArrays(GL_TRIANGLES, mf, mc, -1));
    TRY(glBegin(GL_POINTS); glDrawArrays(GL_TRIANGLES, 0, 1 << 20); glEnd());
    TRY(glBegin(GL_POINTS); glDrawElements(GL_TRIANGLES, 1 << 20, GL_UNSIGNED_INT, tidx);
        glEnd());

    /* Buffers: an index buffer of 12 bytes read past its end, a vertex
     * buffer whose offsets are pointers. */
    static const GLuint idx3[3] = {0, 1, 2};
    TRY(glGenBuffers(2, bufs));
    TRY(glBindBuffer(GL_ARRAY_BUFFER, bufs[0]));
    TRY(glBufferData(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW));
    TRY(glVertexPointer(3, GL_FLOAT, 0, AT(0)));
    TRY(glBindBuffer(GL_ARRAY_BUFFER, 0));
    TRY(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bufs[1]));
    TRY(glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx3, idx3, GL_STATIC_DRAW));
    TRY(glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, AT(8)));
    TRY(glDrawElements(GL_TRIANGLES, 1 << 20, GL_UNSIGNED_INT, AT(0x10000)));
    TRY(glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_ONLY));
    TRY(glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, AT(0)));
    TRY(glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER));

    /* What it draws: the textured triangle, from both buffers. */
    TRY(glViewport(0, 0, SIDE, SIDE));
    TRY(glClearColor(0.25f, 0.5f, 0.75f, 1));
    TRY(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
    TRY(glEnable(GL_TEXTURE_2D));
    TRY(glEnableClientState(GL_TEXTURE_COORD_ARRAY));
    static const GLfloat uv[6] = {0, 0, 1, 0, 1, 1};
    TRY(glTexCoordPointer(2, GL_FLOAT, 0, uv));
    TRY(glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, AT(0)));
    TRY(glFinish());
    uint32_t sum = 2166136261u;
    for (size_t i = 0; i < sizeof frame; i++)
        sum = (sum ^ frame[i]) * 16777619u;
    printf("pixels %08x\n", (unsigned)sum);
    OSMesaDestroyContext(ctx);
    return 0;
}
