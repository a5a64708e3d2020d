/* sdltext.c: SDL text in bounded buffers (sdltext.h). */
#include "sdltext.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

bool sdl_put(char *buf, size_t cap, size_t *len, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf + *len, cap - *len, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= cap - *len)
        return false;
    *len += (size_t)n;
    return true;
}

const char *sdl_num(char out[NUMFMT_F32_ROOM + 3], double v)
{
    out[0] = '(';
    size_t n = numfmt_f32(out + 1, isfinite(v) ? (float)v : 0.0f);
    out[1 + n] = ')';
    out[2 + n] = '\0';
    return out;
}
