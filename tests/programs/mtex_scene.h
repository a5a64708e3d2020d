/* mtex_scene.h: the multitexture scenes of the image tests.
 *
 * Unit 0 holds tex_scene.h's checkerboard (GL_REPEAT, GL_NEAREST) over the
 * quad with coordinates -0.5 .. 1.5; unit 1 a 4 x 4 "lightmap" of its own
 * (GL_CLAMP_TO_EDGE, GL_NEAREST) with other coordinates, 0 .. 1 over a
 * rotated range, so that the two units' coordinates differ and a unit
 * dropped or sampled with the other's coordinates shows.
 */
#ifndef RGL_MTEX_SCENE_H
#define RGL_MTEX_SCENE_H

#include "tex_scene.h"

#define MTEX_N 4

/* The lightmap: a ramp of warm to cool greys; alpha from 255 down to 40
 * across (DECAL blends by it). */
static inline void mtex_light(unsigned char px[MTEX_N * MTEX_N * 4])
{
    for (int y = 0; y < MTEX_N; y++)
        for (int x = 0; x < MTEX_N; x++) {
            unsigned char *p = px + (y * MTEX_N + x) * 4;
            p[0] = (unsigned char)(255 - 40 * y);
            p[1] = (unsigned char)(120 + 40 * x);
            p[2] = (unsigned char)(60 + 30 * (x + y));
            p[3] = (unsigned char)(255 - 70 * x);
        }
}

/* Both units' textures, unit 1 left active with env1 as its mode; unit 0
 * uses env0. */
static inline void mtex_make(GLenum env0, GLenum env1)
{
    rayglActiveTexture(GL_TEXTURE0);
    tex_make(GL_RGBA, GL_REPEAT, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env0);
    rayglEnable(GL_TEXTURE_2D);
    rayglActiveTexture(GL_TEXTURE1);
    unsigned char px[MTEX_N * MTEX_N * 4];
    mtex_light(px);
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, MTEX_N, MTEX_N, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env1);
    static const GLfloat envc[4] = {0.2f, 0.9f, 0.4f, 1};
    rayglTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envc);
    rayglEnable(GL_TEXTURE_2D);
}

static const float mtex_pos[4][2] = {{20, 20}, {300, 20}, {300, 220}, {20, 220}};
static const float mtex_st0[4][2] = {{-0.5f, -0.5f}, {1.5f, -0.5f}, {1.5f, 1.5f}, {-0.5f, 1.5f}};
static const float mtex_st1[4][2] = {{0.1f, 0.0f}, {1.0f, 0.15f}, {0.9f, 1.0f}, {0.0f, 0.85f}};

/* The quad; coloured: GL_MODULATE's corner colours (else one colour);
 * st1: unit 1's coordinates from glMultiTexCoord (else texgen). */
static inline void mtex_quad(bool coloured, bool st1)
{
    static const float col[4][3] = {{1, 1, 1}, {1, 0.5f, 0.5f}, {0.5f, 1, 0.6f}, {0.6f, 0.6f, 1}};
    static const float one[3] = {0.9f, 0.8f, 1.0f};
    rayglBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        rayglColor3fv(coloured ? col[i] : one);
        rayglMultiTexCoord2fv(GL_TEXTURE0, mtex_st0[i]);
        if (st1)
            rayglMultiTexCoord2f(GL_TEXTURE1, mtex_st1[i][0], mtex_st1[i][1]);
        rayglVertex2fv(mtex_pos[i]);
    }
    rayglEnd();
}

static inline int mtex_case(int w, int h, GLenum env0, GLenum env1, bool coloured)
{
    tex_view(w, h);
    mtex_make(env0, env1);
    mtex_quad(coloured, true);
    return 0;
}

#endif
