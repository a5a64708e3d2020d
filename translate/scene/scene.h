/* scene.h: the neutral scene model between the interpreter and the writers.
 *
 * The interpreter (gl/) fills a scene from GL commands; the look step
 * (look/) edits it with raygl2pov's re-translation options (camera, size,
 * added lights, scene.options); a writer turns it into files: pov/
 * (POV-Ray SDL and .ini, povwrite.h) or gltf/ (binary glTF, gltfwrite.h),
 * each reached by the driver through writer.h. Nothing here knows GL, SDL
 * or glTF: the model speaks of cameras, meshes, lines, points, lights, in
 * named spaces:
 *
 *   eye space     GL eye coordinates of the frame's camera: the camera sits
 *                 at the origin looking down -z, right-handed, as in GL.
 *                 Lines, points, lights and the camera live here.
 *   object space  what glVertex received; each mesh carries the matrix that
 *                 takes its object space to eye space (the modelview, or the
 *                 modelview remapped into the camera's projection).
 *
 * For a frame started by rayglFrameBegin, "eye space" is the paper's world:
 * the modelview places objects in it and the camera looks at it with
 * look_at, as the paper's POV-Ray output did.
 *
 * Memory: one growable pool each for vertices, triangles, lines and points;
 * meshes index into the pools. The first allocation failure makes the scene
 * sticky-failed (scene.failed): later additions are dropped, and the caller
 * reports the frame as failed. Not thread-safe; one scene per worker.
 */
#ifndef RGL_SCENE_H
#define RGL_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mat4.h"

/* Hard limits: a frame over them is cut (with a diagnostic), never a crash. */
#define SCENE_MAX_VERTICES (1u << 30)
#define SCENE_MAX_ITEMS (1u << 30)

/* One vertex as GL assembled it: object-space position (after dividing by
 * w), the current normal, the colour GL uses for it (clamped to [0, 1]) and
 * texture coordinates (s/q, t/q). */
typedef struct scene_vertex {
    float pos[3];
    float normal[3];
    float color[4];
    float tex[2];
    float tex1[2]; /* of the look's second texture (texture1) */
} scene_vertex;

/* A triangle: absolute vertex indices in the pool, front face first in GL's
 * counter-clockwise sense (the interpreter reorders for glFrontFace(GL_CW)),
 * and the provoking vertex whose colour a flat-shaded face takes. */
typedef struct scene_tri {
    uint32_t v[3];
    uint32_t provoking;
} scene_tri;

/* Everything that makes two runs of triangles look different. Compared
 * bytewise (scene_look_equal): build it zeroed. */
typedef struct scene_look {
    uint8_t lit;       /* GL_LIGHTING was on (issue 4: lit materials) */
    uint8_t flat;      /* GL_FLAT: one colour per face, the provoking vertex's */
    uint8_t blend;     /* SCENE_BLEND_*: how the colour behind shows through */
    uint8_t fog;       /* GL_FOG was on */
    uint8_t scissored;  /* the scissor test cut it to `scissor` */
    uint8_t alpha_test; /* SCENE_ALPHA_*: GL_ALPHA_TEST's function */
    uint8_t pad_[2];
    int32_t material;  /* index into scene.materials when lit, else -1 */
    int32_t texture;   /* index into scene.textures, -1 for none (issue 5) */
    uint32_t names;    /* the name stack (glPushName) it was drawn under: 1 +
                          its place in scene.names (scene_names), 0: empty */
    int32_t scissor[4]; /* x, y, width, height in pixels of the camera's
                           image (origin at its lower left), when scissored */
    int32_t texture1;  /* a second texture unit's, combined with the result of
                          the first by its env_mode (GL 2.1 3.8.13), or -1 */
    float alpha_ref;   /* the alpha test's reference, for SCENE_ALPHA_ABOVE */
    uint32_t clip;     /* its user clip planes: 1 + their set's place in
                          scene.clips (scene_clip_index), 0: none */
    uint32_t stencil_first, stencil_n; /* the stencil test keeps it to the
                          window region of scene.stencil_tris [first, first +
                          n) (or outside it, stencil_out); n 0: none */
    float fog_f;       /* with fog_fixed: the fog factor of the whole draw (one
                          fog coordinate for all its vertices) */
    uint8_t stencil_out, fog_fixed;
    uint8_t fog_own, pad2_[1]; /* fogged by fog_plane, not by the eye-plane distance */
    float fog_plane[4]; /* GL's fog coordinate a.p + d over the mesh's own space,
                           for faces reaching behind the eye (interp_fogbehind.c) */
    uint32_t pstipple; /* polygon stipple: only window pixels whose bit is set
                          in the mask at 1 + its place in scene.pstipples
                          (scene_pstipple_index); 0: none */
    uint8_t pstipple_org[2]; /* the window position of the image's lower left, mod 32 */
    uint8_t pad3_[2];
    float filter; /* with SCENE_BLEND_ALPHA: the share of what is behind that
                     shows multiplied by the colour (POV-Ray's filter); the
                     colour's alpha is then the surface's own share, the
                     rest passes unchanged (transmit 1 - filter - alpha) */
} scene_look;

