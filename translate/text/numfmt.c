/* numfmt.c: shortest round-trip formatting of floats, and integers.
 *
 * A float v = m * 2^e2 rounds back from any decimal inside its rounding
 * interval [v - gap_below/2, v + gap_above/2] (ends included when m is
 * even, as round-half-even does). Scaled by 10^(8-E) (E = floor(log10 v))
 * the interval holds the nine-digit integers [a, b] that read back to v;
 * the shortest decimal is the one of them with the most trailing zeros,
 * and of those the one closest to v. The scaling is done in double: every
 * float and both interval ends are exact doubles, and the product is off by
 * at most about 2^-52 relatively, far below the interval's half-width of
 * about 2^-25. Only when an interval end lies within that error of an
 * integer (or for subnormals) does the general search decide, with an
 * exact big-integer comparison. tests/translate/test_numfmt.c checks the
 * round trip and shortness against strtof over 1.4 million floats of every
 * exponent; all 4.3 billion were checked once (see docs/mapping.md).
 */
#include "numfmt.h"

#include <stdbool.h>
#include <string.h>

/* 10^j for j in [-60, 60] at p10[j + 60], correctly rounded by the compiler. */
static const double p10[121] = {
    1e-60, 1e-59, 1e-58, 1e-57, 1e-56, 1e-55, 1e-54, 1e-53, 1e-52, 1e-51,
    1e-50, 1e-49, 1e-48, 1e-47, 1e-46, 1e-45, 1e-44, 1e-43, 1e-42, 1e-41,
    1e-40, 1e-39, 1e-38, 1e-37, 1e-36, 1e-35, 1e-34, 1e-33, 1e-32, 1e-31,
    1e-30, 1e-29, 1e-28, 1e-27, 1e-26, 1e-25, 1e-24, 1e-23, 1e-22, 1e-21,
    1e-20, 1e-19, 1e-18, 1e-17, 1e-16, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11,
    1e-10, 1e-9,  1e-8,  1e-7,  1e-6,  1e-5,  1e-4,  1e-3,  1e-2,  1e-1,
    1e0,   1e1,   1e2,   1e3,   1e4,   1e5,   1e6,   1e7,   1e8,   1e9,
    1e10,  1e11,  1e12,  1e13,  1e14,  1e15,  1e16,  1e17,  1e18,  1e19,
    1e20,  1e21,  1e22,  1e23,  1e24,  1e25,  1e26,  1e27,  1e28,  1e29,
    1e30,  1e31,  1e32,  1e33,  1e34,  1e35,  1e36,  1e37,  1e38,  1e39,
    1e40,  1e41,  1e42,  1e43,  1e44,  1e45,  1e46,  1e47,  1e48,  1e49,
    1e50,  1e51,  1e52,  1e53,  1e54,  1e55,  1e56,  1e57,  1e58,  1e59, 1e60,
};

/* 10^j; float inputs keep j within [-60, 60]. */
static inline double pow10d(int j) { return p10[j + 60]; }

/* ---- Exact comparison through small big integers ------------------------ */

#define BN_LIMBS 24 /* 768 bits: d * 5^60 * 2^300 at most */

typedef struct bn {
    uint32_t n; /* limbs in use */
    uint32_t l[BN_LIMBS];
} bn;

static void bn_set(bn *b, uint64_t v)
{
    b->l[0] = (uint32_t)v;
    b->l[1] = (uint32_t)(v >> 32);
    b->n = b->l[1] ? 2 : (b->l[0] ? 1 : 0);
}

static void bn_mul_small(bn *b, uint32_t f)
{
    uint64_t carry = 0;
    for (uint32_t i = 0; i < b->n; i++) {
        uint64_t t = (uint64_t)b->l[i] * f + carry;
        b->l[i] = (uint32_t)t;
        carry = t >> 32;
    }
    if (carry && b->n < BN_LIMBS)
        b->l[b->n++] = (uint32_t)carry;
}

static void bn_mul_pow5(bn *b, int k)
{
    while (k >= 13) {
        bn_mul_small(b, 1220703125u); /* 5^13 */
        k -= 13;
    }
    static const uint32_t p5[13] = {1, 5, 25, 125, 625, 3125, 15625, 78125, 390625,
                                    1953125, 9765625, 48828125, 244140625};
    if (k > 0)
        bn_mul_small(b, p5[k]);
}

