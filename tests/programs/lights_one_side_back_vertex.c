/* lights_one_side_back_vertex.c: lights_one_side_back.c's frame translated
 * with --vertex-lighting, which lights back faces as OpenGL does (the
 * normal as given): exact for the whole frame, as the default is for its
 * back faces.
 */
#include "lights_one_side_back.c"
