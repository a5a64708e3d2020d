/* fogsec_exp2.c: GL_EXP2 fog of density 0.07 on GLU and GLUT shapes. */
#define FOG_SETUP                         \
    do {                                  \
        glFogi(GL_FOG_MODE, GL_EXP2);     \
        glFogf(GL_FOG_DENSITY, 0.07f);    \
    } while (0)
#include "fogsec_shapes.h"
