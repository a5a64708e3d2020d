/* tex_env_replace.c: the checkerboard with GL_REPEAT, GL_NEAREST, GL_REPLACE, internal format GL_RGBA
 * (tex_scene.h). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h) { return tex_case(w, h, GL_REPEAT, GL_NEAREST, GL_REPLACE, GL_RGBA); }

RGL_TEST_MAIN(draw)
