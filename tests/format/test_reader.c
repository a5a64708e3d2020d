/* test_reader.c: reading whole traces back.
 *
 * A trace from rgl_trace_builder with INFO, resources and frames on two
 * streams reads back identically with and without its index, from memory
 * and from a file; the index is really used when valid and ignored (in
 * favour of a scan) when it points anywhere wrong; duplicate resource ids
 * resolve to the first; unknown chunk types are skipped; every file-header
 * error gives its own status; the builder refuses calls after finish.
 */
#include <unistd.h>

#include "testutil.h"

static uint8_t buf[1 << 16];

/* Appends a chunk with a correct header and trailer. */
static size_t append_chunk(uint8_t *d, size_t size, uint8_t type, const void *payload,
                           uint32_t len)
{
    rgl_chunk_header_encode(d + size, type, len);
    memcpy(d + size + RGL_CHUNK_HEADER_SIZE, payload, len);
    rgl_put_u32(d + size + RGL_CHUNK_HEADER_SIZE + len,
                rgl_crc32c(0, d + size + RGL_CHUNK_HEADER_SIZE, len));
    return size + RGL_CHUNK_HEADER_SIZE + len + RGL_CHUNK_TRAILER_SIZE;
}

static void check_whole(const sample *s, rgl_reader *rd, const char *how)
{
    size_t info_size;
    const char *info = rgl_reader_info(rd, &info_size);
    rgl_resource res;
    rgl_error err;
    static rgl_cmd cmd;

    CHECKF(rgl_reader_frame_count(rd) == SAMPLE_FRAMES, "%s: %zu frames", how,
           rgl_reader_frame_count(rd));
    for (size_t f = 0; f < SAMPLE_FRAMES; f++)
        CHECKF(sample_frame_ok(s, rd, f, f), "%s: frame %zu", how, f);
    CHECK(info && info_size == sizeof sample_info - 1 && !strcmp(info, sample_info));
    CHECK(rgl_reader_damage_count(rd) == 0 && rgl_reader_damage(rd, 0) == NULL);
    CHECK(rgl_reader_resource_count(rd) == SAMPLE_RESOURCES);
    for (int i = 0; i < SAMPLE_RESOURCES; i++) {
        CHECK(s->res_id[i] == (uint32_t)i + 1);
        CHECK(rgl_reader_resource(rd, s->res_id[i], &res, &err) == RGL_OK);
        CHECK(res.id == s->res_id[i] && res.size == s->res_len[i] &&
              memcmp(res.data, s->res_bytes[i], res.size) == 0);
        CHECK(res.kind == (i == 1 ? RGL_RES_BYTES : RGL_RES_COMMANDS));
        CHECK(memcmp(s->data + res.data_offset, res.data, res.size) == 0);
        CHECK(rgl_reader_resource_at(rd, (size_t)i, &res, &err) == RGL_OK &&
              res.id == (uint32_t)i + 1);
    }
    CHECK(rgl_reader_resource(rd, 0, &res, &err) == RGL_E_RESOURCE);
    CHECK(rgl_reader_resource(rd, 4, &res, &err) == RGL_E_RESOURCE);
    CHECK(rgl_reader_resource(rd, UINT32_MAX, &res, &err) == RGL_E_RESOURCE);
    CHECK(rgl_reader_resource_at(rd, SAMPLE_RESOURCES, &res, &err) == RGL_E_ARGUMENT);
    rgl_frame_info fi;
    CHECK(rgl_reader_frame(rd, SAMPLE_FRAMES, &fi, &err) == RGL_E_ARGUMENT);
    /* Every frame decodes to its end. */
    for (size_t f = 0; f < SAMPLE_FRAMES; f++) {
        rgl_cmd_iter it;
        rgl_status st;
        rgl_reader_frame(rd, f, &fi, &err);
        CHECK(memcmp(s->data + fi.commands_offset, fi.commands, fi.commands_size) == 0);
        rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
        while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK)
            CHECK(cmd.offset >= fi.commands_offset);
        CHECK(st == RGL_END && it.index == 6);
    }
}

