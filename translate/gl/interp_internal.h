/* interp_internal.h: what the interp_*.c files share; not for other users.
 *
 * Holds the interpreter struct, the handler prototypes generated from
 * format/commands.def, and small helpers for reading arguments and
 * reporting GL errors.
 */
#ifndef RGL_INTERP_INTERNAL_H
#define RGL_INTERP_INTERNAL_H

#include <math.h>
#include <string.h>

#include "interp.h"
#include "unrec.h"

/* Every handler named in commands.def; a missing definition fails the link. */
#define RGL_CMD(op, api, gen, name, handler, ...) \
    void interp_##handler(interp *ip, const rgl_cmd *cmd);
#include "commands.def"
#undef RGL_CMD

typedef struct interp_textures interp_textures; /* interp_teximage.h */

/* One projection and viewport used in a frame, and its draws' weight. */
#define INTERP_PROJ_VOTES 8
/* Words of the frame's note bitsets: 64 NOTE_* kinds each. */
#define INTERP_NOTE_WORDS 2
typedef struct interp_proj_vote_t {
    mat4 proj;
    int32_t vp[4];
    uint64_t score;
    bool solid; /* some draw was depth-tested or lit */
    bool depth_drawn;
    uint32_t first_seq, first_depth_seq; /* draw_seq of its first (depth-tested) draw */
} interp_proj_vote_t;

/* One vertex's inputs to GL's lit colour, kept until glEnd shows the
 * colour is needed (interp_relit.c). */
typedef struct interp_relit_in {
    double p[3];
    float normal[3];
    float colour[4];
} interp_relit_in;

/* interp_lit_color_peak's terms of one directional light, made once per
 * position (bit for bit) instead of once per vertex. */
typedef struct interp_litdir {
    float pos[3];
    bool set;
    double vp[3], d; /* unit direction, length of the position */
    double h[3], hl; /* half vector for the infinite viewer, its length */
} interp_litdir;

/* The interpreter: GL's state (st: all of it, what frames carry over),
 * then the translation's bookkeeping, which is no GL state: the scene and
 * log it writes to, the frame being built (diagnostics context, budget,
 * the open primitive, the camera, light sets, passes) and caches. */
struct interp {
    gl_state st;
    struct {
        size_t first;   /* scene.stencil_tris of the buffer's content */
        int32_t value;  /* written there */
        int32_t cleared; /* the clear value there */
        bool written, mixed; /* something / values the scene cannot hold */
        bool write, only; /* this draw writes the stencil; and no colour */
        bool two_side;    /* its front and back faces' states treat it differently */
        uint8_t tri_faces; /* the faces whose triangles it writes: 1 front, 2 back */
        uint8_t clip;     /* this draw kept 1 inside, 2 outside the region */
        size_t n;         /* the region's triangles at this draw */
        bool box_pending; /* the region is box (window pixels), to be made into
                             triangles once the camera is fixed */
        int32_t box[4];
    } stencil; /* interp_stencil.c */
    struct interp_dest *dest; /* the frame's drawn footprint (interp_dest.c); NULL: none yet */
    scene *scene; /* NULL: state only */
    diag_log *log;
    uint8_t *begin_ok; /* by opcode: allowed between glBegin and glEnd */

    /* Diagnostics context. */
    uint64_t frame_index;
    char label[48];
    const rgl_cmd *cmd; /* the command being executed */
    /* NOTE_* kinds already logged in this frame, and logged held: bit
     * (kind - DIAG_FIRST_NOTE) % 64 of word / 64 (interp.c note_word) */
    uint64_t notes_seen[INTERP_NOTE_WORDS];
    uint64_t notes_held[INTERP_NOTE_WORDS];
    struct interp_zorder *zorder; /* the frame's runs of depth modes; NULL: none yet */
    bool cleared;        /* the frame cleared the colour buffer */
    uint32_t painter;    /* draws without a depth test since the frame's start
                            or last clear (interp_prim.c, painter_shift) */
    uint64_t pixels_mark; /* the scene's items after the frame's last pixel draw
                             (interp_pixels.c) */
    scene_mark pixels_first; /* the scene at the overlay's first pixels */
    /* Raster positions set before the camera was fixed: the projection
     * and viewport of the first, and whether another had others; checked
     * against the camera at the frame's end (interp_pixdepth.c). */
    bool raster_pre, raster_pre_mixed;
    mat4 raster_pre_proj;
    int32_t raster_pre_vp[4];
    int32_t pixels_org[2]; /* window position of scene.overlay's pixel (0, 0) */
    int pixels_depth_state; /* how the overlay's pixels were depth-tested (interp_pixdepth.c) */
    bool pixels_result_due; /* a glCopyPixels under a logic op waits for its @CopyPixelsResult */
    double pixels_ndc_z;    /* their raster position's device z, when all share one */
    uint64_t shape_facets; /* facets of tessellated shapes and evaluator mesh points in this
                              frame (interp_shape.c, interp_eval.c) */

    /* The frame's budget and completeness (interp_bounds.c). */
    uint64_t cmds_run, assembled, texels;
    interp_budget_use peak; /* of the scene's counts (interp_budget_peak) */
    unsigned budget_shift; /* the budget divided by 2^shift (interp_set_budget_shift) */
    bool cut;                /* the budget ran out: the rest of the frame is skipped */
    bool heavy;              /* heavy_fn was called in this frame */
    interp_heavy_fn heavy_fn;
    void *heavy_ctx;
    char cut_why[DIAG_TEXT];
    uint32_t nmissing;       /* parts left out for damage */
    char missing[DIAG_TEXT]; /* the first of them */
#define INTERP_MISSING_KEPT 16
    uint64_t missing_hash[INTERP_MISSING_KEPT]; /* of the first parts' texts */

    /* The frame's scissored clears since its last full one (interp_scissor.c). */
#define INTERP_CLEAR_RECTS 64
    struct interp_clear_rect {
        int32_t box[4];
        float color[4];
    } clear_rects[INTERP_CLEAR_RECTS];
    uint32_t nclear_rects;

