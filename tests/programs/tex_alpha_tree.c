/* tex_alpha_tree.c: the alpha test (glAlphaFunc(GL_GREATER, 0.5),
 * GL_ALPHA_TEST) on an alpha-textured tree billboard, GL_NEAREST,
 * GL_MODULATE, in perspective over a ground quad with the depth test on:
 * texels whose alpha fails vanish (their alpha is 0, 0.4 or 0.6 around
 * the crown, so the reference matters), with crisp edges. Two untextured
 * squares with vertex alpha 0.3 (discarded) and 0.8 (kept), no blending. */
#include <stdbool.h>

#include "harness.h"
#include "raygl.h"

enum { T = 16 };

/* tex_alpha_linear.c draws the same with GL_LINEAR. */
#ifndef TREE_FILTER
#define TREE_FILTER GL_NEAREST
#endif

static void tree(unsigned char px[T * T * 4])
{
    for (int y = 0; y < T; y++)
        for (int x = 0; x < T; x++) {
            unsigned char *p = px + (y * T + x) * 4;
            int dx = x - 8, dy = y - 10;
            int d2 = dx * dx * 2 + dy * dy * 3;
            bool trunk = y < 6 && x >= 7 && x <= 8;
            p[0] = trunk ? 110 : (unsigned char)(30 + x * 4);
            p[1] = trunk ? 70 : (unsigned char)(120 + y * 6);
            p[2] = trunk ? 30 : 40;
            p[3] = trunk || d2 < 60 ? 255 : d2 < 80 ? 153 : d2 < 110 ? 102 : 0;
        }
}

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.45f, 0.6f, 0.85f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(50, (double)w / h, 0.5, 50);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    raygluLookAt(0, 1.2, 5, 0, 0.9, 0, 0, 1, 0);
    rayglEnable(GL_DEPTH_TEST);
    rayglColor3f(0.35f, 0.5f, 0.2f); /* ground */
    rayglBegin(GL_QUADS);
    rayglVertex3f(-6, 0, -6);
    rayglVertex3f(-6, 0, 6);
    rayglVertex3f(6, 0, 6);
    rayglVertex3f(6, 0, -6);
    rayglEnd();
    unsigned char px[T * T * 4];
    tree(px);
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, TREE_FILTER);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, TREE_FILTER);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    rayglAlphaFunc(GL_GREATER, 0.5f);
    rayglEnable(GL_ALPHA_TEST);
    rayglEnable(GL_TEXTURE_2D);
    rayglColor3f(1, 1, 1);
    /* two crossed billboards, one behind the other's gaps */
    for (int k = 0; k < 2; k++) {
        float x0 = k ? -1.6f : -0.3f, z = k ? -1.5f : 0.0f;
        rayglBegin(GL_QUADS);
        rayglTexCoord2f(0, 0);
        rayglVertex3f(x0, 0, z);
        rayglTexCoord2f(1, 0);
        rayglVertex3f(x0 + 2, 0, z);
        rayglTexCoord2f(1, 1);
        rayglVertex3f(x0 + 2, 2.4f, z);
        rayglTexCoord2f(0, 1);
        rayglVertex3f(x0, 2.4f, z);
        rayglEnd();
    }
    rayglDisable(GL_TEXTURE_2D);
    static const float al[2] = {0.3f, 0.8f};
    for (int k = 0; k < 2; k++) {
        rayglColor4f(0.9f, 0.2f, 0.2f, al[k]);
        float x0 = 1.8f + 0.7f * k;
        rayglBegin(GL_QUADS);
        rayglVertex3f(x0, 0.2f, 0.5f);
        rayglVertex3f(x0 + 0.5f, 0.2f, 0.5f);
        rayglVertex3f(x0 + 0.5f, 0.7f, 0.5f);
        rayglVertex3f(x0, 0.7f, 0.5f);
        rayglEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