/* The alpha test of a look (glAlphaFunc with GL_ALPHA_TEST on). */
enum {
    SCENE_ALPHA_OFF = 0,   /* off, or GL_ALWAYS */
    SCENE_ALPHA_ABOVE = 1, /* GL_GREATER, GL_GEQUAL: fragments from alpha_ref up */
    SCENE_ALPHA_NEVER = 2, /* GL_NEVER: nothing drawn */
    SCENE_ALPHA_OTHER = 3, /* GL_LESS, GL_LEQUAL, GL_EQUAL, GL_NOTEQUAL */
};

/* A run of triangles sharing transform and look: one mesh to a writer. */
typedef struct scene_mesh {
    mat4 to_eye;   /* object -> eye space; identity when in_eye */
    bool in_eye;   /* vertices are already in eye space (projective input) */
    scene_look look;
    size_t first_tri, tri_count; /* range in scene.tris */
    uint32_t proto; /* 0: drawn as itself; k: part of protos[k - 1] */
} scene_mesh;

/* Display lists whose calls drew the same meshes (issue 5,
 * interp_list.c): the meshes of a prototype are written once, each
 * with its to_eye taken relative to the prototype's space, and each call
 * is an instance placing the prototype with its own matrix. */
typedef struct scene_proto {
    size_t first_mesh, nmeshes; /* range in scene.meshes */
} scene_proto;

typedef struct scene_instance {
    uint32_t proto; /* index into scene.protos */
    mat4 to_eye;    /* prototype space -> eye space */
} scene_instance;

/* A strip of a line in eye space: a flat quad facing the camera, from
 * p[0] to p[1], whose edges lie at p[i] +- half[i] (eye-space vectors
 * parallel to the image plane). The interpreter sizes and places the
 * strips of a line so that their image covers exactly the pixels GL
 * lights for it (docs/mapping.md section 7). */
typedef struct scene_line {
    float p[2][3];
    float half[2][3];
    /* at the corners p[0] - half[0], p[0] + half[0], p[1] + half[1],
     * p[1] - half[1]; all equal when flat shaded */
    float color[4][4];
} scene_line;

/* A rectangle of a point's pixels in eye space, at the point's depth
 * (GL clips points by their centre: the interpreter keeps those GL
 * draws): corners at p +- right +- up (half extents along the image
 * axes). A square point is one; a round one (GL_POINT_SMOOTH) one per
 * run of alike rows of its pixels. */
typedef struct scene_point {
    float p[3];
    float right[3], up[3];
    float color[4];
} scene_point;

typedef enum scene_camera_kind {
    SCENE_CAMERA_PERSPECTIVE, /* from a projection with a centre */
    SCENE_CAMERA_ORTHOGRAPHIC,
    SCENE_CAMERA_LOOKAT, /* rayglFrameBegin: location + look_at */
} scene_camera_kind;

