/* imagediff.c: PNG input and output and the comparison figures shared by
 * imgcmp (tests/image) and raygl-compare (imagediff.h has the definitions).
 */
#include "imagediff.h"

#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int img_read_png(const char *path, img *out, char *why, size_t cap)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(why, cap, "%s", strerror(errno));
        return -1;
    }
    uint8_t sig[8];
    if (fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        snprintf(why, cap, "not a PNG file");
        fclose(f);
        return -1;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytepp rows = NULL;
    if (!info) {
        png_destroy_read_struct(&png, NULL, NULL);
        fclose(f);
        snprintf(why, cap, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        free(rows);
        free(out->rgb);
        out->rgb = NULL;
        fclose(f);
        snprintf(why, cap, "damaged PNG");
        return -1;
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    png_uint_32 w = png_get_image_width(png, info);
    png_uint_32 h = png_get_image_height(png, info);
    if (w == 0 || h == 0 || w > IMG_SIDE_MAX || h > IMG_SIDE_MAX) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        snprintf(why, cap, "unsupported size %ux%u", (unsigned)w, (unsigned)h);
        return -1;
    }
    png_fixed_point g;
    if (png_get_gAMA_fixed(png, info, &g)) {
        out->has_gama = true;
        out->gama = g / 100000.0;
    }
    int intent;
    if (png_get_sRGB(png, info, &intent))
        out->has_srgb = true;
    /* Values as stored: no png_set_gamma, so nothing is converted. */
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 3) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        snprintf(why, cap, "unexpected pixel layout");
        return -1;
    }
    out->w = (int)w;
    out->h = (int)h;
    out->rgb = malloc((size_t)w * h * 3);
    rows = malloc(sizeof *rows * h);
    if (!out->rgb || !rows)
        png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < h; y++)
        rows[y] = out->rgb + (size_t)y * w * 3;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    fclose(f);
    return 0;
}

int img_write_png(const char *path, const uint8_t *rgb, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        fclose(f);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_gAMA_fixed(png, info, 45455);
    png_write_info(png, info);
    for (int y = 0; y < h; y++)
        png_write_row(png, (png_const_bytep)(rgb + (size_t)y * (size_t)w * 3));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return fclose(f) == 0 ? 0 : -1;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

void img_border_mode(const img *a, int bg[3])
{
    size_t n = 0, cap = 2 * (size_t)a->w + 2 * (size_t)a->h;
    uint32_t *v = malloc(cap * sizeof *v);
    bg[0] = bg[1] = bg[2] = 0;
    if (!v)
        return;
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x < a->w; x++) {
            if (y != 0 && y != a->h - 1 && x != 0 && x != a->w - 1)
                continue;
            const uint8_t *p = a->rgb + ((size_t)y * a->w + x) * 3;
            v[n++] = (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
        }
    qsort(v, n, sizeof *v, cmp_u32);
    uint32_t best = v[0];
    size_t best_run = 0;
    for (size_t i = 0; i < n;) {
        size_t j = i;
        while (j < n && v[j] == v[i])
            j++;
        if (j - i > best_run) {
            best_run = j - i;
            best = v[i];
        }
        i = j;
    }
    free(v);
    bg[0] = (int)(best >> 16 & 255);
    bg[1] = (int)(best >> 8 & 255);
    bg[2] = (int)(best & 255);
}

static bool is_fg(const uint8_t *p, const int bg[3], int tol)
{
    for (int c = 0; c < 3; c++)
        if (abs((int)p[c] - bg[c]) > tol)
            return true;
    return false;
}

static int pixel_diff(const uint8_t *pa, const uint8_t *pb)
{
    int m = 0;
    for (int c = 0; c < 3; c++) {
        int d = abs((int)pa[c] - (int)pb[c]);
        if (d > m)
            m = d;
    }
    return m;
}

void img_compare(const img *a, const img *b, int tol, const int bg[3], img_stats *s)
{
    int w = a->w, h = a->h;
    memset(s, 0, sizeof *s);
    s->tol = tol;
    s->npix = (size_t)w * (size_t)h;
    memcpy(s->bg, bg, sizeof s->bg);
    s->bx0 = w;
    s->by0 = h;
    s->bx1 = s->by1 = -1;
    s->core_x = s->core_y = -1;
    uint64_t sum[3] = {0, 0, 0};
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = ((size_t)y * w + x) * 3;
            const uint8_t *pa = a->rgb + i, *pb = b->rgb + i;
            for (int c = 0; c < 3; c++)
                sum[c] += (uint64_t)abs((int)pa[c] - (int)pb[c]);
            int m = pixel_diff(pa, pb);
            if (m <= tol) {
                s->within++;
            } else {
                s->bx0 = x < s->bx0 ? x : s->bx0;
                s->bx1 = x > s->bx1 ? x : s->bx1;
                s->by0 = y < s->by0 ? y : s->by0;
                s->by1 = y > s->by1 ? y : s->by1;
            }
            if (m > s->maxd) {
                s->maxd = m;
                s->max_x = x;
                s->max_y = y;
            }
            bool fa = is_fg(pa, bg, tol), fb = is_fg(pb, bg, tol);
            s->fg_a += fa;
            s->fg_b += fb;
            s->fg_both += fa && fb;
        }
    /* Mismatch core: beyond T, and so are the 4 edge neighbours (the image
     * border is never core). A pixel-wide line of mismatch, even a diagonal
     * staircase, has no core; an area wrong and at least 3 pixels thick in
     * both directions has. */
    for (int y = 1; y + 1 < h; y++)
        for (int x = 1; x + 1 < w; x++) {
            static const int nx[5] = {0, -1, 1, 0, 0}, ny[5] = {0, 0, 0, -1, 1};
            bool all = true;
            for (int k = 0; k < 5 && all; k++) {
                size_t i = ((size_t)(y + ny[k]) * w + (size_t)(x + nx[k])) * 3;
                all = pixel_diff(a->rgb + i, b->rgb + i) > tol;
            }
            if (all) {
                if (s->core == 0) {
                    s->core_x = x;
                    s->core_y = y;
                }
                s->core++;
            }
        }
    for (int c = 0; c < 3; c++) {
        s->mean[c] = (double)sum[c] / (double)s->npix;
        s->mean_all += s->mean[c] / 3;
    }
    size_t fg_union = s->fg_a + s->fg_b - s->fg_both;
    s->silhouette = fg_union ? (double)s->fg_both / (double)fg_union : 1.0;
}

int img_side_by_side(const img *a, const img *b, int tol, img *out)
{
    const int gap = 4;
    int w = a->w, h = a->h, dw = 3 * w + 2 * gap;
    memset(out, 0, sizeof *out);
    uint8_t *d = malloc((size_t)dw * h * 3);
    if (!d)
        return -1;
    memset(d, 96, (size_t)dw * h * 3);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = ((size_t)y * w + x) * 3;
            uint8_t *row = d + (size_t)y * dw * 3;
            memcpy(row + (size_t)x * 3, a->rgb + i, 3);
            memcpy(row + (size_t)(w + gap + x) * 3, b->rgb + i, 3);
            uint8_t *q = row + (size_t)(2 * (w + gap) + x) * 3;
            for (int c = 0; c < 3; c++) {
                int dd = abs((int)a->rgb[i + c] - (int)b->rgb[i + c]);
                int v = dd <= tol ? dd * 16 : 64 + 8 * dd;
                q[c] = (uint8_t)(v > 255 ? 255 : v);
            }
        }
    out->w = dw;
    out->h = h;
    out->rgb = d;
    return 0;
}
