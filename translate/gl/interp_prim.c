/* interp_prim.c: glBegin/glEnd, the current vertex attributes, primitive
 * assembly, face culling, polygon mode, lines, points and glRect.
 *
 * Vertices go straight into the scene's vertex pool as they arrive, with
 * the current normal, colour and texture coordinates (GL 1.x 2.7). At
 * glEnd the primitive is assembled as GL does (2.6.1): strips alternate
 * their winding, quads split (0,1,2)(0,2,3), or (0,1,3)(1,2,3) when
 * called from a display list or when a vertex of the draw lies outside the
 * view volume (as Mesa does: tests/programs/proj_quad_split.c), quad
 * strips take vertices
 * (2i, 2i+1, 2i+3, 2i+2), polygons are fans; incomplete primitives are
 * dropped; the provoking vertex (flat shading) is the last vertex of each
 * triangle, quad or segment and the first of a polygon (table 2.2).
 * Facing follows the window-space winding (2.14.1 and 3.5.1), computed in
 * clip space so that primitives crossing the eye plane still face right.
 * Lines and points leave the pool again: they become eye-space segments and
 * squares sized to their pixel width.
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
    /* Cube maps and 3D textures are drawn (interp_texture.c): their notes
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

/* The next segment of a line draw without a depth test: one painter's
 * step nearer than the one before, as GL draws it over what came before
 * where both light a pixel (a strip's joints, wide lines, crossings).
 * *delta takes eye points of the draw's own shift (base) to the new one. */
static bool painter_step(interp *ip, uint32_t base, mat4 *delta)
{
    const gl_attribs *a = &ip->st.a;
    if ((a->caps[INTERP_CAP_DEPTH_TEST] && (a->depth.func == GL_LESS || a->depth.func == GL_LEQUAL)) ||
        ip->painter >= PAINTER_MAX || !ip->scene)
        return false;
    mat4 from = mat4_identity(), inv;
    interp_painter_apply(ip, base, &from);
    if (!mat4_invert(&from, &inv))
        return false;
    *delta = inv;
    interp_painter_apply(ip, ++ip->painter, delta);
    return true;
}

bool interp_object_to_eye(const interp *ip, const mat4 *mv, const mat4 *proj,
                         const int32_t vp[4], mat4 *out)
{
    *out = *mv;
    if (!ip->frame_begin &&
        (memcmp(vp, ip->cam_viewport, sizeof ip->cam_viewport) != 0 ||
         !mat4_equal_f32(proj, &ip->cam_proj))) {
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
        bool same_vp = memcmp(vp, ip->cam_viewport, sizeof ip->cam_viewport) == 0;
        mat4 w = interp_window_matrix(proj, vp);
        bool own = same_vp && mat4_equal_f32(proj, &ip->cam_proj);
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
            interp_note(ip, DIAG_NOTE_BLEND_ADD);
    }
    for (int i = 0; i < 3; i++)
        c[i] = (float)(c[i] * ws / cover);
    c[3] = (float)cover;
}

static void begin_mode(interp *ip, GLenum mode)
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
    begin_mode(ip, mode);
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

/* ---- Assembly ------------------------------------------------------------------- */

typedef struct assembly {
    interp *ip;
    scene *s;
    uint32_t base;  /* absolute index of the primitive's first vertex */
    bool facing;    /* facing must be computed (culling or mixed modes) */
    bool back;      /* with facing: the triangle being filled is a back face */
    bool cull_front, cull_back;
    bool swap;      /* glFrontFace(GL_CW): reorder so that front is CCW */
    bool check_bad; /* some vertex is not finite */
    bool flat;
    bool first; /* GL_FIRST_VERTEX_CONVENTION (glProvokingVertex) */
    float line_width, point_size;
    bool line_smooth, point_smooth;
    bool point_sprite; /* GL_POINT_SPRITE: square, its size not rounded (GL 2.1 3.3.1) */
    bool point_params; /* glPointParameter away from its defaults */
    bool list_quads; /* quads split along v1-v3, as Mesa does in a list or when clipping */
    bool stipple;       /* glLineStipple applies (interp_stipple.c) */
    double stipple_s;   /* GL's stipple counter (a float in Mesa) */
    bool step;          /* a line draw (not outlined faces, which interp_proj may step) */
    uint32_t segments;  /* segments added so far: each after the first a painter's step */
    uint32_t painter;   /* the draw's own painter's shift (ip->painter when it began) */
    int relit;          /* INTERP_RELIT_*: filled faces lit as GL does (interp_relit.c) */
    bool lit_edges;     /* outlined (GL_LINE, GL_POINT) lit faces: GL's lit colours, relit_col */
    bool fog_split;     /* triangles behind the eye get their own fog (interp_fogbehind.c) */
    const scene_look *look; /* the mesh's look, and where its vertices are, for fog_split */
    const mat4 *to_eye;
    bool in_eye;
    bool alpha_test; /* interp_alpha_testing: faces may be discarded */
    bool fill_checks; /* the stencil, alpha_test or fog_split: fill_tri_checks */
    scene_mesh *mesh;
    /* The GL-lit pass's triangles take the copies of their corners
     * (interp_relit_vertices): pool index of vertex k's copy; NULL for
     * the vertices themselves (base + k). */
    const uint32_t *copy;
} assembly;

