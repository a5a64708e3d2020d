/* tex_repeat_linear.c: the checkerboard with GL_REPEAT, GL_LINEAR, GL_REPLACE, internal format GL_RGB
 * (tex_scene.h). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h) { return tex_case(w, h, GL_REPEAT, GL_LINEAR, GL_REPLACE, GL_RGB); }

RGL_TEST_MAIN(draw)
