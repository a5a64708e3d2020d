/* scenes.h: small frames shared by the translator's tests (scenes.c). */
#ifndef RGL_TR_SCENES_H
#define RGL_TR_SCENES_H

#include "tracegen.h"

void scene_paper_box(seq *s);
void scene_smooth(seq *s);
void scene_lines_points(seq *s);
void scene_faces(seq *s);
void scene_framebegin(seq *s, const char *name);
void scene_awkward(seq *s);

#endif
