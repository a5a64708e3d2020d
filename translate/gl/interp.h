/* interp.h: the OpenGL 1.x state machine that replays a trace into a scene.
 *
 * One interpreter holds one GL context's state (gl_state) and, while a frame
 * is translated, the scene it draws into. Commands arrive decoded
 * (rgl_cmd); each goes through a dispatch table generated from
 * format/commands.def to its handler interp_<handler> (interp_*.c), so a
 * command without a handler does not link. A command GL would reject is
 * skipped and counted in the diagnostics log with its frame and position,
 * as GL records an error and goes on.
 *
 * Where each area of GL lives (every file of gl/, by area, as Mesa's
 * src/mesa/main has one file per area of state):
 *
 * The machine
 *   interp.c          dispatch, run loop, diagnostics, GL's initial state,
 *                     glEnable/glDisable, the attribute stack
 *   interp_internal.h struct interp and what the files share
 *   caps.def          the capabilities glEnable/glDisable accept
 *   interp_bounds.c   the frame's budget (a frame that would cost more is
 *                     cut) and the parts a damaged trace left out of it
 *   interp_unrecorded.c @NotRecorded: the calls the recorder did not record
 *   unrec.c, unrec.h  their tables, counted by entry point
 *   namemap.c, namemap.h GL object names to table indexes (lists, textures)
 * Vertices and primitives
 *   interp_prim.c     glBegin, the current vertex attributes, the vertices
 *   interp_assemble.c glEnd: primitive assembly, culling, polygon mode,
 *                     lines and points, glRect
 *   interp_array.c    vertex arrays and their draws, buffer objects
 *   interp_list.c     display lists: the table, calls, nesting, and the
 *                     prototypes that repeated calls share
 *   interp_eval.c     evaluators: maps, grids, glEvalCoord, glEvalMesh
 *   interp_nurbs.c    GLU NURBS surfaces, curves and trims
 *   interp_shape.c    GLU quadrics and GLUT solids
 *   interp_point.c    point parameters, the provoking vertex
 *   interp_sprite.c   textured points and point sprites
 *   interp_lines.c    lines and points as GL rasterises them: clipped,
 *                     cut into strips over GL's pixels
 *   rasterise.c, rasterise.h which pixels Mesa lights for a line or point
 *   interp_stipple.c  line stipple
 *   interp_pstipple.c polygon stipple
 *   interp_offset.c   glPolygonOffset
 * Transforms, camera and clipping
 *   interp_matrix.c   matrix modes, stacks, transforms, @Matrix, viewport
 *   interp_raster.c   clear, shading, face and rasterisation state, the
 *                     frame calls (rayglFrameBegin), the frame's camera
 *   interp_proj.c     a frame of several projections: its camera, layers
 *   interp_clip.c     user clip planes
 *   interp_select.c   render modes and the name stack
 * Lighting and fog
 *   interp_light.c    lights, light model, materials, colour material, fog
 *   interp_lightset.c the frame's light sets (each lit draw's lights)
 *   interp_vmaterial.c glMaterial between the vertices of a primitive
 *   interp_gouraud.c  per-vertex lighting on request (--vertex-lighting)
 *   interp_relit.c    GL's own lighting for faces a writer cannot light so
 *   interp_fogsec.c   fog coordinates and the secondary colour
 *   interp_fogbehind.c fog of primitives reaching behind the eye
 * Textures
 *   interp_texture.c  texture objects, parameters, environment, texgen
 *                     state, copies between contexts
 *   interp_teximage.c texture images: formats, types, mipmap building
 *   interp_texdraw.c  what a draw samples: the scene texture of a unit,
 *                     the texture coordinates of each vertex
 *   interp_teximage.h texture objects and images as the files share them
 *   interp_texpacked.c GL's packed pixel types
 *   interp_texslice.c derived images: mirror-clamped, 3D slices
 *   interp_texcopy.c  glCopyTex*, 3D textures
 *   interp_multitex.c texture units: glActiveTexture, glMultiTexCoord
 *   interp_combine.c  the GL_COMBINE environment
 * Per-fragment operations and the framebuffer
 *   interp_alphatest.c the alpha test
 *   interp_scissor.c  the scissor test, scissored clears
 *   interp_stencil.c  the stencil test
 *   interp_masks.c    colour and depth write masks
 *   interp_blend.c    blending and logic ops: how a draw's colours show
 *                     what is behind
 *   interp_dest.c     what the colour buffer holds where a draw lands (for
 *                     the blends and logic ops that read it)
 *   interp_buffers.c  glDrawBuffer: the colour buffers a draw goes to
 *   interp_zorder.c   draw order without a depth test: whether it can
 *                     change a pixel
 *   interp_accum.c    the accumulation buffer
 *   interp_pixels.c   raster position, bitmaps, pixel rectangles
 *   interp_pixdepth.c their depth
 *   interp_pixmap.c   pixel maps and the pixel transfer of colours
 *
 * Not thread-safe; one interpreter per worker thread.
 */