/* The provoking vertex of a primitive whose last and first vertices are
 * `last` and `first` (GL 3.2 table 2.12). Quads and quad strips keep the
 * last vertex: Mesa's GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION is
 * false (EXT_provoking_vertex allows either). */
static uint32_t pv(const assembly *as, uint32_t last, uint32_t first)
{
    return as->first ? first : last;
}

static bool vertex_ok(const scene_vertex *v)
{
    return isfinite(v->pos[0]) && isfinite(v->pos[1]) && isfinite(v->pos[2]);
}

/* Eye-space position of a pool vertex (already there when prim_in_eye). */
static bool eye_pos(const interp *ip, const scene_vertex *v, double out[3])
{
    if (ip->prim_in_eye) {
        for (int k = 0; k < 3; k++)
            out[k] = v->pos[k];
    } else {
        double in[4] = {v->pos[0], v->pos[1], v->pos[2], 1}, o[4];
        mat4_apply(&ip->prim_to_eye, in, o);
        if (!(o[3] > 0))
            return false;
        for (int k = 0; k < 3; k++)
            out[k] = o[k] / o[3];
    }
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

/* The colour GL rasterises pool vertex i with: its own, or for an
 * outlined lit face GL's lit colour (the pool holds the colour POV-Ray
 * lights a filled face with). */
static const float *edge_colour(const assembly *as, uint32_t i)
{
    if (as->lit_edges)
        return as->ip->relit_col[i - as->base];
    return as->s->verts[i].color;
}

/* A segment of the primitive, between pool vertices i0 and i1, with the
 * colours GL gives it (flat: the provoking vertex's). */
static void add_segment(assembly *as, uint32_t i0, uint32_t i1, uint32_t provoking)
{
    interp *ip = as->ip;
    const scene_vertex *v0 = &as->s->verts[i0], *v1 = &as->s->verts[i1];
    interp_line ln;
    double t[2];
    if (ip->stencil.only)
        return; /* into the stencil buffer alone (not followed: a note) */
    ip->segments++;
    if (!eye_pos(ip, v0, ln.p[0]) || !eye_pos(ip, v1, ln.p[1]) ||
        !interp_clip_segment(ip, ln.p[0], ln.p[1], &t[0], &t[1]))
        return;
    const float *c0 = edge_colour(as, as->flat ? provoking : i0);
    const float *c1 = edge_colour(as, as->flat ? provoking : i1);
    /* cut by a clip plane: the colour there */
    for (int e = 0; e < 2; e++)
        for (int k = 0; k < 4; k++)
            ln.color[e][k] = (float)(c0[k] + (c1[k] - c0[k]) * t[e]);
    ln.width = as->line_width;
    ln.smooth = as->line_smooth;
    ln.stipple = as->stipple;
    ln.have_win = t[0] == 0 && t[1] == 1 && interp_gl_window(ip, v0->pos, ln.win[0]) &&
                  interp_gl_window(ip, v1->pos, ln.win[1]);
    mat4 delta;
    if (as->step && as->segments++ > 0 && painter_step(ip, as->painter, &delta))
        for (int e = 0; e < 2; e++) {
            double in[4] = {ln.p[e][0], ln.p[e][1], ln.p[e][2], 1}, o[4];
            mat4_apply(&delta, in, o);
            for (int k = 0; k < 3; k++)
                ln.p[e][k] = o[k] / o[3];
        }
    interp_add_line(ip, &ln, &as->stipple_s);
}

/* GL's point (GL 1.x 3.3) clipped by its centre alone (2.12): inside the
 * view volume it is drawn whole, outside not at all. */
static void add_point(assembly *as, uint32_t i, uint32_t colour_from)
{
    double p[3];
    if (as->ip->stencil.only)
        return;
    if (!eye_pos(as->ip, &as->s->verts[i], p) || !interp_clip_point(as->ip, p))
        return;
    double size = as->point_size, fade = 1;
    if (as->point_params)
        size = interp_point_size(&as->ip->st.a, p, &fade);
    /* GL fades points below the threshold when multisampling (GL 2.1 3.3) */
    if (size < as->ip->st.a.point.fade_threshold)
        interp_note(as->ip, DIAG_NOTE_POINT_FADE);
    float c[4];
    memcpy(c, edge_colour(as, colour_from), sizeof c);
    c[3] *= (float)fade;
    double win[2];
    bool gl_win = interp_gl_window(as->ip, as->s->verts[i].pos, win);
    size_t first = as->s->npoints;
    interp_add_point(as->ip, p, gl_win ? win : NULL, c, size, as->point_smooth, as->point_params,
                     as->point_sprite);
    bool taken = as->s->npoints > first;
    for (size_t k = first; k < as->s->npoints && taken; k++)
        taken = interp_point_textured(as->ip, &as->s->points[k], &as->s->verts[i],
                                      as->point_smooth);
    if (taken)
        as->s->npoints = first; /* textured squares instead (interp_sprite.c) */
}

/* Whether a vertex of the primitive lies outside the view volume. Mesa
 * (llvmpipe) then draws the whole draw through its clipper, which splits
 * quads (v0,v1,v3)(v1,v2,v3) (docs/mapping.md "Quad and polygon
 * decomposition"; tests/programs/proj_quad_split.c). */
static bool crosses_view_volume(const interp *ip, uint32_t n)
{
    const mat4 *m = &ip->prim_clip;
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    for (uint32_t i = 0; i < n; i++) {
        double in[4] = {v[i].pos[0], v[i].pos[1], v[i].pos[2], 1}, c[4];
        mat4_apply(m, in, c);
        if (!(c[3] > 0) || fabs(c[0]) > c[3] || fabs(c[1]) > c[3] || fabs(c[2]) > c[3])
            return true;
    }
    return false;
}

/* Clip-space x, y, w of every vertex of the primitive, for facing, and
 * x/w, y/w: each vertex is in up to three triangles of a strip, whose
 * areas divided by w there for every edge. */
static bool compute_clip(interp *ip, uint32_t n)
{
    if (n > ip->cap_clipv &&
        tr_grow((void **)&ip->clipv, &ip->cap_clipv, n, sizeof *ip->clipv) != 0)
        return false;
    const mat4 *m = &ip->prim_clip;
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    for (uint32_t i = 0; i < n; i++) {
        double x = v[i].pos[0], y = v[i].pos[1], z = v[i].pos[2];
        ip->clipv[i][0] = m->m[0] * x + m->m[4] * y + m->m[8] * z + m->m[12];
        ip->clipv[i][1] = m->m[1] * x + m->m[5] * y + m->m[9] * z + m->m[13];
        ip->clipv[i][2] = m->m[3] * x + m->m[7] * y + m->m[11] * z + m->m[15];
        ip->clipv[i][3] = ip->clipv[i][0] / ip->clipv[i][2];
        ip->clipv[i][4] = ip->clipv[i][1] / ip->clipv[i][2];
    }
    return true;
}

/* Counter-clockwise in window space? For polygons wholly in front of the
 * eye, the signed area of the projection; otherwise the sign of the
 * homogeneous determinant of the first three vertices, which gives the
 * winding of the visible, clipped part. idx are relative to the base. */
static inline bool is_ccw3(const interp *ip, uint32_t i0, uint32_t i1, uint32_t i2)
{
    double (*c)[5] = ip->clipv;
    const double *a = c[i0], *b = c[i1], *d = c[i2];
    if (a[2] > 0 && b[2] > 0 && d[2] > 0) { /* is_ccw's loop unrolled, same sums */
        double area = 0;
        area += a[3] * b[4] - b[3] * a[4];
        area += b[3] * d[4] - d[3] * b[4];
        area += d[3] * a[4] - a[3] * d[4];
        return area > 0;
    }
    double det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                 a[2] * (b[0] * d[1] - b[1] * d[0]);
    return det > 0;
}

static bool is_ccw(const interp *ip, const uint32_t *idx, int n)
{
    double (*c)[5] = ip->clipv;
    if (n == 3) /* strips and triangles */
        return is_ccw3(ip, idx[0], idx[1], idx[2]);
    bool all_front = true;
    for (int k = 0; k < n; k++)
        if (!(c[idx[k]][2] > 0))
            all_front = false;
    if (all_front) {
        double area = 0;
        for (int k = 0; k < n; k++) {
            const double *a = c[idx[k]], *b = c[idx[(k + 1) % n]];
            area += a[3] * b[4] - b[3] * a[4];
        }
        return area > 0;
    }
    const double *a = c[idx[0]], *b = c[idx[1]], *d = c[idx[2]];
    double det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                 a[2] * (b[0] * d[1] - b[1] * d[0]);
    return det > 0;
}

/* What fill_tri does besides adding the triangle, when fill_checks says
 * there is any: the stencil region, the alpha test, the fog behind the
 * eye. False when the face is not drawn. */
static bool fill_tri_checks(assembly *as, uint32_t a, uint32_t b, uint32_t c)
{
    /* its window region, for later stencil tests (of the faces that write) */
    if (as->ip->stencil.write && (as->ip->stencil.tri_faces & (as->back ? 2 : 1))) {
        double p[3][3];
        const scene_vertex *v = as->s->verts + as->base;
        if (eye_pos(as->ip, &v[a], p[0]) && eye_pos(as->ip, &v[b], p[1]) &&
            eye_pos(as->ip, &v[c], p[2]))
            interp_stencil_tri(as->ip, p);
    }
    if (!as->mesh || as->ip->stencil.only)
        return false;
    const uint32_t abc[3] = {a, b, c};
    if (as->alpha_test && !interp_alpha_face(as->ip, abc, 3, as->mesh->look.texture))
        return false;
    if (as->fog_split) {
        const uint32_t rel[3] = {a, b, c};
        as->mesh = interp_fog_behind_mesh(as->ip, as->look, as->to_eye, as->in_eye, as->base, rel);
        if (!as->mesh)
            return false;
    }
    return true;
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void fill_tri(assembly *as, uint32_t a, uint32_t b, uint32_t c, uint32_t provoking)
{
    if (as->fill_checks ? !fill_tri_checks(as, a, b, c) : !as->mesh)
        return;
    const uint32_t *cp = as->copy;
    uint32_t pa = cp ? cp[a] : as->base + a, pb = cp ? cp[b] : as->base + b;
    uint32_t pc = cp ? cp[c] : as->base + c, pp = cp ? cp[provoking] : as->base + provoking;
    if (as->swap)
        scene_add_tri(as->s, pa, pc, pb, pp);
    else
        scene_add_tri(as->s, pa, pb, pc, pp);
}

/* relit_keep's room for one more triangle, out of its way. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static bool relit_grow(assembly *as)
{
    interp *ip = as->ip;
    if (tr_grow((void **)&ip->relit_tris, &ip->cap_relit_tris, ip->nrelit_tris + 1,
                sizeof *ip->relit_tris) != 0) {
        as->s->failed = true;
        return false;
    }
    return true;
}

/* Keeps a filled triangle for the GL-lit pass (interp_relit.c): its
 * corners get GL's colour there, and it goes to that pass's mesh. */
static inline void relit_keep(assembly *as, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t provoking)
{
    interp *ip = as->ip;
    if (ip->nrelit_tris >= ip->cap_relit_tris && !relit_grow(as))
        return;
    uint32_t *t = ip->relit_tris[ip->nrelit_tris++];
    t[0] = a, t[1] = b, t[2] = c, t[3] = provoking;
    ip->relit_need[a] = ip->relit_need[b] = ip->relit_need[c] = ip->relit_need[provoking] = 1;
}

/* One polygon (triangle, quad or GL_POLYGON) with vertices idx (relative)
 * and its provoking vertex. */
static void emit_polygon(assembly *as, const uint32_t *idx, int n, uint32_t provoking)
{
    interp *ip = as->ip;
    const gl_attribs *a = &ip->st.a;
    if (as->check_bad)
        for (int k = 0; k < n; k++)
            if (!vertex_ok(&as->s->verts[as->base + idx[k]]))
                return;
    GLenum mode = a->polygon.mode[0];
    bool front = true;
    if (as->facing) {
        front = is_ccw(ip, idx, n) != as->swap;
        if ((front && as->cull_front) || (!front && as->cull_back))
            return;
        if (!front && ip->stencil.two_side)
            interp_note(ip, DIAG_NOTE_STENCIL_TWO_SIDE);
        as->back = !front;
        mode = a->polygon.mode[front ? 0 : 1];
    }
    if (as->relit == INTERP_RELIT_PROBE) {
        if (!front && mode == GL_FILL)
            interp_note(ip, DIAG_NOTE_RELIT_SPECULAR);
    } else if (as->relit && mode == GL_FILL) {
        bool gl_lit = as->relit == INTERP_RELIT_ALL || !front;
        if (gl_lit) {
            for (int k = 1; k + 1 < n; k++)
                relit_keep(as, idx[0], idx[k], idx[k + 1], provoking);
            return;
        }
    }
    if (mode == GL_FILL) {
        for (int k = 1; k + 1 < n; k++)
            fill_tri(as, idx[0], idx[k], idx[k + 1], provoking);
        return;
    }
    as->stipple_s = 0; /* each polygon restarts the stipple (NOTE_STIPPLE) */
    for (int k = 0; k < n; k++) {
        if (!(ip->edge[idx[k]] & 1))
            continue; /* GL draws only boundary edges (and their vertices) */
        if (mode == GL_LINE)
            add_segment(as, as->base + idx[k], as->base + idx[(k + 1) % n], as->base + provoking);
        else
            add_point(as, as->base + idx[k], as->flat ? as->base + provoking : as->base + idx[k]);
    }
}

/* Every mode takes edge flags, strips and fans too: GL 2.1 2.6.2 says
 * their edges are all boundary edges, but Mesa (gallium's draw module,
 * the reference here) flags edge (a, b) of each triangle or quad it
 * emits by a's flag, in the vertex orders below (tests/programs/
 * edgeflag_strips.c). */
static void assemble_polygons(assembly *as, GLenum mode, uint32_t n)
{
    uint32_t t[4];
    switch (mode) {
    case GL_TRIANGLES:
        for (uint32_t i = 0; i + 3 <= n; i += 3) {
            t[0] = i, t[1] = i + 1, t[2] = i + 2;
            emit_polygon(as, t, 3, pv(as, i + 2, i));
        }
        break;
    case GL_TRIANGLE_STRIP:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            if (i % 2 == 0)
                t[0] = i, t[1] = i + 1;
            else
                t[0] = i + 1, t[1] = i;
            t[2] = i + 2;
            emit_polygon(as, t, 3, pv(as, i + 2, i));
        }
        break;
    case GL_TRIANGLE_FAN:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            t[0] = 0, t[1] = i + 1, t[2] = i + 2;
            emit_polygon(as, t, 3, pv(as, i + 2, i + 1));
        }
        break;
    case GL_QUADS:
        for (uint32_t i = 0; i + 4 <= n; i += 4) {
            /* The fan starts at v1 for the v1-v3 diagonal: same edges. */
            uint32_t f = as->list_quads ? 1 : 0;
            for (uint32_t k = 0; k < 4; k++)
                t[k] = i + (k + f) % 4;
            emit_polygon(as, t, 4, i + 3);
        }
        break;
    case GL_QUAD_STRIP:
        for (uint32_t i = 0; i + 4 <= n; i += 2) {
            t[0] = i, t[1] = i + 1, t[2] = i + 3, t[3] = i + 2;
            emit_polygon(as, t, 4, i + 3);
        }
        break;
    case GL_POLYGON:
        if (n >= 3) {
            uint32_t *all = tr_realloc(NULL, n * sizeof *all);
            if (!all) {
                as->s->failed = true;
                return;
            }
            for (uint32_t i = 0; i < n; i++)
                all[i] = i;
            emit_polygon(as, all, (int)n, 0);
            tr_free(all);
        }
        break;
    default:
        break;
    }
}