    /* glBegin .. glEnd */
    bool in_begin;
    GLenum prim_mode;
    bool prim_skip;     /* vertices are dropped (no scene, or a bad transform) */
    /* The open primitive's vertices take interp_add_vertex's short path:
     * filled, no texture unit, alpha test, colour sum, fog coordinate or
     * mapped blend; PRIM_PLAIN_LIT: lit by the writer (surface colour). */
    uint8_t prim_plain;
    bool prim_plain_relit; /* and GL's lit colour may be wanted (interp_relit_defer) */
    size_t prim_first;  /* first vertex of the primitive in scene->verts */
    mat4 prim_to_eye;   /* object -> camera eye space for this primitive */
    /* lit_line_colour's last modelview and its inverse (ok: invertible),
     * kept while the matrix stays bit for bit the same: one inversion per
     * matrix, not per vertex. */
    mat4 lit_mv, lit_mv_inv;
    bool lit_mv_set, lit_mv_ok;
    /* interp_lit_color_peak's per-light terms of a directional light, kept
     * while its position stays bit for bit the same (a cache: written
     * through a const interp). */
    interp_litdir litdir[INTERP_MAX_LIGHTS];
    bool prim_in_eye;   /* prim_to_eye is applied to the vertices themselves */
    bool prim_indexed;  /* drawn from an index array (glDrawElements and kin) */
    uint8_t prim_blend; /* SCENE_BLEND_* of the primitive */
    int draw_unit[2];   /* the draw's first two enabled texture units, or -1 */
    bool prim_tex_from1; /* the look's texture is draw_unit[1]'s (tex1 coordinates) */
    bool prim_blend_mapped; /* its vertex colours carry another blend function as transmit */
    bool prim_fx;         /* interp_blend.c maps its colours at glEnd */
    struct interp_sprite *sprites; /* its textured points (interp_sprite.c) */
    size_t nsprites, cap_sprites;
    float prim_filter;    /* the look's filter (scene_look.filter) */
    bool prim_color_sum;  /* the secondary colour goes into the vertex colours (interp_fogsec.c) */
    bool prim_fog_vertex; /* the fog of the fog coordinate goes into them, no fog layer */
    bool prim_coord_same; /* every vertex so far had the fog coordinate prim_coord0 */
    float prim_coord0;
    mat4 prim_clip;     /* object -> clip space of the primitive's own projection */
    uint8_t *edge;      /* edge flag of each vertex of the primitive */
    size_t cap_edge;
    double (*clipv)[5]; /* clip-space x, y, w of each vertex (culling), then x/w, y/w */
    size_t cap_clipv;
    uint64_t segments;            /* interp_frame_segments */
    struct ras_run *ras_runs;     /* a segment's pixels (interp_lines.c) */
    size_t cap_ras_runs;
    struct ras_piece *ras_pieces; /* and the strips that cover them */
    size_t cap_ras_pieces;
    float prim_alpha;        /* the first vertex's alpha (interp_alpha_vertex) */
    bool prim_alpha_varies;  /* another vertex's differs */
    float (*relit_col)[4]; /* GL's lit colour of each vertex (interp_relit.c) */
    size_t cap_relit;
    interp_relit_in *relit_in; /* what that colour is made of, until it is made */
    size_t cap_relit_in;
    size_t relit_pending;  /* vertices kept in relit_in */
    size_t relit_made;     /* of those, the first ones with their colour in relit_col */
    uint8_t *relit_need;   /* vertex k is a corner of a face left for the GL-lit pass */
    size_t cap_relit_need;
    uint32_t (*relit_tris)[4]; /* those faces' triangles: corners and provoking vertex */
    size_t nrelit_tris, cap_relit_tris;
    uint32_t *relit_copy;  /* pool index of a marked vertex's GL-lit copy */
    size_t cap_relit_copy;
    bool relit_over;       /* some vertex was lit past 1 in a channel */
    bool prim_relit;       /* the look being made is of GL-lit faces */
    /* A filled primitive being assembled (mip_defer): its mipmapped
     * texture's note waits for its triangles (mip_pending, interp_texdraw.c). */
    bool mip_defer, mip_pending;
    int32_t mip_texture;
    double (*fogz)[4];     /* GL's eye point and fog distance of each vertex, when fogged
                              (interp_fogbehind.c) */
    size_t cap_fogz;
    bool fog_split;        /* the primitive's triangles behind the eye get their own fog */

    /* The frame's camera: fixed by the first draw (or at the frame's end).
     * own_*: the GL projection and viewport of the camera's own draws;
     * cam_*: the picture's, the window the frame stands for (the same,
     * or own_proj widened to the union of the frame's viewports, own_vp's
     * pixels where GL put them: interp_proj.c). */
    bool camera_fixed;
    mat4 own_proj;
    int32_t own_vp[4];
    mat4 cam_proj;
    int32_t cam_viewport[4];
    /* The union of the viewports of the draws and colour clears since the
     * last full colour clear (win_n: 0 none yet), and the one a second
     * translation is given. */
    int32_t win[4];
    int win_n;
    bool win_preset;
    int32_t win_preset_rect[4];
    mat4 cam_from_ndc; /* inverse of (viewport-scaled) camera projection */
    bool cam_from_ndc_ok;

    /* Several projections in a frame (interp_proj.c): the votes for the
     * camera, the preset one of a second translation, and whether only
     * background-layer draws were made since the last colour clear. */
    interp_proj_vote_t votes[INTERP_PROJ_VOTES];
    int nvotes;
    bool cam_preset;
    mat4 cam_preset_proj;
    int32_t cam_preset_vp[4];
    bool back_open;
    bool own_drawn; /* a draw with the camera's projection since the colour clear */
    uint32_t draw_seq;                       /* draws since then */
    uint32_t clear_seq[INTERP_PROJ_VOTES];   /* draw_seq at each depth clear */
    int nclear_seq;
    bool preset_back_cleared; /* the first translation found a background
                                 drawn with the depth test, then cleared */
    /* Depth-only clears after draws since the colour clear split the
     * frame into epochs, each in front of the ones before: this one, the
     * count the first translation found (preset in the second), whether
     * this one has draws. */
    uint32_t depth_epoch, depth_epochs;
    bool epoch_drawn;

    /* Display lists (interp_list.c): the table is GL state (st.lists);
     * here where bodies come from, the nesting, and the groups: the
     * frame's list calls whose output may be shared. */
    interp_resource_fn res_fn;
    void *res_ctx;
    int list_depth;
    bool list_ce;        /* running a GL_COMPILE_AND_EXECUTE body as it is defined */
    uint32_t list_calls; /* this frame's, against a hostile trace's recursion */
    struct interp_groups *groups;
    /* The frame's pixel rectangles, converted (interp_pixels.c). */
    struct interp_pixconv *pixconv;

    /* The client arrays of the next draw: the @ArrayData records before
     * it (interp_array.c). */
    struct interp_array_data {
        bool set;
        int32_t first, size;
        uint32_t type;
        const uint8_t *data;
        size_t bytes;
    } arrays[7]; /* interp_array.c's ARR_* */
    /* Texture coordinates of units 1.. (units[0] unused: arrays[3] is
     * unit 0's): an @ArrayData of GL_TEXTURE_COORD_ARRAY fills the client
     * active unit's. */
    struct interp_array_data unit_tc[INTERP_TEX_UNITS];

    /* The GL lights and fog the frame's scene holds (those of its first lit
     * or fogged draw), to notice when a later draw uses others. */
    uint8_t seen_light_on[INTERP_MAX_LIGHTS];
    gl_light seen_light[INTERP_MAX_LIGHTS];
    uint32_t seen_set; /* their light set (interp_lightset.c) */
    /* The scene's light sets: where each starts and its size, its hash,
     * and a table from hash to 1 + set (0: an empty slot; at most half
     * full, so a probe always ends). */
    struct interp_lsets {
        uint32_t count;
        uint32_t first[SCENE_MAX_LIGHTSETS];
        uint8_t n[SCENE_MAX_LIGHTSETS];
        uint64_t hash[SCENE_MAX_LIGHTSETS];
        int16_t slot[2 * SCENE_MAX_LIGHTSETS];
    } lsets;
    bool vertex_lighting; /* interp_set_vertex_lighting */
    bool show_front;      /* interp_set_shown_front */
    bool no_shadows;      /* interp_set_shadows(ip, false) */
    bool not_pov;         /* interp_set_pov(ip, false) */

    /* glMaterial between the vertices of the open primitive
     * (interp_vmaterial.c): each vertex's material once one changed, and
     * the terms its vertex colours carry at glEnd. */
    struct interp_vmat {
        bool changed;
        gl_material (*mats)[2];
        size_t n, cap;
        uint8_t cm_extra[2];
    } vmat;

    /* The frame's accumulation-buffer passes (interp_accum.c): after the
     * first glAccum(GL_ACCUM or GL_LOAD), what later passes draw is dropped
     * back to mark until glAccum(GL_RETURN); each pass's first draw gives
     * its projection and modelview, compared with the first pass's. */
    struct interp_accum {
        bool active;       /* passes after the first are being dropped */
        bool want_draw;    /* the current pass has not drawn yet */
        scene_mark mark;   /* the scene holding the first pass */
        uint32_t painter;  /* ip->painter at the mark */
        uint32_t passes;   /* accumulated so far */
        double weight;     /* sum of the accumulated values */
        bool odd_weights;  /* GL_MULT, GL_ADD, or unequal values */
        bool have_first;
        mat4 proj0, mv0;   /* the first pass's first draw */
        mat4 proj, mv;     /* the current pass's first draw */
        uint32_t n_jitter, n_lens, n_other; /* later passes by kind */
        double max_jitter;  /* of the projection, in pixels */
        double focus_min, focus_max; /* lens passes' focal distances */
        double eye_sum[2], eye_sum2; /* their eyes' offsets (first pass's eye space) */
        bool buffer_odd;   /* a clear or operation the passes alone do not show */
        bool cleared;      /* the frame cleared the accumulation buffer */
    } accum;

