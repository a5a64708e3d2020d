/* fog_exp2.c: GL_EXP2 fog of density 0.1. */
#define FOG_SETUP                        \
    do {                                 \
        glFogi(GL_FOG_MODE, GL_EXP2);    \
        glFogf(GL_FOG_DENSITY, 0.1f);    \
    } while (0)
#include "fog.h"