static void bn_shl(bn *b, int s)
{
    int words = s / 32, bits = s % 32;
    if (b->n == 0 || s == 0)
        return;
    if (b->n + (uint32_t)words + 1 > BN_LIMBS)
        words = BN_LIMBS - (int)b->n - 1; /* cannot happen for float inputs */
    uint32_t n = b->n + (uint32_t)words + 1;
    for (int i = (int)n - 1; i >= 0; i--) {
        int src = i - words;
        uint32_t hi = src >= 0 && src < (int)b->n ? b->l[src] : 0;
        uint32_t lo = src - 1 >= 0 && src - 1 < (int)b->n ? b->l[src - 1] : 0;
        b->l[i] = bits ? (hi << bits) | (lo >> (32 - bits)) : hi;
    }
    b->n = n;
    while (b->n && b->l[b->n - 1] == 0)
        b->n--;
}

static int bn_cmp(const bn *a, const bn *b)
{
    if (a->n != b->n)
        return a->n < b->n ? -1 : 1;
    for (int i = (int)a->n - 1; i >= 0; i--)
        if (a->l[i] != b->l[i])
            return a->l[i] < b->l[i] ? -1 : 1;
    return 0;
}

/* Sign of d * 10^k - n * 2^e, exactly. */
static int cmp_dec_bin(uint64_t d, int k, uint64_t n, int e)
{
    bn a, r;
    int ta = k, tr = e;
    bn_set(&a, d);
    bn_set(&r, n);
    if (k >= 0)
        bn_mul_pow5(&a, k);
    else
        bn_mul_pow5(&r, -k);
    if (ta > tr)
        bn_shl(&a, ta - tr);
    else
        bn_shl(&r, tr - ta);
    return bn_cmp(&a, &r);
}

/* ---- The search ---------------------------------------------------------- */

typedef struct fparts {
    double v, lo, hi;     /* value and rounding interval, exact doubles */
    uint64_t nlo, nhi;    /* the interval ends as n * 2^e2q */
    int e2q;
    bool inclusive;       /* ends belong to the interval (m even) */
    int E;                /* floor(log10 v), or one less in rare cases */
} fparts;

/* d * 10^k >= lo (or > lo when the ends are excluded), exactly. */
static bool exact_above_lo(const fparts *f, uint64_t d, int k)
{
    int c = cmp_dec_bin(d, k, f->nlo, f->e2q);
    return c > 0 || (c == 0 && f->inclusive);
}

/* d * 10^k <= hi (or < hi), exactly. */
static bool exact_below_hi(const fparts *f, uint64_t d, int k)
{
    int c = cmp_dec_bin(d, k, f->nhi, f->e2q);
    return c < 0 || (c == 0 && f->inclusive);
}

/* Finds the shortest decimal in the interval, searching among the p-digit
 * integers d * 10^k (k = E - p + 1) for the one with the most trailing
 * zeros, closest to v. Returns false when no p-digit integer fits (only when
 * E came out one too high). */
static inline bool shortest(const fparts *f, int p, uint64_t *dout, int *kout)
{
    int k = f->E - p + 1;
    double sc = pow10d(-k);
    double slo = f->lo * sc, shi = f->hi * sc, s = f->v * sc;
    double eps = s * 0x1p-46; /* far above the scaling error */
    /* Values are positive and below 2^60: signed truncation floors. */
    int64_t a = (int64_t)slo, b = (int64_t)shi;
    if ((double)a < slo)
        a++;

    /* The admissible integers are [a, b]; settle the ends exactly when the
     * scaled interval ends lie within rounding error of an integer. */
    if ((double)a - slo <= eps) {
        if (!exact_above_lo(f, (uint64_t)a, k))
            a++;
    } else if (a > 1 && slo - (double)(a - 1) <= eps && exact_above_lo(f, (uint64_t)a - 1, k)) {
        a--;
    }
    if (shi - (double)b <= eps) {
        if (b > 0 && !exact_below_hi(f, (uint64_t)b, k))
            b--;
    } else if ((double)(b + 1) - shi <= eps && exact_below_hi(f, (uint64_t)b + 1, k)) {
        b++;
    }
    if (a > b || a == 0)
        return false;

    /* Most trailing zeros: drop digits while [a, b] still holds a multiple
     * of ten (divisions by the constant 10 compile to multiplications). */
    int t = 0;
    if (b < (1ll << 32)) {
        uint32_t a32 = (uint32_t)a, b32 = (uint32_t)b;
        for (;;) {
            uint32_t a10 = (a32 + 9) / 10, b10 = b32 / 10;
            if (a10 > b10)
                break;
            a32 = a10;
            b32 = b10;
            t++;
        }
        a = a32;
        b = b32;
    } else {
        for (;;) {
            int64_t a10 = (a + 9) / 10, b10 = b / 10;
            if (a10 > b10)
                break;
            a = a10;
            b = b10;
            t++;
        }
    }
    int64_t d = (int64_t)(s * pow10d(-t) + 0.5);
    if (d < a)
        d = a;
    if (d > b)
        d = b;
    *dout = (uint64_t)d;
    *kout = k + t;
    return true;
}

