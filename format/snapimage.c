/* snapimage.c: the images of @Snapshot commands (format 1.2): checking the
 * command, inflating its resource, and compressing an image for the
 * recorder. zlib does the deflate work; everything the trace says is
 * checked before it sizes an allocation (docs/format.md, section 3.1).
 */
#include <string.h>

#include <zlib.h>

#include "errset.h"
#include "format.h"

/* zlib's deflate expands at most 1032 times (a stored run of 258-byte
 * matches, two bits each); an image larger than this many times its stream
 * cannot come from it. */
#define ZLIB_MAX_RATIO 1032u
#define ZLIB_STREAM_MIN 8u /* 2-byte header, an empty block, Adler-32 */

rgl_status rgl_snapshot_from_cmd(const rgl_cmd *cmd, rgl_snapshot *out, rgl_error *err)
{
    if (!cmd || !out || cmd->opcode != RGL_OP_Snapshot || cmd->nargs != 7)
        return rgl_set_error(err, RGL_E_ARGUMENT, 0, 0, "not an @Snapshot command");
    int64_t x = rgl_arg_i(&cmd->arg[0], 0), y = rgl_arg_i(&cmd->arg[1], 0);
    int64_t w = rgl_arg_i(&cmd->arg[2], 0), h = rgl_arg_i(&cmd->arg[3], 0);
    uint64_t format = cmd->arg[4].v.u, codec = cmd->arg[5].v.u, image = cmd->arg[6].v.u;
    if (err)
        memset(err, 0, sizeof *err);
    if (w < 1 || h < 1 || w > RGL_SNAPSHOT_SIDE_MAX || h > RGL_SNAPSHOT_SIDE_MAX) {
        rgl_set_error(err, RGL_E_IMAGE, cmd->offset, cmd->opcode, "size %lldx%lld not in 1..%d",
                  (long long)w, (long long)h, RGL_SNAPSHOT_SIDE_MAX);
    } else if (format != RGL_SNAPSHOT_FORMAT_RGB) {
        rgl_set_error(err, RGL_E_IMAGE, cmd->offset, cmd->opcode, "unknown pixel format 0x%llx",
                  (unsigned long long)format);
    } else if (codec != RGL_SNAPSHOT_CODEC_ZLIB) {
        rgl_set_error(err, RGL_E_IMAGE, cmd->offset, cmd->opcode, "unknown codec %llu",
                  (unsigned long long)codec);
    } else if (image < 1 || image > RGL_RESOURCE_ID_MAX) {
        rgl_set_error(err, RGL_E_IMAGE, cmd->offset, cmd->opcode, "no image resource");
    } else {
        out->x = (int32_t)x;
        out->y = (int32_t)y;
        out->width = (int32_t)w;
        out->height = (int32_t)h;
        out->format = (uint32_t)format;
        out->codec = (uint32_t)codec;
        out->image = (uint32_t)image;
        out->offset = cmd->offset;
        return RGL_OK;
    }
    if (err)
        err->cmd_index = cmd->index;
    return RGL_E_IMAGE;
}

/* zlib's allocations go through the format library's wrapper, so a test can
 * fail them like any other. */
static voidpf z_alloc(voidpf opaque, uInt items, uInt size)
{
    (void)opaque;
    if (size && items > (size_t)-1 / size)
        return Z_NULL;
    return rgl_format_realloc(NULL, (size_t)items * size);
}

static void z_free(voidpf opaque, voidpf p)
{
    (void)opaque;
    rgl_format_realloc(p, 0);
}

