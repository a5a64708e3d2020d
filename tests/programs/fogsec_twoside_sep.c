/* fogsec_twoside_sep.c: lit_two_sided.c's bowl and tube with
 * GL_LIGHT_MODEL_COLOR_CONTROL GL_SEPARATE_SPECULAR_COLOR (issue 14's
 * conformance list): untextured, GL adds the specular term after the
 * (absent) texture, which changes nothing but the clamping. */
#define LIT_TWO_SIDED_EXTRA glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR)
#include "lit_two_sided.c"
