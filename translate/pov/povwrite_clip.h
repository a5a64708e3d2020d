/* povwrite_clip.h: user clip planes in SDL (povwrite_clip.c). */
#ifndef RGL_POVWRITE_CLIP_H
#define RGL_POVWRITE_CLIP_H

#include "outbuf.h"
#include "scene.h"

/* Writes look's user clip planes as a clipped_by of eye-space planes, to be
 * placed after the object's matrix; nothing when it has none. */
void povwrite_clip(outbuf *ob, const scene *s, const scene_look *look);

/* Writes look's stencil region (interp_stencil.c) as a clipped_by of the
 * union of its triangles' cones of rays from the camera (inverse when the
 * look is kept outside it), after the object's matrix; nothing when it
 * has none. */
void povwrite_stencil(outbuf *ob, const scene *s, const scene_look *look);

#endif
