/* povwrite_solid.h: GLU/GLUT solids (scene_solid) as POV-Ray solids. */
#ifndef RGL_POVWRITE_SOLID_H
#define RGL_POVWRITE_SOLID_H

#include "outbuf.h"
#include "povwrite_light.h"
#include "scene.h"

/* Writes the declarations the solids use (the teapot's patches), before
 * the scene's union. */
void povwrite_solid_declares(outbuf *ob, const scene *s);

/* Writes every solid of the scene, each in its object space with its
 * matrix (inside the scene's union, so the near/far clip applies). */
void povwrite_solids(outbuf *ob, const scene *s, const povlight *pl);

/* Writes "// names: 1 4" and a newline: the name stack (bottom first) that
 * look.names value `names` stands for; nothing for 0. */
void povwrite_names(outbuf *ob, const scene *s, uint32_t names);

/* Writes clipped_by{...}: the planes through the camera's rays along the
 * edges of a scissored look's box (scene.h), which keep what the box
 * shows; nothing for a look that is not scissored. */
void povwrite_scissor(outbuf *ob, const scene *s, const scene_look *look);

/* The eye-space centre of the first solid, for the union's anchor; false
 * when there is none. */
bool povwrite_solid_anchor(const scene *s, float out[3]);

#endif
