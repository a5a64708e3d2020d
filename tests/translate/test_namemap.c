/* test_namemap.c: the name -> index hash of the interpreter's tables.
 *
 * Random puts, gets and deletions (with names that collide in their low
 * bits, and in long runs) against a plain array; copies and clears; and
 * 10^5 names put in decreasing order then each looked up, in linear time
 * (the display-list table was a sorted array: inserting in that order
 * moved O(n^2) bytes).
 */
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "namemap.h"

#define N 4096

static uint64_t rng = 0x243F6A8885A308D3ull;
static uint32_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)rng;
}

static int64_t model[N]; /* name k (1..N-1) -> index, or -1 */

static void check_all(const namemap *m, const char *when)
{
    size_t n = 0;
    for (uint32_t k = 1; k < N; k++) {
        uint32_t name = k * 65536u; /* equal low bits */
        int64_t got = namemap_get(m, name);
        if (got != model[k]) {
            fprintf(stderr, "%s: name %u: %lld, expected %lld\n", when, name, (long long)got,
                    (long long)model[k]);
            check_failures++;
            return;
        }
        n += model[k] >= 0;
    }
    CHECK_EQ_U(m->n, n);
}

int main(void)
{
    namemap m, c;
    namemap_init(&m);
    namemap_init(&c);
    CHECK(namemap_get(&m, 5) == -1);
    namemap_del(&m, 5);
    CHECK(namemap_put(&m, 0, 1) == -1); /* 0 is no name */
    for (uint32_t k = 0; k < N; k++)
        model[k] = -1;
    for (int round = 0; round < 200000; round++) {
        uint32_t k = 1 + next() % (N - 1), op = next() % 3;
        uint32_t name = k * 65536u;
        if (op < 2) {
            uint32_t v = next();
            CHECK(namemap_put(&m, name, v) == 0);
            model[k] = v;
        } else {
            namemap_del(&m, name);
            model[k] = -1;
        }
        if (round % 20000 == 0)
            check_all(&m, "random");
    }
    check_all(&m, "random, end");
    CHECK(namemap_copy(&c, &m) == 0);
    check_all(&c, "copy");
    namemap_clear(&m);
    CHECK(m.n == 0 && namemap_get(&m, 65536u) == -1);
    namemap_finish(&m);
    namemap_finish(&c);

    clock_t t0 = clock();
    namemap_init(&m);
    for (uint32_t name = 100000; name > 0; name--)
        CHECK(namemap_put(&m, name, name + 1) == 0);
    uint64_t sum = 0;
    for (int rep = 0; rep < 10; rep++)
        for (uint32_t name = 1; name <= 100000; name++)
            sum += (uint64_t)namemap_get(&m, name);
    for (uint32_t name = 1; name <= 100000; name += 2)
        namemap_del(&m, name);
    CHECK(m.n == 50000 && namemap_get(&m, 1) == -1 && namemap_get(&m, 2) == 3);
    double s = (double)(clock() - t0) / CLOCKS_PER_SEC;
    CHECK_EQ_U(sum, 10 * (100000ull * 100001 / 2 + 100000));
    CHECK(s < 2.0);
    printf("  10^5 names in decreasing order, 10^6 lookups, 5 x 10^4 deletions: %.3f s\n", s);
    namemap_finish(&m);
    return CHECK_RESULT("test_namemap");
}
