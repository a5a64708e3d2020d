/* fog_linear.c: GL_LINEAR fog from 3 to 16. */
#define FOG_SETUP                       \
    do {                                \
        glFogi(GL_FOG_MODE, GL_LINEAR); \
        glFogf(GL_FOG_START, 3.0f);     \
        glFogf(GL_FOG_END, 16.0f);      \
    } while (0)
#include "fog.h"