/* The camera in eye space, as the rays it casts (a ray tracer's camera): a ray
 * for image coordinates (u, v) in [-1/2, 1/2]^2 (u right, v up) starts at
 * location (+ u*right + v*up for orthographic) and runs along
 * direction + u*right + v*up (perspective) or direction (orthographic).
 * clip holds GL's near and far planes as half-spaces a.xyz . p + a.w >= 0
 * that visible points satisfy. */
typedef struct scene_camera {
    scene_camera_kind kind;
    double location[3], right[3], up[3], direction[3];
    double look_at[3]; /* LOOKAT only */
    bool has_clip;
    double clip[2][4];
    int width, height; /* image size in pixels: the GL viewport */
} scene_camera;

typedef enum scene_light_kind {
    SCENE_LIGHT_PARALLEL, /* GL w = 0, or rayglFrameBegin's white light */
    SCENE_LIGHT_POINT,    /* GL w != 0, cutoff 180 */
    SCENE_LIGHT_SPOT,     /* GL w != 0, cutoff <= 90 */
} scene_light_kind;

/* A light in eye space with all of GL's terms (GL 1.x 2.13.1). For a GL
 * parallel light, direction points toward the light and the writer places
 * it outside the scene; rayglFrameBegin's light has a position and a
 * point_at instead (aimed). */
typedef struct scene_light {
    scene_light_kind kind;
    bool aimed;          /* position and point_at given (rayglFrameBegin) */
    double position[3];  /* POINT, SPOT, aimed PARALLEL */
    double point_at[3];  /* aimed PARALLEL */
    double direction[3]; /* PARALLEL: toward the light; SPOT: GL's spot direction */
    float color[3];      /* GL_DIFFUSE */
    float ambient[3], specular[3];
    float spot_exponent, spot_cutoff;   /* degrees */
    float attenuation[3];               /* constant, linear, quadratic */
    uint32_t set;        /* the light set it belongs to (not aimed lights) */
    /* A light the look step added (look/look.c, raygl2pov --light): aimed,
     * lighting everything. spot_radius: a spot's cone of full intensity
     * (degrees; spot_cutoff is where it ends). An area light (area_samples
     * set) is a POINT at its centre spreading over area_axis[0] and
     * area_axis[1] (eye-space vectors across it), sampled n x m. */
    bool added;
    float spot_radius;
    double area_axis[2][3];
    int area_samples[2];
} scene_light;

/* Light sets (docs/mapping.md "Lights per object"): the GL lights of a lit
 * draw are one set; a later draw under other lights opens another, and its
 * materials name it (scene_material.lightset). A set's lights are
 * consecutive in scene.lights. Aimed lights light everything. */
#define SCENE_MAX_LIGHTSETS 256

/* A GL material, front [0] and back [1], as the lit runs that refer to it
 * saw it (GL 1.x 2.13.1). color_material names the terms (SCENE_CM_* bits,
 * per face) that come from each vertex's colour instead (GL_COLOR_MATERIAL);
 * model_ambient is GL_LIGHT_MODEL_AMBIENT then. With two_sided false both
 * sides of a face use the front material. */
enum {
    SCENE_CM_AMBIENT = 1,
    SCENE_CM_DIFFUSE = 2,
    SCENE_CM_SPECULAR = 4,
    SCENE_CM_EMISSION = 8,
};

typedef struct scene_material {
    float ambient[2][4], diffuse[2][4], specular[2][4], emission[2][4];
    float shininess[2];
    float model_ambient[4];
    uint8_t color_material[2];
    bool two_sided;
    bool local_viewer;
    uint32_t lightset; /* the lights that light it (scene_light.set) */
} scene_material;

/* How the colour behind a face shows through it (glBlendFunc with
 * GL_BLEND on). ALPHA is GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA: the face
 * lets 1 - alpha of what is behind through. */
enum {
    SCENE_BLEND_OPAQUE = 0,
    SCENE_BLEND_ALPHA = 1,     /* transmit 1 - alpha */
    SCENE_BLEND_INVISIBLE = 2, /* GL_ZERO, GL_ONE: nothing drawn */
};

/* What the look step asks of the picture beyond GL's (look/look.c:
 * raygl2pov's ray-tracing and render options), for every writer to give as
 * its format can. All zero: GL's look, as the writers give it by default. */
