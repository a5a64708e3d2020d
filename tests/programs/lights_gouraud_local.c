/* lights_gouraud_local.c: lights_gouraud.h's scene, GL_LIGHT_MODEL_LOCAL_VIEWER
 * true: how far GL's per-vertex lighting lies from
 * POV-Ray's per-pixel lighting (docs/mapping.md "Gouraud and per-pixel").
 */
#include "lights_gouraud.h"

static int draw(int w, int h)
{
    gouraud_scene(w, h, 1);
    return 0;
}

RGL_TEST_MAIN(draw)
