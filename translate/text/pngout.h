/* pngout.h: texture images as PNG files in the output folder (issue 5). */
#ifndef RGL_PNGOUT_H
#define RGL_PNGOUT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Images of at most this many bytes (w x h x 3 or 4) are deflated (level
 * 6 up to a quarter of it, else 1); larger ones are stored. */
#define PNGOUT_COMPRESS_MAX (1u << 20)

/* Writes w x h RGBA texels (bottom row first, as GL holds them) as
 * DIR/NAME, top row first, RGB or (alpha) RGBA, 8 bits, tagged gAMA
 * 1/2.2 as the frames are. NAME is a bare file name. The file is written
 * under a temporary name and renamed into place; an existing DIR/NAME is
 * kept (names are content hashes: it holds the same image). Returns 0, or
 * -1 with errno set. */
int pngout_place(const char *dir, const char *name, const uint8_t *rgba, int w, int h,
                 bool alpha);

/* The same PNG bytes in memory (a .glb embeds its images): *out is
 * malloc'd (free() it), *n its size. Returns 0, or -1 with errno set. */
int pngout_encode(const uint8_t *rgba, int w, int h, bool alpha, uint8_t **out, size_t *n);

#endif