typedef struct scene_options {
    bool no_shadows;  /* nothing casts shadows */
    float reflection; /* lit surfaces mirror their surroundings by this, 0 to 1 */
    int area_lights;  /* N: the GL lights cast soft shadows, as discs of N x N
                         samples; 0: as points */
    bool radiosity;   /* global illumination: light bounces off surfaces */
    bool antialias;   /* the image antialiased */
    int quality;      /* the renderer's quality on POV-Ray's scale (1 to 11;
                         -1: 0); 0: the renderer's default */
    bool world_view;  /* the look's camera and lights were given in world
                         coordinates: scene.view takes them to eye space */
} scene_options;

/* The eye distance c that glFog's factor takes (NV_fog_distance). */
enum scene_fog_distance {
    SCENE_FOG_ABS_Z = 0, /* |z_eye|: GL_EYE_PLANE_ABSOLUTE_NV, Mesa's default */
    SCENE_FOG_Z = 1,     /* z_eye, negative in front of the eye: GL_EYE_PLANE */
    SCENE_FOG_RADIAL = 2 /* sqrt(x^2 + y^2 + z^2) in eye space: GL_EYE_RADIAL_NV */
};

/* glFog, in eye space: GL's fog factor of the eye distance c (distance). */
enum {
    SCENE_FOG_LINEAR = 1, /* GL_LINEAR: (end - c) / (end - start) */
    SCENE_FOG_EXP,        /* GL_EXP: e^-(density c) */
    SCENE_FOG_EXP2,       /* GL_EXP2: e^-((density c)^2) */
};

typedef struct scene_fog {
    bool on;
    int mode; /* SCENE_FOG_* */
    float density, start, end, color[4];
    int distance; /* enum scene_fog_distance */
} scene_fog;

/* How a texture's colour and the fragment's combine (glTexEnv's
 * GL_TEXTURE_ENV_MODE; GL 2.1 3.8.13, table 3.22); 0: none given. */
enum {
    SCENE_ENV_MODULATE = 1, /* GL_MODULATE: their product */
    SCENE_ENV_REPLACE,      /* GL_REPLACE: the texel's */
    SCENE_ENV_DECAL,        /* GL_DECAL: the texel over the fragment by its alpha */
    SCENE_ENV_BLEND,        /* GL_BLEND: the fragment's and env_color mixed by the texel */
    SCENE_ENV_ADD,          /* GL_ADD: their sum */
};

/* A comparison of the alpha test (glAlphaFunc, GL 1.x 4.1.4): the fragment
 * passes when its alpha compares so with the reference; 0: no test. */
enum {
    SCENE_CMP_NEVER = 1,
    SCENE_CMP_LESS,
    SCENE_CMP_EQUAL,
    SCENE_CMP_LEQUAL,
    SCENE_CMP_GREATER,
    SCENE_CMP_NOTEQUAL,
    SCENE_CMP_GEQUAL,
    SCENE_CMP_ALWAYS,
};

/* Mipmapped minification (GL's GL_<texel>_MIPMAP_<level> filters, GL 2.1
 * 3.8.8): nearest or linear texels within a level, from the nearest level
 * or blended between the two nearest; 0: not mipmapped. */
enum {
    SCENE_MIP_NEAREST_MIPMAP_NEAREST = 1,
    SCENE_MIP_LINEAR_MIPMAP_NEAREST,
    SCENE_MIP_NEAREST_MIPMAP_LINEAR,
    SCENE_MIP_LINEAR_MIPMAP_LINEAR,
};

/* An image the scene maps (issue 5): level 0 of a GL texture as the GL
 * texels it holds (RGBA, 8 bits, bottom row first), with how GL samples it.
 * The pixels belong to the scene (freed by scene_reset). hash names the
 * image by its content (the writer's file name). */
