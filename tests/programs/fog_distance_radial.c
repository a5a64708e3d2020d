/* fog_distance_radial.c: NV_fog_distance's GL_EYE_RADIAL_NV: GL_LINEAR fog
 * of the eye distance sqrt(xe^2 + ye^2 + ze^2) instead of |ze| (Mesa's
 * default, GL_EYE_PLANE_ABSOLUTE_NV). The scene of fog.h, whose objects off
 * the axis are fogged more than by |ze|.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#define FOG_SETUP                                           \
    do {                                                    \
        glFogi(GL_FOG_MODE, GL_LINEAR);                     \
        glFogf(GL_FOG_START, 3.0f);                         \
        glFogf(GL_FOG_END, 16.0f);                          \
        glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);  \
    } while (0)
#include "fog.h"
