/* lit_atten_constant.c: constant attenuation only (1 / 1.6): exact. */
#define LIT_KC 1.6f
#define LIT_KL 0.0f
#define LIT_KQ 0.0f
#define LIT_GAIN 1.5f
#include "lit_atten.h"