rgl_status rgl_snapshot_decode(const rgl_snapshot *snap, const rgl_resource *res, uint8_t **rgb,
                               rgl_error *err)
{
    if (!snap || !res || !rgb)
        return rgl_set_error(err, RGL_E_ARGUMENT, 0, 0, "no snapshot, resource or output");
    *rgb = NULL;
    if (snap->width < 1 || snap->height < 1 || snap->width > RGL_SNAPSHOT_SIDE_MAX ||
        snap->height > RGL_SNAPSHOT_SIDE_MAX)
        return rgl_set_error(err, RGL_E_IMAGE, snap->offset, RGL_OP_Snapshot, "size %dx%d",
                         (int)snap->width, (int)snap->height);
    if (res->kind != RGL_RES_BYTES)
        return rgl_set_error(err, RGL_E_RESOURCE, res->data_offset, RGL_OP_Snapshot,
                         "image #%u is not a BYTES resource (kind %u)", (unsigned)res->id,
                         (unsigned)res->kind);
    size_t row = (size_t)snap->width * 3;
    size_t raw = row * (size_t)snap->height;
    if (res->size < ZLIB_STREAM_MIN || (uint64_t)res->size * ZLIB_MAX_RATIO < raw)
        return rgl_set_error(err, RGL_E_IMAGE, res->data_offset, RGL_OP_Snapshot,
                         "image #%u: %zu compressed bytes cannot hold %dx%d pixels",
                         (unsigned)res->id, res->size, (int)snap->width, (int)snap->height);

    uint8_t *out = rgl_format_realloc(NULL, raw);
    uint8_t *tmp = rgl_format_realloc(NULL, row);
    if (!out || !tmp) {
        rgl_format_realloc(out, 0);
        rgl_format_realloc(tmp, 0);
        return rgl_set_error(err, RGL_E_NOMEM, res->data_offset, RGL_OP_Snapshot,
                         "image #%u: %zu bytes", (unsigned)res->id, raw);
    }
    z_stream z;
    memset(&z, 0, sizeof z);
    z.zalloc = z_alloc;
    z.zfree = z_free;
    rgl_status st = RGL_OK;
    int zr = inflateInit(&z);
    if (zr != Z_OK) {
        st = rgl_set_error(err, zr == Z_MEM_ERROR ? RGL_E_NOMEM : RGL_E_IMAGE, res->data_offset,
                       RGL_OP_Snapshot, "image #%u: inflateInit failed", (unsigned)res->id);
        goto fail_buf;
    }
    z.next_in = (Bytef *)(uintptr_t)res->data;
    z.avail_in = (uInt)res->size;
    z.next_out = out;
    z.avail_out = (uInt)raw;
    zr = inflate(&z, Z_FINISH);
    uint64_t at = res->data_offset + z.total_in;
    if (zr == Z_MEM_ERROR) {
        st = rgl_set_error(err, RGL_E_NOMEM, at, RGL_OP_Snapshot, "image #%u: inflate",
                       (unsigned)res->id);
    } else if (zr == Z_STREAM_END && z.avail_out != 0) {
        st = rgl_set_error(err, RGL_E_IMAGE, at, RGL_OP_Snapshot,
                       "image #%u: stream ends after %lu of %zu bytes", (unsigned)res->id,
                       (unsigned long)z.total_out, raw);
    } else if (zr == Z_STREAM_END && z.avail_in != 0) {
        st = rgl_set_error(err, RGL_E_IMAGE, at, RGL_OP_Snapshot,
                       "image #%u: %u bytes after the stream", (unsigned)res->id,
                       (unsigned)z.avail_in);
    } else if (zr == Z_BUF_ERROR && z.avail_out == 0) {
        st = rgl_set_error(err, RGL_E_IMAGE, at, RGL_OP_Snapshot,
                       "image #%u: stream holds more than %dx%d pixels", (unsigned)res->id,
                       (int)snap->width, (int)snap->height);
    } else if (zr == Z_BUF_ERROR) {
        st = rgl_set_error(err, RGL_E_IMAGE, at, RGL_OP_Snapshot,
                       "image #%u: stream truncated after %lu of %zu bytes", (unsigned)res->id,
                       (unsigned long)z.total_out, raw);
    } else if (zr != Z_STREAM_END) {
        st = rgl_set_error(err, RGL_E_IMAGE, at, RGL_OP_Snapshot, "image #%u: %s",
                       (unsigned)res->id, z.msg ? z.msg : "bad zlib stream");
    }
    inflateEnd(&z);
    if (st != RGL_OK)
        goto fail_buf;

    /* Wire rows are GL's, bottom first; callers get the top row first. */
    for (int32_t a = 0, b = snap->height - 1; a < b; a++, b--) {
        memcpy(tmp, out + (size_t)a * row, row);
        memcpy(out + (size_t)a * row, out + (size_t)b * row, row);
        memcpy(out + (size_t)b * row, tmp, row);
    }
    rgl_format_realloc(tmp, 0);
    *rgb = out;
    if (err)
        memset(err, 0, sizeof *err);
    return RGL_OK;

fail_buf:
    rgl_format_realloc(tmp, 0);
    rgl_format_realloc(out, 0);
    return st;
}

typedef void *(*realloc_fn)(void *ptr, size_t size);

/* The encoder's zlib allocations go through the caller's function (opaque
 * points at it). */
static voidpf enc_alloc(voidpf opaque, uInt items, uInt size)
{
    if (size && items > (size_t)-1 / size)
        return Z_NULL;
    return (*(realloc_fn *)opaque)(NULL, (size_t)items * size);
}

static void enc_free(voidpf opaque, voidpf p) { (*(realloc_fn *)opaque)(p, 0); }

rgl_status rgl_snapshot_encode(const uint8_t *rgb, int32_t width, int32_t height, int level,
                               void *(*alloc)(void *ptr, size_t size), uint8_t **out,
                               size_t *size)
{
    if (!rgb || !alloc || !out || !size || width < 1 || height < 1 ||
        width > RGL_SNAPSHOT_SIDE_MAX || height > RGL_SNAPSHOT_SIDE_MAX || level < 1 ||
        level > 9)
        return RGL_E_ARGUMENT;
    *out = NULL;
    *size = 0;
    size_t raw = (size_t)width * (size_t)height * 3u;
    size_t cap = compressBound((uLong)raw);
    uint8_t *buf = alloc(NULL, cap);
    if (!buf)
        return RGL_E_NOMEM;
    z_stream z;
    memset(&z, 0, sizeof z);
    z.zalloc = enc_alloc;
    z.zfree = enc_free;
    z.opaque = (voidpf)&alloc;
    int zr = deflateInit(&z, level);
    if (zr == Z_OK) {
        z.next_in = (Bytef *)(uintptr_t)rgb;
        z.avail_in = (uInt)raw;
        z.next_out = buf;
        z.avail_out = (uInt)cap;
        zr = deflate(&z, Z_FINISH);
        deflateEnd(&z);
    }
    if (zr != Z_STREAM_END) {
        alloc(buf, 0);
        return zr == Z_MEM_ERROR ? RGL_E_NOMEM : RGL_E_ARGUMENT;
    }
    *out = buf;
    *size = (size_t)z.total_out;
    return RGL_OK;
}
