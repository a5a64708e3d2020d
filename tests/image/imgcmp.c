/* imgcmp.c: compares two PNG images pixel by pixel for the image tests.
 *
 *     imgcmp [options] A.png B.png
 *
 * A is the reference (the OpenGL frame), B the candidate (the POV-Ray
 * frame). The images must have the same size. imgcmp always prints every
 * figure, then PASS or FAIL with the reasons; exit status 0 when every
 * threshold given holds, 1 when one does not, 2 on bad usage or an image
 * that cannot be read.
 *
 * Figures:
 *   within T    fraction of pixels whose three channels all differ by <= T
 *               (in 8-bit levels, so T=2 is 2/255)
 *   mean diff   mean absolute difference per channel and over all channels,
 *               in levels (0.5 means 0.5/255)
 *   max diff    the largest channel difference, where it is, both pixels
 *   silhouette  foreground = pixels that differ from the background colour
 *               by more than T in some channel; agreement |A∩B| / |A∪B| of
 *               the two foreground masks (1 when both are empty)
 *   gamma       the gAMA / sRGB tags of both files (values are compared as
 *               stored: no gamma conversion is applied when reading)
 *   mismatch    bounding box of the pixels beyond T
 *   core        pixels beyond T whose 4 edge neighbours are all beyond T
 *               too: an area drawn wrong (a wrong colour, a missing or extra
 *               primitive, 3 pixels thick or more), as opposed to edges
 *               that differ by a pixel, which leave thin lines of mismatch
 *               and no core
 *
 * Options:
 *   --tol T              per-channel tolerance in levels (default 2)
 *   --min-match F        fail when the fraction within T is below F (default 0.99)
 *   --max-mean M         fail when the overall mean difference exceeds M levels
 *   --min-silhouette S   fail when the silhouette agreement is below S
 *   --max-core N         fail when more than N pixels are mismatch core
 *   --background R,G,B   background colour in levels (default: the most
 *                        frequent colour on A's border)
 *   --check-gamma        fail unless B is tagged for display gamma 2.2
 *                        (gAMA 0.45455 within 1%, or sRGB), as A is
 *   --diff OUT.png       write A | B | amplified difference side by side:
 *                        a difference within T shows as d*16 (dark), one
 *                        beyond T as 64+8*d (bright), per channel
 *   --pair OUT.png       write A | B side by side (the docs' pictures,
 *                        tools/make-doc-images.sh)
 *   --at X,Y             print both pixels at X,Y (0-based, top row 0);
 *                        may be repeated
 *   --shadow X0,Y0,X1,Y1,X2,Y2,X3,Y3,F
 *                        a shadow that B shows and A does not: the mean
 *                        brightness (r+g+b)/3 of B in the box X0..X1,
 *                        Y0..Y1 (inclusive) is at most F times that of B
 *                        in the box X2..X3, Y2..Y3, while A's ratio is at
 *                        least 0.95 (the boxes alike in A); prints the four
 *                        means and both ratios
 */
#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_PROBES 64

typedef struct image {
    int w, h;
    uint8_t *rgb; /* top row first, 3 bytes per pixel */
    bool has_gama;
    double gama; /* file gamma as stored in gAMA (0.45455 for display 2.2) */
    bool has_srgb;
} image;

typedef struct options {
    int tol;
    double min_match;
    double max_mean; /* < 0: not checked */
    double min_sil;  /* < 0: not checked */
    long max_core;   /* < 0: not checked */
    bool have_bg;
    int bg[3];
    bool check_gamma;
    const char *diff_path;
    const char *pair_path;
    int nprobes;
    int probe[MAX_PROBES][2];
    bool have_shadow;
    int shadow_box[8];
    double shadow_max;
    const char *a_path, *b_path;
} options;

/* Mean of (r + g + b) / 3 over the box x0..x1, y0..y1 (clipped to the
 * image); -1 when the box misses it. */
static double box_mean(const image *img, const int *box)
{
    double sum = 0;
    size_t n = 0;
    for (int y = box[1]; y <= box[3] && y < img->h; y++)
        for (int x = box[0]; x <= box[2] && x < img->w; x++) {
            const uint8_t *p = img->rgb + ((size_t)y * img->w + x) * 3;
            sum += (p[0] + p[1] + p[2]) / 3.0;
            n++;
        }
    return n ? sum / (double)n : -1;
}

