/* tex_border.c: texture borders and GL_TEXTURE_BASE_LEVEL (the
 * conformance items of issue 14). Left: an 8 x 8 checkerboard with a
 * one-texel orange border (glTexImage2D border 1, a 10 x 10 image),
 * GL_REPEAT, GL_CLAMP_TO_EDGE and GL_CLAMP, GL_NEAREST (Mesa keeps no
 * border texels: it strips the border, as the translator does). Right: a texture whose level
 * 0 is white and levels 1.. grey, with GL_TEXTURE_BASE_LEVEL 1 and
 * GL_TEXTURE_MAX_LEVEL 3: GL draws grey. */
#include <stdbool.h>
#include <string.h>

#include "harness.h"
#include "raygl.h"

static void quad(float x0, float x1, float s0, float s1)
{
    rayglBegin(GL_QUADS);
    rayglTexCoord2f(s0, s0);
    rayglVertex2f(x0, 20);
    rayglTexCoord2f(s1, s0);
    rayglVertex2f(x1, 20);
    rayglTexCoord2f(s1, s1);
    rayglVertex2f(x1, 220);
    rayglTexCoord2f(s0, s1);
    rayglVertex2f(x0, 220);
    rayglEnd();
}

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.13f, 0.37f, 0.0f);
    rayglClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    enum { N = 10 };
    unsigned char px[N * N * 3];
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            unsigned char *p = px + (y * N + x) * 3;
            bool border = x == 0 || y == 0 || x == N - 1 || y == N - 1;
            bool light = (x + y) % 2 == 0;
            p[0] = (unsigned char)(border ? 255 : light ? 220 : 40);
            p[1] = (unsigned char)(border ? 128 : light ? 220 : 40);
            p[2] = (unsigned char)(border ? 0 : light ? 220 : 120);
        }
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 1); /* rows of 30 bytes */
    GLuint names[4];
    rayglGenTextures(4, names);
    rayglEnable(GL_TEXTURE_2D);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    static const GLint wraps[3] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP};
    for (int k = 0; k < 3; k++) {
        rayglBindTexture(GL_TEXTURE_2D, names[k]);
        rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, N, N, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
        rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[k]);
        rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[k]);
        rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        quad(10 + 77.0f * k, 80 + 77.0f * k, -0.25f, 1.25f);
    }
    /* levels 0 (8 x 8 white) .. 3 (1 x 1 grey) */
    rayglBindTexture(GL_TEXTURE_2D, names[3]);
    static unsigned char lv[8 * 8 * 3];
    for (int l = 0; l < 4; l++) {
        int s = 8 >> l;
        memset(lv, l == 0 ? 255 : 128, sizeof lv);
        rayglTexImage2D(GL_TEXTURE_2D, l, GL_RGB, s, s, 0, GL_RGB, GL_UNSIGNED_BYTE, lv);
    }
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    quad(241, 311, 0, 1);
    return 0;
}

RGL_TEST_MAIN(draw)
