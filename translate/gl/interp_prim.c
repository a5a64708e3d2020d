/* interp_prim.c: glBegin, the current vertex attributes, and the vertices
 * of a primitive; interp_assemble.c assembles them at glEnd.
 *
 * Vertices go straight into the scene's vertex pool as they arrive, with
 * the current normal, colour and texture coordinates (GL 1.x 2.7).
 */
#include "interp_internal.h"

#include <string.h>

#include "talloc.h"

#define PRIM_PLAIN_UNLIT 1 /* interp_internal.h, prim_plain */
#define PRIM_PLAIN_LIT 2

/* ---- Current attributes ------------------------------------------------------ */

/* GL 1.x table 2.9: integer colour and normal components map to [0, 1] or
 * [-1, 1]: unsigned c / (2^b - 1), signed (2c + 1) / (2^b - 1). */
static double normalise(uint8_t type, double c)
{
    switch (type) {
    case RGL_T_ub: return c / 255.0;
    case RGL_T_b: return (2 * c + 1) / 255.0;
    case RGL_T_us: return c / 65535.0;
    case RGL_T_s: return (2 * c + 1) / 65535.0;
    case RGL_T_ui: return c / 4294967295.0;
    case RGL_T_i: return (2 * c + 1) / 4294967295.0;
    default: return c;
    }
}

void interp_color(interp *ip, const rgl_cmd *cmd)
{
    uint32_t n = cmd_value_count(cmd);
    uint8_t type = cmd_value_type(cmd);
    float *c = ip->st.a.current.color;
    for (uint32_t k = 0; k < 4; k++)
        c[k] = k < n ? (float)normalise(type, cmd_value(cmd, k)) : 1.0f;
    if (ip->st.a.caps[INTERP_CAP_COLOR_MATERIAL])
        interp_cm_colour(ip);
}

/* The current secondary colour and fog coordinate: taken by each vertex
 * (interp_fogsec.c). */
void interp_secondarycolor(interp *ip, const rgl_cmd *cmd)
{
    uint8_t type = cmd_value_type(cmd);
    for (uint32_t k = 0; k < 3; k++)
        ip->st.a.current.secondary[k] = (float)normalise(type, cmd_value(cmd, k));
}

void interp_fogcoord(interp *ip, const rgl_cmd *cmd)
{
    double v = cmd_value(cmd, 0);
    ip->st.a.current.fog_coord = isfinite(v) ? (float)v : 0.0f;
}

void interp_normal(interp *ip, const rgl_cmd *cmd)
{
    uint8_t type = cmd_value_type(cmd);
    for (uint32_t k = 0; k < 3; k++)
        ip->st.a.current.normal[k] = (float)normalise(type, cmd_value(cmd, k));
}

void interp_texcoord(interp *ip, const rgl_cmd *cmd)
{
    uint32_t n = cmd_value_count(cmd);
    static const float def[4] = {0, 0, 0, 1};
    for (uint32_t k = 0; k < 4; k++)
        ip->st.a.current.texcoord[k] = k < n ? (float)cmd_value(cmd, k) : def[k];
}

void interp_edgeflag(interp *ip, const rgl_cmd *cmd)
{
    ip->st.a.current.edge_flag = rgl_arg_i(&cmd->arg[0], 0) != 0;
}

/* ---- glBegin ------------------------------------------------------------------- */

