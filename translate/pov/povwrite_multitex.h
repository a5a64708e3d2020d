/* povwrite_multitex.h: two texture units in one POV-Ray pigment (docs/mapping.md
 * "Multitexture"). */
#ifndef RAYGL_POVWRITE_MULTITEX_H
#define RAYGL_POVWRITE_MULTITEX_H

#include <stdbool.h>
#include <stddef.h>

#include "outbuf.h"
#include "povwrite_texture.h"
#include "scene.h"

/* Room for the combined pigment's text. */
#define POVMT_PIGMENT_MAX 2048

/* The length of the run of triangles from tris[0] whose second
 * coordinates (tex1) are one affine function of their first (tex):
 * tex1 = M tex + t, map = {M00, M01, t0, M10, M11, t1} (GL's
 * coordinates). A triangle whose first coordinates have no area joins the
 * run it is in. nt > 0. */
size_t povmt_run(const scene_vertex *verts, const scene_tri *tris, size_t nt, double map[6]);

/* Whether the result of unit t0 then unit t1 leaves the fragment colour
 * out (the pigment is the colour, unlit), or multiplies it (both
 * GL_MODULATE). */
bool povmt_texel(const scene_texture *t0, const scene_texture *t1);

/* Declares, before the mesh, functions sampling images img0 and img1 of
 * pt (names rgl_mt<id>a, rgl_mt<id>b) and writes into buf the pigment
 * body that combines them as GL's environment chain does: unit 0 samples
 * the mesh's uv (file coordinates), unit 1 that uv through map, taken
 * from GL's coordinates into img1's file by scale1/offset1 and out of
 * img0's by scale0/offset0. cf is the fragment colour folded in when
 * povmt_texel. Returns 0, or -1 when buf is too small. */
int povmt_pigment(outbuf *ob, const povtex *pt, size_t img0, size_t img1,
                  const scene_texture *t0, const scene_texture *t1, const float scale0[2],
                  const float offset0[2], const float scale1[2], const float offset1[2],
                  const double map[6], const float cf[4], unsigned id, char *buf, size_t cap);

/* One unit's GL_BLEND or GL_ADD over a colour (issue 14; docs/mapping.md
 * section 24): povmt_declare declares, before the mesh, a function
 * rgl_mt<id>a sampling image img of pt; povmt_env_texture writes a whole
 * unlit texture{ } whose pigment is that environment applied to colour cf
 * per channel, as povmt_pigment's second unit. Both return 0, or -1 on
 * failure (nothing written). */
int povmt_declare(outbuf *ob, const povtex *pt, size_t img, const scene_texture *t, unsigned id);
int povmt_env_texture(outbuf *ob, const scene_texture *t, unsigned id, const float cf[4]);

/* The same environments on a lit surface (povlight_texture_env): lit gets
 * the pigment the lit colour multiplies (GL_BLEND: 1 - Ct per channel,
 * times tint when not NULL; GL_ADD: empty, the material's own colour),
 * env the one added (Cc Ct; Ct). Returns 0, or -1 when a buffer is too
 * small. */
/* The pigment of image function rgl_mt<id>a (povmt_declare) times tint
 * per channel (GL_MODULATE of a lit colour-material surface whose colours
 * vary: one per texture_list entry). Returns 0, or -1 when buf is too
 * small. */
int povmt_tinted(const scene_texture *t, unsigned id, const float tint[3], char *buf, size_t cap);

int povmt_env_lit(const scene_texture *t, unsigned id, const float tint[3], char *lit, size_t lcap,
                  char *env, size_t ecap);

#endif
