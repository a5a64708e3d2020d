/* fog_exp.c: GL_EXP fog of density 0.12. */
#define FOG_SETUP                        \
    do {                                 \
        glFogi(GL_FOG_MODE, GL_EXP);     \
        glFogf(GL_FOG_DENSITY, 0.12f);   \
    } while (0)
#include "fog.h"
