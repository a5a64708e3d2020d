/* fuzz_decode.c: the libFuzzer target for the reader, decoder and dumper.
 *
 * Each input is used four ways: as a whole trace (rgl_reader_open_memory,
 * every frame and resource, every command decoded and formatted); as a bare
 * command sequence; wrapped by rgl_trace_builder into a valid trace, so the
 * checksums hold and the fuzzer reaches the decoder through the reader too;
 * and as a list of chunks given valid checksums and an END trailer. Beyond "no crash", it checks what must hold for any input: a decoded
 * command re-encodes to exactly its input bytes, errors point inside the
 * input, and rgl_cmd_format agrees with itself at every buffer size.
 * fuzz/replay.c runs the same function over the corpus in every meson test.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "fuzz_decode: check failed: %s (%s:%d)\n", #cond, __FILE__, \
                    __LINE__);                                                       \
            abort();                                                                 \
        }                                                                            \
    } while (0)

static void check_format(const rgl_cmd *cmd)
{
    char line[8192], small[24];
    size_t n = rgl_cmd_format(cmd, line, sizeof line);
    size_t m = rgl_cmd_format(cmd, small, sizeof small);
    CHECK(n == m);
    if (n < sizeof line) {
        CHECK(strlen(line) == n);
        CHECK(strlen(small) == (n < sizeof small ? n : sizeof small - 1));
        CHECK(memcmp(line, small, strlen(small)) == 0);
    }
}

/* Decodes every command of [data, data+size) at file offset base. */
static void decode_sequence(const uint8_t *data, size_t size, uint64_t base)
{
    static rgl_cmd cmd; /* large: keep it off the stack */
    static uint8_t again[1u << 16];
    rgl_cmd_iter it;
    rgl_status st;
    uint64_t count = 0;

    rgl_cmd_iter_init(&it, data, size, base);
    while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
        size_t len = (size_t)(it.pos - data) - (size_t)(cmd.offset - base);
        size_t n;
        CHECK(cmd.index == count++);
        CHECK(cmd.offset >= base && cmd.offset < base + size);
        check_format(&cmd);
        /* Canonical encoding: decode then encode gives back the input. */
        n = rgl_cmd_encode(&cmd, again, sizeof again);
        if (len <= sizeof again) {
            CHECK(n == len);
            CHECK(memcmp(again, data + (cmd.offset - base), len) == 0);
        }
        for (uint32_t i = 0; i < cmd.nargs; i++) {
            (void)rgl_arg_f(&cmd.arg[i], 0);
            (void)rgl_arg_i(&cmd.arg[i], cmd.arg[i].count);
        }
    }
    if (st != RGL_END) {
        CHECK(it.error.status == st);
        CHECK(it.error.offset >= base && it.error.offset <= base + size);
        CHECK(it.error.cmd_index == count);
        CHECK(rgl_cmd_next(&it, &cmd) == st); /* the error sticks */
        CHECK(strlen(it.error.detail) < sizeof it.error.detail);
    }
}

/* Every @Snapshot of the sequence: its image decoded from the trace's
 * resource (format 1.2), errors inside the input. */
static void decode_snapshots(rgl_reader *r, const uint8_t *seq, size_t n, uint64_t base,
                             size_t size)
{
    static rgl_cmd cmd;
    rgl_cmd_iter it;
    rgl_cmd_iter_init(&it, seq, n, base);
    while (rgl_cmd_next(&it, &cmd) == RGL_OK) {
        rgl_snapshot snap;
        rgl_resource res;
        rgl_error err;
        uint8_t *rgb = NULL;
        if (cmd.opcode != RGL_OP_Snapshot)
            continue;
        if (rgl_snapshot_from_cmd(&cmd, &snap, &err) != RGL_OK) {
            CHECK(err.offset <= size && err.status == RGL_E_IMAGE);
            continue;
        }
        if (rgl_reader_resource(r, snap.image, &res, &err) != RGL_OK)
            continue;
        if (rgl_snapshot_decode(&snap, &res, &rgb, &err) == RGL_OK) {
            CHECK(rgb != NULL);
            rgl_format_realloc(rgb, 0);
        } else {
            CHECK(rgb == NULL && err.offset <= size);
        }
    }
}

