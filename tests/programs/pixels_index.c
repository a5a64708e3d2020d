/* pixels_index.c: colour-index pixel rectangles in an RGBA context (GL 2.1
 * 3.6.3, 3.6.5; issue 22): glDrawPixels of GL_COLOR_INDEX looked up in the
 * GL_PIXEL_MAP_I_TO_R, _G, _B, _A maps (glPixelMapfv, uiv, usv), each index
 * masked to its map's size (16 and 4 entries: index 18 takes entry 2).
 * Blocks of unsigned bytes, shorts and floats; one with GL_INDEX_SHIFT 1
 * and GL_INDEX_OFFSET 3, which Mesa does not apply on this path (measured;
 * the spec shifts and offsets first). Over a cleared background,
 * glPixelZoom 3. */
#include "harness.h"

#include <raygl/gl.h>

enum { N = 8 };

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    static GLfloat r[16];
    static GLuint g[16];
    static GLushort b[4];
    static GLfloat a[2] = {1, 1};
    for (int i = 0; i < 16; i++) {
        r[i] = (i & 1 ? 0.9f : 0.15f) + 0.05f * (i & 2);
        g[i] = i & 4 ? 0xE0000000u : 0x30000000u;
    }
    for (int i = 0; i < 4; i++)
        b[i] = (GLushort)(6000 + 19000 * i);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 16, r);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_G, 16, g);
    glPixelMapusv(GL_PIXEL_MAP_I_TO_B, 4, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, a);
    static GLubyte ub[N * N];
    static GLushort us[N * N];
    static GLfloat fl[N * N];
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            int i = (x + 3 * y) % 19;
            ub[y * N + x] = (GLubyte)i;
            us[y * N + x] = (GLushort)(i + 256);
            fl[y * N + x] = (float)i + 0.25f;
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelZoom(3, 3);
    glRasterPos2i(20, 30);
    glDrawPixels(N, N, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(120, 30);
    glDrawPixels(N, N, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, us);
    glRasterPos2i(220, 30);
    glDrawPixels(N, N, GL_COLOR_INDEX, GL_FLOAT, fl);
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    glRasterPos2i(20, 140);
    glDrawPixels(N, N, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    return 0;
}

RGL_TEST_MAIN(draw)