    /* rayglFrameBegin */
    bool frame_begin;
    char frame_name[RGL_STRING_MAX + 1];
    unrec_table unrecorded; /* the frame's @NotRecorded (interp_unrecorded.c) */
    double fb_loc[3], fb_look[3], fb_light[3];
};

/* ---- GL's enums as the scene names them (scene.h) ---------------------------- */

/* GL_MODULATE .. GL_ADD: SCENE_ENV_*; 0 for another mode. */
static inline uint32_t interp_scene_env(GLenum mode)
{
    switch (mode) {
    case GL_MODULATE: return SCENE_ENV_MODULATE;
    case GL_REPLACE: return SCENE_ENV_REPLACE;
    case GL_DECAL: return SCENE_ENV_DECAL;
    case GL_BLEND: return SCENE_ENV_BLEND;
    case GL_ADD: return SCENE_ENV_ADD;
    default: return 0;
    }
}

/* GL_NEVER .. GL_ALWAYS (consecutive, GL 1.x table 4.1): SCENE_CMP_*; 0
 * for another value. */
static inline uint32_t interp_scene_cmp(GLenum func)
{
    return func >= GL_NEVER && func <= GL_ALWAYS ? func - GL_NEVER + SCENE_CMP_NEVER : 0;
}

/* GL_*_MIPMAP_*: SCENE_MIP_*; 0 for a filter that does not mipmap. */
static inline uint32_t interp_scene_mip(GLenum filter)
{
    switch (filter) {
    case GL_NEAREST_MIPMAP_NEAREST: return SCENE_MIP_NEAREST_MIPMAP_NEAREST;
    case GL_LINEAR_MIPMAP_NEAREST: return SCENE_MIP_LINEAR_MIPMAP_NEAREST;
    case GL_NEAREST_MIPMAP_LINEAR: return SCENE_MIP_NEAREST_MIPMAP_LINEAR;
    case GL_LINEAR_MIPMAP_LINEAR: return SCENE_MIP_LINEAR_MIPMAP_LINEAR;
    default: return 0;
    }
}

/* GL_LINEAR, GL_EXP, GL_EXP2: SCENE_FOG_*; 0 for another mode. */
static inline int interp_scene_fog(GLenum mode)
{
    return mode == GL_LINEAR ? SCENE_FOG_LINEAR
           : mode == GL_EXP  ? SCENE_FOG_EXP
           : mode == GL_EXP2 ? SCENE_FOG_EXP2
                             : 0;
}

/* ---- Arguments -------------------------------------------------------------- */

/* A scalar argument as double (any wire type). */
/* An enum passed as a float or double (glFogf(GL_FOG_MODE, ...),
 * glTexParameterf): the value when it is one a GLenum holds, else
 * 0xffffffff, which no enum is (a C cast of a negative or too large value
 * is undefined behaviour; found by fuzz_translate). */
static inline GLenum interp_enum_of(double v)
{
    return v >= 0 && v <= 4294967295.0 ? (GLenum)v : 0xffffffffu;
}

static inline double arg_num(const rgl_arg *a)
{
    switch (a->type) {
    case RGL_T_f:
    case RGL_T_d:
        return a->v.f;
    case RGL_T_b:
    case RGL_T_s:
    case RGL_T_i:
    case RGL_T_sz:
    case RGL_T_ip:
        return (double)a->v.i;
    default:
        return (double)a->v.u;
    }
}

/* The k-th number of a command whose values are either separate scalars
 * (glVertex3f) or one array (glVertex3fv). *n receives how many there are. */
static inline double cmd_value(const rgl_cmd *cmd, uint32_t k)
{
    const rgl_arg *a0 = &cmd->arg[0];
    if (a0->kind == RGL_ARG_ARRAY || a0->kind == RGL_ARG_COUNTED)
        return k < a0->count ? a0->array[k] : 0.0;
    return k < cmd->nargs ? arg_num(&cmd->arg[k]) : 0.0;
}

static inline uint32_t cmd_value_count(const rgl_cmd *cmd)
{
    const rgl_arg *a0 = &cmd->arg[0];
    if (a0->kind == RGL_ARG_ARRAY || a0->kind == RGL_ARG_COUNTED)
        return a0->count;
    return cmd->nargs;
}

/* The wire type of those values. */
static inline uint8_t cmd_value_type(const rgl_cmd *cmd) { return cmd->arg[0].type; }

static inline uint32_t arg_enum(const rgl_cmd *cmd, uint32_t k)
{
    return k < cmd->nargs ? (uint32_t)cmd->arg[k].v.u : 0;
}

/* ---- Diagnostics -------------------------------------------------------------- */

/* Logs a diagnostic about the current command, prefixed with its frame,
 * index, name and offset. */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
void interp_diag(interp *ip, diag_kind kind, const char *fmt, ...);

/* Logs a NOTE_* kind once per frame (the CLI then says it once per run):
 * call it where the approximation can change a pixel of the frame. */
void interp_note(interp *ip, diag_kind kind);
/* Logs a NOTE_* kind once per frame as held: its approximation applies but
 * cannot change a pixel of this frame, for the reason why (at most
 * DIAG_WHY - 1 bytes; printed only with --verbose). Nothing once the note is
 * said in the frame. */
void interp_note_held(interp *ip, diag_kind kind, const char *why);
/* A note of the POV-Ray scene's approximation: for glTF output
 * (interp_set_pov false) held, and gltf said instead (DIAG_COUNT: none),
 * the glTF file's own way with what the note concerns. */
void interp_note_pov(interp *ip, diag_kind kind, diag_kind gltf);
/* interp_note (why NULL) or interp_note_held, naming the command given
 * (has_cmd: one) instead of the current one: a note decided at the frame's
 * end names the draw it concerns. */
void interp_note_cmd(interp *ip, diag_kind kind, bool has_cmd, uint64_t index, const char *name,
                     uint64_t offset, const char *why);

/* Draw order without a depth test (interp_zorder.c): each draw opens a
 * run of its depth mode (a depth function other than GL_LESS, GL_LEQUAL or
 * GL_ALWAYS says NOTE_DEPTH at once); at the frame's end NOTE_DEPTH is said
 * where the ray tracer's nearest-first can show another primitive than
 * OpenGL's draw order, else held. */
void interp_zorder_draw(interp *ip);
void interp_zorder_begin_frame(interp *ip);
void interp_zorder_end_frame(interp *ip);
void interp_zorder_free(interp *ip);
/* Whether interp_note(kind) would log nothing now (said in this frame, or
 * no log): a costly test for a note may be skipped then. */
bool interp_note_said(const interp *ip, diag_kind kind);

/* glTexImage1D/2D's effect on the bound texture, pixels from resource id
 * (0: undefined contents), and glTexSubImage1D/2D's (dims 1 or 2): for
 * the copies of interp_texcopy.c (interp_teximage.c). */
void interp_tex_image(interp *ip, GLenum target, int32_t level, int32_t internal, int64_t w,
                      int64_t h, int32_t border, GLenum format, GLenum type, uint32_t id);
void interp_tex_subimage(interp *ip, int dims, GLenum target, int64_t level, int64_t x0,
                         int64_t y0, int64_t w, int64_t h, GLenum format, GLenum type,
                         uint32_t id);

