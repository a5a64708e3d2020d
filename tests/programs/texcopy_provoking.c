/* texcopy_provoking.c: begin_modes.c with GL_FLAT shading and
 * glProvokingVertex(GL_FIRST_VERTEX_CONVENTION). */
#define BEGIN_MODES_FLAT 1
#define BEGIN_MODES_FIRST 1
#include "begin_modes.c"
