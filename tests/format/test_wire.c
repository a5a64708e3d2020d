/* test_wire.c: the primitive encodings of format/wire.h and their checks in
 * the decoder: varint edges, zigzag, over-long and oversized varints,
 * non-canonical varints, little-endian fixed fields, and float bit patterns
 * (NaN payloads, signalling NaN, infinities, -0, subnormals) kept exact.
 */
#include "testutil.h"

static size_t put_var(uint8_t *buf, uint64_t v) { return (size_t)(rgl_put_varint(buf, v) - buf); }

static void test_varint_edges(void)
{
    static const struct {
        uint64_t v;
        size_t len;
    } cases[] = {
        {0, 1}, {1, 1}, {127, 1}, {128, 2}, {16383, 2}, {16384, 3}, {(1u << 21) - 1, 3},
        {1u << 21, 4}, {(1u << 28) - 1, 4}, {1u << 28, 5}, {UINT32_MAX, 5},
        {(uint64_t)UINT32_MAX + 1, 5}, {UINT64_MAX >> 1, 9}, {UINT64_MAX, 10},
    };
    uint8_t buf[16];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t n = put_var(buf, cases[i].v);
        const uint8_t *p = buf;
        uint64_t back = 0;
        CHECKF(n == cases[i].len, "varint %llu: %zu bytes", (unsigned long long)cases[i].v, n);
        CHECK(rgl_get_varint(&p, buf + n, RGL_VARINT64_MAX, &back) == 0);
        CHECK(back == cases[i].v && p == buf + n);
        /* One byte short: truncated, and the position stays put. */
        p = buf;
        CHECK(rgl_get_varint(&p, buf + n - 1, RGL_VARINT64_MAX, &back) == -1 && p == buf);
    }
    /* Ten bytes whose last carries bits beyond 64. */
    memset(buf, 0xff, 9);
    buf[9] = 0x02;
    const uint8_t *p = buf;
    uint64_t v;
    CHECK(rgl_get_varint(&p, buf + 10, RGL_VARINT64_MAX, &v) == -2);
    /* Eleven bytes: longer than any varint. */
    memset(buf, 0x80, 10);
    buf[10] = 0;
    p = buf;
    CHECK(rgl_get_varint(&p, buf + 11, RGL_VARINT64_MAX, &v) == -2);
    printf("  varint edges: lengths at every 7-bit boundary, truncation, 64-bit overflow\n");
}

static void test_zigzag(void)
{
    static const int64_t vals[] = {0, -1, 1, -2, 2, INT32_MIN, INT32_MAX, INT64_MIN, INT64_MAX,
                                   -64, 63, -65, 64};
    static const uint64_t zz[] = {0, 1, 2, 3, 4, 0xffffffffull, 0xfffffffeull, UINT64_MAX,
                                  UINT64_MAX - 1, 127, 126, 129, 128};
    for (size_t i = 0; i < sizeof vals / sizeof vals[0]; i++) {
        CHECKF(rgl_zigzag(vals[i]) == zz[i], "zigzag(%lld)", (long long)vals[i]);
        CHECK(rgl_unzigzag(zz[i]) == vals[i]);
    }
    /* Every int32 zigzags into a uint32: the 5-byte limit holds for i and sz. */
    CHECK(rgl_zigzag(INT32_MIN) <= UINT32_MAX && rgl_zigzag(INT32_MAX) <= UINT32_MAX);
    printf("  zigzag: small values, int32 and int64 extremes\n");
}

static void test_fixed(void)
{
    uint8_t b[8];
    rgl_put_u16(b, 0x1234);
    CHECK(b[0] == 0x34 && b[1] == 0x12 && rgl_get_u16(b) == 0x1234);
    rgl_put_u32(b, 0x0A0B0C0Du);
    CHECK(b[0] == 0x0D && b[3] == 0x0A && rgl_get_u32(b) == 0x0A0B0C0Du);
    rgl_put_u64(b, 0x0102030405060708ull);
    CHECK(b[0] == 0x08 && b[7] == 0x01 && rgl_get_u64(b) == 0x0102030405060708ull);
    rgl_put_f(b, -6.0f);
    CHECK(rgl_get_u32(b) == RGL_SAMPLE_F32);
    printf("  fixed fields: little-endian u16/u32/u64, -6.0f is 0xC0C00000\n");
}