/* Whether unit k draws a rectangle texture: its GL_TEXTURE_RECTANGLE is
 * enabled and neither 3D nor cube map is (interp_texdraw.c). */
bool interp_texture_rect_on(const interp *ip, uint32_t k);

/* Forgets the r coordinates seen (interp_texture.c): a new primitive
 * starts, whose r decides which slice of a 3D texture it shows. */
void interp_texture_r_reset(interp *ip);
/* Forgets the scene textures the last frame made (interp_texdraw.c). */
void interp_texture_begin_frame(interp *ip);

/* glTexImage3D's effect on the bound 3D texture (interp_teximage.c). */
void interp_tex_image3d(interp *ip, int32_t level, int32_t internal, int64_t w, int64_t h,
                        int64_t d, int32_t border, GLenum format, GLenum type, uint32_t id);
void interp_tex_subimage3d(interp *ip, int64_t level, int64_t x0, int64_t y0, int64_t z0,
                           int64_t w, int64_t h, int64_t d, GLenum format, GLenum type,
                           uint32_t id);

/* Whether wrap is one of EXT_texture_mirror_clamp's modes (interp_texture.c). */
bool interp_mirror_clamp(GLenum wrap);

/* Packed pixel types (interp_texpacked.c): the components of one packed
 * pixel of `type` and its *bytes, 0 for a type that is not packed; the
 * components of the pixel at p, in [0, 1], in component order. */
int interp_packed_layout(GLenum type, size_t *bytes);
void interp_packed_decode(const uint8_t *p, GLenum type, float out[4]);

/* Point parameters (interp_point.c): whether any is away from GL's
 * default, and the derived size of a point at eye-space position eye
 * (GL 1.4 3.3), *fade its alpha factor. */
bool interp_point_params_set(const gl_attribs *a);
double interp_point_size(const gl_attribs *a, const double eye[3], double *fade);

/* GL errors for the current command; the caller then returns (skips it). */
void interp_bad_enum(interp *ip, const char *what, uint32_t value);
void interp_bad_value(interp *ip, const char *fmt_detail);
void interp_bad_op(interp *ip, const char *why);

/* True, after logging GL_INVALID_OPERATION, when between glBegin and glEnd:
 * for every command GL does not allow there. */
bool interp_reject_in_begin(interp *ip);

/* ---- Shared between the files --------------------------------------------------- */

/* Pixels in client formats (interp_teximage.c). interp_pixel_bytes: the
 * tightly packed size of w x h pixels of format/type, 0 for a pair not
 * translated (index, depth and stencil formats) or too many
 * pixels. interp_pixels_float: n such pixels as GL's RGBA floats before
 * pixel transfer (GL 2.1 3.6.4). interp_pixels_fetch: the bytes of pixel
 * resource id, exactly `need` of them (counted in the frame's budget), or
 * NULL after a diagnostic (*lost = id when damage is why). */
size_t interp_pixel_bytes(GLenum format, GLenum type, int64_t w, int64_t h);

/* At the frame's end, the camera fixed: fits the image of bitmaps and
 * pixel rectangles to the camera's viewport, and notes that geometry drawn
 * after them shows behind them (interp_pixels.c). */
void interp_pixels_end_frame(interp *ip);
/* Forgets the last frame's converted pixel rectangles; frees them all
 * (interp_pixels.c). */
void interp_pixels_begin_frame(interp *ip);
void interp_pixels_free(interp *ip);
void interp_pixels_float(float *dst, const uint8_t *src, size_t n, GLenum format, GLenum type);
const uint8_t *interp_pixels_fetch(interp *ip, uint32_t id, size_t need, uint32_t *lost);

/* The frame's budget (interp_bounds.c). interp_bounds_begin_frame starts
 * a frame's counts. interp_budget_after is called after each command with
 * its offset, interp_budget_vertex before a vertex is assembled and
 * interp_budget_texels before texture bytes are read, copied or kept: each
 * returns false once the frame is cut (and cuts it when this one is over),
 * and the caller then stops. */
void interp_bounds_begin_frame(interp *ip);
bool interp_budget_over(interp *ip, uint64_t offset);
void interp_heavy_check(interp *ip);
/* A limit of the frame budget as this interpreter applies it. */
#define INTERP_LIMIT(ip, name) ((uint64_t)INTERP_BUDGET_##name >> (ip)->budget_shift)
static inline bool interp_budget_after(interp *ip, uint64_t offset)
{
    const scene *s = ip->scene;
    if ((ip->cmds_run & 1023) == 0 && !ip->heavy && ip->heavy_fn)
        interp_heavy_check(ip);
    if (ip->cut || ++ip->cmds_run > INTERP_LIMIT(ip, COMMANDS) ||
        (s && (s->nverts > INTERP_LIMIT(ip, VERTICES) || s->ntris > INTERP_LIMIT(ip, TRIANGLES) ||
               s->nlines + s->npoints > INTERP_LIMIT(ip, LINES) ||
               s->nsolids > INTERP_LIMIT(ip, SOLIDS) ||
               s->ninstances > INTERP_LIMIT(ip, INSTANCES))))
        return !interp_budget_over(ip, offset);
    return true;
}
/* interp_budget_after for a command that changed none of the scene's
 * counts it checks (or kept them within their limits), when the check
 * after the command before it passed: only the command count can be over.
 * True when it is not; else interp_budget_over(ip, offset) decides. */
static inline bool interp_budget_count(interp *ip)
{
    if ((ip->cmds_run & 1023) == 0 && !ip->heavy && ip->heavy_fn)
        interp_heavy_check(ip);
    return !ip->cut && ++ip->cmds_run <= INTERP_LIMIT(ip, COMMANDS);
}
bool interp_budget_vertex(interp *ip);
/* interp_budget_vertex with its common case (room left) inline. */
static inline bool interp_budget_vertex_fast(interp *ip)
{
    if (!ip->cut && ip->assembled < INTERP_LIMIT(ip, ASSEMBLED) &&
        (!ip->scene || ip->scene->nverts < INTERP_LIMIT(ip, VERTICES))) {
        ip->assembled++;
        return true;
    }
    return interp_budget_vertex(ip);
}
bool interp_budget_texels(interp *ip, uint64_t bytes);
/* Takes the scene's counts into the frame's peaks (interp_budget_used):
 * called before they fall (a shared list call, a clear, a dropped
 * accumulation pass) and at the frame's end. */
void interp_budget_peak(interp *ip);


/* Index of a cap, or -1 for an enum glEnable does not accept. */
int interp_cap_index(GLenum cap);

/* Fixes the frame's camera if no draw has yet (interp_raster.c). */
void interp_fix_camera(interp *ip);

/* Several projections in one frame (interp_proj.c). begin_frame forgets
 * the votes and the preset; clear notes a glClear of the whole colour
 * buffer; depth_clear a glClear of the depth buffer; vote counts a draw
 * with the current projection; own_draw notes a draw with the camera's
 * projection; layer rewrites a remapped draw's
 * window matrix w to put a draw made without the depth test in its
 * screen-space layer. */
void interp_proj_begin_frame(interp *ip);
void interp_proj_clear(interp *ip);
void interp_proj_own_draw(interp *ip);
void interp_proj_depth_clear(interp *ip);
void interp_proj_vote(interp *ip, GLenum mode);
void interp_proj_layer(interp *ip, mat4 *w);
/* Adds the current viewport to the frame's window (a draw's, a colour
 * clear's); widen_camera makes the picture's camera the preset window's
 * (interp_fix_camera). */
void interp_proj_window_add(interp *ip);
void interp_proj_widen_camera(interp *ip);
/* Maps the window depth of w (the draw's projection and viewport) into the
 * camera's: the draw's glDepthRange and its depth epoch. False when that
 * is the identity. */
