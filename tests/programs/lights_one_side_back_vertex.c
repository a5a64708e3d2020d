/* lights_one_side_back_vertex.c: lights_one_side_back.c's frame translated
 * with --vertex-lighting, which lights back faces as OpenGL does (the
 * normal as given): exact where the per-pixel default is a known failure.
 */
#include "lights_one_side_back.c"