static void read_trace(const uint8_t *data, size_t size)
{
    rgl_reader *r = NULL;
    rgl_error err;
    size_t info_size;

    if (rgl_reader_open_memory(data, size, &r, &err) != RGL_OK) {
        CHECK(r == NULL);
        CHECK(err.offset <= size);
        return;
    }
    const char *info = rgl_reader_info(r, &info_size);
    if (info)
        CHECK(strlen(info) <= info_size);
    for (size_t i = 0; i < rgl_reader_damage_count(r); i++)
        CHECK(rgl_reader_damage(r, i)->offset <= size);
    for (size_t i = 0; i < rgl_reader_frame_count(r); i++) {
        rgl_frame_info f;
        rgl_resource res;
        if (rgl_reader_frame(r, i, &f, &err) != RGL_OK) {
            CHECK(err.offset <= size);
            continue;
        }
        CHECK(f.commands_offset + f.commands_size <= size);
        CHECK(f.commands == data + f.commands_offset);
        decode_sequence(f.commands, f.commands_size, f.commands_offset);
        decode_snapshots(r, f.commands, f.commands_size, f.commands_offset, size);
        if (f.state)
            (void)rgl_reader_resource(r, f.state, &res, &err);
    }
    for (size_t i = 0; i < rgl_reader_resource_count(r); i++) {
        rgl_resource res;
        if (rgl_reader_resource_at(r, i, &res, &err) != RGL_OK) {
            CHECK(err.offset <= size);
            continue;
        }
        CHECK(res.data_offset + res.size <= size);
        if (res.kind == RGL_RES_COMMANDS)
            decode_sequence(res.data, res.size, res.data_offset);
    }
    rgl_reader_destroy(r);
}

/* The input as a frame and a resource of a valid trace, with and without an
 * index, so the reader and decoder see it past the checksums. */
static void wrapped(const uint8_t *data, size_t size)
{
    for (int with_index = 0; with_index < 2; with_index++) {
        rgl_trace_builder *b = rgl_trace_builder_create();
        const uint8_t *trace;
        size_t trace_size;
        uint32_t id = 0, bytes_id = 0;
        if (!b)
            return;
        /* The bytes go once into each path: as the frame without an index,
         * as the resource with one (the other gets no commands). */
        if (rgl_trace_builder_info(b, "program=fuzz\n", 13) == RGL_OK &&
            rgl_trace_builder_resource(b, RGL_RES_COMMANDS, data, with_index ? size : 0, &id) ==
                RGL_OK &&
            /* #2: the bytes again as a BYTES resource, for @Snapshot(image=#2) */
            rgl_trace_builder_resource(b, RGL_RES_BYTES, data, size, &bytes_id) == RGL_OK &&
            rgl_trace_builder_frame(b, 0, 0, 0, id, data, with_index ? 0 : size) == RGL_OK &&
            rgl_trace_builder_finish(b, with_index, &trace, &trace_size) == RGL_OK)
            read_trace(trace, trace_size);
        rgl_trace_builder_destroy(b);
    }
}

/* The input as a list of chunks, [type % 8][length][payload] each, given
 * correct headers and checksums, then an END chunk aimed at one of them: the
 * reader's chunk handling and index checks see fuzzed payloads behind valid
 * CRCs (INDEX payloads above all). */
static void chunked(const uint8_t *data, size_t size)
{
    size_t cap = RGL_FILE_HEADER_SIZE + size * 21 + 64, n = RGL_FILE_HEADER_SIZE, count = 0;
    uint8_t *buf = malloc(cap), end[8];
    uint64_t offsets[64] = {0};
    const uint8_t *p = data, *e = data + size;

    if (!buf || size < 1)
        goto out;
    rgl_file_header_encode(buf, 0);
    p++; /* the first byte picks the chunk END points at */
    while (e - p >= 2) {
        uint8_t type = p[0] % 8;
        uint32_t len = p[1];
        p += 2;
        if (len > (size_t)(e - p))
            len = (uint32_t)(e - p);
        if (count < 64)
            offsets[count] = n;
        count++;
        rgl_chunk_header_encode(buf + n, type, len);
        memcpy(buf + n + RGL_CHUNK_HEADER_SIZE, p, len);
        uint32_t crc = rgl_crc32c(0, p, len);
        memcpy(buf + n + RGL_CHUNK_HEADER_SIZE + len, (uint8_t[]){(uint8_t)crc,
               (uint8_t)(crc >> 8), (uint8_t)(crc >> 16), (uint8_t)(crc >> 24)}, 4);
        n += RGL_CHUNK_HEADER_SIZE + len + RGL_CHUNK_TRAILER_SIZE;
        p += len;
    }
    if (count) {
        uint64_t at = offsets[data[0] % (count < 64 ? count : 64)];
        for (int k = 0; k < 8; k++)
            end[k] = (uint8_t)(at >> (8 * k));
        rgl_chunk_header_encode(buf + n, RGL_CHUNK_END, 8);
        memcpy(buf + n + RGL_CHUNK_HEADER_SIZE, end, 8);
        uint32_t crc = rgl_crc32c(0, end, 8);
        memcpy(buf + n + RGL_CHUNK_HEADER_SIZE + 8, (uint8_t[]){(uint8_t)crc,
               (uint8_t)(crc >> 8), (uint8_t)(crc >> 16), (uint8_t)(crc >> 24)}, 4);
        n += 28;
    }
    read_trace(buf, n);
out:
    free(buf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    read_trace(data, size);
    decode_sequence(data, size, 0);
    wrapped(data, size);
    chunked(data, size);
    return 0;
}
