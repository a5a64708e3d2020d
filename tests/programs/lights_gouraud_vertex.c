/* lights_gouraud_vertex.c: lights_gouraud.h's scene with a local viewer,
 * translated with --vertex-lighting: GL's per-vertex lit colours,
 * interpolated as GL interpolates them (docs/mapping.md "Gouraud and
 * per-pixel").
 */
#include "lights_gouraud.h"

static int draw(int w, int h)
{
    gouraud_scene(w, h, 1);
    return 0;
}

RGL_TEST_MAIN(draw)
