/* teapot_mesh.h: the solid teapot as one triangle mesh whose patches share
 * their seam vertices (teapot_mesh.c), in teapot.h's object space. */
#ifndef RGL_TEAPOT_MESH_H
#define RGL_TEAPOT_MESH_H

#include <stddef.h>
#include <stdint.h>

typedef struct teapot_mesh {
    float (*pos)[3];
    float (*normal)[3]; /* unit, outward; the mean over patches at a seam */
    size_t nverts;
    uint32_t (*tri)[3];
    size_t ntris;
} teapot_mesh;

/* Cuts every patch into steps x steps cells (1..64) and fills m; m's
 * arrays are the caller's to free with teapot_mesh_free. Returns 0, or -1
 * (m empty) when out of memory or steps is out of range. */
int teapot_mesh_build(teapot_mesh *m, int steps);

/* Frees m's arrays; m may be empty. */
void teapot_mesh_free(teapot_mesh *m);

#endif
