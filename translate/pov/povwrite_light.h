/* povwrite_light.h: the POV-Ray writer's lighting part (povwrite_light.c):
 * GL lights as light_source, GL materials as finishes, blending as
 * transmit, fog as a texture layer. Private to the writer (povwrite.c).
 */
#ifndef RGL_POVWRITE_LIGHT_H
#define RGL_POVWRITE_LIGHT_H

#include <stdbool.h>

#include "outbuf.h"
#include "povwrite.h"
#include "scene.h"

/* How many triangles ahead the passes over a mesh's triangles prefetch the
 * vertex pool: the pool (56 bytes a vertex, megabytes a frame) comes from
 * L3 or memory at each pass, and the hardware's prefetch alone left the
 * scene box and the colour test waiting on its loads. */
#define POOL_AHEAD 48

/* What the lighting part needs about the whole scene, computed once per
 * frame by povlight_begin. */
typedef struct povlight {
    const scene *s;
    scene_options opt; /* the scene's (scene.options) */
    double centre[3]; /* of the drawn geometry's bounding box, eye space */
    double radius;    /* half its diagonal (at least a small positive value) */
    float light_ambient[3]; /* sum of the GL lights' ambient, attenuated at the centre */
    /* Light sets (scene_light.set): per set, whether an object of the
     * frame uses it, its lights' ambient as light_ambient, and the multiple
     * of the diffuse colour its highlights take with shadows on. groups:
     * more than one set is used, each lights its objects in a light_group;
     * pass: which objects the writer writes now (POVLIGHT_ALL, or a set's,
     * or POVLIGHT_UNGROUPED: the rest). */
    bool groups;
    int32_t pass;
    uint8_t used[SCENE_MAX_LIGHTSETS];
    float set_ambient[SCENE_MAX_LIGHTSETS][3];
    double set_ratio[SCENE_MAX_LIGHTSETS];
    /* With shadows, a set whose lights' specular is one multiple of their
     * diffuse per channel (channel[k] > 0; none textured): lights of their
     * specular colour, pigments scaled by 1 / channel. */
    double set_channel[SCENE_MAX_LIGHTSETS][3];
} povlight;

#define POVLIGHT_ALL (-2)
#define POVLIGHT_UNGROUPED (-1)

/* Fills pl for scene s (options may be NULL: the defaults). */
void povlight_begin(povlight *pl, const scene *s);

/* True when a run needs more than the plain unlit texture{pigment{rgb}}. */
bool povlight_special(const scene_look *look);

/* One texture{...} for a face side (0 front, 1 back) of a run with look,
 * vertex colour c (GL_COLOR_MATERIAL's colour and the coverage alpha,
 * scene_vertex.color). */
void povlight_texture(const povlight *pl, outbuf *ob, const scene_look *look, const float c[4],
                      int side);

/* The same without the texture{ } around it (for interior_texture{ }). */
void povlight_texture_body(const povlight *pl, outbuf *ob, const scene_look *look,
                           const float c[4], int side);

/* The body of a texture whose pigment is `pigment` (the text inside
 * pigment{ }: a texture image) multiplied by GL's lit or unlit colour of
 * look and c, as GL_MODULATE does (finish terms unscaled; lit, diffuse is
 * the mean of the material's, exact for grey materials). */
void povlight_texture_mapped(const povlight *pl, outbuf *ob, const scene_look *look,
                             const float c[4], int side, const char *pigment);

/* GL_MODULATE of a lit surface whose diffuse colour is not grey (GL 1.5
 * table 3.22 applied per channel): true when one image can carry it, with
 * kdp the diffuse colour (channels floored to a share of the largest) and
 * tint = kdp / max(kdp), what the writer multiplies the texels by
 * (povtex_map). c: the mesh's one vertex colour (GL_COLOR_MATERIAL's
 * diffuse), NULL when the colours vary. False for grey or unlit surfaces
 * and for two-sided materials whose sides differ. */
bool povlight_modulate_tint(const povlight *pl, const scene_look *look, const float *c,
                            float kdp[3], float tint[3]);

/* GL_BLEND and GL_ADD of a lit surface (GL 1.5 table 3.22): a whole
 * texture{ } averaging the lit surface, its pigment lit_pigment (NULL:
 * the material's colour; made with kdp's tint as povlight_texture_tinted,
 * or kdp NULL), and the unlit env_pigment, each at twice its weight: the
 * lit colour times lit_pigment plus env_pigment. */
void povlight_texture_env(const povlight *pl, outbuf *ob, const scene_look *look, const float c[4],
                          int side, const char *lit_pigment, const float *kdp,
                          const char *env_pigment);

/* povlight_texture_mapped for a pigment made with povlight_modulate_tint's
 * tint: diffuse max(kdp), ambient and emission per channel over the tint. */
void povlight_texture_tinted(const povlight *pl, outbuf *ob, const scene_look *look,
                             const float c[4], int side, const char *pigment, const float kdp[3]);

/* The fog layer of a mesh whose object space goes to eye space by to_eye
 * (NULL: already eye space), declared as `name`:
 * `#declare name=texture{...}` and a newline; distance: the eye distance
 * the factor takes (enum scene_fog_distance). */
void povlight_fog_declare(const povlight *pl, outbuf *ob, const char *name, const mat4 *to_eye,
                          int distance);

/* Point p (object space) in eye space through to_eye (NULL: eye space):
 * mat4_apply's sums without the w row and the multiply by w = 1 (m * 1 is
 * m), so the same doubles. Inline: called for every lit vertex. */
static inline void povlight_eye_point(const mat4 *to_eye, const float p[3], double out[3])
{
    double x = p[0], y = p[1], z = p[2];
    if (!to_eye) {
        out[0] = x, out[1] = y, out[2] = z;
        return;
    }
    const double *m = to_eye->m;
    out[0] = m[0] * x + m[4] * y + m[8] * z + m[12];
    out[1] = m[1] * x + m[5] * y + m[9] * z + m[13];
    out[2] = m[2] * x + m[6] * y + m[10] * z + m[14];
}

/* Whether a triangle (a, b, c in eye space, counter-clockwise front first)
 * shows its front to the camera. */
bool povlight_front_facing(const povlight *pl, const double a[3], const double b[3],
                           const double c[3]);

/* The normal n (object space) of a vertex at eye-space point p on a
 * front-facing lit face, turned just far enough toward the camera that
 * POV-Ray does not flip it (see the .c); out = n when it faces the camera
 * already. to_eye_inv is to_eye's inverse, computed once per mesh (NULL
 * with to_eye set: singular, n is kept). */
void povlight_front_normal(const povlight *pl, const mat4 *to_eye, const mat4 *to_eye_inv,
                           const double p[3], const float n[3], float out[3]);

/* The light_source statements of the scene's GL lights (with groups: the
 * lights that light everything, rayglFrameBegin's). */
void povlight_lights(const povlight *pl, outbuf *ob);

/* The light set of a look's objects, POVLIGHT_UNGROUPED for an unlit one or
 * without groups. */
int32_t povlight_look_set(const povlight *pl, const scene_look *look);

/* Whether an object of this look belongs to the writer's current pass. */
bool povlight_in_pass(const povlight *pl, const scene_look *look);

/* The light_source statements of light set `set` (inside its
 * light_group). */
void povlight_set_lights(const povlight *pl, outbuf *ob, uint32_t set);

#endif
