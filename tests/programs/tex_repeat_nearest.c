/* tex_repeat_nearest.c: the checkerboard with GL_REPEAT, GL_NEAREST, GL_MODULATE, internal format GL_RGB
 * (tex_scene.h). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h) { return tex_case(w, h, GL_REPEAT, GL_NEAREST, GL_MODULATE, GL_RGB); }

RGL_TEST_MAIN(draw)
