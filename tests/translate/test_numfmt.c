/* test_numfmt.c: the float formatter reads back exactly, is shortest and
 * closest, and ignores the locale.
 *
 * Every 1283rd float bit pattern (3.3 million values, all exponents, both
 * signs, subnormals), and every power of two and its neighbours, must read
 * back through strtof to the same float, use no more significant digits than
 * the shortest %.*e that does, and be the closest decimal of its length that
 * reads back (printf rounds exactly), on an exact tie the one away from zero.
 */
#include <locale.h>
#include <stdbool.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "numfmt.h"

static int sig_digits(const char *s)
{
    int n = 0, last = 0, started = 0;
    for (; *s && *s != 'e'; s++) {
        if (*s < '0' || *s > '9')
            continue;
        if (*s != '0')
            started = 1;
        if (started) {
            n++;
            if (*s != '0')
                last = n;
        }
    }
    return last;
}

/* The shortest %.*e that reads back as f, into b; its digit count. */
static int shortest_ref(float f, char *b, size_t size)
{
    for (int p = 1; p <= 9; p++) {
        snprintf(b, size, "%.*e", p - 1, (double)f);
        if (strtof(b, NULL) == f)
            return p;
    }
    return 99;
}

/* f lies exactly halfway between two decimals of p significant digits:
 * its exact expansion (a float has at most 112 significant digits; 100
 * suffice for the normal ones that can tie) is a 5 at digit p + 1, then
 * zeros. */
static int exact_tie(float f, int p)
{
    char b[160];
    snprintf(b, sizeof b, "%.100e", fabs((double)f));
    char *e = strchr(b, 'e');
    int digit = 0;
    for (char *c = b; c < e; c++) {
        if (*c == '.')
            continue;
        digit++;
        if (digit == p + 1 && *c != '5')
            return 0;
        if (digit > p + 1 && *c != '0')
            return 0;
    }
    return 1;
}

static void fmt(float f, char *out)
{
    char buf[NUMFMT_F32_ROOM + 1];
    size_t n = numfmt_f32(buf, f);
    memcpy(out, buf, n);
    out[n] = '\0';
}

static void test_sweep(void)
{
    unsigned long bad = 0, longer = 0, farther = 0, n = 0;
    /* The sweep, then every power of two (the float below is half as far:
     * a narrower interval below) and both neighbours of each. */
    const uint32_t nsweep = (uint32_t)(0xffffffffu / 1283 + 1);
    for (uint32_t i = 0; i < nsweep + 3 * 254; i++) {
        uint32_t b = i < nsweep ? i * 1283 : (((i - nsweep) / 3 + 1) << 23) + (i - nsweep) % 3 - 1;
        float f;
        memcpy(&f, &b, 4);
        if (f != f || f - f != 0)
            continue;
        char s[64];
        fmt(f, s);
        n++;
        if (strlen(s) > NUMFMT_F32_MAX && bad++ < 5)
            fprintf(stderr, "0x%08x -> %s is longer than NUMFMT_F32_MAX\n", b, s);
        if (strtof(s, NULL) != f) {
            if (bad++ < 5)
                fprintf(stderr, "0x%08x (%.9g) -> %s does not read back\n", b, (double)f, s);
            continue;
        }
        if (f == 0)
            continue;
        char ref[64];
        int q = sig_digits(s);
        if (q > shortest_ref(f, ref, sizeof ref)) {
            if (longer++ < 5)
                fprintf(stderr, "0x%08x (%.9g) -> %s is not the shortest\n", b, (double)f, s);
            continue;
        }
        /* Of its length, the closest (printf's rounding) unless that one
         * falls outside the interval (a power of two's is narrower below);
         * on an exact tie the one away from zero. */
        snprintf(ref, sizeof ref, "%.*e", q - 1, (double)f);
        double mine = strtod(s, NULL);
        bool ok = exact_tie(f, q) ? fabs(mine) > fabs((double)f)
                                  : mine == strtod(ref, NULL) || strtof(ref, NULL) != f;
        if (!ok && farther++ < 5)
            fprintf(stderr, "0x%08x (%.9g) -> %s, the closest is %s\n", b, (double)f, s, ref);
    }
    printf("numfmt: %lu floats, %lu do not read back, %lu not shortest, %lu not closest\n", n,
           bad, longer, farther);
    CHECK(bad == 0);
    CHECK(longer == 0);
    CHECK(farther == 0);
    CHECK(n > 3330000);
}

