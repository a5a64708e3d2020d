/* tex_alpha_linear.c: tex_alpha_tree.c with GL_LINEAR filtering: GL tests
 * the filtered alpha per fragment, so the crown's edge is a crisp curve
 * between texel centres, not a texel staircase nor a soft ramp. */
#define TREE_FILTER GL_LINEAR
#include "tex_alpha_tree.c"
