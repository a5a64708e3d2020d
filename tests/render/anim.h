/* anim.h: a small animated trace for the rendering tests and benchmark:
 * frame i is a cube turned by 360*i/n degrees over a checkered floor,
 * under gluPerspective(45) and gluLookAt(0,3,7 -> 0,0,0, up y). */
#ifndef RGL_ANIM_H
#define RGL_ANIM_H

#include "tracegen.h"

#define ANIM_EYE 0, 3, 7
#define ANIM_FOVY 45.0

/* Appends frame i of n (viewport w x h) to s. */
void anim_frame(seq *s, int i, int n, int w, int h);

#endif