/* Decodes buf as one command; returns the status and the error. */
static rgl_status decode1(const uint8_t *buf, size_t n, rgl_cmd *cmd, rgl_error *err)
{
    rgl_cmd_iter it;
    rgl_status st;
    rgl_cmd_iter_init(&it, buf, n, 1000);
    st = rgl_cmd_next(&it, cmd);
    *err = it.error;
    return st;
}

static void test_decoder_varints(void)
{
    static rgl_cmd cmd;
    rgl_error err;
    uint8_t buf[32];
    size_t n;

    /* glColor3ui(UINT32_MAX, 0, 128): largest 5-byte value accepted. */
    n = 0;
    buf[n++] = RGL_OP_Color3ui;
    n += put_var(buf + n, UINT32_MAX);
    n += put_var(buf + n, 0);
    n += put_var(buf + n, 128);
    CHECK(decode1(buf, n, &cmd, &err) == RGL_OK);
    CHECK(cmd.arg[0].v.u == UINT32_MAX && cmd.arg[1].v.u == 0 && cmd.arg[2].v.u == 128);

    /* 2^32 in five bytes: too large for a 32-bit type. */
    n = 0;
    buf[n++] = RGL_OP_Color3ui;
    n += put_var(buf + n, (uint64_t)UINT32_MAX + 1);
    buf[n++] = 0;
    buf[n++] = 0;
    CHECK(decode1(buf, n, &cmd, &err) == RGL_E_VARINT);
    CHECK(err.offset == 1001 && err.opcode == RGL_OP_Color3ui && err.cmd_index == 0);

    /* Six bytes: longer than a 32-bit varint may be. */
    n = 0;
    buf[n++] = RGL_OP_Color3ui;
    memcpy(buf + n, "\x81\x80\x80\x80\x80\x00", 6);
    n += 6;
    buf[n++] = 0;
    buf[n++] = 0;
    CHECK(decode1(buf, n, &cmd, &err) == RGL_E_VARINT && err.offset == 1001);

    /* Non-canonical: 0 written as 0x80 0x00. */
    n = 0;
    buf[n++] = RGL_OP_Color3ui;
    buf[n++] = 0x80;
    buf[n++] = 0x00;
    buf[n++] = 0;
    buf[n++] = 0;
    CHECK(decode1(buf, n, &cmd, &err) == RGL_E_VARINT && err.offset == 1001);

    /* Truncated inside the second argument's varint. */
    n = 0;
    buf[n++] = RGL_OP_Color3ui;
    buf[n++] = 5;
    buf[n++] = 0x80;
    CHECK(decode1(buf, n, &cmd, &err) == RGL_E_TRUNCATED && err.offset == 1002);

    /* glVertex3i(INT32_MIN, INT32_MAX, -1): zigzag fits 5 bytes. */
    n = 0;
    buf[n++] = RGL_OP_Vertex3i;
    n += put_var(buf + n, rgl_zigzag(INT32_MIN));
    n += put_var(buf + n, rgl_zigzag(INT32_MAX));
    n += put_var(buf + n, rgl_zigzag(-1));
    CHECK(decode1(buf, n, &cmd, &err) == RGL_OK);
    CHECK(cmd.arg[0].v.i == INT32_MIN && cmd.arg[1].v.i == INT32_MAX && cmd.arg[2].v.i == -1);

    /* An opcode of two bytes, and one over RGL_OPCODE_LIMIT. */
    n = put_var(buf, RGL_OP_Viewport);
    CHECK(n == 2);
    memset(buf + n, 0, 4);
    CHECK(decode1(buf, n + 4, &cmd, &err) == RGL_OK && cmd.opcode == RGL_OP_Viewport);
    n = put_var(buf, RGL_OPCODE_LIMIT);
    CHECK(decode1(buf, n, &cmd, &err) == RGL_E_OPCODE && err.opcode == 0 && err.offset == 1000);
    printf("  decoder varints: 32-bit limit, over-long, non-canonical, truncated, opcodes\n");
}