/* Notes for state this draw uses but the scene does not translate (yet). */
static void draw_notes(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    const uint8_t *c = a->caps;
    if (c[INTERP_CAP_FOG])
        interp_fix_fog(ip);
    if (c[INTERP_CAP_ALPHA_TEST] && a->color_buffer.alpha_func != GL_ALWAYS &&
        ip->prim_mode <= GL_LINE_STRIP)
        interp_note(ip, DIAG_NOTE_ALPHA_TEST); /* polygons: interp_alpha_face */
    /* Cube maps and 3D textures are drawn (interp_texdraw.c): their notes
     * come with the texture, as the environment's do. */
    /* Polygon stipple: interp_pstipple.c; line stipple: interp_stipple.c. */
    if (interp_scissor_cuts(ip, a->viewport.rect) && ip->prim_mode <= GL_LINE_STRIP)
        interp_note(ip, DIAG_NOTE_SCISSOR); /* lines and points: drawn whole */
    /* Blend equations and logic ops: interp_blend.c; the fade threshold:
     * add_point, for points below it. */
    interp_zorder_draw(ip); /* NOTE_DEPTH, at the frame's end */
    /* GL 1.x 3.9: with GL_SINGLE_COLOR the texture modulates the specular
     * term too; POV-Ray adds the highlight after the texture, which is
     * GL_SEPARATE_SPECULAR_COLOR. */
    if (c[INTERP_CAP_LIGHTING] && a->lighting.color_control == GL_SINGLE_COLOR &&
        (c[INTERP_CAP_TEXTURE_2D] || c[INTERP_CAP_TEXTURE_1D]) &&
        a->texture.env_mode == GL_MODULATE) {
        const float *sp = a->lighting.material[0].specular, *bp = a->lighting.material[1].specular;
        bool cm_spec = interp_cm_on(ip) &&
                       a->lighting.color_material_mode == GL_SPECULAR;
        if (cm_spec || sp[0] > 0 || sp[1] > 0 || sp[2] > 0 || bp[0] > 0 || bp[1] > 0 || bp[2] > 0)
            interp_note(ip, DIAG_NOTE_SINGLE_COLOR);
    }
}

/* Without a depth test GL shows the later of two draws where they overlap;
 * a ray tracer shows the nearer. For draws in one plane (the common case:
 * 2D drawings) the tie is broken toward draw order by moving each draw
 * made without a depth test a little closer to the camera than the one
 * before. POV-Ray does not tell apart two surfaces closer than about 2e-4
 * along a ray (measured: a translucent triangle 1e-4 in front of another
 * hides it, 3e-4 shows both, at distances 0.01 to 10^4), so the steps are
 * at least that at the scene's scale: PAINTER_ORTHO eye units along the
 * view direction (orthographic: the camera and its near plane move back by
 * the frame's whole shift, interp_proj.c), or a factor 1 - k
 * PAINTER_PERSP about the eye (perspective: image positions unchanged;
 * k stops at PAINTER_PERSP_MAX, half way to the eye). k counts such draws
 * since the frame's start or last clear. Surfaces truly apart stay in
 * depth order (docs/mapping.md, "What a ray tracer does differently" and
 * "Projections, depth and draw order"). */
#define PAINTER_ORTHO 1e-3
#define PAINTER_PERSP 5e-5
#define PAINTER_PERSP_MAX 10000
#define PAINTER_MAX INTERP_PAINTER_MAX

double interp_painter_reach(const interp *ip)
{
    return ip->scene && ip->scene->camera.kind == SCENE_CAMERA_ORTHOGRAPHIC
               ? (ip->painter + 1) * PAINTER_ORTHO
               : 0;
}

void interp_painter_apply(const interp *ip, uint32_t painter, mat4 *to_eye)
{
    const scene_camera *cam = &ip->scene->camera;
    mat4 s = mat4_identity();
    if (cam->kind == SCENE_CAMERA_ORTHOGRAPHIC) {
        double k = painter * PAINTER_ORTHO;
        double dl = sqrt(cam->direction[0] * cam->direction[0] +
                         cam->direction[1] * cam->direction[1] +
                         cam->direction[2] * cam->direction[2]);
        if (!(dl > 0))
            return;
        for (int i = 0; i < 3; i++)
            s.m[12 + i] = -cam->direction[i] / dl * k;
    } else {
        double f = 1 - (painter < PAINTER_PERSP_MAX ? painter : PAINTER_PERSP_MAX) * PAINTER_PERSP;
        for (int i = 0; i < 3; i++) {
            s.m[i * 5] = f;
            s.m[12 + i] = cam->location[i] * (1 - f);
        }
    }
    *to_eye = mat4_mul(&s, to_eye);
}

static void painter_shift(interp *ip, mat4 *to_eye)
{
    const gl_attribs *a = &ip->st.a;
    if (a->caps[INTERP_CAP_DEPTH_TEST] && (a->depth.func == GL_LESS || a->depth.func == GL_LEQUAL))
        return;
    if (ip->painter < PAINTER_MAX)
        ip->painter++;
    interp_painter_apply(ip, ip->painter, to_eye);
}

