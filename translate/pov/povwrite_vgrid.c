/* povwrite_vgrid.c: vertex colours on a grid of texels (povwrite_vgrid.h).
 *
 * Pairs of consecutive faces that share an edge are quads; quads that
 * share an edge are neighbours. A breadth-first walk from each quad not yet
 * placed lays its component on integer texels, each neighbour on the far
 * side of the shared edge; a quad whose corners are already elsewhere, or
 * whose texels another vertex holds, stays off the grid. Components are
 * then packed side by side in rows.
 */
#include "povwrite_vgrid.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "talloc.h"

#define NONE UINT32_MAX
#define LANES 0x0000000100010001ull /* one in each of three 16-bit lanes */
#define COORD_BIAS (1 << 21)

/* Texels taken, as bitmaps of TILE x TILE texels per component, found
 * through a small hash of their tiles: the walk places neighbours, so it
 * reads the tile of the texel before nearly every time (the last one is
 * kept), where a hash per texel took a look-up at every test. */
#define TILE_SHIFT 5
#define TILE (1 << TILE_SHIFT)

struct povgrid_tile {
    uint64_t key; /* tile_key */
    uint32_t row[TILE];
};

void povgrid_init(povgrid *g)
{
    memset(g, 0, sizeof *g);
}

void povgrid_finish(povgrid *g)
{
    tr_free(g->tx);
    tr_free(g->ty);
    tr_free(g->in_grid);
    tr_free(g->qc);
    tr_free(g->quad);
    tr_free(g->qface);
    tr_free(g->edges);
    tr_free(g->emore);
    tr_free(g->nb);
    tr_free(g->tiles);
    tr_free(g->tslot);
    tr_free(g->comp);
    tr_free(g->queue);
    tr_free(g->cbox);
    memset(g, 0, sizeof *g);
}

static uint8_t q8(float x)
{
    return (uint8_t)(x > 0 ? (x < 1 ? (int)(x * 255.0f + 0.5f) : 255) : 0); /* NaN: 0 */
}

static inline uint64_t mix(uint64_t k)
{
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdull;
    k ^= k >> 33;
    return k;
}

static inline uint64_t tile_key(int32_t comp, int32_t x, int32_t y)
{
    return ((uint64_t)comp << 34 | (uint64_t)((x + COORD_BIAS) >> TILE_SHIFT) << 17 |
            (uint64_t)((y + COORD_BIAS) >> TILE_SHIFT)) +
           1;
}

/* The tile of key: its index, or NONE when it has none yet. */
static uint32_t tile_find(const povgrid *g, uint64_t key, size_t *slot)
{
    size_t i = (size_t)mix(key) & (g->cap_tslot - 1);
    for (;; i = (i + 1) & (g->cap_tslot - 1)) {
        uint32_t t = g->tslot[i];
        if (t == 0 || g->tiles[t - 1].key == key) {
            *slot = i;
            return t - 1; /* 0 - 1: NONE */
        }
    }
}

/* tile_row when the tile is not the last one found. */
static uint32_t *tile_row_slow(povgrid *g, uint64_t key, int32_t y, bool make)
{
    size_t slot;
    uint32_t t = tile_find(g, key, &slot);
    if (t == NONE) {
        if (!make)
            return NULL;
        if (tr_grow((void **)&g->tiles, &g->cap_tiles, g->ntiles + 1, sizeof *g->tiles) != 0)
            return NULL;
        t = (uint32_t)g->ntiles++;
        memset(&g->tiles[t], 0, sizeof g->tiles[t]);
        g->tiles[t].key = key;
        g->tslot[slot] = t + 1;
        if (g->ntiles * 2 > g->cap_tslot) { /* kept at most half full */
            uint32_t *ns = tr_realloc(g->tslot, 2 * g->cap_tslot * sizeof *ns);
            if (!ns)
                return NULL;
            g->tslot = ns;
            g->cap_tslot *= 2;
            memset(ns, 0, g->cap_tslot * sizeof *ns);
            for (size_t i = 0; i < g->ntiles; i++) {
                size_t at;
                tile_find(g, g->tiles[i].key, &at);
                g->tslot[at] = (uint32_t)i + 1;
            }
        }
    }
    g->tlast_key = key;
    g->tlast = t;
    return &g->tiles[t].row[(y + COORD_BIAS) & (TILE - 1)];
}

/* The row of texels (comp, *, y) around x, made when `make`; NULL when
 * there is none (not made), or memory ran out (made). */
