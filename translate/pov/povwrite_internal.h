/* povwrite_internal.h: the POV-Ray writer's state, shared by povwrite.c
 * (the file: camera, lights, lines and points, groups of meshes) and
 * povwrite_mesh2.c (each mesh as a mesh2). Private to these two files.
 */
#ifndef RGL_POVWRITE_INTERNAL_H
#define RGL_POVWRITE_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "dedup.h"
#include "mat4.h"
#include "outbuf.h"
#include "povwrite.h"
#include "povwrite_cube.h"
#include "povwrite_light.h"
#include "povwrite_mipmap.h"
#include "povwrite_texture.h"
#include "scene.h"

/* Formatted floats, by bit pattern: meshes repeat coordinates, normal
 * components and colour channels far more often than whole vertices, and
 * copying 16 bytes is much cheaper than formatting. Direct-mapped; 2^14
 * entries (512 KB, in L2): 1% fewer instructions on the strips trace than
 * 2^12 (more repeats found), same text. */
#define FCACHE_BITS 14

typedef struct fcache_entry {
    uint32_t bits;
    uint32_t len; /* 0: empty */
    char text[24]; /* NUMFMT_F32_MAX and more: copied whole */
} fcache_entry;

/* Formatted indices: faces name each vertex several times, so the text of
 * 0, 1, 2, ... is made once, counting in decimal, and kept for every mesh
 * and frame: digits from the lowest byte, the length in the highest (so up
 * to 10^7), for the first ITEXT_MAX indices. */
#define ITEXT_MAX (1u << 20)

/* The vertices already indexed, by what a turned vertex's key is made of:
 * strips send each vertex again in the next strip, and the copy's key
 * (its normal turned toward the camera, povlight_front_normal) is the
 * same. Direct-mapped; 2^13 entries reach back more than one strip of
 * the strips frame. */
#define VMEMO_BITS 13

typedef struct vmemo_entry {
    uint32_t raw[10]; /* position, normal, colour bits (scene_vertex) */
    uint32_t tag;     /* the mesh part's generation << 1 | facing; 0: empty */
    uint32_t r;       /* its vertex index */
} vmemo_entry;

_Static_assert(offsetof(scene_vertex, normal) == 3 * sizeof(float) &&
                   offsetof(scene_vertex, color) == 6 * sizeof(float),
               "position, normal and colour are contiguous");

struct povwriter {
    fcache_entry fcache[1u << FCACHE_BITS];
    vmemo_entry *vmemo; /* 2^VMEMO_BITS, made on first use */
    uint32_t vmemo_gen;
    size_t fcache_hits; /* look-ups that found their number */
    bool fcache_off;    /* numbers formatted without the cache (put_vectors) */
    uint64_t *itext;    /* text of the indices 0.. (ITEXT_MAX at most) */
    size_t nitext, cap_itext;
    dedup vtx, col; /* whole vertices (up to 10 words); colours */
    uint32_t *vcol;  /* colour index of each vertex of vtx */
    size_t cap_vcol;
    uint32_t *remap; /* per pool vertex of the mesh: its vertex index */
    size_t cap_remap;
    uint32_t *faces; /* per kept face: 3 vertex, 3 colour indices */
    size_t cap_faces;
    scene_vertex *bverts; /* lines and points as quads */
    size_t nbverts, cap_bverts;
    scene_tri *btris;
    size_t nbtris, cap_btris;
    povlight light; /* lighting, blending and fog of the scene being written */
    bool mesh_no_shadow; /* write_mesh2 adds no_shadow (points outside the union) */
    bool in_proto;       /* writing a display list's prototype: no eye space known */
    uint8_t *front;      /* per pool vertex of the mesh: on a front-facing face */
    size_t cap_front;
    double *eye;         /* per pool vertex of the mesh: its eye-space position */
    size_t cap_eye;
    povtex tex;          /* the frame's texture images */
    unsigned mt_count;   /* the frame's multitexture functions, for their names */
    bool tinted;         /* the mesh's image is tinted (povlight_modulate_tint) */
    bool per_entry;      /* no tint fits the mesh: each colour entry tints a function of it */
    const scene_mip_run *mip; /* the mesh part's level choice (write_mesh2), or NULL */
    const povcube *cube;   /* the mesh's cube map (write_mesh2), or NULL */
    const double *cube_map; /* and the part's r over (s, t) */
    unsigned env_id;     /* the mesh's GL_BLEND or GL_ADD image function (povmt_declare) */
    float mod_kdp[3], mod_tint[3];
    const float **vcorner; /* colour image: 3 corner colours per kept face */
    size_t cap_vcorner;
    uint32_t *offg; /* colour image on a grid: the kept faces off it */
    size_t cap_offg;
    float *vuv; /* colour image: uv per grid vertex, then 3 per face off the grid */
    size_t cap_vuv;
    const float **vcolp; /* colour image: each vertex's colour (in its key) */
    size_t cap_vcolp;
    povgrid grid;
    struct mesh_key *mkeys; /* write_mesh_groups: the pass's meshes by look and transform */
    size_t cap_mkeys;
    uint32_t *mgroup; /* per mesh: its group's start in mkeys, if it leads one */
    size_t cap_mgroup;
    scene_tri *gtris; /* a group's triangles */
    size_t cap_gtris;
};

static inline bool finite3f(const float v[3])
{
    return isfinite(v[0]) & isfinite(v[1]) & isfinite(v[2]); /* no branches */
}

/* `matrix<...>` of an affine transform, unless it is the identity. */
void povwrite_put_matrix(outbuf *ob, const mat4 *to_eye);

/* The texture of an unlit surface of colour c: the pixel is c exactly
 * (the #default finish: emission, no ambient, no diffuse; docs/mapping.md). */
void povwrite_unlit_texture(outbuf *ob, const float c[4]);

#endif
