/* lit_atten_quadratic.c: constant and quadratic attenuation: POV-Ray's
 * fade_power 2, exact. */
#define LIT_KC 0.4f
#define LIT_KL 0.0f
#define LIT_KQ 0.12f
#define LIT_GAIN 1.7f
#include "lit_atten.h"
