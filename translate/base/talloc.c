/* talloc.c: the allocation wrapper with its failure injection (talloc.h). */
#include "talloc.h"

#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>

static atomic_ulong fail_countdown; /* 0: off; else allocations left + 1 */

void tr_fail_alloc(unsigned long n) { atomic_store(&fail_countdown, n); }

void *tr_realloc(void *ptr, size_t size)
{
    if (size == 0) {
        free(ptr);
        return NULL;
    }
    unsigned long c = atomic_load_explicit(&fail_countdown, memory_order_relaxed);
    if (c != 0) {
        if (c == 1)
            return NULL; /* stays at 1: every later allocation fails too */
        atomic_fetch_sub(&fail_countdown, 1);
    }
    return realloc(ptr, size);
}

int tr_grow(void **ptr, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return 0;
    size_t n = *cap ? *cap : 16;
    while (n < need) {
        if (n > SIZE_MAX / 2)
            return -1;
        n *= 2;
    }
    if (n > SIZE_MAX / elem)
        return -1;
    void *p = tr_realloc(*ptr, n * elem);
    if (!p)
        return -1;
    *ptr = p;
    *cap = n;
    return 0;
}