typedef struct scene_texture {
    uint8_t *rgba;
    int width, height;
    uint64_t hash;           /* of the size and texels (scene_add_texture) */
    bool repeat_s, repeat_t; /* GL_REPEAT; else clamped */
    bool mirror_s, mirror_t; /* repeated as GL_MIRRORED_REPEAT */
    bool border_s, border_t; /* clamped as GL_CLAMP (the border colour counts
                                under linear filtering), not GL_CLAMP_TO_EDGE */
    bool to_border_s, to_border_t; /* GL_CLAMP_TO_BORDER: the border colour
                                outside the texture, under either filter */
    float border[4];         /* GL_TEXTURE_BORDER_COLOR */
    bool linear;             /* magnification GL_LINEAR */
    uint32_t env_mode;       /* SCENE_ENV_* */
    float env_color[4];
    bool colour_is_texel;    /* the texel's colour replaces the fragment's
                                (REPLACE or DECAL of a colour format) */
    /* The alpha test per texel (interp_alphatest.c), when the texel's
     * alpha counts: SCENE_CMP_*, 0 for none; the fragment's alpha is the
     * texel's times the vertex alpha when alpha_uses_af. */
    uint32_t alpha_func;
    float alpha_ref, alpha_af; /* alpha_af: the draw's vertex alpha */
    bool alpha_uses_af;
    /* Mipmapped minification (issue 14): the minification filter when it
     * mipmaps (SCENE_MIP_*, else 0), the scene texture of the next level
     * (-1 at the last; each level an image of its own, same sampling), and
     * the LOD clamps (GL_TEXTURE_MIN_LOD, MAX_LOD, relative to this level). */
    uint32_t mip_filter;
    int32_t mip_next;
    float min_lod, max_lod;
    float lod_bias; /* added to lambda before the clamp (GL_TEXTURE_LOD_BIAS) */
    /* A cube map (GL_TEXTURE_CUBE_MAP): this is face +X, and mip_next
     * links -X, +Y, -Y, +Z, -Z in turn (mip_filter 0); the coordinates are
     * the vertices' (tex[0], tex[1], tex1[0]) = (s, t, r). */
    bool cube;
} scene_texture;

/* Whether a texture's alpha test is drawn on the filtered alpha (GL_LINEAR
 * and a comparison with a side: the writer's pigment_map by transmit),
 * rather than texel by texel in the image. */
static inline bool scene_alpha_crisp(const scene_texture *t)
{
    return t->linear && !t->mip_filter && !t->cube && t->alpha_func >= SCENE_CMP_LESS &&
           t->alpha_func <= SCENE_CMP_GEQUAL && t->alpha_func != SCENE_CMP_EQUAL &&
           t->alpha_func != SCENE_CMP_NOTEQUAL;
}

/* Whether alpha a passes the alpha test func (SCENE_CMP_*; 0 and ALWAYS
 * pass everything) against ref (GL 1.x 4.1.4). */
static inline bool scene_alpha_pass(uint32_t func, float a, float ref)
{
    switch (func) {
    case SCENE_CMP_NEVER: return false;
    case SCENE_CMP_LESS: return a < ref;
    case SCENE_CMP_EQUAL: return a == ref;
    case SCENE_CMP_LEQUAL: return a <= ref;
    case SCENE_CMP_GREATER: return a > ref;
    case SCENE_CMP_NOTEQUAL: return a != ref;
    case SCENE_CMP_GEQUAL: return a >= ref;
    default: return true;
    }
}

/* A GLU/GLUT solid, which a writer draws as the exact shape (POV-Ray's
 * sphere, box, cone, torus, disc, bicubic patches) or tessellates (glTF),
 * in its object space (GL's axis conventions), placed by to_eye:
 *   SPHERE  params[0] radius, centred at the origin
 *   BOX     corners -params[0..2] .. +params[0..2]
 *   CONE    base radius params[0] at z=0, top radius params[1] at
 *           z=params[2]; open (no caps) when `open`
 *   TORUS   ring radius params[0], tube radius params[1], in the xy plane
 *           around z
 *   DISC    outer radius params[0], hole radius params[1], in z=0
 *   TEAPOT  freeglut's teapot of size params[0] (teapot.h) */
typedef enum scene_solid_kind {
    SCENE_SOLID_SPHERE, SCENE_SOLID_BOX, SCENE_SOLID_CONE, SCENE_SOLID_TORUS,
    SCENE_SOLID_DISC, SCENE_SOLID_TEAPOT,
} scene_solid_kind;

