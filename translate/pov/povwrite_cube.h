/* povwrite_cube.h: cube maps in the POV-Ray writer (issue 14;
 * docs/mapping.md section 24). Private to the writer. */
#ifndef RGL_POVWRITE_CUBE_H
#define RGL_POVWRITE_CUBE_H

#include <stddef.h>
#include <stdint.h>

#include "outbuf.h"
#include "povwrite_texture.h"
#include "scene.h"

/* A cube map's six faces declared as pigment functions rgl_cube<id>f<k>
 * (k: +X, -X, +Y, -Y, +Z, -Z), with how face coordinates map into each
 * face's image file. */
typedef struct povcube {
    unsigned id;
    float scale[6][2], offset[6][2];
} povcube;

/* Declares the faces of cube texture t (scene_texture.cube; the faces
 * linked by mip_next) and, per channel, the function of a direction
 * (s, t, r) that samples the cube as GL does (GL 2.1 3.8.6, table 3.21:
 * the major axis picks the face, the other two coordinates divided by it
 * the texel), rgl_cube<id>c<channel>(s, t, r). Returns 0, or -1 when
 * memory ran out or t is not a whole cube. */
int povcube_declare(outbuf *ob, povtex *pt, const scene *s, int32_t t, unsigned id, povcube *c);

/* Puts into buf the pigment text (uv_mapping: x, y are s, t) of a run
 * whose r = map[0] s + map[1] t + map[2] (povmt_run's map of tex1[0] over
 * tex). Returns 0, or -1 when buf is too small. */
int povcube_pigment(const povcube *c, const double map[6], char *buf, size_t cap);

#endif
