/* lit_atten_linear.c: constant and linear attenuation: POV-Ray's
 * fade_power 1, exact. */
#define LIT_KC 0.5f
#define LIT_KL 0.35f
#define LIT_KQ 0.0f
#define LIT_GAIN 1.6f
#include "lit_atten.h"
