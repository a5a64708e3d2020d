/* tex_lit_env.c: GL_BLEND and GL_ADD on lit surfaces (issue 14): the
 * grey wood-like texture of tex_lit_gold on two squares, left GL_BLEND
 * with a blue GL_TEXTURE_ENV_COLOR over a gold material (C = L (1 - Ct)
 * + Cc Ct per channel, L the lit colour), right GL_ADD (C = L + Ct) of a
 * darkened copy of the texture over a dim red material, under a local
 * viewer and a point light with no specular, dim enough that nothing
 * saturates. */
#include "harness.h"
#include "tex_scene.h"

/* Grey rings with a little grain, 16 x 16. */
static void wood(unsigned char px[16 * 16 * 3])
{
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            int r = ((x - 3) * (x - 3) + (y - 5) * (y - 5)) / 6;
            unsigned char v = (unsigned char)(r % 2 ? 150 : 230);
            v = (unsigned char)(v - ((x * 7 + y * 3) % 5) * 6);
            for (int k = 0; k < 3; k++)
                px[(y * 16 + x) * 3 + k] = v;
        }
}

static void square(float x0)
{
    enum { N = 16 };
    for (int j = 0; j < N; j++) {
        rayglBegin(GL_QUAD_STRIP);
        rayglNormal3f(0, 0, 1);
        for (int i = 0; i <= N; i++)
            for (int k = 1; k >= 0; k--) {
                float u = (float)i / N, v = (float)(j + k) / N;
                rayglTexCoord2f(u, v);
                rayglVertex2f(x0 + 1.4f * u, -1.2f + 2.4f * v);
            }
        rayglEnd();
    }
}

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(45, (double)w / h, 1, 100);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglEnable(GL_DEPTH_TEST);
    rayglLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    static const GLfloat lpos[4] = {0.5f, 1, 1, 1}, amb[4] = {0.25f, 0.25f, 0.25f, 1};
    static const GLfloat gold_d[4] = {0.75f, 0.6f, 0.18f, 1}, gold_a[4] = {0.45f, 0.36f, 0.1f, 1};
    static const GLfloat none[4] = {0, 0, 0, 1};
    rayglLightfv(GL_LIGHT0, GL_POSITION, lpos);
    rayglLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    rayglEnable(GL_LIGHTING);
    rayglEnable(GL_LIGHT0);
    rayglMaterialfv(GL_FRONT, GL_SPECULAR, none);
    unsigned char px[16 * 16 * 3];
    wood(px);
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    static const GLfloat env[4] = {0.2f, 0.35f, 0.9f, 1};
    rayglTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    rayglEnable(GL_TEXTURE_2D);
    rayglTranslatef(0, 0, -4);
    rayglRotatef(-30, 1, 0, 0);
    rayglMaterialfv(GL_FRONT, GL_DIFFUSE, gold_d);
    rayglMaterialfv(GL_FRONT, GL_AMBIENT, gold_a);
    square(-1.5f);
    /* ADD: the texture at a third of its brightness over dim red */
    for (int i = 0; i < 16 * 16 * 3; i++)
        px[i] = (unsigned char)(px[i] / 3);
    GLuint dim;
    rayglGenTextures(1, &dim);
    rayglBindTexture(GL_TEXTURE_2D, dim);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    static const GLfloat red_d[4] = {0.5f, 0.15f, 0.1f, 1}, red_a[4] = {0.3f, 0.1f, 0.1f, 1};
    rayglMaterialfv(GL_FRONT, GL_DIFFUSE, red_d);
    rayglMaterialfv(GL_FRONT, GL_AMBIENT, red_a);
    square(0.1f);
    return 0;
}

RGL_TEST_MAIN(draw)