static void test_roundtrip(void)
{
    for (int with_index = 0; with_index < 2; with_index++) {
        sample s;
        rgl_reader *rd;
        rgl_error err;
        CHECK(sample_build(&s, with_index, 7));
        CHECK(rgl_reader_open_memory(s.data, s.size, &rd, &err) == RGL_OK);
        check_whole(&s, rd, with_index ? "memory, index" : "memory, no index");
        /* Without index and END the trace was not closed; it ends between chunks. */
        uint64_t tail;
        CHECK(rgl_reader_closed(rd, &tail) == (bool)with_index &&
              tail == (with_index ? 0 : s.size));
        rgl_reader_destroy(rd);

        char path[] = "/tmp/rgl-reader-XXXXXX";
        int fd = mkstemp(path);
        CHECK(fd >= 0 && write(fd, s.data, s.size) == (ssize_t)s.size);
        close(fd);
        CHECK(rgl_reader_open_file(path, &rd, &err) == RGL_OK);
        if (rd)
            check_whole(&s, rd, with_index ? "file, index" : "file, no index");
        rgl_reader_destroy(rd);
        unlink(path);
        rgl_trace_builder_destroy(s.builder);
    }
    printf("  builder trace reads back whole: memory and file, with and without index\n");
}

static void test_index_used(void)
{
    sample s;
    rgl_reader *rd;
    rgl_error err;
    size_t n;
    chunk_span spans[32];

    for (int with_index = 0; with_index < 2; with_index++) {
        CHECK(sample_build(&s, with_index, 8));
        memcpy(buf, s.data, s.size);
        /* Damage the INFO chunk's header: the index does not list INFO, so
         * with an index nothing is scanned and no damage is seen. */
        buf[RGL_FILE_HEADER_SIZE + 6] ^= 0x55;
        CHECK(rgl_reader_open_memory(buf, s.size, &rd, &err) == RGL_OK);
        CHECK(rgl_reader_frame_count(rd) == SAMPLE_FRAMES);
        CHECK(rgl_reader_info(rd, NULL) == NULL);
        CHECKF(rgl_reader_damage_count(rd) == (with_index ? 0u : 1u), "damage %zu",
               rgl_reader_damage_count(rd));
        if (!with_index && rgl_reader_damage_count(rd))
            CHECK(rgl_reader_damage(rd, 0)->offset == RGL_FILE_HEADER_SIZE &&
                  rgl_reader_damage(rd, 0)->status == RGL_E_CHECKSUM);
        rgl_reader_destroy(rd);
        rgl_trace_builder_destroy(s.builder);
    }

    /* Hand-made indexes: a right one (variant 0), then ones that point wrong,
     * each refused so that the scan finds everything. */
    CHECK(sample_build(&s, false, 9));
    n = chunk_spans(s.data, s.size, spans, 32);
    CHECK(n == 1 + SAMPLE_RESOURCES + SAMPLE_FRAMES);
    for (int variant = 0; variant < 6; variant++) {
        uint8_t idx[128], *p = idx, end[8];
        size_t size;
        uint64_t index_at;
        memcpy(buf, s.data, s.size);
        size = s.size;
        p = rgl_put_varint(p, SAMPLE_FRAMES);
        for (int f = 0; f < SAMPLE_FRAMES; f++) {
            uint64_t off = spans[1 + SAMPLE_RESOURCES + f].start;
            if (variant == 1 && f == 2)
                off = spans[1].start; /* a resource listed as a frame */
            if (variant == 2 && f == 3)
                off += 1; /* not a chunk header */
            if (variant == 3 && f == 1)
                off = spans[1 + SAMPLE_RESOURCES + 3].start; /* out of file order */
            p = rgl_put_varint(p, off);
        }
        p = rgl_put_varint(p, variant == 4 ? 1 : SAMPLE_RESOURCES);
        for (int i = 0; i < (variant == 4 ? 1 : SAMPLE_RESOURCES); i++) {
            p = rgl_put_varint(p, variant == 4 ? 2u : (uint32_t)i + 1); /* id 2 at id 1's chunk */
            p = rgl_put_varint(p, spans[1 + i].start);
        }
        index_at = size;
        size = append_chunk(buf, size, RGL_CHUNK_INDEX, idx, (uint32_t)(p - idx));
        rgl_put_u64(end, variant == 5 ? index_at + 3 : index_at);
        size = append_chunk(buf, size, RGL_CHUNK_END, end, 8);
        CHECK(rgl_reader_open_memory(buf, size, &rd, &err) == RGL_OK);
        CHECKF(rgl_reader_frame_count(rd) == SAMPLE_FRAMES, "variant %d: %zu frames", variant,
               rgl_reader_frame_count(rd));
        for (size_t f = 0; f < SAMPLE_FRAMES; f++)
            CHECKF(sample_frame_ok(&s, rd, f, f), "variant %d frame %zu", variant, f);
        CHECK(rgl_reader_resource_count(rd) == SAMPLE_RESOURCES);
        CHECKF(rgl_reader_closed(rd, NULL), "variant %d: an END trailer closes the trace", variant);
        rgl_reader_destroy(rd);
    }
    rgl_trace_builder_destroy(s.builder);
    printf("  a valid index is used (no scan); wrong indexes fall back to a full scan\n");
}