static void usage(FILE *f)
{
    fputs("usage: imgcmp [--tol T] [--min-match F] [--max-mean M] [--min-silhouette S]\n"
          "              [--max-core N] [--background R,G,B] [--check-gamma] [--diff OUT.png]\n"
          "              [--pair OUT.png] [--at X,Y]... [--shadow X0,Y0,X1,Y1,X2,Y2,X3,Y3,F] A.png B.png\n",
          f);
}

static int read_png(const char *path, image *img)
{
    memset(img, 0, sizeof *img);
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "imgcmp: %s: %s\n", path, strerror(errno));
        return -1;
    }
    uint8_t sig[8];
    if (fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        fprintf(stderr, "imgcmp: %s: not a PNG file\n", path);
        fclose(f);
        return -1;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytepp rows = NULL;
    if (!info) {
        png_destroy_read_struct(&png, NULL, NULL);
        fclose(f);
        fprintf(stderr, "imgcmp: %s: out of memory\n", path);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        free(rows);
        free(img->rgb);
        img->rgb = NULL;
        fclose(f);
        fprintf(stderr, "imgcmp: %s: damaged PNG\n", path);
        return -1;
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);

    png_uint_32 w = png_get_image_width(png, info);
    png_uint_32 h = png_get_image_height(png, info);
    if (w == 0 || h == 0 || w > 16384 || h > 16384) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        fprintf(stderr, "imgcmp: %s: unsupported size %ux%u\n", path, (unsigned)w, (unsigned)h);
        return -1;
    }
    png_fixed_point g;
    if (png_get_gAMA_fixed(png, info, &g)) {
        img->has_gama = true;
        img->gama = g / 100000.0;
    }
    int intent;
    if (png_get_sRGB(png, info, &intent))
        img->has_srgb = true;

    /* Values as stored: no png_set_gamma, so nothing is converted. */
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 3) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        fprintf(stderr, "imgcmp: %s: unexpected pixel layout\n", path);
        return -1;
    }
    img->w = (int)w;
    img->h = (int)h;
    img->rgb = malloc((size_t)w * h * 3);
    rows = malloc(sizeof *rows * h);
    if (!img->rgb || !rows)
        png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < h; y++)
        rows[y] = img->rgb + (size_t)y * w * 3;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    fclose(f);
    return 0;
}

static int write_png(const char *path, const uint8_t *rgb, int w, int h)
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

/* The most frequent colour on the image border. */
static void border_mode(const image *img, int bg[3])
{
    size_t n = 0, cap = 2 * (size_t)img->w + 2 * (size_t)img->h;
    uint32_t *v = malloc(cap * sizeof *v);
    if (!v) {
        bg[0] = bg[1] = bg[2] = 0;
        return;
    }
    for (int y = 0; y < img->h; y++)
        for (int x = 0; x < img->w; x++) {
            if (y != 0 && y != img->h - 1 && x != 0 && x != img->w - 1)
                continue;
            const uint8_t *p = img->rgb + ((size_t)y * img->w + x) * 3;
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

static int parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end != '\0' || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

static int parse_ints(const char *s, int *out, int n, int lo, int hi)
{
    for (int i = 0; i < n; i++) {
        char *end;
        errno = 0;
        long v = strtol(s, &end, 10);
        if (errno || end == s || v < lo || v > hi)
            return -1;
        out[i] = (int)v;
        if (i + 1 < n) {
            if (*end != ',')
                return -1;
            s = end + 1;
        } else if (*end != '\0') {
            return -1;
        }
    }
    return 0;
}

static int parse_args(int argc, char **argv, options *o)
{
    memset(o, 0, sizeof *o);
    o->tol = 2;
    o->min_match = 0.99;
    o->max_mean = -1;
    o->min_sil = -1;
    o->max_core = -1;
    int npos = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0) {
            usage(stdout);
            exit(0);
        }
        if (strcmp(a, "--check-gamma") == 0) {
            o->check_gamma = true;
            continue;
        }
        if (a[0] == '-' && a[1] == '-') {
            if (i + 1 >= argc) {
                fprintf(stderr, "imgcmp: %s: missing value\n", a);
                return -1;
            }
            const char *v = argv[++i];
            int bad = 0;
            if (strcmp(a, "--tol") == 0) {
                bad = parse_ints(v, &o->tol, 1, 0, 255);
            } else if (strcmp(a, "--min-match") == 0) {
                bad = parse_double(v, &o->min_match);
            } else if (strcmp(a, "--max-mean") == 0) {
                bad = parse_double(v, &o->max_mean);
            } else if (strcmp(a, "--min-silhouette") == 0) {
                bad = parse_double(v, &o->min_sil);
            } else if (strcmp(a, "--max-core") == 0) {
                int n = 0;
                bad = parse_ints(v, &n, 1, 0, 1 << 30);
                o->max_core = n;
            } else if (strcmp(a, "--background") == 0) {
                bad = parse_ints(v, o->bg, 3, 0, 255);
                o->have_bg = true;
            } else if (strcmp(a, "--shadow") == 0) {
                /* eight integers, then the ratio after the last comma */
                const char *comma = strrchr(v, ',');
                char ints[128];
                size_t n = comma ? (size_t)(comma - v) : 0;
                bad = !comma || n >= sizeof ints;
                if (!bad) {
                    memcpy(ints, v, n);
                    ints[n] = '\0';
                    bad = parse_ints(ints, o->shadow_box, 8, 0, 1 << 20) ||
                          parse_double(comma + 1, &o->shadow_max);
                }
                bad = bad || o->shadow_box[0] > o->shadow_box[2] ||
                      o->shadow_box[1] > o->shadow_box[3] || o->shadow_box[4] > o->shadow_box[6] ||
                      o->shadow_box[5] > o->shadow_box[7];
                o->have_shadow = true;
            } else if (strcmp(a, "--diff") == 0) {
                o->diff_path = v;
            } else if (strcmp(a, "--pair") == 0) {
                o->pair_path = v;
            } else if (strcmp(a, "--at") == 0) {
                if (o->nprobes == MAX_PROBES) {
                    fprintf(stderr, "imgcmp: at most %d --at\n", MAX_PROBES);
                    return -1;
                }
                bad = parse_ints(v, o->probe[o->nprobes++], 2, 0, 1 << 20);
            } else {
                fprintf(stderr, "imgcmp: unknown option %s\n", a);
                return -1;
            }
            if (bad) {
                fprintf(stderr, "imgcmp: %s %s: bad value\n", a, v);
                return -1;
            }
            continue;
        }
        if (npos == 0)
            o->a_path = a;
        else if (npos == 1)
            o->b_path = a;
        npos++;
    }
    if (npos != 2) {
        fprintf(stderr, "imgcmp: expected two images\n");
        return -1;
    }
    return 0;
}