static const char digit_pairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

static unsigned count_digits(uint64_t v)
{
    unsigned n = 1;
    while (v >= 100000000) {
        v /= 100000000;
        n += 8;
    }
    return n + (v >= 10) + (v >= 100) + (v >= 1000) + (v >= 10000) + (v >= 100000) +
           (v >= 1000000) + (v >= 10000000);
}

/* The n digits of v, most significant first, into out[0..n). */
static void fill_digits(char *out, uint64_t v, unsigned n)
{
    char *p = out + n;
    while (v >= (1ull << 32)) {
        unsigned r = (unsigned)(v % 100);
        v /= 100;
        p -= 2;
        memcpy(p, digit_pairs + 2 * r, 2);
    }
    uint32_t w = (uint32_t)v; /* 32-bit divisions are cheaper */
    while (w >= 100) {
        unsigned r = w % 100;
        w /= 100;
        p -= 2;
        memcpy(p, digit_pairs + 2 * r, 2);
    }
    if (w >= 10) {
        p -= 2;
        memcpy(p, digit_pairs + 2 * w, 2);
    } else {
        p[-1] = (char)('0' + w);
    }
}

/* Up to six digits (mesh indices mostly), without loops. */
static size_t put_small(char *out, uint32_t v)
{
    if (v < 100) {
        if (v < 10) {
            out[0] = (char)('0' + v);
            return 1;
        }
        memcpy(out, digit_pairs + 2 * v, 2);
        return 2;
    }
    if (v < 10000) {
        uint32_t hi = v / 100, lo = v % 100;
        if (hi < 10) {
            out[0] = (char)('0' + hi);
            memcpy(out + 1, digit_pairs + 2 * lo, 2);
            return 3;
        }
        memcpy(out, digit_pairs + 2 * hi, 2);
        memcpy(out + 2, digit_pairs + 2 * lo, 2);
        return 4;
    }
    uint32_t hi = v / 10000, mid = v / 100 % 100, lo = v % 100;
    size_t n = 0;
    if (hi < 10) {
        out[n++] = (char)('0' + hi);
    } else {
        memcpy(out, digit_pairs + 2 * hi, 2);
        n = 2;
    }
    memcpy(out + n, digit_pairs + 2 * mid, 2);
    memcpy(out + n + 2, digit_pairs + 2 * lo, 2);
    return n + 4;
}

size_t numfmt_u64(char *out, uint64_t v)
{
    if (v < 1000000)
        return put_small(out, (uint32_t)v);
    unsigned n = count_digits(v);
    fill_digits(out, v, n);
    return n;
}

size_t numfmt_i64(char *out, int64_t v)
{
    if (v < 0) {
        out[0] = '-';
        return 1 + numfmt_u64(out + 1, (uint64_t)0 - (uint64_t)v);
    }
    return numfmt_u64(out, (uint64_t)v);
}

/* Writes d * 10^k (0 < d < 10^17) in fixed or scientific notation. Copies
 * are fixed-size (16 bytes) so they compile to plain moves; out has
 * NUMFMT_F32_ROOM bytes. */
static size_t put_decimal(char *out, uint64_t d, int k)
{
    char dig[40];
    while (d % 10 == 0) {
        d /= 10;
        k++;
    }
    int n = (int)count_digits(d);
    fill_digits(dig, d, (unsigned)n);
    int x = k + n - 1; /* exponent of the first digit */
    int fixed_len = x >= n - 1 ? x + 1 : (x >= 0 ? n + 1 : n + 1 - x);
    int ax = x < 0 ? -x : x;
    int sci_len = n + (n > 1) + 1 + (x < 0) + (ax >= 10 ? 2 : 1);

    if (fixed_len <= sci_len + 3) {
        if (x >= n - 1) { /* an integer: digits, then zeros (at most 16 in all) */
            memset(dig + n, '0', 24);
            memcpy(out, dig, 16);
        } else if (x >= 0) { /* d.ddd */
            memcpy(out, dig, 16);
            out[x + 1] = '.';
            memcpy(out + x + 2, dig + x + 1, 16);
        } else { /* 0.000ddd: at most 5 zeros after the point get here */
            memcpy(out, "0.00000000", 8);
            memcpy(out - x + 1, dig, 16);
        }
        return (size_t)fixed_len;
    }
    char *p = out;
    *p++ = dig[0];
    if (n > 1) {
        *p++ = '.';
        memcpy(p, dig + 1, 16);
        p += n - 1;
    }
    *p++ = 'e';
    if (x < 0)
        *p++ = '-';
    if (ax >= 10) {
        memcpy(p, digit_pairs + 2 * ax, 2);
        p += 2;
    } else {
        *p++ = (char)('0' + ax);
    }
    return (size_t)(p - out);
}

