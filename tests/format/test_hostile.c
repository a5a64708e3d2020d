/* test_hostile.c: inputs made to hurt.
 *
 * Commands with huge or over-limit counts and lengths, unknown and malformed
 * opcodes, errors after good commands (offset, index and opcode exact, and
 * sticky); traces with a chunk length past the end, a CRC-valid header with
 * a length over the limit, an index claiming 2^60 frames, a resource with id
 * 0, a file of nothing but sync patterns, megabytes of random bytes, and
 * hundreds of thousands of tiny chunks: each opens in bounded time and
 * memory, reports where it went wrong, and keeps what is whole.
 */
#include <time.h>

#include "testutil.h"

static uint8_t buf[1 << 16];

static size_t put_var(uint8_t *p, uint64_t v) { return (size_t)(rgl_put_varint(p, v) - p); }

/* Decodes [buf, buf+n) at base 100; expects `want` at byte `at` of the
 * command with index `index` (opcode `op`). */
static void expect_error(size_t n, rgl_status want, uint64_t at, uint64_t index, uint32_t op,
                         const char *what)
{
    static rgl_cmd cmd;
    rgl_cmd_iter it;
    rgl_status st;
    uint64_t good = 0;
    rgl_cmd_iter_init(&it, buf, n, 100);
    while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK)
        good++;
    CHECKF(st == want, "%s: got %s, want %s", what, rgl_status_str(st), rgl_status_str(want));
    CHECKF(it.error.offset == 100 + at, "%s: offset %llu, want %llu (%s)", what,
           (unsigned long long)it.error.offset, (unsigned long long)(100 + at), it.error.detail);
    CHECK(it.error.cmd_index == index && good == index);
    CHECKF(it.error.opcode == op, "%s: opcode 0x%x", what, (unsigned)it.error.opcode);
    CHECK(it.error.detail[0] != '\0');
    CHECK(rgl_cmd_next(&it, &cmd) == want && rgl_cmd_next(&it, &cmd) == want);
}

static void hostile_commands(void)
{
    size_t n, lead;

    /* Two good commands first, so offsets and indices are not trivially 0. */
    lead = 0;
    buf[lead++] = RGL_OP_End;
    buf[lead++] = RGL_OP_Begin;
    buf[lead++] = 4;

    n = lead + put_var(buf + lead, RGL_OP_Lightfv);
    buf[n++] = 0x80; buf[n++] = 0x80; buf[n++] = 1; /* light 0x4000 */
    buf[n++] = 0x83; buf[n++] = 0x24;               /* pname 0x1203 */
    size_t count_at = n;
    n += put_var(buf + n, UINT32_MAX);
    expect_error(n, RGL_E_LIMIT, count_at, 2, RGL_OP_Lightfv, "count 2^32-1");
    n = count_at + put_var(buf + count_at, RGL_ARRAY_MAX + 1);
    memset(buf + n, 0, 4 * 65);
    expect_error(n + 4 * 65, RGL_E_LIMIT, count_at, 2, RGL_OP_Lightfv, "count 65");
    n = count_at + put_var(buf + count_at, RGL_ARRAY_MAX);
    memset(buf + n, 0, 10);
    expect_error(n + 10, RGL_E_TRUNCATED, count_at, 2, RGL_OP_Lightfv, "count 64, 10 bytes");
    n = count_at + put_var(buf + count_at, (uint64_t)UINT32_MAX + 1);
    expect_error(n, RGL_E_VARINT, count_at, 2, RGL_OP_Lightfv, "count 2^32");

    /* Blob lengths: over the payload limit, and past the end. */
    n = lead + put_var(buf + lead, RGL_OP_DrawElements);
    buf[n++] = 4; buf[n++] = 12; buf[n++] = 0x83; buf[n++] = 0x28;
    size_t len_at = n;
    n += put_var(buf + n, (uint64_t)RGL_CHUNK_MAX_PAYLOAD + 1);
    expect_error(n, RGL_E_LIMIT, len_at, 2, RGL_OP_DrawElements, "blob 2^30+1");
    n = len_at + put_var(buf + len_at, 1000);
    memset(buf + n, 7, 10);
    expect_error(n + 10, RGL_E_TRUNCATED, len_at, 2, RGL_OP_DrawElements, "blob past end");

    /* Strings: over RGL_STRING_MAX, and past the end. */
    n = lead + put_var(buf + lead, RGL_OP_FrameBegin);
    len_at = n;
    n += put_var(buf + n, RGL_STRING_MAX + 1);
    memset(buf + n, 'a', RGL_STRING_MAX + 1 + 40);
    expect_error(n + RGL_STRING_MAX + 1 + 40, RGL_E_LIMIT, len_at, 2, RGL_OP_FrameBegin,
                 "string 4097");
    n = len_at + put_var(buf + len_at, RGL_STRING_MAX);
    expect_error(n + 100, RGL_E_TRUNCATED, len_at, 2, RGL_OP_FrameBegin, "string past end");

    /* Opcodes: 0, past the table, at and past the limit, malformed varints. */
    static const uint64_t bad_ops[] = {0, 0x1ff, 0x3fff, RGL_OPCODE_LIMIT, UINT32_MAX};
    for (size_t i = 0; i < sizeof bad_ops / sizeof bad_ops[0]; i++) {
        n = lead + put_var(buf + lead, bad_ops[i]);
        memset(buf + n, 0, 8);
        expect_error(n + 8, RGL_E_OPCODE, lead, 2, 0, "unknown opcode");
    }
    memcpy(buf + lead, "\x81\x00", 2); /* 1, written in two bytes */
    expect_error(lead + 2, RGL_E_VARINT, lead, 2, 0, "non-canonical opcode");
    memcpy(buf + lead, "\xff\xff\xff\xff\xff\xff\x01", 7);
    expect_error(lead + 7, RGL_E_VARINT, lead, 2, 0, "over-long opcode");
    memcpy(buf + lead, "\xff\xff", 2);
    expect_error(lead + 2, RGL_E_TRUNCATED, lead, 2, 0, "opcode cut short");

    /* An empty sequence and a NULL one just end. */
    static rgl_cmd cmd;
    rgl_cmd_iter it;
    rgl_cmd_iter_init(&it, NULL, 0, 0);
    CHECK(rgl_cmd_next(&it, &cmd) == RGL_END);
    printf("  commands: huge and over-limit counts, blobs, strings, bad opcodes; errors exact"
           " and sticky\n");
}

