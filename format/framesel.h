/* framesel.h: frame lists, one grammar for every tool that selects frames:
 * raygl2pov --frames, raygl-compare --frames and RAYGL_FRAMES (the
 * recorder, set by raygl record --frames).
 *
 * A list is comma-separated items, each N, A-B (B >= A) or A- (to the
 * end), optionally followed by :STEP (1 or more): 0-100:10 is 0, 10, ...,
 * 100. Frames are numbered from 0. A trailing comma is allowed. No
 * allocation, no printing.
 */
#ifndef RGL_FRAMESEL_H
#define RGL_FRAMESEL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* One item; last is UINT64_MAX for A- (open). */
typedef struct rgl_frame_range {
    uint64_t first, last, step;
} rgl_frame_range;

typedef enum rgl_framesel_status {
    RGL_FRAMESEL_OK = 0,
    RGL_FRAMESEL_NUMBER,     /* expected a frame number at *at */
    RGL_FRAMESEL_BACKWARDS,  /* A-B with B < A (the item is in *r) */
    RGL_FRAMESEL_STEP,       /* expected a step of 1 or more at *at */
    RGL_FRAMESEL_UNEXPECTED, /* **at cannot follow an item */
} rgl_framesel_status;

/* Parses the item that starts at *p (not at the list's end: the caller
 * stops at '\0') into *r, and moves *p past it and the comma after it.
 * On an error, *p points where the list went wrong and *r holds what was
 * read so far. */
rgl_framesel_status rgl_framesel_next(const char **p, rgl_frame_range *r);

/* Reads the decimal number at s (digits only, no sign) into out and points
 * end past it; false when s starts with no digit or the number passes
 * UINT64_MAX. */
bool rgl_parse_u64(const char *s, const char **end, uint64_t *out);

/* Whether frame i is one of r's. */
static inline bool rgl_framesel_has(const rgl_frame_range *r, uint64_t i)
{
    return i >= r->first && i <= r->last && (i - r->first) % r->step == 0;
}

/* The last frame r selects, or UINT64_MAX when r is open. */
static inline uint64_t rgl_framesel_last(const rgl_frame_range *r)
{
    if (r->last == UINT64_MAX)
        return UINT64_MAX;
    return r->first + (r->last - r->first) / r->step * r->step;
}

#endif
