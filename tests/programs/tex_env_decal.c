/* tex_env_decal.c: the checkerboard with GL_REPEAT, GL_NEAREST, GL_DECAL, internal format GL_RGBA
 * (tex_scene.h). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h) { return tex_case(w, h, GL_REPEAT, GL_NEAREST, GL_DECAL, GL_RGBA); }

RGL_TEST_MAIN(draw)
