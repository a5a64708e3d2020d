/* teapot_mesh.c: the solid teapot as one closed-seam triangle mesh
 * (teapot_mesh.h), for a writer that draws the solid teapot as a mesh
 * (the POV-Ray writer: its bicubic patches let rays through the seams).
 *
 * Each of the 32 patches is cut into a regular grid and every grid point
 * evaluated on the Bezier surface with its analytic normal. Points that
 * two patches share along a seam come out equal to float precision but not
 * always bit for bit (a patch pair runs with reversed parameters), and
 * POV-Ray's bicubic_patch cuts each patch on its own: rays slipped through
 * the seams there and showed the inside as dark dots. Here a point is
 * stored once per float position, so the triangles of both patches share
 * the very vertex, and the lid's top row, 0.002 across around the axis in
 * freeglut's data, is closed onto the axis.
 */
#include "teapot_mesh.h"

#include <math.h>
#include <string.h>

#include "talloc.h"
#include "teapot.h"

/* Points closer to the teapot's axis than this (object units at size 1)
 * lie on a patch edge that collapses there: the bottom's centre and the
 * lid's top row. */
#define AXIS_SNAP 0.0025

#define HASH_BITS 17

static uint32_t key_hash(const float p[3])
{
    uint32_t b[3];
    memcpy(b, p, sizeof b);
    uint32_t h = 2166136261u;
    for (int k = 0; k < 3; k++) {
        h ^= b[k];
        h *= 16777619u;
        h ^= h >> 15;
    }
    return h;
}

int teapot_mesh_build(teapot_mesh *m, int steps)
{
    memset(m, 0, sizeof *m);
    if (steps < 1 || steps > 64)
        return -1;
    size_t side = (size_t)steps + 1;
    size_t maxv = TEAPOT_PATCHES * side * side;
    size_t maxt = TEAPOT_PATCHES * (size_t)steps * (size_t)steps * 2;
    size_t nslots = (size_t)1 << HASH_BITS;
    while (nslots < 2 * maxv)
        nslots *= 2;
    uint32_t *slot = tr_realloc(NULL, nslots * sizeof *slot);
    uint32_t *grid = tr_realloc(NULL, side * side * sizeof *grid);
    m->pos = tr_realloc(NULL, maxv * sizeof *m->pos);
    m->normal = tr_realloc(NULL, maxv * sizeof *m->normal);
    m->tri = tr_realloc(NULL, maxt * sizeof *m->tri);
    if (!slot || !grid || !m->pos || !m->normal || !m->tri) {
        tr_free(slot);
        tr_free(grid);
        teapot_mesh_free(m);
        return -1;
    }
    memset(slot, 0xff, nslots * sizeof *slot);
    for (int p = 0; p < TEAPOT_PATCHES; p++) {
        for (size_t i = 0; i < side; i++)
            for (size_t j = 0; j < side; j++) {
                double q[3], n[3];
                teapot_eval(p, (double)i / steps, (double)j / steps, q, n);
                if (q[0] * q[0] + q[2] * q[2] < AXIS_SNAP * AXIS_SNAP)
                    q[0] = q[2] = 0;
                float f[3] = {(float)q[0], (float)q[1], (float)q[2]};
                size_t h = key_hash(f) & (nslots - 1);
                while (slot[h] != UINT32_MAX && memcmp(m->pos[slot[h]], f, sizeof f) != 0)
                    h = (h + 1) & (nslots - 1);
                if (slot[h] == UINT32_MAX) {
                    slot[h] = (uint32_t)m->nverts;
                    memcpy(m->pos[m->nverts], f, sizeof f);
                    for (int k = 0; k < 3; k++)
                        m->normal[m->nverts][k] = (float)n[k];
                    m->nverts++;
                } else { /* a seam: the mean of the patches' normals */
                    float *nn = m->normal[slot[h]];
                    for (int k = 0; k < 3; k++)
                        nn[k] += (float)n[k];
                }
                grid[i * side + j] = slot[h];
            }
        for (size_t i = 0; i < (size_t)steps; i++)
            for (size_t j = 0; j < (size_t)steps; j++) {
                uint32_t a = grid[i * side + j], b = grid[i * side + j + 1];
                uint32_t c = grid[(i + 1) * side + j + 1], d = grid[(i + 1) * side + j];
                const uint32_t t[2][3] = {{a, b, c}, {a, c, d}};
                for (int k = 0; k < 2; k++) {
                    if (t[k][0] == t[k][1] || t[k][1] == t[k][2] || t[k][0] == t[k][2])
                        continue; /* collapsed onto the axis */
                    memcpy(m->tri[m->ntris++], t[k], sizeof t[k]);
                }
            }
    }
    for (size_t v = 0; v < m->nverts; v++) {
        float *nn = m->normal[v];
        double l = sqrt((double)nn[0] * nn[0] + (double)nn[1] * nn[1] + (double)nn[2] * nn[2]);
        for (int k = 0; k < 3; k++)
            nn[k] = l > 0 ? (float)(nn[k] / l) : (float)(k == 1);
    }
    tr_free(slot);
    tr_free(grid);
    return 0;
}

void teapot_mesh_free(teapot_mesh *m)
{
    tr_free(m->pos);
    tr_free(m->normal);
    tr_free(m->tri);
    memset(m, 0, sizeof *m);
}