typedef struct scene_solid {
    scene_solid_kind kind;
    bool open;
    double params[3];
    mat4 to_eye;
    scene_look look;
    float color[4]; /* the current colour (issue 4 adds the material) */
} scene_solid;

typedef struct scene {
    scene_camera camera;
    bool have_camera;
    float background[4]; /* the clear colour */

    scene_vertex *verts;
    size_t nverts, cap_verts;
    scene_tri *tris;
    size_t ntris, cap_tris;
    scene_mesh *meshes;
    size_t nmeshes, cap_meshes;
    scene_line *lines;
    size_t nlines, cap_lines;
    scene_point *points;
    size_t npoints, cap_points;
    scene_light *lights;
    size_t nlights, cap_lights;
    scene_proto *protos;
    size_t nprotos, cap_protos;
    scene_instance *instances;
    size_t ninstances, cap_instances;
    size_t mesh_floor;   /* scene_mesh_for extends no mesh below this index */
    uint32_t generation; /* counts scene_clear_geometry calls */
    scene_fog fog;     /* glFog of the first fogged draw */
    scene_solid *solids;
    size_t nsolids, cap_solids;
    scene_texture *textures; /* look.texture indexes this */
    size_t ntextures, cap_textures;
    scene_material *materials; /* lit runs refer to these by index */
    size_t nmaterials, cap_materials;
    double (*stencil_tris)[9]; /* eye-space triangles drawn into the stencil
                                  buffer (interp_stencil.c) */
    size_t nstencil, cap_stencil;
    uint8_t (*pstipples)[128]; /* polygon stipple masks that looks refer to
                                  (kept apart: a look is per mesh) */
    size_t npstipples, cap_pstipples;
    double (*clips)[4]; /* user clip plane sets that looks refer to: a row
                           {count}, then that many eye-space planes */
    size_t nclips, cap_clips, clips_last;
    uint32_t *names; /* name stacks that looks refer to: a count, then the names */
    size_t nnames, cap_names, names_last; /* names_last: 1 + where the last one starts */
    bool lights_fixed; /* lights hold the GL lights of the first lit draw */
    uint32_t nlightsets; /* light sets in lights, numbered 0.. */
    /* World -> eye: the modelview just after the frame's first gluLookAt
     * (raygl2pov's --camera-* and --light overrides are given in world
     * coordinates when there is one; look.c). */
    bool have_view;
    mat4 view;
    double view_look_at[3]; /* that gluLookAt's centre, world coordinates */
    scene_options options; /* the look step's (look/look.c) */

    /* Bitmaps and pixel rectangles (interp_pixels.c): one RGBA image of
     * overlay_w x overlay_h pixels, the camera's viewport, bottom row
     * first, alpha 0 where none was drawn; shown in front of the scene,
     * unlit, casting no shadow. NULL: none in this frame. */
    uint8_t *overlay;
    int overlay_w, overlay_h;
    /* Set: the overlay lies in the eye-space plane p . e + p[3] = 0 (its
     * pixels' depth, interp_pixdepth.c) instead of in front. */
    bool overlay_at_depth;
    double overlay_plane[4];
    /* What the frame's accumulation-buffer passes add to the one pass the
     * scene holds (interp_accum.c): antialiasing by supersampling to this
     * depth (0: none), and focal blur around focal_point (eye space) through a
     * lens of this diameter. */
    int antialias_depth;
    bool focal_blur;
    double aperture, focal_point[3];
    int blur_samples;

    bool failed; /* an allocation or limit failed; the scene is incomplete */
} scene;

/* The sizes of the geometry pools at one moment, to drop what is added
 * after it (interp_accum.c keeps one pass of several). */
typedef struct scene_mark {
    size_t nverts, ntris, nmeshes, nlines, npoints, nsolids, ntextures, nprotos, ninstances,
        nmaterials;
} scene_mark;

/* Empty scene with no storage. scene_finish frees it; scene_reset empties it
 * and keeps the storage for the next frame. */
void scene_init(scene *s);
void scene_finish(scene *s);
void scene_reset(scene *s);

