/* namemap.h: GL object names to indexes, for the interpreter's tables.
 *
 * Display lists and texture objects are looked up by name at every call; a
 * trace may define 10^5 of them and then call one 10^7 times from a
 * display list, so a lookup must not cost in proportion to the table. An
 * open-addressing hash (linear probing, deletion by backward shift) from a
 * nonzero 32-bit name to an index in the caller's array. Not thread-safe.
 */
#ifndef RGL_NAMEMAP_H
#define RGL_NAMEMAP_H

#include <stddef.h>
#include <stdint.h>

typedef struct namemap {
    uint32_t *keys; /* 0: empty */
    uint32_t *vals;
    size_t cap, n;  /* cap: 0 or a power of two */
} namemap;

/* An empty map with no storage; namemap_finish frees it (then empty). */
void namemap_init(namemap *m);
void namemap_finish(namemap *m);

/* The index stored for name, or -1. */
int64_t namemap_get(const namemap *m, uint32_t name);

/* Stores index for name (nonzero), replacing an earlier one. Returns 0, or
 * -1 when memory ran out (the map is then unchanged). */
int namemap_put(namemap *m, uint32_t name, uint32_t index);

/* Removes name, if present. */
void namemap_del(namemap *m, uint32_t name);

/* Empties the map, keeping its storage. */
void namemap_clear(namemap *m);

/* dst becomes a copy of src (dst's earlier contents are freed). Returns 0,
 * or -1 when memory ran out (dst is then empty). */
int namemap_copy(namemap *dst, const namemap *src);

#endif
