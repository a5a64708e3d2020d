/* imagediff.h: comparing two RGB images, the GL one and the POV-Ray one.
 *
 * Shared by the image tests' imgcmp (tests/image/) and raygl-compare, so
 * both report the same figures, defined once here:
 *
 *   within T    fraction of pixels whose three channels all differ by <= T
 *               (in 8-bit levels: T=2 is 2/255)
 *   mean diff   mean absolute difference per channel and over all, in levels
 *   max diff    the largest channel difference and where it is
 *   silhouette  foreground = pixels that differ from the background colour
 *               by more than T in some channel; |A∩B| / |A∪B| of the two
 *               foreground masks (intersection over union; 1 when both are
 *               empty)
 *   core        pixels beyond T whose 4 edge neighbours are beyond T too: an
 *               area drawn wrong, as opposed to edges off by a pixel
 *
 * Images are 8-bit RGB, top row first. Nothing here prints or exits.
 */
#ifndef RGL_IMAGEDIFF_H
#define RGL_IMAGEDIFF_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define IMG_SIDE_MAX 16384

typedef struct img {
    int w, h;
    uint8_t *rgb; /* top row first, 3 bytes per pixel; free() it */
    bool has_gama;
    double gama; /* file gamma as stored in gAMA (0.45455 for display 2.2) */
    bool has_srgb;
} img;

typedef struct img_stats {
    int tol;
    size_t npix, within;
    double mean[3], mean_all;
    int maxd, max_x, max_y;
    int bg[3];
    size_t fg_a, fg_b, fg_both;
    double silhouette;
    int bx0, by0, bx1, by1; /* bounding box of pixels beyond T; bx1 < 0: none */
    size_t core;
    int core_x, core_y; /* first core pixel */
} img_stats;

/* Reads a PNG as 8-bit RGB, values as stored (no gamma conversion). Returns
 * 0, or -1 with a short reason in why (cap bytes). */
int img_read_png(const char *path, img *out, char *why, size_t cap);

/* Writes rgb (w x h, top row first) as an 8-bit RGB PNG tagged gAMA 1/2.2,
 * as POV-Ray tags its File_Gamma=2.2 output. Returns 0 or -1 (errno set
 * when the file could not be opened or closed). */
int img_write_png(const char *path, const uint8_t *rgb, int w, int h);

/* The most frequent colour on the image's border. */
void img_border_mode(const img *a, int bg[3]);

/* Every figure above for A (reference) and B (candidate) of equal size,
 * with tolerance tol and background bg. */
void img_compare(const img *a, const img *b, int tol, const int bg[3], img_stats *out);

/* A | B | amplified difference side by side, 4 grey pixels apart: a
 * difference within tol shows as d*16 (dark), one beyond as 64+8*d
 * (bright), per channel. Returns a malloc'd image of (3w + 8) x h in *out,
 * or -1 when out of memory. */
int img_side_by_side(const img *a, const img *b, int tol, img *out);

#endif