static void print_gamma(const char *label, const image *img)
{
    printf("%s", label);
    if (img->has_srgb)
        printf(" sRGB");
    if (img->has_gama)
        printf(" gAMA %.5f (display gamma %.3f)", img->gama, 1.0 / img->gama);
    if (!img->has_srgb && !img->has_gama)
        printf(" untagged");
}

static bool display_gamma_22(const image *img)
{
    if (img->has_gama)
        return fabs(img->gama - 1.0 / 2.2) <= 0.01 / 2.2;
    return img->has_srgb;
}

int main(int argc, char **argv)
{
    options o;
    if (parse_args(argc, argv, &o) != 0) {
        usage(stderr);
        return 2;
    }
    image a, b;
    if (read_png(o.a_path, &a) != 0)
        return 2;
    if (read_png(o.b_path, &b) != 0) {
        free(a.rgb);
        return 2;
    }
    printf("imgcmp: A %s (%dx%d)\n", o.a_path, a.w, a.h);
    printf("imgcmp: B %s (%dx%d)\n", o.b_path, b.w, b.h);
    if (a.w != b.w || a.h != b.h) {
        printf("size: A %dx%d, B %dx%d differ\nFAIL: image sizes differ\n", a.w, a.h, b.w, b.h);
        free(a.rgb);
        free(b.rgb);
        return 1;
    }

    int w = a.w, h = a.h;
    size_t npix = (size_t)w * h;
    if (!o.have_bg)
        border_mode(&a, o.bg);

    size_t within = 0, fg_a = 0, fg_b = 0, fg_both = 0;
    uint64_t sum[3] = {0, 0, 0};
    int maxd = 0, max_x = 0, max_y = 0;
    int bx0 = w, by0 = h, bx1 = -1, by1 = -1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = ((size_t)y * w + x) * 3;
            const uint8_t *pa = a.rgb + i, *pb = b.rgb + i;
            int m = 0;
            for (int c = 0; c < 3; c++) {
                int d = abs((int)pa[c] - (int)pb[c]);
                sum[c] += (uint64_t)d;
                if (d > m)
                    m = d;
            }
            if (m <= o.tol) {
                within++;
            } else {
                if (x < bx0)
                    bx0 = x;
                if (x > bx1)
                    bx1 = x;
                if (y < by0)
                    by0 = y;
                if (y > by1)
                    by1 = y;
            }
            if (m > maxd) {
                maxd = m;
                max_x = x;
                max_y = y;
            }
            bool fa = is_fg(pa, o.bg, o.tol), fb = is_fg(pb, o.bg, o.tol);
            fg_a += fa;
            fg_b += fb;
            fg_both += fa && fb;
        }

    /* Mismatch core: beyond T, and so are the 4 edge neighbours (the image
     * border is never core). A pixel-wide line of mismatch, even a diagonal
     * staircase, has no core; an area wrong and at least 3 pixels thick in
     * both directions has. */
    size_t core = 0;
    int core_x = -1, core_y = -1;
    for (int y = 1; y + 1 < h; y++)
        for (int x = 1; x + 1 < w; x++) {
            static const int nx[5] = {0, -1, 1, 0, 0}, ny[5] = {0, 0, 0, -1, 1};
            bool all = true;
            for (int k = 0; k < 5 && all; k++) {
                size_t i = ((size_t)(y + ny[k]) * w + (size_t)(x + nx[k])) * 3;
                int m = 0;
                for (int c = 0; c < 3; c++) {
                    int d = abs((int)a.rgb[i + c] - (int)b.rgb[i + c]);
                    if (d > m)
                        m = d;
                }
                all = m > o.tol;
            }
            if (all) {
                if (core == 0) {
                    core_x = x;
                    core_y = y;
                }
                core++;
            }
        }

    double frac = (double)within / (double)npix;
    double mean[3], mean_all = 0;
    for (int c = 0; c < 3; c++) {
        mean[c] = (double)sum[c] / (double)npix;
        mean_all += mean[c] / 3;
    }
    size_t fg_union = fg_a + fg_b - fg_both;
    double sil = fg_union ? (double)fg_both / (double)fg_union : 1.0;

    printf("within %d/255: %.5f (%zu of %zu pixels; %zu beyond)\n", o.tol, frac, within, npix,
           npix - within);
    printf("mean diff: %.4f/255 (r %.4f, g %.4f, b %.4f)\n", mean_all, mean[0], mean[1],
           mean[2]);
    {
        const uint8_t *pa = a.rgb + ((size_t)max_y * w + max_x) * 3;
        const uint8_t *pb = b.rgb + ((size_t)max_y * w + max_x) * 3;
        printf("max diff: %d/255 at (%d,%d): A (%d,%d,%d) B (%d,%d,%d)\n", maxd, max_x, max_y,
               pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]);
    }
    printf("silhouette: %.5f (background %d,%d,%d; A %zu, B %zu, both %zu, A only %zu, B only "
           "%zu)\n",
           sil, o.bg[0], o.bg[1], o.bg[2], fg_a, fg_b, fg_both, fg_a - fg_both, fg_b - fg_both);
    print_gamma("gamma: A", &a);
    print_gamma(", B", &b);
    printf("\n");
    if (bx1 >= 0)
        printf("mismatch: x %d..%d, y %d..%d\n", bx0, bx1, by0, by1);
    else
        printf("mismatch: none\n");
    if (core)
        printf("core: %zu pixels (first at (%d,%d))\n", core, core_x, core_y);
    else
        printf("core: 0 pixels\n");
    for (int k = 0; k < o.nprobes; k++) {
        int x = o.probe[k][0], y = o.probe[k][1];
        if (x >= w || y >= h) {
            printf("at (%d,%d): outside the image\n", x, y);
            continue;
        }
        const uint8_t *pa = a.rgb + ((size_t)y * w + x) * 3;
        const uint8_t *pb = b.rgb + ((size_t)y * w + x) * 3;
        printf("at (%d,%d): A (%d,%d,%d) B (%d,%d,%d)\n", x, y, pa[0], pa[1], pa[2], pb[0],
               pb[1], pb[2]);
    }

    double shadow_ratio[2] = {0, 0};
    if (o.have_shadow) {
        const image *im[2] = {&a, &b};
        for (int k = 0; k < 2; k++) {
            double in = box_mean(im[k], o.shadow_box), out = box_mean(im[k], o.shadow_box + 4);
            shadow_ratio[k] = in >= 0 && out > 0 ? in / out : -1;
            printf("shadow: %s box (%d,%d)-(%d,%d) mean %.2f, box (%d,%d)-(%d,%d) mean %.2f, "
                   "ratio %.4f\n",
                   k ? "B" : "A", o.shadow_box[0], o.shadow_box[1], o.shadow_box[2],
                   o.shadow_box[3], in, o.shadow_box[4], o.shadow_box[5], o.shadow_box[6],
                   o.shadow_box[7], out, shadow_ratio[k]);
        }
    }

    int rc = 0;
    if (o.diff_path) {
        const int gap = 4;
        int dw = 3 * w + 2 * gap;
        uint8_t *d = malloc((size_t)dw * h * 3);
        if (!d) {
            fprintf(stderr, "imgcmp: out of memory\n");
            rc = 2;
        } else {
            memset(d, 96, (size_t)dw * h * 3);
            for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++) {
                    size_t i = ((size_t)y * w + x) * 3;
                    uint8_t *row = d + (size_t)y * dw * 3;
                    memcpy(row + (size_t)x * 3, a.rgb + i, 3);
                    memcpy(row + (size_t)(w + gap + x) * 3, b.rgb + i, 3);
                    uint8_t *q = row + (size_t)(2 * (w + gap) + x) * 3;
                    for (int c = 0; c < 3; c++) {
                        int dd = abs((int)a.rgb[i + c] - (int)b.rgb[i + c]);
                        int v = dd <= o.tol ? dd * 16 : 64 + 8 * dd;
                        q[c] = (uint8_t)(v > 255 ? 255 : v);
                    }
                }
            if (write_png(o.diff_path, d, dw, h) != 0) {
                fprintf(stderr, "imgcmp: %s: cannot write\n", o.diff_path);
                rc = 2;
            } else {
                printf("diff image: %s\n", o.diff_path);
            }
            free(d);
        }
    }

    if (o.pair_path && rc == 0) {
        const int gap = 4;
        int pw = 2 * w + gap;
        uint8_t *d = malloc((size_t)pw * h * 3);
        if (!d) {
            fprintf(stderr, "imgcmp: out of memory\n");
            rc = 2;
        } else {
            memset(d, 255, (size_t)pw * h * 3);
            for (int y = 0; y < h; y++) {
                uint8_t *row = d + (size_t)y * pw * 3;
                memcpy(row, a.rgb + (size_t)y * w * 3, (size_t)w * 3);
                memcpy(row + (size_t)(w + gap) * 3, b.rgb + (size_t)y * w * 3, (size_t)w * 3);
            }
            if (write_png(o.pair_path, d, pw, h) != 0) {
                fprintf(stderr, "imgcmp: %s: cannot write\n", o.pair_path);
                rc = 2;
            } else {
                printf("pair image: %s\n", o.pair_path);
            }
            free(d);
        }
    }

    int fails = 0;
    char why[512] = "";
    size_t wl = 0;