#ifndef RGL_INTERP_H
#define RGL_INTERP_H

#include <GL/gl.h>
#include <stdbool.h>
#include <stdint.h>

#include "diag.h"
#include "format.h"
#include "mat4.h"
#include "scene.h"

/* GL's own limits (the minimums of the GL 1.x specification, which Mesa
 * also uses for the fixed-function stacks). */
#define INTERP_MODELVIEW_DEPTH 32
#define INTERP_PROJECTION_DEPTH 2
#define INTERP_TEXTURE_DEPTH 2
#define INTERP_ATTRIB_DEPTH 16
#define INTERP_MAX_LIGHTS 8
/* Texture units (Mesa's GL_MAX_TEXTURE_UNITS); the scene draws the first
 * two enabled ones (interp_multitex.c). */
#define INTERP_TEX_UNITS 8
#define INTERP_MAX_VIEWPORT 16384 /* Mesa's GL_MAX_VIEWPORT_DIMS */
#define INTERP_MAX_LIST_NESTING 64 /* GL_MAX_LIST_NESTING (GL 1.x table 6.28) */
#define INTERP_MAX_TEXTURE_SIZE 16384 /* Mesa's GL_MAX_TEXTURE_SIZE */
#define INTERP_MAX_EVAL_ORDER 30 /* Mesa's GL_MAX_EVAL_ORDER */
#define INTERP_MAX_NAME_STACK 64 /* Mesa's GL_MAX_NAME_STACK_DEPTH */

/* Mesa's GL_MAX_CLIP_PLANES is 8; GL names the planes past 5 only as
 * GL_CLIP_PLANE0 + i. */
#ifndef GL_CLIP_PLANE6
#define GL_CLIP_PLANE6 (GL_CLIP_PLANE0 + 6)
#endif
#ifndef GL_CLIP_PLANE7
#define GL_CLIP_PLANE7 (GL_CLIP_PLANE0 + 7)
#endif

/* The frame budget (docs/mapping.md, "Bounds"): what one frame may cost,
 * display-list bodies and state snapshots included, so that a few hundred
 * bytes (a list that calls itself twice) cannot ask for unbounded time or
 * memory. Output is counted as the scene holds it: a display list drawn
 * many times and shared (interp_list.c) counts its vertices once and one
 * instance per call, a texture image drawn many times once
 * (interp_texdraw.c). A frame that would exceed one is cut there: the rest
 * of its commands are skipped, what came before is kept, and
 * interp_frame_cut says why. */
#define INTERP_BUDGET_COMMANDS (1u << 26)    /* commands run */
#define INTERP_BUDGET_ASSEMBLED (1u << 24)   /* vertices assembled */
#define INTERP_BUDGET_VERTICES (1u << 22)    /* vertices the scene holds */
#define INTERP_BUDGET_TRIANGLES (1u << 22)   /* triangles it holds */
#define INTERP_BUDGET_LINES (1u << 20)       /* lines and points it holds (each
                                                costs the writer as a few triangles) */
