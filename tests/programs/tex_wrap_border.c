/* tex_wrap_border.c: wrap modes and the border colour under GL_LINEAR
 * (issue 22). A 4 x 4 texture magnified ~14 pixels a texel, coordinates
 * -0.5 .. 1.5, GL_TEXTURE_BORDER_COLOR blue. Top row, the same wrap on
 * both axes: GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP (the edge texels' outer
 * half blended with the border colour, constant beyond), GL_CLAMP_TO_BORDER
 * (the border colour outside, blended across the edge),
 * GL_MIRRORED_REPEAT; the image given with a one-texel orange border
 * (glTexImage2D border 1), which Mesa strips, so the border colour is
 * what GL_CLAMP and GL_CLAMP_TO_BORDER meet. Bottom row, per-axis pairs
 * (s, t): CLAMP/REPEAT, CLAMP_TO_BORDER/CLAMP, REPEAT/CLAMP_TO_BORDER,
 * MIRRORED_REPEAT/CLAMP, and CLAMP_TO_BORDER under GL_NEAREST. REPLACE,
 * unlit, gluOrtho2D. */
#include <stdbool.h>
#include <string.h>

#include "harness.h"

#include <raygl/gl.h>

#ifndef GL_CLAMP_TO_BORDER
#define GL_CLAMP_TO_BORDER 0x812D
#endif
#ifndef GL_MIRRORED_REPEAT
#define GL_MIRRORED_REPEAT 0x8370
#endif

enum { N = 4 };

static void quad(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(-0.5f, -0.5f);
    glVertex2f(x0, y0);
    glTexCoord2f(1.5f, -0.5f);
    glVertex2f(x1, y0);
    glTexCoord2f(1.5f, 1.5f);
    glVertex2f(x1, y1);
    glTexCoord2f(-0.5f, 1.5f);
    glVertex2f(x0, y1);
    glEnd();
}

static void texture(GLuint name, bool bordered, const unsigned char *px, const unsigned char *pb,
                    GLint ws, GLint wt, GLint filter)
{
    static const GLfloat blue[4] = {0.1f, 0.3f, 0.9f, 1};
    glBindTexture(GL_TEXTURE_2D, name);
    if (bordered)
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, N + 2, N + 2, 1, GL_RGB, GL_UNSIGNED_BYTE, pb);
    else
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, N, N, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, ws);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wt);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, blue);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.13f, 0.37f, 0.0f);
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char px[N * N * 3], pb[(N + 2) * (N + 2) * 3];
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            unsigned char *p = px + (y * N + x) * 3;
            bool light = (x + y) % 2 == 0;
            p[0] = light ? 220 : 40;
            p[1] = light ? 220 : 40;
            p[2] = light ? 220 : 120;
            if (x == N - 1 && y == N - 1)
                p[0] = 250, p[1] = 10, p[2] = 10;
        }
    for (int y = 0; y < N + 2; y++)
        for (int x = 0; x < N + 2; x++) {
            unsigned char *p = pb + (y * (N + 2) + x) * 3;
            if (x == 0 || y == 0 || x == N + 1 || y == N + 1)
                p[0] = 255, p[1] = 128, p[2] = 0;
            else
                memcpy(p, px + ((y - 1) * N + (x - 1)) * 3, 3);
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    GLuint names[10];
    glGenTextures(10, names);
    static const GLint same[5] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_CLAMP_TO_BORDER,
                                  GL_MIRRORED_REPEAT};
    for (int k = 0; k < 5; k++) {
        texture(names[k], true, px, pb, same[k], same[k], GL_LINEAR);
        quad(6 + 62.0f * k, 125, 62 + 62.0f * k, 225);
    }
    static const GLint pair[5][3] = {{GL_CLAMP, GL_REPEAT, GL_LINEAR},
                                     {GL_CLAMP_TO_BORDER, GL_CLAMP, GL_LINEAR},
                                     {GL_REPEAT, GL_CLAMP_TO_BORDER, GL_LINEAR},
                                     {GL_MIRRORED_REPEAT, GL_CLAMP, GL_LINEAR},
                                     {GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER, GL_NEAREST}};
    for (int k = 0; k < 5; k++) {
        texture(names[5 + k], false, px, pb, pair[k][0], pair[k][1], pair[k][2]);
        quad(6 + 62.0f * k, 10, 62 + 62.0f * k, 110);
    }
    return 0;
}

RGL_TEST_MAIN(draw)
