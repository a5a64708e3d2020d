/* vlit_glut_solids.c: glut_lit.c's curved GLUT and GLU solids translated
 * with --vertex-lighting (issue 27; GLUT window: run under Xvfb). GL's
 * facets in GL's lit colours, where before each solid became its exact
 * POV-Ray shape drawn unlit (0.827 within 8/255). */
#include "glut_lit.c"
