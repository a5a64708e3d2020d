/* frame_front.h: what a single-buffered frame shows (frame_front.c). */
#ifndef RGL_FRAME_FRONT_H
#define RGL_FRAME_FRONT_H

#include <stdbool.h>

#include "format.h"

/* How many earlier frames a single-buffered frame may replay. Bounds the
 * work per frame against a trace of a million flushes with no clear; the
 * frame budget (interp_bounds.c) bounds what they draw. */
#define FRONT_MAX_FRAMES 64

/* What a frame's commands say about the front buffer. */
typedef struct front_scan {
    bool flushed;      /* the last GL call is glFlush or glFinish */
    bool clears_color; /* a glClear with GL_COLOR_BUFFER_BIT, while the draw
                          buffer may be the front one */
} front_scan;

/* Scans fi's commands (a damaged tail ends the scan). Recorder records and
 * rayglFrameEnd do not count as the last call. */
front_scan front_scan_frame(const rgl_frame_info *fi);

#endif
