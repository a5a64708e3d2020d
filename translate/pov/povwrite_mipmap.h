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

/* Writes (before the mesh) the functions of run r as rgl_mip<id>... and
 * puts into buf the pigment text that samples texture t's levels (t is
 * the base level, linked by mip_next) as GL's minification filter does:
 * a pigment_map indexed by the level of detail, each level's image from
 * povtex_map (keep_alpha, tint as there) taken at the mesh's own (u, v).
 * Returns 0, or -1 when memory ran out or buf is too small. */
int povmip_pigment(outbuf *ob, povtex *pt, const scene *s, int32_t t, const scene_mip_run *r,
                   unsigned id, const float uvlo[2], const float uvhi[2], bool keep_alpha,
                   const float tint[3], char *buf, size_t cap);

#endif
