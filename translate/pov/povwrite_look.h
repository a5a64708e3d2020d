/* povwrite_look.h: what the look step (look/look.c) put into the scene
 * beyond GL's picture, as POV-Ray SDL and INI lines: private to the
 * POV-Ray writer (povwrite.c, pov_writer.c).
 */
#ifndef RGL_POVWRITE_LOOK_H
#define RGL_POVWRITE_LOOK_H

#include <stddef.h>

#include "outbuf.h"
#include "scene.h"

/* After the scene's own SDL: radiosity (scene.options) and the added
 * lights (scene_light.added), in eye space. */
void povlook_scene(outbuf *ob, const scene *s);

/* Then the user's include files, copied into the output folder as names:
 * RayGL_World (world -> eye, scene.view when the look was given in world
 * coordinates) and one #include line each. Nothing when n is 0. */
void povlook_includes(outbuf *ob, const scene *s, const char *const *names, size_t n);

/* INI lines after pov_write_ini's: antialiasing, quality. */
void povlook_ini(outbuf *ob, const scene_options *o);

/* Copies each of paths[0..n-1] into dir as "include-N-NAME" (NAME reduced
 * to [A-Za-z0-9._-]), atomically; an unchanged copy is left as it is.
 * Fills *names (free with povlook_free_names) or returns -1 with a
 * message in msg. */
int povlook_copy_includes(const char *const *paths, size_t n, const char *dir, char ***names,
                          char *msg, size_t cap);
void povlook_free_names(char **names, size_t n);

#endif
