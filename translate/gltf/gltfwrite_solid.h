/* gltfwrite_solid.h: GLU/GLUT solids (scene_solid) as triangle meshes for
 * the glTF writer: glTF has no analytic shapes, so the writer tessellates
 * them (GLTF_SOLID_SLICES x GLTF_SOLID_STACKS, finer than GLU's usual).
 * Internal to gltfwrite.c and gltfwrite_solid.c. */
#ifndef RGL_GLTFWRITE_SOLID_H
#define RGL_GLTFWRITE_SOLID_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "outbuf.h"
#include "scene.h"

typedef struct writer writer;

/* Appends the solid as one triangle primitive to pj. */
void gltf_solid_prim(writer *w, outbuf *pj, const scene_solid *so);

/* gltfwrite.c's primitive under construction. */
bool gltf_solid_reserve(writer *w, size_t n);
size_t gltf_solid_count(const writer *w);
void gltf_solid_vertex(writer *w, const double p[3], const double n[3], const float col[4],
                       const mat4 *m);
void gltf_solid_index(writer *w, uint32_t i);
void gltf_solid_flush(writer *w, outbuf *pj, const scene_look *look);

#endif
