/* namemap.c: GL object names to indexes (namemap.h). */
#include "namemap.h"

#include <string.h>

#include "talloc.h"

void namemap_init(namemap *m) { memset(m, 0, sizeof *m); }

void namemap_finish(namemap *m)
{
    tr_free(m->keys);
    tr_free(m->vals);
    memset(m, 0, sizeof *m);
}

static size_t slot_of(uint32_t name, size_t cap)
{
    return (size_t)(((uint64_t)name * 0x9E3779B97F4A7C15ull) >> 32) & (cap - 1);
}

int64_t namemap_get(const namemap *m, uint32_t name)
{
    if (!m->cap || name == 0)
        return -1;
    for (size_t i = slot_of(name, m->cap);; i = (i + 1) & (m->cap - 1)) {
        if (m->keys[i] == name)
            return m->vals[i];
        if (m->keys[i] == 0)
            return -1;
    }
}

static void insert(uint32_t *keys, uint32_t *vals, size_t cap, uint32_t name, uint32_t index)
{
    size_t i = slot_of(name, cap);
    while (keys[i] != 0 && keys[i] != name)
        i = (i + 1) & (cap - 1);
    keys[i] = name;
    vals[i] = index;
}

/* Room for one more at a load of at most 1/2. */
static int reserve(namemap *m)
{
    if (2 * (m->n + 1) <= m->cap)
        return 0;
    size_t cap = m->cap ? 2 * m->cap : 16;
    if (cap > SIZE_MAX / 2 / sizeof(uint32_t))
        return -1;
    uint32_t *keys = tr_realloc(NULL, cap * sizeof *keys);
    uint32_t *vals = keys ? tr_realloc(NULL, cap * sizeof *vals) : NULL;
    if (!vals) {
        tr_free(keys);
        return -1;
    }
    memset(keys, 0, cap * sizeof *keys);
    for (size_t i = 0; i < m->cap; i++)
        if (m->keys[i])
            insert(keys, vals, cap, m->keys[i], m->vals[i]);
    tr_free(m->keys);
    tr_free(m->vals);
    m->keys = keys;
    m->vals = vals;
    m->cap = cap;
    return 0;
}

int namemap_put(namemap *m, uint32_t name, uint32_t index)
{
    if (name == 0)
        return -1;
    if (namemap_get(m, name) < 0) {
        if (reserve(m) != 0)
            return -1;
        m->n++;
    }
    insert(m->keys, m->vals, m->cap, name, index);
    return 0;
}

void namemap_del(namemap *m, uint32_t name)
{
    if (!m->cap || name == 0)
        return;
    size_t mask = m->cap - 1, i = slot_of(name, m->cap);
    while (m->keys[i] != name) {
        if (m->keys[i] == 0)
            return;
        i = (i + 1) & mask;
    }
    /* Backward shift: later keys of the run move up into the hole unless
     * their home slot lies cyclically after it. */
    for (size_t j = (i + 1) & mask; m->keys[j] != 0; j = (j + 1) & mask) {
        size_t home = slot_of(m->keys[j], m->cap);
        if (((j - home) & mask) >= ((j - i) & mask)) {
            m->keys[i] = m->keys[j];
            m->vals[i] = m->vals[j];
            i = j;
        }
    }
    m->keys[i] = 0;
    m->n--;
}

void namemap_clear(namemap *m)
{
    if (m->cap)
        memset(m->keys, 0, m->cap * sizeof *m->keys);
    m->n = 0;
}

int namemap_copy(namemap *dst, const namemap *src)
{
    namemap_finish(dst);
    if (!src->cap)
        return 0;
    dst->keys = tr_realloc(NULL, src->cap * sizeof *dst->keys);
    dst->vals = dst->keys ? tr_realloc(NULL, src->cap * sizeof *dst->vals) : NULL;
    if (!dst->vals) {
        namemap_finish(dst);
        return -1;
    }
    memcpy(dst->keys, src->keys, src->cap * sizeof *dst->keys);
    memcpy(dst->vals, src->vals, src->cap * sizeof *dst->vals);
    dst->cap = src->cap;
    dst->n = src->n;
    return 0;
}