static inline uint32_t *tile_row(povgrid *g, int32_t comp, int32_t x, int32_t y, bool make)
{
    uint64_t key = tile_key(comp, x, y);
    if (key == g->tlast_key)
        return &g->tiles[g->tlast].row[(y + COORD_BIAS) & (TILE - 1)];
    return tile_row_slow(g, key, y, make);
}

static inline int put_vertex(povgrid *g, uint32_t v, int32_t comp, int32_t x, int32_t y)
{
    uint32_t *row = tile_row(g, comp, x, y, true);
    if (!row)
        return -1;
    *row |= 1u << ((x + COORD_BIAS) & (TILE - 1));
    g->tx[v] = x;
    g->ty[v] = y;
    g->comp[v] = comp;
    return 0;
}

/* Whether v can go to (x, y) of comp: there already, or unplaced and the
 * texel free. */
static inline bool fits(povgrid *g, uint32_t v, int32_t comp, int32_t x, int32_t y)
{
    if (g->tx[v] != -1 || g->comp[v] != -1)
        return g->comp[v] == comp && g->tx[v] == x && g->ty[v] == y;
    const uint32_t *row = tile_row(g, comp, x, y, false);
    return !row || !(*row >> ((x + COORD_BIAS) & (TILE - 1)) & 1);
}

/* Quads: consecutive faces sharing an edge, in parallelogram colours.
 * Returns their number. */
static size_t make_quads(povgrid *g, const uint32_t *faces, size_t stride, size_t n)
{
    size_t nq = 0;
    const uint64_t *qc = g->qc;
    for (size_t i = 0; i + 1 < n; i++) {
        const uint32_t *a = faces + stride * i, *b = faces + stride * (i + 1);
        int sa = 0, sb = 2;
        /* Strips: b's first two corners are a's last two (either way). */
        if (!(((b[0] == a[1] && b[1] == a[2]) || (b[0] == a[2] && b[1] == a[1])) &&
              b[2] != a[0])) {
            int shared = 0;
            sa = sb = -1;
            for (int k = 0; k < 3; k++) {
                bool in_b = a[k] == b[0] || a[k] == b[1] || a[k] == b[2];
                bool in_a = b[k] == a[0] || b[k] == a[1] || b[k] == a[2];
                shared += in_b;
                if (!in_b)
                    sa = k;
                if (!in_a)
                    sb = k;
            }
            if (shared != 2 || sa < 0 || sb < 0)
                continue;
        }
        static const int next[3] = {1, 2, 0}, after[3] = {2, 0, 1};
        uint32_t o1 = a[sa], x = a[next[sa]], y = a[after[sa]], o2 = b[sb];
        /* x + y - o1 - o2 within the slack in every channel: 512 more in
         * each lane (no borrow), then the lane's bit 15 tells each bound. */
        uint64_t t = qc[x] + qc[y] + 512 * LANES - qc[o1] - qc[o2];
        if (((t + (0x8000 - 512 + POVTEX_GRID_TOL) * LANES) & 0x8000 * LANES) != 0x8000 * LANES ||
            ((t + (0x8000 - 513 - POVTEX_GRID_TOL) * LANES) & 0x8000 * LANES) != 0)
            continue;
        uint32_t *q = g->quad + 4 * nq;
        q[0] = o1, q[1] = x, q[2] = o2, q[3] = y;
        g->qface[nq++] = (uint32_t)i;
        i++; /* the pair is taken */
    }
    return nq;
}

/* The quads on each edge, kept by the edge's lower vertex: a vertex's
 * first EDGE_INLINE edges in its own bucket (a grid's vertex is the lower
 * end of two or three), more in a chain. Strips number their vertices in
 * order, so the buckets are read nearly in order, where a hash of the edge
 * would miss the cache at every look-up. */
#define EDGE_INLINE 3

struct povgrid_edges {
    uint32_t n;    /* edges in the bucket */
    uint32_t more; /* the chain's first entry in g->emore, or NONE */
    uint32_t hi[EDGE_INLINE], first[EDGE_INLINE]; /* first: 4 quad + its edge */
};

struct povgrid_edge_more {
    uint32_t hi, first, next;
};

/* g->nb[4 q + k], for edge k of quad q: the other quad among the first
 * two on the edge (in the order quads were made), NONE, or MANY when the
 * quad comes third or later (the walk then takes both, edge_quads). */
#define MANY (UINT32_MAX - 1)

/* Quad edge qe (of quad q) is on the edge whose first quad edge is f. */
static inline void pair_edge(povgrid *g, uint32_t f, uint32_t qe, uint32_t q)
{
    if (g->nb[f] == NONE) { /* the second quad on the edge */
        g->nb[f] = q;
        g->nb[qe] = f / 4;
    } else {
        g->nb[qe] = MANY;
    }
}