static const uint32_t pow10_u32[10] = {1,      10,      100,      1000,      10000,
                                       100000, 1000000, 10000000, 100000000, 1000000000};

/* The eight digits of v < 10^8 as ASCII in one word, the first digit in
 * the lowest byte: v splits into two halves of four digits, each into two
 * pairs, each into two digits, every lane at once (x / 100 = x * 5243 >> 19
 * for x < 10^4, x / 10 = x * 103 >> 10 for x < 100). */
static inline uint64_t digits8(uint32_t v)
{
    uint64_t w = v / 10000 | (uint64_t)(v % 10000) << 32;
    uint64_t q = (w * 5243 >> 19) & 0x0000007f0000007full;
    w = q | (w - q * 100) << 16;
    q = (w * 103 >> 10) & 0x000f000f000f000full;
    w = q | (w - q * 10) << 8;
    return w | 0x3030303030303030ull;
}

/* d (n significant digits, n <= 9, d < 10^9) times 10^(x - n + 1), in fixed
 * notation when that is no more than three characters longer than
 * scientific; else 0 (the caller takes put_decimal). The digits are made in
 * registers and only stored, never read back: a wide load of narrow stores
 * just made stalls (store forwarding fails), which cost this function half
 * its time. Bytes past the length are scratch (NUMFMT_F32_ROOM). */
/* Stores w's bytes lowest first, whatever the host's byte order. */
static inline void put8(char *out, uint64_t w)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    w = __builtin_bswap64(w);
#endif
    memcpy(out, &w, 8);
}

static size_t fast_fixed(char *out, uint32_t d, int n, int x)
{
    int fixed_len;
    if (x >= 0 && x < n - 1) { /* d.ddd (most numbers): n + 1 long, shorter than d.ddde0 */
        fixed_len = n + 1;
    } else {
        fixed_len = x >= n - 1 ? x + 1 : n + 1 - x;
        int ax = x < 0 ? -x : x;
        int sci_len = n + (n > 1) + 1 + (x < 0) + (ax >= 10 ? 2 : 1);
        if (fixed_len > sci_len + 3 || x > 8)
            return 0;
    }
    /* Nine digits, zeros after the n significant ones: c0, then w. */
    uint32_t D = d * pow10_u32[9 - n];
    char c0 = (char)('0' + D / 100000000);
    uint64_t w = digits8(D % 100000000);
    if (x >= 0) { /* an integer (at most 9 digits), or d.ddd */
        out[0] = c0;
        put8(out + 1, w);
        if (x < n - 1) { /* x <= 7: the digits after the point are w's from byte x */
            out[x + 1] = '.';
            put8(out + x + 2, w >> (8 * x));
        }
    } else { /* 0.000ddd: at most 5 zeros after the point */
        memcpy(out, "0.000000", 8);
        out[1 - x] = c0;
        put8(out + 2 - x, w);
    }
    return (size_t)fixed_len;
}

/* The general search, for subnormals and the rare floats where the fast
 * path below cannot decide. */
static size_t general(char *out, uint32_t u)
{
    uint32_t ef = u >> 23, mf = u & 0x7fffffu;
    uint64_t m = ef ? (mf | 0x800000u) : mf;
    int e2 = ef ? (int)ef - 150 : -149;
    float fa;
    memcpy(&fa, &u, sizeof fa);

    fparts f;
    f.v = (double)fa;
    double ulp; /* 2^e2 built from its bits: e2 >= -149 is a normal double */
    uint64_t ulp_bits = (uint64_t)(e2 + 1023) << 52;
    memcpy(&ulp, &ulp_bits, sizeof ulp);
    bool narrow_below = mf == 0 && ef > 1; /* the float below is half as far */
    f.lo = f.v - (narrow_below ? ulp * 0.25 : ulp * 0.5);
    f.hi = f.v + ulp * 0.5;
    f.nlo = 4 * m - (narrow_below ? 1 : 2);
    f.nhi = 4 * m + 2;
    f.e2q = e2 - 2;
    f.inclusive = (m & 1) == 0;

    /* floor(log10 v) from floor(log2 v), corrected by the table. */
    int bitlen = 64 - __builtin_clzll(m);
    int l2 = e2 + bitlen - 1;
    int E = (l2 * 1233 + 4096 * 64) / 4096 - 64; /* floor(l2 log10 2) or one less */
    if (f.v >= pow10d(E + 1))
        E++;
    else if (f.v < pow10d(E))
        E--;
    f.E = E;

    uint64_t d = 0;
    int k = 0;
    for (int p = 9; !shortest(&f, p, &d, &k) && p < 17; p++)
        ; /* p > 9 only when E came out one too high */
    return put_decimal(out, d, k);
}


