/* conf_fog.c: one fog setting a frame (so that no frame changes the fog
 * between draws), on conf_fog.h's rectangles at eye distances 2 to 14:
 *   0  GL_LINEAR from 3 to 12 (rectangles before the start, inside, past
 *      the end)
 *   1  GL_EXP, density 0.12
 *   2  GL_EXP2, density 0.09
 *   3  GL_LINEAR with GL_FOG_START > GL_FOG_END (12 to 3): the factor runs
 *      the other way (nearer is foggier), clamped
 *   4  GL_EXP with density 0: no fog
 * conf_fog_start_end.c: GL_FOG_START equal to GL_FOG_END. */
#include "real.h"

#include <raygl/gl.h>

#include "conf_fog.h"

static void draw(int frame, int w, int h)
{
    static const GLint mode[5] = {GL_LINEAR, GL_EXP, GL_EXP2, GL_LINEAR, GL_EXP};
    static const float start[5] = {3, 0, 0, 12, 0}, end[5] = {12, 1, 1, 3, 1};
    static const float density[5] = {1, 0.12f, 0.09f, 1, 0};
    conf_fog_scene(w, h, mode[frame], start[frame], end[frame], density[frame]);
}

RGL_REAL_MAIN(draw, 5)