/* Fast path: every face filled, nothing culled, every vertex finite. */
static void assemble_filled(assembly *as, GLenum mode, uint32_t n)
{
    switch (mode) {
    case GL_TRIANGLES:
        for (uint32_t i = 0; i + 3 <= n; i += 3)
            fill_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
        break;
    case GL_TRIANGLE_STRIP:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            if (i % 2 == 0)
                fill_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
            else
                fill_tri(as, i + 1, i, i + 2, pv(as, i + 2, i));
        }
        break;
    case GL_TRIANGLE_FAN:
        for (uint32_t i = 0; i + 3 <= n; i++)
            fill_tri(as, 0, i + 1, i + 2, pv(as, i + 2, i + 1));
        break;
    case GL_QUADS:
        for (uint32_t i = 0; i + 4 <= n; i += 4) {
            if (as->list_quads) {
                fill_tri(as, i, i + 1, i + 3, i + 3);
                fill_tri(as, i + 1, i + 2, i + 3, i + 3);
            } else {
                fill_tri(as, i, i + 1, i + 2, i + 3);
                fill_tri(as, i, i + 2, i + 3, i + 3);
            }
        }
        break;
    case GL_QUAD_STRIP:
        for (uint32_t i = 0; i + 4 <= n; i += 2) {
            fill_tri(as, i, i + 1, i + 3, i + 3);
            fill_tri(as, i, i + 3, i + 2, i + 3);
        }
        break;
    case GL_POLYGON:
        for (uint32_t i = 1; i + 1 < n; i++)
            fill_tri(as, 0, i, i + 1, 0);
        break;
    default:
        break;
    }
}

