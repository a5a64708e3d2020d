/* lit_atten_mixed.c: all three attenuation terms: POV-Ray's fade fits
 * GL's value and slope at the scene's centre (approximate). */
#define LIT_KC 0.3f
#define LIT_KL 0.2f
#define LIT_KQ 0.06f
#define LIT_GAIN 1.6f
#include "lit_atten.h"