static void test_cases(void)
{
    static const struct {
        float f;
        const char *s;
    } cases[] = {
        {0.5f, "0.5"},       {0.1f, "0.1"},         {45, "45"},
        {-0.0f, "0"},        {0, "0"},              {1e-7f, "1e-7"},
        {1e10f, "1e10"},     {1e6f, "1e6"},         {100000, "100000"},
        {0.853553f, "0.853553"}, {-0.146447f, "-0.146447"}, {0.00001f, "0.00001"},
        {3.4028235e38f, "3.4028235e38"}, {1.4e-45f, "1e-45"}, {16777216.0f, "16777216"},
        {2.0f / 3, "0.6666667"}, {123456.7f, "123456.7"}, {-2.5e-12f, "-2.5e-12"},
        /* the longest fixed forms (a fuzz find: the writer's cache held 16) */
        {-1.07363935e15f, "-1073639350000000"}, {-1.00000057e-6f, "-0.0000010000006"},
        /* exact ties between the two closest shortest: away from zero */
        {2097152.25f, "2097152.3"}, {-2097153.75f, "-2097153.8"}, {0.0185546875f, "0.018554688"},
        /* powers of two (the float below is half as far), the largest and
         * smallest normal, the first integer past 2^24 */
        {0x1p-20f, "9.536743e-7"}, {0x1p100f, "1.2676506e30"}, {0x1p-126f, "1.1754944e-38"},
        {0x1p-125f, "2.3509887e-38"}, {0x1p127f, "1.7014118e38"}, {16777218.0f, "16777218"},
        {0.3f, "0.3"}, {1e-5f, "0.00001"}, {1.5e-6f, "0.0000015"}, {1e-6f, "1e-6"},
        {9.9999e-7f, "9.9999e-7"}, {123456789.0f, "123456790"}, {1e9f, "1e9"},
        {4.5e9f, "4.5e9"}, {0x1p45f, "35184372000000"}, {0x1p56f, "7.2057594e16"},
        /* an interval end on a short decimal: in it for an even mantissa only */
        {33554932.0f, "33554932"}, {33554948.0f, "33554948"}, {33554928.0f, "33554930"}, {1234567e3f, "1234567000"}, {8.589973e9f, "8589974000"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char s[64];
        fmt(cases[i].f, s);
        if (strcmp(s, cases[i].s) != 0) {
            fprintf(stderr, "%.9g -> %s, expected %s\n", (double)cases[i].f, s, cases[i].s);
            check_failures++;
        }
    }
    char s[64];
    fmt(NAN, s);
    CHECK(strcmp(s, "0") == 0);
    fmt(-INFINITY, s);
    CHECK(strcmp(s, "0") == 0);
    char b[32];
    b[numfmt_u64(b, 18446744073709551615ull)] = '\0';
    CHECK(strcmp(b, "18446744073709551615") == 0);
    b[numfmt_i64(b, INT64_MIN)] = '\0';
    CHECK(strcmp(b, "-9223372036854775808") == 0);
    b[numfmt_u64(b, 0)] = '\0';
    CHECK(strcmp(b, "0") == 0);
    for (uint64_t v = 0; v < 3000000; v += (v < 20000 ? 1 : 7)) {
        char want[32];
        snprintf(want, sizeof want, "%llu", (unsigned long long)v);
        b[numfmt_u64(b, v)] = '\0';
        if (strcmp(b, want) != 0 && check_failures++ < 5)
            fprintf(stderr, "numfmt_u64(%s) = %s\n", want, b);
    }
}

/* With a comma-decimal locale active, the text stays the same. The test
 * script generates de_DE.UTF-8 with localedef and sets LOCPATH; without it
 * the test reports a skip (77) rather than passing blindly. */
static int test_locale(void)
{
    if (!setlocale(LC_ALL, "de_DE.UTF-8") && !setlocale(LC_ALL, "de_DE.utf8"))
        return 77;
    char probe[32];
    snprintf(probe, sizeof probe, "%.1f", 0.5);
    CHECK(strcmp(probe, "0,5") == 0); /* the locale really is comma-decimal */
    char s[64];
    fmt(0.5f, s);
    CHECK(strcmp(s, "0.5") == 0);
    fmt(-1234.5f, s);
    CHECK(strcmp(s, "-1234.5") == 0);
    setlocale(LC_ALL, "C");
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "--locale") == 0) {
        int rc = test_locale();
        if (rc == 77) {
            fprintf(stderr, "test_numfmt: no de_DE locale available\n");
            return 77;
        }
        return CHECK_RESULT("test_numfmt --locale");
    }
    test_cases();
    test_sweep();
    return CHECK_RESULT("test_numfmt");
}