static void test_duplicates_and_unknown(void)
{
    sample s;
    rgl_reader *rd;
    rgl_error err;
    rgl_resource res;
    uint8_t payload[16] = {1, RGL_RES_BYTES, 'd', 'u', 'p'};
    size_t size;

    CHECK(sample_build(&s, false, 10));
    memcpy(buf, s.data, s.size);
    /* A later resource with id 1, and chunks of types this reader lacks. */
    size = append_chunk(buf, s.size, 77, "future", 6);
    size = append_chunk(buf, size, RGL_CHUNK_RESOURCE, payload, 5);
    size = append_chunk(buf, size, 200, "", 0);
    CHECK(rgl_reader_open_memory(buf, size, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_damage_count(rd) == 0);
    CHECK(rgl_reader_frame_count(rd) == SAMPLE_FRAMES);
    CHECK(rgl_reader_resource_count(rd) == SAMPLE_RESOURCES);
    CHECK(rgl_reader_resource(rd, 1, &res, &err) == RGL_OK && res.size == s.res_len[0] &&
          memcmp(res.data, s.res_bytes[0], res.size) == 0);
    rgl_reader_destroy(rd);
    rgl_trace_builder_destroy(s.builder);
    printf("  duplicate resource id: the first wins; unknown chunk types skipped quietly\n");
}

static rgl_status open_status(const uint8_t *d, size_t n, uint64_t *offset)
{
    rgl_reader *rd = (rgl_reader *)1;
    rgl_error err;
    rgl_status st = rgl_reader_open_memory(d, n, &rd, &err);
    if (st != RGL_OK)
        CHECK(rd == NULL && err.status == st);
    if (offset)
        *offset = err.offset;
    rgl_reader_destroy(st == RGL_OK ? rd : NULL);
    return st;
}

static void fix_header_crc(uint8_t *h) { rgl_put_u32(h + 28, rgl_crc32c(0, h, 28)); }

static void test_file_header(void)
{
    uint8_t h[64];
    uint64_t off;
    rgl_file_header_encode(h, 0);
    CHECK(memcmp(h, "\x89RGL\r\n\x1a\n", 8) == 0 && rgl_get_u16(h + 8) == 1 &&
          rgl_get_u16(h + 10) == RGL_FORMAT_MINOR && rgl_get_u32(h + 12) == 0 &&
          rgl_get_u32(h + 16) == 0x0A0B0C0Du && rgl_get_u32(h + 20) == 0xC0C00000u &&
          rgl_get_u32(h + 24) == 32);
    CHECK(open_status(h, 32, NULL) == RGL_OK); /* a header alone: an empty trace */
    CHECK(open_status(h, 0, NULL) == RGL_E_TRUNCATED);
    CHECK(open_status(NULL, 0, NULL) == RGL_E_TRUNCATED);
    CHECK(open_status(h, 5, NULL) == RGL_E_TRUNCATED);
    CHECK(open_status(h, 31, NULL) == RGL_E_TRUNCATED);
    CHECK(open_status((const uint8_t *)"hello", 5, NULL) == RGL_E_MAGIC);
    CHECK(open_status((const uint8_t *)"PK\x03\x04 not a trace at all, longer than 32",
                      40, NULL) == RGL_E_MAGIC);

    uint8_t t[32];
    memcpy(t, h, 32);
    t[1] = 'r';
    CHECK(open_status(t, 32, &off) == RGL_E_MAGIC && off == 0);
    memcpy(t, h, 32);
    rgl_put_u16(t + 8, 2);
    CHECK(open_status(t, 32, &off) == RGL_E_VERSION && off == 8);
    fix_header_crc(t);
    CHECK(open_status(t, 32, NULL) == RGL_E_VERSION);
    memcpy(t, h, 32);
    rgl_put_u16(t + 10, 7); /* a newer minor is accepted */
    fix_header_crc(t);
    CHECK(open_status(t, 32, NULL) == RGL_OK);
    memcpy(t, h, 32);
    rgl_put_u32(t + 16, 0x0D0C0B0Au);
    CHECK(open_status(t, 32, &off) == RGL_E_BYTE_ORDER && off == 16);
    memcpy(t, h, 32);
    rgl_put_u32(t + 20, 0x0000C0C0u);
    fix_header_crc(t);
    CHECK(open_status(t, 32, &off) == RGL_E_BYTE_ORDER && off == 20);
    /* A big-endian writer: every field swapped. */
    memcpy(t, h, 32);
    t[8] = 0; t[9] = 1;
    rgl_put_u32(t + 16, 0x0D0C0B0Au);
    rgl_put_u32(t + 20, 0x0000C0C0u);
    CHECK(open_status(t, 32, NULL) == RGL_E_BYTE_ORDER);
    memcpy(t, h, 32);
    t[12] ^= 1; /* flags, not covered by any other check */
    CHECK(open_status(t, 32, &off) == RGL_E_CHECKSUM && off == 28);
    memcpy(t, h, 32);
    t[30] ^= 1;
    CHECK(open_status(t, 32, NULL) == RGL_E_CHECKSUM);
    memcpy(t, h, 32);
    rgl_put_u32(t + 24, 16);
    fix_header_crc(t);
    CHECK(open_status(t, 32, NULL) == RGL_E_VERSION);
    rgl_put_u32(t + 24, 64);
    fix_header_crc(t);
    CHECK(open_status(t, 32, NULL) == RGL_E_TRUNCATED);

    rgl_reader *rd = (rgl_reader *)1;
    rgl_error err;
    char path[] = "/tmp/rgl-empty-XXXXXX";
    int fd = mkstemp(path);
    close(fd);
    CHECK(rgl_reader_open_file(path, &rd, &err) == RGL_E_TRUNCATED && rd == NULL);
    unlink(path);
    CHECK(rgl_reader_open_file("/nonexistent/trace.raygl", &rd, &err) == RGL_E_IO);
    CHECK(rgl_reader_open_file("/tmp", &rd, &err) == RGL_E_IO);
    CHECK(rgl_reader_open_memory(NULL, 4, &rd, &err) == RGL_E_ARGUMENT);
    rgl_reader_destroy(NULL);
    printf("  file header: magic, version, newer minor, byte order, checksum, size; empty files\n");
}

static void test_builder(void)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    const uint8_t *d;
    size_t n;
    uint32_t id = 0;
    CHECK(rgl_trace_builder_resource(b, RGL_RES_BYTES, "x", 1, &id) == RGL_OK && id == 1);
    CHECK(rgl_trace_builder_resource(b, RGL_RES_BYTES, "", 0, &id) == RGL_OK && id == 2);
    CHECK(rgl_trace_builder_resource(b, RGL_RES_BYTES, NULL, 3, &id) == RGL_E_ARGUMENT);
    CHECK(rgl_trace_builder_frame(b, 0, 0, 0, 0, NULL, 0) == RGL_OK);
    CHECK(rgl_trace_builder_finish(b, true, &d, &n) == RGL_OK);
    /* The END chunk is the last 28 bytes and points at the INDEX chunk. */
    CHECK(n > 28 && !memcmp(d + n - 28, RGL_CHUNK_SYNC, 4) && d[n - 24] == RGL_CHUNK_END);
    uint64_t idx = rgl_get_u64(d + n - 12);
    CHECK(idx < n - 28 && d[idx + 4] == RGL_CHUNK_INDEX);
    CHECK(rgl_trace_builder_frame(b, 0, 1, 0, 0, NULL, 0) == RGL_E_STATE);
    CHECK(rgl_trace_builder_finish(b, true, &d, &n) == RGL_E_STATE);
    rgl_trace_builder_destroy(b);
    rgl_trace_builder_destroy(NULL);
    printf("  builder: ids from 1, END trailer last, calls after finish refused\n");
}

int main(void)
{
    test_roundtrip();
    test_index_used();
    test_duplicates_and_unknown();
    test_file_header();
    test_builder();
    return test_summary("test_reader");
}
