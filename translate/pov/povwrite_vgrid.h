/* povwrite_vgrid.h: a mesh's vertex colours laid on a grid of texels, one
 * texel per vertex (docs/mapping.md section 6, "Vertex colours").
 *
 * Strips, quad strips and the grids they tessellate draw pairs of faces
 * that form quads. A quad whose fourth corner's colour is the other three's
 * parallelogram (D = B + C - A within POVTEX_GRID_TOL) is one cell of the
 * grid: bilinear filtering over its four texels is then GL's linear
 * interpolation on each of its two faces. Quads that share an edge share
 * the edge's texels, so each vertex has one texel and one uv, taken by
 * face_indices like the normals. Faces that fit no cell are left to
 * povtex_colours' blocks of their own. Used by povwrite_mesh2.c.
 */
#ifndef RAYGL_POVWRITE_VGRID_H
#define RAYGL_POVWRITE_VGRID_H

#include <stddef.h>
#include <stdint.h>

/* The parallelogram's slack, in 1/255 per channel of the 8-bit texels:
 * the error inside a face is at most a quarter of it. */
#define POVTEX_GRID_TOL 2

typedef struct povgrid {
    int32_t *tx, *ty;   /* per vertex: its texel, tx -1 when on no cell */
    uint64_t *qc;       /* per vertex: its 8-bit RGB in 16-bit lanes, red lowest */
    uint8_t *in_grid;   /* per face: on a cell */
    int32_t width, height; /* the grid's texels */
    size_t ncells;      /* faces on cells */
    /* scratch */
    uint32_t *quad;     /* per quad: its corners in cyclic order */
    size_t cap_quad;
    uint32_t *qface;    /* per quad: its first face */
    size_t cap_qface;
    struct povgrid_edges *edges; /* per vertex: the edges it is the lower end of */
    size_t cap_edges;
    struct povgrid_edge_more *emore; /* edges past a vertex's bucket */
    size_t nemore, cap_emore;
    uint32_t *nb;       /* per quad edge: the other quad on it (povwrite_vgrid.c) */
    size_t cap_nb;
    struct povgrid_tile *tiles; /* texels taken, by tiles (povwrite_vgrid.c) */
    size_t ntiles, cap_tiles;
    uint32_t *tslot;    /* tile + 1 by hash of its key (open addressing) */
    size_t cap_tslot;
    uint64_t tlast_key; /* the tile found last */
    uint32_t tlast;
    int32_t *comp;      /* per vertex: its component */
    uint32_t *queue;
    size_t cap_queue;
    size_t cap_v, cap_ty, cap_comp, cap_f, cap_qc;
    int32_t *cbox;      /* per component: x0, y0, x1, y1 */
    size_t cap_cbox;
} povgrid;

void povgrid_init(povgrid *g);
void povgrid_finish(povgrid *g);

/* Lays the n faces (vertices faces[stride * i + 0..2], below nv) on a grid
 * by the colours col[v] (RGB, 0..1) of their vertices. Fills g->tx, ty, qc,
 * in_grid, width, height, ncells. Returns 0, or -1 when memory ran out. */
int povgrid_build(povgrid *g, const uint32_t *faces, size_t stride, size_t n, size_t nv,
                  const float *const *col);

#endif
