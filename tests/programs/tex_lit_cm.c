/* tex_lit_cm.c: GL_MODULATE on a lit surface whose GL_COLOR_MATERIAL
 * colour varies over the mesh (issue 14): the grey wood-like texture of
 * tex_lit_gold on one square of 16 x 16 quads whose vertex colours run
 * from yellow to cyan to magenta, under a local viewer and a point light
 * with no specular. One image cannot carry the colours: each colour entry
 * multiplies a function of the image by its own colour. */
#include "tex_lit_scene.h"

static int draw(int w, int h)
{
    unsigned char px[16 * 16 * 3];
    tex_lit_begin(w, h, px);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    tex_lit_place();
    rayglColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    rayglEnable(GL_COLOR_MATERIAL);
    tex_lit_square(-1.4f, 2.8f, true);
    return 0;
}

RGL_TEST_MAIN(draw)
