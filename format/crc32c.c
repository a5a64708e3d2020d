/* crc32c.c: CRC-32C (Castagnoli), the checksum of every header and chunk.
 *
 * Two implementations with one result: a portable slicing-by-8 one over
 * tables computed once (pthread_once), and one using the SSE4.2 crc32
 * instruction, chosen at run time when the CPU has it. The instruction's
 * latency is three times its throughput, so on long buffers the SSE4.2 path
 * runs three independent CRCs over three adjacent lanes and joins them
 * (the recorder checksums each frame, megabytes, at every frame end). The polynomial is
 * 0x1EDC6F41, reflected 0x82F63B78; the register starts at ~0 and the result
 * is inverted, so crc32c("123456789") = 0xE3069283.
 */
#include <pthread.h>
#include <string.h>

#include "format.h"

#define CRC32C_POLY_REFLECTED 0x82F63B78u

/* Bytes in each of the three lanes of crc32c_sse42's interleaved loop. */
#define CRC_LANE 1024

static uint32_t crc_table[8][256];
/* crc_shift[k][b]: the register (no inversions) byte b at position k turns
 * into after CRC_LANE zero bytes. The register of A||B is then shift(the
 * register after A) ^ (the register of B started from 0): CRC is linear. */
static uint32_t crc_shift[4][256];
static pthread_once_t crc_table_once = PTHREAD_ONCE_INIT;

static void crc_table_build(void)
{
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = n;
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (CRC32C_POLY_REFLECTED & (0u - (c & 1u)));
        crc_table[0][n] = c;
    }
    /* Table k advances a byte's contribution by k more zero bytes. */
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = crc_table[0][n];
        for (int k = 1; k < 8; k++) {
            c = crc_table[0][c & 0xff] ^ (c >> 8);
            crc_table[k][n] = c;
        }
    }
    uint32_t bit[32];
    for (int b = 0; b < 32; b++) {
        uint32_t c = 1u << b;
        for (int n = 0; n < CRC_LANE; n++)
            c = crc_table[0][c & 0xff] ^ (c >> 8);
        bit[b] = c;
    }
    for (int k = 0; k < 4; k++) {
        for (uint32_t n = 0; n < 256; n++) {
            uint32_t c = 0;
            for (int b = 0; b < 8; b++)
                if (n & (1u << b))
                    c ^= bit[8 * k + b];
            crc_shift[k][n] = c;
        }
    }
}

static inline uint32_t crc_shift_lane(uint32_t c)
{
    return crc_shift[0][c & 0xff] ^ crc_shift[1][(c >> 8) & 0xff] ^
           crc_shift[2][(c >> 16) & 0xff] ^ crc_shift[3][c >> 24];
}

static inline uint64_t load_le64(const uint8_t *p)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--)
        v = (v << 8) | p[i];
    return v;
}

uint32_t rgl_crc32c_sw(uint32_t crc, const void *data, size_t size)
{
    const uint8_t *p = data;
    uint32_t c = ~crc;

    pthread_once(&crc_table_once, crc_table_build);
    while (size && ((uintptr_t)p & 7)) {
        c = crc_table[0][(c ^ *p++) & 0xff] ^ (c >> 8);
        size--;
    }
    while (size >= 8) {
        uint64_t w = load_le64(p) ^ c;
        c = crc_table[7][w & 0xff] ^ crc_table[6][(w >> 8) & 0xff] ^
            crc_table[5][(w >> 16) & 0xff] ^ crc_table[4][(w >> 24) & 0xff] ^
            crc_table[3][(w >> 32) & 0xff] ^ crc_table[2][(w >> 40) & 0xff] ^
            crc_table[1][(w >> 48) & 0xff] ^ crc_table[0][w >> 56];
        p += 8;
        size -= 8;
    }
    while (size--)
        c = crc_table[0][(c ^ *p++) & 0xff] ^ (c >> 8);
    return ~c;
}

#if defined(__x86_64__) && defined(__GNUC__)

/* The crc32 instruction computes the same reflected CRC-32C step. memcpy
 * keeps the unaligned loads defined. */
__attribute__((target("sse4.2"))) static uint32_t crc32c_sse42(uint32_t crc, const uint8_t *p,
                                                                  size_t size)
{
    uint64_t c = ~crc;
    while (size && ((uintptr_t)p & 7)) {
        c = __builtin_ia32_crc32qi((uint32_t)c, *p++);
        size--;
    }
    if (size >= 3 * CRC_LANE)
        pthread_once(&crc_table_once, crc_table_build);
    while (size >= 3 * CRC_LANE) {
        uint64_t b = 0, d = 0;
        for (size_t i = 0; i < CRC_LANE; i += 8) {
            uint64_t x, y, z;
            memcpy(&x, p + i, 8);
            memcpy(&y, p + CRC_LANE + i, 8);
            memcpy(&z, p + 2 * CRC_LANE + i, 8);
            c = __builtin_ia32_crc32di(c, x);
            b = __builtin_ia32_crc32di(b, y);
            d = __builtin_ia32_crc32di(d, z);
        }
        c = crc_shift_lane(crc_shift_lane((uint32_t)c) ^ (uint32_t)b) ^ (uint32_t)d;
        p += 3 * CRC_LANE;
        size -= 3 * CRC_LANE;
    }
    while (size >= 8) {
        uint64_t w;
        memcpy(&w, p, 8);
        c = __builtin_ia32_crc32di(c, w);
        p += 8;
        size -= 8;
    }
    while (size--)
        c = __builtin_ia32_crc32qi((uint32_t)c, *p++);
    return ~(uint32_t)c;
}

bool rgl_crc32c_hw_available(void)
{
    return __builtin_cpu_supports("sse4.2");
}

uint32_t rgl_crc32c_hw(uint32_t crc, const void *data, size_t size)
{
    if (!rgl_crc32c_hw_available())
        return rgl_crc32c_sw(crc, data, size);
    return crc32c_sse42(crc, data, size);
}

uint32_t rgl_crc32c(uint32_t crc, const void *data, size_t size)
{
    if (rgl_crc32c_hw_available())
        return crc32c_sse42(crc, data, size);
    return rgl_crc32c_sw(crc, data, size);
}

#else

bool rgl_crc32c_hw_available(void) { return false; }

uint32_t rgl_crc32c_hw(uint32_t crc, const void *data, size_t size)
{
    return rgl_crc32c_sw(crc, data, size);
}

uint32_t rgl_crc32c(uint32_t crc, const void *data, size_t size)
{
    return rgl_crc32c_sw(crc, data, size);
}

#endif