/* emit_polygon for one triangle when both faces are filled, every vertex
 * finite and facing is needed (culling, or back faces lit as GL does).
 * Inline in each loop: a call per triangle cost a fifth of its work. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void facing_tri(assembly *as, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t provoking)
{
    bool front = is_ccw3(as->ip, a, b, c) != as->swap;
    if (front ? as->cull_front : as->cull_back)
        return;
    if (!front && as->ip->stencil.two_side) /* it took the front faces' stencil */
        interp_note(as->ip, DIAG_NOTE_STENCIL_TWO_SIDE);
    as->back = !front;
    if (as->relit && (as->relit == INTERP_RELIT_ALL || !front))
        relit_keep(as, a, b, c, provoking);
    else
        fill_tri(as, a, b, c, provoking);
}

/* The triangle modes through facing_tri: one face test per triangle, in
 * assemble_polygons' order. */
static bool assemble_facing(assembly *as, GLenum mode, uint32_t n)
{
    switch (mode) {
    case GL_TRIANGLES:
        for (uint32_t i = 0; i + 3 <= n; i += 3)
            facing_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
        return true;
    case GL_TRIANGLE_STRIP:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            if (i % 2 == 0)
                facing_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
            else
                facing_tri(as, i + 1, i, i + 2, pv(as, i + 2, i));
        }
        return true;
    case GL_TRIANGLE_FAN:
        for (uint32_t i = 0; i + 3 <= n; i++)
            facing_tri(as, 0, i + 1, i + 2, pv(as, i + 2, i + 1));
        return true;
    default:
        return false;
    }
}