bool interp_object_to_eye(const interp *ip, const mat4 *mv, const mat4 *proj,
                         const int32_t vp[4], mat4 *out)
{
    *out = *mv;
    if (!ip->frame_begin &&
        (memcmp(vp, ip->own_vp, sizeof ip->own_vp) != 0 || !mat4_equal_f32(proj, &ip->own_proj))) {
        if (!ip->cam_from_ndc_ok)
            return false;
        mat4 w = interp_window_matrix(proj, vp);
        mat4 remap = mat4_mul(&ip->cam_from_ndc, &w);
        *out = mat4_mul(&remap, mv);
    }
    return mat4_finite(out);
}

/* Sets prim_to_eye / prim_clip for a draw with the current matrices.
 * Returns false when the transform cannot place anything. */
static bool setup_transform(interp *ip)
{
    const mat4 *mv = interp_matrix(ip, INTERP_MV);
    const mat4 *proj = interp_matrix(ip, INTERP_PROJ);
    mat4 to_eye = *mv;

    ip->prim_clip = mat4_mul(proj, mv);
    if (!ip->frame_begin) {
        const int32_t *vp = ip->st.a.viewport.rect;
        bool same_vp = memcmp(vp, ip->own_vp, sizeof ip->own_vp) == 0;
        mat4 w = interp_window_matrix(proj, vp);
        bool own = same_vp && mat4_equal_f32(proj, &ip->own_proj);
        if (!own)
            interp_proj_layer(ip, &w);
        /* glDepthRange and depth-only clears move the draw's depth: along
         * the camera's rays, so the picture keeps its pixels. */
        bool moved = interp_proj_depth_map(ip, &w);
        if (!own || moved) {
            /* Drawn with another projection or viewport: map its window
             * position into the camera's eye space. Window x, y and depth
             * are GL's, so colours and depth order are exact; lighting,
             * fog and depth-tested textures are seen from the camera. */
            const uint8_t *c = ip->st.a.caps;
            if ((c[INTERP_CAP_LIGHTING] && ip->prim_mode > GL_LINE_STRIP) || c[INTERP_CAP_FOG] ||
                ((c[INTERP_CAP_TEXTURE_2D] || c[INTERP_CAP_TEXTURE_1D]) &&
                 c[INTERP_CAP_DEPTH_TEST]))
                interp_note(ip, DIAG_NOTE_PROJECTION);
            if (!ip->cam_from_ndc_ok)
                return false;
            mat4 remap = mat4_mul(&ip->cam_from_ndc, &w);
            to_eye = mat4_mul(&remap, mv);
        }
        if (own)
            interp_proj_own_draw(ip);
    }
    if (!mat4_finite(&to_eye) || !mat4_finite(&ip->prim_clip)) {
        interp_diag(ip, DIAG_BAD_NUMBER, "matrix with NaN or infinite elements: draw skipped");
        return false;
    }
    painter_shift(ip, &to_eye);
    interp_offset_apply(ip, &to_eye);
    ip->prim_to_eye = to_eye;
    ip->prim_in_eye = false;
    if (!mat4_affine(&to_eye)) {
        if (mat4_affine(mv))
            ; /* the remap is projective, not the program's matrix: no note */
        else
            interp_note(ip, DIAG_NOTE_PROJECTIVE_MODELVIEW);
        ip->prim_in_eye = true;
    } else {
        /* POV-Ray cannot invert a singular matrix: flatten such draws. */
        double det = mat4_det3(&to_eye), scale = 0;
        for (int i = 0; i < 11; i++)
            if (i % 4 != 3)
                scale = fmax(scale, fabs(to_eye.m[i]));
        if (!(fabs(det) > 1e-12 * scale * scale * scale))
            ip->prim_in_eye = true;
    }
    return true;
}

/* GL_BLEND's weight (GL 1.x 4.1.7) for the factors that depend on the
 * source alpha only. The colour factors, and the destination alpha (the
 * framebuffer's alpha is not known here), return false. */
static bool alpha_weight(GLenum f, double as, double *w)
{
    switch (f) {
    case GL_ZERO:
        *w = 0;
        return true;
    case GL_ONE:
        *w = 1;
        return true;
    case GL_SRC_ALPHA:
        *w = as;
        return true;
    case GL_ONE_MINUS_SRC_ALPHA:
        *w = 1 - as;
        return true;
    default:
        return false;
    }
}