/* ---- Traces --------------------------------------------------------------- */

static uint8_t *big;

static size_t append_chunk(uint8_t *d, size_t size, uint8_t type, const void *payload,
                           uint32_t len)
{
    rgl_chunk_header_encode(d + size, type, len);
    if (len)
        memcpy(d + size + RGL_CHUNK_HEADER_SIZE, payload, len);
    rgl_put_u32(d + size + RGL_CHUNK_HEADER_SIZE + len,
                rgl_crc32c(0, d + size + RGL_CHUNK_HEADER_SIZE, len));
    return size + RGL_CHUNK_HEADER_SIZE + len + RGL_CHUNK_TRAILER_SIZE;
}

static size_t frame_payload(uint8_t *p, uint32_t number)
{
    size_t n = 0;
    n += put_var(p + n, 0);
    n += put_var(p + n, number);
    n += put_var(p + n, 0);
    n += put_var(p + n, 0);
    p[n++] = RGL_OP_End;
    return n;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void hostile_traces(void)
{
    rgl_reader *rd;
    rgl_error err;
    uint8_t fp[16];
    size_t size, good_end;

    /* A frame, then a chunk whose (CRC-valid) length runs past the end:
     * the recording stopped while writing it. Not closed, and the cut
     * chunk is its last write, not damage; nor is the start of a header. */
    uint64_t tail;
    rgl_file_header_encode(buf, 0);
    size = append_chunk(buf, RGL_FILE_HEADER_SIZE, RGL_CHUNK_FRAME, fp, (uint32_t)frame_payload(fp, 0));
    good_end = size;
    CHECK(rgl_reader_open_memory(buf, size, &rd, &err) == RGL_OK);
    CHECK(!rgl_reader_closed(rd, &tail) && tail == good_end && rgl_reader_damage_count(rd) == 0);
    rgl_reader_destroy(rd);
    rgl_chunk_header_encode(buf + size, RGL_CHUNK_FRAME, 5000);
    for (size_t cut = 1; cut <= RGL_CHUNK_HEADER_SIZE + 10; cut += cut < 20 ? 1 : 6) {
        CHECK(rgl_reader_open_memory(buf, good_end + cut, &rd, &err) == RGL_OK);
        CHECK(rgl_reader_frame_count(rd) == 1 && rgl_reader_damage_count(rd) == 0);
        CHECKF(!rgl_reader_closed(rd, &tail) && tail == good_end, "cut %zu: tail %llu", cut,
               (unsigned long long)tail);
        rgl_reader_destroy(rd);
    }
    /* Garbage at the end is damage, and the trace is not closed either. */
    memcpy(buf + good_end, "garbage!", 8);
    CHECK(rgl_reader_open_memory(buf, good_end + 8, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_damage_count(rd) == 1 && rgl_reader_damage(rd, 0)->offset == good_end);
    CHECK(!rgl_reader_closed(rd, &tail) && tail == good_end + 8);
    rgl_reader_destroy(rd);
    rgl_chunk_header_encode(buf + good_end, RGL_CHUNK_FRAME, 5000);
    size = good_end + RGL_CHUNK_HEADER_SIZE + 10;

    /* A CRC-valid header with a length over the limit, then a good frame. */
    rgl_chunk_header_encode(buf + good_end, RGL_CHUNK_FRAME, RGL_CHUNK_MAX_PAYLOAD + 1);
    size = append_chunk(buf, good_end + RGL_CHUNK_HEADER_SIZE, RGL_CHUNK_FRAME, fp,
                        (uint32_t)frame_payload(fp, 1));
    CHECK(rgl_reader_open_memory(buf, size, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_frame_count(rd) == 2 && rgl_reader_damage_count(rd) == 1);
    CHECK(rgl_reader_damage(rd, 0)->status == RGL_E_CHUNK &&
          rgl_reader_damage(rd, 0)->offset == good_end);
    rgl_reader_destroy(rd);

    /* A resource with id 0 and one with an id over the limit. */
    size = append_chunk(buf, good_end, RGL_CHUNK_RESOURCE, "\x00\x01zz", 4);
    size = append_chunk(buf, size, RGL_CHUNK_RESOURCE, "\x80\x80\x80\x80\x08\x01", 6);
    CHECK(rgl_reader_open_memory(buf, size, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_resource_count(rd) == 0 && rgl_reader_damage_count(rd) == 2);
    CHECK(rgl_reader_damage(rd, 0)->status == RGL_E_RESOURCE);
    rgl_reader_destroy(rd);

    /* An index claiming 2^60 frames: refused before any allocation. */
    uint8_t idx[16], endp[8];
    size_t n = put_var(idx, 1ull << 60);
    n += put_var(idx + n, 0);
    size = append_chunk(buf, good_end, RGL_CHUNK_INDEX, idx, (uint32_t)n);
    rgl_put_u64(endp, good_end);
    size = append_chunk(buf, size, RGL_CHUNK_END, endp, 8);
    CHECK(rgl_reader_open_memory(buf, size, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_frame_count(rd) == 1 && rgl_reader_damage_count(rd) == 0);
    rgl_reader_destroy(rd);
    /* An END pointing at itself. */
    rgl_put_u64(endp, size - 28);
    size = append_chunk(buf, size - 28, RGL_CHUNK_END, endp, 8);
    CHECK(rgl_reader_open_memory(buf, size, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_frame_count(rd) == 1);
    rgl_reader_destroy(rd);

    /* Megabytes of sync patterns with broken headers: one damaged region,
     * scanned in linear time. */
    size_t mb = 4u << 20;
    big = malloc(mb + 4096);
    rgl_file_header_encode(big, 0);
    for (size_t i = RGL_FILE_HEADER_SIZE; i + 4 <= mb; i += 4)
        memcpy(big + i, RGL_CHUNK_SYNC, 4);
    size = append_chunk(big, mb, RGL_CHUNK_FRAME, fp, (uint32_t)frame_payload(fp, 9));
    double t0 = now();
    CHECK(rgl_reader_open_memory(big, size, &rd, &err) == RGL_OK);
    double t1 = now() - t0;
    CHECK(rgl_reader_frame_count(rd) == 1 && rgl_reader_damage_count(rd) == 1);
    CHECKF(t1 < 5.0, "4 MiB of sync patterns took %.2f s", t1);
    rgl_reader_destroy(rd);
    printf("  4 MiB of sync patterns: one damaged region, frame after it found (%.3f s)\n", t1);

    /* Random bytes after a good header: bounded, damage listed at most 1024. */
    rng r = {77};
    for (size_t i = RGL_FILE_HEADER_SIZE; i < mb; i++)
        big[i] = (uint8_t)rng_next(&r);
    t0 = now();
    CHECK(rgl_reader_open_memory(big, mb, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_frame_count(rd) == 0 && rgl_reader_damage_count(rd) >= 1 &&
          rgl_reader_damage_count(rd) <= 1024);
    rgl_reader_destroy(rd);
    printf("  4 MiB of random bytes: opens, damage reported (%.3f s)\n", now() - t0);

    /* Many tiny chunks: empty chunks of an unknown type and empty frames. */
    size = RGL_FILE_HEADER_SIZE;
    size_t frames = 0;
    while (size + 64 < mb) {
        if (frames % 2)
            size = append_chunk(big, size, 99, NULL, 0);
        else
            size = append_chunk(big, size, RGL_CHUNK_FRAME, fp, (uint32_t)frame_payload(fp, 0));
        frames++;
    }
    t0 = now();
    CHECK(rgl_reader_open_memory(big, size, &rd, &err) == RGL_OK);
    CHECK(rgl_reader_frame_count(rd) == (frames + 1) / 2 && rgl_reader_damage_count(rd) == 0);
    rgl_frame_info fi;
    CHECK(rgl_reader_frame(rd, rgl_reader_frame_count(rd) - 1, &fi, &err) == RGL_OK);
    rgl_reader_destroy(rd);
    printf("  %zu tiny chunks (%zu frames): opened in %.3f s\n", frames, (frames + 1) / 2,
           now() - t0);
    free(big);
}

int main(void)
{
    hostile_commands();
    hostile_traces();
    return test_summary("test_hostile");
}
