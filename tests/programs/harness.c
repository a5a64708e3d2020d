/* harness.c: OSMesa context, trace, frame end and PNG output for the image
 * test programs (see harness.h).
 *
 * The programs link libOSMesa before libGL, so the gl* calls made by the
 * program, by libraygl and by libGLU resolve to OSMesa's. If they did not,
 * GL would draw nowhere and the buffer would keep the sentinel pattern it is
 * filled with here: rgl_test_finish() checks for that.
 */
#include "harness.h"

#ifdef RGL_HARNESS_GLUT
#include <GL/freeglut.h>
#endif

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imagediff.h"
#include "raygl.h"

/* The pattern the buffer is filled with before GL draws (RGBA). No clear
 * colour a test uses has this alpha together with these colours. */
static const unsigned char sentinel[4] = {0xa5, 0x5a, 0xc3, 0x3c};

/* The largest image a test asks for; keeps --size from asking for gigabytes. */
#define MAX_SIDE 4096

static void usage(FILE *f, const char *name)
{
    fprintf(f, "usage: %s --trace OUT.raygl --png OUT.png [--size WxH]\n", name);
}

static int parse_size(const char *s, int *w, int *h)
{
    char *end;
    errno = 0;
    long lw = strtol(s, &end, 10);
    if (errno || end == s || *end != 'x')
        return -1;
    const char *hs = end + 1;
    long lh = strtol(hs, &end, 10);
    if (errno || end == hs || *end != '\0')
        return -1;
    if (lw < 1 || lh < 1 || lw > MAX_SIDE || lh > MAX_SIDE)
        return -1;
    *w = (int)lw;
    *h = (int)lh;
    return 0;
}

int rgl_test_init(rgl_test *t, int argc, char **argv)
{
    memset(t, 0, sizeof *t);
    t->name = argc > 0 ? argv[0] : "test";
    t->width = RGL_TEST_DEFAULT_WIDTH;
    t->height = RGL_TEST_DEFAULT_HEIGHT;

    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0) {
            usage(stdout, t->name);
            return 2;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "%s: %s: missing value\n", t->name, a);
            usage(stderr, t->name);
            return 2;
        }
        const char *v = argv[++i];
        if (strcmp(a, "--trace") == 0) {
            t->trace_path = v;
        } else if (strcmp(a, "--png") == 0) {
            t->png_path = v;
        } else if (strcmp(a, "--size") == 0) {
            if (parse_size(v, &t->width, &t->height) != 0) {
                fprintf(stderr, "%s: --size %s: expected WxH, each 1..%d\n", t->name, v,
                        MAX_SIDE);
                return 2;
            }
        } else {
            fprintf(stderr, "%s: unknown option %s\n", t->name, a);
            usage(stderr, t->name);
            return 2;
        }
    }
    if (!t->trace_path || !t->png_path) {
        usage(stderr, t->name);
        return 2;
    }

    size_t npix = (size_t)t->width * (size_t)t->height;
    t->pixels = malloc(npix * 4);
    if (!t->pixels) {
        fprintf(stderr, "%s: out of memory\n", t->name);
        return 1;
    }
    for (size_t i = 0; i < npix; i++)
        memcpy(t->pixels + 4 * i, sentinel, 4);

#ifdef RGL_HARNESS_GLUT
    /* A GLUT window (an X display: Xvfb in the tests): freeglut's shapes
     * need glutInit and a current window. The frame is drawn into the
     * back buffer and read back from there. */
    int gargc = 1;
    char *gargv[2] = {(char *)t->name, NULL};
    glutInit(&gargc, gargv);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowSize(t->width, t->height);
    if (glutCreateWindow("raygl image test") <= 0) {
        fprintf(stderr, "%s: glutCreateWindow failed\n", t->name);
        goto fail_pixels;
    }
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
    if (rayglRecordOpen(t->trace_path) != 0) {
        fprintf(stderr, "%s: %s: cannot open the trace: %s\n", t->name, t->trace_path,
                strerror(errno));
        goto fail_pixels;
    }
    return 0;
