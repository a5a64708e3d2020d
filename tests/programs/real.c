/* real.c: the frame loop of the multi-frame programs (real.h). */
#include "real.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imagediff.h"
#include "raygl.h"

#define MAX_SIDE 4096

static int usage(const char *name)
{
    fprintf(stderr, "usage: %s --trace OUT.raygl --png-dir DIR [--size WxH]\n", name);
    return 2;
}

/* Writes the OSMesa buffer (bottom row first) as DIR/gl-NNNNN.png. */
static int write_frame(const char *dir, int frame, const unsigned char *px, int w, int h)
{
    unsigned char *rgb = malloc((size_t)w * (size_t)h * 3);
    if (!rgb)
        return -1;
    for (int y = 0; y < h; y++) {
        const unsigned char *src = px + (size_t)(h - 1 - y) * (size_t)w * 4;
        unsigned char *dst = rgb + (size_t)y * (size_t)w * 3;
        for (int x = 0; x < w; x++)
            memcpy(dst + 3 * x, src + 4 * x, 3);
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/gl-%05d.png", dir, frame);
    int rc = img_write_png(path, rgb, w, h);
    free(rgb);
    return rc;
}

int real_main(int argc, char **argv, int nframes, real_draw_fn draw)
{
    const char *name = argc > 0 ? argv[0] : "real";
    const char *trace = NULL, *dir = NULL;
    int w = 320, h = 240;
    for (int i = 1; i < argc; i++) {
        if (i + 1 >= argc)
            return usage(name);
        const char *a = argv[i], *v = argv[++i];
        char *end;
        if (strcmp(a, "--trace") == 0) {
            trace = v;
        } else if (strcmp(a, "--png-dir") == 0) {
            dir = v;
        } else if (strcmp(a, "--size") == 0) {
            long lw = strtol(v, &end, 10), lh = *end == 'x' ? strtol(end + 1, &end, 10) : 0;
            if (*end || lw < 1 || lh < 1 || lw > MAX_SIDE || lh > MAX_SIDE) {
                fprintf(stderr, "%s: --size %s: expected WxH, each 1..%d\n", name, v, MAX_SIDE);
                return 2;
            }
            w = (int)lw;
            h = (int)lh;
        } else {
            fprintf(stderr, "%s: unknown option %s\n", name, a);
            return usage(name);
        }
    }
    if (!trace || !dir)
        return usage(name);
    unsigned char *px = calloc((size_t)w * (size_t)h, 4);
    if (!px) {
        fprintf(stderr, "%s: out of memory\n", name);
        return 1;
    }
    int rc = 1;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, px, GL_UNSIGNED_BYTE, w, h)) {
        fprintf(stderr, "%s: cannot create the OSMesa context\n", name);
        goto fail_ctx;
    }
    if (rayglRecordOpen(trace) != 0) {
        fprintf(stderr, "%s: %s: cannot open the trace: %s\n", name, trace, strerror(errno));
        goto fail_ctx;
    }
    for (int f = 0; f < nframes; f++) {
        draw(f, w, h);
        rayglFrameEnd();
        glFinish();
        if (write_frame(dir, f, px, w, h) != 0) {
            fprintf(stderr, "%s: %s: cannot write frame %d's PNG\n", name, dir, f);
            goto fail_trace;
        }
    }
    rc = 0;
fail_trace:
    rayglRecordClose();
    if (rc == 0 && rayglRecordStatus() == RAYGL_FAILED) {
        const char *err = rayglRecordError();
        fprintf(stderr, "%s: recording failed: %s\n", name, err ? err : "");
        rc = 1;
    }
fail_ctx:
    if (ctx)
        OSMesaDestroyContext(ctx);
    free(px);
    return rc;
}