static void assemble_lines(assembly *as, GLenum mode, uint32_t n)
{
    uint32_t b = as->base;
    switch (mode) {
    case GL_POINTS:
        for (uint32_t i = 0; i < n; i++)
            if (!as->check_bad || vertex_ok(&as->s->verts[b + i]))
                add_point(as, b + i, b + i);
        break;
    case GL_LINES:
        for (uint32_t i = 0; i + 2 <= n; i += 2) {
            as->stipple_s = 0; /* GL restarts the stipple per segment */
            add_segment(as, b + i, b + i + 1, pv(as, b + i + 1, b + i));
        }
        break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
        for (uint32_t i = 0; i + 2 <= n; i++)
            add_segment(as, b + i, b + i + 1, pv(as, b + i + 1, b + i));
        if (mode == GL_LINE_LOOP && n >= 2) /* table 2.2: provoking is vertex 1 */
            add_segment(as, b + n - 1, b, pv(as, b, b + n - 1));
        break;
    default:
        break;
    }
}

/* Moves the primitive's vertices into eye space (projective or singular
 * transforms that a POV-Ray matrix cannot carry). Normals follow with the
 * inverse transpose of the linear part, as GL transforms them. */
static void vertices_to_eye(interp *ip, uint32_t n)
{
    scene_vertex *v = ip->scene->verts + ip->prim_first;
    mat4 inv, nt;
    bool have_nt = mat4_invert(&ip->prim_to_eye, &inv);
    nt = mat4_transpose(&inv);
    for (uint32_t i = 0; i < n; i++) {
        double in[4] = {v[i].pos[0], v[i].pos[1], v[i].pos[2], 1}, o[4];
        mat4_apply(&ip->prim_to_eye, in, o);
        if (o[3] > 0 && isfinite(o[3])) {
            for (int k = 0; k < 3; k++)
                v[i].pos[k] = (float)(o[k] / o[3]);
        } else {
            v[i].pos[0] = v[i].pos[1] = v[i].pos[2] = NAN; /* behind the eye */
        }
        if (have_nt) {
            double nin[4] = {v[i].normal[0], v[i].normal[1], v[i].normal[2], 0}, no[4];
            mat4_apply(&nt, nin, no);
            for (int k = 0; k < 3; k++)
                v[i].normal[k] = (float)no[k];
        }
    }
}

