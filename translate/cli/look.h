/* look.h: the re-translation settings that change how a frame looks
 * (--width/--height, --camera-*, --no-gl-lights, --light, --antialias,
 * --quality, --radiosity, --include): parsed by the setters in look.c,
 * applied to a translated scene before it is written, and written as SDL
 * and INI lines appended after the POV-Ray writer's own output, so that the
 * writer (povwrite.c) stays as it is.
 *
 * Coordinates: camera and light overrides are in the scene's world
 * coordinates when the frame has a view transform (scene.have_view: the
 * modelview just after its first gluLookAt; or a rayglFrameBegin frame,
 * whose eye space is the paper's world), in GL eye coordinates otherwise
 * (or always, with --override-space eye).
 */
#ifndef RGL_LOOK_H
#define RGL_LOOK_H

#include <stdbool.h>
#include <stddef.h>

#include "outbuf.h"
#include "scene.h"

typedef enum look_light_kind {
    LOOK_LIGHT_POINT,
    LOOK_LIGHT_PARALLEL,
    LOOK_LIGHT_SPOT,
    LOOK_LIGHT_AREA,
} look_light_kind;

typedef struct look_light {
    look_light_kind kind;
    double at[3], to[3], color[3];
    double radius, falloff; /* spot, degrees */
    double size[2];         /* area: extent along its two axes */
    int samples[2];         /* area: lights along each axis */
} look_light;

typedef struct look_settings {
    int width, height; /* 0: the GL viewport's */
    bool has_location, has_look_at, has_up, has_fov, orthographic, eye_space;
    double location[3], look_at[3], up[3], fov;
    bool no_gl_lights;
    look_light *lights;
    size_t nlights, cap_lights;
    bool antialias, radiosity;
    int quality; /* 0: POV-Ray's default */
    const char **includes; /* as given (paths) */
    size_t nincludes, cap_includes;
} look_settings;

/* Frees what the setters allocated. */
void look_free(look_settings *l);

/* True when any option changes the camera. */
bool look_overrides_camera(const look_settings *l);

/* Applies size, camera and --no-gl-lights to a translated scene. Returns
 * NULL, or a note for the user (e.g. the override space used). */
const char *look_apply(const look_settings *l, scene *s);

/* The SDL appended after the writer's scene: radiosity, the added lights
 * (in eye space, through s->view) and the #include lines of the copied
 * include files (bare names inside the output folder). Returns 0 or -1. */
int look_write_scene(outbuf *ob, const look_settings *l, const scene *s,
                     const char *const *include_names, size_t ninclude);

/* The added lights (--light) as scene lights in eye space, for a writer
 * that reads only the scene model (the glTF writer); the POV-Ray output
 * writes them with look_write_scene instead. Returns 0 or -1 (memory). */
int look_add_lights(const look_settings *l, scene *s);

/* INI lines appended after pov_write_ini's: antialiasing, quality. */
int look_write_ini(outbuf *ob, const look_settings *l);

/* Copies each --include file into dir as "include-N-NAME" (NAME reduced to
 * [A-Za-z0-9._-]), atomically. Fills names[i] (allocated; free with
 * look_free_names) or returns -1 with a message in msg. */
int look_copy_includes(const look_settings *l, const char *dir, char ***names, char *msg,
                       size_t cap);
void look_free_names(char **names, size_t n);

/* Whether files a and b hold the same bytes (an unchanged output is left
 * in place, keeping its time, so what was rendered from it stays up to date). */
bool files_same(const char *a, const char *b);

#endif
