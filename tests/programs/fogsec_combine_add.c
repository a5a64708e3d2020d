/* fogsec_combine_add.c: unit 1 in COMBINE ADD(TEXTURE1, PREVIOUS), as
 * GL_ADD (mtex_add's picture). */
#define COMBINE_SETUP \
    combine(GL_ADD, GL_TEXTURE1, GL_SRC_COLOR, GL_PREVIOUS, GL_SRC_COLOR, GL_CONSTANT, GL_SRC_ALPHA)
#include "fogsec_combine.h"
