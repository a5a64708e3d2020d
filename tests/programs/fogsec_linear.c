/* fogsec_linear.c: GL_LINEAR fog from 4 to 24 on GLU and GLUT shapes. */
#define FOG_SETUP                       \
    do {                                \
        glFogi(GL_FOG_MODE, GL_LINEAR); \
        glFogf(GL_FOG_START, 4.0f);     \
        glFogf(GL_FOG_END, 24.0f);      \
    } while (0)
#include "fogsec_shapes.h"