/* Drops all geometry (glClear of the colour buffer erases what was drawn). */
void scene_clear_geometry(scene *s);

/* The pools' sizes now; scene_truncate drops everything added since mark
 * (and counts as a clear for scene.generation). */
void scene_mark_take(const scene *s, scene_mark *mark);
void scene_truncate(scene *s, const scene_mark *mark);

/* Makes room for n more vertices and returns where they go (the caller
 * fills them and then calls scene_commit_vertices), or NULL on failure. */
scene_vertex *scene_reserve_vertices(scene *s, size_t n);
static inline void scene_commit_vertices(scene *s, size_t n) { s->nverts += n; }

/* The mesh that new triangles go to: the last one when its transform and
 * look are the same (compared at float precision) and it is at or above
 * mesh_floor, else a new one. NULL on failure. */
scene_mesh *scene_mesh_for(scene *s, const mat4 *to_eye, bool in_eye, const scene_look *look);

/* Appends a triangle to the last mesh. Returns false on failure. Inline
 * while the array has room (a call per triangle was a fifth of the
 * interpreter's triangle assembly); scene_add_tri_grow makes room. */
bool scene_add_tri_grow(scene *s, uint32_t a, uint32_t b, uint32_t c, uint32_t provoking);
static inline bool scene_add_tri(scene *s, uint32_t a, uint32_t b, uint32_t c, uint32_t provoking)
{
    if (s->failed || s->nmeshes == 0 || s->ntris >= s->cap_tris)
        return scene_add_tri_grow(s, a, b, c, provoking);
    scene_tri *t = &s->tris[s->ntris++];
    t->v[0] = a;
    t->v[1] = b;
    t->v[2] = c;
    t->provoking = provoking;
    s->meshes[s->nmeshes - 1].tri_count++;
    return true;
}

/* Append items; NULL on failure. The caller fills the returned item. */
scene_line *scene_add_line(scene *s);
scene_proto *scene_add_proto(scene *s);
scene_instance *scene_add_instance(scene *s);
scene_point *scene_add_point(scene *s);
scene_light *scene_add_light(scene *s);
scene_solid *scene_add_solid(scene *s);

/* The index of a texture with these pixels and sampling (the scene takes
 * rgba, which it frees, or frees at once when it already holds an equal
 * texture), or -1 on failure (rgba freed). t->hash is the scene's to set. */
int32_t scene_add_texture(scene *s, const scene_texture *t);
/* Whether a and b are sampled alike: every field but the texels and their
 * hash (size, wrap, filters, environment, alpha test, mipmap link). */
bool scene_texture_sampling_same(const scene_texture *a, const scene_texture *b);

/* Index of a material equal (bytewise) to m in the pool, adding it when
 * new; -1 on failure. Build m zeroed. */
int32_t scene_material_index(scene *s, const scene_material *m);

bool scene_look_equal(const scene_look *a, const scene_look *b);

/* Whether the scene needs what POV-Ray computes only from quality 6 up:
 * a textured or blended mesh, or a translucent pixel of the overlay. */
bool scene_needs_quality6(const scene *s);

/* The one multiple r of their diffuse colours (scene_light.color) that
 * fits the specular colours of lights l[0..n-1] best (least squares over
 * every channel; 0 without diffuse); true when each specular colour is r
 * times its diffuse colour. */
bool scene_lights_specular_ratio(const scene_light *l, size_t n, double *ratio);

/* Per channel k, the one ratio t[k] > 0 of every light's specular to its
 * diffuse (lights without diffuse in a channel have no specular there);
 * false when the lights disagree, or a channel has no specular. */
bool scene_lights_specular_channels(const scene_light *l, size_t n, double t[3]);

/* The look.names value of the name stack names[0..n-1] (bottom first):
 * the last stack added when equal, else a new one; 0 for an empty stack
 * or on failure (the scene is then failed). */
uint32_t scene_names_index(scene *s, const uint32_t *names, uint32_t n);

/* The names of look.names value id and their count in *n; NULL (and 0)
 * for 0 or a value the scene does not hold. */