bool interp_proj_depth_map(interp *ip, mat4 *w);
/* At the frame's end: an orthographic camera and its near plane step back
 * by the painter's reach (interp_proj.c). */
void interp_proj_end_frame(interp *ip);
/* Gives each triangle or quad after the first of a draw made without the
 * depth test (GL_TRIANGLES, GL_QUADS: n pool vertices from prim_first, in
 * object space) a painter's step of its own, so that the later of two
 * overlapping in one plane shows (interp_proj.c). */
void interp_proj_painter_prims(interp *ip, GLenum mode, uint32_t n);

/* The viewport-scaled projection of the current state: clip -> window-ish. */
mat4 interp_window_matrix(const mat4 *proj, const int32_t vp[4]);

/* Adds a vertex with the current attributes to the open primitive, which
 * must be drawing (in_begin, not prim_skip) (interp_prim.c). */
void interp_add_vertex(interp *ip, double x, double y, double z, double w);
/* The same for a plain primitive (prim_plain) and w = 1, when the current
 * normal and colour were just set to n and c (interp.c's glNormal3f,
 * glColor3f, glVertex3f): handed over in registers, not read back from
 * memory just after being stored, which stalls on store forwarding. */
void interp_add_vertex_nc(interp *ip, double x, double y, double z, float n0, float n1, float n2,
                          float c0, float c1, float c2, float c3);

/* glBegin(mode) and glEnd for the primitives the interpreter draws itself
 * (GLU and GLUT shapes): the same assembly, culling and polygon mode as
 * the program's own. interp_prim_begin returns false when the draw is
 * skipped (no scene, or a transform that places nothing); call
 * interp_prim_end either way (interp_assemble.c). */
bool interp_prim_begin(interp *ip, GLenum mode);
void interp_prim_end(interp *ip);

/* The look of a draw with the current state (interp_assemble.c). */
scene_look interp_current_look(interp *ip);

/* Texture objects (interp_texture.c): copied with the context state,
 * emptied by a reset, freed with the interpreter. */
int interp_textures_copy(interp *dst, const interp *src);
void interp_textures_free(interp *ip);

/* Accumulation passes (interp_accum.c): interp_accum_begin_frame forgets
 * the last frame's; interp_accum_draw is called at every draw's start;
 * interp_accum_clear by a glClear of the colour buffer returns true when
 * the clear only ends a pass (the scene keeps the first pass). */
void interp_accum_begin_frame(interp *ip);
void interp_accum_draw(interp *ip);

/* interp_fogsec.c. interp_fogsec_begin: at a draw's start (after the
 * texture units are known), whether its vertex colours take the colour sum
 * and the fog of the fog coordinate, with a note where they cannot.
 * interp_fogsec_vertex: applies them to one vertex colour (RGB, in place). */
void interp_fogsec_begin(interp *ip, GLenum mode);

/* interp_combine.c. _defaults: GL's initial combiner state. _texenv: a
 * glTexEnv of a combiner pname on the active unit (false: not one).
 * _mode: the fixed mode a unit's combiner setting equals (unit: its
 * index; first: the draw's first unit), or 0 when none does. */
void interp_combine_defaults(struct gl_texture_unit *t);
bool interp_combine_texenv(interp *ip, GLenum pname, double v);
GLenum interp_combine_mode(const struct gl_texture_unit *t, int unit, bool first);

/* interp_pixdepth.c. _raster: at glRasterPos, with its clip coordinates.
 * _draw: at each pixel draw, before the overlay is made. _end_frame:
 * places the overlay at the pixels' depth when they all share one
 * depth-tested plane (scene.overlay_at_depth); whether the overlay is then
 * where GL puts it (drawn_after: geometry was drawn after the last pixels). */
void interp_pixdepth_raster(interp *ip, const double clip[4]);
void interp_pixdepth_draw(interp *ip);
bool interp_pixdepth_end_frame(interp *ip, bool drawn_after);

/* GL's lit colour of a vertex at object point (x, y, z) with the current
 * normal, colour and material, as lit lines and points take it
 * (interp_prim.c); the raster position takes it too (GL 2.1 2.13). */
void interp_lit_point_colour(interp *ip, double x, double y, double z, float out[4]);
void interp_fogsec_vertex(interp *ip, float color[4]);
/* interp_fogsec_track: at each vertex, whether the draw keeps one fog
 * coordinate. interp_fogsec_look: a lit or textured draw fogged by fog
 * coordinates gets their one factor (look.fog_fixed), or a note. */
void interp_fogsec_track(interp *ip);
void interp_fogsec_look(interp *ip, scene_look *look);
/* The fog of the eye distance of eye-space point eye on a line end's or
 * point's colour, when fog is on and comes from the depth (interp_fogsec.c). */
void interp_fogsec_eye(interp *ip, const double eye[3], float color[4]);
/* GL_FOG_DISTANCE_MODE_NV as the scene's enum scene_fog_distance, and the
 * distance c it takes of an eye-space point (interp_fogbehind.c). */
int interp_fog_distance_kind(const interp *ip);
double interp_fog_distance(const interp *ip, const double eye[3]);
bool interp_accum_clear(interp *ip);

/* Evaluator state (interp_eval.c): copied with the context state (-1 on
 * allocation failure, the maps not copied then at their initial value),
 * freed by a reset and with the interpreter. */
int interp_eval_copy(interp *dst, const interp *src);
void interp_eval_free(interp *ip);

/* The Bezier curve of `order` points of k values each, packed, at t in
 * [0, 1] (GL 1.x 5.1, Bernstein polynomials), into out[k]; and the surface of
 * uorder x vorder points (u major) at (u, v), with its partial derivatives
 * in u and v into du and dv (either may be NULL). k <= 4, orders
 * 1..INTERP_MAX_EVAL_ORDER (interp_eval.c). */
void interp_eval_curve(const double *pts, int order, uint32_t k, double t, double *out);
void interp_eval_surface(const double *pts, int uorder, int vorder, uint32_t k, double u,
                         double v, double *out, double *du, double *dv);

/* A NURBS curve of n points of k values each (packed), order 1..24, over
 * n + order knots, at u (clamped to its domain [knots[order-1], knots[n]]),
 * into out[k], and its derivative into der (may be NULL); the surface of
 * un x vn points (u major) at (u, v), with partial derivatives into du and
 * dv (both or neither NULL), k <= 4. Homogeneous points stay homogeneous.
 * False when the sizes are invalid or every knot span is empty
 * (interp_nurbs.c). */
bool interp_nurbs_curve_at(const double *pts, uint32_t k, const double *knots, int n, int order,
                           double u, double *out, double *der);
bool interp_nurbs_surface_at(const double *pts, uint32_t k, const double *uknots, int un,
                             int uorder, const double *vknots, int vn, int vorder, double u,
                             double v, double *out, double *du, double *dv);

/* The texture index (in the scene) that a draw with the current state
 * samples, or -1 (interp_texdraw.c): its first enabled unit's. */
int32_t interp_texture_for_draw(interp *ip);
/* The same for texture unit k, or -1 when it is disabled or incomplete. */
int32_t interp_texture_for_unit(interp *ip, int k);
/* After a filled primitive's triangles (from first_tri): NOTE_TEX_MIPMAP
 * when a mipmapped texture's level of detail is not taken per pixel on
 * them (not runs of two or more triangles on one plane map, each with
 * lambda varying; scene_mip_split). */
void interp_tex_mip_check(interp *ip, size_t first_tri);

/* Texture units (interp_multitex.c). A unit's state as a draw reads it,
 * wherever it is kept (pointers into ip->st, valid until the next
 * command). */
