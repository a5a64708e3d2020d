/* tex_mirrored.c: the checkerboard with GL_MIRRORED_REPEAT, GL_NEAREST, GL_REPLACE (tex_scene.h):
 * the tiles left and right of the unit square, and above and below it,
 * are its mirror images (the red and green corner texels meet their
 * copies at the tile edges). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    return tex_case(w, h, GL_MIRRORED_REPEAT, GL_NEAREST, GL_REPLACE, GL_RGB);
}

RGL_TEST_MAIN(draw)