#else
    /* 16-bit accumulation channels: the accum_*.c programs use them; 8
     * stencil bits: shapes_stencil.c does. */
    t->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
    if (!t->ctx) {
        fprintf(stderr, "%s: OSMesaCreateContextExt failed\n", t->name);
        goto fail_pixels;
    }
    if (!OSMesaMakeCurrent(t->ctx, t->pixels, GL_UNSIGNED_BYTE, t->width, t->height)) {
        fprintf(stderr, "%s: OSMesaMakeCurrent failed\n", t->name);
        goto fail_ctx;
    }
    if (rayglRecordOpen(t->trace_path) != 0) {
        fprintf(stderr, "%s: %s: cannot open the trace: %s\n", t->name, t->trace_path,
                strerror(errno));
        goto fail_ctx;
    }
    return 0;

fail_ctx:
    OSMesaDestroyContext(t->ctx);
    t->ctx = NULL;
#endif
fail_pixels:
    free(t->pixels);
    t->pixels = NULL;
    return 1;
}

int rgl_test_finish(rgl_test *t)
{
    int rc = 1;
    rayglFrameEnd();
    glFinish();

    if (rayglRecordStatus() == RAYGL_FAILED) {
        const char *err = rayglRecordError();
        fprintf(stderr, "%s: recording failed: %s\n", t->name, err ? err : "(no message)");
        goto out;
    }

    size_t npix = (size_t)t->width * (size_t)t->height;
#ifdef RGL_HARNESS_GLUT
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, t->width, t->height, GL_RGBA, GL_UNSIGNED_BYTE, t->pixels);
#endif
    size_t untouched = 0, distinct = 0;
    for (size_t i = 0; i < npix; i++) {
        const unsigned char *p = t->pixels + 4 * i;
        if (memcmp(p, sentinel, 4) == 0)
            untouched++;
        if (memcmp(p, t->pixels, 3) != 0)
            distinct++;
    }
    if (untouched == npix) {
        fprintf(stderr,
                "%s: the OSMesa buffer was never drawn into: the gl* calls went to another "
                "GL (link libOSMesa before libGL)\n",
                t->name);
        goto out;
    }
    if (untouched != 0) {
        fprintf(stderr, "%s: %zu pixels were never drawn into (no glClear?)\n", t->name,
                untouched);
        goto out;
    }
    if (distinct == 0) {
        fprintf(stderr, "%s: the GL image is one flat colour: the scene drew nothing\n",
                t->name);
        goto out;
    }

    GLint y_up = 1;
#ifndef RGL_HARNESS_GLUT
    OSMesaGetIntegerv(OSMESA_Y_UP, &y_up);
#endif
    unsigned char *rgb = malloc(npix * 3);
    if (!rgb) {
        fprintf(stderr, "%s: out of memory\n", t->name);
        goto out;
    }
    for (int y = 0; y < t->height; y++) {
        int src_row = y_up ? t->height - 1 - y : y;
        const unsigned char *src = t->pixels + (size_t)src_row * (size_t)t->width * 4;
        unsigned char *dst = rgb + (size_t)y * (size_t)t->width * 3;
        for (int x = 0; x < t->width; x++) {
            dst[3 * x + 0] = src[4 * x + 0];
            dst[3 * x + 1] = src[4 * x + 1];
            dst[3 * x + 2] = src[4 * x + 2];
        }
    }
    if (img_write_png(t->png_path, rgb, t->width, t->height) != 0) {
        fprintf(stderr, "%s: %s: cannot write the PNG\n", t->name, t->png_path);
        free(rgb);
        goto out;
    }
    free(rgb);
    rc = 0;

out:
    rayglRecordClose();
    if (rc == 0 && rayglRecordStatus() == RAYGL_FAILED) {
        const char *err = rayglRecordError();
        fprintf(stderr, "%s: closing the trace failed: %s\n", t->name, err ? err : "");
        rc = 1;
    }
#ifndef RGL_HARNESS_GLUT
    OSMesaDestroyContext(t->ctx);
    t->ctx = NULL;
#endif
    free(t->pixels);
    t->pixels = NULL;
    return rc;
}