/* add_edge past the bucket: the edges in the chain. */
static int add_edge_more(povgrid *g, struct povgrid_edges *b, uint32_t hi, uint32_t qe,
                         uint32_t q)
{
    for (uint32_t m = b->more; m != NONE; m = g->emore[m].next)
        if (g->emore[m].hi == hi) {
            pair_edge(g, g->emore[m].first, qe, q);
            return 0;
        }
    g->nb[qe] = NONE;
    if (g->nemore >= NONE ||
        tr_grow((void **)&g->emore, &g->cap_emore, g->nemore + 1, sizeof *g->emore) != 0)
        return -1;
    struct povgrid_edge_more *e = &g->emore[g->nemore];
    e->hi = hi;
    e->first = qe;
    e->next = b->more;
    b->more = (uint32_t)g->nemore++;
    return 0;
}

/* Enters edge k of quad q (its corners u, w), after every quad made
 * before it. Returns 0, or -1 when memory ran out. */
static inline int add_edge(povgrid *g, uint32_t u, uint32_t w, uint32_t q, uint32_t k)
{
    uint32_t lo = u < w ? u : w, hi = u < w ? w : u, qe = 4 * q + k;
    struct povgrid_edges *b = &g->edges[lo];
    uint32_t n = b->n;
    for (uint32_t j = 0; j < n; j++)
        if (b->hi[j] == hi) {
            pair_edge(g, b->first[j], qe, q);
            return 0;
        }
    if (n < EDGE_INLINE) {
        g->nb[qe] = NONE;
        b->n = n + 1;
        b->hi[n] = hi;
        b->first[n] = qe;
        return 0;
    }
    return add_edge_more(g, b, hi, qe, q);
}

/* The first two quads on edge u-w, NONE where there are fewer: out[0],
 * out[1] (only for edges of three quads or more). */
static void edge_quads(const povgrid *g, uint32_t u, uint32_t w, uint32_t out[2])
{
    uint32_t lo = u < w ? u : w, hi = u < w ? w : u, f = NONE;
    const struct povgrid_edges *b = &g->edges[lo];
    for (uint32_t j = 0; j < b->n && f == NONE; j++)
        if (b->hi[j] == hi)
            f = b->first[j];
    for (uint32_t m = b->more; m != NONE && f == NONE; m = g->emore[m].next)
        if (g->emore[m].hi == hi)
            f = g->emore[m].first;
    out[0] = f == NONE ? NONE : f / 4;
    out[1] = f == NONE ? NONE : g->nb[f];
}

/* The walk: components of quads laid on texels (*ncomp of them, *placed
 * faces). Returns 0, or -1 when memory ran out. */
/* The walk's component being laid: its number, its box, the queue's end,
 * the faces laid. */
typedef struct walk_state {
    int32_t k;
    int32_t *box;
    size_t tail, placed;
} walk_state;

#define SEEN (1u << 31) /* qface: the quad was met by the walk */

/* Lays quad q2, met across edge e of quad qc4 (placed, a unit square), on
 * the far side of that edge when its other corners fit there: marks it
 * seen either way, queues it when laid. Returns 0, or -1 when memory ran
 * out. */
static inline int place(povgrid *g, walk_state *wk, const uint32_t *qc4, int e, uint32_t q2)
{
    g->qface[q2] |= SEEN;
    uint32_t u = qc4[e], w = qc4[(e + 1) % 4];
    /* Away from the quad: the corner after w lies on its far side. */
    int32_t ux = g->tx[u], uy = g->ty[u], wx = g->tx[w], wy = g->ty[w];
    uint32_t o = qc4[(e + 2) % 4];
    int32_t nx = 0, ny = 0;
    if (ux == wx)
        nx = g->tx[o] > ux ? -1 : 1;
    else
        ny = g->ty[o] > uy ? -1 : 1;
    const uint32_t *d = g->quad + 4 * q2;
    int iu = 0;
    while (iu < 4 && d[iu] != u)
        iu++;
    if (iu == 4)
        return 0;
    uint32_t pu, pw;
    if (d[(iu + 1) % 4] == w)
        pu = d[(iu + 3) % 4], pw = d[(iu + 2) % 4];
    else if (d[(iu + 3) % 4] == w)
        pu = d[(iu + 1) % 4], pw = d[(iu + 2) % 4];
    else
        return 0;
    int32_t k = wk->k, pux = ux + nx, puy = uy + ny, pwx = wx + nx, pwy = wy + ny;
    if (pux < -COORD_BIAS + 2 || pux > COORD_BIAS - 2 || puy < -COORD_BIAS + 2 ||
        puy > COORD_BIAS - 2 || !fits(g, pu, k, pux, puy) || !fits(g, pw, k, pwx, pwy))
        return 0;
    if ((g->comp[pu] == -1 && put_vertex(g, pu, k, pux, puy) != 0) ||
        (g->comp[pw] == -1 && put_vertex(g, pw, k, pwx, pwy) != 0))
        return -1;
    int32_t *box = wk->box;
    int32_t lx = pux < pwx ? pux : pwx, ly = puy < pwy ? puy : pwy;
    int32_t hx = pux > pwx ? pux : pwx, hy = puy > pwy ? puy : pwy;
    box[0] = lx < box[0] ? lx : box[0];
    box[1] = ly < box[1] ? ly : box[1];
    box[2] = hx > box[2] ? hx : box[2];
    box[3] = hy > box[3] ? hy : box[3];
    uint32_t f = g->qface[q2] & ~SEEN;
    g->in_grid[f] = g->in_grid[f + 1] = 1;
    wk->placed += 2;
    g->queue[wk->tail++] = q2;
    return 0;
}