/* Whether the open primitive's vertices (in the pool from prim_first on;
 * none for a solid, of the current colour) share one colour. */
static bool prim_one_colour(const interp *ip)
{
    const scene *s = ip->scene;
    for (size_t i = ip->prim_first + 1; i < s->nverts; i++)
        if (memcmp(s->verts[i].color, s->verts[ip->prim_first].color, sizeof(float[4])) != 0)
            return false;
    return true;
}

scene_look interp_current_look(interp *ip)
{
    scene_look look;
    memset(&look, 0, sizeof look);
    look.lit = ip->st.a.caps[INTERP_CAP_LIGHTING] && !interp_vertex_lit(ip);
    look.flat = ip->st.a.lighting.shade_model == GL_FLAT;
    look.blend = ip->prim_blend;
    look.filter = ip->prim_filter;
    look.fog = ip->st.a.caps[INTERP_CAP_FOG] && !ip->prim_fog_vertex;
    if (ip->st.a.caps[INTERP_CAP_ALPHA_TEST]) {
        GLenum f = ip->st.a.color_buffer.alpha_func;
        look.alpha_test = f == GL_GREATER || f == GL_GEQUAL ? SCENE_ALPHA_ABOVE
                          : f == GL_NEVER                   ? SCENE_ALPHA_NEVER
                          : f == GL_ALWAYS                  ? SCENE_ALPHA_OFF
                                                            : SCENE_ALPHA_OTHER;
        if (look.alpha_test == SCENE_ALPHA_ABOVE)
            look.alpha_ref = ip->st.a.color_buffer.alpha_ref;
    }
    look.material = look.lit ? interp_lit_material(ip) : -1;
    if (look.lit && look.material < 0)
        look.lit = 0;
    look.texture = interp_texture_for_unit(ip, ip->draw_unit[0]);
    look.texture1 = interp_texture_for_unit(ip, ip->draw_unit[1]);
    if (look.texture1 >= 0) {
        const scene_texture *t0 = look.texture >= 0 ? &ip->scene->textures[look.texture] : NULL;
        const scene_texture *t1 = &ip->scene->textures[look.texture1];
        bool one_colour = t0 && !(t0->env_mode == GL_MODULATE && t1->env_mode == GL_MODULATE) &&
                          !t0->colour_is_texel && (look.lit || !look.flat);
        if (t1->colour_is_texel) /* the second unit's texel replaces the first's result */
            look.texture = -1;
        else if ((one_colour && (look.lit || !prim_one_colour(ip))) ||
                 (t0 && look.blend != SCENE_BLEND_OPAQUE))
            interp_note(ip, DIAG_NOTE_MULTITEX); /* see the note's text */
        else if (one_colour) /* unlit, and every vertex has the colour it is combined with */
            interp_note_held(ip, DIAG_NOTE_MULTITEX, "the draw's vertices share one colour");
    }
    if (look.texture < 0 && look.texture1 >= 0) {
        /* An incomplete (or replaced) first unit passes its input on: the
         * second unit draws alone, with its coordinates in tex. */
        look.texture = look.texture1;
        look.texture1 = -1;
        ip->prim_tex_from1 = true;
    }
    look.names = interp_names_for_draw(ip);
    interp_scissor_look(ip, &look);
    interp_pstipple_look(ip, &look);
    look.clip = interp_clip_look(ip);
    interp_stencil_look(ip, &look);
    interp_lightset_textured(ip, &look);
    interp_fogsec_look(ip, &look);
    return look;
}

/* GL lights the normal as transformed (2.11.3); POV-Ray always normalises
 * it. Says so when a lit primitive's normals are not unit length in eye
 * space (GL_NORMALIZE off, GL_RESCALE_NORMAL not making them so). */
