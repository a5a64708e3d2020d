/* tex_scene.h: the textured scenes of the texture image tests (issue 5).
 *
 * An 8 x 8 checkerboard of two colours whose bottom-left texel is green and
 * top-right texel red (so a flip or a transposition shows), mapped onto a
 * quad under gluOrtho2D(0, 320, 0, 240) with coordinates from -0.5 to 1.5
 * (two tiles each way: the wrap mode decides what lies outside the unit
 * square). A texel covers about 17 x 12 pixels at 320x240: the texture is
 * magnified, so the magnification filter decides, as in the tests' claims.
 * The corners carry different colours, which MODULATE and DECAL show.
 */
#ifndef RGL_TEX_SCENE_H
#define RGL_TEX_SCENE_H

#include <stdbool.h>

#include "raygl.h"

#define TEX_N 8

/* The checkerboard as RGBA bytes, bottom row first; alpha 255 on the
 * light squares and 64 on the dark ones (DECAL blends by it). */
static inline void tex_checker(unsigned char px[TEX_N * TEX_N * 4])
{
    for (int y = 0; y < TEX_N; y++)
        for (int x = 0; x < TEX_N; x++) {
            unsigned char *p = px + (y * TEX_N + x) * 4;
            bool light = (x + y) % 2 == 0;
            p[0] = light ? 230 : 30;
            p[1] = light ? 200 : 60;
            p[2] = light ? 40 : 200;
            p[3] = light ? 255 : 64;
            if (x == 0 && y == 0) {
                p[0] = 20, p[1] = 220, p[2] = 60;
            } else if (x == TEX_N - 1 && y == TEX_N - 1) {
                p[0] = 250, p[1] = 10, p[2] = 10;
            }
        }
}

static inline void tex_view(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.13f, 0.37f, 0.0f);
    rayglClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* A bound 2D texture object holding the checkerboard in `internal` format
 * with the given wrap and filter. */
static inline void tex_make(GLint internal, GLenum wrap, GLenum filter)
{
    unsigned char px[TEX_N * TEX_N * 4];
    tex_checker(px);
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    rayglTexImage2D(GL_TEXTURE_2D, 0, internal, TEX_N, TEX_N, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wrap);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wrap);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)filter);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter);
}

/* The quad, corners coloured; tc: glTexCoord per corner (else texgen). */
static inline void tex_quad(bool tc)
{
    static const float pos[4][2] = {{20, 20}, {300, 20}, {300, 220}, {20, 220}};
    static const float st[4][2] = {{-0.5f, -0.5f}, {1.5f, -0.5f}, {1.5f, 1.5f}, {-0.5f, 1.5f}};
    static const float col[4][3] = {{1, 1, 1}, {1, 0.5f, 0.5f}, {0.5f, 1, 0.6f}, {0.6f, 0.6f, 1}};
    rayglBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        rayglColor3fv(col[i]);
        if (tc)
            rayglTexCoord2fv(st[i]);
        rayglVertex2fv(pos[i]);
    }
    rayglEnd();
}

/* The common case: one 2D texture, wrap, filter and environment mode. */
static inline int tex_case(int w, int h, GLenum wrap, GLenum filter, GLenum env, GLint internal)
{
    tex_view(w, h);
    tex_make(internal, wrap, filter);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
    rayglEnable(GL_TEXTURE_2D);
    tex_quad(true);
    return 0;
}

#endif