/* How much of a draw's colour covers what is behind it: GL_BLEND with
 * GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA covers alpha (POV-Ray's transmit
 * 1 - alpha is exactly that blend). Other functions of the source alpha
 * are mapped onto transmit per vertex (map_blend) where the vertex colour
 * is GL's final colour (unlit, or lit lines and points, untextured); the
 * rest is drawn as GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, with a note. */
static uint8_t blend_mode(interp *ip, GLenum mode)
{
    const gl_attribs *a = &ip->st.a;
    ip->prim_blend_mapped = false;
    int fx = interp_blend_begin(ip, mode);
    if (fx >= 0)
        return (uint8_t)fx;
    if (!a->caps[INTERP_CAP_BLEND])
        return SCENE_BLEND_OPAQUE;
    if (a->color_buffer.blend_equation != GL_FUNC_ADD)
        interp_note(ip, DIAG_NOTE_BLEND_EQUATION); /* lit, textured or fogged */
    GLenum src = a->color_buffer.blend_src, dst = a->color_buffer.blend_dst;
    if (src == GL_SRC_ALPHA && dst == GL_ONE_MINUS_SRC_ALPHA)
        return SCENE_BLEND_ALPHA;
    if (src == GL_ONE && dst == GL_ZERO)
        return SCENE_BLEND_OPAQUE;
    if (src == GL_ZERO && dst == GL_ONE)
        return SCENE_BLEND_INVISIBLE;
    double w;
    bool final_colour = !(a->caps[INTERP_CAP_LIGHTING] && mode > GL_LINE_STRIP) &&
                        !a->caps[INTERP_CAP_TEXTURE_1D] && !a->caps[INTERP_CAP_TEXTURE_2D];
    if (final_colour && alpha_weight(src, 0, &w) && alpha_weight(dst, 0, &w))
        ip->prim_blend_mapped = true;
    else
        interp_note(ip, DIAG_NOTE_BLEND);
    return SCENE_BLEND_ALPHA;
}

/* GL shows ws c + wd behind; POV-Ray shows (1 - t) k + t behind for a
 * pigment k with transmit t. So t = wd and k = ws c / (1 - wd), exact,
 * except where wd = 1 (additive blending), which transmit cannot reach:
 * there t = 127/128, which keeps all but 1/128 of what is behind (under
 * 2/255), with a note. k may exceed 1: POV-Ray clamps only the pixel, as
 * GL clamps the blended sum. */
#define BLEND_MIN_COVER (1.0 / 128)

static void map_blend(interp *ip, float c[4])
{
    const gl_attribs *a = &ip->st.a;
    double ws = 0, wd = 0, as = c[3];
    alpha_weight(a->color_buffer.blend_src, as, &ws);
    alpha_weight(a->color_buffer.blend_dst, as, &wd);
    double cover = 1 - wd;
    if (cover < BLEND_MIN_COVER) {
        cover = BLEND_MIN_COVER;
        if (ws > 0)
            interp_note_pov(ip, DIAG_NOTE_BLEND_ADD, DIAG_NOTE_GLTF_BLEND_ADD);
    }
    for (int i = 0; i < 3; i++)
        c[i] = (float)(c[i] * ws / cover);
    c[3] = (float)cover;
}

void interp_begin_mode(interp *ip, GLenum mode)
{
    interp_cm_draw(ip);
    ip->in_begin = true;
    ip->prim_mode = mode;
    ip->prim_skip = true;
    ip->prim_plain = 0;
    ip->prim_fx = false;
    ip->prim_filter = 0;
    interp_vmat_begin(ip);
    ip->prim_color_sum = ip->prim_fog_vertex = false;
    if (!ip->scene || !interp_render_mode_draws(ip))
        return;
    interp_accum_draw(ip);
    if (ip->accum.active)
        return; /* a later accumulation pass: the scene holds the first */
    interp_unrec_draw_uses(ip, mode);
    draw_notes(ip);
    interp_proj_vote(ip, mode);
    interp_fix_camera(ip);
    if (interp_scissor_hides(ip) || !interp_stencil_draw(ip) || interp_masks_hide(ip) ||
        !setup_transform(ip))
        return;
    ip->prim_skip = false;
    ip->prim_first = ip->scene->nverts;
    interp_draw_units(ip);
    ip->prim_blend = blend_mode(ip, mode);
    interp_fogsec_begin(ip, mode);
    const uint8_t *c = ip->st.a.caps;
    bool lit = c[INTERP_CAP_LIGHTING];
    ip->prim_plain = 0;
    if (mode > GL_LINE_STRIP && !(lit && interp_vertex_lit(ip)) && ip->draw_unit[0] < 0 &&
        !ip->prim_color_sum && !ip->prim_fog_vertex && !ip->prim_blend_mapped &&
        !interp_alpha_testing(ip))
        ip->prim_plain = lit ? PRIM_PLAIN_LIT : PRIM_PLAIN_UNLIT;
    ip->prim_plain_relit = interp_relit_wanted(ip);
}

