/* tex_clamp_nearest.c: the checkerboard with GL_CLAMP, GL_NEAREST, GL_REPLACE, internal format GL_RGB
 * (tex_scene.h). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h) { return tex_case(w, h, GL_CLAMP, GL_NEAREST, GL_REPLACE, GL_RGB); }

RGL_TEST_MAIN(draw)
