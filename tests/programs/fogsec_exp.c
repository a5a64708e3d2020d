/* fogsec_exp.c: GL_EXP fog of density 0.09 on GLU and GLUT shapes. */
#define FOG_SETUP                         \
    do {                                  \
        glFogi(GL_FOG_MODE, GL_EXP);      \
        glFogf(GL_FOG_DENSITY, 0.09f);    \
    } while (0)
#include "fogsec_shapes.h"
