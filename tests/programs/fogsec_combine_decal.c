/* fogsec_combine_decal.c: unit 1 in COMBINE INTERPOLATE(TEXTURE, PREVIOUS,
 * the texture's alpha), as GL_DECAL of an RGBA texture (mtex_decal's
 * picture). */
#define COMBINE_SETUP \
    combine(GL_INTERPOLATE, GL_TEXTURE, GL_SRC_COLOR, GL_PREVIOUS, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA)
#include "fogsec_combine.h"