void interp_begin(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    if (mode > GL_POLYGON) {
        interp_bad_enum(ip, "primitive mode", mode);
        return;
    }
    interp_begin_mode(ip, mode);
}

/* ---- Vertices ---------------------------------------------------------------- */

/* interp_surface_colour with the current colour (c0, c1, c2, c3): the
 * caller's copy of it, in registers (add_vertex_plain). */
static inline void surface_colour(const interp *ip, float c0, float c1, float c2, float c3,
                                  float out[4])
{
    const gl_attribs *a = &ip->st.a;
    if (a->caps[INTERP_CAP_LIGHTING]) {
        /* The writer lights it: the colour carries what GL_COLOR_MATERIAL
         * takes from glColor, and GL's lit alpha, the diffuse one
         * (interp_color_material_update keeps the material's diffuse equal
         * to glColor when colour material covers it). */
        const gl_material *fm = &a->lighting.material[0];
        if (!interp_cm_on(ip))
            c0 = fm->diffuse[0], c1 = fm->diffuse[1], c2 = fm->diffuse[2];
        c3 = fm->diffuse[3];
    }
    out[0] = clamp01(c0);
    out[1] = clamp01(c1);
    out[2] = clamp01(c2);
    if (ip->prim_blend == SCENE_BLEND_OPAQUE)
        out[3] = 1;
    else if (ip->prim_blend == SCENE_BLEND_INVISIBLE)
        out[3] = 0;
    else
        out[3] = clamp01(c3);
}

void interp_surface_colour(const interp *ip, float out[4])
{
    const float *c = ip->st.a.current.color;
    surface_colour(ip, c[0], c[1], c[2], c[3], out);
}

/* GL's lit colour at a vertex in object space, with its normal in GL's own
 * eye space (2.11.3: the inverse transpose of the modelview, normalised
 * under GL_NORMALIZE, rescaled under GL_RESCALE_NORMAL). lit_prepare
 * finds the modelview's inverse (kept while the matrix is bit for bit the
 * same) and the lighting state once for a primitive's vertices. */
/* back: as GL lights back faces (two-sided lighting's back material and
 * the normal turned). */
static void lit_prepare_side(interp *ip, interp_lit_prep *lp, bool back)
{
    const gl_attribs *a = &ip->st.a;
    const mat4 *mv = interp_matrix(ip, INTERP_MV);
    if (!ip->lit_mv_set || memcmp(&ip->lit_mv, mv, sizeof *mv) != 0) {
        ip->lit_mv = *mv;
        ip->lit_mv_ok = mat4_invert(mv, &ip->lit_mv_inv);
        ip->lit_mv_set = true;
    }
    interp_lit_prepare(ip, back, lp);
    lp->mv = mv;
    lp->inv = ip->lit_mv_ok ? &ip->lit_mv_inv : NULL;
    lp->normalize = a->caps[INTERP_CAP_NORMALIZE];
    lp->rescale = a->caps[INTERP_CAP_RESCALE_NORMAL];
    const double *im = ip->lit_mv_inv.m;
    lp->rescale_r = sqrt(im[2] * im[2] + im[6] * im[6] + im[10] * im[10]);
}

static void lit_prepare(interp *ip, interp_lit_prep *lp) { lit_prepare_side(ip, lp, false); }