#define INTERP_BUDGET_SOLIDS (1u << 18)      /* exact GLU/GLUT solids it holds */
#define INTERP_BUDGET_INSTANCES (1u << 18)   /* placements of shared list output */
#define INTERP_BUDGET_TEXELS (1u << 28)      /* texture bytes read, copied or held: each
                                                image once, however often drawn */

enum interp_matrix_mode { INTERP_MV, INTERP_PROJ, INTERP_TEX, INTERP_NMODES };

enum interp_cap {
#define CAP(name, def, group) INTERP_CAP_##name,
#include "caps.def"
#undef CAP
    INTERP_CAP_COUNT
};

typedef struct gl_material {
    float ambient[4], diffuse[4], specular[4], emission[4];
    float shininess;
} gl_material;

typedef struct gl_light {
    float ambient[4], diffuse[4], specular[4];
    float position[4];       /* eye space, transformed at the glLight call */
    float spot_direction[3]; /* eye space */
    float spot_exponent, spot_cutoff;
    float attenuation[3]; /* constant, linear, quadratic */
} gl_light;

/* The state glPushAttrib can save, grouped as its mask bits. */
typedef struct gl_attribs {
    struct {
        float color[4], normal[3], texcoord[4];
        float secondary[3], fog_coord; /* glSecondaryColor, glFogCoord: kept, not drawn yet */
        bool edge_flag;
        /* The current raster position (GL 2.1 2.13): window x, y, depth
         * z in [0, 1], clip w; its colour (the current colour at the
         * glRasterPos call); invalid once clipped: pixels draw nothing. */
        double raster_pos[4];
        float raster_color[4];
        bool raster_valid;
        /* glRasterPos under the camera's projection and viewport: its
         * normalised device z places depth-tested pixels (interp_pixdepth.c). */
        bool raster_in_camera;
        double raster_ndc_z;
    } current; /* GL_CURRENT_BIT */
    uint8_t caps[INTERP_CAP_COUNT]; /* GL_ENABLE_BIT (and each cap's group) */
    struct {
        GLenum shade_model;
        gl_material material[2]; /* front, back */
        GLenum color_material_face, color_material_mode;
        gl_light light[INTERP_MAX_LIGHTS];
        float model_ambient[4];
        bool local_viewer, two_side;
        GLenum color_control; /* GL_LIGHT_MODEL_COLOR_CONTROL */
        GLenum provoking;     /* glProvokingVertex */
    } lighting; /* GL_LIGHTING_BIT */
    struct {
        GLenum front_face, cull_mode;
        GLenum mode[2]; /* front, back: GL_FILL, GL_LINE, GL_POINT */
        float offset_factor, offset_units;
        uint8_t stipple[128]; /* glPolygonStipple: 32 rows of 4 bytes, bottom
                                 row first, most significant bit first */
    } polygon; /* GL_POLYGON_BIT; stipple: GL_POLYGON_STIPPLE_BIT */
    struct {
        float width;
        int32_t stipple_factor;    /* glLineStipple, clamped to [1, 256] */
        uint16_t stipple_pattern; /* bit 0 first */
    } line; /* GL_LINE_BIT */
    struct {
        /* front and back faces' (GL 2.0 two-sided stencil; points, lines,
         * bitmaps and pixels take the front's) */
        struct gl_stencil_face {
            GLenum func, fail, zfail, zpass;
            int32_t ref;
            uint32_t value_mask, write_mask;
        } face[2];
        int32_t clear;
    } stencil; /* GL_STENCIL_BUFFER_BIT */
    struct {
        float clear[4]; /* glClearAccum, clamped to [-1, 1] */
    } accum; /* GL_ACCUM_BUFFER_BIT */
    struct {
        float size;
        /* glPointParameter (GL 1.4 3.3): the derived size's clamp, the
         * size below which points fade, the distance attenuation. */
        float size_min, size_max, fade_threshold, atten[3];
        GLenum sprite_origin; /* GL_POINT_SPRITE_COORD_ORIGIN */
    } point; /* GL_POINT_BIT */
    struct {
        int32_t rect[4]; /* x, y, width, height */
        double near, far;
    } viewport; /* GL_VIEWPORT_BIT */
    struct {
        GLenum matrix_mode;
        double clip_plane[8][4]; /* eye space, at the glClipPlane call */
    } transform; /* GL_TRANSFORM_BIT */
    struct {
        float clear[4];
        GLenum blend_src, blend_dst, alpha_func; /* blend_*: the colour's factors */
        GLenum blend_equation, logic_op;
        GLenum blend_src_alpha, blend_dst_alpha, blend_equation_alpha;
        float blend_color[4]; /* glBlendColor */
        float alpha_ref;
        bool mask[4];
        GLenum draw_buffer; /* glDrawBuffer; INTERP_DRAW_BUFFER_DEFAULT: the
                               context's default, the buffer it shows */
    } color_buffer; /* GL_COLOR_BUFFER_BIT */
    struct {
        GLenum func;
        bool mask;
        double clear;
    } depth; /* GL_DEPTH_BUFFER_BIT */
    struct {
        GLenum mode;
        float density, start, end, color[4];
        GLenum coord_src; /* GL_FOG_COORD_SRC */
        GLenum distance;  /* GL_FOG_DISTANCE_MODE_NV */
    } fog; /* GL_FOG_BIT */
    struct {
        GLenum perspective, point, line, polygon, fog;
    } hint; /* GL_HINT_BIT */
    struct gl_texture_unit {
        GLenum env_mode;
        float env_color[4];
        /* GL_COMBINE (interp_combine.c): RGB and alpha functions, the RGB
         * arguments' sources and operands, the scales. */
        GLenum combine_rgb, combine_alpha, combine_src[3], combine_op[3];
        float rgb_scale, alpha_scale;
        uint32_t binding_1d, binding_2d;
        uint32_t binding_rect;    /* GL_TEXTURE_RECTANGLE(_ARB, _NV) */
        uint32_t binding_3d;
        uint32_t binding_cube;    /* GL_TEXTURE_CUBE_MAP */
        GLenum gen_mode[4];       /* s, t, r, q: GL_EYE_LINEAR, ... */
        double obj_plane[4][4];   /* GL_OBJECT_PLANE */
        double eye_plane[4][4];   /* GL_EYE_PLANE, times the inverse modelview
                                     current at the glTexGen call */
        bool coord_replace;       /* GL_POINT_SPRITE's GL_COORD_REPLACE */
        float lod_bias;           /* GL_TEXTURE_FILTER_CONTROL's GL_TEXTURE_LOD_BIAS */
    } texture; /* GL_TEXTURE_BIT */
    struct {
        int32_t grid_n[2][2];    /* [dimension - 1][u, v]: glMapGrid's partitions */
        double grid[2][2][2];    /* [dimension - 1][u, v][start, end] */
    } eval; /* GL_EVAL_BIT (the maps themselves are not attributes) */
    struct {
        float zoom[2];         /* glPixelZoom */
        float scale[4], bias[4]; /* GL_RED_SCALE .. GL_ALPHA_BIAS */
        bool map_color;        /* GL_MAP_COLOR */
        /* glPixelMap: GL_PIXEL_MAP_I_TO_I .. GL_PIXEL_MAP_A_TO_A in order,
         * each map_size entries (GL 2.1 table 6.18: initially one, 0) */
        uint16_t map_size[10];
        float map[10][256];
    } pixel; /* GL_PIXEL_MODE_BIT */
    struct {
        int32_t box[4]; /* x, y, width, height */
        bool set;       /* false: the initial box, the whole window */
    } scissor; /* GL_SCISSOR_BIT */
} gl_attribs;

