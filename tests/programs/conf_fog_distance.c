/* conf_fog_distance.c: GL_FOG_DISTANCE_MODE_NV (NV_fog_distance) set to its
 * default, GL_EYE_PLANE_ABSOLUTE_NV: the fog takes |eye z| as without it.
 * Linear fog from 3 to 12 over conf_fog.h's rectangles at eye distances 2
 * to 14. (With GL_EYE_RADIAL_NV the distance would be the eye radius.) */
#include "harness.h"

#include <raygl/gl.h>

#include "conf_fog.h"

#ifndef GL_FOG_DISTANCE_MODE_NV
#define GL_FOG_DISTANCE_MODE_NV 0x855A
#define GL_EYE_PLANE_ABSOLUTE_NV 0x855C
#endif

static int draw(int w, int h)
{
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE_ABSOLUTE_NV);
    conf_fog_scene(w, h, GL_LINEAR, 3.0f, 12.0f, 1.0f);
    return 0;
}

RGL_TEST_MAIN(draw)