static int walk(povgrid *g, size_t nq, int32_t *ncomp_out, size_t *placed_out)
{
    /* The walk's queue; a quad seen is marked in qface's high bit. */
    g->ntiles = 0;
    g->tlast_key = 0;
    if (!g->tslot) {
        g->tslot = tr_realloc(NULL, 64 * sizeof *g->tslot);
        if (!g->tslot)
            return -1;
        g->cap_tslot = 64;
    }
    memset(g->tslot, 0, g->cap_tslot * sizeof *g->tslot);
    if (tr_grow((void **)&g->queue, &g->cap_queue, nq, sizeof *g->queue) != 0)
        return -1;
    int32_t ncomp = 0;
    size_t placed = 0;
    for (size_t q0 = 0; q0 < nq; q0++) {
        if (g->qface[q0] & SEEN)
            continue;
        g->qface[q0] |= SEEN;
        const uint32_t *c = g->quad + 4 * q0;
        if (g->comp[c[0]] != -1 || g->comp[c[1]] != -1 || g->comp[c[2]] != -1 ||
            g->comp[c[3]] != -1 || ncomp >= (1 << 19))
            continue;
        int32_t k = ncomp++;
        if (tr_grow((void **)&g->cbox, &g->cap_cbox, (size_t)ncomp * 4, sizeof *g->cbox) != 0)
            return -1;
        int32_t *box = g->cbox + 4 * k;
        box[0] = box[1] = 0, box[2] = box[3] = 1;
        walk_state wk = {k, box, 0, 0};
        if (put_vertex(g, c[0], k, 0, 0) != 0 || put_vertex(g, c[1], k, 1, 0) != 0 ||
            put_vertex(g, c[2], k, 1, 1) != 0 || put_vertex(g, c[3], k, 0, 1) != 0)
            return -1;
        g->in_grid[g->qface[q0] & ~SEEN] = g->in_grid[(g->qface[q0] & ~SEEN) + 1] = 1;
        placed += 2;
        size_t head = 0;
        g->queue[wk.tail++] = (uint32_t)q0;
        while (head < wk.tail) {
            uint32_t q = g->queue[head++];
            /* The queue's quads lie far apart (a wave across the grid):
             * their neighbour words fetched ahead. */
            if (head + 8 < wk.tail)
                __builtin_prefetch(&g->nb[4 * (size_t)g->queue[head + 8]]);
            const uint32_t *qc4 = g->quad + 4 * q;
            for (int e = 0; e < 4; e++) {
                uint32_t q2 = g->nb[4 * q + (uint32_t)e];
                if (q2 == NONE || (q2 != MANY && (g->qface[q2] & SEEN)))
                    continue;
                int rc;
                if (q2 != MANY) {
                    rc = place(g, &wk, qc4, e, q2);
                } else { /* an edge of three quads or more: the first two on it */
                    uint32_t on_edge[2];
                    edge_quads(g, qc4[e], qc4[(e + 1) % 4], on_edge);
                    rc = 0;
                    for (int h = 0; h < 2 && rc == 0; h++)
                        if (on_edge[h] != NONE && !(g->qface[on_edge[h]] & SEEN))
                            rc = place(g, &wk, qc4, e, on_edge[h]);
                }
                if (rc != 0)
                    return -1;
            }
        }
        placed += wk.placed;
    }

    *ncomp_out = ncomp;
    *placed_out = placed;
    return 0;
}