#define FAILED(...)                                                                      \
    do {                                                                                 \
        fails++;                                                                         \
        if (wl < sizeof why)                                                             \
            wl += (size_t)snprintf(why + wl, sizeof why - wl, "%s", fails > 1 ? "; " : ""); \
        if (wl < sizeof why)                                                             \
            wl += (size_t)snprintf(why + wl, sizeof why - wl, __VA_ARGS__);              \
    } while (0)
    if (frac < o.min_match)
        FAILED("within %d/255 %.5f < %.5f", o.tol, frac, o.min_match);
    if (o.max_mean >= 0 && mean_all > o.max_mean)
        FAILED("mean diff %.4f > %.4f", mean_all, o.max_mean);
    if (o.min_sil >= 0 && sil < o.min_sil)
        FAILED("silhouette %.5f < %.5f", sil, o.min_sil);
    if (o.max_core >= 0 && core > (size_t)o.max_core)
        FAILED("mismatch core %zu > %ld pixels", core, o.max_core);
    if (o.check_gamma && !display_gamma_22(&b))
        FAILED("B is not tagged for display gamma 2.2");
    if (o.have_shadow && !(shadow_ratio[1] >= 0 && shadow_ratio[1] <= o.shadow_max))
        FAILED("no shadow in B: ratio %.4f > %.4f", shadow_ratio[1], o.shadow_max);
    if (o.have_shadow && !(shadow_ratio[0] >= 0.95))
        FAILED("A is darker in the shadow box too: ratio %.4f < 0.95", shadow_ratio[0]);
#undef FAILED
    if (fails) {
        printf("FAIL: %s\n", why);
        rc = rc ? rc : 1;
    } else {
        printf("PASS (within %d/255 >= %.5f", o.tol, o.min_match);
        if (o.max_mean >= 0)
            printf(", mean <= %.4f", o.max_mean);
        if (o.min_sil >= 0)
            printf(", silhouette >= %.5f", o.min_sil);
        if (o.max_core >= 0)
            printf(", core <= %ld", o.max_core);
        if (o.have_shadow)
            printf(", shadow ratio <= %.4f", o.shadow_max);
        printf(")\n");
    }
    free(a.rgb);
    free(b.rgb);
    return rc;
}
