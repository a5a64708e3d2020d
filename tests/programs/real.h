/* real.h: the frame loop of the real_*.c and proj_*.c multi-frame programs.
 *
 * Programs in the style of classic GL teaching programs and screensavers
 * (issue 14's measurement): each draws `nframes` frames into an OSMesa
 * context (RGBA, 24-bit depth, 8-bit stencil, 16-bit accumulation) with the
 * drop-in header, and the loop ends every frame with rayglFrameEnd and
 * writes what GL shows as DIR/gl-NNNNN.png. A program drawing into the
 * front buffer calls glFlush itself, as a single-buffered program does.
 *
 *     prog --trace out.raygl --png-dir DIR [--size WxH]
 *
 * tests/image/run-frames-test.sh runs one; tools/measure-frames.sh all.
 */
#ifndef RGL_TEST_REAL_H
#define RGL_TEST_REAL_H

#include <GL/osmesa.h>

#include <GL/gl.h>
#include <GL/glu.h>

/* Draws frame `frame` (from 0) of a w x h window. */
typedef void (*real_draw_fn)(int frame, int w, int h);

/* Parses the command line, runs the frames, writes the PNGs. Returns the
 * exit status: 0, 1 on failure, 2 on bad usage (after saying why). */
int real_main(int argc, char **argv, int nframes, real_draw_fn draw);

#define RGL_REAL_MAIN(draw, nframes) \
    int main(int argc, char **argv) { return real_main(argc, argv, (nframes), (draw)); }

#endif