typedef struct interp_tex_unit {
    const struct gl_texture_unit *texture;
    const uint8_t *caps; /* INTERP_CAP_TEXTURE_1D .. _GEN_Q, from 0 */
    const mat4 *matrix;  /* top of the unit's texture stack */
    const float *texcoord; /* current coordinates */
} interp_tex_unit;
interp_tex_unit interp_unit(interp *ip, uint32_t k);
/* Sets ip->draw_unit from the enables (notes a third enabled unit). */
void interp_draw_units(interp *ip);
/* Initial unit state, after the rest of st is (interp_default_state). */
void interp_multitex_defaults(gl_state *st);
/* Texture object `name` is deleted: parked units bound to it bind 0. */
void interp_multitex_unbind(interp *ip, uint32_t name);

/* The texture coordinates GL gives a vertex at object position obj (w = 1
 * after division) with normal nrm: texgen, then the texture matrix, then
 * division by q (interp_texdraw.c). */
void interp_vertex_texcoord(interp *ip, int unit, const double obj[4], const float nrm[3],
                            float out[2]);
/* The same with r (s, t, r: a cube map's direction), and whether a unit
 * draws a cube map (GL_TEXTURE_CUBE_MAP enabled). */
void interp_vertex_texcoord3(interp *ip, int unit, const double obj[4], const float nrm[3],
                             float out[3]);
bool interp_unit_cube(interp *ip, int unit);
/* The object -> eye transform a draw with modelview mv, projection proj and
 * viewport vp gets (remapped into the frame's camera as a draw does, but
 * without the painter's shift). False when no such transform exists. */
bool interp_object_to_eye(const interp *ip, const mat4 *mv, const mat4 *proj,
                         const int32_t vp[4], mat4 *out);

/* Moves to_eye toward the camera by the painter's shift of draw number
 * `painter` made without a depth test (interp_prim.c, painter_shift). */
void interp_painter_apply(const interp *ip, uint32_t painter, mat4 *to_eye);
/* How far the painter's shift has moved draws toward an orthographic
 * camera so far, plus one step (0 for a perspective camera): the near
 * plane lets that much through (interp_prim.c). */
double interp_painter_reach(const interp *ip);
#define INTERP_PAINTER_MAX 100000 /* painter counts no further */

/* Whether draws reach the picture: the render mode is GL_RENDER (else
 * a note says what is left out); and the look.names value of the current
 * name stack for a draw (interp_select.c). */
bool interp_render_mode_draws(interp *ip);
uint32_t interp_names_for_draw(interp *ip);

/* User clip planes (interp_clip.c). interp_clip_look: the id of the
 * enabled planes' set in the scene (scene_clip_index), 0 for none.
 * interp_clip_segment: clips eye-space segment p0-p1 by the enabled planes,
 * moving the ends and setting *t0, *t1 to their places along the original
 * (0 and 1 when whole); false when nothing is left. interp_clip_point:
 * whether an eye-space point is kept. */
uint32_t interp_clip_look(interp *ip);
bool interp_clip_segment(const interp *ip, double p0[3], double p1[3], double *t0, double *t1);
bool interp_clip_point(const interp *ip, const double p[3]);

/* The stencil test (interp_stencil.c). interp_stencil_draw: at a draw's
 * start, sets ip->stencil.write/clip/two_side and returns false when the
 * test hides the whole draw (two_side: the front faces' state decided it,
 * the back faces' would not have; interp_prim.c notes a back face drawn); interp_stencil_writes: draws now write the
 * stencil buffer; interp_stencil_look: the region a drawn look is kept
 * to; interp_stencil_tri: a triangle (eye space) a writing draw covers;
 * interp_stencil_clear: glClear of the stencil buffer. */
bool interp_stencil_draw(interp *ip);
bool interp_stencil_writes(const interp *ip);
/* The test is on with the two faces' states apart (glStencil*Separate). */
bool interp_stencil_faces_differ(const interp *ip);
void interp_stencil_look(interp *ip, scene_look *look);
void interp_stencil_tri(interp *ip, double p[3][3]);
void interp_stencil_clear(interp *ip);

/* The colour buffers (interp_buffers.c): interp_draw_buffer_hidden: what
 * is drawn now goes to no buffer the frame shows; interp_set_shown_front:
 * the frame shows the front buffer (it ends with glFlush or glFinish), or
 * the back one of a double-buffered context. */
bool interp_draw_buffer_hidden(const interp *ip);

/* The colour and depth masks (interp_masks.c): true when a draw changes
 * no colour (every colour channel masked) and is left out, with a note
 * when it writes depth; notes a partial colour mask. */
bool interp_masks_hide(interp *ip);
/* A colour clear (not scissored) under a partial colour mask over a frame
 * whose content so far is flat colours (unlit, untextured, opaque,
 * unfogged triangles, lines, points and pixels): the channels the mask
 * lets through take the clear colour in all of it and in the background,
 * the others keep theirs, as GL's pixels do. False (nothing changed) for
 * any other content. */
bool interp_masks_clear(interp *ip);

/* Line stipple (interp_stipple.c). interp_stipple_on: lines drawn now are
 * stippled. interp_stipple_dashes: the dashes GL draws of window segment
 * w0-w1 (already clipped), as [from, to] fractions of it (at most max),
 * GL's counter starting at *counter and advanced past the segment. */
#define INTERP_STIPPLE_DASHES 2048
bool interp_stipple_on(const interp *ip);
size_t interp_stipple_dashes(const interp *ip, const double w0[2], const double w1[2],
                             double *counter, double (*dash)[2], size_t max);
/* Polygon stipple (interp_pstipple.c): the look of a filled draw made now
 * takes the stipple when GL_POLYGON_STIPPLE is on and the mask has a hole. */
void interp_pstipple_look(const interp *ip, scene_look *look);

/* Lines and points as GL rasterises them (interp_lines.c). A segment in
 * eye space, already clipped by the user planes, with GL's colour at its
 * ends (the provoking vertex's at both when flat); width as glLineWidth
 * set it. interp_add_line clips it by the near and far planes and the
 * viewport and adds the strips that cover GL's pixels (each dash of them
 * when stippled, the counter running on). interp_add_point adds the
 * pixels of a point of that size (GL's size, after glPointParameter)
 * whose centre p is inside the view volume; a sprite (GL_POINT_SPRITE)
 * is the square of that size unrounded, GL's pixel centres inside it. */
typedef struct interp_line {
    double p[2][3];
    float color[2][4];
    float width;
    bool smooth, stipple;
    bool have_win;     /* win: the ends' window positions as GL computes them */
    double win[2][2];
} interp_line;
/* The window position (the frame's, in pixels) of object point obj drawn
 * now, computed in float as Mesa computes it, so that ties at pixel edges
 * and diamond corners fall its way; false when the draw is not made with
 * the camera's own projection and viewport (then the camera's mapping,
 * in double, places it). */
bool interp_gl_window(const interp *ip, const float obj[3], double out[2]);
void interp_add_line(interp *ip, const interp_line *ln, double *stipple_counter);
void interp_add_point(interp *ip, const double p[3], const double *win, const float color[4],
                      double size, bool smooth, bool params, bool sprite);

/* glPolygonOffset (interp_offset.c). interp_offset_active: polygons drawn
 * now are offset (their shapes are drawn as GL's facets);
 * interp_offset_apply: moves a polygon draw's to_eye along the camera's
 * rays by its offset (a note when it does). */
bool interp_offset_active(const interp *ip);
void interp_offset_apply(interp *ip, mat4 *to_eye);

/* Pixel maps and transfer (interp_pixmap.c): interp_pixel_transfer
 * applies the scales, biases and colour maps to one RGBA pixel (GL 2.1
 * 3.6.5); interp_pixels_transfer_note notes colour maps, and scales and
 * biases of pixels from_index colour indices, as Mesa applies them once
 * or twice;
 * interp_pixels_index_bytes is the size of w x h colour indices of
 * type (0: a type not translated), interp_pixels_index turns n of them
 * into RGBA by the index shift, offset and the I_TO_* maps. */
