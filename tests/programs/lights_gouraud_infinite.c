/* lights_gouraud_infinite.c: lights_gouraud.h's scene, GL_LIGHT_MODEL_LOCAL_VIEWER
 * false (GL's default): how far GL's per-vertex lighting lies from
 * POV-Ray's per-pixel lighting (docs/mapping.md "Gouraud and per-pixel").
 */
#include "lights_gouraud.h"

static int draw(int w, int h)
{
    gouraud_scene(w, h, 0);
    return 0;
}

RGL_TEST_MAIN(draw)