/* A texture unit's server state while another unit is active: gl_attribs
 * and gl_state hold the active unit's in place (interp_multitex.c). */
typedef struct gl_tex_unit_parked {
    struct gl_texture_unit texture;
    uint8_t caps[8]; /* INTERP_CAP_TEXTURE_1D .. INTERP_CAP_TEXTURE_GEN_Q */
    uint8_t rect;    /* INTERP_CAP_TEXTURE_RECTANGLE */
    mat4 matrix[INTERP_TEXTURE_DEPTH];
    int depth;
} gl_tex_unit_parked;

typedef struct gl_attrib_entry {
    uint32_t mask;
    gl_attribs saved;
} gl_attrib_entry;

/* A GLU quadric object's state (by the recorder's id). */
typedef struct interp_quadric {
    uint32_t id; /* 0: free slot */
    GLenum draw_style, normals, orientation;
    bool texture;
} interp_quadric;

#define INTERP_QUADRICS 64

#define INTERP_DRAW_BUFFER_DEFAULT 0xffffffffu

/* The whole context state that frames carry over: GL's state, apart from
 * the interpreter's bookkeeping of the frame it translates (struct interp,
 * interp_internal.h). */
typedef struct gl_state {
    gl_attribs a;
    mat4 modelview[INTERP_MODELVIEW_DEPTH];
    mat4 projection[INTERP_PROJECTION_DEPTH];
    mat4 texture[INTERP_TEXTURE_DEPTH];
    int depth[INTERP_NMODES]; /* index of each stack's top */
    gl_attrib_entry attrib_stack[INTERP_ATTRIB_DEPTH];
    int attrib_depth;
    uint32_t list_base; /* glListBase (issue 5) */
    /* Render mode and name stack (interp_select.c; not attributes). */
    GLenum render_mode;
    int32_t select_size, feedback_size; /* -1: no buffer given */
    uint32_t names[INTERP_MAX_NAME_STACK];
    int nnames;
    uint32_t active_unit, client_unit; /* glActiveTexture, glClientActiveTexture */
    gl_tex_unit_parked units[INTERP_TEX_UNITS]; /* the active unit's slot is stale */
    float unit_texcoord[INTERP_TEX_UNITS][4]; /* current, units 1..; unit 0's is a.current */
    interp_quadric quadrics[INTERP_QUADRICS]; /* GLU quadric objects (interp_shape.c) */
    /* GL_COLOR_MATERIAL as Mesa follows it (interp_light.c, "Colour
     * material"; not attributes): the terms glMaterial set since the last
     * draw (by face, SCENE_CM_* bits), and after a glEnable that kept some
     * of them, the colour current then and whether a draw came since. */
    struct gl_cm {
        uint8_t held[2];
        bool stale, drawn;
        float ref[4];
    } cm;
    /* The context's colour buffers (glDrawBuffer's visual, format.md
     * 3.19): 0 unknown, else 1 | 2 double-buffered | 4 stereo. */
    uint32_t visual;
    /* The parts on the heap, made on first use (NULL until then: GL's
     * initial state), owned by the interpreter; interp_copy_state copies
     * what they hold: texture objects and the unpack state
     * (interp_texture.c), evaluator maps (interp_eval.c), GLU NURBS
     * objects and the open shape (interp_nurbs.c), the display-list table
     * (interp_list.c). */
    struct interp_textures *tex;
    struct interp_eval *eval;
    struct interp_nurbs *nurbs;
    struct interp_lists *lists;
} gl_state;

