/* numfmt.c: shortest round-trip formatting of floats, and integers.
 *
 * A float v = m * 2^e2 rounds back from any decimal inside its rounding
 * interval [v - gap_below/2, v + gap_above/2] (ends included when m is
 * even, as round-half-even does); the text is the shortest decimal in it,
 * of those the closest to v, on a tie the one away from zero. Normal floats
 * take an exact integer path (numfmt_f32): the interval scaled by a power
 * of ten so that it is one to ten units wide, from one 64x64-bit product
 * per end (the idea of Giulietti's Schubfach). Subnormals, and the rare
 * floats the rounded powers of ten leave undecided, take the general
 * search below: the interval scaled in double, settled by exact big-integer
 * comparisons. tests/translate/test_numfmt.c checks round trip, shortness
 * and closeness against strtof and printf over 3.3 million floats of every
 * exponent and every power of two; all 4.3 billion gave the same text as
 * the double-based path this one replaced (see bench/translate/README.md).
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
__attribute__((noinline)) static size_t put_decimal(char *out, uint64_t d, int k)
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
    /* Fixed unless more than three characters longer than scientific
     * (n + (n > 1) + 2 + (x < 0) characters for |x| < 10): 0.000ddd down
     * to five zeros after the point, integers up to five zeros past the
     * digits (four each for one digit) and nine digits in all. */
    int fixed_len;
    if (x < 0) {
        if (x < -5 - (n > 1))
            return 0;
        fixed_len = n + 1 - x;
    } else if (x < n - 1) { /* d.ddd (most numbers) */
        fixed_len = n + 1;
    } else {
        if (x > 8 || x > n + (n > 1) + 4)
            return 0;
        fixed_len = x + 1;
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
__attribute__((noinline, cold)) static size_t general(char *out, uint32_t u)
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


/* 10^j * 2^r for j in [-31, 46] at pow10_g[j + 31], r chosen so that the
 * value lies in [2^63, 2^64): exact for j in [0, 27] (5^27 fits), rounded
 * up for the others. Made by exact rational arithmetic (Python fractions). */
static const uint64_t pow10_g[78] = {
    0x81ceb32c4b43fcf5ull, 0xa2425ff75e14fc32ull, 0xcad2f7f5359a3b3full,
    0xfd87b5f28300ca0eull, 0x9e74d1b791e07e49ull, 0xc612062576589ddbull,
    0xf79687aed3eec552ull, 0x9abe14cd44753b53ull, 0xc16d9a0095928a28ull,
    0xf1c90080baf72cb2ull, 0x971da05074da7befull, 0xbce5086492111aebull,
    0xec1e4a7db69561a6ull, 0x9392ee8e921d5d08ull, 0xb877aa3236a4b44aull,
    0xe69594bec44de15cull, 0x901d7cf73ab0acdaull, 0xb424dc35095cd810ull,
    0xe12e13424bb40e14ull, 0x8cbccc096f5088ccull, 0xafebff0bcb24aaffull,
    0xdbe6fecebdedd5bfull, 0x89705f4136b4a598ull, 0xabcc77118461cefdull,
    0xd6bf94d5e57a42bdull, 0x8637bd05af6c69b6ull, 0xa7c5ac471b478424ull,
    0xd1b71758e219652cull, 0x83126e978d4fdf3cull, 0xa3d70a3d70a3d70bull,
    0xcccccccccccccccdull, 0x8000000000000000ull, 0xa000000000000000ull,
    0xc800000000000000ull, 0xfa00000000000000ull, 0x9c40000000000000ull,
    0xc350000000000000ull, 0xf424000000000000ull, 0x9896800000000000ull,
    0xbebc200000000000ull, 0xee6b280000000000ull, 0x9502f90000000000ull,
    0xba43b74000000000ull, 0xe8d4a51000000000ull, 0x9184e72a00000000ull,
    0xb5e620f480000000ull, 0xe35fa931a0000000ull, 0x8e1bc9bf04000000ull,
    0xb1a2bc2ec5000000ull, 0xde0b6b3a76400000ull, 0x8ac7230489e80000ull,
    0xad78ebc5ac620000ull, 0xd8d726b7177a8000ull, 0x878678326eac9000ull,
    0xa968163f0a57b400ull, 0xd3c21bcecceda100ull, 0x84595161401484a0ull,
    0xa56fa5b99019a5c8ull, 0xcecb8f27f4200f3aull, 0x813f3978f8940985ull,
    0xa18f07d736b90be6ull, 0xc9f2c9cd04674edfull, 0xfc6f7c4045812297ull,
    0x9dc5ada82b70b59eull, 0xc5371912364ce306ull, 0xf684df56c3e01bc7ull,
    0x9a130b963a6c115dull, 0xc097ce7bc90715b4ull, 0xf0bdc21abb48db21ull,
    0x96769950b50d88f5ull, 0xbc143fa4e250eb32ull, 0xeb194f8e1ae525feull,
    0x92efd1b8d0cf37bfull, 0xb7abc627050305aeull, 0xe596b7b0c643c71aull,
    0x8f7e32ce7bea5c70ull, 0xb35dbf821ae4f38cull, 0xe0352f62a19e306full
};

/* For each biased exponent ef of a normal float (e2 = ef - 150), the
 * scaling of its interval: k = floor(log10 2^e2) (gi = 31 - k indexes
 * pow10_g) and h, which makes m * 2^h * g = 10^-k * m * 2^e2 * 2^64. g is
 * exact for ef in [61, 153]. */
static const struct {
    uint8_t gi, h;
} scale_of[254] = {
    {76, 1}, {76, 2}, {76, 3}, {75, 1}, {75, 2}, {75, 3}, {75, 4}, {74, 1}, {74, 2}, {74, 3},
    {73, 1}, {73, 2}, {73, 3}, {72, 1}, {72, 2}, {72, 3}, {72, 4}, {71, 1}, {71, 2}, {71, 3},
    {70, 1}, {70, 2}, {70, 3}, {69, 1}, {69, 2}, {69, 3}, {69, 4}, {68, 1}, {68, 2}, {68, 3},
    {67, 1}, {67, 2}, {67, 3}, {66, 1}, {66, 2}, {66, 3}, {66, 4}, {65, 1}, {65, 2}, {65, 3},
    {64, 1}, {64, 2}, {64, 3}, {63, 1}, {63, 2}, {63, 3}, {63, 4}, {62, 1}, {62, 2}, {62, 3},
    {61, 1}, {61, 2}, {61, 3}, {60, 1}, {60, 2}, {60, 3}, {59, 1}, {59, 2}, {59, 3}, {59, 4},
    {58, 1}, {58, 2}, {58, 3}, {57, 1}, {57, 2}, {57, 3}, {56, 1}, {56, 2}, {56, 3}, {56, 4},
    {55, 1}, {55, 2}, {55, 3}, {54, 1}, {54, 2}, {54, 3}, {53, 1}, {53, 2}, {53, 3}, {53, 4},
    {52, 1}, {52, 2}, {52, 3}, {51, 1}, {51, 2}, {51, 3}, {50, 1}, {50, 2}, {50, 3}, {50, 4},
    {49, 1}, {49, 2}, {49, 3}, {48, 1}, {48, 2}, {48, 3}, {47, 1}, {47, 2}, {47, 3}, {47, 4},
    {46, 1}, {46, 2}, {46, 3}, {45, 1}, {45, 2}, {45, 3}, {44, 1}, {44, 2}, {44, 3}, {44, 4},
    {43, 1}, {43, 2}, {43, 3}, {42, 1}, {42, 2}, {42, 3}, {41, 1}, {41, 2}, {41, 3}, {41, 4},
    {40, 1}, {40, 2}, {40, 3}, {39, 1}, {39, 2}, {39, 3}, {38, 1}, {38, 2}, {38, 3}, {38, 4},
    {37, 1}, {37, 2}, {37, 3}, {36, 1}, {36, 2}, {36, 3}, {35, 1}, {35, 2}, {35, 3}, {35, 4},
    {34, 1}, {34, 2}, {34, 3}, {33, 1}, {33, 2}, {33, 3}, {32, 1}, {32, 2}, {32, 3}, {31, 1},
    {31, 2}, {31, 3}, {31, 4}, {30, 1}, {30, 2}, {30, 3}, {29, 1}, {29, 2}, {29, 3}, {28, 1},
    {28, 2}, {28, 3}, {28, 4}, {27, 1}, {27, 2}, {27, 3}, {26, 1}, {26, 2}, {26, 3}, {25, 1},
    {25, 2}, {25, 3}, {25, 4}, {24, 1}, {24, 2}, {24, 3}, {23, 1}, {23, 2}, {23, 3}, {22, 1},
    {22, 2}, {22, 3}, {22, 4}, {21, 1}, {21, 2}, {21, 3}, {20, 1}, {20, 2}, {20, 3}, {19, 1},
    {19, 2}, {19, 3}, {19, 4}, {18, 1}, {18, 2}, {18, 3}, {17, 1}, {17, 2}, {17, 3}, {16, 1},
    {16, 2}, {16, 3}, {16, 4}, {15, 1}, {15, 2}, {15, 3}, {14, 1}, {14, 2}, {14, 3}, {13, 1},
    {13, 2}, {13, 3}, {13, 4}, {12, 1}, {12, 2}, {12, 3}, {11, 1}, {11, 2}, {11, 3}, {10, 1},
    {10, 2}, {10, 3}, {10, 4}, {9, 1}, {9, 2}, {9, 3}, {8, 1}, {8, 2}, {8, 3}, {7, 1}, {7, 2},
    {7, 3}, {7, 4}, {6, 1}, {6, 2}, {6, 3}, {5, 1}, {5, 2}, {5, 3}, {4, 1}, {4, 2}, {4, 3}, {4,
    4}, {3, 1}, {3, 2}, {3, 3}, {2, 1}, {2, 2}, {2, 3}, {1, 1}, {1, 2}, {1, 3}, {0, 1}, {0, 2}
};

/* The high and low words of g * c. */
#ifdef __SIZEOF_INT128__
__extension__ typedef unsigned __int128 numfmt_u128;
static inline uint64_t mul_hilo(uint64_t g, uint64_t c, uint64_t *lo)
{
    numfmt_u128 p = (numfmt_u128)g * c;
    *lo = (uint64_t)p;
    return (uint64_t)(p >> 64);
}
#else
static inline uint64_t mul_hilo(uint64_t g, uint64_t c, uint64_t *lo)
{
    uint64_t ll = (g & 0xffffffffu) * (c & 0xffffffffu), lh = (g & 0xffffffffu) * (c >> 32);
    uint64_t hl = (g >> 32) * (c & 0xffffffffu), hh = (g >> 32) * (c >> 32);
    uint64_t mid = (ll >> 32) + (uint32_t)lh + (uint32_t)hl;
    *lo = (mid << 32) | (uint32_t)ll;
    return hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
}
#endif

/* 4 X for X = cx * 2^q * 10^-k, given cp = cx * 2^h with g * cp = 4 X *
 * 2^64: the high word, its lowest bit set when X has a fraction (rounded
 * to odd, after Giulietti's Schubfach), so that comparing it with a
 * multiple of four is comparing 4 X itself. *rem is the low word: a g
 * rounded up adds less than cp to it, so below cp the exact X may be an
 * integer or the floor one less. */
static inline uint32_t scale_odd(uint64_t g, uint64_t cp, uint64_t *rem)
{
    uint64_t hi = mul_hilo(g, cp, rem);
    return (uint32_t)hi | (*rem != 0);
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

    /* The interval scaled by 10^-k, k chosen so that its width is in
     * [1, 10): k = floor(log10 2^e2), or floor(log10 (3/4 2^e2)) when the
     * float below is half as far (m = 2^23). Four times the scaled value
     * and ends, rounded to odd, decide everything exactly: the interval
     * holds at most one multiple of ten (then it is the shortest), else
     * the shortest are s or s + 1 (s = floor of the value), the closer if
     * both fit, s + 1 on a tie (2097152.25 gives 2097152.3, as before). */
    int k = 31 - scale_of[ef - 1].gi, h = scale_of[ef - 1].h;
    uint64_t g = pow10_g[31 - k];
    uint64_t cb = (uint64_t)m << (2 + h), d2 = (uint64_t)2 << h, dl = d2;
    bool exact = ef >= 61 && ef <= 153;
    if (mf == 0 && ef > 1) { /* the float below is half as far */
        dl = d2 >> 1;
        if (((e2 * 1233 - 512 + 4096 * 64) >> 12) - 64 < k) {
            /* one more digit: the interval is under one wide at 10^-k */
            k--;
            exact = k >= -27;
            int r = 63 - (((-k * 1741647 + (128 << 19)) >> 19) - 128);
            h = 64 - r + e2;
            g = pow10_g[31 - k];
            cb = (uint64_t)m << (2 + h);
            d2 = (uint64_t)2 << h;
            dl = d2 >> 1;
        }
    }
    uint32_t inc = ~m & 1; /* ends belong when m is even */
    uint64_t rb, rl, rr;
    uint32_t vb = scale_odd(g, cb, &rb);
    uint32_t vbl = scale_odd(g, cb - dl, &rl);
    uint32_t vbr = scale_odd(g, cb + d2, &rr);
    /* g rounded up, and an end or the value may be off: the exact search. */
    if (!exact && (rb < cb || rl < cb - dl || rr < cb + d2))
        return neg + general(out, u);
    vbl += !inc;
    vbr -= !inc;

    uint32_t s = vb >> 2, s10 = s / 10;
    uint32_t d;
    int n, x;
    bool upin = vbl <= 40 * s10, wpin = 40 * s10 + 40 <= vbr;
    if (upin != wpin) {
        /* The one multiple of ten: strip its zeros (at most seven). */
        d = s10 + wpin;
        n = 6 + (d >= 1000000) + (d >= 10000000);
        x = k + n;
        if (d % 10000 == 0) {
            d /= 10000;
            n -= 4;
        }
        if (d % 100 == 0) {
            d /= 100;
            n -= 2;
        }
        if (d % 10 == 0) {
            d /= 10;
            n -= 1;
        }
    } else {
        bool uin = vbl <= 4 * s, win = 4 * s + 4 <= vbr;
        d = s + (uin != win ? win : vb >= 4 * s + 2);
        /* 7 to 9 digits, the last not a zero (else a multiple of ten fit). */
        n = 7 + (d >= 10000000) + (d >= 100000000);
        x = k + n - 1;
    }
    size_t len = fast_fixed(out, d, n, x);
    if (len)
        return neg + len;
    return neg + put_decimal(out, d, x - n + 1);
}
