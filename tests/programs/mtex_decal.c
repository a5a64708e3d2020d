/* mtex_decal.c: a checkerboard on unit 0 (GL_MODULATE) and a lightmap with
 * its own coordinates on unit 1 in GL_DECAL (mtex_scene.h). */
#include "harness.h"
#include "mtex_scene.h"

static int draw(int w, int h) { return mtex_case(w, h, GL_MODULATE, GL_DECAL, false); }

RGL_TEST_MAIN(draw)
