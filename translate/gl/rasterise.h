/* rasterise.h: which pixels GL lights for an aliased line or a point, as
 * Mesa's llvmpipe decides it (the GL of the image tests: OSMesa and GLX
 * under Xvfb), and shapes whose image covers exactly those pixel centres.
 *
 * Window coordinates are GL's: origin at the frame's lower left, pixel
 * (i, j) covering [i, i + 1) x [j, j + 1), its centre at (i + 0.5, j + 0.5).
 * The rules (docs/mapping.md section 7): a width-1 line lights one pixel
 * per column (x-major) or row (y-major), the ends by the diamond-exit rule
 * (GL 2.1 3.4.1); a width-w line w pixels across its minor axis in each of
 * those columns (3.4.2); a point of size s the s x s square of 3.3.1, s
 * rounded; a round point (GL_POINT_SMOOTH) the pixels inside its circle.
 * Mesa computes in float with vertices snapped to 1/256 pixel; so does
 * this file, in Mesa's own frame (y running down from the top), so that
 * ties fall as Mesa's do. Pure functions: no state, no allocation.
 */
#ifndef RGL_TR_RASTERISE_H
#define RGL_TR_RASTERISE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* The pixels lit at one index along the major axis: minor indices lo..hi
 * (none when lo > hi). */
typedef struct ras_run {
    int32_t lo, hi;
} ras_run;

/* A line's pixels: runs[k] at major index first + k (axis 0: the run is
 * a column's rows; 1: a row's columns). */
typedef struct ras_line {
    int axis;
    int32_t first;
    size_t count;
} ras_line;

/* The pixels of the aliased line from (x0, y0) to (x1, y1), width rounded
 * as Mesa rounds it (at least 1), in a frame of width x height pixels:
 * only major indices inside the frame are kept, at most max runs (a
 * frame's width or height is always enough). Returns false when the line
 * lights nothing there. The ends are the line's own: clip it to the
 * viewport first, as GL does. */
bool ras_line_pixels(double x0, double y0, double x1, double y1, double width, int32_t frame_w,
                     int32_t frame_h, ras_line *out, ras_run *runs, size_t max);

/* The window position of object point obj (GL's frame, origin at the
 * viewport's lower left) as Mesa computes it, for the rules above to see
 * the rounding Mesa's do: proj and mv as GL holds them (column-major, in
 * float), multiplied in float row by column, the vertex transformed the
 * same way without fused operations, divided by w, and put through the
 * viewport (w x h) as one fused multiply-add in Mesa's frame, whose y runs
 * down. False when w <= 0 or a result is not finite. */
bool ras_window(const float proj[16], const float mv[16], int32_t w, int32_t h,
                const float obj[3], double out[2]);

/* Clips the segment from p[0] to p[1] to the rectangle [r[0], r[2]] x
 * [r[1], r[3]] (the sides of GL's view volume in the window), as GL clips
 * before it rasterises; an end moved lands exactly on its side. *t0, *t1:
 * the part kept, as fractions of the way from p[0]. Returns false when
 * nothing is left. */
bool ras_clip_line(double p[2][2], const double r[4], double *t0, double *t1);

/* A strip of the window that covers exactly some runs of a line: along
 * the major axis from a to b (pixel edges), between the minor edges
 * slope * t + lo and slope * t + hi (t the major coordinate). Every pixel
 * centre lies at least RAS_MARGIN pixels inside or outside. */
typedef struct ras_piece {
    int32_t a, b;
    double lo, hi;
} ras_piece;

#define RAS_MARGIN (1.0 / 64)

/* Cuts a line's runs into such strips, each as long as the margin allows
 * (one for an axis-aligned or 45-degree line, one per few dozen pixels for
 * other slopes). slope: minor per major of the line in the window.
 * Returns the number written, at most max; 0 when max is too small. */
size_t ras_line_pieces(const ras_line *l, const ras_run *runs, double slope, ras_piece *out,
                       size_t max);

/* The square of an aliased point of the given size at (x, y): pixels
 * x0..x0+n-1, y0..y0+n-1. */
void ras_point_square(double x, double y, double size, int32_t frame_h, int32_t *x0, int32_t *y0,
                      int32_t *n);

/* A round point (GL_POINT_SMOOTH) of diameter d at (x, y): row y0 + k
 * lights columns rows[k].lo..rows[k].hi. Mesa draws it as a d x d square
 * whose fragments outside the inscribed circle it discards; d is
 * max(glPointSize, 2), or a size from glPointParameter as it is. Where a
 * pixel centre lies exactly on the circle, Mesa's float rounding decides
 * (measured: either way); here it is lit. Returns the number of rows (at
 * most max, 0 when too few or none). */
size_t ras_point_round(double x, double y, double d, int32_t frame_h, int32_t *y0,
                       ras_run *rows, size_t max);

#endif
