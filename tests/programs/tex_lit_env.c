/* tex_lit_env.c: GL_BLEND and GL_ADD on lit surfaces (issue 14): the
 * grey wood-like texture of tex_lit_gold on two squares, left GL_BLEND
 * with a blue GL_TEXTURE_ENV_COLOR over a gold material (C = L (1 - Ct)
 * + Cc Ct per channel, L the lit colour), right GL_ADD (C = L + Ct) of a
 * darkened copy of the texture over a dim red material, under a local
 * viewer and a point light with no specular, dim enough that nothing
 * saturates. */
#include "tex_lit_scene.h"

static int draw(int w, int h)
{
    unsigned char px[16 * 16 * 3];
    tex_lit_begin(w, h, px);
    static const GLfloat env[4] = {0.2f, 0.35f, 0.9f, 1};
    rayglTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    tex_lit_place();
    static const GLfloat gold_d[4] = {0.75f, 0.6f, 0.18f, 1}, gold_a[4] = {0.45f, 0.36f, 0.1f, 1};
    rayglMaterialfv(GL_FRONT, GL_DIFFUSE, gold_d);
    rayglMaterialfv(GL_FRONT, GL_AMBIENT, gold_a);
    tex_lit_square(-1.5f, 1.4f, false);
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
    tex_lit_square(0.1f, 1.4f, false);
    return 0;
}

RGL_TEST_MAIN(draw)