static void lit_colour_at(const interp *ip, const interp_lit_prep *lp, double x, double y,
                          double z, const float cn[3], const float colour[4], float out[4],
                          double *peak)
{
    double p[3] = {0, 0, 0}, n[3] = {0, 0, 0};
    if (lp->need_p) { /* else no term reads it */
        double in[4] = {x, y, z, 1}, o[4];
        mat4_apply(lp->mv, in, o);
        if (o[3] == 1) /* an affine modelview: x / 1 is x, without three divisions */
            p[0] = o[0], p[1] = o[1], p[2] = o[2];
        else
            for (int k = 0; k < 3; k++)
                p[k] = o[3] != 0 ? o[k] / o[3] : o[k];
    }
    if (lp->inv) {
        const double *im = lp->inv->m;
        /* n^T M^-1: row k of the inverse's transpose. In scalars: stored
         * one by one and read back two at a time, the array stalled on
         * store forwarding at every vertex. */
        double n0 = cn[0] * im[0] + cn[1] * im[1] + cn[2] * im[2];
        double n1 = cn[0] * im[4] + cn[1] * im[5] + cn[2] * im[6];
        double n2 = cn[0] * im[8] + cn[1] * im[9] + cn[2] * im[10];
        n[0] = n0, n[1] = n1, n[2] = n2;
        double len = lp->normalize ? sqrt(n0 * n0 + n1 * n1 + n2 * n2) : 0; /* only then */
        if (lp->normalize && len > 0) {
            for (int k = 0; k < 3; k++)
                n[k] /= len;
        } else if (lp->rescale) {
            double r = lp->rescale_r;
            if (r > 0)
                for (int k = 0; k < 3; k++)
                    n[k] /= r;
        }
    }
    interp_lit_prepared(ip, lp, p, n, colour, out, peak);
}

static void lit_line_colour(interp *ip, double x, double y, double z, float out[4], double *peak)
{
    const gl_attribs *a = &ip->st.a;
    interp_lit_prep lp;
    lit_prepare(ip, &lp);
    lit_colour_at(ip, &lp, x, y, z, a->current.normal, a->current.color, out, peak);
}

/* The faces moved are back faces (or, one-sided, all of a textured
 * split's, lit as front faces are): under two-sided lighting, lit as GL
 * lights back faces. */
void interp_relit_prepare(interp *ip, interp_lit_prep *lp)
{
    lit_prepare_side(ip, lp, ip->st.a.lighting.two_side);
}

void interp_relit_colour(interp *ip, const interp_lit_prep *lp, const interp_relit_in *in,
                         float c[4], double *peak)
{
    lit_colour_at(ip, lp, in->p[0], in->p[1], in->p[2], in->normal, in->colour, c, peak);
    if (ip->prim_blend_mapped)
        map_blend(ip, c);
    if (ip->prim_blend == SCENE_BLEND_OPAQUE)
        c[3] = 1;
    else if (ip->prim_blend == SCENE_BLEND_INVISIBLE)
        c[3] = 0;
}

void interp_lit_point_colour(interp *ip, double x, double y, double z, float out[4])
{
    lit_line_colour(ip, x, y, z, out, NULL);
}

/* add_vertex_plain's calls, out of its way (a call there made the
 * compiler keep its arguments in memory, read back in wider loads than
 * they were stored with: a store-forwarding stall at every vertex): the
 * budget, room in the pool and the per-vertex arrays. False when the
 * vertex is dropped. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static bool plain_make_room(interp *ip, size_t k)
{
    scene *s = ip->scene;
    if (!interp_budget_vertex(ip) || !scene_reserve_vertices(s, 1))
        return false;
    if (k >= ip->cap_edge && tr_grow((void **)&ip->edge, &ip->cap_edge, k + 1, 1) != 0) {
        s->failed = true;
        return false;
    }
    /* interp_relit_defer's room; a failure keeps the vertex, as there */
    if (ip->prim_plain_relit && k >= ip->cap_relit_in && (k == 0 || k == ip->relit_pending))
        interp_relit_grow(ip, k);
    return true;
}