void interp_pixels_transfer_note(interp *ip, bool from_index);
void interp_pixel_transfer(const interp *ip, const float in[4], float out[4]);
size_t interp_pixels_index_bytes(GLenum type, int64_t w, int64_t h);
void interp_pixels_index(interp *ip, float *px, const uint8_t *src, size_t n, GLenum type);

/* glClear of the accumulation buffer (interp_accum.c). */
void interp_accum_buffer_clear(interp *ip);

/* Textured points and point sprites (interp_sprite.c): interp_point_textured
 * takes point pt of vertex v (true: pt is not to be kept) when the draw is
 * textured (a smooth point without sprites: noted, not taken); interp_point_sprites_end adds what it took as textured squares
 * at the draw's end; interp_lines_textured notes a textured line draw. */
bool interp_point_textured(interp *ip, const scene_point *pt, const scene_vertex *v, bool smooth);
void interp_point_sprites_end(interp *ip);
void interp_lines_textured(interp *ip);
void interp_sprites_free(interp *ip);

/* A scissored glClear of the stencil buffer (interp_stencil.c): only the
 * scissor box takes the clear value. */
void interp_stencil_clear_box(interp *ip);

/* Blending and logic ops (interp_blend.c). interp_blend_begin: at a
 * draw's start, -1 when interp_prim.c maps the blend itself, else the
 * SCENE_BLEND_* its vertices are stored with; interp_blend_end, at glEnd
 * with the draw's n vertices in the pool (object space), turns them into
 * what the scene shows of GL's blend or logic op, and sets prim_blend and
 * prim_filter (or notes what it cannot). */
bool interp_blend_factor_ok(GLenum f);
int interp_blend_begin(interp *ip, GLenum mode);
void interp_blend_end(interp *ip, uint32_t n);

/* What the colour buffer holds under the open draw (interp_dest.c): true,
 * with bg the clear colour, when the frame cleared it and nothing drawn
 * since reaches the draw's n vertices' footprint; with need_once, also
 * only when no two of its primitives share a pixel. interp_dest_free
 * releases what it keeps. */
bool interp_dest_draw(interp *ip, uint32_t n, bool need_once, float bg[4]);
void interp_dest_free(interp *ip);
/* Whether a scene item made after mark m may reach the box of the
 * overlay's pixels in the image (true where one cannot be placed). */
bool interp_dest_after_overlay(const interp *ip, const scene_mark *m);
/* A glClear of the depth buffer (scissored or not) after draws; at the
 * frame's end, a note where a later draw inside its box lies behind an
 * earlier one there, which GL's clear lets it cover and the scene does not
 * (interp_dest.c). */
void interp_dest_depth_clear(interp *ip);
void interp_dest_end_frame(interp *ip);

/* The scissor test (interp_scissor.c). interp_scissor_cuts: it is on and
 * its box leaves out part of viewport vp. interp_scissor_clear: a glClear
 * of the colour buffer with the scissor test on; false when the box holds
 * the whole viewport (the caller clears everything), else it keeps the box
 * for interp_scissor_end_frame, which adds the boxes to the scene once the
 * frame's camera is fixed. */
bool interp_scissor_cuts(const interp *ip, const int32_t vp[4]);
/* With the camera fixed: whether the box leaves nothing of the picture
 * (a draw then draws nothing); and look's scissor fields for a draw now. */
bool interp_scissor_hides(const interp *ip);
void interp_scissor_look(const interp *ip, scene_look *look);

/* The alpha test (interp_alphatest.c). interp_alpha_vertex: vertex k of
 * the primitive, of alpha a as GL computed it (before blending forces
 * it): INTERP_ALPHA_FAIL when it fails the test, else 0; kept with the
 * vertex's edge flag (ip->edge, bit 0). interp_alpha_face: false when GL
 * discards all of polygon idx (relative to prim_first; every vertex fails
 * and the texture's alpha, scene texture `texture` or -1, does not
 * count); notes the cases drawn approximately. */
#define INTERP_ALPHA_FAIL 2
uint8_t interp_alpha_vertex(interp *ip, size_t k, float a);
/* Whether the alpha test discards anything now (enabled, not GL_ALWAYS). */
bool interp_alpha_testing(const interp *ip);
bool interp_alpha_face(interp *ip, const uint32_t *idx, int n, int32_t texture);
bool interp_scissor_clear(interp *ip);
void interp_scissor_end_frame(interp *ip);

/* Closes an open glBegin without drawing it (interp_assemble.c). */
void interp_abort_begin(interp *ip);
/* Opens a primitive of mode (glBegin, glRect; interp_prim.c). */
void interp_begin_mode(interp *ip, GLenum mode);

/* The display-list table's life cycle, called from interp.c and
 * interp_begin_frame (interp_list.c). copy returns false on allocation
 * failure (dst then has no lists). */
void interp_lists_reset(interp *ip);
bool interp_lists_copy(interp *dst, const interp *src);
void interp_lists_free(interp *ip);
void interp_lists_begin_frame(interp *ip);

/* Forgets the @ArrayData of the current sequence (interp_array.c). */
void interp_arrays_forget(interp *ip);

/* Initial values (interp.c). */
void interp_default_state(gl_state *st);

/* GLU NURBS state's life cycle (interp_nurbs.c): copy returns -1 on
 * allocation failure (dst then has the initial properties). */
void interp_nurbs_free(interp *ip);
int interp_nurbs_copy(interp *dst, const interp *src);

/* Marks the colour glColor sets into the material with GL_COLOR_MATERIAL
 * (interp_light.c). */
void interp_color_material_update(interp *ip);

/* Colour material as Mesa follows it (interp_light.c): interp_cm_colour
 * after the current colour changed while GL_COLOR_MATERIAL is on (in place
 * of interp_color_material_update); interp_cm_enable at the cap's change;
 * interp_cm_draw as a draw (or glRasterPos) starts. interp_cm_on: the material's terms
 * colour material names come from the colour now (on, and not kept from
 * before the glEnable). */
void interp_cm_colour(interp *ip);
void interp_cm_enable(interp *ip, bool on);
void interp_cm_draw(interp *ip);
/* Mesa flushes its vertex buffer here (glNewList, glEndList, glCallList,
 * glPushAttrib, glPopAttrib): a glMaterial before no longer holds. */
static inline void interp_cm_flush(interp *ip) { ip->st.cm.held[0] = ip->st.cm.held[1] = 0; }
static inline bool interp_cm_on(const interp *ip)
{
    return ip->st.a.caps[INTERP_CAP_COLOR_MATERIAL] && !ip->st.cm.stale;
}

/* The scene material index of the current lighting state, with the light
 * set of the lights enabled now (interp_light.c, interp_lightset.c); -1 on
 * failure. */
int32_t interp_lit_material(interp *ip);

/* Fixes the frame's fog at its first fogged draw (interp_light.c). */
void interp_fix_fog(interp *ip);

/* GL's lit colour (GL 1.x 2.13.1) of a vertex at eye position p with eye
 * normal n, for the front (back = false) or back material, from the
 * current state; colour is the vertex colour for GL_COLOR_MATERIAL.
 * For lines and points, which the scene draws unlit (interp_light.c). */
/* glMaterial between vertices (interp_vmaterial.c): _begin at glBegin,
 * _before_change in glMaterial before it changes the material, _vertex
 * after each vertex is added to the pool, _end at glEnd of a filled primitive of n
 * vertices before its look is made (true: the material was swapped, saved
 * in `saved`, to be put back by _restore after the look). */
void interp_vmat_begin(interp *ip);
void interp_vmat_before_change(interp *ip);
void interp_vmat_vertex(interp *ip);
bool interp_vmat_end(interp *ip, uint32_t n, gl_material saved[2]);
void interp_vmat_restore(interp *ip, const gl_material saved[2]);
uint8_t interp_cm_bits(GLenum mode);