typedef struct interp interp;

/* A new interpreter in GL's initial state. scene may be NULL: the
 * interpreter then only tracks state (replaying earlier frames for a
 * STATE_CARRIED frame). log receives diagnostics (may be NULL). NULL on
 * allocation failure. */
interp *interp_create(scene *out, diag_log *log);

/* Divides every limit of the frame budget by 2^shift (at most 16) for the
 * frames ip runs from now on: the fuzz targets run on a small budget, so
 * an input that would cut a frame at the full budget costs them little. */
void interp_set_budget_shift(interp *ip, unsigned shift);

/* On: lit surfaces take GL's lit colour at each vertex, interpolated and
 * drawn unlit, as OpenGL shades them (raygl2pov --vertex-lighting,
 * interp_gouraud.c); off (the default): POV-Ray lights each pixel. */
void interp_set_vertex_lighting(interp *ip, bool on);

/* Whether the frame about to run shows the front buffer (it ends with
 * glFlush or glFinish: a single-buffered frame) rather than a
 * double-buffered context's back buffer; draws into the other one are
 * left out (interp_buffers.c). Until set: the back one. */
void interp_set_shown_front(interp *ip, bool front);

/* Whether the scenes are rendered with shadows (the default; off:
 * raygl2pov --no-shadows): the notes of highlights the shadowed render
 * approximates are said only then, those of the shadowless one only
 * without (interp_lightset.c). */
