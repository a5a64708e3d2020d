/* talloc.h: the one allocation wrapper of translate/.
 *
 * Every allocation in the translator goes through tr_realloc, so a test can
 * make the n-th one fail (tr_fail_alloc) and check that failure is reported,
 * not crashed on.
 */
#ifndef RGL_TALLOC_H
#define RGL_TALLOC_H

#include <stddef.h>

/* realloc semantics; tr_realloc(p, 0) frees p and returns NULL. Thread-safe. */
void *tr_realloc(void *ptr, size_t size);

static inline void tr_free(void *ptr) { (void)tr_realloc(ptr, 0); }

/* Test hook: the n-th allocation from now (1 = the next) and every later one
 * fail, until called again; 0 turns failures off. */
void tr_fail_alloc(unsigned long n);

/* Grows *ptr (an array of elem-sized items with capacity *cap) to hold at
 * least need items, doubling. Returns 0, or -1 (nothing changed) on
 * overflow or allocation failure. */
int tr_grow(void **ptr, size_t *cap, size_t need, size_t elem);

#endif
