/* begin_modes_flat.c: begin_modes.c with GL_FLAT shading (provoking vertex). */
#define BEGIN_MODES_FLAT 1
#include "begin_modes.c"