/* interp_add_vertex for a plain primitive (begin_mode's prim_plain) and
 * w = 1, once room is made for vertex k of the primitive: the same
 * vertex, without the tests that cannot pass and with the common cases
 * inline. The normal n and colour c are the current ones, as values: read
 * back from memory just after glNormal3f and glColor3f stored them, in
 * loads wider than those stores, they stalled on store forwarding
 * (interp_add_vertex_nc hands them over from the decoder). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void plain_store(interp *ip, scene *s, size_t k, double x, double y, double z,
                               float n0, float n1, float n2, float c0, float c1, float c2,
                               float c3)
{
    scene_vertex *v = s->verts + s->nverts;
    const gl_attribs *a = &ip->st.a;
    v->pos[0] = (float)x;
    v->pos[1] = (float)y;
    v->pos[2] = (float)z;
    v->normal[0] = n0;
    v->normal[1] = n1;
    v->normal[2] = n2;
    if (ip->prim_plain == PRIM_PLAIN_LIT) {
        surface_colour(ip, c0, c1, c2, c3, v->color);
    } else {
        v->color[0] = clamp01(c0);
        v->color[1] = clamp01(c1);
        v->color[2] = clamp01(c2);
        v->color[3] = ip->prim_blend == SCENE_BLEND_OPAQUE      ? 1
                      : ip->prim_blend == SCENE_BLEND_INVISIBLE ? 0
                                                                : clamp01(c3);
    }
    if (a->current.fog_coord != ip->prim_coord0) /* interp_fogsec_track */
        ip->prim_coord_same = false;
    if (ip->prim_plain_relit) { /* interp_relit_defer, its room made above */
        if (k == 0)
            ip->relit_pending = ip->relit_made = 0;
        if (k == ip->relit_pending && k < ip->cap_relit_in) {
            interp_relit_in *in = &ip->relit_in[k];
            in->p[0] = x, in->p[1] = y, in->p[2] = z;
            in->normal[0] = n0, in->normal[1] = n1, in->normal[2] = n2;
            in->colour[0] = c0, in->colour[1] = c1, in->colour[2] = c2, in->colour[3] = c3;
            ip->relit_pending = k + 1;
        }
    }
    float q = a->current.texcoord[3];
    v->tex1[0] = v->tex1[1] = 0;
    if (q == 1 || q == 0 || !isfinite(q)) {
        v->tex[0] = a->current.texcoord[0];
        v->tex[1] = a->current.texcoord[1];
    } else {
        v->tex[0] = a->current.texcoord[0] / q;
        v->tex[1] = a->current.texcoord[1] / q;
    }
    ip->edge[k] = (uint8_t)a->current.edge_flag;
    scene_commit_vertices(s, 1);
}

/* add_vertex_plain when the quick test finds no room: makes it (or drops
 * the vertex). Apart, so that the common path makes no call before the
 * vertex is stored and keeps its arguments in registers (a call there
 * spilled them to the stack at every vertex). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void plain_store_slow(interp *ip, double x, double y, double z, float n0, float n1,
                             float n2, float c0, float c1, float c2, float c3)
{
    scene *s = ip->scene;
    size_t k = s->nverts - ip->prim_first;
    if (!plain_make_room(ip, k))
        return;
    plain_store(ip, s, k, x, y, z, n0, n1, n2, c0, c1, c2, c3);
    if (ip->vmat.changed)
        interp_vmat_vertex(ip);
}

static inline void add_vertex_plain(interp *ip, double x, double y, double z, float n0, float n1,
                                    float n2, float c0, float c1, float c2, float c3)
{
    scene *s = ip->scene;
    size_t k = s->nverts - ip->prim_first;
    bool room = !ip->cut && ip->assembled < INTERP_LIMIT(ip, ASSEMBLED) &&
                s->nverts < INTERP_LIMIT(ip, VERTICES) && s->nverts < s->cap_verts &&
                s->nverts < SCENE_MAX_VERTICES && !s->failed && k < ip->cap_edge &&
                (!ip->prim_plain_relit || k < ip->cap_relit_in);
    if (!room) {
        plain_store_slow(ip, x, y, z, n0, n1, n2, c0, c1, c2, c3);
        return;
    }
    ip->assembled++; /* interp_budget_vertex's count */
    plain_store(ip, s, k, x, y, z, n0, n1, n2, c0, c1, c2, c3);
    if (ip->vmat.changed)
        interp_vmat_vertex(ip);
}

void interp_add_vertex_nc(interp *ip, double x, double y, double z, float n0, float n1, float n2,
                          float c0, float c1, float c2, float c3)
{
    add_vertex_plain(ip, x, y, z, n0, n1, n2, c0, c1, c2, c3);
}

