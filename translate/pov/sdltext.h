/* sdltext.h: small pieces of SDL text built in a caller's bounded buffer,
 * shared by the writers that compose function pigments (povwrite_mipmap.c,
 * povwrite_multitex.c, povwrite_cube.c). */
#ifndef RGL_SDLTEXT_H
#define RGL_SDLTEXT_H

#include <stdbool.h>
#include <stddef.h>

#include "numfmt.h"

/* Appends the formatted text to buf (at *len); false, *len unchanged, once
 * it does not fit in cap. No float conversions: numbers go through
 * sdl_num. */
bool sdl_put(char *buf, size_t cap, size_t *len, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* v as SDL text in parentheses (a negative one may follow an operator);
 * not finite: "(0)". Returns out. */
const char *sdl_num(char out[NUMFMT_F32_ROOM + 3], double v);

#endif
