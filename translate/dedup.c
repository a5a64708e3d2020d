/* dedup.c: the insertion-ordered key set (dedup.h). Linear probing over a
 * power-of-two table kept at most half full. */
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
    uint32_t *s = tr_realloc(d->slots, nslots * sizeof *s);
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
    while (n < expected * 2 && n < ((size_t)1 << 31))
        n *= 2;
    d->count = 0;
    if (d->slots && d->mask + 1 >= n && d->mask + 1 <= n * 8) {
        memset(d->slots, 0, (d->mask + 1) * sizeof *d->slots);
        return 0;
    }
    return resize(d, n);
}

static inline size_t hash_key(const uint32_t *k, uint32_t words)
{
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (uint32_t i = 0; i < words; i++) {
        h ^= k[i];
        h *= 0xff51afd7ed558ccdull;
        h ^= h >> 32;
    }
    return (size_t)(h ^ (h >> 29));
}

static void rehash(dedup *d)
{
    memset(d->slots, 0, (d->mask + 1) * sizeof *d->slots);
    for (size_t i = 0; i < d->count; i++) {
        size_t h = hash_key(dedup_key(d, i), d->words) & d->mask;
        while (d->slots[h])
            h = (h + 1) & d->mask;
        d->slots[h] = (uint32_t)(i + 1);
    }
}

uint32_t dedup_index(dedup *d, const uint32_t *key)
{
    size_t bytes = d->words * sizeof *key;
    size_t h = hash_key(key, d->words) & d->mask;
    for (;;) {
        uint32_t s = d->slots[h];
        if (!s)
            break;
        if (memcmp(dedup_key(d, s - 1), key, bytes) == 0)
            return s - 1;
        h = (h + 1) & d->mask;
    }
    if (d->count >= UINT32_MAX - 1)
        return DEDUP_NONE;
    if (tr_grow((void **)&d->keys, &d->cap_keys, (d->count + 1) * d->words, sizeof *key) != 0)
        return DEDUP_NONE;
    memcpy(d->keys + d->count * d->words, key, bytes);
    d->slots[h] = (uint32_t)(++d->count);
    if (d->count * 2 > d->mask + 1) {
        if (resize(d, (d->mask + 1) * 2) != 0)
            return DEDUP_NONE;
        rehash(d);
    }
    return (uint32_t)(d->count - 1);
}
