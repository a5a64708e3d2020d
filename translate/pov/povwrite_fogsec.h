/* povwrite_fogsec.h: the fog layer of one mesh or solid, by its eye
 * distance or by one fog coordinate (povwrite_fogsec.c). */
#ifndef RGL_POVWRITE_FOGSEC_H
#define RGL_POVWRITE_FOGSEC_H

#include "mat4.h"
#include "outbuf.h"
#include "povwrite_light.h"
#include "scene.h"

/* Writes `#declare name=texture{...}`: the scene's fog colour with
 * transmit f, where f is look->fog_f when look->fog_fixed (a draw fogged
 * by one fog coordinate), else the eye-distance function of
 * povlight_fog_declare (to_eye: the object's matrix to eye space). */
void povfog_declare(const povlight *pl, outbuf *ob, const char *name, const mat4 *to_eye,
                    const scene_look *look);

#endif