/* Whether the open filled primitive is lit per vertex here
 * (interp_gouraud.c): vertex lighting on, lighting on, one-sided. */
bool interp_vertex_lit(const interp *ip);

/* Notes a lit primitive (its triangles from first_tri on) with a face
 * large against its distance to a positional light or, with a local
 * viewer, to the eye: lit per pixel, it differs from GL's per-vertex
 * lighting (interp_gouraud.c). */
void interp_gouraud_check(interp *ip, size_t first_tri);

/* The light set of the GL lights enabled now, added to the scene when the
 * frame has not had it yet (interp_lightset.c). */
uint32_t interp_lightset_current(interp *ip);

/* Notes a lit, textured draw under a set whose highlights only the
 * per-channel form makes exact (not open to textures). */
void interp_lightset_textured(interp *ip, const scene_look *look);

/* The spot factor of directional light l (w = 0), one number for every
 * vertex: GL spots such a light too (1 when its cutoff is 180). */
double interp_spot_parallel(const gl_light *l);

void interp_lit_color(const interp *ip, const double p[3], const double n[3], bool back,
                      const float colour[4], float out[4]);
/* The same, with the largest channel before GL clamps it in *peak. */
void interp_lit_color_peak(const interp *ip, const double p[3], const double n[3], bool back,
                           const float colour[4], float out[4], double *peak);

/* interp_lit_color_peak in two steps, for many vertices lit under one
 * state (a primitive's: between glBegin and glEnd only glMaterial changes
 * it, and the kept colours are made before, interp_relit_flush).
 * _prepare finds once what every vertex reads of the lights and of
 * GL_COLOR_MATERIAL; _prepared lights one vertex as interp_lit_color_peak
 * does, bit for bit, while that state holds. */
typedef struct interp_lit_prep {
    int face;          /* the material lit: 1 for back faces under two-sided lighting */
    uint8_t cm;        /* SCENE_CM_* terms the vertex colour gives */
    bool local_viewer;
    bool need_p;       /* a positional light or a local viewer reads the eye point */
    int nlights;
    uint8_t light[INTERP_MAX_LIGHTS]; /* the lights on that add something, in order */
    /* For interp_prim.c's vertices in object space: the modelview, its
     * inverse (NULL: singular) and GL_RESCALE_NORMAL's factor. */
    const mat4 *mv, *inv;
    bool normalize, rescale;
    double rescale_r;
} interp_lit_prep;
void interp_lit_prepare(const interp *ip, bool back, interp_lit_prep *lp);
void interp_lit_prepared(const interp *ip, const interp_lit_prep *lp, const double p[3],
                         const double n[3], const float colour[4], float out[4], double *peak);

/* GL's own lighting for the faces POV-Ray would light otherwise
 * (interp_relit.c): back faces under one-sided lighting, and textured
 * GL_MODULATE surfaces lit past white (GL clamps before the texture).
 * _wanted: the open filled primitive's vertices need GL's lit colour;
 * _defer: keeps vertex k's inputs (the current normal and colour) for
 * (inline, at every vertex; _grow: room for vertex k, false when none)
 * _flush, which makes the kept vertices' colours (at a change of material
 * between vertices, and when glEnd needs them); _prepare: GL's state for
 * _colour (interp_lit_prepare), which gives one vertex's (post-processed)
 * lit colour and its unclamped peak (peak may be NULL);
 * _split: at glEnd, which faces go to a GL-lit mesh (0: none,
 * INTERP_RELIT_BACK: back faces, INTERP_RELIT_ALL: all); _need_clear:
 * no vertex marked in relit_need, no face kept in relit_tris yet (false:
 * out of memory); _vertices: the marked ones of the primitive's n
 * vertices copied with their GL colours, relit_copy[k] the pool index of
 * vertex k's copy (false on failure); _done: forget the primitive. */
/* Fog of primitives reaching behind the eye (interp_fogbehind.c). _check:
 * at glEnd of n pool vertices (before they move to eye space), notes a
 * fogged line or unfilled polygon with vertices both behind and in front
 * of the eye, or sets fog_split for a filled one; _mesh: the mesh for the
 * triangle rel (relative to base), with its own fog plane when a corner is
 * behind the eye. */
void interp_fog_behind_check(interp *ip, uint32_t n);
scene_mesh *interp_fog_behind_mesh(interp *ip, const scene_look *look, const mat4 *to_eye,
                                   bool in_eye, uint32_t base, const uint32_t rel[3]);

#define INTERP_RELIT_BACK 1
#define INTERP_RELIT_ALL 2
#define INTERP_RELIT_PROBE 3 /* back faces noted (NOTE_RELIT_SPECULAR), drawn as they are */
bool interp_relit_wanted(const interp *ip);
bool interp_relit_grow(interp *ip, size_t k);
static inline void interp_relit_defer(interp *ip, size_t k, double x, double y, double z,
                                      const float normal[3], const float colour[4])
{
    if (k == 0)
        ip->relit_pending = ip->relit_made = 0;
    if (k != ip->relit_pending)
        return; /* an earlier vertex was not kept: _vertices will refuse */
    if (k >= ip->cap_relit_in && !interp_relit_grow(ip, k))
        return;
    interp_relit_in *in = &ip->relit_in[k];
    in->p[0] = x, in->p[1] = y, in->p[2] = z;
    memcpy(in->normal, normal, sizeof in->normal);
    memcpy(in->colour, colour, sizeof in->colour);
    ip->relit_pending = k + 1;
}
void interp_relit_flush(interp *ip);
void interp_relit_prepare(interp *ip, interp_lit_prep *lp);
void interp_relit_colour(interp *ip, const interp_lit_prep *lp, const interp_relit_in *in,
                         float c[4], double *peak);
int interp_relit_split(interp *ip, const scene_look *look);
/* Whether a lit vertex of the open primitive can come out past white in a
 * channel without its highlight (a bound from the material, colour
 * material and the lights). */
bool interp_relit_may_saturate(const interp *ip);
bool interp_relit_need_clear(interp *ip, uint32_t n);
bool interp_relit_vertices(interp *ip, uint32_t n);
void interp_relit_done(interp *ip);

/* The colour a surface vertex carries into the scene (scene_vertex.color):
 * glColor unlit; lit, what GL_COLOR_MATERIAL takes from glColor (or the
 * front diffuse colour) with GL's lit alpha; alpha 1 unless blending
 * (interp_prim.c). */
void interp_surface_colour(const interp *ip, float out[4]);

static inline float clamp01(float x) { return x > 0 ? (x < 1 ? x : 1) : 0; /* NaN -> 0 */ }

/* Records that this frame draws something unrecorded calls of use u act on
 * (format/unrecorded.def's UNREC_USE rows; interp_unrecorded.c). */
static inline void interp_unrec_use(interp *ip, unrec_use u)
{
    if (ip->scene)
        ip->unrecorded.uses |= 1u << u;
}

/* The uses of a pixel operation: one that draws into the colour buffer
 * (bitmaps, glDrawPixels, glCopyPixels), reads it where the trace lacks
 * what it read (glCopyPixels, glCopyTex*Image not read back: those read
 * back hold the program's read buffer's pixels, whichever it was) or
 * reads an image from the program's memory (textures,
 * pixels, bitmaps, stipples); under GL_MAP_COLOR or GL_MAP_STENCIL, the
 * pixel maps' too. */
void interp_unrec_pixel_uses(interp *ip, bool draws, bool reads, bool from_memory);

/* The uses of a draw beginning now (begin_mode): blending, stencil,
 * points, multisample coverage (textures: interp_draw_units). */
void interp_unrec_draw_uses(interp *ip, GLenum mode);

#endif
