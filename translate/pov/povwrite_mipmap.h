/* povwrite_mipmap.h: mipmapped minification in the POV-Ray writer
 * (issue 14; docs/mapping.md section 24). Private to the writer. */
#ifndef RGL_POVWRITE_MIPMAP_H
#define RGL_POVWRITE_MIPMAP_H

#include <stdbool.h>
#include <stddef.h>

#include "mat4.h"
#include "outbuf.h"
#include "povwrite_texture.h"
#include "scene.h"

/* Room for a mipmapped pigment's text (a pigment_map of up to 15 levels). */
#define POVMIP_PIGMENT_MAX 4096

/* A run of a mesh's triangles that share one level choice: planar, the
 * eye-space position is one affine function of (u, v) over the run and
 * GL's level of detail is computed per pixel from it; otherwise lambda
 * is one value for the run (its triangles' mean). */
typedef struct povmip_run {
    bool planar;
    double a[3], b[3], c[3]; /* camera image coordinates: (u, v, 1) . a etc. */
    double lambda;
} povmip_run;

/* The length of the run from tris[0] (nt > 0): triangles on one affine
 * map of their (u, v) into eye space (to_eye NULL: the vertices are in eye
 * space), planar; or 1 when tris[0] shares its map with no neighbour,
 * with its lambda at its centroid (not planar). A run over which lambda
 * varies by less than 1/POVMIP_STEPS at its corners is not planar
 * either: its lambda is the middle of theirs. tw, th: the base level's
 * size in texels. */
#define POVMIP_STEPS 16
size_t povmip_split(const scene_camera *cam, const mat4 *to_eye, const scene_vertex *verts,
                    const scene_tri *tris, size_t nt, int tw, int th, povmip_run *out);

/* Writes (before the mesh) the functions of run r as rgl_mip<id>... and
 * puts into buf the pigment text that samples texture t's levels (t is
 * the base level, linked by mip_next) as GL's minification filter does:
 * a pigment_map indexed by the level of detail, each level's image from
 * povtex_map (keep_alpha, tint as there) taken at the mesh's own (u, v).
 * Returns 0, or -1 when memory ran out or buf is too small. */
int povmip_pigment(outbuf *ob, povtex *pt, const scene *s, int32_t t, const povmip_run *r,
                   unsigned id, const float uvlo[2], const float uvhi[2], bool keep_alpha,
                   const float tint[3], char *buf, size_t cap);

#endif
