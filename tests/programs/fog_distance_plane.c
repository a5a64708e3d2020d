/* fog_distance_plane.c: NV_fog_distance's GL_EYE_PLANE: the fog takes the
 * signed eye-plane distance z_eye, negative in front of the eye, so
 * GL_EXP fog's factor e^(-density z_eye) is past 1 and clamped: nothing is
 * fogged (Mesa; measured). The scene of fog.h, first with
 * GL_EYE_PLANE_ABSOLUTE_NV (Mesa's default) set and then GL_EYE_PLANE.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#define FOG_SETUP                                                \
    do {                                                         \
        glFogi(GL_FOG_MODE, GL_EXP);                             \
        glFogf(GL_FOG_DENSITY, 0.12f);                           \
        glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE_ABSOLUTE_NV); \
        glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE);           \
    } while (0)
#include "fog.h"
