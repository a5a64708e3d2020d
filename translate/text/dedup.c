/* dedup.c: the insertion-ordered key set (dedup.h).
 *
 * Linear probing over a power-of-two table kept at most half full. Each
 * slot holds the key's index and 32 bits of its hash, so a probe touches
 * the key itself only when the hash bits match. The table stops growing at
 * DEDUP_WINDOW slots, so that it stays in the processor's cache: once that
 * holds DEDUP_WINDOW / 2 keys it is emptied and refilled by the keys that
 * follow. Equal keys are then shared when they come within about that many
 * new keys of each other, which is where meshes repeat their vertices;
 * farther repeats are written again, which costs bytes, never correctness.
 */
#include "dedup.h"

#include <string.h>

#include "talloc.h"

void dedup_init(dedup *d, uint32_t words)
{
    memset(d, 0, sizeof *d);
    d->words = words;
}

void dedup_finish(dedup *d)
{
    tr_free(d->slots);
    tr_free(d->keys);
    uint32_t w = d->words;
    memset(d, 0, sizeof *d);
    d->words = w;
}

static int resize(dedup *d, size_t nslots)
{
    uint64_t *s = tr_realloc(d->slots, nslots * sizeof *s);
    if (!s)
        return -1;
    d->slots = s;
    d->mask = nslots - 1;
    memset(s, 0, nslots * sizeof *s);
    return 0;
}

int dedup_reset(dedup *d, size_t expected)
{
    size_t n = 64;
    while (n < expected * 2 && n < DEDUP_WINDOW)
        n *= 2;
    d->count = d->live = 0;
    if (d->slots && d->mask + 1 >= n) {
        memset(d->slots, 0, (d->mask + 1) * sizeof *d->slots);
        return 0;
    }
    return resize(d, n);
}

static inline uint64_t load64(const uint32_t *k)
{
    uint64_t x;
    memcpy(&x, k, sizeof x);
    return x;
}

/* Two words at a time, independent multiplications (they run in
 * parallel), then one mix; written out for each size, as the compiler
 * keeps a loop of ten rounds. */
#define MIX2(i, m) (load64(k + (i)) + (i)) * (m)
#define MIX1(i, m) (k[i] + (uint64_t)(i)) * (m)
static inline uint64_t hash_words(const uint32_t *k, uint32_t words)
{
    static const uint64_t mul[DEDUP_MAX_WORDS] = {
        0x9e3779b97f4a7c15ull, 0xc2b2ae3d27d4eb4full, 0x165667b19e3779f9ull,
        0xd6e8feb86659fd93ull, 0xff51afd7ed558ccdull, 0xc4ceb9fe1a85ec53ull,
        0x94d049bb133111ebull, 0xbf58476d1ce4e5b9ull, 0x27d4eb2f165667c5ull,
        0x85ebca6b2f1a9d33ull, 0xa0761d6478bd642full, 0xe7037ed1a0b428dbull,
    };
    uint64_t h = words;
    uint32_t i = 0;
    for (; i + 2 <= words; i += 2)
        h += MIX2(i, mul[i]);
    if (i < words)
        h += MIX1(i, mul[i]);
    return h;
}

static inline uint64_t finish_hash(uint64_t h)
{
    h ^= h >> 31;
    h *= 0x7fb5d329728ea185ull;
    return h ^ (h >> 27);
}

/* The common key sizes spelled out. */
static inline uint64_t hash_key(const uint32_t *k, uint32_t words)
{
    static const uint64_t m0 = 0x9e3779b97f4a7c15ull, m2 = 0x165667b19e3779f9ull,
                          m4 = 0xff51afd7ed558ccdull, m6 = 0x94d049bb133111ebull,
                          m8 = 0x27d4eb2f165667c5ull;
    switch (words) {
    case 3: return finish_hash(3 + MIX2(0, m0) + MIX1(2, m2));
    case 4: return finish_hash(4 + MIX2(0, m0) + MIX2(2, m2));
    case 6: return finish_hash(6 + MIX2(0, m0) + MIX2(2, m2) + MIX2(4, m4));
    case 7: return finish_hash(7 + MIX2(0, m0) + MIX2(2, m2) + MIX2(4, m4) + MIX1(6, m6));
    case 10:
        return finish_hash(10 + MIX2(0, m0) + MIX2(2, m2) + MIX2(4, m4) + MIX2(6, m6) +
                           MIX2(8, m8));
    default: return finish_hash(hash_words(k, words));
    }
}
#undef MIX2
#undef MIX1

static inline int same_key(const uint32_t *a, const uint32_t *b, uint32_t words)
{
    uint64_t diff = 0;
    uint32_t i = 0;
    for (; i + 2 <= words; i += 2)
        diff |= load64(a + i) ^ load64(b + i);
    if (i < words)
        diff |= a[i] ^ b[i];
    return diff == 0;
}

/* Re-enters the live keys (the last `live` ones) into the table. */
static void rehash(dedup *d)
{
    memset(d->slots, 0, (d->mask + 1) * sizeof *d->slots);
    for (size_t i = d->count - d->live; i < d->count; i++) {
        uint64_t h = hash_key(dedup_key(d, i), d->words);
        size_t at = (size_t)h & d->mask;
        while (d->slots[at])
            at = (at + 1) & d->mask;
        d->slots[at] = (h & 0xffffffff00000000ull) | (uint64_t)(i + 1);
    }
}

/* The look-up for keys of `words` words: inline with a constant for the
 * common sizes, so that hashing, comparing and copying are straight code. */
__attribute__((always_inline)) static inline uint32_t index_of(dedup *d, const uint32_t *key,
                                                              uint32_t words)
{
    uint64_t h = hash_key(key, words), tag = h & 0xffffffff00000000ull;
    size_t at = (size_t)h & d->mask;
    for (;;) {
        uint64_t s = d->slots[at];
        if (!s)
            break;
        if ((s & 0xffffffff00000000ull) == tag) {
            uint32_t i = (uint32_t)s - 1;
            if (same_key(d->keys + (size_t)i * words, key, words))
                return i;
        }
        at = (at + 1) & d->mask;
    }
    if (d->count >= UINT32_MAX - 1)
        return DEDUP_NONE;
    size_t end = (d->count + 1) * words;
    if (end > d->cap_keys && tr_grow((void **)&d->keys, &d->cap_keys, end, sizeof *key) != 0)
        return DEDUP_NONE;
    memcpy(d->keys + d->count * words, key, words * sizeof *key);
    d->slots[at] = tag | (uint64_t)(++d->count);
    d->live++;
    if (d->live * 2 > d->mask + 1) {
        if (d->mask + 1 < DEDUP_WINDOW) {
            if (resize(d, (d->mask + 1) * 2) != 0)
                return DEDUP_NONE;
            rehash(d);
        } else {
            memset(d->slots, 0, (d->mask + 1) * sizeof *d->slots); /* a new window */
            d->live = 0;
        }
    }
    return (uint32_t)(d->count - 1);
}

uint32_t dedup_index(dedup *d, const uint32_t *key)
{
    switch (d->words) {
    case 3: return index_of(d, key, 3);
    case 4: return index_of(d, key, 4);
    case 6: return index_of(d, key, 6);
    case 7: return index_of(d, key, 7);
    case 10: return index_of(d, key, 10);
    default: return index_of(d, key, d->words);
    }
}
