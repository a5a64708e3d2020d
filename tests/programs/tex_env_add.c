/* tex_env_add.c: GL_TEXTURE_ENV_MODE GL_ADD, one unit, unlit: a dim
 * 8 x 8 texture added to dim corner colours (C = Cf + Ct, GL 1.5 table
 * 3.22), and a second quad whose sum saturates (clamped to 1). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    unsigned char px[TEX_N * TEX_N * 3];
    for (int y = 0; y < TEX_N; y++)
        for (int x = 0; x < TEX_N; x++) {
            unsigned char *p = px + (y * TEX_N + x) * 3;
            p[0] = (unsigned char)(x * 15);
            p[1] = (unsigned char)(y * 15);
            p[2] = (unsigned char)((x + y) % 2 ? 110 : 20);
        }
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX_N, TEX_N, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    rayglEnable(GL_TEXTURE_2D);
    static const float col[4][3] = {{0.5f, 0.2f, 0.1f}, {0.1f, 0.5f, 0.3f},
                                    {0.3f, 0.1f, 0.5f}, {0.4f, 0.4f, 0.4f}};
    static const float pos[4][2] = {{20, 20}, {200, 20}, {200, 220}, {20, 220}};
    static const float st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    rayglBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        rayglColor3fv(col[i]);
        rayglTexCoord2fv(st[i]);
        rayglVertex2fv(pos[i]);
    }
    /* one colour: the clamp is the same at every corner */
    rayglColor3f(0.9f, 0.8f, 0.3f);
    for (int i = 0; i < 4; i++) {
        rayglTexCoord2fv(st[i]);
        rayglVertex2f(pos[i][0] * 0.4f + 210, pos[i][1]);
    }
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