void interp_set_shadows(interp *ip, bool on);

/* Whether the scenes are written for POV-Ray (the default; off: glTF,
 * raygl2pov --format gltf): the notes of how POV-Ray renders the lights
 * (with or without shadows) are held otherwise, as no such render is
 * made. */
void interp_set_pov(interp *ip, bool on);
void interp_destroy(interp *ip);

/* Back to GL's initial state; the scene and log stay attached. */
void interp_reset(interp *ip);

/* Copies the context state (not the scene, log or frame data) from src,
 * display lists included. */
void interp_copy_state(interp *dst, const interp *src);

/* Where display-list bodies come from: fetches resource `id` (normally
 * from the trace's reader; the data must stay valid while the interpreter
 * lives). Without one, glCallList draws nothing and says so. */
typedef rgl_status (*interp_resource_fn)(void *ctx, uint32_t id, rgl_resource *out,
                                         rgl_error *err);
void interp_set_resources(interp *ip, interp_resource_fn fn, void *ctx);

/* Attaches a scene (or NULL) and a log (or NULL). */
void interp_attach(interp *ip, scene *out, diag_log *log);

/* Logs note `kind` once for the frame (the frame's own notes, frame.c);
 * held: as a note that cannot change a pixel of it, for the reason why. */
void interp_frame_note(interp *ip, diag_kind kind);
void interp_frame_note_held(interp *ip, diag_kind kind, const char *why);

/* The camera a frame using several projections should have: true, with
 * its projection and viewport, when it is not the one the frame's first
 * draw fixed (then translate the frame again with it preset, after
 * interp_begin_frame, passing back_cleared on) (interp_proj.c). */
bool interp_proj_choice(const interp *ip, mat4 *proj, int32_t vp[4], bool *back_cleared);
void interp_proj_preset(interp *ip, const mat4 *proj, const int32_t vp[4], bool back_cleared);
/* The depth-only clears between draws in the frame's last colour-cleared
 * part, after the first draw of the camera proj, vp (NULL: the one the
 * first draw fixed): when not 0, translate the frame again with them
 * preset (after interp_begin_frame), so each part lies in front of the
 * ones before. */
/* The window the frame stands for, when it is not the picture's camera
 * viewport: the union of the viewports of the frame's draws and colour
 * clears after its last full colour clear (a split screen, a HUD in a
 * corner; a trace holds no window size). Then translate the frame again
 * with it preset (after interp_begin_frame): the camera widened so that
 * each viewport's picture lands where GL put it (interp_proj.c). */
bool interp_proj_window(const interp *ip, int32_t win[4]);
void interp_proj_preset_window(interp *ip, const int32_t win[4]);
uint32_t interp_proj_depth_epochs(const interp *ip, const mat4 *proj, const int32_t vp[4]);
void interp_proj_preset_epochs(interp *ip, uint32_t n);

/* Forgets which notes the frame logged, so each is logged again once. */
void interp_clear_notes(interp *ip);

/* Names the frame for diagnostics: "frame 12" and, while a snapshot
 * resource is replayed, "snapshot #3". label may be NULL. */