/* [a, b] divided by p when it holds a multiple of p (ceiling, floor). */
static inline bool drop_digits(uint32_t *a, uint32_t *b, uint32_t p)
{
    uint32_t ap = (*a + p - 1) / p, bp = *b / p;
    if (ap > bp)
        return false;
    *a = ap;
    *b = bp;
    return true;
}

size_t numfmt_f32(char *out, float value)
{
    uint32_t u;
    memcpy(&u, &value, sizeof u);
    size_t neg = u >> 31;
    u &= 0x7fffffffu;
    if (u == 0 || u >= 0x7f800000u) {
        out[0] = '0';
        return 1;
    }
    out[0] = '-';
    out += neg;

    uint32_t ef = u >> 23, mf = u & 0x7fffffu;
    if (ef == 0)
        return neg + general(out, u);
    uint32_t m = mf | 0x800000u;
    int e2 = (int)ef - 150;

    /* Integers below 2^24: their own digits are the shortest (the interval
     * is at most one wide). */
    if (e2 <= 0 && e2 > -24 && (m & ((1u << -e2) - 1)) == 0) {
        uint32_t iv = m >> -e2;
        /* Below 10^4 fixed notation is never longer than three past scientific. */
        return neg + (iv < 10000 ? put_small(out, iv) : put_decimal(out, iv, 0));
    }

    /* The fast path: the nine-digit scaling of the interval, in double. */
    float fa;
    memcpy(&fa, &u, sizeof fa);
    double v = (double)fa;
    int l2 = (int)ef - 127;
    int E = (l2 * 1233 + 4096 * 64) / 4096 - 64;
    if (v >= p10[E + 61])
        E++;
    double sc = p10[68 - E]; /* 10^(8 - E): nine digits before the point */
    double ulp_sc, s = v * sc;
    uint64_t ulp_bits = (uint64_t)(e2 + 1023) << 52;
    memcpy(&ulp_sc, &ulp_bits, sizeof ulp_sc);
    ulp_sc *= sc;
    double slo = s - (mf == 0 && ef > 1 ? 0.25 : 0.5) * ulp_sc, shi = s + 0.5 * ulp_sc;
    double eps = s * 0x1p-46;
    int64_t a = (int64_t)slo, b = (int64_t)shi;
    a += (double)a < slo;
    /* Within rounding error of an end, or E one off: the exact search. */
    if ((double)a - slo <= eps || slo - (double)(a - 1) <= eps || shi - (double)b <= eps ||
        (double)(b + 1) - shi <= eps || a > b || s < 1e8)
        return neg + general(out, u);

    /* Drop trailing digits while [a, b] still holds a multiple of ten:
     * one or two at a time (most numbers), then by 10^4, 10^2, 10 for the
     * round ones (0.2 drops eight): holding a multiple of 10^j is monotone
     * in j, and ceil(ceil(a/p)/q) = ceil(a/pq), so the greedy steps end
     * where the loop would. */
    uint32_t a32 = (uint32_t)a, b32 = (uint32_t)b;
    int t = 0;
    if (drop_digits(&a32, &b32, 10) && ++t && drop_digits(&a32, &b32, 10) && ++t) {
        t += drop_digits(&a32, &b32, 10000) ? 4 : 0;
        t += drop_digits(&a32, &b32, 100) ? 2 : 0;
        t += drop_digits(&a32, &b32, 10) ? 1 : 0;
    }
    uint32_t d = (uint32_t)(s * p10[60 - t] + 0.5);
    d = d < a32 ? a32 : (d > b32 ? b32 : d);
    /* d has 9 - t digits, or one more when it rounded up to a power of ten;
     * the last one is not a zero (else the loop would have gone on). */
    int n = 9 - t, x = E;
    if (d >= pow10_u32[n]) {
        n++;
        x++;
    }
    if (n <= 9) {
        size_t len = fast_fixed(out, d, n, x);
        if (len)
            return neg + len;
    }
    return neg + put_decimal(out, d, E - 8 + t);
}
