/* test_snapshot.c: @Snapshot images (format 1.2, format/snapimage.c). An
 * image survives encode and decode with its rows turned top first; hostile
 * commands and resources (sizes out of range, unknown format or codec, a
 * resource of the wrong kind, a stream cut short, with bytes after it,
 * holding more or fewer pixels, too small for the size it claims, damaged)
 * give RGL_E_IMAGE or RGL_E_RESOURCE, never a crash or an allocation of
 * what the input claims; a failed allocation gives RGL_E_NOMEM. */
#include "testutil.h"

static void *std_alloc(void *p, size_t n) { return rgl_format_realloc(p, n); }

static rgl_cmd make_cmd(int64_t w, int64_t h, uint64_t format, uint64_t codec, uint64_t image)
{
    rgl_cmd cmd;
    CHECK(rgl_cmd_init(&cmd, RGL_OP_Snapshot) == RGL_OK);
    cmd.arg[0].v.i = 0;
    cmd.arg[1].v.i = 0;
    cmd.arg[2].v.i = w;
    cmd.arg[3].v.i = h;
    cmd.arg[4].v.u = format;
    cmd.arg[5].v.u = codec;
    cmd.arg[6].v.u = image;
    cmd.offset = 1234;
    return cmd;
}

static rgl_status decode(int w, int h, uint32_t kind, const uint8_t *data, size_t size,
                         uint8_t **rgb, rgl_error *err)
{
    rgl_snapshot snap = {0, 0, w, h, RGL_SNAPSHOT_FORMAT_RGB, RGL_SNAPSHOT_CODEC_ZLIB, 3, 99};
    rgl_resource res = {3, kind, data, size, 5000};
    return rgl_snapshot_decode(&snap, &res, rgb, err);
}

int main(void)
{
    enum { W = 37, H = 23 };
    static uint8_t img[W * H * 3];
    for (size_t i = 0; i < sizeof img; i++)
        img[i] = (uint8_t)(i * 7 + i / 97);
    uint8_t *z = NULL;
    size_t zn = 0;
    CHECK(rgl_snapshot_encode(img, W, H, 1, std_alloc, &z, &zn) == RGL_OK);
    CHECK(zn > 8);

    /* Round trip: rows come back top first (the wire holds GL's order). */
    rgl_error err;
    uint8_t *rgb = NULL;
    CHECK(decode(W, H, RGL_RES_BYTES, z, zn, &rgb, &err) == RGL_OK);
    if (CHECK(rgb != NULL)) {
        for (int y = 0; y < H; y++)
            CHECK(memcmp(rgb + (size_t)y * W * 3, img + (size_t)(H - 1 - y) * W * 3, W * 3) == 0);
        rgl_format_realloc(rgb, 0);
    }

    /* The command's checks. */
    rgl_snapshot snap;
    rgl_cmd c = make_cmd(W, H, RGL_SNAPSHOT_FORMAT_RGB, 1, 3);
    CHECK(rgl_snapshot_from_cmd(&c, &snap, &err) == RGL_OK && snap.width == W && snap.image == 3);
    const struct { int64_t w, h; uint64_t f, c, id; } bad[] = {
        {0, 5, 0x1907, 1, 3}, {5, 0, 0x1907, 1, 3}, {-1, 5, 0x1907, 1, 3},
        {16385, 5, 0x1907, 1, 3}, {5, 1 << 30, 0x1907, 1, 3}, {5, 5, 0x1908, 1, 3},
        {5, 5, 0x1907, 0, 3}, {5, 5, 0x1907, 2, 3}, {5, 5, 0x1907, 1, 0},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        c = make_cmd(bad[i].w, bad[i].h, bad[i].f, bad[i].c, bad[i].id);
        CHECKF(rgl_snapshot_from_cmd(&c, &snap, &err) == RGL_E_IMAGE && err.offset == 1234 &&
                   err.opcode == RGL_OP_Snapshot && err.detail[0],
               "case %zu", i);
    }
    c = make_cmd(1, 1, 0x1907, 1, 1);
    c.opcode = RGL_OP_Flush;
    CHECK(rgl_snapshot_from_cmd(&c, &snap, &err) == RGL_E_ARGUMENT);

    /* Hostile resources. */
    rgb = (uint8_t *)1;
    CHECK(decode(W, H, RGL_RES_COMMANDS, z, zn, &rgb, &err) == RGL_E_RESOURCE && rgb == NULL);
    CHECKF(decode(W, H, RGL_RES_BYTES, z, zn - 5, &rgb, &err) == RGL_E_IMAGE, "cut: %s",
           err.detail);
    CHECK(err.offset >= 5000 && err.offset <= 5000 + zn);
    CHECK(decode(W, H, RGL_RES_BYTES, z, 3, &rgb, &err) == RGL_E_IMAGE);
    uint8_t *longer = malloc(zn + 4);
    memcpy(longer, z, zn);
    memset(longer + zn, 0, 4);
    CHECKF(decode(W, H, RGL_RES_BYTES, longer, zn + 4, &rgb, &err) == RGL_E_IMAGE &&
               strstr(err.detail, "after the stream"),
           "%s", err.detail);
    CHECKF(decode(W, H - 1, RGL_RES_BYTES, z, zn, &rgb, &err) == RGL_E_IMAGE &&
               strstr(err.detail, "more than"),
           "%s", err.detail);
    CHECKF(decode(W, H + 1, RGL_RES_BYTES, z, zn, &rgb, &err) == RGL_E_IMAGE &&
               strstr(err.detail, "ends after"),
           "%s", err.detail);
    /* 16384 x 16384 claimed from a few hundred bytes: refused unallocated. */
    rgl_format_fail_alloc(1);
    CHECKF(decode(16384, 16384, RGL_RES_BYTES, z, zn, &rgb, &err) == RGL_E_IMAGE &&
               strstr(err.detail, "cannot hold"),
           "%s", err.detail);
    rgl_format_fail_alloc(0);
    for (size_t k = 0; k < zn; k++) {
        memcpy(longer, z, zn);
        longer[k] ^= 0x5a;
        rgl_status st = decode(W, H, RGL_RES_BYTES, longer, zn, &rgb, &err);
        /* A flip in the last byte's padding bits leaves the stream valid:
         * then the image must come back whole (Adler-32 checks it). */
        bool same = st == RGL_OK &&
                    memcmp(rgb + (size_t)(H - 1) * W * 3, img, W * 3) == 0;
        CHECKF(st == RGL_E_IMAGE || same, "flip at %zu: %s", k, rgl_status_str(st));
        if (st == RGL_OK)
            rgl_format_realloc(rgb, 0);
    }
    free(longer);
    for (unsigned long n = 1; n <= 6; n++) {
        rgl_format_fail_alloc(n);
        rgl_status st = decode(W, H, RGL_RES_BYTES, z, zn, &rgb, &err);
        rgl_format_fail_alloc(0);
        CHECK(st == RGL_OK || st == RGL_E_NOMEM);
        if (st == RGL_OK)
            rgl_format_realloc(rgb, 0);
    }
    CHECK(strcmp(rgl_status_str(RGL_E_IMAGE), "malformed snapshot image") == 0);
    rgl_format_realloc(z, 0);
    return test_summary("snapshot");
}
