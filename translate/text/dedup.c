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

/* Independent multiplications (they run in parallel), then one mix. */
static inline uint64_t hash_words(const uint32_t *k, uint32_t words)
{
    static const uint64_t mul[DEDUP_MAX_WORDS] = {
        0x9e3779b97f4a7c15ull, 0xc2b2ae3d27d4eb4full, 0x165667b19e3779f9ull,
        0xd6e8feb86659fd93ull, 0xff51afd7ed558ccdull, 0xc4ceb9fe1a85ec53ull,
        0x94d049bb133111ebull, 0xbf58476d1ce4e5b9ull, 0x27d4eb2f165667c5ull,
        0x85ebca6b2f1a9d33ull, 0xa0761d6478bd642full, 0xe7037ed1a0b428dbull,
    };
    uint64_t h = words;
    for (uint32_t i = 0; i < words; i++)
        h += (k[i] + (uint64_t)i) * mul[i];
    h ^= h >> 31;
    h *= 0x7fb5d329728ea185ull;
    return h ^ (h >> 27);
}

/* The common key sizes get their own unrolled copy. */
static inline uint64_t hash_key(const uint32_t *k, uint32_t words)
{
    switch (words) {
    case 3: return hash_words(k, 3);
    case 4: return hash_words(k, 4);
    case 6: return hash_words(k, 6);
    case 7: return hash_words(k, 7);
    case 10: return hash_words(k, 10);
    default: return hash_words(k, words);
    }
}

static inline int same_key(const uint32_t *a, const uint32_t *b, uint32_t words)
{
    uint32_t diff = 0;
    for (uint32_t i = 0; i < words; i++)
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

uint32_t dedup_index(dedup *d, const uint32_t *key)
{
    uint64_t h = hash_key(key, d->words), tag = h & 0xffffffff00000000ull;
    size_t at = (size_t)h & d->mask;
    for (;;) {
        uint64_t s = d->slots[at];
        if (!s)
            break;
        if ((s & 0xffffffff00000000ull) == tag) {
            uint32_t i = (uint32_t)s - 1;
            if (same_key(dedup_key(d, i), key, d->words))
                return i;
        }
        at = (at + 1) & d->mask;
    }
    if (d->count >= UINT32_MAX - 1)
        return DEDUP_NONE;
    if (tr_grow((void **)&d->keys, &d->cap_keys, (d->count + 1) * d->words, sizeof *key) != 0)
        return DEDUP_NONE;
    memcpy(d->keys + d->count * d->words, key, d->words * sizeof *key);
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
