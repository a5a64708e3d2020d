/* dedup.h: an insertion-ordered set of small fixed-size keys.
 *
 * The writer shares equal positions, normals and colours within a mesh2
 * (vertex_vectors, normal_vectors, texture_list): each key gets the index
 * of its first insertion, and the keys stay in that order for writing.
 * Sharing is exact for up to DEDUP_WINDOW / 2 distinct keys; past that it
 * works over a sliding window (dedup.c), which keeps lookups in cache.
 * Keys are 1..DEDUP_MAX_WORDS 32-bit words (float bit patterns, so -0 and 0 differ and
 * NaN never reaches here). Reused across meshes; not thread-safe.
 */
#ifndef RGL_DEDUP_H
#define RGL_DEDUP_H

#include <stddef.h>
#include <stdint.h>

#define DEDUP_NONE UINT32_MAX
#define DEDUP_WINDOW (1u << 15) /* most slots; half of them hold keys */
#define DEDUP_MAX_WORDS 12

typedef struct dedup {
    uint32_t words;  /* key size in 32-bit words */
    uint64_t *slots; /* open addressing: hash bits << 32 | index + 1; 0 = empty */
    size_t mask;     /* slot count - 1 */
    uint32_t *keys;  /* count * words, in insertion order */
    size_t count, cap_keys;
    size_t live; /* keys in the table (since it was last emptied) */
} dedup;

void dedup_init(dedup *d, uint32_t words);
void dedup_finish(dedup *d);

/* Empties the set, sized for about `expected` keys. Returns 0 or -1. */
int dedup_reset(dedup *d, size_t expected);

/* The index of key (inserting it when new), or DEDUP_NONE when memory runs
 * out. */
uint32_t dedup_index(dedup *d, const uint32_t *key);

static inline const uint32_t *dedup_key(const dedup *d, size_t i) { return d->keys + i * d->words; }

#endif
