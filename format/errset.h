/* errset.h: filling an rgl_error, for the format/ sources only. */
#ifndef RGL_ERRSET_H
#define RGL_ERRSET_H

#include <stdint.h>

#include "format.h"

/* Sets *err (when not NULL) to status at offset, for opcode (0: none),
 * with a printf-style detail; returns status. */
#if defined(__GNUC__)
__attribute__((format(printf, 5, 6)))
#endif
rgl_status rgl_set_error(rgl_error *err, rgl_status status, uint64_t offset, uint32_t opcode,
                         const char *fmt, ...);

#endif
