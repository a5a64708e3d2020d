/* conf_fog_start_end.c: GL_LINEAR fog with GL_FOG_START equal to
 * GL_FOG_END, where the spec's factor (end - z) / (end - start) divides by
 * zero, on conf_fog.h's rectangles at eye distances 2 to 14:
 *   0  start = end = 8: Mesa fogs what lies nearer than 8 wholly, from 8
 *      to 9 partly, and leaves what lies past 9 (measured: the factor is
 *      clamp(z - 8))
 *   1  start = end = 0: nothing fogged (every distance is past 1) */
#include "real.h"

#include <raygl/gl.h>

#include "conf_fog.h"

static void draw(int frame, int w, int h)
{
    conf_fog_scene(w, h, GL_LINEAR, frame == 0 ? 8.0f : 0.0f, frame == 0 ? 8.0f : 0.0f, 1.0f);
}

RGL_REAL_MAIN(draw, 2)