static void test_float_bits(void)
{
    static const uint32_t pats[] = {0x00000000u, 0x80000000u, 0x7f800000u, 0xff800000u,
                                    0x7fc00000u, 0xffc00000u, 0x7fa00001u, 0x7f800001u,
                                    0xffffffffu, 0x00000001u, 0x807fffffu, 0x7f7fffffu};
    static const uint64_t dpats[] = {0x8000000000000000ull, 0x7ff0000000000001ull,
                                     0xfff8000000000abcull, 0x7ff0000000000000ull,
                                     0x0000000000000001ull};
    static rgl_cmd cmd, cmd2;
    rgl_error err;
    uint8_t buf[64], again[64];
    size_t n;

    for (size_t i = 0; i < sizeof pats / sizeof pats[0]; i++) {
        n = 0;
        buf[n++] = RGL_OP_Vertex3f;
        rgl_put_u32(buf + n, pats[i]);
        rgl_put_u32(buf + n + 4, pats[i] ^ 0x80000000u);
        rgl_put_u32(buf + n + 8, 0x3f800000u);
        n += 12;
        CHECK(decode1(buf, n, &cmd, &err) == RGL_OK);
        CHECK(rgl_cmd_encode(&cmd, again, sizeof again) == n);
        CHECKF(memcmp(buf, again, n) == 0, "float bits 0x%08lx do not survive decode+encode",
               (unsigned long)pats[i]);
        /* Through the array form too (elements become doubles in scratch). */
        rgl_cmd_init(&cmd2, RGL_OP_Vertex3fv);
        ((double *)cmd2.arg[0].array)[0] = cmd.arg[0].v.f;
        ((double *)cmd2.arg[0].array)[1] = cmd.arg[1].v.f;
        ((double *)cmd2.arg[0].array)[2] = cmd.arg[2].v.f;
        again[0] = 0;
        CHECK(rgl_cmd_encode(&cmd2, again, sizeof again) == n);
        CHECK(memcmp(buf + 1, again + 1, n - 1) == 0);
    }
    for (size_t i = 0; i < sizeof dpats / sizeof dpats[0]; i++) {
        n = put_var(buf, RGL_OP_ClearDepth); /* 0x92: a two-byte opcode */
        rgl_put_u64(buf + n, dpats[i]);
        n += 8;
        CHECK(decode1(buf, n, &cmd, &err) == RGL_OK);
        CHECK(rgl_f64_bits(cmd.arg[0].v.f) == dpats[i]);
        CHECK(rgl_cmd_encode(&cmd, again, sizeof again) == n && memcmp(buf, again, n) == 0);
    }
    /* A double no float can hold is refused, not silently made infinite. */
    rgl_cmd_init(&cmd, RGL_OP_PointSize);
    cmd.arg[0].v.f = 1e300;
    CHECK(rgl_cmd_encode(&cmd, again, sizeof again) == 0);
    cmd.arg[0].v.f = 0.1; /* rounds to the nearest float */
    CHECK(rgl_cmd_encode(&cmd, again, sizeof again) == 6 && rgl_get_u32(again + 2) == 0x3dcccccdu);
    printf("  float bits: +-0, +-inf, quiet/signalling NaN payloads, subnormals, exact round trip\n");
}

int main(void)
{
    test_varint_edges();
    test_zigzag();
    test_fixed();
    test_decoder_varints();
    test_float_bits();
    return test_summary("test_wire");
}