int povgrid_build(povgrid *g, const uint32_t *faces, size_t stride, size_t n, size_t nv,
                  const float *const *col)
{
    g->width = g->height = 0;
    g->ncells = 0;
    if (tr_grow((void **)&g->tx, &g->cap_v, nv ? nv : 1, sizeof *g->tx) != 0 ||
        tr_grow((void **)&g->ty, &g->cap_ty, nv ? nv : 1, sizeof *g->ty) != 0 ||
        tr_grow((void **)&g->comp, &g->cap_comp, nv ? nv : 1, sizeof *g->comp) != 0 ||
        tr_grow((void **)&g->qc, &g->cap_qc, nv ? nv : 1, sizeof *g->qc) != 0)
        return -1;
    if (tr_grow((void **)&g->in_grid, &g->cap_f, n ? n : 1, 1) != 0)
        return -1;
    /* Each vertex's colour as the 8-bit texel it would take, once: the
     * quads below test four corners each, the image takes them. */
    for (size_t v = 0; v < nv; v++) {
        g->tx[v] = g->ty[v] = g->comp[v] = -1;
        const float *c = col[v];
        g->qc[v] = (uint64_t)q8(c[0]) | (uint64_t)q8(c[1]) << 16 | (uint64_t)q8(c[2]) << 32;
    }
    memset(g->in_grid, 0, n);
    if (n < 2 || n > (1u << 21))
        return 0;
    if (tr_grow((void **)&g->quad, &g->cap_quad, (n / 2) * 4, sizeof *g->quad) != 0 ||
        tr_grow((void **)&g->qface, &g->cap_qface, n / 2, sizeof *g->qface) != 0)
        return -1;
    size_t nq = make_quads(g, faces, stride, n);
    if (nq == 0)
        return 0;
    if (tr_grow((void **)&g->edges, &g->cap_edges, nv, sizeof *g->edges) != 0 ||
        tr_grow((void **)&g->nb, &g->cap_nb, 4 * nq, sizeof *g->nb) != 0)
        return -1;
    for (size_t v = 0; v < nv; v++) {
        g->edges[v].n = 0;
        g->edges[v].more = NONE;
    }
    g->nemore = 0;
    for (uint32_t q = 0; q < nq; q++) {
        const uint32_t *c = g->quad + 4 * (size_t)q;
        if (add_edge(g, c[0], c[1], q, 0) != 0 || add_edge(g, c[1], c[2], q, 1) != 0 ||
            add_edge(g, c[2], c[3], q, 2) != 0 || add_edge(g, c[3], c[0], q, 3) != 0)
            return -1;
    }
    int32_t ncomp = 0;
    size_t placed = 0;
    if (walk(g, nq, &ncomp, &placed) != 0)
        return -1;

    /* Components in rows (shelves) of about the square's width. */
    double area = 0;
    int32_t widest = 0;
    for (int32_t k = 0; k < ncomp; k++) {
        const int32_t *b = g->cbox + 4 * k;
        area += (double)(b[2] - b[0] + 1) * (b[3] - b[1] + 1);
        widest = b[2] - b[0] + 1 > widest ? b[2] - b[0] + 1 : widest;
    }
    int32_t target = widest;
    while ((double)target * target < area)
        target++;
    int32_t x = 0, y = 0, shelf = 0, w = 0;
    for (int32_t k = 0; k < ncomp; k++) {
        int32_t *b = g->cbox + 4 * k;
        int32_t bw = b[2] - b[0] + 1, bh = b[3] - b[1] + 1;
        if (x > 0 && x + bw > target) {
            y += shelf;
            x = shelf = 0;
        }
        /* x0, y0 become the component's offset */
        b[0] = x - b[0];
        b[1] = y - b[1];
        x += bw;
        shelf = bh > shelf ? bh : shelf;
        w = x > w ? x : w;
    }
    int32_t h = y + shelf;
    /* A grid mostly empty, or past an image's size, is no gain. */
    if (w > 16384 || h > 16384 || (double)w * h > 4.0 * (double)placed + 4096) {
        memset(g->in_grid, 0, n);
        for (size_t v = 0; v < nv; v++)
            g->tx[v] = g->ty[v] = -1;
        return 0;
    }
    for (size_t v = 0; v < nv; v++)
        if (g->comp[v] != -1) {
            const int32_t *b = g->cbox + 4 * g->comp[v];
            g->tx[v] += b[0];
            g->ty[v] += b[1];
        }
    g->width = w;
    g->height = h;
    g->ncells = placed;
    return 0;
}
