/* tex_lit_gold.c: GL_MODULATE on lit surfaces with coloured materials
 * (issue 14): a grey wood-like texture on two squares, one of a gold
 * material (diffuse and ambient), one yellow-tinted through
 * GL_COLOR_MATERIAL, under a local viewer and a point light with no
 * specular, dim enough that GL never clamps the lit colour before the
 * texture multiplies it. GL multiplies the texel by the lit colour per channel; a
 * scalar diffuse turns the gold grey. */
#include "tex_lit_scene.h"

static int draw(int w, int h)
{
    unsigned char px[16 * 16 * 3];
    tex_lit_begin(w, h, px);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    tex_lit_place();
    static const GLfloat gold_d[4] = {0.75f, 0.6f, 0.18f, 1}, gold_a[4] = {0.45f, 0.36f, 0.1f, 1};
    rayglMaterialfv(GL_FRONT, GL_DIFFUSE, gold_d);
    rayglMaterialfv(GL_FRONT, GL_AMBIENT, gold_a);
    tex_lit_square(-1.5f, 1.4f, false);
    rayglColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    rayglEnable(GL_COLOR_MATERIAL);
    rayglColor3f(0.75f, 0.65f, 0.3f);
    tex_lit_square(0.1f, 1.4f, false);
    return 0;
}

RGL_TEST_MAIN(draw)
