/* gltfwrite_internal.h: what the glTF writer's files share (gltfwrite.c:
 * the file, materials, meshes; gltfwrite_light.c: the camera and the
 * lights): the writer's state and the JSON helpers. Internal to gltf/. */
#ifndef RGL_GLTFWRITE_INTERNAL_H
#define RGL_GLTFWRITE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "gltfwrite.h"
#include "outbuf.h"
#include "scene.h"

#define GLTF_PI 3.14159265358979323846

#define GLTF_MAX_NOTES 32

enum { GLTF_ARRAY_BUFFER = 34962, GLTF_ELEMENT_ARRAY_BUFFER = 34963, T_FLOAT = 5126, T_UINT = 5125 };
/* glTF's sampler values (the specification's, GL's numbers). */
enum { GLTF_NEAREST = 9728, GLTF_LINEAR = 9729, GLTF_REPEAT = 10497, GLTF_CLAMP_TO_EDGE = 33071 };

typedef struct bytes {
    uint8_t *p;
    size_t n, cap;
} bytes;

typedef struct list {
    outbuf ob; /* ",{...}" items */
    size_t count;
} list;

typedef struct writer {
    const scene *s;
    bool failed;
    bytes bin;
    list accessors, views, meshes, nodes, materials, textures, images, samplers, lights,
        cameras;
    char **mat_json; /* materials written, to share equal ones */
    size_t cap_mat_json;
    int32_t *tex_index; /* scene texture -> glTF texture, -1 until written */
    uint32_t *remap, *stamp, gen;
    /* one primitive's vertices */
    float *pos, *nrm, *col, *uv;
    float solid_colour[4]; /* GL colour of the solid being written */
    size_t nv, cap_v;
    uint32_t *idx;
    size_t ni, cap_i;
    uint32_t *scene_nodes;
    size_t nscene_nodes, cap_scene_nodes;
    bool used_unlit, used_specular, used_lights;
    outbuf notes;
    size_t nnotes;
    const char *note_seen[GLTF_MAX_NOTES];
    gltf_stats st;
} writer;

/* GL's colours are display values; glTF's factors, vertex colours and light
 * colours are linear (gltfwrite.c). */
double gltfw_srgb_linear(double v);
/* A number (non-finite and huge ones as 0); n of them as a JSON array. */
void gltfw_num(outbuf *ob, double v);
void gltfw_nums(outbuf *ob, const double *v, int n);
/* Starts an item of l; returns its index. */
size_t gltfw_item(list *l);
/* A note for extras.notes, once each (text is a static string). */
void gltfw_note(writer *w, const char *text);
/* A node; mesh, camera, light < 0 for none; matrix NULL for identity. */
size_t gltfw_add_node(writer *w, long mesh, long camera, long light, const double *matrix,
                      const double *rot, const double *trans, const char *name);
/* A unit quaternion (x, y, z, w) turning -z to fwd and +y toward up. */
void gltfw_orient(const double fwd_in[3], const double up_in[3], double q[4]);

/* The scene's camera, and its lights as KHR_lights_punctual
 * (gltfwrite_light.c). */
void gltfw_write_camera(writer *w);
void gltfw_write_lights(writer *w);

#endif