const uint32_t *scene_names(const scene *s, uint32_t id, uint32_t *n);

/* User clip plane sets (scene_clip.c). scene_clip_index stores n planes
 * (a, b, c, d: eye-space points with a x + b y + c z + d >= 0 are kept)
 * and returns the id a look refers to them by (the last set again when
 * equal); 0 when n is 0 or on failure (the scene's failed flag set).
 * scene_clip_set: the planes of id (NULL, *n = 0 for none or a bad id). */
uint32_t scene_clip_index(scene *s, const double (*planes)[4], uint32_t n);

/* Polygon stipple masks (scene_clip.c): the id a look refers to mask by (the
 * last mask's again when equal), 0 on failure (the scene's failed flag
 * set); scene_pstipple_mask: the mask of id, NULL for a bad id. */
uint32_t scene_pstipple_index(scene *s, const uint8_t mask[128]);
const uint8_t *scene_pstipple_mask(const scene *s, uint32_t id);
const double (*scene_clip_set(const scene *s, uint32_t id, uint32_t *n))[4];

/* Camera from a GL projection matrix and viewport (x, y, width, height).
 * Handles any projection with a centre (perspective, off-axis frustum,
 * rotated or skewed) and any parallel one (orthographic). Returns false,
 * leaving a default orthographic camera of the identity projection, when
 * the matrix is singular, not finite, or projective in a way no camera of
 * rays (scene_camera) reproduces. */
bool scene_camera_from_gl(scene_camera *cam, const mat4 *proj, const int viewport[4]);

/* The camera the paper's rayglFrameBegin asked for: at loc, looking at look,
 * up +y, with the vertical field of view fovy_deg (degrees) and the image
 * size of the viewport. Returns false for a degenerate request (loc equal to
 * look, or looking straight along +-y), leaving a usable camera. */
bool scene_camera_lookat(scene_camera *cam, const double loc[3], const double look[3],
                         double fovy_deg, int width, int height);

/* Window position in pixels (x right, y up, origin at the image centre) of
 * eye point p. Returns false when p is not in front of the camera. */
bool scene_camera_project(const scene_camera *cam, const double p[3], double out[2]);

/* The camera coordinates of eye point p: p = location + x[0] direction +
 * x[1] right + x[2] up. x[0] is the parameter t of the camera's ray through
 * p (location + t (direction + u right + v up) for a perspective camera,
 * u = x[1] / t, v = x[2] / t; offset by t direction for an orthographic
 * one): points on one ray compare their distance by it. Linear in p.
 * Returns false when the camera's axes are degenerate. */
bool scene_camera_coords(const scene_camera *cam, const double p[3], double x[3]);

/* Eye-space size of one pixel (horizontal and vertical) at eye point p.
 * Returns false when p is not in front of the camera. */
bool scene_camera_pixel_size(const scene_camera *cam, const double p[3], double *px, double *py);

/* A run of a mesh's triangles that share one mipmap level choice
 * (scene_mip.c): planar, the eye-space position is one affine function of
 * (u, v) over the run and GL's level of detail is computed per pixel from
 * it; otherwise lambda is one value for the run. */
typedef struct scene_mip_run {
    bool planar;
    double a[3], b[3], c[3]; /* camera image coordinates: (u, v, 1) . a etc. */
    double lambda;
    double lo, hi; /* lambda's range at the run's corners (0, 0: not placed) */
} scene_mip_run;

/* The length of the run from tris[0] (nt > 0): triangles on one affine
 * map of their (u, v) into eye space (to_eye NULL: the vertices are in eye
 * space), planar; or 1 when tris[0] shares its map with no neighbour,
 * with its lambda at its centroid (not planar). A run over which lambda
 * varies by less than 1/SCENE_MIP_STEPS at its corners is not planar
 * either: its lambda is the middle of theirs. tw, th: the base level's
 * size in texels. */
#define SCENE_MIP_STEPS 16
size_t scene_mip_split(const scene_camera *cam, const mat4 *to_eye, const scene_vertex *verts,
                       const scene_tri *tris, size_t nt, int tw, int th, scene_mip_run *out);

#endif