void interp_set_frame(interp *ip, uint64_t frame_index, const char *label);

/* Starts a frame: an empty scene (when attached), no camera yet. */
void interp_begin_frame(interp *ip);

/* Ends a frame: closes an unterminated glBegin (dropping its partial
 * primitive), and fixes the camera and background if no draw did. */
void interp_end_frame(interp *ip);

/* Executes one decoded command. */
void interp_exec(interp *ip, const rgl_cmd *cmd);

/* Executes a command sequence (a frame's commands or a resource). Returns
 * RGL_OK, or the decoder's error (details in *err) after executing every
 * command before the damage. */
rgl_status interp_run(interp *ip, const uint8_t *data, size_t size, uint64_t base_offset,
                      rgl_error *err);

/* As interp_run, but every command through the general decoder and
 * interp_exec (no fast path for per-vertex commands): for tests, which
 * check that both give the same scene. */
rgl_status interp_run_slow(interp *ip, const uint8_t *data, size_t size, uint64_t base_offset,
                           rgl_error *err);

/* A heavy frame: once in a frame, when what its scene holds first passes
 * INTERP_HEAVY_BYTES (an estimate, texture bytes included), fn(ctx) is
 * called and may block until the frame may go on. raygl2pov lets one heavy
 * frame run at a time, so that -j N costs at most one frame's budget plus
 * N - 1 light frames, whatever the trace; the output does not change. */
#define INTERP_HEAVY_BYTES (32u << 20)
typedef void (*interp_heavy_fn)(void *ctx);
void interp_set_heavy(interp *ip, interp_heavy_fn fn, void *ctx);

/* Why the current frame was cut (its budget ran out), as one line that
 * names where, or NULL when it was not. Valid until the next frame. */
const char *interp_frame_cut(const interp *ip);

/* What the current frame used of each budget (INTERP_BUDGET_*): the
 * counts that only grow (commands, vertices assembled, texture bytes) as
 * they stand, and the most the scene held of the others at any one time
 * (a shared list call holds its geometry until it is found shared, a
 * glClear drops what was drawn). limit: the budget as applied. */
typedef struct interp_budget_use {
    uint64_t commands, assembled, vertices, triangles, lines, solids, instances, texels;
} interp_budget_use;
void interp_budget_used(const interp *ip, interp_budget_use *used, interp_budget_use *limit);

/* What the current frame was drawn without because the trace is damaged
 * (display-list bodies or texture images that could not be read): the
 * first such part as one line, and in *count how many there were; NULL
 * (and 0) when nothing. Valid until the next frame. */
const char *interp_frame_missing(const interp *ip, uint32_t *count);

/* Records that the current frame is drawn without `what` (damage in the
 * trace: a display-list body, texture pixels, state that damaged earlier
 * frames would have carried), for interp_frame_missing. */
void interp_missing(interp *ip, const char *what);

/* The line segments the current frame assembled (each pair of GL_LINES,
 * edge of a strip or loop, outlined polygon edge), whether or not GL
 * lights a pixel of them: for tests (a segment becomes as many scene
 * lines as its pixels need, none when it lights none). */
uint64_t interp_frame_segments(const interp *ip);

/* The state, for tests and for the frame driver. */
const gl_state *interp_state(const interp *ip);

/* The current top of a matrix stack. */
const mat4 *interp_matrix(const interp *ip, int mode);

/* The rayglFrameBegin file name of the current frame (NUL-terminated,
 * unsanitised), or NULL when the frame has none. */
const char *interp_frame_name(const interp *ip);

struct unrec_table;
/* The calls the current frame's @NotRecorded commands say were not
 * recorded (unrec.h); empty for an interpreter without a scene. */
const struct unrec_table *interp_unrecorded(const interp *ip);

/* Says that the frame being built was recorded without a live GL context
 * (its uses then include UNREC_USE_BATCH: unrec.h). */
void interp_unrecorded_batch(interp *ip);

#endif
