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
 *   --expect X0,Y0,X1,Y1,R,G,B,T
 *                        B's mean colour in the box X0..X1, Y0..Y1 is
 *                        (R, G, B) within T levels per channel (a shadow
 *                        that is dark and not tinted); prints the means
 */
#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imagediff.h"

#define MAX_PROBES 64

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
    bool have_expect;
    int expect[8];
    const char *a_path, *b_path;
} options;

/* Mean of (r + g + b) / 3 over the box x0..x1, y0..y1 (clipped to the
 * image); -1 when the box misses it. */
static double box_mean(const img *img, const int *box)
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
          "              [--pair OUT.png] [--at X,Y]... [--shadow X0,Y0,X1,Y1,X2,Y2,X3,Y3,F]\n"
          "              [--expect X0,Y0,X1,Y1,R,G,B,T] A.png B.png\n",
          f);
}

static int read_png(const char *path, img *out)
{
    char why[128];
    if (img_read_png(path, out, why, sizeof why) != 0) {
        fprintf(stderr, "imgcmp: %s: %s\n", path, why);
        return -1;
    }
    return 0;
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
            } else if (strcmp(a, "--expect") == 0) {
                bad = parse_ints(v, o->expect, 8, 0, 1 << 20) || o->expect[0] > o->expect[2] ||
                      o->expect[1] > o->expect[3];
                o->have_expect = true;
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

static void print_gamma(const char *label, const img *img)
{
    printf("%s", label);
    if (img->has_srgb)
        printf(" sRGB");
    if (img->has_gama)
        printf(" gAMA %.5f (display gamma %.3f)", img->gama, 1.0 / img->gama);
    if (!img->has_srgb && !img->has_gama)
        printf(" untagged");
}

static bool display_gamma_22(const img *img)
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
    img a, b;
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
    if (!o.have_bg)
        img_border_mode(&a, o.bg);
    img_stats st;
    img_compare(&a, &b, o.tol, o.bg, &st);
    size_t npix = st.npix, within = st.within, core = st.core;
    size_t fg_a = st.fg_a, fg_b = st.fg_b, fg_both = st.fg_both;
    double frac = (double)within / (double)npix, mean_all = st.mean_all, sil = st.silhouette;
    const double *mean = st.mean;

    printf("within %d/255: %.5f (%zu of %zu pixels; %zu beyond)\n", o.tol, frac, within, npix,
           npix - within);
    printf("mean diff: %.4f/255 (r %.4f, g %.4f, b %.4f)\n", mean_all, mean[0], mean[1],
           mean[2]);
    {
        const uint8_t *pa = a.rgb + ((size_t)st.max_y * w + st.max_x) * 3;
        const uint8_t *pb = b.rgb + ((size_t)st.max_y * w + st.max_x) * 3;
        printf("max diff: %d/255 at (%d,%d): A (%d,%d,%d) B (%d,%d,%d)\n", st.maxd, st.max_x,
               st.max_y, pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]);
    }
    printf("silhouette: %.5f (background %d,%d,%d; A %zu, B %zu, both %zu, A only %zu, B only "
           "%zu)\n",
           sil, o.bg[0], o.bg[1], o.bg[2], fg_a, fg_b, fg_both, fg_a - fg_both, fg_b - fg_both);
    print_gamma("gamma: A", &a);
    print_gamma(", B", &b);
    printf("\n");
    if (st.bx1 >= 0)
        printf("mismatch: x %d..%d, y %d..%d\n", st.bx0, st.bx1, st.by0, st.by1);
    else
        printf("mismatch: none\n");
    if (core)
        printf("core: %zu pixels (first at (%d,%d))\n", core, st.core_x, st.core_y);
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
        const img *im[2] = {&a, &b};
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

    bool expect_ok = true;
    if (o.have_expect) {
        double m[3] = {0, 0, 0};
        size_t n = 0;
        for (int y = o.expect[1]; y <= o.expect[3] && y < b.h; y++)
            for (int x = o.expect[0]; x <= o.expect[2] && x < b.w; x++, n++)
                for (int k = 0; k < 3; k++)
                    m[k] += b.rgb[((size_t)y * b.w + x) * 3 + k];
        for (int k = 0; k < 3; k++) {
            m[k] = n ? m[k] / (double)n : -1e9;
            expect_ok = expect_ok && fabs(m[k] - o.expect[4 + k]) <= o.expect[7];
        }
        printf("expect: B box (%d,%d)-(%d,%d) mean (%.2f,%.2f,%.2f), expected (%d,%d,%d) +- %d\n",
               o.expect[0], o.expect[1], o.expect[2], o.expect[3], m[0], m[1], m[2], o.expect[4],
               o.expect[5], o.expect[6], o.expect[7]);
    }

    int rc = 0;
    if (o.diff_path) {
        img d;
        if (img_side_by_side(&a, &b, o.tol, &d) != 0) {
            fprintf(stderr, "imgcmp: out of memory\n");
            rc = 2;
        } else {
            if (img_write_png(o.diff_path, d.rgb, d.w, d.h) != 0) {
                fprintf(stderr, "imgcmp: %s: cannot write\n", o.diff_path);
                rc = 2;
            } else {
                printf("diff image: %s\n", o.diff_path);
            }
            free(d.rgb);
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
    if (!expect_ok)
        FAILED("B's box is not the expected colour");
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
