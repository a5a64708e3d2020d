/* gltfwrite.h: the glTF 2.0 backend: scene model -> one binary glTF (.glb).
 *
 * The second writer beside povwrite.h: it reads only the scene model
 * (scene.h). Eye space becomes the glTF scene's space (both are
 * right-handed, +y up, the camera looking down -z), so the camera node
 * sits where GL's eye is. docs/mapping-gltf.md explains every mapping and
 * what glTF cannot say (kept as notes in the file's extras). The same
 * scene gives the same bytes; every string from the trace is escaped.
 */
#ifndef RGL_GLTFWRITE_H
#define RGL_GLTFWRITE_H

#include <stdint.h>

#include "outbuf.h"
#include "scene.h"

/* Tessellation of GLU/GLUT solids (scene_solid): slices around, stacks
 * along; finer than GLU's usual 16-32 (docs/mapping-gltf.md). */
#define GLTF_SOLID_SLICES 48
#define GLTF_SOLID_STACKS 24

typedef struct gltf_frame_info {
    const char *source;     /* the trace's name, or NULL */
    uint64_t frame_index;   /* in file order */
    const char *frame_name; /* rayglFrameBegin's, or NULL */
    const char *incomplete; /* why the scene is incomplete, or NULL */
} gltf_frame_info;

/* Figures of the last file written, for tests. */
typedef struct gltf_stats {
    size_t meshes, nodes, materials, accessors, lights, images;
    size_t instance_nodes; /* nodes placing a shared prototype mesh */
} gltf_stats;

/* Writes the scene as a complete .glb into ob (binary bytes). Returns 0, or
 * -1 when memory ran out or the sink failed (ob->failed). stats may be
 * NULL. */
int gltf_write(outbuf *ob, const scene *s, const gltf_frame_info *info, gltf_stats *stats);

#endif