/* The other vertices: not inlined into interp_add_vertex, whose short
 * path would pay for this one's registers at every call. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void add_vertex_general(interp *ip, double x, double y, double z, double w)
{
    scene *s = ip->scene;
    size_t k = s->nverts - ip->prim_first;
    if (!interp_budget_vertex(ip))
        return;
    scene_vertex *v = scene_reserve_vertices(s, 1);
    if (!v)
        return;
    if (k >= ip->cap_edge && tr_grow((void **)&ip->edge, &ip->cap_edge, k + 1, 1) != 0) {
        s->failed = true;
        return;
    }
    if (w != 1) {
        if (w == 0 || !isfinite(w)) {
            x = y = z = NAN; /* a point at infinity: the primitive is dropped */
        } else {
            x /= w;
            y /= w;
            z /= w;
        }
    }
    const gl_attribs *a = &ip->st.a;
    v->pos[0] = (float)x;
    v->pos[1] = (float)y;
    v->pos[2] = (float)z;
    memcpy(v->normal, a->current.normal, sizeof v->normal);
    if (!a->caps[INTERP_CAP_LIGHTING]) {
        for (int i = 0; i < 4; i++)
            v->color[i] = clamp01(a->current.color[i]);
    } else if (ip->prim_mode <= GL_LINE_STRIP || interp_vertex_lit(ip)) {
        lit_line_colour(ip, x, y, z, v->color, NULL);
    } else {
        interp_surface_colour(ip, v->color);
    }
    if (ip->prim_color_sum || ip->prim_fog_vertex)
        interp_fogsec_vertex(ip, v->color);
    interp_fogsec_track(ip);
    uint8_t afail = interp_alpha_vertex(ip, k, v->color[3]);
    if (ip->prim_blend_mapped)
        map_blend(ip, v->color);
    if (ip->prim_blend == SCENE_BLEND_OPAQUE)
        v->color[3] = 1;
    else if (ip->prim_blend == SCENE_BLEND_INVISIBLE)
        v->color[3] = 0;
    if (interp_relit_wanted(ip)) /* GL's colour, should its face need it */
        interp_relit_defer(ip, k, x, y, z, a->current.normal, a->current.color);
    float q = a->current.texcoord[3];
    v->tex1[0] = v->tex1[1] = 0;
    if (ip->draw_unit[0] >= 0) {
        double obj[4] = {x, y, z, 1};
        if (ip->draw_unit[1] < 0 && interp_unit_cube(ip, ip->draw_unit[0])) {
            float str[3]; /* a cube map's r rides in tex1 (scene_texture.cube) */
            interp_vertex_texcoord3(ip, ip->draw_unit[0], obj, v->normal, str);
            v->tex[0] = str[0];
            v->tex[1] = str[1];
            v->tex1[0] = str[2];
        } else {
            interp_vertex_texcoord(ip, ip->draw_unit[0], obj, v->normal, v->tex);
        }
        if (ip->draw_unit[1] >= 0)
            interp_vertex_texcoord(ip, ip->draw_unit[1], obj, v->normal, v->tex1);
    } else if (q == 1 || q == 0 || !isfinite(q)) {
        v->tex[0] = a->current.texcoord[0];
        v->tex[1] = a->current.texcoord[1];
    } else {
        v->tex[0] = a->current.texcoord[0] / q;
        v->tex[1] = a->current.texcoord[1] / q;
    }
    ip->edge[k] = (uint8_t)(a->current.edge_flag | afail);
    scene_commit_vertices(s, 1);
    interp_vmat_vertex(ip);
}

void interp_add_vertex(interp *ip, double x, double y, double z, double w)
{
    const float *n = ip->st.a.current.normal, *c = ip->st.a.current.color;
    if (ip->prim_plain && w == 1)
        add_vertex_plain(ip, x, y, z, n[0], n[1], n[2], c[0], c[1], c[2], c[3]);
    else
        add_vertex_general(ip, x, y, z, w);
}

void interp_vertex(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->in_begin) {
        interp_diag(ip, DIAG_IGNORED, "vertex outside glBegin/glEnd ignored");
        return;
    }
    if (ip->prim_skip)
        return;
    double v[4] = {0, 0, 0, 1};
    if (cmd->opcode == RGL_OP_Vertex3f) { /* the common case, without the switch */
        v[0] = cmd->arg[0].v.f;
        v[1] = cmd->arg[1].v.f;
        v[2] = cmd->arg[2].v.f;
    } else {
        uint32_t n = cmd_value_count(cmd);
        for (uint32_t k = 0; k < n && k < 4; k++)
            v[k] = cmd_value(cmd, k);
    }
    interp_add_vertex(ip, v[0], v[1], v[2], v[3]);
}
