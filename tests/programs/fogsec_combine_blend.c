/* fogsec_combine_blend.c: unit 1 in COMBINE INTERPOLATE(CONSTANT,
 * PREVIOUS, TEXTURE), as GL_BLEND with GL_TEXTURE_ENV_COLOR (mtex_blend's
 * picture). */
#define COMBINE_SETUP \
    combine(GL_INTERPOLATE, GL_CONSTANT, GL_SRC_COLOR, GL_PREVIOUS, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_COLOR)
#include "fogsec_combine.h"
