/* povwrite_pstipple.h: polygon stipple in SDL (povwrite_pstipple.c). */
#ifndef RGL_POVWRITE_PSTIPPLE_H
#define RGL_POVWRITE_PSTIPPLE_H

#include "outbuf.h"
#include "scene.h"

/* Writes look's polygon stipple as a clipped_by keeping the points whose
 * window pixel has its mask bit set, to be placed after the object's
 * matrix (in eye space); nothing when the look is not stippled. */
void povwrite_pstipple(outbuf *ob, const scene *s, const scene_look *look);

#endif
