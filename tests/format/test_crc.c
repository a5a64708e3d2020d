/* test_crc.c: CRC-32C against known vectors (RFC 3720 appendix B.4 and the
 * usual "123456789"), chaining, and the software and SSE4.2 paths agreeing
 * on random buffers at every alignment and many lengths.
 */
#include <stdlib.h>
#include "testutil.h"

typedef uint32_t (*crc_fn)(uint32_t, const void *, size_t);

static void vectors(const char *name, crc_fn crc)
{
    uint8_t buf[48];
    CHECKF(crc(0, "123456789", 9) == 0xE3069283u, "%s: 123456789", name);
    CHECK(crc(0, "", 0) == 0);
    CHECK(crc(0, NULL, 0) == 0);
    memset(buf, 0, 32);
    CHECKF(crc(0, buf, 32) == 0x8A9136AAu, "%s: 32 zeros", name);
    memset(buf, 0xff, 32);
    CHECKF(crc(0, buf, 32) == 0x62A8AB43u, "%s: 32 ones", name);
    for (int i = 0; i < 32; i++)
        buf[i] = (uint8_t)i;
    CHECKF(crc(0, buf, 32) == 0x46DD794Eu, "%s: incrementing", name);
    for (int i = 0; i < 32; i++)
        buf[i] = (uint8_t)(31 - i);
    CHECKF(crc(0, buf, 32) == 0x113FDB5Cu, "%s: decrementing", name);
    /* Chaining: the CRC of a whole equals the CRC continued over its parts. */
    CHECK(crc(crc(0, "1234", 4), "56789", 5) == 0xE3069283u);
}

int main(void)
{
    static uint8_t buf[4096 + 16];
    rng r = {42};

    vectors("rgl_crc32c", rgl_crc32c);
    vectors("rgl_crc32c_sw", rgl_crc32c_sw);
    vectors("rgl_crc32c_hw", rgl_crc32c_hw);
    printf("  vectors: 123456789, RFC 3720 B.4 (zeros, ones, up, down), chaining\n");

    for (size_t i = 0; i < sizeof buf; i++)
        buf[i] = (uint8_t)rng_next(&r);
    unsigned long compared = 0;
    for (size_t align = 0; align < 16; align++) {
        for (size_t len = 0; len <= 4096; len += (len < 80 ? 1 : 61)) {
            uint32_t seed = (uint32_t)rng_next(&r);
            uint32_t a = rgl_crc32c_sw(seed, buf + align, len);
            uint32_t b = rgl_crc32c_hw(seed, buf + align, len);
            CHECKF(a == b, "sw 0x%08lx != hw 0x%08lx at align %zu len %zu", (unsigned long)a,
                   (unsigned long)b, align, len);
            CHECK(rgl_crc32c(seed, buf + align, len) == a);
            compared++;
        }
    }
    /* Past three lanes the hw path interleaves three CRCs and joins them:
     * lengths around each multiple of the 3 KiB block, and a megabyte. */
    size_t big_n = (1u << 20) + 77;
    uint8_t *big = malloc(big_n + 8);
    CHECK(big != NULL);
    if (big) {
        for (size_t i = 0; i < big_n + 8; i++)
            big[i] = (uint8_t)rng_next(&r);
        static const size_t lens[] = {3071, 3072, 3073, 3080, 6143, 6144, 6151, 9216 + 5,
                                      65536, 100003};
        for (size_t align = 0; align < 8; align++) {
            for (size_t i = 0; i < sizeof lens / sizeof lens[0]; i++) {
                uint32_t seed = (uint32_t)rng_next(&r);
                uint32_t a = rgl_crc32c_sw(seed, big + align, lens[i]);
                uint32_t b = rgl_crc32c_hw(seed, big + align, lens[i]);
                CHECKF(a == b, "sw 0x%08lx != hw 0x%08lx at align %zu len %zu",
                       (unsigned long)a, (unsigned long)b, align, lens[i]);
                compared++;
            }
        }
        uint32_t a = rgl_crc32c_sw(0, big, big_n);
        CHECKF(a == rgl_crc32c_hw(0, big, big_n), "sw != hw over %zu bytes", big_n);
        /* Chaining across a lane boundary. */
        CHECK(rgl_crc32c_hw(rgl_crc32c_hw(0, big, 5000), big + 5000, big_n - 5000) == a);
        compared += 2;
        free(big);
    }
    printf("  sw and hw paths agree on %lu random buffers (hw %s on this CPU)\n", compared,
           rgl_crc32c_hw_available() ? "available" : "NOT available: fallback compared");
    return test_summary("test_crc");
}
