/* naming.h: output file names (--name-pattern).
 *
 * A stem (the file name without .pov/.ini/.png) comes from the pattern, or
 * by default from rayglFrameBegin's name or "frame-NNNNN". Every stem is
 * reduced to [A-Za-z0-9._-], at most NAME_MAX_STEM bytes, never starting
 * with a dot, so it always names a plain file inside the output folder.
 */
#ifndef RGL_NAMING_H
#define RGL_NAMING_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define NAME_MAX_STEM 100

typedef struct name_vars {
    uint64_t index;         /* file order */
    uint32_t stream, number;
    const char *frame_name; /* rayglFrameBegin's, or NULL */
    const char *trace;      /* the trace's path */
} name_vars;

/* The stem of a frame into out (cap >= NAME_MAX_STEM + 1). pattern NULL:
 * the default naming. Never empty. */
void name_stem(const char *pattern, const name_vars *v, char *out, size_t cap);

/* Whether p starts with a placeholder a pattern may hold ("{index:5}"). */
bool name_is_placeholder(const char *p);

/* Reduces name (its last path component, without ".pov") to a plain file
 * stem; empty when nothing usable is left. */
void name_sanitize(const char *name, char *out, size_t cap);

#endif