static void check_normals(interp *ip, uint32_t n)
{
    const gl_attribs *a = &ip->st.a;
    if (a->caps[INTERP_CAP_NORMALIZE] || ip->prim_in_eye || interp_note_said(ip, DIAG_NOTE_NORMALS))
        return;
    mat4 inv;
    if (!mat4_invert(interp_matrix(ip, INTERP_MV), &inv))
        return;
    double r = 1;
    if (a->caps[INTERP_CAP_RESCALE_NORMAL]) {
        r = sqrt(inv.m[2] * inv.m[2] + inv.m[6] * inv.m[6] + inv.m[10] * inv.m[10]);
        if (!(r > 0))
            return;
    }
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    const double *m = inv.m;
    for (uint32_t i = 0; i < n; i++) {
        /* In scalars, and no division by an r of 1: an array stored and
         * read back, and three divisions, were most of this loop's time. */
        const float *cn = v[i].normal;
        double e0 = cn[0] * m[0] + cn[1] * m[1] + cn[2] * m[2];
        double e1 = cn[0] * m[4] + cn[1] * m[5] + cn[2] * m[6];
        double e2 = cn[0] * m[8] + cn[1] * m[9] + cn[2] * m[10];
        if (r != 1)
            e0 /= r, e1 /= r, e2 /= r;
        double len2 = e0 * e0 + e1 * e1 + e2 * e2;
        if (fabs(len2 - 1) > 2e-3) {
            interp_note(ip, DIAG_NOTE_NORMALS);
            return;
        }
    }
}

static void end_primitive_body(interp *ip)
{
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    ip->in_begin = false;
    ip->prim_plain = 0;
    if (ip->prim_skip || !s)
        return;
    if (s->nverts < ip->prim_first)
        return; /* the pool was cleared under us (cannot happen: Clear is refused in Begin) */
    uint32_t n = (uint32_t)(s->nverts - ip->prim_first);
    GLenum mode = ip->prim_mode;
    if (n == 0)
        return;
    interp_blend_end(ip, n);
    interp_fog_behind_check(ip, n);
    assembly as;
    memset(&as, 0, sizeof as);
    as.ip = ip;
    as.s = s;
    as.base = (uint32_t)ip->prim_first;
    as.painter = ip->painter;
    /* of one colour, whichever segment shows is the same: no step (a
     * draw of thousands, stroke text, would use up the painter's range) */
    as.step = (mode == GL_LINES || mode == GL_LINE_STRIP || mode == GL_LINE_LOOP) &&
              !prim_one_colour(ip);
    as.flat = a->lighting.shade_model == GL_FLAT;
    as.first = a->lighting.provoking == GL_FIRST_VERTEX_CONVENTION;
    as.swap = a->polygon.front_face == GL_CW;
    as.line_smooth = a->caps[INTERP_CAP_LINE_SMOOTH];
    as.stipple = interp_stipple_on(ip);
    /* Stippled lines are cut as Mesa cuts them (interp_stipple.c); the
     * edges of outlined polygons restart the pattern where Mesa's own
     * triangles begin, which the translator does not follow. */
    if (as.stipple && ip->prim_mode > GL_LINE_STRIP &&
        (a->polygon.mode[0] == GL_LINE || a->polygon.mode[1] == GL_LINE))
        interp_note(ip, DIAG_NOTE_STIPPLE);
    as.point_sprite = a->caps[INTERP_CAP_POINT_SPRITE];
    as.point_smooth = a->caps[INTERP_CAP_POINT_SMOOTH] && !as.point_sprite;
    as.line_width = a->line.width;
    as.point_size = a->point.size;
    as.point_params = interp_point_params_set(a);
    /* Mesa splits quads along v1-v3 in a list, and when drawn from an
     * index array (tests/programs/conf_arrays_quad_split.c). */
    as.list_quads = ip->list_depth > (ip->list_ce ? 1 : 0) || ip->prim_indexed;
    as.alpha_test = interp_alpha_testing(ip);
    for (uint32_t i = 0; i < n && !as.check_bad; i++)
        if (!vertex_ok(&s->verts[as.base + i]))
            as.check_bad = true;

    if (mode <= GL_LINE_STRIP) {
        if (mode != GL_POINTS)
            interp_lines_textured(ip);
        if (ip->prim_in_eye)
            vertices_to_eye(ip, n);
        as.check_bad = true;
        assemble_lines(&as, mode, n);
        s->nverts = ip->prim_first; /* lines and points keep no pool vertices */
        return;
    }

    bool cull = a->caps[INTERP_CAP_CULL_FACE];
    GLenum cm = a->polygon.cull_mode;
    as.cull_front = cull && (cm == GL_FRONT || cm == GL_FRONT_AND_BACK);
    as.cull_back = cull && (cm == GL_BACK || cm == GL_FRONT_AND_BACK);
    /* Back faces may need GL's lighting (interp_relit.c). */
    as.facing = cull || a->polygon.mode[0] != a->polygon.mode[1] || interp_relit_wanted(ip) ||
                ip->stencil.two_side || ip->stencil.tri_faces != 3;
    if (as.facing && !compute_clip(ip, n)) {
        s->failed = true;
        return;
    }
    if (mode == GL_QUADS && !as.list_quads)
        as.list_quads = crosses_view_volume(ip, n);
    interp_proj_painter_prims(ip, mode, n);
    if (ip->prim_in_eye) {
        vertices_to_eye(ip, n);
        as.check_bad = true;
    }
    ip->prim_tex_from1 = false;
    gl_material vmat_saved[2];
    bool vmat = interp_vmat_end(ip, n, vmat_saved);
    scene_look look = interp_current_look(ip);
    if (vmat)
        interp_vmat_restore(ip, vmat_saved);
    if (ip->prim_tex_from1)
        for (size_t i = 0; i < n; i++) {
            scene_vertex *v = &s->verts[ip->prim_first + i];
            memcpy(v->tex, v->tex1, sizeof v->tex);
        }
    if (look.lit)
        check_normals(ip, n);
    mat4 id = mat4_identity();
    as.mesh = scene_mesh_for(s, ip->prim_in_eye ? &id : &ip->prim_to_eye, ip->prim_in_eye, &look);
    as.fog_split = ip->fog_split;
    as.fill_checks = ip->stencil.write || ip->stencil.only || as.alpha_test || as.fog_split;
    as.look = &look;
    as.to_eye = ip->prim_in_eye ? &id : &ip->prim_to_eye;
    as.in_eye = ip->prim_in_eye;
    size_t first_tri = s->ntris;
    /* the split reads relit_over, the colours' peak */
    if (look.texture >= 0 || (look.lit && interp_relit_wanted(ip) && interp_relit_may_saturate(ip)))
        interp_relit_flush(ip);
    as.relit = interp_relit_split(ip, &look);
    if (as.relit && as.relit != INTERP_RELIT_PROBE && !interp_relit_need_clear(ip, n))
        as.relit = 0;
    /* Outlined faces lit: GL lights their vertices (one-sided lighting;
     * interp_relit.c keeps what that needs; under two-sided lighting its
     * colours are the back faces'). */
    if (look.lit && (a->polygon.mode[0] != GL_FILL || a->polygon.mode[1] != GL_FILL)) {
        if (interp_relit_wanted(ip) && !a->lighting.two_side) {
            interp_relit_flush(ip);
            as.lit_edges = ip->relit_made >= n && ip->relit_col;
        }
        if (!as.lit_edges)
            interp_note(ip, DIAG_NOTE_LIT_OUTLINE);
    }
    bool filled = !as.check_bad && a->polygon.mode[0] == GL_FILL;
    if (filled && !as.facing && !as.relit)
        assemble_filled(&as, mode, n);
    else if (!(filled && as.facing && a->polygon.mode[1] == GL_FILL &&
               as.relit != INTERP_RELIT_PROBE && assemble_facing(&as, mode, n)))
        assemble_polygons(&as, mode, n);
    if (as.relit && as.relit != INTERP_RELIT_PROBE && ip->nrelit_tris > 0) {
        if (interp_relit_vertices(ip, n)) {
            ip->prim_relit = true;
            scene_look gl_look = interp_current_look(ip);
            ip->prim_relit = false;
            as.mesh = scene_mesh_for(s, ip->prim_in_eye ? &id : &ip->prim_to_eye, ip->prim_in_eye,
                                     &gl_look);
            as.copy = ip->relit_copy;
            as.look = &gl_look;
            for (size_t k = 0; k < ip->nrelit_tris; k++) {
                const uint32_t *t = ip->relit_tris[k];
                fill_tri(&as, t[0], t[1], t[2], t[3]);
            }
        }
    }
    interp_relit_done(ip);
    if (look.lit)
        interp_gouraud_check(ip, first_tri);
    if (a->polygon.mode[0] == GL_LINE || a->polygon.mode[1] == GL_LINE)
        interp_lines_textured(ip);
}

