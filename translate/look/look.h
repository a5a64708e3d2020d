/* look.h: the look step: what raygl2pov's re-translation options change in
 * a built scene before any writer sees it (--width/--height, --camera-*,
 * --override-space, --no-gl-lights, --light, and the ray-tracing and
 * render options --no-shadows, --reflection, --area-lights, --radiosity,
 * --antialias, --quality: scene.options). It edits the scene and nothing
 * else; each writer gives what the edited scene says as its format can.
 * cli/options_look.c parses the options into a look_settings.
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

#include "scene.h"

/* The largest --width or --height. */
#define LOOK_MAX_SIZE 65536

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
    scene_options options; /* --no-shadows ... --quality, as the scene takes them
                              (world_view is the step's) */
    const char **includes; /* --include, as given (paths): the writers' business
                              (writer.h, writer_trace) */
    size_t nincludes, cap_includes;
} look_settings;

/* Frees what the option setters allocated. */
void look_free(look_settings *l);

/* True when any option changes the camera. */
bool look_overrides_camera(const look_settings *l);

/* Applies l to a built scene: size, camera, --no-gl-lights, then the
 * added lights (scene_light.added, in eye space through s->view) and
 * scene.options. Returns 0, or -1 when memory ran out (s->failed).
 * *note: NULL, or a note for the user (the override space used; static). */
int look_apply(const look_settings *l, scene *s, const char **note);

#endif
