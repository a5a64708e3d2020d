/* povwrite_mesh2.h: a mesh of the scene as POV-Ray mesh2 (povwrite_mesh2.c),
 * for povwrite.c.
 */
#ifndef RGL_POVWRITE_MESH2_H
#define RGL_POVWRITE_MESH2_H

#include <stddef.h>

#include "mat4.h"
#include "outbuf.h"
#include "povwrite.h"
#include "scene.h"

/* Writes the nt triangles tris (indices into verts) of one look as mesh2
 * objects into ob: in eye space when to_eye is NULL, else with its
 * matrix; with two texture units, one mesh2 per run of triangles whose
 * second coordinates are one function of their first (povmt_run).
 * Uses and updates w's caches and images; returns 0, or -1 when memory
 * runs out. Not thread-safe for one w. */
int povmesh2_write(povwriter *w, outbuf *ob, const scene_vertex *verts, const scene_tri *tris,
                   size_t nt, const scene_look *look, const mat4 *to_eye);

#endif