static void end_primitive(interp *ip)
{
    end_primitive_body(ip);
    interp_point_sprites_end(ip);
}

void interp_end(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    if (!ip->in_begin) {
        interp_bad_op(ip, "glEnd without glBegin");
        return;
    }
    end_primitive(ip);
    ip->prim_color_sum = ip->prim_fog_vertex = false;
}

bool interp_prim_begin(interp *ip, GLenum mode)
{
    begin_mode(ip, mode);
    return !ip->prim_skip;
}

void interp_prim_end(interp *ip)
{
    if (ip->in_begin)
        end_primitive(ip);
    ip->prim_color_sum = ip->prim_fog_vertex = false;
}

void interp_abort_begin(interp *ip)
{
    if (!ip->in_begin)
        return;
    ip->in_begin = false;
    ip->prim_plain = 0;
    ip->prim_fx = false;
    ip->prim_color_sum = ip->prim_fog_vertex = false;
    if (ip->scene && !ip->prim_skip && ip->scene->nverts >= ip->prim_first)
        ip->scene->nverts = ip->prim_first;
}

/* glRect(x1, y1, x2, y2) is Begin(POLYGON), (x1,y1) (x2,y1) (x2,y2)
 * (x1,y2), End (GL 1.x 2.9). */
void interp_rect(interp *ip, const rgl_cmd *cmd)
{
    double v[4];
    if (cmd->nargs == 2) { /* the vector forms: two arrays of two */
        v[0] = rgl_arg_f(&cmd->arg[0], 0);
        v[1] = rgl_arg_f(&cmd->arg[0], 1);
        v[2] = rgl_arg_f(&cmd->arg[1], 0);
        v[3] = rgl_arg_f(&cmd->arg[1], 1);
    } else {
        for (int i = 0; i < 4; i++)
            v[i] = arg_num(&cmd->arg[i]);
    }
    begin_mode(ip, GL_POLYGON);
    if (!ip->prim_skip) {
        interp_add_vertex(ip, v[0], v[1], 0, 1);
        interp_add_vertex(ip, v[2], v[1], 0, 1);
        interp_add_vertex(ip, v[2], v[3], 0, 1);
        interp_add_vertex(ip, v[0], v[3], 0, 1);
    }
    end_primitive(ip);
}
